!> The 3-D rod's bending in a time step, on arrays (it knows no piece): the divided difference
!> of the bending energy B(th) = 2 EI tan^2(th / 2) / h_k between the old and the new turning
!> angle of a node, and the discrete gradient of the turning angle written with rotation vectors,
!> with its derivatives for the Jacobian (docs/theory/model3d.md; model/rod3d.f90 describes the
!> scheme). The bending part of node k is mom_k grad th_k, mom_k the divided difference of B
!> between th_k^n and th_k^n+1 and grad th_k a discrete gradient of the turning angle: the
!> change of th_k is split into the changes of a with b held (at b^n and at b^n+1, averaged) and
!> of b with a held, and each one-vector change of the scale-free function g(x) = th(x, y) gets
!>
!>     D = grad g(x_mid) + [g(x1) - g(x0) - grad g(x_mid) . (x1 - x0)] (c x x_mid) / |c|^2,  c = x0 x x1,
!>
!> which satisfies D . (x1 - x0) = g(x1) - g(x0) exactly, tends to grad g as the step shrinks
!> and, in a plane, equals the planar rod's perp(x_mid) dphi / (sin(dphi) |x0| |x1|). Below a
!> rotation of 1e-8 rad in a step the bracket (third order in the rotation) is dropped.
!>
!> Its own module so that its helpers stay private: gfortran 12 inlines and specialises a
!> module's private procedures within their module, and neither a submodule's procedures nor a
!> public one (a global symbol may be interposed under fpm's -fPIC). The piece
!> (model/rod3d.f90, step_bending and step_bending_jacobian) calls one public kernel per node;
!> the other public procedures are wrappers for the piece's cold parts.
module xcable_model_rod3d_kernels
   use xcable_core_kinds, only: dp
   use xcable_numerics_tan, only: fast_tan
   implicit none
   private
   public :: node_bending, node_bending_jacobian, rotation_vector, bend_energy_of, bend_moment_of, small_rotation

   !> Turning-angle differences below this use the Taylor form of the divided difference.
   real(dp), parameter :: small_rotation = 1.0e-4_dp
   !> Cell rotations in a step below this drop the third-order bracket of the discrete gradient.
   real(dp), parameter :: bracket_rotation = 1.0e-8_dp

contains

   !> A node's bending in a step, values only (node_bending_jacobian's forces to the same bits):
   !> B1 - B0 = coef (phi1 + phi0) . (phi1 - phi0), phi1 - phi0 = Ja (a1 - a0) + Jb (b1 - b0), Ja
   !> carrying the mean of the changes of a at b0 and at b1, Jb that of the changes of b at a0 and
   !> at a1, each about the Jacobian at the mid vectors.
   pure subroutine node_bending(a0, a, b0, b, phi0, ei, hk, fa, fb)
      !> The node's two cell vectors at the old level (a0, b0) and at the new (a, b).
      real(dp), intent(in) :: a0(3), a(3), b0(3), b(3)
      !> The rotation vector of the old turning, phi(a0, b0).
      real(dp), intent(in) :: phi0(3)
      !> The node's EI (N m^2) and its length h_k (m).
      real(dp), intent(in) :: ei, hk
      !> Ja^T p and Jb^T p: the forces on the cells before and after the node times their ds, N m.
      real(dp), intent(out) :: fa(3), fb(3)
      real(dp) :: phi1(3), phi_a1b0(3), phi_a0b1(3), q1, coef, psum(3)
      real(dp) :: ja(3, 3), jb(3, 3)
      integer :: i
      call rotation_vector_r(a, b, phi1)
      call rotation_vector_r(a, b0, phi_a1b0)
      call rotation_vector_r(a0, b, phi_a0b1)
      q1 = phi1(1)*phi1(1) + phi1(2)*phi1(2) + phi1(3)*phi1(3)
      coef = bend_coefficient_r(ei, hk, phi0(1)**2 + phi0(2)**2 + phi0(3)**2, q1)
      psum = (phi1 + phi0)*coef
      ! phi(a, b) = -phi(b, a): the changes in b are those of -phi(b, a).
      call discrete_jacobian_r(a0, a, (b0 + b)*0.5_dp, 1.0_dp, ((phi_a1b0 - phi0) + (phi1 - phi_a0b1))*0.5_dp, ja)
      call discrete_jacobian_r(b0, b, (a0 + a)*0.5_dp, -1.0_dp, ((phi_a0b1 - phi0) + (phi1 - phi_a1b0))*0.5_dp, jb)
      do i = 1, 3
         fa(i) = ja(1, i)*psum(1) + ja(2, i)*psum(2) + ja(3, i)*psum(3)
         fb(i) = jb(1, i)*psum(1) + jb(2, i)*psum(2) + jb(3, i)*psum(3)
      end do
   end subroutine node_bending

   !> A node's bending in a step and its blocks. The forces are node_bending's (the same
   !> operations, so the same bits); their derivatives with respect to the new a and b are written
   !> out: those of the rotation vectors (rotation_vector_r), of the bending coefficient, and of
   !> each discrete Jacobian's force J^T p (discrete_force_derivatives).
   pure subroutine node_bending_jacobian(a0, a, b0, b, phi0, ei, hk, fa, fb, dfa_da, dfa_db, dfb_da, dfb_db)
      !> The node's two cell vectors at the old level (a0, b0) and at the new (a, b).
      real(dp), intent(in) :: a0(3), a(3), b0(3), b(3)
      !> The rotation vector of the old turning, phi(a0, b0).
      real(dp), intent(in) :: phi0(3)
      !> The node's EI (N m^2) and its length h_k (m).
      real(dp), intent(in) :: ei, hk
      !> Ja^T p and Jb^T p: the forces on the cells before and after the node times their ds, N m.
      real(dp), intent(out) :: fa(3), fb(3)
      !> Their derivatives with respect to the new a and b.
      real(dp), intent(out) :: dfa_da(3, 3), dfa_db(3, 3), dfb_da(3, 3), dfb_db(3, 3)
      real(dp) :: phi1(3), phi_a1b0(3), phi_a0b1(3), q1, q0, coef, dcoef, psum(3)
      real(dp) :: ja(3, 3), jb(3, 3), j1a(3, 3), j1b(3, 3), jab0(3, 3), ja0b(3, 3), dpa(3, 3), dpb(3, 3), dq(6)
      real(dp) :: ja_mid(3, 3), jb_mid(3, 3), delta_a(3), delta_b(3)
      integer :: i, j
      call rotation_vector_r(a, b, phi1, j1a, j1b)
      call rotation_vector_r(a, b0, phi_a1b0, jab0)
      call rotation_vector_r(a0, b, phi_a0b1, jy=ja0b)
      q1 = phi1(1)*phi1(1) + phi1(2)*phi1(2) + phi1(3)*phi1(3)
      q0 = phi0(1)**2 + phi0(2)**2 + phi0(3)**2
      call bend_coefficient_derivative(ei, hk, q0, q1, coef, dcoef)
      psum = (phi1 + phi0)*coef
      delta_a = ((phi_a1b0 - phi0) + (phi1 - phi_a0b1))*0.5_dp
      delta_b = ((phi_a0b1 - phi0) + (phi1 - phi_a1b0))*0.5_dp
      call discrete_jacobian_r(a0, a, (b0 + b)*0.5_dp, 1.0_dp, delta_a, ja, ja_mid)
      call discrete_jacobian_r(b0, b, (a0 + a)*0.5_dp, -1.0_dp, delta_b, jb, jb_mid)
      do i = 1, 3
         fa(i) = ja(1, i)*psum(1) + ja(2, i)*psum(2) + ja(3, i)*psum(3)
         fb(i) = jb(1, i)*psum(1) + jb(2, i)*psum(2) + jb(3, i)*psum(3)
      end do
      ! d psum = coef d phi1 + (phi1 + phi0) coef'(q1) 2 phi1^T d phi1.
      do j = 1, 3
         dq(j) = 2*dcoef*(phi1(1)*j1a(1, j) + phi1(2)*j1a(2, j) + phi1(3)*j1a(3, j))
         dq(j + 3) = 2*dcoef*(phi1(1)*j1b(1, j) + phi1(2)*j1b(2, j) + phi1(3)*j1b(3, j))
      end do
      do j = 1, 3
         dpa(:, j) = coef*j1a(:, j) + (phi1 + phi0)*dq(j)
         dpb(:, j) = coef*j1b(:, j) + (phi1 + phi0)*dq(j + 3)
      end do
      call discrete_force_derivatives(a0, a, b0, b, 1.0_dp, ja_mid, delta_a, 0.5_dp*(jab0 + j1a), 0.5_dp*(j1b - ja0b), &
                                      psum, dpa, dpb, dfa_da, dfa_db)
      call discrete_force_derivatives(b0, b, a0, a, -1.0_dp, jb_mid, delta_b, 0.5_dp*(ja0b + j1b), 0.5_dp*(j1a - jab0), &
                                      psum, dpb, dpa, dfb_db, dfb_da)
   end subroutine node_bending_jacobian

   !> rotation_vector_r without its Jacobians, for the piece's old level and fold check.
   pure subroutine rotation_vector(x, y, phi)
      real(dp), intent(in) :: x(3), y(3)
      real(dp), intent(out) :: phi(3)
      call rotation_vector_r(x, y, phi)
   end subroutine rotation_vector

   !> energy_of, for the piece's records (bend_energy).
   pure real(dp) function bend_energy_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      bend_energy_of = energy_of(ei, h, th)
   end function bend_energy_of

   !> moment_of, for the piece's records (bend_moment).
   pure real(dp) function bend_moment_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      bend_moment_of = moment_of(ei, h, th)
   end function bend_moment_of


   !> 2 EI tan^2(th / 2) / h, J: bend_energy of a node of EI ei and length h.
   pure real(dp) function energy_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      energy_of = 2*ei*fast_tan(0.5_dp*th)**2/h
   end function energy_of

   !> dB/dth of a node of EI ei and length h, N m.
   pure real(dp) function moment_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      real(dp) :: t
      t = fast_tan(0.5_dp*th)
      moment_of = 2*ei*t*(1 + t*t)/h
   end function moment_of

   !> d2B/dth2 of a node of EI ei and length h, N m.
   pure real(dp) function stiffness_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      real(dp) :: t
      t = fast_tan(0.5_dp*th)
      stiffness_of = ei*(1 + t*t)*(1 + 3*t*t)/h
   end function stiffness_of

   !> [B(th1) - B(th0)] / (th1 - th0) and its derivative in th1 (Taylor forms when close), of a
   !> node of EI ei and length hk.
   pure subroutine bend_divided(ei, hk, th0, th1, m, dm)
      real(dp), intent(in) :: ei, hk
      real(dp), intent(in) :: th0, th1
      real(dp), intent(out) :: m, dm
      real(dp) :: h, mid, t, third
      h = th1 - th0
      if (abs(h) < small_rotation) then
         mid = 0.5_dp*(th0 + th1)
         t = fast_tan(0.5_dp*mid)
         third = ei*(1 + t*t)*t*(4 + 6*t*t)/hk
         m = moment_of(ei, hk, mid) + third*h*h/24
         dm = 0.5_dp*stiffness_of(ei, hk, mid) + third*h/12
      else
         m = (energy_of(ei, hk, th1) - energy_of(ei, hk, th0))/h
         dm = (moment_of(ei, hk, th1) - m)/h
      end if
   end subroutine bend_divided

   !> bend_coefficient_r (the same operations) and its derivative in q1.
   pure subroutine bend_coefficient_derivative(ei, hk, q0, q1, coef, dcoef)
      real(dp), intent(in) :: ei, hk
      real(dp), intent(in) :: q0, q1
      real(dp), intent(out) :: coef, dcoef
      real(dp) :: th0, th1, m, dm, big
      big = 2*ei/hk
      th0 = sqrt(q0)
      th1 = sqrt(q1)
      if (th0 + th1 < 1.0e-3_dp) then
         coef = (0.25_dp + (q1 + q0)/24.0_dp + (q1*q1 + q1*q0 + q0*q0)*(17.0_dp/2880.0_dp) &
                 + (q1 + q0)*(q1*q1 + q0*q0)*(31.0_dp/40320.0_dp))*big
         dcoef = (1.0_dp/24.0_dp + (2*q1 + q0)*(17.0_dp/2880.0_dp) &
                  + ((q1*q1 + q0*q0) + (q1 + q0)*2*q1)*(31.0_dp/40320.0_dp))*big
      else
         call bend_divided(ei, hk, th0, th1, m, dm)
         coef = m/(th0 + th1)
         dcoef = (dm - coef)/(th0 + th1)/(2*max(th1, 1.0e-12_dp))
      end if
   end subroutine bend_coefficient_derivative

   !> The derivatives of f = J^T p, J the discrete Jacobian of discrete_jacobian_r(x0, x1, y, sign,
   !> delta) with y = (y0 + y1) / 2 (jx: its sign dphi/dx at the mid vectors, the J without the
   !> bracket), with respect to x1 (dfx) and y1 (dfy), given the derivatives
   !> of delta (ddx, ddy) and of p (dpx, dpy). With J = sign dphi/dx (x_mid, y) + br w^T,
   !> br = delta - sign dphi/dx dx, f = g + w beta with g = sign dphi/dx^T p and beta = br . p =
   !> delta . p - g . dx, so the only second derivatives needed are the Hessian of the scalar
   !> p . phi(x, y) in x and in x and y. Writing phi = R(c) u, u = x^ x y^, c = x^ . y^ (unit
   !> vectors; R = th / sin th), p . phi = R(c) T with T = p . u, and its gradient in x is
   !> Px v, Px = (I - x^ x^^T) / |x|, v = R' T y^ + R (y^ x p). Then
   !>
   !>     Hxx = [Q (R'' T y^ y^^T + R' (y^ q^T + q y^^T)) Px - (x^ . v) Px - x^ (Px v)^T - (Px v) x^^T] / |x|,
   !>     Hxy = Px [R'' T y^ x^^T + R' y^ m^T + R' T I + R' q x^^T - R [p]x] Py,
   !>
   !> with Q = I - x^ x^^T, q = y^ x p, m = p x x^, [p]x the cross-product matrix of p.
   pure subroutine discrete_force_derivatives(x0, x1, y0, y1, sign, jx, delta, ddx, ddy, p, dpx, dpy, dfx, dfy)
      real(dp), intent(in) :: x0(3), x1(3), y0(3), y1(3), sign, jx(3, 3), delta(3), ddx(3, 3), ddy(3, 3), p(3), &
                              dpx(3, 3), dpy(3, 3)
      real(dp), intent(out) :: dfx(3, 3), dfy(3, 3)
      real(dp) :: xm(3), y(3), nx, ny, xh(3), yh(3), u(3), s2, c, r0, r1, r2, t, q(3), m(3), v(3)
      real(dp) :: qx(3, 3), px(3, 3), py(3, 3), mm(3, 3), nn(3, 3), hxx(3, 3), hxy(3, 3), pv(3), g(3), xv
      real(dp) :: cv(3), cc, w(3), dx(3), beta, dbx(3), dby(3), dcm(3, 3), dcc(3), x0x(3, 3), xmx(3, 3)
      integer :: i, j
      xm = (x0 + x1)*0.5_dp
      y = (y0 + y1)*0.5_dp
      nx = sqrt(xm(1)**2 + xm(2)**2 + xm(3)**2)
      ny = sqrt(y(1)**2 + y(2)**2 + y(3)**2)
      xh = xm/nx
      yh = y/ny
      u = cross(xh, yh)
      s2 = u(1)**2 + u(2)**2 + u(3)**2
      c = xh(1)*yh(1) + xh(2)*yh(2) + xh(3)*yh(3)
      call turning_factors(s2, c, r0, r1, r2)
      t = p(1)*u(1) + p(2)*u(2) + p(3)*u(3)
      q = cross(yh, p)
      m = cross(p, xh)
      v = r1*t*yh + r0*q
      xv = xh(1)*v(1) + xh(2)*v(2) + xh(3)*v(3)
      do j = 1, 3
         do i = 1, 3
            qx(i, j) = merge(1.0_dp, 0.0_dp, i == j) - xh(i)*xh(j)
            py(i, j) = (merge(1.0_dp, 0.0_dp, i == j) - yh(i)*yh(j))/ny
            mm(i, j) = r2*t*yh(i)*yh(j) + r1*(yh(i)*q(j) + q(i)*yh(j))
            nn(i, j) = r2*t*yh(i)*xh(j) + r1*yh(i)*m(j) + r1*q(i)*xh(j)
         end do
         nn(j, j) = nn(j, j) + r1*t
      end do
      px = qx/nx
      nn = nn - r0*cross_matrix(p)
      pv = matmul(px, v)
      hxx = matmul(qx, matmul(mm, px)) - xv*px
      do j = 1, 3
         do i = 1, 3
            hxx(i, j) = (hxx(i, j) - xh(i)*pv(j) - pv(i)*xh(j))/nx
         end do
      end do
      hxy = matmul(px, matmul(nn, py))
      ! g = J^T p and its derivatives (J with its sign; d x_mid / d x1 = d y / d y1 = I / 2).
      g = matmul(p, jx)
      dfx = 0.5_dp*sign*hxx + matmul(transpose(jx), dpx)
      dfy = 0.5_dp*sign*hxy + matmul(transpose(jx), dpy)
      cv = cross(x0, x1)
      cc = cv(1)*cv(1) + cv(2)*cv(2) + cv(3)*cv(3)
      if (cc <= (bracket_rotation**2)*dot_product(x0, x0)*(x1(1)**2 + x1(2)**2 + x1(3)**2)) return
      dx = x1 - x0
      w = cross(cv, xm)/cc
      beta = dot_product(delta, p) - dot_product(g, dx)
      dbx = matmul(p, ddx) + matmul(delta, dpx) - matmul(dx, dfx) - g
      dby = matmul(p, ddy) + matmul(delta, dpy) - matmul(dx, dfy)
      ! w = (c x x_mid) / |c|^2, c = x0 x x1: d(c x x_mid) = (-[x_mid]x [x0]x + [c]x / 2) dx1, d|c|^2 = 2 c^T [x0]x dx1.
      x0x = cross_matrix(x0)
      xmx = cross_matrix(xm)
      dcm = -matmul(xmx, x0x) + 0.5_dp*cross_matrix(cv)
      dcc = 2*matmul(cv, x0x)
      do j = 1, 3
         do i = 1, 3
            dfx(i, j) = dfx(i, j) + (dcm(i, j) - w(i)*dcc(j))/cc*beta + w(i)*dbx(j)
            dfy(i, j) = dfy(i, j) + w(i)*dby(j)
         end do
      end do

   contains

      pure function cross(e, f) result(r)
         real(dp), intent(in) :: e(3), f(3)
         real(dp) :: r(3)
         r = [e(2)*f(3) - e(3)*f(2), e(3)*f(1) - e(1)*f(3), e(1)*f(2) - e(2)*f(1)]
      end function cross

      !> [e]x, the matrix of f -> e x f.
      pure function cross_matrix(e) result(r)
         real(dp), intent(in) :: e(3)
         real(dp) :: r(3, 3)
         r(1, 1) = 0
         r(2, 1) = e(3)
         r(3, 1) = -e(2)
         r(1, 2) = -e(3)
         r(2, 2) = 0
         r(3, 2) = e(1)
         r(1, 3) = e(2)
         r(2, 3) = -e(1)
         r(3, 3) = 0
      end function cross_matrix
   end subroutine discrete_force_derivatives

   !> R(c) = th / sin th of the turning with cos th = c, sin^2 th = s2, and its first two
   !> derivatives in c: R' = (c R - 1) / s2, R'' = (R + 3 c R') / s2, by their series in
   !> w = 1 - c = s2 / (1 + c) when w < 0.01 (truncation below 1e-15).
   pure subroutine turning_factors(s2, c, r0, r1, r2)
      real(dp), intent(in) :: s2, c
      real(dp), intent(out) :: r0, r1, r2
      real(dp), parameter :: a0(0:8) = [1.0_dp, 1.0_dp/3, 2.0_dp/15, 2.0_dp/35, 8.0_dp/315, 8.0_dp/693, 16.0_dp/3003, &
                                        16.0_dp/6435, 128.0_dp/109395]
      real(dp), parameter :: a1(0:7) = [-1.0_dp/3, -4.0_dp/15, -6.0_dp/35, -32.0_dp/315, -40.0_dp/693, -32.0_dp/1001, &
                                        -112.0_dp/6435, -1024.0_dp/109395]
      real(dp), parameter :: a2(0:6) = [4.0_dp/15, 12.0_dp/35, 32.0_dp/105, 160.0_dp/693, 160.0_dp/1001, 224.0_dp/2145, &
                                        7168.0_dp/109395]
      real(dp) :: w, s
      integer :: i
      w = 2
      if (c > 0) w = s2/(1 + c)
      if (w < 0.01_dp) then
         r0 = a0(8)
         do i = 7, 0, -1
            r0 = r0*w + a0(i)
         end do
         r1 = a1(7)
         do i = 6, 0, -1
            r1 = r1*w + a1(i)
         end do
         r2 = a2(6)
         do i = 5, 0, -1
            r2 = r2*w + a2(i)
         end do
      else
         s = sqrt(s2)
         r0 = atan2(s, c)/s
         r1 = (c*r0 - 1)/s2
         r2 = (r0 + 3*c*r1)/s2
      end if
   end subroutine turning_factors

   !> The rotation vector phi(x, y) = th u / |u|, u = x x y / (|x| |y|), of the smallest rotation
   !> taking the direction of x to that of y (|phi| = th; smooth through th = 0), with its
   !> Jacobians d phi / dx and d phi / dy when asked.
   pure subroutine rotation_vector_r(x, y, phi, jx, jy)
      real(dp), intent(in) :: x(3), y(3)
      real(dp), intent(out) :: phi(3)
      real(dp), intent(out), optional :: jx(3, 3), jy(3, 3)
      real(dp) :: nx, ny, u(3), s2, c, rho, rho_s2, rho_c, z, s, g(3), inv_xy, inv_xx, inv_yy, w(3), r(3)
      integer :: i, j
      nx = sqrt(x(1)*x(1) + x(2)*x(2) + x(3)*x(3))
      ny = sqrt(y(1)*y(1) + y(2)*y(2) + y(3)*y(3))
      u(1) = (x(2)*y(3) - x(3)*y(2))/(nx*ny)
      u(2) = (x(3)*y(1) - x(1)*y(3))/(nx*ny)
      u(3) = (x(1)*y(2) - x(2)*y(1))/(nx*ny)
      s2 = u(1)*u(1) + u(2)*u(2) + u(3)*u(3)
      c = (x(1)*y(1) + x(2)*y(2) + x(3)*y(3))/(nx*ny)
      if (c > 0 .and. s2 < 1.0e-5_dp*c**2) then
         z = s2/(c*c)
         rho = (1.0_dp - z/3.0_dp + z*z/5.0_dp - z*z*z/7.0_dp)/c
         rho_s2 = (-1.0_dp/3.0_dp + z*(2.0_dp/5.0_dp) - z*z*(3.0_dp/7.0_dp))/(c*c*c)
         rho_c = -rho/c + (-1.0_dp/3.0_dp + z*(2.0_dp/5.0_dp) - z*z*(3.0_dp/7.0_dp))*(-2.0_dp)*z/(c*c)
      else
         s = sqrt(s2)
         rho = atan2(s, c)/s
         rho_s2 = (c/(s2 + c*c) - rho)/(2.0_dp*s2)
         rho_c = -1.0_dp/(s2 + c*c)
      end if
      phi = u*rho
      if (.not. (present(jx) .or. present(jy))) return
      inv_xy = 1.0_dp/(nx*ny)
      if (present(jx)) then
         ! du/dx dx = (dx x y) / (|x| |y|) - u (x . dx) / |x|^2; (dx x y) = -[y]x dx.
         inv_xx = 1.0_dp/(nx*nx)
         w = [y(2)*u(3) - y(3)*u(2), y(3)*u(1) - y(1)*u(3), y(1)*u(2) - y(2)*u(1)]
         g = (w*inv_xy - x*(s2*inv_xx))*(2.0_dp*rho_s2) + (y*inv_xy - x*(c*inv_xx))*rho_c - x*(rho*inv_xx)
         do j = 1, 3
            do i = 1, 3
               jx(i, j) = u(i)*g(j)
            end do
         end do
         r = y*(rho*inv_xy)
         jx(1, 2) = jx(1, 2) + r(3)
         jx(1, 3) = jx(1, 3) - r(2)
         jx(2, 1) = jx(2, 1) - r(3)
         jx(2, 3) = jx(2, 3) + r(1)
         jx(3, 1) = jx(3, 1) + r(2)
         jx(3, 2) = jx(3, 2) - r(1)
      end if
      if (present(jy)) then
         ! du/dy dy = (x x dy) / (|x| |y|) - u (y . dy) / |y|^2; (x x dy) = [x]x dy.
         inv_yy = 1.0_dp/(ny*ny)
         w = [u(2)*x(3) - u(3)*x(2), u(3)*x(1) - u(1)*x(3), u(1)*x(2) - u(2)*x(1)]
         g = (w*inv_xy - y*(s2*inv_yy))*(2.0_dp*rho_s2) + (x*inv_xy - y*(c*inv_yy))*rho_c - y*(rho*inv_yy)
         do j = 1, 3
            do i = 1, 3
               jy(i, j) = u(i)*g(j)
            end do
         end do
         r = x*(rho*inv_xy)
         jy(1, 2) = jy(1, 2) - r(3)
         jy(1, 3) = jy(1, 3) + r(2)
         jy(2, 1) = jy(2, 1) + r(3)
         jy(2, 3) = jy(2, 3) - r(1)
         jy(3, 1) = jy(3, 1) - r(2)
         jy(3, 2) = jy(3, 2) + r(1)
      end if
   end subroutine rotation_vector_r

   !> Discrete Jacobian jac between x0 and x1 of the one-vector function h(x) = sign phi(x, y)
   !> (see the module header), given its change delta = h(x1) - h(x0): jac (x1 - x0) = delta
   !> exactly. jmid: sign d phi / dx at the mid vector, the part without the bracket.
   pure subroutine discrete_jacobian_r(x0, x1, y, sign, delta, jac, jmid)
      real(dp), intent(in) :: x0(3), x1(3), y(3)
      real(dp), intent(in) :: sign
      real(dp), intent(in) :: delta(3)
      real(dp), intent(out) :: jac(3, 3)
      real(dp), intent(out), optional :: jmid(3, 3)
      real(dp) :: xm(3), c(3), cc, w(3), dx(3), phi(3), bracket(3)
      integer :: i, j
      xm = (x0 + x1)*0.5_dp
      call rotation_vector_r(xm, y, phi, jac)
      if (sign < 0) jac = -jac
      if (present(jmid)) jmid = jac
      c = [x0(2)*x1(3) - x0(3)*x1(2), x0(3)*x1(1) - x0(1)*x1(3), x0(1)*x1(2) - x0(2)*x1(1)]
      cc = c(1)*c(1) + c(2)*c(2) + c(3)*c(3)
      if (cc <= (bracket_rotation**2)*dot_product(x0, x0)*(x1(1)**2 + x1(2)**2 + x1(3)**2)) return
      dx = x1 - x0
      do i = 1, 3
         bracket(i) = delta(i) - (jac(i, 1)*dx(1) + jac(i, 2)*dx(2) + jac(i, 3)*dx(3))
      end do
      w = [c(2)*xm(3) - c(3)*xm(2), c(3)*xm(1) - c(1)*xm(3), c(1)*xm(2) - c(2)*xm(1)]/cc
      do j = 1, 3
         do i = 1, 3
            jac(i, j) = jac(i, j) + bracket(i)*w(j)
         end do
      end do
   end subroutine discrete_jacobian_r

   !> [B(th1) - B(th0)] / (th1^2 - th0^2) of node k from q0 = th0^2 and q1 = th1^2: a polynomial
   !> in q near the straight state, from the divided difference in th otherwise.
   pure real(dp) function bend_coefficient_r(ei, hk, q0, q1) result(coef)
      real(dp), intent(in) :: ei, hk
      real(dp), intent(in) :: q0, q1
      real(dp) :: th0, th1, m, dm, big
      big = 2*ei/hk
      th0 = sqrt(q0)
      th1 = sqrt(q1)
      if (th0 + th1 < 1.0e-3_dp) then
         coef = (0.25_dp + (q1 + q0)/24.0_dp + (q1*q1 + q1*q0 + q0*q0)*(17.0_dp/2880.0_dp) &
                 + (q1 + q0)*(q1*q1 + q0*q0)*(31.0_dp/40320.0_dp))*big
      else
         call bend_divided(ei, hk, th0, th1, m, dm)
         coef = m/(th0 + th1)
      end if
   end function bend_coefficient_r
end module xcable_model_rod3d_kernels
