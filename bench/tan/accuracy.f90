!> Accuracy of fast_tan (src/xcable/numerics/tan.f90) and of the intrinsic (glibc) tan
!> against tan in quad precision (libquadmath), in units in the last place:
!>
!>     gfortran -O2 src/xcable/core/kinds.f90 src/xcable/numerics/tan.f90 bench/tan/accuracy.f90 \
!>        -o /tmp/tan_accuracy && /tmp/tan_accuracy [arguments per family, default 2000000]
!>
!> (docs/measurements/data/speed_rounds.md quotes a run with 1500000: 1.2e7 arguments.)
!>
!> Per family of arguments: the share not correctly rounded (the quad value rounded to
!> double taken as the correctly rounded one), the largest and the mean distance from
!> the exact value in units of the last place of the correctly rounded value, for
!> fast_tan and for tan. Each argument gets a random sign.
program tan_accuracy
   use xcable_core_kinds, only: dp
   use xcable_numerics_tan, only: fast_tan
   use, intrinsic :: iso_fortran_env, only: int64, real128
   implicit none
   integer, parameter :: qp = real128
   real(dp), parameter :: half_pi = 1.5707963267948966_dp
   character(len=*), parameter :: names(8) = [character(len=44) :: &
      'uniform in [0, pi/2]', 'log-uniform |x| in [2^-30, pi/2]', &
      'the rods: log-uniform |x| in [1e-8, 0.1]', 'pi/2 - k ulp, k log-uniform in [0, 2^30]', &
      'within 2^-40 of 1/16 and pi/4', 'random bit patterns below pi/2', &
      'uniform in [1/16, pi/4]', 'uniform in [pi/4, pi/2]']
   integer(int64) :: state, n, k, bad(2), d
   integer :: family
   real(dp) :: x, v(3), rounded, got(2), units, worst(2), mean(2), at(2)
   real(qp) :: exact
   character(len=32) :: arg
   n = 2000000
   if (command_argument_count() >= 1) then
      call get_command_argument(1, arg)
      read (arg, *) n
   end if
   state = 20261202_int64
   write (*, '(a)') '| arguments | fast_tan: not correctly rounded | worst | mean | at | '// &
      'glibc: not correctly rounded | worst | mean |'
   write (*, '(a)') '|---|---:|---:|---:|---:|---:|---:|---:|'
   do family = 1, 8
      bad = 0
      worst = 0
      mean = 0
      at = 0
      do k = 1, n
         v = [uniform(state), uniform(state), uniform(state)]
         select case (family)
         case (1)
            x = half_pi*v(1)
         case (2)
            x = half_pi*2.0_dp**(-30*v(1))
         case (3)
            x = 1e-8_dp*(0.1_dp/1e-8_dp)**v(1)
         case (4)
            x = half_pi
            x = transfer(transfer(x, 0_int64) - int(2.0_dp**(30*v(1)) - 1, int64), x)
         case (5)
            x = merge(0.0625_dp, 0.7853981633974483_dp, v(2) < 0.5_dp)*(1 + (v(1) - 0.5_dp)*2.0_dp**(-40))
         case (6)
            x = transfer(int(v(1)*real(transfer(half_pi, 0_int64), dp), int64), x)
         case (7)
            x = 0.0625_dp + (0.7853981633974483_dp - 0.0625_dp)*v(1)
         case default
            x = 0.7853981633974483_dp + (half_pi - 0.7853981633974483_dp)*v(1)
         end select
         if (v(3) < 0.5_dp) x = -x
         exact = tan(real(x, qp))
         rounded = real(exact, dp)
         got = [fast_tan(x), tan(x)]
         do d = 1, 2
            if (got(d) /= rounded) bad(d) = bad(d) + 1
            if (rounded == 0) cycle
            units = real(abs((real(got(d), qp) - exact)/real(spacing(rounded), qp)), dp)
            mean(d) = mean(d) + units
            if (units > worst(d)) then
               worst(d) = units
               if (d == 1) at(1) = x
            end if
         end do
      end do
      write (*, '(a,a,f7.4,a,f6.3,a,f6.3,a,es13.6,a,f7.4,a,f6.3,a,f6.3,a)') '| '//trim(names(family)), &
         ' | ', 100*real(bad(1), dp)/n, ' % | ', worst(1), ' | ', mean(1)/n, ' | ', at(1), &
         ' | ', 100*real(bad(2), dp)/n, ' % | ', worst(2), ' | ', mean(2)/n, ' |'
   end do

contains

   real(dp) function uniform(state)
      integer(int64), intent(inout) :: state
      state = state*6364136223846793005_int64 + 1442695040888963407_int64
      uniform = real(shiftr(state, 11), dp)*2.0_dp**(-53)
   end function uniform

end program tan_accuracy
