!> References of the work-precision benchmark: simple-wave theory of a
!> straight string released by the ramp T_s cos^2(pi t / (2 t_br)) at its
!> breaking end and held by a wall (u = 0) at the other end.
!>
!> Straight string: the sag (centimetres over 70 m) and gravity change the
!> static tension along the cable by w0^2 L^2 / (8 T_s), about 1 N at 180 kN
!> (6e-6 T_s), and the tangential component of gravity changes the end speed
!> by about g (w0 L / 2 T_s) t, 4e-3 m/s over 0.1 s (3e-5 of 111 m/s): the
!> references are accurate to well under 1 % (about 1e-4).
!>
!> Breaking-end speed: the Riemann variable phi(eps) = integral of c d eps is
!> carried unchanged from the static state to the end, where the tension is
!> zero after t_br, so |u| = phi(eps0) - phi(eps(T = 0)) (a shock changes it
!> only at third order in its strength).
!>
!> 1 % drop at the wall: characteristics leave the breaking end at the time
!> tau when f(eps) = T_s cos^2(pi tau / (2 t_br)) and run at c(eps) (per
!> unstretched length). At the wall the change of phi doubles, so the wall
!> strain eps_w with f(eps_w) = 0.99 T_s needs the incoming strain eps_inc
!> with phi(eps0) - phi(eps_inc) = (phi(eps0) - phi(eps_w)) / 2. Where the law
!> is concave (eps > 0.2086) later characteristics are faster: they may catch
!> the front before the wall, forming a weak shock. The shock is fitted: it
!> absorbs the characteristics that reach it and runs at the Rankine-Hugoniot
!> speed S^2 = (f(eps0) - f(eps_b)) / (m (eps0 - eps_b)) between the
!> undisturbed strain ahead and the strain eps_b of the last characteristic
!> absorbed. Its reflection at the wall is taken as that of a simple wave
!> (error third order in the shock strength). The incoming characteristic is
!> slowed near the wall by the waves already reflected; a bound on that delay
!> is reported with the reference.
module bench_theory
   use xcable_core_kinds, only: dp
   use xcable_material_law, only: material_law
   use xcable_theory_closed_forms, only: wave_speed, riemann_speed, wall_incoming_strain
   implicit none
   private
   public :: wave_reference, simple_wave_reference

   !> The references of one case.
   type :: wave_reference
      !> Static strain and tension T_s (N).
      real(dp) :: eps0 = 0, tension = 0
      !> Axial wave speed at eps0, m/s.
      real(dp) :: speed0 = 0
      !> Peak breaking-end speed, m/s.
      real(dp) :: end_speed = 0
      !> Time of the 1 % drop of the wall tension, s (with the shock fitted).
      real(dp) :: drop_time = 0
      !> The same from the characteristic eps_inc alone (no shock), s.
      real(dp) :: drop_time_characteristic = 0
      !> Arrival of the first disturbance (front or shock) at the wall, s.
      real(dp) :: front_time = 0
      !> Distance from the breaking end where the first characteristics cross, m (huge: none before the wall).
      real(dp) :: shock_distance = huge(1.0_dp)
      !> Strain jump of the shock when it reaches the wall (0: no shock).
      real(dp) :: shock_jump = 0
      !> Upper bound of the delay of the eps_inc characteristic by the reflected waves, s.
      real(dp) :: interaction_bound = 0
   end type wave_reference

   !> Characteristics per ramp in the shock fitting.
   integer, parameter :: n_char = 20000

