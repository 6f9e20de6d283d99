!> A free end: no force, no couple, no mass (the internal force vanishes there).
module xcable_ends_free
   use xcable_ends_end, only: end_condition
   implicit none
   private
   public :: free_end

   !> A free end.
   type, extends(end_condition) :: free_end
   contains
      procedure :: kind => free_kind
   end type free_end

contains

   pure function free_kind(self) result(name)
      class(free_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'free'
   end function free_kind
end module xcable_ends_free
