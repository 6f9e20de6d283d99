!> Tension-strain laws T = f(eps) of the cable material (paper eq. 17).
!>
!> A law is an abstract type with deferred tension f, stiffness f' and
!> stiffness slope f''; the strain energy per unstretched length W(eps) =
!> integral of f from 0 to eps is used by the energy ledger. Concrete laws:
!> `tanh_law` (the nylon double-braid fit of Tjavaras et al. 1998) and
!> `linear_law` (T = EA eps, for closed-form checks).
module xcable_material_law
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_material_elementary, only: law_tanh, law_atanh, law_tanh_sech2
   use, intrinsic :: iso_c_binding, only: c_double
   implicit none
   private
   public :: material_law, tanh_law, linear_law, tanh_law_of, strain_kept
   public :: paper_tanh_coefficients, secant_stiffness

   !> Coefficients p1..p5 of eq. 17 for the paper's nylon line (N, -, -, N, N).
   real(dp), parameter :: paper_tanh_coefficients(5) = &
      [2.703e5_dp, 10.2_dp, -2.128_dp, 2.627e5_dp, 135.5_dp]

   !> Values of a law that every inversion by strain_at asks for, kept from one
   !> inversion to the next (for one law only): its tension at the points where
   !> strain_at starts (the bracket -0.1, 0.1 and the steps that widen it, the first
   !> Newton point) and its stiffness at the first Newton point. Inverting many
   !> tensions (the statics' first guess) then takes 9 of 14 evaluations.
   type :: strain_kept
      !> Values kept.
      integer :: n = 0
      !> Whether value(i) is a stiffness (else a tension), its strain, and the value.
      logical :: is_stiffness(24) = .false.
      real(dp) :: at(24) = 0, value(24) = 0
   end type strain_kept

   !> A tension-strain law.
   type, abstract :: material_law
      !> Largest strain for which the law is documented (static states above it are refused).
      real(dp) :: strain_max = 0.35_dp
      !> Smallest strain for which the law is given (a table's first row); a run that
      !> compresses cells below it is warned.
      real(dp) :: strain_min = -huge(1.0_dp)
      !> Strain at and below which the law carries no tension: the kink of a rope that cannot
      !> push (material/tension_only.f90); -huge for a law continued into compression.
      real(dp) :: strain_slack = -huge(1.0_dp)
   contains
      !> Tension f(eps), N.
      procedure(law_function), deferred :: tension
      !> Axial stiffness f'(eps), N.
      procedure(law_function), deferred :: stiffness
      !> Slope of the stiffness f''(eps), N.
      procedure(law_function), deferred :: stiffness_slope
      !> Strain energy per unstretched length, J/m.
      procedure(law_function), deferred :: strain_energy
      !> Short name of the law.
      procedure(law_name), deferred :: name
      !> Strain at a given tension (inverse of f).
      procedure :: strain_at
      !> Tension and stiffness together (one evaluation where the law allows).
      procedure :: tension_stiffness
      !> Tension, stiffness and its slope together (one evaluation where the law allows).
      procedure :: tension_stiffness_slope
      !> Change of the strain energy between two strains, W(eps1) - W(eps0), J/m.
      procedure :: strain_energy_change
      !> W(eps1) - W(eps0) and the tension f(eps1) together (one evaluation where the law allows).
      procedure :: strain_energy_change_tension
   end type material_law

   interface
      !> expm1 and log1p of the C library (C99), not in Fortran.
      pure real(c_double) function c_expm1(x) bind(c, name='expm1')
         import :: c_double
         real(c_double), value :: x
      end function c_expm1
      pure real(c_double) function c_log1p(x) bind(c, name='log1p')
         import :: c_double
         real(c_double), value :: x
      end function c_log1p
   end interface

   abstract interface
      !> A scalar function of the strain.
      elemental function law_function(self, eps) result(val)
         import :: material_law, dp
         !> The law.
         class(material_law), intent(in) :: self
         !> Strain.
         real(dp), intent(in) :: eps
         real(dp) :: val
      end function law_function
      !> Name of a law.
      pure function law_name(self) result(name)
         import :: material_law
         !> The law.
         class(material_law), intent(in) :: self
         character(:), allocatable :: name
      end function law_name
   end interface

   !> T = p1 tanh(p2 eps + p3) + p4 + p5 eps (eq. 17).
   type, extends(material_law) :: tanh_law
      !> Coefficients p1..p5.
      real(dp) :: p(5) = paper_tanh_coefficients
      !> p3, log cosh p3 (the strain energy's constant term), 1 / (1 + exp(-2 p3)) and
      !> 1 / (1 + exp(2 p3)) (tanh_energy_small's), as new_law sets them; used while p(3) is
      !> lc3(1). It saves an exp and a log per strain energy (3 % of fast_180kN).
      real(dp) :: lc3(4) = [huge(1.0_dp), 0.0_dp, 0.0_dp, 0.0_dp]
   contains
      procedure :: tension => tanh_tension
      procedure :: stiffness => tanh_stiffness
      procedure :: stiffness_slope => tanh_stiffness_slope
      procedure :: strain_energy => tanh_strain_energy
      procedure :: name => tanh_name
      procedure :: tension_stiffness => tanh_tension_stiffness
      procedure :: tension_stiffness_slope => tanh_tension_stiffness_slope
      procedure :: strain_energy_change => tanh_strain_energy_change
      procedure :: strain_energy_change_tension => tanh_strain_energy_change_tension
   end type tanh_law

   !> T = EA eps.
   type, extends(material_law) :: linear_law
      !> Axial stiffness EA, N.
      real(dp) :: ea = 1.0_dp
   contains
      procedure :: tension => linear_tension
      procedure :: stiffness => linear_stiffness
      procedure :: stiffness_slope => linear_stiffness_slope
      procedure :: strain_energy => linear_strain_energy
      procedure :: name => linear_name
   end type linear_law

contains

   !> The law's secant stiffness over the first 0.1 % of strain, (f(1e-3) - f(0)) / 1e-3, N: a
   !> scale of its axial stiffness near zero strain for any law (a table's, a cut one's).
   real(dp) function secant_stiffness(law)
      class(material_law), intent(in) :: law
      secant_stiffness = (law%tension(1.0e-3_dp) - law%tension(0.0_dp))/1.0e-3_dp
   end function secant_stiffness

   !> W(eps1) - W(eps0), J/m (a law whose energy cancels at small strain steps overrides it).
   elemental function strain_energy_change(self, eps0, eps1) result(val)
      class(material_law), intent(in) :: self
      real(dp), intent(in) :: eps0, eps1
      real(dp) :: val
      val = self%strain_energy(eps1) - self%strain_energy(eps0)
   end function strain_energy_change

   !> W(eps1) - W(eps0), J/m, and f(eps1), N, of any law (two calls).
   pure subroutine strain_energy_change_tension(self, eps0, eps1, dw, f1)
      !> The law.
      class(material_law), intent(in) :: self
      !> Old and new strain (by value, as the tanh law's: see tanh_strain_energy_change_tension).
      real(dp), intent(in), value :: eps0, eps1
      !> W(eps1) - W(eps0), J/m, and f(eps1), N.
      real(dp), intent(out) :: dw, f1
      dw = self%strain_energy_change(eps0, eps1)
      f1 = self%tension(eps1)
   end subroutine strain_energy_change_tension

   !> The tanh law of coefficients p (eq. 17), with the constants of its strain energy kept.
   function tanh_law_of(p, strain_max) result(law)
      !> Coefficients p1..p5.
      real(dp), intent(in) :: p(5)
      !> Largest documented strain.
      real(dp), intent(in) :: strain_max
      type(tanh_law) :: law
      law = tanh_law(p=p, strain_max=strain_max, lc3=[p(3), log_cosh(p(3)), 1/(1 + exp(-2*p(3))), 1/(1 + exp(2*p(3)))])
   end function tanh_law_of

   !> Strain at which the law gives the tension t (f is strictly increasing).
   !> Safeguarded Newton inside an expanding bracket. With kept, the values at the
   !> starting points come from earlier calls (the same bits: the same law, the same
   !> strains).
   function strain_at(self, t, kept) result(eps)
      !> The law.
      class(material_law), intent(in) :: self
      !> Tension, N.
      real(dp), intent(in) :: t
      !> Values kept across calls for this law.
      type(strain_kept), intent(inout), optional :: kept
      real(dp) :: eps
      real(dp) :: lo, hi, step, f, df
      integer :: it
      lo = -0.1_dp
      hi = 0.1_dp
      step = 0.2_dp
      do it = 1, 200
         if (value_at(lo, .false.) <= t) exit
         lo = lo - step
         step = 2*step
      end do
      step = 0.2_dp
      do it = 1, 200
         if (value_at(hi, .false.) >= t) exit
         hi = hi + step
         step = 2*step
      end do
      eps = 0.5_dp*(lo + hi)
      do it = 1, 200
         if (it == 1) then
            f = value_at(eps, .false.) - t
         else
            f = self%tension(eps) - t
         end if
         if (abs(f) <= 1.0e-13_dp*max(1.0_dp, abs(t))) exit
         if (f > 0) then
            hi = eps
         else
            lo = eps
         end if
         if (hi - lo <= 4*epsilon(1.0_dp)*max(1.0_dp, abs(eps))) exit
         if (it == 1) then
            df = value_at(eps, .true.)
         else
            df = self%stiffness(eps)
         end if
         ! A flat stretch of the law (a rope without compression below its slack strain): bisect.
         if (df > 0) then
            eps = eps - f/df
         else
            eps = 0.5_dp*(lo + hi)
         end if
         if (.not. (eps > lo .and. eps < hi)) eps = 0.5_dp*(lo + hi)
      end do

   contains

      !> The law's tension (or stiffness) at strain x, from kept when it holds it
      !> (strains compared bit for bit), else computed (and kept).
      real(dp) function value_at(x, stiffness) result(value)
         real(dp), intent(in) :: x
         logical, intent(in) :: stiffness
         integer :: i
         if (present(kept)) then
            do i = 1, kept%n
               if (kept%is_stiffness(i) .eqv. stiffness) then
                  if (transfer(kept%at(i), 0_i8) == transfer(x, 0_i8)) then
                     value = kept%value(i)
                     return
                  end if
               end if
            end do
         end if
         if (stiffness) then
            value = self%stiffness(x)
         else
            value = self%tension(x)
         end if
         if (.not. present(kept)) return
         if (kept%n == size(kept%at)) return
         kept%n = kept%n + 1
         kept%is_stiffness(kept%n) = stiffness
         kept%at(kept%n) = x
         kept%value(kept%n) = value
      end function value_at
   end function strain_at

   !> Tension f(eps) and stiffness f'(eps) of any law (two calls).
   pure subroutine tension_stiffness(self, eps, f, fp)
      !> The law.
      class(material_law), intent(in) :: self
      !> Strain.
      real(dp), intent(in) :: eps
      !> Tension, N.
      real(dp), intent(out) :: f
      !> Stiffness, N.
      real(dp), intent(out) :: fp
      f = self%tension(eps)
      fp = self%stiffness(eps)
   end subroutine tension_stiffness

   !> Tension f(eps), stiffness f'(eps) and its slope f''(eps) of any law (three calls).
   pure subroutine tension_stiffness_slope(self, eps, f, fp, fpp)
      !> The law.
      class(material_law), intent(in) :: self
      !> Strain (by value, as the tanh law's: see tanh_strain_energy_change_tension).
      real(dp), intent(in), value :: eps
      !> Tension, stiffness and slope of the stiffness, N.
      real(dp), intent(out) :: f, fp, fpp
      f = self%tension(eps)
      fp = self%stiffness(eps)
      fpp = self%stiffness_slope(eps)
   end subroutine tension_stiffness_slope

   !> tanh_tension, tanh_stiffness and tanh_stiffness_slope from one tanh and 1 / cosh^2 of
   !> x = p2 eps + p3 (law_tanh_sech2: one exp where |x| >= 0.55).
   pure subroutine tanh_tension_stiffness_slope(self, eps, f, fp, fpp)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in), value :: eps
      real(dp), intent(out) :: f, fp, fpp
      real(dp) :: t, s2
      call law_tanh_sech2(self%p(2)*eps + self%p(3), t, s2)
      f = self%p(1)*t + self%p(4) + self%p(5)*eps
      fp = self%p(1)*self%p(2)*s2 + self%p(5)
      fpp = -2*self%p(1)*self%p(2)**2*t*s2
   end subroutine tanh_tension_stiffness_slope

   !> Tension and stiffness of the tanh law from one exponential q = exp(2 x):
   !> tanh x = 1 - 2 d and 1 / cosh^2 x = 4 q d^2 with d = 1 / (1 + q). Near
   !> x = 0 this tanh has an absolute (not relative) error of a few 1e-16, that
   !> is 1e-10 N of tension; it costs half of tanh and cosh from the library,
   !> and the Newton iterations call it once per node and residual.
   pure subroutine tanh_tension_stiffness(self, eps, f, fp)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp), intent(out) :: f, fp
      real(dp) :: q, d
      q = exp(min(2*(self%p(2)*eps + self%p(3)), 700.0_dp))
      d = 1/(1 + q)
      f = self%p(1)*(1 - 2*d) + self%p(4) + self%p(5)*eps
      fp = 4*self%p(1)*self%p(2)*q*d*d + self%p(5)
   end subroutine tanh_tension_stiffness

   elemental function tanh_tension(self, eps) result(val)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = self%p(1)*tanh(self%p(2)*eps + self%p(3)) + self%p(4) + self%p(5)*eps
   end function tanh_tension

   elemental function tanh_stiffness(self, eps) result(val)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = self%p(1)*self%p(2)/cosh(self%p(2)*eps + self%p(3))**2 + self%p(5)
   end function tanh_stiffness

   elemental function tanh_stiffness_slope(self, eps) result(val)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, x
      x = self%p(2)*eps + self%p(3)
      val = -2*self%p(1)*self%p(2)**2*tanh(x)/cosh(x)**2
   end function tanh_stiffness_slope

   !> W(eps1) - W(eps0) of the tanh law without the cancellation of the two energies: W holds
   !> (p1 / p2) log cosh(p2 eps + p3), about 4e4 J/m for the paper's law, beside p4 eps of
   !> nearly the same size, so W computed so carries an absolute round-off of up to 1e-11 J/m
   !> and the rods' divided difference (W1 - W0) / (eps1 - eps0) an error of that over the
   !> strain step, up to 1e-5 N at the smallest steps it is taken at (1e-6; below, the rods
   !> take a Taylor form), docs/theory/model3d.md (Water in motion). With x = p2 eps + p3, log cosh x1 - log cosh x0 =
   !> 2 atanh(tanh(x_mid) tanh(dx / 2)), which keeps the relative accuracy of the change, so
   !> the error is that of the tension itself (a few 1e-11 N). For p2 |eps1 - eps0| >= 1,
   !> where nothing cancels, the difference of the two energies.
   elemental function tanh_strain_energy_change(self, eps0, eps1) result(val)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in) :: eps0, eps1
      real(dp) :: val, tm, td
      if (abs(self%p(2)*(eps1 - eps0)) < 1) then
         call tanh_change(self%p, eps0, eps1, val, tm, td)
      else
         val = tanh_strain_energy(self, eps1) - tanh_strain_energy(self, eps0)
      end if
   end function tanh_strain_energy_change

   !> The tanh law's W(eps1) - W(eps0) and f(eps1) together: f(eps1) takes tanh x1 from the
   !> change's two tanh, tanh(x_mid + d) = (tanh x_mid + tanh d) / (1 + tanh x_mid tanh d)
   !> with d = p2 (eps1 - eps0) / 2, instead of a third tanh (a few units in the last place
   !> of tanh x1; the rods use f(eps1) only in their Jacobian).
   pure subroutine tanh_strain_energy_change_tension(self, eps0, eps1, dw, f1)
      class(tanh_law), intent(in) :: self
      ! The strains by value, in registers: the caller (cell_terms, once a cell) need not store
      ! them (with tension_stiffness_slope's eps: 0.6293e9 -> 0.6280e9 instructions on
      ! fast_180kN, callgrind).
      real(dp), intent(in), value :: eps0, eps1
      real(dp), intent(out) :: dw, f1
      real(dp) :: tm, td
      if (abs(self%p(2)*(eps1 - eps0)) < 1) then
         call tanh_change(self%p, eps0, eps1, dw, tm, td)
         f1 = self%p(1)*((tm + td)/(1 + tm*td)) + self%p(4) + self%p(5)*eps1
      else
         dw = tanh_strain_energy(self, eps1) - tanh_strain_energy(self, eps0)
         f1 = tanh_tension(self, eps1)
      end if
   end subroutine tanh_strain_energy_change_tension

   !> The tanh law's W(eps1) - W(eps0) from 2 atanh(tanh(x_mid) tanh(dx / 2)) (p2 |eps1 - eps0| < 1),
   !> and the two tanh, of x_mid and of dx / 2 (law_tanh, law_atanh: xcable_material_elementary).
   pure subroutine tanh_change(p, eps0, eps1, val, tm, td)
      real(dp), intent(in) :: p(5), eps0, eps1
      real(dp), intent(out) :: val, tm, td
      real(dp) :: h, mid
      h = eps1 - eps0
      mid = 0.5_dp*(eps0 + eps1)
      tm = law_tanh(p(2)*mid + p(3))
      td = law_tanh(0.5_dp*p(2)*h)
      val = 2*p(1)/p(2)*law_atanh(tm*td) + (p(4) + p(5)*mid)*h
   end subroutine tanh_change

   !> W(eps); for p2 |eps| < 1 tanh_energy_small, free of the cancellation between the
   !> log cosh and p4 eps terms (the energies of a slack line to the relative round-off
   !> instead of 1e-12 J/m).
   elemental function tanh_strain_energy(self, eps) result(val)
      class(tanh_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, c3, c(2)
      if (abs(self%p(2)*eps) < 1) then
         if (self%lc3(1) == self%p(3)) then
            c = self%lc3(3:4)
         else
            c = [1/(1 + exp(-2*self%p(3))), 1/(1 + exp(2*self%p(3)))]
         end if
         val = tanh_energy_small(self%p, eps, c)
         return
      end if
      if (self%lc3(1) == self%p(3)) then
         c3 = self%lc3(2)
      else
         c3 = log_cosh(self%p(3))
      end if
      val = self%p(1)/self%p(2)*(log_cosh(self%p(2)*eps + self%p(3)) - c3) &
            + self%p(4)*eps + 0.5_dp*self%p(5)*eps**2
   end function tanh_strain_energy

   !> W(eps) of the tanh law for p2 |eps| < 1, with d = p2 eps and x = p3 + d:
   !>     log cosh x - log cosh p3 = -d + log1p(c1 expm1(2 d)),  c1 = 1 / (1 + exp(-2 p3))  (x <= 0)
   !>                              = +d + log1p(c2 expm1(-2 d)), c2 = 1 / (1 + exp(2 p3))   (x > 0)
   !> (exp(2 x) or exp(-2 x) at most 1 inside), so W = (p4 -+ p1) eps + p5 eps^2 / 2 +
   !> (p1 / p2) log1p(...): one expm1 and one log1p from the library instead of tanh_change's
   !> two tanh and an atanh, and a milder cancellation at small strains (p4 - p1 against
   !> W's slope f(0), about 180 for the paper's law, against p4 and p1 tanh p3 there, 6 000).
   pure function tanh_energy_small(p, eps, c) result(val)
      !> Coefficients p1..p5.
      real(dp), intent(in) :: p(5)
      !> Strain (p2 |eps| < 1).
      real(dp), intent(in) :: eps
      !> c1 and c2.
      real(dp), intent(in) :: c(2)
      real(dp) :: val, d
      d = p(2)*eps
      if (d + p(3) <= 0) then
         val = (p(4) - p(1))*eps + p(1)/p(2)*c_log1p(c(1)*c_expm1(2*d)) + 0.5_dp*p(5)*eps**2
      else
         val = (p(4) + p(1))*eps + p(1)/p(2)*c_log1p(c(2)*c_expm1(-2*d)) + 0.5_dp*p(5)*eps**2
      end if
   end function tanh_energy_small

   !> log(cosh(x)) without overflow.
   elemental function log_cosh(x) result(val)
      real(dp), intent(in) :: x
      real(dp) :: val
      val = abs(x) + log1p_exp(-2*abs(x)) - log(2.0_dp)
   end function log_cosh

   !> log(1 + exp(y)) for y <= 0.
   elemental function log1p_exp(y) result(val)
      real(dp), intent(in) :: y
      real(dp) :: val, e
      e = exp(y)
      if (e < 1.0e-8_dp) then
         val = e - 0.5_dp*e*e
      else
         val = log(1.0_dp + e)
      end if
   end function log1p_exp

   pure function tanh_name(self) result(name)
      class(tanh_law), intent(in) :: self
      character(:), allocatable :: name
      name = 'tanh'
   end function tanh_name

   elemental function linear_tension(self, eps) result(val)
      class(linear_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = self%ea*eps
   end function linear_tension

   elemental function linear_stiffness(self, eps) result(val)
      class(linear_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = self%ea + 0*eps
   end function linear_stiffness

   elemental function linear_stiffness_slope(self, eps) result(val)
      class(linear_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = 0*self%ea*eps
   end function linear_stiffness_slope

   elemental function linear_strain_energy(self, eps) result(val)
      class(linear_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = 0.5_dp*self%ea*eps**2
   end function linear_strain_energy

   pure function linear_name(self) result(name)
      class(linear_law), intent(in) :: self
      character(:), allocatable :: name
      name = 'linear'
   end function linear_name
end module xcable_material_law
