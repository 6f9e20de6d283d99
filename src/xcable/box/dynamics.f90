!> The box scheme's rupture (eqs. 22-25, 31-32) as version 0.1 gave it: its
!> controls, its records (run_history, run_summary), its observer of the
!> states, the ramp of the released end force and the energies of a state.
!> The steps are those of the box scheme's model (box/model.f90) in the one
!> step loop (driver/stepping.f90); run_rupture runs them with these records
!> (its submodule, box/dynamics/rupture.f90).
!>
!> Bounds that keep every run finite (issue 6): Newton stops after
!> max_iterations, or when its update grows three times in a row, or on a
!> non-finite residual or update; one step is halved at most
!> log2(1 / min_step_fraction) times before the run stops; the rejected
!> attempts of the whole run are limited to 1000 + the number of requested
!> steps; a step that no longer advances the time stops the run; the wall
!> clock (max_wall_time) is checked before every attempt, rejected ones
!> included. history%rejected(i) counts the attempts rejected before accepted
!> step i; summary%rejected_steps counts them all (with those of a final
!> failing step).
module xcable_box_dynamics
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type
   use xcable_box_equations, only: cable_model, n_eq, i_eps, i_u, i_v, i_om
   use xcable_solver_newton, only: newton_options
   implicit none
   private
   public :: dynamics_options, run_history, run_summary, run_observer, run_rupture, rupture_factor
   public :: energy_terms, n_energy, energy_names

   !> Energy ledger columns: strain, kinetic, bending, gravity, work of the end force, ledger.
   integer, parameter :: n_energy = 6
   character(len=*), parameter :: energy_names(n_energy) = &
      [character(len=8) :: 'strain', 'kinetic', 'bending', 'gravity', 'work', 'ledger']

   !> Controls of a rupture run.
   type :: dynamics_options
      !> Breaking time t_br, s (0: instantaneous).
      real(dp) :: t_break = 0.05_dp
      !> End of the run, s.
      real(dp) :: t_end = 0.16_dp
      !> Requested time step, s.
      real(dp) :: dt = 1.0e-4_dp
      !> Time weight of the new level: 1/2 is the paper's scheme; > 1/2 damps high frequencies.
      real(dp) :: theta = 0.5_dp
      !> Snapshot interval, s (0: only t = 0 and t_end).
      real(dp) :: interval = 0.01_dp
      !> Newton controls.
      type(newton_options) :: newton
      !> First guess by linear extrapolation from the two previous levels.
      logical :: extrapolate = .true.
      !> Keep the energy ledger in the history.
      logical :: energy = .false.
      !> Smallest step allowed by the step control, as a fraction of dt.
      real(dp) :: min_step_fraction = 1.0_dp/1024
      !> Wall-clock limit, s (0: none).
      real(dp) :: max_wall_time = 0
      !> Print progress on stderr.
      logical :: progress = .false.
   end type dynamics_options

   !> One record per accepted time step (index 0: the static state at t = 0).
   type :: run_history
      !> Number of accepted steps.
      integer :: n = 0
      !> Time, s.
      real(dp), allocatable :: time(:)
      !> Step taken, s.
      real(dp), allocatable :: step(:)
      !> u at the breaking end, m/s.
      real(dp), allocatable :: end_velocity(:)
      !> Tension at the fixed end, N.
      real(dp), allocatable :: fixed_end_tension(:)
      !> Newton iterations of the accepted step.
      integer, allocatable :: newton_iterations(:)
      !> Rejected attempts before the accepted step.
      integer, allocatable :: rejected(:)
      !> Energy ledger (n_energy, 0:n), J, when asked for.
      real(dp), allocatable :: energy(:, :)
      !> Unknowns at the fixed end and at the breaking end (n_eq, 2, 0:n).
      real(dp), allocatable :: end_y(:, :, :)
      !> Position (x, z) of the breaking end (2, 0:n), m.
      real(dp), allocatable :: end_position(:, :)
      !> Smallest and largest strain at any node over the records.
      real(dp) :: min_strain = huge(1.0_dp), max_strain = -huge(1.0_dp)
   contains
      procedure :: reserve => history_reserve
   end type run_history

   !> Figures of a run.
   type :: run_summary
      !> Largest |u| at the breaking end, m/s, and when.
      real(dp) :: peak_end_speed = 0, peak_end_speed_time = 0
      !> Smallest tension at the fixed end, N, and when.
      real(dp) :: min_fixed_end_tension = 0, min_fixed_end_tension_time = 0
      !> First time the fixed-end tension is 1 % below its static value, s (-1: never).
      real(dp) :: front_arrival_time = -1
      !> max |ledger - ledger(0)| / strain energy(0) (-1: ledger not kept).
      real(dp) :: energy_drift = -1
      !> Accepted and rejected steps.
      integer :: steps = 0, rejected_steps = 0
      !> Newton iterations: total and largest in one step; Jacobian factorisations.
      integer :: newton_iterations = 0, max_newton_iterations = 0, factorisations = 0
      !> Simulated time reached, s.
      real(dp) :: time_reached = 0
      !> Wall time of the dynamics, s.
      real(dp) :: wall_time = 0
      !> Largest |b0^2 + b3^2 - 1| over nodes and steps: the kinematic error of
      !> the discrete Euler parameters, large only where the curvature is
      !> unresolved (a buckle at the grid scale).
      real(dp) :: max_unit_norm_error = 0
   end type run_summary

   !> Receives the snapshots of a run (the output writer).
   type, abstract :: run_observer
   contains
      procedure(snapshot_interface), deferred :: snapshot
   end type run_observer

   abstract interface
      subroutine snapshot_interface(self, t, y, error)
         import :: run_observer, dp, error_type
         !> Observer.
         class(run_observer), intent(inout) :: self
         !> Time, s.
         real(dp), intent(in) :: t
         !> Unknowns (7, nodes).
         real(dp), intent(in) :: y(:, :)
         !> Error when writing fails.
         type(error_type), allocatable, intent(out) :: error
      end subroutine snapshot_interface
   end interface


   interface
      !> Integrate the rupture from the static state to t_end: the box scheme's model
      !> (box/model.f90) in the one step loop (driver/stepping.f90), with the records of
      !> version 0.1 (a submodule, box/dynamics/rupture.f90: the model uses this module's types).
      module subroutine run_rupture(model, s, y_static, options, history, summary, error, observer)
         !> Cable data.
         type(cable_model), intent(in) :: model
         !> Node arc lengths, m.
         real(dp), intent(in) :: s(:)
         !> Static state (7, nodes).
         real(dp), intent(in) :: y_static(:, :)
         !> Controls.
         type(dynamics_options), intent(in) :: options
         !> One record per accepted step.
         type(run_history), intent(out) :: history
         !> Figures of the run (filled also when it fails).
         type(run_summary), intent(out) :: summary
         !> Error when the run cannot go on (the history and summary hold what was done).
         type(error_type), allocatable, intent(out) :: error
         !> Receives the snapshots.
         class(run_observer), intent(inout), target, optional :: observer
      end subroutine run_rupture
   end interface

contains

   !> Fraction of the static end force applied at time t (eqs. 31-32).
   elemental function rupture_factor(t, t_break) result(r)
      !> Time, s.
      real(dp), intent(in) :: t
      !> Breaking time, s.
      real(dp), intent(in) :: t_break
      real(dp) :: r
      real(dp), parameter :: pi = acos(-1.0_dp)
      if (t <= 0) then
         r = 1
      else if (t >= t_break) then
         r = 0
      else
         r = cos(0.5_dp*pi*t/t_break)**2
      end if
   end function rupture_factor

   !> Make room for at least n records (keeps the content).
   subroutine history_reserve(self, n, energy)
      !> History.
      class(run_history), intent(inout) :: self
      !> Records needed (steps).
      integer, intent(in) :: n
      !> Whether the energy ledger is kept.
      logical, intent(in) :: energy
      real(dp), allocatable :: r(:), e(:, :), ey(:, :, :)
      integer, allocatable :: i(:)
      integer :: m
      if (allocated(self%time)) then
         if (ubound(self%time, 1) >= n) return
      end if
      m = self%n
      if (.not. allocated(self%time)) then
         allocate (self%time(0:n), self%step(0:n), self%end_velocity(0:n), self%fixed_end_tension(0:n))
         allocate (self%newton_iterations(0:n), self%rejected(0:n))
         allocate (self%end_y(n_eq, 2, 0:n), self%end_position(2, 0:n))
         if (energy) allocate (self%energy(n_energy, 0:n))
         return
      end if
      allocate (ey(n_eq, 2, 0:n)); ey(:, :, 0:m) = self%end_y(:, :, 0:m); call move_alloc(ey, self%end_y)
      allocate (e(2, 0:n)); e(:, 0:m) = self%end_position(:, 0:m); call move_alloc(e, self%end_position)
      allocate (r(0:n)); r(0:m) = self%time(0:m); call move_alloc(r, self%time)
      allocate (r(0:n)); r(0:m) = self%step(0:m); call move_alloc(r, self%step)
      allocate (r(0:n)); r(0:m) = self%end_velocity(0:m); call move_alloc(r, self%end_velocity)
      allocate (r(0:n)); r(0:m) = self%fixed_end_tension(0:m); call move_alloc(r, self%fixed_end_tension)
      allocate (i(0:n)); i(0:m) = self%newton_iterations(0:m); call move_alloc(i, self%newton_iterations)
      allocate (i(0:n)); i(0:m) = self%rejected(0:m); call move_alloc(i, self%rejected)
      if (energy) then
         allocate (e(n_energy, 0:n)); e(:, 0:m) = self%energy(:, 0:m); call move_alloc(e, self%energy)
      end if
   end subroutine history_reserve

   !> Strain, kinetic, bending and gravity energy of a state (trapezoid rule in s), J.
   subroutine energy_terms(model, y, s, z, e)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns (7, nodes).
      real(dp), intent(in) :: y(:, :)
      !> Node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Vertical positions, m.
      real(dp), intent(in) :: z(:)
      !> Energies (4).
      real(dp), intent(out) :: e(4)
      real(dp) :: density(4), density_prev(4)
      integer :: k
      ! Node by node (no work array: the ledger is kept at every step).
      e = 0
      do k = 1, size(s)
         density(1) = model%law%strain_energy(y(i_eps, k))
         density(2) = 0.5_dp*model%mass*(y(i_u, k)**2 + y(i_v, k)**2)
         density(3) = 0.5_dp*model%bending_stiffness*y(i_om, k)**2
         density(4) = model%weight*z(k)
         if (k > 1) e = e + 0.5_dp*(s(k) - s(k - 1))*(density + density_prev)
         density_prev = density
      end do
   end subroutine energy_terms
end module xcable_box_dynamics
