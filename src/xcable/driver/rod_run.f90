!> Time integration of a scene with the rod discretisation: statics, the
!> break, the time steps with their step control. One `rod_run` holds the
!> whole state of a run (its history and summary too, which the driver keeps:
!> driver/history.f90, driver/summary.f90); each phase is a type-bound procedure.
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
   use xcable_scene_scene, only: scene_type, scene_grid, section_at
   use xcable_loads_load, only: measure_names, load_measures, note_measures
   use xcable_model_rod, only: rod_piece, collapsed_length, rod_problem, rod_kl, rod_ku, perp, cross2, bend_energy, bend_moment, &
                               bend_curvature, cell_rotations, small_strain_step
   use xcable_ends_end_condition, only: end_condition
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_dissipation
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_force, only: force_end
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve, largest_magnitude
   use xcable_solver_banded, only: band_matrix
   use xcable_model_rod_statics, only: rod_static_state, solve_rod_statics, piece_sections
   use xcable_driver_records, only: run_history, run_summary, static_info, run_observer, n_energy, n_fields, &
                                 n_end_quantities, static_figures, slack_tension_fraction, note_min_strain, &
                                 n_fields3, field3_names, n_end_quantities_y
   use xcable_theory_closed_forms, only: wave_speed
   use xcable_io_archive, only: state_archive, sync_real, sync_reals, sync_matrix, sync_cube, sync_int, sync_ints, &
                                sync_logical
   use xcable_system_posix, only: termination_requested
   use xcable_driver_run_state, only: rod_run_options, run_progress, run_clock, tension_watch, pause_none, &
                                      pause_checkpoint, pause_termination, max_steps, rupture_tolerance, max_rupture_aims
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: rod_run, rod_run_options, run_progress, end_value, snapshot_time, ends_change
   public :: wall_limit, plan_step, reject_attempt, advance_time, jacobian_kept, check_range, check_folds
   public :: exchange_progress, watch_step
   ! The state of a run besides its pieces (driver/run_state.f90), for the users of this module.
   public :: tension_watch, pause_none, pause_checkpoint, pause_termination, max_steps, rupture_tolerance, max_rupture_aims

   !> Skip of the quiescent cable (attempt): a node is quiet when it moves by at most
   !> quiet_fraction newton_tol cell lengths in a step, or by quiet_ulps units of round-off
   !> of the largest coordinate; margin nodes around the moving ones; outer nodes of a
   !> window that must stay quiet.
   real(dp), parameter :: quiet_fraction = 1.0e-5_dp, quiet_ulps = 16
   integer, parameter :: window_margin = 8, check_nodes = 2

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
      !> Whether ends other than the scene's change in time (a network's points and its other
      !> lines' ends): ends_change is then true.
      logical :: other_ends_change = .false.
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
      !> Wall time of the dynamics so far (all processes of a resumed run), s.
      procedure :: wall_time => run_wall_time
      !> The state between two steps to an archive, and back into a prepared run.
      procedure :: save_state => run_save_state
      procedure :: load_state => run_load_state
      !> Fields on the output nodes.
      procedure :: fields => run_fields
   end type rod_run

   !> What the step loop asks of a model of the cable in a run (its pieces,
   !> one or two after a break inside the cable). Each procedure gets the run,
   !> whose time (run%t), options, records and step control it reads and writes.
   type, abstract, public :: cable_model
   contains
      !> The history's end labels and slots (the loop then appends the record of t = 0), and the
      !> static state to the observer.
      procedure(model_begin), deferred :: begin
      !> A step of h from run%t on every piece (Newton), then the checks of the new state. An
      !> error says why the attempt fails; retry_same: Newton failed from a kept factorisation
      !> (the step control tries the same step again with a fresh one). iterations: the most
      !> Newton iterations a piece took.
      procedure(model_attempt), deferred :: attempt
      !> Drop the attempt: the pieces back to the old level, no kept factorisation.
      procedure(model_plain), deferred :: reject
      !> The search for a break by tension on the attempt of h just made (watch_step with the
      !> first piece's two levels); retry: the attempt is dropped, to be taken again shorter.
      procedure(model_watch), deferred :: watch
      !> Take the attempt of h: new velocities, reactions, the ledger's work of the step.
      procedure(model_accept), deferred :: accept
      !> The fields of a snapshot at ts (run%t <= ts <= t_new): interpolated inside the step just
      !> accepted (from run%t to t_new), or those of the static state (static). extra: the fields
      !> of field3_names (driver/records.f90) too, when with_extra.
      procedure(model_snapshot), deferred :: snapshot
      !> The model's part of history record i at run%t (the driver, driver/history.f90, keeps
      !> the history: it wrote the record's time, step, Newton iterations and rejected attempts,
      !> and stores what the model gives, all zero on entry): the quantities of the end in each
      !> slot (ends(:, j): x, z, vx, vz, tension, force_x, force_z; ends_y(:, j): y, vy, force_y
      !> of a 3-D model), the loads' measures (size 0 when the history keeps none) and, with the
      !> ledger on, its terms: the energies of energy_names(1:4) and their sum as the model adds
      !> them (stored), the work of the ends, of the distributed loads and the dissipation (work).
      procedure(model_record), deferred :: record
      !> The break: a held end let go, or the piece cut in two at the break node.
      procedure(model_split), deferred :: split
      !> The kind ('fixed', 'motion', ..., 'break') of the end in history slot j at the end of the
      !> run, and whether it is held (the summary's fixed-end figures and the front's arrival).
      procedure(model_end_info), deferred :: end_info
      !> What the model adds to the summary once the run's summary is made.
      procedure(model_plain), deferred :: conclude
      !> The state between two steps to an archive (a checkpoint; archive%ok tells whether it
      !> was stored), and back into a run prepared from the same case (errors stat_input).
      procedure(model_save), deferred :: save_state
      procedure(model_load), deferred :: load_state
      !> The step to try from run%t and the time it lands on (see plan_step, the default: the
      !> step control's step, shortened to land on t_end or the break). A model with a step
      !> plan of its own (the box scheme's whole steps in each snapshot interval) gives it here.
      procedure :: plan => model_plan
      !> The time moves on after an accepted step of h_try (see advance_time, the default).
      procedure :: advance => model_advance
      !> The step control after a rejected attempt (see reject_attempt, the default).
      procedure :: reject_step => model_reject_step
      !> The time a snapshot due at ts is reported at (the default: ts).
      procedure :: snapshot_at => model_snapshot_at
      !> A summary of the model's own at the end of the run (made: the default .false., the
      !> driver's summary, driver/summary.f90, with the model's end_info).
      procedure :: finish => model_finish
   end type cable_model

   abstract interface
      subroutine model_begin(self, run, observer, error)
         import :: cable_model, rod_run, run_observer, error_type
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         class(run_observer), intent(inout), optional :: observer
         type(error_type), allocatable, intent(out) :: error
      end subroutine model_begin

      subroutine model_attempt(self, run, h, iterations, retry_same, error)
         import :: cable_model, rod_run, dp, error_type
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: h
         integer, intent(out) :: iterations
         logical, intent(out) :: retry_same
         type(error_type), allocatable, intent(out) :: error
      end subroutine model_attempt

      subroutine model_plain(self, run)
         import :: cable_model, rod_run
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
      end subroutine model_plain

      subroutine model_watch(self, run, h, retry)
         import :: cable_model, rod_run, dp
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: h
         logical, intent(out) :: retry
      end subroutine model_watch

      subroutine model_accept(self, run, h)
         import :: cable_model, rod_run, dp
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: h
      end subroutine model_accept

      subroutine model_snapshot(self, run, t_new, ts, static, fields, extra, with_extra)
         import :: cable_model, rod_run, dp
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: t_new, ts
         logical, intent(in) :: static
         real(dp), intent(out) :: fields(:, :), extra(:, :)
         logical, intent(out) :: with_extra
      end subroutine model_snapshot

      subroutine model_record(self, run, i, ends, ends_y, measures, energies, stored, work)
         import :: cable_model, rod_run, dp
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         integer, intent(in) :: i
         real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
         real(dp), intent(inout) :: energies(4), stored, work(3)
      end subroutine model_record

      subroutine model_split(self, run, error)
         import :: cable_model, rod_run, error_type
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         type(error_type), allocatable, intent(out) :: error
      end subroutine model_split

      subroutine model_end_info(self, run, j, kind, held)
         import :: cable_model, rod_run
         class(cable_model), intent(in) :: self
         type(rod_run), intent(in) :: run
         integer, intent(in) :: j
         character(:), allocatable, intent(out) :: kind
         logical, intent(out) :: held
      end subroutine model_end_info

      subroutine model_save(self, run, archive)
         import :: cable_model, rod_run, state_archive
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         class(state_archive), intent(inout) :: archive
      end subroutine model_save

      subroutine model_load(self, run, archive, error)
         import :: cable_model, rod_run, state_archive, error_type
         class(cable_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         class(state_archive), intent(inout) :: archive
         type(error_type), allocatable, intent(out) :: error
      end subroutine model_load
   end interface

   !> The planar rod (model/rod.f90) as the model of a run: the pieces of the run itself
   !> (rod_run%pieces), stepped by the submodules step.f90 (the window of the quiescent
   !> skip, the range and fold checks, the break) and records.f90 (snapshots and history).
   type, extends(cable_model), public :: planar_model
   contains
      procedure :: begin => planar_begin
      procedure :: attempt => planar_attempt
      procedure :: reject => planar_reject
      procedure :: watch => planar_watch
      procedure :: accept => planar_accept
      procedure :: snapshot => planar_snapshot
      procedure :: record => planar_record
      procedure :: split => planar_split
      procedure :: end_info => planar_end_info
      procedure :: conclude => planar_conclude
      procedure :: save_state => planar_save_state
      procedure :: load_state => planar_load_state
   end type planar_model


   ! Procedures of the submodules in driver/rod_run/.
   interface
      !> Set up the run: grid, the whole cable as one piece, the statics, the
      !> time step. Errors: stat_input for an inconsistent scene, stat_numerics
      !> when the statics fails.
      module subroutine run_prepare(self, scene, options, error)
         !> Run.
         class(rod_run), intent(inout) :: self
         !> Scene.
         type(scene_type), intent(in) :: scene
         !> Controls.
         type(rod_run_options), intent(in) :: options
         !> Error.
         type(error_type), allocatable, intent(out) :: error
      end subroutine run_prepare

      !> The history of a run turned into x-z (plane_azimuth), turned back into the scene's frame:
      !> x, vx and force_x of each end and record, and their y components (ends_y).
      module subroutine turn_back_history(self)
         type(rod_run), intent(inout) :: self
      end subroutine turn_back_history

      !> The fields of a run turned into x-z (plane_azimuth) in the scene's frame: the x column
      !> turned back (in place), and the fields of field3_names from it and the columns' velocities
      !> v (2, n_out): y and vy; the plan-view curvature, twist, binormal shear and curvature about
      !> n are zero in a vertical plane.
      module subroutine turned_back(self, fields, v, extra)
         type(rod_run), intent(in) :: self
         real(dp), intent(inout) :: fields(:, :)
         real(dp), intent(in) :: v(:, :)
         real(dp), intent(out) :: extra(:, :)
      end subroutine turned_back

      !> The velocities of the pieces' nodes on the output columns (2, n_out); before a break
      !> inside the cable the break node fills both of its columns (as in run_fields).
      module function column_velocities(self) result(v)
         type(rod_run), intent(in) :: self
         real(dp), allocatable :: v(:, :)
      end function column_velocities

      !> Save the state of the run between two steps (after a pause of
      !> advance, or after start) to an archive: everything the next step and
      !> the records depend on (see exchange_state). archive%ok tells whether
      !> it was stored.
      module subroutine run_save_state(self, archive)
         !> Run.
         class(rod_run), intent(inout) :: self
         !> Where the state goes.
         class(state_archive), intent(inout) :: archive
      end subroutine run_save_state

      !> Load a state saved by save_state into a run prepared from the same case
      !> (the same statics, grid and time step), ready for advance. Errors
      !> (stat_input) when the archive fails or holds a state this run cannot
      !> have.
      module subroutine run_load_state(self, archive, error)
         !> Run, prepared.
         class(rod_run), intent(inout) :: self
         !> Where the state comes from.
         class(state_archive), intent(inout) :: archive
         !> Error.
         type(error_type), allocatable, intent(out) :: error
      end subroutine run_load_state

      !> Where the step loop stands (run_progress), listed for saving and
      !> loading: the step to try, the good steps since it was halved, the
      !> rejections since the last accepted step, the next snapshot, the wall
      !> time so far. Either model (exchange_state, driver/rod3d_drive.f90).
      module subroutine exchange_progress(self, a, saving)
         !> Run.
         type(rod_run), intent(inout) :: self
         !> Archive.
         class(state_archive), intent(inout) :: a
         !> Save (.true.) or load.
         logical, intent(in) :: saving
      end subroutine exchange_progress

      !> Time of snapshot i (i >= 1); huge when there is none.
      pure real(dp) module function snapshot_time(self, i)
         type(rod_run), intent(in) :: self
         integer, intent(in) :: i
      end function snapshot_time

      !> Step control (either model, see the module header): the error when the
      !> wall time of the dynamics so far, wall (s), is past options%max_wall_time.
      module subroutine wall_limit(self, wall, error)
         !> Run.
         type(rod_run), intent(in) :: self
         !> Wall time of this process's dynamics, s.
         real(dp), intent(in) :: wall
         !> Error when the limit is reached.
         type(error_type), allocatable, intent(out) :: error
      end subroutine wall_limit

      !> Step control: the step to try from self%t, progress%h shortened to land
      !> on t_stop (t_end, or the start of the break). Error when it no longer
      !> advances the time.
      module subroutine plan_step(self, h_try, t_stop, landing, error)
         !> Run.
         type(rod_run), intent(in) :: self
         !> Step to try and where the run lands (s); whether the step was shortened to land there.
         real(dp), intent(out) :: h_try, t_stop
         logical, intent(out) :: landing
         !> Error when the step no longer advances the time.
         type(error_type), allocatable, intent(out) :: error
      end subroutine plan_step

      !> Step control after a rejected attempt: count it; try the same step again
      !> (retry: Newton failed from a kept factorisation, the next attempt takes
      !> a fresh one) or half of it. Error when the run has rejected more than
      !> 1000 + the requested steps, or the step fell below min_step_fraction dt.
      module subroutine reject_attempt(self, reason, retry, error)
         !> Run.
         type(rod_run), intent(inout) :: self
         !> Why the attempt was rejected.
         character(*), intent(in) :: reason
         !> Whether to retry the same step.
         logical, intent(in) :: retry
         !> Error when the step control gives up.
         type(error_type), allocatable, intent(out) :: error
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
      module subroutine watch_step(self, h, r_old, r_new, ds, law, retry, tensions, s_nodes)
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
         !> A line of segments: the cells' tensions at the old and new level (N) and the factor
         !> mbl / (the cell's segment's MBL) (columns 1 to 3, n - 1 rows).
         real(dp), intent(in), optional :: tensions(:, :)
         !> The nodes' arc lengths the watch reports its places in (m; default: the run's s).
         real(dp), intent(in), optional :: s_nodes(:)
      end subroutine watch_step

      !> Step control after an accepted step of h_try: the time moves on (onto
      !> t_stop when it lands there), the step taken is recorded, and after four
      !> good steps a halved step doubles back towards dt.
      module subroutine advance_time(self, h_try, t_stop, landing)
         !> Run.
         type(rod_run), intent(inout) :: self
         !> The step taken and the time it was to land on (plan_step), s; whether it was shortened to land there.
         real(dp), intent(in) :: h_try, t_stop
         logical, intent(in) :: landing
      end subroutine advance_time

      !> Whether a Newton solve with opts starts from the kept factorisation of work.
      pure logical module function jacobian_kept(opts, work)
         !> Newton controls and work arrays.
         type(newton_options), intent(in) :: opts
         type(newton_workspace), intent(in) :: work
      end function jacobian_kept

      !> Whether an end moves or changes its load in time.
      logical module function ends_change(self)
         type(rod_run), intent(in) :: self
      end function ends_change

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
      module subroutine attempt(self, p, h, kept, iterations, error)
         type(rod_run), intent(inout) :: self
         integer, intent(in) :: p
         real(dp), intent(in) :: h
         logical, intent(out) :: kept
         integer, intent(inout) :: iterations
         type(error_type), allocatable, intent(out) :: error
      end subroutine attempt

      !> Reject states outside the model's range (after an attempt on every piece).
      module subroutine check_state(self, h, error)
         type(rod_run), intent(inout) :: self
         real(dp), intent(in) :: h
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_state

      !> The model's range after an attempt on piece p (either model): finite
      !> unknowns x and no cell squeezed below 5 % of its length (l: cell lengths
      !> / unstretched lengths at the new level). Error stat_numerics naming the first.
      module subroutine check_range(x, l, law, p, error)
         !> Unknowns of the new level; cell length ratios.
         real(dp), intent(in) :: x(:), l(:)
         !> The piece's law (for the advice) and its index.
         class(material_law), intent(in) :: law
         integer, intent(in) :: p
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_range

      !> The model's range (either model): no turning angle passed half a turn
      !> within the step of h s. fold(k) is how far node k's change of turning
      !> angle in the step is from the change its two cells' rotations give (rad:
      !> near 0, or near 2 pi when the angle went through half a turn); error
      !> stat_numerics for the first node above 3 rad (or not a number).
      module subroutine check_folds(fold, p, h, error)
         !> Mismatch at each node (0 at the ends), rad.
         real(dp), intent(in) :: fold(:)
         !> Piece index; the step, s.
         integer, intent(in) :: p
         real(dp), intent(in) :: h
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_folds

      !> Accept the step of length h: new velocities, the reactions at held ends,
      !> the work and the dissipation of the step, and the resolution figures.
      module subroutine accept(self, h)
         type(rod_run), intent(inout) :: self
         real(dp), intent(in) :: h
      end subroutine accept

      !> End labels and slots, and the supports' forces of the static state (the history's
      !> record of t = 0 follows: driver/stepping.f90).
      module subroutine start_history(self)
         type(rod_run), intent(inout) :: self
      end subroutine start_history

      !> The break: split the piece at the break node into two, or release a held
      !> end. The new ends carry the force (and at an inner break the moment) that
      !> held them at the break time, ramped to zero over t_break (eqs. 31-32).
      module subroutine split(self, error)
         type(rod_run), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: error
      end subroutine split

      !> The pieces after the break, with new ends that start from self%cut_force
      !> and cut_couple: the released end replaced (a break at an end), or the
      !> piece cut in two at the break node, each new piece taking the positions,
      !> velocities, output columns, history slots and reactions of its nodes.
      !> Also rebuilds the pieces of a broken run loaded from a checkpoint.
      module subroutine apply_split(self)
         type(rod_run), intent(inout) :: self
      end subroutine apply_split

      !> The planar model (planar_model; the bindings of cable_model, driver/stepping.f90's loop).
      !> The records of t = 0 and the static state (turned back into the scene's frame for a
      !> scene run turned into x-z) to the observer.
      module subroutine planar_begin(self, run, observer, error)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         class(run_observer), intent(inout), optional :: observer
         type(error_type), allocatable, intent(out) :: error
      end subroutine planar_begin

      !> An attempt of h on every piece (attempt; the first failure stops), then check_state.
      module subroutine planar_attempt(self, run, h, iterations, retry_same, error)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: h
         integer, intent(out) :: iterations
         logical, intent(out) :: retry_same
         type(error_type), allocatable, intent(out) :: error
      end subroutine planar_attempt

      !> A rejected attempt: no piece keeps its factorisation (the attempt left r and v alone).
      module subroutine planar_reject(self, run)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
      end subroutine planar_reject

      !> The search for a break by tension on the first piece's attempt of h (watch_step).
      module subroutine planar_watch(self, run, h, retry)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: h
         logical, intent(out) :: retry
      end subroutine planar_watch

      !> The attempt of h taken (accept).
      module subroutine planar_accept(self, run, h)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: h
      end subroutine planar_accept

      !> The fields of a snapshot at ts (the static state's, or interpolated inside the step),
      !> turned back into the scene's frame with the 3-D fields for a scene run turned into x-z.
      module subroutine planar_snapshot(self, run, t_new, ts, static, fields, extra, with_extra)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         real(dp), intent(in) :: t_new, ts
         logical, intent(in) :: static
         real(dp), intent(out) :: fields(:, :), extra(:, :)
         logical, intent(out) :: with_extra
      end subroutine planar_snapshot

      !> The pieces' part of history record i: ends, measures, ledger terms.
      module subroutine planar_record(self, run, i, ends, ends_y, measures, energies, stored, work)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         integer, intent(in) :: i
         real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
         real(dp), intent(inout) :: energies(4), stored, work(3)
      end subroutine planar_record

      !> The break (split).
      module subroutine planar_split(self, run, error)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         type(error_type), allocatable, intent(out) :: error
      end subroutine planar_split

      !> Kind of the end in history slot j, and whether it is held.
      module subroutine planar_end_info(self, run, j, kind, held)
         class(planar_model), intent(in) :: self
         type(rod_run), intent(in) :: run
         integer, intent(in) :: j
         character(:), allocatable, intent(out) :: kind
         logical, intent(out) :: held
      end subroutine planar_end_info

      !> After the summary: a scene run turned into x-z has its history turned back (turn_back_history).
      module subroutine planar_conclude(self, run)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
      end subroutine planar_conclude

      !> The run's state to an archive (rod_run's save_state).
      module subroutine planar_save_state(self, run, archive)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         class(state_archive), intent(inout) :: archive
      end subroutine planar_save_state

      !> The run's state from an archive (rod_run's load_state).
      module subroutine planar_load_state(self, run, archive, error)
         class(planar_model), intent(inout) :: self
         type(rod_run), intent(inout) :: run
         class(state_archive), intent(inout) :: archive
         type(error_type), allocatable, intent(out) :: error
      end subroutine planar_load_state
      !> Fields on the output nodes from the current state of the pieces (or from given positions
      !> and velocities on the output columns); the fields of field_names (driver/records.f90).
      module subroutine run_fields(self, fields, positions, velocities)
         !> Run.
         class(rod_run), intent(inout) :: self
         !> Fields (n_out, n_fields) in the order of field_names.
         real(dp), intent(out) :: fields(:, :)
         !> Positions and velocities per piece (2, n_out): if given, used instead of the pieces' current state.
         real(dp), intent(in), optional :: positions(:, :), velocities(:, :)
      end subroutine run_fields

      !> Value at an end node (side 1: node 1, side 2: node n) of a cell field, extrapolated
      !> half a cell unless the three end cells zig-zag (either model).
      pure real(dp) module function end_value(cells, side)
         !> Cell values.
         real(dp), intent(in) :: cells(:)
         !> 1 or 2.
         integer, intent(in) :: side
      end function end_value
   end interface

