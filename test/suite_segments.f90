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
               new_unittest('break_at_the_segment_that_reaches_its_mbl', test_mbl)]
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
end module suite_segments
