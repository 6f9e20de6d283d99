!> Namelist input of a network of lines (&line_1 ... &line_8 between the network points,
!> &point_k with a kind; issue 31): a three-line spread meeting at a free buoy read back, each
!> line's single-line case (case_config%line_case: its segments, length, ends and the buoy on
!> line 1 only), the ends meeting at a point, the echo read back, the run refused until the
!> driver exists, and one test per refusal, each checking that the one-line message names the
!> group, the variable and its value.
module suite_input_network
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_error, only: fatal_error, stat_input
   use xcable_io_input, only: case_config, read_config, config_text
   use xcable_io_input_checks, only: validate
   use xcable_driver_simulation, only: simulation
   use xcable_fixtures, only: write_text
   implicit none
   private
   public :: collect_input_network

   character(len=*), parameter :: path = 'build/test_input_network.nml'
   character(len=*), parameter :: echo_path = 'build/test_input_network_echo.nml'
   character(len=*), parameter :: table_path = 'build/test_input_network_motion.dat'
   character(len=*), parameter :: nl = new_line('a')

   !> The line and water of the spread (no &cable length: each line has its own).
   character(len=*), parameter :: scene = '&cable diameter = 0.1, density = 7850 /'//nl// &
                                          '&fluid density = 1025 /'//nl// &
                                          '&segment_1 length = 50, nodes = 11 /'//nl// &
                                          '&segment_2 length = 100, nodes = 21 /'//nl// &
                                          '&numerics t_end = 1 /'//nl

   !> The buoy and the three anchors (the third moved by a harmonic motion).
   character(len=*), parameter :: buoy = "&point_1 kind = 'free', z = -20, volume = 10, mass = 1000 /"//nl
   character(len=*), parameter :: anchor_2 = "&point_2 kind = 'fixed', x = 200, z = -100 /"//nl
   character(len=*), parameter :: anchor_3 = "&point_3 kind = 'fixed', x = -100, y = 173.2, z = -100 /"//nl
   character(len=*), parameter :: anchor_4 = "&point_4 kind = 'motion', x = -100, y = -173.2, z = -100, "// &
                                             'amplitude = 1, period = 10, direction_x = 2, direction_z = 0 /'//nl

   !> The lines: two of the segments 1 and 2, one uniform.
   character(len=*), parameter :: line_1 = "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 2 /"//nl
   character(len=*), parameter :: line_2 = "&line_2 end_a = 'Point_3', end_b = 'point_1', segments = 1, 2 /"//nl
   character(len=*), parameter :: line_3 = "&line_3 end_a = 'point_4', end_b = 'point_1', length = 160, nodes = 31 /"//nl

