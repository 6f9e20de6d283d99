!> Small writers and readers of HDF5 datasets and attributes, shared by the
!> result file (io/output.f90), the checkpoints (io/checkpoint.f90) and the
!> sweep collector (example/sweep_collect.f90).
!>
!> Each takes a logical `ok` that it clears on any HDF5 error and never sets,
!> so that a caller can write many items and check once. Attributes are
!> replaced if they exist (the status of a result file is rewritten). A
!> reader of an absent attribute clears ok and leaves its value empty.
module xcable_io_hdf5
   use xcable_kinds, only: dp
   use hdf5
   implicit none
   private
   public :: put_real_vector, put_int_vector, put_text_vector, put_real_attr, put_int_attr, put_text_attr
   public :: get_text_attr, get_real_attr, get_int_attr, delete_attr

contains

   !> A 1-D real dataset, with a `units` attribute when units is given and not empty.
   subroutine put_real_vector(loc, name, values, ok, units)
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
            if (len(units) > 0) call put_text_attr(dset, 'units', units, ok)
         end if
         call h5dclose_f(dset, hdferr)
      end if
      call h5sclose_f(space, hdferr)
   end subroutine put_real_vector

   !> A 1-D integer dataset.
   subroutine put_int_vector(loc, name, values, ok)
      !> File or group.
      integer(hid_t), intent(in) :: loc
      !> Dataset name.
      character(*), intent(in) :: name
      !> Values.
      integer, intent(in) :: values(:)
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
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

   !> A fixed-length string attribute (replaced if it exists; an empty text is
   !> written as one blank, since HDF5 has no zero-length fixed string).
   subroutine put_text_attr(loc, name, text, ok)
      !> File, group or dataset.
      integer(hid_t), intent(in) :: loc
      !> Attribute name.
      character(*), intent(in) :: name
      !> Value.
      character(*), intent(in) :: text
      !> Cleared on an HDF5 error.
      logical, intent(inout) :: ok
      integer(hid_t) :: attr, space, string_type
      integer :: hdferr
      call drop_attr(loc, name, ok)
      call h5screate_f(H5S_SCALAR_F, space, hdferr)
      call h5tcopy_f(H5T_NATIVE_CHARACTER, string_type, hdferr)
      call h5tset_size_f(string_type, int(max(len(text), 1), size_t), hdferr)
      call h5acreate_f(loc, name, string_type, space, attr, hdferr)
      if (hdferr /= 0) then
         ok = .false.
      else
         if (len(text) > 0) then
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
      integer :: hdferr, class
      logical :: exists
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
      if (hdferr /= 0 .or. class /= H5T_STRING_F) then
         ok = .false.
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
end module xcable_io_hdf5
