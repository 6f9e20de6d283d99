!> An end whose position is prescribed: a fairlead that moves.
!>
!> 'harmonic': X(t) = X0 + a d w(t) [sin(2 pi t / T + phi) - sin(phi)], with
!> the unit direction d, and w(t) = 1 - cos^2(pi t / (2 t_r)) rising smoothly
!> from 0 to 1 over the start time t_r (w = 1 when t_r = 0), so that X(0) =
!> X0, and with t_r > 0 the motion starts from rest. 'table': X(t) = X0 + the
!> tabulated displacement (x, y, z; cubic Hermite, continuous velocity).
module xcable_ends_motion
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: real_text
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition, smooth_ramp, smooth_ramp_rate
   use xcable_ends_table, only: time_table, group_table
   implicit none
   private
   public :: motion_end, new_motion_end, check_motion_end

   real(dp), parameter :: two_pi = 2*acos(-1.0_dp)

   !> A moving end.
   type, extends(end_condition) :: motion_end
      !> 'harmonic' or 'table'.
      character(len=8) :: motion = 'harmonic'
      !> Mean (and starting) position, m.
      real(dp) :: origin(2) = 0
      !> Amplitude (m), period (s), phase (rad), unit direction, start time (s).
      real(dp) :: amplitude = 0, period = 1, phase = 0, direction(2) = [0.0_dp, 1.0_dp], ramp_time = 0
      !> Displacement table of the 'table' motion: components x, y, z.
      type(time_table) :: table
      !> For the 3-D model: y of the origin (m) and the y component of the harmonic motion's
      !> direction (the direction (x, y, z) is then direction(1), direction_y, direction(2), given
      !> normalised).
      real(dp) :: origin_y = 0, direction_y = 0
   contains
      procedure :: kind => motion_kind
      procedure :: held => motion_held
      procedure :: position => motion_position
      procedure :: velocity => motion_velocity
      procedure :: position3 => motion_position3
      procedure :: velocity3 => motion_velocity3
      procedure :: time_dependent => motion_time_dependent
   end type motion_end

contains

   !> The moving end of a validated &end_a / &end_b group.
   subroutine new_motion_end(config, end)
      !> The group.
      type(end_config), intent(in) :: config
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      real(dp) :: direction(3)
      ! The direction normalised over its three components (x, y, z).
      direction = [config%direction_x, config%direction_y, config%direction_z]
      if (norm2(direction) > 0) direction = direction/norm2(direction)
      allocate (end, source=motion_end(motion=config%motion, origin=[config%x, config%z], &
                                       amplitude=config%amplitude, period=config%period, phase=config%phase, &
                                       direction=direction([1, 3]), ramp_time=config%ramp_time, &
                                       table=group_table(config, .false.), origin_y=config%y, &
                                       direction_y=direction(2)))
   end subroutine new_motion_end

   !> A moving end's group: a period > 0 and a direction for a harmonic motion, a table for a
   !> 'table' motion.
   subroutine check_motion_end(prefix, e, other, other_held, error)
      !> Start of a message: 'file: &end_b: '.
      character(*), intent(in) :: prefix
      !> The group, the other end's group and whether that end is held.
      type(end_config), intent(in) :: e, other
      logical, intent(in) :: other_held
      !> Error naming the variable, its value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      if (e%motion == 'harmonic') then
         if (.not. e%period > 0) then
            call fatal_error(error, prefix//'period = '//real_text(e%period)//": must be > 0 for motion = 'harmonic'", &
                             stat_input)
            return
         end if
         if (e%direction_x == 0 .and. e%direction_y == 0 .and. e%direction_z == 0) then
            call fatal_error(error, prefix//'direction_x = 0, direction_y = 0, direction_z = 0: the direction of the '// &
                             'harmonic motion must not be zero (a vector of nonzero length)', stat_input)
            return
         end if
      end if
      if (e%motion == 'table' .and. e%table_rows == 0) &
         call fatal_error(error, prefix//"motion = 'table' without a table: give table_time, table_x and table_z "// &
                          '(at least 2 rows) or table_file', stat_input)
   end subroutine check_motion_end

   !> A moving end changes with time (its position).
   pure logical function motion_time_dependent(self)
      class(motion_end), intent(in) :: self
      motion_time_dependent = .true.
   end function motion_time_dependent

   pure function motion_kind(self) result(name)
      class(motion_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'motion'
   end function motion_kind

   pure logical function motion_held(self)
      class(motion_end), intent(in) :: self
      motion_held = .true.
   end function motion_held

   !> Smooth start factor w(t) and its rate.
   pure subroutine start_factor(self, t, w, dw)
      class(motion_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp), intent(out) :: w, dw
      if (self%ramp_time > 0) then
         w = 1 - smooth_ramp(t, 0.0_dp, self%ramp_time)
         dw = -smooth_ramp_rate(t, 0.0_dp, self%ramp_time)
      else
         w = 1
         dw = 0
      end if
   end subroutine start_factor

   pure function motion_position(self, t) result(x)
      class(motion_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(2), w, dw, d(3)
      if (self%motion == 'table') then
         d = self%table%at(t)
         x = self%origin + d([1, 3])
      else
         call start_factor(self, t, w, dw)
         x = self%origin + self%amplitude*w*(sin(two_pi*t/self%period + self%phase) - sin(self%phase))*self%direction
      end if
   end function motion_position

   pure function motion_velocity(self, t) result(v)
      class(motion_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: v(2), w, dw, omega, d(3)
      if (self%motion == 'table') then
         d = self%table%rate(t)
         v = d([1, 3])
      else
         call start_factor(self, t, w, dw)
         omega = two_pi/self%period
         v = self%amplitude*(dw*(sin(omega*t + self%phase) - sin(self%phase)) + w*omega*cos(omega*t + self%phase)) &
             *self%direction
      end if
   end function motion_velocity

   pure function motion_position3(self, t) result(x)
      class(motion_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(3), p(2), w, dw, y, d(3)
      p = self%position(t)
      y = self%origin_y
      if (self%motion == 'table') then
         d = self%table%at(t)
         y = y + d(2)
      else
         call start_factor(self, t, w, dw)
         y = y + self%amplitude*w*(sin(two_pi*t/self%period + self%phase) - sin(self%phase))*self%direction_y
      end if
      x = [p(1), y, p(2)]
   end function motion_position3

   pure function motion_velocity3(self, t) result(v)
      class(motion_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: v(3), p(2), w, dw, omega, vy, d(3)
      p = self%velocity(t)
      vy = 0
      if (self%motion == 'table') then
         d = self%table%rate(t)
         vy = d(2)
      else
         call start_factor(self, t, w, dw)
         omega = two_pi/self%period
         vy = self%amplitude*(dw*(sin(omega*t + self%phase) - sin(self%phase)) + w*omega*cos(omega*t + self%phase)) &
              *self%direction_y
      end if
      v = [p(1), vy, p(2)]
   end function motion_velocity3
end module xcable_ends_motion
