!> Small string helpers for messages.
module xcable_core_strings
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: str, to_lower, real_text, quantity

   !> Convert a number to a compact string.
   interface str
      module procedure str_real, str_int, str_logical
   end interface str

contains

   !> Real to string as people write it: six significant digits without trailing zeros, plain
   !> from 1e-3 to 1e6 ('0.229588', '315000', '1'), else with an exponent ('1.5e-7').
   pure function str_real(x) result(s)
      !> Value.
      real(dp), intent(in) :: x
      character(:), allocatable :: s
      s = significant(x, 6)
   end function str_real

   !> Integer to string.
   pure function str_int(i) result(s)
      !> Value.
      integer, intent(in) :: i
      character(:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function str_int

   !> Logical to string.
   pure function str_logical(l) result(s)
      !> Value.
      logical, intent(in) :: l
      character(:), allocatable :: s
      s = merge('.true. ', '.false.', l)
      s = trim(s)
   end function str_logical

   !> The shortest decimal text that reads back to exactly x: plain for
   !> 1e-4 <= |x| < 1e6 ('60', '0.05', '315000'), else with an exponent
   !> ('2.3e8', '1e-7'). For the namelist echo, the schema's defaults and
   !> messages that must show the value given.
   pure function real_text(x) result(s)
      !> Value.
      real(dp), intent(in) :: x
      character(:), allocatable :: s
      character(len=40) :: buf, best
      ! The formats of the probes, es40.(d - 1)e4 for d = 1 .. 17 significant digits (written
      ! out: an internal write of the format per probe was a quarter of the echo's cost).
      character(len=12), parameter :: fmts(17) = [character(len=12) :: '(es40.0e4)', '(es40.1e4)', &
         '(es40.2e4)', '(es40.3e4)', '(es40.4e4)', '(es40.5e4)', '(es40.6e4)', '(es40.7e4)', '(es40.8e4)', &
         '(es40.9e4)', '(es40.10e4)', '(es40.11e4)', '(es40.12e4)', '(es40.13e4)', '(es40.14e4)', &
         '(es40.15e4)', '(es40.16e4)']
      character(:), allocatable :: digits, sign
      real(dp) :: y
      integer :: d, ios, e_at, exponent, n, lo, hi
      logical :: special
      call special_text(x, s, special)
      if (special) return
      ! A whole number below 1e6 in magnitude is its integer text (what the probes below give it:
      ! the digits, no point; most values of a case's echo are such): no formatted I/O.
      if (abs(x) < 1.0e6_dp) then
         if (x == aint(x)) then
            s = str_int(nint(x))
            return
         end if
      end if
      ! The fewest significant digits that read back exactly: 17 always do, and
      ! if d digits do, d + 1 do too, so bisect.
      ! The text of the last probe that read back (hi's, when hi was probed) is kept.
      lo = 1
      hi = 17
      best = ''
      do while (lo < hi)
         d = (lo + hi)/2
         write (buf, fmts(d)) x
         read (buf, *, iostat=ios) y
         if (ios == 0 .and. y == x) then
            hi = d
            best = buf
         else
            lo = d + 1
         end if
      end do
      if (len_trim(best) > 0) then
         buf = best
      else
         write (buf, fmts(hi)) x
      end if
      buf = adjustl(buf)
      sign = ''
      if (buf(1:1) == '-') then
         sign = '-'
         buf = buf(2:)
      end if
      e_at = scan(buf, 'Ee')
      read (buf(e_at + 1:), *) exponent
      ! Mantissa digits without the point, trailing zeros dropped.
      digits = buf(1:1)//buf(3:e_at - 1)
      if (buf(2:2) /= '.') digits = buf(1:1)
      n = len(digits)
      do while (n > 1)
         if (digits(n:n) /= '0') exit
         n = n - 1
      end do
      digits = digits(1:n)
      if (exponent >= -4 .and. exponent < 6) then
         if (exponent < 0) then
            s = sign//'0.'//repeat('0', -exponent - 1)//digits
         else if (n <= exponent + 1) then
            s = sign//digits//repeat('0', exponent + 1 - n)
         else
            s = sign//digits(1:exponent + 1)//'.'//digits(exponent + 2:)
         end if
      else
         if (n == 1) then
            s = sign//digits
         else
            s = sign//digits(1:1)//'.'//digits(2:)
         end if
         s = s//'e'//str_int(exponent)
      end if
   end function real_text

   !> Lower-case copy of a string (ASCII).
   pure function to_lower(s) result(t)
      !> Input.
      character(*), intent(in) :: s
      character(len(s)) :: t
      integer :: i, c
      t = s
      do i = 1, len(s)
         c = iachar(s(i:i))
         if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
      end do
   end function to_lower

   !> A value with its unit as people write it: four significant digits without trailing
   !> zeros, and for forces, energies and powers (N, J, W) a prefix k, M or G above 1000
   !> ('315 kN', '1.234 MN'), for times below 1 s ms, below 0.1 ms us ('0.459 ms', '50 us');
   !> other units keep their value ('70.66 m', '111.7 m/s', '-0.0001234 m' as '-1.234e-4 m').
   pure function quantity(x, unit) result(s)
      !> Value, in the SI unit given.
      real(dp), intent(in) :: x
      !> Its unit ('N', 'kg', 'm/s', ...; '' for a plain number).
      character(*), intent(in) :: unit
      character(:), allocatable :: s
      character(len=*), parameter :: big(3) = ['k', 'M', 'G']
      character(:), allocatable :: prefix
      real(dp) :: v
      integer :: k
      v = x
      prefix = ''
      if (unit == 'N' .or. unit == 'J' .or. unit == 'W' .or. unit == 'N m') then
         do k = 1, 3
            if (abs(v) < 999.95_dp) exit
            v = v/1000
            prefix = big(k)
         end do
      else if (unit == 's' .and. abs(v) < 0.99995_dp .and. v /= 0) then
         v = v*1000
         prefix = 'm'
         if (abs(v) < 0.099995_dp) then
            v = v*1000
            prefix = 'u'
         end if
      end if
      s = significant(v, 4)
      if (len(unit) > 0) s = s//' '//prefix//unit
   end function quantity

   !> n significant digits, plain between 1e-3 and 1e6, trailing zeros dropped (for 4: '315',
   !> '0.004592', '1.234e-5').
   pure function significant(x, n) result(s)
      real(dp), intent(in) :: x
      integer, intent(in) :: n
      character(:), allocatable :: s
      character(len=40) :: buf
      integer :: e, digits, i
      logical :: special
      call special_text(x, s, special)
      if (special) return
      e = floor(log10(abs(x)))
      ! Rounding to four digits may carry into the next decade (9999.7 -> 1.000e4).
      if (abs(x) >= 10.0_dp**(e + 1) - 0.5_dp*10.0_dp**(e + 1 - n)) e = e + 1
      if (e >= -3 .and. e < 6) then
         digits = max(0, n - 1 - e)
         write (buf, '(f40.'//str_int(digits)//')') x
         s = trim(adjustl(buf))
         if (index(s, '.') > 0) then
            i = len(s)
            do while (s(i:i) == '0')
               i = i - 1
            end do
            if (s(i:i) == '.') i = i - 1
            s = s(1:i)
         end if
      else
         write (buf, '(es20.'//str_int(n - 1)//'e3)') x
         s = trim(adjustl(buf))
         i = index(s, 'E')
         ! Mantissa without trailing zeros, exponent without a plus and leading zeros.
         block
            character(:), allocatable :: mant, ex
            integer :: j, ev
            mant = s(1:i - 1)
            j = len(mant)
            do while (mant(j:j) == '0')
               j = j - 1
            end do
            if (mant(j:j) == '.') j = j - 1
            mant = mant(1:j)
            read (s(i + 1:), *) ev
            ex = str_int(ev)
            s = mant//'e'//ex
         end block
      end if
   end function significant

   !> NaN, an infinity or zero as text ('NaN', '+Inf', '-Inf', '0'): is_special .true. and s set for those.
   pure subroutine special_text(x, s, is_special)
      real(dp), intent(in) :: x
      character(:), allocatable, intent(out) :: s
      logical, intent(out) :: is_special
      is_special = .true.
      if (x /= x) then
         s = 'NaN'
      else if (abs(x) > huge(x)) then
         s = merge('+Inf', '-Inf', x > 0)
      else if (x == 0) then
         s = '0'
      else
         is_special = .false.
      end if
   end subroutine special_text
end module xcable_core_strings
