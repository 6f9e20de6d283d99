!> A tension-strain law from data: a table of strains and tensions,
!> interpolated by a monotone cubic (&material law = 'table').
!>
!> Between rows the tension is the cubic Hermite interpolant with Steffen's
!> slopes (M. Steffen, Astron. Astrophys. 239, 443-450, 1990): on strictly
!> increasing data it is monotone, C1, and its slope f' is positive and
!> continuous, so the axial wave speed sqrt(f' / m) has no jumps (a
!> piecewise-linear table would make a rarefaction a staircase of small
!> shocks). Beyond the table the law continues along the tangent of its first
!> or last row: f stays C1 and f' constant out there. In compression the
!> &material compression option applies as for any law ('none' removes
!> everything below zero tension). f'' is the derivative of the cubic's
!> slope (continuous within a row interval, finite at the rows), and the
!> strain energy is the exact integral of the cubic from 0.
!>
!> The interval of a strain is found in O(1): a uniform index of the strain
!> range maps each of its buckets to the first row interval it meets.
module xcable_material_table
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_core_strings, only: str
   use xcable_material_law, only: material_law
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: table_law, new_table_law

   !> A tabulated law.
   type, extends(material_law) :: table_law
      !> Strains and tensions of the rows (N), strictly increasing.
      real(dp), allocatable :: strain(:), tension_rows(:)
      !> Slope f' at each row (Steffen), N.
      real(dp), allocatable :: slope(:)
      !> Integral of f from the first row to each row, J/m, and from the first row to strain 0.
      real(dp), allocatable :: energy(:)
      real(dp) :: energy_at_zero = 0
      !> Bucket index: first row interval of each bucket, and the bucket width.
      integer, allocatable :: bucket(:)
      real(dp) :: bucket_width = 1
   contains
      procedure :: tension => table_tension
      procedure :: stiffness => table_stiffness
      procedure :: stiffness_slope => table_stiffness_slope
      procedure :: strain_energy => table_strain_energy
      procedure :: name => table_name
      procedure :: tension_stiffness => table_tension_stiffness
   end type table_law

