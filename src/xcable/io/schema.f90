!> The namelist schema: one table that describes every group and variable of
!> a case file (type, element count, string length, unit, default, allowed
!> values or range, meaning). The reader (io/input.f90) takes from it the
!> names and types the scanner checks, the range and allowed-value checks of
!> the validation and the order and form of the echo; `write_schema` makes
!> from it the input table of docs/user/namelist.md and the sweep scripts' variable table
!> (`xcable --schema markdown|tsv`).
!>
!> Adding a variable: a component with its default in io/config.f90, an
!> entry here (the default written as the echo writes it), and in
!> io/input.f90 one line of `access` plus the namelist read of its group
!> (local, namelist statement, copy in and out); then `make schema`. The
!> tests of suite input fail until all of these agree. A variable that steers
!> a run without changing what it computes (progress lines, limits of wall
!> time, checkpoints) is marked resume_may_differ: a checkpoint is accepted
!> by `xcable --resume` when every other variable is as it was.
!>
!> The groups &segment_1 ... &segment_8 are made from the entries of &cable,
!> &material and &fluid (add_segments: a copy of each entry that describes the
!> line, with its twin group named): a variable added there for a segment to
!> take needs its name in add_segments' list, a component of segment_config, a
!> line of access_segment and of read_segment, and one in segment_case.
module xcable_io_schema
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: real_text
   use xcable_io_config, only: max_table_points, max_segments
   use xcable_material_factory, only: law_names
   use xcable_ends_registry, only: end_kind, end_kind_list, end_kind_names, kinds_using
   implicit none
   private
   public :: schema_entry, schema_table, schema_groups, find_entry, group_entries
   public :: schema_text, write_schema, allowed_text, bound_text, known_fields, is_table
   public :: segment_of, segment_group, group_list

   !> Snapshot fields that &output fields may name.
   character(len=*), parameter :: known_fields(8) = &
      [character(len=9) :: 'tension', 'shear', 'strain', 'u', 'v', 'x', 'z', 'curvature']

   !> One namelist variable.
   type :: schema_entry
      !> Group and variable name, lower case.
      character(len=16) :: group = ''
      character(len=24) :: name = ''
      !> 'real', 'integer', 'logical' or 'string'.
      character(len=8) :: type = 'real'
      !> Number of elements (1 a scalar, 5 for p, max_table_points for a table).
      integer :: count = 1
      !> Length of a string variable.
      integer :: length = 0
      !> Unit ('-': none).
      character(len=16) :: unit = '-'
      !> Default, written as the echo writes it ('' for a table: no rows).
      character(len=64) :: default = ''
      !> Allowed words of a string, separated by blanks ('' : any text).
      character(len=96) :: choices = ''
      !> Whether the value is a list of such words (blanks or commas between).
      logical :: word_list = .false.
      !> Whether a number has a range: lower <= x (lower < x if lower_open) and x <= upper.
      logical :: bounded = .false.
      real(dp) :: lower = 0, upper = 0
      logical :: lower_open = .false.
      !> Upper bound taken from another variable, 'group%name' ('' : upper).
      character(len=40) :: upper_from = ''
      !> What 0 (or '' for a string) stands for; then 0 is allowed besides the range ('' : nothing).
      character(len=40) :: zero_means = ''
      !> What the default stands for when the variable is not given; a given value must be in range ('' : nothing).
      character(len=40) :: default_means = ''
      !> Added to a range error: why the range is what it is.
      character(len=120) :: note = ''
      !> A variable of &end_a / &end_b that the echo writes only for the kinds that use it (the
      !> others are written for every kind, as the files before the end-kind registry had them).
      logical :: own_kinds_only = .false.
      !> Whether the value may differ between a run and its `xcable --resume` (it steers the run,
      !> not what it computes: left out of the namelist fingerprint a checkpoint is checked against).
      logical :: resume_may_differ = .false.
      !> The group whose value a variable of &segment_k takes when the segment does not give
      !> it ('cable', 'material' or 'fluid'; '' : a variable of its own).
      character(len=16) :: twin = ''
      !> Meaning, one line.
      character(len=320) :: doc = ''
   end type schema_entry

   !> Entries of the table being built that hold an entry (build_table, add).
   integer :: filled = 0

