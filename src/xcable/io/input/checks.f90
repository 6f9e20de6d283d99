!> The validation of a case: every variable against its schema entry (range or allowed
!> words), then the conditions between variables (the ends, the tables, the rupture, the model);
!> and the defaults derived from others.
!> (Split from io/input.f90, which reads a case through these modules.)
module xcable_io_input_checks
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str, real_text
   use xcable_io_config, only: case_config, end_config
   use xcable_ends_registry, only: end_kind, find_end_kind, end_kind_names, kinds_using
   use xcable_io_schema, only: schema_entry, schema_table, find_entry, group_entries, allowed_text, group_list, &
                               segment_group, segment_of, point_group, point_of, line_group, line_of
   use xcable_io_input_access, only: access, config_value, get_value
   use xcable_io_input_scanner, only: is_word, next_item, shown
   use xcable_io_input_bathymetry, only: load_bathymetry
   use xcable_io_input_tables, only: check_column, check_material_table, load_material_table, load_segment_table, &
                                     load_table, time_order
   use xcable_io_input_echo, only: value_text
   implicit none
   private
   public :: derive_defaults, max_time_steps, validate
   ! For the submodule io/input/checks/points.f90 (gfortran gives a module's private procedures
   ! no symbol a submodule can link to).
   public :: check_entry, quoted_words, check_segment_loads

   !> Most snapshots a run may ask for (t_end / interval).
   real(dp), parameter :: max_snapshots = 1.0e5_dp

   !> Most time steps a run may ask for (t_end / dt): the history is kept in
   !> memory, and a step far below this is a typing error (dt = 1e-300 made
   !> an integer overflow and a crash).
   integer, parameter :: max_time_steps = 1000000

   !> Poisson ratio of the default torsional stiffness GIp = EI / (1 + nu) (a solid isotropic rod; nylon).
   real(dp), parameter :: default_poisson = 0.4_dp

   interface
      !> The bodies on the line (io/input/checks/points.f90).
      module subroutine check_points(c, t, error)
         !> The case.
         type(case_config), intent(inout) :: c
         !> The schema.
         type(schema_entry), intent(in) :: t(:)
         !> Error naming file, group, variable, value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_points

      !> What a case with &line groups may not have; a network point without lines
      !> (io/input/checks/network.f90).
      module subroutine check_network_groups(c, t, error)
         !> The case.
         type(case_config), intent(inout) :: c
         !> The schema.
         type(schema_entry), intent(in) :: t(:)
         !> Error naming file, group, variable, value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_network_groups

      !> A network point (&point_k with a kind) (io/input/checks/network.f90).
      module subroutine check_network_point(c, t, k, error)
         !> The case.
         type(case_config), intent(inout) :: c
         !> The schema.
         type(schema_entry), intent(in) :: t(:)
         !> The point.
         integer, intent(in) :: k
         !> Error naming file, group, variable, value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_network_point

      !> A body on the single line in a network: refused (io/input/checks/network.f90).
      module subroutine check_body_in_network(c, k, error)
         !> The case.
         type(case_config), intent(in) :: c
         !> The point.
         integer, intent(in) :: k
         !> Error naming file, group, variable, value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_body_in_network

      !> The lines of a network (io/input/checks/network.f90).
      module subroutine check_lines(c, t, error)
         !> The case.
         type(case_config), intent(inout) :: c
         !> The schema.
         type(schema_entry), intent(in) :: t(:)
         !> Error naming file, group, variable, value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_lines

      !> The break of a network (io/input/checks/network.f90).
      module subroutine check_network_rupture(c, error)
         !> The case.
         type(case_config), intent(in) :: c
         !> Error naming file, group, variable, value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_network_rupture
   end interface

