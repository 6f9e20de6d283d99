!> The summary of a run, made by the driver for every model: its figures from the history (the
!> ends' tensions, speeds, slack intervals and the front's arrival; the ledger's drift), what the
!> loads measured in the static state, the break, the step control's figures, and the warnings.
!> The model gives only what it alone knows: the kind of the end in each history slot and
!> whether it is held (cable_model%end_info), and what it adds afterwards (conclude). A model
!> with a summary of its own (the box scheme's figures of version 0.1) makes it in finish.
module xcable_driver_summary
   use xcable_core_kinds, only: dp
   use xcable_core_strings, only: str, quantity
   use xcable_loads_load, only: note_measures
   use xcable_driver_records, only: run_history, slack_tension_fraction
   use xcable_driver_rod_run, only: rod_run, cable_model
   implicit none
   private
   public :: summarise_run

   !> Warning thresholds (documented in docs/user/results.md, "Warnings").
   real(dp), parameter, public :: warn_energy_drift = 0.01_dp, warn_turning_angle = 1.0_dp, &
                                  warn_rejected_fraction = 0.01_dp, warn_courant_change = 0.01_dp, &
                                  warn_static_compression = 1.0e-6_dp
   !> Resolution warnings: the largest turning of the static shape between neighbouring cells
   !> (rad; where the shape turns by theta per cell, a cell's chord misses the arc by about
   !> theta / 8 of its length: 1.2 % at 0.1) and the fewest cells
   !> across a break's front (the length over which its force ramps down, c t_break).
   real(dp), parameter, public :: warn_static_turn = 0.1_dp, min_front_cells = 4
   !> A compression (a negative tension of the law) beyond this fraction of the largest static
   !> tension is warned, with where and when.
   real(dp), parameter, public :: warn_dynamic_compression = 0.01_dp

contains

   !> The end of the dynamics (also of one stopped by an error or a termination): the wall time,
   !> the time reached, the summary figures and warnings (summarise) with the kind of each end
   !> from the model (end_info).
   subroutine summarise_run(run, model)
      !> Run.
      type(rod_run), intent(inout) :: run
      !> Model of its cable.
      class(cable_model), intent(in) :: model
      character(len=16), allocatable :: kinds(:)
      logical, allocatable :: held(:)
      character(:), allocatable :: kind
      integer :: j, n_slots
      n_slots = size(run%history%end_labels)
      allocate (kinds(n_slots), held(n_slots))
      do j = 1, n_slots
         call model%end_info(run, j, kind, held(j))
         kinds(j) = kind
      end do
      run%summary%wall_time = run%wall_time()
      run%summary%time_reached = run%t
      call summarise(run, kinds, held)
   end subroutine summarise_run

   !> Summary figures and warnings from the history.
   subroutine summarise(self, kinds, held)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Kind of the end in each history slot, and whether it is held (the model's end_info).
      character(len=*), intent(in) :: kinds(:)
      logical, intent(in) :: held(:)
      integer :: i, j, n, n_ends
      real(dp) :: speed, f0, f1, fi, reference, slack_level
      logical :: held_end
      n = self%history%n
      n_ends = size(self%history%end_labels)
      ! Derived from the history afresh (also for a run summarised when it was interrupted).
      if (allocated(self%summary%ends)) deallocate (self%summary%ends)
      allocate (self%summary%ends(n_ends))
      self%summary%steps = n
      self%summary%peak_end_speed = 0
      self%summary%peak_end_speed_time = 0
      self%summary%min_fixed_end_tension = huge(1.0_dp)
      self%summary%min_fixed_end_tension_time = 0
      self%summary%front_arrival_time = -1
      self%summary%peak_end_speed_end = ''
      self%summary%has_fixed_end = .false.
      ! A front is the 1 % drop of a held end's tension after a break; other scenes have none.
      self%summary%has_front = self%broken
      self%summary%broke = self%broken
      if (self%broken) then
         self%summary%break_time = self%scene%break_time
         self%summary%break_s = self%scene%s_break
         self%summary%break_ramp = self%scene%t_break
      end if
      ! The loads' measures of the static state, and what the loads say about them.
      self%summary%notes = ''
      if (allocated(self%summary%static_measures)) deallocate (self%summary%static_measures)
      if (allocated(self%summary%measure_names)) deallocate (self%summary%measure_names)
      if (allocated(self%history%measures)) then
         self%summary%static_measures = self%history%measures(:, 0)
         self%summary%measure_names = self%history%measure_names
         call note_measures(self%scene%loads, self%summary%static_measures, self%scene%length, self%summary%notes)
      end if
      ! The break by tension: what the first pass found (driver/simulation.f90).
      self%summary%by_tension = self%scene%by_tension
      if (self%scene%by_tension) then
         ! The MBL of the cell that reached it, or that came closest (a line of segments: its
         ! segment's; a network: its line's segment's).
         self%summary%mbl = self%scene%mbl
         if (self%broken .and. self%rupture%cell_mbl > 0) self%summary%mbl = self%rupture%cell_mbl
         if (.not. self%broken .and. self%rupture%max_mbl > 0) self%summary%mbl = self%rupture%max_mbl
         self%summary%break_tension = self%rupture%tension
         self%summary%break_cell_s = self%rupture%s
         self%summary%largest_tension = self%rupture%max_tension
         self%summary%largest_tension_s = self%rupture%max_s
         self%summary%largest_tension_time = self%rupture%max_time
      end if
      slack_level = slack_tension_fraction*max(self%info%max_tension, self%info%tension_a, self%info%tension_b)
      do j = 1, n_ends
         associate (e => self%summary%ends(j))
            e%kind = kinds(j)
            e%min_tension = self%history%ends(5, j, 0)
            e%max_tension = self%history%ends(5, j, 0)
            e%max_tension_time = self%history%time(0)
            do i = 0, n
               speed = norm2(self%history%ends(3:4, j, i))
               ! A 3-D run (driver/rod3d_drive.f90): with the y velocity.
               if (allocated(self%history%ends_y)) speed = hypot(speed, self%history%ends_y(2, j, i))
               if (speed > e%peak_speed) then
                  e%peak_speed = speed
                  e%peak_speed_time = self%history%time(i)
               end if
               if (self%history%ends(5, j, i) < e%min_tension) then
                  e%min_tension = self%history%ends(5, j, i)
                  e%min_tension_time = self%history%time(i)
               end if
               if (self%history%ends(5, j, i) > e%max_tension) then
                  e%max_tension = self%history%ends(5, j, i)
                  e%max_tension_time = self%history%time(i)
               end if
            end do
            call slack_intervals(self%history, j, slack_level, e%slack_intervals, e%slack_time)
            ! The peak end speed: the fastest end, whatever its kind (a released end after a break,
            ! a moving fairlead, a mass).
            if (e%peak_speed > self%summary%peak_end_speed) then
               self%summary%peak_end_speed = e%peak_speed
               self%summary%peak_end_speed_time = e%peak_speed_time
               self%summary%peak_end_speed_end = self%history%end_labels(j)
            end if
            if (trim(e%kind) == 'fixed') then
               self%summary%has_fixed_end = .true.
               if (e%min_tension < self%summary%min_fixed_end_tension) then
                  self%summary%min_fixed_end_tension = e%min_tension
                  self%summary%min_fixed_end_tension_time = e%min_tension_time
               end if
            end if
            held_end = held(j)
            if (held_end .and. self%summary%has_front) then
               ! The 1 % drop of the tension at the end.
               f0 = self%history%ends(5, j, 0)
               do i = 1, n
                  fi = self%history%ends(5, j, i)
                  if (fi <= 0.99_dp*f0) then
                     f1 = self%history%ends(5, j, i - 1)
                     e%front_arrival_time = self%history%time(i - 1) + (self%history%time(i) - self%history%time(i - 1)) &
                                            *(0.99_dp*f0 - f1)/(fi - f1)
                     exit
                  end if
               end do
               if (e%front_arrival_time >= 0 .and. (self%summary%front_arrival_time < 0 .or. &
                                                    e%front_arrival_time < self%summary%front_arrival_time)) &
                  self%summary%front_arrival_time = e%front_arrival_time
            end if
         end associate
      end do
      if (self%summary%min_fixed_end_tension == huge(1.0_dp)) self%summary%min_fixed_end_tension = 0
      if (self%summary%dt_used == 0) self%summary%dt_used = self%dt
      self%summary%courant_used = self%summary%courant_requested*self%summary%dt_used/self%dt
      self%summary%dissipated = self%dissipation
      if (self%options%energy) then
         reference = self%history%energy(1, 0)
         if (reference <= 0) reference = max(maxval(abs(self%history%energy(1:4, 0))), 1.0_dp)
         self%summary%energy_drift = maxval(abs(self%history%energy(7, 0:n) - self%history%energy(7, 0)))/reference
      end if
      self%summary%warnings = ''
      if (self%summary%energy_drift > warn_energy_drift) call warn('the energy ledger drifted by '// &
         str(100*self%summary%energy_drift)//' % of the initial strain energy (more than '// &
         str(100*warn_energy_drift)//' %)')
      if (self%summary%max_turning_angle > warn_turning_angle) call warn('neighbouring cells turned by up to '// &
         str(self%summary%max_turning_angle)//' rad (more than '//str(warn_turning_angle)// &
         ' rad): a kink at the grid scale, the buckled zone is not resolved; more nodes resolve it')
      associate (law => self%scene%law)
         if (self%summary%max_strain > law%strain_max) call warn('cells were stretched to strain '// &
            str(self%summary%max_strain)//', beyond the range of the '//law%name()//' law (strain '// &
            str(law%strain_max)//'): the law was extrapolated there')
         if (self%summary%min_strain < law%strain_min) call warn('cells were compressed to strain '// &
            str(self%summary%min_strain)//', below the range of the '//law%name()//' law (strain '// &
            str(law%strain_min)//'): it was continued there along its first tangent, as stiff in compression '// &
            'as at the first row (give rows for compression, or compression = ''none'')')
      end associate
      if (self%static_min_tension < -warn_static_compression*self%static_max_tension) call warn( &
         'the static state is in compression: tension down to '//str(self%static_min_tension)//' N at s = '// &
         str(self%static_min_tension_s)//' m (largest tension '//str(self%static_max_tension)//' N); a rope '// &
         'cannot push: this state is held by the bending stiffness and the law''s compression branch, and may '// &
         'be a loop or a buckle (compare with compression = ''none'' and with more nodes)')
      ! A rope that pushes: the law's compressive branch reached in the dynamics.
      associate (law => self%scene%law)
         if (law%tension(self%summary%min_strain) < -warn_dynamic_compression*self%static_max_tension) &
            call warn('the line was compressed to '//quantity(law%tension(self%summary%min_strain), 'N')// &
                      ' (strain '//str(self%summary%min_strain)//') at s = '//quantity(self%summary%min_strain_s, 'm')// &
                      ', t = '//quantity(self%summary%min_strain_time, 's')//': with compression = ''law'' the rope '// &
                      'pushes back along its law below zero strain; a rope cannot push: compression = ''none''')
      end associate
      ! The grid against the scene: the static shape and the break's front.
      if (self%static_max_turn > warn_static_turn) call warn('the static shape turns by up to '// &
         str(self%static_max_turn)//' rad between neighbouring cells (more than '//str(warn_static_turn)// &
         ' rad): the grid is too coarse for the shape; about '//str(nodes_for(self%static_max_turn/warn_static_turn))// &
         ' nodes resolve it')
      if (self%front_cells > 0 .and. self%front_cells < min_front_cells) call warn('the break''s front (t_break = '// &
         str(self%scene%t_break)//' s at wave speed '//str(self%front_cells*maxval(self%s(2:) - self%s(:size(self%s) - 1))/ &
         self%scene%t_break)//' m/s) spans '//str(self%front_cells)//' cells, fewer than '//str(min_front_cells)// &
         ': about '//str(nodes_for(min_front_cells/self%front_cells))//' nodes resolve it')
      if (self%summary%rejected_steps > max(10, int(warn_rejected_fraction*max(n, 1)))) call warn( &
         str(self%summary%rejected_steps)//' step attempts were rejected ('//str(n)// &
         ' accepted): the step control struggled; a smaller dt or courant may be more economical')
      if (abs(self%summary%courant_used/max(self%summary%courant_requested, tiny(1.0_dp)) - 1) > warn_courant_change) &
         call warn('the Courant number taken, '//str(self%summary%courant_used)//', differs from the one asked for, '// &
                   str(self%summary%courant_requested))

   contains

      subroutine warn(line)
         character(*), intent(in) :: line
         if (len(self%summary%warnings) > 0) self%summary%warnings = self%summary%warnings//new_line('a')
         self%summary%warnings = self%summary%warnings//line
      end subroutine warn

      !> The node count that refines the grid by factor (its cells factor times shorter).
      integer function nodes_for(factor)
         real(dp), intent(in) :: factor
         nodes_for = ceiling(factor*(self%options%nodes - 1)) + 1
      end function nodes_for
   end subroutine summarise

   !> The intervals in which end j of the history was slack (its tension at most level), with the
   !> crossings interpolated linearly between records, and their total length, s.
   subroutine slack_intervals(history, j, level, intervals, total)
      !> History of the run.
      type(run_history), intent(in) :: history
      !> The end's slot.
      integer, intent(in) :: j
      !> Tension at and below which the end counts as slack, N.
      real(dp), intent(in) :: level
      !> Start and end of each interval (2, k), s.
      real(dp), allocatable, intent(out) :: intervals(:, :)
      !> Their total, s.
      real(dp), intent(out) :: total
      real(dp), allocatable :: grown(:, :)
      real(dp) :: start, f0, f1, tc
      integer :: i, k
      logical :: slack
      allocate (intervals(2, 8))
      k = 0
      slack = history%ends(5, j, 0) <= level
      start = history%time(0)
      do i = 1, history%n
         f0 = history%ends(5, j, i - 1)
         f1 = history%ends(5, j, i)
         if ((f1 <= level) .eqv. slack) cycle
         tc = history%time(i - 1) + (history%time(i) - history%time(i - 1))*(level - f0)/(f1 - f0)
         if (slack) then
            call push(start, tc)
         else
            start = tc
         end if
         slack = .not. slack
      end do
      if (slack) call push(start, history%time(history%n))
      intervals = intervals(:, 1:k)
      total = sum(intervals(2, :) - intervals(1, :))
   contains
      subroutine push(a, b)
         real(dp), intent(in) :: a, b
         if (k == size(intervals, 2)) then
            allocate (grown(2, 2*k))
            grown(:, 1:k) = intervals
            call move_alloc(grown, intervals)
         end if
         k = k + 1
         intervals(:, k) = [a, b]
      end subroutine push
   end subroutine slack_intervals

end module xcable_driver_summary
