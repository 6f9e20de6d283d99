!> One stress-test run in process (issue 6) through the simulation driver
!> (driver/simulation.f90), for either scheme: the case is a case_config
!> with the paper's defaults, prepared and run like the program runs it,
!> with the energy ledger and a wall-clock limit; the figures of the stress
!> tables are taken from the run's history and summary. A compression probe
!> (a run_observer) measures at each snapshot the compressed zone at the
!> fixed end from the output fields, so it reads both schemes alike.
!>
!> Measures (the window is the part of the run before the fixed end first goes
!> into compression, T(0, t) <= 0, or the whole run if it never does):
!> - overshoot: largest rise of the fixed-end tension above its static value
!>   in the window, / T_s. An unloading front can only lower the tension, so
!>   any rise is a scheme's ringing (short waves running ahead of the front)
!>   or, in a slack cable, the swing of the sag.
!> - ringing: (total variation - |net change|) / (2 T_s) of the fixed-end
!>   tension in the window: the summed height of every rebound. A monotone
!>   drop gives 0.
!> - speed error: (peak speed |V| of the released end in the window -
!>   simple-wave theory) / theory (straight string: not a reference for a
!>   slack cable with a sag of metres). Version 0.1 of this study took the
!>   tangential speed |u| of the box scheme; |V| is what both schemes record.
!> - drop error: time of the 1 % drop of the fixed-end tension minus
!>   simple-wave theory with the ramp (xcable_theory_closed_forms%wall_drop_time; without
!>   the weak shock of the concave law above eps = 0.2086, so approximate at
!>   315 and 400 kN), s.
!> - energy drift: max |ledger - ledger(0)| / strain energy(0) over the run
!>   (the driver's summary).
!> - released end: its position at the times release_times, linear in time
!>   between the two accepted steps around each (steps of at most 0.2 ms).
module stress_runs
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, stat_input
   use xcable_io_config, only: case_config
   use xcable_io_input, only: read_config
   use xcable_material_law, only: material_law
   use xcable_material_factory, only: new_law
   use xcable_driver_simulation, only: simulation
   use xcable_driver_records, only: run_history, run_summary, static_info, run_observer
   use xcable_theory_closed_forms, only: riemann_speed, wave_speed, wall_drop_time
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: run_spec, run_outcome, stress_run, compression_probe, paper_bending_stiffness, wall_reflection
   public :: release_times, outcome_tag, scene_namelist

   !> E pi d^4 / 64 of the paper's cable, N m^2.
   real(dp), parameter :: paper_bending_stiffness = 230.0e6_dp*acos(-1.0_dp)*0.05_dp**4/64
   !> Times at which the released end's position is recorded, s.
   real(dp), parameter :: release_times(4) = [0.5_dp, 1.0_dp, 1.5_dp, 2.0_dp]
   !> Snapshot records the probe keeps at most.
   integer, parameter :: probe_capacity = 1000

   !> What to run.
   type :: run_spec
      !> Part of the sweep the run belongs to.
      character(len=12) :: study = ''
      !> Discretisation: 'rod' or 'box'.
      character(len=8) :: scheme = 'rod'
      !> Static end tension, N; breaking time, s.
      real(dp) :: tension = 180.0e3_dp, t_break = 5.0e-3_dp
      !> Nodes.
      integer :: nodes = 121
      !> Courant number (c dt / ds); EI as a multiple of the paper's; time weight.
      real(dp) :: courant = 1, ei_factor = 1, theta = 0.5_dp
      !> End of the run, s (0: t_break + 2.2 L / c(eps0), past the front's reflection).
      real(dp) :: t_end = 0
      !> Snapshot interval, s (0: none but t_end). The box scheme fits whole steps into it.
      real(dp) :: interval = 0.01_dp
      !> Wall-clock limit of the dynamics, s.
      real(dp) :: wall_limit = 30
      !> A 3-D scene (scene_namelist) instead of the paper's break ('': the break).
      character(len=12) :: scene = ''
   end type run_spec

   !> Compression at the fixed end, one record per snapshot.
   type, extends(run_observer) :: compression_probe
      !> Bending stiffness of the run, N m^2.
      real(dp) :: bending_stiffness = 0
      !> Output arc lengths and the static curvature on them.
      real(dp), allocatable :: s(:), static_curvature(:)
      !> Snapshots recorded.
      integer :: n = 0
      !> Time, s; fixed-end tension, N; length of the compressed zone at the
      !> fixed end (T < 0), m; Euler load pi^2 EI / l^2 of that length, N;
      !> largest distance of the zone's nodes from its chord, m; largest
      !> |Omega3 - static| in the zone, 1/m; smallest strain in the zone.
      real(dp), allocatable :: time(:), wall_tension(:), length(:), euler_load(:), deflection(:), &
                               curvature(:), min_strain(:)
   contains
      procedure :: static => probe_static
      procedure :: snapshot => probe_snapshot
   end type compression_probe

   !> Figures of a run.
   type :: run_outcome
      !> Whether the run reached t_end; otherwise the named reason.
      logical :: complete = .false.
      character(:), allocatable :: reason
      !> End asked for, time reached, step asked for, s; Courant number taken.
      real(dp) :: t_end = 0, time_reached = 0, dt = 0, courant_used = 0
      !> Static sag, m.
      real(dp) :: sag = 0
      !> See the module doc.
      real(dp) :: energy_drift = 0, overshoot = 0, ringing = 0, speed_error = 0, drop_error = 0
      !> Numerical dissipation booked in the ledger (theta > 0.5, rod) and the initial strain energy, J.
      real(dp) :: dissipated = 0, strain_energy0 = 0
      !> Newton iterations in the hardest step and per accepted step; rejected attempts; accepted steps.
      integer :: max_newton = 0, rejected = 0, steps = 0
      real(dp) :: newton_per_step = 0
      !> Smallest accepted step but the last (which lands on t_end), s.
      real(dp) :: min_step = 0
      !> Wall time of the dynamics, s.
      real(dp) :: wall = 0
      !> Smallest fixed-end tension, N; peak speed of the released end, m/s.
      real(dp) :: min_wall_tension = 0, peak_end_speed = 0
      !> Box: largest |b0^2 + b3^2 - 1|. Rod: largest turning angle between two cells, rad.
      real(dp) :: max_unit_norm_error = 0, max_turning_angle = 0
      !> Smallest strain reached (rod: every cell; box: the two end nodes only, what its summary keeps).
      real(dp) :: min_strain = 0
      !> The run's warnings, one per line ('' : none).
      character(:), allocatable :: warnings
      !> Time the fixed end first went into compression, s (-1: never).
      real(dp) :: compression_time = -1
      !> Hardest Newton step and rejected attempts before and after that time.
      integer :: newton_tension = 0, newton_compression = 0, rejected_tension = 0, rejected_compression = 0
      !> Released end's position at release_times, m (NaN: not reached).
      real(dp) :: end_x(size(release_times)) = 0, end_z(size(release_times)) = 0
   end type run_outcome

contains

   !> The paper's tanh law and mass per length (for the references).
   subroutine paper_law(law, mass)
      !> The tanh law of eq. 17 with the paper's coefficients.
      class(material_law), allocatable, intent(out) :: law
      !> Mass per unstretched length, kg/m.
      real(dp), intent(out) :: mass
      type(case_config) :: config
      type(error_type), allocatable :: error
      ! The defaults of case_config name the tanh law, which new_law always knows (no error).
      call new_law(law, trim(config%law), config%p, config%ea, config%strain_max, error)
      mass = config%density*0.25_dp*acos(-1.0_dp)*config%diameter**2
   end subroutine paper_law

   !> Run one case and measure it; probe, if present, records the compressed zone.
   subroutine stress_run(spec, outcome, probe)
      !> What to run.
      type(run_spec), intent(in) :: spec
      !> Its figures.
      type(run_outcome), intent(out) :: outcome
      !> Compression probe (reset by the run's static state).
      type(compression_probe), intent(inout), optional :: probe
      type(case_config) :: config
      type(simulation), target :: sim
      type(run_history), pointer :: history
      type(run_summary), pointer :: summary
      type(static_info), pointer :: info
      type(error_type), allocatable :: error
      class(material_law), allocatable :: law
      real(dp) :: eps0, t_s, mass, theory, nan
      real(dp), allocatable :: wall_tension(:), end_speed(:)
      integer :: i, last, n

      nan = ieee_value(1.0_dp, ieee_quiet_nan)
      outcome%energy_drift = nan
      outcome%overshoot = nan
      outcome%ringing = nan
      outcome%speed_error = nan
      outcome%drop_error = nan
      outcome%end_x = nan
      outcome%end_z = nan
      outcome%warnings = ''
      call paper_law(law, mass)
      eps0 = law%strain_at(spec%tension)
      config%source = 'stress'
      config%scheme = spec%scheme
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
      config%t_end = spec%t_end
      if (spec%t_end <= 0) config%t_end = spec%t_break + 2.2_dp*config%length/wave_speed(law, mass, eps0)
      if (len_trim(spec%scene) > 0) call scene_config(spec, config, error)
      outcome%t_end = config%t_end
      if (.not. allocated(error)) call sim%prepare(config, error)
      if (allocated(error)) then
         outcome%reason = error%message
         if (error%stat == stat_input) outcome%reason = 'input: '//error%message
         if (error%stat /= stat_input) outcome%reason = 'statics: '//error%message
         return
      end if
      info => sim%static()
      outcome%sag = info%sag
      if (present(probe)) then
         probe%bending_stiffness = config%bending_stiffness
         call sim%run(probe, error)
      else
         call sim%run(error=error)
      end if
      history => sim%history()
      summary => sim%summary()
      outcome%complete = .not. allocated(error)
      outcome%reason = 'complete'
      if (allocated(error)) outcome%reason = error%message
      outcome%dt = summary%dt_requested
      outcome%courant_used = summary%courant_used
      outcome%time_reached = summary%time_reached
      outcome%energy_drift = summary%energy_drift
      outcome%dissipated = summary%dissipated
      if (allocated(history%energy)) outcome%strain_energy0 = history%energy(1, 0)
      outcome%max_newton = summary%max_newton_iterations
      outcome%rejected = summary%rejected_steps
      outcome%steps = summary%steps
      outcome%min_step = summary%dt_requested
      if (history%n >= 2) outcome%min_step = minval(history%step(1:history%n - 1))
      outcome%newton_per_step = real(summary%newton_iterations, dp)/max(summary%steps, 1)
      outcome%wall = summary%wall_time
      outcome%min_wall_tension = summary%min_fixed_end_tension
      outcome%peak_end_speed = summary%peak_end_speed
      outcome%max_unit_norm_error = summary%max_unit_norm_error
      outcome%max_turning_angle = summary%max_turning_angle
      outcome%min_strain = summary%min_strain
      if (allocated(summary%warnings)) outcome%warnings = summary%warnings

      ! Slot 1 is end a (held), slot 2 end b (released) in both schemes.
      n = history%n
      wall_tension = history%ends(5, 1, 0:n)
      end_speed = norm2(history%ends(3:4, 2, 0:n), 1)
      do i = 1, size(release_times)
         call end_position_at(history, release_times(i), outcome%end_x(i), outcome%end_z(i))
      end do
      ! The window: up to the first record with the fixed end in compression (index from 1 here).
      t_s = wall_tension(1)
      last = n + 1
      do i = 2, n + 1
         if (wall_tension(i) <= 0) then
            last = i - 1
            outcome%compression_time = history%time(i - 1)
            exit
         end if
      end do
      outcome%overshoot = max(0.0_dp, maxval(wall_tension(1:last)) - t_s)/spec%tension
      outcome%ringing = 0
      if (last >= 2) outcome%ringing = (sum(abs(wall_tension(2:last) - wall_tension(1:last - 1))) - &
                                        abs(wall_tension(last) - wall_tension(1)))/(2*spec%tension)
      outcome%newton_tension = maxval(history%newton_iterations(0:last - 1))
      outcome%rejected_tension = sum(history%rejected(0:last - 1))
      if (last < n + 1) then
         outcome%newton_compression = maxval(history%newton_iterations(last:n))
         outcome%rejected_compression = max(summary%rejected_steps - outcome%rejected_tension, 0)
      end if
      theory = riemann_speed(law, mass, law%strain_at(0.0_dp), eps0)
      outcome%speed_error = (maxval(end_speed(1:last)) - theory)/theory
      if (summary%front_arrival_time > 0) then
         outcome%drop_error = summary%front_arrival_time - &
                              wall_drop_time(law, mass, config%length, eps0, spec%t_break, 0.01_dp)
      end if
      ! The break's measures do not apply to the 3-D scenes.
      if (len_trim(spec%scene) > 0) then
         outcome%overshoot = nan
         outcome%ringing = nan
         outcome%speed_error = nan
         outcome%drop_error = nan
      end if
   end subroutine stress_run

   !> The namelist of a 3-D scene (&numerics model = '3d'; nodes, Courant
   !> number, EI and t_end from the spec, 60 m of the paper's cable):
   !> - slack3d: a slack line hanging between (0, 0, 0) and (40, 20, 0), let go
   !>   at end b over t_break (the off-plane slack release), to 2 s;
   !> - fairlead3d: in water (Morison drag, added mass), a current of 0.3 m/s
   !>   across the plane (y), the fairlead at (50, 0, 0) moving 1 m along y
   !>   (period 2 s, ramped over 0.5 s), to 4 s;
   !> - torque3d: end b loaded by a force (3000, 500, 1000) N and a torque of
   !>   200 N m, both ramped up over 0.5 s, to 2 s.
   function scene_namelist(spec) result(text)
      !> What to run (spec%scene names the scene).
      type(run_spec), intent(in) :: spec
      character(:), allocatable :: text
      character(len=200) :: numerics
      character(len=*), parameter :: nl = new_line('a')
      write (numerics, '(a,i0,a,g0.6,a,g0.6,a)') "&numerics model = '3d', nodes = ", spec%nodes, ', courant = ', &
         spec%courant, ', t_end = ', spec%t_end, ' /'
      text = "&cable bending_stiffness = "//real_text(spec%ei_factor*paper_bending_stiffness)//" /"//nl// &
             "&end_a kind = 'fixed', x = 0, z = 0 /"//nl//trim(numerics)//nl
      select case (trim(spec%scene))
      case ('slack3d')
         text = text//"&end_b kind = 'fixed', x = 40, y = 20, z = 0 /"//nl// &
                "&rupture s_break = 60, t_break = "//real_text(spec%t_break)//" /"
      case ('fairlead3d')
         text = text//"&end_b kind = 'motion', x = 50, z = 0, amplitude = 1, period = 2, direction_x = 0, "// &
                "direction_y = 1, direction_z = 0, ramp_time = 0.5 /"//nl// &
                "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = 0.3 /"// &
                nl//"&rupture enabled = .false. /"
      case ('torque3d')
         text = text//"&end_b kind = 'force', force_x = 3000, force_y = 500, force_z = 1000, torque = 200, "// &
                "history = 'ramp', ramp_time = 0.5 /"//nl//"&rupture enabled = .false. /"
      case default
         text = ''
      end select
   contains
      function real_text(x) result(t)
         real(dp), intent(in) :: x
         character(:), allocatable :: t
         character(len=32) :: buf
         write (buf, '(es22.15)') x
         t = trim(adjustl(buf))
      end function real_text
   end function scene_namelist

   !> The case of a 3-D scene: its namelist read as the program reads one
   !> (through build/stress_scene.nml), with the sweep's output settings.
   subroutine scene_config(spec, config, error)
      type(run_spec), intent(in) :: spec
      type(case_config), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: path = 'build/stress_scene.nml'
      character(:), allocatable :: text
      integer :: unit
      text = scene_namelist(spec)
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') text//new_line('a')//"&output interval = 0, energy = .true., quiet = .true. /"
      close (unit)
      call read_config(path, config, error)
      if (allocated(error)) return
      config%max_wall_time = spec%wall_limit
   end subroutine scene_config

   !> Position of the released end (slot 2) at time t, linear between the
   !> two records around it; NaN if the run did not get there.
   subroutine end_position_at(history, t, x, z)
      !> History of the run (slot 2: the released end).
      type(run_history), intent(in) :: history
      !> Time, s.
      real(dp), intent(in) :: t
      !> Position, m (left as it is if the run did not reach t).
      real(dp), intent(inout) :: x, z
      integer :: lo, hi, mid
      real(dp) :: w
      if (history%n < 1) return
      if (history%time(history%n) < t*(1 - 1.0e-12_dp)) return
      ! Bisection for time(lo) <= t <= time(hi).
      lo = 0
      hi = history%n
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (history%time(mid) <= t) then
            lo = mid
         else
            hi = mid
         end if
      end do
      w = 0
      if (history%time(hi) > history%time(lo)) w = min(max((t - history%time(lo))/(history%time(hi) - history%time(lo)), &
                                                           0.0_dp), 1.0_dp)
      x = (1 - w)*history%ends(1, 2, lo) + w*history%ends(1, 2, hi)
      z = (1 - w)*history%ends(2, 2, lo) + w*history%ends(2, 2, hi)
   end subroutine end_position_at

   !> Short name of how a run ended.
   function outcome_tag(complete, reason) result(tag)
      !> Whether the run completed; its reason otherwise.
      logical, intent(in) :: complete
      character(*), intent(in) :: reason
      character(:), allocatable :: tag
      if (complete) then
         tag = 'complete'
      else if (index(reason, 'input:') == 1) then
         tag = 'refused'
      else if (index(reason, 'statics:') == 1) then
         tag = 'statics'
      else if (index(reason, 'wall-clock') > 0) then
         tag = 'wall clock'
      else if (index(reason, 'rejected attempts by') > 0) then
         tag = 'step budget'
      else if (index(reason, 'collapsed') > 0) then
         tag = 'collapse'
      else if (index(reason, 'unit circle') > 0) then
         tag = 'frame lost'
      else if (index(reason, 'half a turn') > 0) then
         tag = 'fold'
      else if (index(reason, 'not finite') > 0 .or. index(reason, 'non-finite') > 0) then
         tag = 'non-finite'
      else if (index(reason, 'Newton') > 0 .or. index(reason, 'dgbtrf') > 0) then
         tag = 'newton'
      else
         tag = 'other'
      end if
   end function outcome_tag

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
      class(material_law), allocatable :: law
      real(dp) :: mass, eps_zero, lo, hi, mid
      integer :: it, j
      call paper_law(law, mass)
      eps0 = law%strain_at(tension)
      eps_zero = law%strain_at(0.0_dp)
      u_end = riemann_speed(law, mass, eps_zero, eps0)
      do j = 1, size(floors)
         capacity(j) = riemann_speed(law, mass, floors(j), eps_zero)
      end do
      ! Bisection on [-1000, eps_zero]: far in compression c tends to sqrt(p5 / m).
      lo = -1000
      hi = eps_zero
      do it = 1, 200
         mid = 0.5_dp*(lo + hi)
         if (riemann_speed(law, mass, mid, eps_zero) > u_end) then
            lo = mid
         else
            hi = mid
         end if
      end do
      eps_wall = 0.5_dp*(lo + hi)
      wall_tension = law%tension(eps_wall)
   end subroutine wall_reflection

   !> Keep the grid and the static curvature; start a new record (run_observer).
   subroutine probe_static(self, info, error)
      !> Probe.
      class(compression_probe), intent(inout) :: self
      !> The static state.
      type(static_info), intent(in) :: info
      !> Never set.
      type(error_type), allocatable, intent(out) :: error
      self%s = info%s
      self%static_curvature = info%fields(:, 8)
      self%n = 0
      if (.not. allocated(self%time)) then
         allocate (self%time(probe_capacity), self%wall_tension(probe_capacity), self%length(probe_capacity), &
                   self%euler_load(probe_capacity), self%deflection(probe_capacity), self%curvature(probe_capacity), &
                   self%min_strain(probe_capacity))
      end if
   end subroutine probe_static

   !> Measure the compressed zone at the fixed end (run_observer).
   subroutine probe_snapshot(self, t, fields, error)
      !> Probe.
      class(compression_probe), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Fields (nodes, n_fields): tension, shear, strain, u, v, x, z, curvature.
      real(dp), intent(in) :: fields(:, :)
      !> Never set.
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: zone, chord_x, chord_z, chord, dist
      integer :: k, last, np
      np = size(self%s)
      if (self%n == size(self%time)) return
      self%n = self%n + 1
      associate (tension => fields(:, 1), strain => fields(:, 3), x => fields(:, 6), z => fields(:, 7), &
                 omega => fields(:, 8))
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
         if (zone > 0) self%euler_load(self%n) = pi**2*self%bending_stiffness/zone**2
         self%deflection(self%n) = 0
         self%curvature(self%n) = 0
         self%min_strain(self%n) = strain(1)
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
            self%curvature(self%n) = max(self%curvature(self%n), abs(omega(k) - self%static_curvature(k)))
            self%min_strain(self%n) = min(self%min_strain(self%n), strain(k))
         end do
      end associate
   end subroutine probe_snapshot
end module stress_runs
