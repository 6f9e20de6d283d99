!> What the drivers record of a 3-D piece's state: its energies (rod3d_energies), twist rates
!> (rod3d_twist_rates) and the reaction of a held end (rod3d_reaction).
!> (A submodule of model/rod3d.f90.)
submodule (xcable_model_rod3d) xcable_model_rod3d_records
   implicit none

contains

   !> Energies of a state: strain, kinetic, bending, gravity, twist (J).
   module function rod3d_energies(self, x, v) result(en)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Unknowns (4 per node) and velocities (3, n).
      real(dp), intent(in) :: x(:), v(:, :)
      real(dp) :: en(5), r(3, self%n), psi(self%n), e(3, self%n - 1), l(self%n - 1), th(self%n)
      integer :: k, c
      call rod3d_unpack(x, r, psi)
      call self%geometry(r, e, l, th)
      en = 0
      if (allocated(self%sections)) then
         do c = 1, self%n - 1
            en(1) = en(1) + self%ds(c)*self%sections(self%cell_sec(c))%law%strain_energy(l(c) - 1)
            en(5) = en(5) + 0.5_dp*self%cell_gip(c)*(psi(c + 1) - psi(c))**2/self%ds(c)
         end do
      else
         do c = 1, self%n - 1
            en(1) = en(1) + self%ds(c)*self%law%strain_energy(l(c) - 1)
            en(5) = en(5) + 0.5_dp*self%gip*(psi(c + 1) - psi(c))**2/self%ds(c)
         end do
      end if
      do k = 1, self%n
         en(2) = en(2) + 0.5_dp*self%mass(0, k)*dot_product(v(:, k), v(:, k))
         en(4) = en(4) + rod3d_node_weight(self, k)*r(3, k)
      end do
      do k = 1, self%n - 1
         en(2) = en(2) + self%mass(1, k)*dot_product(v(:, k), v(:, k + 1))
      end do
      do k = 1, self%n - 2
         en(2) = en(2) + self%mass(2, k)*dot_product(v(:, k), v(:, k + 2))
      end do
      do k = 2, self%n - 1
         en(3) = en(3) + bend_energy(self, k, th(k))
      end do
      ! The energy stored in state-dependent ends (springs) goes with the strain energy.
      if (self%end_a%state_dependent()) en(1) = en(1) + self%end_a%stored_energy(r(:, 1))
      if (self%end_b%state_dependent()) en(1) = en(1) + self%end_b%stored_energy(r(:, self%n))
   end function rod3d_energies

   !> Twist rate tau_c = Omega1 of each cell of x (n - 1), 1/m.
   module pure function rod3d_twist_rates(self, x) result(tau)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      real(dp) :: tau(self%n - 1)
      integer :: c
      do c = 1, self%n - 1
         tau(c) = (x(3*self%n + c + 1) - x(3*self%n + c))/self%ds(c)
      end do
   end function rod3d_twist_rates

   !> The force the support exerts on end node k (1 or n) to keep its balance, after an
   !> evaluation at the state (statics: dt = 0).
   module function rod3d_reaction(self, k, dt) result(f)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> End node, 1 or n.
      integer, intent(in) :: k
      !> Step of the evaluation (0: statics).
      real(dp), intent(in) :: dt
      real(dp) :: f(3), mv(3)
      integer :: n, j
      n = self%n
      f = [0.0_dp, 0.0_dp, rod3d_node_weight(self, k)] - self%load_node(:, k)
      if (k < n) f = f - self%force(:, k)
      if (k > 1) f = f + self%force(:, k - 1)
      if (dt > 0) then
         mv = self%mass(0, k)*self%v1(:, k)
         do j = 1, 2
            if (k + j <= n) mv = mv + self%mass(j, k)*self%v1(:, k + j)
            if (k - j >= 1) mv = mv + self%mass(j, k - j)*self%v1(:, k - j)
         end do
         f = f + (mv - self%mv0(:, k))/dt
      end if
   end function rod3d_reaction
end submodule xcable_model_rod3d_records
