!> A surface z(x, y) given on a rectangular grid of heights, as flat triangular facets: each
!> grid cell [x_i, x_i+1] x [y_j, y_j+1] is cut along its diagonal from (x_i, y_j) to
!> (x_i+1, y_j+1) into two triangles, each the plane through its three corners. The surface
!> is continuous, and a facet is an exact plane (its normal is constant on it). Outside the
!> grid it is continued flat from its edge (the height of the nearest edge point), as
!> MoorDyn does with its bathymetry. A grid of one point in x (or y) is a surface that does not
!> vary along x (or y).
!>
!> The seabed takes the facet under the middle of each cell (loads/seabed.f90).
module xcable_numerics_facets
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: facet_at

contains

   !> The plane of the facet under the horizontal point (px, py): z = z0 + sx (x - px) +
   !> sy (y - py) near it, z0 the surface's height at the point.
   pure subroutine facet_at(gx, gy, gz, px, py, z0, sx, sy)
      !> Grid lines along x and y (increasing), m; heights gz(size(gx), size(gy)), m.
      real(dp), intent(in) :: gx(:), gy(:), gz(:, :)
      !> The point, m.
      real(dp), intent(in) :: px, py
      !> Height at the point (m) and the facet's slopes dz/dx, dz/dy.
      real(dp), intent(out) :: z0, sx, sy
      real(dp) :: u, v, hx, hy, z00, z10, z01, z11, qx, qy
      integer :: i, j
      logical :: out_x, out_y
      call cell_of(gx, px, i, u, hx, qx, out_x)
      call cell_of(gy, py, j, v, hy, qy, out_y)
      z00 = gz(i, j)
      z10 = gz(min(i + 1, size(gx)), j)
      z01 = gz(i, min(j + 1, size(gy)))
      z11 = gz(min(i + 1, size(gx)), min(j + 1, size(gy)))
      if (u >= v) then
         ! The triangle (0, 0), (1, 0), (1, 1).
         z0 = z00 + (z10 - z00)*u + (z11 - z10)*v
         sx = (z10 - z00)/hx
         sy = (z11 - z10)/hy
      else
         ! The triangle (0, 0), (0, 1), (1, 1).
         z0 = z00 + (z11 - z01)*u + (z01 - z00)*v
         sx = (z11 - z01)/hx
         sy = (z01 - z00)/hy
      end if
      ! Flat beyond the grid, and along an axis of one grid line.
      if (out_x .or. size(gx) == 1) sx = 0
      if (out_y .or. size(gy) == 1) sy = 0
   end subroutine facet_at

   !> The grid cell i of the coordinate p on the lines g, the local coordinate u in [0, 1], the
   !> cell's width h, and whether p lies beyond the grid (then u is that of the nearest edge).
   pure subroutine cell_of(g, p, i, u, h, q, outside)
      real(dp), intent(in) :: g(:), p
      integer, intent(out) :: i
      real(dp), intent(out) :: u, h, q
      logical, intent(out) :: outside
      integer :: lo, hi, mid
      outside = p < g(1) .or. p > g(size(g))
      q = min(max(p, g(1)), g(size(g)))
      if (size(g) == 1) then
         i = 1
         u = 0
         h = 1
         return
      end if
      lo = 1
      hi = size(g)
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (q >= g(mid)) then
            lo = mid
         else
            hi = mid
         end if
      end do
      i = lo
      h = g(i + 1) - g(i)
      u = (q - g(i))/h
   end subroutine cell_of
end module xcable_numerics_facets
