!> The bathymetry of a case (&seabed bathymetry_file): a grid of depths in MoorDyn's bathymetry
!> file format, so that a file written for MoorDyn serves here too:
!>
!>     ----- any title line -----
!>     nGridX 3
!>     nGridY 2
!>             -100   0   100
!>     -50     62    60   58
!>      50     63    61   59
!>
!> the third line the grid's x lines, each following line a y line and the depths (m, positive
!> below z = 0) at the x lines. Both lists increase strictly. The bottom between the points is
!> made of flat facets (numerics/facets.f90); beyond the grid it continues flat from its edge.
module xcable_io_input_bathymetry
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str, real_text
   use xcable_io_config, only: case_config
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: load_bathymetry

   !> Most grid lines along x or y.
   integer, parameter :: max_grid_lines = 10000

contains

   !> Read &seabed bathymetry_file, if given, into the case's bathymetry arrays.
   subroutine load_bathymetry(c, error)
      !> The case: bathymetry_x, bathymetry_y and bathymetry_depth filled.
      type(case_config), intent(inout) :: c
      !> Error naming the case file, the group, the file and its line.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: prefix
      character(len=65536) :: line
      character(len=32) :: word
      integer :: unit, ios, nx, ny, j, k, lineno
      real(dp), allocatable :: row(:)
      logical :: exists, opened

      if (len_trim(c%bathymetry_file) == 0) return
      prefix = c%source//": &seabed: bathymetry_file = '"//trim(c%bathymetry_file)//"': "
      if (c%is_given('seabed', 'depth') .or. c%is_given('seabed', 'slope_x') .or. c%is_given('seabed', 'slope_y')) then
         call fatal_error(error, prefix//'a bathymetry replaces the plane of depth, slope_x and slope_y: give '// &
                          'one or the other', stat_input)
         return
      end if
      inquire (file=trim(c%bathymetry_file), exist=exists)
      if (.not. exists) then
         call fatal_error(error, prefix//'no such file', stat_input)
         return
      end if
      open (newunit=unit, file=trim(c%bathymetry_file), status='old', action='read', iostat=ios)
      if (ios /= 0) then
         call fatal_error(error, prefix//'cannot be opened', stat_input)
         return
      end if
      opened = .true.
      lineno = 1
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) then
         call bad('the file is empty')
         return
      end if
      call count_line('nGridX', nx)
      if (allocated(error)) return
      call count_line('nGridY', ny)
      if (allocated(error)) return
      allocate (c%bathymetry_x(nx), c%bathymetry_y(ny), c%bathymetry_depth(nx, ny), row(nx + 1))
      lineno = lineno + 1
      read (unit, *, iostat=ios) c%bathymetry_x
      if (ios /= 0) then
         call bad('line '//str(lineno)//': expected the '//str(nx)//' grid lines along x')
         return
      end if
      do j = 1, ny
         lineno = lineno + 1
         read (unit, *, iostat=ios) row
         if (ios /= 0) then
            call bad('line '//str(lineno)//': expected a y line and '//str(nx)//' depths (row '//str(j)//' of '// &
                     str(ny)//')')
            return
         end if
         c%bathymetry_y(j) = row(1)
         c%bathymetry_depth(:, j) = row(2:)
      end do
      close (unit)
      opened = .false.
      if (.not. (all(ieee_is_finite(c%bathymetry_x)) .and. all(ieee_is_finite(c%bathymetry_y)) .and. &
                 all(ieee_is_finite(c%bathymetry_depth)))) then
         call bad('a number is not finite')
         return
      end if
      do k = 2, nx
         if (c%bathymetry_x(k) <= c%bathymetry_x(k - 1)) then
            call bad('line 4: the x lines must increase strictly (x('//str(k)//') = '// &
                     real_text(c%bathymetry_x(k))//' after '//real_text(c%bathymetry_x(k - 1))//')')
            return
         end if
      end do
      do k = 2, ny
         if (c%bathymetry_y(k) <= c%bathymetry_y(k - 1)) then
            call bad('line '//str(4 + k)//': the y lines must increase strictly (y = '// &
                     real_text(c%bathymetry_y(k))//' after '//real_text(c%bathymetry_y(k - 1))//')')
            return
         end if
      end do

   contains

      !> A line 'name count' (count from 1 to max_grid_lines).
      subroutine count_line(name, count)
         character(*), intent(in) :: name
         integer, intent(out) :: count
         lineno = lineno + 1
         count = 0
         read (unit, *, iostat=ios) word, count
         if (ios /= 0 .or. count < 1 .or. count > max_grid_lines) then
            call bad('line '//str(lineno)//': expected "'//name//' n" with n from 1 to '//str(max_grid_lines))
         end if
      end subroutine count_line

      !> The error, the file closed and the arrays dropped.
      subroutine bad(why)
         character(*), intent(in) :: why
         call fatal_error(error, prefix//why//" (MoorDyn's bathymetry format: a title line, nGridX n, "// &
                          'nGridY m, the n x lines, then m lines of y and n depths)', stat_input)
         if (opened) close (unit)
         opened = .false.
         if (allocated(c%bathymetry_x)) deallocate (c%bathymetry_x)
         if (allocated(c%bathymetry_y)) deallocate (c%bathymetry_y)
         if (allocated(c%bathymetry_depth)) deallocate (c%bathymetry_depth)
      end subroutine bad
   end subroutine load_bathymetry
end module xcable_io_input_bathymetry
