!> A body at a node of the line: a clump weight or a buoy at a joint of two
!> segments (&point_k joint). It is the point of a mooring network in its
!> simplest place, between two line ends of one line; the same body will sit
!> where several lines meet.
!>
!> The body has a mass m, a displaced volume V, an added-mass coefficient Ca
!> and a drag coefficient Cd on a projected area A, all isotropic (MoorDyn's
!> point has the same five). In water of density rho, with gravity g and a
!> uniform current U, it adds to its node
!>
!>     inertia   m + Ca rho V              (the node's mass matrix, every direction)
!>     weight    m g                       (down)
!>     buoyancy  rho g V phi(z)            (up; phi the wetted share, 1 well under the surface)
!>     drag      -1/2 rho Cd A |w| w,      w = V_node - U
!>
!> The buoyancy is that of the sphere of the body's volume (radius
!> R = (3 V / 4 pi)^(1/3)) cut by the water surface z_s: with h = z_s - (z - R)
!> the depth of its lowest point, clamped to [0, 2 R], the wetted share is
!> h^2 (3 R - h) / (4 R^3), smooth where it starts and ends (a named
!> approximation: a buoy of another shape floats at another draft; its
!> added mass and drag stay those of the whole body). Over a time step the
!> buoyancy acts at the step's mean height (z^n + z^n+1) / 2 and the drag on
!> the step's mean velocity (R^n+1 - R^n) / dt, like the cells' loads, so that
!> the work they do over the step is their force times the displacement; in
!> statics at the height and w = -U. The weight m g is part of the node's
!> weight (its potential g z in the ledger), the inertia part of the mass
!> matrix (its kinetic energy), and the buoyancy's and the drag's work are
!> booked with the other loads'.
module xcable_loads_point
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: point_body

   !> A body at a node.
   type :: point_body
      !> Arc length of its node from end a (unstretched), m.
      real(dp) :: s = 0
      !> Mass, kg; displaced volume, m^3; added-mass coefficient; drag coefficient; projected
      !> area for the drag, m^2.
      real(dp) :: mass = 0, volume = 0, ca = 0, cd = 0, area = 0
      !> Water density, kg/m^3 (0: no water); gravity, m/s^2; the current (x, y, z), m/s; the
      !> height of the water surface, m.
      real(dp) :: density = 0, gravity = 0, current(3) = 0, surface = huge(1.0_dp)
   contains
      !> Mass with the added mass, kg.
      procedure :: inertia
      !> Weight less buoyancy when fully submerged, N (positive down).
      procedure :: net_weight
      !> Weight, N (down).
      procedure :: weight
      !> Whether it has buoyancy.
      procedure :: has_buoyancy
      !> Buoyancy at a height, with its derivative.
      procedure :: buoyancy
      !> Whether it has drag.
      procedure :: has_drag
      !> Drag force on its node over a step or at rest, with its derivative.
      procedure :: drag
      !> Its force on its node besides its weight (buoyancy and drag), with its derivative.
      procedure :: force
   end type point_body

