!> The end of a line at a free point of a network (driver/network.f90): held at the point's
!> position, which the network's Newton iteration sets (`at`) before each evaluation. It is
!> not a kind of the namelist (ends/registry.f90): the input names the point, and the network
!> puts this end there. Its rows are kept by the piece (rod3d_piece%keep_rows), so that the
!> network can add the line's force on the point to the point's balance.
module xcable_ends_joint
   use xcable_core_kinds, only: dp
   use xcable_ends_end_condition, only: end_condition
   implicit none
   private
   public :: joint_end

   !> A line's end held at a network point.
   type, extends(end_condition) :: joint_end
      !> The point's position (x, y, z), m.
      real(dp) :: at(3) = 0
      !> The network point it is on.
      integer :: point = 0
   contains
      procedure :: kind => joint_kind
      procedure :: held => joint_held
      procedure :: time_dependent => joint_moves
      procedure :: position => joint_position
      procedure :: position3 => joint_position3
   end type joint_end

contains

   !> 'joint'.
   pure function joint_kind(self) result(name)
      !> End.
      class(joint_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'joint'
   end function joint_kind

   !> Held: at the point.
   pure logical function joint_held(self)
      !> End.
      class(joint_end), intent(in) :: self
      joint_held = .true.
   end function joint_held

   !> It moves with the point.
   pure logical function joint_moves(self)
      !> End.
      class(joint_end), intent(in) :: self
      joint_moves = .true.
   end function joint_moves

   !> The point's (x, z), m.
   pure function joint_position(self, t) result(x)
      !> End.
      class(joint_end), intent(in) :: self
      !> Time, s (the point's position is the network's current one).
      real(dp), intent(in) :: t
      real(dp) :: x(2)
      x = [self%at(1), self%at(3)]
   end function joint_position

   !> The point's (x, y, z), m.
   pure function joint_position3(self, t) result(x)
      !> End.
      class(joint_end), intent(in) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      real(dp) :: x(3)
      x = self%at
   end function joint_position3
end module xcable_ends_joint
