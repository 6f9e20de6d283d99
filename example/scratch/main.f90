program scratch
   use xcable_kinds, only: dp
   use xcable_error, only: error_type
   use xcable_io_config, only: case_config
   use xcable_scene, only: scene_type, scene_from_config
   use xcable_rod_run, only: rod_run, rod_run_options
   implicit none
   type(case_config) :: config
   type(scene_type) :: scene
   type(rod_run) :: run
   type(rod_run_options) :: opt
   type(error_type), allocatable :: err
   integer :: i
   character(len=64) :: arg
   real(dp) :: tension, tbr, tend
   integer :: nodes
   call get_command_argument(1, arg); read (arg, *) tension
   call get_command_argument(2, arg); read (arg, *) tbr
   call get_command_argument(3, arg); read (arg, *) tend
   call get_command_argument(4, arg); read (arg, *) nodes
   config%source = 'scratch'
   config%tension = tension
   config%t_break = tbr
   call scene_from_config(config, scene, err)
   if (allocated(err)) stop 'scene'
   opt%nodes = nodes
   opt%t_end = tend
   opt%energy = .true.
   opt%interval = 0.1_dp
   opt%newton%tolerance = 1.0e-7_dp
   call get_command_argument(5, arg); read (arg, *) opt%newton%reuse_jacobian
   call get_command_argument(6, arg); read (arg, *) opt%mu
   call get_command_argument(7, arg); read (arg, *) opt%mu2
   call run%prepare(scene, opt, err)
   if (allocated(err)) then
      print *, 'prepare: ', err%message
      stop
   end if
   print *, 'span', run%static%span, 'sag', run%static%sag, 'dt', run%dt, 'newton', run%static%newton_iterations
   call run%run(error=err)
   if (allocated(err)) print *, 'run: ', err%message
   print *, 'steps', run%summary%steps, 'wall', run%summary%wall_time, 'newton', run%summary%newton_iterations, &
      'fact', run%summary%factorisations, 'rejected', run%summary%rejected_steps
   print *, 'drift', run%summary%energy_drift, 'peak', run%summary%peak_end_speed, 'front', run%summary%front_arrival_time
   print *, 'min T', run%summary%min_fixed_end_tension, 'max turn', run%summary%max_turning_angle, &
      'min strain', run%summary%min_strain
   do i = 0, run%history%n, max(1, run%history%n/10)
      print '(f8.4, 7es13.5)', run%history%time(i), run%history%energy(:, i)
   end do
   print *, 'end b final', run%history%ends(1:2, 2, run%history%n), 'peak t', run%summary%peak_end_speed_time
   do i = 0, run%history%n, max(1, run%history%n/40)
      print '(f8.4, 3f12.4)', run%history%time(i), norm2(run%history%ends(3:4, 2, i)), run%history%ends(5, 1, i)
   end do
   if (len(run%summary%warnings) > 0) print *, 'WARN: ', run%summary%warnings
end program
