!> The analytic Jacobian of the discrete equations against a central
!> finite-difference Jacobian, entry by entry, for statics and for a time step
!> at a state with non-zero velocities, shear and curvature.
module suite_jacobian
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_fixtures, only: paper_case
   use xcable_box_equations, only: cable_model, n_eq, equation_terms, equation_derivatives, mass_times
   use xcable_solver_newton, only: newton_options, newton_workspace
   use xcable_box_dynamics, only: dynamics_options
   use xcable_box_discrete, only: box_system
   use xcable_box_statics, only: catenary_guess
   use xcable_theory_closed_forms, only: wave_speed
   implicit none
   private
   public :: collect_jacobian

   character(len=6), parameter :: names(n_eq) = ['eps   ', 'Sn    ', 'u     ', 'v     ', 'beta0 ', 'beta3 ', 'Omega3']

contains

   subroutine collect_jacobian(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('node_derivatives', test_node_derivatives), &
               new_unittest('static_jacobian', test_static), &
               new_unittest('dynamic_jacobian_theta_half', test_dynamic_half), &
               new_unittest('dynamic_jacobian_theta_0.7', test_dynamic_damped)]
   end subroutine collect_jacobian

   !> A state with every unknown non-trivial (7, nodes).
   subroutine lively_state(model, s, tension, y, phase)
      type(cable_model), intent(in) :: model
      real(dp), intent(in) :: s(:), tension, phase
      real(dp), intent(out) :: y(:, :)
      type(error_type), allocatable :: error
      real(dp) :: angle
      integer :: k
      call catenary_guess(model, s, tension, y, error)
      do k = 1, size(s)
         y(1, k) = y(1, k) + 0.01_dp*sin(0.3_dp*k + phase)
         y(2, k) = 350*cos(0.7_dp*k + phase)
         y(3, k) = 12*sin(0.4_dp*k + phase)
         y(4, k) = 2.5_dp*cos(0.9_dp*k + phase)
         angle = 2*atan2(y(6, k), y(5, k)) + 0.05_dp*sin(0.5_dp*k + phase)
         y(5, k) = cos(0.5_dp*angle)*(1 + 0.002_dp*sin(k + phase))
         y(6, k) = sin(0.5_dp*angle)
         y(7, k) = 0.08_dp*sin(0.6_dp*k + phase)
      end do
   end subroutine lively_state

   !> d(M z)/dY and dP/dY at one node against central differences.
   subroutine test_node_derivatives(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      real(dp) :: y(n_eq, 5), z(n_eq), dmz(n_eq, n_eq), dp_(n_eq, n_eq), mass(n_eq, n_eq), p1(n_eq), p2(n_eq)
      real(dp) :: yp(n_eq), ym(n_eq), h, fd(n_eq), mz(n_eq)
      integer :: j, i
      call paper_case(180.0e3_dp, 5, model, s, newton, dyn, error)
      if (allocated(error)) return
      call lively_state(model, s, 180.0e3_dp, y, 0.3_dp)
      z = [1.0e-3_dp, 20.0_dp, 0.5_dp, -0.2_dp, 3.0e-3_dp, -2.0e-3_dp, 1.0e-3_dp]
      call equation_derivatives(model, y(:, 3), z, dmz, dp_)
      call equation_terms(model, y(:, 3), mass, p1)
      mz = mass_times(model, y(:, 3), z)
      if (maxval(abs(mz - matmul(mass, z))) > 1.0e-12_dp*maxval(abs(mz))) then
         call fatal_error(error, 'mass_times differs from M z')
         return
      end if
      do j = 1, n_eq
         h = 1.0e-6_dp*max(abs(y(j, 3)), merge(1.0e3_dp, 1.0e-2_dp, j == 2))
         yp = y(:, 3); yp(j) = yp(j) + h
         ym = y(:, 3); ym(j) = ym(j) - h
         fd = (mass_times(model, yp, z) - mass_times(model, ym, z))/(2*h)
         do i = 1, n_eq
            if (abs(fd(i) - dmz(i, j)) > 1.0e-6_dp*max(abs(fd(i)), 1.0e-8_dp)) then
               call fatal_error(error, 'd(M z)/dY row '//str(i)//', '//trim(names(j))//': analytic '// &
                                str(dmz(i, j))//', finite difference '//str(fd(i)))
               return
            end if
         end do
         call equation_terms(model, yp, mass, p1)
         call equation_terms(model, ym, mass, p2)
         fd = (p1 - p2)/(2*h)
         do i = 1, n_eq
            if (abs(fd(i) - dp_(i, j)) > 1.0e-6_dp*max(abs(fd(i)), 1.0e-8_dp)) then
               call fatal_error(error, 'dP/dY row '//str(i)//', '//trim(names(j))//': analytic '// &
                                str(dp_(i, j))//', finite difference '//str(fd(i)))
               return
            end if
         end do
      end do
   end subroutine test_node_derivatives

   !> Compare the band Jacobian of a system at x with central differences.
   subroutine compare_jacobian(error, system, x, label)
      type(error_type), allocatable, intent(out) :: error
      type(box_system), intent(inout) :: system
      real(dp), intent(inout) :: x(:)
      character(*), intent(in) :: label
      type(newton_workspace) :: work
      real(dp), allocatable :: r0(:), rp(:), rm(:), scale(:), fd(:, :)
      real(dp) :: h, saved, analytic, row_max, tol
      integer :: n, kl, ku, i, j, ne, nk, checked
      n = size(x)
      call system%band_widths(kl, ku)
      scale = system%unknown_scale()
      call work%init(n, kl, ku, scale)
      allocate (r0(n), rp(n), rm(n), fd(n, n))
      call system%evaluate(x, r0, work%jacobian, .true.)
      do j = 1, n
         h = 1.0e-6_dp*max(abs(x(j)), scale(j))
         saved = x(j)
         x(j) = saved + h
         call system%evaluate(x, rp, work%jacobian, .false.)
         x(j) = saved - h
         call system%evaluate(x, rm, work%jacobian, .false.)
         x(j) = saved
         fd(:, j) = (rp - rm)/(2*h)*scale(j)
      end do
      call system%evaluate(x, r0, work%jacobian, .true.)
      checked = 0
      do i = 1, n
         row_max = maxval(abs(fd(i, :)))
         do j = 1, n
            if (j >= i - kl .and. j <= i + ku) then
               analytic = work%jacobian%ab(work%jacobian%row(i, j), j)*scale(j)
            else
               analytic = 0
            end if
            tol = 1.0e-6_dp*max(row_max, 1.0e-10_dp)
            if (abs(analytic - fd(i, j)) > tol) then
               ne = mod(j - 1, n_eq) + 1
               nk = (j - 1)/n_eq + 1
               call fatal_error(error, label//': entry ('//str(i)//', '//str(j)//') = d(row '//str(i)//')/d('// &
                                trim(names(ne))//' at node '//str(nk)//'): analytic '//str(analytic/scale(j))// &
                                ', finite difference '//str(fd(i, j)/scale(j)))
               return
            end if
            if (fd(i, j) /= 0) checked = checked + 1
         end do
      end do
      call check(error, checked > 3*n, label//': too few non-zero entries compared ('//str(checked)//')')
   end subroutine compare_jacobian

   subroutine test_static(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:), x(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(box_system) :: system
      real(dp) :: y(n_eq, 6)
      call paper_case(180.0e3_dp, 6, model, s, newton, dyn, error)
      if (allocated(error)) return
      call lively_state(model, s, 180.0e3_dp, y, 0.0_dp)
      y(3:4, :) = 0.1_dp*y(3:4, :)
      call system%init(model, s, .false., 180.0e3_dp, wave_speed(model%law, model%mass, 0.178_dp), 1.0_dp)
      x = reshape(y, [size(y)])
      call compare_jacobian(error, system, x, 'static')
   end subroutine test_static

   subroutine dynamic_case(error, theta)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in) :: theta
      type(cable_model) :: model
      real(dp), allocatable :: s(:), x(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(box_system) :: system
      real(dp) :: y_old(n_eq, 6), y(n_eq, 6)
      call paper_case(315.0e3_dp, 6, model, s, newton, dyn, error)
      if (allocated(error)) return
      call lively_state(model, s, 315.0e3_dp, y_old, 0.0_dp)
      call lively_state(model, s, 315.0e3_dp, y, 0.2_dp)
      call system%init(model, s, .true., 315.0e3_dp, wave_speed(model%law, model%mass, 0.228_dp), theta)
      system%omega_fixed = 1.0e-4_dp
      system%omega_free = -2.0e-4_dp
      call system%prepare_step(y_old, 2.0e-4_dp, 1.5e5_dp, -2.0e3_dp)
      x = reshape(y, [size(y)])
      call compare_jacobian(error, system, x, 'dynamic, theta = '//str(theta))
   end subroutine dynamic_case

   subroutine test_dynamic_half(error)
      type(error_type), allocatable, intent(out) :: error
      call dynamic_case(error, 0.5_dp)
   end subroutine test_dynamic_half

   subroutine test_dynamic_damped(error)
      type(error_type), allocatable, intent(out) :: error
      call dynamic_case(error, 0.7_dp)
   end subroutine test_dynamic_damped
end module suite_jacobian
