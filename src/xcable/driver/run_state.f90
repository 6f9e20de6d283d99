!> What a run carries besides its pieces and its records: its controls (rod_run_options), where
!> the step loop stands between two steps (run_progress, kept in a checkpoint), this process's
!> clock (run_clock), the search for a break by tension (tension_watch), and the step loop's
!> constants (why it paused, the most steps, the break by tension's tolerance). The run
!> (driver/rod_run.f90, rod_run) holds one of each.
module xcable_driver_run_state
   use xcable_core_kinds, only: dp, i8
   use xcable_solver_newton, only: newton_options
   implicit none
   private

   !> Why advance returned: the run ended (t_end or an error), a checkpoint is
   !> due, or SIGTERM arrived.
   integer, parameter, public :: pause_none = 0, pause_checkpoint = 1, pause_termination = 2

   !> Most time steps a run may ask for.
   integer, parameter, public :: max_steps = 1000000

   !> The break by tension (&rupture criterion = 'tension'): a step whose largest cell tension
   !> passes mbl by more than rupture_tolerance mbl is taken again, shorter, aimed at the time
   !> where that cell's tension, linear between the step's two levels, reaches mbl; a step that
   !> ends within rupture_tolerance mbl of it ends the search (docs/theory/numerics.md, "The
   !> break by tension"). At most max_rupture_aims aims at one crossing.
   real(dp), parameter, public :: rupture_tolerance = 1.0e-4_dp
   integer, parameter, public :: max_rupture_aims = 40

   !> The search for a break by tension (the first pass of such a run, driver/simulation.f90),
   !> and what it found, for the summary of the run with the break.
   type, public :: tension_watch
      !> Minimum breaking load, N (0: no search).
      real(dp) :: mbl = 0
      !> Whether a cell reached mbl; when (s), which cell, the tension it reached (N) and the
      !> middle of that cell (m).
      logical :: found = .false.
      real(dp) :: time = 0, tension = 0, s = 0
      integer :: cell = 0
      !> The cell tensions at that time (N).
      real(dp), allocatable :: cells(:)
      !> Step aimed at the crossing (s; 0: none) and the aims at this crossing so far.
      real(dp) :: h_aim = 0
      integer :: aims = 0
      !> The bracket of the search: steps (s) below and past the crossing and their largest cell
      !> tensions (N); which end moved last (-1: below, 1: past, 0: none yet).
      real(dp) :: h_lo = 0, f_lo = 0, h_hi = 0, f_hi = 0
      integer :: side = 0
      !> The MBL of the cell that reached it (N; a line of segments: its segment's).
      real(dp) :: cell_mbl = 0
      !> Of the accepted steps, the cell closest to its MBL: its share of it (in units of mbl),
      !> its tension (N), its MBL (N), the middle of the cell (m) and the time (s).
      real(dp) :: max_share = 0, max_tension = 0, max_mbl = 0, max_s = 0, max_time = 0
   end type tension_watch

   !> Controls of a rod run.
   type, public :: rod_run_options
      !> Number of nodes.
      integer :: nodes = 121
      !> Time step (0: from the Courant number), Courant number, end of the run, s.
      real(dp) :: dt = 0, courant = 1, t_end = 0.16_dp
      !> Time weight of the new level (1/2: energy-conserving).
      real(dp) :: theta = 0.5_dp
      !> Share of the averaged mass matrix (1: averaged, 0: lumped), and the weight of the
      !> second-difference kinetic energy (model/rod.f90).
      real(dp) :: mu = 1, mu2 = 0
      !> Kelvin-Voigt damping c, N s.
      real(dp) :: damping = 0
      !> Snapshot interval, s (0: only t_end).
      real(dp) :: interval = 0.01_dp
      !> Newton controls of a time step (tolerance, iteration limit, reuse).
      type(newton_options) :: newton
      !> First guess of a step: R + dt V.
      logical :: extrapolate = .true.
      !> Keep the energy ledger.
      logical :: energy = .false.
      !> Solve each step only on the part of the cable that moves (see attempt): the nodes
      !> outside keep their state. Off (the default): every step solves the whole piece.
      logical :: skip_quiescent = .false.
      !> Smallest step of the step control, as a fraction of dt; wall-clock limit (s, 0: none).
      real(dp) :: min_step_fraction = 1.0_dp/1024, max_wall_time = 0
      !> Pause for a checkpoint every this many seconds of wall time (0: never).
      real(dp) :: checkpoint_interval = 0
      !> Pause for a checkpoint every this many accepted steps (0: never). Not a namelist variable:
      !> the tests' way to checkpoint at a known step.
      integer :: checkpoint_steps = 0
      !> Pause when SIGTERM has arrived (the program installs the handler, system/posix.f90).
      logical :: stop_on_termination = .false.
   end type rod_run_options

   !> Where the step loop stands between two steps: what it carries from one
   !> step to the next besides the state of the pieces (kept in a checkpoint).
   type, public :: run_progress
      !> Step the step control tries next, s.
      real(dp) :: h = 0
      !> Steps accepted since the step was last halved (it doubles after four), and attempts
      !> rejected since the last accepted step.
      integer :: n_good = 0, rejected_here = 0
      !> Index of the next snapshot (snapshot_time); snapshots 0 .. snapshot_index - 1 are written.
      integer :: snapshot_index = 1
      !> Wall time of the dynamics in the processes before this one (a resumed run), s.
      real(dp) :: wall_before = 0
   end type run_progress

   !> The wall clock of this process's part of a run (not kept in a checkpoint).
   type, public :: run_clock
      !> Clock count at the start (or the resume) and counts per second.
      integer(i8) :: start = 0, rate = 1
      !> Wall time (s, from start) of the last progress report and of the last checkpoint pause.
      real(dp) :: last_report = 0, last_checkpoint = 0
      !> History records at the last checkpoint pause (the next needs a step more).
      integer :: records_at_checkpoint = 0
   end type run_clock

end module xcable_driver_run_state
