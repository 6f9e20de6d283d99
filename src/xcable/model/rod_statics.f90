!> The static state of the whole cable in the rod discretisation: Newton's
!> method on the equilibrium of every node (model/rod.f90) from the
!> extensible catenary (theory/closed_forms.f90) as the first guess.
!>
!> - Both ends held: the catenary between the two points.
!> - One end held, the other loaded (free, force, point mass): the load fixes
!>   the internal force at the loaded end, and the catenary is integrated from
!>   the held end.
!> - The paper's symmetric case (end tension given): the span is adjusted by a
!>   secant iteration until the force the support exerts at end b has the
!>   magnitude T_s (the span of the exact catenary is the first guess).
!>
!> The static solve always iterates to a scaled update of 1e-10 (the time
!> steps use &numerics newton_tol). A solution that is folded (at some
!> interior node the two cells turn back on themselves, by more than pi/2)
!> counts as a failed solve: with distributed loads the continuation in
!> them is tried, and a folded state is never returned (issue 15).
!>
!> A line nearly slack on a seabed between held ends, when Newton fails, is paid in from a
!> taut state (pay_in: end b moved out, then back in steps) before the relaxation; a rope that
!> cannot push that would be slack on the bottom, and a free end hanging onto a flat,
!> frictionless bottom (refuse_slack_tail), have no single static state and are refused with why
!> (docs/theory/seabed.md).
!>
!> When all that fails (both ends held or one), the statics relaxes: a
!> sequence of anchored equilibria (anchored_problem), an overdamped path to
!> the state, then Newton with the fold check from there (docs/theory/numerics.md,
!> Statics when Newton fails). A state the direct path finds is unchanged.
module xcable_model_rod_statics
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_input, stat_numerics
   use xcable_core_strings, only: str
   use xcable_scene_scene, only: scene_type, section_cells, sections_on
   use xcable_loads_load, only: load_slot, loads_in_statics, any_static_form
   use xcable_model_rod, only: rod_problem, rod_piece, rod_section, rod_kl, rod_ku, collapsed_length
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_force, only: force_end
   use xcable_ends_end_condition, only: end_condition
   use xcable_solver_newton, only: newton_problem, newton_workspace, newton_options, newton_report, newton_solve
   use xcable_solver_banded, only: band_matrix
   use xcable_material_law, only: material_law, secant_stiffness
   use xcable_material_tension_only, only: tension_only_law, uncut_law
   use xcable_theory_closed_forms, only: catenary_from_force, catenary_between, catenary_summary, catenary_segment, &
                                         segments_from_force
   implicit none
   private
   public :: rod_static_state, solve_rod_statics, static_tolerance, sag_below_chord, piece_sections

   !> Scaled update at which the static solve stops.
   real(dp), parameter :: static_tolerance = 1.0e-10_dp
   !> Newton iterations the statics allows a solve with the seabed's static friction (from the state
   !> without it: the friction's fade near zero tension converges slowly on fine grids).
   integer, parameter :: static_friction_iterations = 100
   !> Smallest step of the continuation in the static friction (a share of it) when Newton fails to
   !> take it at once.
   real(dp), parameter :: static_friction_min_share = 1.0_dp/64
   !> Gauss-Legendre panels per cell of the catenary first guess (catenary_from_force; its
   !> exact reference takes 8): one panel of 8 points is exact to round-off on a cell, and
   !> the statics' Newton iteration takes the guess to the same state to round-off
   !> (docs/measurements/data/speed_rounds.md, "The statics' first guess").
   integer, parameter :: guess_panels = 1
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
   !> The sideways offset of the folded first guess of a slack line between ends one above the
   !> other (folded_guess), a share of the line's length.
   real(dp), parameter :: fold_offset = 0.1_dp

   !> The static equilibrium with every loaded node tied by a spring to an
   !> anchor point (the last accepted state of the relaxation): residual
   !> R(x) + k (x - anchor) on the rows of nodes that are not held. It is the
   !> equilibrium after one implicit step of the overdamped motion from the
   !> anchor; for conservative loads it minimises the energy plus k |x - anchor|^2 / 2.
   type, extends(newton_problem) :: anchored_problem
      !> The rod's static problem.
      type(rod_problem), pointer :: rod => null()
      !> Anchor points, 2 per node.
      real(dp), allocatable :: anchor(:)
      !> Spring stiffness in residual units per metre.
      real(dp) :: stiffness = 0
      !> First and last row that carries a spring.
      integer :: first = 1, last = 0
   contains
      procedure :: evaluate => anchored_evaluate
   end type anchored_problem

   !> A static solution.
   type :: rod_static_state
      !> Positions (2, n), m.
      real(dp), allocatable :: r(:, :)
      !> Resolved point of end b in the symmetric case (x, z), m.
      real(dp) :: end_b_point(2) = 0
      !> Force the supports exert at the two ends (held ends), N.
      real(dp) :: reaction_a(2) = 0, reaction_b(2) = 0
      !> Horizontal distance between the ends, and the sag below their chord (sag_below_chord), m.
      real(dp) :: span = 0, sag = 0
      !> Newton iterations (all solves) and secant iterations on the span.
      integer :: newton_iterations = 0, span_iterations = 0
   end type rod_static_state

