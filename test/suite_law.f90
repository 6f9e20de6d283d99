!> Tension-strain laws: f', f'' and the strain energy against central
!> differences, and the inverse strain_at.
module suite_law
   use xcable_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_strings, only: str
   use xcable_material_law, only: material_law, tanh_law, linear_law
   implicit none
   private
   public :: collect_law

contains

   subroutine collect_law(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('tanh_derivatives', test_tanh_derivatives), &
               new_unittest('linear_derivatives', test_linear_derivatives), &
               new_unittest('inverse', test_inverse), &
               new_unittest('paper_values', test_paper_values), &
               new_unittest('tanh_energy_change_quad', test_tanh_energy_change)]
   end subroutine collect_law

   !> Compare f', f'' and dW/deps with central differences over the strain range.
   subroutine check_law(error, law)
      type(error_type), allocatable, intent(out) :: error
      class(material_law), intent(in) :: law
      real(dp) :: eps, h, fd
      integer :: i
      h = 1.0e-5_dp
      do i = 0, 40
         eps = -0.5_dp + 0.02_dp*i
         fd = (law%tension(eps + h) - law%tension(eps - h))/(2*h)
         call check_close(error, law%stiffness(eps), fd, law%name()//" f' at eps = "//str(eps), &
                          rel_tol=1.0e-7_dp, abs_tol=1.0e-6_dp)
         if (allocated(error)) return
         fd = (law%stiffness(eps + h) - law%stiffness(eps - h))/(2*h)
         call check_close(error, law%stiffness_slope(eps), fd, law%name()//" f'' at eps = "//str(eps), &
                          rel_tol=1.0e-6_dp, abs_tol=1.0e-3_dp)
         if (allocated(error)) return
         fd = (law%strain_energy(eps + h) - law%strain_energy(eps - h))/(2*h)
         call check_close(error, law%tension(eps), fd, law%name()//" dW/deps at eps = "//str(eps), &
                          rel_tol=1.0e-7_dp, abs_tol=1.0e-4_dp)
         if (allocated(error)) return
      end do
      call check_close(error, law%strain_energy(0.0_dp), 0.0_dp, 'W(0)', abs_tol=1.0e-9_dp)
   end subroutine check_law

   !> The tanh law's strain energy and its change between two strains against the same
   !> closed form, (p1 / p2) log cosh(p2 eps + p3) + p4 eps + p5 eps^2 / 2 from W(0) = 0,
   !> evaluated in quadruple precision: strains from -0.05 to 0.3, steps from 1e-7 to 0.2
   !> (both branches). The change's error over the step, which is the error of the rods'
   !> divided difference (N), and W's error over max(|W|, 1 J/m). Measured: 1.1e-10 N and 6.1e-14; with
   !> W from its log cosh form and the change as W1 - W0 (the code before): 1.9e-4 N and 1.2e-11.
   subroutine test_tanh_energy_change(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: qp = selected_real_kind(30)
      type(tanh_law) :: law
      real(dp), parameter :: eps0s(8) = [-0.05_dp, -1.0e-4_dp, 0.0_dp, 1.0e-4_dp, 1.0e-3_dp, 0.012_dp, 0.15_dp, 0.3_dp]
      real(dp), parameter :: hs(7) = [1.0e-7_dp, 1.0e-6_dp, 3.0e-6_dp, 1.0e-4_dp, 1.0e-2_dp, 0.05_dp, 0.2_dp]
      real(dp) :: eps0, eps1, worst_q, worst_w
      integer :: i, j, sgn
      worst_q = 0
      worst_w = 0
      do i = 1, size(eps0s)
         eps0 = eps0s(i)
         worst_w = max(worst_w, abs(law%strain_energy(eps0) - real(w_quad(eps0), dp))/max(abs(real(w_quad(eps0), dp)), 1.0_dp))
         do j = 1, size(hs)
            do sgn = -1, 1, 2
               eps1 = eps0 + sgn*hs(j)
               worst_q = max(worst_q, abs(law%strain_energy_change(eps0, eps1) - &
                                          real(w_quad(eps1) - w_quad(eps0), dp))/abs(eps1 - eps0))
            end do
         end do
      end do
      write (*, '(4x,a,es9.2,a,es9.2,a)') 'tanh law against quadruple precision: change over the step ', worst_q, &
         ' N, strain energy ', worst_w, ' of max(|W|, 1 J/m)'
      call check(error, worst_q < 5.0e-10_dp, 'the change of W over the step is off by '//str(worst_q)//' N')
      if (allocated(error)) return
      call check(error, worst_w < 3.0e-13_dp, 'W is off by '//str(worst_w)//' (of max(|W|, 1 J/m))')
   contains
      pure function w_quad(eps) result(w)
         real(dp), intent(in) :: eps
         real(qp) :: w, p(5), e
         p = real(law%p, qp)
         e = real(eps, qp)
         w = p(1)/p(2)*(log(cosh(p(2)*e + p(3))) - log(cosh(p(3)))) + p(4)*e + p(5)*e*e/2
      end function w_quad
   end subroutine test_tanh_energy_change

   subroutine test_tanh_derivatives(error)
      type(error_type), allocatable, intent(out) :: error
      call check_law(error, tanh_law())
   end subroutine test_tanh_derivatives

   subroutine test_linear_derivatives(error)
      type(error_type), allocatable, intent(out) :: error
      call check_law(error, linear_law(ea=4.5e5_dp))
   end subroutine test_linear_derivatives

   !> strain_at inverts f across tension and compression.
   subroutine test_inverse(error)
      type(error_type), allocatable, intent(out) :: error
      type(tanh_law) :: law
      real(dp) :: t, eps
      integer :: i
      do i = -7, 50
         t = 1.0e4_dp*i
         eps = law%strain_at(t)
         call check_close(error, law%tension(eps), t, 'f(strain_at(T)) at T = '//str(t), rel_tol=1.0e-10_dp, &
                          abs_tol=1.0e-6_dp)
         if (allocated(error)) return
      end do
   end subroutine test_inverse

   !> The paper's statements: 180 kN gives 17.8 % and 315 kN 22.8 % (section 4.2);
   !> f(0) is about -42 N (PHYSICS.md); the law is convex below -p3/p2.
   subroutine test_paper_values(error)
      type(error_type), allocatable, intent(out) :: error
      type(tanh_law) :: law
      call check_close(error, law%strain_at(180.0e3_dp), 0.178_dp, 'strain at 180 kN', abs_tol=0.0015_dp)
      if (allocated(error)) return
      call check_close(error, law%strain_at(315.0e3_dp), 0.228_dp, 'strain at 315 kN', abs_tol=0.0015_dp)
      if (allocated(error)) return
      call check_close(error, law%tension(0.0_dp), -42.0_dp, 'f(0)', abs_tol=20.0_dp)
      if (allocated(error)) return
      call check(error, law%stiffness_slope(0.20_dp) > 0 .and. law%stiffness_slope(0.22_dp) < 0, &
                 'law convex below eps = 0.2086 and concave above')
   end subroutine test_paper_values
end module suite_law
