!> Checkpoints and resume (either scheme): a run stopped by SIGTERM (raised
!> from inside the run, by the observer at a chosen snapshot) and resumed
!> from its checkpoint computes, bit for bit, the snapshots, history and
!> summary of the run that was not stopped; so does a run resumed from a
!> checkpoint written every so many steps, and writing checkpoints does not
!> change a run. Three scenes cover the state a checkpoint must hold: the
!> paper's rupture (a released end, the energy ledger), a line parting in
!> the middle while end a moves (a checkpoint before and one after the
!> split into two pieces), and a kept Newton factorisation (reuse_jacobian,
!> theta 0.55, internal damping). The 3-D model the same way
!> (driver/rod3d_drive.f90): a fairlead moving across the plane in water,
!> its end let go during the run (checkpoints before and after the break),
!> the same line parted inside (two 3-D pieces; before the break and during
!> its ramp), and a release off the plane whose steps are rejected and halved; the
!> snapshots' 3-D fields and the history's y components are compared too.
!> The box scheme the same way (box/model.f90): the paper's rupture stopped
!> during and after the release and with its step halved, and a checkpoint
!> every 7 steps. Damaged, truncated, foreign (another version, another
!> namelist, the other model, the other scheme) and missing checkpoints are
!> refused.
module suite_checkpoint
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_core_error, only: stat_input
   use xcable_io_config, only: case_config
   use xcable_io_input, only: config_text, read_config
   use xcable_fixtures, only: pushing_rope
   use xcable_driver_simulation, only: simulation
   use xcable_driver_records, only: run_observer, static_info, run_history, run_summary, n_fields
   use xcable_io_checkpoint, only: checkpoint_file, remove_checkpoint
   use xcable_io_hdf5_put, only: put_text_attr
   use xcable_system_posix, only: install_termination_handler, raise_termination, clear_termination
   use suite_rod_dynamics, only: rupture_config
   use hdf5
   use, intrinsic :: iso_fortran_env, only: output_unit, int8
   implicit none
   private
   public :: collect_checkpoint

   !> Records the snapshots of a run and raises SIGTERM at one of them.
   type, extends(run_observer) :: recorder
      !> Snapshots recorded, their times and fields (nodes, n_fields, snapshot).
      integer :: n = 0
      real(dp), allocatable :: times(:), fields(:, :, :)
      !> The 3-D fields of the snapshots (nodes, n_fields3, snapshot), when sent.
      integer :: n_extra = 0
      real(dp), allocatable :: extra(:, :, :)
      !> Raise SIGTERM when this snapshot (1: the one at t = 0) has been recorded (0: never).
      integer :: raise_at = 0
   contains
      procedure :: static => recorder_static
      procedure :: snapshot => recorder_snapshot
      procedure :: snapshot_extra => recorder_extra
   end type recorder

   character(len=*), parameter :: path = 'build/test_checkpoint.ckpt'
   !> Where the 3-D cases' namelists are written to be read.
   character(len=*), parameter :: namelist_path = 'build/test_checkpoint3d.nml'

   !> 3-D: a line in water between a fixed end and a fairlead moving across
   !> the plane (1 m along y, period 2 s), a current across the plane
   !> (0.3 m/s along y), the ledger kept; the fairlead end breaks at 0.6 s
   !> (its force ramped to zero over 0.5 s). 31 nodes, dt 10 ms, to 1.2 s.
   character(len=*), parameter :: fairlead_line = &
      "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
      "&end_b kind = 'motion', x = 50, z = 0, amplitude = 1, period = 2, direction_x = 0, direction_y = 1, "// &
      "direction_z = 0, ramp_time = 0.5 /"//new_line('a')// &
      "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = 0.3, "// &
      "surface_z = -1 /"//new_line('a')
   character(len=*), parameter :: fairlead_run = "&numerics nodes = 31, dt = 0.01, t_end = 1.2 /"//new_line('a')// &
                                                 "&output interval = 0.1, energy = .true., quiet = .true. /"
   character(len=*), parameter :: fairlead3d = fairlead_line//"&rupture s_break = 60, t_break = 0.5, time = 0.6 /"// &
                                               new_line('a')//fairlead_run

   !> 3-D: the fairlead scene parted inside instead (s = 20 m of 60) at 0.6 s,
   !> the cut's force, couple and torque ramped to zero over 0.2 s.
   character(len=*), parameter :: middle3d = fairlead_line//"&rupture s_break = 20, t_break = 0.2, time = 0.6 /"// &
                                             new_line('a')//fairlead_run

   !> 3-D: end a fixed, end b loaded by a force and a torque of 5 N m (a
   !> uniform twist) ramped off over 1 s, parted at s = 30 m at 0.05 s over 50
   !> ms (41 nodes, to 0.2 s): the piece with end b holds its twist at
   !> neither end, and its anchored twist angle (that at the cut, not the
   !> static one) must come back on loading.
   character(len=*), parameter :: twisted3d = &
      "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
      "&end_b kind = 'force', force_x = 3000, force_z = 1000, torque = 5, history = 'ramp', ramp_time = 1 /"// &
      new_line('a')// &
      "&rupture s_break = 30, t_break = 0.05, time = 0.05 /"//new_line('a')// &
      "&numerics nodes = 41, t_end = 0.2 /"//new_line('a')// &
      "&output interval = 0.01, energy = .true., quiet = .true. /"

   !> 3-D: a slack line (end b 40 m along x, 20 m along y) let go at end b,
   !> EI / 1000, 121 nodes, Courant 14, to 0.5 s: some attempts are
   !> rejected, steps halved and doubled back.
   character(len=*), parameter :: release3d = &
      "&cable bending_stiffness = 0.07056 /"//new_line('a')// &
      "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
      "&end_b kind = 'fixed', x = 40, y = 20, z = 0 /"//new_line('a')// &
      "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
      "&numerics model = '3d', nodes = 121, courant = 14, t_end = 0.5 /"//new_line('a')// &
      "&output interval = 0.02, energy = .true., quiet = .true. /"
   !> The same scene with model = 'auto': it lies in one vertical plane, so it runs in 2-D, turned
   !> into x-z, its results turned back (driver/simulation.f90).
   character(len=*), parameter :: release_turned = &
      "&cable bending_stiffness = 0.07056 /"//new_line('a')// &
      "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
      "&end_b kind = 'fixed', x = 40, y = 20, z = 0 /"//new_line('a')// &
      "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
      "&numerics nodes = 121, courant = 14, t_end = 0.5 /"//new_line('a')// &
      "&output interval = 0.02, energy = .true., quiet = .true. /"

