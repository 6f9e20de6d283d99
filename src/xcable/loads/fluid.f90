!> Fluid loads on the cable (&fluid): buoyancy, Morison drag and added mass.
!>
!> Per unstretched length, on a cell with stretch vector e (|e| = 1 + eps,
!> tangent t = e / |e|), velocity w and acceleration a, in a fluid of density
!> rho moving with the uniform current U:
!>
!>     buoyancy   rho A g upward (A the unstretched cross-section: the volume of
!>                a piece of rope does not change as it stretches)
!>     drag       1/2 rho d sqrt(1 + eps) [Cdn |V_n| V_n + pi Cdt |V_t| V_t],
!>                V = U - w the velocity of the fluid relative to the cable, V_t
!>                its part along t and V_n the rest; d sqrt(1 + eps) is the
!>                stretched diameter d / sqrt(1 + eps) times the stretched length
!>                (1 + eps) of a unit of unstretched length
!>     added mass -Ca rho A (a_n), a_n the part of a normal to t (the fluid does not
!>                accelerate: a uniform, steady current)
!>
!> The coefficients follow MoorDyn's and OrcaFlex's convention: Cdn on the
!> diameter (projected area d per length), Cdt on the surface (pi d per length),
!> Ca on the displaced volume. The derivatives of |V| V are |V| I + V V^T / |V|,
!> continuous and zero at V = 0.
module xcable_loads_fluid
   use xcable_core_kinds, only: dp
   use xcable_loads_load, only: cable_load
   use xcable_numerics_vector3, only: outer3, identity3
   implicit none
   private
   public :: fluid_load

   real(dp), parameter :: pi = acos(-1.0_dp)

   !> A fluid around the cable.
   type, extends(cable_load) :: fluid_load
      !> Fluid density, kg/m^3.
      real(dp) :: density = 0
      !> Normal and tangential drag coefficients, normal added-mass coefficient.
      real(dp) :: cd_normal = 0, cd_tangential = 0, ca_normal = 0
      !> Uniform current (x, z), m/s.
      real(dp) :: current(2) = 0
      !> Its y component, seen only by the 3-D rod, m/s.
      real(dp) :: current_y = 0
      !> Unstretched diameter (m) and cross-section (m^2) of the cable; gravity, m/s^2.
      real(dp) :: diameter = 0, area = 0, gravity = 0
   contains
      procedure :: name => fluid_name
      procedure :: cell_force => fluid_cell_force
      procedure :: lift => fluid_lift
      procedure :: has_3d => fluid_has_3d
      procedure :: cell_force3 => fluid_cell_force3
   end type fluid_load

