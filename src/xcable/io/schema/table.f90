!> The entries of the namelist schema: build_table, the one place that lists every group and
!> variable of a case file with its type, unit, default, range, words and meaning (the groups
!> &segment_1 ... &segment_8 copied from &cable, &material and &fluid, the network point's
!> variables of &point_1 ... &point_8 from &end_a), and its helpers.
!> (A submodule of io/schema.f90: it fills the table once per process, schema_table keeps it.)
submodule (xcable_io_schema) xcable_io_schema_table
   use xcable_material_factory, only: law_names
   use xcable_ends_registry, only: end_kind, end_kind_list, end_kind_names, kinds_using
   use xcable_io_config, only: point_kinds, point_end_variables
   implicit none

   !> Entries of the table being built that hold an entry (build_table, add).
   integer :: filled = 0

contains

   !> Build the table.
   module subroutine build_table(t)
      !> The table.
      type(schema_entry), allocatable, intent(out) :: t(:)
      character(len=5), parameter :: ends(2) = ['end_a', 'end_b']
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
      ! &point_1 ... &point_8: bodies at the joints and free ends
      call add_points(t)
      ! &line_1 ... &line_8: the lines of a network between points
      call add_lines(t)
      ! &static
      call add(t, 'static', 'tension', 'real', 'N', '315000', &
               "end tension T_s of the paper's symmetric catenary (ends at one height, span from the tension); must "// &
               'exceed w0 L / 2 and need a strain below strain_max; not together with &end_b x or z', 0.0_dp, 1.0e9_dp, &
               lower_open=.true.)
      ! &end_a (s = 0) and &end_b (s = L): the same variables; the kinds from the registry.
      call add_ends(t, ends)
      ! &rupture
      call add(t, 'rupture', 'enabled', 'logical', '-', '.true.', &
               'whether the cable breaks; a case without the &rupture group does not break')
      call add(t, 'rupture', 's_break', 'real', 'm', '-1', &
               'unstretched arc length of the break from end a (in a network, along its &rupture line from that '// &
               "line's end a, at most its length); a break at an end needs that end fixed or moving", &
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
      call add(t, 'rupture', 'line', 'integer', '-', '0', &
               "the line of a network that parts (&line_k, criterion 'time'); only with &line groups; s_break is "// &
               'then measured along that line from its end a', 1.0_dp, real(max_lines, dp), zero_means='not given')
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
               'wall-clock time between checkpoints of a rod run (the file &output file + .ckpt, for xcable '// &
               '--resume); a rod run also writes one when it gets SIGTERM, whatever this says', 0.0_dp, 1.0e7_dp, &
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

   !> The groups &point_1 ... &point_8, all alike: a body (clump weight, buoy) at a joint of two
   !> segments or at an end that is not held; or, with a kind, a point of a network of lines: its
   !> position and a motion point's motion (copies of &end_a's entries of kind 'motion'), and the
   !> body of a free point. The entries of one point are made once, in a scratch part of the table
   !> (with a scratch &end_a to copy from), and appended for each point.
   subroutine add_points(t)
      !> The table; the points appended.
      type(schema_entry), allocatable, intent(inout) :: t(:)
      character(len=5), parameter :: scratch(1) = ['end_a']
      type(schema_entry), allocatable :: proto(:)
      character(len=16) :: group
      integer :: k, i, before, first
      before = filled
      call add_ends(t, scratch, kinds_named=.false.)
      first = filled + 1
      group = ''
      call add(t, group, 'kind', 'string', '-', "''", "a point of a network of lines (&line_k end_a, end_b): "// &
               "'fixed' (held at x, y, z), 'free' (a junction the lines place, with the body of mass, volume, "// &
               "ca, cd and area there) or 'motion' (moved about x, y, z as an end of kind 'motion')", length=16, &
               choices=point_kinds, zero_means='a body on the single line, at joint')
      call add(t, group, 'joint', 'integer', '-', '-1', 'the node the body sits on: k > 0 the end of '// &
               '&segment_k (where &segment_k+1 starts; the last one is end b, and a line without segments has '// &
               'joints 0 and 1), 0 end a; an end only if it is not held (free, force, mass or spring); not for '// &
               'a network point', 0.0_dp, real(max_segments, dp), default_means='must be given without kind')
      call add(t, group, 'mass', 'real', 'kg', '0', 'mass of the body (a clump weight); its weight mass g acts '// &
               "down on the joint (or the free network point; not on a 'fixed' or 'motion' one)", 0.0_dp, 1.0e9_dp)
      call add(t, group, 'volume', 'real', 'm^3', '0', 'volume the body displaces (a buoy): buoyancy &fluid '// &
               'density g volume up, less where the sphere of this volume rises through &fluid surface_z', &
               0.0_dp, 1.0e6_dp)
      call add(t, group, 'ca', 'real', '-', '0', 'added-mass coefficient: ca &fluid density volume more '// &
               'inertia, in every direction', 0.0_dp, 100.0_dp)
      call add(t, group, 'cd', 'real', '-', '0', 'drag coefficient on area: the force 1/2 &fluid density cd '// &
               'area |w| w against the velocity w relative to the current, in every direction', 0.0_dp, 100.0_dp)
      call add(t, group, 'area', 'real', 'm^2', '0', 'projected area of the body for its drag', 0.0_dp, 1.0e6_dp)
      proto = t(first:filled)
      do i = before + 1, first - 1
         if (index(' '//point_end_variables//' ', ' '//trim(t(i)%name)//' ') == 0) cycle
         proto = [proto, t(i)]
         associate (e => proto(size(proto)))
            e%own_kinds_only = .false.
            select case (e%name)
            case ('x', 'y', 'z')
               e%doc = trim(e%name)//" of a network point: where a 'fixed' point is, the mean position of a "// &
                       "'motion' point, the first guess of a 'free' point's position [kind 'fixed', 'free' or 'motion']"
            case default
               e%doc = 'as &end_a '//trim(e%name)//" of kind 'motion', for a network point of kind 'motion'"
            end select
         end associate
      end do
      filled = before
      do k = 1, max_points
         do i = 1, size(proto)
            proto(i)%group = point_group(k)
            call append(t, proto(i))
         end do
      end do
   end subroutine add_points

   !> The groups &line_1 ... &line_8, all alike: the lines of a network between two network
   !> points (&point_k with a kind), each of &segment_k groups or uniform. (Made once, appended
   !> for each line, as the points.)
   subroutine add_lines(t)
      !> The table; the lines appended.
      type(schema_entry), allocatable, intent(inout) :: t(:)
      type(schema_entry), allocatable :: proto(:)
      character(len=16) :: group
      integer :: k, i, before
      before = filled
      group = ''
      call add(t, group, 'end_a', 'string', '-', "''", "the network point at end a of the line, as its "// &
               "group's name ('point_3': a &point_k with kind 'fixed', 'free' or 'motion')", length=16, &
               default_means='must be given')
      call add(t, group, 'end_b', 'string', '-', "''", "the network point at end b, as end_a; another point "// &
               'than end_a', length=16, default_means='must be given')
      call add(t, group, 'segments', 'integer', '-', '', 'the &segment_k groups the line is made of, from its '// &
               'end a (a group may serve several lines: three like lines all say segments = 1, 2)', 1.0_dp, &
               real(max_segments, dp), count=max_segments, default_means='a uniform line of &cable and &material')
      call add(t, group, 'length', 'real', 'm', '0', "unstretched length of the line; with segments, their "// &
               'sum (given, it must be it)', 1.0e-2_dp, 1.0e5_dp, default_means='&cable length if given')
      call add(t, group, 'nodes', 'integer', '-', '0', 'nodes of a line without segments (with segments, each '// &
               'has its nodes or a share of &numerics nodes)', 3.0_dp, 100001.0_dp, default_means='&numerics nodes')
      proto = t(before + 1:filled)
      filled = before
      do k = 1, max_lines
         do i = 1, size(proto)
            proto(i)%group = line_group(k)
            call append(t, proto(i))
         end do
      end do
   end subroutine add_lines

   !> The groups of the ends given (&end_a and &end_b; add_points takes a copy of &end_a's to
   !> pick a network point's variables from): the same variables, the kinds from the registry.
   subroutine add_ends(t, ends, kinds_named)
      !> The table; the ends appended.
      type(schema_entry), allocatable, intent(inout) :: t(:)
      !> The groups.
      character(len=*), intent(in) :: ends(:)
      !> Whether each variable's meaning ends with the kinds that use it (default .true.; the
      !> scratch copy add_points takes has meanings of its own).
      logical, intent(in), optional :: kinds_named
      type(end_kind), allocatable :: kinds(:)
      character(:), allocatable :: kind_doc
      integer :: k
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
      if (present(kinds_named)) then
         if (.not. kinds_named) return
      end if
      do k = 1, filled
         if (.not. any(t(k)%group == ends) .or. t(k)%name == 'kind') cycle
         t(k)%doc = trim(t(k)%doc)//' [kind '//words_or(kinds_using(t(k)%name))//']'
      end do
   end subroutine add_ends

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
end submodule xcable_io_schema_table
