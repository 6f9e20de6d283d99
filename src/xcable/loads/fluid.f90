!> Fluid loads on the cable (&fluid): buoyancy, Morison drag and added mass, on the
!> part of the cable under the water's surface, and the air's above it.
!>
!> Per unstretched length, on a cell with stretch vector e (|e| = 1 + eps,
!> tangent t = e / |e|), velocity w and acceleration a, in a fluid of density
!> rho moving with the current U:
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
!>
!> The surface (loads/surface.f90): a cell whose wetted fraction is phi takes
!> phi of the water's loads (density rho_w, the current) and 1 - phi of the
!> air's (density rho_a, still air). The water's buoyancy rho_w A g is given as
!> the load's lift (the scene takes it off the weight, as for a cable all under
!> water), so the force of a cell adds the buoyancy it lacks above the surface,
!> -(1 - phi) (rho_w - rho_a) A g upward. phi depends on the heights of the
!> cell's two ends, z -+ e_z ds / 2: the force's derivatives with respect to the
!> mid position and the stretch vector carry it.
module xcable_loads_fluid
   use xcable_core_kinds, only: dp
   use xcable_core_strings, only: quantity
   use xcable_loads_load, only: cable_load
   use xcable_numerics_vector3, only: outer3, identity3
   use xcable_loads_surface, only: water_surface
   use xcable_io_config, only: case_config
   implicit none
   private
   public :: fluid_load, fluid_from_case

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
      !> The water's surface (its level huge: all of the cable in the fluid).
      type(water_surface) :: surface = water_surface(level=huge(1.0_dp), band=0)
      !> Density of the air above the surface, kg/m^3 (same coefficients as in the water).
      real(dp) :: air_density = 0
   contains
      procedure :: name => fluid_name
      procedure :: cell_force => fluid_cell_force
      procedure :: lift => fluid_lift
      procedure :: has_3d => fluid_has_3d
      procedure :: cell_force3 => fluid_cell_force3
      !> Wetted fraction of a cell with mid height z and vertical stretch e_z.
      procedure :: wetted => fluid_wetted
      procedure :: measure_name => fluid_measure_name
      procedure :: cell_measure => fluid_cell_measure
      procedure :: measure_note => fluid_measure_note
   end type fluid_load

