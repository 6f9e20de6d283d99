!> The material frames of a 3-D piece's cells as unit quaternions (rod3d_frames), the paper's Euler
!> parameters of a frame (paper_euler_parameters) and the quaternion helpers they use.
!> (A submodule of model/rod3d.f90.)
submodule (xcable_model_rod3d) xcable_model_rod3d_frames
   implicit none

contains

   !> Material frames of the cells of x as unit quaternions (4, n - 1), [beta0, beta1, beta2, beta3]:
   !> the rotation of the fixed frame (x, y, z) onto (t, n, b) of each cell. The frame of a
   !> cell along x is (x, -z, y), the paper's convention (n the in-plane normal, down for a
   !> horizontal cable, b out of the plane along y). It is turned about z onto the vertical
   !> plane of the first cell, carried to the first cell and on from cell to cell by the
   !> smallest rotations between tangents, then turned by the cell's mean psi about t; so a
   !> line in any vertical plane has n in that plane and b along its normal.
   !> paper_euler_parameters gives the paper's parameters.
   module pure subroutine rod3d_frames(self, x, beta)
      !> Piece.
      class(rod3d_piece), intent(in) :: self
      !> Unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      !> Quaternions (4, n - 1).
      real(dp), intent(out) :: beta(:, :)
      real(dp) :: r(3, self%n), psi(self%n), e(3, self%n - 1), l(self%n - 1), th(self%n), q(4), prev(3), angle
      real(dp) :: h(2), azimuth
      integer :: c
      call rod3d_unpack(x, r, psi)
      call self%geometry(r, e, l, th)
      ! The base frame: a quarter turn about x, (x, y, z) onto (x, -z, y), then turned about z
      ! onto the vertical plane of the first cell, h = its horizontal direction with h_x >= 0
      ! (so that b is that plane's normal and n lies in it; an x-z scene keeps (x, -z, y)
      ! exactly). A vertical first cell keeps the x-z plane.
      prev = [1.0_dp, 0.0_dp, 0.0_dp]
      q = [sqrt(0.5_dp), -sqrt(0.5_dp), 0.0_dp, 0.0_dp]
      h = [e(1, 1), e(2, 1)]
      if (h(1) < 0 .or. (h(1) == 0 .and. h(2) < 0)) h = -h
      if (h(2) /= 0 .and. norm2(h) > 1.0e-6_dp*l(1)) then
         azimuth = atan2(h(2), h(1))
         prev = [cos(azimuth), sin(azimuth), 0.0_dp]
         q = quaternion_product([cos(0.5_dp*azimuth), 0.0_dp, 0.0_dp, sin(0.5_dp*azimuth)], q)
      end if
      do c = 1, self%n - 1
         q = quaternion_product(minimal_rotation(prev, e(:, c)/l(c)), q)
         prev = e(:, c)/l(c)
         angle = 0.25_dp*(psi(c) + psi(c + 1))
         beta(:, c) = quaternion_product(q, [cos(angle), sin(angle), 0.0_dp, 0.0_dp])
      end do
   end subroutine rod3d_frames

   !> The paper's Euler parameters of a frame given as frames() gives it: the rotation of the
   !> paper's fixed frame (i up, j horizontal, k = i x j, that is (z, x, y)) onto (t, n, b),
   !> in components along i, j, k. In a planar state beta1 = beta2 = 0 and
   !> t = (beta0^2 - beta3^2) i + 2 beta0 beta3 j, as in eqs. 18-21.
   module pure function paper_euler_parameters(beta) result(b)
      !> Quaternion of frames() (rotation of (x, y, z) onto (t, n, b)).
      real(dp), intent(in) :: beta(4)
      real(dp) :: b(4), r(4)
      ! Compose with the rotation taking (z, x, y) onto (x, y, z) (a third of a turn about (1, 1, 1)).
      r = quaternion_product(beta, [0.5_dp, 0.5_dp, 0.5_dp, 0.5_dp])
      b = [r(1), r(4), r(2), r(3)]
   end function paper_euler_parameters

   !> The unit quaternion of the smallest rotation taking unit vector u to unit vector v
   !> (half a turn about z when v = -u is along x, about an axis normal to u otherwise).
   pure function minimal_rotation(u, v) result(q)
      real(dp), intent(in) :: u(3), v(3)
      real(dp) :: q(4), w(3), axis(3)
      w = [u(2)*v(3) - u(3)*v(2), u(3)*v(1) - u(1)*v(3), u(1)*v(2) - u(2)*v(1)]
      q = [1 + dot_product(u, v), w]
      if (q(1) < 1.0e-12_dp) then
         axis = [-u(2), u(1), 0.0_dp]
         if (norm2(axis) < 1.0e-6_dp) axis = [0.0_dp, -u(3), u(2)]
         q = [0.0_dp, axis/norm2(axis)]
      else
         q = q/norm2(q)
      end if
   end function minimal_rotation

   !> Quaternion product p q.
   pure function quaternion_product(p, q) result(r)
      real(dp), intent(in) :: p(4), q(4)
      real(dp) :: r(4)
      r(1) = p(1)*q(1) - dot_product(p(2:4), q(2:4))
      r(2:4) = p(1)*q(2:4) + q(1)*p(2:4) + [p(3)*q(4) - p(4)*q(3), p(4)*q(2) - p(2)*q(4), p(2)*q(3) - p(3)*q(2)]
   end function quaternion_product
end submodule xcable_model_rod3d_frames
