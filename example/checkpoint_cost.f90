!> checkpoint_cost: what checkpoints cost a rod run (docs/measurements/benchmark.md,
!> "Cost of checkpoints"; bench/checkpoint_cost.sh runs it).
!>
!>   checkpoint_cost CASE.nml [REPS] [MODE]
!>
!> Without MODE it times, REPS times each (median; 5 by default), the
!> dynamics of the case (the statics excluded):
!>   plain     sim%run without checkpoints (the library's path);
!>   off       with checkpoints enabled as xcable enables them when
!>             checkpoint_interval = 0 (a SIGTERM handler check per step);
!>   every k   a checkpoint every k accepted steps, for a few k;
!> and one checkpoint (create, state, fsync'd rename) of the state at t = 0
!> and of the state at t_end, whose history holds every step: the cost of a
!> checkpoint grows with the history it carries. It prints a Markdown table
!> with wall and CPU times (the wall time includes the fsync).
!>
!> With MODE it runs one mode once and prints nothing, for counting
!> instructions with valgrind --tool=callgrind: plain, off, or text (plain
!> after making the namelist fingerprint that off makes, to tell the
!> one-time cost of the fingerprint from the per-step cost of the checks).
program checkpoint_cost
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type
   use xcable_core_strings, only: str
   use xcable_io_input, only: case_config, read_config, config_text
   use xcable_driver_simulation, only: simulation
   use xcable_driver_stepping, only: start_dynamics
   use xcable_io_checkpoint, only: checkpoint_file, remove_checkpoint
   use xcable_core_version, only: code_version
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   implicit none
   character(len=*), parameter :: path = 'build/checkpoint_cost.ckpt'
   integer, parameter :: every(3) = [200, 50, 10]
   type(case_config) :: config
   type(error_type), allocatable :: error
   character(len=1024) :: arg
   character(:), allocatable :: case_path, mode
   integer :: reps, k, n_steps, written
   real(dp) :: wall(2), cpu(2), plain(2), off(2), t_first(2), t_last(2), size_first, size_last
   real(dp), allocatable :: samples(:, :)

   if (command_argument_count() < 1) then
      write (error_unit, '(a)') 'usage: checkpoint_cost CASE.nml [REPS] [plain|off|text]'
      stop 2
   end if
   call get_command_argument(1, arg)
   case_path = trim(arg)
   reps = 5
   if (command_argument_count() >= 2) then
      call get_command_argument(2, arg)
      read (arg, *) reps
   end if
   mode = ''
   if (command_argument_count() >= 3) then
      call get_command_argument(3, arg)
      mode = trim(arg)
   end if
   call read_config(case_path, config, error)
   call stop_on(error)
   config%quiet = .true.

   if (len(mode) > 0) then
      call timed_run(mode, 0, wall, cpu, n_steps, written)
      stop
   end if

   allocate (samples(2, reps))
   plain = median_of('plain', 0)
   off = median_of('off', 0)
   write (output_unit, '(a)') '| run | checkpoints | wall, s (median of '//str(reps)//') | CPU, s | wall / plain |'
   write (output_unit, '(a)') '|---|---|---|---|---|'
   call row('no checkpoints (library path)', 0, plain)
   call row('checkpoint_interval = 0 (xcable''s default)', 0, off)
   do k = 1, size(every)
      wall = median_of('every', every(k))
      call row('a checkpoint every '//str(every(k))//' steps', written, wall)
   end do
   call single_checkpoints(t_first, t_last, size_first, size_last)
   write (output_unit, '(a)') ''
   write (output_unit, '(a)') '| one checkpoint | history records | file, kB | wall, ms (median) | CPU, ms |'
   write (output_unit, '(a)') '|---|---|---|---|---|'
   write (output_unit, '(a)') '| of the state at t = 0 | 1 | '//fixed(size_first/1024, 1)//' | '// &
      fixed(1000*t_first(1), 2)//' | '//fixed(1000*t_first(2), 2)//' |'
   write (output_unit, '(a)') '| of the state at t_end | '//str(n_steps + 1)//' | '//fixed(size_last/1024, 1)//' | '// &
      fixed(1000*t_last(1), 2)//' | '//fixed(1000*t_last(2), 2)//' |'
   call remove_checkpoint(path)

contains

   !> Median wall and CPU time of reps runs of a mode.
   function median_of(run_mode, k) result(m)
      character(*), intent(in) :: run_mode
      integer, intent(in) :: k
      real(dp) :: m(2)
      integer :: i
      do i = 1, reps
         call timed_run(run_mode, k, wall, cpu, n_steps, written)
         samples(:, i) = [wall(1), cpu(1)]
      end do
      m = [median(samples(1, :)), median(samples(2, :))]
   end function median_of

   !> Prepare the case and time its dynamics in one mode.
   subroutine timed_run(run_mode, k, wall, cpu, steps, checkpoints)
      character(*), intent(in) :: run_mode
      integer, intent(in) :: k
      real(dp), intent(out) :: wall(2), cpu(2)
      integer, intent(out) :: steps, checkpoints
      type(simulation) :: sim
      integer(i8) :: c0, c1, rate
      real(dp) :: p0, p1
      character(:), allocatable :: fingerprint
      call sim%prepare(config, error)
      call stop_on(error)
      select case (run_mode)
      case ('text')
         fingerprint = config_text(config, fingerprint=.true.)
         if (len(fingerprint) == 0) stop 1
      case ('off')
         call sim%enable_checkpoints(path, config_text(config, fingerprint=.true.), 'cost', 0.0_dp, .true.)
      case ('every')
         call sim%enable_checkpoints(path, config_text(config, fingerprint=.true.), 'cost', 0.0_dp, .true., &
                                     every_steps=k)
      end select
      call system_clock(c0, rate)
      call cpu_time(p0)
      call sim%run(error=error)
      call cpu_time(p1)
      call system_clock(c1)
      call stop_on(error)
      wall = real(c1 - c0, dp)/rate
      cpu = p1 - p0
      steps = sim%rod%history%n
      checkpoints = sim%checkpoints_written
      call remove_checkpoint(path)
   end subroutine timed_run

   !> Time single checkpoints of the state at t = 0 and at t_end.
   subroutine single_checkpoints(first, last, bytes_first, bytes_last)
      real(dp), intent(out) :: first(2), last(2), bytes_first, bytes_last
      type(simulation) :: sim
      call sim%prepare(config, error)
      call stop_on(error)
      call start_dynamics(sim%rod, sim%planar, error=error)
      call stop_on(error)
      call time_saves(sim, first, bytes_first)
      call sim%prepare(config, error)
      call stop_on(error)
      call sim%run(error=error)
      call stop_on(error)
      call time_saves(sim, last, bytes_last)
   end subroutine single_checkpoints

   !> Median wall and CPU time of reps checkpoints of the run's current state, and the file's size.
   subroutine time_saves(sim, t, bytes)
      type(simulation), intent(inout) :: sim
      real(dp), intent(out) :: t(2), bytes
      type(checkpoint_file) :: file
      integer(i8) :: c0, c1, rate
      real(dp) :: p0, p1
      integer :: i, file_size
      do i = 1, reps
         call system_clock(c0, rate)
         call cpu_time(p0)
         call file%create(path, code_version, 'cost', 'cost', sim%rod%t, error)
         call stop_on(error)
         call sim%rod%save_state(file)
         call file%commit(error)
         call stop_on(error)
         call cpu_time(p1)
         call system_clock(c1)
         samples(:, i) = [real(c1 - c0, dp)/rate, p1 - p0]
      end do
      t = [median(samples(1, :)), median(samples(2, :))]
      inquire (file=path, size=file_size)
      bytes = file_size
   end subroutine time_saves

   subroutine row(what, checkpoints, m)
      character(*), intent(in) :: what
      integer, intent(in) :: checkpoints
      real(dp), intent(in) :: m(2)
      write (output_unit, '(a)') '| '//what//' | '//str(checkpoints)//' | '//fixed(m(1), 3)//' | '//fixed(m(2), 3)// &
         ' | '//fixed(m(1)/plain(1), 3)//' |'
   end subroutine row

   real(dp) function median(x)
      real(dp), intent(in) :: x(:)
      real(dp) :: y(size(x)), swap
      integer :: i, j
      y = x
      do i = 2, size(y)
         do j = i, 2, -1
            if (y(j - 1) <= y(j)) exit
            swap = y(j); y(j) = y(j - 1); y(j - 1) = swap
         end do
      end do
      median = merge(y((size(y) + 1)/2), 0.5_dp*(y(size(y)/2) + y(size(y)/2 + 1)), mod(size(y), 2) == 1)
   end function median

   function fixed(x, digits) result(text)
      real(dp), intent(in) :: x
      integer, intent(in) :: digits
      character(:), allocatable :: text
      character(len=32) :: buffer
      write (buffer, '(f0.'//str(digits)//')') x
      text = trim(buffer)
      if (text(1:1) == '.') text = '0'//text
   end function fixed

   subroutine stop_on(e)
      type(error_type), allocatable, intent(in) :: e
      if (.not. allocated(e)) return
      write (error_unit, '(a)') 'checkpoint_cost: '//e%message
      stop 1
   end subroutine stop_on
end program checkpoint_cost
