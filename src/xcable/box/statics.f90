!> The initial static state (eq. 18 without time derivatives, boundary
!> conditions 28-29): Newton's method from the extensible-catenary guess.
module xcable_box_statics
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, prefix_error
   use xcable_box_equations, only: cable_model, n_eq, i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om
   use xcable_box_geometry, only: positions
   use xcable_box_discrete, only: box_system
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   use xcable_theory_closed_forms, only: horizontal_force, wave_speed
   implicit none
   private
   public :: static_state, solve_statics, catenary_guess

   !> A static solution and its derived quantities.
   type :: static_state
      !> Unknowns (7, nodes).
      real(dp), allocatable :: y(:, :)
      !> Horizontal and vertical positions, m.
      real(dp), allocatable :: x(:), z(:)
      !> Horizontal distance between the ends, m.
      real(dp) :: span = 0
      !> Depth of the lowest point below the ends, m.
      real(dp) :: sag = 0
      !> Angle of the tangent below the horizontal at the fixed end, rad.
      real(dp) :: end_angle = 0
      !> What Newton did.
      type(newton_report) :: newton
   end type static_state

contains

   !> Extensible catenary without bending at the nodes: the first guess.
   subroutine catenary_guess(model, s, end_tension, y, error)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> End tension, N.
      real(dp), intent(in) :: end_tension
      !> Guess (7, nodes).
      real(dp), intent(out) :: y(:, :)
      !> Error when the tension cannot hold the weight.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: h, v, t, angle
      integer :: k
      call horizontal_force(model%weight, model%length, end_tension, h, error)
      if (allocated(error)) return
      do k = 1, size(s)
         v = model%weight*(s(k) - 0.5_dp*model%length)
         t = sqrt(h*h + v*v)
         angle = atan2(h, v)
         y(i_eps, k) = model%law%strain_at(t)
         y(i_sn, k) = 0
         y(i_u, k) = 0
         y(i_v, k) = 0
         y(i_b0, k) = cos(0.5_dp*angle)
         y(i_b3, k) = sin(0.5_dp*angle)
         y(i_om, k) = -h*model%weight/(t*t)
      end do
   end subroutine catenary_guess

   !> Solve the static problem on the grid s.
   subroutine solve_statics(model, s, end_tension, options, state, error)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Node arc lengths from 0 to L, m.
      real(dp), intent(in) :: s(:)
      !> End tension T_s, N.
      real(dp), intent(in) :: end_tension
      !> Newton controls.
      type(newton_options), intent(in) :: options
      !> The solution.
      type(static_state), intent(out) :: state
      !> Error when the tension is too small or Newton fails.
      type(error_type), allocatable, intent(out) :: error
      type(box_system) :: system
      type(newton_workspace) :: work
      type(newton_options) :: full_newton
      real(dp), allocatable :: x(:)
      integer :: np, kl, ku
      np = size(s)
      allocate (state%y(n_eq, np), state%x(np), state%z(np))
      call catenary_guess(model, s, end_tension, state%y, error)
      if (allocated(error)) return
      call system%init(model, s, .false., end_tension, wave_speed(model%law, model%mass, state%y(i_eps, 1)), 1.0_dp)
      call system%band_widths(kl, ku)
      call work%init(n_eq*np, kl, ku, system%unknown_scale())
      full_newton = options
      full_newton%reuse_jacobian = .false.
      x = reshape(state%y, [n_eq*np])
      call newton_solve(system, x, work, full_newton, state%newton, error)
      if (allocated(error)) then
         call prefix_error(error, 'statics: ')
         return
      end if
      state%y = reshape(x, [n_eq, np])
      call positions(state%y, s, state%x, state%z)
      state%span = state%x(np) - state%x(1)
      state%sag = max(state%z(1), state%z(np)) - minval(state%z)
      state%end_angle = atan2(-(state%y(i_b0, 1)**2 - state%y(i_b3, 1)**2), 2*state%y(i_b0, 1)*state%y(i_b3, 1))
   end subroutine solve_statics
end module xcable_box_statics
