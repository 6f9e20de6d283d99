!> xcable: rupture dynamics of a highly extensible cable from a namelist.
!>
!>   xcable case.nml
!>   xcable --check case.nml   (validate the case and exit)
!>   xcable --schema markdown|tsv   (the input table: README's, or the sweep scripts')
!>
!> Exit codes: 0 complete; 1 numerical failure (the result file says 'failed',
!> with the reason and time); 2 bad input or output path (no result file).
program xcable_main
   use xcable_kinds, only: dp
   use xcable_error, only: error_type, stat_input, stat_io
   use xcable_strings, only: str
   use xcable_io_input, only: case_config, read_config, config_text
   use xcable_io_schema, only: write_schema
   use xcable_case, only: setup_case
   use xcable_model_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_statics, only: static_state, solve_statics
   use xcable_dynamics, only: dynamics_options, run_history, run_summary, run_rupture
   use xcable_io_output, only: result_file
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   implicit none

   type(case_config) :: config
   type(cable_model) :: model
   real(dp), allocatable :: s(:)
   type(newton_options) :: newton
   type(dynamics_options) :: dynamics
   type(static_state) :: state
   type(run_history) :: history
   type(run_summary) :: summary
   type(result_file) :: output
   type(error_type), allocatable :: error, write_error
   character(len=4096) :: path
   integer :: nargs
   logical :: check_only
   character(len=*), parameter :: usage = 'usage: xcable [--check] <case.nml>   (--check: validate only; '// &
                                          'see README.md for the namelist groups); xcable --schema markdown|tsv'

   nargs = command_argument_count()
   call schema_option()
   check_only = .false.
   if (nargs == 2) then
      call get_command_argument(1, path)
      check_only = trim(path) == '--check'
   end if
   if (.not. (nargs == 1 .or. check_only)) then
      write (error_unit, '(a)') usage
      stop 2, quiet=.true.
   end if
   call get_command_argument(nargs, path)
   if (trim(path) == '--help' .or. trim(path) == '-h') then
      write (output_unit, '(a)') usage
      stop
   end if

   call read_config(trim(path), config, error)
   if (allocated(error)) call fail_input(error)
   call setup_case(config, model, s, newton, dynamics, error)
   if (allocated(error)) call fail_input(error)
   if (check_only) then
      write (output_unit, '(a)') trim(path)//': ok'
      stop
   end if

   call output%create(trim(config%file), model, s, config%fields, config_text(config), trim(path), config%gnuplot, error)
   if (allocated(error)) then
      call output%finish('failed', error%message)
      call fail_input(error)
   end if

   call solve_statics(model, s, config%tension, newton, state, error)
   if (allocated(error)) call fail_run(error, 0.0_dp)
   call output%write_static(state, error)
   if (allocated(error)) call fail_run(error, 0.0_dp)
   if (.not. config%quiet) write (error_unit, '(a)') 'xcable: static state: span '//str(state%span)//' m, sag '// &
      str(state%sag)//' m, '//str(state%newton%iterations)//' Newton iterations; dynamics with '// &
      str(config%nodes)//' nodes, dt '//str(dynamics%dt)//' s'

   call run_rupture(model, s, state%y, dynamics, history, summary, error, output)
   ! A failed run keeps its history and summary too; the first error is reported.
   call output%write_history(history, write_error)
   if (.not. allocated(error) .and. allocated(write_error)) call move_alloc(write_error, error)
   call output%write_summary(summary, write_error)
   if (.not. allocated(error) .and. allocated(write_error)) call move_alloc(write_error, error)
   if (allocated(error)) call fail_run(error, summary%time_reached)
   call output%finish('complete', error=error)
   if (allocated(error)) then
      write (error_unit, '(a)') 'xcable: error: '//error%message
      stop 1, quiet=.true.
   end if
   if (.not. config%quiet) write (error_unit, '(a)') 'xcable: complete in '//str(summary%wall_time)//' s: '// &
      str(summary%steps)//' steps, peak end speed '//str(summary%peak_end_speed)//' m/s, results in '//trim(config%file)

contains

   !> xcable --schema markdown|tsv: print the input table and stop.
   subroutine schema_option()
      character(len=16) :: option, format
      if (nargs /= 2) return
      call get_command_argument(1, option)
      if (option /= '--schema') return
      call get_command_argument(2, format)
      call write_schema(output_unit, trim(format), error)
      if (allocated(error)) call fail_input(error)
      stop
   end subroutine schema_option

   !> Bad input: one line on stderr, exit code 2.
   subroutine fail_input(err)
      type(error_type), intent(in) :: err
      write (error_unit, '(a)') 'xcable: error: '//err%message
      stop 2, quiet=.true.
   end subroutine fail_input

   !> Numerical failure: mark the file failed, one line on stderr, exit code 1.
   subroutine fail_run(err, time)
      type(error_type), intent(in) :: err
      real(dp), intent(in) :: time
      call output%finish('failed', err%message, time)
      write (error_unit, '(a)') 'xcable: failed at t = '//str(time)//' s: '//err%message
      if (err%stat == stat_input .or. err%stat == stat_io) stop 2, quiet=.true.
      stop 1, quiet=.true.
   end subroutine fail_run
end program xcable_main