contains

   !> Build the law from its rows; error (stat_input) unless there are at least
   !> two finite rows with strictly increasing strain and tension. The law's
   !> range is that of its rows (strain_min, strain_max): beyond them it is extrapolated.
   subroutine new_table_law(strain, tension, law, error)
      !> Strains of the rows.
      real(dp), intent(in) :: strain(:)
      !> Tensions of the rows, N.
      real(dp), intent(in) :: tension(:)
      !> The law.
      type(table_law), intent(out) :: law
      !> Error naming the bad row.
      type(error_type), allocatable, intent(out) :: error
      integer :: n, i, b, nb
      real(dp) :: h(size(strain) - 1), d(size(strain) - 1), p, lo
      n = size(strain)
      if (n < 2 .or. size(tension) /= n) then
         call fatal_error(error, 'table_strain, table_tension: '//str(n)//' and '//str(size(tension))// &
                          ' values; the table needs at least 2 rows of both', stat_input)
         return
      end if
      do i = 1, n
         if (.not. (ieee_is_finite(strain(i)) .and. ieee_is_finite(tension(i)))) then
            call fatal_error(error, 'table row '//str(i)//': strain '//str(strain(i))//', tension '//str(tension(i))// &
                             ': not a finite number', stat_input)
            return
         end if
         if (i == 1) cycle
         if (.not. strain(i) > strain(i - 1)) then
            call fatal_error(error, 'table row '//str(i)//': strain '//str(strain(i))//' after '//str(strain(i - 1))// &
                             ': strains must increase strictly', stat_input)
            return
         end if
         if (.not. tension(i) > tension(i - 1)) then
            call fatal_error(error, 'table row '//str(i)//': tension '//str(tension(i))//' after '// &
                             str(tension(i - 1))//' N: tensions must increase strictly (a positive slope, '// &
                             'so that the wave speed is real)', stat_input)
            return
         end if
      end do
      law%strain_max = strain(n)
      law%strain_min = strain(1)
      law%strain = strain
      law%tension_rows = tension
      h = strain(2:n) - strain(1:n - 1)
      d = (tension(2:n) - tension(1:n - 1))/h
      allocate (law%slope(n))
      ! Steffen's slopes: inside, the one of the parabola through three rows, limited
      ! to keep the cubic monotone; at the ends, the same rule with one side.
      if (n == 2) then
         law%slope = d(1)
      else
         do i = 2, n - 1
            p = (d(i - 1)*h(i) + d(i)*h(i - 1))/(h(i - 1) + h(i))
            law%slope(i) = (sign(1.0_dp, d(i - 1)) + sign(1.0_dp, d(i)))*min(abs(d(i - 1)), abs(d(i)), 0.5_dp*abs(p))
         end do
         p = d(1)*(1 + h(1)/(h(1) + h(2))) - d(2)*h(1)/(h(1) + h(2))
         law%slope(1) = end_slope(p, d(1))
         p = d(n - 1)*(1 + h(n - 1)/(h(n - 1) + h(n - 2))) - d(n - 2)*h(n - 1)/(h(n - 1) + h(n - 2))
         law%slope(n) = end_slope(p, d(n - 1))
      end if
      ! Energy at the rows: integral of the cubic between rows, from the row at or below 0.
      allocate (law%energy(n))
      law%energy(1) = 0
      do i = 2, n
         law%energy(i) = law%energy(i - 1) + 0.5_dp*h(i - 1)*(tension(i - 1) + tension(i)) &
                         + h(i - 1)**2*(law%slope(i - 1) - law%slope(i))/12
      end do
      ! Bucket index over [strain(1), strain(n)].
      nb = 4*(n - 1)
      law%bucket_width = (strain(n) - strain(1))/nb
      allocate (law%bucket(nb))
      i = 1
      do b = 1, nb
         lo = strain(1) + (b - 1)*law%bucket_width
         do while (i < n - 1)
            if (strain(i + 1) > lo) exit
            i = i + 1
         end do
         law%bucket(b) = i
      end do
      ! The strain energy is the integral from strain 0.
      law%energy_at_zero = table_energy_raw(law, 0.0_dp)

   contains

      !> One-sided Steffen slope at an end row, kept at a tenth of the end
      !> interval's secant at least (Steffen's rule may give 0 where the data
      !> stiffen fast; any slope from 0 to 3 secants keeps the cubic monotone,
      !> and a positive one keeps the wave speed positive).
      pure real(dp) function end_slope(parabola, secant)
         real(dp), intent(in) :: parabola, secant
         if (parabola*secant <= 0) then
            end_slope = 0
         else if (abs(parabola) > 2*abs(secant)) then
            end_slope = 2*secant
         else
            end_slope = parabola
         end if
         end_slope = max(end_slope, 0.1_dp*secant)
      end function end_slope
   end subroutine new_table_law

   !> Row interval i (rows i, i+1) holding eps, with eps inside the table; 0 below, n above.
   pure integer function interval(self, eps) result(i)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      integer :: n, b
      n = size(self%strain)
      if (eps < self%strain(1)) then
         i = 0
         return
      end if
      if (eps >= self%strain(n)) then
         i = n
         return
      end if
      b = min(int((eps - self%strain(1))/self%bucket_width) + 1, size(self%bucket))
      i = self%bucket(b)
      do while (i < n - 1)
         if (self%strain(i + 1) > eps) exit
         i = i + 1
      end do
   end function interval

   !> Tension, slope and slope of the slope at eps.
   pure subroutine evaluate(self, eps, f, fp, fpp)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp), intent(out) :: f, fp, fpp
      integer :: i, n
      real(dp) :: h, u, y0, y1, m0, m1
      n = size(self%strain)
      i = interval(self, eps)
      if (i == 0) then
         fp = self%slope(1)
         f = self%tension_rows(1) + fp*(eps - self%strain(1))
         fpp = 0
      else if (i == n) then
         fp = self%slope(n)
         f = self%tension_rows(n) + fp*(eps - self%strain(n))
         fpp = 0
      else
         h = self%strain(i + 1) - self%strain(i)
         u = (eps - self%strain(i))/h
         y0 = self%tension_rows(i)
         y1 = self%tension_rows(i + 1)
         m0 = self%slope(i)
         m1 = self%slope(i + 1)
         f = (1 + 2*u)*(1 - u)**2*y0 + u*(1 - u)**2*h*m0 + u*u*(3 - 2*u)*y1 + u*u*(u - 1)*h*m1
         fp = (6*u*u - 6*u)/h*y0 + (3*u*u - 4*u + 1)*m0 + (6*u - 6*u*u)/h*y1 + (3*u*u - 2*u)*m1
         fpp = ((12*u - 6)/h*y0 + (6*u - 4)*m0 + (6 - 12*u)/h*y1 + (6*u - 2)*m1)/h
      end if
   end subroutine evaluate

   !> Integral of the tension from the first row's strain to eps.
   pure real(dp) function table_energy_raw(self, eps) result(w)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      integer :: i, n
      real(dp) :: h, u, y0, y1, m0, m1, d
      n = size(self%strain)
      i = interval(self, eps)
      if (i == 0) then
         d = eps - self%strain(1)
         w = self%tension_rows(1)*d + 0.5_dp*self%slope(1)*d*d
      else if (i == n) then
         d = eps - self%strain(n)
         w = self%energy(n) + self%tension_rows(n)*d + 0.5_dp*self%slope(n)*d*d
      else
         h = self%strain(i + 1) - self%strain(i)
         u = (eps - self%strain(i))/h
         y0 = self%tension_rows(i)
         y1 = self%tension_rows(i + 1)
         m0 = self%slope(i)
         m1 = self%slope(i + 1)
         ! Integrals from 0 to u of the Hermite basis times h.
         w = self%energy(i) + h*((u - u**3 + 0.5_dp*u**4)*y0 + (0.5_dp*u*u - 2*u**3/3 + 0.25_dp*u**4)*h*m0 &
                                 + (u**3 - 0.5_dp*u**4)*y1 + (0.25_dp*u**4 - u**3/3)*h*m1)
      end if
   end function table_energy_raw

   elemental function table_tension(self, eps) result(val)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, fp, fpp
      call evaluate(self, eps, val, fp, fpp)
   end function table_tension

   elemental function table_stiffness(self, eps) result(val)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, f, fpp
      call evaluate(self, eps, f, val, fpp)
   end function table_stiffness

   elemental function table_stiffness_slope(self, eps) result(val)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val, f, fp
      call evaluate(self, eps, f, fp, val)
   end function table_stiffness_slope

   elemental function table_strain_energy(self, eps) result(val)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp) :: val
      val = table_energy_raw(self, eps) - self%energy_at_zero
   end function table_strain_energy

   pure subroutine table_tension_stiffness(self, eps, f, fp)
      class(table_law), intent(in) :: self
      real(dp), intent(in) :: eps
      real(dp), intent(out) :: f, fp
      real(dp) :: fpp
      call evaluate(self, eps, f, fp, fpp)
   end subroutine table_tension_stiffness

   pure function table_name(self) result(name)
      class(table_law), intent(in) :: self
      character(:), allocatable :: name
      name = 'table'
   end function table_name
end module xcable_material_table
