!> Instructions per call of fast_tan and of the intrinsic (glibc) tan, for callgrind:
!>
!>     gfortran -O3 -funroll-loops -fno-tree-vectorize src/xcable/core/kinds.f90 \
!>        src/xcable/numerics/tan.f90 bench/tan/cost.f90 -o /tmp/tan_cost
!>     valgrind --tool=callgrind /tmp/tan_cost <family> <which>
!>
!> family 1: the rods' arguments (|x| log-uniform in [1e-6, 0.05], either sign),
!> 2: uniform in [-pi/2, pi/2], 3: |x| in [1/16, pi/4], 4: |x| in [pi/4, pi/2];
!> which: fast or libm. The inclusive cost of fast_tan (or of tan) over its 10^6
!> calls is the figure (callgrind_annotate --inclusive=yes). -fno-tree-vectorize:
!> gfortran otherwise calls libmvec's vector tan in the loop over the intrinsic.
program tan_cost
   use xcable_core_kinds, only: dp
   use xcable_numerics_tan, only: fast_tan
   implicit none
   integer, parameter :: n = 1000000
   real(dp), parameter :: half_pi = 1.5707963267948966_dp, quarter_pi = 0.7853981633974483_dp
   real(dp), allocatable :: x(:), v(:, :)
   real(dp) :: total
   integer :: family, i
   character(len=8) :: arg, which
   call get_command_argument(1, arg)
   read (arg, *) family
   call get_command_argument(2, which)
   allocate (x(n), v(2, n))
   call random_number(v)
   select case (family)
   case (1)
      x = 1e-6_dp*(0.05_dp/1e-6_dp)**v(1, :)
   case (2)
      x = half_pi*v(1, :)
   case (3)
      x = 0.0625_dp + (quarter_pi - 0.0625_dp)*v(1, :)
   case default
      x = quarter_pi + (half_pi - quarter_pi)*v(1, :)
   end select
   x = sign(x, v(2, :) - 0.5_dp)
   total = 0
   if (which == 'fast') then
      do i = 1, n
         total = total + fast_tan(x(i))
      end do
   else
      do i = 1, n
         total = total + tan(x(i))
      end do
   end if
   print *, total
end program tan_cost
