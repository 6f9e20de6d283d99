!> Time stepping of the rupture (box scheme in time, eqs. 22-25): at each step
!> Newton's method on all boxes with the analytic Jacobian and the banded solve.
!>
!> The breaking end carries the static end force scaled by
!> cos^2(pi t / (2 t_break)) until t_break and zero after (eqs. 31-32). Steps
!> are uniform within each output interval; a step whose Newton iteration fails
!> or that leaves the physical range is retried with half the step, down to a
!> floor, and the step grows back to the requested one after four good steps.
!> A Newton failure of an attempt that started from a Jacobian kept from
!> earlier steps is first retried at the same step with a fresh Jacobian.
!>
!> Bounds that keep every run finite (issue 6): Newton stops after
!> max_iterations, or when its update grows three times in a row, or on a
!> non-finite residual or update; one step is halved at most
!> log2(1 / min_step_fraction) times before the run stops; the rejected
!> attempts of the whole run are limited to 1000 + the number of requested
!> steps (beyond that the step stays far below dt and the run stops with a
!> named reason: ask for a smaller dt); a step that no longer advances the
!> time stops the run; the wall clock (max_wall_time) is checked before every
!> attempt, rejected ones included. history%rejected(i) counts the attempts
!> rejected before accepted step i; summary%rejected_steps counts them all
!> (with those of a final failing step).
module xcable_box_dynamics
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_numerics
   use xcable_core_strings, only: str
   use xcable_box_equations, only: cable_model, n_eq, i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om
   use xcable_box_geometry, only: positions, fixed_frame_velocity
   use xcable_box_discrete, only: box_system
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   use xcable_theory_closed_forms, only: wave_speed
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: dynamics_options, run_history, run_summary, run_observer, run_rupture, rupture_factor
   public :: energy_terms, n_energy, energy_names

   !> Energy ledger columns: strain, kinetic, bending, gravity, work of the end force, ledger.
   integer, parameter :: n_energy = 6
   character(len=*), parameter :: energy_names(n_energy) = &
      [character(len=8) :: 'strain', 'kinetic', 'bending', 'gravity', 'work', 'ledger']

   !> Controls of a rupture run.
   type :: dynamics_options
      !> Breaking time t_br, s (0: instantaneous).
      real(dp) :: t_break = 0.05_dp
      !> End of the run, s.
      real(dp) :: t_end = 0.16_dp
      !> Requested time step, s.
      real(dp) :: dt = 1.0e-4_dp
      !> Time weight of the new level: 1/2 is the paper's scheme; > 1/2 damps high frequencies.
      real(dp) :: theta = 0.5_dp
      !> Snapshot interval, s (0: only t = 0 and t_end).
      real(dp) :: interval = 0.01_dp
      !> Newton controls.
      type(newton_options) :: newton
      !> First guess by linear extrapolation from the two previous levels.
      logical :: extrapolate = .true.
      !> Keep the energy ledger in the history.
      logical :: energy = .false.
      !> Smallest step allowed by the step control, as a fraction of dt.
      real(dp) :: min_step_fraction = 1.0_dp/1024
      !> Wall-clock limit, s (0: none).
      real(dp) :: max_wall_time = 0
      !> Print progress on stderr.
      logical :: progress = .false.
   end type dynamics_options

   !> One record per accepted time step (index 0: the static state at t = 0).
   type :: run_history
      !> Number of accepted steps.
      integer :: n = 0
      !> Time, s.
      real(dp), allocatable :: time(:)
      !> Step taken, s.
      real(dp), allocatable :: step(:)
      !> u at the breaking end, m/s.
      real(dp), allocatable :: end_velocity(:)
      !> Tension at the fixed end, N.
      real(dp), allocatable :: fixed_end_tension(:)
      !> Newton iterations of the accepted step.
      integer, allocatable :: newton_iterations(:)
      !> Rejected attempts before the accepted step.
      integer, allocatable :: rejected(:)
      !> Energy ledger (n_energy, 0:n), J, when asked for.
      real(dp), allocatable :: energy(:, :)
      !> Unknowns at the fixed end and at the breaking end (n_eq, 2, 0:n).
      real(dp), allocatable :: end_y(:, :, :)
      !> Position (x, z) of the breaking end (2, 0:n), m.
      real(dp), allocatable :: end_position(:, :)
      !> Smallest and largest strain at any node over the records.
      real(dp) :: min_strain = huge(1.0_dp), max_strain = -huge(1.0_dp)
   contains
      procedure :: reserve => history_reserve
   end type run_history

   !> Figures of a run.
   type :: run_summary
      !> Largest |u| at the breaking end, m/s, and when.
      real(dp) :: peak_end_speed = 0, peak_end_speed_time = 0
      !> Smallest tension at the fixed end, N, and when.
      real(dp) :: min_fixed_end_tension = 0, min_fixed_end_tension_time = 0
      !> First time the fixed-end tension is 1 % below its static value, s (-1: never).
      real(dp) :: front_arrival_time = -1
      !> max |ledger - ledger(0)| / strain energy(0) (-1: ledger not kept).
      real(dp) :: energy_drift = -1
      !> Accepted and rejected steps.
      integer :: steps = 0, rejected_steps = 0
      !> Newton iterations: total and largest in one step; Jacobian factorisations.
      integer :: newton_iterations = 0, max_newton_iterations = 0, factorisations = 0
      !> Simulated time reached, s.
      real(dp) :: time_reached = 0
      !> Wall time of the dynamics, s.
      real(dp) :: wall_time = 0
      !> Largest |b0^2 + b3^2 - 1| over nodes and steps: the kinematic error of
      !> the discrete Euler parameters, large only where the curvature is
      !> unresolved (a buckle at the grid scale).
      real(dp) :: max_unit_norm_error = 0
   end type run_summary

   !> Receives the snapshots of a run (the output writer).
   type, abstract :: run_observer
   contains
      procedure(snapshot_interface), deferred :: snapshot
   end type run_observer

   abstract interface
      subroutine snapshot_interface(self, t, y, error)
         import :: run_observer, dp, error_type
         !> Observer.
         class(run_observer), intent(inout) :: self
         !> Time, s.
         real(dp), intent(in) :: t
         !> Unknowns (7, nodes).
         real(dp), intent(in) :: y(:, :)
         !> Error when writing fails.
         type(error_type), allocatable, intent(out) :: error
      end subroutine snapshot_interface
   end interface

