!> fast_tan (src/xcable/numerics/tan.f90) against tan in quad precision
!> (libquadmath) and against the intrinsic (glibc) tan, on 480 000 reproducible
!> arguments of either sign: uniform in [0, pi/2], log-uniform from 2^-30 to
!> pi/2, the rods' (log-uniform in [1e-8, 0.1]), pi/2 minus up to 2^30 units,
!> near the branch limits 1/16 and pi/4, and random bit patterns below pi/2
!> (subnormals included); and special values one by one (signed zeros, tiny,
!> pi/2 rounded down, beyond pi/2 where the intrinsic takes over, infinities, NaN).
!> Measured here (units in the last place of the correctly rounded value, from the
!> exact one): 0.501 for |x| < 1/16, 0.638 for 1/16 <= |x| <= pi/4, 0.91 for
!> pi/4 < |x| <= pi/2; at most 1 unit from the intrinsic's. Bounds: 0.6, 0.8,
!> 1.0 and 2 (bench/tan/accuracy.f90 on 1.6e7 arguments: docs/measurements/data/speed_rounds.md "An own tan").
!> Mutations seen to fail: the last coefficient of the first polynomial dropped
!> (72 units), the table's low part tan_lo left out (1.22), T tan u left out of the
!> middle branch's denominator (1e12), the tail e of the reduction pi/2 - x left out
!> (1.59), 1 + T^2 taken as 1 (7e13). Not errors, and not caught: the table index
!> truncated instead of rounded (|u| up to 1/64, still within 0.8).
module suite_tan
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_numerics_tan, only: fast_tan, fast_tan_array
   use, intrinsic :: iso_fortran_env, only: int64, real128
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan, ieee_is_nan
   implicit none
   private
   public :: collect_tan

   integer, parameter :: qp = real128
   real(dp), parameter :: half_pi = 1.5707963267948966_dp

