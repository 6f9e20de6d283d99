!> The 3-D rod (model/rod3d.f90) as a run of the program: &numerics model
!> = '3d', or 'auto' for a scene that leaves the x-z plane.
!>
!> It builds on a prepared planar run (driver/rod_run.f90), whose grid, time
!> step, output nodes, records and summary it shares: the planar static
!> state, with y interpolated linearly between the ends, is the first guess
!> of the 3-D statics. A folded static state is refused (check_static3); on
!> a refusal or a failure the statics continues in the distributed loads
!> (continue_statics), and fails when no unfolded state is found. The dynamics take the planar run's steps (dt, the last
!> one shortened to land on t_end and on the start of a break), snapshots at
!> the same times (cubic Hermite inside a step), and the same history and
!> ledger columns; the twist energy is booked with the strain energy. The
!> fields of a state are those of driver/rod3d_fields.f90; the history keeps
!> the y components of the ends too (run_history%ends_y).
!>
!> The dynamics are those of the one step loop (driver/stepping.f90), for
!> which this type is the model of the cable (cable_model): an attempt on
!> every piece with the checks of the new state (check_state3: the planar
!> run's check_range, and the fold check in 3-D form,
!> rod3d_piece%turning_folds), the rejection, the acceptance, the snapshots,
!> the history record and the break. The step control, its landing, the
!> checkpoint pauses and the summary are the loop's and the planar run's.
!>
!> Checkpoints as the planar run's (driver/rod3d_drive/checkpoint.f90): save_state and
!> load_state list the state (exchange3) with the planar run's sync procedures (io/archive.f90) and its
!> exchange_progress and exchange_records.
!>
!> A break inside the cable as in the planar run (driver/rod3d_drive/break.f90): the output has the break
!> node twice (the planar run's columns and end slots break_a, break_b), and
!> at the break the piece is cut in two 3-D pieces whose new ends carry the
!> force (x, y, z) and the bending couple that held them, ramped to zero over
!> t_break. The couple is the node's bending moment about its own axis (the
!> normal of the node's two cells; -y or +y in a planar scene, so that a
!> planar scene gives the planar run's couple), and the twist moment of the
!> cut goes on as the new ends' torques, ramped alike. The bending energy of
!> the break node leaves with the cut, booked as work, as in the planar run.
!> With distributed loads (fluid) each new end's force is that of its own
!> piece's end node at rest, so that both pieces start in the balance the
!> whole cable had (their forces add up to none).
module xcable_driver_rod3d_drive
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_numerics, stat_input
   use xcable_core_strings, only: str
   use xcable_driver_rod_run, only: rod_run, cable_model, end_value, jacobian_kept, check_range, &
                                    check_folds, watch_step, max_steps
   use xcable_theory_closed_forms, only: wave_speed
   use xcable_io_archive, only: state_archive, sync_int, sync_reals, sync_matrix
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_model_rod3d, only: rod3d_piece, rod3d_section
   use xcable_scene_scene, only: scene_type, section_cells, sections_on, section_at
   use xcable_ends_end_condition, only: end_condition
   use xcable_loads_load, only: measure_names, load_measures, loads_in_statics, any_static_form
   use xcable_material_law, only: material_law, secant_stiffness
   use xcable_material_tension_only, only: uncut_law
   use xcable_driver_records, only: run_observer, static_figures, note_min_strain
   use xcable_driver_history, only: hermite_levels, open_history, exchange_records
   use xcable_driver_rod3d_fields, only: fields3, n_fields3, field3_names
   implicit none
   private
   public :: rod3d_drive, n_fields3, field3_names
   ! A 3-D piece's checks of a new state and its end tension, also for the lines of a network
   ! (driver/network_drive.f90).
   public :: check_state3, end_tension, state_between, exchange_run3
   ! A network's line that parts is cut as a single line is (driver/network_drive.f90): the
   ! pieces after the break (release, also for a broken network loaded from a checkpoint) and
   ! the break node's two history ends before it.
   public :: release, break_node_ends, slot_end
   ! For the submodules driver/rod3d_drive/ (gfortran 12 makes a module's private procedures
   ! local symbols that its submodules cannot link to).
   public :: state_fields, piece_sections3, set_time

   !> One 3-D piece of cable in a run.
   type :: piece3
      !> The 3-D stepper (its piece, state and ledger).
      type(rod3d_run) :: run
      !> The previous time level (for snapshots inside a step).
      real(dp), allocatable :: x_prev(:), v_prev(:, :)
      !> Force of the supports on the end nodes at the current time (held ends), N.
      real(dp) :: reaction(3, 2) = 0
      !> Output columns of the nodes, and history slots of the two ends (0: none).
      integer, allocatable :: column(:)
      integer :: end_slot(2) = 0
   end type piece3

   !> A 3-D run: the 3-D rod as the model of a run (cable_model, driven by driver/stepping.f90).
   type, extends(cable_model) :: rod3d_drive
      !> The pieces (one, or two after a break inside the cable).
      type(piece3), allocatable :: pieces(:)
      !> Whether the break has happened.
      logical :: broken = .false.
      !> The force (x, y, z; N) each new end of the break starts from (the released end: the first), the
      !> couples (N m) about their axes (unit vectors) and the torques about the outward tangents (N m).
      real(dp) :: cut_force(3, 2) = 0, cut_couple(2) = 0, cut_axis(3, 2) = 0, cut_torque(2) = 0
      !> Extra fields of the static state (n_out, n_fields3).
      real(dp), allocatable :: static_extra(:, :)
      !> Pieces the last attempt solved (a rejection takes them back to the old level).
      integer :: tried = 0
   contains
      !> The 3-D statics from the planar run's static state; static fields and records.
      procedure :: prepare => drive_prepare
      !> The bindings of cable_model (the step loop's view of the model).
      procedure :: begin => drive_begin
      procedure :: attempt => drive_attempt
      procedure :: reject => drive_reject
      procedure :: watch => drive_watch
      procedure :: accept => drive_accept
      procedure :: snapshot => drive_snapshot
      procedure :: record => drive_record
      procedure :: split => drive_split
      procedure :: end_info => drive_end_info
      procedure :: conclude => drive_conclude
      !> The state between two steps to an archive (a checkpoint), and back into a prepared run.
      procedure :: save_state => drive_save_state
      procedure :: load_state => drive_load_state
   end type rod3d_drive

   ! The preparation of the 3-D run (its statics) is in the submodule driver/rod3d_drive/statics.f90.
   interface
      !> Set up the 3-D piece on the prepared planar run's grid and solve its statics.
      module subroutine drive_prepare(self, rod, error, azimuth, pivot)
         !> 3-D run.
         class(rod3d_drive), intent(inout) :: self
         !> Planar run, prepared (its scene, grid, time step; its static fields are replaced).
         type(rod_run), intent(inout) :: rod
         !> Error: stat_input for what the 3-D run cannot do, stat_numerics when the statics fails.
         type(error_type), allocatable, intent(out) :: error
         !> The angle (rad) the planar run's scene was turned by about the vertical through pivot (x, y)
         !> to lie in x-z (driver/simulation.f90; default 0: not turned). Its static state is turned back.
         real(dp), intent(in), optional :: azimuth, pivot(2)
      end subroutine drive_prepare
   end interface

   ! The checkpoint (save_state, load_state) is in the submodule driver/rod3d_drive/checkpoint.f90.
   interface
      !> Save the state of the run between two steps (after start, or a pause
      !> of advance) to an archive. archive%ok tells whether it was stored.
      module subroutine drive_save_state(self, run, archive)
         !> 3-D run.
         class(rod3d_drive), intent(inout) :: self
         !> The planar run it shares its records with.
         type(rod_run), intent(inout) :: run
         !> Where the state goes.
         class(state_archive), intent(inout) :: archive
      end subroutine drive_save_state
      !> Load a state saved by save_state into a run prepared from the same case,
      !> ready for advance. Errors (stat_input) when the archive fails or holds a
      !> state this run cannot have.
      module subroutine drive_load_state(self, run, archive, error)
         !> 3-D run, prepared.
         class(rod3d_drive), intent(inout) :: self
         !> The planar run it shares its records with (prepared).
         type(rod_run), intent(inout) :: run
         !> Where the state comes from.
         class(state_archive), intent(inout) :: archive
         !> Error.
         type(error_type), allocatable, intent(out) :: error
      end subroutine drive_load_state
   end interface

   ! The break (split, release) is in the submodule driver/rod3d_drive/break.f90.
   interface
      !> The break: the new ends' forces, couples and torques, and the pieces after it.
      module subroutine split(self, rod, error)
         type(rod3d_drive), intent(inout) :: self
         type(rod_run), intent(inout) :: rod
         !> Error when a piece cannot be set up.
         type(error_type), allocatable, intent(out) :: error
      end subroutine split
      !> The pieces after the break (also those of a broken run loaded from a checkpoint).
      module subroutine release(self, rod, error)
         type(rod3d_drive), intent(inout) :: self
         type(rod_run), intent(inout) :: rod
         !> Error when a piece cannot be set up.
         type(error_type), allocatable, intent(out) :: error
      end subroutine release
   end interface

contains

   !> The start of the dynamics: the history's labels and record of t = 0, the static state
   !> with its snapshot (and the 3-D fields) to the observer.
   subroutine drive_begin(self, run, observer, error)
      class(rod3d_drive), intent(inout) :: self
      !> The planar run it shares its records with.
      type(rod_run), intent(inout) :: run
      class(run_observer), intent(inout), optional :: observer
      type(error_type), allocatable, intent(out) :: error
      call start_records(self, run)
      if (.not. present(observer)) return
      call observer%static(run%info, error)
      if (.not. allocated(error)) call observer%snapshot(0.0_dp, run%info%fields, error)
      if (.not. allocated(error)) call observer%snapshot_extra(0.0_dp, field3_names, self%static_extra, error)
   end subroutine drive_begin

   !> An attempt of h on every piece (the first that fails stops the others), each checked
   !> (check_state3) before the next.
   subroutine drive_attempt(self, run, h, iterations, retry_same, error)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer, intent(out) :: iterations
      logical, intent(out) :: retry_same
      type(error_type), allocatable, intent(out) :: error
      logical :: kept, newton_failed
      integer :: p
      kept = .false.
      newton_failed = .false.
      iterations = 0
      self%tried = 0
      do p = 1, size(self%pieces)
         associate (piece => self%pieces(p))
            piece%x_prev = piece%run%x
            piece%v_prev = piece%run%v
            piece%run%t = run%t
            kept = kept .or. jacobian_kept(piece%run%options, piece%run%work)
            self%tried = p
            call piece%run%attempt(h, run%options%theta, error)
            newton_failed = allocated(error)
            if (.not. newton_failed) call check_state3(piece%run%problem%piece, piece%run%x, p, h, error)
            iterations = max(iterations, piece%run%last_iterations)
         end associate
         if (allocated(error)) exit
      end do
      retry_same = newton_failed .and. kept
   end subroutine drive_attempt

   !> The pieces the last attempt solved back to the old level.
   subroutine drive_reject(self, run)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer :: p
      do p = 1, self%tried
         call self%pieces(p)%run%reject()
      end do
   end subroutine drive_reject

   !> The search for a break by tension on the attempt of h (one piece: the run without its break).
   subroutine drive_watch(self, run, h, retry)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      logical, intent(out) :: retry
      real(dp), allocatable :: tensions(:, :), r0(:, :), r1(:, :)
      integer :: c, j
      associate (r3 => self%pieces(1)%run, n => self%pieces(1)%run%problem%piece%n, &
                 piece => self%pieces(1)%run%problem%piece)
         if (size(run%scene%sections) > 1) then
            ! A line of segments: each cell against its own segment's MBL (as the planar run's
            ! planar_watch, driver/rod_run/step.f90).
            r0 = reshape(r3%x_old(1:3*n), [3, n])
            r1 = reshape(r3%x(1:3*n), [3, n])
            allocate (tensions(n - 1, 3))
            do c = 1, n - 1
               tensions(c, 1) = piece%cell_tension(c, norm2(r0(:, c + 1) - r0(:, c))/piece%ds(c) - 1)
               tensions(c, 2) = piece%cell_tension(c, norm2(r1(:, c + 1) - r1(:, c))/piece%ds(c) - 1)
               j = section_at(run%scene, 0.5_dp*(piece%s(c) + piece%s(c + 1)))
               tensions(c, 3) = 0
               if (run%scene%sections(j)%mbl > 0) tensions(c, 3) = run%watch%mbl/run%scene%sections(j)%mbl
            end do
            call watch_step(run, h, r0, r1, piece%ds, piece%law, retry, tensions)
         else
            call watch_step(run, h, reshape(r3%x_old(1:3*n), [3, n]), reshape(r3%x(1:3*n), [3, n]), &
                            piece%ds, piece%law, retry)
         end if
      end associate
      if (retry) call self%pieces(1)%run%reject()
   end subroutine drive_watch

   !> The attempt of h taken on every piece: new velocities and ledger (rod3d_run's accept),
   !> the forces of the supports on the end nodes.
   subroutine drive_accept(self, run, h)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer :: p
      do p = 1, size(self%pieces)
         associate (r3 => self%pieces(p)%run)
            call r3%accept(h, run%options%theta)
            self%pieces(p)%reaction(:, 1) = r3%problem%piece%reaction(1, h)
            self%pieces(p)%reaction(:, 2) = r3%problem%piece%reaction(r3%problem%piece%n, h)
         end associate
      end do
   end subroutine drive_accept

   !> The fields of a snapshot at ts: the static state's (static) or interpolated inside the step
   !> just accepted (interpolated), with the 3-D fields.
   subroutine drive_snapshot(self, run, t_new, ts, static, fields, extra, with_extra)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: t_new, ts
      logical, intent(in) :: static
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      logical, intent(out) :: with_extra
      with_extra = .true.
      if (static) then
         fields = run%info%fields
         extra = self%static_extra
      else
         call interpolated(self, run, run%t, t_new - run%t, ts, fields, extra)
      end if
   end subroutine drive_snapshot

   !> The break (split).
   subroutine drive_split(self, run, error)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      type(error_type), allocatable, intent(out) :: error
      call split(self, run, error)
   end subroutine drive_split

   !> The end in history slot j at the end of the run: its kind and whether it is held.
   subroutine drive_end_info(self, run, j, kind, held)
      class(rod3d_drive), intent(in) :: self
      type(rod_run), intent(in) :: run
      integer, intent(in) :: j
      character(:), allocatable, intent(out) :: kind
      logical, intent(out) :: held
      integer :: p
      kind = ''
      held = .false.
      do p = 1, size(self%pieces)
         call slot_end(self%pieces(p)%run%problem%piece, self%pieces(p)%end_slot, j, kind, held)
      end do
   end subroutine drive_end_info

   !> The kind of a piece's end in history slot j and whether it is held (kind and held are left
   !> as they are when neither of the piece's end slots is j).
   subroutine slot_end(piece, end_slot, j, kind, held)
      !> The piece and the history slots of its two ends.
      type(rod3d_piece), intent(in) :: piece
      integer, intent(in) :: end_slot(2), j
      character(:), allocatable, intent(inout) :: kind
      logical, intent(inout) :: held
      if (end_slot(1) == j) then
         kind = piece%end_a%kind()
         held = piece%end_a%held()
      end if
      if (end_slot(2) == j) then
         kind = piece%end_b%kind()
         held = piece%end_b%held()
      end if
   end subroutine slot_end

   !> The summary's Newton figures from the pieces (full Newton: one factorisation per
   !> iteration) and, with the ledger on, the dissipation booked by the pieces (the first
   !> carries what the whole cable booked before a break), as the planar run reports them.
   subroutine drive_conclude(self, run)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer :: p
      associate (s => run%summary)
         s%newton_iterations = sum([(self%pieces(p)%run%iterations, p=1, size(self%pieces))])
         s%factorisations = s%newton_iterations
         if (run%options%energy) s%dissipated = sum([(self%pieces(p)%run%dissipated, p=1, size(self%pieces))])
      end associate
   end subroutine drive_conclude

   !> The time of every piece's stepper.
   subroutine set_time(self, t)
      type(rod3d_drive), intent(inout) :: self
      real(dp), intent(in) :: t
      integer :: p
      do p = 1, size(self%pieces)
         self%pieces(p)%run%t = t
      end do
   end subroutine set_time

   !> The step control's range check of an attempt on piece p (the planar
   !> run's check_state in 3-D form): finite unknowns, no cell squeezed below
   !> 5 % of its length, no turning angle through half a turn within the step of h.
   subroutine check_state3(piece, x, p, h, error)
      type(rod3d_piece), intent(in) :: piece
      !> Unknowns of the attempt's new level.
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: p
      real(dp), intent(in) :: h
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: r(3, piece%n), e(3, piece%n - 1), l(piece%n - 1), th(piece%n), fold(piece%n)
      r = reshape(x(1:3*piece%n), [3, piece%n])
      call piece%geometry(r, e, l, th)
      call check_range(x, l, piece%law, p, error)
      if (allocated(error)) return
      call piece%turning_folds(r, fold)
      call check_folds(fold, p, h, error)
   end subroutine check_state3

   !> History labels and slots (break_a and break_b too with a break inside the cable); the record of
   !> t = 0 follows (driver/stepping.f90).
   subroutine start_records(self, rod)
      type(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: rod
      call open_history(rod, 16, .true.)
      self%pieces(1)%end_slot = [1, 2]
   end subroutine start_records

   !> The 3-D model's part of history record i at run%t (the driver keeps the history,
   !> driver/history.f90): the end quantities of the planar run's (x and z
   !> components) and their y components (ends_y); before a break inside the cable, break_a and
   !> break_b are the break node with the pull of the cable on either side, as in the planar run.
   subroutine drive_record(self, run, i, ends, ends_y, measures, energies, stored, work)
      class(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer, intent(in) :: i
      real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
      real(dp), intent(inout) :: energies(4), stored, work(3)
      integer :: side, k, n, p, slot
      real(dp) :: f(3), en(5), ledger(3)
      call set_time(self, run%t)
      associate (rod => run)
         en = 0
         ledger = 0
         do p = 1, size(self%pieces)
            associate (piece => self%pieces(p)%run%problem%piece, x => self%pieces(p)%run%x, &
                       run => self%pieces(p)%run, reaction => self%pieces(p)%reaction)
               n = piece%n
               call piece%geometry(reshape(x(1:3*n), [3, n]), piece%e1, piece%l1, piece%th1)
               do side = 1, 2
                  slot = self%pieces(p)%end_slot(side)
                  if (slot == 0) cycle
                  k = merge(1, n, side == 1)
                  if (side == 1) then
                     f = reaction(:, 1)
                     if (.not. piece%end_a%held()) f = piece%end_a%applied_force3(rod%t)
                     if (piece%end_a%state_dependent()) f = f + state_force(piece%end_a, rod%t, x(1:3), run%v(:, 1))
                  else
                     f = reaction(:, 2)
                     if (.not. piece%end_b%held()) f = piece%end_b%applied_force3(rod%t)
                     if (piece%end_b%state_dependent()) f = f + state_force(piece%end_b, rod%t, x(3*n - 2:3*n), run%v(:, n))
                  end if
                  ends(:, slot) = [x(3*k - 2), x(3*k), run%v(1, k), run%v(3, k), end_tension(piece, side), &
                                        f(1), f(3)]
                  ends_y(:, slot) = [x(3*k - 1), run%v(2, k), f(2)]
               end do
               if (size(measures) > 0) then
                  if (p == 1) measures = 0
                  call load_measures(rod%scene%loads, reshape(x(1:3*n), [3, n]), piece%ds, measures, piece%s)
               end if
               rod%summary%max_turning_angle = max(rod%summary%max_turning_angle, maxval(piece%th1))
               call note_min_strain(rod%summary, piece%l1, self%pieces(p)%column, rod%s_out, rod%t)
               rod%summary%max_strain = max(rod%summary%max_strain, maxval(piece%l1) - 1)
               if (rod%options%energy) then
                  en = en + run%energies()
                  ledger = ledger + [run%end_work, run%load_work, run%dissipated]
               end if
            end associate
         end do
         ! Before a break inside the cable, its two ends are the break node.
         if (size(self%pieces) == 1 .and. rod%break_node > 0) &
            call break_node_ends(self%pieces(1)%run%problem%piece, self%pieces(1)%run%x, self%pieces(1)%run%v, &
                                 rod%break_node, ends(:, 3:4), ends_y(:, 3:4))
         if (rod%options%energy) then
            energies = [en(1) + en(5), en(2:4)]
            stored = sum(en)
            work = ledger
         end if
      end associate
   end subroutine drive_record

   !> The history's two ends of a break node k inside the cable before the break (the records
   !> break_a, break_b): the node, with the pull of the cable on either side (the cell after it
   !> on break_a, the cell before it on break_b, as the planar run), and the node's tension.
   subroutine break_node_ends(piece, x, v, k, ends, ends_y)
      !> The piece, its unknowns and velocities (3, n).
      type(rod3d_piece), intent(in) :: piece
      real(dp), intent(in) :: x(:), v(:, :)
      !> The break node.
      integer, intent(in) :: k
      !> The two records: x, z, vx, vz, tension, fx, fz (7, 2) and y, vy, fy (3, 2).
      real(dp), intent(inout) :: ends(:, :), ends_y(:, :)
      real(dp) :: e(3), f(3), ten
      e = x(3*k + 1:3*k + 3) - x(3*k - 2:3*k)
      f = piece%cell_tension(k, norm2(e)/piece%ds(k) - 1)*e/norm2(e)
      ten = 0.5_dp*(norm2(f) + piece%cell_tension(k - 1, norm2(x(3*k - 2:3*k) - x(3*k - 5:3*k - 3)) &
                                                         /piece%ds(k - 1) - 1))
      ends(:, 1) = [x(3*k - 2), x(3*k), v(1, k), v(3, k), ten, f(1), f(3)]
      ends_y(:, 1) = [x(3*k - 1), v(2, k), f(2)]
      e = x(3*k - 2:3*k) - x(3*k - 5:3*k - 3)
      f = -piece%cell_tension(k - 1, norm2(e)/piece%ds(k - 1) - 1)*e/norm2(e)
      ends(:, 2) = [x(3*k - 2), x(3*k), v(1, k), v(3, k), ten, f(1), f(3)]
      ends_y(:, 2) = [x(3*k - 1), v(2, k), f(2)]
   end subroutine break_node_ends

   !> The force of a state-dependent end's own state at position x with velocity v, N.
   function state_force(end, t, x, v) result(f)
      !> The end.
      class(end_condition), intent(in) :: end
      !> Time, s.
      real(dp), intent(in) :: t
      !> Position and velocity of its node (x, y, z).
      real(dp), intent(in) :: x(3), v(3)
      real(dp) :: f(3), dx(3, 3), dv(3, 3), damp(3)
      call end%state_force(t, x, v, f, dx, dv, damp)
   end function state_force

   !> Tension at an end (side 1: node 1, side 2: node n) from its end cells
   !> (piece%l1 set), extrapolated as the planar run's end values.
   real(dp) function end_tension(piece, side)
      type(rod3d_piece), intent(in) :: piece
      integer, intent(in) :: side
      real(dp) :: cells(3)
      integer :: j, c, m
      m = min(3, piece%n - 1)
      do j = 1, m
         c = merge(j, piece%n - j, side == 1)
         cells(j) = piece%cell_tension(c, piece%l1(c) - 1)
      end do
      end_tension = max(end_value(cells(1:m), 1), piece%cell_tension(merge(1, piece%n - 1, side == 1), -0.99_dp))
   end function end_tension

   !> A 3-D piece on a line of segments: its sections from the scene's (rod3d_piece
   !> set_sections), those with cells on the piece (its nodes' arc lengths s), as the planar
   !> run's piece_sections (model/rod_statics.f90). Nothing for a scene of one segment.
   subroutine piece_sections3(piece, scene)
      !> Piece, initialised on its part of the line.
      type(rod3d_piece), intent(inout) :: piece
      !> Scene.
      type(scene_type), intent(in) :: scene
      integer, allocatable :: last(:), keep(:)
      type(rod3d_section), allocatable :: sections(:)
      integer :: j
      if (size(scene%sections) <= 1) then
         ! A uniform line may carry a body at an end.
         if (allocated(scene%points)) call piece%set_points(scene%points)
         return
      end if
      last = section_cells(scene, piece%s)
      keep = sections_on(scene, piece%s)
      allocate (sections(size(keep)))
      do j = 1, size(keep)
         associate (sec => scene%sections(keep(j)))
            allocate (sections(j)%law, source=sec%law)
            sections(j)%mass = sec%mass
            sections(j)%weight = sec%weight
            sections(j)%ei = sec%ei
            sections(j)%gip = sec%gip
            sections(j)%damping = sec%damping
         end associate
      end do
      call piece%set_sections(last(keep), sections)
      if (allocated(scene%points)) call piece%set_points(scene%points)
   end subroutine piece_sections3

   !> Fields at ts inside the step (t0, t0 + h): cubic Hermite in the positions
   !> and velocities of its two levels, the twist angles linear.
   subroutine interpolated(self, rod, t0, h, ts, fields, extra)
      type(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(in) :: rod
      real(dp), intent(in) :: t0, h, ts
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      real(dp), allocatable :: x(:), v(:, :)
      integer :: p
      do p = 1, size(self%pieces)
         associate (piece => self%pieces(p))
            call state_between(piece%run%problem%piece%n, piece%x_prev, piece%v_prev, piece%run%x, piece%run%v, &
                               t0, h, ts, x, v)
            call piece_fields(piece, x, v, fields, extra)
         end associate
      end do
      call double_break_node(rod, size(self%pieces), fields, extra)
   end subroutine interpolated

   !> The state of a 3-D piece at time ts inside the step from t0 to t0 + h: positions and
   !> velocities by cubic Hermite interpolation of the two levels (hermite_levels), the twist
   !> angles linearly.
   subroutine state_between(n, x_prev, v_prev, x1, v1, t0, h, ts, x, v)
      !> Nodes.
      integer, intent(in) :: n
      !> The two levels: unknowns (4 n) and velocities (3, n).
      real(dp), intent(in) :: x_prev(:), v_prev(:, :), x1(:), v1(:, :)
      !> Start and length of the step, and the time wanted, s.
      real(dp), intent(in) :: t0, h, ts
      !> The state at ts.
      real(dp), allocatable, intent(out) :: x(:), v(:, :)
      real(dp), allocatable :: r0(:, :), r1(:, :), r(:, :)
      real(dp) :: u
      u = min(max((ts - t0)/h, 0.0_dp), 1.0_dp)
      r0 = reshape(x_prev(1:3*n), [3, n])
      r1 = reshape(x1(1:3*n), [3, n])
      r = r0
      v = r0
      call hermite_levels((ts - t0)/h, h, r0, v_prev, r1, v1, r, v)
      x = x1
      x(1:3*n) = reshape(r, [3*n])
      x(3*n + 1:) = (1 - u)*x_prev(3*n + 1:) + u*x1(3*n + 1:)
   end subroutine state_between

   !> A 3-D run's state in a checkpoint, under prefix: its nodes (checked on loading), unknowns,
   !> velocities and ledger (a piece of a 3-D run, a line of a network). Error (stat_input) when
   !> the checkpoint's nodes are not the run's.
   subroutine exchange_run3(a, prefix, run, name, saving, error)
      !> Archive.
      class(state_archive), intent(inout) :: a
      !> Prefix of its datasets, and what the run is, for the message ('piece 2', 'line 3').
      character(*), intent(in) :: prefix, name
      !> The run.
      type(rod3d_run), intent(inout) :: run
      !> Save (.true.) or load.
      logical, intent(in) :: saving
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      real(dp) :: ledger(4)
      n = run%problem%piece%n
      call sync_int(a, prefix//'nodes', n, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (n /= run%problem%piece%n) then
            call fatal_error(error, 'the checkpoint holds '//str(n)//' nodes in '//name//', this case '// &
                             str(run%problem%piece%n), stat_input)
            return
         end if
      end if
      call sync_reals(a, prefix//'x', run%x, saving)
      call sync_matrix(a, prefix//'v', run%v, saving)
      ledger = [run%energy0, run%end_work, run%load_work, run%dissipated]
      call sync_reals(a, prefix//'ledger', ledger, saving)
      if (.not. saving) then
         run%energy0 = ledger(1)
         run%end_work = ledger(2)
         run%load_work = ledger(3)
         run%dissipated = ledger(4)
      end if
   end subroutine exchange_run3

   !> Fields on the output nodes of the pieces' current state.
   subroutine state_fields(self, rod, fields, extra)
      type(rod3d_drive), intent(in) :: self
      type(rod_run), intent(in) :: rod
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      integer :: p
      do p = 1, size(self%pieces)
         call piece_fields(self%pieces(p), self%pieces(p)%run%x, self%pieces(p)%run%v, fields, extra)
      end do
      call double_break_node(rod, size(self%pieces), fields, extra)
   end subroutine state_fields

   !> The fields of one piece at the state (x, v), into its output columns.
   subroutine piece_fields(piece, x, v, fields, extra)
      type(piece3), intent(in) :: piece
      real(dp), intent(in) :: x(:), v(:, :)
      real(dp), intent(inout) :: fields(:, :), extra(:, :)
      real(dp) :: f(piece%run%problem%piece%n, size(fields, 2)), e(piece%run%problem%piece%n, size(extra, 2))
      call fields3(piece%run%problem%piece, x, v, f, e)
      fields(piece%column, :) = f
      extra(piece%column, :) = e
   end subroutine piece_fields

   !> Before a break inside the cable the break node fills both of its columns.
   pure subroutine double_break_node(rod, n_pieces, fields, extra)
      type(rod_run), intent(in) :: rod
      integer, intent(in) :: n_pieces
      real(dp), intent(inout) :: fields(:, :), extra(:, :)
      if (n_pieces == 1 .and. rod%break_node > 0) then
         fields(rod%break_node + 1, :) = fields(rod%break_node, :)
         extra(rod%break_node + 1, :) = extra(rod%break_node, :)
      end if
   end subroutine double_break_node
end module xcable_driver_rod3d_drive
