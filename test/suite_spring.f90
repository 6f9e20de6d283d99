!> The spring end (kind = 'spring', ends/spring.f90) against closed forms:
!> - a straight line in zero gravity between a fixed end and a spring: the
!>   static tension T = f(eps) = k (D - L (1 + eps) - L0), in closed form for
!>   the linear law, in 2-D and out of the plane in 3-D (the tanh law, the
!>   scalar equation solved by bisection);
!> - a sagging line on a spring (statics): the extensible catenary from the
!>   fixed end whose end force the spring balances (theory/closed_forms.f90's
!>   catenary_from_force), on two grids (second order);
!> - a point mass on a spring at the end of a light line: the period of the
!>   axial oscillation, from the exact frequency equation of the line (wave
!>   equation) with the mass and the spring at its end,
!>   EA beta cos(beta L) = (M w^2 - k) sin(beta L), beta = w sqrt(m / EA)
!>   (for a light line w^2 -> (k + EA / L) / M: the mass sits between the
!>   line and the spring, which act in parallel), and the trapezoidal rule's
!>   own frequency w_h = (2 / dt) atan(w dt / 2) of a linear oscillator;
!>   in 2-D and in 3-D along a line out of the plane; the ledger closes;
!> - the ledger of a mass on a spring with a rest length and a dashpot swinging
!>   across the line (the spring turns): the discrete gradient of the
!>   spring's energy closes it to the Newton tolerance, where the midpoint
!>   rule would not (its error grows with the spring's rotation per step).
module suite_spring
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config, end_config
   use xcable_driver_simulation, only: simulation
   use xcable_theory_closed_forms, only: catenary_from_force
   use xcable_material_law, only: material_law, tanh_law, linear_law
   use xcable_ends_end_condition, only: end_condition
   use xcable_ends_factory, only: new_end
   use xcable_driver_rod3d_run, only: rod3d_run
   use suite_rod_statics, only: statics_config
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_spring

   real(dp), parameter :: pi = acos(-1.0_dp)
   !> Measured (the tests' bounds are three times these): the mass on a spring's period against
   !> the trapezoidal rule's frequency of the exact one, and the sagging line's end point
   !> extrapolated from 41 and 81 nodes against the catenary, m.
   real(dp), parameter :: err_period_measured = 4.4e-7_dp, err_r_measured = 1.7e-8_dp
   !> Measured: the swinging spring's ledger drift over its largest energy.
   real(dp), parameter :: swing_drift_measured = 1.1e-13_dp

contains

   subroutine collect_spring(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('straight_line_zero_gravity', test_straight), &
               new_unittest('straight_line_3d_out_of_plane', test_straight_3d), &
               new_unittest('sagging_line_catenary', test_sagging), &
               new_unittest('mass_on_spring_period', test_period), &
               new_unittest('mass_on_spring_period_3d', test_period_3d), &
               new_unittest('ledger_swinging_spring', test_swing)]
   end subroutine collect_spring

   !> A 10 m line of the linear law in zero gravity, end a fixed at the origin, end b on a spring
   !> to the anchor (d, 0) with the rest length l0.
   function straight_config(nodes, ea, k, d, l0) result(c)
      integer, intent(in) :: nodes
      real(dp), intent(in) :: ea, k, d, l0
      type(case_config) :: c
      c = statics_config(nodes)
      c%length = 10
      c%gravity = 0
      c%law = 'linear'
      c%ea = ea
      c%end_b%kind = 'spring'
      c%end_b%x = d
      c%end_b%z = 0
      c%end_b%stiffness = k
      c%end_b%rest_length = l0
      c%given = 'end_b%x end_b%z'
   end function straight_config

   !> Linear law: EA eps = k (D - L (1 + eps) - L0), so eps = k (D - L - L0) / (EA + k L).
   subroutine test_straight(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: ea = 4.0e5_dp, k = 3.0e4_dp, d = 10.7_dp, l0 = 0.25_dp
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: eps, tension, err_t, err_x, x_end, t_num
      integer :: n
      call sim%prepare(straight_config(21, ea, k, d, l0), error)
      if (allocated(error)) return
      eps = k*(d - 10 - l0)/(ea + k*10)
      tension = ea*eps
      n = size(sim%rod%static%r, 2)
      x_end = sim%rod%static%r(1, n)
      t_num = ea*((sim%rod%static%r(1, n) - sim%rod%static%r(1, n - 1))/0.5_dp - 1)
      err_t = abs(t_num - tension)/tension
      err_x = abs(x_end - 10*(1 + eps))/10
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,f0.3,a)') 'straight line on a spring: tension error ', err_t, &
         ', end position error / L ', err_x, ' (T = ', tension, ' N)'
      call check(error, err_t < 1.0e-12_dp .and. err_x < 1.0e-12_dp .and. abs(sim%rod%static%r(2, n)) < 1.0e-12_dp, &
                 'straight line on a spring: tension error '//str(err_t)//', position error '//str(err_x))
      if (allocated(error)) return
      ! Mirrored: the spring at end a (anchor at 10 - D), end b fixed at (10, 0).
      c = straight_config(21, ea, k, d, l0)
      c%end_a = c%end_b
      c%end_a%x = 10 - d
      c%end_b = end_config()
      c%end_b%x = 10
      c%given = 'end_a%x end_a%z end_b%x end_b%z'
      call sim%prepare(c, error)
      if (allocated(error)) return
      t_num = ea*((sim%rod%static%r(1, 2) - sim%rod%static%r(1, 1))/0.5_dp - 1)
      err_t = abs(t_num - tension)/tension
      err_x = abs(sim%rod%static%r(1, 1) - (10 - 10*(1 + eps)))/10
      write (output_unit, '(4x,a,es9.2,a,es9.2)') 'the same with the spring at end a: tension error ', err_t, &
         ', end position error / L ', err_x
      call check(error, err_t < 1.0e-12_dp .and. err_x < 1.0e-12_dp, 'straight line on a spring at end a: tension '// &
                 'error '//str(err_t)//', position error '//str(err_x))
   end subroutine test_straight

   !> The tanh law's T = f(eps) = k (D - L (1 + eps) - L0) by bisection on eps.
   real(dp) function spring_strain(law, k, d, length, l0) result(eps)
      class(material_law), intent(in) :: law
      real(dp), intent(in) :: k, d, length, l0
      real(dp) :: lo, hi
      integer :: it
      lo = 0
      hi = (d - length - l0)/length
      do it = 1, 200
         eps = 0.5_dp*(lo + hi)
         if (law%tension(eps) > k*(d - length*(1 + eps) - l0)) then
            hi = eps
         else
            lo = eps
         end if
      end do
   end function spring_strain

   !> A 3-D piece (rod3d_run) in zero gravity: end a fixed at pa, end b on a spring to pa + d u,
   !> u out of the x-z plane; nodes on the straight line; mass m per length, a point mass at b.
   subroutine line_3d(run, law, n, pa, u, d, k, l0, mass, m, error)
      type(rod3d_run), intent(out) :: run
      class(material_law), intent(in) :: law
      integer, intent(in) :: n
      real(dp), intent(in) :: pa(3), u(3), d, k, l0, mass, m
      type(error_type), allocatable, intent(out) :: error
      type(end_config) :: fixed, spring
      class(end_condition), allocatable :: end_a, end_b
      real(dp) :: s(n), anchor(3)
      integer :: j
      fixed%kind = 'fixed'
      fixed%x = pa(1)
      fixed%y = pa(2)
      fixed%z = pa(3)
      anchor = pa + d*u
      spring%kind = 'spring'
      spring%x = anchor(1)
      spring%y = anchor(2)
      spring%z = anchor(3)
      spring%stiffness = k
      spring%rest_length = l0
      spring%mass = mass
      call new_end(fixed, 'end_a', end_a, error)
      if (allocated(error)) return
      call new_end(spring, 'end_b', end_b, error)
      if (allocated(error)) return
      s = [(10.0_dp*(j - 1)/(n - 1), j=1, n)]
      call run%problem%piece%init(s, m, 0.0_dp, 1.0e-2_dp, 1.0e-2_dp, 0.0_dp, 1.0_dp, law, end_a, end_b, 1.0e4_dp, &
                                  error)
      if (allocated(error)) return
      call run%init(1.0e-12_dp)
      do j = 1, n
         run%x(3*j - 2:3*j) = pa + s(j)*u
      end do
      call run%statics(0.0_dp, error)
   end subroutine line_3d

   !> The straight line out of the plane (3-D rod, tanh law): tension and end position.
   subroutine test_straight_3d(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: k = 2.0e5_dp, d = 10.4_dp, l0 = 0.1_dp
      type(rod3d_run) :: run
      type(tanh_law) :: law
      real(dp) :: u(3), pa(3), eps, err_t, err_x, rn(3), t_num
      integer, parameter :: n = 21
      pa = [1.0_dp, -2.0_dp, 3.0_dp]
      u = [cos(0.5_dp)*cos(0.3_dp), sin(0.5_dp)*cos(0.3_dp), sin(0.3_dp)]
      call line_3d(run, law, n, pa, u, d, k, l0, 0.0_dp, 1.0_dp, error)
      if (allocated(error)) return
      eps = spring_strain(law, k, d, 10.0_dp, l0)
      rn = run%x(3*n - 2:3*n)
      t_num = law%tension(norm2(rn - run%x(3*n - 5:3*n - 3))/0.5_dp - 1)
      err_t = abs(t_num - law%tension(eps))/law%tension(eps)
      err_x = norm2(rn - (pa + 10*(1 + eps)*u))/10
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,f0.1,a)') '3-D straight line on a spring out of the plane: '// &
         'tension error ', err_t, ', end position error / L ', err_x, ' (T = ', law%tension(eps), ' N)'
      call check(error, err_t < 1.0e-10_dp .and. err_x < 1.0e-12_dp, '3-D straight line on a spring: tension '// &
                 'error '//str(err_t)//', position error '//str(err_x))
   end subroutine test_straight_3d

   !> The paper's cable (tanh law, nearly no bending stiffness), 30 m, end a fixed at the origin,
   !> end b on a spring (k = 400 N/m, rest length 1 m) to the anchor (29, -6) m: against the
   !> extensible catenary whose end force N(L) the spring balances, N(L) = F_spring(R(L)) (Newton
   !> on N(L) with central differences, catenary_from_force's 8-point quadrature). End position
   !> and end force on 41 and 81 nodes: second order, the finer within the bounds.
   subroutine test_sagging(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: k = 400, l0 = 1, anchor(2) = [29.0_dp, -6.0_dp], length = 30
      type(tanh_law) :: law
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w, nl(2), pos(2), err_x(2), err_f(2), f_rod(2), order, ends(2, 2), err_r
      integer :: g, n
      w = 1140*pi*0.05_dp**2/4*9.81_dp
      call reference(nl, pos)
      do g = 1, 2
         c = statics_config(merge(41, 81, g == 1))
         c%length = length
         c%bending_stiffness = 1.0e-3_dp
         c%end_b%kind = 'spring'
         c%end_b%x = anchor(1)
         c%end_b%z = anchor(2)
         c%end_b%stiffness = k
         c%end_b%rest_length = l0
         c%given = 'end_b%x end_b%z'
         call sim%prepare(c, error)
         if (allocated(error)) return
         n = size(sim%rod%static%r, 2)
         ! The spring's force at the rod's end.
         f_rod = sim%rod%static%r(:, n) - anchor
         f_rod = -k*(norm2(f_rod) - l0)*f_rod/norm2(f_rod)
         ends(:, g) = sim%rod%static%r(:, n)
         err_x(g) = norm2(sim%rod%static%r(:, n) - pos)
         err_f(g) = norm2(f_rod - nl)/norm2(nl)
      end do
      order = log(err_x(1)/err_x(2))/log(2.0_dp)
      ! Richardson's extrapolation of the two grids' end points.
      err_r = norm2((4*ends(:, 2) - ends(:, 1))/3 - pos)
      write (output_unit, '(4x,a,2es9.2,a,2es9.2,a,f5.2,a,es9.2,a,f0.2,a)') 'sagging line on a spring vs the '// &
         'catenary (41, 81 nodes): end position error (m)', err_x, ', end force error', err_f, ' (order ', order, &
         '; extrapolated ', err_r, ' m; |N(L)| = ', norm2(nl), ' N)'
      call check(error, err_x(2) < 1.5e-4_dp .and. err_f(2) < 1.0e-4_dp .and. abs(order - 2) < 0.05_dp .and. &
                 err_r < 3*err_r_measured, 'sagging line on a spring: end position error '//str(err_x(2))// &
                 ' m, end force error '//str(err_f(2))//', order '//str(order)//', extrapolated '//str(err_r)//' m')

   contains

      !> The catenary from the fixed end with the end force N(L) that the spring balances.
      subroutine reference(force, point)
         real(dp), intent(out) :: force(2), point(2)
         real(dp) :: g0(2), gp(2), gm(2), jac(2, 2), h, det, trial(2)
         integer :: it, j
         force = [300.0_dp, 200.0_dp]
         do it = 1, 50
            g0 = mismatch(force)
            if (norm2(g0) < 1.0e-11_dp*norm2(force)) exit
            h = 1.0e-5_dp*norm2(force)
            do j = 1, 2
               trial = force
               trial(j) = force(j) + h
               gp = mismatch(trial)
               trial(j) = force(j) - h
               gm = mismatch(trial)
               jac(:, j) = (gp - gm)/(2*h)
            end do
            det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
            force = force - [jac(2, 2)*g0(1) - jac(1, 2)*g0(2), -jac(2, 1)*g0(1) + jac(1, 1)*g0(2)]/det
         end do
         point = end_point(force)
      end subroutine reference

      function end_point(force) result(p)
         real(dp), intent(in) :: force(2)
         real(dp) :: p(2), rr(2, 2), ee(2), tt(2)
         call catenary_from_force(law, w, force - [0.0_dp, w*length], [0.0_dp, 0.0_dp], [0.0_dp, length], rr, ee, tt)
         p = rr(:, 2)
      end function end_point

      !> N(L) minus the spring's force at the catenary's end point.
      function mismatch(force) result(m)
         real(dp), intent(in) :: force(2)
         real(dp) :: m(2), p(2), dvec(2)
         p = end_point(force)
         dvec = p - anchor
         m = force + k*(norm2(dvec) - l0)*dvec/norm2(dvec)
      end function mismatch
   end subroutine test_sagging

   !> The lowest angular frequency of a line (EA, mass m per length, length L) fixed at one end
   !> with a point mass M and a spring k to the ground at the other, for axial motion: the lowest
   !> root of EA beta cos(beta L) - (M w^2 - k) sin(beta L), beta = w sqrt(m / EA) (bisection from
   !> the first change of sign).
   real(dp) function axial_frequency(ea, m, length, mass, k) result(w)
      real(dp), intent(in) :: ea, m, length, mass, k
      real(dp) :: lo, hi, rigid
      integer :: it
      rigid = sqrt(1/(1/k + length/ea)/mass)
      lo = 0.5_dp*rigid
      hi = lo
      do while (f(hi) > 0)
         lo = hi
         hi = hi*1.01_dp
      end do
      do it = 1, 200
         w = 0.5_dp*(lo + hi)
         if (f(w) > 0) then
            lo = w
         else
            hi = w
         end if
      end do
   contains
      real(dp) function f(om)
         real(dp), intent(in) :: om
         real(dp) :: beta
         beta = om*sqrt(m/ea)
         f = ea*beta*cos(beta*length) - (mass*om**2 - k)*sin(beta*length)
      end function f
   end function axial_frequency

   !> Downward zero crossings of v(t) - mean(v) over the record: the mean period.
   real(dp) function mean_period(t, v) result(period)
      real(dp), intent(in) :: t(:), v(:)
      real(dp) :: first, last, tc
      integer :: i, count
      count = 0
      first = 0
      last = 0
      do i = 2, size(t)
         if (v(i - 1) > 0 .and. v(i) <= 0) then
            tc = t(i - 1) + (t(i) - t(i - 1))*v(i - 1)/(v(i - 1) - v(i))
            if (count == 0) first = tc
            last = tc
            count = count + 1
         end if
      end do
      period = (last - first)/max(count - 1, 1)
   end function mean_period

   !> A 50 kg mass on a spring (k = 2e4 N/m, rest length 0.2 m) at the end of a 10 m line of the
   !> linear law (EA = 1e5 N, 0.02 kg/m) fixed at the other end, zero gravity, set moving along
   !> the line at 0.05 m/s: the period from the end's velocity against the frequency equation,
   !> and the ledger. dt = 5e-4 s: the trapezoidal rule's period error (w dt)^2 / 12 is 2.8e-6.
   subroutine test_period(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: ea = 1.0e5_dp, k = 2.0e4_dp, mass = 50
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: m, w, period, err, drift, w_h
      integer :: n, j, nh
      c = straight_config(21, ea, k, 10.5_dp, 0.2_dp)
      c%density = 1.0_dp/(pi*0.05_dp**2/4)*0.02_dp
      c%end_b%mass = mass
      c%dt = 5.0e-4_dp
      c%t_end = 3
      c%energy = .true.
      c%interval = 0
      c%newton_tol = 1.0e-12_dp
      m = 0.02_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      n = size(sim%rod%pieces(1)%v, 2)
      do j = 1, n
         sim%rod%pieces(1)%v(:, j) = [0.05_dp*(j - 1)/(n - 1), 0.0_dp]
      end do
      call sim%run(error=error)
      if (allocated(error)) return
      nh = sim%rod%history%n
      w = axial_frequency(ea, m, 10.0_dp, mass, k)
      w_h = 2/c%dt*atan(0.5_dp*w*c%dt)
      period = mean_period(sim%rod%history%time(0:nh), sim%rod%history%ends(3, 2, 0:nh))
      err = abs(period - 2*pi/w_h)/(2*pi/w_h)
      associate (en => sim%rod%history%energy)
         drift = maxval(abs(en(7, 0:nh) - en(7, 0)))/maxval(abs(en(1:4, 0:nh)))
      end associate
      write (output_unit, '(4x,a,f0.7,a,f0.7,a,f0.7,a,es9.2,a,es9.2)') 'mass on a spring: period ', period, &
         ' s; exact ', 2*pi/w, ' s, with the trapezoidal rule''s ', 2*pi/w_h, ' s: relative error ', err, &
         '; ledger drift ', drift
      call check(error, err < 3*err_period_measured .and. drift < 1.0e-11_dp, 'mass on a spring: period error '// &
                 str(err)//', ledger drift '//str(drift))
   end subroutine test_period

   !> The same oscillator along a line out of the x-z plane (3-D rod, rod3d_run): the period of
   !> the velocity along the line against the frequency equation, and the ledger.
   subroutine test_period_3d(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: ea = 1.0e5_dp, k = 2.0e4_dp, mass = 50, dt = 5.0e-4_dp
      type(rod3d_run) :: run
      type(linear_law) :: law
      real(dp) :: u(3), pa(3), w, period, err, worst, scale, t(0:6000), vu(0:6000), w_h
      integer, parameter :: n = 21
      integer :: j, i
      law%ea = ea
      pa = [0.5_dp, 1.5_dp, -2.0_dp]
      u = [cos(1.1_dp)*cos(-0.4_dp), sin(1.1_dp)*cos(-0.4_dp), sin(-0.4_dp)]
      call line_3d(run, law, n, pa, u, 10.5_dp, k, 0.2_dp, mass, 0.02_dp, error)
      if (allocated(error)) return
      do j = 1, n
         run%v(:, j) = 0.05_dp*(j - 1)/(n - 1.0_dp)*u
      end do
      call run%start(run%x, run%v, 0.0_dp)
      worst = 0
      scale = 0
      t(0) = 0
      vu(0) = dot_product(run%v(:, n), u)
      do i = 1, 6000
         call run%step(dt, 0.5_dp, error)
         if (allocated(error)) return
         t(i) = run%t
         vu(i) = dot_product(run%v(:, n), u)
         worst = max(worst, abs(run%imbalance()))
         scale = max(scale, sum(abs(run%energies())))
      end do
      w = axial_frequency(ea, 0.02_dp, 10.0_dp, mass, k)
      w_h = 2/dt*atan(0.5_dp*w*dt)
      period = mean_period(t, vu)
      err = abs(period - 2*pi/w_h)/(2*pi/w_h)
      write (output_unit, '(4x,a,f0.7,a,f0.7,a,es9.2,a,es9.2)') '3-D mass on a spring out of the plane: period ', &
         period, ' s, with the trapezoidal rule''s exact ', 2*pi/w_h, ' s: relative error ', err, '; ledger ', &
         worst/scale
      call check(error, err < 3*err_period_measured .and. worst/scale < 1.0e-11_dp, '3-D mass on a spring: '// &
                 'period error '//str(err)//', ledger '//str(worst/scale))
   end subroutine test_period_3d

   !> Zero gravity, a 5 kg mass at the end of the 10 m line, on a spring (k = 2e4 N/m, rest
   !> length 0.3 m, dashpot 20 N s/m) to the anchor (10.5, 0) m, the line set swinging across at
   !> up to 3 m/s; 2 ms steps: the ledger (stored energy, spring included, minus work plus
   !> dissipation, the dashpot's included) closes to the Newton tolerance, and the dashpot took
   !> energy.
   subroutine test_swing(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: drift, taken
      integer :: n, j, nh
      c = straight_config(21, 1.0e5_dp, 2.0e4_dp, 10.5_dp, 0.3_dp)
      c%end_b%mass = 5
      c%end_b%damping = 20
      c%dt = 2.0e-3_dp
      c%t_end = 1
      c%energy = .true.
      c%interval = 0
      c%newton_tol = 1.0e-12_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      n = size(sim%rod%pieces(1)%v, 2)
      do j = 1, n
         sim%rod%pieces(1)%v(:, j) = [0.0_dp, 3.0_dp*(j - 1)/(n - 1)]
      end do
      call sim%run(error=error)
      if (allocated(error)) return
      nh = sim%rod%history%n
      associate (en => sim%rod%history%energy)
         drift = maxval(abs(en(7, 0:nh) - en(7, 0)))/maxval(abs(en(1:4, 0:nh)))
         taken = en(6, nh)/maxval(abs(en(1:4, 0:nh)))
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'swinging mass on a spring: ledger drift ', drift, &
         ' of the largest energy; the dashpot took ', taken, ' of it'
      call check(error, drift < 3*swing_drift_measured .and. taken > 1.0e-4_dp, 'swinging mass on a spring: ledger '// &
                 'drift '//str(drift)//', dashpot '//str(taken))
   end subroutine test_swing
end module suite_spring
