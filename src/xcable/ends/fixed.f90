!> A fixed end: the end node stays at a given point (a pin: no moment).
module xcable_ends_fixed
   use xcable_core_kinds, only: dp
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition
   implicit none
   private
   public :: fixed_end, new_fixed_end

   !> An end pinned at a point.
   type, extends(end_condition) :: fixed_end
      !> The point (x, z), m.
      real(dp) :: point(2) = 0
      !> Its y, for the 3-D model, m.
      real(dp) :: y = 0
   contains
      procedure :: kind => fixed_kind
      procedure :: held => fixed_held
      procedure :: position => fixed_position
      procedure :: position3 => fixed_position3
   end type fixed_end

contains

   !> The fixed end of a validated &end_a / &end_b group.
   subroutine new_fixed_end(config, end)
      !> The group.
      type(end_config), intent(in) :: config
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      allocate (end, source=fixed_end(point=[config%x, config%z], y=config%y))
   end subroutine new_fixed_end

   pure function fixed_kind(self) result(name)
      class(fixed_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'fixed'
   end function fixed_kind

   pure logical function fixed_held(self)
      class(fixed_end), intent(in) :: self
      fixed_held = .true.
   end function fixed_held

   pure function fixed_position(self, t) result(x)
      class(fixed_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(2)
      x = self%point
   end function fixed_position

   pure function fixed_position3(self, t) result(x)
      class(fixed_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(3)
      x = [self%point(1), self%y, self%point(2)]
   end function fixed_position3
end module xcable_ends_fixed
