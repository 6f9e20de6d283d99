!> The water's surface (&fluid surface_z, air_density, surface_band): the
!> wetted fraction of a straight cell against the exact fraction and its
!> derivatives against central differences (a cell lying in the surface too);
!> the fluid's cell force across the surface against central differences in 2-D
!> and 3-D; a crane line hanging through the surface against the closed form of
!> its dry and wet weights; the line lowered through the surface against the
!> quasi-static closed form, without a jump as nodes cross; the energy ledger
!> of a line that bobs through the surface.
module suite_surface
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_loads_fluid, only: fluid_load
   use xcable_loads_surface, only: water_surface
   use xcable_driver_simulation, only: simulation
   use xcable_fixtures, only: run_text, column_text
   use xcable_driver_records, only: run_observer, static_info
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_surface

   real(dp), parameter :: pi = acos(-1.0_dp)
   character(len=*), parameter :: path = 'build/test_surface.nml'

   !> Keeps the static end tensions, ignores the snapshots.
   type, extends(run_observer) :: tension_keeper
      real(dp) :: tension(2) = 0
      !> Snapshots: times and heights z of the nodes (node, snapshot).
      integer :: n = 0
      real(dp), allocatable :: t(:), z(:, :)
   contains
      procedure :: static => keep_static
      procedure :: snapshot => keep_snapshot
   end type tension_keeper

   !> The crane scene: a 30 m line (d 0.1 m, 2000 kg/m^3, EA 1e8 N) with a 100 kg mass at end b,
   !> hung from end a in sea water.
   real(dp), parameter :: crane_length = 30, crane_d = 0.1_dp, crane_rho = 2000, crane_ea = 1.0e8_dp, &
                          crane_mass = 100, water = 1025, g = 9.81_dp

