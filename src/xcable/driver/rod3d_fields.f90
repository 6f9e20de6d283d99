!> The output fields of a 3-D rod state (model/rod3d.f90) on its nodes: the
!> planar fields of field_names (driver/records.f90) and the 3-D ones of
!> field3_names, for the snapshots and the static state of a 3-D run
!> (driver/rod3d_drive.f90).
!>
!> Directions are those of the cells' material frames (t, n, b) of
!> rod3d_piece%frames (right-handed, t x n = b; a cell along x has (x, -z, y),
!> carried by parallel transport and turned by the twist), so that a planar
!> scene gives the planar run's fields: n is then the paper's normal and b = y.
!> With the curvature vector kappa = t x dt/ds (per unstretched length; at
!> node k the discrete 2 tan(th_k / 2) / h_k along e_k-1 x e_k) and the
!> bending moment M = dB/dth along the same direction (N m):
!>
!>   - curvature   = kappa . b = Omega3 (the paper's: negative for a sagging line)
!>   - curvature_n = kappa . n = Omega2
!>   - shear       = Sn = F . n, binormal_shear = Sb = F . b, the shear force
!>     of the moment balance dM/dS + t x F = 0 (S the stretched arc length):
!>     F_perp = t x dM/dS per cell, so Sn = -(dM/dS) . b and Sb = (dM/dS) . n;
!>     without twist (no torque) Sn = -EI dOmega3/ds / (1 + eps) and
!>     Sb = EI dOmega2/ds / (1 + eps) to the order of the scheme.
!>   - curvature_z = kappa . z, the turning of the tangent seen in plan.
!>
!> At an interior node the curvature components are the means of the
!> projections on its two cells' frames (the same when no twist separates
!> them); shear, tension and strain are cell values averaged (ends
!> extrapolated, as in the planar run); u and v are the velocity along the
!> node tangent and along the mean of its cells' n made normal to it.
module xcable_driver_rod3d_fields
   use xcable_core_kinds, only: dp
   use xcable_numerics_vector3, only: cross3
   use xcable_material_tension_only, only: damped_tension
   use xcable_driver_rod_run, only: end_value
   use xcable_model_rod3d, only: rod3d_piece
   use xcable_driver_records, only: n_fields3, field3_names
   implicit none
   private
   public :: fields3, frame_axes, n_fields3, field3_names

