!> A small test harness shaped like test-drive: suites of named tests, each a
!> subroutine that allocates `error` when a check fails; the driver runs all
!> suites or one `suite [test]` and exits non-zero if anything failed.
module xcable_testing
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error
   use xcable_core_strings, only: str
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: error_type, unittest_type, testsuite_type, new_unittest, new_testsuite, test_interface
   public :: check, check_close, run_suite

   abstract interface
      !> A test: allocate error when a check fails.
      subroutine test_interface(error)
         import :: error_type
         type(error_type), allocatable, intent(out) :: error
      end subroutine test_interface
   end interface

   !> A named test.
   type :: unittest_type
      character(:), allocatable :: name
      procedure(test_interface), pointer, nopass :: test => null()
   end type unittest_type

   !> A named suite with the procedure that lists its tests.
   type :: testsuite_type
      character(:), allocatable :: name
      procedure(collect_interface), pointer, nopass :: collect => null()
   end type testsuite_type

   abstract interface
      !> List the tests of a suite.
      subroutine collect_interface(tests)
         import :: unittest_type
         type(unittest_type), allocatable, intent(out) :: tests(:)
      end subroutine collect_interface
   end interface

   !> Check a condition, or two numbers against tolerances.
   interface check
      module procedure check_condition
   end interface check

contains

   !> Make a test.
   function new_unittest(name, test) result(t)
      character(*), intent(in) :: name
      procedure(test_interface) :: test
      type(unittest_type) :: t
      t%name = name
      t%test => test
   end function new_unittest

   !> Make a suite.
   function new_testsuite(name, collect) result(s)
      character(*), intent(in) :: name
      procedure(collect_interface) :: collect
      type(testsuite_type) :: s
      s%name = name
      s%collect => collect
   end function new_testsuite

   !> Fail with message unless condition holds.
   subroutine check_condition(error, condition, message)
      !> Set when the check fails.
      type(error_type), allocatable, intent(out) :: error
      !> What must hold.
      logical, intent(in) :: condition
      !> What failed.
      character(*), intent(in) :: message
      if (.not. condition) call fatal_error(error, message)
   end subroutine check_condition

   !> Fail unless |actual - expected| <= max(abs_tol, rel_tol |expected|).
   subroutine check_close(error, actual, expected, message, rel_tol, abs_tol)
      !> Set when the check fails.
      type(error_type), allocatable, intent(out) :: error
      !> Computed and reference values.
      real(dp), intent(in) :: actual, expected
      !> What is compared.
      character(*), intent(in) :: message
      !> Relative and absolute tolerances (0 if absent).
      real(dp), intent(in), optional :: rel_tol, abs_tol
      real(dp) :: tol
      tol = 0
      if (present(rel_tol)) tol = max(tol, rel_tol*abs(expected))
      if (present(abs_tol)) tol = max(tol, abs_tol)
      if (.not. (abs(actual - expected) <= tol)) then
         call fatal_error(error, message//': got '//str(actual)//', expected '//str(expected)//' within '//str(tol))
      end if
   end subroutine check_close

   !> Run the tests of a suite (all, or the one named only); count failures.
   subroutine run_suite(suite, only, passed, failed)
      !> Suite.
      type(testsuite_type), intent(in) :: suite
      !> Name of the single test to run ('' for all).
      character(*), intent(in) :: only
      !> Counters, incremented.
      integer, intent(inout) :: passed, failed
      type(unittest_type), allocatable :: tests(:)
      type(error_type), allocatable :: error
      integer :: i
      call suite%collect(tests)
      do i = 1, size(tests)
         if (len(only) > 0 .and. tests(i)%name /= only) cycle
         call tests(i)%test(error)
         if (allocated(error)) then
            failed = failed + 1
            write (output_unit, '(a)') '  FAIL '//suite%name//' / '//tests(i)%name//': '//error%message
            deallocate (error)
         else
            passed = passed + 1
            write (output_unit, '(a)') '  ok   '//suite%name//' / '//tests(i)%name
         end if
         flush (output_unit)
      end do
   end subroutine run_suite
end module xcable_testing
