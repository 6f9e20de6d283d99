!> The seabed (&seabed): the contact, damping and friction force of a cell and
!> its unequal shares against central differences, in 2-D and 3-D, for cells
!> lying on the bottom, crossing it at several angles and clear of it; an
!> elastic catenary resting partly on a frictionless bottom against its closed
!> form; the OC3-Hywind mooring's published stiffness (Jonkman 2010); and the energy ledger of a line dropped onto the bottom, with and
!> without friction.
module suite_seabed
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_loads_seabed, only: seabed_load
   use xcable_driver_simulation, only: simulation
   use xcable_model_rod, only: rod_kl, rod_ku
   use xcable_fdcheck, only: check_jacobian
   use xcable_fixtures, only: run_text, column_text
   use xcable_driver_records, only: run_observer, static_info
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_seabed

   real(dp), parameter :: pi = acos(-1.0_dp), g = 9.81_dp
   character(len=*), parameter :: path = 'build/test_seabed.nml'

   !> Keeps the static state's heights and end tensions.
   type, extends(run_observer) :: static_keeper
      real(dp) :: tension(2) = 0
      real(dp), allocatable :: s(:), x(:), z(:)
   contains
      procedure :: static => keep_static
      procedure :: snapshot => skip_snapshot
   end type static_keeper

