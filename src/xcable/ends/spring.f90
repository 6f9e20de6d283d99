!> An end tied by a spring (and a dashpot in line with it) to an anchor point:
!> the worked example of a state-dependent end (docs/dev/adding-an-end.md).
!>
!> With d = X - A the vector from the anchor A to the cable's end node X,
!> l = |d| and its direction d^ = d / l, the force on the cable's end is
!>
!>     F = -k (l - L0) d^ - c (V . d^) d^,
!>
!> k the stiffness, L0 the rest length, c the damping. The dashpot acts on the
!> rate of change of the spring's length (V . d^), not on the velocity across
!> it: a spring-damper element. The spring stores U = k (l - L0)^2 / 2 (the
!> rods book it with the cable's strain energy), the dashpot dissipates
!> c (V . d^)^2 per second (booked as dissipation). With L0 > 0 the spring also
!> pushes (l < L0), like a coil spring. Over a time step from X0 to X1 the
!> elastic force is the discrete gradient of U (step_force),
!>
!>     F_e = -k ((l0 + l1) / 2 - L0) (d0 + d1) / (l0 + l1),
!>
!> with F_e . (X1 - X0) = -(U1 - U0) exactly, and the dashpot acts along the
!> midpoint direction w = (d0 + d1) / |d0 + d1| on the mean velocity
!> (X1 - X0) / dt: it removes c dt (w . (X1 - X0) / dt)^2 exactly. The ledger
!> of a run with a spring end therefore closes to the Newton tolerance.
!>
!> The end may also carry a point mass (mass, kg: its inertia and weight, as
!> a 'mass' end's).
module xcable_ends_spring
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: real_text
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition
   use xcable_numerics_vector3, only: outer3, identity3
   implicit none
   private
   public :: spring_end, new_spring_end, check_spring_end

   !> An end on a spring to an anchor point.
   type, extends(end_condition) :: spring_end
      !> Anchor point (x, y, z), m.
      real(dp) :: anchor(3) = 0
      !> Stiffness k, N/m; damping c, N s/m; rest length L0, m.
      real(dp) :: stiffness = 0, damping = 0, rest_length = 0
      !> Point mass at the end, kg.
      real(dp) :: mass = 0
   contains
      procedure :: kind => spring_kind
      procedure :: point_mass => spring_point_mass
      procedure :: position => spring_position
      procedure :: position3 => spring_position3
      procedure :: state_dependent => spring_state_dependent
      procedure :: state_force => spring_state_force
      procedure :: step_force => spring_step_force
      procedure :: stored_energy => spring_stored_energy
   end type spring_end

contains

   !> The spring end of a validated &end_a / &end_b group.
   subroutine new_spring_end(config, end)
      !> The group.
      type(end_config), intent(in) :: config
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      allocate (end, source=spring_end(anchor=[config%x, config%y, config%z], stiffness=config%stiffness, &
                                       damping=config%damping, rest_length=config%rest_length, mass=config%mass))
   end subroutine new_spring_end

   !> The conditions of a spring end's group beyond the schema's ranges: a stiffness > 0, and,
   !> with a positive rest length, an anchor apart from the other end's point when that end is
   !> held (then the spring would be at rest with the cable folded onto itself, and its
   !> direction at rest is undetermined).
   subroutine check_spring_end(prefix, e, other, other_held, error)
      !> Start of a message: 'file: &end_b: '.
      character(*), intent(in) :: prefix
      !> The spring end's group.
      type(end_config), intent(in) :: e
      !> The other end's group, and whether that end is held at its x, y, z.
      type(end_config), intent(in) :: other
      logical, intent(in) :: other_held
      !> Error naming the variable, its value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      if (.not. e%stiffness > 0) then
         call fatal_error(error, prefix//'stiffness = '//real_text(e%stiffness)//": must be > 0 for kind = "// &
                          "'spring' (a spring of no stiffness holds nothing; use kind = 'free')", stat_input)
         return
      end if
      if (e%rest_length > 0 .and. other_held .and. e%x == other%x .and. e%y == other%y .and. e%z == other%z) then
         call fatal_error(error, prefix//'x, y, z = '//real_text(e%x)//', '//real_text(e%y)//', '// &
                          real_text(e%z)//' with rest_length = '//real_text(e%rest_length)// &
                          ": the anchor is the other end's point; allowed: an anchor apart from it, or "// &
                          'rest_length = 0', stat_input)
      end if
   end subroutine check_spring_end

   pure function spring_kind(self) result(name)
      class(spring_end), intent(in) :: self
      character(:), allocatable :: name
      name = 'spring'
   end function spring_kind

   pure real(dp) function spring_point_mass(self)
      class(spring_end), intent(in) :: self
      spring_point_mass = self%mass
   end function spring_point_mass

   !> The anchor (x, z): the point the statics' first guess starts the end from (the end is
   !> not held: held() is false, and its position follows from the statics).
   pure function spring_position(self, t) result(x)
      class(spring_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(2)
      x = self%anchor([1, 3])
   end function spring_position

   !> The anchor (x, y, z), as spring_position.
   pure function spring_position3(self, t) result(x)
      class(spring_end), intent(in) :: self
      real(dp), intent(in) :: t
      real(dp) :: x(3)
      x = self%anchor
   end function spring_position3

   pure logical function spring_state_dependent(self)
      class(spring_end), intent(in) :: self
      spring_state_dependent = .true.
   end function spring_state_dependent

   !> F = -k (l - L0) d^ - c (v . d^) d^ and its derivatives (at l = 0: the direction is
   !> undetermined; the force is -k d and the dashpot is left out there).
   pure subroutine spring_state_force(self, t, x, v, f, df_dx, df_dv, f_damping)
      !> The end.
      class(spring_end), intent(in) :: self
      !> Time, s; position (x, y, z), m; velocity, m/s.
      real(dp), intent(in) :: t, x(3), v(3)
      !> Force on the cable's end node, N; its derivatives, N/m and N s/m; its dissipative part, N.
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_dv(3, 3), f_damping(3)
      real(dp) :: d(3), l, u(3), p(3, 3), rate
      d = x - self%anchor
      l = norm2(d)
      if (.not. l > 0) then
         f = -self%stiffness*d
         df_dx = -self%stiffness*identity3()
         df_dv = 0
         f_damping = 0
         return
      end if
      u = d/l
      p = identity3() - outer3(u, u)
      rate = dot_product(v, u)
      f_damping = -self%damping*rate*u
      f = -self%stiffness*(l - self%rest_length)*u + f_damping
      ! d u / d x = P / l.
      df_dx = -self%stiffness*((1 - self%rest_length/l)*identity3() + self%rest_length/l*outer3(u, u)) &
              - self%damping*(rate*p + outer3(u, matmul(p, v)))/l
      df_dv = -self%damping*outer3(u, u)
   end subroutine spring_state_force

   !> Over a step from x0 to x1: the discrete gradient of the spring's energy and the dashpot
   !> along the midpoint direction on the mean velocity (see the module's description).
   pure subroutine spring_step_force(self, t0, dt, x0, x1, f, df_dx1, f_damping)
      !> The end.
      class(spring_end), intent(in) :: self
      !> Time at the start of the step and the step, s.
      real(dp), intent(in) :: t0, dt
      !> Positions of the end node at the start and the end of the step, m.
      real(dp), intent(in) :: x0(3), x1(3)
      !> Force over the step on the cable's end node, N; its derivative with respect to x1, N/m;
      !> its dissipative part, N.
      real(dp), intent(out) :: f(3), df_dx1(3, 3), f_damping(3)
      real(dp) :: d0(3), d1(3), s(3), l0, l1, sum_l, q, u1(3), w(3), ls, vm(3), rate, p(3, 3)
      d0 = x0 - self%anchor
      d1 = x1 - self%anchor
      l0 = norm2(d0)
      l1 = norm2(d1)
      s = d0 + d1
      sum_l = l0 + l1
      f = 0
      df_dx1 = 0
      if (sum_l > 0) then
         ! q: the divided difference of U(l) = k (l - L0)^2 / 2 between l0 and l1.
         q = self%stiffness*(0.5_dp*sum_l - self%rest_length)
         f = -q*s/sum_l
         u1 = 0
         if (l1 > 0) u1 = d1/l1
         df_dx1 = -((0.5_dp*self%stiffness - q/sum_l)*outer3(s, u1)/sum_l + q/sum_l*identity3())
      end if
      f_damping = 0
      ls = norm2(s)
      if (ls > 0 .and. self%damping > 0) then
         w = s/ls
         vm = (x1 - x0)/dt
         rate = dot_product(w, vm)
         p = identity3() - outer3(w, w)
         f_damping = -self%damping*rate*w
         ! d w / d x1 = P / |s|; d vm / d x1 = I / dt.
         df_dx1 = df_dx1 - self%damping*((rate*p + outer3(w, matmul(p, vm)))/ls + outer3(w, w)/dt)
      end if
      f = f + f_damping
   end subroutine spring_step_force

   !> U = k (l - L0)^2 / 2, J.
   pure real(dp) function spring_stored_energy(self, x)
      !> The end.
      class(spring_end), intent(in) :: self
      !> Position of the end node (x, y, z), m.
      real(dp), intent(in) :: x(3)
      spring_stored_energy = 0.5_dp*self%stiffness*(norm2(x - self%anchor) - self%rest_length)**2
   end function spring_stored_energy

end module xcable_ends_spring
