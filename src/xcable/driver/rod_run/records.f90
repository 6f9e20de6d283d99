!> The records of a rod run: the fields on the output nodes, the history (one record per
!> accepted step), the snapshots (interpolated within the step), a turned run's results turned
!> back (the summary with its warnings is the driver's, driver/summary.f90).
!> (A submodule of driver/rod_run.f90.)
submodule (xcable_driver_rod_run) xcable_driver_rod_run_records
   use xcable_driver_history, only: hermite_levels, open_history
   implicit none

contains

   !> The history of a run turned into x-z (plane_azimuth), turned back into the scene's frame:
   !> x, vx and force_x of each end and record, and their y components (ends_y).
   module subroutine turn_back_history(self)
      type(rod_run), intent(inout) :: self
      real(dp) :: c, s
      c = cos(self%plane_azimuth)
      s = sin(self%plane_azimuth)
      associate (h => self%history)
         if (allocated(h%ends_y)) deallocate (h%ends_y)
         allocate (h%ends_y(n_end_quantities_y, size(h%ends, 2), lbound(h%ends, 3):ubound(h%ends, 3)))
         ! ends: x, z, vx, vz, tension, force_x, force_z; ends_y: y, vy, force_y.
         h%ends_y(1, :, :) = self%plane_pivot(2) + s*(h%ends(1, :, :) - self%plane_pivot(1))
         h%ends_y(2, :, :) = s*h%ends(3, :, :)
         h%ends_y(3, :, :) = s*h%ends(6, :, :)
         h%ends(1, :, :) = self%plane_pivot(1) + c*(h%ends(1, :, :) - self%plane_pivot(1))
         h%ends(3, :, :) = c*h%ends(3, :, :)
         h%ends(6, :, :) = c*h%ends(6, :, :)
      end associate
   end subroutine turn_back_history

   !> The fields of a run turned into x-z (plane_azimuth) in the scene's frame: the x column
   !> turned back (in place), and the fields of field3_names from it and the columns' velocities
   !> v (2, n_out): y and vy; the plan-view curvature, twist, binormal shear and curvature about
   !> n are zero in a vertical plane.
   module subroutine turned_back(self, fields, v, extra)
      type(rod_run), intent(in) :: self
      real(dp), intent(inout) :: fields(:, :)
      real(dp), intent(in) :: v(:, :)
      real(dp), intent(out) :: extra(:, :)
      real(dp) :: c, s, u(size(fields, 1))
      c = cos(self%plane_azimuth)
      s = sin(self%plane_azimuth)
      ! fields: tension shear strain u v x z curvature; extra: y vy curvature_z twist binormal_shear curvature_n.
      u = fields(:, 6) - self%plane_pivot(1)
      fields(:, 6) = self%plane_pivot(1) + c*u
      extra = 0
      extra(:, 1) = self%plane_pivot(2) + s*u
      extra(:, 2) = s*v(1, :)
   end subroutine turned_back

   !> The velocities of the pieces' nodes on the output columns (2, n_out); before a break
   !> inside the cable the break node fills both of its columns (as in run_fields).
   module function column_velocities(self) result(v)
      type(rod_run), intent(in) :: self
      real(dp), allocatable :: v(:, :)
      integer :: p
      allocate (v(2, self%n_out))
      v = 0
      do p = 1, size(self%pieces)
         v(:, self%pieces(p)%column) = self%pieces(p)%v
      end do
      if (size(self%pieces) == 1 .and. self%break_node > 0) v(:, self%break_node + 1) = v(:, self%break_node)
   end function column_velocities

   !> Time of snapshot i (i >= 1); huge when there is none.
   pure real(dp) module function snapshot_time(self, i)
      type(rod_run), intent(in) :: self
      integer, intent(in) :: i
      if (self%options%interval > 0) then
         snapshot_time = i*self%options%interval
         if (snapshot_time > self%options%t_end*(1 + 1.0e-9_dp)) snapshot_time = huge(1.0_dp)
      else
         snapshot_time = merge(self%options%t_end, huge(1.0_dp), i == 1)
      end if
   end function snapshot_time

   !> End labels and slots, and the supports' forces of the static state (the history's
   !> record of t = 0 follows: driver/stepping.f90).
   module subroutine start_history(self)
      type(rod_run), intent(inout) :: self
      call open_history(self, 16, .false.)
      self%pieces(1)%end_slot = [1, 2]
      self%pieces(1)%reaction(:, 1) = self%static%reaction_a
      self%pieces(1)%reaction(:, 2) = self%static%reaction_b
   end subroutine start_history

   !> The planar model's part of history record i at run%t (the driver keeps the history,
   !> driver/history.f90): the ends (position, velocity, tension, the force on the cable: the
   !> support's at a held end, the applied one at a loaded end), the loads' measures, the
   !> ledger's terms.
   module subroutine planar_record(self, run, i, ends, ends_y, measures, energies, stored, work)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      integer, intent(in) :: i
      real(dp), intent(inout) :: ends(:, :), ends_y(:, :), measures(:)
      real(dp), intent(inout) :: energies(4), stored, work(3)
      integer :: p, side, node, slot
      real(dp) :: en(4), e(2), f(2), ten
      en = 0
      do p = 1, size(run%pieces)
         associate (run_piece => run%pieces(p), piece => run%pieces(p)%problem%piece)
            do side = 1, 2
               slot = run_piece%end_slot(side)
               if (slot == 0) cycle
               node = merge(1, piece%n, side == 1)
               ten = end_tension(piece, run_piece%r, side)
               if (side == 1) then
                  if (piece%end_a%held()) then
                     f = run_piece%reaction(:, 1)
                  else
                     f = piece%end_a%applied_force(run%t)
                     if (piece%end_a%state_dependent()) f = f + state_force(piece%end_a, node)
                  end if
               else
                  if (piece%end_b%held()) then
                     f = run_piece%reaction(:, 2)
                  else
                     f = piece%end_b%applied_force(run%t)
                     if (piece%end_b%state_dependent()) f = f + state_force(piece%end_b, node)
                  end if
               end if
               ends(:, slot) = [run_piece%r(:, node), run_piece%v(:, node), ten, f]
            end do
            if (run%options%energy) then
               call piece%complete_memo()
               call piece%geometry(run_piece%r, piece%e1, piece%l1, piece%th1)
               en = en + piece%energies(run_piece%r, run_piece%v, piece%l1, piece%th1)
            end if
         end associate
      end do
      ! Before a break inside the cable, its two ends are the break node: the
      ! pull of the cable on either side (mean tension of the node's two cells).
      if (size(run%pieces) == 1 .and. run%break_node > 0) then
         associate (r => run%pieces(1)%r, v => run%pieces(1)%v, k => run%break_node, &
                    piece => run%pieces(1)%problem%piece)
            e = r(:, k + 1) - r(:, k)
            f = piece%cell_tension(k, norm2(e)/piece%ds(k) - 1)*e/norm2(e)
            ten = 0.5_dp*(norm2(f) + piece%cell_tension(k - 1, norm2(r(:, k) - r(:, k - 1))/piece%ds(k - 1) - 1))
            ends(:, 3) = [r(:, k), v(:, k), ten, f]
            e = r(:, k) - r(:, k - 1)
            f = -piece%cell_tension(k - 1, norm2(e)/piece%ds(k - 1) - 1)*e/norm2(e)
            ends(:, 4) = [r(:, k), v(:, k), ten, f]
         end associate
      end if
      if (size(measures) > 0) then
         measures = 0
         do p = 1, size(run%pieces)
            associate (piece => run%pieces(p)%problem%piece)
               call load_measures(run%scene%loads, run%pieces(p)%r, piece%ds, measures, piece%s)
            end associate
         end do
      end if
      if (run%options%energy) then
         energies = en
         stored = sum(en)
         work = [run%work, run%load_work, run%dissipation]
      end if

   contains

      !> The force of a state-dependent end's own state at its node (x, z), N.
      function state_force(end, node) result(force)
         class(end_condition), intent(in) :: end
         integer, intent(in) :: node
         real(dp) :: force(2), f3(3), dx(3, 3), dv(3, 3), damp(3)
         associate (run_piece => run%pieces(p))
            call end%state_force(run%t, [run_piece%r(1, node), 0.0_dp, run_piece%r(2, node)], &
                                 [run_piece%v(1, node), 0.0_dp, run_piece%v(2, node)], f3, dx, dv, damp)
         end associate
         force = f3([1, 3])
      end function state_force
   end subroutine planar_record

   !> Tension at an end of a piece (side 1: node 1, side 2: node n), from its
   !> end cells by end_value, and not below the law's tension at the strain
   !> -0.99 (a steep, buckled end would extrapolate past what the law can give).
   function end_tension(piece, r, side) result(t_end)
      type(rod_piece), intent(in) :: piece
      real(dp), intent(in) :: r(:, :)
      integer, intent(in) :: side
      real(dp) :: t_end, cells(3)
      integer :: n, j, c
      n = piece%n
      do j = 1, min(3, n - 1)
         c = merge(j, n - j, side == 1)
         cells(j) = piece%cell_tension(c, norm2(r(:, c + 1) - r(:, c))/piece%ds(c) - 1)
      end do
      t_end = max(end_value(cells(1:min(3, n - 1)), 1), piece%cell_tension(merge(1, n - 1, side == 1), -0.99_dp))
   end function end_tension

   !> Fields at time ts inside the step just accepted (from self%t to the new level): the driver's
   !> cubic Hermite in the positions and velocities of its two ends (hermite_levels).
   subroutine interpolated_fields(self, ts, fields, velocities)
      type(rod_run), intent(inout) :: self
      real(dp), intent(in) :: ts
      real(dp), intent(out) :: fields(:, :)
      !> The interpolated velocities on the output columns (2, n_out).
      real(dp), allocatable, intent(out), optional :: velocities(:, :)
      real(dp), allocatable :: r(:, :), v(:, :), rp_r(:, :), rp_v(:, :)
      real(dp) :: h
      integer :: p
      allocate (r(2, self%n_out), v(2, self%n_out))
      do p = 1, size(self%pieces)
         associate (rp => self%pieces(p))
            h = rp%problem%dt
            allocate (rp_r(2, size(rp%column)), rp_v(2, size(rp%column)))
            call hermite_levels((ts - self%t)/h, h, rp%r_prev, rp%v_prev, rp%r, rp%v, rp_r, rp_v)
            r(:, rp%column) = rp_r
            v(:, rp%column) = rp_v
            deallocate (rp_r, rp_v)
         end associate
      end do
      call self%fields(fields, r, v)
      if (present(velocities)) then
         if (size(self%pieces) == 1 .and. self%break_node > 0) v(:, self%break_node + 1) = v(:, self%break_node)
         call move_alloc(v, velocities)
      end if
   end subroutine interpolated_fields

   !> The planar model's end in history slot j at the end of the run: its kind ('fixed',
   !> 'motion', ..., 'break') and whether it is held ('' and not held: no end in that slot).
   module subroutine planar_end_info(self, run, j, kind, held)
      class(planar_model), intent(in) :: self
      type(rod_run), intent(in) :: run
      integer, intent(in) :: j
      character(:), allocatable, intent(out) :: kind
      logical, intent(out) :: held
      integer :: p
      kind = ''
      held = .false.
      do p = 1, size(run%pieces)
         if (run%pieces(p)%end_slot(1) == j) then
            kind = run%pieces(p)%problem%piece%end_a%kind()
            held = run%pieces(p)%problem%piece%end_a%held()
         end if
         if (run%pieces(p)%end_slot(2) == j) then
            kind = run%pieces(p)%problem%piece%end_b%kind()
            held = run%pieces(p)%problem%piece%end_b%held()
         end if
      end do
   end subroutine planar_end_info
   !> The planar model's start: the history's labels and its record of t = 0, and the static
   !> state with its snapshot to the observer (turned back into the scene's frame for a scene
   !> run turned into x-z, with the fields of a 3-D run).
   module subroutine planar_begin(self, run, observer, error)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      class(run_observer), intent(inout), optional :: observer
      type(error_type), allocatable, intent(out) :: error
      type(static_info) :: turned
      call start_history(run)
      if (.not. present(observer)) return
      if (run%plane_azimuth /= 0) then
         turned = run%info
         allocate (turned%extra(run%n_out, n_fields3))
         call turned_back(run, turned%fields, column_velocities(run), turned%extra)
         call observer%static(turned, error)
         if (allocated(error)) return
         call observer%snapshot(0.0_dp, turned%fields, error)
         if (allocated(error)) return
         call observer%snapshot_extra(0.0_dp, field3_names, turned%extra, error)
      else
         call observer%static(run%info, error)
         if (allocated(error)) return
         call observer%snapshot(0.0_dp, run%info%fields, error)
      end if
   end subroutine planar_begin

   !> The planar model's snapshot at ts: the static state's fields (static) or those interpolated
   !> inside the step just accepted (interpolated_fields); for a scene run turned into x-z, turned
   !> back into the scene's frame with the fields of a 3-D run (turned_back).
   module subroutine planar_snapshot(self, run, t_new, ts, static, fields, extra, with_extra)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      real(dp), intent(in) :: t_new, ts
      logical, intent(in) :: static
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      logical, intent(out) :: with_extra
      real(dp), allocatable :: v(:, :)
      if (static) then
         fields = run%info%fields
         if (run%plane_azimuth /= 0) v = column_velocities(run)
      else
         call interpolated_fields(run, ts, fields, v)
      end if
      with_extra = run%plane_azimuth /= 0
      if (with_extra) call turned_back(run, fields, v, extra)
   end subroutine planar_snapshot

   !> The planar model after the summary: the history of a scene run turned into x-z turned back
   !> into the scene's frame (the summary was made from the turned one).
   module subroutine planar_conclude(self, run)
      class(planar_model), intent(inout) :: self
      type(rod_run), intent(inout) :: run
      if (run%plane_azimuth /= 0) call turn_back_history(run)
   end subroutine planar_conclude

   !> Fields on the output nodes from the current state of the pieces: cell
   !> values (tension, strain, shear) at a node are the mean of its cells
   !> (one cell at an end); u, v along the node tangent (the mean direction of
   !> its cells) and the paper's normal n = -perp(t); curvature is the paper's
   !> Omega3 = -theta_k / h_k (0 at the ends).
   module subroutine run_fields(self, fields, positions, velocities)
      !> Run.
      class(rod_run), intent(inout) :: self
      !> Fields (n_out, n_fields) in the order of field_names.
      real(dp), intent(out) :: fields(:, :)
      !> Positions and velocities per piece (2, n_out): if given, used instead of the pieces' current state.
      real(dp), intent(in), optional :: positions(:, :), velocities(:, :)
      integer :: p, k, n, col
      real(dp), allocatable :: ten(:), eps(:), shear(:), mom(:), r(:, :), v(:, :)
      real(dp) :: tk(2), nk(2), e(2)
      do p = 1, size(self%pieces)
         associate (piece => self%pieces(p)%problem%piece, cols => self%pieces(p)%column)
            n = piece%n
            allocate (ten(n - 1), eps(n - 1), shear(n - 1), mom(n), r(2, n), v(2, n))
            if (present(positions)) then
               r = positions(:, cols)
               v = velocities(:, cols)
            else
               r = self%pieces(p)%r
               v = self%pieces(p)%v
            end if
            call piece%cell_fields(r, ten, eps, shear, mom, v)
            do k = 1, n
               col = cols(k)
               if (k == 1) then
                  fields(col, 1) = max(end_value(ten, 1), piece%cell_tension(1, -0.99_dp))
                  fields(col, 2) = end_value(shear, 1)
                  fields(col, 3) = max(end_value(eps, 1), -0.99_dp)
                  e = r(:, 2) - r(:, 1)
               else if (k == n) then
                  fields(col, 1) = max(end_value(ten, 2), piece%cell_tension(n - 1, -0.99_dp))
                  fields(col, 2) = end_value(shear, 2)
                  fields(col, 3) = max(end_value(eps, 2), -0.99_dp)
                  e = r(:, n) - r(:, n - 1)
               else
                  fields(col, 1) = 0.5_dp*(ten(k - 1) + ten(k))
                  fields(col, 2) = 0.5_dp*(shear(k - 1) + shear(k))
                  fields(col, 3) = 0.5_dp*(eps(k - 1) + eps(k))
                  e = (r(:, k + 1) - r(:, k))/norm2(r(:, k + 1) - r(:, k)) + (r(:, k) - r(:, k - 1))/norm2(r(:, k) - r(:, k - 1))
               end if
               tk = e/max(norm2(e), tiny(1.0_dp))
               nk = -perp(tk)
               fields(col, 4) = dot_product(v(:, k), tk)
               fields(col, 5) = dot_product(v(:, k), nk)
               fields(col, 6) = r(1, k)
               fields(col, 7) = r(2, k)
               fields(col, 8) = 0
               if (k > 1 .and. k < n) fields(col, 8) = -bend_curvature(piece, k, piece%th1(k))
            end do
            ! Before a break inside the cable the break node fills both of its columns.
            if (size(self%pieces) == 1 .and. self%break_node > 0) fields(self%break_node + 1, :) = fields(self%break_node, :)
            deallocate (ten, eps, shear, mom, r, v)
         end associate
      end do
   end subroutine run_fields

   !> Value at an end node (side 1: node 1, side 2: node n) of a cell field:
   !> the end cell's value extrapolated half a cell along the slope c1 - c2
   !> of the two end cells (second order), unless the three end cells
   !> zig-zag (c1 - c2 and c2 - c3 of opposite signs: a buckle at the grid
   !> scale), where the extrapolation would overshoot and the end cell's own
   !> value is used.
   pure real(dp) module function end_value(cells, side)
      !> Cell values.
      real(dp), intent(in) :: cells(:)
      !> 1 or 2.
      integer, intent(in) :: side
      integer :: m
      real(dp) :: c1, c2, c3
      m = size(cells)
      if (m < 3) then
         end_value = merge(cells(1), cells(m), side == 1)
         return
      end if
      if (side == 1) then
         c1 = cells(1); c2 = cells(2); c3 = cells(3)
      else
         c1 = cells(m); c2 = cells(m - 1); c3 = cells(m - 2)
      end if
      if ((c1 - c2)*(c2 - c3) < 0) then
         end_value = c1
      else
         end_value = c1 + 0.5_dp*(c1 - c2)
      end if
   end function end_value

end submodule xcable_driver_rod_run_records
