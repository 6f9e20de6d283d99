!> The one step loop of every rod run, planar or 3-D: the start of the
!> dynamics, the time steps with their step control, the break, the
!> checkpoint pauses and the end.
!>
!> The loop asks a model of the cable (an extension of cable_model,
!> declared in driver/rod_run.f90 with the run it reads and writes) for what
!> depends on the discretisation: an attempt at a step on all its pieces with
!> the checks of the new state, the rejection or the acceptance of it, the
!> fields of a snapshot inside the step, its part of a history record (ends,
!> measures, ledger terms), the break. It owns the rest: when snapshots are due and
!> their output, the history's records (driver/history.f90), the summary
!> (driver/summary.f90),
!> the step to try and its landing on t_end and on the start of the break
!> (plan_step), the halving and doubling back (reject_attempt, advance_time),
!> the search for a break by tension (the model gives the two levels'
!> positions to watch_step), the wall-clock limit, the pauses for checkpoints
!> and SIGTERM, and the progress reports. The step control's policy is in the
!> header of driver/rod_run.f90, whose run (rod_run) holds the history and the
!> summary the driver keeps.
!>
!> The planar rod's pieces are the model planar_model (driver/rod_run.f90 and
!> its submodules); the 3-D rod's are rod3d_drive (driver/rod3d_drive.f90);
!> the paper's box scheme is box_model (box/model.f90), which brings its own
!> step plan, rejection words, snapshot times and summary through the
!> bindings plan, advance, reject_step, snapshot_at and finish (their
!> defaults are plan_step, advance_time, reject_attempt, the due time and the
!> run's summary). A new discretisation is one more extension of
!> cable_model; the loop does not change.
module xcable_driver_stepping
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, prefix_error
   use xcable_driver_rod_run, only: rod_run, cable_model, run_progress, pause_none, pause_checkpoint, &
                                    pause_termination, max_steps, wall_limit, ends_change, snapshot_time
   use xcable_driver_records, only: run_observer, n_fields, n_fields3, field3_names
   use xcable_driver_summary, only: summarise_run
   use xcable_driver_history, only: append_record
   use xcable_system_posix, only: termination_requested
   implicit none
   private
   public :: run_dynamics, start_dynamics, advance_dynamics, finish_dynamics

contains

   !> Integrate to t_end, sending snapshots to the observer: start, advance
   !> until done, finish. On error the history and summary hold what was
   !> done. A run that is to write checkpoints goes through the three parts
   !> itself (driver/simulation.f90).
   subroutine run_dynamics(run, model, observer, error)
      !> Run (prepared).
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(inout) :: model
      !> Receives the static state and snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the run cannot go on.
      type(error_type), allocatable, intent(out) :: error
      integer :: pause
      call start_dynamics(run, model, observer, error)
      if (.not. allocated(error)) then
         do
            call advance_dynamics(run, model, observer, error, pause)
            if (allocated(error) .or. pause == pause_none) exit
         end do
      end if
      call finish_dynamics(run, model)
   end subroutine run_dynamics

   !> The start of the dynamics: the record of t = 0, the static state and
   !> its snapshot to the observer, a break at t = 0, and the skip to a later
   !> break when nothing moves before it.
   subroutine start_dynamics(run, model, observer, error)
      !> Run (prepared).
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(inout) :: model
      !> Receives the static state and the snapshots before the break.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the output fails or a piece cannot be set up.
      type(error_type), allocatable, intent(out) :: error
      integer :: capacity
      call system_clock(run%clock%start, run%clock%rate)
      run%clock%last_report = 0
      run%t = 0
      run%work = 0
      run%load_work = 0
      run%dissipation = 0
      run%progress = run_progress(h=run%dt)
      call model%begin(run, observer, error)
      if (allocated(error)) return
      run%history%n = -1
      call append_record(run, model, 0, 0, 0.0_dp)
      capacity = int(min(run%options%t_end/run%dt, real(max_steps, dp))) + 16
      call run%history%reserve(capacity, size(run%history%end_labels), run%options%energy)
      ! A break at t = 0 happens before the first step.
      if (run%scene%breaks .and. run%scene%break_time <= 0) then
         call model%split(run, error)
         if (allocated(error)) return
      end if
      ! Nothing moves before a break if no end moves or changes its load: skip to it.
      if (run%scene%breaks .and. .not. run%broken .and. .not. ends_change(run)) then
         call emit_snapshots(run, model, observer, run%scene%break_time, .true., error)
         if (allocated(error)) return
         run%t = run%scene%break_time
         call append_record(run, model, 0, 0, run%t - run%history%time(run%history%n))
         call model%split(run, error)
         if (allocated(error)) return
      end if
      run%clock%records_at_checkpoint = run%history%n
   end subroutine start_dynamics

   !> Time steps until t_end, an error, or a pause: the SIGTERM flag is set
   !> (with options%stop_on_termination) or a checkpoint is due (every
   !> options%checkpoint_interval seconds of wall time, or every
   !> options%checkpoint_steps accepted steps), checked before every step
   !> attempt, where the state is complete (a checkpoint needs at least one
   !> step since the last). After a pause the state can be saved and
   !> advance_dynamics called again.
   subroutine advance_dynamics(run, model, observer, error, pause)
      !> Run (started, or loaded from a checkpoint).
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(inout) :: model
      !> Receives the snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the run cannot go on.
      type(error_type), allocatable, intent(out) :: error
      !> Why it returned: pause_none (t_end or an error), pause_checkpoint or pause_termination.
      integer, intent(out) :: pause
      type(error_type), allocatable :: step_error
      integer(i8) :: clock_now
      real(dp) :: h_try, wall, t_stop
      integer :: iterations
      logical :: retry_same, landing, retry

      pause = pause_none
      do while (run%t < run%options%t_end*(1 - 1.0e-12_dp))
         call system_clock(clock_now)
         wall = real(clock_now - run%clock%start, dp)/run%clock%rate
         call wall_limit(run, wall, error)
         if (allocated(error)) exit
         ! A pause, where the state is that of an accepted step (or of the start).
         pause = checkpoint_pause(run, wall)
         if (pause /= pause_none) return
         call model%plan(run, h_try, t_stop, landing, error)
         if (allocated(error)) exit
         call model%attempt(run, h_try, iterations, retry_same, step_error)
         if (allocated(step_error)) then
            call model%reject(run)
            call model%reject_step(run, step_error%message, retry_same, error)
            deallocate (step_error)
            if (allocated(error)) exit
            cycle
         end if
         ! The search for a break by tension: a step past the crossing is taken again, shorter.
         if (run%watch%mbl > 0) then
            call model%watch(run, h_try, retry)
            if (retry) cycle
         end if
         ! Accept: snapshots inside the step, then the new level.
         call model%accept(run, h_try)
         call emit_snapshots(run, model, observer, run%t + h_try, .false., error)
         if (allocated(error)) exit
         call model%advance(run, h_try, t_stop, landing)
         call append_record(run, model, iterations, run%progress%rejected_here, h_try)
         run%progress%rejected_here = 0
         if (run%watch%found) exit
         if (run%scene%breaks .and. .not. run%broken .and. run%t >= run%scene%break_time*(1 - 1.0e-12_dp)) then
            call model%split(run, error)
            if (allocated(error)) exit
         end if
         call system_clock(clock_now)
         wall = real(clock_now - run%clock%start, dp)/run%clock%rate
         if (present(observer) .and. wall - run%clock%last_report >= 1.0_dp) then
            run%clock%last_report = wall
            call observer%progress(run%t, run%options%t_end, wall)
         end if
      end do
   end subroutine advance_dynamics

   !> The end of the dynamics (also of one stopped by an error or a
   !> termination): wall time, time reached, summary figures and warnings
   !> (driver/summary.f90, unless the model makes a summary of its own in
   !> finish), and what the model adds to them (conclude).
   subroutine finish_dynamics(run, model)
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(inout) :: model
      logical :: made
      if (.not. allocated(run%history%end_labels)) return
      call model%finish(run, made)
      if (.not. made) call summarise_run(run, model)
      call model%conclude(run)
   end subroutine finish_dynamics

   !> Snapshots due up to t_new (snapshot_time, from the run's next one): inside the step just
   !> accepted (from run%t to t_new), or of the static state (static), with the fields the model
   !> gives, to the observer (with the 3-D fields when the model gives them).
   subroutine emit_snapshots(run, model, observer, t_new, static, error)
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(inout) :: model
      !> Receives the snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> End of the step just accepted (or the time the static state holds until), s.
      real(dp), intent(in) :: t_new
      !> Whether the snapshots are of the static state.
      logical, intent(in) :: static
      !> Error of the output.
      type(error_type), allocatable, intent(inout) :: error
      real(dp) :: ts, fields(run%n_out, n_fields), extra(run%n_out, n_fields3)
      logical :: with_extra
      do
         ts = snapshot_time(run, run%progress%snapshot_index)
         if (ts > t_new*(1 + 1.0e-12_dp)) exit
         call model%snapshot(run, t_new, ts, static, fields, extra, with_extra)
         run%progress%snapshot_index = run%progress%snapshot_index + 1
         if (.not. present(observer)) cycle
         call observer%snapshot(model%snapshot_at(run, ts), fields, error)
         if (.not. allocated(error) .and. with_extra) &
            call observer%snapshot_extra(model%snapshot_at(run, ts), field3_names, extra, error)
         if (allocated(error)) then
            call prefix_error(error, 'output: ')
            return
         end if
      end do
   end subroutine emit_snapshots

   !> Whether the step loop pauses before its next attempt:
   !> pause_termination when SIGTERM has arrived (options%stop_on_termination),
   !> pause_checkpoint when a checkpoint is due (every
   !> options%checkpoint_interval seconds of wall time, or every
   !> options%checkpoint_steps accepted steps; at least one step since the
   !> last), else pause_none. The clock notes a checkpoint pause.
   integer function checkpoint_pause(run, wall) result(pause)
      !> Run (its history counts the steps).
      type(rod_run), intent(inout) :: run
      !> Wall time of this process's dynamics, s.
      real(dp), intent(in) :: wall
      logical :: due
      pause = pause_none
      if (run%options%stop_on_termination) then
         if (termination_requested()) then
            pause = pause_termination
            return
         end if
      end if
      if (run%history%n > run%clock%records_at_checkpoint) then
         due = .false.
         if (run%options%checkpoint_interval > 0) &
            due = wall - run%clock%last_checkpoint >= run%options%checkpoint_interval
         if (run%options%checkpoint_steps > 0) &
            due = due .or. run%history%n - run%clock%records_at_checkpoint >= run%options%checkpoint_steps
         if (due) then
            run%clock%last_checkpoint = wall
            run%clock%records_at_checkpoint = run%history%n
            pause = pause_checkpoint
         end if
      end if
   end function checkpoint_pause

end module xcable_driver_stepping