contains

   subroutine collect_surface(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('wetted_fraction_of_a_straight_cell', test_fraction), &
               new_unittest('cell_force_derivatives_across_the_surface', test_force_derivatives), &
               new_unittest('crane_statics', test_crane), &
               new_unittest('lowering_through_the_surface', test_lowering), &
               new_unittest('ledger_of_a_line_bobbing_through_the_surface', test_ledger)]
   end subroutine collect_surface

   subroutine keep_static(self, info, error)
      class(tension_keeper), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
      self%tension = [info%tension_a, info%tension_b]
   end subroutine keep_static

   subroutine keep_snapshot(self, t, fields, error)
      class(tension_keeper), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: tt(:), zz(:, :)
      if (.not. allocated(self%t)) allocate (self%t(0), self%z(size(fields, 1), 0))
      allocate (tt(self%n + 1), zz(size(fields, 1), self%n + 1))
      tt(1:self%n) = self%t(1:self%n)
      zz(:, 1:self%n) = self%z(:, 1:self%n)
      self%n = self%n + 1
      tt(self%n) = t
      zz(:, self%n) = fields(:, 7)
      call move_alloc(tt, self%t)
      call move_alloc(zz, self%z)
   end subroutine keep_snapshot

   !> Where no end lies in the band, the fraction is the exact fraction of the straight cell
   !> under the level (to round-off), at any angle and with either end up; with band 0 it is so
   !> everywhere, and a horizontal cell in the level is half wet. Its derivatives agree with
   !> central differences wherever the band is crossed (a cell lying in the surface, ends inside
   !> the band, a cell spanning it); and sliding one end through the surface in steps of 1e-5 m
   !> changes it by at most the step over the band (no jump).
   subroutine test_fraction(error)
      type(error_type), allocatable, intent(out) :: error
      type(water_surface) :: s, step
      real(dp), parameter :: outside(2, 8) = reshape([-2.0_dp, 1.5_dp, 1.5_dp, -2.0_dp, -0.4_dp, 0.36_dp, &
                                                      0.9_dp, 0.2_dp, 0.36_dp, 0.9_dp, -1.0_dp, -0.5_dp, &
                                                      0.2_dp, 0.4_dp, 0.351_dp, 0.249_dp], [2, 8])
      real(dp), parameter :: inside(2, 9) = reshape([0.3_dp, 0.3_dp, 0.31_dp, 0.29_dp, 0.27_dp, 0.5_dp, &
                                                     -0.2_dp, 0.32_dp, 0.3_dp, -1.0_dp, 0.28_dp, 0.28_dp, &
                                                     0.33_dp, 0.26_dp, 0.2_dp, 0.4_dp, 0.3_dp, 0.3_dp + 1.0e-12_dp], &
                                                    [2, 9])
      real(dp) :: phi, d1, d2, p1, p2, q1, q2, worst_exact, worst_fd, worst_jump, h, z, last, lo, hi
      integer :: k
      s = water_surface(level=0.3_dp, band=0.1_dp)
      step = water_surface(level=0.3_dp, band=0)
      worst_exact = 0
      do k = 1, size(outside, 2)
         lo = minval(outside(:, k))
         hi = maxval(outside(:, k))
         call s%wetted_fraction(outside(1, k), outside(2, k), phi, d1, d2)
         worst_exact = max(worst_exact, abs(phi - min(1.0_dp, max(0.0_dp, (0.3_dp - lo)/(hi - lo)))))
         call step%wetted_fraction(inside(1, k), inside(2, k), phi, d1, d2)
         lo = minval(inside(:, k))
         hi = maxval(inside(:, k))
         if (hi > lo) worst_exact = max(worst_exact, abs(phi - min(1.0_dp, max(0.0_dp, (0.3_dp - lo)/(hi - lo)))))
      end do
      call step%wetted_fraction(0.3_dp, 0.3_dp, phi, d1, d2)
      worst_exact = max(worst_exact, abs(phi - 0.5_dp))
      worst_fd = 0
      h = 1.0e-7_dp
      do k = 1, size(inside, 2)
         call s%wetted_fraction(inside(1, k), inside(2, k), phi, d1, d2)
         call s%wetted_fraction(inside(1, k) + h, inside(2, k), p1, q1, q2)
         call s%wetted_fraction(inside(1, k) - h, inside(2, k), p2, q1, q2)
         worst_fd = max(worst_fd, abs((p1 - p2)/(2*h) - d1)*s%band)
         call s%wetted_fraction(inside(1, k), inside(2, k) + h, p1, q1, q2)
         call s%wetted_fraction(inside(1, k), inside(2, k) - h, p2, q1, q2)
         worst_fd = max(worst_fd, abs((p1 - p2)/(2*h) - d2)*s%band)
      end do
      worst_jump = 0
      call s%wetted_fraction(-0.5_dp, 0.3_dp, last, d1, d2)
      do k = 1, 150000
         z = -0.5_dp + 1.0e-5_dp*k
         call s%wetted_fraction(z, 0.3_dp, phi, d1, d2)
         worst_jump = max(worst_jump, abs(phi - last)/(1.0e-5_dp/s%band))
         last = phi
      end do
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,f7.4)') 'wetted fraction: off the exact fraction by', worst_exact, &
         '; derivatives off central differences by', worst_fd, ' (times the band); largest change over a step '// &
         '/ (step / band)', worst_jump
      call check(error, worst_exact < 1.0e-15_dp, 'the wetted fraction is off the exact one by '//str(worst_exact))
      if (allocated(error)) return
      call check(error, worst_fd < 1.0e-9_dp, 'the wetted fraction''s derivatives are off by '//str(worst_fd))
      if (allocated(error)) return
      call check(error, worst_jump <= 1, 'the wetted fraction jumps: '//str(worst_jump))
   end subroutine test_fraction

   !> The fluid's force per unstretched length on cells that cross the surface at angles from
   !> 0 (lying in it) to 135 degrees, with the air's drag and added mass above it and a current
   !> below: df/dx, df/de, df/dw and df/da against central differences, in 2-D (cell_force) and
   !> in 3-D (cell_force3, the cell turned out of the x-z plane).
   subroutine test_force_derivatives(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angles(7) = [0.0_dp, 2.0_dp, 5.0_dp, 30.0_dp, 60.0_dp, 90.0_dp, 135.0_dp]
      real(dp), parameter :: heights(5) = [0.0_dp, 0.012_dp, -0.02_dp, 0.2_dp, -0.07_dp]
      real(dp), parameter :: ds = 0.5_dp, h = 1.0e-7_dp, azimuth = 40*pi/180
      type(fluid_load) :: f
      real(dp) :: x2(2), e2(2), w2(2), a2(2), x3(3), e3(3), w3(3), a3(3), al, worst2, worst3, crossed
      integer :: i, j
      f = fluid_load(density=water, cd_normal=1.2_dp, cd_tangential=0.05_dp, ca_normal=1.0_dp, &
                     current=[0.4_dp, 0.1_dp], current_y=0.2_dp, diameter=0.05_dp, area=0.25_dp*pi*0.05_dp**2, &
                     gravity=g, surface=water_surface(level=0, band=0.05_dp), air_density=1.225_dp)
      worst2 = 0
      worst3 = 0
      crossed = 0
      do i = 1, size(angles)
         al = angles(i)*pi/180
         do j = 1, size(heights)
            x2 = [1.7_dp, heights(j)]
            e2 = 1.01_dp*[cos(al), sin(al)]
            w2 = [0.3_dp, -0.45_dp]
            a2 = [-0.8_dp, 0.6_dp]
            worst2 = max(worst2, off(x2, e2, w2, a2))
            x3 = [1.7_dp, -0.4_dp, heights(j)]
            e3 = 1.01_dp*[cos(al)*cos(azimuth), cos(al)*sin(azimuth), sin(al)]
            w3 = [0.3_dp, 0.2_dp, -0.45_dp]
            a3 = [-0.8_dp, 0.1_dp, 0.6_dp]
            worst3 = max(worst3, off(x3, e3, w3, a3))
         end do
      end do
      write (output_unit, '(4x,a,2es9.2)') 'fluid force across the surface, 2-D and 3-D: largest |analytic - '// &
         'central difference| / (1 + |f|)', worst2, worst3
      call check(error, crossed > 0, 'no cell crossed the surface')
      if (allocated(error)) return
      call check(error, max(worst2, worst3) < 3.0e-8_dp, 'the fluid force''s derivatives across the surface are '// &
                 'off by '//str(worst2)//' (2-D), '//str(worst3)//' (3-D)')

   contains

      !> The largest deviation of df/dx, df/de, df/dw, df/da (2-D or 3-D by the size of x) over
      !> 1 + |f|; counts the cells that cross the surface.
      real(dp) function off(x, e, w, a) result(worst)
         real(dp), intent(in) :: x(:), e(:), w(:), a(:)
         real(dp), dimension(size(x)) :: f0, fp, fm, u
         real(dp), dimension(size(x), size(x)) :: dx, de, dw, da, d
         real(dp) :: phi, p1, p2
         integer :: k, v, m
         m = size(x)
         call force(x, e, w, a, f0, dx, de, dw, da)
         call f%wetted(x(m), ds, e(m), phi, p1, p2)
         if (phi > 0 .and. phi < 1) crossed = crossed + 1
         worst = 0
         do v = 1, 4
            do k = 1, m
               u = 0
               u(k) = h
               select case (v)
               case (1)
                  fp = value(x + u, e, w, a); fm = value(x - u, e, w, a)
               case (2)
                  fp = value(x, e + u, w, a); fm = value(x, e - u, w, a)
               case (3)
                  fp = value(x, e, w + u, a); fm = value(x, e, w - u, a)
               case (4)
                  fp = value(x, e, w, a + u); fm = value(x, e, w, a - u)
               end select
               d(:, k) = (fp - fm)/(2*h)
            end do
            select case (v)
            case (1)
               worst = max(worst, maxval(abs(d - dx)))
            case (2)
               worst = max(worst, maxval(abs(d - de)))
            case (3)
               worst = max(worst, maxval(abs(d - dw)))
            case (4)
               worst = max(worst, maxval(abs(d - da)))
            end select
         end do
         worst = worst/(1 + norm2(f0))
      end function off

      subroutine force(x, e, w, a, ff, dx, de, dw, da)
         real(dp), intent(in) :: x(:), e(:), w(:), a(:)
         real(dp), intent(out) :: ff(:), dx(:, :), de(:, :), dw(:, :), da(:, :)
         if (size(x) == 2) then
            call f%cell_force(x, ds, e, w, a, ff, dx, de, dw, da)
         else
            call f%cell_force3(x, ds, e, w, a, ff, dx, de, dw, da)
         end if
      end subroutine force

      function value(x, e, w, a) result(ff)
         real(dp), intent(in) :: x(:), e(:), w(:), a(:)
         real(dp) :: ff(size(x)), d0(size(x), size(x)), d1(size(x), size(x)), d2(size(x), size(x)), &
                     d3(size(x), size(x))
         call force(x, e, w, a, ff, d0, d1, d2, d3)
      end function value
   end subroutine test_force_derivatives

   !> The crane scene's top tension, dry weight above the water, wet weight below it, and the mass:
   !> T = g [m H' + (m - rho A) (L - H') + M], H' the unstretched length above the water, from
   !> H = H' + (T_w H' + m g H'^2 / 2) / EA with T_w the tension at the waterline (the line's
   !> stretch above it).
   real(dp) function crane_tension(height) result(t)
      real(dp), intent(in) :: height
      real(dp) :: area, m, wet, above, t_water
      integer :: k
      area = 0.25_dp*pi*crane_d**2
      m = crane_rho*area
      wet = (m - water*area)*g
      above = max(height, 0.0_dp)
      do k = 1, 60
         if (height <= 0) exit
         t_water = crane_mass*g + wet*(crane_length - above)
         above = above + (height - (above + (t_water*above + 0.5_dp*m*g*above**2)/crane_ea))
      end do
      t = crane_mass*g + wet*(crane_length - above) + m*g*above
   end function crane_tension

   !> The crane scene as namelist text, end a at height z (m), with the rest of &numerics.
   function crane_text(z, numerics) result(text)
      real(dp), intent(in) :: z
      character(*), intent(in) :: numerics
      character(:), allocatable :: text
      character(len=40) :: zt
      write (zt, '(es23.16)') z
      text = "&cable length = 30, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /"//new_line('a')// &
             "&material law = 'linear', ea = 1e8 /"//new_line('a')// &
             "&fluid density = 1025 /"//new_line('a')// &
             "&end_a kind = 'fixed', x = 0, z = "//trim(zt)//" /"//new_line('a')// &
             "&end_b kind = 'mass', mass = 100 /"//new_line('a')// &
             "&rupture enabled = .false. /"//new_line('a')// &
             "&numerics "//numerics//" /"//new_line('a')// &
             "&output interval = 0, quiet = .true. /"
   end function crane_text

   !> The crane's top tension with the tip 10 m above the water and 5 m under it (all of the
   !> line in water, as before the surface), 41 nodes, in 2-D and in 3-D; and in 2-D with the tip
   !> at 17 heights 0.09 m apart from 10 m down, which take the waterline through two nodes and
   !> the band around each: every one to the closed form (no jump as a node crosses).
   subroutine test_crane(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=2), parameter :: models(2) = ['2d', '3d']
      type(simulation) :: sim
      type(tension_keeper) :: obs
      real(dp) :: worst, exact, rel, tips(19), sweep
      integer :: i, j
      tips(1:2) = [10.0_dp, -5.0_dp]
      tips(3:19) = [(10 - 0.09_dp*i, i=1, 17)]
      worst = 0
      sweep = 0
      do i = 1, size(tips)
         exact = crane_tension(tips(i))
         do j = 1, merge(2, 1, i <= 2)
            call run_text(path, crane_text(tips(i), "model = '"//models(j)//"', nodes = 41, dt = 1e-3, t_end = 1e-3, "// &
                          "newton_tol = 1e-12"), sim, obs, error)
            if (allocated(error)) return
            rel = abs(obs%tension(1) - exact)/exact
            if (i <= 2) then
               write (output_unit, '(4x,a,f6.1,3a,f11.4,a,f11.4,a,es9.2)') 'crane, tip at z = ', tips(i), ' m, ', &
                  models(j), ': top tension', obs%tension(1), ' N, closed form', exact, ' N, relative error', rel
            else
               sweep = max(sweep, rel)
            end if
            worst = max(worst, rel)
         end do
      end do
      write (output_unit, '(4x,a,es9.2)') 'crane, tip at 17 heights from 9.91 m to 8.47 m: largest relative error', sweep
      call check(error, worst < 5.0e-9_dp, 'the crane''s top tension is off the closed form by '//str(worst))
   end subroutine test_crane

   !> The crane's tip lowered at 0.5 m/s (a smooth start over 2 s) from 10 m above the water to
   !> 5 m under it, the default time step of 5 ms: the force on the tip follows the
   !> quasi-static closed form with the dry length the tip's height, once averaged over 1 s
   !> windows (the axial ringing), from t = 3 s.
   subroutine test_lowering(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: speed = 0.5_dp, ramp = 2, t_end = 31
      type(simulation) :: sim
      type(tension_keeper) :: obs
      real(dp) :: worst_mean, window_t, window_exact, rows(50), zs(50)
      integer :: k, n, count, start
      ! Rows every 0.1 s over the start (so the table's first slope is nearly 0), then every second.
      rows(1:21) = [(0.1_dp*k, k=0, 20)]
      rows(22:50) = [(real(k, dp), k=3, 31)]
      where (rows < ramp)
         zs = -speed*(0.5_dp*rows - ramp/(2*pi)*sin(pi*rows/ramp))
      elsewhere
         zs = -speed*(rows - 0.5_dp*ramp)
      end where
      call run_text(path, "&cable length = 30, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /"//new_line('a')// &
                    "&material law = 'linear', ea = 1e8 /"//new_line('a')// &
                    "&fluid density = 1025 /"//new_line('a')// &
                    "&end_a kind = 'motion', x = 0, z = 10, motion = 'table',"//new_line('a')// &
                    column_text('table_time', rows)//new_line('a')//column_text('table_x', 0*rows)//new_line('a')// &
                    column_text('table_z', zs)//" /"//new_line('a')// &
                    "&end_b kind = 'mass', mass = 100 /"//new_line('a')// &
                    "&rupture enabled = .false. /"//new_line('a')// &
                    "&numerics nodes = 41, dt = 0.005, t_end = "//str(t_end)//" /"//new_line('a')// &
                    "&output interval = 0, quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      associate (hist => sim%rod%history)
         n = hist%n
         worst_mean = 0
         start = 0
         ! 1 s windows (200 records) from t = 3 s, past the start's transient; the force on the
         ! tip (the support's reaction, what a load cell at the crane reads).
         do while (start < n .and. hist%time(start) < 3)
            start = start + 1
         end do
         window_t = 0
         window_exact = 0
         count = 0
         do k = start, n
            window_t = window_t + hist%ends(7, 1, k)
            window_exact = window_exact + crane_tension(hist%ends(2, 1, k))
            count = count + 1
            if (count == 200 .or. k == n) then
               worst_mean = max(worst_mean, abs(window_t - window_exact)/window_exact)
               window_t = 0
               window_exact = 0
               count = 0
            end if
         end do
         write (output_unit, '(4x,a,f7.3,a,es9.2)') 'lowering through the surface to z = ', hist%ends(2, 1, n), &
            ' m: 1 s means of the force on the tip off the quasi-static closed form by', worst_mean
         call check(error, abs(hist%ends(2, 1, n) + 5) < 1.0e-6_dp, 'the tip did not reach z = -5 m')
         if (allocated(error)) return
      end associate
      call check(error, worst_mean < 3.0e-4_dp, 'the lowered line''s top tension is off the quasi-static closed '// &
                 'form by '//str(worst_mean))
   end subroutine test_lowering

   !> A nylon line (1140 kg/m^3, 20.3 m) hung between two supports 0.5 m above the water, 20 m
   !> apart, sags 1 m into it; end b heaves by 0.4 m (3 s period), so that the waterline runs
   !> along 7 m of cells. No drag and no added mass: the only fluid force besides the wet
   !> weight is the buoyancy the dry part lacks, booked as the fluid's work. The energy ledger
   !> closes to the Newton tolerance; and that work is minus the change of the exact potential
   !> of the surface's buoyancy (the integral along the straight cells, by quadrature here) up to
   !> the lumping of each cell's force onto its two nodes, which vanishes at order 2 under
   !> refinement (61 and 121 nodes, dt 5 and 2.5 ms).
   subroutine test_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: grids(2) = [61, 121]
      type(simulation) :: sim
      type(tension_keeper) :: obs
      real(dp) :: drift(2), scale, wet_min, wet_max, mismatch(2), change, k_b, band
      integer :: n, i, j, r
      k_b = 1025*0.25_dp*pi*0.03_dp**2*g
      band = 0.03_dp
      do i = 1, 2
         obs%n = 0
         if (allocated(obs%t)) deallocate (obs%t, obs%z)
         call run_text(path, "&cable length = 20.3, diameter = 0.03, density = 1140 /"//new_line('a')// &
                       "&material law = 'linear', ea = 2e6 /"//new_line('a')// &
                       "&fluid density = 1025 /"//new_line('a')// &
                       "&end_a kind = 'fixed', x = 0, z = 0.5 /"//new_line('a')// &
                       "&end_b kind = 'motion', x = 20, z = 0.5, motion = 'harmonic', amplitude = 0.4, "// &
                       "period = 3, ramp_time = 1, direction_x = 0, direction_z = 1 /"//new_line('a')// &
                       "&rupture enabled = .false. /"//new_line('a')// &
                       "&numerics nodes = "//str(grids(i))//", dt = "//str(0.005_dp*60/(grids(i) - 1))// &
                       ", t_end = 6, newton_tol = 1e-12 /"//new_line('a')// &
                       "&output interval = 1, quiet = .true., energy = .true. /", sim, obs, error)
         if (allocated(error)) return
         associate (hist => sim%rod%history)
            n = hist%n
            scale = maxval(abs(hist%energy(1:6, 0:n)))
            drift(i) = maxval(abs(hist%energy(7, 0:n) - hist%energy(7, 0)))/scale
            wet_min = minval(hist%measures(1, 0:n))
            wet_max = maxval(hist%measures(1, 0:n))
            ! The fluid's work against the exact potential at each snapshot (every second).
            mismatch(i) = 0
            change = 0
            do j = 2, obs%n
               r = minloc(abs(hist%time(0:n) - obs%t(j)), 1) - 1
               change = max(change, abs(potential(obs%z(:, j)) - potential(obs%z(:, 1))))
               mismatch(i) = max(mismatch(i), abs(hist%energy(8, r) + potential(obs%z(:, j)) - potential(obs%z(:, 1))))
            end do
         end associate
         write (output_unit, '(4x,a,i4,a,2f7.2,a,es9.2,a,es9.2,a,f6.3,a)') 'line bobbing through the surface,', &
            grids(i), ' nodes: wetted length', wet_min, wet_max, ' m; ledger drift', drift(i), &
            ' of the largest term; fluid work + exact potential change', mismatch(i), ' J (the change: up to', &
            change, ' J)'
      end do
      call check(error, wet_max - wet_min > 5, 'the waterline hardly moved: '//str(wet_min)//' to '//str(wet_max))
      if (allocated(error)) return
      call check(error, maxval(drift) < 1.0e-10_dp, 'the ledger of the bobbing line drifts by '//str(maxval(drift)))
      if (allocated(error)) return
      call check(error, mismatch(1)/mismatch(2) > 3.5_dp .and. mismatch(2) < 3.0e-2_dp, 'the fluid''s work is not '// &
                 'the change of the buoyancy''s potential at order 2: '//str(mismatch(1))//', '//str(mismatch(2))//' J')

   contains

      !> The potential of the buoyancy the dry part lacks, k_b int (1 - g(z)) dz per unstretched
      !> length, along the straight cells of a uniform grid (midpoint rule, 2000 points a cell).
      real(dp) function potential(z) result(u)
         real(dp), intent(in) :: z(:)
         real(dp) :: ds, zz, xi
         integer :: c, q
         ds = 20.3_dp/(size(z) - 1)
         u = 0
         do c = 1, size(z) - 1
            do q = 1, 2000
               xi = (q - 0.5_dp)/2000
               zz = z(c) + xi*(z(c + 1) - z(c))
               if (zz >= 0.5_dp*band) then
                  u = u + ds/2000*k_b*zz
               else if (zz > -0.5_dp*band) then
                  u = u + ds/2000*k_b*(zz + 0.5_dp*band)**2/(2*band)
               end if
            end do
         end do
      end function potential
   end subroutine test_ledger
end module suite_surface
