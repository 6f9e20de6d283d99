!> The scanner of a namelist file: its lines, its groups and their assignments, each name
!> checked against the group's variables and each value against the variable's type (from the
!> schema), before gfortran's namelist input reads the group.
!> (Split from io/input.f90, which reads a case through these modules.)
module xcable_io_input_scanner
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str, to_lower
   use xcable_io_config, only: case_config, max_segments
   use xcable_io_schema, only: schema_entry, find_entry, group_entries, group_list, segment_group, point_group
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use xcable_io_input_access, only: access, config_value
   implicit none
   private
   public :: count_table_rows, inline_rows, is_word, line_len, load_lines, lower_words, next_item, &
             scan_groups, shown, shown_length

   integer, parameter :: line_len = 1024, max_lines = 5000

   !> Values longer than this are cut in messages.
   integer, parameter :: shown_length = 60

contains

   !> Put the value of a string variable with allowed words in lower case, without leading blanks.
   subroutine lower_words(c, e)
      !> The case.
      type(case_config), intent(inout) :: c
      !> A string variable with allowed words.
      type(schema_entry), intent(in) :: e
      type(config_value) :: v
      character(:), allocatable :: lower
      call access(c, e, v, .false.)
      lower = to_lower(trim(adjustl(v%text)))
      ! (Stored only when it changes: a store of a network point's variable allocates its end.)
      if (lower == v%text) return
      v%text = lower
      call access(c, e, v, .true.)
   end subroutine lower_words

   !> The number of rows of each inline table: the number of values given to
   !> its first column (an end's table_time, the material's table_strain),
   !> which the other columns must match (an end's table_y may be left out).
   subroutine count_table_rows(c, t, counts, error)
      !> The case; table_rows of each end (and network point) and material_table_rows (the line's and each
      !> segment's) set.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Values given to each entry (its highest index assigned).
      integer, intent(in) :: counts(:)
      !> Error naming the columns and their counts.
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: end_columns(3) = [character(len=10) :: 'table_time', 'table_x', 'table_z']
      character(len=*), parameter :: material_columns(2) = [character(len=13) :: 'table_strain', 'table_tension']
      integer :: k
      call inline_rows(c, t, counts, 'end_a', end_columns, c%end_a%table_rows, error)
      if (allocated(error)) return
      call optional_column('end_a', c%end_a%table_rows)
      if (allocated(error)) return
      call inline_rows(c, t, counts, 'end_b', end_columns, c%end_b%table_rows, error)
      if (allocated(error)) return
      call optional_column('end_b', c%end_b%table_rows)
      if (allocated(error)) return
      call inline_rows(c, t, counts, 'material', material_columns, c%material_table_rows, error)
      if (allocated(error)) return
      do k = 1, max_segments
         call inline_rows(c, t, counts, trim(segment_group(k)), material_columns, &
                          c%segments(k)%material_table_rows, error)
         if (allocated(error)) return
      end do
      ! A motion point's table (&point_k of a network; point_ends allocated where a variable of them is given).
      if (allocated(c%point_ends)) then
         do k = 1, c%point_count
            call inline_rows(c, t, counts, trim(point_group(k)), end_columns, c%point_ends(k)%table_rows, error)
            if (allocated(error)) return
            call optional_column(trim(point_group(k)), c%point_ends(k)%table_rows)
            if (allocated(error)) return
         end do
      end if
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
                                   group_list(group_names, '&', '', ', '), stat_input)
                  return
               end if
               ig = findloc_name(group_names, group)
               if (ig == 0) then
                  call fatal_error(error, path//': line '//str(i)//': unknown group &'//group// &
                                   '; allowed: '//group_list(group_names, '&', '', ', '), stat_input)
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
                          group_list(group_names, '&', '', ', '), stat_input)
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

   !> Whether word is one of the blank-separated words.
   pure logical function is_word(word, words)
      !> Word.
      character(*), intent(in) :: word
      !> Blank-separated words.
      character(*), intent(in) :: words
      is_word = len_trim(word) > 0 .and. index(' '//trim(words)//' ', ' '//trim(word)//' ') > 0
   end function is_word

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
end module xcable_io_input_scanner
