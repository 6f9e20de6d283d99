!> tanh and atanh for the tanh law's step terms (the rods' divided difference of the
!> strain energy, evaluated once per cell and Newton iteration).
!>
!> The library's tanh computes expm1 for every argument, about 100 instructions a call;
!> atanh goes through log1p. The arguments the rods give are of two kinds: p2 eps + p3,
!> mostly beyond 0.55 in size, and p2 (eps1 - eps0) / 2 and the product of two tanh, mostly
!> below 1/64. Here both take a shorter path with the same accuracy (within 2 units in the
!> last place of the correctly rounded value; test/suite_law.f90, elementary_against_quad),
!> and every other argument goes to the library:
!>
!> - |x| < 1/64: the Taylor series of tanh and atanh to the x^9 term. The first term left
!>   out is below 1.4e-20 of the value (tanh: 1382/155925 x^11; atanh: x^11 / 11), the
!>   correction to x below 1e-4 of it, so the sum rounds once at x.
!> - tanh, |x| >= 0.55: (1 - q) / (1 + q) with q = exp(-2 |x|) <= 1/3, so that 1 - q
!>   keeps the relative accuracy of q (its error enters as q / (1 - q) <= 1/2 of q's);
!>   1 / cosh^2 x = 4 q / (1 + q)^2, which keeps it too (1 - tanh^2 would lose digits
!>   where tanh is near 1).
module xcable_material_elementary
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: law_tanh, law_atanh, law_tanh_sech2

   !> Below this size the series (see the module header).
   real(dp), parameter :: series_limit = 1.0_dp/64
   !> From this size tanh from one exp (see the module header).
   real(dp), parameter :: exp_limit = 0.55_dp

contains

   !> tanh x (see the module header).
   elemental function law_tanh(x) result(t)
      ! x by value (in a register: the law kernels' callers need not store it; with law_atanh's
      ! and law_tanh_sech2's z and x: 0.6257e9 -> 0.6236e9 instructions on fast_180kN, callgrind).
      real(dp), intent(in), value :: x
      real(dp) :: t, a, z, q
      a = abs(x)
      if (a < series_limit) then
         z = x*x
         t = x + x*(z*(-1.0_dp/3 + z*(2.0_dp/15 + z*(-17.0_dp/315 + z*(62.0_dp/2835)))))
      else if (a >= exp_limit) then
         q = exp(-2*a)
         t = sign((1 - q)/(1 + q), x)
      else
         t = tanh(x)
      end if
   end function law_tanh

   !> tanh x and 1 / cosh^2 x (see the module header).
   elemental subroutine law_tanh_sech2(x, t, s2)
      real(dp), intent(in), value :: x
      real(dp), intent(out) :: t, s2
      real(dp) :: a, q, c
      a = abs(x)
      if (a < series_limit) then
         t = law_tanh(x)
         s2 = 1 - t*t
      else if (a >= exp_limit) then
         q = exp(-2*a)
         t = sign((1 - q)/(1 + q), x)
         s2 = 4*q/(1 + q)**2
      else
         t = tanh(x)
         c = cosh(x)
         s2 = 1/c**2
      end if
   end subroutine law_tanh_sech2

   !> atanh z (see the module header).
   elemental function law_atanh(z) result(t)
      real(dp), intent(in), value :: z
      real(dp) :: t, y
      if (abs(z) < series_limit) then
         y = z*z
         t = z + z*(y*(1.0_dp/3 + y*(1.0_dp/5 + y*(1.0_dp/7 + y*(1.0_dp/9)))))
      else
         t = atanh(z)
      end if
   end function law_atanh
end module xcable_material_elementary
