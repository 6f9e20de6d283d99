!> The node rows of a planar piece from its cells' forces and blocks: the residual and the band
!> Jacobian of the statics and of a step (assemble), and of a step on a window of nodes
!> (assemble_window), with the ends that depend on their own state. (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_assembly
   implicit none

contains

   !> Node residuals and the Jacobian from the cell forces and blocks (statics:
   !> t1 is the time; dynamics: t1 = t0, t2 = dt).
   module subroutine assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
      class(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: t1, t2
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian, dynamic
      real(dp), intent(in), optional :: theta
      integer :: n, c, k, j, side, node, band0, a, b, row, col
      real(dp) :: share
      real(dp) :: scale, rate, fext_a(2), fext_b(2), t_new, jac_a(2, 2), jac_b(2, 2)
      logical :: held_a, held_b, state_a, state_b
      n = self%n
      scale = 1/self%tension_ref
      held_a = self%end_a%held()
      held_b = self%end_b%held()
      if (dynamic) then
         t_new = t1 + t2
         fext_a = 0.5_dp*(self%end_a%applied_force(t1) + self%end_a%applied_force(t_new))
         fext_b = 0.5_dp*(self%end_b%applied_force(t1) + self%end_b%applied_force(t_new))
         rate = 1/(theta*t2*t2)
         ! V^n+1 from the new positions. (Element by element: the array expressions cost 2-3
         ! times more, in temporaries.)
         do k = 1, n
            do a = 1, 2
               self%v1(a, k) = ((x(2*k - 2 + a) - self%r0(a, k))/t2 - (1 - theta)*self%v0(a, k))/theta
            end do
         end do
      else
         t_new = t1
         fext_a = self%end_a%applied_force(t1)
         fext_b = self%end_b%applied_force(t1)
         rate = 0
      end if
      ! Ends that depend on their own state (springs): their force at the node, and its derivative.
      state_a = self%end_a%state_dependent()
      state_b = self%end_b%state_dependent()
      if (state_a) call add_end_state(self%end_a, dynamic, t1, t2, self%r0(:, 1), x(1:2), fext_a, jac_a)
      if (state_b) call add_end_state(self%end_b, dynamic, t1, t2, self%r0(:, n), x(2*n - 1:2*n), fext_b, jac_b)
      ! Node k: N_k - N_k-1, its weight, loads, applied forces and in a step the inertia
      ! [M (V^n+1 - V^n)]_k / dt, over T_ref. Each node's rows are summed in one go, their
      ! terms in the order of the former loops (a pass over the residual for each kind of
      ! term: the same bits in 11e6 fewer instructions on fast_180kN, callgrind).
      if (allocated(self%node_w)) then
         call node_residuals(n, 1, n, self%force, rod_node_weight(self, 1), rod_node_weight(self, n), 1.0_dp, self%node_w, &
                             self%load_node, fext_a, fext_b, dynamic, self%mass, self%v1, self%mv0, t2, scale, residual)
      else
         call node_residuals(n, 1, n, self%force, rod_node_weight(self, 1), rod_node_weight(self, n), self%weight, &
                             self%lumped, self%load_node, fext_a, fext_b, dynamic, self%mass, self%v1, self%mv0, t2, &
                             scale, residual)
      end if
      if (held_a) residual(1:2) = (x(1:2) - self%end_a%position(t_new))/self%length_ref
      if (held_b) residual(2*n - 1:2*n) = (x(2*n - 1:2*n) - self%end_b%position(t_new))/self%length_ref
      if (.not. with_jacobian) return

      call jacobian%clear()
      band0 = jacobian%kl + jacobian%ku + 1
      call add_jacobian(n, 1, n, jacobian%ldab, band0, jacobian%ab, self%block, self%ds, self%mass, scale, rate, &
                        held_a, held_b, dynamic, self%block_scaled, self%mass_scaled)
      if (state_a) call add_end_block(jacobian, 0, jac_a, scale)
      if (state_b) call add_end_block(jacobian, 2*n - 2, jac_b, scale)
      ! Bodies at nodes: their drag's derivative (its force is in load_node).
      if (allocated(self%points)) then
         do c = 1, size(self%points)
            k = self%point_node(c)
            if ((k == 1 .and. held_a) .or. (k == n .and. held_b)) cycle
            call add_end_block(jacobian, 2*(k - 1), self%point_jac(:, :, c), scale)
         end do
      end if
      ! Distributed loads: node c and node c+1 each get -F_c / 2 (and -G_c, +G_c of unequal shares).
      if (allocated(self%loads)) then
         if (size(self%loads) > 0) then
            do c = 1, n - 1
               do side = 0, 1
                  node = c + side
                  do j = 0, 1
                     k = c + j
                     if (k == 1 .and. held_a) cycle
                     if (k == n .and. held_b) cycle
                     do a = 1, 2
                        do b = 1, 2
                           row = 2*(k - 1) + a
                           col = 2*(node - 1) + b
                           share = 0.5_dp*self%load_block(a, b, side, c)
                           if (self%skewed) share = share + merge(1.0_dp, -1.0_dp, j == 0)*self%skew_block(a, b, side, c)
                           jacobian%ab(band0 + row - col, col) = jacobian%ab(band0 + row - col, col) - share*scale
                        end do
                     end do
                  end do
               end do
            end do
         end if
      end if
      if (held_a) call held_rows(1)
      if (held_b) call held_rows(n)

   contains

      !> Rows of a held node: R_k - X(t) = 0.
      subroutine held_rows(kk)
         integer, intent(in) :: kk
         integer :: aa
         do aa = 1, 2
            row = 2*(kk - 1) + aa
            jacobian%ab(band0, row) = 1/self%length_ref
         end do
      end subroutine held_rows
   end subroutine assemble

   !> assemble (dynamic) on the rows and columns of the nodes lo .. hi, from the cell
   !> forces and blocks step_window computed; the positions of all nodes in memo_x.
   !> Each residual entry gets its terms in assemble's order.
   module subroutine assemble_window(self, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)
      type(rod_piece), intent(inout) :: self
      integer, intent(in) :: lo, hi
      real(dp), intent(in) :: t0, dt, theta
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian
      integer :: n, off, va, vb
      real(dp) :: scale, rate, fext_a(2), fext_b(2), t_new, jac_a(2, 2), jac_b(2, 2)
      logical :: held_a, held_b, state_a, state_b
      n = self%n
      scale = 1/self%tension_ref
      held_a = self%end_a%held()
      held_b = self%end_b%held()
      t_new = t0 + dt
      off = 2*(lo - 1)
      ! New velocities where the rows (and the reactions at the ends) need them.
      va = max(1, lo - 2)
      vb = min(n, hi + 2)
      call window_velocities(va, vb)
      if (va > 1) call window_velocities(1, min(3, n))
      if (vb < n) call window_velocities(max(1, n - 2), n)
      ! The rows of the nodes lo .. hi: node_residuals, as assemble's (explicit shapes: the
      ! same operations in the same order as the loop over self's components it replaces,
      ! 0.6375e9 -> 0.6359e9 instructions on fast_180kN, callgrind).
      fext_a = 0
      fext_b = 0
      if (lo == 1) fext_a = 0.5_dp*(self%end_a%applied_force(t0) + self%end_a%applied_force(t_new))
      if (hi == n) fext_b = 0.5_dp*(self%end_b%applied_force(t0) + self%end_b%applied_force(t_new))
      state_a = lo == 1 .and. self%end_a%state_dependent()
      state_b = hi == n .and. self%end_b%state_dependent()
      if (state_a) call add_end_state(self%end_a, .true., t0, dt, self%r0(:, 1), self%memo_x(1:2), fext_a, jac_a)
      if (state_b) call add_end_state(self%end_b, .true., t0, dt, self%r0(:, n), self%memo_x(2*n - 1:2*n), fext_b, &
                                      jac_b)
      if (allocated(self%node_w)) then
         ! The node weights as lumped lengths of a unit weight (1 * w_k: the same bits).
         call node_residuals(n, lo, hi, self%force, rod_node_weight(self, 1), rod_node_weight(self, n), 1.0_dp, &
                             self%node_w, self%load_node, fext_a, fext_b, .true., self%mass, self%v1, self%mv0, dt, &
                             scale, residual)
      else
         call node_residuals(n, lo, hi, self%force, rod_node_weight(self, 1), rod_node_weight(self, n), self%weight, &
                             self%lumped, self%load_node, fext_a, fext_b, .true., self%mass, self%v1, self%mv0, dt, &
                             scale, residual)
      end if
      if (held_a .and. lo == 1) residual(1:2) = (self%memo_x(1:2) - self%end_a%position(t_new))/self%length_ref
      if (held_b .and. hi == n) residual(2*(hi - lo) + 1:2*(hi - lo) + 2) = &
         (self%memo_x(2*n - 1:2*n) - self%end_b%position(t_new))/self%length_ref
      if (.not. with_jacobian) return
      rate = 1/(theta*dt*dt)
      call jacobian%clear()
      call add_jacobian(n, lo, hi, jacobian%ldab, jacobian%kl + jacobian%ku + 1, jacobian%ab, self%block, self%ds, &
                        self%mass, scale, rate, held_a, held_b, .true., self%block_scaled, self%mass_scaled)
      if (state_a) call add_end_block(jacobian, 0, jac_a, scale)
      if (state_b) call add_end_block(jacobian, 2*(hi - lo), jac_b, scale)
      if (held_a .and. lo == 1) then
         jacobian%ab(jacobian%kl + jacobian%ku + 1, 1:2) = 1/self%length_ref
      end if
      if (held_b .and. hi == n) then
         jacobian%ab(jacobian%kl + jacobian%ku + 1, 2*(hi - lo) + 1:2*(hi - lo) + 2) = 1/self%length_ref
      end if

   contains

      subroutine window_velocities(k1, k2)
         integer, intent(in) :: k1, k2
         integer :: kk, aa
         do kk = k1, k2
            do aa = 1, 2
               self%v1(aa, kk) = ((self%memo_x(2*kk - 2 + aa) - self%r0(aa, kk))/dt - (1 - theta)*self%v0(aa, kk))/theta
            end do
         end do
      end subroutine window_velocities
   end subroutine assemble_window

   !> The force of an end that depends on its own state, added to f (the time-only applied
   !> force of its node), and its derivative with respect to the node's (new) position: the
   !> statics' state_force at rest at x (dynamic false, t the time), or a step's step_force
   !> from x0 at t to x over dt.
   subroutine add_end_state(end, dynamic, t, dt, x0, x, f, jac)
      !> The end (state_dependent).
      class(end_condition), intent(in) :: end
      !> A step (or the statics).
      logical, intent(in) :: dynamic
      !> Time (the step's start), s; the step, s.
      real(dp), intent(in) :: t, dt
      !> The node's old (a step) and new position (x, z), m.
      real(dp), intent(in) :: x0(2), x(2)
      !> Force on the node, N: the end's force is added.
      real(dp), intent(inout) :: f(2)
      !> d (end's force) / d x, N/m.
      real(dp), intent(out) :: jac(2, 2)
      real(dp) :: f3(3), j3(3, 3), dv(3, 3), damp(3)
      if (dynamic) then
         call end%step_force(t, dt, point3(x0), point3(x), f3, j3, damp)
      else
         call end%state_force(t, point3(x), [0.0_dp, 0.0_dp, 0.0_dp], f3, j3, dv, damp)
      end if
      f = f + f3([1, 3])
      jac = j3([1, 3], [1, 3])
   end subroutine add_end_state

   !> -jac times the row scale on the 2x2 diagonal block of the rows and columns off + 1, off + 2
   !> (an end node's: its rows hold -F).
   subroutine add_end_block(jacobian, off, jac, scale)
      !> Jacobian, band storage.
      type(band_matrix), intent(inout) :: jacobian
      !> Unknowns before the block.
      integer, intent(in) :: off
      !> d F / d x of the end, N/m.
      real(dp), intent(in) :: jac(2, 2)
      !> Row scale.
      real(dp), intent(in) :: scale
      integer :: a, b, band0
      band0 = jacobian%kl + jacobian%ku + 1
      do b = 1, 2
         do a = 1, 2
            jacobian%ab(band0 + a - b, off + b) = jacobian%ab(band0 + a - b, off + b) - jac(a, b)*scale
         end do
      end do
   end subroutine add_end_block
end submodule xcable_model_rod_assembly
