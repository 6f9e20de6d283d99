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
!> read_end, read_segment) and the generic code needs a way from a schema entry to its
!> component of case_config (access); the suite input checks both against
!> the schema for every entry.
!>
!> The parts live in io/input/: the scanner (scanner.f90), the way from a schema entry to its
!> component (access.f90), the tables inline or from files (tables.f90), the validation
!> (checks.f90) and the echo (echo.f90). This module holds the order of it all and the namelist
!> reads, and gives the names the rest of the code uses.
module xcable_io_input
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_io_config, only: case_config, end_config, segment_config, point_config, line_config, max_table_points, &
                               max_segments, point_end_variables
   use xcable_io_schema, only: schema_entry, schema_table, schema_groups, find_entry, known_fields, segment_of, &
                               segment_group, point_of, point_group, line_of, line_group
   use xcable_core_strings, only: to_lower
   use xcable_io_input_scanner, only: count_table_rows, line_len, load_lines, lower_words, scan_groups
   use xcable_io_input_echo, only: config_text, value_text
   use xcable_io_input_checks, only: derive_defaults, max_time_steps, validate
   implicit none
   private
   public :: case_config, read_config, read_values, config_text, value_text, known_fields, derive_defaults, &
             max_time_steps

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
   !> names, value types), count the segments (refusing a gap in their
   !> numbering), read the groups that are present, record which
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
      ! The segments, numbered from end a without a gap: as many as the highest number given.
      do i = 1, size(groups)
         if (present_group(i)) config%segment_count = max(config%segment_count, segment_of(groups(i)))
      end do
      do i = 1, config%segment_count
         if (any(groups == segment_group(i) .and. present_group)) cycle
         call fatal_error(error, path//': &'//trim(segment_group(config%segment_count))//' given without &'// &
                          trim(segment_group(i))//': the segments are numbered from end a, 1, 2, ... without a '// &
                          'gap; give &'//trim(segment_group(i))//' or renumber', stat_input)
         return
      end do
      ! The bodies at the joints, numbered alike.
      do i = 1, size(groups)
         if (present_group(i)) config%point_count = max(config%point_count, point_of(groups(i)))
      end do
      do i = 1, config%point_count
         if (any(groups == point_group(i) .and. present_group)) cycle
         call fatal_error(error, path//': &'//trim(point_group(config%point_count))//' given without &'// &
                          trim(point_group(i))//': the points are numbered 1, 2, ... without a gap; give &'// &
                          trim(point_group(i))//' or renumber', stat_input)
         return
      end do
      ! The lines of a network, numbered alike.
      do i = 1, size(groups)
         if (present_group(i)) config%line_count = max(config%line_count, line_of(groups(i)))
      end do
      do i = 1, config%line_count
         if (any(groups == line_group(i) .and. present_group)) cycle
         call fatal_error(error, path//': &'//trim(line_group(config%line_count))//' given without &'// &
                          trim(line_group(i))//': the lines are numbered 1, 2, ... without a gap; give &'// &
                          trim(line_group(i))//' or renumber', stat_input)
         return
      end do
      call read_groups(path, config, groups, present_group, error)
      if (allocated(error)) return
      ! The points' ends only where a variable of them is given (bodies on the single line have none).
      if (allocated(config%point_ends)) then
         if (.not. any([(any(counts(point_end_entries(point_group(i))) > 0), i=1, config%point_count)])) &
            deallocate (config%point_ends)
      end if
      ! A line's segments: as many as the values given; its ends: the numbers of the points named.
      do i = 1, config%line_count
         config%lines(i)%segment_count = min(counts(find_entry(t, line_group(i), 'segments')), max_segments)
         config%lines(i)%end_point(1) = named_point(config%lines(i)%point_names(1))
         config%lines(i)%end_point(2) = named_point(config%lines(i)%point_names(2))
      end do
      config%given = ''
      do i = 1, size(t)
         if (counts(i) > 0) config%given = config%given//' '//trim(t(i)%group)//'%'//trim(t(i)%name)
      end do
      config%given = adjustl(config%given)
      ! (The words given: those not given are their defaults, in lower case.)
      do i = 1, size(t)
         if (len_trim(t(i)%choices) > 0 .and. counts(i) > 0) call lower_words(config, t(i))
      end do
      ! A network point's end has the point's kind.
      if (allocated(config%point_ends)) config%point_ends(1:config%point_count)%kind = &
         config%points(1:config%point_count)%kind
      call count_table_rows(config, t, counts, error)

   contains

      !> The entries of a point's end (its kind, position and motion) in the schema.
      function point_end_entries(group) result(indices)
         character(*), intent(in) :: group
         integer, allocatable :: indices(:)
         integer :: j
         allocate (indices(0))
         do j = 1, size(t)
            if (t(j)%group /= group) cycle
            if (t(j)%name == 'kind' .or. index(' '//point_end_variables//' ', ' '//trim(t(j)%name)//' ') > 0) &
               indices = [indices, j]
         end do
      end function point_end_entries
   end subroutine read_values

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
      integer :: nodes, newton_max_iter, line
      logical :: enabled, reuse_jacobian, extrapolate, skip_quiescent, quiet, energy, gnuplot, xdmf
      character(len=512) :: file, table_file
      character(len=256) :: fields
      namelist /cable/ length, diameter, density, young, gravity, area, bending_stiffness, gip
      namelist /material/ law, p, ea, table_strain, table_tension, table_file, strain_max, compression, damping
      namelist /static/ tension
      namelist /rupture/ enabled, s_break, t_break, time, criterion, mbl, line
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
      criterion = c%break_criterion; mbl = c%mbl; line = c%break_line
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
         case ('seabed')
            call read_seabed(unit, c, ios, msg)
         case ('rupture')
            read (unit, nml=rupture, iostat=ios, iomsg=msg)
         case ('numerics')
            read (unit, nml=numerics, iostat=ios, iomsg=msg)
         case ('output')
            read (unit, nml=output, iostat=ios, iomsg=msg)
         case ('segment_1', 'segment_2', 'segment_3', 'segment_4', 'segment_5', 'segment_6', 'segment_7', 'segment_8')
            ! A segment's p starts from &material's (read before it): p(2) = ... changes one coefficient.
            c%segments(segment_of(group_names(ig)))%p = p
            call read_segment(unit, segment_of(group_names(ig)), c%segments(segment_of(group_names(ig))), ios, msg)
         case ('point_1', 'point_2', 'point_3', 'point_4', 'point_5', 'point_6', 'point_7', 'point_8')
            ! The points' ends are read whole (read_values keeps them where a variable of them is given).
            if (.not. allocated(c%point_ends)) allocate (c%point_ends(size(c%points)))
            call read_point(unit, point_of(group_names(ig)), c%points(point_of(group_names(ig))), &
                            c%point_ends(point_of(group_names(ig))), ios, msg)
         case ('line_1', 'line_2', 'line_3', 'line_4', 'line_5', 'line_6', 'line_7', 'line_8')
            call read_line(unit, line_of(group_names(ig)), c%lines(line_of(group_names(ig))), ios, msg)
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
      c%break_criterion = criterion; c%mbl = mbl; c%break_line = line
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

   !> Read &segment_k into one segment (the namelist groups have the names &segment_1 ...
   !> &segment_8 and the same variables).
   subroutine read_segment(unit, k, seg, ios, msg)
      !> Open namelist file, rewound.
      integer, intent(in) :: unit
      !> Segment, 1 .. max_segments.
      integer, intent(in) :: k
      !> The segment: defaults in, values given out.
      type(segment_config), intent(inout) :: seg
      !> iostat of the read.
      integer, intent(out) :: ios
      !> iomsg of the read.
      character(len=*), intent(inout) :: msg
      real(dp) :: length, diameter, density, young, area, bending_stiffness, gip, p(5), ea, strain_max, damping, &
                  cd_normal, cd_tangential, ca_normal, mbl
      real(dp) :: table_strain(max_table_points), table_tension(max_table_points)
      character(len=16) :: law, compression
      character(len=512) :: table_file
      integer :: nodes
      namelist /segment_1/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_2/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_3/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_4/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_5/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_6/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_7/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      namelist /segment_8/ length, diameter, density, young, area, bending_stiffness, gip, law, p, ea, table_strain, &
         table_tension, table_file, strain_max, compression, damping, cd_normal, cd_tangential, ca_normal, nodes, mbl
      length = seg%length; diameter = seg%diameter; density = seg%density; young = seg%young; area = seg%area
      bending_stiffness = seg%bending_stiffness; gip = seg%gip; law = seg%law; p = seg%p; ea = seg%ea
      table_strain = seg%material_table_strain; table_tension = seg%material_table_tension
      table_file = seg%material_table_file; strain_max = seg%strain_max; compression = seg%compression
      damping = seg%damping; cd_normal = seg%cd_normal; cd_tangential = seg%cd_tangential; ca_normal = seg%ca_normal
      nodes = seg%nodes; mbl = seg%mbl
      select case (k)
      case (1); read (unit, nml=segment_1, iostat=ios, iomsg=msg)
      case (2); read (unit, nml=segment_2, iostat=ios, iomsg=msg)
      case (3); read (unit, nml=segment_3, iostat=ios, iomsg=msg)
      case (4); read (unit, nml=segment_4, iostat=ios, iomsg=msg)
      case (5); read (unit, nml=segment_5, iostat=ios, iomsg=msg)
      case (6); read (unit, nml=segment_6, iostat=ios, iomsg=msg)
      case (7); read (unit, nml=segment_7, iostat=ios, iomsg=msg)
      case (8); read (unit, nml=segment_8, iostat=ios, iomsg=msg)
      case default
         ios = 1
         msg = 'no namelist read for this segment (max_segments above 8 in io/config.f90)'
      end select
      if (ios /= 0) return
      seg%length = length; seg%diameter = diameter; seg%density = density; seg%young = young; seg%area = area
      seg%bending_stiffness = bending_stiffness; seg%gip = gip; seg%law = law; seg%p = p; seg%ea = ea
      seg%material_table_strain = table_strain; seg%material_table_tension = table_tension
      seg%material_table_file = table_file; seg%strain_max = strain_max; seg%compression = compression
      seg%damping = damping; seg%cd_normal = cd_normal; seg%cd_tangential = cd_tangential; seg%ca_normal = ca_normal
      seg%nodes = nodes; seg%mbl = mbl
   end subroutine read_segment

   !> Read &point_k into one body or network point (the groups &point_1 ... &point_8 have the same
   !> variables).
   subroutine read_point(unit, k, pt, e, ios, msg)
      !> Open namelist file, rewound.
      integer, intent(in) :: unit
      !> Point, 1 .. max_points.
      integer, intent(in) :: k
      !> The point: defaults in, values given out.
      type(point_config), intent(inout) :: pt
      !> Its end (a network point's position and motion): defaults in, values given out.
      type(end_config), intent(inout) :: e
      !> iostat of the read.
      integer, intent(out) :: ios
      !> iomsg of the read.
      character(len=*), intent(inout) :: msg
      real(dp) :: mass, volume, ca, cd, area
      integer :: joint
      character(len=16) :: kind, motion
      real(dp) :: x, y, z, amplitude, period, phase, direction_x, direction_y, direction_z, ramp_time
      real(dp) :: table_time(max_table_points), table_x(max_table_points), table_y(max_table_points), &
                  table_z(max_table_points)
      character(len=512) :: table_file
      namelist /point_1/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_2/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_3/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_4/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_5/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_6/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_7/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      namelist /point_8/ joint, mass, volume, ca, cd, area, kind, x, y, z, motion, amplitude, period, phase, &
         direction_x, direction_y, direction_z, ramp_time, table_time, table_x, table_y, table_z, table_file
      joint = pt%joint; mass = pt%mass; volume = pt%volume; ca = pt%ca; cd = pt%cd; area = pt%area
      kind = pt%kind; x = e%x; y = e%y; z = e%z; motion = e%motion; amplitude = e%amplitude; period = e%period
      phase = e%phase; direction_x = e%direction_x; direction_y = e%direction_y; direction_z = e%direction_z
      ramp_time = e%ramp_time; table_time = e%table_time; table_x = e%table_x; table_y = e%table_y
      table_z = e%table_z; table_file = e%table_file
      select case (k)
      case (1); read (unit, nml=point_1, iostat=ios, iomsg=msg)
      case (2); read (unit, nml=point_2, iostat=ios, iomsg=msg)
      case (3); read (unit, nml=point_3, iostat=ios, iomsg=msg)
      case (4); read (unit, nml=point_4, iostat=ios, iomsg=msg)
      case (5); read (unit, nml=point_5, iostat=ios, iomsg=msg)
      case (6); read (unit, nml=point_6, iostat=ios, iomsg=msg)
      case (7); read (unit, nml=point_7, iostat=ios, iomsg=msg)
      case (8); read (unit, nml=point_8, iostat=ios, iomsg=msg)
      case default
         ios = 1
         msg = 'no namelist read for this point (max_points above 8 in io/config.f90)'
      end select
      if (ios /= 0) return
      pt%joint = joint; pt%mass = mass; pt%volume = volume; pt%ca = ca; pt%cd = cd; pt%area = area
      pt%kind = kind
      e%kind = kind; e%x = x; e%y = y; e%z = z; e%motion = motion; e%amplitude = amplitude; e%period = period
      e%phase = phase; e%direction_x = direction_x; e%direction_y = direction_y; e%direction_z = direction_z
      e%ramp_time = ramp_time; e%table_time = table_time; e%table_x = table_x; e%table_y = table_y
      e%table_z = table_z; e%table_file = table_file
   end subroutine read_point

   !> Read &line_k into one line of a network (the groups &line_1 ... &line_8 have the same
   !> variables).
   subroutine read_line(unit, k, ln, ios, msg)
      !> Open namelist file, rewound.
      integer, intent(in) :: unit
      !> Line, 1 .. max_lines.
      integer, intent(in) :: k
      !> The line: defaults in, values given out.
      type(line_config), intent(inout) :: ln
      !> iostat of the read.
      integer, intent(out) :: ios
      !> iomsg of the read.
      character(len=*), intent(inout) :: msg
      character(len=16) :: end_a, end_b
      integer :: segments(max_segments), nodes
      real(dp) :: length
      namelist /line_1/ end_a, end_b, segments, length, nodes
      namelist /line_2/ end_a, end_b, segments, length, nodes
      namelist /line_3/ end_a, end_b, segments, length, nodes
      namelist /line_4/ end_a, end_b, segments, length, nodes
      namelist /line_5/ end_a, end_b, segments, length, nodes
      namelist /line_6/ end_a, end_b, segments, length, nodes
      namelist /line_7/ end_a, end_b, segments, length, nodes
      namelist /line_8/ end_a, end_b, segments, length, nodes
      end_a = ln%point_names(1); end_b = ln%point_names(2); segments = ln%segments; length = ln%length
      nodes = ln%nodes
      select case (k)
      case (1); read (unit, nml=line_1, iostat=ios, iomsg=msg)
      case (2); read (unit, nml=line_2, iostat=ios, iomsg=msg)
      case (3); read (unit, nml=line_3, iostat=ios, iomsg=msg)
      case (4); read (unit, nml=line_4, iostat=ios, iomsg=msg)
      case (5); read (unit, nml=line_5, iostat=ios, iomsg=msg)
      case (6); read (unit, nml=line_6, iostat=ios, iomsg=msg)
      case (7); read (unit, nml=line_7, iostat=ios, iomsg=msg)
      case (8); read (unit, nml=line_8, iostat=ios, iomsg=msg)
      case default
         ios = 1
         msg = 'no namelist read for this line (max_lines above 8 in io/config.f90)'
      end select
      if (ios /= 0) return
      ln%point_names = [end_a, end_b]; ln%segments = segments; ln%length = length; ln%nodes = nodes
   end subroutine read_line

   !> The point a line end names: k for 'point_k' (any case, blanks and a leading '&' aside), 0
   !> for anything else.
   pure integer function named_point(name)
      !> As written in &line_k end_a or end_b.
      character(*), intent(in) :: name
      character(:), allocatable :: word
      word = to_lower(trim(adjustl(name)))
      if (len(word) > 0) then
         if (word(1:1) == '&') word = adjustl(word(2:))
      end if
      named_point = point_of(word)
   end function named_point

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
      real(dp) :: density, cd_normal, cd_tangential, ca_normal, current_x, current_y, current_z, surface_z, &
                  air_density, surface_band
      namelist /fluid/ density, cd_normal, cd_tangential, ca_normal, current_x, current_y, current_z, surface_z, &
         air_density, surface_band
      density = c%fluid_density; cd_normal = c%cd_normal; cd_tangential = c%cd_tangential
      ca_normal = c%ca_normal; current_x = c%current_x; current_z = c%current_z; current_y = c%current_y
      surface_z = c%surface_z; air_density = c%air_density; surface_band = c%surface_band
      read (unit, nml=fluid, iostat=ios, iomsg=msg)
      if (ios /= 0) return
      c%fluid_density = density; c%cd_normal = cd_normal; c%cd_tangential = cd_tangential
      c%ca_normal = ca_normal; c%current_x = current_x; c%current_z = current_z; c%current_y = current_y
      c%surface_z = surface_z; c%air_density = air_density; c%surface_band = surface_band
   end subroutine read_fluid

   !> Read &seabed into the case.
   subroutine read_seabed(unit, c, ios, msg)
      !> Open namelist file, rewound.
      integer, intent(in) :: unit
      !> The case: defaults in, values given out.
      type(case_config), intent(inout) :: c
      !> iostat of the read.
      integer, intent(out) :: ios
      !> iomsg of the read.
      character(len=*), intent(inout) :: msg
      real(dp) :: depth, slope_x, slope_y, stiffness, damping, mu_axial, mu_lateral, slip_velocity
      character(len=16) :: static_friction
      character(len=512) :: bathymetry_file
      namelist /seabed/ depth, slope_x, slope_y, stiffness, damping, mu_axial, mu_lateral, slip_velocity, &
         static_friction, bathymetry_file
      depth = c%seabed_depth; slope_x = c%seabed_slope_x; slope_y = c%seabed_slope_y
      stiffness = c%seabed_stiffness; damping = c%seabed_damping; mu_axial = c%mu_axial
      mu_lateral = c%mu_lateral; slip_velocity = c%slip_velocity; static_friction = c%static_friction
      bathymetry_file = c%bathymetry_file
      read (unit, nml=seabed, iostat=ios, iomsg=msg)
      if (ios /= 0) return
      c%seabed_depth = depth; c%seabed_slope_x = slope_x; c%seabed_slope_y = slope_y
      c%seabed_stiffness = stiffness; c%seabed_damping = damping; c%mu_axial = mu_axial
      c%mu_lateral = mu_lateral; c%slip_velocity = slip_velocity; c%static_friction = static_friction
      c%bathymetry_file = bathymetry_file
   end subroutine read_seabed
end module xcable_io_input
