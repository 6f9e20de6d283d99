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
!>
!> One solve's shared state is a statics_solve, which its strategies take. This file holds the
!> driver (solve_rod_statics: the symmetric case's span iteration, the order of the strategies,
!> the static friction, the span, sag and reactions of the solution). The strategies are in the
!> submodules model/rod_statics/: guess.f90 (the first guesses), newton.f90 (Newton from the
!> current state with its fold check, the laws' compressive branch standing in, the continuation
!> in the loads, the relaxation) and seabed.f90 (a line on a seabed: the pay-in, the laying
!> down, the refusals, the continuation in the static friction).
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
   !> Gauss-Legendre panels per cell of the catenary first guess (catenary_from_force; its
   !> exact reference takes 8): one panel of 8 points is exact to round-off on a cell, and
   !> the statics' Newton iteration takes the guess to the same state to round-off
   !> (docs/measurements/data/speed_rounds.md, "The statics' first guess").
   integer, parameter :: guess_panels = 1

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

   !> One static solve (solve_rod_statics) as its strategies share it: what it solves (the scene,
   !> the problem, the Newton controls), the solution it builds, and what the strategies leave
   !> for one another on the way. The pointers point at solve_rod_statics' arguments during
   !> the call.
   type :: statics_solve
      !> The scene.
      type(scene_type), pointer :: scene => null()
      !> The piece (whole cable) as a Newton problem, and its piece (problem%piece).
      type(rod_problem), pointer :: problem => null()
      type(rod_piece), pointer :: piece => null()
      !> Newton controls (the iteration limit is used; the tolerance is static_tolerance).
      type(newton_options) :: options
      !> The solution: state%r is the current state, from which every solve starts.
      type(rod_static_state), pointer :: state => null()
      !> Nodes of the piece.
      integer :: n = 0
      !> The piece's own laws while their compressive branch stands in (uncut_laws): 0 the
      !> piece's, 1.. its sections'.
      type(rod_section), allocatable :: own_laws(:)
      !> Whether a solve reached a state with a collapsed cell (refused by check_fold).
      logical :: saw_collapse = .false.
      !> Whether the pay-in found the line slack on the bottom (no single static state), and why:
      !> the error when the relaxation finds no equilibrium either.
      logical :: refused = .false.
      character(:), allocatable :: slack_why
   end type statics_solve

   ! The first guesses: in the submodule model/rod_statics/guess.f90.
   interface
      !> The catenary guess (state%r).
      module subroutine first_guess(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: err
      end subroutine first_guess

      !> Both ends held, distributed loads: the catenary under the weight plus the loads' mean on
      !> the straight chord (state%r; found = .false. when there is none or no such catenary).
      module subroutine loaded_guess(self, found)
         type(statics_solve), intent(inout) :: self
         logical, intent(out) :: found
      end subroutine loaded_guess

      !> The note for the statics' error on a slack line between held ends one above the other.
      module function folded_note(self) result(note)
         type(statics_solve), intent(in) :: self
         character(:), allocatable :: note
      end function folded_note
   end interface

   ! A line on a seabed: in the submodule model/rod_statics/seabed.f90.
   interface
      !> The continuation in the static friction when Newton fails to take it at once.
      module subroutine friction_continuation(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(inout) :: err
      end subroutine friction_continuation

      !> A line nearly slack on a seabed between held ends paid in from a taut state (or refused).
      module subroutine pay_in(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(inout) :: err
      end subroutine pay_in

      !> A loose end resting on a seabed under a pull along it: Newton from the line laid on it.
      module subroutine lay_down(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(inout) :: err
      end subroutine lay_down

      !> A free end hanging onto a flat, frictionless floor (no single static state) refused.
      module subroutine refuse_slack_tail(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: err
      end subroutine refuse_slack_tail

      !> Height of the highest floor of the loads under the horizontal point x, m (-huge: none).
      real(dp) module function floor_at(self, x) result(z)
         type(statics_solve), intent(in) :: self
         real(dp), intent(in) :: x
      end function floor_at

      !> The note for the statics' error on a line too long to be taut over a seabed.
      module function slack_on_floor_note(self) result(note)
         type(statics_solve), intent(in) :: self
         character(:), allocatable :: note
      end function slack_on_floor_note
   end interface

   ! Newton, the laws' compressive branch standing in, and the paths when Newton fails from the
   ! guess: in the submodule model/rod_statics/newton.f90. (What the submodules call is in the
   ! submodules: gfortran 12 makes the module's own procedures local symbols, and stops with an
   ! internal error on a submodule's call of one with an allocatable intent(out) argument.)
   interface
      !> The piece's laws (its sections' too) replaced by their compressive branch continued
      !> (uncut_law) until own_laws_back; cut: whether any was a law that cannot push.
      module subroutine uncut_laws(self, cut)
         type(statics_solve), intent(inout) :: self
         logical, intent(out) :: cut
      end subroutine uncut_laws

      !> The piece's own laws back (after uncut_laws).
      module subroutine own_laws_back(self)
         type(statics_solve), intent(inout) :: self
      end subroutine own_laws_back

      !> Newton from state%r (the iteration limit: max_iterations, default the case's), the state
      !> refused when folded (check_fold).
      module subroutine solve_now(self, err, max_iterations)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: err
         integer, intent(in), optional :: max_iterations
      end subroutine solve_now

      !> Newton from state%r, else the continuation in the distributed loads.
      module subroutine solve_with_loads(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: err
      end subroutine solve_with_loads

      !> The relaxation from state%r, a rope that cannot push first as one that can.
      module subroutine relax_rope(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: err
      end subroutine relax_rope

      !> The relaxation from state%r: anchored equilibria, then Newton (solve_now).
      module subroutine relax(self, err)
         type(statics_solve), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: err
      end subroutine relax
   end interface

contains

   !> Solve the statics of the scene on the grid s. problem%piece must be set
   !> up on s with the scene's ends (the symmetric case replaces end b).
   subroutine solve_rod_statics(scene, problem, options, state, error)
      !> Scene.
      type(scene_type), intent(in), target :: scene
      !> The piece (whole cable) as a Newton problem.
      type(rod_problem), intent(inout), target :: problem
      !> Newton controls (the iteration limit is used; the tolerance is static_tolerance).
      type(newton_options), intent(in) :: options
      !> The solution.
      type(rod_static_state), intent(out), target :: state
      !> Error when no equilibrium is found.
      type(error_type), allocatable, intent(out) :: error
      type(statics_solve) :: self
      real(dp) :: span0, span1, sag, angle, mid, r0, r1, span2
      integer :: it
      self%scene => scene
      self%problem => problem
      self%piece => problem%piece
      self%options = options
      self%state => state
      self%n = problem%piece%n
      allocate (state%r(2, self%n))
      problem%dt = 0
      problem%t0 = 0
      if (scene%from_tension) then
         call catenary_summary(scene%law, scene%weight, scene%length, scene%tension, span0, sag, angle, mid, error)
         if (allocated(error)) then
            call prefix_error(error, scene%source//': &static: ')
            return
         end if
         call set_end_b(self, span0)
         call first_guess(self, error)
         if (allocated(error)) return
         call solve_at_span(self, r0, error)
         if (allocated(error)) return
         if (abs(r0) > 1.0e-12_dp) then
            span1 = span0*(1 + 1.0e-7_dp)
            do it = 1, 30
               call stretch_to(self, span1)
               call solve_at_span(self, r1, error)
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
         call first_guess(self, error)
         if (allocated(error)) return
         call refuse_slack_tail(self, error)
         if (allocated(error)) return
         call solve_or_relax(self, error)
         ! No equilibrium, and the pay-in saw why (a rope slack on the bottom): that is the error.
         if (allocated(error) .and. self%refused) then
            error%message = self%slack_why
            return
         end if
         if (allocated(error)) then
            error%message = error%message//slack_on_floor_note(self)//folded_note(self)
            if (self%saw_collapse) error%message = error%message//'; on the way Newton reached an equilibrium with '// &
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
            call uncut_laws(self, was_cut)
            call solve_now(self, error, static_friction_iterations)
            if (allocated(error)) call friction_continuation(self, error)
            call own_laws_back(self)
            if (.not. allocated(error) .and. was_cut) call solve_now(self, error, static_friction_iterations)
         end block
         if (.not. allocated(error)) call finish(self)
         call loads_in_statics(problem%piece%loads, .false., 0.0_dp, 0.0_dp)
         if (allocated(error)) call prefix_error(error, 'with the static friction on the seabed: ')
         return
      end if
      call finish(self)
   end subroutine solve_rod_statics

   !> Replace end b by a fixed end at the height of end a, span to its right.
   subroutine set_end_b(self, span)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      real(dp), intent(in) :: span
      real(dp) :: pa(2)
      pa = self%piece%end_a%position(0.0_dp)
      self%state%end_b_point = pa + [span, 0.0_dp]
      deallocate (self%piece%end_b)
      allocate (self%piece%end_b, source=fixed_end(point=self%state%end_b_point))
      self%piece%end_b%label = 'end_b'
   end subroutine set_end_b

   !> Move end b to a new span, stretching the current solution horizontally.
   subroutine stretch_to(self, span)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      real(dp), intent(in) :: span
      real(dp) :: pa(2), old
      pa = self%piece%end_a%position(0.0_dp)
      old = self%state%end_b_point(1) - pa(1)
      self%state%r(1, :) = pa(1) + (self%state%r(1, :) - pa(1))*span/old
      call set_end_b(self, span)
   end subroutine stretch_to

   !> Solve at the current span; mismatch = |reaction at b| / T_s - 1.
   subroutine solve_at_span(self, mismatch, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      real(dp), intent(out) :: mismatch
      type(error_type), allocatable, intent(out) :: err
      real(dp) :: f(2)
      call solve_now(self, err)
      if (allocated(err)) return
      f = self%piece%reaction(self%n, reshape(self%state%r, [2*self%n]), 0.0_dp, 0.5_dp)
      mismatch = norm2(f)/self%scene%tension - 1
   end subroutine solve_at_span

   !> The direct solve (with its continuation in the loads); only when that
   !> fails, the pay-in of a line nearly slack on a seabed (pay_in), then the
   !> relaxation under the full loads: with distributed loads
   !> first from the catenary under their mean on the straight chord (a
   !> strong current can bow the line to the other side of the chord than
   !> its weight, and the bending energy, unbounded as cells fold, keeps the
   !> line from turning through a fold to get there), then from the
   !> catenary under the weight.
   subroutine solve_or_relax(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: err
      type(error_type), allocatable :: err2
      real(dp), allocatable :: guess(:, :)
      logical :: loaded
      guess = self%state%r
      call solve_with_loads(self, err)
      if (.not. allocated(err)) return
      self%piece%load_factor = 1
      ! A line nearly slack on a seabed: paid in from a taut state (or refused, with why).
      call pay_in(self, err)
      if (.not. allocated(err)) return
      self%state%r = guess
      ! A loose end resting on a seabed under a pull along it: from the line laid on the bottom.
      call lay_down(self, err)
      if (.not. allocated(err)) return
      self%state%r = guess
      call loaded_guess(self, loaded)
      if (loaded) then
         call relax_rope(self, err2)
         if (.not. allocated(err2)) then
            deallocate (err)
            return
         end if
         err%message = err%message//'; relaxation from the catenary under the mean load: '//err2%message
         deallocate (err2)
      end if
      self%state%r = guess
      call relax_rope(self, err2)
      if (.not. allocated(err2)) then
         deallocate (err)
         return
      end if
      err%message = err%message//'; relaxation: '//err2%message
   end subroutine solve_or_relax

   !> Span, sag and the reactions of the solution.
   subroutine finish(self)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      real(dp) :: x(2*self%n), res(2*self%n)
      type(band_matrix) :: unused
      x = reshape(self%state%r, [2*self%n])
      ! One evaluation at the solution sets the cell forces the reactions use.
      call self%problem%evaluate(x, res, unused, .false.)
      self%state%reaction_a = self%piece%reaction(1, x, 0.0_dp, 0.5_dp)
      self%state%reaction_b = self%piece%reaction(self%n, x, 0.0_dp, 0.5_dp)
      self%state%span = abs(self%state%r(1, self%n) - self%state%r(1, 1))
      self%state%sag = sag_below_chord(self%state%r)
   end subroutine finish

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
end module xcable_model_rod_statics
