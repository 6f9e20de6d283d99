!> Where the state of a run goes to and comes from: named arrays of reals
!> and integers. A run lists its own state (driver/rod_run.f90, save_state
!> and load_state); a checkpoint file (io/checkpoint.f90) stores the arrays.
!>
!> The sync_* procedures put (saving) or get one item, so that a run lists
!> its state once for both directions (rod_run%exchange_state, and the 3-D
!> run's in driver/rod3d_drive.f90).
!>
!> Names are paths ('history/time', 'pieces/2/r'). A get reads exactly the
!> number of values its array holds: a missing array, or one of another
!> size, is a failure. Failures are collected (the first one's message is
!> kept) so that a reader can read everything and check once; a failed get
!> leaves zeros.
module xcable_io_archive
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: state_archive
   public :: sync_real, sync_reals, sync_matrix, sync_cube, sync_int, sync_ints, sync_logical

   !> A store of named arrays.
   type, abstract :: state_archive
      !> Whether every put and get so far succeeded.
      logical :: ok = .true.
      !> What went wrong first ('' : nothing).
      character(:), allocatable :: message
   contains
      !> Store reals, or integers, under a name.
      procedure(put_reals_interface), deferred :: put_reals
      procedure(put_ints_interface), deferred :: put_ints
      !> Read reals, or integers, stored under a name (exactly size(values) of them).
      procedure(get_reals_interface), deferred :: get_reals
      procedure(get_ints_interface), deferred :: get_ints
      !> Number of values stored under a name (-1: none).
      procedure(size_interface), deferred :: stored_size
      !> Record a failure (the first message is kept).
      procedure :: fail => archive_fail
   end type state_archive

   abstract interface
      subroutine put_reals_interface(self, name, values)
         import :: state_archive, dp
         !> Archive.
         class(state_archive), intent(inout) :: self
         !> Name (a path).
         character(*), intent(in) :: name
         !> Values.
         real(dp), intent(in) :: values(:)
      end subroutine put_reals_interface
      subroutine put_ints_interface(self, name, values)
         import :: state_archive
         !> Archive.
         class(state_archive), intent(inout) :: self
         !> Name (a path).
         character(*), intent(in) :: name
         !> Values.
         integer, intent(in) :: values(:)
      end subroutine put_ints_interface
      subroutine get_reals_interface(self, name, values)
         import :: state_archive, dp
         !> Archive.
         class(state_archive), intent(inout) :: self
         !> Name (a path).
         character(*), intent(in) :: name
         !> Values (their size is the number expected); zeros on a failure.
         real(dp), intent(out) :: values(:)
      end subroutine get_reals_interface
      subroutine get_ints_interface(self, name, values)
         import :: state_archive
         !> Archive.
         class(state_archive), intent(inout) :: self
         !> Name (a path).
         character(*), intent(in) :: name
         !> Values (their size is the number expected); zeros on a failure.
         integer, intent(out) :: values(:)
      end subroutine get_ints_interface
      integer function size_interface(self, name)
         import :: state_archive
         !> Archive.
         class(state_archive), intent(inout) :: self
         !> Name (a path).
         character(*), intent(in) :: name
      end function size_interface
   end interface

contains

   !> Record a failure; the first message is kept.
   subroutine archive_fail(self, message)
      !> Archive.
      class(state_archive), intent(inout) :: self
      !> What went wrong.
      character(*), intent(in) :: message
      if (self%ok) self%message = message
      self%ok = .false.
   end subroutine archive_fail

   !> Put (saving) or get a real under a name.
   subroutine sync_real(a, name, x, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      real(dp), intent(inout) :: x
      logical, intent(in) :: saving
      real(dp) :: buffer(1)
      if (saving) then
         call a%put_reals(name, [x])
      else
         call a%get_reals(name, buffer)
         x = buffer(1)
      end if
   end subroutine sync_real

   !> Put (saving) or get reals under a name.
   subroutine sync_reals(a, name, x, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      real(dp), intent(inout) :: x(:)
      logical, intent(in) :: saving
      if (saving) then
         call a%put_reals(name, x)
      else
         call a%get_reals(name, x)
      end if
   end subroutine sync_reals

   !> Put (saving) or get a matrix under a name (stored column by column).
   subroutine sync_matrix(a, name, x, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      real(dp), intent(inout) :: x(:, :)
      logical, intent(in) :: saving
      real(dp), allocatable :: buffer(:)
      if (saving) then
         call a%put_reals(name, reshape(x, [size(x)]))
      else
         allocate (buffer(size(x)))
         call a%get_reals(name, buffer)
         x = reshape(buffer, shape(x))
      end if
   end subroutine sync_matrix

   !> Put (saving) or get a rank-3 array under a name.
   subroutine sync_cube(a, name, x, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      real(dp), intent(inout) :: x(:, :, :)
      logical, intent(in) :: saving
      real(dp), allocatable :: buffer(:)
      if (saving) then
         call a%put_reals(name, reshape(x, [size(x)]))
      else
         allocate (buffer(size(x)))
         call a%get_reals(name, buffer)
         x = reshape(buffer, shape(x))
      end if
   end subroutine sync_cube

   !> Put (saving) or get an integer under a name.
   subroutine sync_int(a, name, i, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      integer, intent(inout) :: i
      logical, intent(in) :: saving
      integer :: buffer(1)
      if (saving) then
         call a%put_ints(name, [i])
      else
         call a%get_ints(name, buffer)
         i = buffer(1)
      end if
   end subroutine sync_int

   !> Put (saving) or get integers under a name.
   subroutine sync_ints(a, name, i, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      integer, intent(inout) :: i(:)
      logical, intent(in) :: saving
      if (saving) then
         call a%put_ints(name, i)
      else
         call a%get_ints(name, i)
      end if
   end subroutine sync_ints

   !> Put (saving) or get a logical under a name (as 0 or 1).
   subroutine sync_logical(a, name, flag, saving)
      class(state_archive), intent(inout) :: a
      character(*), intent(in) :: name
      logical, intent(inout) :: flag
      logical, intent(in) :: saving
      integer :: buffer(1)
      if (saving) then
         call a%put_ints(name, [merge(1, 0, flag)])
      else
         call a%get_ints(name, buffer)
         flag = buffer(1) == 1
      end if
   end subroutine sync_logical
end module xcable_io_archive
