!> The break of a 3-D run: the forces, couples and torques the new ends start from (split), and
!> the pieces after it (release: the released end replaced, or the piece cut in two at the break
!> node; also the pieces of a broken run loaded from a checkpoint). (A submodule of
!> driver/rod3d_drive.f90.)
submodule (xcable_driver_rod3d_drive) xcable_driver_rod3d_drive_break
   use xcable_model_rod3d, only: bend_moment3 => bend_moment, bend_energy3 => bend_energy
   use xcable_numerics_vector3, only: cross3
   use xcable_solver_banded, only: band_matrix
   use xcable_ends_force, only: force_end
   implicit none

contains

   !> The break. At a held end: the end lets go with the support's force.
   !> Inside the cable: the new ends start from the forces of the cells at
   !> the break node on either side (with half the weight of each one's
   !> cell, as the planar run), the node's bending couple about its axis and
   !> the twist moment; the node's bending energy leaves with the cut, booked
   !> as work of the ends. All are ramped to zero over t_break.
   module subroutine split(self, rod, error)
      type(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: rod
      !> Error when a piece cannot be set up.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: res(:)
      real(dp) :: axis(3), tau(rod%options%nodes - 1)
      type(band_matrix) :: unused
      integer :: kb, p
      self%broken = .true.
      rod%broken = .true.
      if (rod%break_node == 0) then
         self%cut_force(:, 1) = self%pieces(1)%reaction(:, merge(2, 1, rod%scene%break_at_b))
         call release(self, rod, error)
         return
      end if
      kb = rod%break_node
      associate (run => self%pieces(1)%run, piece => self%pieces(1)%run%problem%piece)
         allocate (res(size(run%x)))
         call piece%static_system(run%x, rod%t, res, unused, .false.)
         self%cut_force(:, 1) = piece%force(:, kb - 1) + [0.0_dp, 0.0_dp, 0.5_dp*cell_weight(piece, kb - 1)*piece%ds(kb - 1)]
         self%cut_force(:, 2) = -piece%force(:, kb) + [0.0_dp, 0.0_dp, 0.5_dp*cell_weight(piece, kb)*piece%ds(kb)]
         ! The couple about the normal of the node's cells (none on a straight node: axis -y).
         axis = cross3(piece%e1(:, kb - 1), piece%e1(:, kb))
         if (norm2(axis) > 0) then
            axis = axis/norm2(axis)
            self%cut_couple(1) = bend_moment3(piece, kb, piece%th1(kb))
         else
            axis = [0.0_dp, -1.0_dp, 0.0_dp]
            self%cut_couple(1) = 0
         end if
         self%cut_couple(2) = -self%cut_couple(1)
         self%cut_axis(:, 1) = axis
         self%cut_axis(:, 2) = axis
         tau = piece%twist_rates(run%x)
         self%cut_torque = [piece%gip_at(kb - 1)*tau(kb - 1), piece%gip_at(kb)*tau(kb)]
         run%end_work = run%end_work - bend_energy3(piece, kb, piece%th1(kb))
      end associate
      call release(self, rod, error)
      if (allocated(error)) return
      ! Distributed loads: each new end node keeps its own cell's share (the pieces' loads at rest).
      if (.not. allocated(self%pieces(1)%run%problem%piece%loads)) return
      do p = 1, 2
         associate (run => self%pieces(p)%run, piece => self%pieces(p)%run%problem%piece)
            res = run%x
            call piece%static_system(run%x, rod%t, res, unused, .false.)
            self%cut_force(:, p) = self%cut_force(:, p) - piece%load_node(:, merge(piece%n, 1, p == 1))
         end associate
      end do
      call set_cut_force(self%pieces(1)%run%problem%piece%end_b, self%cut_force(:, 1))
      call set_cut_force(self%pieces(2)%run%problem%piece%end_a, self%cut_force(:, 2))
   end subroutine split

   !> Weight per length of cell c, N/m (a line of segments: its section's).
   pure real(dp) function cell_weight(piece, c)
      type(rod3d_piece), intent(in) :: piece
      integer, intent(in) :: c
      if (allocated(piece%sections)) then
         cell_weight = piece%sections(piece%cell_sec(c))%weight
      else
         cell_weight = piece%weight
      end if
   end function cell_weight

   !> The starting force of a cut end (a force_end) set to f (x, y, z).
   subroutine set_cut_force(end, f)
      class(end_condition), intent(inout) :: end
      real(dp), intent(in) :: f(3)
      select type (end)
      type is (force_end)
         end%force0 = f([1, 3])
         end%force0_y = f(2)
      end select
   end subroutine set_cut_force

   !> The pieces after the break, with new ends that start from cut_force,
   !> cut_couple, cut_axis and cut_torque, ramped to zero over t_break: the
   !> released end replaced; or the piece cut in two at
   !> the break node, each new piece taking the positions, twist angles,
   !> velocities, output columns, history slots and reactions of its nodes,
   !> the first the ledger so far. Also rebuilds the pieces of a broken run
   !> loaded from a checkpoint.
   module subroutine release(self, rod, error)
      type(rod3d_drive), intent(inout) :: self
      type(rod_run), intent(inout) :: rod
      !> Error when a piece cannot be set up.
      type(error_type), allocatable, intent(out) :: error
      type(force_end) :: cut, cut_b
      type(piece3), allocatable :: old(:)
      real(dp) :: f(3)
      integer :: n, kb, p, first(2), last(2)
      f = self%cut_force(:, 1)
      cut = force_end(kind_name='break', history='ramp', t0=rod%scene%break_time, duration=rod%scene%t_break, &
                      force0=[f(1), f(3)], force0_y=f(2))
      if (rod%break_node == 0) then
         associate (piece => self%pieces(1)%run%problem%piece)
            if (rod%scene%break_at_b) then
               cut%label = 'end_b'
               deallocate (piece%end_b)
               allocate (piece%end_b, source=cut)
            else
               cut%label = 'end_a'
               deallocate (piece%end_a)
               allocate (piece%end_a, source=cut)
            end if
         end associate
         self%pieces(1)%run%work%usable = .false.
         return
      end if
      cut%label = 'break_a'
      cut%couple0 = self%cut_couple(1)
      cut%axis = self%cut_axis(:, 1)
      cut%torque0 = self%cut_torque(1)
      f = self%cut_force(:, 2)
      cut_b = force_end(kind_name='break', history='ramp', t0=rod%scene%break_time, duration=rod%scene%t_break, &
                        force0=[f(1), f(3)], force0_y=f(2), couple0=self%cut_couple(2), torque0=self%cut_torque(2))
      cut_b%axis = self%cut_axis(:, 2)
      cut_b%label = 'break_b'
      kb = rod%break_node
      n = rod%options%nodes
      first = [1, kb]
      last = [kb, n]
      call move_alloc(self%pieces, old)
      allocate (self%pieces(2))
      associate (whole => old(1)%run%problem%piece, x => old(1)%run%x)
         do p = 1, 2
            associate (run => self%pieces(p)%run, piece => self%pieces(p)%run%problem%piece)
               if (p == 1) then
                  call piece%init(rod%s(1:kb), whole%mass_per_length, whole%weight, whole%ei, whole%gip, whole%gravity, &
                                  whole%mu, whole%law, whole%end_a, cut, whole%tension_ref, error, whole%mu2, &
                                  whole%damping)
               else
                  call piece%init(rod%s(kb:n), whole%mass_per_length, whole%weight, whole%ei, whole%gip, whole%gravity, &
                                  whole%mu, whole%law, cut_b, whole%end_b, whole%tension_ref, error, whole%mu2, &
                                  whole%damping)
               end if
               if (allocated(error)) return
               ! A line of segments: each piece its sections (the laws of the whole).
               call piece_sections3(piece, rod%scene)
               if (allocated(whole%loads)) piece%loads = whole%loads
               piece%load_factor = whole%load_factor
               call run%init(old(1)%run%options%tolerance)
               run%options = old(1)%run%options
               run%x = [x(3*first(p) - 2:3*last(p)), x(3*n + first(p):3*n + last(p))]
               ! A piece no end of which holds the twist keeps its first node's angle (no rigid spin).
               piece%psi_anchor = x(3*n + first(p))
               run%v = old(1)%run%v(:, first(p):last(p))
               run%t = old(1)%run%t
            end associate
         end do
      end associate
      ! The ledger so far goes on with the first piece.
      associate (run => self%pieces(1)%run, before => old(1)%run)
         run%energy0 = before%energy0
         run%end_work = before%end_work
         run%load_work = before%load_work
         run%dissipated = before%dissipated
         run%iterations = before%iterations
      end associate
      self%pieces(1)%column = old(1)%column(1:kb)
      self%pieces(1)%end_slot = [1, 3]
      self%pieces(1)%reaction(:, 1) = old(1)%reaction(:, 1)
      self%pieces(2)%column = [kb + 1, old(1)%column(kb + 1:n)]
      self%pieces(2)%end_slot = [4, 2]
      self%pieces(2)%reaction(:, 2) = old(1)%reaction(:, 2)
   end subroutine release
end submodule xcable_driver_rod3d_drive_break
