!> What a run produces besides its snapshots: the history (one record per
!> accepted time step), the summary figures, the static state, and the
!> observer interface through which the output (or a test) receives them.
!>
!> Every scene has named ends: 'end_a' (s = 0) and 'end_b' (s = L), and for a
!> break inside the cable 'break_a' and 'break_b' (the two new ends, on the
!> side of end a and of end b). For each end the history keeps its position,
!> velocity, the tension of its cell and the external force on it (the
!> support's reaction for a held end, the applied force for a loaded one).
!> A 3-D run also keeps the y components (ends_y: y, vy, force_y).
module xcable_driver_records
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type
   use xcable_core_strings, only: str, quantity
   implicit none
   private
   public :: run_history, run_summary, static_info, run_observer, end_summary, static_figures, summary_text
   public :: slack_tension_fraction, note_min_strain
   public :: n_end_quantities, end_quantity_names, n_energy, energy_names, field_names, n_fields
   public :: n_end_quantities_y, end_quantity_names_y, n_fields3, field3_names

   !> An end counts as slack while its cell's tension is at most this fraction of the largest
   !> static tension (the summary's slack_time and slack intervals).
   real(dp), parameter :: slack_tension_fraction = 1.0e-3_dp

   !> Quantities recorded per end and step.
   integer, parameter :: n_end_quantities = 7
   character(len=*), parameter :: end_quantity_names(n_end_quantities) = &
      [character(len=8) :: 'x', 'z', 'vx', 'vz', 'tension', 'force_x', 'force_z']
   !> The y components a 3-D run records per end and step besides them.
   integer, parameter :: n_end_quantities_y = 3
   character(len=*), parameter :: end_quantity_names_y(n_end_quantities_y) = [character(len=8) :: 'y', 'vy', 'force_y']
   !> Energy ledger columns (J): ledger = strain + kinetic + bending + gravity - work - loads + dissipation;
   !> work: of the ends; loads: of the distributed loads (fluid drag and added mass).
   integer, parameter :: n_energy = 8
   character(len=*), parameter :: energy_names(n_energy) = &
      [character(len=11) :: 'strain', 'kinetic', 'bending', 'gravity', 'work', 'dissipation', 'ledger', 'loads']
   !> Snapshot fields, in this order.
   integer, parameter :: n_fields = 8
   character(len=*), parameter :: field_names(n_fields) = &
      [character(len=9) :: 'tension', 'shear', 'strain', 'u', 'v', 'x', 'z', 'curvature']
   !> Fields a 3-D run writes besides them (driver/rod3d_fields.f90): y, the
   !> velocity along the global y axis (vy), the curvature about z (the plan view's), the
   !> twist rate Omega1 = dpsi/ds, the shear force along the binormal (Sb)
   !> and the curvature about the normal (Omega2); their units and descriptions are in
   !> the output registry (io/output_registry.f90).
   integer, parameter :: n_fields3 = 6
   character(len=*), parameter :: field3_names(n_fields3) = &
      [character(len=14) :: 'y', 'vy', 'curvature_z', 'twist', 'binormal_shear', 'curvature_n']

   !> One record per accepted step (index 0: the static state at t = 0).
   type :: run_history
      !> Number of accepted steps.
      integer :: n = 0
      !> Time and step taken, s.
      real(dp), allocatable :: time(:), step(:)
      !> Newton iterations of the accepted step and attempts rejected before it.
      integer, allocatable :: newton_iterations(:), rejected(:)
      !> Names of the ends.
      character(len=8), allocatable :: end_labels(:)
      !> End quantities (n_end_quantities, ends, 0:n).
      real(dp), allocatable :: ends(:, :, :)
      !> The y components of a 3-D run (n_end_quantities_y, ends, 0:n); not allocated for a planar run.
      real(dp), allocatable :: ends_y(:, :, :)
      !> Energy ledger (n_energy, 0:n), J, when asked for.
      real(dp), allocatable :: energy(:, :)
      !> Lengths the loads measure along the cable (the wetted length, ...): their names and
      !> values (names, 0:n), m; not allocated when no load measures one.
      character(len=32), allocatable :: measure_names(:)
      real(dp), allocatable :: measures(:, :)
   contains
      !> Make room for at least n records (keeps the content).
      procedure :: reserve => history_reserve
      !> Keep the loads' measures of these names (none: nothing kept).
      procedure :: keep_measures => history_keep_measures
   end type run_history

   !> Figures of one end.
   type :: end_summary
      !> Largest speed |V| (m/s) and when (s).
      real(dp) :: peak_speed = 0, peak_speed_time = 0
      !> Smallest and largest tension of the end cell (N), and when the smallest happened (s).
      real(dp) :: min_tension = 0, min_tension_time = 0, max_tension = 0
      !> First time the end force falls 1 % below its value at t = 0 (s; -1: never). Held ends only.
      real(dp) :: front_arrival_time = -1
      !> When the largest tension happened (s).
      real(dp) :: max_tension_time = 0
      !> Kind of the end at the end of the run ('fixed', 'motion', ..., 'break').
      character(len=16) :: kind = ''
      !> Time the end was slack (its cell's tension at most slack_tension_fraction of the
      !> largest static tension), s, and those intervals (2, k: start and end, s).
      real(dp) :: slack_time = 0
      real(dp), allocatable :: slack_intervals(:, :)
   end type end_summary

   !> Figures of a run.
   type :: run_summary
      !> Per end, in the order of run_history%end_labels.
      type(end_summary), allocatable :: ends(:)
      !> The paper's figures: the largest speed of a released (breaking) end, m/s, and when;
      !> the smallest tension at end a, N, and when; the 1 % drop of the end-a force, s.
      real(dp) :: peak_end_speed = 0, peak_end_speed_time = 0
      real(dp) :: min_fixed_end_tension = 0, min_fixed_end_tension_time = 0
      real(dp) :: front_arrival_time = -1
      !> Which end had the peak speed; whether the scene has a fixed end (min_fixed_end_tension
      !> is of its fixed ends only) and whether a front arrived (after a break: front_arrival_time).
      character(len=8) :: peak_end_speed_end = ''
      logical :: has_fixed_end = .false., has_front = .false.
      !> The break, when it happened: the time it started (s), its arc length from end a (m) and the
      !> duration of its force ramp (s).
      logical :: broke = .false.
      real(dp) :: break_time = 0, break_s = 0, break_ramp = 0
      !> A network: the line that parted (&line_k; 0: a single line). Its break_s, break_cell_s and
      !> largest_tension_s are on the results' arc length (the lines laid out one after another).
      integer :: break_line = 0
      !> The break by tension (&rupture criterion = 'tension'): whether it was asked for, the
      !> minimum breaking load (N); of a break, the tension the first cell reached (N) and the
      !> middle of that cell (m); without one, the largest cell tension reached (N), where (the
      !> cell's middle, m) and when (s).
      logical :: by_tension = .false.
      real(dp) :: mbl = 0, break_tension = 0, break_cell_s = 0
      real(dp) :: largest_tension = 0, largest_tension_s = 0, largest_tension_time = 0
      !> max |ledger - ledger(0)| / strain energy at t = 0 (-1: ledger not kept), and the
      !> numerical dissipation booked in the ledger (J).
      real(dp) :: energy_drift = -1, dissipated = 0
      !> Accepted and rejected steps; Newton iterations (total, largest per step); factorisations.
      integer :: steps = 0, rejected_steps = 0, newton_iterations = 0, max_newton_iterations = 0, factorisations = 0
      !> Simulated time reached and wall time of the dynamics, s.
      real(dp) :: time_reached = 0, wall_time = 0
      !> Time step asked for and the largest one taken (s); Courant number asked for and taken.
      real(dp) :: dt_requested = 0, dt_used = 0, courant_requested = 0, courant_used = 0
      !> Box scheme: largest |b0^2 + b3^2 - 1|. Rod: largest turning angle between two cells (rad).
      real(dp) :: max_unit_norm_error = 0, max_turning_angle = 0
      !> Smallest and largest strain reached.
      real(dp) :: min_strain = 0, max_strain = 0
      !> Where (arc length of the cell's middle, m) and when (s) the smallest strain was reached.
      real(dp) :: min_strain_s = 0, min_strain_time = 0
      !> Warnings: one line each ('' : none).
      character(:), allocatable :: warnings
      !> What the log says about the scene besides (a line partly out of the water, ...): one
      !> line each ('' : nothing).
      character(:), allocatable :: notes
      !> The loads' measures of the static state (run_history%measures at record 0), m, and their names.
      real(dp), allocatable :: static_measures(:)
      character(len=32), allocatable :: measure_names(:)
   end type run_summary

   !> The static state, with its fields on the output nodes.
   type :: static_info
      !> Node arc lengths, m.
      real(dp), allocatable :: s(:)
      !> Fields (nodes, n_fields), in the order of field_names.
      real(dp), allocatable :: fields(:, :)
      !> Horizontal distance between the ends, and the largest vertical distance below their chord, m.
      real(dp) :: span = 0, sag = 0
      !> Angle of the tangent at end a below the horizontal, rad.
      real(dp) :: end_angle = 0
      !> Tension at end a and end b, N.
      real(dp) :: tension_a = 0, tension_b = 0
      !> Angle of the cable below the horizontal where it leaves end b (towards end a), rad; the
      !> lowest point (height z, m, and arc length s, m); the largest tension, N (static_figures).
      real(dp) :: end_angle_b = 0, lowest_z = 0, lowest_s = 0, max_tension = 0
      !> Newton iterations.
      integer :: newton_iterations = 0
      !> Euler parameters of the box scheme (absent for the rod).
      real(dp), allocatable :: beta0(:), beta3(:)
      !> Fields of a 3-D run besides field_names (nodes, n_fields3), in the order of field3_names
      !> (absent in 2-D).
      real(dp), allocatable :: extra(:, :)
      !> Whether it is one line between two ends (not a network of lines): span, sag, the end
      !> angles and tensions and the lowest point are written only then.
      logical :: one_line = .true.
   end type static_info

   !> Receives the static state and the snapshots of a run (the output file, or a test).
   type, abstract :: run_observer
   contains
      !> The static state.
      procedure(static_interface), deferred :: static
      !> One snapshot.
      procedure(snapshot_interface), deferred :: snapshot
      !> Progress of the run (default: nothing).
      procedure :: progress => observer_progress
      !> Fields of a snapshot besides field_names, sent after it (the 3-D run's y, w, ...; default: nothing).
      procedure :: snapshot_extra => observer_snapshot_extra
   end type run_observer

   abstract interface
      subroutine static_interface(self, info, error)
         import :: run_observer, static_info, error_type
         !> Observer.
         class(run_observer), intent(inout) :: self
         !> The static state.
         type(static_info), intent(in) :: info
         !> Error when writing fails.
         type(error_type), allocatable, intent(out) :: error
      end subroutine static_interface
      subroutine snapshot_interface(self, t, fields, error)
         import :: run_observer, dp, error_type
         !> Observer.
         class(run_observer), intent(inout) :: self
         !> Time, s.
         real(dp), intent(in) :: t
         !> Fields (nodes, n_fields) in the order of field_names.
         real(dp), intent(in) :: fields(:, :)
         !> Error when writing fails.
         type(error_type), allocatable, intent(out) :: error
      end subroutine snapshot_interface
   end interface

contains

   !> Default progress report: none.
   subroutine observer_progress(self, t, t_end, wall)
      !> Observer.
      class(run_observer), intent(inout) :: self
      !> Time reached and end of the run (s); wall time so far (s).
      real(dp), intent(in) :: t, t_end, wall
   end subroutine observer_progress

   !> Default extra fields: ignored.
   subroutine observer_snapshot_extra(self, t, names, fields, error)
      !> Observer.
      class(run_observer), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Names of the fields.
      character(*), intent(in) :: names(:)
      !> Fields (nodes, size(names)).
      real(dp), intent(in) :: fields(:, :)
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
   end subroutine observer_snapshot_extra

   !> Make room for at least n records (keeps the content).
   subroutine history_reserve(self, n, n_ends, energy, with_y)
      !> History.
      class(run_history), intent(inout) :: self
      !> Records needed (steps).
      integer, intent(in) :: n
      !> Number of ends.
      integer, intent(in) :: n_ends
      !> Whether the energy ledger is kept.
      logical, intent(in) :: energy
      !> Keep the y components too (a 3-D run; ends_y). Once kept, they grow with the rest.
      logical, intent(in), optional :: with_y
      real(dp), allocatable :: r(:), e(:, :), q(:, :, :)
      integer, allocatable :: i(:)
      integer :: m
      if (present(with_y)) then
         if (with_y .and. .not. allocated(self%ends_y) .and. allocated(self%time)) then
            allocate (self%ends_y(n_end_quantities_y, n_ends, 0:ubound(self%time, 1)))
            self%ends_y = 0
         end if
      end if
      if (allocated(self%time)) then
         if (ubound(self%time, 1) >= n) return
      end if
      if (.not. allocated(self%time)) then
         allocate (self%time(0:n), self%step(0:n), self%newton_iterations(0:n), self%rejected(0:n))
         allocate (self%ends(n_end_quantities, n_ends, 0:n))
         self%ends = 0
         if (energy) allocate (self%energy(n_energy, 0:n))
         if (present(with_y)) then
            if (with_y) then
               allocate (self%ends_y(n_end_quantities_y, n_ends, 0:n))
               self%ends_y = 0
            end if
         end if
         return
      end if
      m = self%n
      allocate (r(0:n)); r(0:m) = self%time(0:m); call move_alloc(r, self%time)
      allocate (r(0:n)); r(0:m) = self%step(0:m); call move_alloc(r, self%step)
      allocate (i(0:n)); i(0:m) = self%newton_iterations(0:m); call move_alloc(i, self%newton_iterations)
      allocate (i(0:n)); i(0:m) = self%rejected(0:m); call move_alloc(i, self%rejected)
      allocate (q(n_end_quantities, n_ends, 0:n)); q = 0; q(:, :, 0:m) = self%ends(:, :, 0:m)
      call move_alloc(q, self%ends)
      if (allocated(self%ends_y)) then
         allocate (q(n_end_quantities_y, n_ends, 0:n)); q = 0; q(:, :, 0:m) = self%ends_y(:, :, 0:m)
         call move_alloc(q, self%ends_y)
      end if
      if (energy) then
         allocate (e(n_energy, 0:n)); e(:, 0:m) = self%energy(:, 0:m); call move_alloc(e, self%energy)
      end if
      if (allocated(self%measures)) then
         allocate (e(size(self%measures, 1), 0:n)); e = 0; e(:, 0:m) = self%measures(:, 0:m)
         call move_alloc(e, self%measures)
      end if
   end subroutine history_reserve

   !> Keep the loads' measures of these names, from the next record on (after reserve).
   subroutine history_keep_measures(self, names)
      !> History.
      class(run_history), intent(inout) :: self
      !> Names of the measures.
      character(*), intent(in) :: names(:)
      if (allocated(self%measures)) deallocate (self%measures)
      if (allocated(self%measure_names)) deallocate (self%measure_names)
      if (size(names) == 0) return
      allocate (self%measure_names(size(names)))
      self%measure_names = names
      allocate (self%measures(size(names), 0:ubound(self%time, 1)))
      self%measures = 0
   end subroutine history_keep_measures

   !> The figures of the static state that follow from its fields: the angles at the ends (of
   !> the end cells below the horizontal, looking into the cable), the lowest point and the largest tension (y of a 3-D state from extra, horizontal distances
   !> in the plane of x and y).
   subroutine static_figures(info)
      !> The static state (fields set).
      type(static_info), intent(inout) :: info
      integer :: n, k
      real(dp) :: dx, dy, dz
      n = size(info%fields, 1)
      k = minloc(info%fields(:, 7), 1)
      info%lowest_z = info%fields(k, 7)
      info%lowest_s = info%s(k)
      info%max_tension = maxval(info%fields(:, 1))
      dx = info%fields(2, 6) - info%fields(1, 6)
      dz = info%fields(2, 7) - info%fields(1, 7)
      dy = 0
      if (allocated(info%extra)) dy = info%extra(2, 1) - info%extra(1, 1)
      info%end_angle = atan2(-dz, hypot(dx, dy))
      dx = info%fields(n - 1, 6) - info%fields(n, 6)
      dz = info%fields(n - 1, 7) - info%fields(n, 7)
      dy = 0
      if (allocated(info%extra)) dy = info%extra(n - 1, 1) - info%extra(n, 1)
      info%end_angle_b = atan2(-dz, hypot(dx, dy))
   end subroutine static_figures

   !> Keep the smallest strain of a piece's cells (lengths l1 over the unstretched ones) with
   !> where (the cell's middle, from the output columns of its nodes) and when it happened.
   subroutine note_min_strain(summary, l1, column, s_out, t)
      !> Figures of the run.
      type(run_summary), intent(inout) :: summary
      !> Cell stretches |e| = 1 + strain.
      real(dp), intent(in) :: l1(:)
      !> Output columns of the piece's nodes.
      integer, intent(in) :: column(:)
      !> Arc lengths of the output columns, m.
      real(dp), intent(in) :: s_out(:)
      !> Time, s.
      real(dp), intent(in) :: t
      integer :: c
      c = minloc(l1(1:size(column) - 1), 1)
      if (l1(c) - 1 < summary%min_strain) then
         summary%min_strain = l1(c) - 1
         summary%min_strain_s = 0.5_dp*(s_out(column(c)) + s_out(column(c + 1)))
         summary%min_strain_time = t
      end if
   end subroutine note_min_strain

   !> The summary as people read it, one line each: the static state, what each end did, the
   !> events (break, slack), and the run's cost; warnings are printed apart.
   function summary_text(summary, info, labels) result(text)
      !> Figures of the run.
      type(run_summary), intent(in) :: summary
      !> The static state.
      type(static_info), intent(in) :: info
      !> Names of the ends, in the order of summary%ends.
      character(len=*), intent(in) :: labels(:)
      character(:), allocatable :: text
      real(dp), parameter :: degree = 180/acos(-1.0_dp)
      integer :: j, k
      character(:), allocatable :: line
      if (info%one_line) then
         text = 'static state: end a '//quantity(info%tension_a, 'N')//angle_text(info%end_angle)//', end b '// &
                quantity(info%tension_b, 'N')//angle_text(info%end_angle_b)//'; span '//quantity(info%span, 'm')// &
                ', lowest point z = '//quantity(info%lowest_z, 'm')//' at s = '//quantity(info%lowest_s, 'm')
      else
         ! A network: no one line's ends, span or lowest point (its points are in the statics' message).
         text = 'static state: largest tension '//quantity(info%max_tension, 'N')
      end if
      if (allocated(summary%notes)) then
         if (len(summary%notes) > 0) text = text//new_line('a')//summary%notes
      end if
      if (allocated(summary%ends)) then
         do j = 1, size(summary%ends)
            associate (e => summary%ends(j))
               line = new_line('a')//trim(labels(j))//' ('//trim(e%kind)//'): tension '// &
                      quantity(e%min_tension, 'N')//' to '//quantity(e%max_tension, 'N')
               ! A fixed end does not move; a released end is slack by definition.
               if (trim(e%kind) /= 'fixed') line = line//', peak speed '//quantity(e%peak_speed, 'm/s')// &
                                                 ' at t = '//quantity(e%peak_speed_time, 's')
               if (e%slack_time > 0 .and. trim(e%kind) /= 'break') &
                  line = line//', slack for '//quantity(e%slack_time, 's')
               if (summary%has_front .and. e%front_arrival_time >= 0) &
                  line = line//', front arrived at '//quantity(e%front_arrival_time, 's')
               text = text//line
            end associate
         end do
      end if
      if (summary%broke) then
         text = text//new_line('a')//'break at s = '//quantity(summary%break_s, 'm')//', t = '// &
                quantity(summary%break_time, 's')
         if (summary%break_line > 0) text = text//' (line '//str(summary%break_line)//' of the network)'
         if (summary%break_ramp > 0) then
            text = text//', its force ramped down over '//quantity(summary%break_ramp, 's')
         else
            text = text//', at once'
         end if
         if (summary%by_tension) text = text//new_line('a')//'the tension reached the MBL ('// &
                                       quantity(summary%mbl, 'N')//'): '//quantity(summary%break_tension, 'N')// &
                                       ' in the cell at s = '//quantity(summary%break_cell_s, 'm')
      else if (summary%by_tension) then
         text = text//new_line('a')//'no break: the tension never reached the MBL ('//quantity(summary%mbl, 'N')// &
                '): largest '//quantity(summary%largest_tension, 'N')//' at s = '// &
                quantity(summary%largest_tension_s, 'm')//', t = '//quantity(summary%largest_tension_time, 's')
      end if
      if (allocated(summary%ends)) then
         do j = 1, size(summary%ends)
            associate (e => summary%ends(j))
               if (.not. allocated(e%slack_intervals)) cycle
               if (size(e%slack_intervals, 2) == 0 .or. trim(e%kind) == 'break') cycle
               line = new_line('a')//trim(labels(j))//' slack: '
               do k = 1, min(size(e%slack_intervals, 2), 5)
                  if (k > 1) line = line//', '
                  line = line//quantity(e%slack_intervals(1, k), 's')//' to '//quantity(e%slack_intervals(2, k), 's')
               end do
               if (size(e%slack_intervals, 2) > 5) line = line//' and '//str(size(e%slack_intervals, 2) - 5)//' more'
               text = text//line
            end associate
         end do
      end if
   contains

      !> ' at 12.3 deg down' (the cable leaves the end below the horizontal) or ' ... up'.
      function angle_text(angle) result(t)
         real(dp), intent(in) :: angle
         character(:), allocatable :: t
         t = ', '//quantity(degree*abs(angle), '')//' deg '//merge('down', 'up  ', angle >= 0)
         t = trim(t)
      end function angle_text
   end function summary_text
end module xcable_driver_records
