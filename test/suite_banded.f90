!> The dgbsv wrapper and the band factorisation against a dense solve.
module suite_banded
   use xcable_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_strings, only: str
   use xcable_solver_banded, only: band_matrix, solve_banded
   implicit none
   private
   public :: collect_banded

contains

   subroutine collect_banded(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('dgbsv_vs_dense', test_dgbsv_vs_dense), &
               new_unittest('factor_solve_vs_dense', test_factor_vs_dense), &
               new_unittest('size_checks', test_size_checks), &
               new_unittest('singular', test_singular)]
   end subroutine collect_banded

   !> A reproducible banded matrix (dense copy) with kl, ku diagonals.
   subroutine make_matrix(n, kl, ku, dense, band)
      integer, intent(in) :: n, kl, ku
      real(dp), intent(out) :: dense(n, n)
      type(band_matrix), intent(out) :: band
      integer :: i, j
      call band%init(n, kl, ku)
      dense = 0
      do j = 1, n
         do i = max(1, j - ku), min(n, j + kl)
            dense(i, j) = sin(1.3_dp*i + 0.7_dp*j) + merge(0.5_dp, 0.0_dp, i == j)
            band%ab(band%row(i, j), j) = dense(i, j)
         end do
      end do
   end subroutine make_matrix

   !> Dense Gaussian elimination with partial pivoting (reference).
   subroutine dense_solve(a, b)
      real(dp), intent(inout) :: a(:, :), b(:)
      integer :: n, k, p, i
      real(dp) :: row(size(b)), tmp
      n = size(b)
      do k = 1, n
         p = k - 1 + maxloc(abs(a(k:n, k)), 1)
         row = a(k, :); a(k, :) = a(p, :); a(p, :) = row
         tmp = b(k); b(k) = b(p); b(p) = tmp
         do i = k + 1, n
            tmp = a(i, k)/a(k, k)
            a(i, k:n) = a(i, k:n) - tmp*a(k, k:n)
            b(i) = b(i) - tmp*b(k)
         end do
      end do
      do k = n, 1, -1
         b(k) = (b(k) - dot_product(a(k, k + 1:n), b(k + 1:n)))/a(k, k)
      end do
   end subroutine dense_solve

   subroutine test_dgbsv_vs_dense(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 40, kl = 9, ku = 10
      real(dp) :: dense(n, n), b(n), x(n)
      type(band_matrix) :: band
      integer :: i
      call make_matrix(n, kl, ku, dense, band)
      b = [(cos(0.3_dp*i), i=1, n)]
      x = b
      call solve_banded(band%ab, kl, ku, x, error)
      if (allocated(error)) return
      call dense_solve(dense, b)
      do i = 1, n
         call check_close(error, x(i), b(i), 'x('//str(i)//')', rel_tol=1.0e-10_dp, abs_tol=1.0e-12_dp)
         if (allocated(error)) return
      end do
   end subroutine test_dgbsv_vs_dense

   subroutine test_factor_vs_dense(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 35, kl = 10, ku = 9
      real(dp) :: dense(n, n), b(n), x(n), ax(n)
      type(band_matrix) :: band
      integer :: i
      call make_matrix(n, kl, ku, dense, band)
      b = [(1.0_dp/i, i=1, n)]
      call band%matvec(b, ax)
      call check_close(error, maxval(abs(ax - matmul(dense, b))), 0.0_dp, 'band matvec', abs_tol=1.0e-12_dp)
      if (allocated(error)) return
      x = b
      call band%factor(error)
      if (allocated(error)) return
      call band%solve(x, error)
      if (allocated(error)) return
      call dense_solve(dense, b)
      call check_close(error, maxval(abs(x - b)), 0.0_dp, 'max |x_band - x_dense|', abs_tol=1.0e-11_dp)
   end subroutine test_factor_vs_dense

   !> Wrong sizes are refused with a message, not a crash.
   subroutine test_size_checks(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: err
      real(dp) :: ab(5, 10), b(9), b10(10)
      type(band_matrix) :: band
      ab = 0
      b = 0
      call solve_banded(ab, 1, 1, b, err)
      call check(error, allocated(err), 'right-hand side of the wrong size accepted')
      if (allocated(error)) return
      deallocate (err)
      b10 = 0
      call solve_banded(ab, 2, 2, b10, err)
      call check(error, allocated(err), 'band storage with the wrong number of rows accepted')
      if (allocated(error)) return
      deallocate (err)
      call band%init(10, 1, 1)
      call band%solve(b10, err)
      call check(error, allocated(err), 'solve before factor accepted')
   end subroutine test_size_checks

   !> A singular matrix gives dgbtrf's info as a message.
   subroutine test_singular(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: err
      type(band_matrix) :: band
      call band%init(4, 1, 1)
      call band%factor(err)
      call check(error, allocated(err), 'zero matrix factorised without error')
      if (allocated(error)) return
      call check(error, index(err%message, 'singular') > 0, 'message does not say singular: '//err%message)
   end subroutine test_singular
end module suite_banded
