!> Accuracy of fast_atan2 (src/xcable/numerics/atan2.f90) and of the intrinsic (glibc)
!> against atan2 in quad precision (libquadmath) rounded to double, which is taken as
!> the correctly rounded value. Build and run (docs/measurements/data/speed_rounds.md, "An own atan2"):
!>
!>     gfortran -O3 -funroll-loops src/xcable/core/kinds.f90 src/xcable/numerics/atan2.f90 \
!>        bench/atan2/accuracy.f90 -o /tmp/atan2_accuracy && /tmp/atan2_accuracy [millions]
program atan2_accuracy
   use xcable_core_kinds, only: dp
   use xcable_numerics_atan2, only: fast_atan2
   use, intrinsic :: iso_fortran_env, only: int64, real128
   implicit none
   integer, parameter :: qp = real128
   integer :: family, millions
   integer(int64) :: n, k
   character(len=32) :: arg
   real(dp) :: y, x, v(4)
   character(len=*), parameter :: names(6) = [character(len=40) :: &
      'angle uniform, radius 2^-30..2^30', 'random bits (all magnitudes)', &
      'rod-like: x ~ 1, |y| <= 0.5 log-uniform', 't near 2^-k (k = 1..40)', &
      't near interval edges and 1', 'y = 0, x = 0, |y| = |x|, inf, subnormal']
   type :: tally_type
      integer(int64) :: count = 0, miss = 0, worst_bits = 0
      real(dp) :: worst_exact = 0
      real(dp) :: worst_y = 0, worst_x = 0
   end type
   type(tally_type) :: mine, libm, first, second

   millions = 1
   if (command_argument_count() >= 1) then
      call get_command_argument(1, arg)
      read (arg, *) millions
   end if
   call random_seed()
   write (*, '(a)') 'family | n | fast: not CR, worst ulps from CR, worst ulps from exact | glibc: same'
   do family = 1, 6
      mine = tally_type()
      libm = tally_type()
      n = int(millions, int64)*1000000_int64
      if (family == 6) n = 1
      do k = 1, n
         if (family == 6) then
            call edge_cases()
            exit
         end if
         call random_number(v)
         select case (family)
         case (1)
            call uniform_angle(v, y, x)
         case (2)
            y = random_bits(v(1), v(2))
            x = random_bits(v(3), v(4))
         case (3)
            x = 1 + (v(1) - 0.5_dp)*0.2_dp
            y = sign(0.5_dp*2.0_dp**(-40*v(2)), v(3) - 0.5_dp)
         case (4)
            call near_binade(v, y, x)
         case (5)
            call near_edge(v, y, x)
         end select
         call quadrants(y, x, v(4))
      end do
      write (*, '(a40, " | ", i9, " | ", i8, 1x, i2, 1x, f6.3, " | ", i8, 1x, i2, 1x, f6.3)') names(family), &
         mine%count, mine%miss, mine%worst_bits, mine%worst_exact, libm%miss, libm%worst_bits, libm%worst_exact
      write (*, '(a, 2(i9, i8, 1x, i2, 1x, f6.3, 3x))') '   by branch, t < 1/16 | table:', &
         first%count, first%miss, first%worst_bits, first%worst_exact, &
         second%count, second%miss, second%worst_bits, second%worst_exact
      first = tally_type()
      second = tally_type()
      if (mine%worst_bits > 1) write (*, '(a, 2es26.17)') '   fast worst at y, x =', mine%worst_y, mine%worst_x
   end do

