!> Networks of lines joined at free points (driver/network.f90, issue "Moorings"): two lines
!> meeting at a free point with a buoy against the one line of two segments with the buoy at
!> its joint (the same equations, written twice: statics and a heave, in a current, with drag
!> and added mass); the kept rows of a joint end against central differences; the points'
!> stiffness (the bordered system's Schur complement) against differences of re-solved
!> networks; a three-line spread meeting at a buoy, symmetric, found from a guess off its
!> axis; its ledger over a heave of one fairlead.
module suite_network
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_core_error, only: stat_input
   use xcable_io_config, only: case_config
   use xcable_io_input, only: read_config
   use xcable_driver_simulation, only: simulation
   use xcable_driver_rod3d_drive, only: state_fields
   use xcable_driver_records, only: n_fields, n_fields3
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_driver_network, only: network_run, network_joint
   use xcable_io_config, only: point_config
   use xcable_fixtures, only: write_text
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_network

   character(len=*), parameter :: path = 'build/suite_network.nml'
   character(len=*), parameter :: nl = new_line('a')
   !> The water, the rope's material, the numerics.
   character(len=*), parameter :: common = &
      "&material law = 'linear', ea = 2.0e6, compression = 'none' /"//nl// &
      "&fluid density = 1025.0, cd_normal = 1.2, cd_tangential = 0.05, ca_normal = 1.0, current_x = 0.3, "// &
      "surface_z = 0.0 /"//nl
   !> The numerics.
   character(len=*), parameter :: numerics = "&numerics model = '3d', mass_matrix = 'lumped', newton_tol = 1e-12"
   !> The anchor, the fairlead (heaved 1 m over 4 s) and the buoy at the joint (m, kg, m^3).
   real(dp), parameter :: anchor(3) = [0.0_dp, 0.0_dp, -60.0_dp], fairlead(3) = [70.0_dp, 20.0_dp, -5.0_dp]
   character(len=*), parameter :: heave = "kind = 'motion', amplitude = 1.0, period = 4.0, direction_z = 1.0"

contains

   subroutine collect_network(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('two_lines_at_a_buoy_equal_one_line_with_the_buoy', test_equal_one_line), &
               new_unittest('kept_rows_jacobian_fd', test_kept_rows), &
               new_unittest('point_stiffness_fd', test_point_stiffness), &
               new_unittest('spread_at_a_buoy_symmetric_and_ledger', test_spread), &
               new_unittest('input_two_lines_equal_one_line', test_input_equal_one_line), &
               new_unittest('buoy_on_legs_lying_on_the_seabed_ledger', test_seabed_ledger), &
               new_unittest('break_by_time_inside_equals_one_line', test_break_time), &
               new_unittest('break_by_time_below_the_buoy_equals_one_line', test_break_time_below), &
               new_unittest('break_by_tension_inside_equals_one_line', test_break_tension_inside), &
               new_unittest('break_by_tension_at_the_fairlead_equals_one_line', test_break_tension_end), &
               new_unittest('break_by_tension_not_reached_equals_one_line', test_break_not_reached), &
               new_unittest('mbl_below_the_static_tension_refused', test_mbl_below_static)]
   end subroutine collect_network

   !> Read and prepare a case given as namelist text.
   subroutine prepared(text, sim, error)
      character(*), intent(in) :: text
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      call write_text(path, common//text//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      c%quiet = .true.
      call sim%prepare(c, error)
   end subroutine prepared

   !> Read, prepare and run a case given as namelist text.
   subroutine ran(text, sim, error)
      character(*), intent(in) :: text
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      call write_text(path, text)
      call read_config(path, c, error)
      if (allocated(error)) return
      c%quiet = .true.
      call sim%prepare(c, error)
      if (.not. allocated(error)) call sim%run(error=error)
   end subroutine ran

   !> Read and prepare a case, with a body put on end b (a joint end's body, which the input
   !> would refuse on the held end the line is prepared with).
   subroutine prepared_with_body(text, body, sim, error)
      character(*), intent(in) :: text
      type(point_config), intent(in) :: body
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      call write_text(path, common//text//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      c%quiet = .true.
      c%point_count = 1
      c%points(1) = body
      call sim%prepare(c, error)
   end subroutine prepared_with_body

   !> The buoy: 50 kg displacing 0.3 m^3, ca 0.5, cd 0.8 on 0.5 m^2.
   function buoy(joint) result(b)
      integer, intent(in) :: joint
      type(point_config) :: b
      b%joint = joint
      b%mass = 50
      b%volume = 0.3_dp
      b%ca = 0.5_dp
      b%cd = 0.8_dp
      b%area = 0.5_dp
   end function buoy

   function xyz(name, p) result(text)
      character(*), intent(in) :: name
      real(dp), intent(in) :: p(3)
      character(:), allocatable :: text
      character(len=100) :: buffer
      write (buffer, '(3(a,es24.16e3))') ', x = ', p(1), ', y = ', p(2), ', z = ', p(3)
      text = name//trim(buffer)
   end function xyz

   !> The one line: 40 m of heavier rope (3000 kg/m^3) from the anchor, 50 m of rope to the fairlead,
   !> the buoy at the joint.
   function one_line(numerics_end) result(text)
      !> The end of the &numerics group (default ' /').
      character(*), intent(in), optional :: numerics_end
      character(:), allocatable :: text, tail
      tail = " /"
      if (present(numerics_end)) tail = numerics_end
      text = "&cable length = 90.0, diameter = 0.05, density = 1500.0, bending_stiffness = 1e-6 /"//nl// &
             numerics//tail//nl//"&segment_1 length = 40.0, nodes = 41, density = 3000.0 /"//nl// &
             "&segment_2 length = 50.0, nodes = 51 /"//nl// &
             xyz("&end_a kind = 'fixed'", anchor)//" /"//nl// &
             xyz("&end_b "//heave, fairlead)//" /"//nl
   end function one_line

   !> The two lines of one_line, the joint at the guess.
   subroutine two_lines(guess, lines, error)
      real(dp), intent(in) :: guess(3)
      type(rod3d_run), allocatable, intent(out) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim1, sim2
      call prepared_with_body("&cable length = 40.0, diameter = 0.05, density = 3000.0, bending_stiffness = 1e-6 /"//nl// &
                              numerics//", nodes = 41 /"//nl// &
                              xyz("&end_a kind = 'fixed'", anchor)//" /"//nl// &
                              xyz("&end_b kind = 'fixed'", guess)//" /", buoy(1), sim1, error)
      if (allocated(error)) return
      call prepared("&cable length = 50.0, diameter = 0.05, density = 1500.0, bending_stiffness = 1e-6 /"//nl// &
                    numerics//", nodes = 51 /"//nl// &
                    xyz("&end_a kind = 'fixed'", guess)//" /"//nl// &
                    xyz("&end_b "//heave, fairlead)//" /", sim2, error)
      if (allocated(error)) return
      allocate (lines(2))
      lines(1) = sim1%rod3%pieces(1)%run
      lines(2) = sim2%rod3%pieces(1)%run
   end subroutine two_lines

   !> The two segments of one_line, without an MBL.
   function plain_segments() result(text)
      character(:), allocatable :: text
      text = "&segment_1 length = 40.0, nodes = 41, density = 3000.0 /"//nl//"&segment_2 length = 50.0, nodes = 51 /"//nl
   end function plain_segments

   !> The network of one_line (input): the segment groups given, line 1 (segment 1) from the anchor
   !> to the free point with the buoy, first guessed 2.7 m off, line 2 (segment 2) on to the fairlead.
   function two_lines_text(segments) result(text)
      character(*), intent(in) :: segments
      character(:), allocatable :: text
      text = "&cable length = 90.0, diameter = 0.05, density = 1500.0, bending_stiffness = 1e-6 /"//nl//segments// &
             xyz("&point_1 kind = 'free'", [15.0_dp, 6.0_dp, -40.0_dp])// &
             ", mass = 50.0, volume = 0.3, ca = 0.5, cd = 0.8, area = 0.5 /"//nl// &
             xyz("&point_2 kind = 'fixed'", anchor)//" /"//nl// &
             xyz("&point_3 "//heave, fairlead)//" /"//nl// &
             "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1 /"//nl// &
             "&line_2 end_a = 'point_1', end_b = 'point_3', segments = 2 /"//nl
   end function two_lines_text

   !> Positions of a run's nodes first .. last (3, :).
   function nodes_of(run, first, last) result(r)
      type(rod3d_run), intent(in) :: run
      integer, intent(in) :: first, last
      real(dp) :: r(3, last - first + 1)
      r = reshape(run%x(3*first - 2:3*last), [3, last - first + 1])
   end function nodes_of

   !> Two lines meeting at a free point with the buoy on it are the one line of two segments with
   !> the buoy at its joint: the same unknowns and equations (lumped mass; the joint's bending,
   !> EI 1e-6 N m^2, is the only term the one line has more). Statics from a guess 2.7 m off, then
   !> 40 steps of 0.025 s of the heave in the current, against the one line on the same steps.
   subroutine test_equal_one_line(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: ref
      type(rod3d_run), allocatable :: lines(:)
      type(network_run) :: net
      real(dp) :: joint(3), err_static, err_step, dt, theta, led(4), led0(4), drift, scale
      integer :: i
      call prepared_with_body(one_line(), buoy(1), ref, error)
      if (allocated(error)) return
      associate (r => ref%rod3%pieces(1)%run)
         joint = r%x(3*41 - 2:3*41)
         call two_lines(joint + [2.0_dp, -1.0_dp, 1.5_dp], lines, error)
         if (allocated(error)) return
         call net%init(lines, [network_joint(1, 2, 1), network_joint(2, 1, 1)], 1, error)
         if (allocated(error)) return
         call net%statics(0.0_dp, error)
         if (allocated(error)) return
         scale = 90
         err_static = max(maxval(abs(nodes_of(net%lines(1), 1, 41) - nodes_of(r, 1, 41))), &
                          maxval(abs(nodes_of(net%lines(2), 1, 51) - nodes_of(r, 41, 91))))/scale
         write (output_unit, '(4x,a,es9.2,a,i0,a,es9.2,a)') 'statics: ', err_static, ' of L off the one line (', &
            net%last_iterations, ' iterations; imbalance ', maxval(abs(net%imbalance)), ' N)'
         ! Measured 2.1e-14 (Newton to 1e-12).
         call check(error, err_static < 1.0e-13_dp, 'the network''s static state is '//str(err_static)// &
                    ' of L off the one line''s')
         if (allocated(error)) return
         dt = 0.025_dp
         theta = 0.5_dp
         led0 = net%ledger()
         do i = 1, 40
            call r%step(dt, theta, error)
            if (allocated(error)) return
            call net%attempt(dt, theta, error)
            if (allocated(error)) return
            call net%accept(dt, theta)
         end do
         err_step = max(maxval(abs(nodes_of(net%lines(1), 1, 41) - nodes_of(r, 1, 41))), &
                        maxval(abs(nodes_of(net%lines(2), 1, 51) - nodes_of(r, 41, 91))))/scale
         led = net%ledger()
         drift = abs((led(1) - led0(1)) - (led(2) + led(3) - led(4)))/max(abs(led(1)), 1.0_dp)
         write (output_unit, '(4x,a,es9.2,a,es9.2)') 'after 1 s of heave: ', err_step, ' of L; ledger ', drift
         ! Measured 8.4e-15 and 1.4e-14.
         call check(error, err_step < 5.0e-14_dp, 'after the heave the network is '//str(err_step)// &
                    ' of L off the one line')
         if (allocated(error)) return
         call check(error, drift < 1.0e-13_dp, 'the network''s ledger does not close: '//str(drift))
      end associate
   end subroutine test_equal_one_line

   !> The kept rows of a joint end (its momentum rows before the held rows replace them) against
   !> central differences of the kept residual, in a step and in the statics.
   subroutine test_kept_rows(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run), allocatable :: lines(:)
      type(network_run) :: net
      real(dp), allocatable :: x(:), res(:)
      real(dp) :: fd(3), h, worst, scale_row, kept(3, 9)
      integer :: mode, side, j, col, m, first
      call two_lines([25.0_dp, 5.0_dp, -40.0_dp], lines, error)
      if (allocated(error)) return
      call net%init(lines, [network_joint(1, 2, 1), network_joint(2, 1, 1)], 1, error)
      if (allocated(error)) return
      call net%statics(0.0_dp, error)
      if (allocated(error)) return
      worst = 0
      do mode = 1, 2
         if (mode == 1) then
            call net%attempt(0.05_dp, 0.5_dp, error)
            if (allocated(error)) return
         end if
         associate (run => net%lines(1), piece => net%lines(1)%problem%piece)
            ! Off balance: move the nodes a little, so that the rows are not zero.
            m = size(run%x)
            x = run%x + 0.01_dp*sin([(real(j, dp), j=1, m)])
            allocate (res(m))
            do side = 1, 2
               if (.not. piece%keep_rows(side)) cycle
               call run%problem%evaluate(x, res, run%work%jacobian, .true.)
               kept = piece%kept_jac(:, :, side)
               first = piece%kept_first(side)
               scale_row = maxval(abs(kept))
               do j = 1, 9
                  col = first - 1 + j
                  h = 1.0e-6_dp
                  x(col) = x(col) + h
                  call run%problem%evaluate(x, res, run%work%jacobian, .false.)
                  fd = piece%kept_residual(:, side)
                  x(col) = x(col) - 2*h
                  call run%problem%evaluate(x, res, run%work%jacobian, .false.)
                  fd = (fd - piece%kept_residual(:, side))/(2*h)
                  x(col) = x(col) + h
                  worst = max(worst, maxval(abs(fd - kept(:, j)))/scale_row)
               end do
            end do
            deallocate (res)
         end associate
         if (mode == 1) call net%reject()
      end do
      write (output_unit, '(4x,a,es9.2,a)') 'kept rows: ', worst, ' of the row scale off central differences'
      ! Measured 8.4e-10 (the differences' truncation).
      call check(error, worst < 5.0e-9_dp, 'the kept rows'' Jacobian is off central differences by '//str(worst))
   end subroutine test_kept_rows

   !> The points' stiffness (the Schur complement of the bordered Newton matrix) against
   !> differences of the point's force with the lines re-solved at the point moved: the
   !> derivative that makes the network's Newton iteration quadratic.
   subroutine test_point_stiffness(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod3d_run), allocatable :: lines(:)
      type(network_run) :: net, moved
      real(dp) :: k(3, 3), fd(3, 3), h, worst, f(3, 2)
      integer :: a, sgn
      call two_lines([25.0_dp, 5.0_dp, -40.0_dp], lines, error)
      if (allocated(error)) return
      call net%init(lines, [network_joint(1, 2, 1), network_joint(2, 1, 1)], 1, error)
      if (allocated(error)) return
      call net%statics(0.0_dp, error)
      if (allocated(error)) return
      k = net%point_stiffness()
      h = 1.0e-4_dp
      do a = 1, 3
         do sgn = 1, 2
            moved = net
            moved%xp(a, 1) = moved%xp(a, 1) + merge(h, -h, sgn == 1)
            call lines_in_balance(moved, error)
            if (allocated(error)) return
            f(:, sgn) = moved%imbalance(:, 1)
         end do
         ! The sum of the kept rows is minus the lines' force on the point.
         fd(:, a) = (f(:, 1) - f(:, 2))/(2*h)
      end do
      worst = maxval(abs(fd - k))/maxval(abs(k))
      write (output_unit, '(4x,a,es9.2,a)') 'point stiffness: ', worst, ' off differences of re-solved lines'
      ! Measured 7.1e-10 (differences of 1e-4 m).
      call check(error, worst < 5.0e-9_dp, 'the points'' stiffness is off by '//str(worst))
   end subroutine test_point_stiffness

   !> Solve the lines of a network with its points held where they are (each line alone).
   subroutine lines_in_balance(net, error)
      type(network_run), intent(inout) :: net
      type(error_type), allocatable, intent(out) :: error
      call net%hold_statics(0.0_dp, error)
   end subroutine lines_in_balance

   !> Three lines of 75 m from anchors at 120 degrees, 60 m from the axis, meet at a buoy: the
   !> current along x, line 1's anchor on the x axis, the others mirror images across it. From a
   !> guess 2 m off the plane of symmetry, the statics finds the buoy on it; the ledger of 2 s of
   !> heave of line 1's anchor closes.
   subroutine test_spread(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sims(3)
      type(rod3d_run), allocatable :: lines(:)
      type(network_run) :: net
      real(dp) :: guess(3), a(3), off, led0(4), led(4), drift, dt, buoy0(3)
      integer :: l, i
      character(len=*), parameter :: line = "&cable length = 75.0, diameter = 0.05, density = 1500.0, "// &
                                            "bending_stiffness = 1.0 /"//nl//numerics//", nodes = 61 /"//nl
      guess = [3.0_dp, 2.0_dp, -25.0_dp]
      allocate (lines(3))
      do l = 1, 3
         a(3) = -60
         a(1:2) = 60*[cos(2*acos(-1.0_dp)/3*(l - 1)), sin(2*acos(-1.0_dp)/3*(l - 1))]
         if (l == 1) then
            call prepared_with_body(line//xyz("&end_a kind = 'fixed'", guess)//" /"//nl// &
                                    xyz("&end_b "//heave, a)//" /", buoy(0), sims(l), error)
            ! (the buoy on line 1's end a: joint 0)
         else
            call prepared(line//xyz("&end_a kind = 'fixed'", guess)//" /"//nl// &
                          xyz("&end_b kind = 'fixed'", a)//" /", sims(l), error)
         end if
         if (allocated(error)) return
         lines(l) = sims(l)%rod3%pieces(1)%run
      end do
      call net%init(lines, [network_joint(1, 1, 1), network_joint(2, 1, 1), network_joint(3, 1, 1)], 1, error)
      if (allocated(error)) return
      call net%statics(0.0_dp, error)
      if (allocated(error)) return
      off = abs(net%xp(2, 1))
      write (output_unit, '(4x,a,3f10.4,a,es9.2,a,i0,a)') 'spread: the buoy at', net%xp(:, 1), ', ', off, &
         ' m off the plane of symmetry (', net%last_iterations, ' iterations)'
      ! Measured 4.0e-15 m.
      call check(error, off < 2.0e-14_dp, 'the spread''s buoy is '//str(off)//' m off the plane of symmetry')
      if (allocated(error)) return
      dt = 0.05_dp
      buoy0 = net%xp(:, 1)
      led0 = net%ledger()
      do i = 1, 40
         call net%attempt(dt, 0.5_dp, error)
         if (allocated(error)) return
         call net%accept(dt, 0.5_dp)
      end do
      led = net%ledger()
      drift = abs((led(1) - led0(1)) - (led(2) + led(3) - led(4)))/max(abs(led(1)), abs(led(2)), 1.0_dp)
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a)') 'spread heave: ledger ', drift, ' (end work ', &
         led(2), ' J; the points'' work on the lines ', net%joint_work, ' J; the buoy moved ', &
         norm2(net%xp(:, 1) - buoy0), ' m)'
      ! Measured 9.0e-16; with the kept rows of one line 0.1 % off, 2.9e-7.
      call check(error, drift < 5.0e-15_dp, 'the spread''s ledger does not close: '//str(drift))
   end subroutine test_spread
   !> Through the input and the driver (&line_k, &point_k kind, driver/network_drive.f90): the
   !> two lines at a free point with the buoy against the one line with the buoy at its joint, both
   !> run for 1 s at dt = 0.025 s: the history of the anchor's and the fairlead's tension and the
   !> ledger.
   subroutine test_input_equal_one_line(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: one, net
      character(:), allocatable :: run
      real(dp) :: worst, drift, top, wet
      integer :: i
      run = ", dt = 0.025, t_end = 1.0 /"//nl//"&output energy = .true. /"
      call ran(common//one_line(run)// &
                      "&point_1 joint = 1, mass = 50.0, volume = 0.3, ca = 0.5, cd = 0.8, area = 0.5 /"//nl, one, error)
      if (allocated(error)) return
      call ran(common//numerics//run//nl//two_lines_text(plain_segments()), net, error)
      if (allocated(error)) return
      associate (h1 => one%rod%history, h2 => net%rod%history)
         call check(error, h1%n == h2%n .and. h2%n == 40, 'the runs took '//str(h1%n)//' and '//str(h2%n)//' steps')
         if (allocated(error)) return
         call check(error, size(h2%end_labels) == 4, 'the network''s history has '//str(size(h2%end_labels))//' ends')
         if (allocated(error)) return
         call check(error, h2%end_labels(4) == 'line_2_b', 'the network''s last end is '//h2%end_labels(4))
         if (allocated(error)) return
         top = maxval(abs(h1%ends(5, 2, 0:h1%n)))
         worst = 0
         do i = 0, h1%n
            worst = max(worst, abs(h1%ends(5, 1, i) - h2%ends(5, 1, i)), abs(h1%ends(5, 2, i) - h2%ends(5, 4, i)))
         end do
         worst = worst/top
         drift = maxval(abs(h2%energy(7, 0:h2%n) - h2%energy(7, 0)))/maxval(abs(h2%energy(1:4, 0:h2%n)))
         ! The wetted length (the fluid's measure) of the two lines is that of the one line.
         call check(error, allocated(h2%measures), 'the network''s history has no load measures')
         if (allocated(error)) return
         wet = maxval(abs(h1%measures(1, 0:h1%n) - h2%measures(1, 0:h2%n)))
         call check(error, wet < 1.0e-9_dp .and. minval(h2%measures(1, 0:h2%n)) > 89, 'the network''s wetted '// &
                    'length is off the one line''s by '//str(wet)//' m')
         if (allocated(error)) return
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2)') 'through the input: the ends'' tensions ', worst, &
         ' of the largest off the one line''s; the network''s ledger ', drift
      ! Measured 2.1e-12 and 2.7e-15.
      call check(error, worst < 1.0e-11_dp, 'through the input, the network''s end tensions are '//str(worst)// &
                 ' off the one line''s')
      if (allocated(error)) return
      call check(error, drift < 1.0e-13_dp, 'the network''s ledger drifts by '//str(drift))
   end subroutine test_input_equal_one_line
   !> A break by time in the second line of the network of test_input_equal_one_line, 30 m
   !> from the buoy, against the one line's break at the same place (70 m from the anchor).
   subroutine test_break_time(error)
      type(error_type), allocatable, intent(out) :: error
      call break_equal_one_line("&rupture time = 0.5, s_break = 70.0, t_break = 0.05 /", &
                                "&rupture line = 2, time = 0.5, s_break = 30.0, t_break = 0.05 /", &
                                70.0_dp, 1.0e-13_dp, 5.0e-11_dp, 3.0e-11_dp, error)
      ! Measured: the ends 4.0e-14 of L, their tensions 1.7e-11 of the largest, the output's
      ! positions at the end 9.3e-12 of L (the slack line's round-off).
   end subroutine test_break_time

   !> A break by time in the first line, 20 m from the anchor: the piece on the buoy's side
   !> becomes a new line of the network, which takes over the joint at the buoy (and the buoy).
   subroutine test_break_time_below(error)
      type(error_type), allocatable, intent(out) :: error
      call break_equal_one_line("&rupture time = 0.5, s_break = 20.0, t_break = 0.05 /", &
                                "&rupture line = 1, time = 0.5, s_break = 20.0, t_break = 0.05 /", &
                                20.0_dp, 3.0e-13_dp, 5.0e-11_dp, 7.0e-11_dp, error)
      ! Measured: the ends 1.1e-13 of L, their tensions 1.2e-11 of the largest, the output 2.3e-11.
   end subroutine test_break_time_below

   !> A break by tension (mbl 33 kN), found by each code's first pass near the fairlead (a node
   !> inside the line), against the one line's.
   subroutine test_break_tension_inside(error)
      type(error_type), allocatable, intent(out) :: error
      call break_equal_one_line("&rupture criterion = 'tension', mbl = 33000.0, t_break = 0.05 /", &
                                "&rupture criterion = 'tension', mbl = 33000.0, t_break = 0.05 /", &
                                87.0_dp, 1.0e-11_dp, 2.0e-10_dp, 2.0e-10_dp, error)
      ! Measured: the two first passes' breaks 1.9e-13 s apart (their searches' round-off); the
      ! ends then 2.6e-12 of L, their tensions 6.5e-11 of the largest, the output 6.0e-11 of L.
   end subroutine test_break_tension_inside

   !> A break by tension (mbl 31 kN) at the fairlead, a held end that lets go, against the one line's.
   subroutine test_break_tension_end(error)
      type(error_type), allocatable, intent(out) :: error
      call break_equal_one_line("&rupture criterion = 'tension', mbl = 31000.0, t_break = 0.05 /", &
                                "&rupture criterion = 'tension', mbl = 31000.0, t_break = 0.05 /", &
                                90.0_dp, 3.0e-12_dp, 1.0e-8_dp, 1.5e-10_dp, error)
      ! Measured: the breaks 1.1e-14 s apart; the ends 6.3e-13 of L; the tensions 3.1e-9 of the
      ! largest, at 0.95 s where the anchor's slack end pulls taut again (a tension of EA times a
      ! strain from positions 5e-11 m apart); the output 4.8e-11 of L.
   end subroutine test_break_tension_end

   !> A break by tension that does not happen, with an MBL per segment (10 MN for the heavy rope,
   !> 60 kN for the other): the network's summary names the cell that came closest to its MBL,
   !> with its own tension and its segment's MBL, as the one line's does.
   subroutine test_break_not_reached(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: one, net
      character(:), allocatable :: run, segments
      run = ", dt = 0.025, t_end = 1.0 /"//nl//"&rupture criterion = 'tension', t_break = 0.05 /"
      segments = "&segment_1 length = 40.0, nodes = 41, density = 3000.0, mbl = 1.0e7 /"//nl// &
                 "&segment_2 length = 50.0, nodes = 51, mbl = 6.0e4 /"//nl
      call ran(common//numerics//run//nl//segments// &
                      "&cable length = 90.0, diameter = 0.05, density = 1500.0, bending_stiffness = 1e-6 /"//nl// &
                      xyz("&end_a kind = 'fixed'", anchor)//" /"//nl//xyz("&end_b "//heave, fairlead)//" /"//nl// &
                      "&point_1 joint = 1, mass = 50.0, volume = 0.3, ca = 0.5, cd = 0.8, area = 0.5 /"//nl, one, error)
      if (allocated(error)) return
      call ran(common//numerics//run//nl//two_lines_text(segments), net, error)
      if (allocated(error)) return
      associate (s1 => one%rod%summary, s2 => net%rod%summary)
         write (output_unit, '(4x,a,2f10.2,a,2f8.3,a,2f9.1,a)') 'no break: largest tensions', s1%largest_tension, &
            s2%largest_tension, ' N at s =', s1%largest_tension_s, s2%largest_tension_s, ' m, MBLs', s1%mbl, s2%mbl, ' N'
         call check(error, .not. (s1%broke .or. s2%broke) .and. s2%mbl == 6.0e4_dp .and. s1%mbl == s2%mbl .and. &
                    abs(s1%largest_tension - s2%largest_tension) < 1.0e-9_dp*s1%mbl .and. &
                    abs(s1%largest_tension_s - s2%largest_tension_s) < 1.0e-9_dp .and. &
                    s2%largest_tension > 2.8e4_dp .and. s2%largest_tension < s2%mbl .and. s2%largest_tension_s > 40, &
                    'the summaries of the break that did not happen: the one line''s largest tension '// &
                    str(s1%largest_tension)//' N at s = '//str(s1%largest_tension_s)//' m (MBL '//str(s1%mbl)// &
                    ' N), the network''s '//str(s2%largest_tension)//' N at s = '//str(s2%largest_tension_s)// &
                    ' m (MBL '//str(s2%mbl)//' N)')
      end associate
   end subroutine test_break_not_reached

   !> An MBL at or below a static tension of the network (29 kN, where line 1 carries 29.02 kN next
   !> to the buoy) is refused after the statics (stat_input), naming the group, the line and where.
   subroutine test_mbl_below_static(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: net
      type(error_type), allocatable :: refused
      call prepared(numerics//", dt = 0.025, t_end = 1.0 /"//nl// &
                    "&rupture criterion = 'tension', mbl = 29000.0 /"//nl//two_lines_text(plain_segments()), net, refused)
      call check(error, allocated(refused), 'an mbl below the static tension was not refused')
      if (allocated(error)) return
      write (output_unit, '(4x,a)') refused%message
      call check(error, refused%stat == stat_input .and. index(refused%message, '&rupture: mbl = 29000') > 0 .and. &
                 index(refused%message, '&line_1') > 0 .and. index(refused%message, 'would part in statics') > 0, &
                 'the refusal says: '//refused%message)
   end subroutine test_mbl_below_static

   !> The network of test_input_equal_one_line (two lines at a free point with the buoy) with a
   !> break, against the one line with the buoy at its joint and the same break, both run for 1 s
   !> at dt = 0.025 s (later, the slack and buckled line makes round-off grow: by 2 s to 3e-6 of
   !> the largest tension): the break's time and place (s_expected on the results' arc length, the
   !> same for both), every end's position and tension in the history (the network's line_1_a,
   !> line_2_b, break_a, break_b against the one line's end_a, end_b, break_a, break_b) to tol of
   !> the largest, and the network's ledger across the break.
   subroutine break_equal_one_line(rupture_one, rupture_net, s_expected, tol_x, tol, tol_out, error)
      character(*), intent(in) :: rupture_one, rupture_net
      !> The tolerances: the ends' positions (of L), their tensions (of the largest) and the output's
      !> positions at the end (of L).
      real(dp), intent(in) :: s_expected, tol_x, tol, tol_out
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: one, net
      character(:), allocatable :: run
      real(dp) :: worst, worst_x, drift, top, span
      real(dp), allocatable :: f1(:, :), e1(:, :), f2(:, :), e2(:, :), so1(:), so2(:)
      integer, allocatable :: starts1(:), starts2(:)
      integer :: i, j, n_slots, slots(4), junction, m, k
      logical :: same_s
      run = ", dt = 0.025, t_end = 1.0 /"//nl//"&output energy = .true. /"
      call ran(common//one_line(run)//rupture_one//nl// &
                      "&point_1 joint = 1, mass = 50.0, volume = 0.3, ca = 0.5, cd = 0.8, area = 0.5 /"//nl, one, error)
      if (allocated(error)) return
      call ran(common//numerics//run//nl//rupture_net//nl//two_lines_text(plain_segments()), net, error)
      if (allocated(error)) return
      associate (h1 => one%rod%history, h2 => net%rod%history, s1 => one%rod%summary, s2 => net%rod%summary)
         call check(error, s1%broke .and. s2%broke, 'a run did not break (the one line: '// &
                    merge('broke   ', 'no break', s1%broke)//', the network: '//merge('broke   ', 'no break', s2%broke)//')')
         if (allocated(error)) return
         call check(error, abs(s1%break_time - s2%break_time) <= 1.0e-12_dp .and. &
                    s2%break_line == merge(1, 2, s_expected < 40) .and. &
                    abs(s2%break_s - s_expected) < 1.0e-9_dp .and. abs(s1%break_s - s_expected) < 1.0e-9_dp, &
                    'the breaks: the one line''s at t = '//str(s1%break_time)//' s, s = '//str(s1%break_s)// &
                    ' m, the network''s at t = '//str(s2%break_time)//' s, s = '//str(s2%break_s)//' m of line '// &
                    str(s2%break_line)//' (s = '//str(s_expected)//' m expected)')
         if (allocated(error)) return
         n_slots = size(h1%end_labels)
         call check(error, h1%n == h2%n .and. size(h2%end_labels) == n_slots + 2, 'the runs took '//str(h1%n)//' and '// &
                    str(h2%n)//' steps, with '//str(n_slots)//' and '//str(size(h2%end_labels))//' ends')
         if (allocated(error)) return
         ! The one line's ends (end_a, end_b and, of a break inside, break_a, break_b) in the network.
         slots = [1, 4, 5, 6]
         top = maxval(abs(h1%ends(5, 1:n_slots, 0:h1%n)))
         span = 90
         worst = 0
         worst_x = 0
         do i = 0, h1%n
            do j = 1, n_slots
               worst = max(worst, abs(h1%ends(5, j, i) - h2%ends(5, slots(j), i))/top)
               worst_x = max(worst_x, maxval(abs(h1%ends(1:2, j, i) - h2%ends(1:2, slots(j), i)))/span, &
                             abs(h1%ends_y(1, j, i) - h2%ends_y(1, slots(j), i))/span)
            end do
         end do
         drift = maxval(abs(h2%energy(7, 0:h2%n) - h2%energy(7, 0)))/maxval(abs(h2%energy(1:4, 0:h2%n)))
         write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2,a,f8.5,a,es9.2,a)') 'the network''s break: its ends ', &
            worst_x, ' of L and ', worst, ' of the largest tension off the one line''s; the ledger ', drift, &
            '; at t = ', s2%break_time, ' s (', s2%break_time - s1%break_time, ' s after the one line''s)'
         call check(error, worst_x < tol_x, 'the network''s ends are '//str(worst_x)//' of L off the one line''s')
         if (allocated(error)) return
         call check(error, worst < tol, 'the network''s end tensions are '//str(worst)//' off the one line''s')
         if (allocated(error)) return
         call check(error, drift < 1.0e-13_dp, 'the broken network''s ledger drifts by '//str(drift))
         if (allocated(error)) return
      end associate
      ! The output at the end: the network's columns are the one line's with the joint's node twice
      ! (line 1's last, line 2's first, from column junction on); the break node is twice in both.
      allocate (f1(one%output_nodes(), n_fields), e1(one%output_nodes(), n_fields3))
      call state_fields(one%rod3, one%rod, f1, e1)
      allocate (f2(net%output_nodes(), n_fields), e2(net%output_nodes(), n_fields3))
      call net%network%state_fields(f2, e2)
      junction = net%network%lines(2)%column(1)
      so1 = one%output_s()
      so2 = net%output_s()
      worst_x = 0
      same_s = size(so2) == size(so1) + 1
      do m = 1, size(so2)
         if (.not. same_s) exit
         k = merge(m, m - 1, m < junction)
         same_s = same_s .and. abs(so1(k) - so2(m)) < 1.0e-12_dp
         worst_x = max(worst_x, abs(f1(k, 6) - f2(m, 6))/span, abs(f1(k, 7) - f2(m, 7))/span, abs(e1(k, 1) - e2(m, 1))/span)
      end do
      call check(error, same_s, 'the network''s output s is not the one line''s with the joint''s node twice')
      if (allocated(error)) return
      starts1 = one%piece_starts()
      starts2 = net%piece_starts()
      call check(error, size(starts2) == size(starts1) + 1 .and. size(starts1) <= 1, 'the outputs'' pieces start '// &
                 'at '//str(size(starts1))//' and '//str(size(starts2))//' columns (0 and 1, or 1 and 2 expected)')
      if (allocated(error)) return
      if (size(starts1) == 1) then
         call check(error, starts2(merge(2, 1, starts1(1) > junction)) == merge(starts1(1) + 1, starts1(1), &
                    starts1(1) > junction), 'the network''s break starts a piece at column '//str(starts2(1))//', '// &
                    str(starts2(2))//', the one line''s at '//str(starts1(1)))
         if (allocated(error)) return
      end if
      write (output_unit, '(4x,a,es9.2,a)') 'the output''s positions at the end: ', worst_x, ' of L off the one line''s'
      call check(error, worst_x < tol_out, 'the network''s output positions are '//str(worst_x)//' of L off the one line''s')
   end subroutine break_equal_one_line

   !> The buoy of input/buoy_spread.nml on two legs of 80 m of chain and 120 m of polyester whose
   !> chains lie on a seabed 100 m deep with Coulomb friction, the hawser to the surging vessel:
   !> 2 s through the input and the driver. The ledger of the network closes with the contact and
   !> the friction (the loads' work), and the chains lie on the bottom (the grounded length).
   subroutine test_seabed_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: drift, grounded, loads
      call write_text(path, &
                      "&cable diameter = 0.1376, density = 1115.0 /"//nl// &
                      "&material law = 'linear', ea = 1.0e8 /"//nl// &
                      "&seabed depth = 100.0, mu_axial = 0.5, mu_lateral = 0.8 /"//nl// &
                      "&fluid density = 1025.0, cd_normal = 1.2, cd_tangential = 0.1, ca_normal = 1.0, surface_z = 0.0 /"// &
                      nl//"&segment_1 length = 80.0, diameter = 0.1368, density = 7860.0, ea = 4.945e8, cd_normal = 2.4, "// &
                      "nodes = 17 /"//nl// &
                      "&segment_2 length = 120.0, nodes = 25 /"//nl// &
                      "&segment_3 length = 110.0, nodes = 23 /"//nl// &
                      "&point_1 kind = 'free', z = -30.0, mass = 2000.0, volume = 20.0, ca = 0.5, cd = 0.6, area = 8.0 /"//nl// &
                      "&point_2 kind = 'fixed', x = 160.0, y = 30.0, z = -100.0 /"//nl// &
                      "&point_3 kind = 'fixed', x = 160.0, y = -30.0, z = -100.0 /"//nl// &
                      "&point_4 kind = 'motion', x = -100.0, z = -5.0, amplitude = 2.0, period = 10.0, direction_x = 1.0, "// &
                      "direction_z = 0.0, ramp_time = 10.0 /"//nl// &
                      "&line_1 end_a = 'point_2', end_b = 'point_1', segments = 1, 2 /"//nl// &
                      "&line_2 end_a = 'point_3', end_b = 'point_1', segments = 1, 2 /"//nl// &
                      "&line_3 end_a = 'point_1', end_b = 'point_4', segments = 3 /"//nl// &
                      "&numerics t_end = 2.0, courant = 2.0, newton_tol = 1e-10 /"//nl// &
                      "&output energy = .true. /"//nl)
      call read_config(path, c, error)
      if (allocated(error)) return
      c%quiet = .true.
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(error=error)
      if (allocated(error)) return
      associate (h => sim%rod%history)
         drift = maxval(abs(h%energy(7, 0:h%n) - h%energy(7, 0)))/maxval(abs(h%energy(1:4, 0:h%n)))
         grounded = h%measures(2, h%n)
         loads = maxval(abs(h%energy(8, 0:h%n)))
      end associate
      write (output_unit, '(4x,a,es9.2,a,f8.3,a,es9.2,a)') 'legs on the seabed: ledger ', drift, ', grounded ', &
         grounded, ' m, loads'' work up to ', loads, ' J'
      call check(error, grounded > 100 .and. loads > 0, 'the chains do not lie on the bottom (grounded '// &
                 str(grounded)//' m) or nothing works on them')
      if (allocated(error)) return
      ! Measured 7.1e-16.
      call check(error, drift < 5.0e-15_dp, 'the network''s ledger on the seabed drifts by '//str(drift))
   end subroutine test_seabed_ledger
end module suite_network
