!> A free end: no force, no couple, no mass (the internal force vanishes there).
module xcable_ends_free
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition
   implicit none
   private
   public :: free_end, new_free_end

   !> A free end.
   type, extends(end_condition) :: free_end
   contains
      procedure :: kind => free_kind
   end type free_end

contains

   !> The free end of a validated &end_a / &end_b group.
   subroutine new_free_end(config, end)
      !> The group.
      type(end_config), intent(in) :: config
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      allocate (end, source=free_end())
   end subroutine new_free_end

   pure function free_kind(self) result(name)
      class(free_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'free'
   end function free_kind
end module xcable_ends_free