contains

   !> Fields on the nodes of a one-piece 3-D state (unknowns x, velocities v):
   !> the planar fields in the order of field_names and the extra ones of
   !> field3_names (see the module's comment for their definitions).
   subroutine fields3(piece, x, v, fields, extra)
      !> Piece.
      type(rod3d_piece), intent(in) :: piece
      !> Unknowns (positions node after node, then the twist angles) and velocities (3, n).
      real(dp), intent(in) :: x(:), v(:, :)
      !> Planar fields (n, n_fields) and 3-D fields (n, n_fields3).
      real(dp), intent(out) :: fields(:, :), extra(:, :)
      real(dp) :: r(3, piece%n), e(3, piece%n - 1), l(piece%n - 1), th(piece%n), ten(piece%n - 1), &
                  eps(piece%n - 1), sn(piece%n - 1), sb(piece%n - 1), mom(3, piece%n), kap(3, piece%n), &
                  tau(piece%n - 1), nc(3, piece%n - 1), bc(3, piece%n - 1), c(3), tk(3), nk(3), dm(3), a, t2
      integer :: n, k, j
      n = piece%n
      r = reshape(x(1:3*n), [3, n])
      call piece%geometry(r, e, l, th)
      call frame_axes(piece, x, nc, bc)
      kap = 0
      mom = 0
      do k = 2, n - 1
         c = cross3(e(:, k - 1), e(:, k))
         a = norm2(c)
         if (a > 0) then
            c = c/a
            t2 = tan(0.5_dp*th(k))
            kap(:, k) = 2*t2/piece%dual_length(k)*c
            ! The moment dB/dth = 2 EI t (1 + t^2) / h along the curvature vector.
            mom(:, k) = 2*piece%ei_at(k)*t2*(1 + t2*t2)/piece%dual_length(k)*c
         end if
      end do
      do j = 1, n - 1
         eps(j) = l(j) - 1
         if (allocated(piece%sections)) then
            ! A line of segments: the cell's own law and damping.
            associate (sec => piece%sections(piece%cell_sec(j)))
               ten(j) = sec%law%tension(eps(j))
               if (sec%damping > 0) ten(j) = damped_tension(sec%law, eps(j), ten(j), &
                                                            sec%damping*dot_product(e(:, j), v(:, j + 1) - v(:, j))/ &
                                                            (piece%ds(j)*l(j)))
            end associate
         else
            ten(j) = piece%law%tension(eps(j))
            if (piece%damping > 0) ten(j) = damped_tension(piece%law, eps(j), ten(j), &
                                                           piece%damping*dot_product(e(:, j), v(:, j + 1) - v(:, j))/ &
                                                           (piece%ds(j)*l(j)))
         end if
         dm = (mom(:, j + 1) - mom(:, j))/(piece%ds(j)*l(j))
         sn(j) = -dot_product(dm, bc(:, j))
         sb(j) = dot_product(dm, nc(:, j))
      end do
      tau = piece%twist_rates(x)
      do k = 1, n
         if (k == 1) then
            fields(k, 1) = max(end_value(ten, 1), piece%cell_tension(1, -0.99_dp))
            fields(k, 2) = end_value(sn, 1)
            fields(k, 3) = max(end_value(eps, 1), -0.99_dp)
            extra(k, 5) = end_value(sb, 1)
            tk = r(:, 2) - r(:, 1)
            nk = nc(:, 1)
            extra(k, 4) = tau(1)
         else if (k == n) then
            fields(k, 1) = max(end_value(ten, 2), piece%cell_tension(n - 1, -0.99_dp))
            fields(k, 2) = end_value(sn, 2)
            fields(k, 3) = max(end_value(eps, 2), -0.99_dp)
            extra(k, 5) = end_value(sb, 2)
            tk = r(:, n) - r(:, n - 1)
            nk = nc(:, n - 1)
            extra(k, 4) = tau(n - 1)
         else
            fields(k, 1) = 0.5_dp*(ten(k - 1) + ten(k))
            fields(k, 2) = 0.5_dp*(sn(k - 1) + sn(k))
            fields(k, 3) = 0.5_dp*(eps(k - 1) + eps(k))
            extra(k, 5) = 0.5_dp*(sb(k - 1) + sb(k))
            tk = (r(:, k + 1) - r(:, k))/norm2(r(:, k + 1) - r(:, k)) + (r(:, k) - r(:, k - 1))/norm2(r(:, k) - r(:, k - 1))
            nk = nc(:, k - 1) + nc(:, k)
            extra(k, 4) = 0.5_dp*(tau(k - 1) + tau(k))
         end if
         tk = tk/max(norm2(tk), tiny(1.0_dp))
         nk = nk - dot_product(nk, tk)*tk
         nk = nk/max(norm2(nk), tiny(1.0_dp))
         fields(k, 4) = dot_product(v(:, k), tk)
         fields(k, 5) = dot_product(v(:, k), nk)
         fields(k, 6) = r(1, k)
         fields(k, 7) = r(3, k)
         fields(k, 8) = 0
         extra(k, 6) = 0
         if (k > 1 .and. k < n) then
            fields(k, 8) = 0.5_dp*dot_product(kap(:, k), bc(:, k - 1) + bc(:, k))
            extra(k, 6) = 0.5_dp*dot_product(kap(:, k), nc(:, k - 1) + nc(:, k))
         end if
         extra(k, 1) = r(2, k)
         extra(k, 2) = v(2, k)
         extra(k, 3) = kap(3, k)
      end do
   end subroutine fields3

   !> The normal n and binormal b of each cell's material frame (frames()),
   !> in fixed components (3, n - 1).
   pure subroutine frame_axes(piece, x, normal, binormal)
      !> Piece.
      type(rod3d_piece), intent(in) :: piece
      !> Unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      !> n and b of each cell.
      real(dp), intent(out) :: normal(:, :), binormal(:, :)
      real(dp) :: beta(4, piece%n - 1)
      integer :: j
      call piece%frames(x, beta)
      do j = 1, piece%n - 1
         normal(:, j) = rotated(beta(:, j), [0.0_dp, 1.0_dp, 0.0_dp])
         binormal(:, j) = rotated(beta(:, j), [0.0_dp, 0.0_dp, 1.0_dp])
      end do
   end subroutine frame_axes

   !> The vector u turned by the unit quaternion q = [q0, q_vec]:
   !> u + 2 q0 (q_vec x u) + 2 q_vec x (q_vec x u).
   pure function rotated(q, u) result(w)
      real(dp), intent(in) :: q(4), u(3)
      real(dp) :: w(3), c(3)
      c = cross3(q(2:4), u)
      w = u + 2*q(1)*c + 2*cross3(q(2:4), c)
   end function rotated
end module xcable_driver_rod3d_fields
