!> The statics' first guesses: the extensible catenary between the held ends or from the held
!> end under a loaded end's load (a spring's where it balances the catenary: state_end_load),
!> the folded catenary of a slack line between ends one above the other, and, for the
!> relaxation, the catenary under the weight and the distributed loads' mean on the chord.
!> (A submodule of model/rod_statics.f90.)
submodule (xcable_model_rod_statics) xcable_model_rod_statics_guess
   implicit none

   !> The sideways offset of the folded first guess of a slack line between ends one above the
   !> other (folded_guess), a share of the line's length.
   real(dp), parameter :: fold_offset = 0.1_dp

contains

   !> The catenary guess.
   module subroutine first_guess(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: err
      real(dp) :: n0(2), pa(2), pb(2), load(2), ss(self%n)
      real(dp), allocatable :: eps(:), ten(:), rr(:, :)
      logical :: held_a, held_b, segmented
      segmented = size(self%scene%sections) > 1
      allocate (eps(self%n), ten(self%n), rr(2, self%n))
      held_a = self%piece%end_a%held()
      held_b = self%piece%end_b%held()
      ss = self%piece%s - self%piece%s(1)
      if (held_a .and. held_b) then
         pa = self%piece%end_a%position(0.0_dp)
         pb = self%piece%end_b%position(0.0_dp)
         if (vertical_slack(self, pa, pb)) then
            call folded_guess(self, pa, pb, ss, err)
            return
         end if
         if (segmented) then
            call catenary_between(self%scene%law, self%scene%weight, self%scene%length, pa, pb, n0, err, &
                                  scene_segments(self%scene))
         else
            call catenary_between(self%scene%law, self%scene%weight, self%scene%length, pa, pb, n0, err)
         end if
         if (allocated(err)) then
            call prefix_error(err, self%scene%source//': statics: ')
            return
         end if
         call guess_from_force(self, n0, pa, ss, self%state%r)
      else if (held_a) then
         ! The internal force at s = L is the load of end b (its force and the point mass's weight).
         load = self%piece%end_b%applied_force(0.0_dp) - [0.0_dp, self%scene%gravity*self%piece%end_b%point_mass() + &
                                                                  body_weight(self, self%scene%length)]
         ! An end on a spring: the load where the spring balances the catenary.
         if (self%piece%end_b%state_dependent()) &
            call state_end_load(self, self%piece%end_b, self%piece%end_a%position(0.0_dp), .true., load)
         n0 = load - [0.0_dp, self%scene%weight*self%scene%length + body_weight(self, -1.0_dp)]
         pa = self%piece%end_a%position(0.0_dp)
         call guess_from_force(self, n0, pa, ss, self%state%r)
      else if (held_b) then
         ! The internal force at s = 0 balances the load of end a.
         load = self%piece%end_a%applied_force(0.0_dp) - [0.0_dp, self%scene%gravity*self%piece%end_a%point_mass() + &
                                                                  body_weight(self, 0.0_dp)]
         if (self%piece%end_a%state_dependent()) &
            call state_end_load(self, self%piece%end_a, self%piece%end_b%position(0.0_dp), .false., load)
         n0 = -load
         pb = self%piece%end_b%position(0.0_dp)
         call guess_from_force(self, n0, [0.0_dp, 0.0_dp], ss, rr)
         self%state%r(1, :) = rr(1, :) - rr(1, self%n) + pb(1)
         self%state%r(2, :) = rr(2, :) - rr(2, self%n) + pb(2)
      else
         call fatal_error(err, self%scene%source//': statics: neither end is held (fixed or moving): the cable has '// &
                          'no static position', stat_input)
      end if
   end subroutine first_guess

   !> The net weight of the bodies (scene%points) at arc length s (N), or with s < 0 of those
   !> inside the line (not at its ends).
   real(dp) function body_weight(self, s) result(w)
      !> The solve.
      type(statics_solve), intent(in) :: self
      real(dp), intent(in) :: s
      integer :: k
      w = 0
      if (.not. allocated(self%scene%points)) return
      do k = 1, size(self%scene%points)
         associate (p => self%scene%points(k))
            if (s >= 0) then
               if (abs(p%s - s) <= 1.0e-9_dp*self%scene%length) w = w + p%net_weight()
            else if (p%s > 1.0e-9_dp*self%scene%length .and. p%s < (1 - 1.0e-9_dp)*self%scene%length) then
               w = w + p%net_weight()
            end if
         end associate
      end do
   end function body_weight

   !> Whether both held ends are one above the other (their horizontal distance below 1e-9 of
   !> the line's length) and the line is slack (their distance shorter than its length at zero
   !> tension): it hangs folded.
   logical function vertical_slack(self, pa, pb)
      !> The solve.
      type(statics_solve), intent(in) :: self
      real(dp), intent(in) :: pa(2), pb(2)
      vertical_slack = abs(pb(1) - pa(1)) < 1.0e-9_dp*max(self%scene%length, 1.0_dp) .and. &
                       norm2(pb - pa) < self%scene%length*(1 + self%scene%law%strain_at(0.0_dp)) .and. &
                       self%scene%weight > 0
   end function vertical_slack

   !> The first guess of a slack line between ends one above the other: the catenary to a
   !> point fold_offset L beside end b, sheared back onto end b (x - fold_offset L s / L): a
   !> narrow U that hangs below the lower end, down and up again, whose two strands the
   !> bending stiffness holds apart at the fold.
   subroutine folded_guess(self, pa, pb, ss, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      real(dp), intent(in) :: pa(2), pb(2), ss(:)
      type(error_type), allocatable, intent(out) :: err
      real(dp) :: n0(2), off
      off = fold_offset*self%scene%length
      if (size(self%scene%sections) > 1) then
         call catenary_between(self%scene%law, self%scene%weight, self%scene%length, pa, pb + [off, 0.0_dp], n0, err, &
                               scene_segments(self%scene))
      else
         call catenary_between(self%scene%law, self%scene%weight, self%scene%length, pa, pb + [off, 0.0_dp], n0, err)
      end if
      if (allocated(err)) then
         call prefix_error(err, self%scene%source//': statics: ')
         return
      end if
      call guess_from_force(self, n0, pa, ss, self%state%r)
      self%state%r(1, :) = self%state%r(1, :) - off*ss/ss(self%n)
   end subroutine folded_guess

   !> The catenary from the force n0 at s = 0 through r0 at the points ss, on a line of
   !> segments segment by segment (the first guess).
   subroutine guess_from_force(self, n0, r0, ss, r)
      !> The solve.
      type(statics_solve), intent(in) :: self
      real(dp), intent(in) :: n0(2), r0(2), ss(:)
      real(dp), intent(out) :: r(:, :)
      real(dp) :: eps(size(ss)), ten(size(ss))
      if (size(self%scene%sections) > 1) then
         call segments_from_force(scene_segments(self%scene), n0, r0, ss, r, eps, ten, guess_panels)
      else
         call catenary_from_force(self%scene%law, self%scene%weight, n0, r0, ss, r, eps, ten, guess_panels)
      end if
   end subroutine guess_from_force

   !> The catenary segments of a scene's sections (for the first guess).
   function scene_segments(scene) result(segments)
      type(scene_type), intent(in) :: scene
      type(catenary_segment), allocatable :: segments(:)
      integer :: j, k
      allocate (segments(size(scene%sections)))
      do j = 1, size(scene%sections)
         allocate (segments(j)%law, source=scene%sections(j)%law)
         segments(j)%weight = scene%sections(j)%weight
         segments(j)%length = scene%sections(j)%s_end - scene%sections(j)%s_start
      end do
      ! The bodies at the joints: the vertical force jumps by their weight.
      if (.not. allocated(scene%points)) return
      do k = 1, size(scene%points)
         do j = 1, size(scene%sections) - 1
            if (abs(scene%points(k)%s - scene%sections(j)%s_end) <= 1.0e-9_dp*scene%length) &
               segments(j)%end_weight = segments(j)%end_weight + scene%points(k)%net_weight()
         end do
      end do
   end function scene_segments

   !> The load of a state-dependent loaded end (a spring) for the catenary guess: the load
   !> (time-only force, state force at the catenary's end point, the point mass's weight)
   !> equal to the catenary's internal force there, by a damped Newton iteration on that
   !> force (central differences), from the catenary between the held end's point and the
   !> end's own position (a spring's anchor). The iteration's best load is kept; the
   !> statics' Newton iteration on the whole cable finishes from the guess.
   subroutine state_end_load(self, end, held_point, at_b, load)
      !> The solve.
      type(statics_solve), intent(in) :: self
      !> The state-dependent end.
      class(end_condition), intent(in) :: end
      !> The held end's point (x, z), m.
      real(dp), intent(in) :: held_point(2)
      !> Whether the end is end b (the held end is a), or end a.
      logical, intent(in) :: at_b
      !> In: the load without the state force (time-only force and weight); out: with it, N.
      real(dp), intent(inout) :: load(2)
      type(error_type), allocatable :: err
      real(dp) :: fixed_load(2), y(2), g(2), gp(2), gm(2), jac(2, 2), step(2), trial(2), gt(2), h, det, own(3), d(2)
      integer :: it, j, ls
      fixed_load = load
      own = end%position3(0.0_dp)
      d = [own(1), own(3)] - held_point
      ! The internal force at the end from the catenary between the two points.
      if (at_b) then
         call catenary_between(self%scene%law, self%scene%weight, self%scene%length, held_point, [own(1), own(3)], y, &
                               err)
         y = y + [0.0_dp, self%scene%weight*self%scene%length]
      else
         call catenary_between(self%scene%law, self%scene%weight, self%scene%length, [own(1), own(3)], held_point, y, &
                               err)
      end if
      if (allocated(err)) then
         ! (Ends one above the other: a straight line towards the end's point.)
         y = merge(1.0_dp, -1.0_dp, at_b)*(self%scene%weight*self%scene%length + 1)*d/max(norm2(d), tiny(1.0_dp))
      end if
      g = state_mismatch(self, end, held_point, at_b, fixed_load, y)
      do it = 1, 60
         if (norm2(g) <= 1.0e-10_dp*max(norm2(y), self%scene%weight*self%scene%length, 1.0_dp)) exit
         h = 1.0e-6_dp*max(norm2(y), self%scene%weight*self%scene%length, 1.0_dp)
         do j = 1, 2
            trial = y
            trial(j) = y(j) + h
            gp = state_mismatch(self, end, held_point, at_b, fixed_load, trial)
            trial(j) = y(j) - h
            gm = state_mismatch(self, end, held_point, at_b, fixed_load, trial)
            jac(:, j) = (gp - gm)/(2*h)
         end do
         det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
         if (.not. abs(det) > 0) exit
         step = [jac(2, 2)*g(1) - jac(1, 2)*g(2), -jac(2, 1)*g(1) + jac(1, 1)*g(2)]/det
         do ls = 1, 30
            trial = y - step
            gt = state_mismatch(self, end, held_point, at_b, fixed_load, trial)
            if (norm2(gt) < norm2(g)) exit
            step = 0.5_dp*step
         end do
         if (.not. norm2(gt) < norm2(g)) exit
         y = trial
         g = gt
      end do
      load = merge(y, -y, at_b)
   end subroutine state_end_load

   !> For state_end_load, an internal force yy at the end (N(L) at end b, N(0) at end a): the
   !> internal force minus the load at the catenary's end point (N(0) = -load at end a).
   function state_mismatch(self, end, held_point, at_b, fixed_load, yy) result(m)
      !> The solve.
      type(statics_solve), intent(in) :: self
      class(end_condition), intent(in) :: end
      real(dp), intent(in) :: held_point(2), fixed_load(2), yy(2)
      logical, intent(in) :: at_b
      real(dp) :: m(2), rr(2, self%n), ee(self%n), tt(self%n), p(2), f3(3), dx(3, 3), dv(3, 3), damp(3)
      if (at_b) then
         call catenary_from_force(self%scene%law, self%scene%weight, &
                                  yy - [0.0_dp, self%scene%weight*self%scene%length], held_point, ss_all(self), rr, &
                                  ee, tt, guess_panels)
         p = rr(:, self%n)
      else
         call catenary_from_force(self%scene%law, self%scene%weight, yy, [0.0_dp, 0.0_dp], ss_all(self), rr, ee, tt, &
                                  guess_panels)
         p = held_point - rr(:, self%n)
      end if
      call end%state_force(0.0_dp, [p(1), 0.0_dp, p(2)], [0.0_dp, 0.0_dp, 0.0_dp], f3, dx, dv, damp)
      if (at_b) then
         m = yy - (fixed_load + f3([1, 3]))
      else
         m = yy + (fixed_load + f3([1, 3]))
      end if
   end function state_mismatch

   !> The nodes' arc lengths from end a of the piece, m.
   function ss_all(self) result(ss)
      !> The solve.
      type(statics_solve), intent(in) :: self
      real(dp) :: ss(self%n)
      ss = self%piece%s - self%piece%s(1)
   end function ss_all

   !> Both ends held, distributed loads: the catenary between the ends under
   !> the weight plus the mean of the loads on the straight chord, taken as a
   !> uniform load (found = .false. when there is none or no such catenary).
   module subroutine loaded_guess(self, found)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      logical, intent(out) :: found
      type(error_type), allocatable :: err
      type(band_matrix) :: unused
      real(dp) :: pa(2), pb(2), g(2), q(2, 2), n0(2), res(2*self%n), ss(self%n), rr(2, self%n), eps(self%n), &
                  ten(self%n), x(2*self%n)
      integer :: k
      found = .false.
      if (.not. (self%piece%end_a%held() .and. self%piece%end_b%held())) return
      if (.not. allocated(self%piece%loads)) return
      if (size(self%piece%loads) == 0) return
      pa = self%piece%end_a%position(0.0_dp)
      pb = self%piece%end_b%position(0.0_dp)
      ss = self%piece%s - self%piece%s(1)
      do k = 1, self%n
         x(2*k - 1:2*k) = pa + (pb - pa)*ss(k)/ss(self%n)
      end do
      call unused%init(2*self%n, rod_kl, rod_ku)
      call self%problem%evaluate(x, res, unused, .false.)
      g = sum(self%piece%load_node, 2)/self%scene%length - [0.0_dp, self%scene%weight]
      if (.not. (norm2(g) > 0)) return
      ! The rotation q that turns g onto -e_z.
      q(1, :) = [-g(2), g(1)]/norm2(g)
      q(2, :) = -g/norm2(g)
      call catenary_between(self%scene%law, norm2(g), self%scene%length, [0.0_dp, 0.0_dp], matmul(q, pb - pa), n0, err)
      if (allocated(err)) return
      call catenary_from_force(self%scene%law, norm2(g), n0, [0.0_dp, 0.0_dp], ss, rr, eps, ten)
      do k = 1, self%n
         self%state%r(:, k) = pa + matmul(transpose(q), rr(:, k))
      end do
      found = .true.
   end subroutine loaded_guess

   !> A slack line between held ends one above the other hangs folded (vertical_slack): its
   !> fold is held open by the bending stiffness against a little compression. The note for the
   !> statics' error says so.
   module function folded_note(self) result(note)
      !> The solve.
      type(statics_solve), intent(in) :: self
      character(:), allocatable :: note
      real(dp) :: pa(2), pb(2)
      note = ''
      if (.not. (self%piece%end_a%held() .and. self%piece%end_b%held())) return
      pa = self%piece%end_a%position(0.0_dp)
      pb = self%piece%end_b%position(0.0_dp)
      if (.not. vertical_slack(self, pa, pb)) return
      note = '; the ends are one above the other, '//str(norm2(pb - pa))//' m apart, closer than the '// &
             'line''s length at zero tension ('//str(self%scene%length*(1 + self%scene%law%strain_at(0.0_dp)))// &
             ' m): the slack line hangs folded, down below the lower end and up again, its fold held open '// &
             'by the bending stiffness against a little compression, which a rope that cannot push '// &
             '(compression = ''none'') does not give: the statics find no state for it; give the ends a '// &
             'horizontal offset, or compression = ''law'''
   end function folded_note
end submodule xcable_model_rod_statics_guess
