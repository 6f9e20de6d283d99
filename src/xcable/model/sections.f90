!> What a line of segments changes in a rod's constant arrays, shared by the planar rod and the
!> 3-D rod (their set_sections): the EI of each node from its two cells, and the mass matrix
!> built as a uniform rod's with each cell's own mass.
module xcable_model_sections
   use xcable_core_kinds, only: dp
   use xcable_loads_point, only: point_body
   implicit none
   private
   public :: joint_ei, cell_mass_matrix, point_nodes, add_point_masses

contains

   !> EI of each node from the cells' (n - 1): an interior node's the two cells' weighted by
   !> their lengths (the bending energy EI kappa^2 h_k / 2 split between its two half-cells),
   !> an end node its cell's.
   pure subroutine joint_ei(n, ds, eic, node_ei)
      !> Nodes; cell lengths (n - 1), m; the cells' EI (n - 1), N m^2.
      integer, intent(in) :: n
      real(dp), intent(in) :: ds(n - 1), eic(n - 1)
      !> Each node's EI (n), N m^2.
      real(dp), intent(out) :: node_ei(n)
      integer :: k
      node_ei(1) = eic(1)
      node_ei(n) = eic(n - 1)
      do k = 2, n - 1
         if (eic(k - 1) == eic(k)) then
            node_ei(k) = eic(k)
         else
            node_ei(k) = (eic(k - 1)*ds(k - 1) + eic(k)*ds(k))/(ds(k - 1) + ds(k))
         end if
      end do
   end subroutine joint_ei

   !> The mass matrix of a rod (mass(j, k) = M(k, k + j), two off-diagonals) with each cell's
   !> mass per length mc: the share mu of the averaged matrix, 1 - mu lumped, the point masses
   !> at the ends, and the second-difference term of weight mu2 with a node's mass the mean of
   !> its two cells' weighted by their lengths.
   pure subroutine cell_mass_matrix(n, ds, dual, mc, mu, mu2, point_a, point_b, mass)
      !> Nodes; cell lengths (n - 1) and the nodes' dual lengths (n), m; cell masses (n - 1), kg/m.
      integer, intent(in) :: n
      real(dp), intent(in) :: ds(n - 1), dual(n), mc(n - 1)
      !> Share of the averaged matrix; weight of the second differences; point masses, kg.
      real(dp), intent(in) :: mu, mu2, point_a, point_b
      !> The matrix (0:2, n), kg.
      real(dp), intent(out) :: mass(0:2, n)
      integer :: c, k
      real(dp) :: w, mk
      mass = 0
      do c = 1, n - 1
         mass(0, c) = mass(0, c) + (1 - mu)*0.5_dp*mc(c)*ds(c)
         mass(0, c + 1) = mass(0, c + 1) + (1 - mu)*0.5_dp*mc(c)*ds(c)
      end do
      mass(0, 1) = mass(0, 1) + point_a
      mass(0, n) = mass(0, n) + point_b
      mass(1, 1:n - 1) = 0.25_dp*mu*mc*ds
      mass(0, 1:n - 1) = mass(0, 1:n - 1) + 0.25_dp*mu*mc*ds
      mass(0, 2:n) = mass(0, 2:n) + 0.25_dp*mu*mc*ds
      do k = 2, n - 1
         mk = (mc(k - 1)*ds(k - 1) + mc(k)*ds(k))/(ds(k - 1) + ds(k))
         w = mu2*mk*dual(k)/16
         mass(0, k - 1) = mass(0, k - 1) + w
         mass(0, k) = mass(0, k) + 4*w
         mass(0, k + 1) = mass(0, k + 1) + w
         mass(1, k - 1) = mass(1, k - 1) - 2*w
         mass(1, k) = mass(1, k) - 2*w
         mass(2, k - 1) = mass(2, k - 1) + w
      end do
   end subroutine cell_mass_matrix
   !> The node of each body on a piece with the node arc lengths s: the node at its arc length
   !> (within 1e-9 of the piece's length), or 0 when the piece has none there. A body on the
   !> node where the line parts stays with the piece on end a's side: a piece that starts at a
   !> cut (s(1) > 0) leaves its first node's body to the piece before.
   pure function point_nodes(s, points) result(nodes)
      !> Node arc lengths of the piece, m.
      real(dp), intent(in) :: s(:)
      !> The line's bodies.
      type(point_body), intent(in) :: points(:)
      integer :: nodes(size(points))
      integer :: i, k
      do i = 1, size(points)
         nodes(i) = 0
         do k = 1, size(s)
            if (abs(s(k) - points(i)%s) <= 1.0e-9_dp*(s(size(s)) - s(1))) nodes(i) = k
         end do
         if (nodes(i) == 1 .and. s(1) > 1.0e-9_dp*(s(size(s)) - s(1))) nodes(i) = 0
      end do
   end function point_nodes

   !> Each body's inertia on the diagonal of the mass matrix (mass(0, k) = M(k, k)) and its weight
   !> on its node's weight.
   pure subroutine add_point_masses(points, nodes, mass, node_w)
      !> The bodies on the piece and their nodes.
      type(point_body), intent(in) :: points(:)
      integer, intent(in) :: nodes(:)
      !> Mass matrix (0:2, n), kg; node weights (n), N.
      real(dp), intent(inout) :: mass(0:, :), node_w(:)
      integer :: i
      do i = 1, size(points)
         mass(0, nodes(i)) = mass(0, nodes(i)) + points(i)%inertia()
         node_w(nodes(i)) = node_w(nodes(i)) + points(i)%weight()
      end do
   end subroutine add_point_masses
end module xcable_model_sections
