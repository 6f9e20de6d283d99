!> Runs of the benchmark: write a namelist, time the whole `xcable` process
!> (one thread; the caller repeats runs in rounds and takes the median) and
!> read back what the result file holds (summary, end histories, tension
!> snapshots).
module bench_runs
   use xcable_core_kinds, only: dp, i8
   use hdf5
   implicit none
   private
   public :: run_spec, run_result, run_case, median, paired_ratio, instruction_command, read_instructions
   public :: max_repeats

   !> Most timed runs kept per configuration.
   integer, parameter :: max_repeats = 25

   !> One configuration of the benchmark.
   type :: run_spec
      !> Stem of the namelist and result files.
      character(:), allocatable :: label
      !> Discretisation ('rod' or 'box') and the rod's mass matrix ('averaged' or 'lumped').
      character(:), allocatable :: scheme, mass_matrix
      !> Static end tension (N), breaking time and end of the run (s).
      real(dp) :: tension = 0, t_break = 0, t_end = 0
      !> Nodes and Courant number c(eps0) dt / ds.
      integer :: nodes = 0
      real(dp) :: courant = 1
      !> Time weight (0.5: the scheme's default, energy-conserving for the rod).
      real(dp) :: theta = 0.5_dp
      !> Snapshot interval (s) and fields.
      real(dp) :: interval = 0.01_dp
      character(:), allocatable :: fields
      !> Energy ledger and gnuplot text.
      logical :: energy = .false., gnuplot = .false.
      !> Newton tolerance (0: the code's default).
      real(dp) :: newton_tol = 0
      !> &numerics reuse_jacobian: -1 not given (the scheme's default), 0 .false., 1 .true.
      integer :: reuse_jacobian = -1
   end type run_spec

   !> What a run gave.
   type :: run_result
      !> Whether the result file was read.
      logical :: ok = .false.
      !> Exit code of the last run (0 complete, 1 failed, 2 bad input).
      integer :: exit_code = -1
      !> Median wall time and CPU time (user + system) of the whole process, s;
      !> the timed runs, their walls and CPU times in the order of the rounds.
      real(dp) :: wall = 0, cpu = 0
      integer :: repeats = 0
      real(dp) :: walls(max_repeats) = 0, cpus(max_repeats) = 0
      !> Simulated time reached, s; largest step taken, s; Courant number taken.
      real(dp) :: time_reached = 0, step = 0, courant_used = 0
      !> Accepted and rejected steps, Newton iterations, factorisations.
      integer :: steps = 0, rejected = 0, newton_iterations = 0, factorisations = 0
      !> Energy booked as numerical dissipation (J), largest ledger drift / initial
      !> strain energy (-1: no ledger), initial strain energy (J, 0: no ledger).
      real(dp) :: dissipated = 0, energy_drift = -1, strain_energy = 0
      !> History: time; speed of the breaking end (end b) along the cable, positive
      !> in the recoil; tension at the fixed end (end a).
      real(dp), allocatable :: time(:), end_speed(:), fixed_end_tension(:)
      !> Snapshot times and tension (nodes, snapshots).
      real(dp), allocatable :: snapshot_time(:), tension(:, :)
   end type run_result

contains

   !> Median of a small sample.
   pure real(dp) function median(x)
      !> Sample.
      real(dp), intent(in) :: x(:)
      real(dp) :: a(size(x)), v
      integer :: i, j, n
      median = 0
      n = size(x)
      if (n == 0) return
      a = x
      do i = 2, n
         v = a(i)
         j = i - 1
         do while (j >= 1)
            if (a(j) <= v) exit
            a(j + 1) = a(j)
            j = j - 1
         end do
         a(j + 1) = v
      end do
      if (mod(n, 2) == 1) then
         median = a((n + 1)/2)
      else
         median = 0.5_dp*(a(n/2) + a(n/2 + 1))
      end if
   end function median

   !> Median over the common rounds of the ratio of two runs' times (each round
   !> ran both, close together in time, so the state of the machine cancels).
   pure real(dp) function paired_ratio(numerator, denominator, cpu) result(ratio)
      !> Runs whose times are divided.
      type(run_result), intent(in) :: numerator, denominator
      !> Whether CPU times (instead of wall times) are divided.
      logical, intent(in) :: cpu
      integer :: m
      m = min(numerator%repeats, denominator%repeats)
      ratio = 0
      if (m == 0) return
      if (cpu) then
         if (any(denominator%cpus(1:m) <= 0)) return
         ratio = median(numerator%cpus(1:m)/denominator%cpus(1:m))
      else
         ratio = median(numerator%walls(1:m)/denominator%walls(1:m))
      end if
   end function paired_ratio

   !> Write the namelist of a run (first call) and run the executable once:
   !> wall time of the whole process from outside, CPU time from bash's `time`.
   subroutine run_case(spec, exe, dir, res)
      !> Configuration.
      type(run_spec), intent(in) :: spec
      !> Path of the xcable executable.
      character(*), intent(in) :: exe
      !> Work directory for namelists and result files.
      character(*), intent(in) :: dir
      !> Results: exit_code, walls and cpus (one more), and what the result file holds.
      type(run_result), intent(inout) :: res
      character(:), allocatable :: nml, h5, cmd, timing
      integer :: exitstat, cmdstat, unit, ios
      integer(i8) :: c0, c1, rate
      real(dp) :: times(3)
      nml = dir//'/'//spec%label//'.nml'
      h5 = dir//'/'//spec%label//'.h5'
      timing = dir//'/'//spec%label//'.time'
      if (res%repeats == 0) call write_namelist(spec, nml, h5)
      ! bash reports the child's user and system time (getrusage, 1 ms) and
      ! exits with the status of the timed command.
      cmd = 'OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 exec bash -c ''TIMEFORMAT="%3R %3U %3S"; { time '//exe// &
            ' '//nml//' > '//dir//'/'//spec%label//'.log 2>&1 ; } 2> '//timing//''''
      call system_clock(c0, rate)
      call execute_command_line(cmd, exitstat=exitstat, cmdstat=cmdstat)
      call system_clock(c1)
      if (cmdstat /= 0) exitstat = -1
      res%exit_code = exitstat
      times = 0
      open (newunit=unit, file=timing, status='old', action='read', iostat=ios)
      if (ios == 0) then
         read (unit, *, iostat=ios) times
         close (unit)
      end if
      if (res%repeats < size(res%walls)) then
         res%repeats = res%repeats + 1
         res%walls(res%repeats) = real(c1 - c0, dp)/rate
         res%cpus(res%repeats) = times(2) + times(3)
      end if
      res%wall = median(res%walls(1:res%repeats))
      res%cpu = median(res%cpus(1:res%repeats))
      if (res%repeats == 1 .and. exitstat >= 0 .and. exitstat /= 2) call read_result(h5, res)
   end subroutine run_case

   !> The shell command that counts the instructions of a run with valgrind
   !> --tool=callgrind (its log: <label>.callgrind in the work directory). The
   !> count does not change from one run to the next, unlike the wall time on a
   !> shared machine.
   function instruction_command(spec, exe, dir) result(cmd)
      !> Configuration (its namelist was written by run_case).
      type(run_spec), intent(in) :: spec
      !> Path of the xcable executable.
      character(*), intent(in) :: exe
      !> Work directory.
      character(*), intent(in) :: dir
      character(:), allocatable :: cmd
      cmd = 'OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=/dev/null '// &
            exe//' '//dir//'/'//spec%label//'.nml > /dev/null 2> '//dir//'/'//spec%label//'.callgrind'
   end function instruction_command

   !> Instructions of a run from its callgrind log (0: no log, valgrind missing or failed).
   real(dp) function read_instructions(spec, dir) result(count)
      !> Configuration.
      type(run_spec), intent(in) :: spec
      !> Work directory.
      character(*), intent(in) :: dir
      character(len=256) :: line
      integer :: unit, ios, k
      count = 0
      open (newunit=unit, file=dir//'/'//spec%label//'.callgrind', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         k = index(line, 'Collected :')
         if (k > 0) then
            read (line(k + 11:), *, iostat=ios) count
            if (ios /= 0) count = 0
            exit
         end if
      end do
      close (unit)
   end function read_instructions

   !> The namelist of a configuration (groups left out take the paper's values).
   subroutine write_namelist(spec, nml, h5)
      !> Configuration.
      type(run_spec), intent(in) :: spec
      !> Paths of the namelist and of the result file.
      character(*), intent(in) :: nml, h5
      integer :: unit
      open (newunit=unit, file=nml, status='replace', action='write')
      write (unit, '(a)') '! written by the benchmark (example/bench)'
      write (unit, '(a,es23.16,a)') '&static tension = ', spec%tension, ' /'
      write (unit, '(a,es23.16,a)') '&rupture t_break = ', spec%t_break, ' /'
      write (unit, '(5a,i0,a,es23.16,a,es23.16,a,f6.3)', advance='no') "&numerics scheme = '", spec%scheme, &
         "', mass_matrix = '", spec%mass_matrix, "', nodes = ", spec%nodes, ', courant = ', spec%courant, &
         ', t_end = ', spec%t_end, ', theta = ', spec%theta
      if (spec%newton_tol > 0) write (unit, '(a,es10.3)', advance='no') ', newton_tol = ', spec%newton_tol
      if (spec%reuse_jacobian >= 0) write (unit, '(2a)', advance='no') ', reuse_jacobian = ', &
         trim(merge('.true. ', '.false.', spec%reuse_jacobian == 1))
      write (unit, '(a)') ' /'
      write (unit, '(5a,es23.16,5a)') "&output file = '", h5, "', fields = '", spec%fields, "', interval = ", &
         spec%interval, ', quiet = .true., energy = ', trim(merge('.true. ', '.false.', spec%energy)), &
         ', gnuplot = ', trim(merge('.true. ', '.false.', spec%gnuplot)), ' /'
      close (unit)
   end subroutine write_namelist

   !> Read summary, end histories and tension snapshots of a result file.
   subroutine read_result(path, res)
      !> Result file.
      character(*), intent(in) :: path
      !> Filled with what the file holds; ok when the history was read.
      type(run_result), intent(inout) :: res
      integer(hid_t) :: file, group
      integer :: hdferr
      logical :: exists
      real(dp), allocatable :: xa(:), za(:), xb(:), zb(:), vx(:), vz(:), strain(:)
      real(dp) :: chord(2)
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      if (hdferr /= 0) return
      call h5lexists_f(file, 'summary', exists, hdferr)
      if (exists) then
         call h5gopen_f(file, 'summary', group, hdferr)
         res%time_reached = attr_real(group, 'time_reached')
         res%step = attr_real(group, 'dt_used')
         res%courant_used = attr_real(group, 'courant_used')
         res%dissipated = attr_real(group, 'dissipated')
         res%energy_drift = attr_real(group, 'energy_drift')
         res%steps = attr_int(group, 'steps')
         res%rejected = attr_int(group, 'rejected_steps')
         res%newton_iterations = attr_int(group, 'newton_iterations')
         res%factorisations = attr_int(group, 'factorisations')
         call h5gclose_f(group, hdferr)
      end if
      call h5lexists_f(file, 'history', exists, hdferr)
      if (exists) then
         call read_vector(file, 'history/time', res%time)
         call read_vector(file, 'history/end_a/tension', res%fixed_end_tension)
         call read_vector(file, 'history/end_a/x', xa)
         call read_vector(file, 'history/end_a/z', za)
         call read_vector(file, 'history/end_b/x', xb)
         call read_vector(file, 'history/end_b/z', zb)
         call read_vector(file, 'history/end_b/vx', vx)
         call read_vector(file, 'history/end_b/vz', vz)
         call read_vector(file, 'history/energy/strain', strain)
         if (size(strain) > 0) res%strain_energy = strain(1)
         res%ok = size(res%time) > 1 .and. size(res%fixed_end_tension) == size(res%time) .and. &
                  size(vx) == size(res%time) .and. size(vz) == size(res%time) .and. size(xa) > 0 .and. size(xb) > 0
         if (res%ok) then
            ! Along the cable: the direction from end a to end b at t = 0; the
            ! recoil runs against it, so the speed is minus the projection.
            chord = [xb(1) - xa(1), zb(1) - za(1)]
            chord = chord/norm2(chord)
            res%end_speed = -(vx*chord(1) + vz*chord(2))
         end if
      end if
      call read_vector(file, 'time', res%snapshot_time)
      call h5lexists_f(file, 'tension', exists, hdferr)
      if (exists) call read_matrix(file, 'tension', res%tension)
      call h5fclose_f(file, hdferr)
   end subroutine read_result

   !> A real attribute (0 if absent).
   real(dp) function attr_real(loc, name) result(val)
      !> Group that holds it.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      integer(hid_t) :: attr
      integer :: hdferr
      val = 0
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) return
      call h5aread_f(attr, H5T_NATIVE_DOUBLE, val, [1_hsize_t], hdferr)
      call h5aclose_f(attr, hdferr)
   end function attr_real

   !> An integer attribute (0 if absent).
   integer function attr_int(loc, name) result(val)
      !> Group that holds it.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      integer(hid_t) :: attr
      integer :: hdferr
      val = 0
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) return
      call h5aread_f(attr, H5T_NATIVE_INTEGER, val, [1_hsize_t], hdferr)
      call h5aclose_f(attr, hdferr)
   end function attr_int

   !> A 1-D real dataset (empty if absent).
   subroutine read_vector(loc, name, v)
      !> File or group that holds it.
      integer(hid_t), intent(in) :: loc
      !> Dataset path below loc.
      character(*), intent(in) :: name
      !> Its values.
      real(dp), allocatable, intent(out) :: v(:)
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1), maxdims(1)
      integer :: hdferr
      logical :: exists
      allocate (v(0))
      call h5lexists_f(loc, name, exists, hdferr)
      if (hdferr /= 0 .or. .not. exists) return
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) return
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
      call h5sclose_f(space, hdferr)
      deallocate (v)
      allocate (v(dims(1)))
      if (dims(1) > 0) call h5dread_f(dset, H5T_NATIVE_DOUBLE, v, dims, hdferr)
      call h5dclose_f(dset, hdferr)
   end subroutine read_vector

   !> A 2-D real dataset (empty if absent).
   subroutine read_matrix(loc, name, a)
      !> File or group that holds it.
      integer(hid_t), intent(in) :: loc
      !> Dataset name.
      character(*), intent(in) :: name
      !> Its values (nodes, snapshots).
      real(dp), allocatable, intent(out) :: a(:, :)
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(2), maxdims(2)
      integer :: hdferr
      allocate (a(0, 0))
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) return
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
      call h5sclose_f(space, hdferr)
      deallocate (a)
      allocate (a(dims(1), dims(2)))
      if (dims(2) > 0) call h5dread_f(dset, H5T_NATIVE_DOUBLE, a, dims, hdferr)
      call h5dclose_f(dset, hdferr)
   end subroutine read_matrix
end module bench_runs
