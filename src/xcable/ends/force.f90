!> An end loaded by an applied force history F(t) (and a couple history C(t)):
!> the internal force at the end equals the applied force.
!>
!> Histories: 'constant' F0; 'ramp' the paper's release, F0 cos^2(pi (t - t0)
!> / (2 T)) from t0 to t0 + T, F0 before and 0 after (eqs. 31-32); 'table' a
!> force table (straight segments). A break is this end with the 'ramp'
!> history, starting at the break time, from the static internal force and
!> moment at the break point (kind 'break').
module xcable_ends_force
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: real_text
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition, smooth_ramp
   use xcable_ends_table, only: time_table, group_table
   implicit none
   private
   public :: force_end, new_force_end, check_force_end

   !> A force-loaded end.
   type, extends(end_condition) :: force_end
      !> Kind reported: 'force', or 'break' for the ends a break makes.
      character(len=8) :: kind_name = 'force'
      !> 'constant', 'ramp' or 'table'.
      character(len=8) :: history = 'constant'
      !> Force of the 'constant' history and starting force of the 'ramp', N.
      real(dp) :: force0(2) = 0
      !> Starting couple of the 'ramp' (and constant couple otherwise), N m.
      real(dp) :: couple0 = 0
      !> For the 3-D model: the y component of force0, N, and the torque about the outward
      !> tangent (ramped as the force), N m.
      real(dp) :: force0_y = 0, torque0 = 0
      !> For the 3-D model: the unit axis the couple turns about (-y: the planar couple's).
      real(dp) :: axis(3) = [0.0_dp, -1.0_dp, 0.0_dp]
      !> Start and duration of the ramp, s.
      real(dp) :: t0 = 0, duration = 0
      !> Force table of the 'table' history: components x, y, z.
      type(time_table) :: table
   contains
      procedure :: kind => force_kind
      procedure :: applied_force => force_applied_force
      procedure :: applied_couple => force_applied_couple
      procedure :: time_dependent => force_time_dependent
      procedure :: applied_force3 => force_applied_force3
      procedure :: applied_torque => force_applied_torque
      procedure :: couple_axis => force_couple_axis
   end type force_end

contains

   !> The force end of a validated &end_a / &end_b group.
   subroutine new_force_end(config, end)
      !> The group.
      type(end_config), intent(in) :: config
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      allocate (end, source=force_end(history=config%history, force0=[config%force_x, config%force_z], &
                                      duration=config%ramp_time, table=group_table(config, .true.), &
                                      force0_y=config%force_y, torque0=config%torque))
   end subroutine new_force_end

   !> A force end's group: a ramp time > 0 for a ramp, a table for a 'table' history.
   subroutine check_force_end(prefix, e, other, other_held, error)
      !> Start of a message: 'file: &end_b: '.
      character(*), intent(in) :: prefix
      !> The group, the other end's group and whether that end is held.
      type(end_config), intent(in) :: e, other
      logical, intent(in) :: other_held
      !> Error naming the variable, its value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      if (e%history == 'ramp' .and. .not. e%ramp_time > 0) then
         call fatal_error(error, prefix//'ramp_time = '//real_text(e%ramp_time)//": must be > 0 for history = 'ramp'", &
                          stat_input)
         return
      end if
      if (e%history == 'table' .and. e%table_rows == 0) &
         call fatal_error(error, prefix//"history = 'table' without a table: give table_time, table_x and table_z "// &
                          '(at least 2 rows) or table_file', stat_input)
   end subroutine check_force_end

   pure function force_kind(self) result(name)
      class(force_end), intent(in) :: self
      character(:), allocatable :: name
      name = trim(self%kind_name)
   end function force_kind

   pure function force_applied_force(self, t) result(f)
      class(force_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: f(2), f3(3)
      select case (self%history)
      case ('ramp')
         f = self%force0*smooth_ramp(t, self%t0, self%duration)
      case ('table')
         f3 = self%table%at(t)
         f = f3([1, 3])
      case default
         f = self%force0
      end select
   end function force_applied_force

   pure function force_applied_couple(self, t) result(c)
      class(force_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: c
      if (self%history == 'ramp') then
         c = self%couple0*smooth_ramp(t, self%t0, self%duration)
      else
         c = self%couple0
      end if
   end function force_applied_couple

   pure logical function force_time_dependent(self)
      class(force_end), intent(in) :: self
      force_time_dependent = self%history /= 'constant'
   end function force_time_dependent

   pure function force_applied_force3(self, t) result(f)
      class(force_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: f(3), f2(2), scale
      if (self%history == 'table') then
         f = self%table%at(t)
         return
      end if
      f2 = self%applied_force(t)
      select case (self%history)
      case ('ramp')
         scale = smooth_ramp(t, self%t0, self%duration)
      case default
         scale = 1
      end select
      f = [f2(1), self%force0_y*scale, f2(2)]
   end function force_applied_force3

   pure real(dp) function force_applied_torque(self, t) result(m)
      class(force_end), intent(in) :: self
      real(dp), intent(in) :: t
      if (self%history == 'ramp') then
         m = self%torque0*smooth_ramp(t, self%t0, self%duration)
      else
         m = self%torque0
      end if
   end function force_applied_torque

   pure function force_couple_axis(self) result(axis)
      class(force_end), intent(in) :: self
      real(dp) :: axis(3)
      axis = self%axis
   end function force_couple_axis
end module xcable_ends_force
