!> Forward-mode dual numbers with six derivative slots: a value and its
!> derivatives with respect to six seeded inputs (the 3-D rod seeds the two
!> new cell vectors of a node). The bending terms of the 3-D rod's discrete
!> gradient are written once with these, and their exact derivatives (to
!> round-off, no truncation error) fill its Jacobian; the Jacobian tests
!> check them against central differences like every other derivative.
module xcable_model_dual
   use xcable_kinds, only: dp
   implicit none
   private
   public :: dual, dual_slots, operator(+), operator(-), operator(*), operator(/)
   public :: sqrt, atan2, dot3, cross3, constant, seeded

   !> Number of derivative slots.
   integer, parameter :: dual_slots = 6

   !> A value and its derivatives.
   type :: dual
      !> Value.
      real(dp) :: v = 0
      !> Derivatives with respect to the seeded inputs.
      real(dp) :: d(dual_slots) = 0
   end type dual

   interface operator(+)
      module procedure add_dd, add_dr, add_rd
   end interface
   interface operator(-)
      module procedure sub_dd, sub_dr, sub_rd, neg_d
   end interface
   interface operator(*)
      module procedure mul_dd, mul_dr, mul_rd
   end interface
   interface operator(/)
      module procedure div_dd, div_dr, div_rd
   end interface
   interface sqrt
      module procedure sqrt_d
   end interface
   interface atan2
      module procedure atan2_dd
   end interface

contains

   !> A constant (no derivatives).
   elemental type(dual) function constant(x) result(r)
      !> Value.
      real(dp), intent(in) :: x
      r%v = x
      r%d = 0
   end function constant

   !> Input i with value x (derivative 1 in slot i).
   elemental type(dual) function seeded(x, i) result(r)
      !> Value.
      real(dp), intent(in) :: x
      !> Slot.
      integer, intent(in) :: i
      r%v = x
      r%d = 0
      r%d(i) = 1
   end function seeded

   elemental type(dual) function add_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v + b%v
      r%d = a%d + b%d
   end function add_dd

   elemental type(dual) function add_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v + b
      r%d = a%d
   end function add_dr

   elemental type(dual) function add_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a + b%v
      r%d = b%d
   end function add_rd

   elemental type(dual) function sub_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v - b%v
      r%d = a%d - b%d
   end function sub_dd

   elemental type(dual) function sub_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v - b
      r%d = a%d
   end function sub_dr

   elemental type(dual) function sub_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a - b%v
      r%d = -b%d
   end function sub_rd

   elemental type(dual) function neg_d(a) result(r)
      type(dual), intent(in) :: a
      r%v = -a%v
      r%d = -a%d
   end function neg_d

   elemental type(dual) function mul_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v*b%v
      r%d = a%d*b%v + a%v*b%d
   end function mul_dd

   elemental type(dual) function mul_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v*b
      r%d = a%d*b
   end function mul_dr

   elemental type(dual) function mul_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a*b%v
      r%d = a*b%d
   end function mul_rd

   elemental type(dual) function div_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v/b%v
      r%d = (a%d - r%v*b%d)/b%v
   end function div_dd

   elemental type(dual) function div_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v/b
      r%d = a%d/b
   end function div_dr

   elemental type(dual) function div_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a/b%v
      r%d = -r%v*b%d/b%v
   end function div_rd

   elemental type(dual) function sqrt_d(a) result(r)
      type(dual), intent(in) :: a
      r%v = sqrt(a%v)
      r%d = 0.5_dp*a%d/r%v
   end function sqrt_d

   !> atan2(y, x) with d = (x dy - y dx) / (x^2 + y^2).
   elemental type(dual) function atan2_dd(y, x) result(r)
      type(dual), intent(in) :: y, x
      r%v = atan2(y%v, x%v)
      r%d = (x%v*y%d - y%v*x%d)/(x%v**2 + y%v**2)
   end function atan2_dd

   !> Dot product of two 3-vectors.
   pure type(dual) function dot3(a, b) result(r)
      type(dual), intent(in) :: a(3), b(3)
      r = a(1)*b(1) + a(2)*b(2) + a(3)*b(3)
   end function dot3

   !> Cross product of two 3-vectors.
   pure function cross3(a, b) result(r)
      type(dual), intent(in) :: a(3), b(3)
      type(dual) :: r(3)
      r(1) = a(2)*b(3) - a(3)*b(2)
      r(2) = a(3)*b(1) - a(1)*b(3)
      r(3) = a(1)*b(2) - a(2)*b(1)
   end function cross3
end module xcable_model_dual
