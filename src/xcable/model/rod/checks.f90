!> Whether Newton may trust its contraction estimate on a planar piece: not when the update may
!> have carried a cell past the kink of a rope's law. (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_checks
   use xcable_material_tension_only, only: may_cross_kink
   implicit none

contains

   !> Newton's contraction estimate (newton_problem) after the update from the last evaluated
   !> point: trusted unless it may have carried a cell past the kink of the law by more than
   !> the tolerance (may_cross_kink) (the cells
   !> whose strains the evaluation computed from the unknowns: a window's lo - 1 .. hi).
   module function rod_problem_estimate_trusted(self, update, tolerance) result(trusted)
      !> Problem.
      class(rod_problem), intent(in) :: self
      !> The update, 2 per node of the window (all nodes when there is none), m.
      real(dp), intent(in) :: update(:)
      !> Tolerance on the scaled update (scale: length_ref).
      real(dp), intent(in) :: tolerance
      logical :: trusted
      real(dp) :: du(rod_nodal, self%piece%n)
      integer :: lo, hi, ca, cb
      integer :: j, a, b
      trusted = .true.
      if (.not. self%piece%has_kink()) return
      lo = 1
      hi = self%piece%n
      if (windowed(self)) then
         lo = self%lo
         hi = self%hi
      end if
      ca = max(1, lo - 1)
      cb = min(self%piece%n - 1, hi)
      du(:, ca:cb + 1) = 0
      du(:, lo:hi) = reshape(update, [rod_nodal, hi - lo + 1])
      if (.not. allocated(self%piece%sections)) then
         trusted = .not. may_cross_kink(self%piece%law%strain_slack, self%piece%l1(ca:cb), self%piece%ds(ca:cb), &
                                        du(:, ca:cb + 1), tolerance*self%piece%length_ref)
         return
      end if
      do j = 1, size(self%piece%sections)
         a = max(ca, self%piece%sections(j)%first)
         b = min(cb, self%piece%sections(j)%last)
         if (a > b) cycle
         if (.not. self%piece%sections(j)%law%strain_slack > -huge(1.0_dp)) cycle
         if (may_cross_kink(self%piece%sections(j)%law%strain_slack, self%piece%l1(a:b), self%piece%ds(a:b), &
                            du(:, a:b + 1), tolerance*self%piece%length_ref)) trusted = .false.
      end do
   end function rod_problem_estimate_trusted

   !> Whether the law of any cell has a kink (strain_slack: a rope that cannot push).
   module pure function rod_has_kink(self) result(kink)
      !> Piece.
      class(rod_piece), intent(in) :: self
      logical :: kink
      integer :: j
      kink = self%law%strain_slack > -huge(1.0_dp)
      if (.not. allocated(self%sections)) return
      do j = 1, size(self%sections)
         if (self%sections(j)%law%strain_slack > -huge(1.0_dp)) kink = .true.
      end do
   end function rod_has_kink
end submodule xcable_model_rod_checks
