!> Where the state of a run goes to and comes from: named arrays of reals
!> and integers. A run lists its own state (driver/rod_run.f90, save_state
!> and load_state); a checkpoint file (io/checkpoint.f90) stores the arrays.
!>
!> Names are paths ('history/time', 'pieces/2/r'). A get reads exactly the
!> number of values its array holds: a missing array, or one of another
!> size, is a failure. Failures are collected (the first one's message is
!> kept) so that a reader can read everything and check once; a failed get
!> leaves zeros.
module xcable_io_archive
   use xcable_kinds, only: dp
   implicit none
   private
   public :: state_archive

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
end module xcable_io_archive
