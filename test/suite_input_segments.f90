!> Namelist input of a line of segments (&segment_1 ... &segment_8, issue 31): a valid
!> line read back (each segment's own values, the line's where it gives none, a table file,
!> the derived length and nodes), its echo read back, the groups documented once, and one
!> test per refusal, each checking that the one-line message names the file, the group,
!> the variable, its value and what is allowed. Part of the suite input.
module suite_input_segments
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: fatal_error, stat_input
   use xcable_io_input, only: case_config, read_config, config_text, value_text
   use xcable_io_schema, only: schema_entry, schema_table, schema_text
   use xcable_scene_scene, only: scene_type, scene_from_config
   use xcable_fixtures, only: write_text
   implicit none
   private
   public :: collect_input_segments

   character(len=*), parameter :: path = 'build/test_input_segments.nml'
   character(len=*), parameter :: echo_path = 'build/test_input_segments_echo.nml'
   character(len=*), parameter :: table_path = 'build/test_input_segments_law.dat'
   character(len=*), parameter :: nl = new_line('a')

   !> Two segments of 20 and 40 m on the default line (60 m, not given).
   character(len=*), parameter :: two = '&segment_1 length = 20 /'//nl//'&segment_2 length = 40 /'//nl

contains

   !> The tests of the segments' input.
   subroutine collect_input_segments(tests)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('segments_read', test_read), &
               new_unittest('segments_echo_round_trip', test_echo), &
               new_unittest('segments_documented_once', test_documented_once), &
               new_unittest('segment_numbering_gap', test_gap), &
               new_unittest('segment_without_length', test_length_missing), &
               new_unittest('segment_length_out_of_range', test_length_range), &
               new_unittest('segment_lengths_not_the_line', test_length_sum), &
               new_unittest('segment_nodes_in_some', test_nodes_some), &
               new_unittest('segment_nodes_against_numerics', test_nodes_differ), &
               new_unittest('segment_nodes_too_few', test_nodes_too_few), &
               new_unittest('segment_unknown_words', test_words), &
               new_unittest('segment_table_law', test_table), &
               new_unittest('segment_ranges', test_ranges), &
               new_unittest('segment_box_scheme', test_box), &
               new_unittest('segment_mbl', test_mbl), &
               new_unittest('segment_unknown_names', test_unknown)]
   end subroutine collect_input_segments

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

   !> Chain, polyester and chain in water: the first and last a linear law and a diameter and
   !> density of their own, the middle a table law from a file with the line's density; nodes
   !> in every segment.
   function chain_rope_chain() result(text)
      character(:), allocatable :: text
      call write_text(table_path, '# strain tension'//nl//'0 0'//nl//'0.02 1.5e5'//nl//'0.1 9e5 # knee'//nl)
      text = '&cable diameter = 0.05, density = 1140 /'//nl// &
             '&fluid density = 1025, cd_normal = 1.2 /'//nl// &
             "&segment_1 length = 20, diameter = 0.1, density = 7850, law = 'linear', ea = 5e8, nodes = 11 /"//nl// &
             "&segment_2 length = 30, diameter = 0.04, law = 'table', table_file = '"//table_path// &
             "', damping = 50, nodes = 21 /"//nl// &
             '&segment_3 length = 10, diameter = 0.08, p(2) = 12.5, cd_normal = 2.4, nodes = 6, mbl = 2e6 /'//nl// &
             "&rupture criterion = 'tension', mbl = 1e6 /"//nl
   end function chain_rope_chain

   !> The valid line read back: the count, each segment's own values and the line's where it
   !> gives none (segment_case), the table read from its file, an element of p, &cable length
   !> the sum of the lengths and &numerics nodes the sum of the nodes less the joints; a
   !> segment of another diameter derives its own area (its section's mass per length).
   subroutine test_read(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      type(case_config) :: c, s1, s2, s3
      type(scene_type) :: scene
      call write_text(path, chain_rope_chain())
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, c%segment_count == 3 .and. c%segments_of_line() == 3, 'segment_count')
      if (allocated(error)) return
      call check_close(error, c%length, 60.0_dp, '&cable length: the sum of the lengths', rel_tol=0.0_dp)
      if (allocated(error)) return
      call check(error, c%nodes == 11 + 21 + 6 - 2, '&numerics nodes: the sum less the joints, not '// &
                 value_text(c, schema_table_entry('numerics', 'nodes')))
      if (allocated(error)) return
      s1 = c%segment_case(1)
      s2 = c%segment_case(2)
      s3 = c%segment_case(3)
      call check(error, s2%law == 'table' .and. s2%diameter == 0.04_dp .and. s2%density == 1140 .and. &
                 s2%length == 30 .and. s2%damping == 50 .and. s2%cd_normal == 1.2_dp, &
                 'segment 2: its own law, diameter, length and damping, &cable density and &fluid cd_normal')
      if (allocated(error)) return
      call check(error, s2%material_table_rows == 3 .and. &
                 all(s2%material_table_strain(1:3) == [0.0_dp, 0.02_dp, 0.1_dp]) .and. &
                 all(s2%material_table_tension(1:3) == [0.0_dp, 1.5e5_dp, 9.0e5_dp]), &
                 'segment 2: the rows of its table_file')
      if (allocated(error)) return
      call check(error, s1%law == 'linear' .and. s1%ea == 5.0e8_dp .and. s1%density == 7850 .and. &
                 s1%damping == 0 .and. s1%mbl == 1.0e6_dp, 'segment 1: its law, EA and density; the line''s '// &
                 'damping and &rupture mbl')
      if (allocated(error)) return
      call check(error, s3%law == 'tanh' .and. s3%p(2) == 12.5_dp .and. s3%p(1) == c%p(1) .and. &
                 s3%p(5) == c%p(5) .and. s3%cd_normal == 2.4_dp .and. s3%mbl == 2.0e6_dp, &
                 'segment 3: p(2) its own, the other coefficients &material''s; its cd_normal and mbl')
      if (allocated(error)) return
      call check(error, c%is_given('segment_2', 'law') .and. .not. c%is_given('segment_2', 'density'), &
                 'given: "'//c%given//'"')
      if (allocated(error)) return
      ! &cable area is derived from &cable diameter; the segments of their own diameters derive their own.
      call check(error, s1%area == 0 .and. s3%area == 0 .and. s1%bending_stiffness == 0 .and. &
                 c%area > 0, 'a segment of its own diameter takes the line''s derived area or EI')
      if (allocated(error)) return
      call scene_from_config(c, scene, error)
      if (allocated(error)) return
      call check_close(error, scene%sections(1)%mass, 7850*pi/4*0.1_dp**2, 'section 1: mass per length', &
                       rel_tol=1.0e-14_dp)
      if (allocated(error)) return
      call check_close(error, scene%sections(2)%mass, 1140*pi/4*0.04_dp**2, 'section 2: mass per length', &
                       rel_tol=1.0e-14_dp)
   end subroutine test_read

   !> The echo of the line (config_text) reads back to the same case: every variable, each
   !> segment as it sees the case, and the same echo; a case without segments echoes none.
   subroutine test_echo(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: first, second, a, b
      type(schema_entry), allocatable :: t(:)
      character(:), allocatable :: text
      integer :: i, k
      call write_text(path, chain_rope_chain())
      call read_config(path, first, error)
      if (allocated(error)) return
      text = config_text(first)
      call check(error, index(text, "&segment_2 length = 30, diameter = 0.04, law = 'table', table_strain = 0, "// &
                 '0.02, 0.1,') > 0 .and. index(text, "! &segment_2: the table was read from table_file = '"// &
                 table_path//"'") > 0 .and. index(text, '&segment_3 length = 10, diameter = 0.08, p = 270300, '// &
                 '12.5,') > 0 .and. index(text, '&segment_4') == 0, 'the echo of the segments reads'//nl//text)
      if (allocated(error)) return
      call write_text(echo_path, text)
      call read_config(echo_path, second, error)
      if (allocated(error)) then
         error%message = 'the echo is refused: '//error%message//nl//text
         return
      end if
      t = schema_table()
      do i = 1, size(t)
         if (t(i)%name == 'table_file') cycle
         call check(error, value_text(first, t(i)) == value_text(second, t(i)), '&'//trim(t(i)%group)//' '// &
                    trim(t(i)%name)//' read "'//value_text(first, t(i))//'", echoed and read back "'// &
                    value_text(second, t(i))//'"')
         if (allocated(error)) return
      end do
      do k = 1, 3
         a = first%segment_case(k)
         b = second%segment_case(k)
         call check(error, a%law == b%law .and. a%diameter == b%diameter .and. a%density == b%density .and. &
                    a%area == b%area .and. a%bending_stiffness == b%bending_stiffness .and. a%ea == b%ea .and. &
                    all(a%p == b%p) .and. a%material_table_rows == b%material_table_rows .and. &
                    a%cd_normal == b%cd_normal .and. a%mbl == b%mbl .and. a%length == b%length, &
                    'segment '//achar(48 + k)//' sees another case after the echo')
         if (allocated(error)) return
      end do
      ! The echo of the echo: the same, but for the comment on the table file (its rows are inline).
      i = index(text, "! &segment_2: the table was read")
      k = index(text(i:), nl)
      call check(error, config_text(second) == text(1:i - 1)//text(i + k:), 'the echo of the echo differs:'//nl// &
                 config_text(second))
      if (allocated(error)) return
      call write_text(path, '&static tension = 2e5 /'//nl)
      call read_config(path, first, error)
      if (allocated(error)) return
      call check(error, index(config_text(first), '&segment') == 0, 'a case without segments echoes them:'//nl// &
                 config_text(first))
   end subroutine test_echo

   !> docs/user/namelist.md describes &segment_1 ... &segment_8 once (21 rows), while the
   !> table knows every group (the sweeps' tsv names each).
   subroutine test_documented_once(error)
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: md, tsv
      md = schema_text('markdown')
      tsv = schema_text('tsv')
      call check(error, index(md, '| `&segment_1` ... `&segment_8` | `length` |') > 0 .and. &
                 index(md, '`&segment_2`') == 0 .and. index(md, '| `mbl` | real | N | `0` (&rupture mbl)') > 0, &
                 'the markdown table does not give &segment_1 ... &segment_8 one set of rows')
      if (allocated(error)) return
      call check(error, index(tsv, 'segment_8'//achar(9)//'mbl') > 0 .and. &
                 index(tsv, 'segment_5'//achar(9)//'table_strain'//achar(9)//'real'//achar(9)//'1000') > 0, &
                 'the tsv table does not name every segment''s variables')
   end subroutine test_documented_once

   subroutine test_gap(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = 20 /'//nl//'&segment_3 length = 40 /'//nl, &
                          [character(40) :: path, '&segment_3 given without &segment_2', 'without a gap'])
   end subroutine test_gap

   subroutine test_length_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = 20 /'//nl//'&segment_2 diameter = 0.1 /'//nl, &
                          [character(40) :: path, '&segment_2', 'length not given', '[0.01, 100000]'])
   end subroutine test_length_missing

   subroutine test_length_range(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = -20 /'//nl//'&segment_2 length = 80 /'//nl, &
                          [character(40) :: path, '&segment_1', 'length = -20', 'in [0.01, 100000]'])
      if (allocated(error)) return
      ! Before the sum is checked against &cable length.
      call expect_refusal(error, '&cable length = 60 /'//nl//'&segment_1 length = 0 /'//nl// &
                          '&segment_2 length = 80 /'//nl, &
                          [character(40) :: path, '&segment_1', 'length = 0', 'in [0.01, 100000]'])
   end subroutine test_length_range

   !> Given, &cable length must be the sum of the lengths (to 1e-9 of it); not given, it is.
   subroutine test_length_sum(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      call expect_refusal(error, '&cable length = 60 /'//nl//'&segment_1 length = 20 /'//nl// &
                          '&segment_2 length = 30 /'//nl, &
                          [character(60) :: path, '&cable', 'length = 60', '&segment_1, &segment_2', &
                           '20 + 30 = 50', 'must be their sum'])
      if (allocated(error)) return
      call write_text(path, '&cable length = 60.00000000001 /'//nl//two)
      call read_config(path, c, error)
      if (allocated(error)) return
      ! Not given, it is their sum before the checks that take it (s_break at most L).
      call write_text(path, '&segment_1 length = 50 /'//nl//'&segment_2 length = 150 /'//nl// &
                      '&rupture s_break = 120 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      call check(error, c%length == 200 .and. c%s_break == 120, '&cable length is not the sum of the segments''')
   end subroutine test_length_sum

   subroutine test_nodes_some(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = 20, nodes = 11 /'//nl//'&segment_2 length = 40 /'//nl, &
                          [character(40) :: path, '&segment_2', 'nodes not given', '1 of the 2', 'every segment'])
   end subroutine test_nodes_some

   subroutine test_nodes_differ(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = 20, nodes = 11 /'//nl//'&segment_2 length = 40, nodes = 21 /'// &
                          nl//'&numerics nodes = 121 /'//nl, &
                          [character(40) :: path, '&numerics', 'nodes = 121', '11 + 21 - 1 joints = 31', &
                           'give nodes = 31'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, nodes = 2 /'//nl, &
                          [character(40) :: path, '&segment_1', 'nodes = 2 - 0 joints = 2', 'from 3 to 100001'])
   end subroutine test_nodes_differ

   !> Shared by length, every segment needs two cells: 2 n + 1 nodes at least.
   subroutine test_nodes_too_few(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      call expect_refusal(error, two//'&segment_3 length = 10 /'//nl//'&numerics nodes = 6 /'//nl, &
                          [character(40) :: path, '&numerics', 'nodes = 6', '3 segments', 'at least 2*3 + 1 = 7'])
      if (allocated(error)) return
      call write_text(path, two//'&segment_3 length = 10 /'//nl//'&numerics nodes = 7 /'//nl)
      call read_config(path, c, error)
   end subroutine test_nodes_too_few

   subroutine test_words(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, "&segment_1 length = 20, law = 'cubic' /"//nl//'&segment_2 length = 40 /'//nl, &
                          [character(40) :: path, '&segment_1', "law = 'cubic'", "'tanh', 'linear', 'table'"])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20 /'//nl//"&segment_2 length = 40, compression = 'push' /"//nl, &
                          [character(40) :: path, '&segment_2', "compression = 'push'", "'law', 'none'"])
   end subroutine test_words

   !> A segment's table law as &material's: rows increasing, read from its table_file, not
   !> for another law, not missing; a law of its own other than 'table' leaves the line's
   !> table to the line.
   subroutine test_table(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c, seen
      call expect_refusal(error, "&segment_1 length = 20, law = 'table', table_strain = 0, 0.1, 0.05, "// &
                          'table_tension = 0, 1e4, 2e4 /'//nl//'&segment_2 length = 40 /'//nl, &
                          [character(60) :: path, '&segment_1', 'table_strain(3) = 0.05', 'increase strictly'])
      if (allocated(error)) return
      call expect_refusal(error, "&segment_1 length = 20, law = 'table', table_file = 'build/no_such_law.dat' /"// &
                          nl//'&segment_2 length = 40 /'//nl, &
                          [character(60) :: path, '&segment_1', "table_file = 'build/no_such_law.dat'", &
                           'no such file'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20 /'//nl//"&segment_2 length = 40, table_strain = 0, 0.1, "// &
                          'table_tension = 0, 1e4 /'//nl, &
                          [character(60) :: path, '&segment_2', 'table_strain = 0, 0.1', &
                           "rows of the table law given for law = 'tanh'"])
      if (allocated(error)) return
      call expect_refusal(error, "&segment_1 length = 20, law = 'table' /"//nl//'&segment_2 length = 40 /'//nl, &
                          [character(60) :: path, '&segment_1', "law = 'table' without a table"])
      if (allocated(error)) return
      call write_text(path, "&material law = 'table', table_strain = 0, 0.1, table_tension = 0, 1e4 /"//nl// &
                      "&segment_1 length = 20, law = 'linear', ea = 1e6 /"//nl//'&segment_2 length = 40 /'//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      seen = c%segment_case(2)
      call check(error, seen%law == 'table' .and. seen%material_table_rows == 2, &
                 'segment 2 takes the line''s table law')
   end subroutine test_table

   !> Each variable's range as its twin's (with its note), and the checks of &material's
   !> values on the case as the segment sees it.
   subroutine test_ranges(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 length = 20 /'//nl//'&segment_2 length = 40, diameter = 50 /'//nl, &
                          [character(40) :: path, '&segment_2', 'diameter = 50', 'in [0.0001, 1]', 'in metres'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, p(1) = -5 /'//nl//'&segment_2 length = 40 /'//nl, &
                          [character(40) :: path, '&segment_1', 'p(1) = -5', '> 0 and <= 1e12 for the tanh law'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, nodes = 1 /'//nl//'&segment_2 length = 40, nodes = 5 /'//nl, &
                          [character(40) :: path, '&segment_1', 'nodes = 1', 'an integer from 2 to 100001'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, young = 1e3, diameter = 1e-3 /'//nl// &
                          '&segment_2 length = 40 /'//nl, &
                          [character(40) :: path, '&segment_1', 'young = 1000, diameter = 0.001', &
                           'set bending_stiffness'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, cd_normal = 1.2 /'//nl//'&segment_2 length = 40 /'//nl, &
                          [character(40) :: path, '&segment_1', 'cd_normal = 1.2', 'without a fluid'])
   end subroutine test_ranges

   subroutine test_box(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, two//"&numerics scheme = 'box' /"//nl, &
                          [character(40) :: path, '&numerics', "scheme = 'box'", '&segment_1, &segment_2', &
                           'one uniform cable', "scheme = 'rod'"])
   end subroutine test_box

   !> A segment's MBL is for a break by tension; that break needs one for every segment.
   subroutine test_mbl(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      call expect_refusal(error, '&segment_1 length = 20, mbl = 1e6 /'//nl//'&segment_2 length = 40 /'//nl, &
                          [character(60) :: path, '&segment_1', 'mbl = 1e6', "criterion = 'tension'", &
                           'does not break'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, mbl = 1e6 /'//nl//'&segment_2 length = 40 /'//nl// &
                          '&rupture s_break = 30 /'//nl, &
                          [character(60) :: path, '&segment_1', 'mbl = 1e6', "here criterion = 'time'"])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, mbl = 1e6 /'//nl//'&segment_2 length = 40 /'//nl// &
                          "&rupture criterion = 'tension' /"//nl, &
                          [character(60) :: path, '&segment_2', 'mbl = 0 and &rupture mbl = not given', &
                           'every segment'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, mbl = -1 /'//nl//'&segment_2 length = 40 /'//nl// &
                          "&rupture criterion = 'tension', mbl = 1e6 /"//nl, &
                          [character(60) :: path, '&segment_1', 'mbl = -1', '0 (&rupture mbl) or > 0'])
      if (allocated(error)) return
      call write_text(path, '&segment_1 length = 20, mbl = 1e6 /'//nl//'&segment_2 length = 40, mbl = 2e6 /'//nl// &
                      "&rupture criterion = 'tension' /"//nl)
      call read_config(path, c, error)
   end subroutine test_mbl

   !> Unknown variables of a segment, and a segment beyond the eighth.
   subroutine test_unknown(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_refusal(error, '&segment_1 lenght = 20 /'//nl, &
                          [character(60) :: path, '&segment_1', 'unknown variable "lenght"', 'length, diameter'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_1 length = 20, gravity = 1 /'//nl, &
                          [character(60) :: path, '&segment_1', 'unknown variable "gravity"'])
      if (allocated(error)) return
      call expect_refusal(error, '&segment_9 length = 20 /'//nl, &
                          [character(60) :: path, 'unknown group &segment_9', '&segment_1 ... &segment_8'])
   end subroutine test_unknown

   !> The schema entry of group%name.
   function schema_table_entry(group, name) result(e)
      character(*), intent(in) :: group, name
      type(schema_entry) :: e
      type(schema_entry), allocatable :: t(:)
      integer :: i
      t = schema_table()
      do i = 1, size(t)
         if (t(i)%group == group .and. t(i)%name == name) e = t(i)
      end do
   end function schema_table_entry
end module suite_input_segments
