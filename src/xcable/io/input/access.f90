!> From a schema entry to its component of case_config and back (`access`): the generic code's
!> way to read, check and echo any variable by its table row.
!> (Split from io/input.f90, which reads a case through these modules.)
module xcable_io_input_access
   use xcable_core_kinds, only: dp
   use xcable_io_config, only: case_config, end_config, segment_config, point_config, line_config, point_end_variables, &
                               max_points
   use xcable_io_schema, only: schema_entry, segment_of, point_of, line_of
   implicit none
   private
   public :: access, config_value, get_value

   !> The value of one variable, on its way between case_config and the generic code.
   type :: config_value
      !> Whether the variable is known to `access`.
      logical :: found = .false.
      !> A real or the elements of a real array (a table: its rows); the elements of an integer
      !> list (&line_k segments).
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
      if (segment_of(e%group) > 0) then
         call access_segment(c%segments(segment_of(e%group)), e%name, v, store)
         return
      end if
      if (point_of(e%group) > 0) then
         if (index(' '//point_end_variables//' ', ' '//trim(e%name)//' ') > 0) then
            call access_point_end(c, point_of(e%group), e%name, v, store)
         else
            call access_point(c%points(point_of(e%group)), e%name, v, store)
         end if
         return
      end if
      if (line_of(e%group) > 0) then
         call access_line(c%lines(line_of(e%group)), e%name, v, store)
         return
      end if
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
      case ('fluid%surface_z'); call move(c%surface_z, v, store)
      case ('fluid%air_density'); call move(c%air_density, v, store)
      case ('fluid%surface_band'); call move(c%surface_band, v, store)
      case ('seabed%depth'); call move(c%seabed_depth, v, store)
      case ('seabed%slope_x'); call move(c%seabed_slope_x, v, store)
      case ('seabed%slope_y'); call move(c%seabed_slope_y, v, store)
      case ('seabed%stiffness'); call move(c%seabed_stiffness, v, store)
      case ('seabed%damping'); call move(c%seabed_damping, v, store)
      case ('seabed%mu_axial'); call move(c%mu_axial, v, store)
      case ('seabed%mu_lateral'); call move(c%mu_lateral, v, store)
      case ('seabed%slip_velocity'); call move(c%slip_velocity, v, store)
      case ('seabed%static_friction'); call move(c%static_friction, v, store)
      case ('seabed%bathymetry_file'); call move(c%bathymetry_file, v, store)
      case ('static%tension'); call move(c%tension, v, store)
      case ('rupture%enabled'); call move(c%break_enabled, v, store)
      case ('rupture%s_break'); call move(c%s_break, v, store)
      case ('rupture%t_break'); call move(c%t_break, v, store)
      case ('rupture%time'); call move(c%break_time, v, store)
      case ('rupture%criterion'); call move(c%break_criterion, v, store)
      case ('rupture%mbl'); call move(c%mbl, v, store)
      case ('rupture%line'); call move(c%break_line, v, store)
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

   !> `access` for the variables of &segment_1 ... &segment_8.
   subroutine access_segment(g, name, v, store)
      !> The segment.
      type(segment_config), intent(inout) :: g
      !> Variable name.
      character(*), intent(in) :: name
      !> Its value.
      type(config_value), intent(inout) :: v
      !> Whether to set the component from v.
      logical, intent(in) :: store
      select case (name)
      case ('length'); call move(g%length, v, store)
      case ('diameter'); call move(g%diameter, v, store)
      case ('density'); call move(g%density, v, store)
      case ('young'); call move(g%young, v, store)
      case ('area'); call move(g%area, v, store)
      case ('bending_stiffness'); call move(g%bending_stiffness, v, store)
      case ('gip'); call move(g%gip, v, store)
      case ('law'); call move(g%law, v, store)
      case ('p'); call move(g%p, v, store)
      case ('ea'); call move(g%ea, v, store)
      case ('table_strain'); call move_rows(g%material_table_strain, g%material_table_rows, v, store)
      case ('table_tension'); call move_rows(g%material_table_tension, g%material_table_rows, v, store)
      case ('table_file'); call move(g%material_table_file, v, store)
      case ('strain_max'); call move(g%strain_max, v, store)
      case ('compression'); call move(g%compression, v, store)
      case ('damping'); call move(g%damping, v, store)
      case ('cd_normal'); call move(g%cd_normal, v, store)
      case ('cd_tangential'); call move(g%cd_tangential, v, store)
      case ('ca_normal'); call move(g%ca_normal, v, store)
      case ('nodes'); call move(g%nodes, v, store)
      case ('mbl'); call move(g%mbl, v, store)
      case default
         v%found = .false.
      end select
   end subroutine access_segment

   !> `access` for the variables of &point_1 ... &point_8.
   subroutine access_point(g, name, v, store)
      !> The point.
      type(point_config), intent(inout) :: g
      !> Variable name.
      character(*), intent(in) :: name
      !> Its value.
      type(config_value), intent(inout) :: v
      !> Whether to set the component from v.
      logical, intent(in) :: store
      select case (name)
      case ('joint'); call move(g%joint, v, store)
      case ('mass'); call move(g%mass, v, store)
      case ('volume'); call move(g%volume, v, store)
      case ('ca'); call move(g%ca, v, store)
      case ('cd'); call move(g%cd, v, store)
      case ('area'); call move(g%area, v, store)
      case ('kind'); call move(g%kind, v, store)
      case default
         v%found = .false.
      end select
   end subroutine access_point

   !> `access` for a network point's position and motion (&point_k x, y, z, motion, ...):
   !> case_config%point_ends(k); where the case has none, their defaults (a store allocates them).
   subroutine access_point_end(c, k, name, v, store)
      !> The case.
      type(case_config), intent(inout) :: c
      !> The point.
      integer, intent(in) :: k
      !> Variable name.
      character(*), intent(in) :: name
      !> Its value.
      type(config_value), intent(inout) :: v
      !> Whether to set the component from v.
      logical, intent(in) :: store
      type(end_config) :: defaults
      if (.not. allocated(c%point_ends)) then
         if (.not. store) then
            call access_end(defaults, name, v, store)
            return
         end if
         allocate (c%point_ends(max_points))
      end if
      call access_end(c%point_ends(k), name, v, store)
   end subroutine access_point_end

   !> `access` for the variables of &line_1 ... &line_8.
   subroutine access_line(g, name, v, store)
      !> The line.
      type(line_config), intent(inout) :: g
      !> Variable name.
      character(*), intent(in) :: name
      !> Its value.
      type(config_value), intent(inout) :: v
      !> Whether to set the component from v.
      logical, intent(in) :: store
      select case (name)
      case ('end_a'); call move(g%point_names(1), v, store)
      case ('end_b'); call move(g%point_names(2), v, store)
      case ('segments'); call move_integer_rows(g%segments, g%segment_count, v, store)
      case ('length'); call move(g%length, v, store)
      case ('nodes'); call move(g%nodes, v, store)
      case default
         v%found = .false.
      end select
   end subroutine access_line

   !> An integer list: its first rows elements, as reals in v%reals (a store sets the elements
   !> given, not rows).
   subroutine move_integer_rows(x, rows, v, store)
      !> The list.
      integer, intent(inout) :: x(:)
      !> Elements in use.
      integer, intent(in) :: rows
      !> Value.
      type(config_value), intent(inout) :: v
      !> Whether to set x from v.
      logical, intent(in) :: store
      if (store) then
         x(1:size(v%reals)) = nint(v%reals)
      else
         v%reals = real(x(1:rows), dp)
      end if
   end subroutine move_integer_rows

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
end module xcable_io_input_access
