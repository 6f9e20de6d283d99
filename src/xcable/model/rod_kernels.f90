!> The planar rod's arithmetic on arrays (model/rod.f90 holds the piece that calls it): the
!> geometry of the cells (stretch vectors, lengths, turning angles, rotations), the cell
!> forces of the discrete gradient with their Jacobian blocks, the mass products, and the
!> assembly of the node residuals and of the band Jacobian. None of it knows the piece:
!> everything comes in as arrays and scalars, so that each kernel can be tested and timed
!> alone. (Split from model/rod.f90, issue 28; the operations are those it had, the same bits.)
module xcable_model_rod_kernels
   use xcable_core_kinds, only: dp, i8
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: slack_cell_force
   use xcable_numerics_atan2, only: fast_atan2, fast_atan2_array
   use xcable_numerics_tan, only: fast_tan, fast_tan_array
   use xcable_solver_banded, only: band_matrix
   implicit none
   private
   public :: perp, cross2, outer, identity2, geometry_of, turning_angles, cell_rotations_of, geometry_cells, &
             add_jacobian, cell_terms, moment_gradient_of, node_residuals
   public :: small_strain_step, small_rotation

   !> Strain differences below this use the Taylor form of the divided difference.
   real(dp), parameter :: small_strain_step = 1.0e-6_dp
   !> Rotations below this use the Taylor form of dphi / sin(dphi).
   real(dp), parameter :: small_rotation = 1.0e-4_dp

