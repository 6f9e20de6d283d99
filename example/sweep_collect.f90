!> sweep_collect: one summary of every result of a sweep made by batch/sweep-generate.
!>
!>   sweep_collect OUTDIR          (usually through batch/sweep-collect OUTDIR)
!>
!> Reads OUTDIR/manifest.tsv (task index and swept values), OUTDIR/sweep.env
!> (the width of the task names) and each OUTDIR/results/NNNN.h5, and writes
!> OUTDIR/summary.csv and OUTDIR/summary.h5 with one row per task: the swept
!> values, the status and the /summary figures of the run. Every task of the
!> manifest is a row: status 'complete', 'failed' or 'interrupted' (from the
!> file; interrupted: stopped by SIGTERM with a checkpoint, which
!> sweep-submit/sweep-local --failed-only resume), 'running' (a run still
!> going, or killed), 'missing' (no result file: not run yet, or
!> refused by xcable as bad input; its log says which) or 'unreadable' (a file
!> that HDF5 cannot open, or without a status). Figures a file does not hold
!> are NaN (reals) or -1 (counts).
!>
!> summary.h5 layout: one 1-D dataset per column (/task, /status, /peak_end_speed,
!> ..., /warnings, /failure_reason), each real one with a 'units' attribute; /swept/<group%variable>
!> holds the swept values, as reals when they are all numbers and as strings
!> otherwise; root attributes sweep, cases and the count of each status.
!>
!> Exit codes: 0 written (whatever the statuses); 1 a summary file cannot be
!> written; 2 not a sweep directory or a malformed manifest.
program sweep_collect
   use xcable_core_kinds, only: dp
   use hdf5
   use xcable_io_hdf5_put, only: put_real_vector, put_int_vector, put_text_vector, put_int_attr, put_text_attr, &
                             get_text_attr
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   implicit none

   !> Real figures: attributes of /summary, then failure_time of the root.
   character(len=*), parameter :: real_names(11) = [character(len=26) :: 'peak_end_speed', &
      'peak_end_speed_time', 'min_fixed_end_tension', 'min_fixed_end_tension_time', 'front_arrival_time', &
      'energy_drift', 'time_reached', 'wall_time', 'dt_used', 'courant_used', 'failure_time']
   !> Units of the real figures.
   character(len=*), parameter :: real_units(11) = [character(len=4) :: 'm/s', 's', 'N', 's', 's', '-', 's', 's', &
                                                                         's', '-', 's']
   !> Integer figures: attributes of /summary.
   character(len=*), parameter :: int_names(5) = [character(len=21) :: 'steps', 'rejected_steps', &
      'newton_iterations', 'max_newton_iterations', 'factorisations']
   !> Statuses counted in the summary.
   character(len=*), parameter :: status_names(6) = [character(len=11) :: 'complete', 'failed', 'interrupted', &
      'running', 'missing', 'unreadable']
   !> Longest manifest line, swept value and failure reason kept.
   integer, parameter :: line_len = 8192, value_len = 256, reason_len = 1024

   !> What one task's result holds.
   type :: task_result
      !> Task index.
      integer :: task = -1
      !> complete, failed, interrupted, running, missing or unreadable.
      character(len=16) :: status = 'missing'
      !> Why the run failed ('' unless failed).
      character(len=reason_len) :: failure_reason = ''
      !> The run's warnings, separated by '; ' ('' : none).
      character(len=reason_len) :: warnings = ''
      !> Values of real_names (NaN when absent).
      real(dp) :: reals(size(real_names))
      !> Values of int_names (-1 when absent).
      integer :: ints(size(int_names)) = -1
   end type task_result

   character(len=4096) :: arg
   character(:), allocatable :: outdir, message
   character(len=value_len), allocatable :: swept_names(:), swept_values(:, :)
   type(task_result), allocatable :: results(:)
   integer :: width, ntasks, i, hdferr, counts(size(status_names))
   logical :: ok

   if (command_argument_count() /= 1) then
      write (error_unit, '(a)') 'usage: sweep_collect OUTDIR   (a sweep directory made by batch/sweep-generate)'
      stop 2, quiet=.true.
   end if
   call get_command_argument(1, arg)
   if (trim(arg) == '-h' .or. trim(arg) == '--help') then
      write (output_unit, '(a)') 'usage: sweep_collect OUTDIR: writes OUTDIR/summary.csv and OUTDIR/summary.h5'
      stop
   end if
   outdir = trim(arg)
   do while (len(outdir) > 1 .and. outdir(len(outdir):) == '/')
      outdir = outdir(:len(outdir) - 1)
   end do

   call read_width(outdir//'/sweep.env', width, message)
   if (allocated(message)) call fail(2, message)
   call read_manifest(outdir//'/manifest.tsv', swept_names, swept_values, results, message)
   if (allocated(message)) call fail(2, message)
   ntasks = size(results)

   call h5open_f(hdferr)
   if (hdferr /= 0) call fail(1, 'cannot initialise the HDF5 library')
   ! A missing or damaged file is a status here, not an error: keep HDF5 quiet.
   call h5eset_auto_f(0, hdferr)
   do i = 1, ntasks
      call read_result(outdir//'/results/'//task_name(results(i)%task, width)//'.h5', results(i))
   end do

   do i = 1, size(status_names)
      counts(i) = count(results%status == status_names(i))
   end do
   call write_csv(outdir//'/summary.csv', swept_names, swept_values, results, ok)
   if (.not. ok) call fail(1, outdir//'/summary.csv: cannot be written')
   call write_h5(outdir//'/summary.h5', outdir, swept_names, swept_values, results, counts, ok)
   if (.not. ok) call fail(1, outdir//'/summary.h5: cannot be written')
   call h5close_f(hdferr)

   write (output_unit, '(a,i0,a,6(i0,1x,a,:,", "))') 'sweep_collect: ', ntasks, ' tasks: ', &
      (counts(i), trim(status_names(i)), i=1, size(status_names))
   write (output_unit, '(a)') 'sweep_collect: wrote '//outdir//'/summary.csv and '//outdir//'/summary.h5'

contains

   !> One line on stderr and the exit code.
   subroutine fail(code, text)
      !> Exit code.
      integer, intent(in) :: code
      !> Message.
      character(*), intent(in) :: text
      write (error_unit, '(a)') 'sweep_collect: '//text
      select case (code)
      case (1)
         stop 1, quiet=.true.
      case default
         stop 2, quiet=.true.
      end select
   end subroutine fail

   !> Zero-padded name of a task's files.
   function task_name(task, width) result(name)
      !> Task index.
      integer, intent(in) :: task
      !> Number of digits.
      integer, intent(in) :: width
      character(:), allocatable :: name
      character(len=32) :: buffer
      character(len=16) :: fmt
      write (fmt, '(a,i0,a,i0,a)') '(i', width, '.', width, ')'
      write (buffer, fmt) task
      name = trim(buffer)
   end function task_name

   !> SWEEP_WIDTH from sweep.env.
   subroutine read_width(path, width, message)
      !> Path of sweep.env.
      character(*), intent(in) :: path
      !> Digits of the task names.
      integer, intent(out) :: width
      !> Error message (unallocated on success).
      character(:), allocatable, intent(out) :: message
      character(len=line_len) :: line
      integer :: unit, ios
      width = -1
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         message = path//': cannot be read; not a sweep directory (make one with batch/sweep-generate)'
         return
      end if
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, 'SWEEP_WIDTH=') == 1) then
            read (line(len('SWEEP_WIDTH=') + 1:), *, iostat=ios) width
            if (ios /= 0) width = -1
         end if
      end do
      close (unit)
      if (width < 1 .or. width > 9) message = path//': no valid SWEEP_WIDTH line'
   end subroutine read_width

   !> The manifest: header (task, then the swept variables) and one row per task.
   subroutine read_manifest(path, names, values, results, message)
      !> Path of manifest.tsv.
      character(*), intent(in) :: path
      !> Swept variables (group%variable).
      character(len=value_len), allocatable, intent(out) :: names(:)
      !> Swept values as written in the manifest, [variable, task].
      character(len=value_len), allocatable, intent(out) :: values(:, :)
      !> One entry per task, with its index set.
      type(task_result), allocatable, intent(out) :: results(:)
      !> Error message (unallocated on success).
      character(:), allocatable, intent(out) :: message
      character(len=line_len) :: line
      character(len=value_len), allocatable :: fields(:)
      integer :: unit, ios, nrows, row, ios_task, lineno
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         message = path//': cannot be read; not a sweep directory (make one with batch/sweep-generate)'
         return
      end if
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) then
         message = path//': empty'
         close (unit)
         return
      end if
      call split_tabs(line, fields)
      if (trim(fields(1)) /= 'task') then
         message = path//': the header does not start with "task"'
         close (unit)
         return
      end if
      names = fields(2:)
      nrows = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (len_trim(line) > 0) nrows = nrows + 1
      end do
      allocate (values(size(names), nrows), results(nrows))
      rewind (unit)
      read (unit, '(a)') line
      row = 0
      lineno = 1
      do while (row < nrows)
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         lineno = lineno + 1
         if (len_trim(line) == 0) cycle
         row = row + 1
         call split_tabs(line, fields)
         read (fields(1), *, iostat=ios_task) results(row)%task
         if (ios_task /= 0 .or. size(fields) /= size(names) + 1) then
            write (line, '(a,i0,a,i0,a)') ': line ', lineno, ': expected a task index and ', size(names), ' values'
            message = path//trim(line)
            close (unit)
            return
         end if
         values(:, row) = fields(2:)
         results(row)%reals = ieee_value(0.0_dp, ieee_quiet_nan)
      end do
      close (unit)
      if (nrows == 0) message = path//': no task'
   end subroutine read_manifest

   !> Split a line at tabs.
   subroutine split_tabs(line, fields)
      !> Line of the manifest.
      character(*), intent(in) :: line
      !> Its fields, trimmed.
      character(len=value_len), allocatable, intent(out) :: fields(:)
      integer :: n, start, i
      n = 1
      do i = 1, len_trim(line)
         if (line(i:i) == achar(9)) n = n + 1
      end do
      allocate (fields(n))
      n = 0
      start = 1
      do i = 1, len_trim(line) + 1
         if (i > len_trim(line)) then
            n = n + 1
            fields(n) = adjustl(line(start:len_trim(line)))
         else if (line(i:i) == achar(9)) then
            n = n + 1
            fields(n) = adjustl(line(start:i - 1))
            start = i + 1
         end if
      end do
   end subroutine split_tabs

   !> Status and figures of one result file.
   subroutine read_result(path, result)
      !> Path of the task's HDF5 file.
      character(*), intent(in) :: path
      !> The task's entry.
      type(task_result), intent(inout) :: result
      integer(hid_t) :: file, group
      integer :: hdferr, k
      logical :: exists
      character(:), allocatable :: text
      inquire (file=path, exist=exists)
      if (.not. exists) then
         result%status = 'missing'
         return
      end if
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      if (hdferr /= 0) then
         result%status = 'unreadable'
         return
      end if
      call read_text(file, 'status', text)
      if (allocated(text)) then
         result%status = text
      else
         result%status = 'unreadable'
      end if
      call read_text(file, 'failure_reason', text)
      if (allocated(text)) result%failure_reason = text
      call read_text(file, 'warnings', text)
      if (allocated(text)) result%warnings = one_line(text)
      call read_real(file, 'failure_time', result%reals(size(real_names)))
      call h5lexists_f(file, 'summary', exists, hdferr)
      if (exists .and. hdferr == 0) then
         call h5gopen_f(file, 'summary', group, hdferr)
         if (hdferr == 0) then
            do k = 1, size(real_names) - 1
               call read_real(group, trim(real_names(k)), result%reals(k))
            end do
            do k = 1, size(int_names)
               call read_int(group, trim(int_names(k)), result%ints(k))
            end do
            call h5gclose_f(group, hdferr)
         end if
      end if
      call h5fclose_f(file, hdferr)
   end subroutine read_result

   !> A string attribute; text is left unallocated when it is absent or unreadable.
   subroutine read_text(loc, name, text)
      !> File or group holding the attribute.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Its value, trimmed.
      character(:), allocatable, intent(out) :: text
      character(:), allocatable :: value
      logical :: ok
      ! get_text_attr reads fixed-length strings and the result file's variable-length UTF-8 ones.
      ok = .true.
      call get_text_attr(loc, name, value, ok)
      if (ok .and. len(value) <= reason_len) text = value
   end subroutine read_text

   !> A real scalar attribute; value is unchanged when it is absent.
   subroutine read_real(loc, name, value)
      !> File or group holding the attribute.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Its value.
      real(dp), intent(inout) :: value
      integer(hid_t) :: attr
      integer :: hdferr
      logical :: exists
      real(dp) :: buffer
      call h5aexists_f(loc, name, exists, hdferr)
      if (.not. exists .or. hdferr /= 0) return
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) return
      call h5aread_f(attr, H5T_NATIVE_DOUBLE, buffer, [1_hsize_t], hdferr)
      if (hdferr == 0) value = buffer
      call h5aclose_f(attr, hdferr)
   end subroutine read_real

   !> An integer scalar attribute; value is unchanged when it is absent.
   subroutine read_int(loc, name, value)
      !> File or group holding the attribute.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Its value.
      integer, intent(inout) :: value
      integer(hid_t) :: attr
      integer :: hdferr, buffer
      logical :: exists
      call h5aexists_f(loc, name, exists, hdferr)
      if (.not. exists .or. hdferr /= 0) return
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) return
      call h5aread_f(attr, H5T_NATIVE_INTEGER, buffer, [1_hsize_t], hdferr)
      if (hdferr == 0) value = buffer
      call h5aclose_f(attr, hdferr)
   end subroutine read_int

   !> A CSV field: quoted (quotes doubled) when it holds a comma, a quote or a blank.
   function csv_field(text) result(field)
      !> Field text.
      character(*), intent(in) :: text
      character(:), allocatable :: field
      integer :: i
      if (scan(text, ',"; ') == 0) then
         field = text
         return
      end if
      field = '"'
      do i = 1, len(text)
         if (text(i:i) == '"') then
            field = field//'""'
         else
            field = field//text(i:i)
         end if
      end do
      field = field//'"'
   end function csv_field

   !> A real as text: 10 significant digits, NaN for absent.
   function real_text(value) result(text)
      !> Value.
      real(dp), intent(in) :: value
      character(:), allocatable :: text
      character(len=32) :: buffer
      if (ieee_is_nan(value)) then
         text = 'NaN'
      else if (abs(value) >= 1.0e99_dp .or. (value /= 0 .and. abs(value) < 1.0e-99_dp)) then
         write (buffer, '(es18.9e3)') value
         text = trim(adjustl(buffer))
      else
         write (buffer, '(es16.9e2)') value
         text = trim(adjustl(buffer))
      end if
   end function real_text

   !> Warnings on one line: their line breaks become '; '.
   function one_line(text) result(line)
      character(*), intent(in) :: text
      character(:), allocatable :: line
      integer :: i
      line = ''
      do i = 1, len(text)
         if (text(i:i) == new_line('a')) then
            line = line//'; '
         else
            line = line//text(i:i)
         end if
      end do
   end function one_line

   !> summary.csv: header, then one line per task.
   subroutine write_csv(path, names, values, results, ok)
      !> Output path.
      character(*), intent(in) :: path
      !> Swept variables.
      character(len=value_len), intent(in) :: names(:)
      !> Swept values, [variable, task].
      character(len=value_len), intent(in) :: values(:, :)
      !> The tasks.
      type(task_result), intent(in) :: results(:)
      !> Whether the file was written.
      logical, intent(out) :: ok
      character(:), allocatable :: line
      character(len=24) :: buffer
      integer :: unit, ios, i, k
      open (newunit=unit, file=path, status='replace', action='write', iostat=ios)
      ok = ios == 0
      if (.not. ok) return
      line = 'task'
      do k = 1, size(names)
         line = line//','//csv_field(trim(names(k)))
      end do
      line = line//',status'
      do k = 1, size(real_names)
         line = line//','//trim(real_names(k))
      end do
      do k = 1, size(int_names)
         line = line//','//trim(int_names(k))
      end do
      write (unit, '(a)', iostat=ios) line//',warnings,failure_reason'
      do i = 1, size(results)
         write (buffer, '(i0)') results(i)%task
         line = trim(buffer)
         do k = 1, size(names)
            line = line//','//csv_field(trim(values(k, i)))
         end do
         line = line//','//trim(results(i)%status)
         do k = 1, size(real_names)
            line = line//','//real_text(results(i)%reals(k))
         end do
         do k = 1, size(int_names)
            write (buffer, '(i0)') results(i)%ints(k)
            line = line//','//trim(buffer)
         end do
         line = line//','//csv_field(trim(results(i)%warnings))//','//csv_field(trim(results(i)%failure_reason))
         write (unit, '(a)', iostat=ios) line
      end do
      ok = ios == 0
      close (unit)
   end subroutine write_csv

   !> summary.h5: one dataset per column, the swept values under /swept.
   subroutine write_h5(path, outdir, names, values, results, counts, ok)
      !> Output path.
      character(*), intent(in) :: path
      !> The sweep directory (written as an attribute).
      character(*), intent(in) :: outdir
      !> Swept variables.
      character(len=value_len), intent(in) :: names(:)
      !> Swept values, [variable, task].
      character(len=value_len), intent(in) :: values(:, :)
      !> The tasks.
      type(task_result), intent(in) :: results(:)
      !> Tasks of each status of status_names.
      integer, intent(in) :: counts(:)
      !> Whether the file was written.
      logical, intent(out) :: ok
      integer(hid_t) :: file, group
      integer :: hdferr, k, i, ios, n
      real(dp), allocatable :: numbers(:)
      integer, allocatable :: integers(:)
      character(len=16), allocatable :: statuses(:)
      character(len=reason_len), allocatable :: reasons(:)
      logical :: numeric
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, file, hdferr)
      ok = hdferr == 0
      if (.not. ok) return
      n = size(results)
      integers = results%task
      call put_int_vector(file, 'task', integers, ok)
      statuses = results%status
      call put_text_vector(file, 'status', statuses, ok)
      do k = 1, size(real_names)
         numbers = results%reals(k)
         call put_real_vector(file, trim(real_names(k)), numbers, ok, trim(real_units(k)))
      end do
      do k = 1, size(int_names)
         integers = results%ints(k)
         call put_int_vector(file, trim(int_names(k)), integers, ok)
      end do
      reasons = results%failure_reason
      call put_text_vector(file, 'failure_reason', reasons, ok)
      reasons = results%warnings
      call put_text_vector(file, 'warnings', reasons, ok)
      call h5gcreate_f(file, 'swept', group, hdferr)
      ok = ok .and. hdferr == 0
      if (.not. allocated(numbers)) allocate (numbers(n))
      do k = 1, size(names)
         numeric = .true.
         do i = 1, n
            read (values(k, i), *, iostat=ios) numbers(i)
            if (ios /= 0 .or. verify(trim(values(k, i)), '0123456789+-.eEdD') > 0) numeric = .false.
         end do
         if (numeric) then
            call put_real_vector(group, trim(names(k)), numbers, ok)
         else
            call put_text_vector(group, trim(names(k)), values(k, :), ok)
         end if
      end do
      call h5gclose_f(group, hdferr)
      call put_text_attr(file, 'sweep', outdir, ok)
      call put_int_attr(file, 'cases', n, ok)
      do k = 1, size(status_names)
         call put_int_attr(file, trim(status_names(k)), counts(k), ok)
      end do
      call h5fclose_f(file, hdferr)
      ok = ok .and. hdferr == 0
   end subroutine write_h5
end program sweep_collect
