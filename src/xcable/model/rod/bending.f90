!> The planar rod's bending on arrays, which knows no piece: the bending energy of a node
!> B = 2 EI tan^2(th / 2) / h_k, its moment and stiffness from t = tan(th / 2), and the divided
!> differences of a step, m = [B(th1) - B(th0)] / (th1 - th0) and dm / dth1, node by node
!> (bend_divided) and at the nodes of a block in packed SSE2 pairs (bend_arguments,
!> bend_divided_array; model/rod.f90 bend_nodes).
!>
!> Its own module so that its helpers stay private: gfortran 12 inlines them only as private
!> procedures of their module (bend_taylor into bend_divided_array's packed loop); the piece's
!> bend_energy, bend_moment and bend_stiffness take the public wrappers bending_energy,
!> bending_moment and bending_stiffness.
module xcable_model_rod_bending
   use xcable_core_kinds, only: dp, i8
   use xcable_model_rod_kernels, only: small_rotation
   implicit none
   private
   public :: bending_energy, bending_moment, bending_stiffness, bend_arguments, bend_divided_array

contains

   !> bend_energy_of, for the piece.
   pure real(dp) function bending_energy(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bending_energy = bend_energy_of(ei, hk, t)
   end function bending_energy

   !> bend_moment_of, for the piece.
   pure real(dp) function bending_moment(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bending_moment = bend_moment_of(ei, hk, t)
   end function bending_moment

   !> bend_stiffness_of, for the piece.
   pure real(dp) function bending_stiffness(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bending_stiffness = bend_stiffness_of(ei, hk, t)
   end function bending_stiffness


   !> bend_energy from t = tan(th / 2).
   !> (Bending stiffness ei, N m^2, and dual length hk of the node, m: also bend_moment_of,
   !> bend_stiffness_of, bend_taylor, bend_divided.)
   elemental real(dp) function bend_energy_of(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bend_energy_of = 2*ei*t**2/hk
   end function bend_energy_of

   !> bend_moment from t = tan(th / 2).
   elemental real(dp) function bend_moment_of(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bend_moment_of = 2*ei*t*(1 + t*t)/hk
   end function bend_moment_of

   !> bend_stiffness from t = tan(th / 2).
   elemental real(dp) function bend_stiffness_of(ei, hk, t)
      real(dp), intent(in) :: ei, hk, t
      bend_stiffness_of = ei*(1 + t*t)*(1 + 3*t*t)/hk
   end function bend_stiffness_of

   !> The discrete gradient of the bending energy of a node between the turning
   !> angles th0 and th1, m = [B(th1) - B(th0)] / (th1 - th0), and dm / dth1
   !> (Taylor forms when the two are close, bend_taylor).
   pure subroutine bend_divided(ei, hk, th0, th1, b0, t, m, dm, b1, b1_ok)
      real(dp), intent(in) :: ei, hk
      !> Old and new turning angle, and the old one's bending energy B(th0).
      real(dp), intent(in) :: th0, th1, b0
      !> fast_tan(bend_argument(th0, th1)).
      real(dp), intent(in) :: t
      real(dp), intent(out) :: m, dm
      !> B(th1) when it was computed (b1_ok).
      real(dp), intent(out) :: b1
      logical, intent(out) :: b1_ok
      real(dp) :: h
      h = th1 - th0
      if (abs(h) < small_rotation) then
         call bend_taylor(ei, hk, h, t, m, dm)
         b1 = 0
         b1_ok = .false.
      else
         ! One tan for B(th1) and its moment (the compiler called tan twice here).
         b1 = bend_energy_of(ei, hk, t)
         b1_ok = .true.
         m = (b1 - b0)/h
         dm = (bend_moment_of(ei, hk, t) - m)/h
      end if
   end subroutine bend_divided

   !> bend_divided's Taylor forms (|h| < small_rotation, h = th1 - th0, t the tan of half
   !> the mean turning angle): m = B' + B''' h^2 / 24 and dm = B'' / 2 + B''' h / 12.
   elemental subroutine bend_taylor(ei, hk, h, t, m, dm)
      real(dp), intent(in) :: ei, hk, h, t
      real(dp), intent(out) :: m, dm
      real(dp) :: third
      ! d3B/dth3 = EI (1 + t^2) t (4 + 6 t^2) / h_k
      third = ei*(1 + t*t)*t*(4 + 6*t*t)/hk
      m = bend_moment_of(ei, hk, t) + third*h*h/24
      dm = 0.5_dp*bend_stiffness_of(ei, hk, t) + third*h/12
   end subroutine bend_taylor

   !> bend_divided at n nodes, bit for bit: bend_taylor at every node in a loop without
   !> branches (gfortran 12 packs it two nodes to an SSE2 operation, divisions included),
   !> then, if some node is not that case (|th1 - th0| >= small_rotation, NaN),
   !> bend_divided itself for each of those. test/suite_rod.f90 compares bend_nodes' results
   !> with the per-node forms by their bits (bend_terms_in_pairs_same_bits).
   pure subroutine bend_divided_array(n, ei, hk, th0, th1, b0, t, m, dm, b1, b1_ok)
      !> Number of nodes.
      integer, intent(in) :: n
      !> Bending stiffness, N m^2.
      real(dp), intent(in) :: ei
      !> The nodes' dual lengths, old and new turning angles, old bending energies and tan
      !> (fast_tan(bend_argument(th0, th1))).
      real(dp), intent(in) :: hk(n), th0(n), th1(n), b0(n), t(n)
      !> bend_divided's results at each node.
      real(dp), intent(out) :: m(n), dm(n), b1(n)
      logical, intent(out) :: b1_ok(n)
      real(dp) :: h
      integer :: i
      integer(i8) :: others
      ! others: the OR of the complemented bits of |h| - small_rotation, whose sign bit is
      ! set if some |h| >= small_rotation or is NaN (as in fast_tan_array).
      others = 0
      !GCC$ unroll 1
      do i = 1, n
         h = th1(i) - th0(i)
         call bend_taylor(ei, hk(i), h, t(i), m(i), dm(i))
         others = ior(others, not(transfer(abs(h) - small_rotation, 0_i8)))
      end do
      b1 = 0
      b1_ok = .false.
      if (others >= 0) return
      do i = 1, n
         if (.not. abs(th1(i) - th0(i)) < small_rotation) &
            call bend_divided(ei, hk(i), th0(i), th1(i), b0(i), t(i), m(i), dm(i), b1(i), b1_ok(i))
      end do
   end subroutine bend_divided_array

   !> The argument of tan in bend_divided: half the mean turning angle where the two are
   !> close (its Taylor form), else half the new one.
   elemental real(dp) function bend_argument(th0, th1) result(x)
      real(dp), intent(in) :: th0, th1
      integer(i8) :: close
      ! Both forms, and the one that applies picked by a mask of bits, so that bend_arguments'
      ! loop packs in SSE2 pairs (gfortran 12 keeps a merge of the two, or of integer masks
      ! from a comparison, a branch). close: all bits set where |th1 - th0| < small_rotation,
      ! the sign bit of |th1 - th0| - small_rotation copied (never -0; a NaN is positive, as
      ! abs leaves it: not close, as the comparison).
      close = shifta(transfer(abs(th1 - th0) - small_rotation, 0_i8), 63)
      x = transfer(ior(iand(close, transfer(0.5_dp*(0.5_dp*(th0 + th1)), 0_i8)), &
                       iand(not(close), transfer(0.5_dp*th1, 0_i8))), 0.0_dp)
   end function bend_argument

   !> x(i) = bend_argument(th0(i), th1(i)), i = 1 .. n, in packed SSE2 pairs (explicit-shape
   !> arrays, as fast_tan_array's).
   pure subroutine bend_arguments(n, th0, th1, x)
      integer, intent(in) :: n
      real(dp), intent(in) :: th0(n), th1(n)
      real(dp), intent(out) :: x(n)
      integer :: i
      !GCC$ unroll 1
      do i = 1, n
         x(i) = bend_argument(th0(i), th1(i))
      end do
   end subroutine bend_arguments
end module xcable_model_rod_bending
