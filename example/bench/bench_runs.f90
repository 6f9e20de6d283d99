!> Runs of the benchmark: write a namelist, time the whole `xcable` process
!> (one thread; the caller repeats runs in rounds and takes the median) and
!> read back what the result file holds (summary, history, tension snapshots).
module bench_runs
   use xcable_kinds, only: dp, i8
   use hdf5
   implicit none
   private
   public :: run_spec, run_result, run_case, median, count_instructions

   !> One configuration of the benchmark.
   type :: run_spec
      !> Stem of the namelist and result files.
      character(:), allocatable :: label
      !> Static end tension (N), breaking time and end of the run (s).
      real(dp) :: tension = 0, t_break = 0, t_end = 0
      !> Nodes and Courant number c(eps0) dt / ds.
      integer :: nodes = 0
      real(dp) :: courant = 1
      !> Snapshot interval (s) and fields.
      real(dp) :: interval = 0.01_dp
      character(:), allocatable :: fields
      !> Energy ledger and gnuplot text.
      logical :: energy = .false., gnuplot = .false.
      !> Newton tolerance (0: the code's default).
      real(dp) :: newton_tol = 0
   end type run_spec

   !> What a run gave.
   type :: run_result
      !> Whether the result file was read.
      logical :: ok = .false.
      !> Exit code of the last run (0 complete, 1 failed, 2 bad input).
      integer :: exit_code = -1
      !> Median wall time of the whole process, s, the timed runs and their walls.
      real(dp) :: wall = 0
      integer :: repeats = 0
      real(dp) :: walls(25) = 0
      !> Simulated time reached, s; largest step taken, s.
      real(dp) :: time_reached = 0, step = 0
      !> Accepted and rejected steps, Newton iterations, factorisations.
      integer :: steps = 0, rejected = 0, newton_iterations = 0, factorisations = 0
      !> History: time, breaking-end velocity, fixed-end tension.
      real(dp), allocatable :: time(:), end_velocity(:), fixed_end_tension(:)
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
      a = x
      n = size(a)
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

   !> Write the namelist of a run and run the executable once; wall time of the whole process.
   subroutine run_case(spec, exe, dir, res)
      !> Configuration.
      type(run_spec), intent(in) :: spec
      !> Path of the xcable executable.
      character(*), intent(in) :: exe
      !> Work directory for namelists and result files.
      character(*), intent(in) :: dir
      !> Results: exit_code, walls (one more), and what the result file holds.
      type(run_result), intent(inout) :: res
      character(:), allocatable :: nml, h5, cmd
      integer :: exitstat, cmdstat
      integer(i8) :: c0, c1, rate
      nml = dir//'/'//spec%label//'.nml'
      h5 = dir//'/'//spec%label//'.h5'
      if (res%repeats == 0) call write_namelist(spec, nml, h5)
      cmd = 'OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 exec '//exe//' '//nml//' > '//dir//'/'//spec%label//'.log 2>&1'
      call system_clock(c0, rate)
      call execute_command_line(cmd, exitstat=exitstat, cmdstat=cmdstat)
      call system_clock(c1)
      if (cmdstat /= 0) exitstat = -1
      res%exit_code = exitstat
      if (res%repeats < size(res%walls)) then
         res%repeats = res%repeats + 1
         res%walls(res%repeats) = real(c1 - c0, dp)/rate
      end if
      res%wall = median(res%walls(1:res%repeats))
      if (res%repeats == 1 .and. exitstat >= 0 .and. exitstat /= 2) call read_result(h5, res)
   end subroutine run_case

   !> Instructions executed by the whole process (valgrind --tool=callgrind; 0 if
   !> valgrind is missing): a count that, unlike the wall time on a shared
   !> machine, does not change from one run to the next.
   real(dp) function count_instructions(spec, exe, dir) result(count)
      !> Configuration (its namelist was written by run_case).
      type(run_spec), intent(in) :: spec
      !> Path of the xcable executable.
      character(*), intent(in) :: exe
      !> Work directory.
      character(*), intent(in) :: dir
      character(:), allocatable :: log
      character(len=256) :: line
      integer :: unit, ios, exitstat, k
      count = 0
      log = dir//'/'//spec%label//'.callgrind'
      call execute_command_line('valgrind --tool=callgrind --callgrind-out-file=/dev/null '//exe//' '//dir//'/'// &
                                spec%label//'.nml > /dev/null 2> '//log, exitstat=exitstat)
      open (newunit=unit, file=log, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         k = index(line, 'Collected :')
         if (k > 0) then
            read (line(k + 11:), *, iostat=ios) count
            exit
         end if
      end do
      close (unit)
   end function count_instructions

   !> The namelist of a configuration (groups left out take the paper's values).
   subroutine write_namelist(spec, nml, h5)
      type(run_spec), intent(in) :: spec
      character(*), intent(in) :: nml, h5
      integer :: unit
      open (newunit=unit, file=nml, status='replace', action='write')
      write (unit, '(a)') '! written by the benchmark (example/bench)'
      write (unit, '(a,es23.16,a)') '&static tension = ', spec%tension, ' /'
      write (unit, '(a,es23.16,a)') '&rupture t_break = ', spec%t_break, ' /'
      if (spec%newton_tol > 0) then
         write (unit, '(a,i0,a,es23.16,a,es23.16,a,es10.3,a)') '&numerics nodes = ', spec%nodes, ', courant = ', &
            spec%courant, ', t_end = ', spec%t_end, ', newton_tol = ', spec%newton_tol, ' /'
      else
         write (unit, '(a,i0,a,es23.16,a,es23.16,a)') '&numerics nodes = ', spec%nodes, ', courant = ', spec%courant, &
            ', t_end = ', spec%t_end, ' /'
      end if
      write (unit, '(5a,es23.16,5a)') "&output file = '", h5, "', fields = '", spec%fields, "', interval = ", &
         spec%interval, ', quiet = .true., energy = ', trim(merge('.true. ', '.false.', spec%energy)), &
         ', gnuplot = ', trim(merge('.true. ', '.false.', spec%gnuplot)), ' /'
      close (unit)
   end subroutine write_namelist

   !> Read summary, history and tension snapshots of a result file.
   subroutine read_result(path, res)
      character(*), intent(in) :: path
      type(run_result), intent(inout) :: res
      integer(hid_t) :: file, group
      integer :: hdferr
      logical :: exists
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      if (hdferr /= 0) return
      call h5lexists_f(file, 'summary', exists, hdferr)
      if (exists) then
         call h5gopen_f(file, 'summary', group, hdferr)
         res%time_reached = attr_real(group, 'time_reached')
         res%steps = attr_int(group, 'steps')
         res%rejected = attr_int(group, 'rejected_steps')
         res%newton_iterations = attr_int(group, 'newton_iterations')
         res%factorisations = attr_int(group, 'factorisations')
         call h5gclose_f(group, hdferr)
      end if
      call h5lexists_f(file, 'history', exists, hdferr)
      if (exists) then
         call h5gopen_f(file, 'history', group, hdferr)
         call read_vector(group, 'time', res%time)
         call read_vector(group, 'end_velocity', res%end_velocity)
         call read_vector(group, 'fixed_end_tension', res%fixed_end_tension)
         call h5gclose_f(group, hdferr)
         if (size(res%time) > 1) res%step = maxval(res%time(2:) - res%time(:size(res%time) - 1))
         res%ok = .true.
      end if
      call read_vector(file, 'time', res%snapshot_time)
      call h5lexists_f(file, 'tension', exists, hdferr)
      if (exists) call read_matrix(file, 'tension', res%tension)
      call h5fclose_f(file, hdferr)
   end subroutine read_result

   real(dp) function attr_real(loc, name) result(val)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      integer(hid_t) :: attr
      integer :: hdferr
      val = 0
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) return
      call h5aread_f(attr, H5T_NATIVE_DOUBLE, val, [1_hsize_t], hdferr)
      call h5aclose_f(attr, hdferr)
   end function attr_real

   integer function attr_int(loc, name) result(val)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      integer(hid_t) :: attr
      integer :: hdferr
      val = 0
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) return
      call h5aread_f(attr, H5T_NATIVE_INTEGER, val, [1_hsize_t], hdferr)
      call h5aclose_f(attr, hdferr)
   end function attr_int

   subroutine read_vector(loc, name, v)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      real(dp), allocatable, intent(out) :: v(:)
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1), maxdims(1)
      integer :: hdferr
      allocate (v(0))
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

   subroutine read_matrix(loc, name, a)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
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
