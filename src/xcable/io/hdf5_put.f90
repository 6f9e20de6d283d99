!> Small writers and readers of HDF5 datasets and attributes, shared by the
!> result file (io/output.f90), the checkpoints (io/checkpoint.f90) and the
!> sweep collector (example/sweep_collect.f90).
!>
!> Each takes a logical `ok` that it clears on any HDF5 error and never sets,
!> so that a caller can write many items and check once. Attributes are
!> replaced if they exist (the status of a result file is rewritten). A
!> reader of an absent attribute clears ok and leaves its value empty.
!>
!> Text attributes are fixed-length strings, or with `utf8` variable-length
!> UTF-8 strings (the result file's: h5py reads those as str, fixed-length ones
!> as bytes); get_text_attr reads both.
module xcable_io_hdf5_put
   use xcable_core_kinds, only: dp
   use hdf5
   use h5ds, only: h5dsset_scale_f, h5dsattach_scale_f, h5dsis_attached_f, h5dsset_label_f
   use, intrinsic :: iso_c_binding, only: c_ptr, c_char, c_loc, c_f_pointer, c_size_t, c_null_char, c_associated, c_int
   implicit none
   private
   public :: put_real_vector, put_int_vector, put_text_vector, put_real_attr, put_int_attr, put_text_attr
   public :: open_scale, attach, append
   public :: get_text_attr, get_real_attr, get_int_attr, delete_attr