contains

   !> Solve the statics of the scene on the grid s. problem%piece must be set
   !> up on s with the scene's ends (the symmetric case replaces end b).
   subroutine solve_rod_statics(scene, problem, options, state, error)
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> The piece (whole cable) as a Newton problem.
      type(rod_problem), intent(inout), target :: problem
      !> Newton controls (the iteration limit is used; the tolerance is static_tolerance).
      type(newton_options), intent(in) :: options
      !> The solution.
      type(rod_static_state), intent(out) :: state
      !> Error when no equilibrium is found.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: span0, span1, sag, angle, mid, r0, r1, span2
      integer :: it, n
      !> The piece's own laws while their compressive branch stands in (uncut_laws): 0 the
      !> piece's, 1.. its sections'.
      type(rod_section), allocatable :: own_laws(:)
      !> Whether a solve reached a state with a collapsed cell (refused by check_fold).
      logical :: saw_collapse
      !> Whether the pay-in found the line slack on the bottom (no single static state), and why:
      !> the error when the relaxation finds no equilibrium either.
      logical :: refused
      character(:), allocatable :: slack_why
      n = problem%piece%n
      saw_collapse = .false.
      refused = .false.
      allocate (state%r(2, n))
      problem%dt = 0
      problem%t0 = 0
      if (scene%from_tension) then
         call catenary_summary(scene%law, scene%weight, scene%length, scene%tension, span0, sag, angle, mid, error)
         if (allocated(error)) then
            call prefix_error(error, scene%source//': &static: ')
            return
         end if
         call set_end_b(span0)
         call first_guess(error)
         if (allocated(error)) return
         call solve_at_span(r0, error)
         if (allocated(error)) return
         if (abs(r0) > 1.0e-12_dp) then
            span1 = span0*(1 + 1.0e-7_dp)
            do it = 1, 30
               call stretch_to(span1)
               call solve_at_span(r1, error)
               if (allocated(error)) return
               state%span_iterations = it
               if (abs(r1) <= 1.0e-12_dp .or. r1 == r0) exit
               span2 = span1 - r1*(span1 - span0)/(r1 - r0)
               span0 = span1
               r0 = r1
               span1 = span2
               if (it == 30) then
                  call fatal_error(error, 'statics: the span for the end tension '//str(scene%tension)// &
                                   ' N was not found (relative mismatch '//str(r1)//')', stat_numerics)
                  return
               end if
            end do
         end if
      else
         call first_guess(error)
         if (allocated(error)) return
         call refuse_slack_tail(error)
         if (allocated(error)) return
         call solve_or_relax(error)
         ! No equilibrium, and the pay-in saw why (a rope slack on the bottom): that is the error.
         if (allocated(error) .and. refused) then
            error%message = slack_why
            return
         end if
         if (allocated(error)) then
            error%message = error%message//slack_on_floor_note()//folded_note()
            if (saw_collapse) error%message = error%message//'; on the way Newton reached an equilibrium with '// &
               'a collapsed cell (slack line heaped into a point), which the dynamics cannot start from: the '// &
               'line is slack somewhere; with compression = ''none'' nothing resists that, with ''law'' the '// &
               'rope pushes back'
            return
         end if
      end if
      ! Loads with a static form of their own (the seabed's static friction): from the state
      ! without it, Newton with it (the friction moves the grounded part by its stretch only).
      if (any_static_form(problem%piece%loads)) then
         call loads_in_statics(problem%piece%loads, .true., secant_stiffness(problem%piece%law), scene%weight)
         ! First with the law's compressive branch (uncut_law), then with the law itself.
         block
            logical :: was_cut
            call uncut_laws(was_cut)
            call solve_now(error, static_friction_iterations)
            if (allocated(error)) call friction_continuation(error)
            call own_laws_back()
            if (.not. allocated(error) .and. was_cut) call solve_now(error, static_friction_iterations)
         end block
         if (.not. allocated(error)) call finish()
         call loads_in_statics(problem%piece%loads, .false., 0.0_dp, 0.0_dp)
         if (allocated(error)) call prefix_error(error, 'with the static friction on the seabed: ')
         return
      end if
      call finish()

   contains

      !> The piece's laws (its sections' too) replaced by their compressive branch continued
      !> (uncut_law) until own_laws_back; cut: whether any was a law that cannot push.
      subroutine uncut_laws(cut)
         logical, intent(out) :: cut
         class(material_law), allocatable :: uncut
         logical :: was_cut
         integer :: j, m
         m = 0
         if (allocated(problem%piece%sections)) m = size(problem%piece%sections)
         allocate (own_laws(0:m))
         call uncut_law(problem%piece%law, uncut, cut)
         call move_alloc(problem%piece%law, own_laws(0)%law)
         call move_alloc(uncut, problem%piece%law)
         do j = 1, m
            call uncut_law(problem%piece%sections(j)%law, uncut, was_cut)
            cut = cut .or. was_cut
            call move_alloc(problem%piece%sections(j)%law, own_laws(j)%law)
            call move_alloc(uncut, problem%piece%sections(j)%law)
         end do
      end subroutine uncut_laws

      !> The piece's own laws back (after uncut_laws).
      subroutine own_laws_back()
         integer :: j
         deallocate (problem%piece%law)
         call move_alloc(own_laws(0)%law, problem%piece%law)
         do j = 1, size(own_laws) - 1
            deallocate (problem%piece%sections(j)%law)
            call move_alloc(own_laws(j)%law, problem%piece%sections(j)%law)
         end do
         deallocate (own_laws)
      end subroutine own_laws_back

      !> When Newton fails from the state without the static friction to the state with it: from
      !> the former again, the friction in steps of its share, each from the last state found, the
      !> step halved after a failure (from a half, down to static_friction_min_share) and doubled
      !> after a success.
      subroutine friction_continuation(err)
         type(error_type), allocatable, intent(inout) :: err
         real(dp), allocatable :: r_good(:, :)
         real(dp) :: done, step, try
         r_good = state%r
         deallocate (err)
         done = 0
         step = 0.5_dp
         do while (done < 1)
            try = min(1.0_dp, done + step)
            call loads_in_statics(problem%piece%loads, .true., secant_stiffness(problem%piece%law), scene%weight, try)
            call solve_now(err, static_friction_iterations)
            if (allocated(err)) then
               state%r = r_good
               step = step/2
               if (step < static_friction_min_share) then
                  err%message = err%message//' (the continuation in the friction reached '// &
                                str(nint(100*done))//' % of it)'
                  call loads_in_statics(problem%piece%loads, .true., secant_stiffness(problem%piece%law), &
                                        scene%weight)
                  return
               end if
               deallocate (err)
            else
               done = try
               r_good = state%r
               step = 2*step
            end if
         end do
      end subroutine friction_continuation

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
      subroutine pay_in(err)
         type(error_type), allocatable, intent(inout) :: err
         class(end_condition), allocatable :: own_b
         type(error_type), allocatable :: sub
         real(dp), allocatable :: r_good(:, :)
         real(dp) :: pa(2), pb(2), far, done, step, try, chord, ten(n - 1)
         integer :: k
         logical :: cut
         if (.not. (problem%piece%end_a%held() .and. problem%piece%end_b%held())) return
         if (len(slack_on_floor_note()) > 0) return
         pa = problem%piece%end_a%position(0.0_dp)
         pb = problem%piece%end_b%position(0.0_dp)
         if (floor_at(pa(1)) <= -huge(1.0_dp) .or. floor_at(pb(1)) <= -huge(1.0_dp)) return
         if (.not. abs(pb(1) - pa(1)) > 0) return
         call move_alloc(problem%piece%end_b, own_b)
         ! A rope that cannot push is paid in as one that can (uncut_laws: an iterate that squeezes
         ! a grounded cell meets no stiffness otherwise); where the line is taut the two agree.
         call uncut_laws(cut)
         ! The taut start: the first chord of payout_chord whose direct solve succeeds.
         far = 0
         do k = 1, size(payout_chord)
            chord = payout_chord(k)*scene%length
            if (abs(pb(2) - pa(2)) >= chord .or. hypot(pb(1) - pa(1), pb(2) - pa(2)) >= chord) cycle
            far = sign(sqrt(chord**2 - (pb(2) - pa(2))**2), pb(1) - pa(1)) - (pb(1) - pa(1))
            call move_b(pb + [far, 0.0_dp])
            call first_guess(sub)
            if (allocated(sub)) exit
            call solve_with_loads(sub)
            if (.not. allocated(sub)) exit
            deallocate (sub)
         end do
         if (far == 0 .or. allocated(sub)) then
            call own_laws_back()
            if (allocated(problem%piece%end_b)) deallocate (problem%piece%end_b)
            call move_alloc(own_b, problem%piece%end_b)
            err%message = err%message//'; paying the line in: no taut start found'
            return
         end if
         r_good = state%r
         done = 0
         step = 0.25_dp
         do while (done < 1)
            try = min(1.0_dp, done + step)
            call move_b(pb + [(1 - try)*far, 0.0_dp])
            call solve_now(sub)
            ! Newton may cycle where the nodes touch down one by one on a stiff bottom: on a small
            ! step, the overdamped path from the last state (relax).
            if (allocated(sub) .and. step <= payout_relax_share) then
               state%r = r_good
               call relax(sub)
            end if
            if (allocated(sub)) then
               state%r = r_good
               call move_b(pb + [(1 - done)*far, 0.0_dp])
               step = step/2
               if (step < payout_min_share) exit
               deallocate (sub)
            else
               done = try
               r_good = state%r
               step = 2*step
            end if
         end do
         ! Paid in, a rope that cannot push where the one that can pushes (a grounded part rising
         ! towards the touchdown, whose weight up the slope exceeds the tension there): it is
         ! slack there, heaped on the frictionless bottom in any shape.
         if (.not. allocated(sub) .and. cut) then
            do k = 1, n - 1
               ten(k) = problem%piece%cell_tension(k, norm2(state%r(:, k + 1) - state%r(:, k))/problem%piece%ds(k) - 1)
            end do
            k = minloc(ten, 1)
            if (ten(k) < 0) then
               call own_laws_back()
               deallocate (problem%piece%end_b)
               call move_alloc(own_b, problem%piece%end_b)
               refused = .true.
               slack_why = ('statics: the line lies on the seabed with too little tension to be '// &
                                'taut: with its law continued below zero strain it would push '// &
                                str(-ten(k))//' N at s = '//str(problem%piece%s(k) - problem%piece%s(1) + &
                                0.5_dp*problem%piece%ds(k))//' m (on a bottom that rises towards the '// &
                                'touchdown, where the grounded line''s weight up the slope exceeds the '// &
                                'tension), so a rope that cannot push (compression = ''none'') lies slack '// &
                                'there, heaped on the frictionless bottom in any shape, with no single static '// &
                                'state; move the ends apart, shorten the line, or give the law its compressive '// &
                                'branch (compression = ''law'')')
               return
            end if
         end if
         call own_laws_back()
         deallocate (problem%piece%end_b)
         call move_alloc(own_b, problem%piece%end_b)
         if (.not. allocated(sub)) call solve_now(sub)
         if (allocated(sub)) then
            err%message = err%message//'; paying the line in from '//str(abs(far))//' m further out: '// &
                          sub%message//' (with end b '//str(abs(1 - done)*abs(far))//' m from its place)'
            return
         end if
         deallocate (err)
      end subroutine pay_in

      !> One end held, the other loose (not state-dependent) and resting on a seabed under a pull
      !> along it, the direct solve failed: Newton from the line laid on the bottom. The horizontal
      !> tension H of the grounded part is the loose end's horizontal force (or, with none, its
      !> weight down the bottom's slope, w (L - drop) |slope|: a free end on a slope lies downhill);
      !> the guess is the catenary from the held end whose tangent is horizontal where it reaches
      !> the floor (suspended length sqrt(drop^2 + 2 drop H / w)), then straight along the floor,
      !> away from the held end in the direction of that pull. Solved with the laws' compressive
      !> branch first (uncut_laws), then with the laws themselves. err in: the direct path's
      !> error; out: unchanged (with why this failed) or none.
      subroutine lay_down(err)
         type(error_type), allocatable, intent(inout) :: err
         type(error_type), allocatable :: sub
         class(end_condition), allocatable :: own_loose
         real(dp) :: top(2), load(2), drop, hh, hh0, ls, slope, sgn, d, ss(n), rr(2, n), eps(n), ten(n), xs
         real(dp) :: done, step, try
         real(dp), allocatable :: r_good(:, :)
         logical :: held_a, cut
         integer :: k, j
         held_a = problem%piece%end_a%held()
         if (held_a .eqv. problem%piece%end_b%held()) return
         if (held_a) then
            if (problem%piece%end_b%state_dependent() .or. problem%piece%end_b%point_mass() /= 0) return
            load = problem%piece%end_b%applied_force(0.0_dp)
            top = problem%piece%end_a%position(0.0_dp)
         else
            if (problem%piece%end_a%state_dependent() .or. problem%piece%end_a%point_mass() /= 0) return
            load = problem%piece%end_a%applied_force(0.0_dp)
            top = problem%piece%end_b%position(0.0_dp)
         end if
         if (floor_at(top(1)) <= -huge(1.0_dp) .or. .not. scene%weight > 0) return
         drop = top(2) - floor_at(top(1))
         d = 0.5_dp*scene%length
         slope = (floor_at(top(1) + d) - floor_at(top(1) - d))/(2*d)
         if (load(1) /= 0) then
            hh = abs(load(1))
            sgn = sign(1.0_dp, load(1))
         else if (slope /= 0) then
            hh = scene%weight*max(scene%length - drop, 0.0_dp)*abs(slope)
            sgn = -sign(1.0_dp, slope)
         else
            return
         end if
         if (.not. (hh > 0 .and. drop > 0)) return
         ! The pull the line is laid with: its touchdown bend (radius H / w) over lay_pull_cells cells.
         hh0 = max(hh, lay_pull_cells*scene%weight*maxval(problem%piece%ds))
         ls = sqrt(drop**2 + 2*drop*hh0/scene%weight)
         if (ls >= scene%length) return
         ! The arc lengths from the held end.
         if (held_a) then
            ss = problem%piece%s - problem%piece%s(1)
         else
            ss = problem%piece%s(n) - problem%piece%s(n:1:-1)
         end if
         call catenary_from_force(scene%law, scene%weight, [sgn*hh0, -scene%weight*ls], top, ss, rr, eps, ten, &
                                  guess_panels)
         j = count(ss <= ls)
         xs = rr(1, j) + sgn*(ls - ss(j))
         do k = j + 1, n
            rr(1, k) = xs + sgn*(ss(k) - ls)
            rr(2, k) = floor_at(rr(1, k))
         end do
         if (held_a) then
            state%r = rr
         else
            state%r = rr(:, n:1:-1)
         end if
         ! The loose end pulled by hh0 - hh more along the bottom, then let go in shares of that.
         if (held_a) then
            call move_alloc(problem%piece%end_b, own_loose)
         else
            call move_alloc(problem%piece%end_a, own_loose)
         end if
         call uncut_laws(cut)
         call pull_loose(held_a, load + [sgn*(hh0 - hh), 0.0_dp])
         call solve_with_loads(sub)
         done = 0
         step = 0.25_dp
         if (.not. allocated(sub)) then
            r_good = state%r
            do while (done < 1)
               try = min(1.0_dp, done + step)
               call pull_loose(held_a, load + [(1 - try)*sgn*(hh0 - hh), 0.0_dp])
               call solve_now(sub)
               if (allocated(sub)) then
                  state%r = r_good
                  step = step/2
                  if (step < payout_min_share) exit
                  deallocate (sub)
               else
                  done = try
                  r_good = state%r
                  step = 2*step
               end if
            end do
         end if
         if (held_a) then
            deallocate (problem%piece%end_b)
            call move_alloc(own_loose, problem%piece%end_b)
         else
            deallocate (problem%piece%end_a)
            call move_alloc(own_loose, problem%piece%end_a)
         end if
         if (.not. allocated(sub)) call solve_now(sub)
         call own_laws_back()
         if (.not. allocated(sub) .and. cut) call solve_now(sub)
         if (allocated(sub)) then
            err%message = err%message//'; from the line laid on the bottom, pulled by '//str(hh0)// &
                          ' N and let go to '//str(nint(100*done))//' %: '//sub%message
            return
         end if
         deallocate (err)
      end subroutine lay_down

      !> The loose end (end b with end a held, or end a) a force end with the force f (lay_down).
      subroutine pull_loose(held_a, f)
         logical, intent(in) :: held_a
         real(dp), intent(in) :: f(2)
         type(force_end) :: pulled
         pulled%force0 = f
         if (held_a) then
            if (allocated(problem%piece%end_b)) deallocate (problem%piece%end_b)
            allocate (problem%piece%end_b, source=pulled)
            problem%piece%end_b%label = 'end_b'
         else
            if (allocated(problem%piece%end_a)) deallocate (problem%piece%end_a)
            allocate (problem%piece%end_a, source=pulled)
            problem%piece%end_a%label = 'end_a'
         end if
      end subroutine pull_loose

      !> End b replaced by a fixed end at the point p (pay_in).
      subroutine move_b(p)
         real(dp), intent(in) :: p(2)
         if (allocated(problem%piece%end_b)) deallocate (problem%piece%end_b)
         allocate (problem%piece%end_b, source=fixed_end(point=p))
         problem%piece%end_b%label = 'end_b'
      end subroutine move_b

      !> One end held, the other free of horizontal force (free, a point mass, a vertical force),
      !> over a flat, frictionless floor with no current: the horizontal force is zero all along
      !> the line, which hangs straight down from the held end, and a line longer than that drop
      !> lies on the bottom with no tension, in any shape (straight either way, heaped): there is
      !> no single static state (Newton meets the singular Jacobian of the slack part). Refused
      !> with why, from the first guess (state%r: the vertical catenary) when it reaches below the
      !> floor and the loads on it have no horizontal part.
      subroutine refuse_slack_tail(err)
         type(error_type), allocatable, intent(out) :: err
         type(band_matrix) :: unused
         real(dp) :: x(2*n), res(2*n), top(2), drop, load(2)
         logical :: held_a
         character(:), allocatable :: loose
         integer :: k
         held_a = problem%piece%end_a%held()
         if (held_a .eqv. problem%piece%end_b%held()) return
         if (any_static_form(problem%piece%loads)) return
         if (held_a) then
            if (problem%piece%end_b%state_dependent()) return
            load = problem%piece%end_b%applied_force(0.0_dp)
            top = problem%piece%end_a%position(0.0_dp)
            loose = 'end b'
         else
            if (problem%piece%end_a%state_dependent()) return
            load = problem%piece%end_a%applied_force(0.0_dp)
            top = problem%piece%end_b%position(0.0_dp)
            loose = 'end a'
         end if
         if (load(1) /= 0) return
         if (floor_at(top(1)) <= -huge(1.0_dp)) return
         ! The guess hangs straight down and reaches below the floor.
         if (maxval(abs(state%r(1, :) - top(1))) > 1.0e-9_dp*scene%length) return
         if (.not. any([(state%r(2, k) < floor_at(state%r(1, k)), k = 1, n)])) return
         ! No load along the floor on the guess (a slope, a current).
         x = reshape(state%r, [2*n])
         call unused%init(2*n, rod_kl, rod_ku)
         call problem%evaluate(x, res, unused, .false.)
         if (sum(abs(problem%piece%load_node(1, :))) > 1.0e-9_dp*sum(abs(problem%piece%load_node(2, :)))) return
         drop = top(2) - floor_at(top(1))
         call fatal_error(err, scene%source//': statics: '//loose//' is free of horizontal force and the line ('// &
                          str(scene%length)//' m) is longer than the drop from the held end to the seabed ('// &
                          str(drop)//' m), which is flat and frictionless (no current, no static_friction): '// &
                          'nothing pulls the line sideways, it hangs straight down and about '// &
                          str(scene%length - drop)//' m of it lies on the bottom with no tension, in any shape '// &
                          '(straight either way or heaped), so it has no single static state; hold '//loose// &
                          ' where it should lie on the bottom (kind = ''fixed'', its x and z on the bottom), '// &
                          'or shorten the line below the drop', stat_input)
      end subroutine refuse_slack_tail

      !> Replace end b by a fixed end at the height of end a, span to its right.
      subroutine set_end_b(span)
         real(dp), intent(in) :: span
         real(dp) :: pa(2)
         pa = problem%piece%end_a%position(0.0_dp)
         state%end_b_point = pa + [span, 0.0_dp]
         deallocate (problem%piece%end_b)
         allocate (problem%piece%end_b, source=fixed_end(point=state%end_b_point))
         problem%piece%end_b%label = 'end_b'
      end subroutine set_end_b

      !> Move end b to a new span, stretching the current solution horizontally.
      subroutine stretch_to(span)
         real(dp), intent(in) :: span
         real(dp) :: pa(2), old
         pa = problem%piece%end_a%position(0.0_dp)
         old = state%end_b_point(1) - pa(1)
         state%r(1, :) = pa(1) + (state%r(1, :) - pa(1))*span/old
         call set_end_b(span)
      end subroutine stretch_to

      !> Solve at the current span; mismatch = |reaction at b| / T_s - 1.
      subroutine solve_at_span(mismatch, err)
         real(dp), intent(out) :: mismatch
         type(error_type), allocatable, intent(out) :: err
         real(dp) :: f(2)
         call solve_now(err)
         if (allocated(err)) return
         f = problem%piece%reaction(n, reshape(state%r, [2*n]), 0.0_dp, 0.5_dp)
         mismatch = norm2(f)/scene%tension - 1
      end subroutine solve_at_span

      !> Newton from state%r; if that fails and the cable carries distributed loads
      !> (a current can push it far from the catenary guess), solve without them
      !> and raise them step by step, each solution the guess of the next.
      subroutine solve_with_loads(err)
         type(error_type), allocatable, intent(out) :: err
         real(dp), allocatable :: guess(:, :), last(:, :)
         real(dp) :: factor, step
         integer :: tries
         character(:), allocatable :: why
         if (.not. allocated(problem%piece%loads)) then
            call solve_now(err)
            return
         end if
         if (size(problem%piece%loads) == 0) then
            call solve_now(err)
            return
         end if
         why = ''
         guess = state%r
         call solve_now(err)
         if (.not. allocated(err)) return
         deallocate (err)
         state%r = guess
         problem%piece%load_factor = 0
         call solve_now(err)
         if (allocated(err)) then
            problem%piece%load_factor = 1
            return
         end if
         factor = 0
         step = 0.25_dp
         last = state%r
         do tries = 1, 200
            problem%piece%load_factor = min(1.0_dp, factor + step)
            call solve_now(err)
            if (allocated(err)) then
               why = err%message
               deallocate (err)
               state%r = last
               step = 0.5_dp*step
               if (step < 1.0e-4_dp) exit
               cycle
            end if
            factor = problem%piece%load_factor
            last = state%r
            if (factor >= 1) exit
            step = min(2*step, 1 - factor)
         end do
         problem%piece%load_factor = 1
         if (factor < 1) call fatal_error(err, 'statics: no equilibrium found under the distributed loads ('// &
                                         load_names(problem%piece%loads)//'): '// &
                                         'reached '//str(100*factor)//' % of them (the last step: '//why//')', &
                                         stat_numerics)
      end subroutine solve_with_loads

      !> The direct solve (with its continuation in the loads); only when that
      !> fails, the pay-in of a line nearly slack on a seabed (pay_in), then the
      !> relaxation under the full loads: with distributed loads
      !> first from the catenary under their mean on the straight chord (a
      !> strong current can bow the line to the other side of the chord than
      !> its weight, and the bending energy, unbounded as cells fold, keeps the
      !> line from turning through a fold to get there), then from the
      !> catenary under the weight.
      subroutine solve_or_relax(err)
         type(error_type), allocatable, intent(out) :: err
         type(error_type), allocatable :: err2
         real(dp), allocatable :: guess(:, :)
         logical :: loaded
         guess = state%r
         call solve_with_loads(err)
         if (.not. allocated(err)) return
         problem%piece%load_factor = 1
         ! A line nearly slack on a seabed: paid in from a taut state (or refused, with why).
         call pay_in(err)
         if (.not. allocated(err)) return
         state%r = guess
         ! A loose end resting on a seabed under a pull along it: from the line laid on the bottom.
         call lay_down(err)
         if (.not. allocated(err)) return
         state%r = guess
         call loaded_guess(loaded)
         if (loaded) then
            call relax_rope(err2)
            if (.not. allocated(err2)) then
               deallocate (err)
               return
            end if
            err%message = err%message//'; relaxation from the catenary under the mean load: '//err2%message
            deallocate (err2)
         end if
         state%r = guess
         call relax_rope(err2)
         if (.not. allocated(err2)) then
            deallocate (err)
            return
         end if
         err%message = err%message//'; relaxation: '//err2%message
      end subroutine solve_or_relax

      !> Relax from state%r. A rope that cannot push (compression = 'none') is
      !> first relaxed as one that can (its law continued below zero strain:
      !> without it a squeezed cell has no stiffness at all and can collapse on
      !> the way), and Newton for the rope itself starts from that state.
      subroutine relax_rope(err)
         type(error_type), allocatable, intent(out) :: err
         logical :: rope
         call uncut_laws(rope)
         call relax(err)
         call own_laws_back()
         if (.not. rope) return
         if (allocated(err)) return
         call solve_now(err)
         if (.not. allocated(err)) return
         deallocate (err)
         call relax(err)
      end subroutine relax_rope

      !> Both ends held, distributed loads: the catenary between the ends under
      !> the weight plus the mean of the loads on the straight chord, taken as a
      !> uniform load (found = .false. when there is none or no such catenary).
      subroutine loaded_guess(found)
         logical, intent(out) :: found
         type(error_type), allocatable :: err
         type(band_matrix) :: unused
         real(dp) :: pa(2), pb(2), g(2), q(2, 2), n0(2), res(2*n), ss(n), rr(2, n), eps(n), ten(n), x(2*n)
         integer :: k
         found = .false.
         if (.not. (problem%piece%end_a%held() .and. problem%piece%end_b%held())) return
         if (.not. allocated(problem%piece%loads)) return
         if (size(problem%piece%loads) == 0) return
         pa = problem%piece%end_a%position(0.0_dp)
         pb = problem%piece%end_b%position(0.0_dp)
         ss = problem%piece%s - problem%piece%s(1)
         do k = 1, n
            x(2*k - 1:2*k) = pa + (pb - pa)*ss(k)/ss(n)
         end do
         call unused%init(2*n, rod_kl, rod_ku)
         call problem%evaluate(x, res, unused, .false.)
         g = sum(problem%piece%load_node, 2)/scene%length - [0.0_dp, scene%weight]
         if (.not. (norm2(g) > 0)) return
         ! The rotation q that turns g onto -e_z.
         q(1, :) = [-g(2), g(1)]/norm2(g)
         q(2, :) = -g/norm2(g)
         call catenary_between(scene%law, norm2(g), scene%length, [0.0_dp, 0.0_dp], matmul(q, pb - pa), n0, err)
         if (allocated(err)) return
         call catenary_from_force(scene%law, norm2(g), n0, [0.0_dp, 0.0_dp], ss, rr, eps, ten)
         do k = 1, n
            state%r(:, k) = pa + matmul(transpose(q), rr(:, k))
         end do
         found = .true.
      end subroutine loaded_guess

      !> Pseudo-transient relaxation from state%r: a sequence of anchored
      !> equilibria (anchored_problem), each anchored at the last, the spring
      !> stiffened fourfold when its solve fails or moves a node by more than
      !> one cell length and softened fourfold when it succeeds, until Newton
      !> on the bare problem (solve_now, with its fold check) converges from
      !> the relaxed state. The path is that of an overdamped motion, so it
      !> does not jump, as an undamped Newton step can, past the equilibrium
      !> into a folded or far-off state.
      subroutine relax(err)
         type(error_type), allocatable, intent(out) :: err
         integer, parameter :: max_steps = 2000
         type(anchored_problem) :: anchored
         type(newton_workspace) :: work
         type(newton_options) :: opts
         type(newton_report) :: report
         type(error_type), allocatable :: sub
         real(dp), allocatable :: x(:), trial(:), res(:)
         real(dp) :: moved, polish_below, k0
         integer :: steps, accepted
         anchored%rod => problem
         anchored%first = 1
         anchored%last = 2*n
         if (problem%piece%end_a%held()) anchored%first = 3
         if (problem%piece%end_b%held()) anchored%last = 2*n - 2
         call work%init(2*n, rod_kl, rod_ku, spread(problem%piece%length_ref, 1, 2*n))
         opts = options
         opts%tolerance = 1.0e-8_dp
         opts%max_iterations = 12
         opts%reuse_jacobian = .false.
         opts%final_residual = .false.
         x = reshape(state%r, [2*n])
         allocate (res(2*n))
         call problem%evaluate(x, res, work%jacobian, .false.)
         ! The first spring moves the worst node by about one cell length.
         k0 = max(maxval(abs(res(anchored%first:anchored%last))), tiny(1.0_dp))/problem%piece%length_ref
         anchored%stiffness = k0
         polish_below = 1.0e-2_dp
         accepted = 0
         do steps = 1, max_steps
            anchored%anchor = x
            trial = x
            call newton_solve(anchored, trial, work, opts, report, sub)
            state%newton_iterations = state%newton_iterations + report%iterations
            moved = huge(1.0_dp)
            if (.not. allocated(sub)) moved = maxval(abs(trial - x))/problem%piece%length_ref
            if (allocated(sub)) deallocate (sub)
            if (.not. (moved <= 1)) then
               anchored%stiffness = 4*anchored%stiffness
               if (anchored%stiffness > 1.0e12_dp*k0) exit
               cycle
            end if
            x = trial
            accepted = accepted + 1
            anchored%stiffness = 0.25_dp*anchored%stiffness
            if (moved < polish_below) then
               state%r = reshape(x, [2, n])
               call solve_now(sub)
               if (.not. allocated(sub)) return
               deallocate (sub)
               polish_below = 0.1_dp*polish_below
            end if
         end do
         call fatal_error(err, 'no equilibrium reached ('//str(accepted)//' of '//str(steps - 1)// &
                          ' relaxation steps accepted, spring '//str(anchored%stiffness/k0)//' of the first)', &
                          stat_numerics)
      end subroutine relax

      !> Newton from state%r.
      subroutine solve_now(err, max_iterations)
         type(error_type), allocatable, intent(out) :: err
         !> Iteration limit (default: the case's).
         integer, intent(in), optional :: max_iterations
         type(newton_workspace) :: work
         type(newton_options) :: opts
         type(newton_report) :: report
         real(dp), allocatable :: x(:)
         opts = options
         opts%tolerance = static_tolerance
         opts%reuse_jacobian = .false.
         if (present(max_iterations)) opts%max_iterations = max_iterations
         call work%init(2*n, rod_kl, rod_ku, spread(problem%piece%length_ref, 1, 2*n))
         x = reshape(state%r, [2*n])
         call newton_solve(problem, x, work, opts, report, err)
         state%newton_iterations = state%newton_iterations + report%iterations
         if (allocated(err)) then
            call prefix_error(err, 'statics: ')
            return
         end if
         call check_fold(reshape(x, [2, n]), err)
         if (allocated(err)) return
         state%r = reshape(x, [2, n])
      end subroutine solve_now

      !> A solution is refused when it is folded: at some interior node the two
      !> cells turn back on themselves (turning angle above pi/2), when under the full loads a
      !> node lies deeper in a floor (a seabed) than a cell length, or when a cell has
      !> collapsed (shorter than collapsed_length of its unstretched length, as the step
      !> control refuses it). Such a state is
      !> an equilibrium of compressed, zigzagging cells (compression = 'law') or a
      !> bend sharper than the grid resolves, not the static state sought.
      subroutine check_fold(r, err)
         real(dp), intent(in) :: r(:, :)
         type(error_type), allocatable, intent(out) :: err
         real(dp), parameter :: fold_angle = 0.5_dp*acos(-1.0_dp)
         real(dp) :: a(2), b(2), th, worst
         integer :: k, at
         worst = 0
         at = 0
         do k = 2, size(r, 2) - 1
            a = r(:, k) - r(:, k - 1)
            b = r(:, k + 1) - r(:, k)
            th = abs(atan2(a(1)*b(2) - a(2)*b(1), dot_product(a, b)))
            if (.not. (th <= worst)) then
               worst = th
               at = k
            end if
         end do
         if (.not. (worst <= fold_angle)) call fatal_error(err, 'statics: a folded state (the cells at node '// &
                                                           str(at)//' turn back on themselves, by '//str(worst)// &
                                                           ' rad, more than pi/2)', stat_numerics)
         if (allocated(err)) return
         ! Under the full loads, a node pushed into a floor (a seabed) by more than a cell: a line
         ! standing on the bottom as a column (a rope that can push, hanging straight down onto
         ! it), not the state sought.
         if (problem%piece%load_factor >= 1) then
            do k = 1, size(r, 2)
               if (floor_at(r(1, k)) - r(2, k) > problem%piece%ds(min(k, size(r, 2) - 1))) then
                  call fatal_error(err, 'statics: a state with node '//str(k)//' '// &
                                   str(floor_at(r(1, k)) - r(2, k))//' m into the seabed (more than a cell)', &
                                   stat_numerics)
                  return
               end if
            end do
         end if
         ! A collapsed cell (a slack rope heaped into one point): the dynamics would refuse it.
         do k = 1, size(r, 2) - 1
            if (norm2(r(:, k + 1) - r(:, k)) < collapsed_length*problem%piece%ds(k)) then
               saw_collapse = .true.
               call fatal_error(err, 'statics: a collapsed state (cell '//str(k)//' squeezed to '// &
                                str(100*norm2(r(:, k + 1) - r(:, k))/problem%piece%ds(k))// &
                                ' % of its length: slack line heaped into a point)', stat_numerics)
               return
            end if
         end do
      end subroutine check_fold

      !> The catenary guess.
      subroutine first_guess(err)
         type(error_type), allocatable, intent(out) :: err
         real(dp) :: n0(2), pa(2), pb(2), load(2), ss(n)
         real(dp), allocatable :: eps(:), ten(:), rr(:, :)
         logical :: held_a, held_b, segmented
         segmented = size(scene%sections) > 1
         allocate (eps(n), ten(n), rr(2, n))
         held_a = problem%piece%end_a%held()
         held_b = problem%piece%end_b%held()
         ss = problem%piece%s - problem%piece%s(1)
         if (held_a .and. held_b) then
            pa = problem%piece%end_a%position(0.0_dp)
            pb = problem%piece%end_b%position(0.0_dp)
            if (vertical_slack(pa, pb)) then
               call folded_guess(pa, pb, ss, err)
               return
            end if
            if (segmented) then
               call catenary_between(scene%law, scene%weight, scene%length, pa, pb, n0, err, scene_segments(scene))
            else
               call catenary_between(scene%law, scene%weight, scene%length, pa, pb, n0, err)
            end if
            if (allocated(err)) then
               call prefix_error(err, scene%source//': statics: ')
               return
            end if
            call guess_from_force(n0, pa, ss, state%r)
         else if (held_a) then
            ! The internal force at s = L is the load of end b (its force and the point mass's weight).
            load = problem%piece%end_b%applied_force(0.0_dp) - [0.0_dp, scene%gravity*problem%piece%end_b%point_mass() + &
                                                                     body_weight(scene%length)]
            ! An end on a spring: the load where the spring balances the catenary.
            if (problem%piece%end_b%state_dependent()) &
               call state_end_load(problem%piece%end_b, problem%piece%end_a%position(0.0_dp), .true., load)
            n0 = load - [0.0_dp, scene%weight*scene%length + body_weight(-1.0_dp)]
            pa = problem%piece%end_a%position(0.0_dp)
            call guess_from_force(n0, pa, ss, state%r)
         else if (held_b) then
            ! The internal force at s = 0 balances the load of end a.
            load = problem%piece%end_a%applied_force(0.0_dp) - [0.0_dp, scene%gravity*problem%piece%end_a%point_mass() + &
                                                                     body_weight(0.0_dp)]
            if (problem%piece%end_a%state_dependent()) &
               call state_end_load(problem%piece%end_a, problem%piece%end_b%position(0.0_dp), .false., load)
            n0 = -load
            pb = problem%piece%end_b%position(0.0_dp)
            call guess_from_force(n0, [0.0_dp, 0.0_dp], ss, rr)
            state%r(1, :) = rr(1, :) - rr(1, n) + pb(1)
            state%r(2, :) = rr(2, :) - rr(2, n) + pb(2)
         else
            call fatal_error(err, scene%source//': statics: neither end is held (fixed or moving): the cable has '// &
                             'no static position', stat_input)
         end if
      end subroutine first_guess

      !> The net weight of the bodies (scene%points) at arc length s (N), or with s < 0 of those
      !> inside the line (not at its ends).
      real(dp) function body_weight(s) result(w)
         real(dp), intent(in) :: s
         integer :: k
         w = 0
         if (.not. allocated(scene%points)) return
         do k = 1, size(scene%points)
            associate (p => scene%points(k))
               if (s >= 0) then
                  if (abs(p%s - s) <= 1.0e-9_dp*scene%length) w = w + p%net_weight()
               else if (p%s > 1.0e-9_dp*scene%length .and. p%s < (1 - 1.0e-9_dp)*scene%length) then
                  w = w + p%net_weight()
               end if
            end associate
         end do
      end function body_weight
      !> Whether both held ends are one above the other (their horizontal distance below 1e-9 of
      !> the line's length) and the line is slack (their distance shorter than its length at zero
      !> tension): it hangs folded.
      logical function vertical_slack(pa, pb)
         real(dp), intent(in) :: pa(2), pb(2)
         vertical_slack = abs(pb(1) - pa(1)) < 1.0e-9_dp*max(scene%length, 1.0_dp) .and. &
                          norm2(pb - pa) < scene%length*(1 + scene%law%strain_at(0.0_dp)) .and. scene%weight > 0
      end function vertical_slack

      !> The first guess of a slack line between ends one above the other: the catenary to a
      !> point fold_offset L beside end b, sheared back onto end b (x - fold_offset L s / L): a
      !> narrow U that hangs below the lower end, down and up again, whose two strands the
      !> bending stiffness holds apart at the fold.
      subroutine folded_guess(pa, pb, ss, err)
         real(dp), intent(in) :: pa(2), pb(2), ss(:)
         type(error_type), allocatable, intent(out) :: err
         real(dp) :: n0(2), off
         off = fold_offset*scene%length
         if (size(scene%sections) > 1) then
            call catenary_between(scene%law, scene%weight, scene%length, pa, pb + [off, 0.0_dp], n0, err, &
                                  scene_segments(scene))
         else
            call catenary_between(scene%law, scene%weight, scene%length, pa, pb + [off, 0.0_dp], n0, err)
         end if
         if (allocated(err)) then
            call prefix_error(err, scene%source//': statics: ')
            return
         end if
         call guess_from_force(n0, pa, ss, state%r)
         state%r(1, :) = state%r(1, :) - off*ss/ss(n)
      end subroutine folded_guess

      !> The catenary from the force n0 at s = 0 through r0 at the points ss, on a line of
      !> segments segment by segment (the first guess).
      subroutine guess_from_force(n0, r0, ss, r)
         real(dp), intent(in) :: n0(2), r0(2), ss(:)
         real(dp), intent(out) :: r(:, :)
         real(dp) :: eps(size(ss)), ten(size(ss))
         if (size(scene%sections) > 1) then
            call segments_from_force(scene_segments(scene), n0, r0, ss, r, eps, ten, guess_panels)
         else
            call catenary_from_force(scene%law, scene%weight, n0, r0, ss, r, eps, ten, guess_panels)
         end if
      end subroutine guess_from_force

      !> Height of the highest floor of the loads (a seabed's bottom) under the horizontal point
      !> x, m (-huge: none).
      real(dp) function floor_at(x) result(z)
         real(dp), intent(in) :: x
         integer :: k
         z = -huge(1.0_dp)
         if (.not. allocated(problem%piece%loads)) return
         do k = 1, size(problem%piece%loads)
            z = max(z, problem%piece%loads(k)%load%floor([x]))
         end do
      end function floor_at

      !> Both ends held over a floor (a seabed) and a line at least as long as the way from
      !> one end straight down to the floor, along it, and straight up to the other end: there
      !> is no taut static state, the excess lies slack on a frictionless floor (any heap of it
      !> is an equilibrium), and Newton finds none. The note for the statics' error says so.
      function slack_on_floor_note() result(note)
         character(:), allocatable :: note
         real(dp) :: pa(2), pb(2), fa, fb, way
         note = ''
         if (.not. (problem%piece%end_a%held() .and. problem%piece%end_b%held())) return
         pa = problem%piece%end_a%position(0.0_dp)
         pb = problem%piece%end_b%position(0.0_dp)
         fa = floor_at(pa(1))
         fb = floor_at(pb(1))
         if (fa <= -huge(1.0_dp) .or. fb <= -huge(1.0_dp)) return
         way = (pa(2) - fa) + hypot(pb(1) - pa(1), fb - fa) + (pb(2) - fb)
         if (scene%length >= way) note = '; the line ('//str(scene%length)//' m) is at least as long as the '// &
            'way down from end a to the seabed, along it and up to end b ('//str(way)//' m): it cannot be taut, '// &
            'and a slack line on a frictionless seabed has no single static state; move the ends apart or '// &
            'shorten the line'
      end function slack_on_floor_note

      !> A slack line between held ends one above the other hangs folded (vertical_slack): its
      !> fold is held open by the bending stiffness against a little compression. The note for the
      !> statics' error says so.
      function folded_note() result(note)
         character(:), allocatable :: note
         real(dp) :: pa(2), pb(2)
         note = ''
         if (.not. (problem%piece%end_a%held() .and. problem%piece%end_b%held())) return
         pa = problem%piece%end_a%position(0.0_dp)
         pb = problem%piece%end_b%position(0.0_dp)
         if (.not. vertical_slack(pa, pb)) return
         note = '; the ends are one above the other, '//str(norm2(pb - pa))//' m apart, closer than the '// &
                'line''s length at zero tension ('//str(scene%length*(1 + scene%law%strain_at(0.0_dp)))// &
                ' m): the slack line hangs folded, down below the lower end and up again, its fold held open '// &
                'by the bending stiffness against a little compression, which a rope that cannot push '// &
                '(compression = ''none'') does not give: the statics find no state for it; give the ends a '// &
                'horizontal offset, or compression = ''law'''
      end function folded_note

      !> The load of a state-dependent loaded end (a spring) for the catenary guess: the load
      !> (time-only force, state force at the catenary's end point, the point mass's weight)
      !> equal to the catenary's internal force there, by a damped Newton iteration on that
      !> force (central differences), from the catenary between the held end's point and the
      !> end's own position (a spring's anchor). The iteration's best load is kept; the
      !> statics' Newton iteration on the whole cable finishes from the guess.
      subroutine state_end_load(end, held_point, at_b, load)
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
            call catenary_between(scene%law, scene%weight, scene%length, held_point, [own(1), own(3)], y, err)
            y = y + [0.0_dp, scene%weight*scene%length]
         else
            call catenary_between(scene%law, scene%weight, scene%length, [own(1), own(3)], held_point, y, err)
         end if
         if (allocated(err)) then
            ! (Ends one above the other: a straight line towards the end's point.)
            y = merge(1.0_dp, -1.0_dp, at_b)*(scene%weight*scene%length + 1)*d/max(norm2(d), tiny(1.0_dp))
         end if
         g = state_mismatch(end, held_point, at_b, fixed_load, y)
         do it = 1, 60
            if (norm2(g) <= 1.0e-10_dp*max(norm2(y), scene%weight*scene%length, 1.0_dp)) exit
            h = 1.0e-6_dp*max(norm2(y), scene%weight*scene%length, 1.0_dp)
            do j = 1, 2
               trial = y
               trial(j) = y(j) + h
               gp = state_mismatch(end, held_point, at_b, fixed_load, trial)
               trial(j) = y(j) - h
               gm = state_mismatch(end, held_point, at_b, fixed_load, trial)
               jac(:, j) = (gp - gm)/(2*h)
            end do
            det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
            if (.not. abs(det) > 0) exit
            step = [jac(2, 2)*g(1) - jac(1, 2)*g(2), -jac(2, 1)*g(1) + jac(1, 1)*g(2)]/det
            do ls = 1, 30
               trial = y - step
               gt = state_mismatch(end, held_point, at_b, fixed_load, trial)
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
      function state_mismatch(end, held_point, at_b, fixed_load, yy) result(m)
         class(end_condition), intent(in) :: end
         real(dp), intent(in) :: held_point(2), fixed_load(2), yy(2)
         logical, intent(in) :: at_b
         real(dp) :: m(2), rr(2, n), ee(n), tt(n), p(2), f3(3), dx(3, 3), dv(3, 3), damp(3)
         if (at_b) then
            call catenary_from_force(scene%law, scene%weight, yy - [0.0_dp, scene%weight*scene%length], &
                                     held_point, ss_all(), rr, ee, tt, guess_panels)
            p = rr(:, n)
         else
            call catenary_from_force(scene%law, scene%weight, yy, [0.0_dp, 0.0_dp], ss_all(), rr, ee, tt, &
                                     guess_panels)
            p = held_point - rr(:, n)
         end if
         call end%state_force(0.0_dp, [p(1), 0.0_dp, p(2)], [0.0_dp, 0.0_dp, 0.0_dp], f3, dx, dv, damp)
         if (at_b) then
            m = yy - (fixed_load + f3([1, 3]))
         else
            m = yy + (fixed_load + f3([1, 3]))
         end if
      end function state_mismatch

      !> The nodes' arc lengths from end a of the piece, m.
      function ss_all() result(ss)
         real(dp) :: ss(n)
         ss = problem%piece%s - problem%piece%s(1)
      end function ss_all

      !> Span, sag and the reactions of the solution.
      subroutine finish()
         real(dp) :: x(2*n), res(2*n)
         type(band_matrix) :: unused
         x = reshape(state%r, [2*n])
         ! One evaluation at the solution sets the cell forces the reactions use.
         call problem%evaluate(x, res, unused, .false.)
         state%reaction_a = problem%piece%reaction(1, x, 0.0_dp, 0.5_dp)
         state%reaction_b = problem%piece%reaction(n, x, 0.0_dp, 0.5_dp)
         state%span = abs(state%r(1, n) - state%r(1, 1))
         state%sag = sag_below_chord(state%r)
      end subroutine finish
   end subroutine solve_rod_statics

   !> Residual and Jacobian of the anchored equilibrium.
   subroutine anchored_evaluate(self, x, residual, jacobian, with_jacobian)
      !> The problem.
      class(anchored_problem), intent(inout) :: self
      !> Positions, 2 per node.
      real(dp), intent(in) :: x(:)
      !> Residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian (band storage).
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form the Jacobian.
      logical, intent(in) :: with_jacobian
      integer :: i, band0
      call self%rod%evaluate(x, residual, jacobian, with_jacobian)
      do i = self%first, self%last
         residual(i) = residual(i) + self%stiffness*(x(i) - self%anchor(i))
      end do
      if (.not. with_jacobian) return
      band0 = jacobian%kl + jacobian%ku + 1
      do i = self%first, self%last
         jacobian%ab(band0, i) = jacobian%ab(band0, i) + self%stiffness
      end do
   end subroutine anchored_evaluate
   !> Sag: the largest vertical distance of the line below the chord joining its
   !> ends (for ends one above the other, the largest horizontal distance from it).
   pure real(dp) function sag_below_chord(r)
      !> Positions (2, n), m.
      real(dp), intent(in) :: r(:, :)
      real(dp) :: d(2), zc
      integer :: k, n
      n = size(r, 2)
      d = r(:, n) - r(:, 1)
      sag_below_chord = 0
      do k = 1, n
         if (abs(d(1)) > 1.0e-9_dp*max(norm2(d), 1.0_dp)) then
            zc = r(2, 1) + d(2)*(r(1, k) - r(1, 1))/d(1)
            sag_below_chord = max(sag_below_chord, zc - r(2, k))
         else
            sag_below_chord = max(sag_below_chord, abs(r(1, k) - r(1, 1)))
         end if
      end do
   end function sag_below_chord

   !> The loads' names, comma-separated.
   function load_names(loads) result(text)
      type(load_slot), intent(in) :: loads(:)
      character(:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, size(loads)
         ! (A load on several segments once.)
         if (index(', '//text//', ', ', '//loads(i)%load%name()//', ') > 0) cycle
         if (len(text) > 0) text = text//', '
         text = text//loads(i)%load%name()
      end do
   end function load_names

   !> A planar piece on a line of segments: its sections from the scene's (rod_piece
   !> set_sections), those with cells on the piece (its nodes' arc lengths s). Nothing for a
   !> scene of one segment.
   subroutine piece_sections(piece, scene)
      !> Piece, initialised on its part of the line.
      type(rod_piece), intent(inout) :: piece
      !> Scene.
      type(scene_type), intent(in) :: scene
      integer, allocatable :: last(:), keep(:)
      type(rod_section), allocatable :: laws(:)
      integer :: j
      if (size(scene%sections) <= 1) then
         ! A uniform line may carry a body at an end.
         if (allocated(scene%points)) call piece%set_points(scene%points)
         return
      end if
      last = section_cells(scene, piece%s)
      keep = sections_on(scene, piece%s)
      allocate (laws(size(keep)))
      do j = 1, size(keep)
         allocate (laws(j)%law, source=scene%sections(keep(j))%law)
      end do
      call piece%set_sections(last(keep), laws, scene%sections(keep)%mass, scene%sections(keep)%weight, &
                              scene%sections(keep)%ei, scene%sections(keep)%damping)
      if (allocated(scene%points)) call piece%set_points(scene%points)
   end subroutine piece_sections

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
end module xcable_model_rod_statics
