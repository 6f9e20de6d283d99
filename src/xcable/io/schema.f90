!> The namelist schema: one table that describes every group and variable of
!> a case file (type, element count, string length, unit, default, allowed
!> values or range, meaning). The reader (io/input.f90) takes from it the
!> names and types the scanner checks, the range and allowed-value checks of
!> the validation and the order and form of the echo; `write_schema` makes
!> from it the input table of docs/user/namelist.md and the sweep scripts' variable table
!> (`xcable --schema markdown|tsv`).
!>
!> Adding a variable: a component with its default in io/config.f90, an
!> entry in build_table (io/schema/table.f90; the default written as the echo writes it), and in
!> io/input.f90 one line of `access` plus the namelist read of its group
!> (local, namelist statement, copy in and out); then `make schema`. The
!> tests of suite input fail until all of these agree. A variable that steers
!> a run without changing what it computes (progress lines, limits of wall
!> time, checkpoints) is marked resume_may_differ: a checkpoint is accepted
!> by `xcable --resume` when every other variable is as it was.
!>
!> The groups &segment_1 ... &segment_8 are made from the entries of &cable,
!> &material and &fluid (add_segments, io/schema/table.f90: a copy of each entry that describes the
!> line, with its twin group named): a variable added there for a segment to
!> take needs its name in add_segments' list, a component of segment_config, a
!> line of access_segment and of read_segment, and one in segment_case.
!>
!> The groups &point_1 ... &point_8 take, besides the body's variables, a kind and the variables
!> of an end of kind 'motion' (copies of &end_a's entries, add_points); &line_1 ... &line_8 are
!> the lines of a network between such points (add_lines).
module xcable_io_schema
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: real_text
   use xcable_io_config, only: max_table_points, max_segments, max_points, max_lines
   implicit none
   private
   public :: schema_entry, schema_table, schema_groups, find_entry, group_entries
   public :: schema_text, write_schema, allowed_text, bound_text, known_fields, is_table
   public :: segment_of, segment_group, group_list, point_of, point_group, line_of, line_group

   !> Snapshot fields that &output fields may name.
   character(len=*), parameter :: known_fields(8) = &
      [character(len=9) :: 'tension', 'shear', 'strain', 'u', 'v', 'x', 'z', 'curvature']

   !> One namelist variable.
   type :: schema_entry
      !> Group and variable name, lower case.
      character(len=16) :: group = ''
      character(len=24) :: name = ''
      !> 'real', 'integer', 'logical' or 'string'.
      character(len=8) :: type = 'real'
      !> Number of elements (1 a scalar, 5 for p, max_table_points for a table).
      integer :: count = 1
      !> Length of a string variable.
      integer :: length = 0
      !> Unit ('-': none).
      character(len=16) :: unit = '-'
      !> Default, written as the echo writes it ('' for a table: no rows).
      character(len=64) :: default = ''
      !> Allowed words of a string, separated by blanks ('' : any text).
      character(len=96) :: choices = ''
      !> Whether the value is a list of such words (blanks or commas between).
      logical :: word_list = .false.
      !> Whether a number has a range: lower <= x (lower < x if lower_open) and x <= upper.
      logical :: bounded = .false.
      real(dp) :: lower = 0, upper = 0
      logical :: lower_open = .false.
      !> Upper bound taken from another variable, 'group%name' ('' : upper).
      character(len=40) :: upper_from = ''
      !> What 0 (or '' for a string) stands for; then 0 is allowed besides the range ('' : nothing).
      character(len=40) :: zero_means = ''
      !> What the default stands for when the variable is not given; a given value must be in range ('' : nothing).
      character(len=40) :: default_means = ''
      !> Added to a range error: why the range is what it is.
      character(len=120) :: note = ''
      !> A variable of &end_a / &end_b that the echo writes only for the kinds that use it (the
      !> others are written for every kind, as the files before the end-kind registry had them).
      logical :: own_kinds_only = .false.
      !> Whether the value may differ between a run and its `xcable --resume` (it steers the run,
      !> not what it computes: left out of the namelist fingerprint a checkpoint is checked against).
      logical :: resume_may_differ = .false.
      !> The group whose value a variable of &segment_k takes when the segment does not give
      !> it ('cable', 'material' or 'fluid'; '' : a variable of its own).
      character(len=16) :: twin = ''
      !> Meaning, one line.
      character(len=320) :: doc = ''
   end type schema_entry

   interface
      !> Build the table (io/schema/table.f90).
      module subroutine build_table(t)
         !> The table.
         type(schema_entry), allocatable, intent(out) :: t(:)
      end subroutine build_table
   end interface

contains

   !> The table: every group and variable, in the order of the file and the echo.
   !> Built once per process (its appends copy the entries before: 2 million
   !> instructions a build, and a run asks for it six times).
   function schema_table() result(t)
      type(schema_entry), allocatable :: t(:)
      type(schema_entry), allocatable, save :: built(:)
      if (.not. allocated(built)) call build_table(built)
      t = built
   end function schema_table

   !> The name of the group of segment k: 'segment_k'.
   pure function segment_group(k) result(group)
      !> Segment, 1 .. max_segments.
      integer, intent(in) :: k
      character(len=16) :: group
      group = 'segment_'//number_text(k)
   end function segment_group

   !> The segment a group describes: k for 'segment_k', 0 for any other group.
   pure integer function segment_of(group)
      !> Group name, lower case.
      character(*), intent(in) :: group
      segment_of = numbered(group, 'segment_', max_segments)
   end function segment_of

   !> The name of the group of point k: 'point_k'.
   pure function point_group(k) result(group)
      !> Point, 1 .. max_points.
      integer, intent(in) :: k
      character(len=16) :: group
      group = 'point_'//number_text(k)
   end function point_group

   !> The point a group describes: k for 'point_k', 0 for any other group.
   pure integer function point_of(group)
      !> Group name, lower case.
      character(*), intent(in) :: group
      point_of = numbered(group, 'point_', max_points)
   end function point_of

   !> The name of the group of line k of a network: 'line_k'.
   pure function line_group(k) result(group)
      !> Line, 1 .. max_lines.
      integer, intent(in) :: k
      character(len=16) :: group
      group = 'line_'//number_text(k)
   end function line_group

   !> The line a group describes: k for 'line_k', 0 for any other group.
   pure integer function line_of(group)
      !> Group name, lower case.
      character(*), intent(in) :: group
      line_of = numbered(group, 'line_', max_lines)
   end function line_of

   !> k for a group named prefix followed by k (1 .. most, no leading zero), else 0. (Parsed,
   !> not compared with the names written for each k: the reader and the echo ask it of every
   !> variable, and the written names took 6 % of a short run's instructions.)
   pure integer function numbered(group, prefix, most)
      !> Group name, lower case; its prefix ('segment_'); the largest number.
      character(*), intent(in) :: group, prefix
      integer, intent(in) :: most
      integer :: n, i, k
      numbered = 0
      n = len_trim(group)
      if (n <= len(prefix) .or. n > len(prefix) + 2) return
      if (group(1:len(prefix)) /= prefix) return
      if (verify(group(len(prefix) + 1:n), '0123456789') /= 0 .or. group(len(prefix) + 1:len(prefix) + 1) == '0') return
      k = 0
      do i = len(prefix) + 1, n
         k = 10*k + (iachar(group(i:i)) - iachar('0'))
      end do
      if (k <= most) numbered = k
   end function numbered

   !> k (0 .. 99) in decimal digits.
   pure function number_text(k) result(s)
      integer, intent(in) :: k
      character(:), allocatable :: s
      if (k < 10) then
         s = achar(iachar('0') + k)
      else
         s = achar(iachar('0') + k/10)//achar(iachar('0') + mod(k, 10))
      end if
   end function number_text

   !> Group names as '&a, &b, &segment_1 ... &segment_8' (a run of more than two numbered groups
   !> &segment_k, &point_k or &line_k as its first and last), each after a prefix, with a separator.
   function group_list(names, open, close, separator) result(s)
      !> Group names, blank-padded.
      character(len=*), intent(in) :: names(:)
      !> What goes before and after each name ('&' and '', or '`&' and '`').
      character(*), intent(in) :: open, close
      !> Between two names (', ').
      character(*), intent(in) :: separator
      character(:), allocatable :: s
      integer :: i, j
      s = ''
      i = 1
      do while (i <= size(names))
         j = i
         if (segment_of(names(i)) == 1) then
            do while (j < size(names))
               if (segment_of(names(j + 1)) /= segment_of(names(j)) + 1) exit
               j = j + 1
            end do
         else if (point_of(names(i)) == 1) then
            do while (j < size(names))
               if (point_of(names(j + 1)) /= point_of(names(j)) + 1) exit
               j = j + 1
            end do
         else if (line_of(names(i)) == 1) then
            do while (j < size(names))
               if (line_of(names(j + 1)) /= line_of(names(j)) + 1) exit
               j = j + 1
            end do
         end if
         if (len(s) > 0) s = s//separator
         if (j - i >= 2) then
            s = s//open//trim(names(i))//close//' ... '//open//trim(names(j))//close
         else
            s = s//open//trim(names(i))//close
            j = i
         end if
         i = j + 1
      end do
   end function group_list

   !> The groups of the table, in order.
   function schema_groups(t) result(groups)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      character(len=16), allocatable :: groups(:)
      integer :: i
      allocate (groups(0))
      do i = 1, size(t)
         if (.not. any(groups == t(i)%group)) groups = [character(len=16) :: groups, t(i)%group]
      end do
   end function schema_groups

   !> The indices of the entries of a group, in order.
   function group_entries(t, group) result(indices)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      !> Group name.
      character(*), intent(in) :: group
      integer, allocatable :: indices(:)
      integer :: i
      allocate (indices(0))
      do i = 1, size(t)
         if (t(i)%group == group) indices = [indices, i]
      end do
   end function group_entries

   !> Index of group%name in the table (0: none).
   pure integer function find_entry(t, group, name)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      !> Group and variable name, lower case.
      character(*), intent(in) :: group, name
      integer :: i
      find_entry = 0
      do i = 1, size(t)
         if (t(i)%group == group .and. t(i)%name == name) then
            find_entry = i
            return
         end if
      end do
   end function find_entry

   !> Whether an entry is a table (an array too long to list or sweep).
   pure logical function is_table(e)
      !> Entry.
      type(schema_entry), intent(in) :: e
      is_table = e%count == max_table_points
   end function is_table

   !> A bound as text: an integer for an integer variable, else the shortest real.
   function bound_text(e, x) result(s)
      !> Entry.
      type(schema_entry), intent(in) :: e
      !> Bound.
      real(dp), intent(in) :: x
      character(:), allocatable :: s
      character(len=24) :: buf
      if (e%type == 'integer') then
         write (buf, '(i0)') nint(x)
         s = trim(buf)
      else
         s = real_text(x)
      end if
   end function bound_text

   !> What a variable allows, as in 'must be ...': "in [0.01, 1e5]", "> 0 and <= 1e9",
   !> "0 (for pi d^2 / 4) or in [...]", "an integer from 3 to 100001", "one of 'tanh', 'linear'".
   !> upper gives the value of an upper bound taken from another variable (upper_from).
   function allowed_text(e, upper) result(s)
      !> Entry.
      type(schema_entry), intent(in) :: e
      !> Effective upper bound when e%upper_from is set.
      real(dp), intent(in), optional :: upper
      character(:), allocatable :: s, hi
      if (len_trim(e%choices) > 0) then
         if (e%word_list) then
            s = 'words from: '//comma_list(e%choices, "")
         else
            s = 'one of '//comma_list(e%choices, "'")
         end if
         return
      end if
      if (.not. e%bounded) then
         s = ''
         return
      end if
      if (len_trim(e%upper_from) > 0) then
         hi = upper_name(e)
         if (present(upper)) hi = bound_text(e, upper)//' ('//hi//')'
      else
         hi = bound_text(e, e%upper)
      end if
      if (e%type == 'integer') then
         s = 'an integer from '//bound_text(e, e%lower)//' to '//hi
      else if (e%lower_open) then
         s = '> '//bound_text(e, e%lower)//' and <= '//hi
      else
         s = 'in ['//bound_text(e, e%lower)//', '//hi//']'
      end if
      if (len_trim(e%zero_means) > 0) s = '0 ('//trim(e%zero_means)//') or '//s
   end function allowed_text

   !> The variable an upper bound is taken from, as '&group name'.
   function upper_name(e) result(s)
      !> Entry with upper_from set.
      type(schema_entry), intent(in) :: e
      character(:), allocatable :: s
      integer :: pct
      pct = index(e%upper_from, '%')
      s = '&'//e%upper_from(1:pct - 1)//' '//trim(e%upper_from(pct + 1:))
   end function upper_name

   !> The table as text: 'markdown' (the input table of docs/user/namelist.md) or 'tsv'
   !> (group, variable, type, count, with a header line; the sweep scripts'
   !> table). Lines end with a new line; '' for an unknown format.
   function schema_text(format) result(text)
      !> 'markdown' or 'tsv'.
      character(*), intent(in) :: format
      character(:), allocatable :: text
      type(schema_entry), allocatable :: t(:)
      character(len=16), allocatable :: groups(:)
      character(len=*), parameter :: nl = new_line('a'), tab = achar(9)
      character(:), allocatable :: heading
      integer :: i, ig, jg
      integer, allocatable :: mine(:)
      character(len=24) :: buf
      t = schema_table()
      text = ''
      select case (format)
      case ('tsv')
         text = 'group'//tab//'variable'//tab//'type'//tab//'count'//nl
         do i = 1, size(t)
            write (buf, '(i0)') t(i)%count
            text = text//trim(t(i)%group)//tab//trim(t(i)%name)//tab//trim(t(i)%type)//tab//trim(buf)//nl
         end do
      case ('markdown')
         text = '| group | variable | type | unit | default | allowed | meaning |'//nl// &
                '|---|---|---|---|---|---|---|'//nl
         groups = schema_groups(t)
         ig = 1
         do while (ig <= size(groups))
            ! Groups with the same variables (&end_a, &end_b; &segment_1 ... &segment_8) share their rows.
            jg = ig
            do while (jg < size(groups))
               if (.not. same_variables(t, groups(ig), groups(jg + 1))) exit
               jg = jg + 1
            end do
            heading = group_list(groups(ig:jg), '`&', '`', ', ')
            mine = group_entries(t, groups(ig))
            do i = 1, size(mine)
               if (i > 1) heading = ''
               text = text//markdown_row(t(mine(i)), heading)//nl
            end do
            ig = jg + 1
         end do
      end select
   end function schema_text

   !> Write the table ('markdown' or 'tsv') to a unit.
   subroutine write_schema(unit, format, error)
      !> Open formatted unit.
      integer, intent(in) :: unit
      !> 'markdown' or 'tsv'.
      character(*), intent(in) :: format
      !> Error for an unknown format.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (format /= 'markdown' .and. format /= 'tsv') then
         call fatal_error(error, "--schema "//format//": unknown format; allowed: markdown, tsv", stat_input)
         return
      end if
      text = schema_text(format)
      write (unit, '(a)', advance='no') text
   end subroutine write_schema

   !> One row of the markdown table.
   function markdown_row(e, heading) result(row)
      !> Entry.
      type(schema_entry), intent(in) :: e
      !> Text of the group column ('' after the first row of a group).
      character(*), intent(in) :: heading
      character(:), allocatable :: row, type, default, allowed
      character(len=24) :: buf
      type = trim(e%type)
      if (e%count > 1) then
         write (buf, '(i0)') e%count
         type = type//'('//trim(buf)//')'
      else if (e%type == 'string') then
         write (buf, '(i0)') e%length
         type = type//'('//trim(buf)//')'
      end if
      if (len_trim(e%default) == 0 .and. .not. is_table(e)) then
         default = 'none'
      else if (len_trim(e%default) == 0) then
         default = 'no rows'
      else
         default = '`'//trim(e%default)//'`'
      end if
      if (len_trim(e%zero_means) > 0 .and. (e%default == '0' .or. e%default == "''")) &
         default = default//' ('//trim(e%zero_means)//')'
      if (len_trim(e%default_means) > 0) default = default//' ('//trim(e%default_means)//')'
      if (len_trim(e%twin) > 0) default = '&'//trim(e%twin)//"'s value"
      allowed = allowed_text(e)
      if (len_trim(e%choices) > 0) then
         if (e%word_list) then
            allowed = 'words from `'//trim(e%choices)//'`'
         else
            allowed = comma_list(e%choices, '`'//"'", "'"//'`')
         end if
      else if (e%type == 'logical') then
         allowed = '`.true.`, `.false.`'
      else if (len(allowed) == 0) then
         allowed = 'text'
      end if
      row = '| '//heading//' | `'//trim(e%name)//'` | '//type//' | '//trim(e%unit)//' | '//default//' | '// &
            allowed//' | '//trim(e%doc)
      if (len_trim(e%note) > 0) row = row//' ('//trim(e%note)//')'
      if (e%resume_may_differ) row = row//'; may differ on --resume'
      row = escape_tags(row//' |')
   end function markdown_row

   !> '<' before a letter, outside `code`, as '&lt;' (markdown would take <namelist stem> for a tag).
   function escape_tags(text) result(s)
      !> A row of the table.
      character(*), intent(in) :: text
      character(:), allocatable :: s
      logical :: in_code
      integer :: i
      s = ''
      in_code = .false.
      do i = 1, len(text)
         if (text(i:i) == '`') in_code = .not. in_code
         if (text(i:i) == '<' .and. .not. in_code .and. verify(text(i + 1:min(i + 1, len(text))), &
                                                                'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ') == 0) then
            s = s//'&lt;'
         else
            s = s//text(i:i)
         end if
      end do
   end function escape_tags

   !> Whether two groups have the same variables (names, types, defaults, meanings).
   logical function same_variables(t, a, b)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      !> Two groups.
      character(*), intent(in) :: a, b
      integer, allocatable :: ia(:), ib(:)
      integer :: i
      ia = group_entries(t, a)
      ib = group_entries(t, b)
      same_variables = size(ia) == size(ib)
      if (.not. same_variables) return
      do i = 1, size(ia)
         same_variables = t(ia(i))%name == t(ib(i))%name .and. t(ia(i))%type == t(ib(i))%type .and. &
                          t(ia(i))%default == t(ib(i))%default .and. t(ia(i))%doc == t(ib(i))%doc
         if (.not. same_variables) return
      end do
   end function same_variables

   !> Blank-separated words as "'a', 'b', 'c'" (with the given quotes).
   function comma_list(words, open, close) result(s)
      !> Blank-separated words, and what goes before each.
      character(*), intent(in) :: words, open
      !> What goes after each (open if absent).
      character(*), intent(in), optional :: close
      character(:), allocatable :: s, last
      integer :: i, start
      last = open
      if (present(close)) last = close
      s = ''
      start = 0
      do i = 1, len(words) + 1
         if (i > len(words)) then
            if (start > 0) s = s//open//words(start:i - 1)//last
         else if (words(i:i) == ' ') then
            if (start > 0) s = s//open//words(start:i - 1)//last//', '
            start = 0
         else if (start == 0) then
            start = i
         end if
      end do
      if (len(s) >= 2) then
         if (s(len(s) - 1:) == ', ') s = s(1:len(s) - 2)
      end if
   end function comma_list
end module xcable_io_schema
