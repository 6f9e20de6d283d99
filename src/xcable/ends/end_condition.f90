!> End conditions of a cable piece: the abstract type every end kind extends.
!>
!> An end is either *held* (its position is prescribed as a function of time:
!> a fixed point or a moving fairlead) or *loaded* (its position is free and
!> it carries an applied force, a couple and possibly a point mass). The rod
!> discretisation (model/rod.f90) assembles every end through this interface
!> alone: a held end's rows are R = X(t); a loaded end adds its force to the
!> node's momentum balance, its couple to the end cell and its mass to the
!> node's inertia and weight. A new end kind is one module extending
!> `end_condition` and one line in ends/factory.f90.
!>
!> Frame: x horizontal, z vertical (up); forces in N, positions in m.
module xcable_ends_end
   use xcable_kinds, only: dp
   implicit none
   private
   public :: end_condition, smooth_ramp, smooth_ramp_rate

   !> An end condition.
   type, abstract :: end_condition
      !> Name of the end in the output ('end_a', 'end_b', 'break_a', 'break_b').
      character(:), allocatable :: label
   contains
      !> Kind name ('fixed', 'free', 'force', 'motion', 'mass', 'break').
      procedure(kind_interface), deferred :: kind
      !> Whether the position is prescribed.
      procedure :: held => end_held
      !> Prescribed position at time t (held ends), m.
      procedure :: position => end_position
      !> Prescribed velocity at time t (held ends), m/s.
      procedure :: velocity => end_velocity
      !> Applied force at time t (loaded ends), N.
      procedure :: applied_force => end_applied_force
      !> Applied couple at time t on the end cell, N m (positive counter-clockwise in the x-z plane).
      procedure :: applied_couple => end_applied_couple
      !> Point mass at the end, kg.
      procedure :: point_mass => end_point_mass
      !> Whether the applied force or couple changes with time.
      procedure :: time_dependent => end_time_dependent
      !> The 3-D model's view of the end (x, y, z), z up: prescribed position, velocity,
      !> applied force (by default the plane's x and z with y = 0), and the applied torque
      !> about the outward tangent, N m (0 by default).
      procedure :: position3 => end_position3
      procedure :: velocity3 => end_velocity3
      procedure :: applied_force3 => end_applied_force3
      procedure :: applied_torque => end_applied_torque
      !> The 3-D model's axis of the applied couple (a unit vector; by default -y, the planar
      !> couple's: counter-clockwise in the x-z plane).
      procedure :: couple_axis => end_couple_axis
   end type end_condition

   abstract interface
      !> Kind name of an end.
      pure function kind_interface(self) result(name)
         import :: end_condition
         !> The end.
         class(end_condition), intent(in) :: self
         character(:), allocatable :: name
      end function kind_interface
   end interface

contains

   pure logical function end_held(self)
      class(end_condition), intent(in) :: self
      end_held = .false.
   end function end_held

   pure function end_position(self, t) result(x)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(2)
      x = 0
   end function end_position

   pure function end_velocity(self, t) result(v)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: v(2)
      v = 0
   end function end_velocity

   pure function end_applied_force(self, t) result(f)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: f(2)
      f = 0
   end function end_applied_force

   pure function end_applied_couple(self, t) result(c)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: c
      c = 0
   end function end_applied_couple

   pure real(dp) function end_point_mass(self)
      class(end_condition), intent(in) :: self
      end_point_mass = 0
   end function end_point_mass

   pure logical function end_time_dependent(self)
      class(end_condition), intent(in) :: self
      end_time_dependent = .false.
   end function end_time_dependent

   pure function end_position3(self, t) result(x)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(3), p(2)
      p = self%position(t)
      x = [p(1), 0.0_dp, p(2)]
   end function end_position3

   pure function end_velocity3(self, t) result(v)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: v(3), p(2)
      p = self%velocity(t)
      v = [p(1), 0.0_dp, p(2)]
   end function end_velocity3

   pure function end_applied_force3(self, t) result(f)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: f(3), p(2)
      p = self%applied_force(t)
      f = [p(1), 0.0_dp, p(2)]
   end function end_applied_force3

   pure real(dp) function end_applied_torque(self, t) result(m)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: t
      m = 0
   end function end_applied_torque

   pure function end_couple_axis(self) result(axis)
      class(end_condition), intent(in) :: self
      real(dp) :: axis(3)
      axis = [0.0_dp, -1.0_dp, 0.0_dp]
   end function end_couple_axis

   !> The paper's release ramp (eqs. 31-32): 1 before t0, cos^2(pi (t - t0) / (2 duration))
   !> during the ramp, 0 after (a step at t0 when the duration is 0).
   elemental real(dp) function smooth_ramp(t, t0, duration) result(r)
      !> Time, start of the ramp and its duration, s.
      real(dp), intent(in) :: t, t0, duration
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (t <= t0) then
         r = 1
      else if (t >= t0 + duration) then
         r = 0
      else
         r = cos(0.5_dp*pi*(t - t0)/duration)**2
      end if
   end function smooth_ramp

   !> Time derivative of smooth_ramp, 1/s.
   elemental real(dp) function smooth_ramp_rate(t, t0, duration) result(r)
      !> Time, start of the ramp and its duration, s.
      real(dp), intent(in) :: t, t0, duration
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (t <= t0 .or. t >= t0 + duration) then
         r = 0
      else
         r = -0.5_dp*pi/duration*sin(pi*(t - t0)/duration)
      end if
   end function smooth_ramp_rate
end module xcable_ends_end
