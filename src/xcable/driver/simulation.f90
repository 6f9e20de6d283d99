!> One driver for every run: from a validated case to its static state,
!> dynamics and records, whatever the discretisation. The program, the
!> examples, the benchmark and the tests all go through it:
!>
!>     call sim%prepare(config, error)   ! scene, grid, statics, time step
!>     call sim%run(observer, error)     ! dynamics; observer gets the snapshots
!>     sim%history(), sim%summary()      ! what the run produced
!>
!> prepare returns stat_input errors for an inconsistent case (nothing has
!> been written yet) and stat_numerics when the statics fails.
!>
!> Checkpoints (either scheme, either model): after `enable_checkpoints`, run writes the
!> state to a checkpoint file (io/checkpoint.f90) every so many seconds of
!> wall time, and when SIGTERM arrives it writes one and stops (`interrupted`
!> is then set). `resume` loads a checkpoint into a prepared simulation, so
!> that run continues from it; the resumed run computes what the
!> uninterrupted one would have, to the last bit on the same machine and
!> build (the state saved is listed in driver/rod_run.f90, exchange_state,
!> for the 3-D model in driver/rod3d_drive.f90, exchange3, and for the box
!> scheme in box/model.f90, exchange_box). A checkpoint resumes only with the
!> scheme and model that wrote it.
module xcable_driver_simulation
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_input
   use xcable_core_strings, only: str, real_text, quantity
   use xcable_io_config, only: case_config, end_config
   use xcable_scene_scene, only: scene_type, scene_from_config, set_break, section_at
   use xcable_driver_rod_run, only: rod_run, rod_run_options, cable_model, planar_model, pause_none, pause_termination, &
                                    tension_watch, rupture_tolerance
   use xcable_box_run, only: box_run
   use xcable_driver_rod3d_drive, only: rod3d_drive, n_fields3
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_driver_network, only: network_joint
   use xcable_driver_network_drive, only: network_drive
   use xcable_driver_stepping, only: run_dynamics, start_dynamics, advance_dynamics, finish_dynamics
   use xcable_driver_records, only: run_history, run_summary, static_info, run_observer, n_fields
   use xcable_io_checkpoint, only: checkpoint_file
   use xcable_core_version, only: code_version
   implicit none
   private
   public :: simulation, run_options_from_config, checkpoint_settings
   ! For the submodule driver/simulation/network.f90 (gfortran 12 makes a module's private
   ! procedures local symbols that its submodules cannot link to).
   public :: break_node_of

   !> Inertia kept by the shortest wave (two cells) with the averaged mass
   !> matrix, as a fraction of the lumped one (model/rod.f90, docs/theory/numerics.md).
   real(dp), parameter, public :: averaged_sawtooth_mass = 0.1_dp

   !> A y component that turning a scene into x-z leaves at most this fraction of its vector's
   !> size is round-off, and set to 0 (plane_config): the scene lies in the vertical plane.
   real(dp), parameter :: plane_tolerance = 1.0e-12_dp

   !> Where and when a run writes checkpoints.
   type :: checkpoint_settings
      !> Path of the checkpoint file ('' : no checkpoints).
      character(:), allocatable :: path
      !> Wall time between checkpoints, s (0: none at intervals).
      real(dp) :: interval = 0
      !> Accepted steps between checkpoints (0: none; the tests' way to checkpoint at known steps).
      integer :: every_steps = 0
      !> Write one and stop when SIGTERM arrives (the program installs the handler).
      logical :: on_termination = .false.
      !> The case's namelist fingerprint (io/input.f90 config_text, fingerprint) and the run's identifier.
      character(:), allocatable :: fingerprint, run_id
   end type checkpoint_settings

   !> A run of a case.
   type :: simulation
      !> 'rod' or 'box'.
      character(len=8) :: scheme = 'rod'
      !> The model that runs: '2d' or '3d' (&numerics model; 'auto' resolved).
      character(len=2) :: model = '2d'
      !> The run of each scheme (only one is used).
      type(rod_run) :: rod
      type(box_run) :: box
      !> The model of the cable that the step loop (driver/stepping.f90) drives on rod: the planar
      !> rod (rod's own pieces) or the 3-D rod (model '3d'; it shares the grid, time step and
      !> records of rod). model_of gives the one in use.
      type(planar_model) :: planar
      type(rod3d_drive) :: rod3
      !> A network of lines (&line_k; driver/network_drive.f90), and whether the case is one.
      type(network_drive) :: network
      logical :: is_network = .false.
      !> What the model computes, for the result file.
      character(:), allocatable :: terms
      !> Checkpoints (rod scheme).
      type(checkpoint_settings) :: checkpoints
      !> Checkpoints written by this process.
      integer :: checkpoints_written = 0
      !> Whether the run continues from a checkpoint (resume), and whether it stopped at SIGTERM.
      logical :: resumed = .false., interrupted = .false.
   contains
      procedure :: prepare => sim_prepare
      procedure :: run => sim_run
      !> The model of the cable in use (rod scheme): planar or rod3.
      procedure :: model_of => sim_model_of
      !> Write checkpoints during run (rod scheme).
      procedure :: enable_checkpoints => sim_enable_checkpoints
      !> Continue from a checkpoint: load it into the prepared run.
      procedure :: resume => sim_resume
      !> Snapshots written so far, the one at t = 0 included (after resume: those the checkpoint counts).
      procedure :: snapshots_written => sim_snapshots_written
      !> Output node arc lengths.
      procedure :: output_s => sim_output_s
      !> Output columns where a new piece starts.
      procedure :: piece_starts => sim_piece_starts
      !> The time step (s) and number of steps asked for.
      procedure :: time_step => sim_time_step
      !> Pointers to the records.
      procedure :: history => sim_history
      procedure :: summary => sim_summary
      procedure :: static => sim_static
      !> Whether the results have the 3-D layout (y fields and the ends' y components): a 3-D
      !> run, or a 2-D run of a scene in a vertical plane at an azimuth, turned back.
      procedure :: three_d_output => sim_three_d_output
      !> Output nodes (all lines of a network).
      procedure :: output_nodes => sim_output_nodes
      !> A network's static state in words: its free points' positions, the largest tension.
      procedure :: network_statics_text => sim_network_statics_text
   end type simulation

   ! The preparation of a network of lines is in the submodule driver/simulation/network.f90.
   interface
      !> A network of lines (&line_k, free &point_k): each line prepared as a single line, then the
      !> statics of the whole network, and the records of the run laid out line after line.
      module subroutine prepare_network(self, config, error)
         !> Simulation.
         type(simulation), intent(inout) :: self
         !> Validated case of a network.
         type(case_config), intent(in) :: config
         !> Error: a line's preparation, or the network's statics.
         type(error_type), allocatable, intent(out) :: error
      end subroutine prepare_network
      !> The break by tension of a network: a first pass watching every line's cells against their
      !> segments' MBL, then the network prepared again with the break found (a break by time
      !> of that line), as find_break does for a single line.
      module subroutine find_network_break(self, config, error, statics_only)
         !> Simulation, its network prepared without the break.
         type(simulation), intent(inout), target :: self
         !> Validated case of a network with &rupture criterion = 'tension'.
         type(case_config), intent(in) :: config
         !> Error: stat_input when a static tension reaches its MBL; the first pass's errors.
         type(error_type), allocatable, intent(out) :: error
         !> Stop after the check against the static tensions.
         logical, intent(in), optional :: statics_only
      end subroutine find_network_break
   end interface

contains

   !> Controls of a rod run from a case. reuse_jacobian keeps the scheme's
   !> default unless the case gives it: the rod refactors at every iteration
   !> (its factorisation is cheap and full Newton converges in 2-4 iterations),
   !> the box scheme keeps its factorisation while Newton contracts well.
   function run_options_from_config(config) result(options)
      !> Validated case.
      type(case_config), intent(in) :: config
      type(rod_run_options) :: options
      options%nodes = config%nodes
      options%dt = config%dt
      options%courant = config%courant
      options%t_end = config%t_end
      options%theta = config%theta
      options%mu = merge(1.0_dp, 0.0_dp, trim(config%mass_matrix) == 'averaged')
      options%mu2 = merge(averaged_sawtooth_mass, 0.0_dp, trim(config%mass_matrix) == 'averaged')
      options%damping = config%damping
      options%interval = config%interval
      options%newton%tolerance = config%newton_tol
      options%newton%max_iterations = config%newton_max_iter
      options%newton%reuse_jacobian = config%reuse_jacobian .and. config%is_given('numerics', 'reuse_jacobian')
      options%extrapolate = config%extrapolate
      options%skip_quiescent = config%skip_quiescent
      options%energy = config%energy
      options%min_step_fraction = config%min_step_fraction
      options%max_wall_time = config%max_wall_time
   end function run_options_from_config

   !> Scene, grid, statics and time step of a validated case.
   subroutine sim_prepare(self, config, error, statics_only)
      !> Simulation.
      class(simulation), intent(inout) :: self
      !> Validated case.
      type(case_config), intent(in) :: config
      !> Error: stat_input for an inconsistent case, stat_numerics when the statics fails.
      type(error_type), allocatable, intent(out) :: error
      !> Only the checks and the statics (xcable --check): a break by tension is not looked
      !> for (its first pass is a run), the MBL is checked against the static tension
      !> (default .false.).
      logical, intent(in), optional :: statics_only
      type(scene_type) :: scene
      type(rod_run) :: fresh_rod
      type(box_run) :: fresh_box
      type(rod3d_drive) :: fresh_rod3
      type(network_drive) :: fresh_network
      ! A simulation may be prepared again for another case (checkpoints are enabled after prepare).
      self%rod = fresh_rod
      self%box = fresh_box
      self%rod3 = fresh_rod3
      self%network = fresh_network
      self%is_network = .false.
      self%checkpoints = checkpoint_settings()
      self%checkpoints_written = 0
      self%resumed = .false.
      self%interrupted = .false.
      self%scheme = trim(config%scheme)
      self%model = config%model_to_run()
      if (config%is_network()) then
         call prepare_network(self, config, error)
         if (allocated(error)) return
         if (config%break_enabled .and. trim(config%break_criterion) == 'tension') &
            call find_network_break(self, config, error, statics_only)
         return
      end if
      select case (self%scheme)
      case ('box')
         call self%box%prepare(config, self%rod, error)
         self%terms = 'box scheme (eqs. 18-25): strain bending gravity; end b released by the ramp'
      case default
         call scene_from_config(config, scene, error)
         if (allocated(error)) return
         call prepare_rod(self, config, scene, error)
         if (allocated(error)) return
         if (scene%by_tension) call find_break(self, config, scene, error, statics_only)
      end select
   end subroutine sim_prepare


   !> The rod run of a scene (either model): its grid, statics and time step, from fresh runs.
   subroutine prepare_rod(self, config, scene, error)
      type(simulation), intent(inout) :: self
      type(case_config), intent(in) :: config
      type(scene_type), intent(in) :: scene
      type(error_type), allocatable, intent(out) :: error
      type(rod_run) :: fresh_rod
      type(rod3d_drive) :: fresh_rod3
      self%rod = fresh_rod
      self%rod3 = fresh_rod3
      ! (Again on the second call of a break by tension: the first may have turned to 2-D.)
      self%model = config%model_to_run()
      ! model = 'auto' and a scene in one vertical plane that is not x-z: the 2-D run of the scene
      ! turned into x-z, its results turned back (driver/rod_run.f90, plane_azimuth).
      if (self%model == '3d' .and. trim(config%model) == 'auto') then
         block
            type(scene_type) :: planar
            type(case_config) :: flat
            real(dp) :: azimuth
            logical :: in_plane
            azimuth = chord_azimuth(scene)
            if (azimuth /= 0) then
               call plane_config(config, azimuth, flat, in_plane)
               if (in_plane) then
                  call scene_from_config(flat, planar, error)
                  if (allocated(error)) return
                  call carry_break(scene, planar)
                  call self%rod%prepare(planar, run_options_from_config(config), error)
                  if (allocated(error)) return
                  self%rod%plane_azimuth = azimuth
                  self%rod%plane_pivot = [config%end_a%x, config%end_a%y]
                  self%model = '2d'
                  self%terms = terms_of(planar)
                  if (config%damping > 0) self%terms = self%terms//' damping'
                  self%terms = self%terms//'; in the vertical plane at azimuth '// &
                               real_text(azimuth*180/acos(-1.0_dp))//' deg, run in 2-D and turned back'
                  return
               end if
            end if
         end block
      end if
      if (self%model == '3d') then
         ! The 3-D statics start from a planar static state (driver/rod3d_drive.f90): that of
         ! the scene turned about the vertical so that its chord lies in the x-z plane (the
         ! true span and static strains, not those of the scene's shadow on x-z). The planar
         ! preparation also gives the grid and the output nodes; the 3-D run then takes the
         ! scene as given, and its static state, step, Courant number and checks are its own.
         block
            type(scene_type) :: planar
            real(dp) :: azimuth
            azimuth = chord_azimuth(scene)
            if (azimuth == 0) then
               ! (The planar run may place end b itself: the paper's symmetric case.)
               call self%rod%prepare(scene, run_options_from_config(config), error)
            else
               call scene_from_config(turned_config(config, -azimuth), planar, error)
               if (allocated(error)) return
               call carry_break(scene, planar)
               call self%rod%prepare(planar, run_options_from_config(config), error)
               if (.not. allocated(error)) self%rod%scene = scene
            end if
            if (allocated(error)) return
         end block
      else
         call self%rod%prepare(scene, run_options_from_config(config), error)
         if (allocated(error)) return
      end if
      self%terms = terms_of(scene)
      if (config%damping > 0) self%terms = self%terms//' damping'
      if (self%model == '3d') then
         call self%rod3%prepare(self%rod, error, chord_azimuth(scene), [config%end_a%x, config%end_a%y])
         self%terms = 'rod3d:'//self%terms(5:)//' twist'
         ! The planar statics was the 3-D statics' first guess; no planar piece runs under the 3-D one.
         if (allocated(self%rod%pieces)) deallocate (self%rod%pieces)
      end if
   end subroutine prepare_rod

   !> A break by tension, once found, is where and when the scene has it: its break copied into the
   !> planar scene its run is prepared from (the scene turned).
   subroutine carry_break(scene, planar)
      type(scene_type), intent(in) :: scene
      type(scene_type), intent(inout) :: planar
      planar%breaks = scene%breaks
      planar%s_break = scene%s_break
      planar%break_time = scene%break_time
      planar%break_at_a = scene%break_at_a
      planar%break_at_b = scene%break_at_b
   end subroutine carry_break

   !> The break by tension (&rupture criterion = 'tension'), found by a first pass: the run
   !> without the break (no output), whose step loop watches the cell tensions (rod_run's
   !> watch_step: the step that passes mbl is taken again, shorter, until its largest cell
   !> tension is within rupture_tolerance of mbl) and stops there. The run is then prepared
   !> again with a break at that time, at the node nearest that cell (break_node_of): the
   !> run with the break is a break at a time and place, as criterion 'time' does it. Without a
   !> crossing it is prepared again without a break. What the pass found goes to the summary.
   !> Errors: stat_input when the static state already reaches mbl (within rupture_tolerance;
   !> nothing has been written);
   !> the first pass's errors.
   subroutine find_break(self, config, scene, error, statics_only)
      type(simulation), intent(inout), target :: self
      type(case_config), intent(in) :: config
      !> The scene: its break is set here.
      type(scene_type), intent(inout) :: scene
      type(error_type), allocatable, intent(out) :: error
      !> Stop after the check against the static tension.
      logical, intent(in), optional :: statics_only
      type(tension_watch) :: found
      class(cable_model), pointer :: model
      real(dp) :: static_max
      integer :: kb, n
      static_max = max(self%rod%static_max_tension, self%rod%info%max_tension)
      if (size(scene%sections) > 1) then
         call segment_static_check(error)
         if (allocated(error)) return
      ! Within the search's tolerance of mbl counts as reaching it (rod_run, watch_step).
      else if (static_max >= (1 - rupture_tolerance)*scene%mbl) then
         call fatal_error(error, config%source//': &rupture: mbl = '//real_text(scene%mbl)//': at or below the '// &
                          'largest static tension, '//quantity(static_max, 'N')//': the line would part in statics; '// &
                          'give an mbl above it', stat_input)
         return
      end if
      if (present(statics_only)) then
         if (statics_only) return
      end if
      self%rod%watch%mbl = scene%mbl
      model => self%model_of()
      call run_dynamics(self%rod, model, error=error)
      if (allocated(error)) then
         call prefix_error(error, 'the first pass of the break by tension (the run without the break, to find '// &
                           'where and when the tension reaches mbl): ')
         return
      end if
      found = self%rod%watch
      found%mbl = 0
      found%h_aim = 0
      if (found%found) then
         n = size(self%rod%s)
         kb = break_node_of(found%cells, found%cell, scene%end_a%held(), scene%end_b%held())
         if (kb == 1) then
            call set_break(scene, 0.0_dp, found%time, error)
         else if (kb == n) then
            call set_break(scene, scene%length, found%time, error)
         else
            call set_break(scene, self%rod%s(kb), found%time, error)
         end if
         if (allocated(error)) return
      end if
      call prepare_rod(self, config, scene, error)
      if (allocated(error)) return
      self%rod%rupture = found

   contains

      !> A line of segments: each cell's static tension against its own segment's MBL.
      subroutine segment_static_check(err)
         type(error_type), allocatable, intent(out) :: err
         integer :: c, j
         real(dp) :: t
         associate (r => self%rod%static%r, s => self%rod%s)
            do c = 1, size(s) - 1
               j = section_at(scene, 0.5_dp*(s(c) + s(c + 1)))
               associate (sec => scene%sections(j))
                  if (sec%mbl <= 0) cycle
                  t = sec%law%tension(norm2(r(:, c + 1) - r(:, c))/(s(c + 1) - s(c)) - 1)
                  if (t >= (1 - rupture_tolerance)*sec%mbl) then
                     call fatal_error(err, config%source//': &segment_'//str(j)//': mbl = '//real_text(sec%mbl)// &
                                      ': at or below the segment''s static tension, '//quantity(t, 'N')//' at s = '// &
                                      quantity(0.5_dp*(s(c) + s(c + 1)), 'm')//': the line would part in statics; '// &
                                      'give an mbl above it', stat_input)
                     return
                  end if
               end associate
            end do
         end associate
      end subroutine segment_static_check
   end subroutine find_break

   !> The break node of a break by tension: of the two nodes of the first cell to reach the MBL
   !> (cell c), the one with the larger node tension (the mean of its two cells; an end node, its
   !> cell's). A break stays at a node (the cable is cut in two pieces there, or a held end lets
   !> go): an end node only at a held end, an inner node with two cells at least on either side
   !> (scene_grid); else the nearest such node (of two, the one with the larger node tension).
   pure integer function break_node_of(cells, c, held_a, held_b) result(kb)
      !> Cell tensions when the first cell reached the MBL, N.
      real(dp), intent(in) :: cells(:)
      !> That cell.
      integer, intent(in) :: c
      !> Whether end a and end b are held.
      logical, intent(in) :: held_a, held_b
      real(dp) :: node(size(cells) + 1)
      integer :: n, k, d
      n = size(cells) + 1
      node(1) = cells(1)
      node(n) = cells(n - 1)
      do k = 2, n - 1
         node(k) = 0.5_dp*(cells(k - 1) + cells(k))
      end do
      kb = c
      if (node(c + 1) > node(c)) kb = c + 1
      if (allowed(kb)) return
      do d = 1, n
         if (allowed(kb - d) .and. allowed(kb + d)) then
            kb = merge(kb + d, kb - d, node(kb + d) > node(kb - d))
            return
         else if (allowed(kb - d)) then
            kb = kb - d
            return
         else if (allowed(kb + d)) then
            kb = kb + d
            return
         end if
      end do
   contains
      pure logical function allowed(k)
         integer, intent(in) :: k
         allowed = (k == 1 .and. held_a) .or. (k == n .and. held_b) .or. (k >= 3 .and. k <= n - 2)
      end function allowed
   end function break_node_of

   !> Azimuth, in the horizontal plane, of the vertical plane the scene's line starts in, rad (from
   !> x towards y): that of the chord from end a's point to end b's point when both ends have one
   !> (a held end's position, a spring's anchor) at distinct horizontal places; with one point, that
   !> of the other end's horizontal force (its pull away from the point); else 0.
   real(dp) function chord_azimuth(scene) result(phi)
      type(scene_type), intent(in) :: scene
      real(dp) :: a(3), b(3), f(3)
      logical :: point_a, point_b
      phi = 0
      point_a = scene%end_a%held() .or. scene%end_a%state_dependent()
      point_b = scene%end_b%held() .or. scene%end_b%state_dependent()
      if (point_a .and. point_b) then
         a = scene%end_a%position3(0.0_dp)
         b = scene%end_b%position3(0.0_dp)
         if (hypot(b(1) - a(1), b(2) - a(2)) <= 1.0e-9_dp*max(scene%length, 1.0_dp)) return
         if (abs(b(2) - a(2)) == 0) return
         phi = atan2(b(2) - a(2), b(1) - a(1))
      else if (point_a .or. point_b) then
         ! The loaded end's horizontal force; end a's pulls the line away from end b's point.
         if (point_a) then
            f = scene%end_b%applied_force3(0.0_dp)
         else
            f = -scene%end_a%applied_force3(0.0_dp)
         end if
         if (abs(f(2)) == 0) return
         phi = atan2(f(2), f(1))
      end if
   end function chord_azimuth

   !> The case turned by angle (rad) about the vertical through end a: the ends' points, motion
   !> directions, forces and table columns, and the current.
   function turned_config(config, angle) result(c)
      type(case_config), intent(in) :: config
      real(dp), intent(in) :: angle
      type(case_config) :: c
      real(dp) :: ox, oy
      c = config
      if (angle == 0) return
      ox = config%end_a%x
      oy = config%end_a%y
      call turn_end(c%end_a)
      call turn_end(c%end_b)
      call turn(c%current_x, c%current_y, 0.0_dp, 0.0_dp)
   contains
      subroutine turn_end(e)
         type(end_config), intent(inout) :: e
         integer :: k
         call turn(e%x, e%y, ox, oy)
         call turn(e%direction_x, e%direction_y, 0.0_dp, 0.0_dp)
         call turn(e%force_x, e%force_y, 0.0_dp, 0.0_dp)
         ! Table columns: displacements of a motion, or forces: vectors.
         do k = 1, e%table_rows
            call turn(e%table_x(k), e%table_y(k), 0.0_dp, 0.0_dp)
         end do
      end subroutine turn_end
      subroutine turn(x, y, x0, y0)
         real(dp), intent(inout) :: x, y
         real(dp), intent(in) :: x0, y0
         real(dp) :: u, v
         u = x - x0
         v = y - y0
         x = x0 + cos(angle)*u - sin(angle)*v
         y = y0 + sin(angle)*u + cos(angle)*v
      end subroutine turn
   end function turned_config

   !> The case turned by -azimuth about the vertical through end a's point (x, y) and moved so
   !> that this point has y = 0, with the y components that the turn leaves at round-off set to 0
   !> (at most plane_tolerance of their vector's size); in_plane: the result lies in the x-z
   !> plane (case_config%is_planar), so that the 2-D model runs it.
   subroutine plane_config(config, azimuth, c, in_plane)
      type(case_config), intent(in) :: config
      real(dp), intent(in) :: azimuth
      type(case_config), intent(out) :: c
      logical, intent(out) :: in_plane
      real(dp) :: scale
      c = turned_config(config, -azimuth)
      scale = max(config%length, hypot(config%end_b%x - config%end_a%x, config%end_b%y - config%end_a%y))
      call flatten_end(c%end_a)
      call flatten_end(c%end_b)
      call flatten(c%current_y, hypot(c%current_x, c%current_y))
      in_plane = c%is_planar()
   contains
      subroutine flatten_end(e)
         type(end_config), intent(inout) :: e
         integer :: k
         e%y = e%y - config%end_a%y
         call flatten(e%y, scale + abs(e%x - config%end_a%x))
         call flatten(e%force_y, hypot(e%force_x, e%force_y))
         call flatten(e%direction_y, hypot(e%direction_x, e%direction_y))
         do k = 1, e%table_rows
            call flatten(e%table_y(k), hypot(e%table_x(k), e%table_y(k)))
         end do
      end subroutine flatten_end
      subroutine flatten(y, size)
         real(dp), intent(inout) :: y
         real(dp), intent(in) :: size
         if (abs(y) <= plane_tolerance*size) y = 0
      end subroutine flatten
   end subroutine plane_config

   !> What the rod model computes for a scene.
   function terms_of(scene) result(terms)
      type(scene_type), intent(in) :: scene
      character(:), allocatable :: terms, name
      integer :: k
      terms = 'rod: strain bending'
      if (scene%gravity > 0) terms = terms//' gravity'
      if (scene%end_a%point_mass() > 0 .or. scene%end_b%point_mass() > 0) terms = terms//' point_mass'
      if (scene%end_a%kind() == 'force' .or. scene%end_b%kind() == 'force') terms = terms//' end_force'
      if (scene%end_a%kind() == 'motion' .or. scene%end_b%kind() == 'motion') terms = terms//' end_motion'
      ! An end with a state of its own (a spring, and the bodies to come): its kind names the term.
      if (scene%end_a%state_dependent()) terms = terms//' end_'//scene%end_a%kind()
      if (scene%end_b%state_dependent() .and. .not. (scene%end_a%state_dependent() .and. &
                                                    scene%end_a%kind() == scene%end_b%kind())) &
         terms = terms//' end_'//scene%end_b%kind()
      if (scene%breaks) terms = terms//' break'
      ! (On a line of segments, each term once: that of any segment.)
      do k = 1, size(scene%sections)
         name = scene%sections(k)%law%name()
         if (index(name, 'without compression') > 0) call add('tension_only')
         if (name == 'table' .or. index(name, 'table ') == 1) call add('table_law')
      end do
      if (size(scene%sections) > 1) terms = terms//' segments'
      if (allocated(scene%loads)) then
         do k = 1, size(scene%loads)
            call add(scene%loads(k)%load%name())
         end do
      end if
   contains
      subroutine add(term)
         character(*), intent(in) :: term
         if (index(terms//' ', ' '//term//' ') == 0) terms = terms//' '//term
      end subroutine add
   end function terms_of

   !> The dynamics.
   subroutine sim_run(self, observer, error)
      !> Simulation (prepared).
      class(simulation), intent(inout), target :: self
      !> Receives the static state and the snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the run cannot go on (the records hold what was done).
      type(error_type), allocatable, intent(out) :: error
      class(cable_model), pointer :: model
      integer :: pause
      model => self%model_of()
      if (.not. allocated(self%checkpoints%path)) then
         call run_dynamics(self%rod, model, observer, error)
         return
      end if
      if (.not. self%resumed) call start_dynamics(self%rod, model, observer, error)
      if (.not. allocated(error)) then
         do
            call advance_dynamics(self%rod, model, observer, error, pause)
            if (allocated(error) .or. pause == pause_none) exit
            call write_checkpoint(self, error)
            if (allocated(error)) exit
            if (pause == pause_termination) then
               self%interrupted = .true.
               exit
            end if
         end do
      end if
      call finish_dynamics(self%rod, model)
   end subroutine sim_run

   !> The model of the cable that the step loop drives: the box scheme's (scheme 'box'), the
   !> 3-D rod for model '3d', else the planar rod.
   function sim_model_of(self) result(model)
      !> Simulation (prepared).
      class(simulation), intent(inout), target :: self
      class(cable_model), pointer :: model
      if (self%scheme == 'box') then
         model => self%box%stepper
      else if (self%is_network) then
         model => self%network
      else if (self%model == '3d') then
         model => self%rod3
      else
         model => self%planar
      end if
   end function sim_model_of

   !> Write checkpoints to path during run: every interval seconds of wall
   !> time (0: none), every every_steps accepted steps (0: none; tests), and,
   !> with on_termination, when SIGTERM arrives (then the run stops and
   !> interrupted is set). Either scheme, either model.
   subroutine sim_enable_checkpoints(self, path, fingerprint, run_id, interval, on_termination, every_steps)
      !> Simulation (prepared).
      class(simulation), intent(inout) :: self
      !> Checkpoint file.
      character(*), intent(in) :: path
      !> Namelist fingerprint and identifier of the run, written into each checkpoint.
      character(*), intent(in) :: fingerprint, run_id
      !> Wall time between checkpoints, s (0: none at intervals).
      real(dp), intent(in) :: interval
      !> Stop with a checkpoint at SIGTERM.
      logical, intent(in) :: on_termination
      !> Accepted steps between checkpoints (0: none).
      integer, intent(in), optional :: every_steps
      self%checkpoints%path = path
      self%checkpoints%fingerprint = fingerprint
      self%checkpoints%run_id = run_id
      self%checkpoints%interval = interval
      self%checkpoints%on_termination = on_termination
      self%checkpoints%every_steps = 0
      if (present(every_steps)) self%checkpoints%every_steps = every_steps
      self%rod%options%checkpoint_interval = interval
      self%rod%options%checkpoint_steps = self%checkpoints%every_steps
      self%rod%options%stop_on_termination = on_termination
   end subroutine sim_enable_checkpoints

   !> Write the state of the run to the checkpoint file (atomically).
   subroutine write_checkpoint(self, error)
      type(simulation), intent(inout), target :: self
      type(error_type), allocatable, intent(out) :: error
      type(checkpoint_file) :: file
      class(cable_model), pointer :: model
      call file%create(self%checkpoints%path, code_version, self%checkpoints%fingerprint, self%checkpoints%run_id, &
                       self%rod%t, error)
      if (allocated(error)) return
      model => self%model_of()
      call model%save_state(self%rod, file)
      call file%commit(error)
      if (.not. allocated(error)) self%checkpoints_written = self%checkpoints_written + 1
   end subroutine write_checkpoint

   !> Continue from the checkpoint at path (enable_checkpoints first: its path
   !> is where later checkpoints go). Refuses (stat_input, nothing loaded
   !> that matters: the caller stops) a file that cannot be read, is damaged,
   !> was written by another version or for another namelist; run_id returns
   !> the identifier of the run the checkpoint belongs to.
   subroutine sim_resume(self, path, fingerprint, run_id, error)
      !> Simulation (prepared).
      class(simulation), intent(inout), target :: self
      !> Checkpoint file.
      character(*), intent(in) :: path
      !> The case's namelist fingerprint.
      character(*), intent(in) :: fingerprint
      !> Identifier of the run that wrote the checkpoint.
      character(:), allocatable, intent(out) :: run_id
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      type(checkpoint_file) :: file
      class(cable_model), pointer :: model
      call file%open(path, error)
      if (allocated(error)) return
      run_id = file%run_id
      ! A checkpoint of the other scheme (its namelist differs in scheme).
      if ((file%stored_size('box/y') >= 0) .neqv. (self%scheme == 'box')) then
         call fatal_error(error, "checkpoint '"//path//"' was written by a "// &
                          merge('rod-scheme', 'box-scheme', self%scheme == 'box')//' run, this case runs the '// &
                          merge('box scheme', 'rod scheme', self%scheme == 'box')//" (&numerics scheme): a "// &
                          "checkpoint resumes only with the scheme that wrote it", stat_input)
         call file%close()
         return
      end if
      ! A checkpoint of the other model (its namelist differs in model, or in what 'auto' looks at).
      if (self%scheme /= 'box' .and. ((file%stored_size('rod3d/x') >= 0) .neqv. (self%model == '3d'))) then
         call fatal_error(error, "checkpoint '"//path//"' was written by a "//merge('3-D', '2-D', self%model == '2d')// &
                          ' run, this case runs the '//merge('3-D', '2-D', self%model == '3d')//" model (&numerics "// &
                          "model): a checkpoint resumes only with the model that wrote it", stat_input)
         call file%close()
         return
      end if
      if (file%code_version /= code_version) then
         call fatal_error(error, "checkpoint '"//path//"' was written by xcable "//file%code_version//', this is '// &
                          code_version//': a checkpoint resumes only with the version that wrote it', stat_input)
         call file%close()
         return
      end if
      if (file%namelist /= fingerprint) then
         call fatal_error(error, "checkpoint '"//path//"' was written for another case: "// &
                          first_difference(file%namelist, fingerprint), stat_input)
         call file%close()
         return
      end if
      model => self%model_of()
      call model%load_state(self%rod, file, error)
      if (allocated(error)) then
         error%message = "checkpoint '"//path//"': "//error%message
         call file%close()
         return
      end if
      call file%verify(error)
      if (allocated(error)) return
      self%checkpoints%run_id = run_id
      self%resumed = .true.
   end subroutine sim_resume

   !> Where two namelist texts first differ, as "line k: 'a' (checkpoint), 'b' (now)".
   function first_difference(then, now) result(text)
      character(*), intent(in) :: then, now
      character(:), allocatable :: text
      integer :: line, i, a0, b0, a1, b1
      line = 1
      a0 = 1
      b0 = 1
      do i = 1, min(len(then), len(now))
         if (then(i:i) /= now(i:i)) exit
         if (then(i:i) == new_line('a')) then
            line = line + 1
            a0 = i + 1
            b0 = i + 1
         end if
      end do
      a1 = index(then(a0:), new_line('a'))
      a1 = merge(len(then), a0 + a1 - 2, a1 == 0)
      b1 = index(now(b0:), new_line('a'))
      b1 = merge(len(now), b0 + b1 - 2, b1 == 0)
      text = 'the namelist differs in line '//str(line)//": '"//then(a0:a1)//"' (checkpoint), '"//now(b0:b1)// &
             "' (now); the variables that may differ are marked in docs/user/namelist.md"
   end function first_difference

   logical function sim_three_d_output(self)
      class(simulation), intent(in) :: self
      sim_three_d_output = self%model == '3d' .or. self%rod%plane_azimuth /= 0
   end function sim_three_d_output

   integer function sim_snapshots_written(self) result(n)
      class(simulation), intent(in) :: self
      n = self%rod%progress%snapshot_index
   end function sim_snapshots_written

   function sim_output_s(self) result(s)
      class(simulation), intent(in) :: self
      real(dp), allocatable :: s(:)
      s = self%rod%s_out
   end function sim_output_s

   function sim_piece_starts(self) result(starts)
      class(simulation), intent(in) :: self
      integer, allocatable :: starts(:)
      allocate (starts(0))
      if (self%is_network) then
         ! Each line after the first starts a piece of the output, and a break inside a line too.
         starts = self%network%piece_starts()
         return
      end if
      if (self%scheme /= 'box') then
         if (self%rod%break_node > 0) starts = [self%rod%break_node + 1]
      end if
   end function sim_piece_starts

   integer function sim_output_nodes(self)
      class(simulation), intent(in) :: self
      sim_output_nodes = self%rod%n_out
   end function sim_output_nodes

   function sim_network_statics_text(self) result(text)
      class(simulation), intent(in) :: self
      character(:), allocatable :: text
      integer :: p
      character(len=16) :: at(3)
      integer :: j
      text = ''
      do p = 1, self%network%net%points
         do j = 1, 3
            write (at(j), '(f16.3)') self%network%net%xp(j, p)
            ! (-0.000 is 0.000)
            if (abs(self%network%net%xp(j, p)) < 5.0e-4_dp) at(j) = '0.000'
         end do
         text = text//'&point_'//str(self%network%point_number(p))//' at ('//trim(adjustl(at(1)))//', '// &
                trim(adjustl(at(2)))//', '//trim(adjustl(at(3)))//') m; '
      end do
      text = text//'largest tension '//quantity(self%rod%info%max_tension, 'N')
   end function sim_network_statics_text

   subroutine sim_time_step(self, dt, steps)
      class(simulation), intent(in) :: self
      real(dp), intent(out) :: dt
      integer, intent(out) :: steps
      dt = self%rod%dt
      steps = ceiling(self%rod%options%t_end/dt)
   end subroutine sim_time_step

   function sim_history(self) result(p)
      class(simulation), intent(in), target :: self
      type(run_history), pointer :: p
      p => self%rod%history
   end function sim_history

   function sim_summary(self) result(p)
      class(simulation), intent(in), target :: self
      type(run_summary), pointer :: p
      p => self%rod%summary
   end function sim_summary

   function sim_static(self) result(p)
      class(simulation), intent(in), target :: self
      type(static_info), pointer :: p
      p => self%rod%info
   end function sim_static
end module xcable_driver_simulation
