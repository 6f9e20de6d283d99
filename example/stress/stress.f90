!> Stress tests of xcable: where the code gives a trustworthy answer
!> and where it stops, and why, for both discretisations.
!>
!>   fpm run --example stress --profile release -- [quick] [out=DIR] [peer=DIR] [only=STUDY] [scheme=rod|box]
!>                                                  [version=TEXT]
!>
!> Every run is made in process through the simulation driver (stress_runs:
!> sim%prepare, sim%run with the energy ledger and a wall-clock limit), never
!> by spawning the executable. Studies (each for scheme = 'box', the paper's
!> scheme of version 0.1, and for scheme = 'rod', the default since 0.2):
!> - grid21, grid121: the full factorial of tension {2, 50, 180, 315, 400} kN,
!>   t_break {0, 0.5, 5, 50} ms, Courant {0.1, 1, 10}, EI {paper, paper/1000}
!>   and theta {0.5, 0.55} on 21 and 121 nodes (240 runs each);
!> - fine481: 481 nodes, every tension and t_break, both theta, at Courant 1
!>   and 10, plus EI/1000 at t_break 5 ms, plus Courant 0.1 at 180 and 315 kN;
!> - theta: the time weight from 0.5 to 1 at t_break 0 and 5 ms (121 nodes,
!>   and 481 nodes at 180 kN): ringing against accuracy;
!> - compression: 180, 315 and 400 kN on 121 to 961 nodes to t = 0.16 s with a
!>   probe of the compressed zone at the fixed end every millisecond;
!> - slack: the slack releases (2, 5, 20, 50 kN; t_break 5 and 50 ms) to
!>   t = 2 s on 61 to 961 nodes at Courant 0.5, 1 and 2 with the rod at its
!>   defaults, and the box scheme at its defaults (241 nodes, Courant 1) and
!>   on 121 and 481 nodes at Courant 1. To keep the sweep near 25 minutes on
!>   one free core (35 minutes on a loaded one), the rod's 961-node runs at
!>   Courant 0.5 are made at 2 and 5 kN only (at 20 and 50 kN they would
!>   cost about 8 minutes more).
!> t_end of the first four studies is t_break + 2.2 L / c(eps0): the front
!> reaches the fixed end, reflects and returns to the breaking end (the
!> compression phase included). The box studies are those of version 0.1,
!> so that its map stays reproducible.
!> - scenes3d: the 3-D model (&numerics model = '3d') on three scenes of
!>   stress_runs%scene_namelist: the slack line released off its plane, a
!>   fairlead moving across the plane in water with a cross current, and a
!>   ramped force with a torque; on 61 and 121 nodes (31 and 61 for the
!>   fairlead) at Courant 1, 4 and 10, EI the paper's and / 1000. Its table
!>   goes to <out>/stress3d.md and stress3d.csv, so that `only=scenes3d`
!>   (make stress-3d, under a minute) regenerates it alone.
!> `quick` is a smoke test of about 15 s: grid21 with both schemes, the
!> slack releases on 61 nodes (rod, and the box at 2 and 50 kN) and a short
!> compression study. `only=` runs the studies it lists (comma-separated),
!> `scheme=` one scheme; `version=` is the code version for the provenance.
!>
!> Writes <out>/stress.md (tables) and <out>/stress.csv (one row per run);
!> the slack positions are compared with the peer runs in <peer> (default
!> bench/peer/runs) when their files are there.
program stress
   use xcable_core_kinds, only: dp, i8
   use stress_runs, only: run_spec, run_outcome, stress_run, compression_probe, paper_bending_stiffness, &
                          wall_reflection, release_times, outcome_tag
   use stress_reference, only: peer_grids, peer_position
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, compiler_version, compiler_options
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
   implicit none

   !> What the compression probe showed in one run.
   type :: compression_row
      !> Peak compression at the fixed end, N, and when, s.
      real(dp) :: peak = 0, peak_time = -1
      !> Compressed length at the peak, m, and its Euler load pi^2 EI / l^2, N.
      real(dp) :: length = 0, euler = 0
      !> First snapshot with |T(0)| above the Euler load of the zone, s (-1: never).
      real(dp) :: euler_time = -1
      !> First snapshot with the curvature of the zone 0.1 1/m off its static value, s (-1: never).
      real(dp) :: buckle_time = -1
      !> Largest deflection of the zone from its chord, m; largest change of
      !> Omega3 in it, 1/m; smallest strain in it.
      real(dp) :: deflection = 0, curvature = 0, min_strain = 0
   end type compression_row

   real(dp), parameter :: tensions(5) = [2.0e3_dp, 50.0e3_dp, 180.0e3_dp, 315.0e3_dp, 400.0e3_dp]
   real(dp), parameter :: breaks(4) = [0.0_dp, 0.5e-3_dp, 5.0e-3_dp, 50.0e-3_dp]
   real(dp), parameter :: courants(3) = [0.1_dp, 1.0_dp, 10.0_dp]
   real(dp), parameter :: ei_factors(2) = [1.0_dp, 1.0e-3_dp]
   !> The damped scheme of the sweep (docs/measurements/stability.md: why 0.55).
   real(dp), parameter :: damped_theta = 0.55_dp
   real(dp), parameter :: thetas(2) = [0.5_dp, damped_theta]
   !> Curvature change that marks a buckle, 1/m: a 2 mm buckle at the fastest-growing
   !> wavelength (0.9 m at 7 kN); the static curvature is 7e-5 1/m. (A deflection from
   !> the zone's chord would see the sag of a zone tens of metres long.)
   real(dp), parameter :: buckle_curvature = 0.1_dp
   real(dp), parameter :: theta_ladder(9) = [0.5_dp, 0.5025_dp, 0.505_dp, 0.51_dp, 0.52_dp, 0.55_dp, 0.6_dp, &
                                             0.75_dp, 1.0_dp]
   character(len=3), parameter :: schemes(2) = ['box', 'rod']
   !> The slack releases.
   real(dp), parameter :: slack_tensions(4) = [2.0e3_dp, 5.0e3_dp, 20.0e3_dp, 50.0e3_dp]
   real(dp), parameter :: slack_breaks(2) = [5.0e-3_dp, 50.0e-3_dp]
   integer, parameter :: slack_nodes(5) = [61, 121, 241, 481, 961]
   real(dp), parameter :: slack_courants(3) = [0.5_dp, 1.0_dp, 2.0_dp]
   real(dp), parameter :: slack_t_end = 2.0_dp
   !> The defaults of a case: nodes and Courant number of the program's input reference.
   integer, parameter :: default_nodes = 241
   !> Wall-clock limits, s: short studies, compression, slack releases.
   real(dp), parameter :: wall_short = 30, wall_compression = 60, wall_slack = 600

   type(run_spec), allocatable :: specs(:)
   type(run_outcome), allocatable :: outcomes(:)
   type(compression_row), allocatable :: rows(:)
   type(compression_probe) :: probe
   character(len=256) :: arg, out_dir, peer_dir, only_study, only_scheme, code_version
   logical :: quick
   integer :: i, n, nargs
   integer(i8) :: clock_start, clock_now, clock_rate
   real(dp) :: total_wall, nan

   nan = ieee_value(1.0_dp, ieee_quiet_nan)
   quick = .false.
   out_dir = 'docs/measurements/data'
   peer_dir = 'bench/peer/runs'
   only_study = ''
   only_scheme = ''
   code_version = 'unknown'
   nargs = command_argument_count()
   do i = 1, nargs
      call get_command_argument(i, arg)
      if (trim(arg) == 'quick') then
         quick = .true.
      else if (index(arg, 'out=') == 1) then
         out_dir = arg(5:)
      else if (index(arg, 'peer=') == 1) then
         peer_dir = arg(6:)
      else if (index(arg, 'only=') == 1) then
         only_study = arg(6:)
      else if (index(arg, 'scheme=') == 1) then
         only_scheme = arg(8:)
      else if (index(arg, 'version=') == 1) then
         code_version = arg(9:)
      else
         write (error_unit, '(a)') 'usage: stress [quick] [out=DIR] [peer=DIR] [only=STUDY] [scheme=rod|box] [version=TEXT]'
         error stop 2
      end if
   end do

   allocate (specs(0))
   call build_design()
   n = size(specs)
   allocate (outcomes(n), rows(n))
   write (output_unit, '(a,i0,a)') 'stress: ', n, ' runs'
   call system_clock(clock_start, clock_rate)
   do i = 1, n
      if (specs(i)%study == 'compression') then
         call stress_run(specs(i), outcomes(i), probe)
         call read_probe(probe, rows(i))
      else
         call stress_run(specs(i), outcomes(i))
      end if
      call system_clock(clock_now)
      write (output_unit, '(i4,1x,a11,1x,a3,f6.1,a,f5.1,a,i4,a,f5.1,a,es8.1,a,f6.4,a,f7.4,a,f7.1,a,f7.0,a)') i, &
         specs(i)%study, specs(i)%scheme, specs(i)%tension/1.0e3_dp, ' kN', 1.0e3_dp*specs(i)%t_break, ' ms', &
         specs(i)%nodes, ' nodes C', specs(i)%courant, ' EI', specs(i)%ei_factor*paper_bending_stiffness, ' theta ', &
         specs(i)%theta, '  t ', outcomes(i)%time_reached, ' s in', outcomes(i)%wall, ' s (', &
         real(clock_now - clock_start, dp)/clock_rate, ' s)  '//tag(i)
      flush (output_unit)
   end do
   call system_clock(clock_now)
   total_wall = real(clock_now - clock_start, dp)/clock_rate
   if (any(specs%study /= 'scenes3d')) then
      call write_csv(trim(out_dir)//'/stress.csv')
      call write_markdown(trim(out_dir)//'/stress.md')
      write (output_unit, '(a,f8.1,a)') 'stress: wrote '//trim(out_dir)//'/stress.md and stress.csv in ', total_wall, ' s'
   end if
   if (any(specs%study == 'scenes3d')) then
      call write_scenes3d(trim(out_dir))
      write (output_unit, '(a)') 'stress: wrote '//trim(out_dir)//'/stress3d.md and stress3d.csv'
   end if

contains

   !> The list of runs.
   subroutine build_design()
      integer :: it, ib, ic, ie, ih, inodes, nodes, is
      integer, parameter :: grid_nodes(2) = [21, 121]
      character(len=3) :: scheme
      do is = 1, size(schemes)
         scheme = schemes(is)
         do inodes = 1, merge(1, 2, quick)
            nodes = grid_nodes(inodes)
            do it = 1, size(tensions)
               do ib = 1, size(breaks)
                  do ic = 1, size(courants)
                     do ie = 1, size(ei_factors)
                        do ih = 1, size(thetas)
                           call add(merge('grid21 ', 'grid121', nodes == 21), scheme, tensions(it), breaks(ib), nodes, &
                                    courants(ic), ei_factors(ie), thetas(ih))
                        end do
                     end do
                  end do
               end do
            end do
         end do
         if (.not. quick) then
            do it = 1, size(tensions)
               do ib = 1, 4
                  do ih = 1, size(thetas)
                     call add('fine481', scheme, tensions(it), breaks(ib), 481, 1.0_dp, 1.0_dp, thetas(ih))
                     call add('fine481', scheme, tensions(it), breaks(ib), 481, 10.0_dp, 1.0_dp, thetas(ih))
                  end do
               end do
               do ih = 1, size(thetas)
                  call add('fine481', scheme, tensions(it), 5.0e-3_dp, 481, 1.0_dp, 1.0e-3_dp, thetas(ih))
               end do
            end do
            do it = 3, 4
               do ih = 1, size(thetas)
                  call add('fine481', scheme, tensions(it), 5.0e-3_dp, 481, 0.1_dp, 1.0_dp, thetas(ih))
               end do
            end do
            do it = 2, 4
               do ib = 1, 3, 2
                  do ih = 1, size(theta_ladder)
                     call add('theta', scheme, tensions(it), breaks(ib), 121, 1.0_dp, 1.0_dp, theta_ladder(ih))
                  end do
               end do
            end do
            do ib = 1, 3, 2
               do ih = 1, 6
                  call add('theta', scheme, tensions(3), breaks(ib), 481, 1.0_dp, 1.0_dp, theta_ladder(ih))
               end do
            end do
         end if
         call add_compression(scheme)
      end do
      call add_slack()
      call add_scenes3d()
   end subroutine build_design

   !> The 3-D scenes (stress_runs%scene_namelist) at Courant 1, 4 and 10.
   subroutine add_scenes3d()
      character(len=12), parameter :: scenes(3) = [character(len=12) :: 'slack3d', 'fairlead3d', 'torque3d']
      real(dp), parameter :: scene_courants(3) = [1.0_dp, 4.0_dp, 10.0_dp], t_ends(3) = [2.0_dp, 4.0_dp, 2.0_dp]
      integer :: isc, ig, ic, ie, nodes
      do isc = 1, size(scenes)
         do ig = 1, 2
            nodes = merge(61, 121, ig == 1)
            if (scenes(isc) == 'fairlead3d') nodes = (nodes + 1)/2
            do ic = 1, size(scene_courants)
               do ie = 1, size(ei_factors)
                  if (quick .and. (ig /= 1 .or. ic /= 2 .or. ie /= 1)) cycle
                  call add('scenes3d', 'rod', 0.0_dp, 0.0_dp, nodes, scene_courants(ic), ei_factors(ie), 0.5_dp, &
                           t_ends(isc), 0.0_dp, wall_short, scenes(isc))
               end do
            end do
         end do
      end do
   end subroutine add_scenes3d

   !> The compression study: grids up to 961 nodes, to t = 0.16 s, a snapshot every millisecond.
   subroutine add_compression(scheme)
      character(*), intent(in) :: scheme
      integer, parameter :: grids(4) = [121, 241, 481, 961]
      integer :: it, ib, ig
      do it = 3, 5
         do ib = 3, 4
            do ig = 1, merge(2, 4, quick)
               if (quick .and. (it /= 4 .or. ib /= 3)) cycle
               call add('compression', scheme, tensions(it), breaks(ib), grids(ig), 1.0_dp, 1.0_dp, 0.5_dp, 0.16_dp, &
                        1.0e-3_dp, wall_compression)
            end do
         end do
      end do
      if (quick) return
      call add('compression', scheme, tensions(4), breaks(3), 481, 1.0_dp, 1.0_dp, damped_theta, 0.16_dp, 1.0e-3_dp, &
               wall_compression)
      call add('compression', scheme, tensions(4), breaks(3), 961, 1.0_dp, 1.0_dp, damped_theta, 0.16_dp, 1.0e-3_dp, &
               wall_compression)
      call add('compression', scheme, tensions(4), breaks(3), 481, 1.0_dp, 1.0e-3_dp, 0.5_dp, 0.16_dp, 1.0e-3_dp, &
               wall_compression)
      call add('compression', scheme, tensions(4), breaks(3), 481, 1.0_dp, 10.0_dp, 0.5_dp, 0.16_dp, 1.0e-3_dp, &
               wall_compression)
   end subroutine add_compression

   !> The slack releases to 2 s (no snapshots: the positions come from the history).
   subroutine add_slack()
      integer :: it, ib, ig, ic
      do it = 1, size(slack_tensions)
         do ib = 1, size(slack_breaks)
            do ig = 1, size(slack_nodes)
               if (quick .and. slack_nodes(ig) /= 61) cycle
               do ic = 1, size(slack_courants)
                  if (quick .and. slack_courants(ic) /= 1) cycle
                  ! Budget: at 20 and 50 kN the 961-node runs at Courant 0.5 would cost about 8 minutes.
                  if (slack_nodes(ig) == 961 .and. slack_courants(ic) < 1 .and. slack_tensions(it) > 5.0e3_dp) cycle
                  call add('slack', 'rod', slack_tensions(it), slack_breaks(ib), slack_nodes(ig), slack_courants(ic), &
                           1.0_dp, 0.5_dp, slack_t_end, 0.0_dp, wall_slack)
               end do
            end do
            ! The box scheme at Courant 1: the defaults (241 nodes) and one grid either side.
            do ig = 1, size(slack_nodes)
               if (quick) then
                  if (slack_nodes(ig) /= 61 .or. (it /= 1 .and. it /= 4) .or. ib /= 1) cycle
               else
                  if (slack_nodes(ig) < 121 .or. slack_nodes(ig) > 481) cycle
               end if
               call add('slack', 'box', slack_tensions(it), slack_breaks(ib), slack_nodes(ig), 1.0_dp, 1.0_dp, 0.5_dp, &
                        slack_t_end, 0.0_dp, wall_slack)
            end do
         end do
      end do
   end subroutine add_slack

   !> Append a run (unless filtered out by only= or scheme=).
   subroutine add(study, scheme, tension, t_break, nodes, courant, ei_factor, theta, t_end, interval, wall_limit, scene)
      character(*), intent(in) :: study, scheme
      real(dp), intent(in) :: tension, t_break, courant, ei_factor, theta
      integer, intent(in) :: nodes
      real(dp), intent(in), optional :: t_end, interval, wall_limit
      character(*), intent(in), optional :: scene
      type(run_spec) :: spec
      if (len_trim(only_study) > 0 .and. index(','//trim(only_study)//',', ','//trim(study)//',') == 0) return
      if (len_trim(only_scheme) > 0 .and. trim(only_scheme) /= scheme) return
      spec%study = study
      spec%scheme = scheme
      spec%tension = tension
      spec%t_break = t_break
      spec%nodes = nodes
      spec%courant = courant
      spec%ei_factor = ei_factor
      spec%theta = theta
      spec%wall_limit = wall_short
      if (present(t_end)) spec%t_end = t_end
      if (present(interval)) spec%interval = interval
      if (present(wall_limit)) spec%wall_limit = wall_limit
      if (present(scene)) spec%scene = scene
      specs = [specs, spec]
   end subroutine add

   !> Reduce the probe's records to one row.
   subroutine read_probe(p, row)
      type(compression_probe), intent(in) :: p
      type(compression_row), intent(out) :: row
      integer :: k
      if (p%n == 0) return
      k = minloc(p%wall_tension(1:p%n), 1)
      if (p%wall_tension(k) < 0) then
         row%peak = -p%wall_tension(k)
         row%peak_time = p%time(k)
         row%length = p%length(k)
         row%euler = p%euler_load(k)
      end if
      do k = 1, p%n
         if (row%euler_time < 0 .and. p%length(k) > 0) then
            if (-p%wall_tension(k) > p%euler_load(k)) row%euler_time = p%time(k)
         end if
         if (row%buckle_time < 0 .and. p%curvature(k) > buckle_curvature) row%buckle_time = p%time(k)
      end do
      row%deflection = maxval(p%deflection(1:p%n))
      row%curvature = maxval(p%curvature(1:p%n))
      row%min_strain = minval(p%min_strain(1:p%n))
   end subroutine read_probe

   !> Short name of how run k ended.
   function tag(k) result(text)
      integer, intent(in) :: k
      character(:), allocatable :: text
      text = outcome_tag(outcomes(k)%complete, outcomes(k)%reason)
   end function tag

   !> Short names of a run's warnings ('' : none), from the driver's wording.
   function warning_codes(text) result(codes)
      character(*), intent(in) :: text
      character(:), allocatable :: codes
      character(len=*), parameter :: phrases(7) = [character(len=25) :: 'energy ledger', 'neighbouring cells turned', &
                                                   'unit circle', 'rejected', 'Courant number taken', 'beyond the range', &
                                                   'below the range']
      character(len=*), parameter :: words(7) = [character(len=12) :: 'ledger', 'kink', 'unit circle', 'rejected', &
                                                 'Courant', 'strain range', 'strain range']
      integer :: j
      codes = ''
      do j = 1, size(phrases)
         if (index(text, trim(phrases(j))) == 0 .or. index(codes, trim(words(j))) > 0) cycle
         if (len(codes) > 0) codes = codes//', '
         codes = codes//trim(words(j))
      end do
   end function warning_codes

   !> The warnings on one line (CSV).
   function one_line(text) result(t)
      character(*), intent(in) :: text
      character(:), allocatable :: t
      integer :: k
      t = ''
      do k = 1, len(text)
         if (text(k:k) == new_line('a')) then
            t = t//' | '
         else if (text(k:k) == '"') then
            t = t//"'"
         else
            t = t//text(k:k)
         end if
      end do
   end function one_line

   !> One row per run.
   subroutine write_csv(path)
      character(*), intent(in) :: path
      integer :: u, k, ios, j
      character(len=512) :: msg
      character(:), allocatable :: positions
      character(len=32) :: buf
      open (newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         write (error_unit, '(a)') 'stress: cannot write '//path//': '//trim(msg)
         error stop 1
      end if
      write (u, '(a)') 'study,scheme,tension_kN,t_break_ms,nodes,courant,bending_stiffness,theta,t_end,dt,outcome,'// &
         'time_reached,energy_drift,dissipated_J,overshoot,ringing,speed_error,drop_error_ms,newton_per_step,'// &
         'max_newton,newton_tension,newton_compression,rejected,rejected_compression,steps,wall_s,courant_used,'// &
         'min_fixed_end_tension_kN,compression_time,max_unit_norm_error,max_turning_angle,min_strain,peak_end_speed,'// &
         'x_0.5,z_0.5,x_1,z_1,x_1.5,z_1.5,x_2,z_2,peak_compression_kN,compressed_length,euler_load_kN,euler_time,'// &
         'buckle_time,max_deflection,warnings,reason'
      do k = 1, n
         associate (s => specs(k), o => outcomes(k), r => rows(k))
            positions = ''
            do j = 1, size(release_times)
               write (buf, '(g0.8)') o%end_x(j)
               positions = positions//','//trim(nan_blank(buf))
               write (buf, '(g0.8)') o%end_z(j)
               positions = positions//','//trim(nan_blank(buf))
            end do
            write (u, '(a,",",a,",",g0.6,",",g0.4,",",i0,",",g0.3,",",g0.4,",",g0.5,",",g0.6,",",g0.6,",",a,'// &
                   '8(",",g0.5),6(",",i0),3(",",g0.4),5(",",g0.5),a,6(",",g0.5),",""",a,""",""",a,"""")') &
               trim(s%study), trim(s%scheme), s%tension/1.0e3_dp, 1.0e3_dp*s%t_break, s%nodes, s%courant, &
               s%ei_factor*paper_bending_stiffness, s%theta, o%t_end, o%dt, tag(k), o%time_reached, &
               o%energy_drift, o%dissipated, o%overshoot, o%ringing, o%speed_error, 1.0e3_dp*o%drop_error, &
               o%newton_per_step, o%max_newton, o%newton_tension, o%newton_compression, o%rejected, &
               o%rejected_compression, o%steps, o%wall, o%courant_used, o%min_wall_tension/1.0e3_dp, &
               o%compression_time, o%max_unit_norm_error, o%max_turning_angle, o%min_strain, o%peak_end_speed, &
               positions, r%peak/1.0e3_dp, r%length, r%euler/1.0e3_dp, r%euler_time, r%buckle_time, r%deflection, &
               one_line(o%warnings), one_line(o%reason)
         end associate
      end do
      close (u)
   end subroutine write_csv

   !> The 3-D scenes: <dir>/stress3d.md (a table, one row per run) and <dir>/stress3d.csv.
   subroutine write_scenes3d(dir)
      character(*), intent(in) :: dir
      integer :: u, k, ios, runs, done
      character(len=512) :: msg
      real(dp) :: wall
      open (newunit=u, file=dir//'/stress3d.csv', status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         write (error_unit, '(a)') 'stress: cannot write '//dir//'/stress3d.csv: '//trim(msg)
         error stop 1
      end if
      write (u, '(a)') 'scene,nodes,courant,bending_stiffness,t_end,dt,outcome,time_reached,energy_drift,steps,rejected,'// &
         'newton_per_step,max_newton,smallest_step_fraction,max_turning_angle,min_strain,wall_s,warnings,reason'
      do k = 1, n
         if (specs(k)%study /= 'scenes3d') cycle
         associate (s => specs(k), o => outcomes(k))
            write (u, '(a,",",i0,",",g0.3,",",g0.4,",",g0.4,",",g0.6,",",a,2(",",g0.5),2(",",i0),",",g0.4,",",i0,'// &
                   '4(",",g0.4),",""",a,""",""",a,"""")') trim(s%scene), s%nodes, s%courant, &
               s%ei_factor*paper_bending_stiffness, o%t_end, o%dt, tag(k), o%time_reached, o%energy_drift, o%steps, &
               o%rejected, o%newton_per_step, o%max_newton, o%min_step/max(o%dt, tiny(1.0_dp)), o%max_turning_angle, &
               o%min_strain, o%wall, one_line(o%warnings), one_line(o%reason)
         end associate
      end do
      close (u)
      open (newunit=u, file=dir//'/stress3d.md', status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         write (error_unit, '(a)') 'stress: cannot write '//dir//'/stress3d.md: '//trim(msg)
         error stop 1
      end if
      runs = count(specs%study == 'scenes3d')
      done = 0
      wall = 0
      do k = 1, n
         if (specs(k)%study /= 'scenes3d') cycle
         if (outcomes(k)%complete) done = done + 1
         wall = wall + outcomes(k)%wall
      end do
      write (u, '(a)') '# Stress tests of the 3-D model'
      write (u, '(a)') ''
      write (u, '(a)') 'Generated by `make stress-3d` (example/stress `only=scenes3d`; also part of `make stress`): '// &
         itext(runs)//' runs, '//itext(done)//' complete, dynamics '//num(wall, 0)//' s on a shared two-core '// &
         'machine. Code: '//trim(code_version)//'. Every run is a row of [stress3d.csv](stress3d.csv); the planar '// &
         'sweep is [stress.md](stress.md), its measures and outcome names apply here.'
      write (u, '(a)') ''
      write (u, '(a)') 'Scenes (example/stress/stress_runs.f90, `scene_namelist`; 60 m of the paper''s cable, '// &
         '`&numerics model = ''3d''`, theta 0.5, the step control of the program): `slack3d`, a slack line hanging '// &
         'between (0, 0, 0) and (40, 20, 0) m let go at end b, to 2 s; `fairlead3d`, in water with a current of '// &
         '0.3 m/s across the plane, the fairlead at (50, 0, 0) m moving 1 m along y (period 2 s), to 4 s; '// &
         '`torque3d`, end b loaded by a force (3000, 500, 1000) N and a torque of 200 N m ramped up over 0.5 s, '// &
         'to 2 s. The Courant number is c dt / ds with c the largest axial wave speed of the static state. '// &
         '*smallest step*: the smallest accepted step / dt (the last step, shortened to land on t_end, '// &
         'left out). *drift*: the ledger''s drift / the initial strain energy.'
      write (u, '(a)') ''
      write (u, '(a)') '| scene | nodes | Courant | EI N m^2 | dt s | outcome | t reached s | steps | rejected | '// &
         'smallest step | Newton / step | max Newton | drift | max turn rad | warnings | wall s |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do k = 1, n
         if (specs(k)%study /= 'scenes3d') cycle
         associate (s => specs(k), o => outcomes(k))
            write (u, '(a)') '| '//trim(s%scene)//' | '//itext(s%nodes)//' | '//num(s%courant, 0)//' | '// &
               sci(s%ei_factor*paper_bending_stiffness, 2)//' | '//sci(o%dt, 2)//' | '//tag(k)//' | '// &
               num(o%time_reached, 3)//' | '//itext(o%steps)//' | '//itext(o%rejected)//' | '// &
               num(o%min_step/max(o%dt, tiny(1.0_dp)), 3)//' | '//num(o%newton_per_step, 1)//' | '// &
               itext(o%max_newton)//' | '//sci(o%energy_drift, 1)//' | '//num(o%max_turning_angle, 2)//' | '// &
               warning_codes(o%warnings)//' | '//num(o%wall, 1)//' |'
         end associate
      end do
      close (u)
   end subroutine write_scenes3d

   !> An empty field for NaN (CSV).
   function nan_blank(text) result(t)
      character(*), intent(in) :: text
      character(:), allocatable :: t
      t = trim(adjustl(text))
      if (index(t, 'NaN') > 0) t = ''
   end function nan_blank

   !> The markdown report.
   subroutine write_markdown(path)
      character(*), intent(in) :: path
      integer :: u, ios
      character(len=512) :: msg
      open (newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         write (error_unit, '(a)') 'stress: cannot write '//path//': '//trim(msg)
         error stop 1
      end if
      write (u, '(a)') '# Stress tests: every run'
      write (u, '(a)') ''
      write (u, '(a,i0,a)') 'Generated by `make stress` (example/stress, in process through the simulation driver, '// &
         'one thread): ', n, ' runs in '//num(total_wall, 0)//' s ('//num(total_wall/60, 1)//' min) on a shared '// &
         'two-core machine. Code: '//trim(code_version)//'. Compiler: '//compiler_version()//', options: '// &
         compiler_options()//'. The stability map that reads these tables is '// &
         '[stability.md](../stability.md); every run is a row of [stress.csv](stress.csv). The 3-D scenes '// &
         '(study scenes3d, `make stress-3d`) have their own page, [stress3d.md](stress3d.md).'
      write (u, '(a)') ''
      call measures_section(u)
      call design_section(u)
      call summary_table(u)
      call slack_section(u)
      call map_table(u, 'box')
      call map_table(u, 'rod')
      call factor_table(u)
      call theta_table(u)
      call compression_table(u)
      call run_table(u, 'grid21', 'All runs: 21 nodes')
      call run_table(u, 'grid121', 'All runs: 121 nodes')
      call run_table(u, 'fine481', 'All runs: 481 nodes')
      close (u)
   end subroutine write_markdown

   subroutine measures_section(u)
      integer, intent(in) :: u
      write (u, '(a)') '## Measures'
      write (u, '(a)') ''
      write (u, '(a)') 'The *tension window* is the part of a run before the fixed end first goes into compression '// &
         '(T(0, t) <= 0), or the whole run if it never does.'
      write (u, '(a)') ''
      write (u, '(a)') '- **outcome**: `complete` (reached t_end) or the named reason the run stopped, at the time '// &
         'reached: `collapse` (box: strain below -0.9; rod: a cell squeezed below 5 % of its length), `frame lost` '// &
         '(box: b0^2 + b3^2 off the unit circle by more than 0.5), `fold` (rod: a turning angle passing half a turn '// &
         'in one step), `newton` (no convergence, divergence or a singular Jacobian), `step budget` (too many rejected '// &
         'attempts), `wall clock` (the run''s limit: 30 s in the short studies, 60 s in `compression`, 600 s in '// &
         '`slack`), `refused` (input checks). A stop after the step control halved the step to its floor is named by '// &
         'the last reason it gave.'
      write (u, '(a)') '- **overshoot**: largest rise of the fixed-end tension above its static value in the tension '// &
         'window, / T_s. Unloading can only lower the tension: a rise is ringing (short waves running ahead of the '// &
         'front), except in the slack cables, whose fall really loads the support.'
      write (u, '(a)') '- **ringing**: (total variation - |net change|) / (2 T_s) of the fixed-end tension in the '// &
         'tension window: the summed height of all rebounds (0 for a monotone drop).'
      write (u, '(a)') '- **speed error**: (peak speed |V| of the released end in the tension window - simple-wave '// &
         'theory) / theory (straight string; not a reference for the slack cables, whose sag is metres). Version 0.1 '// &
         'of these tables took the box scheme''s tangential speed |u|.'
      write (u, '(a)') '- **drop error**: time of the 1 % drop of the fixed-end tension minus simple-wave theory, ms '// &
         '(without the weak shock of the concave law: approximate at 315 and 400 kN).'
      write (u, '(a)') '- **ledger drift**: max |ledger(t) - ledger(0)| / strain energy(0) over the run reached, '// &
         'from the driver (ledger = strain + kinetic + bending + gravity - work of the ends + numerical dissipation '// &
         'booked by the rod at theta > 0.5).'
      write (u, '(a)') '- **Newton**: iterations per accepted step (all iterations, rejected attempts included, / '// &
         'accepted steps) and the most in one accepted step, in the tension window / after it; **rejected**: step '// &
         'attempts rejected by the step control, in all / after the window.'
      write (u, '(a)') '- **turn / unit**: rod: the largest turning angle between two neighbouring cells, rad; box: '// &
         'the largest |b0^2 + b3^2 - 1|. **min strain**: rod: the smallest cell strain; box: the smallest strain '// &
         'at the two end nodes (all its summary keeps).'
      write (u, '(a)') '- **warnings** (the driver''s, docs/theory/numerics.md section 8): `ledger` (drift above 1 %), '// &
         '`kink` (rod: a turn above 1 rad), `unit circle` (box: above 0.05), `rejected` (more than 10 and 1 % of the '// &
         'steps), `Courant` (the Courant number taken differs from the one asked for by more than 1 %), `strain range` '// &
         '(cells stretched or compressed beyond the range of the law, where it was extrapolated).'
      write (u, '(a)') ''
   end subroutine measures_section

   subroutine design_section(u)
      integer, intent(in) :: u
      write (u, '(a)') '## Design'
      write (u, '(a)') ''
      write (u, '(a)') 'Each of the first five studies is run with both schemes; the box runs are the study of '// &
         'version 0.1 (same cases, same snapshot interval 0.01 s, so the same steps).'
      write (u, '(a)') ''
      write (u, '(a)') '- `grid21`, `grid121`: full factorial of tension {2, 50, 180, 315, 400} kN x t_break '// &
         '{0, 0.5, 5, 50} ms x Courant {0.1, 1, 10} x EI {70.6, 0.0706} N m^2 x theta {0.5, 0.55} on 21 and 121 nodes.'
      write (u, '(a)') '- `fine481`: 481 nodes; every tension x every t_break x theta {0.5, 0.55} at Courant 1 '// &
         'and 10; EI / 1000 at 5 ms; Courant 0.1 at 180 and 315 kN.'
      write (u, '(a)') '- `theta`: the time weight from 0.5 to 1 (backward Euler) at 50, 180, 315 kN, t_break 0 and '// &
         '5 ms, 121 nodes, Courant 1; and at 481 nodes for 180 kN.'
      write (u, '(a)') '- `compression`: 180, 315, 400 kN, t_break 5 and 50 ms, 121 to 961 nodes, Courant 1, to '// &
         't = 0.16 s, with a probe of the compressed zone at the fixed end every millisecond.'
      write (u, '(a)') '- t_end = t_break + 2.2 L / c(eps0) (0.16 s in `compression`): the front reaches the fixed '// &
         'end, reflects and is back at the breaking end, so the compression phase is always included.'
      write (u, '(a)') '- `slack`: the slack releases, tension {2, 5, 20, 50} kN x t_break {5, 50} ms, to t = 2 s. '// &
         'Rod at its defaults (averaged mass, theta 0.5, compression by the law) on {61, 121, 241, 481, 961} nodes x '// &
         'Courant {0.5, 1, 2}, except 961 nodes at Courant 0.5 for 20 and 50 kN (left out for the budget: about '// &
         '100 s a run, 8 min in all). Box scheme at Courant 1 on 121, 241 (the defaults) and 481 nodes (a 961-node '// &
         'box run would cost about a minute, 8 min in all). The Courant number is c dt / ds with c '// &
         'the axial wave speed of the static state (rod: the largest over its cells; box: at the end strain; the '// &
         'same here): 294 m/s at 2 kN to 491 m/s at 50 kN. The peer reference below takes c at the stiffest point of '// &
         'the law (1110 m/s): its Courant 0.5 is about 0.13 to 0.22 of ours.'
      write (u, '(a)') '- `scenes3d`: three scenes of the 3-D model at Courant 1, 4 and 10 (36 runs); their rows are '// &
         'in stress.csv, their table in [stress3d.md](stress3d.md).'
      write (u, '(a)') ''
   end subroutine design_section

   !> Runs, outcomes and warnings by study and scheme.
   subroutine summary_table(u)
      integer, intent(in) :: u
      character(len=12), parameter :: studies(6) = [character(len=12) :: 'grid21', 'grid121', 'fine481', 'theta', &
                                                    'compression', 'slack']
      character(len=12), parameter :: tags(9) = [character(len=12) :: 'complete', 'collapse', 'frame lost', 'fold', &
                                                 'newton', 'step budget', 'wall clock', 'non-finite', 'other']
      integer :: is, isc, k, j, counts(size(tags)), runs, warned
      real(dp) :: wall
      character(:), allocatable :: line
      write (u, '(a)') '## Outcome by study and scheme'
      write (u, '(a)') ''
      write (u, '(a)') '*with warnings*: runs that completed with at least one warning. *wall*: the dynamics of all '// &
         'runs of the row, s.'
      write (u, '(a)') ''
      line = '| study | scheme | runs |'
      do j = 1, size(tags)
         line = line//' '//trim(tags(j))//' |'
      end do
      write (u, '(a)') line//' with warnings | wall s |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do is = 1, size(studies)
         do isc = 1, size(schemes)
            runs = 0
            counts = 0
            warned = 0
            wall = 0
            do k = 1, n
               if (specs(k)%study /= studies(is) .or. specs(k)%scheme /= schemes(isc)) cycle
               runs = runs + 1
               wall = wall + outcomes(k)%wall
               if (outcomes(k)%complete .and. len(outcomes(k)%warnings) > 0) warned = warned + 1
               do j = 1, size(tags)
                  if (tag(k) == trim(tags(j))) counts(j) = counts(j) + 1
               end do
               if (tag(k) == 'refused' .or. tag(k) == 'statics') counts(size(tags)) = counts(size(tags)) + 1
            end do
            if (runs == 0) cycle
            line = '| '//trim(studies(is))//' | '//schemes(isc)//' | '//itext(runs)//' |'
            do j = 1, size(tags)
               line = line//' '//itext(counts(j))//' |'
            end do
            write (u, '(a)') line//' '//itext(warned)//' | '//num(wall, 0)//' |'
         end do
      end do
      write (u, '(a)') ''
   end subroutine summary_table

   !> Index of the slack run with these settings (0: none).
   integer function find_slack(scheme, tension, t_break, nodes, courant) result(k)
      character(*), intent(in) :: scheme
      real(dp), intent(in) :: tension, t_break, courant
      integer, intent(in) :: nodes
      do k = 1, n
         if (specs(k)%study == 'slack' .and. specs(k)%scheme == scheme .and. specs(k)%tension == tension .and. &
             specs(k)%t_break == t_break .and. specs(k)%nodes == nodes .and. specs(k)%courant == courant) return
      end do
      k = 0
   end function find_slack

   !> The slack releases.
   subroutine slack_section(u)
      integer, intent(in) :: u
      integer :: it, ib, ig, ic, k, is
      if (count(specs%study == 'slack') == 0) return
      write (u, '(a)') '## Slack releases'
      write (u, '(a)') ''
      write (u, '(a)') 'The paper''s cable hanging at a low tension (2 to 50 kN: sag 5.1 m to 0.22 m) released at '// &
         'end b and followed to t = 2 s, through the recoil, the fall and the buckling of the recoiled cable at the '// &
         'fixed end.'
      write (u, '(a)') ''
      write (u, '(a)') '### The defaults on every slack release (241 nodes, Courant 1)'
      write (u, '(a)') ''
      call slack_header(u, .false.)
      do it = 1, size(slack_tensions)
         do ib = 1, size(slack_breaks)
            do is = size(schemes), 1, -1
               k = find_slack(schemes(is), slack_tensions(it), slack_breaks(ib), default_nodes, 1.0_dp)
               if (k > 0) call slack_row(u, k, .false.)
            end do
         end do
      end do
      write (u, '(a)') ''
      write (u, '(a)') '### Every slack run'
      write (u, '(a)') ''
      call slack_header(u, .true.)
      do it = 1, size(slack_tensions)
         do ib = 1, size(slack_breaks)
            do is = size(schemes), 1, -1
               do ig = 1, size(slack_nodes)
                  do ic = 1, size(slack_courants)
                     k = find_slack(schemes(is), slack_tensions(it), slack_breaks(ib), slack_nodes(ig), slack_courants(ic))
                     if (k > 0) call slack_row(u, k, .true.)
                  end do
               end do
            end do
         end do
      end do
      write (u, '(a)') ''
      call position_tables(u)
      call reference_table(u)
      call courant_table(u)
   end subroutine slack_section

   subroutine slack_header(u, full)
      integer, intent(in) :: u
      logical, intent(in) :: full
      if (full) then
         write (u, '(a)') '| tension kN | t_break ms | scheme | nodes | Courant | outcome | ledger drift | rejected | '// &
            'Newton / step (max) | turn rad / unit | min strain | warnings | wall s |'
         write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      else
         write (u, '(a)') '| tension kN | t_break ms | scheme | outcome | ledger drift | rejected | '// &
            'Newton / step (max) | turn rad / unit | min strain | warnings | wall s |'
         write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|'
      end if
   end subroutine slack_header

   subroutine slack_row(u, k, full)
      integer, intent(in) :: u, k
      logical, intent(in) :: full
      character(:), allocatable :: line, turn
      associate (s => specs(k), o => outcomes(k))
         if (s%scheme == 'rod') then
            turn = num(o%max_turning_angle, 3)
         else
            turn = sci(o%max_unit_norm_error, 1)
         end if
         line = '| '//num(s%tension/1.0e3_dp, 0)//' | '//num(1.0e3_dp*s%t_break, 0)//' | '//trim(s%scheme)
         if (full) line = line//' | '//itext(s%nodes)//' | '//num(s%courant, 1)
         line = line//' | '//ended(k)//' | '//sci(o%energy_drift, 1)//' | '//itext(o%rejected)//' | '// &
                num(o%newton_per_step, 2)//' ('//itext(o%max_newton)//') | '//turn//' | '//num(o%min_strain, 3)//' | '// &
                warning_codes(o%warnings)//' | '//num(o%wall, 1)//' |'
         write (u, '(a)') line
      end associate
   end subroutine slack_row

   !> Released end's position per case: the rod at Courant 1 on every grid, and the box.
   subroutine position_tables(u)
      integer, intent(in) :: u
      integer :: it, ib, ig, is, k, j, finest
      character(:), allocatable :: line
      write (u, '(a)') '### Released end: position'
      write (u, '(a)') ''
      write (u, '(a)') 'x, z of end b (m; end a at the origin, z up) at 0.5, 1, 1.5 and 2 s, Courant 1. In brackets: '// &
         'the distance to the rod''s finest grid (961 nodes), m. `-`: the run stopped before.'
      write (u, '(a)') ''
      do it = 1, size(slack_tensions)
         do ib = 1, size(slack_breaks)
            finest = find_slack('rod', slack_tensions(it), slack_breaks(ib), slack_nodes(size(slack_nodes)), 1.0_dp)
            write (u, '(a)') '**'//num(slack_tensions(it)/1.0e3_dp, 0)//' kN, t_break '// &
               num(1.0e3_dp*slack_breaks(ib), 0)//' ms**'
            write (u, '(a)') ''
            write (u, '(a)') '| scheme | nodes | 0.5 s | 1 s | 1.5 s | 2 s |'
            write (u, '(a)') '|---|---|---|---|---|---|'
            do is = size(schemes), 1, -1
               do ig = 1, size(slack_nodes)
                  k = find_slack(schemes(is), slack_tensions(it), slack_breaks(ib), slack_nodes(ig), 1.0_dp)
                  if (k == 0) cycle
                  line = '| '//trim(specs(k)%scheme)//' | '//itext(specs(k)%nodes)
                  do j = 1, size(release_times)
                     line = line//' | '//xz(outcomes(k)%end_x(j), outcomes(k)%end_z(j))
                     if (finest > 0 .and. finest /= k) line = line//' ('// &
                        dist_text(outcomes(k)%end_x(j), outcomes(k)%end_z(j), outcomes(finest)%end_x(j), &
                                  outcomes(finest)%end_z(j))//')'
                  end do
                  write (u, '(a)') line//' |'
               end do
            end do
            write (u, '(a)') ''
         end do
      end do
   end subroutine position_tables

   !> The rod and the box against the peer lumped-mass runs.
   subroutine reference_table(u)
      integer, intent(in) :: u
      integer, parameter :: compared(3) = [961, 481, 241]
      real(dp) :: px(size(release_times), size(peer_grids)), pz(size(release_times), size(peer_grids))
      logical :: have(size(peer_grids))
      integer :: it, ib, ig, j, k, fine, second, m
      character(:), allocatable :: line
      write (u, '(a)') '### Against the peer reference'
      write (u, '(a)') ''
      write (u, '(a)') 'Reference: the peer lumped-mass runs (bench/peer, lumped.py: velocity Verlet at Courant 0.5 '// &
         'on the largest wave speed, lumped mass, the same law, EI and statics without bending), their finest grid '// &
         '(N segments, N + 1 nodes). *peer spread*: the distance between its two finest grids, a measure of how far '// &
         'the reference itself has converged. The other columns: the distance from the reference position, m, of '// &
         'the rod at Courant 1 on 961, 481 and 241 nodes and of the box scheme at its defaults (241 nodes).'
      write (u, '(a)') ''
      write (u, '(a)') '| case | t s | peer x, z (N) | peer spread | rod 961 | rod 481 | rod 241 | box 241 |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|'
      do it = 1, size(slack_tensions)
         do ib = 1, size(slack_breaks)
            do ig = 1, size(peer_grids)
               call peer_position(trim(peer_dir), slack_tensions(it), slack_breaks(ib), peer_grids(ig), release_times, &
                                  px(:, ig), pz(:, ig), have(ig))
            end do
            fine = 0
            second = 0
            do ig = 1, size(peer_grids)
               if (.not. have(ig)) cycle
               second = fine
               fine = ig
            end do
            do j = 1, size(release_times)
               line = '| '//num(slack_tensions(it)/1.0e3_dp, 0)//' kN, '//num(1.0e3_dp*slack_breaks(ib), 0)//' ms | '// &
                      num(release_times(j), 1)
               if (fine == 0) then
                  write (u, '(a)') line//' | no peer file | | | | | |'
                  cycle
               end if
               line = line//' | '//xz(px(j, fine), pz(j, fine))//' ('//itext(peer_grids(fine))//') | '
               if (second > 0) line = line//dist_text(px(j, fine), pz(j, fine), px(j, second), pz(j, second))
               do m = 1, size(compared)
                  k = find_slack('rod', slack_tensions(it), slack_breaks(ib), compared(m), 1.0_dp)
                  line = line//' | '
                  if (k > 0) line = line//dist_text(outcomes(k)%end_x(j), outcomes(k)%end_z(j), px(j, fine), pz(j, fine))
               end do
               k = find_slack('box', slack_tensions(it), slack_breaks(ib), default_nodes, 1.0_dp)
               line = line//' | '
               if (k > 0) line = line//dist_text(outcomes(k)%end_x(j), outcomes(k)%end_z(j), px(j, fine), pz(j, fine))
               write (u, '(a)') line//' |'
            end do
         end do
      end do
      write (u, '(a)') ''
   end subroutine reference_table

   !> The rod's Courant number: how far the end moves and what the run costs.
   subroutine courant_table(u)
      integer, intent(in) :: u
      integer :: it, ib, ig, ic, k, k1
      character(:), allocatable :: line, moves, drifts, rejects, walls
      write (u, '(a)') '### The rod''s Courant number'
      write (u, '(a)') ''
      write (u, '(a)') 'Per grid, Courant 0.5 / 1 / 2: distance of the released end at 2 s from its position at '// &
         'Courant 1 (m), ledger drift, rejected attempts and wall time (s). `-`: not run or stopped before 2 s.'
      write (u, '(a)') ''
      write (u, '(a)') '| case | nodes | end at 2 s: C 0.5 / C 2 vs C 1, m | ledger drift | rejected | wall s |'
      write (u, '(a)') '|---|---|---|---|---|---|'
      do it = 1, size(slack_tensions)
         do ib = 1, size(slack_breaks)
            do ig = 1, size(slack_nodes)
               k1 = find_slack('rod', slack_tensions(it), slack_breaks(ib), slack_nodes(ig), 1.0_dp)
               if (k1 == 0) cycle
               moves = ''
               drifts = ''
               rejects = ''
               walls = ''
               do ic = 1, size(slack_courants)
                  k = find_slack('rod', slack_tensions(it), slack_breaks(ib), slack_nodes(ig), slack_courants(ic))
                  if (ic > 1) then
                     drifts = drifts//' / '
                     rejects = rejects//' / '
                     walls = walls//' / '
                  end if
                  if (k == 0) then
                     drifts = drifts//'-'
                     rejects = rejects//'-'
                     walls = walls//'-'
                  else
                     drifts = drifts//sci(outcomes(k)%energy_drift, 1)
                     rejects = rejects//itext(outcomes(k)%rejected)
                     walls = walls//num(outcomes(k)%wall, 0)
                  end if
                  if (slack_courants(ic) == 1) cycle
                  if (len(moves) > 0) moves = moves//' / '
                  if (k == 0) then
                     moves = moves//'-'
                  else
                     moves = moves//dist_text(outcomes(k)%end_x(4), outcomes(k)%end_z(4), outcomes(k1)%end_x(4), &
                                              outcomes(k1)%end_z(4))
                  end if
               end do
               line = '| '//num(slack_tensions(it)/1.0e3_dp, 0)//' kN, '//num(1.0e3_dp*slack_breaks(ib), 0)//' ms | '// &
                      itext(slack_nodes(ig))//' | '//moves//' | '//drifts//' | '//rejects//' | '//walls//' |'
               write (u, '(a)') line
            end do
         end do
      end do
      write (u, '(a)') ''
   end subroutine courant_table

   !> Completed runs by tension, grid and EI (grid and fine studies, all
   !> breaks, Courant numbers and theta pooled), for one scheme.
   subroutine map_table(u, scheme)
      integer, intent(in) :: u
      character(*), intent(in) :: scheme
      integer, parameter :: grid_nodes(3) = [21, 121, 481]
      integer :: it, ig, ie, k, runs, done, tension_ok
      character(:), allocatable :: line
      if (count(specs%scheme == scheme .and. is_grid_study(specs%study)) == 0) return
      write (u, '(a)') '## Map, '//scheme//' scheme: runs complete / runs (tension phase ok)'
      write (u, '(a)') ''
      write (u, '(a)') 'Studies grid21, grid121 and fine481; every t_break, Courant number and theta of the study '// &
         'pooled. *tension phase ok*: the run got past the tension window (the fixed end went into compression, or '// &
         'the run completed).'
      write (u, '(a)') ''
      write (u, '(a)') '| tension | 21 nodes | 121 nodes | 481 nodes | 21 nodes, EI / 1000 | 121 nodes, EI / 1000 | '// &
         '481 nodes, EI / 1000 |'
      write (u, '(a)') '|---|---|---|---|---|---|---|'
      do it = 1, size(tensions)
         line = '| '//num(tensions(it)/1.0e3_dp, 0)//' kN'
         do ie = 1, 2
            do ig = 1, 3
               runs = 0
               done = 0
               tension_ok = 0
               do k = 1, n
                  if (.not. is_grid_study(specs(k)%study) .or. specs(k)%scheme /= scheme) cycle
                  if (specs(k)%nodes /= grid_nodes(ig) .or. specs(k)%tension /= tensions(it) .or. &
                      specs(k)%ei_factor /= ei_factors(ie)) cycle
                  runs = runs + 1
                  if (outcomes(k)%complete) done = done + 1
                  if (outcomes(k)%complete .or. outcomes(k)%compression_time > 0) tension_ok = tension_ok + 1
               end do
               line = line//' | '//itext(done)//' / '//itext(runs)//' ('//itext(tension_ok)//')'
            end do
         end do
         write (u, '(a)') line//' |'
      end do
      write (u, '(a)') ''
   end subroutine map_table

   elemental logical function is_grid_study(study)
      character(*), intent(in) :: study
      is_grid_study = study == 'grid21' .or. study == 'grid121' .or. study == 'fine481'
   end function is_grid_study

   !> Outcomes by the level of each factor (grid and fine studies), per scheme.
   subroutine factor_table(u)
      integer, intent(in) :: u
      integer :: f, l, nl, is
      real(dp) :: levels(6)
      character(len=24) :: label
      if (count(is_grid_study(specs%study)) == 0) return
      write (u, '(a)') '## Outcome by factor'
      write (u, '(a)') ''
      write (u, '(a)') 'Studies grid21, grid121 and fine481 pooled. *tension phase ok*: the run reached the end '// &
         'of the tension window (the fixed end went into compression, or the run completed). *stopped*: collapse / '// &
         'frame lost or fold / Newton / other. Medians are over the runs of the level, taken in the tension window.'
      write (u, '(a)') ''
      write (u, '(a)') '| scheme | factor | level | runs | complete | tension phase ok | stopped | with warnings | '// &
         'median overshoot | median \|speed error\| | median ledger drift | median time reached / t_end |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|'
      do is = 1, size(schemes)
         do f = 1, 6
            select case (f)
            case (1); nl = 5; levels(1:5) = tensions
            case (2); nl = 4; levels(1:4) = breaks
            case (3); nl = 3; levels(1:3) = [21.0_dp, 121.0_dp, 481.0_dp]
            case (4); nl = 3; levels(1:3) = courants
            case (5); nl = 2; levels(1:2) = ei_factors
            case (6); nl = 2; levels(1:2) = thetas
            end select
            do l = 1, nl
               select case (f)
               case (1); label = num(levels(l)/1.0e3_dp, 0)//' kN'
               case (2); label = num(levels(l)*1.0e3_dp, 1)//' ms'
               case (3); write (label, '(i0)') nint(levels(l))
               case (4); label = num(levels(l), 1)
               case (5); label = num(levels(l)*paper_bending_stiffness, 4)//' N m^2'
               case (6); label = num(levels(l), 2)
               end select
               call factor_row(u, schemes(is), f, levels(l), trim(label))
            end do
         end do
      end do
      write (u, '(a)') ''
   end subroutine factor_table

   !> One level of one factor.
   subroutine factor_row(u, scheme, f, level, label)
      integer, intent(in) :: u, f
      character(*), intent(in) :: scheme
      real(dp), intent(in) :: level
      character(*), intent(in) :: label
      character(len=10), parameter :: names(6) = [character(len=10) :: 'tension', 't_break', 'nodes', 'Courant', &
                                                   'EI', 'theta']
      logical :: pick(n)
      integer :: k, counts(7)
      real(dp) :: v
      do k = 1, n
         select case (f)
         case (1); v = specs(k)%tension
         case (2); v = specs(k)%t_break
         case (3); v = specs(k)%nodes
         case (4); v = specs(k)%courant
         case (5); v = specs(k)%ei_factor
         case (6); v = specs(k)%theta
         end select
         pick(k) = is_grid_study(specs(k)%study) .and. specs(k)%scheme == scheme .and. abs(v - level) <= 1.0e-9_dp*abs(level)
      end do
      if (count(pick) == 0) return
      counts = 0
      do k = 1, n
         if (.not. pick(k)) cycle
         if (outcomes(k)%complete) counts(1) = counts(1) + 1
         if (outcomes(k)%complete .or. outcomes(k)%compression_time > 0) counts(2) = counts(2) + 1
         select case (tag(k))
         case ('collapse'); counts(3) = counts(3) + 1
         case ('frame lost', 'fold'); counts(4) = counts(4) + 1
         case ('newton'); counts(5) = counts(5) + 1
         case ('complete')
         case default; counts(6) = counts(6) + 1
         end select
         if (outcomes(k)%complete .and. len(outcomes(k)%warnings) > 0) counts(7) = counts(7) + 1
      end do
      write (u, '(a)') '| '//scheme//' | '//trim(names(f))//' | '//label//' | '//itext(count(pick))//' | '// &
         itext(counts(1))//' | '//itext(counts(2))//' | '//itext(counts(3))//' / '//itext(counts(4))//' / '// &
         itext(counts(5))//' / '//itext(counts(6))//' | '//itext(counts(7))//' | '// &
         sci(median(pack(outcomes%overshoot, pick)), 1)//' | '//sci(median(abs(pack(outcomes%speed_error, pick))), 1)// &
         ' | '//sci(median(pack(outcomes%energy_drift, pick)), 1)//' | '// &
         num(median(pack(outcomes%time_reached/outcomes%t_end, pick)), 2)//' |'
   end subroutine factor_row

   !> The theta ladder.
   subroutine theta_table(u)
      integer, intent(in) :: u
      integer :: k, is
      if (count(specs%study == 'theta') == 0) return
      write (u, '(a)') '## Dissipation: the time weight theta'
      write (u, '(a)') ''
      write (u, '(a)') 'Courant 1, EI 70.6 N m^2. theta = 0.5 is the paper''s scheme and the rod''s '// &
         'energy-conserving one; theta > 0.5 damps the shortest waves (box: by (1 - theta) / theta per step) and '// &
         'costs first-order accuracy (the front is smeared: the 1 % drop comes early). The rod books what it damps '// &
         'in its ledger, so its drift stays small; *dissipated* is that energy / the initial strain energy.'
      write (u, '(a)') ''
      write (u, '(a)') '| scheme | tension kN | t_break ms | nodes | theta | outcome | overshoot | ringing | '// &
         'speed error | drop error ms | ledger drift | dissipated | Newton max |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do is = 1, size(schemes)
         do k = 1, n
            if (specs(k)%study /= 'theta' .or. specs(k)%scheme /= schemes(is)) cycle
            associate (s => specs(k), o => outcomes(k))
               write (u, '(a)') '| '//trim(s%scheme)//' | '//num(s%tension/1.0e3_dp, 0)//' | '// &
                  num(1.0e3_dp*s%t_break, 1)//' | '//itext(s%nodes)//' | '//num(s%theta, 4)//' | '//ended(k)//' | '// &
                  sci(o%overshoot, 2)//' | '//sci(o%ringing, 2)//' | '//sci(o%speed_error, 2)//' | '// &
                  sci(1.0e3_dp*o%drop_error, 2)//' | '//sci(o%energy_drift, 1)//' | '// &
                  sci(o%dissipated/o%strain_energy0, 1)//' | '//itext(o%max_newton)//' |'
            end associate
         end do
      end do
      write (u, '(a)') ''
   end subroutine theta_table

   !> The compression study.
   subroutine compression_table(u)
      integer, intent(in) :: u
      integer :: k, is
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (count(specs%study == 'compression') == 0) return
      write (u, '(a)') '## Compression at the fixed end'
      write (u, '(a)') ''
      call wall_table(u)
      write (u, '(a)') 'Courant 1, t_end 0.16 s, a probe every millisecond (from the output fields, the same for '// &
         'both schemes). *into compression*: first time T(0, t) <= 0 (every step). *peak*: largest compression at '// &
         'the fixed end, with the length l_c of the compressed zone (T < 0, from the fixed end) at that time and its '// &
         'Euler load P_E = pi^2 EI / l_c^2. *Euler-unstable*: first time |T(0)| > P_E of the current zone. '// &
         '*buckled*: first time the curvature in the zone departs from its static value by more than 0.1 1/m (a 2 mm '// &
         'buckle at the fastest-growing wavelength; the static curvature is 7e-5 1/m). *max deflection*: largest '// &
         'distance of the zone from its chord (the sag of a long zone included). *pts/wave*: the fastest-growing '// &
         'buckling wavelength 2 pi sqrt(2 EI / |T|) at the peak, in grid intervals. *min strain*: smallest strain in '// &
         'the zone at the snapshots. *turn / unit*: see Measures. Newton and rejected: after the fixed end went into '// &
         'compression.'
      write (u, '(a)') ''
      write (u, '(a)') '| scheme | tension kN | t_break ms | nodes | EI N m^2 | theta | outcome | into compression s | '// &
         'peak kN | l_c m | P_E kN | Euler-unstable s | buckled s | max deflection m | min strain | pts/wave | '// &
         'turn / unit | ledger drift | Newton | rejected |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do is = 1, size(schemes)
         do k = 1, n
            if (specs(k)%study /= 'compression' .or. specs(k)%scheme /= schemes(is)) cycle
            associate (s => specs(k), o => outcomes(k), r => rows(k))
               write (u, '(a)') '| '//trim(s%scheme)//' | '//num(s%tension/1.0e3_dp, 0)//' | '// &
                  num(1.0e3_dp*s%t_break, 1)//' | '//itext(s%nodes)//' | '//num(s%ei_factor*paper_bending_stiffness, 4)// &
                  ' | '//num(s%theta, 2)//' | '//ended(k)//' | '//when(o%compression_time)//' | '// &
                  num(r%peak/1.0e3_dp, 2)//' | '//num(r%length, 3)//' | '//sci(r%euler/1.0e3_dp, 2)//' | '// &
                  when(r%euler_time)//' | '//when(r%buckle_time)//' | '//sci(r%deflection, 2)//' | '// &
                  num(r%min_strain, 3)//' | '// &
                  num(2*pi*sqrt(2*s%ei_factor*paper_bending_stiffness/max(r%peak, 1.0_dp))/(60.0_dp/(s%nodes - 1)), 1)// &
                  ' | '//turn_text(k)//' | '//sci(o%energy_drift, 1)//' | '//itext(o%newton_compression)//' | '// &
                  itext(o%rejected_compression)//' |'
            end associate
         end do
      end do
      write (u, '(a)') ''
   end subroutine compression_table

   !> Turning angle (rod) or unit-norm error (box) of run k.
   function turn_text(k) result(text)
      integer, intent(in) :: k
      character(:), allocatable :: text
      if (specs(k)%scheme == 'rod') then
         text = num(outcomes(k)%max_turning_angle, 3)
      else
         text = sci(outcomes(k)%max_unit_norm_error, 1)
      end if
   end function turn_text

   !> Straight-string theory of the reflection at the fixed end.
   subroutine wall_table(u)
      integer, intent(in) :: u
      real(dp) :: eps0, u_end, eps_wall, wall_tension, capacity(2)
      integer :: k
      write (u, '(a)') 'Straight-string theory first (simple waves). Released from eps0, the breaking end '// &
         'reaches u_end = integral of c d eps from the strain of zero tension to eps0. At the fixed end (u = 0) the '// &
         'change of the Riemann variable doubles: the wall must reach the strain eps_w with integral of c d eps '// &
         'from eps_w to the zero-tension strain = u_end. In compression the tanh law is nearly flat (c tends to '// &
         'sqrt(p5 / m) = 7.8 m/s), so it can stop at most the speeds in the last two columns above the strains -0.3 '// &
         'and -0.9:'
      write (u, '(a)') ''
      write (u, '(a)') '| tension kN | eps0 | u_end m/s | eps_w (straight string) | T(eps_w) kN | capacity to -0.3 m/s | '// &
         'capacity to -0.9 m/s |'
      write (u, '(a)') '|---|---|---|---|---|---|---|'
      do k = 1, size(tensions)
         call wall_reflection(tensions(k), [-0.3_dp, -0.9_dp], eps0, u_end, eps_wall, wall_tension, capacity)
         write (u, '(a)') '| '//num(tensions(k)/1.0e3_dp, 0)//' | '//num(eps0, 4)//' | '//num(u_end, 1)//' | '// &
            num(eps_wall, 3)//' | '//num(wall_tension/1.0e3_dp, 2)//' | '//num(capacity(1), 1)//' | '// &
            num(capacity(2), 1)//' |'
      end do
      write (u, '(a)') ''
      write (u, '(a)') 'Every case above 2 kN asks the straight string for a wall strain far below -0.9: the straight '// &
         'model cannot stop the cable at the fixed end. What the computed model does instead:'
      write (u, '(a)') ''
   end subroutine wall_table

   !> Every run of a study, both schemes.
   subroutine run_table(u, study, title)
      integer, intent(in) :: u
      character(*), intent(in) :: study, title
      integer :: k, is
      if (count(specs%study == study) == 0) return
      write (u, '(a)') '## '//title
      write (u, '(a)') ''
      write (u, '(a)') '| scheme | tension kN | t_break ms | nodes | Courant | EI N m^2 | theta | t_end s | outcome | '// &
         'ledger drift | overshoot | ringing | speed error | drop error ms | Newton max | rejected | turn / unit | '// &
         'warnings | wall s |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do is = 1, size(schemes)
         do k = 1, n
            if (specs(k)%study /= study .or. specs(k)%scheme /= schemes(is)) cycle
            associate (s => specs(k), o => outcomes(k))
               write (u, '(a)') '| '//trim(s%scheme)//' | '//num(s%tension/1.0e3_dp, 0)//' | '// &
                  num(1.0e3_dp*s%t_break, 1)//' | '//itext(s%nodes)//' | '//num(s%courant, 1)//' | '// &
                  num(s%ei_factor*paper_bending_stiffness, 4)//' | '//num(s%theta, 2)//' | '//num(o%t_end, 4)//' | '// &
                  ended(k)//' | '//sci(o%energy_drift, 2)//' | '//sci(o%overshoot, 2)//' | '//sci(o%ringing, 2)//' | '// &
                  sci(o%speed_error, 2)//' | '//sci(1.0e3_dp*o%drop_error, 2)//' | '//itext(o%newton_tension)//'/'// &
                  itext(o%newton_compression)//' | '//itext(o%rejected)//'/'//itext(o%rejected_compression)//' | '// &
                  turn_text(k)//' | '//warning_codes(o%warnings)//' | '//num(o%wall, 2)//' |'
            end associate
         end do
      end do
      write (u, '(a)') ''
   end subroutine run_table

   !> A time, s, or 'never' (negative).
   function when(t) result(text)
      real(dp), intent(in) :: t
      character(:), allocatable :: text
      text = 'never'
      if (t >= 0) text = num(t, 4)
   end function when

   !> 'complete' or 'tag at t = ...' of run k.
   function ended(k) result(text)
      integer, intent(in) :: k
      character(:), allocatable :: text
      if (outcomes(k)%complete) then
         text = 'complete'
      else
         text = tag(k)//' at '//num(outcomes(k)%time_reached, 4)
      end if
   end function ended

   !> 'x, z' with 3 decimals, or '-' (NaN).
   function xz(x, z) result(text)
      real(dp), intent(in) :: x, z
      character(:), allocatable :: text
      if (ieee_is_nan(x) .or. ieee_is_nan(z)) then
         text = '-'
      else
         text = num(x, 3)//', '//num(z, 3)
      end if
   end function xz

   !> Distance between two points, or '-'.
   function dist_text(x1, z1, x2, z2) result(text)
      real(dp), intent(in) :: x1, z1, x2, z2
      character(:), allocatable :: text
      real(dp) :: d
      d = hypot(x1 - x2, z1 - z2)
      if (ieee_is_nan(d)) then
         text = '-'
      else
         text = sci(d, 1)
      end if
   end function dist_text

   !> An integer as text.
   function itext(i) result(text)
      integer, intent(in) :: i
      character(:), allocatable :: text
      character(len=16) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function itext

   !> A number with d decimals and a leading zero ("0.5", not ".5"); '-' for NaN.
   function num(x, d) result(text)
      real(dp), intent(in) :: x
      integer, intent(in) :: d
      character(:), allocatable :: text
      character(len=40) :: buf, form
      if (ieee_is_nan(x)) then
         text = '-'
         return
      end if
      write (form, '(a,i0,a)') '(f40.', d, ')'
      write (buf, form) x
      text = trim(adjustl(buf))
      if (text(1:1) == '.') text = '0'//text
      if (text(1:2) == '-.') text = '-0'//text(2:)
      if (d == 0 .and. text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
   end function num

   !> A number in scientific notation with d decimals ("1.2e-03"); '-' for NaN, '0' for zero.
   function sci(x, d) result(text)
      real(dp), intent(in) :: x
      integer, intent(in) :: d
      character(:), allocatable :: text
      character(len=40) :: buf, form
      integer :: k
      if (ieee_is_nan(x)) then
         text = '-'
         return
      end if
      if (x == 0) then
         text = '0'
         return
      end if
      write (form, '(a,i0,a,i0,a)') '(es', d + 8, '.', d, ')'
      write (buf, form) x
      text = trim(adjustl(buf))
      k = index(text, 'E')
      if (k > 0) text(k:k) = 'e'
   end function sci

   !> Median of the values that are not NaN (NaN if none).
   function median(values) result(m)
      real(dp), intent(in) :: values(:)
      real(dp) :: m
      real(dp), allocatable :: v(:)
      real(dp) :: swap
      integer :: i, j
      v = pack(values, .not. ieee_is_nan(values))
      if (size(v) == 0) then
         m = nan
         return
      end if
      do i = 2, size(v)
         swap = v(i)
         j = i - 1
         do while (j >= 1)
            if (v(j) <= swap) exit
            v(j + 1) = v(j)
            j = j - 1
         end do
         v(j + 1) = swap
      end do
      m = 0.5_dp*(v((size(v) + 1)/2) + v(size(v)/2 + 1))
   end function median
end program stress
