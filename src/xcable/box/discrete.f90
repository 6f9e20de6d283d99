!> The discrete equations of the box scheme (paper eqs. 22-29) and their
!> analytic Jacobian, assembled straight into LAPACK band storage.
!>
!> Box k lies between nodes a = k-1 and b = k, of unstretched length ds(k-1).
!> With the time weight theta (1/2 is the paper's centred scheme, eq. 25), the
!> residual of the box, divided by 4 dt ds as in eq. 25, is
!>
!>   R = [theta (Y_b - Y_a) + (1-theta) (Y_b' - Y_a')] / ds
!>     + [Mbar_a (Y_a - Y_a') + Mbar_b (Y_b - Y_b')] / (2 dt)
!>     + [theta (P_a + P_b) + (1-theta) (P_a' + P_b')] / 2,
!>   Mbar = theta M(Y) + (1-theta) M(Y'),
!>
!> where a prime marks the previous time level. Statics drops the time terms
!> and the old level. Each row is multiplied by a constant so that all rows have
!> units of 1/m and comparable size (row 2 by 1/T_ref, rows 3-4 by 1/c_ref, row 7
!> by EI/T_ref); boundary rows are made dimensionless the same way.
!>
!> Ordering: unknown j of node k is column 7 (k-1) + j. Rows are the left
!> boundary conditions (n_left of them), then the 7 rows of each box in turn,
!> then the right boundary conditions. Within a box the rows are the
!> equations in the order `box_rows` = 1, 2, 3, 4, 7, 5, 6: equations 1-4 and
!> 7 involve eps (the first unknown) of both nodes, equations 5 and 6 only b0,
!> b3 and Omega3 (the last three), so putting 5 and 6 last keeps every row
!> within kl = n_left + 4 sub-diagonals; ku = 13 - n_left (kl + ku = 17).
!> In the natural order (kl = n_left + 6) a factorisation costs 1.4 times as
!> much (it scales with kl (kl + ku)), and no order of the rows alone does
!> better than 17 (checked over all 7! orders).
!>
!> Boundary conditions (docs/theory/equations.md):
!> - statics, fixed end: f(eps) = T_s, Sn = 0, u = 0, v = 0;
!>   free end: f(eps) = T_s, Sn = 0, b0^2 + b3^2 = 1;
!> - dynamics, fixed end: u = 0, v = 0, Omega3 = its static value;
!>   breaking end: T t + Sn n = F_v i + F_h j (two rows), Omega3 = static value,
!>   b0^2 + b3^2 = 1.
module xcable_box_discrete
   use xcable_core_kinds, only: dp
   use xcable_box_equations, only: cable_model, n_eq, i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om, &
                                     equation_terms, equation_derivatives, forcing_from_law, mass_times_from_law
   use xcable_solver_banded, only: band_matrix
   use xcable_solver_newton, only: newton_problem
   implicit none
   private
   public :: box_system, left_conditions_static, left_conditions_dynamic

   !> Number of boundary conditions at the fixed end.
   integer, parameter :: left_conditions_static = 4, left_conditions_dynamic = 3
   !> Equation held by each row of a box (see the ordering above).
   integer, parameter :: box_rows(n_eq) = [1, 2, 3, 4, 7, 5, 6]

   !> The discrete system of all boxes and both ends at one time level.
   type, extends(newton_problem) :: box_system
      !> Cable data.
      type(cable_model) :: model
      !> Number of nodes.
      integer :: nodes = 0
      !> Unstretched length of each box (nodes - 1), m.
      real(dp), allocatable :: ds(:)
      !> True for a time step, false for statics.
      logical :: dynamic = .false.
      !> Time weight of the new level (1/2: the paper's scheme).
      real(dp) :: theta = 0.5_dp
      !> Time step, s.
      real(dp) :: dt = 0
      !> Number of fixed-end conditions.
      integer :: n_left = left_conditions_static
      !> End tension of the static state, N.
      real(dp) :: end_tension = 0
      !> Omega3 held at the fixed end and at the breaking end, 1/m.
      real(dp) :: omega_fixed = 0, omega_free = 0
      !> Applied force at the breaking end at the new time level: horizontal (j) and vertical (i), N.
      real(dp) :: force_h = 0, force_v = 0
      !> Row scales of the box equations.
      real(dp) :: row_scale(n_eq) = 1
      !> Reference tension (N), speed (m/s) and curvature (1/m) of the boundary rows.
      real(dp) :: tension_ref = 1, speed_ref = 1, omega_ref = 1
      !> Previous time level.
      real(dp), allocatable :: y_old(:, :)
      !> M at the previous time level, per node.
      real(dp), allocatable :: mass_old(:, :, :)
      !> Old-level part of each box residual (unscaled).
      real(dp), allocatable :: old_part(:, :)
      !> Compliance 1 / f'(eps) at the previous time level, per node, 1/N.
      real(dp), allocatable :: compliance_old(:)
      !> Work: M, P and their derivatives at the new level, per node.
      real(dp), allocatable :: mass_new(:, :, :), forcing_new(:, :)
      real(dp), allocatable :: dmass_new(:, :, :), dforcing_new(:, :, :)
      !> Work: the change z = Y - Y' and the inertia term (theta M(Y) + (1-theta) M(Y')) z / (2 dt), per node.
      real(dp), allocatable :: change(:, :), inertia(:, :)
   contains
      !> Set up for a cable, a grid and a mode.
      procedure :: init => box_init
      !> Band widths of the Jacobian.
      procedure :: band_widths
      !> Scale of each unknown for Newton's convergence test.
      procedure :: unknown_scale
      !> Store the previous level and precompute its part of the residual.
      procedure :: prepare_step
      !> Residual and Jacobian (newton_problem).
      procedure :: evaluate => box_evaluate
   end type box_system

contains

   !> Set up the discrete system.
   subroutine box_init(self, model, s, dynamic, end_tension, speed_ref, theta)
      !> System.
      class(box_system), intent(inout) :: self
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unstretched arc length of the nodes, increasing from 0 to L, m.
      real(dp), intent(in) :: s(:)
      !> Time stepping (true) or statics (false).
      logical, intent(in) :: dynamic
      !> Static end tension T_s, N (also the tension scale).
      real(dp), intent(in) :: end_tension
      !> Axial wave speed at the static strain, m/s (the speed scale).
      real(dp), intent(in) :: speed_ref
      !> Time weight of the new level, 1/2 to 1.
      real(dp), intent(in) :: theta
      integer :: np
      self%model = model
      np = size(s)
      self%nodes = np
      self%ds = s(2:np) - s(1:np - 1)
      self%dynamic = dynamic
      self%theta = merge(theta, 1.0_dp, dynamic)
      self%n_left = merge(left_conditions_dynamic, left_conditions_static, dynamic)
      self%end_tension = end_tension
      self%tension_ref = end_tension
      self%speed_ref = speed_ref
      self%omega_ref = 1/model%length
      self%row_scale = [1.0_dp, 1/end_tension, 1/speed_ref, 1/speed_ref, 1.0_dp, 1.0_dp, &
                        model%bending_stiffness/end_tension]
      if (allocated(self%y_old)) deallocate (self%y_old, self%mass_old, self%old_part, self%mass_new, &
                                             self%forcing_new, self%dmass_new, self%dforcing_new, &
                                             self%compliance_old, self%change, self%inertia)
      allocate (self%y_old(n_eq, np), self%mass_old(n_eq, n_eq, np), self%old_part(n_eq, np - 1))
      allocate (self%mass_new(n_eq, n_eq, np), self%forcing_new(n_eq, np))
      allocate (self%dmass_new(n_eq, n_eq, np), self%dforcing_new(n_eq, n_eq, np))
      allocate (self%compliance_old(np), self%change(n_eq, np), self%inertia(n_eq, np))
      self%y_old = 0
      self%mass_old = 0
      self%old_part = 0
      self%compliance_old = 0
      self%change = 0
      self%inertia = 0
   end subroutine box_init

   !> Sub- and super-diagonals of the Jacobian for this ordering.
   pure subroutine band_widths(self, kl, ku)
      !> System.
      class(box_system), intent(in) :: self
      !> Sub-diagonals.
      integer, intent(out) :: kl
      !> Super-diagonals.
      integer, intent(out) :: ku
      kl = self%n_left + n_eq - 3
      ku = 2*n_eq - 1 - self%n_left
   end subroutine band_widths

   !> Scale of each unknown (7 per node) for the convergence test.
   pure function unknown_scale(self) result(scale)
      !> System.
      class(box_system), intent(in) :: self
      real(dp) :: scale(n_eq*self%nodes)
      real(dp) :: node_scale(n_eq)
      integer :: k
      node_scale = [1.0_dp, self%tension_ref, self%speed_ref, self%speed_ref, 1.0_dp, 1.0_dp, self%omega_ref]
      do k = 1, self%nodes
         scale(n_eq*(k - 1) + 1:n_eq*k) = node_scale
      end do
   end function unknown_scale

   !> Store the previous level, the step and the end force at the new level.
   subroutine prepare_step(self, y_old, dt, force_h, force_v)
      !> System.
      class(box_system), intent(inout) :: self
      !> State at the previous time level (7, nodes).
      real(dp), intent(in) :: y_old(:, :)
      !> Time step, s.
      real(dp), intent(in) :: dt
      !> Applied horizontal and vertical force at the breaking end at the new level, N.
      real(dp), intent(in) :: force_h, force_v
      integer :: k
      self%y_old = y_old
      self%dt = dt
      self%force_h = force_h
      self%force_v = force_v
      ! P at the old level goes to forcing_new as work space (assemble overwrites it).
      do k = 1, self%nodes
         call equation_terms(self%model, y_old(:, k), self%mass_old(:, :, k), self%forcing_new(:, k), &
                             self%compliance_old(k))
      end do
      do k = 2, self%nodes
         self%old_part(:, k - 1) = (1 - self%theta)*((y_old(:, k) - y_old(:, k - 1))/self%ds(k - 1) &
                                                     + 0.5_dp*(self%forcing_new(:, k - 1) + self%forcing_new(:, k)))
      end do
   end subroutine prepare_step

   !> Residual and, if asked, Jacobian (newton_problem interface).
   subroutine box_evaluate(self, x, residual, jacobian, with_jacobian)
      !> System.
      class(box_system), intent(inout) :: self
      !> Unknowns, 7 per node, node after node.
      real(dp), intent(in) :: x(:)
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian in band storage.
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to compute the Jacobian.
      logical, intent(in) :: with_jacobian
      call assemble(self, x, residual, jacobian, with_jacobian, self%nodes)
   end subroutine box_evaluate

   !> Assembly on the node-by-node view y(7, nodes) of the unknowns.
   subroutine assemble(self, y, residual, jacobian, with_jacobian, np)
      class(box_system), intent(inout) :: self
      integer, intent(in) :: np
      real(dp), intent(in) :: y(n_eq, np)
      real(dp), intent(out) :: residual(n_eq*np)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian
      real(dp) :: block(n_eq, n_eq), r(n_eq), mz(n_eq), mz_old(n_eq)
      real(dp) :: theta, half_rate, inv_ds, f, fp, c2, s2, ts, sn
      integer :: k, row0, col0, i, j, m, nl, band0
      integer :: side

      theta = self%theta
      nl = self%n_left
      half_rate = 0
      if (self%dynamic) half_rate = 0.5_dp/self%dt
      ! Node terms, once per node: P, the inertia term and (for the Jacobian) M
      ! and the derivatives; the law is evaluated once per node.
      associate (z => self%change)
         do k = 1, np
            if (self%dynamic) then
               z(:, k) = y(:, k) - self%y_old(:, k)
            else
               z(:, k) = 0
            end if
            if (with_jacobian) then
               call equation_terms(self%model, y(:, k), self%mass_new(:, :, k), self%forcing_new(:, k))
               call equation_derivatives(self%model, y(:, k), z(:, k), self%dmass_new(:, :, k), &
                                         self%dforcing_new(:, :, k))
               if (self%dynamic) then
                  mz = matmul(self%mass_new(:, :, k), z(:, k))
               end if
            else
               call self%model%law%tension_stiffness(y(i_eps, k), f, fp)
               call forcing_from_law(self%model, y(:, k), f, 1/fp, self%forcing_new(:, k))
               if (self%dynamic) call mass_times_from_law(self%model, y(:, k), 1/fp, z(:, k), mz)
            end if
            if (self%dynamic) then
               call mass_times_from_law(self%model, self%y_old(:, k), self%compliance_old(k), z(:, k), mz_old)
               self%inertia(:, k) = half_rate*(theta*mz + (1 - theta)*mz_old)
            else
               self%inertia(:, k) = 0
            end if
         end do
      end associate
      if (with_jacobian) then
         jacobian%ab = 0
         jacobian%factorised = .false.
      end if
      band0 = jacobian%kl + jacobian%ku + 1

      ! Fixed end (node 1): rows 1..nl.
      ts = self%tension_ref
      if (self%dynamic) then
         residual(1) = y(i_u, 1)/self%speed_ref
         residual(2) = y(i_v, 1)/self%speed_ref
         residual(3) = (y(i_om, 1) - self%omega_fixed)/self%omega_ref
         if (with_jacobian) then
            call put(1, i_u, 1/self%speed_ref)
            call put(2, i_v, 1/self%speed_ref)
            call put(3, i_om, 1/self%omega_ref)
         end if
      else
         residual(1) = (self%model%law%tension(y(i_eps, 1)) - self%end_tension)/ts
         residual(2) = y(i_sn, 1)/ts
         residual(3) = y(i_u, 1)/self%speed_ref
         residual(4) = y(i_v, 1)/self%speed_ref
         if (with_jacobian) then
            call put(1, i_eps, self%model%law%stiffness(y(i_eps, 1))/ts)
            call put(2, i_sn, 1/ts)
            call put(3, i_u, 1/self%speed_ref)
            call put(4, i_v, 1/self%speed_ref)
         end if
      end if

      ! Boxes.
      do k = 2, np
         inv_ds = 1/self%ds(k - 1)
         r = theta*((y(:, k) - y(:, k - 1))*inv_ds + 0.5_dp*(self%forcing_new(:, k - 1) + self%forcing_new(:, k)))
         if (self%dynamic) r = r + self%old_part(:, k - 1) + self%inertia(:, k - 1) + self%inertia(:, k)
         row0 = nl + n_eq*(k - 2)
         do i = 1, n_eq
            residual(row0 + i) = self%row_scale(box_rows(i))*r(box_rows(i))
         end do
         if (.not. with_jacobian) cycle
         do side = 0, 1
            i = k - 1 + side
            block = 0.5_dp*theta*self%dforcing_new(:, :, i)
            do j = 1, n_eq
               block(j, j) = block(j, j) + merge(theta, -theta, side == 1)*inv_ds
            end do
            if (self%dynamic) then
               block = block + half_rate*(theta*self%dmass_new(:, :, i) + theta*self%mass_new(:, :, i) &
                                          + (1 - theta)*self%mass_old(:, :, i))
            end if
            col0 = n_eq*(i - 1)
            do j = 1, n_eq
               ! Rows m of the box below the band hold structural zeros of the
               ! block (the ordering above): they have no place in band storage.
               do m = 1, min(n_eq, jacobian%kl + (col0 + j) - row0)
                  jacobian%ab(band0 + row0 - (col0 + j) + m, col0 + j) = self%row_scale(box_rows(m))*block(box_rows(m), j)
               end do
            end do
         end do
      end do

      ! Breaking end (node np): the remaining rows.
      row0 = nl + n_eq*(np - 1)
      f = self%model%law%tension(y(i_eps, np))
      fp = self%model%law%stiffness(y(i_eps, np))
      associate (b0 => y(i_b0, np), b3 => y(i_b3, np))
         if (self%dynamic) then
            sn = y(i_sn, np)
            c2 = b0**2 - b3**2
            s2 = 2*b0*b3
            residual(row0 + 1) = (f*c2 - sn*s2 - self%force_v)/ts
            residual(row0 + 2) = (f*s2 + sn*c2 - self%force_h)/ts
            residual(row0 + 3) = (y(i_om, np) - self%omega_free)/self%omega_ref
            residual(row0 + 4) = b0**2 + b3**2 - 1
            if (with_jacobian) then
               call put_end(1, i_eps, fp*c2/ts)
               call put_end(1, i_sn, -s2/ts)
               call put_end(1, i_b0, (2*f*b0 - 2*sn*b3)/ts)
               call put_end(1, i_b3, (-2*f*b3 - 2*sn*b0)/ts)
               call put_end(2, i_eps, fp*s2/ts)
               call put_end(2, i_sn, c2/ts)
               call put_end(2, i_b0, (2*f*b3 + 2*sn*b0)/ts)
               call put_end(2, i_b3, (2*f*b0 - 2*sn*b3)/ts)
               call put_end(3, i_om, 1/self%omega_ref)
               call put_end(4, i_b0, 2*b0)
               call put_end(4, i_b3, 2*b3)
            end if
         else
            residual(row0 + 1) = (f - self%end_tension)/ts
            residual(row0 + 2) = y(i_sn, np)/ts
            residual(row0 + 3) = b0**2 + b3**2 - 1
            if (with_jacobian) then
               call put_end(1, i_eps, fp/ts)
               call put_end(2, i_sn, 1/ts)
               call put_end(3, i_b0, 2*b0)
               call put_end(3, i_b3, 2*b3)
            end if
         end if
      end associate

   contains

      !> A(row, column j of node 1) = val.
      subroutine put(row, j, val)
         integer, intent(in) :: row, j
         real(dp), intent(in) :: val
         jacobian%ab(band0 + row - j, j) = val
      end subroutine put

      !> A(row0 + row, column j of node np) = val.
      subroutine put_end(row, j, val)
         integer, intent(in) :: row, j
         real(dp), intent(in) :: val
         integer :: col
         col = n_eq*(np - 1) + j
         jacobian%ab(band0 + row0 + row - col, col) = val
      end subroutine put_end
   end subroutine assemble
end module xcable_box_discrete
