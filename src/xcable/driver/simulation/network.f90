!> The preparation of a network of lines (a submodule of driver/simulation.f90).
submodule (xcable_driver_simulation) xcable_driver_simulation_network
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
      real(dp), allocatable :: s_out(:), fields(:, :), extra(:, :)
      self%is_network = .true.
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
         associate (piece => runs(l)%problem%piece)
            n = piece%n
            self%network%lines(l)%first = first
            first = first + n
            s_out = [s_out, piece%s + offset]
            offset = offset + piece%s(n)
         end associate
         dt = min(dt, line%rod%dt)
         if (l == 1) then
            self%rod = line%rod
            self%terms = 'rod3d network: '//trim(line%terms(7:))
         end if
      end do
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
end submodule xcable_driver_simulation_network
