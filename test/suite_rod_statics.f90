!> Statics of the rod discretisation against the exact extensible catenary
!> (quadrature, any law; bending is absent from it and leaves a small floor):
!> the paper's symmetric case from the end tension, and lines held between
!> two points at different heights, taut and slack, with the observed order
!> of convergence; Newton's quadratic convergence; a line hanging from one
!> end; and the inconsistent scenes that must be refused.
module suite_rod_statics
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: stat_input
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_driver_simulation, only: simulation
   use xcable_theory_closed_forms, only: catenary_from_force, catenary_between, catenary_summary
   use xcable_material_law, only: material_law
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_rod_statics, statics_config

   integer, parameter :: ladder(4) = [31, 61, 121, 241], suite_ladder(4) = ladder

contains

   subroutine collect_rod_statics(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('symmetric_catenary_180kN', test_180), &
               new_unittest('symmetric_catenary_2kN', test_2kN), &
               new_unittest('inclined_taut', test_inclined_taut), &
               new_unittest('inclined_slack_linear_law', test_inclined_slack), &
               new_unittest('hanging_from_one_end', test_hanging), &
               new_unittest('very_slack_rope_catenary', test_very_slack_rope), &
               new_unittest('very_slack_paper_cable_refined', test_very_slack_paper), &
               new_unittest('current_towards_end_a', test_current_towards_a), &
               new_unittest('compressed_static_state_warned', test_compression_warning), &
               new_unittest('newton_quadratic', test_newton), &
               new_unittest('tension_too_small_refused', test_too_small), &
               new_unittest('ends_too_far_apart_refused', test_too_far), &
               new_unittest('vertical_taut_tether', test_vertical_tether), &
               new_unittest('vertical_tether_in_water_second_order', test_vertical_tether_water), &
               new_unittest('vertical_slack_line_hangs_folded', test_vertical_folded), &
               new_unittest('vertical_slack_rope_refused', test_vertical_slack), &
               new_unittest('catenary_guess_one_panel', test_guess_one_panel)]
   end subroutine collect_rod_statics

   !> The paper's cable; the tests change what they need.
   function statics_config(nodes) result(c)
      integer, intent(in) :: nodes
      type(case_config) :: c
      c%source = 'test'
      c%nodes = nodes
      ! The paper's rope, which pushes back along its law in compression.
      c%compression = 'law'
      c%break_enabled = .false.
      c%t_end = 0.01_dp
      c%newton_tol = 1.0e-10_dp
   end function statics_config

   !> The line of bench/studies/statics_sweep.py (60 m, linear law, end b at (48, 24) m) in
   !> water with a current current_x along x, planar model.
   function line_in_current(nodes, current_x) result(c)
      integer, intent(in) :: nodes
      real(dp), intent(in) :: current_x
      type(case_config) :: c
      c = statics_config(nodes)
      c%law = 'linear'
      c%ea = 451603.943953533_dp
      c%diameter = 0.05_dp
      c%fluid_density = 1025
      c%cd_normal = 1.2_dp
      c%cd_tangential = 0.008_dp
      c%ca_normal = 1
      c%current_x = current_x
      c%surface_z = 100 ! all of the line under water
      c%end_b%x = 48
      c%end_b%z = 24
      c%model = '2d'
      c%given = 'end_b%x end_b%z'
   end function line_in_current

   !> Relative errors of span, sag, end tension and mid-span strain of the
   !> symmetric case against the exact catenary on the ladder; observed order
   !> from successive differences; the finest errors below the bounds.
   subroutine symmetric(error, tension, ei, bounds)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in) :: tension, ei, bounds(4)
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: err(4, size(ladder)), span, sag, angle, mid, order
      character(len=12), parameter :: what(4) = [character(len=12) :: 'span', 'sag', 'end tension', 'mid strain']
      integer :: i, q, n
      do i = 1, size(ladder)
         c = statics_config(ladder(i))
         c%tension = tension
         c%bending_stiffness = ei
         call sim%prepare(c, error)
         if (allocated(error)) return
         call catenary_summary(sim%rod%scene%law, sim%rod%scene%weight, c%length, tension, span, sag, angle, mid, error)
         if (allocated(error)) return
         n = ladder(i)
         associate (r => sim%rod%static%r)
            err(:, i) = [(sim%rod%static%span - span)/span, (sim%rod%static%sag - sag)/sag, &
                         (norm2(sim%rod%static%reaction_a) - tension)/tension, &
                         (0.5_dp*(norm2(r(:, (n + 1)/2 + 1) - r(:, (n + 1)/2)) + norm2(r(:, (n + 1)/2) - r(:, (n - 1)/2))) &
                          /(c%length/(n - 1)) - 1 - mid)/mid]
         end associate
      end do
      write (output_unit, '(4x,a,f9.0,a,es9.2,a)') 'rod statics at ', tension, ' N, EI ', ei, &
         ' N m^2: relative errors against the exact catenary'
      write (output_unit, '(4x,a6,4a14)') 'nodes', (trim(what(q)), q=1, 4)
      do i = 1, size(ladder)
         write (output_unit, '(4x,i6,4es14.3)') ladder(i), err(:, i)
      end do
      n = size(ladder)
      do q = 1, 4
         call check(error, abs(err(q, n)) <= bounds(q), trim(what(q))//' error at 241 nodes '//str(err(q, n))// &
                    ' exceeds '//str(bounds(q)))
         if (allocated(error)) return
         ! Errors at round-off (the end tension, matched by the span iteration) have no order.
         if (maxval(abs(err(q, n - 2:n))) < 1.0e-11_dp) cycle
         order = log(abs((err(q, n - 2) - err(q, n - 1))/(err(q, n - 1) - err(q, n))))/log(2.0_dp)
         write (output_unit, '(4x,a,a,f6.2)') trim(what(q)), ': observed order ', order
         call check(error, order > 1.8_dp .and. order < 2.3_dp, trim(what(q))//' converges at order '//str(order))
         if (allocated(error)) return
      end do
   end subroutine symmetric

   !> The paper's cable at 180 kN. The sag keeps a floor of -7.4e-7 that does
   !> not fall with refinement: the bending stiffness (absent from the
   !> catenary) with moment-free pinned ends lifts the sag by about
   !> 7 EI / (T L^2); test_2kN with EI = 1e-3 N m^2 shows no such floor.
   subroutine test_180(error)
      type(error_type), allocatable, intent(out) :: error
      call symmetric(error, 180.0e3_dp, 0.0_dp, [2.0e-10_dp, 2.0e-6_dp, 1.0e-12_dp, 2.0e-10_dp])
   end subroutine test_180

   !> A slack cable (2 kN, sag 5.1 m) of negligible bending stiffness.
   subroutine test_2kN(error)
      type(error_type), allocatable, intent(out) :: error
      call symmetric(error, 2.0e3_dp, 1.0e-3_dp, [5.0e-6_dp, 5.0e-6_dp, 1.0e-12_dp, 5.0e-6_dp])
   end subroutine test_2kN

   !> A line held between two points at different heights against the exact
   !> catenary between them: the force at both supports, the angle of the end
   !> cells, the lowest point and the stretched length, on the ladder.
   subroutine inclined(error, c, label, bounds, nodes, no_order)
      type(error_type), allocatable, intent(out) :: error
      type(case_config), intent(inout) :: c
      character(*), intent(in) :: label
      real(dp), intent(in) :: bounds(6)
      !> The ladder of node counts (default: ladder); the bounds hold at the last.
      integer, intent(in), optional :: nodes(:)
      !> Quantities whose order is not checked (their error has reached a floor that is not the grid's).
      logical, intent(in), optional :: no_order(6)
      type(simulation) :: sim
      integer, allocatable :: ladder(:)
      real(dp) :: err(6, 8), n0(2), nl(2), pa(2), pb(2), rr(2, 3), ee(3), tt(3), s_low, z_low, stretched
      real(dp) :: order, ta(2), tb(2), na(2), nb(2)
      character(len=14), parameter :: what(6) = [character(len=14) :: 'force at a', 'force at b', 'angle at a', &
                                                 'angle at b', 'lowest point', 'stretched len']
      integer :: i, q, n
      ladder = suite_ladder
      if (present(nodes)) ladder = nodes
      do i = 1, size(ladder)
         c%nodes = ladder(i)
         n = ladder(i)
         call sim%prepare(c, error)
         if (allocated(error)) return
         associate (law => sim%rod%scene%law, w => sim%rod%scene%weight, l => c%length, r => sim%rod%static%r)
            pa = [c%end_a%x, c%end_a%z]
            pb = [c%end_b%x, c%end_b%z]
            call catenary_between(law, w, l, pa, pb, n0, error)
            if (allocated(error)) return
            nl = n0 + [0.0_dp, w*l]
            s_low = min(max(-n0(2)/w, 0.0_dp), l)
            call catenary_from_force(law, w, n0, pa, [0.0_dp, s_low, l], rr, ee, tt)
            z_low = rr(2, 2)
            stretched = 0
            do q = 1, n - 1
               stretched = stretched + norm2(r(:, q + 1) - r(:, q))
            end do
            ! The end cells lie along the force at their middle, s = ds/2 and L - ds/2.
            ta = r(:, 2) - r(:, 1)
            tb = r(:, n) - r(:, n - 1)
            na = n0 + [0.0_dp, 0.5_dp*w*l/(n - 1)]
            nb = nl - [0.0_dp, 0.5_dp*w*l/(n - 1)]
            err(:, i) = [norm2(sim%rod%static%reaction_a + n0)/norm2(n0), norm2(sim%rod%static%reaction_b - nl)/norm2(nl), &
                         atan2(cross(na, ta), dot_product(na, ta)), atan2(cross(nb, tb), dot_product(nb, tb)), &
                         (minval(r(2, :)) - z_low)/max(abs(z_low - max(pa(2), pb(2))), 1.0e-3_dp), &
                         (stretched - (l + integral_strain(law, w, n0, l)))/l]
         end associate
      end do
      write (output_unit, '(4x,a)') 'rod statics, '//label//': errors against the exact catenary between the ends'
      write (output_unit, '(4x,a6,6a14)') 'nodes', (trim(what(q)), q=1, 6)
      do i = 1, size(ladder)
         write (output_unit, '(4x,i6,6es14.3)') ladder(i), err(:, i)
      end do
      n = size(ladder)
      do q = 1, 6
         call check(error, abs(err(q, n)) <= bounds(q), label//': '//trim(what(q))//' error at '// &
                    str(ladder(n))//' nodes '//str(err(q, n))//' exceeds '//str(bounds(q)))
         if (allocated(error)) return
         if (abs(err(q, n - 1) - err(q, n)) < 1.0e-12_dp) cycle
         if (present(no_order)) then
            if (no_order(q)) cycle
         end if
         order = log(abs((err(q, n - 2) - err(q, n - 1))/(err(q, n - 1) - err(q, n))))/log(2.0_dp)
         write (output_unit, '(4x,a,a,f6.2)') trim(what(q)), ': observed order ', order
         call check(error, order > 1.7_dp .and. order < 2.4_dp, label//': '//trim(what(q))//' converges at order '// &
                    str(order))
         if (allocated(error)) return
      end do

   contains

      pure real(dp) function cross(a, b)
         real(dp), intent(in) :: a(2), b(2)
         cross = a(1)*b(2) - a(2)*b(1)
      end function cross
   end subroutine inclined

   !> Integral of the strain along the exact catenary (Gauss-Legendre, 64 panels).
   real(dp) function integral_strain(law, w, n0, l) result(total)
      class(material_law), intent(in) :: law
      real(dp), intent(in) :: w, n0(2), l
      real(dp), parameter :: xg(2) = [-1/sqrt(3.0_dp), 1/sqrt(3.0_dp)]
      integer :: p, q
      real(dp) :: a, b, sq
      total = 0
      do p = 1, 4096
         a = l*(p - 1)/4096
         b = l*p/4096
         do q = 1, 2
            sq = 0.5_dp*(a + b) + 0.5_dp*(b - a)*xg(q)
            total = total + 0.5_dp*(b - a)*law%strain_at(norm2(n0 + [0.0_dp, w*sq]))
         end do
      end do
   end function integral_strain

   subroutine test_inclined_taut(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = statics_config(31)
      c%end_b%x = 66
      c%end_b%z = 20
      c%bending_stiffness = 1.0e-3_dp
      c%given = 'end_b%x end_b%z'
      call inclined(error, c, 'taut, end b 20 m higher', [5.0e-9_dp, 5.0e-9_dp, 5.0e-9_dp, 5.0e-9_dp, 1.0e-5_dp, 5.0e-10_dp])
   end subroutine test_inclined_taut

   subroutine test_inclined_slack(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = statics_config(31)
      c%law = 'linear'
      c%end_b%x = 40
      c%end_b%z = -15
      c%bending_stiffness = 1.0e-3_dp
      c%given = 'end_b%x end_b%z'
      call inclined(error, c, 'slack, linear law, end b 15 m lower', &
                    [1.0e-5_dp, 1.0e-5_dp, 1.0e-5_dp, 1.0e-5_dp, 1.0e-5_dp, 1.0e-6_dp])
   end subroutine test_inclined_slack

   !> A very slack rope (compression = 'none', EI 1e-3 N m^2) held at two points
   !> 5 m apart, 60 m long: two nearly vertical legs joined by a bottom of
   !> radius 0.6 m. Newton from the catenary guess diverges at every grid (the
   !> squeezed cells of a rope that cannot push have no stiffness); the
   !> relaxation (model/rod_statics.f90) finds the state. The lowest point and the
   !> stretched length converge to the exact catenary at second order on 121,
   !> 241, 481 nodes (orders 2.13 and 1.90; with the rope's exact cut at zero
   !> tension, version 0.6, the stretched length's error is 5.0e-9 at 481 nodes and
   !> 61 nodes is not in its asymptotic range: order 0.42 from 61, 121, 241); the end forces and angles
   !> reach a floor of 6.1e-6 at 241 and 481 nodes alike (not the grid's, nor
   !> EI's: the same with EI 1e-3), so their order is not checked. Bounds: 3
   !> times the values measured at 481 nodes.
   subroutine test_very_slack_rope(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = statics_config(61)
      c%compression = 'none'
      c%end_b%x = 5
      c%end_b%z = 0
      c%bending_stiffness = 1.0e-5_dp
      c%given = 'end_b%x end_b%z'
      call inclined(error, c, 'very slack rope, ends 5 m apart', &
                    [2.0e-5_dp, 2.0e-5_dp, 2.0e-5_dp, 2.0e-5_dp, 1.5e-4_dp, 1.5e-8_dp], nodes=[121, 241, 481], &
                    no_order=[.true., .true., .true., .true., .false., .false.])
   end subroutine test_very_slack_rope

   !> The paper's cable (its EI) held at two points 5 m apart, with
   !> compression = 'law' and 'none': the bending stiffness shapes the bottom
   !> (bending length 2-4 m against the catenary's bottom radius of 0.6 m), so
   !> the reference is the grid: the 241-node state (Newton from the catenary
   !> fails there with either option) against the 961-node one at the common
   !> nodes, second order from 241, 481, 961. With 'none' it needs the
   !> relaxation with the law continued below zero.
   subroutine test_very_slack_paper(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=4), parameter :: option(2) = ['law ', 'none']
      type(case_config) :: c
      type(simulation) :: sim
      real(dp), allocatable :: r(:, :, :)
      real(dp) :: d(2), order, w
      integer, parameter :: grid(3) = [241, 481, 961]
      integer :: i, j
      c = statics_config(241)
      c%end_b%x = 5
      c%end_b%z = 0
      c%given = 'end_b%x end_b%z'
      allocate (r(2, grid(1), 3))
      do j = 1, 2
         c%compression = trim(option(j))
         do i = 1, 3
            c%nodes = grid(i)
            call sim%prepare(c, error)
            if (allocated(error)) return
            r(:, :, i) = sim%rod%static%r(:, ::(grid(i) - 1)/(grid(1) - 1))
            if (i == 1) then
               w = sim%rod%scene%weight
               call check_close(error, sim%rod%static%reaction_a(2) + sim%rod%static%reaction_b(2), w*c%length, &
                                'vertical support forces against the weight', rel_tol=1.0e-12_dp)
               if (allocated(error)) return
            end if
         end do
         d = [maxval(norm2(r(:, :, 1) - r(:, :, 3), 1)), maxval(norm2(r(:, :, 2) - r(:, :, 3), 1))]/c%length
         order = log(maxval(norm2(r(:, :, 1) - r(:, :, 2), 1))/maxval(norm2(r(:, :, 2) - r(:, :, 3), 1)))/log(2.0_dp)
         write (output_unit, '(4x,a,2es11.3,a,f6.2)') 'paper cable, ends 5 m apart, '//option(j)// &
            ': largest node distance / L to 961 nodes at 241, 481:', d, '; observed order', order
         call check(error, d(1) <= 1.2e-4_dp, option(j)//': 241 nodes differ from 961 by '//str(d(1))//' L')
         if (allocated(error)) return
         call check(error, order > 1.7_dp .and. order < 2.4_dp, option(j)//': the static state converges at order '// &
                    str(order))
         if (allocated(error)) return
      end do
   end subroutine test_very_slack_paper

   !> The line of bench/peer/sway3d.py (60 m, end b 48 m along and 24 m up, in
   !> sea water) in a current of 2 m/s towards end a. Weight and drag bow the
   !> line to opposite sides of its chord; the continuation in the loads from
   !> the hanging line stalled at 13 % (61 nodes). The relaxation from the
   !> catenary under the mean load finds the bow of the current: all cells in
   !> tension, the line turning clockwise (the drag-only closed form turns by
   !> -1.94 rad with T = 910 N), end tensions converging at second order.
   subroutine test_current_towards_a(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      type(simulation) :: sim
      integer, parameter :: grid(3) = [31, 61, 121]
      real(dp) :: ta(3), turning, a(2), b(2), order
      integer :: i, k, n
      c = line_in_current(61, -2.0_dp)
      do i = 1, 3
         c%nodes = grid(i)
         call sim%prepare(c, error)
         if (allocated(error)) return
         n = grid(i)
         ta(i) = norm2(sim%rod%static%reaction_a)
         turning = 0
         associate (r => sim%rod%static%r)
            do k = 2, n - 1
               a = r(:, k) - r(:, k - 1)
               b = r(:, k + 1) - r(:, k)
               turning = turning + atan2(a(1)*b(2) - a(2)*b(1), dot_product(a, b))
            end do
            call check(error, minval(norm2(r(:, 2:n) - r(:, 1:n - 1), 1))/(c%length/(n - 1)) > 1, &
                       'a cell in compression at '//str(n)//' nodes')
            if (allocated(error)) return
         end associate
         write (output_unit, '(4x,a,i4,a,f9.3,a,f8.4,a)') 'current of 2 m/s towards end a,', n, ' nodes: T_a', &
            ta(i), ' N, turning', turning, ' rad'
         call check(error, turning > -2.1_dp .and. turning < -1.8_dp, 'total turning '//str(turning)//' rad')
         if (allocated(error)) return
      end do
      order = log(abs((ta(1) - ta(2))/(ta(2) - ta(3))))/log(2.0_dp)
      write (output_unit, '(4x,a,f6.2)') 'T_a: observed order', order
      call check(error, order > 1.7_dp .and. order < 2.4_dp, 'T_a converges at order '//str(order))
   end subroutine test_current_towards_a

   !> A static state that pushes is reported. The line of current_towards_end_a
   !> (compression = 'law') in a current of 1 m/s towards end a on 161 nodes:
   !> Newton finds a loop at end a, its cells pushing by about 157 N (bench/
   !> studies/statics_sweep.py); its run's warnings say so, also with the 3-D
   !> model (whose statics start from that state). The same line in still
   !> water hangs in tension and does not warn.
   subroutine test_compression_warning(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      type(simulation) :: sim
      real(dp), allocatable :: tension(:)
      integer :: i, n
      logical :: warned
      do i = 1, 3
         c = line_in_current(161, merge(0.0_dp, -1.0_dp, i == 2))
         c%model = merge('3d', '2d', i == 3)
         c%t_end = 0.001_dp
         c%dt = 0.001_dp
         call sim%prepare(c, error)
         if (allocated(error)) return
         n = c%nodes
         ! The planar static state (of a 3-D run: its statics' first guess).
         associate (r => sim%rod%static%r, s => sim%rod%s)
            tension = sim%rod%scene%law%tension(norm2(r(:, 2:n) - r(:, 1:n - 1), 1)/(s(2:n) - s(1:n - 1)) - 1)
         end associate
         call sim%run(error=error)
         if (allocated(error)) return
         warned = index(sim%rod%summary%warnings, 'the static state is in compression') > 0
         write (output_unit, '(4x,a,a,f5.1,a,2f10.2,a,f10.2,a,l2)') c%model, ' current', c%current_x, &
            ' m/s: static tension from', minval(tension), maxval(tension), ' N (3-D statics: ', &
            sim%rod%static_min_tension, ' N); warned', warned
         if (i /= 2) then
            call check(error, minval(tension) < -100, 'the 1 m/s case no longer pushes (the test needs a loop): '// &
                       str(minval(tension))//' N')
            if (allocated(error)) return
         end if
         call check(error, warned .eqv. (i /= 2), c%model//', current '//str(c%current_x)//' m/s: the warnings are "'// &
                    sim%rod%summary%warnings//'"')
         if (allocated(error)) return
      end do
   end subroutine test_compression_warning

   !> End a fixed, end b carrying a point mass: the line hangs straight down,
   !> the tension at the support is the weight of cable and mass, and the
   !> length is the integral of the strain of the linear law.
   subroutine test_hanging(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w, total, stretched, exact, mass
      integer :: n
      c = statics_config(61)
      c%law = 'linear'
      c%end_b%kind = 'mass'
      mass = 50
      c%end_b%mass = mass
      c%given = ''
      call sim%prepare(c, error)
      if (allocated(error)) return
      n = c%nodes
      w = sim%rod%scene%weight
      total = w*c%length + mass*c%gravity
      associate (r => sim%rod%static%r, ea => sim%rod%scene%law%tension(1.0_dp))
         stretched = -r(2, n)
         ! T(s) = M g + w (L - s): length = L + (M g L + w L^2 / 2) / EA.
         exact = c%length + (mass*c%gravity*c%length + 0.5_dp*w*c%length**2)/ea
         write (output_unit, '(4x,a,2es12.3)') 'hanging mass: relative errors of the support force and the hanging length', &
            (norm2(sim%rod%static%reaction_a) - total)/total, (stretched - exact)/exact
         call check_close(error, norm2(sim%rod%static%reaction_a), total, 'support force', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, stretched, exact, 'hanging length', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check(error, maxval(abs(r(1, :))) < 1.0e-9_dp, 'the line does not hang vertically')
      end associate
   end subroutine test_hanging

   !> The statics' first guess integrates the catenary with one Gauss-Legendre panel per
   !> cell (model/rod_statics.f90, guess_panels); the reference takes 8. On the paper's cable
   !> between its ends (31, 61 and 241 nodes, 180 kN and 2 kN at the ends), the positions
   !> of the two agree to round-off of the length.
   subroutine test_guess_one_panel(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      integer, parameter :: nodes(3) = [31, 61, 241]
      real(dp), parameter :: tensions(2) = [180.0e3_dp, 2.0e3_dp]
      real(dp), allocatable :: s(:), r1(:, :), r8(:, :), e(:), t(:)
      real(dp) :: n0(2), pa(2), pb(2), worst
      integer :: i, j, k, n
      worst = 0
      do i = 1, size(nodes)
         do j = 1, size(tensions)
            n = nodes(i)
            c = statics_config(n)
            c%tension = tensions(j)
            call sim%prepare(c, error)
            if (allocated(error)) return
            pa = [c%end_a%x, c%end_a%z]
            pb = sim%rod%static%r(:, n)
            s = [(c%length*(k - 1)/(n - 1), k=1, n)]
            allocate (r1(2, n), r8(2, n), e(n), t(n))
            call catenary_between(sim%rod%scene%law, sim%rod%scene%weight, c%length, pa, pb, n0, error)
            if (allocated(error)) return
            call catenary_from_force(sim%rod%scene%law, sim%rod%scene%weight, n0, pa, s, r8, e, t)
            call catenary_from_force(sim%rod%scene%law, sim%rod%scene%weight, n0, pa, s, r1, e, t, panels=1)
            worst = max(worst, maxval(abs(r1 - r8))/c%length)
            deallocate (r1, r8, e, t)
         end do
      end do
      write (output_unit, '(4x,a,es10.2)') 'catenary guess, one panel a cell against 8: largest |dR| / L', worst
      ! Measured 9.5e-15 (241 nodes, 180 kN): the summation's round-off, as between 16 and 8
      ! panels (up to 7.3e-15).
      call check(error, worst < 3.0e-14_dp, 'the one-panel guess is '//str(worst)//' of the length from the reference')
   end subroutine test_guess_one_panel

   !> The static Newton iteration converges quadratically.
   subroutine test_newton(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      c = statics_config(121)
      c%tension = 2.0e3_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,i0,a,i0,a)') 'rod statics (2 kN, 121 nodes): ', sim%rod%static%newton_iterations, &
         ' Newton iterations in ', sim%rod%static%span_iterations + 1, ' solves of the span iteration'
      call check(error, sim%rod%static%newton_iterations <= 8*(sim%rod%static%span_iterations + 1), &
                 'more than 8 Newton iterations per solve from the catenary guess')
   end subroutine test_newton

   !> A tension that cannot hold the cable's weight is an input error naming the tension.
   subroutine test_too_small(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: refused
      type(simulation) :: sim
      type(case_config) :: c
      c = statics_config(21)
      c%tension = 600
      call sim%prepare(c, refused)
      call check(error, allocated(refused), 'a tension below w0 L / 2 was accepted')
      if (allocated(error)) return
      call check(error, refused%stat == stat_input .and. index(refused%message, '&static: tension = 600') > 0 .and. &
                 index(refused%message, 'half the weight') > 0, 'unexpected message: '//refused%message)
   end subroutine test_too_small

   !> Ends farther apart than the cable can reach are an input error.
   subroutine test_too_far(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: refused
      type(simulation) :: sim
      type(case_config) :: c
      c = statics_config(21)
      c%end_b%x = 85
      c%end_b%z = 0
      c%given = 'end_b%x end_b%z'
      call sim%prepare(c, refused)
      call check(error, allocated(refused), 'ends 85 m apart were accepted for a 60 m cable with strain_max 0.35')
      if (allocated(error)) return
      call check(error, refused%stat == stat_input .and. index(refused%message, 'reaches at most') > 0, &
                 'unexpected message: '//refused%message)
   end subroutine test_too_far
   !> A taut tether between two fixed ends one above the other (end a 30 m below end b, a
   !> 30 m line of the linear law stretched to 30.6 m), planar and 3-D: it hangs straight, the
   !> tension grows by w along s, and the stretched length L + (T_a L + w L^2 / 2) / EA is the
   !> span: T_a = (span - L) EA / L - w L / 2, T_b = T_a + w L. The weight sits at the nodes and
   !> the law is linear, so the grid is exact: measured 2.4e-14 relative (61 nodes, both models).
   subroutine test_vertical_tether(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w, ea, span, ta, tb, off
      integer :: n, m
      character(len=2), parameter :: models(2) = ['2d', '3d']
      do m = 1, 2
         c = statics_config(61)
         c%law = 'linear'
         c%length = 30
         c%end_a%x = 0
         c%end_a%z = -30
         c%end_b%x = 0
         c%end_b%z = 0.6_dp
         c%model = models(m)
         c%given = 'end_a%x end_a%z end_b%x end_b%z'
         call sim%prepare(c, error)
         if (allocated(error)) return
         n = c%nodes
         w = sim%rod%scene%weight
         ea = sim%rod%scene%law%tension(1.0_dp)
         span = 30.6_dp
         ta = (span - c%length)*ea/c%length - 0.5_dp*w*c%length
         tb = ta + w*c%length
         ! The end tensions the run reports (the 3-D statics' own in 3-D).
         write (output_unit, '(4x,a,a,2es12.3)') models(m), ' vertical tether: relative errors of T_a and T_b', &
            (sim%rod%info%tension_a - ta)/tb, (sim%rod%info%tension_b - tb)/tb
         call check_close(error, sim%rod%info%tension_a, ta, models(m)//' tension at end a', rel_tol=1.0e-13_dp)
         if (allocated(error)) return
         call check_close(error, sim%rod%info%tension_b, tb, models(m)//' tension at end b', rel_tol=1.0e-13_dp)
         if (allocated(error)) return
         if (m == 1) then
            off = maxval(abs(sim%rod%static%r(1, :)))
         else
            off = maxval(hypot(sim%rod3%pieces(1)%run%x(1:3*n:3), sim%rod3%pieces(1)%run%x(2:3*n:3)))
         end if
         call check(error, off < 1.0e-9_dp*c%length, models(m)//': the tether leaves the vertical by '//str(off)//' m')
         if (allocated(error)) return
      end do
   end subroutine test_vertical_tether

   !> A taut tether one above the other in water (the paper's rope, its tanh law, 30 m between
   !> z = -30 and z = 0.6, all under water): its wet weight w (the scene's, net of the lift)
   !> sits at the nodes, so each cell carries the exact tension T(s) = T_a + w s at its middle,
   !> and the stretched length is the midpoint rule of the integral of 1 + eps(T_a + w s): the
   !> end tensions' error is of second order in ds. The exact T_a solves
   !> int_0^L (1 + eps(T_a + w s)) ds = span (Simpson's rule on 4000 intervals, a secant
   !> iteration on T_a); T_b = T_a + w L. Planar and 3-D, at 61 and 121 nodes; measured: the
   !> errors of T_a and T_b 1.19e-9 and 2.97e-10 of T_b (order 2.00), the same in 3-D.
   subroutine test_vertical_tether_water(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w, span, ta, tb, err(2, 2), order, a, dry
      integer :: m, i
      integer, parameter :: grids(2) = [61, 121]
      character(len=2), parameter :: models(2) = ['2d', '3d']
      span = 30.6_dp
      do m = 1, 2
         do i = 1, 2
            c = statics_config(grids(i))
            c%length = 30
            c%end_a%x = 0
            c%end_a%z = -30
            c%end_b%x = 0
            c%end_b%z = 0.6_dp
            c%fluid_density = 1025
            c%surface_z = 100
            c%model = models(m)
            c%given = 'end_a%x end_a%z end_b%x end_b%z'
            call sim%prepare(c, error)
            if (allocated(error)) return
            w = sim%rod%scene%weight
            dry = sim%rod%scene%mass*sim%rod%scene%gravity
            if (i == 1) then
               ! (In water: the weight is net of the lift.)
               call check(error, w < 0.9_dp*dry, 'the weight '//str(w)//' N/m is not net of the lift (dry '// &
                          str(dry)//' N/m)')
               if (allocated(error)) return
               ta = exact_bottom_tension(sim%rod%scene%law, w, c%length, span)
               tb = ta + w*c%length
            end if
            err(1, i) = (sim%rod%info%tension_a - ta)/tb
            err(2, i) = (sim%rod%info%tension_b - tb)/tb
         end do
         order = log(abs(err(1, 1)/err(1, 2)))/log(2.0_dp)
         write (output_unit, '(4x,a,a,4es11.2,a,f6.2)') models(m), ' tether in water: errors of T_a, T_b / T_b ' // &
            '(61, 121 nodes)', err(:, 1), err(:, 2), '; order', order
         call check(error, abs(order - 2) < 0.1_dp, models(m)//': the order of T_a is '//str(order)//', not 2')
         if (allocated(error)) return
         a = maxval(abs(err(:, 2)))
         call check(error, a < 1.0e-9_dp, models(m)//': end tensions off by '//str(a)//' of T_b at 121 nodes')
         if (allocated(error)) return
      end do
   contains
      !> T_a such that the integral of 1 + eps(T_a + w s) over the unstretched length is the span.
      real(dp) function exact_bottom_tension(law, w, length, span) result(t0)
         class(material_law), intent(in) :: law
         real(dp), intent(in) :: w, length, span
         real(dp) :: t1, g0, g1, t2
         integer :: it
         t0 = law%tension(span/length - 1) - 0.5_dp*w*length
         t1 = 1.001_dp*t0
         g0 = stretched(t0) - span
         g1 = stretched(t1) - span
         do it = 1, 50
            if (g1 == g0) exit
            t2 = t1 - g1*(t1 - t0)/(g1 - g0)
            t0 = t1
            g0 = g1
            t1 = t2
            g1 = stretched(t1) - span
            if (abs(g1) < 1.0e-14_dp*span) exit
         end do
         t0 = t1
      end function exact_bottom_tension
      !> The stretched length for T_a = t (Simpson).
      real(dp) function stretched(t)
         real(dp), intent(in) :: t
         integer, parameter :: k = 4000
         integer :: j
         real(dp) :: h
         class(material_law), allocatable :: law
         allocate (law, source=sim%rod%scene%law)
         h = c%length/k
         stretched = 0
         do j = 0, k
            stretched = stretched + merge(1, merge(4, 2, mod(j, 2) == 1), j == 0 .or. j == k)* &
                        (1 + law%strain_at(t + w*j*h))
         end do
         stretched = stretched*h/3
      end function stretched
   end subroutine test_vertical_tether_water

   !> A slack line between ends one above the other (40 m between z = -50 and z = -20, a rope
   !> that pushes back along its law, EI 70.6 N m^2): it hangs folded, down below the lower end
   !> and up again, its fold held open by the bending stiffness (the first guess: the catenary to
   !> a point beside end b, sheared back). Along a planar rod under its weight with ends free to
   !> turn, T - w z + EI kappa^2 / 2 is constant (inextensible), so T_b - T_a = w (z_b - z_a)
   !> as for the doubled line; the linear law at EA = 1e9 N keeps the stretch's share below
   !> 1e-6. The supports carry the weight: their vertical forces sum to w L. The doubled line's
   !> fold would be 5 m below the lower end; the bending rounds it a little higher. Planar and
   !> 3-D (the same state), at 81 and 161 nodes: measured (T_b - T_a) / (w dz) - 1 = -2.2e-6
   !> and -3.0e-6, the vertical forces 7.7e-9 and 6.1e-9 below w L, the lowest point at
   !> z = -54.30 and -54.31 m.
   subroutine test_vertical_folded(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w, err(2), balance, lowest
      integer :: m, i, n
      integer, parameter :: grids(2) = [81, 161]
      character(len=2), parameter :: models(2) = ['2d', '3d']
      do m = 1, 2
         do i = 1, 2
            c = statics_config(grids(i))
            c%law = 'linear'
            c%ea = 1.0e9_dp
            c%length = 40
            c%end_a%x = 0
            c%end_a%z = -50
            c%end_b%x = 0
            c%end_b%z = -20
            c%model = models(m)
            c%given = 'end_a%x end_a%z end_b%x end_b%z'
            call sim%prepare(c, error)
            if (allocated(error)) return
            n = c%nodes
            w = sim%rod%scene%weight
            err(i) = ((sim%rod%info%tension_b - sim%rod%info%tension_a) - w*30)/(w*30)
            if (m == 1) then
               balance = sim%rod%static%reaction_a(2) + sim%rod%static%reaction_b(2)
               lowest = minval(sim%rod%static%r(2, :))
            else
               balance = sim%rod3%pieces(1)%reaction(3, 1) + sim%rod3%pieces(1)%reaction(3, 2)
               lowest = minval(sim%rod3%pieces(1)%run%x(3:3*n:3))
            end if
            write (output_unit, '(4x,a,a,i4,a,es11.2,a,es11.2,a,f8.3,a,2f9.2)') models(m), ' folded line,', n, &
               ' nodes: (T_b - T_a) / (w dz) - 1', err(i), ', vertical forces / wL - 1', balance/(w*c%length) - 1, &
               ', lowest z', lowest, ', T_a, T_b', sim%rod%info%tension_a, sim%rod%info%tension_b
            call check(error, abs(err(i)) < 1.0e-5_dp, models(m)//': T_b - T_a is not w (z_b - z_a): off by '// &
                       str(err(i)))
            if (allocated(error)) return
            call check(error, abs(balance/(w*c%length) - 1) < 3.0e-8_dp, models(m)//': the supports carry '// &
                       str(balance)//' N, the line weighs '//str(w*c%length)//' N')
            if (allocated(error)) return
            ! Folded: below the lower end, above the doubled line's fold (55 m down, 5 m below end a).
            call check(error, lowest < -54 .and. lowest > -55, models(m)//': the lowest point is at z = '// &
                       str(lowest)//' m, not in the fold between 54 and 55 m down')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_vertical_folded

   !> A slack rope that cannot push (compression = 'none') between two ends one above the other
   !> would hang folded, its fold held open by bending against compression it cannot take: the
   !> statics fail and the message says why.
   subroutine test_vertical_slack(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: refused
      type(simulation) :: sim
      type(case_config) :: c
      c = statics_config(61)
      c%compression = 'none'
      c%end_a%x = 0
      c%end_a%z = -20
      c%end_b%x = 0
      c%end_b%z = 0
      c%given = 'end_a%x end_a%z end_b%x end_b%z'
      call sim%prepare(c, refused)
      call check(error, allocated(refused), 'a slack rope between ends one above the other was accepted')
      if (allocated(error)) return
      call check(error, index(refused%message, 'hangs folded') > 0 .and. index(refused%message, 'compression = ''law''') > 0, &
                 'unexpected message: '//refused%message)
   end subroutine test_vertical_slack
end module suite_rod_statics
