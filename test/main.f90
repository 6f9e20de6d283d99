!> Test driver: runs every suite, or `suite [test]` given on the command line.
program xcable_tests
   use xcable_testing, only: testsuite_type, new_testsuite, run_suite
   use suite_law, only: collect_law
   use suite_banded, only: collect_banded
   use suite_jacobian, only: collect_jacobian
   use suite_statics, only: collect_statics
   use suite_dynamics, only: collect_dynamics
   use suite_input, only: collect_input
   use suite_stability, only: collect_stability
   use suite_output, only: collect_output
   use suite_golden, only: collect_golden
   use suite_rod, only: collect_rod
   use suite_rod_statics, only: collect_rod_statics
   use suite_rod_dynamics, only: collect_rod_dynamics
   use suite_scenes, only: collect_scenes
   use suite_laws, only: collect_laws
   use suite_registry, only: collect_registry
   use suite_spring, only: collect_spring
   use suite_fluid, only: collect_fluid
   use suite_surface, only: collect_surface
   use suite_seabed, only: collect_seabed
   use suite_checkpoint, only: collect_checkpoint
   use suite_rod3d, only: collect_rod3d
   use suite_model3d, only: collect_model3d
   use suite_quiescent, only: collect_quiescent
   use suite_atan2, only: collect_atan2
   use suite_tan, only: collect_tan
   use suite_slack, only: collect_slack
   use suite_rupture, only: collect_rupture
   use suite_segments, only: collect_segments
   use suite_points, only: collect_points
   use suite_network, only: collect_network
   use suite_input_network, only: collect_input_network
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   implicit none
   type(testsuite_type), allocatable :: suites(:)
   character(len=64) :: only_suite, only_test
   integer :: i, passed, failed, ran

   suites = [new_testsuite('law', collect_law), &
             new_testsuite('banded', collect_banded), &
             new_testsuite('jacobian', collect_jacobian), &
             new_testsuite('statics', collect_statics), &
             new_testsuite('dynamics', collect_dynamics), &
             new_testsuite('input', collect_input), &
             new_testsuite('stability', collect_stability), &
             new_testsuite('output', collect_output), &
             new_testsuite('golden', collect_golden), &
             new_testsuite('rod', collect_rod), &
             new_testsuite('rod_statics', collect_rod_statics), &
             new_testsuite('rod_dynamics', collect_rod_dynamics), &
             new_testsuite('scenes', collect_scenes), &
             new_testsuite('laws', collect_laws), &
            new_testsuite('spring', collect_spring), &
             new_testsuite('registry', collect_registry), &
             new_testsuite('fluid', collect_fluid), &
             new_testsuite('surface', collect_surface), &
             new_testsuite('seabed', collect_seabed), &
             new_testsuite('checkpoint', collect_checkpoint), &
             new_testsuite('rod3d', collect_rod3d), &
             new_testsuite('model3d', collect_model3d), &
             new_testsuite('quiescent', collect_quiescent), &
             new_testsuite('atan2', collect_atan2), &
             new_testsuite('tan', collect_tan), &
             new_testsuite('slack', collect_slack), &
             new_testsuite('rupture', collect_rupture), &
             new_testsuite('segments', collect_segments), &
             new_testsuite('points', collect_points), &
             new_testsuite('network', collect_network), &
             new_testsuite('input_network', collect_input_network)]
   only_suite = ''
   only_test = ''
   if (command_argument_count() >= 1) call get_command_argument(1, only_suite)
   if (command_argument_count() >= 2) call get_command_argument(2, only_test)
   passed = 0
   failed = 0
   ran = 0
   do i = 1, size(suites)
      if (len_trim(only_suite) > 0 .and. suites(i)%name /= trim(only_suite)) cycle
      ran = ran + 1
      write (output_unit, '(a)') 'suite '//suites(i)%name
      call run_suite(suites(i), trim(only_test), passed, failed)
   end do
   if (ran == 0) then
      write (error_unit, '(a)') 'no suite named '//trim(only_suite)
      error stop 1
   end if
   write (output_unit, '(i0,a,i0,a)') passed, ' passed, ', failed, ' failed'
   if (failed > 0) error stop 1
end program xcable_tests
