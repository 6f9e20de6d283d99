!> The XDMF sidecar of a result file (&output xdmf): a small XML text beside
!> the HDF5 file that tells ParaView, VisIt or any XDMF reader how to read the
!> snapshots as a time series of polylines.
!>
!> The sidecar holds no numbers of the run: every snapshot is a grid whose
!> points are row i of /x, /y (a 3-D run; zeros for a planar one) and /z, and
!> whose node attributes are row i of the other snapshot fields, all read from
!> the HDF5 file by hyperslab. The cells are the segments between
!> neighbouring nodes of a piece (the segment across a break is left out),
!> written once and referenced by every grid. Times come from /time.
!>
!> It is written from the finished file (after its status), so a resumed run
!> gets the same sidecar as an uninterrupted one, and through a temporary
!> file renamed into place, so an interrupted write leaves no partial sidecar.
!> The sidecar's own path is the result's with the extension .xmf.
module xcable_io_xdmf
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_io
   use xcable_core_strings, only: str
   use xcable_driver_records, only: field_names, field3_names
   use xcable_system_posix, only: replace_file
   use hdf5
   implicit none
   private
   public :: write_xdmf, xdmf_path, remove_xdmf, probe_xdmf

contains

   !> Path of the sidecar of a result file: its stem (without the extension) and '.xmf'.
   pure function xdmf_path(path) result(sidecar)
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      character(:), allocatable :: sidecar
      integer :: dot
      dot = index(path, '.', back=.true.)
      if (dot <= index(path, '/', back=.true.)) dot = len(path) + 1
      sidecar = path(1:dot - 1)//'.xmf'
   end function xdmf_path

   !> Remove the sidecar of a result file (and a partial one), if there is one:
   !> a new run replaces the file it describes.
   subroutine remove_xdmf(path)
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      integer :: unit, ios
      character(:), allocatable :: sidecar
      sidecar = xdmf_path(path)
      open (newunit=unit, file=sidecar, status='old', iostat=ios)
      if (ios == 0) close (unit, status='delete')
      open (newunit=unit, file=sidecar//'.part', status='old', iostat=ios)
      if (ios == 0) close (unit, status='delete')
   end subroutine remove_xdmf

   !> Whether the sidecar can be written: its temporary file is created and
   !> removed (before a run, so that a run is refused before it starts rather
   !> than losing its sidecar at the end).
   subroutine probe_xdmf(path, error)
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      !> Error when the sidecar cannot be created.
      type(error_type), allocatable, intent(out) :: error
      integer :: unit, ios
      character(len=256) :: msg
      open (newunit=unit, file=xdmf_path(path)//'.part', status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, 'cannot create '//xdmf_path(path)//'.part (&output xdmf = .true.): '//trim(msg), &
                          stat_io)
         return
      end if
      close (unit, status='delete')
   end subroutine probe_xdmf

   !> Write the sidecar of the closed result file at path.
   subroutine write_xdmf(path, piece_starts, error)
      !> Path of the HDF5 file (closed).
      character(*), intent(in) :: path
      !> Output columns where a new piece starts (empty: one piece).
      integer, intent(in) :: piece_starts(:)
      !> Error when the file cannot be read or the sidecar not written.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: file
      integer :: hdferr, unit, ios, n, m, i, k, q, segments
      real(dp), allocatable :: time(:)
      character(len=14), allocatable :: attributes(:)
      character(:), allocatable :: sidecar, temporary, h5name, message
      character(len=256) :: msg
      logical :: has_y, ok

      call h5open_f(hdferr)
      call h5fopen_f(path, H5F_ACC_RDONLY_F, file, hdferr)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot open '"//path//"' to write its XDMF sidecar (&output xdmf)", stat_io)
         return
      end if
      ok = .true.
      call read_vector(file, 'time', time, ok)
      n = dataset_extent(file, 'x', 2, ok)
      has_y = exists(file, 'y')
      allocate (attributes(0))
      do q = 1, size(field_names)
         if (field_names(q) == 'x' .or. field_names(q) == 'z') cycle
         if (exists(file, trim(field_names(q)))) attributes = [attributes, field_names(q)]
      end do
      do q = 1, size(field3_names)
         if (field3_names(q) == 'y') cycle
         if (exists(file, trim(field3_names(q)))) attributes = [attributes, field3_names(q)]
      end do
      call h5fclose_f(file, hdferr)
      if (.not. ok .or. n <= 0) then
         call fatal_error(error, "'"//path//"' has no snapshots of x and z to describe (&output xdmf needs "// &
                          "&output fields with x and z)", stat_io)
         return
      end if
      m = size(time)

      h5name = path(index(path, '/', back=.true.) + 1:)
      sidecar = xdmf_path(path)
      temporary = sidecar//'.part'
      open (newunit=unit, file=temporary, status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, 'cannot create '//temporary//' (&output xdmf): '//trim(msg), stat_io)
         return
      end if
      segments = n - 1 - count(piece_starts > 1 .and. piece_starts <= n)
      write (unit, '(a)') '<?xml version="1.0" ?>'
      write (unit, '(a)') '<Xdmf Version="2.0">'
      write (unit, '(a)') ' <Domain>'
      write (unit, '(a)') '  <Topology Name="segments" TopologyType="Polyline" NodesPerElement="2" '// &
         'NumberOfElements="'//str(segments)//'">'
      write (unit, '(a)') '   <DataItem Dimensions="'//str(segments)//' 2" NumberType="Int" Format="XML">'
      do k = 1, n - 1
         if (any(piece_starts == k + 1)) cycle
         write (unit, '(4x,a)') str(k - 1)//' '//str(k)
      end do
      write (unit, '(a)') '   </DataItem>'
      write (unit, '(a)') '  </Topology>'
      if (.not. has_y) then
         write (unit, '(a)') '  <DataItem Name="plane" Dimensions="'//str(n)//'" NumberType="Float" '// &
            'Precision="8" Format="XML">'
         write (unit, '(4x,a)') repeat('0 ', n)
         write (unit, '(a)') '  </DataItem>'
      end if
      write (unit, '(a)') '  <Grid Name="snapshots" GridType="Collection" CollectionType="Temporal">'
      do i = 1, m
         write (unit, '(a)') '   <Grid Name="t'//str(i - 1)//'" GridType="Uniform">'
         write (unit, '(a,es24.16e3,a)') '    <Time Value="', time(i), '"/>'
         write (unit, '(a)') '    <Topology Reference="/Xdmf/Domain/Topology[@Name=''segments'']"/>'
         write (unit, '(a)') '    <Geometry GeometryType="X_Y_Z">'
         call row('x', i)
         if (has_y) then
            call row('y', i)
         else
            write (unit, '(a)') '     <DataItem Reference="XML">/Xdmf/Domain/DataItem[@Name=''plane'']</DataItem>'
         end if
         call row('z', i)
         write (unit, '(a)') '    </Geometry>'
         do q = 1, size(attributes)
            write (unit, '(a)') '    <Attribute Name="'//trim(attributes(q))//'" AttributeType="Scalar" Center="Node">'
            call row(trim(attributes(q)), i)
            write (unit, '(a)') '    </Attribute>'
         end do
         write (unit, '(a)') '   </Grid>'
      end do
      write (unit, '(a)') '  </Grid>'
      write (unit, '(a)') ' </Domain>'
      write (unit, '(a)') '</Xdmf>'
      close (unit, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, 'writing '//temporary//' (&output xdmf) failed: '//trim(msg), stat_io)
         return
      end if
      message = replace_file(temporary, sidecar)
      if (len(message) > 0) call fatal_error(error, 'cannot rename '//temporary//' to '//sidecar//': '//message, stat_io)

   contains

      !> Row i (1-based) of the snapshot dataset name, as a hyperslab.
      subroutine row(name, i)
         character(*), intent(in) :: name
         integer, intent(in) :: i
         ! The comment names the row: VTK's XDMF reader (ParaView's) keys its cache of
         ! a grid's points on the text that opens the geometry's first item, and
         ! without one it reports an error for every snapshot (it then reads right).
         write (unit, '(a)') '     <DataItem ItemType="HyperSlab" Dimensions="1 '//str(n)//'" Type="HyperSlab">'// &
            '<!-- '//name//', snapshot '//str(i - 1)//' -->'
         write (unit, '(a)') '      <DataItem Dimensions="3 2" Format="XML">'//str(i - 1)//' 0 1 1 1 '//str(n)// &
            '</DataItem>'
         write (unit, '(a)') '      <DataItem Dimensions="'//str(m)//' '//str(n)//'" NumberType="Float" '// &
            'Precision="8" Format="HDF">'//h5name//':/'//name//'</DataItem>'
         write (unit, '(a)') '     </DataItem>'
      end subroutine row

   end subroutine write_xdmf

   !> Whether the root of the file has a link of this name.
   logical function exists(file, name)
      integer(hid_t), intent(in) :: file
      character(*), intent(in) :: name
      integer :: hdferr
      call h5lexists_f(file, name, exists, hdferr)
      exists = exists .and. hdferr == 0
   end function exists

   !> Extents of a dataset of the given rank (Fortran order: the fastest-varying, HDF5's last,
   !> first); ok cleared when it is absent or of another rank.
   subroutine dataset_dims(file, name, dims, ok)
      integer(hid_t), intent(in) :: file
      character(*), intent(in) :: name
      integer(hsize_t), intent(out) :: dims(:)
      logical, intent(inout) :: ok
      integer(hid_t) :: dset, space
      integer(hsize_t) :: maxdims(size(dims))
      integer :: hdferr
      dims = 0
      if (.not. exists(file, name)) then
         ok = .false.
         return
      end if
      call h5dopen_f(file, name, dset, hdferr)
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims, maxdims, hdferr)
      if (hdferr /= size(dims)) ok = .false.
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
   end subroutine dataset_dims

   !> Number of nodes of a snapshot dataset (its rows' length); 0 if absent.
   integer function dataset_extent(file, name, rank, ok) result(extent)
      integer(hid_t), intent(in) :: file
      character(*), intent(in) :: name
      integer, intent(in) :: rank
      logical, intent(inout) :: ok
      integer(hsize_t) :: dims(rank)
      call dataset_dims(file, name, dims, ok)
      extent = int(dims(1))
   end function dataset_extent

   !> A 1-D real dataset.
   subroutine read_vector(file, name, values, ok)
      integer(hid_t), intent(in) :: file
      character(*), intent(in) :: name
      real(dp), allocatable, intent(out) :: values(:)
      logical, intent(inout) :: ok
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: hdferr
      call dataset_dims(file, name, dims, ok)
      allocate (values(dims(1)))
      if (.not. ok) return
      call h5dopen_f(file, name, dset, hdferr)
      call h5dread_f(dset, H5T_NATIVE_DOUBLE, values, dims, hdferr)
      if (hdferr /= 0) ok = .false.
      call h5dclose_f(dset, hdferr)
   end subroutine read_vector

end module xcable_io_xdmf