contains

   subroutine quadrants(y, x, r)
      real(dp), intent(in) :: y, x, r
      ! each draw in one of the four quadrants and one of the two octants of it
      select case (int(8*r))
      case (0)
         call compare(y, x)
      case (1)
         call compare(-y, x)
      case (2)
         call compare(y, -x)
      case (3)
         call compare(-y, -x)
      case (4)
         call compare(x, y)
      case (5)
         call compare(-x, y)
      case (6)
         call compare(x, -y)
      case default
         call compare(-x, -y)
      end select
   end subroutine quadrants

   subroutine compare(y, x)
      real(dp), intent(in) :: y, x
      real(qp) :: exact
      real(dp) :: rounded
      exact = atan2(real(y, qp), real(x, qp))
      rounded = real(exact, dp)
      call tally(mine, fast_atan2(y, x), rounded, exact, y, x)
      call tally(libm, atan2(y, x), rounded, exact, y, x)
      ! by branch of fast_atan2: t < 1/16 (polynomial) or the table
      if (min(abs(y), abs(x)) < 0.0625_dp*max(abs(y), abs(x))) then
         call tally(first, fast_atan2(y, x), rounded, exact, y, x)
      else
         call tally(second, fast_atan2(y, x), rounded, exact, y, x)
      end if
   end subroutine compare

   subroutine tally(t, got, rounded, exact, y, x)
      type(tally_type), intent(inout) :: t
      real(dp), intent(in) :: got, rounded, y, x
      real(qp), intent(in) :: exact
      integer(int64) :: d
      real(dp) :: e
      t%count = t%count + 1
      if (got /= rounded .or. (sign(1.0_dp, got) /= sign(1.0_dp, rounded))) then
         t%miss = t%miss + 1
         d = abs(transfer(got, d) - transfer(rounded, d))
         if (sign(1.0_dp, got) /= sign(1.0_dp, rounded) .or. got /= got) d = huge(d)
         if (d > t%worst_bits) then
            t%worst_bits = d
            t%worst_y = y
            t%worst_x = x
         end if
      end if
      if (rounded /= 0) then
         e = real(abs((real(got, qp) - exact)/real(spacing(rounded), qp)), dp)
         t%worst_exact = max(t%worst_exact, e)
      end if
   end subroutine tally

   subroutine uniform_angle(v, y, x)
      real(dp), intent(in) :: v(4)
      real(dp), intent(out) :: y, x
      real(dp) :: angle, radius
      angle = (2*v(1) - 1)*acos(-1.0_dp)
      radius = 2.0_dp**(60*v(2) - 30)
      y = radius*sin(angle)
      x = radius*cos(angle)
   end subroutine uniform_angle

   real(dp) function random_bits(r1, r2)
      real(dp), intent(in) :: r1, r2
      integer(int64) :: bits
      ! exponent field 0..2046 (subnormals and zero included), random mantissa
      bits = ior(shiftl(int(2047*r1, int64), 52), int(r2*2.0_dp**52, int64))
      random_bits = transfer(bits, random_bits)
   end function random_bits

   subroutine near_binade(v, y, x)
      real(dp), intent(in) :: v(4)
      real(dp), intent(out) :: y, x
      integer :: kk
      real(dp) :: t
      ! t just above 2^-k, where atan(t) is just below 2^-k (the width 2^-k 4^-k/3)
      kk = 1 + int(40*v(1))
      t = 2.0_dp**(-kk)*(1 + v(2)*4.0_dp**(-kk)/2.5_dp)
      x = 1 + v(3)
      y = t*x
   end subroutine near_binade

   subroutine near_edge(v, y, x)
      real(dp), intent(in) :: v(4)
      real(dp), intent(out) :: y, x
      integer :: e, m
      real(dp) :: t
      e = -4 + int(4*v(1))
      m = int(17*v(2))
      t = 2.0_dp**e*(1 + m/16.0_dp)*(1 + (v(3) - 0.5_dp)*1e-12_dp)
      if (m == 16 .and. e == -1) t = 1 - v(3)*1e-15_dp
      x = 1 + v(4)
      y = min(t, 1.0_dp)*x
   end subroutine near_edge

   subroutine edge_cases()
      real(dp) :: z, big, sub, inf
      integer :: i
      z = 0
      big = huge(1.0_dp)
      sub = tiny(1.0_dp)/8
      inf = ieee_inf()
      do i = 0, 1
         call all_signs(z, 1.0_dp)
         call all_signs(1.0_dp, z)
         call all_signs(z, z)
         call all_signs(1.0_dp, 1.0_dp)
         call all_signs(big, big)
         call all_signs(sub, sub)
         call all_signs(sub, big)
         call all_signs(big, sub)
         call all_signs(sub, 1.0_dp)
         call all_signs(tiny(1.0_dp), 0.999_dp*tiny(1.0_dp))
         call all_signs(big, 0.9_dp*big)
         call all_signs(0.95_dp*big, big)
         call all_signs(inf, 1.0_dp)
         call all_signs(1.0_dp, inf)
         call all_signs(inf, inf)
         call all_signs(inf, z)
         call all_signs(z, inf)
         call all_signs(0.0625_dp, 1.0_dp)
         call all_signs(nearest(0.0625_dp, -1.0_dp), 1.0_dp)
         call all_signs(nearest(1.0_dp, -1.0_dp), 1.0_dp)
         call all_signs(5e-324_dp, 1.0_dp)
         call all_signs(1e-300_dp, 1e300_dp)
      end do
      write (*, '(a)') 'edge cases: see the counts (each case in all sign combinations)'
   end subroutine edge_cases

   subroutine all_signs(y, x)
      real(dp), intent(in) :: y, x
      call compare(y, x)
      call compare(-y, x)
      call compare(y, -x)
      call compare(-y, -x)
      call compare(x, y)
      call compare(-x, y)
      call compare(x, -y)
      call compare(-x, -y)
   end subroutine all_signs

   real(dp) function ieee_inf()
      use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
      ieee_inf = ieee_value(1.0_dp, ieee_positive_inf)
   end function ieee_inf

end program atan2_accuracy
