!> A three-line spread meeting at a subsurface buoy (driver/network.f90, issue 31 "Moorings"):
!> the statics and a horizontal heave of one anchor, printed as plain columns for
!> bench/peer/network.py (MoorDyn's same scene) and for convergence studies.
!>
!>   fpm run --example network_spread --profile release -- [nodes=41] [dt=0.01] [t_end=60]
!>       [sample=0.1] [mass=lumped|averaged] [tol=1e-10] [nodes_file=PATH]
!>       [buoy_line=1] [fairlead=0] [fairlead_length=25.2]
!>
!> The scene. Sea water (1025 kg/m^3, g = 9.81 m/s^2, surface z = 0), a flat bottom at
!> z = -100 m which no line reaches (there is no seabed in xcable's scene: the buoy holds the
!> lines up, and each rises from its anchor). Three lines of 160 mm polyester (16.6 kg/m,
!> EA 2.79e7 N, volume-equivalent diameter 0.1376 m, linear and unable to push, EI 1e-3 N m^2),
!> each 106 m long, from anchors at radius 80 m on the bottom at azimuths 0, 120 and 240
!> degrees (end a) to a buoy (end b) of 2000 kg displacing 8 m^3, Ca 0.5, Cd 0.6 on 4 m^2, on
!> line 1's end node (with buoy_line = k on line k's). Line drag and added mass: Cd 1.2
!> normal, 0.008 tangential (on pi d, as MoorDyn's CdAx), Ca 1 normal. Still water.
!>
!> The motion: line 1's anchor moves along its line (x), X(t) = X0 + A w(t) sin(2 pi t / T),
!> A = 2 m, T = 10 s, w = sin^2(pi t / (2 T)) for t < T, then 1 (a start from rest).
!>
!> With fairlead=1 the anchors stay fixed and a fourth line of the same rope, fairlead_length
!> long, runs from the buoy (its end a) up to a fairlead at (0.5, 0, -5) m (end b), which surges
!> along x by the same motion: a taut, nearly vertical line tilting either way, its tension rising
!> at both ends of the stroke.
!>
!> How the network is built (there is no namelist input for networks yet): each line is a
!> one-line case read from namelist text with its buoy end 'fixed' at the guess (0, 0, -30) m,
!> prepared (its own statics), its 3-D run taken; network_run%init joins the three end b's at
!> one free point; network_run%statics, then fixed steps of dt (implicit midpoint, theta 1/2).
!>
!> Output (stdout): comment lines start with '#'. The first other line is the static state:
!>   buoy x y z, then the tension at the buoy of lines 1 2 3 (4), then at their other ends;
!> every other line is a sample (every `sample` s, from t = 0):
!>   t, buoy x y z, then per line its tension at the buoy ('top') and at its other end ('bottom':
!>   the anchor, line 4's fairlead).
!> End tensions: the tension vectors T_c e_c / |e_c| of the two end cells carried linearly to the
!> end node, |1.5 T_1 - 0.5 T_2| (the same estimate bench/peer/network.py takes of MoorDyn's
!> nodes). The last comment lines give the CPU and wall time of the statics and of the steps,
!> and Newton's iterations. With nodes_file, the static nodes of lines 1, 2, 3 (4) (x y z, from end
!> a to end b, one node a line) are written to that file.
program network_spread
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type
   use xcable_io_config, only: case_config, point_config
   use xcable_io_input, only: read_config
   use xcable_driver_simulation, only: simulation
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_driver_network, only: network_run, network_joint
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   implicit none
   character(len=*), parameter :: nl = new_line('a')
   real(dp), parameter :: pi = acos(-1.0_dp)
   real(dp), parameter :: length = 106, radius = 80, depth = 100, guess(3) = [0.0_dp, 0.0_dp, -30.0_dp]
   real(dp), parameter :: mass = 16.6_dp, ea = 2.79e7_dp, diameter = 0.1376_dp
   type(simulation) :: sims(4)
   type(rod3d_run), allocatable :: lines(:)
   type(network_run) :: net
   type(error_type), allocatable :: error
   type(point_config) :: buoy
   character(len=64) :: arg
   character(len=16) :: mass_matrix
   character(len=512) :: nodes_file
   integer :: unit, k, buoy_line, fairlead, nl4
   real(dp) :: fairlead_length
   real(dp) :: dt, t_end, sample, tol, anchor(3), top(4), bottom(4), c0, c1, c2
   integer :: nodes, i, l, steps, every, iterations
   integer(int64) :: w0, w1, w2, rate

   nodes = 41
   dt = 0.01_dp
   t_end = 60
   sample = 0.1_dp
   tol = 1.0e-10_dp
   mass_matrix = 'lumped'
   nodes_file = ''
   buoy_line = 1
   fairlead = 0
   fairlead_length = 25.2_dp
   do i = 1, command_argument_count()
      call get_command_argument(i, arg)
      if (index(arg, 'nodes=') == 1) read (arg(7:), *) nodes
      if (index(arg, 'dt=') == 1) read (arg(4:), *) dt
      if (index(arg, 't_end=') == 1) read (arg(7:), *) t_end
      if (index(arg, 'sample=') == 1) read (arg(8:), *) sample
      if (index(arg, 'mass=') == 1) mass_matrix = arg(6:)
      if (index(arg, 'tol=') == 1) read (arg(5:), *) tol
      if (index(arg, 'buoy_line=') == 1) read (arg(11:), *) buoy_line
      if (index(arg, 'fairlead=') == 1) read (arg(10:), *) fairlead
      if (index(arg, 'fairlead_length=') == 1) read (arg(17:), *) fairlead_length
      if (index(arg, 'nodes_file=') == 1) call get_command_argument(i, nodes_file)
   end do
   every = nint(sample/dt)
   if (every < 1 .or. abs(every*dt - sample) > 1.0e-9_dp*sample) then
      write (error_unit, '(a)') 'network_spread: sample must be a multiple of dt'
      stop 1
   end if
   steps = nint(t_end/dt)

   buoy%joint = 1
   buoy%mass = 2000
   buoy%volume = 8
   buoy%ca = 0.5_dp
   buoy%cd = 0.6_dp
   buoy%area = 4

   call cpu_time(c0)
   call system_clock(w0, rate)
   nl4 = merge(4, 3, fairlead == 1)
   allocate (lines(nl4))
   do l = 1, nl4
      anchor = [radius*cos(2*pi/3*(l - 1)), radius*sin(2*pi/3*(l - 1)), -depth]
      if (l == 4) anchor = [0.5_dp, 0.0_dp, -5.0_dp]
      call prepare_line(l, anchor, sims(l), error)
      call stop_on(error)
      lines(l) = sims(l)%rod3%pieces(1)%run
   end do
   if (nl4 == 4) then
      call net%init(lines, [network_joint(1, 2, 1), network_joint(2, 2, 1), network_joint(3, 2, 1), &
                            network_joint(4, 1, 1)], 1, error)
   else
      call net%init(lines, [network_joint(1, 2, 1), network_joint(2, 2, 1), network_joint(3, 2, 1)], 1, error)
   end if
   call stop_on(error)
   call net%statics(0.0_dp, error)
   call stop_on(error)
   call cpu_time(c1)
   call system_clock(w1)
   if (len_trim(nodes_file) > 0) then
      open (newunit=unit, file=trim(nodes_file(12:)), status='replace', action='write')
      do l = 1, nl4
         do k = 1, net%lines(l)%problem%piece%n
            write (unit, '(3es25.16e3)') net%lines(l)%x(3*k - 2:3*k)
         end do
      end do
      close (unit)
   end if

   write (output_unit, '(a,i0,a,i0,a,es10.3,a,a,a,es8.1,a,i0,a)') '# network_spread: ', nl4, ' lines, nodes ', &
      nodes, ', dt ', dt, ' s, mass matrix ', trim(mass_matrix), ', newton_tol ', tol, '; statics in ', &
      net%last_iterations, ' iterations'
   write (output_unit, '(a)') '# static: buoy_x buoy_y buoy_z, T_top of each line, T_bottom of each line'
   do l = 1, nl4
      call end_tensions(l, net%lines(l), top(l), bottom(l))
   end do
   write (output_unit, '(3f16.9,8f16.6)') net%xp(:, 1), top(1:nl4), bottom(1:nl4)
   write (output_unit, '(a)') '# t buoy_x buoy_y buoy_z, then T_top T_bottom of each line'
   call sample_row()
   iterations = net%iterations
   do i = 1, steps
      call net%attempt(dt, 0.5_dp, error)
      call stop_on(error)
      call net%accept(dt, 0.5_dp)
      if (mod(i, every) == 0) call sample_row()
   end do
   call cpu_time(c2)
   call system_clock(w2)
   write (output_unit, '(a,2f10.4,a,2f10.4,a,i0,a,f6.3,a)') '# time s (cpu, wall): statics ', c1 - c0, &
      real(w1 - w0, dp)/rate, '; steps ', c2 - c1, real(w2 - w1, dp)/rate, '; ', steps, ' steps, ', &
      real(net%iterations - iterations, dp)/max(steps, 1), ' Newton iterations per step'

contains

   !> One line as a one-line case: end a the anchor (line 1's moves), end b 'fixed' at the guess
   !> (the buoy on line buoy_line's end b).
   subroutine prepare_line(l, anchor, sim, error)
      integer, intent(in) :: l
      real(dp), intent(in) :: anchor(3)
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      character(len=512) :: path
      character(len=:), allocatable :: text
      integer :: unit
      text = "&cable length = "//r(length)//", diameter = "//r(diameter)//", density = "// &
             r(mass/(pi*diameter**2/4))//", bending_stiffness = 1e-3 /"//nl// &
             "&material law = 'linear', ea = "//r(ea)//", compression = 'none' /"//nl// &
             "&fluid density = 1025.0, surface_z = 0.0, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1.0 /"//nl// &
             "&numerics model = '3d', mass_matrix = '"//trim(mass_matrix)//"', newton_tol = "//r(tol)// &
             ", nodes = "//i2s(nodes)//" /"//nl
      if (l == 4) then
         ! The fairlead line: end a at the buoy, end b the surging fairlead.
         text = replace_length(text, fairlead_length)
         text = text//"&end_a kind = 'fixed', "//xyz(guess)//" /"//nl// &
                "&end_b kind = 'motion', motion = 'harmonic', amplitude = 2.0, period = 10.0, "// &
                "ramp_time = 10.0, direction_x = 1.0, direction_y = 0.0, direction_z = 0.0, "//xyz(anchor)//" /"//nl
      else
         if (l == 1 .and. fairlead /= 1) then
            text = text//"&end_a kind = 'motion', motion = 'harmonic', amplitude = 2.0, period = 10.0, "// &
                   "ramp_time = 10.0, direction_x = 1.0, direction_y = 0.0, direction_z = 0.0, "//xyz(anchor)//" /"//nl
         else
            text = text//"&end_a kind = 'fixed', "//xyz(anchor)//" /"//nl
         end if
         text = text//"&end_b kind = 'fixed', "//xyz(guess)//" /"//nl
      end if
      call get_environment_variable('TMPDIR', path)
      if (len_trim(path) == 0) path = '/tmp'
      path = trim(path)//'/network_spread_'//i2s(getpid_safe())//'_'//i2s(l)//'.nml'
      open (newunit=unit, file=trim(path), status='replace', action='write', access='stream', form='unformatted')
      write (unit) text
      close (unit)
      call read_config(trim(path), c, error)
      open (newunit=unit, file=trim(path), status='old')
      close (unit, status='delete')
      if (allocated(error)) return
      c%quiet = .true.
      if (l == buoy_line) then
         ! The buoy on the joint end (the input would refuse a body on a held end).
         c%point_count = 1
         c%points(1) = buoy
      end if
      call sim%prepare(c, error)
   end subroutine prepare_line

   !> A number for the process's files (the clock: two runs at once get different names).
   integer function getpid_safe()
      integer(int64) :: count
      call system_clock(count)
      getpid_safe = int(mod(count, 100000000_int64))
   end function getpid_safe

   !> The tensions of line l at the buoy (end b of lines 1 to 3, end a of line 4) and at its other end.
   subroutine end_tensions(l, run, t_top, t_bottom)
      integer, intent(in) :: l
      type(rod3d_run), intent(in) :: run
      real(dp), intent(out) :: t_top, t_bottom
      t_bottom = end_tension(run, merge(2, 1, l == 4))
      t_top = end_tension(run, merge(1, 2, l == 4))
   end subroutine end_tensions

   !> The case text with the cable's length replaced (the first 'length = ' of &cable).
   function replace_length(text, value) result(out)
      character(*), intent(in) :: text
      real(dp), intent(in) :: value
      character(len=:), allocatable :: out
      integer :: i, j
      i = index(text, 'length = ') + len('length = ')
      j = i + index(text(i:), ',') - 1
      out = text(:i - 1)//r(value)//text(j:)
   end function replace_length

   !> |1.5 T_1 - 0.5 T_2| of the two end cells' tension vectors at side 1 (node 1) or 2 (node n), N.
   real(dp) function end_tension(run, side) result(t)
      type(rod3d_run), intent(in) :: run
      integer, intent(in) :: side
      real(dp) :: tv(3, 2), e(3)
      integer :: n, j, c
      n = run%problem%piece%n
      do j = 1, 2
         c = merge(j, n - j, side == 1)
         e = run%x(3*c + 1:3*c + 3) - run%x(3*c - 2:3*c)
         tv(:, j) = run%problem%piece%cell_tension(c, norm2(e)/run%problem%piece%ds(c) - 1)*e/norm2(e)
      end do
      t = norm2(1.5_dp*tv(:, 1) - 0.5_dp*tv(:, 2))
   end function end_tension

   subroutine sample_row()
      real(dp) :: tt(2, 4)
      integer :: k
      do k = 1, nl4
         call end_tensions(k, net%lines(k), tt(1, k), tt(2, k))
      end do
      write (output_unit, '(f10.4,3f16.9,8f16.6)') net%t, net%xp(:, 1), tt(:, 1:nl4)
   end subroutine sample_row

   subroutine stop_on(error)
      type(error_type), allocatable, intent(in) :: error
      if (allocated(error)) then
         write (error_unit, '(a)') 'network_spread: '//error%message
         stop 1
      end if
   end subroutine stop_on

   function r(x) result(text)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buffer
      write (buffer, '(es24.16e3)') x
      text = trim(adjustl(buffer))
   end function r

   function i2s(k) result(text)
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      character(len=16) :: buffer
      write (buffer, '(i0)') k
      text = trim(buffer)
   end function i2s

   function xyz(p) result(text)
      real(dp), intent(in) :: p(3)
      character(len=:), allocatable :: text
      text = "x = "//r(p(1))//", y = "//r(p(2))//", z = "//r(p(3))
   end function xyz
end program network_spread
