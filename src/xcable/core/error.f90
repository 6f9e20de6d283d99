!> Error handling: library routines return an allocatable error_type to their
!> caller instead of stopping; only app/ prints and stops.
module xcable_core_error
   implicit none
   private
   public :: error_type, fatal_error, prefix_error
   public :: stat_input, stat_numerics, stat_io

   !> Error classes: bad input (exit code 2), numerical failure, file I/O.
   integer, parameter :: stat_input = 2, stat_numerics = 3, stat_io = 4

   !> An error with a class and a one-line message.
   type :: error_type
      !> Error class (stat_input, stat_numerics, stat_io).
      integer :: stat = stat_numerics
      !> Human-readable one-line message.
      character(:), allocatable :: message
   end type error_type

contains

   !> Allocate an error with the given message and class.
   subroutine fatal_error(error, message, stat)
      !> Error to create.
      type(error_type), allocatable, intent(out) :: error
      !> Message.
      character(*), intent(in) :: message
      !> Error class; stat_numerics if absent.
      integer, intent(in), optional :: stat
      allocate (error)
      error%message = message
      if (present(stat)) error%stat = stat
   end subroutine fatal_error

   !> Put a prefix (such as the stage that failed) before an error's message.
   pure subroutine prefix_error(error, prefix)
      !> Error to change.
      type(error_type), intent(inout) :: error
      !> Prefix.
      character(*), intent(in) :: prefix
      error%message = prefix//error%message
   end subroutine prefix_error
end module xcable_core_error
