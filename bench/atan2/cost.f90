!> Instructions per call of fast_atan2 and of the intrinsic (glibc) atan2, for callgrind:
!>
!>     gfortran -O3 -funroll-loops src/xcable/core/kinds.f90 src/xcable/numerics/atan2.f90 \
!>        bench/atan2/cost.f90 -o /tmp/atan2_cost
!>     valgrind --tool=callgrind /tmp/atan2_cost <family> <which>
!>
!> family 1: the rod's arguments (x in [0.9, 1.1], |y| log-uniform in [1e-6, 0.05]),
!> 2: uniform angles in all quadrants, 3: t = |y|/|x| in [1/16, 1], x > 0;
!> which: fast or libm. The inclusive cost of fast_atan2 (or of atan2 with its wrapper)
!> over its 10^6 calls is the figure (callgrind_annotate --inclusive=yes).
program atan2_cost
   use xcable_core_kinds, only: dp
   use xcable_numerics_atan2, only: fast_atan2
   implicit none
   integer, parameter :: n = 1000000
   real(dp), allocatable :: y(:), x(:), v(:, :)
   real(dp) :: total
   integer :: family, i
   character(len=8) :: arg, which
   call get_command_argument(1, arg)
   read (arg, *) family
   call get_command_argument(2, which)
   allocate (y(n), x(n), v(3, n))
   call random_number(v)
   select case (family)
   case (1)
      x = 0.9_dp + 0.2_dp*v(1, :)
      y = sign(1e-6_dp*(0.05_dp/1e-6_dp)**v(2, :), v(3, :) - 0.5_dp)
   case (2)
      x = cos((2*v(1, :) - 1)*acos(-1.0_dp))
      y = sin((2*v(1, :) - 1)*acos(-1.0_dp))
   case default
      x = 1 + v(1, :)
      y = x*(0.0625_dp + 0.9375_dp*v(2, :))
   end select
   total = 0
   if (which == 'fast') then
      do i = 1, n
         total = total + fast_atan2(y(i), x(i))
      end do
   else
      do i = 1, n
         total = total + atan2(y(i), x(i))
      end do
   end if
   print *, total
end program atan2_cost
