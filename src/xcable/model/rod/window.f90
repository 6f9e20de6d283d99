!> A step of a planar piece solved on a window of its nodes (the skip of the quiescent cable,
!> driver/rod_run): the evaluation of the window's rows, the same operations as the whole
!> step's on each value (its rows: assemble_window, model/rod/assembly.f90), and the level the
!> nodes outside the window keep (rod_freeze_level). (A submodule of model/rod.f90.)
submodule (xcable_model_rod) xcable_model_rod_window
   implicit none

contains

   !> rod_step_system on the window of nodes lo .. hi (2 < hi - lo + 1 < n; no distributed
   !> loads): x holds the new positions of the window's nodes; the others stay at the
   !> old level (rod_freeze_level). The residual rows and the unknowns (Jacobian
   !> columns) are the window's; the cells and nodes whose terms enter them are computed
   !> (cells lo - 2 .. hi + 1 for the geometry, nodes lo - 1 .. hi + 1 for the moments,
   !> cells lo - 1 .. hi for the forces), and so are the end cells and end velocities a
   !> reaction needs. The operations on each value are those of rod_step_system.
   module subroutine step_window(self, x, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)
      type(rod_piece), intent(inout) :: self
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: lo, hi
      real(dp), intent(in) :: t0, dt, theta
      real(dp), intent(out) :: residual(:)
      type(band_matrix), intent(inout) :: jacobian
      logical, intent(in) :: with_jacobian
      integer :: n, ga, gb, ca, cb
      n = self%n
      self%memo_x(2*lo - 1:2*hi) = x
      ga = max(1, lo - 2)
      gb = min(n - 1, hi + 1)
      call geometry_cells(n, self%ds, self%memo_x, self%e1, self%l1, self%th1, ga, gb)
      self%memo_e(:, ga:gb) = self%e1(:, ga:gb)
      self%memo_l(ga:gb) = self%l1(ga:gb)
      self%memo_th(ga + 1:gb) = self%th1(ga + 1:gb)
      call bend_nodes(self, max(2, lo - 1), min(n - 1, hi + 1))
      ca = max(1, lo - 1)
      cb = min(n - 1, hi)
      ! The end cells for the reactions (rod_reaction), when outside.
      if (ca > 1) then
         call bend_nodes(self, 2, 2)
         call window_cells(1, 1)
      end if
      if (cb < n - 1) then
         call bend_nodes(self, n - 1, n - 1)
         call window_cells(n - 1, n - 1)
      end if
      call window_cells(ca, cb)
      self%memo_valid = .true.
      ! No loads on a window: load_node holds the zeros of init (apply_loads).
      call assemble_window(self, lo, hi, t0, dt, theta, residual, jacobian, with_jacobian)

   contains

      subroutine window_cells(c1, c2)
         integer, intent(in) :: c1, c2
         call section_cell_terms(self, t0, dt, with_jacobian, c1, c2)
      end subroutine window_cells
   end subroutine step_window
   !> Before a step solved on a window of nodes (rod_problem lo, hi): the new level's
   !> geometry and the memo of the last evaluation are set to the old level's, which is
   !> what the nodes outside the window keep (their new positions are their old ones, so
   !> these are the values an evaluation would compute for them, the same bits); the
   !> window's evaluations then overwrite their own part.
   module subroutine rod_freeze_level(self)
      class(rod_piece), intent(inout) :: self
      integer :: n
      n = self%n
      call copy_geometry(n, self%e0, self%l0, self%th0, self%e1, self%l1, self%th1)
      call copy_values(2*n, self%r0, self%memo_x)
      call copy_geometry(n, self%e0, self%l0, self%th0, self%memo_e, self%memo_l, self%memo_th)
      call copy_values(n, self%b0, self%memo_b)
      self%memo_b_ok = .true.
      ! atan2(e0 x e0, e0 . e0) = 0: a cell that keeps its positions does not rotate.
      self%memo_dphi = 0
      self%memo_valid = .true.
   end subroutine rod_freeze_level
end submodule xcable_model_rod_window
