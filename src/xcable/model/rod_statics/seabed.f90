!> The statics of a line on a seabed (docs/theory/seabed.md): a line nearly slack on the bottom
!> between held ends paid in from a taut state (pay_in), a loose end resting on the bottom laid
!> down along it (lay_down), a free end hanging onto a flat, frictionless bottom refused
!> (refuse_slack_tail), the floor under a point and the note on a line too long to be taut over
!> it, and the continuation in the seabed's static friction (friction_continuation).
!> (A submodule of model/rod_statics.f90.)
submodule (xcable_model_rod_statics) xcable_model_rod_statics_seabed
   implicit none

   !> Smallest step of the continuation in the static friction (a share of it) when Newton fails to
   !> take it at once.
   real(dp), parameter :: static_friction_min_share = 1.0_dp/64
   !> The chords (shares of the line's length) tried in turn as the taut start from which the
   !> statics pay in a line nearly slack on the seabed (pay_in), and the smallest step of the
   !> pay-in, a share of the offset.
   real(dp), parameter :: payout_chord(3) = [0.9_dp, 0.95_dp, 0.98_dp], payout_min_share = 1.0_dp/1024
   !> The step of the pay-in (a share of the offset) from which a failed Newton solve is followed by
   !> the relaxation from the last state.
   real(dp), parameter :: payout_relax_share = 1.0_dp/64
   !> The pull with which the statics lay a loose end on a seabed (lay_down) before letting it go
   !> to its own load: the touchdown bend's radius H / w over this many cells.
   real(dp), parameter :: lay_pull_cells = 5

contains

   !> Both ends held over a floor (a seabed), the direct solve failed, and the line is shorter
   !> than slack_on_floor_note's way (a line nearly slack on the bottom): the line paid in,
   !> before the relaxation. End b is moved away from end a horizontally until the chord is
   !> payout_chord of the line's length (tried in turn: a line taut enough for Newton from the
   !> catenary guess), and brought back in steps of a share of that offset, each solve from the
   !> last state, the step halved after a failure (down to payout_min_share; from
   !> payout_relax_share down a failed Newton solve is retried by the relaxation) and doubled
   !> after a success. A rope that cannot push is paid in as one that can, then solved as itself;
   !> if it would push somewhere, it is slack there (refused, slack_why: the error if the
   !> relaxation finds no state either; it may find one of the heaps, returned as before). On a
   !> frictionless bottom the static state of a line with any tension is unique (its grounded
   !> part straight and taut), so the path only finds it. err in: the direct path's error; out:
   !> unchanged (with why the pay-in failed), the refusal, or none.
   module subroutine pay_in(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(inout) :: err
      class(end_condition), allocatable :: own_b
      type(error_type), allocatable :: sub
      real(dp), allocatable :: r_good(:, :)
      real(dp) :: pa(2), pb(2), far, done, step, try, chord, ten(self%n - 1)
      integer :: k
      logical :: cut
      if (.not. (self%piece%end_a%held() .and. self%piece%end_b%held())) return
      if (len(slack_on_floor_note(self)) > 0) return
      pa = self%piece%end_a%position(0.0_dp)
      pb = self%piece%end_b%position(0.0_dp)
      if (floor_at(self, pa(1)) <= -huge(1.0_dp) .or. floor_at(self, pb(1)) <= -huge(1.0_dp)) return
      if (.not. abs(pb(1) - pa(1)) > 0) return
      call move_alloc(self%piece%end_b, own_b)
      ! A rope that cannot push is paid in as one that can (uncut_laws: an iterate that squeezes
      ! a grounded cell meets no stiffness otherwise); where the line is taut the two agree.
      call uncut_laws(self, cut)
      ! The taut start: the first chord of payout_chord whose direct solve succeeds.
      far = 0
      do k = 1, size(payout_chord)
         chord = payout_chord(k)*self%scene%length
         if (abs(pb(2) - pa(2)) >= chord .or. hypot(pb(1) - pa(1), pb(2) - pa(2)) >= chord) cycle
         far = sign(sqrt(chord**2 - (pb(2) - pa(2))**2), pb(1) - pa(1)) - (pb(1) - pa(1))
         call move_b(self, pb + [far, 0.0_dp])
         call first_guess(self, sub)
         if (allocated(sub)) exit
         call solve_with_loads(self, sub)
         if (.not. allocated(sub)) exit
         deallocate (sub)
      end do
      if (far == 0 .or. allocated(sub)) then
         call own_laws_back(self)
         if (allocated(self%piece%end_b)) deallocate (self%piece%end_b)
         call move_alloc(own_b, self%piece%end_b)
         err%message = err%message//'; paying the line in: no taut start found'
         return
      end if
      r_good = self%state%r
      done = 0
      step = 0.25_dp
      do while (done < 1)
         try = min(1.0_dp, done + step)
         call move_b(self, pb + [(1 - try)*far, 0.0_dp])
         call solve_now(self, sub)
         ! Newton may cycle where the nodes touch down one by one on a stiff bottom: on a small
         ! step, the overdamped path from the last state (relax).
         if (allocated(sub) .and. step <= payout_relax_share) then
            self%state%r = r_good
            call relax(self, sub)
         end if
         if (allocated(sub)) then
            self%state%r = r_good
            call move_b(self, pb + [(1 - done)*far, 0.0_dp])
            step = step/2
            if (step < payout_min_share) exit
            deallocate (sub)
         else
            done = try
            r_good = self%state%r
            step = 2*step
         end if
      end do
      ! Paid in, a rope that cannot push where the one that can pushes (a grounded part rising
      ! towards the touchdown, whose weight up the slope exceeds the tension there): it is
      ! slack there, heaped on the frictionless bottom in any shape.
      if (.not. allocated(sub) .and. cut) then
         do k = 1, self%n - 1
            ten(k) = self%piece%cell_tension(k, norm2(self%state%r(:, k + 1) - self%state%r(:, k))/self%piece%ds(k) - 1)
         end do
         k = minloc(ten, 1)
         if (ten(k) < 0) then
            call own_laws_back(self)
            deallocate (self%piece%end_b)
            call move_alloc(own_b, self%piece%end_b)
            self%refused = .true.
            self%slack_why = ('statics: the line lies on the seabed with too little tension to be '// &
                             'taut: with its law continued below zero strain it would push '// &
                             str(-ten(k))//' N at s = '//str(self%piece%s(k) - self%piece%s(1) + &
                             0.5_dp*self%piece%ds(k))//' m (on a bottom that rises towards the '// &
                             'touchdown, where the grounded line''s weight up the slope exceeds the '// &
                             'tension), so a rope that cannot push (compression = ''none'') lies slack '// &
                             'there, heaped on the frictionless bottom in any shape, with no single static '// &
                             'state; move the ends apart, shorten the line, or give the law its compressive '// &
                             'branch (compression = ''law'')')
            return
         end if
      end if
      call own_laws_back(self)
      deallocate (self%piece%end_b)
      call move_alloc(own_b, self%piece%end_b)
      if (.not. allocated(sub)) call solve_now(self, sub)
      if (allocated(sub)) then
         err%message = err%message//'; paying the line in from '//str(abs(far))//' m further out: '// &
                       sub%message//' (with end b '//str(abs(1 - done)*abs(far))//' m from its place)'
         return
      end if
      deallocate (err)
   end subroutine pay_in

   !> End b replaced by a fixed end at the point p (pay_in).
   subroutine move_b(self, p)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      real(dp), intent(in) :: p(2)
      if (allocated(self%piece%end_b)) deallocate (self%piece%end_b)
      allocate (self%piece%end_b, source=fixed_end(point=p))
      self%piece%end_b%label = 'end_b'
   end subroutine move_b

   !> One end held, the other loose (not state-dependent) and resting on a seabed under a pull
   !> along it, the direct solve failed: Newton from the line laid on the bottom. The horizontal
   !> tension H of the grounded part is the loose end's horizontal force (or, with none, its
   !> weight down the bottom's slope, w (L - drop) |slope|: a free end on a slope lies downhill);
   !> the guess is the catenary from the held end whose tangent is horizontal where it reaches
   !> the floor (suspended length sqrt(drop^2 + 2 drop H / w)), then straight along the floor,
   !> away from the held end in the direction of that pull. Solved with the laws' compressive
   !> branch first (uncut_laws), then with the laws themselves. err in: the direct path's
   !> error; out: unchanged (with why this failed) or none.
   module subroutine lay_down(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(inout) :: err
      type(error_type), allocatable :: sub
      class(end_condition), allocatable :: own_loose
      real(dp) :: top(2), load(2), drop, hh, hh0, ls, slope, sgn, d, ss(self%n), rr(2, self%n), eps(self%n), &
                  ten(self%n), xs
      real(dp) :: done, step, try
      real(dp), allocatable :: r_good(:, :)
      logical :: held_a, cut
      integer :: k, j
      held_a = self%piece%end_a%held()
      if (held_a .eqv. self%piece%end_b%held()) return
      if (held_a) then
         if (self%piece%end_b%state_dependent() .or. self%piece%end_b%point_mass() /= 0) return
         load = self%piece%end_b%applied_force(0.0_dp)
         top = self%piece%end_a%position(0.0_dp)
      else
         if (self%piece%end_a%state_dependent() .or. self%piece%end_a%point_mass() /= 0) return
         load = self%piece%end_a%applied_force(0.0_dp)
         top = self%piece%end_b%position(0.0_dp)
      end if
      if (floor_at(self, top(1)) <= -huge(1.0_dp) .or. .not. self%scene%weight > 0) return
      drop = top(2) - floor_at(self, top(1))
      d = 0.5_dp*self%scene%length
      slope = (floor_at(self, top(1) + d) - floor_at(self, top(1) - d))/(2*d)
      if (load(1) /= 0) then
         hh = abs(load(1))
         sgn = sign(1.0_dp, load(1))
      else if (slope /= 0) then
         hh = self%scene%weight*max(self%scene%length - drop, 0.0_dp)*abs(slope)
         sgn = -sign(1.0_dp, slope)
      else
         return
      end if
      if (.not. (hh > 0 .and. drop > 0)) return
      ! The pull the line is laid with: its touchdown bend (radius H / w) over lay_pull_cells cells.
      hh0 = max(hh, lay_pull_cells*self%scene%weight*maxval(self%piece%ds))
      ls = sqrt(drop**2 + 2*drop*hh0/self%scene%weight)
      if (ls >= self%scene%length) return
      ! The arc lengths from the held end.
      if (held_a) then
         ss = self%piece%s - self%piece%s(1)
      else
         ss = self%piece%s(self%n) - self%piece%s(self%n:1:-1)
      end if
      call catenary_from_force(self%scene%law, self%scene%weight, [sgn*hh0, -self%scene%weight*ls], top, ss, rr, eps, &
                               ten, guess_panels)
      j = count(ss <= ls)
      xs = rr(1, j) + sgn*(ls - ss(j))
      do k = j + 1, self%n
         rr(1, k) = xs + sgn*(ss(k) - ls)
         rr(2, k) = floor_at(self, rr(1, k))
      end do
      if (held_a) then
         self%state%r = rr
      else
         self%state%r = rr(:, self%n:1:-1)
      end if
      ! The loose end pulled by hh0 - hh more along the bottom, then let go in shares of that.
      if (held_a) then
         call move_alloc(self%piece%end_b, own_loose)
      else
         call move_alloc(self%piece%end_a, own_loose)
      end if
      call uncut_laws(self, cut)
      call pull_loose(self, held_a, load + [sgn*(hh0 - hh), 0.0_dp])
      call solve_with_loads(self, sub)
      done = 0
      step = 0.25_dp
      if (.not. allocated(sub)) then
         r_good = self%state%r
         do while (done < 1)
            try = min(1.0_dp, done + step)
            call pull_loose(self, held_a, load + [(1 - try)*sgn*(hh0 - hh), 0.0_dp])
            call solve_now(self, sub)
            if (allocated(sub)) then
               self%state%r = r_good
               step = step/2
               if (step < payout_min_share) exit
               deallocate (sub)
            else
               done = try
               r_good = self%state%r
               step = 2*step
            end if
         end do
      end if
      if (held_a) then
         deallocate (self%piece%end_b)
         call move_alloc(own_loose, self%piece%end_b)
      else
         deallocate (self%piece%end_a)
         call move_alloc(own_loose, self%piece%end_a)
      end if
      if (.not. allocated(sub)) call solve_now(self, sub)
      call own_laws_back(self)
      if (.not. allocated(sub) .and. cut) call solve_now(self, sub)
      if (allocated(sub)) then
         err%message = err%message//'; from the line laid on the bottom, pulled by '//str(hh0)// &
                       ' N and let go to '//str(nint(100*done))//' %: '//sub%message
         return
      end if
      deallocate (err)
   end subroutine lay_down

   !> The loose end (end b with end a held, or end a) a force end with the force f (lay_down).
   subroutine pull_loose(self, held_a, f)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      logical, intent(in) :: held_a
      real(dp), intent(in) :: f(2)
      type(force_end) :: pulled
      pulled%force0 = f
      if (held_a) then
         if (allocated(self%piece%end_b)) deallocate (self%piece%end_b)
         allocate (self%piece%end_b, source=pulled)
         self%piece%end_b%label = 'end_b'
      else
         if (allocated(self%piece%end_a)) deallocate (self%piece%end_a)
         allocate (self%piece%end_a, source=pulled)
         self%piece%end_a%label = 'end_a'
      end if
   end subroutine pull_loose

   !> One end held, the other free of horizontal force (free, a point mass, a vertical force),
   !> over a flat, frictionless floor with no current: the horizontal force is zero all along
   !> the line, which hangs straight down from the held end, and a line longer than that drop
   !> lies on the bottom with no tension, in any shape (straight either way, heaped): there is
   !> no single static state (Newton meets the singular Jacobian of the slack part). Refused
   !> with why, from the first guess (state%r: the vertical catenary) when it reaches below the
   !> floor and the loads on it have no horizontal part.
   module subroutine refuse_slack_tail(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: err
      type(band_matrix) :: unused
      real(dp) :: x(2*self%n), res(2*self%n), top(2), drop, load(2)
      logical :: held_a
      character(:), allocatable :: loose
      integer :: k
      held_a = self%piece%end_a%held()
      if (held_a .eqv. self%piece%end_b%held()) return
      if (any_static_form(self%piece%loads)) return
      if (held_a) then
         if (self%piece%end_b%state_dependent()) return
         load = self%piece%end_b%applied_force(0.0_dp)
         top = self%piece%end_a%position(0.0_dp)
         loose = 'end b'
      else
         if (self%piece%end_a%state_dependent()) return
         load = self%piece%end_a%applied_force(0.0_dp)
         top = self%piece%end_b%position(0.0_dp)
         loose = 'end a'
      end if
      if (load(1) /= 0) return
      if (floor_at(self, top(1)) <= -huge(1.0_dp)) return
      ! The guess hangs straight down and reaches below the floor.
      if (maxval(abs(self%state%r(1, :) - top(1))) > 1.0e-9_dp*self%scene%length) return
      if (.not. any([(self%state%r(2, k) < floor_at(self, self%state%r(1, k)), k = 1, self%n)])) return
      ! No load along the floor on the guess (a slope, a current).
      x = reshape(self%state%r, [2*self%n])
      call unused%init(2*self%n, rod_kl, rod_ku)
      call self%problem%evaluate(x, res, unused, .false.)
      if (sum(abs(self%piece%load_node(1, :))) > 1.0e-9_dp*sum(abs(self%piece%load_node(2, :)))) return
      drop = top(2) - floor_at(self, top(1))
      call fatal_error(err, self%scene%source//': statics: '//loose//' is free of horizontal force and the line ('// &
                       str(self%scene%length)//' m) is longer than the drop from the held end to the seabed ('// &
                       str(drop)//' m), which is flat and frictionless (no current, no static_friction): '// &
                       'nothing pulls the line sideways, it hangs straight down and about '// &
                       str(self%scene%length - drop)//' m of it lies on the bottom with no tension, in any shape '// &
                       '(straight either way or heaped), so it has no single static state; hold '//loose// &
                       ' where it should lie on the bottom (kind = ''fixed'', its x and z on the bottom), '// &
                       'or shorten the line below the drop', stat_input)
   end subroutine refuse_slack_tail

   !> Height of the highest floor of the loads (a seabed's bottom) under the horizontal point
   !> x, m (-huge: none).
   real(dp) module function floor_at(self, x) result(z)
      !> The solve.
      type(statics_solve), intent(in) :: self
      real(dp), intent(in) :: x
      integer :: k
      z = -huge(1.0_dp)
      if (.not. allocated(self%piece%loads)) return
      do k = 1, size(self%piece%loads)
         z = max(z, self%piece%loads(k)%load%floor([x]))
      end do
   end function floor_at

   !> Both ends held over a floor (a seabed) and a line at least as long as the way from
   !> one end straight down to the floor, along it, and straight up to the other end: there
   !> is no taut static state, the excess lies slack on a frictionless floor (any heap of it
   !> is an equilibrium), and Newton finds none. The note for the statics' error says so.
   module function slack_on_floor_note(self) result(note)
      !> The solve.
      type(statics_solve), intent(in) :: self
      character(:), allocatable :: note
      real(dp) :: pa(2), pb(2), fa, fb, way
      note = ''
      if (.not. (self%piece%end_a%held() .and. self%piece%end_b%held())) return
      pa = self%piece%end_a%position(0.0_dp)
      pb = self%piece%end_b%position(0.0_dp)
      fa = floor_at(self, pa(1))
      fb = floor_at(self, pb(1))
      if (fa <= -huge(1.0_dp) .or. fb <= -huge(1.0_dp)) return
      way = (pa(2) - fa) + hypot(pb(1) - pa(1), fb - fa) + (pb(2) - fb)
      if (self%scene%length >= way) note = '; the line ('//str(self%scene%length)//' m) is at least as long as the '// &
         'way down from end a to the seabed, along it and up to end b ('//str(way)//' m): it cannot be taut, '// &
         'and a slack line on a frictionless seabed has no single static state; move the ends apart or '// &
         'shorten the line'
   end function slack_on_floor_note

   !> When Newton fails from the state without the static friction to the state with it: from
   !> the former again, the friction in steps of its share, each from the last state found, the
   !> step halved after a failure (from a half, down to static_friction_min_share) and doubled
   !> after a success.
   module subroutine friction_continuation(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(inout) :: err
      real(dp), allocatable :: r_good(:, :)
      real(dp) :: done, step, try
      r_good = self%state%r
      deallocate (err)
      done = 0
      step = 0.5_dp
      do while (done < 1)
         try = min(1.0_dp, done + step)
         call loads_in_statics(self%piece%loads, .true., secant_stiffness(self%piece%law), self%scene%weight, try)
         call solve_now(self, err, static_friction_iterations)
         if (allocated(err)) then
            self%state%r = r_good
            step = step/2
            if (step < static_friction_min_share) then
               err%message = err%message//' (the continuation in the friction reached '// &
                             str(nint(100*done))//' % of it)'
               call loads_in_statics(self%piece%loads, .true., secant_stiffness(self%piece%law), &
                                     self%scene%weight)
               return
            end if
            deallocate (err)
         else
            done = try
            r_good = self%state%r
            step = 2*step
         end if
      end do
   end subroutine friction_continuation
end submodule xcable_model_rod_statics_seabed
