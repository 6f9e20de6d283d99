!> The dgbsv wrapper and the band factorisation against a dense solve; the
!> own kernels (band_lu, band_substitute) against LAPACK's dgbtrf and dgbtrs
!> on random band matrices and on Jacobians of the rod (taken from runs) and
!> of the box scheme: the same pivots and factors bit for bit, and the same
!> solutions (the row form of the back substitution does dgbtrs's
!> operations in dgbtrs's order; measured difference 0, tolerance 1e-15 of
!> max |x|).
module suite_banded
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_solver_banded, only: band_matrix, solve_banded
   use xcable_driver_simulation, only: simulation
   use xcable_io_config, only: case_config
   use xcable_model_rod, only: rod_kl, rod_ku
   use xcable_fixtures, only: paper_case
   use xcable_box_equations, only: cable_model, n_eq
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options
   use xcable_box_discrete, only: box_system
   use xcable_box_statics, only: catenary_guess
   use xcable_theory_closed_forms, only: wave_speed
   use suite_rod_dynamics, only: rupture_config, run_config
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_banded, compare_kernels

contains

   subroutine collect_banded(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('dgbsv_vs_dense', test_dgbsv_vs_dense), &
               new_unittest('factor_solve_vs_dense', test_factor_vs_dense), &
               new_unittest('size_checks', test_size_checks), &
               new_unittest('singular', test_singular), &
               new_unittest('own_kernels_vs_lapack_random', test_kernels_random), &
               new_unittest('own_kernels_vs_lapack_rod_runs', test_kernels_rod), &
               new_unittest('own_kernels_vs_lapack_box', test_kernels_box), &
               new_unittest('clear_after_factor', test_clear_after_factor)]
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

   !> clear after a factorisation: every entry of the matrix (rows kl + 1.. of ab) is zero
   !> again, and the matrix filled in again factorises to the bits of a fresh one, although
   !> clear leaves the fill-in rows 1 .. kl as the factorisation left them (band_clear);
   !> for the rod's widths (kl = ku = 5, a path of its own) and two others.
   subroutine test_clear_after_factor(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 40
      integer, parameter :: widths(2, 3) = reshape([5, 5, 3, 2, 10, 9], [2, 3])
      real(dp) :: dense(n, n)
      type(band_matrix) :: used, fresh
      integer :: w, kl, ku, i, j
      do w = 1, size(widths, 2)
         kl = widths(1, w)
         ku = widths(2, w)
         call make_matrix(n, kl, ku, dense, used)
         call used%factor(error)
         if (allocated(error)) return
         call check(error, any(used%ab(1:kl, :) /= 0), 'the test needs fill-in, kl = '//str(kl))
         if (allocated(error)) return
         call used%clear()
         call check(error, all(used%ab(kl + 1:, :) == 0) .and. .not. used%factorised, &
                    'clear left entries of the matrix, kl = '//str(kl)//', ku = '//str(ku))
         if (allocated(error)) return
         do j = 1, n
            do i = max(1, j - ku), min(n, j + kl)
               used%ab(used%row(i, j), j) = dense(i, j)
            end do
         end do
         call used%factor(error)
         if (allocated(error)) return
         call make_matrix(n, kl, ku, dense, fresh)
         call fresh%factor(error)
         if (allocated(error)) return
         call check(error, all(used%ab == fresh%ab) .and. all(used%ipiv == fresh%ipiv), &
                    'factors after clear differ from a fresh matrix''s, kl = '//str(kl)//', ku = '//str(ku))
         if (allocated(error)) return
      end do
   end subroutine test_clear_after_factor

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

   !> Factorise a copy of a with the own kernels and with LAPACK: error unless
   !> ipiv and ab agree exactly and the solutions for two right-hand sides
   !> agree within rel_tol of the largest |x|. worst: the largest relative
   !> difference of the solutions.
   subroutine compare_kernels(a, label, rel_tol, worst, error)
      type(band_matrix), intent(in) :: a
      character(*), intent(in) :: label
      real(dp), intent(in) :: rel_tol
      real(dp), intent(inout) :: worst
      type(error_type), allocatable, intent(out) :: error
      type(band_matrix) :: own, ref
      type(error_type), allocatable :: e_own, e_ref
      real(dp), allocatable :: b(:), x_own(:), x_ref(:)
      real(dp) :: diff
      integer :: i, k
      own = a
      own%lapack = .false.
      ref = a
      ref%lapack = .true.
      call own%factor(e_own)
      call ref%factor(e_ref)
      ! A matrix that is singular to the last bit: both must say so at the same column.
      if (allocated(e_own) .neqv. allocated(e_ref)) then
         call fatal_error(error, label//': one kernel finds the matrix singular, the other not')
         return
      end if
      if (allocated(e_own)) then
         if (e_own%message(index(e_own%message, ':'):) /= e_ref%message(index(e_ref%message, ':'):)) then
            call fatal_error(error, label//': "'//e_own%message//'" against "'//e_ref%message//'"')
            return
         end if
      end if
      if (any(own%ipiv /= ref%ipiv)) then
         i = findloc(own%ipiv /= ref%ipiv, .true., 1)
         call fatal_error(error, label//': pivot of column '//str(i)//' is '//str(own%ipiv(i))//', dgbtrf: '// &
                          str(ref%ipiv(i)))
         return
      end if
      if (any(own%ab /= ref%ab)) then
         call fatal_error(error, label//': factors differ from dgbtrf''s (largest difference '// &
                          str(maxval(abs(own%ab - ref%ab)))//')')
         return
      end if
      if (allocated(e_own)) return
      allocate (b(a%n))
      do k = 1, 2
         do i = 1, a%n
            b(i) = merge(1.0_dp, cos(0.37_dp*i*i + 1.1_dp), k == 1)
         end do
         x_own = b
         x_ref = b
         call own%solve(x_own, error)
         if (allocated(error)) return
         call ref%solve(x_ref, error)
         if (allocated(error)) return
         diff = maxval(abs(x_own - x_ref))/maxval(abs(x_ref))
         worst = max(worst, diff)
         if (.not. (diff <= rel_tol)) then
            call fatal_error(error, label//': solution differs from dgbtrs''s by '//str(diff)//' of max |x| (tolerance '// &
                             str(rel_tol)//')')
            return
         end if
      end do
   end subroutine compare_kernels

   !> Random band matrices, widths 0-12 (5, 5 and 8, 8 among them, the widths with
   !> their own compiled kernels), orders 1-300, with and without
   !> dominant diagonals (no or frequent interchanges), exact zeros, ties of
   !> magnitude and zero pivots.
   subroutine test_kernels_random(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: widths(2, 8) = reshape([5, 5, 8, 8, 7, 10, 0, 0, 1, 3, 4, 0, 12, 9, 2, 2], [2, 8])
      integer, parameter :: orders(6) = [1, 3, 11, 17, 120, 300]
      type(band_matrix) :: a
      real(dp) :: r, worst
      integer :: w, o, i, j, kl, ku, n, variant, seed_size
      integer, allocatable :: seed(:)
      call random_seed(size=seed_size)
      seed = [(7919*i, i=1, seed_size)]
      call random_seed(put=seed)
      worst = 0
      do w = 1, size(widths, 2)
         kl = widths(1, w)
         ku = widths(2, w)
         do o = 1, size(orders)
            n = orders(o)
            if (n > 1 .and. (kl >= n .or. ku >= n)) cycle
            do variant = 1, 4
               call a%init(n, kl, ku)
               do j = 1, n
                  do i = max(1, j - ku), min(n, j + kl)
                     call random_number(r)
                     a%ab(a%row(i, j), j) = r - 0.5_dp
                     ! Variant 2: exact zeros; variant 3: a dominant diagonal; variant 4: the
                     ! integers -3..3, with ties of magnitude in the pivot search (the first
                     ! is the pivot) and zero pivots.
                     if (variant == 2 .and. i /= j .and. mod(i + 2*j, 3) == 0) a%ab(a%row(i, j), j) = 0
                     if (variant == 3 .and. i == j) a%ab(a%row(i, j), j) = 4 + r
                     if (variant == 4) a%ab(a%row(i, j), j) = nint(7*r - 3.5_dp)
                  end do
               end do
               ! Garbage in the fill-in rows, which both must ignore.
               a%ab(1:kl, :) = 99
               call compare_kernels(a, 'random n = '//str(n)//', kl = '//str(kl)//', ku = '//str(ku)// &
                                    ', variant '//str(variant), 1.0e-15_dp, worst, error)
               if (allocated(error)) return
            end do
         end do
      end do
      write (output_unit, '(4x,a,es9.2)') 'random: largest |x_own - x_dgbtrs| / max |x|', worst
      ! A zero column: both report the same singular pivot.
      call a%init(6, 2, 1)
      do j = 1, 6
         do i = max(1, j - 1), min(6, j + 2)
            if (j /= 4) a%ab(a%row(i, j), j) = 1 + i + 0.5_dp*j
         end do
      end do
      call singular_agrees(a, error)
      if (allocated(error)) return
      ! A zero column 7 of 30 with widths 5, 5 and 8, 8 (their own instances) and 2, 1:
      ! in band_lu's loop over columns 1..n - kl - ku, the one above is in its loop over
      ! the last kl + ku columns.
      do w = 1, 3
         kl = merge(5, merge(8, 2, w == 2), w == 1)
         ku = merge(5, merge(8, 1, w == 2), w == 1)
         call a%init(30, kl, ku)
         do j = 1, 30
            do i = max(1, j - ku), min(30, j + kl)
               if (j /= 7) a%ab(a%row(i, j), j) = cos(1.7_dp*i + 0.3_dp*j) + merge(2.0_dp, 0.0_dp, i == j)
            end do
         end do
         call singular_agrees(a, error)
         if (allocated(error)) return
      end do
   end subroutine test_kernels_random

   !> A singular matrix: both kernels stop with the same column in the message.
   subroutine singular_agrees(a, error)
      type(band_matrix), intent(in) :: a
      type(error_type), allocatable, intent(out) :: error
      type(band_matrix) :: own, ref
      type(error_type), allocatable :: e_own, e_ref
      own = a
      ref = a
      ref%lapack = .true.
      call own%factor(e_own)
      call ref%factor(e_ref)
      call check(error, allocated(e_own) .and. allocated(e_ref), 'singular matrix factorised without error')
      if (allocated(error)) return
      call check(error, e_own%message(index(e_own%message, ':'):) == e_ref%message(index(e_ref%message, ':'):), &
                 'singular: "'//e_own%message//'" against "'//e_ref%message//'"')
   end subroutine singular_agrees

   !> Jacobians of the rod (241 and 61 nodes, fast_180kN) at the end of runs
   !> to 3 ms (the ramp), 40 ms (the front on its way) and 120 ms (after
   !> the reflection, compressed and buckling), and at Courant 4.
   subroutine test_kernels_rod(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      type(band_matrix) :: jac
      real(dp), allocatable :: res(:)
      real(dp) :: t_ends(3) = [0.003_dp, 0.04_dp, 0.12_dp], worst
      integer :: nodes(2) = [241, 61], i, k, p, n, interchanges
      worst = 0
      interchanges = 0
      do k = 1, size(nodes)
         do i = 1, size(t_ends)
            c = rupture_config(180.0e3_dp, 0.005_dp, t_ends(i), nodes(k))
            if (k == 2) c%courant = 4
            call run_config(c, sim, error)
            if (allocated(error)) return
            do p = 1, size(sim%rod%pieces)
               associate (piece => sim%rod%pieces(p))
                  n = size(piece%x)
                  call jac%init(n, rod_kl, rod_ku)
                  allocate (res(n))
                  call piece%problem%evaluate(piece%x, res, jac, .true.)
                  deallocate (res)
                  call compare_kernels(jac, 'rod, '//str(nodes(k))//' nodes, t = '//str(t_ends(i))//' s, piece '// &
                                       str(p), 1.0e-15_dp, worst, error)
                  if (allocated(error)) return
                  call jac%factor(error)
                  if (allocated(error)) return
                  interchanges = interchanges + count(jac%ipiv /= [(i, i=1, n)])
               end associate
            end do
         end do
      end do
      write (output_unit, '(4x,a,es9.2,a,i0,a)') 'rod: largest |x_own - x_dgbtrs| / max |x|', worst, ' (', &
         interchanges, ' row interchanges)'
      call check(error, interchanges > 0, 'rod Jacobians: no row interchange, the pivoting is not tested')
   end subroutine test_kernels_rod

   !> A Jacobian of the box scheme (kl = 7, ku = 10) in a time step.
   subroutine test_kernels_box(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:), x(:), res(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(box_system) :: system
      type(band_matrix) :: jac
      real(dp), allocatable :: y(:, :)
      real(dp) :: worst
      integer :: kl, ku
      call paper_case(315.0e3_dp, 41, model, s, newton, dyn, error)
      if (allocated(error)) return
      allocate (y(n_eq, size(s)))
      call catenary_guess(model, s, 315.0e3_dp, y, error)
      if (allocated(error)) return
      call system%init(model, s, .true., 315.0e3_dp, wave_speed(model%law, model%mass, 0.228_dp), 0.5_dp)
      call system%prepare_step(y, 2.0e-4_dp, 1.5e5_dp, -2.0e3_dp)
      y(3, :) = y(3, :) + 3
      x = reshape(y, [size(y)])
      call system%band_widths(kl, ku)
      call jac%init(size(x), kl, ku)
      allocate (res(size(x)))
      call system%evaluate(x, res, jac, .true.)
      worst = 0
      call compare_kernels(jac, 'box, 41 nodes', 1.0e-15_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') 'box: largest |x_own - x_dgbtrs| / max |x|', worst
   end subroutine test_kernels_box
end module suite_banded
