!> The cable's equations of motion in the paper's form (eqs. 18-21):
!>
!>     dY/ds + M(Y) dY/dt + P(Y) = 0,   Y = [eps, Sn, u, v, beta0, beta3, Omega3]
!>
!> Row 1: tangential momentum divided by f'(eps); row 2: normal momentum;
!> rows 3-4: compatibility; rows 5-6: Euler-parameter kinematics (eq. 16);
!> row 7: moment balance with M_b = EI Omega3. Gravity -w0 i, i points up,
!> t = (b0^2 - b3^2) i + 2 b0 b3 j, n = -2 b0 b3 i + (b0^2 - b3^2) j.
!>
!> Besides M and P this module gives the exact derivatives d(M(Y) z)/dY and
!> dP/dY that the Jacobian of the discrete equations is built from.
module xcable_box_equations
   use xcable_core_kinds, only: dp
   use xcable_material_law, only: material_law
   implicit none
   private
   public :: cable_model, n_eq
   public :: i_eps, i_sn, i_u, i_v, i_b0, i_b3, i_om
   public :: equation_terms, equation_derivatives, mass_times
   public :: forcing_from_law, mass_times_from_law

   !> Number of unknowns per node.
   integer, parameter :: n_eq = 7
   !> Positions of the unknowns in Y.
   integer, parameter :: i_eps = 1, i_sn = 2, i_u = 3, i_v = 4, i_b0 = 5, i_b3 = 6, i_om = 7

   !> Physical data of the cable that the equations need.
   type :: cable_model
      !> Mass per unstretched length m = rho A, kg/m.
      real(dp) :: mass = 0
      !> Weight per unstretched length w0 = m g, N/m.
      real(dp) :: weight = 0
      !> Bending stiffness EI, N m^2.
      real(dp) :: bending_stiffness = 1
      !> Unstretched length, m.
      real(dp) :: length = 1
      !> Tension-strain law.
      class(material_law), allocatable :: law
   end type cable_model

