!> The checks of the bodies on the line (&point_1 ... &point_8). (A submodule of
!> io/input/checks.f90.)
submodule (xcable_io_input_checks) xcable_io_input_checks_points
   use xcable_io_config, only: point_end_variables
   implicit none

contains

   !> The bodies at the joints (&point_1 ... &point_n, numbered without a gap, which the reader
   !> checks): each on a joint of the line's segments or on an end that is not held, one body per
   !> joint, its variables in their ranges; a volume only in water, a drag coefficient only with
   !> an area.
   module subroutine check_points(c, t, error)
      !> The case.
      type(case_config), intent(inout) :: c
      !> The schema.
      type(schema_entry), intent(in) :: t(:)
      !> Error naming file, group, variable, value and what is allowed.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: prefix
      character(len=16) :: group
      integer :: k, i, j
      do k = 1, c%point_count
         group = point_group(k)
         prefix = c%source//': &'//trim(group)//': '
         ! A network point (a kind given), and a body in a network, have checks of their own.
         if (c%points(k)%in_network()) then
            call check_network_point(c, t, k, error)
            if (allocated(error)) return
            cycle
         end if
         if (c%line_count > 0) then
            call check_body_in_network(c, k, error)
            return
         end if
         ! A network point's variables without a kind.
         do i = 1, size(t)
            if (trim(t(i)%group) /= trim(group) .or. .not. is_word(t(i)%name, point_end_variables)) cycle
            if (.not. c%is_given(trim(group), trim(t(i)%name))) cycle
            call fatal_error(error, prefix//trim(t(i)%name)//' = '//value_text(c, t(i))//': given for a point '// &
                             'without kind (a body on the single line, at joint): '//trim(t(i)%name)//' is a '// &
                             "variable of a network point (kind 'fixed', 'free' or 'motion', the end of a &line_k); "// &
                             'leave '//trim(t(i)%name)//' out', stat_input)
            return
         end do
         if (.not. c%is_given(trim(group), 'joint')) then
            call fatal_error(error, prefix//'joint not given: a point sits on a joint of two segments; give joint = '// &
                             'k for the end of &segment_k', stat_input)
            return
         end if
         j = c%points(k)%joint
         if (trim(c%scheme) == 'box') then
            call fatal_error(error, c%source//": &numerics: scheme = 'box' with &"//trim(group)//': the box scheme '// &
                             "has no bodies on its line; allowed: scheme = 'rod'", stat_input)
            return
         end if
         if (j < 0 .or. j > c%segments_of_line()) then
            call fatal_error(error, prefix//'joint = '//str(j)//': the line has '//str(c%segments_of_line())// &
                             ' segment(s); allowed: 0 .. '//str(c%segments_of_line())//' (0 is end a, k the end '// &
                             'of &segment_k, '//str(c%segments_of_line())//' end b)', stat_input)
            return
         end if
         if ((j == 0 .and. is_word(c%end_a%kind, end_kind_names(held=.true.))) .or. &
             (j == c%segments_of_line() .and. is_word(c%end_b%kind, end_kind_names(held=.true.)))) then
            call fatal_error(error, prefix//'joint = '//str(j)//': that is end '//merge('a', 'b', j == 0)// &
                             ", which is held (kind '"//trim(merge(c%end_a%kind, c%end_b%kind, j == 0))// &
                             "'): its support carries the body; allowed: a point on a joint or on an end of kind "// &
                             quoted_words(end_kind_names(held=.false.), ' or '), stat_input)
            return
         end if
         do i = 1, size(t)
            if (trim(t(i)%group) /= trim(group)) cycle
            call check_entry(c, t(i), error)
            if (allocated(error)) return
         end do
         do i = 1, k - 1
            if (c%points(i)%joint /= j) cycle
            call fatal_error(error, prefix//'joint = '//str(j)//': &'//trim(point_group(i))//' sits on it already; '// &
                             'allowed: one point per joint (give their mass, volume and area together)', stat_input)
            return
         end do
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
      end do
   end subroutine check_points
end submodule xcable_io_input_checks_points
