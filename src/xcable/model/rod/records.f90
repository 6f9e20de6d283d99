!> What the drivers record of a planar piece's state besides its energies: the reaction of a held
!> end (rod_reaction) and the cells' tension, strain and shear and the nodes' moments
!> (rod_cell_fields).
!> (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_records
   implicit none

contains

   !> The force the support exerts on end node k (1 or n) to keep the balance of
   !> that node: for statics (dt = 0) -(N_k - N_k-1) + w_k e_z - F_k, for a step
   !> also plus the node's inertia [M (V^n+1 - V^n)]_k / dt. Uses the cell forces
   !> of the last evaluation (at the converged state: a residual, or for a step
   !> rod_problem%accepted_state, which computes the end cells' forces and the end
   !> nodes' velocities this needs), so call it right after.
   module function rod_reaction(self, k, x, dt, theta) result(f)
      !> Piece.
      class(rod_piece), intent(in) :: self
      !> End node, 1 or n.
      integer, intent(in) :: k
      !> Positions at which the piece was last evaluated, 2 per node.
      real(dp), intent(in) :: x(:)
      !> Step (0: statics) and time weight.
      real(dp), intent(in) :: dt, theta
      real(dp) :: f(2), mv(2)
      integer :: n, j
      n = self%n
      f = [0.0_dp, rod_node_weight(self, k)] - self%load_node(:, k)
      if (k < n) f = f - self%force(:, k)
      if (k > 1) f = f + self%force(:, k - 1)
      if (dt > 0) then
         ! (M V^n+1)_k with V^n+1 of the last evaluation.
         mv = self%mass(0, k)*self%v1(:, k)
         do j = 1, 2
            if (k + j <= n) mv = mv + self%mass(j, k)*self%v1(:, k + j)
            if (k - j >= 1) mv = mv + self%mass(j, k - j)*self%v1(:, k - j)
         end do
         f = f + (mv - self%mv0(:, k))/dt
      end if
   end function rod_reaction

   !> Tension, strain and shear force of each cell and the moment of each node of positions R.
   module subroutine rod_cell_fields(self, r, tension, strain, shear, moment_node, v)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      !> Positions (2, n).
      real(dp), intent(in) :: r(:, :)
      !> Velocities (2, n): with them the tension includes the damping c d(eps)/dt.
      real(dp), intent(in), optional :: v(:, :)
      !> Tension (N; with the damping when v is given), strain, shear force (N; along the normal n of the
      !> paper, -perp(t)) per cell (n - 1).
      real(dp), intent(out) :: tension(:), strain(:), shear(:)
      !> Moment per node, dB/dtheta, N m (0 at the ends).
      real(dp), intent(out) :: moment_node(:)
      integer :: c, k
      call self%geometry(r, self%e1, self%l1, self%th1)
      moment_node = 0
      do k = 2, self%n - 1
         moment_node(k) = bend_moment(self, k, self%th1(k))
      end do
      do c = 1, self%n - 1
         strain(c) = self%l1(c) - 1
         if (allocated(self%sections)) then
            associate (sec => self%sections(self%cell_sec(c)))
               tension(c) = sec%law%tension(strain(c))
               if (present(v) .and. sec%damping > 0) tension(c) = damped_tension(sec%law, strain(c), tension(c), &
                  sec%damping*dot_product(self%e1(:, c), v(:, c + 1) - v(:, c))/(self%ds(c)*self%l1(c)))
            end associate
         else
            tension(c) = self%law%tension(strain(c))
            if (present(v) .and. self%damping > 0) tension(c) = damped_tension(self%law, strain(c), tension(c), &
               self%damping*dot_product(self%e1(:, c), v(:, c + 1) - v(:, c))/(self%ds(c)*self%l1(c)))
         end if
         ! Sn along the paper's normal n = -perp(t): EI Omega' + (1 + eps) Sn = 0.
         shear(c) = (moment_node(c + 1) - moment_node(c))/(self%ds(c)*self%l1(c))
      end do
   end subroutine rod_cell_fields
end submodule xcable_model_rod_records
