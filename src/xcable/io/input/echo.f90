!> The resolved case as namelist text (its echo into the result file, and the fingerprint a
!> checkpoint is checked against).
!> (Split from io/input.f90, which reads a case through these modules.)
module xcable_io_input_echo
   use xcable_core_strings, only: str, real_text
   use xcable_io_config, only: case_config, end_config, point_end_variables, point_body_variables
   use xcable_ends_registry, only: end_kind, find_end_kind
   use xcable_io_schema, only: schema_entry, schema_table, schema_groups, group_entries, segment_of, point_of, &
                               line_of
   use xcable_io_input_access, only: access, config_value, get_value
   use xcable_io_input_scanner, only: is_word
   implicit none
   private
   public :: config_text, value_text

contains

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
               if (is_list(e)) n = size(v%reals)
               ! (An integer list without elements, &line_k segments not given, is not written.)
               if (n == 0) cycle
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
      if (.not. is_list(e)) then
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
         if (e%count > 1) then
            text = str(nint(v%reals(k)))
         else
            text = str(v%int)
         end if
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

   !> Whether a value is a list of elements in v%reals: a real, or an integer list.
   pure logical function is_list(e)
      !> The variable.
      type(schema_entry), intent(in) :: e
      is_list = e%type == 'real' .or. (e%type == 'integer' .and. e%count > 1)
   end function is_list

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
   !> no table without rows, and no table_file unless given; of &segment_k only the
   !> variables given, for the segments given; &point_k for the points given.
   logical function echoed(c, e, position_b)
      !> The case.
      type(case_config), intent(in) :: c
      !> The variable.
      type(schema_entry), intent(in) :: e
      !> Whether a position of end b was given (given_position_b).
      logical, intent(in) :: position_b
      echoed = .true.
      ! &segment_k: the segments given, and of each the variables given (the others take the
      ! line's values): a case without segments has the echo it had before them.
      if (segment_of(e%group) > 0) then
         echoed = segment_of(e%group) <= c%segment_count
         if (.not. echoed) return
         associate (g => c%segments(segment_of(e%group)))
            select case (e%name)
            case ('table_strain', 'table_tension')
               echoed = g%material_table_rows > 0
            case ('table_file')
               echoed = len_trim(g%material_table_file) > 0
            case default
               echoed = c%is_given(trim(e%group), trim(e%name))
            end select
         end associate
         return
      end if
      ! &point_k: the points given; a body on the single line (no kind) with its joint and body
      ! as before networks; a network point with its kind and position, a free one's body and a
      ! motion point's motion (its table as an end's).
      if (point_of(e%group) > 0) then
         echoed = point_of(e%group) <= c%point_count
         if (.not. echoed) return
         associate (pt => c%points(point_of(e%group)))
            if (.not. pt%in_network()) then
               echoed = .not. (e%name == 'kind' .or. is_word(e%name, point_end_variables))
            else if (e%name == 'joint') then
               echoed = .false.
            else if (is_word(e%name, point_body_variables)) then
               echoed = trim(pt%kind) == 'free'
            else if (e%name == 'kind' .or. is_word(e%name, 'x y z')) then
               echoed = .true.
            else
               echoed = trim(pt%kind) == 'motion' .and. end_echoed(c%point_end(point_of(e%group)), e)
            end if
         end associate
         return
      end if
      ! &line_k: the lines given; the segments of a line of segments, the nodes of a uniform one.
      if (line_of(e%group) > 0) then
         echoed = line_of(e%group) <= c%line_count
         if (.not. echoed) return
         select case (e%name)
         case ('segments')
            echoed = c%lines(line_of(e%group))%segment_count > 0
         case ('nodes')
            echoed = c%lines(line_of(e%group))%segment_count == 0
         end select
         return
      end if
      ! A network of lines: its ends are its points (no &end_a, &end_b, nor the tension of the
      ! symmetric catenary).
      if (c%line_count > 0 .and. (e%group == 'static' .or. e%group == 'end_a' .or. e%group == 'end_b')) then
         echoed = .false.
         return
      end if
      if (e%group == 'static' .and. e%name == 'tension') echoed = .not. position_b .and. &
         is_word(c%end_a%kind, 'fixed') .and. is_word(c%end_b%kind, 'fixed')
      ! &rupture: criterion and mbl for a break by tension, s_break and time for one by time
      ! (the echo of a case by time is that of the cases before the criterion), and a network's
      ! line that parts.
      if (e%group == 'rupture') then
         select case (e%name)
         case ('criterion', 'mbl')
            echoed = trim(c%break_criterion) == 'tension'
         case ('s_break', 'time')
            echoed = trim(c%break_criterion) /= 'tension'
         case ('line')
            ! (Only a network's break by time names a line: the echo of other cases as before.)
            echoed = c%line_count > 0 .and. c%break_line > 0 .and. trim(c%break_criterion) /= 'tension'
         end select
         return
      end if
      ! &fluid surface_band: its default (the diameter) is not a value of its range.
      if (e%group == 'fluid' .and. e%name == 'surface_band') then
         echoed = c%surface_band >= 0
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
end module xcable_io_input_echo