contains

   pure function fluid_name(self) result(name)
      class(fluid_load), intent(in) :: self
      character(:), allocatable :: name
      name = 'fluid'
   end function fluid_name

   !> Buoyancy per unstretched length, N/m.
   pure real(dp) function fluid_lift(self)
      class(fluid_load), intent(in) :: self
      fluid_lift = self%density*self%area*self%gravity
   end function fluid_lift

   !> Drag and added mass per unstretched length on a cell, and their derivatives.
   pure subroutine fluid_cell_force(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      !> Mid position and unstretched length of the cell (unused: the fluid is the same everywhere).
      real(dp), intent(in) :: x(2), ds
      real(dp), intent(in) :: e(2), w(2), a(2)
      real(dp), intent(out) :: f(2), df_dx(2, 2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      real(dp) :: l, t(2), tt(2, 2), pn(2, 2), v(2), vt(2), vn(2), k, root, ma, drag(2), dd_dt(2, 2), dd_dv(2, 2)
      real(dp) :: turn(2, 2)
      df_dx = 0
      l = norm2(e)
      t = e/l
      tt = outer(t, t)
      pn = identity() - tt
      v = self%current - w
      vt = matmul(tt, v)
      vn = v - vt
      k = 0.5_dp*self%density*self%diameter
      root = sqrt(l)
      ! Drag: k root D, D = Cdn g(V_n) + pi Cdt g(V_t), g(V) = |V| V.
      drag = self%cd_normal*norm2(vn)*vn + pi*self%cd_tangential*norm2(vt)*vt
      dd_dv = self%cd_normal*matmul(dg(vn), pn) + pi*self%cd_tangential*matmul(dg(vt), tt)
      ! d(T V)/dt = (t . V) I + t V^T, d(P V)/dt = -that.
      turn = dot_product(t, v)*identity() + outer(t, v)
      dd_dt = matmul(pi*self%cd_tangential*dg(vt) - self%cd_normal*dg(vn), turn)
      ma = self%ca_normal*self%density*self%area
      f = k*root*drag - ma*matmul(pn, a)
      df_dw = -k*root*dd_dv
      df_da = -ma*pn
      ! Through t = e / l (dt/de = P / l) and sqrt(l) (d sqrt(l)/de = t^T / (2 sqrt(l))).
      df_de = k*(outer(drag, t)/(2*root) + root*matmul(dd_dt, pn)/l) &
              + ma*matmul(dot_product(t, a)*identity() + outer(t, a), pn)/l
   end subroutine fluid_cell_force

   pure logical function fluid_has_3d(self)
      class(fluid_load), intent(in) :: self
      fluid_has_3d = .true.
   end function fluid_has_3d

   !> The 3-D form of fluid_cell_force: the same formulas with vectors (x, y, z), the
   !> current (current(1), current_y, current(2)).
   pure subroutine fluid_cell_force3(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      !> Mid position and unstretched length of the cell (unused: the fluid is the same everywhere).
      real(dp), intent(in) :: x(3), ds
      real(dp), intent(in) :: e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      real(dp) :: l, t(3), tt(3, 3), pn(3, 3), v(3), vt(3), vn(3), k, root, ma, drag(3), dd_dt(3, 3), dd_dv(3, 3)
      real(dp) :: turn(3, 3), eye(3, 3)
      eye = identity3()
      df_dx = 0
      l = norm2(e)
      t = e/l
      tt = outer3(t, t)
      pn = eye - tt
      v = [self%current(1), self%current_y, self%current(2)] - w
      vt = matmul(tt, v)
      vn = v - vt
      k = 0.5_dp*self%density*self%diameter
      root = sqrt(l)
      drag = self%cd_normal*norm2(vn)*vn + pi*self%cd_tangential*norm2(vt)*vt
      dd_dv = self%cd_normal*matmul(dg3(vn), pn) + pi*self%cd_tangential*matmul(dg3(vt), tt)
      turn = dot_product(t, v)*eye + outer3(t, v)
      dd_dt = matmul(pi*self%cd_tangential*dg3(vt) - self%cd_normal*dg3(vn), turn)
      ma = self%ca_normal*self%density*self%area
      f = k*root*drag - ma*matmul(pn, a)
      df_dw = -k*root*dd_dv
      df_da = -ma*pn
      df_de = k*(outer3(drag, t)/(2*root) + root*matmul(dd_dt, pn)/l) &
              + ma*matmul(dot_product(t, a)*eye + outer3(t, a), pn)/l
   end subroutine fluid_cell_force3

   pure function dg3(v) result(m)
      real(dp), intent(in) :: v(3)
      real(dp) :: m(3, 3), s
      s = norm2(v)
      if (s > 0) then
         m = s*identity3() + outer3(v, v)/s
      else
         m = 0
      end if
   end function dg3

   !> d(|V| V)/dV = |V| I + V V^T / |V| (0 at V = 0).
   pure function dg(v) result(m)
      real(dp), intent(in) :: v(2)
      real(dp) :: m(2, 2), s
      s = norm2(v)
      if (s > 0) then
         m = s*identity() + outer(v, v)/s
      else
         m = 0
      end if
   end function dg

   pure function outer(a, b) result(m)
      real(dp), intent(in) :: a(2), b(2)
      real(dp) :: m(2, 2)
      m(:, 1) = a*b(1)
      m(:, 2) = a*b(2)
   end function outer

   pure function identity() result(m)
      real(dp) :: m(2, 2)
      m = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
   end function identity
end module xcable_loads_fluid
