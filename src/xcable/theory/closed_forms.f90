!> Closed-form and quadrature references the numerical solution is checked
!> against: the exact extensible catenary for a general law (no bending), the
!> axial wave speed (eq. 33) and the simple-wave velocity of a released string.
module xcable_theory_closed_forms
   use xcable_core_kinds, only: dp
   use xcable_material_law, only: material_law, strain_kept
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str
   implicit none
   private
   public :: catenary_shape, catenary_summary, horizontal_force
   public :: wave_speed, riemann_speed, gauss_legendre, wall_drop_time, wall_incoming_strain
   public :: catenary_from_force, catenary_between, catenary_segment, segments_from_force

   !> A segment of a line for the catenary of a line of segments: its law, weight per
   !> unstretched length (N/m) and unstretched length (m), and the weight of a body at its end
   !> (N, down; negative for a buoy), where the vertical force jumps by it.
   type :: catenary_segment
      class(material_law), allocatable :: law
      real(dp) :: weight = 0, length = 0, end_weight = 0
   end type catenary_segment

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

   !> Extensible catenary (no bending) from the internal force at s = 0: with
   !> N(s) = n0 + w0 s e_z the internal force (the pull of the part beyond s on
   !> the part before it), T = |N|, eps = f^-1(T) and dR/ds = (1 + eps) N / T,
   !> the positions at the points s (increasing, s(1) = 0) from R(0) = r0, by
   !> composite Gauss-Legendre quadrature. Strain and tension at the points too.
   subroutine catenary_from_force(law, weight, n0, r0, s, r, eps, tension, panels)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Weight per unstretched length, N/m.
      real(dp), intent(in) :: weight
      !> Internal force at s = 0 (x, z), N.
      real(dp), intent(in) :: n0(2)
      !> Position at s = 0, m.
      real(dp), intent(in) :: r0(2)
      !> Points, m.
      real(dp), intent(in) :: s(:)
      !> Positions (2, size(s)), m.
      real(dp), intent(out) :: r(:, :)
      !> Strain and tension (N) at the points.
      real(dp), intent(out) :: eps(:), tension(:)
      !> Gauss-Legendre panels between two points: 8 when absent (the exact reference of the
      !> tests and of catenary_between); the rod statics' first guess takes 1 (model/rod_statics.f90).
      integer, intent(in), optional :: panels
      real(dp) :: xg(n_gauss), wg(n_gauss), a, b, sq, nv(2), t, e
      integer :: k, p, q, np
      type(strain_kept) :: kept
      np = 8
      if (present(panels)) np = panels
      call gauss_legendre(n_gauss, xg, wg)
      do k = 1, size(s)
         nv = n0 + [0.0_dp, weight*s(k)]
         tension(k) = norm2(nv)
         eps(k) = law%strain_at(tension(k), kept)
         if (k == 1) then
            r(:, 1) = r0
            cycle
         end if
         r(:, k) = r(:, k - 1)
         do p = 1, np
            a = s(k - 1) + (s(k) - s(k - 1))*(p - 1)/np
            b = s(k - 1) + (s(k) - s(k - 1))*p/np
            do q = 1, n_gauss
               sq = 0.5_dp*(a + b) + 0.5_dp*(b - a)*xg(q)
               nv = n0 + [0.0_dp, weight*sq]
               t = norm2(nv)
               if (t <= 0) cycle
               e = law%strain_at(t, kept)
               r(:, k) = r(:, k) + 0.5_dp*(b - a)*wg(q)*(1 + e)*nv/t
            end do
         end do
      end do
   end subroutine catenary_from_force

   !> catenary_from_force on a line of segments, from the internal force n0 at s = 0 (each
   !> segment with its own law and weight; the force continuous at a joint): the positions,
   !> strains and tensions at the points s (increasing, s(1) = 0; a point on a joint takes
   !> the strain of the segment before it).
   subroutine segments_from_force(segments, n0, r0, s, r, eps, tension, panels)
      !> The segments from s = 0.
      type(catenary_segment), intent(in) :: segments(:)
      !> Internal force at s = 0 (x, z), N; position at s = 0, m.
      real(dp), intent(in) :: n0(2), r0(2)
      !> Points, m.
      real(dp), intent(in) :: s(:)
      !> Positions (2, size(s)), m.
      real(dp), intent(out) :: r(:, :)
      !> Strain and tension (N) at the points.
      real(dp), intent(out) :: eps(:), tension(:)
      !> Gauss-Legendre panels between two points (catenary_from_force).
      integer, intent(in), optional :: panels
      real(dp) :: start, nj(2), rj(2)
      real(dp), allocatable :: sl(:), rl(:, :), el(:), tl(:)
      integer :: j, k, first, last, m
      start = 0
      nj = n0
      rj = r0
      first = 1
      do j = 1, size(segments)
         ! The points of segment j: first .. last.
         last = first - 1
         do k = first, size(s)
            if (s(k) > start + segments(j)%length .and. j < size(segments)) exit
            last = k
         end do
         m = last - first + 1
         sl = [0.0_dp, s(first:last) - start, segments(j)%length]
         allocate (rl(2, m + 2), el(m + 2), tl(m + 2))
         call catenary_from_force(segments(j)%law, segments(j)%weight, nj, rj, max(sl, 0.0_dp), rl, el, tl, panels)
         if (m > 0) then
            r(:, first:last) = rl(:, 2:m + 1)
            eps(first:last) = el(2:m + 1)
            tension(first:last) = tl(2:m + 1)
         end if
         rj = rl(:, m + 2)
         nj = nj + [0.0_dp, segments(j)%weight*segments(j)%length + segments(j)%end_weight]
         start = start + segments(j)%length
         first = last + 1
         deallocate (rl, el, tl)
      end do
   end subroutine segments_from_force

   !> The extensible catenary hanging between two points: the internal force
   !> n0 at s = 0 such that R(L) = rb when R(0) = ra (a damped Newton
   !> iteration on n0 with central-difference derivatives, from the
   !> inextensible catenary or, for a taut line, a straight line). The ends may
   !> be at different heights; the line may be slack or taut.
   subroutine catenary_between(law, weight, length, ra, rb, n0, error, segments)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Weight per unstretched length, N/m.
      real(dp), intent(in) :: weight
      !> Unstretched length, m.
      real(dp), intent(in) :: length
      !> End points (x, z), m.
      real(dp), intent(in) :: ra(2), rb(2)
      !> Internal force at end a, N.
      real(dp), intent(out) :: n0(2)
      !> Error when no catenary is found.
      type(error_type), allocatable, intent(out) :: error
      !> A line of segments (then law, weight and length are those of its first guess: a law, the
      !> mean weight and the whole length).
      type(catenary_segment), intent(in), optional :: segments(:)
      real(dp) :: d(2), dist, chord, a, lo, hi, h0, res(2), jac(2, 2), step(2), trial(2), rt(2), hstep, nrm, nrm_t
      real(dp) :: rp(2), rm(2), eps_zero, lam
      integer :: it, j, ls
      d = rb - ra
      dist = norm2(d)
      eps_zero = law%strain_at(0.0_dp)
      if (abs(d(1)) < 1.0e-9_dp*max(length, 1.0_dp) .and. dist < length*(1 + eps_zero) .and. weight > 0) then
         ! A slack line between two points one above the other hangs folded (two strands side by
         ! side, a fold the planar statics do not find from any guess tried: a catenary to a point
         ! 0.01 L or 0.1 L beside the end failed). A taut one is straight (below).
         call fatal_error(error, 'the ends are one above the other, '//str(dist)//' m apart, closer than the '// &
                          'cable''s length at zero tension ('//str(length*(1 + eps_zero))//' m): the slack line '// &
                          'would hang folded on itself; give the ends a horizontal offset', stat_input)
         return
      end if
      if (dist >= length*(1 + eps_zero) .or. weight <= 0) then
         ! Taut (or weightless): a straight line at the tension of its mean strain.
         h0 = law%tension(max(dist/length - 1, eps_zero + 1.0e-6_dp))
         n0 = h0*d/dist - [0.0_dp, 0.5_dp*weight*length]
      else
         ! Slack: the inextensible catenary through the two points, a = H / w0 from
         ! 2 a sinh(dx / (2 a)) = sqrt(L^2 - dz^2) (bisection on log a).
         chord = sqrt(max(length**2 - d(2)**2, (1.0e-6_dp*length)**2))
         lo = 1.0e-6_dp*abs(d(1))
         hi = 1.0e6_dp*length
         do it = 1, 200
            a = sqrt(lo*hi)
            if (2*a*sinh(min(abs(d(1))/(2*a), 700.0_dp)) > chord) then
               lo = a
            else
               hi = a
            end if
         end do
         h0 = weight*a
         ! Vertical force at a: the lowest point is where V = 0; for the inextensible
         ! catenary z(L) - z(0) = a (cosh u_b - cosh u_a), x(L) - x(0) = a (u_b - u_a),
         ! with sinh u = V / H.
         lam = abs(d(1))/a
         ! solve a (cosh(u_a + lam) - cosh(u_a)) = dz for u_a (monotone in u_a)
         lo = -50
         hi = 50
         do it = 1, 200
            rp(1) = 0.5_dp*(lo + hi)
            if (a*(cosh(rp(1) + lam) - cosh(rp(1))) > d(2)) then
               hi = rp(1)
            else
               lo = rp(1)
            end if
         end do
         n0 = [sign(h0, d(1)), h0*sinh(0.5_dp*(lo + hi))]
      end if
      ! Newton on the end mismatch R(L) - rb.
      call mismatch(n0, res)
      nrm = norm2(res)
      do it = 1, 100
         if (nrm <= 1.0e-12_dp*length) return
         do j = 1, 2
            hstep = 1.0e-6_dp*max(norm2(n0), weight*length, 1.0_dp)
            trial = n0
            trial(j) = n0(j) + hstep
            call mismatch(trial, rp)
            trial(j) = n0(j) - hstep
            call mismatch(trial, rm)
            jac(:, j) = (rp - rm)/(2*hstep)
         end do
         step = solve2(jac, res)
         ! Backtracking: halve the step until the mismatch falls.
         do ls = 1, 40
            trial = n0 - step
            call mismatch(trial, rt)
            nrm_t = norm2(rt)
            if (nrm_t < nrm) exit
            step = 0.5_dp*step
         end do
         n0 = trial
         res = rt
         nrm = nrm_t
      end do
      if (nrm > 1.0e-8_dp*length) then
         call fatal_error(error, 'no catenary between ('//str(ra(1))//', '//str(ra(2))//') and ('//str(rb(1))// &
                          ', '//str(rb(2))//') m (end mismatch '//str(nrm)//' m)', stat_input)
      end if

   contains

      subroutine mismatch(force0, m)
         real(dp), intent(in) :: force0(2)
         real(dp), intent(out) :: m(2)
         real(dp) :: rr(2, 2), ee(2), tt(2)
         if (present(segments)) then
            call segments_from_force(segments, force0, ra, [0.0_dp, length], rr, ee, tt)
         else
            call catenary_from_force(law, weight, force0, ra, [0.0_dp, length], rr, ee, tt)
         end if
         m = rr(:, 2) - rb
      end subroutine mismatch

      pure function solve2(mat, rhs) result(sol)
         real(dp), intent(in) :: mat(2, 2), rhs(2)
         real(dp) :: sol(2), det
         det = mat(1, 1)*mat(2, 2) - mat(1, 2)*mat(2, 1)
         sol = [mat(2, 2)*rhs(1) - mat(1, 2)*rhs(2), -mat(2, 1)*rhs(1) + mat(1, 1)*rhs(2)]/det
      end function solve2
   end subroutine catenary_between

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
end module xcable_theory_closed_forms
