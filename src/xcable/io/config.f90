!> The resolved content of a case file: one component per namelist variable,
!> grouped as in the file, with the paper's values as defaults (the slow
!> rupture at 315 kN). The schema (io/schema.f90) describes every component:
!> its group, type, unit, range and meaning; the reader, the validation, the
!> echo into the result file and docs/user/namelist.md all follow the schema.
module xcable_io_config
   use xcable_core_kinds, only: dp
   use xcable_material_law, only: paper_tanh_coefficients
   use xcable_numerics_facets, only: facet_at
   implicit none
   private
   public :: case_config, end_config, segment_config, point_config, line_config, max_table_points, max_segments, &
             max_points, max_lines, point_kinds, point_end_variables, point_body_variables

   !> Longest inline table (law tables and end histories).
   integer, parameter :: max_table_points = 1000

   !> One end of the cable (&end_a at s = 0, &end_b at s = L).
   type :: end_config
      !> A kind of the registry (ends/registry.f90): 'fixed', 'free', 'force', 'motion', 'mass', 'spring'.
      character(len=16) :: kind = 'fixed'
      !> Position of a fixed end, the mean position of a moving end, or a spring's anchor, m (x horizontal, z up).
      real(dp) :: x = 0, z = 0
      !> Its y (3-D model), m.
      real(dp) :: y = 0
      !> Applied force of a force end (constant value, or the value the ramp starts from), N.
      real(dp) :: force_x = 0, force_z = 0
      !> y component of the applied force (3-D model), N; torque about the end's outward tangent, N m.
      real(dp) :: force_y = 0, torque = 0
      !> Force history: 'constant', 'ramp' (cos^2 to zero over ramp_time) or 'table'.
      character(len=16) :: history = 'constant'
      !> Duration of the force ramp, or of the smooth start of a motion, s.
      real(dp) :: ramp_time = 0
      !> Motion of a moving end: 'harmonic' or 'table'.
      character(len=16) :: motion = 'harmonic'
      !> Harmonic motion: amplitude (m), period (s), phase (rad) and direction (unit vector, x and z).
      real(dp) :: amplitude = 0, period = 1, phase = 0, direction_x = 0, direction_z = 1
      !> y component of the direction of the harmonic motion (3-D model).
      real(dp) :: direction_y = 0
      !> Point mass of a mass end (or at a spring end), kg.
      real(dp) :: mass = 0
      !> A spring end: stiffness (N/m), damping of the dashpot in line with it (N s/m), rest length (m).
      real(dp) :: stiffness = 0, damping = 0, rest_length = 0
      !> Inline table: times (s) and x, z columns (force in N, or displacement in m).
      real(dp) :: table_time(max_table_points) = 0, table_x(max_table_points) = 0, table_z(max_table_points) = 0
      !> Its y column (3-D model; 0 when not given).
      real(dp) :: table_y(max_table_points) = 0
      !> Number of table rows given inline (0: none).
      integer :: table_rows = 0
      !> Table file with columns t, x (, z) or t, x, y, z ('' : none).
      character(len=512) :: table_file = ''
   end type end_config

   !> Most segments of a line (&segment_1 ... &segment_8).
   integer, parameter :: max_segments = 8

   !> One segment of the line (&segment_k, counted from end a): the variables of &cable,
   !> &material and &fluid that differ from those groups' values, and its own length, nodes
   !> and minimum breaking load. A variable not given in the group takes the line's value
   !> (case_config%segment_case resolves them; case_config%is_given('segment_k', name) tells
   !> which were given).
   type :: segment_config
      !> Unstretched length, m (must be given).
      real(dp) :: length = 0
      !> As in &cable.
      real(dp) :: diameter = 0, density = 0, young = 0, area = 0, bending_stiffness = 0, gip = 0
      !> As in &material.
      character(len=16) :: law = '', compression = ''
      real(dp) :: p(5) = 0, ea = 0, strain_max = 0, damping = 0
      real(dp) :: material_table_strain(max_table_points) = 0, material_table_tension(max_table_points) = 0
      integer :: material_table_rows = 0
      character(len=512) :: material_table_file = ''
      !> As in &fluid.
      real(dp) :: cd_normal = 0, cd_tangential = 0, ca_normal = 0
      !> Nodes of the segment, its two end nodes included (0: a share of &numerics nodes in
      !> proportion to its length).
      integer :: nodes = 0
      !> Minimum breaking load, N (&rupture criterion 'tension'; 0: &rupture mbl).
      real(dp) :: mbl = 0
   end type segment_config

   !> Most bodies on a line (&point_1 ... &point_8).
   integer, parameter :: max_points = 8

   !> The kinds of a network point (&point_k kind; '' : a body on the single line).
   character(len=*), parameter :: point_kinds = 'fixed free motion'

   !> The variables of &point_k that a network point takes from the end kinds (those of an end of
   !> kind 'motion': position, motion and its table), kept in point_config%end.
   character(len=*), parameter :: point_end_variables = 'x y z motion amplitude period phase direction_x '// &
                                                        'direction_y direction_z ramp_time table_time table_x '// &
                                                        'table_y table_z table_file'

   !> The variables of the body of &point_k (at a joint of the single line, or at a free network point).
   character(len=*), parameter :: point_body_variables = 'mass volume ca cd area'

   !> A body at a joint of two segments (&point_k): a clump weight or a buoy; or, with a kind, a
   !> point of a network of lines (&line_k end_a, end_b): fixed, moved, or free (a junction, with
   !> the body there).
   type :: point_config
      !> The joint: k > 0 the end of &segment_k (where &segment_k+1 starts; the last is end b), 0 end
      !> a (-1: not given). Not for a network point.
      integer :: joint = -1
      !> Mass, kg; displaced volume, m^3; added-mass and drag coefficients; projected area, m^2.
      real(dp) :: mass = 0, volume = 0, ca = 0, cd = 0, area = 0
      !> The kind of a network point: 'fixed', 'free' or 'motion' ('' : a body on the single line).
      !> Its position and motion are an end's: case_config%point_end(k).
      character(len=16) :: kind = ''
   contains
      !> Whether the point is a point of a network (a kind given).
      procedure :: in_network => point_in_network
   end type point_config

   !> Most lines of a network (&line_1 ... &line_8).
   integer, parameter :: max_lines = 8

   !> One line of a network (&line_k): between two network points, made of &segment_k groups
   !> from its end a, or uniform (&cable and &material).
   type :: line_config
      !> The points at end a and end b as written ('point_3'), and their numbers (0: none such).
      character(len=16) :: point_names(2) = ''
      integer :: end_point(2) = 0
      !> Number of segments listed (0: uniform) and the &segment_k groups, from end a.
      integer :: segment_count = 0
      integer :: segments(max_segments) = 0
      !> Unstretched length, m (0: not given; after validation the line's length).
      real(dp) :: length = 0
      !> Nodes of a uniform line (0: not given; after validation &numerics nodes where not given).
      integer :: nodes = 0
   end type line_config

   !> A case.
   type :: case_config
      !> Namelist file the case came from.
      character(:), allocatable :: source
      ! &cable
      !> Unstretched length L, m.
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
      !> Torsional stiffness GIp, N m^2 (0: EI / (1 + nu) with nu = 0.4).
      real(dp) :: gip = 0
      ! &material
      !> 'tanh' (eq. 17), 'linear' or 'table' (rows of strain and tension).
      character(len=16) :: law = 'tanh'
      !> Coefficients of eq. 17.
      real(dp) :: p(5) = paper_tanh_coefficients
      !> EA of the linear law, N (0: young * area).
      real(dp) :: ea = 0
      !> Largest strain the law is used for in statics.
      real(dp) :: strain_max = 0.35_dp
      !> Behaviour in compression: 'law' (the law continued below zero) or 'none' (no compressive tension).
      character(len=16) :: compression = 'none'
      !> Rows of the 'table' law: strains and tensions (N), inline (&material table_strain, table_tension).
      real(dp) :: material_table_strain(max_table_points) = 0, material_table_tension(max_table_points) = 0
      !> Number of rows given inline or read from the file (0: none).
      integer :: material_table_rows = 0
      !> File with the rows of the 'table' law: columns strain, tension ('' : none; &material table_file).
      character(len=512) :: material_table_file = ''
      !> Internal (Kelvin-Voigt) damping c of T = f(eps) + c d(eps)/dt, N s (&material damping).
      real(dp) :: damping = 0
      !> &fluid: density (kg/m^3; 0: no fluid), drag and added-mass coefficients, uniform current (m/s).
      real(dp) :: fluid_density = 0, cd_normal = 0, cd_tangential = 0, ca_normal = 0, current_x = 0, current_z = 0
      !> &fluid current_y: the current's y component (3-D model), m/s.
      real(dp) :: current_y = 0
      !> &fluid surface_z: height of the still-water level, m; air_density: the air above it, kg/m^3;
      !> surface_band: height over which a cross-section goes from dry to wet, m (negative: the diameter).
      real(dp) :: surface_z = 0, air_density = 0, surface_band = -1
      !> &seabed: depth of the seabed under z = 0 at x = y = 0, m (0: no seabed); its slopes dz/dx and
      !> dz/dy; contact stiffness (Pa: N/m^2 per m of penetration and per m of diameter) and damping
      !> (Pa s/m); Coulomb friction coefficients along and across the line; the slip speed below which
      !> friction is proportional to the slip, m/s.
      real(dp) :: seabed_depth = 0, seabed_slope_x = 0, seabed_slope_y = 0, seabed_stiffness = 3.0e6_dp, &
                  seabed_damping = 3.0e5_dp, mu_axial = 0, mu_lateral = 0, slip_velocity = 1.0e-2_dp
      !> &seabed static_friction: the statics' friction along the bottom, fully mobilised towards
      !> end a or end b (the anchor), or 'none'.
      character(len=16) :: static_friction = 'none'
      !> &seabed bathymetry_file: a grid of depths (MoorDyn's bathymetry file) in place of the plane
      !> ('' : none); read into bathymetry_x, bathymetry_y (grid lines, m) and bathymetry_depth
      !> (depths below z = 0 at the grid points, m; (x, y)).
      character(len=512) :: bathymetry_file = ''
      real(dp), allocatable :: bathymetry_x(:), bathymetry_y(:), bathymetry_depth(:, :)
      ! &segment_1 ... &segment_8
      !> Number of segments given (0: the line is one segment, &cable and &material).
      integer :: segment_count = 0
      !> The segments, from end a; only 1 .. segment_count are used.
      type(segment_config) :: segments(max_segments)
      ! &point_1 ... &point_8
      !> Number of bodies given (numbered without a gap).
      integer :: point_count = 0
      !> The bodies; only 1 .. point_count are used.
      type(point_config) :: points(max_points)
      !> The network points as ends (&point_k kind, x, y, z and a motion point's motion, as &end_a
      !> kind = 'motion' has them): point_ends(k) for point k, its kind that of points(k).
      !> Allocated (max_points) only where a &point_k gives one of these variables; read them
      !> with point_end(k). (Not an end in each point_config: an end carries its tables, and a
      !> case is copied often; an allocatable end inside points(:) made every copy three times
      !> dearer, 25 % more instructions in a run's start.)
      type(end_config), allocatable :: point_ends(:)
      ! &line_1 ... &line_8
      !> Number of lines of a network given (0: the single line of &end_a and &end_b).
      integer :: line_count = 0
      !> The lines; only 1 .. line_count are used.
      type(line_config) :: lines(max_lines)
      ! &static
      !> End tension of the paper's symmetric catenary, N (ends at one height, span from the tension).
      real(dp) :: tension = 315.0e3_dp
      ! &end_a, &end_b
      type(end_config) :: end_a, end_b
      ! &rupture
      !> Whether the cable breaks: &rupture enabled, whose default .true. holds when the group is
      !> given; a namelist without &rupture does not break (the reader sets .false., io/input.f90
      !> read_values).
      logical :: break_enabled = .true.
      !> Unstretched arc length of the break from end a, m (negative: L, the paper's end break).
      real(dp) :: s_break = -1
      !> Breaking time: the force across the break goes as cos^2 to zero over t_break, s.
      real(dp) :: t_break = 0.05_dp
      !> Time at which the break starts, s (&rupture time).
      real(dp) :: break_time = 0
      !> What sets the break: 'time' (at s_break, at break_time) or 'tension' (where and when the
      !> tension first reaches mbl).
      character(len=16) :: break_criterion = 'time'
      !> Minimum breaking load, N (&rupture mbl; criterion 'tension'; 0: not given). One value for
      !> the line: a per-segment value comes with the segments.
      real(dp) :: mbl = 0
      !> The line of a network that parts (&rupture line: &line_k, criterion 'time'; 0: not given).
      !> s_break is then measured along that line from its end a.
      integer :: break_line = 0
      ! &numerics
      !> Discretisation: 'rod' (energy-conserving discrete rod) or 'box' (the paper's box scheme).
      character(len=16) :: scheme = 'rod'
      !> Model: 'auto' (2-D for a planar scene, 3-D otherwise), '2d' or '3d'.
      character(len=16) :: model = 'auto'
      !> Number of nodes.
      integer :: nodes = 121
      !> Time step, s (0: from courant).
      real(dp) :: dt = 0
      !> Courant number c(eps0) dt / ds giving dt when dt = 0.
      real(dp) :: courant = 1
      !> End of the run, s.
      real(dp) :: t_end = 0.16_dp
      !> Time weight theta (0.5: conservative / the paper's).
      real(dp) :: theta = 0.5_dp
      !> Kinetic energy of the rod scheme: 'averaged' (cell-averaged velocities, as the box scheme) or 'lumped'.
      character(len=16) :: mass_matrix = 'averaged'
      !> Newton tolerance on the scaled update.
      real(dp) :: newton_tol = 1.0e-7_dp
      !> Newton iteration limit.
      integer :: newton_max_iter = 25
      !> Keep the factorised Jacobian while Newton contracts well.
      logical :: reuse_jacobian = .true.
      !> First guess of a step by extrapolation.
      logical :: extrapolate = .true.
      !> Rod: solve each step only where the cable moves.
      logical :: skip_quiescent = .true.
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
      !> Write an XDMF sidecar (.xmf) that lets ParaView and other XDMF readers open the HDF5 file.
      logical :: xdmf = .false.
      !> Wall-clock time between checkpoints of a run (either scheme), s (0: none; SIGTERM still writes one).
      real(dp) :: checkpoint_interval = 0
      !> Variables assigned in the file, as 'group%variable' names separated by blanks
      !> (so that "both given" and "not given" can be told apart from defaults).
      character(:), allocatable :: given
   contains
      !> Whether group%variable was assigned in the file.
      procedure :: is_given
      !> Whether every end, load, current and motion lies in the x-z plane.
      procedure :: is_planar
      !> The model that runs: '2d' or '3d'.
      procedure :: model_to_run
      !> Whether the case has a seabed (&seabed depth > 0 or a bathymetry).
      procedure :: has_seabed
      !> Height of the seabed under a horizontal point, m.
      procedure :: seabed_z
      !> Number of segments of the line (1 without &segment_ groups).
      procedure :: segments_of_line
      !> The case seen by one segment: its values in &cable, &material and &fluid.
      procedure :: segment_case
      !> Whether the case is a network of lines (&line_k groups).
      procedure :: is_network
      !> The case of line l of a network alone, as a single line.
      procedure :: line_case
      !> The line ends that meet at a network point: (line, side) pairs.
      procedure :: point_lines
      !> A network point as an end (its kind, position and motion), for the end registry's builder.
      procedure :: point_end
   end type case_config

contains

   !> Whether a variable was assigned in the case file.
   pure logical function is_given(self, group, variable)
      !> The case.
      class(case_config), intent(in) :: self
      !> Group and variable name (lower case).
      character(*), intent(in) :: group, variable
      is_given = .false.
      if (.not. allocated(self%given)) return
      is_given = index(' '//self%given//' ', ' '//group//'%'//variable//' ') > 0
   end function is_given

   !> Whether the scene is planar: every end position, force, motion direction,
   !> current, force or motion table and torque in the x-z plane (y = 0 and no torque).
   pure logical function is_planar(self)
      !> The case.
      class(case_config), intent(in) :: self
      is_planar = self%current_y == 0 .and. end_planar(self%end_a) .and. end_planar(self%end_b)
   end function is_planar

   pure logical function end_planar(e)
      type(end_config), intent(in) :: e
      end_planar = e%y == 0 .and. e%force_y == 0 .and. e%direction_y == 0 .and. e%torque == 0 .and. &
                   all(e%table_y(1:e%table_rows) == 0)
   end function end_planar

   !> '2d' or '3d': model = '2d' or '3d' as given; 'auto' takes 2-D for a planar scene; a network
   !> of lines (&line_k) is 3-D.
   pure function model_to_run(self) result(model)
      !> The case.
      class(case_config), intent(in) :: self
      character(len=2) :: model
      ! A network of lines: the 3-D model ('2d' is refused by the validation).
      if (self%line_count > 0) then
         model = '3d'
         return
      end if
      select case (trim(self%model))
      case ('2d')
         model = '2d'
      case ('3d')
         model = '3d'
      case default
         model = merge('2d', '3d', self%is_planar())
      end select
   end function model_to_run

   !> Whether the case has a seabed: &seabed depth > 0, or a bathymetry read from its file.
   pure logical function has_seabed(self)
      !> The case.
      class(case_config), intent(in) :: self
      has_seabed = self%seabed_depth > 0 .or. allocated(self%bathymetry_depth)
   end function has_seabed

   !> Height of the seabed under the horizontal point (x, y), m: the plane of &seabed depth,
   !> slope_x and slope_y, or the bathymetry's facets.
   pure real(dp) function seabed_z(self, x, y)
      !> The case.
      class(case_config), intent(in) :: self
      !> The point, m.
      real(dp), intent(in) :: x, y
      real(dp) :: sx, sy
      if (allocated(self%bathymetry_depth)) then
         call facet_at(self%bathymetry_x, self%bathymetry_y, -self%bathymetry_depth, x, y, seabed_z, sx, sy)
      else
         seabed_z = -self%seabed_depth + self%seabed_slope_x*x + self%seabed_slope_y*y
      end if
   end function seabed_z

   !> Number of segments of the line: segment_count, or 1 without &segment_ groups.
   pure integer function segments_of_line(self)
      !> The case.
      class(case_config), intent(in) :: self
      segments_of_line = max(self%segment_count, 1)
   end function segments_of_line

   !> The case as segment k sees it: &cable, &material and &fluid with the segment's values
   !> where its group gives them, its length in length and its breaking load in mbl (the
   !> line's &rupture mbl where it gives none). A value the line derives from others (area,
   !> EI, GIp, EA) is 0 (derived again, by the section) where the segment gives what it is
   !> derived from. Without segments (segment_count = 0), k = 1 is the case itself.
   function segment_case(self, k) result(c)
      !> The case.
      class(case_config), intent(in) :: self
      !> Segment, 1 .. segments_of_line().
      integer, intent(in) :: k
      type(case_config) :: c
      real(dp), parameter :: pi = acos(-1.0_dp)
      !> Poisson ratio of the default GIp = EI / (1 + nu), as io/input/checks.f90 derives it.
      real(dp), parameter :: poisson = 0.4_dp
      character(len=16) :: g
      c = self
      if (self%segment_count == 0) return
      associate (sg => self%segments(k))
         write (g, '(a,i0)') 'segment_', k
         c%length = sg%length
         if (given('diameter')) c%diameter = sg%diameter
         if (given('density')) c%density = sg%density
         if (given('young')) c%young = sg%young
         if (given('area')) c%area = sg%area
         if (given('bending_stiffness')) c%bending_stiffness = sg%bending_stiffness
         if (given('gip')) c%gip = sg%gip
         if (given('law')) c%law = sg%law
         if (given('compression')) c%compression = sg%compression
         if (given('p')) c%p = sg%p
         if (given('ea')) c%ea = sg%ea
         if (given('strain_max')) c%strain_max = sg%strain_max
         if (given('damping')) c%damping = sg%damping
         if (given('table_strain') .or. given('table_tension') .or. given('table_file')) then
            c%material_table_strain = sg%material_table_strain
            c%material_table_tension = sg%material_table_tension
            c%material_table_rows = sg%material_table_rows
            c%material_table_file = sg%material_table_file
         end if
         if (given('cd_normal')) c%cd_normal = sg%cd_normal
         if (given('cd_tangential')) c%cd_tangential = sg%cd_tangential
         if (given('ca_normal')) c%ca_normal = sg%ca_normal
         if (sg%mbl > 0) c%mbl = sg%mbl
         ! What &cable derives (the area from the diameter, EI from young and the diameter, GIp
         ! from EI, the linear law's EA from young and the area; 0 in the file, the derived
         ! value after derive_defaults or in the echo of the case) a segment that gives what it
         ! comes from, but not the derived value itself, derives from its own values: 0 here,
         ! derived by the section.
         if (.not. given('area') .and. given('diameter') .and. &
             derived(self%area, 0.25_dp*pi*self%diameter**2)) c%area = 0
         if (.not. given('bending_stiffness') .and. (given('diameter') .or. given('young')) .and. &
             derived(self%bending_stiffness, self%young*pi*self%diameter**4/64)) c%bending_stiffness = 0
         if (.not. given('gip') .and. c%bending_stiffness /= self%bending_stiffness .and. &
             derived(self%gip, self%bending_stiffness/(1 + poisson))) c%gip = 0
         if (.not. given('ea') .and. (given('young') .or. given('area') .or. given('diameter')) .and. &
             derived(self%ea, self%young*self%area)) c%ea = 0
      end associate
   contains
      logical function given(name)
         character(*), intent(in) :: name
         given = self%is_given(trim(g), name)
      end function given

      !> Whether the line's value of a variable is the derived one: 0, or what the line's other
      !> values give (to the bit: a value given that happens to be it is taken as derived).
      logical function derived(value, from_others)
         real(dp), intent(in) :: value, from_others
         derived = value == 0 .or. value == from_others
      end function derived
   end function segment_case

   !> Whether a point is a point of a network: a kind given (&point_k kind).
   pure logical function point_in_network(self)
      !> The point.
      class(point_config), intent(in) :: self
      point_in_network = len_trim(self%kind) > 0
   end function point_in_network

   !> Point k as an end: its kind ('fixed', 'free', 'motion'; '' for a body on the single line),
   !> its position x, y, z (a free point's first guess) and a motion point's motion; for 'fixed'
   !> and 'motion' what the end registry's builder takes (ends/registry.f90). The defaults of an
   !> end where the case has no point_ends.
   pure function point_end(self, k) result(e)
      !> The case.
      class(case_config), intent(in) :: self
      !> Point, 1 .. point_count.
      integer, intent(in) :: k
      type(end_config) :: e
      if (allocated(self%point_ends)) then
         e = self%point_ends(k)
      else
         e = end_config()
      end if
      e%kind = self%points(k)%kind
   end function point_end

   !> Whether the case is a network of lines (&line_1 ... &line_n).
   pure logical function is_network(self)
      !> The case.
      class(case_config), intent(in) :: self
      is_network = self%line_count > 0
   end function is_network

   !> The line ends that meet at point p: ends(1, i) the line, ends(2, i) its side (1: end a,
   !> 2: end b), by line and side; none for a point that joins no line.
   pure function point_lines(self, p) result(ends)
      !> The case (validated: the lines' end_point resolved).
      class(case_config), intent(in) :: self
      !> Point, 1 .. point_count.
      integer, intent(in) :: p
      integer, allocatable :: ends(:, :)
      integer :: l, side, n
      n = count(self%lines(1:self%line_count)%end_point(1) == p) + &
          count(self%lines(1:self%line_count)%end_point(2) == p)
      allocate (ends(2, n))
      n = 0
      do l = 1, self%line_count
         do side = 1, 2
            if (self%lines(l)%end_point(side) /= p) cycle
            n = n + 1
            ends(:, n) = [l, side]
         end do
      end do
   end function point_lines

   !> The case of line l of a network alone, as a single line that the code of one line runs:
   !> its segments the &segment_k groups it lists, in order (none: &cable with the line's length
   !> and &numerics nodes the line's nodes); &end_a and &end_b from its points (a fixed or motion
   !> point's end; a free point held fixed at its x, y, z, the first guess the network starts
   !> from); the body of a free point as &point_1 (and &point_2) at its end, on the lowest-numbered
   !> line that ends at that point only; no &line groups, no network points, no &static tension,
   !> the 3-D model. The break: the line of a break by time (&rupture line = l, enabled) keeps it,
   !> criterion 'time', its time, t_break and s_break (along the line from its end a, as the
   !> network's: -1 its end b), and the &rupture variables given (but line); every other line, and
   !> every line of a break by tension, does not break (break_enabled .false.) but keeps the MBLs
   !> (mbl and its segments'), which the network's break by tension reads. is_given answers for
   !> the groups it makes as if the file had written them: the segments' variables under their
   !> new numbers, the ends' kind and position (and a motion point's variables given), the bodies'
   !> joint and variables given. (The body sits on an end held here: the case is a start for the
   !> network's solve, not a case to validate.)
   function line_case(self, l) result(c)
      !> The case (validated).
      class(case_config), intent(in) :: self
      !> Line, 1 .. line_count.
      integer, intent(in) :: l
      type(case_config) :: c
      character(len=16) :: side_group
      character(:), allocatable :: given, names, all_given
      integer :: k, j, side, p, pos
      type(point_config) :: body
      type(end_config) :: e
      logical :: parts
      ! Whether this line is the one that parts at a time (its break is the single line's).
      parts = self%break_enabled .and. trim(self%break_criterion) == 'time' .and. l == self%break_line
      all_given = ''
      if (allocated(self%given)) all_given = self%given
      c = self
      c%line_count = 0
      c%point_count = 0
      c%points = point_config()
      if (allocated(c%point_ends)) deallocate (c%point_ends)
      c%break_enabled = parts
      c%break_line = 0
      c%model = '3d'
      given = ''
      ! The groups the line case makes again are left out; the rest as given.
      pos = 1
      do
         names = next_word(all_given, pos)
         if (len(names) == 0) exit
         if (made_here(names)) cycle
         given = given//' '//names
      end do
      associate (line => self%lines(l))
         c%segment_count = line%segment_count
         c%segments = segment_config()
         if (line%segment_count > 0) then
            do k = 1, line%segment_count
               j = line%segments(k)
               c%segments(k) = self%segments(j)
               given = given//renamed(group_name('segment_', j), group_name('segment_', k), '')
            end do
            c%length = sum(c%segments(1:line%segment_count)%length)
            ! Nodes given in every segment: the line has their sum less the joints.
            if (all(c%segments(1:line%segment_count)%nodes > 0)) &
               c%nodes = sum(c%segments(1:line%segment_count)%nodes) - (line%segment_count - 1)
         else
            c%length = line%length
            c%nodes = line%nodes
            given = given//' cable%length numerics%nodes'
         end if
         do side = 1, 2
            p = line%end_point(side)
            side_group = merge('end_a', 'end_b', side == 1)
            if (p < 1 .or. p > self%point_count) cycle
            if (.not. self%points(p)%in_network()) cycle
            associate (pt => self%points(p))
               e = self%point_end(p)
               if (trim(pt%kind) == 'free') e = end_config(kind='fixed', x=e%x, y=e%y, z=e%z)
               if (side == 1) then
                  c%end_a = e
               else
                  c%end_b = e
               end if
               given = given//' '//trim(side_group)//'%kind '//trim(side_group)//'%x '//trim(side_group)//'%y '// &
                       trim(side_group)//'%z'
               if (trim(pt%kind) == 'motion') &
                  given = given//renamed(group_name('point_', p), side_group, point_end_variables)
               ! The body of a free point, on the lowest-numbered line that ends there.
               if (trim(pt%kind) == 'free' .and. first_line_at(p) == l .and. &
                   first_side_at(p) == side .and. has_body(p)) then
                  body = point_config(joint=merge(0, max(line%segment_count, 1), side == 1), mass=pt%mass, &
                                      volume=pt%volume, ca=pt%ca, cd=pt%cd, area=pt%area)
                  c%point_count = c%point_count + 1
                  c%points(c%point_count) = body
                  given = given//' '//group_name('point_', c%point_count)//'%joint'// &
                          renamed(group_name('point_', p), group_name('point_', c%point_count), point_body_variables)
               end if
            end associate
         end do
      end associate
      c%given = adjustl(given)

   contains

      !> Whether a 'group%variable' of the file is one of those the line case makes again.
      logical function made_here(word)
         character(*), intent(in) :: word
         integer :: pct
         pct = index(word, '%')
         made_here = starts(word, 'segment_') .or. starts(word, 'point_') .or. starts(word, 'line_') .or. &
                     starts(word, 'end_a%') .or. starts(word, 'end_b%') .or. starts(word, 'static%') .or. &
                     word == 'cable%length' .or. word == 'numerics%nodes'
         ! &rupture: the line that parts keeps what was given of it (its s_break, time, t_break,
         ! criterion), but not which line (a single line has no &rupture line); the others none.
         if (starts(word, 'rupture%')) made_here = .not. parts .or. word == 'rupture%line'
         if (pct == 0) made_here = .true.
      end function made_here

      logical function starts(word, prefix)
         character(*), intent(in) :: word, prefix
         starts = .false.
         if (len(word) >= len(prefix)) starts = word(1:len(prefix)) == prefix
      end function starts

      !> The variables of group from given in the file, as ' to%variable ...' (only those in
      !> the blank-separated list only, unless it is '').
      function renamed(from, to, only) result(text)
         character(*), intent(in) :: from, to, only
         character(:), allocatable :: text, word, name
         integer :: at
         text = ''
         at = 1
         do
            word = next_word(all_given, at)
            if (len(word) == 0) exit
            if (.not. starts(word, trim(from)//'%')) cycle
            name = word(len_trim(from) + 2:)
            if (len(only) > 0) then
               if (index(' '//only//' ', ' '//name//' ') == 0) cycle
            end if
            text = text//' '//trim(to)//'%'//name
         end do
      end function renamed

      !> The lowest-numbered line with an end at point q (0: none), and its first side there.
      integer function first_line_at(q)
         integer, intent(in) :: q
         integer :: m
         first_line_at = 0
         do m = 1, self%line_count
            if (any(self%lines(m)%end_point == q)) then
               first_line_at = m
               return
            end if
         end do
      end function first_line_at

      integer function first_side_at(q)
         integer, intent(in) :: q
         first_side_at = merge(1, 2, self%lines(first_line_at(q))%end_point(1) == q)
      end function first_side_at

      !> Whether a free point has a body: a variable of it given.
      logical function has_body(q)
         integer, intent(in) :: q
         character(:), allocatable :: word
         integer :: at
         has_body = .false.
         at = 1
         do
            word = next_word(point_body_variables, at)
            if (len(word) == 0) exit
            if (self%is_given(group_name('point_', q), word)) has_body = .true.
         end do
      end function has_body
   end function line_case

   !> A numbered group's name: prefix and k ('segment_3').
   pure function group_name(prefix, k) result(name)
      character(*), intent(in) :: prefix
      integer, intent(in) :: k
      character(:), allocatable :: name
      character(len=12) :: buf
      write (buf, '(i0)') k
      name = prefix//trim(buf)
   end function group_name

   !> The next blank-separated word of text from pos ('' at the end); pos moves past it.
   function next_word(text, pos) result(word)
      character(*), intent(in) :: text
      integer, intent(inout) :: pos
      character(:), allocatable :: word
      integer :: first
      do while (pos <= len(text))
         if (text(pos:pos) /= ' ') exit
         pos = pos + 1
      end do
      first = pos
      do while (pos <= len(text))
         if (text(pos:pos) == ' ') exit
         pos = pos + 1
      end do
      word = text(first:pos - 1)
   end function next_word
end module xcable_io_config