contains

   !> A 1-D real dataset, with a `units` attribute when units is given and not empty, and a
   !> `description` when one is given (both UTF-8 text).
   subroutine put_real_vector(loc, name, values, ok, units, description)
      !> File or group.
      integer(hid_t), intent(in) :: loc
      !> Dataset name.
      character(*), intent(in) :: name
      !> Values.
      real(dp), intent(in) :: values(:)
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      !> Units.
      character(*), intent(in), optional :: units
      !> One line saying what it holds.
      character(*), intent(in), optional :: description
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1)
      integer :: hdferr
      real(dp), allocatable :: packed(:)
      dims = size(values)
      call h5screate_simple_f(1, dims, space, hdferr)
      call h5dcreate_f(loc, name, H5T_NATIVE_DOUBLE, space, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         if (is_contiguous(values)) then
            call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, dims, hdferr)
         else
            ! A strided section (one end's history): packed here, not by a hidden temporary
            ! (which a debug build reports at run time).
            packed = values
            call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, packed, dims, hdferr)
         end if
         ok = ok .and. hdferr == 0
         if (present(units)) then
            if (len(units) > 0) call put_text_attr(dset, 'units', units, ok, utf8=.true.)
         end if
         if (present(description)) call put_text_attr(dset, 'description', description, ok, utf8=.true.)
         call h5dclose_f(dset, hdferr)
      end if
      call h5sclose_f(space, hdferr)
   end subroutine put_real_vector

   !> A 1-D integer dataset, with `units` and `description` attributes when given (UTF-8 text).
   subroutine put_int_vector(loc, name, values, ok, units, description)
      !> File or group.
      integer(hid_t), intent(in) :: loc
      !> Dataset name.
      character(*), intent(in) :: name
      !> Values.
      integer, intent(in) :: values(:)
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      !> Units and one line saying what it holds.
      character(*), intent(in), optional :: units, description
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(1)
      integer :: hdferr
      dims = size(values)
      call h5screate_simple_f(1, dims, space, hdferr)
      call h5dcreate_f(loc, name, H5T_NATIVE_INTEGER, space, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         call h5dwrite_f(dset, H5T_NATIVE_INTEGER, values, dims, hdferr)
         ok = ok .and. hdferr == 0
         if (present(units)) call put_text_attr(dset, 'units', units, ok, utf8=.true.)
         if (present(description)) call put_text_attr(dset, 'description', description, ok, utf8=.true.)
         call h5dclose_f(dset, hdferr)
      end if
      call h5sclose_f(space, hdferr)
   end subroutine put_int_vector

   !> A 1-D dataset of fixed-length, null-padded strings, as long as the longest
   !> trimmed entry (so h5py reads 'failed', not 'failed  ').
   subroutine put_text_vector(loc, name, values, ok)
      !> File or group.
      integer(hid_t), intent(in) :: loc
      !> Dataset name.
      character(*), intent(in) :: name
      !> Values.
      character(len=*), intent(in) :: values(:)
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      integer(hid_t) :: dset, space, string_type
      integer(hsize_t) :: dims(1)
      integer :: hdferr, length, i
      character(len=:), allocatable :: buffer(:)
      length = 1
      if (size(values) > 0) length = max(1, maxval(len_trim(values)))
      allocate (character(len=length) :: buffer(size(values)))
      do i = 1, size(values)
         buffer(i) = repeat(achar(0), length)
         buffer(i)(1:len_trim(values(i))) = values(i)(1:len_trim(values(i)))
      end do
      dims = size(values)
      call h5screate_simple_f(1, dims, space, hdferr)
      call h5tcopy_f(H5T_NATIVE_CHARACTER, string_type, hdferr)
      call h5tset_size_f(string_type, int(length, size_t), hdferr)
      call h5tset_strpad_f(string_type, H5T_STR_NULLPAD_F, hdferr)
      call h5dcreate_f(loc, name, string_type, space, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         call h5dwrite_f(dset, string_type, buffer, dims, hdferr)
         ok = ok .and. hdferr == 0
         call h5dclose_f(dset, hdferr)
      end if
      call h5tclose_f(string_type, hdferr)
      call h5sclose_f(space, hdferr)
   end subroutine put_text_vector

   !> A real attribute (replaced if it exists).
   subroutine put_real_attr(loc, name, value, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      real(dp), intent(in) :: value
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      integer(hid_t) :: attr, space
      integer :: hdferr
      call drop_attr(loc, name, ok)
      call h5screate_f(H5S_SCALAR_F, space, hdferr)
      call h5acreate_f(loc, name, H5T_NATIVE_DOUBLE, space, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         call h5awrite_f(attr, H5T_NATIVE_DOUBLE, value, [1_hsize_t], hdferr)
         ok = ok .and. hdferr == 0
         call h5aclose_f(attr, hdferr)
      end if
      call h5sclose_f(space, hdferr)
   end subroutine put_real_attr

   !> An integer attribute (replaced if it exists).
   subroutine put_int_attr(loc, name, value, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      integer, intent(in) :: value
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      integer(hid_t) :: attr, space
      integer :: hdferr
      call drop_attr(loc, name, ok)
      call h5screate_f(H5S_SCALAR_F, space, hdferr)
      call h5acreate_f(loc, name, H5T_NATIVE_INTEGER, space, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         call h5awrite_f(attr, H5T_NATIVE_INTEGER, value, [1_hsize_t], hdferr)
         ok = ok .and. hdferr == 0
         call h5aclose_f(attr, hdferr)
      end if
      call h5sclose_f(space, hdferr)
   end subroutine put_int_attr

   !> A string attribute (replaced if it exists): fixed-length (an empty text is
   !> written as one blank, since HDF5 has no zero-length fixed string), or with
   !> utf8 a variable-length UTF-8 string (an empty text stays empty).
   subroutine put_text_attr(loc, name, text, ok, utf8)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      character(*), intent(in) :: text
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      !> Write a variable-length UTF-8 string (default: fixed-length).
      logical, intent(in), optional :: utf8
      integer(hid_t) :: attr, space, string_type
      integer :: hdferr, i
      logical :: variable
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), target :: pointers(1)
      type(c_ptr) :: buffer
      variable = .false.
      if (present(utf8)) variable = utf8
      call drop_attr(loc, name, ok)
      call h5screate_f(H5S_SCALAR_F, space, hdferr)
      if (variable) then
         call h5tcopy_f(H5T_STRING, string_type, hdferr)
         call h5tset_cset_f(string_type, H5T_CSET_UTF8_F, hdferr)
      else
         call h5tcopy_f(H5T_NATIVE_CHARACTER, string_type, hdferr)
         call h5tset_size_f(string_type, int(max(len(text), 1), size_t), hdferr)
      end if
      call h5acreate_f(loc, name, string_type, space, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         if (variable) then
            allocate (chars(len(text) + 1))
            do i = 1, len(text)
               chars(i) = text(i:i)
            end do
            chars(len(text) + 1) = c_null_char
            pointers(1) = c_loc(chars)
            buffer = c_loc(pointers)
            call h5awrite_f(attr, string_type, buffer, hdferr)
         else if (len(text) > 0) then
            call h5awrite_f(attr, string_type, text, [1_hsize_t], hdferr)
         else
            call h5awrite_f(attr, string_type, ' ', [1_hsize_t], hdferr)
         end if
         ok = ok .and. hdferr == 0
         call h5aclose_f(attr, hdferr)
      end if
      call h5tclose_f(string_type, hdferr)
      call h5sclose_f(space, hdferr)
   end subroutine put_text_attr

   !> A string attribute, trimmed ('' and ok cleared when absent or not a string).
   subroutine get_text_attr(loc, name, text, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      character(:), allocatable, intent(out) :: text
      !> Cleared on an HDF5 error or an absent attribute.
      logical, intent(inout) :: ok
      integer(hid_t) :: attr, file_type, memory_type
      integer(size_t) :: length
      integer :: hdferr, class, cset
      logical :: exists, variable
      text = ''
      call h5aexists_f(loc, name, exists, hdferr)
      if (hdferr /= 0 .or. .not. exists) then
         ok = .false.
         return
      end if
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5aget_type_f(attr, file_type, hdferr)
      call h5tget_class_f(file_type, class, hdferr)
      call h5tget_size_f(file_type, length, hdferr)
      variable = .false.
      if (hdferr == 0 .and. class == H5T_STRING_F) call h5tis_variable_str_f(file_type, variable, hdferr)
      if (hdferr /= 0 .or. class /= H5T_STRING_F) then
         ok = .false.
      else if (variable) then
         call h5tget_cset_f(file_type, cset, hdferr)
         call h5tcopy_f(H5T_STRING, memory_type, hdferr)
         call h5tset_cset_f(memory_type, cset, hdferr)
         call read_variable(text)
         call h5tclose_f(memory_type, hdferr)
      else
         deallocate (text)
         allocate (character(len=int(length)) :: text)
         call h5tcopy_f(H5T_NATIVE_CHARACTER, memory_type, hdferr)
         call h5tset_size_f(memory_type, length, hdferr)
         call h5aread_f(attr, memory_type, text, [1_hsize_t], hdferr)
         if (hdferr /= 0) then
            ok = .false.
            text = ''
         end if
         call h5tclose_f(memory_type, hdferr)
         text = trim(text)
      end if
      call h5tclose_f(file_type, hdferr)
      call h5aclose_f(attr, hdferr)

   contains

      !> Read the variable-length string of attr (its memory freed by HDF5's allocator).
      subroutine read_variable(value)
         character(:), allocatable, intent(out) :: value
         type(c_ptr), target :: pointers(1)
         type(c_ptr) :: buffer
         character(kind=c_char), pointer :: chars(:)
         integer :: n, i
         interface
            function c_strlen(s) bind(c, name='strlen') result(n)
               import :: c_ptr, c_size_t
               type(c_ptr), value :: s
               integer(c_size_t) :: n
            end function c_strlen
            function h5_free_memory(p) bind(c, name='H5free_memory') result(status)
               import :: c_ptr, c_int
               type(c_ptr), value :: p
               integer(c_int) :: status
            end function h5_free_memory
         end interface
         value = ''
         buffer = c_loc(pointers)
         call h5aread_f(attr, memory_type, buffer, hdferr)
         if (hdferr /= 0) then
            ok = .false.
            return
         end if
         if (.not. c_associated(pointers(1))) return
         n = int(c_strlen(pointers(1)))
         call c_f_pointer(pointers(1), chars, [n])
         value = repeat(' ', n)
         do i = 1, n
            value(i:i) = chars(i)
         end do
         if (h5_free_memory(pointers(1)) < 0) ok = .false.
         value = trim(value)
      end subroutine read_variable
   end subroutine get_text_attr

   !> A real scalar attribute (0 and ok cleared when absent).
   subroutine get_real_attr(loc, name, value, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      real(dp), intent(out) :: value
      !> Cleared on an HDF5 error or an absent attribute.
      logical, intent(inout) :: ok
      integer(hid_t) :: attr
      integer :: hdferr
      logical :: exists
      value = 0
      call h5aexists_f(loc, name, exists, hdferr)
      if (hdferr /= 0 .or. .not. exists) then
         ok = .false.
         return
      end if
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5aread_f(attr, H5T_NATIVE_DOUBLE, value, [1_hsize_t], hdferr)
      if (hdferr /= 0) ok = .false.
      call h5aclose_f(attr, hdferr)
   end subroutine get_real_attr

   !> An integer scalar attribute (0 and ok cleared when absent).
   subroutine get_int_attr(loc, name, value, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      integer, intent(out) :: value
      !> Cleared on an HDF5 error or an absent attribute.
      logical, intent(inout) :: ok
      integer(hid_t) :: attr
      integer :: hdferr
      logical :: exists
      value = 0
      call h5aexists_f(loc, name, exists, hdferr)
      if (hdferr /= 0 .or. .not. exists) then
         ok = .false.
         return
      end if
      call h5aopen_f(loc, name, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5aread_f(attr, H5T_NATIVE_INTEGER, value, [1_hsize_t], hdferr)
      if (hdferr /= 0) ok = .false.
      call h5aclose_f(attr, hdferr)
   end subroutine get_int_attr

   !> Delete an attribute if it exists (ok cleared on an HDF5 error).
   subroutine delete_attr(loc, name, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      call drop_attr(loc, name, ok)
   end subroutine delete_attr

   !> Delete the attribute name of loc if it exists.
   subroutine drop_attr(loc, name, ok)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      logical, intent(inout) :: ok
      logical :: exists
      integer :: hdferr
      call h5aexists_f(loc, name, exists, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else if (exists) then
         call h5adelete_f(loc, name, hdferr)
         ok = ok .and. hdferr == 0
      end if
   end subroutine drop_attr
   !> Open the dataset name of loc as a dimension scale called scale_name (made one if it is
   !> not yet); scale is -1 when the dataset does not exist.
   subroutine open_scale(loc, name, scale_name, scale, ok)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name, scale_name
      integer(hid_t), intent(out) :: scale
      logical, intent(inout) :: ok
      integer :: hdferr
      logical :: exists
      scale = -1
      call h5lexists_f(loc, name, exists, hdferr)
      if (.not. exists) return
      call h5dopen_f(loc, name, scale, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         scale = -1
         return
      end if
      call h5aexists_f(scale, 'CLASS', exists, hdferr)
      if (.not. exists) then
         call h5dsset_scale_f(scale, hdferr, scale_name)
         ok = ok .and. hdferr == 0
      end if
   end subroutine open_scale

   !> Attach the dimension scale `scale` to dimension `dimension` (0 the slowest, as h5py
   !> and C count) of the dataset name of loc, labelled `label`, unless it is attached
   !> already; nothing when the dataset does not exist.
   subroutine attach(scale, loc, name, dimension, label, ok, fresh)
      integer(hid_t), intent(in) :: scale, loc
      character(*), intent(in) :: name, label
      integer, intent(in) :: dimension
      logical, intent(inout) :: ok
      !> The dataset is known to have no scale on this dimension yet (no check).
      logical, intent(in), optional :: fresh
      integer(hid_t) :: dset
      integer :: hdferr, index
      logical :: exists, attached
      call h5lexists_f(loc, name, exists, hdferr)
      if (.not. exists) return
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      ! HDF5 1.10's Fortran interface takes the dimension as C counts it, from 1 (checked with
      ! h5py: test/test_outputs.py).
      index = dimension + 1
      attached = .false.
      if (.not. present(fresh)) then
         call h5dsis_attached_f(dset, scale, index, attached, hdferr)
         if (hdferr /= 0) attached = .false.
      end if
      if (.not. attached) then
         call h5dsattach_scale_f(dset, scale, index, hdferr)
         ok = ok .and. hdferr == 0
         call h5dsset_label_f(dset, index, label, hdferr)
         ok = ok .and. hdferr == 0
      end if
      call h5dclose_f(dset, hdferr)
   end subroutine attach

   !> Append a value (rank 1) or a row of node values (rank 2) to the
   !> extendible dataset name, created on first use.
   !> ok is cleared when the dataset cannot be created or opened, extended or
   !> written.
   subroutine append(loc, name, values, rank, ok, kept)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      integer, intent(in) :: rank
      logical, intent(inout) :: ok
      !> The dataset kept open: used when >= 0, else set to the dataset opened
      !> (which then stays open); absent: the dataset is closed again.
      integer(hid_t), intent(inout), optional :: kept
      integer :: hdferr, err
      integer(hid_t) :: dset, space, memspace, plist
      integer(hsize_t) :: dims(2), maxdims(2), offset(2), count(2)
      logical :: exists, open_already
      count = [int(size(values), hsize_t), 1_hsize_t]
      err = 0
      open_already = .false.
      if (present(kept)) open_already = kept >= 0
      if (open_already) then
         dset = kept
      else
         call h5lexists_f(loc, name, exists, hdferr)
         if (.not. exists) then
            call create_dataset()
         else
            call h5dopen_f(loc, name, dset, err)
         end if
         if (err /= 0) then
            ok = .false.
            return
         end if
         if (present(kept)) kept = dset
      end if
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
      call h5sclose_f(space, hdferr)
      if (rank == 1) then
         offset(1) = dims(1)
         dims(1) = dims(1) + 1
         count(1) = 1
      else
         offset = [0_hsize_t, dims(2)]
         dims(2) = dims(2) + 1
      end if
      call h5dset_extent_f(dset, dims(1:rank), hdferr)
      ok = ok .and. hdferr == 0
      call h5dget_space_f(dset, space, hdferr)
      call h5sselect_hyperslab_f(space, H5S_SELECT_SET_F, offset(1:rank), count(1:rank), hdferr)
      call h5screate_simple_f(rank, count(1:rank), memspace, hdferr)
      call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, count(1:rank), hdferr, memspace, space)
      ok = ok .and. hdferr == 0
      call h5sclose_f(memspace, hdferr)
      call h5sclose_f(space, hdferr)
      if (.not. present(kept)) call h5dclose_f(dset, hdferr)
   contains
      subroutine create_dataset()
         call h5pcreate_f(H5P_DATASET_CREATE_F, plist, hdferr)
         if (rank == 1) then
            dims(1) = 0
            maxdims(1) = H5S_UNLIMITED_F
            call h5pset_chunk_f(plist, 1, [64_hsize_t], hdferr)
         else
            dims = [count(1), 0_hsize_t]
            maxdims = [count(1), H5S_UNLIMITED_F]
            call h5pset_chunk_f(plist, 2, count, hdferr)
         end if
         call h5screate_simple_f(rank, dims(1:rank), space, hdferr, maxdims(1:rank))
         call h5dcreate_f(loc, name, H5T_NATIVE_DOUBLE, space, dset, err, plist)
         call h5sclose_f(space, hdferr)
         call h5pclose_f(plist, hdferr)
      end subroutine create_dataset
   end subroutine append
end module xcable_io_hdf5_put