contains

   subroutine collect_seabed(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('contact_and_friction_derivatives', test_derivatives), &
               new_unittest('catenary_on_a_frictionless_bottom', test_catenary), &
               new_unittest('catenary_on_the_bottom_3d_at_an_azimuth', test_catenary_3d), &
               new_unittest('catenary_with_static_friction_closed_form', test_static_friction), &
               new_unittest('chain_with_full_static_friction', test_chain_friction), &
               new_unittest('oc3_hywind_mooring_stiffness_published', test_oc3_hywind), &
               new_unittest('ledger_of_a_line_dropped_on_the_bottom', test_ledger), &
               new_unittest('line_towed_along_the_bottom', test_towed), &
               new_unittest('line_too_long_to_be_taut_explained', test_too_long), &
               new_unittest('nearly_slack_line_paid_in_closed_form', test_paid_in), &
               new_unittest('slack_rope_on_the_bottom_refused', test_slack_refused), &
               new_unittest('end_resting_on_the_bottom_laid_closed_form', test_laid), &
               new_unittest('bathymetry_of_a_plane_is_the_plane', test_bathymetry_plane), &
               new_unittest('bathymetry_across_the_line_3d', test_bathymetry_3d), &
               new_unittest('bathymetry_with_a_bend_ledger_and_derivatives', test_bathymetry_bend), &
               new_unittest('bathymetry_bad_input_refused', test_bathymetry_bad)]
   end subroutine collect_seabed

   subroutine keep_static(self, info, error)
      class(static_keeper), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
      self%tension = [info%tension_a, info%tension_b]
      self%s = info%s
      self%x = info%fields(:, 6)
      self%z = info%fields(:, 7)
   end subroutine keep_static

   subroutine skip_snapshot(self, t, fields, error)
      class(static_keeper), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
   end subroutine skip_snapshot

   !> A sloping bottom (slopes 0.1 along x, -0.05 along y), contact stiffness, damping and
   !> friction along and across the line: the force per unstretched length and its unequal
   !> share, df/dx, df/de, df/dw (and the same of g) against central differences, for cells at
   !> angles from 0 (lying on the bottom) to 90 degrees to it and at heights from in to out of
   !> it, moving in the bottom's plane and into it.
   subroutine test_derivatives(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angles(6) = [0.0_dp, 3.0_dp, 20.0_dp, 45.0_dp, 90.0_dp, 160.0_dp]
      real(dp), parameter :: heights(6) = [-0.02_dp, -0.003_dp, 0.0_dp, 0.004_dp, 0.05_dp, 0.4_dp]
      real(dp), parameter :: stretches(3) = [1.02_dp, 1.1_dp, 0.97_dp]
      real(dp), parameter :: ds = 0.5_dp, h = 1.0e-7_dp, azimuth = 25*pi/180
      type(seabed_load) :: bed
      real(dp) :: worst(2), worst_static(2), al, x3(3), e3(3), w3(3), x2(2), e2(2), w2(2), base
      integer :: i, j, k, m, touching
      bed = seabed_load(depth=30, slope_x=0.1_dp, slope_y=-0.05_dp, stiffness=2.0e5_dp, damping=3.0e3_dp, &
                        mu_axial=0.6_dp, mu_lateral=0.9_dp, slip_velocity=0.05_dp)
      worst = 0
      worst_static = 0
      touching = 0
      do i = 1, size(angles)
         al = angles(i)*pi/180
         do j = 1, size(heights)
            ! The cell's middle at (2, -1.5) (3-D) or x = 2 (2-D), heights(j) above the bottom there.
            base = bed%bottom([2.0_dp, -1.5_dp])
            x3 = [2.0_dp, -1.5_dp, base + heights(j)]
            e3 = 1.02_dp*[cos(al)*cos(azimuth), cos(al)*sin(azimuth), sin(al)] + [0.0_dp, 0.0_dp, 0.1_dp*cos(al)]
            w3 = [0.3_dp, -0.2_dp, -0.05_dp]
            worst(2) = max(worst(2), off(x3, e3, w3))
            x2 = [2.0_dp, bed%bottom([2.0_dp]) + heights(j)]
            e2 = 1.02_dp*[cos(al), sin(al)] + [0.0_dp, 0.1_dp*cos(al)]
            w2 = [0.3_dp, -0.05_dp]
            worst(1) = max(worst(1), off(x2, e2, w2))
         end do
      end do
      ! The statics' friction towards end a and towards end b, with a fading strain eps_r of 0.03
      ! (the default's 1e-8 is below what central differences resolve): cells stretched by 2 %
      ! (inside the fade), 10 % (past it) and compressed (none).
      do k = -1, 1, 2
         bed%static_towards = k
         bed%static_strain = 0.03_dp
         call bed%set_statics(.true., 0.0_dp, 0.0_dp, 1.0_dp)
         do i = 1, size(angles)
            al = angles(i)*pi/180
            do j = 1, size(heights)
               do m = 1, 3
                  base = bed%bottom([2.0_dp, -1.5_dp])
                  x3 = [2.0_dp, -1.5_dp, base + heights(j)]
                  e3 = stretches(m)*[cos(al)*cos(azimuth), cos(al)*sin(azimuth), sin(al)]
                  w3 = [0.3_dp, -0.2_dp, -0.05_dp]
                  worst_static(2) = max(worst_static(2), off(x3, e3, w3))
                  x2 = [2.0_dp, bed%bottom([2.0_dp]) + heights(j)]
                  e2 = stretches(m)*[cos(al), sin(al)]
                  w2 = [0.3_dp, -0.05_dp]
                  worst_static(1) = max(worst_static(1), off(x2, e2, w2))
               end do
            end do
         end do
      end do
      call bed%set_statics(.false., 0.0_dp, 0.0_dp, 1.0_dp)
      write (output_unit, '(4x,a,2es9.2,a,i0,a)') 'seabed force and shares: largest |analytic - central difference| '// &
         '/ (1 + |f| + the largest derivative), 2-D and 3-D', worst, ' (', touching, ' cells touching)'
      write (output_unit, '(4x,a,2es9.2)') 'with the statics'' friction, 2-D and 3-D', worst_static
      call check(error, maxval(worst_static) < 3.0e-8_dp, 'the seabed''s static friction derivatives are off by '// &
                 str(worst_static(1))//' (2-D), '//str(worst_static(2))//' (3-D)')
      if (allocated(error)) return
      call check(error, touching > 20, 'too few cells touched the bottom: '//str(touching))
      if (allocated(error)) return
      call check(error, maxval(worst) < 3.0e-8_dp, 'the seabed''s derivatives are off by '//str(worst(1))//' (2-D), '// &
                 str(worst(2))//' (3-D)')

   contains

      !> Largest deviation of f's and g's derivatives in x, e and w.
      real(dp) function off(x, e, w) result(dev)
         real(dp), intent(in) :: x(:), e(:), w(:)
         real(dp), dimension(size(x)) :: f, gg, fp, fm, gp, gm, u, a
         real(dp), dimension(size(x), size(x)) :: fx, fe, fw, gx, ge, gw, q1, q2, q3, q4, q5, q6
         integer :: k, v, m
         m = size(x)
         a = 0
         call force(x, e, w, f, gg, fx, fe, fw, gx, ge, gw)
         if (norm2(f) > 0) touching = touching + 1
         dev = 0
         do v = 1, 3
            do k = 1, m
               u = 0
               u(k) = h
               select case (v)
               case (1)
                  call force(x + u, e, w, fp, gp, q1, q2, q3, q4, q5, q6)
                  call force(x - u, e, w, fm, gm, q1, q2, q3, q4, q5, q6)
                  dev = max(dev, maxval(abs((fp - fm)/(2*h) - fx(:, k))), maxval(abs((gp - gm)/(2*h) - gx(:, k))))
               case (2)
                  call force(x, e + u, w, fp, gp, q1, q2, q3, q4, q5, q6)
                  call force(x, e - u, w, fm, gm, q1, q2, q3, q4, q5, q6)
                  dev = max(dev, maxval(abs((fp - fm)/(2*h) - fe(:, k))), maxval(abs((gp - gm)/(2*h) - ge(:, k))))
               case (3)
                  call force(x, e, w + u, fp, gp, q1, q2, q3, q4, q5, q6)
                  call force(x, e, w - u, fm, gm, q1, q2, q3, q4, q5, q6)
                  dev = max(dev, maxval(abs((fp - fm)/(2*h) - fw(:, k))), maxval(abs((gp - gm)/(2*h) - gw(:, k))))
               end select
            end do
         end do
         ! Relative to the largest derivative (a stiff contact's derivatives are much larger than
         ! its force, and central differences err by a fraction of them).
         dev = dev/(1 + norm2(f) + max(maxval(abs(fx)), maxval(abs(fe)), maxval(abs(fw)), maxval(abs(gx)), &
                                       maxval(abs(ge))))
      end function off

      subroutine force(x, e, w, f, gg, fx, fe, fw, gx, ge, gw)
         real(dp), intent(in) :: x(:), e(:), w(:)
         real(dp), intent(out) :: f(:), gg(:), fx(:, :), fe(:, :), fw(:, :), gx(:, :), ge(:, :), gw(:, :)
         real(dp) :: a(size(x)), fa(size(x), size(x)), ga(size(x), size(x))
         a = 0
         if (size(x) == 2) then
            call bed%cell_force(x, ds, e, w, a, f, fx, fe, fw, fa)
         else
            call bed%cell_force3(x, ds, e, w, a, f, fx, fe, fw, fa)
         end if
         call bed%cell_skew(x, ds, e, w, a, gg, gx, ge, gw, ga)
      end subroutine force
   end subroutine test_derivatives

   !> A 100 m line (d 0.1 m, 2000 kg/m^3, EA 1e8 N, in sea water) from an anchor on a flat,
   !> frictionless bottom 40 m down to a fairlead 80 m away at z = 0: the elastic catenary with
   !> a grounded part, against its closed form (grounded_catenary): anchor tension H, fairlead
   !> tension sqrt(H^2 + V^2), grounded length L_b. Stiffness 1e10 Pa (the line sinks
   !> w/k = 7.5e-8 m into the bottom), 1601 nodes. The touchdown, from the static shape: the
   !> square root of the height of the first two nodes off the bottom is linear in the arc
   !> length (z = (s - s_t)^2 / (2 R) near it), extrapolated to 0.
   subroutine test_catenary(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: length = 100, span = 80, drop = 40, ea = 1.0e8_dp
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: w, hh, lb, touch, errs(3), flat
      integer :: k
      w = (2000 - 1025)*0.25_dp*pi*0.1_dp**2*g
      call grounded_catenary(length, span, drop, w, ea, [1800.0_dp, 40.0_dp], hh, lb)
      call run_text(path, "&cable length = 100, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /"//new_line('a')// &
                    "&material law = 'linear', ea = 1e8 /"//new_line('a')// &
                    "&fluid density = 1025, surface_z = 10 /"//new_line('a')// &
                    "&seabed depth = 40, stiffness = 1e10 /"//new_line('a')// &
                    "&end_a kind = 'fixed', x = 0, z = -40 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 80, z = 0 /"//new_line('a')// &
                    "&rupture enabled = .false. /"//new_line('a')// &
                    "&numerics nodes = 1601, dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12 /"//new_line('a')// &
                    "&output interval = 0, quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      call touchdown(obs, drop, touch, k)
      ! The grounded nodes (clear of the anchor and the touchdown) lie flat at the sink w/k: with
      ! equal shares of each cell's contact they would zigzag (a mode no cell's mean sees).
      flat = maxval(abs(obs%z(3:k - 3) + drop + w/(1.0e10_dp*0.1_dp)))
      errs = [abs(obs%tension(1) - hh)/hh, abs(obs%tension(2) - hypot(hh, w*(length - lb)))/hypot(hh, w*(length - lb)), &
              abs(touch - lb)/lb]
      write (output_unit, '(4x,a,3f12.5,a,3es9.2,a,es9.2,a)') 'catenary on the bottom: anchor tension, fairlead '// &
         'tension, touchdown', obs%tension(1), obs%tension(2), touch, '; relative errors', errs, &
         '; grounded nodes off the sink by up to', flat, ' m'
      call check(error, flat < 2.0e-8_dp, 'the grounded part is not flat: '//str(flat)//' m')
      if (allocated(error)) return
      call check(error, errs(1) < 2.0e-6_dp .and. errs(2) < 2.0e-6_dp .and. errs(3) < 1.0e-4_dp, &
                 'the catenary on the bottom is off its closed form: '//str(errs(1))//', '//str(errs(2))//', '// &
                 str(errs(3)))

   end subroutine test_catenary

   !> The catenary of test_catenary with friction on the bottom in the statics
   !> (static_friction = 'end_a': mu_axial fully mobilised towards the anchor), against the closed
   !> form (grounded_catenary with cb = mu): mu = 0.5 leaves the anchor a tension
   !> (H - mu w L_b > 0), mu = 1 takes it all (T_a = 0, the tension reaches zero before the
   !> anchor). 401, 801 and 1601 nodes, planar; the 3-D model on 401 nodes gives the planar
   !> figures. Compared: the anchor tension (against H), the fairlead tension, the touchdown.
   subroutine test_static_friction(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: length = 100, span = 80, drop = 40, ea = 1.0e8_dp
      character(len=*), parameter :: mus(2) = ['0.5', '1.0']
      real(dp), parameter :: mu_values(2) = [0.5_dp, 1.0_dp]
      integer, parameter :: nodes(3) = [401, 801, 1601]
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: w, mu, hh, lb, ta, tf, errs(3, 3, 2), err3(3), touch
      integer :: i, j
      character(len=8) :: nn
      w = (2000 - 1025)*0.25_dp*pi*0.1_dp**2*g
      do i = 1, 2
         mu = mu_values(i)
         call grounded_catenary(length, span, drop, w, ea, [1800.0_dp, 40.0_dp], hh, lb, cb=mu)
         ta = max(hh - mu*w*lb, 0.0_dp)
         tf = hypot(hh, w*(length - lb))
         do j = 1, size(nodes) + 1
            write (nn, '(i0)') nodes(min(j, size(nodes)))
            if (j > size(nodes)) nn = '401'
            call run_text(path, "&cable length = 100, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /"// &
                          new_line('a')//"&material law = 'linear', ea = 1e8 /"//new_line('a')// &
                          "&fluid density = 1025, surface_z = 10 /"//new_line('a')// &
                          "&seabed depth = 40, stiffness = 1e10, mu_axial = "//mus(i)// &
                          ", static_friction = 'end_a' /"//new_line('a')// &
                          "&end_a kind = 'fixed', x = 0, z = -40 /"//new_line('a')// &
                          "&end_b kind = 'fixed', x = 80, z = 0 /"//new_line('a')// &
                          "&rupture enabled = .false. /"//new_line('a')// &
                          "&numerics nodes = "//trim(nn)//", dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12"// &
                          merge(", model = '3d'", "              ", j > size(nodes))//" /"//new_line('a')// &
                          "&output interval = 0, quiet = .true. /", sim, obs, error)
            if (allocated(error)) return
            call touchdown(obs, drop, touch)
            if (j <= size(nodes)) then
               errs(:, j, i) = [abs(obs%tension(1) - ta)/hh, abs(obs%tension(2) - tf)/tf, abs(touch - lb)/lb]
               write (output_unit, '(4x,a,a,i6,a,3f12.4,a,3es9.2)') 'mu ', mus(i), nodes(j), &
                  ' nodes: anchor, fairlead tension, touchdown', obs%tension(1), obs%tension(2), touch, &
                  '; errors (anchor / H, fairlead, touchdown)', errs(:, j, i)
            else
               err3 = [abs(obs%tension(1) - ta)/hh, abs(obs%tension(2) - tf)/tf, abs(touch - lb)/lb]
               write (output_unit, '(4x,a,a,a,3f12.4,a,3es9.2)') 'mu ', mus(i), ' 3-D, 401 nodes:', obs%tension(1), &
                  obs%tension(2), touch, '; errors', err3
               call check(error, maxval(abs(err3 - errs(:, 1, i))) < 1.0e-6_dp, 'mu '//mus(i)//': the 3-D statics '// &
                          'differ from the planar: '//str(maxval(abs(err3 - errs(:, 1, i)))))
               if (allocated(error)) return
            end if
         end do
         write (output_unit, '(4x,a,a,a,f12.4,a,3f12.4)') 'mu ', mus(i), ': closed form anchor', ta, &
            ' N, fairlead, touchdown, H', tf, lb, hh
      end do
      ! Measured at 1601 nodes: anchor 4.4e-4 and 7.5e-4 of H, fairlead 3.3e-7 and 3.4e-7,
      ! touchdown 1.6e-5 and 1.4e-5. The anchor's error is first order: its support takes half the
      ! first cell's friction, mu w ds / 2, and where the friction takes all the tension it fades
      ! over fade_cells cells (loads/seabed.f90); the anchor errors halve with each halving of ds.
      call check(error, maxval(errs(1, 3, :)) < 2.0e-3_dp .and. maxval(errs(2, 3, :)) < 1.0e-6_dp .and. &
                 maxval(errs(3, 3, :)) < 5.0e-5_dp, 'the catenary with static friction is off its closed form: '// &
                 'anchor '//str(maxval(errs(1, 3, :)))//', fairlead '//str(maxval(errs(2, 3, :)))//', touchdown '// &
                 str(maxval(errs(3, 3, :))))
      if (allocated(error)) return
      call check(error, minval(errs(1, 2, :)/errs(1, 3, :)) > 1.8_dp, 'the anchor tension does not converge at '// &
                 'first order: error ratios 801/1601 nodes '//str(errs(1, 2, 1)/errs(1, 3, 1))//', '// &
                 str(errs(1, 2, 2)/errs(1, 3, 2)))
   end subroutine test_static_friction

   !> The chain of input/chain_mooring_heave.nml (250 m, 76 mm R4 studless, linear EA) on a flat,
   !> default (soft) bottom 60 m down, its fairlead 230 m away and 10 m under the surface, with
   !> static_friction = 'end_a' and mu_axial = 1 (the friction takes all the anchor's tension),
   !> 401 nodes: Newton cannot take the friction at once from the frictionless state, and the
   !> statics' continuation in its share finds it. The fairlead's tension against the closed form
   !> with friction (grounded_catenary, cb = 1): measured 1.9e-5 (the line sinks 2.4 mm into the
   !> soft bottom; NREL MoorPy's catenary gives the closed form's figure, bench/peer/static_friction.py).
   subroutine test_chain_friction(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: dc = 0.076_dp, length = 250, span = 230, drop = 50
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: mass, ea, dvol, w, density, hh, lb, tf, err
      character(len=200) :: line
      mass = 20.01e3_dp*dc*dc
      ea = 85.61e9_dp*dc*dc - 3.927e7_dp*dc**3
      dvol = 1.801_dp*dc
      density = mass/(0.25_dp*pi*dvol*dvol)
      w = (mass - 1025*0.25_dp*pi*dvol*dvol)*g
      call grounded_catenary(length, span, drop, w, ea, [50000.0_dp, 160.0_dp], hh, lb, cb=1.0_dp)
      tf = hypot(hh, w*(length - lb))
      write (line, '(a,es22.15,a,es22.15,a)') "&cable length = 250, diameter = ", dvol, ", density = ", density, &
         ", bending_stiffness = 0 /"
      call run_text(path, trim(line)//new_line('a')// &
                    "&material law = 'linear', ea = "//str(ea)//" /"//new_line('a')// &
                    "&fluid density = 1025, surface_z = 0 /"//new_line('a')// &
                    "&seabed depth = 60, mu_axial = 1, static_friction = 'end_a' /"//new_line('a')// &
                    "&end_a kind = 'fixed', x = 0, z = -60 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 230, z = -10 /"//new_line('a')// &
                    "&rupture enabled = .false. /"//new_line('a')// &
                    "&numerics nodes = 401, dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12 /"//new_line('a')// &
                    "&output interval = 0, quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      err = abs(obs%tension(2) - tf)/tf
      write (output_unit, '(4x,a,2f14.3,a,es9.2)') 'chain, mu 1: fairlead tension, closed form', obs%tension(2), tf, &
         '; relative difference', err
      call check(error, err < 5.0e-5_dp, 'the chain with full static friction is off the closed form: '//str(err))
   end subroutine test_chain_friction

   !> The catenary of test_catenary on 101 nodes with its fairlead at 30 degrees in the
   !> horizontal plane, run by the 3-D model: the end tensions and the grounded length are the
   !> planar run's.
   subroutine test_catenary_3d(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: common = "&cable length = 100, diameter = 0.1, density = 2000, "// &
                                              "bending_stiffness = 1e-3 /"//new_line('a')// &
                                              "&material law = 'linear', ea = 1e8 /"//new_line('a')// &
                                              "&fluid density = 1025, surface_z = 10 /"//new_line('a')// &
                                              "&seabed depth = 40, stiffness = 1e10 /"//new_line('a')// &
                                              "&end_a kind = 'fixed', x = 0, z = -40 /"//new_line('a')// &
                                              "&rupture enabled = .false. /"//new_line('a')// &
                                              "&output interval = 0, quiet = .true. /"//new_line('a')
      type(simulation) :: sim2, sim3
      type(static_keeper) :: obs2, obs3
      real(dp) :: diff(3)
      call run_text(path, common//"&end_b kind = 'fixed', x = 80, z = 0 /"//new_line('a')// &
                    "&numerics nodes = 101, dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12 /", sim2, obs2, error)
      if (allocated(error)) return
      call run_text(path, common//"&end_b kind = 'fixed', x = 69.28203230275509, y = 40, z = 0 /"//new_line('a')// &
                    "&numerics model = '3d', nodes = 101, dt = 1e-3, t_end = 1e-3, newton_tol = 1e-12 /", &
                    sim3, obs3, error)
      if (allocated(error)) return
      diff = [abs(obs3%tension - obs2%tension)/obs2%tension, &
              abs(sim3%rod%history%measures(1, 0) - sim2%rod%history%measures(1, 0))/sim2%rod%history%measures(1, 0)]
      write (output_unit, '(4x,a,3es9.2)') 'catenary on the bottom at 30 degrees, 3-D against 2-D: end tensions and '// &
         'grounded length differ by', diff
      call check(error, maxval(diff) < 1.0e-10_dp, 'the 3-D catenary on the bottom differs from the planar one by '// &
                 str(maxval(diff)))
   end subroutine test_catenary_3d

   !> The OC3-Hywind mooring (Jonkman 2010, NREL/TP-500-47535, Table 5-1): three chain lines of
   !> 902.2 m, 698.094 N/m in water, EA 384.243 MN, from anchors on a flat bottom 320 m down at a
   !> radius of 853.87 m to fairleads 70 m down at a radius of 5.2 m, 120 degrees apart. The
   !> report gives the system's linearised stiffness at the undisplaced platform (its Eq. 5-3),
   !> among it surge K11 = 41,180 N/m and heave K33 = 11,940 N/m. With H and V the horizontal and
   !> vertical force at a fairlead, X its horizontal and h its vertical distance from the anchor,
   !> three lines 120 degrees apart give
   !>   K11 = 3/2 (dH/dX + H/X),   K33 = 3 dV/dh
   !> (the second term of K11: the lines across the motion turn). One line in the x-z plane, run at
   !> (X, h) and 1 and 2 m either side in each, gives the derivatives by central differences over
   !> 1 and 2 m, extrapolated to 0 (Richardson: (4 D(1) - D(2))/3; over 1 m alone dH/dX is off by
   !> 18 N/m, as the closed form shows). Frictionless bottom, stiff (the grounded part sinks
   !> 8e-7 m), 401, 801 and 1601 nodes; against the table (four digits: within 5 N/m) and the
   !> grounded catenary's closed form (the same differences).
   subroutine test_oc3_hywind(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: length = 902.2_dp, ea = 384.243e6_dp, span = 853.87_dp - 5.2_dp, drop = 250
      real(dp), parameter :: published(2) = [41180.0_dp, 11940.0_dp], weight = 698.094_dp, gravity = 9.80665_dp
      integer, parameter :: resolutions(3) = [401, 801, 1601]
      real(dp), parameter :: dx(9) = [0, 1, -1, 2, -2, 0, 0, 0, 0], dz(9) = [0, 0, 0, 0, 0, 1, -1, 2, -2]
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: hv(2, 9), cf(2, 9), k(2, size(resolutions)), kcf(2), hh, lb, off(2, size(resolutions)), change(2)
      character(len=24) :: density
      integer :: i, j
      ! The mass per volume that gives the table's weight in water exactly (12214.7 kg/m^3; the
      ! table's 77.7066 kg/m gives 698.0946 N/m).
      write (density, '(es24.16)') 1025 + weight/(gravity*0.25_dp*pi*0.09_dp**2)
      do j = 1, size(dx)
         call grounded_catenary(length, span + dx(j), drop + dz(j), weight, ea, [7.4e5_dp, 135.0_dp], hh, lb)
         cf(:, j) = [hh, weight*(length - lb)]
      end do
      kcf = stiffness(cf)
      do i = 1, size(resolutions)
         do j = 1, size(dx)
            call run_text(path, "&cable length = 902.2, diameter = 0.09, density = "//trim(adjustl(density))// &
                          ", gravity = 9.80665, bending_stiffness = 1 /"//new_line('a')// &
                          "&material law = 'linear', ea = 384.243e6, compression = 'none' /"//new_line('a')// &
                          "&fluid density = 1025 /"//new_line('a')// &
                          "&seabed depth = 320, stiffness = 1e10 /"//new_line('a')// &
                          "&end_a kind = 'fixed', x = 0, z = -320 /"//new_line('a')// &
                          "&end_b kind = 'fixed', x = "//str(span + dx(j))//", z = "//str(drop + dz(j) - 320)//" /"// &
                          new_line('a')//"&rupture enabled = .false. /"//new_line('a')// &
                          "&numerics nodes = "//str(resolutions(i))//", dt = 1e-3, t_end = 1e-3 /"//new_line('a')// &
                          "&output interval = 0, quiet = .true. /", sim, obs, error)
            if (allocated(error)) return
            ! The support's force on end b (the fairlead): H along +x, V up.
            hv(:, j) = sim%rod%history%ends(6:7, 2, 0)
         end do
         k(:, i) = stiffness(hv)
         off(:, i) = k(:, i) - kcf
         write (output_unit, '(4x,a,i5,a,2f12.2,a,2f10.2,a,2f7.2,a,2f7.2,a)') 'OC3-Hywind mooring,', resolutions(i), &
            ' nodes: fairlead H, V', hv(:, 1), ' N; K11, K33', k(:, i), ' N/m; off the closed form by', off(:, i), &
            ' N/m, off the table by', k(:, i) - published, ' N/m'
      end do
      ! (Beyond 401 nodes the place of the touchdown between two nodes dominates what is left: the
      ! differences do not shrink at an order, so the change is reported.)
      change = k(:, 3) - k(:, 2)
      write (output_unit, '(4x,a,2f10.2,a,2f12.2,a,2f7.2,a)') 'OC3-Hywind mooring: K11, K33 of the closed form', kcf, &
         ' N/m, its fairlead H, V', cf(:, 1), ' N; K11, K33 change by', change, ' N/m from 801 to 1601 nodes'
      ! The table's last digit is 10 N/m: its rounding alone allows 5.
      call check(error, all(abs(k(:, size(resolutions)) - published) < 5), 'the OC3-Hywind mooring stiffness is off '// &
                 'the published K11 = 41180 N/m, K33 = 11940 N/m: '//str(k(1, size(resolutions)))//', '// &
                 str(k(2, size(resolutions)))//' N/m')
      if (allocated(error)) return
      call check(error, all(abs(off(:, size(resolutions))) < 1.0_dp), 'the OC3-Hywind mooring stiffness is off its '// &
                 'closed form by '//str(off(1, size(resolutions)))//', '//str(off(2, size(resolutions)))//' N/m')

   contains

      !> K11 and K33 of three lines from the fairlead forces (2, 9) at the nine positions.
      function stiffness(f) result(kk)
         real(dp), intent(in) :: f(:, :)
         real(dp) :: kk(2), near(2), far(2)
         near = [(f(1, 2) - f(1, 3))/2, (f(2, 6) - f(2, 7))/2]
         far = [(f(1, 4) - f(1, 5))/4, (f(2, 8) - f(2, 9))/4]
         kk = [1.5_dp, 3.0_dp]*(4*near - far)/3 + [1.5_dp*f(1, 1)/span, 0.0_dp]
      end function stiffness
   end subroutine test_oc3_hywind

   !> The touchdown of a static shape on a flat bottom drop below z = 0: the square root of the
   !> height of the first two nodes more than 1e-6 m off the bottom is linear in the arc length
   !> (z = (s - s_t)^2 / (2 R) near it), extrapolated to 0; first, the first of those nodes.
   subroutine touchdown(obs, drop, touch, first)
      type(static_keeper), intent(in) :: obs
      real(dp), intent(in) :: drop
      real(dp), intent(out) :: touch
      integer, intent(out), optional :: first
      integer :: k
      real(dp) :: z1, z2
      do k = 2, size(obs%z) - 1
         if (obs%z(k) + drop > 1.0e-6_dp) exit
      end do
      z1 = sqrt(obs%z(k) + drop)
      z2 = sqrt(obs%z(k + 1) + drop)
      touch = obs%s(k) - z1*(obs%s(k + 1) - obs%s(k))/(z2 - z1)
      if (present(first)) first = k
   end subroutine touchdown

   !> The elastic catenary resting partly on a flat frictionless bottom, its anchor on the bottom
   !> and its other end span away and drop above (solved by Newton from a guess of H and L_b):
   !> with H the horizontal tension, L_b the grounded length, L_s = L - L_b and V = w L_s,
   !>   X = L_b (1 + H/EA) + (H/w) asinh(V/H) + H L_s/EA,
   !>   Z = (H/w) (sqrt(1 + (V/H)^2) - 1) + w L_s^2/(2 EA);
   !> anchor tension H, the other end's forces H and V. With a Coulomb friction coefficient cb
   !> along the bottom, fully mobilised towards the anchor (the classic closed form of a line laid
   !> from its anchor and pulled taut: Jonkman 2007, NREL/TP-500-41958, and MAP), the grounded
   !> tension falls from H at the touchdown by cb w per metre, to T_a = max(H - cb w L_b, 0) at the
   !> anchor, and the grounded stretch L_b H / EA becomes (L_b H - cb w L_b^2 / 2) / EA, or
   !> H^2 / (2 cb w EA) where the tension reaches zero before the anchor.
   subroutine grounded_catenary(length, span, drop, w, ea, guess, hh, lb, cb)
      real(dp), intent(in) :: length, span, drop, w, ea, guess(2)
      real(dp), intent(out) :: hh, lb
      !> Friction coefficient along the bottom (default 0).
      real(dp), intent(in), optional :: cb
      real(dp) :: v(2), r(2), jac(2, 2), dv(2), rp(2), rm(2), det
      integer :: it, j
      v = guess
      do it = 1, 60
         r = residual(v)
         do j = 1, 2
            dv = 0
            dv(j) = 1.0e-6_dp*max(1.0_dp, abs(v(j)))
            rp = residual(v + dv)
            rm = residual(v - dv)
            jac(:, j) = (rp - rm)/(2*dv(j))
         end do
         det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
         v = v - [jac(2, 2)*r(1) - jac(1, 2)*r(2), -jac(2, 1)*r(1) + jac(1, 1)*r(2)]/det
      end do
      hh = v(1)
      lb = v(2)

   contains

      function residual(v) result(r)
         real(dp), intent(in) :: v(2)
         real(dp) :: r(2), ls, vv
         ls = length - v(2)
         vv = w*ls
         r(1) = v(2)*(1 + v(1)/ea) + v(1)/w*asinh(vv/v(1)) + v(1)*ls/ea - span
         if (present(cb)) then
            if (v(1) >= cb*w*v(2)) then
               r(1) = v(2) + (v(2)*v(1) - cb*w*v(2)**2/2)/ea + v(1)/w*asinh(vv/v(1)) + v(1)*ls/ea - span
            else
               r(1) = v(2) + v(1)**2/(2*cb*w*ea) + v(1)/w*asinh(vv/v(1)) + v(1)*ls/ea - span
            end if
         end if
         r(2) = v(1)/w*(sqrt(1 + (vv/v(1))**2) - 1) + w*ls**2/(2*ea) - drop
      end function residual
   end subroutine grounded_catenary

   !> A 30 m line held at one end 2 m above a bottom sloping along x, its other end free,
   !> released from a straight horizontal state so that it falls onto the bottom and slides;
   !> no fluid drag. The energy ledger closes to the Newton tolerance without friction and with
   !> it, and friction's work is negative and grows (it only takes energy).
   subroutine test_ledger(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: mu(2) = ['0.0', '0.6']
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: drift(2), work(2), grounded(2)
      integer :: i, n
      do i = 1, 2
         call run_text(path, "&cable length = 30, diameter = 0.05, density = 2000, bending_stiffness = 10 /"// &
                       new_line('a')//"&material law = 'linear', ea = 1e6 /"//new_line('a')// &
                       "&seabed depth = 2, slope_x = -0.05, stiffness = 1e7, mu_axial = "//mu(i)// &
                       ", mu_lateral = "//mu(i)//" /"//new_line('a')// &
                       "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                       "&end_b kind = 'force', force_x = 2000, force_z = 0, history = 'ramp', ramp_time = 0.2 /"// &
                       new_line('a')//"&rupture enabled = .false. /"//new_line('a')// &
                       "&numerics nodes = 61, dt = 0.002, t_end = 2, newton_tol = 1e-12 /"//new_line('a')// &
                       "&output interval = 0, quiet = .true., energy = .true. /", sim, obs, error)
         if (allocated(error)) return
         associate (hist => sim%rod%history)
            n = hist%n
            drift(i) = maxval(abs(hist%energy(7, 0:n) - hist%energy(7, 0)))/maxval(abs(hist%energy(1:6, 0:n)))
            work(i) = hist%energy(8, n)
            grounded(i) = hist%measures(1, n)
         end associate
         write (output_unit, '(4x,a,a,a,es9.2,a,f10.3,a,f7.3,a)') 'line dropped on the bottom, mu ', mu(i), &
            ': ledger drift', drift(i), ' of the largest term; the bottom''s work', work(i), ' J; grounded', &
            grounded(i), ' m at the end'
      end do
      call check(error, maxval(drift) < 1.0e-12_dp, 'the ledger of the dropped line drifts by '//str(maxval(drift)))
      if (allocated(error)) return
      call check(error, minval(grounded) > 5, 'the line did not reach the bottom')
      if (allocated(error)) return
      call check(error, work(2) < work(1), 'friction did not take energy: '//str(work(1))//', '//str(work(2))//' J')
   end subroutine test_ledger
   !> A 30 m line (d 0.05 m, 2000 kg/m^3, in air) lying on a flat bottom 10 m down, end a held on
   !> the bottom, end b pulled along it by 10 N; end a is then towed along -x at 0.2 m/s (a
   !> smooth start over 2 s), mu_axial 0.5. Sliding steadily, each metre of line takes the
   !> regularised Coulomb friction mu w g(v), g(v) = v / sqrt(v^2 + v_s^2): the tension grows
   !> along the line at that rate, and the force on end a is 10 N plus mu g(v) times the weight
   !> the bottom carries, w L less what the support at end a carries (its vertical reaction:
   !> the held end sits on the bottom's surface, the rest of the line sinks w/k into it). Means
   !> over 6-12 s, with v_s = 0.1 and 0.01 m/s. (compression = 'law': the static line lies flat
   !> under 10 N, and a guess through the bottom, lifted, would start slack.)
   subroutine test_towed(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: slips(2) = ['0.1 ', '0.01']
      real(dp), parameter :: v = 0.2_dp, mu = 0.5_dp
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: rows(31), xs(31), w, vs, gv, fx, fz, expected, worst_force, worst_rate, rate
      character(len=8) :: word
      integer :: i, k, n, m
      rows(1:21) = [(0.1_dp*k, k=0, 20)]
      rows(22:31) = [(real(k, dp), k=3, 12)]
      where (rows < 2)
         xs = -v*(0.5_dp*rows - 1/pi*sin(pi*rows/2))
      elsewhere
         xs = -v*(rows - 1)
      end where
      w = 2000*0.25_dp*pi*0.05_dp**2*g
      worst_force = 0
      worst_rate = 0
      do i = 1, 2
         word = slips(i)
         read (word, *) vs
         gv = v/sqrt(v*v + vs*vs)
         call run_text(path, "&cable length = 30, diameter = 0.05, density = 2000 /"//new_line('a')// &
                       "&material law = 'linear', ea = 1e6, compression = 'law' /"//new_line('a')// &
                       "&seabed depth = 10, mu_axial = 0.5, slip_velocity = "//trim(slips(i))//" /"//new_line('a')// &
                       "&end_a kind = 'motion', x = 0, z = -10, motion = 'table',"//new_line('a')// &
                       column_text('table_time', rows)//new_line('a')//column_text('table_x', xs)//new_line('a')// &
                       column_text('table_z', 0*rows)//" /"//new_line('a')// &
                       "&end_b kind = 'force', force_x = 10, force_z = 0 /"//new_line('a')// &
                       "&rupture enabled = .false. /"//new_line('a')// &
                       "&numerics nodes = 61, dt = 0.01, t_end = 12 /"//new_line('a')// &
                       "&output interval = 0, quiet = .true. /", sim, obs, error)
         if (allocated(error)) return
         associate (hist => sim%rod%history)
            n = hist%n
            fx = 0
            fz = 0
            m = 0
            do k = 0, n
               if (hist%time(k) < 6) cycle
               fx = fx - hist%ends(6, 1, k)
               fz = fz + hist%ends(7, 1, k)
               m = m + 1
            end do
            fx = fx/m
            fz = fz/m
         end associate
         ! The tension's growth along the line at the end, between the cells 10 from either end.
         associate (r => sim%rod%pieces(1)%r, piece => sim%rod%pieces(1)%problem%piece)
            rate = (piece%law%tension(norm2(r(:, 51) - r(:, 50))/piece%ds(50) - 1) - &
                    piece%law%tension(norm2(r(:, 11) - r(:, 10))/piece%ds(10) - 1))/(piece%s(50) - piece%s(10))
         end associate
         expected = 10 + mu*gv*(w*30 - fz)
         worst_force = max(worst_force, abs(fx - expected)/expected)
         worst_rate = max(worst_rate, abs(abs(rate) - mu*w*gv)/(mu*w*gv))
         write (output_unit, '(4x,a,a,a,f9.3,a,f9.3,a,f6.3,a,f8.4,a,f8.4,a)') 'towed along the bottom, slip_velocity ', &
            trim(slips(i)), ': force on end a', fx, ' N, expected', expected, ' N (the support carries', fz, &
            ' N); tension growth', abs(rate), ' N/m, expected', mu*w*gv, ' N/m'
      end do
      write (output_unit, '(4x,a,2es9.2)') 'towed along the bottom: relative errors of the force and the growth', &
         worst_force, worst_rate
      ! (With v_s = 0.01 m/s the steep friction law makes the line ring along itself, +-15 N at
      ! end a: the growth taken from one state, the last, is off by 9e-4 there, 5e-5 at 0.1 m/s.)
      call check(error, worst_force < 5.0e-5_dp .and. worst_rate < 3.0e-3_dp, 'the towed line''s friction is off: '// &
                 str(worst_force)//' (force), '//str(worst_rate)//' (growth along the line)')
   end subroutine test_towed
   !> A chain mooring (input/chain_mooring_heave.nml's) with its fairlead moved in, from 230 m
   !> to 200 m: 250 m of line against a way of 246.04 m from the anchor along the bottom and up
   !> to the fairlead. It cannot be taut, a slack line on a frictionless bottom has no single
   !> static state, and the statics' error says so, with both lengths. At 230 m (the case) no
   !> such note: the statics are found. Between the two, a collapsed state is refused, with why.
   subroutine test_too_long(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(static_keeper) :: keep
      type(error_type), allocatable :: failed
      character(len=*), parameter :: nl = new_line('a')
      character(len=*), parameter :: common = &
         "&cable length = 250.0, diameter = 0.13688, density = 7850.0, bending_stiffness = 1.0 /"//nl// &
         "&material law = 'linear', ea = 4.9446e8, compression = 'none' /"//nl// &
         "&fluid density = 1025.0 /"//nl//"&seabed depth = 60.0, slope_x = 0.02 /"//nl// &
         "&end_a kind = 'fixed', x = 0.0, z = -60.0 /"//nl//"&rupture enabled = .false. /"//nl// &
         "&numerics nodes = 101, t_end = 0.01 /"//nl//"&output interval = 0, quiet = .true. /"//nl
      call run_text(path, common//"&end_b kind = 'fixed', x = 200.0, z = -10.0 /", sim, keep, failed)
      call check(error, allocated(failed), 'a line too long to be taut over the bottom: statics found')
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'fairlead at 200 m: '//failed%message(max(1, index(failed%message, '; the line')):)
      call check(error, index(failed%message, 'the line (250 m) is at least as long as the way down from end a') > 0 &
                 .and. index(failed%message, '(246.04 m): it cannot be taut') > 0, &
                 'the error does not say the line is too long: '//failed%message)
      if (allocated(error)) return
      ! At 210 m the line is short enough to be taut but nearly slack at the anchor (the rope
      ! that can push carries -1.9 kN there): Newton reaches an equilibrium with a cell heaped
      ! to 0.18 % of its length, which the dynamics refuses at its first step; the statics
      ! refuse it too, and say so.
      call run_text(path, common//"&end_b kind = 'fixed', x = 210.0, z = -10.0 /", sim, keep, failed)
      call check(error, allocated(failed), 'a nearly slack line: statics found')
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'fairlead at 210 m: '//failed%message(max(1, index(failed%message, 'statics:')):)
      call check(error, index(failed%message, 'too little tension to be taut: with its law continued below zero '// &
                              'strain it would push 1905') > 0, 'the error does not say the rope is slack: '//failed%message)
      if (allocated(error)) return
      call run_text(path, common//"&end_b kind = 'fixed', x = 230.0, z = -10.0 /", sim, keep, failed)
      call check(error, .not. allocated(failed), 'the case itself fails')
   end subroutine test_too_long

   !> A line nearly slack on a flat, frictionless bottom: the chain of test_chain_friction (250 m,
   !> rope that cannot push), its anchor on a stiff bottom (1e10 Pa) 60 m down, its fairlead 10 m
   !> under the surface and 205 m away (the way down, along the bottom and up: 255 m), 801
   !> nodes. Before the pay-in (pay_in of model/rod_statics.f90) no statics: Newton from the
   !> catenary guess diverged and the relaxation ran out of steps. The grounded part is straight and
   !> taut: the anchor's tension is the horizontal tension at the touchdown, against the elastic
   !> catenary with a grounded part (grounded_catenary): H 1535.81 N, fairlead 50 826.21 N.
   !> Measured: anchor 9.9e-4, fairlead 6.5e-5 (the touchdown's kink at a node, first order).
   !> Also the 101-node chain 202 m out (H 446 N: its touchdown bend, radius H / w = 0.45 m, is a
   !> fifth of a cell), which failed too: found, taut on the bottom, its horizontal force the same
   !> at both ends.
   subroutine test_paid_in(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: dc = 0.076_dp, length = 250, span = 205, drop = 50
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: mass, ea, dvol, w, density, hh, lb, tf, errs(2)
      character(len=200) :: line
      character(len=:), allocatable :: common
      mass = 20.01e3_dp*dc*dc
      ea = 85.61e9_dp*dc*dc - 3.927e7_dp*dc**3
      dvol = 1.801_dp*dc
      density = mass/(0.25_dp*pi*dvol*dvol)
      w = (mass - 1025*0.25_dp*pi*dvol*dvol)*g
      call grounded_catenary(length, span, drop, w, ea, [1500.0_dp, 198.0_dp], hh, lb)
      tf = hypot(hh, w*(length - lb))
      write (line, '(a,es22.15,a,es22.15,a)') "&cable length = 250, diameter = ", dvol, ", density = ", density, &
         ", bending_stiffness = 1 /"
      common = trim(line)//new_line('a')// &
               "&material law = 'linear', ea = "//str(ea)//", compression = 'none' /"//new_line('a')// &
               "&fluid density = 1025, surface_z = 0 /"//new_line('a')// &
               "&end_a kind = 'fixed', x = 0, z = -60 /"//new_line('a')// &
               "&rupture enabled = .false. /"//new_line('a')// &
               "&output interval = 0, quiet = .true. /"//new_line('a')
      call run_text(path, common//"&seabed depth = 60, stiffness = 1e10 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 205, z = -10 /"//new_line('a')// &
                    "&numerics nodes = 801, dt = 1e-3, t_end = 1e-3 /", sim, obs, error)
      if (allocated(error)) return
      errs = [abs(obs%tension(1) - hh)/hh, abs(obs%tension(2) - tf)/tf]
      write (output_unit, '(4x,a,2f12.3,a,2f12.3,a,2es9.2)') 'nearly slack chain, 801 nodes: anchor, fairlead', &
         obs%tension, ' N; closed form', hh, tf, ' N; relative errors', errs
      call check(error, errs(1) < 3.0e-3_dp .and. errs(2) < 3.0e-4_dp, 'the nearly slack chain is off its closed '// &
                 'form: anchor '//str(errs(1))//', fairlead '//str(errs(2)))
      if (allocated(error)) return
      call run_text(path, common//"&seabed depth = 60 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 202, z = -10 /"//new_line('a')// &
                    "&numerics nodes = 101, dt = 1e-3, t_end = 1e-3 /", sim, obs, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,2f12.3,a)') 'nearly slack chain, 202 m, 101 nodes: anchor, fairlead', obs%tension, ' N'
      call check(error, obs%tension(1) > 0 .and. obs%tension(2) > obs%tension(1), 'the nearly slack chain at 202 m '// &
                 'is not taut on the bottom')
   end subroutine test_paid_in

   !> Scenes with no single static state, refused with why. (1) The chain of test_too_long 205 m
   !> out on its bottom rising 2 % towards the fairlead: the grounded line's weight up the slope
   !> (986 N/m over 4 m of rise) exceeds the tension at the touchdown, the rope that can push
   !> would push 3.9 kN at the anchor, so the rope that cannot is slack there, heaped. (2) A
   !> 60 m line hanging from a point 40 m over a flat, frictionless bottom with its end b free,
   !> with either compression: nothing pulls it sideways, 20 m lie on the bottom with no tension
   !> (the rope that can push gave a column standing 10 m into the bottom, at -17 MN). (3) The
   !> same with end b held on the bottom 21 m out (way 61 m): found (it failed before), taut. A line
   !> of two segments with its end b free is refused as (2).
   subroutine test_slack_refused(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(static_keeper) :: keep
      type(error_type), allocatable :: failed
      character(len=*), parameter :: nl = new_line('a')
      character(len=*), parameter :: chain = &
         "&cable length = 250.0, diameter = 0.13688, density = 7850.0, bending_stiffness = 1.0 /"//nl// &
         "&material law = 'linear', ea = 4.9446e8, compression = 'none' /"//nl// &
         "&fluid density = 1025.0 /"//nl//"&seabed depth = 60.0, slope_x = 0.02 /"//nl// &
         "&end_a kind = 'fixed', x = 0.0, z = -60.0 /"//nl//"&rupture enabled = .false. /"//nl// &
         "&numerics nodes = 101, t_end = 0.01 /"//nl//"&output interval = 0, quiet = .true. /"//nl// &
         "&end_b kind = 'fixed', x = 205.0, z = -10.0 /"
      character(len=*), parameter :: line = &
         "&cable length = 60, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /"//nl// &
         "&fluid density = 1025, surface_z = 10 /"//nl//"&seabed depth = 40 /"//nl// &
         "&end_a kind = 'fixed', x = 0, z = 0 /"//nl//"&rupture enabled = .false. /"//nl// &
         "&numerics nodes = 61, dt = 1e-3, t_end = 1e-3 /"//nl//"&output interval = 0, quiet = .true. /"//nl
      character(len=*), parameter :: laws(2) = ['none', 'law ']
      integer :: i
      call run_text(path, chain, sim, keep, failed)
      call check(error, allocated(failed), 'a rope slack on a rising bottom: statics found')
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'slack on a rising bottom: '//failed%message(max(1, index(failed%message, 'statics:')):)
      call check(error, index(failed%message, 'too little tension to be taut: with its law continued below zero '// &
                              'strain it would push 3923') > 0 .and. index(failed%message, 'relaxation') == 0, &
                 'the error does not say the rope is slack on the bottom: '//failed%message)
      if (allocated(error)) return
      do i = 1, 2
         call run_text(path, line//"&material law = 'linear', ea = 1e8, compression = '"//trim(laws(i))//"' /"//nl// &
                       "&end_b kind = 'free' /", sim, keep, failed)
         call check(error, allocated(failed), 'a free end on a frictionless bottom: statics found')
         if (allocated(error)) return
         if (i == 1) write (output_unit, '(4x,a)') 'free end on the bottom: '// &
            failed%message(max(1, index(failed%message, 'statics:')):)
         call check(error, index(failed%message, 'end b is free of horizontal force') > 0 .and. &
                    index(failed%message, 'about 20 m of it lies on the bottom with no tension') > 0, &
                    'the error does not say the free end lies slack: '//failed%message)
         if (allocated(error)) return
      end do
      ! The same with a line of two segments (a heavier first 20 m).
      call run_text(path, line//"&material law = 'linear', ea = 1e8, compression = 'none' /"//nl// &
                    "&segment_1 length = 20, diameter = 0.12, density = 7800 /"//nl//"&segment_2 length = 40 /"//nl// &
                    "&end_b kind = 'free' /", sim, keep, failed)
      call check(error, allocated(failed), 'a free end of segments on a frictionless bottom: statics found')
      if (allocated(error)) return
      call check(error, index(failed%message, 'end b is free of horizontal force') > 0, &
                 'the error does not say the free end of segments lies slack: '//failed%message)
      if (allocated(error)) return
      call run_text(path, line//"&material law = 'linear', ea = 1e8, compression = 'none' /"//nl// &
                    "&end_b kind = 'fixed', x = 21, z = -40 /", sim, keep, failed)
      call check(error, .not. allocated(failed), 'the end held on the bottom: no statics')
      if (allocated(error)) return
      write (output_unit, '(4x,a,2f12.3,a)') 'end held on the bottom 21 m out: tensions', keep%tension, ' N'
      call check(error, keep%tension(2) > 0, 'the end held on the bottom: the line is not taut')
   end subroutine test_slack_refused

   !> A loose end resting on the bottom under a pull along it (lay_down of model/rod_statics.f90):
   !> the 60 m line of test_slack_refused (rope that cannot push, EI 1e-3 N m^2) hanging from a
   !> point 40 m over a flat, stiff bottom (1e10 Pa), its end b pulled along the bottom by 50 N,
   !> 481 nodes; before, no statics. The grounded part carries the 50 N; the top's tension against
   !> the elastic catenary whose tangent is horizontal at the bottom, H = 50 N: Z = (H/w)(sqrt(1 +
   !> (w L_s/H)^2) - 1) + w L_s^2/(2 EA), T = sqrt(H^2 + (w L_s)^2) = 3054.808 N. Measured 2.0e-6
   !> (4.9e-5 at 241 nodes). And the free end on a bottom rising 10 % along x: the line lies
   !> downhill (towards -x), taut from its free end, found (before, no statics), and so does a
   !> line of two segments, and the rope that can push on a bottom rising 2 % (before, a column in
   !> the bottom).
   subroutine test_laid(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(static_keeper) :: keep
      character(len=*), parameter :: nl = new_line('a')
      character(len=*), parameter :: line = &
         "&cable length = 60, diameter = 0.1, density = 2000, bending_stiffness = 1e-3 /"//nl// &
         "&material law = 'linear', ea = 1e8, compression = 'none' /"//nl// &
         "&fluid density = 1025, surface_z = 10 /"//nl// &
         "&end_a kind = 'fixed', x = 0, z = 0 /"//nl//"&rupture enabled = .false. /"//nl// &
         "&output interval = 0, quiet = .true. /"//nl
      real(dp), parameter :: hh = 50, drop = 40, ea = 1.0e8_dp
      real(dp) :: w, ls, lo, hi, top, err
      integer :: it
      w = (2000 - 1025)*0.25_dp*pi*0.1_dp**2*g
      ! The suspended length by bisection on the height.
      lo = drop
      hi = 2*drop
      do it = 1, 200
         ls = 0.5_dp*(lo + hi)
         if ((hh/w)*(sqrt(1 + (w*ls/hh)**2) - 1) + w*ls**2/(2*ea) > drop) then
            hi = ls
         else
            lo = ls
         end if
      end do
      top = hypot(hh, w*ls)
      call run_text(path, line//"&seabed depth = 40, stiffness = 1e10 /"//nl// &
                    "&end_b kind = 'force', force_x = 50 /"//nl// &
                    "&numerics nodes = 481, dt = 1e-3, t_end = 1e-3 /", sim, keep, error)
      if (allocated(error)) return
      err = abs(keep%tension(1) - top)/top
      write (output_unit, '(4x,a,2f12.4,a,f12.4,a,es9.2)') 'end pulled along the bottom by 50 N: tensions', &
         keep%tension, ' N; closed form at the top', top, ' N; relative error', err
      call check(error, err < 1.0e-5_dp .and. abs(keep%tension(2) - hh) < 1.0e-6_dp*hh, 'the line laid on the '// &
                 'bottom is off its closed form: top '//str(err)//', end '//str(keep%tension(2)))
      if (allocated(error)) return
      call run_text(path, line//"&seabed depth = 40, slope_x = 0.1 /"//nl//"&end_b kind = 'free' /"//nl// &
                    "&numerics nodes = 61, dt = 1e-3, t_end = 1e-3 /", sim, keep, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,2f12.4,a,f9.3,a)') 'free end on a bottom rising 10 %: tensions', keep%tension, &
         ' N, the free end at x =', keep%x(size(keep%x)), ' m'
      call check(error, keep%x(size(keep%x)) < -10 .and. keep%tension(1) > 0, 'the free end does not lie downhill: '// &
                 str(keep%x(size(keep%x))))
      if (allocated(error)) return
      ! The same with a line of two segments (a heavier first 20 m).
      call run_text(path, line//"&segment_1 length = 20, diameter = 0.12, density = 7800 /"//nl// &
                    "&segment_2 length = 40 /"//nl//"&seabed depth = 40, slope_x = 0.1 /"//nl// &
                    "&end_b kind = 'free' /"//nl//"&numerics nodes = 61, dt = 1e-3, t_end = 1e-3 /", sim, keep, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,2f12.4,a,f9.3,a)') 'the same, two segments: tensions', keep%tension, &
         ' N, the free end at x =', keep%x(size(keep%x)), ' m'
      call check(error, keep%x(size(keep%x)) < -10 .and. keep%tension(1) > 0, 'the free end of segments does not '// &
                 'lie downhill: '//str(keep%x(size(keep%x))))
      if (allocated(error)) return
      ! The rope that can push on a bottom rising 2 %: before, a column standing 10 m deep in the
      ! bottom at -17 MN (the direct solve's state, now refused by the statics' depth check).
      call run_text(path, line(:index(line, '&material') - 1)//"&material law = 'linear', ea = 1e8, compression = 'law' /"//nl// &
                    line(index(line, '&fluid'):)//"&seabed depth = 40, slope_x = 0.02 /"//nl// &
                    "&end_b kind = 'free' /"//nl//"&numerics nodes = 61, dt = 1e-3, t_end = 1e-3 /", sim, keep, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,2f12.4,a,f9.3,a)') 'the rope that can push on a 2 % slope: tensions', keep%tension, &
         ' N, the free end at x =', keep%x(size(keep%x)), ' m'
      call check(error, keep%x(size(keep%x)) < -10 .and. keep%tension(1) > 0 .and. keep%tension(1) < 3100, &
                 'the rope that can push does not lie downhill: '//str(keep%x(size(keep%x)))//' m, '// &
                 str(keep%tension(1))//' N')
   end subroutine test_laid

   !> The chain of input/chain_mooring_heave.nml (its seabed 60 m down rising 2 % along x,
   !> friction) heaved for 6 s, with the plane given as &seabed depth and slope_x, and as a
   !> bathymetry file of that plane (a 4 x 2 grid: its facets are the plane). The static
   !> tensions agree to the bit, the end tensions over the run to 6.2e-10 of the largest (the
   !> facet's plane is the same plane to round-off, which the stiff contact and the friction
   !> regularised over 0.01 m/s amplify).
   subroutine test_bathymetry_plane(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: plane, grid
      type(static_keeper) :: obs_plane, obs_grid
      real(dp) :: dt_static, dt_run
      integer :: n
      call write_grid('build/test_bathymetry_plane.dat', [-100.0_dp, 0.0_dp, 120.0_dp, 300.0_dp], &
                      [-50.0_dp, 50.0_dp], reshape([62.0_dp, 60.0_dp, 57.6_dp, 54.0_dp, &
                                                    62.0_dp, 60.0_dp, 57.6_dp, 54.0_dp], [4, 2]))
      call run_text(path, chain_text("depth = 60.0, slope_x = 0.02"), plane, obs_plane, error)
      if (allocated(error)) return
      call run_text(path, chain_text("bathymetry_file = 'build/test_bathymetry_plane.dat'"), grid, obs_grid, error)
      if (allocated(error)) return
      n = plane%rod%history%n
      call check(error, grid%rod%history%n == n, 'the runs took different steps')
      if (allocated(error)) return
      dt_static = maxval(abs(obs_grid%tension - obs_plane%tension))/maxval(obs_plane%tension)
      dt_run = maxval(abs(grid%rod%history%ends(5, 1:2, 0:n) - plane%rod%history%ends(5, 1:2, 0:n)))/ &
               maxval(plane%rod%history%ends(5, 1:2, 0:n))
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'the plane as a bathymetry: static tensions', dt_static, &
         ', end tensions over 6 s', dt_run, ' of the largest'
      call check(error, dt_static < 1.0e-12_dp .and. dt_run < 3.0e-9_dp, 'the bathymetry of a plane is not the '// &
                 'plane: '//str(dt_static)//' (statics), '//str(dt_run)//' (run)')
   end subroutine test_bathymetry_plane

   !> The 3-D model: a 33 m line between two anchors on a bottom that slopes across it (along y,
   !> dz/dy = 0.1), lying partly on it, at y = 5 m. As a bathymetry (a 2 x 3 grid) and as
   !> &seabed slope_y: the same static state.
   subroutine test_bathymetry_3d(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: plane, grid
      type(static_keeper) :: obs_plane, obs_grid
      real(dp) :: dx
      character(len=*), parameter :: head = "&cable length = 33, diameter = 0.05, density = 3000, "// &
                                            "bending_stiffness = 10 /"//new_line('a')// &
                                            "&material law = 'linear', ea = 1e6 /"//new_line('a')// &
                                            "&fluid density = 1025, surface_z = 10 /"//new_line('a')
      character(len=*), parameter :: tail = "&end_a kind = 'fixed', x = 0, y = 5, z = -9 /"//new_line('a')// &
                                            "&end_b kind = 'fixed', x = 30, y = 5, z = -4 /"//new_line('a')// &
                                            "&numerics model = '3d', nodes = 81, dt = 1e-3, t_end = 1e-3 /"// &
                                            new_line('a')//"&output interval = 0, quiet = .true. /"
      call write_grid('build/test_bathymetry_3d.dat', [-10.0_dp, 50.0_dp], [-10.0_dp, 0.0_dp, 20.0_dp], &
                      reshape([11.0_dp, 11.0_dp, 10.0_dp, 10.0_dp, 8.0_dp, 8.0_dp], [2, 3]))
      call run_text(path, head//"&seabed depth = 10, slope_y = 0.1, stiffness = 1e8 /"//new_line('a')//tail, plane, &
                    obs_plane, error)
      if (allocated(error)) return
      call run_text(path, head//"&seabed bathymetry_file = 'build/test_bathymetry_3d.dat', stiffness = 1e8 /"// &
                    new_line('a')//tail, grid, obs_grid, error)
      if (allocated(error)) return
      dx = max(maxval(abs(obs_grid%x - obs_plane%x)), maxval(abs(obs_grid%z - obs_plane%z)))
      write (output_unit, '(4x,a,es9.2,a,f7.3,a)') 'a bottom sloping across the line, 3-D: bathymetry against '// &
         'the plane', dx, ' m; grounded', grounded(plane), ' m'
      call check(error, grounded(plane) > 5, 'the line does not lie on the bottom')
      if (allocated(error)) return
      call check(error, dx < 1.0e-9_dp, 'the bathymetry across the line is not the plane: '//str(dx)//' m')
   end subroutine test_bathymetry_3d

   !> A bottom with a bend: flat 20 m down up to x = 15 m, then rising at 1 in 5 (a 2-point grid
   !> in y). A 30 m line held at end a 2 m above the flat, pulled level by 2000 N at end b (the
   !> statics: the slope lifts its far part), then let go (the pull ramped to zero over 0.2 s):
   !> it falls onto the flat and the slope and slides down over the bend, with friction. The
   !> ledger closes, and the step's analytic Jacobian at the end agrees with central
   !> differences (a state whose cells lie on the facets; as in suite registry, the contact's
   !> damping a tenth of the default, its slope jumping where a cell's end touches, and the slip
   !> regularised over 0.5 m/s, wide against the differences' steps).
   subroutine test_bathymetry_bend(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(static_keeper) :: obs
      real(dp) :: drift, worst, lifted
      real(dp), allocatable :: x(:)
      integer :: n, k, np
      call write_grid('build/test_bathymetry_bend.dat', [0.0_dp, 15.0_dp, 60.0_dp], [-10.0_dp, 10.0_dp], &
                      reshape([20.0_dp, 20.0_dp, 11.0_dp, 20.0_dp, 20.0_dp, 11.0_dp], [3, 2]))
      call run_text(path, "&cable length = 30, diameter = 0.05, density = 2000, bending_stiffness = 10 /"// &
                    new_line('a')//"&material law = 'linear', ea = 1e6 /"//new_line('a')// &
                    "&seabed bathymetry_file = 'build/test_bathymetry_bend.dat', stiffness = 1e7, damping = 3e4, "// &
                    "mu_axial = 0.6, mu_lateral = 0.6, slip_velocity = 0.5 /"//new_line('a')// &
                    "&end_a kind = 'fixed', x = 0, z = -18 /"//new_line('a')// &
                    "&end_b kind = 'force', force_x = 2000, force_z = 0, history = 'ramp', ramp_time = 0.2 /"// &
                    new_line('a')//"&numerics nodes = 61, dt = 0.002, t_end = 2, newton_tol = 1e-12 /"// &
                    new_line('a')//"&output interval = 0, quiet = .true., energy = .true. /", sim, obs, error)
      if (allocated(error)) return
      ! At rest the far end lies on the slope, lifted above z = -18.
      lifted = maxval(obs%z) + 18
      associate (hist => sim%rod%history)
         n = hist%n
         drift = maxval(abs(hist%energy(7, 0:n) - hist%energy(7, 0)))/maxval(abs(hist%energy(1:6, 0:n)))
      end associate
      ! The step from the final state, at a perturbed guess.
      associate (run => sim%rod%pieces(1))
         np = size(run%v, 2)
         run%problem%t0 = sim%rod%t
         run%problem%dt = 0.002_dp
         run%problem%theta = 0.5_dp
         call run%problem%piece%prepare_step(run%r, run%v)
         x = reshape(run%r + 0.002_dp*run%v, [2*np])
         do k = 1, size(x)
            x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
         end do
         call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-6_dp, worst, error)
      end associate
      if (allocated(error)) return
      write (output_unit, '(4x,a,f7.3,a,es9.2,a,es9.2,a,f7.3,a)') 'a bottom with a bend: the slope lifts the line by', &
         lifted, ' m at rest; ledger drift', drift, ', Jacobian', worst, ' of the row scale; grounded', &
         grounded(sim), ' m at the end'
      call check(error, lifted > 0.5_dp, 'the slope does not carry the line at rest: '//str(lifted)//' m')
      if (allocated(error)) return
      call check(error, grounded(sim) > 20, 'the line did not fall onto the bottom')
      if (allocated(error)) return
      call check(error, drift < 1.0e-13_dp, 'the ledger drifts by '//str(drift))
   end subroutine test_bathymetry_bend

   !> The grounded length at the end of a run, m.
   real(dp) function grounded(sim)
      type(simulation), intent(in) :: sim
      integer :: k
      grounded = -1
      do k = 1, size(sim%rod%summary%measure_names)
         if (sim%rod%summary%measure_names(k) == 'grounded_length') grounded = sim%rod%history%measures(k, &
                                                                                                  sim%rod%history%n)
      end do
   end function grounded

   !> A bathymetry file that is missing, out of order, short of a row, or given with the
   !> plane's depth; an anchor below the bathymetry: each refused with its reason.
   subroutine test_bathymetry_bad(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(static_keeper) :: obs
      character(len=64) :: files(4)
      character(len=80) :: expect(5)
      integer :: i
      call write_grid('build/test_bathymetry_bad1.dat', [0.0_dp, 15.0_dp, 10.0_dp], [-10.0_dp, 10.0_dp], &
                      reshape([20.0_dp, 20.0_dp, 11.0_dp, 20.0_dp, 20.0_dp, 11.0_dp], [3, 2]))
      call write_grid('build/test_bathymetry_bad2.dat', [0.0_dp, 15.0_dp, 60.0_dp], [-10.0_dp, 10.0_dp], &
                      reshape([20.0_dp, 20.0_dp, 11.0_dp, 20.0_dp, 20.0_dp, 11.0_dp], [3, 2]), short=.true.)
      files = [character(len=64) :: 'build/no_such_bathymetry.dat', 'build/test_bathymetry_bad1.dat', &
               'build/test_bathymetry_bad2.dat', 'build/test_bathymetry_bend.dat']
      expect = [character(len=80) :: 'no such file', 'the x lines must increase strictly', &
                'expected a y line and 3 depths (row 2 of 2)', 'a bathymetry replaces the plane', &
                'the fixed end is below the seabed (z = -20']
      do i = 1, 5
         block
            character(:), allocatable :: seabed
            seabed = "&seabed bathymetry_file = '"//trim(files(min(i, 4)))//"'"
            if (i == 4) seabed = seabed//", depth = 20"
            call run_text(path, "&cable length = 40 /"//new_line('a')//seabed//" /"//new_line('a')// &
                          "&end_a kind = 'fixed', x = 0, z = "//merge('-21', '-19', i == 5)//" /"//new_line('a')// &
                          "&end_b kind = 'fixed', x = 32, z = -2 /"//new_line('a')// &
                          "&output interval = 0, quiet = .true. /", sim, obs, error)
         end block
         if (.not. allocated(error)) then
            call check(error, .false., 'case '//str(i)//' was not refused')
            return
         end if
         write (output_unit, '(4x,a)') trim(error%message)
         if (index(error%message, trim(expect(i))) == 0) then
            error%message = 'case '//str(i)//': not the expected reason "'//trim(expect(i))//'": '//error%message
            return
         end if
         deallocate (error)
      end do
   end subroutine test_bathymetry_bad

   !> The chain of input/chain_mooring_heave.nml with the given &seabed bottom, 6 s of its heave.
   function chain_text(bottom) result(text)
      character(*), intent(in) :: bottom
      character(:), allocatable :: text
      text = "&cable length = 250.0, diameter = 0.13688, density = 7850.0, bending_stiffness = 1.0 /"//new_line('a')// &
             "&material law = 'linear', ea = 4.9446e8, compression = 'none' /"//new_line('a')// &
             "&fluid density = 1025.0, cd_normal = 1.333, cd_tangential = 0.64, ca_normal = 1.0 /"//new_line('a')// &
             "&seabed "//bottom//", mu_axial = 0.7, mu_lateral = 1.0 /"//new_line('a')// &
             "&end_a kind = 'fixed', x = 0.0, z = -60.0 /"//new_line('a')// &
             "&end_b kind = 'motion', x = 230.0, z = -10.0, motion = 'harmonic', amplitude = 3.0, period = 12.0, "// &
             "direction_x = 0.0, direction_z = 1.0, ramp_time = 4.0 /"//new_line('a')// &
             "&numerics nodes = 101, courant = 4.0, t_end = 6.0 /"//new_line('a')// &
             "&output interval = 0, quiet = .true. /"
   end function chain_text

   !> A bathymetry file in MoorDyn's format: x lines gx, y lines gy, depths d(x, y) (m, positive
   !> down); short: the last row left out.
   subroutine write_grid(file, gx, gy, d, short)
      character(*), intent(in) :: file
      real(dp), intent(in) :: gx(:), gy(:), d(:, :)
      logical, intent(in), optional :: short
      integer :: unit, j, rows
      rows = size(gy)
      if (present(short)) then
         if (short) rows = rows - 1
      end if
      open (newunit=unit, file=file, status='replace', action='write')
      write (unit, '(a)') '----- MoorDyn Bathymetry Input File ----'
      write (unit, '(a,i0)') 'nGridX ', size(gx)
      write (unit, '(a,i0)') 'nGridY ', size(gy)
      write (unit, '(8x,*(1x,es24.16))') gx
      do j = 1, rows
         write (unit, '(*(1x,es24.16))') gy(j), d(:, j)
      end do
      close (unit)
   end subroutine write_grid
end module suite_seabed
