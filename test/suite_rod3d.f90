!> The 3-D rod (model/rod3d.f90): its Jacobians against central differences
!> entry by entry; a planar scene in 3-D against the planar rod; rotation
!> about the vertical and mirror symmetry; the energy ledger; torsion (a
!> torque gives the uniform twist rate M_t / GIp) and the unit norm of the
!> frame's Euler parameters along a run.
module suite_rod3d
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_material_law, only: tanh_law, linear_law
   use xcable_ends_end_condition, only: end_condition
   use xcable_ends_force, only: force_end
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_motion, only: motion_end
   use xcable_ends_end_condition, only: smooth_ramp
   use xcable_loads_fluid, only: fluid_load
   use xcable_loads_load, only: load_slot
   use xcable_model_rod, only: rod_problem, rod_kl, rod_ku
   use xcable_model_rod3d, only: rod3d_problem, rod3d_kl, rod3d_ku, turning_angle, paper_euler_parameters
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   use xcable_fdcheck, only: check_jacobian
   use xcable_io_config, only: case_config
   use xcable_driver_simulation, only: simulation
   use suite_registry, only: scene_config, variants
   use xcable_io_config, only: end_config
   use xcable_ends_factory, only: new_end, end_kinds
   use xcable_solver_banded, only: band_matrix
   use suite_banded, only: compare_kernels
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_rod3d

   real(dp), parameter :: pi = acos(-1.0_dp)
   !> The paper's cable: mass per length (kg/m), gravity, EI (N m^2); a GIp for the tests.
   real(dp), parameter :: m_cable = 2.239_dp, g = 9.81_dp, ei = 70.6_dp, gip = 47.0_dp

   !> A test end in 3-D: held at a point, or loaded by F(t) = F0 + F1 sin(2 pi t / period),
   !> a torque M0 + M1 t and a point mass.
   type, extends(end_condition) :: end3
      logical :: is_held = .false.
      real(dp) :: point(3) = 0, force0(3) = 0, force1(3) = 0, period = 1, torque0 = 0, torque1 = 0, mass = 0
      !> Couple (about -y, the planar convention) C0 + C1 t, N m.
      real(dp) :: couple0 = 0, couple1 = 0
   contains
      procedure :: kind => end3_kind
      procedure :: held => end3_held
      procedure :: position => end3_position
      procedure :: position3 => end3_position3
      procedure :: velocity3 => end3_velocity3
      procedure :: applied_force => end3_force
      procedure :: applied_force3 => end3_force3
      procedure :: applied_torque => end3_torque
      procedure :: point_mass => end3_mass
      procedure :: applied_couple => end3_couple
   end type end3

