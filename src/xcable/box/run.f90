!> The paper's box scheme (&numerics scheme = 'box') as a run: its statics
!> (statics.f90) and its time stepping (dynamics.f90) as they were in version
!> 0.1, so that they reproduce its results to the last digit, with their
!> results translated into the records every run produces (run_records.f90).
!> The box scheme describes the paper's scene only: end a fixed, end b fixed
!> and released by the break (s_break = L), the end tension given.
module xcable_box_run
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str, real_text
   use xcable_io_config, only: case_config
   use xcable_box_case, only: setup_case
   use xcable_box_equations, only: cable_model, n_eq, i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om
   use xcable_box_geometry, only: positions, fixed_frame_velocity
   use xcable_solver_newton, only: newton_options
   use xcable_box_statics, only: static_state, solve_statics
   use xcable_box_dynamics, only: dynamics_options, box_history => run_history, box_summary => run_summary, &
                              box_observer => run_observer, run_rupture, rupture_factor
   use xcable_driver_records, only: run_history, run_summary, static_info, run_observer, n_fields, n_energy
   implicit none
   private
   public :: box_run, box_supports

   !> A box-scheme run.
   type :: box_run
      !> Cable data, grid and controls of the box scheme.
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dynamics
      !> End tension, N; Courant number asked for.
      real(dp) :: tension = 0, courant = 1
      !> Static state.
      type(static_state) :: state
      type(static_info) :: info
      !> Records.
      type(run_history) :: history
      type(run_summary) :: summary
   contains
      procedure :: prepare => box_prepare
      procedure :: run => box_run_dynamics
   end type box_run

   !> Passes the box scheme's snapshots on as fields.
   type, extends(box_observer) :: box_forward
      class(run_observer), pointer :: target => null()
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
   contains
      procedure :: snapshot => forward_snapshot
   end type box_forward

