!> The statics' Newton solves: Newton from the current state with the check that refuses a folded,
!> buried or collapsed state (solve_now, check_fold), the laws' compressive branch standing in
!> for a rope that cannot push (uncut_laws, own_laws_back), and the paths to the static state
!> when Newton from the first guess fails: the continuation in the distributed loads
!> (solve_with_loads), and the relaxation, a sequence of anchored equilibria (anchored_problem)
!> along an overdamped path, then Newton from there (relax, relax_rope; docs/theory/numerics.md,
!> Statics when Newton fails). (A submodule of model/rod_statics.f90.)
submodule (xcable_model_rod_statics) xcable_model_rod_statics_newton
   implicit none

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

contains

   !> Newton from state%r.
   module subroutine solve_now(self, err, max_iterations)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: err
      !> Iteration limit (default: the case's).
      integer, intent(in), optional :: max_iterations
      type(newton_workspace) :: work
      type(newton_options) :: opts
      type(newton_report) :: report
      real(dp), allocatable :: x(:)
      opts = self%options
      opts%tolerance = static_tolerance
      opts%reuse_jacobian = .false.
      if (present(max_iterations)) opts%max_iterations = max_iterations
      call work%init(2*self%n, rod_kl, rod_ku, spread(self%piece%length_ref, 1, 2*self%n))
      x = reshape(self%state%r, [2*self%n])
      call newton_solve(self%problem, x, work, opts, report, err)
      self%state%newton_iterations = self%state%newton_iterations + report%iterations
      if (allocated(err)) then
         call prefix_error(err, 'statics: ')
         return
      end if
      call check_fold(self, reshape(x, [2, self%n]), err)
      if (allocated(err)) return
      self%state%r = reshape(x, [2, self%n])
   end subroutine solve_now

   !> A solution is refused when it is folded: at some interior node the two
   !> cells turn back on themselves (turning angle above pi/2), when under the full loads a
   !> node lies deeper in a floor (a seabed) than a cell length, or when a cell has
   !> collapsed (shorter than collapsed_length of its unstretched length, as the step
   !> control refuses it). Such a state is
   !> an equilibrium of compressed, zigzagging cells (compression = 'law') or a
   !> bend sharper than the grid resolves, not the static state sought.
   subroutine check_fold(self, r, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
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
      if (self%piece%load_factor >= 1) then
         do k = 1, size(r, 2)
            if (floor_at(self, r(1, k)) - r(2, k) > self%piece%ds(min(k, size(r, 2) - 1))) then
               call fatal_error(err, 'statics: a state with node '//str(k)//' '// &
                                str(floor_at(self, r(1, k)) - r(2, k))//' m into the seabed (more than a cell)', &
                                stat_numerics)
               return
            end if
         end do
      end if
      ! A collapsed cell (a slack rope heaped into one point): the dynamics would refuse it.
      do k = 1, size(r, 2) - 1
         if (norm2(r(:, k + 1) - r(:, k)) < collapsed_length*self%piece%ds(k)) then
            self%saw_collapse = .true.
            call fatal_error(err, 'statics: a collapsed state (cell '//str(k)//' squeezed to '// &
                             str(100*norm2(r(:, k + 1) - r(:, k))/self%piece%ds(k))// &
                             ' % of its length: slack line heaped into a point)', stat_numerics)
            return
         end if
      end do
   end subroutine check_fold

   !> The piece's laws (its sections' too) replaced by their compressive branch continued
   !> (uncut_law) until own_laws_back; cut: whether any was a law that cannot push.
   module subroutine uncut_laws(self, cut)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      logical, intent(out) :: cut
      class(material_law), allocatable :: uncut
      logical :: was_cut
      integer :: j, m
      m = 0
      if (allocated(self%piece%sections)) m = size(self%piece%sections)
      allocate (self%own_laws(0:m))
      call uncut_law(self%piece%law, uncut, cut)
      call move_alloc(self%piece%law, self%own_laws(0)%law)
      call move_alloc(uncut, self%piece%law)
      do j = 1, m
         call uncut_law(self%piece%sections(j)%law, uncut, was_cut)
         cut = cut .or. was_cut
         call move_alloc(self%piece%sections(j)%law, self%own_laws(j)%law)
         call move_alloc(uncut, self%piece%sections(j)%law)
      end do
   end subroutine uncut_laws

   !> The piece's own laws back (after uncut_laws).
   module subroutine own_laws_back(self)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      integer :: j
      deallocate (self%piece%law)
      call move_alloc(self%own_laws(0)%law, self%piece%law)
      do j = 1, size(self%own_laws) - 1
         deallocate (self%piece%sections(j)%law)
         call move_alloc(self%own_laws(j)%law, self%piece%sections(j)%law)
      end do
      deallocate (self%own_laws)
   end subroutine own_laws_back

   !> Newton from state%r; if that fails and the cable carries distributed loads
   !> (a current can push it far from the catenary guess), solve without them
   !> and raise them step by step, each solution the guess of the next.
   module subroutine solve_with_loads(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: err
      real(dp), allocatable :: guess(:, :), last(:, :)
      real(dp) :: factor, step
      integer :: tries
      character(:), allocatable :: why
      if (.not. allocated(self%piece%loads)) then
         call solve_now(self, err)
         return
      end if
      if (size(self%piece%loads) == 0) then
         call solve_now(self, err)
         return
      end if
      why = ''
      guess = self%state%r
      call solve_now(self, err)
      if (.not. allocated(err)) return
      deallocate (err)
      self%state%r = guess
      self%piece%load_factor = 0
      call solve_now(self, err)
      if (allocated(err)) then
         self%piece%load_factor = 1
         return
      end if
      factor = 0
      step = 0.25_dp
      last = self%state%r
      do tries = 1, 200
         self%piece%load_factor = min(1.0_dp, factor + step)
         call solve_now(self, err)
         if (allocated(err)) then
            why = err%message
            deallocate (err)
            self%state%r = last
            step = 0.5_dp*step
            if (step < 1.0e-4_dp) exit
            cycle
         end if
         factor = self%piece%load_factor
         last = self%state%r
         if (factor >= 1) exit
         step = min(2*step, 1 - factor)
      end do
      self%piece%load_factor = 1
      if (factor < 1) call fatal_error(err, 'statics: no equilibrium found under the distributed loads ('// &
                                      load_names(self%piece%loads)//'): '// &
                                      'reached '//str(100*factor)//' % of them (the last step: '//why//')', &
                                      stat_numerics)
   end subroutine solve_with_loads

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

   !> Relax from state%r. A rope that cannot push (compression = 'none') is
   !> first relaxed as one that can (its law continued below zero strain:
   !> without it a squeezed cell has no stiffness at all and can collapse on
   !> the way), and Newton for the rope itself starts from that state.
   module subroutine relax_rope(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: err
      logical :: rope
      call uncut_laws(self, rope)
      call relax(self, err)
      call own_laws_back(self)
      if (.not. rope) return
      if (allocated(err)) return
      call solve_now(self, err)
      if (.not. allocated(err)) return
      deallocate (err)
      call relax(self, err)
   end subroutine relax_rope

   !> Pseudo-transient relaxation from state%r: a sequence of anchored
   !> equilibria (anchored_problem), each anchored at the last, the spring
   !> stiffened fourfold when its solve fails or moves a node by more than
   !> one cell length and softened fourfold when it succeeds, until Newton
   !> on the bare problem (solve_now, with its fold check) converges from
   !> the relaxed state. The path is that of an overdamped motion, so it
   !> does not jump, as an undamped Newton step can, past the equilibrium
   !> into a folded or far-off state.
   module subroutine relax(self, err)
      !> The solve.
      type(statics_solve), intent(inout) :: self
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
      anchored%rod => self%problem
      anchored%first = 1
      anchored%last = 2*self%n
      if (self%piece%end_a%held()) anchored%first = 3
      if (self%piece%end_b%held()) anchored%last = 2*self%n - 2
      call work%init(2*self%n, rod_kl, rod_ku, spread(self%piece%length_ref, 1, 2*self%n))
      opts = self%options
      opts%tolerance = 1.0e-8_dp
      opts%max_iterations = 12
      opts%reuse_jacobian = .false.
      opts%final_residual = .false.
      x = reshape(self%state%r, [2*self%n])
      allocate (res(2*self%n))
      call self%problem%evaluate(x, res, work%jacobian, .false.)
      ! The first spring moves the worst node by about one cell length.
      k0 = max(maxval(abs(res(anchored%first:anchored%last))), tiny(1.0_dp))/self%piece%length_ref
      anchored%stiffness = k0
      polish_below = 1.0e-2_dp
      accepted = 0
      do steps = 1, max_steps
         anchored%anchor = x
         trial = x
         call newton_solve(anchored, trial, work, opts, report, sub)
         self%state%newton_iterations = self%state%newton_iterations + report%iterations
         moved = huge(1.0_dp)
         if (.not. allocated(sub)) moved = maxval(abs(trial - x))/self%piece%length_ref
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
            self%state%r = reshape(x, [2, self%n])
            call solve_now(self, sub)
            if (.not. allocated(sub)) return
            deallocate (sub)
            polish_below = 0.1_dp*polish_below
         end if
      end do
      call fatal_error(err, 'no equilibrium reached ('//str(accepted)//' of '//str(steps - 1)// &
                       ' relaxation steps accepted, spring '//str(anchored%stiffness/k0)//' of the first)', &
                       stat_numerics)
   end subroutine relax

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
end submodule xcable_model_rod_statics_newton
