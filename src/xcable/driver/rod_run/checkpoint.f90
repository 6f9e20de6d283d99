!> The state of a rod run to and from a checkpoint (one list of items for both ways).
!> (A submodule of driver/rod_run.f90.)
submodule (xcable_driver_rod_run) xcable_driver_rod_run_checkpoint
   implicit none

contains

   !> Save the state of the run between two steps (after a pause of
   !> advance, or after start) to an archive: everything the next step and
   !> the records depend on (see exchange_state). archive%ok tells whether
   !> it was stored.
   module subroutine run_save_state(self, archive)
      !> Run.
      class(rod_run), intent(inout) :: self
      !> Where the state goes.
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable :: error
      call exchange_state(self, archive, .true., error)
   end subroutine run_save_state

   !> Load a state saved by save_state into a run prepared from the same case
   !> (the same statics, grid and time step), ready for advance. Errors
   !> (stat_input) when the archive fails or holds a state this run cannot
   !> have.
   module subroutine run_load_state(self, archive, error)
      !> Run, prepared.
      class(rod_run), intent(inout) :: self
      !> Where the state comes from.
      class(state_archive), intent(inout) :: archive
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      call exchange_state(self, archive, .false., error)
      if (allocated(error)) return
      if (.not. archive%ok) then
         call fatal_error(error, archive%message, stat_input)
         return
      end if
      call system_clock(self%clock%start, self%clock%rate)
      self%clock%last_report = 0
      self%clock%last_checkpoint = 0
      self%clock%records_at_checkpoint = self%history%n
   end subroutine run_load_state

   !> The state of a run, listed once for saving (saving = .true.) and
   !> loading, so that the two cannot differ. It is what the step loop carries
   !> from one step to the next:
   !>  - time, step size asked for and the step control (progress: the step
   !>    to try, the good steps since it was halved, the rejections since the
   !>    last accepted step, the next snapshot, the wall time so far);
   !>  - the break (whether it happened, the forces and couples its new ends
   !>    start from) and so the pieces; per piece its positions and
   !>    velocities at the current time, the reactions of its held ends, and
   !>    Newton's kept factorisation when one is kept (reuse_jacobian): its
   !>    LU factors and pivots, the contraction and the step it was made for;
   !>  - the energy accumulators (work of the ends, work of the distributed
   !>    loads, dissipation);
   !>  - the history (every record so far) and the summary's counters.
   !> Not saved, because every step recomputes them before use: the pieces'
   !> work arrays (old level, geometry, forces: prepare_step and the
   !> residual), the Newton residual and update, the positions and
   !> velocities of the previous time level (r_prev, v_prev: accept sets them
   !> before the snapshots inside the step read them; the rod is a one-step
   !> method). The distributed loads (fluid) and the internal damping keep no
   !> state of their own: a step evaluates them from its two levels, and the
   !> statics leave the loads' factor at 1. Not saved, because prepare computes
   !> them from the case: the grid, the static state, the scene, its ends and
   !> loads, the damping coefficient.
   subroutine exchange_state(self, a, saving, error)
      type(rod_run), intent(inout) :: self
      class(state_archive), intent(inout) :: a
      logical, intent(in) :: saving
      type(error_type), allocatable, intent(out) :: error
      integer :: n_pieces, p, n, flags(2), kb, expected_nodes(2)
      real(dp) :: newton_reals(2)
      character(:), allocatable :: prefix

      call sync_real(a, 'run/t', self%t, saving)
      call sync_real(a, 'run/dt', self%dt, saving)
      call sync_real(a, 'run/work', self%work, saving)
      call sync_real(a, 'run/load_work', self%load_work, saving)
      call sync_real(a, 'run/dissipation', self%dissipation, saving)
      call sync_logical(a, 'run/broken', self%broken, saving)
      call sync_matrix(a, 'run/cut_force', self%cut_force, saving)
      call sync_reals(a, 'run/cut_couple', self%cut_couple, saving)
      call exchange_progress(self, a, saving)

      ! The pieces: one, or two after a break inside the cable.
      n_pieces = 0
      if (allocated(self%pieces)) n_pieces = size(self%pieces)
      call sync_int(a, 'run/pieces', n_pieces, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         kb = self%break_node
         if (self%broken .and. .not. self%scene%breaks) then
            call fatal_error(error, 'the checkpoint holds a broken cable, the case has no break', stat_input)
            return
         end if
         if (n_pieces /= merge(2, 1, self%broken .and. kb > 0)) then
            call fatal_error(error, 'the checkpoint holds '//str(n_pieces)//' pieces of cable, this case '// &
                             str(merge(2, 1, self%broken .and. kb > 0))//' at that stage', stat_input)
            return
         end if
         self%pieces(1)%end_slot = [1, 2]
         if (self%broken) call apply_split(self)
      end if
      expected_nodes = [self%options%nodes, 0]
      if (n_pieces == 2) expected_nodes = [self%break_node, self%options%nodes - self%break_node + 1]
      do p = 1, n_pieces
         prefix = 'pieces/'//str(p)//'/'
         associate (run_piece => self%pieces(p), work => self%pieces(p)%work)
            n = run_piece%problem%piece%n
            call sync_int(a, prefix//'nodes', n, saving)
            if (.not. saving .and. a%ok .and. n /= expected_nodes(p)) then
               call fatal_error(error, 'the checkpoint holds '//str(n)//' nodes in piece '//str(p)//', this case '// &
                                str(expected_nodes(p)), stat_input)
               return
            end if
            call sync_matrix(a, prefix//'r', run_piece%r, saving)
            call sync_matrix(a, prefix//'v', run_piece%v, saving)
            call sync_matrix(a, prefix//'reaction', run_piece%reaction, saving)
            call sync_real(a, prefix//'tension_ref', run_piece%problem%piece%tension_ref, saving)
            ! Newton's kept factorisation, when a kept one can be used (reuse_jacobian).
            flags = merge(1, 0, [work%usable .and. self%options%newton%reuse_jacobian, work%jacobian%factorised])
            newton_reals = [run_piece%factor_step, work%contraction]
            call sync_ints(a, prefix//'newton_flags', flags, saving)
            call sync_reals(a, prefix//'newton_reals', newton_reals, saving)
            if (.not. saving) then
               work%usable = flags(1) == 1
               work%jacobian%factorised = flags(2) == 1
               run_piece%factor_step = newton_reals(1)
               work%contraction = newton_reals(2)
            end if
            if (flags(1) == 1) then
               call sync_matrix(a, prefix//'jacobian', work%jacobian%ab, saving)
               call sync_ints(a, prefix//'pivots', work%jacobian%ipiv, saving)
            end if
         end associate
      end do

      call exchange_records(self, a, saving, merge(4, 2, self%break_node > 0), error)
   end subroutine exchange_state

   !> Where the step loop stands (run_progress), listed for saving and
   !> loading: the step to try, the good steps since it was halved, the
   !> rejections since the last accepted step, the next snapshot, the wall
   !> time so far. Either model (exchange_state, driver/rod3d_drive.f90).
   module subroutine exchange_progress(self, a, saving)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Archive.
      class(state_archive), intent(inout) :: a
      !> Save (.true.) or load.
      logical, intent(in) :: saving
      real(dp) :: wall
      call sync_real(a, 'progress/h', self%progress%h, saving)
      call sync_int(a, 'progress/n_good', self%progress%n_good, saving)
      call sync_int(a, 'progress/rejected_here', self%progress%rejected_here, saving)
      call sync_int(a, 'progress/snapshot_index', self%progress%snapshot_index, saving)
      ! The wall time of the dynamics so far (this process's and the earlier ones').
      if (saving) wall = self%wall_time()
      call sync_real(a, 'progress/wall_time', wall, saving)
      if (.not. saving) self%progress%wall_before = wall
   end subroutine exchange_progress

   !> The records so far, listed for saving and loading: every history
   !> record (with the y components, ends_y, of a 3-D run) and the summary's
   !> counters and extremes. Either model (exchange_state,
   !> driver/rod3d_drive.f90); loading sets up the history with n_ends ends.
   module subroutine exchange_records(self, a, saving, n_ends, error, with_y)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Archive.
      class(state_archive), intent(inout) :: a
      !> Save (.true.) or load.
      logical, intent(in) :: saving
      !> Ends of the history (2, or 4 with a break inside the cable).
      integer, intent(in) :: n_ends
      !> Error (stat_input) when the archive's history does not fit.
      type(error_type), allocatable, intent(inout) :: error
      !> The y components too (a 3-D run; default .false.).
      logical, intent(in), optional :: with_y
      integer :: n_records
      logical :: y_kept
      y_kept = .false.
      if (present(with_y)) y_kept = with_y
      ! The history: every record so far.
      n_records = self%history%n
      call sync_int(a, 'history/n', n_records, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (n_records < 0 .or. a%stored_size('history/time') /= n_records + 1) then
            call fatal_error(error, 'the checkpoint''s history has '//str(n_records)//' records but '// &
                             str(a%stored_size('history/time'))//' times', stat_input)
            return
         end if
         if (allocated(self%history%end_labels)) deallocate (self%history%end_labels)
         allocate (self%history%end_labels(n_ends))
         self%history%end_labels(1:2) = [character(len=8) :: 'end_a', 'end_b']
         if (n_ends == 4) self%history%end_labels(3:4) = [character(len=8) :: 'break_a', 'break_b']
         call self%history%reserve(max(n_records, int(min(self%options%t_end/self%dt, real(max_steps, dp)))) + 16, &
                                   n_ends, self%options%energy, with_y=y_kept)
         ! (The box scheme's run has no scene loads.)
         if (allocated(self%scene%loads)) call self%history%keep_measures(measure_names(self%scene%loads))
         self%history%n = n_records
      end if
      associate (h => self%history, m => n_records)
         call sync_reals(a, 'history/time', h%time(0:m), saving)
         call sync_reals(a, 'history/step', h%step(0:m), saving)
         call sync_ints(a, 'history/newton_iterations', h%newton_iterations(0:m), saving)
         call sync_ints(a, 'history/rejected', h%rejected(0:m), saving)
         call sync_cube(a, 'history/ends', h%ends(:, :, 0:m), saving)
         if (self%options%energy) call sync_matrix(a, 'history/energy', h%energy(:, 0:m), saving)
         if (y_kept) call sync_cube(a, 'history/ends_y', h%ends_y(:, :, 0:m), saving)
         if (allocated(h%measures)) call sync_matrix(a, 'history/measures', h%measures(:, 0:m), saving)
      end associate

      ! The summary's counters and extremes so far (summarise derives the rest at the end).
      associate (s => self%summary)
         call sync_int(a, 'summary/rejected_steps', s%rejected_steps, saving)
         call sync_int(a, 'summary/newton_iterations', s%newton_iterations, saving)
         call sync_int(a, 'summary/max_newton_iterations', s%max_newton_iterations, saving)
         call sync_int(a, 'summary/factorisations', s%factorisations, saving)
         call sync_real(a, 'summary/dt_requested', s%dt_requested, saving)
         call sync_real(a, 'summary/dt_used', s%dt_used, saving)
         call sync_real(a, 'summary/courant_requested', s%courant_requested, saving)
         call sync_real(a, 'summary/max_turning_angle', s%max_turning_angle, saving)
         call sync_real(a, 'summary/min_strain', s%min_strain, saving)
         call sync_real(a, 'summary/min_strain_s', s%min_strain_s, saving)
         call sync_real(a, 'summary/min_strain_time', s%min_strain_time, saving)
         call sync_real(a, 'summary/max_strain', s%max_strain, saving)
      end associate
   end subroutine exchange_records
   !> The planar model's state to an archive: the run's (save_state).
   module subroutine planar_save_state(self, run, archive)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: archive
      call run%save_state(archive)
   end subroutine planar_save_state

   !> The planar model's state from an archive: the run's (load_state).
   module subroutine planar_load_state(self, run, archive, error)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable, intent(out) :: error
      call run%load_state(archive, error)
   end subroutine planar_load_state

end submodule xcable_driver_rod_run_checkpoint
