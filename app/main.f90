!> xcable: dynamics of a highly extensible cable from a namelist.
!>
!>   xcable case.nml
!>   xcable --resume case.nml       (continue from the checkpoint of case.nml's result file)
!>   xcable --check case.nml        (validate the case, solve its statics, and exit)
!>   xcable --schema markdown|tsv   (the input table: docs/user/namelist.md's, or the sweep scripts')
!>   xcable --outputs markdown|tsv  (the output registry: docs/user/output.md)
!>   xcable --version               (the version, the compiler and its options)
!>
!> Exit codes: 0 complete (warnings, if any, on stderr and in the file);
!> 1 numerical failure (the result file says 'failed', with the reason and
!> the time; or no file when the statics fails); 2 bad input or output path
!> (no result file), or a checkpoint that --resume refuses (nothing changed);
!> 3 interrupted by SIGTERM: a checkpoint was written and the
!> result file says 'interrupted'; `xcable --resume case.nml` continues.
!>
!> Checkpoints (either scheme): the file &output file + '.ckpt', written every
!> &output checkpoint_interval seconds of wall time and when SIGTERM arrives;
!> removed when the run completes or fails. A new run (without --resume)
!> removes a checkpoint left by an earlier one of the same result file.
program xcable_main
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, stat_input, stat_io
   use xcable_core_strings, only: str, quantity
   use xcable_io_input, only: case_config, read_config, config_text
   use xcable_io_schema, only: write_schema
   use xcable_io_output_registry, only: write_outputs
   use xcable_driver_simulation, only: simulation
   use xcable_driver_records, only: run_summary, run_history, static_info, summary_text
   use xcable_app_output, only: app_output
   use xcable_core_version, only: version_lines, unoptimised_note
   use xcable_io_checkpoint, only: checkpoint_path, remove_checkpoint
   use xcable_io_xdmf, only: write_xdmf, remove_xdmf, probe_xdmf
   use xcable_system_posix, only: install_termination_handler, new_run_id
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   implicit none

   type(case_config) :: config
   type(simulation) :: sim
   type(app_output) :: output
   type(error_type), allocatable :: error, write_error
   type(run_summary), pointer :: summary
   type(run_history), pointer :: history
   type(static_info), pointer :: info
   character(len=4096) :: path, option
   character(:), allocatable :: checkpoint, fingerprint, run_id, problem
   integer :: nargs, steps
   real(dp) :: dt
   logical :: check_only, resume, exists
   character(len=*), parameter :: usage = 'usage: xcable [--check | --resume] <case.nml>   (--check: validate only; '// &
                                          '--resume: continue from the checkpoint; see docs/user/namelist.md for the namelist '// &
                                          'groups); xcable --schema markdown|tsv; xcable --outputs markdown|tsv; '// &
                                          'xcable --version'

   nargs = command_argument_count()
   call schema_option()
   check_only = .false.
   resume = .false.
   if (nargs == 2) then
      call get_command_argument(1, option)
      check_only = trim(option) == '--check'
      resume = trim(option) == '--resume'
   end if
   if (.not. (nargs == 1 .or. check_only .or. resume)) then
      write (error_unit, '(a)') 'xcable: error: '//usage
      stop 2, quiet=.true.
   end if
   call get_command_argument(nargs, path)
   if (nargs == 1 .and. (trim(path) == '--help' .or. trim(path) == '-h')) then
      write (output_unit, '(a)') usage
      stop
   end if
   if (nargs == 1 .and. trim(path) == '--version') then
      write (output_unit, '(a)') version_lines()
      stop
   end if
   ! An option without its case (xcable --resume): say so, not 'no such file'.
   if (nargs == 1 .and. path(1:1) == '-') then
      write (error_unit, '(a)') 'xcable: error: '//trim(path)//': an option without a case file, or not an option; '//usage
      stop 2, quiet=.true.
   end if

   call read_config(trim(path), config, error)
   if (allocated(error)) call fail_input(error)
   if (len(unoptimised_note()) > 0 .and. .not. config%quiet) write (error_unit, '(a)') 'xcable: note: '// &
      unoptimised_note()
   call sim%prepare(config, error, statics_only=check_only)
   if (allocated(error)) then
      if (error%stat == stat_input .or. error%stat == stat_io) call fail_input(error)
      write (error_unit, '(a)') 'xcable: failed before the dynamics (no result file): '//error%message
      stop 1, quiet=.true.
   end if
   call sim%time_step(dt, steps)
   if (check_only) then
      ! The result file's folder must take a file: a probe next to it, removed at once.
      call probe_output(trim(config%file))
      info => sim%static()
      if (sim%is_network) then
         write (output_unit, '(a)') trim(path)//': ok (a network of '//str(config%line_count)//' lines, '// &
            str(sim%output_nodes())//' nodes, dt '//quantity(dt, 's')//', '//str(steps)//' steps); statics: '// &
            sim%network_statics_text()
         stop
      end if
      write (output_unit, '(a)') trim(path)//': ok ('//trim(config%scheme)//' scheme, '//sim%model//' model, '// &
         str(config%nodes)//' nodes, dt '//quantity(dt, 's')//', '//str(steps)//' steps); static end tensions: '// &
         'end a '//quantity(info%tension_a, 'N')//', end b '//quantity(info%tension_b, 'N')//', span '// &
         quantity(info%span, 'm')
      stop
   end if

   output%quiet = config%quiet
   ! SIGTERM (a batch system's time limit): from here on the run (either scheme, either model)
   ! writes a checkpoint at its next step and stops (before the dynamics: at t = 0).
   problem = install_termination_handler()
   if (len(problem) > 0) write (error_unit, '(a)') 'xcable: warning: '//problem//': SIGTERM ends the run '// &
      'without a checkpoint'
   checkpoint = checkpoint_path(trim(config%file))
   fingerprint = config_text(config, fingerprint=.true.)
   if (resume) then
      ! Everything is checked before the result file is touched.
      inquire (file=checkpoint, exist=exists)
      if (.not. exists) call fail_text(trim(path)//': no checkpoint '//checkpoint//' to resume from (a run '// &
                                       'writes one every &output checkpoint_interval seconds and when it gets '// &
                                       'SIGTERM); run without --resume')
      call sim%enable_checkpoints(checkpoint, fingerprint, '', config%checkpoint_interval, on_termination=.true.)
      call sim%resume(checkpoint, fingerprint, run_id, error)
      if (allocated(error)) call fail_input(error)
      call output%reopen(trim(config%file), sim%output_s(), config%fields, config_text(config), trim(path), &
                         config%gnuplot, sim%piece_starts(), sim%snapshots_written(), run_id, error, &
                         three_d=sim%three_d_output())
      if (allocated(error)) then
         ! Not fail_run: summary is not associated before sim%run, and the checkpoint stays.
         call fail_input(error)
      end if
      if (.not. config%quiet) write (error_unit, '(a)') 'xcable: resuming from '//checkpoint//' at t = '// &
         str(sim%rod%t)//' s (step '//str(sim%rod%history%n)//')'
   else
      ! A checkpoint of an earlier run of this result file no longer fits it.
      call remove_checkpoint(checkpoint)
      ! So is an XDMF sidecar of it (a new one is written when this run completes).
      call remove_xdmf(trim(config%file))
      if (config%xdmf) then
         call probe_xdmf(trim(config%file), error)
         if (allocated(error)) call fail_input(error)
      end if
      run_id = new_run_id()
      call output%create(trim(config%file), sim%output_s(), config%fields, config_text(config), trim(path), &
                         config%gnuplot, trim(config%scheme), sim%terms, sim%piece_starts(), error, run_id=run_id, &
                         three_d=sim%three_d_output())
      if (.not. allocated(error)) call output%mark('model', sim%model, error)
      if (allocated(error)) then
         call output%finish('failed', error%message)
         call fail_input(error)
      end if
      call sim%enable_checkpoints(checkpoint, fingerprint, run_id, config%checkpoint_interval, &
                              on_termination=.true.)
      info => sim%static()
      if (.not. config%quiet .and. sim%is_network) write (error_unit, '(a)') 'xcable: statics of the network '// &
         'solved ('//sim%network_statics_text()//'); dynamics with the rod scheme, '//str(sim%output_nodes())// &
         ' nodes, dt '//quantity(dt, 's')
      if (.not. config%quiet .and. .not. sim%is_network) write (error_unit, '(a)') 'xcable: statics solved (end tensions '// &
         quantity(info%tension_a, 'N')//' and '//quantity(info%tension_b, 'N')//'); dynamics with the '// &
         trim(config%scheme)//' scheme, '//str(config%nodes)//' nodes, dt '//quantity(dt, 's')
   end if

   call sim%run(output, error)
   summary => sim%summary()
   history => sim%history()
   if (sim%interrupted) call stop_interrupted()
   ! A failed run keeps its history and summary too; the first error is reported.
   call output%write_history(history, write_error)
   if (.not. allocated(error) .and. allocated(write_error)) call move_alloc(write_error, error)
   info => sim%static()
   call output%write_summary(summary, history%end_labels, write_error, info)
   if (.not. allocated(error) .and. allocated(write_error)) call move_alloc(write_error, error)
   if (allocated(error)) call fail_run(error, summary%time_reached)
   call output%finish('complete', warnings=summary%warnings, error=error)
   if (allocated(error)) then
      write (error_unit, '(a)') 'xcable: error: '//error%message
      stop 1, quiet=.true.
   end if
   ! Complete: the checkpoint has served (the status is written first).
   call remove_checkpoint(checkpoint)
   if (config%xdmf) then
      call write_xdmf(trim(config%file), sim%piece_starts(), error)
      if (allocated(error)) then
         write (error_unit, '(a)') 'xcable: error: '//error%message//' (the HDF5 file is complete)'
         stop 1, quiet=.true.
      end if
   end if
   if (.not. config%quiet) call print_lines(summary_text(summary, info, history%end_labels))
   call print_warnings(summary%warnings)
   if (.not. config%quiet) then
      write (error_unit, '(a)') 'xcable: complete in '//quantity(summary%wall_time, 's')//': '// &
         str(summary%steps)//' steps to t = '//quantity(summary%time_reached, 's')//', results in '//trim(config%file)
   end if

contains

   !> xcable --schema markdown|tsv: print the input table and stop; xcable --outputs
   !> markdown|tsv: the output registry (every dataset and attribute of the result file).
   subroutine schema_option()
      character(len=16) :: option, format
      if (nargs /= 2) return
      call get_command_argument(1, option)
      if (option /= '--schema' .and. option /= '--outputs') return
      call get_command_argument(2, format)
      if (option == '--schema') then
         call write_schema(output_unit, trim(format), error)
      else
         call write_outputs(output_unit, trim(format), error)
      end if
      if (allocated(error)) call fail_input(error)
      stop
   end subroutine schema_option

   !> --check: stop with an input error unless a file can be made where the result file goes.
   subroutine probe_output(file)
      character(*), intent(in) :: file
      integer :: unit, ios
      character(len=256) :: msg
      open (newunit=unit, file=file//'.check', status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) call fail_text(trim(path)//": &output: file = '"//file//"': cannot write there ("//trim(msg)// &
                                   '): does its folder exist and is it writable?')
      close (unit, status='delete')
   end subroutine probe_output

   !> Each line of text on stderr, after 'xcable: '.
   subroutine print_lines(text, prefix)
      character(*), intent(in) :: text
      !> Written after 'xcable: ' on each line ('warning: ').
      character(*), intent(in), optional :: prefix
      character(:), allocatable :: head
      integer :: start, nl
      head = 'xcable: '
      if (present(prefix)) head = head//prefix
      start = 1
      do while (start <= len(text))
         nl = index(text(start:), new_line('a'))
         if (nl == 0) then
            write (error_unit, '(a)') head//text(start:)
            exit
         end if
         write (error_unit, '(a)') head//text(start:start + nl - 2)
         start = start + nl
      end do
   end subroutine print_lines

   !> One line per warning on stderr.
   subroutine print_warnings(text)
      character(*), intent(in) :: text
      call print_lines(text, 'warning: ')
   end subroutine print_warnings

   !> Bad input: one line on stderr, exit code 2.
   subroutine fail_input(err)
      type(error_type), intent(in) :: err
      call fail_text(err%message)
   end subroutine fail_input

   !> One line on stderr, exit code 2.
   subroutine fail_text(message)
      character(*), intent(in) :: message
      write (error_unit, '(a)') 'xcable: error: '//message
      stop 2, quiet=.true.
   end subroutine fail_text

   !> Numerical failure: mark the file failed, one line on stderr, exit code 1.
   !> A failed run keeps no checkpoint (resuming would fail again).
   subroutine fail_run(err, time)
      type(error_type), intent(in) :: err
      real(dp), intent(in) :: time
      call output%finish('failed', err%message, time, summary%warnings)
      call remove_checkpoint(checkpoint)
      write (error_unit, '(a)') 'xcable: failed at t = '//str(time)//' s: '//err%message
      call print_warnings(summary%warnings)
      if (err%stat == stat_input .or. err%stat == stat_io) stop 2, quiet=.true.
      stop 1, quiet=.true.
   end subroutine fail_run

   !> SIGTERM: the checkpoint is written; the file gets the summary so far and
   !> the status 'interrupted'; exit code 3.
   subroutine stop_interrupted()
      call output%write_summary(summary, history%end_labels, write_error, sim%static())
      if (allocated(write_error)) then
         write (error_unit, '(a)') 'xcable: interrupted (SIGTERM) at t = '//str(summary%time_reached)// &
            ' s, checkpoint '//checkpoint//' written, but: '//write_error%message
         stop 1, quiet=.true.
      end if
      call output%finish('interrupted', warnings=summary%warnings, error=write_error)
      if (allocated(write_error)) then
         write (error_unit, '(a)') 'xcable: interrupted (SIGTERM) at t = '//str(summary%time_reached)// &
            ' s, checkpoint '//checkpoint//' written, but: '//write_error%message
         stop 1, quiet=.true.
      end if
      write (error_unit, '(a)') 'xcable: interrupted (SIGTERM) at t = '//str(summary%time_reached)//' s; checkpoint '// &
         checkpoint//'; continue with: xcable --resume '//trim(path)
      stop 3, quiet=.true.
   end subroutine stop_interrupted
end program xcable_main
