!> Banded linear systems: own LU and substitution kernels, with LAPACK
!> (dgbtrf, dgbtrs, dgbsv) as the reference and an option.
!>
!> The matrix is kept in LAPACK band storage for factorisation:
!> A(i, j) is stored in ab(kl + ku + 1 + i - j, j) for
!> max(1, j - ku) <= i <= min(n, j + kl); the first kl rows of ab are
!> workspace for the fill-in of partial pivoting. Newton's method factorises
!> and keeps the factors (ab and ipiv, the complete factorisation) for one or
!> several substitutions.
!>
!> Own kernels (the default; `lapack = .true.` calls dgbtrf and dgbtrs).
!> Why: at these band widths the reference BLAS calls that LAPACK makes per
!> column (idamax, dswap, dscal, dger in dgbtf2; dger, dtbsv in dgbtrs) cost
!> more than the arithmetic. Measured with callgrind on fast_180kN as shipped
!> (the rod, 241 nodes, n = 482, kl = ku = 5, 1236 factorisations and
!> substitutions): 251 000 instructions per factorisation with dgbtrf,
!> 114 000 with band_lu; 72 000 per substitution with the former plain-loop
!> copy of dgbtrs (136 000 with dgbtrs itself), 36 000 with band_substitute;
!> the whole run 2.42e9 -> 2.20e9 instructions, results bit for bit the same
!> (docs/measurements/data/speed_rounds.md).
!> - `band_lu` does the operations of LAPACK's unblocked dgbtf2 (which dgbtrf
!>   calls for kl < 32) in the same order: the first entry of largest
!>   magnitude as pivot, the rows interchanged over columns j..ju, the
!>   multipliers scaled by the reciprocal of the pivot, and the rank-one
!>   update of columns j + 1..ju that skips zero entries of the pivot row. Its
!>   factors and pivots are dgbtrf's bit for bit (tested on random matrices
!>   and on Jacobians of the rod and the box scheme).
!> - `band_substitute` runs L by columns (interchanges and multipliers, as
!>   dgbtrs) and U by rows: each unknown is one sum over the unknowns already
!>   found, accumulated in a register from the farthest to the nearest, then
!>   divided by the diagonal. dgbtrs's column form does the same operations
!>   in the same order but keeps the partial sums in memory, updating the
!>   whole band of unknowns per column; the solutions are the same bit for
!>   bit (tested).
!> Both are compiled three times from one source (band_lu.inc,
!> band_substitute.inc): for any widths, and with kl = ku = 5 (the planar rod)
!> and kl = ku = 8 (the 3-D rod) as constants, which lets the compiler unroll
!> the loops over the band: with the widths as variables the planar rod's
!> factorisation took 237 000 instructions, about twice as many; on sway3d the
!> 3-D instance (with the packed updates of band_lu.inc) took band_factor
!> 47.4e6 -> 29.4e6 and band_solve 11.9e6 ->
!> 8.2e6 instructions (the whole run 0.401e9 -> 0.378e9, the same bits).
!> The kernels read and write only ab and ipiv, the complete factorisation
!> (what a checkpoint keeps); no other copy of the factors exists.
!> `solve_banded` is dgbsv.
module xcable_solver_banded
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_numerics
   use xcable_core_strings, only: str
   implicit none
   private
   public :: band_matrix, solve_banded

   interface
      !> LAPACK: solve a banded system (LU with partial pivoting).
      pure subroutine dgbsv(n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(dp), intent(inout) :: ab(ldab, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgbsv
      !> LAPACK: LU factorisation of a banded matrix.
      pure subroutine dgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
         import :: dp
         integer, intent(in) :: m, n, kl, ku, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgbtrf
      !> LAPACK: solve with a banded LU factorisation.
      pure subroutine dgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: dp
         character, intent(in) :: trans
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         integer, intent(in) :: ipiv(*)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dgbtrs
   end interface

   !> A square banded matrix in LAPACK factorisation storage, with its pivots.
   type :: band_matrix
      !> Order of the matrix.
      integer :: n = 0
      !> Number of sub-diagonals.
      integer :: kl = 0
      !> Number of super-diagonals.
      integer :: ku = 0
      !> Leading dimension of ab, 2 kl + ku + 1.
      integer :: ldab = 0
      !> Band storage (ldab, n).
      real(dp), allocatable :: ab(:, :)
      !> Row interchanges of the LU factorisation.
      integer, allocatable :: ipiv(:)
      !> True once factorised (ab then holds the LU factors).
      logical :: factorised = .false.
      !> Factorise and solve with LAPACK's dgbtrf and dgbtrs instead of band_lu and band_substitute.
      logical :: lapack = .false.
   contains
      !> Allocate for order n with kl sub- and ku super-diagonals.
      procedure :: init => band_init
      !> Set every entry of the matrix to zero (rows kl + 1.. of ab; not the fill-in rows).
      procedure :: clear => band_clear
      !> Use the first m columns only (m at most the allocated order): a smaller matrix in the same storage.
      procedure :: set_order => band_set_order
      !> Row of ab that holds A(i, j).
      procedure :: row => band_row
      !> Factorise in place (band_lu, or dgbtrf).
      procedure :: factor => band_factor
      !> Solve with the factors (band_substitute, or dgbtrs), overwriting b.
      procedure :: solve => band_solve
      !> Multiply the (unfactorised) matrix by a vector.
      procedure :: matvec => band_matvec
   end type band_matrix

contains

   !> Allocate for order n with kl sub- and ku super-diagonals.
   subroutine band_init(self, n, kl, ku)
      !> Matrix.
      class(band_matrix), intent(inout) :: self
      !> Order.
      integer, intent(in) :: n
      !> Sub-diagonals.
      integer, intent(in) :: kl
      !> Super-diagonals.
      integer, intent(in) :: ku
      self%n = n
      self%kl = kl
      self%ku = ku
      self%ldab = 2*kl + ku + 1
      if (allocated(self%ab)) deallocate (self%ab)
      if (allocated(self%ipiv)) deallocate (self%ipiv)
      allocate (self%ab(self%ldab, n), self%ipiv(n))
      self%ab = 0
      self%ipiv = 0
      self%factorised = .false.
   end subroutine band_init

   !> Make the matrix of order m in the same storage (its first m columns; m
   !> at most the order it was allocated for). Forgets any factorisation.
   subroutine band_set_order(self, m, error)
      !> Matrix.
      class(band_matrix), intent(inout) :: self
      !> New order.
      integer, intent(in) :: m
      !> Error when m is not in 1 .. the allocated order.
      type(error_type), allocatable, intent(out) :: error
      if (.not. allocated(self%ab)) then
         call fatal_error(error, 'band_set_order: matrix not allocated', stat_numerics)
         return
      end if
      if (m < 1 .or. m > size(self%ab, 2)) then
         call fatal_error(error, 'band_set_order: order '//str(m)//' outside 1 .. '//str(size(self%ab, 2)), &
                          stat_numerics)
         return
      end if
      self%n = m
      self%factorised = .false.
   end subroutine band_set_order

   !> Set every entry of the matrix to zero (rows kl + 1 .. ldab of ab).
   !> The fill-in rows 1 .. kl of ab are left as they are: the factorisations (band_lu as
   !> dgbtf2, and dgbtrf) set them before they use them. With kl = ku = 5 (the rod) the rows
   !> kl + 1 .. ldab of a column are cleared by stores of a known length: ab = 0 on the
   !> component made a memset call per column (16 500 instructions per clear of the rod's
   !> 482 columns, 2.6 % of fast_180kN; these stores save 1.4 % of it).
   pure subroutine band_clear(self)
      !> Matrix.
      class(band_matrix), intent(inout) :: self
      if (self%kl == 5 .and. self%ku == 5) then
         call clear_rows_5_5(size(self%ab, 2), self%ab)
      else
         self%ab(self%kl + 1:, :) = 0
      end if
      self%factorised = .false.
   end subroutine band_clear

   !> band_clear with kl = ku = 5: rows 6 .. 16 of m columns.
   pure subroutine clear_rows_5_5(m, ab)
      integer, intent(in) :: m
      real(dp), intent(inout) :: ab(16, m)
      integer :: j
      do j = 1, m
         ab(6:16, j) = 0
      end do
   end subroutine clear_rows_5_5

   !> Row of ab that holds A(i, j).
   elemental integer function band_row(self, i, j) result(r)
      !> Matrix.
      class(band_matrix), intent(in) :: self
      !> Row of A.
      integer, intent(in) :: i
      !> Column of A.
      integer, intent(in) :: j
      r = self%kl + self%ku + 1 + i - j
   end function band_row

   !> Factorise in place with band_lu (or dgbtrf).
   subroutine band_factor(self, error)
      !> Matrix; holds the LU factors on return.
      class(band_matrix), intent(inout) :: self
      !> Error if the matrix is singular.
      type(error_type), allocatable, intent(out) :: error
      integer :: info
      if (self%lapack) then
         call dgbtrf(self%n, self%n, self%kl, self%ku, self%ab, self%ldab, self%ipiv, info)
      else if (self%kl == 5 .and. self%ku == 5) then
         call band_lu_5_5(self%n, self%ab, self%ipiv, info)
      else if (self%kl == 8 .and. self%ku == 8) then
         call band_lu_8_8(self%n, self%ab, self%ipiv, info)
      else
         call band_lu(self%n, self%kl, self%ku, self%ab, self%ipiv, info)
      end if
      if (info /= 0) then
         call fatal_error(error, info_message(trim(merge('dgbtrf ', 'band_lu', self%lapack)), info), stat_numerics)
         return
      end if
      self%factorised = .true.
   end subroutine band_factor

   !> LU factorisation with partial pivoting of a square band matrix, the
   !> operations of LAPACK's dgbtf2 (see the module header).
   pure subroutine band_lu(n, kl, ku, ab, ipiv, info)
      !> Order, sub- and super-diagonals.
      integer, intent(in) :: n, kl, ku
      include 'band_lu.inc'
   end subroutine band_lu

   !> band_lu with kl = ku = 5 (the rod) as constants.
   pure subroutine band_lu_5_5(n, ab, ipiv, info)
      !> Order.
      integer, intent(in) :: n
      integer, parameter :: kl = 5, ku = 5
      include 'band_lu.inc'
   end subroutine band_lu_5_5

   !> band_lu with kl = ku = 8 (the 3-D rod) as constants.
   pure subroutine band_lu_8_8(n, ab, ipiv, info)
      !> Order.
      integer, intent(in) :: n
      integer, parameter :: kl = 8, ku = 8
      include 'band_lu.inc'
   end subroutine band_lu_8_8

   !> Solve A x = b with the factors; b is overwritten by x.
   subroutine band_solve(self, b, error)
      !> Factorised matrix.
      class(band_matrix), intent(in) :: self
      !> Right-hand side on entry, solution on return.
      real(dp), intent(inout) :: b(:)
      !> Error on a size mismatch or unfactorised matrix.
      type(error_type), allocatable, intent(out) :: error
      integer :: info
      if (.not. self%factorised) then
         call fatal_error(error, 'band_solve: matrix is not factorised', stat_numerics)
         return
      end if
      if (size(b) /= self%n) then
         call fatal_error(error, 'band_solve: right-hand side has size '//str(size(b))// &
                          ', matrix has order '//str(self%n), stat_numerics)
         return
      end if
      if (self%lapack) then
         call dgbtrs('N', self%n, self%kl, self%ku, 1, self%ab, self%ldab, self%ipiv, b, self%n, info)
      else if (self%kl == 5 .and. self%ku == 5) then
         call band_substitute_5_5(self%n, self%ab, self%ipiv, b)
      else if (self%kl == 8 .and. self%ku == 8) then
         call band_substitute_8_8(self%n, self%ab, self%ipiv, b)
      else
         call band_substitute(self%n, self%kl, self%ku, self%ab, self%ipiv, b)
      end if
   end subroutine band_solve

   !> Forward substitution with L by columns, back substitution with U by
   !> rows (see the module header).
   pure subroutine band_substitute(n, kl, ku, ab, ipiv, b)
      !> Order, sub- and super-diagonals.
      integer, intent(in) :: n, kl, ku
      include 'band_substitute.inc'
   end subroutine band_substitute

   !> band_substitute with kl = ku = 5 (the rod) as constants.
   pure subroutine band_substitute_5_5(n, ab, ipiv, b)
      !> Order.
      integer, intent(in) :: n
      integer, parameter :: kl = 5, ku = 5
      include 'band_substitute.inc'
   end subroutine band_substitute_5_5

   !> band_substitute with kl = ku = 8 (the 3-D rod) as constants.
   pure subroutine band_substitute_8_8(n, ab, ipiv, b)
      !> Order.
      integer, intent(in) :: n
      integer, parameter :: kl = 8, ku = 8
      include 'band_substitute.inc'
   end subroutine band_substitute_8_8

   !> y = A x for the unfactorised matrix.
   pure subroutine band_matvec(self, x, y)
      !> Matrix (not factorised).
      class(band_matrix), intent(in) :: self
      !> Vector.
      real(dp), intent(in) :: x(:)
      !> Product.
      real(dp), intent(out) :: y(:)
      integer :: i, j
      y = 0
      do j = 1, self%n
         do i = max(1, j - self%ku), min(self%n, j + self%kl)
            y(i) = y(i) + self%ab(self%kl + self%ku + 1 + i - j, j)*x(j)
         end do
      end do
   end subroutine band_matvec

   !> Solve A x = b once with dgbsv; ab (ldab, n) holds A in factorisation
   !> storage with ldab = 2 kl + ku + 1, and is overwritten by the factors.
   subroutine solve_banded(ab, kl, ku, b, error)
      !> Band storage of A.
      real(dp), intent(inout) :: ab(:, :)
      !> Sub-diagonals.
      integer, intent(in) :: kl
      !> Super-diagonals.
      integer, intent(in) :: ku
      !> Right-hand side on entry, solution on return.
      real(dp), intent(inout) :: b(:)
      !> Error on a size mismatch or a singular matrix.
      type(error_type), allocatable, intent(out) :: error
      integer :: n, info
      integer, allocatable :: ipiv(:)
      n = size(ab, 2)
      if (kl < 0 .or. ku < 0 .or. (n > 1 .and. (kl >= n .or. ku >= n))) then
         call fatal_error(error, 'solve_banded: band widths kl = '//str(kl)//', ku = '//str(ku)// &
                          ' do not fit order '//str(n), stat_numerics)
         return
      end if
      if (size(ab, 1) /= 2*kl + ku + 1) then
         call fatal_error(error, 'solve_banded: band storage has '//str(size(ab, 1))//' rows, need 2 kl + ku + 1 = ' &
                          //str(2*kl + ku + 1), stat_numerics)
         return
      end if
      if (size(b) /= n) then
         call fatal_error(error, 'solve_banded: right-hand side has size '//str(size(b))//', matrix has order ' &
                          //str(n), stat_numerics)
         return
      end if
      allocate (ipiv(n))
      call dgbsv(n, kl, ku, 1, ab, size(ab, 1), ipiv, b, n, info)
      if (info /= 0) call fatal_error(error, info_message('dgbsv', info), stat_numerics)
   end subroutine solve_banded

   !> Message for a LAPACK info code.
   function info_message(routine, info) result(msg)
      character(*), intent(in) :: routine
      integer, intent(in) :: info
      character(:), allocatable :: msg
      if (info < 0) then
         msg = routine//': argument '//str(-info)//' has an illegal value'
      else
         msg = routine//': singular Jacobian (zero pivot U('//str(info)//','//str(info)//'))'
      end if
   end function info_message
end module xcable_solver_banded
