!> The preparation of a network of lines (a submodule of driver/simulation.f90).
submodule (xcable_driver_simulation) xcable_driver_simulation_network
   use xcable_model_rod3d, only: rod3d_piece
   implicit none

contains

   !> A network of lines (&line_k, free &point_k): each line prepared as a single line (its case
   !> config%line_case(l): its free points held where the input puts them, the body of a free
   !> point on the lowest-numbered line there), then the statics of the whole network
   !> (driver/network.f90), and the records of the run laid out line after line
   !> (driver/network_drive.f90). The step is the shortest of the lines' steps.
   module subroutine prepare_network(self, config, error)
      type(simulation), intent(inout) :: self
      type(case_config), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: line
      type(rod3d_run), allocatable :: runs(:)
      type(network_joint), allocatable :: joints(:)
      integer, allocatable :: ends(:, :)
      integer :: l, p, j, n, first, free, n_out
      real(dp) :: dt, offset
      real(dp), allocatable :: s_out(:), fields(:, :), extra(:, :), s_line(:)
      integer :: k, kb
      logical :: moving
      self%is_network = .true.
      moving = .false.
      allocate (self%network%cell_mbl(0))
      self%model = '3d'
      allocate (runs(config%line_count), self%network%lines(config%line_count))
      first = 1
      offset = 0
      dt = huge(1.0_dp)
      allocate (s_out(0))
      do l = 1, config%line_count
         call line%prepare(config%line_case(l), error)
         if (allocated(error)) then
            error%message = '&line_'//str(l)//': '//point_words(error%message, l)
            return
         end if
         runs(l) = line%rod3%pieces(1)%run
         associate (piece => runs(l)%problem%piece, place => self%network%lines(l), scene => line%rod%scene)
            n = piece%n
            place%column = [(first + k - 1, k=1, n)]
            place%end_slot = [2*l - 1, 2*l]
            s_line = piece%s + offset
            ! Each cell's MBL (its segment's; 0: it does not part), for the break by tension.
            self%network%cell_mbl = [self%network%cell_mbl, &
                                     [(scene%sections(section_at(scene, 0.5_dp*(piece%s(k) + piece%s(k + 1))))%mbl, &
                                       k=1, n - 1)], 0.0_dp]
            if (scene%breaks) then
               ! The line that parts (&rupture line): cut as a single line is, from its own run.
               self%network%break_line = l
               self%network%break_rod = line%rod
               kb = line%rod%break_node
               if (kb > 0) then
                  ! The break node twice in the output: the line's columns, then the new line's.
                  place%column(kb + 1:n) = place%column(kb + 1:n) + 1
                  place%dup_node = kb
                  place%dup_column = first + kb
                  s_line = [s_line(1:kb), s_line(kb:n)]
                  self%network%break_s = s_line(kb)
               else
                  self%network%break_s = merge(s_line(size(s_line)), s_line(1), scene%break_at_b)
               end if
            end if
            ! Whether an end of a line moves or changes its load (the points on it held at their guesses).
            moving = moving .or. scene%end_a%time_dependent() .or. scene%end_b%time_dependent()
            first = first + size(s_line)
            s_out = [s_out, s_line]
            offset = offset + piece%s(n)
         end associate
         dt = min(dt, line%rod%dt)
         if (l == 1) then
            self%rod = line%rod
            self%terms = 'rod3d network: '//trim(line%terms(7:))
         end if
      end do
      self%network%input_lines = config%line_count
      ! (The last line's cells end the list: no cell after it.)
      self%network%cell_mbl = self%network%cell_mbl(1:size(self%network%cell_mbl) - 1)
      ! The lines' ends at free points.
      allocate (joints(0), self%network%point_number(0))
      free = 0
      do p = 1, config%point_count
         if (trim(config%points(p)%kind) /= 'free') cycle
         free = free + 1
         self%network%point_number = [self%network%point_number, p]
         ends = config%point_lines(p)
         do j = 1, size(ends, 2)
            joints = [joints, network_joint(ends(1, j), ends(2, j), free)]
         end do
      end do
      call self%network%net%init(runs, joints, free, error)
      if (.not. allocated(error)) call self%network%net%statics(0.0_dp, error)
      if (allocated(error)) then
         error%message = config%source//': '//error%message
         return
      end if
      ! The run's records: the lines one after another.
      n_out = first - 1
      self%rod%n_out = n_out
      self%rod%s_out = s_out
      self%rod%dt = dt
      self%rod%break_node = 0
      self%rod%other_ends_change = moving
      ! The run's break is the line's: when it starts, its ramp and the front it sends.
      self%rod%scene%breaks = self%network%break_line > 0
      if (self%network%break_line > 0) then
         associate (sc => self%network%break_rod%scene)
            self%rod%scene%break_time = sc%break_time
            self%rod%scene%t_break = sc%t_break
            self%rod%scene%s_break = self%network%break_s
            self%rod%scene%break_at_a = sc%break_at_a
            self%rod%scene%break_at_b = sc%break_at_b
            self%rod%front_cells = self%network%break_rod%front_cells
         end associate
      end if
      if (allocated(self%rod%pieces)) deallocate (self%rod%pieces)
      allocate (fields(n_out, n_fields), extra(n_out, n_fields3))
      call self%network%state_fields(fields, extra)
      self%rod%info%s = s_out
      self%rod%info%fields = fields
      self%rod%info%extra = extra
      self%network%static_extra = extra
      associate (net => self%network%net, last => self%network%net%lines(config%line_count))
         self%rod%info%tension_a = norm2(net%lines(1)%problem%piece%reaction(1, 0.0_dp))
         self%rod%info%tension_b = norm2(last%problem%piece%reaction(last%problem%piece%n, 0.0_dp))
      end associate
      self%rod%info%max_tension = maxval(fields(:, 1))
      self%rod%info%one_line = .false.
      call self%network%open_history(self%rod)
      ! The static resolution check on the network's state (the lines' ends, joints included, turn no cells).
      self%rod%static_max_turn = 0
      do l = 1, config%line_count
         associate (piece => self%network%net%lines(l)%problem%piece, x => self%network%net%lines(l)%x)
            n = piece%n
            call piece%geometry(reshape(x(1:3*n), [3, n]), piece%e1, piece%l1, piece%th1)
            self%rod%static_max_turn = max(self%rod%static_max_turn, maxval(piece%th1))
         end associate
      end do
   contains

      !> A message of a line's own case in the network's words: its &end_a / &end_b are its points.
      function point_words(message, l) result(text)
         character(*), intent(in) :: message
         integer, intent(in) :: l
         character(:), allocatable :: text
         character(len=6), parameter :: groups(2) = ['&end_a', '&end_b']
         integer :: side, k, p
         logical :: free_end
         text = message
         free_end = .false.
         do side = 1, 2
            p = config%lines(l)%end_point(side)
            k = index(text, groups(side))
            if (k == 0 .or. p < 1) cycle
            text = text(1:k - 1)//'&point_'//str(p)//' (its end '//merge('a', 'b', side == 1)//')'// &
                   text(k + len(groups(side)):)
            free_end = free_end .or. trim(config%points(p)%kind) == 'free'
         end do
         if (free_end) text = text//' (a free point''s x, y, z are the first guess of where it settles: put it '// &
                              'within reach of its lines)'
      end function point_words
   end subroutine prepare_network

   !> The break by tension of a network (&rupture criterion = 'tension'), as find_break does it
   !> for a single line: the static tensions checked against each cell's MBL, then a first pass
   !> (the network without a break, no output) whose step loop watches every line's cells
   !> against their segments' MBL (network_drive's watch) and stops where the first reaches it.
   !> The network is then prepared again with a break by time of that line, at the node
   !> break_node_of gives (an end at a free point does not count as held: the line is cut inside).
   module subroutine find_network_break(self, config, error, statics_only)
      type(simulation), intent(inout), target :: self
      type(case_config), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: statics_only
      type(case_config) :: again
      type(tension_watch) :: found
      type(network_drive) :: fresh_network
      type(rod_run) :: fresh_rod
      class(cable_model), pointer :: model
      real(dp) :: t, mbl, watch_mbl, mbl_found
      integer :: l, c, n, kb, cell
      ! The static tensions against each cell's MBL.
      do l = 1, size(self%network%lines)
         associate (piece => self%network%net%lines(l)%problem%piece, x => self%network%net%lines(l)%x, &
                    col => self%network%lines(l)%column)
            do c = 1, piece%n - 1
               mbl = self%network%cell_mbl(col(c))
               if (mbl <= 0) cycle
               t = piece%cell_tension(c, norm2(x(3*c + 1:3*c + 3) - x(3*c - 2:3*c))/piece%ds(c) - 1)
               if (t >= (1 - rupture_tolerance)*mbl) then
                  call fatal_error(error, config%source//': '//mbl_group(l, piece, c)//': mbl = '//real_text(mbl)// &
                                   ': at or below the static tension of &line_'//str(l)//', '//quantity(t, 'N')// &
                                   ' at s = '//quantity(0.5_dp*(piece%s(c) + piece%s(c + 1)) - piece%s(1), 'm')// &
                                   ' of the line: the line would part in statics; give an mbl above it', stat_input)
                  return
               end if
            end do
         end associate
      end do
      if (present(statics_only)) then
         if (statics_only) return
      end if
      ! The first pass: each cell's tension in units of the largest MBL.
      watch_mbl = maxval(self%network%cell_mbl)
      allocate (self%network%cell_factor(size(self%network%cell_mbl)))
      self%network%cell_factor = 0
      where (self%network%cell_mbl > 0) self%network%cell_factor = watch_mbl/self%network%cell_mbl
      self%network%s_watch = self%rod%s_out
      self%rod%watch%mbl = watch_mbl
      model => self%model_of()
      call run_dynamics(self%rod, model, error=error)
      if (allocated(error)) then
         call prefix_error(error, 'the first pass of the break by tension (the network without the break, to '// &
                           'find where and when a tension reaches its mbl): ')
         return
      end if
      found = self%rod%watch
      found%mbl = 0
      found%h_aim = 0
      again = config
      mbl_found = watch_mbl
      if (found%found) then
         call self%network%line_cell(found%cell, l, cell)
         associate (piece => self%network%net%lines(l)%problem%piece, col => self%network%lines(l)%column)
            n = piece%n
            kb = break_node_of(found%cells(col(1):col(n) - 1), cell, &
                               piece%end_a%held() .and. .not. piece%keep_rows(1), &
                               piece%end_b%held() .and. .not. piece%keep_rows(2))
            mbl_found = self%network%cell_mbl(found%cell)
            again%break_criterion = 'time'
            again%break_line = l
            again%break_time = found%time
            again%s_break = piece%s(kb) - piece%s(1)
         end associate
      end if
      ! The network prepared again: with the break found, or without one.
      self%rod = fresh_rod
      self%network = fresh_network
      call prepare_network(self, again, error)
      if (allocated(error)) return
      self%rod%rupture = found
      self%rod%scene%by_tension = .true.
      self%rod%scene%mbl = mbl_found

   contains

      !> The group whose mbl cell c of line l has: its segment's, or &rupture's.
      function mbl_group(l, piece, c) result(group)
         integer, intent(in) :: l, c
         type(rod3d_piece), intent(in) :: piece
         character(:), allocatable :: group
         integer :: j
         group = '&rupture'
         if (config%lines(l)%segment_count == 0 .or. .not. allocated(piece%cell_sec)) return
         j = config%lines(l)%segments(piece%cell_sec(c))
         if (config%segments(j)%mbl > 0) group = '&segment_'//str(j)
      end function mbl_group
   end subroutine find_network_break
end submodule xcable_driver_simulation_network
