!> A rope that cannot push: any law with its compressive branch removed
!> (&material compression = 'none').
!>
!> With eps_z the strain where the law's tension is zero (strain_slack), the
!> tension is exactly 0 at and below eps_z and the law itself above it: no band,
!> no tension in slack. The strain energy is W(eps) = 0 at and below eps_z and
!> W_base(eps) - W_base(eps_z) above, the exact integral of that tension, so the
!> discrete gradient (W1 - W0) / (eps1 - eps0) of the rods is continuous across
!> the kink and their ledger exact. The stiffness at eps_z itself is the tensile
!> one (Newton's Jacobian takes the taut side at the kink).
!>
!> The rods' cell force of a step for such a law, with its Kelvin-Voigt damping
!> acting only on the taut part and never pushing, is slack_cell_force
!> (docs/theory/compression.md, "The tension-only law").
module xcable_material_tension_only
   use xcable_core_kinds, only: dp
   use xcable_material_law, only: material_law
   implicit none
   private
   public :: tension_only_law, new_tension_only, uncut_law, slack_cell_force, slack_dissipation, damped_tension, may_cross_kink

   !> The law without compression.
   type, extends(material_law) :: tension_only_law
      !> The law in tension.
      class(material_law), allocatable :: base
   contains
      procedure :: tension => to_tension
      procedure :: stiffness => to_stiffness
      procedure :: stiffness_slope => to_stiffness_slope
      procedure :: strain_energy => to_strain_energy
      procedure :: strain_energy_change => to_strain_energy_change
      procedure :: strain_energy_change_tension => to_strain_energy_change_tension
      procedure :: tension_stiffness => to_tension_stiffness
      procedure :: tension_stiffness_slope => to_tension_stiffness_slope
      procedure :: name => to_name
   end type tension_only_law

contains

   !> A copy of the law with its compressive branch: a tension-only law's base, any other law
   !> itself. The statics with the seabed's static friction solves with it first (a line whose
   !> friction takes all its tension would otherwise meet Newton with slack, stiffness-free
   !> cells), then with the law itself from there.
   subroutine uncut_law(law, uncut, was_cut)
      class(material_law), intent(in) :: law
      class(material_law), allocatable, intent(out) :: uncut
      !> Whether the law was a tension-only law.
      logical, intent(out) :: was_cut
      select type (law)
      type is (tension_only_law)
         allocate (uncut, source=law%base)
         was_cut = .true.
      class default
         allocate (uncut, source=law)
         was_cut = .false.
      end select
   end subroutine uncut_law

   !> Wrap a law: its strain of zero tension becomes the kink (strain_slack).
   function new_tension_only(base) result(law)
      !> The law in tension.
      class(material_law), intent(in) :: base
      type(tension_only_law) :: law
      allocate (law%base, source=base)
      law%strain_max = base%strain_max
      law%strain_slack = base%strain_at(0.0_dp)
   end function new_tension_only

   elemental function to_tension(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      if (eps <= self%strain_slack) then
         val = 0
      else
         val = self%base%tension(eps)
      end if
   end function to_tension

   !> f', the tensile one at eps_z.
   elemental function to_stiffness(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      if (eps < self%strain_slack) then
         val = 0
      else
         val = self%base%stiffness(eps)
      end if
   end function to_stiffness

   !> f'', the tensile one at eps_z.
   elemental function to_stiffness_slope(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      if (eps < self%strain_slack) then
         val = 0
      else
         val = self%base%stiffness_slope(eps)
      end if
   end function to_stiffness_slope

   !> W(eps): 0 at and below eps_z, W_base(eps) - W_base(eps_z) above (the base law's change,
   !> which keeps its digits).
   elemental function to_strain_energy(self, eps) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      if (eps <= self%strain_slack) then
         val = 0
      else
         val = self%base%strain_energy_change(self%strain_slack, eps)
      end if
   end function to_strain_energy

   !> W(eps1) - W(eps0): the base law's change between the taut parts max(eps, eps_z), so
   !> that no difference of two energies loses digits (material/law.f90).
   elemental function to_strain_energy_change(self, eps0, eps1) result(val)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps0, eps1
      real(dp) :: val
      if (max(eps0, eps1) <= self%strain_slack) then
         val = 0
      else
         val = self%base%strain_energy_change(max(eps0, self%strain_slack), max(eps1, self%strain_slack))
      end if
   end function to_strain_energy_change

   !> W(eps1) - W(eps0) and f(eps1): the base law's (one evaluation) where both strains are taut.
   pure subroutine to_strain_energy_change_tension(self, eps0, eps1, dw, f1)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in), value :: eps0, eps1
      real(dp), intent(out) :: dw, f1
      if (min(eps0, eps1) > self%strain_slack) then
         call self%base%strain_energy_change_tension(eps0, eps1, dw, f1)
      else
         dw = to_strain_energy_change(self, eps0, eps1)
         f1 = to_tension(self, eps1)
      end if
   end subroutine to_strain_energy_change_tension

   !> f and f' (the base law's together above eps_z).
   pure subroutine to_tension_stiffness(self, eps, f, fp)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp), intent(out) :: f, fp
      if (eps > self%strain_slack) then
         call self%base%tension_stiffness(eps, f, fp)
      else
         f = 0
         fp = to_stiffness(self, eps)
      end if
   end subroutine to_tension_stiffness

   !> f, f' and f'' (the base law's together above eps_z).
   pure subroutine to_tension_stiffness_slope(self, eps, f, fp, fpp)
      class(tension_only_law), intent(in) :: self
      real(dp), intent(in), value :: eps
      real(dp), intent(out) :: f, fp, fpp
      if (eps > self%strain_slack) then
         call self%base%tension_stiffness_slope(eps, f, fp, fpp)
      else
         f = 0
         fp = to_stiffness(self, eps)
         fpp = to_stiffness_slope(self, eps)
      end if
   end subroutine to_tension_stiffness_slope

   pure function to_name(self) result(name)
      class(tension_only_law), intent(in) :: self
      character(:), allocatable :: name
      name = self%base%name()//' without compression'
   end function to_name

   !> The axial force of a cell in a step (per unit of the rods' strain direction) for a law
   !> with a kink at eps_z = law%strain_slack, with Kelvin-Voigt damping c on the taut part:
   !>   q = (W1 - W0) / h, h = eps1 - eps0 (the exact divided difference; where both strains are
   !>       taut and |h| < small_step its Taylor form f(mid) + f'' h^2 / 24, as the rods take it;
   !>       0 where both are slack),
   !>   D = c (max(eps1, eps_z) - max(eps0, eps_z)) / dt (the rate of the taut strain),
   !>   N = max(q + D, 0) (a damper on a rope cannot push either),
   !> and dN / d(eps1), the taut side at a kink. The work of N in the step, ds N h, is the change
   !> of strain energy ds q h plus the dissipation ds (N - q) h >= 0 (D h >= 0; where the clip
   !> acts, D < 0, so h < 0 and -q h >= 0).
   pure subroutine slack_cell_force(law, eps0, eps1, damping, dt, small_step, n, dn, q)
      !> The law (strain_slack its kink).
      class(material_law), intent(in) :: law
      !> Old and new strain of the cell.
      real(dp), intent(in) :: eps0, eps1
      !> Damping c, N s; the step, s; the strain step below which the Taylor form is taken.
      real(dp), intent(in) :: damping, dt, small_step
      !> N and dN / d(eps1), N.
      real(dp), intent(out) :: n, dn
      !> The conservative part q, N (the ledger's: dissipation ds (N - q) h).
      real(dp), intent(out), optional :: q
      real(dp) :: ez, h, qc, dq, f, fp, fpp, mid, d, dd
      ez = law%strain_slack
      h = eps1 - eps0
      if (min(eps0, eps1) >= ez .and. abs(h) < small_step) then
         ! (Both at eps_z: q = 0 and the taut side's dq = f'(eps_z) / 2.)
         mid = 0.5_dp*(eps0 + eps1)
         call law%tension_stiffness_slope(mid, f, fp, fpp)
         qc = f + fpp*h*h/24
         dq = 0.5_dp*fp + fpp*h/12
      else if (max(eps0, eps1) <= ez) then
         qc = 0
         dq = 0
      else
         ! Straddling the kink the Taylor form is not the divided difference (f'' jumps there):
         ! the exact one, at any h.
         call law%strain_energy_change_tension(eps0, eps1, qc, f)
         qc = qc/h
         dq = (f - qc)/h
      end if
      d = damping*(max(eps1, ez) - max(eps0, ez))/dt
      dd = 0
      if (eps1 >= ez) dd = damping/dt
      if (qc + d >= 0) then
         n = qc + d
         dn = dq + dd
      else
         n = 0
         dn = 0
      end if
      if (present(q)) q = qc
   end subroutine slack_cell_force

   !> The energy the damping of slack_cell_force takes from a cell in the step, per unstretched
   !> length: (N - q) (eps1 - eps0) >= 0, J/m.
   elemental real(dp) function slack_dissipation(law, eps0, eps1, damping, dt, small_step) result(val)
      !> The law (strain_slack its kink).
      class(material_law), intent(in) :: law
      !> Old and new strain of the cell.
      real(dp), intent(in) :: eps0, eps1
      !> Damping c, N s; the step, s; the rods' strain step of the Taylor form.
      real(dp), intent(in) :: damping, dt, small_step
      real(dp) :: n, dn, q
      call slack_cell_force(law, eps0, eps1, damping, dt, small_step, n, dn, q)
      val = (n - q)*(eps1 - eps0)
   end function slack_dissipation

   !> The tension of a cell with its damping term d = c d(eps)/dt: f + d for a law continued into
   !> compression; for a rope that cannot push the damping acts on the taut part only (eps >=
   !> eps_z) and the sum never pushes, max(f + d, 0).
   elemental real(dp) function damped_tension(law, eps, f, d) result(val)
      !> The law.
      class(material_law), intent(in) :: law
      !> Strain, tension f(eps) (N) and damping term (N).
      real(dp), intent(in) :: eps, f, d
      if (law%strain_slack == -huge(1.0_dp)) then
         val = f + d
      else if (eps >= law%strain_slack) then
         val = max(f + d, 0.0_dp)
      else
         val = 0
      end if
   end function damped_tension

   !> Whether a change du (dims, n) of the node positions may carry a cell further than
   !> allowance past the kink at eps_z. The strain |e| - 1 of a cell, e = (R_c+1 - R_c) / ds_c,
   !> changes by at most |du_c+1 - du_c| / ds_c, so a cell moves past the kink by at most
   !> |du_c+1 - du_c| - |eps_c - eps_z| ds_c in length. Past it the slope of the cell force
   !> differs from the one the Newton update was made with, by about f'(eps_z) / 2, so its
   !> force is off the linear model by f'(eps_z) / 2 times the overshoot in strain, which the
   !> next update corrects by about half the overshoot in length. Newton's contraction estimate
   !> assumes a smooth residual along the last update: where an overshoot exceeds the update's
   !> tolerance (allowance, m), it does not hold (newton_problem estimate_trusted;
   !> docs/theory/compression.md).
   pure logical function may_cross_kink(eps_z, l, ds, du, allowance) result(may)
      !> Strain of the kink.
      real(dp), intent(in) :: eps_z
      !> Cell lengths over their unstretched lengths (1 + strain), and the unstretched lengths, m.
      real(dp), intent(in) :: l(:), ds(:)
      !> Change of the positions of the cells' nodes (one more node than cells), m.
      real(dp), intent(in) :: du(:, :)
      !> The overshoot allowed, m.
      real(dp), intent(in) :: allowance
      integer :: c
      may = .false.
      do c = 1, size(l)
         if (norm2(du(:, c + 1) - du(:, c)) - abs(l(c) - 1 - eps_z)*ds(c) > allowance) then
            may = .true.
            return
         end if
      end do
   end function may_cross_kink
end module xcable_material_tension_only
