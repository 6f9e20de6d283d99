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
!> length) are the sums over the lines.
!>
!> A break (&rupture line = k, or the break by tension over every line): the line is cut as
!> the 3-D run cuts a single line (driver/rod3d_drive/break.f90), from that line's own planar
!> run (its grid, break node, bodies and ramp): released at a held end, or cut in two at a
!> node inside, the piece on the end b side becoming a new last line of the network. The output
!> then has that node twice (the line's columns, then the new line's), and the history two
!> more ends, break_a and break_b (before the break: the break node with the pull of the cable
!> on either side). The break by tension watches every line's cells against their segments' MBL
!> (watch); the arc lengths it reports are the output's (the lines laid out one after another).
module xcable_driver_network_drive
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str
   use xcable_driver_rod_run, only: rod_run, cable_model
   use xcable_driver_rod3d_drive, only: check_state3, end_tension, state_between, exchange_run3, rod3d_drive, &
                                        release, break_node_ends, slot_end
   use xcable_driver_rod_run, only: watch_step
   use xcable_driver_network, only: network_run
   use xcable_driver_records, only: run_observer, note_min_strain
   use xcable_driver_rod3d_fields, only: fields3, n_fields3, field3_names
   use xcable_io_archive, only: state_archive, sync_real, sync_reals, sync_matrix, sync_int, sync_ints, sync_logical
   use xcable_driver_rod_run, only: exchange_progress
   use xcable_driver_history, only: exchange_records, open_history
   use xcable_model_rod3d, only: rod3d_piece
   use xcable_loads_load, only: load_measures
   implicit none
   private
   public :: network_drive, network_end_labels

   !> One line's place in the output and its previous level.
   type :: line_place
      !> Output columns of the line's nodes, and history slots of its two ends.
      integer, allocatable :: column(:)
      integer :: end_slot(2) = 0
      !> Before the break, the break node of this line (0: none) and its second output column.
      integer :: dup_node = 0, dup_column = 0
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
      !> The lines of the input (the network may have one more after a break inside a line).
      integer :: input_lines = 0
      !> The line that parts (0: none), its own planar run (its scene's break and ramp, grid,
      !> break node and bodies: what cuts it), the cut (its new ends' forces), and whether the
      !> break has happened.
      integer :: break_line = 0
      type(rod_run) :: break_rod
      type(rod3d_drive) :: cutter
      logical :: broken = .false.
      !> The break's place on the results' arc length (the lines one after another), m.
      real(dp) :: break_s = 0
      !> The break by tension's first pass: per output cell (between output columns c and c + 1),
      !> the factor watch mbl / (its segment's MBL) (0 between two lines), and the output's arc
      !> lengths the watch reports in.
      real(dp), allocatable :: cell_factor(:), s_watch(:)
      !> Per output cell of the input's lines, its segment's MBL (N; 0 between two lines and
      !> where nothing parts).
      real(dp), allocatable :: cell_mbl(:)
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
      !> The line and its cell of an output cell (the break by tension's first pass).
      procedure :: line_cell
      !> The output columns that start a piece of the output (each line's first but the first
      !> line's, and the second column of a break node inside a line), increasing.
      procedure :: piece_starts
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
      call open_history(run, 16, .true., history_labels(self))
   end subroutine drive_open_history

   !> The history's end labels: two per line of the input, and break_a, break_b with a break
   !> inside a line.
   function history_labels(self) result(labels)
      type(network_drive), intent(in) :: self
      character(len=8), allocatable :: labels(:)
      labels = network_end_labels(self%input_lines)
      if (self%break_line > 0) then
         if (self%break_rod%break_node > 0) labels = [character(len=8) :: labels, 'break_a', 'break_b']
      end if
   end function history_labels

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

   !> The search for a break by tension on the attempt of h (the first pass, the network without
   !> its break): every line's cells against their segments' MBL, as one chain of the output's
   !> cells (a cell between two lines has the factor 0: it does not part).
   subroutine drive_watch(self, run, h, retry)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      logical, intent(out) :: retry
      real(dp), allocatable :: tensions(:, :), r0(:, :), r1(:, :), ds(:)
      integer :: l, c, n, m
      retry = .false.
      if (.not. allocated(self%cell_factor)) return
      m = size(self%cell_factor)
      allocate (tensions(m, 3), r0(3, m + 1), r1(3, m + 1), ds(m))
      tensions = 0
      tensions(:, 3) = self%cell_factor
      ds = 1
      do l = 1, size(self%lines)
         associate (line => self%net%lines(l), piece => self%net%lines(l)%problem%piece, col => self%lines(l)%column)
            n = piece%n
            r0(:, col) = reshape(line%x_old(1:3*n), [3, n])
            r1(:, col) = reshape(line%x(1:3*n), [3, n])
            do c = 1, n - 1
               tensions(col(c), 1) = piece%cell_tension(c, norm2(r0(:, col(c + 1)) - r0(:, col(c)))/piece%ds(c) - 1)
               tensions(col(c), 2) = piece%cell_tension(c, norm2(r1(:, col(c + 1)) - r1(:, col(c)))/piece%ds(c) - 1)
               ds(col(c)) = piece%ds(c)
            end do
         end associate
      end do
      call watch_step(run, h, r0, r1, ds, self%net%lines(1)%problem%piece%law, retry, tensions, self%s_watch)
      if (retry) call self%net%reject()
   end subroutine drive_watch

   !> The output columns that start a piece of the output, increasing.
   function piece_starts(self) result(starts)
      class(network_drive), intent(in) :: self
      integer, allocatable :: starts(:)
      integer :: l, i, k
      allocate (starts(0))
      do l = 1, size(self%lines)
         if (self%lines(l)%column(1) > 1) starts = [starts, self%lines(l)%column(1)]
         if (self%lines(l)%dup_column > 0) starts = [starts, self%lines(l)%dup_column]
      end do
      ! (A few lines: insertion sort.)
      do i = 2, size(starts)
         k = starts(i)
         do l = i - 1, 1, -1
            if (starts(l) <= k) exit
            starts(l + 1) = starts(l)
         end do
         starts(l + 1) = k
      end do
   end function piece_starts

   !> The line and its cell of the output's cell c (cell c between output columns c and c + 1);
   !> line 0 for a cell between two lines.
   subroutine line_cell(self, c, l, cell)
      !> Network run (not broken).
      class(network_drive), intent(in) :: self
      integer, intent(in) :: c
      integer, intent(out) :: l, cell
      do l = 1, size(self%lines)
         associate (col => self%lines(l)%column)
            if (c >= col(1) .and. c < col(size(col))) then
               cell = c - col(1) + 1
               return
            end if
         end associate
      end do
      l = 0
      cell = 0
   end subroutine line_cell

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
            call place_fields(line, f, e, fields, extra)
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
            call place_fields(self%lines(l), f, e, fields, extra)
            deallocate (f, e)
         end associate
      end do
   end subroutine drive_state_fields

   !> A line's fields (its nodes, f and e) in their output columns (the break node in both of
   !> its columns before the break).
   pure subroutine place_fields(place, f, e, fields, extra)
      type(line_place), intent(in) :: place
      real(dp), intent(in) :: f(:, :), e(:, :)
      real(dp), intent(inout) :: fields(:, :), extra(:, :)
      fields(place%column, :) = f
      extra(place%column, :) = e
      if (place%dup_column > 0) then
         fields(place%dup_column, :) = f(place%dup_node, :)
         extra(place%dup_column, :) = e(place%dup_node, :)
      end if
   end subroutine place_fields

   subroutine drive_record(self, run, i, ends, ends_y, measures, energies, stored, work)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer, intent(in) :: i
      real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
      real(dp), intent(inout) :: energies(4), stored, work(3)
      real(dp) :: en(5), ledger(4), f(3)
      integer :: l, side, k, n, slot
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
               slot = self%lines(l)%end_slot(side)
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
            call note_min_strain(run%summary, piece%l1, self%lines(l)%column, run%s_out, run%t)
            ! Before a break inside the line, its two ends break_a and break_b are the break node.
            if (self%lines(l)%dup_node > 0) &
               call break_node_ends(piece, x, run3%v, self%lines(l)%dup_node, ends(:, 2*self%input_lines + 1:), &
                                    ends_y(:, 2*self%input_lines + 1:))
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


   !> The break of line break_line at the time the step loop reached: the line cut as a single
   !> 3-D line is (rod3d_drive's split, from the line's own planar run), and the pieces put in
   !> the network in its place (network_run's part_line).
   subroutine drive_split(self, run, error)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      type(error_type), allocatable, intent(out) :: error
      integer :: lb
      lb = self%break_line
      if (lb == 0) then
         call fatal_error(error, 'the network has no line that parts', stat_input)
         return
      end if
      call load_cutter(self, lb)
      self%break_rod%t = run%t
      call self%cutter%split(self%break_rod, error)
      if (allocated(error)) then
         error%message = 'the break of line '//str(lb)//': '//error%message
         return
      end if
      call install_pieces(self)
      self%broken = .true.
      run%broken = .true.
   end subroutine drive_split

   !> The cutter holds line lb as the one piece of a 3-D run (before split or release).
   subroutine load_cutter(self, lb)
      type(network_drive), intent(inout) :: self
      integer, intent(in) :: lb
      integer :: k
      if (allocated(self%cutter%pieces)) deallocate (self%cutter%pieces)
      allocate (self%cutter%pieces(1))
      self%cutter%pieces(1)%run = self%net%lines(lb)
      self%cutter%pieces(1)%column = [(k, k=1, self%net%lines(lb)%problem%piece%n)]
      self%cutter%pieces(1)%reaction = self%lines(lb)%reaction
   end subroutine load_cutter

   !> The cutter's pieces into the network in place of the line that parted: its first piece in
   !> the line's place, the second (a break inside) as a new last line, with the output columns
   !> and history slots of their nodes and ends.
   subroutine install_pieces(self)
      type(network_drive), intent(inout) :: self
      type(line_place), allocatable :: places(:)
      integer :: lb, kb, n, last
      lb = self%break_line
      if (size(self%cutter%pieces) == 1) then
         call self%net%part_line(lb, self%cutter%pieces(1)%run)
      else
         call self%net%part_line(lb, self%cutter%pieces(1)%run, self%cutter%pieces(2)%run)
         kb = self%break_rod%break_node
         last = size(self%lines) + 1
         allocate (places(last))
         places(1:last - 1) = self%lines
         associate (old => self%lines(lb), new => places(last))
            n = size(old%column)
            new%column = [old%dup_column, old%column(kb + 1:n)]
            new%end_slot = [2*self%input_lines + 2, old%end_slot(2)]
            new%reaction(:, 2) = old%reaction(:, 2)
            new%reaction(:, 1) = 0
            places(lb)%column = old%column(1:kb)
            places(lb)%end_slot = [old%end_slot(1), 2*self%input_lines + 1]
            places(lb)%reaction(:, 2) = 0
            places(lb)%dup_node = 0
            places(lb)%dup_column = 0
         end associate
         call move_alloc(places, self%lines)
         self%lines(last)%x_prev = self%net%lines(last)%x
         self%lines(last)%v_prev = self%net%lines(last)%v
      end if
      self%lines(lb)%x_prev = self%net%lines(lb)%x
      self%lines(lb)%v_prev = self%net%lines(lb)%v
      deallocate (self%cutter%pieces)
   end subroutine install_pieces

   subroutine drive_end_info(self, run, j, kind, held)
      class(network_drive), intent(in) :: self
      type(rod_run), intent(in) :: run
      integer, intent(in) :: j
      character(:), allocatable, intent(out) :: kind
      logical, intent(out) :: held
      integer :: l
      kind = ''
      held = .false.
      do l = 1, size(self%lines)
         call slot_end(self%net%lines(l)%problem%piece, self%lines(l)%end_slot, j, kind, held)
      end do
   end subroutine drive_end_info

   subroutine drive_conclude(self, run)
      class(network_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp) :: ledger(4)
      run%summary%newton_iterations = self%net%iterations
      run%summary%factorisations = self%net%iterations*size(self%lines)
      ! The break: which line, and where on the results' arc length (the lines one after another).
      if (self%broken) then
         run%summary%break_line = self%break_line
         run%summary%break_s = self%break_s
      end if
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
      integer :: iterations(2), n_lines, l, points, expected, n
      real(dp) :: work(1)
      character(:), allocatable :: prefix
      call sync_real(a, 'run/t', rod%t, saving)
      call sync_real(a, 'run/dt', rod%dt, saving)
      call exchange_progress(rod, a, saving)
      n_lines = size(self%lines)
      points = self%net%points
      call sync_int(a, 'network/lines', n_lines, saving)
      call sync_int(a, 'network/points', points, saving)
      if (self%break_line > 0) then
         call sync_logical(a, 'network/broken', self%broken, saving)
         call sync_matrix(a, 'network/cut_force', self%cutter%cut_force, saving)
         if (self%break_rod%break_node > 0) then
            call sync_reals(a, 'network/cut_couple', self%cutter%cut_couple, saving)
            call sync_matrix(a, 'network/cut_axis', self%cutter%cut_axis, saving)
            call sync_reals(a, 'network/cut_torque', self%cutter%cut_torque, saving)
         end if
      end if
      if (.not. saving) then
         if (.not. a%ok) return
         expected = self%input_lines
         if (self%broken .and. self%break_rod%break_node > 0) expected = expected + 1
         if (n_lines /= expected .or. points /= self%net%points) then
            call fatal_error(error, 'the checkpoint holds a network of '//str(n_lines)//' lines and '//str(points)// &
                             ' free points, this case '//str(expected)//' and '//str(self%net%points)// &
                             ' at that stage', stat_input)
            return
         end if
         ! A broken network: its pieces as the break made them, their states loaded below.
         if (self%broken) then
            call load_cutter(self, self%break_line)
            self%cutter%broken = .true.
            self%break_rod%broken = .true.
            call release(self%cutter, self%break_rod, error)
            if (allocated(error)) return
            call install_pieces(self)
            rod%broken = .true.
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
      ! The cut pieces' anchored twist angles: their first nodes', pinned there since the cut.
      if (.not. saving .and. self%broken .and. self%break_rod%break_node > 0) then
         do l = 1, n_lines
            if (l /= self%break_line .and. l /= n_lines) cycle
            n = self%net%lines(l)%problem%piece%n
            self%net%lines(l)%problem%piece%psi_anchor = self%net%lines(l)%x(3*n + 1)
         end do
      end if
      call exchange_records(rod, a, saving, error, with_y=.true., end_labels=history_labels(self))
   end subroutine exchange
end module xcable_driver_network_drive
