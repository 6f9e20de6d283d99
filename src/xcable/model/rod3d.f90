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
!> th_k^n+1 and grad th_k a discrete gradient of the turning angle: the
!> change of th_k is split into the changes of a with b held (at b^n and at
!> b^n+1, averaged) and of b with a held, and each one-vector change of the
!> scale-free function g(x) = th(x, y) gets
!>
!>     D = grad g(x_mid) + [g(x1) - g(x0) - grad g(x_mid) . (x1 - x0)] (c x x_mid) / |c|^2,  c = x0 x x1,
!>
!> which satisfies D . (x1 - x0) = g(x1) - g(x0) exactly, tends to grad g as
!> the step shrinks and, in a plane, equals the planar rod's perp(x_mid)
!> dphi / (sin(dphi) |x0| |x1|). So the energy changes by exactly the work of
!> the ends, and a planar run reproduces the planar rod as long as no turning
!> angle passes through zero within a step (the planar rod's angle is signed,
!> this one is not). Below a rotation of 1e-8 rad in a step the bracket
!> (third order in the rotation) is dropped. The Jacobian is written out,
!> the bending blocks of a step included (step_bending_jacobian: first and
!> second derivatives of the rotation vector); the statics' bending blocks
!> use forward-mode dual numbers (defined in rod3d/statics.f90).
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
!> This file holds the piece's types, its geometry and mass helpers, the time step with the
!> discrete gradient of the bending, and the assembly of the node rows: the hot path of a 3-D run,
!> kept in one compilation unit because gfortran inlines and specialises its kernels only as
!> private procedures of the unit (in a submodule the step's kernels cost +1.2 %, the assembly
!> +1.8 % instructions on input/sway3d.nml). The submodules in model/rod3d/ hold the cold parts:
!> init.f90 (the set-up), statics.f90 (the static system and its dual numbers), loads.f90 (the
!> distributed loads and the end couples), records.f90 (energies, twist rates, the reaction) and
!> frames.f90 (the material frames, Euler parameters).
module xcable_model_rod3d
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_cell_force, may_cross_kink
   use xcable_numerics_tan, only: fast_tan
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
   ! For the submodules in model/rod3d/ (see the wrappers at the end).
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
   !> Turning-angle differences below this use the Taylor form of the divided difference.
   real(dp), parameter :: small_rotation = 1.0e-4_dp
   !> Cell rotations in a step below this drop the third-order bracket of the discrete gradient.
   real(dp), parameter :: bracket_rotation = 1.0e-8_dp

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

   !> Newton's contraction estimate (newton_problem) after the update from the last evaluated
   !> point: trusted unless it may have carried a cell past the kink of the law by more than
   !> the tolerance (may_cross_kink).
   logical function rod3d_problem_estimate_trusted(self, update, tolerance) result(trusted)
      !> Problem.
      class(rod3d_problem), intent(in) :: self
      !> The update: 3 positions per node, then the twists, m and rad.
      real(dp), intent(in) :: update(:)
      !> Tolerance on the scaled update (scale of the positions: length_ref).
      real(dp), intent(in) :: tolerance
      real(dp), allocatable :: du(:, :)
      integer :: j, a, b
      trusted = .true.
      if (.not. allocated(self%piece%sections)) then
         if (.not. self%piece%law%strain_slack > -huge(1.0_dp)) return
         trusted = .not. may_cross_kink(self%piece%law%strain_slack, self%piece%l1, self%piece%ds, &
                                        reshape(update(1:3*self%piece%n), [3, self%piece%n]), &
                                        tolerance*self%piece%length_ref)
         return
      end if
      ! A line of segments: each section whose law has a kink, on its own cells.
      if (.not. self%piece%has_kink()) return
      du = reshape(update(1:3*self%piece%n), [3, self%piece%n])
      do j = 1, size(self%piece%sections)
         a = self%piece%sections(j)%first
         b = self%piece%sections(j)%last
         if (.not. self%piece%sections(j)%law%strain_slack > -huge(1.0_dp)) cycle
         if (may_cross_kink(self%piece%sections(j)%law%strain_slack, self%piece%l1(a:b), self%piece%ds(a:b), &
                            du(:, a:b + 1), tolerance*self%piece%length_ref)) trusted = .false.
      end do
   end function rod3d_problem_estimate_trusted

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
      bend_energy = energy_of(self%ei_at(k), self%dual_length(k), th)
   end function bend_energy

   !> dB/dth, N m.
   pure real(dp) function bend_moment(self, k, th)
      class(rod3d_piece), intent(in) :: self
      integer, intent(in) :: k
      real(dp), intent(in) :: th
      bend_moment = moment_of(self%ei_at(k), self%dual_length(k), th)
   end function bend_moment

   !> 2 EI tan^2(th / 2) / h, J: bend_energy of a node of EI ei and length h.
   pure real(dp) function energy_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      energy_of = 2*ei*fast_tan(0.5_dp*th)**2/h
   end function energy_of

   !> dB/dth of a node of EI ei and length h, N m.
   pure real(dp) function moment_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      real(dp) :: t
      t = fast_tan(0.5_dp*th)
      moment_of = 2*ei*t*(1 + t*t)/h
   end function moment_of

   !> d2B/dth2 of a node of EI ei and length h, N m.
   pure real(dp) function stiffness_of(ei, h, th)
      real(dp), intent(in) :: ei, h, th
      real(dp) :: t
      t = fast_tan(0.5_dp*th)
      stiffness_of = ei*(1 + t*t)*(1 + 3*t*t)/h
   end function stiffness_of

   !> [B(th1) - B(th0)] / (th1 - th0) and its derivative in th1 (Taylor forms when close), of a
   !> node of EI ei and length hk.
   pure subroutine bend_divided(ei, hk, th0, th1, m, dm)
      real(dp), intent(in) :: ei, hk
      real(dp), intent(in) :: th0, th1
      real(dp), intent(out) :: m, dm
      real(dp) :: h, mid, t, third
      h = th1 - th0
      if (abs(h) < small_rotation) then
         mid = 0.5_dp*(th0 + th1)
         t = fast_tan(0.5_dp*mid)
         third = ei*(1 + t*t)*t*(4 + 6*t*t)/hk
         m = moment_of(ei, hk, mid) + third*h*h/24
         dm = 0.5_dp*stiffness_of(ei, hk, mid) + third*h/12
      else
         m = (energy_of(ei, hk, th1) - energy_of(ei, hk, th0))/h
         dm = (moment_of(ei, hk, th1) - m)/h
      end if
   end subroutine bend_divided

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

   !> Whether the law of any cell has a kink (strain_slack: a rope that cannot push).
   pure logical function rod3d_has_kink(self) result(kink)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      integer :: j
      kink = self%law%strain_slack > -huge(1.0_dp)
      if (.not. allocated(self%sections)) return
      do j = 1, size(self%sections)
         if (self%sections(j)%law%strain_slack > -huge(1.0_dp)) kink = .true.
      end do
   end function rod3d_has_kink

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

   !> The fold check of the step control (driver/rod_run.f90, check_folds) in
   !> 3-D: for each interior node k, |phi(e1_k-1, e1_k) - phi(e0_k-1, e0_k) -
   !> (rho_k - rho_k-1)|, with phi the rotation vector of the node's turning
   !> and rho_c that of cell c from the old level (prepare_step) to the
   !> positions r1. In a plane it is the planar rod's |th1 - th0 - (dphi_b -
   !> dphi_a)|: 0 to round-off, or about 2 pi when the angle went through half
   !> a turn. Out of the plane it is first order in the cells' rotations (a
   !> rotation omega of both cells adds |omega x phi|, at most pi |omega|,
   !> and near th = pi the axis of phi swings fast): it passes 3 rad when a
   !> turning angle goes through or close around half a turn, or a sharp bend
   !> turns by about 1 rad out of its plane in one step.
   pure subroutine rod3d_turning_folds(self, r1, fold)
      !> Piece (holds the old level).
      class(rod3d_piece), intent(in) :: self
      !> New positions (3, n), m.
      real(dp), intent(in) :: r1(:, :)
      !> Mismatch at each node (n; 0 at the ends), rad.
      real(dp), intent(out) :: fold(:)
      real(dp) :: e1(3, self%n - 1), rho(3, self%n - 1)
      integer :: c, k
      do c = 1, self%n - 1
         e1(:, c) = r1(:, c + 1) - r1(:, c)
         rho(:, c) = rotation(self%e0(:, c), e1(:, c))
      end do
      fold = 0
      do k = 2, self%n - 1
         fold(k) = norm2(rotation(e1(:, k - 1), e1(:, k)) - rotation(self%e0(:, k - 1), self%e0(:, k)) - &
                         (rho(:, k) - rho(:, k - 1)))
      end do

   contains

      !> The rotation vector phi(a, b) (rotation_vector_r).
      pure function rotation(a, b) result(phi)
         real(dp), intent(in) :: a(3), b(3)
         real(dp) :: phi(3)
         call rotation_vector_r(a, b, phi)
      end function rotation
   end subroutine rod3d_turning_folds

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
         call rotation_vector_r(self%e0(:, k - 1), self%e0(:, k), self%phi_old(:, k))
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
      call assemble(self, x, t0, dt, residual, jacobian, with_jacobian, .true., theta)
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

   !> Node k's bending force in a step, values only (the step_bending_jacobian's forces to the
   !> same bits): B1 - B0 = coef (phi1 + phi0) . (phi1 - phi0), phi1 - phi0 = Ja (a1 - a0) +
   !> Jb (b1 - b0), Ja carrying the mean of the changes of a at b0 and at b1, Jb that of the
   !> changes of b at a0 and at a1, each about the Jacobian at the mid vectors.
   subroutine step_bending(self, k, ei)
      class(rod3d_piece), intent(inout) :: self
      integer, intent(in) :: k
      !> The node's EI, N m^2.
      real(dp), intent(in) :: ei
      real(dp) :: a(3), b(3), a0(3), b0(3), phi0(3), phi1(3), phi_a1b0(3), phi_a0b1(3), q1, coef, psum(3)
      real(dp) :: ja(3, 3), jb(3, 3)
      integer :: i
      a = self%e1(:, k - 1)
      b = self%e1(:, k)
      a0 = self%e0(:, k - 1)
      b0 = self%e0(:, k)
      phi0 = self%phi_old(:, k)
      call rotation_vector_r(a, b, phi1)
      call rotation_vector_r(a, b0, phi_a1b0)
      call rotation_vector_r(a0, b, phi_a0b1)
      q1 = phi1(1)*phi1(1) + phi1(2)*phi1(2) + phi1(3)*phi1(3)
      coef = bend_coefficient_r(ei, self%dual_length(k), phi0(1)**2 + phi0(2)**2 + phi0(3)**2, q1)
      psum = (phi1 + phi0)*coef
      ! phi(a, b) = -phi(b, a): the changes in b are those of -phi(b, a).
      call discrete_jacobian_r(a0, a, (b0 + b)*0.5_dp, 1.0_dp, ((phi_a1b0 - phi0) + (phi1 - phi_a0b1))*0.5_dp, ja)
      call discrete_jacobian_r(b0, b, (a0 + a)*0.5_dp, -1.0_dp, ((phi_a0b1 - phi0) + (phi1 - phi_a1b0))*0.5_dp, jb)
      do i = 1, 3
         self%force(i, k - 1) = self%force(i, k - 1) + (ja(1, i)*psum(1) + ja(2, i)*psum(2) + ja(3, i)*psum(3)) &
                                /self%ds(k - 1)
         self%force(i, k) = self%force(i, k) + (jb(1, i)*psum(1) + jb(2, i)*psum(2) + jb(3, i)*psum(3))/self%ds(k)
      end do
   end subroutine step_bending

   !> Node k's bending force in a step and its blocks. The forces are step_bending's (the same
   !> operations, so the same bits); their derivatives with respect to the new a and b are written
   !> out: those of the rotation vectors (rotation_vector_r), of the bending coefficient, and of
   !> each discrete Jacobian's force J^T p (discrete_force_derivatives).
   subroutine step_bending_jacobian(self, k, ei)
      class(rod3d_piece), intent(inout) :: self
      integer, intent(in) :: k
      !> The node's EI, N m^2.
      real(dp), intent(in) :: ei
      real(dp) :: a(3), b(3), a0(3), b0(3), phi0(3), phi1(3), phi_a1b0(3), phi_a0b1(3), q1, q0, coef, dcoef, psum(3)
      real(dp) :: ja(3, 3), jb(3, 3), j1a(3, 3), j1b(3, 3), jab0(3, 3), ja0b(3, 3), dpa(3, 3), dpb(3, 3), dq(6)
      real(dp) :: ja_mid(3, 3), jb_mid(3, 3), delta_a(3), delta_b(3), dfa_da(3, 3), dfa_db(3, 3), dfb_db(3, 3), dfb_da(3, 3)
      integer :: i, j
      a = self%e1(:, k - 1)
      b = self%e1(:, k)
      a0 = self%e0(:, k - 1)
      b0 = self%e0(:, k)
      phi0 = self%phi_old(:, k)
      call rotation_vector_r(a, b, phi1, j1a, j1b)
      call rotation_vector_r(a, b0, phi_a1b0, jab0)
      call rotation_vector_r(a0, b, phi_a0b1, jy=ja0b)
      q1 = phi1(1)*phi1(1) + phi1(2)*phi1(2) + phi1(3)*phi1(3)
      q0 = phi0(1)**2 + phi0(2)**2 + phi0(3)**2
      call bend_coefficient_derivative(ei, self%dual_length(k), q0, q1, coef, dcoef)
      psum = (phi1 + phi0)*coef
      delta_a = ((phi_a1b0 - phi0) + (phi1 - phi_a0b1))*0.5_dp
      delta_b = ((phi_a0b1 - phi0) + (phi1 - phi_a1b0))*0.5_dp
      call discrete_jacobian_r(a0, a, (b0 + b)*0.5_dp, 1.0_dp, delta_a, ja, ja_mid)
      call discrete_jacobian_r(b0, b, (a0 + a)*0.5_dp, -1.0_dp, delta_b, jb, jb_mid)
      do i = 1, 3
         self%force(i, k - 1) = self%force(i, k - 1) + (ja(1, i)*psum(1) + ja(2, i)*psum(2) + ja(3, i)*psum(3)) &
                                /self%ds(k - 1)
         self%force(i, k) = self%force(i, k) + (jb(1, i)*psum(1) + jb(2, i)*psum(2) + jb(3, i)*psum(3))/self%ds(k)
      end do
      ! d psum = coef d phi1 + (phi1 + phi0) coef'(q1) 2 phi1^T d phi1.
      do j = 1, 3
         dq(j) = 2*dcoef*(phi1(1)*j1a(1, j) + phi1(2)*j1a(2, j) + phi1(3)*j1a(3, j))
         dq(j + 3) = 2*dcoef*(phi1(1)*j1b(1, j) + phi1(2)*j1b(2, j) + phi1(3)*j1b(3, j))
      end do
      do j = 1, 3
         dpa(:, j) = coef*j1a(:, j) + (phi1 + phi0)*dq(j)
         dpb(:, j) = coef*j1b(:, j) + (phi1 + phi0)*dq(j + 3)
      end do
      call discrete_force_derivatives(a0, a, b0, b, 1.0_dp, ja_mid, delta_a, 0.5_dp*(jab0 + j1a), 0.5_dp*(j1b - ja0b), &
                                      psum, dpa, dpb, dfa_da, dfa_db)
      call discrete_force_derivatives(b0, b, a0, a, -1.0_dp, jb_mid, delta_b, 0.5_dp*(ja0b + j1b), 0.5_dp*(j1a - jab0), &
                                      psum, dpb, dpa, dfb_db, dfb_da)
      self%block(:, :, 0, k - 1) = self%block(:, :, 0, k - 1) + dfa_da/self%ds(k - 1)
      self%block(:, :, 1, k - 1) = self%block(:, :, 1, k - 1) + dfa_db/self%ds(k - 1)
      self%block(:, :, -1, k) = self%block(:, :, -1, k) + dfb_da/self%ds(k)
      self%block(:, :, 0, k) = self%block(:, :, 0, k) + dfb_db/self%ds(k)
   end subroutine step_bending_jacobian

   !> bend_coefficient_r (the same operations) and its derivative in q1.
   pure subroutine bend_coefficient_derivative(ei, hk, q0, q1, coef, dcoef)
      real(dp), intent(in) :: ei, hk
      real(dp), intent(in) :: q0, q1
      real(dp), intent(out) :: coef, dcoef
      real(dp) :: th0, th1, m, dm, big
      big = 2*ei/hk
      th0 = sqrt(q0)
      th1 = sqrt(q1)
      if (th0 + th1 < 1.0e-3_dp) then
         coef = (0.25_dp + (q1 + q0)/24.0_dp + (q1*q1 + q1*q0 + q0*q0)*(17.0_dp/2880.0_dp) &
                 + (q1 + q0)*(q1*q1 + q0*q0)*(31.0_dp/40320.0_dp))*big
         dcoef = (1.0_dp/24.0_dp + (2*q1 + q0)*(17.0_dp/2880.0_dp) &
                  + ((q1*q1 + q0*q0) + (q1 + q0)*2*q1)*(31.0_dp/40320.0_dp))*big
      else
         call bend_divided(ei, hk, th0, th1, m, dm)
         coef = m/(th0 + th1)
         dcoef = (dm - coef)/(th0 + th1)/(2*max(th1, 1.0e-12_dp))
      end if
   end subroutine bend_coefficient_derivative

   !> The derivatives of f = J^T p, J the discrete Jacobian of discrete_jacobian_r(x0, x1, y, sign,
   !> delta) with y = (y0 + y1) / 2 (jx: its sign dphi/dx at the mid vectors, the J without the
   !> bracket), with respect to x1 (dfx) and y1 (dfy), given the derivatives
   !> of delta (ddx, ddy) and of p (dpx, dpy). With J = sign dphi/dx (x_mid, y) + br w^T,
   !> br = delta - sign dphi/dx dx, f = g + w beta with g = sign dphi/dx^T p and beta = br . p =
   !> delta . p - g . dx, so the only second derivatives needed are the Hessian of the scalar
   !> p . phi(x, y) in x and in x and y. Writing phi = R(c) u, u = x^ x y^, c = x^ . y^ (unit
   !> vectors; R = th / sin th), p . phi = R(c) T with T = p . u, and its gradient in x is
   !> Px v, Px = (I - x^ x^^T) / |x|, v = R' T y^ + R (y^ x p). Then
   !>
   !>     Hxx = [Q (R'' T y^ y^^T + R' (y^ q^T + q y^^T)) Px - (x^ . v) Px - x^ (Px v)^T - (Px v) x^^T] / |x|,
   !>     Hxy = Px [R'' T y^ x^^T + R' y^ m^T + R' T I + R' q x^^T - R [p]x] Py,
   !>
   !> with Q = I - x^ x^^T, q = y^ x p, m = p x x^, [p]x the cross-product matrix of p.
   pure subroutine discrete_force_derivatives(x0, x1, y0, y1, sign, jx, delta, ddx, ddy, p, dpx, dpy, dfx, dfy)
      real(dp), intent(in) :: x0(3), x1(3), y0(3), y1(3), sign, jx(3, 3), delta(3), ddx(3, 3), ddy(3, 3), p(3), &
                              dpx(3, 3), dpy(3, 3)
      real(dp), intent(out) :: dfx(3, 3), dfy(3, 3)
      real(dp) :: xm(3), y(3), nx, ny, xh(3), yh(3), u(3), s2, c, r0, r1, r2, t, q(3), m(3), v(3)
      real(dp) :: qx(3, 3), px(3, 3), py(3, 3), mm(3, 3), nn(3, 3), hxx(3, 3), hxy(3, 3), pv(3), g(3), xv
      real(dp) :: cv(3), cc, w(3), dx(3), beta, dbx(3), dby(3), dcm(3, 3), dcc(3), x0x(3, 3), xmx(3, 3)
      integer :: i, j
      xm = (x0 + x1)*0.5_dp
      y = (y0 + y1)*0.5_dp
      nx = sqrt(xm(1)**2 + xm(2)**2 + xm(3)**2)
      ny = sqrt(y(1)**2 + y(2)**2 + y(3)**2)
      xh = xm/nx
      yh = y/ny
      u = cross(xh, yh)
      s2 = u(1)**2 + u(2)**2 + u(3)**2
      c = xh(1)*yh(1) + xh(2)*yh(2) + xh(3)*yh(3)
      call turning_factors(s2, c, r0, r1, r2)
      t = p(1)*u(1) + p(2)*u(2) + p(3)*u(3)
      q = cross(yh, p)
      m = cross(p, xh)
      v = r1*t*yh + r0*q
      xv = xh(1)*v(1) + xh(2)*v(2) + xh(3)*v(3)
      do j = 1, 3
         do i = 1, 3
            qx(i, j) = merge(1.0_dp, 0.0_dp, i == j) - xh(i)*xh(j)
            py(i, j) = (merge(1.0_dp, 0.0_dp, i == j) - yh(i)*yh(j))/ny
            mm(i, j) = r2*t*yh(i)*yh(j) + r1*(yh(i)*q(j) + q(i)*yh(j))
            nn(i, j) = r2*t*yh(i)*xh(j) + r1*yh(i)*m(j) + r1*q(i)*xh(j)
         end do
         nn(j, j) = nn(j, j) + r1*t
      end do
      px = qx/nx
      nn = nn - r0*cross_matrix(p)
      pv = matmul(px, v)
      hxx = matmul(qx, matmul(mm, px)) - xv*px
      do j = 1, 3
         do i = 1, 3
            hxx(i, j) = (hxx(i, j) - xh(i)*pv(j) - pv(i)*xh(j))/nx
         end do
      end do
      hxy = matmul(px, matmul(nn, py))
      ! g = J^T p and its derivatives (J with its sign; d x_mid / d x1 = d y / d y1 = I / 2).
      g = matmul(p, jx)
      dfx = 0.5_dp*sign*hxx + matmul(transpose(jx), dpx)
      dfy = 0.5_dp*sign*hxy + matmul(transpose(jx), dpy)
      cv = cross(x0, x1)
      cc = cv(1)*cv(1) + cv(2)*cv(2) + cv(3)*cv(3)
      if (cc <= (bracket_rotation**2)*dot_product(x0, x0)*(x1(1)**2 + x1(2)**2 + x1(3)**2)) return
      dx = x1 - x0
      w = cross(cv, xm)/cc
      beta = dot_product(delta, p) - dot_product(g, dx)
      dbx = matmul(p, ddx) + matmul(delta, dpx) - matmul(dx, dfx) - g
      dby = matmul(p, ddy) + matmul(delta, dpy) - matmul(dx, dfy)
      ! w = (c x x_mid) / |c|^2, c = x0 x x1: d(c x x_mid) = (-[x_mid]x [x0]x + [c]x / 2) dx1, d|c|^2 = 2 c^T [x0]x dx1.
      x0x = cross_matrix(x0)
      xmx = cross_matrix(xm)
      dcm = -matmul(xmx, x0x) + 0.5_dp*cross_matrix(cv)
      dcc = 2*matmul(cv, x0x)
      do j = 1, 3
         do i = 1, 3
            dfx(i, j) = dfx(i, j) + (dcm(i, j) - w(i)*dcc(j))/cc*beta + w(i)*dbx(j)
            dfy(i, j) = dfy(i, j) + w(i)*dby(j)
         end do
      end do

   contains

      pure function cross(e, f) result(r)
         real(dp), intent(in) :: e(3), f(3)
         real(dp) :: r(3)
         r = [e(2)*f(3) - e(3)*f(2), e(3)*f(1) - e(1)*f(3), e(1)*f(2) - e(2)*f(1)]
      end function cross

      !> [e]x, the matrix of f -> e x f.
      pure function cross_matrix(e) result(r)
         real(dp), intent(in) :: e(3)
         real(dp) :: r(3, 3)
         r(1, 1) = 0
         r(2, 1) = e(3)
         r(3, 1) = -e(2)
         r(1, 2) = -e(3)
         r(2, 2) = 0
         r(3, 2) = e(1)
         r(1, 3) = e(2)
         r(2, 3) = -e(1)
         r(3, 3) = 0
      end function cross_matrix
   end subroutine discrete_force_derivatives

   !> R(c) = th / sin th of the turning with cos th = c, sin^2 th = s2, and its first two
   !> derivatives in c: R' = (c R - 1) / s2, R'' = (R + 3 c R') / s2, by their series in
   !> w = 1 - c = s2 / (1 + c) when w < 0.01 (truncation below 1e-15).
   pure subroutine turning_factors(s2, c, r0, r1, r2)
      real(dp), intent(in) :: s2, c
      real(dp), intent(out) :: r0, r1, r2
      real(dp), parameter :: a0(0:8) = [1.0_dp, 1.0_dp/3, 2.0_dp/15, 2.0_dp/35, 8.0_dp/315, 8.0_dp/693, 16.0_dp/3003, &
                                        16.0_dp/6435, 128.0_dp/109395]
      real(dp), parameter :: a1(0:7) = [-1.0_dp/3, -4.0_dp/15, -6.0_dp/35, -32.0_dp/315, -40.0_dp/693, -32.0_dp/1001, &
                                        -112.0_dp/6435, -1024.0_dp/109395]
      real(dp), parameter :: a2(0:6) = [4.0_dp/15, 12.0_dp/35, 32.0_dp/105, 160.0_dp/693, 160.0_dp/1001, 224.0_dp/2145, &
                                        7168.0_dp/109395]
      real(dp) :: w, s
      integer :: i
      w = 2
      if (c > 0) w = s2/(1 + c)
      if (w < 0.01_dp) then
         r0 = a0(8)
         do i = 7, 0, -1
            r0 = r0*w + a0(i)
         end do
         r1 = a1(7)
         do i = 6, 0, -1
            r1 = r1*w + a1(i)
         end do
         r2 = a2(6)
         do i = 5, 0, -1
            r2 = r2*w + a2(i)
         end do
      else
         s = sqrt(s2)
         r0 = atan2(s, c)/s
         r1 = (c*r0 - 1)/s2
         r2 = (r0 + 3*c*r1)/s2
      end if
   end subroutine turning_factors

   !> The rotation vector phi(x, y) = th u / |u|, u = x x y / (|x| |y|), of the smallest rotation
   !> taking the direction of x to that of y (|phi| = th; smooth through th = 0), with its
   !> Jacobians d phi / dx and d phi / dy when asked.
   pure subroutine rotation_vector_r(x, y, phi, jx, jy)
      real(dp), intent(in) :: x(3), y(3)
      real(dp), intent(out) :: phi(3)
      real(dp), intent(out), optional :: jx(3, 3), jy(3, 3)
      real(dp) :: nx, ny, u(3), s2, c, rho, rho_s2, rho_c, z, s, g(3), inv_xy, inv_xx, inv_yy, w(3), r(3)
      integer :: i, j
      nx = sqrt(x(1)*x(1) + x(2)*x(2) + x(3)*x(3))
      ny = sqrt(y(1)*y(1) + y(2)*y(2) + y(3)*y(3))
      u(1) = (x(2)*y(3) - x(3)*y(2))/(nx*ny)
      u(2) = (x(3)*y(1) - x(1)*y(3))/(nx*ny)
      u(3) = (x(1)*y(2) - x(2)*y(1))/(nx*ny)
      s2 = u(1)*u(1) + u(2)*u(2) + u(3)*u(3)
      c = (x(1)*y(1) + x(2)*y(2) + x(3)*y(3))/(nx*ny)
      if (c > 0 .and. s2 < 1.0e-5_dp*c**2) then
         z = s2/(c*c)
         rho = (1.0_dp - z/3.0_dp + z*z/5.0_dp - z*z*z/7.0_dp)/c
         rho_s2 = (-1.0_dp/3.0_dp + z*(2.0_dp/5.0_dp) - z*z*(3.0_dp/7.0_dp))/(c*c*c)
         rho_c = -rho/c + (-1.0_dp/3.0_dp + z*(2.0_dp/5.0_dp) - z*z*(3.0_dp/7.0_dp))*(-2.0_dp)*z/(c*c)
      else
         s = sqrt(s2)
         rho = atan2(s, c)/s
         rho_s2 = (c/(s2 + c*c) - rho)/(2.0_dp*s2)
         rho_c = -1.0_dp/(s2 + c*c)
      end if
      phi = u*rho
      if (.not. (present(jx) .or. present(jy))) return
      inv_xy = 1.0_dp/(nx*ny)
      if (present(jx)) then
         ! du/dx dx = (dx x y) / (|x| |y|) - u (x . dx) / |x|^2; (dx x y) = -[y]x dx.
         inv_xx = 1.0_dp/(nx*nx)
         w = [y(2)*u(3) - y(3)*u(2), y(3)*u(1) - y(1)*u(3), y(1)*u(2) - y(2)*u(1)]
         g = (w*inv_xy - x*(s2*inv_xx))*(2.0_dp*rho_s2) + (y*inv_xy - x*(c*inv_xx))*rho_c - x*(rho*inv_xx)
         do j = 1, 3
            do i = 1, 3
               jx(i, j) = u(i)*g(j)
            end do
         end do
         r = y*(rho*inv_xy)
         jx(1, 2) = jx(1, 2) + r(3)
         jx(1, 3) = jx(1, 3) - r(2)
         jx(2, 1) = jx(2, 1) - r(3)
         jx(2, 3) = jx(2, 3) + r(1)
         jx(3, 1) = jx(3, 1) + r(2)
         jx(3, 2) = jx(3, 2) - r(1)
      end if
      if (present(jy)) then
         ! du/dy dy = (x x dy) / (|x| |y|) - u (y . dy) / |y|^2; (x x dy) = [x]x dy.
         inv_yy = 1.0_dp/(ny*ny)
         w = [u(2)*x(3) - u(3)*x(2), u(3)*x(1) - u(1)*x(3), u(1)*x(2) - u(2)*x(1)]
         g = (w*inv_xy - y*(s2*inv_yy))*(2.0_dp*rho_s2) + (x*inv_xy - y*(c*inv_yy))*rho_c - y*(rho*inv_yy)
         do j = 1, 3
            do i = 1, 3
               jy(i, j) = u(i)*g(j)
            end do
         end do
         r = x*(rho*inv_xy)
         jy(1, 2) = jy(1, 2) - r(3)
         jy(1, 3) = jy(1, 3) + r(2)
         jy(2, 1) = jy(2, 1) + r(3)
         jy(2, 3) = jy(2, 3) - r(1)
         jy(3, 1) = jy(3, 1) - r(2)
         jy(3, 2) = jy(3, 2) + r(1)
      end if
   end subroutine rotation_vector_r

   !> Discrete Jacobian jac between x0 and x1 of the one-vector function h(x) = sign phi(x, y)
   !> (see the module header), given its change delta = h(x1) - h(x0): jac (x1 - x0) = delta
   !> exactly. jmid: sign d phi / dx at the mid vector, the part without the bracket.
   pure subroutine discrete_jacobian_r(x0, x1, y, sign, delta, jac, jmid)
      real(dp), intent(in) :: x0(3), x1(3), y(3)
      real(dp), intent(in) :: sign
      real(dp), intent(in) :: delta(3)
      real(dp), intent(out) :: jac(3, 3)
      real(dp), intent(out), optional :: jmid(3, 3)
      real(dp) :: xm(3), c(3), cc, w(3), dx(3), phi(3), bracket(3)
      integer :: i, j
      xm = (x0 + x1)*0.5_dp
      call rotation_vector_r(xm, y, phi, jac)
      if (sign < 0) jac = -jac
      if (present(jmid)) jmid = jac
      c = [x0(2)*x1(3) - x0(3)*x1(2), x0(3)*x1(1) - x0(1)*x1(3), x0(1)*x1(2) - x0(2)*x1(1)]
      cc = c(1)*c(1) + c(2)*c(2) + c(3)*c(3)
      if (cc <= (bracket_rotation**2)*dot_product(x0, x0)*(x1(1)**2 + x1(2)**2 + x1(3)**2)) return
      dx = x1 - x0
      do i = 1, 3
         bracket(i) = delta(i) - (jac(i, 1)*dx(1) + jac(i, 2)*dx(2) + jac(i, 3)*dx(3))
      end do
      w = [c(2)*xm(3) - c(3)*xm(2), c(3)*xm(1) - c(1)*xm(3), c(1)*xm(2) - c(2)*xm(1)]/cc
      do j = 1, 3
         do i = 1, 3
            jac(i, j) = jac(i, j) + bracket(i)*w(j)
         end do
      end do
   end subroutine discrete_jacobian_r

   !> [B(th1) - B(th0)] / (th1^2 - th0^2) of node k from q0 = th0^2 and q1 = th1^2: a polynomial
   !> in q near the straight state, from the divided difference in th otherwise.
   pure real(dp) function bend_coefficient_r(ei, hk, q0, q1) result(coef)
      real(dp), intent(in) :: ei, hk
      real(dp), intent(in) :: q0, q1
      real(dp) :: th0, th1, m, dm, big
      big = 2*ei/hk
      th0 = sqrt(q0)
      th1 = sqrt(q1)
      if (th0 + th1 < 1.0e-3_dp) then
         coef = (0.25_dp + (q1 + q0)/24.0_dp + (q1*q1 + q1*q0 + q0*q0)*(17.0_dp/2880.0_dp) &
                 + (q1 + q0)*(q1*q1 + q0*q0)*(31.0_dp/40320.0_dp))*big
      else
         call bend_divided(ei, hk, th0, th1, m, dm)
         coef = m/(th0 + th1)
      end if
   end function bend_coefficient_r

   !> Node rows from the cell forces and blocks, inertia, weight, end forces, twist and held rows
   !> (statics: t1 the time; a step: t1 = t0, t2 = dt).
   subroutine assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
      class(rod3d_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: t1, t2
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian, dynamic
      real(dp), intent(in) :: theta
      integer :: n, c, k, band0, a, b
      real(dp) :: scale, rate, t_new, r(3, self%n), psi(self%n), twist_scale, tau, jac_a(3, 3), jac_b(3, 3)
      logical :: held_a, held_b, anchor_a, anchor_b, state_a, state_b
      n = self%n
      scale = 1/self%tension_ref
      twist_scale = self%length_ref/self%gip
      held_a = self%end_a%held()
      held_b = self%end_b%held()
      anchor_a = held_a .or. .not. held_b
      anchor_b = held_b
      call unpack(x, r, psi)
      residual = 0
      do c = 1, n - 1
         residual(3*c - 2:3*c) = residual(3*c - 2:3*c) - self%force(:, c)
         residual(3*c + 1:3*c + 3) = residual(3*c + 1:3*c + 3) + self%force(:, c)
      end do
      if (allocated(self%node_w)) then
         do k = 1, n
            residual(3*k) = residual(3*k) + section_node_weight(self, k)
            residual(3*k - 2:3*k) = residual(3*k - 2:3*k) - self%load_node(:, k)
         end do
      else
         do k = 1, n
            residual(3*k) = residual(3*k) + node_weight(self, k)
            residual(3*k - 2:3*k) = residual(3*k - 2:3*k) - self%load_node(:, k)
         end do
      end if
      if (dynamic) then
         t_new = t1 + t2
         residual(1:3) = residual(1:3) - 0.5_dp*(self%end_a%applied_force3(t1) + self%end_a%applied_force3(t_new))
         residual(3*n - 2:3*n) = residual(3*n - 2:3*n) &
                                     - 0.5_dp*(self%end_b%applied_force3(t1) + self%end_b%applied_force3(t_new))
         rate = 1/(theta*t2*t2)
         self%v1 = ((r - self%r0)/t2 - (1 - theta)*self%v0)/theta
         call self%mass_times(self%v1, self%force_node)
         do k = 1, n
            residual(3*k - 2:3*k) = residual(3*k - 2:3*k) + (self%force_node(:, k) - self%mv0(:, k))/t2
         end do
      else
         t_new = t1
         residual(1:3) = residual(1:3) - self%end_a%applied_force3(t1)
         residual(3*n - 2:3*n) = residual(3*n - 2:3*n) - self%end_b%applied_force3(t1)
         rate = 0
      end if
      ! Ends that depend on their own state (springs): their force, and its derivative.
      state_a = self%end_a%state_dependent()
      state_b = self%end_b%state_dependent()
      if (state_a) call end_state(self%end_a, self%r0(:, 1), r(:, 1), residual(1:3), jac_a)
      if (state_b) call end_state(self%end_b, self%r0(:, n), r(:, n), residual(3*n - 2:3*n), jac_b)
      residual = residual*scale
      ! Twist rows (quasi-static, at the new time): dU/dpsi_k minus the applied torques.
      if (allocated(self%cell_gip)) then
         do c = 1, n - 1
            tau = (psi(c + 1) - psi(c))/self%ds(c)
            residual(3*n + c) = residual(3*n + c) - self%cell_gip(c)*tau*twist_scale
            residual(3*n + c + 1) = residual(3*n + c + 1) + self%cell_gip(c)*tau*twist_scale
         end do
      else
         do c = 1, n - 1
            tau = (psi(c + 1) - psi(c))/self%ds(c)
            residual(3*n + c) = residual(3*n + c) - self%gip*tau*twist_scale
            residual(3*n + c + 1) = residual(3*n + c + 1) + self%gip*tau*twist_scale
         end do
      end if
      residual(3*n + 1) = residual(3*n + 1) + self%end_a%applied_torque(t_new)*twist_scale
      residual(4*n) = residual(4*n) - self%end_b%applied_torque(t_new)*twist_scale
      if (anchor_a .and. held_a) residual(3*n + 1) = psi(1)
      if (anchor_a .and. .not. held_a) residual(3*n + 1) = psi(1) - self%psi_anchor
      if (anchor_b) residual(4*n) = psi(n)
      if (held_a) residual(1:3) = (r(:, 1) - self%end_a%position3(t_new))/self%length_ref
      if (held_b) residual(3*n - 2:3*n) = (r(:, n) - self%end_b%position3(t_new))/self%length_ref
      if (.not. with_jacobian) return

      jacobian%ab = 0
      jacobian%factorised = .false.
      band0 = jacobian%kl + jacobian%ku + 1
      call add_position_blocks(n, size(jacobian%ab, 1), size(jacobian%ab, 2), jacobian%ab, band0, self%block, self%ds, &
                               self%mass, self%load_block, scale, rate, held_a, held_b, dynamic, has_loads(self), &
                               self%skew_block, self%skewed)
      if (allocated(self%cell_gip)) then
         do c = 1, n - 1
            call add_twist(3*n + c, 3*n + c, self%cell_gip(c)/self%ds(c)*twist_scale)
            call add_twist(3*n + c, 3*n + c + 1, -self%cell_gip(c)/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c, -self%cell_gip(c)/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c + 1, self%cell_gip(c)/self%ds(c)*twist_scale)
         end do
      else
         do c = 1, n - 1
            call add_twist(3*n + c, 3*n + c, self%gip/self%ds(c)*twist_scale)
            call add_twist(3*n + c, 3*n + c + 1, -self%gip/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c, -self%gip/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c + 1, self%gip/self%ds(c)*twist_scale)
         end do
      end if
      do b = 1, 3
         do a = 1, 3
            if (state_a) call add_twist(a, b, -jac_a(a, b)*scale)
            if (state_b) call add_twist(3*(n - 1) + a, 3*(n - 1) + b, -jac_b(a, b)*scale)
         end do
      end do
      ! Bodies at nodes: their drag's derivative (its force is in load_node).
      if (allocated(self%points)) then
         do c = 1, size(self%points)
            k = self%point_node(c)
            if ((k == 1 .and. held_a) .or. (k == n .and. held_b)) cycle
            do b = 1, 3
               do a = 1, 3
                  call add_twist(3*(k - 1) + a, 3*(k - 1) + b, -self%point_jac(a, b, c)*scale)
               end do
            end do
         end do
      end if
      if (anchor_a) call set_row(3*n + 1, [3*n + 1], [1.0_dp])
      if (anchor_b) call set_row(4*n, [4*n], [1.0_dp])
      if (held_a) then
         do a = 1, 3
            call set_row(a, [a], [1/self%length_ref])
         end do
      end if
      if (held_b) then
         do a = 1, 3
            call set_row(3*(n - 1) + a, [3*(n - 1) + a], [1/self%length_ref])
         end do
      end if

   contains

      !> A state-dependent end's force taken from its node's rows (statics: at rest at x1, time t1;
      !> a step: from x0 over t2), and its derivative with respect to x1.
      subroutine end_state(end, x0, x1, rows, jac)
         class(end_condition), intent(in) :: end
         real(dp), intent(in) :: x0(3), x1(3)
         real(dp), intent(inout) :: rows(3)
         real(dp), intent(out) :: jac(3, 3)
         real(dp) :: f(3), dv(3, 3), damp(3)
         if (dynamic) then
            call end%step_force(t1, t2, x0, x1, f, jac, damp)
         else
            call end%state_force(t1, x1, [0.0_dp, 0.0_dp, 0.0_dp], f, jac, dv, damp)
         end if
         rows = rows - f
      end subroutine end_state

      !> Adds value to the entry (rr, cc) of the band.
      subroutine add_twist(rr, cc, value)
         integer, intent(in) :: rr, cc
         real(dp), intent(in) :: value
         jacobian%ab(band0 + rr - cc, cc) = jacobian%ab(band0 + rr - cc, cc) + value
      end subroutine add_twist

      !> Replace row rr by the given entries.
      subroutine set_row(rr, cols, values)
         integer, intent(in) :: rr, cols(:)
         real(dp), intent(in) :: values(:)
         integer :: cc, ii
         do cc = max(1, rr - jacobian%kl), min(size(x), rr + jacobian%ku)
            jacobian%ab(band0 + rr - cc, cc) = 0
         end do
         do ii = 1, size(cols)
            jacobian%ab(band0 + rr - cols(ii), cols(ii)) = values(ii)
         end do
      end subroutine set_row
   end subroutine assemble

   !> The Jacobian's position blocks (cells, inertia, distributed loads) in band storage ab, as
   !> explicit-shape arrays (a class argument's allocatable components cost several times the
   !> instructions in these loops, docs/measurements/data/speed_rounds.md item 4); the same sums in the same order.
   pure subroutine add_position_blocks(n, ld, ncol, ab, band0, block, ds, mass, load_block, scale, rate, held_a, held_b, &
                                       dynamic, loads, skew_block, skewed)
      integer, intent(in) :: n, ld, ncol, band0
      real(dp), intent(inout) :: ab(ld, ncol)
      real(dp), intent(in) :: block(3, 3, -1:1, n - 1), ds(n - 1), mass(0:2, n), load_block(3, 3, 0:1, n - 1)
      real(dp), intent(in) :: scale, rate
      logical, intent(in) :: held_a, held_b, dynamic, loads
      !> The unequal shares' blocks (cable_load cell_skew) and whether there are any.
      real(dp), intent(in) :: skew_block(3, 3, 0:1, n - 1)
      logical, intent(in) :: skewed
      integer :: c, cp, side, node, j, k, a, b, row, col
      real(dp) :: sgn, t(3, 3), share
      ! Cell c's force N_c enters node c with - and node c+1 with +; e_cp = (R_cp+1 - R_cp) / ds_cp.
      ! Each block is scaled once: (+-1 / ds) scale block = +-((1 / ds) scale block), the same bits.
      do c = 1, n - 1
         do cp = max(1, c - 1), min(n - 1, c + 1)
            sgn = 1.0_dp/ds(cp)*scale
            do b = 1, 3
               do a = 1, 3
                  t(a, b) = sgn*block(a, b, cp - c, c)
               end do
            end do
            do side = 0, 1
               node = cp + side
               do j = 0, 1
                  k = c + j
                  if (k == 1 .and. held_a) cycle
                  if (k == n .and. held_b) cycle
                  if (side == j) then
                     do b = 1, 3
                        col = 3*(node - 1) + b
                        do a = 1, 3
                           row = 3*(k - 1) + a
                           ab(band0 + row - col, col) = ab(band0 + row - col, col) + t(a, b)
                        end do
                     end do
                  else
                     do b = 1, 3
                        col = 3*(node - 1) + b
                        do a = 1, 3
                           row = 3*(k - 1) + a
                           ab(band0 + row - col, col) = ab(band0 + row - col, col) - t(a, b)
                        end do
                     end do
                  end if
               end do
            end do
         end do
      end do
      if (dynamic) then
         do k = 1, n
            if (k == 1 .and. held_a) cycle
            if (k == n .and. held_b) cycle
            do a = 1, 3
               row = 3*(k - 1) + a
               do j = -2, 2
                  node = k + j
                  if (node < 1 .or. node > n) cycle
                  col = row + 3*j
                  ab(band0 + row - col, col) = ab(band0 + row - col, col) + mass(abs(j), min(k, node))*rate*scale
               end do
            end do
         end do
      end if
      if (loads) then
         ! Node c and node c+1 each get -F_c / 2 (and -G_c, +G_c of unequal shares).
         do c = 1, n - 1
            do side = 0, 1
               node = c + side
               do j = 0, 1
                  k = c + j
                  if (k == 1 .and. held_a) cycle
                  if (k == n .and. held_b) cycle
                  do a = 1, 3
                     row = 3*(k - 1) + a
                     do b = 1, 3
                        col = 3*(node - 1) + b
                        share = 0.5_dp*load_block(a, b, side, c)
                        if (skewed) share = share + merge(1.0_dp, -1.0_dp, j == 0)*skew_block(a, b, side, c)
                        ab(band0 + row - col, col) = ab(band0 + row - col, col) - share*scale
                     end do
                  end do
               end do
            end do
         end do
      end if
   end subroutine add_position_blocks

   !> Whether the piece has distributed loads.
   pure logical function has_loads(self)
      class(rod3d_piece), intent(in) :: self
      has_loads = .false.
      if (allocated(self%loads)) has_loads = size(self%loads) > 0
   end function has_loads

   ! ---- for the submodules in model/rod3d/ ----
   ! gfortran 12 makes a module's private procedures local symbols that its submodules cannot link
   ! to; making unpack, node_weight and assemble themselves public would keep the compiler from
   ! inlining and specialising them in the time step here (a global symbol may be interposed under
   ! fpm's -fPIC). So the submodules call these public wrappers.

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

   !> assemble, for the submodules (the statics).
   subroutine rod3d_assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
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
      call assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
   end subroutine rod3d_assemble
end module xcable_model_rod3d
