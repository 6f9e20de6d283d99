!> One driver for every run: from a validated case to its static state,
!> dynamics and records, whatever the discretisation. The program, the
!> examples, the benchmark and the tests all go through it:
!>
!>     call sim%prepare(config, error)   ! scene, grid, statics, time step
!>     call sim%run(observer, error)     ! dynamics; observer gets the snapshots
!>     sim%history(), sim%summary()      ! what the run produced
!>
!> prepare returns stat_input errors for an inconsistent case (nothing has
!> been written yet) and stat_numerics when the statics fails.
module xcable_simulation
   use xcable_kinds, only: dp
   use xcable_error, only: error_type, fatal_error, stat_input
   use xcable_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_scene, only: scene_type, scene_from_config
   use xcable_rod_run, only: rod_run, rod_run_options
   use xcable_box_run, only: box_run
   use xcable_run_records, only: run_history, run_summary, static_info, run_observer
   implicit none
   private
   public :: simulation, run_options_from_config

   !> Inertia kept by the shortest wave (two cells) with the averaged mass
   !> matrix, as a fraction of the lumped one (model/rod.f90, docs/numerics.md).
   real(dp), parameter, public :: averaged_sawtooth_mass = 0.1_dp

   !> A run of a case.
   type :: simulation
      !> 'rod' or 'box'.
      character(len=8) :: scheme = 'rod'
      !> The run of each scheme (only one is used).
      type(rod_run) :: rod
      type(box_run) :: box
      !> What the model computes, for the result file.
      character(:), allocatable :: terms
   contains
      procedure :: prepare => sim_prepare
      procedure :: run => sim_run
      !> Output node arc lengths.
      procedure :: output_s => sim_output_s
      !> Output columns where a new piece starts.
      procedure :: piece_starts => sim_piece_starts
      !> The time step (s) and number of steps asked for.
      procedure :: time_step => sim_time_step
      !> Pointers to the records.
      procedure :: history => sim_history
      procedure :: summary => sim_summary
      procedure :: static => sim_static
   end type simulation