contains

   !> M(Y) (7x7, eq. 20) and P(Y) (eq. 21) at one node.
   pure subroutine equation_terms(model, y, mass, forcing, compliance)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns at the node.
      real(dp), intent(in) :: y(n_eq)
      !> M(Y).
      real(dp), intent(out) :: mass(n_eq, n_eq)
      !> P(Y).
      real(dp), intent(out) :: forcing(n_eq)
      !> 1 / f'(eps) at the node, 1/N.
      real(dp), intent(out), optional :: compliance
      real(dp) :: m, g, f, fp
      m = model%mass
      call model%law%tension_stiffness(y(i_eps), f, fp)
      g = 1.0_dp/fp
      if (present(compliance)) compliance = g
      mass = 0
      mass(1, i_u) = -m*g
      mass(1, i_b0) = -2*m*y(i_v)*y(i_b3)*g
      mass(1, i_b3) = 2*m*y(i_v)*y(i_b0)*g
      mass(2, i_v) = -m
      mass(2, i_b0) = 2*m*y(i_u)*y(i_b3)
      mass(2, i_b3) = -2*m*y(i_u)*y(i_b0)
      mass(3, i_eps) = -1
      mass(4, i_b0) = 2*(1 + y(i_eps))*y(i_b3)
      mass(4, i_b3) = -2*(1 + y(i_eps))*y(i_b0)
      call forcing_from_law(model, y, f, g, forcing)
   end subroutine equation_terms

   !> P(Y) (eq. 21) at one node, given the law's values there (no law call).
   pure subroutine forcing_from_law(model, y, f, g, forcing)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns at the node.
      real(dp), intent(in) :: y(n_eq)
      !> Tension f(eps), N.
      real(dp), intent(in) :: f
      !> Compliance 1 / f'(eps), 1/N.
      real(dp), intent(in) :: g
      !> P(Y).
      real(dp), intent(out) :: forcing(n_eq)
      forcing(1) = -g*(y(i_sn)*y(i_om) + model%weight*(y(i_b0)**2 - y(i_b3)**2))
      forcing(2) = f*y(i_om) + 2*model%weight*y(i_b0)*y(i_b3)
      forcing(3) = -y(i_om)*y(i_v)
      forcing(4) = y(i_om)*y(i_u)
      forcing(5) = 0.5_dp*y(i_b3)*y(i_om)
      forcing(6) = -0.5_dp*y(i_b0)*y(i_om)
      forcing(7) = y(i_sn)*(1 + y(i_eps))**3/model%bending_stiffness
   end subroutine forcing_from_law

   !> M(Y) z for a vector z, without forming M.
   pure function mass_times(model, y, z) result(mz)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns at the node.
      real(dp), intent(in) :: y(n_eq)
      !> Vector multiplied.
      real(dp), intent(in) :: z(n_eq)
      real(dp) :: mz(n_eq)
      call mass_times_from_law(model, y, 1.0_dp/model%law%stiffness(y(i_eps)), z, mz)
   end function mass_times

   !> M(Y) z at one node given the compliance 1 / f'(eps) there (no law call, no temporary).
   pure subroutine mass_times_from_law(model, y, g, z, mz)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns at the node.
      real(dp), intent(in) :: y(n_eq)
      !> Compliance 1 / f'(eps), 1/N.
      real(dp), intent(in) :: g
      !> Vector multiplied.
      real(dp), intent(in) :: z(n_eq)
      !> M(Y) z.
      real(dp), intent(out) :: mz(n_eq)
      real(dp) :: m
      m = model%mass
      mz(1) = m*g*(-z(i_u) - 2*y(i_v)*y(i_b3)*z(i_b0) + 2*y(i_v)*y(i_b0)*z(i_b3))
      mz(2) = m*(-z(i_v) + 2*y(i_u)*y(i_b3)*z(i_b0) - 2*y(i_u)*y(i_b0)*z(i_b3))
      mz(3) = -z(i_eps)
      mz(4) = 2*(1 + y(i_eps))*(y(i_b3)*z(i_b0) - y(i_b0)*z(i_b3))
      mz(5:) = 0
   end subroutine mass_times_from_law

   !> Exact derivatives at one node: dmz = d(M(Y) z)/dY for fixed z, and dP/dY.
   pure subroutine equation_derivatives(model, y, z, dmz, dforcing)
      !> Cable data.
      type(cable_model), intent(in) :: model
      !> Unknowns at the node.
      real(dp), intent(in) :: y(n_eq)
      !> Vector that M(Y) multiplies (held fixed).
      real(dp), intent(in) :: z(n_eq)
      !> d(M(Y) z)/dY, row = equation, column = unknown.
      real(dp), intent(out) :: dmz(n_eq, n_eq)
      !> dP/dY.
      real(dp), intent(out) :: dforcing(n_eq, n_eq)
      real(dp) :: m, w0, fp, g, dg, f, a1, onep, ei
      m = model%mass
      w0 = model%weight
      ei = model%bending_stiffness
      fp = model%law%stiffness(y(i_eps))
      f = model%law%tension(y(i_eps))
      g = 1.0_dp/fp
      dg = -model%law%stiffness_slope(y(i_eps))*g*g
      onep = 1 + y(i_eps)

      dmz = 0
      a1 = -z(i_u) - 2*y(i_v)*y(i_b3)*z(i_b0) + 2*y(i_v)*y(i_b0)*z(i_b3)
      dmz(1, i_eps) = m*dg*a1
      dmz(1, i_v) = m*g*(-2*y(i_b3)*z(i_b0) + 2*y(i_b0)*z(i_b3))
      dmz(1, i_b0) = m*g*2*y(i_v)*z(i_b3)
      dmz(1, i_b3) = -m*g*2*y(i_v)*z(i_b0)
      dmz(2, i_u) = 2*m*(y(i_b3)*z(i_b0) - y(i_b0)*z(i_b3))
      dmz(2, i_b0) = -2*m*y(i_u)*z(i_b3)
      dmz(2, i_b3) = 2*m*y(i_u)*z(i_b0)
      dmz(4, i_eps) = 2*(y(i_b3)*z(i_b0) - y(i_b0)*z(i_b3))
      dmz(4, i_b0) = -2*onep*z(i_b3)
      dmz(4, i_b3) = 2*onep*z(i_b0)

      dforcing = 0
      dforcing(1, i_eps) = -dg*(y(i_sn)*y(i_om) + w0*(y(i_b0)**2 - y(i_b3)**2))
      dforcing(1, i_sn) = -g*y(i_om)
      dforcing(1, i_om) = -g*y(i_sn)
      dforcing(1, i_b0) = -2*g*w0*y(i_b0)
      dforcing(1, i_b3) = 2*g*w0*y(i_b3)
      dforcing(2, i_eps) = fp*y(i_om)
      dforcing(2, i_om) = f
      dforcing(2, i_b0) = 2*w0*y(i_b3)
      dforcing(2, i_b3) = 2*w0*y(i_b0)
      dforcing(3, i_om) = -y(i_v)
      dforcing(3, i_v) = -y(i_om)
      dforcing(4, i_om) = y(i_u)
      dforcing(4, i_u) = y(i_om)
      dforcing(5, i_b3) = 0.5_dp*y(i_om)
      dforcing(5, i_om) = 0.5_dp*y(i_b3)
      dforcing(6, i_b0) = -0.5_dp*y(i_om)
      dforcing(6, i_om) = -0.5_dp*y(i_b0)
      dforcing(7, i_sn) = onep**3/ei
      dforcing(7, i_eps) = 3*y(i_sn)*onep**2/ei
   end subroutine equation_derivatives
end module xcable_box_equations
