!> The paper's box scheme (&numerics scheme = 'box') as a run: its statics
!> (statics.f90) as in version 0.1, and its model of the cable (model.f90) set
!> up on the run that the one step loop (driver/stepping.f90) drives, with
!> the records every run produces. Its results are those of version 0.1 to the
!> last digit.
!> The box scheme describes the paper's scene only: end a fixed, end b fixed
!> and released by the break (s_break = L), the end tension given.
module xcable_box_run
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_box_case, only: setup_case
   use xcable_box_equations, only: cable_model, i_b0, i_b3
   use xcable_solver_newton, only: newton_options
   use xcable_box_statics, only: static_state, solve_statics
   use xcable_box_dynamics, only: dynamics_options
   use xcable_box_model, only: box_model, state_fields
   use xcable_driver_records, only: static_info, n_fields
   use xcable_driver_rod_run, only: rod_run
   implicit none
   private
   public :: box_run, box_supports

   !> A box-scheme run.
   type :: box_run
      !> Cable data, grid and controls of the box scheme.
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dynamics
      !> End tension, N; Courant number asked for.
      real(dp) :: tension = 0, courant = 1
      !> Static state.
      type(static_state) :: state
      type(static_info) :: info
      !> The model of the cable that the step loop drives.
      type(box_model) :: stepper
   contains
      procedure :: prepare => box_prepare
   end type box_run

contains

   !> Whether the box scheme can describe the scene of a case ('' : yes; else why not).
   function box_supports(config) result(why)
      !> The case.
      type(case_config), intent(in) :: config
      character(:), allocatable :: why
      why = ''
      if (trim(config%end_a%kind) /= 'fixed' .or. trim(config%end_b%kind) /= 'fixed') then
         why = 'the box scheme describes the paper''s scene only: &end_a and &end_b fixed (here '// &
               trim(config%end_a%kind)//' and '//trim(config%end_b%kind)//')'
      else if (config%is_given('end_b', 'x') .or. config%is_given('end_b', 'z') .or. config%is_given('end_a', 'x') &
               .or. config%is_given('end_a', 'z')) then
         why = 'the box scheme takes the end tension (&static tension), not end positions'
      else if (.not. config%break_enabled) then
         why = 'the box scheme runs the paper''s rupture only (&rupture enabled = .true.)'
      else if (config%s_break >= 0 .and. abs(config%s_break - config%length) > 1.0e-12_dp*config%length) then
         why = 'the box scheme breaks the cable at end b only (s_break = L)'
      else if (config%break_time /= 0) then
         why = 'the box scheme starts the break at t = 0 only'
      else if (config%gravity < 1.0e-6_dp) then
         why = 'the box scheme needs gravity >= 1e-6 (without weight its static cable may turn freely)'
      else if (trim(config%law) /= 'tanh' .and. trim(config%law) /= 'linear') then
         why = 'the box scheme has the tanh and linear laws only'
      else if (config%damping /= 0) then
         why = 'the box scheme has no internal damping'
      else if (config%fluid_density /= 0 .or. config%air_density /= 0) then
         why = 'the box scheme has no fluid loads'
      else if (trim(config%compression) /= 'law') then
         why = 'the box scheme has the law''s compression only (compression = ''law'')'
      end if
   end function box_supports

   !> Model, grid, controls and the statics; the run that the step loop drives (its options,
   !> time step, output nodes and static state) and the model on it (stepper).
   subroutine box_prepare(self, config, run, error)
      !> Box-scheme run.
      class(box_run), intent(inout) :: self
      !> Validated case.
      type(case_config), intent(in) :: config
      !> The run of the step loop (fresh).
      type(rod_run), intent(inout) :: run
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: why
      why = box_supports(config)
      if (len(why) > 0) then
         call fatal_error(error, config%source//': &numerics: scheme = ''box'': '//why//'; use scheme = ''rod''', &
                          stat_input)
         return
      end if
      call setup_case(config, self%model, self%s, self%newton, self%dynamics, error)
      if (allocated(error)) return
      self%tension = config%tension
      self%courant = config%courant
      call solve_statics(self%model, self%s, config%tension, self%newton, self%state, error)
      if (allocated(error)) return
      self%info%s = self%s
      allocate (self%info%fields(size(self%s), n_fields))
      call state_fields(self%model, self%s, self%state%y, self%info%fields)
      self%info%span = self%state%span
      self%info%sag = self%state%sag
      self%info%end_angle = self%state%end_angle
      self%info%tension_a = self%info%fields(1, 1)
      self%info%tension_b = self%info%fields(size(self%s), 1)
      self%info%newton_iterations = self%state%newton%iterations
      self%info%beta0 = self%state%y(i_b0, :)
      self%info%beta3 = self%state%y(i_b3, :)
      call self%stepper%setup(self%model, self%s, self%state%y, self%dynamics, self%courant, run)
      run%info = self%info
   end subroutine box_prepare
end module xcable_box_run
