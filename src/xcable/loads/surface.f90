!> The water's surface: how much of a straight cell lies under it.
!>
!> A still-water level z = level. A cross-section of the cable at height z is
!> wet in the proportion
!>
!>     g(z) = clamp(1/2 + (level - z) / band, 0, 1)
!>
!> going from dry to wet over a band of height `band` centred on the level
!> (the rope's own diameter by default: a horizontal rope lying in the surface
!> is half under water), and g = 1 below the level, 0 above it, when band = 0.
!> The wetted fraction of a straight cell whose ends are at heights z1 and z2 is
!> the mean of g along it,
!>
!>     phi(z1, z2) = 1/(z2 - z1) int_z1^z2 g(z) dz      (g((z1 + z2)/2) when z1 = z2),
!>
!> which is the exact fraction of the cell under the level whenever neither end
!> lies inside the band (g is odd about the level inside the band, so its
!> integral across the whole band is that of the step). phi is continuous in the
!> two heights, with continuous first derivatives for band > 0: a cell that
!> crosses the surface, a node that crosses it and a horizontal cell lying in it
!> all give forces without a jump, and Newton sees their derivatives.
!>
!> A sea state (waves) replaces the flat level by the instantaneous level at the
!> cell and supplies the water's kinematics at a point; everything else here
!> stays as it is.
module xcable_loads_surface
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: water_surface

   !> A still-water level.
   type :: water_surface
      !> Height of the level, m (z up).
      real(dp) :: level = 0
      !> Height of the band over which a cross-section goes from dry to wet, m (0: a step).
      real(dp) :: band = 0
   contains
      !> Wet proportion g(z) of a cross-section at height z.
      procedure :: wet => surface_wet
      !> Wetted fraction of a straight cell and its derivatives with respect to its ends' heights.
      procedure :: wetted_fraction => surface_wetted_fraction
   end type water_surface

   !> Below this fraction of the band, a cell's height difference counts as zero
   !> (phi = g of its middle): the divided difference would lose digits.
   real(dp), parameter :: flat_cell = 1.0e-9_dp

contains

   !> g(z): 1 under the band, 0 above it, linear in between.
   elemental real(dp) function surface_wet(self, z)
      !> The surface.
      class(water_surface), intent(in) :: self
      !> Height, m.
      real(dp), intent(in) :: z
      if (self%band > 0) then
         surface_wet = min(1.0_dp, max(0.0_dp, 0.5_dp + (self%level - z)/self%band))
      else if (z < self%level) then
         surface_wet = 1
      else if (z > self%level) then
         surface_wet = 0
      else
         surface_wet = 0.5_dp
      end if
   end function surface_wet

   !> dg/dz at z (-1/band inside the band, else 0; on a band edge, the side of the band's inside
   !> when inside is true).
   pure real(dp) function wet_slope(self, z)
      class(water_surface), intent(in) :: self
      real(dp), intent(in) :: z
      wet_slope = 0
      if (self%band > 0) then
         if (abs(z - self%level) < 0.5_dp*self%band) wet_slope = -1/self%band
      end if
   end function wet_slope

   !> The wetted fraction phi of a straight cell with its ends at heights z1 and z2, and
   !> dphi/dz1, dphi/dz2.
   pure subroutine surface_wetted_fraction(self, z1, z2, phi, dphi_dz1, dphi_dz2)
      !> The surface.
      class(water_surface), intent(in) :: self
      !> Heights of the cell's ends, m.
      real(dp), intent(in) :: z1, z2
      !> Wetted fraction (0 to 1) and its derivatives, 1/m.
      real(dp), intent(out) :: phi, dphi_dz1, dphi_dz2
      real(dp) :: lo, hi, h, bottom, top, a, b, wet_length, slope
      lo = min(z1, z2)
      hi = max(z1, z2)
      bottom = self%level - 0.5_dp*self%band
      top = self%level + 0.5_dp*self%band
      dphi_dz1 = 0
      dphi_dz2 = 0
      ! All under the band, or all above it.
      if (hi < bottom .or. (self%band > 0 .and. hi == bottom)) then
         phi = 1
         return
      end if
      if (lo > top .or. (self%band > 0 .and. lo == top)) then
         phi = 0
         return
      end if
      h = hi - lo
      if (h <= flat_cell*max(self%band, tiny(1.0_dp))) then
         ! A flat cell: g of its middle, each end moving the middle by half.
         phi = self%wet(0.5_dp*(lo + hi))
         slope = 0.5_dp*wet_slope(self, 0.5_dp*(lo + hi))
         dphi_dz1 = slope
         dphi_dz2 = slope
         return
      end if
      ! int_lo^hi g: the part under the band (g = 1), and the part inside it (g linear: its
      ! length times g of its middle).
      wet_length = max(0.0_dp, min(hi, bottom) - lo)
      a = max(lo, bottom)
      b = min(hi, top)
      if (b > a) wet_length = wet_length + (b - a)*self%wet(0.5_dp*(a + b))
      phi = wet_length/h
      ! d(h phi)/dhi = g(hi), d(h phi)/dlo = -g(lo).
      if (z2 >= z1) then
         dphi_dz2 = (self%wet(hi) - phi)/h
         dphi_dz1 = (phi - self%wet(lo))/h
      else
         dphi_dz1 = (self%wet(hi) - phi)/h
         dphi_dz2 = (phi - self%wet(lo))/h
      end if
   end subroutine surface_wetted_fraction
end module xcable_loads_surface
