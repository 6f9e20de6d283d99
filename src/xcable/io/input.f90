!> Reading a case from a namelist file into `case_config`, then validating it.
!>
!> gfortran reports a misspelled variable, a wrong-typed value, a missing group
!> and a missing closing '/' alike (often as "End of file"), so the file is
!> first scanned here: groups are located, unknown or duplicated groups and
!> unterminated groups are refused, every assignment's name is checked against
!> the group's variables and its value against the variable's type, both taken
!> from the schema (io/schema.f90). Only then is each group read with the
!> compiler's namelist input. The validation checks every variable against
!> its schema entry (range or allowed words), then the conditions between
!> variables (the ends, the tables, the rupture). Every message is one line
!> naming the file, the group, the variable, its value and what is allowed.
!>
!> The namelist reads need compile-time lists of variables (read_groups,
!> read_end) and the generic code needs a way from a schema entry to its
!> component of case_config (access); the suite input checks both against
!> the schema for every entry.
module xcable_io_input
   use xcable_kinds, only: dp, i8
   use xcable_error, only: error_type, fatal_error, stat_input
   use xcable_strings, only: str, to_lower, real_text
   use xcable_io_config, only: case_config, end_config, max_table_points
   use xcable_ends_registry, only: end_kind, find_end_kind, end_kind_names, kinds_using
   use xcable_io_schema, only: schema_entry, schema_table, schema_groups, find_entry, group_entries, allowed_text, &
                               known_fields, is_table
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: case_config, read_config, read_values, config_text, value_text, known_fields, derive_defaults

   integer, parameter :: line_len = 1024, max_lines = 5000

   !> Most time steps a run may ask for (t_end / dt): the history is kept in
   !> memory, and a step far below this is a typing error (dt = 1e-300 made
   !> an integer overflow and a crash).
   integer, parameter, public :: max_time_steps = 1000000

   !> Most snapshots a run may ask for (t_end / interval).
   real(dp), parameter :: max_snapshots = 1.0e5_dp
   !> Poisson ratio of the default torsional stiffness GIp = EI / (1 + nu) (a solid isotropic rod; nylon).
   real(dp), parameter :: default_poisson = 0.4_dp

   !> Values longer than this are cut in messages.
   integer, parameter :: shown_length = 60

   !> Why the columns of the tables must increase (ends of the messages on their order).
   character(len=*), parameter :: time_order = 'the times must increase strictly', &
                                  strain_order = 'the strains must increase strictly', &
                                  tension_order = "the tensions must increase strictly (a zero or negative slope f' "// &
                                                  'leaves the law without a real wave speed)'

   !> The value of one variable, on its way between case_config and the generic code.
   type :: config_value
      !> Whether the variable is known to `access`.
      logical :: found = .false.
      !> A real or the elements of a real array (a table: its rows).
      real(dp), allocatable :: reals(:)
      !> An integer.
      integer :: int = 0
      !> A logical.
      logical :: flag = .false.
      !> A string, without trailing blanks.
      character(:), allocatable :: text
   end type config_value

   !> Move a component to (store = .false.) or from (store = .true.) a config_value.
   interface move
      module procedure move_real, move_reals, move_integer, move_logical, move_string
   end interface move

