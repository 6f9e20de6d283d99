!> Fluid loads (&fluid) against closed forms: the derivatives of the cell
!> force against central differences (also where the relative velocity is
!> near zero); a cable streaming in a current at the critical angle; a
!> horizontal cable falling broadside to its terminal speed along the tanh
!> law of quadratic drag with added mass; a hanging chain in water swinging
!> with the wet weight over the dry plus added mass. (The ledger with fluid
!> loads and the step Jacobian are in suite registry.)
module suite_fluid
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_loads_fluid, only: fluid_load
   use xcable_loads_load, only: load_slot, cable_load
   use xcable_fdcheck, only: check_jacobian
   use xcable_model_rod3d, only: rod3d_kl, rod3d_ku
   use xcable_material_law, only: linear_law
   use xcable_ends_free, only: free_end
   use xcable_model_rod, only: rod_problem, rod_kl, rod_ku
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   use xcable_driver_simulation, only: simulation
   use suite_rod_statics, only: statics_config
   use suite_scenes, only: free_end_period
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_fluid

   real(dp), parameter :: pi = acos(-1.0_dp)

   !> A load that depends on the cell's position (a test of the loads' position path): a pull
   !> towards the point p0 growing with the distance and the cell's stretch, f = -k |e| (x - p0),
   !> so df/dx = -k |e| I and df/de = -k (x - p0) e^T / |e|.
   type, extends(cable_load) :: field_load
      real(dp) :: k = 400, p0(3) = [4.0_dp, 1.0_dp, -3.0_dp]
   contains
      procedure :: name => field_name
      procedure :: cell_force => field_force
      procedure :: has_3d => field_has_3d
      procedure :: cell_force3 => field_force3
   end type field_load

