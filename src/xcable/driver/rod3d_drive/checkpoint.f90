!> The checkpoint of a 3-D run: its state between two steps listed once (exchange3) for saving
!> and loading, with the planar run's sync procedures (io/archive.f90) and its exchange_progress
!> and the history's exchange_records (driver/history.f90). (A submodule of driver/rod3d_drive.f90.)
submodule (xcable_driver_rod3d_drive) xcable_driver_rod3d_drive_checkpoint
   use xcable_driver_rod_run, only: exchange_progress
   use xcable_driver_history, only: exchange_records
   use xcable_io_archive, only: sync_real, sync_reals, sync_matrix, sync_int, sync_ints, sync_logical
   implicit none

contains

   !> Save the state of the run between two steps (after start, or a pause
   !> of advance) to an archive (see exchange3). archive%ok tells whether it was stored.
   module subroutine drive_save_state(self, run, archive)
      !> 3-D run.
      class(rod3d_drive), intent(inout) :: self
      !> The planar run it shares its records with.
      type(rod_run), intent(inout) :: run
      !> Where the state goes.
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable :: error
      call exchange3(self, run, archive, .true., error)
   end subroutine drive_save_state

   !> Load a state saved by save_state into a run prepared from the same case,
   !> ready for advance. Errors (stat_input) when the archive fails or holds a
   !> state this run cannot have.
   module subroutine drive_load_state(self, run, archive, error)
      !> 3-D run, prepared.
      class(rod3d_drive), intent(inout) :: self
      !> The planar run it shares its records with (prepared).
      type(rod_run), intent(inout) :: run
      !> Where the state comes from.
      class(state_archive), intent(inout) :: archive
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      integer :: p
      call exchange3(self, run, archive, .false., error)
      if (allocated(error)) return
      if (.not. archive%ok) then
         call fatal_error(error, archive%message, stat_input)
         return
      end if
      call set_time(self, run%t)
      do p = 1, size(self%pieces)
         self%pieces(p)%run%work%usable = .false.
      end do
      call system_clock(run%clock%start, run%clock%rate)
      run%clock%last_report = 0
      run%clock%last_checkpoint = 0
      run%clock%records_at_checkpoint = run%history%n
   end subroutine drive_load_state

   !> The state of a 3-D run, listed once for saving (saving = .true.) and
   !> loading. Besides what the planar run keeps of the step loop and the
   !> records (rod_run's exchange_progress, exchange_records: the step
   !> control, the next snapshot, the wall time, every history record with
   !> its y components, the summary's counters), it is:
   !>  - time and step size asked for (run/t, run/dt);
   !>  - the break (whether it happened; the forces, x, y, z, its new ends
   !>    start from, and inside the cable their couples, couple axes and
   !>    torques) and so the pieces;
   !>  - per piece (rod3d/ for the first, rod3d/2/ for the second): its
   !>    nodes, the unknowns (positions and twist angles, 4 per node) and
   !>    velocities at the current time, the ledger's accumulators (stored
   !>    energy at the start, work of the ends and of the loads, dissipation)
   !>    and the Newton iterations so far.
   !> Not saved: the previous time level (x_prev, v_prev: set before every
   !> attempt), the forces of the supports on the end nodes (accept sets
   !> them before the history and the break read them), the pieces' work
   !> arrays (prepare_step and the residual set them), Newton's workspace (a
   !> 3-D step keeps no factorisation: accept and reject leave it unusable),
   !> and what prepare computes from the case (the grid, the 3-D static
   !> state, the ends and loads).
   subroutine exchange3(self, rod, a, saving, error)
      type(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: rod
      class(state_archive), intent(inout) :: a
      logical, intent(in) :: saving
      type(error_type), allocatable, intent(out) :: error
      integer :: n, iterations(1), n_pieces, p, expected
      character(:), allocatable :: prefix
      call sync_real(a, 'run/t', rod%t, saving)
      call sync_real(a, 'run/dt', rod%dt, saving)
      call sync_logical(a, 'run/broken', self%broken, saving)
      call sync_matrix(a, 'rod3d/cut_force', self%cut_force, saving)
      if (rod%break_node > 0) then
         call sync_reals(a, 'rod3d/cut_couple', self%cut_couple, saving)
         call sync_matrix(a, 'rod3d/cut_axis', self%cut_axis, saving)
         call sync_reals(a, 'rod3d/cut_torque', self%cut_torque, saving)
      end if
      call exchange_progress(rod, a, saving)
      n_pieces = size(self%pieces)
      call sync_int(a, 'rod3d/pieces', n_pieces, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (self%broken .and. .not. rod%scene%breaks) then
            call fatal_error(error, 'the checkpoint holds a broken cable, the case has no break', stat_input)
            return
         end if
         expected = merge(2, 1, self%broken .and. rod%break_node > 0)
         if (n_pieces /= expected) then
            call fatal_error(error, 'the checkpoint holds '//str(n_pieces)//' pieces of cable, this case '// &
                             str(expected)//' at that stage', stat_input)
            return
         end if
         rod%broken = self%broken
         if (self%broken) call release(self, rod, error)
         if (allocated(error)) return
      end if
      do p = 1, n_pieces
         prefix = 'rod3d/'
         if (p > 1) prefix = 'rod3d/'//str(p)//'/'
         associate (run => self%pieces(p)%run)
            call exchange_run3(a, prefix, run, 'piece '//str(p), saving, error)
            if (allocated(error) .or. .not. a%ok) return
            n = run%problem%piece%n
            iterations = run%iterations
            call sync_ints(a, prefix//'newton_iterations', iterations, saving)
            if (.not. saving) then
               ! The cut piece's anchored twist angle: its first node's, pinned there since the cut.
               if (n_pieces == 2) run%problem%piece%psi_anchor = run%x(3*n + 1)
               run%iterations = iterations(1)
            end if
         end associate
      end do
      call exchange_records(rod, a, saving, error, with_y=.true.)
   end subroutine exchange3
end submodule xcable_driver_rod3d_drive_checkpoint
