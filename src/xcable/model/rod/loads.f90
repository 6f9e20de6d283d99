!> The distributed loads on a planar piece (fluid, seabed, ...): each cell's force and its
!> derivatives, half to each of its nodes. (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_loads
   implicit none

contains

   !> The distributed loads at the positions x: each cell's force (the load per
   !> unstretched length times ds) goes half to each of its nodes. In a step
   !> (dt > 0) a cell's kinematics are centred on the step: stretch vector
   !> (e^n + e^n+1) / 2, velocity (R^n+1 - R^n) / dt and acceleration
   !> (V^n+1 - V^n) / dt, each the mean of its two nodes'; in statics, e of x at
   !> rest. Fills load_node and, when asked, load_block.
   module subroutine apply_loads(self, x, dt, theta, with_jacobian)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt, theta
      logical, intent(in) :: with_jacobian
      call cell_loads(self, x, dt, theta, with_jacobian)
      if (allocated(self%points)) call point_loads(self, x, dt)
   end subroutine apply_loads

   !> The buoyancy and drag of the bodies at nodes on load_node (which cell_loads cleared, or which holds the
   !> zeros of init when there are no cell loads: cleared here), and its derivative (x, z) in
   !> point_jac.
   subroutine point_loads(self, x, dt)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt
      integer :: i, k
      real(dp) :: f(3), jac(3, 3), x0(3), x1(3)
      logical :: cleared
      cleared = allocated(self%loads)
      if (cleared) cleared = size(self%loads) > 0
      if (.not. cleared) self%load_node = 0
      do i = 1, size(self%points)
         k = self%point_node(i)
         x1 = [x(2*k - 1), 0.0_dp, x(2*k)]
         if (dt > 0) then
            x0 = [self%r0(1, k), 0.0_dp, self%r0(2, k)]
         else
            x0 = x1
         end if
         call self%points(i)%force(dt, x0, x1, f, jac)
         self%load_node(:, k) = self%load_node(:, k) + self%load_factor*f([1, 3])
         self%point_jac(:, :, i) = self%load_factor*jac([1, 3], [1, 3])
      end do
   end subroutine point_loads

   !> The distributed loads along the cells (apply_loads).
   subroutine cell_loads(self, x, dt, theta, with_jacobian)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt, theta
      logical, intent(in) :: with_jacobian
      integer :: c, i, n
      real(dp) :: e(2), w(2), a(2), f(2), df_de(2, 2), df_dw(2, 2), df_da(2, 2), r1(2, 2), de_coef, kin(2, 2), &
                  xm(2), dx_coef, df_dx(2, 2)
      ! Without loads load_node stays the zeros init set: only this routine writes other
      ! values, and a piece's loads are set once, before its first evaluation. (Clearing it
      ! at every evaluation, a memset per node, took 0.8 % of fast_180kN's instructions.)
      if (.not. allocated(self%loads)) return
      if (size(self%loads) == 0) return
      self%load_node = 0
      n = self%n
      self%load_block = 0
      self%skewed = any_skew(self%loads)
      if (self%skewed) self%skew_block = 0
      do c = 1, n - 1
         r1 = reshape(x(2*c - 1:2*c + 2), [2, 2])
         call cell_kinematics(self%e0(:, c), self%e1(:, c), self%r0(:, c:c + 1), self%v0(:, c:c + 1), r1, dt, theta, &
                              e, w, a, de_coef, xm, dx_coef)
         do i = 1, size(self%loads)
            if (.not. self%loads(i)%acts_on(self%s(c), self%s(c + 1))) cycle
            call self%loads(i)%load%cell_force(xm, self%ds(c), e, w, a, f, df_dx, df_de, df_dw, df_da)
            f = self%load_factor*f
            df_dx = self%load_factor*df_dx
            df_de = self%load_factor*df_de
            df_dw = self%load_factor*df_dw
            df_da = self%load_factor*df_da
            self%load_node(:, c) = self%load_node(:, c) + 0.5_dp*self%ds(c)*f
            self%load_node(:, c + 1) = self%load_node(:, c + 1) + 0.5_dp*self%ds(c)*f
            if (.not. with_jacobian) cycle
            ! dF_c/dR_b = ds [df/dx dx/dR_b + df/de de/dR_b + df/dw dw/dR_b + df/da da/dR_b],
            ! dx/dR_b = dx_coef, de/dR_b = +-de_coef / ds.
            kin = self%ds(c)*dx_coef*df_dx
            if (dt > 0) kin = kin + self%ds(c)*(df_dw/(2*dt) + df_da/(2*theta*dt*dt))
            self%load_block(:, :, 0, c) = self%load_block(:, :, 0, c) - de_coef*df_de + kin
            self%load_block(:, :, 1, c) = self%load_block(:, :, 1, c) + de_coef*df_de + kin
         end do
         ! The unequal shares: node c takes +ds g, node c + 1 -ds g.
         if (.not. self%skewed) cycle
         do i = 1, size(self%loads)
            if (.not. self%loads(i)%load%has_skew()) cycle
            if (.not. self%loads(i)%acts_on(self%s(c), self%s(c + 1))) cycle
            call self%loads(i)%load%cell_skew(xm, self%ds(c), e, w, a, f, df_dx, df_de, df_dw, df_da)
            f = self%load_factor*f
            self%load_node(:, c) = self%load_node(:, c) + self%ds(c)*f
            self%load_node(:, c + 1) = self%load_node(:, c + 1) - self%ds(c)*f
            if (.not. with_jacobian) cycle
            kin = self%ds(c)*dx_coef*df_dx
            if (dt > 0) kin = kin + self%ds(c)*(df_dw/(2*dt) + df_da/(2*theta*dt*dt))
            self%skew_block(:, :, 0, c) = self%skew_block(:, :, 0, c) + self%load_factor*(-de_coef*df_de + kin)
            self%skew_block(:, :, 1, c) = self%skew_block(:, :, 1, c) + self%load_factor*(de_coef*df_de + kin)
         end do
      end do
   end subroutine cell_loads
end submodule xcable_model_rod_loads
