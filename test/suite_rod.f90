!> The discrete rod (model/rod.f90): its analytic Jacobians (statics and time
!> steps) against central differences entry by entry, through the generic
!> check every model shares; and the discrete gradient, which must give the
!> exact change of the stored energy for any two states.
module suite_rod
   use xcable_core_kinds, only: dp, i8
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_strings, only: str
   use xcable_material_law, only: material_law, tanh_law, linear_law
   use xcable_numerics_atan2, only: fast_atan2
   use xcable_material_tension_only, only: new_tension_only
   use xcable_material_table, only: table_law, new_table_law
   use xcable_model_rod, only: rod_problem, rod_piece, rod_kl, rod_ku, cell_terms, bend_nodes, small_rotation
   use xcable_numerics_tan, only: fast_tan
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_force, only: force_end
   use xcable_ends_mass, only: mass_end
   use xcable_ends_motion, only: motion_end
   use xcable_solver_banded, only: band_matrix
   use xcable_fdcheck, only: check_jacobian
   use, intrinsic :: iso_fortran_env, only: output_unit, int64
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
   implicit none
   private
   public :: collect_rod

   integer, parameter :: n = 9
   !> model/rod.f90's, for cell_terms_reference.
   real(dp), parameter :: small_strain_step_ = 1.0e-6_dp, small_rotation_ = 1.0e-4_dp

