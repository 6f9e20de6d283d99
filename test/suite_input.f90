!> Namelist input: the paper's cases read back, the schema against the reader
!> (every variable read, echoed and read back; the defaults; the README
!> table), and one test per class of bad input, each checking that the
!> message names the file, the group, the variable and what is allowed.
module suite_input
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: fatal_error, stat_input
   use xcable_io_input, only: case_config, read_config, read_values, config_text, value_text
   use xcable_io_schema, only: schema_entry, schema_table, schema_text, is_table
   use xcable_core_strings, only: real_text, to_lower, str
   use xcable_box_case, only: setup_case
   use xcable_box_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options
   use xcable_fixtures, only: write_text
   use suite_input_segments, only: collect_input_segments
   implicit none
   private
   public :: collect_input

   character(len=*), parameter :: path = 'build/test_input.nml'
   character(len=*), parameter :: nl = new_line('a')
   character(len=*), parameter :: table_path = 'build/test_input_table.dat'
   character(len=*), parameter :: material_path = 'build/test_input_material.dat'

contains

   subroutine collect_input(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      type(unittest_type), allocatable :: segment_tests(:)
      tests = [new_unittest('paper_cases', test_paper_cases), &
               new_unittest('defaults_without_groups', test_defaults), &
               new_unittest('misspelled_variable', test_misspelled), &
               new_unittest('wrong_type', test_wrong_type), &
               new_unittest('missing_slash', test_missing_slash), &
               new_unittest('missing_file', test_missing_file), &
               new_unittest('negative_length', test_negative_length), &
               new_unittest('too_few_nodes', test_nodes), &
               new_unittest('tension_not_positive', test_tension_zero), &
               new_unittest('tension_beyond_law', test_tension_range), &
               new_unittest('unknown_group', test_unknown_group), &
               new_unittest('no_group', test_no_group), &
               new_unittest('duplicated_group', test_duplicate), &
               new_unittest('nan_value', test_nan), &
               new_unittest('unknown_field', test_unknown_field), &
               new_unittest('unknown_law', test_unknown_law), &
               new_unittest('readme_table', test_readme_table), &
               new_unittest('schema_defaults', test_schema_defaults), &
               new_unittest('schema_round_trip', test_schema_round_trip), &
               new_unittest('echo_round_trip', test_echo_round_trip), &
               new_unittest('echo_text', test_echo_text), &
               new_unittest('given_variables', test_given), &
               new_unittest('s_break_default', test_s_break_default), &
               new_unittest('direction_normalised', test_direction_normalised), &
               new_unittest('table_file_read', test_table_file_read), &
               new_unittest('tension_and_end_position', test_tension_and_position), &
               new_unittest('s_break_outside_cable', test_s_break_outside), &
               new_unittest('mass_end_without_mass', test_mass_not_positive), &
               new_unittest('unknown_end_kind', test_unknown_kind), &
               new_unittest('unknown_words', test_unknown_words), &
               new_unittest('two_free_ends', test_two_free_ends), &
               new_unittest('nothing_holds_cable', test_nothing_holds), &
               new_unittest('position_of_loose_end', test_position_of_loose_end), &
               new_unittest('spring_values', test_spring_values), &
               new_unittest('variable_of_another_kind', test_variable_of_another_kind), &
               new_unittest('unknown_kind_lists_registry', test_unknown_kind_lists_registry), &
               new_unittest('ramp_without_time', test_ramp_without_time), &
               new_unittest('harmonic_period', test_harmonic_period), &
               new_unittest('harmonic_direction', test_harmonic_direction), &
               new_unittest('table_missing', test_table_missing), &
               new_unittest('table_too_short', test_table_too_short), &
               new_unittest('table_not_increasing', test_table_not_increasing), &
               new_unittest('table_columns_unequal', test_table_columns), &
               new_unittest('table_inline_and_file', test_table_inline_and_file), &
               new_unittest('table_file_missing', test_table_file_missing), &
               new_unittest('table_file_malformed', test_table_file_malformed), &
               new_unittest('rupture_at_loose_end', test_rupture_at_loose_end), &
               new_unittest('rupture_by_tension', test_rupture_by_tension), &
               new_unittest('material_table_read', test_material_table_read), &
               new_unittest('material_table_missing', test_material_table_missing), &
               new_unittest('material_table_too_short', test_material_table_too_short), &
               new_unittest('material_table_not_finite', test_material_table_not_finite), &
               new_unittest('material_strain_not_increasing', test_material_strain_order), &
               new_unittest('material_tension_not_increasing', test_material_tension_order), &
               new_unittest('material_table_columns_unequal', test_material_table_columns), &
               new_unittest('material_table_without_table_law', test_material_table_other_law), &
               new_unittest('material_table_inline_and_file', test_material_table_inline_and_file), &
               new_unittest('material_table_file_missing', test_material_table_file_missing), &
               new_unittest('material_table_file_malformed', test_material_table_file_malformed), &
               new_unittest('damping_out_of_range', test_damping), &
               new_unittest('real_text_shortest_round_trip', test_real_text)]
      ! The segments' input (&segment_1 ... &segment_8).
      call collect_input_segments(segment_tests)
      tests = [tests, segment_tests]
   end subroutine collect_input

   !> real_text (the namelist echo's numbers): the text reads back to exactly x, and with one
   !> significant digit fewer (x written by es editing to that many digits) it does not; plain
   !> for 1e-4 <= |x| < 1e6, with an exponent otherwise. On 20 000 values: decimals of 1 to
   !> 17 significant digits from 1e-12 to 1e12 of both signs, and random doubles.
   subroutine test_real_text(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=40) :: buf, fmt
      character(:), allocatable :: t, mant
      real(dp) :: x, y, u(3)
      integer :: i, nd, ios, e_at, n, nbad
      nbad = 0
      do i = 1, 20000
         call random_number(u)
         if (mod(i, 2) == 0) then
            ! A decimal of nd digits.
            nd = 1 + int(17*u(1))
            write (fmt, '(a,i0,a)') '(es40.', nd - 1, 'e4)'
            write (buf, fmt) (2*u(2) - 1)*10.0_dp**int(24*u(3) - 12)
            read (buf, *) x
         else
            x = (2*u(2) - 1)*10.0_dp**(24*u(3) - 12)
         end if
         if (x == 0) cycle
         t = real_text(x)
         read (t, *, iostat=ios) y
         if (ios /= 0 .or. y /= x) then
            nbad = nbad + 1
            cycle
         end if
         ! The significant digits of t.
         e_at = scan(t, 'e')
         mant = t
         if (e_at > 0) mant = t(1:e_at - 1)
         if ((abs(x) >= 1.0e-4_dp .and. abs(x) < 1.0e6_dp) .neqv. e_at == 0) nbad = nbad + 1
         mant = strip(mant)
         n = len(mant)
         if (n >= 2) then
            write (fmt, '(a,i0,a)') '(es40.', n - 2, 'e4)'
            write (buf, fmt) x
            read (buf, *) y
            if (y == x) nbad = nbad + 1
         end if
      end do
      call check(error, nbad == 0, str(nbad)//' of 20000 numbers not the shortest text that reads back')
   contains
      !> The digits of a mantissa without sign, point, and leading and trailing zeros.
      function strip(m) result(d)
         character(*), intent(in) :: m
         character(:), allocatable :: d
         integer :: k
         d = ''
         do k = 1, len(m)
            if (index('0123456789', m(k:k)) > 0) d = d//m(k:k)
         end do
         do while (len(d) > 1)
            if (d(1:1) /= '0') exit
            d = d(2:)
         end do
         do while (len(d) > 1)
            if (d(len(d):len(d)) /= '0') exit
            d = d(1:len(d) - 1)
         end do
      end function strip
   end subroutine test_real_text

   !> Read text as a case (validation and the law-dependent checks) and expect
   !> an input error whose message contains every one of the words.
   subroutine expect_error(error, text, words)
      type(error_type), allocatable, intent(out) :: error
      character(*), intent(in) :: text
      character(len=*), intent(in) :: words(:)
      type(case_config) :: config
      type(error_type), allocatable :: err
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      integer :: i
      if (len(text) > 0) call write_text(path, text)
      call read_config(path, config, err)
      if (.not. allocated(err)) call setup_case(config, model, s, newton, dyn, err)
      if (.not. allocated(err)) then
         call fatal_error(error, 'accepted: '//text)
         return
      end if
      call check(error, err%stat == stat_input, 'not classed as bad input: '//err%message)
      if (allocated(error)) return
      call check(error, index(err%message, new_line('a')) == 0, 'message is not one line: '//err%message)
      if (allocated(error)) return
      do i = 1, size(words)
         call check(error, index(err%message, trim(words(i))) > 0, 'message lacks "'//trim(words(i))//'": '//err%message)
         if (allocated(error)) return
      end do
   end subroutine expect_error

   subroutine test_paper_cases(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      character(len=10), parameter :: cases(4) = ['fast_180kN', 'fast_315kN', 'slow_180kN', 'slow_315kN']
      real(dp), parameter :: tension(4) = [180.0e3_dp, 315.0e3_dp, 180.0e3_dp, 315.0e3_dp]
      real(dp), parameter :: t_break(4) = [0.005_dp, 0.005_dp, 0.05_dp, 0.05_dp]
      real(dp), parameter :: t_end(4) = [0.14_dp, 0.13_dp, 0.17_dp, 0.16_dp]
      integer :: i
      do i = 1, 4
         call read_config('input/'//trim(cases(i))//'.nml', config, error)
         if (allocated(error)) return
         call check_close(error, config%tension, tension(i), cases(i)//' tension', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, config%t_break, t_break(i), cases(i)//' t_break', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, config%t_end, t_end(i), cases(i)//' t_end', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, config%interval, 0.01_dp, cases(i)//' interval', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check(error, trim(config%file) == 'results/'//trim(cases(i))//'.h5', cases(i)//' output file')
         if (allocated(error)) return
      end do
   end subroutine test_paper_cases

   !> Groups left out take the paper's values; area and EI follow from d and E.
   subroutine test_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, '&static tension = 180000 /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check_close(error, config%area, 1.9635e-3_dp, 'area from the diameter', rel_tol=1.0e-4_dp)
      if (allocated(error)) return
      call check_close(error, config%bending_stiffness, 70.56_dp, 'EI from E and d', rel_tol=1.0e-3_dp)
      if (allocated(error)) return
      call check_close(error, config%length, 60.0_dp, 'length', rel_tol=1.0e-12_dp)
      if (allocated(error)) return
      call check(error, trim(config%file) == 'results/test_input.h5', 'default output file: '//trim(config%file))
   end subroutine test_defaults

   subroutine test_misspelled(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&numerics nodez = 11 /'//nl, [character(24) :: path, '&numerics', 'nodez', 'allowed'])
   end subroutine test_misspelled

   subroutine test_wrong_type(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&numerics nodes = 12.5 /'//nl, [character(24) :: path, '&numerics', 'nodes', '12.5', &
                                                                 'integer'])
   end subroutine test_wrong_type

   subroutine test_missing_slash(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 1.8e5'//nl//'&rupture t_break = 0.005 /'//nl, &
                        [character(24) :: path, '&static', '/'])
   end subroutine test_missing_slash

   subroutine test_missing_file(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      type(error_type), allocatable :: err
      call read_config('build/no_such_file.nml', config, err)
      call check(error, allocated(err), 'missing file accepted')
      if (allocated(error)) return
      call check(error, index(err%message, 'build/no_such_file.nml') > 0 .and. err%stat == stat_input, &
                 'message does not name the file: '//err%message)
   end subroutine test_missing_file

   subroutine test_negative_length(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&cable length = -60 /'//nl, [character(24) :: path, '&cable', 'length = -60', 'in [0.01'])
   end subroutine test_negative_length

   subroutine test_nodes(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&numerics nodes = 2 /'//nl, [character(24) :: path, '&numerics', 'nodes = 2', 'from 3'])
   end subroutine test_nodes

   subroutine test_tension_zero(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 0 /'//nl, [character(24) :: path, '&static', 'tension', '> 0'])
   end subroutine test_tension_zero

   !> 600 kN needs a strain beyond the tanh law's documented range.
   subroutine test_tension_range(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 600000 /'//nl, [character(24) :: path, '&static', 'tension', &
                                                                   'strain_max'])
   end subroutine test_tension_range

   subroutine test_unknown_group(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 1.8e5 /'//nl//'&solver tol = 1 /'//nl, &
                        [character(24) :: path, '&solver', 'allowed'])
   end subroutine test_unknown_group

   subroutine test_no_group(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '! only a comment'//nl//nl, [character(24) :: path, 'no namelist group'])
   end subroutine test_no_group

   subroutine test_duplicate(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 1.8e5 /'//nl//'&static tension = 2e5 /'//nl, &
                        [character(24) :: path, '&static', 'twice'])
   end subroutine test_duplicate

   subroutine test_nan(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&rupture t_break = NaN /'//nl, [character(24) :: path, '&rupture', 't_break', 'finite'])
   end subroutine test_nan

   subroutine test_unknown_field(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&output fields = 'tension speed' /"//nl, [character(24) :: path, '&output', 'fields', &
                                                                           'speed', 'allowed'])
   end subroutine test_unknown_field

   subroutine test_unknown_law(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'cubic' /"//nl, [character(24) :: path, '&material', 'cubic', 'tanh'])
   end subroutine test_unknown_law
   !> The input table of docs/user/namelist.md is the schema's (make schema rewrites it).
   subroutine test_readme_table(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: readme = 'docs/user/namelist.md'
      character(len=*), parameter :: begin = '<!-- schema:begin -->', finish = '<!-- schema:end -->'
      character(:), allocatable :: table, expected
      character(len=4096) :: line
      integer :: unit, ios, lineno, at, first
      logical :: inside, ended
      open (newunit=unit, file=readme, status='old', action='read', iostat=ios)
      call check(error, ios == 0, readme//' not found in the working directory (fpm test runs in the project root)')
      if (allocated(error)) return
      table = ''
      inside = .false.
      ended = .false.
      lineno = 0
      first = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         lineno = lineno + 1
         if (trim(line) == finish .and. inside) then
            ended = .true.
            exit
         end if
         if (inside) table = table//trim(line)//nl
         if (trim(line) == begin) then
            inside = .true.
            first = lineno + 1
         end if
      end do
      close (unit)
      call check(error, ended, readme//' lacks the markers '//begin//' and '//finish//' around the input table')
      if (allocated(error)) return
      expected = schema_text('markdown')
      if (table == expected) return
      ! Name the first line that differs.
      at = 1
      do while (at <= min(len(table), len(expected)))
         if (table(at:at) /= expected(at:at)) exit
         at = at + 1
      end do
      call fatal_error(error, readme//' line '//str_count(table(1:at - 1), nl, first)//': the input table differs '// &
                       'from xcable --schema markdown (src/xcable/io/schema.f90); run make schema')
   end subroutine test_readme_table

   !> Line number in a file of the end of a text that starts on line first.
   function str_count(text, newline, first) result(s)
      character(*), intent(in) :: text, newline
      integer, intent(in) :: first
      character(:), allocatable :: s
      character(len=12) :: buf
      integer :: i, n
      n = first
      do i = 1, len(text)
         if (text(i:i) == newline) n = n + 1
      end do
      write (buf, '(i0)') n
      s = trim(buf)
   end function str_count

   !> The schema's defaults are those of case_config (io/config.f90).
   subroutine test_schema_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(schema_entry), allocatable :: t(:)
      type(case_config) :: config
      integer :: i
      t = schema_table()
      do i = 1, size(t)
         call check(error, value_text(config, t(i)) == trim(t(i)%default), '&'//trim(t(i)%group)//' '// &
                    trim(t(i)%name)//': schema default "'//trim(t(i)%default)//'", case_config default "'// &
                    value_text(config, t(i))//'"')
         if (allocated(error)) return
      end do
   end subroutine test_schema_defaults

   !> Every variable of the schema, given a value of its own in a namelist,
   !> is read (the namelist reads know it) into its own component (access
   !> maps it there): the schema and the two compile-time lists agree.
   subroutine test_schema_round_trip(error)
      type(error_type), allocatable, intent(out) :: error
      type(schema_entry), allocatable :: t(:)
      type(case_config) :: config
      character(len=16) :: group
      character(:), allocatable :: text, expected(:), value
      integer :: i
      t = schema_table()
      allocate (character(len=200) :: expected(size(t)))
      text = ''
      group = ''
      do i = 1, size(t)
         if (t(i)%group /= group) then
            if (len(text) > 0) text = text//' /'//nl
            group = t(i)%group
            text = text//'&'//trim(group)
         end if
         call own_value(t(i), i, value, expected(i))
         text = text//nl//'   '//trim(t(i)%name)//' = '//value
      end do
      text = text//' /'//nl
      call write_text(path, text)
      call read_values(path, config, error)
      if (allocated(error)) return
      do i = 1, size(t)
         call check(error, value_text(config, t(i)) == trim(expected(i)), '&'//trim(t(i)%group)//' '// &
                    trim(t(i)%name)//': wrote '//trim(expected(i))//', read back "'//value_text(config, t(i))//'"')
         if (allocated(error)) return
      end do
   end subroutine test_schema_round_trip

   !> A value of entry i unlike any default and any other entry's: as written
   !> in the namelist, and as value_text should give it back.
   subroutine own_value(e, i, written, expected)
      type(schema_entry), intent(in) :: e
      integer, intent(in) :: i
      character(:), allocatable, intent(out) :: written
      character(*), intent(out) :: expected
      character(len=16) :: buf
      integer :: k, n
      select case (e%type)
      case ('real')
         n = e%count
         if (is_table(e)) n = 3
         written = ''
         do k = 1, n
            if (k > 1) written = written//', '
            written = written//real_text(1000.0_dp*i + k + 0.25_dp)
         end do
         expected = written
      case ('integer')
         write (buf, '(i0)') 1000 + i
         written = trim(buf)
         expected = written
      case ('logical')
         written = merge('.false.', '.true. ', e%default == '.true.')
         written = trim(written)
         expected = written
      case default
         if (len_trim(e%choices) > 0 .and. e%word_list) then
            written = "'Z, U'"
            expected = "'z, u'"
         else if (len_trim(e%choices) > 0) then
            ! The last allowed word (not the default, which is the first), in capitals.
            k = index(trim(e%choices), ' ', back=.true.)
            written = "'"//upper(trim(e%choices(k + 1:)))//"'"
            expected = "'"//trim(e%choices(k + 1:))//"'"
         else
            write (buf, '(a,i0,a)') "'f", i, ".dat'"
            written = trim(buf)
            expected = written
         end if
      end select
   end subroutine own_value

   !> Upper-case copy.
   pure function upper(s) result(t)
      character(*), intent(in) :: s
      character(len(s)) :: t
      integer :: i
      t = s
      do i = 1, len(s)
         if (s(i:i) >= 'a' .and. s(i:i) <= 'z') t(i:i) = achar(iachar(s(i:i)) - 32)
      end do
   end function upper

   !> The echo of a case reads back to the same case.
   subroutine test_echo_round_trip(error)
      type(error_type), allocatable, intent(out) :: error
      call write_text(table_path, '# t x z'//nl//'0 0 0'//nl//'0.5 0.1 0.2  # comment'//nl//'1.25 0.3 -0.1'//nl)
      call echo_case(error, 'paper', '&static tension = 180000 /'//nl)
      if (allocated(error)) return
      call echo_case(error, 'scene', "&material law = 'linear', compression = 'none' /"//nl// &
                     "&end_a kind = 'motion', x = 1.5, z = -2, amplitude = 0.3, period = 0.7, phase = 1, "// &
                     'direction_x = 3, direction_z = 4, ramp_time = 0.1 /'//nl// &
                     "&end_b kind = 'force', force_x = 1e4, force_z = -500, history = 'ramp', ramp_time = 0.02 /"//nl// &
                     '&rupture s_break = 20, t_break = 0.01, time = 0.003 /'//nl// &
                     "&numerics scheme = 'box', mass_matrix = 'lumped', dt = 1e-4, t_end = 0.01 /"//nl// &
                     "&output file = 'it''s.h5', fields = 'tension, u' /"//nl)
      if (allocated(error)) return
      call echo_case(error, 'tables', "&end_a kind = 'motion', motion = 'table', table_file = '"//table_path//"' /"//nl// &
                     "&end_b x = 50, z = 1, kind = 'motion', motion = 'table', table_time = 0, 0.25, 2, "// &
                     'table_x = 3*0.5, table_z = 1, 2, 3 /'//nl)
      if (allocated(error)) return
      call echo_case(error, 'material table', "&material law = 'table', table_strain = -0.01, 0, 0.05, 0.3, "// &
                     'table_tension = -2e3, 0, 1.2e5, 4.5e5, damping = 250 /'//nl)
      if (allocated(error)) return
      call write_text(material_path, '# strain tension'//nl//'0 0'//nl//'0.1 1e5 # a comment'//nl//'0.35 5e5'//nl)
      call echo_case(error, 'material table file', "&material law = 'table', table_file = '"//material_path// &
                     "', damping = 1.5 /"//nl)
   end subroutine test_echo_round_trip

   !> The echo (config_text) of two cases is the text the code wrote before config_text
   !> was made cheaper (taken from the files of xcable 867173b for these cases): end b's
   !> position given and the tension left out, a table read from a file written inline
   !> with its comment, a material table, a quote in a string; and the paper's case
   !> with its tension and without end b's position.
   subroutine test_echo_text(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      character(:), allocatable :: expected
      call write_text(table_path, '# t x z'//nl//'0 0 0'//nl//'0.5 0.1 0.2'//nl//'1.25 0.3 -0.1'//nl)
      call write_text(path, "&cable length = 20, diameter = 0.03 /"//nl// &
                      "&material law = 'table', table_strain = -0.01, 0, 0.05, 0.3, "// &
                      "table_tension = -2e3, 0, 1.2e5, 4.5e5, damping = 250 /"//nl// &
                      "&end_a kind = 'motion', motion = 'table', table_file = '"//table_path//"' /"//nl// &
                      "&end_b kind = 'fixed', x = 18.5, z = -3.25 /"//nl// &
                      "&numerics nodes = 21, t_end = 0.002 /"//nl// &
                      "&output file = 'results/it''s.h5', interval = 0.001, checkpoint_interval = 3600, "// &
                      "quiet = .true. /"//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      expected = "&cable length = 20, diameter = 0.03, density = 1140, young = 2.3e8, gravity = 9.81,"//nl // &
         "   area = 0.0007068583470577034, bending_stiffness = 9.144979865059037, gip = 6.532128475042169 /"//nl // &
         "&material law = 'table', p = 270300, 10.2, -2.128, 262700, 135.5, ea = 0, table_strain = -0.01, 0,"//nl // &
         "   0.05, 0.3, table_tension = -2000, 0, 120000, 450000, strain_max = 0.35, compression = 'none',"//nl // &
         "   damping = 250 /"//nl // &
         "&fluid density = 0, cd_normal = 0, cd_tangential = 0, ca_normal = 0, current_x = 0, current_y = 0,"//nl // &
         "   current_z = 0, surface_z = 0, air_density = 0 /"//nl // &
         "&seabed depth = 0, slope_x = 0, slope_y = 0, stiffness = 3e6, damping = 300000, mu_axial = 0,"//nl // &
         "   mu_lateral = 0, slip_velocity = 0.01, bathymetry_file = '', static_friction = 'none' /"//nl // &
         "! &end_a: the table was read from table_file = '"//table_path//"'"//nl // &
         "&end_a kind = 'motion', x = 0, y = 0, z = 0, force_x = 0, force_y = 0, force_z = 0, torque = 0,"//nl // &
         "   history = 'constant', ramp_time = 0, motion = 'table', amplitude = 0, period = 1, phase = 0,"//nl // &
         "   direction_x = 0, direction_y = 0, direction_z = 1, mass = 0, table_time = 0, 0.5, 1.25,"//nl // &
         "   table_x = 0, 0.1, 0.3, table_z = 0, 0.2, -0.1 /"//nl // &
         "&end_b kind = 'fixed', x = 18.5, y = 0, z = -3.25, force_x = 0, force_y = 0, force_z = 0, torque = 0,"//nl // &
         "   history = 'constant', ramp_time = 0, motion = 'harmonic', amplitude = 0, period = 1, phase = 0,"//nl // &
         "   direction_x = 0, direction_y = 0, direction_z = 1, mass = 0 /"//nl // &
         "&rupture enabled = .false., s_break = 20, t_break = 0.05, time = 0 /"//nl // &
         "&numerics scheme = 'rod', model = 'auto', nodes = 21, dt = 0, courant = 1, t_end = 0.002,"//nl // &
         "   theta = 0.5, mass_matrix = 'averaged', newton_tol = 1e-7, newton_max_iter = 25,"//nl // &
         "   reuse_jacobian = .true., extrapolate = .true., skip_quiescent = .true.,"//nl // &
         "   min_step_fraction = 0.0009765625, max_wall_time = 0 /"//nl // &
         "&output file = 'results/it''s.h5', interval = 0.001,"//nl // &
         "   fields = 'tension shear strain u v x z curvature', quiet = .true., energy = .false.,"//nl // &
         "   gnuplot = .false., xdmf = .false., checkpoint_interval = 3600 /"//nl
      call check(error, config_text(config) == expected, 'end b placed: the echo reads'//nl//config_text(config)// &
                 'instead of'//nl//expected)
      if (allocated(error)) return
      call check(error, index(config_text(config, fingerprint=.true.), 'checkpoint_interval') == 0 .and. &
                 index(config_text(config, fingerprint=.true.), "table_x = 0, 0.1, 0.3") > 0, &
                 'end b placed: the fingerprint reads'//nl//config_text(config, fingerprint=.true.))
      if (allocated(error)) return
      call write_text(path, '&static tension = 150000 /'//nl//'&rupture /'//nl//'&numerics nodes = 11, t_end = 0.001 /'// &
                      nl//"&output file = 'results/p2.h5', interval = 0.001, quiet = .true. /"//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      expected = "&cable length = 60, diameter = 0.05, density = 1140, young = 2.3e8, gravity = 9.81,"//nl // &
         "   area = 0.001963495408493621, bending_stiffness = 70.56311624273953, gip = 50.402225887671094 /"//nl // &
         "&material law = 'tanh', p = 270300, 10.2, -2.128, 262700, 135.5, ea = 0, strain_max = 0.35,"//nl // &
         "   compression = 'none', damping = 0 /"//nl // &
         "&fluid density = 0, cd_normal = 0, cd_tangential = 0, ca_normal = 0, current_x = 0, current_y = 0,"//nl // &
         "   current_z = 0, surface_z = 0, air_density = 0 /"//nl // &
         "&seabed depth = 0, slope_x = 0, slope_y = 0, stiffness = 3e6, damping = 300000, mu_axial = 0,"//nl // &
         "   mu_lateral = 0, slip_velocity = 0.01, bathymetry_file = '', static_friction = 'none' /"//nl // &
         "&static tension = 150000 /"//nl // &
         "&end_a kind = 'fixed', x = 0, y = 0, z = 0, force_x = 0, force_y = 0, force_z = 0, torque = 0,"//nl // &
         "   history = 'constant', ramp_time = 0, motion = 'harmonic', amplitude = 0, period = 1, phase = 0,"//nl // &
         "   direction_x = 0, direction_y = 0, direction_z = 1, mass = 0 /"//nl // &
         "&end_b kind = 'fixed', force_x = 0, force_y = 0, force_z = 0, torque = 0, history = 'constant',"//nl // &
         "   ramp_time = 0, motion = 'harmonic', amplitude = 0, period = 1, phase = 0, direction_x = 0,"//nl // &
         "   direction_y = 0, direction_z = 1, mass = 0 /"//nl // &
         "&rupture enabled = .true., s_break = 60, t_break = 0.05, time = 0 /"//nl // &
         "&numerics scheme = 'rod', model = 'auto', nodes = 11, dt = 0, courant = 1, t_end = 0.001,"//nl // &
         "   theta = 0.5, mass_matrix = 'averaged', newton_tol = 1e-7, newton_max_iter = 25,"//nl // &
         "   reuse_jacobian = .true., extrapolate = .true., skip_quiescent = .true.,"//nl // &
         "   min_step_fraction = 0.0009765625, max_wall_time = 0 /"//nl // &
         "&output file = 'results/p2.h5', interval = 0.001, fields = 'tension shear strain u v x z curvature',"//nl // &
         "   quiet = .true., energy = .false., gnuplot = .false., xdmf = .false., checkpoint_interval = 0 /"//nl
      call check(error, config_text(config) == expected, 'paper case: the echo reads'//nl//config_text(config)// &
                 'instead of'//nl//expected)
   end subroutine test_echo_text

   !> Read a case, write its echo, read that: every variable the same
   !> (table_file aside: the echo writes the table inline).
   subroutine echo_case(error, name, text)
      type(error_type), allocatable, intent(out) :: error
      character(*), intent(in) :: name, text
      character(len=*), parameter :: echo_path = 'build/test_input_echo.nml'
      type(case_config) :: first, second
      type(schema_entry), allocatable :: t(:)
      integer :: i
      call write_text(path, text)
      call read_config(path, first, error)
      if (allocated(error)) then
         error%message = name//': '//error%message
         return
      end if
      call write_text(echo_path, config_text(first))
      call read_config(echo_path, second, error)
      if (allocated(error)) then
         error%message = name//': the echo is refused: '//error%message//nl//config_text(first)
         return
      end if
      t = schema_table()
      do i = 1, size(t)
         if (t(i)%name == 'table_file') cycle
         call check(error, value_text(first, t(i)) == value_text(second, t(i)), name//': &'//trim(t(i)%group)//' '// &
                    trim(t(i)%name)//' read "'//value_text(first, t(i))//'", echoed and read back "'// &
                    value_text(second, t(i))//'"')
         if (allocated(error)) return
      end do
      call check(error, config_text(first) == config_text(second) .or. index(config_text(first), 'table_file') > 0, &
                 name//': the echo of the echo differs')
   end subroutine echo_case

   !> config%given lists the variables assigned, an element of p as p.
   subroutine test_given(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, '&material p(2) = 10.5 /'//nl//'&static tension = 2e5 /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check(error, config%is_given('material', 'p') .and. config%is_given('static', 'tension') .and. &
                 .not. config%is_given('cable', 'length') .and. .not. config%is_given('material', 'law'), &
                 'given: "'//config%given//'"')
   end subroutine test_given

   !> s_break left out is the end b, s = L; given, it is kept.
   subroutine test_s_break_default(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, '&cable length = 40 /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check_close(error, config%s_break, 40.0_dp, 's_break left out', rel_tol=1.0e-15_dp)
      if (allocated(error)) return
      call write_text(path, '&cable length = 40 /'//nl//'&rupture s_break = 0 /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check_close(error, config%s_break, 0.0_dp, 's_break = 0', abs_tol=0.0_dp)
   end subroutine test_s_break_default

   !> The direction of a harmonic motion is normalised.
   subroutine test_direction_normalised(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, "&end_a kind = 'motion', direction_x = 3, direction_z = -4 /"//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check_close(error, config%end_a%direction_x, 0.6_dp, 'direction_x', rel_tol=1.0e-15_dp)
      if (allocated(error)) return
      call check_close(error, config%end_a%direction_z, -0.8_dp, 'direction_z', rel_tol=1.0e-15_dp)
   end subroutine test_direction_normalised

   !> A table file of two columns (z = 0), with comments and blank lines, fills the table.
   subroutine test_table_file_read(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(table_path, '# force history'//nl//nl//'0 100'//nl//'  0.5, 200 # half'//nl//'1 50'//nl)
      call write_text(path, "&end_b kind = 'force', history = 'table', table_file = '"//table_path//"' /"//nl// &
                      '&rupture enabled = .false. /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check(error, config%end_b%table_rows == 3, 'table_rows')
      if (allocated(error)) return
      call check(error, all(config%end_b%table_time(1:3) == [0.0_dp, 0.5_dp, 1.0_dp]) .and. &
                 all(config%end_b%table_x(1:3) == [100.0_dp, 200.0_dp, 50.0_dp]) .and. &
                 all(config%end_b%table_z(1:3) == 0), 'table values')
   end subroutine test_table_file_read

   subroutine test_tension_and_position(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 2e5 /'//nl//'&end_b x = 50 /'//nl, &
                        [character(24) :: path, '&static', 'tension = 200000', '&end_b x = 50', 'both given', 'give one'])
   end subroutine test_tension_and_position

   subroutine test_s_break_outside(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&rupture s_break = 70 /'//nl, [character(32) :: path, '&rupture', 's_break = 70', &
                                                                 'in [0, 60 (&cable length)]'])
      if (allocated(error)) return
      ! A negative s_break is the default's way to say L; given, it is refused.
      call expect_error(error, '&rupture s_break = -1 /'//nl, [character(24) :: path, '&rupture', 's_break = -1', &
                                                                 'in [0, 60'])
   end subroutine test_s_break_outside

   subroutine test_mass_not_positive(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'mass' /"//nl, [character(24) :: path, '&end_b', 'mass = 0', '> 0', &
                                                               "kind = 'mass'"])
   end subroutine test_mass_not_positive

   subroutine test_unknown_kind(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'pinned' /"//nl, [character(24) :: path, '&end_a', "kind = 'pinned'", &
                                                                 "'fixed', 'free', 'force'", "'motion', 'mass'"])
   end subroutine test_unknown_kind

   !> Every variable with allowed words refuses another word, naming the words.
   subroutine test_unknown_words(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: cases(5) = [character(len=40) :: &
                                                 'end_b history constant ramp', 'end_a motion harmonic table', &
                                                 'numerics scheme rod box', 'numerics mass_matrix averaged lumped', &
                                                 'material compression law none']
      character(len=40) :: line, group, name, first, second
      integer :: i
      do i = 1, size(cases)
         line = cases(i)
         read (line, *) group, name, first, second
         call expect_error(error, '&'//trim(group)//' '//trim(name)//" = 'bogus' /"//nl, &
                           [character(40) :: path, '&'//trim(group), trim(name)//" = 'bogus'", 'must be one of', &
                            "'"//trim(first)//"'", "'"//trim(second)//"'"])
         if (allocated(error)) return
      end do
   end subroutine test_unknown_words

   subroutine test_two_free_ends(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'free' /"//nl//"&end_b kind = 'free' /"//nl, &
                        [character(32) :: path, "&end_a: kind = 'free'", "&end_b: kind = 'free'", 'no support', &
                         'no static state'])
   end subroutine test_two_free_ends

   subroutine test_nothing_holds(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'free' /"//nl//"&end_b kind = 'force' /"//nl, &
                        [character(32) :: path, "&end_a: kind = 'free'", "&end_b: kind = 'force'", &
                         'nothing holds the cable', "'fixed' or 'motion'"])
      if (allocated(error)) return
      call expect_error(error, "&end_a kind = 'mass', mass = 10 /"//nl//"&end_b kind = 'force' /"//nl, &
                        [character(32) :: path, "&end_a: kind = 'mass'", 'nothing holds the cable'])
   end subroutine test_nothing_holds

   subroutine test_position_of_loose_end(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'force', x = 5 /"//nl, &
                        [character(32) :: path, '&end_b', 'x = 5', "kind = 'force'", 'follows from the statics'])
      if (allocated(error)) return
      call expect_error(error, "&end_a kind = 'free', z = -3 /"//nl, &
                        [character(32) :: path, '&end_a', 'z = -3', "kind = 'free'", 'follows from the statics'])
   end subroutine test_position_of_loose_end

   !> A spring end's own conditions: a stiffness and damping not negative (the schema's range), a
   !> stiffness > 0, and with a rest length an anchor apart from the other (held) end's point.
   subroutine test_spring_values(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: a = "&end_a kind = 'fixed', x = 0, z = 0 /"//nl
      call expect_error(error, a//"&end_b kind = 'spring', x = 12, z = -1, stiffness = -5 /"//nl, &
                        [character(32) :: path, '&end_b', 'stiffness = -5', '[0, 1e12]'])
      if (allocated(error)) return
      call expect_error(error, a//"&end_b kind = 'spring', x = 12, z = -1, stiffness = 1e3, damping = -0.5 /"//nl, &
                        [character(32) :: path, '&end_b', 'damping = -0.5', '[0, 1e12]'])
      if (allocated(error)) return
      call expect_error(error, a//"&end_b kind = 'spring', x = 12, z = -1 /"//nl, &
                        [character(40) :: path, '&end_b', 'stiffness = 0', "must be > 0 for kind = 'spring'"])
      if (allocated(error)) return
      call expect_error(error, a//"&end_b kind = 'spring', x = 0, z = 0, stiffness = 1e3, rest_length = 2 /"//nl, &
                        [character(40) :: path, '&end_b', 'x, y, z = 0, 0, 0', 'rest_length = 2', &
                         "the other end's point"])
      if (allocated(error)) return
      ! The same anchor without a rest length, or beside a loaded end, is a scene.
      call expect_accepted(error, a//"&end_b kind = 'spring', x = 0, z = 0, stiffness = 1e3 /"//nl// &
                           '&rupture enabled = .false. /'//nl)
   end subroutine test_spring_values

   !> A variable of one kind given to another is refused, naming the kinds that use it (issue 29:
   !> amplitude and period on an end left 'fixed'); a variable at its default is not (the echo
   !> writes every variable).
   subroutine test_variable_of_another_kind(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'fixed', x = 50, amplitude = 0.5, period = 2 /"//nl, &
                        [character(40) :: path, '&end_b', 'amplitude = 0.5', "kind = 'fixed'", "kind 'motion'", &
                         'x, y, z'])
      if (allocated(error)) return
      call expect_error(error, "&end_b kind = 'force', force_x = 1e4, stiffness = 1000 /"//nl// &
                        '&rupture s_break = 30 /'//nl, &
                        [character(40) :: path, '&end_b', 'stiffness = 1000', "kind = 'force'", "kind 'spring'"])
      if (allocated(error)) return
      call expect_error(error, "&end_a kind = 'motion', mass = 3, amplitude = 1 /"//nl, &
                        [character(40) :: path, '&end_a', 'mass = 3', "kind = 'motion'", "kind 'mass' or 'spring'"])
      if (allocated(error)) return
      call expect_accepted(error, "&end_b kind = 'fixed', x = 50, amplitude = 0, period = 1 /"//nl)
   end subroutine test_variable_of_another_kind

   !> An unknown kind: the message lists the registered kinds, the spring among them.
   subroutine test_unknown_kind_lists_registry(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'pinned' /"//nl, &
                        [character(40) :: path, '&end_b', "'fixed'", "'motion'", "'mass'", "'spring'"])
   end subroutine test_unknown_kind_lists_registry

   !> Read text as a case: it must be accepted.
   subroutine expect_accepted(error, text)
      type(error_type), allocatable, intent(out) :: error
      character(*), intent(in) :: text
      type(case_config) :: config
      type(error_type), allocatable :: err
      call write_text(path, text)
      call read_config(path, config, err)
      if (allocated(err)) call fatal_error(error, 'refused: '//text//': '//err%message)
   end subroutine expect_accepted

   subroutine test_ramp_without_time(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'force', history = 'ramp' /"//nl//'&rupture s_break = 30 /'//nl, &
                        [character(32) :: path, '&end_b', 'ramp_time = 0', '> 0', "history = 'ramp'"])
   end subroutine test_ramp_without_time

   subroutine test_harmonic_period(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'motion', period = 0 /"//nl, &
                        [character(32) :: path, '&end_a', 'period = 0', '> 0', "motion = 'harmonic'"])
   end subroutine test_harmonic_period

   subroutine test_harmonic_direction(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'motion', direction_z = 0 /"//nl, &
                        [character(40) :: path, '&end_a', 'direction_x = 0, direction_y = 0, direction_z = 0', 'must not be zero'])
   end subroutine test_harmonic_direction

   subroutine test_table_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'force', history = 'table' /"//nl//'&rupture s_break = 30 /'//nl, &
                        [character(40) :: path, '&end_b', "history = 'table' without a table", 'table_file'])
   end subroutine test_table_missing

   subroutine test_table_too_short(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'motion', motion = 'table', table_time = 0.5, table_x = 1, "// &
                        'table_z = 0 /'//nl, [character(40) :: path, '&end_a', 'table_time = 0.5', '1 row', &
                                              'at least 2'])
   end subroutine test_table_too_short

   subroutine test_table_not_increasing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, 1, table_x = 3*0, "// &
                        'table_z = 3*0 /'//nl, [character(40) :: path, '&end_a', 'table_time(3) = 1', &
                                                'table_time(2) = 1', 'increase strictly'])
   end subroutine test_table_not_increasing

   subroutine test_table_columns(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, table_x = 1, "// &
                        'table_z(2) = 0 /'//nl, [character(40) :: path, '&end_a', 'table_time has 2 values', &
                                                 'table_x 1', 'table_z 2', 'equal counts'])
      if (allocated(error)) return
      call expect_error(error, "&end_b kind = 'motion', motion = 'table', table_time = 0, 1, table_x = 1, 2, "// &
                        'table_z = 0 /'//nl, [character(40) :: path, '&end_b', 'table_time has 2 values', &
                                              'table_x 2', 'table_z 1', 'equal counts'])
   end subroutine test_table_columns

   subroutine test_table_inline_and_file(error)
      type(error_type), allocatable, intent(out) :: error
      call write_text(table_path, '0 1'//nl//'1 2'//nl)
      call expect_error(error, "&end_a kind = 'motion', motion = 'table', table_time = 0, 1, table_x = 1, 2, "// &
                        "table_z = 0, 0, table_file = '"//table_path//"' /"//nl, &
                        [character(48) :: path, '&end_a', "table_file = '"//table_path//"'", 'inline table', &
                         'give one'])
   end subroutine test_table_inline_and_file

   subroutine test_table_file_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_a kind = 'motion', motion = 'table', table_file = 'build/no_such_table.dat' /"// &
                        nl, [character(48) :: path, '&end_a', "table_file = 'build/no_such_table.dat'", 'no such file'])
   end subroutine test_table_file_missing

   !> A bad line of a table file is named by its number.
   subroutine test_table_file_malformed(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: text = "&end_a kind = 'motion', motion = 'table', table_file = '"// &
                                            table_path//"' /"//nl
      call write_text(table_path, '# t x'//nl//'0 1'//nl//'0.5 abc'//nl)
      call expect_error(error, text, [character(48) :: path, '&end_a', "table_file = '"//table_path//"'", 'line 3', &
                                      '"abc" is not a finite real number'])
      if (allocated(error)) return
      call write_text(table_path, '0 1 2 3 4'//nl)
      call expect_error(error, text, [character(48) :: path, '&end_a', 'line 1', 'expected 2, 3 or 4 numbers'])
      if (allocated(error)) return
      call write_text(table_path, '0 1 2'//nl//'1 2'//nl)
      call expect_error(error, text, [character(48) :: path, '&end_a', 'line 2', 'the lines before have 3'])
      if (allocated(error)) return
      call write_text(table_path, '0 1'//nl//'# x'//nl//'0 2'//nl)
      call expect_error(error, text, [character(48) :: path, '&end_a', 'line 3', 'increase strictly'])
      if (allocated(error)) return
      call write_text(table_path, '# only a comment'//nl//'0 1'//nl)
      call expect_error(error, text, [character(48) :: path, '&end_a', 'has 1 row; a table must have at least 2'])
      if (allocated(error)) return
      call write_text(table_path, '# only a comment'//nl)
      call expect_error(error, text, [character(48) :: path, '&end_a', 'has 0 rows; a table must have at least 2'])
   end subroutine test_table_file_malformed

   subroutine test_rupture_at_loose_end(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&end_b kind = 'free' /"//nl//'&rupture /'//nl, &
                        [character(40) :: path, '&rupture', 's_break = 60 (the default, L)', "kind = 'free'", &
                         'nothing to break', 'enabled = .false.'])
      if (allocated(error)) return
      call expect_error(error, "&end_a kind = 'force' /"//nl//'&rupture s_break = 0 /'//nl, &
                        [character(40) :: path, '&rupture', 's_break = 0, at end a', "kind = 'force'", &
                         'nothing to break'])
   end subroutine test_rupture_at_loose_end

   !> &rupture criterion = 'tension': criterion and mbl are read; bad input names the file,
   !> the group, the variable and its value and what is allowed: a criterion other than 'time'
   !> and 'tension'; mbl not given, 0 or negative; s_break or time given with it (both named
   !> when both are); the box scheme. (An MBL at or below the static tension: suite rupture.)
   subroutine test_rupture_by_tension(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, "&rupture criterion = 'tension', mbl = 4.5e5, t_break = 0.01 /"//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check(error, trim(config%break_criterion) == 'tension' .and. config%mbl == 4.5e5_dp .and. &
                 config%break_enabled, 'criterion and mbl not read')
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'force' /"//nl, &
                        [character(40) :: path, '&rupture', "criterion = 'force'", "'time', 'tension'"])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension' /"//nl, &
                        [character(40) :: path, '&rupture', 'mbl = not given', "criterion = 'tension'", 'above 0 N'])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension', mbl = 0 /"//nl, &
                        [character(40) :: path, '&rupture', 'mbl = 0', 'above 0 N'])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension', mbl = -5 /"//nl, &
                        [character(40) :: path, '&rupture', 'mbl = -5', '> 0'])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension', mbl = 1e6, s_break = 30 /"//nl, &
                        [character(40) :: path, '&rupture', "criterion = 'tension'", 's_break = 30', 'not used'])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension', mbl = 1e6, time = 0.1 /"//nl, &
                        [character(40) :: path, '&rupture', "criterion = 'tension'", 'time = 0.1', 'not used'])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension', mbl = 1e6, s_break = 30, time = 0.1 /"//nl, &
                        [character(40) :: path, '&rupture', 's_break = 30 and time = 0.1', 'not used'])
      if (allocated(error)) return
      call expect_error(error, "&rupture criterion = 'tension', mbl = 1e6 /"//nl//"&numerics scheme = 'box' /"//nl, &
                        [character(40) :: path, '&rupture', "criterion = 'tension'", 'box scheme'])
   end subroutine test_rupture_by_tension

   !> The rows of the table law, inline or from a file (comments and blank
   !> lines skipped), and the damping coefficient are read into the case.
   subroutine test_material_table_read(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, "&material law = 'table', table_strain = 0, 0.1, 0.3, table_tension = 0, 8e4, 4e5, "// &
                      'damping = 120 /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check(error, config%material_table_rows == 3, 'inline rows: material_table_rows')
      if (allocated(error)) return
      call check(error, all(config%material_table_strain(1:3) == [0.0_dp, 0.1_dp, 0.3_dp]) .and. &
                 all(config%material_table_tension(1:3) == [0.0_dp, 8.0e4_dp, 4.0e5_dp]), 'inline rows: values')
      if (allocated(error)) return
      call check_close(error, config%damping, 120.0_dp, 'damping', rel_tol=0.0_dp)
      if (allocated(error)) return
      call write_text(material_path, '# strain  tension (N)'//nl//nl//'-0.01 -1500'//nl//'0 0'//nl// &
                      '  0.05, 60000  # knee'//nl//'   '//nl//'0.35 5.04e5'//nl)
      call write_text(path, "&material law = 'table', table_file = '"//material_path//"' /"//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check(error, config%material_table_rows == 4, 'file rows: material_table_rows')
      if (allocated(error)) return
      call check(error, all(config%material_table_strain(1:4) == [-0.01_dp, 0.0_dp, 0.05_dp, 0.35_dp]) .and. &
                 all(config%material_table_tension(1:4) == [-1500.0_dp, 0.0_dp, 6.0e4_dp, 5.04e5_dp]), &
                 'file rows: values')
      if (allocated(error)) return
      call check(error, trim(config%material_table_file) == material_path .and. config%damping == 0, &
                 'table_file kept, damping default 0')
   end subroutine test_material_table_read

   subroutine test_material_table_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table' /"//nl, &
                        [character(48) :: path, '&material', "law = 'table' without a table", 'table_strain', &
                         'table_file'])
   end subroutine test_material_table_missing

   subroutine test_material_table_too_short(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table', table_strain = 0.1, table_tension = 1e4 /"//nl, &
                        [character(40) :: path, '&material', 'table_strain = 0.1', '1 row', 'at least 2'])
   end subroutine test_material_table_too_short

   !> NaN and Inf are refused by the scan (naming the value); a strain of the
   !> table at or below -1 (a cell of no length) by the range.
   subroutine test_material_table_not_finite(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table', table_strain = 0, NaN, table_tension = 0, 1e4 /"//nl, &
                        [character(40) :: path, '&material', 'table_strain = 0, NaN', '"NaN" is not a finite real'])
      if (allocated(error)) return
      call expect_error(error, "&material law = 'table', table_strain = 0, 0.1, table_tension = 0, Inf /"//nl, &
                        [character(40) :: path, '&material', 'table_tension = 0, Inf', '"Inf" is not a finite real'])
      if (allocated(error)) return
      call expect_error(error, "&material law = 'table', table_strain = -1, 0.1, table_tension = 0, 1e4 /"//nl, &
                        [character(40) :: path, '&material', 'table_strain(1) = -1', '> -1 and <= 1'])
   end subroutine test_material_table_not_finite

   subroutine test_material_strain_order(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table', table_strain = 0, 0.1, 0.1, table_tension = 0, 1e4, 2e4 /"// &
                        nl, [character(40) :: path, '&material', 'table_strain(3) = 0.1', &
                             'not above table_strain(2) = 0.1', 'strains must increase strictly'])
      if (allocated(error)) return
      call expect_error(error, "&material law = 'table', table_strain = 0.2, 0.1, table_tension = 0, 1e4 /"//nl, &
                        [character(40) :: path, '&material', 'table_strain(2) = 0.1', 'strains must increase'])
   end subroutine test_material_strain_order

   !> A zero or negative slope of the law: a flat or decreasing tension.
   subroutine test_material_tension_order(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table', table_strain = 0, 0.1, 0.2, table_tension = 0, 2e4, 1.5e4 /"// &
                        nl, [character(48) :: path, '&material', 'table_tension(3) = 15000', &
                             'not above table_tension(2) = 20000', 'tensions must increase strictly', 'negative slope'])
      if (allocated(error)) return
      call expect_error(error, "&material law = 'table', table_strain = 0, 0.1, table_tension = 2*1e4 /"//nl, &
                        [character(48) :: path, '&material', 'table_tension(2) = 10000', 'tensions must increase'])
   end subroutine test_material_tension_order

   subroutine test_material_table_columns(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table', table_strain = 0, 0.1, 0.2, table_tension = 0, 1e4 /"//nl, &
                        [character(40) :: path, '&material', 'table_strain has 3 values', 'table_tension 2', &
                         'two columns', 'equal counts'])
   end subroutine test_material_table_columns

   !> Rows of the table law (inline or a file) with another law are refused.
   subroutine test_material_table_other_law(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&material table_strain = 0, 0.1, table_tension = 0, 1e4 /'//nl, &
                        [character(48) :: path, '&material', 'table_strain = 0, 0.1', "law = 'tanh'", &
                         "set law = 'table'"])
      if (allocated(error)) return
      call write_text(material_path, '0 0'//nl//'0.1 1e4'//nl)
      call expect_error(error, "&material law = 'linear', table_file = '"//material_path//"' /"//nl, &
                        [character(48) :: path, '&material', "table_file = '"//material_path//"'", "law = 'linear'", &
                         "set law = 'table'"])
   end subroutine test_material_table_other_law

   subroutine test_material_table_inline_and_file(error)
      type(error_type), allocatable, intent(out) :: error
      call write_text(material_path, '0 0'//nl//'0.1 1e4'//nl)
      call expect_error(error, "&material law = 'table', table_strain = 0, 0.1, table_tension = 0, 1e4, "// &
                        "table_file = '"//material_path//"' /"//nl, &
                        [character(48) :: path, '&material', "table_file = '"//material_path//"'", &
                         'inline table (table_strain, 2 rows)', 'give one'])
   end subroutine test_material_table_inline_and_file

   subroutine test_material_table_file_missing(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'table', table_file = 'build/no_such_law.dat' /"//nl, &
                        [character(64) :: path, '&material', "table_file = 'build/no_such_law.dat'", &
                         'no such file (the path is relative to the working directory)'])
   end subroutine test_material_table_file_missing

   !> A bad table file of the law: its line named.
   subroutine test_material_table_file_malformed(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: text = "&material law = 'table', table_file = '"//material_path//"' /"//nl
      character(:), allocatable :: rows
      integer :: i
      call write_text(material_path, '# strain tension'//nl//'0 0'//nl//'0.1 x'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', "table_file = '"//material_path//"'", &
                                      'line 3', '"x" is not a finite real number'])
      if (allocated(error)) return
      call write_text(material_path, '0 0'//nl//'0.1 1e4 2e4'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'line 2', &
                                      'expected 2 numbers (strain and tension)'])
      if (allocated(error)) return
      call write_text(material_path, '0 0'//nl//'0.1'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'line 2', 'expected 2 numbers'])
      if (allocated(error)) return
      call write_text(material_path, '0 0'//nl//'# knee'//nl//'0.2 1e4'//nl//'0.1 2e4'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'line 4', 'strain 0.1 is not above', &
                                      'strains must increase strictly'])
      if (allocated(error)) return
      call write_text(material_path, '0 0'//nl//'0.1 2e4'//nl//'0.2 2e4'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'line 3', 'tension 20000 is not above', &
                                      'tensions must increase strictly'])
      if (allocated(error)) return
      call write_text(material_path, '0 NaN'//nl//'0.1 2e4'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'line 1', '"NaN" is not a finite'])
      if (allocated(error)) return
      call write_text(material_path, '# one row'//nl//'0.1 2e4'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'has 1 row; a table must have at least 2'])
      if (allocated(error)) return
      call write_text(material_path, nl//'# no rows'//nl)
      call expect_error(error, text, [character(48) :: path, '&material', 'has 0 rows; a table must have at least 2'])
      if (allocated(error)) return
      rows = ''
      do i = 0, 1000
         rows = rows//real_text(0.001_dp*i)//' '//real_text(10.0_dp*i)//nl
      end do
      call write_text(material_path, rows)
      call expect_error(error, text, [character(48) :: path, '&material', 'line 1001', 'more than 1000 rows'])
   end subroutine test_material_table_file_malformed

   !> The damping coefficient is >= 0 and finite (at most 1e12 N s).
   subroutine test_damping(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&material damping = -1 /'//nl, [character(40) :: path, '&material', 'damping = -1', &
                                                                  'in [0, 1e12]'])
      if (allocated(error)) return
      call expect_error(error, '&material damping = 1e300 /'//nl, [character(40) :: path, '&material', &
                                                                     'damping = 1e300', 'in [0, 1e12]'])
      if (allocated(error)) return
      call expect_error(error, '&material damping = Inf /'//nl, [character(40) :: path, '&material', 'damping = Inf', &
                                                                   'not a finite real number'])
   end subroutine test_damping
end module suite_input
