!> The preparation of a rod run: the scene's grid, the statics, the time step from the static state
!> and the figures and checks of that state.
!> (A submodule of driver/rod_run.f90.)
submodule (xcable_driver_rod_run) xcable_driver_rod_run_prepare
   implicit none

contains

   !> Set up the run: grid, the whole cable as one piece, the statics, the
   !> time step. Errors: stat_input for an inconsistent scene, stat_numerics
   !> when the statics fails.
   module subroutine run_prepare(self, scene, options, error)
      !> Run.
      class(rod_run), intent(inout) :: self
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> Controls.
      type(rod_run_options), intent(in) :: options
      !> Error.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: pa(2), pb(2), reach, c_max, ds_max
      integer :: n, k, c
      type(newton_options) :: static_newton
      self%scene = scene
      self%options = options
      n = options%nodes
      call scene_grid(scene, n, self%s, self%break_node)
      if (scene%interior_break() .and. self%break_node == 0) then
         call fatal_error(error, scene%source//': &numerics: nodes = '//str(n)// &
                          ': a break inside the cable needs at least 5 nodes', stat_input)
         return
      end if
      ! Ends held at two points farther apart than the cable can reach.
      if (scene%end_a%held() .and. scene%end_b%held() .and. .not. scene%from_tension) then
         pa = scene%end_a%position(0.0_dp)
         pb = scene%end_b%position(0.0_dp)
         reach = scene%length*(1 + scene%law%strain_max)
         if (norm2(pb - pa) >= reach) then
            call fatal_error(error, scene%source//': &end_b: x, z = '//str(pb(1))//', '//str(pb(2))// &
                             ': the ends are '//str(norm2(pb - pa))//' m apart, the cable reaches at most '// &
                             str(reach)//' m (L (1 + strain_max))', stat_input)
            return
         end if
      end if
      if (scene%gravity <= 0 .and. .not. ((scene%end_a%held() .or. scene%end_a%state_dependent()) .and. &
                                          (scene%end_b%held() .or. scene%end_b%state_dependent()))) then
         call fatal_error(error, scene%source//': &cable: gravity = 0: a cable held at one end only has no '// &
                          'static shape without weight', stat_input)
         return
      end if
      allocate (self%pieces(1))
      call self%pieces(1)%problem%piece%init(self%s, scene%mass, scene%weight, scene%ei, scene%gravity, options%mu, &
                                              scene%law, scene%end_a, scene%end_b, max(scene%tension, 1.0_dp), options%mu2, &
                                              options%damping)
      call piece_sections(self%pieces(1)%problem%piece, scene)
      if (allocated(scene%loads)) self%pieces(1)%problem%piece%loads = scene%loads
      static_newton = options%newton
      call solve_rod_statics(scene, self%pieces(1)%problem, static_newton, self%static, error)
      if (allocated(error)) return
      if (scene%from_tension) then
         deallocate (self%scene%end_b)
         allocate (self%scene%end_b, source=fixed_end(point=self%static%end_b_point))
         self%scene%end_b%label = 'end_b'
      end if
      ! The static state must stay within the law's documented range.
      associate (r => self%static%r, piece => self%pieces(1)%problem%piece)
         do c = 1, n - 1
            if (norm2(r(:, c + 1) - r(:, c))/piece%ds(c) - 1 > cell_strain_max(piece, c)) then
               call fatal_error(error, scene%source//': the static state needs strain '// &
                                str(norm2(r(:, c + 1) - r(:, c))/piece%ds(c) - 1)//' at s = '// &
                                str(0.5_dp*(piece%s(c) + piece%s(c + 1)))//' m, above the range of the law ('// &
                                trim(law_group(scene, piece, c))//' strain_max = '//str(cell_strain_max(piece, c))// &
                                '): the ends are too far apart or the loads too large', stat_input)
               return
            end if
         end do
      end associate
      ! Row scale: the largest static tension (1 N at least).
      associate (piece => self%pieces(1)%problem%piece)
         if (allocated(piece%sections)) then
            piece%tension_ref = 1
            c_max = 0
            do c = 1, n - 1
               associate (sec => piece%sections(piece%cell_sec(c)), &
                          eps => norm2(self%static%r(:, c + 1) - self%static%r(:, c))/piece%ds(c) - 1)
                  piece%tension_ref = max(piece%tension_ref, abs(sec%law%tension(eps)))
                  c_max = max(c_max, wave_speed(sec%law, sec%mass, eps))
               end associate
            end do
         else
            piece%tension_ref = max(maxval(abs(piece%law%tension(norm2(self%static%r(:, 2:n) - &
                                                                       self%static%r(:, 1:n - 1), 1)/piece%ds - 1))), &
                                    1.0_dp)
            c_max = 0
            do c = 1, n - 1
               c_max = max(c_max, wave_speed(piece%law, piece%mass_per_length, &
                                             norm2(self%static%r(:, c + 1) - self%static%r(:, c))/piece%ds(c) - 1))
            end do
         end if
         ds_max = maxval(piece%ds)
      end associate
      if (options%dt > 0) then
         self%dt = options%dt
      else
         self%dt = options%courant*ds_max/c_max
      end if
      self%summary%dt_requested = self%dt
      self%summary%courant_requested = self%dt*c_max/ds_max
      ! The strains reached start with those of the static state.
      associate (piece => self%pieces(1)%problem%piece)
         self%summary%min_strain = minval(norm2(self%static%r(:, 2:n) - self%static%r(:, 1:n - 1), 1)/piece%ds - 1)
         self%summary%min_strain_s = self%static_min_tension_s
         self%summary%max_strain = maxval(norm2(self%static%r(:, 2:n) - self%static%r(:, 1:n - 1), 1)/piece%ds - 1)
         block
            real(dp) :: cell_tension(n - 1)
            integer :: c_low
            do c = 1, n - 1
               cell_tension(c) = piece%cell_tension(c, norm2(self%static%r(:, c + 1) - self%static%r(:, c))/piece%ds(c) - 1)
            end do
            c_low = minloc(cell_tension, 1)
            self%static_min_tension = cell_tension(c_low)
            self%static_min_tension_s = 0.5_dp*(self%s(c_low) + self%s(c_low + 1))
            self%static_max_tension = maxval(abs(cell_tension))
         end block
         block
            real(dp) :: e(2, n - 1), turn(max(n - 2, 1))
            integer :: i
            e = self%static%r(:, 2:n) - self%static%r(:, 1:n - 1)
            if (n > 2) then
               turn = abs(atan2(e(1, 1:n - 2)*e(2, 2:n - 1) - e(2, 1:n - 2)*e(1, 2:n - 1), &
                                e(1, 1:n - 2)*e(1, 2:n - 1) + e(2, 1:n - 2)*e(2, 2:n - 1)))
               ! A body on a node (&point_k) bends the line there by its force: a kink that no grid
               ! resolves, not a sign of a coarse one.
               if (allocated(piece%point_node)) then
                  do i = 1, size(piece%point_node)
                     if (piece%point_node(i) > 1 .and. piece%point_node(i) < n) turn(piece%point_node(i) - 1) = 0
                  end do
               end if
               self%static_max_turn = maxval(turn)
            end if
         end block
      end associate
      if (scene%breaks .and. scene%t_break > 0) self%front_cells = c_max*scene%t_break/ds_max
      if (.not. (options%t_end/self%dt <= max_steps)) then
         call fatal_error(error, scene%source//': &numerics: the time step '//str(self%dt)//' s (courant = '// &
                          str(options%courant)//', ds = '//str(ds_max)//' m, largest wave speed '//str(c_max)// &
                          ' m/s) gives more than '//str(max_steps)//' steps to t_end = '//str(options%t_end)//' s'// &
                          '; give a longer step: courant = '//str(1.01_dp*options%t_end/max_steps*c_max/ds_max)// &
                          ' or more (or dt = '//str(1.01_dp*options%t_end/max_steps)//' s or more). The implicit '// &
                          'scheme is stable at any Courant number (the step control retries a step Newton cannot '// &
                          'take); for slow motions, as a heave over minutes, 10 to 100 is usual: check it against '// &
                          'a run at half the step', stat_input)
         return
      end if
      ! Output nodes: the break node twice.
      self%n_out = n + merge(1, 0, self%break_node > 0)
      allocate (self%s_out(self%n_out))
      allocate (self%pieces(1)%column(n))
      do k = 1, n
         self%pieces(1)%column(k) = k
         if (self%break_node > 0 .and. k > self%break_node) self%pieces(1)%column(k) = k + 1
         self%s_out(self%pieces(1)%column(k)) = self%s(k)
      end do
      if (self%break_node > 0) self%s_out(self%break_node + 1) = self%s(self%break_node)
      self%pieces(1)%r = self%static%r
      call self%pieces(1)%work%init(2*n, rod_kl, rod_ku, spread(self%pieces(1)%problem%piece%length_ref, 1, 2*n))
      allocate (self%pieces(1)%v(2, n))
      self%pieces(1)%v = 0
      if (self%scene%end_a%held()) self%pieces(1)%v(:, 1) = self%scene%end_a%velocity(0.0_dp)
      if (self%scene%end_b%held()) self%pieces(1)%v(:, n) = self%scene%end_b%velocity(0.0_dp)
      deallocate (self%pieces(1)%problem%piece%end_b)
      allocate (self%pieces(1)%problem%piece%end_b, source=self%scene%end_b)
      call static_fields(self)
   end subroutine run_prepare

   !> Fill self%info from the static state.
   subroutine static_fields(self)
      type(rod_run), intent(inout) :: self
      integer :: n
      n = self%options%nodes
      self%info%s = self%s_out
      allocate (self%info%fields(self%n_out, n_fields))
      call self%fields(self%info%fields)
      self%info%span = self%static%span
      self%info%sag = self%static%sag
      self%info%tension_a = self%info%fields(1, 1)
      self%info%tension_b = self%info%fields(self%n_out, 1)
      if (self%scene%end_a%held()) self%info%tension_a = norm2(self%static%reaction_a)
      if (self%scene%end_b%held() .or. self%scene%from_tension) self%info%tension_b = norm2(self%static%reaction_b)
      self%info%newton_iterations = self%static%newton_iterations
      call static_figures(self%info)
   end subroutine static_fields

   !> The largest strain of the law of cell c.
   pure real(dp) function cell_strain_max(piece, c)
      type(rod_piece), intent(in) :: piece
      integer, intent(in) :: c
      if (allocated(piece%sections)) then
         cell_strain_max = piece%sections(piece%cell_sec(c))%law%strain_max
      else
         cell_strain_max = piece%law%strain_max
      end if
   end function cell_strain_max

   !> The group that gives the law of cell c: '&material' or '&segment_k'.
   function law_group(scene, piece, c) result(group)
      type(scene_type), intent(in) :: scene
      type(rod_piece), intent(in) :: piece
      integer, intent(in) :: c
      character(len=16) :: group
      integer :: j
      group = '&material'
      if (size(scene%sections) <= 1) return
      do j = 1, size(scene%sections)
         if (0.5_dp*(piece%s(c) + piece%s(c + 1)) < scene%sections(j)%s_end) exit
      end do
      write (group, '(a,i0)') '&segment_', min(j, size(scene%sections))
   end function law_group
end submodule xcable_driver_rod_run_prepare
