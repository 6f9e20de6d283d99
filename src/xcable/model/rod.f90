!> The energy-conserving discrete rod: the default discretisation of the
!> planar cable (docs/ARCHITECTURE.md, docs/theory/numerics.md).
!>
!> The continuum is the paper's (extensible, shear-rigid, bending stiffness
!> EI, T = f(eps), moment M = EI Omega with Omega the curvature per unstretched
!> length, so that the moment balance reads EI Omega' + (1 + eps) Sn = 0). It
!> is discretised on a staggered grid: the unknowns are the node positions R_k
!> (x horizontal, z up); each cell c between nodes c and c+1 carries the
!> stretch vector e_c = (R_c+1 - R_c) / ds_c, its strain eps_c = |e_c| - 1 and
!> its tension f(eps_c); each interior node carries the turning angle theta_k
!> between its two cells and the moment M_k = EI theta_k / h_k, h_k the mean of
!> the two cell lengths. The stored energy is
!>
!>     U = sum_c ds_c W(eps_c) + sum_k EI theta_k^2 / (2 h_k) + sum_k w_k z_k,
!>
!> W the strain energy of the law per unstretched length and w_k the weight of
!> node k (its share of the cable and any point mass). The kinetic energy is
!> 1/2 V^T M V with M = (1 - mu) M_lumped + mu M_averaged: M_lumped puts m ds/2
!> at each end of a cell, M_averaged gives each cell the kinetic energy of its
!> mean velocity, m ds |V_c + V_c+1|^2 / 8. With mu = 1 ('averaged', the
!> default) the linear axial waves of the scheme are those of the paper's box
!> scheme, exact at Courant number 1.
!>
!> Time stepping, from (R^n, V^n) to (R^n+1, V^n+1):
!>
!>     R^n+1 - R^n = dt [(1 - theta) V^n + theta V^n+1]
!>     M (V^n+1 - V^n) / dt = -grad U(R^n, R^n+1) + F_ext,
!>
!> where grad U(R^n, R^n+1) is a discrete gradient: it satisfies
!> grad U . (R^n+1 - R^n) = U(R^n+1) - U(R^n) exactly. With theta = 1/2 the
!> energy changes by exactly the work of the ends and loads (to the Newton
!> tolerance), in every regime, taut, slack, compressed or buckled; theta >
!> 1/2 removes (theta - 1/2) (V^n+1 - V^n)^T M (V^n+1 - V^n) per step, which
!> the energy ledger books as numerical dissipation. The discrete gradient of
!> a cell: the strain part q (e^n + e^n+1) / (|e^n| + |e^n+1|) with q the
!> divided difference of W between the two strains, and the bending part
!> S_c G_c / ds_c with S_c the difference of the time-averaged moments at the
!> two nodes of the cell and G_c = perp(e_mid) dphi / (sin(dphi) |e^n| |e^n+1|),
!> dphi the rotation of the cell in the step; G_c . (e^n+1 - e^n) = dphi exactly.
!>
!> The unknowns of Newton's method are the new positions, two per node, node
!> after node; the momentum balance of node k involves nodes k-2 .. k+2, so
!> the Jacobian has kl = ku = 5. A held end's rows are R = X(t).
!>
!> This file holds the piece's types, its geometry, memo and energies, and the time step with
!> its helpers: the hot path, whose small helpers gfortran 12 inlines and specialises only as
!> private procedures of this unit (a submodule's procedures and public ones are global symbols,
!> which fpm's -fPIC keeps whole; docs/dev/model-interface.md). The piece-free kernels are
!> modules: model/rod_kernels.f90 (cells, node rows, the band Jacobian) and model/rod/bending.f90
!> (the bending energy and its divided differences, its helpers private there). The submodules
!> in model/rod/ hold the parts called once per evaluation or colder: assembly.f90 (the node
!> rows), equilibrium.f90 (the static system), loads.f90 (distributed loads), window.f90 (a step
!> on a window of nodes), accepted.f90 (the accepted state of a step), checks.f90 (Newton's
!> trust in its estimate), init.f90 (the set-up) and records.f90 (the reaction, the cell fields).
module xcable_model_rod
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, stat_numerics
   use xcable_core_strings, only: str
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_cell_force, damped_tension
   use xcable_numerics_atan2, only: fast_atan2, fast_atan2_array
   use xcable_numerics_tan, only: fast_tan, fast_tan_array
   use xcable_solver_banded, only: band_matrix
   use xcable_ends_end_condition, only: end_condition
   use xcable_solver_newton, only: newton_problem
   use xcable_loads_load, only: load_slot, cell_kinematics, any_skew
   use xcable_loads_point, only: point_body
   use xcable_model_rod_kernels, only: perp, cross2, outer, identity2, geometry_of, turning_angles, &
                                       cell_rotations_of, geometry_cells, add_jacobian, cell_terms, &
                                       moment_gradient_of, node_residuals, small_strain_step, small_rotation
   use xcable_model_rod_bending, only: bending_energy, bending_moment, bending_stiffness, bend_arguments, bend_divided_array
   implicit none
   private
   public :: rod_piece, rod_section, rod_problem, rod_kl, rod_ku, perp, cross2, rod_unknown_names, rod_nodal
   public :: bend_energy, bend_moment, bend_curvature, cell_rotations
   ! Public for their tests: cell_terms (suite_rod, cell_terms_blocks_same_bits), add_jacobian
   ! (suite_quiescent, jacobian_gathered_as_cell_by_cell), bend_nodes and small_rotation
   ! (suite_rod, bend_terms_in_pairs_same_bits). bend_nodes' kernels stay private, inlined
   ! into it (public, they cost 0.9e6 instructions on fast_180kN).
   public :: cell_terms, add_jacobian, bend_nodes, small_rotation, small_strain_step
   public :: collapsed_length
   ! For the submodules in model/rod/: the wrappers at the end, and helpers that are calls here
   ! too (not inlined into the step: public costs them nothing).
   public :: rod_node_weight, rod_old_energies, geometry_flat, cell_couple, windowed, point3, bend_stiffness
   public :: section_cell_terms, copy_values, copy_geometry

   !> A cell shorter than this fraction of its unstretched length has collapsed: the step
   !> control rejects such a state (driver/rod_run/step.f90 check_range), the statics refuse it.
   real(dp), parameter :: collapsed_length = 0.05_dp

   !> The unknowns of a node, in their order in Newton's vector (node after node).
   character(len=*), parameter :: rod_unknown_names(2) = [character(len=1) :: 'x', 'z']
   !> Unknowns per node.
   integer, parameter :: rod_nodal = size(rod_unknown_names)
   !> Nodes on either side whose unknowns enter a node's rows: the turning angles
   !> of nodes k-1, k, k+1 reach nodes k-2 .. k+2.
   integer, parameter :: rod_reach = 2
   !> Band widths of the Jacobian, from the layout.
   integer, parameter :: rod_kl = rod_nodal*(rod_reach + 1) - 1, rod_ku = rod_kl

   !> One section of a piece on a line of segments: its cells (piece-local) and its material.
   type :: rod_section
      !> First and last cell.
      integer :: first = 1, last = 0
      !> Tension-strain law.
      class(material_law), allocatable :: law
      !> Mass and weight per unstretched length, kg/m and N/m; EI, N m^2; damping c, N s.
      real(dp) :: mass = 0, weight = 0, ei = 0, damping = 0
   end type rod_section

   !> One piece of cable between two ends: grid, material and work arrays.
   type :: rod_piece
      !> Number of nodes.
      integer :: n = 0
      !> Unstretched arc length of the nodes from end a of the whole cable, m.
      real(dp), allocatable :: s(:)
      !> Cell lengths (n - 1), m.
      real(dp), allocatable :: ds(:)
      !> Length attributed to each node: half of each adjacent cell, m.
      real(dp), allocatable :: lumped(:)
      !> h_k = mean length of the two cells at an interior node (0 at the ends), m.
      real(dp), allocatable :: dual(:)
      !> Mass and weight per unstretched length, kg/m and N/m; bending stiffness EI, N m^2; gravity, m/s^2.
      real(dp) :: mass_per_length = 0, weight = 0, ei = 0, gravity = 0, mu2 = 0
      !> Internal (Kelvin-Voigt) damping c of T = f(eps) + c d(eps)/dt, N s (for a rope that cannot
      !> push on the taut part only, and never pushing: slack_cell_force).
      real(dp) :: damping = 0
      !> Share of the averaged mass matrix (1: averaged, 0: lumped).
      real(dp) :: mu = 1
      !> Tension-strain law.
      class(material_law), allocatable :: law
      !> Ends at node 1 and node n.
      class(end_condition), allocatable :: end_a, end_b
      !> Row scale of the momentum rows (a reference tension, N) and the position scale (m).
      real(dp) :: tension_ref = 1, length_ref = 1
      ! Work arrays, allocated once by init.
      !> Old level: positions, velocities, M V, cell vectors, lengths, turning angles.
      real(dp), allocatable :: r0(:, :), v0(:, :), mv0(:, :), e0(:, :), l0(:), th0(:)
      !> Old level's bending energy of each node, J: the fixed end of the divided differences,
      !> evaluated once per step by prepare_step instead of at every Newton iteration. (The
      !> strain part needs no W(eps0): the law gives W(eps1) - W(eps0) itself; W is computed
      !> only for the energy ledger, by rod_energies.)
      real(dp), allocatable :: b0(:)
      !> The last step evaluation's positions x, its geometry, and the bending energies it
      !> computed (memo_b_ok: where it computed them): prepare_step takes the old level from
      !> here when r0 is x bit for bit (the accepted state, whose geometry and energies would
      !> otherwise be computed again; rod_geometry and rod_energies, the ledger's, take them too).
      real(dp), allocatable :: memo_x(:), memo_e(:, :), memo_l(:), memo_th(:), memo_b(:)
      logical, allocatable :: memo_b_ok(:)
      !> The cells' rotations from the old level that the last step evaluation computed.
      real(dp), allocatable :: memo_dphi(:)
      logical :: memo_valid = .false.
      !> New level: cell vectors, lengths, turning angles, cell forces; work (2, n).
      real(dp), allocatable :: e1(:, :), l1(:), th1(:), force(:, :), force_node(:, :)
      !> Cell quantities of the Jacobian: 2x2 blocks dN_c/de_c' for c' = c-1, c, c+1.
      real(dp), allocatable :: block(:, :, :, :)
      !> Work of add_jacobian: the blocks over ds_c' and times the row scale (gather_rows).
      real(dp), allocatable :: block_scaled(:, :, :, :)
      !> Work of add_jacobian: the mass terms times the rate and the row scale (gather_rows).
      real(dp), allocatable :: mass_scaled(:, :, :, :)
      !> Per node in the last evaluation: the moment (statics: dB/dtheta; a step: the divided
      !> difference of B between the two levels), N m, and its derivative with respect to the
      !> new turning angle, N m.
      real(dp), allocatable :: mom(:), dmom(:)
      !> Mass matrix, symmetric with two off-diagonals: mass(j, k) = M(k, k+j), kg.
      real(dp), allocatable :: mass(:, :)
      !> Velocities of the last evaluated new level (2, n), m/s.
      real(dp), allocatable :: v1(:, :)
      !> Distributed loads (fluid, ...): none when not allocated or empty.
      type(load_slot), allocatable :: loads(:)
      !> Force of the loads on each node in the last evaluation (2, n), N, and the
      !> derivatives of each cell's load force with respect to the new positions of
      !> its two nodes (2, 2, 0:1, n - 1): side 0 node c, side 1 node c + 1.
      real(dp), allocatable :: load_node(:, :), load_block(:, :, :, :)
      !> Of loads that share unequally (cable_load cell_skew): whether there is one, and the
      !> derivatives of each cell's unequal part G_c = ds g (node c takes +G_c, node c + 1 -G_c).
      logical :: skewed = .false.
      real(dp), allocatable :: skew_block(:, :, :, :)
      !> Factor on the distributed loads (1; the statics ramps it up when it must).
      real(dp) :: load_factor = 1
      !> A line of segments (set_sections; not allocated: one uniform material, the scalars
      !> mass_per_length, weight, ei, damping and law above, which then are the first
      !> section's): the sections, the section of each cell, and per node its weight (N) and
      !> EI (N m^2: the mean of its two cells' weighted by their lengths).
      type(rod_section), allocatable :: sections(:)
      integer, allocatable :: cell_sec(:)
      real(dp), allocatable :: node_w(:), node_ei(:)
      !> Bodies at nodes (clump weights, buoys: set_points; not allocated: none), the node of
      !> each, and the derivative (x, z) of each one's drag in the last evaluation, N/m.
      type(point_body), allocatable :: points(:)
      integer, allocatable :: point_node(:)
      real(dp), allocatable :: point_jac(:, :, :)
   contains
      !> A line of segments: the sections' cells and materials.
      procedure :: set_sections => rod_set_sections
      !> Bodies at the joints (after set_sections).
      procedure :: set_points => rod_set_points
      !> The tension of cell c at a strain, N.
      procedure :: cell_tension => rod_cell_tension
      !> Whether the law of any cell has a kink (a rope that cannot push).
      procedure :: has_kink => rod_has_kink
      !> Set up grid, material and work arrays.
      procedure :: init => rod_init
      !> Number of unknowns.
      procedure :: unknowns => rod_unknowns
      !> Cell vectors, lengths and turning angles of positions R.
      procedure :: geometry => rod_geometry
      !> Strain, kinetic, bending and gravity energy, J.
      procedure :: energies => rod_energies
      !> The strain and bending energies of the last step evaluation where it skipped them.
      procedure :: complete_memo => rod_complete_memo
      !> M V.
      procedure :: mass_times => rod_mass_times
      !> Residual and Jacobian of the static equilibrium at time t.
      procedure :: static_system => rod_static_system
      !> Store the old level of a time step.
      procedure :: prepare_step => rod_prepare_step
      !> Before a step on a window: the new level and the memo are the old level's (nodes held there).
      procedure :: freeze_level => rod_freeze_level
      !> Residual and Jacobian of a time step.
      procedure :: step_system => rod_step_system
      !> New velocities from new positions.
      procedure :: new_velocity => rod_new_velocity
      !> Tension, strain and shear of each cell and the moment of each node.
      procedure :: cell_fields => rod_cell_fields
      !> The external force a held end node needs (its reaction), after an evaluation at the state.
      procedure :: reaction => rod_reaction
   end type rod_piece

   !> The nonlinear system Newton solves for one piece: the static equilibrium
   !> at time t0, or the step from t0 to t0 + dt.
   type, extends(newton_problem) :: rod_problem
      !> The piece (its old level set by prepare_step for a step).
      type(rod_piece) :: piece
      !> Time step (0: statics), old time, time weight.
      real(dp) :: dt = 0, t0 = 0, theta = 0.5_dp
      !> Window of a step (skip of the quiescent cable, rod_run): the unknowns are those of
      !> nodes lo .. hi, the other nodes are held at the old level (set by freeze_level);
      !> hi = 0: the whole piece.
      integer :: lo = 1, hi = 0
   contains
      procedure :: evaluate => rod_problem_evaluate
      !> Newton's contraction estimate only where no cell can have crossed the kink.
      procedure :: estimate_trusted => rod_problem_estimate_trusted
      !> After a converged step solve at x: what the accepted state needs, instead of a full
      !> residual (step_state).
      procedure :: accepted_state => rod_problem_accepted_state
   end type rod_problem

   ! Procedures of the submodules in model/rod/ (see the file head).
   interface
      !> Set up a piece on the node arc lengths s.
      module subroutine rod_init(self, s, mass, weight, ei, gravity, mu, law, end_a, end_b, tension_ref, mu2, damping)
         !> Piece.
         class(rod_piece), intent(inout) :: self
         !> Node arc lengths, increasing, m.
         real(dp), intent(in) :: s(:)
         !> Mass (kg/m) and weight (N/m) per unstretched length, EI (N m^2), gravity (m/s^2).
         real(dp), intent(in) :: mass, weight, ei, gravity
         !> Share of the averaged mass matrix, 0 to 1.
         real(dp), intent(in) :: mu
         !> Tension-strain law.
         class(material_law), intent(in) :: law
         !> Ends at s(1) and s(n).
         class(end_condition), intent(in) :: end_a, end_b
         !> Reference tension of the row scaling, N.
         real(dp), intent(in) :: tension_ref
         !> Weight of the second-difference kinetic energy (0 if absent).
         real(dp), intent(in), optional :: mu2
         !> Kelvin-Voigt damping c, N s (0 if absent).
         real(dp), intent(in), optional :: damping
      end subroutine rod_init

      !> A line of segments: section j holds the cells last(j - 1) + 1 .. last(j) with its law,
      !> mass (kg/m), weight (N/m), EI (N m^2) and damping (N s). The piece keeps the grid and
      !> ends of init; the mass matrix is rebuilt, the scalars become the first section's.
      module subroutine rod_set_sections(self, last, laws, mass, weight, ei, damping)
         !> Piece.
         class(rod_piece), intent(inout) :: self
         !> Last cell of each section (the last one n - 1).
         integer, intent(in) :: last(:)
         !> The sections' laws.
         type(rod_section), intent(in) :: laws(:)
         !> Per section: mass and weight per length, EI, damping.
         real(dp), intent(in) :: mass(:), weight(:), ei(:), damping(:)
      end subroutine rod_set_sections

      !> Bodies at nodes (after set_sections): each on the node at its arc length, if the piece
      !> has one there; its inertia in the mass matrix, its weight in the node's, its drag a load.
      module subroutine rod_set_points(self, points)
         !> Piece.
         class(rod_piece), intent(inout) :: self
         !> The line's bodies.
         type(point_body), intent(in) :: points(:)
      end subroutine rod_set_points

      !> The force the support exerts on end node k (1 or n) to keep the balance of
      !> that node: for statics (dt = 0) -(N_k - N_k-1) + w_k e_z - F_k, for a step
      !> also plus the node's inertia [M (V^n+1 - V^n)]_k / dt. Uses the cell forces
      !> of the last evaluation (at the converged state: a residual, or for a step
      !> rod_problem%accepted_state, which computes the end cells' forces and the end
      !> nodes' velocities this needs), so call it right after.
      module function rod_reaction(self, k, x, dt, theta) result(f)
         !> Piece.
         class(rod_piece), intent(in) :: self
         !> End node, 1 or n.
         integer, intent(in) :: k
         !> Positions at which the piece was last evaluated, 2 per node.
         real(dp), intent(in) :: x(:)
         !> Step (0: statics) and time weight.
         real(dp), intent(in) :: dt, theta
         real(dp) :: f(2)
      end function rod_reaction

      !> Tension, strain and shear force of each cell and the moment of each node of positions R.
      module subroutine rod_cell_fields(self, r, tension, strain, shear, moment_node, v)
         !> Piece.
         class(rod_piece), intent(inout) :: self
         !> Positions (2, n).
         real(dp), intent(in) :: r(:, :)
         !> Velocities (2, n): with them the tension includes the damping c d(eps)/dt.
         real(dp), intent(in), optional :: v(:, :)
         !> Tension (N; with the damping when v is given), strain, shear force (N; along the normal n of the
         !> paper, -perp(t)) per cell (n - 1).
         real(dp), intent(out) :: tension(:), strain(:), shear(:)
         !> Moment per node, dB/dtheta, N m (0 at the ends).
         real(dp), intent(out) :: moment_node(:)
      end subroutine rod_cell_fields
      !> Residual (and Jacobian) of the static equilibrium at time t: for a loaded
      !> node, [-(N_k - N_k-1) + w_k e_z - F_k(t)] / T_ref with N_c the exact
      !> gradient of U per cell; for a held node (R_k - X(t)) / ds_ref. (model/rod/equilibrium.f90)
      module subroutine rod_static_system(self, x, t, residual, jacobian, with_jacobian)
         !> Piece.
         class(rod_piece), intent(inout) :: self
         !> Positions, 2 per node.
         real(dp), intent(in) :: x(:)
         !> Time of the loads and held positions, s.
         real(dp), intent(in) :: t
         !> Scaled residual.
         real(dp), intent(out) :: residual(:)
         !> Jacobian (band storage).
         type(band_matrix), intent(inout) :: jacobian
         !> Whether to form the Jacobian.
         logical, intent(in) :: with_jacobian
      end subroutine rod_static_system

      !> Node residuals and the Jacobian from the cell forces and blocks (statics:
      !> t1 is the time; dynamics: t1 = t0, t2 = dt). (model/rod/assembly.f90)
      module subroutine assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
         class(rod_piece), intent(inout) :: self
         real(dp), intent(in) :: x(:)
         real(dp), intent(in) :: t1, t2
         real(dp), intent(out) :: residual(:)
         type(band_matrix), intent(inout) :: jacobian
         logical, intent(in) :: with_jacobian, dynamic
         real(dp), intent(in), optional :: theta
      end subroutine assemble

      !> assemble (dynamic) on the rows and columns of the nodes lo .. hi, from the cell
      !> forces and blocks step_window computed. (model/rod/assembly.f90)
      module subroutine assemble_window(self, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)
         type(rod_piece), intent(inout) :: self
         integer, intent(in) :: lo, hi
         real(dp), intent(in) :: t0, dt, theta
         real(dp), intent(out) :: residual(:)
         type(band_matrix), intent(inout) :: jacobian
         logical, intent(in) :: with_jacobian
      end subroutine assemble_window

      !> The distributed loads at the positions x: load_node and, when asked, load_block.
      !> (model/rod/loads.f90)
      module subroutine apply_loads(self, x, dt, theta, with_jacobian)
         class(rod_piece), intent(inout) :: self
         real(dp), intent(in) :: x(:)
         real(dp), intent(in) :: dt, theta
         logical, intent(in) :: with_jacobian
      end subroutine apply_loads

      !> Newton's contraction estimate after the update from the last evaluated point: trusted
      !> unless it may have carried a cell past the kink of the law. (model/rod/checks.f90)
      module function rod_problem_estimate_trusted(self, update, tolerance) result(trusted)
         !> Problem.
         class(rod_problem), intent(in) :: self
         !> The update, 2 per node of the window (all nodes when there is none), m.
         real(dp), intent(in) :: update(:)
         !> Tolerance on the scaled update (scale: length_ref).
         real(dp), intent(in) :: tolerance
         logical :: trusted
      end function rod_problem_estimate_trusted

      !> Whether the law of any cell has a kink (strain_slack: a rope that cannot push).
      !> (model/rod/checks.f90)
      module pure function rod_has_kink(self) result(kink)
         !> Piece.
         class(rod_piece), intent(in) :: self
         logical :: kink
      end function rod_has_kink
      !> rod_step_system on the window of nodes lo .. hi (2 < hi - lo + 1 < n; no distributed
      !> loads); the other nodes stay at the old level (rod_freeze_level). (model/rod/window.f90)
      module subroutine step_window(self, x, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)
         type(rod_piece), intent(inout) :: self
         real(dp), intent(in) :: x(:)
         integer, intent(in) :: lo, hi
         real(dp), intent(in) :: t0, dt, theta
         real(dp), intent(out) :: residual(:)
         type(band_matrix), intent(inout) :: jacobian
         logical, intent(in) :: with_jacobian
      end subroutine step_window

      !> The evaluation of a step at its converged positions x (the window's unknowns when the
      !> problem has a window), in place of the full residual. (model/rod/accepted.f90)
      module subroutine rod_problem_accepted_state(self, x)
         !> Problem (a step: dt > 0).
         class(rod_problem), intent(inout) :: self
         !> Positions, 2 per node of the window (all nodes when there is none).
         real(dp), intent(in) :: x(:)
      end subroutine rod_problem_accepted_state
      !> Before a step on a window: the new level's geometry and the memo of the last evaluation
      !> are set to the old level's (what the nodes outside the window keep). (model/rod/window.f90)
      module subroutine rod_freeze_level(self)
         class(rod_piece), intent(inout) :: self
      end subroutine rod_freeze_level
   end interface

contains

   !> Residual and Jacobian (newton_problem interface).
   subroutine rod_problem_evaluate(self, x, residual, jacobian, with_jacobian)
      !> Problem.
      class(rod_problem), intent(inout) :: self
      !> Positions, 2 per node.
      real(dp), intent(in) :: x(:)
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian in band storage.
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form it.
      logical, intent(in) :: with_jacobian
      if (windowed(self)) then
         call step_window(self%piece, x, self%lo, self%hi, self%t0, self%dt, self%theta, residual, jacobian, &
                          with_jacobian)
      else if (self%dt > 0) then
         call self%piece%step_system(x, self%t0, self%dt, self%theta, residual, jacobian, with_jacobian)
      else
         call self%piece%static_system(x, self%t0, residual, jacobian, with_jacobian)
      end if
   end subroutine rod_problem_evaluate

   !> Whether the problem is a step on a window of the piece's nodes (lo .. hi, not all of them).
   pure logical function windowed(self)
      class(rod_problem), intent(in) :: self
      windowed = self%dt > 0 .and. self%hi > 0 .and. (self%lo > 1 .or. self%hi < self%piece%n)
   end function windowed

   !> Number of unknowns (two per node).
   pure integer function rod_unknowns(self)
      !> Piece.
      class(rod_piece), intent(in) :: self
      rod_unknowns = rod_nodal*self%n
   end function rod_unknowns

   !> Cell vectors e_c, their lengths and the turning angles at the interior nodes.
   pure subroutine rod_geometry(self, r, e, l, th)
      !> Piece.
      class(rod_piece), intent(in) :: self
      !> Positions (2, n), m.
      real(dp), intent(in) :: r(:, :)
      !> Cell vectors (2, n - 1), lengths (n - 1) and turning angles (n; 0 at the ends), rad.
      real(dp), intent(out) :: e(:, :), l(:), th(:)
      ! The positions of the last step evaluation (the accepted state): its geometry, the same bits.
      if (is_memo(self, r)) then
         call copy_geometry(self%n, self%memo_e, self%memo_l, self%memo_th, e, l, th)
      else
         call geometry_of(self%n, self%ds, r, e, l, th)
      end if
   end subroutine rod_geometry

   !> rod_geometry of the positions as Newton's vector x (2 n, node after node), read in place:
   !> reshape(x, [2, n]) made a copy on the heap at every evaluation (the copy and its
   !> allocation 0.123e9 of lean fast_180kN's 6.28e9 instructions on 961 nodes, callgrind).
   pure subroutine geometry_flat(self, x, e, l, th)
      class(rod_piece), intent(in) :: self
      real(dp), intent(in) :: x(2, self%n)
      real(dp), intent(out) :: e(:, :), l(:), th(:)
      call rod_geometry(self, x, e, l, th)
   end subroutine geometry_flat

   !> Weight of node k (cable share and point mass), N. (An interior node's is
   !> weight lumped(k): the loops over the nodes write that out and call this for
   !> the end nodes only; gfortran did not inline it, 2.9e5 calls on fast_180kN.)
   pure real(dp) function node_weight(self, k)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      if (allocated(self%node_w)) then
         node_weight = self%node_w(k)
      else
         node_weight = self%weight*self%lumped(k)
      end if
      if (k == 1) node_weight = node_weight + self%gravity*self%end_a%point_mass()
      if (k == self%n) node_weight = node_weight + self%gravity*self%end_b%point_mass()
   end function node_weight

   !> M V for velocities V (2, n).
   pure subroutine rod_mass_times(self, v, mv)
      !> Piece.
      class(rod_piece), intent(in) :: self
      !> Velocities (2, n), m/s.
      real(dp), intent(in) :: v(:, :)
      !> M V (2, n), kg m/s.
      real(dp), intent(out) :: mv(:, :)
      call mass_product(self%n, self%mass, v, mv)
   end subroutine rod_mass_times

   !> Fill in the bending energies that the last step evaluation did not compute (memo_b of
   !> the nodes it took by the Taylor form): the same values that rod_energies and the next
   !> prepare_step's old_energies would each compute (it saves computing them twice per step
   !> when the ledger is kept).
   subroutine rod_complete_memo(self)
      class(rod_piece), intent(inout) :: self
      integer :: k
      if (.not. self%memo_valid) return
      do k = 2, self%n - 1
         if (self%memo_b_ok(k)) cycle
         self%memo_b(k) = bend_energy(self, k, self%memo_th(k))
         self%memo_b_ok(k) = .true.
      end do
   end subroutine rod_complete_memo

   !> Energies of a state: strain, kinetic, bending, gravity (J), from the
   !> geometry e, l, th of R (as rod_geometry gives it).
   pure function rod_energies(self, r, v, l, th) result(en)
      !> Piece.
      class(rod_piece), intent(in) :: self
      !> Positions and velocities (2, n).
      real(dp), intent(in) :: r(:, :), v(:, :)
      !> Cell lengths (n - 1) and turning angles (n) of r.
      real(dp), intent(in) :: l(:), th(:)
      real(dp) :: en(4)
      integer :: k, c
      logical :: memo
      ! At the last step evaluation's positions, the bending energies it computed (the same
      ! bits). The strain energies are computed here only: a step needs none (its strain
      ! force is the law's W(eps1) - W(eps0), strain_energy_change).
      memo = is_memo(self, r)
      en = 0
      if (allocated(self%sections)) then
         do c = 1, self%n - 1
            en(1) = en(1) + self%ds(c)*self%sections(self%cell_sec(c))%law%strain_energy(l(c) - 1)
         end do
      else
         do c = 1, self%n - 1
            en(1) = en(1) + self%ds(c)*self%law%strain_energy(l(c) - 1)
         end do
      end if
      ! The energy stored in state-dependent ends (springs) goes with the strain energy.
      if (self%end_a%state_dependent()) en(1) = en(1) + self%end_a%stored_energy(point3(r(:, 1)))
      if (self%end_b%state_dependent()) en(1) = en(1) + self%end_b%stored_energy(point3(r(:, self%n)))
      en(2) = kinetic_energy(self%n, self%mass, v)
      do k = 1, self%n
         ! node_weight's value, without its call for the inner nodes.
         if (k == 1 .or. k == self%n .or. allocated(self%node_w)) then
            en(4) = en(4) + node_weight(self, k)*r(2, k)
         else
            en(4) = en(4) + (self%weight*self%lumped(k))*r(2, k)
         end if
      end do
      do k = 2, self%n - 1
         if (memo) then
            if (self%memo_b_ok(k) .and. same_bits(th(k), self%memo_th(k))) then
               en(3) = en(3) + self%memo_b(k)
               cycle
            end if
         end if
         en(3) = en(3) + bend_energy(self, k, th(k))
      end do
   end function rod_energies

   !> 1/2 V^T M V summed as rod_energies did on the components: the diagonal, then
   !> the first and the second off-diagonal, node by node (the same bits), on
   !> explicit-shape arrays (with the inner nodes' weights without node_weight's call,
   !> rod_energies took 15.2e6 instructions on fast_180kN instead of 30.1e6).
   pure real(dp) function kinetic_energy(n, mass, v) result(e)
      !> Nodes.
      integer, intent(in) :: n
      !> The mass matrix's diagonals (0:2, n).
      real(dp), intent(in) :: mass(0:2, n)
      !> Velocities (2, n).
      real(dp), intent(in) :: v(2, n)
      integer :: k
      e = 0
      do k = 1, n
         e = e + 0.5_dp*mass(0, k)*dot_product(v(:, k), v(:, k))
      end do
      do k = 1, n - 1
         e = e + mass(1, k)*dot_product(v(:, k), v(:, k + 1))
      end do
      do k = 1, n - 2
         e = e + mass(2, k)*dot_product(v(:, k), v(:, k + 2))
      end do
   end function kinetic_energy

   !> Store the old level (positions and velocities) of a step.
   subroutine rod_prepare_step(self, r0, v0)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      !> Positions and velocities at the old level (2, n).
      real(dp), intent(in) :: r0(:, :), v0(:, :)
      ! Copied as 2 n values: the array assignment from an assumed shape called memcpy for
      ! each node (286 526 calls on fast_180kN, 0.8 % of its instructions with this routine's).
      call copy_values(2*self%n, r0, self%r0)
      call copy_values(2*self%n, v0, self%v0)
      call self%mass_times(v0, self%mv0)
      if (is_memo(self, r0)) then
         call copy_geometry(self%n, self%memo_e, self%memo_l, self%memo_th, self%e0, self%l0, self%th0)
         call old_energies(self, self%memo_b, self%memo_b_ok)
      else
         call self%geometry(r0, self%e0, self%l0, self%th0)
         call old_energies(self)
      end if
   end subroutine rod_prepare_step

   !> Rotation of each cell from the old level e0 to the new e1, atan2(e0 x e1, e0 . e1), rad,
   !> with e1 that of the new positions r: the last step evaluation's values when r is its
   !> positions bit for bit (it saves 1.4 % of fast_180kN in rod_run's check_state).
   subroutine cell_rotations(self, r, dphi)
      class(rod_piece), intent(in) :: self
      real(dp), intent(in) :: r(:, :)
      real(dp), intent(out) :: dphi(:)
      integer :: c
      if (is_memo(self, r)) then
         dphi = self%memo_dphi
      else
         do c = 1, self%n - 1
            dphi(c) = fast_atan2(self%e0(1, c)*self%e1(2, c) - self%e0(2, c)*self%e1(1, c), &
                                 dot_product(self%e0(:, c), self%e1(:, c)))
         end do
      end if
   end subroutine cell_rotations

   !> Whether positions r are those of the last step evaluation, bit for bit.
   pure logical function is_memo(self, r)
      class(rod_piece), intent(in) :: self
      real(dp), intent(in) :: r(:, :)
      integer :: i, k
      is_memo = .false.
      if (.not. self%memo_valid) return
      if (size(r, 1) /= 2 .or. size(r) /= size(self%memo_x)) return
      do k = 1, size(r, 2)
         do i = 1, 2
            if (.not. same_bits(r(i, k), self%memo_x(2*k - 2 + i))) return
         end do
      end do
      is_memo = .true.
   end function is_memo

   !> b0 from the old level's turning angles, or where given (b_ok) from b, the same
   !> values computed by the last evaluation.
   subroutine old_energies(self, b, b_ok)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in), optional :: b(:)
      logical, intent(in), optional :: b_ok(:)
      integer :: k
      do k = 1, self%n
         if (present(b)) then
            if (b_ok(k)) then
               self%b0(k) = b(k)
               cycle
            end if
         end if
         self%b0(k) = bend_energy(self, k, self%th0(k))
      end do
   end subroutine old_energies

   !> New velocities from the new positions: V^n+1 = [(R^n+1 - R^n)/dt - (1 - theta) V^n] / theta.
   pure subroutine rod_new_velocity(self, r1, dt, theta, v1)
      !> Piece (holds the old level).
      class(rod_piece), intent(in) :: self
      !> New positions (2, n), m.
      real(dp), intent(in) :: r1(:, :)
      !> Step (s) and time weight.
      real(dp), intent(in) :: dt, theta
      !> New velocities (2, n), m/s.
      real(dp), intent(out) :: v1(:, :)
      call new_velocity_of(2*self%n, r1, self%r0, self%v0, dt, theta, v1)
   end subroutine rod_new_velocity

   !> Residual and Jacobian of the step from t0 to t0 + dt with the old level
   !> stored by prepare_step: for a loaded node k,
   !> [(M V^n+1)_k - (M V^n)_k] / dt - (N_k - N_k-1) + w_k e_z - F_k(mid), over T_ref,
   !> with N_c the discrete gradient per cell; for a held node (R_k - X(t0 + dt)) / ds_ref.
   subroutine rod_step_system(self, x, t0, dt, theta, residual, jacobian, with_jacobian)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      !> New positions, 2 per node.
      real(dp), intent(in) :: x(:)
      !> Old time and step, s; time weight (1/2 conserves energy).
      real(dp), intent(in) :: t0, dt, theta
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian (band storage).
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form the Jacobian.
      logical, intent(in) :: with_jacobian
      integer :: n, k
      n = self%n
      call geometry_flat(self, x, self%e1, self%l1, self%th1)
      call copy_values(2*n, x, self%memo_x)
      call copy_geometry(n, self%e1, self%l1, self%th1, self%memo_e, self%memo_l, self%memo_th)
      self%memo_b_ok = .false.
      call bend_nodes(self, 2, n - 1)
      call section_cell_terms(self, t0, dt, with_jacobian, 1, n - 1)
      self%memo_valid = .true.
      call apply_loads(self, x, dt, theta, with_jacobian)
      call assemble(self, x, t0, dt, residual, jacobian, with_jacobian, dynamic=.true., theta=theta)
   end subroutine rod_step_system

   !> The bending terms of a step (bend_divided) at the nodes k1 .. k2: the moment, its
   !> derivative and, where computed, the new bending energy (memo).
   subroutine bend_nodes(self, k1, k2)
      type(rod_piece), intent(inout) :: self
      integer, intent(in) :: k1, k2
      !> Nodes a block (the arguments of tan on the stack).
      integer, parameter :: block = 32
      real(dp) :: x(block), t(block)
      integer :: k, first, last, ka, kb
      if (allocated(self%node_ei)) then
         ! Runs of nodes of one EI, each as below.
         ka = k1
         do while (ka <= k2)
            kb = ka
            do while (kb < k2)
               if (self%node_ei(kb + 1) /= self%node_ei(ka)) exit
               kb = kb + 1
            end do
            do first = ka, kb, block
               last = min(first + block - 1, kb)
               call bend_arguments(last - first + 1, self%th0(first:last), self%th1(first:last), x)
               call fast_tan_array(last - first + 1, x, t)
               call bend_divided_array(last - first + 1, self%node_ei(ka), self%dual(first:last), &
                                       self%th0(first:last), self%th1(first:last), self%b0(first:last), t, &
                                       self%mom(first:last), self%dmom(first:last), self%memo_b(first:last), &
                                       self%memo_b_ok(first:last))
            end do
            ka = kb + 1
         end do
         return
      end if
      ! The tan of each node first, by fast_tan_array (packed SSE2 pairs), of bend_divided's
      ! argument computed as it did, the same bits: on fast_180kN fast_tan 10.20e6 -> 3.02e6
      ! instructions (bend_energy's calls), fast_tan_array 4.77e6, bend_nodes 21.60e6 -> 22.59e6;
      ! the whole process 0.5685e9 -> 0.5672e9 (callgrind, docs/measurements/data/speed_rounds.md).
      do first = k1, k2, block
         last = min(first + block - 1, k2)
         call bend_arguments(last - first + 1, self%th0(first:last), self%th1(first:last), x)
         call fast_tan_array(last - first + 1, x, t)
         ! Then bend_divided by bend_divided_array (its Taylor branch in packed SSE2 pairs, the
         ! divisions too: about 96 % of the nodes on fast_180kN), the same bits; with the
         ! packed arguments bend_nodes 22.59e6 -> 15.17e6 instructions, the lean run -1.5 %.
         call bend_divided_array(last - first + 1, self%ei, self%dual(first:last), self%th0(first:last), &
                                 self%th1(first:last), self%b0(first:last), t, self%mom(first:last), &
                                 self%dmom(first:last), self%memo_b(first:last), self%memo_b_ok(first:last))
      end do
   end subroutine bend_nodes

   !> cell_terms on the cells c1 .. c2 of a step: with the piece's law and damping, or on a
   !> line of segments section by section with each one's.
   subroutine section_cell_terms(self, t0, dt, with_jacobian, c1, c2)
      type(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: t0, dt
      logical, intent(in) :: with_jacobian
      integer, intent(in) :: c1, c2
      integer :: n, j, a, b
      n = self%n
      if (.not. allocated(self%sections)) then
         call cell_terms(n, self%law, self%e0, self%e1, self%l0, self%l1, self%ds, self%mom, self%dmom, &
                         self%damping, dt, cell_couple(self, 1, t0, t0 + dt), cell_couple(self, n - 1, t0, t0 + dt), &
                         with_jacobian, self%force, self%block, self%memo_dphi, c1, c2)
         return
      end if
      do j = 1, size(self%sections)
         a = max(c1, self%sections(j)%first)
         b = min(c2, self%sections(j)%last)
         if (a > b) cycle
         call cell_terms(n, self%sections(j)%law, self%e0, self%e1, self%l0, self%l1, self%ds, self%mom, &
                         self%dmom, self%sections(j)%damping, dt, cell_couple(self, 1, t0, t0 + dt), &
                         cell_couple(self, n - 1, t0, t0 + dt), with_jacobian, self%force, self%block, &
                         self%memo_dphi, a, b)
      end do
   end subroutine section_cell_terms

   !> EI of node k, N m^2.
   pure real(dp) function node_ei(self, k)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      if (allocated(self%node_ei)) then
         node_ei = self%node_ei(k)
      else
         node_ei = self%ei
      end if
   end function node_ei

   !> The tension of cell c at a strain (its section's law), N.
   pure real(dp) function rod_cell_tension(self, c, strain) result(tension)
      !> Piece.
      class(rod_piece), intent(in) :: self
      !> Cell.
      integer, intent(in) :: c
      !> Strain.
      real(dp), intent(in) :: strain
      if (allocated(self%sections)) then
         tension = self%sections(self%cell_sec(c))%law%tension(strain)
      else
         tension = self%law%tension(strain)
      end if
   end function rod_cell_tension

   !> Bending energy of interior node k at turning angle th: B = 2 EI tan^2(th / 2) / h_k,
   !> that is EI kappa^2 h_k / 2 with the discrete curvature kappa = 2 tan(th / 2) / h_k
   !> (the curvature of discrete elastic rods). It is EI th^2 / (2 h_k) to O(th^4) and grows
   !> without bound as two cells fold onto each other (th -> +-pi), which keeps the
   !> turning angle inside (-pi, pi). 0 at the ends of the piece.
   pure real(dp) function bend_energy(self, k, th)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_energy = 0
      if (k >= 2 .and. k <= self%n - 1) bend_energy = bending_energy(node_ei(self, k), self%dual(k), fast_tan(0.5_dp*th))
   end function bend_energy

   !> The discrete curvature 2 tan(th / 2) / h_k of node k, 1/m (counter-clockwise positive).
   pure real(dp) function bend_curvature(self, k, th)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_curvature = 2*fast_tan(0.5_dp*th)/self%dual(k)
   end function bend_curvature

   !> Moment dB/dth of node k, N m.
   pure real(dp) function bend_moment(self, k, th)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_moment = bending_moment(node_ei(self, k), self%dual(k), fast_tan(0.5_dp*th))
   end function bend_moment

   !> d2B/dth2 of node k, N m.
   pure real(dp) function bend_stiffness(self, k, th)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_stiffness = bending_stiffness(node_ei(self, k), self%dual(k), fast_tan(0.5_dp*th))
   end function bend_stiffness

   !> Applied couple on cell c (the end cells), averaged over [ta, tb].
   pure real(dp) function cell_couple(self, c, ta, tb)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: c
      real(dp), intent(in) :: ta, tb
      cell_couple = 0
      if (c == 1) cell_couple = cell_couple + 0.5_dp*(self%end_a%applied_couple(ta) + self%end_a%applied_couple(tb))
      if (c == self%n - 1) cell_couple = cell_couple + 0.5_dp*(self%end_b%applied_couple(ta) &
                                                               + self%end_b%applied_couple(tb))
   end function cell_couple

   !> M V with the band of M in mass(0:2, n), on explicit-shape arrays: the same
   !> operations in the same order as on the assumed-shape arrays and the class
   !> component, in 5 times fewer instructions (callgrind, fast_180kN; the other
   !> kernels below: 2-3 times; docs/measurements/data/speed_rounds.md).
   pure subroutine mass_product(n, mass, v, mv)
      integer, intent(in) :: n
      real(dp), intent(in) :: mass(0:2, n), v(2, n)
      real(dp), intent(out) :: mv(2, n)
      integer :: k, j
      do k = 1, n
         mv(:, k) = mass(0, k)*v(:, k)
      end do
      do j = 1, 2
         do k = 1, n - j
            mv(:, k) = mv(:, k) + mass(j, k)*v(:, k + j)
            mv(:, k + j) = mv(:, k + j) + mass(j, k)*v(:, k)
         end do
      end do
   end subroutine mass_product

   !> Copy a geometry (explicit shapes: a plain copy, not one through the
   !> descriptors of class components).
   pure subroutine copy_geometry(n, e, l, th, e_to, l_to, th_to)
      integer, intent(in) :: n
      real(dp), intent(in) :: e(2, n - 1), l(n - 1), th(n)
      real(dp), intent(out) :: e_to(2, n - 1), l_to(n - 1), th_to(n)
      e_to = e
      l_to = l
      th_to = th
   end subroutine copy_geometry

   !> Copy m values.
   pure subroutine copy_values(m, a, a_to)
      integer, intent(in) :: m
      real(dp), intent(in) :: a(m)
      real(dp), intent(out) :: a_to(m)
      a_to = a
   end subroutine copy_values

   !> Whether a and b are the same number to the bit (unlike ==, which takes -0 for +0).
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b
      same_bits = transfer(a, 0_i8) == transfer(b, 0_i8)
   end function same_bits

   !> rod_new_velocity on explicit-shape arrays (the same expression; the array expression on
   !> the class components took 2.7 times the instructions, callgrind on fast_180kN).
   pure subroutine new_velocity_of(m, r1, r0, v0, dt, theta, v1)
      integer, intent(in) :: m
      real(dp), intent(in) :: r1(m), r0(m), v0(m), dt, theta
      real(dp), intent(out) :: v1(m)
      v1 = ((r1 - r0)/dt - (1 - theta)*v0)/theta
   end subroutine new_velocity_of

   !> A planar point (x, z) as the 3-D point (x, 0, z) of the ends' state procedures.
   pure function point3(p) result(q)
      !> The point (x, z).
      real(dp), intent(in) :: p(2)
      real(dp) :: q(3)
      q = [p(1), 0.0_dp, p(2)]
   end function point3

   ! ---- for the submodules in model/rod/ ----
   ! gfortran 12 makes a module's private procedures local symbols that its submodules cannot link
   ! to; making node_weight and old_energies themselves public would keep the compiler from
   ! inlining and specialising them in the step here (a global symbol may be interposed under
   ! fpm's -fPIC). So the submodules call these public wrappers.

   !> node_weight, for the submodules.
   pure real(dp) function rod_node_weight(self, k)
      !> Piece.
      class(rod_piece), intent(in) :: self
      !> Node.
      integer, intent(in) :: k
      rod_node_weight = node_weight(self, k)
   end function rod_node_weight

   !> old_energies (b0 from the old level's turning angles), for the submodules.
   subroutine rod_old_energies(self)
      !> Piece.
      class(rod_piece), intent(inout) :: self
      call old_energies(self)
   end subroutine rod_old_energies
end module xcable_model_rod
