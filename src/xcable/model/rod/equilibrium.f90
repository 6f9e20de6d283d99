!> The static system of a planar piece: the residual and Jacobian of its equilibrium at a time
!> (model/rod_statics.f90 solves it). (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_equilibrium
   implicit none

contains

   !> Residual (and Jacobian) of the static equilibrium at time t: for a loaded
   !> node, [-(N_k - N_k-1) + w_k e_z - F_k(t)] / T_ref with N_c the exact
   !> gradient of U per cell; for a held node (R_k - X(t)) / ds_ref.
   module subroutine rod_static_system(self, x, t, residual, jacobian, with_jacobian)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      !> Positions, 2 per node.
      real(dp), intent(in) :: x(:)
      !> Time of the loads and held positions, s.
      real(dp), intent(in) :: t
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian (band storage).
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form the Jacobian.
      logical, intent(in) :: with_jacobian
      integer :: c, n, k
      real(dp) :: f, fp, t_c(2), pvec(2), moment_diff, couple, stiff(2, 2), dp_de(2, 2)
      real(dp) :: dmom(2, -1:1), jm(2, 2)
      n = self%n
      call geometry_flat(self, x, self%e1, self%l1, self%th1)
      jm = reshape([0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp], [2, 2])
      do k = 2, n - 1
         self%mom(k) = bend_moment(self, k, self%th1(k))
         self%dmom(k) = bend_stiffness(self, k, self%th1(k))
      end do
      do c = 1, n - 1
         associate (e => self%e1(:, c), l => self%l1(c))
            if (allocated(self%sections)) then
               call self%sections(self%cell_sec(c))%law%tension_stiffness(l - 1, f, fp)
            else
               call self%law%tension_stiffness(l - 1, f, fp)
            end if
            t_c = e/l
            pvec = perp(e)/l**2
            couple = cell_couple(self, c, t, t)
            moment_diff = self%mom(c) - self%mom(c + 1) - couple
            self%force(:, c) = f*t_c + moment_diff/self%ds(c)*pvec
            if (.not. with_jacobian) cycle
            stiff = fp*outer(t_c, t_c) + f/l*(identity2() - outer(t_c, t_c))
            dp_de = (jm - 2*outer(matmul(jm, e), e)/l**2)/l**2
            dmom = moment_difference_gradient(self, c)
            self%block(:, :, 0, c) = stiff + moment_diff/self%ds(c)*dp_de + outer(pvec, dmom(:, 0))/self%ds(c)
            self%block(:, :, -1, c) = outer(pvec, dmom(:, -1))/self%ds(c)
            self%block(:, :, 1, c) = outer(pvec, dmom(:, 1))/self%ds(c)
         end associate
      end do
      call apply_loads(self, x, 0.0_dp, 0.5_dp, with_jacobian)
      call assemble(self, x, t, t, residual, jacobian, with_jacobian, dynamic=.false.)
   end subroutine rod_static_system

   !> d(M_c - M_c+1)/de_c' for c' = c-1, c, c+1 (columns -1:1), with the moments' derivatives
   !> dmom with respect to the new turning angles (statics and steps alike): the turning
   !> angle of node k changes by perp(e_c) . de_c / |e_c|^2 with its cell c = k - 1 or k.
   pure function moment_difference_gradient(self, c) result(d)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: c
      real(dp) :: d(2, -1:1)
      d = moment_gradient_of(self%n, c, self%e1, self%l1, self%dmom)
   end function moment_difference_gradient
end submodule xcable_model_rod_equilibrium
