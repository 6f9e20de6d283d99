!> Newton's method for the discrete cable equations, with a banded Jacobian.
!>
!> A problem extends `newton_problem` and evaluates its residual and, when
!> asked, its Jacobian straight into LAPACK band storage. The solver keeps the
!> factorised Jacobian between calls when `reuse_jacobian` is set and refreshes
!> it as soon as the iteration contracts poorly (simplified Newton), so a time
!> step whose state changes little costs one factorisation every few steps.
!> Two thresholds govern the refresh: within a solve, an update larger than
!> `max_contraction` times the previous one (the iteration nearly stalls);
!> at the start of a solve, a last observed contraction above
!> `refresh_contraction` (the kept Jacobian has aged: a fresh one at the first
!> guess saves more iterations than it costs). In the paper's ruptures a
!> factorisation with its Jacobian costs about six iterations (residual and
!> substitution); 0.05 and 0.5 minimise the total (docs/measurements/benchmark.md).
!> All work arrays live in `newton_workspace`, allocated once.
!>
!> Convergence: the update is at most the tolerance; with `estimate_error`,
!> also when, from the second iteration on, the observed contraction
!> rho = |dx_k| / |dx_(k-1)| < 1/2 bounds the distance to the solution,
!> rho / (1 - rho) |dx_k| (the tail of a geometric series), by the tolerance.
!> A simplified Newton iteration contracting by 0.05 per step thus stops one
!> iteration earlier, at the same accuracy. The estimate assumes a smooth
!> residual along the last update; a problem with kinks (a rope that cannot
!> push) says where that may fail (`estimate_trusted`), and there only the
!> update itself is tested. The defaults are the classical
!> iteration; a time step (the box scheme's model, the rods' step control)
!> sets estimate_error, max_contraction 0.5, refresh_contraction 0.05 and no
!> final residual.
module xcable_solver_newton
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_numerics
   use xcable_core_strings, only: str
   use xcable_solver_banded, only: band_matrix
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: newton_problem, newton_options, newton_report, newton_workspace, newton_solve, largest_magnitude

   !> A nonlinear system F(x) = 0 with a banded Jacobian.
   type, abstract :: newton_problem
   contains
      !> Residual F(x) and, if with_jacobian, dF/dx into the band matrix.
      procedure(evaluate_interface), deferred :: evaluate
      !> Whether the contraction estimate may stop the iteration after this update from the
      !> last evaluated point (a problem with kinks says no where the update may have crossed
      !> one: the estimate assumes a smooth residual along it).
      procedure :: estimate_trusted
   end type newton_problem

   abstract interface
      subroutine evaluate_interface(self, x, residual, jacobian, with_jacobian)
         import :: newton_problem, band_matrix, dp
         !> The problem.
         class(newton_problem), intent(inout) :: self
         !> Unknowns.
         real(dp), intent(in) :: x(:)
         !> Residual.
         real(dp), intent(out) :: residual(:)
         !> Jacobian (set only if with_jacobian).
         type(band_matrix), intent(inout) :: jacobian
         !> Whether to compute the Jacobian.
         logical, intent(in) :: with_jacobian
      end subroutine evaluate_interface
   end interface

   !> Controls of the iteration.
   type :: newton_options
      !> Converged when max |dx_i| / scale_i (or, with estimate_error, its estimate of the remaining error) <= tolerance.
      real(dp) :: tolerance = 1.0e-9_dp
      !> Largest number of iterations.
      integer :: max_iterations = 25
      !> Keep the factorised Jacobian across iterations and calls while it contracts well.
      logical :: reuse_jacobian = .false.
      !> Refresh the Jacobian when an update is larger than this fraction of the previous one.
      real(dp) :: max_contraction = 0.25_dp
      !> Refresh it at the start of a solve when the last solve contracted by more than this per iteration.
      real(dp) :: refresh_contraction = huge(1.0_dp)
      !> Stop also when the contraction estimate of the remaining error is <= tolerance.
      logical :: estimate_error = .false.
      !> Evaluate the residual at the converged point for the report (residual_norm).
      logical :: final_residual = .true.
   end type newton_options

   !> What one solve did.
   type :: newton_report
      !> Iterations (linear solves) done.
      integer :: iterations = 0
      !> Jacobian factorisations done.
      integer :: factorisations = 0
      !> Whether it converged.
      logical :: converged = .false.
      !> max |F_i| (rows scaled by the problem) before each iteration and after the last.
      real(dp) :: residual_norm(0:100) = 0
      !> Scaled update norm of each iteration.
      real(dp) :: update_norm(100) = 0
   end type newton_report

   !> Work arrays of the solver, allocated once per problem size.
   type :: newton_workspace
      !> Jacobian, factorised when `factorised` is true.
      type(band_matrix) :: jacobian
      !> Residual.
      real(dp), allocatable :: residual(:)
      !> Update.
      real(dp), allocatable :: update(:)
      !> Scale of each unknown for the convergence test.
      real(dp), allocatable :: scale(:)
      !> Whether jacobian holds a usable factorisation (set .false. when dt changes).
      logical :: usable = .false.
      !> Contraction per iteration observed at the end of the last solve (0: unknown or one iteration).
      real(dp) :: contraction = 0
   contains
      !> Allocate for n unknowns with kl, ku diagonals.
      procedure :: init => workspace_init
   end type newton_workspace

