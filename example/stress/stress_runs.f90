!> One stress-test run in process (issue 6): the case is built like the app
!> builds it (case_config, setup_case), then statics and the rupture with the
!> energy ledger and a wall-clock limit, and the figures of the stress table
!> are taken from the history. A compression probe (a run_observer) measures
!> at each snapshot the compressed zone at the fixed end.
!>
!> Measures (the window is the part of the run before the fixed end first goes
!> into compression, T(0, t) <= 0, or the whole run if it never does):
!> - overshoot: largest rise of the fixed-end tension above its static value
!>   in the window, / T_s. An unloading front can only lower the tension, so
!>   any rise is the box scheme's ringing (its short waves run ahead of the
!>   front at Courant < 1 and lag it at Courant > 1) or, in a slack cable, the
!>   swing of the sag.
!> - ringing: (total variation - |net change|) / (2 T_s) of the fixed-end
!>   tension in the window: the summed height of every rebound. A monotone
!>   drop gives 0.
!> - speed error: (peak |u| at the breaking end in the window - simple-wave
!>   theory) / theory (PHYSICS.md; straight string: not a reference for a
!>   slack cable with a sag of metres).
!> - drop error: time of the 1 % drop of the fixed-end tension minus
!>   simple-wave theory with the ramp (xcable_theory%wall_drop_time; without
!>   the weak shock of the concave law above eps = 0.2086, so approximate at
!>   315 and 400 kN), s.
!> - energy drift: max |ledger - ledger(0)| / strain energy(0) over the run.
module stress_runs
   use xcable_kinds, only: dp
   use xcable_error, only: error_type
   use xcable_io_input, only: case_config
   use xcable_case, only: setup_case
   use xcable_model_equations, only: cable_model, i_eps, i_om
   use xcable_model_geometry, only: positions
   use xcable_solver_newton, only: newton_options
   use xcable_dynamics, only: dynamics_options, run_history, run_summary, run_observer, run_rupture
   use xcable_statics, only: static_state, solve_statics
   use xcable_theory, only: riemann_speed, wave_speed, wall_drop_time
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: run_spec, run_outcome, stress_run, compression_probe, paper_bending_stiffness, wall_reflection

   !> E pi d^4 / 64 of the paper's cable, N m^2.
   real(dp), parameter :: paper_bending_stiffness = 230.0e6_dp*acos(-1.0_dp)*0.05_dp**4/64

   !> What to run.
   type :: run_spec
      !> Part of the sweep the run belongs to.
      character(len=12) :: study = ''
      !> Static end tension, N; breaking time, s.
      real(dp) :: tension = 180.0e3_dp, t_break = 5.0e-3_dp
      !> Nodes.
      integer :: nodes = 121
      !> Courant number c(eps0) dt / ds; EI as a multiple of the paper's; time weight.
      real(dp) :: courant = 1, ei_factor = 1, theta = 0.5_dp
      !> End of the run, s (0: t_break + 2.2 L / c(eps0), past the front's reflection).
      real(dp) :: t_end = 0
      !> Snapshot interval, s.
      real(dp) :: interval = 0.01_dp
      !> Wall-clock limit of the dynamics, s.
      real(dp) :: wall_limit = 30
   end type run_spec

   !> Compression at the fixed end, one record per snapshot.
   type, extends(run_observer) :: compression_probe
      !> Cable data, grid and static state.
      type(cable_model) :: model
      real(dp), allocatable :: s(:), y_static(:, :)
      !> Snapshots recorded.
      integer :: n = 0
      !> Time, s; fixed-end tension, N; length of the compressed zone at the
      !> fixed end (T < 0), m; Euler load pi^2 EI / l^2 of that length, N;
      !> largest distance of the zone's nodes from its chord, m; largest
      !> |Omega3 - static| in the zone, 1/m; smallest strain in the zone.
      real(dp), allocatable :: time(:), wall_tension(:), length(:), euler_load(:), deflection(:), &
                               curvature(:), min_strain(:)
   contains
      procedure :: snapshot => probe_snapshot
   end type compression_probe

   !> Figures of a run.
   type :: run_outcome
      !> Whether the run reached t_end; otherwise the named reason.
      logical :: complete = .false.
      character(:), allocatable :: reason
      !> End asked for, time reached, step used, s.
      real(dp) :: t_end = 0, time_reached = 0, dt = 0
      !> Static sag, m.
      real(dp) :: sag = 0
      !> See the module doc.
      real(dp) :: energy_drift = 0, overshoot = 0, ringing = 0, speed_error = 0, drop_error = 0
      !> Newton iterations in the hardest step; rejected attempts; accepted steps.
      integer :: max_newton = 0, rejected = 0, steps = 0
      !> Wall time of the dynamics, s.
      real(dp) :: wall = 0
      !> Smallest fixed-end tension, N, and the largest |b0^2 + b3^2 - 1|.
      real(dp) :: min_wall_tension = 0, max_unit_norm_error = 0
      !> Time the fixed end first went into compression, s (-1: never).
      real(dp) :: compression_time = -1
      !> Hardest Newton step and rejected attempts before and after that time.
      integer :: newton_tension = 0, newton_compression = 0, rejected_tension = 0, rejected_compression = 0
   end type run_outcome

contains

   !> Run one case and measure it; probe, if present, records the compressed zone.
   subroutine stress_run(spec, outcome, probe)
      !> What to run.
      type(run_spec), intent(in) :: spec
      !> Its figures.
      type(run_outcome), intent(out) :: outcome
      !> Compression probe (reset here).
      type(compression_probe), intent(inout), optional :: probe
      type(case_config) :: config
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dynamics
      type(static_state) :: state
      type(run_history) :: history
      type(run_summary) :: summary
      type(error_type), allocatable :: error
      real(dp) :: eps0, t_s, c0, theory, nan
      integer :: i, last

      nan = ieee_value(1.0_dp, ieee_quiet_nan)
      outcome%energy_drift = nan
      outcome%overshoot = nan
      outcome%ringing = nan
      outcome%speed_error = nan
      outcome%drop_error = nan
      config%source = 'stress'
      config%tension = spec%tension
      config%t_break = spec%t_break
      config%nodes = spec%nodes
      config%courant = spec%courant
      config%theta = spec%theta
      config%bending_stiffness = spec%ei_factor*paper_bending_stiffness
      config%interval = spec%interval
      config%energy = .true.
      config%quiet = .true.
      config%max_wall_time = spec%wall_limit
      ! t_end first with a placeholder (setup_case needs one), then the automatic value.
      config%t_end = merge(spec%t_end, 1.0_dp, spec%t_end > 0)
      call setup_case(config, model, s, newton, dynamics, error)
      if (allocated(error)) then
         outcome%reason = 'input: '//error%message
         return
      end if
      eps0 = model%law%strain_at(spec%tension)
      c0 = wave_speed(model%law, model%mass, eps0)
      if (spec%t_end <= 0) then
         config%t_end = spec%t_break + 2.2_dp*model%length/c0
         call setup_case(config, model, s, newton, dynamics, error)
         if (allocated(error)) then
            outcome%reason = 'input: '//error%message
            return
         end if
      end if
      outcome%t_end = dynamics%t_end
      outcome%dt = dynamics%dt
      call solve_statics(model, s, spec%tension, newton, state, error)
      if (allocated(error)) then
         outcome%reason = error%message
         return
      end if
      outcome%sag = state%sag
      if (present(probe)) then
         probe%model = model
         probe%s = s
         probe%y_static = state%y
         probe%n = 0
         call run_rupture(model, s, state%y, dynamics, history, summary, error, probe)
      else
         call run_rupture(model, s, state%y, dynamics, history, summary, error)
      end if
      outcome%complete = .not. allocated(error)
      outcome%reason = 'complete'
      if (allocated(error)) outcome%reason = error%message
      outcome%time_reached = summary%time_reached
      outcome%energy_drift = summary%energy_drift
      outcome%max_newton = summary%max_newton_iterations
      outcome%rejected = summary%rejected_steps
      outcome%steps = summary%steps
      outcome%wall = summary%wall_time
      outcome%min_wall_tension = summary%min_fixed_end_tension
      outcome%max_unit_norm_error = summary%max_unit_norm_error

      ! The window: up to the first record with the fixed end in compression.
      t_s = history%fixed_end_tension(0)
      last = history%n
      do i = 1, history%n
         if (history%fixed_end_tension(i) <= 0) then
            last = i - 1
            outcome%compression_time = history%time(i)
            exit
         end if
      end do
      associate (tw => history%fixed_end_tension)
         outcome%overshoot = max(0.0_dp, maxval(tw(0:last)) - t_s)/spec%tension
         outcome%ringing = 0
         if (last >= 1) outcome%ringing = (sum(abs(tw(1:last) - tw(0:last - 1))) - abs(tw(last) - tw(0)))/(2*spec%tension)
      end associate
      outcome%newton_tension = maxval(history%newton_iterations(0:last))
      outcome%rejected_tension = sum(history%rejected(0:last))
      if (last < history%n) then
         outcome%newton_compression = maxval(history%newton_iterations(last + 1:history%n))
         outcome%rejected_compression = summary%rejected_steps - outcome%rejected_tension
      end if
      theory = riemann_speed(model%law, model%mass, model%law%strain_at(0.0_dp), eps0)
      outcome%speed_error = (maxval(abs(history%end_velocity(0:last))) - theory)/theory
      if (summary%front_arrival_time > 0) then
         outcome%drop_error = summary%front_arrival_time - &
                              wall_drop_time(model%law, model%mass, model%length, eps0, spec%t_break, 0.01_dp)
      end if
   end subroutine stress_run

   !> Straight-string reflection at the fixed end of the paper's cable released
   !> from the static tension: the breaking end reaches u_end = phi(eps0) -
   !> phi(eps_zero) (phi = integral of c d eps, T(eps_zero) = 0), and at the
   !> wall (u = 0) the change of phi doubles, so the wall strain eps_wall
   !> solves phi(eps_zero) - phi(eps_wall) = u_end. capacity(j) is
   !> phi(eps_zero) - phi(floors(j)): the largest end speed the compressive
   !> branch of the law can stop above the strain floors(j).
   subroutine wall_reflection(tension, floors, eps0, u_end, eps_wall, wall_tension, capacity)
      !> Static end tension, N.
      real(dp), intent(in) :: tension
      !> Strains at which to give the capacity.
      real(dp), intent(in) :: floors(:)
      !> Static strain; end speed, m/s; wall strain; wall tension, N.
      real(dp), intent(out) :: eps0, u_end, eps_wall, wall_tension
      !> Capacity to each floor, m/s.
      real(dp), intent(out) :: capacity(:)
      type(case_config) :: config
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dynamics
      type(error_type), allocatable :: error
      real(dp) :: eps_zero, lo, hi, mid
      integer :: it, j
      config%source = 'stress'
      config%bending_stiffness = paper_bending_stiffness
      config%tension = tension
      call setup_case(config, model, s, newton, dynamics, error)
      eps0 = model%law%strain_at(tension)
      eps_zero = model%law%strain_at(0.0_dp)
      u_end = riemann_speed(model%law, model%mass, eps_zero, eps0)
      do j = 1, size(floors)
         capacity(j) = riemann_speed(model%law, model%mass, floors(j), eps_zero)
      end do
      ! Bisection on [-1000, eps_zero]: far in compression c tends to sqrt(p5 / m).
      lo = -1000
      hi = eps_zero
      do it = 1, 200
         mid = 0.5_dp*(lo + hi)
         if (riemann_speed(model%law, model%mass, mid, eps_zero) > u_end) then
            lo = mid
         else
            hi = mid
         end if
      end do
      eps_wall = 0.5_dp*(lo + hi)
      wall_tension = model%law%tension(eps_wall)
   end subroutine wall_reflection

   !> Measure the compressed zone at the fixed end (run_observer).
   subroutine probe_snapshot(self, t, y, error)
      !> Probe.
      class(compression_probe), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Unknowns (7, nodes).
      real(dp), intent(in) :: y(:, :)
      !> Never set.
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: x(size(self%s)), z(size(self%s)), tension(size(self%s)), zone, chord_x, chord_z, chord, dist
      integer :: k, last, np
      np = size(self%s)
      if (.not. allocated(self%time)) then
         allocate (self%time(1000), self%wall_tension(1000), self%length(1000), self%euler_load(1000), &
                   self%deflection(1000), self%curvature(1000), self%min_strain(1000))
      end if
      if (self%n == size(self%time)) return
      self%n = self%n + 1
      tension = self%model%law%tension(y(i_eps, :))
      call positions(y, self%s, x, z)
      ! Compressed zone: the nodes from the fixed end while T < 0; its length
      ! ends at the interpolated zero of T.
      last = 0
      do k = 1, np
         if (tension(k) >= 0) exit
         last = k
      end do
      zone = 0
      if (last >= 1 .and. last < np) then
         zone = self%s(last) + (self%s(last + 1) - self%s(last))*(-tension(last))/(tension(last + 1) - tension(last))
      else if (last == np) then
         zone = self%s(np)
      end if
      self%time(self%n) = t
      self%wall_tension(self%n) = tension(1)
      self%length(self%n) = zone
      self%euler_load(self%n) = huge(1.0_dp)
      if (zone > 0) self%euler_load(self%n) = pi**2*self%model%bending_stiffness/zone**2
      self%deflection(self%n) = 0
      self%curvature(self%n) = 0
      self%min_strain(self%n) = y(i_eps, 1)
      if (last >= 2) then
         chord_x = x(last) - x(1)
         chord_z = z(last) - z(1)
         chord = max(hypot(chord_x, chord_z), tiny(1.0_dp))
         do k = 1, last
            dist = abs((x(k) - x(1))*chord_z - (z(k) - z(1))*chord_x)/chord
            self%deflection(self%n) = max(self%deflection(self%n), dist)
         end do
      end if
      do k = 1, max(last, 1)
         self%curvature(self%n) = max(self%curvature(self%n), abs(y(i_om, k) - self%y_static(i_om, k)))
         self%min_strain(self%n) = min(self%min_strain(self%n), y(i_eps, k))
      end do
   end subroutine probe_snapshot
end module stress_runs