contains

   !> Fraction of the static end force applied at time t (eqs. 31-32).
   elemental function rupture_factor(t, t_break) result(r)
      !> Time, s.
      real(dp), intent(in) :: t
      !> Breaking time, s.
      real(dp), intent(in) :: t_break
      real(dp) :: r
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (t <= 0) then
         r = 1
      else if (t >= t_break) then
         r = 0
      else
         r = cos(0.5_dp*pi*t/t_break)**2
      end if
   end function rupture_factor

   !> Make room for at least n records (keeps the content).
   subroutine history_reserve(self, n, energy)
      !> History.
      class(run_history), intent(inout) :: self
      !> Records needed (steps).
      integer, intent(in) :: n
      !> Whether the energy ledger is kept.
      logical, intent(in) :: energy
      real(dp), allocatable :: r(:), e(:, :), ey(:, :, :)
      integer, allocatable :: i(:)
      integer :: m
      if (allocated(self%time)) then
         if (ubound(self%time, 1) >= n) return
      end if
      m = self%n
      if (.not. allocated(self%time)) then
         allocate (self%time(0:n), self%step(0:n), self%end_velocity(0:n), self%fixed_end_tension(0:n))
         allocate (self%newton_iterations(0:n), self%rejected(0:n))
         allocate (self%end_y(n_eq, 2, 0:n), self%end_position(2, 0:n))
         if (energy) allocate (self%energy(n_energy, 0:n))
         return
      end if
      allocate (ey(n_eq, 2, 0:n)); ey(:, :, 0:m) = self%end_y(:, :, 0:m); call move_alloc(ey, self%end_y)
      allocate (e(2, 0:n)); e(:, 0:m) = self%end_position(:, 0:m); call move_alloc(e, self%end_position)
      allocate (r(0:n)); r(0:m) = self%time(0:m); call move_alloc(r, self%time)
      allocate (r(0:n)); r(0:m) = self%step(0:m); call move_alloc(r, self%step)
      allocate (r(0:n)); r(0:m) = self%end_velocity(0:m); call move_alloc(r, self%end_velocity)
      allocate (r(0:n)); r(0:m) = self%fixed_end_tension(0:m); call move_alloc(r, self%fixed_end_tension)
      allocate (i(0:n)); i(0:m) = self%newton_iterations(0:m); call move_alloc(i, self%newton_iterations)
      allocate (i(0:n)); i(0:m) = self%rejected(0:m); call move_alloc(i, self%rejected)
      if (energy) then
         allocate (e(n_energy, 0:n)); e(:, 0:m) = self%energy(:, 0:m); call move_alloc(e, self%energy)
      end if
   end subroutine history_reserve

   !> Strain, kinetic, bending and gravity energy of a state (trapezoid rule in s), J.
   subroutine energy_terms(model, y, s, z, e)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns (7, nodes).
      real(dp), intent(in) :: y(:, :)
      !> Node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Vertical positions, m.
      real(dp), intent(in) :: z(:)
      !> Energies (4).
      real(dp), intent(out) :: e(4)
      real(dp) :: density(4), density_prev(4)
      integer :: k
      ! Node by node (no work array: the ledger is kept at every step).
      e = 0
      do k = 1, size(s)
         density(1) = model%law%strain_energy(y(i_eps, k))
         density(2) = 0.5_dp*model%mass*(y(i_u, k)**2 + y(i_v, k)**2)
         density(3) = 0.5_dp*model%bending_stiffness*y(i_om, k)**2
         density(4) = model%weight*z(k)
         if (k > 1) e = e + 0.5_dp*(s(k) - s(k - 1))*(density + density_prev)
         density_prev = density
      end do
   end subroutine energy_terms

   !> Integrate the rupture from the static state to t_end.
   subroutine run_rupture(model, s, y_static, options, history, summary, error, observer)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Static state (7, nodes).
      real(dp), intent(in) :: y_static(:, :)
      !> Controls.
      type(dynamics_options), intent(in) :: options
      !> One record per accepted step.
      type(run_history), intent(out) :: history
      !> Figures of the run (filled also when it fails).
      type(run_summary), intent(out) :: summary
      !> Error when the run cannot go on (the history and summary hold what was done).
      type(error_type), allocatable, intent(out) :: error
      !> Receives the snapshots.
      class(run_observer), intent(inout), optional :: observer

      type(box_system) :: system
      type(newton_workspace) :: work
      type(newton_report) :: report
      type(newton_options) :: newton
      type(error_type), allocatable :: step_error
      real(dp), allocatable :: y(:, :), y_prev(:, :), x_new(:), xpos(:), zpos(:)
      real(dp) :: t, h, h_step, h_prev, t_event, t_next_snapshot, end_tension, force_h, force_v, r
      real(dp) :: power_old, power_new, work_done, e(4), vel_x, vel_z, c_ref, wall, last_report
      integer :: np, kl, ku, n_good, rejected_here, capacity, snapshot_index, k
      integer(i8) :: clock_start, clock_now, clock_rate, nsteps
      real(dp) :: max_rejections
      logical :: have_prev, kept_jacobian, newton_failed
      character(:), allocatable :: reason

      call system_clock(clock_start, clock_rate)
      np = size(s)
      allocate (y(n_eq, np), y_prev(n_eq, np), x_new(n_eq*np), xpos(np), zpos(np))
      y = y_static
      y_prev = y_static
      ! Newton settings of a time step (docs/measurements/benchmark.md, "Speed work"): stop on
      ! the contraction estimate, keep the Jacobian while it contracts by 0.5
      ! per iteration within a step, refresh it at the start of a step once it
      ! contracted by more than 0.05, and skip the report's final residual.
      newton = options%newton
      newton%final_residual = .false.
      newton%estimate_error = .true.
      newton%max_contraction = 0.5_dp
      newton%refresh_contraction = 0.05_dp
      end_tension = model%law%tension(y_static(i_eps, np))
      ! Static end force: the internal force vector T t + Sn n at the breaking end.
      associate (b0 => y_static(i_b0, np), b3 => y_static(i_b3, np), sn => y_static(i_sn, np))
         force_v = end_tension*(b0**2 - b3**2) - sn*2*b0*b3
         force_h = end_tension*2*b0*b3 + sn*(b0**2 - b3**2)
      end associate
      c_ref = wave_speed(model%law, model%mass, y_static(i_eps, np))
      call system%init(model, s, .true., end_tension, c_ref, options%theta)
      system%omega_fixed = y_static(i_om, 1)
      system%omega_free = y_static(i_om, np)
      call system%band_widths(kl, ku)
      call work%init(n_eq*np, kl, ku, system%unknown_scale())

      ! Room for the requested steps and snapshots (in real arithmetic: a step
      ! that is tiny against t_end overflowed the integer count); the history
      ! grows when the step control needs more.
      capacity = int(min(options%t_end/options%dt + options%t_end/max(options%interval, options%dt), 1.0e6_dp)) + 16
      max_rejections = 1000 + options%t_end/options%dt
      call history%reserve(capacity, options%energy)
      call record(0, 0.0_dp, 0.0_dp, 0, 0)
      if (options%energy) then
         work_done = 0
         power_old = 0
         call store_energy(0)
      end if

      t = 0
      h = options%dt
      h_prev = options%dt
      have_prev = .false.
      n_good = 0
      rejected_here = 0
      snapshot_index = 0
      t_next_snapshot = next_snapshot_time(0)
      last_report = 0
      if (present(observer)) then
         call observer%snapshot(0.0_dp, y, error)
         if (allocated(error)) return
      end if

      do while (t < options%t_end*(1 - 1.0e-12_dp))
         call system_clock(clock_now)
         wall = real(clock_now - clock_start, dp)/clock_rate
         if (options%max_wall_time > 0 .and. wall > options%max_wall_time) then
            call fatal_error(error, 'wall-clock limit of '//str(options%max_wall_time)//' s reached at t = '// &
                             str(t)//' s', stat_numerics)
            exit
         end if
         t_event = min(t_next_snapshot, options%t_end)
         nsteps = max(1_i8, ceiling(min((t_event - t)/h - 1.0e-6_dp, 1.0e18_dp), i8))
         h_step = (t_event - t)/nsteps
         if (nsteps == 1) h_step = t_event - t
         if (.not. (t + h_step > t)) then
            call fatal_error(error, 'step control: the step '//str(h_step)//' s no longer advances the time at t = '// &
                             str(t)//' s', stat_numerics)
            exit
         end if
         r = rupture_factor(t + h_step, options%t_break)
         call system%prepare_step(y, h_step, r*force_h, r*force_v)
         ! First guess (node by node: no array temporaries in the time loop).
         do k = 1, np
            if (have_prev .and. options%extrapolate) then
               x_new(n_eq*(k - 1) + 1:n_eq*k) = y(:, k) + (h_step/h_prev)*(y(:, k) - y_prev(:, k))
            else
               x_new(n_eq*(k - 1) + 1:n_eq*k) = y(:, k)
            end if
         end do
         ! Whether Newton starts from a factorisation kept from earlier steps
         ! (the test of newton_solve for a fresh one).
         kept_jacobian = newton%reuse_jacobian .and. work%usable .and. work%contraction <= newton%refresh_contraction
         call newton_solve(system, x_new, work, newton, report, step_error)
         summary%factorisations = summary%factorisations + report%factorisations
         newton_failed = allocated(step_error)
         if (.not. allocated(step_error)) call check_physical(x_new, np, step_error)
         if (allocated(step_error)) then
            summary%rejected_steps = summary%rejected_steps + 1
            rejected_here = rejected_here + 1
            work%usable = .false.
            reason = step_error%message
            if (summary%rejected_steps > max_rejections) then
               call fatal_error(error, 'step control: '//str(summary%rejected_steps)//' rejected attempts by t = '// &
                                str(t)//' s (the limit is 1000 + the '//str(nint(min(max_rejections - 1000, 2.0e9_dp)))// &
                                ' requested steps): the step stays far below dt = '//str(options%dt)// &
                                ' s; last: '//reason, stat_numerics)
               exit
            end if
            ! A Newton failure that started from a kept factorisation may be the
            ! old Jacobian's fault, not the step's: retry the same step once with
            ! a fresh one before halving (without this, a Newton iteration bound
            ! of a few iterations ratcheted the step down to the floor).
            if (newton_failed .and. kept_jacobian) cycle
            ! Reject: retry with half the step.
            h = 0.5_dp*h
            n_good = 0
            if (h < options%dt*options%min_step_fraction) then
               call fatal_error(error, 'step control: step fell below '//str(options%dt*options%min_step_fraction)// &
                                ' s at t = '//str(t)//' s after '//str(rejected_here)//' rejected attempts; last: ' &
                                //reason, stat_numerics)
               exit
            end if
            cycle
         end if
         ! Accept.
         y_prev = y
         do k = 1, np
            y(:, k) = x_new(n_eq*(k - 1) + 1:n_eq*k)
         end do
         summary%max_unit_norm_error = max(summary%max_unit_norm_error, &
                                           maxval(abs(y(i_b0, :)**2 + y(i_b3, :)**2 - 1)))
         h_prev = h_step
         have_prev = .true.
         if (nsteps == 1) then
            t = t_event
         else
            t = t + h_step
         end if
         if (h < options%dt) then
            n_good = n_good + 1
            if (n_good >= 4) then
               h = min(2*h, options%dt)
               n_good = 0
               ! The kept factorisation holds the mass terms of the old step.
               work%usable = .false.
            end if
         end if
         if (history%n + 1 > ubound(history%time, 1)) call history%reserve(2*ubound(history%time, 1), options%energy)
         call record(history%n + 1, t, h_step, report%iterations, rejected_here)
         rejected_here = 0
         if (options%energy) call store_energy(history%n)
         if (t >= t_next_snapshot*(1 - 1.0e-12_dp) .and. t_next_snapshot <= options%t_end*(1 + 1.0e-12_dp)) then
            snapshot_index = snapshot_index + 1
            t_next_snapshot = next_snapshot_time(snapshot_index)
            if (present(observer)) then
               call observer%snapshot(t, y, step_error)
               if (allocated(step_error)) then
                  call prefix_error(step_error, 'output: ')
                  call move_alloc(step_error, error)
                  exit
               end if
            end if
         end if
         call system_clock(clock_now)
         wall = real(clock_now - clock_start, dp)/clock_rate
         if (options%progress .and. wall - last_report >= 1.0_dp) then
            last_report = wall
            write (error_unit, '(a,f5.1,a,es10.3,a,es10.3,a,f8.1,a,f8.1,a)') 'xcable: ', 100*t/options%t_end, &
               '%  t = ', t, ' s of ', options%t_end, ' s, wall ', wall, ' s, remaining ', &
               wall*(options%t_end - t)/max(t, tiny(t)), ' s'
         end if
      end do

      call system_clock(clock_now)
      summary%wall_time = real(clock_now - clock_start, dp)/clock_rate
      summary%time_reached = t
      call summarise()

   contains

      !> Time of snapshot i (interval 0: only the end).
      pure real(dp) function next_snapshot_time(i)
         integer, intent(in) :: i
         if (options%interval > 0) then
            next_snapshot_time = (i + 1)*options%interval
            if (next_snapshot_time > options%t_end*(1 + 1.0e-9_dp)) next_snapshot_time = huge(1.0_dp)
         else
            next_snapshot_time = merge(options%t_end, huge(1.0_dp), i == 0)
         end if
      end function next_snapshot_time

      !> Store one history record.
      subroutine record(i, time, step, iterations, rejected)
         integer, intent(in) :: i, iterations, rejected
         real(dp), intent(in) :: time, step
         history%n = i
         history%time(i) = time
         history%step(i) = step
         history%end_velocity(i) = y(i_u, np)
         history%fixed_end_tension(i) = model%law%tension(y(i_eps, 1))
         history%newton_iterations(i) = iterations
         history%rejected(i) = rejected
         history%end_y(:, 1, i) = y(:, 1)
         history%end_y(:, 2, i) = y(:, np)
         history%min_strain = min(history%min_strain, minval(y(i_eps, :)))
         history%max_strain = max(history%max_strain, maxval(y(i_eps, :)))
         call positions(y, s, xpos, zpos)
         history%end_position(:, i) = [xpos(np), zpos(np)]
      end subroutine record

      !> Energy ledger at record i.
      subroutine store_energy(i)
         integer, intent(in) :: i
         call positions(y, s, xpos, zpos)
         call energy_terms(model, y, s, zpos, e)
         call fixed_frame_velocity(y(:, np), vel_x, vel_z)
         power_new = rupture_factor(history%time(i), options%t_break)*(force_h*vel_x + force_v*vel_z)
         if (i > 0) work_done = work_done + 0.5_dp*history%step(i)*(power_old + power_new)
         power_old = power_new
         history%energy(1:4, i) = e
         history%energy(5, i) = work_done
         history%energy(6, i) = sum(e) - work_done
      end subroutine store_energy

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

      !> Summary figures from the history.
      subroutine summarise()
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
         if (options%energy) then
            summary%energy_drift = maxval(abs(history%energy(6, 0:history%n) - history%energy(6, 0))) &
                                   /history%energy(1, 0)
         end if
      end subroutine summarise
   end subroutine run_rupture
end module xcable_box_dynamics
