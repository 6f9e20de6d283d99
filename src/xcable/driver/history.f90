!> The history of a run, kept by the driver for every model: one record per accepted step (and
!> the record of t = 0), with what the step loop knows (the time, the step, Newton's iterations,
!> the attempts rejected before it) and the model's part, which the model gives through
!> cable_model%record: the quantities of its ends (and their y components in 3-D), the loads'
!> measures, and the terms of the energy ledger (its energies and their sum, the work of the
!> ends and of the distributed loads, the dissipation), from which the driver makes the
!> ledger's columns (driver/records.f90, energy_names).
module xcable_driver_history
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str
   use xcable_loads_load, only: measure_names
   use xcable_io_archive, only: state_archive, sync_real, sync_reals, sync_matrix, sync_cube, sync_int, sync_ints
   use xcable_driver_records, only: n_end_quantities, n_end_quantities_y
   use xcable_driver_rod_run, only: rod_run, cable_model, max_steps
   implicit none
   private
   public :: open_history, append_record, hermite_levels, exchange_records

contains

   !> Open the history of a run (a model's begin, a checkpoint's load): its end slots and their
   !> labels (end_a, end_b; break_a, break_b with a break inside the cable), room for capacity
   !> records, the ledger when it is kept, the ends' y components (with_y: a 3-D model) and the
   !> loads' measures.
   subroutine open_history(run, capacity, with_y, end_labels)
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Records to make room for.
      integer, intent(in) :: capacity
      !> Keep the ends' y components.
      logical, intent(in) :: with_y
      !> The ends' labels (default: end_a, end_b, and break_a, break_b with a break inside the
      !> cable; a network of lines gives its own).
      character(len=8), intent(in), optional :: end_labels(:)
      integer :: n_ends
      if (allocated(run%history%end_labels)) deallocate (run%history%end_labels)
      if (present(end_labels)) then
         n_ends = size(end_labels)
         run%history%end_labels = end_labels
      else
         n_ends = merge(4, 2, run%break_node > 0)
         allocate (run%history%end_labels(n_ends))
         run%history%end_labels(1:2) = [character(len=8) :: 'end_a', 'end_b']
         if (n_ends == 4) run%history%end_labels(3:4) = [character(len=8) :: 'break_a', 'break_b']
      end if
      call run%history%reserve(capacity, n_ends, run%options%energy, with_y=with_y)
      ! (The box scheme's run has no scene loads.)
      if (allocated(run%scene%loads)) call run%history%keep_measures(measure_names(run%scene%loads))
   end subroutine open_history

   !> Append a history record at run%t: the step taken, Newton's iterations and the attempts
   !> rejected before it, then the model's part (ends, measures, ledger).
   subroutine append_record(run, model, iterations, rejected, step)
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(inout) :: model
      !> Newton iterations of the step (the most of a piece) and attempts rejected before it.
      integer, intent(in) :: iterations, rejected
      !> The step, s.
      real(dp), intent(in) :: step
      real(dp), allocatable :: ends(:, :), ends_y(:, :), measures(:)
      real(dp) :: energies(4), stored, work(3)
      integer :: i, n_slots, n_measures
      associate (h => run%history)
         n_slots = size(h%end_labels)
         if (h%n + 1 > ubound(h%time, 1)) call h%reserve(2*ubound(h%time, 1), n_slots, run%options%energy)
         i = h%n + 1
         h%n = i
         h%time(i) = run%t
         h%step(i) = step
         h%newton_iterations(i) = iterations
         h%rejected(i) = rejected
         n_measures = 0
         if (allocated(h%measures)) n_measures = size(h%measures, 1)
         allocate (ends(n_end_quantities, n_slots), ends_y(n_end_quantities_y, n_slots), measures(n_measures))
      end associate
      if (i > 0) run%summary%max_newton_iterations = max(run%summary%max_newton_iterations, iterations)
      ends = 0
      ends_y = 0
      measures = 0
      energies = 0
      stored = 0
      work = 0
      call model%record(run, i, ends, ends_y, measures, energies, stored, work)
      associate (h => run%history)
         h%ends(:, :, i) = ends
         if (allocated(h%ends_y)) h%ends_y(:, :, i) = ends_y
         if (n_measures > 0) h%measures(:, i) = measures
         ! The ledger: the energies, the work of the ends, the dissipation, the balance (what is
         ! stored less the work done on the cable plus what it dissipated), the work of the loads.
         if (run%options%energy) then
            h%energy(1:4, i) = energies
            h%energy(5, i) = work(1)
            h%energy(6, i) = work(3)
            h%energy(7, i) = stored - work(1) - work(2) + work(3)
            h%energy(8, i) = work(2)
         end if
      end associate
   end subroutine append_record

   !> A snapshot inside a step (either rod model): cubic Hermite between the step's two levels,
   !> the positions r0, r1 and velocities v0, v1 of the same nodes ((2 or 3, n) each), at the
   !> fraction u of the step of h (clamped to 0 .. 1): the positions r there and the velocities
   !> v, their derivative (third order in the positions). The model gives its levels and makes
   !> its fields from r and v.
   pure subroutine hermite_levels(u, h, r0, v0, r1, v1, r, v)
      !> Fraction of the step; the step, s.
      real(dp), intent(in) :: u, h
      !> Positions (m) and velocities (m/s) at the start and at the end of the step.
      real(dp), intent(in) :: r0(:, :), v0(:, :), r1(:, :), v1(:, :)
      !> Positions and velocities at the fraction u.
      real(dp), intent(out) :: r(:, :), v(:, :)
      real(dp) :: w, h00, h10, h01, h11, d00, d10, d01, d11
      w = min(max(u, 0.0_dp), 1.0_dp)
      h00 = (1 + 2*w)*(1 - w)**2
      h10 = w*(1 - w)**2
      h01 = w*w*(3 - 2*w)
      h11 = w*w*(w - 1)
      d00 = 6*w*w - 6*w
      d10 = 3*w*w - 4*w + 1
      d01 = 6*w - 6*w*w
      d11 = 3*w*w - 2*w
      r = h00*r0 + h10*h*v0 + h01*r1 + h11*h*v1
      v = (d00*r0 + d01*r1)/h + d10*v0 + d11*v1
   end subroutine hermite_levels

   !> The records so far, listed for saving and loading (a checkpoint of either rod model:
   !> rod_run's exchange_state, rod3d_drive's exchange3): every history record (with the y
   !> components, ends_y, of a 3-D run) and the summary's counters and extremes; loading opens
   !> the history (open_history) with room for the rest of the run.
   subroutine exchange_records(self, a, saving, error, with_y, end_labels)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Archive.
      class(state_archive), intent(inout) :: a
      !> Save (.true.) or load.
      logical, intent(in) :: saving
      !> Error (stat_input) when the archive's history does not fit.
      type(error_type), allocatable, intent(inout) :: error
      !> The y components too (a 3-D run; default .false.).
      logical, intent(in), optional :: with_y
      !> The ends' labels, when not the cable's own (a network of lines).
      character(len=8), intent(in), optional :: end_labels(:)
      integer :: n_records
      logical :: y_kept
      y_kept = .false.
      if (present(with_y)) y_kept = with_y
      ! The history: every record so far.
      n_records = self%history%n
      call sync_int(a, 'history/n', n_records, saving)
      if (.not. saving) then
         if (.not. a%ok) return
         if (n_records < 0 .or. a%stored_size('history/time') /= n_records + 1) then
            call fatal_error(error, 'the checkpoint''s history has '//str(n_records)//' records but '// &
                             str(a%stored_size('history/time'))//' times', stat_input)
            return
         end if
         call open_history(self, max(n_records, int(min(self%options%t_end/self%dt, real(max_steps, dp)))) + 16, y_kept, &
                           end_labels)
         self%history%n = n_records
      end if
      associate (h => self%history, m => n_records)
         call sync_reals(a, 'history/time', h%time(0:m), saving)
         call sync_reals(a, 'history/step', h%step(0:m), saving)
         call sync_ints(a, 'history/newton_iterations', h%newton_iterations(0:m), saving)
         call sync_ints(a, 'history/rejected', h%rejected(0:m), saving)
         call sync_cube(a, 'history/ends', h%ends(:, :, 0:m), saving)
         if (self%options%energy) call sync_matrix(a, 'history/energy', h%energy(:, 0:m), saving)
         if (y_kept) call sync_cube(a, 'history/ends_y', h%ends_y(:, :, 0:m), saving)
         if (allocated(h%measures)) call sync_matrix(a, 'history/measures', h%measures(:, 0:m), saving)
      end associate

      ! The summary's counters and extremes so far (summarise derives the rest at the end).
      associate (s => self%summary)
         call sync_int(a, 'summary/rejected_steps', s%rejected_steps, saving)
         call sync_int(a, 'summary/newton_iterations', s%newton_iterations, saving)
         call sync_int(a, 'summary/max_newton_iterations', s%max_newton_iterations, saving)
         call sync_int(a, 'summary/factorisations', s%factorisations, saving)
         call sync_real(a, 'summary/dt_requested', s%dt_requested, saving)
         call sync_real(a, 'summary/dt_used', s%dt_used, saving)
         call sync_real(a, 'summary/courant_requested', s%courant_requested, saving)
         call sync_real(a, 'summary/max_turning_angle', s%max_turning_angle, saving)
         call sync_real(a, 'summary/min_strain', s%min_strain, saving)
         call sync_real(a, 'summary/min_strain_s', s%min_strain_s, saving)
         call sync_real(a, 'summary/min_strain_time', s%min_strain_time, saving)
         call sync_real(a, 'summary/max_strain', s%max_strain, saving)
      end associate
   end subroutine exchange_records

end module xcable_driver_history