contains

   !> Read and validate a case.
   subroutine read_config(path, config, error)
      !> Namelist file.
      character(*), intent(in) :: path
      !> The case.
      type(case_config), intent(out) :: config
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      call read_values(path, config, error)
      if (allocated(error)) return
      call validate(config, error)
   end subroutine read_config

   !> Read a case without validating its values: scan the file (groups,
   !> names, value types), read the groups that are present, record which
   !> variables are given (config%given), put the words of string variables
   !> in lower case and count the inline table rows.
   subroutine read_values(path, config, error)
      !> Namelist file.
      character(*), intent(in) :: path
      !> The case, not yet validated.
      type(case_config), intent(out) :: config
      !> Error naming file, group and variable.
      type(error_type), allocatable, intent(out) :: error
      type(schema_entry), allocatable :: t(:)
      character(len=16), allocatable :: groups(:)
      character(len=line_len), allocatable :: lines(:)
      logical, allocatable :: present_group(:)
      integer, allocatable :: counts(:)
      integer :: nlines, i

      config%source = path
      t = schema_table()
      groups = schema_groups(t)
      call load_lines(path, lines, nlines, error)
      if (allocated(error)) return
      allocate (present_group(size(groups)), counts(size(t)))
      call scan_groups(path, lines(1:nlines), t, groups, present_group, counts, error)
      if (allocated(error)) return
      ! A break only when asked for: &rupture given (its enabled then defaults to .true.).
      config%break_enabled = any(groups == 'rupture' .and. present_group)
      call read_groups(path, config, groups, present_group, error)
      if (allocated(error)) return
      config%given = ''
      do i = 1, size(t)
         if (counts(i) > 0) config%given = config%given//' '//trim(t(i)%group)//'%'//trim(t(i)%name)
      end do
      config%given = adjustl(config%given)
      do i = 1, size(t)
         if (len_trim(t(i)%choices) > 0) call lower_words(config, t(i))
      end do
      call count_table_rows(config, t, counts, error)
   end subroutine read_values

   !> Put the value of a string variable with allowed words in lower case, without leading blanks.
   subroutine lower_words(c, e)
      !> The case.
      type(case_config), intent(inout) :: c
      !> A string variable with allowed words.
      type(schema_entry), intent(in) :: e
      type(config_value) :: v
      call access(c, e, v, .false.)
      v%text = to_lower(trim(adjustl(v%text)))
      call access(c, e, v, .true.)
   end subroutine lower_words

   !> The number of rows of each inline table: the number of values given to
   !> its first column (an end's table_time, the material's table_strain),
   !> which the other columns must match (an end's table_y may be left out).
   subroutine count_table_rows(c, t, counts, error)
      !> The case; table_rows of each end and material_table_rows set.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Values given to each entry (its highest index assigned).
      integer, intent(in) :: counts(:)
      !> Error naming the columns and their counts.
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: end_columns(3) = [character(len=10) :: 'table_time', 'table_x', 'table_z']
      character(len=*), parameter :: material_columns(2) = [character(len=13) :: 'table_strain', 'table_tension']
      call inline_rows(c, t, counts, 'end_a', end_columns, c%end_a%table_rows, error)
      if (allocated(error)) return
      call optional_column('end_a', c%end_a%table_rows)
      if (allocated(error)) return
      call inline_rows(c, t, counts, 'end_b', end_columns, c%end_b%table_rows, error)
      if (allocated(error)) return
      call optional_column('end_b', c%end_b%table_rows)
      if (allocated(error)) return
      call inline_rows(c, t, counts, 'material', material_columns, c%material_table_rows, error)
   contains
      !> An end's table_y (3-D model): left out, or one value a row.
      subroutine optional_column(group, rows)
         character(*), intent(in) :: group
         integer, intent(in) :: rows
         integer :: n
         n = counts(find_entry(t, group, 'table_y'))
         if (n == 0 .or. n == rows) return
         call fatal_error(error, c%source//': &'//group//': table_y has '//str(n)//' values, table_time '// &
                          str(rows)//': table_y is left out or has one value a row', stat_input)
      end subroutine optional_column
   end subroutine count_table_rows

   !> The rows of one inline table: the count of its first column, refused
   !> unless every column has that count.
   subroutine inline_rows(c, t, counts, group, columns, rows, error)
      !> The case (for its source).
      type(case_config), intent(in) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Values given to each entry (its highest index assigned).
      integer, intent(in) :: counts(:)
      !> Group of the table.
      character(*), intent(in) :: group
      !> Names of its columns, the first giving the count.
      character(len=*), intent(in) :: columns(:)
      !> Number of rows.
      integer, intent(out) :: rows
      !> Error naming the columns and their counts.
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: how_many(3) = [character(len=5) :: 'one', 'two', 'three']
      character(:), allocatable :: found
      integer :: n(size(columns)), k
      do k = 1, size(columns)
         n(k) = counts(find_entry(t, group, trim(columns(k))))
      end do
      rows = n(1)
      if (all(n == rows)) return
      found = trim(columns(1))//' has '//str(n(1))//' values'
      do k = 2, size(columns)
         found = found//', '//trim(columns(k))//' '//str(n(k))
      end do
      call fatal_error(error, c%source//': &'//group//': '//found//': the '//trim(how_many(size(columns)))// &
                       ' columns of a table must have equal counts', stat_input)
   end subroutine inline_rows

   !> Read the file into lines, refusing what is not plain text.
   !>
   !> The bytes are read unformatted and split here, at LF or CR LF: gfortran's
   !> formatted stream input also ends a line at a lone CR (old Mac text) but
   !> its namelist input does not, so the scan and the read would see
   !> different files. A lone CR, a control byte or a byte above 126 is
   !> refused with its line and column; a tab counts as a blank.
   subroutine load_lines(path, lines, nlines, error)
      !> Text file.
      character(*), intent(in) :: path
      !> Its lines (the first nlines are used).
      character(len=line_len), allocatable, intent(out) :: lines(:)
      !> Number of lines.
      integer, intent(out) :: nlines
      !> Error naming the file, the line and the column.
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: max_bytes = line_len*max_lines
      character(len=:), allocatable :: bytes
      character(len=256) :: msg
      integer(i8) :: file_size
      integer :: unit, ios, i, c, column
      logical :: exists
      inquire (file=path, exist=exists)
      if (.not. exists) then
         call fatal_error(error, path//': no such file', stat_input)
         return
      end if
      open (newunit=unit, file=path, status='old', action='read', access='stream', form='unformatted', &
            iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, path//': cannot open: '//trim(msg), stat_input)
         return
      end if
      inquire (unit=unit, size=file_size)
      if (file_size < 0 .or. file_size > max_bytes) then
         close (unit)
         call fatal_error(error, path//': size '//str(int(file_size))//' bytes: not a namelist file (at most '// &
                          str(max_bytes)//' bytes)', stat_input)
         return
      end if
      allocate (character(len=int(file_size)) :: bytes)
      ios = 0
      if (file_size > 0) read (unit, iostat=ios, iomsg=msg) bytes
      close (unit)
      if (ios /= 0) then
         call fatal_error(error, path//': cannot read: '//trim(msg)//' (not a regular text file?)', stat_input)
         return
      end if
      allocate (lines(max_lines))
      nlines = 0
      column = -1
      do i = 1, len(bytes)
         c = ichar(bytes(i:i))
         if (column < 0) then
            ! A new line starts.
            if (nlines == max_lines) then
               call fatal_error(error, path//': more than '//str(max_lines)//' lines', stat_input)
               return
            end if
            nlines = nlines + 1
            lines(nlines) = ''
            column = 0
         end if
         if (c == 10) then
            column = -1
            cycle
         end if
         if (c == 13) then
            if (i < len(bytes)) then
               if (ichar(bytes(i + 1:i + 1)) == 10) cycle
            end if
            call fatal_error(error, path//': line '//str(nlines)//', column '//str(column + 1)// &
                             ': carriage return without line feed (old Mac line ends?); save the file with '// &
                             'LF or CR LF line ends', stat_input)
            return
         end if
         if (c == 9) c = 32
         if (c < 32 .or. c > 126) then
            call fatal_error(error, path//': line '//str(nlines)//', column '//str(column + 1)// &
                             ': byte '//str(c)//' is not printable text (a namelist is plain ASCII)', stat_input)
            return
         end if
         column = column + 1
         if (column > line_len) then
            call fatal_error(error, path//': line '//str(nlines)//' is longer than '//str(line_len)// &
                             ' characters', stat_input)
            return
         end if
         lines(nlines)(column:column) = achar(c)
      end do
   end subroutine load_lines

   !> Locate the groups, refuse unknown, duplicated and unterminated ones, and
   !> check each assignment's variable name and value type.
   subroutine scan_groups(path, lines, t, group_names, present_group, counts, error)
      !> Namelist file (for messages).
      character(*), intent(in) :: path
      !> Its lines.
      character(len=*), intent(in) :: lines(:)
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> The groups of the schema.
      character(len=16), intent(in) :: group_names(:)
      !> Which groups the file has.
      logical, intent(out) :: present_group(:)
      !> For each entry of the schema, its highest element assigned (0: not given).
      integer, intent(out) :: counts(:)
      !> Error naming the file, the line or group, and the variable.
      type(error_type), allocatable, intent(out) :: error
      ! The group's text is gathered in a buffer as long as the file (appending to a
      ! deferred-length string character by character is quadratic in a long table).
      character(:), allocatable :: text, group
      integer :: i, j, start_line, ig, nt
      logical :: in_group, in_quote
      character :: quote, ch

      present_group = .false.
      counts = 0
      in_group = .false.
      in_quote = .false.
      quote = ' '
      allocate (character(len=sum(len_trim(lines)) + size(lines)) :: text)
      nt = 0
      group = ''
      start_line = 0
      do i = 1, size(lines)
         j = 0
         do while (j < len_trim(lines(i)))
            j = j + 1
            ch = lines(i)(j:j)
            if (in_quote) then
               if (ch == quote) in_quote = .false.
               if (in_group) call append(ch)
               cycle
            end if
            if (ch == '!') exit
            if (.not. in_group) then
               if (ch == ' ') cycle
               if (ch /= '&') then
                  call fatal_error(error, path//': line '//str(i)//': "'//trim(adjustl(lines(i)))// &
                                   '" is outside any namelist group (a group starts with &name and ends with /)', &
                                   stat_input)
                  return
               end if
               group = word_at(lines(i), j + 1)
               if (len(group) == 0) then
                  call fatal_error(error, path//': line '//str(i)//': "&" without a group name; allowed: '// &
                                   join_names(group_names, '&'), stat_input)
                  return
               end if
               ig = findloc_name(group_names, group)
               if (ig == 0) then
                  call fatal_error(error, path//': line '//str(i)//': unknown group &'//group// &
                                   '; allowed: '//join_names(group_names, '&'), stat_input)
                  return
               end if
               if (present_group(ig)) then
                  call fatal_error(error, path//': line '//str(i)//': group &'//group// &
                                   ' appears twice; give each group once', stat_input)
                  return
               end if
               present_group(ig) = .true.
               in_group = .true.
               start_line = i
               nt = 0
               j = j + len(group)
               cycle
            end if
            if (ch == '&') then
               call fatal_error(error, path//': group &'//group//' (line '//str(start_line)// &
                                ') has no closing "/" before line '//str(i), stat_input)
               return
            end if
            if (ch == '/') then
               call check_assignments(path, t, group, text(1:nt), counts, error)
               if (allocated(error)) return
               in_group = .false.
               cycle
            end if
            if (ch == '"' .or. ch == "'") then
               in_quote = .true.
               quote = ch
            end if
            call append(ch)
         end do
         if (in_group) call append(' ')
      end do
      if (in_group) then
         call fatal_error(error, path//': group &'//group//' (line '//str(start_line)// &
                          ') has no closing "/" before the end of the file', stat_input)
         return
      end if
      if (.not. any(present_group)) then
         call fatal_error(error, path//': no namelist group found; expected some of '// &
                          join_names(group_names, '&'), stat_input)
      end if

   contains

      subroutine append(c)
         character, intent(in) :: c
         nt = nt + 1
         text(nt:nt) = c
      end subroutine append
   end subroutine scan_groups

   !> Check the names and value types of the assignments of one group, and
   !> record the highest element each assignment gives.
   subroutine check_assignments(path, t, group, text, counts, error)
      !> Namelist file (for messages).
      character(*), intent(in) :: path
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Group, and the text between its name and its closing '/'.
      character(*), intent(in) :: group, text
      !> For each entry, its highest element assigned; updated.
      integer, intent(inout) :: counts(:)
      !> Error naming the file, the group and the variable.
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: eq(:), mine(:)
      integer :: neq, i, j, name_start, name_end, value_end, iv, capacity, first, count
      character(:), allocatable :: name, value, subscript
      logical :: in_quote
      character :: quote

      mine = group_entries(t, group)
      ! Positions of '=' outside quotes.
      allocate (eq(len(text)))
      neq = 0
      in_quote = .false.
      quote = ' '
      do i = 1, len(text)
         if (in_quote) then
            if (text(i:i) == quote) in_quote = .false.
         else if (text(i:i) == '"' .or. text(i:i) == "'") then
            in_quote = .true.
            quote = text(i:i)
         else if (text(i:i) == '=') then
            neq = neq + 1
            eq(neq) = i
         end if
      end do
      if (neq == 0 .and. len_trim(text) > 0) then
         call fatal_error(error, path//': &'//group//': "'//shown(trim(adjustl(text)))// &
                          '" is not an assignment (expected variable = value)', stat_input)
         return
      end if
      if (neq > 0) then
         if (len_trim(text(1:eq(1) - 1)) == 0) then
            call fatal_error(error, path//': &'//group//': "=" without a variable name', stat_input)
            return
         end if
      end if
      do j = 1, neq
         call name_before(text, eq(j), name_start, name_end)
         name = to_lower(text(name_start:name_end))
         if (j == 1) then
            if (len_trim(text(1:name_start - 1)) > 0) then
               call fatal_error(error, path//': &'//group//': unexpected "'// &
                                shown(trim(adjustl(text(1:name_start - 1))))//'" before '//name, stat_input)
               return
            end if
         end if
         subscript = ''
         if (index(name, '(') > 0) then
            subscript = name(index(name, '('):)
            name = name(1:index(name, '(') - 1)
         end if
         iv = 0
         if (len(name) > 0) iv = find_entry(t, group, name)
         if (iv == 0) then
            call fatal_error(error, path//': &'//group//': unknown variable "'//text(name_start:name_end)// &
                             '"; allowed: '//join_names(t(mine)%name, ''), stat_input)
            return
         end if
         call check_subscript(path, group, name, subscript, t(iv)%count, first, capacity, error)
         if (allocated(error)) return
         if (j < neq) then
            call name_before(text, eq(j + 1), value_end, i)
            value_end = value_end - 1
         else
            value_end = len(text)
         end if
         value = trim(adjustl(text(eq(j) + 1:value_end)))
         do while (len(value) > 0)
            if (value(len(value):len(value)) /= ',') exit
            value = trim(value(1:len(value) - 1))
         end do
         call check_value(path, group, name//subscript, value, t(iv)%type, capacity, t(iv)%length, count, error)
         if (allocated(error)) return
         counts(iv) = max(counts(iv), first - 1 + count)
      end do
   end subroutine check_assignments

   !> Check the subscript of an assignment, '' or '(i)' or '(i:j)', against the
   !> variable's size and give the number of values it can take. gfortran
   !> itself reports a bad subscript as "Index 1 out of range" whatever the index.
   subroutine check_subscript(path, group, name, subscript, size, first, capacity, error)
      !> Namelist file, group, variable and its subscript ('' if none), for messages.
      character(*), intent(in) :: path, group, name, subscript
      !> Number of elements of the variable (1: a scalar).
      integer, intent(in) :: size
      !> First element assigned.
      integer, intent(out) :: first
      !> Number of values the assignment can take.
      integer, intent(out) :: capacity
      !> Error naming the variable and the subscripts allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: inside
      integer :: colon, last, ios
      capacity = size
      first = 1
      if (len(subscript) == 0) return
      if (size == 1) then
         call fatal_error(error, path//': &'//group//': '//name//subscript//': '//name// &
                          ' is a single value; write it without a subscript', stat_input)
         return
      end if
      inside = ''
      if (subscript(len(subscript):len(subscript)) == ')') inside = subscript(2:len(subscript) - 1)
      colon = index(inside, ':')
      last = size
      ios = merge(1, 0, len_trim(inside) == 0 .or. verify(inside, '0123456789: ') > 0)
      if (ios == 0 .and. colon == 0) then
         read (inside, *, iostat=ios) first
      else if (ios == 0) then
         if (len_trim(inside(1:colon - 1)) > 0) read (inside(1:colon - 1), *, iostat=ios) first
         if (ios == 0 .and. len_trim(inside(colon + 1:)) > 0) read (inside(colon + 1:), *, iostat=ios) last
      end if
      if (ios /= 0 .or. first < 1 .or. last > size .or. first > last) then
         call fatal_error(error, path//': &'//group//': '//name//subscript//': the subscript must be an index '// &
                          'from 1 to '//str(size)//' (or a range i:j within it)', stat_input)
         return
      end if
      capacity = size - first + 1
      if (colon > 0) capacity = last - first + 1
   end subroutine check_subscript

   !> Start and end of the variable name (with an optional subscript) before position ieq.
   subroutine name_before(text, ieq, name_start, name_end)
      !> Text of a group.
      character(*), intent(in) :: text
      !> Position of an '='.
      integer, intent(in) :: ieq
      !> Where the name starts and ends.
      integer, intent(out) :: name_start, name_end
      integer :: i, depth
      i = ieq - 1
      do while (i >= 1)
         if (text(i:i) /= ' ') exit
         i = i - 1
      end do
      name_end = i
      depth = 0
      do while (i >= 1)
         if (text(i:i) == ')') depth = depth + 1
         if (text(i:i) == '(') depth = depth - 1
         if (depth == 0 .and. .not. is_name_char(text(i:i)) .and. text(i:i) /= '(' .and. text(i:i) /= ')') exit
         if (depth > 0 .and. .not. (is_name_char(text(i:i)) .or. index('():, ', text(i:i)) > 0)) exit
         i = i - 1
      end do
      name_start = i + 1
      if (name_start > name_end) name_start = name_end
   end subroutine name_before

   !> Check that a value text has the variable's type (real, integer, logical
   !> or string). A numeric value list may use repeat counts r*v; the number of
   !> values it gives must fit the variable (gfortran says only "Cannot match
   !> namelist object name" or "Repeat count too large"), and a string must fit
   !> its variable (gfortran cuts it silently).
   subroutine check_value(path, group, name, value, type, capacity, max_length, count, error)
      !> Namelist file, group and variable (with its subscript), for messages.
      character(*), intent(in) :: path, group, name
      !> The value text, without the trailing comma.
      character(*), intent(in) :: value
      !> 'real', 'integer', 'logical' or 'string'.
      character(*), intent(in) :: type
      !> Number of values the assignment can take.
      integer, intent(in) :: capacity
      !> Length of a string variable.
      integer, intent(in) :: max_length
      !> Number of values given (repeat counts included).
      integer, intent(out) :: count
      !> Error naming the variable, its value and the type expected.
      type(error_type), allocatable, intent(out) :: error
      integer :: pos, ios, ival, star, repeat
      character(:), allocatable :: item, what
      real(dp) :: rval
      logical :: lval
      count = 0
      if (len(value) == 0) then
         call fatal_error(error, path//': &'//group//': '//name//' has no value', stat_input)
         return
      end if
      select case (type)
      case ('real')
         what = 'a finite real number'
      case ('integer')
         what = 'an integer'
      case ('logical')
         what = '.true. or .false.'
      case default
         what = 'a quoted string'
      end select
      if (type == 'string') then
         count = 1
         if (.not. (value(1:1) == "'" .or. value(1:1) == '"') .or. len(value) < 2 .or. &
             value(len(value):len(value)) /= value(1:1)) then
            call fatal_error(error, path//': &'//group//': '//name//' = '//shown(value)//': must be '//what, stat_input)
         else if (len(value) - 2 > max_length) then
            call fatal_error(error, path//': &'//group//': '//name//' = '//value(1:min(len(value), 40))// &
                             '...: is '//str(len(value) - 2)//' characters long; at most '//str(max_length)// &
                             ' are allowed', stat_input)
         end if
         return
      end if
      pos = 1
      do
         call next_item(value, pos, item)
         if (len(item) == 0) exit
         star = index(item, '*')
         repeat = 1
         if (star > 0) then
            ! r*v: r a positive integer, v a value or nothing (r null values).
            ios = merge(1, 0, star == 1 .or. verify(item(1:max(star - 1, 1)), '0123456789') > 0)
            if (ios == 0) read (item(1:star - 1), *, iostat=ios) repeat
            if (ios /= 0 .or. repeat < 1) then
               call fatal_error(error, path//': &'//group//': '//name//' = '//shown(value)//': "'//shown(item)// &
                                '" is not a repeat count r*value with r a positive integer', stat_input)
               return
            end if
            item = item(star + 1:)
         end if
         if (repeat > capacity - count) then
            if (capacity == 1) then
               call fatal_error(error, path//': &'//group//': '//name//' = '//shown(value)//': too many values; '// &
                                name//' takes one value', stat_input)
            else
               call fatal_error(error, path//': &'//group//': '//name//' = '//shown(value)//': too many values; '// &
                                name//' takes at most '//str(capacity), stat_input)
            end if
            return
         end if
         count = count + repeat
         if (len(item) == 0) cycle
         select case (type)
         case ('real')
            read (item, *, iostat=ios) rval
            if (ios == 0) then
               if (.not. ieee_is_finite(rval)) ios = 1
            end if
            if (ios == 0 .and. verify(item, '0123456789+-.eEdD') > 0) ios = 1
         case ('integer')
            read (item, *, iostat=ios) ival
            if (ios == 0 .and. verify(item, '0123456789+-') > 0) ios = 1
         case ('logical')
            read (item, *, iostat=ios) lval
            if (ios == 0 .and. index('.tf', to_lower(item(1:1))) == 0) ios = 1
         end select
         if (ios /= 0) then
            call fatal_error(error, path//': &'//group//': '//name//' = '//shown(value)//': "'//shown(item)// &
                             '" is not '//what, stat_input)
            return
         end if
      end do
      if (count == 0) call fatal_error(error, path//': &'//group//': '//name//' has no value', stat_input)
   end subroutine check_value

   !> The next item of a list separated by commas and blanks, from position
   !> pos on ('' when none is left); pos moves past it.
   subroutine next_item(text, pos, item)
      !> The list.
      character(*), intent(in) :: text
      !> Where to start; on return, where the next search starts.
      integer, intent(inout) :: pos
      !> The item.
      character(:), allocatable, intent(out) :: item
      integer :: start
      do while (pos <= len(text))
         if (text(pos:pos) /= ',' .and. text(pos:pos) /= ' ') exit
         pos = pos + 1
      end do
      start = pos
      do while (pos <= len(text))
         if (text(pos:pos) == ',' .or. text(pos:pos) == ' ') exit
         pos = pos + 1
      end do
      item = text(start:pos - 1)
   end subroutine next_item

   !> A value for a message: cut after shown_length characters.
   pure function shown(value) result(s)
      !> The value text.
      character(*), intent(in) :: value
      character(:), allocatable :: s
      if (len(value) > shown_length) then
         s = value(1:shown_length)//'...'
      else
         s = value
      end if
   end function shown

   !> Read the groups that are present with the compiler's namelist input.
   !> The namelist statements here are the compile-time copy of the schema's
   !> variable lists (the suite input checks them against the schema).
   subroutine read_groups(path, c, group_names, present_group, error)
      !> Namelist file.
      character(*), intent(in) :: path
      !> The case: defaults in, values given out.
      type(case_config), intent(inout) :: c
      !> The groups of the schema.
      character(len=16), intent(in) :: group_names(:)
      !> Which groups the file has.
      logical, intent(in) :: present_group(:)
      !> Error naming the group.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: length, diameter, density, young, gravity, area, bending_stiffness, gip
      character(len=16) :: law, compression, scheme, mass_matrix, model, criterion
      real(dp) :: p(5), ea, strain_max, tension, s_break, t_break, time, dt, courant, t_end, theta, newton_tol
      real(dp) :: min_step_fraction, max_wall_time, interval, damping, checkpoint_interval, mbl
      real(dp) :: table_strain(max_table_points), table_tension(max_table_points)
      integer :: nodes, newton_max_iter
      logical :: enabled, reuse_jacobian, extrapolate, skip_quiescent, quiet, energy, gnuplot, xdmf
      character(len=512) :: file, table_file
      character(len=256) :: fields
      namelist /cable/ length, diameter, density, young, gravity, area, bending_stiffness, gip
      namelist /material/ law, p, ea, table_strain, table_tension, table_file, strain_max, compression, damping
      namelist /static/ tension
      namelist /rupture/ enabled, s_break, t_break, time, criterion, mbl
      namelist /numerics/ scheme, model, nodes, dt, courant, t_end, theta, mass_matrix, newton_tol, newton_max_iter, &
         reuse_jacobian, extrapolate, min_step_fraction, max_wall_time, skip_quiescent
      namelist /output/ file, interval, fields, quiet, energy, gnuplot, xdmf, checkpoint_interval
      integer :: unit, ios, ig
      character(len=512) :: msg

      length = c%length; diameter = c%diameter; density = c%density; young = c%young
      gravity = c%gravity; area = c%area; bending_stiffness = c%bending_stiffness; gip = c%gip
      law = c%law; p = c%p; ea = c%ea; strain_max = c%strain_max; compression = c%compression
      table_strain = c%material_table_strain; table_tension = c%material_table_tension
      table_file = c%material_table_file; damping = c%damping
      tension = c%tension
      enabled = c%break_enabled; s_break = c%s_break; t_break = c%t_break; time = c%break_time
      criterion = c%break_criterion; mbl = c%mbl
      scheme = c%scheme; model = c%model; nodes = c%nodes; dt = c%dt; courant = c%courant; t_end = c%t_end; theta = c%theta
      mass_matrix = c%mass_matrix; newton_tol = c%newton_tol; newton_max_iter = c%newton_max_iter
      reuse_jacobian = c%reuse_jacobian; extrapolate = c%extrapolate; min_step_fraction = c%min_step_fraction
      max_wall_time = c%max_wall_time; skip_quiescent = c%skip_quiescent
      file = c%file; interval = c%interval; fields = c%fields; quiet = c%quiet; energy = c%energy
      gnuplot = c%gnuplot; xdmf = c%xdmf; checkpoint_interval = c%checkpoint_interval

      open (newunit=unit, file=path, status='old', action='read', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, path//': cannot open: '//trim(msg), stat_input)
         return
      end if
      do ig = 1, size(group_names)
         if (.not. present_group(ig)) cycle
         rewind (unit)
         select case (trim(group_names(ig)))
         case ('cable')
            read (unit, nml=cable, iostat=ios, iomsg=msg)
         case ('material')
            read (unit, nml=material, iostat=ios, iomsg=msg)
         case ('static')
            read (unit, nml=static, iostat=ios, iomsg=msg)
         case ('end_a')
            call read_end(unit, 'end_a', c%end_a, ios, msg)
         case ('end_b')
            call read_end(unit, 'end_b', c%end_b, ios, msg)
         case ('fluid')
            call read_fluid(unit, c, ios, msg)
         case ('rupture')
            read (unit, nml=rupture, iostat=ios, iomsg=msg)
         case ('numerics')
            read (unit, nml=numerics, iostat=ios, iomsg=msg)
         case ('output')
            read (unit, nml=output, iostat=ios, iomsg=msg)
         case default
            ios = 1
            msg = 'no namelist read for this group (a schema group missing in read_groups)'
         end select
         if (ios /= 0) then
            call fatal_error(error, path//': &'//trim(group_names(ig))//': cannot be read: '//trim(msg), stat_input)
            close (unit)
            return
         end if
      end do
      close (unit)

      c%length = length; c%diameter = diameter; c%density = density; c%young = young
      c%gravity = gravity; c%area = area; c%bending_stiffness = bending_stiffness; c%gip = gip
      c%law = law; c%p = p; c%ea = ea; c%strain_max = strain_max; c%compression = compression
      c%material_table_strain = table_strain; c%material_table_tension = table_tension
      c%material_table_file = table_file; c%damping = damping
      c%tension = tension
      c%break_enabled = enabled; c%s_break = s_break; c%t_break = t_break; c%break_time = time
      c%break_criterion = criterion; c%mbl = mbl
      c%scheme = scheme; c%model = model; c%nodes = nodes; c%dt = dt; c%courant = courant; c%t_end = t_end; c%theta = theta
      c%mass_matrix = mass_matrix; c%newton_tol = newton_tol; c%newton_max_iter = newton_max_iter
      c%reuse_jacobian = reuse_jacobian; c%extrapolate = extrapolate; c%min_step_fraction = min_step_fraction
      c%max_wall_time = max_wall_time; c%skip_quiescent = skip_quiescent
      c%file = file; c%interval = interval; c%fields = fields; c%quiet = quiet; c%energy = energy
      c%gnuplot = gnuplot; c%xdmf = xdmf; c%checkpoint_interval = checkpoint_interval
   end subroutine read_groups

   !> Read &end_a or &end_b (the same variables) into one end.
   subroutine read_end(unit, group, e, ios, msg)
      !> Open namelist file, rewound.
      integer, intent(in) :: unit
      !> 'end_a' or 'end_b'.
      character(*), intent(in) :: group
      !> The end: defaults in, values given out.
      type(end_config), intent(inout) :: e
      !> iostat of the read.
      integer, intent(out) :: ios
      !> iomsg of the read.
      character(len=*), intent(inout) :: msg
      character(len=16) :: kind, history, motion
      real(dp) :: x, z, force_x, force_z, ramp_time, amplitude, period, phase, direction_x, direction_z, mass
      real(dp) :: y, force_y, torque, direction_y, stiffness, damping, rest_length
      real(dp) :: table_time(max_table_points), table_x(max_table_points), table_z(max_table_points)
      real(dp) :: table_y(max_table_points)
      character(len=512) :: table_file
      namelist /end_a/ kind, x, y, z, force_x, force_y, force_z, torque, history, ramp_time, motion, amplitude, &
         period, phase, direction_x, direction_y, direction_z, mass, stiffness, damping, rest_length, table_time, &
         table_x, table_y, table_z, table_file
      namelist /end_b/ kind, x, y, z, force_x, force_y, force_z, torque, history, ramp_time, motion, amplitude, &
         period, phase, direction_x, direction_y, direction_z, mass, stiffness, damping, rest_length, table_time, &
         table_x, table_y, table_z, table_file

      kind = e%kind; x = e%x; z = e%z; force_x = e%force_x; force_z = e%force_z; history = e%history
      ramp_time = e%ramp_time; motion = e%motion; amplitude = e%amplitude; period = e%period; phase = e%phase
      direction_x = e%direction_x; direction_z = e%direction_z; mass = e%mass
      y = e%y; force_y = e%force_y; torque = e%torque; direction_y = e%direction_y
      stiffness = e%stiffness; damping = e%damping; rest_length = e%rest_length
      table_time = e%table_time; table_x = e%table_x; table_z = e%table_z; table_file = e%table_file
      table_y = e%table_y
      if (group == 'end_a') then
         read (unit, nml=end_a, iostat=ios, iomsg=msg)
      else
         read (unit, nml=end_b, iostat=ios, iomsg=msg)
      end if
      if (ios /= 0) return
      e%kind = kind; e%x = x; e%z = z; e%force_x = force_x; e%force_z = force_z; e%history = history
      e%ramp_time = ramp_time; e%motion = motion; e%amplitude = amplitude; e%period = period; e%phase = phase
      e%direction_x = direction_x; e%direction_z = direction_z; e%mass = mass
      e%y = y; e%force_y = force_y; e%torque = torque; e%direction_y = direction_y
      e%stiffness = stiffness; e%damping = damping; e%rest_length = rest_length
      e%table_time = table_time; e%table_x = table_x; e%table_z = table_z; e%table_file = table_file
      e%table_y = table_y
   end subroutine read_end

   !> Read &fluid (its density has the name of &cable's, so it has its own scope).
   subroutine read_fluid(unit, c, ios, msg)
      !> Open namelist file, rewound.
      integer, intent(in) :: unit
      !> The case: defaults in, values given out.
      type(case_config), intent(inout) :: c
      !> iostat of the read.
      integer, intent(out) :: ios
      !> iomsg of the read.
      character(len=*), intent(inout) :: msg
      real(dp) :: density, cd_normal, cd_tangential, ca_normal, current_x, current_y, current_z
      namelist /fluid/ density, cd_normal, cd_tangential, ca_normal, current_x, current_y, current_z
      density = c%fluid_density; cd_normal = c%cd_normal; cd_tangential = c%cd_tangential
      ca_normal = c%ca_normal; current_x = c%current_x; current_z = c%current_z; current_y = c%current_y
      read (unit, nml=fluid, iostat=ios, iomsg=msg)
      if (ios /= 0) return
      c%fluid_density = density; c%cd_normal = cd_normal; c%cd_tangential = cd_tangential
      c%ca_normal = ca_normal; c%current_x = current_x; c%current_z = current_z; c%current_y = current_y
   end subroutine read_fluid

   !> Get (store = .false.) or set (store = .true.) the value of a schema
   !> entry in a case: the one map from a namelist variable to its component
   !> of case_config for the generic code (validation, echo, tests).
   subroutine access(c, e, v, store)
      !> The case.
      type(case_config), intent(inout) :: c
      !> The variable.
      type(schema_entry), intent(in) :: e
      !> Its value; v%found is .false. for a variable this map does not know.
      type(config_value), intent(inout) :: v
      !> Whether to set the component from v.
      logical, intent(in) :: store
      v%found = .true.
      select case (e%group)
      case ('end_a')
         call access_end(c%end_a, e%name, v, store)
         return
      case ('end_b')
         call access_end(c%end_b, e%name, v, store)
         return
      end select
      select case (trim(e%group)//'%'//trim(e%name))
      case ('cable%length'); call move(c%length, v, store)
      case ('cable%diameter'); call move(c%diameter, v, store)
      case ('cable%density'); call move(c%density, v, store)
      case ('cable%young'); call move(c%young, v, store)
      case ('cable%gravity'); call move(c%gravity, v, store)
      case ('cable%area'); call move(c%area, v, store)
      case ('cable%bending_stiffness'); call move(c%bending_stiffness, v, store)
      case ('cable%gip'); call move(c%gip, v, store)
      case ('material%law'); call move(c%law, v, store)
      case ('material%p'); call move(c%p, v, store)
      case ('material%ea'); call move(c%ea, v, store)
      case ('material%strain_max'); call move(c%strain_max, v, store)
      case ('material%compression'); call move(c%compression, v, store)
      case ('material%table_strain'); call move_rows(c%material_table_strain, c%material_table_rows, v, store)
      case ('material%table_tension'); call move_rows(c%material_table_tension, c%material_table_rows, v, store)
      case ('material%table_file'); call move(c%material_table_file, v, store)
      case ('material%damping'); call move(c%damping, v, store)
      case ('fluid%density'); call move(c%fluid_density, v, store)
      case ('fluid%cd_normal'); call move(c%cd_normal, v, store)
      case ('fluid%cd_tangential'); call move(c%cd_tangential, v, store)
      case ('fluid%ca_normal'); call move(c%ca_normal, v, store)
      case ('fluid%current_x'); call move(c%current_x, v, store)
      case ('fluid%current_y'); call move(c%current_y, v, store)
      case ('fluid%current_z'); call move(c%current_z, v, store)
      case ('static%tension'); call move(c%tension, v, store)
      case ('rupture%enabled'); call move(c%break_enabled, v, store)
      case ('rupture%s_break'); call move(c%s_break, v, store)
      case ('rupture%t_break'); call move(c%t_break, v, store)
      case ('rupture%time'); call move(c%break_time, v, store)
      case ('rupture%criterion'); call move(c%break_criterion, v, store)
      case ('rupture%mbl'); call move(c%mbl, v, store)
      case ('numerics%scheme'); call move(c%scheme, v, store)
      case ('numerics%model'); call move(c%model, v, store)
      case ('numerics%nodes'); call move(c%nodes, v, store)
      case ('numerics%dt'); call move(c%dt, v, store)
      case ('numerics%courant'); call move(c%courant, v, store)
      case ('numerics%t_end'); call move(c%t_end, v, store)
      case ('numerics%theta'); call move(c%theta, v, store)
      case ('numerics%mass_matrix'); call move(c%mass_matrix, v, store)
      case ('numerics%newton_tol'); call move(c%newton_tol, v, store)
      case ('numerics%newton_max_iter'); call move(c%newton_max_iter, v, store)
      case ('numerics%reuse_jacobian'); call move(c%reuse_jacobian, v, store)
      case ('numerics%extrapolate'); call move(c%extrapolate, v, store)
      case ('numerics%skip_quiescent'); call move(c%skip_quiescent, v, store)
      case ('numerics%min_step_fraction'); call move(c%min_step_fraction, v, store)
      case ('numerics%max_wall_time'); call move(c%max_wall_time, v, store)
      case ('output%file'); call move(c%file, v, store)
      case ('output%interval'); call move(c%interval, v, store)
      case ('output%fields'); call move(c%fields, v, store)
      case ('output%quiet'); call move(c%quiet, v, store)
      case ('output%energy'); call move(c%energy, v, store)
      case ('output%gnuplot'); call move(c%gnuplot, v, store)
      case ('output%xdmf'); call move(c%xdmf, v, store)
      case ('output%checkpoint_interval'); call move(c%checkpoint_interval, v, store)
      case default
         v%found = .false.
      end select
   end subroutine access

   !> `access` for the variables of &end_a and &end_b.
   subroutine access_end(e, name, v, store)
      !> The end.
      type(end_config), intent(inout) :: e
      !> Variable name.
      character(*), intent(in) :: name
      !> Its value.
      type(config_value), intent(inout) :: v
      !> Whether to set the component from v.
      logical, intent(in) :: store
      select case (name)
      case ('kind'); call move(e%kind, v, store)
      case ('x'); call move(e%x, v, store)
      case ('y'); call move(e%y, v, store)
      case ('z'); call move(e%z, v, store)
      case ('force_y'); call move(e%force_y, v, store)
      case ('torque'); call move(e%torque, v, store)
      case ('direction_y'); call move(e%direction_y, v, store)
      case ('force_x'); call move(e%force_x, v, store)
      case ('force_z'); call move(e%force_z, v, store)
      case ('history'); call move(e%history, v, store)
      case ('ramp_time'); call move(e%ramp_time, v, store)
      case ('motion'); call move(e%motion, v, store)
      case ('amplitude'); call move(e%amplitude, v, store)
      case ('period'); call move(e%period, v, store)
      case ('phase'); call move(e%phase, v, store)
      case ('direction_x'); call move(e%direction_x, v, store)
      case ('direction_z'); call move(e%direction_z, v, store)
      case ('mass'); call move(e%mass, v, store)
      case ('stiffness'); call move(e%stiffness, v, store)
      case ('damping'); call move(e%damping, v, store)
      case ('rest_length'); call move(e%rest_length, v, store)
      case ('table_time'); call move_rows(e%table_time, e%table_rows, v, store)
      case ('table_x'); call move_rows(e%table_x, e%table_rows, v, store)
      case ('table_y'); call move_rows(e%table_y, e%table_rows, v, store)
      case ('table_z'); call move_rows(e%table_z, e%table_rows, v, store)
      case ('table_file'); call move(e%table_file, v, store)
      case default
         v%found = .false.
      end select
   end subroutine access_end

   !> A real scalar.
   subroutine move_real(x, v, store)
      !> Component.
      real(dp), intent(inout) :: x
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set x from v.
      logical, intent(in) :: store
      if (store) then
         x = v%reals(1)
      else
         v%reals = [x]
      end if
   end subroutine move_real

   !> A real array.
   subroutine move_reals(x, v, store)
      !> Component.
      real(dp), intent(inout) :: x(:)
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set x from v.
      logical, intent(in) :: store
      if (store) then
         x(1:size(v%reals)) = v%reals
      else
         v%reals = x
      end if
   end subroutine move_reals

   !> A table column: its first rows elements (a store sets the elements given, not rows).
   subroutine move_rows(x, rows, v, store)
      !> Column.
      real(dp), intent(inout) :: x(:)
      !> Rows of the table.
      integer, intent(in) :: rows
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set x from v.
      logical, intent(in) :: store
      if (store) then
         x(1:size(v%reals)) = v%reals
      else
         v%reals = x(1:rows)
      end if
   end subroutine move_rows

   !> An integer.
   subroutine move_integer(i, v, store)
      !> Component.
      integer, intent(inout) :: i
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set i from v.
      logical, intent(in) :: store
      if (store) then
         i = v%int
      else
         v%int = i
      end if
   end subroutine move_integer

   !> A logical.
   subroutine move_logical(l, v, store)
      !> Component.
      logical, intent(inout) :: l
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set l from v.
      logical, intent(in) :: store
      if (store) then
         l = v%flag
      else
         v%flag = l
      end if
   end subroutine move_logical

   !> A string.
   subroutine move_string(s, v, store)
      !> Component.
      character(*), intent(inout) :: s
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set s from v.
      logical, intent(in) :: store
      if (store) then
         s = v%text
      else
         v%text = trim(s)
      end if
   end subroutine move_string

   !> The value of an entry in a case.
   function get_value(c, e) result(v)
      !> The case.
      type(case_config), intent(in) :: c
      !> The variable.
      type(schema_entry), intent(in) :: e
      type(config_value) :: v
      type(case_config) :: copy
      copy = c
      call access(copy, e, v, .false.)
   end function get_value

   !> The values whose 0 means "derived from others": the area from the
   !> diameter, EI from young and the diameter, EA of the linear law from young
   !> and the area; and a negative s_break, the end b (s = L). Called by
   !> validate and by setup_case, so that a case built in code (tests,
   !> examples) gets them as a namelist does.
   pure subroutine derive_defaults(c)
      !> Case; derived values replace zeros.
      type(case_config), intent(inout) :: c
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (c%area == 0) c%area = 0.25_dp*pi*c%diameter**2
      if (c%bending_stiffness == 0) c%bending_stiffness = c%young*pi*c%diameter**4/64
      if (c%gip == 0) c%gip = c%bending_stiffness/(1 + default_poisson)
      if (c%law == 'linear' .and. c%ea == 0) c%ea = c%young*c%area
      if (c%s_break < 0) c%s_break = c%length
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
      ! The law first: its table file is read only for law = 'table' (checked after the ranges).
      call check_entry(c, t(find_entry(t, 'material', 'law')), error)
      if (allocated(error)) return
      if (c%law == 'table') then
         call load_material_table(c, error)
         if (allocated(error)) return
      end if
      do i = 1, size(t)
         call check_entry(c, t(i), error)
         if (allocated(error)) return
      end do
      call check_material_table(c, error)
      if (allocated(error)) return
      ! Lower bounds (issue 6, bad-input fuzzing): a value that is positive but
      ! tiny (1e-300) passed "> 0" and gave a zero mass, an infinite wave
      ! speed, a zero step or a singular Jacobian; the schema's ranges are
      ! generous physical ones. The tanh law's coefficients have ranges of
      ! their own.
      if (c%law == 'tanh') then
         call coefficient(1, 0.0_dp, 1.0e12_dp, .true.); if (allocated(error)) return
         call coefficient(2, 0.0_dp, 1.0e6_dp, .true.); if (allocated(error)) return
         call coefficient(3, -1.0e3_dp, 1.0e3_dp, .false.); if (allocated(error)) return
         call coefficient(5, 0.0_dp, 1.0e12_dp, .true.); if (allocated(error)) return
      end if
      ! An EI given is in range (above); one derived from young and d may not be:
      ! EI far below 1e-6 N m^2 leaves the moment balance empty at double precision.
      if (c%bending_stiffness == 0 .and. c%young*pi*c%diameter**4/64 < 1.0e-6_dp) then
         call fatal_error(error, c%source//': &cable: young = '//real_text(c%young)//', diameter = '// &
                          real_text(c%diameter)//': give a bending stiffness E pi d^4 / 64 = '// &
                          str(c%young*pi*c%diameter**4/64)//' N m^2, below 1e-6; set bending_stiffness', stat_input)
         return
      end if
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
            call fatal_error(error, c%source//': &material: p('//str(k)//') = '//real_text(c%p(k))// &
                             ': must be > '//real_text(lower)//' and <= '//real_text(upper)//' for the tanh law', &
                             stat_input)
         else
            if (c%p(k) >= lower .and. c%p(k) <= upper) return
            call fatal_error(error, c%source//': &material: p('//str(k)//') = '//real_text(c%p(k))// &
                             ': must be in ['//real_text(lower)//', '//real_text(upper)//'] for the tanh law', stat_input)
         end if
      end subroutine coefficient
   end subroutine validate

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
         if (e%type == 'integer') v%reals = [real(v%int, dp)]
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
               item = str(v%int)
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

   !> Whether word is one of the blank-separated words.
   pure logical function is_word(word, words)
      !> Word.
      character(*), intent(in) :: word
      !> Blank-separated words.
      character(*), intent(in) :: words
      is_word = len_trim(word) > 0 .and. index(' '//trim(words)//' ', ' '//trim(word)//' ') > 0
   end function is_word

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
      if (c%fluid_density == 0 .and. (c%cd_normal /= 0 .or. c%cd_tangential /= 0 .or. c%ca_normal /= 0)) then
         call fatal_error(error, c%source//': &fluid: drag or added-mass coefficients without a fluid (density = 0); '// &
                          'give &fluid density (> 0: 1025 for sea water, 1.2 for air)', stat_input)
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
         if (.not. c%is_given('rupture', 'mbl') .or. c%mbl <= 0) then
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
   end subroutine check_scene

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

   !> Read an end's table_file, if given, into its table: two, three or four
   !> numbers a line (t, x; t, x, z; or t, x, y, z; y and z are 0 when absent),
   !> the times strictly increasing.
   subroutine load_table(c, group, e, error)
      !> The case (for its source).
      type(case_config), intent(in) :: c
      !> 'end_a' or 'end_b'.
      character(*), intent(in) :: group
      !> The end; its table and table_rows are filled from the file.
      type(end_config), intent(inout) :: e
      !> Error naming the case file, the group, the table file and its line.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: values(:, :)
      integer, allocatable :: lines(:)
      character(:), allocatable :: prefix
      integer :: rows, columns

      if (len_trim(e%table_file) == 0) return
      prefix = c%source//': &'//group//": table_file = '"//trim(e%table_file)//"': "
      call read_table_file(prefix, trim(e%table_file), 'table_time', e%table_rows, 2, 4, &
                           't, x; t, x, z; or t, x, y, z', values, lines, rows, error, columns)
      if (allocated(error)) return
      call check_column(prefix, 'time', values(1:rows, 1), time_order, error, lines(1:rows))
      if (allocated(error)) return
      e%table_time(1:rows) = values(1:rows, 1)
      e%table_x(1:rows) = values(1:rows, 2)
      if (columns == 4) then
         e%table_y(1:rows) = values(1:rows, 3)
         e%table_z(1:rows) = values(1:rows, 4)
      else
         e%table_z(1:rows) = values(1:rows, 3)
      end if
      e%table_rows = rows
   end subroutine load_table

   !> Read the material's table_file, if given, into the rows of the table
   !> law: two numbers a line (strain and tension), both strictly increasing.
   subroutine load_material_table(c, error)
      !> The case; material_table_strain, material_table_tension and material_table_rows filled from the file.
      type(case_config), intent(inout) :: c
      !> Error naming the case file, the table file and its line.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: values(:, :)
      integer, allocatable :: lines(:)
      character(:), allocatable :: prefix
      integer :: rows

      if (len_trim(c%material_table_file) == 0) return
      prefix = c%source//": &material: table_file = '"//trim(c%material_table_file)//"': "
      call read_table_file(prefix, trim(c%material_table_file), 'table_strain', c%material_table_rows, 2, 2, &
                           'strain and tension', values, lines, rows, error)
      if (allocated(error)) return
      call check_column(prefix, 'strain', values(1:rows, 1), strain_order, error, lines(1:rows))
      if (allocated(error)) return
      call check_column(prefix, 'tension', values(1:rows, 2), tension_order, error, lines(1:rows))
      if (allocated(error)) return
      c%material_table_strain(1:rows) = values(1:rows, 1)
      c%material_table_tension(1:rows) = values(1:rows, 2)
      c%material_table_rows = rows
   end subroutine load_material_table

   !> Read a table file (of an end or of the material): min_columns to
   !> size(values, 2) numbers a line, the same number on every line, '#'
   !> starts a comment, blank lines are skipped; at least 2 and at most
   !> max_table_points rows. A file given together with inline rows is refused.
   subroutine read_table_file(prefix, file, first_column, inline_rows, min_columns, max_columns, layout, values, &
                              lines, rows, error, ncolumns)
      !> Start of every message: the case file, the group and the table_file.
      character(*), intent(in) :: prefix
      !> The table file (relative to the working directory).
      character(*), intent(in) :: file
      !> Name of the first inline column (for the message on inline rows and a file together).
      character(*), intent(in) :: first_column
      !> Number of rows given inline.
      integer, intent(in) :: inline_rows
      !> Fewest and most numbers a line.
      integer, intent(in) :: min_columns, max_columns
      !> What the columns are, for messages ('strain and tension').
      character(*), intent(in) :: layout
      !> The rows (max_table_points by max_columns); columns a line does not give are 0.
      real(dp), allocatable, intent(out) :: values(:, :)
      !> The line of the file each row is on.
      integer, allocatable, intent(out) :: lines(:)
      !> Number of rows read.
      integer, intent(out) :: rows
      !> Error naming the table file and the line at fault.
      type(error_type), allocatable, intent(out) :: error
      !> Numbers a line of the file.
      integer, intent(out), optional :: ncolumns
      character(len=line_len), allocatable :: text_lines(:)
      character(:), allocatable :: text, item, expected
      real(dp) :: x
      integer :: nlines, i, pos, n, columns, ios
      logical :: exists

      allocate (values(max_table_points, max_columns), lines(max_table_points))
      values = 0
      lines = 0
      rows = 0
      if (inline_rows > 0) then
         call fatal_error(error, prefix//'given together with the inline table ('//first_column//', '// &
                          rows_text(inline_rows)//'); give one', stat_input)
         return
      end if
      inquire (file=file, exist=exists)
      if (.not. exists) then
         call fatal_error(error, prefix//'no such file (the path is relative to the working directory)', stat_input)
         return
      end if
      call load_lines(file, text_lines, nlines, error)
      if (allocated(error)) then
         error%message = prefix//error%message
         return
      end if
      expected = str(min_columns)
      do n = min_columns + 1, max_columns - 1
         expected = expected//', '//str(n)
      end do
      if (max_columns > min_columns) expected = expected//' or '//str(max_columns)
      columns = 0
      if (present(ncolumns)) ncolumns = 0
      do i = 1, nlines
         text = text_lines(i)
         if (index(text, '#') > 0) text = text(1:index(text, '#') - 1)
         n = 0
         pos = 1
         do
            call next_item(text, pos, item)
            if (len(item) == 0) exit
            n = n + 1
            if (n > max_columns) cycle
            read (item, *, iostat=ios) x
            if (ios == 0) then
               if (.not. ieee_is_finite(x)) ios = 1
            end if
            if (ios == 0 .and. verify(item, '0123456789+-.eEdD') > 0) ios = 1
            if (ios /= 0) then
               call fatal_error(error, prefix//'line '//str(i)//': "'//shown(trim(text_lines(i)))//'": "'// &
                                shown(item)//'" is not a finite real number', stat_input)
               return
            end if
            if (rows < max_table_points) values(rows + 1, n) = x
         end do
         if (n == 0) cycle
         if (n < min_columns .or. n > max_columns) then
            call fatal_error(error, prefix//'line '//str(i)//': "'//shown(trim(text_lines(i)))//'": expected '// &
                             expected//' numbers ('//layout//')', stat_input)
            return
         end if
         if (columns == 0) columns = n
         if (n /= columns) then
            call fatal_error(error, prefix//'line '//str(i)//': "'//shown(trim(text_lines(i)))//'": '//str(n)// &
                             ' numbers, but the lines before have '//str(columns), stat_input)
            return
         end if
         if (rows == max_table_points) then
            call fatal_error(error, prefix//'line '//str(i)//': more than '//str(max_table_points)//' rows', stat_input)
            return
         end if
         rows = rows + 1
         lines(rows) = i
      end do
      if (rows < 2) then
         call fatal_error(error, prefix//'has '//rows_text(rows)//'; a table must have at least 2', stat_input)
         return
      end if
      if (present(ncolumns)) ncolumns = columns
   end subroutine read_table_file

   !> Error unless a table column has at least 2 rows and increases strictly,
   !> naming the first value that does not: as name(k) = value for an inline
   !> column, or by its line for a column read from a table file (lines given).
   subroutine check_column(prefix, name, x, reason, error, lines)
      !> Start of the message: the case file and the group (and the table_file).
      character(*), intent(in) :: prefix
      !> The column: its variable ('table_time'), or with lines what it holds ('time').
      character(*), intent(in) :: name
      !> Its rows.
      real(dp), intent(in) :: x(:)
      !> Why the order matters, ending the message ('the times must increase strictly').
      character(*), intent(in) :: reason
      !> Error naming the row or line at fault.
      type(error_type), allocatable, intent(out) :: error
      !> The line of the table file each row is on.
      integer, intent(in), optional :: lines(:)
      character(:), allocatable :: what
      integer :: k
      if (size(x) == 1) then
         call fatal_error(error, prefix//name//' = '//real_text(x(1))//': the table has 1 row; it must have at '// &
                          'least 2', stat_input)
         return
      end if
      do k = 2, size(x)
         if (x(k) > x(k - 1)) cycle
         if (present(lines)) then
            what = 'line '//str(lines(k))//': '//name//' '//real_text(x(k))//' is not above the '//name// &
                   ' before, '//real_text(x(k - 1))
         else
            what = name//'('//str(k)//') = '//real_text(x(k))//': not above '//name//'('//str(k - 1)//') = '// &
                   real_text(x(k - 1))
         end if
         call fatal_error(error, prefix//what//'; '//reason, stat_input)
         return
      end do
   end subroutine check_column

   !> The rows of the table law: only for law = 'table', and there given
   !> (inline or from table_file), at least 2, with strains and tensions
   !> strictly increasing (a table_file is read into the rows before, by load_material_table).
   subroutine check_material_table(c, error)
      !> The case (law word and rows checked against the schema).
      type(case_config), intent(in) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: prefix, rows, law
      integer :: k, n
      prefix = c%source//': &material: '
      n = c%material_table_rows
      law = "law = '"//trim(c%law)//"'"
      if (c%law /= 'table') then
         if (n > 0) then
            rows = real_text(c%material_table_strain(1))
            do k = 2, n
               rows = rows//', '//real_text(c%material_table_strain(k))
               if (len(rows) > shown_length) exit
            end do
            call fatal_error(error, prefix//'table_strain = '//shown(rows)//': rows of the table law given for '// &
                             law//"; set law = 'table' or leave table_strain and table_tension out", stat_input)
         else if (len_trim(c%material_table_file) > 0) then
            call fatal_error(error, prefix//"table_file = '"//trim(c%material_table_file)//"': rows of the table "// &
                             'law given for '//law//"; set law = 'table' or leave table_file out", stat_input)
         end if
         return
      end if
      if (n == 0) then
         call fatal_error(error, prefix//law//' without a table: give table_strain and table_tension (at least '// &
                          '2 rows) or table_file', stat_input)
         return
      end if
      call check_column(prefix, 'table_strain', c%material_table_strain(1:n), strain_order, error)
      if (allocated(error)) return
      call check_column(prefix, 'table_tension', c%material_table_tension(1:n), tension_order, error)
   end subroutine check_material_table

   !> A number of rows as '1 row' or 'n rows'.
   function rows_text(n) result(s)
      !> Number of rows.
      integer, intent(in) :: n
      character(:), allocatable :: s
      s = str(n)//' rows'
      if (n == 1) s = '1 row'
   end function rows_text

   !> The resolved case as namelist text (for provenance in the output): every
   !> variable of the schema, group by group, except those that may not be
   !> given together with others (the tension or the position of end b, the
   !> positions of free, force and mass ends) and tables without rows; a
   !> table read from a file is written inline, the file named in a comment.
   !> Read back, it gives the same case (with the table inline, not from the file).
   !> With fingerprint, the variables that may differ between a run and its
   !> resume (schema: resume_may_differ) are left out: the text a checkpoint
   !> is checked against.
   function config_text(c, fingerprint) result(text)
      !> The case.
      type(case_config), intent(in) :: c
      !> Leave out what may differ on --resume (default: .false.).
      logical, intent(in), optional :: fingerprint
      character(:), allocatable :: text
      integer, parameter :: width = 100
      character(len=*), parameter :: nl = new_line('a')
      type(schema_entry), allocatable :: t(:)
      character(len=16), allocatable :: groups(:)
      integer, allocatable :: mine(:)
      type(config_value) :: v
      type(case_config) :: copy
      character(:), allocatable :: block, comment, line, sep, token
      integer :: ig, i, k, n
      logical :: skip_steering, position_b
      skip_steering = .false.
      if (present(fingerprint)) skip_steering = fingerprint
      ! One copy of the case for `access` (which takes it intent(inout) and only
      ! reads it here), not one per variable as get_value makes: those copies (the
      ! end tables) were 45 % of the instructions of config_text.
      copy = c
      position_b = given_position_b(c)
      t = schema_table()
      groups = schema_groups(t)
      text = ''
      do ig = 1, size(groups)
         mine = group_entries(t, groups(ig))
         block = ''
         comment = ''
         line = '&'//trim(groups(ig))
         sep = ' '
         do i = 1, size(mine)
            associate (e => t(mine(i)))
               if (.not. echoed(c, e, position_b)) cycle
               if (skip_steering .and. e%resume_may_differ) cycle
               call access(copy, e, v, .false.)
               if (e%name == 'table_file') then
                  comment = comment//"! &"//trim(e%group)//": the table was read from table_file = '"// &
                            v%text//"'"//nl
                  cycle
               end if
               n = 1
               if (e%type == 'real') n = size(v%reals)
               do k = 1, n
                  token = item_text(e, v, k)
                  if (k == 1) token = trim(e%name)//' = '//token
                  if (len(line) + len(sep) + len(token) > width) then
                     block = block//line//trim(sep)//nl
                     line = '   '//token
                  else
                     line = line//sep//token
                  end if
                  sep = ', '
               end do
            end associate
         end do
         ! A group with nothing to write (&static beside the end positions) is left out.
         if (sep == ' ') cycle
         text = text//comment//block//line//' /'//nl
      end do
   end function config_text

   !> The value of a variable in a case as the echo writes it ('' for a table without rows).
   function value_text(c, e) result(text)
      !> The case.
      type(case_config), intent(in) :: c
      !> The variable.
      type(schema_entry), intent(in) :: e
      character(:), allocatable :: text
      type(config_value) :: v
      integer :: k
      v = get_value(c, e)
      text = ''
      if (.not. v%found) return
      if (e%type /= 'real') then
         text = item_text(e, v, 1)
         return
      end if
      do k = 1, size(v%reals)
         if (k > 1) text = text//', '
         text = text//item_text(e, v, k)
      end do
   end function value_text

   !> Element k of a value as namelist text.
   function item_text(e, v, k) result(text)
      !> The variable.
      type(schema_entry), intent(in) :: e
      !> Its value.
      type(config_value), intent(in) :: v
      !> Element (reals).
      integer, intent(in) :: k
      character(:), allocatable :: text
      integer :: i
      select case (e%type)
      case ('real')
         text = real_text(v%reals(k))
      case ('integer')
         text = str(v%int)
      case ('logical')
         text = merge('.true. ', '.false.', v%flag)
         text = trim(text)
      case default
         ! Quoted, a quote inside doubled.
         text = "'"
         do i = 1, len(v%text)
            text = text//v%text(i:i)
            if (v%text(i:i) == "'") text = text//"'"
         end do
         text = text//"'"
      end select
   end function item_text

   !> Whether a position of end b was given (then the tension is not echoed).
   logical function given_position_b(c)
      !> The case.
      type(case_config), intent(in) :: c
      given_position_b = c%is_given('end_b', 'x') .or. c%is_given('end_b', 'y') .or. c%is_given('end_b', 'z')
   end function given_position_b

   !> Whether the echo writes a variable: the tension only for the paper's
   !> symmetric case (both ends fixed, no position given for end b), end b's
   !> position only when given; not the position of an end whose kind does not use it (free,
   !> force, mass), nor a variable of own_kinds_only for another kind;
   !> no table without rows, and no table_file unless given.
   logical function echoed(c, e, position_b)
      !> The case.
      type(case_config), intent(in) :: c
      !> The variable.
      type(schema_entry), intent(in) :: e
      !> Whether a position of end b was given (given_position_b).
      logical, intent(in) :: position_b
      echoed = .true.
      if (e%group == 'static' .and. e%name == 'tension') echoed = .not. position_b .and. &
         is_word(c%end_a%kind, 'fixed') .and. is_word(c%end_b%kind, 'fixed')
      ! &rupture: criterion and mbl for a break by tension, s_break and time for one by time
      ! (the echo of a case by time is that of the cases before the criterion).
      if (e%group == 'rupture') then
         select case (e%name)
         case ('criterion', 'mbl')
            echoed = trim(c%break_criterion) == 'tension'
         case ('s_break', 'time')
            echoed = trim(c%break_criterion) /= 'tension'
         end select
         return
      end if
      if (e%group == 'material') then
         select case (e%name)
         case ('table_strain', 'table_tension')
            echoed = c%material_table_rows > 0
         case ('table_file')
            echoed = len_trim(c%material_table_file) > 0
         end select
         return
      end if
      ! The end itself, not a copy (a copy of its tables cost more than the rest of the echo).
      if (e%group == 'end_a') then
         echoed = end_echoed(c%end_a, e)
      else if (e%group == 'end_b') then
         echoed = end_echoed(c%end_b, e)
         if (is_word(e%name, 'x y z')) echoed = echoed .and. position_b
      end if
   end function echoed

   !> `echoed` for a variable of &end_a or &end_b, but for the condition on end b's position.
   logical function end_echoed(side, e)
      !> The end.
      type(end_config), intent(in) :: side
      !> The variable.
      type(schema_entry), intent(in) :: e
      end_echoed = .true.
      if (e%own_kinds_only) then
         end_echoed = is_word(e%name, kind_variables(side%kind))
         return
      end if
      select case (e%name)
      case ('x', 'y', 'z')
         ! Not for the kinds whose position follows from the statics.
         end_echoed = is_word(e%name, kind_variables(side%kind))
      case ('table_time', 'table_x', 'table_z')
         end_echoed = side%table_rows > 0
      case ('table_y')
         end_echoed = any(side%table_y(1:side%table_rows) /= 0)
      case ('table_file')
         end_echoed = len_trim(side%table_file) > 0
      end select
   end function end_echoed

   !> The variables a kind uses, blank-separated ('' for a word that is not a kind).
   function kind_variables(kind) result(words)
      !> The kind's word.
      character(*), intent(in) :: kind
      character(:), allocatable :: words
      type(end_kind) :: line
      logical :: found
      call find_end_kind(kind, line, found)
      words = ''
      if (found) words = trim(line%variables)
   end function kind_variables

   !> Identifier starting at position i of a line, lower case.
   function word_at(line, i) result(word)
      !> Line.
      character(*), intent(in) :: line
      !> Where the identifier starts.
      integer, intent(in) :: i
      character(:), allocatable :: word
      integer :: j
      j = i
      do while (j <= len(line))
         if (.not. is_name_char(line(j:j))) exit
         j = j + 1
      end do
      word = to_lower(line(i:j - 1))
   end function word_at

   !> Whether a character may be part of a name.
   pure logical function is_name_char(ch)
      !> Character.
      character, intent(in) :: ch
      is_name_char = (ch >= 'a' .and. ch <= 'z') .or. (ch >= 'A' .and. ch <= 'Z') .or. &
                     (ch >= '0' .and. ch <= '9') .or. ch == '_'
   end function is_name_char

   !> Index of name in names (0: none).
   pure integer function findloc_name(names, name)
      !> Names, blank-padded.
      character(len=*), intent(in) :: names(:)
      !> Name.
      character(*), intent(in) :: name
      integer :: i
      findloc_name = 0
      do i = 1, size(names)
         if (trim(names(i)) == name) then
            findloc_name = i
            return
         end if
      end do
   end function findloc_name

   !> Names as 'a, b, c', each after a prefix.
   function join_names(names, prefix) result(s)
      !> Names, blank-padded.
      character(len=*), intent(in) :: names(:)
      !> Put before each name ('&' for groups).
      character(*), intent(in) :: prefix
      character(:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(names)
         s = s//prefix//trim(names(i))
         if (i < size(names)) s = s//', '
      end do
   end function join_names
end module xcable_io_input
