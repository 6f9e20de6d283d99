!> Small string helpers for messages.
module xcable_strings
   use xcable_kinds, only: dp
   implicit none
   private
   public :: str, to_lower

   !> Convert a number to a compact string.
   interface str
      module procedure str_real, str_int, str_logical
   end interface str

contains

   !> Real to string (shortest general format).
   pure function str_real(x) result(s)
      !> Value.
      real(dp), intent(in) :: x
      character(:), allocatable :: s
      character(len=32) :: buf
      if (x /= x) then
         s = 'NaN'
      else if (abs(x) > huge(x)) then
         s = merge('+Inf', '-Inf', x > 0)
      else
         write (buf, '(g0.6)') x
         s = trim(adjustl(buf))
      end if
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
end module xcable_strings
