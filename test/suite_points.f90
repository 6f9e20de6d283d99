!> Bodies at the joints of a line of segments (issue "Moorings": clump weights and buoys,
!> &point_k): the chain and rope line of suite_segments with a clump, and in water with a buoy,
!> against the elastic catenary of each segment in closed form with the vertical force jumping
!> by the body's net weight at the joint (its own formulas here), with the order of
!> convergence; the 3-D model turned out of the x-z plane against the planar one; the energy
!> ledger with the body's added mass and drag in a current; the step's and the statics'
!> Jacobians against central differences; and the bad input.
module suite_points
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_driver_simulation, only: simulation
   use suite_segments, only: chain_rope_config
   use suite_rod_statics, only: statics_config
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_points

   !> The chain and rope line of chain_rope_config: lengths (m), areas (m^2), EA (N), end b (m).
   real(dp), parameter :: seg_length(2) = [50.0_dp, 150.0_dp], seg_area(2) = [0.01_dp, 0.005_dp], &
                          seg_ea(2) = [5.0e8_dp, 2.0e7_dp], end_b(2) = [170.0_dp, 90.0_dp], g = 9.81_dp

contains

   subroutine collect_points(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('clump_and_buoy_catenary_closed_form', test_closed_form), &
               new_unittest('model_3d_points_turned_equal_2d', test_3d_turned), &
               new_unittest('ledger_with_a_buoy_in_a_current', test_ledger), &
               new_unittest('points_jacobians', test_jacobians), &
               new_unittest('body_at_a_free_end_closed_form', test_free_end), &
               new_unittest('buoy_at_the_surface_draft_and_jacobians', test_surface_buoy), &
               new_unittest('body_on_the_break_node_counted_once', test_break_at_body), &
               new_unittest('points_bad_input_refused', test_bad_input)]
   end subroutine collect_points

   !> The chain and rope line with a body at its joint: case 1 a clump of 300 kg in air; case 2
   !> in sea water (1025 kg/m^3; the rope 1100 kg/m^3) a buoy of 100 kg displacing 0.8 m^3.
   function body_config(nodes, case) result(c)
      integer, intent(in) :: nodes, case
      type(case_config) :: c
      c = chain_rope_config(nodes)
      c%point_count = 1
      c%points(1)%joint = 1
      c%given = c%given//' point_1%joint point_1%mass'
      if (case == 1) then
         c%points(1)%mass = 300
      else
         c%points(1)%mass = 100
         c%points(1)%volume = 0.8_dp
         c%segments(2)%density = 1100
         c%fluid_density = 1025
         c%surface_z = 200
         c%given = c%given//' point_1%volume'
      end if
   end function body_config

   !> The z component of the cross product of two vectors (x, z) of the plane: a x b . e_y sign
   !> aside, what atan2 needs for the turning angle.
   pure real(dp) function cross(a, b)
      real(dp), intent(in) :: a(2), b(2)
      cross = a(1)*b(2) - a(2)*b(1)
   end function cross

   !> Weights per length (N/m) and the body's net weight (N) of body_config's case.
   subroutine case_weights(case, w, wp)
      integer, intent(in) :: case
      real(dp), intent(out) :: w(2), wp
      if (case == 1) then
         w = [8000, 1000]*seg_area*g
         wp = 300*g
      else
         w = ([8000, 1100] - 1025)*seg_area*g
         wp = (100 - 1025*0.8_dp)*g
      end if
   end subroutine case_weights

   !> Position at arc length s of the elastic catenary of the two linear segments with the force
   !> (H, V0) = y at s = 0: each segment from its start s0 adds
   !>   x: H (s - s0) / EA + H / w (asinh(V / H) - asinh(V_0 / H)),
   !>   z: (V_0 (s - s0) + w (s - s0)^2 / 2) / EA + H / w (sqrt(1 + (V / H)^2) - sqrt(1 + (V_0 / H)^2)),
   !> V_0 and V the vertical force at s0 and s; past the joint V_0 = V0 + w_1 L_1 + W_p.
   function point_at(y, s, w, wp) result(p)
      real(dp), intent(in) :: y(2), s, w(2), wp
      real(dp) :: p(2), s0, va, vb, ds
      integer :: j
      p = 0
      s0 = 0
      va = y(2)
      do j = 1, 2
         ds = min(s, s0 + seg_length(j)) - s0
         if (ds <= 0) exit
         vb = va + w(j)*ds
         p(1) = p(1) + y(1)*ds/seg_ea(j) + y(1)/w(j)*(asinh(vb/y(1)) - asinh(va/y(1)))
         p(2) = p(2) + (va*ds + 0.5_dp*w(j)*ds**2)/seg_ea(j) + y(1)/w(j)*(sqrt(1 + (vb/y(1))**2) - sqrt(1 + (va/y(1))**2))
         s0 = s0 + seg_length(j)
         va = va + w(j)*seg_length(j) + wp
      end do
   end function point_at

   !> (H, V0) that takes the catenary to end b: Newton with central differences, halving the step.
   subroutine exact_force(w, wp, y)
      real(dp), intent(in) :: w(2), wp
      real(dp), intent(out) :: y(2)
      real(dp) :: r(2), jac(2, 2), dy(2), det, step(2)
      integer :: it, j, ls
      y = [0.5_dp*sum(w*seg_length), -0.2_dp*sum(w*seg_length)]
      do it = 1, 100
         r = point_at(y, sum(seg_length), w, wp) - end_b
         if (norm2(r) < 1.0e-11_dp) exit
         do j = 1, 2
            dy = 0
            dy(j) = 1.0e-6_dp*max(1.0_dp, abs(y(j)))
            jac(:, j) = (point_at(y + dy, sum(seg_length), w, wp) - point_at(y - dy, sum(seg_length), w, wp))/(2*dy(j))
         end do
         det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
         step = [jac(2, 2)*r(1) - jac(1, 2)*r(2), -jac(2, 1)*r(1) + jac(1, 1)*r(2)]/det
         do ls = 1, 30
            if (y(1) - step(1) > 0) then
               if (norm2(point_at(y - step, sum(seg_length), w, wp) - end_b) < norm2(r)) exit
            end if
            step = 0.5_dp*step
         end do
         y = y - step
      end do
   end subroutine exact_force

   !> The rod's statics on 201 and 401 nodes against the closed form, for the clump and the buoy:
   !> the largest error of the nodes' positions (over the line's length) and of the cells'
   !> tensions at their middles (over the largest tension); second order. The joint's vertical
   !> force jumps by W_p: the two cells at the joint differ in tension as the closed form says.
   subroutine test_closed_form(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: ladder(2) = [201, 401]
      type(simulation) :: sim
      real(dp) :: y(2), w(2), wp, err_r(2), err_t(2), t_max, sm, t_exact, vm, turn_joint, turn_other, turn_k
      integer :: i, k, n, case
      do case = 1, 2
         call case_weights(case, w, wp)
         call exact_force(w, wp, y)
         t_max = max(norm2(y), norm2([y(1), y(2) + sum(w*seg_length) + wp]))
         do i = 1, 2
            call sim%prepare(body_config(ladder(i), case), error)
            if (allocated(error)) return
            associate (r => sim%rod%static%r, s => sim%rod%s, piece => sim%rod%pieces(1)%problem%piece)
               n = size(s)
               err_r(i) = 0
               err_t(i) = 0
               do k = 1, n
                  err_r(i) = max(err_r(i), norm2(r(:, k) - point_at(y, s(k), w, wp)))
               end do
               do k = 1, n - 1
                  sm = 0.5_dp*(s(k) + s(k + 1))
                  vm = y(2) + w(1)*min(sm, seg_length(1)) + w(2)*max(sm - seg_length(1), 0.0_dp)
                  if (sm > seg_length(1)) vm = vm + wp
                  t_exact = norm2([y(1), vm])
                  err_t(i) = max(err_t(i), abs(piece%cell_tension(k, norm2(r(:, k + 1) - r(:, k))/piece%ds(k) - 1) - &
                                               t_exact))
               end do
               err_t(i) = err_t(i)/t_max
               err_r(i) = err_r(i)/sum(seg_length)
               ! The kink at the body is the body's, not the grid's: the static check of the grid's
               ! resolution (the largest turn between cells, its warning) leaves that node out.
               turn_other = 0
               do k = 2, n - 1
                  turn_k = abs(atan2(cross(r(:, k) - r(:, k - 1), r(:, k + 1) - r(:, k)), &
                                     dot_product(r(:, k) - r(:, k - 1), r(:, k + 1) - r(:, k))))
                  if (abs(s(k) - seg_length(1)) < 1.0e-9_dp) then
                     turn_joint = turn_k
                  else
                     turn_other = max(turn_other, turn_k)
                  end if
               end do
               call check(error, turn_joint > 2*turn_other .and. abs(sim%rod%static_max_turn - turn_other) <= &
                          1.0e-12_dp*turn_other, 'the static turn check counts the body''s kink: '// &
                          str(sim%rod%static_max_turn)//' rad, the joint '//str(turn_joint)//' rad, elsewhere '// &
                          str(turn_other)//' rad')
               if (allocated(error)) return
            end associate
            write (output_unit, '(4x,a,i2,a,i4,a,es9.2,a,es9.2,a,f7.4,a,f7.4,a)') 'body case', case, ', ', ladder(i), &
               ' nodes: positions', err_r(i), ' of L, tensions', err_t(i), ' of the largest; turn at the joint', &
               turn_joint, ' rad, elsewhere', turn_other, ' rad'
         end do
         write (output_unit, '(4x,a,f5.2,a,f5.2)') 'observed order: positions ', log(err_r(1)/err_r(2))/log(2.0_dp), &
            ', tensions ', log(err_t(1)/err_t(2))/log(2.0_dp)
         ! Measured (401 nodes): clump 1.1e-6 and 8.0e-6, buoy 2.3e-6 and 1.8e-5.
         call check(error, err_r(2) < 6.0e-6_dp .and. err_t(2) < 5.0e-5_dp, 'the line with a body at its joint '// &
                    'is off its closed form (case '//str(case)//'): positions '//str(err_r(2))//' of L, tensions '// &
                    str(err_t(2))//' of the largest')
         if (allocated(error)) return
         call check(error, err_r(1)/err_r(2) > 3.0_dp .and. err_t(1)/err_t(2) > 1.8_dp, 'no second order (case '// &
                    str(case)//'): positions '//str(err_r(1)/err_r(2))//', tensions '//str(err_t(1)/err_t(2)))
         if (allocated(error)) return
      end do
   end subroutine test_closed_form

   !> The buoy case in water with a current of 0.3 m/s along x, drag on the lines and on the
   !> buoy (cd 0.8 on 1.2 m^2), its added mass (ca 0.5), heaved at end b (1 m, period 2 s) for
   !> 0.5 s, Newton to 1e-12, the ledger on.
   function heave_config(nodes, model) result(c)
      integer, intent(in) :: nodes
      character(*), intent(in) :: model
      type(case_config) :: c
      c = body_config(nodes, 2)
      c%model = model
      c%segments(1)%bending_stiffness = 200
      c%points(1)%cd = 0.8_dp
      c%points(1)%area = 1.2_dp
      c%points(1)%ca = 0.5_dp
      c%cd_normal = 1.2_dp
      c%cd_tangential = 0.01_dp
      c%ca_normal = 1
      c%current_x = 0.3_dp
      c%end_b%kind = 'motion'
      c%end_b%motion = 'harmonic'
      c%end_b%amplitude = 1
      c%end_b%period = 2
      c%end_b%direction_x = 0
      c%end_b%direction_z = 1
      c%t_end = 0.5_dp
      c%interval = 0
      c%energy = .true.
      c%newton_tol = 1.0e-12_dp
      c%given = c%given//' segment_1%bending_stiffness point_1%cd point_1%area point_1%ca'
   end function heave_config

   !> The heaved buoy case turned about the vertical through end a by 30 degrees (the current
   !> turned with it), model = '3d', against the planar run: the static state and the state after
   !> 0.5 s, positions (turned back, and off the plane) over the largest coordinate, on the same
   !> step.
   subroutine test_3d_turned(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angle = acos(-1.0_dp)/6
      type(simulation) :: sim2, sim3
      type(case_config) :: c
      real(dp) :: dr_static, dr_end, dt2, dt3
      integer :: k_steps
      call sim2%prepare(heave_config(101, '2d'), error)
      if (allocated(error)) return
      c = heave_config(101, '3d')
      c%end_b%x = end_b(1)*cos(angle)
      c%end_b%y = end_b(1)*sin(angle)
      c%current_x = 0.3_dp*cos(angle)
      c%current_y = 0.3_dp*sin(angle)
      c%given = c%given//' end_b%y fluid%current_y'
      call sim3%prepare(c, error)
      if (allocated(error)) return
      call check(error, allocated(sim3%rod3%pieces(1)%run%problem%piece%points), 'the 3-D piece has no body')
      if (allocated(error)) return
      dr_static = difference(sim2%rod%static%r, sim3%rod3%pieces(1)%run%x)
      call sim2%time_step(dt2, k_steps)
      call sim3%time_step(dt3, k_steps)
      call sim2%run(error=error)
      if (allocated(error)) return
      call sim3%run(error=error)
      if (allocated(error)) return
      dr_end = difference(sim2%rod%pieces(1)%r, sim3%rod3%pieces(1)%run%x)
      write (output_unit, '(4x,a,2es9.2)') 'buoy turned by 30 degrees in 3-D against 2-D: static and after 0.5 s '// &
         'positions', dr_static, dr_end
      call check(error, abs(dt3 - dt2) <= 1.0e-12_dp*dt2, 'the turned 3-D run takes another step')
      if (allocated(error)) return
      ! Measured 1.7e-16 and 1.8e-13.
      call check(error, max(dr_static, dr_end) < 5.0e-13_dp, 'the turned 3-D run with a buoy differs from the '// &
                 'planar one: static '//str(dr_static)//', after 0.5 s '//str(dr_end))
   contains
      real(dp) function difference(r2, x3)
         real(dp), intent(in) :: r2(:, :), x3(:)
         real(dp) :: p(3)
         integer :: k
         difference = 0
         do k = 1, size(r2, 2)
            p = x3(3*k - 2:3*k)
            difference = max(difference, abs(cos(angle)*p(1) + sin(angle)*p(2) - r2(1, k)), &
                             abs(-sin(angle)*p(1) + cos(angle)*p(2)), abs(p(3) - r2(2, k)))
         end do
         difference = difference/maxval(abs(r2))
      end function difference
   end subroutine test_3d_turned

   !> The heaved buoy case for 2 s, in 2-D and in 3-D: the ledger (with the buoy's kinetic
   !> energy with its added mass, its weight less buoyancy in the potential, its drag's work with
   !> the loads') closes to 1e-11 of the largest energy.
   subroutine test_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=2), parameter :: models(2) = ['2d', '3d']
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: drift
      integer :: m, n
      do m = 1, 2
         c = heave_config(121, models(m))
         c%t_end = 2
         c%courant = 2
         c%newton_tol = 1.0e-11_dp
         call sim%prepare(c, error)
         if (allocated(error)) return
         call sim%run(error=error)
         if (allocated(error)) return
         associate (en => sim%rod%history%energy)
            n = sim%rod%history%n
            drift = maxval(abs(en(7, 0:n) - en(7, 0)))/maxval(abs(en(1:4, 0:n)))
         end associate
         write (output_unit, '(4x,a,a,a,es9.2,a)') 'buoy in a current, ', models(m), ': ledger drift', drift, &
            ' of the largest energy'
         ! Measured 1.4e-12 (2-D), 1.6e-12 (3-D).
         call check(error, drift < 1.0e-11_dp, models(m)//': the ledger with a buoy drifts by '//str(drift))
         if (allocated(error)) return
      end do
   end subroutine test_ledger

   !> The Jacobians of the step (and of the statics) with the buoy's drag in the current and its
   !> added mass, after 20 ms of a stirred motion, at a perturbed state, against central
   !> differences: the planar rod and the 3-D rod turned out of the x-z plane.
   subroutine test_jacobians(error)
      use xcable_fdcheck, only: check_jacobian
      use xcable_model_rod, only: rod_kl, rod_ku
      use xcable_model_rod3d, only: rod3d_kl, rod3d_ku
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angle = acos(-1.0_dp)/6
      type(simulation) :: sim
      type(case_config) :: c
      real(dp), allocatable :: x(:)
      real(dp) :: worst2, worst3, worst3s
      integer :: k, np
      c = heave_config(41, '2d')
      c%dt = 1.0e-3_dp
      c%t_end = 0.02_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      np = size(sim%rod%pieces(1)%v, 2)
      do k = 2, np - 1
         sim%rod%pieces(1)%v(:, k) = sim%rod%pieces(1)%v(:, k) + 0.3_dp*[sin(1.7_dp*k), cos(2.3_dp*k)]
      end do
      call sim%run(error=error)
      if (allocated(error)) return
      associate (run => sim%rod%pieces(1))
         run%problem%t0 = sim%rod%t
         run%problem%dt = c%dt
         run%problem%theta = c%theta
         call run%problem%piece%prepare_step(run%r, run%v)
         x = reshape(run%r + c%dt*run%v, [2*np])
         do k = 1, size(x)
            x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
         end do
         ! Measured 2.5e-9 (2-D step), 2.5e-9 (3-D step), 3.2e-9 (3-D statics) of the row scale.
         call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-8_dp, worst2, error)
         if (allocated(error)) then
            error%message = '2-D step: '//error%message
            return
         end if
      end associate
      c = heave_config(41, '3d')
      c%end_b%x = end_b(1)*cos(angle)
      c%end_b%y = end_b(1)*sin(angle)
      c%current_y = 0.2_dp
      c%given = c%given//' end_b%y fluid%current_y'
      c%dt = 1.0e-3_dp
      c%t_end = 0.02_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      associate (run => sim%rod3%pieces(1)%run)
         np = run%problem%piece%n
         do k = 2, np - 1
            run%v(:, k) = run%v(:, k) + 0.3_dp*[sin(1.7_dp*k), cos(2.3_dp*k), sin(0.9_dp*k)]
         end do
      end associate
      call sim%run(error=error)
      if (allocated(error)) return
      associate (run => sim%rod3%pieces(1)%run)
         run%problem%t0 = run%t
         run%problem%dt = c%dt
         run%problem%theta = c%theta
         call run%problem%piece%prepare_step(reshape(run%x(1:3*np), [3, np]), run%v)
         x = run%x
         x(1:3*np) = x(1:3*np) + c%dt*reshape(run%v, [3*np])
         do k = 1, size(x)
            x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
         end do
         call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-8_dp, worst3, error)
         if (allocated(error)) then
            error%message = '3-D step: '//error%message
            return
         end if
         run%problem%dt = 0
         call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-8_dp, worst3s, error)
         if (allocated(error)) then
            error%message = '3-D statics: '//error%message
            return
         end if
      end associate
      write (output_unit, '(4x,a,3es9.2,a)') 'buoy with drag: Jacobian deviations', worst2, worst3, worst3s, &
         ' (2-D step, 3-D step, 3-D statics) of the row scale'
   end subroutine test_jacobians

   !> A body at the free end b of a line hanging from end a at the origin, in 2-D and in 3-D:
   !> case 1 a uniform line (200 m, 0.01 m^2 at 8000 kg/m^3, linear EA 5e8 N) in air with a clump
   !> of 300 kg, hanging straight down; case 2 the chain and rope line in sea water (the rope
   !> 1100 kg/m^3) with a buoy of 1000 kg displacing 5 m^3 (40.2 kN up, more than the line's 34.8
   !> kN wet weight), standing straight up. The tension is the body's net weight plus (minus) the
   !> line's below (above), T(s) = |W_p + w_>(s)|, and the height z(s) = -+ (s + int_0^s T / EA);
   !> a linear tension in each cell makes the rod exact up to round-off: positions to 1e-12 of L,
   !> tensions to 1e-9 of the largest.
   subroutine test_free_end(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=2), parameter :: models(2) = ['2d', '3d']
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w(2), len(2), ea(2), wp, sgn, err_r, err_t, t_max, z_exact, t_exact, sm, x_node(3)
      integer :: case, m, k, n, j
      do case = 1, 2
         do m = 1, 2
            if (case == 1) then
               c = statics_config(101)
               c%law = 'linear'
               c%ea = seg_ea(1)
               c%area = seg_area(1)
               c%density = 8000
               c%length = 200
               c%bending_stiffness = 1
               c%given = 'point_1%joint point_1%mass'
               c%point_count = 1
               c%points(1)%joint = 1
               c%points(1)%mass = 300
               len = [200.0_dp, 0.0_dp]
               w = [8000*seg_area(1)*g, 0.0_dp]
               ea = [seg_ea(1), 1.0_dp]
               wp = 300*g
               sgn = -1
            else
               c = chain_rope_config(101)
               c%segments(2)%density = 1100
               c%fluid_density = 1025
               c%surface_z = 400
               c%point_count = 1
               c%points(1)%joint = 2
               c%points(1)%mass = 1000
               c%points(1)%volume = 5
               c%given = 'segment_1%length segment_1%area segment_1%density segment_1%ea segment_2%length '// &
                         'segment_2%area segment_2%density segment_2%ea point_1%joint point_1%mass point_1%volume'
               len = seg_length
               w = ([8000, 1100] - 1025)*seg_area*g
               ea = seg_ea
               wp = (1000 - 1025*5.0_dp)*g
               sgn = 1
            end if
            c%model = models(m)
            c%end_b%kind = 'free'
            call sim%prepare(c, error)
            if (allocated(error)) return
            n = size(sim%rod%s)
            err_r = 0
            err_t = 0
            t_max = abs(wp + sum(w*len))
            do k = 1, n
               if (m == 1) then
                  x_node = [sim%rod%static%r(1, k), 0.0_dp, sim%rod%static%r(2, k)]
               else
                  x_node = sim%rod3%pieces(1)%run%x(3*k - 2:3*k)
               end if
               ! z(s): s plus the stretch int_0^s T / EA, T linear in each segment.
               z_exact = 0
               do j = 1, 2
                  sm = min(sim%rod%s(k), sum(len(1:j))) - sum(len(1:j - 1))
                  if (sm <= 0) cycle
                  z_exact = z_exact + sm + sm*0.5_dp*(tension_at(sum(len(1:j - 1))) + &
                                                     tension_at(sum(len(1:j - 1)) + sm))/ea(j)
               end do
               err_r = max(err_r, abs(x_node(3) - sgn*z_exact), abs(x_node(1)), abs(x_node(2)))
            end do
            do k = 1, n - 1
               sm = 0.5_dp*(sim%rod%s(k) + sim%rod%s(k + 1))
               t_exact = tension_at(sm)
               if (m == 1) then
                  associate (r => sim%rod%static%r, piece => sim%rod%pieces(1)%problem%piece)
                     err_t = max(err_t, abs(piece%cell_tension(k, norm2(r(:, k + 1) - r(:, k))/piece%ds(k) - 1) - &
                                            t_exact))
                  end associate
               else
                  associate (x => sim%rod3%pieces(1)%run%x, piece => sim%rod3%pieces(1)%run%problem%piece)
                     err_t = max(err_t, abs(piece%cell_tension(k, norm2(x(3*k + 1:3*k + 3) - x(3*k - 2:3*k))/ &
                                                               piece%ds(k) - 1) - t_exact))
                  end associate
               end if
            end do
            err_r = err_r/sum(len)
            err_t = err_t/t_max
            write (output_unit, '(4x,a,i2,a,a,a,es9.2,a,es9.2,a)') 'body at a free end, case', case, ', ', models(m), &
               ': positions', err_r, ' of L, tensions', err_t, ' of the largest'
            call check(error, err_r < 1.0e-12_dp .and. err_t < 1.0e-9_dp, 'a body at a free end (case '//str(case)// &
                       ', '//models(m)//'): positions '//str(err_r)//' of L, tensions '//str(err_t)//' of the largest')
            if (allocated(error)) return
         end do
      end do
   contains
      !> |W_p + the line's weight from s to its end b|, N.
      real(dp) function tension_at(s)
         real(dp), intent(in) :: s
         tension_at = abs(wp + w(1)*max(len(1) - s, 0.0_dp) + w(2)*max(len(1) + len(2) - max(s, len(1)), 0.0_dp))
         if (len(2) == 0) tension_at = abs(wp + w(1)*(len(1) - s))
      end function tension_at
   end subroutine test_free_end

   !> A surface buoy: 49.5 m of rope (0.005 m^2 at 1100 kg/m^3 in sea water, 3.68 N/m wet;
   !> linear, EA 1e7 N) from an anchor 50 m deep (end a) to a free end b with a buoy of 200 kg
   !> displacing 2 m^3 (the sphere of radius 0.78 m), the surface at z = 0: the buoy floats with
   !> its centre z_b where z_b + 50 - L = (L (B(z_b) - m g) - w L^2 / 2) / EA, B the buoyancy of
   !> the wetted cap; solved here by bisection. The rod's end b and its tension at end b (B - m g)
   !> in 2-D and 3-D to 1e-9; then the Jacobians of the statics and of a step at that state
   !> (the buoyancy's derivative in the cap) against central differences.
   subroutine test_surface_buoy(error)
      use xcable_fdcheck, only: check_jacobian
      use xcable_model_rod, only: rod_kl, rod_ku
      use xcable_model_rod3d, only: rod3d_kl, rod3d_ku
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp), length = 49.5_dp, ea = 1.0e7_dp, vol = 2, mass = 200, &
                             w = (1100 - 1025)*0.005_dp*g
      character(len=2), parameter :: models(2) = ['2d', '3d']
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: lo, hi, zb, tb, err_z, err_t, z_rod, t_rod, worst, worst_s
      real(dp), allocatable :: x(:)
      integer :: m, n, it, k, np
      lo = -5
      hi = 1
      do it = 1, 200
         zb = 0.5_dp*(lo + hi)
         if (zb + 50 - length - (length*(buoyancy(zb) - mass*g) - 0.5_dp*w*length**2)/ea > 0) then
            hi = zb
         else
            lo = zb
         end if
      end do
      tb = buoyancy(zb) - mass*g
      do m = 1, 2
         c = statics_config(51)
         c%law = 'linear'
         c%ea = ea
         c%area = 0.005_dp
         c%density = 1100
         c%length = length
         c%bending_stiffness = 1
         c%fluid_density = 1025
         c%surface_z = 0
         c%end_a%z = -50
         c%end_b%kind = 'free'
         c%point_count = 1
         c%points(1)%joint = 1
         c%points(1)%mass = mass
         c%points(1)%volume = vol
         c%model = models(m)
         c%given = 'end_a%z point_1%joint point_1%mass point_1%volume fluid%surface_z'
         call sim%prepare(c, error)
         if (allocated(error)) return
         n = size(sim%rod%s)
         if (m == 1) then
            associate (r => sim%rod%static%r, piece => sim%rod%pieces(1)%problem%piece)
               z_rod = r(2, n)
               t_rod = piece%cell_tension(n - 1, norm2(r(:, n) - r(:, n - 1))/piece%ds(n - 1) - 1)
            end associate
         else
            associate (xx => sim%rod3%pieces(1)%run%x, piece => sim%rod3%pieces(1)%run%problem%piece)
               z_rod = xx(3*n)
               t_rod = piece%cell_tension(n - 1, norm2(xx(3*n - 2:3*n) - xx(3*n - 5:3*n - 3))/piece%ds(n - 1) - 1)
            end associate
         end if
         ! The last cell's tension at its middle: half a cell's wet weight below the end's.
         err_z = abs(z_rod - zb)
         err_t = abs(t_rod - (tb - 0.5_dp*w*length/(n - 1)))/tb
         write (output_unit, '(4x,a,a,a,f9.5,a,f10.2,a,es9.2,a,es9.2)') 'surface buoy, ', models(m), ': centre at z =', &
            zb, ' m, tension', tb, ' N; rod off by', err_z, ' m and', err_t
         ! Measured: 2.0e-13 m and 4.1e-13 (2-D), likewise in 3-D.
         call check(error, err_z < 1.0e-9_dp .and. err_t < 1.0e-9_dp, models(m)//': the surface buoy floats at '// &
                    str(z_rod)//' m with '//str(t_rod)//' N, not at '//str(zb)//' m with '//str(tb)//' N')
         if (allocated(error)) return
         ! The Jacobians at a perturbed state near the static one, in the cap.
         c%dt = 2.0e-3_dp
         c%t_end = 2.0e-3_dp
         c%interval = 0
         call sim%prepare(c, error)
         if (allocated(error)) return
         if (m == 1) then
            associate (run => sim%rod%pieces(1))
               np = size(run%v, 2)
               run%problem%t0 = 0
               run%problem%dt = c%dt
               run%problem%theta = c%theta
               run%v(1, :) = 0.2_dp
               run%v(2, :) = 0.5_dp
               call run%problem%piece%prepare_step(sim%rod%static%r, run%v)
               x = reshape(sim%rod%static%r + c%dt*run%v, [2*np])
               do k = 1, size(x)
                  x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
               end do
               call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-8_dp, worst, error)
               if (allocated(error)) return
               run%problem%dt = 0
               call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-8_dp, worst_s, &
                                   error)
               if (allocated(error)) return
            end associate
         else
            associate (run => sim%rod3%pieces(1)%run)
               np = run%problem%piece%n
               run%problem%t0 = 0
               run%problem%dt = c%dt
               run%problem%theta = c%theta
               run%v(1, :) = 0.2_dp
               run%v(2, :) = 0.1_dp
               run%v(3, :) = 0.5_dp
               call run%problem%piece%prepare_step(reshape(run%x(1:3*np), [3, np]), run%v)
               x = run%x
               x(1:3*np) = x(1:3*np) + c%dt*reshape(run%v, [3*np])
               do k = 1, size(x)
                  x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
               end do
               call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-8_dp, worst, &
                                   error)
               if (allocated(error)) return
               run%problem%dt = 0
               call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-8_dp, &
                                   worst_s, error)
               if (allocated(error)) return
            end associate
         end if
         write (output_unit, '(4x,a,a,a,2es9.2,a)') 'surface buoy, ', models(m), ': Jacobian deviations', worst, &
            worst_s, ' (step, statics) of the row scale'
      end do
   contains
      !> rho g V times the wetted share of the sphere of volume V centred at z (surface z = 0).
      real(dp) function buoyancy(z)
         real(dp), intent(in) :: z
         real(dp) :: r, h
         r = (3*vol/(4*pi))**(1.0_dp/3)
         h = min(max(0 - (z - r), 0.0_dp), 2*r)
         buoyancy = 1025*g*vol*h**2*(3*r - h)/(4*r**3)
      end function buoyancy
   end subroutine test_surface_buoy

   !> The clump case with the line parting at its joint (by time, at s = 50 m, after 10 ms), in
   !> 2-D and 3-D: the two pieces' node weights add up to the line's weight and the clump's once
   !> (the clump stays with the piece on end a's side).
   subroutine test_break_at_body(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=2), parameter :: models(2) = ['2d', '3d']
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: w(2), wp, total, expected
      integer :: m, p
      call case_weights(1, w, wp)
      expected = sum(w*seg_length) + wp
      do m = 1, 2
         c = body_config(101, 1)
         c%model = models(m)
         c%break_enabled = .true.
         c%s_break = seg_length(1)
         c%break_time = 0.01_dp
         c%t_end = 0.02_dp
         c%interval = 0
         c%given = c%given//' rupture%s_break rupture%break_time'
         call sim%prepare(c, error)
         if (allocated(error)) return
         call sim%run(error=error)
         if (allocated(error)) return
         total = 0
         if (m == 1) then
            call check(error, size(sim%rod%pieces) == 2, 'the line did not part')
            if (allocated(error)) return
            do p = 1, 2
               total = total + sum(sim%rod%pieces(p)%problem%piece%node_w)
            end do
         else
            call check(error, size(sim%rod3%pieces) == 2, 'the 3-D line did not part')
            if (allocated(error)) return
            do p = 1, 2
               total = total + sum(sim%rod3%pieces(p)%run%problem%piece%node_w)
            end do
         end if
         write (output_unit, '(4x,a,a,a,f12.4,a,f12.4,a)') 'parted at the clump, ', models(m), ': node weights', &
            total, ' N, line and clump', expected, ' N'
         call check(error, abs(total - expected) < 1.0e-9_dp*expected, models(m)//': the pieces weigh '//str(total)// &
                    ' N, the line with its clump '//str(expected)//' N')
         if (allocated(error)) return
      end do
   end subroutine test_break_at_body

   !> Bad &point_k input: each refused with exit code 2 by the reader, naming the group and the
   !> variable.
   subroutine test_bad_input(error)
      use xcable_io_input, only: read_config
      use xcable_core_error, only: stat_input
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: line = "&segment_1 length = 50.0 / &segment_2 length = 150.0 / "
      character(len=200) :: cases(7), expect(7)
      type(case_config) :: c
      type(error_type), allocatable :: err
      integer :: i, unit
      character(len=*), parameter :: path = 'build/suite_points_bad.nml'
      cases(1) = line//"&point_1 mass = 10.0 /"
      expect(1) = '&point_1: joint not given'
      cases(2) = line//"&point_1 joint = 3, mass = 10.0 /"
      expect(2) = '&point_1: joint = 3: the line has 2 segment(s); allowed: 0 .. 2'
      cases(3) = "&point_1 joint = 1, mass = 10.0 /"
      expect(3) = "that is end b, which is held (kind 'fixed')"
      cases(4) = line//"&point_2 joint = 1, mass = 10.0 /"
      expect(4) = '&point_2 given without &point_1'
      cases(5) = line//"&point_1 joint = 1, mass = -10.0 /"
      expect(5) = 'mass'
      cases(6) = line//"&point_1 joint = 1, volume = 1.0 /"
      expect(6) = 'buoyancy needs water'
      cases(7) = line//"&point_1 joint = 1, mass = 5.0 / &point_2 joint = 1, mass = 5.0 /"
      expect(7) = '&point_1 sits on it already'
      do i = 1, size(cases)
         open (newunit=unit, file=path, status='replace', action='write')
         write (unit, '(a)') "&cable length = 200.0 / &end_a kind = 'fixed', x = 0.0, z = 0.0 / "// &
            "&end_b kind = 'fixed', x = 170.0, z = 90.0 / "//trim(cases(i))
         close (unit)
         call read_config(path, c, err)
         call check(error, allocated(err), 'case '//str(i)//' not refused: '//trim(cases(i)))
         if (allocated(error)) return
         call check(error, err%stat == stat_input .and. index(err%message, trim(expect(i))) > 0, 'case '//str(i)// &
                    ': the message does not say "'//trim(expect(i))//'": '//err%message)
         if (allocated(error)) return
         deallocate (err)
      end do
      open (newunit=unit, file=path, status='old')
      close (unit, status='delete')
   end subroutine test_bad_input
end module suite_points