contains

   !> perp(a) = a rotated by +90 degrees, so that perp(a) . b = a x b.
   pure function perp(a) result(p)
      !> Vector.
      real(dp), intent(in) :: a(2)
      real(dp) :: p(2)
      p(1) = -a(2)
      p(2) = a(1)
   end function perp

   !> Scalar cross product a x b = a1 b2 - a2 b1. (gfortran did not inline it: the loops of
   !> this module write it out, 7.5e5 calls and 0.5 % of fast_180kN's instructions.)
   pure real(dp) function cross2(a, b)
      !> Vectors.
      real(dp), intent(in) :: a(2), b(2)
      cross2 = a(1)*b(2) - a(2)*b(1)
   end function cross2

   !> rod_geometry on explicit-shape arrays (the compiler keeps their addresses in registers).
   pure subroutine geometry_of(n, ds, r, e, l, th)
      integer, intent(in) :: n
      real(dp), intent(in) :: ds(n - 1), r(2, n)
      real(dp), intent(out) :: e(2, n - 1), l(n - 1), th(n)
      integer :: c, k, a
      do c = 1, n - 1
         ! e's two components in packed operations (the loop kept, unroll 1, for gfortran 12's
         ! loop vectorizer; the same operations): geometry_of 17.0e6 -> 15.7e6 instructions on
         ! fast_180kN, geometry_cells 5.04e6 -> 4.61e6 (callgrind).
         !GCC$ unroll 1
         do a = 1, 2
            e(a, c) = (r(a, c + 1) - r(a, c))/ds(c)
         end do
         l(c) = norm2(e(:, c))
      end do
      th = 0
      call turning_angles(n, e, th, 2, n - 1)
   end subroutine geometry_of

   !> The turning angles th(k), k = ka .. kb, of the cell vectors e: fast_atan2(e_k-1 x e_k,
   !> e_k-1 . e_k) bit for bit, by fast_atan2_array (packed SSE2 pairs) on blocks of 32 nodes
   !> (its arguments on the stack). On fast_180kN (callgrind): fast_atan2 31.6e6 -> 0.76e6
   !> instructions, with fast_atan2_array 15.0e6, geometry_of and geometry_cells 20.3e6 -> 19.2e6
   !> with this routine; the whole process 0.5887e9 -> 0.5685e9 with cell_terms' (docs/measurements/data/speed_rounds.md).
   pure subroutine turning_angles(n, e, th, ka, kb)
      integer, intent(in) :: n, ka, kb
      real(dp), intent(in) :: e(2, n - 1)
      real(dp), intent(inout) :: th(n)
      integer, parameter :: block = 32
      real(dp) :: y(block), x(block)
      integer :: first, last, k
      do first = ka, kb, block
         last = min(first + block - 1, kb)
         do k = first, last
            y(k - first + 1) = e(1, k - 1)*e(2, k) - e(2, k - 1)*e(1, k)
            x(k - first + 1) = dot_product(e(:, k - 1), e(:, k))
         end do
         call fast_atan2_array(last - first + 1, y, x, th(first:last))
      end do
   end subroutine turning_angles

   !> The rotation of the cells ca .. cb from e0 to e1, atan2(e0 x e1, e0 . e1), as cell_terms computes it
   !> (fast_atan2, the same bits; test/suite_quiescent.f90 checks).
   pure subroutine cell_rotations_of(n, e0, e1, dphi, ca, cb)
      integer, intent(in) :: n, ca, cb
      real(dp), intent(in) :: e0(2, n - 1), e1(2, n - 1)
      real(dp), intent(inout) :: dphi(n - 1)
      integer, parameter :: block = 32
      real(dp) :: y(block), x(block)
      integer :: first, last, c
      ! fast_atan2_array (packed SSE2 pairs) on blocks of 32 cells, its arguments on the stack.
      do first = ca, cb, block
         last = min(first + block - 1, cb)
         do c = first, last
            y(c - first + 1) = e0(1, c)*e1(2, c) - e0(2, c)*e1(1, c)
            x(c - first + 1) = dot_product(e0(:, c), e1(:, c))
         end do
         call fast_atan2_array(last - first + 1, y, x, dphi(first:last))
      end do
   end subroutine cell_rotations_of

   !> geometry_of on the cells ca .. cb: their vectors and lengths, and the turning angles of
   !> the nodes between two of them (ca + 1 .. cb); positions r of all n nodes (2 n).
   pure subroutine geometry_cells(n, ds, r, e, l, th, ca, cb)
      integer, intent(in) :: n, ca, cb
      real(dp), intent(in) :: ds(n - 1), r(2, n)
      real(dp), intent(inout) :: e(2, n - 1), l(n - 1), th(n)
      integer :: c, k, a
      do c = ca, cb
         ! (Packed, as in geometry_of.)
         !GCC$ unroll 1
         do a = 1, 2
            e(a, c) = (r(a, c + 1) - r(a, c))/ds(c)
         end do
         l(c) = norm2(e(:, c))
      end do
      call turning_angles(n, e, th, ca + 1, cb)
   end subroutine geometry_cells

   !> The Jacobian's terms of the cell forces and of the mass (dynamic) into band storage, on
   !> the rows and columns of the nodes lo .. hi (1 .. n for assemble, the window's for
   !> assemble_window; row and column 1 are those of node lo's first unknown). dN_c/dR_node is
   !> block(c, cp) (+-1 / ds_cp) for the two nodes of cell cp; node c gets -N_c, node c + 1
   !> gets +N_c; A(row, col) is ab(band0 + row - col, col), cleared before. Every entry gets
   !> its terms in the order of a loop over the cells c, their neighbours cp and the sides,
   !> then the mass term M_(k, k + j) / (theta dt^2) (rate), all times the row scale.
   !> The rows of the nodes whose stencil k - 2 .. k + 2 lies in the window and the piece's
   !> inner nodes (3 .. n - 2) are gathered a node at a time (gather_rows); the few others
   !> (the window's edges and the piece's ends, held ones left out) get the cells' terms
   !> added cell by cell (edge_cell) and their mass terms (mass_outer).
   pure subroutine add_jacobian(n, lo, hi, ldab, band0, ab, block, ds, mass, scale, rate, held_a, held_b, dynamic, q, &
                                mq)
      integer, intent(in) :: n, lo, hi, ldab, band0
      real(dp), intent(inout) :: ab(ldab, 2*(hi - lo + 1))
      real(dp), intent(in) :: block(2, 2, -1:1, n - 1), ds(n - 1), mass(0:2, n), scale, rate
      logical, intent(in) :: held_a, held_b, dynamic
      !> Work (gather_rows).
      real(dp), intent(inout) :: q(2, 2, -1:1, n - 1), mq(2, 2, 0:2, n)
      integer :: c, k, off, g1, g2
      off = 2*(lo - 1)
      ! The gathered nodes: both cells of each (k - 1 and k) are inner cells whose neighbours'
      ! nodes are in the window.
      g1 = max(3, lo + 2)
      g2 = min(n - 2, hi - 2)
      if (g1 <= g2) then
         ! The cells with a row outside g1 .. g2, in their order; then the gathered rows.
         do c = max(1, lo - 1), min(n - 1, hi, g1 - 1)
            call edge_cell(c, ab)
         end do
         do c = max(1, lo - 1, g2), min(n - 1, hi)
            call edge_cell(c, ab)
         end do
         call gather_rows(n, g1, g2, ldab, 2*(hi - lo + 1), band0, ab, block, ds, mass, scale, rate, dynamic, off, q, &
                          mq)
         if (.not. dynamic) return
         do k = lo, g1 - 1
            call mass_outer(k, ab)
         end do
         do k = g2 + 1, hi
            call mass_outer(k, ab)
         end do
      else
         do c = max(1, lo - 1), min(n - 1, hi)
            call edge_cell(c, ab)
         end do
         if (.not. dynamic) return
         do k = lo, hi
            call mass_outer(k, ab)
         end do
      end if

   contains

      !> The mass term on the window's columns and the rows of node k (not gathered), but
      !> those of a held end node.
      pure subroutine mass_outer(k, ab)
         integer, intent(in) :: k
         real(dp), intent(inout) :: ab(ldab, 2*(hi - lo + 1))
         integer :: a, row
         if (k == 1 .and. held_a) return
         if (k == n .and. held_b) return
         do a = 1, 2
            row = 2*(k - 1) + a - off
            if (k - 2 >= lo) ab(band0 + 4, row - 4) = ab(band0 + 4, row - 4) + mass(2, k - 2)*rate*scale
            if (k - 1 >= lo) ab(band0 + 2, row - 2) = ab(band0 + 2, row - 2) + mass(1, k - 1)*rate*scale
            ab(band0, row) = ab(band0, row) + mass(0, k)*rate*scale
            if (k + 1 <= hi) ab(band0 - 2, row + 2) = ab(band0 - 2, row + 2) + mass(1, k)*rate*scale
            if (k + 2 <= hi) ab(band0 - 4, row + 4) = ab(band0 - 4, row + 4) + mass(2, k)*rate*scale
         end do
      end subroutine mass_outer

      !> Cell c's blocks on the window's columns, added to the rows of its nodes that are in
      !> the window and not gathered, but those of a held end node.
      pure subroutine edge_cell(c, ab)
         integer, intent(in) :: c
         real(dp), intent(inout) :: ab(ldab, 2*(hi - lo + 1))
         integer :: cp, side, node, col, row
         real(dp) :: sgn, blk(2, 2)
         logical :: first, second
         first = c >= lo .and. .not. (c == 1 .and. held_a) .and. .not. (c >= g1 .and. c <= g2)
         second = c + 1 <= hi .and. .not. (c + 1 == n .and. held_b) .and. .not. (c + 1 >= g1 .and. c + 1 <= g2)
         do cp = max(1, c - 1), min(n - 1, c + 1)
            do side = 0, 1
               node = cp + side
               if (node < lo .or. node > hi) cycle
               sgn = merge(1.0_dp, -1.0_dp, side == 1)/ds(cp)
               blk = block(:, :, cp - c, c)*sgn*scale
               col = 2*(node - 1) - off
               if (first) then
                  row = 2*(c - 1) - off - col + band0
                  ab(row, col + 1) = ab(row, col + 1) - blk(1, 1)
                  ab(row + 1, col + 1) = ab(row + 1, col + 1) - blk(2, 1)
                  ab(row - 1, col + 2) = ab(row - 1, col + 2) - blk(1, 2)
                  ab(row, col + 2) = ab(row, col + 2) - blk(2, 2)
               end if
               if (second) then
                  row = 2*c - off - col + band0
                  ab(row, col + 1) = ab(row, col + 1) + blk(1, 1)
                  ab(row + 1, col + 1) = ab(row + 1, col + 1) + blk(2, 1)
                  ab(row - 1, col + 2) = ab(row - 1, col + 2) + blk(1, 2)
                  ab(row, col + 2) = ab(row, col + 2) + blk(2, 2)
               end if
            end do
         end do
      end subroutine edge_cell
   end subroutine add_jacobian

   !> add_jacobian's rows of the nodes k1 .. k2 (each with its cells k - 1 and k inner, and
   !> the columns of the nodes k - 2 .. k + 2 in ab), gathered: each entry summed in
   !> registers, in the order add_jacobian's loop over the cells gives its terms, and stored
   !> once. With q_c(j) = block(c, c + j) / ds_(c+j) * scale, the blocks cell c adds with its
   !> sign are -q_c(j) for the first node of cell c + j and +q_c(j) for its second, so the
   !> rows of node k (cells k - 1, +, and k, -; a = q_(k-1), b = q_k) in the columns of
   !> node k + d are, from the cleared 0:
   !>   d = -2: -a(-1);  d = -1: +a(-1) - a(0) + b(-1);  d = 0: +a(0) - a(1) - b(-1) + b(0);
   !>   d = 1: +a(1) - b(0) + b(1);  d = 2: -b(1);
   !> then the mass term. x - (-y) is x + y and (-y) s = -(y s) exactly, so these are the
   !> bits of adding cell by cell. The mass term is added as a diagonal 2 x 2 block (mq), so
   !> that each column's two rows stay one packed SSE2 operation: its off-diagonal zero
   !> changes nothing, because a sum that starts as 0 + y or 0 - y is never -0 (under
   !> rounding to nearest a sum or difference is -0 only from a -0 operand), and x + 0 = x
   !> for every other x; in statics mq is all zero for the same reason. q and mq are formed
   !> first, in passes of their own (1 / ds once per cell). Measured on fast_180kN lean (241
   !> nodes, no gnuplot text, no ledger; callgrind), against the former scatter cell by cell
   !> (24 read-modify-writes of two rows per cell) and the mass term added node by node:
   !> the whole run 485.5e6 -> 473.8e6 instructions, the same bits on the ten input/ cases;
   !> each column as one expression stored directly, 2.0e6 fewer again.
   !> (The mass term added to one lane of a register, or from a block built per node on the
   !> stack, cost more: 477.9e6 and 473.2e6 but no faster, the latter's packed loads waiting
   !> on two scalar stores each.)
   pure subroutine gather_rows(n, k1, k2, ldab, ncol, band0, ab, block, ds, mass, scale, rate, dynamic, off, q, mq)
      integer, intent(in) :: n, k1, k2, ldab, ncol, band0, off
      real(dp), intent(inout) :: ab(ldab, ncol)
      real(dp), intent(in) :: block(2, 2, -1:1, n - 1), ds(n - 1), mass(0:2, n), scale, rate
      logical, intent(in) :: dynamic
      real(dp), intent(inout) :: q(2, 2, -1:1, n - 1), mq(2, 2, 0:2, n)
      real(dp) :: r_m, r_0, r_p, w
      integer :: c, k, j, a, b, row, col
      if (k1 > k2) return
      ! q_c for the cells k1 - 1 .. k2.
      r_m = 1/ds(k1 - 2)
      r_0 = 1/ds(k1 - 1)
      do c = k1 - 1, k2
         r_p = 1/ds(c + 1)
         do b = 1, 2
            !GCC$ unroll 1
            do a = 1, 2
               q(a, b, -1, c) = block(a, b, -1, c)*r_m*scale
            end do
            !GCC$ unroll 1
            do a = 1, 2
               q(a, b, 0, c) = block(a, b, 0, c)*r_0*scale
            end do
            !GCC$ unroll 1
            do a = 1, 2
               q(a, b, 1, c) = block(a, b, 1, c)*r_p*scale
            end do
         end do
         r_m = r_0
         r_0 = r_p
      end do
      ! The mass terms of the nodes k1 - 2 .. k2 as diagonal 2 x 2 blocks (zero in statics).
      w = 0
      do k = k1 - 2, k2
         do j = 0, 2
            if (dynamic) w = mass(j, k)*rate*scale
            mq(1, 1, j, k) = w
            mq(2, 1, j, k) = 0
            mq(1, 2, j, k) = 0
            mq(2, 2, j, k) = w
         end do
      end do
      ! Node k's rows, column by column (d = -2 .. 2, then the component b): the sum, then the
      ! mass block, in one expression evaluated from the left.
      do k = k1, k2
         row = 2*(k - 1) + 1 - off
         do b = 1, 2
            col = 2*(k - 3) + b - off
            !GCC$ unroll 1
            do a = 1, 2
               ab(band0 + row + a - 1 - col, col) = 0.0_dp - q(a, b, -1, k - 1) + mq(a, b, 2, k - 2)
            end do
            col = col + 2
            !GCC$ unroll 1
            do a = 1, 2
               ab(band0 + row + a - 1 - col, col) = 0.0_dp + q(a, b, -1, k - 1) - q(a, b, 0, k - 1) + q(a, b, -1, k) &
                                                    + mq(a, b, 1, k - 1)
            end do
            col = col + 2
            !GCC$ unroll 1
            do a = 1, 2
               ab(band0 + row + a - 1 - col, col) = 0.0_dp + q(a, b, 0, k - 1) - q(a, b, 1, k - 1) - q(a, b, -1, k) &
                                                    + q(a, b, 0, k) + mq(a, b, 0, k)
            end do
            col = col + 2
            !GCC$ unroll 1
            do a = 1, 2
               ab(band0 + row + a - 1 - col, col) = 0.0_dp + q(a, b, 1, k - 1) - q(a, b, 0, k) + q(a, b, 1, k) &
                                                    + mq(a, b, 1, k)
            end do
            col = col + 2
            !GCC$ unroll 1
            do a = 1, 2
               ab(band0 + row + a - 1 - col, col) = 0.0_dp - q(a, b, 1, k) + mq(a, b, 2, k)
            end do
         end do
      end do
   end subroutine gather_rows

   !> The cell forces N_c and, with_jacobian, their blocks dN_c/de_c' of a step (rod_step_system's
   !> loop over the cells) on explicit-shape arrays, so that the compiler keeps their addresses in
   !> registers; couple_first and couple_last: cell_couple of cells 1 and n - 1; the cells ca .. cb only.
   !>
   !> The cells go in blocks of 32 (cell_block_terms): the law's q and dq and rho(dphi) cell by cell
   !> (they call functions), then the forces and blocks of the block's inner cells by one loop over
   !> the cells that gfortran 12's loop vectoriser packs two cells to an SSE2 operation (one divpd
   !> for two divisions); the end cells 1 and n - 1 (a couple, one neighbour) by end_cell_terms.
   !> Element by element the operations are those of the loop over the cells they replace
   !> (end_cell_terms is its body), in the same order, so the same bits (test/suite_rod.f90,
   !> cell_terms_blocks_same_bits). Why: that loop packed only a cell's two rows, its per-cell
   !> scalars (q, lsum, g, the divisions by l1, lsum, l0 l1, ds_c) one at a time, with broadcasts
   !> and spills around them. Measured on a lean fast_180kN run (241 nodes, no figures, no
   !> ledger): cell_terms 128.7e6 -> 110.9e6 instructions with its callees, the division
   !> instructions in it 7.27e6 -> 5.83e6, the whole run 504.0e6 -> 486.5e6 (-3.5 %); docs/measurements/data/speed_rounds.md,
   !> "cell_terms in blocks, fifth round (bit for bit)".
   subroutine cell_terms(n, law, e0_, e1_, l0_, l1_, ds, mom, dmom, damping, dt, couple_first, couple_last, &
                         with_jacobian, force, block, dphi1, ca, cb)
      integer, intent(in) :: n
      class(material_law), intent(in) :: law
      real(dp), intent(in) :: e0_(2, n - 1), e1_(2, n - 1), l0_(n - 1), l1_(n - 1), ds(n - 1), mom(n), &
                              dmom(n), damping, dt, couple_first, couple_last
      logical, intent(in) :: with_jacobian
      real(dp), intent(inout) :: force(2, n - 1), block(2, 2, -1:1, n - 1)
      !> Rotation of each cell from e0 to e1, rad.
      real(dp), intent(inout) :: dphi1(n - 1)
      !> First and last cell to compute.
      integer, intent(in) :: ca, cb
      integer, parameter :: nb = 32
      integer :: first, last
      ! The cells' rotations first, in packed pairs (cell_rotations_of, fast_atan2_array), the
      ! same bits: cell_terms with cell_rotations_of 77.5e6 -> 76.3e6 instructions on fast_180kN.
      call cell_rotations_of(n, e0_, e1_, dphi1, ca, cb)
      do first = ca, cb, nb
         last = min(first + nb - 1, cb)
         call cell_block_terms(n, law, e0_, e1_, l0_, l1_, ds, mom, dmom, damping, dt, couple_first, couple_last, &
                               with_jacobian, force, block, dphi1, first, last)
      end do
   end subroutine cell_terms

   !> cell_terms on the cells first .. last (at most 32), the rotations dphi1 given. Per cell of
   !> the block (index p, cell first + p - 1), written out:
   !>   q = (W1 - W0) / h (law) or its Taylor form, + c h / dt (a law with a kink: slack_cell_force); N_c = q wsum / lsum + S_c / ds_c gvec,
   !>   gvec = perp(wsum / 2) g, g = rho(dphi) / (l0 l1), wsum = e0 + e1, lsum = l0 + l1;
   !>   ds_dq = dq e1 / l1, dstrain = outer(wsum / lsum, ds_dq)
   !>     + q (identity2() / lsum - outer(wsum, e1 / l1) / lsum**2),
   !>   dg_de = drho dphi_de / (l0 l1) - rho / (l0 l1**2) e1 / l1, dphi_de = perp(e1) / l1**2,
   !>   dgvec = 0.5 g jm + outer(pem, dg_de), block_0 = dstrain + s_c / ds_c dgvec
   !>     + outer(gvec, ds_de(:, 0)) / ds_c, block_+-1 = outer(gvec, ds_de(:, +-1)) / ds_c,
   !>   ds_de = moment_gradient_of.
   subroutine cell_block_terms(n, law, e0_, e1_, l0_, l1_, ds, mom, dmom, damping, dt, couple_first, couple_last, &
                               with_jacobian, force, block, dphi1, first, last)
      integer, intent(in) :: n
      class(material_law), intent(in) :: law
      real(dp), intent(in) :: e0_(2, n - 1), e1_(2, n - 1), l0_(n - 1), l1_(n - 1), ds(n - 1), mom(n), &
                              dmom(n), damping, dt, couple_first, couple_last, dphi1(n - 1)
      logical, intent(in) :: with_jacobian
      real(dp), intent(inout) :: force(2, n - 1), block(2, 2, -1:1, n - 1)
      integer, intent(in) :: first, last
      integer, parameter :: nb = 32
      integer :: m, p, c, pa, pb
      real(dp) :: f, fp, fpp, mid, lsum, qq, dqq, w1, w2, g, pem1, pem2, gv1, gv2, sd, l0, l1, e11, e12, &
                  dsdq1, dsdq2, wl1, wl2, e1l1, e1l2, dpd1, dpd2, rl, dg1, dg2, d01, d02, dm1, dm2, dp1, dp2, &
                  il, zl, ls2, hg, kv
      logical :: slack
      real(dp) :: eps0(nb), eps1(nb), h(nb), qv(nb), dqv(nb), rhov(nb), drhov(nb)
      real(dp), parameter :: jm(2, 2) = reshape([0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp], [2, 2]), &
                             id2(2, 2) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
      m = last - first + 1
      !GCC$ unroll 1
      do p = 1, m
         eps0(p) = l0_(first + p - 1) - 1
         eps1(p) = l1_(first + p - 1) - 1
         h(p) = eps1(p) - eps0(p)
         ! rho(dphi) = dphi / sin(dphi) and its derivative: the Taylor form here, the others below.
         rhov(p) = 1 + dphi1(first + p - 1)**2/6
         drhov(p) = dphi1(first + p - 1)/3
      end do
      ! A rope that cannot push (a law with a kink at strain_slack): q and dq with its damping
      ! from slack_cell_force, the damping below kv = 0; else the damping below, c h / dt.
      slack = law%strain_slack > -huge(1.0_dp)
      kv = damping
      if (slack) kv = 0
      ! Cell by cell, what calls a function.
      do p = 1, m
         ! Strain part: q (e0 + e1) / (l0 + l1), q the divided difference of W.
         if (slack) then
            call slack_cell_force(law, eps0(p), eps1(p), damping, dt, small_strain_step, qv(p), dqv(p))
         else if (abs(h(p)) < small_strain_step) then
            mid = 0.5_dp*(eps0(p) + eps1(p))
            ! f, f', f'' in one call (the tanh law: one tanh and 1 / cosh^2 together).
            call law%tension_stiffness_slope(mid, f, fp, fpp)
            qv(p) = f + fpp*h(p)*h(p)/24
            dqv(p) = 0.5_dp*fp + fpp*h(p)/12
         else
            ! W1 - W0 from the law, not a difference of two W: that loses digits
            ! (tanh_strain_energy_change). No W itself: only the ledger uses it (rod_energies).
            ! dq only enters the blocks: a residual alone does not ask for the law's tension.
            if (with_jacobian) then
               call law%strain_energy_change_tension(eps0(p), eps1(p), qv(p), f)
               qv(p) = qv(p)/h(p)
               dqv(p) = (f - qv(p))/h(p)
            else
               qv(p) = law%strain_energy_change(eps0(p), eps1(p))/h(p)
               dqv(p) = 0
            end if
         end if
         associate (dphi => dphi1(first + p - 1))
            if (.not. abs(dphi) < small_rotation) then
               rhov(p) = dphi/sin(dphi)
               drhov(p) = (sin(dphi) - dphi*cos(dphi))/sin(dphi)**2
            end if
         end associate
      end do
      ! The inner cells (two neighbours, no couple), packed. The scalars are the loop's names
      ! written per component: qq, dqq (q, dq with the damping), w (wsum), gv (gvec), sd (s_c / ds_c),
      ! dsdq (ds_dq), dpd (dphi_de), dg (dg_de), d0, dm, dp (ds_de(:, 0), (:, -1), (:, 1)), il and zl
      ! (identity2() / lsum: 1 / lsum, 0 / lsum), hg (0.5 g). The operations on a zero (0 / lsum,
      ! 0 + ..., hg jm(1, 1)) stay: signed zeros ("cell_terms, third round").
      pa = max(first, 2) - first + 1
      pb = min(last, n - 2) - first + 1
      if (with_jacobian) then
         !GCC$ unroll 1
         do p = pa, pb
            c = first + p - 1
            l0 = l0_(c)
            l1 = l1_(c)
            e11 = e1_(1, c)
            e12 = e1_(2, c)
            lsum = l0 + l1
            ! Kelvin-Voigt damping: c (eps1 - eps0) / dt along the same direction; its
            ! work in the step, ds c (eps1 - eps0)^2 / dt, is the energy it dissipates.
            qq = qv(p) + kv*h(p)/dt
            dqq = dqv(p) + kv/dt
            w1 = e0_(1, c) + e11
            w2 = e0_(2, c) + e12
            g = rhov(p)/(l0*l1)
            pem1 = -(0.5_dp*w2)
            pem2 = 0.5_dp*w1
            gv1 = pem1*g
            gv2 = pem2*g
            sd = (mom(c) - mom(c + 1))/ds(c)
            force(1, c) = qq*w1/lsum + sd*gv1
            force(2, c) = qq*w2/lsum + sd*gv2
            dsdq1 = dqq*e11/l1
            dsdq2 = dqq*e12/l1
            wl1 = w1/lsum
            wl2 = w2/lsum
            e1l1 = e11/l1
            e1l2 = e12/l1
            dpd1 = -e12/l1**2
            dpd2 = e11/l1**2
            rl = rhov(p)/(l0*l1**2)
            dg1 = drhov(p)*dpd1/(l0*l1) - rl*e11/l1
            dg2 = drhov(p)*dpd2/(l0*l1) - rl*e12/l1
            ! moment_gradient_of (its dth is dphi_de).
            d01 = 0 + dmom(c)*dpd1 + dmom(c + 1)*dpd1
            d02 = 0 + dmom(c)*dpd2 + dmom(c + 1)*dpd2
            dm1 = -(dmom(c)*(-e1_(2, c - 1))/l1_(c - 1)**2)
            dm2 = -(dmom(c)*e1_(1, c - 1)/l1_(c - 1)**2)
            dp1 = -(dmom(c + 1)*(-e1_(2, c + 1))/l1_(c + 1)**2)
            dp2 = -(dmom(c + 1)*e1_(1, c + 1)/l1_(c + 1)**2)
            il = id2(1, 1)/lsum
            zl = id2(2, 1)/lsum
            ls2 = lsum**2
            hg = 0.5_dp*g
            block(1, 1, 0, c) = wl1*dsdq1 + qq*(il - w1*e1l1/ls2) + sd*(hg*jm(1, 1) + pem1*dg1) + gv1*d01/ds(c)
            block(2, 1, 0, c) = wl2*dsdq1 + qq*(zl - w2*e1l1/ls2) + sd*(hg*jm(2, 1) + pem2*dg1) + gv2*d01/ds(c)
            block(1, 2, 0, c) = wl1*dsdq2 + qq*(zl - w1*e1l2/ls2) + sd*(hg*jm(1, 2) + pem1*dg2) + gv1*d02/ds(c)
            block(2, 2, 0, c) = wl2*dsdq2 + qq*(il - w2*e1l2/ls2) + sd*(hg*jm(2, 2) + pem2*dg2) + gv2*d02/ds(c)
            block(1, 1, -1, c) = gv1*dm1/ds(c)
            block(2, 1, -1, c) = gv2*dm1/ds(c)
            block(1, 2, -1, c) = gv1*dm2/ds(c)
            block(2, 2, -1, c) = gv2*dm2/ds(c)
            block(1, 1, 1, c) = gv1*dp1/ds(c)
            block(2, 1, 1, c) = gv2*dp1/ds(c)
            block(1, 2, 1, c) = gv1*dp2/ds(c)
            block(2, 2, 1, c) = gv2*dp2/ds(c)
         end do
      else
         !GCC$ unroll 1
         do p = pa, pb
            c = first + p - 1
            lsum = l0_(c) + l1_(c)
            qq = qv(p) + kv*h(p)/dt
            w1 = e0_(1, c) + e1_(1, c)
            w2 = e0_(2, c) + e1_(2, c)
            g = rhov(p)/(l0_(c)*l1_(c))
            gv1 = -(0.5_dp*w2)*g
            gv2 = (0.5_dp*w1)*g
            sd = (mom(c) - mom(c + 1))/ds(c)
            force(1, c) = qq*w1/lsum + sd*gv1
            force(2, c) = qq*w2/lsum + sd*gv2
         end do
      end if
      ! The end cells (as an inner cell, but with the couple and one neighbour).
      if (first == 1) call end_cell_terms(n, 1, e0_, e1_, l0_, l1_, ds, mom, dmom, kv, dt, couple_first, &
                                          with_jacobian, qv(1), dqv(1), rhov(1), drhov(1), h(1), force, block)
      if (last == n - 1 .and. n > 2) &
         call end_cell_terms(n, n - 1, e0_, e1_, l0_, l1_, ds, mom, dmom, kv, dt, couple_last, with_jacobian, &
                             qv(m), dqv(m), rhov(m), drhov(m), h(m), force, block)
   end subroutine cell_block_terms

   !> The force and, with_jacobian, the blocks of cell c as the loop over the cells computed them
   !> (cell_block_terms' inner cells the same bits), from its law's q and dq, rho(dphi), its
   !> derivative drho and the strain step h: for the end cells 1 and n - 1 (couple: cell_couple).
   pure subroutine end_cell_terms(n, c, e0_, e1_, l0_, l1_, ds, mom, dmom, damping, dt, couple, with_jacobian, &
                                  q0, dq0, rho, drho, h, force, block)
      integer, intent(in) :: n, c
      real(dp), intent(in) :: e0_(2, n - 1), e1_(2, n - 1), l0_(n - 1), l1_(n - 1), ds(n - 1), mom(n), &
                              dmom(n), damping, dt, couple, q0, dq0, rho, drho, h
      logical, intent(in) :: with_jacobian
      real(dp), intent(inout) :: force(2, n - 1), block(2, 2, -1:1, n - 1)
      real(dp), parameter :: jm(2, 2) = reshape([0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp], [2, 2]), &
                             id2(2, 2) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
      real(dp) :: q, dq, lsum, em(2), g, gvec(2), s_c, ds_dq(2), dg_de(2), dphi_de(2), dstrain(2, 2), &
                  dgvec(2, 2), ds_de(2, -1:1), wsum(2), pem(2), wl(2), e1l(2), fq(2)
      integer :: i, j
      associate (e0 => e0_(:, c), e1 => e1_(:, c), l0 => l0_(c), l1 => l1_(c))
         q = q0
         dq = dq0
         lsum = l0 + l1
         !GCC$ unroll 1
         do i = 1, 2
            wsum(i) = e0(i) + e1(i)
         end do
         q = q + damping*h/dt
         dq = dq + damping/dt
         !GCC$ unroll 1
         do i = 1, 2
            fq(i) = q*wsum(i)/lsum
         end do
         !GCC$ unroll 1
         do i = 1, 2
            em(i) = 0.5_dp*wsum(i)
         end do
         g = rho/(l0*l1)
         pem(1) = -em(2)
         pem(2) = em(1)
         gvec = pem*g
         s_c = mom(c) - mom(c + 1) - couple
         !GCC$ unroll 1
         do i = 1, 2
            force(i, c) = fq(i) + s_c/ds(c)*gvec(i)
         end do
         if (.not. with_jacobian) return
         !GCC$ unroll 1
         do i = 1, 2
            ds_dq(i) = dq*e1(i)/l1
         end do
         !GCC$ unroll 1
         do i = 1, 2
            wl(i) = wsum(i)/lsum
         end do
         !GCC$ unroll 1
         do i = 1, 2
            e1l(i) = e1(i)/l1
         end do
         dphi_de = [-e1(2), e1(1)]/l1**2
         !GCC$ unroll 1
         do i = 1, 2
            dg_de(i) = drho*dphi_de(i)/(l0*l1) - rho/(l0*l1**2)*e1(i)/l1
         end do
         ds_de = moment_gradient_of(n, c, e1_, l1_, dmom)
         do j = 1, 2
            !GCC$ unroll 1
            do i = 1, 2
               dstrain(i, j) = wl(i)*ds_dq(j) + q*(id2(i, j)/lsum - wsum(i)*e1l(j)/lsum**2)
            end do
            !GCC$ unroll 1
            do i = 1, 2
               dgvec(i, j) = 0.5_dp*g*jm(i, j) + pem(i)*dg_de(j)
            end do
            !GCC$ unroll 1
            do i = 1, 2
               block(i, j, 0, c) = dstrain(i, j) + s_c/ds(c)*dgvec(i, j) + gvec(i)*ds_de(j, 0)/ds(c)
            end do
            !GCC$ unroll 1
            do i = 1, 2
               block(i, j, -1, c) = gvec(i)*ds_de(j, -1)/ds(c)
            end do
            !GCC$ unroll 1
            do i = 1, 2
               block(i, j, 1, c) = gvec(i)*ds_de(j, 1)/ds(c)
            end do
         end do
      end associate
   end subroutine end_cell_terms

   !> moment_difference_gradient on explicit-shape arrays.
   pure function moment_gradient_of(n, c, e1, l1, dmom) result(d)
      integer, intent(in) :: n, c
      real(dp), intent(in) :: e1(2, n - 1), l1(n - 1), dmom(n)
      real(dp) :: d(2, -1:1), dth(2)
      d = 0
      ! perp written out (not inlined by gfortran).
      dth = [-e1(2, c), e1(1, c)]/l1(c)**2
      if (c >= 2) then
         d(:, 0) = d(:, 0) + dmom(c)*dth
         d(:, -1) = -dmom(c)*[-e1(2, c - 1), e1(1, c - 1)]/l1(c - 1)**2
      end if
      if (c + 1 <= n - 1) then
         d(:, 0) = d(:, 0) + dmom(c + 1)*dth
         d(:, 1) = -dmom(c + 1)*[-e1(2, c + 1), e1(1, c + 1)]/l1(c + 1)**2
      end if
   end function moment_gradient_of

   !> The node residuals of assemble before the held ends' rows, on explicit-shape arrays:
   !> N_k - N_k-1, the weight (w1, wn at the end nodes, weight lumped(k) inside), the loads,
   !> the applied forces at the ends and, dynamic, the inertia [M (V^n+1 - V^n)]_k / dt, all
   !> over T_ref (times scale). Each node's two rows are summed in one go, their terms in the
   !> order of the former passes over the residual (one for each kind of term) and M V^n+1 in
   !> mass_product's, so the same bits in 0.8 % fewer instructions on fast_180kN (callgrind).
   !> The rows of the nodes k1 .. k2 (1 .. n for assemble, the window's for assemble_window).
   pure subroutine node_residuals(n, k1, k2, force, w1, wn, weight, lumped, load_node, fext_a, fext_b, dynamic, mass, &
                                  v1, mv0, dt, scale, residual)
      integer, intent(in) :: n, k1, k2
      real(dp), intent(in) :: force(2, n - 1), w1, wn, weight, lumped(n), load_node(2, n), fext_a(2), fext_b(2)
      logical, intent(in) :: dynamic
      real(dp), intent(in) :: mass(0:2, n), v1(2, n), mv0(2, n), dt, scale
      real(dp), intent(out) :: residual(2, k1:k2)
      integer :: k, a
      real(dp) :: res(2), mv(2), g(2)
      ! The weight enters both rows of an inner node as (-0, weight) lumped(k): lumped(k) > 0
      ! (half the lengths of its cells), so row 1 gains -0, and x + (-0) = x for every x: the
      ! same bits, and the pair stays one register (res(2) alone went through the stack: a
      ! packed load right after a scalar store, which waits). node_residuals 17.38e6 ->
      ! 16.63e6 instructions on fast_180kN, process CPU about -2 % (docs/measurements/data/speed_rounds.md).
      g = [-0.0_dp, weight]
      do k = k1, k2
         if (dynamic .and. k >= 3 .and. k <= n - 2) then
            ! An inner node of a step: the operations of the general case below, in its order,
            ! the two rows in packed SSE2 operations (the loops over a kept as loops, unroll 1,
            ! so that gfortran 12's loop vectorizer packs them: node_residuals 23.9e6 -> 17.4e6
            ! instructions on fast_180kN, callgrind).
            !GCC$ unroll 1
            do a = 1, 2
               res(a) = ((0.0_dp + force(a, k - 1)) - force(a, k)) + g(a)*lumped(k)
               mv(a) = (((mass(0, k)*v1(a, k) + mass(1, k - 1)*v1(a, k - 1)) + mass(1, k)*v1(a, k + 1)) &
                        + mass(2, k - 2)*v1(a, k - 2)) + mass(2, k)*v1(a, k + 2)
               residual(a, k) = ((res(a) - load_node(a, k)) + (mv(a) - mv0(a, k))/dt)*scale
            end do
            cycle
         end if
         res = 0
         if (k > 1) res = res + force(:, k - 1)
         if (k < n) res = res - force(:, k)
         if (k == 1) then
            res(2) = res(2) + w1
         else if (k == n) then
            res(2) = res(2) + wn
         else
            res(2) = res(2) + weight*lumped(k)
         end if
         res = res - load_node(:, k)
         if (k == 1) res = res - fext_a
         if (k == n) res = res - fext_b
         if (dynamic) then
            ! (M V^n+1)_k in mass_product's order.
            if (k >= 3 .and. k <= n - 2) then
               mv = (((mass(0, k)*v1(:, k) + mass(1, k - 1)*v1(:, k - 1)) + mass(1, k)*v1(:, k + 1)) &
                     + mass(2, k - 2)*v1(:, k - 2)) + mass(2, k)*v1(:, k + 2)
            else
               mv = mass(0, k)*v1(:, k)
               if (k >= 2) mv = mv + mass(1, k - 1)*v1(:, k - 1)
               if (k <= n - 1) mv = mv + mass(1, k)*v1(:, k + 1)
               if (k >= 3) mv = mv + mass(2, k - 2)*v1(:, k - 2)
               if (k <= n - 2) mv = mv + mass(2, k)*v1(:, k + 2)
            end if
            res = res + (mv - mv0(:, k))/dt
         end if
         residual(:, k) = res*scale
      end do
   end subroutine node_residuals

   pure function outer(a, b) result(m)
      real(dp), intent(in) :: a(2), b(2)
      real(dp) :: m(2, 2)
      m(:, 1) = a*b(1)
      m(:, 2) = a*b(2)
   end function outer

   pure function identity2() result(m)
      real(dp) :: m(2, 2)
      m = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
   end function identity2
end module xcable_model_rod_kernels