contains

   !> The default: a smooth residual, the estimate holds.
   logical function estimate_trusted(self, update, tolerance)
      !> The problem.
      class(newton_problem), intent(in) :: self
      !> The last update (x_k = x_k-1 - update), unscaled.
      real(dp), intent(in) :: update(:)
      !> Tolerance on the scaled update.
      real(dp), intent(in) :: tolerance
      estimate_trusted = .true.
   end function estimate_trusted

   !> Allocate the workspace.
   subroutine workspace_init(self, n, kl, ku, scale)
      !> Workspace.
      class(newton_workspace), intent(inout) :: self
      !> Number of unknowns.
      integer, intent(in) :: n
      !> Sub-diagonals of the Jacobian.
      integer, intent(in) :: kl
      !> Super-diagonals of the Jacobian.
      integer, intent(in) :: ku
      !> Scale of each unknown.
      real(dp), intent(in) :: scale(n)
      call self%jacobian%init(n, kl, ku)
      if (allocated(self%residual)) deallocate (self%residual, self%update, self%scale)
      allocate (self%residual(n), self%update(n), self%scale(n))
      self%scale = scale
      self%usable = .false.
      self%contraction = 0
   end subroutine workspace_init

   !> Solve F(x) = 0 starting from x.
   subroutine newton_solve(problem, x, work, options, report, error)
      !> The system.
      class(newton_problem), intent(inout) :: problem
      !> First guess on entry, solution on return.
      real(dp), intent(inout) :: x(:)
      !> Work arrays (and the kept factorisation).
      type(newton_workspace), intent(inout) :: work
      !> Controls.
      type(newton_options), intent(in) :: options
      !> What was done.
      type(newton_report), intent(out) :: report
      !> Error when it does not converge.
      type(error_type), allocatable, intent(out) :: error
      logical :: fresh, converged
      real(dp) :: dnorm, dnorm_prev, rnorm, rate
      integer :: it, growth, m

      ! The unknowns may be fewer than the workspace was made for (a window of a larger
      ! problem, rod_run's skip of the quiescent cable): the work arrays' first m entries.
      m = size(x)
      if (m /= work%jacobian%n) then
         call work%jacobian%set_order(m, error)
         if (allocated(error)) return
         work%usable = .false.
      end if
      if (.not. options%reuse_jacobian) work%usable = .false.
      fresh = .not. work%usable .or. work%contraction > options%refresh_contraction
      call problem%evaluate(x, work%residual(1:m), work%jacobian, fresh)
      rnorm = largest_magnitude(m, work%residual)
      report%residual_norm(0) = rnorm
      if (.not. ieee_is_finite(rnorm)) then
         call fatal_error(error, 'Newton: residual is not finite (NaN or Inf) at the first guess', stat_numerics)
         return
      end if
      dnorm_prev = huge(1.0_dp)
      growth = 0
      do it = 1, options%max_iterations
         if (fresh) then
            call work%jacobian%factor(error)
            work%usable = .false.
            if (allocated(error)) return
            work%usable = .true.
            report%factorisations = report%factorisations + 1
         end if
         work%update(1:m) = work%residual(1:m)
         call work%jacobian%solve(work%update(1:m), error)
         if (allocated(error)) return
         call take_update(m, x, work%update, work%scale, dnorm)
         report%iterations = it
         if (it <= size(report%update_norm)) report%update_norm(it) = dnorm
         if (.not. ieee_is_finite(dnorm)) then
            call fatal_error(error, 'Newton: update is not finite (NaN or Inf) at iteration '//str(it), stat_numerics)
            work%usable = .false.
            return
         end if
         ! Refresh a kept Jacobian as soon as it stops contracting well.
         fresh = .not. options%reuse_jacobian .or. dnorm > options%max_contraction*dnorm_prev
         rate = 1
         if (it >= 2) rate = dnorm/dnorm_prev
         converged = dnorm <= options%tolerance
         if (options%estimate_error .and. rate < 0.5_dp .and. .not. converged) then
            if (problem%estimate_trusted(work%update(1:m), options%tolerance)) &
               converged = rate/(1 - rate)*dnorm <= options%tolerance
         end if
         if (converged) then
            report%converged = .true.
            work%contraction = 0
            if (it >= 2) work%contraction = rate
            if (options%final_residual) then
               call problem%evaluate(x, work%residual(1:m), work%jacobian, .false.)
               if (it <= ubound(report%residual_norm, 1)) report%residual_norm(it) = maxval(abs(work%residual(1:m)))
            end if
            return
         end if
         if (dnorm > dnorm_prev .and. it > 2) then
            growth = growth + 1
         else
            growth = 0
         end if
         if (growth >= 3) then
            call fatal_error(error, 'Newton: diverging (update grew three times in a row, now '//str(dnorm)//')', &
                             stat_numerics)
            work%usable = .false.
            return
         end if
         dnorm_prev = dnorm
         call problem%evaluate(x, work%residual(1:m), work%jacobian, fresh)
         rnorm = largest_magnitude(m, work%residual)
         if (it <= ubound(report%residual_norm, 1)) report%residual_norm(it) = rnorm
         if (.not. ieee_is_finite(rnorm)) then
            call fatal_error(error, 'Newton: residual is not finite (NaN or Inf) at iteration '//str(it), stat_numerics)
            work%usable = .false.
            return
         end if
      end do
      call fatal_error(error, 'Newton: no convergence in '//str(options%max_iterations)//' iterations (update '// &
                       str(dnorm)//', tolerance '//str(options%tolerance)//')', stat_numerics)
      work%usable = .false.
   end subroutine newton_solve

   !> x = x - u and the scaled update norm max |u_i| / scale_i, over m values. (Explicit
   !> shapes, unrolled by the compiler: newton_solve's own instructions on fast_180kN
   !> 6.73e6 -> 6.25e6, callgrind; the same values.)
   pure subroutine take_update(m, x, u, scale, dnorm)
      integer, intent(in) :: m
      real(dp), intent(inout) :: x(m)
      real(dp), intent(in) :: u(m), scale(m)
      real(dp), intent(out) :: dnorm
      x = x - u
      dnorm = maxval(abs(u)/scale)
   end subroutine take_update

   !> maxval(abs(a)) of m values (an explicit-shape argument: the intrinsic on an array
   !> component or section costs several times as many instructions).
   pure real(dp) function largest_magnitude(m, a)
      integer, intent(in) :: m
      real(dp), intent(in) :: a(m)
      largest_magnitude = maxval(abs(a))
   end function largest_magnitude
end module xcable_solver_newton
