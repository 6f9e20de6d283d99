!> The tables of a case: the rows of a time table or of the material law, given inline or
!> read from a text file, and their checks (order, counts, finite values).
!> (Split from io/input.f90, which reads a case through these modules.)
module xcable_io_input_tables
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str, real_text
   use xcable_io_config, only: case_config, end_config, max_table_points
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use xcable_io_input_scanner, only: inline_rows, line_len, load_lines, next_item, shown, shown_length
   implicit none
   private
   public :: check_column, check_material_table, load_material_table, load_segment_table, load_table, time_order

   !> Why the columns of the tables must increase (ends of the messages on their order).
   character(len=*), parameter :: time_order = 'the times must increase strictly', &
                                  strain_order = 'the strains must increase strictly', &
                                  tension_order = "the tensions must increase strictly (a zero or negative slope f' "// &
                                                  'leaves the law without a real wave speed)'

contains

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
      call load_law_table(c%source//': &material: ', c%material_table_file, c%material_table_strain, &
                          c%material_table_tension, c%material_table_rows, error)
   end subroutine load_material_table

   !> Read the table_file of &segment_k, if given, into the segment's rows of the table law,
   !> as load_material_table reads &material's.
   subroutine load_segment_table(c, k, error)
      !> The case; the segment's table rows filled from the file.
      type(case_config), intent(inout) :: c
      !> Segment, 1 .. segment_count.
      integer, intent(in) :: k
      !> Error naming the case file, the segment's group, the table file and its line.
      type(error_type), allocatable, intent(out) :: error
      associate (g => c%segments(k))
         call load_law_table(c%source//': &segment_'//str(k)//': ', g%material_table_file, g%material_table_strain, &
                             g%material_table_tension, g%material_table_rows, error)
      end associate
   end subroutine load_segment_table

   !> Read the rows of a table law from its file ('' : none): strain and tension a line.
   subroutine load_law_table(group_prefix, file, strain, tension, rows, error)
      !> Start of every message: the case file and the group ('case.nml: &material: ').
      character(*), intent(in) :: group_prefix
      !> The table file.
      character(*), intent(in) :: file
      !> The strains and tensions; filled from the file.
      real(dp), intent(inout) :: strain(:), tension(:)
      !> Rows given inline in; rows read out.
      integer, intent(inout) :: rows
      !> Error naming the case file, the table file and its line.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: values(:, :)
      integer, allocatable :: lines(:)
      character(:), allocatable :: prefix
      integer :: n

      if (len_trim(file) == 0) return
      prefix = group_prefix//"table_file = '"//trim(file)//"': "
      call read_table_file(prefix, trim(file), 'table_strain', rows, 2, 2, &
                           'strain and tension', values, lines, n, error)
      if (allocated(error)) return
      call check_column(prefix, 'strain', values(1:n, 1), strain_order, error, lines(1:n))
      if (allocated(error)) return
      call check_column(prefix, 'tension', values(1:n, 2), tension_order, error, lines(1:n))
      if (allocated(error)) return
      strain(1:n) = values(1:n, 1)
      tension(1:n) = values(1:n, 2)
      rows = n
   end subroutine load_law_table

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
   subroutine check_material_table(c, error, group)
      !> The case (law word and rows checked against the schema).
      type(case_config), intent(in) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      !> The group named in messages (default 'material'; 'segment_k' for the case as a segment sees it).
      character(*), intent(in), optional :: group
      character(:), allocatable :: prefix, rows, law
      integer :: k, n
      prefix = c%source//': &material: '
      if (present(group)) prefix = c%source//': &'//group//': '
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
end module xcable_io_input_tables
