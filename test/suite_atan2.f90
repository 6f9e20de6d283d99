!> fast_atan2 (src/xcable/numerics/atan2.f90) against atan2 in quad precision
!> (libquadmath) rounded to double, taken as the correctly rounded value, on
!> 560 000 reproducible arguments in all eight octants: random angles and radii,
!> random bit patterns (every magnitude, subnormals), the rod's arguments (x near
!> 1, small y), quotients just above 2^-k (the worst place of the first branch)
!> and near the table's interval edges, pairs of tiny (subnormal) and of huge
!> arguments; and the special values one by one.
!> Measured here: 1 unit from the correctly rounded value at worst, 1.40 units
!> from the exact value in the first branch (t < 1/16), 0.555 in the table
!> branch (bench/atan2/accuracy.f90 on 2e7 arguments: 1, 1.469, 0.566); the
!> bounds are 1 unit, 1.5 (the first branch's bound, docs/measurements/data/speed_rounds.md) and 0.6.
!> Mutations seen to fail: the last coefficient of the first polynomial dropped
!> (739 units), c*big_lo left out of the table branch (123 units), the table
!> index one off (1.8e16 units), no scaling of huge arguments (NaN) or of tiny
!> ones (11 units), the sign of the result from y < 0 instead of the sign bit
!> of y (atan2(-0, 2) = +0).
module suite_atan2
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_numerics_atan2, only: fast_atan2, fast_atan2_array
   use, intrinsic :: iso_fortran_env, only: int64, real128
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan, ieee_is_nan
   implicit none
   private
   public :: collect_atan2

   integer, parameter :: qp = real128

   !> Worst distance seen, in units in the last place, by branch.
   type :: worst_type
      integer(int64) :: from_rounded = 0
      real(dp) :: first_branch = 0, table_branch = 0
      real(dp) :: y = 0, x = 0
   end type worst_type

contains

   subroutine collect_atan2(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('against_quad_precision', test_against_quad), &
               new_unittest('special_values', test_special_values), &
               new_unittest('array_same_bits', test_array_same_bits)]
   end subroutine collect_atan2

   !> 560 000 arguments, 80 000 in each of seven families, each in one of the eight octants.
   subroutine test_against_quad(error)
      type(error_type), allocatable, intent(out) :: error
      type(worst_type) :: worst
      integer(int64) :: state
      integer :: family, k
      real(dp) :: v(4), y, x, t
      integer :: kk
      state = 20261201_int64
      do family = 1, 7
         do k = 1, 80000
            v = [uniform(state), uniform(state), uniform(state), uniform(state)]
            select case (family)
            case (1) ! angle uniform, radius 2^-30..2^30
               y = 2.0_dp**(60*v(2) - 30)*sin((2*v(1) - 1)*acos(-1.0_dp))
               x = 2.0_dp**(60*v(2) - 30)*cos((2*v(1) - 1)*acos(-1.0_dp))
            case (2) ! random bits: every exponent, subnormals
               y = transfer(ior(shiftl(int(2047*v(1), int64), 52), int(v(2)*2.0_dp**52, int64)), y)
               x = transfer(ior(shiftl(int(2047*v(3), int64), 52), int(uniform(state)*2.0_dp**52, int64)), x)
            case (3) ! the rod: x near 1, |y| from 0.5 down to 0.5e-12
               x = 1 + (v(1) - 0.5_dp)*0.2_dp
               y = 0.5_dp*2.0_dp**(-40*v(2))
            case (4) ! t just above 2^-k, atan(t) just below
               kk = 1 + int(40*v(1))
               t = 2.0_dp**(-kk)*(1 + v(2)*4.0_dp**(-kk)/2.5_dp)
               x = 1 + v(3)
               y = t*x
            case (5) ! the table's interval edges, and 1
               t = 2.0_dp**(-4 + int(4*v(1)))*(1 + int(17*v(2))/16.0_dp)*(1 + (v(3) - 0.5_dp)*1e-12_dp)
               x = 1 + uniform(state)
               y = min(t, 1.0_dp)*x
            case (6) ! both tiny: exponent fields 0 (subnormal) to 40, the scaling below 2^-960
               y = transfer(ior(shiftl(int(41*v(1), int64), 52), int(v(2)*2.0_dp**52, int64)), y)
               x = transfer(ior(shiftl(int(41*v(3), int64), 52), int(uniform(state)*2.0_dp**52, int64)), x)
            case (7) ! both huge: exponent fields 2006 to 2046, the scaling above 2^960
               y = transfer(ior(shiftl(2006 + int(41*v(1), int64), 52), int(v(2)*2.0_dp**52, int64)), y)
               x = transfer(ior(shiftl(2006 + int(41*v(3), int64), 52), int(uniform(state)*2.0_dp**52, int64)), x)
            end select
            select case (int(8*v(4)))
            case (0)
               call compare(y, x, worst)
            case (1)
               call compare(-y, x, worst)
            case (2)
               call compare(y, -x, worst)
            case (3)
               call compare(-y, -x, worst)
            case (4)
               call compare(x, y, worst)
            case (5)
               call compare(-x, y, worst)
            case (6)
               call compare(x, -y, worst)
            case default
               call compare(-x, -y, worst)
            end select
         end do
      end do
      if (worst%from_rounded > 1 .or. worst%first_branch > 1.5_dp .or. worst%table_branch > 0.6_dp) then
         call fatal_error(error, 'fast_atan2: worst '//str(real(worst%from_rounded, dp))// &
                          ' units from the correctly rounded value (bound 1), '//str(worst%first_branch)// &
                          ' from the exact one for t < 1/16 (bound 1.5), '//str(worst%table_branch)// &
                          ' in the table branch (bound 0.6); at y = '//str(worst%y)//', x = '//str(worst%x))
      end if
   end subroutine test_against_quad

   !> fast_atan2_array against fast_atan2, every result by its bits (NaNs too), on 10^6
   !> reproducible arguments in eight families: the rod's (x near 1, small y), x negative,
   !> quotients within a few units of 1/16 on both sides (the packed loop's limit), random
   !> angles, random bit patterns of either sign (every magnitude, subnormals), magnitudes
   !> near the smallest and the largest, y/x near 2^-k, and every pair of 18 special values
   !> (signed zeros, infinities, NaNs of both signs, subnormals, huge). The arrays are cut
   !> into pieces of 1 to 100 arguments (blocks of 32 inside, odd lengths, the packed loop's
   !> tail). Mutations seen to fail: a signed comparison of t's bits instead of the unsigned
   !> one (x < 0 taken as the packed case), and the limit 1/8 instead of 1/16.
   subroutine test_array_same_bits(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: total = 1000000
      real(dp), allocatable :: y(:), x(:), got(:)
      real(dp) :: v(4), special(18), sg
      integer(int64) :: state
      integer :: k, first, last, differ, worst_k, kk
      allocate (y(total), x(total), got(total))
      special = [0.0_dp, -0.0_dp, 1.0_dp, -1.0_dp, ieee_value(1.0_dp, ieee_positive_inf), &
                 -ieee_value(1.0_dp, ieee_positive_inf), ieee_value(1.0_dp, ieee_quiet_nan), &
                 -ieee_value(1.0_dp, ieee_quiet_nan), huge(1.0_dp), -huge(1.0_dp), tiny(1.0_dp)/8, &
                 -tiny(1.0_dp)/8, 5e-324_dp, -5e-324_dp, 0.0625_dp, -0.0625_dp, tiny(1.0_dp), 3.0_dp]
      state = 20261202_int64
      do k = 1, total
         v = [uniform(state), uniform(state), uniform(state), uniform(state)]
         sg = merge(-1.0_dp, 1.0_dp, v(4) < 0.5_dp)
         select case (mod(k, 8))
         case (0) ! the rod
            y(k) = sg*0.5_dp*2.0_dp**(-40*v(2))
            x(k) = 1 + (v(1) - 0.5_dp)*0.2_dp
         case (1) ! x negative
            x(k) = -(1 + v(1))
            y(k) = sg*2.0_dp**(-50*v(2))
         case (2) ! t within a few units of 1/16, both sides
            x(k) = 1 + v(1)
            y(k) = sg*(0.0625_dp*x(k) + (int(9*v(2)) - 4)*spacing(0.0625_dp))
         case (3) ! random angles, radius 2^-30 .. 2^30
            y(k) = 2.0_dp**(60*v(2) - 30)*sin((2*v(1) - 1)*acos(-1.0_dp))
            x(k) = 2.0_dp**(60*v(2) - 30)*cos((2*v(1) - 1)*acos(-1.0_dp))
         case (4) ! random bit patterns, both signs
            y(k) = transfer(ior(shiftl(int(v(1)*2.0_dp**32, int64), 32), int(v(3)*2.0_dp**32, int64)), 1.0_dp)
            x(k) = transfer(ior(shiftl(int(v(2)*2.0_dp**32, int64), 32), int(v(4)*2.0_dp**32, int64)), 1.0_dp)
         case (5) ! near the smallest and the largest magnitudes
            kk = merge(0, 2006, v(3) < 0.5_dp)
            y(k) = sg*transfer(ior(shiftl(kk + int(41*v(1), int64), 52), int(v(2)*2.0_dp**52, int64)), 1.0_dp)
            x(k) = transfer(ior(shiftl(kk + int(41*v(2), int64), 52), int(v(1)*2.0_dp**52, int64)), 1.0_dp)
         case (6) ! y/x near 2^-k, x of either sign
            x(k) = merge(-1.0_dp, 1.0_dp, v(3) < 0.2_dp)*(1 + v(2))
            y(k) = sg*abs(x(k))*2.0_dp**(-1 - int(40*v(1)))*(1 + (v(2) - 0.5_dp)*1e-15_dp)
         case default ! special values, every pair
            y(k) = special(1 + mod(k/8, 18))
            x(k) = special(1 + mod(k/144, 18))
         end select
      end do
      first = 1
      do while (first <= total)
         last = min(total, first + int(100*uniform(state)))
         call fast_atan2_array(last - first + 1, y(first:last), x(first:last), got(first:last))
         first = last + 1
      end do
      differ = 0
      worst_k = 0
      do k = 1, total
         if (transfer(got(k), 0_int64) /= transfer(fast_atan2(y(k), x(k)), 0_int64)) then
            differ = differ + 1
            if (worst_k == 0) worst_k = k
         end if
      end do
      if (differ > 0) then
         call fatal_error(error, 'fast_atan2_array: '//str(differ)//' of '//str(total)// &
                          ' results differ from fast_atan2 in their bits, first at y = '//str(y(worst_k))// &
                          ', x = '//str(x(worst_k)))
      end if
   end subroutine test_array_same_bits

   !> One argument against the quad-precision value; the worst distances so far.
   subroutine compare(y, x, worst)
      real(dp), intent(in) :: y, x
      type(worst_type), intent(inout) :: worst
      real(qp) :: exact
      real(dp) :: rounded, got, units
      integer(int64) :: d
      exact = atan2(real(y, qp), real(x, qp))
      rounded = real(exact, dp)
      got = fast_atan2(y, x)
      d = abs(transfer(got, d) - transfer(rounded, d))
      if (sign(1.0_dp, got) /= sign(1.0_dp, rounded) .or. got /= got) d = huge(d)
      if (d > worst%from_rounded) then
         worst%from_rounded = d
         worst%y = y
         worst%x = x
      end if
      if (rounded == 0) return
      units = real(abs((real(got, qp) - exact)/real(spacing(rounded), qp)), dp)
      if (min(abs(y), abs(x)) < 0.0625_dp*max(abs(y), abs(x))) then
         worst%first_branch = max(worst%first_branch, units)
      else
         worst%table_branch = max(worst%table_branch, units)
      end if
      if (units > 1.5_dp) then
         worst%y = y
         worst%x = x
      end if
   end subroutine compare

   !> Uniform in [0, 1) from a 64-bit linear congruential generator (reproducible everywhere).
   real(dp) function uniform(state)
      integer(int64), intent(inout) :: state
      state = state*6364136223846793005_int64 + 1442695040888963407_int64
      uniform = real(shiftr(state, 11), dp)*2.0_dp**(-53)
   end function uniform

   !> Signed zeros, the axes, the diagonals, infinities, NaN, subnormal and huge arguments.
   subroutine test_special_values(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: z, inf, nan, pi, big, sub, three_quarters
      z = 0
      inf = ieee_value(1.0_dp, ieee_positive_inf)
      nan = ieee_value(1.0_dp, ieee_quiet_nan)
      pi = acos(-1.0_dp)
      three_quarters = real(3*acos(-1.0_qp)/4, dp)
      big = huge(1.0_dp)
      sub = tiny(1.0_dp)/8
      call check(error, ieee_is_nan(fast_atan2(nan, 1.0_dp)) .and. ieee_is_nan(fast_atan2(1.0_dp, nan)) &
                 .and. ieee_is_nan(fast_atan2(nan, nan)), 'a NaN argument gives NaN')
      if (allocated(error)) return
      call expect(z, z, z, 'atan2(+0, +0)')
      call expect(-z, z, -z, 'atan2(-0, +0)')
      call expect(z, -z, pi, 'atan2(+0, -0)')
      call expect(-z, -z, -pi, 'atan2(-0, -0)')
      call expect(z, 2.0_dp, z, 'atan2(+0, 2)')
      call expect(-z, 2.0_dp, -z, 'atan2(-0, 2)')
      call expect(z, -2.0_dp, pi, 'atan2(+0, -2)')
      call expect(-z, -2.0_dp, -pi, 'atan2(-0, -2)')
      call expect(3.0_dp, z, pi/2, 'atan2(3, +0)')
      call expect(3.0_dp, -z, pi/2, 'atan2(3, -0)')
      call expect(-3.0_dp, z, -pi/2, 'atan2(-3, +0)')
      call expect(-3.0_dp, -z, -pi/2, 'atan2(-3, -0)')
      call expect(5.0_dp, 5.0_dp, pi/4, 'atan2(5, 5)')
      call expect(-5.0_dp, -5.0_dp, -three_quarters, 'atan2(-5, -5)')
      call expect(big, big, pi/4, 'atan2(huge, huge)')
      call expect(-big, big, -pi/4, 'atan2(-huge, huge)')
      call expect(big, -big, three_quarters, 'atan2(huge, -huge)')
      call expect(sub, sub, pi/4, 'atan2(subnormal, subnormal)')
      call expect(sub, -big, pi, 'atan2(subnormal, -huge)')
      call expect(-big, sub, -pi/2, 'atan2(-huge, subnormal)')
      call expect(inf, 1.0_dp, pi/2, 'atan2(inf, 1)')
      call expect(1.0_dp, inf, z, 'atan2(1, inf)')
      call expect(-1.0_dp, -inf, -pi, 'atan2(-1, -inf)')
      call expect(inf, inf, pi/4, 'atan2(inf, inf)')
      call expect(-inf, -inf, -three_quarters, 'atan2(-inf, -inf)')
      ! huge and tiny quotients: atan2(y, x) = y/x rounded, pi - (y/x), pi/2
      call expect(1e-300_dp, 1e300_dp, 1e-300_dp/1e300_dp, 'atan2(1e-300, 1e300)')
      call expect(1e-300_dp, -1e300_dp, pi, 'atan2(1e-300, -1e300)')
      call expect(5e-324_dp, 1.0_dp, 5e-324_dp, 'atan2(min subnormal, 1)')
      call expect(1e300_dp, 1e-300_dp, pi/2, 'atan2(1e300, 1e-300)')
   contains
      subroutine expect(y, x, value, what)
         real(dp), intent(in) :: y, x, value
         character(*), intent(in) :: what
         real(dp) :: got
         if (allocated(error)) return
         got = fast_atan2(y, x)
         ! equal bits: the sign of a zero matters; pi, pi/2, pi/4, 3pi/4 as the doubles nearest
         if (transfer(got, 0_int64) /= transfer(value, 0_int64)) then
            call fatal_error(error, what//' = '//str(got)//', expected '//str(value))
         end if
      end subroutine expect
   end subroutine test_special_values

end module suite_atan2
