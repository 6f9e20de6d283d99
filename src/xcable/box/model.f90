!> The paper's box scheme (eqs. 22-25) as a model of the cable for the one
!> step loop (driver/stepping.f90): at each step Newton's method on all boxes
!> with the analytic Jacobian and the banded solve, the checks of the new
!> state, the records of the two ends and the ledger.
!>
!> The breaking end carries the static end force scaled by
!> cos^2(pi t / (2 t_break)) until t_break and zero after (eqs. 31-32).
!>
!> Its step plan is its own (plan, advance): steps are uniform within each
!> output interval (a whole number of them from the step control's step to
!> the next snapshot or t_end), and the snapshots are the states at the ends
!> of those steps, not interpolated. The step control's halving, its retry
!> with a fresh Jacobian and its bounds are the driver's (reject_attempt);
!> when the step doubles back after four good steps, the kept factorisation
!> (which holds the mass terms of the old step) is dropped. These are the
!> steps of version 0.1, to the last digit.
!>
!> Its summary is its own (finish): the box scheme's figures of version 0.1
!> (summarise), translated into the run's summary.
module xcable_box_model
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, stat_numerics, stat_input
   use xcable_core_strings, only: str
   use xcable_box_equations, only: box_cable => cable_model, n_eq, i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om
   use xcable_box_geometry, only: positions, fixed_frame_velocity
   use xcable_box_discrete, only: box_system
   use xcable_box_dynamics, only: dynamics_options, box_history => run_history, box_summary => run_summary, &
                                  rupture_factor, energy_terms
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   use xcable_theory_closed_forms, only: wave_speed
   use xcable_io_archive, only: state_archive, sync_real, sync_reals, sync_matrix, sync_cube, sync_int, sync_ints
   use xcable_driver_rod_run, only: rod_run, cable_model, snapshot_time, exchange_progress
   use xcable_driver_history, only: exchange_records
   use xcable_driver_records, only: run_observer, run_summary, n_fields
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: box_model, state_fields

   !> The box scheme as a model of the cable in a run.
   type, extends(cable_model) :: box_model
      !> Cable data, node arc lengths (m), the static state (n_eq, nodes) and the controls.
      type(box_cable) :: cable
      real(dp), allocatable :: s(:), y_static(:, :)
      type(dynamics_options) :: options
      !> Courant number asked for (the run's summary).
      real(dp) :: courant = 1
      !> The discrete system, Newton's work arrays and controls, and the report of the last solve.
      type(box_system) :: system
      type(newton_workspace) :: work
      type(newton_options) :: newton
      type(newton_report) :: report
      !> The state (n_eq, nodes) at run%t and the level before, and the new level being tried.
      real(dp), allocatable :: y(:, :), y_prev(:, :), x_new(:), xpos(:), zpos(:)
      !> The step that led to y (s), and whether there was one.
      real(dp) :: h_prev = 0
      logical :: have_prev = .false.
      !> Static end force at the breaking end (N); the ledger's power of the end force (W) and its work (J).
      real(dp) :: force_h = 0, force_v = 0, power_old = 0, work_done = 0
      !> The box scheme's own records and figures (version 0.1's run_history and run_summary).
      type(box_history) :: history
      type(box_summary) :: summary
   contains
      !> The cable, the grid, the static state and the controls; the run's options, step and
      !> output grid from them.
      procedure :: setup => box_setup
      procedure :: begin => box_begin
      procedure :: attempt => box_attempt
      procedure :: reject => box_reject
      procedure :: watch => box_watch
      procedure :: accept => box_accept
      procedure :: snapshot => box_snapshot
      procedure :: record => box_record
      procedure :: split => box_split
      procedure :: end_info => box_end_info
      procedure :: conclude => box_conclude
      procedure :: save_state => box_save_state
      procedure :: load_state => box_load_state
      procedure :: plan => box_plan
      procedure :: advance => box_advance
      procedure :: finish => box_finish
      procedure :: reject_step => box_reject_step
      procedure :: snapshot_at => box_snapshot_at
   end type box_model

