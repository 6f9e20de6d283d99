!> Several 3-D lines joined at free points: a mooring network (a spread meeting at a buoy,
!> a bridle), solved as one system by block elimination (docs/theory/networks.md).
!>
!> Each line is a 3-D run of its own (driver/rod3d_run.f90: its piece, state, Newton
!> workspace and ledger). A line's end at a free point is a joint end (ends/joint.f90): held
!> at the point's position, which this module sets, with the end node's momentum rows kept
!> by the piece (rod3d_piece%keep_rows) before the held rows replace them. The unknowns are
!> the lines' own (positions and twist angles) and the free points' positions X_p; a
!> point's velocity is that of the line ends on it. The equations are the lines' own, with
!> the held rows r_end - X_p = 0 at the joints, and per point the balance of the kept rows
!> of the line ends on it,
!>
!>     g_p = sum_(l, s at p) T_l e_(l,s) = 0,
!>
!> T_l the line's row scale (the kept rows are scaled by 1 / T_l). A body on the point (its
!> mass, weight, buoyancy, drag) is a body on the end node of one of its lines (the
!> lowest-numbered), so it is in that line's kept rows, its mass matrix and its energies.
!> The end nodes of the lines at a point carry their half cells' mass, so the point moves
!> with its body and all of them.
!>
!> A Newton iteration. Each line's Jacobian A_l (band, with the held rows) is factorised once;
!> with z_l = A_l^-1 res_l and, per joint (l, s), Z_(l,s) = A_l^-1 E_s / L_l (E_s the three
!> unit columns of the held rows, L_l their scale), the update of the line is
!>
!>     du_l = -z_l + sum_(s of l) Z_(l,s) dX_(p(s)),
!>
!> and the points' updates solve the small dense system (3 per point)
!>
!>     sum_(l, s at p) T_l J_(l,s) [sum_(s' of l) Z_(l,s') dX_(p(s'))] = -g_p + sum_(l, s at p) T_l J_(l,s) z_l,
!>
!> J_(l,s) the kept Jacobian rows (nine columns: the end node and its two neighbours).
!> This is Newton's method on the whole system, exactly (no splitting between lines and
!> points): the band of each line stays its own, and the cost per iteration is one band
!> factorisation per line, 1 + 3 substitutions per joint of it, and one dense solve of order 3
!> x points. A closed loop (two lines between the same two points, or a ring of lines) is no
!> different to it.
!>
!> The statics take the same iteration on the static systems, from the lines' own static
!> states with the points where the input guessed them; a point moves at most static_step of
!> its shortest line per iteration (the whole update scaled alike, which keeps it a Newton
!> direction), until the full steps converge. The time step is that of each line's scheme;
!> the ledger of a line books the work of the point on its end (the held end's reaction, as for
!> any held end), and those works cancel between the lines at a point: the network's ledger is
!> the sum of its lines'.
module xcable_driver_network
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_numerics, stat_input
   use xcable_core_strings, only: str
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_ends_joint, only: joint_end
   use xcable_material_law, only: material_law
   use xcable_material_tension_only, only: uncut_law
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private
   public :: network_run, network_joint

   interface
      !> LAPACK: solve a general system (LU with partial pivoting).
      pure subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
   end interface

   !> A line's end at a network point.
   type :: network_joint
      !> The line, its side (1: end a, 2: end b) and the point.
      integer :: line = 0, side = 0, point = 0
   end type network_joint

   !> A joint's columns Z = A^-1 E / L in the last iteration (unknowns of its line, 3).
   type :: joint_columns_type
      real(dp), allocatable :: z(:, :)
   end type joint_columns_type

   !> A line's laws kept aside while the statics solves with others.
   type :: kept_law_type
      class(material_law), allocatable :: law
      type(kept_law_type), allocatable :: sections(:)
   end type kept_law_type

   !> Lines joined at free points.
   type :: network_run
      !> The lines, each a 3-D run.
      type(rod3d_run), allocatable :: lines(:)
      !> The lines' ends at free points.
      type(network_joint), allocatable :: joints(:)
      !> Number of free points, and their positions (3, points), m.
      integer :: points = 0
      real(dp), allocatable :: xp(:, :)
      !> Positions at the old level of a step (a rejection goes back to them).
      real(dp), allocatable :: xp_old(:, :)
      !> Time, s.
      real(dp) :: t = 0
      !> Newton: tolerance on the scaled update, and the iterations allowed in a step and in the statics.
      real(dp) :: tolerance = 1.0e-9_dp
      integer :: max_iterations = 50, static_iterations = 400
      !> Statics: the largest move of a point in one iteration, as a share of its shortest line.
      real(dp) :: static_step = 0.1_dp
      !> Newton iterations: all, and those of the last solve.
      integer :: iterations = 0, last_iterations = 0
      !> The points' force imbalance after the last solve (3, points), N: the sum of the kept rows.
      real(dp), allocatable :: imbalance(:, :)
      !> The work of the points on the lines' ends since the start, J (zero but for round-off and
      !> Newton's tolerance when the points are in balance: the ledger's check of the points).
      real(dp) :: joint_work = 0
      !> Per joint, its columns in the last iteration.
      type(joint_columns_type), allocatable, private :: columns(:)
      !> The lines' own laws while the statics solves with their compressive branches.
      type(kept_law_type), allocatable, private :: kept_laws(:)
   contains
      !> Take the lines and the joints; the joint ends replace the lines' ends there.
      procedure :: init => network_init
      !> The static state of the network at time t.
      procedure :: statics => network_statics
      !> The lines' static states with the points held where they are (each line alone), and the
      !> points' imbalance there.
      procedure :: hold_statics => network_hold_statics
      !> One time step: the new level, not yet accepted.
      procedure :: attempt => network_attempt
      !> Accept the new level (the lines' ledgers).
      procedure :: accept => network_accept
      !> Back to the old level.
      procedure :: reject => network_reject
      !> The sums over the lines: stored energy, the work of the held ends, of the loads, and the
      !> dissipation since the start, J.
      procedure :: ledger => network_ledger
      !> The derivative of the points' force with respect to their positions, the lines in
      !> balance (the Schur complement of the last Newton matrix), N/m (3 points, 3 points).
      procedure :: point_stiffness => network_point_stiffness
      !> A line parted (driver/network_drive.f90): line l replaced by the piece on its end a's
      !> side, and the piece on its end b's side (if the break is inside the line) added as a
      !> new last line, taking over the joint at l's end b.
      procedure :: part_line => network_part_line
   end type network_run

contains

   !> Take the lines (moved in) and the joints. Each joint's end becomes a joint end at that
   !> end node's position; a point starts where the first of its joints' end nodes is.
   subroutine network_init(self, lines, joints, points, error)
      !> Network.
      class(network_run), intent(inout) :: self
      !> The lines, prepared (their static states are the first guess); moved into the network.
      type(rod3d_run), allocatable, intent(inout) :: lines(:)
      !> Their ends at free points.
      type(network_joint), intent(in) :: joints(:)
      !> Number of free points.
      integer, intent(in) :: points
      !> Error (stat_input): a joint naming no line or point, a point without joints, one end twice.
      type(error_type), allocatable, intent(out) :: error
      integer :: j, p, k
      logical :: placed(points)
      call move_alloc(lines, self%lines)
      self%joints = joints
      self%points = points
      allocate (self%columns(size(joints)))
      allocate (self%xp(3, points), self%xp_old(3, points), self%imbalance(3, points))
      self%xp = 0
      self%imbalance = 0
      placed = .false.
      do j = 1, size(joints)
         associate (jt => joints(j))
            if (jt%line < 1 .or. jt%line > size(self%lines) .or. jt%side < 1 .or. jt%side > 2 .or. &
                jt%point < 1 .or. jt%point > points) then
               call fatal_error(error, 'network: joint '//str(j)//' names line '//str(jt%line)//', side '// &
                                str(jt%side)//', point '//str(jt%point)//': out of range', stat_input)
               return
            end if
            if (any(joints(1:j - 1)%line == jt%line .and. joints(1:j - 1)%side == jt%side)) then
               call fatal_error(error, 'network: the end '//str(jt%side)//' of line '//str(jt%line)// &
                                ' is on two points', stat_input)
               return
            end if
            associate (run => self%lines(jt%line), piece => self%lines(jt%line)%problem%piece)
               k = merge(1, piece%n, jt%side == 1)
               if (.not. placed(jt%point)) self%xp(:, jt%point) = run%x(3*k - 2:3*k)
               placed(jt%point) = .true.
               piece%keep_rows(jt%side) = .true.
               if (jt%side == 1) then
                  deallocate (piece%end_a)
                  allocate (piece%end_a, source=joint_end(at=self%xp(:, jt%point), point=jt%point))
               else
                  deallocate (piece%end_b)
                  allocate (piece%end_b, source=joint_end(at=self%xp(:, jt%point), point=jt%point))
               end if
            end associate
         end associate
      end do
      do p = 1, points
         if (.not. placed(p)) then
            call fatal_error(error, 'network: point '//str(p)//' joins no line', stat_input)
            return
         end if
      end do
      self%tolerance = self%lines(1)%options%tolerance
      self%xp_old = self%xp
   end subroutine network_init

   !> The static state at time t, from the lines' states and the points' positions.
   subroutine network_statics(self, t, error)
      !> Network.
      class(network_run), intent(inout) :: self
      !> Time of the held ends' positions and the loads, s.
      real(dp), intent(in) :: t
      !> Error (stat_numerics) when the iteration does not converge.
      type(error_type), allocatable, intent(out) :: error
      integer :: l
      self%t = t
      do l = 1, size(self%lines)
         self%lines(l)%problem%dt = 0
         self%lines(l)%problem%t0 = t
      end do
      ! A rope that cannot push: first with its law's compressive branch (a slack cell has no
      ! stiffness, and the points' system none in a slack line's direction), then with the law
      ! itself from there, as the single line's statics on a seabed (rod3d_drive/statics.f90).
      if (any([(self%lines(l)%problem%piece%has_kink(), l=1, size(self%lines))])) then
         call swap_laws(self)
         call solve(self, .true., error)
         call swap_laws(self)
         if (allocated(error)) then
            error%message = 'network statics (the ropes'' laws with their compressive branch): '//error%message
            return
         end if
      end if
      call solve(self, .true., error)
      if (allocated(error)) then
         error%message = 'network statics: '//error%message
         return
      end if
      self%joint_work = 0
      do l = 1, size(self%lines)
         associate (run => self%lines(l), piece => self%lines(l)%problem%piece)
            run%v = 0
            ! Held ends start with their own velocity (a motion end); a point starts at rest.
            if (piece%end_a%held() .and. .not. piece%keep_rows(1)) run%v(:, 1) = piece%end_a%velocity3(t)
            if (piece%end_b%held() .and. .not. piece%keep_rows(2)) run%v(:, piece%n) = piece%end_b%velocity3(t)
            call run%start(run%x, run%v, t)
         end associate
      end do
      self%xp_old = self%xp
   end subroutine network_statics

   !> The lines' static states at time t with the points held where they are, and the points'
   !> imbalance (the sum of the kept rows) there.
   subroutine network_hold_statics(self, t, error)
      !> Network.
      class(network_run), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Error of a line's statics.
      type(error_type), allocatable, intent(out) :: error
      integer :: l
      call place_points(self)
      do l = 1, size(self%lines)
         call self%lines(l)%statics(t, error)
         if (allocated(error)) then
            error%message = 'line '//str(l)//': '//error%message
            return
         end if
      end do
      call finish(self)
   end subroutine network_hold_statics

   !> One step of dt: the new level of every line and point, not yet accepted.
   subroutine network_attempt(self, dt, theta, error)
      !> Network.
      class(network_run), intent(inout) :: self
      !> Step, s; implicitness (0.5: the energy-conserving midpoint).
      real(dp), intent(in) :: dt, theta
      !> Error (stat_numerics) when Newton does not converge.
      type(error_type), allocatable, intent(out) :: error
      integer :: l, k, n, j
      self%xp_old = self%xp
      do l = 1, size(self%lines)
         associate (run => self%lines(l), piece => self%lines(l)%problem%piece)
            n = piece%n
            run%x_old = run%x
            run%t = self%t
            call piece%prepare_step(reshape(run%x_old(1:3*n), [3, n]), run%v)
            run%problem%dt = dt
            run%problem%t0 = self%t
            run%problem%theta = theta
            do k = 1, n
               run%x(3*k - 2:3*k) = run%x_old(3*k - 2:3*k) + dt*run%v(:, k)
            end do
         end associate
      end do
      do j = size(self%joints), 1, -1
         associate (jt => self%joints(j), piece => self%lines(self%joints(j)%line)%problem%piece)
            k = merge(1, piece%n, jt%side == 1)
            self%xp(:, jt%point) = self%lines(jt%line)%x(3*k - 2:3*k)
         end associate
      end do
      call solve(self, .false., error)
      if (allocated(error)) error%message = '3-D network step at t = '//str(self%t)//' s: '//error%message
   end subroutine network_attempt

   !> Accept the new level: each line's ledger and velocities.
   subroutine network_accept(self, dt, theta)
      !> Network.
      class(network_run), intent(inout) :: self
      !> The step taken, s; implicitness.
      real(dp), intent(in) :: dt, theta
      integer :: l, j, k
      call place_points(self)
      do j = 1, size(self%joints)
         associate (jt => self%joints(j), run => self%lines(self%joints(j)%line))
            if (.not. run%evaluated_at_x) call run%problem%evaluate(run%x, run%work%residual, run%work%jacobian, .false.)
            run%evaluated_at_x = .true.
            k = merge(1, run%problem%piece%n, jt%side == 1)
            self%joint_work = self%joint_work + dot_product(run%problem%piece%reaction(k, dt), &
                                                            run%x(3*k - 2:3*k) - run%x_old(3*k - 2:3*k))
         end associate
      end do
      do l = 1, size(self%lines)
         call self%lines(l)%accept(dt, theta)
      end do
      self%t = self%t + dt
      self%xp_old = self%xp
   end subroutine network_accept

   !> Back to the old level.
   subroutine network_reject(self)
      !> Network.
      class(network_run), intent(inout) :: self
      integer :: l
      do l = 1, size(self%lines)
         call self%lines(l)%reject()
      end do
      self%xp = self%xp_old
      call place_points(self)
   end subroutine network_reject

   !> Stored energy now, and since the start the work of the held ends (the supports: not the
   !> points, whose work on the lines' ends is joint_work), of the loads, and the dissipation, J
   !> (sums over the lines).
   function network_ledger(self) result(ledger)
      !> Network.
      class(network_run), intent(in) :: self
      real(dp) :: ledger(4)
      integer :: l
      ledger = 0
      do l = 1, size(self%lines)
         associate (run => self%lines(l))
            ledger = ledger + [sum(run%energies()), run%end_work, run%load_work, run%dissipated]
         end associate
      end do
      ledger(2) = ledger(2) - self%joint_work
   end function network_ledger

   !> The points' stiffness: d(sum of the kept rows' forces) / dX with the lines in balance, N/m.
   function network_point_stiffness(self) result(s)
      !> Network (after a solve: its lines' factorised Jacobians are those of the last iterate).
      class(network_run), intent(inout) :: self
      real(dp) :: s(3*self%points, 3*self%points)
      real(dp) :: rhs(3*self%points)
      type(error_type), allocatable :: error
      call border(self, s, rhs, error)
   end function network_point_stiffness

   !> Line l parted: replaced by first (its end a's side), and second (the end b's side of a
   !> break inside the line; its end b the old line's) added as line size(lines) + 1. The
   !> joint ends are the pieces' own (the break copies the line's ends); here the pieces keep
   !> the rows of their ends at points, and a joint at l's end b moves to the new line.
   subroutine network_part_line(self, l, first, second)
      !> Network.
      class(network_run), intent(inout) :: self
      !> The line that parted.
      integer, intent(in) :: l
      !> The pieces after the break (moved in).
      type(rod3d_run), intent(inout) :: first
      type(rod3d_run), intent(inout), optional :: second
      type(rod3d_run), allocatable :: lines(:)
      logical :: kept(2)
      integer :: j, n_lines
      kept = self%lines(l)%problem%piece%keep_rows
      n_lines = size(self%lines)
      if (present(second)) then
         allocate (lines(n_lines + 1))
         do j = 1, n_lines
            if (j /= l) call move_line(self%lines(j), lines(j))
         end do
         call move_line(first, lines(l))
         call move_line(second, lines(n_lines + 1))
         call move_alloc(lines, self%lines)
         self%lines(l)%problem%piece%keep_rows = [kept(1), .false.]
         self%lines(n_lines + 1)%problem%piece%keep_rows = [.false., kept(2)]
         do j = 1, size(self%joints)
            if (self%joints(j)%line == l .and. self%joints(j)%side == 2) self%joints(j)%line = n_lines + 1
         end do
      else
         call move_line(first, self%lines(l))
         ! A released end was held by a support, not a point: the rows at points stay.
         self%lines(l)%problem%piece%keep_rows = kept
      end if
      call place_points(self)
   end subroutine network_part_line

   !> A line's run moved from one place to another (its state, piece and workspace).
   subroutine move_line(from, to)
      type(rod3d_run), intent(inout) :: from, to
      to = from
   end subroutine move_line

   ! ---- the solve ----

   !> Swap each line's laws with their kept copies: the first call puts in the laws with their
   !> compressive branch (uncut_law), the second the laws themselves back.
   subroutine swap_laws(self)
      type(network_run), intent(inout) :: self
      class(material_law), allocatable :: other
      logical :: was_cut
      integer :: l, j
      do l = 1, size(self%lines)
         associate (piece => self%lines(l)%problem%piece)
            if (.not. allocated(self%kept_laws)) allocate (self%kept_laws(size(self%lines)))
            if (.not. allocated(self%kept_laws(l)%law)) then
               call uncut_law(piece%law, other, was_cut)
               call move_alloc(piece%law, self%kept_laws(l)%law)
               call move_alloc(other, piece%law)
               if (allocated(piece%sections)) then
                  allocate (self%kept_laws(l)%sections(size(piece%sections)))
                  do j = 1, size(piece%sections)
                     call uncut_law(piece%sections(j)%law, other, was_cut)
                     call move_alloc(piece%sections(j)%law, self%kept_laws(l)%sections(j)%law)
                     call move_alloc(other, piece%sections(j)%law)
                  end do
               end if
            else
               deallocate (piece%law)
               call move_alloc(self%kept_laws(l)%law, piece%law)
               if (allocated(piece%sections)) then
                  do j = 1, size(piece%sections)
                     deallocate (piece%sections(j)%law)
                     call move_alloc(self%kept_laws(l)%sections(j)%law, piece%sections(j)%law)
                  end do
                  deallocate (self%kept_laws(l)%sections)
               end if
            end if
         end associate
      end do
   end subroutine swap_laws

   !> Set each joint end's position to its point's.
   subroutine place_points(self)
      type(network_run), intent(inout) :: self
      integer :: j
      do j = 1, size(self%joints)
         associate (jt => self%joints(j), piece => self%lines(self%joints(j)%line)%problem%piece)
            if (jt%side == 1) then
               select type (e => piece%end_a)
               type is (joint_end)
                  e%at = self%xp(:, jt%point)
               end select
            else
               select type (e => piece%end_b)
               type is (joint_end)
                  e%at = self%xp(:, jt%point)
               end select
            end if
         end associate
      end do
   end subroutine place_points

   !> Evaluate and factorise every line at its current iterate, and form the points' system:
   !> the matrix s (the Schur complement) and the right-hand side rhs = -g + sum T J z. Each line's
   !> work%update holds z_l (= A_l^-1 res_l) afterwards.
   subroutine border(self, s, rhs, error)
      type(network_run), intent(inout) :: self
      real(dp), intent(out) :: s(:, :), rhs(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: l, j, jj, m, p, q, first, nc
      real(dp) :: tref
      s = 0
      rhs = 0
      call place_points(self)
      do l = 1, size(self%lines)
         associate (run => self%lines(l), piece => self%lines(l)%problem%piece)
            m = size(run%x)
            call run%problem%evaluate(run%x, run%work%residual(1:m), run%work%jacobian, .true.)
            if (.not. all(ieee_is_finite(run%work%residual(1:m)))) then
               call fatal_error(error, 'the residual of line '//str(l)//' is not finite', stat_numerics)
               return
            end if
            call run%work%jacobian%factor(error)
            if (allocated(error)) return
            run%work%update(1:m) = run%work%residual(1:m)
            call run%work%jacobian%solve(run%work%update(1:m), error)
            if (allocated(error)) return
         end associate
      end do
      do j = 1, size(self%joints)
         call joint_columns(self%lines(self%joints(j)%line), self%joints(j)%side, self%columns(j)%z, error)
         if (allocated(error)) return
      end do
      do j = 1, size(self%joints)
         l = self%joints(j)%line
         associate (run => self%lines(l), piece => self%lines(l)%problem%piece, jt => self%joints(j))
            m = size(run%x)
            tref = piece%tension_ref
            p = 3*(jt%point - 1)
            first = piece%kept_first(jt%side)
            nc = min(9, m - first + 1)
            rhs(p + 1:p + 3) = rhs(p + 1:p + 3) - tref*piece%kept_residual(:, jt%side) &
                               + tref*matmul(piece%kept_jac(:, 1:nc, jt%side), run%work%update(first:first + nc - 1))
            do jj = 1, size(self%joints)
               if (self%joints(jj)%line /= l) cycle
               q = 3*(self%joints(jj)%point - 1)
               s(p + 1:p + 3, q + 1:q + 3) = s(p + 1:p + 3, q + 1:q + 3) &
                                             + tref*matmul(piece%kept_jac(:, 1:nc, jt%side), &
                                                           self%columns(jj)%z(first:first + nc - 1, :))
            end do
         end associate
      end do
   end subroutine border

   !> Z = A^-1 E / L of one joint of a line (its factorised Jacobian): the line's response to a
   !> unit move of the point, (unknowns, 3). The columns' storage is kept from one iteration to
   !> the next (allocated once per joint).
   subroutine joint_columns(run, side, zcol, error)
      type(rod3d_run), intent(inout) :: run
      integer, intent(in) :: side
      real(dp), allocatable, intent(inout) :: zcol(:, :)
      type(error_type), allocatable, intent(out) :: error
      integer :: m, k, a
      m = size(run%x)
      k = merge(1, run%problem%piece%n, side == 1)
      if (allocated(zcol)) then
         if (size(zcol, 1) /= m) deallocate (zcol)
      end if
      if (.not. allocated(zcol)) allocate (zcol(m, 3))
      zcol = 0
      do a = 1, 3
         zcol(3*(k - 1) + a, a) = 1/run%problem%piece%length_ref
         call run%work%jacobian%solve(zcol(:, a), error)
         if (allocated(error)) return
      end do
   end subroutine joint_columns

   !> Newton's iteration on the lines and points (statics: a point's move limited per iteration).
   subroutine solve(self, static, error)
      type(network_run), intent(inout) :: self
      logical, intent(in) :: static
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: s(3*self%points, 3*self%points), dxp(3*self%points), alpha, dnorm, shortest(self%points), move
      real(dp), allocatable :: du(:)
      integer :: it, l, j, m, p, info, ipiv(3*self%points), limit
      limit = merge(self%static_iterations, self%max_iterations, static)
      shortest = huge(1.0_dp)
      do j = 1, size(self%joints)
         associate (piece => self%lines(self%joints(j)%line)%problem%piece)
            shortest(self%joints(j)%point) = min(shortest(self%joints(j)%point), sum(piece%ds))
         end associate
      end do
      self%last_iterations = 0
      do it = 1, limit
         call border(self, s, dxp, error)
         if (allocated(error)) return
         info = 0
         if (self%points > 0) call dgesv(3*self%points, 1, s, 3*self%points, ipiv, dxp, 3*self%points, info)
         if (info /= 0) then
            call fatal_error(error, 'the points'' system is singular (dgesv info '//str(info)//')', stat_numerics)
            return
         end if
         alpha = 1
         if (static) then
            do p = 1, self%points
               move = norm2(dxp(3*p - 2:3*p))
               if (move > self%static_step*shortest(p)) alpha = min(alpha, self%static_step*shortest(p)/move)
            end do
         end if
         dnorm = 0
         do p = 1, self%points
            dnorm = max(dnorm, maxval(abs(alpha*dxp(3*p - 2:3*p)))/self%lines(1)%problem%piece%length_ref)
            self%xp(:, p) = self%xp(:, p) + alpha*dxp(3*p - 2:3*p)
         end do
         do l = 1, size(self%lines)
            associate (run => self%lines(l))
               m = size(run%x)
               du = -run%work%update(1:m)
               do j = 1, size(self%joints)
                  if (self%joints(j)%line /= l) cycle
                  p = self%joints(j)%point
                  du = du + matmul(self%columns(j)%z, dxp(3*p - 2:3*p))
               end do
               du = alpha*du
               if (.not. all(ieee_is_finite(du))) then
                  call fatal_error(error, 'the update of line '//str(l)//' is not finite at iteration '//str(it), &
                                   stat_numerics)
                  return
               end if
               dnorm = max(dnorm, maxval(abs(du)/run%work%scale(1:m)))
               run%x = run%x + du
            end associate
         end do
         self%last_iterations = it
         self%iterations = self%iterations + 1
         if (dnorm <= self%tolerance .and. alpha == 1) then
            call finish(self)
            return
         end if
      end do
      call fatal_error(error, 'Newton did not converge in '//str(limit)//' iterations (last scaled update '// &
                       str(dnorm)//')', stat_numerics)
   end subroutine solve

   !> The residuals at the converged iterate (the lines' forces and the points' imbalance).
   subroutine finish(self)
      type(network_run), intent(inout) :: self
      integer :: l, m, j
      call place_points(self)
      do l = 1, size(self%lines)
         associate (run => self%lines(l))
            m = size(run%x)
            call run%problem%evaluate(run%x, run%work%residual(1:m), run%work%jacobian, .false.)
            run%evaluated_at_x = .true.
            run%work%usable = .false.
         end associate
      end do
      self%imbalance = 0
      do j = 1, size(self%joints)
         associate (jt => self%joints(j), piece => self%lines(self%joints(j)%line)%problem%piece)
            self%imbalance(:, jt%point) = self%imbalance(:, jt%point) + piece%tension_ref*piece%kept_residual(:, jt%side)
         end associate
      end do
   end subroutine finish
end module xcable_driver_network
