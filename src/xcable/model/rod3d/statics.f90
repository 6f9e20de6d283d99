!> The static equilibrium of a 3-D piece (rod3d_static_system): the exact gradient of the energy,
!> its bending blocks by forward-mode dual numbers (defined here, with their one user).
!> (A submodule of model/rod3d.f90.)
submodule (xcable_model_rod3d) xcable_model_rod3d_statics
   implicit none

   ! Forward-mode dual numbers: a value and its derivatives with respect to six seeded inputs
   ! (the two cell vectors of a node; the statics' bending blocks). They live in this submodule, with
   ! their one user, so that the compiler can inline their arithmetic (gfortran inlines only within a
   ! compilation unit; a separate module cost a factor of several).
   !> Number of derivative slots.
   integer, parameter :: dual_slots = 6

   !> A value and its derivatives.
   type :: dual
      !> Value.
      real(dp) :: v = 0
      !> Derivatives with respect to the seeded inputs.
      real(dp) :: d(dual_slots) = 0
   end type dual

   interface operator(+)
      module procedure add_dd, add_dr, add_rd
   end interface
   interface operator(-)
      module procedure sub_dd, sub_dr, sub_rd, neg_d
   end interface
   interface operator(*)
      module procedure mul_dd, mul_dr, mul_rd
   end interface
   interface operator(/)
      module procedure div_dd, div_dr, div_rd
   end interface
   interface sqrt
      module procedure sqrt_d
   end interface

contains

   !> Add node k's bending force to the cell forces and, with the Jacobian, its blocks.
   !> fa, fb: the node's contributions to ds N of its cells k-1 and k, with derivatives
   !> in slots 1-3 (new e_k-1) and 4-6 (new e_k).
   subroutine add_node_bending(self, k, fa, fb, with_jacobian)
      class(rod3d_piece), intent(inout) :: self
      integer, intent(in) :: k
      type(dual), intent(in) :: fa(3), fb(3)
      logical, intent(in) :: with_jacobian
      integer :: i
      do i = 1, 3
         self%force(i, k - 1) = self%force(i, k - 1) + fa(i)%v/self%ds(k - 1)
         self%force(i, k) = self%force(i, k) + fb(i)%v/self%ds(k)
         if (.not. with_jacobian) cycle
         self%block(i, :, 0, k - 1) = self%block(i, :, 0, k - 1) + fa(i)%d(1:3)/self%ds(k - 1)
         self%block(i, :, 1, k - 1) = self%block(i, :, 1, k - 1) + fa(i)%d(4:6)/self%ds(k - 1)
         self%block(i, :, -1, k) = self%block(i, :, -1, k) + fb(i)%d(1:3)/self%ds(k)
         self%block(i, :, 0, k) = self%block(i, :, 0, k) + fb(i)%d(4:6)/self%ds(k)
      end do
   end subroutine add_node_bending

   !> Residual (and Jacobian) of the static equilibrium at time t: the exact gradient of U.
   module subroutine rod3d_static_system(self, x, t, residual, jacobian, with_jacobian)
      !> Piece.
      class(rod3d_piece), intent(inout) :: self
      !> Unknowns, 4 per node.
      real(dp), intent(in) :: x(:)
      !> Time of the loads and held positions, s.
      real(dp), intent(in) :: t
      !> Scaled residual.
      real(dp), intent(out) :: residual(:)
      !> Jacobian (band storage).
      type(band_matrix), intent(inout) :: jacobian
      !> Whether to form the Jacobian.
      logical, intent(in) :: with_jacobian
      integer :: c, n, k, i
      real(dp) :: f, fp, tc(3), r(3, self%n), psi(self%n)
      type(dual) :: a(3), b(3), na, nb, cosine, coef
      n = self%n
      call rod3d_unpack(x, r, psi)
      call self%geometry(r, self%e1, self%l1, self%th1)
      self%block = 0
      do c = 1, n - 1
         if (allocated(self%sections)) then
            call self%sections(self%cell_sec(c))%law%tension_stiffness(self%l1(c) - 1, f, fp)
         else
            call self%law%tension_stiffness(self%l1(c) - 1, f, fp)
         end if
         tc = self%e1(:, c)/self%l1(c)
         self%force(:, c) = f*tc
         if (with_jacobian) self%block(:, :, 0, c) = fp*outer3(tc, tc) + f/self%l1(c)*(identity3() - outer3(tc, tc))
      end do
      call add_couples(self, t, t, .false., with_jacobian)
      do k = 2, n - 1
         do i = 1, 3
            a(i) = seeded(self%e1(i, k - 1), i)
            b(i) = seeded(self%e1(i, k), i + 3)
         end do
         ! B = K (1 - c) / (1 + c), c = cos(th), K = 2 EI / h: grad B = -2 K / (1 + c)^2 grad c.
         na = sqrt(dot3(a, a))
         nb = sqrt(dot3(b, b))
         cosine = dot3(a, b)/(na*nb)
         coef = (-4*self%ei_at(k)/self%dual_length(k))/((1.0_dp + cosine)*(1.0_dp + cosine))
         call add_node_bending(self, k, (b/(na*nb) - a*(cosine/(na*na)))*coef, &
                               (a/(na*nb) - b*(cosine/(nb*nb)))*coef, &
                               with_jacobian)
      end do
      call apply_loads(self, x, 0.0_dp, 0.5_dp, with_jacobian)
      call rod3d_assemble(self, x, t, t, residual, jacobian, with_jacobian, .false., 0.5_dp)
   end subroutine rod3d_static_system

   ! ---- dual-number arithmetic ----

   !> A constant (no derivatives).
   elemental type(dual) function constant(x) result(r)
      !> Value.
      real(dp), intent(in) :: x
      r%v = x
      r%d = 0
   end function constant

   !> Input i with value x (derivative 1 in slot i).
   elemental type(dual) function seeded(x, i) result(r)
      !> Value.
      real(dp), intent(in) :: x
      !> Slot.
      integer, intent(in) :: i
      r%v = x
      r%d = 0
      r%d(i) = 1
   end function seeded

   elemental type(dual) function add_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v + b%v
      r%d = a%d + b%d
   end function add_dd

   elemental type(dual) function add_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v + b
      r%d = a%d
   end function add_dr

   elemental type(dual) function add_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a + b%v
      r%d = b%d
   end function add_rd

   elemental type(dual) function sub_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v - b%v
      r%d = a%d - b%d
   end function sub_dd

   elemental type(dual) function sub_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v - b
      r%d = a%d
   end function sub_dr

   elemental type(dual) function sub_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a - b%v
      r%d = -b%d
   end function sub_rd

   elemental type(dual) function neg_d(a) result(r)
      type(dual), intent(in) :: a
      r%v = -a%v
      r%d = -a%d
   end function neg_d

   elemental type(dual) function mul_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v*b%v
      r%d = a%d*b%v + a%v*b%d
   end function mul_dd

   elemental type(dual) function mul_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v*b
      r%d = a%d*b
   end function mul_dr

   elemental type(dual) function mul_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a*b%v
      r%d = a*b%d
   end function mul_rd

   elemental type(dual) function div_dd(a, b) result(r)
      type(dual), intent(in) :: a, b
      r%v = a%v/b%v
      r%d = (a%d - r%v*b%d)/b%v
   end function div_dd

   elemental type(dual) function div_dr(a, b) result(r)
      type(dual), intent(in) :: a
      real(dp), intent(in) :: b
      r%v = a%v/b
      r%d = a%d/b
   end function div_dr

   elemental type(dual) function div_rd(a, b) result(r)
      real(dp), intent(in) :: a
      type(dual), intent(in) :: b
      r%v = a/b%v
      r%d = -r%v*b%d/b%v
   end function div_rd

   elemental type(dual) function sqrt_d(a) result(r)
      type(dual), intent(in) :: a
      r%v = sqrt(a%v)
      r%d = 0.5_dp*a%d/r%v
   end function sqrt_d

   !> Dot product of two 3-vectors.
   pure type(dual) function dot3(a, b) result(r)
      type(dual), intent(in) :: a(3), b(3)
      r = a(1)*b(1) + a(2)*b(2) + a(3)*b(3)
   end function dot3
end submodule xcable_model_rod3d_statics
