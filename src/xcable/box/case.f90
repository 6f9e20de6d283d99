!> From a validated `case_config` to the objects of the computation: the
!> cable model, the grid and the controls of statics and dynamics. The checks
!> that need the material law (the static strain within the law's documented
!> range, a tension that can hold the cable) are made here, before any solve.
module xcable_box_case
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_input
   use xcable_core_strings, only: str
   use xcable_io_input, only: case_config, max_time_steps, derive_defaults
   use xcable_material_factory, only: new_law
   use xcable_box_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options
   use xcable_theory_closed_forms, only: wave_speed
   implicit none
   private
   public :: setup_case

contains

   !> Build the model, grid and controls of a case.
   subroutine setup_case(validated, model, s, newton, dynamics, error)
      !> Validated case (a zero area, EI or EA is derived as read_config does).
      type(case_config), intent(in) :: validated
      !> Cable data.
      type(cable_model), intent(out) :: model
      !> Node arc lengths (uniform grid), m.
      real(dp), allocatable, intent(out) :: s(:)
      !> Newton controls.
      type(newton_options), intent(out) :: newton
      !> Controls of the time stepping.
      type(dynamics_options), intent(out) :: dynamics
      !> Error (class stat_input) naming the variable at fault.
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      real(dp) :: eps_static, half_weight, ds
      integer :: k

      config = validated
      call derive_defaults(config)
      call new_law(model%law, trim(config%law), config%p, config%ea, config%strain_max, error)
      if (allocated(error)) then
         call prefix_error(error, config%source//': &material: ')
         return
      end if
      model%mass = config%density*config%area
      model%weight = model%mass*config%gravity
      model%bending_stiffness = config%bending_stiffness
      model%length = config%length

      half_weight = 0.5_dp*model%weight*model%length
      if (config%tension <= 1.001_dp*half_weight) then
         call fatal_error(error, config%source//': &static: tension = '//str(config%tension)// &
                          ': must exceed half the weight of the cable, w0 L / 2 = '//str(half_weight)//' N', stat_input)
         return
      end if
      eps_static = model%law%strain_at(config%tension)
      if (eps_static > config%strain_max) then
         call fatal_error(error, config%source//': &static: tension = '//str(config%tension)//': needs strain '// &
                          str(eps_static)//', above the range of the '//trim(config%law)//' law (strain_max = '// &
                          str(config%strain_max)//', tension '//str(model%law%tension(config%strain_max))//' N)', &
                          stat_input)
         return
      end if

      allocate (s(config%nodes))
      do k = 1, config%nodes
         s(k) = config%length*real(k - 1, dp)/(config%nodes - 1)
      end do
      ds = s(2) - s(1)

      newton%tolerance = config%newton_tol
      newton%max_iterations = config%newton_max_iter
      newton%reuse_jacobian = config%reuse_jacobian

      dynamics%t_break = config%t_break
      dynamics%t_end = config%t_end
      if (config%dt > 0) then
         dynamics%dt = config%dt
      else
         dynamics%dt = config%courant*ds/wave_speed(model%law, model%mass, eps_static)
         if (.not. (config%t_end/dynamics%dt <= max_time_steps)) then
            call fatal_error(error, config%source//': &numerics: courant = '//str(config%courant)//': gives dt = '// &
                             str(dynamics%dt)//' s (ds = '//str(ds)//' m, c(eps0) = '// &
                             str(wave_speed(model%law, model%mass, eps_static))//' m/s), more than '// &
                             str(max_time_steps)//' steps to t_end = '//str(config%t_end)//' s', stat_input)
            return
         end if
         ! Steps are uniform within each snapshot interval (dynamics). Fit a whole
         ! number of steps into the interval by rounding the step up, so that the
         ! Courant number at eps0 is the requested one or slightly above: below 1
         ! the box scheme's shortest waves run ahead of the front (up to c /
         ! lambda^2), and a step rounded down (lambda = 0.98 at 241 nodes) brings
         ! the 1 % tension drop at the fixed end 0.14 ms early instead of 0.03 ms
         ! late (docs/measurements/benchmark.md).
         if (config%interval >= dynamics%dt) then
            dynamics%dt = config%interval/floor(config%interval/dynamics%dt*(1 + 1.0e-9_dp))
         end if
      end if
      dynamics%theta = config%theta
      dynamics%interval = config%interval
      dynamics%newton = newton
      dynamics%extrapolate = config%extrapolate
      dynamics%energy = config%energy
      dynamics%min_step_fraction = config%min_step_fraction
      dynamics%max_wall_time = config%max_wall_time
      dynamics%progress = .not. config%quiet
   end subroutine setup_case
end module xcable_box_case
