!> Checkpoint files: the state of a run between two steps, in HDF5, for
!> `xcable --resume` (driver/simulation.f90 writes and reads them; the run
!> lists its own state, driver/rod_run.f90 exchange_state).
!>
!> Writing is atomic: the file is written as `<path>.tmp`, closed, synced
!> and renamed over `<path>` (system/posix.c), so `<path>` is always the
!> previous complete checkpoint or the new one, also when the process is
!> killed half-way or the node fails.
!>
!> Layout: root attributes
!>   format            'xcable checkpoint', format_version 1
!>   code_version      the version that wrote it (src/xcable/core/version.f90)
!>   compiler_version  for the reader's information
!>   namelist          the fingerprint of the case: the resolved namelist
!>                     without the variables that may differ on --resume
!>   run_id            the identifier of the run, also in its result file
!>   time              simulated time of the state, s (for the reader)
!>   header_checksum   16 hex digits over code_version, namelist and run_id
!>   checksum          16 hex digits over every dataset, in the order written
!> and one 1-D dataset per item of the state (groups run/, progress/,
!> pieces/<p>/, history/, summary/; matrices column by column).
!>
!> Reading checks the header (format, then header_checksum) on opening; the
!> caller compares version and namelist, loads the state (which reads every
!> dataset, each of the size the run expects) and calls verify, which
!> compares the checksum of what was read. A truncated file does not open
!> (HDF5 checks the file's length against its superblock); a damaged one
!> fails a read or a checksum.
module xcable_io_checkpoint
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input, stat_io
   use xcable_io_archive, only: state_archive
   use xcable_io_hdf5_put, only: put_text_attr, put_int_attr, put_real_attr, get_text_attr, get_int_attr
   use xcable_system_posix, only: replace_file, checksum_start, checksum_update, checksum_text
   use hdf5
   use, intrinsic :: iso_c_binding, only: c_int64_t
   use, intrinsic :: iso_fortran_env, only: compiler_version
   implicit none
   private
   public :: checkpoint_file, checkpoint_format_version, remove_checkpoint, checkpoint_path

   !> Version of the layout.
   integer, parameter :: checkpoint_format_version = 1
   !> Name of the format (root attribute format).
   character(len=*), parameter :: format_name = 'xcable checkpoint'

   !> An open checkpoint file, being written or read.
   type, extends(state_archive) :: checkpoint_file
      !> Path of the checkpoint (a new one is written to path//'.tmp').
      character(:), allocatable :: path
      !> HDF5 identifier of the open file (-1: none).
      integer(hid_t) :: file = -1
      !> Link creation properties: intermediate groups are created.
      integer(hid_t) :: links = -1
      !> Whether it is being written.
      logical :: writing = .false.
      !> Checksum of the datasets written or read so far.
      integer(c_int64_t) :: hash = 0
      !> Header as read: version that wrote it, namelist fingerprint, run identifier.
      character(:), allocatable :: code_version, namelist, run_id
   contains
      procedure :: put_reals => checkpoint_put_reals
      procedure :: put_ints => checkpoint_put_ints
      procedure :: get_reals => checkpoint_get_reals
      procedure :: get_ints => checkpoint_get_ints
      procedure :: stored_size => checkpoint_stored_size
      !> Start writing a new checkpoint (to path//'.tmp') with its header.
      procedure :: create => checkpoint_create
      !> Finish writing: checksum, close, and replace path by the new file.
      procedure :: commit => checkpoint_commit
      !> Open an existing checkpoint and read its header.
      procedure :: open => checkpoint_open
      !> After the state has been read: compare its checksum.
      procedure :: verify => checkpoint_verify
      !> Close (and, when writing, remove the unfinished .tmp).
      procedure :: close => checkpoint_close
   end type checkpoint_file

contains

   !> Start a new checkpoint: create path//'.tmp' and write the header.
   subroutine checkpoint_create(self, path, code_version, namelist, run_id, time, error)
      !> Checkpoint.
      class(checkpoint_file), intent(inout) :: self
      !> Path of the checkpoint.
      character(*), intent(in) :: path
      !> Version of the code, namelist fingerprint, identifier of the run.
      character(*), intent(in) :: code_version, namelist, run_id
      !> Simulated time of the state, s.
      real(dp), intent(in) :: time
      !> Error (stat_io) when the file cannot be created.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: access
      integer :: hdferr, status
      integer(c_int64_t) :: header
      self%path = path
      self%writing = .true.
      self%ok = .true.
      self%hash = checksum_start()
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5pcreate_f(H5P_FILE_ACCESS_F, access, hdferr)
      ! As the result file: the 1.8 format, for a namelist attribute above 64 KB.
      call h5pset_libver_bounds_f(access, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, hdferr)
      call h5fcreate_f(path//'.tmp', H5F_ACC_TRUNC_F, self%file, hdferr, access_prp=access)
      call h5pclose_f(access, status)
      if (hdferr /= 0) then
         self%file = -1
         call fatal_error(error, "checkpoint: cannot create '"//path//".tmp': is its directory writable?", stat_io)
         return
      end if
      call h5pcreate_f(H5P_LINK_CREATE_F, self%links, hdferr)
      call h5pset_create_inter_group_f(self%links, 1, hdferr)
      header = checksum_start()
      call checksum_update(header, code_version)
      call checksum_update(header, namelist)
      call checksum_update(header, run_id)
      call put_text_attr(self%file, 'format', format_name, self%ok)
      call put_int_attr(self%file, 'format_version', checkpoint_format_version, self%ok)
      call put_text_attr(self%file, 'code_version', code_version, self%ok)
      call put_text_attr(self%file, 'compiler_version', compiler_version(), self%ok)
      call put_text_attr(self%file, 'namelist', namelist, self%ok)
      call put_text_attr(self%file, 'run_id', run_id, self%ok)
      call put_real_attr(self%file, 'time', time, self%ok)
      call put_text_attr(self%file, 'header_checksum', checksum_text(header), self%ok)
      if (.not. self%ok) then
         call self%close()
         call fatal_error(error, "checkpoint: writing the header of '"//path//".tmp' failed", stat_io)
      end if
   end subroutine checkpoint_create

   !> Finish a checkpoint being written: the checksum, then close the file
   !> and put it in place of path (fsync, rename, fsync of the directory).
   subroutine checkpoint_commit(self, error)
      !> Checkpoint.
      class(checkpoint_file), intent(inout) :: self
      !> Error (stat_io) when a write failed or the file cannot be put in place.
      type(error_type), allocatable, intent(out) :: error
      integer :: hdferr
      character(:), allocatable :: why
      call put_text_attr(self%file, 'checksum', checksum_text(self%hash), self%ok)
      call h5pclose_f(self%links, hdferr)
      self%links = -1
      call h5fclose_f(self%file, hdferr)
      self%file = -1
      if (.not. self%ok .or. hdferr /= 0) then
         if (.not. allocated(self%message)) self%message = 'closing the file failed'
         call fatal_error(error, "checkpoint: writing '"//self%path//".tmp' failed: "//self%message, stat_io)
         call delete_file(self%path//'.tmp')
         return
      end if
      why = replace_file(self%path//'.tmp', self%path)
      if (len(why) > 0) then
         call fatal_error(error, "checkpoint: cannot rename '"//self%path//".tmp' to '"//self%path//"': "//why, stat_io)
         call delete_file(self%path//'.tmp')
      end if
      self%writing = .false.
   end subroutine checkpoint_commit

   !> Open a checkpoint for reading and check its header: the format, and that
   !> the header is intact. version, namelist and run_id are then those it holds.
   subroutine checkpoint_open(self, path, error)
      !> Checkpoint.
      class(checkpoint_file), intent(inout) :: self
      !> Path.
      character(*), intent(in) :: path
      !> Error (stat_input) naming what is wrong with the file.
      type(error_type), allocatable, intent(out) :: error
      integer :: hdferr, version
      logical :: ok
      character(:), allocatable :: format, stored
      integer(c_int64_t) :: header
      self%path = path
      self%writing = .false.
      self%ok = .true.
      self%hash = checksum_start()
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, self%file, hdferr)
      if (hdferr /= 0) then
         self%file = -1
         call fatal_error(error, "checkpoint '"//path//"' cannot be read: HDF5 cannot open it (truncated, "// &
                          'damaged or not a checkpoint)', stat_input)
         return
      end if
      ok = .true.
      call get_text_attr(self%file, 'format', format, ok)
      call get_int_attr(self%file, 'format_version', version, ok)
      if (.not. ok .or. format /= format_name) then
         call fatal_error(error, "'"//path//"' is not an xcable checkpoint (no format attribute '"//format_name//"')", &
                          stat_input)
         call self%close()
         return
      end if
      if (version /= checkpoint_format_version) then
         call fatal_error(error, "checkpoint '"//path//"' has layout version "//int_text(version)//', this xcable '// &
                          'reads '//int_text(checkpoint_format_version), stat_input)
         call self%close()
         return
      end if
      call get_text_attr(self%file, 'code_version', self%code_version, ok)
      call get_text_attr(self%file, 'namelist', self%namelist, ok)
      call get_text_attr(self%file, 'run_id', self%run_id, ok)
      call get_text_attr(self%file, 'header_checksum', stored, ok)
      header = checksum_start()
      call checksum_update(header, self%code_version)
      call checksum_update(header, self%namelist)
      call checksum_update(header, self%run_id)
      if (.not. ok .or. stored /= checksum_text(header)) then
         call fatal_error(error, "checkpoint '"//path//"' is damaged: its header does not match its checksum", stat_input)
         call self%close()
      end if
   end subroutine checkpoint_open

   !> Compare the checksum of the state read with the one stored; close the file.
   subroutine checkpoint_verify(self, error)
      !> Checkpoint, open for reading, its state read.
      class(checkpoint_file), intent(inout) :: self
      !> Error (stat_input) when a read failed or the checksum differs.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: stored
      logical :: ok
      ok = .true.
      call get_text_attr(self%file, 'checksum', stored, ok)
      if (.not. self%ok) then
         call fatal_error(error, "checkpoint '"//self%path//"' is damaged: "//self%message, stat_input)
      else if (.not. ok .or. stored /= checksum_text(self%hash)) then
         call fatal_error(error, "checkpoint '"//self%path//"' is damaged: its content does not match its checksum", &
                          stat_input)
      end if
      call self%close()
   end subroutine checkpoint_verify

   !> Close the file; a checkpoint left unfinished loses its .tmp file.
   subroutine checkpoint_close(self)
      !> Checkpoint.
      class(checkpoint_file), intent(inout) :: self
      integer :: hdferr
      if (self%links >= 0) call h5pclose_f(self%links, hdferr)
      self%links = -1
      if (self%file >= 0) call h5fclose_f(self%file, hdferr)
      self%file = -1
      if (self%writing) call delete_file(self%path//'.tmp')
      self%writing = .false.
   end subroutine checkpoint_close

   !> Store reals as a 1-D dataset (state_archive).
   subroutine checkpoint_put_reals(self, name, values)
      class(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      call write_dataset(self, name, H5T_NATIVE_DOUBLE, size(values), reals=values)
      call checksum_update(self%hash, values)
   end subroutine checkpoint_put_reals

   !> Store integers as a 1-D dataset (state_archive).
   subroutine checkpoint_put_ints(self, name, values)
      class(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      integer, intent(in) :: values(:)
      call write_dataset(self, name, H5T_NATIVE_INTEGER, size(values), ints=values)
      call checksum_update(self%hash, values)
   end subroutine checkpoint_put_ints

   !> Read exactly size(values) reals (state_archive).
   subroutine checkpoint_get_reals(self, name, values)
      class(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      real(dp), intent(out) :: values(:)
      values = 0
      call read_dataset(self, name, H5T_NATIVE_DOUBLE, size(values), reals=values)
      call checksum_update(self%hash, values)
   end subroutine checkpoint_get_reals

   !> Read exactly size(values) integers (state_archive).
   subroutine checkpoint_get_ints(self, name, values)
      class(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      integer, intent(out) :: values(:)
      values = 0
      call read_dataset(self, name, H5T_NATIVE_INTEGER, size(values), ints=values)
      call checksum_update(self%hash, values)
   end subroutine checkpoint_get_ints

   !> Number of values of a dataset (-1: none; state_archive).
   integer function checkpoint_stored_size(self, name) result(n)
      class(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1), maxdims(1)
      integer :: hdferr, rank
      n = -1
      call h5dopen_f(self%file, name, dset, hdferr)
      if (hdferr /= 0) return
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_ndims_f(space, rank, hdferr)
      if (hdferr == 0 .and. rank == 1) then
         call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
         if (hdferr >= 0) n = int(dims(1))
      end if
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
   end function checkpoint_stored_size

   !> Write a 1-D dataset of n reals or integers (groups on the path are created).
   subroutine write_dataset(self, name, type, n, reals, ints)
      type(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      integer(hid_t), intent(in) :: type
      integer, intent(in) :: n
      real(dp), intent(in), optional :: reals(:)
      integer, intent(in), optional :: ints(:)
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1)
      integer :: hdferr, err
      if (.not. self%ok) return
      dims = n
      call h5screate_simple_f(1, dims, space, hdferr)
      call h5dcreate_f(self%file, name, type, space, dset, err, lcpl_id=self%links)
      if (err /= 0) then
         call self%fail('cannot create the dataset '//name)
      else
         if (present(reals)) call h5dwrite_f(dset, type, reals, dims, err)
         if (present(ints)) call h5dwrite_f(dset, type, ints, dims, err)
         if (err /= 0) call self%fail('cannot write the dataset '//name)
         call h5dclose_f(dset, hdferr)
      end if
      call h5sclose_f(space, hdferr)
   end subroutine write_dataset

   !> Read a 1-D dataset of exactly n reals or integers.
   subroutine read_dataset(self, name, type, n, reals, ints)
      type(checkpoint_file), intent(inout) :: self
      character(*), intent(in) :: name
      integer(hid_t), intent(in) :: type
      integer, intent(in) :: n
      real(dp), intent(inout), optional :: reals(:)
      integer, intent(inout), optional :: ints(:)
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: hdferr, err, stored
      if (.not. self%ok) return
      stored = self%stored_size(name)
      if (stored /= n) then
         if (stored < 0) then
            call self%fail('the dataset '//name//' is missing or unreadable')
         else
            call self%fail('the dataset '//name//' holds '//int_text(stored)//' values, the run needs '//int_text(n))
         end if
         return
      end if
      dims = n
      call h5dopen_f(self%file, name, dset, err)
      if (err /= 0) then
         call self%fail('the dataset '//name//' cannot be opened')
         return
      end if
      if (present(reals)) call h5dread_f(dset, type, reals, dims, err)
      if (present(ints)) call h5dread_f(dset, type, ints, dims, err)
      if (err /= 0) call self%fail('the dataset '//name//' cannot be read')
      call h5dclose_f(dset, hdferr)
   end subroutine read_dataset

   !> The checkpoint of a result file: its path with '.ckpt' appended.
   pure function checkpoint_path(result_path) result(path)
      !> Path of the result file (&output file).
      character(*), intent(in) :: result_path
      character(:), allocatable :: path
      path = result_path//'.ckpt'
   end function checkpoint_path

   !> Remove a checkpoint and an unfinished one beside it (path.tmp), if they exist.
   subroutine remove_checkpoint(path)
      !> Path of the checkpoint.
      character(*), intent(in) :: path
      call delete_file(path)
      call delete_file(path//'.tmp')
   end subroutine remove_checkpoint

   !> An integer as text.
   function int_text(i) result(s)
      integer, intent(in) :: i
      character(:), allocatable :: s
      character(len=24) :: buffer
      write (buffer, '(i0)') i
      s = trim(buffer)
   end function int_text

   !> Remove a file if it exists.
   subroutine delete_file(path)
      character(*), intent(in) :: path
      integer :: unit, ios
      logical :: exists
      inquire (file=path, exist=exists)
      if (.not. exists) return
      open (newunit=unit, file=path, status='old', iostat=ios)
      if (ios == 0) close (unit, status='delete')
   end subroutine delete_file
end module xcable_io_checkpoint
