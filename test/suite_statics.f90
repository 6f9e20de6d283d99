!> The static state against the exact extensible catenary: the tanh law by
!> quadrature (180 kN, 315 kN and a slack 2 kN case with a sag of metres) and
!> the linear law in closed form (Irvine's elastic catenary), with a
!> refinement study that shows second-order convergence; and the quadratic
!> convergence of Newton's iteration.
module suite_statics
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_strings, only: str
   use xcable_core_error, only: stat_input
   use xcable_fixtures, only: paper_case
   use xcable_box_equations, only: cable_model, i_eps, i_sn
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options
   use xcable_box_statics, only: static_state, solve_statics
   use xcable_theory_closed_forms, only: catenary_summary, catenary_shape, horizontal_force, wave_speed
   use xcable_material_law, only: material_law, tanh_law, linear_law, strain_kept
   use xcable_material_table, only: table_law, new_table_law
   use xcable_material_tension_only, only: new_tension_only
   use xcable_core_kinds, only: i8
   use xcable_box_statics, only: catenary_guess
   use xcable_box_discrete, only: box_system
   use xcable_solver_newton, only: newton_workspace, newton_report, newton_solve
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_statics, static_errors

   integer, parameter :: ladder(4) = [31, 61, 121, 241]

contains

   subroutine collect_statics(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('catenary_180kN', test_180), &
               new_unittest('catenary_315kN', test_315), &
               new_unittest('catenary_slack_2kN', test_slack), &
               new_unittest('irvine_linear_law', test_irvine), &
               new_unittest('newton_quadratic', test_newton_quadratic), &
               new_unittest('newton_quadratic_far_guess', test_newton_far), &
               new_unittest('tension_too_small', test_too_small), &
               new_unittest('kept_inverse_same_bits', test_kept_inverse)]
   end subroutine collect_statics

   !> Relative errors of span, sag, end angle and mid-span strain against the
   !> exact catenary, at a number of nodes.
   subroutine static_errors(tension, nodes, err, error, law)
      real(dp), intent(in) :: tension
      integer, intent(in) :: nodes
      real(dp), intent(out) :: err(4)
      type(error_type), allocatable, intent(out) :: error
      character(*), intent(in), optional :: law
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      real(dp) :: span, sag, angle, mid
      call paper_case(tension, nodes, model, s, newton, dyn, error, law=law)
      if (allocated(error)) return
      call solve_statics(model, s, tension, newton, state, error)
      if (allocated(error)) return
      call catenary_summary(model%law, model%weight, model%length, tension, span, sag, angle, mid, error)
      if (allocated(error)) return
      err(1) = (state%span - span)/span
      err(2) = (state%sag - sag)/sag
      err(3) = (state%end_angle - angle)/angle
      err(4) = (state%y(i_eps, (nodes + 1)/2) - mid)/mid
   end subroutine static_errors

   !> Refinement study: errors fall at second order and the finest is small.
   subroutine refinement(error, tension, finest_bound)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in) :: tension
      !> Bound on the relative errors at 241 nodes (span, sag, angle, strain).
      real(dp), intent(in) :: finest_bound(4)
      real(dp) :: err(4, size(ladder)), order
      character(len=12), parameter :: what(4) = [character(len=12) :: 'span', 'sag', 'end angle', 'mid strain']
      integer :: i, q, n
      do i = 1, size(ladder)
         call static_errors(tension, ladder(i), err(:, i), error)
         if (allocated(error)) return
      end do
      write (output_unit, '(4x,a,f9.0,a)') 'statics at ', tension, ' N: relative errors against the exact catenary'
      write (output_unit, '(4x,a6,4a14)') 'nodes', (trim(what(q)), q=1, 4)
      do i = 1, size(ladder)
         write (output_unit, '(4x,i6,4es14.3)') ladder(i), err(:, i)
      end do
      ! Observed order from the differences of successive grids, which holds
      ! also where bending (absent from the catenary) leaves an error floor.
      do q = 1, 4
         n = size(ladder)
         if (abs(err(q, n - 1) - err(q, n)) < 1.0e-12_dp) cycle
         order = log(abs((err(q, n - 2) - err(q, n - 1))/(err(q, n - 1) - err(q, n))))/log(2.0_dp)
         write (output_unit, '(4x,a,a,f6.2)') trim(what(q)), ': observed order ', order
         call check(error, order > 1.8_dp .and. order < 2.2_dp, trim(what(q))//' converges at order '//str(order)// &
                    ', expected 2')
         if (allocated(error)) return
         call check(error, abs(err(q, n)) <= finest_bound(q), trim(what(q))//' error at 241 nodes '// &
                    str(err(q, n))//' exceeds '//str(finest_bound(q)))
         if (allocated(error)) return
      end do
   end subroutine refinement

   subroutine test_180(error)
      type(error_type), allocatable, intent(out) :: error
      call refinement(error, 180.0e3_dp, [3.0e-10_dp, 1.5e-9_dp, 6.0e-10_dp, 1.0e-13_dp])
   end subroutine test_180

   subroutine test_315(error)
      type(error_type), allocatable, intent(out) :: error
      call refinement(error, 315.0e3_dp, [1.0e-10_dp, 5.0e-10_dp, 2.0e-10_dp, 1.0e-13_dp])
   end subroutine test_315

   subroutine test_slack(error)
      type(error_type), allocatable, intent(out) :: error
      call refinement(error, 2.0e3_dp, [1.0e-6_dp, 4.0e-5_dp, 5.0e-6_dp, 1.0e-6_dp])
   end subroutine test_slack

   !> Linear law T = EA eps: span = H L / EA + (2 H / w) asinh(w L / (2 H)),
   !> sag = (H / w) (sqrt(1 + (w L / (2 H))^2) - 1) + w L^2 / (8 EA).
   subroutine test_irvine(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      real(dp) :: h, w, l, ea, span, sag, err(2, 3), order(2)
      integer :: i
      real(dp), parameter :: tension = 5.0e3_dp
      do i = 1, 3
         call paper_case(tension, 30*2**i + 1, model, s, newton, dyn, error, law='linear')
         if (allocated(error)) return
         call solve_statics(model, s, tension, newton, state, error)
         if (allocated(error)) return
         w = model%weight
         l = model%length
         ea = model%law%tension(1.0_dp)
         call horizontal_force(w, l, tension, h, error)
         span = h*l/ea + 2*h/w*asinh(w*l/(2*h))
         sag = h/w*(sqrt(1 + (w*l/(2*h))**2) - 1) + w*l*l/(8*ea)
         err(:, i) = [(state%span - span)/span, (state%sag - sag)/sag]
      end do
      order = log(abs((err(:, 1) - err(:, 2))/(err(:, 2) - err(:, 3))))/log(2.0_dp)
      write (output_unit, '(4x,a,2es12.3,a,2f6.2)') 'Irvine (linear law, 5 kN): relative errors of span, sag at 241 nodes', &
         err(:, 3), '; observed orders', order
      call check(error, all(abs(err(:, 3)) < 3.0e-6_dp), 'span or sag differs from the closed form by more than 3e-6')
      if (allocated(error)) return
      call check(error, all(order > 1.8_dp .and. order < 2.2_dp), 'Irvine: observed order not 2: '//str(order(1))// &
                 ', '//str(order(2)))
   end subroutine test_irvine

   !> The update norms of Newton fall quadratically: d(k+1) <= C d(k)^2.
   subroutine test_newton_quadratic(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      real(dp) :: d(100), ratio
      integer :: k, n, tested
      call paper_case(2.0e3_dp, 121, model, s, newton, dyn, error)
      if (allocated(error)) return
      newton%tolerance = 1.0e-13_dp
      call solve_statics(model, s, 2.0e3_dp, newton, state, error)
      if (allocated(error)) return
      n = state%newton%iterations
      d = state%newton%update_norm
      write (output_unit, '(4x,a,*(es10.2))') 'Newton update norms (slack case):', d(1:n)
      write (output_unit, '(4x,a,*(es10.2))') 'scaled residual norms:          ', state%newton%residual_norm(0:n)
      tested = 0
      do k = 1, n - 1
         if (d(k) > 1.0e-1_dp .or. d(k + 1) < 1.0e-12_dp) cycle
         ratio = d(k + 1)/d(k)**2
         call check(error, ratio < 1.0e2_dp, 'update '//str(k + 1)//' = '//str(d(k + 1))//' is not quadratic in '// &
                    str(d(k)))
         if (allocated(error)) return
         tested = tested + 1
      end do
      call check(error, tested >= 1 .and. n >= 3, 'too few iterations to see the convergence rate')
   end subroutine test_newton_quadratic

   !> From a guess far from the solution (strain 20 % off, shear 1 kN, the
   !> angle and curvature off), the scaled residual falls quadratically once
   !> Newton is close: r(k+1) <= C r(k)^2. Measured C is up to about 60 in this
   !> max-norm of scaled rows; C <= 100 still refuses linear convergence (at
   !> r = 1e-6 it would need a contraction factor below 1e-4).
   subroutine test_newton_far(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      real(dp), allocatable :: s(:), x(:), y(:, :)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(box_system) :: system
      type(newton_workspace) :: work
      type(newton_report) :: report
      real(dp) :: r(0:100)
      integer :: kl, ku, k, n, tested
      call paper_case(180.0e3_dp, 61, model, s, newton, dyn, error)
      if (allocated(error)) return
      allocate (y(7, size(s)))
      call catenary_guess(model, s, 180.0e3_dp, y, error)
      if (allocated(error)) return
      y(i_eps, :) = 1.2_dp*y(i_eps, :)
      y(i_sn, :) = 1.0e3_dp
      y(5, :) = y(5, :) + 0.02_dp
      y(7, :) = 3*y(7, :)
      call system%init(model, s, .false., 180.0e3_dp, wave_speed(model%law, model%mass, 0.178_dp), 1.0_dp)
      call system%band_widths(kl, ku)
      call work%init(size(y), kl, ku, system%unknown_scale())
      newton%tolerance = 1.0e-14_dp
      x = reshape(y, [size(y)])
      call newton_solve(system, x, work, newton, report, error)
      if (allocated(error)) return
      n = report%iterations
      r = report%residual_norm
      write (output_unit, '(4x,a,*(es9.1))') 'Newton from a far guess, scaled residual norms:', r(0:n)
      tested = 0
      do k = 0, n - 1
         if (r(k) > 1.0e-2_dp .or. r(k + 1) < 1.0e-13_dp) cycle
         call check(error, r(k + 1) <= 100*r(k)**2, 'residual '//str(r(k + 1))//' after '//str(r(k))// &
                    ' is not quadratic')
         if (allocated(error)) return
         tested = tested + 1
      end do
      call check(error, tested >= 2, 'fewer than two iterations in the quadratic range ('//str(tested)//')')
   end subroutine test_newton_far

   !> A tension that cannot hold the cable's weight is refused, as bad input
   !> naming the tension and the limit.
   subroutine test_too_small(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: refused
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      call paper_case(600.0_dp, 21, model, s, newton, dyn, refused)
      call check(error, allocated(refused), 'a tension below w0 L / 2 was accepted')
      if (allocated(error)) return
      call check(error, refused%stat == stat_input .and. index(refused%message, 'tension = 600') > 0 .and. &
                 index(refused%message, 'w0 L / 2') > 0, 'unexpected refusal: '//refused%message)
   end subroutine test_too_small

   !> strain_at with kept values (the statics' first guess inverts the law with the
   !> values at the starting points kept) gives strain_at's bits without them, for the tanh, linear and table
   !> laws and the tanh law without compression, one kept per law over tensions from
   !> -1e6 N to 3e6 N (far beyond the tables and the saturation of the tanh law, so that
   !> the brackets widen many times), zero among them.
   subroutine test_kept_inverse(error)
      type(error_type), allocatable, intent(out) :: error
      type(table_law) :: table
      call new_table_law([-0.02_dp, 0.0_dp, 0.05_dp, 0.2_dp, 0.4_dp], [-5.0e3_dp, 0.0_dp, 6.0e4_dp, 3.0e5_dp, 9.0e5_dp], &
                         table, error)
      if (allocated(error)) return
      call compare(tanh_law(), 'tanh')
      if (allocated(error)) return
      call compare(linear_law(ea=4.5e5_dp), 'linear')
      if (allocated(error)) return
      call compare(table, 'table')
      if (allocated(error)) return
      call compare(new_tension_only(tanh_law()), 'tanh without compression')
   contains
      subroutine compare(law, name)
         class(material_law), intent(in) :: law
         character(*), intent(in) :: name
         type(strain_kept) :: kept
         real(dp) :: t, a, b
         integer :: i, n_same
         n_same = 0
         do i = -400, 1200
            t = 2500.0_dp*i + 0.37_dp*modulo(i*7919, 1000)
            a = law%strain_at(t)
            b = law%strain_at(t, kept)
            if (transfer(a, 0_i8) == transfer(b, 0_i8)) n_same = n_same + 1
            if (transfer(a, 0_i8) /= transfer(b, 0_i8)) then
               call check(error, .false., name//': at T = '//str(t)//' N strain_at gives '//str(a)// &
                          ', with kept values '//str(b))
               return
            end if
         end do
         call check(error, n_same == 1601 .and. kept%n > 4, name//': '//str(n_same)//' of 1601 compared, '// &
                    str(kept%n)//' values kept')
      end subroutine compare
   end subroutine test_kept_inverse

end module suite_statics
