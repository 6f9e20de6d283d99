!> Closed-form and quadrature references the numerical solution is checked
!> against: the exact extensible catenary for a general law (no bending), the
!> axial wave speed (eq. 33) and the simple-wave velocity of a released string.
module xcable_theory
   use xcable_kinds, only: dp
   use xcable_material_law, only: material_law
   use xcable_error, only: error_type, fatal_error, stat_input
   use xcable_strings, only: str
   implicit none
   private
   public :: catenary_shape, catenary_summary, horizontal_force
   public :: wave_speed, riemann_speed, gauss_legendre, wall_drop_time, wall_incoming_strain

   !> Gauss-Legendre points per panel.
   integer, parameter :: n_gauss = 8

contains

   !> Horizontal force H of the symmetric catenary with end tension t_end:
   !> the vertical force runs linearly from -w0 L/2 to w0 L/2.
   subroutine horizontal_force(weight, length, t_end, h, error)
      !> Weight per unstretched length w0, N/m.
      real(dp), intent(in) :: weight
      !> Unstretched length, m.
      real(dp), intent(in) :: length
      !> End tension, N.
      real(dp), intent(in) :: t_end
      !> Horizontal force, N.
      real(dp), intent(out) :: h
      !> Error when the tension cannot hold the weight.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: half_weight
      half_weight = 0.5_dp*weight*length
      if (t_end <= half_weight) then
         call fatal_error(error, 'end tension '//str(t_end)//' N cannot hold half the weight w0 L / 2 = ' &
                          //str(half_weight)//' N', stat_input)
         h = 0
         return
      end if
      h = sqrt((t_end - half_weight)*(t_end + half_weight))
   end subroutine horizontal_force

   !> Exact extensible catenary at the points s: H constant, V = w0 (s - L/2),
   !> T = sqrt(H^2 + V^2), eps = f^-1(T), dx/ds = (1+eps) H/T, dz/ds = (1+eps) V/T,
   !> integrated by composite Gauss-Legendre quadrature from the fixed end.
   subroutine catenary_shape(law, weight, length, t_end, s, x, z, eps, error)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Weight per unstretched length, N/m.
      real(dp), intent(in) :: weight
      !> Unstretched length, m.
      real(dp), intent(in) :: length
      !> End tension, N.
      real(dp), intent(in) :: t_end
      !> Points (increasing, from 0), m.
      real(dp), intent(in) :: s(:)
      !> Horizontal and vertical positions and strain at the points.
      real(dp), intent(out) :: x(:), z(:), eps(:)
      !> Error when the tension cannot hold the weight.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: h, xg(n_gauss), wg(n_gauss), a, b, sq, e, t, v, dxp, dzp
      integer :: k, p, q
      integer, parameter :: panels = 16
      call horizontal_force(weight, length, t_end, h, error)
      if (allocated(error)) return
      call gauss_legendre(n_gauss, xg, wg)
      x(1) = 0
      z(1) = 0
      do k = 1, size(s)
         v = weight*(s(k) - 0.5_dp*length)
         eps(k) = law%strain_at(sqrt(h*h + v*v))
         if (k == 1) cycle
         dxp = 0
         dzp = 0
         do p = 1, panels
            a = s(k - 1) + (s(k) - s(k - 1))*(p - 1)/panels
            b = s(k - 1) + (s(k) - s(k - 1))*p/panels
            do q = 1, n_gauss
               sq = 0.5_dp*(a + b) + 0.5_dp*(b - a)*xg(q)
               v = weight*(sq - 0.5_dp*length)
               t = sqrt(h*h + v*v)
               e = law%strain_at(t)
               dxp = dxp + 0.5_dp*(b - a)*wg(q)*(1 + e)*h/t
               dzp = dzp + 0.5_dp*(b - a)*wg(q)*(1 + e)*v/t
            end do
         end do
         x(k) = x(k - 1) + dxp
         z(k) = z(k - 1) + dzp
      end do
   end subroutine catenary_shape

   !> Span, sag, end angle below the horizontal and mid-span strain of the exact catenary.
   subroutine catenary_summary(law, weight, length, t_end, span, sag, end_angle, mid_strain, error)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Weight per unstretched length, N/m.
      real(dp), intent(in) :: weight
      !> Unstretched length, m.
      real(dp), intent(in) :: length
      !> End tension, N.
      real(dp), intent(in) :: t_end
      !> Horizontal distance between the ends, m.
      real(dp), intent(out) :: span
      !> Depth of mid-span below the ends, m.
      real(dp), intent(out) :: sag
      !> Angle of the tangent at the ends below the horizontal, rad.
      real(dp), intent(out) :: end_angle
      !> Strain at mid-span.
      real(dp), intent(out) :: mid_strain
      !> Error when the tension cannot hold the weight.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: x(3), z(3), eps(3), h
      call catenary_shape(law, weight, length, t_end, [0.0_dp, 0.5_dp*length, length], x, z, eps, error)
      if (allocated(error)) return
      call horizontal_force(weight, length, t_end, h, error)
      span = x(3)
      sag = -z(2)
      end_angle = atan2(0.5_dp*weight*length, h)
      mid_strain = eps(2)
   end subroutine catenary_summary

   !> Axial wave speed c = sqrt(f'(eps) / m) (eq. 33), m/s.
   elemental function wave_speed(law, mass, eps) result(c)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Mass per unstretched length, kg/m.
      real(dp), intent(in) :: mass
      !> Strain.
      real(dp), intent(in) :: eps
      real(dp) :: c
      c = sqrt(law%stiffness(eps)/mass)
   end function wave_speed

   !> Integral of c(eps) d eps from eps_low to eps_high (the change of the
   !> Riemann variable; the simple-wave speed of a released end), m/s.
   function riemann_speed(law, mass, eps_low, eps_high) result(phi)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Mass per unstretched length, kg/m.
      real(dp), intent(in) :: mass
      !> Limits of integration.
      real(dp), intent(in) :: eps_low, eps_high
      real(dp) :: phi
      real(dp) :: xg(n_gauss), wg(n_gauss), a, b
      integer :: p, q
      integer, parameter :: panels = 64
      call gauss_legendre(n_gauss, xg, wg)
      phi = 0
      do p = 1, panels
         a = eps_low + (eps_high - eps_low)*(p - 1)/panels
         b = eps_low + (eps_high - eps_low)*p/panels
         do q = 1, n_gauss
            phi = phi + 0.5_dp*(b - a)*wg(q)*wave_speed(law, mass, 0.5_dp*(a + b) + 0.5_dp*(b - a)*xg(q))
         end do
      end do
   end function riemann_speed

   !> Simple-wave time at which the tension at the fixed end (a wall, u = 0)
   !> has dropped by the fraction drop, for a straight string released by the
   !> ramp T_s cos^2(pi t / (2 t_break)) at its other end. At the wall the
   !> change of the Riemann variable phi = integral of c d eps doubles, so the
   !> wall strain eps_w (f(eps_w) = (1 - drop) T_s) is reached when the
   !> incoming characteristic with phi(eps_inc) = (phi(eps0) + phi(eps_w)) / 2
   !> arrives; it left the breaking end when the ramp passed f(eps_inc) and
   !> runs at c(eps_inc). Valid while characteristics do not cross, that is
   !> for a law convex between eps_inc and eps0 (no shock).
   function wall_drop_time(law, mass, length, eps0, t_break, drop) result(t)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Mass per unstretched length, kg/m.
      real(dp), intent(in) :: mass
      !> Unstretched length, m.
      real(dp), intent(in) :: length
      !> Static strain.
      real(dp), intent(in) :: eps0
      !> Breaking time, s.
      real(dp), intent(in) :: t_break
      !> Relative drop of the wall tension (e.g. 0.01).
      real(dp), intent(in) :: drop
      real(dp) :: t
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: t_s, eps_inc, t_e
      t_s = law%tension(eps0)
      eps_inc = wall_incoming_strain(law, mass, eps0, drop)
      t_e = 0
      if (t_break > 0) t_e = 2*t_break/pi*acos(sqrt(law%tension(eps_inc)/t_s))
      t = t_e + length/wave_speed(law, mass, eps_inc)
   end function wall_drop_time

   !> Strain of the incoming simple-wave characteristic that lowers the wall
   !> tension by the fraction drop: phi(eps0) - phi(eps_inc) is half of
   !> phi(eps0) - phi(eps_w), with f(eps_w) = (1 - drop) f(eps0) (bisection).
   function wall_incoming_strain(law, mass, eps0, drop) result(eps_inc)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Mass per unstretched length, kg/m.
      real(dp), intent(in) :: mass
      !> Static strain.
      real(dp), intent(in) :: eps0
      !> Relative drop of the wall tension.
      real(dp), intent(in) :: drop
      real(dp) :: eps_inc
      real(dp) :: eps_w, half, lo, hi
      integer :: it
      eps_w = law%strain_at((1 - drop)*law%tension(eps0))
      half = 0.5_dp*riemann_speed(law, mass, eps_w, eps0)
      lo = eps_w
      hi = eps0
      do it = 1, 100
         eps_inc = 0.5_dp*(lo + hi)
         if (riemann_speed(law, mass, eps_inc, eps0) > half) then
            lo = eps_inc
         else
            hi = eps_inc
         end if
      end do
      eps_inc = 0.5_dp*(lo + hi)
   end function wall_incoming_strain

   !> Gauss-Legendre points and weights on [-1, 1] (Newton on P_n).
   pure subroutine gauss_legendre(n, xg, wg)
      !> Number of points.
      integer, intent(in) :: n
      !> Points and weights.
      real(dp), intent(out) :: xg(n), wg(n)
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: x, p0, p1, p2, dp_dx
      integer :: i, j, it
      do i = 1, n
         x = cos(pi*(i - 0.25_dp)/(n + 0.5_dp))
         do it = 1, 100
            p0 = 1
            p1 = x
            do j = 2, n
               p2 = ((2*j - 1)*x*p1 - (j - 1)*p0)/j
               p0 = p1
               p1 = p2
            end do
            dp_dx = n*(x*p1 - p0)/(x*x - 1)
            if (abs(p1/dp_dx) < 1.0e-16_dp) exit
            x = x - p1/dp_dx
         end do
         xg(i) = x
         wg(i) = 2/((1 - x*x)*dp_dx**2)
      end do
   end subroutine gauss_legendre
end module xcable_theory
