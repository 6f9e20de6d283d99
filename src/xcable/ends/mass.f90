!> An end carrying a point mass M: the mass adds M to the end node's inertia
!> and its weight M g to the node's load (the gravity energy books it).
module xcable_ends_mass
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: real_text
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition
   implicit none
   private
   public :: mass_end, new_mass_end, check_mass_end

   !> A point mass at the end.
   type, extends(end_condition) :: mass_end
      !> Mass, kg.
      real(dp) :: mass = 0
   contains
      procedure :: kind => mass_kind
      procedure :: point_mass => mass_point_mass
   end type mass_end

contains

   !> The mass end of a validated &end_a / &end_b group.
   subroutine new_mass_end(config, end)
      !> The group.
      type(end_config), intent(in) :: config
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      allocate (end, source=mass_end(mass=config%mass))
   end subroutine new_mass_end

   !> A mass end's group: a mass > 0.
   subroutine check_mass_end(prefix, e, other, other_held, error)
      !> Start of a message: 'file: &end_b: '.
      character(*), intent(in) :: prefix
      !> The group, the other end's group and whether that end is held.
      type(end_config), intent(in) :: e, other
      logical, intent(in) :: other_held
      !> Error naming the variable, its value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      if (.not. e%mass > 0) call fatal_error(error, prefix//'mass = '//real_text(e%mass)// &
                                             ": must be > 0 for kind = 'mass'", stat_input)
   end subroutine check_mass_end

   pure function mass_kind(self) result(name)
      class(mass_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'mass'
   end function mass_kind

   pure real(dp) function mass_point_mass(self)
      class(mass_end), intent(in) :: self
      mass_point_mass = self%mass
   end function mass_point_mass
end module xcable_ends_mass