contains

   !> Controls of a rod run from a case. reuse_jacobian keeps the scheme's
   !> default unless the case gives it: the rod refactors at every iteration
   !> (its factorisation is cheap and full Newton converges in 2-4 iterations),
   !> the box scheme keeps its factorisation while Newton contracts well.
   function run_options_from_config(config) result(options)
      !> Validated case.
      type(case_config), intent(in) :: config
      type(rod_run_options) :: options
      options%nodes = config%nodes
      options%dt = config%dt
      options%courant = config%courant
      options%t_end = config%t_end
      options%theta = config%theta
      options%mu = merge(1.0_dp, 0.0_dp, trim(config%mass_matrix) == 'averaged')
      options%mu2 = merge(averaged_sawtooth_mass, 0.0_dp, trim(config%mass_matrix) == 'averaged')
      options%damping = config%damping
      options%interval = config%interval
      options%newton%tolerance = config%newton_tol
      options%newton%max_iterations = config%newton_max_iter
      options%newton%reuse_jacobian = config%reuse_jacobian .and. config%is_given('numerics', 'reuse_jacobian')
      options%extrapolate = config%extrapolate
      options%energy = config%energy
      options%min_step_fraction = config%min_step_fraction
      options%max_wall_time = config%max_wall_time
   end function run_options_from_config

   !> Scene, grid, statics and time step of a validated case.
   subroutine sim_prepare(self, config, error)
      !> Simulation.
      class(simulation), intent(inout) :: self
      !> Validated case.
      type(case_config), intent(in) :: config
      !> Error: stat_input for an inconsistent case, stat_numerics when the statics fails.
      type(error_type), allocatable, intent(out) :: error
      type(scene_type) :: scene
      type(rod_run) :: fresh_rod
      type(box_run) :: fresh_box
      ! A simulation may be prepared again for another case.
      self%rod = fresh_rod
      self%box = fresh_box
      self%scheme = trim(config%scheme)
      select case (self%scheme)
      case ('box')
         call self%box%prepare(config, error)
         self%terms = 'box scheme (eqs. 18-25): strain bending gravity; end b released by the ramp'
      case default
         call scene_from_config(config, scene, error)
         if (allocated(error)) return
         call self%rod%prepare(scene, run_options_from_config(config), error)
         self%terms = terms_of(scene)
         if (config%damping > 0) self%terms = self%terms//' damping'
      end select
   end subroutine sim_prepare

   !> What the rod model computes for a scene.
   function terms_of(scene) result(terms)
      type(scene_type), intent(in) :: scene
      character(:), allocatable :: terms
      integer :: k
      terms = 'rod: strain bending'
      if (scene%gravity > 0) terms = terms//' gravity'
      if (scene%end_a%point_mass() > 0 .or. scene%end_b%point_mass() > 0) terms = terms//' point_mass'
      if (scene%end_a%kind() == 'force' .or. scene%end_b%kind() == 'force') terms = terms//' end_force'
      if (scene%end_a%kind() == 'motion' .or. scene%end_b%kind() == 'motion') terms = terms//' end_motion'
      if (scene%breaks) terms = terms//' break'
      if (index(scene%law%name(), 'without compression') > 0) terms = terms//' tension_only'
      if (scene%law%name() == 'table' .or. index(scene%law%name(), 'table ') == 1) terms = terms//' table_law'
      if (allocated(scene%loads)) then
         do k = 1, size(scene%loads)
            terms = terms//' '//scene%loads(k)%load%name()
         end do
      end if
   end function terms_of

   !> The dynamics.
   subroutine sim_run(self, observer, error)
      !> Simulation (prepared).
      class(simulation), intent(inout) :: self
      !> Receives the static state and the snapshots.
      class(run_observer), intent(inout), optional :: observer
      !> Error when the run cannot go on (the records hold what was done).
      type(error_type), allocatable, intent(out) :: error
      select case (self%scheme)
      case ('box')
         call self%box%run(observer, error)
      case default
         call self%rod%run(observer, error)
      end select
   end subroutine sim_run

   function sim_output_s(self) result(s)
      class(simulation), intent(in) :: self
      real(dp), allocatable :: s(:)
      if (self%scheme == 'box') then
         s = self%box%s
      else
         s = self%rod%s_out
      end if
   end function sim_output_s

   function sim_piece_starts(self) result(starts)
      class(simulation), intent(in) :: self
      integer, allocatable :: starts(:)
      allocate (starts(0))
      if (self%scheme /= 'box') then
         if (self%rod%break_node > 0) starts = [self%rod%break_node + 1]
      end if
   end function sim_piece_starts

   subroutine sim_time_step(self, dt, steps)
      class(simulation), intent(in) :: self
      real(dp), intent(out) :: dt
      integer, intent(out) :: steps
      if (self%scheme == 'box') then
         dt = self%box%dynamics%dt
         steps = ceiling(self%box%dynamics%t_end/dt)
      else
         dt = self%rod%dt
         steps = ceiling(self%rod%options%t_end/dt)
      end if
   end subroutine sim_time_step

   function sim_history(self) result(p)
      class(simulation), intent(in), target :: self
      type(run_history), pointer :: p
      if (self%scheme == 'box') then
         p => self%box%history
      else
         p => self%rod%history
      end if
   end function sim_history

   function sim_summary(self) result(p)
      class(simulation), intent(in), target :: self
      type(run_summary), pointer :: p
      if (self%scheme == 'box') then
         p => self%box%summary
      else
         p => self%rod%summary
      end if
   end function sim_summary

   function sim_static(self) result(p)
      class(simulation), intent(in), target :: self
      type(static_info), pointer :: p
      if (self%scheme == 'box') then
         p => self%box%info
      else
         p => self%rod%info
      end if
   end function sim_static
end module xcable_simulation
