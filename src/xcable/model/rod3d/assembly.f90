!> The assembly of a 3-D piece's node rows: the cell forces and their blocks, inertia, weight,
!> distributed loads, end forces, twist rows and held rows, for a step and for the statics.
!> (A submodule of model/rod3d.f90. Its helpers are internal procedures, which gfortran 12
!> inlines; a submodule's own procedures it would not, docs/dev/model-interface.md.)
submodule (xcable_model_rod3d) xcable_model_rod3d_assembly
   implicit none

contains

   !> Node rows from the cell forces and blocks, inertia, weight, end forces, twist and held rows
   !> (statics: t1 the time; a step: t1 = t0, t2 = dt).
   module subroutine rod3d_assemble(self, x, t1, t2, residual, jacobian, with_jacobian, dynamic, theta)
      class(rod3d_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: t1, t2
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian, dynamic
      real(dp), intent(in) :: theta
      integer :: n, c, k, band0, a, b
      real(dp) :: scale, rate, t_new, r(3, self%n), psi(self%n), twist_scale, tau, jac_a(3, 3), jac_b(3, 3)
      logical :: held_a, held_b, anchor_a, anchor_b, state_a, state_b, skip_a, skip_b
      n = self%n
      scale = 1/self%tension_ref
      twist_scale = self%length_ref/self%gip
      held_a = self%end_a%held()
      held_b = self%end_b%held()
      anchor_a = held_a .or. .not. held_b
      anchor_b = held_b
      ! The rows of a held end are replaced by its held rows; those kept are formed first.
      skip_a = held_a .and. .not. self%keep_rows(1)
      skip_b = held_b .and. .not. self%keep_rows(2)
      call rod3d_unpack(x, r, psi)
      residual = 0
      do c = 1, n - 1
         residual(3*c - 2:3*c) = residual(3*c - 2:3*c) - self%force(:, c)
         residual(3*c + 1:3*c + 3) = residual(3*c + 1:3*c + 3) + self%force(:, c)
      end do
      do k = 1, n
         residual(3*k) = residual(3*k) + rod3d_node_weight(self, k)
         residual(3*k - 2:3*k) = residual(3*k - 2:3*k) - self%load_node(:, k)
      end do
      if (dynamic) then
         t_new = t1 + t2
         residual(1:3) = residual(1:3) - 0.5_dp*(self%end_a%applied_force3(t1) + self%end_a%applied_force3(t_new))
         residual(3*n - 2:3*n) = residual(3*n - 2:3*n) &
                                     - 0.5_dp*(self%end_b%applied_force3(t1) + self%end_b%applied_force3(t_new))
         rate = 1/(theta*t2*t2)
         self%v1 = ((r - self%r0)/t2 - (1 - theta)*self%v0)/theta
         call self%mass_times(self%v1, self%force_node)
         do k = 1, n
            residual(3*k - 2:3*k) = residual(3*k - 2:3*k) + (self%force_node(:, k) - self%mv0(:, k))/t2
         end do
      else
         t_new = t1
         residual(1:3) = residual(1:3) - self%end_a%applied_force3(t1)
         residual(3*n - 2:3*n) = residual(3*n - 2:3*n) - self%end_b%applied_force3(t1)
         rate = 0
      end if
      ! Ends that depend on their own state (springs): their force, and its derivative.
      state_a = self%end_a%state_dependent()
      state_b = self%end_b%state_dependent()
      if (state_a) call end_state(self%end_a, self%r0(:, 1), r(:, 1), residual(1:3), jac_a)
      if (state_b) call end_state(self%end_b, self%r0(:, n), r(:, n), residual(3*n - 2:3*n), jac_b)
      residual = residual*scale
      ! Twist rows (quasi-static, at the new time): dU/dpsi_k minus the applied torques.
      if (allocated(self%cell_gip)) then
         do c = 1, n - 1
            tau = (psi(c + 1) - psi(c))/self%ds(c)
            residual(3*n + c) = residual(3*n + c) - self%cell_gip(c)*tau*twist_scale
            residual(3*n + c + 1) = residual(3*n + c + 1) + self%cell_gip(c)*tau*twist_scale
         end do
      else
         do c = 1, n - 1
            tau = (psi(c + 1) - psi(c))/self%ds(c)
            residual(3*n + c) = residual(3*n + c) - self%gip*tau*twist_scale
            residual(3*n + c + 1) = residual(3*n + c + 1) + self%gip*tau*twist_scale
         end do
      end if
      residual(3*n + 1) = residual(3*n + 1) + self%end_a%applied_torque(t_new)*twist_scale
      residual(4*n) = residual(4*n) - self%end_b%applied_torque(t_new)*twist_scale
      if (anchor_a .and. held_a) residual(3*n + 1) = psi(1)
      if (anchor_a .and. .not. held_a) residual(3*n + 1) = psi(1) - self%psi_anchor
      if (anchor_b) residual(4*n) = psi(n)
      if (self%keep_rows(1)) self%kept_residual(:, 1) = residual(1:3)
      if (self%keep_rows(2)) self%kept_residual(:, 2) = residual(3*n - 2:3*n)
      if (held_a) residual(1:3) = (r(:, 1) - self%end_a%position3(t_new))/self%length_ref
      if (held_b) residual(3*n - 2:3*n) = (r(:, n) - self%end_b%position3(t_new))/self%length_ref
      if (.not. with_jacobian) return

      jacobian%ab = 0
      jacobian%factorised = .false.
      band0 = jacobian%kl + jacobian%ku + 1
      call add_position_blocks(n, size(jacobian%ab, 1), size(jacobian%ab, 2), jacobian%ab, band0, self%block, self%ds, &
                               self%mass, self%load_block, scale, rate, skip_a, skip_b, dynamic, has_loads(self), &
                               self%skew_block, self%skewed)
      if (allocated(self%cell_gip)) then
         do c = 1, n - 1
            call add_twist(3*n + c, 3*n + c, self%cell_gip(c)/self%ds(c)*twist_scale)
            call add_twist(3*n + c, 3*n + c + 1, -self%cell_gip(c)/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c, -self%cell_gip(c)/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c + 1, self%cell_gip(c)/self%ds(c)*twist_scale)
         end do
      else
         do c = 1, n - 1
            call add_twist(3*n + c, 3*n + c, self%gip/self%ds(c)*twist_scale)
            call add_twist(3*n + c, 3*n + c + 1, -self%gip/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c, -self%gip/self%ds(c)*twist_scale)
            call add_twist(3*n + c + 1, 3*n + c + 1, self%gip/self%ds(c)*twist_scale)
         end do
      end if
      do b = 1, 3
         do a = 1, 3
            if (state_a) call add_twist(a, b, -jac_a(a, b)*scale)
            if (state_b) call add_twist(3*(n - 1) + a, 3*(n - 1) + b, -jac_b(a, b)*scale)
         end do
      end do
      ! Bodies at nodes: their drag's derivative (its force is in load_node).
      if (allocated(self%points)) then
         do c = 1, size(self%points)
            k = self%point_node(c)
            if ((k == 1 .and. skip_a) .or. (k == n .and. skip_b)) cycle
            do b = 1, 3
               do a = 1, 3
                  call add_twist(3*(k - 1) + a, 3*(k - 1) + b, -self%point_jac(a, b, c)*scale)
               end do
            end do
         end do
      end if
      if (self%keep_rows(1)) call keep_jacobian(1, 1)
      if (self%keep_rows(2)) call keep_jacobian(2, n)
      if (anchor_a) call set_row(3*n + 1, [3*n + 1], [1.0_dp])
      if (anchor_b) call set_row(4*n, [4*n], [1.0_dp])
      if (held_a) then
         do a = 1, 3
            call set_row(a, [a], [1/self%length_ref])
         end do
      end if
      if (held_b) then
         do a = 1, 3
            call set_row(3*(n - 1) + a, [3*(n - 1) + a], [1/self%length_ref])
         end do
      end if

   contains

      !> A state-dependent end's force taken from its node's rows (statics: at rest at x1, time t1;
      !> a step: from x0 over t2), and its derivative with respect to x1.
      subroutine end_state(end, x0, x1, rows, jac)
         class(end_condition), intent(in) :: end
         real(dp), intent(in) :: x0(3), x1(3)
         real(dp), intent(inout) :: rows(3)
         real(dp), intent(out) :: jac(3, 3)
         real(dp) :: f(3), dv(3, 3), damp(3)
         if (dynamic) then
            call end%step_force(t1, t2, x0, x1, f, jac, damp)
         else
            call end%state_force(t1, x1, [0.0_dp, 0.0_dp, 0.0_dp], f, jac, dv, damp)
         end if
         rows = rows - f
      end subroutine end_state

      !> Copy the momentum rows of end node k (side 1: end a, 2: end b) out of the band: the
      !> columns of the positions of the end node and of its two neighbours.
      subroutine keep_jacobian(side, k)
         integer, intent(in) :: side, k
         integer :: first, a, j, rr, cc
         first = max(1, merge(1, 3*k - 8, side == 1))
         self%kept_first(side) = first
         self%kept_jac(:, :, side) = 0
         do j = 1, 9
            cc = first - 1 + j
            if (cc > 3*n) exit
            do a = 1, 3
               rr = 3*(k - 1) + a
               self%kept_jac(a, j, side) = jacobian%ab(band0 + rr - cc, cc)
            end do
         end do
      end subroutine keep_jacobian

      !> Adds value to the entry (rr, cc) of the band.
      subroutine add_twist(rr, cc, value)
         integer, intent(in) :: rr, cc
         real(dp), intent(in) :: value
         jacobian%ab(band0 + rr - cc, cc) = jacobian%ab(band0 + rr - cc, cc) + value
      end subroutine add_twist

      !> Replace row rr by the given entries.
      subroutine set_row(rr, cols, values)
         integer, intent(in) :: rr, cols(:)
         real(dp), intent(in) :: values(:)
         integer :: cc, ii
         do cc = max(1, rr - jacobian%kl), min(size(x), rr + jacobian%ku)
            jacobian%ab(band0 + rr - cc, cc) = 0
         end do
         do ii = 1, size(cols)
            jacobian%ab(band0 + rr - cols(ii), cols(ii)) = values(ii)
         end do
      end subroutine set_row

      !> The Jacobian's position blocks (cells, inertia, distributed loads) in band storage ab, as
      !> explicit-shape arrays (a class argument's allocatable components cost several times the
      !> instructions in these loops, docs/measurements/data/speed_rounds.md item 4); the same sums in the same order.
      pure subroutine add_position_blocks(n, ld, ncol, ab, band0, block, ds, mass, load_block, scale, rate, held_a, held_b, &
                                          dynamic, loads, skew_block, skewed)
         integer, intent(in) :: n, ld, ncol, band0
         real(dp), intent(inout) :: ab(ld, ncol)
         real(dp), intent(in) :: block(3, 3, -1:1, n - 1), ds(n - 1), mass(0:2, n), load_block(3, 3, 0:1, n - 1)
         real(dp), intent(in) :: scale, rate
         logical, intent(in) :: held_a, held_b, dynamic, loads
         !> The unequal shares' blocks (cable_load cell_skew) and whether there are any.
         real(dp), intent(in) :: skew_block(3, 3, 0:1, n - 1)
         logical, intent(in) :: skewed
         integer :: c, cp, side, node, j, k, a, b, row, col
         real(dp) :: sgn, t(3, 3), share
         ! Cell c's force N_c enters node c with - and node c+1 with +; e_cp = (R_cp+1 - R_cp) / ds_cp.
         ! Each block is scaled once: (+-1 / ds) scale block = +-((1 / ds) scale block), the same bits.
         do c = 1, n - 1
            do cp = max(1, c - 1), min(n - 1, c + 1)
               sgn = 1.0_dp/ds(cp)*scale
               do b = 1, 3
                  do a = 1, 3
                     t(a, b) = sgn*block(a, b, cp - c, c)
                  end do
               end do
               do side = 0, 1
                  node = cp + side
                  do j = 0, 1
                     k = c + j
                     if (k == 1 .and. held_a) cycle
                     if (k == n .and. held_b) cycle
                     if (side == j) then
                        do b = 1, 3
                           col = 3*(node - 1) + b
                           do a = 1, 3
                              row = 3*(k - 1) + a
                              ab(band0 + row - col, col) = ab(band0 + row - col, col) + t(a, b)
                           end do
                        end do
                     else
                        do b = 1, 3
                           col = 3*(node - 1) + b
                           do a = 1, 3
                              row = 3*(k - 1) + a
                              ab(band0 + row - col, col) = ab(band0 + row - col, col) - t(a, b)
                           end do
                        end do
                     end if
                  end do
               end do
            end do
         end do
         if (dynamic) then
            do k = 1, n
               if (k == 1 .and. held_a) cycle
               if (k == n .and. held_b) cycle
               do a = 1, 3
                  row = 3*(k - 1) + a
                  do j = -2, 2
                     node = k + j
                     if (node < 1 .or. node > n) cycle
                     col = row + 3*j
                     ab(band0 + row - col, col) = ab(band0 + row - col, col) + mass(abs(j), min(k, node))*rate*scale
                  end do
               end do
            end do
         end if
         if (loads) then
            ! Node c and node c+1 each get -F_c / 2 (and -G_c, +G_c of unequal shares).
            do c = 1, n - 1
               do side = 0, 1
                  node = c + side
                  do j = 0, 1
                     k = c + j
                     if (k == 1 .and. held_a) cycle
                     if (k == n .and. held_b) cycle
                     do a = 1, 3
                        row = 3*(k - 1) + a
                        do b = 1, 3
                           col = 3*(node - 1) + b
                           share = 0.5_dp*load_block(a, b, side, c)
                           if (skewed) share = share + merge(1.0_dp, -1.0_dp, j == 0)*skew_block(a, b, side, c)
                           ab(band0 + row - col, col) = ab(band0 + row - col, col) - share*scale
                        end do
                     end do
                  end do
               end do
            end do
         end if
      end subroutine add_position_blocks

      !> Whether the piece has distributed loads.
      pure logical function has_loads(self)
         class(rod3d_piece), intent(in) :: self
         has_loads = .false.
         if (allocated(self%loads)) has_loads = size(self%loads) > 0
      end function has_loads
   end subroutine rod3d_assemble
end submodule xcable_model_rod3d_assembly
