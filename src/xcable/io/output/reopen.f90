!> Reopening a result file to resume a run from its checkpoint: the checks, the copy of what the
!> checkpoint counts, the cut gnuplot text.
!> (A submodule of io/output.f90: it sees the result file's type and helpers.)
submodule (xcable_io_output) xcable_io_output_reopen
   implicit none

contains

   !> Reopen the result file of a run that continues from a checkpoint. It
   !> must be the file of that run (run_id), not finished ('running' or
   !> 'interrupted'), with at least the snapshots the checkpoint counts and
   !> the same output nodes; with gnuplot text, its snapshot file must hold
   !> them too. All of this is checked before anything is changed. Then the
   !> part of the file the checkpoint counts is copied into a new file that
   !> replaces it (the snapshots after the checkpoint, /summary, /history and
   !> the failure and warning attributes of an earlier stop left behind), the
   !> text cut alike, the provenance updated (namelist, input_file; resumes
   !> counted) and the status set to 'running'.
   module subroutine result_reopen(self, path, s, fields, namelist_text, input_file, gnuplot, piece_starts, snapshots, run_id, &
                            error, three_d)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      !> Output node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Snapshot fields, separated by blanks or commas.
      character(*), intent(in) :: fields
      !> The resolved namelist (as the resumed run reads it).
      character(*), intent(in) :: namelist_text
      !> Namelist file of the case.
      character(*), intent(in) :: input_file
      !> Whether gnuplot text is written.
      logical, intent(in) :: gnuplot
      !> Output columns where a new piece starts (empty: one piece).
      integer, intent(in) :: piece_starts(:)
      !> Snapshots the checkpoint counts (the one at t = 0 included).
      integer, intent(in) :: snapshots
      !> Identifier of the run of the checkpoint.
      character(*), intent(in) :: run_id
      !> Error (stat_input) naming what does not fit; the file is then unchanged.
      type(error_type), allocatable, intent(out) :: error
      !> A 3-D run: its snapshots have the fields of field3_names too (default .false.).
      logical, intent(in), optional :: three_d
      integer :: hdferr, i, resumes, ios
      logical :: ok, exists
      character(:), allocatable :: status, stored_id, reason, lines(:)
      character(len=*), parameter :: fresh = '; run without --resume to start again'
      integer :: keep_lines
      self%path = path
      self%s = s
      self%piece_starts = piece_starts
      self%three_d = .false.
      if (present(three_d)) self%three_d = three_d
      do i = 1, n_fields
         self%want(i) = has_word(fields, trim(field_names(i)))
      end do
      inquire (file=path, exist=exists)
      if (.not. exists) then
         call fatal_error(error, "the result file '"//path//"' of the checkpoint is missing"//fresh, stat_input)
         return
      end if
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fopen_f(path, H5F_ACC_RDWR_F, self%file, hdferr)
      if (hdferr /= 0) then
         self%file = -1
         call fatal_error(error, "the result file '"//path//"' cannot be opened for writing (damaged, or in use)"//fresh, &
                          stat_input)
         return
      end if
      ok = .true.
      call get_text_attr(self%file, 'status', status, ok)
      call get_text_attr(self%file, 'run_id', stored_id, ok)
      if (.not. ok) then
         call refuse("'"//path//"' has no status or run_id: not the result file of a run with checkpoints"//fresh)
         return
      end if
      select case (status)
      case ('running', 'interrupted')
      case ('complete')
         call refuse("the result file '"//path//"' is already complete: nothing to resume")
         return
      case ('failed')
         ok = .true.
         call get_text_attr(self%file, 'failure_reason', reason, ok)
         call refuse("the result file '"//path//"' says the run failed ("//reason//'): resuming would fail again'//fresh)
         return
      case default
         call refuse("the result file '"//path//"' has the status '"//status//"'"//fresh)
         return
      end select
      if (stored_id /= run_id) then
         call refuse("the result file '"//path//"' belongs to run "//stored_id//', the checkpoint to run '//run_id// &
                     ' (the file was written again since)'//fresh)
         return
      end if
      if (dataset_length(self%file, 's', 1) /= size(s)) then
         call refuse("the result file '"//path//"' has other output nodes than this case"//fresh)
         return
      end if
      if (dataset_length(self%file, 'time', 1) < snapshots) then
         call refuse("the result file '"//path//"' holds "//str(max(dataset_length(self%file, 'time', 1), 0))// &
                     ' snapshots, the checkpoint counts '//str(snapshots)//fresh)
         return
      end if
      do i = 1, n_fields
         if (.not. self%want(i)) cycle
         if (dataset_length(self%file, trim(field_names(i)), 2) < snapshots) then
            call refuse("the result file '"//path//"' lacks snapshots of "//trim(field_names(i))//fresh)
            return
         end if
      end do
      do i = 1, merge(n_fields3, 0, self%three_d)
         if (dataset_length(self%file, trim(field3_names(i)), 2) < snapshots) then
            call refuse("the result file '"//path//"' lacks snapshots of "//trim(field3_names(i))// &
                        ' (a 3-D run writes them)'//fresh)
            return
         end if
      end do
      if (gnuplot) then
         self%text_stem = text_stem_of(path)
         call kept_text(self%text_stem//'.snapshots.dat', snapshots, lines, keep_lines, reason)
         if (len(reason) > 0) then
            call refuse(reason//fresh)
            return
         end if
      end if
      ! Checked: now change it. A process killed inside an HDF5 flush can leave the chunk
      ! indexes of the snapshot datasets out of step with their extents and with the space the
      ! superblock records (entries past the extent or past the end of allocated space); a
      ! file cut in place and written on could then read a row back as zeros (seen after a
      ! SIGKILL of a 3-D run: one chunk too many in /shear, its row zero after the resume).
      ! So the kept part is copied into a new file, which replaces this one: the provenance
      ! attributes, /s and /static as they are, and the first `snapshots` rows of /time and
      ! of every snapshot dataset (rows the checkpoint counts, flushed before it was written),
      ! each dataset built afresh. Until the rename the old file stays as it was.
      call copy_kept(error)
      if (allocated(error)) return
      call lay_out(self, ok)
      resumes = 0
      call get_int_attr(self%file, 'resumes', resumes, exists)
      call put_int_attr(self%file, 'resumes', resumes + 1, ok)
      call put_text(self%file, 'namelist', namelist_text, ok)
      call put_text(self%file, 'input_file', input_file, ok)
      call put_text(self%file, 'status', 'running', ok)
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) then
         call fatal_error(error, "reopening '"//path//"' to resume: an HDF5 write failed"//why(self), stat_io)
         return
      end if
      self%snapshots = snapshots
      if (gnuplot) then
         call rewrite_text(self%text_stem//'.snapshots.dat', lines(1:keep_lines), reason)
         if (len(reason) == 0) open (newunit=self%text_unit, file=self%text_stem//'.snapshots.dat', status='old', &
                                     position='append', action='write', iostat=ios)
         if (len(reason) > 0 .or. ios /= 0) then
            call fatal_error(error, 'cannot rewrite '//self%text_stem//'.snapshots.dat to resume (&output gnuplot)', &
                             stat_io)
            return
         end if
         self%gnuplot_text = .true.
      end if

   contains

      !> The kept part of the file into path.resume, which then replaces path and is
      !> opened as self%file (see above). Errors: stat_io; the old file is then unchanged
      !> (closed), and the partial copy removed.
      subroutine copy_kept(error)
         type(error_type), allocatable, intent(out) :: error
         character(len=*), parameter :: text_attrs(11) = [character(len=16) :: 'status', 'namelist', &
            'input_file', 'code_version', 'compiler_version', 'compiler_options', 'scheme', 'terms', 'run_id', &
            'model', 'description']
         integer(hid_t) :: new, access, copy_list
         character(:), allocatable :: temporary, text, message
         logical :: found, copied
         integer :: q, unit, status_code
         temporary = path//'.resume'
         open (newunit=unit, file=temporary, status='old', iostat=ios)
         if (ios == 0) close (unit, status='delete')
         call h5pcreate_f(H5P_FILE_ACCESS_F, access, hdferr)
         call h5pset_libver_bounds_f(access, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, hdferr)
         call h5fcreate_f(temporary, H5F_ACC_TRUNC_F, new, hdferr, access_prp=access)
         call h5pclose_f(access, status_code)
         if (hdferr /= 0) then
            call fatal_error(error, "cannot create '"//temporary//"' to resume (is the directory writable?)", stat_io)
            call close_kept(self)
            call h5fclose_f(self%file, hdferr)
            self%file = -1
            return
         end if
         copied = .true.
         do q = 1, size(text_attrs)
            call h5aexists_f(self%file, trim(text_attrs(q)), found, hdferr)
            if (.not. found) cycle
            call get_text_attr(self%file, trim(text_attrs(q)), text, copied)
            call put_text(new, trim(text_attrs(q)), text, copied)
         end do
         call h5aexists_f(self%file, 'resumes', found, hdferr)
         if (found) then
            call get_int_attr(self%file, 'resumes', resumes, copied)
            call put_int_attr(new, 'resumes', resumes, copied)
         end if
         ! /s and /static are copied without their attributes: HDF5 1.10 crashes copying the
         ! dimension scales' references (H5Ocopy of /s, in H5T_convert). Their units and
         ! descriptions come again from the registry, their scales from lay_out, the static
         ! figures are copied one by one.
         call h5pcreate_f(H5P_OBJECT_COPY_F, copy_list, hdferr)
         call h5pset_copy_object_f(copy_list, H5O_COPY_WITHOUT_ATTR_FLAG_F, hdferr)
         call h5ocopy_f(self%file, 's', new, 's', hdferr, ocpypl_id=copy_list)
         copied = copied .and. hdferr == 0
         call h5lexists_f(self%file, 'static', found, hdferr)
         if (found) call copy_static(new, copy_list, copied)
         call h5pclose_f(copy_list, hdferr)
         call copy_rows(self%file, new, 'time', 1, snapshots, copied)
         do q = 1, n_fields
            if (self%want(q)) call copy_rows(self%file, new, trim(field_names(q)), 2, snapshots, copied)
         end do
         do q = 1, merge(n_fields3, 0, self%three_d)
            call copy_rows(self%file, new, trim(field3_names(q)), 2, snapshots, copied)
         end do
         call h5fflush_f(new, H5F_SCOPE_GLOBAL_F, hdferr)
         copied = copied .and. hdferr == 0
         call h5fclose_f(new, hdferr)
         copied = copied .and. hdferr == 0
         call close_kept(self)
         call h5fclose_f(self%file, hdferr)
         self%file = -1
         message = ''
         if (copied) message = replace_file(temporary, path)
         if (.not. copied .or. len(message) > 0) then
            open (newunit=unit, file=temporary, status='old', iostat=ios)
            if (ios == 0) close (unit, status='delete')
            if (.not. copied) message = 'an HDF5 read or write failed'
            call fatal_error(error, "reopening '"//path//"' to resume: copying its kept part failed ("// &
                             message//"); the file is unchanged", stat_io)
            return
         end if
         call h5fopen_f(path, H5F_ACC_RDWR_F, self%file, hdferr)
         if (hdferr /= 0) then
            self%file = -1
            call fatal_error(error, "the result file '"//path//"' cannot be opened again after its kept part "// &
                             "was copied", stat_io)
         end if

      end subroutine copy_kept
      !> /static into new: its datasets without attributes (copy_list), described from the
      !> registry; its figures (attributes) one by one.
      subroutine copy_static(new, copy_list, copied)
         integer(hid_t), intent(in) :: new, copy_list
         logical, intent(inout) :: copied
         character(len=*), parameter :: names(n_fields + n_fields3 + 3) = [character(len=14) :: 's', &
                                                                             field_names, field3_names, 'beta0', 'beta3']
         type(output_item), allocatable :: items(:)
         integer(hid_t) :: from, to
         integer :: k, value_int, hdferr
         real(dp) :: value
         logical :: exists
         call h5gopen_f(self%file, 'static', from, hdferr)
         call h5gcreate_f(new, 'static', to, hdferr)
         copied = copied .and. hdferr == 0
         if (hdferr /= 0) return
         call describe_group(self, to, '/static', copied)
         do k = 1, size(names)
            call h5lexists_f(from, trim(names(k)), exists, hdferr)
            if (.not. exists) cycle
            call h5ocopy_f(from, trim(names(k)), to, trim(names(k)), hdferr, ocpypl_id=copy_list)
            copied = copied .and. hdferr == 0
            call describe_dataset(self, to, '/static', trim(names(k)), copied)
         end do
         items = output_items()
         do k = 1, size(items)
            if (index(items(k)%path, '/static@') /= 1) cycle
            call h5aexists_f(from, trim(items(k)%path(9:)), exists, hdferr)
            if (.not. exists) cycle
            if (items(k)%units == '1') then
               call get_int_attr(from, trim(items(k)%path(9:)), value_int, copied)
               call put_int_attr(to, trim(items(k)%path(9:)), value_int, copied)
            else
               call get_real_attr(from, trim(items(k)%path(9:)), value, copied)
               call put_real_attr(to, trim(items(k)%path(9:)), value, copied)
            end if
         end do
         call h5gclose_f(to, hdferr)
         call h5gclose_f(from, hdferr)
      end subroutine copy_static

      !> Refuse: close the file unchanged.
      subroutine refuse(message)
         character(*), intent(in) :: message
         call fatal_error(error, message, stat_input)
         call close_kept(self)
         call h5fclose_f(self%file, hdferr)
         self%file = -1
      end subroutine refuse
   end subroutine result_reopen

   !> Number of snapshots of a dataset (rank 1: its length; rank 2: its second
   !> dimension); -1 when it is missing or of another rank.
   integer function dataset_length(loc, name, rank) result(n)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      integer, intent(in) :: rank
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(2), maxdims(2)
      integer :: hdferr, stored_rank
      n = -1
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) return
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_ndims_f(space, stored_rank, hdferr)
      if (stored_rank == rank) then
         call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
         if (hdferr >= 0) n = int(dims(rank))
      end if
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
   end function dataset_length

   !> The first `keep` snapshots of a snapshot dataset of one file into a new
   !> dataset of that name in another (written as the run writes them, a row at
   !> a time). Only rows inside the dataset's extent are read.
   subroutine copy_rows(from, to, name, rank, keep, ok)
      integer(hid_t), intent(in) :: from, to
      character(*), intent(in) :: name
      integer, intent(in) :: rank, keep
      logical, intent(inout) :: ok
      integer(hid_t) :: dset, space, memspace
      integer(hsize_t) :: dims(2), maxdims(2), count(2), start(2)
      real(dp), allocatable :: rows(:, :)
      integer :: hdferr, j
      call h5dopen_f(from, name, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
      if (rank == 1) dims(2) = dims(1)
      if (rank == 1) dims(1) = 1
      if (dims(2) < keep) then
         ok = .false.
      else
         allocate (rows(dims(1), keep))
         start = 0
         if (rank == 1) then
            count(1) = int(keep, hsize_t)
         else
            count = [dims(1), int(keep, hsize_t)]
         end if
         call h5sselect_hyperslab_f(space, H5S_SELECT_SET_F, start(1:rank), count(1:rank), hdferr)
         call h5screate_simple_f(rank, count(1:rank), memspace, hdferr)
         call h5dread_f(dset, H5T_NATIVE_DOUBLE, rows, count(1:rank), hdferr, memspace, space)
         ok = ok .and. hdferr == 0
         call h5sclose_f(memspace, hdferr)
      end if
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
      if (.not. ok) return
      do j = 1, keep
         call append(to, name, rows(:, j), rank, ok)
      end do
   end subroutine copy_rows

   !> The lines of a gnuplot snapshot file that hold its first `keep` blocks
   !> (the blank lines between blocks after the last kept one left out):
   !> lines(1:count). reason is '' or why the file does not do.
   subroutine kept_text(path, keep, lines, count, reason)
      character(*), intent(in) :: path
      integer, intent(in) :: keep
      character(:), allocatable, intent(out) :: lines(:)
      integer, intent(out) :: count
      character(:), allocatable, intent(out) :: reason
      character(len=512) :: line
      character(len=512), allocatable :: all(:), grown(:)
      integer :: unit, ios, n, blocks
      reason = ''
      count = 0
      allocate (character(len=512) :: lines(0))
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         reason = 'the gnuplot text '//path//' of the run is missing'
         return
      end if
      allocate (all(1024))
      n = 0
      blocks = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, '# t = ') == 1) then
            blocks = blocks + 1
            if (blocks > keep) exit
         end if
         if (n == size(all)) then
            allocate (grown(2*n))
            grown(1:n) = all(1:n)
            call move_alloc(grown, all)
         end if
         n = n + 1
         all(n) = line
      end do
      close (unit)
      if (blocks < keep) then
         reason = 'the gnuplot text '//path//' holds '//str(blocks)//' snapshots, the checkpoint counts '//str(keep)
         return
      end if
      do while (n > 0)
         if (len_trim(all(n)) > 0) exit
         n = n - 1
      end do
      deallocate (lines)
      allocate (character(len=512) :: lines(n))
      lines = all(1:n)
      count = n
   end subroutine kept_text

   !> Write lines (trimmed) to path through path.tmp and a rename; reason '' or why not.
   subroutine rewrite_text(path, lines, reason)
      character(*), intent(in) :: path
      character(len=*), intent(in) :: lines(:)
      character(:), allocatable, intent(out) :: reason
      integer :: unit, ios, i
      reason = ''
      open (newunit=unit, file=path//'.tmp', status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         reason = 'cannot create '//path//'.tmp'
         return
      end if
      do i = 1, size(lines)
         write (unit, '(a)', iostat=ios) trim(lines(i))
         if (ios /= 0) exit
      end do
      close (unit)
      if (ios /= 0) then
         reason = 'cannot write '//path//'.tmp'
         return
      end if
      reason = replace_file(path//'.tmp', path)
   end subroutine rewrite_text
end submodule xcable_io_output_reopen