contains

   !> The tests of the network's input.
   subroutine collect_input_network(tests)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('spread_read', test_read), &
               new_unittest('spread_line_cases', test_line_cases), &
               new_unittest('spread_echo_round_trip', test_echo), &
               new_unittest('spread_out_of_reach_refused', test_run_refused), &
               new_unittest('point_joins_no_line', test_joins_no_line), &
               new_unittest('line_end_no_such_point', test_no_such_point), &
               new_unittest('line_end_on_a_body', test_end_on_body), &
               new_unittest('line_closed_on_itself', test_closed), &
               new_unittest('lines_floating', test_floating), &
               new_unittest('line_segment_out_of_range', test_segment_range), &
               new_unittest('line_segment_not_given', test_segment_missing), &
               new_unittest('segment_used_by_no_line', test_segment_unused), &
               new_unittest('line_numbering_gap', test_gap), &
               new_unittest('line_end_not_given', test_end_missing), &
               new_unittest('line_length_not_the_segments', test_length_sum), &
               new_unittest('line_length_not_given', test_length_missing), &
               new_unittest('line_nodes_with_segments', test_nodes_with_segments), &
               new_unittest('network_with_end_groups', test_end_groups), &
               new_unittest('network_with_static_tension', test_static), &
               new_unittest('network_box_scheme', test_box), &
               new_unittest('network_2d_model', test_2d), &
               new_unittest('network_break_line_not_given', test_break_line_missing), &
               new_unittest('network_break_no_such_line', test_break_no_such_line), &
               new_unittest('network_break_beyond_the_line', test_break_beyond_line), &
               new_unittest('network_break_at_a_free_end_b', test_break_free_b), &
               new_unittest('network_break_at_a_free_end_a', test_break_free_a), &
               new_unittest('network_tension_break_with_line', test_tension_with_line), &
               new_unittest('network_tension_uniform_line_without_mbl', test_tension_uniform), &
               new_unittest('network_tension_segment_without_mbl', test_tension_segment), &
               new_unittest('rupture_line_without_network', test_line_single), &
               new_unittest('network_break_by_time', test_break_by_time), &
               new_unittest('network_break_at_held_ends', test_break_held_ends), &
               new_unittest('network_break_disabled', test_break_disabled), &
               new_unittest('network_break_by_tension_line_cases', test_break_by_tension), &
               new_unittest('network_break_echo_round_trip', test_break_echo), &
               new_unittest('network_static_friction', test_static_friction), &
               new_unittest('network_body_on_joint', test_body_joint), &
               new_unittest('network_point_without_lines', test_without_lines), &
               new_unittest('network_point_with_joint', test_point_joint), &
               new_unittest('network_body_on_held_point', test_body_held), &
               new_unittest('network_point_variable_of_another_kind', test_other_kind), &
               new_unittest('network_variable_on_a_body', test_network_variable_on_body), &
               new_unittest('network_motion_point_checks', test_motion_check), &
               new_unittest('line_nodes_in_some_segments', test_nodes_some), &
               new_unittest('line_nodes_too_few', test_nodes_too_few), &
               new_unittest('network_buoy_without_water', test_buoy_dry), &
               new_unittest('network_anchor_below_seabed', test_below_seabed), &
               new_unittest('motion_point_tables', test_motion_tables)]
   end subroutine collect_input_network

   !> The whole spread.
   function spread() result(text)
      character(:), allocatable :: text
      text = scene//buoy//anchor_2//anchor_3//anchor_4//line_1//line_2//line_3
   end function spread

   !> Read text as a case and expect an input error (one line, class stat_input) whose
   !> message contains every one of the words.
   subroutine expect_refusal(error, text, words)
      type(error_type), allocatable, intent(out) :: error
      character(*), intent(in) :: text
      character(len=*), intent(in) :: words(:)
      type(case_config) :: config
      type(error_type), allocatable :: err
      integer :: i
      call write_text(path, text)
      call read_config(path, config, err)
      if (.not. allocated(err)) then
         call fatal_error(error, 'accepted: '//text)
         return
      end if
      call check(error, err%stat == stat_input, 'not classed as bad input: '//err%message)
      if (allocated(error)) return
      call check(error, index(err%message, nl) == 0, 'message is not one line: '//err%message)
      if (allocated(error)) return
      do i = 1, size(words)
         call check(error, index(err%message, trim(words(i))) > 0, 'message lacks "'//trim(words(i))//'": '// &
                    err%message)
         if (allocated(error)) return
      end do
   end subroutine expect_refusal

   !> The spread read: three lines, four points, the lines' ends resolved (a name in capitals
   !> too), the lengths and nodes resolved, the model 3-D, and the three line ends at the buoy.
   subroutine test_read(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      integer, allocatable :: ends(:, :)
      call write_text(path, spread())
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, c%line_count == 3 .and. c%point_count == 4 .and. c%segment_count == 2, &
                 'counts of lines, points and segments')
      if (allocated(error)) return
      call check(error, all(c%lines(1)%end_point == [2, 1]) .and. all(c%lines(2)%end_point == [3, 1]) .and. &
                 all(c%lines(3)%end_point == [4, 1]), 'the points at the lines'' ends')
      if (allocated(error)) return
      call check(error, c%lines(1)%segment_count == 2 .and. all(c%lines(1)%segments(1:2) == [1, 2]) .and. &
                 c%lines(3)%segment_count == 0, 'the lines'' segments')
      if (allocated(error)) return
      call check(error, c%lines(1)%length == 150 .and. c%lines(2)%length == 150 .and. c%lines(3)%length == 160 .and. &
                 c%lines(3)%nodes == 31, 'the lines'' lengths (the sum of the segments) and nodes')
      if (allocated(error)) return
      call check(error, c%model_to_run() == '3d' .and. c%is_network(), "model 'auto' of a network: 3-D")
      if (allocated(error)) return
      ends = c%point_lines(1)
      call check(error, size(ends, 2) == 3, 'three line ends at the buoy')
      if (allocated(error)) return
      call check(error, all(ends(:, 1) == [1, 2]) .and. all(ends(:, 2) == [2, 2]) .and. all(ends(:, 3) == [3, 2]), &
                 'the ends at the buoy: end b of lines 1, 2, 3')
      if (allocated(error)) return
      ends = c%point_lines(4)
      call check(error, size(ends, 2) == 1 .and. all(ends(:, 1) == [3, 1]), 'point 4: end a of line 3')
      if (allocated(error)) return
      ! The motion point's direction normalised, as an end's.
      call check(error, c%point_ends(4)%direction_x == 1 .and. c%point_ends(4)%direction_z == 0 .and. &
                 c%point_ends(4)%kind == 'motion', &
                 'the motion direction normalised')
   end subroutine test_read

   !> Each line as a single line: its segments (shared groups copied in order), its length, its
   !> ends from the points (the buoy held at its first guess), the buoy's body on line 1 only
   !> (at its end b, joint 2), and is_given for the groups made.
   subroutine test_line_cases(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, l1, l2, l3
      call write_text(path, spread())
      call read_config(path, c, error)
      if (allocated(error)) return
      l1 = c%line_case(1)
      l2 = c%line_case(2)
      l3 = c%line_case(3)
      call check(error, l1%line_count == 0 .and. l1%segment_count == 2 .and. l1%segments(1)%length == 50 .and. &
                 l1%segments(2)%length == 100 .and. l1%length == 150 .and. l1%nodes == 11 + 21 - 1, &
                 'line 1: segments 1 and 2, 150 m, 31 nodes')
      if (allocated(error)) return
      call check(error, trim(l1%end_a%kind) == 'fixed' .and. l1%end_a%x == 200 .and. l1%end_a%z == -100 .and. &
                 trim(l1%end_b%kind) == 'fixed' .and. l1%end_b%x == 0 .and. l1%end_b%z == -20, &
                 'line 1: end a the anchor, end b the buoy held at its first guess')
      if (allocated(error)) return
      call check(error, l1%point_count == 1 .and. l1%points(1)%joint == 2 .and. l1%points(1)%mass == 1000 .and. &
                 l1%points(1)%volume == 10 .and. .not. l1%points(1)%in_network(), 'line 1: the buoy at its end b')
      if (allocated(error)) return
      call check(error, l1%is_given('point_1', 'joint') .and. l1%is_given('point_1', 'volume') .and. &
                 .not. l1%is_given('point_1', 'cd') .and. l1%is_given('segment_2', 'nodes') .and. &
                 l1%is_given('end_a', 'x') .and. .not. l1%is_given('line_1', 'end_a') .and. &
                 .not. l1%is_given('point_1', 'kind'), 'line 1: is_given of the groups made')
      if (allocated(error)) return
      call check(error, l2%point_count == 0 .and. l2%end_a%y == 173.2_dp .and. l2%segment_count == 2, &
                 'line 2: no body (it is on line 1), its anchor')
      if (allocated(error)) return
      call check(error, l3%segment_count == 0 .and. l3%length == 160 .and. l3%nodes == 31 .and. &
                 l3%point_count == 0 .and. trim(l3%end_a%kind) == 'motion' .and. l3%end_a%amplitude == 1 .and. &
                 l3%end_a%period == 10 .and. l3%is_given('end_a', 'amplitude') .and. l3%is_given('cable', 'length') &
                 .and. l3%model_to_run() == '3d' .and. .not. l3%break_enabled, &
                 'line 3: uniform, 160 m, 31 nodes, end a the motion point')
   end subroutine test_line_cases

   !> The echo of the spread reads back to the same echo.
   subroutine test_echo(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, back
      character(:), allocatable :: text
      call write_text(path, spread())
      call read_config(path, c, error)
      if (allocated(error)) return
      text = config_text(c)
      call check(error, index(text, "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 2, length = 150 /") > 0 &
                 .and. index(text, "&point_1 kind = 'free', mass = 1000") > 0 .and. index(text, 'joint') == 0 .and. &
                 index(text, '&end_a') == 0 .and. index(text, '&static') == 0, &
                 'the echo of line 1 and the buoy: '//text)
      if (allocated(error)) return
      call write_text(echo_path, text)
      call read_config(echo_path, back, error)
      if (allocated(error)) return
      back%source = c%source
      back%file = c%file
      call check(error, config_text(back) == text, 'the echo read back differs: '//config_text(back))
   end subroutine test_echo

   !> The run of a network is refused at its preparation, one line naming &line_1.
   subroutine test_run_refused(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      type(simulation) :: sim
      type(error_type), allocatable :: err
      call write_text(path, spread())
      call read_config(path, c, error)
      if (allocated(error)) return
      call sim%prepare(c, err)
      call check(error, allocated(err), 'a network was prepared')
      if (allocated(error)) return
      ! The buoy's guess (0, 0, -20) is 215 m from the anchor of &point_2, out of reach of 150 m of line.
      call check(error, err%stat == stat_input .and. index(err%message, '&line_1') > 0 .and. &
                 index(err%message, '&point_1 (its end b)') > 0 .and. index(err%message, 'within reach') > 0 .and. &
                 index(err%message, nl) == 0, err%message)
   end subroutine test_run_refused

   subroutine test_joins_no_line(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//"&point_5 kind = 'fixed', x = 1 /"//nl, &
                          [character(len=40) :: '&point_5', "kind 'fixed' joins no line", 'end_a or end_b'])
   end subroutine test_joins_no_line

   subroutine test_no_such_point(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4//line_1//line_2// &
                          "&line_3 end_a = 'point_9', end_b = 'point_1', length = 160 /"//nl, &
                          [character(len=40) :: '&line_3', "end_a = 'point_9'", 'no such point', "'point_4'"])
   end subroutine test_no_such_point

   subroutine test_end_on_body(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//'&point_4 joint = 1, mass = 5 /'//nl// &
                          line_1//line_2//line_3, &
                          [character(len=40) :: '&line_3', "end_a = 'point_4'", '&point_4 has no kind'])
   end subroutine test_end_on_body

   subroutine test_closed(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4//line_1//line_2//line_3// &
                          "&line_4 end_a = 'point_1', end_b = 'point_1', length = 10 /"//nl, &
                          [character(len=40) :: '&line_4', "end_a = 'point_1', end_b = 'point_1'", &
                          'both ends on one point'])
   end subroutine test_closed

   !> Two buoys joined by a line, apart from the anchored spread: they float.
   subroutine test_floating(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//"&point_5 kind = 'free', x = 5 /"//nl// &
                          "&point_6 kind = 'free', x = 9 /"//nl// &
                          "&line_4 end_a = 'point_5', end_b = 'point_6', length = 10 /"//nl, &
                          [character(len=40) :: '&line_4', '&point_5, &point_6', 'nothing holds them'])
   end subroutine test_floating

   subroutine test_segment_range(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4// &
                          "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 9 /"//nl//line_2//line_3, &
                          [character(len=40) :: '&line_1', 'segments(2) = 9', 'from 1 to 8'])
   end subroutine test_segment_range

   subroutine test_segment_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4// &
                          "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 3 /"//nl//line_2//line_3, &
                          [character(len=40) :: '&line_1', 'segments(2) = 3', '&segment_3 is not given', &
                          'allowed: 1 .. 2'])
   end subroutine test_segment_missing

   subroutine test_segment_unused(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&segment_3 length = 5 /'//nl, &
                          [character(len=40) :: '&segment_3', 'used by no line'])
   end subroutine test_segment_unused

   subroutine test_gap(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4//line_1//line_3, &
                          [character(len=40) :: '&line_3 given without &line_2', 'without a gap'])
   end subroutine test_gap

   subroutine test_end_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4//line_1//line_2// &
                          "&line_3 end_a = 'point_4', length = 160 /"//nl, &
                          [character(len=40) :: '&line_3', 'end_b not given'])
   end subroutine test_end_missing

   subroutine test_length_sum(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4// &
                          "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 2, length = 140 /"//nl// &
                          line_2//line_3, &
                          [character(len=40) :: '&line_1', 'length = 140', '50 + 100 = 150', 'must be their sum'])
   end subroutine test_length_sum

   subroutine test_length_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4//line_1//line_2// &
                          "&line_3 end_a = 'point_4', end_b = 'point_1' /"//nl, &
                          [character(len=40) :: '&line_3', 'length not given', '&cable length'])
   end subroutine test_length_missing

   subroutine test_nodes_with_segments(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, scene//buoy//anchor_2//anchor_3//anchor_4// &
                          "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 2, nodes = 5 /"//nl// &
                          line_2//line_3, &
                          [character(len=40) :: '&line_1', 'nodes = 5', 'given for a line of segments'])
   end subroutine test_nodes_with_segments

   subroutine test_end_groups(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//"&end_b kind = 'free' /"//nl, &
                          [character(len=60) :: "&end_b: kind = 'free' with &line_1 ... &line_3", &
                          'leave &end_a and &end_b out'])
   end subroutine test_end_groups

   subroutine test_static(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&static tension = 3e5 /'//nl, &
                          [character(len=40) :: '&static: tension = 300000', 'leave &static out'])
   end subroutine test_static

   subroutine test_box(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), '&numerics t_end = 1 /', "&numerics scheme = 'box', t_end = 1 /"), &
                          [character(len=40) :: "&numerics: scheme = 'box'", "scheme = 'rod' for a network"])
   end subroutine test_box

   subroutine test_2d(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), '&numerics t_end = 1 /', "&numerics model = '2d', t_end = 1 /"), &
                          [character(len=40) :: "&numerics: model = '2d'", "allowed: model = '3d' or 'auto'"])
   end subroutine test_2d

   subroutine test_static_friction(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//"&seabed depth = 100.0, static_friction = 'end_a' /"//nl, &
                          [character(len=40) :: "&seabed: static_friction = 'end_a'", "allowed: static_friction = 'none'"])
   end subroutine test_static_friction

   !> A break by time without the line that parts.
   subroutine test_break_line_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&rupture t_break = 0.01 /'//nl, &
                          [character(len=50) :: '&rupture: line not given', "criterion = 'time'", &
                          'give line = 1 .. 3'])
   end subroutine test_break_line_missing

   subroutine test_break_no_such_line(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&rupture line = 5 /'//nl, &
                          [character(len=50) :: '&rupture: line = 5', 'no such line', 'allowed: 1 .. 3'])
   end subroutine test_break_no_such_line

   !> s_break beyond the length of its line (150 m).
   subroutine test_break_beyond_line(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&rupture line = 2, s_break = 150.5 /'//nl, &
                          [character(len=50) :: '&rupture: s_break = 150.5', 'must be from 0 to 150', &
                          'the length of &line_2'])
   end subroutine test_break_beyond_line

   !> s_break not given: the end b of line 2, at the free buoy.
   subroutine test_break_free_b(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&rupture line = 2, time = 0.5 /'//nl, &
                          [character(len=60) :: '&rupture: s_break = 150 (not given: the end b of &line_2)', &
                          "&point_1 of kind 'free'", 'a break at a free point', &
                          'give s_break inside the line, 0 < s_break < 150'])
   end subroutine test_break_free_b

   !> s_break = 0 on line 3 turned round: its end a at the free buoy.
   subroutine test_break_free_a(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), "end_a = 'point_4', end_b = 'point_1'", &
                                          "end_a = 'point_1', end_b = 'point_4'")//'&rupture line = 3, s_break = 0 /'//nl, &
                          [character(len=60) :: '&rupture: s_break = 0, at end a of &line_3', &
                          "&point_1 of kind 'free'", 'a break at a free point'])
   end subroutine test_break_free_a

   !> A break by tension with line, s_break and time: all three named.
   subroutine test_tension_with_line(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//"&rupture criterion = 'tension', mbl = 1e6, line = 2, s_break = 3, "// &
                          'time = 1 /'//nl, &
                          [character(len=70) :: "&rupture: criterion = 'tension', line = 2, s_break = 3, time = 1", &
                          'not used'])
   end subroutine test_tension_with_line

   !> A break by tension without &rupture mbl: the uniform line 3 has no breaking load.
   subroutine test_tension_uniform(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(replaced(spread(), '&segment_1 length = 50, nodes = 11 /', &
                                                   '&segment_1 length = 50, nodes = 11, mbl = 1e6 /'), &
                                          '&segment_2 length = 100, nodes = 21 /', &
                                          '&segment_2 length = 100, nodes = 21, mbl = 1e6 /')// &
                          "&rupture criterion = 'tension' /"//nl, &
                          [character(len=60) :: '&line_3: a uniform line', '&rupture mbl = not given', &
                          'breaking load of every line'])
   end subroutine test_tension_uniform

   !> A break by tension with every line of segments, &segment_2 without its breaking load.
   subroutine test_tension_segment(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(replaced(spread(), '&segment_1 length = 50, nodes = 11 /', &
                                                   '&segment_1 length = 50, nodes = 11, mbl = 1e6 /'), &
                                          'length = 160, nodes = 31 /', 'segments = 1, 2 /')// &
                          "&rupture criterion = 'tension' /"//nl, &
                          [character(len=60) :: '&segment_2: mbl = 0 and &rupture mbl = not given', &
                          'every segment'])
   end subroutine test_tension_segment

   !> &rupture line on the single line.
   subroutine test_line_single(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&cable length = 60 /'//nl//'&rupture line = 1, s_break = 30 /'//nl, &
                          [character(len=50) :: '&rupture: line = 1', 'only with &line groups'])
   end subroutine test_line_single

   !> A break by time 70 m along line 2 (beyond &cable length's default, 60 m): the case keeps it;
   !> line 2's case breaks there, with the &rupture variables given but line; line 1's does not.
   subroutine test_break_by_time(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, l1, l2, l3
      call write_text(path, spread()//'&rupture line = 2, s_break = 70, time = 0.5, t_break = 0.01 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, c%break_enabled .and. c%break_line == 2 .and. c%s_break == 70 .and. c%break_time == 0.5_dp &
                 .and. trim(c%break_criterion) == 'time', 'the break read')
      if (allocated(error)) return
      l2 = c%line_case(2)
      call check(error, l2%break_enabled .and. trim(l2%break_criterion) == 'time' .and. l2%s_break == 70 .and. &
                 l2%break_time == 0.5_dp .and. l2%t_break == 0.01_dp .and. l2%break_line == 0 .and. &
                 l2%length == 150, 'line 2 breaks 70 m from its end a at 0.5 s')
      if (allocated(error)) return
      call check(error, l2%is_given('rupture', 's_break') .and. l2%is_given('rupture', 'time') .and. &
                 l2%is_given('rupture', 't_break') .and. .not. l2%is_given('rupture', 'line'), &
                 "line 2's case: the &rupture variables given, but line: "//l2%given)
      if (allocated(error)) return
      l1 = c%line_case(1)
      l3 = c%line_case(3)
      call check(error, .not. l1%break_enabled .and. .not. l1%is_given('rupture', 's_break') .and. &
                 .not. l3%break_enabled, 'lines 1 and 3 do not break')
   end subroutine test_break_by_time

   !> Breaks at held ends: line 2 turned round (from the buoy to the anchor &point_3), s_break not
   !> given, at its end b (150 m); line 3 at its end a (the motion point). Each line case passes
   !> the single line's checks (its end there held). (Not line 1: the buoy's body is on its case,
   !> at an end held there, which the single line refuses.)
   subroutine test_break_held_ends(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, l
      character(:), allocatable :: turned
      turned = replaced(spread(), "&line_2 end_a = 'Point_3', end_b = 'point_1', segments = 1, 2 /", &
                        "&line_2 end_a = 'point_1', end_b = 'point_3', segments = 2, 1 /")
      call write_text(path, turned//'&rupture line = 2, time = 0.2 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, c%s_break == 150, 's_break not given: the end b of line 2, 150 m')
      if (allocated(error)) return
      l = c%line_case(2)
      call check(error, l%break_enabled .and. l%s_break == 150 .and. trim(l%end_b%kind) == 'fixed' .and. &
                 l%end_b%y == 173.2_dp .and. l%segments(1)%length == 100 .and. l%point_count == 0, &
                 "line 2's case: the break at its fixed end b")
      if (allocated(error)) return
      call validate(l, error)
      if (allocated(error)) return
      call write_text(path, spread()//'&rupture line = 3, s_break = 0 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      l = c%line_case(3)
      call check(error, l%break_enabled .and. l%s_break == 0 .and. trim(l%end_a%kind) == 'motion', &
                 "line 3's case: the break at its motion end a")
      if (allocated(error)) return
      call validate(l, error)
   end subroutine test_break_held_ends

   !> &rupture enabled = .false. with a line: read, no line breaks.
   subroutine test_break_disabled(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, l
      call write_text(path, spread()//'&rupture enabled = .false., line = 2 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      l = c%line_case(2)
      call check(error, .not. c%break_enabled .and. .not. l%break_enabled, 'no break')
   end subroutine test_break_disabled

   !> A break by tension: no line's case breaks, each keeps the MBLs (the segments' own, &rupture
   !> mbl for the uniform line 3 and as each case's mbl).
   subroutine test_break_by_tension(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, l, s1, s2
      integer :: k
      call write_text(path, replaced(replaced(spread(), '&segment_1 length = 50, nodes = 11 /', &
                                              '&segment_1 length = 50, nodes = 11, mbl = 2e6 /'), &
                                     '&segment_2 length = 100, nodes = 21 /', &
                                     '&segment_2 length = 100, nodes = 21, mbl = 1e6 /')// &
                      "&rupture criterion = 'tension', mbl = 5e5 /"//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      do k = 1, 3
         l = c%line_case(k)
         call check(error, .not. l%break_enabled .and. l%mbl == 5.0e5_dp, 'line case without a break, its mbl')
         if (allocated(error)) return
      end do
      l = c%line_case(1)
      s1 = l%segment_case(1)
      s2 = l%segment_case(2)
      call check(error, l%segments(1)%mbl == 2.0e6_dp .and. l%segments(2)%mbl == 1.0e6_dp .and. &
                 s1%mbl == 2.0e6_dp .and. s2%mbl == 1.0e6_dp, "line 1's segments keep their MBLs")
      if (allocated(error)) return
      l = c%line_case(3)
      s1 = l%segment_case(1)
      call check(error, l%segment_count == 0 .and. s1%mbl == 5.0e5_dp, 'the uniform line 3: &rupture mbl')
   end subroutine test_break_by_tension

   !> The echo of a network's break by time names its line and reads back to itself; without a
   !> break the echo names no line.
   subroutine test_break_echo(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, back
      character(:), allocatable :: text
      call write_text(path, spread()//'&rupture line = 2, s_break = 70, time = 0.5 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      text = config_text(c)
      call check(error, index(text, 's_break = 70') > 0 .and. index(text, 'line = 2 /') > 0, &
                 'the echo of the break: '//text)
      if (allocated(error)) return
      call write_text(echo_path, text)
      call read_config(echo_path, back, error)
      if (allocated(error)) return
      back%source = c%source
      back%file = c%file
      call check(error, config_text(back) == text, 'the echo read back differs: '//config_text(back))
      if (allocated(error)) return
      call write_text(path, spread())
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, index(config_text(c), 'line = ') == 0, 'a line named without a break')
   end subroutine test_break_echo

   subroutine test_body_joint(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&point_5 joint = 1, mass = 50 /'//nl, &
                          [character(len=40) :: '&point_5: joint = 1', 'split the line at a free point'])
   end subroutine test_body_joint

   subroutine test_without_lines(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, "&point_1 kind = 'fixed', x = 3 /"//nl, &
                          [character(len=40) :: "&point_1: kind = 'fixed'", 'without any &line group'])
   end subroutine test_without_lines

   subroutine test_point_joint(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), "&point_1 kind = 'free',", "&point_1 kind = 'free', joint = 1,"), &
                          [character(len=40) :: '&point_1: joint = 1', "kind = 'free', a network point"])
   end subroutine test_point_joint

   subroutine test_body_held(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), "&point_2 kind = 'fixed',", "&point_2 kind = 'fixed', mass = 5,"), &
                          [character(len=40) :: '&point_2: mass = 5', "kind = 'fixed'", 'a body there does nothing'])
   end subroutine test_body_held

   subroutine test_other_kind(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), "&point_2 kind = 'fixed',", "&point_2 kind = 'fixed', period = 3,"), &
                          [character(len=50) :: '&point_2: period = 3', "a variable of kind 'motion'", &
                          "kind = 'fixed' takes x, y, z"])
   end subroutine test_other_kind

   subroutine test_network_variable_on_body(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = 20 /'//nl//'&segment_2 length = 40 /'//nl// &
                          "&end_b kind = 'free' /"//nl//'&point_1 joint = 1, mass = 5, z = -3 /'//nl, &
                          [character(len=40) :: '&point_1: z = -3', 'without kind', 'network point'])
   end subroutine test_network_variable_on_body

   subroutine test_motion_check(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), 'period = 10', 'period = 0'), &
                          [character(len=50) :: '&point_4: period = 0', "must be > 0 for motion = 'harmonic'"])
   end subroutine test_motion_check

   !> Nodes in one of the two segments of a line: in every one or in none.
   subroutine test_nodes_some(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), '&segment_2 length = 100, nodes = 21 /', &
                                          '&segment_2 length = 100 /'), &
                          [character(len=50) :: '&line_1', 'segments = 1, 2', '&segment_2 gives no nodes'])
   end subroutine test_nodes_some

   !> Nodes shared by length: at least two cells a segment of each line.
   subroutine test_nodes_too_few(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(replaced(replaced(spread(), '&segment_1 length = 50, nodes = 11 /', &
                                                           '&segment_1 length = 50 /'), &
                                                  '&segment_2 length = 100, nodes = 21 /', '&segment_2 length = 100 /'), &
                                         '&numerics t_end = 1 /', '&numerics t_end = 1, nodes = 4 /'), &
                          [character(len=50) :: '&numerics: nodes = 4', 'the 2 segments of &line_1', &
                          'at least 2*2 + 1 = 5'])
   end subroutine test_nodes_too_few

   !> A free point's buoyancy needs water, as a body's.
   subroutine test_buoy_dry(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, replaced(spread(), '&fluid density = 1025 /', ''), &
                          [character(len=50) :: '&point_1: volume = 10', 'buoyancy needs water'])
   end subroutine test_buoy_dry

   !> A fixed point under the seabed.
   subroutine test_below_seabed(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, spread()//'&seabed depth = 90 /'//nl, &
                          [character(len=50) :: '&point_2: z = -100', 'below the seabed (z = -90'])
   end subroutine test_below_seabed

   !> Motion points moved by tables, one from a file (t, x, y, z) and one inline, with the
   !> words in capitals and a point named '&point_2': the tables read as an end's, the line cases'
   !> ends carry them, and the echo (the file's table written inline) reads back to itself.
   subroutine test_motion_tables(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, back, l2
      character(:), allocatable :: text
      call write_text(table_path, '# t x y z'//nl//'0 0 0 0'//nl//'1 0.5 0.2 0.1'//nl//'2 1 0 0'//nl)
      call write_text(path, scene//"&point_1 kind = 'FREE', z = -20, volume = 10, mass = 1000 /"//nl//anchor_2// &
                      "&point_3 kind = 'motion', x = -100, y = 173.2, z = -100, motion = 'table', table_file = '"// &
                      table_path//"' /"//nl// &
                      "&point_4 kind = 'motion', x = -100, y = -173.2, z = -100, motion = 'Table', "// &
                      'table_time = 0, 1, 2, table_x = 0, 1, 0, table_z = 0, 0.5, 0 /'//nl// &
                      "&line_1 end_a = '&point_2', end_b = 'point_1', segments = 1, 2 /"//nl//line_2//line_3)
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, c%points(1)%kind == 'free' .and. c%lines(1)%end_point(1) == 2 .and. &
                 c%point_ends(3)%table_rows == 3 .and. c%point_ends(3)%table_y(2) == 0.2_dp .and. &
                 c%point_ends(3)%table_z(2) == 0.1_dp .and. c%point_ends(4)%table_rows == 3 .and. &
                 c%point_ends(4)%motion == 'table' .and. c%point_ends(4)%table_z(2) == 0.5_dp, &
                 'the tables of points 3 (file) and 4 (inline), the words in lower case')
      if (allocated(error)) return
      l2 = c%line_case(2)
      call check(error, trim(l2%end_a%kind) == 'motion' .and. l2%end_a%table_rows == 3 .and. &
                 l2%end_a%table_x(3) == 1 .and. l2%is_given('end_a', 'table_file'), 'line 2: end a moved by the table')
      if (allocated(error)) return
      text = config_text(c)
      call write_text(echo_path, text)
      call read_config(echo_path, back, error)
      if (allocated(error)) return
      back%source = c%source
      back%file = c%file
      ! (The echo read back has the table inline, without the comment naming its file.)
      call check(error, index(text, "! &point_3: the table was read from table_file = '"//table_path//"'"//nl) == 1 + &
                 index(text, nl//'! &point_3'), 'the comment naming the table file: '//text)
      if (allocated(error)) return
      call check(error, config_text(back) == replaced(text, "! &point_3: the table was read from table_file = '"// &
                                                      table_path//"'"//nl, ''), &
                 'the echo read back differs: '//config_text(back))
   end subroutine test_motion_tables

   !> text with its first old replaced by new.
   function replaced(text, old, new) result(s)
      character(*), intent(in) :: text, old, new
      character(:), allocatable :: s
      integer :: i
      i = index(text, old)
      if (i == 0) then
         s = text//'! (not found: '//old//')'//nl
      else
         s = text(1:i - 1)//new//text(i + len(old):)
      end if
   end function replaced
end module suite_input_network