contains

   subroutine collect_rod3d(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('jacobian_statics', test_jacobian_statics), &
               new_unittest('jacobian_step', test_jacobian_step), &
               new_unittest('jacobian_step_mass_damping_theta_0.7', test_jacobian_step_mass), &
               new_unittest('jacobian_fluid_cross_current', test_jacobian_fluid), &
               new_unittest('reduction_to_planar_rod', test_reduction), &
               new_unittest('reduction_release_buckling', test_reduction_release), &
               new_unittest('reduction_paper_four_runs', test_paper_runs), &
               new_unittest('rotation_about_vertical', test_rotation), &
               new_unittest('mirror_symmetry', test_mirror), &
               new_unittest('ledger_3d', test_ledger), &
               new_unittest('torsion_twist_rate_unit_frame', test_torsion), &
               new_unittest('out_of_plane_sway', test_sway), &
               new_unittest('discrete_gradient_exact', test_discrete_gradient), &
               new_unittest('every_end_kind', test_every_end_kind), &
               new_unittest('fluid_reduction_symmetry_ledger', test_fluid), &
               new_unittest('ends_with_y_torque', test_ends_y), &
               new_unittest('statics_and_steps_every_end_kind', test_statics_kinds), &
               new_unittest('fold_check_3d', test_fold_check), &
               new_unittest('ledger_reuses_final_residual', test_ledger_reuse), &
               new_unittest('own_band_kernels_vs_lapack', test_kernels)]
   end subroutine collect_rod3d

   ! ---- the test end ----

   pure function end3_kind(self) result(name)
      class(end3), intent(in) :: self
      character(:), allocatable :: name
      name = merge('fixed', 'force', self%is_held)
   end function end3_kind

   pure logical function end3_held(self)
      class(end3), intent(in) :: self
      end3_held = self%is_held
   end function end3_held

   pure function end3_position(self, t) result(x)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(2)
      x = [self%point(1), self%point(3)]
   end function end3_position

   pure function end3_position3(self, t) result(x)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(3)
      x = self%point
   end function end3_position3

   pure function end3_velocity3(self, t) result(v)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: v(3)
      v = 0
   end function end3_velocity3

   pure function end3_force3(self, t) result(f)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: f(3)
      f = self%force0 + self%force1*sin(2*pi*t/self%period)
   end function end3_force3

   pure function end3_force(self, t) result(f)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: f(2), f3(3)
      f3 = self%applied_force3(t)
      f = [f3(1), f3(3)]
   end function end3_force

   pure real(dp) function end3_torque(self, t) result(m)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      m = self%torque0 + self%torque1*t
   end function end3_torque

   pure real(dp) function end3_couple(self, t) result(c)
      class(end3), intent(in) :: self
      real(dp), intent(in) :: t
      c = self%couple0 + self%couple1*t
   end function end3_couple

   pure real(dp) function end3_mass(self)
      class(end3), intent(in) :: self
      end3_mass = self%mass
   end function end3_mass

   ! ---- helpers ----

   !> Rotation by angle alpha about the vertical z, optionally after the mirror y -> -y.
   pure function transform(v, alpha, mirror) result(w)
      real(dp), intent(in) :: v(3), alpha
      logical, intent(in) :: mirror
      real(dp) :: w(3), u(3)
      u = v
      if (mirror) u(2) = -u(2)
      w = [cos(alpha)*u(1) - sin(alpha)*u(2), sin(alpha)*u(1) + cos(alpha)*u(2), u(3)]
   end function transform

   !> A 3-D piece of n nodes over length len: end a held at the origin, end b loaded.
   subroutine make_piece3(p, n, len, eb, error, mu, mu2, damping, gravity, fluid)
      type(rod3d_problem), intent(out) :: p
      integer, intent(in) :: n
      real(dp), intent(in) :: len
      class(end_condition), intent(in) :: eb
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: mu, mu2, damping, gravity
      !> A fluid around the line (its buoyancy comes off the weight).
      type(fluid_load), intent(in), optional :: fluid
      real(dp) :: s(n), mu_, g_, lift
      integer :: k
      s = [(len*(k - 1)/(n - 1), k=1, n)]
      mu_ = 1
      if (present(mu)) mu_ = mu
      g_ = g
      if (present(gravity)) g_ = gravity
      lift = 0
      if (present(fluid)) lift = fluid%lift()
      call p%piece%init(s, m_cable, m_cable*g_ - lift, ei, gip, g_, mu_, tanh_law(), end3(is_held=.true.), eb, 1.0e4_dp, &
                        error, mu2, damping)
      if (allocated(error)) return
      if (present(fluid)) then
         block
            type(load_slot) :: slots(1)
            allocate (slots(1)%load, source=fluid)
            call p%piece%set_loads(slots, error)
         end block
      end if
   end subroutine make_piece3

   !> A curved 3-D state of n nodes, the unknowns x (with twist angles) and velocities.
   subroutine curved_state(n, len, x, r0, v0)
      integer, intent(in) :: n
      real(dp), intent(in) :: len
      real(dp), allocatable, intent(out) :: x(:), r0(:, :), v0(:, :)
      integer :: k
      real(dp) :: s
      allocate (x(4*n), r0(3, n), v0(3, n))
      do k = 1, n
         s = len*(k - 1)/(n - 1)
         r0(:, k) = [s*1.02_dp, 0.4_dp*sin(0.9_dp*s), 0.3_dp*sin(1.3_dp*s)]
         v0(:, k) = [0.5_dp*cos(real(k, dp)), 0.3_dp*sin(real(k, dp)), -0.2_dp*k]
         x(3*k - 2:3*k) = r0(:, k) + [0.01_dp*sin(2.0_dp*k), 0.03_dp*cos(5.0_dp*k), 0.02_dp*cos(3.0_dp*k)]
         x(3*n + k) = 0.1_dp*sin(real(k, dp))
      end do
      ! A cell squeezed and turned by a large angle out of the plane, another stretched.
      x(16:18) = x(16:18) + [-0.4_dp, 0.25_dp, 0.3_dp]
      x(22:24) = x(22:24) + [0.1_dp, -0.1_dp, -0.05_dp]
   end subroutine curved_state

   ! ---- Jacobians ----

   subroutine test_jacobian_statics(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: worst
      integer, parameter :: n = 9
      call make_piece3(p, n, 6.0_dp, end3(force0=[1000.0_dp, 300.0_dp, 200.0_dp], torque0=5.0_dp, couple0=3.0_dp), error)
      if (allocated(error)) return
      call curved_state(n, 6.0_dp, x, r0, v0)
      p%dt = 0
      call check_jacobian(p, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*n), 1.0e-8_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') '3-D statics: largest deviation from central differences / row scale', worst
   end subroutine test_jacobian_statics

   subroutine step_jacobian(error, mu, mu2, damping, theta, mass, label, fluid)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in) :: mu, mu2, damping, theta, mass
      character(*), intent(in) :: label
      type(fluid_load), intent(in), optional :: fluid
      type(rod3d_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: worst
      integer, parameter :: n = 9
      call make_piece3(p, n, 6.0_dp, end3(force0=[1000.0_dp, 300.0_dp, 200.0_dp], force1=[0.0_dp, 400.0_dp, 0.0_dp], &
                                          period=0.05_dp, torque0=5.0_dp, torque1=100.0_dp, mass=mass, &
                                          couple0=3.0_dp, couple1=200.0_dp), &
                       error, mu, mu2, damping, fluid=fluid)
      if (allocated(error)) return
      call curved_state(n, 6.0_dp, x, r0, v0)
      call p%piece%prepare_step(r0, v0)
      p%dt = 0.002_dp
      p%t0 = 0.01_dp
      p%theta = theta
      call check_jacobian(p, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*n), 1.0e-8_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') '3-D step ('//label//'): largest deviation / row scale', worst
   end subroutine step_jacobian

   !> The band kernels compiled for the 3-D rod's widths (kl = ku = 8) against LAPACK's
   !> dgbtrf and dgbtrs on a step Jacobian of a curved, squeezed 30-node piece: the
   !> same pivots and factors bit for bit, and the same solutions (suite_banded).
   subroutine test_kernels(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_problem) :: p
      type(band_matrix) :: jac
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :), res(:)
      real(dp) :: worst
      integer :: i, interchanges
      integer, parameter :: n = 30
      call make_piece3(p, n, 20.0_dp, end3(force0=[1000.0_dp, 300.0_dp, 200.0_dp], torque0=5.0_dp, couple0=3.0_dp), error)
      if (allocated(error)) return
      call curved_state(n, 20.0_dp, x, r0, v0)
      call p%piece%prepare_step(r0, v0)
      p%dt = 0.002_dp
      p%t0 = 0.01_dp
      p%theta = 0.5_dp
      call jac%init(size(x), rod3d_kl, rod3d_ku)
      allocate (res(size(x)))
      call p%evaluate(x, res, jac, .true.)
      worst = 0
      call compare_kernels(jac, '3-D rod, 30 nodes', 1.0e-15_dp, worst, error)
      if (allocated(error)) return
      call jac%factor(error)
      if (allocated(error)) return
      interchanges = count(jac%ipiv /= [(i, i=1, size(x))])
      write (output_unit, '(4x,a,es9.2,a,i0,a)') '3-D rod: largest |x_own - x_dgbtrs| / max |x|', worst, ' (', &
         interchanges, ' row interchanges)'
   end subroutine test_kernels

   subroutine test_jacobian_step(error)
      type(error_type), allocatable, intent(out) :: error
      call step_jacobian(error, 1.0_dp, 0.0_dp, 0.0_dp, 0.5_dp, 0.0_dp, 'averaged mass, theta 0.5')
   end subroutine test_jacobian_step

   !> Water with a current (1, 0.8, -0.3) m/s across the line.
   pure type(fluid_load) function water(current)
      real(dp), intent(in) :: current(3)
      water = fluid_load(density=1025.0_dp, cd_normal=1.2_dp, cd_tangential=0.008_dp, ca_normal=1.0_dp, &
                         current=[current(1), current(3)], current_y=current(2), diameter=0.05_dp, &
                         area=1.964e-3_dp, gravity=g)
   end function water

   subroutine test_jacobian_fluid(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: worst
      integer, parameter :: n = 9
      call step_jacobian(error, 1.0_dp, 0.1_dp, 0.0_dp, 0.5_dp, 0.0_dp, 'water, cross current', &
                         water([1.0_dp, 0.8_dp, -0.3_dp]))
      if (allocated(error)) return
      call make_piece3(p, n, 6.0_dp, end3(force0=[1000.0_dp, 300.0_dp, 200.0_dp]), error, &
                       fluid=water([1.0_dp, 0.8_dp, -0.3_dp]))
      if (allocated(error)) return
      call curved_state(n, 6.0_dp, x, r0, v0)
      p%dt = 0
      call check_jacobian(p, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*n), 1.0e-8_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') '3-D statics in water with a cross current: largest deviation / row scale', worst
   end subroutine test_jacobian_fluid

   subroutine test_jacobian_step_mass(error)
      type(error_type), allocatable, intent(out) :: error
      call step_jacobian(error, 0.5_dp, 0.3_dp, 2.0e3_dp, 0.7_dp, 5.0_dp, 'point mass, damping, theta 0.7')
   end subroutine test_jacobian_step_mass

   ! ---- runs ----

   !> The scene of the runs: a 20 m line of the paper's cable on n nodes, end a held at the
   !> origin, end b pulled by F0 + F1 sin(2 pi t / 0.1 s) (F1 may leave the plane), in its
   !> static state under F0 turned by alpha about the vertical (and mirrored).
   subroutine scene3(run, n, f0, f1, alpha, mirror, torque0, torque1, error, release, current, couple)
      type(rod3d_run), intent(out) :: run
      integer, intent(in) :: n
      real(dp), intent(in) :: f0(3), f1(3), alpha, torque0, torque1
      logical, intent(in) :: mirror
      type(error_type), allocatable, intent(out) :: error
      !> With it, end b is instead the planar force end releasing f0 over this time (s).
      real(dp), intent(in), optional :: release
      !> With it, the line is in water with this current (turned and mirrored with the scene).
      real(dp), intent(in), optional :: current(3)
      !> With it, end b carries this couple (about -y) from t = 0, rising by 10 times it per second.
      real(dp), intent(in), optional :: couple
      real(dp), allocatable :: r2(:, :)
      integer :: k
      if (present(release)) then
         call make_piece3(run%problem, n, 20.0_dp, force_end(history='ramp', force0=[f0(1), f0(3)], &
                                                             duration=release), error)
      else
         if (present(couple)) then
            call make_piece3(run%problem, n, 20.0_dp, end3(force0=transform(f0, alpha, mirror), &
                                                           force1=transform(f1, alpha, mirror), period=0.1_dp, &
                                                           torque0=torque0, torque1=torque1, couple0=couple, &
                                                           couple1=10*couple), error)
         else if (present(current)) then
            call make_piece3(run%problem, n, 20.0_dp, end3(force0=transform(f0, alpha, mirror), &
                                                           force1=transform(f1, alpha, mirror), period=0.1_dp, &
                                                           torque0=torque0, torque1=torque1), error, &
                             fluid=water(transform(current, alpha, mirror)))
         else
            call make_piece3(run%problem, n, 20.0_dp, end3(force0=transform(f0, alpha, mirror), &
                                                           force1=transform(f1, alpha, mirror), period=0.1_dp, &
                                                           torque0=torque0, torque1=torque1), error)
         end if
      end if
      if (allocated(error)) return
      ! In water the update stagnates near 2e-11 (round-off in the drag terms).
      if (present(current)) then
         call run%init(1.0e-10_dp)
      else
         call run%init(1.0e-11_dp)
      end if
      call planar_statics(n, f0, r2, error, current, couple)
      if (allocated(error)) return
      ! Start the 3-D statics off the solution: out of the plane by 1 % of the span.
      do k = 1, n
         run%x(3*k - 2:3*k) = transform([r2(1, k), 0.01_dp*r2(1, k), r2(2, k)], alpha, mirror)
      end do
      call run%statics(0.0_dp, error)
   end subroutine scene3

   !> The planar rod's static state of the same scene (positions (2, n)).
   subroutine planar_statics(n, f0, r, error, current, couple)
      integer, intent(in) :: n
      real(dp), intent(in) :: f0(3)
      real(dp), allocatable, intent(out) :: r(:, :)
      type(error_type), allocatable, intent(out) :: error
      !> A current (only its x and z are seen: its y component must be zero for the 3-D twin).
      real(dp), intent(in), optional :: current(3)
      !> A couple at end b (as scene3).
      real(dp), intent(in), optional :: couple
      real(dp) :: c0
      type(rod_problem) :: p
      type(newton_workspace) :: work
      type(newton_options) :: options
      type(newton_report) :: report
      real(dp), allocatable :: x(:)
      real(dp) :: s(n)
      integer :: k
      s = [(20.0_dp*(k - 1)/(n - 1), k=1, n)]
      c0 = 0
      if (present(couple)) c0 = couple
      call planar_piece(p, s, end3(force0=f0, couple0=c0, couple1=10*c0), current)
      allocate (x(2*n))
      do k = 1, n
         x(2*k - 1:2*k) = [s(k)*1.02_dp, -0.5_dp*sin(pi*s(k)/20)]
      end do
      call work%init(2*n, rod_kl, rod_ku, spread(p%piece%length_ref, 1, 2*n))
      options%tolerance = 1.0e-11_dp
      options%max_iterations = 60
      p%dt = 0
      call newton_solve(p, x, work, options, report, error)
      if (allocated(error)) return
      r = reshape(x, [2, n])
   end subroutine planar_statics

   !> The planar rod on s: end a held at the origin, end b given, in water when a current is given.
   subroutine planar_piece(p, s, eb, current)
      type(rod_problem), intent(out) :: p
      real(dp), intent(in) :: s(:)
      class(end_condition), intent(in) :: eb
      real(dp), intent(in), optional :: current(3)
      type(fluid_load) :: fluid
      if (present(current)) then
         fluid = water(current)
         call p%piece%init(s, m_cable, m_cable*g - fluid%lift(), ei, g, 1.0_dp, tanh_law(), end3(is_held=.true.), &
                           eb, 1.0e4_dp)
         allocate (p%piece%loads(1))
         allocate (p%piece%loads(1)%load, source=fluid)
      else
         call p%piece%init(s, m_cable, m_cable*g, ei, g, 1.0_dp, tanh_law(), end3(is_held=.true.), eb, 1.0e4_dp)
      end if
   end subroutine planar_piece

   !> The planar rod run alongside: positions (2, n) after steps of dt from its statics.
   subroutine planar_run(n, f0, f1, dt, steps, r, error, release, current, couple)
      integer, intent(in) :: n, steps
      real(dp), intent(in) :: f0(3), f1(3), dt
      real(dp), allocatable, intent(out) :: r(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: release, current(3), couple
      real(dp) :: c0
      type(rod_problem) :: p
      type(newton_workspace) :: work
      type(newton_options) :: options
      type(newton_report) :: report
      real(dp), allocatable :: x(:), v(:, :), v1(:, :)
      real(dp) :: s(n)
      integer :: k, i
      s = [(20.0_dp*(k - 1)/(n - 1), k=1, n)]
      call planar_statics(n, f0, r, error, current, couple)
      if (allocated(error)) return
      c0 = 0
      if (present(couple)) c0 = couple
      if (present(release)) then
         call planar_piece(p, s, force_end(history='ramp', force0=[f0(1), f0(3)], duration=release), current)
      else
         call planar_piece(p, s, end3(force0=f0, force1=f1, period=0.1_dp, couple0=c0, couple1=10*c0), current)
      end if
      call work%init(2*n, rod_kl, rod_ku, spread(p%piece%length_ref, 1, 2*n))
      options%tolerance = 1.0e-11_dp
      options%max_iterations = 60
      allocate (v(2, n), v1(2, n))
      v = 0
      do i = 1, steps
         call p%piece%prepare_step(r, v)
         p%dt = dt
         p%t0 = (i - 1)*dt
         x = reshape(r + dt*v, [2*n])
         call newton_solve(p, x, work, options, report, error)
         if (allocated(error)) return
         call p%piece%new_velocity(reshape(x, [2, n]), dt, 0.5_dp, v1)
         r = reshape(x, [2, n])
         v = v1
      end do
   end subroutine planar_run

   !> Steps of a 3-D run.
   subroutine advance(run, dt, steps, error, worst_ledger, worst_norm)
      type(rod3d_run), intent(inout) :: run
      real(dp), intent(in) :: dt
      integer, intent(in) :: steps
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(out), optional :: worst_ledger, worst_norm
      real(dp), allocatable :: beta(:, :)
      integer :: i, c
      if (present(worst_ledger)) worst_ledger = 0
      if (present(worst_norm)) worst_norm = 0
      allocate (beta(4, run%problem%piece%n - 1))
      do i = 1, steps
         call run%step(dt, 0.5_dp, error)
         if (allocated(error)) return
         if (present(worst_ledger)) worst_ledger = max(worst_ledger, abs(run%imbalance()))
         if (present(worst_norm)) then
            call run%problem%piece%frames(run%x, beta)
            do c = 1, size(beta, 2)
               worst_norm = max(worst_norm, abs(norm2(beta(:, c)) - 1))
            end do
         end if
      end do
   end subroutine advance

   !> A planar scene run in 3-D (statics started 1 % out of the plane) gives the planar rod's
   !> positions: after the statics and after 40 steps of 1 ms with the end force varying by 40 %.
   subroutine test_reduction(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: run
      real(dp), allocatable :: r2(:, :)
      real(dp), parameter :: f0(3) = [5000.0_dp, 0.0_dp, 250.0_dp], f1(3) = [-2000.0_dp, 0.0_dp, 300.0_dp]
      real(dp) :: diff_static, diff_run, out_of_plane, frame_err
      integer, parameter :: n = 41
      call scene3(run, n, f0, f1, 0.0_dp, .false., 0.0_dp, 0.0_dp, error)
      if (allocated(error)) return
      call planar_statics(n, f0, r2, error)
      if (allocated(error)) return
      diff_static = planar_difference(run%x, r2, out_of_plane)
      call frame_check(run, frame_err)
      call advance(run, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      call planar_run(n, f0, f1, 1.0e-3_dp, 40, r2, error)
      if (allocated(error)) return
      diff_run = max(planar_difference(run%x, r2, out_of_plane), out_of_plane)
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'planar scene in 3-D vs planar rod: statics ', diff_static, &
         ', after 40 steps ', diff_run, ' of the span (largest position difference, y included)'
      write (output_unit, '(4x,a,es9.2)') 'planar statics: paper''s Euler parameters, largest |beta1|, |beta2| and '// &
         'error of t = (b0^2 - b3^2) i + 2 b0 b3 j ', frame_err
      call check(error, diff_static < 1.0e-14_dp .and. diff_run < 5.0e-12_dp, &
                 '3-D rod differs from the planar rod by more than 1e-14 (statics) or 5e-12 (run) of the span')
      if (allocated(error)) return
      call check(error, frame_err < 1.0e-14_dp, 'the frames of a planar state are not the paper''s planar ones')
      if (allocated(error)) return
      ! With a couple at end b, 50 N m rising at 500 N m/s.
      call scene3(run, n, f0, f1, 0.0_dp, .false., 0.0_dp, 0.0_dp, error, couple=50.0_dp)
      if (allocated(error)) return
      call planar_statics(n, f0, r2, error, couple=50.0_dp)
      if (allocated(error)) return
      diff_static = planar_difference(run%x, r2, out_of_plane)
      call advance(run, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      call planar_run(n, f0, f1, 1.0e-3_dp, 40, r2, error, couple=50.0_dp)
      if (allocated(error)) return
      diff_run = max(planar_difference(run%x, r2, out_of_plane), out_of_plane)
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'the same with an end couple: statics ', diff_static, &
         ', after 40 steps ', diff_run, ' of the span'
      call check(error, diff_static < 1.0e-14_dp .and. diff_run < 5.0e-12_dp, &
                 'with a couple the 3-D rod differs from the planar rod by more than 1e-14 or 5e-12')
   end subroutine test_reduction

   !> The same for a release: 20 kN let go over 5 ms, 300 steps of 0.1 ms, through the unloading
   !> wave's reflection at the held end and the compression and buckling there (turning angles
   !> change sign within steps).
   subroutine test_reduction_release(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: run
      real(dp), allocatable :: r2(:, :)
      real(dp), parameter :: f0(3) = [2.0e4_dp, 0.0_dp, 250.0_dp]
      real(dp) :: diff_run, out_of_plane, th_max
      integer, parameter :: n = 41, steps = 800
      integer :: k
      call scene3(run, n, f0, f0, 0.0_dp, .false., 0.0_dp, 0.0_dp, error, release=0.005_dp)
      if (allocated(error)) return
      call advance(run, 2.0e-4_dp, steps, error)
      if (allocated(error)) return
      call planar_run(n, f0, f0, 2.0e-4_dp, steps, r2, error, release=0.005_dp)
      if (allocated(error)) return
      diff_run = max(planar_difference(run%x, r2, out_of_plane), out_of_plane)
      th_max = 0
      do k = 2, n - 1
         th_max = max(th_max, turning_angle(run%problem%piece%e1(:, k - 1), run%problem%piece%e1(:, k)))
      end do
      write (output_unit, '(4x,a,es9.2,a,f6.3,a,f8.3,a)') 'release in 3-D vs planar rod after 160 ms: ', diff_run, &
         ' of the span; largest turning angle ', th_max, ' rad; end b at x = ', run%x(3*n - 2), ' m'
      call check(error, diff_run < 4.0e-10_dp, '3-D release differs from the planar rod by more than 4e-10 of the span')
   end subroutine test_reduction_release

   !> Frames of a planar state in the paper's convention: largest |beta1|, |beta2| and the
   !> largest error of the paper's planar tangent against the cells' tangents (i = z, j = x).
   subroutine frame_check(run, err)
      type(rod3d_run), intent(in) :: run
      real(dp), intent(out) :: err
      real(dp), allocatable :: beta(:, :)
      real(dp) :: b(4), t(3)
      integer :: c, n
      n = run%problem%piece%n
      allocate (beta(4, n - 1))
      call run%problem%piece%frames(run%x, beta)
      err = 0
      do c = 1, n - 1
         b = paper_euler_parameters(beta(:, c))
         t = (run%x(3*c + 1:3*c + 3) - run%x(3*c - 2:3*c))
         t = t/norm2(t)
         err = max(err, abs(b(2)), abs(b(3)), abs(b(1)**2 - b(4)**2 - t(3)), abs(2*b(1)*b(4) - t(1)))
      end do
   end subroutine frame_check

   !> Largest |R3 - (x, 0, z)| over the span, and the largest |y| over the span.
   real(dp) function planar_difference(x, r2, out_of_plane) result(d)
      real(dp), intent(in) :: x(:), r2(:, :)
      real(dp), intent(out) :: out_of_plane
      integer :: k, n
      real(dp) :: span
      n = size(r2, 2)
      span = r2(1, n) - r2(1, 1)
      d = 0
      out_of_plane = 0
      do k = 1, n
         d = max(d, abs(x(3*k - 2) - r2(1, k)), abs(x(3*k) - r2(2, k)))
         out_of_plane = max(out_of_plane, abs(x(3*k - 1)))
      end do
      d = d/span
      out_of_plane = out_of_plane/span
   end function planar_difference

   !> A 3-D motion (the end force swings out of the plane) of the scene turned by alpha
   !> (and mirrored) against the turned (mirrored) motion of the original scene.
   subroutine symmetry_case(alpha, mirror, diff, error)
      real(dp), intent(in) :: alpha
      logical, intent(in) :: mirror
      real(dp), intent(out) :: diff
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: a, b
      real(dp), parameter :: f0(3) = [5000.0_dp, 0.0_dp, 250.0_dp], f1(3) = [-1500.0_dp, 1500.0_dp, 300.0_dp]
      integer, parameter :: n = 31
      integer :: k
      call scene3(a, n, f0, f1, 0.0_dp, .false., 2.0_dp, 50.0_dp, error)
      if (allocated(error)) return
      call scene3(b, n, f0, f1, alpha, mirror, 2.0_dp, 50.0_dp, error)
      if (allocated(error)) return
      call advance(a, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      call advance(b, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      diff = 0
      do k = 1, n
         diff = max(diff, norm2(b%x(3*k - 2:3*k) - transform(a%x(3*k - 2:3*k), alpha, mirror)))
      end do
      diff = diff/norm2(a%x(3*n - 2:3*n))
      if (maxval(abs(a%x(2:3*n:3))) < 0.05_dp) call fatal_error(error, 'the test motion hardly leaves the plane')
   end subroutine symmetry_case

   subroutine test_rotation(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: diff
      call symmetry_case(0.7_dp, .false., diff, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,es9.2,a)') 'scene turned by 0.7 rad about the vertical: ', diff, &
         ' of the span from the turned solution'
      call check(error, diff < 1.0e-11_dp, 'turned scene differs from the turned solution by more than 1e-11')
   end subroutine test_rotation

   subroutine test_mirror(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: diff
      call symmetry_case(0.0_dp, .true., diff, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,es9.2,a)') 'mirrored scene (y -> -y): ', diff, ' of the span from the mirrored solution'
      call check(error, diff < 1.0e-13_dp, 'mirrored scene differs from the mirrored solution by more than 1e-13')
   end subroutine test_mirror

   !> accept books the ledger from the piece's state at the new level, which Newton's final
   !> residual (options%final_residual, the default) has already set; it evaluates the step
   !> system again only without it. The two ways give the same run bit for bit: a line in a
   !> cross current (loads), end a held (its reaction), end b's force swinging out of the
   !> plane with a torque, 40 steps; unknowns, velocities, the ledger's accumulators and the
   !> Newton iterations.
   subroutine test_ledger_reuse(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: a, b
      real(dp), parameter :: f0(3) = [5000.0_dp, 0.0_dp, 250.0_dp], f1(3) = [-1500.0_dp, 1500.0_dp, 300.0_dp]
      integer, parameter :: n = 31
      call scene3(a, n, f0, f1, 0.0_dp, .false., 2.0_dp, 50.0_dp, error, current=[0.3_dp, 0.5_dp, 0.0_dp])
      if (allocated(error)) return
      call scene3(b, n, f0, f1, 0.0_dp, .false., 2.0_dp, 50.0_dp, error, current=[0.3_dp, 0.5_dp, 0.0_dp])
      if (allocated(error)) return
      b%options%final_residual = .false.
      call advance(a, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      call advance(b, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,3es10.2,a,i0,a,es9.2)') 'ledger with Newton''s final residual: end work, load work, '// &
         'dissipated ', a%end_work, a%load_work, a%dissipated, ' J, ', a%iterations, ' iterations; largest difference '// &
         'from evaluating again ', max(maxval(abs(a%x - b%x)), maxval(abs(a%v - b%v)), abs(a%end_work - b%end_work), &
                                       abs(a%load_work - b%load_work), abs(a%dissipated - b%dissipated))
      call check(error, abs(a%end_work) > 0 .and. abs(a%load_work) > 0, 'the scene does no work at the ends or loads')
      if (allocated(error)) return
      call check(error, all(a%x == b%x) .and. all(a%v == b%v) .and. a%end_work == b%end_work .and. &
                 a%load_work == b%load_work .and. a%dissipated == b%dissipated .and. a%iterations == b%iterations, &
                 'the ledger from Newton''s final residual differs from evaluating again: end work '// &
                 str(a%end_work - b%end_work)//', load work '//str(a%load_work - b%load_work))
   end subroutine test_ledger_reuse

   !> The ledger of a 3-D motion (force swinging out of the plane, torque rising) closes:
   !> largest |stored - initial - end work| over 100 steps, over the strain energy.
   subroutine test_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: run
      real(dp), parameter :: f0(3) = [5000.0_dp, 0.0_dp, 250.0_dp], f1(3) = [-4000.0_dp, 3000.0_dp, 800.0_dp]
      real(dp) :: worst, strain
      call scene3(run, 41, f0, f1, 0.3_dp, .false., 1.0_dp, 200.0_dp, error, couple=0.0_dp)
      if (allocated(error)) return
      call ledger_case(run, worst, strain, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,f8.3,a)') '3-D ledger: largest imbalance ', worst/strain, &
         ' of the strain energy (', strain, ' J); end work ', run%end_work, ' J'
      call check(error, worst/strain < 1.0e-11_dp, '3-D ledger does not close to 1e-11 of the strain energy')
      if (allocated(error)) return
      ! The same with a couple of 50 N m at end b (released statics: the static state is not
      ! that of the couple; the couple then rises at 500 N m/s).
      call scene3(run, 41, f0, f1, 0.3_dp, .false., 1.0_dp, 200.0_dp, error, couple=50.0_dp)
      if (allocated(error)) return
      call ledger_case(run, worst, strain, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,es9.2,a,f8.3,a)') '3-D ledger with an end couple: largest imbalance ', worst/strain, &
         ' of the strain energy; end work ', run%end_work, ' J'
      call check(error, worst/strain < 1.0e-11_dp, '3-D ledger with a couple does not close to 1e-11')
   end subroutine test_ledger

   subroutine ledger_case(run, worst, strain, error)
      type(rod3d_run), intent(inout) :: run
      real(dp), intent(out) :: worst, strain
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: en(5)
      en = run%energies()
      strain = en(1)
      call advance(run, 1.0e-3_dp, 100, error, worst_ledger=worst)
   end subroutine ledger_case

   !> A torque M_t at end b (rising from 1 to 21 N m over the run) gives the twist rate
   !> M_t / GIp in every cell, statics and steps; |beta| stays 1 along the run.
   subroutine test_torsion(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: run
      real(dp), parameter :: f0(3) = [5000.0_dp, 0.0_dp, 250.0_dp], f1(3) = [-1500.0_dp, 1500.0_dp, 300.0_dp]
      real(dp) :: rate_err_static, rate_err_run, worst_norm, expected
      real(dp), allocatable :: tau(:)
      call scene3(run, 41, f0, f1, 0.0_dp, .false., 1.0_dp, 400.0_dp, error)
      if (allocated(error)) return
      tau = run%problem%piece%twist_rates(run%x)
      expected = 1.0_dp/gip
      rate_err_static = maxval(abs(tau - expected))/expected
      call advance(run, 1.0e-3_dp, 50, error, worst_norm=worst_norm)
      if (allocated(error)) return
      tau = run%problem%piece%twist_rates(run%x)
      expected = (1.0_dp + 400.0_dp*run%t)/gip
      rate_err_run = maxval(abs(tau - expected))/expected
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2)') 'twist rate vs M_t / GIp: statics ', rate_err_static, &
         ', after 50 steps ', rate_err_run, '; largest ||beta| - 1| along the run ', worst_norm
      call check(error, rate_err_static < 1.0e-13_dp .and. rate_err_run < 1.0e-13_dp, &
                 'twist rate differs from M_t / GIp by more than 1e-13')
      if (allocated(error)) return
      call check(error, worst_norm < 1.0e-14_dp, 'Euler parameters off the unit sphere by more than 1e-14')
   end subroutine test_torsion

   !> First out-of-plane (sway) mode of a line held at both ends, from a run started at rest
   !> with y = A sin(pi s / L): the time between the first and the third zero crossings of the
   !> middle node's y is half a period. A taut line without gravity against the string with
   !> bending, m w^2 = T k^2 / (1 + eps) + EI k^4 / (1 + eps)^2, k = pi / L (exact for the
   !> continuum: second order in the grid); a sagging line (sag 1 % of the span) against
   !> Irvine's sway frequency w = (pi / L) sqrt(H / ((1 + eps) m)) with H the horizontal force
   !> of the statics (plus the same bending term), which neglects terms of order (sag/span)^2.
   subroutine test_sway(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: grids(3) = [21, 41, 81]
      real(dp) :: err(3), err_sag, ratio
      integer :: i
      do i = 1, 3
         call sway_error(grids(i), 0.0_dp, err(i), error)
         if (allocated(error)) return
      end do
      call sway_error(41, g, err_sag, error)
      if (allocated(error)) return
      ratio = log(abs(err(2)/err(3)))/log(2.0_dp)
      write (output_unit, '(4x,a,3es10.2,a,f5.2,a,es10.2)') 'sway frequency error, taut line on 21/41/81 nodes', err, &
         ' (order ', ratio, '); sagging line (Irvine) on 41 nodes', err_sag
      call check(error, abs(err(3)) < 3.0e-4_dp .and. ratio > 1.8_dp, &
                 'sway frequency of the taut line off by more than 3e-4 on 81 nodes, or not second order')
      if (allocated(error)) return
      call check(error, abs(err_sag) < 2.0e-3_dp, 'sway frequency of the sagging line off Irvine by more than 2e-3')
   end subroutine test_sway

   !> Relative error of the sway frequency of a 20 m line on n nodes (gravity gz).
   subroutine sway_error(n, gz, err, error)
      integer, intent(in) :: n
      real(dp), intent(in) :: gz
      real(dp), intent(out) :: err
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: run
      type(tanh_law) :: law
      real(dp), parameter :: len = 20.0_dp, tension = 5500.0_dp, amplitude = 1.0e-3_dp
      real(dp) :: eps, span, h, omega_ref, k_wave, dt, y_prev, y_now, t_cross(3), eps_mean, sag
      real(dp), allocatable :: tau(:)
      integer :: k, i, crossings, mid
      eps = law%strain_at(tension)
      ! The sagging line's extra length over its chord, 8 d^2 / (3 l) with d = w l^2 / (8 H).
      sag = 0
      if (gz > 0) sag = m_cable*gz*len**2/(8*tension)
      span = len*(1 + eps) - 8*sag**2/(3*len)
      call make_piece3(run%problem, n, len, end3(is_held=.true., point=[span, 0.0_dp, 0.0_dp]), error, gravity=gz)
      if (allocated(error)) return
      call run%init(1.0e-11_dp)
      do k = 1, n
         run%x(3*k - 2:3*k) = [span*(k - 1)/(n - 1), 0.0_dp, -4*sag*(k - 1)*(n - k)/real(n - 1, dp)**2]
      end do
      call run%statics(0.0_dp, error)
      if (allocated(error)) return
      h = run%problem%piece%force(1, 1)
      eps_mean = sum(run%problem%piece%l1 - 1)/(n - 1)
      k_wave = acos(-1.0_dp)/len
      omega_ref = sqrt((h*k_wave**2/(1 + eps_mean) + ei*k_wave**4/(1 + eps_mean)**2)/m_cable)
      if (gz == 0) omega_ref = sqrt((tension*k_wave**2/(1 + eps) + ei*k_wave**4/(1 + eps)**2)/m_cable)
      do k = 1, n
         run%x(3*k - 1) = amplitude*sin(k_wave*len*(k - 1)/(n - 1))
      end do
      call run%start(run%x, run%v, 0.0_dp)
      dt = 2*acos(-1.0_dp)/omega_ref/400
      mid = (n + 1)/2
      y_prev = run%x(3*mid - 1)
      crossings = 0
      do i = 1, 600
         call run%step(dt, 0.5_dp, error)
         if (allocated(error)) return
         y_now = run%x(3*mid - 1)
         if (y_now*y_prev < 0) then
            crossings = crossings + 1
            t_cross(crossings) = run%t - dt*y_now/(y_now - y_prev)
            if (crossings == 3) exit
         end if
         y_prev = y_now
      end do
      if (crossings < 3) then
         call fatal_error(error, 'the sway did not cross zero three times')
         return
      end if
      err = 2*acos(-1.0_dp)/(t_cross(3) - t_cross(1))/omega_ref - 1
      tau = run%problem%piece%twist_rates(run%x)
      if (maxval(abs(tau)) > 0) call fatal_error(error, 'the sway twisted the line')
   end subroutine sway_error

   !> The cell forces of a step do the exact change of the stored energy: sum_c ds_c N_c .
   !> (e_c^n+1 - e_c^n) = U(n+1) - U(n), for random pairs of 3-D states, curved ones (turning
   !> angles up to 1 rad) and nearly straight ones (turning angles near 1e-4, where the
   !> bending coefficient is a series), on a nearly inextensible soft law so that the bending
   !> energy dominates; relative to the bending energy.
   subroutine test_discrete_gradient(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_problem) :: p
      type(band_matrix) :: unused
      integer, parameter :: n = 9
      real(dp) :: s(n), r0(3, n), r1(3, n), v0(3, n), noise(3, n), work, worst(2), scale, u0(5), u1(5)
      real(dp), allocatable :: x0(:), x1(:), res(:)
      integer :: trial, c, k, kind
      s = [(6.0_dp*(k - 1)/(n - 1), k=1, n)]
      worst = 0
      allocate (x0(4*n), x1(4*n), res(4*n))
      x0 = 0
      x1 = 0
      v0 = 0
      do trial = 1, 20
         kind = 1 + mod(trial, 2)
         call p%piece%init(s, m_cable, 0.0_dp, ei, gip, 0.0_dp, 1.0_dp, linear_law(ea=1.0e-3_dp), &
                           end3(is_held=.true.), end3(), 1.0e4_dp, error)
         if (allocated(error)) return
         do k = 1, n
            if (kind == 1) then
               r0(:, k) = [s(k), 0.5_dp*sin(1.1_dp*s(k)), 0.4_dp*cos(0.7_dp*s(k))]
            else
               r0(:, k) = [s(k), 1.0e-4_dp*sin(2.1_dp*s(k)), 1.0e-4_dp*cos(1.7_dp*s(k))]
            end if
         end do
         call random_number(noise)
         r1 = r0 + merge(0.2_dp, 2.0e-4_dp, kind == 1)*(noise - 0.5_dp)
         call p%piece%prepare_step(r0, v0)
         p%dt = 1.0e-3_dp
         do k = 1, n
            x0(3*k - 2:3*k) = r0(:, k)
            x1(3*k - 2:3*k) = r1(:, k)
         end do
         call p%evaluate(x1, res, unused, .false.)
         work = 0
         do c = 1, n - 1
            work = work + p%piece%ds(c)*dot_product(p%piece%force(:, c), p%piece%e1(:, c) - p%piece%e0(:, c))
         end do
         u0 = p%piece%energies(x0, v0)
         u1 = p%piece%energies(x1, v0)
         scale = u0(3) + u1(3)
         worst(kind) = max(worst(kind), abs(work - ((u1(1) + u1(3)) - (u0(1) + u0(3))))/scale)
      end do
      write (output_unit, '(4x,a,2es9.2,a)') '3-D discrete gradient: largest |work - dU| / bending energy, curved, '// &
         'nearly straight:', worst, ' (20 random steps)'
      call check(error, worst(1) < 2.0e-15_dp .and. worst(2) < 2.0e-15_dp, &
                 'the 3-D discrete gradient misses the energy change by '//str(worst(1))//', '//str(worst(2)))
   end subroutine test_discrete_gradient
   !> Every end kind of the factory, built from its input data as the program builds it (force
   !> 'ramp' and 'table', motion 'harmonic' and 'table'), at end b with end a fixed and at end a
   !> with end b fixed: from a line bowed out of the plane at rest, 20 steps of 0.5 ms; the
   !> Jacobian of the step after 5 steps against central differences, and the ledger (end work
   !> included, moving ends' reactions too) over the 20 steps, relative to the sum of the
   !> energies' magnitudes.
   subroutine test_every_end_kind(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=16), allocatable :: variants(:)
      integer :: i, side
      real(dp) :: worst_jac, worst_ledger, jac, ledger
      variants = [character(len=16) :: 'fixed', 'free', 'force ramp', 'force table', 'motion harmonic', &
                  'motion table', 'mass', 'spring', 'spring damped']
      if (size(variants) < size(end_kinds()) + 2) call fatal_error(error, 'a kind of the factory is missing here')
      if (allocated(error)) return
      worst_jac = 0
      worst_ledger = 0
      do side = 1, 2
         do i = 1, size(variants)
            call end_kind_case(variants(i), side, jac, ledger, error)
            if (allocated(error)) then
               error%message = trim(variants(i))//' at end '//merge('b', 'a', side == 1)//': '//error%message
               return
            end if
            worst_jac = max(worst_jac, jac)
            worst_ledger = max(worst_ledger, ledger)
         end do
      end do
      write (output_unit, '(4x,a,es9.2,a,es9.2)') 'every end kind at either end: worst Jacobian deviation ', &
         worst_jac, ', worst ledger imbalance ', worst_ledger
      call check(error, worst_ledger < 5.0e-12_dp, '3-D ledger with some end kind does not close to 5e-12')
   end subroutine test_every_end_kind

   !> One case of test_every_end_kind: the variant at end b (side 1) or end a (side 2).
   subroutine end_kind_case(variant, side, jac, ledger, error)
      character(*), intent(in) :: variant
      integer, intent(in) :: side
      real(dp), intent(out) :: jac, ledger
      type(error_type), allocatable, intent(out) :: error
      type(end_config) :: held, loaded
      class(end_condition), allocatable :: end_a, end_b
      type(rod3d_run) :: run
      integer, parameter :: n = 21
      real(dp), parameter :: len = 10.0_dp
      real(dp) :: s(n), pa(3), pb(3), en(5), scale
      integer :: k, i
      loaded%kind = variant(1:index(variant//' ', ' ') - 1)
      select case (trim(variant))
      case ('force ramp')
         loaded%history = 'ramp'
         loaded%force_x = merge(2000.0_dp, -2000.0_dp, side == 1)
         loaded%force_z = 300
         loaded%ramp_time = 0.02_dp
      case ('force table')
         loaded%history = 'table'
         loaded%table_rows = 3
         loaded%table_time(1:3) = [0.0_dp, 0.004_dp, 0.02_dp]
         loaded%table_x(1:3) = merge(1.0_dp, -1.0_dp, side == 1)*[2000.0_dp, 2500.0_dp, 1000.0_dp]
         loaded%table_z(1:3) = [300.0_dp, 0.0_dp, 500.0_dp]
      case ('motion harmonic')
         loaded%amplitude = 0.05_dp
         loaded%period = 0.02_dp
         loaded%direction_x = 0.6_dp
         loaded%direction_z = 0.8_dp
      case ('motion table')
         loaded%motion = 'table'
         loaded%table_rows = 3
         loaded%table_time(1:3) = [0.0_dp, 0.004_dp, 0.02_dp]
         loaded%table_x(1:3) = [0.0_dp, 0.02_dp, -0.01_dp]
         loaded%table_z(1:3) = [0.0_dp, 0.01_dp, 0.0_dp]
      case ('mass')
         loaded%mass = 5
      end select
      ! Held points: end a at the origin, end b at (10.05, -0.5); a loaded end starts there too.
      pa = 0
      pb = [10.05_dp, 0.0_dp, -0.5_dp]
      held%x = merge(pa(1), pb(1), side == 2)
      held%z = merge(pa(3), pb(3), side == 2)
      loaded%x = merge(pb(1), pa(1), side == 1)
      loaded%z = merge(pb(3), pa(3), side == 1)
      if (loaded%kind == 'spring') then
         ! The anchor out of the plane, beyond the loaded end's start.
         loaded%x = loaded%x + merge(0.3_dp, -0.3_dp, side == 1)
         loaded%y = 0.8_dp
         loaded%z = loaded%z - 0.4_dp
         loaded%stiffness = 5.0e3_dp
         if (variant == 'spring damped') then
            loaded%damping = 200
            loaded%rest_length = 0.3_dp
            loaded%mass = 3
         end if
      end if
      if (side == 1) then
         held%x = pa(1)
         held%z = pa(3)
         call new_end(held, 'end_a', end_a, error)
         if (allocated(error)) return
         call new_end(loaded, 'end_b', end_b, error)
      else
         held%x = pb(1)
         held%z = pb(3)
         call new_end(loaded, 'end_a', end_a, error)
         if (allocated(error)) return
         call new_end(held, 'end_b', end_b, error)
      end if
      if (allocated(error)) return
      s = [(len*(k - 1)/(n - 1), k=1, n)]
      call run%problem%piece%init(s, m_cable, m_cable*g, ei, gip, g, 1.0_dp, tanh_law(), end_a, end_b, 1.0e4_dp, error)
      if (allocated(error)) return
      call run%init(1.0e-11_dp)
      do k = 1, n
         run%x(3*k - 2:3*k) = pa + (pb - pa)*(k - 1)/(n - 1.0_dp) &
                              + [0.0_dp, 0.1_dp, -0.2_dp]*sin(acos(-1.0_dp)*(k - 1)/(n - 1.0_dp))
      end do
      call run%start(run%x, run%v, 0.0_dp)
      ledger = 0
      scale = 0
      jac = 0
      do i = 1, 20
         if (i == 6) then
            call run%problem%piece%prepare_step(reshape(run%x(1:3*n), [3, n]), run%v)
            run%problem%dt = 5.0e-4_dp
            run%problem%t0 = run%t
            call check_jacobian(run%problem, run%x + 1.0e-3_dp*cos(real([(k, k=1, 4*n)], dp)), rod3d_kl, rod3d_ku, &
                                spread(1.0e-6_dp, 1, 4*n), 3.0e-8_dp, jac, error)
            if (allocated(error)) return
         end if
         call run%step(5.0e-4_dp, 0.5_dp, error)
         if (allocated(error)) return
         en = run%energies()
         scale = max(scale, sum(abs(en)) + abs(run%end_work))
         ledger = max(ledger, abs(run%imbalance()))
      end do
      ledger = ledger/scale
   end subroutine end_kind_case
   !> In water: a planar scene (current along x) in 3-D against the planar rod (statics and 40
   !> steps of 1 ms with the end force varying); a cross current and an end force swinging out of
   !> the plane, turned by 0.7 rad about the vertical with its current, against the turned motion;
   !> the ledger of that motion with the fluid's work.
   subroutine test_fluid(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: run, a, b
      real(dp), allocatable :: r2(:, :)
      real(dp), parameter :: f0(3) = [5000.0_dp, 0.0_dp, 250.0_dp], f1(3) = [-2000.0_dp, 0.0_dp, 300.0_dp]
      real(dp), parameter :: f1_out(3) = [-1500.0_dp, 1500.0_dp, 300.0_dp], current(3) = [1.0_dp, 0.0_dp, -0.2_dp]
      real(dp), parameter :: cross(3) = [0.5_dp, 1.5_dp, 0.0_dp]
      real(dp) :: diff_static, diff_run, out_of_plane, diff_turned, worst_ledger, strain, en(5)
      integer, parameter :: n = 31
      integer :: k, i
      ! Reduction.
      call scene3(run, n, f0, f1, 0.0_dp, .false., 0.0_dp, 0.0_dp, error, current=current)
      if (allocated(error)) return
      call planar_statics(n, f0, r2, error, current)
      if (allocated(error)) return
      diff_static = planar_difference(run%x, r2, out_of_plane)
      call advance(run, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      call planar_run(n, f0, f1, 1.0e-3_dp, 40, r2, error, current=current)
      if (allocated(error)) return
      diff_run = max(planar_difference(run%x, r2, out_of_plane), out_of_plane)
      ! Rotation with a cross current, and the ledger.
      call scene3(a, n, f0, f1_out, 0.0_dp, .false., 0.0_dp, 0.0_dp, error, current=cross)
      if (allocated(error)) return
      call scene3(b, n, f0, f1_out, 0.7_dp, .false., 0.0_dp, 0.0_dp, error, current=cross)
      if (allocated(error)) return
      en = a%energies()
      strain = en(1)
      worst_ledger = 0
      do i = 1, 40
         call a%step(1.0e-3_dp, 0.5_dp, error)
         if (allocated(error)) return
         worst_ledger = max(worst_ledger, abs(a%imbalance()))
      end do
      call advance(b, 1.0e-3_dp, 40, error)
      if (allocated(error)) return
      diff_turned = 0
      do k = 1, n
         diff_turned = max(diff_turned, norm2(b%x(3*k - 2:3*k) - transform(a%x(3*k - 2:3*k), 0.7_dp, .false.)))
      end do
      diff_turned = diff_turned/norm2(a%x(3*n - 2:3*n))
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a)') 'in water: planar scene vs planar rod ', &
         diff_static, ' (statics), ', diff_run, ' (40 steps); cross current turned 0.7 rad ', diff_turned, &
         '; ledger ', worst_ledger/strain, ' of the strain energy, fluid work ', a%load_work, ' J'
      call check(error, diff_static < 1.0e-14_dp .and. diff_run < 5.0e-12_dp, &
                 'in water the 3-D rod differs from the planar rod by more than 1e-14 (statics) or 5e-12 (run)')
      if (allocated(error)) return
      call check(error, diff_turned < 1.0e-11_dp, 'in a cross current the turned scene differs by more than 1e-11')
      if (allocated(error)) return
      call check(error, worst_ledger/strain < 3.0e-13_dp .and. a%load_work < 0, &
                 'in a cross current the ledger does not close to 3e-13, or the fluid does no negative work')
   end subroutine test_fluid
   !> The paper's four runs (180 and 315 kN, released over 5 and 50 ms) on 61 nodes at Courant
   !> number 1, from the planar rod's static state (the program's statics, span iteration
   !> included), in the planar rod and in the 3-D rod with the same steps: the largest position
   !> difference at t_end (0.14 s fast, 0.16 s slow, past the reflection at the fixed end and
   !> the compression there) over the span.
   subroutine test_paper_runs(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: tensions(2) = [1.8e5_dp, 3.15e5_dp], t_breaks(2) = [0.005_dp, 0.05_dp]
      real(dp) :: diff(4), th_max(4)
      integer :: i, j
      do i = 1, 2
         do j = 1, 2
            call paper_run(tensions(i), t_breaks(j), merge(0.14_dp, 0.16_dp, j == 1), diff(2*(i - 1) + j), &
                           th_max(2*(i - 1) + j), error)
            if (allocated(error)) return
         end do
      end do
      write (output_unit, '(4x,a,4es9.2,a)') 'paper runs in 3-D vs planar rod (fast 180, slow 180, fast 315, slow 315 kN): ', &
         diff, ' of the span'
      write (output_unit, '(4x,a,4f7.3,a)') 'largest turning angle at t_end: ', th_max, ' rad'
      call check(error, maxval(diff) < 3.0e-11_dp, 'a paper run in 3-D differs from the planar rod by more than 3e-11')
   end subroutine test_paper_runs

   subroutine paper_run(tension, t_break, t_end, diff, th_max, error)
      real(dp), intent(in) :: tension, t_break, t_end
      real(dp), intent(out) :: diff, th_max
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      type(rod_problem) :: p2
      type(rod3d_run) :: run
      type(force_end) :: release
      type(newton_workspace) :: work
      type(newton_options) :: options
      type(newton_report) :: report
      real(dp), allocatable :: r(:, :), v(:, :), v1(:, :), x(:)
      real(dp) :: dt, out_of_plane
      integer :: n, k, steps, i
      c%source = 'test'
      c%nodes = 61
      c%tension = tension
      c%t_break = t_break
      c%t_end = t_end
      c%courant = 1
      c%newton_tol = 1.0e-10_dp
      c%interval = 0
      call sim%prepare(c, error)
      if (allocated(error)) return
      n = c%nodes
      dt = sim%rod%dt
      steps = nint(t_end/dt)
      r = sim%rod%static%r
      release = force_end(kind_name='break', history='ramp', t0=0.0_dp, duration=t_break, &
                          force0=sim%rod%static%reaction_b)
      associate (q => sim%rod%pieces(1)%problem%piece)
         call p2%piece%init(q%s, q%mass_per_length, q%weight, q%ei, q%gravity, q%mu, q%law, q%end_a, release, &
                            q%tension_ref, q%mu2, q%damping)
         call run%problem%piece%init(q%s, q%mass_per_length, q%weight, q%ei, gip, q%gravity, q%mu, q%law, q%end_a, &
                                     release, q%tension_ref, error, q%mu2, q%damping)
         if (allocated(error)) return
      end associate
      ! Planar.
      call work%init(2*n, rod_kl, rod_ku, spread(p2%piece%length_ref, 1, 2*n))
      options%tolerance = 1.0e-10_dp
      options%max_iterations = 60
      allocate (v(2, n), v1(2, n))
      v = 0
      do i = 1, steps
         call p2%piece%prepare_step(r, v)
         p2%dt = dt
         p2%t0 = (i - 1)*dt
         x = reshape(r + dt*v, [2*n])
         call newton_solve(p2, x, work, options, report, error)
         if (allocated(error)) return
         call p2%piece%new_velocity(reshape(x, [2, n]), dt, 0.5_dp, v1)
         r = reshape(x, [2, n])
         v = v1
      end do
      ! 3-D, from the same static state.
      ! Newton's update stagnates near 2.5e-11 at these tensions: both models to 1e-10.
      call run%init(1.0e-10_dp)
      do k = 1, n
         run%x(3*k - 2:3*k) = [sim%rod%static%r(1, k), 0.0_dp, sim%rod%static%r(2, k)]
      end do
      call run%start(run%x, run%v, 0.0_dp)
      do i = 1, steps
         run%t = (i - 1)*dt
         call run%step(dt, 0.5_dp, error)
         if (allocated(error)) return
      end do
      diff = max(planar_difference(run%x, r, out_of_plane), out_of_plane)
      th_max = maxval(run%problem%piece%th1)
   end subroutine paper_run
   !> The end types' 3-D data: a fairlead (motion end) moving along (0.6, 0.8, 0) and a force end
   !> with a y component and a torque, both ramped. The scene turned by 0.9 rad about the
   !> vertical (the ends' data turned by hand) against the turned motion, 30 steps of 0.5 ms;
   !> the motion end's velocity3 against central differences of position3; the twist rate
   !> against the ramped torque / GIp.
   subroutine test_ends_y(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: diff(2), rate_err, vel_err, h, t
      type(motion_end) :: probe
      integer :: kind, i
      do kind = 1, 2
         call turned_pair(kind, 0.9_dp, diff(kind), rate_err, error)
         if (allocated(error)) return
      end do
      probe = fairlead(0.9_dp)
      vel_err = 0
      h = 1.0e-6_dp
      do i = 1, 20
         t = 0.003_dp*i
         vel_err = max(vel_err, norm2(probe%velocity3(t) - (probe%position3(t + h) - probe%position3(t - h))/(2*h)))
      end do
      write (output_unit, '(4x,a,2es9.2,a,es9.2,a,es9.2)') 'ends with y: turned 0.9 rad (motion end, force end) ', diff, &
         '; velocity3 vs position3 ', vel_err, ' m/s; twist rate vs ramped torque / GIp ', rate_err
      call check(error, maxval(diff) < 1.0e-10_dp, 'a turned scene with 3-D end data differs by more than 1e-10')
      if (allocated(error)) return
      call check(error, vel_err < 1.0e-6_dp .and. rate_err < 1.0e-13_dp, &
                 'the motion end''s velocity3 or the force end''s torque is off')
   end subroutine test_ends_y

   !> The anchor of test_ends_y at (0.3, 0, 0.1) turned by alpha.
   type(fixed_end) function anchor(alpha) result(f)
      real(dp), intent(in) :: alpha
      real(dp) :: p(3)
      p = transform([0.3_dp, 0.0_dp, 0.1_dp], alpha, .false.)
      f = fixed_end(point=[p(1), p(3)], y=p(2))
   end function anchor

   !> The fairlead of test_ends_y at (10.05, 0, -0.5) turned by alpha.
   type(motion_end) function fairlead(alpha) result(m)
      real(dp), intent(in) :: alpha
      real(dp) :: o(3), d(3)
      o = transform([10.05_dp, 0.0_dp, -0.5_dp], alpha, .false.)
      d = transform([0.6_dp, 0.8_dp, 0.0_dp], alpha, .false.)
      m = motion_end(origin=[o(1), o(3)], origin_y=o(2), direction=[d(1), d(3)], direction_y=d(2), &
                     amplitude=0.05_dp, period=0.05_dp, ramp_time=0.01_dp)
   end function fairlead

   !> Kind 1: end b the fairlead; kind 2: end b the force end. The run of the original scene
   !> and of the scene turned by alpha; diff the largest distance between the turned first and
   !> the second, over the span; rate_err the twist rate's error (kind 2).
   subroutine turned_pair(kind, alpha, diff, rate_err, error)
      integer, intent(in) :: kind
      real(dp), intent(in) :: alpha
      real(dp), intent(out) :: diff, rate_err
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run) :: runs(2)
      type(force_end) :: pull
      integer, parameter :: n = 21
      real(dp) :: s(n), f(3), angle, tau_expected, u
      real(dp), allocatable :: tau(:)
      integer :: j, k, i
      s = [(10.0_dp*(k - 1)/(n - 1), k=1, n)]
      rate_err = 0
      do j = 1, 2
         angle = merge(0.0_dp, alpha, j == 1)
         if (kind == 1) then
            call runs(j)%problem%piece%init(s, m_cable, m_cable*g, ei, gip, g, 1.0_dp, tanh_law(), &
                                            anchor(angle), fairlead(angle), 1.0e4_dp, error)
         else
            f = transform([2000.0_dp, 1200.0_dp, 300.0_dp], angle, .false.)
            pull = force_end(history='ramp', force0=[f(1), f(3)], force0_y=f(2), torque0=4.0_dp, duration=0.02_dp)
            call runs(j)%problem%piece%init(s, m_cable, m_cable*g, ei, gip, g, 1.0_dp, tanh_law(), &
                                            anchor(angle), pull, 1.0e4_dp, error)
         end if
         if (allocated(error)) return
         call runs(j)%init(1.0e-11_dp)
         do k = 1, n
            u = (k - 1)/(n - 1.0_dp)
            runs(j)%x(3*k - 2:3*k) = transform([0.3_dp + 9.75_dp*u, 0.1_dp*sin(acos(-1.0_dp)*u), &
                                                0.1_dp - 0.6_dp*u - 0.2_dp*sin(acos(-1.0_dp)*u)], angle, .false.)
         end do
         call runs(j)%start(runs(j)%x, runs(j)%v, 0.0_dp)
         do i = 1, 30
            call runs(j)%step(5.0e-4_dp, 0.5_dp, error)
            if (allocated(error)) return
            if (kind == 2) then
               tau = runs(j)%problem%piece%twist_rates(runs(j)%x)
               tau_expected = 4.0_dp*smooth_ramp(runs(j)%t, 0.0_dp, 0.02_dp)/gip
               rate_err = max(rate_err, maxval(abs(tau - tau_expected))/(4.0_dp/gip))
            end if
         end do
      end do
      diff = 0
      do k = 1, n
         diff = max(diff, norm2(runs(2)%x(3*k - 2:3*k) - transform(runs(1)%x(3*k - 2:3*k), alpha, .false.)))
      end do
      diff = diff/10.05_dp
   end subroutine turned_pair
   !> The 3-D statics of every end kind and variant of the registry's scenes (10 m, 21 nodes,
   !> end a fixed, end b of the kind; dry and in water with a current in the plane), started from
   !> the program's planar static state bowed out of the plane by 1 % of x: it must come back to
   !> the planar state (largest difference / length, y included). Then 20 steps of 0.5 ms in
   !> both models from there: the same positions.
   subroutine test_statics_kinds(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      character(len=8), allocatable :: vs(:)
      character(len=16), allocatable :: kinds(:)
      real(dp) :: worst, d, out_of_plane, worst_run
      integer :: i, j, k, n, wet, step
      kinds = end_kinds()
      worst = 0
      worst_run = 0
      do wet = 0, 1
         do i = 1, size(end_kinds())
            vs = variants(trim(kinds(i)))
            do j = 1, size(vs)
               c = scene_config(trim(kinds(i)), trim(vs(j)), 'tanh', 'law', 0.0_dp, wet == 1)
               ! The free end lies on the registry scene's frictionless sloping bottom: the 3-D statics
               ! from the planar state pushed out of its plane diverges there (the line may turn on the
               ! bottom about end a with little to stop it); the planar statics and steps with the
               ! seabed are checked in suite registry, the 3-D force in suite seabed.
               if (trim(kinds(i)) == 'free') c%seabed_depth = 0
               call sim%prepare(c, error)
               if (allocated(error)) return
               block
               type(rod3d_run) :: run
               associate (q => sim%rod%pieces(1)%problem%piece, r2 => sim%rod%static%r)
                  n = q%n
                  call run%problem%piece%init(q%s, q%mass_per_length, q%weight, q%ei, gip, q%gravity, q%mu, q%law, &
                                              q%end_a, q%end_b, q%tension_ref, error, q%mu2, q%damping)
                  if (allocated(error)) return
                  if (allocated(q%loads)) then
                     call run%problem%piece%set_loads(q%loads, error)
                     if (allocated(error)) return
                  end if
                  call run%init(1.0e-11_dp)
                  do k = 1, n
                     run%x(3*k - 2:3*k) = [r2(1, k), 0.01_dp*r2(1, k), r2(2, k)]
                  end do
                  call run%statics(0.0_dp, error)
                  if (allocated(error)) then
                     error%message = trim(kinds(i))//' '//trim(vs(j))//': '//error%message
                     return
                  end if
                  d = planar_difference(run%x, r2, out_of_plane)
                  ! planar_difference divides by the span; use the length instead.
                  d = max(d*abs(r2(1, n) - r2(1, 1)), out_of_plane*abs(r2(1, n) - r2(1, 1)))/c%length
                  worst = max(worst, d)
                  ! Dynamics in both models.
                  block
                     type(rod_problem) :: p2
                     type(newton_workspace) :: work
                     type(newton_options) :: options
                     type(newton_report) :: report
                     real(dp), allocatable :: r(:, :), v(:, :), v1(:, :), x2(:)
                     p2 = sim%rod%pieces(1)%problem
                     call work%init(2*n, rod_kl, rod_ku, spread(p2%piece%length_ref, 1, 2*n))
                     options%tolerance = 1.0e-11_dp
                     options%max_iterations = 60
                     r = r2
                     allocate (v(2, n), v1(2, n))
                     v = 0
                     run%v = 0
                     call run%start(run%x, run%v, 0.0_dp)
                     do step = 1, 20
                        call p2%piece%prepare_step(r, v)
                        p2%dt = 5.0e-4_dp
                        p2%t0 = (step - 1)*5.0e-4_dp
                        x2 = reshape(r + 5.0e-4_dp*v, [2*n])
                        call newton_solve(p2, x2, work, options, report, error)
                        if (allocated(error)) return
                        call p2%piece%new_velocity(reshape(x2, [2, n]), 5.0e-4_dp, 0.5_dp, v1)
                        r = reshape(x2, [2, n])
                        v = v1
                        run%t = (step - 1)*5.0e-4_dp
                        call run%step(5.0e-4_dp, 0.5_dp, error)
                        if (allocated(error)) return
                     end do
                     d = planar_difference(run%x, r, out_of_plane)
                     d = max(d*abs(r(1, n) - r(1, 1)), out_of_plane*abs(r(1, n) - r(1, 1)))/c%length
                     worst_run = max(worst_run, d)
                  end block
               end associate
               end block
            end do
         end do
      end do
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') '3-D statics of every end kind (dry and wet) vs the planar statics: ', &
         worst, ' of the length; after 20 steps ', worst_run
      call check(error, worst < 1.0e-14_dp, 'a 3-D static state differs from the planar one by more than 1e-14')
      if (allocated(error)) return
      call check(error, worst_run < 1.0e-11_dp, 'a 3-D run differs from the planar one by more than 1e-11')
   end subroutine test_statics_kinds

   !> The step control's fold check in 3-D (rod3d_piece%turning_folds):
   !> (a) cells 3 and 4 of a 5-node line turned by 0.2 rad so that the
   !> turning angle at node 3 goes from pi - 0.1 through half a turn: 2 pi at
   !> node 3, 0 elsewhere, in the x-z plane and turned out of it by a
   !> rotation; (b) a planar pair of curved states (turning angles of both
   !> signs, none through half a turn): the planar rod's value, 0; (c) a 3-D
   !> change of a curved state scaled by 1 and 1/2: first order out of the
   !> plane (ratio near 2), far below 3.
   subroutine test_fold_check(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_problem) :: p
      real(dp) :: r0(3, 5), r1(3, 5), v0(3, 5), fold(5), q(3, 3), a, c, s, worst, planar(5), ang0(4), ang1(4)
      real(dp), allocatable :: x(:), rc(:, :), vc(:, :), f1(:), f2(:)
      integer :: k, n
      call make_piece3(p, 5, 4.0_dp, end3(is_held=.true.), error)
      if (allocated(error)) return
      v0 = 0
      ! (a) Cells at the angles (about -y, in x-z) 0, 0, pi - 0.1, pi - 0.1, then 0, 0, pi + 0.1, pi + 0.1.
      ang0 = [0.0_dp, 0.0_dp, pi - 0.1_dp, pi - 0.1_dp]
      ang1 = [0.0_dp, 0.0_dp, pi + 0.1_dp, pi + 0.1_dp]
      call polyline(ang0, r0)
      call polyline(ang1, r1)
      ! A rotation out of the plane (about (1, 2, 3) by 0.8 rad, Rodrigues).
      a = 0.8_dp
      c = cos(a)
      s = sin(a)
      block
         real(dp) :: u(3)
         u = [1.0_dp, 2.0_dp, 3.0_dp]/sqrt(14.0_dp)
         q = reshape([c + u(1)**2*(1 - c), u(2)*u(1)*(1 - c) + u(3)*s, u(3)*u(1)*(1 - c) - u(2)*s, &
                      u(1)*u(2)*(1 - c) - u(3)*s, c + u(2)**2*(1 - c), u(3)*u(2)*(1 - c) + u(1)*s, &
                      u(1)*u(3)*(1 - c) + u(2)*s, u(2)*u(3)*(1 - c) - u(1)*s, c + u(3)**2*(1 - c)], [3, 3])
      end block
      worst = 0
      do k = 1, 2
         call p%piece%prepare_step(r0, v0)
         call p%piece%turning_folds(r1, fold)
         worst = max(worst, abs(fold(3) - 2*pi), maxval(abs(fold([1, 2, 4, 5]))))
         r0 = matmul(q, r0)
         r1 = matmul(q, r1)
      end do
      write (output_unit, '(4x,a,es9.2)') 'fold check through half a turn, in and out of the plane: off 2 pi (node 3) '// &
         'and 0 (others) by ', worst
      call check(error, worst < 1.0e-14_dp, 'fold check through half a turn off by '//str(worst))
      if (allocated(error)) return
      ! (b) A planar pair: cells at angles 0.3 k and 0.3 k + 0.5 sin(k) (turning angles of either sign).
      ang0 = [(0.3_dp*k, k=1, 4)]
      ang1 = [(0.3_dp*k + 0.5_dp*sin(real(3*k, dp)), k=1, 4)]
      call polyline(ang0, r0)
      call polyline(ang1, r1)
      call p%piece%prepare_step(r0, v0)
      call p%piece%turning_folds(r1, fold)
      ! The planar rod's |th1 - th0 - (dphi_b - dphi_a)| with th = angle(b) - angle(a) and dphi = angle1 - angle0
      ! of each cell: 0 while no angle wraps through half a turn.
      planar = 0
      worst = maxval(abs(fold - planar))
      write (output_unit, '(4x,a,es9.2)') 'fold check of a planar pair against the planar formula: ', worst
      call check(error, worst < 1.0e-15_dp, 'planar fold check differs from the planar rod''s by '//str(worst))
      if (allocated(error)) return
      ! (c) First order in the change of a curved 3-D state.
      n = 9
      call make_piece3(p, n, 8.0_dp, end3(is_held=.true.), error)
      if (allocated(error)) return
      call curved_state(n, 8.0_dp, x, rc, vc)
      allocate (f1(n), f2(n))
      call p%piece%prepare_step(rc, vc)
      call p%piece%turning_folds(rc + 0.1_dp*(reshape(x(1:3*n), [3, n]) - rc), f1)
      call p%piece%turning_folds(rc + 0.05_dp*(reshape(x(1:3*n), [3, n]) - rc), f2)
      write (output_unit, '(4x,a,es9.2,a,f6.2)') 'fold check of a small 3-D change: largest ', maxval(f1), &
         ', ratio at half the change ', maxval(f1)/maxval(f2)
      call check(error, maxval(f1) < 0.1_dp .and. maxval(f1)/maxval(f2) > 1.8_dp .and. maxval(f1)/maxval(f2) < 2.2_dp, &
                 'fold check of a small change: '//str(maxval(f1))//', ratio '//str(maxval(f1)/maxval(f2)))

   contains

      !> Nodes of a line of unit cells at the angles ang (about -y: the direction (cos, 0, sin)).
      subroutine polyline(ang, r)
         real(dp), intent(in) :: ang(:)
         real(dp), intent(out) :: r(:, :)
         integer :: j
         r(:, 1) = 0
         do j = 1, size(ang)
            r(:, j + 1) = r(:, j) + [cos(ang(j)), 0.0_dp, sin(ang(j))]
         end do
      end subroutine polyline
   end subroutine test_fold_check
end module suite_rod3d
