!> Work-precision benchmark of xcable (issue 5).
!>
!>   fpm run --example bench --profile release -- [quick] [exe=bin/xcable] [work=build/bench] [out=docs]
!>
!> For fast_180kN and slow_315kN it runs the `xcable` executable (the whole
!> process, one thread, median of at least three runs) on a ladder of grids
!> at fixed Courant numbers c(eps0) dt / ds = 0.5, 1, 2, on a ladder of time
!> steps at 241 nodes and on grids between, and measures per run:
!> - the peak breaking-end speed, while the fixed end is in tension, against
!>   simple-wave theory (bench_theory);
!> - the time of the 1 % drop of the fixed-end tension against simple-wave
!>   theory with the ramp, the wall reflection and the weak shock fitted;
!> - the tension field at 10 ms intervals while the fixed end is in tension,
!>   against the Courant-1 runs on 961 and 481 nodes (Newton tolerance 1e-10),
!>   Richardson-extrapolated when the observed order on 241/481/961 nodes is
!>   within 0.3 of 2; mean and max of |error| / T_s.
!> The timed runs use newton_tol = 1e-7 (a table shows what the tolerance
!> changes). At the target configuration of each case it also times the run
!> with more or less output and with the energy ledger.
!>
!> Writes <out>/benchmark_tables.md (markdown) and <out>/benchmark.dat (data
!> of the figure, bench/benchmark.gp). `quick` runs only the targets and the
!> output costs (for before/after timings) and reuses the reference fields
!> that the last full run saved in <work>.
program bench
   use xcable_kinds, only: dp, i8
   use xcable_error, only: error_type
   use xcable_io_input, only: case_config, read_config
   use xcable_case, only: setup_case
   use xcable_model_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_solver_banded, only: band_matrix
   use xcable_dynamics, only: dynamics_options
   use bench_theory, only: wave_reference, simple_wave_reference
   use bench_runs, only: run_spec, run_result, run_case, median, count_instructions
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   implicit none

   !> A paper case, its target configuration and the targets.
   type :: case_def
      character(len=16) :: name = ''
      real(dp) :: tension = 0, t_break = 0, t_end = 0
      integer :: target_nodes = 241
      real(dp) :: target_courant = 1
      !> Targets: |speed error|, |drop error| (s), mean field error (0: not a target), wall (s).
      real(dp) :: max_speed = 0, max_drop = 0, max_field = 0, max_wall = 0.1_dp
   end type case_def

   !> Errors of one run.
   type :: run_errors
      !> Time at which the fixed end goes into compression (end of the window), s.
      real(dp) :: t_tension = 0
      !> (peak end speed - theory) / theory.
      real(dp) :: speed = 0
      !> Time of the 1 % drop minus theory, s.
      real(dp) :: drop = 0
      !> Mean and max |T - T_ref| / T_s over nodes and snapshots in the window.
      real(dp) :: field_mean = 0, field_max = 0
   end type run_errors

   !> Reference tension field of a case.
   type :: field_reference
      logical :: ok = .false.
      !> Grid (m), snapshot times (s), tension (nodes, snapshots), N.
      real(dp), allocatable :: s(:), times(:), tension(:, :)
      !> Observed order from 241/481/961 nodes, and whether extrapolated.
      real(dp) :: order = 0
      logical :: extrapolated = .false.
      !> Mean |correction| / T_s: the uncertainty of the reference.
      real(dp) :: uncertainty = 0
      !> Where it comes from.
      character(len=160) :: source = ''
   end type field_reference

   integer, parameter :: ladder_nodes(6) = [31, 61, 121, 241, 481, 961]
   real(dp), parameter :: ladder_courant(3) = [0.5_dp, 1.0_dp, 2.0_dp]
   integer, parameter :: dt_nodes = 241
   real(dp), parameter :: dt_courant(6) = [0.25_dp, 0.75_dp, 1.25_dp, 1.5_dp, 3.0_dp, 4.0_dp]
   integer, parameter :: between_nodes(7) = [91, 151, 161, 181, 201, 301, 361]
   real(dp), parameter :: tolerances(5) = [1.0e-5_dp, 1.0e-6_dp, 1.0e-8_dp, 1.0e-9_dp, 1.0e-10_dp]
   real(dp), parameter :: bench_tol = 1.0e-7_dp, reference_tol = 1.0e-10_dp
   real(dp), parameter :: length = 60
   character(len=*), parameter :: all_fields = 'tension shear strain u v x z curvature'
   integer, parameter :: max_runs = 80

   type(case_def) :: cases(2)
   type(run_spec) :: specs(max_runs)
   type(run_result) :: results(max_runs)
   type(run_errors) :: errors(max_runs)
   character(len=16) :: kinds(max_runs)
   type(wave_reference) :: ref
   type(field_reference) :: field
   type(cable_model) :: model
   character(len=512) :: arg, exe, work, out
   logical :: quick
   integer :: i, ic, n, md, dat, round
   real(dp) :: nan, speed_start, speed_end
   !> Timing rounds: at most max_rounds (runs under 0.3 s), 5 under 3 s, else 3.
   integer, parameter :: max_rounds = 11

   nan = ieee_value(1.0_dp, ieee_quiet_nan)
   quick = .false.
   exe = 'bin/xcable'
   work = 'build/bench'
   out = 'docs'
   do i = 1, command_argument_count()
      call get_command_argument(i, arg)
      if (arg == 'quick') then
         quick = .true.
      else if (arg(1:4) == 'exe=') then
         exe = arg(5:)
      else if (arg(1:5) == 'work=') then
         work = arg(6:)
      else if (arg(1:4) == 'out=') then
         out = arg(5:)
      else
         write (error_unit, '(a)') 'usage: bench [quick] [exe=bin/xcable] [work=build/bench] [out=docs]'
         error stop 2
      end if
   end do
   call execute_command_line('mkdir -p '//trim(work))

   cases(1) = case_def('fast_180kN', 180.0e3_dp, 0.005_dp, 0.14_dp, 201, 1.0_dp, 1.0e-3_dp, 0.05e-3_dp, 0, 0.1_dp)
   cases(2) = case_def('slow_315kN', 315.0e3_dp, 0.05_dp, 0.16_dp, 201, 2.0_dp, 0, 0, 5.0e-3_dp, 0.1_dp)

   if (quick) then
      open (newunit=md, file=trim(work)//'/benchmark_quick.md', status='replace', action='write')
   else
      open (newunit=md, file=trim(out)//'/benchmark_tables.md', status='replace', action='write')
      open (newunit=dat, file=trim(out)//'/benchmark.dat', status='replace', action='write')
      write (dat, '(a)') '# xcable work-precision benchmark (example/bench); one gnuplot index per series:'
      write (dat, '(a)') '# 0-2 fast_180kN nodes ladder at Courant 0.5, 1, 2; 3 its dt ladder at 241 nodes; 4 its target;'
      write (dat, '(a)') '# 5 its grids between at Courant 1; 6-11 the same for slow_315kN'
      write (dat, '(a)') '# columns: nodes courant wall[s] |speed error| |1% drop error|[ms] mean|dT|/Ts max|dT|/Ts '// &
         'reached_t_end(1/0)'
   end if

   speed_start = machine_speed()
   call say('# xcable work-precision benchmark')
   call say('')
   call say('Generated by `make bench` (example/bench/). Wall time: the whole `xcable` process (start-up, statics, '// &
            'dynamics, HDF5 output), one thread, release build; median of 11 runs (5 above 0.3 s, 3 above 3 s), '// &
            'taken in rounds over all configurations of a case. Timed runs: newton_tol = 1e-7, tension snapshots '// &
            'every 10 ms, no energy ledger, no gnuplot text (the cost of more output is in the last table of each '// &
            'case).')

   do ic = 1, 2
      call case_model(cases(ic), model)
      call simple_wave_reference(model%law, model%mass, length, model%law%strain_at(cases(ic)%tension), &
                                 cases(ic)%t_break, 0.01_dp, ref)
      call print_reference(cases(ic), ref)
      n = 0
      do i = 1, max_runs
         results(i) = run_result()
      end do
      call build_runs(cases(ic))
      ! Rounds: every run once per round, so that a busy spell of this shared
      ! machine spreads over all configurations instead of spoiling one.
      do round = 1, max_rounds
         do i = 1, n
            if (round > rounds_of(i)) cycle
            write (error_unit, '(a,i0,a,i0,a,i0,2a)') 'bench: round ', round, ', run ', i, '/', n, ' ', &
               trim(specs(i)%label)
            call run_case(specs(i), trim(exe), trim(work), results(i))
         end do
      end do
      call build_field_reference(cases(ic), field)
      do i = 1, n
         call measure(cases(ic), results(i), ref, field, errors(i))
      end do
      call print_tables(cases(ic))
      if (.not. quick) call write_data(ic)
   end do
   speed_end = machine_speed()
   call say('')
   call say('Machine speed during the benchmark (LU factorisation and 20 substitutions of a 1687 x 1687 band '// &
            'matrix, kl = 7, ku = 10, in process): '//trim(real_fmt(1.0e3_dp*speed_start, '(f8.2)'))// &
            ' ms at the start, '//trim(real_fmt(1.0e3_dp*speed_end, '(f8.2)'))//' ms at the end. This '// &
            'machine is shared: the same work takes up to twice as long at busy times, so compare times within '// &
            'one benchmark run.')
   if (.not. quick) close (dat)
   close (md)

contains

   !> Print a line to stdout and the markdown file.
   subroutine say(text)
      character(*), intent(in) :: text
      write (output_unit, '(a)') text
      write (md, '(a)') text
   end subroutine say

   !> A real in a format, trimmed.
   function real_fmt(x, fmt) result(text)
      real(dp), intent(in) :: x
      character(*), intent(in) :: fmt
      character(len=32) :: text
      write (text, fmt) x
      text = adjustl(text)
   end function real_fmt

   !> Rounds of run i from its first wall time (references: one, untimed).
   integer function rounds_of(i)
      integer, intent(in) :: i
      if (kinds(i) == 'reference') then
         rounds_of = 1
      else if (results(i)%repeats == 0) then
         rounds_of = max_rounds
      else if (results(i)%walls(1) < 0.3_dp) then
         rounds_of = max_rounds
      else if (results(i)%walls(1) < 3.0_dp) then
         rounds_of = 5
      else
         rounds_of = 3
      end if
   end function rounds_of

   !> Median time (s) of a fixed in-process kernel: what this machine gives now.
   real(dp) function machine_speed()
      type(band_matrix) :: a
      type(error_type), allocatable :: err
      real(dp), allocatable :: b(:)
      real(dp) :: times(7)
      integer :: r, k, j, nn
      integer(i8) :: c0, c1, rate
      nn = 1687
      call a%init(nn, 7, 10)
      allocate (b(nn))
      do r = 1, size(times)
         call system_clock(c0, rate)
         do j = 1, nn
            do k = max(1, j - 10), min(nn, j + 7)
               a%ab(a%row(k, j), j) = 1/real(1 + abs(k - j) + mod(7*k + 3*j, 5), dp)
            end do
            a%ab(a%row(j, j), j) = 4
         end do
         call a%factor(err)
         do k = 1, 20
            b = 1
            call a%solve(b, err)
         end do
         call system_clock(c1)
         times(r) = real(c1 - c0, dp)/rate
      end do
      machine_speed = median(times)
   end function machine_speed

   !> The model of a case, built from a namelist like the app does.
   subroutine case_model(c, model)
      type(case_def), intent(in) :: c
      type(cable_model), intent(out) :: model
      type(case_config) :: config
      type(error_type), allocatable :: error
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      integer :: unit
      character(:), allocatable :: path
      path = trim(work)//'/'//trim(c%name)//'_model.nml'
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a,es23.16,a)') '&static tension = ', c%tension, ' /'
      write (unit, '(a,es23.16,a)') '&rupture t_break = ', c%t_break, ' /'
      write (unit, '(a,es23.16,a)') '&numerics t_end = ', c%t_end, ' /'
      write (unit, '(3a)') "&output file = '", trim(work)//'/unused.h5', "' /"
      close (unit)
      call read_config(path, config, error)
      if (.not. allocated(error)) call setup_case(config, model, s, newton, dyn, error)
      if (allocated(error)) then
         write (error_unit, '(a)') 'bench: '//error%message
         error stop 1
      end if
      if (abs(model%length - length) > 1.0e-12_dp) error stop 'bench: the paper cable is 60 m long'
   end subroutine case_model

   !> The runs of a case.
   subroutine build_runs(c)
      type(case_def), intent(in) :: c
      integer :: a, b
      logical :: cached
      if (.not. quick) then
         do b = 1, size(ladder_courant)
            do a = 1, size(ladder_nodes)
               call add(c, ladder_nodes(a), ladder_courant(b), 'ladder')
            end do
         end do
         do b = 1, size(dt_courant)
            call add(c, dt_nodes, dt_courant(b), 'dt')
         end do
         do a = 1, size(between_nodes)
            call add(c, between_nodes(a), 1.0_dp, 'between')
         end do
         do b = 1, size(tolerances)
            call add(c, c%target_nodes, c%target_courant, 'tol', tol=tolerances(b))
         end do
      end if
      if (find(c%target_nodes, c%target_courant, 'ladder') == 0 .and. find(c%target_nodes, c%target_courant, 'between') &
          == 0) call add(c, c%target_nodes, c%target_courant, 'target')
      inquire (file=trim(work)//'/reference_'//trim(c%name)//'.bin', exist=cached)
      if (.not. quick .or. .not. cached) then
         do a = 4, 6
            call add(c, ladder_nodes(a), 1.0_dp, 'reference', tol=reference_tol)
         end do
      end if
      call add(c, c%target_nodes, c%target_courant, 'cost', fields='')
      call add(c, c%target_nodes, c%target_courant, 'cost', fields=all_fields)
      call add(c, c%target_nodes, c%target_courant, 'cost', fields=all_fields, gnuplot=.true.)
      call add(c, c%target_nodes, c%target_courant, 'cost', energy=.true.)
      call add(c, c%target_nodes, c%target_courant, 'cost', fields=all_fields, gnuplot=.true., energy=.true.)
   end subroutine build_runs

   !> Append a run.
   subroutine add(c, nodes, courant, kind, fields, energy, gnuplot, interval, tol)
      type(case_def), intent(in) :: c
      integer, intent(in) :: nodes
      real(dp), intent(in) :: courant
      character(*), intent(in) :: kind
      character(*), intent(in), optional :: fields
      logical, intent(in), optional :: energy, gnuplot
      real(dp), intent(in), optional :: interval, tol
      character(len=96) :: label
      n = n + 1
      if (n > max_runs) error stop 'bench: too many runs'
      specs(n) = run_spec()
      specs(n)%tension = c%tension
      specs(n)%t_break = c%t_break
      specs(n)%t_end = c%t_end
      specs(n)%nodes = nodes
      specs(n)%courant = courant
      specs(n)%fields = 'tension'
      specs(n)%newton_tol = bench_tol
      if (present(fields)) specs(n)%fields = fields
      if (present(energy)) specs(n)%energy = energy
      if (present(gnuplot)) specs(n)%gnuplot = gnuplot
      if (present(interval)) specs(n)%interval = interval
      if (present(tol)) specs(n)%newton_tol = tol
      write (label, '(a,a,i0,a,f4.2,3a,i0)') trim(c%name), '_n', nodes, '_c', courant, '_', trim(kind), '_', n
      specs(n)%label = trim(label)
      kinds(n) = kind
   end subroutine add

   !> Index of the run of a kind with these nodes and Courant number (0: none).
   integer function find(nodes, courant, kind) result(idx)
      integer, intent(in) :: nodes
      real(dp), intent(in) :: courant
      character(*), intent(in) :: kind
      integer :: j
      idx = 0
      do j = 1, n
         if (specs(j)%nodes == nodes .and. abs(specs(j)%courant - courant) < 1.0e-9_dp .and. kinds(j) == kind) then
            idx = j
            return
         end if
      end do
   end function find

   !> The target run of the current case.
   integer function target_run() result(idx)
      idx = find(cases(ic)%target_nodes, cases(ic)%target_courant, 'ladder')
      if (idx == 0) idx = find(cases(ic)%target_nodes, cases(ic)%target_courant, 'between')
      if (idx == 0) idx = find(cases(ic)%target_nodes, cases(ic)%target_courant, 'target')
   end function target_run

   !> Courant number c(eps0) dt / ds of the step actually taken.
   real(dp) function actual_courant(j)
      integer, intent(in) :: j
      actual_courant = ref%speed0*results(j)%step/(length/(specs(j)%nodes - 1))
   end function actual_courant

   !> The simple-wave references of a case.
   subroutine print_reference(c, r)
      type(case_def), intent(in) :: c
      type(wave_reference), intent(in) :: r
      character(len=1024) :: line
      call say('')
      call say('## '//trim(c%name))
      call say('')
      write (line, '(a,f6.1,a,f5.1,a,f7.5,a,f7.2,a,f6.3,a)') 'T_s = ', 1.0e-3_dp*r%tension, ' kN, t_br = ', &
         1.0e3_dp*c%t_break, ' ms, eps0 = ', r%eps0, ', c(eps0) = ', r%speed0, ' m/s, L / c(eps0) = ', &
         1.0e3_dp*length/r%speed0, ' ms. References (straight string, simple-wave theory; the sag and gravity '// &
         'change them by about 1e-4, well under 1 %):'
      call say(trim(line))
      call say('')
      write (line, '(a,f8.4,a)') '- peak breaking-end speed: integral of c d eps from T = 0 to eps0 = ', &
         r%end_speed, ' m/s;'
      call say(trim(line))
      if (r%shock_jump > 1.0e-9_dp) then
         write (line, '(a,f8.4,a,f8.4,a,es9.2,a,f6.1,a)') '- 1 % drop of the fixed-end tension: ', &
            1.0e3_dp*r%drop_time, ' ms with the weak shock fitted (the characteristic eps_inc alone: ', &
            1.0e3_dp*r%drop_time_characteristic, ' ms); the shock reaches the wall with a strain jump of ', &
            r%shock_jump, ' (it forms ', r%shock_distance, ' m from the breaking end);'
      else if (r%shock_distance < huge(1.0_dp)) then
         write (line, '(a,f8.4,a,f6.1,a)') '- 1 % drop of the fixed-end tension: ', 1.0e3_dp*r%drop_time, &
            ' ms. The law is concave at eps0, so later characteristics are faster, but the first cross ', &
            r%shock_distance, ' m from the breaking end, beyond the 60 m cable: no shock reaches the wall, and the '// &
            'characteristic eps_inc gives the drop;'
      else
         write (line, '(a,f8.4,a)') '- 1 % drop of the fixed-end tension: ', 1.0e3_dp*r%drop_time, &
            ' ms (the law is convex between eps_inc and eps0: a rarefaction, no shock);'
      end if
      call say(trim(line))
      write (line, '(a,f7.3,a,es8.1,a)') '- first disturbance at the wall ', 1.0e3_dp*r%front_time, &
         ' ms; the waves reflected from the wall before the drop slow the eps_inc characteristic by at most ', &
         1.0e3_dp*r%interaction_bound, ' ms.'
      call say(trim(line))
   end subroutine print_reference

   !> The reference tension field from the Courant-1 reference runs on 241, 481 and 961 nodes.
   subroutine build_field_reference(c, f)
      type(case_def), intent(in) :: c
      type(field_reference), intent(out) :: f
      integer :: i241, i481, i961, j, k, m, unit, ios, nw, nn
      real(dp) :: t_window, d1, d2, cnt
      character(:), allocatable :: cache
      cache = trim(work)//'/reference_'//trim(c%name)//'.bin'
      i241 = find(241, 1.0_dp, 'reference')
      i481 = find(481, 1.0_dp, 'reference')
      i961 = find(961, 1.0_dp, 'reference')
      if (i241 == 0 .or. i481 == 0 .or. i961 == 0) then
         call load_reference(c, f)
         return
      end if
      if (.not. (results(i241)%ok .and. results(i481)%ok .and. results(i961)%ok)) return
      t_window = compression_time(results(i961))
      nw = count(results(i961)%snapshot_time > 0 .and. results(i961)%snapshot_time <= t_window)
      if (nw == 0) return
      allocate (f%times(nw))
      f%times = pack(results(i961)%snapshot_time, results(i961)%snapshot_time > 0 .and. &
                     results(i961)%snapshot_time <= t_window)
      ! Observed order on the 241-node points.
      d1 = 0
      d2 = 0
      cnt = 0
      do j = 1, nw
         do k = 1, 241
            d1 = d1 + abs(value_at(i481, 2*k - 1, f%times(j)) - value_at(i241, k, f%times(j)))
            d2 = d2 + abs(value_at(i961, 4*k - 3, f%times(j)) - value_at(i481, 2*k - 1, f%times(j)))
            cnt = cnt + 1
         end do
      end do
      f%order = log(d1/d2)/log(2.0_dp)
      f%extrapolated = abs(f%order - 2) <= 0.3_dp
      if (f%extrapolated) then
         nn = 481
         allocate (f%s(nn), f%tension(nn, nw))
         f%uncertainty = 0
         do j = 1, nw
            do k = 1, nn
               f%s(k) = length*(k - 1)/(nn - 1)
               f%tension(k, j) = value_at(i961, 2*k - 1, f%times(j)) + &
                                 (value_at(i961, 2*k - 1, f%times(j)) - value_at(i481, k, f%times(j)))/3
               f%uncertainty = f%uncertainty + abs(value_at(i961, 2*k - 1, f%times(j)) - value_at(i481, k, f%times(j)))/3
            end do
         end do
         f%uncertainty = f%uncertainty/(nn*nw)/c%tension
         f%source = '961 and 481 nodes at Courant 1, Richardson-extrapolated (p = 2)'
      else
         nn = 961
         allocate (f%s(nn), f%tension(nn, nw))
         do j = 1, nw
            do k = 1, nn
               f%s(k) = length*(k - 1)/(nn - 1)
               f%tension(k, j) = value_at(i961, k, f%times(j))
            end do
         end do
         f%uncertainty = d2/cnt/c%tension/max(2**f%order - 1, 1.0_dp)
         f%source = '961 nodes at Courant 1 (observed order too far from 2 to extrapolate)'
      end if
      f%ok = .true.
      open (newunit=unit, file=cache, status='replace', action='write', access='stream', form='unformatted', iostat=ios)
      if (ios /= 0) return
      m = len_trim(f%source)
      write (unit) nn, nw, f%order, f%extrapolated, f%uncertainty, m, f%source(1:m), f%s, f%times, f%tension
      close (unit)
   end subroutine build_field_reference

   !> Reference saved by the last full run.
   subroutine load_reference(c, f)
      type(case_def), intent(in) :: c
      type(field_reference), intent(inout) :: f
      integer :: unit, ios, nn, nw, m
      open (newunit=unit, file=trim(work)//'/reference_'//trim(c%name)//'.bin', status='old', action='read', &
            access='stream', form='unformatted', iostat=ios)
      if (ios /= 0) return
      read (unit, iostat=ios) nn, nw, f%order, f%extrapolated, f%uncertainty, m
      if (ios /= 0) return
      f%source = ''
      read (unit, iostat=ios) f%source(1:m)
      allocate (f%s(nn), f%times(nw), f%tension(nn, nw))
      read (unit, iostat=ios) f%s, f%times, f%tension
      close (unit)
      f%ok = ios == 0
      f%source = trim(f%source)//' (saved by the last full run)'
   end subroutine load_reference

   !> Tension at node k of run j at snapshot time t (NaN if absent).
   real(dp) function value_at(j, k, t)
      integer, intent(in) :: j, k
      real(dp), intent(in) :: t
      integer :: m
      value_at = nan
      if (.not. allocated(results(j)%tension)) return
      do m = 1, size(results(j)%snapshot_time)
         if (abs(results(j)%snapshot_time(m) - t) < 1.0e-7_dp) then
            if (k <= size(results(j)%tension, 1)) value_at = results(j)%tension(k, m)
            return
         end if
      end do
   end function value_at

   !> First time the fixed-end tension is <= 0 (end of the history if never), s.
   real(dp) function compression_time(r)
      type(run_result), intent(in) :: r
      integer :: i
      compression_time = r%time(size(r%time))
      do i = 2, size(r%time)
         if (r%fixed_end_tension(i) <= 0) then
            compression_time = r%time(i - 1) + (r%time(i) - r%time(i - 1))*r%fixed_end_tension(i - 1)/ &
                               (r%fixed_end_tension(i - 1) - r%fixed_end_tension(i))
            return
         end if
      end do
   end function compression_time

   !> Errors of one run against the references.
   subroutine measure(c, r, w, f, e)
      type(case_def), intent(in) :: c
      type(run_result), intent(in) :: r
      type(wave_reference), intent(in) :: w
      type(field_reference), intent(in) :: f
      type(run_errors), intent(out) :: e
      integer :: i, j, k, m, nn, cnt
      real(dp) :: peak, t0, x, tref, err
      e%speed = nan
      e%drop = nan
      e%field_mean = nan
      e%field_max = nan
      if (.not. r%ok) return
      if (size(r%time) < 2) return
      e%t_tension = compression_time(r)
      peak = 0
      do i = 1, size(r%time)
         if (r%time(i) <= e%t_tension) peak = max(peak, abs(r%end_velocity(i)))
      end do
      e%speed = (peak - w%end_speed)/w%end_speed
      t0 = r%fixed_end_tension(1)
      do i = 2, size(r%time)
         if (r%fixed_end_tension(i) <= 0.99_dp*t0) then
            e%drop = r%time(i - 1) + (r%time(i) - r%time(i - 1))*(0.99_dp*t0 - r%fixed_end_tension(i - 1))/ &
                     (r%fixed_end_tension(i) - r%fixed_end_tension(i - 1)) - w%drop_time
            exit
         end if
      end do
      if (.not. f%ok .or. .not. allocated(r%tension)) return
      nn = size(r%tension, 1)
      if (nn < 2) return
      e%field_mean = 0
      e%field_max = 0
      cnt = 0
      do j = 1, size(f%times)
         m = 0
         do i = 1, size(r%snapshot_time)
            if (abs(r%snapshot_time(i) - f%times(j)) < 1.0e-7_dp) m = i
         end do
         if (m == 0) then
            e%field_mean = nan
            e%field_max = nan
            return
         end if
         do k = 1, nn
            x = length*(k - 1)/(nn - 1)
            tref = interpolate(f%s, f%tension(:, j), x)
            err = abs(r%tension(k, m) - tref)/c%tension
            e%field_mean = e%field_mean + err
            e%field_max = max(e%field_max, err)
            cnt = cnt + 1
         end do
      end do
      e%field_mean = e%field_mean/cnt
   end subroutine measure

   !> Linear interpolation on an increasing grid (exact at its points).
   pure real(dp) function interpolate(xg, yg, x)
      real(dp), intent(in) :: xg(:), yg(:), x
      integer :: i
      real(dp) :: w
      i = max(1, min(size(xg) - 1, int((x - xg(1))/(xg(size(xg)) - xg(1))*(size(xg) - 1)) + 1))
      do while (i > 1 .and. xg(i) > x)
         i = i - 1
      end do
      do while (i < size(xg) - 1 .and. xg(i + 1) < x)
         i = i + 1
      end do
      w = (x - xg(i))/(xg(i + 1) - xg(i))
      if (abs(x - xg(i)) < 1.0e-9_dp) w = 0
      if (abs(x - xg(i + 1)) < 1.0e-9_dp) w = 1
      interpolate = (1 - w)*yg(i) + w*yg(i + 1)
   end function interpolate

   !> The tables of a case.
   subroutine print_tables(c)
      type(case_def), intent(in) :: c
      integer :: j, base, t
      integer, allocatable :: order(:)
      real(dp) :: instructions(max_runs)
      real(dp) :: t_base
      character(len=1024) :: line
      type(case_config) :: defaults
      call say('')
      if (field%ok) then
         write (line, '(a,f5.2,a,es8.1,a,f5.1,a)') '- tension field: '//trim(field%source)//'; observed order '// &
            'on 241/481/961 nodes ', field%order, ', uncertainty of the reference about ', field%uncertainty, &
            ' T_s (mean); snapshots from 10 ms to ', 1.0e3_dp*maxval(field%times), ' ms (the fixed end in tension).'
         call say(trim(line))
      else
         call say('- tension field: no reference (run the full benchmark once).')
      end if
      t = target_run()
      call say('')
      call say('### '//trim(c%name)//': target')
      call say('')
      call say('| configuration | wall (s) | end speed error | 1 % drop error (ms) | mean abs(dT)/T_s | met |')
      call say('|---|---:|---:|---:|---:|:---:|')
      if (t > 0) then
         write (line, '(a,i0,a,f4.2,a,f8.4,a,es9.2,a,f8.4,a,es9.2,3a)') '| ', specs(t)%nodes, ' nodes, Courant ', &
            specs(t)%courant, ' | ', results(t)%wall, ' | ', errors(t)%speed, ' | ', 1.0e3_dp*errors(t)%drop, ' | ', &
            errors(t)%field_mean, ' | ', trim(merge('yes', 'no ', target_met(c, t))), ' |'
         call say(trim(line))
      end if
      write (line, '(a,f5.3,a)') '| target | <= ', c%max_wall, ' | '//trim(merge('<= 0.1 %', '        ', &
                                                                               c%max_speed > 0))//' | '// &
         trim(merge('<= 0.05 ', '        ', c%max_drop > 0))//' | '//trim(merge('<= 5e-3', '       ', &
                                                                               c%max_field > 0))//' | |'
      call say(trim(line))
      if (.not. quick) then
         call say('')
         call say('### '//trim(c%name)//': grids at fixed Courant numbers')
         call table_head()
         do j = 1, n
            if (kinds(j) == 'ladder') call table_row(j)
         end do
         call say('')
         call say('### '//trim(c%name)//': time steps at 241 nodes')
         call table_head()
         order = runs_by_courant()
         do j = 1, size(order)
            call table_row(order(j))
         end do
         call say('')
         call say('### '//trim(c%name)//': grids between, at Courant 1')
         call table_head()
         do j = 1, n
            if (kinds(j) == 'between' .or. (kinds(j) == 'ladder' .and. abs(specs(j)%courant - 1) < 1.0e-9_dp &
                                            .and. specs(j)%nodes >= 61 .and. specs(j)%nodes <= 481)) call table_row(j)
         end do
         call say('')
         call say('### '//trim(c%name)//': Newton tolerance at the target configuration ('// &
                  trim(adjustl(real_fmt(defaults%newton_tol, '(es8.1)')))//' is the default)')
         call table_head('newton_tol')
         order = [integer ::]
         do j = 1, n
            if (kinds(j) == 'tol' .or. j == t) order = [order, j]
         end do
         call sort_runs(order, -specs(order)%newton_tol)
         do j = 1, size(order)
            call table_row(order(j), specs(order(j))%newton_tol)
         end do
      else
         call say('')
         call table_head()
         if (t > 0) call table_row(t)
      end if
      call say('')
      call say('### '//trim(c%name)//': cost of output and diagnostics ('//trim(int_str(c%target_nodes))// &
               ' nodes, Courant '//trim(real_fmt(c%target_courant, '(f5.2)'))//')')
      call say('')
      call say('| output | wall (s) | change | instructions (1e6) | change |')
      call say('|---|---:|---:|---:|---:|')
      base = 0
      do j = 1, n
         if (kinds(j) == 'cost' .and. specs(j)%fields == '') base = j
      end do
      t_base = results(max(base, 1))%wall
      do j = 1, n
         if (kinds(j) /= 'cost' .and. j /= t) cycle
         instructions(j) = 0
         if (.not. quick) instructions(j) = count_instructions(specs(j), trim(exe), trim(work))
      end do
      do j = 1, n
         if (kinds(j) /= 'cost' .and. j /= t) cycle
         if (instructions(max(base, 1)) > 0) then
            write (line, '(a,f8.4,a,sp,f6.1,ss,a,f8.1,a,sp,f6.1,ss,a)') '| '//trim(cost_label(j))//' | ', results(j)%wall, &
               ' | ', 100*(results(j)%wall/t_base - 1), ' % | ', 1.0e-6_dp*instructions(j), ' | ', &
               100*(instructions(j)/instructions(max(base, 1)) - 1), ' % |'
         else
            write (line, '(a,f8.4,a,sp,f6.1,ss,a)') '| '//trim(cost_label(j))//' | ', results(j)%wall, ' | ', &
               100*(results(j)%wall/t_base - 1), ' % | | |'
         end if
         call say(trim(line))
      end do
   end subroutine print_tables

   !> Whether run j meets the targets of case c.
   logical function target_met(c, j)
      type(case_def), intent(in) :: c
      integer, intent(in) :: j
      target_met = results(j)%wall <= c%max_wall .and. results(j)%exit_code == 0
      if (c%max_speed > 0) target_met = target_met .and. abs(errors(j)%speed) <= c%max_speed
      if (c%max_drop > 0) target_met = target_met .and. abs(errors(j)%drop) <= c%max_drop
      if (c%max_field > 0) target_met = target_met .and. errors(j)%field_mean <= c%max_field
   end function target_met

   character(len=96) function cost_label(j)
      integer, intent(in) :: j
      if (specs(j)%fields == '') then
         cost_label = 'no fields (snapshot times only)'
      else if (specs(j)%fields == 'tension') then
         cost_label = 'tension (as timed above)'
      else
         cost_label = 'all 8 fields'
      end if
      cost_label = trim(cost_label)//', every '//trim(real_fmt(1.0e3_dp*specs(j)%interval, '(f5.1)'))//' ms'
      if (specs(j)%gnuplot) cost_label = trim(cost_label)//' + gnuplot text'
      if (specs(j)%energy) cost_label = trim(cost_label)//' + energy ledger'
   end function cost_label

   character(len=16) function int_str(i)
      integer, intent(in) :: i
      write (int_str, '(i0)') i
   end function int_str

   subroutine table_head(extra)
      character(*), intent(in), optional :: extra
      call say('')
      if (present(extra)) then
         call say('| '//extra//' | nodes | ds (m) | Courant | dt (us) | steps | Newton it. / step | factorisations | '// &
                  'wall (s) | reached (s) | end speed error | 1 % drop error (ms) | mean abs(dT)/T_s | max abs(dT)/T_s |')
         call say('|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
      else
         call say('| nodes | ds (m) | Courant | dt (us) | steps | Newton it. / step | factorisations | wall (s) | '// &
                  'reached (s) | end speed error | 1 % drop error (ms) | mean abs(dT)/T_s | max abs(dT)/T_s |')
         call say('|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
      end if
   end subroutine table_head

   subroutine table_row(j, extra)
      integer, intent(in) :: j
      real(dp), intent(in), optional :: extra
      character(len=512) :: line
      character(len=24) :: reached, lead
      lead = ''
      if (present(extra)) write (lead, '(a,es7.0,a)') '| ', extra, ' '
      if (.not. results(j)%ok) then
         write (line, '(2a,i0,a,i0,a)') trim(lead), '| ', specs(j)%nodes, ' | | | | | | | | no result (exit ', &
            results(j)%exit_code, ') | | | | |'
         call say(trim(line))
         return
      end if
      write (reached, '(f6.4)') results(j)%time_reached
      if (results(j)%exit_code /= 0) reached = trim(reached)//' (failed)'
      write (line, '(2a,i0,a,f6.4,a,f5.3,a,f7.2,a,i0,a,f5.2,a,i0,a,f8.4,3a,es9.2,a,f9.4,a,es9.2,a,es9.2,a)') &
         trim(lead), '| ', specs(j)%nodes, ' | ', length/(specs(j)%nodes - 1), ' | ', actual_courant(j), ' | ', &
         1.0e6_dp*results(j)%step, ' | ', results(j)%steps, ' | ', &
         real(results(j)%newton_iterations, dp)/max(results(j)%steps, 1), ' | ', results(j)%factorisations, ' | ', &
         results(j)%wall, ' | ', trim(reached), ' | ', errors(j)%speed, ' | ', 1.0e3_dp*errors(j)%drop, ' | ', &
         errors(j)%field_mean, ' | ', errors(j)%field_max, ' |'
      call say(trim(line))
   end subroutine table_row

   !> The figure's data of the current case: three ladders, the dt ladder, the target, the grids between.
   subroutine write_data(ic)
      integer, intent(in) :: ic
      integer :: k, j
      integer, allocatable :: order(:)
      logical :: keep
      do k = 1, 6
         do j = 1, n
            if (.not. results(j)%ok) cycle
            select case (k)
            case (1:3)
               keep = kinds(j) == 'ladder' .and. abs(specs(j)%courant - ladder_courant(k)) < 1.0e-9_dp
            case (4)
               keep = .false.
            case (5)
               keep = j == target_run()
            case default
               keep = kinds(j) == 'between'
            end select
            if (.not. keep) cycle
            call data_line(j)
         end do
         if (k == 4) then
            order = runs_by_courant()
            do j = 1, size(order)
               call data_line(order(j))
            end do
         end if
         if (k < 6 .or. ic == 1) write (dat, '(/)')
      end do
   end subroutine write_data

   !> One line of the figure's data.
   subroutine data_line(j)
      integer, intent(in) :: j
      if (.not. results(j)%ok) return
      write (dat, '(i5,f7.3,es12.4,4es12.4,i3)') specs(j)%nodes, actual_courant(j), results(j)%wall, &
         abs(errors(j)%speed), 1.0e3_dp*abs(errors(j)%drop), errors(j)%field_mean, errors(j)%field_max, &
         merge(1, 0, results(j)%exit_code == 0)
   end subroutine data_line

   !> The runs on dt_nodes nodes (ladder and dt ladder), by increasing Courant number.
   function runs_by_courant() result(order)
      integer, allocatable :: order(:)
      integer :: j
      order = [integer ::]
      do j = 1, n
         if (specs(j)%nodes == dt_nodes .and. (kinds(j) == 'ladder' .or. kinds(j) == 'dt')) order = [order, j]
      end do
      call sort_runs(order, specs(order)%courant)
   end function runs_by_courant

   !> Sort run indices by increasing key (insertion sort).
   subroutine sort_runs(order, key)
      integer, intent(inout) :: order(:)
      real(dp), intent(in) :: key(:)
      real(dp) :: k_sorted(size(key)), kt
      integer :: j, k, tmp
      k_sorted = key
      do j = 2, size(order)
         k = j
         do while (k > 1)
            if (k_sorted(k - 1) <= k_sorted(k)) exit
            tmp = order(k)
            order(k) = order(k - 1)
            order(k - 1) = tmp
            kt = k_sorted(k)
            k_sorted(k) = k_sorted(k - 1)
            k_sorted(k - 1) = kt
            k = k - 1
         end do
      end do
   end subroutine sort_runs
end program bench
