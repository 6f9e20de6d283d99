!> The step's checks of a 3-D piece: whether Newton may trust its contraction estimate (no cell
!> carried past the kink of a rope's law) and the fold check of the step control in 3-D.
!> (A submodule of model/rod3d.f90.)
submodule (xcable_model_rod3d) xcable_model_rod3d_checks
   use xcable_material_tension_only, only: may_cross_kink
   implicit none

contains

   !> Newton's contraction estimate (newton_problem) after the update from the last evaluated
   !> point: trusted unless it may have carried a cell past the kink of the law by more than
   !> the tolerance (may_cross_kink).
   module function rod3d_problem_estimate_trusted(self, update, tolerance) result(trusted)
      !> Problem.
      class(rod3d_problem), intent(in) :: self
      !> The update: 3 positions per node, then the twists, m and rad.
      real(dp), intent(in) :: update(:)
      !> Tolerance on the scaled update (scale of the positions: length_ref).
      real(dp), intent(in) :: tolerance
      logical :: trusted
      real(dp), allocatable :: du(:, :)
      integer :: j, a, b
      trusted = .true.
      if (.not. allocated(self%piece%sections)) then
         if (.not. self%piece%law%strain_slack > -huge(1.0_dp)) return
         trusted = .not. may_cross_kink(self%piece%law%strain_slack, self%piece%l1, self%piece%ds, &
                                        reshape(update(1:3*self%piece%n), [3, self%piece%n]), &
                                        tolerance*self%piece%length_ref)
         return
      end if
      ! A line of segments: each section whose law has a kink, on its own cells.
      if (.not. self%piece%has_kink()) return
      du = reshape(update(1:3*self%piece%n), [3, self%piece%n])
      do j = 1, size(self%piece%sections)
         a = self%piece%sections(j)%first
         b = self%piece%sections(j)%last
         if (.not. self%piece%sections(j)%law%strain_slack > -huge(1.0_dp)) cycle
         if (may_cross_kink(self%piece%sections(j)%law%strain_slack, self%piece%l1(a:b), self%piece%ds(a:b), &
                            du(:, a:b + 1), tolerance*self%piece%length_ref)) trusted = .false.
      end do
   end function rod3d_problem_estimate_trusted

   !> Whether the law of any cell has a kink (strain_slack: a rope that cannot push).
   module pure function rod3d_has_kink(self) result(kink)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      logical :: kink
      integer :: j
      kink = self%law%strain_slack > -huge(1.0_dp)
      if (.not. allocated(self%sections)) return
      do j = 1, size(self%sections)
         if (self%sections(j)%law%strain_slack > -huge(1.0_dp)) kink = .true.
      end do
   end function rod3d_has_kink

   !> The fold check of the step control (driver/rod_run.f90, check_folds) in
   !> 3-D: for each interior node k, |phi(e1_k-1, e1_k) - phi(e0_k-1, e0_k) -
   !> (rho_k - rho_k-1)|, with phi the rotation vector of the node's turning
   !> and rho_c that of cell c from the old level (prepare_step) to the
   !> positions r1. In a plane it is the planar rod's |th1 - th0 - (dphi_b -
   !> dphi_a)|: 0 to round-off, or about 2 pi when the angle went through half
   !> a turn. Out of the plane it is first order in the cells' rotations (a
   !> rotation omega of both cells adds |omega x phi|, at most pi |omega|,
   !> and near th = pi the axis of phi swings fast): it passes 3 rad when a
   !> turning angle goes through or close around half a turn, or a sharp bend
   !> turns by about 1 rad out of its plane in one step.
   module pure subroutine rod3d_turning_folds(self, r1, fold)
      !> Piece (holds the old level).
      class(rod3d_piece), intent(in) :: self
      !> New positions (3, n), m.
      real(dp), intent(in) :: r1(:, :)
      !> Mismatch at each node (n; 0 at the ends), rad.
      real(dp), intent(out) :: fold(:)
      real(dp) :: e1(3, self%n - 1), rho(3, self%n - 1)
      integer :: c, k
      do c = 1, self%n - 1
         e1(:, c) = r1(:, c + 1) - r1(:, c)
         rho(:, c) = rotation(self%e0(:, c), e1(:, c))
      end do
      fold = 0
      do k = 2, self%n - 1
         fold(k) = norm2(rotation(e1(:, k - 1), e1(:, k)) - rotation(self%e0(:, k - 1), self%e0(:, k)) - &
                         (rho(:, k) - rho(:, k - 1)))
      end do

   contains

      !> The rotation vector phi(a, b) (rotation_vector).
      pure function rotation(a, b) result(phi)
         real(dp), intent(in) :: a(3), b(3)
         real(dp) :: phi(3)
         call rotation_vector(a, b, phi)
      end function rotation
   end subroutine rod3d_turning_folds
end submodule xcable_model_rod3d_checks
