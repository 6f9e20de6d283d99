!> A rope that cannot push: any law with its compressive branch removed
!> (&material compression = 'none').
!>
!> Below the strain eps_z where the law gives zero tension the tension is 0.
!> So that Newton's method sees a continuous stiffness, the law is blended
!> into zero over a band of strain 2 delta around eps_z, delta = 1e-3 or, for a
!> stiffer law whose range strain_max is below 0.35, 0.3 % of strain_max: a
!> cubic Hermite from (eps_z - delta, 0, slope 0) to (eps_z + delta, f, f'),
!> monotone and C1; above eps_z + delta it is the law itself. The strain
!> energy is the exact integral of this tension from 0, so the energy ledger
!> stays exact.
module xcable_material_tension_only
   use xcable_kinds, only: dp
   use xcable_material_law, only: material_law
   implicit none
   private
   public :: tension_only_law, new_tension_only

   !> Half width of the blend, in strain, and as a fraction of the law's range.
   real(dp), parameter, public :: blend_half_width = 1.0e-3_dp, blend_fraction = 3.0e-3_dp

   !> The law without compression.
   type, extends(material_law) :: tension_only_law
      !> The law in tension.
      class(material_law), allocatable :: base
      !> Blend from a to b; f and f' of the base at b; the energy integral from 0 to a and b.
      real(dp) :: a = 0, b = 0, fb = 0, fpb = 0, g0 = 0, gb = 0
   contains
      procedure :: tension => to_tension
      procedure :: stiffness => to_stiffness
      procedure :: stiffness_slope => to_stiffness_slope
      procedure :: strain_energy => to_strain_energy
      procedure :: strain_energy_change => to_strain_energy_change
      procedure :: name => to_name
   end type tension_only_law

contains

   !> Wrap a law.
   function new_tension_only(base) result(law)
      !> The law in tension.
      class(material_law), intent(in) :: base
      type(tension_only_law) :: law
      real(dp) :: eps_z, delta
      allocate (law%base, source=base)
      law%strain_max = base%strain_max
      eps_z = base%strain_at(0.0_dp)
      delta = min(blend_half_width, blend_fraction*base%strain_max)
      law%a = eps_z - delta
      law%b = eps_z + delta
      law%fb = base%tension(law%b)
      law%fpb = base%stiffness(law%b)
      ! Antiderivative G with G = 0 below a; W(eps) = G(eps) - G(0).
      law%gb = blend_integral(law, law%b)
      law%g0 = antiderivative(law, 0.0_dp)
   end function new_tension_only

   !> Integral of the blend from a to eps (a <= eps <= b).
   pure real(dp) function blend_integral(self, eps)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: h, u
      h = self%b - self%a
      u = (eps - self%a)/h
      blend_integral = h*(self%fb*(u**3 - 0.5_dp*u**4) + h*self%fpb*(0.25_dp*u**4 - u**3/3))
   end function blend_integral

   !> Antiderivative of the tension, zero below a.
   elemental real(dp) function antiderivative(self, eps)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      if (eps <= self%a) then
         antiderivative = 0
      else if (eps < self%b) then
         antiderivative = blend_integral(self, eps)
      else
         antiderivative = self%gb + self%base%strain_energy(eps) - self%base%strain_energy(self%b)
      end if
   end function antiderivative

   elemental function to_tension(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, h, u
      if (eps <= self%a) then
         val = 0
      else if (eps < self%b) then
         h = self%b - self%a
         u = (eps - self%a)/h
         val = self%fb*(3*u**2 - 2*u**3) + h*self%fpb*(u**3 - u**2)
      else
         val = self%base%tension(eps)
      end if
   end function to_tension

   elemental function to_stiffness(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, h, u
      if (eps <= self%a) then
         val = 0
      else if (eps < self%b) then
         h = self%b - self%a
         u = (eps - self%a)/h
         val = (self%fb*(6*u - 6*u**2) + h*self%fpb*(3*u**2 - 2*u))/h
      else
         val = self%base%stiffness(eps)
      end if
   end function to_stiffness

   elemental function to_stiffness_slope(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, h, u
      if (eps <= self%a) then
         val = 0
      else if (eps < self%b) then
         h = self%b - self%a
         u = (eps - self%a)/h
         val = (self%fb*(6 - 12*u) + h*self%fpb*(6*u - 2))/h**2
      else
         val = self%base%stiffness_slope(eps)
      end if
   end function to_stiffness_slope

   elemental function to_strain_energy(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = antiderivative(self, eps) - self%g0
   end function to_strain_energy

   !> W(eps1) - W(eps0): the base law's change where both strains are on the base law (it
   !> keeps the digits the difference of two energies loses, material/law.f90), else the
   !> difference of the energies.
   elemental function to_strain_energy_change(self, eps0, eps1) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps0, eps1
      real(dp) :: val
      if (min(eps0, eps1) >= self%b) then
         val = self%base%strain_energy_change(eps0, eps1)
      else
         val = to_strain_energy(self, eps1) - to_strain_energy(self, eps0)
      end if
   end function to_strain_energy_change

   pure function to_name(self) result(name)
      class(tension_only_law), intent(in) :: self
      character(:), allocatable :: name
      name = self%base%name()//' without compression'
   end function to_name
end module xcable_material_tension_only
