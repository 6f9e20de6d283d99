!> The result file: write errors are reported, not swallowed, and the status
!> attribute reads 'complete' only after finish('complete').
module suite_output
   use xcable_core_kinds, only: dp, i8
   use xcable_core_strings, only: str, quantity
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_driver_records, only: run_history, run_summary
   use xcable_io_hdf5_put, only: put_real_vector, put_int_vector, put_text_vector, put_real_attr, put_int_attr, &
                             put_text_attr, get_text_attr
   use xcable_io_output_registry, only: output_item, find_output, outputs_text
   use xcable_io_output, only: result_file
   use xcable_core_version, only: code_version
   use xcable_core_error, only: stat_input
   use xcable_io_number_text, only: put_es, put_int
   use hdf5
   implicit none
   private
   public :: collect_output

contains

   subroutine collect_output(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('hdf5_writers_report_errors', test_writers), &
               new_unittest('result_file_status_and_errors', test_result_file), &
               new_unittest('echo_above_64_kb', test_large_echo), &
               new_unittest('version_matches_fpm_toml', test_version), &
               new_unittest('reopen_to_resume', test_reopen), &
               new_unittest('number_text_as_formatted_write', test_number_text), &
               new_unittest('number_text_fast_path_boundaries', test_number_text_boundaries), &
               new_unittest('quantities_as_people_write_them', test_quantity), &
               new_unittest('utf8_text_attributes', test_utf8_text), &
               new_unittest('registry_finds_paths', test_registry), &
               new_unittest('unregistered_dataset_refused', test_unregistered), &
               new_unittest('outputs_page_current', test_outputs_page)]
   end subroutine collect_output

   !> Each writer keeps ok on success and clears it when HDF5 refuses (a name
   !> that exists); attributes are replaced, not duplicated.
   subroutine test_writers(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: path = 'build/test_output_writers.h5'
      integer(hid_t) :: file
      integer :: hdferr
      logical :: ok
      character(:), allocatable :: text
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, file, hdferr)
      call check(error, hdferr == 0, 'cannot create '//path)
      if (allocated(error)) return
      ok = .true.
      call put_real_vector(file, 'a', [1.0_dp, 2.0_dp], ok, 'm')
      call put_int_vector(file, 'b', [1, 2, 3], ok)
      call put_text_vector(file, 'c', ['one  ', 'three'], ok)
      call put_real_attr(file, 'r', 1.5_dp, ok)
      call put_int_attr(file, 'i', 7, ok)
      call put_text_attr(file, 'status', 'running', ok)
      call put_text_attr(file, 'status', 'complete', ok)
      call put_real_attr(file, 'r', 2.5_dp, ok)
      call check(error, ok, 'a first write of each item failed')
      if (.not. allocated(error)) then
         call read_text_attr(file, 'status', text)
         call check(error, text == 'complete', 'the status attribute reads "'//text//'" after being replaced')
      end if
      if (.not. allocated(error)) then
         call put_real_vector(file, 'a', [3.0_dp], ok)
         call check(error, .not. ok, 'writing the dataset a twice did not clear ok')
      end if
      if (.not. allocated(error)) then
         ok = .true.
         call put_int_vector(file, 'b', [4], ok)
         call check(error, .not. ok, 'writing the dataset b twice did not clear ok')
      end if
      if (.not. allocated(error)) then
         ok = .true.
         call put_text_vector(file, 'c', ['x'], ok)
         call check(error, .not. ok, 'writing the dataset c twice did not clear ok')
      end if
      if (.not. allocated(error)) then
         ok = .true.
         call put_text_attr(-1_hid_t, 'status', 'complete', ok)
         call check(error, .not. ok, 'writing an attribute to an invalid identifier did not clear ok')
      end if
      call h5fclose_f(file, hdferr)
      call delete_file(path)
   end subroutine test_writers

   !> A result file reads 'running' until finish('complete'); a second
   !> /history is an HDF5 error that reaches the caller with the group's name.
   subroutine test_result_file(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: path = 'build/test_output_result.h5'
      type(result_file) :: output
      type(run_history) :: history
      type(run_summary) :: summary
      type(error_type), allocatable :: write_error
      integer(hid_t) :: file
      integer :: hdferr, i
      character(:), allocatable :: text
      call output%create(path, [(real(i, dp), i=0, 10)], 'tension', '&static tension = 180000 /', 'test.nml', &
                         .false., 'rod', 'strain', [integer ::], error)
      if (allocated(error)) return
      call history%reserve(4, 2, .false.)
      history%end_labels = [character(len=8) :: 'end_a', 'end_b']
      call output%write_history(history, write_error)
      call check(error, .not. allocated(write_error), 'the first /history failed')
      if (allocated(error)) return
      call output%write_history(history, write_error)
      call check(error, allocated(write_error), 'a second /history was not reported as an error')
      if (allocated(error)) return
      call check(error, index(write_error%message, '/history') > 0, 'message: '//write_error%message)
      if (allocated(error)) return
      call output%write_summary(summary, history%end_labels, write_error)
      call check(error, .not. allocated(write_error), 'the summary failed')
      if (allocated(error)) return
      ! Still running: read it while the result file is open (HDF5 allows a
      ! second read-only handle in the same process).
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      call read_text_attr(file, 'status', text)
      call h5fclose_f(file, hdferr)
      call check(error, text == 'running', 'status before finish: "'//text//'"')
      if (allocated(error)) return
      call output%finish('complete', error=write_error)
      call check(error, .not. allocated(write_error), 'finish failed')
      if (allocated(error)) return
      call h5open_f(hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      call check(error, hdferr == 0, 'cannot reopen '//path)
      if (allocated(error)) return
      call read_text_attr(file, 'status', text)
      call h5fclose_f(file, hdferr)
      call check(error, text == 'complete', 'status after finish: "'//text//'"')
      call delete_file(path)
   end subroutine test_result_file

   !> A UTF-8 text attribute (variable length) reads back as written, and is one: its
   !> type is a variable-length string with the UTF-8 character set.
   subroutine test_utf8_text(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: path = 'build/test_output_utf8.h5'
      character(*), parameter :: text = 'tension in N, '//achar(226)//achar(137)//achar(164)//' 315 kN'
      integer(hid_t) :: file, attr, atype
      integer :: hdferr, cset
      logical :: ok, variable
      character(:), allocatable :: back
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, file, hdferr)
      ok = .true.
      call put_text_attr(file, 'note', text, ok, utf8=.true.)
      call put_text_attr(file, 'empty', '', ok, utf8=.true.)
      call get_text_attr(file, 'note', back, ok)
      call check(error, ok .and. back == text, 'the UTF-8 attribute reads back as "'//back//'"')
      if (.not. allocated(error)) then
         call get_text_attr(file, 'empty', back, ok)
         call check(error, ok .and. back == '', 'the empty UTF-8 attribute reads back as "'//back//'"')
      end if
      if (.not. allocated(error)) then
         call h5aopen_f(file, 'note', attr, hdferr)
         call h5aget_type_f(attr, atype, hdferr)
         call h5tis_variable_str_f(atype, variable, hdferr)
         call h5tget_cset_f(atype, cset, hdferr)
         call h5tclose_f(atype, hdferr)
         call h5aclose_f(attr, hdferr)
         call check(error, variable .and. cset == H5T_CSET_UTF8_F, 'the attribute is not a variable-length UTF-8 string')
      end if
      call h5fclose_f(file, hdferr)
      call delete_file(path)
   end subroutine test_utf8_text

   !> The registry finds fixed and per-end paths with their units, and not a path it lacks.
   subroutine test_registry(error)
      type(error_type), allocatable, intent(out) :: error
      type(output_item) :: item
      logical :: found
      call find_output('/history/break_b/vy', item, found)
      call check(error, found .and. item%units == 'm/s', '/history/break_b/vy: not found or not m/s')
      if (allocated(error)) return
      call find_output('/summary@end_a_max_tension_time', item, found)
      call check(error, found .and. item%units == 's', '/summary@end_a_max_tension_time: not found or not s')
      if (allocated(error)) return
      call find_output('/summary/end_b_slack_start', item, found)
      call check(error, found .and. item%dims == 'interval', '/summary/end_b_slack_start: not found')
      if (allocated(error)) return
      call find_output('/history/step', item, found)
      call check(error, .not. found, '/history/step (renamed dt) is still in the registry')
      if (allocated(error)) return
      call find_output('/history/end_a/x/y', item, found)
      call check(error, .not. found, '<end> matched across a /')
      if (allocated(error)) return
      call find_output('/w', item, found)
      call check(error, .not. found, '/w (renamed vy) is still in the registry')
   end subroutine test_registry

   !> A snapshot field the registry does not list is refused, with its name and the registry's
   !> in the message.
   subroutine test_unregistered(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: path = 'build/test_output_unregistered.h5'
      type(result_file) :: output
      type(error_type), allocatable :: write_error
      real(dp) :: fields(3, 8)
      integer :: i
      call output%create(path, [(real(i, dp), i=0, 2)], 'tension', '&static tension = 180000 /', 'test.nml', &
                         .false., 'rod', 'strain', [integer ::], error)
      if (allocated(error)) return
      fields = 1
      call output%snapshot(0.0_dp, fields, write_error)
      call check(error, .not. allocated(write_error), 'the first snapshot failed')
      if (allocated(error)) return
      call output%snapshot_extra(0.0_dp, [character(len=8) :: 'y', 'w'], fields(:, 1:2), write_error)
      call check(error, allocated(write_error), 'a snapshot field w, not in the registry, was written')
      if (allocated(error)) return
      call check(error, index(write_error%message, "'/w' is not in the output registry") > 0, &
                 'message: '//write_error%message)
      call output%finish('failed', 'test')
      call delete_file(path)
   end subroutine test_unregistered

   !> docs/user/output.md is the registry's page (make outputs rewrites it).
   subroutine test_outputs_page(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: page = 'docs/user/output.md'
      character(:), allocatable :: text, expected
      character(len=4096) :: line
      integer :: unit, ios, lineno, at
      open (newunit=unit, file=page, status='old', action='read', iostat=ios)
      call check(error, ios == 0, page//' not found in the working directory (fpm test runs in the project root)')
      if (allocated(error)) return
      text = ''
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         text = text//trim(line)//new_line('a')
      end do
      close (unit)
      expected = outputs_text('markdown')
      if (text == expected) return
      at = 1
      lineno = 1
      do while (at <= min(len(text), len(expected)))
         if (text(at:at) /= expected(at:at)) exit
         if (text(at:at) == new_line('a')) lineno = lineno + 1
         at = at + 1
      end do
      call check(error, .false., page//' is not the output registry''s page from line '//str(lineno)// &
                 ': run make outputs')
   end subroutine test_outputs_page

   !> The echo of a case with long tables (above the 64 KB of a compact HDF5
   !> attribute) is written and reads back whole.
   subroutine test_large_echo(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: path = 'build/test_output_echo.h5'
      type(result_file) :: output
      character(len=200000) :: echo
      character(:), allocatable :: text
      integer(hid_t) :: file
      integer :: hdferr, i
      do i = 1, len(echo)
         echo(i:i) = achar(iachar('a') + mod(i, 26))
      end do
      call output%create(path, [0.0_dp, 1.0_dp], 'tension', echo, 'test.nml', .false., 'rod', 'strain', [integer ::], &
                         error)
      if (allocated(error)) return
      call output%finish('complete')
      call h5open_f(hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      call read_text_attr(file, 'namelist', text)
      call h5fclose_f(file, hdferr)
      call check(error, text == echo, 'the 200 kB echo did not read back whole (length '//str(len(text))//')')
      call delete_file(path)
   end subroutine test_large_echo

   !> The version the program reports (src/xcable/core/version.f90) is the package
   !> version of fpm.toml: the first line `version = "..."` of the manifest.
   subroutine test_version(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: line
      character(:), allocatable :: manifest_version
      integer :: unit, ios, q1, q2
      open (newunit=unit, file='fpm.toml', status='old', action='read', iostat=ios)
      call check(error, ios == 0, 'cannot open fpm.toml (the tests run from the project root)')
      if (allocated(error)) return
      manifest_version = ''
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         line = adjustl(line)
         if (line(1:7) /= 'version') cycle
         if (verify(line(8:index(line, '=') - 1), ' ') /= 0) cycle
         q1 = index(line, '"')
         q2 = index(line, '"', back=.true.)
         if (q2 > q1) manifest_version = line(q1 + 1:q2 - 1)
         exit
      end do
      close (unit)
      call check(error, manifest_version == code_version, 'fpm.toml says version "'//manifest_version// &
                 '", src/xcable/core/version.f90 says "'//code_version//'": change both (and CHANGELOG.md)')
      if (allocated(error)) return
      ! The newest entry of the changelog (above it, an "## Unreleased" entry may collect what is
      ! not released yet) and the README follow it.
      line = first_line('CHANGELOG.md', '## ')
      call check(error, index(line, '## '//code_version//' ') == 1, 'CHANGELOG.md''s newest entry is "'// &
                 trim(line)//'", the version is '//code_version)
      if (allocated(error)) return
      line = first_line('README.md', 'Version ')
      call check(error, index(line, 'Version '//code_version//' ') == 1 .or. trim(line) == 'Version '//code_version, &
                 'README.md says "'//trim(line)//'", the version is '//code_version)

   contains

      !> The first line of a file that starts with prefix ('' if none).
      function first_line(file, prefix) result(found)
         character(*), intent(in) :: file, prefix
         character(len=256) :: found
         character(len=256) :: text
         integer :: u, stat
         found = ''
         open (newunit=u, file=file, status='old', action='read', iostat=stat)
         if (stat /= 0) return
         do
            read (u, '(a)', iostat=stat) text
            if (stat /= 0) exit
            if (index(text, prefix) == 1 .and. index(text, '## Unreleased') /= 1) then
               found = text
               exit
            end if
         end do
         close (u)
      end function first_line
   end subroutine test_version

   !> Reopening for a resume: a file of another run, one with fewer
   !> snapshots than the checkpoint counts, or one that is complete is
   !> refused and left as it was; otherwise the snapshots after the
   !> checkpoint are cut (HDF5 and gnuplot text), the summary of the
   !> interruption removed and the status is 'running' again.
   subroutine test_reopen(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: path = 'build/test_output_reopen.h5'
      type(result_file) :: output
      type(run_summary) :: summary
      type(error_type), allocatable :: reopen_error
      real(dp) :: fields(3, 8)
      integer :: i
      fields = 0
      call output%create(path, [0.0_dp, 1.0_dp, 2.0_dp], 'tension x', '&numerics nodes = 3 /', 'test.nml', .true., &
                         'rod', 'strain', [integer ::], error, run_id='run-A')
      if (allocated(error)) return
      do i = 0, 4
         fields(:, 1) = i
         call output%snapshot(0.1_dp*i, fields, error)
         if (allocated(error)) return
      end do
      call output%write_summary(summary, [character(len=8) :: 'end_a', 'end_b'], error)
      if (allocated(error)) return
      call output%finish('interrupted')
      call refused('another run''s file', 'run-B', 3, 'belongs to run run-A')
      if (allocated(error)) return
      call refused('fewer snapshots than the checkpoint', 'run-A', 7, 'holds 5 snapshots')
      if (allocated(error)) return
      call check(error, file_status() == 'interrupted' .and. snapshots_in_file() == 5 .and. text_blocks() == 5, &
                 'a refused reopen changed the file')
      if (allocated(error)) return
      call output%reopen(path, [0.0_dp, 1.0_dp, 2.0_dp], 'tension x', '&numerics nodes = 3 /', 'test.nml', .true., &
                         [integer ::], 3, 'run-A', error)
      if (allocated(error)) return
      call check(error, file_status() == 'running' .and. snapshots_in_file() == 3 .and. text_blocks() == 3 .and. &
                 .not. has_summary(), 'after reopen: status '//file_status()//', '//str(snapshots_in_file())// &
                 ' snapshots, '//str(text_blocks())//' text blocks (expected running, 3, 3, no /summary)')
      if (allocated(error)) return
      call output%snapshot(0.3_dp, fields, error)
      if (allocated(error)) return
      call output%finish('complete')
      call check(error, snapshots_in_file() == 4 .and. text_blocks() == 4, 'a snapshot after reopen was not appended')
      if (allocated(error)) return
      call refused('a complete file', 'run-A', 3, 'already complete')
      call delete_file(path)
      call delete_file('build/test_output_reopen.snapshots.dat')

   contains

      subroutine refused(what, id, snapshots, expect)
         character(*), intent(in) :: what, id, expect
         integer, intent(in) :: snapshots
         type(result_file) :: other
         call other%reopen(path, [0.0_dp, 1.0_dp, 2.0_dp], 'tension x', '&numerics nodes = 3 /', 'test.nml', .true., &
                           [integer ::], snapshots, id, reopen_error)
         call check(error, allocated(reopen_error), 'reopening '//what//' was not refused')
         if (allocated(error)) return
         call check(error, reopen_error%stat == stat_input .and. index(reopen_error%message, expect) > 0, &
                    'reopening '//what//': "'//reopen_error%message//'" lacks "'//expect//'"')
         deallocate (reopen_error)
      end subroutine refused

      function file_status() result(text)
         character(:), allocatable :: text
         integer(hid_t) :: file
         integer :: hdferr
         call h5open_f(hdferr)
         call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
         call read_text_attr(file, 'status', text)
         call h5fclose_f(file, hdferr)
      end function file_status

      integer function snapshots_in_file() result(n)
         integer(hid_t) :: file, dset, space
         integer(hsize_t) :: dims(1), maxdims(1)
         integer :: hdferr
         call h5open_f(hdferr)
         call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
         call h5dopen_f(file, 'time', dset, hdferr)
         call h5dget_space_f(dset, space, hdferr)
         call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
         n = int(dims(1))
         call h5sclose_f(space, hdferr)
         call h5dclose_f(dset, hdferr)
         call h5fclose_f(file, hdferr)
      end function snapshots_in_file

      logical function has_summary()
         integer(hid_t) :: file
         integer :: hdferr
         call h5open_f(hdferr)
         call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
         call h5lexists_f(file, 'summary', has_summary, hdferr)
         call h5fclose_f(file, hdferr)
      end function has_summary

      integer function text_blocks() result(n)
         character(len=256) :: line
         integer :: unit, ios
         n = 0
         open (newunit=unit, file='build/test_output_reopen.snapshots.dat', status='old', action='read', iostat=ios)
         if (ios /= 0) return
         do
            read (unit, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, '# t = ') == 1) n = n + 1
         end do
         close (unit)
      end function text_blocks
   end subroutine test_reopen

   !> A string attribute of loc ('' when it cannot be read).
   !> A text attribute, fixed-length or variable-length ('' when absent).
   subroutine read_text_attr(loc, name, text)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      character(:), allocatable, intent(out) :: text
      logical :: ok
      ok = .true.
      call get_text_attr(loc, name, text, ok)
   end subroutine read_text_attr

   subroutine delete_file(path)
      character(*), intent(in) :: path
      integer :: unit, ios
      open (newunit=unit, file=path, status='old', iostat=ios)
      if (ios == 0) close (unit, status='delete')
   end subroutine delete_file

   !> put_es and put_int give the characters of gfortran's ESw.d and Iw:
   !> 200 000 numbers per descriptor, of magnitudes 1e-50 to 1e50, with
   !> ties at the last digit (exact binary values ending in 5), powers of ten
   !> and their neighbours, values that round up to the next power, zeros of
   !> both signs, and the numbers written through the formatted write
   !> (beyond the exponent range, not finite).
   subroutine test_number_text(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: w(4) = [16, 17, 14, 23], d(4) = [8, 9, 6, 16]
      real(dp), allocatable :: xs(:)
      real(dp) :: r, zero
      character(len=40) :: expected, got, fmt
      integer :: i, f, pos, seed_size, n, ints(9)
      integer, allocatable :: seed(:)
      call random_seed(size=seed_size)
      seed = [(104729*i, i=1, seed_size)]
      call random_seed(put=seed)
      n = 200000
      allocate (xs(n))
      do i = 1, n
         call random_number(r)
         xs(i) = (r - 0.5_dp)*10.0_dp**(int(r*1.0e6_dp)/10000 - 50)
         if (mod(i, 7) == 0) xs(i) = anint(xs(i)*1.0e3_dp)/1.0e3_dp
         if (mod(i, 11) == 0) xs(i) = 10.0_dp**(mod(i, 60) - 30)
         if (mod(i, 13) == 0) xs(i) = nearest(10.0_dp**(mod(i, 60) - 30), merge(1.0_dp, -1.0_dp, mod(i, 2) == 0))
         ! Integers ending in 5 (ties of the 9- and 10-digit descriptors) and halves.
         if (mod(i, 17) == 0) xs(i) = real(int(r*1.0e6_dp)*10000 + 5, dp) + merge(0.5_dp, 0.0_dp, mod(i, 3) == 0)
         if (mod(i, 19) == 0) xs(i) = real(mod(i, 1000), dp)/8
         if (mod(i, 23) == 0) xs(i) = 9.9999999995_dp*10.0_dp**(mod(i, 10) - 5)
         if (mod(i, 29) == 0) xs(i) = -xs(i)
      end do
      zero = 0
      xs(1:10) = [0.0_dp, -zero, huge(1.0_dp), tiny(1.0_dp), 1.0e100_dp, -1.0e-100_dp, 123456789.5_dp, &
                  123456788.5_dp, 1234567895.0_dp, zero/zero]
      xs(11:12) = [1/zero, -1/zero]
      do f = 1, size(w)
         write (fmt, '(a,i0,a,i0,a)') '(es', w(f), '.', d(f), ')'
         do i = 1, n
            expected = ''
            got = ''
            write (expected(1:w(f)), fmt) xs(i)
            pos = 1
            call put_es(got, pos, xs(i), w(f), d(f))
            if (got /= expected .or. pos /= w(f) + 1) then
               call check(error, .false., 'put_es('//trim(fmt)//') of '//str(xs(i))//': "'//got(1:w(f))// &
                          '", formatted write "'//expected(1:w(f))//'"')
               return
            end if
         end do
      end do
      ints = [0, 1, 9, 10, 25, 999, 9999, 10000, -3]
      do i = 1, size(ints)
         expected = ''
         got = ''
         write (expected(1:4), '(i4)') ints(i)
         pos = 1
         call put_int(got, pos, ints(i), 4)
         call check(error, got == expected .and. pos == 5, 'put_int(i4) of '//str(ints(i))//': "'//got(1:4)// &
                    '", formatted write "'//expected(1:4)//'"')
         if (allocated(error)) return
      end do
   end subroutine test_number_text

   !> The double fast path of put_es (number_text.f90, fast_digits) against
   !> the formatted write where its error bound decides: for each
   !> descriptor, 1 000 000 doubles of random bits in 1e-60 .. 1e60 (every
   !> branch of the scaling, one and two powers of ten, and beyond it),
   !> and 60 000 each of values within 6 ulps of a half-integer of the last
   !> digit (n + 1/2) 10^(E-d), of 10^E and of the round-up point
   !> (10^(d+1) - 1/2) 10^(E-d). The descriptors are the gnuplot text's
   !> (es16.8, es17.9), the fast path's widest (es20.12) and the first one
   !> beyond it (es21.13). Setting the bound to zero (or to half of it) in
   !> fast_digits makes this fail.
   subroutine test_number_text_boundaries(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: w(5) = [16, 17, 20, 21, 14], d(5) = [8, 9, 12, 13, 6]
      integer, parameter :: n_random = 1000000, n_near = 60000
      real(dp) :: r(3), x, centre
      character(len=40) :: fmt
      integer :: f, i, j, e
      integer(i8) :: bits
      integer, allocatable :: seed(:)
      integer :: seed_size
      call random_seed(size=seed_size)
      seed = [(7919*i + 13, i=1, seed_size)]
      call random_seed(put=seed)
      do f = 1, size(w)
         write (fmt, '(a,i0,a,i0,a)') '(es', w(f), '.', d(f), ')'
         do i = 1, n_random
            call random_number(r)
            ! Random exponent field for 2^-200 .. 2^200, random 52-bit fraction, random sign.
            bits = shiftl(int(823 + r(1)*400, i8), 52) + int(r(2)*4503599627370496.0_dp, i8)
            x = transfer(bits, 1.0_dp)
            if (r(3) < 0.5_dp) x = -x
            if (.not. same_text(x)) return
         end do
         do i = 1, n_near
            call random_number(r)
            e = int(r(1)*120) - 60
            select case (mod(i, 3))
            case (0)
               centre = (aint(10.0_dp**d(f)*(1 + 9*r(2))) + 0.5_dp)*10.0_dp**(e - d(f))
            case (1)
               centre = 10.0_dp**e
            case default
               centre = (10.0_dp**(d(f) + 1) - 0.5_dp)*10.0_dp**(e - d(f))
            end select
            x = centre
            do j = 1, 6
               x = nearest(x, -1.0_dp)
            end do
            do j = -6, 6
               if (.not. same_text(x)) return
               x = nearest(x, 1.0_dp)
            end do
         end do
      end do
   contains
      logical function same_text(x)
         real(dp), intent(in) :: x
         character(len=40) :: expected, got
         integer :: pos
         expected = ''
         got = ''
         write (expected(1:w(f)), fmt) x
         pos = 1
         call put_es(got, pos, x, w(f), d(f))
         same_text = got == expected .and. pos == w(f) + 1
         if (.not. same_text) call check(error, .false., 'put_es('//trim(fmt)//') of '//str(x)//': "'// &
                                         got(1:w(f))//'", formatted write "'//expected(1:w(f))//'"')
      end function same_text
   end subroutine test_number_text_boundaries

   !> Numbers in messages as people write them: four significant digits, SI prefixes for forces
   !> and short times, no trailing zeros.
   subroutine test_quantity(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=16), parameter :: want(12) = [character(len=16) :: '315 kN', '1.235 MN', '0.459 ms', &
         '50 us', '70.66 m', '111.7 m/s', '-7.734 kN', '0 N', '1.235e-5 m', '1 kN', '12 s', '2.5e6 m']
      real(dp), parameter :: x(12) = [315.0e3_dp, 1.2346e6_dp, 0.459e-3_dp, 0.05e-3_dp, 70.6584_dp, 111.74_dp, &
                                      -7734.2_dp, 0.0_dp, 1.23456e-5_dp, 999.97_dp, 12.0_dp, 2.5e6_dp]
      character(len=4), parameter :: unit(12) = [character(len=4) :: 'N', 'N', 's', 's', 'm', 'm/s', 'N', 'N', &
                                                 'm', 'N', 's', 'm']
      integer :: k
      do k = 1, size(x)
         call check(error, quantity(x(k), trim(unit(k))) == trim(want(k)), 'quantity('//str(x(k))//', '// &
                    trim(unit(k))//') = "'//quantity(x(k), trim(unit(k)))//'", not "'//trim(want(k))//'"')
         if (allocated(error)) return
      end do
   end subroutine test_quantity
end module suite_output
