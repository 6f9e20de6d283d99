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
               new_unittest('paper_values', test_paper_values)]
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
