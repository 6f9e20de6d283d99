!> The preparation of a 3-D run: its statics from the planar run's static state (turned back
!> onto the scene), the continuation in the loads when Newton fails, the checks of the static
!> state, and the time step from it. (A submodule of driver/rod3d_drive.f90.)
submodule (xcable_driver_rod3d_drive) xcable_driver_rod3d_drive_statics
   implicit none

contains

   !> Set up the 3-D piece on the prepared planar run's grid and solve its statics.
   module subroutine drive_prepare(self, rod, error, azimuth, pivot)
      !> 3-D run.
      class(rod3d_drive), intent(inout) :: self
      !> Planar run, prepared (its scene, grid, time step; its static fields are replaced).
      type(rod_run), intent(inout) :: rod
      !> Error: stat_input for what the 3-D run cannot do, stat_numerics when the statics fails.
      type(error_type), allocatable, intent(out) :: error
      !> The angle (rad) the planar run's scene was turned by about the vertical through pivot (x, y)
      !> to lie in x-z (driver/simulation.f90; default 0: not turned). Its static state is turned back.
      real(dp), intent(in), optional :: azimuth, pivot(2)
      integer :: n, k, c, j
      real(dp) :: ya, yb, length, extra(rod%n_out, n_fields3), pa(2), d2, d3(2), phi, c_max
      real(dp), allocatable :: guess(:), cell_ten(:)
      type(rod3d_section), allocatable :: own_laws(:)
      class(material_law), allocatable :: own, uncut
      logical :: static_form, was_cut, cut
      n = rod%options%nodes
      allocate (self%pieces(1))
      self%pieces(1)%column = rod%pieces(1)%column
      self%pieces(1)%end_slot = [1, 2]
      associate (scene => rod%scene, run => self%pieces(1)%run, piece => self%pieces(1)%run%problem%piece, &
                 reaction => self%pieces(1)%reaction)
         call piece%init(rod%s, scene%mass, scene%weight, scene%ei, scene%gip, scene%gravity, rod%options%mu, &
                         scene%law, scene%end_a, scene%end_b, rod%pieces(1)%problem%piece%tension_ref, error, &
                         rod%options%mu2, rod%options%damping)
         if (allocated(error)) then
            call prefix_error(error, scene%source//': &cable: ')
            return
         end if
         ! A line of segments: the sections of the planar piece (each segment's material).
         call piece_sections3(piece, scene)
         if (allocated(scene%loads)) then
            call piece%set_loads(scene%loads, error)
            if (allocated(error)) then
               call prefix_error(error, scene%source//': ')
               return
            end if
         end if
         ! The statics to 1e-10, as the planar statics.
         call run%init(1.0e-10_dp)
         ! First guess: the planar static state, y from end a's to end b's (a held end's y).
         ya = 0
         yb = 0
         if (scene%end_a%held()) ya = component(scene%end_a%position3(0.0_dp), 2)
         if (scene%end_b%held()) yb = component(scene%end_b%position3(0.0_dp), 2)
         if (.not. scene%end_a%held()) ya = yb
         if (.not. scene%end_b%held()) yb = ya
         length = rod%s(n) - rod%s(1)
         pa = rod%static%r(:, 1)
         d2 = rod%static%r(1, n) - pa(1)
         ! The chord's horizontal run in the 3-D scene (the planar run's scene is turned so that
         ! its chord lies in x-z: simulation.f90).
         d3 = [rod%static%r(1, n) - pa(1), yb - ya]
         if (scene%end_a%held() .and. scene%end_b%held()) &
            d3(1) = component(scene%end_b%position3(0.0_dp), 1) - component(scene%end_a%position3(0.0_dp), 1)
         phi = 0
         if (present(azimuth)) phi = azimuth
         do k = 1, n
            if (phi /= 0 .and. .not. (scene%end_a%held() .and. scene%end_b%held())) then
               ! A turned scene with an end that is not held (a spring, a loaded end): the planar
               ! state turned back about the pivot by the azimuth.
               run%x(3*k - 2:3*k) = [pivot(1) + cos(phi)*(rod%static%r(1, k) - pivot(1)), &
                                          pivot(2) + sin(phi)*(rod%static%r(1, k) - pivot(1)), rod%static%r(2, k)]
            else if (scene%end_a%held() .and. scene%end_b%held() .and. abs(d2) > 1.0e-6_dp*length) then
               ! Both ends held: the planar shape turned (and stretched horizontally) onto the chord's vertical plane.
               run%x(3*k - 2:3*k) = [pa(1) + (rod%static%r(1, k) - pa(1))/d2*d3(1), &
                                          ya + (rod%static%r(1, k) - pa(1))/d2*d3(2), rod%static%r(2, k)]
            else
               run%x(3*k - 2:3*k) = [rod%static%r(1, k), ya + (yb - ya)*(rod%s(k) - rod%s(1))/length, &
                                          rod%static%r(2, k)]
            end if
         end do
         run%x(3*n + 1:) = 0
         guess = run%x
         ! Loads with a static form of their own (the seabed's static friction): the planar guess
         ! has it already; Newton with it, first with the law's compressive branch (uncut_law: a
         ! line whose friction takes all its tension lies at zero strain, where a tension-only
         ! law has no stiffness), then with the law itself, as the planar statics
         ! (model/rod_statics.f90).
         static_form = any_static_form(piece%loads)
         call loads_in_statics(piece%loads, static_form, secant_stiffness(piece%law), scene%weight)
         if (static_form) then
            call uncut_law(piece%law, uncut, was_cut)
            call move_alloc(piece%law, own)
            call move_alloc(uncut, piece%law)
            ! A line of segments: every section's law (the planar statics' uncut_laws).
            if (allocated(piece%sections)) then
               allocate (own_laws(size(piece%sections)))
               do j = 1, size(piece%sections)
                  call uncut_law(piece%sections(j)%law, uncut, cut)
                  was_cut = was_cut .or. cut
                  call move_alloc(piece%sections(j)%law, own_laws(j)%law)
                  call move_alloc(uncut, piece%sections(j)%law)
               end do
            end if
         end if
         call run%statics(0.0_dp, error)
         if (.not. allocated(error)) call check_static3(piece, run%x, error)
         if (allocated(error)) then
            ! Newton from the planar guess failed or landed in a folded state (a strong cross
            ! current): continuation in the distributed loads.
            call continue_statics(run, guess, error)
         end if
         if (static_form) then
            deallocate (piece%law)
            call move_alloc(own, piece%law)
            if (allocated(own_laws)) then
               do j = 1, size(own_laws)
                  deallocate (piece%sections(j)%law)
                  call move_alloc(own_laws(j)%law, piece%sections(j)%law)
               end do
            end if
            if (.not. allocated(error) .and. was_cut) call run%statics(0.0_dp, error)
            if (allocated(error)) call prefix_error(error, 'with the static friction on the seabed: ')
         end if
         if (allocated(error)) then
            call loads_in_statics(piece%loads, .false., 0.0_dp, 0.0_dp)
            call prefix_error(error, scene%source//': ')
            return
         end if
         ! The supports' forces of the static state.
         call run%problem%evaluate(run%x, run%work%residual, run%work%jacobian, .false.)
         call loads_in_statics(piece%loads, .false., 0.0_dp, 0.0_dp)
         run%work%usable = .false.
         reaction(:, 1) = piece%reaction(1, 0.0_dp)
         reaction(:, 2) = piece%reaction(n, 0.0_dp)
         ! Held ends start with their own velocity (a motion end).
         if (scene%end_a%held()) run%v(:, 1) = scene%end_a%velocity3(0.0_dp)
         if (scene%end_b%held()) run%v(:, n) = scene%end_b%velocity3(0.0_dp)
         call run%start(run%x, run%v, 0.0_dp)
         ! Newton in a step: the planar run's policy (driver/rod_run.f90).
         run%options = rod%options%newton
         run%options%estimate_error = .true.
         run%options%max_contraction = 0.5_dp
         run%options%refresh_contraction = 0.05_dp
         ! The static state's records, now those of the 3-D statics.
         call state_fields(self, rod, rod%info%fields, extra)
         self%static_extra = extra
         rod%info%extra = extra
         associate (r => run%x, f => rod%info%fields)
            rod%info%span = norm2(r(3*n - 2:3*n - 1) - r(1:2))
            rod%info%sag = sag3(r, n)
            rod%info%tension_a = f(1, 1)
            rod%info%tension_b = f(rod%n_out, 1)
            if (rod%scene%end_a%held()) rod%info%tension_a = norm2(reaction(:, 1))
            if (rod%scene%end_b%held()) rod%info%tension_b = norm2(reaction(:, 2))
         end associate
         call static_figures(rod%info)
         rod%summary%min_strain = huge(1.0_dp)
         call note_min_strain(rod%summary, piece%l1, self%pieces(1)%column, rod%s_out, 0.0_dp)
         rod%summary%max_strain = maxval(piece%l1) - 1
         ! The static state's compression, for the warning (the planar run's fields held the first guess's).
         if (allocated(piece%sections)) then
            ! A line of segments: each cell's own law.
            allocate (cell_ten(n - 1))
            do c = 1, n - 1
               cell_ten(c) = piece%cell_tension(c, piece%l1(c) - 1)
            end do
            rod%static_min_tension = minval(cell_ten)
            k = minloc(cell_ten, 1)
            rod%static_max_tension = maxval(abs(cell_ten))
         else
            rod%static_min_tension = minval(piece%law%tension(piece%l1(1:n - 1) - 1))
            k = minloc(piece%law%tension(piece%l1(1:n - 1) - 1), 1)
            rod%static_max_tension = maxval(abs(piece%law%tension(piece%l1(1:n - 1) - 1)))
         end if
         rod%static_min_tension_s = 0.5_dp*(rod%s(k) + rod%s(k + 1))
         ! The step from the 3-D static state's strains (the planar preparation's strains are
         ! those of the scene without what leaves its plane: a current across it strains the line
         ! more, its waves are faster, and a step from the planar strains has a larger Courant
         ! number than the one reported).
         if (allocated(piece%sections)) then
            ! A line of segments: each cell's wave speed from its own law and mass.
            c_max = 0
            do c = 1, n - 1
               associate (sec => piece%sections(piece%cell_sec(c)))
                  c_max = max(c_max, wave_speed(sec%law, sec%mass, piece%l1(c) - 1))
               end associate
            end do
         else
            c_max = maxval(wave_speed(piece%law, piece%mass_per_length, piece%l1(1:n - 1) - 1))
         end if
         call step_from_static3(rod, c_max, maxval(piece%ds), error)
      end associate
   end subroutine drive_prepare

   !> The time step of a 3-D run from its static state's largest wave speed c_max (m/s) and its
   !> longest cell ds_max (m): dt = courant ds_max / c_max unless dt was given; the Courant number
   !> reported and the cells across the break's front follow. A c_max within same_wave_speed of the
   !> planar preparation's is that state's, solved to another tolerance: its step is kept (a scene
   !> in a plane then takes its planar twin's step to the bit). Error (stat_input) when it would
   !> take more than max_steps steps.
   subroutine step_from_static3(rod, c_max, ds_max, error)
      type(rod_run), intent(inout) :: rod
      real(dp), intent(in) :: c_max, ds_max
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: same_wave_speed = 1.0e-9_dp
      real(dp) :: c_planar
      c_planar = rod%summary%courant_requested*ds_max/rod%dt
      if (abs(c_max - c_planar) <= same_wave_speed*c_planar) return
      if (rod%options%dt <= 0) rod%dt = rod%options%courant*ds_max/c_max
      rod%summary%dt_requested = rod%dt
      rod%summary%courant_requested = rod%dt*c_max/ds_max
      if (rod%scene%breaks .and. rod%scene%t_break > 0) rod%front_cells = c_max*rod%scene%t_break/ds_max
      if (.not. (rod%options%t_end/rod%dt <= max_steps)) &
         call fatal_error(error, rod%scene%source//': &numerics: the time step '//str(rod%dt)//' s (courant = '// &
                          str(rod%options%courant)//', ds = '//str(ds_max)//' m, largest wave speed '//str(c_max)// &
                          ' m/s of the 3-D static state) gives more than '//str(max_steps)//' steps to t_end = '// &
                          str(rod%options%t_end)//' s; give a longer step (courant or dt)', stat_input)
   end subroutine step_from_static3

   !> The 3-D statics by continuation in the distributed loads, after the
   !> direct solve from the planar guess failed or gave a state check_static3
   !> refuses (error on entry: why). The loads' factor goes from 0 to 1 in
   !> steps of 1/20, each solve starting from the last accepted state (the
   !> first from the guess); a solve that fails or whose state check_static3
   !> refuses is taken again at half the step, and after two accepted steps
   !> the step doubles back (at most to 1/20). The factors are j / (20 2^m),
   !> exact: a continuation that needs no halving solves at k / 20 for k = 1
   !> .. 20. Error stat_numerics (naming the direct solve's failure, the share
   !> of the loads reached and the last step's failure) when the step would
   !> fall below 1/20480 of the loads, after 400 solves, or when the scene
   !> has no distributed loads.
   subroutine continue_statics(run, guess, error)
      !> The 3-D stepper (x: the solution).
      type(rod3d_run), intent(inout) :: run
      !> First guess (the planar static state turned onto the chord's plane).
      real(dp), intent(in) :: guess(:)
      !> On entry, why the direct solve was not taken; on return, allocated when no state was found.
      type(error_type), allocatable, intent(inout) :: error
      integer, parameter :: steps = 20, max_halvings = 10, max_solves = 400
      type(error_type), allocatable :: step_error
      character(:), allocatable :: direct, last
      real(dp), allocatable :: accepted(:)
      integer :: j, m, good, solves
      direct = error%message
      deallocate (error)
      associate (piece => run%problem%piece)
         if (.not. allocated(piece%loads)) then
            call fatal_error(error, direct//' (no distributed loads to continue in)', stat_numerics)
            return
         end if
         if (size(piece%loads) == 0) then
            call fatal_error(error, direct//' (no distributed loads to continue in)', stat_numerics)
            return
         end if
         run%x = guess
         accepted = guess
         last = ''
         j = 0
         m = 0
         good = 0
         do solves = 1, max_solves
            piece%load_factor = real(j + 1, dp)/real(steps*2**m, dp)
            call run%statics(0.0_dp, step_error)
            if (.not. allocated(step_error)) call check_static3(piece, run%x, step_error)
            if (allocated(step_error)) then
               last = step_error%message
               deallocate (step_error)
               run%x = accepted
               if (m == max_halvings) exit
               j = 2*j
               m = m + 1
               good = 0
               cycle
            end if
            j = j + 1
            accepted = run%x
            if (j == steps*2**m) exit
            good = good + 1
            if (good >= 2 .and. m > 0 .and. mod(j, 2) == 0) then
               j = j/2
               m = m - 1
               good = 0
            end if
         end do
         piece%load_factor = 1
         if (j < steps*2**m) call fatal_error(error, direct//'; the continuation in the distributed loads (fluid) '// &
                                              'reached '//str(100*real(j, dp)/real(steps*2**m, dp))// &
                                              ' % of them ('//last//'): no static state found', stat_numerics)
      end associate
   end subroutine continue_statics

   !> A static state the run may start from: finite, no cell squeezed below 5
   !> % of its length (check_range), and not folded: at no interior node do
   !> its two cells turn back on themselves (a turning angle above pi/2, the
   !> angle of the rotation vector phi(e_k-1, e_k) of the step's fold check,
   !> model/rod3d.f90). A static state has no previous level, so the step's
   !> check (a turning angle through half a turn within the step) has
   !> nothing to compare with; a folded state found by Newton is an
   !> equilibrium of the compressed, zigzagging cells (compression = 'law'),
   !> not a passage through half a turn.
   subroutine check_static3(piece, x, error)
      type(rod3d_piece), intent(in) :: piece
      !> Unknowns of the static state.
      real(dp), intent(in) :: x(:)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: half_turn = acos(-1.0_dp), fold_angle = 0.5_dp*half_turn
      real(dp) :: r(3, piece%n), e(3, piece%n - 1), l(piece%n - 1), th(piece%n)
      integer :: k
      r = reshape(x(1:3*piece%n), [3, piece%n])
      call piece%geometry(r, e, l, th)
      call check_range(x, l, piece%law, 1, error)
      if (allocated(error)) then
         call prefix_error(error, '3-D statics: ')
         return
      end if
      k = maxloc(th, 1)
      if (.not. (th(k) <= fold_angle)) call fatal_error(error, '3-D statics: a folded state (the cells at node '// &
                                                         str(k)//' turn back on themselves, by '//str(th(k))// &
                                                         ' rad, more than pi/2)', stat_numerics)
   end subroutine check_static3

   !> Largest vertical distance of a node below the chord between the end nodes, the chord's
   !> height taken where the node's horizontal projection onto it falls, m.
   pure real(dp) function sag3(x, n) result(sag)
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: n
      real(dp) :: d(2), p
      integer :: k
      d = x(3*n - 2:3*n - 1) - x(1:2)
      sag = 0
      do k = 1, n
         p = 0
         if (norm2(d) > 0) p = dot_product(x(3*k - 2:3*k - 1) - x(1:2), d)/dot_product(d, d)
         sag = max(sag, x(3) + p*(x(3*n) - x(3)) - x(3*k))
      end do
   end function sag3

   !> Component i of a vector (for a function result).
   pure real(dp) function component(v, i)
      real(dp), intent(in) :: v(:)
      integer, intent(in) :: i
      component = v(i)
   end function component
end submodule xcable_driver_rod3d_drive_statics
