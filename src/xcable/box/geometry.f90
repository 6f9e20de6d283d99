!> Kinematic quantities derived from the unknowns: tangent, position and
!> velocity in the fixed frame (x horizontal = j component, z vertical = i
!> component, i points up).
module xcable_box_geometry
   use xcable_core_kinds, only: dp
   use xcable_box_equations, only: n_eq, i_eps, i_u, i_v, i_b0, i_b3
   implicit none
   private
   public :: positions, fixed_frame_velocity

contains

   !> Positions by the trapezoid rule on dR/ds = (1 + eps) t from the fixed
   !> end at the origin (consistent with the box scheme).
   pure subroutine positions(y, s, x, z)
      !> Unknowns (7, nodes).
      real(dp), intent(in) :: y(:, :)
      !> Unstretched arc length of the nodes, m.
      real(dp), intent(in) :: s(:)
      !> Horizontal position (j component), m.
      real(dp), intent(out) :: x(:)
      !> Vertical position (i component, up), m.
      real(dp), intent(out) :: z(:)
      real(dp) :: tx, tz, tx_prev, tz_prev
      integer :: k
      ! Node by node, without work arrays (called at every step for the energy ledger).
      x(1) = 0
      z(1) = 0
      tz_prev = (1 + y(i_eps, 1))*(y(i_b0, 1)**2 - y(i_b3, 1)**2)
      tx_prev = (1 + y(i_eps, 1))*2*y(i_b0, 1)*y(i_b3, 1)
      do k = 2, size(s)
         tz = (1 + y(i_eps, k))*(y(i_b0, k)**2 - y(i_b3, k)**2)
         tx = (1 + y(i_eps, k))*2*y(i_b0, k)*y(i_b3, k)
         x(k) = x(k - 1) + 0.5_dp*(s(k) - s(k - 1))*(tx + tx_prev)
         z(k) = z(k - 1) + 0.5_dp*(s(k) - s(k - 1))*(tz + tz_prev)
         tx_prev = tx
         tz_prev = tz
      end do
   end subroutine positions

   !> Velocity u t + v n of one node in the fixed frame.
   pure subroutine fixed_frame_velocity(y, vel_x, vel_z)
      !> Unknowns at the node (7).
      real(dp), intent(in) :: y(n_eq)
      !> Horizontal (j) component, m/s.
      real(dp), intent(out) :: vel_x
      !> Vertical (i) component, m/s.
      real(dp), intent(out) :: vel_z
      real(dp) :: c2, s2
      c2 = y(i_b0)**2 - y(i_b3)**2
      s2 = 2*y(i_b0)*y(i_b3)
      vel_z = y(i_u)*c2 - y(i_v)*s2
      vel_x = y(i_u)*s2 + y(i_v)*c2
   end subroutine fixed_frame_velocity
end module xcable_box_geometry
