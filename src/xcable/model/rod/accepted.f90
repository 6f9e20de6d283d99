!> The accepted state of a step of a planar piece: what the evaluation at the converged
!> positions leaves that the records, the checks and the next step need, without the residual
!> Newton would evaluate there (newton_options%final_residual). (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_accepted
   implicit none

contains

   !> The evaluation of a step at its converged positions x (the window's unknowns when the
   !> problem has a window, as for evaluate), in place of the full residual Newton would
   !> evaluate there (newton_options%final_residual): step_state.
   module subroutine rod_problem_accepted_state(self, x)
      !> Problem (a step: dt > 0).
      class(rod_problem), intent(inout) :: self
      !> Positions, 2 per node of the window (all nodes when there is none).
      real(dp), intent(in) :: x(:)
      if (windowed(self)) then
         call step_state(self%piece, x, self%lo, self%hi, self%t0, self%dt, self%theta)
      else
         call step_state(self%piece, x, 1, self%piece%n, self%t0, self%dt, self%theta)
      end if
   end subroutine rod_problem_accepted_state

   !> What a step's evaluation at its converged positions leaves that the accepted state
   !> needs, computed by the same expressions as rod_step_system and step_window (so the
   !> same bits), without the residual: the new level's geometry e1, l1, th1; the memo
   !> (positions, geometry, the bending energy of every node whose turning angle is
   !> evaluated, each cell's rotation dphi) for check_state, the next prepare_step and the
   !> ledger; the forces of the two end cells, the end nodes' new velocities and the
   !> distributed loads for rod_reaction and the ledger's work. The other cells' forces and
   !> blocks, the other nodes' moments and velocities and the residual are not computed
   !> (they stay those of the last evaluation). Window lo .. hi (1 .. n: the whole piece);
   !> x holds the new positions of its nodes. On fast_180kN (241 nodes) it takes about
   !> 101 000 instructions, the residual alone it replaces about 235 000 (docs/measurements/data/speed_rounds.md).
   subroutine step_state(self, x, lo, hi, t0, dt, theta)
      type(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: lo, hi
      real(dp), intent(in) :: t0, dt, theta
      integer :: n, ga, gb, ca, cb, k, k1, k2, kk, a
      n = self%n
      if (lo == 1 .and. hi == n) then
         call geometry_of(n, self%ds, x, self%e1, self%l1, self%th1)
         call copy_values(2*n, x, self%memo_x)
         call copy_geometry(n, self%e1, self%l1, self%th1, self%memo_e, self%memo_l, self%memo_th)
         self%memo_b_ok = .false.
         k1 = 2
         k2 = n - 1
         ca = 1
         cb = n - 1
      else
         self%memo_x(2*lo - 1:2*hi) = x
         ga = max(1, lo - 2)
         gb = min(n - 1, hi + 1)
         call geometry_cells(n, self%ds, self%memo_x, self%e1, self%l1, self%th1, ga, gb)
         self%memo_e(:, ga:gb) = self%e1(:, ga:gb)
         self%memo_l(ga:gb) = self%l1(ga:gb)
         self%memo_th(ga + 1:gb) = self%th1(ga + 1:gb)
         k1 = max(2, lo - 1)
         k2 = min(n - 1, hi + 1)
         ca = max(1, lo - 1)
         cb = min(n - 1, hi)
      end if
      ! The bending terms of the evaluated nodes, as a step evaluation computes them: the
      ! end cells' forces need the moments of nodes 2 and n - 1, the next step's old level
      ! the bending energies. (bend_divided's B(th1), not B computed by a separate loop:
      ! gfortran vectorises a plain loop over tan with glibc's libmvec, whose tan differs
      ! from libm's in the last bits.)
      call bend_nodes(self, k1, k2)
      if (k1 > 2) call bend_nodes(self, 2, 2)
      if (k2 < n - 1) call bend_nodes(self, n - 1, n - 1)
      call section_cell_terms(self, t0, dt, .false., 1, 1)
      if (n > 2) call section_cell_terms(self, t0, dt, .false., n - 1, n - 1)
      ! Each cell's rotation, as cell_terms computes it.
      call cell_rotations_of(n, self%e0, self%e1, self%memo_dphi, ca, cb)
      self%memo_valid = .true.
      ! (A window has no loads: load_node holds the zeros of init, apply_loads.)
      if (lo == 1 .and. hi == n) call apply_loads(self, x, dt, theta, .false.)
      ! The new velocities a reaction needs (nodes 1 .. 3 and n - 2 .. n).
      do k = 1, n
         if (k > 3 .and. k < n - 2) cycle
         do a = 1, 2
            kk = 2*k - 2 + a
            self%v1(a, k) = ((self%memo_x(kk) - self%r0(a, k))/dt - (1 - theta)*self%v0(a, k))/theta
         end do
      end do
   end subroutine step_state
end submodule xcable_model_rod_accepted
