!> The output registry: every dataset, group and attribute a result file can
!> hold, with its units, a one-line description, its dimensions and when it
!> is written. The result file (io/output.f90) takes the `units` and
!> `description` attributes of each dataset from here and refuses to write a
!> dataset or attribute that is not listed; `xcable --outputs markdown` prints
!> the table (docs/user/output.md).
!>
!> Paths: '/tension' is a dataset or group, '/summary@steps' an attribute of a
!> group ('/@status': of the root). '<end>' stands for the name of an end
!> (end_a, end_b, and break_a, break_b of a break inside the cable).
!>
!> Units are SI: 'N', 'm', 'm/s', '1/m', 's', 'J', 'rad'; '-' for a
!> dimensionless ratio, '1' for a count, '' for text. Dimensions, slowest
!> first (as h5py and C read them): 'time node' for a snapshot field (one row
!> per snapshot, one column per output node), 'node', 'record' (one per
!> accepted step, the first the static state at t = 0), 'interval'.
!>
!> Frames: x, y, z and the v* and force_* of the ends are components in the
!> global frame (z up); u, v, shear, binormal_shear, curvature, curvature_n
!> and twist are components in the cable's material frame (t, n, b): t along
!> the cable from end a to end b, n the paper's normal (t turned by -90
!> degrees in the x-z plane), b = t x n.
module xcable_io_output_registry
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_driver_records, only: field_names, n_fields, field3_names, n_fields3
   implicit none
   private
   public :: output_item, output_items, find_output, write_outputs, outputs_text

   !> One entry of the registry.
   type :: output_item
      !> Path: '/group/name' for a dataset or group, '/group@name' for an attribute.
      character(len=40) :: path = ''
      !> 'dataset', 'group' or 'attribute'.
      character(len=9) :: kind = ''
      !> Dimensions of a dataset, slowest first ('time node', 'node', 'record', 'interval').
      character(len=9) :: dims = ''
      !> SI units ('-' dimensionless, '1' a count, '' text or a group).
      character(len=4) :: units = ''
      !> When it is written ('' : always).
      character(len=48) :: when = ''
      !> One line.
      character(len=200) :: description = ''
   end type output_item

   !> The names '<end>' stands for: the ends of the cable (s = 0, s = L) and the two new ends of a
   !> break inside it (driver/rod_run.f90).
   !> (A network of lines, driver/network_drive.f90: two ends per line, line_1_a ... line_8_b.)
   character(len=*), parameter :: end_names(20) = [character(len=8) :: 'end_a', 'end_b', 'break_a', 'break_b', &
                                                   'line_1_a', 'line_1_b', 'line_2_a', 'line_2_b', 'line_3_a', &
                                                   'line_3_b', 'line_4_a', 'line_4_b', 'line_5_a', 'line_5_b', &
                                                   'line_6_a', 'line_6_b', 'line_7_a', 'line_7_b', 'line_8_a', 'line_8_b']
   !> Descriptions and units of the snapshot fields, in the order of field_names.
   character(len=*), parameter :: field_units(n_fields) = [character(len=4) :: 'N', 'N', '-', 'm/s', 'm/s', 'm', &
                                                            'm', '1/m']
   character(len=*), parameter :: field_text(n_fields) = [character(len=160) :: &
      'tension: the axial force of the cable, positive when pulled', &
      'shear force along the material normal n (material frame)', &
      'axial strain: stretched length per unstretched length, minus 1', &
      'velocity along the material tangent t (material frame; the recoil of a released end b is negative)', &
      'velocity along the material normal n (material frame)', &
      'position along the global x axis (horizontal)', &
      'position along the global z axis (vertical, up)', &
      'curvature Omega3 about the material binormal b per unstretched metre (a sagging line''s is negative)']
   !> The same for the fields of a 3-D run, in the order of field3_names.
   character(len=*), parameter :: field3_units(n_fields3) = [character(len=4) :: 'm', 'm/s', '1/m', '1/m', 'N', &
                                                              '1/m']
   character(len=*), parameter :: field3_text(n_fields3) = [character(len=160) :: &
      'position along the global y axis (out of the x-z plane)', &
      'velocity along the global y axis', &
      'curvature about the global z axis: the turning of the tangent seen in plan, per unstretched metre', &
      'twist rate Omega1 about the material tangent t, per unstretched metre (material frame)', &
      'shear force Sb along the material binormal b (material frame)', &
      'curvature Omega2 about the material normal n, per unstretched metre (material frame)']

   !> The registry as find_output keeps it (built at its first call).
   type(output_item), allocatable, save :: registry(:)
   !> Each entry's path length, and whether its path holds '<end>' (set with registry).
   integer, allocatable, save :: pattern_length(:)
   logical, allocatable, save :: has_end_token(:)