contains

   subroutine collect_checkpoint(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('sigterm_then_resume_is_bitwise', test_sigterm), &
               new_unittest('periodic_checkpoints_change_nothing', test_periodic), &
               new_unittest('refuses_bad_checkpoints', test_refusals), &
               new_unittest('sigterm_then_resume_is_bitwise_3d', test_sigterm_3d), &
               new_unittest('periodic_checkpoints_change_nothing_3d', test_periodic_3d), &
               new_unittest('refuses_the_other_model', test_other_model), &
               new_unittest('sigterm_then_resume_is_bitwise_skip', test_sigterm_skip), &
               new_unittest('sigterm_then_resume_is_bitwise_tension', test_sigterm_tension), &
               new_unittest('sigterm_then_resume_is_bitwise_box', test_sigterm_box), &
               new_unittest('periodic_checkpoints_change_nothing_box', test_periodic_box)]
   end subroutine collect_checkpoint

   subroutine recorder_static(self, info, error)
      class(recorder), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
   end subroutine recorder_static

   subroutine recorder_snapshot(self, t, fields, error)
      class(recorder), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: times(:), stored(:, :, :)
      if (.not. allocated(self%times)) allocate (self%times(0), self%fields(size(fields, 1), n_fields, 0))
      allocate (times(self%n + 1), stored(size(fields, 1), n_fields, self%n + 1))
      times(1:self%n) = self%times(1:self%n)
      stored(:, :, 1:self%n) = self%fields(:, :, 1:self%n)
      times(self%n + 1) = t
      stored(:, :, self%n + 1) = fields
      call move_alloc(times, self%times)
      call move_alloc(stored, self%fields)
      self%n = self%n + 1
      if (self%n == self%raise_at) call raise_termination()
   end subroutine recorder_snapshot

   !> The 3-D fields of the snapshot just recorded.
   subroutine recorder_extra(self, t, names, fields, error)
      class(recorder), intent(inout) :: self
      real(dp), intent(in) :: t
      character(*), intent(in) :: names(:)
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: stored(:, :, :)
      if (.not. allocated(self%extra)) allocate (self%extra(size(fields, 1), size(fields, 2), 0))
      allocate (stored(size(fields, 1), size(fields, 2), self%n_extra + 1))
      stored(:, :, 1:self%n_extra) = self%extra(:, :, 1:self%n_extra)
      stored(:, :, self%n_extra + 1) = fields
      call move_alloc(stored, self%extra)
      self%n_extra = self%n_extra + 1
   end subroutine recorder_extra

   !> The paper's rupture at 180 kN on 61 nodes, the end released in 5 ms, with the ledger.
   function paper_scene() result(c)
      type(case_config) :: c
      c = rupture_config(180.0e3_dp, 0.005_dp, 0.05_dp, 61)
      c%energy = .true.
      c%interval = 0.0025_dp
   end function paper_scene

   !> The paper's rupture (paper_scene) with the box scheme.
   function box_scene() result(c)
      type(case_config) :: c
      c = paper_scene()
      c%scheme = 'box'
   end function box_scene

   !> An inclined taut line (end b at 60 m, 20 m up) whose end a moves up and
   !> down, parting in the middle at t = 10 ms: before the break one piece, after it two.
   function middle_scene() result(c)
      type(case_config) :: c
      c = rupture_config(180.0e3_dp, 0.01_dp, 0.03_dp, 61)
      c%end_a%kind = 'motion'
      c%end_a%amplitude = 0.05_dp
      c%end_a%period = 0.02_dp
      c%end_b%x = 60
      c%end_b%z = 20
      c%given = 'end_b%x end_b%z'
      c%s_break = 30
      c%break_time = 0.01_dp
      c%energy = .true.
      c%interval = 0.002_dp
      c%courant = 0.25_dp
   end function middle_scene

   !> The paper's rupture with a kept factorisation (reuse_jacobian given), theta 0.55 and damping.
   function reuse_scene() result(c)
      type(case_config) :: c
      c = paper_scene()
      c%reuse_jacobian = .true.
      c%given = 'numerics%reuse_jacobian'
      c%theta = 0.55_dp
      c%damping = 2000
   end function reuse_scene

   !> The paper's rupture in water with a current: buoyancy, drag, added mass
   !> and their work in the ledger (energy index 8, loads).
   function fluid_scene() result(c)
      type(case_config) :: c
      c = paper_scene()
      c%fluid_density = 1025
      c%cd_normal = 1.2_dp
      c%cd_tangential = 0.01_dp
      c%ca_normal = 1
      c%current_x = 0.5_dp
      ! The surface across the line near its supports: the wetted length in the history.
      c%surface_z = -2
   end function fluid_scene

   !> The paper's rupture at Courant number 2 with at most 2 Newton
   !> iterations a step: steps are rejected, halved and doubled back.
   function halving_scene() result(c)
      type(case_config) :: c
      c = paper_scene()
      c%courant = 2
      c%newton_max_iter = 2
   end function halving_scene

   !> A case from namelist text, read as the program reads it.
   subroutine case_of(text, c, error)
      character(*), intent(in) :: text
      type(case_config), intent(out) :: c
      type(error_type), allocatable, intent(out) :: error
      integer :: unit
      open (newunit=unit, file=namelist_path, status='replace', action='write')
      write (unit, '(a)') pushing_rope(text)
      close (unit)
      call read_config(namelist_path, c, error)
   end subroutine case_of

   !> Run a case to the end without checkpoints.
   subroutine plain_run(c, sim, store, error)
      type(case_config), intent(in) :: c
      type(simulation), intent(inout) :: sim
      type(recorder), intent(inout) :: store
      type(error_type), allocatable, intent(out) :: error
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(store, error)
   end subroutine plain_run

   !> Prepare a case, with checkpoints to path (every every_steps steps, 0:
   !> none) and the stop at SIGTERM.
   subroutine checkpointed(c, sim, every_steps, error)
      type(case_config), intent(in) :: c
      type(simulation), intent(inout) :: sim
      integer, intent(in) :: every_steps
      type(error_type), allocatable, intent(out) :: error
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%enable_checkpoints(path, config_text(c, fingerprint=.true.), 'test-run', 0.0_dp, .true., every_steps)
   end subroutine checkpointed

   !> Resume a case from path and run it to the end.
   subroutine resumed_run(c, sim, store, error)
      type(case_config), intent(in) :: c
      type(simulation), intent(inout) :: sim
      type(recorder), intent(inout) :: store
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: run_id
      call checkpointed(c, sim, 0, error)
      if (allocated(error)) return
      call sim%resume(path, config_text(c, fingerprint=.true.), run_id, error)
      if (allocated(error)) return
      call check(error, run_id == 'test-run', 'the checkpoint''s run is "'//run_id//'"')
      if (allocated(error)) return
      call sim%run(store, error)
   end subroutine resumed_run

   !> SIGTERM in the middle of a run (at snapshot k): the run writes a
   !> checkpoint and stops; resumed, it ends as the run that was not stopped.
   subroutine test_sigterm(error)
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: problem
      problem = install_termination_handler()
      call check(error, len(problem) == 0, problem)
      if (allocated(error)) return
      call stopped_and_resumed('paper rupture, SIGTERM during the release', paper_scene(), 2, error)
      if (allocated(error)) return
      call stopped_and_resumed('middle break, SIGTERM before the break', middle_scene(), 3, error)
      if (allocated(error)) return
      call stopped_and_resumed('middle break, SIGTERM during the break', middle_scene(), 8, error)
      if (allocated(error)) return
      call stopped_and_resumed('kept factorisation, theta 0.55, damping', reuse_scene(), 6, error)
      if (allocated(error)) return
      call stopped_and_resumed('in water with a current (fluid loads)', fluid_scene(), 5, error)
      if (allocated(error)) return
      call stopped_and_resumed('step halved (2 Newton iterations at most)', halving_scene(), 4, error, halved=.true.)
   end subroutine test_sigterm

   subroutine stopped_and_resumed(what, c, k, error, halved, broken)
      character(*), intent(in) :: what
      type(case_config), intent(in) :: c
      integer, intent(in) :: k
      type(error_type), allocatable, intent(out) :: error
      !> Whether the stop must find the step halved and growing back (the step control's state matters).
      logical, intent(in), optional :: halved
      !> Whether the stop must find the cable broken (.true.) or not yet (.false.).
      logical, intent(in), optional :: broken
      type(simulation) :: reference, stopped, resumed
      type(recorder) :: whole, first, rest
      call plain_run(c, reference, whole, error)
      if (allocated(error)) return
      call checkpointed(c, stopped, 0, error)
      if (allocated(error)) return
      first%raise_at = k
      call stopped%run(first, error)
      call clear_termination()
      if (allocated(error)) return
      call check(error, stopped%interrupted .and. stopped%checkpoints_written == 1, what//': SIGTERM did not stop '// &
                 'the run with one checkpoint')
      if (allocated(error)) return
      call check(error, stopped%rod%t > 0 .and. stopped%rod%t < c%t_end, what//': stopped at t = '//str(stopped%rod%t))
      if (allocated(error)) return
      ! With reuse_jacobian the checkpoint holds a kept factorisation (its LU factors and pivots).
      if (stopped%scheme == 'box') then
         call check(error, stopped%box%stepper%work%usable .and. stopped%box%stepper%have_prev, &
                    what//': no factorisation kept, or no level before, at the checkpoint')
      else if (stopped%rod%options%newton%reuse_jacobian) then
         call check(error, stopped%rod%pieces(1)%work%usable, what//': no factorisation kept at the checkpoint')
      end if
      if (allocated(error)) return
      ! With fluid loads their work so far is part of the state (the ledger's loads).
      if (c%fluid_density > 0) call check(error, merge(stopped%rod3%pieces(1)%run%load_work, stopped%rod%load_work, &
                                                       stopped%model == '3d') /= 0, what//': no work of the loads at the stop')
      if (allocated(error)) return
      if (present(broken)) call check(error, stopped%rod%broken .eqv. broken, what//': broken at the stop: '// &
                                      merge('yes', 'no ', stopped%rod%broken))
      if (allocated(error)) return
      if (present(halved)) call check(error, stopped%rod%progress%h < stopped%rod%dt .and. &
                                      stopped%rod%progress%n_good > 0, what//': the step is not halved at the stop')
      if (allocated(error)) return
      call resumed_run(c, resumed, rest, error)
      if (allocated(error)) return
      call same_run(what, reference, resumed, whole, first, rest, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,i0,a,i0,a)') what//': stopped at t = '//str(stopped%rod%t)//' s (step ', &
         stopped%rod%history%n, ' of ', reference%rod%history%n, '; step '//str(stopped%rod%progress%h/stopped%rod%dt)// &
         ' dt, '//str(stopped%rod%progress%n_good)//' good since halved, '//str(reference%rod%summary%rejected_steps)// &
         ' rejected in the run), resumed: snapshots, history and summary bitwise equal'
      call remove_checkpoint(path)
   end subroutine stopped_and_resumed

   !> A break by tension (&rupture criterion = 'tension'; end b pulled by a force rising from
   !> 20 to 40 kN in 0.05 s, MBL 30 kN: the line parts inside, at s = 58 m, at 0.026 s), planar
   !> and 3-D, SIGTERM before the break (snapshot 3, t = 0.01 s) and after it (snapshot 10):
   !> the resumed run, whose preparation finds the break again by its first pass, equals the
   !> uninterrupted one to the bit.
   subroutine test_sigterm_tension(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: scene = &
         "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
         "&end_b kind = 'force', history = 'table', table_time = 0, 0.05, 1, table_x = 20000, 40000, 40000, "// &
         "table_z = 0, 0, 0 /"//new_line('a')// &
         "&rupture criterion = 'tension', mbl = 30000, t_break = 0.005 /"//new_line('a')// &
         "&output interval = 0.005, quiet = .true. /"//new_line('a')
      character(:), allocatable :: problem
      character(len=2), parameter :: models(2) = ['2d', '3d']
      type(case_config) :: c
      integer :: i
      problem = install_termination_handler()
      call check(error, len(problem) == 0, problem)
      if (allocated(error)) return
      do i = 1, 2
         call case_of(scene//"&numerics model = '"//models(i)//"', nodes = 61, courant = 1.0, t_end = 0.08 /", c, error)
         if (allocated(error)) return
         call stopped_and_resumed(models(i)//' break by tension, SIGTERM before it', c, 3, error, broken=.false.)
         if (allocated(error)) return
         call stopped_and_resumed(models(i)//' break by tension, SIGTERM after it', c, 10, error, broken=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_sigterm_tension

   !> The same with the skip of the quiescent cable (&numerics skip_quiescent): the
   !> window of a step follows from the state a checkpoint holds (the velocities, the
   !> time, the history), so a resumed run chooses the same windows.
   subroutine test_sigterm_skip(error)
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: problem
      type(case_config) :: c
      problem = install_termination_handler()
      call check(error, len(problem) == 0, problem)
      if (allocated(error)) return
      c = paper_scene()
      c%skip_quiescent = .true.
      c%nodes = 121
      call skips(c, 'paper rupture')
      if (allocated(error)) return
      call stopped_and_resumed('paper rupture on 121 nodes, skip_quiescent, SIGTERM during the release', c, 4, error)
      if (allocated(error)) return
      c = middle_scene()
      c%skip_quiescent = .true.
      call skips(c, 'middle break')
      if (allocated(error)) return
      call stopped_and_resumed('middle break, skip_quiescent, SIGTERM during the break', c, 8, error, broken=.true.)

   contains

      !> The scene does skip part of the cable (else the test would prove nothing).
      subroutine skips(scene, what)
         type(case_config), intent(in) :: scene
         character(*), intent(in) :: what
         type(simulation) :: sim
         type(recorder) :: store
         call plain_run(scene, sim, store, error)
         if (allocated(error)) return
         write (output_unit, '(4x,a,f6.3,a)') what//': skipped ', real(sim%rod%skipped_node_solves, dp)/ &
            real(max(sim%rod%node_solves, 1_8), dp), ' of the node solves'
         call check(error, sim%rod%skipped_node_solves > 0, what//': nothing skipped')
      end subroutine skips
   end subroutine test_sigterm_skip

   !> The box scheme: SIGTERM at snapshot k, the checkpoint (the two time levels the first guess
   !> extrapolates from, the kept factorisation, the ledger, the box scheme's own history), the
   !> resumed run bit for bit as the run that was not stopped: during the release (snapshot 2,
   !> t = 5 ms), after it (snapshot 12), and with the step halved (Courant number 2, at most 3
   !> Newton iterations: 83 rejected attempts in 92 steps).
   subroutine test_sigterm_box(error)
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: problem
      type(case_config) :: c
      problem = install_termination_handler()
      call check(error, len(problem) == 0, problem)
      if (allocated(error)) return
      call stopped_and_resumed('box scheme, paper rupture, SIGTERM during the release', box_scene(), 2, error)
      if (allocated(error)) return
      call stopped_and_resumed('box scheme, paper rupture, SIGTERM after the release', box_scene(), 12, error)
      if (allocated(error)) return
      c = box_scene()
      c%courant = 2
      c%newton_max_iter = 3
      call stopped_and_resumed('box scheme, step halved (3 Newton iterations at most)', c, 4, error, halved=.true.)
   end subroutine test_sigterm_box

   !> The box scheme with a checkpoint every 7 steps: the run is as without them; resumed from
   !> the last, the same end again.
   subroutine test_periodic_box(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: reference, periodic, resumed
      type(recorder) :: whole, with_checkpoints, rest, none
      type(case_config) :: c
      integer :: kept
      c = box_scene()
      call plain_run(c, reference, whole, error)
      if (allocated(error)) return
      call checkpointed(c, periodic, 7, error)
      if (allocated(error)) return
      call periodic%run(with_checkpoints, error)
      if (allocated(error)) return
      call same_run('box, a checkpoint every 7 steps', reference, periodic, whole, with_checkpoints, none, error)
      if (allocated(error)) return
      call check(error, periodic%checkpoints_written == (reference%rod%history%n - 1)/7, 'checkpoints written: '// &
                 str(periodic%checkpoints_written)//' for '//str(reference%rod%history%n)//' steps')
      if (allocated(error)) return
      call resumed_run(c, resumed, rest, error)
      if (allocated(error)) return
      kept = whole%n - rest%n
      with_checkpoints%n = kept
      call same_run('box, resumed from the last of them', reference, resumed, whole, with_checkpoints, rest, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,i0,a,i0,a)') 'box scheme: ', periodic%checkpoints_written, &
         ' checkpoints (every 7 steps) change nothing; resumed from the last (', kept, &
         ' snapshots kept): bitwise equal'
      call remove_checkpoint(path)
   end subroutine test_periodic_box

   !> A checkpoint every 7 steps leaves the run as it is; the last one,
   !> resumed, gives the same end again.
   subroutine test_periodic(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: reference, periodic, resumed
      type(recorder) :: whole, with_checkpoints, rest, none
      type(case_config) :: c
      integer :: kept
      c = middle_scene()
      call plain_run(c, reference, whole, error)
      if (allocated(error)) return
      call checkpointed(c, periodic, 7, error)
      if (allocated(error)) return
      call periodic%run(with_checkpoints, error)
      if (allocated(error)) return
      call same_run('with a checkpoint every 7 steps', reference, periodic, whole, with_checkpoints, none, error)
      if (allocated(error)) return
      ! A pause comes before a step: none after the last one.
      call check(error, periodic%checkpoints_written == (reference%rod%history%n - 1)/7, 'checkpoints written: '// &
                 str(periodic%checkpoints_written)//' for '//str(reference%rod%history%n)//' steps')
      if (allocated(error)) return
      call resumed_run(c, resumed, rest, error)
      if (allocated(error)) return
      kept = whole%n - rest%n
      with_checkpoints%n = kept
      call same_run('resumed from the last of them', reference, resumed, whole, with_checkpoints, rest, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,i0,a,i0,a)') 'middle break: ', periodic%checkpoints_written, &
         ' checkpoints (every 7 steps) change nothing; resumed from the last (', kept, &
         ' snapshots kept): bitwise equal'
      call remove_checkpoint(path)
   end subroutine test_periodic

   !> Compare a run (b, with the snapshots first + rest) with the reference
   !> (a, snapshots whole): every snapshot, history record and summary figure
   !> but the wall time, to the bit.
   subroutine same_run(what, a, b, whole, first, rest, error)
      character(*), intent(in) :: what
      type(simulation), intent(in), target :: a, b
      type(recorder), intent(in) :: whole, first, rest
      type(error_type), allocatable, intent(out) :: error
      type(run_history), pointer :: ha, hb
      type(run_summary), pointer :: sa, sb
      integer :: n, j
      ha => a%history()
      hb => b%history()
      sa => a%summary()
      sb => b%summary()
      n = ha%n
      call check(error, first%n + rest%n == whole%n, what//': '//str(first%n)//' + '//str(rest%n)//' snapshots, '// &
                 'the reference has '//str(whole%n))
      if (allocated(error)) return
      do j = 1, whole%n
         if (j <= first%n) then
            call check(error, first%times(j) == whole%times(j) .and. all(first%fields(:, :, j) == whole%fields(:, :, j)), &
                       what//': snapshot '//str(j)//' differs')
         else
            call check(error, rest%times(j - first%n) == whole%times(j) .and. &
                       all(rest%fields(:, :, j - first%n) == whole%fields(:, :, j)), what//': snapshot '//str(j)//' differs')
         end if
         if (allocated(error)) return
      end do
      call check(error, hb%n == n, what//': '//str(hb%n)//' history records, the reference has '//str(n))
      if (allocated(error)) return
      call check(error, all(ha%time(0:n) == hb%time(0:n)) .and. all(ha%step(0:n) == hb%step(0:n)) .and. &
                 all(ha%newton_iterations(0:n) == hb%newton_iterations(0:n)) .and. &
                 all(ha%rejected(0:n) == hb%rejected(0:n)) .and. all(ha%ends(:, :, 0:n) == hb%ends(:, :, 0:n)), &
                 what//': the history differs')
      if (allocated(error)) return
      if (allocated(ha%energy)) call check(error, all(ha%energy(:, 0:n) == hb%energy(:, 0:n)), &
                                           what//': the energy ledger differs')
      if (allocated(error)) return
      call check(error, allocated(ha%measures) .eqv. allocated(hb%measures), what//': measures in one history only')
      if (allocated(error)) return
      if (allocated(ha%measures)) call check(error, all(ha%measures(:, 0:n) == hb%measures(:, 0:n)), &
                                             what//': the loads'' measures (wetted length) differ')
      if (allocated(error)) return
      ! A 3-D run: the ends' y components and the snapshots' 3-D fields.
      call check(error, allocated(ha%ends_y) .eqv. allocated(hb%ends_y), what//': y components in one history only')
      if (allocated(error)) return
      if (allocated(ha%ends_y)) call check(error, all(ha%ends_y(:, :, 0:n) == hb%ends_y(:, :, 0:n)), &
                                           what//': the history''s y components differ')
      if (allocated(error)) return
      call check(error, first%n_extra + rest%n_extra == whole%n_extra .and. &
                 (whole%n_extra == 0 .or. whole%n_extra == whole%n), what//': '//str(first%n_extra)//' + '// &
                 str(rest%n_extra)//' snapshots of 3-D fields, the reference has '//str(whole%n_extra))
      if (allocated(error)) return
      do j = 1, whole%n_extra
         if (j <= first%n_extra) then
            call check(error, all(first%extra(:, :, j) == whole%extra(:, :, j)), what//': 3-D fields of snapshot '// &
                       str(j)//' differ')
         else
            call check(error, all(rest%extra(:, :, j - first%n_extra) == whole%extra(:, :, j)), &
                       what//': 3-D fields of snapshot '//str(j)//' differ')
         end if
         if (allocated(error)) return
      end do
      call check(error, sa%peak_end_speed == sb%peak_end_speed .and. sa%peak_end_speed_time == sb%peak_end_speed_time &
                 .and. sa%min_fixed_end_tension == sb%min_fixed_end_tension .and. &
                 sa%front_arrival_time == sb%front_arrival_time .and. sa%energy_drift == sb%energy_drift .and. &
                 sa%dissipated == sb%dissipated .and. sa%time_reached == sb%time_reached .and. &
                 sa%dt_used == sb%dt_used .and. sa%courant_used == sb%courant_used .and. &
                 sa%max_turning_angle == sb%max_turning_angle .and. sa%min_strain == sb%min_strain .and. &
                 sa%max_strain == sb%max_strain .and. sa%steps == sb%steps .and. &
                 sa%rejected_steps == sb%rejected_steps .and. sa%newton_iterations == sb%newton_iterations .and. &
                 sa%max_newton_iterations == sb%max_newton_iterations .and. sa%factorisations == sb%factorisations &
                 .and. sa%warnings == sb%warnings, what//': the summary differs')
      if (allocated(error)) return
      do j = 1, size(sa%ends)
         call check(error, sa%ends(j)%peak_speed == sb%ends(j)%peak_speed .and. &
                    sa%ends(j)%min_tension == sb%ends(j)%min_tension .and. &
                    sa%ends(j)%max_tension == sb%ends(j)%max_tension .and. &
                    sa%ends(j)%front_arrival_time == sb%ends(j)%front_arrival_time, &
                    what//': the summary of end '//str(j)//' differs')
         if (allocated(error)) return
      end do
   end subroutine same_run

   !> Checkpoints that must not be resumed: missing, truncated, with a byte of
   !> their data changed, with their header changed, written by another
   !> version, written for another namelist. Each is refused as bad input
   !> with a message that says which.
   subroutine test_refusals(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim, other
      type(recorder) :: store
      type(case_config) :: c
      type(checkpoint_file) :: file
      character(:), allocatable :: good, fingerprint
      integer(hid_t) :: handle, dset
      integer(hsize_t) :: offset
      integer :: hdferr
      logical :: ok
      c = paper_scene()
      fingerprint = config_text(c, fingerprint=.true.)
      call checkpointed(c, sim, 20, error)
      if (allocated(error)) return
      call sim%run(store, error)
      if (allocated(error)) return
      good = read_bytes(path)
      call check(error, len(good) > 1000, 'no checkpoint written')
      if (allocated(error)) return

      call refused('a missing checkpoint', 'build/no_such.ckpt', fingerprint, 'cannot be read', error)
      if (allocated(error)) return

      call write_bytes(path, good(1:len(good)/2))
      call refused('a checkpoint cut to half its length', path, fingerprint, 'cannot be read', error)
      if (allocated(error)) return

      ! One byte of the history's times (where HDF5 stored them) changed.
      call write_bytes(path, good)
      call h5open_f(hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, handle, hdferr)
      call h5dopen_f(handle, 'history/time', dset, hdferr)
      call h5dget_offset_f(dset, offset, hdferr)
      call h5dclose_f(dset, hdferr)
      call h5fclose_f(handle, hdferr)
      call check(error, hdferr == 0 .and. offset > 0, 'cannot find the history''s times in the checkpoint')
      if (allocated(error)) return
      call write_bytes(path, good(1:offset + 10)//achar(ieor(iachar(good(offset + 11:offset + 11)), 1))// &
                       good(offset + 12:))
      call refused('a checkpoint with one bit of its data flipped', path, fingerprint, &
                   'content does not match its checksum', error)
      if (allocated(error)) return

      ! The namelist attribute rewritten (as if its text had been damaged).
      call write_bytes(path, good)
      call h5fopen_f(path, H5F_ACC_RDWR_F, handle, hdferr)
      ok = .true.
      call put_text_attr(handle, 'namelist', fingerprint(1:9)//'X'//fingerprint(11:), ok)
      call h5fclose_f(handle, hdferr)
      call refused('a checkpoint whose namelist attribute was changed', path, fingerprint, &
                   'header does not match its checksum', error)
      if (allocated(error)) return

      ! Written by another version (a checkpoint of the same state, the version changed).
      call file%create(path, '0.0.1', fingerprint, 'test-run', sim%rod%t, error)
      if (allocated(error)) return
      call sim%rod%save_state(file)
      call file%commit(error)
      if (allocated(error)) return
      call refused('a checkpoint of another version', path, fingerprint, 'written by xcable 0.0.1, this is', error)
      if (allocated(error)) return

      ! For another namelist: 81 nodes instead of 61.
      call write_bytes(path, good)
      c%nodes = 81
      call refused('a checkpoint of another case (nodes)', path, config_text(c, fingerprint=.true.), &
                   'nodes = 61', error)
      if (allocated(error)) return
      ! But one that differs only in what may differ on --resume is taken.
      c%nodes = 61
      c%quiet = .true.
      c%checkpoint_interval = 30
      c%max_wall_time = 1000
      call other%prepare(c, error)
      if (allocated(error)) return
      call resumed_check(other, config_text(c, fingerprint=.true.), error)
      call remove_checkpoint(path)
      write (output_unit, '(4x,a)') 'refused: missing, truncated, a bit of data flipped, header changed, another '// &
         'version, another case; taken: another quiet, checkpoint_interval, max_wall_time'

   contains

      !> The resume must fail as bad input, the message containing expect.
      subroutine refused(what, file_path, text, expect, error)
         character(*), intent(in) :: what, file_path, text, expect
         type(error_type), allocatable, intent(out) :: error
         type(simulation) :: fresh
         type(error_type), allocatable :: resume_error
         character(:), allocatable :: run_id
         call fresh%prepare(paper_scene(), error)
         if (allocated(error)) return
         call fresh%resume(file_path, text, run_id, resume_error)
         call check(error, allocated(resume_error), what//' was resumed')
         if (allocated(error)) return
         call check(error, resume_error%stat == stat_input .and. index(resume_error%message, expect) > 0, &
                    what//': message "'//resume_error%message//'" lacks "'//expect//'"')
      end subroutine refused

      subroutine resumed_check(run, text, error)
         type(simulation), intent(inout) :: run
         character(*), intent(in) :: text
         type(error_type), allocatable, intent(out) :: error
         character(:), allocatable :: run_id
         call run%resume(path, text, run_id, error)
      end subroutine resumed_check
   end subroutine test_refusals

   !> The 3-D model: SIGTERM at snapshot k, the checkpoint, the resumed run
   !> bit for bit as the run that was not stopped (snapshots with their 3-D
   !> fields, history with the y components, ledger, summary).
   subroutine test_sigterm_3d(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      character(:), allocatable :: problem
      problem = install_termination_handler()
      call check(error, len(problem) == 0, problem)
      if (allocated(error)) return
      call case_of(fairlead3d, c, error)
      if (allocated(error)) return
      call check(error, c%model_to_run() == '3d', 'the fairlead scene does not run 3-D')
      if (allocated(error)) return
      call stopped_and_resumed('3-D fairlead in a current, SIGTERM before the break', c, 4, error, broken=.false.)
      if (allocated(error)) return
      call stopped_and_resumed('3-D fairlead in a current, SIGTERM after the break', c, 9, error, broken=.true.)
      if (allocated(error)) return
      call case_of(middle3d, c, error)
      if (allocated(error)) return
      call stopped_and_resumed('3-D break inside, SIGTERM before the break', c, 4, error, broken=.false.)
      if (allocated(error)) return
      call stopped_and_resumed('3-D break inside, SIGTERM during the ramp', c, 8, error, broken=.true.)
      if (allocated(error)) return
      call check(error, c%s_break > 0 .and. c%s_break < 60, 'the middle scene does not break inside')
      if (allocated(error)) return
      call case_of(twisted3d, c, error)
      if (allocated(error)) return
      call stopped_and_resumed('3-D twisted cable parted inside, SIGTERM during the ramp', c, 9, error, broken=.true.)
      if (allocated(error)) return
      call case_of(release3d, c, error)
      if (allocated(error)) return
      call stopped_and_resumed('3-D release off the plane, step halved', c, 8, error, halved=.true., broken=.true.)
      if (allocated(error)) return
      call case_of(release_turned, c, error)
      if (allocated(error)) return
      call stopped_and_resumed('release in a plane at an azimuth (2-D, turned back)', c, 8, error, broken=.true.)
   end subroutine test_sigterm_3d

   !> The 3-D fairlead with a checkpoint every 7 steps: the run is as without
   !> them; resumed from the last, the same end again.
   subroutine test_periodic_3d(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: reference, periodic, resumed
      type(recorder) :: whole, with_checkpoints, rest, none
      type(case_config) :: c
      integer :: kept
      call case_of(fairlead3d, c, error)
      if (allocated(error)) return
      call plain_run(c, reference, whole, error)
      if (allocated(error)) return
      call checkpointed(c, periodic, 7, error)
      if (allocated(error)) return
      call periodic%run(with_checkpoints, error)
      if (allocated(error)) return
      call same_run('3-D, a checkpoint every 7 steps', reference, periodic, whole, with_checkpoints, none, error)
      if (allocated(error)) return
      call check(error, periodic%checkpoints_written == (reference%rod%history%n - 1)/7, 'checkpoints written: '// &
                 str(periodic%checkpoints_written)//' for '//str(reference%rod%history%n)//' steps')
      if (allocated(error)) return
      call resumed_run(c, resumed, rest, error)
      if (allocated(error)) return
      kept = whole%n - rest%n
      with_checkpoints%n = kept
      with_checkpoints%n_extra = kept
      call same_run('3-D, resumed from the last of them', reference, resumed, whole, with_checkpoints, rest, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,i0,a,i0,a)') '3-D fairlead: ', periodic%checkpoints_written, &
         ' checkpoints (every 7 steps) change nothing; resumed from the last (', kept, &
         ' snapshots kept): bitwise equal'
      call remove_checkpoint(path)
   end subroutine test_periodic_3d

   !> A checkpoint resumes only with the model and scheme that wrote it: the
   !> paper's rupture checkpointed in 2-D is refused by the same case with
   !> model = '3d', and checkpointed in 3-D by the case with model = '2d';
   !> checkpointed by the rod scheme, by the case with scheme = 'box', and the
   !> other way round; the message names the models or schemes (not only the
   !> namelist line that differs).
   subroutine test_other_model(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c2, c3
      c2 = paper_scene()
      c2%model = '2d'
      c3 = c2
      c3%model = '3d'
      call written_then_refused(c2, c3, 'was written by a 2-D run, this case runs the 3-D model', error)
      if (allocated(error)) return
      call written_then_refused(c3, c2, 'was written by a 3-D run, this case runs the 2-D model', error)
      if (allocated(error)) return
      ! The other scheme: the rod's checkpoint offered to the box scheme, and the box's to the rod.
      c3 = c2
      c3%scheme = 'box'
      call written_then_refused(c2, c3, 'was written by a rod-scheme run, this case runs the box scheme', error)
      if (allocated(error)) return
      call written_then_refused(c3, c2, 'was written by a box-scheme run, this case runs the rod scheme', error)
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'a 2-D checkpoint refused by a 3-D case, a 3-D one by a 2-D case; a rod '// &
         'checkpoint by a box case, a box one by a rod case'
      call remove_checkpoint(path)

   contains

      subroutine written_then_refused(writer, reader, expect, error)
         type(case_config), intent(in) :: writer, reader
         character(*), intent(in) :: expect
         type(error_type), allocatable, intent(out) :: error
         type(simulation) :: sim, other
         type(recorder) :: store
         type(error_type), allocatable :: resume_error
         character(:), allocatable :: run_id
         call checkpointed(writer, sim, 20, error)
         if (allocated(error)) return
         call sim%run(store, error)
         if (allocated(error)) return
         call check(error, sim%checkpoints_written > 0, 'no checkpoint written by the '//sim%model//' run')
         if (allocated(error)) return
         call other%prepare(reader, error)
         if (allocated(error)) return
         call other%resume(path, config_text(reader, fingerprint=.true.), run_id, resume_error)
         call check(error, allocated(resume_error), 'a '//sim%model//' checkpoint was resumed by a '//other%model//' case')
         if (allocated(error)) return
         call check(error, resume_error%stat == stat_input .and. index(resume_error%message, expect) > 0, &
                    'message "'//resume_error%message//'" lacks "'//expect//'"')
      end subroutine written_then_refused
   end subroutine test_other_model

   !> The bytes of a file.
   function read_bytes(file_path) result(bytes)
      character(*), intent(in) :: file_path
      character(:), allocatable :: bytes
      integer :: unit, size_bytes, ios
      open (newunit=unit, file=file_path, access='stream', form='unformatted', status='old', action='read', iostat=ios)
      if (ios /= 0) then
         bytes = ''
         return
      end if
      inquire (unit=unit, size=size_bytes)
      allocate (character(len=size_bytes) :: bytes)
      read (unit, iostat=ios) bytes
      close (unit)
   end function read_bytes

   !> Write bytes as a file (replacing it).
   subroutine write_bytes(file_path, bytes)
      character(*), intent(in) :: file_path, bytes
      integer :: unit
      open (newunit=unit, file=file_path, access='stream', form='unformatted', status='replace', action='write')
      write (unit) bytes
      close (unit)
   end subroutine write_bytes
end module suite_checkpoint
