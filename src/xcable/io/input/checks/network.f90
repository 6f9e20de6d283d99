!> The checks of a network of lines (&line_1 ... &line_8 between the network points, &point_k
!> with a kind). (A submodule of io/input/checks.f90.)
!>
!> A network is read and checked; the driver does not run one yet (driver/simulation.f90 refuses
!> it with one line). What a network may not have is refused here, each with one line naming the
!> file, the group, the variable, its value and what is allowed.
submodule (xcable_io_input_checks) xcable_io_input_checks_network
   use xcable_io_config, only: point_config, point_kinds, point_end_variables, point_body_variables
   implicit none

   !> Relative tolerance of a line's length against the sum of its segments' (as the single
   !> line's &cable length against its segments').
   real(dp), parameter :: length_tolerance = 1.0e-9_dp

contains

   !> What a case with &line groups may not have, before the segments and points are checked:
   !> &end_a or &end_b (the lines end at points), &static tension, the box scheme, the 2-D model,
   !> friction in the statics. Without &line groups: no network point (a kind without a line to
   !> end), no &rupture line.
   module subroutine check_network_groups(c, t, error)
      !> The case.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: lines, name
      integer :: k
      do k = 1, c%point_count
         call check_entry(c, t(find_entry(t, point_group(k), 'kind')), error)
         if (allocated(error)) return
      end do
      if (c%line_count == 0) then
         if (c%is_given('rupture', 'line')) then
            call fatal_error(error, c%source//': &rupture: line = '//str(c%break_line)//': only with &line groups '// &
                             '(the line of a network that parts); the single line breaks at s_break from its end a: '// &
                             'leave line out', stat_input)
            return
         end if
         do k = 1, c%point_count
            if (.not. c%points(k)%in_network()) cycle
            call fatal_error(error, c%source//': &'//trim(point_group(k))//": kind = '"//trim(c%points(k)%kind)// &
                             "': a network point without any &line group: a network point is an end of lines; "// &
                             "give &line_1 with end_a = '"//trim(point_group(k))//"' (and end_b), or leave kind out "// &
                             '(a body on the single line, at joint)', stat_input)
            return
         end do
         return
      end if
      lines = group_list([(line_group(k), k=1, c%line_count)], '&', '', ', ')
      do k = 1, 2
         name = first_given(merge('end_a', 'end_b', k == 1))
         if (len(name) == 0) cycle
         call fatal_error(error, c%source//': &'//merge('end_a', 'end_b', k == 1)//': '//name//' = '// &
                          value_text(c, t(find_entry(t, merge('end_a', 'end_b', k == 1), name)))//' with '//lines// &
                          ": the lines of a network end at its points; give them as &point_k (kind 'fixed', 'free' "// &
                          "or 'motion'), name them in &line_k end_a and end_b, and leave &end_a and &end_b out", &
                          stat_input)
         return
      end do
      if (c%is_given('static', 'tension')) then
         call fatal_error(error, c%source//': &static: tension = '//real_text(c%tension)//' with '//lines// &
                          ": the paper's symmetric catenary is a single line; the lines of a network end at its "// &
                          'points (&point_k x, y, z); leave &static out', stat_input)
         return
      end if
      if (trim(c%scheme) == 'box') then
         call fatal_error(error, c%source//": &numerics: scheme = 'box' with "//lines//': the box scheme has one '// &
                          "uniform planar cable; allowed: scheme = 'rod' for a network of lines", stat_input)
         return
      end if
      if (trim(c%model) == '2d') then
         call fatal_error(error, c%source//": &numerics: model = '2d' with "//lines//': a network of lines is '// &
                          "solved in 3-D; allowed: model = '3d' or 'auto' (3-D for a network)", stat_input)
         return
      end if
      if (trim(c%static_friction) /= 'none') then
         call fatal_error(error, c%source//": &seabed: static_friction = '"//trim(c%static_friction)//"' with "// &
                          lines//": a network's statics has no friction on the bottom (not yet; the dynamics have "// &
                          "it); allowed: static_friction = 'none'", stat_input)
         return
      end if

   contains

      !> The first variable of a group given in the file ('' : none).
      function first_given(group) result(name)
         character(*), intent(in) :: group
         character(:), allocatable :: name
         integer, allocatable :: mine(:)
         integer :: i
         name = ''
         mine = group_entries(t, group)
         do i = 1, size(mine)
            if (.not. c%is_given(group, trim(t(mine(i))%name))) cycle
            name = trim(t(mine(i))%name)
            return
         end do
      end function first_given
   end subroutine check_network_groups

   !> A network point (&point_k with a kind): no joint; only the variables its kind uses (the
   !> position for every kind, a body for 'free', the motion of an end of kind 'motion' for
   !> 'motion', with that kind's checks from the end registry); its table from its file; a free
   !> point's volume only in water and its drag only with an area; a held point above the seabed.
   module subroutine check_network_point(c, t, k, error)
      !> The case; the point's table read from its file and its direction normalised.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> The point, 1 .. point_count.
      integer, intent(in) :: k
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: group
      character(:), allocatable :: prefix, kind, name, uses
      type(end_config) :: e
      type(end_kind) :: line
      integer, allocatable :: mine(:)
      logical :: found
      real(dp) :: norm
      integer :: i
      group = point_group(k)
      prefix = c%source//': &'//trim(group)//': '
      kind = "kind = '"//trim(c%points(k)%kind)//"'"
      if (c%is_given(trim(group), 'joint')) then
         call fatal_error(error, prefix//'joint = '//str(c%points(k)%joint)//': given for '//kind//', a network '// &
                          'point: joint places a body on the single line (a point without kind); leave joint out '// &
                          '(the lines that end at the point name it in &line_k end_a or end_b)', stat_input)
         return
      end if
      uses = point_kind_variables(c%points(k)%kind)
      mine = group_entries(t, group)
      do i = 1, size(mine)
         name = trim(t(mine(i))%name)
         if (is_word(name, 'kind joint '//uses)) cycle
         if (.not. c%is_given(trim(group), name)) cycle
         if (is_word(name, point_body_variables)) then
            call fatal_error(error, prefix//name//' = '//value_text(c, t(mine(i)))//': given for '//kind// &
                             ', a held point: a body there does nothing; '//name//" is a variable of kind 'free' "// &
                             '(a junction) or of a body on the single line (no kind); leave '//name//' out', stat_input)
         else
            call fatal_error(error, prefix//name//' = '//value_text(c, t(mine(i)))//': given for '//kind// &
                             ', which does not use it: '//name//' is a variable of kind '// &
                             quoted_words(point_kinds_using(name), ' or ')//'; '//kind//' takes '// &
                             comma_list(uses), stat_input)
         end if
         return
      end do
      do i = 1, size(mine)
         call check_entry(c, t(mine(i)), error)
         if (allocated(error)) return
      end do
      e = c%point_end(k)
      if (trim(e%kind) == 'motion') then
         call load_table(c, trim(group), e, error)
         if (allocated(error)) return
         call find_end_kind('motion', line, found)
         if (found .and. associated(line%check)) then
            call line%check(prefix, e, end_config(), .true., error)
            if (allocated(error)) return
         end if
         norm = norm2([e%direction_x, e%direction_y, e%direction_z])
         if (norm > 0) then
            e%direction_x = e%direction_x/norm
            e%direction_y = e%direction_y/norm
            e%direction_z = e%direction_z/norm
         end if
         call check_column(prefix, 'table_time', e%table_time(1:e%table_rows), time_order, error)
         if (allocated(error)) return
      end if
      if (.not. allocated(c%point_ends)) allocate (c%point_ends(size(c%points)))
      c%point_ends(k) = e
      if (trim(e%kind) /= 'free' .and. c%has_seabed()) then
         if (e%z < c%seabed_z(e%x, e%y) - 1.0e-3_dp) then
            call fatal_error(error, prefix//'z = '//real_text(e%z)//': the '//trim(e%kind)//' point is below the '// &
                             'seabed (z = '//real_text(c%seabed_z(e%x, e%y))//' there); place it on or above the '// &
                             'bottom', stat_input)
            return
         end if
      end if
      if (c%points(k)%volume > 0 .and. c%fluid_density <= 0) then
         call fatal_error(error, prefix//'volume = '//real_text(c%points(k)%volume)//': buoyancy needs water; '// &
                          'give &fluid density, or volume = 0', stat_input)
         return
      end if
      if (c%points(k)%cd > 0 .and. c%points(k)%area <= 0) then
         call fatal_error(error, prefix//'cd = '//real_text(c%points(k)%cd)//' without an area: the drag acts '// &
                          'on area; give area > 0, or cd = 0', stat_input)
         return
      end if
   end subroutine check_network_point

   !> A body on the single line (&point_k without kind) in a case with &line groups: refused,
   !> as a line end (it must be a network point) or as a body on a line of the network (split
   !> the line at a free point instead).
   module subroutine check_body_in_network(c, k, error)
      !> The case.
      type(case_config), intent(in) :: c
      !> The point, 1 .. point_count.
      integer, intent(in) :: k
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: group
      character(:), allocatable :: joint
      integer :: l, side
      group = point_group(k)
      do l = 1, c%line_count
         do side = 1, 2
            if (c%lines(l)%end_point(side) /= k) cycle
            call fatal_error(error, c%source//': &'//trim(line_group(l))//': '//merge('end_a', 'end_b', side == 1)// &
                             " = '"//trim(c%lines(l)%point_names(side))//"': &"//trim(group)//' has no kind (a '// &
                             'body on the single line); a line ends at a network point: give &'//trim(group)// &
                             " kind = 'fixed', 'free' or 'motion'", stat_input)
            return
         end do
      end do
      joint = 'not given'
      if (c%is_given(trim(group), 'joint')) joint = '= '//str(c%points(k)%joint)
      call fatal_error(error, c%source//': &'//trim(group)//': joint '//joint//': a body on a joint of a line is '// &
                       "for the single line; in a network, split the line at a free point (&point_k kind = 'free', "// &
                       'with the mass, volume, ca, cd and area of the body) and end two &line_k groups there', &
                       stat_input)
   end subroutine check_body_in_network

   !> The lines of a network: each between two different network points that exist, its
   !> segments given &segment_k groups, its length (given for a uniform line or &cable length;
   !> with segments their sum) and nodes; every network point joins a line, every segment serves
   !> a line, and every group of lines joined through free points is held by a fixed or motion
   !> point. Sets each line's length and nodes where they follow from others.
   module subroutine check_lines(c, t, error)
      !> The case; the lines' lengths and nodes resolved.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: group
      character(:), allocatable :: prefix, name, terms
      integer :: l, side, p, i, j, n, given_nodes, line_nodes
      real(dp) :: total
      integer :: root(c%point_count)
      logical :: held(c%point_count)
      if (c%line_count == 0) return
      do l = 1, c%line_count
         group = line_group(l)
         prefix = c%source//': &'//trim(group)//': '
         associate (ln => c%lines(l))
            do side = 1, 2
               name = merge('end_a', 'end_b', side == 1)
               if (.not. c%is_given(trim(group), name)) then
                  call fatal_error(error, prefix//name//' not given: a line runs between two network points; '// &
                                   'give '//name//" = 'point_k' (a &point_k with kind 'fixed', 'free' or 'motion')", &
                                   stat_input)
                  return
               end if
               p = ln%end_point(side)
               if (p < 1 .or. p > c%point_count) then
                  call fatal_error(error, prefix//name//" = '"//shown(trim(ln%point_names(side)))//"': no such "// &
                                   'point; allowed: '//network_points()//" (the &point_k groups given with a kind)", &
                                   stat_input)
                  return
               end if
            end do
            if (ln%end_point(1) == ln%end_point(2)) then
               call fatal_error(error, prefix//"end_a = '"//trim(ln%point_names(1))//"', end_b = '"// &
                                trim(ln%point_names(2))//"': both ends on one point: a line closed on itself has no "// &
                                'first guess (the chord between its ends is zero); end it at two different points', &
                                stat_input)
               return
            end if
            call check_entry(c, t(find_entry(t, group, 'segments')), error)
            if (allocated(error)) return
            call check_entry(c, t(find_entry(t, group, 'length')), error)
            if (allocated(error)) return
            call check_entry(c, t(find_entry(t, group, 'nodes')), error)
            if (allocated(error)) return
            n = ln%segment_count
            do i = 1, n
               j = ln%segments(i)
               if (j <= c%segment_count) cycle
               if (c%segment_count == 0) then
                  call fatal_error(error, prefix//'segments('//str(i)//') = '//str(j)//': &'// &
                                   trim(segment_group(j))//' is not given, nor any &segment_k group; give it, or '// &
                                   'leave segments out (a uniform line of &cable and &material)', stat_input)
               else
                  call fatal_error(error, prefix//'segments('//str(i)//') = '//str(j)//': &'// &
                                   trim(segment_group(j))//' is not given; allowed: 1 .. '//str(c%segment_count)// &
                                   ' (the &segment_k groups given)', stat_input)
               end if
               return
            end do
            if (n > 0) then
               if (c%is_given(trim(group), 'nodes')) then
                  call fatal_error(error, prefix//'nodes = '//str(ln%nodes)//': given for a line of segments ('// &
                                   'segments = '//int_list(ln%segments(1:n))//'): each segment has its own nodes, '// &
                                   'or a share of &numerics nodes; leave nodes out', stat_input)
                  return
               end if
               total = sum(c%segments(ln%segments(1:n))%length)
               if (c%is_given(trim(group), 'length')) then
                  if (abs(total - ln%length) > length_tolerance*ln%length) then
                     terms = ''
                     do i = 1, n
                        if (i > 1) terms = terms//' + '
                        terms = terms//real_text(c%segments(ln%segments(i))%length)
                     end do
                     call fatal_error(error, prefix//'length = '//real_text(ln%length)//': the lengths of its '// &
                                      'segments ('//int_list(ln%segments(1:n))//') add up to '//terms//' = '// &
                                      real_text(total)//'; must be their sum, or leave length out (it is then '// &
                                      'their sum)', stat_input)
                     return
                  end if
               else
                  ln%length = total
               end if
               given_nodes = count(c%segments(ln%segments(1:n))%nodes > 0)
               if (given_nodes > 0 .and. given_nodes < n) then
                  do i = 1, n
                     if (c%segments(ln%segments(i))%nodes == 0) exit
                  end do
                  call fatal_error(error, prefix//'segments = '//int_list(ln%segments(1:n))//': &'// &
                                   trim(segment_group(ln%segments(i)))//' gives no nodes, while '//str(given_nodes)// &
                                   ' of the '//str(n)//' segments of the line give theirs: give nodes in every '// &
                                   'segment of the line, or in none (&numerics nodes are then shared by length)', &
                                   stat_input)
                  return
               end if
               if (given_nodes == 0 .and. c%nodes < 2*n + 1) then
                  call fatal_error(error, c%source//': &numerics: nodes = '//str(c%nodes)//': too few for the '// &
                                   str(n)//' segments of &'//trim(group)//', each of which takes at least 2 cells '// &
                                   'of its own; must be at least 2*'//str(n)//' + 1 = '//str(2*n + 1)//', or give '// &
                                   'nodes in every segment', stat_input)
                  return
               end if
               if (given_nodes == n) then
                  line_nodes = sum(c%segments(ln%segments(1:n))%nodes) - (n - 1)
                  if (line_nodes > 100001) then
                     call fatal_error(error, prefix//'segments = '//int_list(ln%segments(1:n))//': nodes = '// &
                                      str(line_nodes)//' on the line (the sum less the joints); must be at most '// &
                                      '100001', stat_input)
                     return
                  end if
               end if
            else
               if (.not. c%is_given(trim(group), 'length')) then
                  if (.not. c%is_given('cable', 'length')) then
                     call fatal_error(error, prefix//'length not given: a line without segments needs its '// &
                                      'unstretched length; give length (m, in [0.01, 100000]), or &cable length '// &
                                      '(then the length of every line without its own), or segments', stat_input)
                     return
                  end if
                  ln%length = c%length
               end if
               if (.not. c%is_given(trim(group), 'nodes')) ln%nodes = c%nodes
            end if
         end associate
      end do

      ! Every network point ends a line; every segment serves a line.
      do p = 1, c%point_count
         if (.not. c%points(p)%in_network()) cycle
         if (size(c%point_lines(p), 2) > 0) cycle
         call fatal_error(error, c%source//': &'//trim(point_group(p))//": kind '"//trim(c%points(p)%kind)// &
                          "' joins no line: name it in some &line_k end_a or end_b, or leave the point out", stat_input)
         return
      end do
      do j = 1, c%segment_count
         if (any([(any(c%lines(l)%segments(1:c%lines(l)%segment_count) == j), l=1, c%line_count)])) cycle
         call fatal_error(error, c%source//': &'//trim(segment_group(j))//': used by no line: the segments of a '// &
                          'network are listed in &line_k segments; list it there, or leave it out', stat_input)
         return
      end do

      ! The groups of lines joined at their points: each held by a fixed or motion point.
      root = [(p, p=1, c%point_count)]
      do l = 1, c%line_count
         call join(c%lines(l)%end_point(1), c%lines(l)%end_point(2))
      end do
      held = .false.
      do p = 1, c%point_count
         if (is_word(c%points(p)%kind, 'fixed motion')) held(top(p)) = .true.
      end do
      do l = 1, c%line_count
         p = top(c%lines(l)%end_point(1))
         if (held(p)) cycle
         terms = ''
         do i = 1, c%line_count
            if (top(c%lines(i)%end_point(1)) /= p) cycle
            if (len(terms) > 0) terms = terms//', '
            terms = terms//'&'//trim(line_group(i))
         end do
         name = ''
         do i = 1, c%point_count
            if (.not. c%points(i)%in_network() .or. top(i) /= p) cycle
            if (len(name) > 0) name = name//', '
            name = name//'&'//trim(point_group(i))
         end do
         call fatal_error(error, c%source//': &'//trim(line_group(l))//': '//terms//" joined at the points "// &
                          name//", all of kind 'free': nothing holds them, so they float and have no static "// &
                          "state; make one of those points kind 'fixed' or 'motion'", stat_input)
         return
      end do

   contains

      !> The network points as "'point_1', 'point_3'" ('none' when there is none).
      function network_points() result(text)
         character(:), allocatable :: text
         integer :: q
         text = ''
         do q = 1, c%point_count
            if (.not. c%points(q)%in_network()) cycle
            if (len(text) > 0) text = text//', '
            text = text//"'"//trim(point_group(q))//"'"
         end do
         if (len(text) == 0) text = 'none (no &point_k group has a kind)'
      end function network_points

      !> The root of a point's group.
      integer function top(q)
         integer, intent(in) :: q
         top = q
         do while (root(top) /= top)
            top = root(top)
         end do
      end function top

      !> Join the groups of two points.
      subroutine join(a, b)
         integer, intent(in) :: a, b
         integer :: ra, rb
         ra = top(a)
         rb = top(b)
         if (ra /= rb) root(max(ra, rb)) = min(ra, rb)
      end subroutine join
   end subroutine check_lines

   !> The break of a network (&rupture, after check_lines: the lines' ends and lengths known).
   !> Criterion 'time': the line that parts (&rupture line, 1 .. line_count; required when the
   !> break is enabled) and s_break along it from its end a, in [0, its length] (not given: its
   !> end b); a break at an end of the line only where that end's point is held ('fixed' or
   !> 'motion': a line lets go of it), not at a free point. Criterion 'tension' (enabled): no line,
   !> s_break nor time (where and when follow from the MBLs), and a breaking load for every line:
   !> &rupture mbl, or on a line of segments each segment's (check_segment_loads, as for the
   !> single line; every segment serves a line).
   module subroutine check_network_rupture(c, error)
      !> The case (validated lines).
      type(case_config), intent(in) :: c
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: prefix, lines, what, at, default
      real(dp) :: s, length
      integer :: l, side, p
      if (c%line_count == 0) return
      prefix = c%source//': &rupture: '
      lines = group_list([(line_group(l), l=1, c%line_count)], '&', '', ', ')
      if (c%break_enabled .and. trim(c%break_criterion) == 'tension') then
         what = ''
         if (c%is_given('rupture', 'line')) what = what//', line = '//str(c%break_line)
         if (c%is_given('rupture', 's_break')) what = what//', s_break = '//real_text(c%s_break)
         if (c%is_given('rupture', 'time')) what = what//', time = '//real_text(c%break_time)
         if (len(what) > 0) then
            call fatal_error(error, prefix//"criterion = 'tension'"//what//' with '//lines//': a line of the '// &
                             'network parts where and when its tension first reaches the MBL, so line, s_break and '// &
                             "time are not used; leave them out, or give criterion = 'time'", stat_input)
            return
         end if
         if (c%is_given('rupture', 'mbl') .and. c%mbl > 0) return
         what = 'not given'
         if (c%is_given('rupture', 'mbl')) what = real_text(c%mbl)
         do l = 1, c%line_count
            if (c%lines(l)%segment_count > 0) cycle
            call fatal_error(error, c%source//': &'//trim(line_group(l))//': a uniform line (no segments) and '// &
                             '&rupture mbl = '//what//": criterion = 'tension' needs the minimum breaking load of "// &
                             'every line, a tension above 0 N: give &rupture mbl (or make the line of &segment_k '// &
                             'groups, each with its mbl)', stat_input)
            return
         end do
         ! Every segment serves a line (check_lines): the single line's check over all of them.
         call check_segment_loads(c, error)
         return
      end if
      ! Criterion 'time' (or no break): the line that parts, and s_break along it.
      l = c%break_line
      if (l < 1 .or. l > c%line_count) then
         if (c%is_given('rupture', 'line')) then
            call fatal_error(error, prefix//'line = '//str(l)//': no such line; allowed: 1 .. '//str(c%line_count)// &
                             ' (the &line_k groups given: '//lines//')', stat_input)
            return
         end if
         if (.not. c%break_enabled) return
         call fatal_error(error, prefix//"line not given with criterion = 'time' and "//lines//': the break of a '// &
                          'network is on one of its lines; give line = 1 .. '//str(c%line_count)//' (s_break is '// &
                          "then measured along it from its end a), or criterion = 'tension'", stat_input)
         return
      end if
      length = c%lines(l)%length
      if (c%is_given('rupture', 's_break') .and. (c%s_break < 0 .or. c%s_break > length)) then
         call fatal_error(error, prefix//'s_break = '//real_text(c%s_break)//': must be from 0 to '// &
                          real_text(length)//', the length of &'//trim(line_group(l))//' (line = '//str(l)// &
                          '): s_break is measured along it from its end a', stat_input)
         return
      end if
      if (.not. c%break_enabled) return
      ! A break at an end of the line (within the scene's tolerance, scene/scene.f90 set_break).
      s = c%s_break
      default = ''
      if (s < 0) then
         s = length
         default = ' (not given: the end b of &'//trim(line_group(l))//')'
      end if
      if (s/length <= 1.0e-12_dp) then
         side = 1
      else if (s/length >= 1 - 1.0e-12_dp) then
         side = 2
      else
         return
      end if
      p = c%lines(l)%end_point(side)
      if (is_word(c%points(p)%kind, 'fixed motion')) return
      at = ', at end '//merge('a', 'b', side == 1)//' of &'//trim(line_group(l))//" (line = "//str(l)//'), &'// &
           trim(point_group(p))//" of kind '"//trim(c%points(p)%kind)//"'"
      call fatal_error(error, prefix//'s_break = '//real_text(s)//default//at//': a break at a free point: give '// &
                       's_break inside the line, 0 < s_break < '//real_text(length)//' (a line cannot let go of a '// &
                       "free point; a break at an end is for a 'fixed' or 'motion' point)", stat_input)
   end subroutine check_network_rupture

   !> The variables of &point_k a network point of a kind uses: the position; a free point's
   !> body; a motion point's, those of an end of kind 'motion' (the end registry's).
   function point_kind_variables(kind) result(words)
      !> 'fixed', 'free' or 'motion'.
      character(*), intent(in) :: kind
      character(:), allocatable :: words
      type(end_kind) :: line
      logical :: found
      select case (trim(kind))
      case ('free')
         words = 'x y z '//point_body_variables
      case default
         call find_end_kind(kind, line, found)
         words = 'x y z'
         if (found) words = trim(line%variables)
      end select
   end function point_kind_variables

   !> The kinds of network point that use a variable, blank-separated.
   function point_kinds_using(name) result(words)
      !> The variable.
      character(*), intent(in) :: name
      character(:), allocatable :: words
      character(:), allocatable :: kind
      integer :: pos
      words = ''
      pos = 1
      do
         call next_item(point_kinds, pos, kind)
         if (len(kind) == 0) exit
         if (.not. is_word(name, point_kind_variables(kind))) cycle
         if (len(words) > 0) words = words//' '
         words = words//kind
      end do
   end function point_kinds_using

   !> Blank-separated words as 'a, b, c'.
   function comma_list(words) result(text)
      character(*), intent(in) :: words
      character(:), allocatable :: text, item
      integer :: pos
      text = ''
      pos = 1
      do
         call next_item(words, pos, item)
         if (len(item) == 0) exit
         if (len(text) > 0) text = text//', '
         text = text//item
      end do
   end function comma_list

   !> Integers as '1, 2, 3'.
   function int_list(values) result(text)
      integer, intent(in) :: values(:)
      character(:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, size(values)
         if (i > 1) text = text//', '
         text = text//str(values(i))
      end do
   end function int_list
end submodule xcable_io_input_checks_network
