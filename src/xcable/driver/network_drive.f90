!> A network of lines (&line_1 ... with free &point_k) as the model of a run: the lines of
!> driver/network.f90 behind the step loop's interface (cable_model, driver/stepping.f90).
!>
!> The output lays the lines out one after another, as the pieces of a parted line: line 1's
!> output nodes, then line 2's, and so on, the arc length running on from line to line (line l
!> starts at the sum of the lengths before it), and each line a piece of its own (the output's
!> piece starts, the XDMF's polylines). The history has two ends per line, `line_1_a`,
!> `line_1_b`, `line_2_a`, ..., with the end kinds of the lines' ends ('joint' at a free point).
!> The ledger's columns are the network's: the lines' energies, the work of the supports (not
!> the points', which cancels), of the loads, and the dissipation.
!>
!> The step is the one step loop's, from the shortest of the lines' steps (each line's
!> Courant number at its static state); a step the network's Newton does not take is taken
!> again shorter, as any model's. The checks of a new state are each line's (its strain
!> range, the fold check). Checkpoints as the 3-D run's: each line's state where that run keeps
!> a piece's, the free points and their work besides. The loads' measures (wetted and grounded
!> length) are the sums over the lines. What a network does not have yet: a break (the input
!> refuses &rupture).
module xcable_driver_network_drive
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str
   use xcable_driver_rod_run, only: rod_run, cable_model
   use xcable_driver_rod3d_drive, only: check_state3, end_tension, state_between, exchange_run3
   use xcable_driver_network, only: network_run
   use xcable_driver_records, only: run_observer, note_min_strain
   use xcable_driver_rod3d_fields, only: fields3, n_fields3, field3_names
   use xcable_io_archive, only: state_archive, sync_real, sync_reals, sync_matrix, sync_int, sync_ints
   use xcable_driver_rod_run, only: exchange_progress
   use xcable_driver_history, only: exchange_records, open_history
   use xcable_model_rod3d, only: rod3d_piece
   use xcable_loads_load, only: load_measures
   implicit none
   private
   public :: network_drive, network_end_labels

   !> One line's place in the output and its previous level.
   type :: line_place
      !> First output column of the line (its n nodes follow).
      integer :: first = 0
      !> The previous time level (snapshots inside a step).
      real(dp), allocatable :: x_prev(:), v_prev(:, :)
      !> Force of the supports (held ends; the points at joints) on the end nodes, N.
      real(dp) :: reaction(3, 2) = 0
   end type line_place

   !> A network run.
   type, extends(cable_model) :: network_drive
      !> The lines and points.
      type(network_run) :: net
      !> Per line, its place.
      type(line_place), allocatable :: lines(:)
      !> Extra fields of the static state (n_out, n_fields3).
      real(dp), allocatable :: static_extra(:, :)
      !> The input's number (&point_k) of each free point.
      integer, allocatable :: point_number(:)
   contains
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
      procedure :: save_state => drive_save_state
      procedure :: load_state => drive_load_state
      !> The history's ends, two per line.
      procedure :: open_history => drive_open_history
      !> The output's fields of the current state (n_out, n_fields) and (n_out, n_fields3).
      procedure :: state_fields => drive_state_fields
   end type network_drive

contains

   !> The history's end labels of a network of lines lines: line_1_a, line_1_b, ...
   pure function network_end_labels(lines) result(labels)
      !> Number of lines.
      integer, intent(in) :: lines
      character(len=8) :: labels(2*lines)
      integer :: l
      do l = 1, lines
         write (labels(2*l - 1), '(a,i0,a)') 'line_', l, '_a'
         write (labels(2*l), '(a,i0,a)') 'line_', l, '_b'
      end do
   end function network_end_labels

   subroutine drive_begin(self, run, observer, error)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(run_observer), intent(inout), optional :: observer
      type(error_type), allocatable, intent(out) :: error
      integer :: l
      call self%open_history(run)
      do l = 1, size(self%lines)
         self%lines(l)%x_prev = self%net%lines(l)%x
         self%lines(l)%v_prev = self%net%lines(l)%v
      end do
      if (.not. present(observer)) return
      call observer%static(run%info, error)
      if (.not. allocated(error)) call observer%snapshot(0.0_dp, run%info%fields, error)
      if (.not. allocated(error)) call observer%snapshot_extra(0.0_dp, field3_names, self%static_extra, error)
   end subroutine drive_begin

   !> The history's ends: two per line (line_1_a, line_1_b, ...), with room for a few records
   !> (at the preparation: a resumed run reads its records into it).
   subroutine drive_open_history(self, run)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      call open_history(run, 16, .true., network_end_labels(size(self%lines)))
   end subroutine drive_open_history

   subroutine drive_attempt(self, run, h, iterations, retry_same, error)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer, intent(out) :: iterations
      logical, intent(out) :: retry_same
      type(error_type), allocatable, intent(out) :: error
      integer :: l, n
      retry_same = .false.
      do l = 1, size(self%lines)
         self%lines(l)%x_prev = self%net%lines(l)%x
         self%lines(l)%v_prev = self%net%lines(l)%v
      end do
      self%net%t = run%t
      call self%net%attempt(h, run%options%theta, error)
      iterations = self%net%last_iterations
      if (allocated(error)) return
      do l = 1, size(self%lines)
         associate (piece => self%net%lines(l)%problem%piece, x => self%net%lines(l)%x)
            n = piece%n
            call check_state3(piece, x, l, h, error)
            if (allocated(error)) return
         end associate
      end do
   end subroutine drive_attempt


   subroutine drive_reject(self, run)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      call self%net%reject()
   end subroutine drive_reject

   !> No watch of the tensions (a network has no break by tension yet).
   subroutine drive_watch(self, run, h, retry)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      logical, intent(out) :: retry
      retry = .false.
   end subroutine drive_watch

   subroutine drive_accept(self, run, h)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer :: l
      call self%net%accept(h, run%options%theta)
      do l = 1, size(self%lines)
         associate (piece => self%net%lines(l)%problem%piece)
            self%lines(l)%reaction(:, 1) = piece%reaction(1, h)
            self%lines(l)%reaction(:, 2) = piece%reaction(piece%n, h)
         end associate
      end do
   end subroutine drive_accept

   subroutine drive_snapshot(self, run, t_new, ts, static, fields, extra, with_extra)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: t_new, ts
      logical, intent(in) :: static
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      logical, intent(out) :: with_extra
      real(dp), allocatable :: x(:), v(:, :), f(:, :), e(:, :)
      integer :: l, n
      with_extra = .true.
      if (static) then
         fields = run%info%fields
         extra = self%static_extra
         return
      end if
      do l = 1, size(self%lines)
         associate (line => self%lines(l), now => self%net%lines(l))
            n = now%problem%piece%n
            call state_between(n, line%x_prev, line%v_prev, now%x, now%v, run%t, t_new - run%t, ts, x, v)
            allocate (f(n, size(fields, 2)), e(n, size(extra, 2)))
            call fields3(now%problem%piece, x, v, f, e)
            fields(line%first:line%first + n - 1, :) = f
            extra(line%first:line%first + n - 1, :) = e
            deallocate (f, e)
         end associate
      end do
   end subroutine drive_snapshot

   !> The fields of the current state (the static state's, after the statics).
   subroutine drive_state_fields(self, fields, extra)
      class(network_drive), intent(in) :: self
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      real(dp), allocatable :: f(:, :), e(:, :)
      integer :: l, n
      do l = 1, size(self%lines)
         associate (now => self%net%lines(l))
            n = now%problem%piece%n
            allocate (f(n, size(fields, 2)), e(n, size(extra, 2)))
            call fields3(now%problem%piece, now%x, now%v, f, e)
            fields(self%lines(l)%first:self%lines(l)%first + n - 1, :) = f
            extra(self%lines(l)%first:self%lines(l)%first + n - 1, :) = e
            deallocate (f, e)
         end associate
      end do
   end subroutine drive_state_fields

   subroutine drive_record(self, run, i, ends, ends_y, measures, energies, stored, work)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer, intent(in) :: i
      real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
      real(dp), intent(inout) :: energies(4), stored, work(3)
      real(dp) :: en(5), ledger(4), f(3)
      integer :: l, side, k, n, slot
      integer, allocatable :: columns(:)
      en = 0
      measures = 0
      do l = 1, size(self%lines)
         associate (run3 => self%net%lines(l), piece => self%net%lines(l)%problem%piece, x => self%net%lines(l)%x)
            n = piece%n
            call piece%geometry(reshape(x(1:3*n), [3, n]), piece%e1, piece%l1, piece%th1)
            ! The loads' measures (the wetted and grounded lengths) of the whole network: each line's
            ! own loads (the same kinds in every line: &fluid and &seabed are the network's).
            if (size(measures) > 0 .and. allocated(piece%loads)) &
               call load_measures(piece%loads, reshape(x(1:3*n), [3, n]), piece%ds, measures, piece%s)
            do side = 1, 2
               slot = 2*(l - 1) + side
               k = merge(1, n, side == 1)
               if (side == 1) then
                  f = self%lines(l)%reaction(:, 1)
                  if (.not. piece%end_a%held()) f = piece%end_a%applied_force3(run%t)
               else
                  f = self%lines(l)%reaction(:, 2)
                  if (.not. piece%end_b%held()) f = piece%end_b%applied_force3(run%t)
               end if
               ends(:, slot) = [x(3*k - 2), x(3*k), run3%v(1, k), run3%v(3, k), end_tension(piece, side), f(1), f(3)]
               ends_y(:, slot) = [x(3*k - 1), run3%v(2, k), f(2)]
            end do
            run%summary%max_turning_angle = max(run%summary%max_turning_angle, maxval(piece%th1))
            columns = [(self%lines(l)%first - 1 + k, k=1, n)]
            call note_min_strain(run%summary, piece%l1, columns, run%s_out, run%t)
            run%summary%max_strain = max(run%summary%max_strain, maxval(piece%l1) - 1)
            if (run%options%energy) en = en + run3%energies()
         end associate
      end do
      if (run%options%energy) then
         ledger = self%net%ledger()
         energies = [en(1) + en(5), en(2:4)]
         stored = sum(en)
         work = ledger(2:4)
      end if
   end subroutine drive_record


   !> A network does not part (the input refuses &rupture for it).
   subroutine drive_split(self, run, error)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      type(error_type), allocatable, intent(out) :: error
      call fatal_error(error, 'a network of lines cannot part (no &rupture for networks yet)', stat_input)
   end subroutine drive_split

   subroutine drive_end_info(self, run, j, kind, held)
      class(network_drive), intent(in) :: self
      type(rod_run), intent(in) :: run
      integer, intent(in) :: j
      character(:), allocatable, intent(out) :: kind
      logical, intent(out) :: held
      integer :: l
      l = (j + 1)/2
      associate (piece => self%net%lines(l)%problem%piece)
         if (mod(j, 2) == 1) then
            kind = piece%end_a%kind()
            held = piece%end_a%held()
         else
            kind = piece%end_b%kind()
            held = piece%end_b%held()
         end if
      end associate
   end subroutine drive_end_info

   subroutine drive_conclude(self, run)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp) :: ledger(4)
      run%summary%newton_iterations = self%net%iterations
      run%summary%factorisations = self%net%iterations*size(self%lines)
      if (run%options%energy) then
         ledger = self%net%ledger()
         run%summary%dissipated = ledger(4)
      end if
   end subroutine drive_conclude

   !> Save the state between two steps: the run's progress and records, each line's state and
   !> ledger (as the 3-D run's pieces: rod3d/ for line 1, rod3d/<l>/ for line l), the free
   !> points and the points' work.
   subroutine drive_save_state(self, run, archive)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable :: error
      call exchange(self, run, archive, .true., error)
   end subroutine drive_save_state

   !> Load a state saved by save_state into a network prepared from the same case.
   subroutine drive_load_state(self, run, archive, error)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(state_archive), intent(inout) :: archive
      type(error_type), allocatable, intent(out) :: error
      integer :: l
      call exchange(self, run, archive, .false., error)
      if (allocated(error)) return
      if (.not. archive%ok) then
         call fatal_error(error, archive%message, stat_input)
         return
      end if
      self%net%t = run%t
      self%net%xp_old = self%net%xp
      do l = 1, size(self%lines)
         self%net%lines(l)%t = run%t
         self%net%lines(l)%work%usable = .false.
      end do
      call system_clock(run%clock%start, run%clock%rate)
      run%clock%last_report = 0
      run%clock%last_checkpoint = 0
      run%clock%records_at_checkpoint = run%history%n
   end subroutine drive_load_state

   subroutine exchange(self, rod, a, saving, error)
      type(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: rod
      class(state_archive), intent(inout) :: a
      logical, intent(in) :: saving
      type(error_type), allocatable, intent(out) :: error
      integer :: iterations(2), n_lines, l, points
      real(dp) :: work(1)
      character(:), allocatable :: prefix
      call sync_real(a, 'run/t', rod%t, saving)
      call sync_real(a, 'run/dt', rod%dt, saving)
      call exchange_progress(rod, a, saving)
      n_lines = size(self%lines)
      points = self%net%points
      call sync_int(a, 'network/lines', n_lines, saving)
      call sync_int(a, 'network/points', points, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (n_lines /= size(self%lines) .or. points /= self%net%points) then
            call fatal_error(error, 'the checkpoint holds a network of '//str(n_lines)//' lines and '//str(points)// &
                             ' free points, this case '//str(size(self%lines))//' and '//str(self%net%points), stat_input)
            return
         end if
      end if
      call sync_matrix(a, 'network/xp', self%net%xp, saving)
      work = self%net%joint_work
      call sync_reals(a, 'network/joint_work', work, saving)
      iterations = [self%net%iterations, 0]
      call sync_ints(a, 'network/newton_iterations', iterations, saving)
      if (.not. saving) then
         self%net%joint_work = work(1)
         self%net%iterations = iterations(1)
      end if
      do l = 1, n_lines
         prefix = 'rod3d/'
         if (l > 1) prefix = 'rod3d/'//str(l)//'/'
         call exchange_run3(a, prefix, self%net%lines(l), 'line '//str(l), saving, error)
         if (allocated(error) .or. .not. a%ok) return
         call sync_matrix(a, prefix//'reaction', self%lines(l)%reaction, saving)
      end do
      call exchange_records(rod, a, saving, error, with_y=.true., end_labels=network_end_labels(n_lines))
   end subroutine exchange
end module xcable_driver_network_drive