contains

   subroutine collect_fluid(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('cell_force_derivatives', test_derivatives), &
               new_unittest('position_dependent_load_jacobians', test_position_load), &
               new_unittest('critical_angle_in_current', test_critical_angle), &
               new_unittest('terminal_speed_broadside', test_terminal_speed), &
               new_unittest('hanging_chain_in_water', test_chain_in_water)]
   end subroutine collect_fluid

   !> A fluid of sea water around the paper's line, all coefficients on.
   function water(current) result(f)
      real(dp), intent(in) :: current(2)
      type(fluid_load) :: f
      f = fluid_load(density=1025.0_dp, cd_normal=1.2_dp, cd_tangential=0.008_dp, ca_normal=1.0_dp, current=current, &
                     diameter=0.05_dp, area=0.25_dp*pi*0.05_dp**2, gravity=9.81_dp)
   end function water

   !> df/de, df/dw, df/da against central differences at random states, at
   !> states whose relative velocity is nearly tangential or nearly normal
   !> (one part 1e-5 m/s), and at a relative velocity of 1e-7 m/s.
   subroutine test_derivatives(error)
      type(error_type), allocatable, intent(out) :: error
      type(fluid_load) :: f
      real(dp) :: e(2), w(2), a(2), g(2), dx(2, 2), de(2, 2), dw(2, 2), da(2, 2), fd(2, 2), h, worst, scale, noise(6)
      ! A cell's mid position: the fluid is the same everywhere, so df/dx = 0 (checked below).
      real(dp), parameter :: x0(2) = [3.0_dp, -7.0_dp]
      integer :: trial, j, size_seed
      integer, allocatable :: seed(:)
      call random_seed(size=size_seed)
      seed = [(7919*j + 17, j=1, size_seed)]
      call random_seed(put=seed)
      worst = 0
      f = water([0.6_dp, -0.2_dp])
      do trial = 1, 40
         call random_number(noise)
         e = [1.1_dp, 0.3_dp] + 0.4_dp*(noise(1:2) - 0.5_dp)
         a = 3*(noise(5:6) - 0.5_dp)
         select case (mod(trial, 4))
         case (0)
            w = 2*(noise(3:4) - 0.5_dp)
         case (1) ! relative velocity nearly along the cell
            w = f%current - (0.3_dp + noise(3))*e/norm2(e) - 1.0e-5_dp*[-e(2), e(1)]
         case (2) ! nearly normal to it
            w = f%current - (0.3_dp + noise(3))*[-e(2), e(1)]/norm2(e) - 1.0e-5_dp*e
         case (3) ! the cell moving with the fluid (and not accelerating, so that f is the small drag alone)
            w = f%current + 1.0e-7_dp*(noise(3:4) - 0.5_dp)
            a = 0
         end select
         call f%cell_force(x0, 1.0_dp, e, w, a, g, dx, de, dw, da)
         scale = 1 + norm2(g)
         ! Steps that move the small part of the relative velocity by much less than itself.
         h = 1.0e-6_dp
         if (mod(trial, 4) == 1 .or. mod(trial, 4) == 2) h = 1.0e-7_dp
         do j = 1, 2
            fd(:, j) = (force(e + h*unit(j), w, a) - force(e - h*unit(j), w, a))/(2*h)
         end do
         worst = max(worst, maxval(abs(fd - de))/scale)
         ! Steps well below the small part of the relative velocity, where there is one.
         h = 1.0e-6_dp
         if (mod(trial, 4) == 1 .or. mod(trial, 4) == 2) h = 1.0e-7_dp
         if (mod(trial, 4) == 3) h = 1.0e-9_dp
         do j = 1, 2
            fd(:, j) = (force(e, w + h*unit(j), a) - force(e, w - h*unit(j), a))/(2*h)
         end do
         worst = max(worst, maxval(abs(fd - dw))/scale)
         h = 1.0e-6_dp
         do j = 1, 2
            fd(:, j) = (force(e, w, a + h*unit(j)) - force(e, w, a - h*unit(j)))/(2*h)
         end do
         worst = max(worst, maxval(abs(fd - da))/scale)
         worst = max(worst, maxval(abs(dx))/scale)
      end do
      write (output_unit, '(4x,a,es9.2)') 'fluid cell force: largest |analytic - central difference| / (1 + |f|)', worst
      call check(error, worst < 3.0e-8_dp, 'fluid derivatives off the central differences by '//str(worst))

   contains

      function force(ee, ww, aa) result(ff)
         real(dp), intent(in) :: ee(2), ww(2), aa(2)
         real(dp) :: ff(2), d0(2, 2), d1(2, 2), d2(2, 2), d3(2, 2)
         call f%cell_force(x0, 1.0_dp, ee, ww, aa, ff, d0, d1, d2, d3)
      end function force

      function unit(jj) result(u)
         integer, intent(in) :: jj
         real(dp) :: u(2)
         u = 0
         u(jj) = 1
      end function unit
   end subroutine test_derivatives

   !> A 50 m line (stiff linear law, so the strain is negligible) held at end a
   !> and free at end b, in a current U with no tangential drag: its exact
   !> static shape is straight at the critical angle phi below the current,
   !> where normal drag balances the normal wet weight,
   !> sin^2(phi) / cos(phi) = 2 w / (rho d Cdn U^2); every cell lies at phi.
   subroutine test_critical_angle(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      type(simulation) :: sim
      real(dp) :: w, ratio, cphi, phi, worst, angle
      integer :: k, n
      c = statics_config(101)
      c%length = 50
      c%law = 'linear'
      c%ea = 1.0e9_dp
      c%end_b%kind = 'free'
      c%given = ''
      c%break_enabled = .false.
      c%fluid_density = 1025
      c%surface_z = 100 ! the end held 100 m under water
      c%cd_normal = 1.2_dp
      c%current_x = 0.5_dp
      c%t_end = 1.0e-3_dp
      c%dt = 1.0e-3_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      w = (c%density - c%fluid_density)*0.25_dp*pi*c%diameter**2*c%gravity
      ratio = 2*w/(c%fluid_density*c%diameter*c%cd_normal*c%current_x**2)
      cphi = 0.5_dp*(-ratio + sqrt(ratio**2 + 4))
      phi = acos(cphi)
      n = size(sim%rod%static%r, 2)
      worst = 0
      do k = 1, n - 1
         associate (d => sim%rod%static%r(:, k + 1) - sim%rod%static%r(:, k))
            angle = atan2(-d(2), d(1))
         end associate
         worst = max(worst, abs(angle - phi))
      end do
      write (output_unit, '(4x,a,f10.6,a,es10.2,a)') 'streaming cable: critical angle ', phi*180/pi, &
         ' degrees; largest deviation of a cell ', worst, ' rad'
      call check(error, worst < 3.0e-8_dp, 'the streaming cable is not straight at the critical angle: '//str(worst))
   end subroutine test_critical_angle

   !> A 20 m straight horizontal line, both ends free, falls broadside in still
   !> water from rest. Nothing bends or stretches it, so each unit length obeys
   !> (m + m_a) dV/dt = w - K V^2 with K = rho d Cdn / 2 and m_a = Ca rho A:
   !> V(t) = V_t tanh(K V_t t / (m + m_a)), V_t = sqrt(w / K). Steps of 20 and
   !> 10 ms (midpoint rule, error order 2).
   subroutine test_terminal_speed(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 21
      real(dp), parameter :: steps(2) = [0.02_dp, 0.01_dp], t_end = 2.0_dp
      type(rod_problem), target :: problems(2)
      type(rod_problem), pointer :: p
      type(fluid_load) :: f
      type(newton_workspace) :: work
      type(newton_options) :: opts
      type(newton_report) :: report
      real(dp) :: s(n), r(2, n), v(2, n), x(2*n), m, wet, kd, ma, vt, t, dt, exact, err(2), final(2)
      integer :: k, i, step
      f = water([0.0_dp, 0.0_dp])
      f%cd_tangential = 0
      m = 1140*f%area
      wet = (m - f%density*f%area)*9.81_dp
      kd = 0.5_dp*f%density*f%diameter*f%cd_normal
      ma = f%ca_normal*f%density*f%area
      vt = sqrt(wet/kd)
      s = [(20.0_dp*(k - 1)/(n - 1), k=1, n)]
      do i = 1, 2
         dt = steps(i)
         p => problems(i)
         call p%piece%init(s, m, wet, 1.0e-3_dp, 9.81_dp, 0.0_dp, linear_law(ea=1.0e6_dp), free_end(), free_end(), 1.0_dp)
         allocate (p%piece%loads(1))
         allocate (p%piece%loads(1)%load, source=f)
         call work%init(2*n, rod_kl, rod_ku, spread(1.0_dp, 1, 2*n))
         opts%tolerance = 1.0e-12_dp
         r(1, :) = s
         r(2, :) = 0
         v = 0
         t = 0
         err(i) = 0
         do step = 1, nint(t_end/dt)
            p%t0 = t
            p%dt = dt
            p%theta = 0.5_dp
            call p%piece%prepare_step(r, v)
            x = reshape(r + dt*v, [2*n])
            work%usable = .false.
            call newton_solve(p, x, work, opts, report, error)
            if (allocated(error)) return
            call p%piece%new_velocity(reshape(x, [2, n]), dt, 0.5_dp, v)
            r = reshape(x, [2, n])
            t = t + dt
            exact = -vt*tanh(kd*vt*t/(m + ma))
            err(i) = max(err(i), maxval(abs(v(2, :) - exact))/vt)
         end do
         final(i) = v(2, (n + 1)/2)
      end do
      write (output_unit, '(4x,a,f9.6,a,f9.6,a,2es10.2)') 'broadside fall: terminal speed ', vt, ' m/s, reached ', &
         -final(2), ' m/s; largest error / V_t with steps 20, 10 ms', err
      call check(error, err(2) < 1.0e-4_dp .and. err(1)/err(2) > 3.5_dp, &
                 'the fall is off the tanh law of quadratic drag: '//str(err(1))//', '//str(err(2)))
   end subroutine test_terminal_speed

   !> The hanging chain of suite scenes (denser: 3000 kg/m^3) in water, without drag: its tension is
   !> the wet weight and its inertia the dry mass plus the normal added mass, so
   !> its first period is the dry one times sqrt((m + m_a) g / w).
   subroutine test_chain_in_water(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: j01 = 2.404825557695773_dp
      type(case_config) :: c
      real(dp) :: omega_dry, period, exact, m, ma, wet
      c = statics_config(61)
      c%length = 10
      c%law = 'linear'
      c%ea = 1.0e8_dp
      c%bending_stiffness = 1.0e-3_dp
      c%end_b%kind = 'free'
      c%given = ''
      c%break_enabled = .false.
      c%dt = 0.005_dp
      c%t_end = 20
      c%density = 3000
      c%fluid_density = 1025
      c%ca_normal = 1
      m = c%density*0.25_dp*pi*c%diameter**2
      ma = c%fluid_density*0.25_dp*pi*c%diameter**2
      wet = (m - ma)*c%gravity
      omega_dry = 0.5_dp*j01*sqrt(c%gravity/c%length)
      ! The mode shape depends on s only: start it with the dry omega and g.
      call free_end_period(c, 'chain', omega_dry, period, error)
      if (allocated(error)) return
      exact = 2*pi/omega_dry*sqrt((m + ma)*c%gravity/wet)
      write (output_unit, '(4x,a,f10.5,a,es11.3)') 'hanging chain in water: period ', exact, &
         ' s (dry: '//str(2*pi/omega_dry)//' s); relative error', (period - exact)/exact
      call check(error, abs(period - exact) < 3.0e-4_dp*exact, 'the chain in water swings off the added-mass period')
   end subroutine test_chain_in_water
   pure function field_name(self) result(name)
      class(field_load), intent(in) :: self
      character(:), allocatable :: name
      name = 'field'
   end function field_name

   pure subroutine field_force(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(field_load), intent(in) :: self
      real(dp), intent(in) :: x(2), ds, e(2), w(2), a(2)
      real(dp), intent(out) :: f(2), df_dx(2, 2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      real(dp) :: d(2)
      d = x - self%p0([1, 3])
      f = -self%k*norm2(e)*d
      df_dx = 0
      df_dx(1, 1) = -self%k*norm2(e)
      df_dx(2, 2) = -self%k*norm2(e)
      df_de = -self%k*spread(d, 2, 2)*spread(e/norm2(e), 1, 2)
      df_dw = 0
      df_da = 0
   end subroutine field_force

   pure logical function field_has_3d(self)
      class(field_load), intent(in) :: self
      field_has_3d = .true.
   end function field_has_3d

   pure subroutine field_force3(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(field_load), intent(in) :: self
      real(dp), intent(in) :: x(3), ds, e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      real(dp) :: d(3)
      integer :: i
      d = x - self%p0
      f = -self%k*norm2(e)*d
      df_dx = 0
      do i = 1, 3
         df_dx(i, i) = -self%k*norm2(e)
      end do
      df_de = -self%k*spread(d, 2, 3)*spread(e/norm2(e), 1, 3)
      df_dw = 0
      df_da = 0
   end subroutine field_force3

   !> Loads receive the cell's position: a load that depends on it (field_load) on a 10 m line
   !> between fixed ends, 21 nodes, planar and 3-D. The analytic Jacobians of a step (the mid
   !> position centred on the step, dx/dR = 1/4 per node) and of the statics (1/2 per node),
   !> with the load's df/dx in them, against central differences of the residuals, at a perturbed
   !> state, within check_jacobian's 1e-6 of the row scale. (Mutations: the df/dx term left out
   !> of the rods' blocks, caught in both: deviations 4.1e-5 (2-D step) and 4.3e-3 (3-D statics).)
   subroutine test_position_load(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      type(field_load) :: field
      type(load_slot) :: slots(1)
      real(dp), allocatable :: x(:)
      real(dp) :: worst
      integer :: k, np, m
      character(len=2), parameter :: models(2) = ['2d', '3d']
      do m = 1, 2
         c = statics_config(21)
         c%length = 10
         c%law = 'linear'
         c%ea = 4.0e5_dp
         c%end_b%x = 9.5_dp
         c%end_b%z = -1
         c%given = 'end_b%x end_b%z'
         c%model = models(m)
         c%dt = 1.0e-3_dp
         call sim%prepare(c, error)
         if (allocated(error)) return
         if (.not. allocated(slots(1)%load)) allocate (slots(1)%load, source=field)
         if (m == 1) then
            sim%rod%pieces(1)%problem%piece%loads = slots
            associate (run => sim%rod%pieces(1))
               np = size(run%r, 2)
               run%problem%dt = c%dt
               run%problem%theta = c%theta
               call run%problem%piece%prepare_step(run%r, run%v)
               x = reshape(run%r, [2*np])
               do k = 1, size(x)
                  x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
               end do
               call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-6_dp, worst, error)
               if (allocated(error)) error%message = '2-D step: '//error%message
               if (allocated(error)) return
               run%problem%dt = 0
               call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-6_dp, worst, error)
               if (allocated(error)) error%message = '2-D statics: '//error%message
               if (allocated(error)) return
            end associate
         else
            associate (run => sim%rod3%pieces(1)%run)
               call run%problem%piece%set_loads(slots, error)
               if (allocated(error)) return
               np = run%problem%piece%n
               x = run%x
               do k = 1, size(x)
                  x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
               end do
               run%problem%dt = 0
               call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-6_dp, worst, &
                                   error)
               if (allocated(error)) error%message = '3-D statics: '//error%message
               if (allocated(error)) return
            end associate
         end if
      end do
   end subroutine test_position_load
end module suite_fluid
