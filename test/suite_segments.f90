!> Lines made of segments (issue "Moorings"): a heavy stiff segment and a light soft one
!> hanging between two points against the elastic catenary of each segment in closed form
!> (its own formulas here, not the code's quadrature), with the order of convergence; a
!> uniform line cut into segments that are all alike is the uniform line; the energy ledger
!> of a line whose middle segment cannot push, released into slack; and the break by
!> tension at the segment whose MBL is reached first, not where the tension is largest.
module suite_segments
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_driver_simulation, only: simulation
   use suite_rod_statics, only: statics_config
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_segments, chain_rope_config

   !> The two segments of the hanging line: lengths (m), weights (N/m) and EA (N).
   real(dp), parameter :: seg_length(2) = [50.0_dp, 150.0_dp], seg_weight(2) = [8000*0.01_dp*9.81_dp, &
                                                                                  1000*0.005_dp*9.81_dp], &
                          seg_ea(2) = [5.0e8_dp, 2.0e7_dp], end_b(2) = [170.0_dp, 90.0_dp]

contains

   subroutine collect_segments(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('chain_and_rope_catenary_closed_form', test_closed_form), &
               new_unittest('alike_segments_are_the_uniform_line', test_alike), &
               new_unittest('ledger_with_a_segment_that_cannot_push', test_ledger), &
               new_unittest('break_at_the_segment_that_reaches_its_mbl', test_mbl), &
               new_unittest('model_3d_planar_segments_equal_2d', test_3d_planar), &
               new_unittest('model_3d_segments_turned_equal_2d', test_3d_turned), &
               new_unittest('model_3d_ledger_with_a_segment_that_cannot_push', test_3d_ledger), &
               new_unittest('model_3d_segments_jacobians', test_3d_jacobian), &
               new_unittest('model_3d_break_at_the_segment_mbl_equals_2d', test_3d_mbl), &
               new_unittest('model_3d_static_friction_on_segments_equals_2d', test_3d_friction)]
   end subroutine collect_segments

   !> 50 m of a heavy stiff segment (area 0.01 m^2, 8000 kg/m^3: 784.8 N/m, EA 5e8 N) from end
   !> a at the origin, then 150 m of a light soft one (0.005 m^2, 1000 kg/m^3: 49.05 N/m, EA
   !> 2e7 N) to end b at (170, 90) m, in air, linear laws, EI 1 N m^2 (a bending boundary
   !> layer of a centimetre).
   function chain_rope_config(nodes) result(c)
      integer, intent(in) :: nodes
      type(case_config) :: c
      c = statics_config(nodes)
      c%law = 'linear'
      c%bending_stiffness = 1
      c%model = '2d'
      c%end_b%x = end_b(1)
      c%end_b%z = end_b(2)
      c%segment_count = 2
      c%segments(1:2)%length = seg_length
      c%segments(1)%area = 0.01_dp
      c%segments(1)%density = 8000
      c%segments(1)%ea = seg_ea(1)
      c%segments(2)%area = 0.005_dp
      c%segments(2)%density = 1000
      c%segments(2)%ea = seg_ea(2)
      c%length = sum(seg_length)
      c%given = 'end_b%x end_b%z segment_1%length segment_1%area segment_1%density segment_1%ea '// &
                'segment_2%length segment_2%area segment_2%density segment_2%ea'
   end function chain_rope_config

   !> The elastic catenary of the two segments: with the internal force N(s) = (H, V0 + W(s)),
   !> W(s) the weight of the line up to s, each segment from its start s0 adds
   !>   x: H (s - s0) / EA + H / w (asinh(V / H) - asinh(V_0 / H)),
   !>   z: (V_0 (s - s0) + w (s - s0)^2 / 2) / EA + H / w (sqrt(1 + (V / H)^2) - sqrt(1 + (V_0 / H)^2)),
   !> V_0 and V the vertical force at s0 and s. (H, V0) by Newton on the end point.
   subroutine exact_catenary(h, v0)
      real(dp), intent(out) :: h, v0
      real(dp) :: y(2), r(2), jac(2, 2), dy(2), rp(2), rm(2), det, step(2)
      integer :: it, j, ls
      y = [0.5_dp*sum(seg_weight*seg_length), -0.2_dp*sum(seg_weight*seg_length)]
      do it = 1, 100
         r = point_at(y, sum(seg_length)) - end_b
         if (norm2(r) < 1.0e-11_dp) exit
         do j = 1, 2
            dy = 0
            dy(j) = 1.0e-6_dp*max(1.0_dp, abs(y(j)))
            rp = point_at(y + dy, sum(seg_length))
            rm = point_at(y - dy, sum(seg_length))
            jac(:, j) = (rp - rm)/(2*dy(j))
         end do
         det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
         step = [jac(2, 2)*r(1) - jac(1, 2)*r(2), -jac(2, 1)*r(1) + jac(1, 1)*r(2)]/det
         do ls = 1, 30
            if (y(1) - step(1) > 0) then
               if (norm2(point_at(y - step, sum(seg_length)) - end_b) < norm2(r)) exit
            end if
            step = 0.5_dp*step
         end do
         y = y - step
      end do
      h = y(1)
      v0 = y(2)
   end subroutine exact_catenary

   !> Position at arc length s of the exact catenary with (H, V0) = y.
   function point_at(y, s) result(p)
      real(dp), intent(in) :: y(2), s
      real(dp) :: p(2), s0, va, vb, ds
      integer :: j
      p = 0
      s0 = 0
      va = y(2)
      do j = 1, 2
         ds = min(s, s0 + seg_length(j)) - s0
         if (ds <= 0) exit
         vb = va + seg_weight(j)*ds
         p(1) = p(1) + y(1)*ds/seg_ea(j) + y(1)/seg_weight(j)*(asinh(vb/y(1)) - asinh(va/y(1)))
         p(2) = p(2) + (va*ds + 0.5_dp*seg_weight(j)*ds**2)/seg_ea(j) + &
                y(1)/seg_weight(j)*(sqrt(1 + (vb/y(1))**2) - sqrt(1 + (va/y(1))**2))
         s0 = s0 + seg_length(j)
         va = va + seg_weight(j)*seg_length(j)
      end do
   end function point_at

   !> The rod's statics on 101, 201 and 401 nodes against the exact catenary: the joint's
   !> position and the largest error of the nodes' positions (over the line's length), and of
   !> the cells' tensions at their middles (over the largest tension); second order.
   subroutine test_closed_form(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: ladder(3) = [101, 201, 401]
      type(simulation) :: sim
      real(dp) :: h, v0, err_r(3), err_t(3), err_joint(3), t_max, sm, t_exact
      integer :: i, k, n, kj
      call exact_catenary(h, v0)
      t_max = max(norm2([h, v0]), norm2([h, v0 + sum(seg_weight*seg_length)]))
      do i = 1, 3
         call sim%prepare(chain_rope_config(ladder(i)), error)
         if (allocated(error)) return
         associate (r => sim%rod%static%r, s => sim%rod%s, piece => sim%rod%pieces(1)%problem%piece)
            n = size(s)
            err_r(i) = 0
            err_t(i) = 0
            kj = 0
            do k = 1, n
               err_r(i) = max(err_r(i), norm2(r(:, k) - point_at([h, v0], s(k))))
               if (abs(s(k) - seg_length(1)) < 1.0e-9_dp) kj = k
            end do
            call check(error, kj > 0, 'no node on the joint at s = 50 m')
            if (allocated(error)) return
            err_joint(i) = norm2(r(:, kj) - point_at([h, v0], s(kj)))
            do k = 1, n - 1
               sm = 0.5_dp*(s(k) + s(k + 1))
               t_exact = norm2([h, v0 + seg_weight(1)*min(sm, seg_length(1)) + &
                                seg_weight(2)*max(sm - seg_length(1), 0.0_dp)])
               err_t(i) = max(err_t(i), abs(piece%cell_tension(k, norm2(r(:, k + 1) - r(:, k))/piece%ds(k) - 1) - &
                                            t_exact))
            end do
            err_t(i) = err_t(i)/t_max
            err_r(i) = err_r(i)/sum(seg_length)
         end associate
         write (output_unit, '(4x,a,i4,a,es9.2,a,es9.2,a,es9.2,a)') 'chain and rope, ', ladder(i), &
            ' nodes: positions', err_r(i), ' of L, joint', err_joint(i), ' m, tensions', err_t(i), ' of the largest'
      end do
      write (output_unit, '(4x,a,f5.2,a,f5.2)') 'observed order: positions ', log(err_r(2)/err_r(3))/log(2.0_dp), &
         ', tensions ', log(err_t(2)/err_t(3))/log(2.0_dp)
      call check(error, err_r(3) < 3.0e-6_dp .and. err_t(3) < 2.5e-5_dp, 'the line of segments is off its closed '// &
                 'form: positions '//str(err_r(3))//' of L, tensions '//str(err_t(3))//' of the largest')
      if (allocated(error)) return
      call check(error, err_r(2)/err_r(3) > 3.0_dp .and. err_t(2)/err_t(3) > 1.8_dp, 'no second order: '// &
                 'positions '//str(err_r(2)/err_r(3))//', tensions '//str(err_t(2)/err_t(3))//' from 201 to 401 nodes')
   end subroutine test_closed_form

   !> A line of three segments with the line's own values (the paper's tanh rope, 60 m cut into
   !> 15, 25 and 20 m, the nodes on the joints of the uniform grid) is the uniform line: the
   !> static state and 0.05 s of a heave at end b to round-off.
   subroutine test_alike(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: one, three
      type(case_config) :: c
      real(dp) :: dr_static, dr_end, scale
      c = statics_config(61)
      c%end_b%x = 50
      c%end_b%z = 5
      c%end_b%kind = 'motion'
      c%end_b%amplitude = 0.5_dp
      c%end_b%period = 0.2_dp
      c%t_end = 0.05_dp
      c%interval = 0
      c%given = 'end_b%x end_b%z'
      call one%prepare(c, error)
      if (allocated(error)) return
      call one%run(error=error)
      if (allocated(error)) return
      c%segment_count = 3
      c%segments(1:3)%length = [15.0_dp, 25.0_dp, 20.0_dp]
      c%given = c%given//' segment_1%length segment_2%length segment_3%length'
      call three%prepare(c, error)
      if (allocated(error)) return
      call check(error, allocated(three%rod%pieces(1)%problem%piece%sections), 'the line of three segments has '// &
                 'no sections')
      if (allocated(error)) return
      call check(error, all(abs(three%rod%s - one%rod%s) <= 1.0e-12_dp*60), 'the grids differ')
      if (allocated(error)) return
      scale = maxval(abs(one%rod%static%r))
      dr_static = maxval(abs(three%rod%static%r - one%rod%static%r))/scale
      call three%run(error=error)
      if (allocated(error)) return
      dr_end = maxval(abs(three%rod%pieces(1)%r - one%rod%pieces(1)%r))/scale
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'three alike segments against the uniform line: static state', &
         dr_static, ', after 0.05 s', dr_end, ' of the largest coordinate'
      call check(error, dr_static < 1.0e-12_dp .and. dr_end < 1.0e-10_dp, 'three alike segments are not the '// &
                 'uniform line: '//str(dr_static)//' (statics), '//str(dr_end)//' (after 0.05 s)')
   end subroutine test_alike

   !> The chain and rope line with a third segment between them that cannot push (a linear
   !> rope of EA 2e6 N, damping 2e4 N s): end b pulled 1 m towards end a and back over 2 s, so
   !> that the middle goes slack and snaps taut again. The ledger closes to 1e-8 of the
   !> largest energy, and the damping dissipates.
   subroutine test_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: drift, dissipated
      integer :: n
      c = chain_rope_config(121)
      c%segment_count = 3
      c%segments(3) = c%segments(2)
      c%segments(2)%length = 30
      c%segments(3)%length = 120
      c%segments(2)%ea = 2.0e6_dp
      c%segments(2)%compression = 'none'
      c%segments(2)%damping = 2.0e4_dp
      c%given = c%given//' segment_2%compression segment_2%damping segment_3%length segment_3%area '// &
                'segment_3%density segment_3%ea'
      c%end_b%kind = 'motion'
      c%end_b%amplitude = 1
      c%end_b%period = 2
      c%end_b%direction_x = -1
      c%end_b%direction_z = 0
      c%t_end = 2
      c%courant = 2
      c%interval = 0
      c%energy = .true.
      c%newton_tol = 1.0e-11_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(error=error)
      if (allocated(error)) return
      associate (en => sim%rod%history%energy)
         n = sim%rod%history%n
         drift = maxval(abs(en(7, 0:n) - en(7, 0)))/maxval(abs(en(1:4, 0:n)))
         dissipated = en(6, n)
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2)') 'three segments, the middle one slack: ledger drift', &
         drift, ' of the largest energy; dissipated', dissipated, ' J; smallest strain', sim%rod%summary%min_strain
      call check(error, drift < 1.0e-8_dp, 'the ledger of the line of segments drifts by '//str(drift))
      if (allocated(error)) return
      call check(error, dissipated > 0, 'the damping of the middle segment dissipated nothing')
   end subroutine test_ledger

   !> The chain and rope line with end b pulled 3 m along the chord (harmonic, period 8 s): the
   !> tension is largest at end b, in the rope. The line parts in the segment whose tension
   !> first reaches that segment's own MBL (&segment_k mbl, or &rupture mbl where it gives
   !> none), not where the tension is largest.
   subroutine test_mbl(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: s_break(2)
      integer :: i
      do i = 1, 2
         c = chain_rope_config(101)
         c%end_b%kind = 'motion'
         c%end_b%motion = 'harmonic'
         c%end_b%amplitude = 3
         c%end_b%period = 8
         c%end_b%direction_x = end_b(1)/norm2(end_b)
         c%end_b%direction_z = end_b(2)/norm2(end_b)
         c%break_enabled = .true.
         c%break_criterion = 'tension'
         c%t_end = 2
         c%interval = 0
         ! Case 1: the chain's MBL (the line's, 60 kN) is below the rope's peak tension (128 kN at
         ! end b) but the rope's own is far above it: the chain parts, where the rope would have
         ! under one MBL. Case 2: the rope's MBL (100 kN) is the one reached.
         if (i == 1) then
            c%mbl = 6.0e4_dp
            c%segments(2)%mbl = 1.0e7_dp
         else
            c%mbl = 1.0e7_dp
            c%segments(2)%mbl = 1.0e5_dp
         end if
         c%given = c%given//' segment_2%mbl'
         call sim%prepare(c, error)
         if (allocated(error)) return
         call sim%run(error=error)
         if (allocated(error)) return
         s_break(i) = sim%rod%scene%s_break
         write (output_unit, '(4x,a,i0,a,f8.2,a,f7.4,a)') 'segments with MBLs, case ', i, ': the line parts at s =', &
            s_break(i), ' m at t =', sim%rod%scene%break_time, ' s'
      end do
      call check(error, all(s_break > 0), 'no break: '//str(s_break(1))//', '//str(s_break(2))//' m')
      if (allocated(error)) return
      call check(error, s_break(1) < seg_length(1) .and. s_break(2) > seg_length(1), 'the line parted at '// &
                 str(s_break(1))//' and '//str(s_break(2))//' m, not in the chain and in the rope')
   end subroutine test_mbl
   ! ---- The 3-D model on a line of segments (model/rod3d.f90 with sections) ----

   !> The chain and rope line (chain_rope_config, the chain's EI 200 N m^2, the rope's 1) heaved
   !> at end b (1 m, period 2 s, along z) for 0.5 s, Newton to 1e-12, with the ledger; water:
   !> all under water in a current of 0.3 m/s along x, the rope's drag coefficient 2.5, the
   !> chain's 1.2.
   function heave_config(nodes, model, water) result(c)
      integer, intent(in) :: nodes
      character(*), intent(in) :: model
      logical, intent(in) :: water
      type(case_config) :: c
      c = chain_rope_config(nodes)
      c%model = model
      c%segments(1)%bending_stiffness = 200
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
      c%given = c%given//' segment_1%bending_stiffness'
      if (.not. water) return
      c%fluid_density = 1025
      c%cd_normal = 1.2_dp
      c%cd_tangential = 0.01_dp
      c%ca_normal = 1
      c%current_x = 0.3_dp
      c%surface_z = 200
      c%segments(2)%cd_normal = 2.5_dp
      c%given = c%given//' segment_2%cd_normal'
   end function heave_config

   !> How far a 3-D state x3 (4 per node) of a scene turned by angle (rad) about the vertical
   !> through the origin is from the planar state r2 (2, n) of its twin: positions (turned back,
   !> and y off the plane) over the largest coordinate, and the cells' tensions (each cell's
   !> law) over the largest.
   subroutine state_difference(sim2, sim3, r2, x3, angle, dr, dt)
      type(simulation), intent(in) :: sim2, sim3
      real(dp), intent(in) :: r2(:, :), x3(:), angle
      real(dp), intent(out) :: dr, dt
      real(dp) :: p(3), t2, t3, t_max
      integer :: k, c, n
      n = size(r2, 2)
      dr = 0
      dt = 0
      t_max = 0
      associate (piece2 => sim2%rod%pieces(1)%problem%piece, piece3 => sim3%rod3%pieces(1)%run%problem%piece)
         do k = 1, n
            p = x3(3*k - 2:3*k)
            dr = max(dr, abs(cos(angle)*p(1) + sin(angle)*p(2) - r2(1, k)), abs(-sin(angle)*p(1) + cos(angle)*p(2)), &
                     abs(p(3) - r2(2, k)))
         end do
         dr = dr/maxval(abs(r2))
         do c = 1, n - 1
            t2 = piece2%cell_tension(c, norm2(r2(:, c + 1) - r2(:, c))/piece2%ds(c) - 1)
            t3 = piece3%cell_tension(c, norm2(x3(3*c + 1:3*c + 3) - x3(3*c - 2:3*c))/piece3%ds(c) - 1)
            dt = max(dt, abs(t3 - t2))
            t_max = max(t_max, abs(t2))
         end do
         dt = dt/t_max
      end associate
   end subroutine state_difference

   !> The heaved chain and rope line in water (heave_config, 101 nodes; each segment's drag on
   !> its own cells) with model = '3d' is the planar run: the static state and the state after 0.5 s (positions, the cells' tensions), the end
   !> tensions and the energies of the history: positions to 5e-13 of the largest coordinate,
   !> tensions to 3e-9 of the largest (the stiff chain's EA times the positions' round-off),
   !> energies to 3e-12.
   subroutine test_3d_planar(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim2, sim3
      real(dp), allocatable :: x3s(:)
      real(dp) :: dr_static, dt_static, dr_end, dt_end, d_hist, d_energy
      call sim2%prepare(heave_config(101, '2d', .true.), error)
      if (allocated(error)) return
      call sim3%prepare(heave_config(101, '3d', .true.), error)
      if (allocated(error)) return
      call check(error, sim3%model == '3d' .and. allocated(sim3%rod3%pieces(1)%run%problem%piece%sections), &
                 'the 3-D run has no sections (model '//sim3%model//')')
      if (allocated(error)) return
      x3s = sim3%rod3%pieces(1)%run%x
      call state_difference(sim2, sim3, sim2%rod%static%r, x3s, 0.0_dp, dr_static, dt_static)
      call sim2%run(error=error)
      if (allocated(error)) return
      call sim3%run(error=error)
      if (allocated(error)) return
      call state_difference(sim2, sim3, sim2%rod%pieces(1)%r, sim3%rod3%pieces(1)%run%x, 0.0_dp, dr_end, dt_end)
      associate (h2 => sim2%rod%history, h3 => sim3%rod%history)
         call check(error, h2%n == h3%n, 'steps: '//str(h2%n)//' in 2-D, '//str(h3%n)//' in 3-D')
         if (allocated(error)) return
         d_hist = maxval(abs(h2%ends(5, 1:2, 0:h2%n) - h3%ends(5, 1:2, 0:h3%n)))/maxval(abs(h2%ends(5, 1:2, 0:h2%n)))
         d_energy = maxval(abs(h2%energy(1:8, 0:h2%n) - h3%energy(1:8, 0:h3%n)))/maxval(abs(h2%energy(1:4, 0:h2%n)))
      end associate
      write (output_unit, '(4x,a,4es9.2,a,2es9.2)') 'chain and rope in 3-D against 2-D: static and after 0.5 s '// &
         'positions, tensions', dr_static, dt_static, dr_end, dt_end, '; end tensions, energies', d_hist, d_energy
      ! Measured: positions 8.4e-17 and 1.4e-13, tensions 4.9e-11 and 9.0e-10 (EA 5e8 N times the
      ! strain: the positions' round-off, 1e-14 m over a cell of 2 m, gives 2.5e-3 N), end tensions
      ! 4.5e-10, energies 9.5e-13.
      call check(error, max(dr_static, dr_end) < 5.0e-13_dp .and. max(dt_static, dt_end, d_hist) < 3.0e-9_dp .and. &
                 d_energy < 3.0e-12_dp, 'the 3-D run of '// &
                 'the line of segments differs from the planar one: static '//str(dr_static)//', '//str(dt_static)// &
                 '; after 0.5 s '//str(dr_end)//', '//str(dt_end)//'; history '//str(d_hist)//', '//str(d_energy))
   end subroutine test_3d_planar

   !> The heaved chain and rope line turned about the vertical through end a by 30 degrees
   !> (end b at (170 cos 30, 170 sin 30, 90) m, the heave along z), model = '3d', against the
   !> planar run turned: the static state and the state after 0.5 s (positions turned back and
   !> off the plane, the cells' tensions) as test_3d_planar, with the same step.
   subroutine test_3d_turned(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angle = acos(-1.0_dp)/6
      type(simulation) :: sim2, sim3
      type(case_config) :: c
      real(dp), allocatable :: x3s(:)
      real(dp) :: dr_static, dt_static, dr_end, dt_end, dt2, dt3
      integer :: k_steps
      call sim2%prepare(heave_config(101, '2d', .false.), error)
      if (allocated(error)) return
      c = heave_config(101, '3d', .false.)
      c%end_b%x = end_b(1)*cos(angle)
      c%end_b%y = end_b(1)*sin(angle)
      c%given = c%given//' end_b%y'
      call sim3%prepare(c, error)
      if (allocated(error)) return
      x3s = sim3%rod3%pieces(1)%run%x
      call state_difference(sim2, sim3, sim2%rod%static%r, x3s, angle, dr_static, dt_static)
      call sim2%time_step(dt2, k_steps)
      call sim3%time_step(dt3, k_steps)
      call sim2%run(error=error)
      if (allocated(error)) return
      call sim3%run(error=error)
      if (allocated(error)) return
      call state_difference(sim2, sim3, sim2%rod%pieces(1)%r, sim3%rod3%pieces(1)%run%x, angle, dr_end, dt_end)
      write (output_unit, '(4x,a,4es9.2,a,es9.2)') 'chain and rope turned by 30 degrees in 3-D against 2-D: '// &
         'static and after 0.5 s positions, tensions', dr_static, dt_static, dr_end, dt_end, '; steps differ by', &
         abs(dt3 - dt2)/dt2
      call check(error, abs(dt3 - dt2) <= 1.0e-12_dp*dt2 .and. sim3%rod%history%n == sim2%rod%history%n, &
                 'the turned 3-D run takes another step: '//str(dt3)//' s, the planar run '//str(dt2)//' s')
      if (allocated(error)) return
      ! Measured: positions 1.7e-16 and 1.0e-13, tensions 3.1e-11 and 6.2e-10 (see test_3d_planar).
      call check(error, max(dr_static, dr_end) < 5.0e-13_dp .and. max(dt_static, dt_end) < 3.0e-9_dp, &
                 'the turned 3-D run of the line '// &
                 'of segments differs from the planar one: static '//str(dr_static)//', '//str(dt_static)// &
                 '; after 0.5 s '//str(dr_end)//', '//str(dt_end))
   end subroutine test_3d_turned

   !> test_ledger's line (a middle segment that cannot push, damped) in 3-D and out of a plane:
   !> turned by 30 degrees about the vertical, end b pulled 1 m along x and back over 2 s (across
   !> the line's vertical plane, so that it swings out of it) while the middle goes slack and
   !> snaps taut. The ledger closes to 2e-12 of the largest energy, the damping dissipates, end
   !> b leaves the line's plane.
   subroutine test_3d_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angle = acos(-1.0_dp)/6
      type(simulation) :: sim
      type(case_config) :: c
      real(dp) :: drift, dissipated, off_plane
      integer :: n, k
      c = chain_rope_config(121)
      c%model = '3d'
      c%end_b%x = end_b(1)*cos(angle)
      c%end_b%y = end_b(1)*sin(angle)
      c%segment_count = 3
      c%segments(3) = c%segments(2)
      c%segments(2)%length = 30
      c%segments(3)%length = 120
      c%segments(2)%ea = 2.0e6_dp
      c%segments(2)%compression = 'none'
      c%segments(2)%damping = 2.0e4_dp
      c%given = c%given//' end_b%y segment_2%compression segment_2%damping segment_3%length segment_3%area '// &
                'segment_3%density segment_3%ea'
      c%end_b%kind = 'motion'
      c%end_b%amplitude = 1
      c%end_b%period = 2
      c%end_b%direction_x = -1
      c%end_b%direction_z = 0
      c%t_end = 2
      c%courant = 2
      c%interval = 0
      c%energy = .true.
      c%newton_tol = 1.0e-11_dp
      call sim%prepare(c, error)
      if (allocated(error)) return
      call check(error, sim%model == '3d' .and. size(sim%rod3%pieces(1)%run%problem%piece%sections) == 3, &
                 'the 3-D run does not have the three segments')
      if (allocated(error)) return
      call sim%run(error=error)
      if (allocated(error)) return
      associate (en => sim%rod%history%energy, h => sim%rod%history)
         n = sim%rod%history%n
         drift = maxval(abs(en(7, 0:n) - en(7, 0)))/maxval(abs(en(1:4, 0:n)))
         dissipated = en(6, n)
         ! How far end b went off the line's vertical plane.
         off_plane = 0
         do k = 0, n
            off_plane = max(off_plane, abs(-sin(angle)*h%ends(1, 2, k) + cos(angle)*h%ends_y(1, 2, k)))
         end do
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a)') 'three segments in 3-D, the middle one slack: '// &
         'ledger drift', drift, ' of the largest energy; dissipated', dissipated, ' J; smallest strain', &
         sim%rod%summary%min_strain, '; off the plane', off_plane, ' m'
      ! Measured 3.2e-13.
      call check(error, drift < 2.0e-12_dp, 'the 3-D ledger of the line of segments drifts by '//str(drift))
      if (allocated(error)) return
      call check(error, dissipated > 0 .and. sim%rod%summary%min_strain < 0 .and. off_plane > 0.01_dp, &
                 'no 3-D slack test: dissipated '//str(dissipated)//' J, smallest strain '// &
                 str(sim%rod%summary%min_strain)//', off the plane '//str(off_plane)//' m')
   end subroutine test_3d_ledger

   !> The Jacobians of the 3-D step and statics on a line of three segments in water, each with
   !> its own law (linear chain, linear rope, tanh rope), mass, weight, EI, GIp, damping and
   !> drag, turned out of the x-z plane: after 20 ms of a stirred motion, at a perturbed state
   !> (positions and twists), against central differences, within 1e-8 of the row scale.
   subroutine test_3d_jacobian(error)
      use xcable_fdcheck, only: check_jacobian
      use xcable_model_rod3d, only: rod3d_kl, rod3d_ku
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angle = acos(-1.0_dp)/6
      type(simulation) :: sim
      type(case_config) :: c
      real(dp), allocatable :: x(:)
      real(dp) :: worst_step, worst_static
      integer :: k, np
      c = chain_rope_config(41)
      c%model = '3d'
      c%end_b%x = end_b(1)*cos(angle)
      c%end_b%y = end_b(1)*sin(angle)
      c%segment_count = 3
      c%segments(3) = c%segments(2)
      c%segments(2)%length = 30
      c%segments(3)%length = 120
      c%segments(1)%bending_stiffness = 5.0e3_dp
      c%segments(2)%ea = 2.0e6_dp
      c%segments(2)%damping = 2.0e4_dp
      c%segments(2)%gip = 40
      c%segments(2)%cd_normal = 2.5_dp
      c%segments(3)%law = 'tanh'
      c%segments(3)%bending_stiffness = 20
      c%fluid_density = 1025
      c%cd_normal = 1.2_dp
      c%cd_tangential = 0.01_dp
      c%ca_normal = 1
      c%current_x = 0.3_dp
      c%surface_z = 200
      c%given = c%given//' end_b%y segment_1%bending_stiffness segment_2%damping segment_2%gip segment_2%cd_normal '// &
                'segment_3%length segment_3%area segment_3%density segment_3%ea segment_3%law '// &
                'segment_3%bending_stiffness'
      c%dt = 1.0e-3_dp
      c%t_end = 0.02_dp
      c%interval = 0
      call sim%prepare(c, error)
      if (allocated(error)) return
      associate (run => sim%rod3%pieces(1)%run)
         np = run%problem%piece%n
         call check(error, size(run%problem%piece%sections) == 3, 'the 3-D piece has '// &
                    str(size(run%problem%piece%sections))//' sections, not 3')
         if (allocated(error)) return
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
         ! Measured 2.5e-9 (step) and 3.4e-9 (statics) of the row scale.
         call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-8_dp, worst_step, &
                             error)
         if (allocated(error)) then
            error%message = '3-D step: '//error%message
            return
         end if
         run%problem%dt = 0
         call check_jacobian(run%problem, x, rod3d_kl, rod3d_ku, spread(1.0e-6_dp, 1, 4*np), 1.0e-8_dp, worst_static, &
                             error)
         if (allocated(error)) then
            error%message = '3-D statics: '//error%message
            return
         end if
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'three segments in water in 3-D: Jacobian deviations', &
         worst_step, ' (step), ', worst_static, ' (statics) of the row scale'
   end subroutine test_3d_jacobian
   !> test_mbl's case 1 (the chain's MBL reached first) with model = '2d' and '3d', on to 0.2 s:
   !> the 3-D run parts in the chain where the planar run does (the same node, the time to
   !> 1e-12 s), into two pieces with their own sections (the chain; the
   !> chain's rest and the rope), whose states at 0.2 s are the planar ones (positions to 1e-12
   !> of the largest coordinate).
   subroutine test_3d_mbl(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim(2)
      type(case_config) :: c
      real(dp) :: dr, scale
      integer :: m, p, k, n
      do m = 1, 2
         c = chain_rope_config(101)
         c%model = merge('2d', '3d', m == 1)
         c%end_b%kind = 'motion'
         c%end_b%motion = 'harmonic'
         c%end_b%amplitude = 3
         c%end_b%period = 8
         c%end_b%direction_x = end_b(1)/norm2(end_b)
         c%end_b%direction_z = end_b(2)/norm2(end_b)
         c%break_enabled = .true.
         c%break_criterion = 'tension'
         c%t_end = 0.2_dp
         c%interval = 0
         c%newton_tol = 1.0e-12_dp
         c%mbl = 6.0e4_dp
         c%segments(2)%mbl = 1.0e7_dp
         c%given = c%given//' segment_2%mbl'
         call sim(m)%prepare(c, error)
         if (allocated(error)) return
         call sim(m)%run(error=error)
         if (allocated(error)) return
      end do
      call check(error, size(sim(2)%rod3%pieces) == 2, 'the 3-D line did not part inside: '// &
                 str(size(sim(2)%rod3%pieces))//' pieces')
      if (allocated(error)) return
      call check(error, size(sim(2)%rod3%pieces(1)%run%problem%piece%sections) == 1 .and. &
                 size(sim(2)%rod3%pieces(2)%run%problem%piece%sections) == 2, 'the 3-D pieces have '// &
                 str(size(sim(2)%rod3%pieces(1)%run%problem%piece%sections))//' and '// &
                 str(size(sim(2)%rod3%pieces(2)%run%problem%piece%sections))//' sections, not 1 and 2')
      if (allocated(error)) return
      dr = 0
      scale = 0
      do p = 1, 2
         associate (r2 => sim(1)%rod%pieces(p)%r, x3 => sim(2)%rod3%pieces(p)%run%x)
            n = size(r2, 2)
            do k = 1, n
               dr = max(dr, abs(x3(3*k - 2) - r2(1, k)), abs(x3(3*k - 1)), abs(x3(3*k) - r2(2, k)))
            end do
            scale = max(scale, maxval(abs(r2)))
         end associate
      end do
      dr = dr/scale
      write (output_unit, '(4x,a,f8.2,a,f8.2,a,es9.2,a,es9.2,a)') 'the chain''s MBL in 3-D: parts at s =', &
         sim(2)%rod%scene%s_break, ' m (2-D:', sim(1)%rod%scene%s_break, ' m), times', &
         abs(sim(2)%rod%scene%break_time - sim(1)%rod%scene%break_time), ' s apart; positions at 0.2 s', dr, &
         ' of the largest'
      call check(error, sim(2)%rod%scene%s_break == sim(1)%rod%scene%s_break .and. &
                 abs(sim(2)%rod%scene%break_time - sim(1)%rod%scene%break_time) < 1.0e-12_dp, 'the 3-D line parts '// &
                 'at s = '//str(sim(2)%rod%scene%s_break)//' m, t = '//str(sim(2)%rod%scene%break_time)// &
                 ' s, the planar one at s = '//str(sim(1)%rod%scene%s_break)//' m, t = '// &
                 str(sim(1)%rod%scene%break_time)//' s')
      if (allocated(error)) return
      ! Measured: times 7.1e-14 s apart, positions 3.3e-13.
      call check(error, dr < 1.0e-12_dp, 'after the break the 3-D pieces differ from the planar ones by '//str(dr))
   end subroutine test_3d_mbl
   !> A line of three segments in water lying on the bottom with the statics' friction (&seabed
   !> static_friction = 'end_a', mu_axial 1: it takes the grounded line's tension to zero), a
   !> heavy chain at each end and a rope that cannot push (compression = 'none') between them,
   !> each segment's seabed on its own cells: the 3-D statics find the planar static state
   !> (positions to 1e-12 of the largest coordinate, tensions to 1e-9 of the largest; measured
   !> 8.9e-17 and 2.8e-11). (They start from it: Newton takes it also without each section's
   !> compressive branch standing in, which the 3-D statics do as the planar uncut_laws.)
   subroutine test_3d_friction(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim2, sim3
      type(case_config) :: c
      real(dp) :: dr, dt
      c = statics_config(201)
      c%law = 'linear'
      c%ea = 1.0e8_dp
      c%diameter = 0.1_dp
      c%density = 2000
      c%bending_stiffness = 1.0e-3_dp
      c%fluid_density = 1025
      c%surface_z = 10
      c%seabed_depth = 40
      c%seabed_stiffness = 1.0e10_dp
      c%mu_axial = 1
      c%static_friction = 'end_a'
      c%end_a%z = -40
      c%end_b%x = 80
      c%end_b%z = 0
      c%segment_count = 3
      c%segments(1:3)%length = [10.0_dp, 50.0_dp, 40.0_dp]
      c%segments(1)%density = 7000
      c%segments(2)%ea = 2.0e7_dp
      c%segments(2)%compression = 'none'
      c%segments(3)%density = 7000
      c%length = 100
      c%given = 'end_a%z end_b%x end_b%z segment_1%length segment_1%density segment_2%length segment_2%ea '// &
                'segment_2%compression segment_3%length segment_3%density'
      c%model = '2d'
      call sim2%prepare(c, error)
      if (allocated(error)) return
      c%model = '3d'
      call sim3%prepare(c, error)
      if (allocated(error)) return
      call state_difference(sim2, sim3, sim2%rod%static%r, sim3%rod3%pieces(1)%run%x, 0.0_dp, dr, dt)
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'three segments on the bottom with static friction, 3-D '// &
         'statics against 2-D: positions', dr, ', tensions', dt, ' of the largest'
      call check(error, dr < 1.0e-12_dp .and. dt < 1.0e-9_dp, 'the 3-D statics with friction differ from the '// &
                 'planar: positions '//str(dr)//', tensions '//str(dt))
   end subroutine test_3d_friction
end module suite_segments