contains

   !> Every entry of the registry, in the order of docs/user/output.md.
   function output_items() result(items)
      type(output_item), allocatable :: items(:)
      integer :: i
      allocate (items(0))
      ! The root: provenance and status.
      call add('/', 'group', '', '', '', 'an xcable result file: one run of one case')
      call add('/@status', 'attribute', '', '', '', &
               "'running' while the run goes on, then 'complete', 'failed' or 'interrupted' (SIGTERM, a checkpoint beside it)")
      call add('/@failure_reason', 'attribute', '', '', 'a failed run', 'why the run failed')
      call add('/@failure_time', 'attribute', '', 's', 'a failed run', 'simulated time at the failure')
      call add('/@warnings', 'attribute', '', '', 'when the run ends', 'the warnings of the run, one per line ('''' : none)')
      call add('/@namelist', 'attribute', '', '', '', 'the resolved case: every namelist variable with its value')
      call add('/@input_file', 'attribute', '', '', '', 'the namelist file of the case')
      call add('/@code_version', 'attribute', '', '', '', 'the version of xcable that wrote the file')
      call add('/@compiler_version', 'attribute', '', '', '', 'the compiler that built it')
      call add('/@compiler_options', 'attribute', '', '', '', 'the compiler options it was built with')
      call add('/@scheme', 'attribute', '', '', '', "the discretisation ('rod' or 'box')")
      call add('/@terms', 'attribute', '', '', '', 'the scheme and the terms of the model it computed')
      call add('/@run_id', 'attribute', '', '', '', 'the identifier of the run (its checkpoints carry it; a resumed run keeps it)')
      call add('/@resumes', 'attribute', '', '1', 'a resumed run', 'how often the run was resumed from a checkpoint')
      call add('/@model', 'attribute', '', '', '', "the model that ran: '2d' or '3d' (a scene in a vertical "// &
               "plane at an azimuth runs in 2-D, turned, and writes the 3-D layout: y, vy, the ends' y components)")
      ! The snapshots.
      call add('/s', 'dataset', 'node', 'm', '', &
               'arc length of each output node in the unstretched cable, from end a (the dimension scale ''node'')')
      call add('/time', 'dataset', 'time', 's', '', &
               'time of each snapshot; the first is t = 0, the static state (the dimension scale ''time'')')
      do i = 1, n_fields
         call add('/'//trim(field_names(i)), 'dataset', 'time node', field_units(i), 'asked for in &output fields', &
                  trim(field_text(i)))
      end do
      do i = 1, n_fields3
         call add('/'//trim(field3_names(i)), 'dataset', 'time node', field3_units(i), '3-D runs', trim(field3_text(i)))
      end do
      ! The static state.
      call add('/static', 'group', '', '', '', 'the static state at t = 0, per output node, and its figures')
      call add('/static/s', 'dataset', 'node', 'm', '', 'arc length of each output node from end a, as /s')
      do i = 1, n_fields
         call add('/static/'//trim(field_names(i)), 'dataset', 'node', field_units(i), '', 'static '//trim(field_text(i)))
      end do
      call add('/static/beta0', 'dataset', 'node', '-', 'box scheme', &
               'Euler parameter beta0 of the box scheme: cos of half the angle of the tangent')
      call add('/static/beta3', 'dataset', 'node', '-', 'box scheme', &
               'Euler parameter beta3 of the box scheme: sin of half the angle of the tangent')
      do i = 1, n_fields3
         call add('/static/'//trim(field3_names(i)), 'dataset', 'node', field3_units(i), '3-D runs', &
                  'static '//trim(field3_text(i)))
      end do
      call add('/static@span', 'attribute', '', 'm', '', 'horizontal distance between the ends')
      call add('/static@sag', 'attribute', '', 'm', '', 'largest vertical distance below the chord between the ends')
      call add('/static@end_angle', 'attribute', '', 'rad', '', 'angle of the tangent at end a below the horizontal')
      call add('/static@end_angle_b', 'attribute', '', 'rad', '', &
               'angle of the cable below the horizontal where it leaves end b (towards end a)')
      call add('/static@tension_a', 'attribute', '', 'N', '', 'tension at end a')
      call add('/static@tension_b', 'attribute', '', 'N', '', 'tension at end b')
      call add('/static@lowest_z', 'attribute', '', 'm', '', 'height of the lowest point')
      call add('/static@lowest_s', 'attribute', '', 'm', '', 'arc length of the lowest point from end a')
      call add('/static@max_tension', 'attribute', '', 'N', '', 'largest tension')
      call add('/static@newton_iterations', 'attribute', '', '1', '', 'Newton iterations of the statics')
      ! The history.
      call add('/history', 'group', '', '', '', 'one record per accepted time step; record 0 is the static state at t = 0')
      call add('/history/time', 'dataset', 'record', 's', '', 'time of each record (the dimension scale ''record'')')
      call add('/history/dt', 'dataset', 'record', 's', '', 'size of the time step that reached the record (0 at t = 0)')
      call add('/history/newton_iterations', 'dataset', 'record', '1', '', 'Newton iterations of the accepted step')
      call add('/history/rejected', 'dataset', 'record', '1', '', 'attempts of the step rejected before the accepted one')
      call add('/history/<end>', 'group', '', '', '', &
               'one end: end_a (s = 0), end_b (s = L), and break_a, break_b, the new ends of a break inside the cable; '// &
               'in a network of lines line_1_a, line_1_b, ... (each line''s end a and end b)')
      call add('/history/<end>/x', 'dataset', 'record', 'm', '', 'position of the end along the global x axis')
      call add('/history/<end>/z', 'dataset', 'record', 'm', '', 'position of the end along the global z axis (up)')
      call add('/history/<end>/vx', 'dataset', 'record', 'm/s', '', 'velocity of the end along the global x axis')
      call add('/history/<end>/vz', 'dataset', 'record', 'm/s', '', 'velocity of the end along the global z axis')
      call add('/history/<end>/tension', 'dataset', 'record', 'N', '', 'tension at the end node: the end cell''s '// &
               'extrapolated half a cell along the slope of the two end cells (second order; the end cell''s own '// &
               'where the three end cells zig-zag), not below the law''s tension at strain -0.99 (0 for a rope that '// &
               'cannot push); the support''s pull is force_x, force_z')
      call add('/history/<end>/force_x', 'dataset', 'record', 'N', '', &
               'external force on the end along the global x axis (a held end''s support reaction, a loaded end''s load)')
      call add('/history/<end>/force_z', 'dataset', 'record', 'N', '', &
               'external force on the end along the global z axis (a held end''s support reaction, a loaded end''s load)')
      call add('/history/<end>/y', 'dataset', 'record', 'm', '3-D runs', 'position of the end along the global y axis')
      call add('/history/<end>/vy', 'dataset', 'record', 'm/s', '3-D runs', 'velocity of the end along the global y axis')
      call add('/history/<end>/force_y', 'dataset', 'record', 'N', '3-D runs', &
               'external force on the end along the global y axis')
      call add('/history/wetted_length', 'dataset', 'record', 'm', '&fluid with water', &
               'unstretched length of the cable under the water''s surface (its cells'' wetted fractions)')
      call add('/history/grounded_length', 'dataset', 'record', 'm', '&seabed', &
               'unstretched length of the cable on (below) the seabed (its cells'' contact fractions)')
      call add('/history/energy', 'group', '', '', '&output energy', &
               'the energy ledger: ledger = strain + kinetic + bending + gravity - work - loads + dissipation stays constant')
      call add('/history/energy/strain', 'dataset', 'record', 'J', '&output energy', 'strain energy of the cable')
      call add('/history/energy/kinetic', 'dataset', 'record', 'J', '&output energy', 'kinetic energy (point masses included)')
      call add('/history/energy/bending', 'dataset', 'record', 'J', '&output energy', 'bending (and twisting) energy')
      call add('/history/energy/gravity', 'dataset', 'record', 'J', '&output energy', 'potential energy of gravity (and buoyancy)')
      call add('/history/energy/work', 'dataset', 'record', 'J', '&output energy', &
               'work done on the cable by its ends since t = 0 (their forces and couples)')
      call add('/history/energy/dissipation', 'dataset', 'record', 'J', '&output energy', &
               'energy dissipated since t = 0 (material damping, theta > 0.5)')
      call add('/history/energy/ledger', 'dataset', 'record', 'J', '&output energy', &
               'the ledger: constant up to round-off and the scheme''s own error')
      call add('/history/energy/loads', 'dataset', 'record', 'J', '&output energy', &
               'work done on the cable by the distributed loads (the fluid) since t = 0')
      ! The summary.
      call add('/summary', 'group', '', '', '', &
               'the figures of the run as attributes (units: this table); absent when they do not apply')
      call add('/summary@static_tension_a', 'attribute', '', 'N', '', 'static tension at end a')
      call add('/summary@static_tension_b', 'attribute', '', 'N', '', 'static tension at end b')
      call add('/summary@static_angle_a', 'attribute', '', 'rad', '', 'static angle of the tangent at end a below the horizontal')
      call add('/summary@static_angle_b', 'attribute', '', 'rad', '', 'static angle below the horizontal at end b')
      call add('/summary@static_span', 'attribute', '', 'm', '', 'static horizontal distance between the ends')
      call add('/summary@static_lowest_z', 'attribute', '', 'm', '', 'static height of the lowest point')
      call add('/summary@static_lowest_s', 'attribute', '', 'm', '', 'static arc length of the lowest point from end a')
      call add('/summary@static_max_tension', 'attribute', '', 'N', '', 'largest static tension')
      call add('/summary@static_wetted_length', 'attribute', '', 'm', '&fluid with water', &
               'unstretched length under the water''s surface in the static state')
      call add('/summary@static_grounded_length', 'attribute', '', 'm', '&seabed', &
               'unstretched length on the seabed in the static state')
      call add('/summary@notes', 'attribute', '', '', 'something to say', &
               'what the log says about the scene, one line each (a line partly out of the water, ...)')
      call add('/summary@peak_end_speed', 'attribute', '', 'm/s', '', 'largest speed of a released or loaded end')
      call add('/summary@peak_end_speed_time', 'attribute', '', 's', '', 'when the largest end speed happened')
      call add('/summary@peak_end_speed_end', 'attribute', '', '', 'an end moved', 'which end had the largest speed')
      call add('/summary@min_fixed_end_tension', 'attribute', '', 'N', 'a held end', 'lowest tension at a held end')
      call add('/summary@min_fixed_end_tension_time', 'attribute', '', 's', 'a held end', 'when it happened')
      call add('/summary@front_arrival_time', 'attribute', '', 's', 'a front arrived', &
               'when the tension at a held end first fell 1 % below its static value after a break')
      call add('/summary@break_time', 'attribute', '', 's', 'a break', 'when the break started')
      call add('/summary@break_s', 'attribute', '', 'm', 'a break', 'arc length of the break from end a '// &
               '(a network: on the results'' s, the lines laid out one after another)')
      call add('/summary@break_line', 'attribute', '', '', 'a break in a network', 'the line that parted (&line_k)')
      call add('/summary@break_ramp', 'attribute', '', 's', 'a break', 'duration of the break''s force ramp')
      call add('/summary@mbl', 'attribute', '', 'N', '&rupture criterion = ''tension''', 'minimum breaking load '// &
               '(a line of segments: that of the cell that reached it, or came closest)')
      call add('/summary@break_tension', 'attribute', '', 'N', 'a break by tension', &
               'tension of the first cell to reach the MBL, at break_time (within the rupture tolerance of mbl)')
      call add('/summary@break_cell_s', 'attribute', '', 'm', 'a break by tension', &
               'arc length from end a of the middle of the first cell to reach the MBL (break_s: its break node)')
      call add('/summary@largest_tension', 'attribute', '', 'N', 'a break by tension that did not happen', &
               'tension of the cell that came closest to its MBL (below it; a line of segments: the largest '// &
               'share of its segment''s MBL)')
      call add('/summary@largest_tension_s', 'attribute', '', 'm', 'a break by tension that did not happen', &
               'arc length from end a of the middle of that cell')
      call add('/summary@largest_tension_time', 'attribute', '', 's', 'a break by tension that did not happen', &
               'when it was reached')
      call add('/summary@energy_drift', 'attribute', '', '-', '&output energy', &
               'largest change of the ledger over the strain energy at t = 0')
      call add('/summary@dissipated', 'attribute', '', 'J', '', 'energy dissipated (booked in the ledger)')
      call add('/summary@time_reached', 'attribute', '', 's', '', 'simulated time reached')
      call add('/summary@wall_time', 'attribute', '', 's', '', 'wall time of the dynamics')
      call add('/summary@dt_requested', 'attribute', '', 's', '', 'time step asked for')
      call add('/summary@dt_used', 'attribute', '', 's', '', 'largest time step taken')
      call add('/summary@courant_requested', 'attribute', '', '-', '', 'Courant number asked for')
      call add('/summary@courant_used', 'attribute', '', '-', '', 'largest Courant number taken')
      call add('/summary@max_unit_norm_error', 'attribute', '', '-', '', 'box scheme: largest |beta0^2 + beta3^2 - 1|')
      call add('/summary@max_turning_angle', 'attribute', '', 'rad', '', 'rod scheme: largest turning angle between two cells')
      call add('/summary@min_strain', 'attribute', '', '-', '', 'smallest strain reached')
      call add('/summary@max_strain', 'attribute', '', '-', '', 'largest strain reached')
      call add('/summary@steps', 'attribute', '', '1', '', 'accepted time steps')
      call add('/summary@rejected_steps', 'attribute', '', '1', '', 'rejected attempts of a step')
      call add('/summary@newton_iterations', 'attribute', '', '1', '', 'Newton iterations in all')
      call add('/summary@max_newton_iterations', 'attribute', '', '1', '', 'most Newton iterations of one step')
      call add('/summary@factorisations', 'attribute', '', '1', '', 'Jacobian factorisations')
      call add('/summary@warnings', 'attribute', '', '', 'a warning', 'the warnings of the run, one per line')
      call add('/summary@<end>_kind', 'attribute', '', '', '', "kind of the end at the end of the run ('fixed', ..., 'break')")
      call add('/summary@<end>_peak_speed', 'attribute', '', 'm/s', '', 'largest speed of the end')
      call add('/summary@<end>_peak_speed_time', 'attribute', '', 's', '', 'when it happened')
      call add('/summary@<end>_min_tension', 'attribute', '', 'N', '', 'smallest tension at the end node (as '// &
               '/history/<end>/tension)')
      call add('/summary@<end>_min_tension_time', 'attribute', '', 's', '', 'when it happened')
      call add('/summary@<end>_max_tension', 'attribute', '', 'N', '', 'largest tension at the end node (as '// &
               '/history/<end>/tension)')
      call add('/summary@<end>_max_tension_time', 'attribute', '', 's', '', 'when it happened')
      call add('/summary@<end>_slack_time', 'attribute', '', 's', '', &
               'time the end was slack (its cell''s tension at most 0.001 of the largest static tension)')
      call add('/summary@<end>_front_arrival_time', 'attribute', '', 's', 'a front arrived', &
               'when the force at the (held) end first fell 1 % below its value at t = 0')
      call add('/summary/<end>_slack_start', 'dataset', 'interval', 's', 'the end was slack', &
               'start of each interval in which the end was slack')
      call add('/summary/<end>_slack_end', 'dataset', 'interval', 's', 'the end was slack', &
               'end of each interval in which the end was slack')

   contains

      !> Append one entry.
      subroutine add(path, kind, dims, units, when, description)
         character(*), intent(in) :: path, kind, dims, units, when, description
         items = [items, output_item(path, kind, dims, units, when, description)]
      end subroutine add
   end function output_items

   !> The registry's entry of a path ('/history/end_a/x', '/summary@steps'); found is .false.
   !> when the path is not registered.
   subroutine find_output(path, item, found)
      !> Path of a dataset or group ('/a/b'), or of an attribute ('/a@b').
      character(*), intent(in) :: path
      !> Its entry.
      type(output_item), intent(out) :: item
      !> Whether the registry lists it.
      logical, intent(out) :: found
      integer :: i, n
      ! The table once per process: every dataset and attribute written looks it up (building it
      ! at each lookup was 60 % of a short run's instructions). A pattern without '<end>' matches
      ! only a path of its own length: its length is compared first (no trim, no index).
      if (.not. allocated(registry)) then
         registry = output_items()
         allocate (pattern_length(size(registry)), has_end_token(size(registry)))
         do i = 1, size(registry)
            pattern_length(i) = len_trim(registry(i)%path)
            has_end_token(i) = index(registry(i)%path, '<end>') > 0
         end do
      end if
      found = .false.
      n = len(path)
      do i = 1, size(registry)
         if (has_end_token(i)) then
            if (.not. matches(registry(i)%path(1:pattern_length(i)), path)) cycle
         else
            if (pattern_length(i) /= n) cycle
            if (registry(i)%path(1:n) /= path) cycle
         end if
         item = registry(i)
         found = .true.
         return
      end do
   end subroutine find_output

   !> Whether a path matches a registry pattern, in which '<end>' stands for the name of an end
   !> (end_names).
   recursive logical function matches(pattern, path) result(yes)
      character(*), intent(in) :: pattern, path
      integer :: k, j, n
      character(len=*), parameter :: token = '<end>'
      yes = .false.
      k = index(pattern, token)
      if (k == 0) then
         yes = pattern == path
         return
      end if
      if (len(path) < k - 1) return
      if (path(1:k - 1) /= pattern(1:k - 1)) return
      do j = 1, size(end_names)
         n = len_trim(end_names(j))
         if (len(path) < k - 1 + n) cycle
         if (path(k:k - 1 + n) /= end_names(j)(1:n)) cycle
         if (matches(pattern(k + len(token):), path(k + n:))) then
            yes = .true.
            return
         end if
      end do
   end function matches

   !> The registry as text: 'markdown' (the page docs/user/output.md) or 'tsv' (one
   !> line per entry: path, kind, dims, units, when, description).
   function outputs_text(format) result(text)
      !> 'markdown' or 'tsv'.
      character(*), intent(in) :: format
      character(:), allocatable :: text
      type(output_item), allocatable :: items(:)
      character(len=*), parameter :: nl = new_line('a'), tab = achar(9)
      integer :: i
      items = output_items()
      if (format == 'tsv') then
         text = 'path'//tab//'kind'//tab//'dims'//tab//'units'//tab//'when'//tab//'description'//nl
         do i = 1, size(items)
            associate (e => items(i))
               text = text//trim(e%path)//tab//trim(e%kind)//tab//trim(e%dims)//tab//trim(e%units)//tab// &
                      trim(e%when)//tab//trim(e%description)//nl
            end associate
         end do
         return
      end if
      text = '# The result file'//nl//nl// &
             '<!-- Generated by `xcable --outputs markdown` from src/xcable/io/output_registry.f90 '// &
             '(`make outputs`); do not edit. -->'//nl//nl// &
             'A run writes one HDF5 file (`&output file`). Every dataset carries the attributes `units` (SI; '// &
             '`-` dimensionless, `1` a count) and `description` (one line). The snapshot fields are '// &
             '`[time, node]` arrays as h5py and C read them (one row per snapshot); `/time` and `/s` are '// &
             'attached to them as HDF5 dimension scales, labelled `time` and `node` (`ds.dims[0][0]` is '// &
             '`/time`, `ds.dims[1][0]` is `/s`), as `/static/s` is to the static fields and '// &
             '`/history/time` to the history. A broken cable has its break node twice in the node arrays '// &
             '(once per piece). Texts are UTF-8 strings (h5py reads them as `str`). A figure that does not '// &
             'apply to the scene is absent, never -1 or 0.'//nl//nl// &
             'Frames: `x`, `y`, `z`, `vy` and the ends'' `vx`, `vy`, `vz`, `force_*` are components in the '// &
             'global frame (`z` up); `u`, `v`, `shear`, `binormal_shear`, `curvature`, `curvature_n` and '// &
             '`twist` are components in the cable''s material frame (t, n, b): `t` along the cable from end a '// &
             'to end b, `n` the paper''s normal (`t` turned by -90 degrees in the x-z plane; down for a cable '// &
             'along +x), `b` = t x n.'//nl//nl// &
             'Paths: `/group/name` is a dataset or group, `/group@name` an attribute; `<end>` is `end_a`, '// &
             '`end_b`, and `break_a`, `break_b` after a break inside the cable; in a network of lines (`&line_k`) '// &
             'the ends of each line, `line_1_a`, `line_1_b`, `line_2_a`, ..., and the lines are laid out one '// &
             'after another along `s` (each line a piece of the output). The attributes of `/static` '// &
             'and `/summary` are plain numbers: their units are in this table.'//nl//nl// &
             '| path | kind | dimensions | units | written | description |'//nl// &
             '|---|---|---|---|---|---|'//nl
      do i = 1, size(items)
         associate (e => items(i))
            text = text//'| `'//trim(e%path)//'` | '//trim(e%kind)//' | '//cell(e%dims)//' | '// &
                   cell(e%units, merge('text', '    ', e%kind == 'attribute'))//' | '//cell(e%when, 'always')// &
                   ' | '//trim(e%description)//' |'//nl
         end associate
      end do
   contains
      !> A table cell: the text, or the default ('' : empty).
      function cell(value, default) result(c)
         character(*), intent(in) :: value
         character(*), intent(in), optional :: default
         character(:), allocatable :: c
         c = trim(value)
         if (len(c) == 0 .and. present(default)) c = default
      end function cell
   end function outputs_text

   !> Print the registry (xcable --outputs markdown|tsv).
   subroutine write_outputs(unit, format, error)
      !> Open formatted unit.
      integer, intent(in) :: unit
      !> 'markdown' or 'tsv'.
      character(*), intent(in) :: format
      !> Error for an unknown format.
      type(error_type), allocatable, intent(out) :: error
      if (format /= 'markdown' .and. format /= 'tsv') then
         call fatal_error(error, '--outputs '//format//': unknown format; allowed: markdown, tsv', stat_input)
         return
      end if
      write (unit, '(a)', advance='no') outputs_text(format)
   end subroutine write_outputs
end module xcable_io_output_registry
