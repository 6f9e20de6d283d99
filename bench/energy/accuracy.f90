!> Accuracy of the tanh law's strain energy W(eps) (src/xcable/material/law.f90,
!> tanh_strain_energy) against W in quad precision, for the paper's coefficients:
!> the code's W, and the form it had before (for p2 |eps| < 1 the change from W(0) = 0,
!> 2 (p1/p2) atanh(tanh(p2 eps/2 + p3) tanh(p2 eps/2)) + (p4 + p5 eps/2) eps, with
!> law_tanh and law_atanh), in units in the last place of max(|W|, |f(0) eps|) (W
!> crosses zero at eps = 5.5e-4, where f(0) eps, the linear term, is its scale):
!>
!>     gfortran -O2 src/xcable/core/kinds.f90 src/xcable/core/error.f90 src/xcable/material/elementary.f90 \
!>        src/xcable/material/law.f90 bench/energy/accuracy.f90 -o /tmp/energy_accuracy
!>     /tmp/energy_accuracy [arguments per family, default 1000000]
program energy_accuracy
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type
   use xcable_material_law, only: material_law, new_law, paper_tanh_coefficients
   use xcable_material_elementary, only: law_tanh, law_atanh
   use, intrinsic :: iso_fortran_env, only: int64, real128
   implicit none
   integer, parameter :: qp = real128
   character(len=*), parameter :: names(4) = [character(len=40) :: &
      'log-uniform eps in [1e-10, 0.098]', 'log-uniform eps in [-0.098, -1e-10]', &
      'uniform eps in [-0.098, 0.098]', 'uniform eps in [0.098, 0.35] (unchanged)']
   class(material_law), allocatable :: law
   type(error_type), allocatable :: error
   real(dp) :: p(5), eps, f0, w(2), units, worst(2), mean(2), at(2), v(2)
   real(qp) :: exact, pq(5)
   integer(int64) :: state, n, k
   integer :: family, j
   character(len=32) :: arg
   n = 1000000
   if (command_argument_count() >= 1) then
      call get_command_argument(1, arg)
      read (arg, *) n
   end if
   p = paper_tanh_coefficients
   pq = real(p, qp)
   call new_law(law, 'tanh', p, 1.0_dp, 0.35_dp, error)
   f0 = law%tension(0.0_dp)
   state = 20261202_int64
   write (*, '(a)') '| strains | new: worst | mean | at | old: worst | mean | at |'
   write (*, '(a)') '|---|---:|---:|---:|---:|---:|---:|'
   do family = 1, 4
      worst = 0
      mean = 0
      at = 0
      do k = 1, n
         v = [uniform(state), uniform(state)]
         select case (family)
         case (1)
            eps = 1e-10_dp*(0.098_dp/1e-10_dp)**v(1)
         case (2)
            eps = -1e-10_dp*(0.098_dp/1e-10_dp)**v(1)
         case (3)
            eps = 0.098_dp*(2*v(1) - 1)
         case default
            eps = 0.098_dp + (0.35_dp - 0.098_dp)*v(1)
         end select
         exact = pq(1)/pq(2)*(log(cosh(pq(2)*eps + pq(3))) - log(cosh(pq(3)))) + pq(4)*eps + pq(5)*eps**2/2
         w(1) = law%strain_energy(eps)
         w(2) = old_w(eps)
         do j = 1, 2
            units = real(abs((real(w(j), qp) - exact)/real(spacing(max(abs(real(exact, dp)), &
                                                                          abs(f0*eps))), qp)), dp)
            mean(j) = mean(j) + units
            if (units > worst(j)) then
               worst(j) = units
               at(j) = eps
            end if
         end do
      end do
      write (*, '(a,2(a,f9.2,a,f8.3,a,es10.3),a)') '| '//trim(names(family)), &
         (' | ', worst(j), ' | ', mean(j)/n, ' | ', at(j), j=1, 2), ' |'
   end do

contains

   !> The form before: for p2 |eps| < 1 the change from W(0) = 0; above, W itself.
   real(dp) function old_w(eps)
      real(dp), intent(in) :: eps
      real(dp) :: tm, td
      if (abs(p(2)*eps) < 1) then
         tm = law_tanh(p(2)*(0.5_dp*eps) + p(3))
         td = law_tanh(0.5_dp*p(2)*eps)
         old_w = 2*p(1)/p(2)*law_atanh(tm*td) + (p(4) + p(5)*(0.5_dp*eps))*eps
      else
         old_w = law%strain_energy(eps)
      end if
   end function old_w

   real(dp) function uniform(state)
      integer(int64), intent(inout) :: state
      state = state*6364136223846793005_int64 + 1442695040888963407_int64
      uniform = real(shiftr(state, 11), dp)*2.0_dp**(-53)
   end function uniform

end program energy_accuracy
