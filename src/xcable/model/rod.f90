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
!> This file holds the piece's types and the statics and time step with their helpers (the hot
!> path, kept in one compilation unit: gfortran inlines and specialises only a unit's private
!> procedures; the piece-free kernels are in model/rod_kernels.f90). The submodules in model/rod/
!> hold the cold parts: init.f90 (the set-up) and records.f90 (the reaction, the cell fields).
module xcable_model_rod
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, stat_numerics
   use xcable_core_strings, only: str
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_cell_force, damped_tension, may_cross_kink
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
   ! For the submodules in model/rod/ (see the wrappers at the end).
   public :: rod_node_weight, rod_old_energies

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

   !> Newton's contraction estimate (newton_problem) after the update from the last evaluated
   !> point: trusted unless it may have carried a cell past the kink of the law by more than
   !> the tolerance (may_cross_kink) (the cells
   !> whose strains the evaluation computed from the unknowns: a window's lo - 1 .. hi).
   logical function rod_problem_estimate_trusted(self, update, tolerance) result(trusted)
      !> Problem.
      class(rod_problem), intent(in) :: self
      !> The update, 2 per node of the window (all nodes when there is none), m.
      real(dp), intent(in) :: update(:)
      !> Tolerance on the scaled update (scale: length_ref).
      real(dp), intent(in) :: tolerance
      real(dp) :: du(rod_nodal, self%piece%n)
      integer :: lo, hi, ca, cb
      integer :: j, a, b
      trusted = .true.
      if (.not. self%piece%has_kink()) return
      lo = 1
      hi = self%piece%n
      if (windowed(self)) then
         lo = self%lo
         hi = self%hi
      end if
      ca = max(1, lo - 1)
      cb = min(self%piece%n - 1, hi)
      du(:, ca:cb + 1) = 0
      du(:, lo:hi) = reshape(update, [rod_nodal, hi - lo + 1])
      if (.not. allocated(self%piece%sections)) then
         trusted = .not. may_cross_kink(self%piece%law%strain_slack, self%piece%l1(ca:cb), self%piece%ds(ca:cb), &
                                        du(:, ca:cb + 1), tolerance*self%piece%length_ref)
         return
      end if
      do j = 1, size(self%piece%sections)
         a = max(ca, self%piece%sections(j)%first)
         b = min(cb, self%piece%sections(j)%last)
         if (a > b) cycle
         if (.not. self%piece%sections(j)%law%strain_slack > -huge(1.0_dp)) cycle
         if (may_cross_kink(self%piece%sections(j)%law%strain_slack, self%piece%l1(a:b), self%piece%ds(a:b), &
                            du(:, a:b + 1), tolerance*self%piece%length_ref)) trusted = .false.
      end do
   end function rod_problem_estimate_trusted

   !> Whether the problem is a step on a window of the piece's nodes (lo .. hi, not all of them).
   pure logical function windowed(self)
      class(rod_problem), intent(in) :: self
      windowed = self%dt > 0 .and. self%hi > 0 .and. (self%lo > 1 .or. self%hi < self%piece%n)
   end function windowed

   !> The evaluation of a step at its converged positions x (the window's unknowns when the
   !> problem has a window, as for evaluate), in place of the full residual Newton would
   !> evaluate there (newton_options%final_residual): step_state.
   subroutine rod_problem_accepted_state(self, x)
      !> Problem (a step: dt > 0).
      class(rod_problem), intent(inout) :: self
      !> Positions, 2 per node of the window (all nodes when there is none).
      real(dp), intent(in) :: x(:)
      if (windowed(self)) then
         call step_state(self%piece, x, self%lo, self%hi, self%t0, self%dt, self%theta)
      else
         call step_state(self%piece, x, 1, self%piece%n, self%t0, self%dt, self%theta)
      end if
   end subroutine rod_problem_accepted_state

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

   !> Residual (and Jacobian) of the static equilibrium at time t: for a loaded
   !> node, [-(N_k - N_k-1) + w_k e_z - F_k(t)] / T_ref with N_c the exact
   !> gradient of U per cell; for a held node (R_k - X(t)) / ds_ref.
   subroutine rod_static_system(self, x, t, residual, jacobian, with_jacobian)
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
      integer :: c, n, k
      real(dp) :: f, fp, t_c(2), pvec(2), moment_diff, couple, stiff(2, 2), dp_de(2, 2)
      real(dp) :: dmom(2, -1:1), jm(2, 2)
      n = self%n
      call geometry_flat(self, x, self%e1, self%l1, self%th1)
      jm = reshape([0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp], [2, 2])
      do k = 2, n - 1
         self%mom(k) = bend_moment(self, k, self%th1(k))
         self%dmom(k) = bend_stiffness(self, k, self%th1(k))
      end do
      do c = 1, n - 1
         associate (e => self%e1(:, c), l => self%l1(c))
            if (allocated(self%sections)) then
               call self%sections(self%cell_sec(c))%law%tension_stiffness(l - 1, f, fp)
            else
               call self%law%tension_stiffness(l - 1, f, fp)
            end if
            t_c = e/l
            pvec = perp(e)/l**2
            couple = cell_couple(self, c, t, t)
            moment_diff = self%mom(c) - self%mom(c + 1) - couple
            self%force(:, c) = f*t_c + moment_diff/self%ds(c)*pvec
            if (.not. with_jacobian) cycle
            stiff = fp*outer(t_c, t_c) + f/l*(identity2() - outer(t_c, t_c))
            dp_de = (jm - 2*outer(matmul(jm, e), e)/l**2)/l**2
            dmom = moment_difference_gradient(self, c)
            self%block(:, :, 0, c) = stiff + moment_diff/self%ds(c)*dp_de + outer(pvec, dmom(:, 0))/self%ds(c)
            self%block(:, :, -1, c) = outer(pvec, dmom(:, -1))/self%ds(c)
            self%block(:, :, 1, c) = outer(pvec, dmom(:, 1))/self%ds(c)
         end associate
      end do
      call apply_loads(self, x, 0.0_dp, 0.5_dp, with_jacobian)
      call assemble(self, x, t, t, residual, jacobian, with_jacobian, dynamic=.false.)
   end subroutine rod_static_system

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

   !> Before a step solved on a window of nodes (rod_problem lo, hi): the new level's
   !> geometry and the memo of the last evaluation are set to the old level's, which is
   !> what the nodes outside the window keep (their new positions are their old ones, so
   !> these are the values an evaluation would compute for them, the same bits); the
   !> window's evaluations then overwrite their own part.
   subroutine rod_freeze_level(self)
      class(rod_piece), intent(inout) :: self
      integer :: n
      n = self%n
      call copy_geometry(n, self%e0, self%l0, self%th0, self%e1, self%l1, self%th1)
      call copy_values(2*n, self%r0, self%memo_x)
      call copy_geometry(n, self%e0, self%l0, self%th0, self%memo_e, self%memo_l, self%memo_th)
      call copy_values(n, self%b0, self%memo_b)
      self%memo_b_ok = .true.
      ! atan2(e0 x e0, e0 . e0) = 0: a cell that keeps its positions does not rotate.
      self%memo_dphi = 0
      self%memo_valid = .true.
   end subroutine rod_freeze_level

   !> rod_step_system on the window of nodes lo .. hi (2 < hi - lo + 1 < n; no distributed
   !> loads): x holds the new positions of the window's nodes; the others stay at the
   !> old level (rod_freeze_level). The residual rows and the unknowns (Jacobian
   !> columns) are the window's; the cells and nodes whose terms enter them are computed
   !> (cells lo - 2 .. hi + 1 for the geometry, nodes lo - 1 .. hi + 1 for the moments,
   !> cells lo - 1 .. hi for the forces), and so are the end cells and end velocities a
   !> reaction needs. The operations on each value are those of rod_step_system.
   subroutine step_window(self, x, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)
      type(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: lo, hi
      real(dp), intent(in) :: t0, dt, theta
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian
      integer :: n, ga, gb, ca, cb
      n = self%n
      self%memo_x(2*lo - 1:2*hi) = x
      ga = max(1, lo - 2)
      gb = min(n - 1, hi + 1)
      call geometry_cells(n, self%ds, self%memo_x, self%e1, self%l1, self%th1, ga, gb)
      self%memo_e(:, ga:gb) = self%e1(:, ga:gb)
      self%memo_l(ga:gb) = self%l1(ga:gb)
      self%memo_th(ga + 1:gb) = self%th1(ga + 1:gb)
      call bend_nodes(self, max(2, lo - 1), min(n - 1, hi + 1))
      ca = max(1, lo - 1)
      cb = min(n - 1, hi)
      ! The end cells for the reactions (rod_reaction), when outside.
      if (ca > 1) then
         call bend_nodes(self, 2, 2)
         call window_cells(1, 1)
      end if
      if (cb < n - 1) then
         call bend_nodes(self, n - 1, n - 1)
         call window_cells(n - 1, n - 1)
      end if
      call window_cells(ca, cb)
      self%memo_valid = .true.
      ! No loads on a window: load_node holds the zeros of init (apply_loads).
      call assemble_window(self, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)

   contains

      subroutine window_cells(c1, c2)
         integer, intent(in) :: c1, c2
         call section_cell_terms(self, t0, dt, with_jacobian, c1, c2)
      end subroutine window_cells
   end subroutine step_window

   !> What a step's evaluation at its converged positions leaves that the accepted state
   !> needs, computed by the same expressions as rod_step_system and step_window (so the
   !> same bits), without the residual: the new level's geometry e1, l1, th1; the memo
   !> (positions, geometry, the bending energy of every node whose turning angle is
   !> evaluated, each cell's rotation dphi) for check_state, the next prepare_step and the
   !> ledger; the forces of the two end cells, the end nodes' new velocities and the
   !> distributed loads for rod_reaction and the ledger's work. The other cells' forces and
   !> blocks, the other nodes' moments and velocities and the residual are not computed
   !> (they stay those of the last evaluation). Window lo .. hi (1 .. n: the whole piece);
   !> x holds the new positions of its nodes. On fast_180kN (241 nodes) it takes about
   !> 101 000 instructions, the residual alone it replaces about 235 000 (docs/measurements/data/speed_rounds.md).
   subroutine step_state(self, x, lo, hi, t0, dt, theta)
      type(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: lo, hi
      real(dp), intent(in) :: t0, dt, theta
      integer :: n, ga, gb, ca, cb, k, k1, k2, kk, a
      n = self%n
      if (lo == 1 .and. hi == n) then
         call geometry_of(n, self%ds, x, self%e1, self%l1, self%th1)
         call copy_values(2*n, x, self%memo_x)
         call copy_geometry(n, self%e1, self%l1, self%th1, self%memo_e, self%memo_l, self%memo_th)
         self%memo_b_ok = .false.
         k1 = 2
         k2 = n - 1
         ca = 1
         cb = n - 1
      else
         self%memo_x(2*lo - 1:2*hi) = x
         ga = max(1, lo - 2)
         gb = min(n - 1, hi + 1)
         call geometry_cells(n, self%ds, self%memo_x, self%e1, self%l1, self%th1, ga, gb)
         self%memo_e(:, ga:gb) = self%e1(:, ga:gb)
         self%memo_l(ga:gb) = self%l1(ga:gb)
         self%memo_th(ga + 1:gb) = self%th1(ga + 1:gb)
         k1 = max(2, lo - 1)
         k2 = min(n - 1, hi + 1)
         ca = max(1, lo - 1)
         cb = min(n - 1, hi)
      end if
      ! The bending terms of the evaluated nodes, as a step evaluation computes them: the
      ! end cells' forces need the moments of nodes 2 and n - 1, the next step's old level
      ! the bending energies. (bend_divided's B(th1), not B computed by a separate loop:
      ! gfortran vectorises a plain loop over tan with glibc's libmvec, whose tan differs
      ! from libm's in the last bits.)
      call bend_nodes(self, k1, k2)
      if (k1 > 2) call bend_nodes(self, 2, 2)
      if (k2 < n - 1) call bend_nodes(self, n - 1, n - 1)
      call section_cell_terms(self, t0, dt, .false., 1, 1)
      if (n > 2) call section_cell_terms(self, t0, dt, .false., n - 1, n - 1)
      ! Each cell's rotation, as cell_terms computes it.
      call cell_rotations_of(n, self%e0, self%e1, self%memo_dphi, ca, cb)
      self%memo_valid = .true.
      ! (A window has no loads: load_node holds the zeros of init, apply_loads.)
      if (lo == 1 .and. hi == n) call apply_loads(self, x, dt, theta, .false.)
      ! The new velocities a reaction needs (nodes 1 .. 3 and n - 2 .. n).
      do k = 1, n
         if (k > 3 .and. k < n - 2) cycle
         do a = 1, 2
            kk = 2*k - 2 + a
            self%v1(a, k) = ((self%memo_x(kk) - self%r0(a, k))/dt - (1 - theta)*self%v0(a, k))/theta
         end do
      end do
   end subroutine step_state

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

   !> Whether the law of any cell has a kink (strain_slack: a rope that cannot push).
   pure logical function rod_has_kink(self) result(kink)
      !> Piece.
      class(rod_piece), intent(in) :: self
      integer :: j
      kink = self%law%strain_slack > -huge(1.0_dp)
      if (.not. allocated(self%sections)) return
      do j = 1, size(self%sections)
         if (self%sections(j)%law%strain_slack > -huge(1.0_dp)) kink = .true.
      end do
   end function rod_has_kink

   !> assemble (dynamic) on the rows and columns of the nodes lo .. hi, from the cell
   !> forces and blocks step_window computed; the positions of all nodes in memo_x.
   !> Each residual entry gets its terms in assemble's order.
   subroutine assemble_window(self, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)
      type(rod_piece), intent(inout) :: self
      integer, intent(in) :: lo, hi
      real(dp), intent(in) :: t0, dt, theta
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian
      integer :: n, off, va, vb
      real(dp) :: scale, rate, fext_a(2), fext_b(2), t_new, jac_a(2, 2), jac_b(2, 2)
      logical :: held_a, held_b, state_a, state_b
      n = self%n
      scale = 1/self%tension_ref
      held_a = self%end_a%held()
      held_b = self%end_b%held()
      t_new = t0 + dt
      off = 2*(lo - 1)
      ! New velocities where the rows (and the reactions at the ends) need them.
      va = max(1, lo - 2)
      vb = min(n, hi + 2)
      call window_velocities(va, vb)
      if (va > 1) call window_velocities(1, min(3, n))
      if (vb < n) call window_velocities(max(1, n - 2), n)
      ! The rows of the nodes lo .. hi: node_residuals, as assemble's (explicit shapes: the
      ! same operations in the same order as the loop over self's components it replaces,
      ! 0.6375e9 -> 0.6359e9 instructions on fast_180kN, callgrind).
      fext_a = 0
      fext_b = 0
      if (lo == 1) fext_a = 0.5_dp*(self%end_a%applied_force(t0) + self%end_a%applied_force(t_new))
      if (hi == n) fext_b = 0.5_dp*(self%end_b%applied_force(t0) + self%end_b%applied_force(t_new))
      state_a = lo == 1 .and. self%end_a%state_dependent()
      state_b = hi == n .and. self%end_b%state_dependent()
      if (state_a) call add_end_state(self%end_a, .true., t0, dt, self%r0(:, 1), self%memo_x(1:2), fext_a, jac_a)
      if (state_b) call add_end_state(self%end_b, .true., t0, dt, self%r0(:, n), self%memo_x(2*n - 1:2*n), fext_b, &
                                      jac_b)
      if (allocated(self%node_w)) then
         ! The node weights as lumped lengths of a unit weight (1 * w_k: the same bits).
         call node_residuals(n, lo, hi, self%force, node_weight(self, 1), node_weight(self, n), 1.0_dp, &
                             self%node_w, self%load_node, fext_a, fext_b, .true., self%mass, self%v1, self%mv0, dt, &
                             scale, residual)
      else
         call node_residuals(n, lo, hi, self%force, node_weight(self, 1), node_weight(self, n), self%weight, &
                             self%lumped, self%load_node, fext_a, fext_b, .true., self%mass, self%v1, self%mv0, dt, &
                             scale, residual)
      end if
      if (held_a .and. lo == 1) residual(1:2) = (self%memo_x(1:2) - self%end_a%position(t_new))/self%length_ref
      if (held_b .and. hi == n) residual(2*(hi - lo) + 1:2*(hi - lo) + 2) = &
         (self%memo_x(2*n - 1:2*n) - self%end_b%position(t_new))/self%length_ref
      if (.not. with_jacobian) return
      rate = 1/(theta*dt*dt)
      call jacobian%clear()
      call add_jacobian(n, lo, hi, jacobian%ldab, jacobian%kl + jacobian%ku + 1, jacobian%ab, self%block, self%ds, &
                        self%mass, scale, rate, held_a, held_b, .true., self%block_scaled, self%mass_scaled)
      if (state_a) call add_end_block(jacobian, 0, jac_a, scale)
      if (state_b) call add_end_block(jacobian, 2*(hi - lo), jac_b, scale)
      if (held_a .and. lo == 1) then
         jacobian%ab(jacobian%kl + jacobian%ku + 1, 1:2) = 1/self%length_ref
      end if
      if (held_b .and. hi == n) then
         jacobian%ab(jacobian%kl + jacobian%ku + 1, 2*(hi - lo) + 1:2*(hi - lo) + 2) = 1/self%length_ref
      end if

   contains

      subroutine window_velocities(k1, k2)
         integer, intent(in) :: k1, k2
         integer :: kk, aa
         do kk = k1, k2
            do aa = 1, 2
               self%v1(aa, kk) = ((self%memo_x(2*kk - 2 + aa) - self%r0(aa, kk))/dt - (1 - theta)*self%v0(aa, kk))/theta
            end do
         end do
      end subroutine window_velocities
   end subroutine assemble_window

   !> d(M_c - M_c+1)/de_c' for c' = c-1, c, c+1 (columns -1:1), with the moments' derivatives
   !> dmom with respect to the new turning angles (statics and steps alike): the turning
   !> angle of node k changes by perp(e_c) . de_c / |e_c|^2 with its cell c = k - 1 or k.
   pure function moment_difference_gradient(self, c) result(d)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: c
      real(dp) :: d(2, -1:1)
      d = moment_gradient_of(self%n, c, self%e1, self%l1, self%dmom)
   end function moment_difference_gradient

   !> The distributed loads at the positions x: each cell's force (the load per
   !> unstretched length times ds) goes half to each of its nodes. In a step
   !> (dt > 0) a cell's kinematics are centred on the step: stretch vector
   !> (e^n + e^n+1) / 2, velocity (R^n+1 - R^n) / dt and acceleration
   !> (V^n+1 - V^n) / dt, each the mean of its two nodes'; in statics, e of x at
   !> rest. Fills load_node and, when asked, load_block.
   subroutine apply_loads(self, x, dt, theta, with_jacobian)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt, theta
      logical, intent(in) :: with_jacobian
      call cell_loads(self, x, dt, theta, with_jacobian)
      if (allocated(self%points)) call point_loads(self, x, dt)
   end subroutine apply_loads

   !> The drag of the bodies at nodes on load_node (which cell_loads cleared, or which holds the
   !> zeros of init when there are no cell loads: cleared here), and its derivative (x, z) in
   !> point_jac.
   subroutine point_loads(self, x, dt)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt
      integer :: i, k
      real(dp) :: f(3), jac(3, 3), x1(3)
      logical :: cleared
      cleared = allocated(self%loads)
      if (cleared) cleared = size(self%loads) > 0
      if (.not. cleared) self%load_node = 0
      do i = 1, size(self%points)
         if (.not. self%points(i)%has_drag()) cycle
         k = self%point_node(i)
         x1 = [x(2*k - 1), 0.0_dp, x(2*k)]
         if (dt > 0) then
            call self%points(i)%drag(dt, [self%r0(1, k), 0.0_dp, self%r0(2, k)], x1, f, jac)
         else
            call self%points(i)%drag(dt, x1, x1, f, jac)
         end if
         self%load_node(:, k) = self%load_node(:, k) + self%load_factor*f([1, 3])
         self%point_jac(:, :, i) = self%load_factor*jac([1, 3], [1, 3])
      end do
   end subroutine point_loads

   !> The distributed loads along the cells (apply_loads).
   subroutine cell_loads(self, x, dt, theta, with_jacobian)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: dt, theta
      logical, intent(in) :: with_jacobian
      integer :: c, i, n
      real(dp) :: e(2), w(2), a(2), f(2), df_de(2, 2), df_dw(2, 2), df_da(2, 2), r1(2, 2), de_coef, kin(2, 2), &
                  xm(2), dx_coef, df_dx(2, 2)
      ! Without loads load_node stays the zeros init set: only this routine writes other
      ! values, and a piece's loads are set once, before its first evaluation. (Clearing it
      ! at every evaluation, a memset per node, took 0.8 % of fast_180kN's instructions.)
      if (.not. allocated(self%loads)) return
      if (size(self%loads) == 0) return
      self%load_node = 0
      n = self%n
      self%load_block = 0
      self%skewed = any_skew(self%loads)
      if (self%skewed) self%skew_block = 0
      do c = 1, n - 1
         r1 = reshape(x(2*c - 1:2*c + 2), [2, 2])
         call cell_kinematics(self%e0(:, c), self%e1(:, c), self%r0(:, c:c + 1), self%v0(:, c:c + 1), r1, dt, theta, &
                              e, w, a, de_coef, xm, dx_coef)
         do i = 1, size(self%loads)
            if (.not. self%loads(i)%acts_on(self%s(c), self%s(c + 1))) cycle
            call self%loads(i)%load%cell_force(xm, self%ds(c), e, w, a, f, df_dx, df_de, df_dw, df_da)
            f = self%load_factor*f
            df_dx = self%load_factor*df_dx
            df_de = self%load_factor*df_de
            df_dw = self%load_factor*df_dw
            df_da = self%load_factor*df_da
            self%load_node(:, c) = self%load_node(:, c) + 0.5_dp*self%ds(c)*f
            self%load_node(:, c + 1) = self%load_node(:, c + 1) + 0.5_dp*self%ds(c)*f
            if (.not. with_jacobian) cycle
            ! dF_c/dR_b = ds [df/dx dx/dR_b + df/de de/dR_b + df/dw dw/dR_b + df/da da/dR_b],
            ! dx/dR_b = dx_coef, de/dR_b = +-de_coef / ds.
            kin = self%ds(c)*dx_coef*df_dx
            if (dt > 0) kin = kin + self%ds(c)*(df_dw/(2*dt) + df_da/(2*theta*dt*dt))
            self%load_block(:, :, 0, c) = self%load_block(:, :, 0, c) - de_coef*df_de + kin
            self%load_block(:, :, 1, c) = self%load_block(:, :, 1, c) + de_coef*df_de + kin
         end do
         ! The unequal shares: node c takes +ds g, node c + 1 -ds g.
         if (.not. self%skewed) cycle
         do i = 1, size(self%loads)
            if (.not. self%loads(i)%load%has_skew()) cycle
            if (.not. self%loads(i)%acts_on(self%s(c), self%s(c + 1))) cycle
            call self%loads(i)%load%cell_skew(xm, self%ds(c), e, w, a, f, df_dx, df_de, df_dw, df_da)
            f = self%load_factor*f
            self%load_node(:, c) = self%load_node(:, c) + self%ds(c)*f
            self%load_node(:, c + 1) = self%load_node(:, c + 1) - self%ds(c)*f
            if (.not. with_jacobian) cycle
            kin = self%ds(c)*dx_coef*df_dx
            if (dt > 0) kin = kin + self%ds(c)*(df_dw/(2*dt) + df_da/(2*theta*dt*dt))
            self%skew_block(:, :, 0, c) = self%skew_block(:, :, 0, c) + self%load_factor*(-de_coef*df_de + kin)
            self%skew_block(:, :, 1, c) = self%skew_block(:, :, 1, c) + self%load_factor*(de_coef*df_de + kin)
         end do
      end do
   end subroutine cell_loads

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
      if (k >= 2 .and. k <= self%n - 1) bend_energy = bend_energy_of(node_ei(self, k), self%dual(k), fast_tan(0.5_dp*th))
   end function bend_energy

   !> bend_energy from t = tan(th / 2).
   !> (Bending stiffness ei, N m^2, and dual length hk of the node, m: also bend_moment_of,
   !> bend_stiffness_of, bend_taylor, bend_divided.)
   elemental real(dp) function bend_energy_of(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bend_energy_of = 2*ei*t**2/hk
   end function bend_energy_of

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
      bend_moment = bend_moment_of(node_ei(self, k), self%dual(k), fast_tan(0.5_dp*th))
   end function bend_moment

   !> bend_moment from t = tan(th / 2).
   elemental real(dp) function bend_moment_of(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bend_moment_of = 2*ei*t*(1 + t*t)/hk
   end function bend_moment_of

   !> d2B/dth2 of node k, N m.
   pure real(dp) function bend_stiffness(self, k, th)
      class(rod_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_stiffness = bend_stiffness_of(node_ei(self, k), self%dual(k), fast_tan(0.5_dp*th))
   end function bend_stiffness

   !> bend_stiffness from t = tan(th / 2).
   elemental real(dp) function bend_stiffness_of(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bend_stiffness_of = ei*(1 + t*t)*(1 + 3*t*t)/hk
   end function bend_stiffness_of

   !> The discrete gradient of the bending energy of a node between the turning
   !> angles th0 and th1, m = [B(th1) - B(th0)] / (th1 - th0), and dm / dth1
   !> (Taylor forms when the two are close, bend_taylor).
   pure subroutine bend_divided(ei, hk, th0, th1, b0, t, m, dm, b1, b1_ok)
      real(dp), intent(in) :: ei, hk
      !> Old and new turning angle, and the old one's bending energy B(th0).
      real(dp), intent(in) :: th0, th1, b0
      !> fast_tan(bend_argument(th0, th1)).
      real(dp), intent(in) :: t
      real(dp), intent(out) :: m, dm
      !> B(th1) when it was computed (b1_ok).
      real(dp), intent(out) :: b1
      logical, intent(out) :: b1_ok
      real(dp) :: h
      h = th1 - th0
      if (abs(h) < small_rotation) then
         call bend_taylor(ei, hk, h, t, m, dm)
         b1 = 0
         b1_ok = .false.
      else
         ! One tan for B(th1) and its moment (the compiler called tan twice here).
         b1 = bend_energy_of(ei, hk, t)
         b1_ok = .true.
         m = (b1 - b0)/h
         dm = (bend_moment_of(ei, hk, t) - m)/h
      end if
   end subroutine bend_divided

   !> bend_divided's Taylor forms (|h| < small_rotation, h = th1 - th0, t the tan of half
   !> the mean turning angle): m = B' + B''' h^2 / 24 and dm = B'' / 2 + B''' h / 12.
   elemental subroutine bend_taylor(ei, hk, h, t, m, dm)
      real(dp), intent(in) :: ei, hk, h, t
      real(dp), intent(out) :: m, dm
      real(dp) :: third
      ! d3B/dth3 = EI (1 + t^2) t (4 + 6 t^2) / h_k
      third = ei*(1 + t*t)*t*(4 + 6*t*t)/hk
      m = bend_moment_of(ei, hk, t) + third*h*h/24
      dm = 0.5_dp*bend_stiffness_of(ei, hk, t) + third*h/12
   end subroutine bend_taylor

   !> bend_divided at n nodes, bit for bit: bend_taylor at every node in a loop without
   !> branches (gfortran 12 packs it two nodes to an SSE2 operation, divisions included),
   !> then, if some node is not that case (|th1 - th0| >= small_rotation, NaN),
   !> bend_divided itself for each of those. test/suite_rod.f90 compares bend_nodes' results
   !> with the per-node forms by their bits (bend_terms_in_pairs_same_bits).
   pure subroutine bend_divided_array(n, ei, hk, th0, th1, b0, t, m, dm, b1, b1_ok)
      !> Number of nodes.
      integer, intent(in) :: n
      !> Bending stiffness, N m^2.
      real(dp), intent(in) :: ei
      !> The nodes' dual lengths, old and new turning angles, old bending energies and tan
      !> (fast_tan(bend_argument(th0, th1))).
      real(dp), intent(in) :: hk(n), th0(n), th1(n), b0(n), t(n)
      !> bend_divided's results at each node.
      real(dp), intent(out) :: m(n), dm(n), b1(n)
      logical, intent(out) :: b1_ok(n)
      real(dp) :: h
      integer :: i
      integer(i8) :: others
      ! others: the OR of the complemented bits of |h| - small_rotation, whose sign bit is
      ! set if some |h| >= small_rotation or is NaN (as in fast_tan_array).
      others = 0
      !GCC$ unroll 1
      do i = 1, n
         h = th1(i) - th0(i)
         call bend_taylor(ei, hk(i), h, t(i), m(i), dm(i))
         others = ior(others, not(transfer(abs(h) - small_rotation, 0_i8)))
      end do
      b1 = 0
      b1_ok = .false.
      if (others >= 0) return
      do i = 1, n
         if (.not. abs(th1(i) - th0(i)) < small_rotation) &
            call bend_divided(ei, hk(i), th0(i), th1(i), b0(i), t(i), m(i), dm(i), b1(i), b1_ok(i))
      end do
   end subroutine bend_divided_array

   !> The argument of tan in bend_divided: half the mean turning angle where the two are
   !> close (its Taylor form), else half the new one.
   elemental real(dp) function bend_argument(th0, th1) result(x)
      real(dp), intent(in) :: th0, th1
      integer(i8) :: close
      ! Both forms, and the one that applies picked by a mask of bits, so that bend_arguments'
      ! loop packs in SSE2 pairs (gfortran 12 keeps a merge of the two, or of integer masks
      ! from a comparison, a branch). close: all bits set where |th1 - th0| < small_rotation,
      ! the sign bit of |th1 - th0| - small_rotation copied (never -0; a NaN is positive, as
      ! abs leaves it: not close, as the comparison).
      close = shifta(transfer(abs(th1 - th0) - small_rotation, 0_i8), 63)
      x = transfer(ior(iand(close, transfer(0.5_dp*(0.5_dp*(th0 + th1)), 0_i8)), &
                       iand(not(close), transfer(0.5_dp*th1, 0_i8))), 0.0_dp)
   end function bend_argument

   !> x(i) = bend_argument(th0(i), th1(i)), i = 1 .. n, in packed SSE2 pairs (explicit-shape
   !> arrays, as fast_tan_array's).
   pure subroutine bend_arguments(n, th0, th1, x)
      integer, intent(in) :: n
      real(dp), intent(in) :: th0(n), th1(n)
      real(dp), intent(out) :: x(n)
      integer :: i
      !GCC$ unroll 1
      do i = 1, n
         x(i) = bend_argument(th0(i), th1(i))
      end do
   end subroutine bend_arguments

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

   !> Node residuals and the Jacobian from the cell forces and blocks (statics:
   !> t1 is the time; dynamics: t1 = t0, t2 = dt).
   subroutine assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: t1, t2
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian, dynamic
      real(dp), intent(in), optional :: theta
      integer :: n, c, k, j, side, node, band0, a, b, row, col
      real(dp) :: share
      real(dp) :: scale, rate, fext_a(2), fext_b(2), t_new, jac_a(2, 2), jac_b(2, 2)
      logical :: held_a, held_b, state_a, state_b
      n = self%n
      scale = 1/self%tension_ref
      held_a = self%end_a%held()
      held_b = self%end_b%held()
      if (dynamic) then
         t_new = t1 + t2
         fext_a = 0.5_dp*(self%end_a%applied_force(t1) + self%end_a%applied_force(t_new))
         fext_b = 0.5_dp*(self%end_b%applied_force(t1) + self%end_b%applied_force(t_new))
         rate = 1/(theta*t2*t2)
         ! V^n+1 from the new positions. (Element by element: the array expressions cost 2-3
         ! times more, in temporaries.)
         do k = 1, n
            do a = 1, 2
               self%v1(a, k) = ((x(2*k - 2 + a) - self%r0(a, k))/t2 - (1 - theta)*self%v0(a, k))/theta
            end do
         end do
      else
         t_new = t1
         fext_a = self%end_a%applied_force(t1)
         fext_b = self%end_b%applied_force(t1)
         rate = 0
      end if
      ! Ends that depend on their own state (springs): their force at the node, and its derivative.
      state_a = self%end_a%state_dependent()
      state_b = self%end_b%state_dependent()
      if (state_a) call add_end_state(self%end_a, dynamic, t1, t2, self%r0(:, 1), x(1:2), fext_a, jac_a)
      if (state_b) call add_end_state(self%end_b, dynamic, t1, t2, self%r0(:, n), x(2*n - 1:2*n), fext_b, jac_b)
      ! Node k: N_k - N_k-1, its weight, loads, applied forces and in a step the inertia
      ! [M (V^n+1 - V^n)]_k / dt, over T_ref. Each node's rows are summed in one go, their
      ! terms in the order of the former loops (a pass over the residual for each kind of
      ! term: the same bits in 11e6 fewer instructions on fast_180kN, callgrind).
      if (allocated(self%node_w)) then
         call node_residuals(n, 1, n, self%force, node_weight(self, 1), node_weight(self, n), 1.0_dp, self%node_w, &
                             self%load_node, fext_a, fext_b, dynamic, self%mass, self%v1, self%mv0, t2, scale, residual)
      else
         call node_residuals(n, 1, n, self%force, node_weight(self, 1), node_weight(self, n), self%weight, &
                             self%lumped, self%load_node, fext_a, fext_b, dynamic, self%mass, self%v1, self%mv0, t2, &
                             scale, residual)
      end if
      if (held_a) residual(1:2) = (x(1:2) - self%end_a%position(t_new))/self%length_ref
      if (held_b) residual(2*n - 1:2*n) = (x(2*n - 1:2*n) - self%end_b%position(t_new))/self%length_ref
      if (.not. with_jacobian) return

      call jacobian%clear()
      band0 = jacobian%kl + jacobian%ku + 1
      call add_jacobian(n, 1, n, jacobian%ldab, band0, jacobian%ab, self%block, self%ds, self%mass, scale, rate, &
                        held_a, held_b, dynamic, self%block_scaled, self%mass_scaled)
      if (state_a) call add_end_block(jacobian, 0, jac_a, scale)
      if (state_b) call add_end_block(jacobian, 2*n - 2, jac_b, scale)
      ! Bodies at nodes: their drag's derivative (its force is in load_node).
      if (allocated(self%points)) then
         do c = 1, size(self%points)
            k = self%point_node(c)
            if ((k == 1 .and. held_a) .or. (k == n .and. held_b)) cycle
            call add_end_block(jacobian, 2*(k - 1), self%point_jac(:, :, c), scale)
         end do
      end if
      ! Distributed loads: node c and node c+1 each get -F_c / 2 (and -G_c, +G_c of unequal shares).
      if (allocated(self%loads)) then
         if (size(self%loads) > 0) then
            do c = 1, n - 1
               do side = 0, 1
                  node = c + side
                  do j = 0, 1
                     k = c + j
                     if (k == 1 .and. held_a) cycle
                     if (k == n .and. held_b) cycle
                     do a = 1, 2
                        do b = 1, 2
                           row = 2*(k - 1) + a
                           col = 2*(node - 1) + b
                           share = 0.5_dp*self%load_block(a, b, side, c)
                           if (self%skewed) share = share + merge(1.0_dp, -1.0_dp, j == 0)*self%skew_block(a, b, side, c)
                           jacobian%ab(band0 + row - col, col) = jacobian%ab(band0 + row - col, col) - share*scale
                        end do
                     end do
                  end do
               end do
            end do
         end if
      end if
      if (held_a) call held_rows(1)
      if (held_b) call held_rows(n)

   contains

      !> Rows of a held node: R_k - X(t) = 0.
      subroutine held_rows(kk)
         integer, intent(in) :: kk
         integer :: aa
         do aa = 1, 2
            row = 2*(kk - 1) + aa
            jacobian%ab(band0, row) = 1/self%length_ref
         end do
      end subroutine held_rows
   end subroutine assemble

   !> The force of an end that depends on its own state, added to f (the time-only applied
   !> force of its node), and its derivative with respect to the node's (new) position: the
   !> statics' state_force at rest at x (dynamic false, t the time), or a step's step_force
   !> from x0 at t to x over dt.
   subroutine add_end_state(end, dynamic, t, dt, x0, x, f, jac)
      !> The end (state_dependent).
      class(end_condition), intent(in) :: end
      !> A step (or the statics).
      logical, intent(in) :: dynamic
      !> Time (the step's start), s; the step, s.
      real(dp), intent(in) :: t, dt
      !> The node's old (a step) and new position (x, z), m.
      real(dp), intent(in) :: x0(2), x(2)
      !> Force on the node, N: the end's force is added.
      real(dp), intent(inout) :: f(2)
      !> d (end's force) / d x, N/m.
      real(dp), intent(out) :: jac(2, 2)
      real(dp) :: f3(3), j3(3, 3), dv(3, 3), damp(3)
      if (dynamic) then
         call end%step_force(t, dt, point3(x0), point3(x), f3, j3, damp)
      else
         call end%state_force(t, point3(x), [0.0_dp, 0.0_dp, 0.0_dp], f3, j3, dv, damp)
      end if
      f = f + f3([1, 3])
      jac = j3([1, 3], [1, 3])
   end subroutine add_end_state

   !> -jac times the row scale on the 2x2 diagonal block of the rows and columns off + 1, off + 2
   !> (an end node's: its rows hold -F).
   subroutine add_end_block(jacobian, off, jac, scale)
      !> Jacobian, band storage.
      type(band_matrix), intent(inout) :: jacobian
      !> Unknowns before the block.
      integer, intent(in) :: off
      !> d F / d x of the end, N/m.
      real(dp), intent(in) :: jac(2, 2)
      !> Row scale.
      real(dp), intent(in) :: scale
      integer :: a, b, band0
      band0 = jacobian%kl + jacobian%ku + 1
      do b = 1, 2
         do a = 1, 2
            jacobian%ab(band0 + a - b, off + b) = jacobian%ab(band0 + a - b, off + b) - jac(a, b)*scale
         end do
      end do
   end subroutine add_end_block

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