contains

   !> The values whose 0 means "derived from others": the area from the
   !> diameter, EI from young and the diameter, EA of the linear law from young
   !> and the area; and a negative s_break, the end b (s = L; in a network, the
   !> length of its &rupture line, when that is one of its lines). On a line of
   !> segments, &cable length not given is the sum of their lengths, and
   !> &numerics nodes not given, when every segment gives its nodes, their sum
   !> less the joints. Called by validate and by setup_case, so that a case
   !> built in code (tests, examples) gets them as a namelist does.
   pure subroutine derive_defaults(c)
      !> Case; derived values replace zeros.
      type(case_config), intent(inout) :: c
      real(dp), parameter :: pi = acos(-1.0_dp)
      integer :: n
      n = c%segment_count
      ! (A network's segments are shared out among its lines: check_lines.)
      if (n > 0 .and. c%line_count == 0) then
         if (.not. c%is_given('cable', 'length')) c%length = sum(c%segments(1:n)%length)
         if (all(c%segments(1:n)%nodes > 0) .and. .not. c%is_given('numerics', 'nodes')) &
            c%nodes = sum(c%segments(1:n)%nodes) - (n - 1)
      end if
      if (c%area == 0) c%area = 0.25_dp*pi*c%diameter**2
      if (c%bending_stiffness == 0) c%bending_stiffness = c%young*pi*c%diameter**4/64
      if (c%gip == 0) c%gip = c%bending_stiffness/(1 + default_poisson)
      if (c%law == 'linear' .and. c%ea == 0) c%ea = c%young*c%area
      if (c%s_break < 0) then
         ! A network's break by time: the end b of its &rupture line (its length, after check_lines).
         if (c%line_count > 0 .and. c%break_line >= 1 .and. c%break_line <= c%line_count) then
            if (c%lines(max(c%break_line, 1))%length > 0) then
               c%s_break = c%lines(max(c%break_line, 1))%length
               return
            end if
         end if
         c%s_break = c%length
      end if
   end subroutine derive_defaults

   !> The checks of a case read: the tables from files, every variable
   !> against its schema entry, the law's table or coefficients, the derived values,
   !> the conditions between variables, and the default output file.
   subroutine validate(c, error)
      !> The case; derived values and table files filled in.
      type(case_config), intent(inout) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      type(schema_entry), allocatable :: t(:)
      type(end_config) :: e
      integer :: i, slash, dot

      t = schema_table()
      e = c%end_a
      call load_table(c, 'end_a', e, error)
      if (allocated(error)) return
      c%end_a = e
      e = c%end_b
      call load_table(c, 'end_b', e, error)
      if (allocated(error)) return
      c%end_b = e
      call load_bathymetry(c, error)
      if (allocated(error)) return
      ! The law first: its table file is read only for law = 'table' (checked after the ranges).
      call check_entry(c, t(find_entry(t, 'material', 'law')), error)
      if (allocated(error)) return
      if (c%law == 'table') then
         call load_material_table(c, error)
         if (allocated(error)) return
      end if
      ! A network (&line groups) first: the groups it may not have.
      call check_network_groups(c, t, error)
      if (allocated(error)) return
      ! The segments' lengths and nodes first: &cable length and &numerics nodes may follow from them.
      call check_segment_layout(c, t, error)
      if (allocated(error)) return
      do i = 1, size(t)
         ! (The segments' variables are checked with their segment, below.)
         if (segment_of(t(i)%group) > 0 .or. point_of(t(i)%group) > 0 .or. line_of(t(i)%group) > 0) cycle
         ! (A network's s_break is along its &rupture line, not &cable length: check_network_rupture.)
         if (c%line_count > 0 .and. t(i)%group == 'rupture' .and. t(i)%name == 's_break') cycle
         call check_entry(c, t(i), error)
         if (allocated(error)) return
      end do
      call check_material_table(c, error)
      if (allocated(error)) return
      call check_law_values(c, 'material', 'cable', error)
      if (allocated(error)) return
      call check_segment_values(c, t, error)
      if (allocated(error)) return
      call check_points(c, t, error)
      if (allocated(error)) return
      call check_lines(c, t, error)
      if (allocated(error)) return
      call check_network_rupture(c, error)
      if (allocated(error)) return
      call derive_defaults(c)
      ! (Fortran does not short-circuit .and.: the division only where the divisor is positive.)
      if (c%t_end > max_time_steps*max(c%dt, 0.0_dp) .and. c%dt > 0) then
         call fatal_error(error, c%source//': &numerics: dt = '//real_text(c%dt)//': gives more than '// &
                          str(max_time_steps)//' steps to t_end = '//real_text(c%t_end)//'; must be at least t_end / '// &
                          str(max_time_steps)//' = '//real_text(c%t_end/max_time_steps), stat_input)
         return
      end if
      if (c%t_end > max_snapshots*max(c%interval, 0.0_dp) .and. c%interval > 0) then
         call fatal_error(error, c%source//': &output: interval = '//real_text(c%interval)// &
                          ': gives more than 100000 snapshots; must be at least t_end / 100000 = '// &
                          real_text(c%t_end/max_snapshots), stat_input)
         return
      end if
      call check_scene(c, error)
      if (allocated(error)) return
      call check_model(c, error)
      if (allocated(error)) return
      if (trim(c%file) == c%source .or. './'//trim(c%file) == c%source .or. trim(c%file) == './'//c%source) then
         call fatal_error(error, c%source//": &output: file = '"//trim(c%file)//"': is the input file itself", &
                          stat_input)
         return
      end if
      if (len_trim(c%file) == 0) then
         slash = index(c%source, '/', back=.true.)
         dot = index(c%source, '.', back=.true.)
         if (dot <= slash) dot = len(c%source) + 1
         c%file = 'results/'//c%source(slash + 1:dot - 1)//'.h5'
      end if
   end subroutine validate

   !> The checks of a law's values beyond the schema's ranges: the tanh law's coefficients,
   !> and an EI derived from young and the diameter. Lower bounds (issue 6, bad-input
   !> fuzzing): a value that is positive but tiny (1e-300) passed "> 0" and gave a zero mass,
   !> an infinite wave speed, a zero step or a singular Jacobian; the schema's ranges are
   !> generous physical ones. The tanh law's coefficients have ranges of their own.
   subroutine check_law_values(c, material_group, cable_group, error)
      !> The case, or the case as a segment sees it (case_config%segment_case).
      type(case_config), intent(in) :: c
      !> The groups named in messages: 'material' and 'cable', or the segment's twice.
      character(*), intent(in) :: material_group, cable_group
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (c%law == 'tanh') then
         call coefficient(1, 0.0_dp, 1.0e12_dp, .true.); if (allocated(error)) return
         call coefficient(2, 0.0_dp, 1.0e6_dp, .true.); if (allocated(error)) return
         call coefficient(3, -1.0e3_dp, 1.0e3_dp, .false.); if (allocated(error)) return
         call coefficient(5, 0.0_dp, 1.0e12_dp, .true.); if (allocated(error)) return
      end if
      ! An EI given is in range (above); one derived from young and d may not be:
      ! EI far below 1e-6 N m^2 leaves the moment balance empty at double precision.
      if (c%bending_stiffness == 0 .and. c%young*pi*c%diameter**4/64 < 1.0e-6_dp) then
         call fatal_error(error, c%source//': &'//cable_group//': young = '//real_text(c%young)//', diameter = '// &
                          real_text(c%diameter)//': give a bending stiffness E pi d^4 / 64 = '// &
                          str(c%young*pi*c%diameter**4/64)//' N m^2, below 1e-6; set bending_stiffness', stat_input)
         return
      end if

   contains

      !> A coefficient of the tanh law in its range.
      subroutine coefficient(k, lower, upper, open)
         !> Which coefficient.
         integer, intent(in) :: k
         !> Its range.
         real(dp), intent(in) :: lower, upper
         !> Whether the lower bound is excluded.
         logical, intent(in) :: open
         if (open) then
            if (c%p(k) > lower .and. c%p(k) <= upper) return
            call fatal_error(error, c%source//': &'//material_group//': p('//str(k)//') = '//real_text(c%p(k))// &
                             ': must be > '//real_text(lower)//' and <= '//real_text(upper)//' for the tanh law', &
                             stat_input)
         else
            if (c%p(k) >= lower .and. c%p(k) <= upper) return
            call fatal_error(error, c%source//': &'//material_group//': p('//str(k)//') = '//real_text(c%p(k))// &
                             ': must be in ['//real_text(lower)//', '//real_text(upper)//'] for the tanh law', stat_input)
         end if
      end subroutine coefficient
   end subroutine check_law_values

   !> The layout of a line of segments (&segment_1 ... &segment_n, numbered without a gap, which
   !> the reader checks): the rod scheme; every segment's length given and in range, and their
   !> sum &cable length (which is set to it when not given); nodes given in every segment
   !> (&numerics nodes then their sum less the joints) or in none (at least two cells a
   !> segment); a segment's breaking load only for a break by tension.
   subroutine check_segment_layout(c, t, error)
      !> The case; &cable length and &numerics nodes set from the segments when not given.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: prefix, terms, groups
      character(len=16) :: group
      real(dp) :: total
      integer :: n, k, given_nodes, line_nodes
      n = c%segment_count
      if (n == 0) return
      groups = group_list([(segment_group(k), k=1, n)], '&', '', ', ')
      if (trim(c%scheme) == 'box') then
         call fatal_error(error, c%source//": &numerics: scheme = 'box' with "//groups//': the box scheme '// &
                          "has one uniform cable; allowed: scheme = 'rod' for a line of segments", stat_input)
         return
      end if
      do k = 1, n
         group = segment_group(k)
         prefix = c%source//': &'//trim(group)//': '
         if (.not. c%is_given(trim(group), 'length')) then
            call fatal_error(error, prefix//'length not given: every segment needs its unstretched length '// &
                             '(m, in [0.01, 100000])', stat_input)
            return
         end if
         call check_entry(c, t(find_entry(t, group, 'length')), error)
         if (allocated(error)) return
         call check_entry(c, t(find_entry(t, group, 'nodes')), error)
         if (allocated(error)) return
         if (c%is_given(trim(group), 'mbl') .and. c%segments(k)%mbl > 0 .and. &
             .not. (c%break_enabled .and. trim(c%break_criterion) == 'tension')) then
            terms = "criterion = '"//trim(c%break_criterion)//"'"
            if (.not. c%break_enabled) terms = 'the line does not break (no &rupture, or enabled = .false.)'
            call fatal_error(error, prefix//'mbl = '//real_text(c%segments(k)%mbl)//": a segment's breaking "// &
                             "load is for &rupture criterion = 'tension', and here "//terms//"; give &rupture "// &
                             "criterion = 'tension', or leave mbl out", stat_input)
            return
         end if
      end do

      ! A network's lines have their own lengths and nodes (check_lines).
      if (c%line_count > 0) return
      total = sum(c%segments(1:n)%length)
      if (c%is_given('cable', 'length')) then
         if (abs(total - c%length) > 1.0e-9_dp*c%length) then
            terms = ''
            do k = 1, n
               if (k > 1) terms = terms//' + '
               terms = terms//real_text(c%segments(k)%length)
            end do
            call fatal_error(error, c%source//': &cable: length = '//real_text(c%length)//': the lengths of '// &
                             groups//' add up to '//terms//' = '//real_text(total)//'; must be their sum, or '// &
                             'leave &cable length out (it is then their sum)', stat_input)
            return
         end if
      else
         c%length = total
      end if

      given_nodes = 0
      do k = 1, n
         if (c%is_given(trim(segment_group(k)), 'nodes')) given_nodes = given_nodes + 1
      end do
      if (given_nodes > 0 .and. given_nodes < n) then
         do k = 1, n
            if (.not. c%is_given(trim(segment_group(k)), 'nodes')) exit
         end do
         call fatal_error(error, c%source//': &'//trim(segment_group(k))//': nodes not given, while '// &
                          str(given_nodes)//' of the '//str(n)//' segments give theirs: give nodes in every '// &
                          'segment, or in none (&numerics nodes are then shared by length)', stat_input)
         return
      end if
      if (given_nodes == n) then
         line_nodes = sum(c%segments(1:n)%nodes) - (n - 1)
         terms = ''
         do k = 1, n
            if (k > 1) terms = terms//' + '
            terms = terms//str(c%segments(k)%nodes)
         end do
         terms = terms//' - '//str(n - 1)//' joints = '//str(line_nodes)
         if (line_nodes < 3 .or. line_nodes > 100001) then
            call fatal_error(error, c%source//': '//groups//': nodes = '//terms//' nodes on the line; must be '// &
                             'from 3 to 100001', stat_input)
            return
         end if
         if (c%is_given('numerics', 'nodes') .and. c%nodes /= line_nodes) then
            call fatal_error(error, c%source//': &numerics: nodes = '//str(c%nodes)//': the segments give '// &
                             terms//' (a joint is a node of both segments); give nodes = '//str(line_nodes)// &
                             ', or leave &numerics nodes out', stat_input)
            return
         end if
         c%nodes = line_nodes
      else if (c%nodes < 2*n + 1) then
         call fatal_error(error, c%source//': &numerics: nodes = '//str(c%nodes)//': too few for '//str(n)// &
                          ' segments, each of which takes at least 2 cells of its own; must be at least 2*'// &
                          str(n)//' + 1 = '//str(2*n + 1)//', or give nodes in every segment', stat_input)
         return
      end if
   end subroutine check_segment_layout

   !> Each segment's variables against their schema entries (the ranges and words of their
   !> twins in &cable, &material and &fluid), its table law's rows (read from its table_file
   !> as &material's are), and the checks of &material's values run on the case as the
   !> segment sees it (case_config%segment_case), the messages naming &segment_k.
   subroutine check_segment_values(c, t, error)
      !> The case; a segment's table_file read into its rows.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: seen
      integer, allocatable :: mine(:)
      character(len=16) :: group
      character(:), allocatable :: what
      logical :: own_table
      integer :: k, i
      do k = 1, c%segment_count
         group = segment_group(k)
         ! Its law first: its table file is read only for the law 'table'.
         call check_entry(c, t(find_entry(t, group, 'law')), error)
         if (allocated(error)) return
         own_table = c%is_given(trim(group), 'table_strain') .or. c%is_given(trim(group), 'table_tension') .or. &
                     c%is_given(trim(group), 'table_file')
         seen = c%segment_case(k)
         if (seen%law == 'table' .and. c%is_given(trim(group), 'table_file')) then
            call load_segment_table(c, k, error)
            if (allocated(error)) return
         end if
         mine = group_entries(t, group)
         do i = 1, size(mine)
            ! (The law above, the length and nodes with the layout.)
            if (is_word(t(mine(i))%name, 'law length nodes')) cycle
            call check_entry(c, t(mine(i)), error)
            if (allocated(error)) return
         end do
         seen = c%segment_case(k)
         ! A law of its own other than 'table' has no table: the line's rows are not its.
         if (c%is_given(trim(group), 'law') .and. seen%law /= 'table' .and. .not. own_table) then
            seen%material_table_rows = 0
            seen%material_table_file = ''
         end if
         call check_material_table(seen, error, trim(group))
         if (allocated(error)) return
         call check_law_values(seen, trim(group), trim(group), error)
         if (allocated(error)) return
         if (c%fluid_density == 0 .and. c%air_density == 0) then
            what = ''
            if (c%is_given(trim(group), 'ca_normal') .and. seen%ca_normal /= 0) &
               what = 'ca_normal = '//real_text(seen%ca_normal)
            if (c%is_given(trim(group), 'cd_tangential') .and. seen%cd_tangential /= 0) &
               what = 'cd_tangential = '//real_text(seen%cd_tangential)
            if (c%is_given(trim(group), 'cd_normal') .and. seen%cd_normal /= 0) &
               what = 'cd_normal = '//real_text(seen%cd_normal)
            if (len(what) > 0) then
               call fatal_error(error, c%source//': &'//trim(group)//': '//what//': drag or added-mass '// &
                                'coefficients without a fluid (&fluid density = 0 and air_density = 0); give '// &
                                '&fluid density (> 0: 1025 for sea water) or air_density (1.225)', stat_input)
               return
            end if
         end if
      end do
   end subroutine check_segment_values

   !> Check one variable against its schema entry: a number against its
   !> range (0 allowed where it stands for a derived value; an upper bound
   !> may come from another variable), a string against its allowed words.
   subroutine check_entry(c, e, error)
      !> The case.
      type(case_config), intent(inout) :: c
      !> The variable.
      type(schema_entry), intent(in) :: e
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      type(config_value) :: v, bound
      type(schema_entry), allocatable :: t(:)
      real(dp) :: upper, x
      integer :: k, pos
      character(:), allocatable :: item, name, prefix
      logical :: ok

      call access(c, e, v, .false.)
      if (.not. v%found) then
         call fatal_error(error, c%source//': &'//trim(e%group)//': '//trim(e%name)// &
                          ': a variable of the schema that the reader does not know (io/input.f90 access)', stat_input)
         return
      end if
      ! A segment's variables: only those of the segments given, and a variable that takes its
      ! twin group's value only when given.
      if (segment_of(e%group) > c%segment_count) return
      if (len_trim(e%twin) > 0 .and. .not. c%is_given(trim(e%group), trim(e%name))) return
      prefix = c%source//': &'//trim(e%group)//': '
      select case (e%type)
      case ('real', 'integer')
         if (.not. e%bounded) return
         if (len_trim(e%default_means) > 0 .and. .not. c%is_given(trim(e%group), trim(e%name))) return
         upper = e%upper
         if (len_trim(e%upper_from) > 0) then
            t = schema_table()
            k = index(e%upper_from, '%')
            k = find_entry(t, e%upper_from(1:k - 1), trim(e%upper_from(k + 1:)))
            bound = get_value(c, t(k))
            upper = bound%reals(1)
         end if
         if (e%type == 'integer' .and. e%count == 1) v%reals = [real(v%int, dp)]
         do k = 1, size(v%reals)
            x = v%reals(k)
            if (len_trim(e%zero_means) > 0 .and. x == 0) cycle
            if (e%lower_open) then
               ok = x > e%lower .and. x <= upper
            else
               ok = x >= e%lower .and. x <= upper
            end if
            if (ok) cycle
            name = trim(e%name)
            if (e%count > 1) name = name//'('//str(k)//')'
            if (e%type == 'integer') then
               item = str(nint(x))
            else
               item = real_text(x)
            end if
            item = prefix//name//' = '//item//': must be '//allowed_text(e, upper)
            if (len_trim(e%note) > 0) item = item//' ('//trim(e%note)//')'
            call fatal_error(error, item, stat_input)
            return
         end do
      case ('string')
         if (len_trim(e%choices) == 0) return
         if (.not. e%word_list) then
            if (is_word(v%text, e%choices)) return
            ! ('' where it has a meaning: &point_k kind not given.)
            if (len_trim(v%text) == 0 .and. len_trim(e%zero_means) > 0) return
            call fatal_error(error, prefix//trim(e%name)//" = '"//shown(v%text)//"': must be "//allowed_text(e), &
                             stat_input)
            return
         end if
         pos = 1
         do
            call next_item(v%text, pos, item)
            if (len(item) == 0) exit
            if (is_word(item, e%choices)) cycle
            call fatal_error(error, prefix//trim(e%name)//" = '"//shown(v%text)//"': unknown word "//'"'//item// &
                             '"; allowed: '//comma_words(e%choices), stat_input)
            return
         end do
      end select
   end subroutine check_entry

   !> Blank-separated words as 'a, b, c'.
   function comma_words(words) result(s)
      !> Blank-separated words.
      character(*), intent(in) :: words
      character(:), allocatable :: s, item
      integer :: pos
      s = ''
      pos = 1
      do
         call next_item(words, pos, item)
         if (len(item) == 0) exit
         if (len(s) > 0) s = s//', '
         s = s//item
      end do
   end function comma_words

   !> The conditions between variables: the tension or the end positions,
   !> each end against its kind, a support, and a break where something holds.
   subroutine check_scene(c, error)
      !> The case (validated variables, derived values); motion directions normalised.
      type(case_config), intent(inout) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: position, broken, held
      type(end_config) :: e
      logical :: held_a, held_b

      e = c%end_a
      call check_end(c, 'end_a', e, c%end_b, error)
      if (allocated(error)) return
      c%end_a = e
      e = c%end_b
      call check_end(c, 'end_b', e, c%end_a, error)
      if (allocated(error)) return
      c%end_b = e

      if (c%is_given('static', 'tension') .and. (c%is_given('end_b', 'x') .or. c%is_given('end_b', 'y') .or. &
                                                 c%is_given('end_b', 'z'))) then
         if (c%is_given('end_b', 'x')) then
            position = 'x = '//real_text(c%end_b%x)
         else if (c%is_given('end_b', 'y')) then
            position = 'y = '//real_text(c%end_b%y)
         else
            position = 'z = '//real_text(c%end_b%z)
         end if
         call fatal_error(error, c%source//': &static: tension = '//real_text(c%tension)//' and &end_b '//position// &
                          ': both given; give one: the tension (the paper'//"'"//'s symmetric case: end b at the '// &
                          'height of end a, the span from the tension) or the end positions', stat_input)
         return
      end if

      if (c%fluid_density == 0 .and. (c%current_x /= 0 .or. c%current_y /= 0 .or. c%current_z /= 0)) then
         if (c%current_x /= 0) then
            position = 'current_x = '//real_text(c%current_x)
         else if (c%current_y /= 0) then
            position = 'current_y = '//real_text(c%current_y)
         else
            position = 'current_z = '//real_text(c%current_z)
         end if
         call fatal_error(error, c%source//': &fluid: '//position//': a current needs a fluid; give &fluid density '// &
                          '(> 0: 1025 for sea water, 1.2 for air)', stat_input)
         return
      end if
      if (c%fluid_density == 0 .and. c%air_density == 0 .and. &
          (c%cd_normal /= 0 .or. c%cd_tangential /= 0 .or. c%ca_normal /= 0)) then
         call fatal_error(error, c%source//': &fluid: drag or added-mass coefficients without a fluid (density = 0 '// &
                          'and air_density = 0); give &fluid density (> 0: 1025 for sea water) or air_density '// &
                          '(1.225)', stat_input)
         return
      end if

      ! The seabed: held ends and anchors above it, the water's surface above it where the line is.
      if (c%has_seabed()) then
         call above_seabed(c%end_a, 'end_a', error)
         if (allocated(error)) return
         call above_seabed(c%end_b, 'end_b', error)
         if (allocated(error)) return
         if (allocated(c%bathymetry_depth)) then
            if (c%fluid_density > 0 .and. c%surface_z < -maxval(c%bathymetry_depth)) then
               call fatal_error(error, c%source//': &fluid: surface_z = '//real_text(c%surface_z)//': below the '// &
                                'deepest point of the bathymetry (z = '//real_text(-maxval(c%bathymetry_depth))// &
                                ', &seabed bathymetry_file = '''//trim(c%bathymetry_file)//'''); the water''s level '// &
                                'must lie above the bottom', stat_input)
               return
            end if
         else if (c%fluid_density > 0 .and. c%surface_z < -c%seabed_depth) then
            call fatal_error(error, c%source//': &fluid: surface_z = '//real_text(c%surface_z)//': below the seabed '// &
                             '(z = '//real_text(-c%seabed_depth)//' at x = y = 0, &seabed depth = '// &
                             real_text(c%seabed_depth)//'); the water''s level must lie above the bottom', stat_input)
            return
         end if
      end if
      ! Friction in the statics needs a bottom and a friction coefficient along the line.
      if (trim(c%static_friction) /= 'none' .and. (.not. c%has_seabed() .or. c%mu_axial <= 0)) then
         call fatal_error(error, c%source//": &seabed: static_friction = '"//trim(c%static_friction)//"': friction "// &
                          'in the statics needs a seabed (depth > 0, now '//real_text(c%seabed_depth)// &
                          ') and a friction coefficient along the line (mu_axial > 0, now '//real_text(c%mu_axial)// &
                          "); give them, or static_friction = 'none'", stat_input)
         return
      end if

      held = quoted_words(end_kind_names(held=.true.), ' or ')
      held_a = is_word(c%end_a%kind, end_kind_names(held=.true.))
      held_b = is_word(c%end_b%kind, end_kind_names(held=.true.))
      if (.not. (held_a .or. held_b)) then
         if (c%end_a%kind == 'free' .and. c%end_b%kind == 'free') then
            call fatal_error(error, c%source//": &end_a: kind = 'free' and &end_b: kind = 'free': a cable with no "// &
                             'support has no static state; make one end '//held, stat_input)
         else
            call fatal_error(error, c%source//": &end_a: kind = '"//trim(c%end_a%kind)//"' and &end_b: kind = '"// &
                             trim(c%end_b%kind)//"': nothing holds the cable (no "//held//' end), so it '// &
                             'has no static state; make one end '//held, stat_input)
         end if
         return
      end if

      ! A network's break: its lines and points (check_network_rupture); not these ends'.
      if (c%line_count > 0) return

      ! A break by tension: where and when follow from mbl, not from s_break and time.
      if (c%break_enabled .and. trim(c%break_criterion) == 'tension') then
         if (trim(c%scheme) == 'box') then
            call fatal_error(error, c%source//": &rupture: criterion = 'tension': the box scheme breaks at a time "// &
                             "only; give &numerics scheme = 'rod', or criterion = 'time'", stat_input)
            return
         end if
         if (c%is_given('rupture', 's_break') .or. c%is_given('rupture', 'time')) then
            position = ''
            if (c%is_given('rupture', 's_break')) position = ' s_break = '//real_text(c%s_break)
            if (c%is_given('rupture', 's_break') .and. c%is_given('rupture', 'time')) position = position//' and'
            if (c%is_given('rupture', 'time')) position = position//' time = '//real_text(c%break_time)
            call fatal_error(error, c%source//": &rupture: criterion = 'tension' with"//position// &
                             ': the line parts where and when its tension first reaches mbl, so s_break and '// &
                             "time are not used; leave them out, or give criterion = 'time'", stat_input)
            return
         end if
         if (c%segment_count > 0) then
            ! On a line of segments: a breaking load for every segment, its own or the line's.
            call check_segment_loads(c, error)
            return
         else if (.not. c%is_given('rupture', 'mbl') .or. c%mbl <= 0) then
            position = 'not given'
            if (c%is_given('rupture', 'mbl')) position = real_text(c%mbl)
            call fatal_error(error, c%source//": &rupture: mbl = "//position//": criterion = 'tension' needs the "// &
                             'minimum breaking load of the line, a tension above 0 N (and above the largest '// &
                             'static tension)', stat_input)
            return
         end if
         return
      end if

      if (c%break_enabled .and. (c%s_break == 0 .or. c%s_break == c%length)) then
         if (c%s_break == 0) then
            broken = 'a'
            if (held_a) return
         else
            broken = 'b'
            if (held_b) return
         end if
         position = real_text(c%s_break)
         if (.not. c%is_given('rupture', 's_break')) position = position//' (the default, L)'
         if (broken == 'a') then
            position = position//", at end a, whose kind = '"//trim(c%end_a%kind)//"'"
         else
            position = position//", at end b, whose kind = '"//trim(c%end_b%kind)//"'"
         end if
         call fatal_error(error, c%source//': &rupture: s_break = '//position//': nothing holds that end, so '// &
                          'there is nothing to break; break at a '//held//' end, inside the cable '// &
                          '(0 < s_break < L), or set enabled = .false.', stat_input)
      end if

   contains

      !> A held end or a spring's anchor at or above the seabed (1 mm below it allowed: an anchor
      !> placed on the bottom, written with rounding).
      subroutine above_seabed(e, group, error)
         type(end_config), intent(in) :: e
         character(*), intent(in) :: group
         type(error_type), allocatable, intent(out) :: error
         real(dp) :: bottom
         ! The kinds placed at a point x, y, z (a held end's position, a spring's anchor).
         if (.not. is_word(e%kind, kinds_using('z'))) return
         bottom = c%seabed_z(e%x, e%y)
         if (e%z >= bottom - 1.0e-3_dp) return
         if (allocated(c%bathymetry_depth)) then
            call fatal_error(error, c%source//': &'//group//': z = '//real_text(e%z)//': the '//trim(e%kind)// &
                             ' end is below the seabed (z = '//real_text(bottom)//' there, &seabed bathymetry_file '// &
                             '= '''//trim(c%bathymetry_file)//'''); place it on or above the bottom', stat_input)
         else
            call fatal_error(error, c%source//': &'//group//': z = '//real_text(e%z)//': the '//trim(e%kind)// &
                             ' end is below the seabed (z = '//real_text(bottom)//' there, &seabed depth = '// &
                             real_text(c%seabed_depth)//'); place it on or above the bottom', stat_input)
         end if
      end subroutine above_seabed
   end subroutine check_scene

   !> A break by tension on a line of segments (or the segments of a network's lines, all of
   !> which serve a line): the minimum breaking load of every segment, its own (&segment_k mbl)
   !> or &rupture mbl.
   subroutine check_segment_loads(c, error)
      !> The case.
      type(case_config), intent(in) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: position
      integer :: k
      if (c%is_given('rupture', 'mbl') .and. c%mbl > 0) return
      position = 'not given'
      if (c%is_given('rupture', 'mbl')) position = real_text(c%mbl)
      do k = 1, c%segment_count
         if (c%segments(k)%mbl > 0) cycle
         call fatal_error(error, c%source//': &'//trim(segment_group(k))//": mbl = 0 and &rupture mbl = "// &
                          position//": criterion = 'tension' needs the minimum breaking load of every segment, a "// &
                          'tension above 0 N: give mbl in &'//trim(segment_group(k))//' or &rupture mbl', &
                          stat_input)
         return
      end do
   end subroutine check_segment_loads

   !> The model against the scene: 3-D data under model = '2d', and what the
   !> 3-D model does not do (the box scheme).
   subroutine check_model(c, error)
      !> The case.
      type(case_config), intent(in) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: what
      if (trim(c%model) == '2d' .and. .not. c%is_planar()) then
         what = out_of_plane(c)
         call fatal_error(error, c%source//': &numerics: model = '//"'2d'"//' with '//what// &
                          ': the 2-D model keeps the cable in the x-z plane; allowed: model = '//"'3d' or 'auto'"// &
                          ', or y components and torques of 0', stat_input)
         return
      end if
      if (c%model_to_run() /= '3d') return
      what = "model = '"//trim(c%model)//"'"
      if (trim(c%model) == 'auto') what = what//' (3-D: '//out_of_plane(c)//')'
      if (trim(c%scheme) == 'box') &
         call fatal_error(error, c%source//": &numerics: scheme = 'box' with "//what//': the box scheme is '// &
                          "planar; allowed: scheme = 'rod' for the 3-D model", stat_input)
   end subroutine check_model

   !> The first datum of a case that leaves the x-z plane, as 'group: variable = value'.
   function out_of_plane(c) result(text)
      type(case_config), intent(in) :: c
      character(:), allocatable :: text
      text = ''
      call end_datum(c%end_a, 'end_a')
      call end_datum(c%end_b, 'end_b')
      if (len(text) == 0 .and. c%current_y /= 0) text = '&fluid current_y = '//real_text(c%current_y)
   contains
      subroutine end_datum(e, group)
         type(end_config), intent(in) :: e
         character(*), intent(in) :: group
         integer :: k
         if (len(text) > 0) return
         if (e%y /= 0) then
            text = '&'//group//' y = '//real_text(e%y)
         else if (e%force_y /= 0) then
            text = '&'//group//' force_y = '//real_text(e%force_y)
         else if (e%direction_y /= 0) then
            text = '&'//group//' direction_y = '//real_text(e%direction_y)
         else if (e%torque /= 0) then
            text = '&'//group//' torque = '//real_text(e%torque)
         else if (any(e%table_y(1:e%table_rows) /= 0)) then
            k = findloc(e%table_y(1:e%table_rows) /= 0, .true., 1)
            text = '&'//group//' table_y('//str(k)//') = '//real_text(e%table_y(k))
         end if
      end subroutine end_datum
   end function out_of_plane

   !> The conditions of one end: no variable its kind does not use (the kinds of
   !> the registry, ends/registry.f90: a position x, y, z where the statics give
   !> it is refused when given at all, another variable when it differs from its
   !> default: the echo writes every variable), the conditions of its kind (its
   !> registry line's check), and the motion direction normalised.
   subroutine check_end(c, group, e, other, error)
      !> The case (for its source and what was given).
      type(case_config), intent(in) :: c
      !> 'end_a' or 'end_b'.
      character(*), intent(in) :: group
      !> The end; its motion direction is normalised.
      type(end_config), intent(inout) :: e
      !> The other end.
      type(end_config), intent(in) :: other
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      type(schema_entry), allocatable :: t(:)
      integer, allocatable :: mine(:)
      type(end_kind) :: line, other_line
      character(:), allocatable :: prefix, kind, name, value
      logical :: found, other_found
      real(dp) :: norm
      integer :: i

      prefix = c%source//': &'//group//': '
      kind = "kind = '"//trim(e%kind)//"'"
      call find_end_kind(e%kind, line, found)
      if (.not. found) then
         call fatal_error(error, prefix//kind//': unknown kind; registered: '// &
                          quoted_words(end_kind_names(), ', '), stat_input)
         return
      end if
      t = schema_table()
      mine = group_entries(t, group)
      do i = 1, size(mine)
         name = trim(t(mine(i))%name)
         if (name == 'kind' .or. is_word(name, line%variables)) cycle
         if (.not. c%is_given(group, name)) cycle
         value = value_text(c, t(mine(i)))
         if (is_word(name, 'x y z')) then
            call fatal_error(error, prefix//name//' = '//value//': given for '//kind//": the position of a '"// &
                             trim(e%kind)//"' end follows from the statics; leave "//name//' out', stat_input)
            return
         end if
         if (value == trim(t(mine(i))%default)) cycle
         call fatal_error(error, prefix//name//' = '//value//': given for '//kind//', which does not use it: '// &
                          name//' is a variable of kind '//quoted_words(kinds_using(name), ' or ')//'; '// &
                          kind//' takes '//variable_list(line%variables), stat_input)
         return
      end do
      if (associated(line%check)) then
         call find_end_kind(other%kind, other_line, other_found)
         call line%check(prefix, e, other, other_found .and. other_line%held, error)
         if (allocated(error)) return
      end if
      norm = norm2([e%direction_x, e%direction_y, e%direction_z])
      if (norm > 0) then
         e%direction_x = e%direction_x/norm
         e%direction_y = e%direction_y/norm
         e%direction_z = e%direction_z/norm
      end if
      call check_column(prefix, 'table_time', e%table_time(1:e%table_rows), time_order, error)

   contains

      !> A kind's variables as 'x, y, z' ('no other variable' when none).
      function variable_list(words) result(text)
         character(*), intent(in) :: words
         character(:), allocatable :: text
         text = comma_words(words)
         if (len(text) == 0) text = 'no other variable'
      end function variable_list
   end subroutine check_end

   !> Blank-separated words as "'a', 'b' and 'c'" with the given last separator (' or ').
   function quoted_words(words, last) result(text)
      !> The words.
      character(*), intent(in) :: words
      !> Separator before the last word (', ' for all commas).
      character(*), intent(in) :: last
      character(:), allocatable :: text, item
      integer :: pos, n, k
      n = 0
      pos = 1
      do
         call next_item(words, pos, item)
         if (len(item) == 0) exit
         n = n + 1
      end do
      text = ''
      pos = 1
      do k = 1, n
         call next_item(words, pos, item)
         if (k > 1 .and. k == n) then
            text = text//last
         else if (k > 1) then
            text = text//', '
         end if
         text = text//"'"//item//"'"
      end do
   end function quoted_words
end module xcable_io_input_checks