contains

   subroutine collect_rod(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('jacobian_statics', test_static_jacobian), &
               new_unittest('jacobian_step_averaged', test_step_averaged), &
               new_unittest('jacobian_step_lumped_theta_0.7', test_step_lumped), &
               new_unittest('jacobian_step_mass_ends_tension_only', test_step_mass_ends), &
               new_unittest('jacobian_step_table_law_damping', test_step_table_damping), &
               new_unittest('jacobian_step_small_rotations_stiff', test_step_small_rotations), &
               new_unittest('discrete_gradient_exact', test_discrete_gradient), &
               new_unittest('old_level_from_last_evaluation', test_old_level_memo), &
               new_unittest('residual_alone_same_bits', test_residual_alone), &
               new_unittest('energies_kinetic_and_gravity', test_energies_kinetic_gravity), &
               new_unittest('cell_terms_blocks_same_bits', test_cell_terms_blocks), &
               new_unittest('bend_terms_in_pairs_same_bits', test_bend_terms_same_bits)]
   end subroutine collect_rod

   !> bend_nodes (model/rod.f90: the bending terms of a step in packed pairs, without
   !> branches in the common case, bend_arguments and bend_divided_array) against the
   !> per-node forms written out here as the code had them, every result by its bits:
   !> the argument of tan by a branch on |th1 - th0| < small_rotation, then the Taylor form
   !> or the divided difference. 2 10^5 reproducible nodes, th0 in [-3, 3], th1 - th0 in
   !> five families: below small_rotation (log-uniform from 1e-14, the Taylor branch),
   !> above it up to 1, within four units of small_rotation (either side, the limit itself
   !> included), +-0, and NaN or infinite; in pieces of 1 to 40 nodes that alternate
   !> between all Taylor and mixed (152796 Taylor nodes). Mutations seen to fail: the mask
   !> without the sign bit's copy (shiftr for shifta in bend_argument: 132796 nodes
   !> differ), the array's test of `others` reversed (`others < 0`: all 47204 other nodes
   !> differ), its second loop on |h| > small_rotation (NaN and the limit: 9986),
   !> bend_moment_of as 2 EI (t (1 + t^2)) / h_k (49165). (The Taylor correction of m with
   !> h h grouped first changes no node: it is about 1e-9 of m.)
   subroutine test_bend_terms_same_bits(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: total = 200000
      type(rod_piece) :: p
      real(dp) :: v(3), sg, h, x, t, third, m, dm, b1
      logical :: ok
      integer(i8) :: state
      integer :: k, first, last, bad, taylor
      allocate (p%th0(total), p%th1(total), p%dual(total), p%b0(total), p%mom(total), p%dmom(total), &
                p%memo_b(total), p%memo_b_ok(total))
      p%ei = 70.6_dp
      state = 20261202_i8
      do k = 1, total
         v = [uniform(state), uniform(state), uniform(state)]
         sg = merge(-1.0_dp, 1.0_dp, v(3) < 0.5_dp)
         p%th0(k) = 6*v(2) - 3
         p%dual(k) = 0.1_dp + v(3)
         p%b0(k) = 10*v(1)*v(2)
         if (mod(k/500, 2) == 0) then
            h = sg*10.0_dp**(-14 + 10*v(1))
         else
            select case (mod(k, 5))
            case (0)
               h = sg*10.0_dp**(-14 + 10*v(1))
            case (1)
               h = sg*10.0_dp**(-4 + 4*v(1))
            case (2)
               h = sg*(small_rotation + (int(9*v(1)) - 4)*spacing(small_rotation))
            case (3)
               h = sg*0.0_dp
            case default
               h = merge(ieee_value(1.0_dp, ieee_quiet_nan), sg*ieee_value(1.0_dp, ieee_positive_inf), v(1) < 0.5_dp)
            end select
         end if
         p%th1(k) = p%th0(k) + h
      end do
      first = 1
      do while (first <= total)
         last = min(total, first + int(40*uniform(state)))
         call bend_nodes(p, first, last)
         first = last + 1
      end do
      bad = 0
      taylor = 0
      do k = 1, total
         associate (ei => p%ei, hk => p%dual(k), th0 => p%th0(k), th1 => p%th1(k))
            h = th1 - th0
            if (abs(h) < small_rotation) then
               taylor = taylor + 1
               x = 0.5_dp*(0.5_dp*(th0 + th1))
               t = fast_tan(x)
               third = ei*(1 + t*t)*t*(4 + 6*t*t)/hk
               m = 2*ei*t*(1 + t*t)/hk + third*h*h/24
               dm = 0.5_dp*(ei*(1 + t*t)*(1 + 3*t*t)/hk) + third*h/12
               b1 = 0
               ok = .false.
            else
               t = fast_tan(0.5_dp*th1)
               b1 = 2*ei*t**2/hk
               ok = .true.
               m = (b1 - p%b0(k))/h
               dm = (2*ei*t*(1 + t*t)/hk - m)/h
            end if
         end associate
         if (transfer(p%mom(k), 0_i8) /= transfer(m, 0_i8) .or. transfer(p%dmom(k), 0_i8) /= transfer(dm, 0_i8) &
             .or. transfer(p%memo_b(k), 0_i8) /= transfer(b1, 0_i8) .or. (p%memo_b_ok(k) .neqv. ok)) bad = bad + 1
      end do
      call check(error, bad == 0 .and. taylor > total/2 .and. taylor < total, &
                 'bend_nodes: '//str(bad)//' of '//str(total)//' nodes differ from the per-node forms in their bits ('// &
                 str(taylor)//' Taylor nodes)')
   end subroutine test_bend_terms_same_bits

   !> Uniform in [0, 1) from a 64-bit linear congruential generator (reproducible everywhere).
   real(dp) function uniform(state)
      integer(i8), intent(inout) :: state
      state = state*6364136223846793005_i8 + 1442695040888963407_i8
      uniform = real(shiftr(state, 11), dp)*2.0_dp**(-53)
   end function uniform

   !> A piece of 9 nodes: end a held (fixed or moving), end b loaded (force
   !> ramp with a couple, or a point mass); a curved state with a strongly
   !> compressed and rotated cell.
   subroutine make_piece(p, x, r0, v0, mu, mu2, tension_only, mass_at_b)
      type(rod_problem), intent(out) :: p
      real(dp), allocatable, intent(out) :: x(:), r0(:, :), v0(:, :)
      real(dp), intent(in) :: mu, mu2
      logical, intent(in) :: tension_only, mass_at_b
      type(force_end) :: fb
      real(dp) :: s(n)
      integer :: k
      s = [(6.0_dp*(k - 1)/(n - 1), k=1, n)]
      fb = force_end(history='ramp', force0=[1000.0_dp, 200.0_dp], couple0=3.0_dp, duration=0.01_dp)
      if (mass_at_b) then
         if (tension_only) then
            call p%piece%init(s, 2.2_dp, 22.0_dp, 70.6_dp, 9.81_dp, mu, new_tension_only(tanh_law()), &
                              motion_end(amplitude=0.3_dp, period=0.5_dp, direction=[0.6_dp, 0.8_dp]), &
                              mass_end(mass=5.0_dp), 1.0e4_dp, mu2)
         else
            call p%piece%init(s, 2.2_dp, 22.0_dp, 70.6_dp, 9.81_dp, mu, linear_law(ea=4.5e5_dp), &
                              motion_end(amplitude=0.3_dp, period=0.5_dp, direction=[0.6_dp, 0.8_dp]), &
                              mass_end(mass=5.0_dp), 1.0e4_dp, mu2)
         end if
      else
         call p%piece%init(s, 2.2_dp, 22.0_dp, 70.6_dp, 9.81_dp, mu, tanh_law(), fixed_end(point=[0.0_dp, 0.0_dp]), fb, &
                           1.0e4_dp, mu2)
      end if
      allocate (x(2*n), r0(2, n), v0(2, n))
      do k = 1, n
         r0(:, k) = [s(k)*1.02_dp, 0.3_dp*sin(1.3_dp*s(k))]
         v0(:, k) = [0.5_dp*cos(real(k, dp)), -0.2_dp*k]
         x(2*k - 1:2*k) = r0(:, k) + [0.01_dp*sin(2.0_dp*k), 0.02_dp*cos(3.0_dp*k)]
      end do
      ! A cell squeezed to 30 % and turned by about 90 degrees, another stretched.
      x(11:12) = x(11:12) + [-0.4_dp, 0.3_dp]
      x(15:16) = x(15:16) + [0.1_dp, -0.05_dp]
   end subroutine make_piece

   subroutine test_static_jacobian(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: worst
      call make_piece(p, x, r0, v0, 1.0_dp, 0.0_dp, .false., .false.)
      p%dt = 0
      p%t0 = 0.003_dp
      ! Measured 1.2e-9 of the row scale.
      call check_jacobian(p, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*n), 5.0e-9_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') 'statics: largest deviation from central differences / row scale', worst
   end subroutine test_static_jacobian

   subroutine test_step_averaged(error)
      type(error_type), allocatable, intent(out) :: error
      call step_case(error, 1.0_dp, 0.0_dp, 0.5_dp, .false., .false., 'averaged mass, theta 0.5')
   end subroutine test_step_averaged

   subroutine test_step_lumped(error)
      type(error_type), allocatable, intent(out) :: error
      call step_case(error, 0.0_dp, 0.0_dp, 0.7_dp, .false., .false., 'lumped mass, theta 0.7')
   end subroutine test_step_lumped

   subroutine test_step_mass_ends(error)
      type(error_type), allocatable, intent(out) :: error
      call step_case(error, 1.0_dp, 0.3_dp, 0.5_dp, .true., .true., 'moving end a, point mass at b, tension only')
      if (allocated(error)) return
      call step_case(error, 0.5_dp, 0.0_dp, 0.5_dp, .false., .true., 'moving end a, point mass at b, linear law')
   end subroutine test_step_mass_ends

   !> A table law sampled from the tanh law, and Kelvin-Voigt damping.
   subroutine test_step_table_damping(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p, plain
      type(table_law) :: table
      type(tanh_law) :: tanh
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :), strain(:)
      real(dp) :: worst
      integer :: k
      call make_piece(plain, x, r0, v0, 1.0_dp, 0.1_dp, .false., .false.)
      strain = [(-0.8_dp + 1.2_dp*(k - 1)/40, k=1, 41)]
      call new_table_law(strain, tanh%tension(strain), table, error)
      if (allocated(error)) return
      call p%piece%init(plain%piece%s, 2.2_dp, 22.0_dp, 70.6_dp, 9.81_dp, 1.0_dp, table, plain%piece%end_a, &
                        plain%piece%end_b, 1.0e4_dp, 0.1_dp, 500.0_dp)
      call p%piece%prepare_step(r0, v0)
      p%dt = 1.0e-3_dp
      p%t0 = 0.002_dp
      p%theta = 0.5_dp
      ! Measured 1.7e-10 of the row scale.
      call check_jacobian(p, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*n), 1.0e-9_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') 'step, table law, damping 500 N s: largest deviation / row scale', worst
   end subroutine test_step_table_damping

   subroutine step_case(error, mu, mu2, theta, tension_only, mass_at_b, what)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in) :: mu, mu2, theta
      logical, intent(in) :: tension_only, mass_at_b
      character(*), intent(in) :: what
      type(rod_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: worst
      call make_piece(p, x, r0, v0, mu, mu2, tension_only, mass_at_b)
      call p%piece%prepare_step(r0, v0)
      p%dt = 1.0e-3_dp
      p%t0 = 0.002_dp
      p%theta = theta
      ! Measured 1.5e-10 to 2.0e-10 of the row scale.
      call check_jacobian(p, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*n), 1.0e-9_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') 'step, '//what//': largest deviation / row scale', worst
   end subroutine step_case

   !> A step whose new level is within 1e-7 m of the old (every node's turning angle changes by
   !> less than small_rotation, so the bending's discrete gradient takes its Taylor forms, and
   !> so do the central differences' perturbed states), with a stiff bending (EI 5e3 N m^2, the
   !> bending forces above the tension's): the Jacobian against central differences.
   subroutine test_step_small_rotations(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p, plain
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: worst
      integer :: k
      call make_piece(plain, x, r0, v0, 1.0_dp, 0.0_dp, .false., .false.)
      call p%piece%init(plain%piece%s, 2.2_dp, 22.0_dp, 5.0e3_dp, 9.81_dp, 1.0_dp, tanh_law(), plain%piece%end_a, &
                        plain%piece%end_b, 1.0e4_dp, 0.0_dp)
      call p%piece%prepare_step(r0, v0)
      do k = 1, n
         x(2*k - 1:2*k) = r0(:, k) + 1.0e-7_dp*[sin(2.0_dp*k), cos(3.0_dp*k)]
      end do
      p%dt = 1.0e-3_dp
      p%t0 = 0.002_dp
      p%theta = 0.5_dp
      call check_jacobian(p, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*n), 1.0e-9_dp, worst, error)
      write (output_unit, '(4x,a,es9.2)') 'step, small rotations, EI 5e3 N m^2: largest deviation / row scale', worst
   end subroutine test_step_small_rotations

   !> For random pairs of states with large stretches and rotations, the
   !> discrete gradient's work equals the change of the strain and bending
   !> energy to round-off: sum_c ds_c N_c . (e1_c - e0_c) = U(R1) - U(R0).
   subroutine test_discrete_gradient(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :), r1(:, :), res(:)
      type(band_matrix) :: unused
      real(dp) :: u0(4), u1(4), work, worst, scale, noise(2, n)
      integer :: trial, c
      worst = 0
      do trial = 1, 20
         call make_piece(p, x, r0, v0, 1.0_dp, 0.0_dp, mod(trial, 2) == 0, .false.)
         call random_number(noise)
         r1 = r0 + 0.4_dp*(noise - 0.5_dp)*trial/10
         call p%piece%prepare_step(r0, v0)
         p%dt = 1.0e-3_dp
         p%t0 = 0.5_dp ! after the ramp: no applied force or couple
         allocate (res(2*n))
         call p%evaluate(reshape(r1, [2*n]), res, unused, .false.)
         work = 0
         do c = 1, n - 1
            work = work + p%piece%ds(c)*dot_product(p%piece%force(:, c), p%piece%e1(:, c) - p%piece%e0(:, c))
         end do
         u0 = p%piece%energies(r0, v0, p%piece%l0, p%piece%th0)
         u1 = p%piece%energies(r1, v0, p%piece%l1, p%piece%th1)
         scale = abs(u0(1)) + abs(u1(1)) + abs(u0(3)) + abs(u1(3))
         worst = max(worst, abs(work - ((u1(1) + u1(3)) - (u0(1) + u0(3))))/scale)
         deallocate (res)
      end do
      write (output_unit, '(4x,a,es9.2)') 'discrete gradient: largest |work - dU| / |U| over 20 random steps', worst
      call check(error, worst < 1.0e-13_dp, 'the discrete gradient misses the energy change by '//str(worst)//' of U')
   end subroutine test_discrete_gradient

   !> prepare_step takes the old level's geometry and energies from the last
   !> step evaluation when the positions are those of that evaluation (the
   !> accepted state), and computes them otherwise (a rejected attempt); so do
   !> geometry and energies (the ledger): all give, bit for bit, what a piece
   !> that never evaluated computes. The state
   !> moves only two nodes, so that most nodes take the Taylor branches, where
   !> the evaluation computes no energy.
   subroutine test_old_level_memo(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p, fresh
      type(band_matrix) :: jac
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :), res(:), x_new(:)
      real(dp) :: e_memo(2, n - 1), l_memo(n - 1), th_memo(n), e_fresh(2, n - 1), l_fresh(n - 1), th_fresh(n)
      real(dp) :: en_memo(4), en_fresh(4)
      integer :: attempt
      call make_piece(p, x, r0, v0, 1.0_dp, 0.0_dp, .false., .false.)
      x_new = reshape(r0, [2*n])
      x_new(7:8) = x_new(7:8) + [0.05_dp, -0.03_dp]
      x_new(13:14) = x_new(13:14) + [-0.02_dp, 0.04_dp]
      call jac%init(2*n, rod_kl, rod_ku)
      allocate (res(2*n))
      do attempt = 1, 2
         call p%piece%prepare_step(r0, v0)
         p%dt = 1.0e-3_dp
         p%t0 = 0.002_dp
         p%theta = 0.5_dp
         call p%evaluate(x_new, res, jac, .false.)
         ! Attempt 1: accepted, the next step starts from x_new; attempt 2: rejected, again from r0.
         fresh = p
         fresh%piece%memo_valid = .false.
         ! The geometry and energies of the evaluated state (the ledger's), from the memo.
         call p%piece%geometry(reshape(x_new, [2, n]), e_memo, l_memo, th_memo)
         call fresh%piece%geometry(reshape(x_new, [2, n]), e_fresh, l_fresh, th_fresh)
         en_memo = p%piece%energies(reshape(x_new, [2, n]), v0, l_memo, th_memo)
         en_fresh = fresh%piece%energies(reshape(x_new, [2, n]), v0, l_fresh, th_fresh)
         call check(error, same(l_memo, l_fresh) .and. same(th_memo, th_fresh) .and. &
                    same(reshape(e_memo, [2*(n - 1)]), reshape(e_fresh, [2*(n - 1)])) .and. same(en_memo, en_fresh), &
                    'geometry or energies of the evaluated state differ from the ones computed afresh')
         if (allocated(error)) return
         if (attempt == 1) then
            call p%piece%prepare_step(reshape(x_new, [2, n]), v0)
            call fresh%piece%prepare_step(reshape(x_new, [2, n]), v0)
         else
            call p%piece%prepare_step(r0, v0)
            call fresh%piece%prepare_step(r0, v0)
         end if
         call check(error, same(p%piece%l0, fresh%piece%l0) .and. same(p%piece%th0, fresh%piece%th0) .and. &
                    same(reshape(p%piece%e0, [2*(n - 1)]), reshape(fresh%piece%e0, [2*(n - 1)])) .and. &
                    same(p%piece%b0, fresh%piece%b0), &
                    'old level after an evaluation ('//merge('accepted', 'rejected', attempt == 1)// &
                    ') differs from the one computed afresh')
         if (allocated(error)) return
      end do
      call check(error, count(p%piece%memo_b_ok) > 0 .and. count(.not. p%piece%memo_b_ok(2:n - 1)) > 0 .and. &
                 count(abs(p%piece%l1 - p%piece%l0) < 1.0e-6_dp) > 0 .and. &
                 count(abs(p%piece%l1 - p%piece%l0) >= 1.0e-6_dp) > 0, &
                 'the test state does not mix Taylor and divided-difference branches')
   contains
      logical function same(a, b)
         real(dp), intent(in) :: a(:), b(:)
         same = all(transfer(a, [0_i8]) == transfer(b, [0_i8]))
      end function same
   end subroutine test_old_level_memo

   !> A residual evaluated without its Jacobian (the one at each step's
   !> converged state, whose cell forces give the reactions) skips what only
   !> the blocks use; its residual and cell forces must be those of the
   !> evaluation with the Jacobian, bit for bit: tanh law and a table law with
   !> damping, at a state far from the old level (divided differences) and
   !> one close to it (most cells and nodes in the Taylor branches).
   subroutine test_residual_alone(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p, plain, damped
      type(table_law) :: table
      type(tanh_law) :: tanh
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :), strain(:)
      integer :: k
      call make_piece(p, x, r0, v0, 1.0_dp, 0.0_dp, .false., .false.)
      call compare(p, 'tanh law')
      if (allocated(error)) return
      call make_piece(plain, x, r0, v0, 1.0_dp, 0.1_dp, .false., .false.)
      strain = [(-0.8_dp + 1.2_dp*(k - 1)/40, k=1, 41)]
      call new_table_law(strain, tanh%tension(strain), table, error)
      if (allocated(error)) return
      call damped%piece%init(plain%piece%s, 2.2_dp, 22.0_dp, 70.6_dp, 9.81_dp, 1.0_dp, table, plain%piece%end_a, &
                             plain%piece%end_b, 1.0e4_dp, 0.1_dp, 500.0_dp)
      call compare(damped, 'table law, damping 500 N s')
   contains
      subroutine compare(q, what)
         type(rod_problem), intent(inout) :: q
         character(*), intent(in) :: what
         type(band_matrix) :: jac
         real(dp), allocatable :: x_near(:), res_j(:), res_r(:), force_j(:, :)
         integer :: state
         call jac%init(2*n, rod_kl, rod_ku)
         allocate (res_j(2*n), res_r(2*n))
         x_near = reshape(r0, [2*n])
         x_near(7:8) = x_near(7:8) + [0.05_dp, -0.03_dp]
         do state = 1, 2
            call q%piece%prepare_step(r0, v0)
            q%dt = 1.0e-3_dp
            q%t0 = 0.002_dp
            q%theta = 0.5_dp
            if (state == 1) then
               call q%evaluate(x, res_j, jac, .true.)
               force_j = q%piece%force
               call q%evaluate(x, res_r, jac, .false.)
            else
               call q%evaluate(x_near, res_j, jac, .true.)
               force_j = q%piece%force
               call q%evaluate(x_near, res_r, jac, .false.)
            end if
            call check(error, all(transfer(res_j, [0_i8]) == transfer(res_r, [0_i8])) .and. &
                       all(transfer(force_j, [0_i8]) == transfer(q%piece%force, [0_i8])), &
                       what//merge(', far from', ', near    ', state == 1)//' the old level: the residual or the '// &
                       'cell forces without the Jacobian differ from those with it')
            if (allocated(error)) return
         end do
         ! The near state mixes the Taylor and divided-difference branches of the cells.
         call check(error, count(abs(q%piece%l1 - q%piece%l0) < 1.0e-6_dp) > 0 .and. &
                    count(abs(q%piece%l1 - q%piece%l0) >= 1.0e-6_dp) > 0, &
                    what//': the near state does not mix Taylor and divided-difference branches')
      end subroutine compare
   end subroutine test_residual_alone

   !> The kinetic and gravity energies of rod_energies against other sums of the same
   !> quantities: 1/2 V . (M V) with M V from mass_times, and the weight of each node
   !> (its share of the cable and the point mass at end b) times its height; on the
   !> averaged mass matrix with its second off-diagonal (mu2 = 0.3).
   subroutine test_energies_kinetic_gravity(error)
      type(error_type), allocatable, intent(out) :: error
      type(rod_problem) :: p
      real(dp), allocatable :: x(:), r0(:, :), v0(:, :)
      real(dp) :: en(4), mv(2, n), e(2, n - 1), l(n - 1), th(n), kinetic, gravity
      integer :: k
      call make_piece(p, x, r0, v0, 1.0_dp, 0.3_dp, .false., .true.)
      call p%piece%geometry(r0, e, l, th)
      en = p%piece%energies(r0, v0, l, th)
      call p%piece%mass_times(v0, mv)
      kinetic = 0.5_dp*sum(v0*mv)
      gravity = 5.0_dp*9.81_dp*r0(2, n)
      do k = 1, n
         gravity = gravity + p%piece%weight*p%piece%lumped(k)*r0(2, k)
      end do
      write (output_unit, '(4x,a,2es10.2)') 'energies: relative differences of kinetic and gravity energy', &
         abs(en(2) - kinetic)/abs(kinetic), abs(en(4) - gravity)/abs(gravity)
      call check(error, abs(en(2) - kinetic) <= 3.0e-15_dp*abs(kinetic), 'kinetic energy '//str(en(2))// &
                 ' J, 1/2 V.MV '//str(kinetic)//' J')
      if (allocated(error)) return
      call check(error, abs(en(4) - gravity) <= 3.0e-15_dp*abs(gravity), 'gravity energy '//str(en(4))// &
                 ' J, sum of weights times heights '//str(gravity)//' J')
   end subroutine test_energies_kinetic_gravity

   !> cell_terms (the cells in blocks of 32, the inner ones packed two to an SSE2 operation)
   !> against the loop over the cells it replaced (cell_terms_reference, its text), every force,
   !> block entry and rotation by its bits, on random cells: a quarter with a strain step below
   !> small_strain_step (the Taylor form of q), a quarter with a rotation below small_rotation
   !> (the Taylor form of rho), a tenth both; the tanh and the linear law, with and without
   !> damping, with and without the Jacobian; pieces of 2 to 100 nodes (the end cells 1 and
   !> n - 1 with their couples, blocks cut at 32) and windows ca .. cb of them (the entries
   !> outside a window must stay as they were). Broken once (dg_de's two divisions of the
   !> packed loop swapped in their order), the test fails.
   subroutine test_cell_terms_blocks(error)
      type(error_type), allocatable, intent(out) :: error
      type(tanh_law) :: tanh
      type(linear_law) :: linear
      integer, parameter :: sizes(6) = [2, 3, 4, 35, 70, 100]
      integer :: rep, is, nn, ilaw, w, jac, windows(2, 5), taylor_q, taylor_rho, differ, compared
      integer(int64) :: state
      state = 20261202_int64
      taylor_q = 0
      taylor_rho = 0
      differ = 0
      compared = 0
      linear = linear_law(ea=4.5e5_dp)
      do rep = 1, 4
      do is = 1, size(sizes)
         nn = sizes(is)
         windows(:, 1) = [1, nn - 1]
         windows(:, 2) = [1, 1]
         windows(:, 3) = [nn - 1, nn - 1]
         windows(:, 4) = [min(2, nn - 1), max(1, nn - 2)]
         windows(:, 5) = [min(5, nn - 1), min(40, nn - 1)]
         do ilaw = 1, 2
            do jac = 0, 1
               do w = 1, size(windows, 2)
                  if (ilaw == 1) then
                     call compare_once(nn, tanh, windows(1, w), windows(2, w), jac == 1)
                  else
                     call compare_once(nn, linear, windows(1, w), windows(2, w), jac == 1)
                  end if
               end do
            end do
         end do
      end do
      end do
      write (output_unit, '(4x, a, i0, a, i0, a, i0, a)') 'cell_terms against the loop over the cells: ', compared, &
         ' values, ', taylor_q, ' cells with the Taylor q, ', taylor_rho, ' with the Taylor rho'
      call check(error, differ == 0, 'cell_terms: '//str(differ)//' of '//str(compared)// &
                 ' values differ in their bits from the loop over the cells')
      if (allocated(error)) return
      call check(error, taylor_q > 100 .and. taylor_rho > 100, 'cell_terms: too few cells in the Taylor branches ('// &
                 str(taylor_q)//' q, '//str(taylor_rho)//' rho)')
   contains
      subroutine compare_once(n, law, ca, cb, with_jacobian)
         integer, intent(in) :: n, ca, cb
         class(material_law), intent(in) :: law
         logical, intent(in) :: with_jacobian
         real(dp) :: e0(2, n - 1), e1(2, n - 1), l0(n - 1), l1(n - 1), ds(n - 1), mom(n), dmom(n), damping, &
                     force_a(2, n - 1), force_b(2, n - 1), block_a(2, 2, -1:1, n - 1), block_b(2, 2, -1:1, n - 1), &
                     dphi_a(n - 1), dphi_b(n - 1), couple_first, couple_last, phi, dphi, u, scale
         integer :: c, k
         do c = 1, n - 1
            l0(c) = 1 + 0.3_dp*(uniform(state) - 0.3_dp)
            phi = 6.283185307179586_dp*(uniform(state) - 0.5_dp)
            u = uniform(state)
            if (u < 0.25_dp .or. u >= 0.9_dp) then
               l1(c) = l0(c) + 2.0e-6_dp*(uniform(state) - 0.5_dp)
            else
               l1(c) = l0(c)*(1 + 0.2_dp*(uniform(state) - 0.5_dp))
            end if
            if ((u >= 0.25_dp .and. u < 0.5_dp) .or. u >= 0.9_dp) then
               dphi = 2.0e-4_dp*(uniform(state) - 0.5_dp)
            else
               dphi = 2.4_dp*(uniform(state) - 0.5_dp)
            end if
            ! (small_strain_step = 1e-6, small_rotation = 1e-4 in model/rod.f90.)
            if (abs((l1(c) - 1) - (l0(c) - 1)) < 1.0e-6_dp) taylor_q = taylor_q + 1
            if (abs(dphi) < 1.0e-4_dp) taylor_rho = taylor_rho + 1
            e0(:, c) = l0(c)*[cos(phi), sin(phi)]
            e1(:, c) = l1(c)*[cos(phi + dphi), sin(phi + dphi)]
            ds(c) = 0.2_dp + 0.1_dp*uniform(state)
         end do
         ! Moments from 0.1 to 1e5 N m, so that the bending part of the blocks is not always lost in
         ! the rounding of the strain part.
         scale = 10**(6*uniform(state) - 1)
         do k = 1, n
            mom(k) = scale*(uniform(state) - 0.5_dp)
            dmom(k) = scale*(uniform(state) - 0.5_dp)
         end do
         damping = merge(0.0_dp, 300.0_dp, uniform(state) < 0.5_dp)
         couple_first = 0.1_dp*scale*(uniform(state) - 0.5_dp)
         couple_last = 0.1_dp*scale*(uniform(state) - 0.5_dp)
         force_a = 7
         block_a = 7
         dphi_a = 7
         force_b = force_a
         block_b = block_a
         dphi_b = dphi_a
         call cell_terms(n, law, e0, e1, l0, l1, ds, mom, dmom, damping, 1.0e-3_dp, couple_first, couple_last, &
                         with_jacobian, force_a, block_a, dphi_a, ca, cb)
         call cell_terms_reference(n, law, e0, e1, l0, l1, ds, mom, dmom, damping, 1.0e-3_dp, couple_first, &
                                   couple_last, with_jacobian, force_b, block_b, dphi_b, ca, cb)
         differ = differ + count(transfer(force_a, [0_int64]) /= transfer(force_b, [0_int64])) &
                  + count(transfer(block_a, [0_int64]) /= transfer(block_b, [0_int64])) &
                  + count(transfer(dphi_a, [0_int64]) /= transfer(dphi_b, [0_int64]))
         compared = compared + size(force_a) + size(block_a) + size(dphi_a)
      end subroutine compare_once
   end subroutine test_cell_terms_blocks

   !> The loop over the cells that cell_terms did cell by cell before it went in blocks (efa47e9,
   !> its text), the reference of test_cell_terms_blocks.
   subroutine cell_terms_reference(n, law, e0_, e1_, l0_, l1_, ds, mom, dmom, damping, dt, couple_first, couple_last, &
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
      integer :: c, i, j
      real(dp) :: q, dq, lsum, em(2), dphi, rho, drho, g, gvec(2), s_c, couple, h, eps0, eps1, mid, f, fp, fpp
      real(dp) :: ds_dq(2), dg_de(2), dphi_de(2), dstrain(2, 2), dgvec(2, 2), ds_de(2, -1:1), wsum(2), pem(2), wl(2), &
                  e1l(2), fq(2)
      real(dp), parameter :: jm(2, 2) = reshape([0.0_dp, 1.0_dp, -1.0_dp, 0.0_dp], [2, 2]), &
                             id2(2, 2) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
      ! The rotations as cell_rotations_of computes them (fast_atan2_array: the bits of fast_atan2,
      ! suite_atan2).
      do c = ca, cb
         dphi1(c) = fast_atan2(e0_(1, c)*e1_(2, c) - e0_(2, c)*e1_(1, c), dot_product(e0_(:, c), e1_(:, c)))
      end do
      do c = ca, cb
         associate (e0 => e0_(:, c), e1 => e1_(:, c), l0 => l0_(c), l1 => l1_(c))
            ! Strain part: q (e0 + e1) / (l0 + l1), q the divided difference of W.
            eps0 = l0 - 1
            eps1 = l1 - 1
            h = eps1 - eps0
            if (abs(h) < small_strain_step_) then
               mid = 0.5_dp*(eps0 + eps1)
               ! f, f', f'' in one call (the tanh law: one tanh and 1 / cosh^2 together).
               call law%tension_stiffness_slope(mid, f, fp, fpp)
               q = f + fpp*h*h/24
               dq = 0.5_dp*fp + fpp*h/12
            else
               ! W1 - W0 from the law, not a difference of two W: that loses digits
               ! (tanh_strain_energy_change). No W itself: only the ledger uses it (rod_energies).
               ! dq only enters the blocks: a residual alone does not ask for the law's tension.
               if (with_jacobian) then
                  call law%strain_energy_change_tension(eps0, eps1, q, f)
                  q = q/h
                  dq = (f - q)/h
               else
                  q = law%strain_energy_change(eps0, eps1)/h
                  dq = 0
               end if
            end if
            lsum = l0 + l1
            ! (The loops over i kept as loops, unroll 1, to be packed: see the blocks below.)
            !GCC$ unroll 1
            do i = 1, 2
               wsum(i) = e0(i) + e1(i)
            end do
            ! Kelvin-Voigt damping: c (eps1 - eps0) / dt along the same direction; its
            ! work in the step, ds c (eps1 - eps0)^2 / dt, is the energy it dissipates.
            q = q + damping*h/dt
            dq = dq + damping/dt
            ! The strain part q wsum / lsum of the force, to which the bending part is added.
            !GCC$ unroll 1
            do i = 1, 2
               fq(i) = q*wsum(i)/lsum
            end do
            ! Bending part: S_c G_c / ds_c with G_c = perp(e_mid) rho(dphi) / (l0 l1).
            !GCC$ unroll 1
            do i = 1, 2
               em(i) = 0.5_dp*wsum(i)
            end do
            dphi = dphi1(c)
            if (abs(dphi) < small_rotation_) then
               rho = 1 + dphi**2/6
               drho = dphi/3
            else
               rho = dphi/sin(dphi)
               drho = (sin(dphi) - dphi*cos(dphi))/sin(dphi)**2
            end if
            g = rho/(l0*l1)
            ! perp(em), written out: gfortran called perp (1.6e6 calls on fast_180kN).
            pem(1) = -em(2)
            pem(2) = em(1)
            gvec = pem*g
            couple = 0
            if (c == 1) then
               couple = couple_first
            else if (c == n - 1) then
               couple = couple_last
            end if
            s_c = mom(c) - mom(c + 1) - couple
            !GCC$ unroll 1
            do i = 1, 2
               force(i, c) = fq(i) + s_c/ds(c)*gvec(i)
            end do
            if (.not. with_jacobian) cycle
            ! The blocks column by column, each column's two rows in one packed SSE2 operation:
            ! the loops over the rows i kept as loops (unroll 1) so that gfortran 12's loop
            ! vectorizer packs them (it does not once they are unrolled). Element by element
            ! the operations of the array expressions they replace, in the same order:
            !   ds_dq = dq e1 / l1, dstrain = outer(wsum / lsum, ds_dq)
            !     + q (identity2() / lsum - outer(wsum, e1 / l1) / lsum**2),
            !   dg_de = drho dphi_de / (l0 l1) - rho / (l0 l1**2) e1 / l1,
            !   dgvec = 0.5 g jm + outer(pem, dg_de), block_0 = dstrain + s_c / ds_c dgvec
            !     + outer(gvec, ds_de(:, 0)) / ds_c, block_+-1 = outer(gvec, ds_de(:, +-1)) / ds_c.
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
            ds_de = moment_gradient_reference(n, c, e1_, l1_, dmom)
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
      end do
   end subroutine cell_terms_reference

   !> moment_gradient_of, the reference's copy.
   pure function moment_gradient_reference(n, c, e1, l1, dmom) result(d)
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
   end function moment_gradient_reference
end module suite_rod