contains

   !> The fluid of a case (&fluid): the water below its surface and the air above it; with no
   !> water (density 0), the air all around the cable; none without either.
   subroutine fluid_from_case(config, area, load)
      !> Validated case.
      type(case_config), intent(in) :: config
      !> Unstretched cross-section of the cable, m^2.
      real(dp), intent(in) :: area
      !> The fluid, or unallocated.
      class(cable_load), allocatable, intent(out) :: load
      type(fluid_load) :: fluid
      real(dp) :: band
      if (config%fluid_density <= 0 .and. config%air_density <= 0) return
      fluid = fluid_load(density=config%fluid_density, cd_normal=config%cd_normal, cd_tangential=config%cd_tangential, &
                         ca_normal=config%ca_normal, current=[config%current_x, config%current_z], &
                         current_y=config%current_y, diameter=config%diameter, area=area, gravity=config%gravity)
      if (config%fluid_density > 0) then
         band = config%surface_band
         if (band < 0) band = config%diameter
         fluid%surface = water_surface(level=config%surface_z, band=band)
         fluid%air_density = config%air_density
      else
         fluid%density = config%air_density
      end if
      allocate (load, source=fluid)
   end subroutine fluid_from_case

   pure function fluid_name(self) result(name)
      class(fluid_load), intent(in) :: self
      character(:), allocatable :: name
      name = 'fluid'
   end function fluid_name

   !> Buoyancy per unstretched length all under water, N/m.
   pure real(dp) function fluid_lift(self)
      class(fluid_load), intent(in) :: self
      fluid_lift = self%density*self%area*self%gravity
   end function fluid_lift

   pure logical function fluid_has_3d(self)
      class(fluid_load), intent(in) :: self
      fluid_has_3d = .true.
   end function fluid_has_3d

   !> Wetted fraction phi of a cell with mid height z, unstretched length ds and vertical
   !> stretch ez (its ends at z -+ ez ds / 2), and dphi/dz, dphi/dez.
   pure subroutine fluid_wetted(self, z, ds, ez, phi, dphi_dz, dphi_de)
      class(fluid_load), intent(in) :: self
      real(dp), intent(in) :: z, ds, ez
      real(dp), intent(out) :: phi, dphi_dz, dphi_de
      real(dp) :: d1, d2
      call self%surface%wetted_fraction(z - 0.5_dp*ez*ds, z + 0.5_dp*ez*ds, phi, d1, d2)
      dphi_dz = d1 + d2
      dphi_de = 0.5_dp*ds*(d2 - d1)
   end subroutine fluid_wetted

   !> The wetted length, when there is water with a surface.
   pure function fluid_measure_name(self) result(name)
      class(fluid_load), intent(in) :: self
      character(:), allocatable :: name
      name = ''
      if (self%density > 0 .and. self%surface%level < huge(1.0_dp)) name = 'wetted_length'
   end function fluid_measure_name

   !> The unstretched length of a cell under water, ds phi, m.
   pure real(dp) function fluid_cell_measure(self, r1, r2, ds)
      class(fluid_load), intent(in) :: self
      real(dp), intent(in) :: r1(:), r2(:), ds
      real(dp) :: phi, d1, d2
      call self%surface%wetted_fraction(r1(size(r1)), r2(size(r2)), phi, d1, d2)
      fluid_cell_measure = ds*phi
   end function fluid_cell_measure

   !> Says when part of the cable is out of the water.
   function fluid_measure_note(self, value, length) result(text)
      class(fluid_load), intent(in) :: self
      real(dp), intent(in) :: value, length
      character(:), allocatable :: text
      text = ''
      if (value >= length*(1 - 1.0e-12_dp)) return
      if (value <= 0) then
         text = 'the line is out of the water at the start (all of it above surface_z = '// &
                quantity(self%surface%level, 'm')//')'
      else
         text = 'part of the line is out of the water at the start: wetted length '//quantity(value, 'm')// &
                ' of '//quantity(length, 'm')//' (surface_z = '//quantity(self%surface%level, 'm')//')'
      end if
   end function fluid_measure_note

   !> Force per unstretched length on a cell and its derivatives, planar (x, z).
   pure subroutine fluid_cell_force(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      !> Mid position and unstretched length of the cell (for its wetted fraction).
      real(dp), intent(in) :: x(2), ds
      real(dp), intent(in) :: e(2), w(2), a(2)
      real(dp), intent(out) :: f(2), df_dx(2, 2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      real(dp) :: phi, dphi_dz, dphi_de, fa(2), fa_de(2, 2), fa_dw(2, 2), fa_da(2, 2)
      df_dx = 0
      call self%wetted(x(2), ds, e(2), phi, dphi_dz, dphi_de)
      ! All under water (the common case): the water's loads alone.
      call morison2(self, self%density, self%current, e, w, a, f, df_de, df_dw, df_da)
      if (phi == 1) return
      fa = 0; fa_de = 0; fa_dw = 0; fa_da = 0
      if (self%air_density > 0) call morison2(self, self%air_density, [0.0_dp, 0.0_dp], e, w, a, fa, fa_de, fa_dw, fa_da)
      call mix(self, phi, dphi_dz, dphi_de, fa, fa_de, fa_dw, fa_da, f, df_dx, df_de, df_dw, df_da)
   end subroutine fluid_cell_force

   !> The 3-D form of fluid_cell_force: the same formulas with vectors (x, y, z), the
   !> current (current(1), current_y, current(2)).
   pure subroutine fluid_cell_force3(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      !> Mid position and unstretched length of the cell (for its wetted fraction).
      real(dp), intent(in) :: x(3), ds
      real(dp), intent(in) :: e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      real(dp) :: phi, dphi_dz, dphi_de, fa(3), fa_de(3, 3), fa_dw(3, 3), fa_da(3, 3)
      df_dx = 0
      call self%wetted(x(3), ds, e(3), phi, dphi_dz, dphi_de)
      call morison3(self, self%density, [self%current(1), self%current_y, self%current(2)], e, w, a, f, df_de, df_dw, &
                    df_da)
      if (phi == 1) return
      fa = 0; fa_de = 0; fa_dw = 0; fa_da = 0
      if (self%air_density > 0) call morison3(self, self%air_density, [0.0_dp, 0.0_dp, 0.0_dp], e, w, a, fa, fa_de, &
                                              fa_dw, fa_da)
      call mix(self, phi, dphi_dz, dphi_de, fa, fa_de, fa_dw, fa_da, f, df_dx, df_de, df_dw, df_da)
   end subroutine fluid_cell_force3

   !> A cell across the surface, any dimension (the last component vertical): f and its
   !> derivatives hold the water's loads on entry and leave as phi of them, 1 - phi of the air's
   !> (fa and its derivatives) and the buoyancy the dry part lacks, with the fraction's
   !> derivatives through the cell's mid height and vertical stretch.
   pure subroutine mix(self, phi, dphi_dz, dphi_de, fa, fa_de, fa_dw, fa_da, f, df_dx, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      real(dp), intent(in) :: phi, dphi_dz, dphi_de, fa(:), fa_de(:, :), fa_dw(:, :), fa_da(:, :)
      real(dp), intent(inout) :: f(:), df_dx(:, :), df_de(:, :), df_dw(:, :), df_da(:, :)
      real(dp) :: jump(size(f)), lack
      integer :: nd
      nd = size(f)
      ! f = phi F_w + (1 - phi) F_a - (1 - phi) (rho_w - rho_a) A g z^.
      lack = (self%density - self%air_density)*self%area*self%gravity
      jump = f - fa
      jump(nd) = jump(nd) + lack
      f = phi*f + (1 - phi)*fa
      f(nd) = f(nd) - (1 - phi)*lack
      df_de = phi*df_de + (1 - phi)*fa_de
      df_dw = phi*df_dw + (1 - phi)*fa_dw
      df_da = phi*df_da + (1 - phi)*fa_da
      df_dx(:, nd) = jump*dphi_dz
      df_de(:, nd) = df_de(:, nd) + jump*dphi_de
   end subroutine mix

   !> Drag and added mass per unstretched length in a fluid of density rho moving with the
   !> current, planar, and their derivatives with respect to e, w and a (fixed sizes: the
   !> inner loop of every cell of a line in water).
   pure subroutine morison2(self, rho, current, e, w, a, f, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      real(dp), intent(in) :: rho, current(2), e(2), w(2), a(2)
      real(dp), intent(out) :: f(2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      real(dp) :: l, t(2), tt(2, 2), pn(2, 2), v(2), vt(2), vn(2), k, root, ma, drag(2), dd_dt(2, 2), dd_dv(2, 2)
      real(dp) :: turn(2, 2)
      l = norm2(e)
      t = e/l
      tt = outer2(t, t)
      pn = identity2() - tt
      v = current - w
      vt = matmul(tt, v)
      vn = v - vt
      k = 0.5_dp*rho*self%diameter
      root = sqrt(l)
      ! Drag: k root D, D = Cdn g(V_n) + pi Cdt g(V_t), g(V) = |V| V.
      drag = self%cd_normal*norm2(vn)*vn + pi*self%cd_tangential*norm2(vt)*vt
      dd_dv = self%cd_normal*matmul(dg2(vn), pn) + pi*self%cd_tangential*matmul(dg2(vt), tt)
      ! d(T V)/dt = (t . V) I + t V^T, d(P V)/dt = -that.
      turn = dot_product(t, v)*identity2() + outer2(t, v)
      dd_dt = matmul(pi*self%cd_tangential*dg2(vt) - self%cd_normal*dg2(vn), turn)
      ma = self%ca_normal*rho*self%area
      f = k*root*drag - ma*matmul(pn, a)
      df_dw = -k*root*dd_dv
      df_da = -ma*pn
      ! Through t = e / l (dt/de = P / l) and sqrt(l) (d sqrt(l)/de = t^T / (2 sqrt(l))).
      df_de = k*(outer2(drag, t)/(2*root) + root*matmul(dd_dt, pn)/l) &
              + ma*matmul(dot_product(t, a)*identity2() + outer2(t, a), pn)/l
   end subroutine morison2

   !> morison2 in 3-D.
   pure subroutine morison3(self, rho, current, e, w, a, f, df_de, df_dw, df_da)
      class(fluid_load), intent(in) :: self
      real(dp), intent(in) :: rho, current(3), e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      real(dp) :: l, t(3), tt(3, 3), pn(3, 3), v(3), vt(3), vn(3), k, root, ma, drag(3), dd_dt(3, 3), dd_dv(3, 3)
      real(dp) :: turn(3, 3), eye(3, 3)
      eye = identity3()
      l = norm2(e)
      t = e/l
      tt = outer3(t, t)
      pn = eye - tt
      v = current - w
      vt = matmul(tt, v)
      vn = v - vt
      k = 0.5_dp*rho*self%diameter
      root = sqrt(l)
      drag = self%cd_normal*norm2(vn)*vn + pi*self%cd_tangential*norm2(vt)*vt
      dd_dv = self%cd_normal*matmul(dg3(vn), pn) + pi*self%cd_tangential*matmul(dg3(vt), tt)
      turn = dot_product(t, v)*eye + outer3(t, v)
      dd_dt = matmul(pi*self%cd_tangential*dg3(vt) - self%cd_normal*dg3(vn), turn)
      ma = self%ca_normal*rho*self%area
      f = k*root*drag - ma*matmul(pn, a)
      df_dw = -k*root*dd_dv
      df_da = -ma*pn
      df_de = k*(outer3(drag, t)/(2*root) + root*matmul(dd_dt, pn)/l) &
              + ma*matmul(dot_product(t, a)*eye + outer3(t, a), pn)/l
   end subroutine morison3

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

   !> d(|V| V)/dV = |V| I + V V^T / |V| (0 at V = 0), planar.
   pure function dg2(v) result(m)
      real(dp), intent(in) :: v(2)
      real(dp) :: m(2, 2), s
      s = norm2(v)
      if (s > 0) then
         m = s*identity2() + outer2(v, v)/s
      else
         m = 0
      end if
   end function dg2

   pure function outer2(a, b) result(m)
      real(dp), intent(in) :: a(2), b(2)
      real(dp) :: m(2, 2)
      m(:, 1) = a*b(1)
      m(:, 2) = a*b(2)
   end function outer2

   pure function identity2() result(m)
      real(dp) :: m(2, 2)
      m = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
   end function identity2
end module xcable_loads_fluid
