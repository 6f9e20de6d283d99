!> The set-up of a 3-D piece (rod3d_init): grid, material, ends, work arrays and the mass matrix.
!> (A submodule of model/rod3d.f90.)
submodule (xcable_model_rod3d) xcable_model_rod3d_init
   use xcable_model_sections, only: joint_ei, cell_mass_matrix, point_nodes, add_point_masses
   implicit none

contains

   !> Set up a piece on the node arc lengths s; error for what the 3-D rod does not have yet.
   module subroutine rod3d_init(self, s, mass, weight, ei, gip, gravity, mu, law, end_a, end_b, tension_ref, error, mu2, damping)
      !> Piece.
      class(rod3d_piece), intent(inout) :: self
      !> Node arc lengths, increasing, m.
      real(dp), intent(in) :: s(:)
      !> Mass (kg/m), weight (N/m), EI and GIp (N m^2), gravity (m/s^2).
      real(dp), intent(in) :: mass, weight, ei, gip, gravity
      !> Share of the averaged mass matrix, 0 to 1.
      real(dp), intent(in) :: mu
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Ends at s(1) and s(n).
      class(end_condition), intent(in) :: end_a, end_b
      !> Reference tension of the row scaling, N.
      real(dp), intent(in) :: tension_ref
      !> Error: GIp <= 0.
      type(error_type), allocatable, intent(out) :: error
      !> Weight of the second-difference kinetic energy; Kelvin-Voigt damping c, N s (0 if absent).
      real(dp), intent(in), optional :: mu2, damping
      integer :: n, k
      real(dp) :: w
      if (.not. gip > 0) then
         call fatal_error(error, 'the torsional stiffness GIp must be > 0', stat_input)
         return
      end if
      ! A piece may be set up again.
      if (allocated(self%law)) deallocate (self%law)
      if (allocated(self%end_a)) deallocate (self%end_a)
      if (allocated(self%end_b)) deallocate (self%end_b)
      if (allocated(self%lumped)) deallocate (self%lumped, self%dual_length, self%r0, self%v0, self%mv0, self%e0, &
                                              self%l0, self%th0, self%e1, self%l1, self%th1, self%force, &
                                              self%force_node, self%v1, self%block, self%mass)
      n = size(s)
      self%n = n
      self%s = s
      self%ds = s(2:n) - s(1:n - 1)
      allocate (self%lumped(n), self%dual_length(n))
      self%lumped = 0
      self%lumped(1:n - 1) = self%lumped(1:n - 1) + 0.5_dp*self%ds
      self%lumped(2:n) = self%lumped(2:n) + 0.5_dp*self%ds
      self%dual_length = 0
      do k = 2, n - 1
         self%dual_length(k) = 0.5_dp*(self%ds(k - 1) + self%ds(k))
      end do
      self%mass_per_length = mass
      self%weight = weight
      self%ei = ei
      self%gip = gip
      self%gravity = gravity
      self%mu = mu
      self%mu2 = 0
      if (present(mu2)) self%mu2 = mu2
      self%damping = 0
      if (present(damping)) self%damping = damping
      allocate (self%law, source=law)
      allocate (self%end_a, source=end_a)
      allocate (self%end_b, source=end_b)
      self%tension_ref = tension_ref
      self%length_ref = sum(self%ds)/(n - 1)
      allocate (self%r0(3, n), self%v0(3, n), self%mv0(3, n), self%e0(3, n - 1), self%l0(n - 1), self%th0(n))
      if (allocated(self%phi_old)) deallocate (self%phi_old)
      allocate (self%phi_old(3, n))
      self%phi_old = 0
      allocate (self%e1(3, n - 1), self%l1(n - 1), self%th1(n), self%force(3, n - 1), self%force_node(3, n))
      allocate (self%v1(3, n), self%block(3, 3, -1:1, n - 1), self%mass(0:2, n))
      if (allocated(self%load_node)) deallocate (self%load_node, self%load_block)
      if (allocated(self%skew_block)) deallocate (self%skew_block)
      allocate (self%load_node(3, n), self%load_block(3, 3, 0:1, n - 1), self%skew_block(3, 3, 0:1, n - 1))
      self%load_node = 0
      self%load_block = 0
      self%skew_block = 0
      if (allocated(self%loads)) deallocate (self%loads)
      if (allocated(self%sections)) deallocate (self%sections)
      if (allocated(self%cell_sec)) deallocate (self%cell_sec)
      if (allocated(self%node_w)) deallocate (self%node_w)
      if (allocated(self%node_ei)) deallocate (self%node_ei)
      if (allocated(self%cell_gip)) deallocate (self%cell_gip)
      self%r0 = 0; self%v0 = 0; self%mv0 = 0; self%e0 = 0; self%l0 = 1; self%th0 = 0
      self%e1 = 0; self%l1 = 1; self%th1 = 0; self%force = 0; self%force_node = 0; self%v1 = 0; self%block = 0
      ! The planar rod's mass matrix, for each component.
      self%mass = 0
      self%mass(0, :) = (1 - mu)*mass*self%lumped
      self%mass(0, 1) = self%mass(0, 1) + end_a%point_mass()
      self%mass(0, n) = self%mass(0, n) + end_b%point_mass()
      self%mass(1, 1:n - 1) = 0.25_dp*mu*mass*self%ds
      self%mass(0, 1:n - 1) = self%mass(0, 1:n - 1) + 0.25_dp*mu*mass*self%ds
      self%mass(0, 2:n) = self%mass(0, 2:n) + 0.25_dp*mu*mass*self%ds
      do k = 2, n - 1
         w = self%mu2*mass*self%dual_length(k)/16
         self%mass(0, k - 1) = self%mass(0, k - 1) + w
         self%mass(0, k) = self%mass(0, k) + 4*w
         self%mass(0, k + 1) = self%mass(0, k + 1) + w
         self%mass(1, k - 1) = self%mass(1, k - 1) - 2*w
         self%mass(1, k) = self%mass(1, k) - 2*w
         self%mass(2, k - 1) = self%mass(2, k - 1) + w
      end do
   end subroutine rod3d_init

   !> A line of segments: the sections' cells and materials; the mass matrix rebuilt with each
   !> cell's mass, the node weights and EIs from the cells beside each node, as the planar rod's
   !> set_sections (model/rod/init.f90), so that a planar line of segments gives its numbers.
   module subroutine rod3d_set_sections(self, last, sections)
      !> Piece.
      class(rod3d_piece), intent(inout) :: self
      !> Last cell of each section (the last one n - 1).
      integer, intent(in) :: last(:)
      !> The sections' materials (their first and last are set here).
      type(rod3d_section), intent(in) :: sections(:)
      integer :: n, j
      real(dp) :: mc(self%n - 1), wc(self%n - 1), eic(self%n - 1)
      n = self%n
      if (allocated(self%sections)) deallocate (self%sections)
      if (allocated(self%cell_sec)) deallocate (self%cell_sec)
      if (allocated(self%cell_gip)) deallocate (self%cell_gip)
      allocate (self%sections(size(last)), self%cell_sec(n - 1), self%cell_gip(n - 1))
      do j = 1, size(last)
         allocate (self%sections(j)%law, source=sections(j)%law)
         self%sections(j)%mass = sections(j)%mass
         self%sections(j)%weight = sections(j)%weight
         self%sections(j)%ei = sections(j)%ei
         self%sections(j)%gip = sections(j)%gip
         self%sections(j)%damping = sections(j)%damping
         self%sections(j)%first = 1
         if (j > 1) self%sections(j)%first = last(j - 1) + 1
         self%sections(j)%last = last(j)
         associate (a => self%sections(j)%first, b => last(j))
            self%cell_sec(a:b) = j
            mc(a:b) = sections(j)%mass
            wc(a:b) = sections(j)%weight
            eic(a:b) = sections(j)%ei
            self%cell_gip(a:b) = sections(j)%gip
         end associate
      end do
      ! The first section's values in the scalars (what a uniform piece reads).
      if (allocated(self%law)) deallocate (self%law)
      allocate (self%law, source=sections(1)%law)
      self%mass_per_length = sections(1)%mass
      self%weight = sections(1)%weight
      self%ei = sections(1)%ei
      self%gip = sections(1)%gip
      self%damping = sections(1)%damping
      ! Node weights: half of each adjacent cell's.
      if (allocated(self%node_w)) deallocate (self%node_w)
      if (allocated(self%node_ei)) deallocate (self%node_ei)
      allocate (self%node_w(n), self%node_ei(n))
      self%node_w = 0
      self%node_w(1:n - 1) = self%node_w(1:n - 1) + 0.5_dp*wc*self%ds
      self%node_w(2:n) = self%node_w(2:n) + 0.5_dp*wc*self%ds
      ! EI of an interior node: its two half-cells' EI weighted by their lengths; at the ends the
      ! end cell's.
      call joint_ei(n, self%ds, eic, self%node_ei)
      ! The mass matrix of rod3d_init with each cell's mass.
      call cell_mass_matrix(n, self%ds, self%dual_length, mc, self%mu, self%mu2, self%end_a%point_mass(), &
                            self%end_b%point_mass(), self%mass)
   end subroutine rod3d_set_sections

   !> Bodies at nodes: each on the node at its arc length (within 1e-9 of the piece's length), if
   !> the piece has one there; its inertia on the diagonal of the mass matrix, its weight on the
   !> node's weight (its buoyancy and drag are loads, point_loads; node_w: set_sections first, or
   !> the uniform share).
   module subroutine rod3d_set_points(self, points)
      class(rod3d_piece), intent(inout) :: self
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
      allocate (self%point_jac(3, 3, size(self%points)))
      self%point_jac = 0
      call add_point_masses(self%points, self%point_node, self%mass, self%node_w)
   end subroutine rod3d_set_points
end submodule xcable_model_rod3d_init
