!> Reading a case from a namelist file into `case_config`, then validating it.
!>
!> gfortran reports a misspelled variable, a wrong-typed value, a missing group
!> and a missing closing '/' alike (often as "End of file"), so the file is
!> first scanned here: groups are located, unknown or duplicated groups and
!> unterminated groups are refused, every assignment's name is checked against
!> the group's variables and its value against the variable's type. Only then
!> is each group read with the compiler's namelist input, and the values are
!> checked against their allowed ranges. Every message names the file, the
!> group, the variable, its value and what is allowed.
module xcable_io_input
   use xcable_kinds, only: dp, i8
   use xcable_error, only: error_type, fatal_error, stat_input
   use xcable_strings, only: str, to_lower
   use xcable_material_law, only: paper_tanh_coefficients
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: case_config, read_config, config_text, known_fields, derive_defaults

   !> Snapshot fields that &output fields may name.
   character(len=*), parameter :: known_fields(8) = &
      [character(len=9) :: 'tension', 'shear', 'strain', 'u', 'v', 'x', 'z', 'curvature']

   integer, parameter :: line_len = 1024, max_lines = 5000

   !> Most time steps a run may ask for (t_end / dt): the history is kept in
   !> memory, and a step far below this is a typing error (dt = 1e-300 made
   !> an integer overflow and a crash).
   integer, parameter, public :: max_time_steps = 1000000

   !> A case, with the paper's values as defaults (slow rupture at 315 kN).
   type :: case_config
      !> Namelist file the case came from.
      character(:), allocatable :: source
      ! &cable
      !> Unstretched length, m.
      real(dp) :: length = 60
      !> Diameter, m.
      real(dp) :: diameter = 0.05_dp
      !> Density, kg/m^3.
      real(dp) :: density = 1140
      !> Young's modulus, Pa.
      real(dp) :: young = 230.0e6_dp
      !> Gravity, m/s^2.
      real(dp) :: gravity = 9.81_dp
      !> Cross-section area, m^2 (0: pi d^2 / 4).
      real(dp) :: area = 0
      !> Bending stiffness EI, N m^2 (0: E pi d^4 / 64).
      real(dp) :: bending_stiffness = 0
      ! &material
      !> 'tanh' (eq. 17) or 'linear'.
      character(len=16) :: law = 'tanh'
      !> Coefficients of eq. 17.
      real(dp) :: p(5) = paper_tanh_coefficients
      !> EA of the linear law, N (0: young * area).
      real(dp) :: ea = 0
      !> Largest strain the law is used for in statics.
      real(dp) :: strain_max = 0.35_dp
      ! &static
      !> End tension of the initial catenary, N.
      real(dp) :: tension = 315.0e3_dp
      ! &rupture
      !> Breaking time, s.
      real(dp) :: t_break = 0.05_dp
      ! &numerics
      !> Number of nodes.
      integer :: nodes = 121
      !> Time step, s (0: from courant).
      real(dp) :: dt = 0
      !> Courant number c(eps0) dt / ds giving dt when dt = 0.
      real(dp) :: courant = 1
      !> End of the run, s.
      real(dp) :: t_end = 0.16_dp
      !> Time weight theta of the box scheme (0.5: the paper's).
      real(dp) :: theta = 0.5_dp
      !> Newton tolerance on the scaled update.
      real(dp) :: newton_tol = 1.0e-7_dp
      !> Newton iteration limit.
      integer :: newton_max_iter = 25
      !> Keep the factorised Jacobian while Newton contracts well.
      logical :: reuse_jacobian = .true.
      !> First guess of a step by extrapolation.
      logical :: extrapolate = .true.
      !> Smallest step of the step control, as a fraction of dt.
      real(dp) :: min_step_fraction = 1.0_dp/1024
      !> Wall-clock limit, s (0: none).
      real(dp) :: max_wall_time = 0
      ! &output
      !> HDF5 result file ('' : results/<namelist stem>.h5).
      character(len=512) :: file = ''
      !> Snapshot interval, s.
      real(dp) :: interval = 0.01_dp
      !> Snapshot fields, separated by spaces or commas.
      character(len=256) :: fields = 'tension shear strain u v x z curvature'
      !> No progress on stderr.
      logical :: quiet = .false.
      !> Keep the energy ledger.
      logical :: energy = .false.
      !> Write gnuplot-ready text beside the HDF5 file.
      logical :: gnuplot = .false.
   end type case_config

contains

   !> Read and validate a case.
   subroutine read_config(path, config, error)
      !> Namelist file.
      character(*), intent(in) :: path
      !> The case.
      type(case_config), intent(out) :: config
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(len=line_len), allocatable :: lines(:)
      integer :: nlines
      character(len=16) :: group_names(6)
      logical :: present_group(6)

      config%source = path
      group_names = [character(len=16) :: 'cable', 'material', 'static', 'rupture', 'numerics', 'output']
      call load_lines(path, lines, nlines, error)
      if (allocated(error)) return
      call scan_groups(path, lines(1:nlines), group_names, present_group, error)
      if (allocated(error)) return
      call read_groups(path, config, group_names, present_group, error)
      if (allocated(error)) return
      call validate(config, error)
   end subroutine read_config

   !> Read the file into lines, refusing what is not plain text.
   !>
   !> The bytes are read unformatted and split here, at LF or CR LF: gfortran's
   !> formatted stream input also ends a line at a lone CR (old Mac text) but
   !> its namelist input does not, so the scan and the read would see
   !> different files. A lone CR, a control byte or a byte above 126 is
   !> refused with its line and column; a tab counts as a blank.
   subroutine load_lines(path, lines, nlines, error)
      character(*), intent(in) :: path
      character(len=line_len), allocatable, intent(out) :: lines(:)
      integer, intent(out) :: nlines
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
   subroutine scan_groups(path, lines, group_names, present_group, error)
      character(*), intent(in) :: path
      character(len=*), intent(in) :: lines(:)
      character(len=16), intent(in) :: group_names(:)
      logical, intent(out) :: present_group(:)
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: text, group
      integer :: i, j, start_line, ig
      logical :: in_group, in_quote
      character :: quote, ch

      present_group = .false.
      in_group = .false.
      in_quote = .false.
      quote = ' '
      text = ''
      group = ''
      start_line = 0
      do i = 1, size(lines)
         j = 0
         do while (j < len_trim(lines(i)))
            j = j + 1
            ch = lines(i)(j:j)
            if (in_quote) then
               if (ch == quote) in_quote = .false.
               if (in_group) text = text//ch
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
               text = ''
               j = j + len(group)
               cycle
            end if
            if (ch == '&') then
               call fatal_error(error, path//': group &'//group//' (line '//str(start_line)// &
                                ') has no closing "/" before line '//str(i), stat_input)
               return
            end if
            if (ch == '/') then
               call check_assignments(path, group, text, error)
               if (allocated(error)) return
               in_group = .false.
               cycle
            end if
            if (ch == '"' .or. ch == "'") then
               in_quote = .true.
               quote = ch
            end if
            text = text//ch
         end do
         if (in_group) text = text//' '
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
   end subroutine scan_groups

   !> Check the names and value types of the assignments of one group.
   subroutine check_assignments(path, group, text, error)
      character(*), intent(in) :: path, group, text
      type(error_type), allocatable, intent(out) :: error
      character(len=24), allocatable :: names(:)
      character :: types(20)
      integer :: sizes(20), lengths(20)
      integer :: eq(200), neq, i, j, name_start, name_end, value_end, iv, capacity
      character(:), allocatable :: name, value, subscript
      logical :: in_quote
      character :: quote

      call group_variables(group, names, types, sizes, lengths)
      ! Positions of '=' outside quotes.
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
            if (neq == size(eq)) exit
            neq = neq + 1
            eq(neq) = i
         end if
      end do
      if (neq == 0 .and. len_trim(text) > 0) then
         call fatal_error(error, path//': &'//group//': "'//trim(adjustl(text))// &
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
               call fatal_error(error, path//': &'//group//': unexpected "'//trim(adjustl(text(1:name_start - 1)))// &
                                '" before '//name, stat_input)
               return
            end if
         end if
         subscript = ''
         if (index(name, '(') > 0) then
            subscript = name(index(name, '('):)
            name = name(1:index(name, '(') - 1)
         end if
         iv = findloc_name(names, name)
         if (iv == 0 .or. len(name) == 0) then
            call fatal_error(error, path//': &'//group//': unknown variable "'//text(name_start:name_end)// &
                             '"; allowed: '//join_names(names, ''), stat_input)
            return
         end if
         call check_subscript(path, group, name, subscript, sizes(iv), capacity, error)
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
         call check_value(path, group, name//subscript, value, types(iv), capacity, lengths(iv), error)
         if (allocated(error)) return
      end do
   end subroutine check_assignments

   !> Check the subscript of an assignment, '' or '(i)' or '(i:j)', against the
   !> variable's size and give the number of values it can take. gfortran
   !> itself reports a bad subscript as "Index 1 out of range" whatever the index.
   subroutine check_subscript(path, group, name, subscript, size, capacity, error)
      character(*), intent(in) :: path, group, name, subscript
      !> Number of elements of the variable (1: a scalar).
      integer, intent(in) :: size
      !> Number of values the assignment can take.
      integer, intent(out) :: capacity
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: inside
      integer :: colon, first, last, ios
      capacity = size
      if (len(subscript) == 0) return
      if (size == 1) then
         call fatal_error(error, path//': &'//group//': '//name//subscript//': '//name// &
                          ' is a single value; write it without a subscript', stat_input)
         return
      end if
      inside = ''
      if (subscript(len(subscript):len(subscript)) == ')') inside = subscript(2:len(subscript) - 1)
      colon = index(inside, ':')
      first = 1
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
      character(*), intent(in) :: text
      integer, intent(in) :: ieq
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

   !> Check that a value text has the variable's type: r real(s), i integer, l logical, s string.
   !> A numeric value list may use repeat counts r*v; the number of values it
   !> gives must fit the variable (gfortran says only "Cannot match namelist
   !> object name" or "Repeat count too large"), and a string must fit its
   !> variable (gfortran cuts it silently).
   subroutine check_value(path, group, name, value, kind, capacity, max_length, error)
      character(*), intent(in) :: path, group, name, value
      character, intent(in) :: kind
      !> Number of values the assignment can take.
      integer, intent(in) :: capacity
      !> Length of a string variable.
      integer, intent(in) :: max_length
      type(error_type), allocatable, intent(out) :: error
      character(len=line_len) :: items(20)
      integer :: n, k, ios, ival, star, repeat, count
      character(:), allocatable :: item
      real(dp) :: rval
      logical :: lval
      character(:), allocatable :: what
      if (len(value) == 0) then
         call fatal_error(error, path//': &'//group//': '//name//' has no value', stat_input)
         return
      end if
      select case (kind)
      case ('r')
         what = 'a finite real number'
      case ('i')
         what = 'an integer'
      case ('l')
         what = '.true. or .false.'
      case default
         what = 'a quoted string'
      end select
      if (kind == 's') then
         if (.not. (value(1:1) == "'" .or. value(1:1) == '"') .or. len(value) < 2 .or. &
             value(len(value):len(value)) /= value(1:1)) then
            call fatal_error(error, path//': &'//group//': '//name//' = '//value//': must be '//what, stat_input)
         else if (len(value) - 2 > max_length) then
            call fatal_error(error, path//': &'//group//': '//name//' = '//value(1:min(len(value), 40))// &
                             '...: is '//str(len(value) - 2)//' characters long; at most '//str(max_length)// &
                             ' are allowed', stat_input)
         end if
         return
      end if
      call split_items(value, items, n)
      if (n == 0) then
         call fatal_error(error, path//': &'//group//': '//name//' has no value', stat_input)
         return
      end if
      count = 0
      do k = 1, n
         item = trim(items(k))
         star = index(item, '*')
         repeat = 1
         if (star > 0) then
            ! r*v: r a positive integer, v a value or nothing (r null values).
            ios = merge(1, 0, star == 1 .or. verify(item(1:max(star - 1, 1)), '0123456789') > 0)
            if (ios == 0) read (item(1:star - 1), *, iostat=ios) repeat
            if (ios /= 0 .or. repeat < 1) then
               call fatal_error(error, path//': &'//group//': '//name//' = '//value//': "'//item// &
                                '" is not a repeat count r*value with r a positive integer', stat_input)
               return
            end if
            item = item(star + 1:)
         end if
         if (repeat > capacity - count) then
            if (capacity == 1) then
               call fatal_error(error, path//': &'//group//': '//name//' = '//value//': too many values; '// &
                                name//' takes one value', stat_input)
            else
               call fatal_error(error, path//': &'//group//': '//name//' = '//value//': too many values; '// &
                                name//' takes at most '//str(capacity), stat_input)
            end if
            return
         end if
         count = count + repeat
         if (len(item) == 0) cycle
         select case (kind)
         case ('r')
            read (item, *, iostat=ios) rval
            if (ios == 0) then
               if (.not. ieee_is_finite(rval)) ios = 1
            end if
            if (ios == 0 .and. verify(item, '0123456789+-.eEdD') > 0) ios = 1
         case ('i')
            read (item, *, iostat=ios) ival
            if (ios == 0 .and. verify(item, '0123456789+-') > 0) ios = 1
         case ('l')
            read (item, *, iostat=ios) lval
            if (ios == 0 .and. index('.tf', to_lower(item(1:1))) == 0) ios = 1
         end select
         if (ios /= 0) then
            call fatal_error(error, path//': &'//group//': '//name//' = '//value//': "'//item// &
                             '" is not '//what, stat_input)
            return
         end if
      end do
   end subroutine check_value

   !> Split a value list at commas and blanks.
   subroutine split_items(value, items, n)
      character(*), intent(in) :: value
      character(len=*), intent(out) :: items(:)
      integer, intent(out) :: n
      integer :: i, start
      n = 0
      start = 0
      do i = 1, len(value) + 1
         if (i > len(value)) then
            if (start > 0) call push(value(start:i - 1))
         else if (value(i:i) == ',' .or. value(i:i) == ' ') then
            if (start > 0) call push(value(start:i - 1))
            start = 0
         else if (start == 0) then
            start = i
         end if
      end do
   contains
      subroutine push(item)
         character(*), intent(in) :: item
         if (n < size(items)) then
            n = n + 1
            items(n) = item
         end if
      end subroutine push
   end subroutine split_items

   !> Variables of a group, their types (r, i, l, s), sizes (elements) and
   !> lengths (characters, strings only; they match case_config).
   subroutine group_variables(group, names, types, sizes, lengths)
      character(*), intent(in) :: group
      character(len=24), allocatable, intent(out) :: names(:)
      character, intent(out) :: types(:)
      integer, intent(out) :: sizes(:), lengths(:)
      sizes = 1
      lengths = 0
      select case (group)
      case ('cable')
         names = [character(len=24) :: 'length', 'diameter', 'density', 'young', 'gravity', 'area', &
                  'bending_stiffness']
         types(1:7) = 'r'
      case ('material')
         names = [character(len=24) :: 'law', 'p', 'ea', 'strain_max']
         types(1:4) = ['s', 'r', 'r', 'r']
         sizes(2) = 5
         lengths(1) = 16
      case ('static')
         names = [character(len=24) :: 'tension']
         types(1) = 'r'
      case ('rupture')
         names = [character(len=24) :: 't_break']
         types(1) = 'r'
      case ('numerics')
         names = [character(len=24) :: 'nodes', 'dt', 'courant', 't_end', 'theta', 'newton_tol', &
                  'newton_max_iter', 'reuse_jacobian', 'extrapolate', 'min_step_fraction', 'max_wall_time']
         types(1:11) = ['i', 'r', 'r', 'r', 'r', 'r', 'i', 'l', 'l', 'r', 'r']
      case ('output')
         names = [character(len=24) :: 'file', 'interval', 'fields', 'quiet', 'energy', 'gnuplot']
         types(1:6) = ['s', 'r', 's', 'l', 'l', 'l']
         lengths(1) = 512
         lengths(3) = 256
      case default
         allocate (names(0))
      end select
   end subroutine group_variables

   !> Read the groups that are present with the compiler's namelist input.
   subroutine read_groups(path, c, group_names, present_group, error)
      character(*), intent(in) :: path
      type(case_config), intent(inout) :: c
      character(len=16), intent(in) :: group_names(:)
      logical, intent(in) :: present_group(:)
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: length, diameter, density, young, gravity, area, bending_stiffness
      character(len=16) :: law
      real(dp) :: p(5), ea, strain_max, tension, t_break, dt, courant, t_end, theta, newton_tol
      real(dp) :: min_step_fraction, max_wall_time, interval
      integer :: nodes, newton_max_iter
      logical :: reuse_jacobian, extrapolate, quiet, energy, gnuplot
      character(len=512) :: file
      character(len=256) :: fields
      namelist /cable/ length, diameter, density, young, gravity, area, bending_stiffness
      namelist /material/ law, p, ea, strain_max
      namelist /static/ tension
      namelist /rupture/ t_break
      namelist /numerics/ nodes, dt, courant, t_end, theta, newton_tol, newton_max_iter, reuse_jacobian, &
         extrapolate, min_step_fraction, max_wall_time
      namelist /output/ file, interval, fields, quiet, energy, gnuplot
      integer :: unit, ios, ig
      character(len=512) :: msg

      length = c%length; diameter = c%diameter; density = c%density; young = c%young
      gravity = c%gravity; area = c%area; bending_stiffness = c%bending_stiffness
      law = c%law; p = c%p; ea = c%ea; strain_max = c%strain_max
      tension = c%tension; t_break = c%t_break
      nodes = c%nodes; dt = c%dt; courant = c%courant; t_end = c%t_end; theta = c%theta
      newton_tol = c%newton_tol; newton_max_iter = c%newton_max_iter; reuse_jacobian = c%reuse_jacobian
      extrapolate = c%extrapolate; min_step_fraction = c%min_step_fraction; max_wall_time = c%max_wall_time
      file = c%file; interval = c%interval; fields = c%fields; quiet = c%quiet; energy = c%energy
      gnuplot = c%gnuplot

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
         case ('rupture')
            read (unit, nml=rupture, iostat=ios, iomsg=msg)
         case ('numerics')
            read (unit, nml=numerics, iostat=ios, iomsg=msg)
         case ('output')
            read (unit, nml=output, iostat=ios, iomsg=msg)
         end select
         if (ios /= 0) then
            call fatal_error(error, path//': &'//trim(group_names(ig))//': cannot be read: '//trim(msg), stat_input)
            close (unit)
            return
         end if
      end do
      close (unit)

      c%length = length; c%diameter = diameter; c%density = density; c%young = young
      c%gravity = gravity; c%area = area; c%bending_stiffness = bending_stiffness
      c%law = to_lower(adjustl(law)); c%p = p; c%ea = ea; c%strain_max = strain_max
      c%tension = tension; c%t_break = t_break
      c%nodes = nodes; c%dt = dt; c%courant = courant; c%t_end = t_end; c%theta = theta
      c%newton_tol = newton_tol; c%newton_max_iter = newton_max_iter; c%reuse_jacobian = reuse_jacobian
      c%extrapolate = extrapolate; c%min_step_fraction = min_step_fraction; c%max_wall_time = max_wall_time
      c%file = file; c%interval = interval; c%fields = fields; c%quiet = quiet; c%energy = energy
      c%gnuplot = gnuplot
   end subroutine read_groups

   !> The values whose 0 means "derived from others": the area from the
   !> diameter, EI from young and the diameter, EA of the linear law from young
   !> and the area. Called by validate and by setup_case, so that a case built
   !> in code (tests, examples) gets them as a namelist does.
   pure subroutine derive_defaults(c)
      !> Case; derived values replace zeros.
      type(case_config), intent(inout) :: c
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (c%area == 0) c%area = 0.25_dp*pi*c%diameter**2
      if (c%bending_stiffness == 0) c%bending_stiffness = c%young*pi*c%diameter**4/64
      if (c%law == 'linear' .and. c%ea == 0) c%ea = c%young*c%area
   end subroutine derive_defaults

   !> Range checks, and the derived defaults (area, EI, EA, output file).
   subroutine validate(c, error)
      type(case_config), intent(inout) :: c
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      character(len=256) :: items(20)
      integer :: n, k, slash, dot
      ! Lower bounds (issue 6, bad-input fuzzing): a value that is positive but
      ! tiny (1e-300) passed "> 0" and gave a zero mass, an infinite wave
      ! speed, a zero step or a singular Jacobian. The bounds are generous
      ! physical ones; gravity must be > 0 because without weight the static
      ! cable may turn freely about the fixed end (the static Jacobian is
      ! singular), and EI far below 1e-6 N m^2 leaves the moment balance
      ! (row 7, scaled by EI / T_s) empty at double precision.
      call positive_in('cable', 'length', c%length, 1.0e-2_dp, 1.0e5_dp); if (allocated(error)) return
      call positive_in('cable', 'diameter', c%diameter, 1.0e-4_dp, 10.0_dp); if (allocated(error)) return
      call positive_in('cable', 'density', c%density, 1.0_dp, 1.0e5_dp); if (allocated(error)) return
      call positive_in('cable', 'young', c%young, 1.0e3_dp, 1.0e13_dp); if (allocated(error)) return
      call in_range('cable', 'gravity', c%gravity, 1.0e-6_dp, 100.0_dp, &
                    ' (without weight the static cable may turn freely: its direction is undetermined)')
      if (allocated(error)) return
      call zero_or_range('cable', 'area', c%area, 1.0e-9_dp, 100.0_dp, 'pi d^2 / 4'); if (allocated(error)) return
      call zero_or_range('cable', 'bending_stiffness', c%bending_stiffness, 1.0e-6_dp, 1.0e12_dp, 'E pi d^4 / 64')
      if (allocated(error)) return
      select case (c%law)
      case ('tanh')
         call positive('material', 'p(1)', c%p(1), 1.0e12_dp); if (allocated(error)) return
         call positive('material', 'p(2)', c%p(2), 1.0e6_dp); if (allocated(error)) return
         call in_range('material', 'p(3)', c%p(3), -1.0e3_dp, 1.0e3_dp); if (allocated(error)) return
         call in_range('material', 'p(4)', c%p(4), -1.0e12_dp, 1.0e12_dp); if (allocated(error)) return
         call positive('material', 'p(5)', c%p(5), 1.0e12_dp); if (allocated(error)) return
      case ('linear')
         call zero_or_range('material', 'ea', c%ea, 1.0_dp, 1.0e13_dp, 'young * area'); if (allocated(error)) return
      case default
         call fatal_error(error, c%source//': &material: law = '//trim(c%law)//": must be 'tanh' or 'linear'", &
                          stat_input)
         return
      end select
      ! An EI given is in range (above); one derived from young and d may not be.
      if (c%bending_stiffness == 0 .and. c%young*pi*c%diameter**4/64 < 1.0e-6_dp) then
         call fatal_error(error, c%source//': &cable: young = '//str(c%young)//', diameter = '//str(c%diameter)// &
                          ': give a bending stiffness E pi d^4 / 64 = '//str(c%young*pi*c%diameter**4/64)// &
                          ' N m^2, below 1e-6; set bending_stiffness', stat_input)
         return
      end if
      call derive_defaults(c)
      call positive('material', 'strain_max', c%strain_max, 10.0_dp); if (allocated(error)) return
      call positive('static', 'tension', c%tension, 1.0e9_dp); if (allocated(error)) return
      call in_range('rupture', 't_break', c%t_break, 0.0_dp, 1.0e4_dp); if (allocated(error)) return
      if (c%nodes < 3 .or. c%nodes > 100001) then
         call fatal_error(error, c%source//': &numerics: nodes = '//str(c%nodes)//': must be an integer from 3 to 100001', &
                          stat_input)
         return
      end if
      call positive('numerics', 't_end', c%t_end, 1.0e4_dp); if (allocated(error)) return
      call in_range('numerics', 'dt', c%dt, 0.0_dp, c%t_end); if (allocated(error)) return
      if (c%dt > 0 .and. c%t_end/c%dt > max_time_steps) then
         call fatal_error(error, c%source//': &numerics: dt = '//str(c%dt)//': gives more than '// &
                          str(max_time_steps)//' steps to t_end = '//str(c%t_end)//'; must be at least t_end / '// &
                          str(max_time_steps)//' = '//str(c%t_end/max_time_steps), stat_input)
         return
      end if
      if (c%dt == 0) then
         call positive('numerics', 'courant', c%courant, 1.0e4_dp); if (allocated(error)) return
      end if
      call in_range('numerics', 'theta', c%theta, 0.5_dp, 1.0_dp); if (allocated(error)) return
      call in_range('numerics', 'newton_tol', c%newton_tol, 1.0e-15_dp, 1.0e-3_dp); if (allocated(error)) return
      if (c%newton_max_iter < 1 .or. c%newton_max_iter > 100) then
         call fatal_error(error, c%source//': &numerics: newton_max_iter = '//str(c%newton_max_iter)// &
                          ': must be an integer from 1 to 100', stat_input)
         return
      end if
      call in_range('numerics', 'min_step_fraction', c%min_step_fraction, 1.0e-9_dp, 1.0_dp)
      if (allocated(error)) return
      call in_range('numerics', 'max_wall_time', c%max_wall_time, 0.0_dp, 1.0e7_dp); if (allocated(error)) return
      call in_range('output', 'interval', c%interval, 0.0_dp, c%t_end); if (allocated(error)) return
      if (c%interval > 0 .and. c%t_end/c%interval > 1.0e5_dp) then
         call fatal_error(error, c%source//': &output: interval = '//str(c%interval)// &
                          ': gives more than 100000 snapshots; must be at least t_end / 100000 = '// &
                          str(c%t_end/1.0e5_dp), stat_input)
         return
      end if
      call split_items(c%fields, items, n)
      do k = 1, n
         if (findloc_name(known_fields, trim(items(k))) == 0) then
            call fatal_error(error, c%source//': &output: fields = '//trim(c%fields)//': unknown field "'// &
                             trim(items(k))//'"; allowed: '//join_names(known_fields, ''), stat_input)
            return
         end if
      end do
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

      subroutine positive(group, name, value, upper)
         character(*), intent(in) :: group, name
         real(dp), intent(in) :: value, upper
         if (.not. (value > 0 .and. value <= upper)) then
            call fatal_error(error, c%source//': &'//group//': '//name//' = '//str(value)// &
                             ': must be > 0 and <= '//str(upper), stat_input)
         end if
      end subroutine positive

      subroutine in_range(group, name, value, lower, upper, why)
         character(*), intent(in) :: group, name
         real(dp), intent(in) :: value, lower, upper
         character(*), intent(in), optional :: why
         if (.not. (value >= lower .and. value <= upper)) then
            if (present(why)) then
               call fatal_error(error, c%source//': &'//group//': '//name//' = '//str(value)// &
                                ': must be in ['//str(lower)//', '//str(upper)//']'//why, stat_input)
            else
               call fatal_error(error, c%source//': &'//group//': '//name//' = '//str(value)// &
                                ': must be in ['//str(lower)//', '//str(upper)//']', stat_input)
            end if
         end if
      end subroutine in_range

      !> A positive quantity with a physical floor.
      subroutine positive_in(group, name, value, lower, upper)
         character(*), intent(in) :: group, name
         real(dp), intent(in) :: value, lower, upper
         if (.not. (value >= lower .and. value <= upper)) then
            call fatal_error(error, c%source//': &'//group//': '//name//' = '//str(value)// &
                             ': must be > 0 and in ['//str(lower)//', '//str(upper)//']', stat_input)
         end if
      end subroutine positive_in

      !> 0 (the derived default) or a value in [lower, upper].
      subroutine zero_or_range(group, name, value, lower, upper, default)
         character(*), intent(in) :: group, name, default
         real(dp), intent(in) :: value, lower, upper
         if (.not. (value == 0 .or. (value >= lower .and. value <= upper))) then
            call fatal_error(error, c%source//': &'//group//': '//name//' = '//str(value)// &
                             ': must be 0 (for '//default//') or in ['//str(lower)//', '//str(upper)//']', stat_input)
         end if
      end subroutine zero_or_range
   end subroutine validate

   !> The resolved case as namelist text (for provenance in the output).
   function config_text(c) result(text)
      !> The case.
      type(case_config), intent(in) :: c
      character(:), allocatable :: text
      character(len=1024) :: line
      text = ''
      write (line, '(a,5(a,g0))') '&cable', ' length = ', c%length, ', diameter = ', c%diameter, &
         ', density = ', c%density, ', young = ', c%young, ', gravity = ', c%gravity
      text = text//trim(line)
      write (line, '(2(a,g0),a)') ', area = ', c%area, ', bending_stiffness = ', c%bending_stiffness, ' /'
      text = text//trim(line)//new_line('a')
      write (line, '(3a,5(g0,:,", "))') "&material law = '", trim(c%law), "', p = ", c%p
      text = text//trim(line)
      write (line, '(2(a,g0),a)') ', ea = ', c%ea, ', strain_max = ', c%strain_max, ' /'
      text = text//trim(line)//new_line('a')
      write (line, '(a,g0,a)') '&static tension = ', c%tension, ' /'
      text = text//trim(line)//new_line('a')
      write (line, '(a,g0,a)') '&rupture t_break = ', c%t_break, ' /'
      text = text//trim(line)//new_line('a')
      write (line, '(a,i0,5(a,g0),a,i0,2(a,l1),2(a,g0),a)') '&numerics nodes = ', c%nodes, ', dt = ', c%dt, &
         ', courant = ', c%courant, ', t_end = ', c%t_end, ', theta = ', c%theta, ', newton_tol = ', c%newton_tol, &
         ', newton_max_iter = ', c%newton_max_iter, ', reuse_jacobian = ', c%reuse_jacobian, &
         ', extrapolate = ', c%extrapolate, ', min_step_fraction = ', c%min_step_fraction, &
         ', max_wall_time = ', c%max_wall_time, ' /'
      text = text//trim(line)//new_line('a')
      write (line, '(3a,g0,3a,3(a,l1),a)') "&output file = '", trim(c%file), "', interval = ", c%interval, &
         ", fields = '", trim(c%fields), "'", ', quiet = ', c%quiet, ', energy = ', c%energy, &
         ', gnuplot = ', c%gnuplot, ' /'
      text = text//trim(line)//new_line('a')
   end function config_text

   !> Identifier starting at position i of a line.
   function word_at(line, i) result(word)
      character(*), intent(in) :: line
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

   pure logical function is_name_char(ch)
      character, intent(in) :: ch
      is_name_char = (ch >= 'a' .and. ch <= 'z') .or. (ch >= 'A' .and. ch <= 'Z') .or. &
                     (ch >= '0' .and. ch <= '9') .or. ch == '_'
   end function is_name_char

   pure integer function findloc_name(names, name)
      character(len=*), intent(in) :: names(:)
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

   function join_names(names, prefix) result(s)
      character(len=*), intent(in) :: names(:)
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