contains

   !> m + Ca rho V, kg.
   pure real(dp) function inertia(self)
      class(point_body), intent(in) :: self
      inertia = self%mass + self%ca*self%density*self%volume
   end function inertia

   !> (m - rho V) g, N.
   pure real(dp) function net_weight(self)
      class(point_body), intent(in) :: self
      net_weight = (self%mass - self%density*self%volume)*self%gravity
   end function net_weight

   !> m g, N.
   pure real(dp) function weight(self)
      class(point_body), intent(in) :: self
      weight = self%mass*self%gravity
   end function weight

   !> Whether rho V g > 0.
   pure logical function has_buoyancy(self)
      class(point_body), intent(in) :: self
      has_buoyancy = self%density*self%volume*self%gravity > 0
   end function has_buoyancy

   !> The buoyancy rho g V phi(z) (N, up) of the body centred at height z, and its derivative in
   !> z (N/m): phi the wetted share of the sphere of volume V under the surface.
   pure subroutine buoyancy(self, z, f, df_dz)
      class(point_body), intent(in) :: self
      !> Height of the body's centre, m.
      real(dp), intent(in) :: z
      !> Buoyancy, N; its derivative, N/m.
      real(dp), intent(out) :: f, df_dz
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: r, h, full
      full = self%density*self%gravity*self%volume
      f = full
      df_dz = 0
      if (self%surface >= huge(1.0_dp)) return
      r = (3*self%volume/(4*pi))**(1.0_dp/3)
      h = self%surface - (z - r)
      if (h >= 2*r) return
      if (h <= 0) then
         f = 0
         return
      end if
      ! phi = h^2 (3 r - h) / (4 r^3); dphi/dz = -dphi/dh = -(6 r h - 3 h^2) / (4 r^3).
      f = full*h*h*(3*r - h)/(4*r**3)
      df_dz = -full*(6*r*h - 3*h*h)/(4*r**3)
   end subroutine buoyancy

   !> Whether 1/2 rho Cd A > 0.
   pure logical function has_drag(self)
      class(point_body), intent(in) :: self
      has_drag = self%density*self%cd*self%area > 0
   end function has_drag

   !> The drag on the node, N, and its derivative with respect to the node's new position x1,
   !> N/m: in a step (dt > 0) on the mean velocity (x1 - x0) / dt, at rest (dt = 0) in the current.
   pure subroutine drag(self, dt, x0, x1, f, df_dx1)
      !> The body.
      class(point_body), intent(in) :: self
      !> Time step, s (0: statics).
      real(dp), intent(in) :: dt
      !> Positions of the node at the start and the end of the step, m.
      real(dp), intent(in) :: x0(3), x1(3)
      !> Force, N; d f / d x1, N/m.
      real(dp), intent(out) :: f(3), df_dx1(3, 3)
      real(dp) :: w(3), speed, c
      integer :: a
      c = 0.5_dp*self%density*self%cd*self%area
      if (dt > 0) then
         w = (x1 - x0)/dt - self%current
      else
         w = -self%current
      end if
      speed = norm2(w)
      f = -c*speed*w
      df_dx1 = 0
      if (dt <= 0 .or. speed <= 0) return
      ! d(|w| w)/dw = |w| I + w w^T / |w|; dw/dx1 = I / dt.
      do a = 1, 3
         df_dx1(:, a) = -c*w*w(a)/(speed*dt)
         df_dx1(a, a) = df_dx1(a, a) - c*speed/dt
      end do
   end subroutine drag

   !> The force of the body on its node besides its weight (N): its buoyancy at the step's mean
   !> height (statics, dt = 0: at x1) and its drag, with the derivative with respect to x1 (N/m).
   pure subroutine force(self, dt, x0, x1, f, df_dx1)
      !> The body.
      class(point_body), intent(in) :: self
      !> Time step, s (0: statics).
      real(dp), intent(in) :: dt
      !> Positions of the node at the start and the end of the step, m.
      real(dp), intent(in) :: x0(3), x1(3)
      !> Force, N; d f / d x1, N/m.
      real(dp), intent(out) :: f(3), df_dx1(3, 3)
      real(dp) :: fb, dfb
      f = 0
      df_dx1 = 0
      if (self%has_drag()) call self%drag(dt, x0, x1, f, df_dx1)
      if (.not. self%has_buoyancy()) return
      if (dt > 0) then
         call self%buoyancy(0.5_dp*(x0(3) + x1(3)), fb, dfb)
         dfb = 0.5_dp*dfb
      else
         call self%buoyancy(x1(3), fb, dfb)
      end if
      f(3) = f(3) + fb
      df_dx1(3, 3) = df_dx1(3, 3) + dfb
   end subroutine force
end module xcable_loads_point
