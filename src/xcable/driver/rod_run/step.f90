!> The planar rod's steps: Newton on a step (the quiescent cable held outside a window), the checks
!> of the new state, the acceptance, and the break (the step control is control.f90).
!> (A submodule of driver/rod_run.f90.)
submodule (xcable_driver_rod_run) xcable_driver_rod_run_step
   implicit none

contains

   !> Whether a Newton solve with opts starts from the kept factorisation of work.
   pure logical module function jacobian_kept(opts, work)
      !> Newton controls and work arrays.
      type(newton_options), intent(in) :: opts
      type(newton_workspace), intent(in) :: work
      jacobian_kept = opts%reuse_jacobian .and. work%usable .and. work%contraction <= opts%refresh_contraction
   end function jacobian_kept

   !> Whether an end moves or changes its load in time.
   logical module function ends_change(self)
      type(rod_run), intent(in) :: self
      ends_change = self%scene%end_a%time_dependent() .or. self%scene%end_b%time_dependent() .or. &
                    self%other_ends_change
   end function ends_change

   !> Newton controls of a time step (see the module header).
   function step_newton(self) result(opts)
      type(rod_run), intent(in) :: self
      type(newton_options) :: opts
      opts = self%options%newton
      opts%estimate_error = .true.
      opts%max_contraction = 0.5_dp
      opts%refresh_contraction = 0.05_dp
      ! No full residual at the converged point: attempt evaluates there only what the
      ! accepted state needs (rod_problem%accepted_state: the geometry, the memo, the end
      ! cells' forces for the reactions). Nothing reads the final residual's norm.
      opts%final_residual = .false.
   end function step_newton

   !> One Newton solve of piece p for the step from self%t to self%t + h.
   !>
   !> Skip of the quiescent cable (options%skip_quiescent): ahead of a front the
   !> cable keeps its state to round-off, and solving there changes nothing. The
   !> step is solved on a window of nodes (choose_window: those that moved in the
   !> last step by more than quiet_fraction newton_tol cell lengths, or quiet_ulps
   !> units of round-off of the largest coordinate when that is more, the ends whose
   !> conditions change, and margin nodes on either side); the nodes outside keep
   !> their positions (they are boundary data of the window's rows). After the
   !> solve, the window's outer nodes on a held side (check_nodes of them) must
   !> have moved by at most the same threshold; otherwise the motion has reached the
   !> margin, the window grows by 2 margin nodes on that side and the step is
   !> solved again from the first guess. A failed solve on a window is redone on
   !> the whole piece. The whole piece is solved at the first step of the dynamics,
   !> with distributed loads, with a kept Jacobian (reuse_jacobian), and whenever no
   !> node moved (nothing to centre a window on).
   module subroutine attempt(self, p, h, kept, iterations, error)
      type(rod_run), intent(inout) :: self
      integer, intent(in) :: p
      real(dp), intent(in) :: h
      logical, intent(out) :: kept
      integer, intent(inout) :: iterations
      type(error_type), allocatable, intent(out) :: error
      type(newton_options) :: opts
      type(newton_report) :: report
      integer :: n, lo, hi, lo_new, hi_new
      real(dp) :: quiet
      associate (piece => self%pieces(p))
         n = piece%problem%piece%n
         piece%problem%t0 = self%t
         piece%problem%dt = h
         piece%problem%theta = self%options%theta
         call piece%problem%piece%prepare_step(piece%r, piece%v)
         ! A factorisation made for another step size is stale (the mass term goes as 1/dt^2).
         if (abs(piece%factor_step - h) > 1.0e-12_dp*h) piece%work%usable = .false.
         opts = step_newton(self)
         kept = jacobian_kept(opts, piece%work)
         call choose_window(self, p, h, opts%tolerance, lo, hi, quiet)
         do
            call first_guess(lo, hi)
            piece%problem%lo = lo
            piece%problem%hi = hi
            call newton_solve(piece%problem, piece%x(2*lo - 1:2*hi), piece%work, opts, report, error)
            iterations = max(iterations, report%iterations)
            if (report%factorisations > 0) piece%factor_step = h
            self%summary%factorisations = self%summary%factorisations + report%factorisations
            self%summary%newton_iterations = self%summary%newton_iterations + report%iterations
            self%node_solves = self%node_solves + n
            self%skipped_node_solves = self%skipped_node_solves + (n - (hi - lo + 1))
            if (lo == 1 .and. hi == n) exit
            if (allocated(error)) then
               ! In doubt, the whole piece.
               deallocate (error)
               self%window_fallbacks = self%window_fallbacks + 1
               lo = 1
               hi = n
               cycle
            end if
            lo_new = lo
            hi_new = hi
            if (lo > 1) then
               if (moved(lo, lo + check_nodes - 1) > quiet) lo_new = max(1, lo - 2*window_margin)
            end if
            if (hi < n) then
               if (moved(hi - check_nodes + 1, hi) > quiet) hi_new = min(n, hi + 2*window_margin)
            end if
            if (lo_new == lo .and. hi_new == hi) exit
            self%window_growths = self%window_growths + 1
            lo = lo_new
            hi = hi_new
         end do
         ! The converged state: what check_state, accept (the reactions), record and the next
         ! step take from the last evaluation (in place of Newton's final residual).
         if (.not. allocated(error)) call piece%problem%accepted_state(piece%x(2*lo - 1:2*hi))
         piece%problem%lo = 1
         piece%problem%hi = 0
      end associate

   contains

      !> The first guess R + h V (or R) of the window's nodes, the old positions elsewhere.
      subroutine first_guess(k1, k2)
         integer, intent(in) :: k1, k2
         associate (piece => self%pieces(p))
            if (k1 > 1 .or. k2 < n) call piece%problem%piece%freeze_level()
            if (allocated(piece%x)) then
               if (size(piece%x) /= 2*n) deallocate (piece%x)
            end if
            if (.not. allocated(piece%x)) allocate (piece%x(2*n))
            call guess_positions(n, k1, k2, self%options%extrapolate, h, piece%r, piece%v, piece%x)
            if (k1 == 1 .and. piece%problem%piece%end_a%held()) &
               piece%x(1:2) = piece%problem%piece%end_a%position(self%t + h)
            if (k2 == n .and. piece%problem%piece%end_b%held()) &
               piece%x(2*n - 1:2*n) = piece%problem%piece%end_b%position(self%t + h)
         end associate
      end subroutine first_guess

      !> Largest displacement of the nodes k1 .. k2 in the step solved, m.
      real(dp) function moved(k1, k2)
         integer, intent(in) :: k1, k2
         integer :: k
         moved = 0
         associate (piece => self%pieces(p))
            do k = max(1, k1), min(n, k2)
               moved = max(moved, abs(piece%x(2*k - 1) - piece%r(1, k)), abs(piece%x(2*k) - piece%r(2, k)))
            end do
         end associate
      end function moved
   end subroutine attempt

   !> Newton's first guess for a step of h: x = R + h V on the nodes k1 .. k2 (R with
   !> extrapolate false), x = R on the others. (A routine of its own, element by
   !> element: in attempt the array expressions with reshape made temporaries, and loops
   !> there reloaded the components' descriptors at every element; attempt's own
   !> instructions on fast_180kN 12.2e6 -> 7.4e6, callgrind; the same values.)
   pure subroutine guess_positions(n, k1, k2, extrapolate, h, r, v, x)
      integer, intent(in) :: n, k1, k2
      logical, intent(in) :: extrapolate
      real(dp), intent(in) :: h, r(2, n), v(2, n)
      real(dp), intent(out) :: x(2*n)
      integer :: k, a
      do k = 1, n
         do a = 1, 2
            x(2*k - 2 + a) = r(a, k)
         end do
      end do
      if (.not. extrapolate) return
      do k = k1, k2
         do a = 1, 2
            x(2*k - 2 + a) = r(a, k) + h*v(a, k)
         end do
      end do
   end subroutine guess_positions

   !> The window of nodes lo .. hi on which the step of h from self%t solves piece p
   !> (attempt): the nodes whose last step moved them, h |V| > quiet (m), the end nodes
   !> whose end conditions change over the step, window_margin nodes on either side;
   !> the whole piece (1 .. n) when the skip is off or not applicable.
   subroutine choose_window(self, p, h, tolerance, lo, hi, quiet)
      type(rod_run), intent(in) :: self
      integer, intent(in) :: p
      !> The step (s) and Newton's tolerance.
      real(dp), intent(in) :: h, tolerance
      integer, intent(out) :: lo, hi
      !> The motion in a step below which a node is quiet, m.
      real(dp), intent(out) :: quiet
      integer :: n, k, first, last
      associate (piece => self%pieces(p), rod => self%pieces(p)%problem%piece)
         n = rod%n
         lo = 1
         hi = n
         quiet = 0
         if (.not. self%options%skip_quiescent .or. self%options%newton%reuse_jacobian) return
         ! Quiet: a motion far below the tolerance, or at the round-off of the coordinates
         ! (where the whole solve moves the quiescent nodes too, by a few units in the last place).
         ! (largest_magnitude on the 2 n values: the intrinsic on piece%r took 33 instructions a
         ! node; with it attempt's own instructions on fast_180kN went 7.4e6 -> 3.5e6, callgrind.)
         quiet = max(quiet_fraction*tolerance*rod%length_ref, quiet_ulps*epsilon(1.0_dp)*largest_magnitude(2*n, piece%r))
         if (self%history%n <= 0) return
         if (allocated(rod%loads)) then
            if (size(rod%loads) > 0) return
         end if
         if (allocated(rod%points)) return
         if (n < 2*window_margin + 4) return
         first = n + 1
         last = 0
         if (.not. end_steady(rod%end_a, self%t, self%t + h)) then
            first = 1
            last = 1
         end if
         if (.not. end_steady(rod%end_b, self%t, self%t + h)) then
            first = min(first, n)
            last = n
         end if
         do k = 1, n
            if (h*max(abs(piece%v(1, k)), abs(piece%v(2, k))) > quiet .or. .not. ieee_is_finite(sum(piece%v(:, k)))) then
               first = min(first, k)
               exit
            end if
         end do
         do k = n, 1, -1
            if (h*max(abs(piece%v(1, k)), abs(piece%v(2, k))) > quiet .or. .not. ieee_is_finite(sum(piece%v(:, k)))) then
               last = max(last, k)
               exit
            end if
         end do
         ! Nothing moves: nothing to centre a window on.
         if (last == 0) return
         lo = max(1, first - window_margin)
         hi = min(n, last + window_margin)
      end associate
   end subroutine choose_window

   !> Whether an end's condition stays the same over [ta, tb]: an end that does not change
   !> with time (a fixed end, a free end, a point mass, a constant force, a spring; not a
   !> moving end nor a force history).
   logical function end_steady(end, ta, tb)
      class(end_condition), intent(in) :: end
      real(dp), intent(in) :: ta, tb
      end_steady = .not. end%time_dependent()
      if (.not. end_steady) return
      end_steady = all(same_value(end%applied_force(ta), end%applied_force(tb))) .and. &
                   same_value(end%applied_couple(ta), end%applied_couple(tb))
   end function end_steady

   !> a == b as numbers (elemental).
   elemental logical function same_value(a, b)
      real(dp), intent(in) :: a, b
      same_value = a == b
   end function same_value

   !> Reject states outside the model's range (after an attempt on every piece).
   module subroutine check_state(self, h, error)
      type(rod_run), intent(inout) :: self
      real(dp), intent(in) :: h
      type(error_type), allocatable, intent(out) :: error
      integer :: p, k
      real(dp), allocatable :: dphi(:), fold(:)
      do p = 1, size(self%pieces)
         associate (piece => self%pieces(p)%problem%piece, x => self%pieces(p)%x)
            ! The last evaluation (accepted_state) was at x: e1, l1, th1 are those of the new level.
            call check_range(x, piece%l1, piece%law, p, error)
            if (allocated(error)) return
            ! Each cell's rotation once, the last evaluation's where it was at x (cell_rotations).
            if (allocated(dphi)) deallocate (dphi, fold)
            allocate (dphi(piece%n - 1), fold(piece%n))
            call cell_rotations(piece, reshape(x, [2, piece%n]), dphi)
            fold = 0
            do k = 2, piece%n - 1
               fold(k) = abs(piece%th1(k) - piece%th0(k) - (dphi(k) - dphi(k - 1)))
            end do
            call check_folds(fold, p, h, error)
            if (allocated(error)) return
         end associate
      end do
   end subroutine check_state

   !> The model's range after an attempt on piece p (either model): finite
   !> unknowns x and no cell squeezed below 5 % of its length (l: cell lengths
   !> / unstretched lengths at the new level). Error stat_numerics naming the first.
   module subroutine check_range(x, l, law, p, error)
      !> Unknowns of the new level; cell length ratios.
      real(dp), intent(in) :: x(:), l(:)
      !> The piece's law (for the advice) and its index.
      class(material_law), intent(in) :: law
      integer, intent(in) :: p
      type(error_type), allocatable, intent(out) :: error
      integer :: c
      if (.not. all(ieee_is_finite(x))) then
         call fatal_error(error, 'non-finite positions in piece '//str(p), stat_numerics)
         return
      end if
      do c = 1, size(l)
         if (l(c) < collapsed_length) then
            call fatal_error(error, 'cell '//str(c)//' of piece '//str(p)//' squeezed to '// &
                             str(100*l(c))//' % of its length (strain '//str(l(c) - 1)// &
                             '): the compressed zone has collapsed'//trim(squeeze_advice(law)), stat_numerics)
            return
         end if
      end do
   end subroutine check_range

   !> The model's range (either model): no turning angle passed half a turn
   !> within the step of h s. fold(k) is how far node k's change of turning
   !> angle in the step is from the change its two cells' rotations give (rad:
   !> near 0, or near 2 pi when the angle went through half a turn); error
   !> stat_numerics for the first node above 3 rad (or not a number).
   module subroutine check_folds(fold, p, h, error)
      !> Mismatch at each node (0 at the ends), rad.
      real(dp), intent(in) :: fold(:)
      !> Piece index; the step, s.
      integer, intent(in) :: p
      real(dp), intent(in) :: h
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      do k = 1, size(fold)
         if (.not. (fold(k) <= 3.0_dp)) then
            call fatal_error(error, 'the turning angle at node '//str(k)//' of piece '//str(p)// &
                             ' passed half a turn within one step of '//str(h)//' s (a fold)', stat_numerics)
            return
         end if
      end do
   end subroutine check_folds

   !> What to try when a cell collapses.
   function squeeze_advice(law) result(advice)
      class(material_law), intent(in) :: law
      character(:), allocatable :: advice
      if (index(law%name(), 'without compression') > 0) then
         advice = ' (with compression = ''none'' nothing resists the shortening of the cable: the slack material '// &
                  'piles up into the cells; the law''s compressive branch, compression = ''law'', resists it)'
      else
         advice = ' (more nodes resolve the buckling, or a smaller dt or courant)'
      end if
   end function squeeze_advice

   !> Accept the step of length h: new velocities, the reactions at held ends,
   !> the work and the dissipation of the step, and the resolution figures.
   module subroutine accept(self, h)
      type(rod_run), intent(inout) :: self
      real(dp), intent(in) :: h
      integer :: p, n, j
      real(dp), allocatable :: r1(:, :), v1(:, :), dv(:, :), mdv(:, :)
      real(dp) :: theta, dphi, f(2)
      theta = self%options%theta
      do p = 1, size(self%pieces)
         associate (run_piece => self%pieces(p), piece => self%pieces(p)%problem%piece)
            n = piece%n
            r1 = reshape(run_piece%x, [2, n])
            allocate (v1(2, n))
            call piece%new_velocity(r1, h, theta, v1)
            if (piece%end_a%held()) run_piece%reaction(:, 1) = piece%reaction(1, run_piece%x, h, theta)
            if (piece%end_b%held()) run_piece%reaction(:, 2) = piece%reaction(n, run_piece%x, h, theta)
            if (self%options%energy) then
               ! Work of the ends: applied force (mean over the step) or reaction, times the displacement.
               call end_work(piece%end_a, 1, 1)
               call end_work(piece%end_b, n, 2)
               ! Distributed loads: their force on each node (centred on the step) times its displacement.
               self%load_work = self%load_work + displacement_work(n, piece%load_node, r1, run_piece%r)
               ! Internal damping: each cell dissipates ds c (eps1 - eps0)^2 / dt; a rope that
               ! cannot push, ds (N - q) (eps1 - eps0) (slack_cell_force).
               if (allocated(piece%sections)) then
                  do j = 1, size(piece%sections)
                     associate (sec => piece%sections(j), a => piece%sections(j)%first, b => piece%sections(j)%last)
                        if (sec%damping <= 0) cycle
                        if (sec%law%strain_slack > -huge(1.0_dp)) then
                           self%dissipation = self%dissipation + sum(piece%ds(a:b)*slack_dissipation(sec%law, &
                                              piece%l0(a:b) - 1, piece%l1(a:b) - 1, sec%damping, h, small_strain_step))
                        else
                           self%dissipation = self%dissipation + sec%damping*sum(piece%ds(a:b)*(piece%l1(a:b) - &
                                                                                               piece%l0(a:b))**2)/h
                        end if
                     end associate
                  end do
               else if (piece%damping > 0) then
                  if (piece%law%strain_slack > -huge(1.0_dp)) then
                     self%dissipation = self%dissipation + sum(piece%ds*slack_dissipation(piece%law, piece%l0 - 1, &
                                                               piece%l1 - 1, piece%damping, h, small_strain_step))
                  else
                     self%dissipation = self%dissipation + piece%damping*sum(piece%ds*(piece%l1 - piece%l0)**2)/h
                  end if
               end if
               ! Ends that depend on their state (springs): their damping's work over the step.
               if (piece%end_a%state_dependent()) call end_damping(piece%end_a, 1)
               if (piece%end_b%state_dependent()) call end_damping(piece%end_b, n)
               if (theta /= 0.5_dp) then
                  dv = v1 - run_piece%v
                  allocate (mdv(2, n))
                  call piece%mass_times(dv, mdv)
                  self%dissipation = self%dissipation + (theta - 0.5_dp)*sum(dv*mdv)
                  deallocate (mdv)
               end if
            end if
            self%summary%max_turning_angle = max(self%summary%max_turning_angle, maxval(abs(piece%th1)))
            call note_min_strain(self%summary, piece%l1, run_piece%column, self%s_out, self%t + h)
            self%summary%max_strain = max(self%summary%max_strain, maxval(piece%l1) - 1)
            ! The levels change hands without copies (four copies of (2, n) through the
            ! components' descriptors cost 21 million instructions on fast_180kN).
            call move_alloc(run_piece%r, run_piece%r_prev)
            call move_alloc(run_piece%v, run_piece%v_prev)
            call move_alloc(r1, run_piece%r)
            call move_alloc(v1, run_piece%v)
         end associate
      end do

   contains

      !> What the damping of a state-dependent end at node `node` took in the step: minus the
      !> work of the damping part of its step force (the elastic part is the change of its
      !> stored energy, which the energies hold).
      subroutine end_damping(end, node)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: node
         real(dp) :: x0(3), x1(3), f3(3), j3(3, 3), damp(3)
         associate (run_piece => self%pieces(p))
            x0 = [run_piece%r(1, node), 0.0_dp, run_piece%r(2, node)]
            x1 = [r1(1, node), 0.0_dp, r1(2, node)]
            call end%step_force(self%t, h, x0, x1, f3, j3, damp)
            self%dissipation = self%dissipation - dot_product(damp, x1 - x0)
         end associate
      end subroutine end_damping

      !> Work of one end in the step: force times displacement, couple times the end cell's rotation.
      subroutine end_work(end, node, side)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: node, side
         integer :: cell
         associate (run_piece => self%pieces(p), piece => self%pieces(p)%problem%piece)
            if (end%held()) then
               f = run_piece%reaction(:, side)
            else
               f = 0.5_dp*(end%applied_force(self%t) + end%applied_force(self%t + h))
            end if
            self%work = self%work + dot_product(f, r1(:, node) - run_piece%r(:, node))
            cell = merge(1, n - 1, side == 1)
            dphi = atan2(cross2(piece%e0(:, cell), piece%e1(:, cell)), dot_product(piece%e0(:, cell), piece%e1(:, cell)))
            self%work = self%work + 0.5_dp*(end%applied_couple(self%t) + end%applied_couple(self%t + h))*dphi
         end associate
      end subroutine end_work
   end subroutine accept

   !> sum(f*(r1 - r0)) over (2, n) arrays, in the order of that expression (element
   !> by element, column by column), on explicit-shape arrays: the expression on the
   !> pieces' components took 10 700 instructions a step on fast_180kN.
   pure real(dp) function displacement_work(n, f, r1, r0) result(w)
      !> Nodes.
      integer, intent(in) :: n
      !> Forces (2, n), N.
      real(dp), intent(in) :: f(2, n)
      !> Positions at the end and start of the step (2, n), m.
      real(dp), intent(in) :: r1(2, n), r0(2, n)
      integer :: k
      w = 0
      do k = 1, n
         w = w + f(1, k)*(r1(1, k) - r0(1, k))
         w = w + f(2, k)*(r1(2, k) - r0(2, k))
      end do
   end function displacement_work

   !> The break: split the piece at the break node into two, or release a held
   !> end. The new ends carry the force (and at an inner break the moment) that
   !> held them at the break time, ramped to zero over t_break (eqs. 31-32).
   module subroutine split(self, error)
      type(rod_run), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: x(:), res(:)
      type(band_matrix) :: unused
      integer :: n, kb, p
      real(dp) :: w_a, w_b, m_b
      n = self%pieces(1)%problem%piece%n
      if (self%scene%break_at_a .or. self%scene%break_at_b) then
         ! The held end lets go with the support's force at the break time.
         if (self%scene%break_at_b) then
            self%cut_force(:, 1) = self%pieces(1)%reaction(:, 2)
         else
            self%cut_force(:, 1) = self%pieces(1)%reaction(:, 1)
         end if
         call apply_split(self)
         return
      end if
      ! Inside: the elastic cell forces at the current positions.
      kb = self%break_node
      associate (piece => self%pieces(1)%problem%piece)
         x = reshape(self%pieces(1)%r, [2*n])
         allocate (res(2*n))
         call piece%static_system(x, self%t, res, unused, .false.)
         if (allocated(piece%sections)) then
            w_a = 0.5_dp*piece%sections(piece%cell_sec(kb - 1))%weight*piece%ds(kb - 1)
            w_b = 0.5_dp*piece%sections(piece%cell_sec(kb))%weight*piece%ds(kb)
         else
            w_a = 0.5_dp*piece%weight*piece%ds(kb - 1)
            w_b = 0.5_dp*piece%weight*piece%ds(kb)
         end if
         m_b = bend_moment(piece, kb, piece%th1(kb))
         self%cut_force(:, 1) = piece%force(:, kb - 1) + [0.0_dp, w_a]
         self%cut_force(:, 2) = -piece%force(:, kb) + [0.0_dp, w_b]
         self%cut_couple = [m_b, -m_b]
         ! The bending energy at the break node leaves with the cut: booked as work.
         self%work = self%work - bend_energy(piece, kb, piece%th1(kb))
      end associate
      call apply_split(self)
      ! Distributed loads: each new end node keeps its own cell's share (the pieces' loads at rest),
      ! so that both pieces start in the balance the whole cable had.
      if (.not. allocated(self%pieces(1)%problem%piece%loads)) return
      do p = 1, 2
         associate (piece => self%pieces(p)%problem%piece)
            x = reshape(self%pieces(p)%r, [2*piece%n])
            res = x
            call piece%static_system(x, self%t, res, unused, .false.)
            self%cut_force(:, p) = self%cut_force(:, p) - piece%load_node(:, merge(piece%n, 1, p == 1))
         end associate
      end do
      select type (end => self%pieces(1)%problem%piece%end_b)
      type is (force_end)
         end%force0 = self%cut_force(:, 1)
      end select
      select type (end => self%pieces(2)%problem%piece%end_a)
      type is (force_end)
         end%force0 = self%cut_force(:, 2)
      end select
   end subroutine split

   !> The pieces after the break, with new ends that start from self%cut_force
   !> and cut_couple: the released end replaced (a break at an end), or the
   !> piece cut in two at the break node, each new piece taking the positions,
   !> velocities, output columns, history slots and reactions of its nodes.
   !> Also rebuilds the pieces of a broken run loaded from a checkpoint.
   module subroutine apply_split(self)
      type(rod_run), intent(inout) :: self
      type(piece_run), allocatable :: old(:)
      type(force_end) :: cut_a, cut_b
      integer :: n, kb
      self%broken = .true.
      n = self%pieces(1)%problem%piece%n
      cut_a = force_end(kind_name='break', history='ramp', t0=self%scene%break_time, duration=self%scene%t_break, &
                        force0=self%cut_force(:, 1), couple0=self%cut_couple(1))
      if (self%scene%break_at_a .or. self%scene%break_at_b) then
         associate (piece => self%pieces(1)%problem%piece)
            if (self%scene%break_at_b) then
               cut_a%label = 'end_b'
               deallocate (piece%end_b)
               allocate (piece%end_b, source=cut_a)
            else
               cut_a%label = 'end_a'
               deallocate (piece%end_a)
               allocate (piece%end_a, source=cut_a)
            end if
         end associate
         self%pieces(1)%work%usable = .false.
         return
      end if
      kb = self%break_node
      cut_b = force_end(kind_name='break', history='ramp', t0=self%scene%break_time, duration=self%scene%t_break, &
                        force0=self%cut_force(:, 2), couple0=self%cut_couple(2))
      cut_a%label = 'break_a'
      cut_b%label = 'break_b'
      call move_alloc(self%pieces, old)
      allocate (self%pieces(2))
      associate (whole => old(1)%problem%piece)
         call self%pieces(1)%problem%piece%init(self%s(1:kb), whole%mass_per_length, whole%weight, whole%ei, whole%gravity, &
                                                 whole%mu, whole%law, whole%end_a, cut_a, whole%tension_ref, whole%mu2, &
                                                 whole%damping)
         call self%pieces(2)%problem%piece%init(self%s(kb:n), whole%mass_per_length, whole%weight, whole%ei, whole%gravity, &
                                                 whole%mu, whole%law, cut_b, whole%end_b, whole%tension_ref, whole%mu2, &
                                                 whole%damping)
         if (allocated(whole%loads)) then
            self%pieces(1)%problem%piece%loads = whole%loads
            self%pieces(2)%problem%piece%loads = whole%loads
         end if
      end associate
      call piece_sections(self%pieces(1)%problem%piece, self%scene)
      call piece_sections(self%pieces(2)%problem%piece, self%scene)
      self%pieces(1)%r = old(1)%r(:, 1:kb)
      self%pieces(1)%v = old(1)%v(:, 1:kb)
      self%pieces(1)%column = old(1)%column(1:kb)
      self%pieces(1)%end_slot = [1, 3]
      self%pieces(1)%reaction(:, 1) = old(1)%reaction(:, 1)
      self%pieces(2)%r = old(1)%r(:, kb:n)
      self%pieces(2)%v = old(1)%v(:, kb:n)
      self%pieces(2)%column = [kb + 1, old(1)%column(kb + 1:n)]
      self%pieces(2)%end_slot = [4, 2]
      self%pieces(2)%reaction(:, 2) = old(1)%reaction(:, 2)
      call self%pieces(1)%work%init(2*kb, rod_kl, rod_ku, spread(self%pieces(1)%problem%piece%length_ref, 1, 2*kb))
      call self%pieces(2)%work%init(2*(n - kb + 1), rod_kl, rod_ku, &
                                    spread(self%pieces(2)%problem%piece%length_ref, 1, 2*(n - kb + 1)))
   end subroutine apply_split
   !> The planar model's attempt of h on every piece (the first that fails stops the others),
   !> then the checks of the new state (check_state).
   module subroutine planar_attempt(self, run, h, iterations, retry_same, error)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      integer, intent(out) :: iterations
      logical, intent(out) :: retry_same
      type(error_type), allocatable, intent(out) :: error
      integer :: p
      logical :: kept, any_kept
      any_kept = .false.
      retry_same = .false.
      iterations = 0
      do p = 1, size(run%pieces)
         call attempt(run, p, h, kept, iterations, error)
         any_kept = any_kept .or. kept
         if (allocated(error)) then
            ! Newton failed: from a kept factorisation the same step is tried again with a fresh one.
            retry_same = any_kept
            return
         end if
      end do
      call check_state(run, h, error)
   end subroutine planar_attempt

   !> The planar model's rejection: no piece keeps its factorisation (an attempt leaves the
   !> current state, r and v, alone).
   module subroutine planar_reject(self, run)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer :: p
      do p = 1, size(run%pieces)
         run%pieces(p)%work%usable = .false.
      end do
   end subroutine planar_reject

   !> The planar model's search for a break by tension (one piece: the run without its break).
   module subroutine planar_watch(self, run, h, retry)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      logical, intent(out) :: retry
      real(dp), allocatable :: tensions(:, :), r1(:, :)
      integer :: c, j
      associate (piece => run%pieces(1)%problem%piece)
         if (size(run%scene%sections) > 1) then
            ! A line of segments: each cell against its own segment's MBL.
            r1 = reshape(run%pieces(1)%x, [2, piece%n])
            allocate (tensions(piece%n - 1, 3))
            do c = 1, piece%n - 1
               tensions(c, 1) = piece%cell_tension(c, norm2(run%pieces(1)%r(:, c + 1) - run%pieces(1)%r(:, c)) &
                                                      /piece%ds(c) - 1)
               tensions(c, 2) = piece%cell_tension(c, norm2(r1(:, c + 1) - r1(:, c))/piece%ds(c) - 1)
               j = section_at(run%scene, 0.5_dp*(piece%s(c) + piece%s(c + 1)))
               tensions(c, 3) = 0
               if (run%scene%sections(j)%mbl > 0) tensions(c, 3) = run%watch%mbl/run%scene%sections(j)%mbl
            end do
            call watch_step(run, h, run%pieces(1)%r, r1, piece%ds, piece%law, retry, tensions)
         else
            call watch_step(run, h, run%pieces(1)%r, reshape(run%pieces(1)%x, [2, piece%n]), piece%ds, piece%law, &
                            retry)
         end if
      end associate
      if (retry) run%pieces(1)%work%usable = .false.
   end subroutine planar_watch

   !> The planar model's acceptance of the attempt of h (accept).
   module subroutine planar_accept(self, run, h)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: h
      call accept(run, h)
   end subroutine planar_accept

   !> The planar model's break (split).
   module subroutine planar_split(self, run, error)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      type(error_type), allocatable, intent(out) :: error
      call split(run, error)
   end subroutine planar_split

end submodule xcable_driver_rod_run_step
