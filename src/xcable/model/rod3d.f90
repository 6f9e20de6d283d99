!> The energy-conserving discrete rod in three dimensions, with torsion
!> (docs/theory/model3d.md). It lifts the planar rod of model/rod.f90 so that a
!> planar motion gives the planar rod's numbers to round-off.
!>
!> Unknowns per node k: the position R_k = (x, y, z), z up, and the material
!> rotation angle psi_k of the cross-section about the tangent. Cell c (nodes
!> c, c+1) carries the stretch vector e_c = (R_c+1 - R_c) / ds_c, the strain
!> |e_c| - 1 with its tension f, and the twist rate tau_c = (psi_c+1 -
!> psi_c) / ds_c (the Darboux component Omega1 per unstretched length); an
!> interior node carries the turning angle th_k in [0, pi) between its two
!> cells (atan2(|a x b|, a . b), a = e_k-1, b = e_k). The stored energy is
!>
!>     U = sum_c ds_c [W(eps_c) + GIp tau_c^2 / 2] + sum_k 2 EI tan^2(th_k / 2) / h_k + sum_k w_k z_k,
!>
!> isotropic bending (EI about both axes: 2 tan(th/2) / h is the length of
!> the discrete curvature vector, binormal over h) and torsion GIp. Without
!> rotary inertia the moment about the tangent is the same in every cell,
!> GIp tau = M_t, the torque applied at a loaded end: the twist rows are
!> solved at the new level of each step (quasi-static). The twist is not
!> coupled to the centreline here (the reference twist of a curved, moving
!> centreline is left out), so a torque sets a uniform twist rate and moves
!> nothing else; the energy ledger books its work by the trapezoid rule,
!> which is exact for these rows.
!>
!> The material frame of cell c is a unit quaternion (Euler parameters
!> beta0..beta3, rotating the fixed frame onto t, n, b): (x, -z, y) turned
!> about z onto the vertical plane of e_1, the minimal rotation onto e_1,
!> carried from cell to cell by the minimal rotation between consecutive
!> cells (parallel transport), then turned about
!> the tangent by the cell's mean psi. frames() gives them; their norm is not
!> re-imposed, so |beta| - 1 measures the drift.
!>
!> Time stepping as in the planar rod: R^n+1 - R^n = dt [(1 - theta) V^n +
!> theta V^n+1] and M (V^n+1 - V^n) / dt = -grad U(R^n, R^n+1) + F, with the
!> same mass matrix for each component. The discrete gradient of the strain
!> part is the planar one in vector form. The bending part of node k is
!> mom_k grad th_k, mom_k the divided difference of B between th_k^n and
!> th_k^n+1 and grad th_k a discrete gradient of the turning angle, exact in
!> the change of th_k (model/rod3d/kernels.f90 gives its formula). So the
!> energy changes by exactly the work of the ends, and a planar run
!> reproduces the planar rod as long as no turning angle passes through zero
!> within a step (the planar rod's angle is signed, this one is not). The
!> Jacobian is written out, the bending blocks of a step included
!> (node_bending_jacobian: first and second derivatives of the rotation
!> vector); the statics' bending blocks use forward-mode dual numbers
!> (defined in rod3d/statics.f90).
!>
!> Newton's vector holds the positions node after node (x, y, z), then the
!> twist angles psi_1 .. psi_n. The momentum rows of node k reach nodes k-2 ..
!> k+2, so kl = ku = 3 * 3 - 1 = 8, the narrowest band node-after-node
!> positions allow; the twist block, uncoupled from the positions, is
!> tridiagonal (interleaving psi with the positions would make the band 11,
!> and will be needed once the twist is coupled to the centreline). A held end's
!> rows are R = X(t) and psi = 0 (the twist held); a loaded end adds its
!> force, torque and point mass. When no end is held psi_1 = psi_anchor (0,
!> or a cut piece's angle at the cut) fixes the rigid spin. Distributed
!> loads (fluid) enter as in the planar rod, through their 3-D form
!> (loads/load.f90 cell_force3). An end couple acts about its end's couple axis (-y, as in the planar input, unless the end says
!> otherwise: the new ends of a break inside the cable), on the angle of the
!> end cell's projection on the plane normal to the axis.
!>
!> This file holds the piece's types, its geometry and mass helpers and the time step (the
!> cells' forces, the loop over the nodes' bending). gfortran 12 inlines and specialises small
!> kernels only as private procedures of their module or internal procedures (a submodule's
!> procedures and public ones are global symbols, which fpm's -fPIC keeps whole;
!> docs/dev/model-interface.md), so the hot parts are cut along those lines: the node's
!> bending in a step is the module model/rod3d/kernels.f90 (one call per node, its helpers
!> private there), the assembly of the node rows the submodule model/rod3d/assembly.f90 (its
!> helpers internal procedures). The other submodules in model/rod3d/ hold the cold parts:
!> init.f90 (the set-up), statics.f90 (the static system and its dual numbers), loads.f90 (the
!> distributed loads and the end couples), records.f90 (energies, twist rates, the reaction),
!> frames.f90 (the material frames, Euler parameters) and checks.f90 (Newton's trust in its
!> estimate, the fold check).
module xcable_model_rod3d
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_cell_force
   use xcable_model_rod3d_kernels, only: node_bending, node_bending_jacobian, rotation_vector, bend_energy_of, &
                                         bend_moment_of, small_rotation
   use xcable_solver_banded, only: band_matrix
   use xcable_ends_end_condition, only: end_condition
   use xcable_solver_newton, only: newton_problem
   use xcable_loads_load, only: load_slot, cell_kinematics, any_skew
   use xcable_loads_point, only: point_body
   use xcable_numerics_vector3, only: outer3, identity3, cross3
   implicit none
   private
   public :: rod3d_piece, rod3d_section, rod3d_problem, rod3d_kl, rod3d_ku, rod3d_nodal, rod3d_unknown_names, turning_angle
   public :: paper_euler_parameters, couple_plane, bend_energy, bend_moment, small_strain_step
   ! For the submodules in model/rod3d/ (the wrappers at the end; the assembly, of assembly.f90).
   public :: rod3d_unpack, rod3d_node_weight, rod3d_assemble

   !> The unknowns of a node: positions at 3 (k - 1) + 1..3, psi at 3 n + k.
   character(len=*), parameter :: rod3d_unknown_names(4) = [character(len=3) :: 'x', 'y', 'z', 'psi']
   !> Unknowns per node.
   integer, parameter :: rod3d_nodal = size(rod3d_unknown_names)
   !> Band widths of the Jacobian: the momentum rows reach two nodes either side (3 * 3 - 1); the twist
   !> block, after all the positions, is tridiagonal.
   integer, parameter :: rod3d_kl = 3*3 - 1, rod3d_ku = rod3d_kl
   !> Strain differences below this use the Taylor form of the divided difference.
   real(dp), parameter :: small_strain_step = 1.0e-6_dp

   !> One section of a 3-D piece on a line of segments: its cells (piece-local) and its material.
   type :: rod3d_section
      !> First and last cell.
      integer :: first = 1, last = 0
      !> Tension-strain law.
      class(material_law), allocatable :: law
      !> Mass and weight per unstretched length, kg/m and N/m; EI and GIp, N m^2; damping c, N s.
      real(dp) :: mass = 0, weight = 0, ei = 0, gip = 0, damping = 0
   end type rod3d_section

   !> One piece of cable between two ends, in 3-D.
   type :: rod3d_piece
      !> Number of nodes.
      integer :: n = 0
      !> Node arc lengths, cell lengths, the length attributed to each node, and h_k (0 at the ends), m.
      real(dp), allocatable :: s(:), ds(:), lumped(:), dual_length(:)
      !> Mass (kg/m) and weight (N/m) per unstretched length, EI and GIp (N m^2), gravity (m/s^2).
      real(dp) :: mass_per_length = 0, weight = 0, ei = 0, gip = 0, gravity = 0
      !> Kelvin-Voigt damping c, N s; share of the averaged mass matrix; second-difference weight.
      real(dp) :: damping = 0, mu = 1, mu2 = 0
      !> Tension-strain law.
      class(material_law), allocatable :: law
      !> Ends at node 1 and node n.
      class(end_condition), allocatable :: end_a, end_b
      !> Row scale of the momentum rows (N), position scale (m).
      real(dp) :: tension_ref = 1, length_ref = 1
      !> Old level: positions, velocities, M V (3, n), cell vectors (3, n - 1), lengths, turning angles.
      real(dp), allocatable :: r0(:, :), v0(:, :), mv0(:, :), e0(:, :), l0(:), th0(:)
      !> Old level: rotation vectors phi(e0_k-1, e0_k) of the interior nodes' turnings (3, n).
      real(dp), allocatable :: phi_old(:, :)
      !> New level: cell vectors, lengths, turning angles, cell forces (3, n - 1), work (3, n), velocities.
      !> A step evaluation sets th1 only when it does not form the Jacobian (Newton's last residual
      !> and the ledger's evaluation are such); the bending in a step does not use it.
      real(dp), allocatable :: e1(:, :), l1(:), th1(:), force(:, :), force_node(:, :), v1(:, :)
      !> dN_c/de_c' for c' = c-1, c, c+1 (3, 3, -1:1, n - 1).
      real(dp), allocatable :: block(:, :, :, :)
      !> Mass matrix, mass(j, k) = M(k, k+j), kg.
      real(dp), allocatable :: mass(:, :)
      !> Distributed loads (set by set_loads; none when not allocated or empty).
      type(load_slot), allocatable :: loads(:)
      !> Force of the loads on each node in the last evaluation (3, n), N, and the derivatives of
      !> each cell's load force with respect to the new positions of its nodes (3, 3, 0:1, n - 1).
      real(dp), allocatable :: load_node(:, :), load_block(:, :, :, :)
      !> Of loads that share unequally (cable_load cell_skew): whether there is one, and the
      !> derivatives of each cell's unequal part G_c = ds g (node c takes +G_c, node c + 1 -G_c).
      logical :: skewed = .false.
      real(dp), allocatable :: skew_block(:, :, :, :)
      !> Factor on the distributed loads.
      real(dp) :: load_factor = 1
      !> The twist angle psi_1 is held at when no end holds the twist (the rigid spin), rad: 0, or
      !> for a piece cut from a twisted cable its first node's angle at the cut.
      real(dp) :: psi_anchor = 0
      !> A line of segments (set_sections; not allocated: one uniform material, the scalars
      !> mass_per_length, weight, ei, gip, damping and law above, which then are the first
      !> section's): the sections, the section of each cell, per node its weight (N) and EI (N
      !> m^2: the mean of its two cells' weighted by their lengths), and per cell its GIp (N m^2).
      type(rod3d_section), allocatable :: sections(:)
      integer, allocatable :: cell_sec(:)
      real(dp), allocatable :: node_w(:), node_ei(:), cell_gip(:)
      !> Bodies at nodes (clump weights, buoys: set_points; not allocated: none), the node of
      !> each, and the derivative of each one's drag in the last evaluation, N/m.
      type(point_body), allocatable :: points(:)
      integer, allocatable :: point_node(:)
      real(dp), allocatable :: point_jac(:, :, :)
      !> Held ends whose momentum rows are kept (a line's end at a free point of a network,
      !> driver/network.f90): keep_rows(side), and of the last evaluation the end node's momentum
      !> residual (3, side; scaled by 1 / tension_ref, as the rows it replaces) and its Jacobian
      !> rows, kept_jac(a, j, side) the derivative of row a with respect to unknown kept_first(side)
      !> - 1 + j (the positions of the end node and of its two neighbours: j = 1 .. 9).
      logical :: keep_rows(2) = .false.
      real(dp) :: kept_residual(3, 2) = 0, kept_jac(3, 9, 2) = 0
      integer :: kept_first(2) = 1
   contains
      !> A line of segments: the sections' cells and materials.
      procedure :: set_sections => rod3d_set_sections
      !> Bodies at the joints (after set_sections).
      procedure :: set_points => rod3d_set_points
      !> The tension of cell c at a strain, N.
      procedure :: cell_tension => rod3d_cell_tension
      !> Whether the law of any cell has a kink (a rope that cannot push).
      procedure :: has_kink => rod3d_has_kink
      !> EI of node k, N m^2.
      procedure :: ei_at => rod3d_ei_at
      !> GIp of cell c, N m^2.
      procedure :: gip_at => rod3d_gip_at
      !> Set the distributed loads; error for a load without a 3-D form.
      procedure :: set_loads => rod3d_set_loads
      !> Set up grid, material and work arrays.
      procedure :: init => rod3d_init
      !> Number of unknowns.
      procedure :: unknowns => rod3d_unknowns
      !> Cell vectors, lengths and turning angles of positions R (3, n).
      procedure :: geometry => rod3d_geometry
      !> How far each node's change of turning in a step is from its cells' rotations (the fold check).
      procedure :: turning_folds => rod3d_turning_folds
      !> Strain, kinetic, bending, gravity and twist energy, J.
      procedure :: energies => rod3d_energies
      !> M V.
      procedure :: mass_times => rod3d_mass_times
      !> Residual and Jacobian of the static equilibrium at time t.
      procedure :: static_system => rod3d_static_system
      !> Store the old level of a time step.
      procedure :: prepare_step => rod3d_prepare_step
      !> Residual and Jacobian of a time step.
      procedure :: step_system => rod3d_step_system
      !> New velocities from new positions.
      procedure :: new_velocity => rod3d_new_velocity
      !> Material frames of the cells as unit quaternions.
      procedure :: frames => rod3d_frames
      !> The external force a held end node needs, after an evaluation at the state.
      procedure :: reaction => rod3d_reaction
      !> Net torque about the tangent carried by the piece (GIp tau of the first cell), N m.
      procedure :: twist_rates => rod3d_twist_rates
   end type rod3d_piece

   !> The nonlinear system of one piece: statics at t0 (dt = 0) or the step from t0 to t0 + dt.
   type, extends(newton_problem) :: rod3d_problem
      !> The piece.
      type(rod3d_piece) :: piece
      !> Step (0: statics), old time, time weight.
      real(dp) :: dt = 0, t0 = 0, theta = 0.5_dp
   contains
      procedure :: evaluate => rod3d_problem_evaluate
      !> Newton's contraction estimate only where no cell can have crossed the kink.
      procedure :: estimate_trusted => rod3d_problem_estimate_trusted
   end type rod3d_problem

   ! Procedures of the submodules in model/rod3d/ (see the file head).
   interface
      !> Set up a piece on the node arc lengths s; error for what the 3-D rod does not have yet.
      module subroutine rod3d_init(self, s, mass, weight, ei, gip, gravity, mu, law, end_a, end_b, tension_ref, error, mu2, damping)
         !> Piece.
         class(rod3d_piece), intent(inout) :: self
         !> Node arc lengths, increasing, m.
         real(dp), intent(in) :: s(:)
         !> Mass (kg/m), weight (N/m), EI and GIp (N m^2), gravity (m/s^2).
         real(dp), intent(in) :: mass, weight, ei, gip, gravity
         !> Share of the averaged mass matrix, 0 to 1.
         real(dp), intent(in) :: mu
         !> Tension-strain law.
         class(material_law), intent(in) :: law
         !> Ends at s(1) and s(n).
         class(end_condition), intent(in) :: end_a, end_b
         !> Reference tension of the row scaling, N.
         real(dp), intent(in) :: tension_ref
         !> Error: GIp <= 0.
         type(error_type), allocatable, intent(out) :: error
         !> Weight of the second-difference kinetic energy; Kelvin-Voigt damping c, N s (0 if absent).
         real(dp), intent(in), optional :: mu2, damping
      end subroutine rod3d_init

      !> A line of segments: section j holds the cells last(j - 1) + 1 .. last(j) with the law,
      !> mass (kg/m), weight (N/m), EI and GIp (N m^2) and damping (N s) of sections(j). The
      !> piece keeps the grid and ends of init; the mass matrix is rebuilt with each cell's mass
      !> (as the planar rod's set_sections), the scalars become the first section's.
      module subroutine rod3d_set_sections(self, last, sections)
         !> Piece.
         class(rod3d_piece), intent(inout) :: self
         !> Last cell of each section (the last one n - 1).
         integer, intent(in) :: last(:)
         !> The sections' materials (their first and last are set here).
         type(rod3d_section), intent(in) :: sections(:)
      end subroutine rod3d_set_sections

      !> Residual (and Jacobian) of the static equilibrium at time t: the exact gradient of U.
      module subroutine rod3d_static_system(self, x, t, residual, jacobian, with_jacobian)
         !> Piece.
         class(rod3d_piece), intent(inout) :: self
         !> Unknowns, 4 per node.
         real(dp), intent(in) :: x(:)
         !> Time of the loads and held positions, s.
         real(dp), intent(in) :: t
         !> Scaled residual.
         real(dp), intent(out) :: residual(:)
         !> Jacobian (band storage).
         type(band_matrix), intent(inout) :: jacobian
         !> Whether to form the Jacobian.
         logical, intent(in) :: with_jacobian
      end subroutine rod3d_static_system

      !> Bodies at nodes (after set_sections): each on the node at its arc length, if the piece
      !> has one there; its inertia in the mass matrix, its weight in the node's, its drag a load.
      module subroutine rod3d_set_points(self, points)
         !> Piece.
         class(rod3d_piece), intent(inout) :: self
         !> The line's bodies.
         type(point_body), intent(in) :: points(:)
      end subroutine rod3d_set_points

      !> Set the distributed loads (their lift must already be off the weight given to init).
      module subroutine rod3d_set_loads(self, loads, error)
         !> Piece.
         class(rod3d_piece), intent(inout) :: self
         !> Loads.
         type(load_slot), intent(in) :: loads(:)
         !> Error for a load without a 3-D form.
         type(error_type), allocatable, intent(out) :: error
      end subroutine rod3d_set_loads

      !> The distributed loads at x on the nodes (load_node) and, with the Jacobian, their blocks
      !> (more in rod3d/loads.f90).
      module subroutine apply_loads(self, x, dt, theta, with_jacobian)
         class(rod3d_piece), intent(inout) :: self
         real(dp), intent(in) :: x(:)
         real(dp), intent(in) :: dt, theta
         logical, intent(in) :: with_jacobian
      end subroutine apply_loads

      !> The applied couples of the ends on the end cells, on the cell forces and blocks: in statics
      !> at ta, in a step averaged over ta and tb (more in rod3d/loads.f90).
      module subroutine add_couples(self, ta, tb, step, with_jacobian)
         class(rod3d_piece), intent(inout) :: self
         real(dp), intent(in) :: ta, tb
         logical, intent(in) :: step, with_jacobian
      end subroutine add_couples

      !> An orthonormal basis (u, w) of the plane normal to the unit axis a, with
      !> u x w = a: u the unit projection of x on the plane (of z when a is near
      !> x). For a = -y it is (x, z) exactly, the planar couple's plane.
      module pure function couple_plane(axis) result(basis)
         !> Unit axis.
         real(dp), intent(in) :: axis(3)
         real(dp) :: basis(3, 2)
      end function couple_plane

      !> Energies of a state: strain, kinetic, bending, gravity, twist (J).
      module function rod3d_energies(self, x, v) result(en)
         !> Piece.
         class(rod3d_piece), intent(in) :: self
         !> Unknowns (4 per node) and velocities (3, n).
         real(dp), intent(in) :: x(:), v(:, :)
         real(dp) :: en(5)
      end function rod3d_energies

      !> Twist rate tau_c = Omega1 of each cell of x (n - 1), 1/m.
      module pure function rod3d_twist_rates(self, x) result(tau)
         !> Piece.
         class(rod3d_piece), intent(in) :: self
         !> Unknowns, 4 per node.
         real(dp), intent(in) :: x(:)
         real(dp) :: tau(self%n - 1)
      end function rod3d_twist_rates

      !> The force the support exerts on end node k (1 or n) to keep its balance, after an
      !> evaluation at the state (statics: dt = 0).
      module function rod3d_reaction(self, k, dt) result(f)
         !> Piece.
         class(rod3d_piece), intent(in) :: self
         !> End node, 1 or n.
         integer, intent(in) :: k
         !> Step of the evaluation (0: statics).
         real(dp), intent(in) :: dt
         real(dp) :: f(3)
      end function rod3d_reaction

      !> Material frames of the cells of x as unit quaternions (4, n - 1), [beta0, beta1, beta2, beta3]:
      !> the rotation of the fixed frame (x, y, z) onto (t, n, b) of each cell (more in
      !> rod3d/frames.f90).
      module pure subroutine rod3d_frames(self, x, beta)
         !> Piece.
         class(rod3d_piece), intent(in) :: self
         !> Unknowns, 4 per node.
         real(dp), intent(in) :: x(:)
         !> Quaternions (4, n - 1).
         real(dp), intent(out) :: beta(:, :)
      end subroutine rod3d_frames

      !> The paper's Euler parameters of a frame given as frames() gives it: the rotation of the
      !> paper's fixed frame (i up, j horizontal, k = i x j, that is (z, x, y)) onto (t, n, b),
      !> in components along i, j, k. In a planar state beta1 = beta2 = 0 and
      !> t = (beta0^2 - beta3^2) i + 2 beta0 beta3 j, as in eqs. 18-21.
      module pure function paper_euler_parameters(beta) result(b)
         !> Quaternion of frames() (rotation of (x, y, z) onto (t, n, b)).
         real(dp), intent(in) :: beta(4)
         real(dp) :: b(4)
      end function paper_euler_parameters
      !> Newton's contraction estimate (newton_problem) after the update from the last evaluated
      !> point: trusted unless it may have carried a cell past the kink of the law by more than
      !> the tolerance (may_cross_kink); in model/rod3d/checks.f90.
      module function rod3d_problem_estimate_trusted(self, update, tolerance) result(trusted)
         !> Problem.
         class(rod3d_problem), intent(in) :: self
         !> The update: 3 positions per node, then the twists, m and rad.
         real(dp), intent(in) :: update(:)
         !> Tolerance on the scaled update (scale of the positions: length_ref).
         real(dp), intent(in) :: tolerance
         logical :: trusted
      end function rod3d_problem_estimate_trusted

      !> Whether the law of any cell has a kink (strain_slack: a rope that cannot push).
      module pure function rod3d_has_kink(self) result(kink)
         !> Piece.
         class(rod3d_piece), intent(in) :: self
         logical :: kink
      end function rod3d_has_kink

      !> The fold check of the step control in 3-D (driver/rod_run.f90, check_folds): the
      !> mismatch of each node's turning against its cells' rotations in the step.
      module pure subroutine rod3d_turning_folds(self, r1, fold)
         !> Piece (holds the old level).
         class(rod3d_piece), intent(in) :: self
         !> New positions (3, n), m.
         real(dp), intent(in) :: r1(:, :)
         !> Mismatch at each node (n; 0 at the ends), rad.
         real(dp), intent(out) :: fold(:)
      end subroutine rod3d_turning_folds

      !> Node rows from the cell forces and blocks, inertia, weight, end forces, twist and held rows
      !> (statics: t1 the time; a step: t1 = t0, t2 = dt), in model/rod3d/assembly.f90.
      module subroutine rod3d_assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
         !> Piece.
         class(rod3d_piece), intent(inout) :: self
         !> Unknowns, 4 per node.
         real(dp), intent(in) :: x(:)
         !> Statics: t1 the time; a step: t1 = t0, t2 = dt.
         real(dp), intent(in) :: t1, t2
         !> Scaled residual.
         real(dp), intent(out) :: residual(:)
         !> Jacobian (band storage).
         type(band_matrix), intent(inout) :: jacobian
         !> Whether to form the Jacobian; whether a step.
         logical, intent(in) :: with_jacobian, dynamic
         !> Time weight.
         real(dp), intent(in) :: theta
      end subroutine rod3d_assemble
   end interface

contains

   !> Residual and Jacobian (newton_problem interface).
   subroutine rod3d_problem_evaluate(self, x, residual, jacobian, with_jacobian)
      !> Problem.
      class(rod3d_problem), intent(inout) :: self
      !> Unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian in band storage.
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form it.
      logical, intent(in) :: with_jacobian
      if (self%dt > 0) then
         call self%piece%step_system(x, self%t0, self%dt, self%theta, residual, jacobian, with_jacobian)
      else
         call self%piece%static_system(x, self%t0, residual, jacobian, with_jacobian)
      end if
   end subroutine rod3d_problem_evaluate

   !> Number of unknowns (four per node).
   pure integer function rod3d_unknowns(self)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      rod3d_unknowns = rod3d_nodal*self%n
   end function rod3d_unknowns

   !> Positions (3, n) and angles psi (n) of Newton's vector.
   pure subroutine unpack(x, r, psi)
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: r(:, :), psi(:)
      integer :: k
      do k = 1, size(psi)
         r(:, k) = x(3*k - 2:3*k)
         psi(k) = x(3*size(psi) + k)
      end do
   end subroutine unpack

   !> Turning angle in [0, pi] between a and b.
   pure real(dp) function turning_angle(a, b) result(th)
      !> Cell vectors.
      real(dp), intent(in) :: a(3), b(3)
      real(dp) :: w(3)
      w = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
      th = atan2(norm2(w), dot_product(a, b))
   end function turning_angle

   !> Bending energy 2 EI tan^2(th / 2) / h_k of interior node k, J.
   pure real(dp) function bend_energy(self, k, th)
      class(rod3d_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_energy = bend_energy_of(self%ei_at(k), self%dual_length(k), th)
   end function bend_energy

   !> dB/dth, N m.
   pure real(dp) function bend_moment(self, k, th)
      class(rod3d_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_moment = bend_moment_of(self%ei_at(k), self%dual_length(k), th)
   end function bend_moment

   !> EI of node k, N m^2 (a line of segments: the length-weighted mean of its cells').
   pure real(dp) function rod3d_ei_at(self, k) result(ei)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Node.
      integer, intent(in) :: k
      if (allocated(self%node_ei)) then
         ei = self%node_ei(k)
      else
         ei = self%ei
      end if
   end function rod3d_ei_at

   !> GIp of cell c, N m^2 (a line of segments: its section's).
   pure real(dp) function rod3d_gip_at(self, c) result(gip)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Cell.
      integer, intent(in) :: c
      if (allocated(self%cell_gip)) then
         gip = self%cell_gip(c)
      else
         gip = self%gip
      end if
   end function rod3d_gip_at

   !> The tension of cell c at a strain (its section's law), N.
   pure real(dp) function rod3d_cell_tension(self, c, strain) result(tension)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Cell.
      integer, intent(in) :: c
      !> Strain.
      real(dp), intent(in) :: strain
      if (allocated(self%sections)) then
         tension = self%sections(self%cell_sec(c))%law%tension(strain)
      else
         tension = self%law%tension(strain)
      end if
   end function rod3d_cell_tension

   !> Cell vectors e_c, their lengths and the turning angles of the interior nodes.
   pure subroutine rod3d_geometry(self, r, e, l, th)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Positions (3, n), m.
      real(dp), intent(in) :: r(:, :)
      !> Cell vectors (3, n - 1), lengths (n - 1), turning angles (n; 0 at the ends).
      real(dp), intent(out) :: e(:, :), l(:), th(:)
      integer :: c, k
      do c = 1, self%n - 1
         e(:, c) = (r(:, c + 1) - r(:, c))/self%ds(c)
         l(c) = norm2(e(:, c))
      end do
      th = 0
      do k = 2, self%n - 1
         th(k) = turning_angle(e(:, k - 1), e(:, k))
      end do
   end subroutine rod3d_geometry

   !> Cell vectors e_c = (R_c+1 - R_c) / ds_c and their lengths (the geometry without the
   !> turning angles), on explicit-shape arrays.
   pure subroutine cell_vectors(n, r, ds, e, l)
      integer, intent(in) :: n
      real(dp), intent(in) :: r(3, n), ds(n - 1)
      real(dp), intent(out) :: e(3, n - 1), l(n - 1)
      integer :: c
      do c = 1, n - 1
         e(:, c) = (r(:, c + 1) - r(:, c))/ds(c)
         l(c) = norm2(e(:, c))
      end do
   end subroutine cell_vectors

   !> a = 0 for a contiguous array of m values.
   pure subroutine clear(m, a)
      integer, intent(in) :: m
      real(dp), intent(out) :: a(m)
      a = 0
   end subroutine clear

   !> Weight of node k (cable share and point mass), N, on a line of segments too.
   pure real(dp) function any_node_weight(self, k)
      class(rod3d_piece), intent(in) :: self
      integer, intent(in) :: k
      if (allocated(self%node_w)) then
         any_node_weight = section_node_weight(self, k)
      else
         any_node_weight = node_weight(self, k)
      end if
   end function any_node_weight

   !> Weight of node k of a line of segments (its cells' halves and point mass), N.
   pure real(dp) function section_node_weight(self, k)
      class(rod3d_piece), intent(in) :: self
      integer, intent(in) :: k
      section_node_weight = self%node_w(k)
      if (k == 1) section_node_weight = section_node_weight + self%gravity*self%end_a%point_mass()
      if (k == self%n) section_node_weight = section_node_weight + self%gravity*self%end_b%point_mass()
   end function section_node_weight

   !> Weight of node k of a uniform piece (cable share and point mass), N.
   pure real(dp) function node_weight(self, k)
      class(rod3d_piece), intent(in) :: self
      integer, intent(in) :: k
      node_weight = self%weight*self%lumped(k)
      if (k == 1) node_weight = node_weight + self%gravity*self%end_a%point_mass()
      if (k == self%n) node_weight = node_weight + self%gravity*self%end_b%point_mass()
   end function node_weight

   !> M V for velocities V (3, n).
   pure subroutine rod3d_mass_times(self, v, mv)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Velocities (3, n), m/s.
      real(dp), intent(in) :: v(:, :)
      !> M V (3, n), kg m/s.
      real(dp), intent(out) :: mv(:, :)
      integer :: k, j
      do k = 1, self%n
         mv(:, k) = self%mass(0, k)*v(:, k)
      end do
      do j = 1, 2
         do k = 1, self%n - j
            mv(:, k) = mv(:, k) + self%mass(j, k)*v(:, k + j)
            mv(:, k + j) = mv(:, k + j) + self%mass(j, k)*v(:, k)
         end do
      end do
   end subroutine rod3d_mass_times

   !> Store the old level (positions, velocities (3, n)) of a step.
   subroutine rod3d_prepare_step(self, r0, v0)
      !> Piece.
      class(rod3d_piece), intent(inout) :: self
      !> Positions and velocities at the old level (3, n).
      real(dp), intent(in) :: r0(:, :), v0(:, :)
      integer :: k
      self%r0 = r0
      self%v0 = v0
      call self%mass_times(v0, self%mv0)
      call self%geometry(r0, self%e0, self%l0, self%th0)
      do k = 2, self%n - 1
         call rotation_vector(self%e0(:, k - 1), self%e0(:, k), self%phi_old(:, k))
      end do
   end subroutine rod3d_prepare_step

   !> New velocities V^n+1 = [(R^n+1 - R^n)/dt - (1 - theta) V^n] / theta.
   pure subroutine rod3d_new_velocity(self, r1, dt, theta, v1)
      !> Piece (holds the old level).
      class(rod3d_piece), intent(in) :: self
      !> New positions (3, n), m.
      real(dp), intent(in) :: r1(:, :)
      !> Step (s) and time weight.
      real(dp), intent(in) :: dt, theta
      !> New velocities (3, n), m/s.
      real(dp), intent(out) :: v1(:, :)
      v1 = ((r1 - self%r0)/dt - (1 - theta)*self%v0)/theta
   end subroutine rod3d_new_velocity

   !> Residual and Jacobian of the step from t0 to t0 + dt (old level from prepare_step).
   subroutine rod3d_step_system(self, x, t0, dt, theta, residual, jacobian, with_jacobian)
      !> Piece.
      class(rod3d_piece), intent(inout) :: self
      !> New unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      !> Old time and step, s; time weight (1/2 conserves energy).
      real(dp), intent(in) :: t0, dt, theta
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian (band storage).
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form the Jacobian.
      logical, intent(in) :: with_jacobian
      integer :: n, k, j
      real(dp) :: r(3, self%n), psi(self%n)
      n = self%n
      call unpack(x, r, psi)
      call cell_vectors(n, r, self%ds, self%e1, self%l1)
      if (with_jacobian) then
         call clear(size(self%block), self%block)
      else
         ! Turning angles of the state (for the drivers' records), in the evaluations without the Jacobian.
         do k = 2, n - 1
            self%th1(k) = turning_angle(self%e1(:, k - 1), self%e1(:, k))
         end do
         self%th1(1) = 0
         self%th1(n) = 0
      end if
      if (allocated(self%sections)) then
         ! A line of segments: each section's cells with its law and damping.
         do j = 1, size(self%sections)
            call step_cells(self, self%sections(j)%law, self%sections(j)%damping, dt, with_jacobian, &
                            self%sections(j)%first, self%sections(j)%last)
         end do
         if (with_jacobian) then
            do k = 2, n - 1
               call step_bending_jacobian(self, k, self%node_ei(k))
            end do
         else
            do k = 2, n - 1
               call step_bending(self, k, self%node_ei(k))
            end do
         end if
      else
         call step_cells(self, self%law, self%damping, dt, with_jacobian, 1, n - 1)
         if (with_jacobian) then
            do k = 2, n - 1
               call step_bending_jacobian(self, k, self%ei)
            end do
         else
            do k = 2, n - 1
               call step_bending(self, k, self%ei)
            end do
         end if
      end if
      call add_couples(self, t0, t0 + dt, .true., with_jacobian)
      call apply_loads(self, x, dt, theta, with_jacobian)
      call rod3d_assemble(self, x, t0, dt, residual, jacobian, with_jacobian, .true., theta)
   end subroutine rod3d_step_system

   !> The cells c1 .. c2 of a step with the law and damping c (N s): their forces (the discrete
   !> gradient of the strain energy, and the damping) and, with the Jacobian, their blocks.
   subroutine step_cells(self, law, damping, dt, with_jacobian, c1, c2)
      class(rod3d_piece), intent(inout) :: self
      class(material_law), intent(in) :: law
      real(dp), intent(in) :: damping, dt
      logical, intent(in) :: with_jacobian
      integer, intent(in) :: c1, c2
      integer :: c, i, j
      real(dp) :: q, dq, lsum, eps0, eps1, h, mid, wsum(3), f, fp, fpp
      do c = c1, c2
         associate (e0 => self%e0(:, c), e1 => self%e1(:, c), l0 => self%l0(c), l1 => self%l1(c))
            eps0 = l0 - 1
            eps1 = l1 - 1
            h = eps1 - eps0
            if (law%strain_slack > -huge(1.0_dp)) then
               ! A rope that cannot push: q and dq with the damping on the taut part.
               call slack_cell_force(law, eps0, eps1, damping, dt, small_strain_step, q, dq)
            else if (abs(h) < small_strain_step) then
               mid = 0.5_dp*(eps0 + eps1)
               ! f, f', f'' at mid in one call (the tanh law: one tanh and one cosh, the same bits).
               call law%tension_stiffness_slope(mid, f, fp, fpp)
               q = f + fpp*h*h/24
               dq = 0.5_dp*fp + fpp*h/12
            else
               call law%strain_energy_change_tension(eps0, eps1, q, f)
               q = q/h
               dq = (f - q)/h
            end if
            if (.not. law%strain_slack > -huge(1.0_dp)) then
               q = q + damping*h/dt
               dq = dq + damping/dt
            end if
            lsum = l0 + l1
            wsum = e0 + e1
            self%force(:, c) = q*wsum/lsum
            if (with_jacobian) then
               ! outer(wsum / lsum, dq e1 / l1) + q (I / lsum - outer(wsum, e1 / l1) / lsum^2), written out.
               do j = 1, 3
                  do i = 1, 3
                     self%block(i, j, 0, c) = wsum(i)/lsum*(dq*e1(j)/l1) &
                                              + q*(merge(1.0_dp, 0.0_dp, i == j)/lsum - wsum(i)*(e1(j)/l1)/lsum**2)
                  end do
               end do
            end if
         end associate
      end do
   end subroutine step_cells

   !> Node k's bending force in a step, values only (node_bending, model/rod3d/kernels.f90; the
   !> step_bending_jacobian's forces to the same bits).
   subroutine step_bending(self, k, ei)
      class(rod3d_piece), intent(inout) :: self
      integer, intent(in) :: k
      !> The node's EI, N m^2.
      real(dp), intent(in) :: ei
      real(dp) :: fa(3), fb(3)
      call node_bending(self%e0(:, k - 1), self%e1(:, k - 1), self%e0(:, k), self%e1(:, k), self%phi_old(:, k), ei, &
                        self%dual_length(k), fa, fb)
      self%force(:, k - 1) = self%force(:, k - 1) + fa/self%ds(k - 1)
      self%force(:, k) = self%force(:, k) + fb/self%ds(k)
   end subroutine step_bending

   !> Node k's bending force in a step and its blocks (node_bending_jacobian, model/rod3d/kernels.f90).
   subroutine step_bending_jacobian(self, k, ei)
      class(rod3d_piece), intent(inout) :: self
      integer, intent(in) :: k
      !> The node's EI, N m^2.
      real(dp), intent(in) :: ei
      real(dp) :: fa(3), fb(3), dfa_da(3, 3), dfa_db(3, 3), dfb_db(3, 3), dfb_da(3, 3)
      call node_bending_jacobian(self%e0(:, k - 1), self%e1(:, k - 1), self%e0(:, k), self%e1(:, k), self%phi_old(:, k), &
                                 ei, self%dual_length(k), fa, fb, dfa_da, dfa_db, dfb_da, dfb_db)
      self%force(:, k - 1) = self%force(:, k - 1) + fa/self%ds(k - 1)
      self%force(:, k) = self%force(:, k) + fb/self%ds(k)
      self%block(:, :, 0, k - 1) = self%block(:, :, 0, k - 1) + dfa_da/self%ds(k - 1)
      self%block(:, :, 1, k - 1) = self%block(:, :, 1, k - 1) + dfa_db/self%ds(k - 1)
      self%block(:, :, -1, k) = self%block(:, :, -1, k) + dfb_da/self%ds(k)
      self%block(:, :, 0, k) = self%block(:, :, 0, k) + dfb_db/self%ds(k)
   end subroutine step_bending_jacobian

   ! ---- for the submodules in model/rod3d/ ----
   ! gfortran 12 makes a module's private procedures local symbols that its submodules cannot link
   ! to; making unpack and node_weight themselves public would keep the compiler from inlining
   ! and specialising them in the time step here (a global symbol may be interposed under fpm's
   ! -fPIC). So the submodules call these public wrappers.

   !> unpack, for the submodules.
   pure subroutine rod3d_unpack(x, r, psi)
      !> Unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      !> Positions (3, n) and twist angles (n).
      real(dp), intent(out) :: r(:, :), psi(:)
      call unpack(x, r, psi)
   end subroutine rod3d_unpack

   !> node_weight, for the submodules.
   pure real(dp) function rod3d_node_weight(self, k)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Node.
      integer, intent(in) :: k
      rod3d_node_weight = any_node_weight(self, k)
   end function rod3d_node_weight
end module xcable_model_rod3d
