!> The rupture dynamics against physics it must reproduce: the front arrival
!> at the fixed end (simple-wave theory with the ramp and the wall
!> reflection), the breaking-end velocity of a simple wave, second-order
!> convergence in space and time together, the energy ledger, and the
!> quasi-static limit of a slow break.
module suite_dynamics
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_fixtures, only: paper_case
   use xcable_box_equations, only: cable_model, n_eq, i_eps, i_u
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options, run_history, run_summary, run_observer, run_rupture, rupture_factor
   use xcable_box_statics, only: static_state, solve_statics
   use xcable_theory_closed_forms, only: wall_drop_time, riemann_speed
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_dynamics, run_case, snapshot_keeper

   !> Keeps every snapshot in memory.
   type, extends(run_observer) :: snapshot_keeper
      integer :: n = 0
      real(dp) :: times(200) = 0
      real(dp), allocatable :: states(:, :, :)
   contains
      procedure :: snapshot => keep_snapshot
   end type snapshot_keeper

contains

   subroutine collect_dynamics(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('front_arrival', test_front_arrival), &
               new_unittest('end_velocity_simple_wave', test_end_velocity), &
               new_unittest('second_order_space_time', test_order), &
               new_unittest('energy_ledger', test_energy), &
               new_unittest('energy_ledger_slack_swing', test_energy_slack), &
               new_unittest('quasi_static', test_quasi_static)]
   end subroutine collect_dynamics

   subroutine keep_snapshot(self, t, y, error)
      class(snapshot_keeper), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: y(:, :)
      type(error_type), allocatable, intent(out) :: error
      if (.not. allocated(self%states)) allocate (self%states(size(y, 1), size(y, 2), size(self%times)))
      if (self%n == size(self%times)) then
         call fatal_error(error, 'snapshot_keeper: too many snapshots')
         return
      end if
      self%n = self%n + 1
      self%times(self%n) = t
      self%states(:, :, self%n) = y
   end subroutine keep_snapshot

   !> Statics then dynamics of the paper's cable.
   subroutine run_case(tension, nodes, t_break, t_end, courant, interval, energy, model, history, summary, keeper, error, &
                       theta)
      real(dp), intent(in) :: tension, t_break, t_end, courant, interval
      integer, intent(in) :: nodes
      logical, intent(in) :: energy
      type(cable_model), intent(out) :: model
      type(run_history), intent(out) :: history
      type(run_summary), intent(out) :: summary
      type(snapshot_keeper), intent(out) :: keeper
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: theta
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      type(static_state) :: state
      call paper_case(tension, nodes, model, s, newton, dyn, error, t_break=t_break, t_end=t_end, courant=courant, &
                      theta=theta)
      if (allocated(error)) return
      dyn%interval = interval
      dyn%energy = energy
      call solve_statics(model, s, tension, newton, state, error)
      if (allocated(error)) return
      call run_rupture(model, s, state%y, dyn, history, summary, error, keeper)
   end subroutine run_case

   !> The 1 % drop of the fixed-end tension arrives when simple-wave theory says.
   subroutine test_front_arrival(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      type(run_history) :: history
      type(run_summary) :: summary
      type(snapshot_keeper) :: keeper
      real(dp) :: theory, err(3), cell_time
      integer :: i
      integer, parameter :: nodes(3) = [61, 121, 241]
      do i = 1, 3
         call run_case(180.0e3_dp, nodes(i), 0.005_dp, 0.07_dp, 1.0_dp, 0.0_dp, .false., model, history, summary, &
                       keeper, error)
         if (allocated(error)) return
         theory = wall_drop_time(model%law, model%mass, model%length, model%law%strain_at(180.0e3_dp), 0.005_dp, 0.01_dp)
         err(i) = summary%front_arrival_time - theory
      end do
      cell_time = model%length/(nodes(3) - 1)/sqrt(model%law%stiffness(model%law%strain_at(180.0e3_dp))/model%mass)
      write (output_unit, '(4x,a,f9.6,a,3es11.3,a,es10.3,a)') '1 % drop at the fixed end: theory ', theory, &
         ' s; error at 61/121/241 nodes', err, ' s (one cell at 241 nodes: ', cell_time, ' s)'
      call check(error, abs(err(3)) < 0.5_dp*cell_time, 'front arrival off theory by more than half a cell time')
      if (allocated(error)) return
      call check(error, abs(err(3)) < abs(err(1)), 'front arrival error does not shrink with refinement')
   end subroutine test_front_arrival

   !> The breaking end reaches the simple-wave velocity: integral of c d eps
   !> from the strain at zero tension to the static strain.
   subroutine test_end_velocity(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      type(run_history) :: history
      type(run_summary) :: summary
      type(snapshot_keeper) :: keeper
      real(dp) :: theory, err(3)
      integer :: i
      integer, parameter :: nodes(3) = [61, 121, 241]
      do i = 1, 3
         call run_case(180.0e3_dp, nodes(i), 0.005_dp, 0.04_dp, 1.0_dp, 0.0_dp, .false., model, history, summary, &
                       keeper, error)
         if (allocated(error)) return
         theory = riemann_speed(model%law, model%mass, model%law%strain_at(0.0_dp), model%law%strain_at(180.0e3_dp))
         err(i) = (summary%peak_end_speed - theory)/theory
      end do
      write (output_unit, '(4x,a,f9.4,a,3es11.3)') 'peak breaking-end speed: theory ', theory, &
         ' m/s; relative error at 61/121/241 nodes', err
      call check(error, abs(err(3)) < 4.0e-4_dp, 'peak end speed off simple-wave theory by more than 4e-4')
      if (allocated(error)) return
      call check(error, abs(err(3)) <= abs(err(1)), 'end speed error does not shrink with refinement')
   end subroutine test_end_velocity

   !> Tension field of a slow rupture at t = 0.04 s on three grids at a fixed
   !> Courant number: the differences fall at second order.
   subroutine test_order(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      type(run_history) :: history
      type(run_summary) :: summary
      type(snapshot_keeper) :: keeper
      integer, parameter :: nodes(5) = [31, 61, 121, 241, 481]
      real(dp) :: coarse(5, 31), diff(4), order(3)
      integer :: i, stride
      do i = 1, 5
         call run_case(180.0e3_dp, nodes(i), 0.05_dp, 0.04_dp, 0.5_dp, 0.04_dp, .false., model, history, summary, &
                       keeper, error)
         if (allocated(error)) return
         stride = (nodes(i) - 1)/30
         coarse(i, :) = model%law%tension(keeper%states(i_eps, 1:nodes(i):stride, keeper%n))
         call check(error, abs(keeper%times(keeper%n) - 0.04_dp) < 1.0e-12_dp, 'last snapshot not at 0.04 s')
         if (allocated(error)) return
      end do
      do i = 1, 4
         diff(i) = maxval(abs(coarse(i, :) - coarse(i + 1, :)))/180.0e3_dp
      end do
      order = log(diff(1:3)/diff(2:4))/log(2.0_dp)
      write (output_unit, '(4x,a,4es11.3,a,3f6.2)') 'tension at t = 0.04 s, max |T_n - T_2n| / T_s (31..481 nodes):', &
         diff, '; observed orders', order
      call check(error, order(3) > 1.8_dp .and. order(3) < 2.3_dp, 'observed order '//str(order(3))//' is not 2')
   end subroutine test_order

   !> The energy ledger drifts less on finer grids.
   subroutine test_energy(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      type(run_history) :: history
      type(run_summary) :: summary
      type(snapshot_keeper) :: keeper
      integer, parameter :: nodes(3) = [61, 121, 241]
      real(dp) :: drift(3)
      integer :: i
      do i = 1, 3
         call run_case(180.0e3_dp, nodes(i), 0.05_dp, 0.09_dp, 1.0_dp, 0.0_dp, .true., model, history, summary, &
                       keeper, error)
         if (allocated(error)) return
         drift(i) = summary%energy_drift
      end do
      write (output_unit, '(4x,a,3es11.3,a,2f6.2)') 'energy ledger drift / strain energy (61/121/241 nodes):', drift, &
         '; observed orders', log(drift(1:2)/drift(2:3))/log(2.0_dp)
      call check(error, drift(2) < 0.5_dp*drift(1) .and. drift(3) < 0.5_dp*drift(2), 'energy drift does not shrink')
      if (allocated(error)) return
      call check(error, drift(3) < 1.0e-4_dp, 'energy drift above 1e-4 at 241 nodes')
   end subroutine test_energy

   !> A slack cable (2 kN, sag 5 m) released in 20 ms swings down under
   !> gravity: large normal velocities and rotations, so the ledger checks the
   !> transverse terms of eq. 18 too. Its drift falls with refinement.
   subroutine test_energy_slack(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      type(run_history) :: history
      type(run_summary) :: summary
      type(snapshot_keeper) :: keeper
      integer, parameter :: nodes(3) = [61, 121, 241]
      real(dp) :: drift(3), swing
      integer :: i
      do i = 1, 3
         call run_case(2.0e3_dp, nodes(i), 0.02_dp, 0.3_dp, 1.0_dp, 0.0_dp, .true., model, history, summary, &
                       keeper, error)
         if (allocated(error)) return
         drift(i) = summary%energy_drift
      end do
      swing = maxval(history%energy(4, 0:history%n)) - minval(history%energy(4, 0:history%n))
      write (output_unit, '(4x,a,3es11.3,a,2f6.2,a,f7.1,a)') 'slack swing: ledger drift / strain energy (61/121/241):', &
         drift, '; orders', log(drift(1:2)/drift(2:3))/log(2.0_dp), '; gravity energy changes by', swing, ' J'
      call check(error, swing > 0.3_dp*history%energy(1, 0), 'the cable did not swing')
      if (allocated(error)) return
      call check(error, drift(2) < 0.33_dp*drift(1) .and. drift(3) < 0.33_dp*drift(2), &
                 'slack-swing energy drift does not fall at better than first order')
      if (allocated(error)) return
      call check(error, drift(3) < 4.0e-3_dp, 'slack-swing energy drift above 0.4 % at 241 nodes')
   end subroutine test_energy_slack

   !> A break much slower than L / c is quasi-static: the tension stays
   !> uniform and equal to the applied force.
   subroutine test_quasi_static(error)
      type(error_type), allocatable, intent(out) :: error
      type(cable_model) :: model
      type(run_history) :: history
      type(run_summary) :: summary
      type(snapshot_keeper) :: keeper
      real(dp) :: dev, applied
      real(dp), parameter :: t_break = 4.0_dp
      integer :: k
      call run_case(180.0e3_dp, 61, t_break, 0.6_dp, 1.0_dp, 0.05_dp, .false., model, history, summary, keeper, error)
      if (allocated(error)) return
      dev = 0
      do k = 1, keeper%n
         applied = 180.0e3_dp*rupture_factor(keeper%times(k), t_break)
         dev = max(dev, maxval(abs(model%law%tension(keeper%states(i_eps, :, k)) - applied))/180.0e3_dp)
      end do
      write (output_unit, '(4x,a,es10.3,a,f6.3)') 'quasi-static (t_break = 4 s = 70 L/c): max |T - F(t)| / T_s =', dev, &
         ', final F / T_s =', rupture_factor(0.6_dp, t_break)
      call check(error, dev < 2.0e-3_dp, 'tension departs from the applied force by more than 2e-3 T_s')
   end subroutine test_quasi_static
end module suite_dynamics
