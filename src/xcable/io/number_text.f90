!> Real numbers as text in the Fortran edit descriptor ESw.d, the same
!> characters as gfortran's formatted write, about 8 times cheaper.
!>
!> Why: gfortran's formatted output costs about 5 000 instructions per
!> number (the format interpreter, then snprintf), and the gnuplot text of a
!> run (snapshots and history) writes tens of thousands of numbers: 9 % of
!> fast_180kN's instructions as shipped (docs/measurements/data/speed_rounds.md).
!>
!> How: |x| = m 2^e2 with m < 2^53 an integer. The d + 1 significant digits
!> are D = |x| 10^(d - E) rounded to the nearest integer, ties to even, with
!> E the decimal exponent; D is computed exactly in 128-bit integers
!> (m 5^k shifted by a power of two, or m 2^s divided by 5^k 2^t), so the
!> rounding is that of a correctly rounded conversion, which is what gfortran
!> does in its default rounding mode (through glibc's printf). E starts from
!> floor(log10 |x|) and is corrected by one when D falls outside
!> [10^d, 10^(d+1)). Before that, for d <= 12, fast_digits tries the same
!> in double arithmetic with a proven error bound (about 250 instead of 600
!> instructions a number) and hands over only when the bound cannot decide
!> the rounding. Numbers the exact path does not cover (not finite, exponents
!> beyond +-99, |x| 10^(d - E) outside the 128-bit range, more than 17
!> digits, a width too small) go through the formatted write itself, so the
!> text is always gfortran's. Tested against write on random numbers of
!> every magnitude, ties, powers of ten and their neighbours, and values
!> within ulps of the fast path's rounding boundaries.
module xcable_io_number_text
   use xcable_core_kinds, only: dp, i8
   implicit none
   private
   public :: put_es, put_int

   integer, parameter :: i16 = selected_int_kind(38)
   integer :: i
   !> Powers of five up to 5^54 (< 2^126).
   integer(i16), parameter :: pow5(0:54) = [(5_i16**i, i=0, 54)]
   !> Powers of ten up to 10^18.
   integer(i8), parameter :: pow10(0:18) = [(10_i8**i, i=0, 18)]
   !> The two-digit numbers 00 to 99, one after the other.
   character(len=200), parameter :: pairs = &
      '00010203040506070809101112131415161718192021222324252627282930313233343536373839'// &
      '40414243444546474849505152535455565758596061626364656667686970717273747576777879'// &
      '8081828384858687888990919293949596979899'
   !> The powers of ten a double holds exactly, 10^0 to 10^22 (5^22 < 2^53).
   real(dp), parameter :: exact10(0:22) = [1.0e0_dp, 1.0e1_dp, 1.0e2_dp, 1.0e3_dp, 1.0e4_dp, 1.0e5_dp, &
                                           1.0e6_dp, 1.0e7_dp, 1.0e8_dp, 1.0e9_dp, 1.0e10_dp, 1.0e11_dp, &
                                           1.0e12_dp, 1.0e13_dp, 1.0e14_dp, 1.0e15_dp, 1.0e16_dp, &
                                           1.0e17_dp, 1.0e18_dp, 1.0e19_dp, 1.0e20_dp, 1.0e21_dp, 1.0e22_dp]
   !> Most digits after the point the double fast path takes (fast_digits).
   integer, parameter :: fast_max_d = 12

contains

   !> Write x in the edit descriptor ESw.d into text(pos:pos + w - 1) and
   !> advance pos by w; text must be long enough.
   pure subroutine put_es(text, pos, x, w, d)
      !> Line being built.
      character(*), intent(inout) :: text
      !> First column to write; on return the column after the field.
      integer, intent(inout) :: pos
      !> Value.
      real(dp), intent(in) :: x
      !> Width and digits after the decimal point.
      integer, intent(in) :: w, d
      character(len=16) :: fmt
      integer(i8) :: sig, q
      integer :: e10, n, k, p, e, r
      logical :: ok, negative
      negative = sign(1.0_dp, x) < 0
      ! abs(x) <= huge: finite (false for NaN and infinities).
      ok = abs(x) <= huge(x) .and. d >= 1 .and. d <= 17
      e10 = 0
      sig = 0
      if (ok .and. x /= 0) call significant_digits(abs(x), d, sig, e10, ok)
      n = d + 6 + merge(1, 0, negative)
      ok = ok .and. abs(e10) <= 99 .and. n <= w
      if (.not. ok) then
         ! The formatted write itself.
         write (fmt, '(a,i0,a,i0,a)') '(es', w, '.', d, ')'
         write (text(pos:pos + w - 1), fmt) x
         pos = pos + w
         return
      end if
      ! [blanks] [-] D . DDDDDDDD E sign two digits, right-justified in w.
      p = pos + w - 1
      e = abs(e10)
      text(p:p) = achar(48 + mod(e, 10))
      text(p - 1:p - 1) = achar(48 + e/10)
      text(p - 2:p - 2) = merge('-', '+', e10 < 0)
      text(p - 3:p - 3) = 'E'
      p = p - 4
      ! Two digits a step (one division by 100 instead of two by 10).
      do k = 1, d/2
         q = sig/100
         r = int(sig - 100*q)
         text(p - 1:p) = pairs(2*r + 1:2*r + 2)
         sig = q
         p = p - 2
      end do
      if (mod(d, 2) == 1) then
         q = sig/10
         text(p:p) = achar(48 + int(sig - 10*q))
         sig = q
         p = p - 1
      end if
      text(p:p) = '.'
      text(p - 1:p - 1) = achar(48 + int(sig))
      p = p - 2
      if (negative) then
         text(p:p) = '-'
         p = p - 1
      end if
      do k = pos, p
         text(k:k) = ' '
      end do
      pos = pos + w
   end subroutine put_es

   !> Write n in the edit descriptor Iw into text(pos:pos + w - 1) and
   !> advance pos by w.
   pure subroutine put_int(text, pos, n, w)
      !> Line being built.
      character(*), intent(inout) :: text
      !> First column to write; on return the column after the field.
      integer, intent(inout) :: pos
      !> Value.
      integer, intent(in) :: n
      !> Width.
      integer, intent(in) :: w
      character(len=16) :: fmt
      integer :: p, m
      if (n < 0 .or. n >= 10**min(w, 9)) then
         write (fmt, '(a,i0,a)') '(i', w, ')'
         write (text(pos:pos + w - 1), fmt) n
      else
         m = n
         p = pos + w - 1
         do
            text(p:p) = achar(48 + mod(m, 10))
            m = m/10
            p = p - 1
            if (m == 0) exit
         end do
         if (p >= pos) text(pos:p) = ' '
      end if
      pos = pos + w
   end subroutine put_int

   !> The d + 1 significant digits of a > 0 (an integer in [10^d, 10^(d+1)))
   !> and its decimal exponent, correctly rounded (ties to even); ok false
   !> when out of the exact range.
   pure subroutine significant_digits(a, d, sig, e10, ok)
      real(dp), intent(in) :: a
      integer, intent(in) :: d
      integer(i8), intent(out) :: sig
      integer, intent(out) :: e10
      logical, intent(out) :: ok
      integer(i8) :: m, below
      integer :: e2, attempt
      if (d <= fast_max_d) then
         call fast_digits(a, d, sig, e10, ok)
         if (ok) return
      end if
      m = int(scale(fraction(a), digits(a)), i8)
      e2 = exponent(a) - digits(a)
      e10 = floor(log10(a))
      do attempt = 1, 3
         call scaled_round(m, e2, d - e10, sig, below, ok)
         if (.not. ok) return
         ! E is too large when a 10^(d - E) is below 10^d before rounding, too small when
         ! it is 10^(d + 1) or more after it.
         if (sig >= pow10(d + 1)) then
            e10 = e10 + 1
         else if (below < pow10(d)) then
            e10 = e10 - 1
         else
            return
         end if
      end do
      ok = .false.
   end subroutine significant_digits

   !> significant_digits in double arithmetic with a proven error bound, for
   !> d <= fast_max_d; ok false (nothing decided) when the bound cannot
   !> prove the rounding, and for exponents it does not cover.
   !>
   !> Derivation. a = 2^e2 (1 + f), a normal double, so e2 from its bits.
   !> E0 = floor(e2 log10 2): the product is never within 4e-4 of an
   !> integer for 0 < |e2| <= 1100 (the closest is 485 log10 2 = 146 - 4.5e-4),
   !> so the double product floors right, and 10^E0 <= 2^e2 <= a < 2^(e2+1)
   !> < 10^(E0+2): the decimal exponent E is E0 or E0 + 1. Y = a 10^(d - E0)
   !> is then >= 10^d. y, the double computed for Y, is a times (or divided
   !> by) one exact power of ten 10^j, j <= 22, or two of them (10^22 and
   !> 10^(j-22)) for 22 < j <= 44; with u = 2^-53 each correctly rounded
   !> product or quotient of normal doubles has relative error <= u, so
   !> |y - Y| <= Y (2u + u^2) <= y (2u + u^2)/(1 - u)^2 < 4u y = tol, and
   !> tol = y 2^-51 is computed exactly. The range of j keeps every
   !> intermediate normal (|E| < 60). When y >= 10^(d+1) + 1, Y > 10^(d+1)
   !> and E = E0 + 1: redo with it (then Y >= 10^d again). Otherwise
   !> Y < 10^(d+1) + 2 (tol < 1 since y < 2^50). Let f = y - floor(y), exact
   !> (y >= 10, so f is a multiple of ulp(y) >= 2^-49 below 1), and f - 1/2
   !> is exact too. When |f - 1/2| > tol no half-integer lies between y and
   !> Y (the other half-integers are more than 1/2 away from y), so
   !> D = nint(Y) = floor(y) + (1 if f > 1/2), with no tie. If D >= 10^(d+1),
   !> Y >= 10^(d+1) - 1/2: whether E is E0 (the rounding carries into a new
   !> digit) or E0 + 1 (Y/10 < 10^d + 0.2 rounds to 10^d), the text is
   !> 10^d with exponent E0 + 1. |f - 1/2| <= tol happens for about 8e-7 of
   !> random numbers at 10 digits; those take the exact path.
   pure subroutine fast_digits(a, d, sig, e10, ok)
      real(dp), intent(in) :: a
      integer, intent(in) :: d
      integer(i8), intent(out) :: sig
      integer, intent(out) :: e10
      logical, intent(out) :: ok
      real(dp), parameter :: log10_2 = 0.30102999566398120_dp
      real(dp) :: y, f
      integer :: e2, k, attempt
      ok = .false.
      sig = 0
      e2 = int(shiftr(transfer(a, 0_i8), 52)) - 1023
      e10 = floor(e2*log10_2)
      if (e2 < -1022) return
      do attempt = 1, 2
         k = d - e10
         if (k >= 0) then
            if (k <= 22) then
               y = a*exact10(k)
            else if (k <= 44) then
               y = (a*exact10(22))*exact10(k - 22)
            else
               return
            end if
         else
            if (k >= -22) then
               y = a/exact10(-k)
            else if (k >= -44) then
               y = (a/exact10(22))/exact10(-k - 22)
            else
               return
            end if
         end if
         if (y < exact10(d + 1) + 1) exit
         if (attempt == 2) return
         e10 = e10 + 1
      end do
      sig = int(y, i8)
      f = y - real(sig, dp)
      if (abs(f - 0.5_dp) <= y*2.0_dp**(-51)) return
      if (f > 0.5_dp) sig = sig + 1
      if (sig >= pow10(d + 1)) then
         sig = pow10(d)
         e10 = e10 + 1
      end if
      ok = .true.
   end subroutine fast_digits

   !> q = m 2^e2 10^k rounded to the nearest integer, ties to even, and
   !> below = its integer part, exactly; ok false when the numbers leave the
   !> 128-bit range or q >= 10^18.
   pure subroutine scaled_round(m, e2, k, q, below, ok)
      integer(i8), intent(in) :: m
      integer, intent(in) :: e2, k
      integer(i8), intent(out) :: q, below
      logical, intent(out) :: ok
      integer(i16) :: num, den, qq, r, half, fl
      integer :: sh
      ok = .false.
      q = 0
      below = 0
      sh = e2 + k
      if (k >= 0) then
         ! m 5^k 2^sh, with m 5^k < 2^53 5^31 < 2^126.
         if (k > 31) return
         num = int(m, i16)*pow5(k)
         if (sh >= 0) then
            if (sh > 60 .or. num >= shiftl(1_i16, 60)) return
            qq = shiftl(num, sh)
            fl = qq
         else
            if (-sh > 125) return
            qq = shiftr(num, -sh)
            fl = qq
            r = num - shiftl(qq, -sh)
            half = shiftl(1_i16, -sh - 1)
            if (r > half .or. (r == half .and. btest(qq, 0))) qq = qq + 1
         end if
      else
         ! m 2^sh / 5^-k.
         if (-k > 54) return
         if (sh >= 0) then
            if (sh > 72) return
            num = shiftl(int(m, i16), sh)
            den = pow5(-k)
         else
            if (-sh + 2.33_dp*(-k) > 124) return
            num = int(m, i16)
            den = shiftl(pow5(-k), -sh)
         end if
         qq = num/den
         fl = qq
         r = num - qq*den
         if (2*r > den .or. (2*r == den .and. btest(qq, 0))) qq = qq + 1
      end if
      if (qq >= int(pow10(18), i16)) return
      q = int(qq, i8)
      below = int(fl, i8)
      ok = .true.
   end subroutine scaled_round
end module xcable_io_number_text
