!> A run of the 3-D rod (model/rod3d.f90) on one piece: the static state by
!> Newton from a given guess, then steps of a given size, with the energy
!> ledger (stored energy minus the work of the ends plus what damping took).
!> A step is an attempt (Newton from R + dt V) followed by accept (new
!> velocities, the ledger) or reject (back to the old level), so that a
!> driver can check the attempt first (driver/rod3d_drive.f90 runs the
!> planar driver's step control on it); step does both without a check.
module xcable_driver_rod3d_run
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, prefix_error
   use xcable_core_strings, only: str
   use xcable_model_rod3d, only: rod3d_problem, rod3d_kl, rod3d_ku, couple_plane, small_strain_step
   use xcable_ends_end_condition, only: end_condition
   use xcable_material_tension_only, only: slack_dissipation
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   implicit none
   private
   public :: rod3d_run

   !> State and ledger of a 3-D run.
   type :: rod3d_run
      !> The piece as a Newton problem.
      type(rod3d_problem) :: problem
      !> Unknowns (4 per node) and velocities (3, n).
      real(dp), allocatable :: x(:), v(:, :)
      !> Time, s.
      real(dp) :: t = 0
      !> Newton work arrays and controls.
      type(newton_workspace) :: work
      type(newton_options) :: options
      !> Stored energy at the start (J), work done by the ends and by the distributed loads (J),
      !> energy taken by damping and theta > 1/2 (J).
      real(dp) :: energy0 = 0, end_work = 0, load_work = 0, dissipated = 0
      !> Newton iterations of all attempts, and of the last attempt.
      integer :: iterations = 0, last_iterations = 0
      !> Unknowns at the old level of the attempt in x.
      real(dp), allocatable :: x_old(:)
      !> Whether the problem was last evaluated at x (Newton's residual at the converged point),
      !> so that accept need not evaluate it again.
      logical :: evaluated_at_x = .false.
   contains
      !> Set up the work arrays after problem%piece has been initialised.
      procedure :: init => run_init
      !> Solve the statics at time t from the guess in x; sets v = 0 and starts the ledger.
      procedure :: statics => run_statics
      !> Start from a given state (x, v) at time t.
      procedure :: start => run_start
      !> One step of size dt (attempt, then accept).
      procedure :: step => run_step
      !> Newton for the step of size dt from the current state (x becomes the new level).
      procedure :: attempt => run_attempt
      !> Take the attempted step: new velocities, time and ledger.
      procedure :: accept => run_accept
      !> Drop the attempted step: x back to the old level.
      procedure :: reject => run_reject
      !> Stored energies [strain, kinetic, bending, gravity, twist], J.
      procedure :: energies => run_energies
      !> Ledger: stored energy - initial - work of ends and loads + dissipated, J (0 when it closes).
      procedure :: imbalance => run_imbalance
   end type rod3d_run

contains

   subroutine run_init(self, tolerance)
      !> Run.
      class(rod3d_run), intent(inout) :: self
      !> Newton tolerance on the scaled update.
      real(dp), intent(in) :: tolerance
      integer :: n
      real(dp), allocatable :: scale(:)
      n = self%problem%piece%n
      allocate (self%x(4*n), self%v(3, n), scale(4*n))
      self%x = 0
      self%v = 0
      scale(1:3*n) = self%problem%piece%length_ref
      scale(3*n + 1:4*n) = 1
      call self%work%init(4*n, rod3d_kl, rod3d_ku, scale)
      self%options%tolerance = tolerance
      self%options%max_iterations = 50
   end subroutine run_init

   subroutine run_statics(self, t, error)
      class(rod3d_run), intent(inout) :: self
      !> Time of the static state, s.
      real(dp), intent(in) :: t
      !> Error when Newton fails.
      type(error_type), allocatable, intent(out) :: error
      type(newton_report) :: report
      self%problem%dt = 0
      self%problem%t0 = t
      call newton_solve(self%problem, self%x, self%work, self%options, report, error)
      if (allocated(error)) then
         call prefix_error(error, '3-D statics: ')
         return
      end if
      self%v = 0
      call self%start(self%x, self%v, t)
   end subroutine run_statics

   subroutine run_start(self, x, v, t)
      class(rod3d_run), intent(inout) :: self
      !> Unknowns (4 per node), velocities (3, n), time.
      real(dp), intent(in) :: x(:), v(:, :), t
      self%x = x
      self%v = v
      self%t = t
      self%energy0 = sum(self%energies())
      self%end_work = 0
      self%load_work = 0
      self%dissipated = 0
      self%evaluated_at_x = .false.
   end subroutine run_start

   subroutine run_step(self, dt, theta, error)
      class(rod3d_run), intent(inout) :: self
      !> Step (s) and time weight.
      real(dp), intent(in) :: dt, theta
      !> Error when Newton fails (x is then back at the old level).
      type(error_type), allocatable, intent(out) :: error
      call self%attempt(dt, theta, error)
      if (allocated(error)) then
         call self%reject()
         return
      end if
      call self%accept(dt, theta)
   end subroutine run_step

   subroutine run_attempt(self, dt, theta, error)
      class(rod3d_run), intent(inout) :: self
      !> Step (s) and time weight.
      real(dp), intent(in) :: dt, theta
      !> Error when Newton fails.
      type(error_type), allocatable, intent(out) :: error
      type(newton_report) :: report
      integer :: n, k
      associate (piece => self%problem%piece)
         n = piece%n
         self%x_old = self%x
         call piece%prepare_step(reshape(self%x_old(1:3*n), [3, n]), self%v)
         self%problem%dt = dt
         self%problem%t0 = self%t
         self%problem%theta = theta
         ! First guess: R + dt V.
         do k = 1, n
            self%x(3*k - 2:3*k) = self%x_old(3*k - 2:3*k) + dt*self%v(:, k)
         end do
         call newton_solve(self%problem, self%x, self%work, self%options, report, error)
         self%last_iterations = report%iterations
         self%iterations = self%iterations + report%iterations
         ! With final_residual, a converged Newton has evaluated the step system at the new level.
         self%evaluated_at_x = .not. allocated(error) .and. report%converged .and. self%options%final_residual
         if (allocated(error)) call prefix_error(error, '3-D step at t = '//str(self%t)//' s: ')
      end associate
   end subroutine run_attempt

   subroutine run_reject(self)
      class(rod3d_run), intent(inout) :: self
      self%x = self%x_old
      self%work%usable = .false.
      self%evaluated_at_x = .false.
   end subroutine run_reject

   subroutine run_accept(self, dt, theta)
      class(rod3d_run), intent(inout) :: self
      !> Step (s) and time weight of the attempt.
      real(dp), intent(in) :: dt, theta
      real(dp), allocatable :: r0(:, :), r1(:, :), v1(:, :)
      real(dp) :: eps0, eps1, dv(3)
      integer :: n, k, c, j
      associate (piece => self%problem%piece, x0 => self%x_old)
         n = piece%n
         r0 = reshape(x0(1:3*n), [3, n])
         r1 = reshape(self%x(1:3*n), [3, n])
         allocate (v1(3, n))
         call piece%new_velocity(r1, dt, theta, v1)
         ! Work of the ends: applied forces (trapezoid in time, as the rows), torques (trapezoid,
         ! exact for the quasi-static twist), reactions of held ends on their displacement. They
         ! read the piece's state at the new level (cell forces, loads), which Newton's final
         ! residual has set; evaluated here only when it has not.
         if (.not. self%evaluated_at_x) call self%problem%evaluate(self%x, self%work%residual, self%work%jacobian, &
                                                                   .false.)
         self%evaluated_at_x = .false.
         self%work%usable = .false.
         call book_end(1)
         call book_end(n)
         self%load_work = self%load_work + sum(piece%load_node*(r1 - r0))
         ! Damping and numerical dissipation (theta > 1/2); on a line of segments each section
         ! with its law and damping.
         if (allocated(piece%sections)) then
            do j = 1, size(piece%sections)
               associate (sec => piece%sections(j))
                  do c = sec%first, sec%last
                     eps0 = piece%l0(c) - 1
                     eps1 = piece%l1(c) - 1
                     if (sec%law%strain_slack > -huge(1.0_dp)) then
                        self%dissipated = self%dissipated + piece%ds(c)*slack_dissipation(sec%law, eps0, eps1, &
                                                                                           sec%damping, dt, &
                                                                                           small_strain_step)
                     else
                        self%dissipated = self%dissipated + sec%damping*piece%ds(c)*(eps1 - eps0)**2/dt
                     end if
                  end do
               end associate
            end do
         else
            do c = 1, n - 1
               eps0 = piece%l0(c) - 1
               eps1 = piece%l1(c) - 1
               if (piece%law%strain_slack > -huge(1.0_dp)) then
                  self%dissipated = self%dissipated + piece%ds(c)*slack_dissipation(piece%law, eps0, eps1, &
                                                                                     piece%damping, dt, small_strain_step)
               else
                  self%dissipated = self%dissipated + piece%damping*piece%ds(c)*(eps1 - eps0)**2/dt
               end if
            end do
         end if
         ! State-dependent ends (springs): what their damping took.
         if (piece%end_a%state_dependent()) call end_damping(piece%end_a, 1)
         if (piece%end_b%state_dependent()) call end_damping(piece%end_b, n)
         if (theta > 0.5_dp) then
            do k = 1, n
               dv = v1(:, k) - self%v(:, k)
               self%dissipated = self%dissipated + (theta - 0.5_dp)*mass_dot(k, v1 - self%v, dv)
            end do
         end if
         self%v = v1
         self%t = self%t + dt
      end associate

   contains

      !> Minus the work of the damping part of a state-dependent end's step force at node k.
      subroutine end_damping(end, k)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: k
         real(dp) :: f(3), jac(3, 3), damp(3)
         call end%step_force(self%t, dt, r0(:, k), r1(:, k), f, jac, damp)
         self%dissipated = self%dissipated - dot_product(damp, r1(:, k) - r0(:, k))
      end subroutine end_damping

      !> The end at node k: the work over the step of its force, its torque and its couple.
      subroutine book_end(k)
         integer, intent(in) :: k
         real(dp) :: force(3), torque0, torque1, dpsi, p0(2), p1(2), dphi, couple, basis(3, 2)
         integer :: c
         associate (piece => self%problem%piece)
            if ((k == 1 .and. piece%end_a%held()) .or. (k == n .and. piece%end_b%held())) then
               force = piece%reaction(k, dt)
            else if (k == 1) then
               force = 0.5_dp*(piece%end_a%applied_force3(self%t) + piece%end_a%applied_force3(self%t + dt))
            else
               force = 0.5_dp*(piece%end_b%applied_force3(self%t) + piece%end_b%applied_force3(self%t + dt))
            end if
            self%end_work = self%end_work + dot_product(force, self%x(3*k - 2:3*k) - self%x_old(3*k - 2:3*k))
            dpsi = self%x(3*n + k) - self%x_old(3*n + k)
            if (k == 1) then
               torque0 = -piece%end_a%applied_torque(self%t)
               torque1 = -piece%end_a%applied_torque(self%t + dt)
            else
               torque0 = piece%end_b%applied_torque(self%t)
               torque1 = piece%end_b%applied_torque(self%t + dt)
            end if
            self%end_work = self%end_work + 0.5_dp*(torque0 + torque1)*dpsi
            ! The couple (about its axis, -y unless the end says otherwise) on the end cell's
            ! projected angle (model/rod3d.f90, add_couples).
            c = merge(1, n - 1, k == 1)
            if (k == 1) then
               couple = 0.5_dp*(piece%end_a%applied_couple(self%t) + piece%end_a%applied_couple(self%t + dt))
               basis = couple_plane(piece%end_a%couple_axis())
            else
               couple = 0.5_dp*(piece%end_b%applied_couple(self%t) + piece%end_b%applied_couple(self%t + dt))
               basis = couple_plane(piece%end_b%couple_axis())
            end if
            p0 = matmul(piece%e0(:, c), basis)
            p1 = matmul(piece%e1(:, c), basis)
            dphi = atan2(p0(1)*p1(2) - p0(2)*p1(1), dot_product(p0, p1))
            self%end_work = self%end_work + couple*dphi
         end associate
      end subroutine book_end

      !> Component sum of (M w)_k . dv for the mass matrix of the piece.
      real(dp) function mass_dot(k, w, dvk)
         integer, intent(in) :: k
         real(dp), intent(in) :: w(:, :), dvk(3)
         real(dp) :: mw(3)
         integer :: j
         associate (piece => self%problem%piece)
            mw = piece%mass(0, k)*w(:, k)
            do j = 1, 2
               if (k + j <= n) mw = mw + piece%mass(j, k)*w(:, k + j)
               if (k - j >= 1) mw = mw + piece%mass(j, k - j)*w(:, k - j)
            end do
         end associate
         mass_dot = dot_product(mw, dvk)
      end function mass_dot
   end subroutine run_accept

   function run_energies(self) result(en)
      class(rod3d_run), intent(in) :: self
      real(dp) :: en(5)
      en = self%problem%piece%energies(self%x, self%v)
   end function run_energies

   real(dp) function run_imbalance(self)
      class(rod3d_run), intent(in) :: self
      run_imbalance = sum(self%energies()) - self%energy0 - self%end_work - self%load_work + self%dissipated
   end function run_imbalance
end module xcable_driver_rod3d_run
