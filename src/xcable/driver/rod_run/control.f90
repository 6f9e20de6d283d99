!> The step control of a run (either model, driver/stepping.f90's loop): the wall-clock limit, the
!> step to try and its landing on t_end and on the break, the rejection and halving, the doubling
!> back after good steps, and the search for a break by tension (watch_step).
!> (A submodule of driver/rod_run.f90.)
submodule (xcable_driver_rod_run) xcable_driver_rod_run_control
   implicit none

contains

   !> Step control (either model, see the module header): the error when the
   !> wall time of the dynamics so far, wall (s), is past options%max_wall_time.
   module subroutine wall_limit(self, wall, error)
      !> Run.
      type(rod_run), intent(in) :: self
      !> Wall time of this process's dynamics, s.
      real(dp), intent(in) :: wall
      !> Error when the limit is reached.
      type(error_type), allocatable, intent(out) :: error
      if (self%options%max_wall_time > 0 .and. wall > self%options%max_wall_time) &
         call fatal_error(error, 'wall-clock limit of '//str(self%options%max_wall_time)//' s reached at t = '// &
                          str(self%t)//' s', stat_numerics)
   end subroutine wall_limit

   !> Step control: the step to try from self%t, progress%h shortened to land
   !> on t_stop (t_end, or the start of the break). Error when it no longer
   !> advances the time.
   module subroutine plan_step(self, h_try, t_stop, landing, error)
      !> Run.
      type(rod_run), intent(in) :: self
      !> Step to try and where the run lands (s); whether the step was shortened to land there.
      real(dp), intent(out) :: h_try, t_stop
      logical, intent(out) :: landing
      !> Error when the step no longer advances the time.
      type(error_type), allocatable, intent(out) :: error
      t_stop = self%options%t_end
      if (self%scene%breaks .and. .not. self%broken .and. self%scene%break_time > self%t) &
         t_stop = min(t_stop, self%scene%break_time)
      h_try = self%progress%h
      landing = self%t + h_try >= t_stop*(1 - 1.0e-12_dp) .or. t_stop - (self%t + h_try) < 1.0e-6_dp*self%progress%h
      if (landing) h_try = t_stop - self%t
      ! A step aimed at the crossing of a break by tension (watch_step).
      if (self%watch%h_aim > 0 .and. self%watch%h_aim < h_try) then
         h_try = self%watch%h_aim
         t_stop = self%t + h_try
         landing = .true.
      end if
      if (.not. (self%t + h_try > self%t)) &
         call fatal_error(error, 'step control: the step '//str(h_try)//' s no longer advances the time at t = '// &
                          str(self%t)//' s', stat_numerics)
   end subroutine plan_step

   !> Step control after a rejected attempt: count it; try the same step again
   !> (retry: Newton failed from a kept factorisation, the next attempt takes
   !> a fresh one) or half of it. Error when the run has rejected more than
   !> 1000 + the requested steps, or the step fell below min_step_fraction dt.
   module subroutine reject_attempt(self, reason, retry, error)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> Why the attempt was rejected.
      character(*), intent(in) :: reason
      !> Whether to retry the same step.
      logical, intent(in) :: retry
      !> Error when the step control gives up.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: max_rejections
      max_rejections = 1000 + self%options%t_end/self%dt
      ! An aim at a crossing (watch_step) is made anew from the next step that passes it.
      self%watch%h_aim = 0
      associate (h => self%progress%h, n_good => self%progress%n_good, rejected_here => self%progress%rejected_here)
         self%summary%rejected_steps = self%summary%rejected_steps + 1
         rejected_here = rejected_here + 1
         if (self%summary%rejected_steps > max_rejections) then
            call fatal_error(error, 'step control: '//str(self%summary%rejected_steps)//' rejected attempts by t = '// &
                             str(self%t)//' s: the step stays far below dt = '//str(self%dt)//' s; last: '//reason// &
                             '; try a smaller dt or courant, or theta = 0.55', stat_numerics)
            return
         end if
         if (retry) return
         h = 0.5_dp*h
         n_good = 0
         if (h < self%dt*self%options%min_step_fraction) &
            call fatal_error(error, 'step control: step fell below '//str(self%dt*self%options%min_step_fraction)// &
                             ' s at t = '//str(self%t)//' s after '//str(rejected_here)//' rejected attempts; last: '// &
                             reason//'; try a smaller dt or courant, more nodes, or theta = 0.55', stat_numerics)
      end associate
   end subroutine reject_attempt

   !> The search for a break by tension on a step of h from self%t just solved (either model):
   !> the cell tensions of the law at the old level r_old and the new level r_new (positions,
   !> (2 or 3, n)). A step whose largest cell tension F passes watch%mbl by more than
   !> rupture_tolerance mbl starts a search on the step from self%t: it is taken again (retry)
   !> with watch%h_aim, first the earliest time at which a cell's tension, linear between the
   !> two levels, reaches mbl, then by false position (Illinois) on F of the step's length
   !> within the bracket of the steps tried, until F is within rupture_tolerance mbl of mbl
   !> (or max_rupture_aims steps were tried): watch%found, its time, cell and tension. A step
   !> that does not pass mbl is kept, and the largest tension so far updated.
   module subroutine watch_step(self, h, r_old, r_new, ds, law, retry, tensions, s_nodes)
      !> Run (its watch).
      type(rod_run), intent(inout) :: self
      !> The step, s.
      real(dp), intent(in) :: h
      !> Node positions at the old and the new level, m.
      real(dp), intent(in) :: r_old(:, :), r_new(:, :)
      !> Unstretched cell lengths, m.
      real(dp), intent(in) :: ds(:)
      !> Tension-strain law.
      class(material_law), intent(in) :: law
      !> Whether the step is to be taken again with watch%h_aim.
      logical, intent(out) :: retry
      !> A line of segments: the cells' tensions at the old and new level (N, (n - 1, 2)) in
      !> place of the law's, and the factor mbl / (the cell's segment's MBL) on each (n - 1; 0:
      !> a segment that does not part), in column 3.
      real(dp), intent(in), optional :: tensions(:, :)
      !> The nodes' arc lengths the watch reports its places in (m; default: the run's s).
      real(dp), intent(in), optional :: s_nodes(:)
      real(dp) :: t_old(size(ds)), t_new(size(ds)), frac, f
      integer :: c, m
      m = size(ds)
      if (present(tensions)) then
         ! Each cell's share of its own MBL, in units of watch%mbl.
         t_old = tensions(:, 1)*tensions(:, 3)
         t_new = tensions(:, 2)*tensions(:, 3)
      else
         do c = 1, m
            t_old(c) = law%tension(norm2(r_old(:, c + 1) - r_old(:, c))/ds(c) - 1)
            t_new(c) = law%tension(norm2(r_new(:, c + 1) - r_new(:, c))/ds(c) - 1)
         end do
      end if
      retry = .false.
      associate (w => self%watch)
         c = maxloc(t_new, 1)
         f = t_new(c)
         if (w%h_aim == 0) then
            ! A step of the run: it passes mbl, reaches it, or stays below.
            if (f > w%mbl*(1 + rupture_tolerance)) then
               frac = 1
               do c = 1, m
                  if (t_new(c) >= w%mbl .and. t_new(c) > t_old(c)) &
                     frac = min(frac, max(w%mbl - t_old(c), 0.0_dp)/(t_new(c) - t_old(c)))
               end do
               w%h_lo = 0
               w%f_lo = maxval(t_old)
               w%h_hi = h
               w%f_hi = f
               w%side = 0
               w%h_aim = min(max(frac, 1.0e-3_dp), 1 - 1.0e-3_dp)*h
               w%aims = 1
               retry = .true.
               return
            end if
         else if (abs(f - w%mbl) > rupture_tolerance*w%mbl .and. w%aims < max_rupture_aims) then
            ! An aimed step that missed: narrow the bracket, aim again (false position, Illinois).
            if (f > w%mbl) then
               w%h_hi = h
               w%f_hi = f
               if (w%side == 1) w%f_lo = w%mbl - 0.5_dp*(w%mbl - w%f_lo)
               w%side = 1
            else
               w%h_lo = h
               w%f_lo = f
               if (w%side == -1) w%f_hi = w%mbl + 0.5_dp*(w%f_hi - w%mbl)
               w%side = -1
            end if
            w%h_aim = w%h_lo + (w%mbl - w%f_lo)/(w%f_hi - w%f_lo)*(w%h_hi - w%h_lo)
            if (.not. (w%h_aim > w%h_lo .and. w%h_aim < w%h_hi)) w%h_aim = 0.5_dp*(w%h_lo + w%h_hi)
            w%aims = w%aims + 1
            retry = .true.
            return
         end if
         w%h_aim = 0
         if (f > w%max_share) then
            w%max_share = f
            w%max_tension = f
            w%max_mbl = w%mbl
            if (present(tensions)) then
               w%max_tension = tensions(c, 2)
               w%max_mbl = w%mbl/tensions(c, 3)
            end if
            w%max_s = cell_middle(c)
            w%max_time = self%t + h
         end if
         if (f >= w%mbl*(1 - rupture_tolerance)) then
            w%found = .true.
            w%time = self%t + h
            w%cell = c
            w%tension = f
            w%cell_mbl = w%mbl
            if (present(tensions)) then
               w%tension = tensions(c, 2)
               w%cell_mbl = w%mbl/tensions(c, 3)
            end if
            w%s = cell_middle(c)
            w%cells = t_new
         end if
      end associate

   contains

      !> The arc length of the middle of cell c, m.
      real(dp) function cell_middle(c)
         integer, intent(in) :: c
         if (present(s_nodes)) then
            cell_middle = 0.5_dp*(s_nodes(c) + s_nodes(c + 1))
         else
            cell_middle = 0.5_dp*(self%s(c) + self%s(c + 1))
         end if
      end function cell_middle
   end subroutine watch_step

   !> Step control after an accepted step of h_try: the time moves on (onto
   !> t_stop when it lands there), the step taken is recorded, and after four
   !> good steps a halved step doubles back towards dt.
   module subroutine advance_time(self, h_try, t_stop, landing)
      !> Run.
      type(rod_run), intent(inout) :: self
      !> The step taken and the time it was to land on (plan_step), s; whether it was shortened to land there.
      real(dp), intent(in) :: h_try, t_stop
      logical, intent(in) :: landing
      self%t = self%t + h_try
      if (abs(self%t - t_stop) <= 1.0e-12_dp*max(t_stop, 1.0_dp)) self%t = t_stop
      ! The step taken: a step shortened only to land on t_end or the break is not a change of dt.
      if (.not. landing) self%summary%dt_used = max(self%summary%dt_used, h_try)
      associate (h => self%progress%h, n_good => self%progress%n_good)
         if (h < self%dt) then
            n_good = n_good + 1
            if (n_good >= 4) then
               h = min(2*h, self%dt)
               n_good = 0
            end if
         end if
      end associate
   end subroutine advance_time

end submodule xcable_driver_rod_run_control
