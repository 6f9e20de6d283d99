!> Small 3-D vector algebra shared by the 3-D rod, its driver and the loads:
!> the outer product (of 3-vectors, and of vectors of any size for the loads'
!> 2-D and 3-D forms), the identity and the cross product.
module xcable_numerics_vector3
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: outer3, identity3, cross3, outer

contains

   !> a b^T.
   pure function outer3(a, b) result(m)
      real(dp), intent(in) :: a(3), b(3)
      real(dp) :: m(3, 3)
      integer :: j
      do j = 1, 3
         m(:, j) = a*b(j)
      end do
   end function outer3

   !> a b^T for vectors of any size.
   pure function outer(a, b) result(m)
      real(dp), intent(in) :: a(:), b(:)
      real(dp) :: m(size(a), size(b))
      integer :: j
      do j = 1, size(b)
         m(:, j) = a*b(j)
      end do
   end function outer

   !> The 3x3 identity.
   pure function identity3() result(m)
      real(dp) :: m(3, 3)
      m = 0
      m(1, 1) = 1
      m(2, 2) = 1
      m(3, 3) = 1
   end function identity3

   !> a x b.
   pure function cross3(a, b) result(c)
      real(dp), intent(in) :: a(3), b(3)
      real(dp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross3
end module xcable_numerics_vector3