contains

   !> Whether the box scheme can describe the scene of a case ('' : yes; else why not).
   function box_supports(config) result(why)
      !> The case.
      type(case_config), intent(in) :: config
      character(:), allocatable :: why
      why = ''
      if (trim(config%end_a%kind) /= 'fixed' .or. trim(config%end_b%kind) /= 'fixed') then
         why = 'the box scheme describes the paper''s scene only: &end_a and &end_b fixed (here '// &
               trim(config%end_a%kind)//' and '//trim(config%end_b%kind)//')'
      else if (config%is_given('end_b', 'x') .or. config%is_given('end_b', 'z') .or. config%is_given('end_a', 'x') &
               .or. config%is_given('end_a', 'z')) then
         why = 'the box scheme takes the end tension (&static tension), not end positions'
      else if (.not. config%break_enabled) then
         why = 'the box scheme runs the paper''s rupture only (&rupture enabled = .true.)'
      else if (config%s_break >= 0 .and. abs(config%s_break - config%length) > 1.0e-12_dp*config%length) then
         why = 'the box scheme breaks the cable at end b only (s_break = L)'
      else if (config%break_time /= 0) then
         why = 'the box scheme starts the break at t = 0 only'
      else if (config%gravity < 1.0e-6_dp) then
         why = 'the box scheme needs gravity >= 1e-6 (without weight its static cable may turn freely)'
      else if (trim(config%law) /= 'tanh' .and. trim(config%law) /= 'linear') then
         why = 'the box scheme has the tanh and linear laws only'
      else if (config%damping /= 0) then
         why = 'the box scheme has no internal damping'
      else if (config%fluid_density /= 0 .or. config%air_density /= 0) then
         why = 'the box scheme has no fluid loads'
      else if (trim(config%compression) /= 'law') then
         why = 'the box scheme has the law''s compression only (compression = ''law'')'
      end if
   end function box_supports

   !> Model, grid, controls and the statics.
   subroutine box_prepare(self, config, error)
      !> Run.
      class(box_run), intent(inout) :: self
      !> Validated case.
      type(case_config), intent(in) :: config
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      character(:), allocatable :: why
      if (config%checkpoint_interval > 0) then
         call fatal_error(error, config%source//': &output: checkpoint_interval = '//real_text(config%checkpoint_interval)// &
                          ': the box scheme writes no checkpoints; must be 0 with scheme = ''box'' (or use '// &
                          'scheme = ''rod'')', stat_input)
         return
      end if
      why = box_supports(config)
      if (len(why) > 0) then
         call fatal_error(error, config%source//': &numerics: scheme = ''box'': '//why//'; use scheme = ''rod''', &
                          stat_input)
         return
      end if
      call setup_case(config, self%model, self%s, self%newton, self%dynamics, error)
      if (allocated(error)) return
      self%tension = config%tension
      self%courant = config%courant
      call solve_statics(self%model, self%s, config%tension, self%newton, self%state, error)
      if (allocated(error)) return
      self%info%s = self%s
      allocate (self%info%fields(size(self%s), n_fields))
      call state_fields(self%model, self%s, self%state%y, self%info%fields)
      self%info%span = self%state%span
      self%info%sag = self%state%sag
      self%info%end_angle = self%state%end_angle
      self%info%tension_a = self%info%fields(1, 1)
      self%info%tension_b = self%info%fields(size(self%s), 1)
      self%info%newton_iterations = self%state%newton%iterations
      self%info%beta0 = self%state%y(i_b0, :)
      self%info%beta3 = self%state%y(i_b3, :)
   end subroutine box_prepare

   !> The eight output fields of a box-scheme state.
   subroutine state_fields(model, s, y, fields)
      type(cable_model), intent(in) :: model
      real(dp), intent(in) :: s(:), y(:, :)
      real(dp), intent(out) :: fields(:, :)
      real(dp) :: x(size(s)), z(size(s))
      call positions(y, s, x, z)
      fields(:, 1) = model%law%tension(y(i_eps, :))
      fields(:, 2) = y(i_sn, :)
      fields(:, 3) = y(i_eps, :)
      fields(:, 4) = y(i_u, :)
      fields(:, 5) = y(i_v, :)
      fields(:, 6) = x
      fields(:, 7) = z
      fields(:, 8) = y(i_om, :)
   end subroutine state_fields

   subroutine forward_snapshot(self, t, y, error)
      class(box_forward), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: y(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: fields(:, :)
      if (.not. associated(self%target)) return
      allocate (fields(size(self%s), n_fields))
      call state_fields(self%model, self%s, y, fields)
      call self%target%snapshot(t, fields, error)
   end subroutine forward_snapshot

   !> The dynamics, and the records.
   subroutine box_run_dynamics(self, observer, error)
      !> Run (prepared).
      class(box_run), intent(inout) :: self
      !> Receives the static state and snapshots.
      class(run_observer), intent(inout), target, optional :: observer
      !> Error when the run cannot go on.
      type(error_type), allocatable, intent(out) :: error
      type(box_forward) :: forward
      type(box_history) :: old
      type(box_summary) :: old_summary
      integer :: i, n, np
      real(dp) :: vx, vz, c2, s2, f, ds, c0, force_h, force_v
      if (present(observer)) then
         call observer%static(self%info, error)
         if (allocated(error)) return
         forward%target => observer
      end if
      forward%model = self%model
      forward%s = self%s
      call run_rupture(self%model, self%s, self%state%y, self%dynamics, old, old_summary, error, forward)
      ! Records: end a (fixed) and end b (released).
      n = old%n
      np = size(self%s)
      allocate (self%history%end_labels(2))
      self%history%end_labels = [character(len=8) :: 'end_a', 'end_b']
      call self%history%reserve(n, 2, allocated(old%energy))
      self%history%n = n
      self%history%time(0:n) = old%time(0:n)
      self%history%step(0:n) = old%step(0:n)
      self%history%newton_iterations(0:n) = old%newton_iterations(0:n)
      self%history%rejected(0:n) = old%rejected(0:n)
      associate (y0 => self%state%y(:, np))
         f = self%model%law%tension(y0(i_eps))
         force_v = f*(y0(i_b0)**2 - y0(i_b3)**2) - y0(i_sn)*2*y0(i_b0)*y0(i_b3)
         force_h = f*2*y0(i_b0)*y0(i_b3) + y0(i_sn)*(y0(i_b0)**2 - y0(i_b3)**2)
      end associate
      do i = 0, n
         associate (ya => old%end_y(:, 1, i), yb => old%end_y(:, 2, i))
            ! End a: the force the support exerts balances T t + Sn n there.
            f = self%model%law%tension(ya(i_eps))
            c2 = ya(i_b0)**2 - ya(i_b3)**2
            s2 = 2*ya(i_b0)*ya(i_b3)
            self%history%ends(:, 1, i) = [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, f, -(f*s2 + ya(i_sn)*c2), -(f*c2 - ya(i_sn)*s2)]
            call fixed_frame_velocity(yb, vx, vz)
            f = self%model%law%tension(yb(i_eps))
            self%history%ends(:, 2, i) = [old%end_position(:, i), vx, vz, f, &
                                          rupture_factor(old%time(i), self%dynamics%t_break)*[force_h, force_v]]
         end associate
         if (allocated(old%energy)) then
            self%history%energy(1:5, i) = old%energy(1:5, i)
            self%history%energy(6, i) = 0
            self%history%energy(7, i) = old%energy(6, i)
            self%history%energy(8, i) = 0
         end if
      end do
      ! Summary: the box scheme's own figures, and per end.
      associate (s => self%summary)
         s%peak_end_speed = old_summary%peak_end_speed
         s%peak_end_speed_time = old_summary%peak_end_speed_time
         s%min_fixed_end_tension = old_summary%min_fixed_end_tension
         s%min_fixed_end_tension_time = old_summary%min_fixed_end_tension_time
         s%front_arrival_time = old_summary%front_arrival_time
         s%energy_drift = old_summary%energy_drift
         s%steps = old_summary%steps
         s%rejected_steps = old_summary%rejected_steps
         s%newton_iterations = old_summary%newton_iterations
         s%max_newton_iterations = old_summary%max_newton_iterations
         s%factorisations = old_summary%factorisations
         s%time_reached = old_summary%time_reached
         s%wall_time = old_summary%wall_time
         s%max_unit_norm_error = old_summary%max_unit_norm_error
         s%min_strain = old%min_strain
         s%max_strain = old%max_strain
         ds = self%s(2) - self%s(1)
         c0 = sqrt(self%model%law%stiffness(self%state%y(i_eps, np))/self%model%mass)
         s%dt_requested = self%courant*ds/c0
         s%dt_used = maxval(old%step(1:max(n, 1)))
         s%courant_requested = self%courant
         s%courant_used = s%dt_used*c0/ds
         allocate (s%ends(2))
         s%ends(1)%min_tension = old_summary%min_fixed_end_tension
         s%ends(1)%min_tension_time = old_summary%min_fixed_end_tension_time
         s%ends(1)%max_tension = maxval(self%history%ends(5, 1, 0:n))
         s%ends(1)%front_arrival_time = old_summary%front_arrival_time
         s%ends(2)%peak_speed = old_summary%peak_end_speed
         s%ends(2)%peak_speed_time = old_summary%peak_end_speed_time
         s%ends(2)%min_tension = minval(self%history%ends(5, 2, 0:n))
         s%ends(2)%max_tension = maxval(self%history%ends(5, 2, 0:n))
         s%warnings = ''
         if (s%energy_drift > 0.01_dp) call warn('the energy ledger drifted by '//str(100*s%energy_drift)// &
                                                 ' % of the initial strain energy (more than 1 %)')
         if (s%max_unit_norm_error > 0.05_dp) call warn('the Euler parameters left the unit circle by '// &
            str(s%max_unit_norm_error)//' (more than 0.05): the buckled zone is not resolved')
         if (s%rejected_steps > max(10, n/100)) call warn(str(s%rejected_steps)//' step attempts were rejected')
         if (abs(s%courant_used/s%courant_requested - 1) > 0.01_dp .and. self%dynamics%dt > 0) &
            call warn('the Courant number taken, '//str(s%courant_used)//', differs from the one asked for, '// &
                      str(s%courant_requested)//' (the box scheme fits whole steps into the snapshot interval)')
      end associate

   contains

      subroutine warn(line)
         character(*), intent(in) :: line
         if (len(self%summary%warnings) > 0) self%summary%warnings = self%summary%warnings//new_line('a')
         self%summary%warnings = self%summary%warnings//line
      end subroutine warn
   end subroutine box_run_dynamics
end module xcable_box_run
