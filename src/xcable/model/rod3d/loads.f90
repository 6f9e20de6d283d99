!> The external loads on a 3-D piece: the distributed loads (rod3d_set_loads, apply_loads) and the
!> ends' applied couples (add_couples, on the plane of couple_plane).
!> (A submodule of model/rod3d.f90.)
submodule (xcable_model_rod3d) xcable_model_rod3d_loads
   implicit none

contains

   !> Set the distributed loads (their lift must already be off the weight given to init).
   module subroutine rod3d_set_loads(self, loads, error)
      !> Piece.
      class(rod3d_piece), intent(inout) :: self
      !> Loads.
      type(load_slot), intent(in) :: loads(:)
      !> Error for a load without a 3-D form.
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      do i = 1, size(loads)
         if (.not. loads(i)%load%has_3d()) then
            call fatal_error(error, "the load '"//loads(i)%load%name()//"' has no 3-D form", stat_input)
            return
         end if
      end do
      self%loads = loads
   end subroutine rod3d_set_loads

   !> The distributed loads at x, as in the planar rod: each cell's force (load per unstretched
   !> length times ds) half to each of its nodes; in a step the cell's kinematics are centred
   !> on the step (stretch vector (e^n + e^n+1) / 2, velocity (R^n+1 - R^n) / dt, acceleration
   !> (V^n+1 - V^n) / dt, means of its two nodes), in statics e of x at rest.
   module subroutine apply_loads(self, x, dt, theta, with_jacobian)
      class(rod3d_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt, theta
      logical, intent(in) :: with_jacobian
      call cell_loads(self, x, dt, theta, with_jacobian)
      if (allocated(self%points)) call point_loads(self, x, dt)
   end subroutine apply_loads

   !> The buoyancy and drag of the bodies at nodes on load_node, and its derivative in point_jac (scaled by
   !> load_factor like the cells' loads).
   subroutine point_loads(self, x, dt)
      class(rod3d_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt
      integer :: i, k
      real(dp) :: f(3), jac(3, 3)
      do i = 1, size(self%points)
         k = self%point_node(i)
         if (dt > 0) then
            call self%points(i)%force(dt, self%r0(:, k), x(3*k - 2:3*k), f, jac)
         else
            call self%points(i)%force(dt, x(3*k - 2:3*k), x(3*k - 2:3*k), f, jac)
         end if
         self%load_node(:, k) = self%load_node(:, k) + self%load_factor*f
         self%point_jac(:, :, i) = self%load_factor*jac
      end do
   end subroutine point_loads

   !> The distributed loads along the cells (apply_loads).
   subroutine cell_loads(self, x, dt, theta, with_jacobian)
      class(rod3d_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt, theta
      logical, intent(in) :: with_jacobian
      integer :: c, i, n
      logical :: ranged
      real(dp) :: e(3), w(3), a(3), f(3), df_de(3, 3), df_dw(3, 3), df_da(3, 3), r1(3, 2), de_coef, kin(3, 3), &
                  xm(3), dx_coef, df_dx(3, 3)
      self%load_node = 0
      self%skewed = .false.
      if (.not. allocated(self%loads)) return
      if (size(self%loads) == 0) return
      n = self%n
      self%load_block = 0
      self%skewed = any_skew(self%loads)
      if (self%skewed) self%skew_block = 0
      ! Loads on part of the line (a line of segments: each segment's on its own cells).
      ranged = any(self%loads%s_from > -huge(1.0_dp) .or. self%loads%s_to < huge(1.0_dp))
      do c = 1, n - 1
         r1 = reshape(x(3*c - 2:3*c + 3), [3, 2])
         call cell_kinematics(self%e0(:, c), self%e1(:, c), self%r0(:, c:c + 1), self%v0(:, c:c + 1), r1, dt, theta, &
                              e, w, a, de_coef, xm, dx_coef)
         do i = 1, size(self%loads)
            if (ranged) then
               if (.not. self%loads(i)%acts_on(self%s(c), self%s(c + 1))) cycle
            end if
            call self%loads(i)%load%cell_force3(xm, self%ds(c), e, w, a, f, df_dx, df_de, df_dw, df_da)
            f = self%load_factor*f
            self%load_node(:, c) = self%load_node(:, c) + 0.5_dp*self%ds(c)*f
            self%load_node(:, c + 1) = self%load_node(:, c + 1) + 0.5_dp*self%ds(c)*f
            if (.not. with_jacobian) cycle
            ! dF_c/dR_b = ds [df/dx dx/dR_b + df/de de/dR_b + df/dw dw/dR_b + df/da da/dR_b],
            ! dx/dR_b = dx_coef, de/dR_b = +-de_coef / ds.
            kin = self%ds(c)*dx_coef*df_dx
            if (dt > 0) kin = kin + self%ds(c)*(df_dw/(2*dt) + df_da/(2*theta*dt*dt))
            self%load_block(:, :, 0, c) = self%load_block(:, :, 0, c) + self%load_factor*(-de_coef*df_de + kin)
            self%load_block(:, :, 1, c) = self%load_block(:, :, 1, c) + self%load_factor*(de_coef*df_de + kin)
         end do
         ! The unequal shares: node c takes +ds g, node c + 1 -ds g.
         if (.not. self%skewed) cycle
         do i = 1, size(self%loads)
            if (.not. self%loads(i)%load%has_skew()) cycle
            if (ranged) then
               if (.not. self%loads(i)%acts_on(self%s(c), self%s(c + 1))) cycle
            end if
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

   !> The applied couples of the ends on the end cells. A couple C about the
   !> unit axis a (end_condition%couple_axis: -y for the planar input's couple,
   !> positive counter-clockwise in the x-z plane) does the work C dphi, dphi
   !> the change of the angle of the cell's projection on the plane normal to
   !> a (couple_plane): in statics the force -C grad(phi) / ds, in a step the
   !> time-averaged couple times the planar rod's exact discrete gradient of
   !> that angle, perp(p_mid) dphi / (sin(dphi) |p0| |p1|) of the projections p.
   module subroutine add_couples(self, ta, tb, step, with_jacobian)
      class(rod3d_piece), intent(inout) :: self
      real(dp), intent(in) :: ta, tb
      logical, intent(in) :: step, with_jacobian
      real(dp) :: couple, p0(2), p1(2), pm(2), l0, l1, cross01, dphi, rho, drho, g, gvec(2), dg(2), dgvec(2, 2)
      real(dp) :: jm(2, 2), jp(2, 2), basis(3, 2)
      integer :: c, side, j
      jm = reshape([0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp], [2, 2])
      do side = 1, 2
         if (side == 1) then
            c = 1
            couple = 0.5_dp*(self%end_a%applied_couple(ta) + self%end_a%applied_couple(tb))
            basis = couple_plane(self%end_a%couple_axis())
         else
            c = self%n - 1
            couple = 0.5_dp*(self%end_b%applied_couple(ta) + self%end_b%applied_couple(tb))
            basis = couple_plane(self%end_b%couple_axis())
         end if
         if (couple == 0) cycle
         p1 = matmul(self%e1(:, c), basis)
         l1 = norm2(p1)
         if (step) then
            p0 = matmul(self%e0(:, c), basis)
            l0 = norm2(p0)
            pm = 0.5_dp*(p0 + p1)
            cross01 = p0(1)*p1(2) - p0(2)*p1(1)
            dphi = atan2(cross01, dot_product(p0, p1))
            if (abs(dphi) < small_rotation) then
               rho = 1 + dphi**2/6
               drho = dphi/3
            else
               rho = dphi/sin(dphi)
               drho = (sin(dphi) - dphi*cos(dphi))/sin(dphi)**2
            end if
            g = rho/(l0*l1)
            gvec = [-pm(2), pm(1)]*g
            ! d gvec / d p1 = g jm / 2 + perp(pm) dg^T, dg = drho dphi/dp1 / (l0 l1) - rho p1 / (l0 l1^3).
            dg = drho*[-p1(2), p1(1)]/l1**2/(l0*l1) - rho/(l0*l1**2)*p1/l1
            do j = 1, 2
               dgvec(:, j) = 0.5_dp*g*jm(:, j) + [-pm(2), pm(1)]*dg(j)
            end do
         else
            gvec = [-p1(2), p1(1)]/l1**2
            jp = (jm - 2*outer2([-p1(2), p1(1)], p1)/l1**2)/l1**2
            dgvec = jp
         end if
         ! Back to x, y, z: the force B g and the block B dg B^T of the plane's basis B.
         self%force(:, c) = self%force(:, c) - couple*matmul(basis, gvec)/self%ds(c)
         if (with_jacobian) self%block(:, :, 0, c) = self%block(:, :, 0, c) &
                                                     - couple*matmul(basis, matmul(dgvec, transpose(basis)))/self%ds(c)
      end do

   contains

      pure function outer2(u, v) result(m)
         real(dp), intent(in) :: u(2), v(2)
         real(dp) :: m(2, 2)
         m(:, 1) = u*v(1)
         m(:, 2) = u*v(2)
      end function outer2
   end subroutine add_couples

   !> An orthonormal basis (u, w) of the plane normal to the unit axis a, with
   !> u x w = a: u the unit projection of x on the plane (of z when a is near
   !> x). For a = -y it is (x, z) exactly, the planar couple's plane.
   module pure function couple_plane(axis) result(basis)
      !> Unit axis.
      real(dp), intent(in) :: axis(3)
      real(dp) :: basis(3, 2), u(3)
      u = [1.0_dp, 0.0_dp, 0.0_dp]
      if (abs(axis(1)) > 0.9_dp) u = [0.0_dp, 0.0_dp, 1.0_dp]
      u = u - dot_product(u, axis)*axis
      u = u/norm2(u)
      basis(:, 1) = u
      basis(:, 2) = cross3(axis, u)
   end function couple_plane
end submodule xcable_model_rod3d_loads
