!> Time integration of a scene with the rod discretisation: statics, the
!> break, the time steps with their step control, the energy ledger, the
!> history and the snapshots. One `rod_run` holds the whole state of a run;
!> each phase is a type-bound procedure.
!>
!> Steps. The step is the one asked for (dt, or courant ds / c with c the
!> largest axial wave speed of the static state and ds the longest cell);
!> only the last step before t_end, or before the start of a break, is
!> shortened to land on it. Snapshots at the times k * interval are
!> interpolated inside the step that contains them (cubic Hermite in the
!> positions and velocities of its two ends, third order), so the output
!> interval does not change the step.
!>
!> Step control. A step whose Newton iteration fails, or that leaves the
!> model's range (a non-finite state, a cell squeezed below 5 % of its length,
!> a turning angle passing half a turn within the step), is retried once with
!> a fresh Jacobian if it started from a kept one, then with half the step,
!> down to min_step_fraction dt; after four good steps the step doubles back
!> towards dt. The rejected attempts of a run are bounded by 1000 + the number
!> of requested steps, and the wall clock (max_wall_time) is checked before
!> every attempt. The 3-D run (driver/rod3d_drive.f90) takes the same step
!> control through the public procedures wall_limit, plan_step,
!> reject_attempt, advance_time, check_range and check_folds.
!>
!> Newton in a time step (this is the policy, not a silent override of the
!> case's settings): the case's tolerance, iteration limit and
!> reuse_jacobian; stop on the contraction estimate of the remaining error;
!> keep the factorised Jacobian while an iteration contracts by 0.5 within a
!> step, and refresh it at the start of a step once the last step contracted
!> by more than 0.05 per iteration, or when the step size changed (the mass
!> term of the Jacobian goes as 1/dt^2).
module xcable_driver_rod_run
   use xcable_core_kinds, only: dp, i8
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_numerics, stat_input
   use xcable_core_strings, only: str, quantity
   use xcable_scene_scene, only: scene_type, scene_grid
   use xcable_model_rod, only: rod_piece, rod_problem, rod_kl, rod_ku, perp, cross2, bend_energy, bend_moment, &
                               bend_curvature, cell_rotations, small_strain_step
   use xcable_ends_end_condition, only: end_condition
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_dissipation
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_force, only: force_end
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve, largest_magnitude
   use xcable_solver_banded, only: band_matrix
   use xcable_model_rod_statics, only: rod_static_state, solve_rod_statics
   use xcable_driver_records, only: run_history, run_summary, static_info, run_observer, n_energy, n_fields, &
                                 n_end_quantities, static_figures, slack_tension_fraction, note_min_strain, &
                                 n_fields3, field3_names, n_end_quantities_y
   use xcable_theory_closed_forms, only: wave_speed
   use xcable_io_archive, only: state_archive, sync_real, sync_reals, sync_matrix, sync_cube, sync_int, sync_ints, &
                                sync_logical
   use xcable_system_posix, only: termination_requested
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: rod_run, rod_run_options, run_progress, end_value, snapshot_time, ends_change
   public :: wall_limit, plan_step, reject_attempt, advance_time, jacobian_kept, check_range, check_folds
   public :: checkpoint_pause, exchange_progress, exchange_records, watch_step

   !> Why advance returned: the run ended (t_end or an error), a checkpoint is
   !> due, or SIGTERM arrived.
   integer, parameter, public :: pause_none = 0, pause_checkpoint = 1, pause_termination = 2

   !> Most time steps a run may ask for.
   integer, parameter, public :: max_steps = 1000000
   !> Skip of the quiescent cable (attempt): a node is quiet when it moves by at most
   !> quiet_fraction newton_tol cell lengths in a step, or by quiet_ulps units of round-off
   !> of the largest coordinate; margin nodes around the moving ones; outer nodes of a
   !> window that must stay quiet.
   real(dp), parameter :: quiet_fraction = 1.0e-5_dp, quiet_ulps = 16
   integer, parameter :: window_margin = 8, check_nodes = 2
   !> Warning thresholds (documented in docs/user/results.md, "Warnings").
   real(dp), parameter, public :: warn_energy_drift = 0.01_dp, warn_turning_angle = 1.0_dp, &
                                  warn_rejected_fraction = 0.01_dp, warn_courant_change = 0.01_dp, &
                                  warn_static_compression = 1.0e-6_dp
   !> Resolution warnings: the largest turning of the static shape between neighbouring cells
   !> (rad; where the shape turns by theta per cell, a cell's chord misses the arc by about
   !> theta / 8 of its length: 1.2 % at 0.1) and the fewest cells
   !> across a break's front (the length over which its force ramps down, c t_break).
   real(dp), parameter, public :: warn_static_turn = 0.1_dp, min_front_cells = 4
   !> A compression (a negative tension of the law) beyond this fraction of the largest static
   !> tension is warned, with where and when.
   real(dp), parameter, public :: warn_dynamic_compression = 0.01_dp

   !> The break by tension (&rupture criterion = 'tension'): a step whose largest cell tension
   !> passes mbl by more than rupture_tolerance mbl is taken again, shorter, aimed at the time
   !> where that cell's tension, linear between the step's two levels, reaches mbl; a step that
   !> ends within rupture_tolerance mbl of it ends the search (docs/theory/numerics.md, "The
   !> break by tension"). At most max_rupture_aims aims at one crossing.
   real(dp), parameter, public :: rupture_tolerance = 1.0e-4_dp
   integer, parameter, public :: max_rupture_aims = 40

   !> The search for a break by tension (the first pass of such a run, driver/simulation.f90),
   !> and what it found, for the summary of the run with the break.
   type, public :: tension_watch
      !> Minimum breaking load, N (0: no search).
      real(dp) :: mbl = 0
      !> Whether a cell reached mbl; when (s), which cell, the tension it reached (N) and the
      !> middle of that cell (m).
      logical :: found = .false.
      real(dp) :: time = 0, tension = 0, s = 0
      integer :: cell = 0
      !> The cell tensions at that time (N).
      real(dp), allocatable :: cells(:)
      !> Step aimed at the crossing (s; 0: none) and the aims at this crossing so far.
      real(dp) :: h_aim = 0
      integer :: aims = 0
      !> The bracket of the search: steps (s) below and past the crossing and their largest cell
      !> tensions (N); which end moved last (-1: below, 1: past, 0: none yet).
      real(dp) :: h_lo = 0, f_lo = 0, h_hi = 0, f_hi = 0
      integer :: side = 0
      !> Largest cell tension of the accepted steps (N), the middle of its cell (m) and its time (s).
      real(dp) :: max_tension = 0, max_s = 0, max_time = 0
   end type tension_watch

   !> Controls of a rod run.
   type :: rod_run_options
      !> Number of nodes.
      integer :: nodes = 121
      !> Time step (0: from the Courant number), Courant number, end of the run, s.
      real(dp) :: dt = 0, courant = 1, t_end = 0.16_dp
      !> Time weight of the new level (1/2: energy-conserving).
      real(dp) :: theta = 0.5_dp
      !> Share of the averaged mass matrix (1: averaged, 0: lumped), and the weight of the
      !> second-difference kinetic energy (model/rod.f90).
      real(dp) :: mu = 1, mu2 = 0
      !> Kelvin-Voigt damping c, N s.
      real(dp) :: damping = 0
      !> Snapshot interval, s (0: only t_end).
      real(dp) :: interval = 0.01_dp
      !> Newton controls of a time step (tolerance, iteration limit, reuse).
      type(newton_options) :: newton
      !> First guess of a step: R + dt V.
      logical :: extrapolate = .true.
      !> Keep the energy ledger.
      logical :: energy = .false.
      !> Solve each step only on the part of the cable that moves (see attempt): the nodes
      !> outside keep their state. Off (the default): every step solves the whole piece.
      logical :: skip_quiescent = .false.
      !> Smallest step of the step control, as a fraction of dt; wall-clock limit (s, 0: none).
      real(dp) :: min_step_fraction = 1.0_dp/1024, max_wall_time = 0
      !> Pause for a checkpoint every this many seconds of wall time (0: never).
      real(dp) :: checkpoint_interval = 0
      !> Pause for a checkpoint every this many accepted steps (0: never). Not a namelist variable:
      !> the tests' way to checkpoint at a known step.
      integer :: checkpoint_steps = 0
      !> Pause when SIGTERM has arrived (the program installs the handler, system/posix.f90).
      logical :: stop_on_termination = .false.
   end type rod_run_options

   !> Where the step loop stands between two steps: what it carries from one
   !> step to the next besides the state of the pieces (kept in a checkpoint).
   type :: run_progress
      !> Step the step control tries next, s.
      real(dp) :: h = 0
      !> Steps accepted since the step was last halved (it doubles after four), and attempts
      !> rejected since the last accepted step.
      integer :: n_good = 0, rejected_here = 0
      !> Index of the next snapshot (snapshot_time); snapshots 0 .. snapshot_index - 1 are written.
      integer :: snapshot_index = 1
      !> Wall time of the dynamics in the processes before this one (a resumed run), s.
      real(dp) :: wall_before = 0
   end type run_progress

   !> The wall clock of this process's part of a run (not kept in a checkpoint).
   type :: run_clock
      !> Clock count at the start (or the resume) and counts per second.
      integer(i8) :: start = 0, rate = 1
      !> Wall time (s, from start) of the last progress report and of the last checkpoint pause.
      real(dp) :: last_report = 0, last_checkpoint = 0
      !> History records at the last checkpoint pause (the next needs a step more).
      integer :: records_at_checkpoint = 0
   end type run_clock

   !> One piece of cable in a run.
   type :: piece_run
      !> The piece as a Newton problem.
      type(rod_problem) :: problem
      !> Newton work arrays and the kept factorisation.
      type(newton_workspace) :: work
      !> Step the kept factorisation was made for, s.
      real(dp) :: factor_step = -1
      !> Positions and velocities (2, n) at the current time.
      real(dp), allocatable :: r(:, :), v(:, :)
      !> Positions and velocities at the previous time (for the snapshots inside a step).
      real(dp), allocatable :: r_prev(:, :), v_prev(:, :)
      !> New level of the step being tried (unknowns, 2 n).
      real(dp), allocatable :: x(:)
      !> Force of the supports on the two end nodes at the current time (held ends), N.
      real(dp) :: reaction(2, 2) = 0
      !> Output columns of the nodes.
      integer, allocatable :: column(:)
      !> History slots of the two ends (0: none).
      integer :: end_slot(2) = 0
   end type piece_run

   !> A run.
   type :: rod_run
      !> The scene.
      type(scene_type) :: scene
      !> Controls.
      type(rod_run_options) :: options
      !> Node arc lengths of the whole cable and the break node (0: none inside).
      real(dp), allocatable :: s(:)
      integer :: break_node = 0
      !> Output nodes (the break node twice) and their arc lengths.
      integer :: n_out = 0
      real(dp), allocatable :: s_out(:)
      !> The pieces (one, or two after a break inside the cable).
      type(piece_run), allocatable :: pieces(:)
      !> Static state and what the output needs of it.
      type(rod_static_state) :: static
      type(static_info) :: info
      !> Time step used, s.
      real(dp) :: dt = 0
      !> Current time, s.
      real(dp) :: t = 0
      !> Energy bookkeeping: work of the ends, work of the distributed loads, dissipation, J.
      real(dp) :: work = 0, load_work = 0, dissipation = 0
      !> Whether the break has happened.
      logical :: broken = .false.
      !> The search for a break by tension (watch%mbl > 0: this run is the search), and what the
      !> search of a run's first pass found (its summary reports it).
      type(tension_watch) :: watch, rupture
      !> Force (N; x, z of each) and couple (N m) the break's new ends start from (cut a, cut b).
      real(dp) :: cut_force(2, 2) = 0, cut_couple(2) = 0
      !> Lowest tension of the static state's cells (N), the arc length of that cell's middle (m)
      !> and the largest tension magnitude (N): a static state in compression is reported (summarise).
      real(dp) :: static_min_tension = 0, static_min_tension_s = 0, static_max_tension = 0
      !> What the grid resolves, for the warnings: the largest turning between neighbouring cells
      !> of the static state (rad), and the cells across the break's front (its ramp t_break at the
      !> largest wave speed; 0: no front, or an instant break).
      real(dp) :: static_max_turn = 0, front_cells = 0
      !> History and summary.
      type(run_history) :: history
      type(run_summary) :: summary
      !> Where the step loop stands, and this process's clock.
      type(run_progress) :: progress
      type(run_clock) :: clock
      !> Fields of a snapshot (n_out, n_fields).
      real(dp), allocatable :: buffer(:, :)
      !> Skip of the quiescent cable in this process (not kept in a checkpoint): nodes times
      !> Newton solves (one per piece and attempt, a redone window counted again), and of
      !> them the nodes held outside the window; windows enlarged because the motion reached
      !> their margin; windows that fell back to the whole piece after a failed Newton solve.
      integer(i8) :: node_solves = 0, skipped_node_solves = 0
      integer :: window_growths = 0, window_fallbacks = 0
      !> A scene in a vertical plane at an azimuth, run turned into the x-z plane
      !> (driver/simulation.f90): the angle (rad, from x towards y) and the point (x, y) about which
      !> its results are turned back into the scene's frame (0: not turned). The observer then gets
      !> the fields of a 3-D run (y, vy; the others zero in a plane) and the history the ends' y
      !> components (turned back when the run finishes).
      real(dp) :: plane_azimuth = 0, plane_pivot(2) = 0
   contains
      !> Statics, the time step and the pieces (before any output).
      procedure :: prepare => run_prepare
      !> The dynamics to t_end (start, advance until done, finish).
      procedure :: run => run_dynamics
      !> The parts of run: the records of t = 0; the steps until t_end or a pause; the summary.
      procedure :: start => run_start
      procedure :: advance => run_advance
      procedure :: finish => run_finish
      !> Wall time of the dynamics so far (all processes of a resumed run), s.
      procedure :: wall_time => run_wall_time
      !> The state between two steps to an archive, and back into a prepared run.
      procedure :: save_state => run_save_state
      procedure :: load_state => run_load_state
      !> Fields on the output nodes.
      procedure :: fields => run_fields
   end type rod_run

contains

   !> Set up the run: grid, the whole cable as one piece, the statics, the
   !> time step. Errors: stat_input for an inconsistent scene, stat_numerics
   !> when the statics fails.
   subroutine run_prepare(self, scene, options, error)
      !> Run.
      class(rod_run), intent(inout) :: self
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> Controls.
      type(rod_run_options), intent(in) :: options
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: pa(2), pb(2), reach, c_max, ds_max
      integer :: n, k, c
      type(newton_options) :: static_newton
      self%scene = scene
      self%options = options
      n = options%nodes
      call scene_grid(scene, n, self%s, self%break_node)
      if (scene%interior_break() .and. self%break_node == 0) then
         call fatal_error(error, scene%source//': &numerics: nodes = '//str(n)// &
                          ': a break inside the cable needs at least 5 nodes', stat_input)
         return
      end if
      ! Ends held at two points farther apart than the cable can reach.
      if (scene%end_a%held() .and. scene%end_b%held() .and. .not. scene%from_tension) then
         pa = scene%end_a%position(0.0_dp)
         pb = scene%end_b%position(0.0_dp)
         reach = scene%length*(1 + scene%law%strain_max)
         if (norm2(pb - pa) >= reach) then
            call fatal_error(error, scene%source//': &end_b: x, z = '//str(pb(1))//', '//str(pb(2))// &
                             ': the ends are '//str(norm2(pb - pa))//' m apart, the cable reaches at most '// &
                             str(reach)//' m (L (1 + strain_max))', stat_input)
            return
         end if
      end if
      if (scene%gravity <= 0 .and. .not. ((scene%end_a%held() .or. scene%end_a%state_dependent()) .and. &
                                          (scene%end_b%held() .or. scene%end_b%state_dependent()))) then
         call fatal_error(error, scene%source//': &cable: gravity = 0: a cable held at one end only has no '// &
                          'static shape without weight', stat_input)
         return
      end if
      allocate (self%pieces(1))
      call self%pieces(1)%problem%piece%init(self%s, scene%mass, scene%weight, scene%ei, scene%gravity, options%mu, &
                                              scene%law, scene%end_a, scene%end_b, max(scene%tension, 1.0_dp), options%mu2, &
                                              options%damping)
      if (allocated(scene%loads)) self%pieces(1)%problem%piece%loads = scene%loads
      static_newton = options%newton
      call solve_rod_statics(scene, self%pieces(1)%problem, static_newton, self%static, error)
      if (allocated(error)) return
      if (scene%from_tension) then
         deallocate (self%scene%end_b)
         allocate (self%scene%end_b, source=fixed_end(point=self%static%end_b_point))
         self%scene%end_b%label = 'end_b'
      end if
      ! The static state must stay within the law's documented range.
      associate (r => self%static%r, piece => self%pieces(1)%problem%piece)
         if (maxval(norm2(r(:, 2:n) - r(:, 1:n - 1), 1)/piece%ds - 1) > piece%law%strain_max) then
            call fatal_error(error, scene%source//': the static state needs strain '// &
                             str(maxval(norm2(r(:, 2:n) - r(:, 1:n - 1), 1)/piece%ds - 1))// &
                             ', above the range of the law (&material strain_max = '//str(piece%law%strain_max)// &
                             '): the ends are too far apart or the loads too large', stat_input)
            return
         end if
      end associate
      ! Row scale: the largest static tension (1 N at least).
      associate (piece => self%pieces(1)%problem%piece)
         piece%tension_ref = max(maxval(abs(piece%law%tension(norm2(self%static%r(:, 2:n) - self%static%r(:, 1:n - 1), 1) &
                                                                  /piece%ds - 1))), 1.0_dp)
         c_max = 0
         do c = 1, n - 1
            c_max = max(c_max, wave_speed(piece%law, piece%mass_per_length, norm2(self%static%r(:, c + 1) - self%static%r(:, c)) &
                                          /piece%ds(c) - 1))
         end do
         ds_max = maxval(piece%ds)
      end associate
      if (options%dt > 0) then
         self%dt = options%dt
      else
         self%dt = options%courant*ds_max/c_max
      end if
      self%summary%dt_requested = self%dt
      self%summary%courant_requested = self%dt*c_max/ds_max
      ! The strains reached start with those of the static state.
      associate (piece => self%pieces(1)%problem%piece)
         self%summary%min_strain = minval(norm2(self%static%r(:, 2:n) - self%static%r(:, 1:n - 1), 1)/piece%ds - 1)
         self%summary%min_strain_s = self%static_min_tension_s
         self%summary%max_strain = maxval(norm2(self%static%r(:, 2:n) - self%static%r(:, 1:n - 1), 1)/piece%ds - 1)
         block
            real(dp) :: cell_tension(n - 1)
            integer :: c_low
            cell_tension = piece%law%tension(norm2(self%static%r(:, 2:n) - self%static%r(:, 1:n - 1), 1)/piece%ds - 1)
            c_low = minloc(cell_tension, 1)
            self%static_min_tension = cell_tension(c_low)
            self%static_min_tension_s = 0.5_dp*(self%s(c_low) + self%s(c_low + 1))
            self%static_max_tension = maxval(abs(cell_tension))
         end block
         block
            real(dp) :: e(2, n - 1)
            e = self%static%r(:, 2:n) - self%static%r(:, 1:n - 1)
            if (n > 2) self%static_max_turn = maxval(abs(atan2(e(1, 1:n - 2)*e(2, 2:n - 1) - e(2, 1:n - 2)*e(1, 2:n - 1), &
                                                            e(1, 1:n - 2)*e(1, 2:n - 1) + e(2, 1:n - 2)*e(2, 2:n - 1))))
         end block
      end associate
      if (scene%breaks .and. scene%t_break > 0) self%front_cells = c_max*scene%t_break/ds_max
      if (.not. (options%t_end/self%dt <= max_steps)) then
         call fatal_error(error, scene%source//': &numerics: the time step '//str(self%dt)//' s (courant = '// &
                          str(options%courant)//', ds = '//str(ds_max)//' m, largest wave speed '//str(c_max)// &
                          ' m/s) gives more than '//str(max_steps)//' steps to t_end = '//str(options%t_end)//' s'// &
                          '; give a longer step: courant = '//str(1.01_dp*options%t_end/max_steps*c_max/ds_max)// &
                          ' or more (or dt = '//str(1.01_dp*options%t_end/max_steps)//' s or more). The implicit '// &
                          'scheme is stable at any Courant number (the step control retries a step Newton cannot '// &
                          'take); for slow motions, as a heave over minutes, 10 to 100 is usual: check it against '// &
                          'a run at half the step', stat_input)
         return
      end if
      ! Output nodes: the break node twice.
      self%n_out = n + merge(1, 0, self%break_node > 0)
      allocate (self%s_out(self%n_out))
      allocate (self%pieces(1)%column(n))
      do k = 1, n
         self%pieces(1)%column(k) = k
         if (self%break_node > 0 .and. k > self%break_node) self%pieces(1)%column(k) = k + 1
         self%s_out(self%pieces(1)%column(k)) = self%s(k)
      end do
      if (self%break_node > 0) self%s_out(self%break_node + 1) = self%s(self%break_node)
      self%pieces(1)%r = self%static%r
      call self%pieces(1)%work%init(2*n, rod_kl, rod_ku, spread(self%pieces(1)%problem%piece%length_ref, 1, 2*n))
      allocate (self%pieces(1)%v(2, n))
      self%pieces(1)%v = 0
      if (self%scene%end_a%held()) self%pieces(1)%v(:, 1) = self%scene%end_a%velocity(0.0_dp)
      if (self%scene%end_b%held()) self%pieces(1)%v(:, n) = self%scene%end_b%velocity(0.0_dp)
      deallocate (self%pieces(1)%problem%piece%end_b)
      allocate (self%pieces(1)%problem%piece%end_b, source=self%scene%end_b)
      call static_fields(self)
   end subroutine run_prepare

   !> Fill self%info from the static state.
   subroutine static_fields(self)
      type(rod_run), intent(inout) :: self
      integer :: n
      n = self%options%nodes
      self%info%s = self%s_out
      allocate (self%info%fields(self%n_out, n_fields))
      call self%fields(self%info%fields)
      self%info%span = self%static%span
      self%info%sag = self%static%sag
      self%info%tension_a = self%info%fields(1, 1)
      self%info%tension_b = self%info%fields(self%n_out, 1)
      if (self%scene%end_a%held()) self%info%tension_a = norm2(self%static%reaction_a)
      if (self%scene%end_b%held() .or. self%scene%from_tension) self%info%tension_b = norm2(self%static%reaction_b)
      self%info%newton_iterations = self%static%newton_iterations
      call static_figures(self%info)
   end subroutine static_fields

   !> Fields on the output nodes from the current state of the pieces: cell
   !> values (tension, strain, shear) at a node are the mean of its cells
   !> (one cell at an end); u, v along the node tangent (the mean direction of
   !> its cells) and the paper's normal n = -perp(t); curvature is the paper's
   !> Omega3 = -theta_k / h_k (0 at the ends).
   subroutine run_fields(self, fields, positions, velocities)
      !> Run.
      class(rod_run), intent(inout) :: self
      !> Fields (n_out, n_fields) in the order of field_names.
      real(dp), intent(out) :: fields(:, :)
      !> Positions and velocities per piece (2, n_out): if given, used instead of the pieces' current state.
      real(dp), intent(in), optional :: positions(:, :), velocities(:, :)
      integer :: p, k, n, col
      real(dp), allocatable :: ten(:), eps(:), shear(:), mom(:), r(:, :), v(:, :)
      real(dp) :: tk(2), nk(2), e(2)
      do p = 1, size(self%pieces)
         associate (piece => self%pieces(p)%problem%piece, cols => self%pieces(p)%column)
            n = piece%n
            allocate (ten(n - 1), eps(n - 1), shear(n - 1), mom(n), r(2, n), v(2, n))
            if (present(positions)) then
               r = positions(:, cols)
               v = velocities(:, cols)
            else
               r = self%pieces(p)%r
               v = self%pieces(p)%v
            end if
            call piece%cell_fields(r, ten, eps, shear, mom, v)
            do k = 1, n
               col = cols(k)
               if (k == 1) then
                  fields(col, 1) = max(end_value(ten, 1), piece%law%tension(-0.99_dp))
                  fields(col, 2) = end_value(shear, 1)
                  fields(col, 3) = max(end_value(eps, 1), -0.99_dp)
                  e = r(:, 2) - r(:, 1)
               else if (k == n) then
                  fields(col, 1) = max(end_value(ten, 2), piece%law%tension(-0.99_dp))
                  fields(col, 2) = end_value(shear, 2)
                  fields(col, 3) = max(end_value(eps, 2), -0.99_dp)
                  e = r(:, n) - r(:, n - 1)
               else
                  fields(col, 1) = 0.5_dp*(ten(k - 1) + ten(k))
                  fields(col, 2) = 0.5_dp*(shear(k - 1) + shear(k))
                  fields(col, 3) = 0.5_dp*(eps(k - 1) + eps(k))
                  e = (r(:, k + 1) - r(:, k))/norm2(r(:, k + 1) - r(:, k)) + (r(:, k) - r(:, k - 1))/norm2(r(:, k) - r(:, k - 1))
               end if
               tk = e/max(norm2(e), tiny(1.0_dp))
               nk = -perp(tk)
               fields(col, 4) = dot_product(v(:, k), tk)
               fields(col, 5) = dot_product(v(:, k), nk)
               fields(col, 6) = r(1, k)
               fields(col, 7) = r(2, k)
               fields(col, 8) = 0
               if (k > 1 .and. k < n) fields(col, 8) = -bend_curvature(piece, k, piece%th1(k))
            end do
            ! Before a break inside the cable the break node fills both of its columns.
            if (size(self%pieces) == 1 .and. self%break_node > 0) fields(self%break_node + 1, :) = fields(self%break_node, :)
            deallocate (ten, eps, shear, mom, r, v)
         end associate
      end do
   end subroutine run_fields

   !> Value at an end node (side 1: node 1, side 2: node n) of a cell field:
   !> the end cell's value extrapolated half a cell along the slope c1 - c2
   !> of the two end cells (second order), unless the three end cells
   !> zig-zag (c1 - c2 and c2 - c3 of opposite signs: a buckle at the grid
   !> scale), where the extrapolation would overshoot and the end cell's own
   !> value is used.
   pure real(dp) function end_value(cells, side)
      !> Cell values.
      real(dp), intent(in) :: cells(:)
      !> 1 or 2.
      integer, intent(in) :: side
      integer :: m
      real(dp) :: c1, c2, c3
      m = size(cells)
      if (m < 3) then
         end_value = merge(cells(1), cells(m), side == 1)
         return
      end if
      if (side == 1) then
         c1 = cells(1); c2 = cells(2); c3 = cells(3)
      else
         c1 = cells(m); c2 = cells(m - 1); c3 = cells(m - 2)
      end if
      if ((c1 - c2)*(c2 - c3) < 0) then
         end_value = c1
      else
         end_value = c1 + 0.5_dp*(c1 - c2)
      end if
   end function end_value

   !> Integrate to t_end, sending snapshots to the observer: start, advance
   !> until done, finish. On error the history and summary hold what was
   !> done. A run that is to write checkpoints goes through start (or
   !> load_state), advance and finish itself (driver/simulation.f90).
   subroutine run_dynamics(self, observer, error)
      !> Run (prepared).
      class(rod_run), intent(inout) :: self
      !> Receives the static state and snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the run cannot go on.
      type(error_type), allocatable, intent(out) :: error
      integer :: pause
      call self%start(observer, error)
      if (allocated(error)) return
      do
         call self%advance(observer, error, pause)
         if (allocated(error) .or. pause == pause_none) exit
      end do
      call self%finish()
   end subroutine run_dynamics

   !> The start of the dynamics: the record of t = 0, the static state and
   !> its snapshot to the observer, a break at t = 0, and the skip to a later
   !> break when nothing moves before it.
   subroutine run_start(self, observer, error)
      !> Run (prepared).
      class(rod_run), intent(inout) :: self
      !> Receives the static state and the snapshots before the break.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the output fails.
      type(error_type), allocatable, intent(out) :: error
      integer :: capacity
      call system_clock(self%clock%start, self%clock%rate)
      self%t = 0
      self%work = 0
      self%load_work = 0
      self%dissipation = 0
      self%progress = run_progress(h=self%dt)
      call start_history(self)
      if (present(observer)) then
         if (self%plane_azimuth /= 0) then
            block
               type(static_info) :: turned
               turned = self%info
               allocate (turned%extra(self%n_out, n_fields3))
               call turned_back(self, turned%fields, column_velocities(self), turned%extra)
               call observer%static(turned, error)
               if (allocated(error)) return
               call observer%snapshot(0.0_dp, turned%fields, error)
               if (allocated(error)) return
               call observer%snapshot_extra(0.0_dp, field3_names, turned%extra, error)
               if (allocated(error)) return
            end block
         else
            call observer%static(self%info, error)
            if (allocated(error)) return
            call observer%snapshot(0.0_dp, self%info%fields, error)
            if (allocated(error)) return
         end if
      end if
      capacity = int(min(self%options%t_end/self%dt, real(max_steps, dp))) + 16
      call self%history%reserve(capacity, size(self%history%end_labels), self%options%energy)
      ! A break at t = 0 happens before the first step.
      if (self%scene%breaks .and. self%scene%break_time <= 0) then
         call split(self, error)
         if (allocated(error)) return
      end if
      ! Nothing moves before a break if no end moves or changes its load: skip to it.
      if (self%scene%breaks .and. .not. self%broken .and. .not. ends_change(self)) then
         call emit_snapshots(self, observer, self%scene%break_time, .true., error)
         if (allocated(error)) return
         self%t = self%scene%break_time
         call record(self, 0, 0, self%t - self%history%time(self%history%n))
         call split(self, error)
         if (allocated(error)) return
      end if
      self%clock%records_at_checkpoint = self%history%n
   end subroutine run_start

   !> Time steps until t_end, an error, or a pause: the SIGTERM flag is set
   !> (with options%stop_on_termination) or a checkpoint is due (every
   !> options%checkpoint_interval seconds of wall time, or every
   !> options%checkpoint_steps accepted steps), checked before every step
   !> attempt, where the state is complete (a checkpoint needs at least one
   !> step since the last). After a pause the state can be saved
   !> (save_state) and advance called again.
   subroutine run_advance(self, observer, error, pause)
      !> Run (started, or loaded from a checkpoint).
      class(rod_run), intent(inout) :: self
      !> Receives the snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the run cannot go on.
      type(error_type), allocatable, intent(out) :: error
      !> Why it returned: pause_none (t_end or an error), pause_checkpoint or pause_termination.
      integer, intent(out) :: pause
      type(error_type), allocatable :: step_error
      integer(i8) :: clock_now
      real(dp) :: h_try, wall, t_stop
      integer :: p, iterations
      logical :: newton_failed, kept, any_kept, landing, retry

      pause = pause_none
      associate (h => self%progress%h, n_good => self%progress%n_good, rejected_here => self%progress%rejected_here)
         do while (self%t < self%options%t_end*(1 - 1.0e-12_dp))
            call system_clock(clock_now)
            wall = real(clock_now - self%clock%start, dp)/self%clock%rate
            call wall_limit(self, wall, error)
            if (allocated(error)) exit
            ! A pause, where the state is that of an accepted step (or of the start).
            pause = checkpoint_pause(self, wall)
            if (pause /= pause_none) return
            call plan_step(self, h_try, t_stop, landing, error)
            if (allocated(error)) exit
            ! One attempt on every piece.
            newton_failed = .false.
            any_kept = .false.
            iterations = 0
            do p = 1, size(self%pieces)
               call attempt(self, p, h_try, kept, iterations, step_error)
               any_kept = any_kept .or. kept
               if (allocated(step_error)) then
                  newton_failed = .true.
                  exit
               end if
            end do
            if (.not. allocated(step_error)) call check_state(self, h_try, step_error)
            if (allocated(step_error)) then
               do p = 1, size(self%pieces)
                  self%pieces(p)%work%usable = .false.
               end do
               call reject_attempt(self, step_error%message, newton_failed .and. any_kept, error)
               deallocate (step_error)
               if (allocated(error)) exit
               cycle
            end if
            ! The search for a break by tension: a step past the crossing is taken again, shorter.
            if (self%watch%mbl > 0) then
               associate (piece => self%pieces(1)%problem%piece)
                  call watch_step(self, h_try, self%pieces(1)%r, reshape(self%pieces(1)%x, [2, piece%n]), &
                                  piece%ds, piece%law, retry)
               end associate
               if (retry) then
                  self%pieces(1)%work%usable = .false.
                  cycle
               end if
            end if
            ! Accept: snapshots inside the step, then the new level.
            call accept(self, h_try)
            call emit_snapshots(self, observer, self%t + h_try, .false., error)
            if (allocated(error)) exit
            call advance_time(self, h_try, t_stop, landing)
            call record(self, iterations, rejected_here, h_try)
            rejected_here = 0
            if (self%watch%found) exit
            if (self%scene%breaks .and. .not. self%broken .and. self%t >= self%scene%break_time*(1 - 1.0e-12_dp)) then
               call split(self, error)
               if (allocated(error)) exit
            end if
            call system_clock(clock_now)
            wall = real(clock_now - self%clock%start, dp)/self%clock%rate
            if (present(observer) .and. wall - self%clock%last_report >= 1.0_dp) then
               self%clock%last_report = wall
               call observer%progress(self%t, self%options%t_end, wall)
            end if
         end do
      end associate
   end subroutine run_advance

   !> Whether the step loop pauses before its next attempt (either model):
   !> pause_termination when SIGTERM has arrived (options%stop_on_termination),
   !> pause_checkpoint when a checkpoint is due (every
   !> options%checkpoint_interval seconds of wall time, or every
   !> options%checkpoint_steps accepted steps; at least one step since the
   !> last), else pause_none. The clock notes a checkpoint pause.
   integer function checkpoint_pause(self, wall) result(pause)
      !> Run (its history counts the steps).
      type(rod_run), intent(inout) :: self
      !> Wall time of this process's dynamics, s.
      real(dp), intent(in) :: wall
      logical :: due
      pause = pause_none
      if (self%options%stop_on_termination) then
         if (termination_requested()) then
            pause = pause_termination
            return
         end if
      end if
      if (self%history%n > self%clock%records_at_checkpoint) then
         due = .false.
         if (self%options%checkpoint_interval > 0) &
            due = wall - self%clock%last_checkpoint >= self%options%checkpoint_interval
         if (self%options%checkpoint_steps > 0) &
            due = due .or. self%history%n - self%clock%records_at_checkpoint >= self%options%checkpoint_steps
         if (due) then
            self%clock%last_checkpoint = wall
            self%clock%records_at_checkpoint = self%history%n
            pause = pause_checkpoint
         end if
      end if
   end function checkpoint_pause

   !> The end of the dynamics (also of one stopped by an error or a
   !> termination): wall time, time reached, summary figures and warnings.
   subroutine run_finish(self)
      !> Run.
      class(rod_run), intent(inout) :: self
      self%summary%wall_time = self%wall_time()
      self%summary%time_reached = self%t
      call summarise(self)
      if (self%plane_azimuth /= 0) call turn_back_history(self)
   end subroutine run_finish

   !> The history of a run turned into x-z (plane_azimuth), turned back into the scene's frame:
   !> x, vx and force_x of each end and record, and their y components (ends_y).
   subroutine turn_back_history(self)
      type(rod_run), intent(inout) :: self
      real(dp) :: c, s
      c = cos(self%plane_azimuth)
      s = sin(self%plane_azimuth)
      associate (h => self%history)
         if (allocated(h%ends_y)) deallocate (h%ends_y)
         allocate (h%ends_y(n_end_quantities_y, size(h%ends, 2), lbound(h%ends, 3):ubound(h%ends, 3)))
         ! ends: x, z, vx, vz, tension, force_x, force_z; ends_y: y, vy, force_y.
         h%ends_y(1, :, :) = self%plane_pivot(2) + s*(h%ends(1, :, :) - self%plane_pivot(1))
         h%ends_y(2, :, :) = s*h%ends(3, :, :)
         h%ends_y(3, :, :) = s*h%ends(6, :, :)
         h%ends(1, :, :) = self%plane_pivot(1) + c*(h%ends(1, :, :) - self%plane_pivot(1))
         h%ends(3, :, :) = c*h%ends(3, :, :)
         h%ends(6, :, :) = c*h%ends(6, :, :)
      end associate
   end subroutine turn_back_history

   !> The fields of a run turned into x-z (plane_azimuth) in the scene's frame: the x column
   !> turned back (in place), and the fields of field3_names from it and the columns' velocities
   !> v (2, n_out): y and vy; the plan-view curvature, twist, binormal shear and curvature about
   !> n are zero in a vertical plane.
   subroutine turned_back(self, fields, v, extra)
      type(rod_run), intent(in) :: self
      real(dp), intent(inout) :: fields(:, :)
      real(dp), intent(in) :: v(:, :)
      real(dp), intent(out) :: extra(:, :)
      real(dp) :: c, s, u(size(fields, 1))
      c = cos(self%plane_azimuth)
      s = sin(self%plane_azimuth)
      ! fields: tension shear strain u v x z curvature; extra: y vy curvature_z twist binormal_shear curvature_n.
      u = fields(:, 6) - self%plane_pivot(1)
      fields(:, 6) = self%plane_pivot(1) + c*u
      extra = 0
      extra(:, 1) = self%plane_pivot(2) + s*u
      extra(:, 2) = s*v(1, :)
   end subroutine turned_back

   !> The velocities of the pieces' nodes on the output columns (2, n_out); before a break
   !> inside the cable the break node fills both of its columns (as in run_fields).
   function column_velocities(self) result(v)
      type(rod_run), intent(in) :: self
      real(dp), allocatable :: v(:, :)
      integer :: p
      allocate (v(2, self%n_out))
      v = 0
      do p = 1, size(self%pieces)
         v(:, self%pieces(p)%column) = self%pieces(p)%v
      end do
      if (size(self%pieces) == 1 .and. self%break_node > 0) v(:, self%break_node + 1) = v(:, self%break_node)
   end function column_velocities

   !> Wall time of the dynamics so far, s: this process's and, for a resumed
   !> run, that of the processes before.
   function run_wall_time(self) result(wall)
      !> Run.
      class(rod_run), intent(in) :: self
      real(dp) :: wall
      integer(i8) :: clock_now
      call system_clock(clock_now)
      wall = self%progress%wall_before + real(clock_now - self%clock%start, dp)/self%clock%rate
   end function run_wall_time

   !> Save the state of the run between two steps (after a pause of
   !> advance, or after start) to an archive: everything the next step and
   !> the records depend on (see exchange_state). archive%ok tells whether
   !> it was stored.
   subroutine run_save_state(self, archive)
      !> Run.
      class(rod_run), intent(inout) :: self
      !> Where the state goes.
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable :: error
      call exchange_state(self, archive, .true., error)
   end subroutine run_save_state

   !> Load a state saved by save_state into a run prepared from the same case
   !> (the same statics, grid and time step), ready for advance. Errors
   !> (stat_input) when the archive fails or holds a state this run cannot
   !> have.
   subroutine run_load_state(self, archive, error)
      !> Run, prepared.
      class(rod_run), intent(inout) :: self
      !> Where the state comes from.
      class(state_archive), intent(inout) :: archive
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      call exchange_state(self, archive, .false., error)
      if (allocated(error)) return
      if (.not. archive%ok) then
         call fatal_error(error, archive%message, stat_input)
         return
      end if
      call system_clock(self%clock%start, self%clock%rate)
      self%clock%last_report = 0
      self%clock%last_checkpoint = 0
      self%clock%records_at_checkpoint = self%history%n
   end subroutine run_load_state

   !> The state of a run, listed once for saving (saving = .true.) and
   !> loading, so that the two cannot differ. It is what the step loop carries
   !> from one step to the next:
   !>  - time, step size asked for and the step control (progress: the step
   !>    to try, the good steps since it was halved, the rejections since the
   !>    last accepted step, the next snapshot, the wall time so far);
   !>  - the break (whether it happened, the forces and couples its new ends
   !>    start from) and so the pieces; per piece its positions and
   !>    velocities at the current time, the reactions of its held ends, and
   !>    Newton's kept factorisation when one is kept (reuse_jacobian): its
   !>    LU factors and pivots, the contraction and the step it was made for;
   !>  - the energy accumulators (work of the ends, work of the distributed
   !>    loads, dissipation);
   !>  - the history (every record so far) and the summary's counters.
   !> Not saved, because every step recomputes them before use: the pieces'
   !> work arrays (old level, geometry, forces: prepare_step and the
   !> residual), the Newton residual and update, the positions and
   !> velocities of the previous time level (r_prev, v_prev: accept sets them
   !> before the snapshots inside the step read them; the rod is a one-step
   !> method). The distributed loads (fluid) and the internal damping keep no
   !> state of their own: a step evaluates them from its two levels, and the
   !> statics leave the loads' factor at 1. Not saved, because prepare computes
   !> them from the case: the grid, the static state, the scene, its ends and
   !> loads, the damping coefficient.
   subroutine exchange_state(self, a, saving, error)
      type(rod_run), intent(inout) :: self
      class(state_archive), intent(inout) :: a
      logical, intent(in) :: saving
      type(error_type), allocatable, intent(out) :: error
      integer :: n_pieces, p, n, flags(2), kb, expected_nodes(2)
      real(dp) :: newton_reals(2)
      character(:), allocatable :: prefix

      call sync_real(a, 'run/t', self%t, saving)
      call sync_real(a, 'run/dt', self%dt, saving)
      call sync_real(a, 'run/work', self%work, saving)
      call sync_real(a, 'run/load_work', self%load_work, saving)
      call sync_real(a, 'run/dissipation', self%dissipation, saving)
      call sync_logical(a, 'run/broken', self%broken, saving)
      call sync_matrix(a, 'run/cut_force', self%cut_force, saving)
      call sync_reals(a, 'run/cut_couple', self%cut_couple, saving)
      call exchange_progress(self, a, saving)

      ! The pieces: one, or two after a break inside the cable.
      n_pieces = 0
      if (allocated(self%pieces)) n_pieces = size(self%pieces)
      call sync_int(a, 'run/pieces', n_pieces, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         kb = self%break_node
         if (self%broken .and. .not. self%scene%breaks) then
            call fatal_error(error, 'the checkpoint holds a broken cable, the case has no break', stat_input)
            return
         end if
         if (n_pieces /= merge(2, 1, self%broken .and. kb > 0)) then
            call fatal_error(error, 'the checkpoint holds '//str(n_pieces)//' pieces of cable, this case '// &
                             str(merge(2, 1, self%broken .and. kb > 0))//' at that stage', stat_input)
            return
         end if
         self%pieces(1)%end_slot = [1, 2]
         if (self%broken) call apply_split(self)
      end if
      expected_nodes = [self%options%nodes, 0]
      if (n_pieces == 2) expected_nodes = [self%break_node, self%options%nodes - self%break_node + 1]
      do p = 1, n_pieces
         prefix = 'pieces/'//str(p)//'/'
         associate (run_piece => self%pieces(p), work => self%pieces(p)%work)
            n = run_piece%problem%piece%n
            call sync_int(a, prefix//'nodes', n, saving)
            if (.not. saving .and. a%ok .and. n /= expected_nodes(p)) then
               call fatal_error(error, 'the checkpoint holds '//str(n)//' nodes in piece '//str(p)//', this case '// &
                                str(expected_nodes(p)), stat_input)
               return
            end if
            call sync_matrix(a, prefix//'r', run_piece%r, saving)
            call sync_matrix(a, prefix//'v', run_piece%v, saving)
            call sync_matrix(a, prefix//'reaction', run_piece%reaction, saving)
            call sync_real(a, prefix//'tension_ref', run_piece%problem%piece%tension_ref, saving)
            ! Newton's kept factorisation, when a kept one can be used (reuse_jacobian).
            flags = merge(1, 0, [work%usable .and. self%options%newton%reuse_jacobian, work%jacobian%factorised])
            newton_reals = [run_piece%factor_step, work%contraction]
            call sync_ints(a, prefix//'newton_flags', flags, saving)
            call sync_reals(a, prefix//'newton_reals', newton_reals, saving)
            if (.not. saving) then
               work%usable = flags(1) == 1
               work%jacobian%factorised = flags(2) == 1
               run_piece%factor_step = newton_reals(1)
               work%contraction = newton_reals(2)
            end if
            if (flags(1) == 1) then
               call sync_matrix(a, prefix//'jacobian', work%jacobian%ab, saving)
               call sync_ints(a, prefix//'pivots', work%jacobian%ipiv, saving)
            end if
         end associate
      end do

      call exchange_records(self, a, saving, merge(4, 2, self%break_node > 0), error)
   end subroutine exchange_state

   !> Where the step loop stands (run_progress), listed for saving and
   !> loading: the step to try, the good steps since it was halved, the
   !> rejections since the last accepted step, the next snapshot, the wall
   !> time so far. Either model (exchange_state, driver/rod3d_drive.f90).
   subroutine exchange_progress(self, a, saving)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Archive.
      class(state_archive), intent(inout) :: a
      !> Save (.true.) or load.
      logical, intent(in) :: saving
      real(dp) :: wall
      call sync_real(a, 'progress/h', self%progress%h, saving)
      call sync_int(a, 'progress/n_good', self%progress%n_good, saving)
      call sync_int(a, 'progress/rejected_here', self%progress%rejected_here, saving)
      call sync_int(a, 'progress/snapshot_index', self%progress%snapshot_index, saving)
      ! The wall time of the dynamics so far (this process's and the earlier ones').
      if (saving) wall = self%wall_time()
      call sync_real(a, 'progress/wall_time', wall, saving)
      if (.not. saving) self%progress%wall_before = wall
   end subroutine exchange_progress

   !> The records so far, listed for saving and loading: every history
   !> record (with the y components, ends_y, of a 3-D run) and the summary's
   !> counters and extremes. Either model (exchange_state,
   !> driver/rod3d_drive.f90); loading sets up the history with n_ends ends.
   subroutine exchange_records(self, a, saving, n_ends, error, with_y)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Archive.
      class(state_archive), intent(inout) :: a
      !> Save (.true.) or load.
      logical, intent(in) :: saving
      !> Ends of the history (2, or 4 with a break inside the cable).
      integer, intent(in) :: n_ends
      !> Error (stat_input) when the archive's history does not fit.
      type(error_type), allocatable, intent(inout) :: error
      !> The y components too (a 3-D run; default .false.).
      logical, intent(in), optional :: with_y
      integer :: n_records
      logical :: y_kept
      y_kept = .false.
      if (present(with_y)) y_kept = with_y
      ! The history: every record so far.
      n_records = self%history%n
      call sync_int(a, 'history/n', n_records, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (n_records < 0 .or. a%stored_size('history/time') /= n_records + 1) then
            call fatal_error(error, 'the checkpoint''s history has '//str(n_records)//' records but '// &
                             str(a%stored_size('history/time'))//' times', stat_input)
            return
         end if
         if (allocated(self%history%end_labels)) deallocate (self%history%end_labels)
         allocate (self%history%end_labels(n_ends))
         self%history%end_labels(1:2) = [character(len=8) :: 'end_a', 'end_b']
         if (n_ends == 4) self%history%end_labels(3:4) = [character(len=8) :: 'break_a', 'break_b']
         call self%history%reserve(max(n_records, int(min(self%options%t_end/self%dt, real(max_steps, dp)))) + 16, &
                                   n_ends, self%options%energy, with_y=y_kept)
         self%history%n = n_records
      end if
      associate (h => self%history, m => n_records)
         call sync_reals(a, 'history/time', h%time(0:m), saving)
         call sync_reals(a, 'history/step', h%step(0:m), saving)
         call sync_ints(a, 'history/newton_iterations', h%newton_iterations(0:m), saving)
         call sync_ints(a, 'history/rejected', h%rejected(0:m), saving)
         call sync_cube(a, 'history/ends', h%ends(:, :, 0:m), saving)
         if (self%options%energy) call sync_matrix(a, 'history/energy', h%energy(:, 0:m), saving)
         if (y_kept) call sync_cube(a, 'history/ends_y', h%ends_y(:, :, 0:m), saving)
      end associate

      ! The summary's counters and extremes so far (summarise derives the rest at the end).
      associate (s => self%summary)
         call sync_int(a, 'summary/rejected_steps', s%rejected_steps, saving)
         call sync_int(a, 'summary/newton_iterations', s%newton_iterations, saving)
         call sync_int(a, 'summary/max_newton_iterations', s%max_newton_iterations, saving)
         call sync_int(a, 'summary/factorisations', s%factorisations, saving)
         call sync_real(a, 'summary/dt_requested', s%dt_requested, saving)
         call sync_real(a, 'summary/dt_used', s%dt_used, saving)
         call sync_real(a, 'summary/courant_requested', s%courant_requested, saving)
         call sync_real(a, 'summary/max_turning_angle', s%max_turning_angle, saving)
         call sync_real(a, 'summary/min_strain', s%min_strain, saving)
         call sync_real(a, 'summary/min_strain_s', s%min_strain_s, saving)
         call sync_real(a, 'summary/min_strain_time', s%min_strain_time, saving)
         call sync_real(a, 'summary/max_strain', s%max_strain, saving)
      end associate
   end subroutine exchange_records

   !> Snapshots due up to time t_new: inside the step just accepted
   !> (interpolated), or of the static state (static = .true.).
   subroutine emit_snapshots(self, observer, t_new, static, error)
      type(rod_run), intent(inout) :: self
      class(run_observer), intent(inout), optional :: observer
      real(dp), intent(in) :: t_new
      logical, intent(in) :: static
      type(error_type), allocatable, intent(inout) :: error
      type(error_type), allocatable :: output_error
      real(dp) :: ts
      real(dp), allocatable :: v(:, :), extra(:, :)
      do
         ts = snapshot_time(self, self%progress%snapshot_index)
         if (ts > t_new*(1 + 1.0e-12_dp)) exit
         if (.not. allocated(self%buffer)) allocate (self%buffer(self%n_out, n_fields))
         if (static) then
            self%buffer = self%info%fields
            if (self%plane_azimuth /= 0) v = column_velocities(self)
         else
            call interpolated_fields(self, ts, self%buffer, v)
         end if
         if (self%plane_azimuth /= 0) then
            allocate (extra(self%n_out, n_fields3))
            call turned_back(self, self%buffer, v, extra)
         end if
         self%progress%snapshot_index = self%progress%snapshot_index + 1
         if (present(observer)) then
            call observer%snapshot(ts, self%buffer, output_error)
            if (.not. allocated(output_error) .and. allocated(extra)) &
               call observer%snapshot_extra(ts, field3_names, extra, output_error)
            if (allocated(output_error)) then
               call prefix_error(output_error, 'output: ')
               call move_alloc(output_error, error)
               return
            end if
         end if
         if (allocated(extra)) deallocate (extra)
      end do
   end subroutine emit_snapshots

   !> Time of snapshot i (i >= 1); huge when there is none.
   pure real(dp) function snapshot_time(self, i)
      type(rod_run), intent(in) :: self
      integer, intent(in) :: i
      if (self%options%interval > 0) then
         snapshot_time = i*self%options%interval
         if (snapshot_time > self%options%t_end*(1 + 1.0e-9_dp)) snapshot_time = huge(1.0_dp)
      else
         snapshot_time = merge(self%options%t_end, huge(1.0_dp), i == 1)
      end if
   end function snapshot_time

   !> Step control (either model, see the module header): the error when the
   !> wall time of the dynamics so far, wall (s), is past options%max_wall_time.
   subroutine wall_limit(self, wall, error)
      !> Run.
      type(rod_run), intent(in) :: self
      !> Wall time of this process's dynamics, s.
      real(dp), intent(in) :: wall
      !> Error when the limit is reached.
      type(error_type), allocatable, intent(out) :: error
      if (self%options%max_wall_time > 0 .and. wall > self%options%max_wall_time) &
         call fatal_error(error, 'wall-clock limit of '//str(self%options%max_wall_time)//' s reached at t = '// &
                          str(self%t)//' s', stat_numerics)
   end subroutine wall_limit

   !> Step control: the step to try from self%t, progress%h shortened to land
   !> on t_stop (t_end, or the start of the break). Error when it no longer
   !> advances the time.
   subroutine plan_step(self, h_try, t_stop, landing, error)
      !> Run.
      type(rod_run), intent(in) :: self
      !> Step to try and where the run lands (s); whether the step was shortened to land there.
      real(dp), intent(out) :: h_try, t_stop
      logical, intent(out) :: landing
      !> Error when the step no longer advances the time.
      type(error_type), allocatable, intent(out) :: error
      t_stop = self%options%t_end
      if (self%scene%breaks .and. .not. self%broken .and. self%scene%break_time > self%t) &
         t_stop = min(t_stop, self%scene%break_time)
      h_try = self%progress%h
      landing = self%t + h_try >= t_stop*(1 - 1.0e-12_dp) .or. t_stop - (self%t + h_try) < 1.0e-6_dp*self%progress%h
      if (landing) h_try = t_stop - self%t
      ! A step aimed at the crossing of a break by tension (watch_step).
      if (self%watch%h_aim > 0 .and. self%watch%h_aim < h_try) then
         h_try = self%watch%h_aim
         t_stop = self%t + h_try
         landing = .true.
      end if
      if (.not. (self%t + h_try > self%t)) &
         call fatal_error(error, 'step control: the step '//str(h_try)//' s no longer advances the time at t = '// &
                          str(self%t)//' s', stat_numerics)
   end subroutine plan_step

   !> Step control after a rejected attempt: count it; try the same step again
   !> (retry: Newton failed from a kept factorisation, the next attempt takes
   !> a fresh one) or half of it. Error when the run has rejected more than
   !> 1000 + the requested steps, or the step fell below min_step_fraction dt.
   subroutine reject_attempt(self, reason, retry, error)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Why the attempt was rejected.
      character(*), intent(in) :: reason
      !> Whether to retry the same step.
      logical, intent(in) :: retry
      !> Error when the step control gives up.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: max_rejections
      max_rejections = 1000 + self%options%t_end/self%dt
      ! An aim at a crossing (watch_step) is made anew from the next step that passes it.
      self%watch%h_aim = 0
      associate (h => self%progress%h, n_good => self%progress%n_good, rejected_here => self%progress%rejected_here)
         self%summary%rejected_steps = self%summary%rejected_steps + 1
         rejected_here = rejected_here + 1
         if (self%summary%rejected_steps > max_rejections) then
            call fatal_error(error, 'step control: '//str(self%summary%rejected_steps)//' rejected attempts by t = '// &
                             str(self%t)//' s: the step stays far below dt = '//str(self%dt)//' s; last: '//reason// &
                             '; try a smaller dt or courant, or theta = 0.55', stat_numerics)
            return
         end if
         if (retry) return
         h = 0.5_dp*h
         n_good = 0
         if (h < self%dt*self%options%min_step_fraction) &
            call fatal_error(error, 'step control: step fell below '//str(self%dt*self%options%min_step_fraction)// &
                             ' s at t = '//str(self%t)//' s after '//str(rejected_here)//' rejected attempts; last: '// &
                             reason//'; try a smaller dt or courant, more nodes, or theta = 0.55', stat_numerics)
      end associate
   end subroutine reject_attempt

   !> The search for a break by tension on a step of h from self%t just solved (either model):
   !> the cell tensions of the law at the old level r_old and the new level r_new (positions,
   !> (2 or 3, n)). A step whose largest cell tension F passes watch%mbl by more than
   !> rupture_tolerance mbl starts a search on the step from self%t: it is taken again (retry)
   !> with watch%h_aim, first the earliest time at which a cell's tension, linear between the
   !> two levels, reaches mbl, then by false position (Illinois) on F of the step's length
   !> within the bracket of the steps tried, until F is within rupture_tolerance mbl of mbl
   !> (or max_rupture_aims steps were tried): watch%found, its time, cell and tension. A step
   !> that does not pass mbl is kept, and the largest tension so far updated.
   subroutine watch_step(self, h, r_old, r_new, ds, law, retry)
      !> Run (its watch).
      type(rod_run), intent(inout) :: self
      !> The step, s.
      real(dp), intent(in) :: h
      !> Node positions at the old and the new level, m.
      real(dp), intent(in) :: r_old(:, :), r_new(:, :)
      !> Unstretched cell lengths, m.
      real(dp), intent(in) :: ds(:)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Whether the step is to be taken again with watch%h_aim.
      logical, intent(out) :: retry
      real(dp) :: t_old(size(ds)), t_new(size(ds)), frac, f
      integer :: c, m
      m = size(ds)
      do c = 1, m
         t_old(c) = law%tension(norm2(r_old(:, c + 1) - r_old(:, c))/ds(c) - 1)
         t_new(c) = law%tension(norm2(r_new(:, c + 1) - r_new(:, c))/ds(c) - 1)
      end do
      retry = .false.
      associate (w => self%watch)
         c = maxloc(t_new, 1)
         f = t_new(c)
         if (w%h_aim == 0) then
            ! A step of the run: it passes mbl, reaches it, or stays below.
            if (f > w%mbl*(1 + rupture_tolerance)) then
               frac = 1
               do c = 1, m
                  if (t_new(c) >= w%mbl .and. t_new(c) > t_old(c)) &
                     frac = min(frac, max(w%mbl - t_old(c), 0.0_dp)/(t_new(c) - t_old(c)))
               end do
               w%h_lo = 0
               w%f_lo = maxval(t_old)
               w%h_hi = h
               w%f_hi = f
               w%side = 0
               w%h_aim = min(max(frac, 1.0e-3_dp), 1 - 1.0e-3_dp)*h
               w%aims = 1
               retry = .true.
               return
            end if
         else if (abs(f - w%mbl) > rupture_tolerance*w%mbl .and. w%aims < max_rupture_aims) then
            ! An aimed step that missed: narrow the bracket, aim again (false position, Illinois).
            if (f > w%mbl) then
               w%h_hi = h
               w%f_hi = f
               if (w%side == 1) w%f_lo = w%mbl - 0.5_dp*(w%mbl - w%f_lo)
               w%side = 1
            else
               w%h_lo = h
               w%f_lo = f
               if (w%side == -1) w%f_hi = w%mbl + 0.5_dp*(w%f_hi - w%mbl)
               w%side = -1
            end if
            w%h_aim = w%h_lo + (w%mbl - w%f_lo)/(w%f_hi - w%f_lo)*(w%h_hi - w%h_lo)
            if (.not. (w%h_aim > w%h_lo .and. w%h_aim < w%h_hi)) w%h_aim = 0.5_dp*(w%h_lo + w%h_hi)
            w%aims = w%aims + 1
            retry = .true.
            return
         end if
         w%h_aim = 0
         if (f > w%max_tension) then
            w%max_tension = f
            w%max_s = 0.5_dp*(self%s(c) + self%s(c + 1))
            w%max_time = self%t + h
         end if
         if (f >= w%mbl*(1 - rupture_tolerance)) then
            w%found = .true.
            w%time = self%t + h
            w%cell = c
            w%tension = f
            w%s = 0.5_dp*(self%s(c) + self%s(c + 1))
            w%cells = t_new
         end if
      end associate
   end subroutine watch_step

   !> Step control after an accepted step of h_try: the time moves on (onto
   !> t_stop when it lands there), the step taken is recorded, and after four
   !> good steps a halved step doubles back towards dt.
   subroutine advance_time(self, h_try, t_stop, landing)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> The step taken and the time it was to land on (plan_step), s; whether it was shortened to land there.
      real(dp), intent(in) :: h_try, t_stop
      logical, intent(in) :: landing
      self%t = self%t + h_try
      if (abs(self%t - t_stop) <= 1.0e-12_dp*max(t_stop, 1.0_dp)) self%t = t_stop
      ! The step taken: a step shortened only to land on t_end or the break is not a change of dt.
      if (.not. landing) self%summary%dt_used = max(self%summary%dt_used, h_try)
      associate (h => self%progress%h, n_good => self%progress%n_good)
         if (h < self%dt) then
            n_good = n_good + 1
            if (n_good >= 4) then
               h = min(2*h, self%dt)
               n_good = 0
            end if
         end if
      end associate
   end subroutine advance_time

   !> Whether a Newton solve with opts starts from the kept factorisation of work.
   pure logical function jacobian_kept(opts, work)
      !> Newton controls and work arrays.
      type(newton_options), intent(in) :: opts
      type(newton_workspace), intent(in) :: work
      jacobian_kept = opts%reuse_jacobian .and. work%usable .and. work%contraction <= opts%refresh_contraction
   end function jacobian_kept

   !> Whether an end moves or changes its load in time.
   logical function ends_change(self)
      type(rod_run), intent(in) :: self
      ends_change = self%scene%end_a%time_dependent() .or. self%scene%end_b%time_dependent()
   end function ends_change

   !> Newton controls of a time step (see the module header).
   function step_newton(self) result(opts)
      type(rod_run), intent(in) :: self
      type(newton_options) :: opts
      opts = self%options%newton
      opts%estimate_error = .true.
      opts%max_contraction = 0.5_dp
      opts%refresh_contraction = 0.05_dp
      ! No full residual at the converged point: attempt evaluates there only what the
      ! accepted state needs (rod_problem%accepted_state: the geometry, the memo, the end
      ! cells' forces for the reactions). Nothing reads the final residual's norm.
      opts%final_residual = .false.
   end function step_newton

   !> One Newton solve of piece p for the step from self%t to self%t + h.
   !>
   !> Skip of the quiescent cable (options%skip_quiescent): ahead of a front the
   !> cable keeps its state to round-off, and solving there changes nothing. The
   !> step is solved on a window of nodes (choose_window: those that moved in the
   !> last step by more than quiet_fraction newton_tol cell lengths, or quiet_ulps
   !> units of round-off of the largest coordinate when that is more, the ends whose
   !> conditions change, and margin nodes on either side); the nodes outside keep
   !> their positions (they are boundary data of the window's rows). After the
   !> solve, the window's outer nodes on a held side (check_nodes of them) must
   !> have moved by at most the same threshold; otherwise the motion has reached the
   !> margin, the window grows by 2 margin nodes on that side and the step is
   !> solved again from the first guess. A failed solve on a window is redone on
   !> the whole piece. The whole piece is solved at the first step of the dynamics,
   !> with distributed loads, with a kept Jacobian (reuse_jacobian), and whenever no
   !> node moved (nothing to centre a window on).
   subroutine attempt(self, p, h, kept, iterations, error)
      type(rod_run), intent(inout) :: self
      integer, intent(in) :: p
      real(dp), intent(in) :: h
      logical, intent(out) :: kept
      integer, intent(inout) :: iterations
      type(error_type), allocatable, intent(out) :: error
      type(newton_options) :: opts
      type(newton_report) :: report
      integer :: n, lo, hi, lo_new, hi_new
      real(dp) :: quiet
      associate (piece => self%pieces(p))
         n = piece%problem%piece%n
         piece%problem%t0 = self%t
         piece%problem%dt = h
         piece%problem%theta = self%options%theta
         call piece%problem%piece%prepare_step(piece%r, piece%v)
         ! A factorisation made for another step size is stale (the mass term goes as 1/dt^2).
         if (abs(piece%factor_step - h) > 1.0e-12_dp*h) piece%work%usable = .false.
         opts = step_newton(self)
         kept = jacobian_kept(opts, piece%work)
         call choose_window(self, p, h, opts%tolerance, lo, hi, quiet)
         do
            call first_guess(lo, hi)
            piece%problem%lo = lo
            piece%problem%hi = hi
            call newton_solve(piece%problem, piece%x(2*lo - 1:2*hi), piece%work, opts, report, error)
            iterations = max(iterations, report%iterations)
            if (report%factorisations > 0) piece%factor_step = h
            self%summary%factorisations = self%summary%factorisations + report%factorisations
            self%summary%newton_iterations = self%summary%newton_iterations + report%iterations
            self%node_solves = self%node_solves + n
            self%skipped_node_solves = self%skipped_node_solves + (n - (hi - lo + 1))
            if (lo == 1 .and. hi == n) exit
            if (allocated(error)) then
               ! In doubt, the whole piece.
               deallocate (error)
               self%window_fallbacks = self%window_fallbacks + 1
               lo = 1
               hi = n
               cycle
            end if
            lo_new = lo
            hi_new = hi
            if (lo > 1) then
               if (moved(lo, lo + check_nodes - 1) > quiet) lo_new = max(1, lo - 2*window_margin)
            end if
            if (hi < n) then
               if (moved(hi - check_nodes + 1, hi) > quiet) hi_new = min(n, hi + 2*window_margin)
            end if
            if (lo_new == lo .and. hi_new == hi) exit
            self%window_growths = self%window_growths + 1
            lo = lo_new
            hi = hi_new
         end do
         ! The converged state: what check_state, accept (the reactions), record and the next
         ! step take from the last evaluation (in place of Newton's final residual).
         if (.not. allocated(error)) call piece%problem%accepted_state(piece%x(2*lo - 1:2*hi))
         piece%problem%lo = 1
         piece%problem%hi = 0
      end associate

   contains

      !> The first guess R + h V (or R) of the window's nodes, the old positions elsewhere.
      subroutine first_guess(k1, k2)
         integer, intent(in) :: k1, k2
         associate (piece => self%pieces(p))
            if (k1 > 1 .or. k2 < n) call piece%problem%piece%freeze_level()
            if (allocated(piece%x)) then
               if (size(piece%x) /= 2*n) deallocate (piece%x)
            end if
            if (.not. allocated(piece%x)) allocate (piece%x(2*n))
            call guess_positions(n, k1, k2, self%options%extrapolate, h, piece%r, piece%v, piece%x)
            if (k1 == 1 .and. piece%problem%piece%end_a%held()) &
               piece%x(1:2) = piece%problem%piece%end_a%position(self%t + h)
            if (k2 == n .and. piece%problem%piece%end_b%held()) &
               piece%x(2*n - 1:2*n) = piece%problem%piece%end_b%position(self%t + h)
         end associate
      end subroutine first_guess

      !> Largest displacement of the nodes k1 .. k2 in the step solved, m.
      real(dp) function moved(k1, k2)
         integer, intent(in) :: k1, k2
         integer :: k
         moved = 0
         associate (piece => self%pieces(p))
            do k = max(1, k1), min(n, k2)
               moved = max(moved, abs(piece%x(2*k - 1) - piece%r(1, k)), abs(piece%x(2*k) - piece%r(2, k)))
            end do
         end associate
      end function moved
   end subroutine attempt

   !> Newton's first guess for a step of h: x = R + h V on the nodes k1 .. k2 (R with
   !> extrapolate false), x = R on the others. (A routine of its own, element by
   !> element: in attempt the array expressions with reshape made temporaries, and loops
   !> there reloaded the components' descriptors at every element; attempt's own
   !> instructions on fast_180kN 12.2e6 -> 7.4e6, callgrind; the same values.)
   pure subroutine guess_positions(n, k1, k2, extrapolate, h, r, v, x)
      integer, intent(in) :: n, k1, k2
      logical, intent(in) :: extrapolate
      real(dp), intent(in) :: h, r(2, n), v(2, n)
      real(dp), intent(out) :: x(2*n)
      integer :: k, a
      do k = 1, n
         do a = 1, 2
            x(2*k - 2 + a) = r(a, k)
         end do
      end do
      if (.not. extrapolate) return
      do k = k1, k2
         do a = 1, 2
            x(2*k - 2 + a) = r(a, k) + h*v(a, k)
         end do
      end do
   end subroutine guess_positions

   !> The window of nodes lo .. hi on which the step of h from self%t solves piece p
   !> (attempt): the nodes whose last step moved them, h |V| > quiet (m), the end nodes
   !> whose end conditions change over the step, window_margin nodes on either side;
   !> the whole piece (1 .. n) when the skip is off or not applicable.
   subroutine choose_window(self, p, h, tolerance, lo, hi, quiet)
      type(rod_run), intent(in) :: self
      integer, intent(in) :: p
      !> The step (s) and Newton's tolerance.
      real(dp), intent(in) :: h, tolerance
      integer, intent(out) :: lo, hi
      !> The motion in a step below which a node is quiet, m.
      real(dp), intent(out) :: quiet
      integer :: n, k, first, last
      associate (piece => self%pieces(p), rod => self%pieces(p)%problem%piece)
         n = rod%n
         lo = 1
         hi = n
         quiet = 0
         if (.not. self%options%skip_quiescent .or. self%options%newton%reuse_jacobian) return
         ! Quiet: a motion far below the tolerance, or at the round-off of the coordinates
         ! (where the whole solve moves the quiescent nodes too, by a few units in the last place).
         ! (largest_magnitude on the 2 n values: the intrinsic on piece%r took 33 instructions a
         ! node; with it attempt's own instructions on fast_180kN went 7.4e6 -> 3.5e6, callgrind.)
         quiet = max(quiet_fraction*tolerance*rod%length_ref, quiet_ulps*epsilon(1.0_dp)*largest_magnitude(2*n, piece%r))
         if (self%history%n <= 0) return
         if (allocated(rod%loads)) then
            if (size(rod%loads) > 0) return
         end if
         if (n < 2*window_margin + 4) return
         first = n + 1
         last = 0
         if (.not. end_steady(rod%end_a, self%t, self%t + h)) then
            first = 1
            last = 1
         end if
         if (.not. end_steady(rod%end_b, self%t, self%t + h)) then
            first = min(first, n)
            last = n
         end if
         do k = 1, n
            if (h*max(abs(piece%v(1, k)), abs(piece%v(2, k))) > quiet .or. .not. ieee_is_finite(sum(piece%v(:, k)))) then
               first = min(first, k)
               exit
            end if
         end do
         do k = n, 1, -1
            if (h*max(abs(piece%v(1, k)), abs(piece%v(2, k))) > quiet .or. .not. ieee_is_finite(sum(piece%v(:, k)))) then
               last = max(last, k)
               exit
            end if
         end do
         ! Nothing moves: nothing to centre a window on.
         if (last == 0) return
         lo = max(1, first - window_margin)
         hi = min(n, last + window_margin)
      end associate
   end subroutine choose_window

   !> Whether an end's condition stays the same over [ta, tb]: an end that does not change
   !> with time (a fixed end, a free end, a point mass, a constant force, a spring; not a
   !> moving end nor a force history).
   logical function end_steady(end, ta, tb)
      class(end_condition), intent(in) :: end
      real(dp), intent(in) :: ta, tb
      end_steady = .not. end%time_dependent()
      if (.not. end_steady) return
      end_steady = all(same_value(end%applied_force(ta), end%applied_force(tb))) .and. &
                   same_value(end%applied_couple(ta), end%applied_couple(tb))
   end function end_steady

   !> a == b as numbers (elemental).
   elemental logical function same_value(a, b)
      real(dp), intent(in) :: a, b
      same_value = a == b
   end function same_value

   !> Reject states outside the model's range (after an attempt on every piece).
   subroutine check_state(self, h, error)
      type(rod_run), intent(inout) :: self
      real(dp), intent(in) :: h
      type(error_type), allocatable, intent(out) :: error
      integer :: p, k
      real(dp), allocatable :: dphi(:), fold(:)
      do p = 1, size(self%pieces)
         associate (piece => self%pieces(p)%problem%piece, x => self%pieces(p)%x)
            ! The last evaluation (accepted_state) was at x: e1, l1, th1 are those of the new level.
            call check_range(x, piece%l1, piece%law, p, error)
            if (allocated(error)) return
            ! Each cell's rotation once, the last evaluation's where it was at x (cell_rotations).
            if (allocated(dphi)) deallocate (dphi, fold)
            allocate (dphi(piece%n - 1), fold(piece%n))
            call cell_rotations(piece, reshape(x, [2, piece%n]), dphi)
            fold = 0
            do k = 2, piece%n - 1
               fold(k) = abs(piece%th1(k) - piece%th0(k) - (dphi(k) - dphi(k - 1)))
            end do
            call check_folds(fold, p, h, error)
            if (allocated(error)) return
         end associate
      end do
   end subroutine check_state

   !> The model's range after an attempt on piece p (either model): finite
   !> unknowns x and no cell squeezed below 5 % of its length (l: cell lengths
   !> / unstretched lengths at the new level). Error stat_numerics naming the first.
   subroutine check_range(x, l, law, p, error)
      !> Unknowns of the new level; cell length ratios.
      real(dp), intent(in) :: x(:), l(:)
      !> The piece's law (for the advice) and its index.
      class(material_law), intent(in) :: law
      integer, intent(in) :: p
      type(error_type), allocatable, intent(out) :: error
      integer :: c
      if (.not. all(ieee_is_finite(x))) then
         call fatal_error(error, 'non-finite positions in piece '//str(p), stat_numerics)
         return
      end if
      do c = 1, size(l)
         if (l(c) < 0.05_dp) then
            call fatal_error(error, 'cell '//str(c)//' of piece '//str(p)//' squeezed to '// &
                             str(100*l(c))//' % of its length (strain '//str(l(c) - 1)// &
                             '): the compressed zone has collapsed'//trim(squeeze_advice(law)), stat_numerics)
            return
         end if
      end do
   end subroutine check_range

   !> The model's range (either model): no turning angle passed half a turn
   !> within the step of h s. fold(k) is how far node k's change of turning
   !> angle in the step is from the change its two cells' rotations give (rad:
   !> near 0, or near 2 pi when the angle went through half a turn); error
   !> stat_numerics for the first node above 3 rad (or not a number).
   subroutine check_folds(fold, p, h, error)
      !> Mismatch at each node (0 at the ends), rad.
      real(dp), intent(in) :: fold(:)
      !> Piece index; the step, s.
      integer, intent(in) :: p
      real(dp), intent(in) :: h
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      do k = 1, size(fold)
         if (.not. (fold(k) <= 3.0_dp)) then
            call fatal_error(error, 'the turning angle at node '//str(k)//' of piece '//str(p)// &
                             ' passed half a turn within one step of '//str(h)//' s (a fold)', stat_numerics)
            return
         end if
      end do
   end subroutine check_folds

   !> What to try when a cell collapses.
   function squeeze_advice(law) result(advice)
      class(material_law), intent(in) :: law
      character(:), allocatable :: advice
      if (index(law%name(), 'without compression') > 0) then
         advice = ' (with compression = ''none'' nothing resists the shortening of the cable: the slack material '// &
                  'piles up into the cells; the law''s compressive branch, compression = ''law'', resists it)'
      else
         advice = ' (more nodes resolve the buckling, or a smaller dt or courant)'
      end if
   end function squeeze_advice

   !> Accept the step of length h: new velocities, the reactions at held ends,
   !> the work and the dissipation of the step, and the resolution figures.
   subroutine accept(self, h)
      type(rod_run), intent(inout) :: self
      real(dp), intent(in) :: h
      integer :: p, n
      real(dp), allocatable :: r1(:, :), v1(:, :), dv(:, :), mdv(:, :)
      real(dp) :: theta, dphi, f(2)
      theta = self%options%theta
      do p = 1, size(self%pieces)
         associate (run_piece => self%pieces(p), piece => self%pieces(p)%problem%piece)
            n = piece%n
            r1 = reshape(run_piece%x, [2, n])
            allocate (v1(2, n))
            call piece%new_velocity(r1, h, theta, v1)
            if (piece%end_a%held()) run_piece%reaction(:, 1) = piece%reaction(1, run_piece%x, h, theta)
            if (piece%end_b%held()) run_piece%reaction(:, 2) = piece%reaction(n, run_piece%x, h, theta)
            if (self%options%energy) then
               ! Work of the ends: applied force (mean over the step) or reaction, times the displacement.
               call end_work(piece%end_a, 1, 1)
               call end_work(piece%end_b, n, 2)
               ! Distributed loads: their force on each node (centred on the step) times its displacement.
               self%load_work = self%load_work + displacement_work(n, piece%load_node, r1, run_piece%r)
               ! Internal damping: each cell dissipates ds c (eps1 - eps0)^2 / dt; a rope that
               ! cannot push, ds (N - q) (eps1 - eps0) (slack_cell_force).
               if (piece%damping > 0) then
                  if (piece%law%strain_slack > -huge(1.0_dp)) then
                     self%dissipation = self%dissipation + sum(piece%ds*slack_dissipation(piece%law, piece%l0 - 1, &
                                                               piece%l1 - 1, piece%damping, h, small_strain_step))
                  else
                     self%dissipation = self%dissipation + piece%damping*sum(piece%ds*(piece%l1 - piece%l0)**2)/h
                  end if
               end if
               ! Ends that depend on their state (springs): their damping's work over the step.
               if (piece%end_a%state_dependent()) call end_damping(piece%end_a, 1)
               if (piece%end_b%state_dependent()) call end_damping(piece%end_b, n)
               if (theta /= 0.5_dp) then
                  dv = v1 - run_piece%v
                  allocate (mdv(2, n))
                  call piece%mass_times(dv, mdv)
                  self%dissipation = self%dissipation + (theta - 0.5_dp)*sum(dv*mdv)
                  deallocate (mdv)
               end if
            end if
            self%summary%max_turning_angle = max(self%summary%max_turning_angle, maxval(abs(piece%th1)))
            call note_min_strain(self%summary, piece%l1, run_piece%column, self%s_out, self%t + h)
            self%summary%max_strain = max(self%summary%max_strain, maxval(piece%l1) - 1)
            ! The levels change hands without copies (four copies of (2, n) through the
            ! components' descriptors cost 21 million instructions on fast_180kN).
            call move_alloc(run_piece%r, run_piece%r_prev)
            call move_alloc(run_piece%v, run_piece%v_prev)
            call move_alloc(r1, run_piece%r)
            call move_alloc(v1, run_piece%v)
         end associate
      end do

   contains

      !> What the damping of a state-dependent end at node `node` took in the step: minus the
      !> work of the damping part of its step force (the elastic part is the change of its
      !> stored energy, which the energies hold).
      subroutine end_damping(end, node)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: node
         real(dp) :: x0(3), x1(3), f3(3), j3(3, 3), damp(3)
         associate (run_piece => self%pieces(p))
            x0 = [run_piece%r(1, node), 0.0_dp, run_piece%r(2, node)]
            x1 = [r1(1, node), 0.0_dp, r1(2, node)]
            call end%step_force(self%t, h, x0, x1, f3, j3, damp)
            self%dissipation = self%dissipation - dot_product(damp, x1 - x0)
         end associate
      end subroutine end_damping

      !> Work of one end in the step: force times displacement, couple times the end cell's rotation.
      subroutine end_work(end, node, side)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: node, side
         integer :: cell
         associate (run_piece => self%pieces(p), piece => self%pieces(p)%problem%piece)
            if (end%held()) then
               f = run_piece%reaction(:, side)
            else
               f = 0.5_dp*(end%applied_force(self%t) + end%applied_force(self%t + h))
            end if
            self%work = self%work + dot_product(f, r1(:, node) - run_piece%r(:, node))
            cell = merge(1, n - 1, side == 1)
            dphi = atan2(cross2(piece%e0(:, cell), piece%e1(:, cell)), dot_product(piece%e0(:, cell), piece%e1(:, cell)))
            self%work = self%work + 0.5_dp*(end%applied_couple(self%t) + end%applied_couple(self%t + h))*dphi
         end associate
      end subroutine end_work
   end subroutine accept

   !> sum(f*(r1 - r0)) over (2, n) arrays, in the order of that expression (element
   !> by element, column by column), on explicit-shape arrays: the expression on the
   !> pieces' components took 10 700 instructions a step on fast_180kN.
   pure real(dp) function displacement_work(n, f, r1, r0) result(w)
      !> Nodes.
      integer, intent(in) :: n
      !> Forces (2, n), N.
      real(dp), intent(in) :: f(2, n)
      !> Positions at the end and start of the step (2, n), m.
      real(dp), intent(in) :: r1(2, n), r0(2, n)
      integer :: k
      w = 0
      do k = 1, n
         w = w + f(1, k)*(r1(1, k) - r0(1, k))
         w = w + f(2, k)*(r1(2, k) - r0(2, k))
      end do
   end function displacement_work

   !> End labels and the record of the static state (index 0).
   subroutine start_history(self)
      type(rod_run), intent(inout) :: self
      integer :: n_ends
      n_ends = merge(4, 2, self%break_node > 0)
      allocate (self%history%end_labels(n_ends))
      self%history%end_labels(1:2) = [character(len=8) :: 'end_a', 'end_b']
      if (n_ends == 4) self%history%end_labels(3:4) = [character(len=8) :: 'break_a', 'break_b']
      self%pieces(1)%end_slot = [1, 2]
      self%pieces(1)%reaction(:, 1) = self%static%reaction_a
      self%pieces(1)%reaction(:, 2) = self%static%reaction_b
      call self%history%reserve(16, n_ends, self%options%energy)
      self%history%n = -1
      call record(self, 0, 0, 0.0_dp)
   end subroutine start_history

   !> Append a history record at the current time.
   subroutine record(self, iterations, rejected, step)
      type(rod_run), intent(inout) :: self
      integer, intent(in) :: iterations, rejected
      real(dp), intent(in) :: step
      integer :: i, p, side, node, slot
      real(dp) :: en(4), e(2), f(2), ten
      if (self%history%n + 1 > ubound(self%history%time, 1)) &
         call self%history%reserve(2*ubound(self%history%time, 1), size(self%history%end_labels), self%options%energy)
      i = self%history%n + 1
      self%history%n = i
      self%history%time(i) = self%t
      self%history%step(i) = step
      self%history%newton_iterations(i) = iterations
      self%history%rejected(i) = rejected
      if (i > 0) self%summary%max_newton_iterations = max(self%summary%max_newton_iterations, iterations)
      en = 0
      do p = 1, size(self%pieces)
         associate (run_piece => self%pieces(p), piece => self%pieces(p)%problem%piece)
            do side = 1, 2
               slot = run_piece%end_slot(side)
               if (slot == 0) cycle
               node = merge(1, piece%n, side == 1)
               ten = end_tension(piece, run_piece%r, side)
               if (side == 1) then
                  if (piece%end_a%held()) then
                     f = run_piece%reaction(:, 1)
                  else
                     f = piece%end_a%applied_force(self%t)
                     if (piece%end_a%state_dependent()) f = f + state_force(piece%end_a, node)
                  end if
               else
                  if (piece%end_b%held()) then
                     f = run_piece%reaction(:, 2)
                  else
                     f = piece%end_b%applied_force(self%t)
                     if (piece%end_b%state_dependent()) f = f + state_force(piece%end_b, node)
                  end if
               end if
               self%history%ends(:, slot, i) = [run_piece%r(:, node), run_piece%v(:, node), ten, f]
            end do
            if (self%options%energy) then
               call piece%complete_memo()
               call piece%geometry(run_piece%r, piece%e1, piece%l1, piece%th1)
               en = en + piece%energies(run_piece%r, run_piece%v, piece%l1, piece%th1)
            end if
         end associate
      end do
      ! Before a break inside the cable, its two ends are the break node: the
      ! pull of the cable on either side (mean tension of the node's two cells).
      if (size(self%pieces) == 1 .and. self%break_node > 0) then
         associate (r => self%pieces(1)%r, v => self%pieces(1)%v, k => self%break_node, &
                    piece => self%pieces(1)%problem%piece)
            e = r(:, k + 1) - r(:, k)
            f = piece%law%tension(norm2(e)/piece%ds(k) - 1)*e/norm2(e)
            ten = 0.5_dp*(norm2(f) + piece%law%tension(norm2(r(:, k) - r(:, k - 1))/piece%ds(k - 1) - 1))
            self%history%ends(:, 3, i) = [r(:, k), v(:, k), ten, f]
            e = r(:, k) - r(:, k - 1)
            f = -piece%law%tension(norm2(e)/piece%ds(k - 1) - 1)*e/norm2(e)
            self%history%ends(:, 4, i) = [r(:, k), v(:, k), ten, f]
         end associate
      end if
      if (self%options%energy) then
         self%history%energy(1:4, i) = en
         self%history%energy(5, i) = self%work
         self%history%energy(6, i) = self%dissipation
         self%history%energy(7, i) = sum(en) - self%work - self%load_work + self%dissipation
         self%history%energy(8, i) = self%load_work
      end if

   contains

      !> The force of a state-dependent end's own state at its node (x, z), N.
      function state_force(end, node) result(force)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: node
         real(dp) :: force(2), f3(3), dx(3, 3), dv(3, 3), damp(3)
         associate (run_piece => self%pieces(p))
            call end%state_force(self%t, [run_piece%r(1, node), 0.0_dp, run_piece%r(2, node)], &
                                 [run_piece%v(1, node), 0.0_dp, run_piece%v(2, node)], f3, dx, dv, damp)
         end associate
         force = f3([1, 3])
      end function state_force
   end subroutine record

   !> Tension at an end of a piece (side 1: node 1, side 2: node n), from its
   !> end cells by end_value, and not below the law's tension at the strain
   !> -0.99 (a steep, buckled end would extrapolate past what the law can give).
   function end_tension(piece, r, side) result(t_end)
      type(rod_piece), intent(in) :: piece
      real(dp), intent(in) :: r(:, :)
      integer, intent(in) :: side
      real(dp) :: t_end, cells(3)
      integer :: n, j, c
      n = piece%n
      do j = 1, min(3, n - 1)
         c = merge(j, n - j, side == 1)
         cells(j) = piece%law%tension(norm2(r(:, c + 1) - r(:, c))/piece%ds(c) - 1)
      end do
      t_end = max(end_value(cells(1:min(3, n - 1)), 1), piece%law%tension(-0.99_dp))
   end function end_tension

   !> Fields at time ts inside the step just accepted (from self%t to the new
   !> level): cubic Hermite in the positions and velocities of its two ends.
   subroutine interpolated_fields(self, ts, fields, velocities)
      type(rod_run), intent(inout) :: self
      real(dp), intent(in) :: ts
      real(dp), intent(out) :: fields(:, :)
      !> The interpolated velocities on the output columns (2, n_out).
      real(dp), allocatable, intent(out), optional :: velocities(:, :)
      real(dp), allocatable :: r(:, :), v(:, :)
      real(dp) :: h, u, h00, h10, h01, h11, d00, d10, d01, d11
      integer :: p
      allocate (r(2, self%n_out), v(2, self%n_out))
      do p = 1, size(self%pieces)
         associate (rp => self%pieces(p))
            h = self%history%time(self%history%n) ! placeholder, replaced below
            h = rp%problem%dt
            u = (ts - self%t)/h
            u = min(max(u, 0.0_dp), 1.0_dp)
            h00 = (1 + 2*u)*(1 - u)**2
            h10 = u*(1 - u)**2
            h01 = u*u*(3 - 2*u)
            h11 = u*u*(u - 1)
            d00 = 6*u*u - 6*u
            d10 = 3*u*u - 4*u + 1
            d01 = 6*u - 6*u*u
            d11 = 3*u*u - 2*u
            r(:, rp%column) = h00*rp%r_prev + h10*h*rp%v_prev + h01*rp%r + h11*h*rp%v
            v(:, rp%column) = (d00*rp%r_prev + d01*rp%r)/h + d10*rp%v_prev + d11*rp%v
         end associate
      end do
      call self%fields(fields, r, v)
      if (present(velocities)) then
         if (size(self%pieces) == 1 .and. self%break_node > 0) v(:, self%break_node + 1) = v(:, self%break_node)
         call move_alloc(v, velocities)
      end if
   end subroutine interpolated_fields

   !> The break: split the piece at the break node into two, or release a held
   !> end. The new ends carry the force (and at an inner break the moment) that
   !> held them at the break time, ramped to zero over t_break (eqs. 31-32).
   subroutine split(self, error)
      type(rod_run), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: x(:), res(:)
      type(band_matrix) :: unused
      integer :: n, kb, p
      real(dp) :: w_a, w_b, m_b
      n = self%pieces(1)%problem%piece%n
      if (self%scene%break_at_a .or. self%scene%break_at_b) then
         ! The held end lets go with the support's force at the break time.
         if (self%scene%break_at_b) then
            self%cut_force(:, 1) = self%pieces(1)%reaction(:, 2)
         else
            self%cut_force(:, 1) = self%pieces(1)%reaction(:, 1)
         end if
         call apply_split(self)
         return
      end if
      ! Inside: the elastic cell forces at the current positions.
      kb = self%break_node
      associate (piece => self%pieces(1)%problem%piece)
         x = reshape(self%pieces(1)%r, [2*n])
         allocate (res(2*n))
         call piece%static_system(x, self%t, res, unused, .false.)
         w_a = 0.5_dp*piece%weight*piece%ds(kb - 1)
         w_b = 0.5_dp*piece%weight*piece%ds(kb)
         m_b = bend_moment(piece, kb, piece%th1(kb))
         self%cut_force(:, 1) = piece%force(:, kb - 1) + [0.0_dp, w_a]
         self%cut_force(:, 2) = -piece%force(:, kb) + [0.0_dp, w_b]
         self%cut_couple = [m_b, -m_b]
         ! The bending energy at the break node leaves with the cut: booked as work.
         self%work = self%work - bend_energy(piece, kb, piece%th1(kb))
      end associate
      call apply_split(self)
      ! Distributed loads: each new end node keeps its own cell's share (the pieces' loads at rest),
      ! so that both pieces start in the balance the whole cable had.
      if (.not. allocated(self%pieces(1)%problem%piece%loads)) return
      do p = 1, 2
         associate (piece => self%pieces(p)%problem%piece)
            x = reshape(self%pieces(p)%r, [2*piece%n])
            res = x
            call piece%static_system(x, self%t, res, unused, .false.)
            self%cut_force(:, p) = self%cut_force(:, p) - piece%load_node(:, merge(piece%n, 1, p == 1))
         end associate
      end do
      select type (end => self%pieces(1)%problem%piece%end_b)
      type is (force_end)
         end%force0 = self%cut_force(:, 1)
      end select
      select type (end => self%pieces(2)%problem%piece%end_a)
      type is (force_end)
         end%force0 = self%cut_force(:, 2)
      end select
   end subroutine split

   !> The pieces after the break, with new ends that start from self%cut_force
   !> and cut_couple: the released end replaced (a break at an end), or the
   !> piece cut in two at the break node, each new piece taking the positions,
   !> velocities, output columns, history slots and reactions of its nodes.
   !> Also rebuilds the pieces of a broken run loaded from a checkpoint.
   subroutine apply_split(self)
      type(rod_run), intent(inout) :: self
      type(piece_run), allocatable :: old(:)
      type(force_end) :: cut_a, cut_b
      integer :: n, kb
      self%broken = .true.
      n = self%pieces(1)%problem%piece%n
      cut_a = force_end(kind_name='break', history='ramp', t0=self%scene%break_time, duration=self%scene%t_break, &
                        force0=self%cut_force(:, 1), couple0=self%cut_couple(1))
      if (self%scene%break_at_a .or. self%scene%break_at_b) then
         associate (piece => self%pieces(1)%problem%piece)
            if (self%scene%break_at_b) then
               cut_a%label = 'end_b'
               deallocate (piece%end_b)
               allocate (piece%end_b, source=cut_a)
            else
               cut_a%label = 'end_a'
               deallocate (piece%end_a)
               allocate (piece%end_a, source=cut_a)
            end if
         end associate
         self%pieces(1)%work%usable = .false.
         return
      end if
      kb = self%break_node
      cut_b = force_end(kind_name='break', history='ramp', t0=self%scene%break_time, duration=self%scene%t_break, &
                        force0=self%cut_force(:, 2), couple0=self%cut_couple(2))
      cut_a%label = 'break_a'
      cut_b%label = 'break_b'
      call move_alloc(self%pieces, old)
      allocate (self%pieces(2))
      associate (whole => old(1)%problem%piece)
         call self%pieces(1)%problem%piece%init(self%s(1:kb), whole%mass_per_length, whole%weight, whole%ei, whole%gravity, &
                                                 whole%mu, whole%law, whole%end_a, cut_a, whole%tension_ref, whole%mu2, &
                                                 whole%damping)
         call self%pieces(2)%problem%piece%init(self%s(kb:n), whole%mass_per_length, whole%weight, whole%ei, whole%gravity, &
                                                 whole%mu, whole%law, cut_b, whole%end_b, whole%tension_ref, whole%mu2, &
                                                 whole%damping)
         if (allocated(whole%loads)) then
            self%pieces(1)%problem%piece%loads = whole%loads
            self%pieces(2)%problem%piece%loads = whole%loads
         end if
      end associate
      self%pieces(1)%r = old(1)%r(:, 1:kb)
      self%pieces(1)%v = old(1)%v(:, 1:kb)
      self%pieces(1)%column = old(1)%column(1:kb)
      self%pieces(1)%end_slot = [1, 3]
      self%pieces(1)%reaction(:, 1) = old(1)%reaction(:, 1)
      self%pieces(2)%r = old(1)%r(:, kb:n)
      self%pieces(2)%v = old(1)%v(:, kb:n)
      self%pieces(2)%column = [kb + 1, old(1)%column(kb + 1:n)]
      self%pieces(2)%end_slot = [4, 2]
      self%pieces(2)%reaction(:, 2) = old(1)%reaction(:, 2)
      call self%pieces(1)%work%init(2*kb, rod_kl, rod_ku, spread(self%pieces(1)%problem%piece%length_ref, 1, 2*kb))
      call self%pieces(2)%work%init(2*(n - kb + 1), rod_kl, rod_ku, &
                                    spread(self%pieces(2)%problem%piece%length_ref, 1, 2*(n - kb + 1)))
   end subroutine apply_split

   !> Summary figures and warnings from the history.
   subroutine summarise(self)
      type(rod_run), intent(inout) :: self
      integer :: i, j, n, n_ends
      real(dp) :: speed, f0, f1, fi, reference, slack_level
      logical :: held_end
      n = self%history%n
      n_ends = size(self%history%end_labels)
      ! Derived from the history afresh (also for a run summarised when it was interrupted).
      if (allocated(self%summary%ends)) deallocate (self%summary%ends)
      allocate (self%summary%ends(n_ends))
      self%summary%steps = n
      self%summary%peak_end_speed = 0
      self%summary%peak_end_speed_time = 0
      self%summary%min_fixed_end_tension = huge(1.0_dp)
      self%summary%min_fixed_end_tension_time = 0
      self%summary%front_arrival_time = -1
      self%summary%peak_end_speed_end = ''
      self%summary%has_fixed_end = .false.
      ! A front is the 1 % drop of a held end's tension after a break; other scenes have none.
      self%summary%has_front = self%broken
      self%summary%broke = self%broken
      if (self%broken) then
         self%summary%break_time = self%scene%break_time
         self%summary%break_s = self%scene%s_break
         self%summary%break_ramp = self%scene%t_break
      end if
      ! The break by tension: what the first pass found (driver/simulation.f90).
      self%summary%by_tension = self%scene%by_tension
      if (self%scene%by_tension) then
         self%summary%mbl = self%scene%mbl
         self%summary%break_tension = self%rupture%tension
         self%summary%break_cell_s = self%rupture%s
         self%summary%largest_tension = self%rupture%max_tension
         self%summary%largest_tension_s = self%rupture%max_s
         self%summary%largest_tension_time = self%rupture%max_time
      end if
      slack_level = slack_tension_fraction*max(self%info%max_tension, self%info%tension_a, self%info%tension_b)
      do j = 1, n_ends
         associate (e => self%summary%ends(j))
            e%kind = end_kind(self, j)
            e%min_tension = self%history%ends(5, j, 0)
            e%max_tension = self%history%ends(5, j, 0)
            e%max_tension_time = self%history%time(0)
            do i = 0, n
               speed = norm2(self%history%ends(3:4, j, i))
               ! A 3-D run (driver/rod3d_drive.f90): with the y velocity.
               if (allocated(self%history%ends_y)) speed = hypot(speed, self%history%ends_y(2, j, i))
               if (speed > e%peak_speed) then
                  e%peak_speed = speed
                  e%peak_speed_time = self%history%time(i)
               end if
               if (self%history%ends(5, j, i) < e%min_tension) then
                  e%min_tension = self%history%ends(5, j, i)
                  e%min_tension_time = self%history%time(i)
               end if
               if (self%history%ends(5, j, i) > e%max_tension) then
                  e%max_tension = self%history%ends(5, j, i)
                  e%max_tension_time = self%history%time(i)
               end if
            end do
            call slack_intervals(self%history, j, slack_level, e%slack_intervals, e%slack_time)
            ! The peak end speed: the fastest end, whatever its kind (a released end after a break,
            ! a moving fairlead, a mass).
            if (e%peak_speed > self%summary%peak_end_speed) then
               self%summary%peak_end_speed = e%peak_speed
               self%summary%peak_end_speed_time = e%peak_speed_time
               self%summary%peak_end_speed_end = self%history%end_labels(j)
            end if
            if (trim(e%kind) == 'fixed') then
               self%summary%has_fixed_end = .true.
               if (e%min_tension < self%summary%min_fixed_end_tension) then
                  self%summary%min_fixed_end_tension = e%min_tension
                  self%summary%min_fixed_end_tension_time = e%min_tension_time
               end if
            end if
            held_end = end_is_held(self, j)
            if (held_end .and. self%summary%has_front) then
               ! The 1 % drop of the tension at the end.
               f0 = self%history%ends(5, j, 0)
               do i = 1, n
                  fi = self%history%ends(5, j, i)
                  if (fi <= 0.99_dp*f0) then
                     f1 = self%history%ends(5, j, i - 1)
                     e%front_arrival_time = self%history%time(i - 1) + (self%history%time(i) - self%history%time(i - 1)) &
                                            *(0.99_dp*f0 - f1)/(fi - f1)
                     exit
                  end if
               end do
               if (e%front_arrival_time >= 0 .and. (self%summary%front_arrival_time < 0 .or. &
                                                    e%front_arrival_time < self%summary%front_arrival_time)) &
                  self%summary%front_arrival_time = e%front_arrival_time
            end if
         end associate
      end do
      if (self%summary%min_fixed_end_tension == huge(1.0_dp)) self%summary%min_fixed_end_tension = 0
      if (self%summary%dt_used == 0) self%summary%dt_used = self%dt
      self%summary%courant_used = self%summary%courant_requested*self%summary%dt_used/self%dt
      self%summary%dissipated = self%dissipation
      if (self%options%energy) then
         reference = self%history%energy(1, 0)
         if (reference <= 0) reference = max(maxval(abs(self%history%energy(1:4, 0))), 1.0_dp)
         self%summary%energy_drift = maxval(abs(self%history%energy(7, 0:n) - self%history%energy(7, 0)))/reference
      end if
      self%summary%warnings = ''
      if (self%summary%energy_drift > warn_energy_drift) call warn('the energy ledger drifted by '// &
         str(100*self%summary%energy_drift)//' % of the initial strain energy (more than '// &
         str(100*warn_energy_drift)//' %)')
      if (self%summary%max_turning_angle > warn_turning_angle) call warn('neighbouring cells turned by up to '// &
         str(self%summary%max_turning_angle)//' rad (more than '//str(warn_turning_angle)// &
         ' rad): a kink at the grid scale, the buckled zone is not resolved; more nodes resolve it')
      associate (law => self%pieces(1)%problem%piece%law)
         if (self%summary%max_strain > law%strain_max) call warn('cells were stretched to strain '// &
            str(self%summary%max_strain)//', beyond the range of the '//law%name()//' law (strain '// &
            str(law%strain_max)//'): the law was extrapolated there')
         if (self%summary%min_strain < law%strain_min) call warn('cells were compressed to strain '// &
            str(self%summary%min_strain)//', below the range of the '//law%name()//' law (strain '// &
            str(law%strain_min)//'): it was continued there along its first tangent, as stiff in compression '// &
            'as at the first row (give rows for compression, or compression = ''none'')')
      end associate
      if (self%static_min_tension < -warn_static_compression*self%static_max_tension) call warn( &
         'the static state is in compression: tension down to '//str(self%static_min_tension)//' N at s = '// &
         str(self%static_min_tension_s)//' m (largest tension '//str(self%static_max_tension)//' N); a rope '// &
         'cannot push: this state is held by the bending stiffness and the law''s compression branch, and may '// &
         'be a loop or a buckle (compare with compression = ''none'' and with more nodes)')
      ! A rope that pushes: the law's compressive branch reached in the dynamics.
      associate (law => self%pieces(1)%problem%piece%law)
         if (law%tension(self%summary%min_strain) < -warn_dynamic_compression*self%static_max_tension) &
            call warn('the line was compressed to '//quantity(law%tension(self%summary%min_strain), 'N')// &
                      ' (strain '//str(self%summary%min_strain)//') at s = '//quantity(self%summary%min_strain_s, 'm')// &
                      ', t = '//quantity(self%summary%min_strain_time, 's')//': with compression = ''law'' the rope '// &
                      'pushes back along its law below zero strain; a rope cannot push: compression = ''none''')
      end associate
      ! The grid against the scene: the static shape and the break's front.
      if (self%static_max_turn > warn_static_turn) call warn('the static shape turns by up to '// &
         str(self%static_max_turn)//' rad between neighbouring cells (more than '//str(warn_static_turn)// &
         ' rad): the grid is too coarse for the shape; about '//str(nodes_for(self%static_max_turn/warn_static_turn))// &
         ' nodes resolve it')
      if (self%front_cells > 0 .and. self%front_cells < min_front_cells) call warn('the break''s front (t_break = '// &
         str(self%scene%t_break)//' s at wave speed '//str(self%front_cells*maxval(self%pieces(1)%problem%piece%ds)/ &
         self%scene%t_break)//' m/s) spans '//str(self%front_cells)//' cells, fewer than '//str(min_front_cells)// &
         ': about '//str(nodes_for(min_front_cells/self%front_cells))//' nodes resolve it')
      if (self%summary%rejected_steps > max(10, int(warn_rejected_fraction*max(n, 1)))) call warn( &
         str(self%summary%rejected_steps)//' step attempts were rejected ('//str(n)// &
         ' accepted): the step control struggled; a smaller dt or courant may be more economical')
      if (abs(self%summary%courant_used/max(self%summary%courant_requested, tiny(1.0_dp)) - 1) > warn_courant_change) &
         call warn('the Courant number taken, '//str(self%summary%courant_used)//', differs from the one asked for, '// &
                   str(self%summary%courant_requested))

   contains

      subroutine warn(line)
         character(*), intent(in) :: line
         if (len(self%summary%warnings) > 0) self%summary%warnings = self%summary%warnings//new_line('a')
         self%summary%warnings = self%summary%warnings//line
      end subroutine warn

      !> The node count that refines the grid by factor (its cells factor times shorter).
      integer function nodes_for(factor)
         real(dp), intent(in) :: factor
         nodes_for = ceiling(factor*(self%options%nodes - 1)) + 1
      end function nodes_for
   end subroutine summarise

   !> The intervals in which end j of the history was slack (its tension at most level), with the
   !> crossings interpolated linearly between records, and their total length, s.
   subroutine slack_intervals(history, j, level, intervals, total)
      !> History of the run.
      type(run_history), intent(in) :: history
      !> The end's slot.
      integer, intent(in) :: j
      !> Tension at and below which the end counts as slack, N.
      real(dp), intent(in) :: level
      !> Start and end of each interval (2, k), s.
      real(dp), allocatable, intent(out) :: intervals(:, :)
      !> Their total, s.
      real(dp), intent(out) :: total
      real(dp), allocatable :: grown(:, :)
      real(dp) :: start, f0, f1, tc
      integer :: i, k
      logical :: slack
      allocate (intervals(2, 8))
      k = 0
      slack = history%ends(5, j, 0) <= level
      start = history%time(0)
      do i = 1, history%n
         f0 = history%ends(5, j, i - 1)
         f1 = history%ends(5, j, i)
         if ((f1 <= level) .eqv. slack) cycle
         tc = history%time(i - 1) + (history%time(i) - history%time(i - 1))*(level - f0)/(f1 - f0)
         if (slack) then
            call push(start, tc)
         else
            start = tc
         end if
         slack = .not. slack
      end do
      if (slack) call push(start, history%time(history%n))
      intervals = intervals(:, 1:k)
      total = sum(intervals(2, :) - intervals(1, :))
   contains
      subroutine push(a, b)
         real(dp), intent(in) :: a, b
         if (k == size(intervals, 2)) then
            allocate (grown(2, 2*k))
            grown(:, 1:k) = intervals
            call move_alloc(grown, intervals)
         end if
         k = k + 1
         intervals(:, k) = [a, b]
      end subroutine push
   end subroutine slack_intervals

   !> Kind of the end in history slot j at the end of the run ('fixed', 'motion', ..., 'break').
   function end_kind(self, j) result(kind)
      type(rod_run), intent(in) :: self
      integer, intent(in) :: j
      character(:), allocatable :: kind
      integer :: p
      kind = ''
      do p = 1, size(self%pieces)
         if (self%pieces(p)%end_slot(1) == j) kind = self%pieces(p)%problem%piece%end_a%kind()
         if (self%pieces(p)%end_slot(2) == j) kind = self%pieces(p)%problem%piece%end_b%kind()
      end do
   end function end_kind

   !> Whether history slot j belongs to an end held at the end of the run.
   logical function end_is_held(self, j)
      type(rod_run), intent(in) :: self
      integer, intent(in) :: j
      integer :: p
      end_is_held = .false.
      do p = 1, size(self%pieces)
         if (self%pieces(p)%end_slot(1) == j) end_is_held = self%pieces(p)%problem%piece%end_a%held()
         if (self%pieces(p)%end_slot(2) == j) end_is_held = self%pieces(p)%problem%piece%end_b%held()
      end do
   end function end_is_held
end module xcable_driver_rod_run
