!> Dynamics of the rod discretisation against physics it must reproduce:
!> the front arrival at the fixed end and the released end's speed
!> (simple-wave theory), second-order convergence in space and time, the
!> quasi-static limit of a slow break, and an energy ledger that closes to
!> the Newton tolerance in every regime: taut, slack, compressed and
!> buckled, without compression, with numerical dissipation, with a moving
!> end and a point mass.
module suite_rod_dynamics
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_driver_simulation, only: simulation
   use xcable_theory_closed_forms, only: wall_drop_time, riemann_speed
   use xcable_ends_end_condition, only: smooth_ramp
   use suite_rod_statics, only: statics_config
   use suite_golden, only: snapshot_store
   use xcable_driver_history, only: hermite_levels
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_rod_dynamics, rupture_config, run_config

contains

   subroutine collect_rod_dynamics(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('front_arrival', test_front_arrival), &
               new_unittest('end_speed_simple_wave', test_end_speed), &
               new_unittest('second_order_space_time', test_order), &
               new_unittest('quasi_static', test_quasi_static), &
               new_unittest('ledger_paper_run_buckling', test_ledger_paper), &
               new_unittest('ledger_slack_release', test_ledger_slack), &
               new_unittest('ledger_without_compression', test_ledger_no_compression), &
               new_unittest('ledger_dissipation_booked', test_ledger_dissipation), &
               new_unittest('ledger_moving_end_point_mass', test_ledger_moving), &
               new_unittest('hermite_snapshot_exact_for_cubics', test_hermite_cubic)]
   end subroutine collect_rod_dynamics

   !> The paper's cable released at end b.
   function rupture_config(tension, t_break, t_end, nodes) result(c)
      real(dp), intent(in) :: tension, t_break, t_end
      integer, intent(in) :: nodes
      type(case_config) :: c
      c = statics_config(nodes)
      c%tension = tension
      c%break_enabled = .true.
      c%t_break = t_break
      c%t_end = t_end
      c%interval = 0
   end function rupture_config

   !> Prepare and run a case; error when either fails.
   subroutine run_config(c, sim, error, store)
      type(case_config), intent(in) :: c
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(snapshot_store), intent(inout), optional :: store
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(store, error)
   end subroutine run_config

   !> The 1 % drop of the force at the fixed end (fast break, 180 kN) against
   !> simple-wave theory with the ramp and the wall reflection.
   subroutine test_front_arrival(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      integer, parameter :: nodes(3) = [121, 241, 481]
      real(dp) :: err(3), theory
      integer :: i
      do i = 1, 3
         call run_config(rupture_config(180.0e3_dp, 0.005_dp, 0.065_dp, nodes(i)), sim, error)
         if (allocated(error)) return
         associate (s => sim%rod%scene)
            theory = wall_drop_time(s%law, s%mass, s%length, s%law%strain_at(180.0e3_dp), 0.005_dp, 0.01_dp)
         end associate
         err(i) = sim%rod%summary%front_arrival_time - theory
      end do
      write (output_unit, '(4x,a,f9.6,a,3es11.3,a)') 'rod: 1 % drop at the fixed end: theory ', theory, &
         ' s; error at 121/241/481 nodes', err, ' s'
      call check(error, abs(err(2)) < 1.2e-4_dp .and. abs(err(3)) < 7.0e-5_dp, 'front arrival too far from theory')
      if (allocated(error)) return
      call check(error, abs(err(3)) < abs(err(2)) .and. abs(err(2)) < abs(err(1)), 'front error does not shrink')
   end subroutine test_front_arrival

   !> The released end moves at the simple-wave speed (integral of c d eps
   !> from T = 0 to the static strain) once the ramp is over: the mean speed
   !> from t_break + 5 ms to 50 ms, and the peak, which includes the overshoot
   !> of the end node when the ramp ends.
   subroutine test_end_speed(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      integer, parameter :: nodes(3) = [121, 241, 481]
      real(dp) :: plateau(3), peak(3), theory, total, weight
      integer :: i, k
      do i = 1, 3
         call run_config(rupture_config(180.0e3_dp, 0.005_dp, 0.05_dp, nodes(i)), sim, error)
         if (allocated(error)) return
         associate (h => sim%rod%history, s => sim%rod%scene)
            theory = riemann_speed(s%law, s%mass, s%law%strain_at(0.0_dp), s%law%strain_at(180.0e3_dp))
            total = 0
            weight = 0
            do k = 1, h%n
               if (h%time(k) < 0.01_dp) cycle
               total = total + norm2(h%ends(3:4, 2, k))*h%step(k)
               weight = weight + h%step(k)
            end do
            plateau(i) = (total/weight - theory)/theory
            peak(i) = (sim%rod%summary%peak_end_speed - theory)/theory
         end associate
      end do
      write (output_unit, '(4x,a,f9.4,a,3es11.3,a,3es11.3)') 'rod: released end speed, theory ', theory, &
         ' m/s; relative error of the plateau (121/241/481)', plateau, '; of the peak', peak
      call check(error, all(abs(plateau) < 1.0e-4_dp), 'plateau speed off simple-wave theory by more than 1e-4')
      if (allocated(error)) return
      call check(error, abs(peak(3)) < 1.0e-3_dp .and. abs(peak(3)) < abs(peak(1)), &
                 'peak end speed off theory by more than 1e-3 at 481 nodes, or not shrinking')
   end subroutine test_end_speed

   !> Tension field of a slow rupture at 40 ms on 31..481 nodes at Courant
   !> number 0.5: the differences between grids fall at second order.
   subroutine test_order(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(snapshot_store) :: store
      integer, parameter :: nodes(5) = [31, 61, 121, 241, 481]
      real(dp) :: coarse(5, 31), diff(4), order(3)
      type(case_config) :: c
      integer :: i, stride
      do i = 1, 5
         c = rupture_config(180.0e3_dp, 0.05_dp, 0.04_dp, nodes(i))
         c%courant = 0.5_dp
         store = snapshot_store()
         call run_config(c, sim, error, store)
         if (allocated(error)) return
         stride = (nodes(i) - 1)/30
         coarse(i, :) = store%fields(1:nodes(i):stride, 1, store%n)
         call check(error, abs(store%times(store%n) - 0.04_dp) < 1.0e-12_dp, 'last snapshot not at 0.04 s')
         if (allocated(error)) return
      end do
      do i = 1, 4
         diff(i) = maxval(abs(coarse(i, :) - coarse(i + 1, :)))/180.0e3_dp
      end do
      order = log(diff(1:3)/diff(2:4))/log(2.0_dp)
      write (output_unit, '(4x,a,4es11.3,a,3f6.2)') 'rod: tension at 40 ms, max |T_n - T_2n| / T_s (31..481 nodes):', &
         diff, '; observed orders', order
      call check(error, order(3) > 1.8_dp .and. order(3) < 2.3_dp, 'observed order '//str(order(3))//' is not 2')
   end subroutine test_order

   !> A break much slower than L / c (4 s, 70 L / c) is quasi-static: the
   !> tension stays equal to the applied force.
   subroutine test_quasi_static(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(snapshot_store) :: store
      type(case_config) :: c
      real(dp) :: dev, applied
      integer :: k
      c = rupture_config(180.0e3_dp, 4.0_dp, 0.6_dp, 61)
      c%interval = 0.05_dp
      call run_config(c, sim, error, store)
      if (allocated(error)) return
      dev = 0
      do k = 1, store%n
         applied = 180.0e3_dp*smooth_ramp(store%times(k), 0.0_dp, 4.0_dp)
         dev = max(dev, maxval(abs(store%fields(:, 1, k) - applied))/180.0e3_dp)
      end do
      write (output_unit, '(4x,a,es10.3)') 'rod: quasi-static (t_break = 4 s = 70 L/c): max |T - F(t)| / T_s =', dev
      call check(error, dev < 2.0e-3_dp, 'tension departs from the applied force by more than 2e-3 T_s')
   end subroutine test_quasi_static

   !> Ledger drift (relative to the initial strain energy) of a run, checked against a bound.
   subroutine ledger_case(error, c, label, bound, dissipated)
      type(error_type), allocatable, intent(out) :: error
      type(case_config), intent(inout) :: c
      character(*), intent(in) :: label
      real(dp), intent(in) :: bound
      real(dp), intent(out), optional :: dissipated
      type(simulation) :: sim
      c%energy = .true.
      call run_config(c, sim, error)
      if (allocated(error)) then
         error%message = label//': '//error%message
         return
      end if
      write (output_unit, '(4x,a,es10.3,a,es10.3,a,f6.2,a)') 'rod ledger, '//label//': drift / E_strain(0) ', &
         sim%rod%summary%energy_drift, ', dissipation booked ', sim%rod%summary%dissipated, ' J, largest turn ', &
         sim%rod%summary%max_turning_angle, ' rad'
      call check(error, sim%rod%summary%energy_drift < bound, label//': ledger drift '// &
                 str(sim%rod%summary%energy_drift)//' above '//str(bound))
      if (present(dissipated)) dissipated = sim%rod%summary%dissipated
   end subroutine ledger_case

   !> The paper's fast 315 kN break to its t_end, through the compression and
   !> buckling at the fixed end: the ledger closes to the Newton tolerance.
   subroutine test_ledger_paper(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = rupture_config(315.0e3_dp, 0.005_dp, 0.13_dp, 121)
      call ledger_case(error, c, 'fast 315 kN to 0.13 s, 121 nodes', 1.0e-8_dp)
   end subroutine test_ledger_paper

   !> A slack release (5 kN, sag 2 m): the swing, the recoil into the fixed
   !> end and its buckling, to 1 s.
   subroutine test_ledger_slack(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = rupture_config(5.0e3_dp, 0.05_dp, 1.0_dp, 61)
      call ledger_case(error, c, 'slack 5 kN release to 1 s, 61 nodes', 1.0e-7_dp)
   end subroutine test_ledger_slack

   !> The same paper run with a rope that cannot push (compression = 'none').
   subroutine test_ledger_no_compression(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = rupture_config(180.0e3_dp, 0.005_dp, 0.14_dp, 121)
      c%compression = 'none'
      call ledger_case(error, c, 'fast 180 kN without compression, 121 nodes', 1.0e-8_dp)
   end subroutine test_ledger_no_compression

   !> With theta = 0.7 the scheme dissipates; the ledger books it and closes.
   subroutine test_ledger_dissipation(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      real(dp) :: dissipated
      c = rupture_config(180.0e3_dp, 0.005_dp, 0.14_dp, 61)
      c%theta = 0.7_dp
      call ledger_case(error, c, 'fast 180 kN, theta 0.7, 61 nodes', 1.0e-8_dp, dissipated)
      if (allocated(error)) return
      call check(error, dissipated > 1.0e3_dp, 'theta = 0.7 dissipated only '//str(dissipated)//' J')
   end subroutine test_ledger_dissipation

   !> A slack line whose end a moves harmonically (a heaving fairlead), with a
   !> 20 kg mass at end b: the work of the moving support (its reaction
   !> times its displacement) closes the ledger.
   subroutine test_ledger_moving(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      c = statics_config(61)
      c%end_a%kind = 'motion'
      c%end_a%amplitude = 2
      c%end_a%period = 1.5_dp
      c%end_a%direction_x = 1
      c%end_a%direction_z = 1
      c%end_a%ramp_time = 0.5_dp
      c%end_b%kind = 'mass'
      c%end_b%mass = 20
      c%given = ''
      c%t_end = 3
      c%interval = 0
      call ledger_case(error, c, 'moving end a, 20 kg at end b, to 3 s', 1.0e-8_dp)
   end subroutine test_ledger_moving
   !> The driver's snapshot inside a step (hermite_levels) is cubic Hermite: a motion cubic in time
   !> is reproduced, positions and velocities, at any fraction of the step from the two levels'
   !> positions and velocities; a fraction past the step is held at its end.
   subroutine test_hermite_cubic(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: t0 = 0.3_dp, h = 0.02_dp, fractions(4) = [0.0_dp, 0.25_dp, 0.6_dp, 1.0_dp]
      real(dp) :: c(0:3, 2, 3), r0(2, 3), v0(2, 3), r1(2, 3), v1(2, 3), r(2, 3), v(2, 3), worst_r, worst_v
      integer :: k, i, j
      ! Coefficients of x(t) and z(t) at three nodes.
      do j = 1, 3
         do i = 1, 2
            c(:, i, j) = [1.0_dp + i + j, -2.0_dp*j + i, 3.0_dp*i - j, 40.0_dp*(i - 1.5_dp)*j]
         end do
      end do
      r0 = at(t0); v0 = rate(t0); r1 = at(t0 + h); v1 = rate(t0 + h)
      worst_r = 0
      worst_v = 0
      do k = 1, size(fractions)
         call hermite_levels(fractions(k), h, r0, v0, r1, v1, r, v)
         worst_r = max(worst_r, maxval(abs(r - at(t0 + fractions(k)*h))))
         worst_v = max(worst_v, maxval(abs(v - rate(t0 + fractions(k)*h)))/maxval(abs(rate(t0 + fractions(k)*h))))
      end do
      write (output_unit, '(4x,a,es10.3,a,es10.3)') 'cubic motion through a step: largest position error ', &
         worst_r, ' m, velocity error (relative) ', worst_v
      call check(error, worst_r < 4.0e-15_dp .and. worst_v < 1.0e-14_dp, 'hermite_levels does not reproduce a cubic: '// &
                 str(worst_r)//' m, '//str(worst_v))
      if (allocated(error)) return
      call hermite_levels(1.5_dp, h, r0, v0, r1, v1, r, v)
      call check(error, all(r == r1) .and. maxval(abs(v - v1)) <= 1.0e-12_dp*maxval(abs(v1)), &
                 'a fraction past the step is not held at its end')
   contains
      function at(t) result(x)
         real(dp), intent(in) :: t
         real(dp) :: x(2, 3)
         x = c(0, :, :) + t*(c(1, :, :) + t*(c(2, :, :) + t*c(3, :, :)))
      end function at
      function rate(t) result(x)
         real(dp), intent(in) :: t
         real(dp) :: x(2, 3)
         x = c(1, :, :) + t*(2*c(2, :, :) + t*3*c(3, :, :))
      end function rate
   end subroutine test_hermite_cubic

end module suite_rod_dynamics
