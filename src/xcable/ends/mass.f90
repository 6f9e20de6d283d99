!> An end carrying a point mass M: the mass adds M to the end node's inertia
!> and its weight M g to the node's load (the gravity energy books it).
module xcable_ends_mass
   use xcable_kinds, only: dp
   use xcable_ends_end, only: end_condition
   implicit none
   private
   public :: mass_end

   !> A point mass at the end.
   type, extends(end_condition) :: mass_end
      !> Mass, kg.
      real(dp) :: mass = 0
   contains
      procedure :: kind => mass_kind
      procedure :: point_mass => mass_point_mass
   end type mass_end

contains

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
