!> Work-precision benchmark of xcable, for both discretisations.
!>
!>   fpm run --example bench --profile release -- [quick] [exe=bin/xcable] [work=build/bench] [out=docs/measurements/data]
!>                                                 [version=TEXT] [jobs=2]
!>
!> For fast_180kN and slow_315kN it runs the `xcable` executable (the whole
!> process, one thread) in three variants: the box scheme (&numerics scheme =
!> 'box', the paper's scheme of version 0.1) and the rod (scheme = 'rod') with
!> the averaged and the lumped mass matrix. Ladders: grids of 31 (box only),
!> 61, 121, 241, 481, 961 nodes at Courant numbers c(eps0) dt / ds = 0.5, 1, 2
!> and grids of 91..361 nodes at Courant 1 for every variant; for the box as in
!> version 0.1 also its time steps at 241 nodes and its Newton tolerance at its
!> target. Per run it measures:
!> - the peak breaking-end speed while the fixed end is in tension, and the
!>   plateau speed (the time mean after the ramp while the fixed end is in
!>   tension), against simple-wave theory (bench_theory);
!> - the time of the 1 % drop of the fixed-end tension against simple-wave
!>   theory with the ramp, the wall reflection and the weak shock fitted;
!> - the tension field at 10 ms intervals while the fixed end is in tension,
!>   against the variant's own Courant-1 runs on 961 and 481 nodes (Newton
!>   tolerance 1e-10), Richardson-extrapolated when the observed order on
!>   241/481/961 nodes is within 0.3 of 2 (bench_measure); the references of
!>   the variants are compared with each other.
!> At the target configuration of each variant it runs the rod with theta =
!> 0.5, 0.55 and 0.6 (what damping costs at the front) and with
!> reuse_jacobian = .true., and the output costs.
!>
!> Timing: every configuration of a case once per round, the variants of a
!> configuration one after the other, so that the ratio of two variants is
!> measured in the same state of this shared machine: medians of 11 rounds
!> (5 for runs above 0.3 s) of the wall time and of the CPU time (user +
!> system) of the whole process, and the median over rounds of the paired
!> ratios. Afterwards valgrind --tool=callgrind counts the instructions of the
!> Courant-1 ladder up to 481 nodes, the targets, the cheapest runs that meet
!> the targets, the reuse, theta and output runs (`jobs` at a time: the count
!> does not depend on the load).
!>
!> Writes <out>/benchmark_tables.md (markdown) and <out>/benchmark.dat (data
!> of the figure, bench/benchmark.gp). `quick` times only the targets and the
!> output costs (for before/after timings, no instruction counts) and reuses
!> the reference fields that the last full run saved in <work>.
program bench
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type
   use xcable_io_input, only: case_config, read_config
   use xcable_box_case, only: setup_case
   use xcable_box_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_solver_banded, only: band_matrix
   use xcable_box_dynamics, only: dynamics_options
   use bench_theory, only: wave_reference, simple_wave_reference
   use bench_runs, only: run_spec, run_result, run_case, median, paired_ratio, instruction_command, read_instructions
   use bench_measure, only: run_errors, field_reference, measure, build_field_reference, save_reference, &
                            load_reference, compare_references
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   implicit none

   !> The variants: box scheme, rod with averaged mass, rod with lumped mass.
   integer, parameter :: n_variants = 3, box = 1, rod = 2, lumped = 3
   character(len=*), parameter :: variant_names(n_variants) = [character(len=12) :: 'box', 'rod averaged', &
                                                                'rod lumped']
   character(len=*), parameter :: variant_scheme(n_variants) = [character(len=3) :: 'box', 'rod', 'rod']
   character(len=*), parameter :: variant_mass(n_variants) = [character(len=8) :: 'averaged', 'averaged', 'lumped']
   character(len=*), parameter :: variant_tags(n_variants) = [character(len=3) :: 'box', 'rod', 'rlm']

   !> A paper case and the target configuration of each variant.
   type :: case_def
      character(len=16) :: name = ''
      real(dp) :: tension = 0, t_break = 0, t_end = 0
      integer :: target_nodes(n_variants) = 241
      real(dp) :: target_courant(n_variants) = 1
   end type case_def

   !> Accuracy targets: |end speed error|, |1 % drop error| (s), mean field error / T_s.
   real(dp), parameter :: max_speed = 1.0e-3_dp, max_drop = 0.05e-3_dp, max_field = 5.0e-3_dp
   !> The sets of targets of the cheapest-configuration table (flags of met).
   character(len=4), parameter :: criteria(3) = ['P.DF', '.MDF', '...F']
   character(len=*), parameter :: criterion_names(3) = [character(len=40) :: 'peak speed, drop, field (P D F)', &
                                                         'plateau speed, drop, field (M D F)', 'field only (F)']
   integer, parameter :: ladder_nodes(6) = [31, 61, 121, 241, 481, 961]
   real(dp), parameter :: ladder_courant(3) = [0.5_dp, 1.0_dp, 2.0_dp]
   integer, parameter :: dt_nodes = 241
   real(dp), parameter :: dt_courant(6) = [0.25_dp, 0.75_dp, 1.25_dp, 1.5_dp, 3.0_dp, 4.0_dp]
   integer, parameter :: between_nodes(7) = [91, 151, 161, 181, 201, 301, 361]
   real(dp), parameter :: tolerances(5) = [1.0e-5_dp, 1.0e-6_dp, 1.0e-8_dp, 1.0e-9_dp, 1.0e-10_dp]
   real(dp), parameter :: thetas(3) = [0.5_dp, 0.55_dp, 0.6_dp]
   real(dp), parameter :: bench_tol = 1.0e-7_dp, reference_tol = 1.0e-10_dp
   real(dp), parameter :: length = 60
   character(len=*), parameter :: all_fields = 'tension shear strain u v x z curvature'
   !> Instructions are counted on the Courant-1 ladder up to this many nodes.
   integer, parameter :: count_nodes_max = 481
   integer, parameter :: max_runs = 160
   !> Timing rounds: max_rounds for runs under 0.3 s, else long_rounds.
   integer, parameter :: max_rounds = 11, long_rounds = 5

   !> Lines of the figure's data kept for a later block.
   type :: text_block
      character(len=200), allocatable :: lines(:)
   end type text_block

   type(case_def) :: cases(2)
   !> The box time steps of both cases, then the theta rows (rod, lumped) of each.
   type(text_block) :: later_blocks(6)
   type(run_spec) :: specs(max_runs)
   type(run_result) :: results(max_runs)
   type(run_errors) :: errors(max_runs)
   character(len=16) :: kinds(max_runs)
   integer :: variant_of(max_runs)
   real(dp) :: instructions(max_runs)
   type(wave_reference) :: ref
   type(field_reference) :: field(n_variants)
   type(cable_model) :: model
   character(len=512) :: arg, exe, work, out, version
   logical :: quick, have_valgrind
   integer :: i, ic, n, md, dat, round, jobs, v, stat
   real(dp) :: speed_start, speed_end
   character(len=64) :: load_start, load_end, date

   quick = .false.
   exe = 'bin/xcable'
   work = 'build/bench'
   out = 'docs/measurements/data'
   version = ''
   jobs = 2
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
      else if (arg(1:8) == 'version=') then
         version = arg(9:)
      else if (arg(1:5) == 'jobs=') then
         read (arg(6:), *, iostat=stat) jobs
         if (stat /= 0 .or. jobs < 1) error stop 'bench: jobs= takes a positive integer'
      else
         write (error_unit, '(a)') 'usage: bench [quick] [exe=bin/xcable] [work=build/bench] [out=docs/measurements/data] '// &
            '[version=TEXT] [jobs=2]'
         error stop 2
      end if
   end do
   call execute_command_line('mkdir -p '//trim(work))
   call execute_command_line('command -v valgrind > /dev/null 2>&1', exitstat=stat)
   have_valgrind = stat == 0

   cases(1) = case_def('fast_180kN', 180.0e3_dp, 0.005_dp, 0.14_dp, [201, 481, 481], [1.0_dp, 1.0_dp, 1.0_dp])
   cases(2) = case_def('slow_315kN', 315.0e3_dp, 0.05_dp, 0.16_dp, [201, 91, 91], [2.0_dp, 1.0_dp, 1.0_dp])

   if (quick) then
      open (newunit=md, file=trim(work)//'/benchmark_quick.md', status='replace', action='write')
   else
      open (newunit=md, file=trim(out)//'/benchmark_tables.md', status='replace', action='write')
      open (newunit=dat, file=trim(out)//'/benchmark.dat', status='replace', action='write')
      write (dat, '(a)') '# xcable work-precision benchmark (example/bench); one gnuplot index per series.'
      write (dat, '(a)') '# Per case (fast_180kN: base 0, slow_315kN: base 15) and variant (box +0, rod averaged +5,'// &
         ' rod lumped +10):'
      write (dat, '(a)') '#   +0, +1, +2: grids at Courant 0.5, 1, 2; +3: grids between at Courant 1; +4: the target.'
      write (dat, '(a)') '# 30, 31: the box time steps at 241 nodes (fast_180kN, slow_315kN); 32, 33: the rod'// &
         ' (averaged, lumped) at theta 0.5, 0.55, 0.6 at its fast_180kN target, 34, 35 at its slow_315kN target.'
      write (dat, '(a)') '# columns: nodes courant wall[s] cpu[s] |peak speed error| |plateau speed error| '// &
         '|1% drop error|[ms] mean|dT|/Ts max|dT|/Ts reached_t_end(1/0) instructions(0: not counted) theta'
   end if

   call date_and_time(date=date)
   date = date(1:4)//'-'//date(5:6)//'-'//date(7:8)
   load_start = load_average()
   speed_start = machine_speed()
   call say('# xcable work-precision benchmark')
   call say('')
   call say('Generated by `make bench` (example/bench/) on '//trim(date)//' with '//trim(exe)// &
            trim(merge(' (version '//trim(version)//')', repeat(' ', 11 + len_trim(version)), len_trim(version) > 0))// &
            '. Variants: the box scheme (&numerics scheme = ''box'', the paper''s scheme of version 0.1) and the rod '// &
            '(scheme = ''rod'', the default) with the averaged and the lumped mass matrix.')
   call say('')
   call say('Times: the whole `xcable` process (start-up, statics, dynamics, HDF5 output), one thread, release '// &
            'build. Every configuration of a case runs once per round, the variants of one configuration one '// &
            'after the other; wall and CPU (user + system) times are medians of 11 rounds (5 for runs above 0.3 s), '// &
            'ratios are medians over rounds of the paired ratios. **This machine was shared with other jobs** '// &
            '(load average '//trim(load_start)//' at the start): the wall times are inflated and noisy, so compare '// &
            'ratios within one benchmark run, CPU times and instruction counts (valgrind --tool=callgrind, exact '// &
            'and independent of the load). Timed runs: newton_tol = 1e-7, theta = 0.5, tension snapshots every '// &
            '10 ms, no energy ledger, no gnuplot text.')
   call say('')
   call say('Targets: end speed within 1e-3 (column "met": P for the peak, M for the plateau mean), 1 % drop '// &
            'at the fixed end within 0.05 ms (D), mean tension-field error within 5e-3 T_s (F); a run that stops '// &
            'before t_end meets none.')

   do ic = 1, 2
      call case_model(cases(ic), model)
      call simple_wave_reference(model%law, model%mass, length, model%law%strain_at(cases(ic)%tension), &
                                 cases(ic)%t_break, 0.01_dp, ref)
      call print_reference(cases(ic), ref)
      n = 0
      do i = 1, max_runs
         results(i) = run_result()
      end do
      instructions = 0
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
      do v = 1, n_variants
         call variant_reference(cases(ic), v, field(v))
      end do
      do i = 1, n
         call measure(results(i), ref, field(variant_of(i)), length, cases(ic)%tension, cases(ic)%t_break, errors(i))
      end do
      if (.not. quick .and. have_valgrind) call count_all_instructions()
      call print_tables(cases(ic))
      if (.not. quick) call write_data(ic)
   end do
   speed_end = machine_speed()
   load_end = load_average()
   call say('')
   call say('## Machine state')
   call say('')
   call say('Machine speed during the benchmark (LU factorisation and 20 substitutions of a 1687 x 1687 band '// &
            'matrix, kl = 7, ku = 10, in process): '//trim(real_fmt(1.0e3_dp*speed_start, '(f8.2)'))// &
            ' ms at the start, '//trim(real_fmt(1.0e3_dp*speed_end, '(f8.2)'))//' ms at the end (0.67-0.68 ms '// &
            'on 2026-11-30, a quiet day). Load average (1, 5, 15 min): '//trim(load_start)//' at the start, '// &
            trim(load_end)//' at the end, on 2 cores.')
   if (.not. quick) close (dat)
   close (md)

contains

   !> Print a line to stdout and the markdown file.
   subroutine say(text)
      !> The line.
      character(*), intent(in) :: text
      write (output_unit, '(a)') text
      write (md, '(a)') text
   end subroutine say

   !> A real in a format, trimmed; blank for NaN.
   function real_fmt(x, fmt) result(text)
      !> Value.
      real(dp), intent(in) :: x
      !> Fortran format.
      character(*), intent(in) :: fmt
      character(len=32) :: text
      text = ''
      if (ieee_is_nan(x)) return
      write (text, fmt) x
      text = adjustl(text)
   end function real_fmt

   !> An integer as text.
   character(len=16) function int_str(i)
      !> Value.
      integer, intent(in) :: i
      write (int_str, '(i0)') i
   end function int_str

   !> The load average of the machine (1, 5 and 15 minutes), from /proc/loadavg.
   character(len=64) function load_average() result(text)
      integer :: unit, ios
      real(dp) :: loads(3)
      text = 'unknown'
      open (newunit=unit, file='/proc/loadavg', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read (unit, *, iostat=ios) loads
      close (unit)
      if (ios == 0) write (text, '(f5.2,", ",f5.2,", ",f5.2)') loads
   end function load_average

   !> Rounds of run i from its first wall time (references: one, untimed).
   integer function rounds_of(i)
      !> Run.
      integer, intent(in) :: i
      if (kinds(i) == 'reference') then
         rounds_of = 1
      else if (results(i)%repeats == 0) then
         rounds_of = max_rounds
      else if (results(i)%walls(1) < 0.3_dp) then
         rounds_of = max_rounds
      else
         rounds_of = long_rounds
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

   !> The model of a case (law, mass), built from a namelist like the app does.
   subroutine case_model(c, model)
      !> The case.
      type(case_def), intent(in) :: c
      !> Its model.
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

   !> The runs of a case, the variants of each configuration next to each other.
   subroutine build_runs(c)
      !> The case.
      type(case_def), intent(in) :: c
      integer :: a, b, w
      logical :: cached
      if (.not. quick) then
         do b = 1, size(ladder_courant)
            do a = 1, size(ladder_nodes)
               do w = 1, n_variants
                  if (w /= box .and. ladder_nodes(a) < 61) cycle
                  call add(c, w, ladder_nodes(a), ladder_courant(b), 'ladder')
               end do
            end do
         end do
         do a = 1, size(between_nodes)
            do w = 1, n_variants
               call add(c, w, between_nodes(a), 1.0_dp, 'between')
            end do
         end do
         do b = 1, size(dt_courant)
            call add(c, box, dt_nodes, dt_courant(b), 'dt')
         end do
         do b = 1, size(tolerances)
            call add(c, box, c%target_nodes(box), c%target_courant(box), 'tol', tol=tolerances(b))
         end do
      end if
      do w = 1, n_variants
         if (find(w, c%target_nodes(w), c%target_courant(w), 'ladder') == 0 .and. &
             find(w, c%target_nodes(w), c%target_courant(w), 'between') == 0) &
            call add(c, w, c%target_nodes(w), c%target_courant(w), 'target')
      end do
      if (.not. quick) then
         do w = rod, lumped
            call add(c, w, c%target_nodes(w), c%target_courant(w), 'reuse', reuse=.true.)
         end do
         do b = 1, size(thetas)
            do w = rod, lumped
               call add(c, w, c%target_nodes(w), c%target_courant(w), 'theta', energy=.true., theta=thetas(b))
            end do
         end do
      end if
      do w = box, rod
         call add(c, w, c%target_nodes(w), c%target_courant(w), 'cost', fields='')
         call add(c, w, c%target_nodes(w), c%target_courant(w), 'cost', fields=all_fields)
         call add(c, w, c%target_nodes(w), c%target_courant(w), 'cost', fields=all_fields, gnuplot=.true.)
         call add(c, w, c%target_nodes(w), c%target_courant(w), 'cost', energy=.true.)
         call add(c, w, c%target_nodes(w), c%target_courant(w), 'cost', fields=all_fields, gnuplot=.true., &
                  energy=.true.)
      end do
      do w = 1, n_variants
         inquire (file=reference_cache(c, w), exist=cached)
         if (quick .and. cached) cycle
         do a = 4, 6
            call add(c, w, ladder_nodes(a), 1.0_dp, 'reference', tol=reference_tol)
         end do
      end do
   end subroutine build_runs

   !> File of the saved reference field of a variant.
   function reference_cache(c, w) result(path)
      !> The case.
      type(case_def), intent(in) :: c
      !> The variant.
      integer, intent(in) :: w
      character(:), allocatable :: path
      path = trim(work)//'/reference_'//trim(c%name)//'_'//trim(variant_tags(w))//'.bin'
   end function reference_cache

   !> Append a run.
   subroutine add(c, w, nodes, courant, kind, fields, energy, gnuplot, tol, theta, reuse)
      !> The case.
      type(case_def), intent(in) :: c
      !> The variant.
      integer, intent(in) :: w
      !> Nodes and Courant number.
      integer, intent(in) :: nodes
      real(dp), intent(in) :: courant
      !> What the run is for.
      character(*), intent(in) :: kind
      !> Snapshot fields (default: tension).
      character(*), intent(in), optional :: fields
      !> Energy ledger, gnuplot text (default: neither).
      logical, intent(in), optional :: energy, gnuplot
      !> Newton tolerance (default bench_tol) and time weight (default 0.5).
      real(dp), intent(in), optional :: tol, theta
      !> &numerics reuse_jacobian (default: not given, the scheme's default).
      logical, intent(in), optional :: reuse
      character(len=96) :: label
      n = n + 1
      if (n > max_runs) error stop 'bench: too many runs'
      specs(n) = run_spec()
      specs(n)%scheme = trim(variant_scheme(w))
      specs(n)%mass_matrix = trim(variant_mass(w))
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
      if (present(tol)) specs(n)%newton_tol = tol
      if (present(theta)) specs(n)%theta = theta
      if (present(reuse)) specs(n)%reuse_jacobian = merge(1, 0, reuse)
      write (label, '(a,a,a,a,i0,a,f4.2,3a,i0)') trim(c%name), '_', trim(variant_tags(w)), '_n', nodes, '_c', courant, &
         '_', trim(kind), '_', n
      specs(n)%label = trim(label)
      kinds(n) = kind
      variant_of(n) = w
   end subroutine add

   !> Index of the run of a variant and kind with these nodes and Courant number (0: none).
   integer function find(w, nodes, courant, kind) result(idx)
      !> The variant.
      integer, intent(in) :: w
      !> Nodes and Courant number.
      integer, intent(in) :: nodes
      real(dp), intent(in) :: courant
      !> What the run is for.
      character(*), intent(in) :: kind
      integer :: j
      idx = 0
      do j = 1, n
         if (variant_of(j) == w .and. specs(j)%nodes == nodes .and. abs(specs(j)%courant - courant) < 1.0e-9_dp &
             .and. kinds(j) == kind) then
            idx = j
            return
         end if
      end do
   end function find

   !> The target run of a variant in the current case.
   integer function target_run(w) result(idx)
      !> The variant.
      integer, intent(in) :: w
      associate (c => cases(ic))
         idx = find(w, c%target_nodes(w), c%target_courant(w), 'ladder')
         if (idx == 0) idx = find(w, c%target_nodes(w), c%target_courant(w), 'between')
         if (idx == 0) idx = find(w, c%target_nodes(w), c%target_courant(w), 'target')
      end associate
   end function target_run

   !> Whether run j is one of the timed runs at the default settings (theta
   !> 0.5, newton_tol 1e-7, tension snapshots): the runs the cheapest
   !> configurations are chosen from.
   logical function plain_run(j)
      !> Run.
      integer, intent(in) :: j
      plain_run = kinds(j) == 'ladder' .or. kinds(j) == 'between' .or. kinds(j) == 'dt' .or. kinds(j) == 'target'
   end function plain_run

   !> The reference field of a variant: from its reference runs, or the one saved by the last full run.
   subroutine variant_reference(c, w, f)
      !> The case.
      type(case_def), intent(in) :: c
      !> The variant.
      integer, intent(in) :: w
      !> Its reference field.
      type(field_reference), intent(out) :: f
      integer :: i241, i481, i961
      i241 = find(w, 241, 1.0_dp, 'reference')
      i481 = find(w, 481, 1.0_dp, 'reference')
      i961 = find(w, 961, 1.0_dp, 'reference')
      if (i241 == 0 .or. i481 == 0 .or. i961 == 0) then
         call load_reference(reference_cache(c, w), f)
         return
      end if
      call build_field_reference(results(i241), results(i481), results(i961), length, c%tension, f)
      call save_reference(f, reference_cache(c, w))
   end subroutine variant_reference

   !> Whether the instructions of run j are counted (the cheapest runs too).
   logical function counted(j)
      !> Run.
      integer, intent(in) :: j
      integer :: k
      counted = kinds(j) == 'theta' .or. kinds(j) == 'cost' .or. kinds(j) == 'reuse' .or. j == target_run(variant_of(j)) .or. &
                (kinds(j) == 'ladder' .and. abs(specs(j)%courant - 1) < 1.0e-9_dp .and. specs(j)%nodes <= count_nodes_max)
      do k = 1, size(criteria)
         if (j == cheapest_run(variant_of(j), criteria(k))) counted = .true.
      end do
   end function counted

   !> Count the instructions of the selected runs with callgrind, `jobs` at a time.
   subroutine count_all_instructions()
      integer :: unit, j
      character(:), allocatable :: list
      list = trim(work)//'/callgrind_'//trim(cases(ic)%name)//'.txt'
      open (newunit=unit, file=list, status='replace', action='write')
      do j = 1, n
         if (counted(j) .and. results(j)%exit_code >= 0) write (unit, '(a)') instruction_command(specs(j), trim(exe), &
                                                                                                trim(work))
      end do
      close (unit)
      write (error_unit, '(a)') 'bench: counting instructions (valgrind --tool=callgrind) of the runs in '//list
      call execute_command_line('xargs -d ''\n'' -n 1 -P '//trim(int_str(jobs))//' sh -c < '//list)
      do j = 1, n
         if (counted(j)) instructions(j) = read_instructions(specs(j), trim(work))
      end do
   end subroutine count_all_instructions

   !> The simple-wave references of a case.
   subroutine print_reference(c, r)
      !> The case.
      type(case_def), intent(in) :: c
      !> Its references.
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
      write (line, '(a,f8.4,a)') '- breaking-end speed: integral of c d eps from T = 0 to eps0 = ', r%end_speed, &
         ' m/s, measured along the chord from end a to end b at t = 0; the peak while the fixed end is in '// &
         'tension, and the plateau: the time mean from t_br until the fixed end goes into compression;'
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

   !> Which targets run j meets: P (peak speed), M (plateau speed), D (1 % drop), F (field); '.' where not.
   character(len=4) function met(j)
      !> Run.
      integer, intent(in) :: j
      logical :: complete
      complete = results(j)%exit_code == 0 .and. results(j)%ok
      met = '....'
      if (complete .and. abs(errors(j)%speed) <= max_speed) met(1:1) = 'P'
      if (complete .and. abs(errors(j)%plateau) <= max_speed) met(2:2) = 'M'
      if (complete .and. abs(errors(j)%drop) <= max_drop) met(3:3) = 'D'
      if (complete .and. errors(j)%field_mean <= max_field) met(4:4) = 'F'
   end function met

   !> The tables of a case.
   subroutine print_tables(c)
      !> The case.
      type(case_def), intent(in) :: c
      integer :: j, w, k, t
      integer, allocatable :: order(:)
      character(len=1024) :: line
      type(case_config) :: defaults
      real(dp) :: mean, largest
      integer :: shared
      call say('')
      call say('### '//trim(c%name)//': reference tension fields')
      call say('')
      call say('Snapshots every 10 ms while the fixed end of the 961-node run is in tension; each variant is '// &
               'measured against its own reference.')
      call say('')
      call say('| variant | reference | observed order (241/481/961) | uncertainty (mean, / T_s) | snapshots |')
      call say('|---|---|---:|---:|---|')
      do w = 1, n_variants
         if (field(w)%ok) then
            write (line, '(a,f5.2,a,es8.1,a,f5.1,a,f5.1,a)') '| '//trim(variant_names(w))//' | '// &
               trim(field(w)%source)//' | ', field(w)%order, ' | ', field(w)%uncertainty, ' | ', &
               1.0e3_dp*minval(field(w)%times), ' - ', 1.0e3_dp*maxval(field(w)%times), ' ms |'
         else
            line = '| '//trim(variant_names(w))//' | none (run the full benchmark once) | | | |'
         end if
         call say(trim(line))
      end do
      call say('')
      call say('Differences between the references (481 points, the snapshots both have):')
      call say('')
      call say('| references | mean abs(dT)/T_s | max abs(dT)/T_s | snapshots |')
      call say('|---|---:|---:|---:|')
      do k = 1, 3
         select case (k)
         case (1)
            call compare_references(field(rod), field(box), length, c%tension, mean, largest, shared)
            line = '| rod averaged - box'
         case (2)
            call compare_references(field(lumped), field(box), length, c%tension, mean, largest, shared)
            line = '| rod lumped - box'
         case default
            call compare_references(field(lumped), field(rod), length, c%tension, mean, largest, shared)
            line = '| rod lumped - rod averaged'
         end select
         call say(trim(line)//' | '//trim(real_fmt(mean, '(es9.2)'))//' | '//trim(real_fmt(largest, '(es9.2)'))// &
                  ' | '//trim(int_str(shared))//' |')
      end do

      call say('')
      call say('### '//trim(c%name)//': target configurations')
      call say('')
      call say('The configuration of each variant that the theta and output rows use (and `make bench-quick` '// &
               'times).')
      call table_head(variant=.true.)
      do w = 1, n_variants
         t = target_run(w)
         if (t > 0) call table_row(t, variant=.true.)
      end do

      if (.not. quick) then
         call cheapest_table(c)
         do w = 1, n_variants
            call say('')
            call say('### '//trim(c%name)//', '//trim(variant_names(w))//': grids at fixed Courant numbers')
            call table_head()
            do j = 1, n
               if (kinds(j) == 'ladder' .and. variant_of(j) == w) call table_row(j)
            end do
            call say('')
            call say('### '//trim(c%name)//', '//trim(variant_names(w))//': grids between, at Courant 1')
            call table_head()
            order = [integer ::]
            do j = 1, n
               if (variant_of(j) /= w) cycle
               if (kinds(j) == 'between' .or. (kinds(j) == 'ladder' .and. abs(specs(j)%courant - 1) < 1.0e-9_dp &
                                               .and. specs(j)%nodes >= 61 .and. specs(j)%nodes <= 481)) order = [order, j]
            end do
            call sort_runs(order, real(specs(order)%nodes, dp))
            do j = 1, size(order)
               call table_row(order(j))
            end do
         end do
         call say('')
         call say('### '//trim(c%name)//', box: time steps at 241 nodes')
         call table_head()
         order = runs_by_courant()
         do j = 1, size(order)
            call table_row(order(j))
         end do
         call say('')
         call say('### '//trim(c%name)//', box: Newton tolerance at the target configuration ('// &
                  trim(adjustl(real_fmt(defaults%newton_tol, '(es8.1)')))//' is the default)')
         call table_head('newton_tol')
         order = [integer ::]
         do j = 1, n
            if (kinds(j) == 'tol' .or. j == target_run(box)) order = [order, j]
         end do
         call sort_runs(order, -specs(order)%newton_tol)
         do j = 1, size(order)
            call table_row(order(j), specs(order(j))%newton_tol)
         end do
         call ratio_table()
         call reuse_table()
         call theta_table()
      end if
      call cost_table(c)
   end subroutine print_tables

   !> The cheapest (median CPU time) complete plain runs of each variant that meet the targets.
   subroutine cheapest_table(c)
      !> The case.
      type(case_def), intent(in) :: c
      integer :: k, w, best
      call say('')
      call say('### '//trim(c%name)//': cheapest configuration that meets the targets')
      call say('')
      call say('Among the complete runs at theta = 0.5 and newton_tol = 1e-7 (ladders, grids between, box time '// &
               'steps), the one with the smallest median CPU time (the wall time of the same run beside it).')
      call table_head(text_column='targets')
      do k = 1, size(criteria)
         do w = 1, n_variants
            best = cheapest_run(w, criteria(k))
            if (best > 0) then
               call table_row(best, variant=.true., criterion=trim(criterion_names(k)))
            else
               call say('| '//trim(criterion_names(k))//' | '//trim(variant_names(w))//' | none on the ladders |'// &
                        repeat(' |', 16))
            end if
         end do
      end do
   end subroutine cheapest_table

   !> The plain run of variant w with the smallest median CPU time among those
   !> that meet the targets want (flags as met gives them, '.' : not asked); 0: none.
   integer function cheapest_run(w, want) result(best)
      !> The variant.
      integer, intent(in) :: w
      !> The targets asked for.
      character(len=4), intent(in) :: want
      integer :: j
      best = 0
      do j = 1, n
         if (variant_of(j) /= w .or. .not. plain_run(j)) cycle
         if (.not. meets(met(j), want)) cycle
         if (best == 0) then
            best = j
         else if (results(j)%cpu < results(best)%cpu) then
            best = j
         end if
      end do
   end function cheapest_run

   !> Whether the target flags got (as met gives them) include every flag of want.
   logical function meets(got, want)
      !> Flags of a run, and the flags asked for ('.' : not asked).
      character(len=4), intent(in) :: got, want
      integer :: q
      meets = .true.
      do q = 1, 4
         if (want(q:q) /= '.' .and. got(q:q) /= want(q:q)) meets = .false.
      end do
   end function meets

   !> Rod / box: cost ratios on the ladders, paired by round, and per node-step.
   subroutine ratio_table()
      integer :: a, b, jb, jr, jl
      real(dp) :: per_step_r, per_step_l
      character(len=1024) :: line
      call say('')
      call say('### '//trim(cases(ic)%name)//': cost of the rod against the box scheme')
      call say('')
      call say('Ratios of the whole process on the same grid and Courant number: wall and CPU time (medians over '// &
               'the rounds of the ratio of the two runs of a round), instructions (callgrind, Courant 1 up to '// &
               trim(int_str(count_nodes_max))//' nodes); "per node-step" divides by the ratio of the steps (the '// &
               'box rounds its step to fit the 10 ms snapshot interval).')
      call say('')
      call say('| nodes | Courant | steps: box, rod, lumped | box wall (s) | box CPU (s) | rod/box wall | '// &
               'rod/box CPU | rod/box instructions | rod/box per node-step (CPU) | rod/box per node-step '// &
               '(instructions) | lumped/box CPU | lumped/box per node-step (instructions) |')
      call say('|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
      do b = 1, size(ladder_courant)
         do a = 2, size(ladder_nodes)
            jb = find(box, ladder_nodes(a), ladder_courant(b), 'ladder')
            jr = find(rod, ladder_nodes(a), ladder_courant(b), 'ladder')
            jl = find(lumped, ladder_nodes(a), ladder_courant(b), 'ladder')
            if (jb == 0 .or. jr == 0 .or. jl == 0) cycle
            if (.not. (results(jb)%ok .and. results(jr)%ok .and. results(jl)%ok)) cycle
            per_step_r = real(results(jb)%steps, dp)/max(results(jr)%steps, 1)
            per_step_l = real(results(jb)%steps, dp)/max(results(jl)%steps, 1)
            write (line, '(a,i0,a,f4.2,a,3(i0,a),f8.4,a,f8.4,a,f6.2,a,f6.2,a)') '| ', ladder_nodes(a), ' | ', &
               ladder_courant(b), ' | ', results(jb)%steps, ', ', results(jr)%steps, ', ', results(jl)%steps, ' | ', &
               results(jb)%wall, ' | ', results(jb)%cpu, ' | ', paired_ratio(results(jr), results(jb), .false.), &
               ' | ', paired_ratio(results(jr), results(jb), .true.), ' | '
            line = trim(line)//' '//trim(ratio_text(instructions(jr), instructions(jb)))//' | '// &
                   trim(real_fmt(paired_ratio(results(jr), results(jb), .true.)*per_step_r, '(f6.2)'))//' | '// &
                   trim(ratio_text(instructions(jr)*per_step_r, instructions(jb)))//' | '// &
                   trim(real_fmt(paired_ratio(results(jl), results(jb), .true.), '(f6.2)'))//' | '// &
                   trim(ratio_text(instructions(jl)*per_step_l, instructions(jb)))//' |'
            call say(trim(line))
         end do
      end do
      call marginal_cost()
   end subroutine ratio_table

   !> a / b with two decimals, blank when either is not counted.
   function ratio_text(a, b) result(text)
      !> Numerator and denominator.
      real(dp), intent(in) :: a, b
      character(len=16) :: text
      text = ''
      if (a > 0 .and. b > 0) write (text, '(f6.2)') a/b
      text = adjustl(text)
   end function ratio_text

   !> Instructions per node-step between the two finest counted grids at
   !> Courant 1 (the start-up and statics cancel), per variant, and the ratios.
   subroutine marginal_cost()
      integer :: w, j1, j2
      real(dp) :: per(n_variants)
      character(len=512) :: line
      per = 0
      do w = 1, n_variants
         j1 = find(w, 241, 1.0_dp, 'ladder')
         j2 = find(w, count_nodes_max, 1.0_dp, 'ladder')
         if (j1 == 0 .or. j2 == 0) cycle
         if (instructions(j1) <= 0 .or. instructions(j2) <= 0) cycle
         per(w) = (instructions(j2) - instructions(j1))/ &
                  (real(specs(j2)%nodes, dp)*results(j2)%steps - real(specs(j1)%nodes, dp)*results(j1)%steps)
      end do
      if (any(per <= 0)) return
      write (line, '(a,i0,a,3(f8.0,a),f5.2,a,f5.2,a)') 'Instructions per node and step between 241 and ', &
         count_nodes_max, ' nodes at Courant 1 (start-up and statics cancel): box ', per(box), ', rod averaged ', &
         per(rod), ', rod lumped ', per(lumped), '; rod/box ', per(rod)/per(box), ', lumped/box ', &
         per(lumped)/per(box), '.'
      call say('')
      call say(trim(line))
   end subroutine marginal_cost

   !> The rod at its targets with the Jacobian kept while Newton contracts well
   !> (reuse_jacobian = .true., the box scheme's default) against its default.
   subroutine reuse_table()
      integer :: w, j
      call say('')
      call say('### '//trim(cases(ic)%name)//': the rod with reuse_jacobian = .true. at its target configuration')
      call say('')
      call say('The rod refreshes and factorises its Jacobian at every Newton iteration unless reuse_jacobian is '// &
               'given; with .true. it keeps the factorised Jacobian while Newton contracts well, as the box scheme '// &
               'does.')
      call table_head(text_column='reuse_jacobian')
      do w = rod, lumped
         do j = 1, n
            if (variant_of(j) /= w) cycle
            if (j == target_run(w)) call table_row(j, criterion='default (.false.)')
            if (kinds(j) == 'reuse') call table_row(j, criterion='.true.')
         end do
      end do
   end subroutine reuse_table

   !> The rod at theta 0.5, 0.55, 0.6 at its target: what damping costs at the front.
   subroutine theta_table()
      integer :: w, j
      character(len=1024) :: line
      call say('')
      call say('### '//trim(cases(ic)%name)//': the rod''s time weight theta at its target configuration')
      call say('')
      call say('theta > 0.5 damps every mode whose velocity changes within a step and books the energy removed '// &
               '(column "dissipated", / the initial strain energy) in the ledger; these runs keep the energy '// &
               'ledger (a few per cent of the time).')
      call say('')
      call say('| variant | theta | nodes | Courant | wall (s) | CPU (s) | instructions (1e6) | Newton it. / step | '// &
               'peak end speed error | plateau speed error | 1 % drop error (ms) | mean abs(dT)/T_s | '// &
               'dissipated / strain energy | met |')
      call say('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|')
      do w = rod, lumped
         do j = 1, n
            if (kinds(j) /= 'theta' .or. variant_of(j) /= w) cycle
            if (.not. results(j)%ok) then
               call say('| '//trim(variant_names(w))//' | '//trim(real_fmt(specs(j)%theta, '(f4.2)'))// &
                        ' | no result (exit '//trim(int_str(results(j)%exit_code))//') | | | | | | | | | | | |')
               cycle
            end if
            write (line, '(a,f4.2,a,i0,a,f5.3,a,f8.4,a,f8.4,a)') '| '//trim(variant_names(w))//' | ', specs(j)%theta, &
               ' | ', specs(j)%nodes, ' | ', results(j)%courant_used, ' | ', results(j)%wall, ' | ', results(j)%cpu, ' | '
            line = trim(line)//' '//trim(instr_text(j))//' | '// &
                   trim(real_fmt(real(results(j)%newton_iterations, dp)/max(results(j)%steps, 1), '(f5.2)'))//' | '// &
                   trim(real_fmt(errors(j)%speed, '(es9.2)'))//' | '//trim(real_fmt(errors(j)%plateau, '(es9.2)'))// &
                   ' | '//trim(real_fmt(1.0e3_dp*errors(j)%drop, '(f9.4)'))//' | '// &
                   trim(real_fmt(errors(j)%field_mean, '(es9.2)'))//' | '// &
                   trim(real_fmt(results(j)%dissipated/max(results(j)%strain_energy, tiny(1.0_dp)), '(es9.2)'))// &
                   ' | '//met(j)//' |'
            call say(trim(line))
         end do
      end do
   end subroutine theta_table

   !> Instructions of run j in millions (blank if not counted).
   function instr_text(j) result(text)
      !> Run.
      integer, intent(in) :: j
      character(len=16) :: text
      text = ''
      if (instructions(j) > 0) write (text, '(f9.1)') 1.0e-6_dp*instructions(j)
      text = adjustl(text)
   end function instr_text

   !> The cost of more output and of the energy ledger at the targets of the box and the rod.
   subroutine cost_table(c)
      !> The case.
      type(case_def), intent(in) :: c
      integer :: j, w, base, t
      character(len=1024) :: line
      do w = box, rod
         t = target_run(w)
         call say('')
         call say('### '//trim(c%name)//', '//trim(variant_names(w))//': cost of output and diagnostics ('// &
                  trim(int_str(c%target_nodes(w)))//' nodes, Courant '//trim(real_fmt(c%target_courant(w), '(f5.2)'))//')')
         call say('')
         call say('| output | wall (s) | change | CPU (s) | change | instructions (1e6) | change |')
         call say('|---|---:|---:|---:|---:|---:|---:|')
         base = 0
         do j = 1, n
            if (kinds(j) == 'cost' .and. variant_of(j) == w .and. specs(j)%fields == '') base = j
         end do
         if (base == 0) cycle
         do j = 1, n
            if (variant_of(j) /= w .or. (kinds(j) /= 'cost' .and. j /= t)) cycle
            write (line, '(a,f8.4,a,sp,f6.1,ss,a,f8.4,a,sp,f6.1,ss,a)') '| '//trim(cost_label(j))//' | ', &
               results(j)%wall, ' | ', 100*(results(j)%wall/results(base)%wall - 1), ' % | ', results(j)%cpu, ' | ', &
               100*(results(j)%cpu/max(results(base)%cpu, 1.0e-3_dp) - 1), ' % | '
            if (instructions(base) > 0 .and. instructions(j) > 0) then
               write (line, '(a,f8.1,a,sp,f6.1,ss,a)') trim(line)//' ', 1.0e-6_dp*instructions(j), ' | ', &
                  100*(instructions(j)/instructions(base) - 1), ' % |'
            else
               line = trim(line)//' | |'
            end if
            call say(trim(line))
         end do
      end do
   end subroutine cost_table

   !> What a cost run writes.
   character(len=96) function cost_label(j)
      !> Run.
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

   !> Head of a run table (optional leading columns).
   subroutine table_head(extra, variant, text_column)
      !> Name of a leading numeric column.
      character(*), intent(in), optional :: extra
      !> Leading variant column.
      logical, intent(in), optional :: variant
      !> Name of a leading text column (followed by the variant column).
      character(*), intent(in), optional :: text_column
      character(len=1024) :: head, rule
      head = '|'
      rule = '|'
      if (present(text_column)) then
         head = trim(head)//' '//text_column//' |'
         rule = trim(rule)//'---|'
      end if
      if (present(variant) .or. present(text_column)) then
         head = trim(head)//' variant |'
         rule = trim(rule)//'---|'
      end if
      if (present(extra)) then
         head = trim(head)//' '//extra//' |'
         rule = trim(rule)//'---:|'
      end if
      head = trim(head)//' nodes | ds (m) | Courant | dt (us) | steps | Newton it. / step | factorisations | '// &
             'wall (s) | CPU (s) | instructions (1e6) | reached (s) | peak end speed error | plateau speed error | '// &
             '1 % drop error (ms) | mean abs(dT)/T_s | max abs(dT)/T_s | met |'
      rule = trim(rule)//'---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|'
      call say('')
      call say(trim(head))
      call say(trim(rule))
   end subroutine table_head

   !> One row of a run table.
   subroutine table_row(j, extra, variant, criterion)
      !> Run.
      integer, intent(in) :: j
      !> Value of the leading numeric column.
      real(dp), intent(in), optional :: extra
      !> Leading variant column.
      logical, intent(in), optional :: variant
      !> Leading criterion column.
      character(*), intent(in), optional :: criterion
      character(len=1024) :: line
      character(len=256) :: lead
      character(len=24) :: reached
      lead = '|'
      if (present(criterion)) lead = trim(lead)//' '//trim(criterion)//' |'
      if (present(variant) .or. present(criterion)) lead = trim(lead)//' '//trim(variant_names(variant_of(j)))//' |'
      if (present(extra)) lead = trim(lead)//' '//trim(real_fmt(extra, '(es7.0)'))//' |'
      if (.not. results(j)%ok) then
         write (line, '(a,i0,a,i0,a)') trim(lead)//' ', specs(j)%nodes, ' | | | | | | | | | | no result (exit ', &
            results(j)%exit_code, ') | | | | | | |'
         call say(trim(line))
         return
      end if
      write (reached, '(f6.4)') results(j)%time_reached
      if (results(j)%exit_code /= 0) reached = trim(reached)//' (failed)'
      write (line, '(a,i0,a,f6.4,a,f5.3,a,f7.2,a,i0,a,f5.2,a,i0,a,f8.4,a,f8.4,a)') trim(lead)//' ', specs(j)%nodes, &
         ' | ', length/(specs(j)%nodes - 1), ' | ', results(j)%courant_used, ' | ', 1.0e6_dp*results(j)%step, ' | ', &
         results(j)%steps, ' | ', real(results(j)%newton_iterations, dp)/max(results(j)%steps, 1), ' | ', &
         results(j)%factorisations, ' | ', results(j)%wall, ' | ', results(j)%cpu, ' |'
      line = trim(line)//' '//trim(instr_text(j))//' | '//trim(reached)//' | '// &
             trim(real_fmt(errors(j)%speed, '(es9.2)'))//' | '//trim(real_fmt(errors(j)%plateau, '(es9.2)'))//' | '// &
             trim(real_fmt(1.0e3_dp*errors(j)%drop, '(f9.4)'))//' | '//trim(field_text(j))//' | '//met(j)//' |'
      call say(trim(line))
   end subroutine table_row

   !> Mean and max field error of run j as two table cells; the run the
   !> reference was taken from (without extrapolation) reads 'the reference'.
   function field_text(j) result(text)
      !> Run.
      integer, intent(in) :: j
      character(len=64) :: text
      if (errors(j)%field_max <= 0 .and. .not. field(variant_of(j))%extrapolated) then
         text = 'the reference | the reference '
      else
         text = trim(real_fmt(errors(j)%field_mean, '(es9.2)'))//' | '//trim(real_fmt(errors(j)%field_max, '(es9.2)'))//' '
      end if
   end function field_text

   !> The figure's data of the current case (the index layout is in the file's
   !> header); the box time steps and the theta rows of both cases follow
   !> those of the second.
   subroutine write_data(ic)
      !> The case.
      integer, intent(in) :: ic
      integer :: w, k, j, q
      integer, allocatable :: order(:)
      do w = 1, n_variants
         do k = 1, 5
            do j = 1, n
               if (variant_of(j) /= w) cycle
               select case (k)
               case (1:3)
                  if (kinds(j) /= 'ladder' .or. abs(specs(j)%courant - ladder_courant(k)) > 1.0e-9_dp) cycle
               case (4)
                  if (kinds(j) /= 'between') cycle
               case default
                  if (j /= target_run(w)) cycle
               end select
               call data_line(j)
            end do
            write (dat, '(/)')
         end do
      end do
      call keep_lines(later_blocks(ic), runs_by_courant())
      do w = rod, lumped
         order = [integer ::]
         do j = 1, n
            if (kinds(j) == 'theta' .and. variant_of(j) == w) order = [order, j]
         end do
         call keep_lines(later_blocks(1 + 2*ic + w - rod), order)
      end do
      if (ic /= 2) return
      do q = 1, size(later_blocks)
         do j = 1, size(later_blocks(q)%lines)
            write (dat, '(a)') trim(later_blocks(q)%lines(j))
         end do
         write (dat, '(/)')
      end do
   end subroutine write_data

   !> One line of the figure's data.
   function data_text(j) result(text)
      !> Run.
      integer, intent(in) :: j
      character(len=200) :: text
      write (text, '(i5,f7.3,2es12.4,5es12.4,i3,es13.5,f6.3)') specs(j)%nodes, results(j)%courant_used, &
         results(j)%wall, results(j)%cpu, abs(errors(j)%speed), abs(errors(j)%plateau), 1.0e3_dp*abs(errors(j)%drop), &
         errors(j)%field_mean, errors(j)%field_max, merge(1, 0, results(j)%exit_code == 0), instructions(j), &
         specs(j)%theta
   end function data_text

   !> Write one line of the figure's data (runs without a result are left out).
   subroutine data_line(j)
      !> Run.
      integer, intent(in) :: j
      if (.not. results(j)%ok) return
      write (dat, '(a)') trim(data_text(j))
   end subroutine data_line

   !> Keep the data lines of some runs for a later block.
   subroutine keep_lines(block, order)
      !> Where they are kept.
      type(text_block), intent(inout) :: block
      !> The runs.
      integer, intent(in) :: order(:)
      integer :: j
      allocate (block%lines(0))
      do j = 1, size(order)
         if (results(order(j))%ok) block%lines = [block%lines, data_text(order(j))]
      end do
   end subroutine keep_lines

   !> The box runs on dt_nodes nodes (ladder and dt ladder), by increasing Courant number.
   function runs_by_courant() result(order)
      integer, allocatable :: order(:)
      integer :: j
      order = [integer ::]
      do j = 1, n
         if (variant_of(j) == box .and. specs(j)%nodes == dt_nodes .and. (kinds(j) == 'ladder' .or. kinds(j) == 'dt')) &
            order = [order, j]
      end do
      call sort_runs(order, specs(order)%courant)
   end function runs_by_courant

   !> Sort run indices by increasing key (insertion sort).
   subroutine sort_runs(order, key)
      !> Run indices.
      integer, intent(inout) :: order(:)
      !> Key of each.
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