contains

   !> The table: every group and variable, in the order of the file and the echo.
   !> Built once per process (its appends copy the entries before: 2 million
   !> instructions a build, and a run asks for it six times).
   function schema_table() result(t)
      type(schema_entry), allocatable :: t(:)
      type(schema_entry), allocatable, save :: built(:)
      if (.not. allocated(built)) call build_table(built)
      t = built
   end function schema_table

   !> Build the table.
   subroutine build_table(t)
      !> The table.
      type(schema_entry), allocatable, intent(out) :: t(:)
      character(len=5), parameter :: ends(2) = ['end_a', 'end_b']
      type(end_kind), allocatable :: kinds(:)
      character(:), allocatable :: kind_doc
      integer :: k
      ! Room for the entries (add doubles it when they do not fit), cut to those added at the end:
      ! t = [t, e] per entry copied the table each time (3.1e6 instructions of a run's start).
      allocate (t(128))
      filled = 0
      ! &cable
      call add(t, 'cable', 'length', 'real', 'm', '60', 'unstretched length L', 1.0e-2_dp, 1.0e5_dp)
      call add(t, 'cable', 'diameter', 'real', 'm', '0.05', 'diameter d', 1.0e-4_dp, 1.0_dp, &
               note='in metres: a 50 mm line is 0.05')
      call add(t, 'cable', 'density', 'real', 'kg/m^3', '1140', 'density rho (mass per length m = rho A)', &
               1.0_dp, 1.0e5_dp)
      call add(t, 'cable', 'young', 'real', 'Pa', '2.3e8', "Young's modulus E (for EI and for EA of the linear law)", &
               1.0e3_dp, 1.0e13_dp)
      call add(t, 'cable', 'gravity', 'real', 'm/s^2', '9.81', 'gravity g (weight per length w0 = m g)', &
               0.0_dp, 100.0_dp, note='0 only for the rod scheme with both ends held: without weight a cable held '// &
               'at one end has no static shape')
      call add(t, 'cable', 'area', 'real', 'm^2', '0', 'cross-section area A', 1.0e-9_dp, 100.0_dp, &
               zero_means='pi d^2 / 4')
      call add(t, 'cable', 'bending_stiffness', 'real', 'N m^2', '0', 'bending stiffness EI (70.6 N m^2 for the paper)', &
               1.0e-6_dp, 1.0e12_dp, zero_means='E pi d^4 / 64')
      call add(t, 'cable', 'gip', 'real', 'N m^2', '0', &
               'torsional stiffness GIp of the 3-D model (a solid isotropic rod has GIp = EI / (1 + nu)); a torque '// &
               'sets a uniform twist rate M_t / GIp, not coupled to the centreline', 1.0e-6_dp, 1.0e12_dp, &
               zero_means='EI / 1.4 (nu = 0.4)')
      ! &material
      call add(t, 'material', 'law', 'string', '-', "'tanh'", &
               "'tanh': T = p1 tanh(p2 eps + p3) + p4 + p5 eps (eq. 17); 'linear': T = EA eps; 'table': T from "// &
               'rows of strain and tension (table_strain and table_tension, or table_file)', length=16, &
               choices=join(law_names))
      call add(t, 'material', 'p', 'real', 'N, -, -, N, N', '270300, 10.2, -2.128, 262700, 135.5', &
               'p1..p5 of eq. 17; for the tanh law p1, p5 in (0, 1e12], p2 in (0, 1e6], p3 in [-1e3, 1e3]', &
               -1.0e12_dp, 1.0e12_dp, count=5)
      call add(t, 'material', 'ea', 'real', 'N', '0', 'EA of the linear law', 1.0_dp, 1.0e13_dp, zero_means='young * area')
      call add(t, 'material', 'table_strain', 'real', '-', '', &
               "rows of the 'table' law: engineering strain of the unstretched length, strictly increasing, at "// &
               'least 2 rows; table_tension has as many (only with law = '//"'table')", -1.0_dp, 1.0_dp, &
               lower_open=.true., count=max_table_points, note='a strain, not per cent: 5 % is 0.05')
      call add(t, 'material', 'table_tension', 'real', 'N', '', &
               "rows of the 'table' law: tension, strictly increasing (a positive slope)", -1.0e12_dp, 1.0e12_dp, &
               count=max_table_points)
      call add(t, 'material', 'table_file', 'string', '-', "''", &
               "the rows of the 'table' law from a text file instead: columns strain and tension, # starts a "// &
               'comment; the path is relative to the working directory', length=512)
      call add(t, 'material', 'strain_max', 'real', '-', '0.35', &
               'largest static strain the law is used for (the tanh fit reaches about 504 kN there)', 0.0_dp, 1.0_dp, &
               lower_open=.true., note='a strain, not per cent: 35 % is 0.35')
      call add(t, 'material', 'compression', 'string', '-', "'none'", &
               "behaviour in compression: 'none' (a rope that cannot push: no tension at and below the strain of zero "// &
               "tension, damping only while taut) or 'law' (the law continued below zero strain, as the paper's cases)", &
               length=16, choices='law none')
      call add(t, 'material', 'damping', 'real', 'N s', '0', &
               'internal (Kelvin-Voigt) damping c of T = f(eps) + c d(eps)/dt', 0.0_dp, 1.0e12_dp)
      ! &fluid
      call add(t, 'fluid', 'density', 'real', 'kg/m^3', '0', &
               'density of the water around the cable (1025 sea water) below surface_z: buoyancy, drag, added mass; '// &
               '0: no water', 0.0_dp, 1.0e5_dp)
      call add(t, 'fluid', 'cd_normal', 'real', '-', '0', &
               'normal drag coefficient, on the stretched diameter (MoorDyn Cdn, OrcaFlex normal Cd)', 0.0_dp, 1.0e3_dp)
      call add(t, 'fluid', 'cd_tangential', 'real', '-', '0', &
               'tangential drag coefficient, on the surface pi d (MoorDyn Cdt, OrcaFlex axial Cd)', 0.0_dp, 1.0e3_dp)
      call add(t, 'fluid', 'ca_normal', 'real', '-', '0', &
               'normal added-mass coefficient, on the displaced volume (MoorDyn Can, OrcaFlex normal Ca)', 0.0_dp, 1.0e3_dp)
      call add(t, 'fluid', 'current_x', 'real', 'm/s', '0', 'uniform current, horizontal (needs density > 0)', &
               -1.0e3_dp, 1.0e3_dp)
      call add(t, 'fluid', 'current_y', 'real', 'm/s', '0', &
               'uniform current, horizontal across the x-z plane (3-D model), as current_x', -1.0e3_dp, 1.0e3_dp)
      call add(t, 'fluid', 'current_z', 'real', 'm/s', '0', 'uniform current, vertical (up), as current_x', &
               -1.0e3_dp, 1.0e3_dp)
      call add(t, 'fluid', 'surface_z', 'real', 'm', '0', &
               'height of the still-water level: the water (density, the current) acts on the part of the cable '// &
               'below it, the air (air_density) on the part above', -1.0e6_dp, 1.0e6_dp)
      call add(t, 'fluid', 'air_density', 'real', 'kg/m^3', '0', &
               'density of the air above the surface (1.225): its drag and added mass with the same coefficients, '// &
               'still air; with density = 0, the air all around the cable', 0.0_dp, 1.0e2_dp)
      call add(t, 'fluid', 'surface_band', 'real', 'm', '-1', &
               'height over which a cross-section goes from dry to wet at the surface (0: a step, exact for a '// &
               'straight cell but not differentiable for one lying in the surface)', 0.0_dp, 1.0e3_dp, &
               default_means='the diameter')
      ! &seabed
      call add(t, 'seabed', 'depth', 'real', 'm', '0', &
               'depth of the seabed under z = 0 at x = y = 0: the bottom is z = -depth + slope_x x + slope_y y', &
               0.0_dp, 1.0e5_dp, zero_means='no seabed')
      call add(t, 'seabed', 'slope_x', 'real', '-', '0', 'slope of the seabed along x, dz/dx', -10.0_dp, 10.0_dp)
      call add(t, 'seabed', 'slope_y', 'real', '-', '0', 'slope of the seabed along y, dz/dy (3-D)', -10.0_dp, 10.0_dp)
      call add(t, 'seabed', 'stiffness', 'real', 'Pa', '3e6', &
               'contact stiffness per unit of penetration and of diameter (MoorDyn kBot): the bottom pushes with '// &
               'stiffness d times the penetration per unstretched metre', 0.0_dp, 1.0e15_dp, lower_open=.true.)
      call add(t, 'seabed', 'damping', 'real', 'Pa s/m', '300000', &
               'contact damping per unit of penetration rate and of diameter (MoorDyn cBot)', 0.0_dp, 1.0e15_dp)
      call add(t, 'seabed', 'mu_axial', 'real', '-', '0', 'Coulomb friction coefficient along the line', &
               0.0_dp, 100.0_dp)
      call add(t, 'seabed', 'mu_lateral', 'real', '-', '0', 'Coulomb friction coefficient across the line (3-D)', &
               0.0_dp, 100.0_dp)
      call add(t, 'seabed', 'slip_velocity', 'real', 'm/s', '0.01', &
               'slip speed below which friction grows with the slip instead of being full: mu N v / sqrt(v^2 + '// &
               'slip_velocity^2)', 0.0_dp, 1.0e3_dp, lower_open=.true.)
      call add(t, 'seabed', 'bathymetry_file', 'string', '-', "''", &
               "a grid of depths in MoorDyn's bathymetry format (a title line, nGridX n, nGridY m, the n x "// &
               'lines, then m lines of y and n depths, m below z = 0) in place of the plane of depth, slope_x and '// &
               'slope_y: the bottom is made of flat triangles between the grid points, flat beyond the grid', &
               length=512)
      call add(t, 'seabed', 'static_friction', 'string', '-', "'none'", &
               "friction in the statics: 'none', or 'end_a' / 'end_b': mu_axial times the contact force along "// &
               "the grounded line towards that end (the anchor), as if the line had been laid from the anchor "// &
               "and pulled taut; it fades where the cell's strain falls to zero", length=16, choices='none end_a end_b')
      ! &segment_1 ... &segment_8: copies of the entries of &cable, &material and &fluid
      call add_segments(t)
      ! &static
      call add(t, 'static', 'tension', 'real', 'N', '315000', &
               "end tension T_s of the paper's symmetric catenary (ends at one height, span from the tension); must "// &
               'exceed w0 L / 2 and need a strain below strain_max; not together with &end_b x or z', 0.0_dp, 1.0e9_dp, &
               lower_open=.true.)
      ! &end_a (s = 0) and &end_b (s = L): the same variables; the kinds from the registry.
      kinds = end_kind_list()
      kind_doc = ''
      do k = 1, size(kinds)
         if (k > 1 .and. k < size(kinds)) kind_doc = kind_doc//', '
         if (k > 1 .and. k == size(kinds)) kind_doc = kind_doc//' or '
         kind_doc = kind_doc//"'"//trim(kinds(k)%name)//"' ("//trim(kinds(k)%doc)//')'
      end do
      kind_doc = kind_doc//'; at least one end '//words_or(end_kind_names(held=.true.))
      do k = 1, size(ends)
         call add(t, ends(k), 'kind', 'string', '-', "'"//trim(kinds(1)%name)//"'", kind_doc, length=16, &
                  choices=end_kind_names())
         call add(t, ends(k), 'x', 'real', 'm', '0', &
                  'horizontal position of a fixed end, mean position of a motion end, or anchor of a spring end (the '// &
                  'position of the other kinds follows from the statics; &end_b: not together with &static tension)', &
                  -1.0e5_dp, 1.0e5_dp)
         call add(t, ends(k), 'y', 'real', 'm', '0', &
                  'horizontal position across the x-z plane (3-D model), as x', -1.0e5_dp, 1.0e5_dp)
         call add(t, ends(k), 'z', 'real', 'm', '0', 'vertical position (up), as x', -1.0e5_dp, 1.0e5_dp)
         call add(t, ends(k), 'force_x', 'real', 'N', '0', &
                  'horizontal force on a force end (the constant value, or the value a ramp starts from)', &
                  -1.0e9_dp, 1.0e9_dp)
         call add(t, ends(k), 'force_y', 'real', 'N', '0', &
                  'force on a force end across the x-z plane (3-D model), as force_x', -1.0e9_dp, 1.0e9_dp)
         call add(t, ends(k), 'force_z', 'real', 'N', '0', 'vertical force on a force end, as force_x', -1.0e9_dp, 1.0e9_dp)
         call add(t, ends(k), 'torque', 'real', 'N m', '0', &
                  'torque on a force end about its outward tangent (3-D model; ramped with the force)', &
                  -1.0e9_dp, 1.0e9_dp)
         call add(t, ends(k), 'history', 'string', '-', "'constant'", &
                  "force history: 'constant', 'ramp' (cos^2 to zero over ramp_time) or 'table'", length=16, &
                  choices='constant ramp table')
         call add(t, ends(k), 'ramp_time', 'real', 's', '0', &
                  'duration of the force ramp (> 0 for a ramp), or of the smooth start of a motion', 0.0_dp, 1.0e4_dp)
         call add(t, ends(k), 'motion', 'string', '-', "'harmonic'", "motion of a motion end: 'harmonic' or 'table'", &
                  length=16, choices='harmonic table')
         call add(t, ends(k), 'amplitude', 'real', 'm', '0', 'amplitude of the harmonic motion', 0.0_dp, 1.0e5_dp)
         call add(t, ends(k), 'period', 'real', 's', '1', 'period of the harmonic motion (> 0)', 0.0_dp, 1.0e4_dp)
         call add(t, ends(k), 'phase', 'real', 'rad', '0', 'phase of the harmonic motion', -1.0e3_dp, 1.0e3_dp)
         call add(t, ends(k), 'direction_x', 'real', '-', '0', &
                  'direction of the harmonic motion, x component (the direction (x, y, z) is normalised; not all zero)', &
                  -1.0e6_dp, 1.0e6_dp)
         call add(t, ends(k), 'direction_y', 'real', '-', '0', &
                  'direction of the harmonic motion, y component (3-D model)', -1.0e6_dp, 1.0e6_dp)
         call add(t, ends(k), 'direction_z', 'real', '-', '1', 'direction of the harmonic motion, z component', &
                  -1.0e6_dp, 1.0e6_dp)
         call add(t, ends(k), 'mass', 'real', 'kg', '0', 'point mass of a mass end (> 0), or at a spring end', &
                  0.0_dp, 1.0e9_dp)
         call add(t, ends(k), 'stiffness', 'real', 'N/m', '0', &
                  'stiffness k of a spring end (> 0): the spring pulls the end towards the anchor x, y, z with '// &
                  'the force k (l - rest_length), l the distance from the anchor to the end', 0.0_dp, 1.0e12_dp, &
                  own_kinds_only=.true.)
         call add(t, ends(k), 'damping', 'real', 'N s/m', '0', &
                  'damping c of the dashpot in line with a spring end: the force c dl/dt along the spring, l the '// &
                  'distance from the anchor to the end', 0.0_dp, 1.0e12_dp, &
                  own_kinds_only=.true.)
         call add(t, ends(k), 'rest_length', 'real', 'm', '0', &
                  'rest length of a spring end (the spring pushes when shorter; with a rest length the anchor must '// &
                  "not be the point of a held other end: the spring's direction at rest would be undetermined)", &
                  0.0_dp, 1.0e5_dp, &
                  own_kinds_only=.true.)
         call add(t, ends(k), 'table_time', 'real', 's', '', &
                  "table of a 'table' history or motion: times, strictly increasing, at least 2 rows; table_x and "// &
                  'table_z have as many values, table_y as many or none', -1.0e7_dp, 1.0e7_dp, count=max_table_points)
         call add(t, ends(k), 'table_x', 'real', 'N or m', '', &
                  'table: x column (force in N of a force end, displacement in m of a motion end)', &
                  -1.0e9_dp, 1.0e9_dp, count=max_table_points)
         call add(t, ends(k), 'table_y', 'real', 'N or m', '', &
                  'table: y column (3-D model; left out: 0)', -1.0e9_dp, 1.0e9_dp, count=max_table_points)
         call add(t, ends(k), 'table_z', 'real', 'N or m', '', 'table: z column', -1.0e9_dp, 1.0e9_dp, &
                  count=max_table_points)
         call add(t, ends(k), 'table_file', 'string', '-', "''", &
                  'the table from a text file instead: 2, 3 or 4 columns t, x; t, x, z; or t, x, y, z (absent '// &
                  'columns 0), # starts a comment; the path is relative to the working directory', length=512)
      end do
      ! Each variable of an end names the kinds that use it (the registry's lines).
      do k = 1, size(t)
         if (.not. any(t(k)%group == ends) .or. t(k)%name == 'kind') cycle
         t(k)%doc = trim(t(k)%doc)//' [kind '//words_or(kinds_using(t(k)%name))//']'
      end do
      ! &rupture
      call add(t, 'rupture', 'enabled', 'logical', '-', '.true.', &
               'whether the cable breaks; a case without the &rupture group does not break')
      call add(t, 'rupture', 's_break', 'real', 'm', '-1', &
               'unstretched arc length of the break from end a; a break at an end needs that end fixed or moving', &
               0.0_dp, 0.0_dp, upper_from='cable%length', default_means='L, the end b')
      call add(t, 'rupture', 't_break', 'real', 's', '0.05', &
               'breaking time: the force across the break goes as cos^2(pi t / (2 t_break)) to zero (0: instantaneous)', &
               0.0_dp, 1.0e4_dp)
      call add(t, 'rupture', 'time', 'real', 's', '0', 'time at which the break starts (criterion ''time'')', &
               0.0_dp, 1.0e4_dp)
      call add(t, 'rupture', 'criterion', 'string', '-', "'time'", &
               "what sets the break: 'time' (at s_break, at time) or 'tension' (where and when the tension first "// &
               "reaches mbl; s_break and time are then not given)", length=16, choices='time tension')
      call add(t, 'rupture', 'mbl', 'real', 'N', '0', &
               "minimum breaking load of the line (criterion 'tension'): the line parts where and when a cell's "// &
               'tension first reaches it', 0.0_dp, 1.0e12_dp, lower_open=.true., zero_means='not given')
      ! &numerics
      call add(t, 'numerics', 'scheme', 'string', '-', "'rod'", &
               "discretisation: 'rod' (energy-conserving discrete rod) or 'box' (the paper's box scheme)", length=16, &
               choices='rod box')
      call add(t, 'numerics', 'model', 'string', '-', "'auto'", &
               "'2d' (the cable in the x-z plane), '3d' (positions x, y, z and twist; the rod scheme) "// &
               "or 'auto': 2-D when every end, force, motion, current and torque "// &
               'lies in one vertical plane (another than x-z: turned into x-z and back), 3-D otherwise', &
               length=16, choices='auto 2d 3d')
      call add(t, 'numerics', 'nodes', 'integer', '-', '121', 'number of nodes, uniform in unstretched arc length '// &
               '(uniform on each side of a break inside the cable, the break point a node)', &
               3.0_dp, 100001.0_dp)
      call add(t, 'numerics', 'dt', 'real', 's', '0', 'time step; at most 1e6 steps to t_end', 0.0_dp, 0.0_dp, &
               lower_open=.true., upper_from='numerics%t_end', zero_means='dt from courant')
      call add(t, 'numerics', 'courant', 'real', '-', '1', &
               'Courant number c dt / ds giving dt when dt = 0: c the largest axial wave speed of the static state '// &
               '(rod; box: at the end strain), ds the longest cell; at most 1e6 steps to t_end', 0.0_dp, 1.0e4_dp, &
               lower_open=.true.)
      call add(t, 'numerics', 't_end', 'real', 's', '0.16', 'end of the run', 0.0_dp, 1.0e4_dp, lower_open=.true.)
      call add(t, 'numerics', 'theta', 'real', '-', '0.5', &
               "time weight: 0.5 conserves energy (rod) and is the paper's scheme (box), second order; up to 1 damps "// &
               '(first order; the rod books the energy removed in the ledger column dissipation)', 0.5_dp, 1.0_dp)
      call add(t, 'numerics', 'mass_matrix', 'string', '-', "'averaged'", &
               "kinetic energy of the rod scheme: 'averaged' (cell-averaged velocities, exact axial waves at Courant 1 "// &
               "as the box scheme, with a tenth of the shortest wave's inertia kept) or 'lumped' (half a cell's mass "// &
               'at each node)', &
               length=16, choices='averaged lumped')
      call add(t, 'numerics', 'newton_tol', 'real', '-', '1e-7', &
               'Newton converges when every update, divided by its scale, is below this (in time steps: when the '// &
               'estimated remaining error is); scales: rod, the cell length for positions; box, 1 for strain and '// &
               'Euler parameters, T_s for shear, c(eps0) for velocities, 1/L for curvature; the statics always to 1e-10', &
               1.0e-15_dp, 1.0e-3_dp)
      call add(t, 'numerics', 'newton_max_iter', 'integer', '-', '25', 'iteration limit of one Newton solve', &
               1.0_dp, 100.0_dp)
      call add(t, 'numerics', 'reuse_jacobian', 'logical', '-', '.true.', &
               'keep the factorised Jacobian while Newton contracts well; not given: .true. for the box scheme, '// &
               '.false. for the rod (its factorisation is cheap and full Newton takes 2-5 iterations)')
      call add(t, 'numerics', 'extrapolate', 'logical', '-', '.true.', &
               'first guess of a step by extrapolation (rod: R + dt V; box: linearly from the two previous levels)')
      call add(t, 'numerics', 'skip_quiescent', 'logical', '-', '.true.', &
               'planar rod: solve each step only on the part of the cable that moves (the nodes that moved in the '// &
               'last step by more than 1e-5 newton_tol cell lengths or 16 units of round-off of the coordinates, '// &
               'and 8 nodes on either side; grown and solved again when the motion reaches the margin); the rest '// &
               'keeps its state. Results agree with the whole solve to round-off, not to the bit (docs/measurements/speed.md)')
      call add(t, 'numerics', 'min_step_fraction', 'real', '-', '0.0009765625', &
               'the step control halves a failed step down to this fraction of dt (1/1024), then stops with a named '// &
               'error', 1.0e-9_dp, 1.0_dp)
      call add(t, 'numerics', 'max_wall_time', 'real', 's', '0', &
               'wall-clock limit of the dynamics of one process (a resumed run counts from its resume); checked '// &
               'before every step attempt', 0.0_dp, 1.0e7_dp, lower_open=.true., zero_means='no limit', &
               resume_may_differ=.true.)
      ! &output
      call add(t, 'output', 'file', 'string', '-', "''", 'HDF5 result file (its directory must exist)', length=512, &
               zero_means='results/<namelist stem>.h5')
      call add(t, 'output', 'interval', 'real', 's', '0.01', 'snapshot interval; at most 1e5 snapshots', 0.0_dp, 0.0_dp, &
               lower_open=.true., upper_from='numerics%t_end', zero_means='snapshots at t = 0 and t_end only')
      call add(t, 'output', 'fields', 'string', '-', "'"//join(known_fields)//"'", &
               'snapshot fields to write, separated by blanks or commas', length=256, choices=join(known_fields), &
               word_list=.true.)
      call add(t, 'output', 'quiet', 'logical', '-', '.false.', 'no progress lines on stderr (use in batch)', &
               resume_may_differ=.true.)
      call add(t, 'output', 'energy', 'logical', '-', '.false.', 'keep the energy ledger in the history')
      call add(t, 'output', 'gnuplot', 'logical', '-', '.false.', 'also write gnuplot-ready text beside the HDF5 file')
      call add(t, 'output', 'xdmf', 'logical', '-', '.false.', &
               'also write an XDMF sidecar (file with the extension .xmf) for ParaView and other XDMF readers; '// &
               'written when the run completes', resume_may_differ=.true.)
      call add(t, 'output', 'checkpoint_interval', 'real', 's', '0', &
               'wall-clock time between checkpoints of a run, either scheme (the file &output file + .ckpt, for '// &
               'xcable --resume); a run also writes one when it gets SIGTERM, whatever this says', 0.0_dp, 1.0e7_dp, &
               lower_open=.true., zero_means='none', resume_may_differ=.true.)
      t = t(1:filled)
   end subroutine build_table

   !> The groups &segment_1 ... &segment_8, all alike: the segment's length, the variables of
   !> &cable, &material and &fluid that describe the line itself (copies of their entries,
   !> with their ranges and words; not given, the twin group's value), its nodes and its
   !> minimum breaking load.
   subroutine add_segments(t)
      !> The table, with &cable, &material and &fluid; the segments appended.
      type(schema_entry), allocatable, intent(inout) :: t(:)
      character(len=*), parameter :: twins = 'cable%diameter cable%density cable%young cable%area '// &
                                           'cable%bending_stiffness cable%gip material%law material%p material%ea '// &
                                           'material%table_strain material%table_tension material%table_file '// &
                                           'material%strain_max material%compression material%damping '// &
                                           'fluid%cd_normal fluid%cd_tangential fluid%ca_normal'
      type(schema_entry), allocatable :: base(:)
      type(schema_entry) :: e
      character(len=16) :: group
      integer :: k, i
      base = t(1:filled)
      do k = 1, max_segments
         group = segment_group(k)
         e = base(find_entry(base, 'cable', 'length'))
         call add(t, group, 'length', 'real', 'm', '0', 'unstretched length of the segment; the lengths add up to '// &
                  '&cable length (which is their sum when not given)', e%lower, e%upper, default_means='must be given')
         do i = 1, size(base)
            if (index(' '//twins//' ', ' '//trim(base(i)%group)//'%'//trim(base(i)%name)//' ') == 0) cycle
            e = base(i)
            e%twin = e%group
            e%group = group
            ! The defaults of segment_config: 0, '' or no rows (the twin group's value is taken).
            select case (e%type)
            case ('string')
               e%default = "''"
            case default
               e%default = '0'
               if (e%count == 5) e%default = '0, 0, 0, 0, 0'
               if (is_table(e)) e%default = ''
            end select
            e%doc = 'as &'//trim(e%twin)//' '//trim(e%name)//', for this segment'
            if (e%name == 'p') e%doc = trim(e%doc)//' (an element given replaces that element of &material p)'
            if (e%name == 'table_file') e%doc = trim(e%doc)//' (read as the &material table_file is)'
            call append(t, e)
         end do
         call add(t, group, 'nodes', 'integer', '-', '0', 'nodes of the segment, its two end nodes included (a '// &
                  'joint is a node of both segments); given in every segment or in none: the line has their sum '// &
                  'less the joints', 2.0_dp, 100001.0_dp, zero_means='a share of &numerics nodes by length')
         call add(t, group, 'mbl', 'real', 'N', '0', "minimum breaking load of the segment (&rupture criterion "// &
                  "'tension'): the line parts where and when a cell of this segment first reaches it", &
                  0.0_dp, 1.0e12_dp, lower_open=.true., zero_means='&rupture mbl')
      end do
   end subroutine add_segments

   !> The name of the group of segment k: 'segment_k'.
   pure function segment_group(k) result(group)
      !> Segment, 1 .. max_segments.
      integer, intent(in) :: k
      character(len=16) :: group
      write (group, '(a,i0)') 'segment_', k
   end function segment_group

   !> The segment a group describes: k for 'segment_k', 0 for any other group.
   pure integer function segment_of(group)
      !> Group name, lower case.
      character(*), intent(in) :: group
      integer :: k
      segment_of = 0
      do k = 1, max_segments
         if (trim(group) == trim(segment_group(k))) then
            segment_of = k
            return
         end if
      end do
   end function segment_of

   !> Group names as '&a, &b, &segment_1 ... &segment_8' (a run of more than two numbered
   !> groups as its first and last), each after a prefix, with a separator.
   function group_list(names, open, close, separator) result(s)
      !> Group names, blank-padded.
      character(len=*), intent(in) :: names(:)
      !> What goes before and after each name ('&' and '', or '`&' and '`').
      character(*), intent(in) :: open, close
      !> Between two names (', ').
      character(*), intent(in) :: separator
      character(:), allocatable :: s
      integer :: i, j
      s = ''
      i = 1
      do while (i <= size(names))
         j = i
         if (segment_of(names(i)) == 1) then
            do while (j < size(names))
               if (segment_of(names(j + 1)) /= segment_of(names(j)) + 1) exit
               j = j + 1
            end do
         end if
         if (len(s) > 0) s = s//separator
         if (j - i >= 2) then
            s = s//open//trim(names(i))//close//' ... '//open//trim(names(j))//close
         else
            s = s//open//trim(names(i))//close
            j = i
         end if
         i = j + 1
      end do
   end function group_list

   !> Append an entry. A number is bounded when lower and upper are given.
   subroutine add(t, group, name, type, unit, default, doc, lower, upper, count, length, choices, word_list, &
                  lower_open, upper_from, zero_means, default_means, note, resume_may_differ, own_kinds_only)
      !> The table.
      type(schema_entry), allocatable, intent(inout) :: t(:)
      !> Group, variable, type, unit, default (as the echo writes it) and meaning.
      character(*), intent(in) :: group, name, type, unit, default, doc
      !> Range of a number (both or neither).
      real(dp), intent(in), optional :: lower, upper
      !> Elements, and the length of a string.
      integer, intent(in), optional :: count, length
      !> Allowed words of a string.
      character(*), intent(in), optional :: choices
      !> Whether the string is a list of the allowed words.
      logical, intent(in), optional :: word_list
      !> Whether the lower bound is excluded.
      logical, intent(in), optional :: lower_open
      !> Variable that gives the upper bound, what 0 stands for, what the default stands for, why the range.
      character(*), intent(in), optional :: upper_from, zero_means, default_means, note
      !> Whether it may differ between a run and its resume.
      logical, intent(in), optional :: resume_may_differ
      !> Whether the echo writes it only for the end kinds that use it.
      logical, intent(in), optional :: own_kinds_only
      type(schema_entry) :: e
      e%group = group
      e%name = name
      e%type = type
      e%unit = unit
      e%default = default
      e%doc = doc
      if (present(lower) .and. present(upper)) then
         e%bounded = .true.
         e%lower = lower
         e%upper = upper
      end if
      if (present(count)) e%count = count
      if (present(length)) e%length = length
      if (present(choices)) e%choices = choices
      if (present(word_list)) e%word_list = word_list
      if (present(lower_open)) e%lower_open = lower_open
      if (present(upper_from)) e%upper_from = upper_from
      if (present(zero_means)) e%zero_means = zero_means
      if (present(default_means)) e%default_means = default_means
      if (present(note)) e%note = note
      if (present(resume_may_differ)) e%resume_may_differ = resume_may_differ
      if (present(own_kinds_only)) e%own_kinds_only = own_kinds_only
      call append(t, e)
   end subroutine add

   !> Append an entry made whole.
   subroutine append(t, e)
      !> The table.
      type(schema_entry), allocatable, intent(inout) :: t(:)
      !> The entry.
      type(schema_entry), intent(in) :: e
      if (filled == size(t)) then
         block
            type(schema_entry), allocatable :: bigger(:)
            allocate (bigger(2*size(t)))
            bigger(1:filled) = t
            call move_alloc(bigger, t)
         end block
      end if
      filled = filled + 1
      t(filled) = e
   end subroutine append

   !> Blank-separated words as 'a, b or c'.
   function words_or(words) result(text)
      !> The words.
      character(*), intent(in) :: words
      character(:), allocatable :: text, rest
      integer :: i
      text = ''
      rest = trim(adjustl(words))
      do while (len(rest) > 0)
         i = index(rest, ' ')
         if (i == 0) then
            if (len(text) > 0) text = text//' or '
            text = text//rest
            exit
         end if
         if (len(text) > 0) text = text//', '
         text = text//rest(1:i - 1)
         rest = trim(adjustl(rest(i + 1:)))
      end do
   end function words_or

   !> The groups of the table, in order.
   function schema_groups(t) result(groups)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      character(len=16), allocatable :: groups(:)
      integer :: i
      allocate (groups(0))
      do i = 1, size(t)
         if (.not. any(groups == t(i)%group)) groups = [character(len=16) :: groups, t(i)%group]
      end do
   end function schema_groups

   !> The indices of the entries of a group, in order.
   function group_entries(t, group) result(indices)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      !> Group name.
      character(*), intent(in) :: group
      integer, allocatable :: indices(:)
      integer :: i
      allocate (indices(0))
      do i = 1, size(t)
         if (t(i)%group == group) indices = [indices, i]
      end do
   end function group_entries

   !> Index of group%name in the table (0: none).
   pure integer function find_entry(t, group, name)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      !> Group and variable name, lower case.
      character(*), intent(in) :: group, name
      integer :: i
      find_entry = 0
      do i = 1, size(t)
         if (t(i)%group == group .and. t(i)%name == name) then
            find_entry = i
            return
         end if
      end do
   end function find_entry

   !> Whether an entry is a table (an array too long to list or sweep).
   pure logical function is_table(e)
      !> Entry.
      type(schema_entry), intent(in) :: e
      is_table = e%count == max_table_points
   end function is_table

   !> A bound as text: an integer for an integer variable, else the shortest real.
   function bound_text(e, x) result(s)
      !> Entry.
      type(schema_entry), intent(in) :: e
      !> Bound.
      real(dp), intent(in) :: x
      character(:), allocatable :: s
      character(len=24) :: buf
      if (e%type == 'integer') then
         write (buf, '(i0)') nint(x)
         s = trim(buf)
      else
         s = real_text(x)
      end if
   end function bound_text

   !> What a variable allows, as in 'must be ...': "in [0.01, 1e5]", "> 0 and <= 1e9",
   !> "0 (for pi d^2 / 4) or in [...]", "an integer from 3 to 100001", "one of 'tanh', 'linear'".
   !> upper gives the value of an upper bound taken from another variable (upper_from).
   function allowed_text(e, upper) result(s)
      !> Entry.
      type(schema_entry), intent(in) :: e
      !> Effective upper bound when e%upper_from is set.
      real(dp), intent(in), optional :: upper
      character(:), allocatable :: s, hi
      if (len_trim(e%choices) > 0) then
         if (e%word_list) then
            s = 'words from: '//comma_list(e%choices, "")
         else
            s = 'one of '//comma_list(e%choices, "'")
         end if
         return
      end if
      if (.not. e%bounded) then
         s = ''
         return
      end if
      if (len_trim(e%upper_from) > 0) then
         hi = upper_name(e)
         if (present(upper)) hi = bound_text(e, upper)//' ('//hi//')'
      else
         hi = bound_text(e, e%upper)
      end if
      if (e%type == 'integer') then
         s = 'an integer from '//bound_text(e, e%lower)//' to '//hi
      else if (e%lower_open) then
         s = '> '//bound_text(e, e%lower)//' and <= '//hi
      else
         s = 'in ['//bound_text(e, e%lower)//', '//hi//']'
      end if
      if (len_trim(e%zero_means) > 0) s = '0 ('//trim(e%zero_means)//') or '//s
   end function allowed_text

   !> The variable an upper bound is taken from, as '&group name'.
   function upper_name(e) result(s)
      !> Entry with upper_from set.
      type(schema_entry), intent(in) :: e
      character(:), allocatable :: s
      integer :: pct
      pct = index(e%upper_from, '%')
      s = '&'//e%upper_from(1:pct - 1)//' '//trim(e%upper_from(pct + 1:))
   end function upper_name

   !> The table as text: 'markdown' (the input table of docs/user/namelist.md) or 'tsv'
   !> (group, variable, type, count, with a header line; the sweep scripts'
   !> table). Lines end with a new line; '' for an unknown format.
   function schema_text(format) result(text)
      !> 'markdown' or 'tsv'.
      character(*), intent(in) :: format
      character(:), allocatable :: text
      type(schema_entry), allocatable :: t(:)
      character(len=16), allocatable :: groups(:)
      character(len=*), parameter :: nl = new_line('a'), tab = achar(9)
      character(:), allocatable :: heading
      integer :: i, ig, jg
      integer, allocatable :: mine(:)
      character(len=24) :: buf
      t = schema_table()
      text = ''
      select case (format)
      case ('tsv')
         text = 'group'//tab//'variable'//tab//'type'//tab//'count'//nl
         do i = 1, size(t)
            write (buf, '(i0)') t(i)%count
            text = text//trim(t(i)%group)//tab//trim(t(i)%name)//tab//trim(t(i)%type)//tab//trim(buf)//nl
         end do
      case ('markdown')
         text = '| group | variable | type | unit | default | allowed | meaning |'//nl// &
                '|---|---|---|---|---|---|---|'//nl
         groups = schema_groups(t)
         ig = 1
         do while (ig <= size(groups))
            ! Groups with the same variables (&end_a, &end_b; &segment_1 ... &segment_8) share their rows.
            jg = ig
            do while (jg < size(groups))
               if (.not. same_variables(t, groups(ig), groups(jg + 1))) exit
               jg = jg + 1
            end do
            heading = group_list(groups(ig:jg), '`&', '`', ', ')
            mine = group_entries(t, groups(ig))
            do i = 1, size(mine)
               if (i > 1) heading = ''
               text = text//markdown_row(t(mine(i)), heading)//nl
            end do
            ig = jg + 1
         end do
      end select
   end function schema_text

   !> Write the table ('markdown' or 'tsv') to a unit.
   subroutine write_schema(unit, format, error)
      !> Open formatted unit.
      integer, intent(in) :: unit
      !> 'markdown' or 'tsv'.
      character(*), intent(in) :: format
      !> Error for an unknown format.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: text
      if (format /= 'markdown' .and. format /= 'tsv') then
         call fatal_error(error, "--schema "//format//": unknown format; allowed: markdown, tsv", stat_input)
         return
      end if
      text = schema_text(format)
      write (unit, '(a)', advance='no') text
   end subroutine write_schema

   !> One row of the markdown table.
   function markdown_row(e, heading) result(row)
      !> Entry.
      type(schema_entry), intent(in) :: e
      !> Text of the group column ('' after the first row of a group).
      character(*), intent(in) :: heading
      character(:), allocatable :: row, type, default, allowed
      character(len=24) :: buf
      type = trim(e%type)
      if (e%count > 1) then
         write (buf, '(i0)') e%count
         type = type//'('//trim(buf)//')'
      else if (e%type == 'string') then
         write (buf, '(i0)') e%length
         type = type//'('//trim(buf)//')'
      end if
      if (len_trim(e%default) == 0) then
         default = 'no rows'
      else
         default = '`'//trim(e%default)//'`'
      end if
      if (len_trim(e%zero_means) > 0 .and. (e%default == '0' .or. e%default == "''")) &
         default = default//' ('//trim(e%zero_means)//')'
      if (len_trim(e%default_means) > 0) default = default//' ('//trim(e%default_means)//')'
      if (len_trim(e%twin) > 0) default = '&'//trim(e%twin)//"'s value"
      allowed = allowed_text(e)
      if (len_trim(e%choices) > 0) then
         if (e%word_list) then
            allowed = 'words from `'//trim(e%choices)//'`'
         else
            allowed = comma_list(e%choices, '`'//"'", "'"//'`')
         end if
      else if (e%type == 'logical') then
         allowed = '`.true.`, `.false.`'
      else if (len(allowed) == 0) then
         allowed = 'text'
      end if
      row = '| '//heading//' | `'//trim(e%name)//'` | '//type//' | '//trim(e%unit)//' | '//default//' | '// &
            allowed//' | '//trim(e%doc)
      if (len_trim(e%note) > 0) row = row//' ('//trim(e%note)//')'
      if (e%resume_may_differ) row = row//'; may differ on --resume'
      row = escape_tags(row//' |')
   end function markdown_row

   !> '<' before a letter, outside `code`, as '&lt;' (markdown would take <namelist stem> for a tag).
   function escape_tags(text) result(s)
      !> A row of the table.
      character(*), intent(in) :: text
      character(:), allocatable :: s
      logical :: in_code
      integer :: i
      s = ''
      in_code = .false.
      do i = 1, len(text)
         if (text(i:i) == '`') in_code = .not. in_code
         if (text(i:i) == '<' .and. .not. in_code .and. verify(text(i + 1:min(i + 1, len(text))), &
                                                                'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ') == 0) then
            s = s//'&lt;'
         else
            s = s//text(i:i)
         end if
      end do
   end function escape_tags

   !> Whether two groups have the same variables (names, types, defaults, meanings).
   logical function same_variables(t, a, b)
      !> The table.
      type(schema_entry), intent(in) :: t(:)
      !> Two groups.
      character(*), intent(in) :: a, b
      integer, allocatable :: ia(:), ib(:)
      integer :: i
      ia = group_entries(t, a)
      ib = group_entries(t, b)
      same_variables = size(ia) == size(ib)
      if (.not. same_variables) return
      do i = 1, size(ia)
         same_variables = t(ia(i))%name == t(ib(i))%name .and. t(ia(i))%type == t(ib(i))%type .and. &
                          t(ia(i))%default == t(ib(i))%default .and. t(ia(i))%doc == t(ib(i))%doc
         if (.not. same_variables) return
      end do
   end function same_variables

   !> Blank-separated words as "'a', 'b', 'c'" (with the given quotes).
   function comma_list(words, open, close) result(s)
      !> Blank-separated words, and what goes before each.
      character(*), intent(in) :: words, open
      !> What goes after each (open if absent).
      character(*), intent(in), optional :: close
      character(:), allocatable :: s, last
      integer :: i, start
      last = open
      if (present(close)) last = close
      s = ''
      start = 0
      do i = 1, len(words) + 1
         if (i > len(words)) then
            if (start > 0) s = s//open//words(start:i - 1)//last
         else if (words(i:i) == ' ') then
            if (start > 0) s = s//open//words(start:i - 1)//last//', '
            start = 0
         else if (start == 0) then
            start = i
         end if
      end do
      if (len(s) >= 2) then
         if (s(len(s) - 1:) == ', ') s = s(1:len(s) - 2)
      end if
   end function comma_list

   !> Names joined by blanks.
   function join(names) result(s)
      !> Names, blank-padded.
      character(len=*), intent(in) :: names(:)
      character(:), allocatable :: s
      integer :: i
      s = trim(names(1))
      do i = 2, size(names)
         s = s//' '//trim(names(i))
      end do
   end function join
end module xcable_io_schema