contains

   !> The step control's plan of the next step (plan_step): the default of cable_model%plan.
   subroutine model_plan(self, run, h_try, t_stop, landing, error)
      !> Model.
      class(cable_model), intent(inout) :: self
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Step to try and where the run lands (s); whether the step was shortened to land there.
      real(dp), intent(out) :: h_try, t_stop
      logical, intent(out) :: landing
      !> Error when the step no longer advances the time.
      type(error_type), allocatable, intent(out) :: error
      call plan_step(run, h_try, t_stop, landing, error)
   end subroutine model_plan

   !> The time moves on after an accepted step (advance_time): the default of cable_model%advance.
   subroutine model_advance(self, run, h_try, t_stop, landing)
      !> Model.
      class(cable_model), intent(inout) :: self
      !> Run.
      type(rod_run), intent(inout) :: run
      !> The step taken and the time it was to land on (plan), s; whether it was shortened to land there.
      real(dp), intent(in) :: h_try, t_stop
      logical, intent(in) :: landing
      call advance_time(run, h_try, t_stop, landing)
   end subroutine model_advance

   !> The step control after a rejected attempt (reject_attempt): the default of
   !> cable_model%reject_step.
   subroutine model_reject_step(self, run, reason, retry, error)
      !> Model.
      class(cable_model), intent(inout) :: self
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Why the attempt was rejected.
      character(*), intent(in) :: reason
      !> Whether to retry the same step.
      logical, intent(in) :: retry
      !> Error when the step control gives up.
      type(error_type), allocatable, intent(out) :: error
      call reject_attempt(run, reason, retry, error)
   end subroutine model_reject_step

   !> No summary of the model's own (the driver makes it): the default of cable_model%finish.
   subroutine model_finish(self, run, made)
      !> Model.
      class(cable_model), intent(inout) :: self
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Whether the model made the run's summary.
      logical, intent(out) :: made
      made = .false.
   end subroutine model_finish

   !> The time of a snapshot due at ts: ts, the default of cable_model%snapshot_at.
   real(dp) function model_snapshot_at(self, run, ts) result(t)
      !> Model.
      class(cable_model), intent(in) :: self
      !> Run.
      type(rod_run), intent(in) :: run
      !> Time the snapshot is due at, s.
      real(dp), intent(in) :: ts
      t = ts
   end function model_snapshot_at

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

end module xcable_driver_rod_run