contains

   subroutine collect_tan(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('against_quad_precision', test_against_quad), &
               new_unittest('special_values', test_special_values), &
               new_unittest('array_same_bits', test_array_same_bits)]
   end subroutine collect_tan

   !> 480 000 arguments, 80 000 in each of six families.
   subroutine test_against_quad(error)
      type(error_type), allocatable, intent(out) :: error
      integer(int64) :: state, d, worst_intrinsic
      integer :: family, k, branch
      real(dp) :: v(3), x, got, rounded, units, worst(3), at(3), at_intrinsic
      real(qp) :: exact
      state = 20261202_int64
      worst = 0
      at = 0
      worst_intrinsic = 0
      at_intrinsic = 0
      do family = 1, 6
         do k = 1, 80000
            v = [uniform(state), uniform(state), uniform(state)]
            select case (family)
            case (1)
               x = half_pi*v(1)
            case (2)
               x = half_pi*2.0_dp**(-30*v(1))
            case (3)
               x = 1e-8_dp*(0.1_dp/1e-8_dp)**v(1)
            case (4)
               x = transfer(transfer(half_pi, 0_int64) - int(2.0_dp**(30*v(1)) - 1, int64), x)
            case (5)
               x = merge(0.0625_dp, 0.7853981633974483_dp, v(2) < 0.5_dp)*(1 + (v(1) - 0.5_dp)*2.0_dp**(-40))
            case default
               x = transfer(int(v(1)*real(transfer(half_pi, 0_int64), dp), int64), x)
            end select
            if (v(3) < 0.5_dp) x = -x
            exact = tan(real(x, qp))
            rounded = real(exact, dp)
            got = fast_tan(x)
            d = abs(transfer(got, d) - transfer(tan(x), d))
            if (sign(1.0_dp, got) /= sign(1.0_dp, tan(x)) .or. got /= got) d = huge(d)
            if (d > worst_intrinsic) then
               worst_intrinsic = d
               at_intrinsic = x
            end if
            if (rounded == 0) then
               units = merge(0.0_dp, huge(1.0_dp), got == 0)
            else
               units = real(abs((real(got, qp) - exact)/real(spacing(rounded), qp)), dp)
            end if
            branch = 3
            if (abs(x) <= 0.7853981633974483_dp) branch = 2
            if (abs(x) < 0.0625_dp) branch = 1
            if (units > worst(branch)) then
               worst(branch) = units
               at(branch) = x
            end if
         end do
      end do
      if (worst(1) > 0.6_dp .or. worst(2) > 0.8_dp .or. worst(3) > 1.0_dp .or. worst_intrinsic > 2) then
         call fatal_error(error, 'fast_tan: worst '//str(worst(1))//' units below 1/16 (bound 0.6, at '// &
                          str(at(1))//'), '//str(worst(2))//' up to pi/4 (bound 0.8, at '//str(at(2))// &
                          '), '//str(worst(3))//' up to pi/2 (bound 1, at '//str(at(3))//'); '// &
                          str(real(worst_intrinsic, dp))//' units from the intrinsic (bound 2, at '// &
                          str(at_intrinsic)//')')
      end if
   end subroutine test_against_quad

   !> fast_tan_array against fast_tan, every result by its bits (NaNs too), on 10^6
   !> reproducible arguments of either sign in five families: the rods' (log-uniform in
   !> [1e-8, 0.1]), within four units of 1/16 (the packed loop's limit), uniform in
   !> [-pi, pi] (beyond pi/2 the intrinsic), random bit patterns (every magnitude,
   !> subnormals, infinities, NaNs), and 12 special values; in pieces of 1 to 100 arguments
   !> whose fallback is rare (most pieces all below 1/16) or common. Mutations seen to fail:
   !> the packed loop's test without `not` (106 differ: pieces whose arguments are all
   !> beyond 1/16 skip the fallback), and its limit 1/8 instead of 1/16 (5001 differ).
   subroutine test_array_same_bits(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: total = 1000000
      real(dp), allocatable :: x(:), got(:)
      real(dp) :: v(3), special(12), sg
      integer(int64) :: state
      integer :: k, first, last, differ, first_k
      allocate (x(total), got(total))
      special = [0.0_dp, -0.0_dp, ieee_value(1.0_dp, ieee_positive_inf), -ieee_value(1.0_dp, ieee_positive_inf), &
                 ieee_value(1.0_dp, ieee_quiet_nan), -ieee_value(1.0_dp, ieee_quiet_nan), tiny(1.0_dp)/8, &
                 -5e-324_dp, 0.0625_dp, -0.0625_dp, half_pi, -huge(1.0_dp)]
      state = 20261202_int64
      do k = 1, total
         v = [uniform(state), uniform(state), uniform(state)]
         sg = merge(-1.0_dp, 1.0_dp, v(3) < 0.5_dp)
         ! pieces of 1000 arguments alternate: the rods' alone, then all families mixed
         if (mod(k/1000, 2) == 0) then
            x(k) = sg*10.0_dp**(-8 + 7*v(1))
            cycle
         end if
         select case (mod(k, 5))
         case (0) ! the rods'
            x(k) = sg*10.0_dp**(-8 + 7*v(1))
         case (1) ! within four units of 1/16
            x(k) = sg*(0.0625_dp + (int(9*v(1)) - 4)*spacing(0.0625_dp))
         case (2) ! uniform in [-pi, pi]
            x(k) = sg*v(1)*acos(-1.0_dp)
         case (3) ! random bit patterns
            x(k) = transfer(ior(shiftl(int(v(1)*2.0_dp**32, int64), 32), int(v(2)*2.0_dp**32, int64)), 1.0_dp)
         case default
            x(k) = special(1 + mod(k/5, 12))
         end select
      end do
      first = 1
      do while (first <= total)
         last = min(total, first + int(100*uniform(state)))
         call fast_tan_array(last - first + 1, x(first:last), got(first:last))
         first = last + 1
      end do
      differ = 0
      first_k = 0
      do k = 1, total
         if (transfer(got(k), 0_int64) /= transfer(fast_tan(x(k)), 0_int64)) then
            differ = differ + 1
            if (first_k == 0) first_k = k
         end if
      end do
      if (differ > 0) then
         call fatal_error(error, 'fast_tan_array: '//str(differ)//' of '//str(total)// &
                          ' results differ from fast_tan in their bits, first at x = '//str(x(first_k)))
      end if
   end subroutine test_array_same_bits

   !> Uniform in [0, 1) from a 64-bit linear congruential generator (reproducible everywhere).
   real(dp) function uniform(state)
      integer(int64), intent(inout) :: state
      state = state*6364136223846793005_int64 + 1442695040888963407_int64
      uniform = real(shiftr(state, 11), dp)*2.0_dp**(-53)
   end function uniform

   !> Signed zeros, tiny and subnormal arguments, pi/2 rounded down (the largest tan of the
   !> kernel), the arguments beyond it (the intrinsic's values), infinities and NaN.
   subroutine test_special_values(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: z, inf, nan, above, pole
      z = 0
      inf = ieee_value(1.0_dp, ieee_positive_inf)
      nan = ieee_value(1.0_dp, ieee_quiet_nan)
      above = nearest(half_pi, 2.0_dp)
      pole = real(tan(real(half_pi, qp)), dp) ! 1.633123935319537e16
      call check(error, ieee_is_nan(fast_tan(nan)) .and. ieee_is_nan(fast_tan(inf)) &
                 .and. ieee_is_nan(fast_tan(-inf)), 'tan of NaN and of +-inf is NaN')
      if (allocated(error)) return
      call expect(z, z, 'tan(+0)')
      call expect(-z, -z, 'tan(-0)')
      call expect(tiny(1.0_dp)/8, tiny(1.0_dp)/8, 'tan(subnormal)')
      call expect(-5e-324_dp, -5e-324_dp, 'tan(-smallest subnormal)')
      call expect(1e-200_dp, 1e-200_dp, 'tan(1e-200)')
      call expect(-1e-9_dp, -1e-9_dp, 'tan(-1e-9)')
      call expect(half_pi, pole, 'tan(pi/2 rounded down)')
      call expect(-half_pi, -pole, 'tan(-(pi/2 rounded down))')
      ! beyond the kernel: the intrinsic's value, bit for bit
      call expect(above, tan(above), 'tan(the double above pi/2)')
      call expect(-above, tan(-above), 'tan(-(the double above pi/2))')
      call expect(2.0_dp, tan(2.0_dp), 'tan(2)')
      call expect(-3.0_dp, tan(-3.0_dp), 'tan(-3)')
      call expect(1e300_dp, tan(1e300_dp), 'tan(1e300)')
      call check(error, fast_tan(above) < 0 .and. fast_tan(half_pi) > 0, 'the sign changes across pi/2')
   contains
      subroutine expect(x, value, what)
         real(dp), intent(in) :: x, value
         character(*), intent(in) :: what
         real(dp) :: got
         if (allocated(error)) return
         got = fast_tan(x)
         if (transfer(got, 0_int64) /= transfer(value, 0_int64)) then
            call fatal_error(error, what//' = '//str(got)//', expected '//str(value))
         end if
      end subroutine expect
   end subroutine test_special_values

end module suite_tan
