!> Numerical stability (issue 6): the step control, the damping of the time
!> weight theta, and what the model does once the fixed end is in compression.
!> Every run is small (61 to 241 nodes) and calls the library directly.
module suite_stability
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_io_input, only: case_config
   use xcable_box_case, only: setup_case
   use xcable_box_equations, only: cable_model, i_eps, i_om
   use xcable_box_geometry, only: positions
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options, run_history, run_summary, run_observer, run_rupture
   use xcable_box_statics, only: static_state, solve_statics
   use xcable_theory_closed_forms, only: riemann_speed
   implicit none
   private
   public :: collect_stability

   !> Records the compressed zone at the fixed end at each snapshot.
   type, extends(run_observer) :: zone_probe
      type(cable_model) :: model
      real(dp), allocatable :: s(:), omega_static(:)
      integer :: n = 0
      !> Time, s; fixed-end tension, N; length of the zone with T < 0 from the
      !> fixed end, m; largest distance of its nodes from its chord, m;
      !> largest |Omega3 - static| in it, 1/m.
      real(dp) :: time(400) = 0, wall_tension(400) = 0, length(400) = 0, deflection(400) = 0, curvature(400) = 0
   contains
      procedure :: snapshot => probe_snapshot
   end type zone_probe

contains

   !> The tests of the suite.
   subroutine collect_stability(tests)
      !> Tests.
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('rejected_steps_recorded', test_rejected_steps), &
               new_unittest('step_floor_named_error', test_step_floor), &
               new_unittest('wall_clock_named_error', test_wall_clock), &
               new_unittest('theta_damps_ringing', test_theta_ringing), &
               new_unittest('compression_buckles', test_compression)]
   end subroutine collect_stability

   !> The paper's cable built like the app builds a case (area and EA derived).
   subroutine make_case(tension, nodes, t_break, t_end, courant, theta, model, s, newton, dynamics, state, error)
      real(dp), intent(in) :: tension, t_break, t_end, courant, theta
      integer, intent(in) :: nodes
      type(cable_model), intent(out) :: model
      real(dp), allocatable, intent(out) :: s(:)
      type(newton_options), intent(out) :: newton
      type(dynamics_options), intent(out) :: dynamics
      type(static_state), intent(out) :: state
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      config%source = 'suite_stability'
      config%tension = tension
      config%nodes = nodes
      config%t_break = t_break
      config%t_end = t_end
      config%courant = courant
      config%theta = theta
      config%quiet = .true.
      call setup_case(config, model, s, newton, dynamics, error)
      if (allocated(error)) return
      call solve_statics(model, s, tension, newton, state, error)
   end subroutine make_case

   !> Step control at Courant 2. Unconstrained, Newton diverges at a step or
   !> two where the end force vanishes (t -> t_break: the end strain falls to
   !> where the wave speed is four times lower); the step is halved and must
   !> then grow back to dt. With Newton limited to three iterations the step
   !> is halved again and again; the run must still reach t_end, record every
   !> rejected attempt against the step that followed, grow the step again
   !> after its smallest value, and give the answer (simple-wave theory).
   subroutine test_rejected_steps(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      type(run_history) :: history, reference
      type(run_summary) :: summary, reference_summary
      real(dp) :: theory
      call make_case(180.0e3_dp, 61, 5.0e-3_dp, 0.04_dp, 2.0_dp, 0.5_dp, model, s, newton, dyn, state, error)
      if (allocated(error)) return
      call run_rupture(model, s, state%y, dyn, reference, reference_summary, error)
      if (allocated(error)) return
      call check_steps(reference, reference_summary, 'unconstrained run', .true.)
      if (allocated(error)) return
      dyn%newton%max_iterations = 3
      call run_rupture(model, s, state%y, dyn, history, summary, error)
      if (allocated(error)) then
         error%message = 'a run forced to reject steps failed: '//error%message
         return
      end if
      call check(error, summary%rejected_steps > reference_summary%rejected_steps + 5, 'max_iterations = 3 '// &
                 'rejected '//str(summary%rejected_steps)//' steps, the reference '//str(reference_summary%rejected_steps))
      if (allocated(error)) return
      call check_steps(history, summary, 'run with max_iterations = 3', .false.)
      if (allocated(error)) return
      ! Both on the plateau of simple-wave theory (the smaller steps of the bounded run are closer to it).
      theory = riemann_speed(model%law, model%mass, model%law%strain_at(0.0_dp), model%law%strain_at(180.0e3_dp))
      call check_close(error, abs(reference%end_velocity(reference%n)), theory, 'end speed at t_end of the '// &
                       'unconstrained run against simple-wave theory', rel_tol=1.0e-2_dp)
      if (allocated(error)) return
      call check_close(error, abs(history%end_velocity(history%n)), theory, 'end speed at t_end with the iteration '// &
                       'bound against simple-wave theory', rel_tol=1.0e-2_dp)

   contains

      !> The history of a complete run against the step control's rules.
      subroutine check_steps(h, summ, what, back_to_dt)
         type(run_history), intent(in) :: h
         type(run_summary), intent(in) :: summ
         character(*), intent(in) :: what
         !> Whether the step must be dt again after the last rejection.
         logical, intent(in) :: back_to_dt
         integer :: i, smallest, last_rejection
         call check_close(error, summ%time_reached, dyn%t_end, what//': time reached', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check(error, sum(h%rejected(1:h%n)) == summ%rejected_steps .and. h%rejected(0) == 0, &
                    what//': history%rejected sums to '//str(sum(h%rejected(0:h%n)))//', summary says '// &
                    str(summ%rejected_steps))
         if (allocated(error)) return
         last_rejection = 0
         do i = 1, h%n
            call check(error, h%step(i) >= dyn%dt*dyn%min_step_fraction*(1 - 1.0e-9_dp) .and. &
                       h%step(i) <= dyn%dt*(1 + 1.0e-9_dp), what//': step '//str(i)//' is '//str(h%step(i))//' s')
            if (allocated(error)) return
            if (h%rejected(i) > 0) last_rejection = i
         end do
         if (summ%rejected_steps == 0) return
         smallest = minloc(h%step(1:h%n), 1)
         call check(error, h%step(smallest) <= 0.5_dp*dyn%dt*(1 + 1.0e-9_dp), what//': rejections but no step '// &
                    'below dt / 2')
         if (allocated(error)) return
         call check(error, maxval(h%step(smallest:h%n - 1)) >= 1.99_dp*h%step(smallest), what//': the step did '// &
                    'not grow after its smallest value '//str(h%step(smallest))//' s')
         if (allocated(error)) return
         if (back_to_dt .and. last_rejection < h%n - 12) then
            call check(error, maxval(h%step(last_rejection:h%n - 1)) >= dyn%dt*(1 - 1.0e-6_dp), &
                       what//': the step did not grow back to dt after the last rejection')
         end if
      end subroutine check_steps
   end subroutine test_rejected_steps

   !> With no room to halve (min_step_fraction = 1) a rejected step ends the
   !> run with a named step-control error, and the summary holds what was done.
   subroutine test_step_floor(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      type(run_history) :: history
      type(run_summary) :: summary
      type(error_type), allocatable :: run_error
      call make_case(180.0e3_dp, 61, 5.0e-3_dp, 0.04_dp, 2.0_dp, 0.5_dp, model, s, newton, dyn, state, error)
      if (allocated(error)) return
      dyn%newton%max_iterations = 2
      dyn%min_step_fraction = 1
      call run_rupture(model, s, state%y, dyn, history, summary, run_error)
      call check(error, allocated(run_error), 'the run did not fail without room to halve the step')
      if (allocated(error)) return
      call check(error, index(run_error%message, 'step control: step fell below') == 1 .and. &
                 index(run_error%message, 'Newton') > 0, 'message: '//run_error%message)
      if (allocated(error)) return
      call check(error, summary%time_reached < dyn%t_end .and. summary%time_reached == history%time(history%n), &
                 'time reached '//str(summary%time_reached)//' is not the last record '//str(history%time(history%n)))
      if (allocated(error)) return
      call check(error, summary%rejected_steps == sum(history%rejected(1:history%n)) + 1, &
                 'the failing attempt is not counted in summary%rejected_steps')
   end subroutine test_step_floor

   !> A wall-clock limit far below the run's length stops it with a named error
   !> (rejected attempts cannot hide from it: it is checked before each attempt).
   subroutine test_wall_clock(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      type(run_history) :: history
      type(run_summary) :: summary
      type(error_type), allocatable :: run_error
      call make_case(180.0e3_dp, 61, 5.0e-3_dp, 0.04_dp, 0.25_dp, 0.5_dp, model, s, newton, dyn, state, error)
      if (allocated(error)) return
      dyn%max_wall_time = 1.0e-9_dp
      call run_rupture(model, s, state%y, dyn, history, summary, run_error)
      call check(error, allocated(run_error), 'a run of hundreds of steps was not stopped by a 1 ns wall-clock limit')
      if (allocated(error)) return
      call check(error, index(run_error%message, 'wall-clock limit') == 1, 'message: '//run_error%message)
      if (allocated(error)) return
      call check(error, summary%time_reached < dyn%t_end, 'the run reached t_end')
   end subroutine test_wall_clock

   !> An instantaneous break rings in the paper's scheme: the box scheme's
   !> short waves run ahead of the front and lift the fixed-end tension above
   !> its static value before the front arrives. theta = 0.55 damps them
   !> ((1 - theta) / theta = 0.82 per step for the shortest) and keeps the
   !> breaking-end speed within 0.2 % of simple-wave theory.
   subroutine test_theta_ringing(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: overshoot(2), speed(2), theory
      real(dp), parameter :: thetas(2) = [0.5_dp, 0.55_dp]
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      type(run_history) :: history
      type(run_summary) :: summary
      integer :: k, i, last
      do k = 1, 2
         call make_case(180.0e3_dp, 121, 0.0_dp, 0.1_dp, 1.0_dp, thetas(k), model, s, newton, dyn, state, error)
         if (allocated(error)) return
         call run_rupture(model, s, state%y, dyn, history, summary, error)
         if (allocated(error)) return
         ! The tension window: until the fixed end first goes into compression.
         last = history%n
         do i = 1, history%n
            if (history%fixed_end_tension(i) <= 0) then
               last = i - 1
               exit
            end if
         end do
         overshoot(k) = (maxval(history%fixed_end_tension(0:last)) - history%fixed_end_tension(0))/180.0e3_dp
         speed(k) = maxval(abs(history%end_velocity(0:last)))
      end do
      theory = riemann_speed(model%law, model%mass, model%law%strain_at(0.0_dp), model%law%strain_at(180.0e3_dp))
      call check(error, overshoot(1) > 0.5_dp, 'theta = 0.5 should ring: the fixed-end tension rises only '// &
                 str(overshoot(1))//' T_s above its static value')
      if (allocated(error)) return
      call check(error, overshoot(2) < 0.2_dp*overshoot(1) .and. overshoot(2) < 0.2_dp, &
                 'theta = 0.55 leaves an overshoot of '//str(overshoot(2))//' T_s (theta = 0.5: '//str(overshoot(1))//')')
      if (allocated(error)) return
      call check_close(error, speed(2), theory, 'peak end speed with theta = 0.55 against simple-wave theory', &
                       rel_tol=2.0e-3_dp)
   end subroutine test_theta_ringing

   !> After the unloading front reflects at the fixed end (u = v = 0) the fixed
   !> end goes into compression. The compression is bounded by the law at
   !> the strain floor, f(-0.9) = -7.72 kN, but is at once far above the
   !> Euler load pi^2 EI / l^2 of the compressed zone, so the straight cable
   !> is unstable; in the model it buckles within about 20 ms (the curvature
   !> in the zone departs from its static value, 7e-5 1/m, by 0.1 1/m: a 2 mm
   !> buckle at the fastest-growing wavelength, 0.9 m; the zone moves 1 cm off
   !> its chord), and the run either reaches t_end or stops with a named
   !> step-control reason, never with NaN.
   subroutine test_compression(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      type(run_history) :: history
      type(run_summary) :: summary
      type(error_type), allocatable :: run_error
      type(zone_probe) :: probe
      real(dp) :: front, t_compression, law_limit, euler, t_buckled, t_deflected, c0
      integer :: i
      call make_case(315.0e3_dp, 241, 5.0e-3_dp, 0.14_dp, 1.0_dp, 0.5_dp, model, s, newton, dyn, state, error)
      if (allocated(error)) return
      dyn%interval = 1.0e-3_dp
      probe%model = model
      probe%s = s
      probe%omega_static = state%y(i_om, :)
      call run_rupture(model, s, state%y, dyn, history, summary, run_error, probe)
      if (allocated(run_error)) then
         call check(error, index(run_error%message, 'step control:') == 1 .and. &
                    (index(run_error%message, 'collapsed') > 0 .or. index(run_error%message, 'unit circle') > 0), &
                    'the compressed run stopped for an unexpected reason: '//run_error%message)
         if (allocated(error)) return
      end if
      ! Into compression only after the front has crossed the cable.
      c0 = sqrt(model%law%stiffness(model%law%strain_at(315.0e3_dp))/model%mass)
      front = model%length/c0
      t_compression = -1
      do i = 1, history%n
         if (history%fixed_end_tension(i) <= 0) then
            t_compression = history%time(i)
            exit
         end if
      end do
      call check(error, t_compression > front .and. t_compression < front + 0.03_dp, &
                 'the fixed end went into compression at '//str(t_compression)//' s; the front crosses in '//str(front)//' s')
      if (allocated(error)) return
      call check(error, summary%time_reached > t_compression + 0.02_dp, 'Newton and the step control gave up '// &
                 str(summary%time_reached - t_compression)//' s after the compression began')
      if (allocated(error)) return
      ! Bounded by the law at the strain floor of the step control, f(-0.9)
      ! (p4 - p1 + p5 eps: -7.72 kN), at every step, not only the snapshots.
      law_limit = model%law%tension(-0.9_dp)
      call check(error, summary%min_fixed_end_tension >= law_limit - 1.0_dp .and. &
                 summary%min_fixed_end_tension < 0.8_dp*law_limit, 'fixed-end compression '// &
                 str(summary%min_fixed_end_tension)//' N against the law''s limit '//str(law_limit)//' N')
      if (allocated(error)) return
      ! Far above the Euler load of the zone, and it buckles.
      t_buckled = -1
      t_deflected = -1
      euler = huge(1.0_dp)
      do i = 1, probe%n
         if (probe%length(i) > 0 .and. probe%wall_tension(i) < 0.5_dp*law_limit) then
            euler = min(euler, pi**2*model%bending_stiffness/probe%length(i)**2/abs(probe%wall_tension(i)))
         end if
         if (t_buckled < 0 .and. probe%curvature(i) > 0.1_dp) t_buckled = probe%time(i)
         if (t_deflected < 0 .and. probe%deflection(i) > 0.01_dp) t_deflected = probe%time(i)
      end do
      call check(error, euler < 0.1_dp, 'the compression never exceeds ten times the Euler load of the zone '// &
                 '(smallest P_E / |T| = '//str(euler)//')')
      if (allocated(error)) return
      call check(error, t_buckled > t_compression .and. t_buckled < t_compression + 0.04_dp, &
                 'the compressed zone did not buckle within 40 ms (curvature changed by 0.1 1/m at '// &
                 str(t_buckled)//' s; compression from '//str(t_compression)//' s)')
      if (allocated(error)) return
      call check(error, t_deflected > t_compression .and. t_deflected < t_compression + 0.04_dp, &
                 'the compressed zone did not move 1 cm off its chord within 40 ms (at '//str(t_deflected)//' s)')
   end subroutine test_compression

   !> Measure the compressed zone (run_observer).
   subroutine probe_snapshot(self, t, y, error)
      class(zone_probe), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: y(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: x(size(self%s)), z(size(self%s)), tension(size(self%s)), chord_x, chord_z, chord
      integer :: k, last
      if (self%n == size(self%time)) then
         call fatal_error(error, 'zone_probe: too many snapshots')
         return
      end if
      self%n = self%n + 1
      tension = self%model%law%tension(y(i_eps, :))
      call positions(y, self%s, x, z)
      last = 0
      do k = 1, size(self%s) - 1
         if (tension(k) >= 0) exit
         last = k
      end do
      self%time(self%n) = t
      self%wall_tension(self%n) = tension(1)
      self%length(self%n) = 0
      self%deflection(self%n) = 0
      self%curvature(self%n) = 0
      if (last == 0) return
      self%length(self%n) = self%s(last) + (self%s(last + 1) - self%s(last))*(-tension(last))/ &
                            (tension(last + 1) - tension(last))
      chord_x = x(last) - x(1)
      chord_z = z(last) - z(1)
      chord = max(hypot(chord_x, chord_z), tiny(1.0_dp))
      do k = 1, last
         self%deflection(self%n) = max(self%deflection(self%n), abs((x(k) - x(1))*chord_z - (z(k) - z(1))*chord_x)/chord)
         self%curvature(self%n) = max(self%curvature(self%n), abs(y(i_om, k) - self%omega_static(k)))
      end do
   end subroutine probe_snapshot
end module suite_stability
