!> Stress tests of xcable (issue 6): where the code gives a trustworthy answer
!> and where it stops, and why.
!>
!>   fpm run --example stress --profile release -- [quick] [out=docs]
!>
!> Every run is made in process (stress_runs: setup_case, solve_statics,
!> run_rupture with the energy ledger and a 30 s wall-clock limit), never by
!> spawning the executable. Studies:
!> - grid21, grid121: the full factorial of tension {2, 50, 180, 315, 400} kN,
!>   t_break {0, 0.5, 5, 50} ms, Courant {0.1, 1, 10}, EI {paper, paper/1000}
!>   and theta {0.5, 0.55} on 21 and 121 nodes (240 runs each);
!> - fine481: 481 nodes, every tension, every t_break and both schemes
!>   at Courant 1 and 10, plus EI/1000 at t_break 5 ms, plus Courant 0.1 at
!>   180 and 315 kN;
!> - theta: the time weight from 0.5 to 1 at t_break 0 and 5 ms (121 nodes,
!>   and 481 nodes at 180 kN): ringing against accuracy;
!> - compression: 180, 315 and 400 kN on 121 to 961 nodes to t = 0.16 s with a
!>   probe of the compressed zone at the fixed end every millisecond.
!> t_end is t_break + 2.2 L / c(eps0): the front reaches the fixed end, reflects
!> and returns to the breaking end (the compression phase included).
!> `quick` runs grid21 and a short compression study only (a smoke test).
!>
!> Writes <out>/stress.md (tables) and <out>/stress.csv (one row per run).
program stress
   use xcable_kinds, only: dp, i8
   use stress_runs, only: run_spec, run_outcome, stress_run, compression_probe, paper_bending_stiffness, wall_reflection
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, compiler_version
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
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
   !> The damped scheme of the sweep (docs/stability.md: why 0.55).
   real(dp), parameter :: damped_theta = 0.55_dp
   real(dp), parameter :: thetas(2) = [0.5_dp, damped_theta]
   !> Curvature change that marks a buckle, 1/m: a 2 mm buckle at the fastest-growing
   !> wavelength (0.9 m at 7 kN); the static curvature is 7e-5 1/m. (A deflection from
   !> the zone's chord would see the sag of a zone tens of metres long.)
   real(dp), parameter :: buckle_curvature = 0.1_dp
   real(dp), parameter :: theta_ladder(9) = [0.5_dp, 0.5025_dp, 0.505_dp, 0.51_dp, 0.52_dp, 0.55_dp, 0.6_dp, &
                                             0.75_dp, 1.0_dp]

   type(run_spec), allocatable :: specs(:)
   type(run_outcome), allocatable :: outcomes(:)
   type(compression_row), allocatable :: rows(:)
   type(compression_probe) :: probe
   character(len=256) :: arg, out_dir
   logical :: quick
   integer :: i, n, nargs
   integer(i8) :: clock_start, clock_now, clock_rate
   real(dp) :: total_wall

   quick = .false.
   out_dir = 'docs'
   nargs = command_argument_count()
   do i = 1, nargs
      call get_command_argument(i, arg)
      if (trim(arg) == 'quick') then
         quick = .true.
      else if (arg(1:4) == 'out=') then
         out_dir = arg(5:)
      else
         write (error_unit, '(a)') 'usage: stress [quick] [out=DIR]'
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
      write (output_unit, '(i4,1x,a12,f6.0,a,f5.1,a,i4,a,f5.1,a,es8.1,a,f6.4,a,f6.3,a)') i, specs(i)%study, &
         specs(i)%tension/1.0e3_dp, ' kN', 1.0e3_dp*specs(i)%t_break, ' ms', specs(i)%nodes, ' nodes C', &
         specs(i)%courant, ' EI', specs(i)%ei_factor*paper_bending_stiffness, ' theta ', specs(i)%theta, &
         '  t ', outcomes(i)%time_reached, ' s  '//outcome_tag(outcomes(i))
      flush (output_unit)
   end do
   call system_clock(clock_now)
   total_wall = real(clock_now - clock_start, dp)/clock_rate
   call write_csv(trim(out_dir)//'/stress.csv')
   call write_markdown(trim(out_dir)//'/stress.md')
   write (output_unit, '(a,f7.1,a)') 'stress: wrote '//trim(out_dir)//'/stress.md and stress.csv in ', total_wall, ' s'

contains

   !> The list of runs.
   subroutine build_design()
      integer :: it, ib, ic, ie, ih, inodes, nodes
      integer, parameter :: grid_nodes(2) = [21, 121]
      do inodes = 1, merge(1, 2, quick)
         nodes = grid_nodes(inodes)
         do it = 1, size(tensions)
            do ib = 1, size(breaks)
               do ic = 1, size(courants)
                  do ie = 1, size(ei_factors)
                     do ih = 1, size(thetas)
                        call add(merge('grid21      ', 'grid121     ', nodes == 21), tensions(it), breaks(ib), nodes, &
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
                  call add('fine481', tensions(it), breaks(ib), 481, 1.0_dp, 1.0_dp, thetas(ih))
                  call add('fine481', tensions(it), breaks(ib), 481, 10.0_dp, 1.0_dp, thetas(ih))
               end do
            end do
            do ih = 1, size(thetas)
               call add('fine481', tensions(it), 5.0e-3_dp, 481, 1.0_dp, 1.0e-3_dp, thetas(ih))
            end do
         end do
         do it = 3, 4
            do ih = 1, size(thetas)
               call add('fine481', tensions(it), 5.0e-3_dp, 481, 0.1_dp, 1.0_dp, thetas(ih))
            end do
         end do
         do it = 2, 4
            do ib = 1, 3, 2
               do ih = 1, size(theta_ladder)
                  call add('theta', tensions(it), breaks(ib), 121, 1.0_dp, 1.0_dp, theta_ladder(ih))
               end do
            end do
         end do
         do ib = 1, 3, 2
            do ih = 1, 6
               call add('theta', tensions(3), breaks(ib), 481, 1.0_dp, 1.0_dp, theta_ladder(ih))
            end do
         end do
      end if
      call add_compression()
   end subroutine build_design

   !> The compression study: grids up to 961 nodes, to t = 0.16 s, a snapshot every millisecond.
   subroutine add_compression()
      integer, parameter :: grids(4) = [121, 241, 481, 961]
      integer :: it, ib, ig
      do it = 3, 5
         do ib = 3, 4
            do ig = 1, merge(2, 4, quick)
               if (quick .and. (it /= 4 .or. ib /= 3)) cycle
               call add('compression', tensions(it), breaks(ib), grids(ig), 1.0_dp, 1.0_dp, 0.5_dp, 0.16_dp, 1.0e-3_dp)
            end do
         end do
      end do
      if (quick) return
      call add('compression', tensions(4), breaks(3), 481, 1.0_dp, 1.0_dp, damped_theta, 0.16_dp, 1.0e-3_dp)
      call add('compression', tensions(4), breaks(3), 961, 1.0_dp, 1.0_dp, damped_theta, 0.16_dp, 1.0e-3_dp)
      call add('compression', tensions(4), breaks(3), 481, 1.0_dp, 1.0e-3_dp, 0.5_dp, 0.16_dp, 1.0e-3_dp)
      call add('compression', tensions(4), breaks(3), 481, 1.0_dp, 10.0_dp, 0.5_dp, 0.16_dp, 1.0e-3_dp)
   end subroutine add_compression

   !> Append a run.
   subroutine add(study, tension, t_break, nodes, courant, ei_factor, theta, t_end, interval)
      character(*), intent(in) :: study
      real(dp), intent(in) :: tension, t_break, courant, ei_factor, theta
      integer, intent(in) :: nodes
      real(dp), intent(in), optional :: t_end, interval
      type(run_spec) :: spec
      spec%study = study
      spec%tension = tension
      spec%t_break = t_break
      spec%nodes = nodes
      spec%courant = courant
      spec%ei_factor = ei_factor
      spec%theta = theta
      if (present(t_end)) spec%t_end = t_end
      if (present(interval)) spec%interval = interval
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

   !> Short name of how a run ended.
   function outcome_tag(o) result(tag)
      type(run_outcome), intent(in) :: o
      character(:), allocatable :: tag
      if (o%complete) then
         tag = 'complete'
      else if (index(o%reason, 'input:') == 1) then
         tag = 'refused'
      else if (index(o%reason, 'statics') > 0) then
         tag = 'statics'
      else if (index(o%reason, 'wall-clock') > 0) then
         tag = 'wall clock'
      else if (index(o%reason, 'rejected attempts by') > 0) then
         tag = 'step budget'
      else if (index(o%reason, 'collapsed') > 0) then
         tag = 'collapse'
      else if (index(o%reason, 'unit circle') > 0) then
         tag = 'frame lost'
      else if (index(o%reason, 'not finite') > 0 .or. index(o%reason, 'non-finite') > 0) then
         tag = 'non-finite'
      else if (index(o%reason, 'Newton') > 0 .or. index(o%reason, 'dgbtrf') > 0) then
         tag = 'newton'
      else
         tag = 'other'
      end if
   end function outcome_tag

   !> One row per run.
   subroutine write_csv(path)
      character(*), intent(in) :: path
      integer :: u, k, ios
      character(len=512) :: msg
      open (newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         write (error_unit, '(a)') 'stress: cannot write '//path//': '//trim(msg)
         error stop 1
      end if
      write (u, '(a)') 'study,tension_kN,t_break_ms,nodes,courant,bending_stiffness,theta,t_end,dt,outcome,'// &
         'time_reached,energy_drift,overshoot,ringing,speed_error,drop_error_ms,max_newton,newton_tension,'// &
         'newton_compression,rejected,rejected_compression,steps,wall_s,min_fixed_end_tension_kN,'// &
         'compression_time,max_unit_norm_error,peak_compression_kN,compressed_length,euler_load_kN,euler_time,'// &
         'buckle_time,max_deflection,reason'
      do k = 1, n
         associate (s => specs(k), o => outcomes(k), r => rows(k))
            write (u, '(a,",",g0.6,",",g0.4,",",i0,",",g0.3,",",g0.4,",",g0.5,",",g0.6,",",g0.6,",",a,'// &
                   '6(",",g0.5),6(",",i0),",",g0.4,3(",",g0.6),6(",",g0.5),",""",a,"""")') &
               trim(s%study), s%tension/1.0e3_dp, 1.0e3_dp*s%t_break, s%nodes, s%courant, &
               s%ei_factor*paper_bending_stiffness, s%theta, o%t_end, o%dt, outcome_tag(o), o%time_reached, &
               o%energy_drift, o%overshoot, o%ringing, o%speed_error, 1.0e3_dp*o%drop_error, &
               o%max_newton, o%newton_tension, o%newton_compression, o%rejected, o%rejected_compression, o%steps, &
               o%wall, o%min_wall_tension/1.0e3_dp, o%compression_time, o%max_unit_norm_error, &
               r%peak/1.0e3_dp, r%length, r%euler/1.0e3_dp, r%euler_time, r%buckle_time, r%deflection, &
               quote_free(o%reason)
         end associate
      end do
      close (u)
   end subroutine write_csv

   !> A reason without double quotes (CSV).
   function quote_free(text) result(t)
      character(*), intent(in) :: text
      character(:), allocatable :: t
      integer :: k
      t = text
      do k = 1, len(t)
         if (t(k:k) == '"') t(k:k) = "'"
      end do
   end function quote_free

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
      write (u, '(a)') '# Stress tests (issue 6)'
      write (u, '(a)') ''
      write (u, '(a,i0,a)') 'Generated by `make stress` (example/stress, in process, one thread): ', n, &
         ' runs in '//num(total_wall, 0)//' s. Compiler: '//compiler_version()//'. The stability map that reads these '// &
         'tables is [stability.md](stability.md); every run is a row of [stress.csv](stress.csv).'
      write (u, '(a)') ''
      write (u, '(a)') '## Measures'
      write (u, '(a)') ''
      write (u, '(a)') 'The *tension window* is the part of a run before the fixed end first goes into compression '// &
         '(T(0, t) <= 0), or the whole run if it never does.'
      write (u, '(a)') ''
      write (u, '(a)') '- **outcome**: `complete` (reached t_end) or the named reason the run stopped, at the time '// &
         'reached: `collapse` (strain below -0.9), `frame lost` (b0^2 + b3^2 off the unit circle by more than 0.5), '// &
         '`newton` (no convergence, divergence or a singular Jacobian after every halving of the step), '// &
         '`step budget`, `wall clock` (30 s per run), `refused` (input checks).'
      write (u, '(a)') '- **overshoot**: largest rise of the fixed-end tension above its static value in the tension '// &
         'window, / T_s. Unloading can only lower the tension: a rise is ringing (the box scheme''s short waves '// &
         'run ahead of the front at Courant < 1), except in the slack 2 kN cable, whose fall really loads the support.'
      write (u, '(a)') '- **ringing**: (total variation - |net change|) / (2 T_s) of the fixed-end tension in the '// &
         'tension window: the summed height of all rebounds (0 for a monotone drop).'
      write (u, '(a)') '- **speed error**: (peak breaking-end speed in the tension window - simple-wave theory) / '// &
         'theory (straight string; not a reference for the 2 kN cable, whose sag is metres).'
      write (u, '(a)') '- **drop error**: time of the 1 % drop of the fixed-end tension minus simple-wave theory, ms '// &
         '(without the weak shock of the concave law: approximate at 315 and 400 kN).'
      write (u, '(a)') '- **energy drift**: max |ledger(t) - ledger(0)| / strain energy(0) over the run reached '// &
         '(ledger = strain + kinetic + bending + gravity - work of the end force).'
      write (u, '(a)') '- **Newton**: most iterations in one accepted step, in the tension window / after it; '// &
         '**rejected**: step attempts rejected by the step control (halved and retried), in all / after the window.'
      write (u, '(a)') ''
      write (u, '(a)') '## Design'
      write (u, '(a)') ''
      write (u, '(a)') '- `grid21`, `grid121`: full factorial of tension {2, 50, 180, 315, 400} kN x t_break '// &
         '{0, 0.5, 5, 50} ms x Courant c(eps0) dt / ds {0.1, 1, 10} x EI {70.6, 0.0706} N m^2 x theta {0.5, '// &
         '0.55} on 21 and 121 nodes.'
      write (u, '(a)') '- `fine481`: 481 nodes; every tension x every t_break x both schemes at Courant 1 '// &
         'and 10; EI / 1000 at 5 ms; Courant 0.1 at 180 and 315 kN.'
      write (u, '(a)') '- `theta`: the time weight from 0.5 (the paper''s) to 1 (backward Euler) at 50, 180, 315 kN, '// &
         't_break 0 and 5 ms, 121 nodes, Courant 1; and at 481 nodes for 180 kN.'
      write (u, '(a)') '- `compression`: 180, 315, 400 kN, t_break 5 and 50 ms, 121 to 961 nodes, Courant 1, to '// &
         't = 0.16 s, with a probe of the compressed zone at the fixed end every millisecond.'
      write (u, '(a)') '- t_end = t_break + 2.2 L / c(eps0) (0.16 s in `compression`): the front reaches the fixed '// &
         'end, reflects and is back at the breaking end, so the compression phase is always included.'
      write (u, '(a)') ''
      call map_table(u)
      call factor_table(u)
      call theta_table(u)
      call compression_table(u)
      call run_table(u, 'grid21', 'All runs: 21 nodes')
      call run_table(u, 'grid121', 'All runs: 121 nodes')
      call run_table(u, 'fine481', 'All runs: 481 nodes')
      close (u)
   end subroutine write_markdown

   !> Completed runs by tension, grid and EI (grid and fine studies, all
   !> breaks, Courant numbers and schemes pooled).
   subroutine map_table(u)
      integer, intent(in) :: u
      integer, parameter :: grid_nodes(3) = [21, 121, 481]
      integer :: it, ig, ie, k, runs, done, tension_ok
      character(:), allocatable :: line
      write (u, '(a)') '## Map: runs complete / runs (tension phase ok)'
      write (u, '(a)') ''
      write (u, '(a)') 'Studies grid21, grid121 and fine481; every t_break, Courant number and scheme of the study '// &
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
                  if (.not. (specs(k)%study == 'grid21' .or. specs(k)%study == 'grid121' .or. &
                             specs(k)%study == 'fine481')) cycle
                  if (specs(k)%nodes /= grid_nodes(ig) .or. specs(k)%tension /= tensions(it) .or. &
                      specs(k)%ei_factor /= ei_factors(ie)) cycle
                  runs = runs + 1
                  if (outcomes(k)%complete) done = done + 1
                  if (outcomes(k)%complete .or. outcomes(k)%compression_time > 0) tension_ok = tension_ok + 1
               end do
               line = line//' | '//num(real(done, dp), 0)//' / '//num(real(runs, dp), 0)//' ('// &
                      num(real(tension_ok, dp), 0)//')'
            end do
         end do
         write (u, '(a)') line//' |'
      end do
      write (u, '(a)') ''
   end subroutine map_table

   !> Outcomes by the level of each factor (grid and fine studies).
   subroutine factor_table(u)
      integer, intent(in) :: u
      integer :: f, l, nl
      real(dp) :: levels(6)
      character(len=24) :: label
      write (u, '(a)') '## Outcome by factor'
      write (u, '(a)') ''
      write (u, '(a)') 'Studies grid21, grid121 and fine481 pooled. *tension phase ok*: the run reached the end '// &
         'of the tension window (the fixed end went into compression, or the run completed). Medians are over the '// &
         'runs of the level, taken in the tension window.'
      write (u, '(a)') ''
      write (u, '(a)') '| factor | level | runs | complete | tension phase ok | collapse | frame lost | newton | '// &
         'other | median overshoot | median \|speed error\| | median time reached / t_end |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|'
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
            call factor_row(u, f, levels(l), trim(label))
         end do
      end do
      write (u, '(a)') ''
   end subroutine factor_table

   !> One level of one factor.
   subroutine factor_row(u, f, level, label)
      integer, intent(in) :: u, f
      real(dp), intent(in) :: level
      character(*), intent(in) :: label
      character(len=10), parameter :: names(6) = [character(len=10) :: 'tension', 't_break', 'nodes', 'Courant', &
                                                   'EI', 'theta']
      logical :: pick(n)
      integer :: k, counts(6)
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
         pick(k) = (specs(k)%study == 'grid21' .or. specs(k)%study == 'grid121' .or. specs(k)%study == 'fine481') &
                   .and. abs(v - level) <= 1.0e-9_dp*abs(level)
      end do
      counts = 0
      do k = 1, n
         if (.not. pick(k)) cycle
         if (outcomes(k)%complete) counts(1) = counts(1) + 1
         if (outcomes(k)%complete .or. outcomes(k)%compression_time > 0) counts(2) = counts(2) + 1
         select case (outcome_tag(outcomes(k)))
         case ('collapse'); counts(3) = counts(3) + 1
         case ('frame lost'); counts(4) = counts(4) + 1
         case ('newton'); counts(5) = counts(5) + 1
         case ('complete')
         case default; counts(6) = counts(6) + 1
         end select
      end do
      write (u, '(a,7(" | ",i0),2(a,es8.1),a,f5.2,a)') '| '//trim(names(f))//' | '//label, count(pick), counts, &
         ' | ', median(pack(outcomes%overshoot, pick)), ' | ', median(abs(pack(outcomes%speed_error, pick))), ' | ', &
         median(pack(outcomes%time_reached/outcomes%t_end, pick)), ' |'
   end subroutine factor_row

   !> The theta ladder.
   subroutine theta_table(u)
      integer, intent(in) :: u
      integer :: k
      write (u, '(a)') '## Dissipation: the time weight theta'
      write (u, '(a)') ''
      write (u, '(a)') 'Courant 1, EI 70.6 N m^2. theta = 0.5 is the paper''s scheme (no damping); theta > 0.5 '// &
         'damps the shortest waves by (1 - theta) / theta per step and costs first-order accuracy (the front is '// &
         'smeared: the 1 % drop comes early).'
      write (u, '(a)') ''
      write (u, '(a)') '| tension kN | t_break ms | nodes | theta | outcome | overshoot | ringing | speed error | '// &
         'drop error ms | energy drift | Newton |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|'
      do k = 1, n
         if (specs(k)%study /= 'theta') cycle
         associate (s => specs(k), o => outcomes(k))
            write (u, '("| ",a," | ",a," | ",i0," | ",f6.4," | ",a,4(" | ",es9.2)," | ",es8.1," | ",i0," |")') &
               num(s%tension/1.0e3_dp, 0), num(1.0e3_dp*s%t_break, 1), s%nodes, s%theta, ended(o), o%overshoot, o%ringing, &
               o%speed_error, 1.0e3_dp*o%drop_error, o%energy_drift, o%max_newton
         end associate
      end do
      write (u, '(a)') ''
   end subroutine theta_table

   !> The compression study.
   subroutine compression_table(u)
      integer, intent(in) :: u
      integer :: k
      real(dp), parameter :: pi = acos(-1.0_dp)
      write (u, '(a)') '## Compression at the fixed end'
      write (u, '(a)') ''
      call wall_table(u)
      write (u, '(a)') 'Courant 1, t_end 0.16 s, a probe every millisecond. *into compression*: first time '// &
         'T(0, t) <= 0. *peak*: largest compression at the fixed end, with the length l_c of the compressed '// &
         'zone (T < 0, from the fixed end) at that time and its Euler load P_E = pi^2 EI / l_c^2. *Euler-unstable*: '// &
         'first time |T(0)| > P_E of the current zone. *buckled*: first time the curvature in the zone departs from '// &
         'its static value by more than 0.1 1/m (a 2 mm buckle at the fastest-growing wavelength; the static '// &
         'curvature is 7e-5 1/m). *max deflection*: largest distance of the zone from its chord (the sag of a long '// &
         'zone included). *pts/wave*: the fastest-growing buckling wavelength 2 pi sqrt(2 EI / |T|) at the peak, in grid '// &
         'intervals. *min strain*: smallest strain in the zone at the snapshots (a run stops when a step would take '// &
         'any strain below -0.9). Newton and rejected: after the fixed end went into compression.'
      write (u, '(a)') ''
      write (u, '(a)') '| tension kN | t_break ms | nodes | EI N m^2 | theta | outcome | into compression s | '// &
         'peak kN | l_c m | P_E kN | Euler-unstable s | buckled s | max deflection m | min strain | pts/wave | '// &
         'Newton | rejected |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do k = 1, n
         if (specs(k)%study /= 'compression') cycle
         associate (s => specs(k), o => outcomes(k), r => rows(k))
            write (u, '("| ",a," | ",a," | ",i0," | ",a," | ",f4.2," | ",a," | ",a," | ",f6.2,'// &
                   '" | ",f6.3," | ",es8.2," | ",a," | ",a," | ",es8.2," | ",f6.3," | ",f5.1,2(" | ",i0)," |")') &
               num(s%tension/1.0e3_dp, 0), num(1.0e3_dp*s%t_break, 1), s%nodes, num(s%ei_factor*paper_bending_stiffness, &
               4), s%theta, ended(o), &
               when(o%compression_time), r%peak/1.0e3_dp, r%length, r%euler/1.0e3_dp, when(r%euler_time), when(r%buckle_time), &
               r%deflection, r%min_strain, &
               2*pi*sqrt(2*s%ei_factor*paper_bending_stiffness/max(r%peak, 1.0_dp))/(60.0_dp/(s%nodes - 1)), &
               o%newton_compression, o%rejected_compression
         end associate
      end do
      write (u, '(a)') ''
   end subroutine compression_table

   !> Straight-string theory of the reflection at the fixed end.
   subroutine wall_table(u)
      integer, intent(in) :: u
      real(dp) :: eps0, u_end, eps_wall, wall_tension, capacity(2)
      integer :: k
      write (u, '(a)') 'Straight-string theory first (simple waves, PHYSICS.md). Released from eps0, the breaking end '// &
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

   !> Every run of a study.
   subroutine run_table(u, study, title)
      integer, intent(in) :: u
      character(*), intent(in) :: study, title
      integer :: k
      write (u, '(a)') '## '//title
      write (u, '(a)') ''
      write (u, '(a)') '| tension kN | t_break ms | nodes | Courant | EI N m^2 | theta | t_end s | outcome | '// &
         'energy drift | overshoot | ringing | speed error | drop error ms | Newton | rejected | wall s |'
      write (u, '(a)') '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do k = 1, n
         if (specs(k)%study /= study) cycle
         associate (s => specs(k), o => outcomes(k))
            write (u, '("| ",a," | ",a," | ",i0," | ",a," | ",a," | ",f4.2," | ",f6.4," | ",a,'// &
                   '5(" | ",es9.2)," | ",i0,"/",i0," | ",i0,"/",i0," | ",a," |")') &
               num(s%tension/1.0e3_dp, 0), num(1.0e3_dp*s%t_break, 1), s%nodes, num(s%courant, 1), &
               num(s%ei_factor*paper_bending_stiffness, 4), s%theta, o%t_end, ended(o), o%energy_drift, o%overshoot, &
               o%ringing, o%speed_error, 1.0e3_dp*o%drop_error, o%newton_tension, o%newton_compression, o%rejected, &
               o%rejected_compression, num(o%wall, 3)
         end associate
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

   !> 'complete' or 'tag at t = ...'.
   function ended(o) result(text)
      type(run_outcome), intent(in) :: o
      character(:), allocatable :: text
      if (o%complete) then
         text = 'complete'
      else
         text = outcome_tag(o)//' at '//num(o%time_reached, 4)
      end if
   end function ended

   !> A number with d decimals and a leading zero ("0.5", not ".5").
   function num(x, d) result(text)
      real(dp), intent(in) :: x
      integer, intent(in) :: d
      character(:), allocatable :: text
      character(len=40) :: buf, form
      write (form, '(a,i0,a)') '(f40.', d, ')'
      write (buf, form) x
      text = trim(adjustl(buf))
      if (text(1:1) == '.') text = '0'//text
      if (text(1:2) == '-.') text = '-0'//text(2:)
      if (d == 0 .and. text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
   end function num

   !> Median of the values that are not NaN (NaN if none).
   function median(values) result(m)
      real(dp), intent(in) :: values(:)
      real(dp) :: m
      real(dp), allocatable :: v(:)
      real(dp) :: swap
      integer :: i, j
      v = pack(values, .not. ieee_is_nan(values))
      if (size(v) == 0) then
         ! No finite value: NaN if there were values (all NaN), 0 if none.
         m = 0
         if (size(values) > 0) m = values(1)
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
