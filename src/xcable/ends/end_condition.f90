!> End conditions of a cable piece: the abstract type every end kind extends.
!>
!> An end is either *held* (its position is prescribed as a function of time:
!> a fixed point or a moving fairlead) or *loaded* (its position is free and
!> it carries an applied force, a couple and possibly a point mass). The rod
!> discretisation (model/rod.f90) assembles every end through this interface
!> alone: a held end's rows are R = X(t); a loaded end adds its force to the
!> node's momentum balance, its couple to the end cell and its mass to the
!> node's inertia and weight. A new end kind is one module extending
!> `end_condition` and one line in ends/registry.f90.
!>
!> A loaded end may also depend on its own state (a spring, a damper): then
!> `state_dependent` is true and the rods add `state_force` (statics) or
!> `step_force` (a time step) to the time-only applied force, with their
!> derivatives in the Jacobian, and book `stored_energy` with the cable's
!> strain energy and the damping part of the force as dissipation. Ends that
!> are not state-dependent (the default) take none of these calls, so their
!> arithmetic is that of the time-only interface. These procedures work on
!> 3-D vectors (x, y, z), z up; the planar rod passes (x, 0, z).
!>
!> Frame: x horizontal, z vertical (up); forces in N, positions in m.
module xcable_ends_end_condition
   use xcable_core_kinds, only: dp
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
      !> Whether the end changes with time: its applied force or couple, or its prescribed position.
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
      !> Whether the end's force depends on its own position or velocity (default: no; then the
      !> four procedures below are never called).
      procedure :: state_dependent => end_state_dependent
      !> The force of the end's own state at (t, x, v) on the cable's end node, N, with its
      !> derivatives d f / d x (N/m) and d f / d v (N s/m) and its dissipative part (N).
      procedure :: state_force => end_state_force
      !> The force of the end's own state over a time step, from position x0 at t0 to x1 at
      !> t0 + dt (mean velocity (x1 - x0) / dt), N, its derivative with respect to x1 (N/m) and
      !> its dissipative part (N). Default: state_force at the midpoint, d f / d x1 =
      !> 1/2 d f / d x + d f / d v / dt. An end whose stored energy is not quadratic overrides
      !> it with a discrete gradient, so that the ledger closes exactly.
      procedure :: step_force => end_step_force
      !> Energy stored in the end at its position x, J (the elastic part of state_force is its
      !> negative gradient).
      procedure :: stored_energy => end_stored_energy
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

   pure logical function end_state_dependent(self)
      class(end_condition), intent(in) :: self
      end_state_dependent = .false.
   end function end_state_dependent

   !> No state force (the default).
   pure subroutine end_state_force(self, t, x, v, f, df_dx, df_dv, f_damping)
      !> The end.
      class(end_condition), intent(in) :: self
      !> Time, s; position (x, y, z), m; velocity, m/s.
      real(dp), intent(in) :: t, x(3), v(3)
      !> Force on the cable's end node, N; its derivatives, N/m and N s/m; its dissipative part, N.
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_dv(3, 3), f_damping(3)
      f = 0
      df_dx = 0
      df_dv = 0
      f_damping = 0
   end subroutine end_state_force

   !> state_force at the step's midpoint (time, position) with the step's mean velocity.
   pure subroutine end_step_force(self, t0, dt, x0, x1, f, df_dx1, f_damping)
      !> The end.
      class(end_condition), intent(in) :: self
      !> Time at the start of the step and the step, s.
      real(dp), intent(in) :: t0, dt
      !> Positions of the end node at the start and the end of the step, m.
      real(dp), intent(in) :: x0(3), x1(3)
      !> Force over the step on the cable's end node, N; its derivative with respect to x1, N/m;
      !> its dissipative part, N.
      real(dp), intent(out) :: f(3), df_dx1(3, 3), f_damping(3)
      real(dp) :: df_dx(3, 3), df_dv(3, 3)
      call self%state_force(t0 + 0.5_dp*dt, 0.5_dp*(x0 + x1), (x1 - x0)/dt, f, df_dx, df_dv, f_damping)
      df_dx1 = 0.5_dp*df_dx + df_dv/dt
   end subroutine end_step_force

   pure real(dp) function end_stored_energy(self, x)
      class(end_condition), intent(in) :: self
      real(dp), intent(in) :: x(3)
      end_stored_energy = 0
   end function end_stored_energy

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
end module xcable_ends_end_condition
