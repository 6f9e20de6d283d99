!> The set-up of a planar piece (rod_init): grid, material, ends, work arrays and the mass matrix.
!> (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_init
   use xcable_model_sections, only: joint_ei, cell_mass_matrix, point_nodes, add_point_masses
   implicit none

contains

   !> Set up a piece on the node arc lengths s.
   module subroutine rod_init(self, s, mass, weight, ei, gravity, mu, law, end_a, end_b, tension_ref, mu2, damping)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      !> Node arc lengths, increasing, m.
      real(dp), intent(in) :: s(:)
      !> Mass (kg/m) and weight (N/m) per unstretched length, EI (N m^2), gravity (m/s^2).
      real(dp), intent(in) :: mass, weight, ei, gravity
      !> Share of the averaged mass matrix, 0 to 1.
      real(dp), intent(in) :: mu
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Ends at s(1) and s(n).
      class(end_condition), intent(in) :: end_a, end_b
      !> Reference tension of the row scaling, N.
      real(dp), intent(in) :: tension_ref
      !> Weight of the second-difference kinetic energy (0 if absent).
      real(dp), intent(in), optional :: mu2
      !> Kelvin-Voigt damping c, N s (0 if absent).
      real(dp), intent(in), optional :: damping
      integer :: n, k
      real(dp) :: w
      n = size(s)
      self%n = n
      self%s = s
      self%ds = s(2:n) - s(1:n - 1)
      allocate (self%lumped(n), self%dual(n))
      self%lumped = 0
      self%lumped(1:n - 1) = self%lumped(1:n - 1) + 0.5_dp*self%ds
      self%lumped(2:n) = self%lumped(2:n) + 0.5_dp*self%ds
      self%dual = 0
      do k = 2, n - 1
         self%dual(k) = 0.5_dp*(self%ds(k - 1) + self%ds(k))
      end do
      self%mass_per_length = mass
      self%weight = weight
      self%ei = ei
      self%gravity = gravity
      self%mu = mu
      self%mu2 = 0
      if (present(mu2)) self%mu2 = mu2
      self%damping = 0
      if (present(damping)) self%damping = damping
      if (allocated(self%law)) deallocate (self%law)
      allocate (self%law, source=law)
      if (allocated(self%end_a)) deallocate (self%end_a)
      if (allocated(self%end_b)) deallocate (self%end_b)
      allocate (self%end_a, source=end_a)
      allocate (self%end_b, source=end_b)
      self%tension_ref = tension_ref
      self%length_ref = sum(self%ds)/(n - 1)
      allocate (self%r0(2, n), self%v0(2, n), self%mv0(2, n), self%e0(2, n - 1), self%l0(n - 1), self%th0(n))
      allocate (self%e1(2, n - 1), self%l1(n - 1), self%th1(n), self%force(2, n - 1), self%force_node(2, n))
      allocate (self%block(2, 2, -1:1, n - 1), self%block_scaled(2, 2, -1:1, n - 1), self%mass(0:2, n), self%v1(2, n), &
                self%mass_scaled(2, 2, 0:2, n), self%mom(n), self%dmom(n))
      self%mom = 0
      self%dmom = 0
      self%r0 = 0; self%v0 = 0; self%mv0 = 0; self%e0 = 0; self%l0 = 1; self%th0 = 0
      allocate (self%b0(n))
      call rod_old_energies(self)
      allocate (self%memo_x(2*n), self%memo_e(2, n - 1), self%memo_l(n - 1), self%memo_th(n), self%memo_b(n), &
                self%memo_b_ok(n), self%memo_dphi(n - 1))
      self%memo_valid = .false.
      self%e1 = 0; self%l1 = 1; self%th1 = 0; self%force = 0; self%block = 0
      self%v1 = 0
      allocate (self%load_node(2, n), self%load_block(2, 2, 0:1, n - 1), self%skew_block(2, 2, 0:1, n - 1))
      self%load_node = 0
      self%load_block = 0
      self%skew_block = 0
      self%mass = 0
      self%mass(0, :) = (1 - mu)*mass*self%lumped
      self%mass(0, 1) = self%mass(0, 1) + end_a%point_mass()
      self%mass(0, n) = self%mass(0, n) + end_b%point_mass()
      self%mass(1, 1:n - 1) = 0.25_dp*mu*mass*self%ds
      self%mass(0, 1:n - 1) = self%mass(0, 1:n - 1) + 0.25_dp*mu*mass*self%ds
      self%mass(0, 2:n) = self%mass(0, 2:n) + 0.25_dp*mu*mass*self%ds
      ! Kinetic energy of the second differences of velocity, w |V_k-1 - 2 V_k + V_k+1|^2 / 2 per interior node.
      do k = 2, n - 1
         w = self%mu2*mass*self%dual(k)/16
         self%mass(0, k - 1) = self%mass(0, k - 1) + w
         self%mass(0, k) = self%mass(0, k) + 4*w
         self%mass(0, k + 1) = self%mass(0, k + 1) + w
         self%mass(1, k - 1) = self%mass(1, k - 1) - 2*w
         self%mass(1, k) = self%mass(1, k) - 2*w
         self%mass(2, k - 1) = self%mass(2, k - 1) + w
      end do
   end subroutine rod_init

   !> A line of segments: the sections' cells and materials; the mass matrix rebuilt with each
   !> cell's mass, the node weights and EIs from the cells beside each node.
   module subroutine rod_set_sections(self, last, laws, mass, weight, ei, damping)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      !> Last cell of each section (the last one n - 1).
      integer, intent(in) :: last(:)
      !> The sections' laws.
      type(rod_section), intent(in) :: laws(:)
      !> Per section: mass and weight per length, EI, damping.
      real(dp), intent(in) :: mass(:), weight(:), ei(:), damping(:)
      integer :: n, j
      real(dp) :: mc(self%n - 1), wc(self%n - 1), eic(self%n - 1)
      n = self%n
      if (allocated(self%sections)) deallocate (self%sections)
      allocate (self%sections(size(last)))
      if (allocated(self%cell_sec)) deallocate (self%cell_sec)
      allocate (self%cell_sec(n - 1))
      do j = 1, size(last)
         self%sections(j)%first = 1
         if (j > 1) self%sections(j)%first = last(j - 1) + 1
         self%sections(j)%last = last(j)
         allocate (self%sections(j)%law, source=laws(j)%law)
         self%sections(j)%mass = mass(j)
         self%sections(j)%weight = weight(j)
         self%sections(j)%ei = ei(j)
         self%sections(j)%damping = damping(j)
         self%cell_sec(self%sections(j)%first:last(j)) = j
         mc(self%sections(j)%first:last(j)) = mass(j)
         wc(self%sections(j)%first:last(j)) = weight(j)
         eic(self%sections(j)%first:last(j)) = ei(j)
      end do
      ! The first section's values in the scalars (what a uniform piece reads).
      if (allocated(self%law)) deallocate (self%law)
      allocate (self%law, source=laws(1)%law)
      self%mass_per_length = mass(1)
      self%weight = weight(1)
      self%ei = ei(1)
      self%damping = damping(1)
      ! Node weights: half of each adjacent cell's.
      if (allocated(self%node_w)) deallocate (self%node_w)
      if (allocated(self%node_ei)) deallocate (self%node_ei)
      allocate (self%node_w(n), self%node_ei(n))
      self%node_w = 0
      self%node_w(1:n - 1) = self%node_w(1:n - 1) + 0.5_dp*wc*self%ds
      self%node_w(2:n) = self%node_w(2:n) + 0.5_dp*wc*self%ds
      ! EI of an interior node: its two half-cells' EI weighted by their lengths (the bending
      ! energy EI kappa^2 h_k / 2 shared between the two cells); at the ends the end cell's.
      call joint_ei(n, self%ds, eic, self%node_ei)
      ! The mass matrix of rod_init with each cell's mass.
      call cell_mass_matrix(n, self%ds, self%dual, mc, self%mu, self%mu2, self%end_a%point_mass(), &
                            self%end_b%point_mass(), self%mass)
   end subroutine rod_set_sections

   !> Bodies at nodes: each on the node at its arc length (within 1e-9 of the piece's length), if
   !> the piece has one there; its inertia on the diagonal of the mass matrix, its weight on the
   !> node's weight (its buoyancy and drag are loads, point_loads; node_w: set_sections first, or
   !> the uniform share).
   module subroutine rod_set_points(self, points)
      class(rod_piece), intent(inout) :: self
      type(point_body), intent(in) :: points(:)
      integer :: nodes(size(points))
      if (allocated(self%points)) deallocate (self%points, self%point_node, self%point_jac)
      nodes = point_nodes(self%s, points)
      if (all(nodes == 0)) return
      if (.not. allocated(self%node_w)) then
         allocate (self%node_w(self%n))
         self%node_w = self%weight*self%lumped
      end if
      self%points = pack(points, nodes > 0)
      self%point_node = pack(nodes, nodes > 0)
      allocate (self%point_jac(2, 2, size(self%points)))
      self%point_jac = 0
      call add_point_masses(self%points, self%point_node, self%mass, self%node_w)
   end subroutine rod_set_points
end submodule xcable_model_rod_init