contains

   !> Simple-wave references of a release with ramp time t_break from static strain eps0.
   subroutine simple_wave_reference(law, mass, length, eps0, t_break, drop, ref)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Mass per unstretched length, kg/m.
      real(dp), intent(in) :: mass
      !> Unstretched length, m.
      real(dp), intent(in) :: length
      !> Static strain.
      real(dp), intent(in) :: eps0
      !> Breaking time, s (> 0).
      real(dp), intent(in) :: t_break
      !> Relative drop of the wall tension that marks the arrival (0.01).
      real(dp), intent(in) :: drop
      !> The references.
      type(wave_reference), intent(out) :: ref
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: t_s, eps_w, eps_inc, tau_max, x, t, s_speed, t_next, t_arr, t_prev
      real(dp) :: tau(0:n_char), eps(0:n_char), c(0:n_char), dtau, t_form, t_ahead, t_behind, t_shock
      integer :: i, a, b, it

      t_s = law%tension(eps0)
      ref%eps0 = eps0
      ref%tension = t_s
      ref%speed0 = wave_speed(law, mass, eps0)
      ref%end_speed = riemann_speed(law, mass, law%strain_at(0.0_dp), eps0)

      ! Incoming strain that gives the drop at the wall (phi doubles there).
      eps_w = law%strain_at((1 - drop)*t_s)
      eps_inc = wall_incoming_strain(law, mass, eps0, drop)
      ref%drop_time_characteristic = departure(law%tension(eps_inc)) + length/wave_speed(law, mass, eps_inc)

      ! Characteristics leaving the end while the tension falls to (1 - 10 drop) T_s.
      tau_max = departure((1 - 10*drop)*t_s)
      dtau = tau_max/n_char
      do i = 0, n_char
         tau(i) = i*dtau
         eps(i) = law%strain_at(t_s*cos(0.5_dp*pi*tau(i)/t_break)**2)
         c(i) = wave_speed(law, mass, eps(i))
      end do

      ! The first crossing of neighbouring characteristics (in time) starts a shock.
      t_form = huge(1.0_dp)
      b = 0
      do i = 1, n_char
         if (c(i) > c(i - 1)) then
            t = (c(i)*tau(i) - c(i - 1)*tau(i - 1))/(c(i) - c(i - 1))
            if (t < t_form) then
               t_form = t
               b = i
            end if
         end if
      end do
      if (b > 0) ref%shock_distance = c(b)*(t_form - tau(b))

      if (ref%shock_distance < length) then
         ! Fit the shock: it runs at S(eps_a, eps_b) between the characteristics
         ! a and b it absorbed last, and absorbs those ahead (a decreasing) and
         ! behind (b increasing) that it meets; ahead of char 0 the strain is eps0.
         a = b - 1
         t = t_form
         x = ref%shock_distance
         do
            s_speed = shock_speed(eps(a), eps(b))
            t_ahead = huge(1.0_dp)
            if (a > 0) t_ahead = meet(a - 1)
            t_behind = huge(1.0_dp)
            if (b < n_char) t_behind = meet(b + 1)
            t_next = min(t_ahead, t_behind)
            if (x + s_speed*(t_next - t) >= length) exit
            x = x + s_speed*(t_next - t)
            t = t_next
            if (t_ahead <= t_behind) then
               a = a - 1
            else
               b = b + 1
            end if
         end do
         t_shock = t + (length - x)/s_speed
         ref%shock_jump = eps(a) - eps(b)
         ref%front_time = length/c(0)
         if (a == 0) ref%front_time = t_shock
      else
         ref%front_time = length/c(0)
         t_shock = huge(1.0_dp)
         a = n_char + 1
         b = n_char + 2
      end if

      ! Wall: the incoming strain falls through the characteristics ahead of the
      ! shock (i < a), jumps at the shock (a..b absorbed), then falls through
      ! those behind it (i > b).
      ref%drop_time = -1
      t_prev = 0
      do i = 0, n_char
         if (i >= a .and. i < b) cycle
         if (i == b) then
            if (t_shock < t_prev) exit
            t_prev = t_shock
            if (eps(b) <= eps_inc) then
               ref%drop_time = t_shock
               exit
            end if
            cycle
         end if
         t_arr = tau(i) + length/c(i)
         ! Characteristics that arrive out of order would have formed a second shock.
         if (t_arr < t_prev) exit
         t_prev = t_arr
         if (eps(i) <= eps_inc) then
            ! Interpolate between this characteristic and the previous one.
            ref%drop_time = t_arr
            if (i > 0 .and. (i < a .or. i - 1 > b)) then
               ref%drop_time = tau(i - 1) + length/c(i - 1) + (t_arr - tau(i - 1) - length/c(i - 1))* &
                               (eps(i - 1) - eps_inc)/(eps(i - 1) - eps(i))
            end if
            exit
         end if
      end do

      ! The eps_inc characteristic meets the waves reflected since the front
      ! arrived within c (t_drop - t_front) / 2 of the wall, where the strain
      ! lies between eps_w and eps_inc.
      ref%interaction_bound = 0.5_dp*wave_speed(law, mass, eps_inc)*(ref%drop_time - ref%front_time)* &
                              abs(1/wave_speed(law, mass, eps_w) - 1/wave_speed(law, mass, eps_inc))

   contains

      !> Time at which characteristic i meets the shock (at x at time t, speed s_speed).
      real(dp) function meet(i)
         integer, intent(in) :: i
         if (abs(s_speed - c(i)) < 1.0e-12_dp*c(i)) then
            meet = huge(1.0_dp)
         else
            meet = (s_speed*t - x - c(i)*tau(i))/(s_speed - c(i))
            if (meet < t) meet = huge(1.0_dp)
         end if
      end function meet

      !> Time at which the ramp passes the tension t.
      real(dp) function departure(tension)
         real(dp), intent(in) :: tension
         departure = 2*t_break/pi*acos(sqrt(min(1.0_dp, max(0.0_dp, tension/t_s))))
      end function departure

      !> Rankine-Hugoniot speed of a jump between strains e1 and e2 (per unstretched length).
      real(dp) function shock_speed(e1, e2)
         real(dp), intent(in) :: e1, e2
         if (abs(e1 - e2) < 1.0e-12_dp) then
            shock_speed = wave_speed(law, mass, e1)
         else
            shock_speed = sqrt((law%tension(e1) - law%tension(e2))/(mass*(e1 - e2)))
         end if
      end function shock_speed
   end subroutine simple_wave_reference
end module bench_theory
