!> run_rupture: the box scheme's model (box/model.f90) in the one step loop
!> (driver/stepping.f90), on a run of its own, with the records of version 0.1
!> and its observer of the states. (A submodule of box/dynamics.f90: the model
!> uses that module's types; the tests of the scheme call run_rupture.)
submodule (xcable_box_dynamics) xcable_box_dynamics_rupture
   use xcable_box_model, only: box_model
   use xcable_driver_rod_run, only: rod_run
   use xcable_driver_stepping, only: run_dynamics
   use xcable_driver_records, only: driver_observer => run_observer, static_info
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none

   !> The step loop's observer that passes the model's state on to a box-scheme observer (the
   !> snapshots are the states at the ends of the steps: the box scheme lands on them).
   type, extends(driver_observer) :: state_forward
      class(run_observer), pointer :: target => null()
      type(box_model), pointer :: model => null()
      logical :: progress_report = .false.
   contains
      procedure :: static => forward_static
      procedure :: snapshot => forward_snapshot
      procedure :: progress => forward_progress
   end type state_forward

contains

   module subroutine run_rupture(model, s, y_static, options, history, summary, error, observer)
      type(cable_model), intent(in) :: model
      real(dp), intent(in) :: s(:)
      real(dp), intent(in) :: y_static(:, :)
      type(dynamics_options), intent(in) :: options
      type(run_history), intent(out) :: history
      type(run_summary), intent(out) :: summary
      type(error_type), allocatable, intent(out) :: error
      class(run_observer), intent(inout), target, optional :: observer
      type(rod_run) :: run
      type(box_model), target :: stepper
      type(state_forward) :: forward
      call stepper%setup(model, s, y_static, options, 1.0_dp, run)
      forward%model => stepper
      forward%progress_report = options%progress
      if (present(observer)) forward%target => observer
      call run_dynamics(run, stepper, forward, error)
      history = stepper%history
      summary = stepper%summary
   end subroutine run_rupture

   subroutine forward_static(self, info, error)
      class(state_forward), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
   end subroutine forward_static

   subroutine forward_snapshot(self, t, fields, error)
      class(state_forward), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      if (associated(self%target)) call self%target%snapshot(t, self%model%y, error)
   end subroutine forward_snapshot

   !> Progress on stderr (options%progress).
   subroutine forward_progress(self, t, t_end, wall)
      class(state_forward), intent(inout) :: self
      real(dp), intent(in) :: t, t_end, wall
      if (.not. self%progress_report) return
      write (error_unit, '(a,f5.1,a,es10.3,a,es10.3,a,f8.1,a,f8.1,a)') 'xcable: ', 100*t/t_end, &
         '%  t = ', t, ' s of ', t_end, ' s, wall ', wall, ' s, remaining ', &
         wall*(t_end - t)/max(t, tiny(t)), ' s'
   end subroutine forward_progress
end submodule xcable_box_dynamics_rupture
