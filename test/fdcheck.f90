!> Generic finite-difference check of an analytic Jacobian: every problem that
!> extends newton_problem (the rod's statics and steps, the box scheme, any
!> new model) is checked entry by entry against central differences.
module xcable_fdcheck
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error
   use xcable_core_strings, only: str
   use xcable_solver_banded, only: band_matrix
   use xcable_solver_newton, only: newton_problem
   implicit none
   private
   public :: check_jacobian

contains

   !> Compare the band Jacobian of problem at x with central differences of
   !> its residual. An entry fails when |analytic - numeric| > tol times the
   !> largest entry of its row (the row scale); the message names the row, the
   !> column and both values. worst returns the largest such ratio.
   subroutine check_jacobian(problem, x, kl, ku, step, tol, worst, error)
      !> The system.
      class(newton_problem), intent(inout) :: problem
      !> Point of the check.
      real(dp), intent(in) :: x(:)
      !> Band widths.
      integer, intent(in) :: kl, ku
      !> Relative difference step (times max(1, |x_j|) ... scaled by the caller's choice).
      real(dp), intent(in) :: step(:)
      !> Tolerance relative to the row scale.
      real(dp), intent(in) :: tol
      !> Largest deviation relative to the row scale.
      real(dp), intent(out) :: worst
      !> Set when an entry deviates by more than tol.
      type(error_type), allocatable, intent(out) :: error
      type(band_matrix) :: jac, dummy
      real(dp), allocatable :: dense(:, :), numeric(:, :), rp(:), rm(:), xp(:), r0(:), rowmax(:)
      integer :: n, i, j, band0, wi, wj
      real(dp) :: dev
      n = size(x)
      call jac%init(n, kl, ku)
      call dummy%init(n, kl, ku)
      allocate (dense(n, n), numeric(n, n), rp(n), rm(n), xp(n), r0(n), rowmax(n))
      call problem%evaluate(x, r0, jac, .true.)
      band0 = kl + ku + 1
      dense = 0
      do j = 1, n
         do i = max(1, j - ku), min(n, j + kl)
            dense(i, j) = jac%ab(band0 + i - j, j)
         end do
      end do
      do j = 1, n
         xp = x
         xp(j) = x(j) + step(j)
         call problem%evaluate(xp, rp, dummy, .false.)
         xp(j) = x(j) - step(j)
         call problem%evaluate(xp, rm, dummy, .false.)
         numeric(:, j) = (rp - rm)/(2*step(j))
      end do
      do i = 1, n
         rowmax(i) = max(maxval(abs(numeric(i, :))), tiny(1.0_dp))
      end do
      worst = 0
      wi = 1
      wj = 1
      do j = 1, n
         do i = 1, n
            dev = abs(dense(i, j) - numeric(i, j))/rowmax(i)
            if (dev > worst) then
               worst = dev
               wi = i
               wj = j
            end if
         end do
      end do
      if (worst > tol) then
         call fatal_error(error, 'Jacobian entry ('//str(wi)//', '//str(wj)//'): analytic '//str(dense(wi, wj))// &
                          ', central difference '//str(numeric(wi, wj))//' (deviation '//str(worst)// &
                          ' of the row scale, tolerance '//str(tol)//')')
      end if
   end subroutine check_jacobian
end module xcable_fdcheck