contains

   !> The cable, grid, static state and controls of the model, and the run they make: its
   !> options, time step and output nodes (the run's scene is empty: no break inside, the
   !> release of end b is the model's ramp).
   subroutine box_setup(self, cable, s, y_static, options, courant, run)
      !> Model.
      class(box_model), intent(inout) :: self
      !> Cable data.
      type(box_cable), intent(in) :: cable
      !> Node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Static state (n_eq, nodes).
      real(dp), intent(in) :: y_static(:, :)
      !> Controls of the time stepping.
      type(dynamics_options), intent(in) :: options
      !> Courant number asked for.
      real(dp), intent(in) :: courant
      !> Run to set up.
      type(rod_run), intent(inout) :: run
      self%cable = cable
      self%s = s
      self%y_static = y_static
      self%options = options
      self%courant = courant
      run%options%nodes = size(s)
      run%options%dt = options%dt
      run%options%courant = courant
      run%options%t_end = options%t_end
      run%options%theta = options%theta
      run%options%interval = options%interval
      run%options%newton = options%newton
      run%options%extrapolate = options%extrapolate
      run%options%energy = options%energy
      run%options%min_step_fraction = options%min_step_fraction
      run%options%max_wall_time = options%max_wall_time
      run%dt = options%dt
      run%s = s
      run%s_out = s
      run%n_out = size(s)
      run%break_node = 0
   end subroutine box_setup

   !> The state at t = 0, the Newton settings of a step, the system and its work arrays, the
   !> history's end labels; the static state and its snapshot to the observer.
   subroutine box_begin(self, run, observer, error)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(run_observer), intent(inout), optional :: observer
      type(error_type), allocatable, intent(out) :: error
      integer :: np
      np = size(self%s)
      call box_ready(self)
      self%work_done = 0
      self%power_old = 0
      if (allocated(run%history%end_labels)) deallocate (run%history%end_labels)
      allocate (run%history%end_labels(2))
      run%history%end_labels = [character(len=8) :: 'end_a', 'end_b']
      call run%history%reserve(16, 2, self%options%energy)
      if (.not. present(observer)) return
      call observer%static(run%info, error)
      if (allocated(error)) return
      block
         real(dp) :: fields(np, n_fields)
         call state_fields(self%cable, self%s, self%y, fields)
         call observer%snapshot(0.0_dp, fields, error)
      end block
   end subroutine box_begin

   !> The state at t = 0 (the static state, no step before it), the Newton settings of a step,
   !> the system and its work arrays, the static end force, and the box scheme's own records
   !> empty with room for the requested steps: what begin and load_state start from.
   subroutine box_ready(self)
      class(box_model), intent(inout) :: self
      type(box_history) :: fresh_history
      type(box_summary) :: fresh_summary
      real(dp) :: end_tension, c_ref
      integer :: np, kl, ku, capacity
      np = size(self%s)
      self%y = self%y_static
      self%y_prev = self%y_static
      if (allocated(self%x_new)) deallocate (self%x_new, self%xpos, self%zpos)
      allocate (self%x_new(n_eq*np), self%xpos(np), self%zpos(np))
      self%h_prev = self%options%dt
      self%have_prev = .false.
      ! Newton settings of a time step (docs/measurements/benchmark.md, "Speed work"): stop on
      ! the contraction estimate, keep the Jacobian while it contracts by 0.5
      ! per iteration within a step, refresh it at the start of a step once it
      ! contracted by more than 0.05, and skip the report's final residual.
      self%newton = self%options%newton
      self%newton%final_residual = .false.
      self%newton%estimate_error = .true.
      self%newton%max_contraction = 0.5_dp
      self%newton%refresh_contraction = 0.05_dp
      end_tension = self%cable%law%tension(self%y_static(i_eps, np))
      ! Static end force: the internal force vector T t + Sn n at the breaking end.
      associate (b0 => self%y_static(i_b0, np), b3 => self%y_static(i_b3, np), sn => self%y_static(i_sn, np))
         self%force_v = end_tension*(b0**2 - b3**2) - sn*2*b0*b3
         self%force_h = end_tension*2*b0*b3 + sn*(b0**2 - b3**2)
      end associate
      c_ref = wave_speed(self%cable%law, self%cable%mass, self%y_static(i_eps, np))
      call self%system%init(self%cable, self%s, .true., end_tension, c_ref, self%options%theta)
      self%system%omega_fixed = self%y_static(i_om, 1)
      self%system%omega_free = self%y_static(i_om, np)
      call self%system%band_widths(kl, ku)
      call self%work%init(n_eq*np, kl, ku, self%system%unknown_scale())
      ! Room for the requested steps and snapshots (in real arithmetic: a step
      ! that is tiny against t_end overflowed the integer count); the history
      ! grows when the step control needs more.
      self%history = fresh_history
      self%summary = fresh_summary
      associate (o => self%options)
         capacity = int(min(o%t_end/o%dt + o%t_end/max(o%interval, o%dt), 1.0e6_dp)) + 16
      end associate
      call self%history%reserve(capacity, self%options%energy)
   end subroutine box_ready

   !> The box scheme's step plan: a whole number of equal steps, of at most the step control's
   !> step, to the next snapshot or t_end (t_stop); landing: this is the last of them.
   subroutine box_plan(self, run, h_try, t_stop, landing, error)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(out) :: h_try, t_stop
      logical, intent(out) :: landing
      type(error_type), allocatable, intent(out) :: error
      integer(i8) :: nsteps
      real(dp) :: t_event
      t_event = min(snapshot_time(run, run%progress%snapshot_index), run%options%t_end)
      nsteps = max(1_i8, ceiling(min((t_event - run%t)/run%progress%h - 1.0e-6_dp, 1.0e18_dp), i8))
      h_try = (t_event - run%t)/nsteps
      if (nsteps == 1) h_try = t_event - run%t
      t_stop = t_event
      landing = nsteps == 1
      if (.not. (run%t + h_try > run%t)) &
         call fatal_error(error, 'step control: the step '//str(h_try)//' s no longer advances the time at t = '// &
                          str(run%t)//' s', stat_numerics)
   end subroutine box_plan

   !> The time after an accepted step: onto t_stop for the last step of a plan; after four good
   !> steps a halved step doubles back towards dt, and the kept factorisation (with the mass
   !> terms of the old step) is dropped.
   subroutine box_advance(self, run, h_try, t_stop, landing)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h_try, t_stop
      logical, intent(in) :: landing
      if (landing) then
         run%t = t_stop
      else
         run%t = run%t + h_try
      end if
      associate (h => run%progress%h, n_good => run%progress%n_good)
         if (h < run%dt) then
            n_good = n_good + 1
            if (n_good >= 4) then
               h = min(2*h, run%dt)
               n_good = 0
               self%work%usable = .false.
            end if
         end if
      end associate
   end subroutine box_advance

   !> The step control after a rejected attempt (the driver's reject_attempt with the box
   !> scheme's words): count it; the same step again (retry) or half of it; the error when the
   !> run has rejected more than 1000 + the requested steps, or the step fell below
   !> min_step_fraction dt.
   subroutine box_reject_step(self, run, reason, retry, error)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      character(*), intent(in) :: reason
      logical, intent(in) :: retry
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: max_rejections
      max_rejections = 1000 + self%options%t_end/self%options%dt
      associate (h => run%progress%h, n_good => run%progress%n_good, rejected_here => run%progress%rejected_here, &
                 rejected => run%summary%rejected_steps)
         rejected = rejected + 1
         rejected_here = rejected_here + 1
         if (rejected > max_rejections) then
            call fatal_error(error, 'step control: '//str(rejected)//' rejected attempts by t = '// &
                             str(run%t)//' s (the limit is 1000 + the '// &
                             str(nint(min(max_rejections - 1000, 2.0e9_dp)))// &
                             ' requested steps): the step stays far below dt = '//str(self%options%dt)// &
                             ' s; last: '//reason, stat_numerics)
            return
         end if
         if (retry) return
         h = 0.5_dp*h
         n_good = 0
         if (h < self%options%dt*self%options%min_step_fraction) &
            call fatal_error(error, 'step control: step fell below '// &
                             str(self%options%dt*self%options%min_step_fraction)//' s at t = '//str(run%t)// &
                             ' s after '//str(rejected_here)//' rejected attempts; last: '//reason, stat_numerics)
      end associate
   end subroutine box_reject_step

   !> A snapshot is the state where the plan landed: at ts, or at t_end when ts passes it by
   !> round-off.
   real(dp) function box_snapshot_at(self, run, ts) result(t)
      class(box_model), intent(in) :: self
      type(rod_run), intent(in) :: run
      real(dp), intent(in) :: ts
      t = min(ts, run%options%t_end)
   end function box_snapshot_at

   !> A step of h from run%t: Newton on all boxes from the extrapolated state, then the checks.
   subroutine box_attempt(self, run, h, iterations, retry_same, error)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer, intent(out) :: iterations
      logical, intent(out) :: retry_same
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: r
      integer :: k, np
      logical :: kept_jacobian
      np = size(self%s)
      r = rupture_factor(run%t + h, self%options%t_break)
      call self%system%prepare_step(self%y, h, r*self%force_h, r*self%force_v)
      ! First guess (node by node: no array temporaries in the time loop).
      do k = 1, np
         if (self%have_prev .and. self%options%extrapolate) then
            self%x_new(n_eq*(k - 1) + 1:n_eq*k) = self%y(:, k) + (h/self%h_prev)*(self%y(:, k) - self%y_prev(:, k))
         else
            self%x_new(n_eq*(k - 1) + 1:n_eq*k) = self%y(:, k)
         end if
      end do
      ! Whether Newton starts from a factorisation kept from earlier steps
      ! (the test of newton_solve for a fresh one).
      kept_jacobian = self%newton%reuse_jacobian .and. self%work%usable .and. &
                      self%work%contraction <= self%newton%refresh_contraction
      call newton_solve(self%system, self%x_new, self%work, self%newton, self%report, error)
      self%summary%factorisations = self%summary%factorisations + self%report%factorisations
      iterations = self%report%iterations
      ! A Newton failure that started from a kept factorisation may be the
      ! old Jacobian's fault, not the step's: the step control retries the same
      ! step once with a fresh one before halving.
      retry_same = allocated(error) .and. kept_jacobian
      if (.not. allocated(error)) call check_physical(self%x_new, np, error)
   end subroutine box_attempt

   !> Drop the attempt: no kept factorisation.
   subroutine box_reject(self, run)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      self%work%usable = .false.
   end subroutine box_reject

   !> The box scheme has no break by tension.
   subroutine box_watch(self, run, h, retry)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      logical, intent(out) :: retry
      retry = .false.
   end subroutine box_watch

   !> Take the attempt: the new level.
   subroutine box_accept(self, run, h)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer :: k
      self%y_prev = self%y
      do k = 1, size(self%s)
         self%y(:, k) = self%x_new(n_eq*(k - 1) + 1:n_eq*k)
      end do
      self%summary%max_unit_norm_error = max(self%summary%max_unit_norm_error, &
                                             maxval(abs(self%y(i_b0, :)**2 + self%y(i_b3, :)**2 - 1)))
      self%h_prev = h
      self%have_prev = .true.
   end subroutine box_accept

   !> The fields of a snapshot: the state at the end of the step just accepted (the plan lands
   !> on every snapshot), or the static state.
   subroutine box_snapshot(self, run, t_new, ts, static, fields, extra, with_extra)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: t_new, ts
      logical, intent(in) :: static
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      logical, intent(out) :: with_extra
      with_extra = .false.
      if (static) then
         call state_fields(self%cable, self%s, self%y_static, fields)
      else
         call state_fields(self%cable, self%s, self%y, fields)
      end if
   end subroutine box_snapshot

   !> History record i at run%t: the box scheme's own record and ledger, and the model's part of
   !> the run's record from them (the ends: a fixed, b released; the ledger's terms).
   subroutine box_record(self, run, i, ends, ends_y, measures, energies, stored, work)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer, intent(in) :: i
      real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
      real(dp), intent(inout) :: energies(4), stored, work(3)
      real(dp) :: e(4), vel_x, vel_z, power_new, f, c2, s2
      integer :: np
      np = size(self%s)
      associate (history => self%history, y => self%y, model => self%cable)
         if (i > ubound(history%time, 1)) call history%reserve(2*ubound(history%time, 1), self%options%energy)
         history%n = i
         history%time(i) = run%t
         history%step(i) = run%history%step(i)
         history%end_velocity(i) = y(i_u, np)
         history%fixed_end_tension(i) = model%law%tension(y(i_eps, 1))
         history%newton_iterations(i) = run%history%newton_iterations(i)
         history%rejected(i) = run%history%rejected(i)
         history%end_y(:, 1, i) = y(:, 1)
         history%end_y(:, 2, i) = y(:, np)
         history%min_strain = min(history%min_strain, minval(y(i_eps, :)))
         history%max_strain = max(history%max_strain, maxval(y(i_eps, :)))
         call positions(y, self%s, self%xpos, self%zpos)
         history%end_position(:, i) = [self%xpos(np), self%zpos(np)]
         if (self%options%energy) then
            ! The ledger: the energies and the work of the end force (trapezoidal in time).
            call positions(y, self%s, self%xpos, self%zpos)
            call energy_terms(model, y, self%s, self%zpos, e)
            call fixed_frame_velocity(y(:, np), vel_x, vel_z)
            power_new = rupture_factor(history%time(i), self%options%t_break)*(self%force_h*vel_x + self%force_v*vel_z)
            if (i > 0) self%work_done = self%work_done + 0.5_dp*history%step(i)*(self%power_old + power_new)
            self%power_old = power_new
            history%energy(1:4, i) = e
            history%energy(5, i) = self%work_done
            history%energy(6, i) = sum(e) - self%work_done
         end if
         ! The run's record: end a (fixed) and end b (released).
         associate (ya => history%end_y(:, 1, i), yb => history%end_y(:, 2, i))
            ! End a: the force the support exerts balances T t + Sn n there.
            f = model%law%tension(ya(i_eps))
            c2 = ya(i_b0)**2 - ya(i_b3)**2
            s2 = 2*ya(i_b0)*ya(i_b3)
            ends(:, 1) = [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, f, -(f*s2 + ya(i_sn)*c2), -(f*c2 - ya(i_sn)*s2)]
            call fixed_frame_velocity(yb, vel_x, vel_z)
            f = model%law%tension(yb(i_eps))
            ends(:, 2) = [history%end_position(:, i), vel_x, vel_z, f, &
                          rupture_factor(history%time(i), self%options%t_break)*[self%force_h, self%force_v]]
         end associate
         ! The run's ledger from it (driver/history.f90): no work of loads, no dissipation.
         if (self%options%energy) then
            energies = history%energy(1:4, i)
            stored = sum(e)
            work(1) = history%energy(5, i)
         end if
      end associate
   end subroutine box_record

   !> No break inside the cable: end b is released by the model's ramp.
   subroutine box_split(self, run, error)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      type(error_type), allocatable, intent(out) :: error
      call fatal_error(error, 'the box scheme breaks the cable at end b only, by its ramp', stat_input)
   end subroutine box_split

   !> End a is fixed and held, end b the released one.
   subroutine box_end_info(self, run, j, kind, held)
      class(box_model), intent(in) :: self
      type(rod_run), intent(in) :: run
      integer, intent(in) :: j
      character(:), allocatable, intent(out) :: kind
      logical, intent(out) :: held
      held = j == 1
      kind = merge('fixed', 'break', j == 1)
   end subroutine box_end_info

   !> Nothing to add: finish made the summary.
   subroutine box_conclude(self, run)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
   end subroutine box_conclude

   !> Save the state between two steps (after begin, or a pause of the step loop) to an archive
   !> (see exchange_box); archive%ok tells whether it was stored.
   subroutine box_save_state(self, run, archive)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable :: error
      call exchange_box(self, run, archive, .true., error)
   end subroutine box_save_state

   !> Load a state saved by save_state into a run prepared from the same case (setup done,
   !> begin not called), ready for the step loop. Errors (stat_input) when the archive fails
   !> or holds a state this run cannot have.
   subroutine box_load_state(self, run, archive, error)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable, intent(out) :: error
      call box_ready(self)
      call exchange_box(self, run, archive, .false., error)
      if (allocated(error)) return
      if (.not. archive%ok) then
         call fatal_error(error, archive%message, stat_input)
         return
      end if
      call system_clock(run%clock%start, run%clock%rate)
      run%clock%last_report = 0
      run%clock%last_checkpoint = 0
      run%clock%records_at_checkpoint = run%history%n
   end subroutine box_load_state

   !> The state of a box-scheme run, listed once for saving (saving = .true.) and loading.
   !> Besides what the rods keep of the step loop and the records (rod_run's exchange_progress
   !> and exchange_records: the step control, the next snapshot, the wall time, every record of
   !> the run's history and the summary's counters), it is:
   !>  - time and step size asked for (run/t, run/dt);
   !>  - the unknowns at the current level and the level before (box/y, box/y_prev: the first
   !>    guess extrapolates from both), the step between them and whether there was one;
   !>  - the ledger's accumulators (the work of the end force and its last power);
   !>  - Newton's kept factorisation when one is kept (reuse_jacobian): LU factors, pivots and
   !>    the contraction of the last solve;
   !>  - the box scheme's own history (every record: time, step, end velocity, fixed-end
   !>    tension, iterations, rejections, both ends' unknowns and end b's position, the energies)
   !>    and strain extremes, from which finish makes its figures, and its summary's counters
   !>    (factorisations, the largest drift of the Euler parameters).
   !> Not saved, because every attempt recomputes them (prepare_step and the residual): the
   !> system's old level and work arrays, Newton's residual and update, the new level being
   !> tried; because begin and load_state compute them from the case (box_ready): the static
   !> state and its end force, the system's constants, the Newton settings of a step.
   subroutine exchange_box(self, run, a, saving, error)
      type(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: a
      logical, intent(in) :: saving
      type(error_type), allocatable, intent(out) :: error
      integer :: np, n, flags(4)
      real(dp) :: reals(5), strains(2)
      call sync_real(a, 'run/t', run%t, saving)
      call sync_real(a, 'run/dt', run%dt, saving)
      call exchange_progress(run, a, saving)
      np = size(self%s)
      call sync_int(a, 'box/nodes', np, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (np /= size(self%s)) then
            call fatal_error(error, 'the checkpoint holds '//str(np)//' nodes, this case '//str(size(self%s)), &
                             stat_input)
            return
         end if
      end if
      call sync_matrix(a, 'box/y', self%y, saving)
      call sync_matrix(a, 'box/y_prev', self%y_prev, saving)
      reals = [self%h_prev, self%work_done, self%power_old, self%work%contraction, self%summary%max_unit_norm_error]
      call sync_reals(a, 'box/reals', reals, saving)
      flags = [merge(1, 0, self%have_prev), merge(1, 0, self%work%usable .and. self%newton%reuse_jacobian), &
               merge(1, 0, self%work%jacobian%factorised), self%summary%factorisations]
      call sync_ints(a, 'box/flags', flags, saving)
      if (.not. saving) then
         self%h_prev = reals(1)
         self%work_done = reals(2)
         self%power_old = reals(3)
         self%work%contraction = reals(4)
         self%summary%max_unit_norm_error = reals(5)
         self%have_prev = flags(1) == 1
         self%work%usable = flags(2) == 1
         self%work%jacobian%factorised = flags(3) == 1
         self%summary%factorisations = flags(4)
      end if
      if (flags(2) == 1) then
         call sync_matrix(a, 'box/jacobian', self%work%jacobian%ab, saving)
         call sync_ints(a, 'box/pivots', self%work%jacobian%ipiv, saving)
      end if
      ! The box scheme's own history.
      n = self%history%n
      call sync_int(a, 'box/history/n', n, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (n < 0 .or. a%stored_size('box/history/time') /= n + 1) then
            call fatal_error(error, 'the checkpoint''s box history has '//str(n)//' records but '// &
                             str(a%stored_size('box/history/time'))//' times', stat_input)
            return
         end if
         call self%history%reserve(n + 16, self%options%energy)
         self%history%n = n
      end if
      associate (h => self%history)
         call sync_reals(a, 'box/history/time', h%time(0:n), saving)
         call sync_reals(a, 'box/history/step', h%step(0:n), saving)
         call sync_reals(a, 'box/history/end_velocity', h%end_velocity(0:n), saving)
         call sync_reals(a, 'box/history/fixed_end_tension', h%fixed_end_tension(0:n), saving)
         call sync_ints(a, 'box/history/newton_iterations', h%newton_iterations(0:n), saving)
         call sync_ints(a, 'box/history/rejected', h%rejected(0:n), saving)
         call sync_cube(a, 'box/history/end_y', h%end_y(:, :, 0:n), saving)
         call sync_matrix(a, 'box/history/end_position', h%end_position(:, 0:n), saving)
         if (self%options%energy) call sync_matrix(a, 'box/history/energy', h%energy(:, 0:n), saving)
         strains = [h%min_strain, h%max_strain]
         call sync_reals(a, 'box/history/strains', strains, saving)
         if (.not. saving) then
            h%min_strain = strains(1)
            h%max_strain = strains(2)
         end if
      end associate
      call exchange_records(run, a, saving, error)
   end subroutine exchange_box

   !> The box scheme's figures (summarise) and the run's summary from them, with its warnings
   !> (made: the driver's summary is not made).
   subroutine box_finish(self, run, made)
      class(box_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      logical, intent(out) :: made
      type(run_summary) :: fresh
      real(dp) :: ds, c0
      integer :: n, np
      made = .true.
      self%summary%rejected_steps = run%summary%rejected_steps
      self%summary%wall_time = run%wall_time()
      self%summary%time_reached = run%t
      call summarise(self%history, self%options%energy, self%summary)
      n = self%history%n
      np = size(self%s)
      run%summary = fresh
      associate (s => run%summary, old_summary => self%summary, old => self%history)
         s%peak_end_speed = old_summary%peak_end_speed
         s%peak_end_speed_time = old_summary%peak_end_speed_time
         s%min_fixed_end_tension = old_summary%min_fixed_end_tension
         s%min_fixed_end_tension_time = old_summary%min_fixed_end_tension_time
         s%front_arrival_time = old_summary%front_arrival_time
         s%energy_drift = old_summary%energy_drift
         s%steps = old_summary%steps
         s%rejected_steps = old_summary%rejected_steps
         s%newton_iterations = old_summary%newton_iterations
         s%max_newton_iterations = old_summary%max_newton_iterations
         s%factorisations = old_summary%factorisations
         s%time_reached = old_summary%time_reached
         s%wall_time = old_summary%wall_time
         s%max_unit_norm_error = old_summary%max_unit_norm_error
         s%min_strain = old%min_strain
         s%max_strain = old%max_strain
         ds = self%s(2) - self%s(1)
         c0 = sqrt(self%cable%law%stiffness(self%y_static(i_eps, np))/self%cable%mass)
         s%dt_requested = self%courant*ds/c0
         s%dt_used = maxval(old%step(1:max(n, 1)))
         s%courant_requested = self%courant
         s%courant_used = s%dt_used*c0/ds
         allocate (s%ends(2))
         s%ends(1)%min_tension = old_summary%min_fixed_end_tension
         s%ends(1)%min_tension_time = old_summary%min_fixed_end_tension_time
         s%ends(1)%max_tension = maxval(run%history%ends(5, 1, 0:n))
         s%ends(1)%front_arrival_time = old_summary%front_arrival_time
         s%ends(2)%peak_speed = old_summary%peak_end_speed
         s%ends(2)%peak_speed_time = old_summary%peak_end_speed_time
         s%ends(2)%min_tension = minval(run%history%ends(5, 2, 0:n))
         s%ends(2)%max_tension = maxval(run%history%ends(5, 2, 0:n))
         s%warnings = ''
         if (s%energy_drift > 0.01_dp) call warn('the energy ledger drifted by '//str(100*s%energy_drift)// &
                                                 ' % of the initial strain energy (more than 1 %)')
         if (s%max_unit_norm_error > 0.05_dp) call warn('the Euler parameters left the unit circle by '// &
            str(s%max_unit_norm_error)//' (more than 0.05): the buckled zone is not resolved')
         if (s%rejected_steps > max(10, n/100)) call warn(str(s%rejected_steps)//' step attempts were rejected')
         if (abs(s%courant_used/s%courant_requested - 1) > 0.01_dp .and. self%options%dt > 0) &
            call warn('the Courant number taken, '//str(s%courant_used)//', differs from the one asked for, '// &
                      str(s%courant_requested)//' (the box scheme fits whole steps into the snapshot interval)')
      end associate

   contains

      subroutine warn(line)
         character(*), intent(in) :: line
         if (len(run%summary%warnings) > 0) run%summary%warnings = run%summary%warnings//new_line('a')
         run%summary%warnings = run%summary%warnings//line
      end subroutine warn
   end subroutine box_finish

   !> The box scheme's summary figures from its history.
   subroutine summarise(history, energy, summary)
      type(box_history), intent(in) :: history
      logical, intent(in) :: energy
      type(box_summary), intent(inout) :: summary
      integer :: i
      summary%steps = history%n
      summary%newton_iterations = sum(history%newton_iterations(1:history%n))
      summary%max_newton_iterations = maxval(history%newton_iterations(0:history%n))
      i = maxloc(abs(history%end_velocity(0:history%n)), 1) - 1
      summary%peak_end_speed = abs(history%end_velocity(i))
      summary%peak_end_speed_time = history%time(i)
      i = minloc(history%fixed_end_tension(0:history%n), 1) - 1
      summary%min_fixed_end_tension = history%fixed_end_tension(i)
      summary%min_fixed_end_tension_time = history%time(i)
      do i = 1, history%n
         if (history%fixed_end_tension(i) <= 0.99_dp*history%fixed_end_tension(0)) then
            summary%front_arrival_time = history%time(i - 1) + (history%time(i) - history%time(i - 1))* &
                                         (0.99_dp*history%fixed_end_tension(0) - history%fixed_end_tension(i - 1))/ &
                                         (history%fixed_end_tension(i) - history%fixed_end_tension(i - 1))
            exit
         end if
      end do
      if (energy) then
         summary%energy_drift = maxval(abs(history%energy(6, 0:history%n) - history%energy(6, 0))) &
                                /history%energy(1, 0)
      end if
   end subroutine summarise

   !> Reject states outside the model's range.
   subroutine check_physical(x, n, err)
      integer, intent(in) :: n
      real(dp), intent(in) :: x(n_eq, n)
      type(error_type), allocatable, intent(out) :: err
      integer :: k
      do k = 1, n
         if (.not. all(ieee_is_finite(x(:, k)))) then
            call fatal_error(err, 'non-finite state at node '//str(k), stat_numerics)
            return
         end if
         if (x(i_eps, k) <= -0.9_dp) then
            call fatal_error(err, 'strain '//str(x(i_eps, k))//' at node '//str(k)// &
                             ' is below -0.9 (the cable has collapsed)', stat_numerics)
            return
         end if
         ! The box scheme keeps b0^2 + b3^2 = 1 only to O((Omega3 ds)^2): a
         ! drift of a few per cent flags a kink at the grid scale (reported
         ! as max_unit_norm_error); half the unit circle means the frame is lost.
         if (abs(x(i_b0, k)**2 + x(i_b3, k)**2 - 1) > 0.5_dp) then
            call fatal_error(err, 'Euler parameters off the unit circle at node '//str(k)// &
                             ' (b0^2 + b3^2 = '//str(x(i_b0, k)**2 + x(i_b3, k)**2)//')', stat_numerics)
            return
         end if
      end do
   end subroutine check_physical

   !> The eight output fields of a box-scheme state.
   subroutine state_fields(model, s, y, fields)
      !> Cable data.
      type(box_cable), intent(in) :: model
      !> Node arc lengths (m) and the state (n_eq, nodes).
      real(dp), intent(in) :: s(:), y(:, :)
      !> Fields (nodes, n_fields).
      real(dp), intent(out) :: fields(:, :)
      real(dp) :: x(size(s)), z(size(s))
      call positions(y, s, x, z)
      fields(:, 1) = model%law%tension(y(i_eps, :))
      fields(:, 2) = y(i_sn, :)
      fields(:, 3) = y(i_eps, :)
      fields(:, 4) = y(i_u, :)
      fields(:, 5) = y(i_v, :)
      fields(:, 6) = x
      fields(:, 7) = z
      fields(:, 8) = y(i_om, :)
   end subroutine state_fields
end module xcable_box_model
