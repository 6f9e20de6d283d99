!> The 3-D model through the program's driver (driver/simulation.f90,
!> driver/rod3d_drive.f90), from namelists: &numerics model = '3d' on a
!> planar scene gives the 2-D run's snapshots, history and summary; 'auto'
!> picks 2-D for a planar scene and 3-D otherwise; non-planar scenes (end b
!> off the plane, released; a cross current) run to t_end with a closed
!> energy ledger. The 3-D output (driver/rod3d_fields.f90): a planar scene
!> has no binormal shear or curvature about n, and out of the plane the
!> shear forces and curvatures satisfy the moment balance dM/ds + (1 + eps)
!> t x F = 0 by finite differences of the output; the history keeps the
!> ends' y components.
!> Step control: a planar scene whose steps are rejected
!> rejects the same attempts in 3-D as in 2-D; an off-plane slack release
!> at Courant 10 completes only through rejected steps; without rejections
!> the driver gives the bare stepper's numbers bit for bit.
!> Tables with a y column: a 'table' motion sampled from the harmonic motion
!> across the plane gives the harmonic run to the table's interpolation
!> error, converging as the rows are refined; table_y picks the 3-D model
!> under 'auto', is refused under '2d', and a 4-column table_file reads as
!> t, x, y, z.
!> Statics (issue 15): under a strong cross current the 61-node line that
!> Newton folded now comes out unfolded, its end tensions within a
!> refinement bound of the finer grids'; a static state that cannot be
!> found is refused (stat_numerics, no snapshots); so is a folded planar
!> static state.
module suite_model3d
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_error, only: stat_numerics
   use xcable_core_strings, only: str
   use xcable_io_input, only: read_config
   use xcable_io_config, only: case_config
   use xcable_fixtures, only: pushing_rope, column_text
   use xcable_driver_simulation, only: simulation
   use xcable_driver_stepping, only: start_dynamics
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_ends_end_condition, only: end_condition
   use xcable_ends_factory, only: new_end
   use xcable_solver_banded, only: band_matrix
   use xcable_driver_records, only: run_observer, static_info, run_history, run_summary, n_fields, field_names
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_model3d

   character(len=*), parameter :: path = 'build/test_model3d.nml'

   !> End a fixed, end b loaded by a force and a torque of 5 N m, parted at s = 30 m at t = 0 over
   !> 50 ms; 41 nodes, to 0.2 s (test_break_inside_twisted).
   character(len=*), parameter :: twisted_break = "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
      "&end_b kind = 'force', force_x = 3000, force_z = 1000, torque = 5 /"//new_line('a')// &
      "&rupture s_break = 30, t_break = 0.05 /"//new_line('a')// &
      "&numerics nodes = 41, t_end = 0.2, newton_tol = 1e-10 /"//new_line('a')// &
      "&output interval = 0.01, energy = .true., quiet = .true. /"

   !> Keeps every snapshot, and the extra (3-D) fields when sent.
   type, extends(run_observer) :: keeper
      integer :: n = 0, n_extra = 0
      real(dp), allocatable :: t(:), fields(:, :, :), extra(:, :, :)
      !> The static state's 3-D fields (a 3-D run).
      real(dp), allocatable :: static_extra(:, :)
      !> The static state's fields and end tensions (a, b), N.
      real(dp), allocatable :: static_fields(:, :)
      real(dp) :: static_tension(2) = 0
   contains
      procedure :: static => keeper_static
      procedure :: snapshot => keeper_snapshot
      procedure :: snapshot_extra => keeper_extra
   end type keeper

contains

   subroutine collect_model3d(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('planar_namelist_3d_equals_2d', test_reduction), &
               new_unittest('planar_break_inside_3d_equals_2d', test_reduction_inside), &
               new_unittest('planar_in_water_3d_equals_2d', test_reduction_water), &
               new_unittest('break_inside_out_of_plane', test_break_inside_3d), &
               new_unittest('break_inside_in_water_2d', test_break_inside_water_2d), &
               new_unittest('break_inside_twisted', test_break_inside_twisted), &
               new_unittest('auto_picks_model', test_auto), &
               new_unittest('end_b_off_plane_released', test_off_plane), &
               new_unittest('cross_current', test_cross_current), &
               new_unittest('moment_balance_out_of_plane', test_moment_balance), &
               new_unittest('twisted_frames', test_twisted_frames), &
               new_unittest('rejected_steps_planar_3d_equals_2d', test_rejections_planar), &
               new_unittest('rejected_steps_off_plane_release', test_rejections_off_plane), &
               new_unittest('driver_equals_bare_stepper', test_bare_stepper), &
               new_unittest('collapse_stops_named', test_collapse), &
               new_unittest('wall_clock_and_step_floor', test_limits), &
               new_unittest('table_y_motion_equals_harmonic', test_table_y_motion), &
               new_unittest('table_y_model_and_file', test_table_y_input), &
               new_unittest('statics_strong_cross_current_unfolded', test_statics_strong_current), &
               new_unittest('statics_unsolvable_refused', test_statics_refused), &
               new_unittest('statics_planar_fold_refused', test_statics_planar_fold), &
               new_unittest('chord_off_the_plane_equals_planar_twin', test_turned_twin), &
               new_unittest('spring_and_loaded_ends_off_the_plane_equal_planar_twin', test_turned_state_ends), &
               new_unittest('auto_plane_at_an_azimuth_runs_in_2d', test_auto_turned), &
               new_unittest('damped_dissipation_in_summary', test_dissipated_summary), &
               new_unittest('step_from_the_3d_static_state', test_step_from_static3)]
   end subroutine collect_model3d

   subroutine keeper_static(self, info, error)
      class(keeper), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
      if (allocated(info%extra)) self%static_extra = info%extra
      self%static_fields = info%fields
      self%static_tension = [info%tension_a, info%tension_b]
   end subroutine keeper_static

   subroutine keeper_snapshot(self, t, fields, error)
      class(keeper), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: tt(:), ff(:, :, :)
      if (.not. allocated(self%t)) allocate (self%t(0), self%fields(size(fields, 1), size(fields, 2), 0))
      self%n = self%n + 1
      tt = [self%t, t]
      allocate (ff(size(fields, 1), size(fields, 2), self%n))
      ff(:, :, 1:self%n - 1) = self%fields
      ff(:, :, self%n) = fields
      call move_alloc(tt, self%t)
      call move_alloc(ff, self%fields)
   end subroutine keeper_snapshot

   subroutine keeper_extra(self, t, names, fields, error)
      class(keeper), intent(inout) :: self
      real(dp), intent(in) :: t
      character(*), intent(in) :: names(:)
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: ff(:, :, :)
      if (.not. allocated(self%extra)) allocate (self%extra(size(fields, 1), size(fields, 2), 0))
      self%n_extra = self%n_extra + 1
      allocate (ff(size(fields, 1), size(fields, 2), self%n_extra))
      ff(:, :, 1:self%n_extra - 1) = self%extra
      ff(:, :, self%n_extra) = fields
      call move_alloc(ff, self%extra)
   end subroutine keeper_extra

   !> Write a namelist and run it through the driver.
   subroutine run_case(text, sim, obs, error)
      character(*), intent(in) :: text
      type(simulation), intent(inout) :: sim
      type(keeper), intent(inout) :: obs
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      integer :: unit
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') pushing_rope(text)
      close (unit)
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      call sim%run(obs, error)
   end subroutine run_case

   !> A scene run with model = '2d' and with '3d' (numerics: the rest of &numerics).
   subroutine run_pair(scene, numerics, sim2, obs2, sim3, obs3, error)
      character(*), intent(in) :: scene, numerics
      type(simulation), intent(inout) :: sim2, sim3
      type(keeper), intent(inout) :: obs2, obs3
      type(error_type), allocatable, intent(out) :: error
      call run_case(scene//new_line('a')//"&numerics model = '2d', "//numerics, sim2, obs2, error)
      if (allocated(error)) return
      call run_case(scene//new_line('a')//"&numerics model = '3d', "//numerics, sim3, obs3, error)
   end subroutine run_pair

   !> The paper's fast 315 kN rupture on 41 nodes (to 0.08 s, past the
   !> reflection at end a), Newton to 1e-12, once with model = '2d' and once
   !> with '3d': the snapshot fields, the end history (positions, velocities,
   !> tension, force) and the energy ledger agree to 1e-10 of each quantity's
   !> largest magnitude, except the strain and the velocities (u, the ends'
   !> vx, vz), differences of positions over a cell and a step, which agree
   !> to 5e-10 (near the released end at 167 m/s); y and w stay 0.
   subroutine test_reduction(error)
      type(error_type), allocatable, intent(out) :: error
      call reduction("&static tension = 315000 /"//new_line('a')// &
                     "&rupture t_break = 0.005 /"//new_line('a')// &
                     "&output interval = 0.01, energy = .true., quiet = .true. /", &
                     "nodes = 41, t_end = 0.08, newton_tol = 1e-12 /", 'planar namelist', 9, error)
   end subroutine test_reduction

   !> The scene of test_reduction parted in the middle instead (s = 30 m of
   !> 60, 5 ms ramp), to 0.05 s (before the recoiling pieces buckle), with
   !> model = '2d' and '3d': two pieces in either model, the same output (42
   !> columns, the break node twice; break_a and break_b in the history) to
   !> the same 1e-10 (5e-10 for strain and velocities), ledger included; y
   !> and w stay 0. (On the inclined line of input/inclined_break_middle.nml,
   !> at 15 kN, the positions agree as well, 3e-13 of the span, but the
   !> tension, EA times the strain, only to 7e-10: so does its break at an end.)
   subroutine test_reduction_inside(error)
      type(error_type), allocatable, intent(out) :: error
      call reduction("&static tension = 315000 /"//new_line('a')// &
                     "&rupture s_break = 30.0, t_break = 0.005 /"//new_line('a')// &
                     "&output interval = 0.01, energy = .true., quiet = .true. /", &
                     "nodes = 41, t_end = 0.05, newton_tol = 1e-12 /", 'break inside', 6, error, 4)
   end subroutine test_reduction_inside

   !> Water in motion (issue 15): two planar scenes in water with model = '2d' and '3d',
   !> compared as test_reduction (1e-10 of each quantity's largest value, 5e-10 for the
   !> strain and the velocities, the fluid's work in the ledger included): a taut line
   !> (2 kN) released at end b over 5 ms in still water, to 0.5 s (41 nodes, Courant 1,
   !> past two reflections), and a slack line (60 m between points 50 m apart, tension
   !> 80-140 N) let go at end b at t = 0 in a current of 0.5 m/s along x, to 0.5 s (dt
   !> 10 ms). Measured: 1.6e-11 and 1.1e-10 (velocities 5.9e-11 and 1.1e-10). The fluid's
   !> cell forces are the same formula in both models; what set them apart, by 1.9e-8 and
   !> 7.4e-7, was the tanh law's strain energy, whose divided difference (W1 - W0) / (eps1
   !> - eps0) lost digits at small tensions (material/law.f90, tanh_strain_energy_change).
   subroutine test_reduction_water(error)
      type(error_type), allocatable, intent(out) :: error
      call reduction("&static tension = 2000 /"//new_line('a')// &
                     "&rupture t_break = 0.005 /"//new_line('a')// &
                     "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1 /"//new_line('a')// &
                     "&output interval = 0.05, energy = .true., quiet = .true. /", &
                     "nodes = 41, t_end = 0.5, newton_tol = 1e-12 /", 'taut line in still water', 11, error)
      if (allocated(error)) return
      call reduction("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                     "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
                     "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
                     "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_x = 0.5 /"// &
                     new_line('a')//"&output interval = 0.05, energy = .true., quiet = .true. /", &
                     "nodes = 41, dt = 0.01, t_end = 0.5, newton_tol = 1e-12 /", 'slack line in a current', 11, error, &
                     v_derived=.true.)
   end subroutine test_reduction_water

   !> A planar scene run with model = '2d' and '3d' compared as test_reduction
   !> says; snapshots: how many are expected; ends: of the history (default 2);
   !> v_derived: the field v counted with the velocities (a line falling, where v
   !> is the velocity that matters: default no).
   subroutine reduction(scene, numerics, label, snapshots, error, ends, v_derived)
      character(*), intent(in) :: scene, numerics, label
      integer, intent(in) :: snapshots
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: ends
      logical, intent(in), optional :: v_derived
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      type(run_history), pointer :: h2, h3
      real(dp) :: worst, d, scale, worst_derived, sb, ends_y
      integer :: i, j, q, n_ends
      logical :: v_counted
      character(len=16) :: where
      call run_pair(scene, numerics, sim2, obs2, sim3, obs3, error)
      if (allocated(error)) return
      call check(error, sim2%model == '2d' .and. sim3%model == '3d', 'models run: '//sim2%model//', '//sim3%model)
      if (allocated(error)) return
      n_ends = 2
      if (present(ends)) n_ends = ends
      v_counted = .false.
      if (present(v_derived)) v_counted = v_derived
      call check(error, size(sim2%rod%pieces) == n_ends/2 .and. size(sim3%rod3%pieces) == n_ends/2, 'pieces at the end: '// &
                 str(size(sim2%rod%pieces))//' in 2-D, '//str(size(sim3%rod3%pieces))//' in 3-D, expected '//str(n_ends/2))
      if (allocated(error)) return
      call check(error, obs2%n == obs3%n .and. obs2%n == snapshots .and. obs3%n_extra == obs3%n .and. obs2%n_extra == 0, &
                 'snapshots: '//str(obs2%n)//' and '//str(obs3%n)//' (3-D extra: '//str(obs3%n_extra)//')')
      if (allocated(error)) return
      worst = 0
      worst_derived = 0
      where = ''
      do j = 1, n_fields
         scale = max(maxval(abs(obs2%fields(:, j, :))), tiny(1.0_dp))
         d = maxval(abs(obs2%fields(:, j, :) - obs3%fields(:, j, :)))/scale
         if (field_names(j) == 'strain' .or. field_names(j) == 'u' .or. &
             (field_names(j) == 'v' .and. v_counted)) then
            worst_derived = max(worst_derived, d)
            cycle
         end if
         if (d > worst) where = field_names(j)
         worst = max(worst, d)
      end do
      h2 => sim2%history()
      h3 => sim3%history()
      call check(error, h2%n == h3%n, 'steps: '//str(h2%n)//' and '//str(h3%n))
      if (allocated(error)) return
      call check(error, size(h2%ends, 2) == n_ends .and. size(h3%ends, 2) == n_ends .and. &
                 size(obs3%fields, 1) == size(obs2%fields, 1), 'ends in the history: '//str(size(h2%ends, 2))// &
                 ' and '//str(size(h3%ends, 2))//', expected '//str(n_ends)//'; output nodes '// &
                 str(size(obs2%fields, 1))//' and '//str(size(obs3%fields, 1)))
      if (allocated(error)) return
      do i = 1, n_ends
         do q = 1, size(h2%ends, 1)
            scale = maxval(abs(h2%ends(q, i, 0:h2%n)))
            ! A fixed end's position and velocity: compared with the span and the released end's speed.
            if (q <= 4) scale = max(scale, 1.0_dp)
            d = maxval(abs(h2%ends(q, i, 0:h2%n) - h3%ends(q, i, 0:h3%n)))/scale
            ! The end velocities: differences of positions over a step, as u.
            if (q == 3 .or. q == 4) then
               worst_derived = max(worst_derived, d)
               cycle
            end if
            if (d > worst) where = 'history '//str(q)
            worst = max(worst, d)
         end do
      end do
      scale = maxval(abs(h2%energy(1, 0:h2%n)))
      d = maxval(abs(h2%energy(:, 0:h2%n) - h3%energy(:, 0:h3%n)))/scale
      if (d > worst) where = 'energy'
      worst = max(worst, d)
      d = max(maxval(abs(obs3%extra(:, 1, :))), maxval(abs(obs3%extra(:, 2, :))))
      ! Out of the plane: the binormal shear against the shear, the curvature about n against the
      ! curvature about b; the ends' y, vy, force_y against the span, speed and force scales.
      sb = maxval(abs(obs3%extra(:, 5, :)))/maxval(abs(obs3%fields(:, 2, :)))
      sb = max(sb, maxval(abs(obs3%extra(:, 6, :)))/maxval(abs(obs3%fields(:, 8, :))))
      call check(error, allocated(h3%ends_y) .and. .not. allocated(h2%ends_y), 'the y history: kept in 3-D '// &
                 merge('yes', 'no ', allocated(h3%ends_y))//', in 2-D '//merge('yes', 'no ', allocated(h2%ends_y)))
      if (allocated(error)) return
      ends_y = max(maxval(abs(h3%ends_y(1, :, 0:h3%n)))/60, maxval(abs(h3%ends_y(2, :, 0:h3%n)))/ &
                   maxval(abs(h3%ends(3:4, :, 0:h3%n))), maxval(abs(h3%ends_y(3, :, 0:h3%n)))/ &
                   maxval(abs(h3%ends(6:7, :, 0:h3%n))))
      write (output_unit, '(4x,a,es9.2,a,a,a,es9.2,a,es9.2,a,es9.2,a,es9.2)') label//', model 3d vs 2d: ', worst, &
         ' of the largest value (worst: ', trim(where), '), strain and velocities ', worst_derived, '; largest |y|, |w|: ', d, &
         ' (m, m/s); binormal shear and curvature about n / their in-plane fields ', sb, '; ends'' y history ', ends_y
      call check(error, sb < 5.0e-15_dp, 'a planar scene in 3-D has a binormal shear or curvature about n of '//str(sb)// &
                 ' of the in-plane ones')
      if (allocated(error)) return
      call check(error, ends_y < 1.0e-14_dp, 'a planar scene in 3-D has y components in the end history: '//str(ends_y))
      if (allocated(error)) return
      call check(error, worst < 1.0e-10_dp, 'model 3d differs from 2d by '//str(worst)//' ('//trim(where)//')')
      if (allocated(error)) return
      call check(error, worst_derived < 5.0e-10_dp, 'model 3d differs from 2d in strain or velocities by '//str(worst_derived))
      if (allocated(error)) return
      call check(error, d < 1.0e-12_dp, 'a planar scene in 3-D left the plane by '//str(d))
   end subroutine reduction

   !> A line in water between two fixed points 50 m apart (60 m of cable),
   !> blown 11 m downstream by a current across the plane (current_y), parted
   !> a third of the way along (s = 20 m) at t = 0 over 10 ms; 41 nodes, dt 5 ms.
   function current_break(current_y, t_end) result(text)
      character(*), intent(in) :: current_y, t_end
      character(:), allocatable :: text
      text = "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
             "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
             "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = "// &
             current_y//" /"//new_line('a')// &
             "&rupture s_break = 20, t_break = 0.01 /"//new_line('a')// &
             "&numerics nodes = 41, dt = 0.005, t_end = "//t_end//", newton_tol = 1e-10 /"//new_line('a')// &
             "&output interval = "//merge('0.1', '0  ', t_end /= '0.005')//", energy = .true., quiet = .true. /"
   end function current_break

   !> A break inside the cable out of the plane (current_break): at the break
   !> the couple's axis (the normal of the break node's cells) leans out of
   !> the y axis, and the new ends' forces and couples hold each piece in the
   !> static state of the whole (each piece's static residual at the break,
   !> with its cut end at full load, as small as Newton left the whole's; the
   !> two cut forces cancel). The run to 1.5 s: two pieces, the ledger (with
   !> the fluid's work) closes, and the scene mirrored (current_y -0.3) gives
   !> the mirrored solution (x, z, tension the same, y and w of opposite
   !> sign; the history's y components too) to round-off.
   subroutine test_break_inside_3d(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim, mirrored
      type(keeper) :: obs, obs_m
      type(case_config) :: config
      type(band_matrix) :: unused
      type(run_summary), pointer :: s
      type(run_history), pointer :: h, hm
      real(dp), allocatable :: res(:)
      real(dp) :: whole, worst(2), axis(3), cancel, mirror
      integer :: p
      ! At the break.
      call read_text(current_break('0.3', '0.005'), config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      associate (run => sim%rod3%pieces(1)%run)
         allocate (res(size(run%x)))
         call run%problem%piece%static_system(run%x, 0.0_dp, res, unused, .false.)
         whole = maxval(abs(res(1:3*run%problem%piece%n)))
      end associate
      call start_dynamics(sim%rod, sim%rod3, error=error)
      if (allocated(error)) return
      call check(error, size(sim%rod3%pieces) == 2, 'pieces after the break: '//str(size(sim%rod3%pieces)))
      if (allocated(error)) return
      do p = 1, 2
         associate (run => sim%rod3%pieces(p)%run)
            deallocate (res)
            allocate (res(size(run%x)))
            call run%problem%piece%static_system(run%x, 0.0_dp, res, unused, .false.)
            worst(p) = maxval(abs(res(1:3*run%problem%piece%n)))
         end associate
      end do
      axis = sim%rod3%cut_axis(:, 1)
      cancel = norm2(sim%rod3%cut_force(:, 1) + sim%rod3%cut_force(:, 2))/norm2(sim%rod3%cut_force(:, 1))
      write (output_unit, '(4x,a,3f8.4,a,es9.2,a,3es9.2,a,es9.2)') 'break inside, out of the plane: couple axis ', axis, &
         ', couple ', sim%rod3%cut_couple(1), ' N m; static residual (scaled) of the whole, of the pieces ', whole, worst, &
         '; cut forces cancel to ', cancel
      call check(error, abs(axis(2)) < 0.99_dp .and. abs(axis(1)) + abs(axis(3)) > 0.1_dp .and. &
                 abs(sim%rod3%cut_force(2, 1)) > 0.01_dp*norm2(sim%rod3%cut_force(:, 1)), &
                 'the break is not out of the plane: axis '//str(axis(1))//', '//str(axis(2))//', '//str(axis(3)))
      if (allocated(error)) return
      call check(error, maxval(worst) < 1.0e-9_dp .and. cancel < 1.0e-9_dp, 'the cut ends do not hold the pieces in '// &
                 'the static state: residual '//str(maxval(worst))//' (the whole: '//str(whole)//'), the cut forces '// &
                 'add up to '//str(cancel)//' of one')
      if (allocated(error)) return
      ! The run and its mirror image.
      call run_case(current_break('0.3', '1.5'), sim, obs, error)
      if (allocated(error)) return
      call run_case(current_break('-0.3', '1.5'), mirrored, obs_m, error)
      if (allocated(error)) return
      s => sim%summary()
      h => sim%history()
      hm => mirrored%history()
      mirror = max(maxval(abs(obs%fields(:, 1, :) - obs_m%fields(:, 1, :)))/1.0e5_dp, &
                   maxval(abs(obs%fields(:, 6:7, :) - obs_m%fields(:, 6:7, :)))/60, &
                   maxval(abs(obs%extra(:, 1:2, :) + obs_m%extra(:, 1:2, :)))/60, &
                   maxval(abs(h%ends(1:2, :, 0:h%n) - hm%ends(1:2, :, 0:h%n)))/60, &
                   maxval(abs(h%ends_y(1, :, 0:h%n) + hm%ends_y(1, :, 0:h%n)))/60)
      write (output_unit, '(4x,a,es9.2,a,es10.3,a,es9.2,a,f7.3,a)') 'run to 1.5 s: ledger drift ', s%energy_drift, &
         ' (fluid work ', h%energy(8, h%n), ' J); mirrored scene against the mirrored solution ', mirror, &
         ' of the length (tension: of 100 kN); peak speed ', s%peak_end_speed, ' m/s'
      call check(error, size(sim%rod3%pieces) == 2 .and. size(h%ends, 2) == 4 .and. &
                 s%time_reached >= 1.5_dp - 1.0e-12_dp, 'pieces '//str(size(sim%rod3%pieces))//', ends '// &
                 str(size(h%ends, 2))//', reached t = '//str(s%time_reached))
      if (allocated(error)) return
      call check(error, s%energy_drift >= 0 .and. s%energy_drift < 5.0e-9_dp, 'ledger drift '//str(s%energy_drift))
      if (allocated(error)) return
      call check(error, mirror < 1.0e-13_dp, 'the mirrored scene differs from the mirrored solution by '//str(mirror))
   end subroutine test_break_inside_3d

   !> The planar run's cut forces with distributed loads: a line in water
   !> between points 50 m apart with a current along x (0.5 m/s), parted at
   !> s = 20 m at t = 0 with model = '2d': each piece's static residual at the
   !> break with its cut end at full load is as small as the whole's, and the
   !> two cut forces cancel (each new end keeps its own cell's share of the
   !> drag at the break node).
   subroutine test_break_inside_water_2d(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: config
      type(band_matrix) :: unused
      real(dp), allocatable :: res(:), x(:)
      real(dp) :: whole, worst(2), cancel
      integer :: p
      call read_text("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                     "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
                     "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_x = 0.5 /"// &
                     new_line('a')//"&rupture s_break = 20, t_break = 0.01 /"//new_line('a')// &
                     "&numerics model = '2d', nodes = 41, dt = 0.005, t_end = 0.005, newton_tol = 1e-10 /"// &
                     new_line('a')//"&output interval = 0, quiet = .true. /", config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      associate (piece => sim%rod%pieces(1)%problem%piece)
         x = reshape(sim%rod%static%r, [2*piece%n])
         allocate (res(size(x)))
         call piece%static_system(x, 0.0_dp, res, unused, .false.)
         whole = maxval(abs(res))
      end associate
      call start_dynamics(sim%rod, sim%planar, error=error)
      if (allocated(error)) return
      call check(error, size(sim%rod%pieces) == 2, 'pieces after the break: '//str(size(sim%rod%pieces)))
      if (allocated(error)) return
      do p = 1, 2
         associate (piece => sim%rod%pieces(p)%problem%piece)
            x = reshape(sim%rod%pieces(p)%r, [2*piece%n])
            deallocate (res)
            allocate (res(size(x)))
            call piece%static_system(x, 0.0_dp, res, unused, .false.)
            worst(p) = maxval(abs(res))
         end associate
      end do
      cancel = norm2(sim%rod%cut_force(:, 1) + sim%rod%cut_force(:, 2))/norm2(sim%rod%cut_force(:, 1))
      write (output_unit, '(4x,a,3es9.2,a,es9.2)') 'break inside in water, 2-D: static residual of the whole, of the '// &
         'pieces ', whole, worst, '; cut forces cancel to ', cancel
      call check(error, maxval(worst) < 1.0e-9_dp .and. cancel < 1.0e-9_dp, 'the cut ends do not hold the pieces '// &
                 'in the static state: residual '//str(maxval(worst))//' (the whole: '//str(whole)// &
                 '), the cut forces add up to '//str(cancel)//' of one')
   end subroutine test_break_inside_water_2d

   !> A twisted cable parted inside: end a fixed, end b loaded by a force and
   !> a torque of 5 N m (a uniform twist), parted at s = 30 m over 50 ms (41
   !> nodes, to 0.2 s). The piece with end b holds no twist at either end:
   !> it keeps the twist angle its first node had at the cut (psi_anchor)
   !> instead of spinning to 0 in the first step, whose work the ledger would
   !> book (drift 1.2e-4 so). Piece 1's twist rate falls with the cut's
   !> torque, piece 2's stays that of end b's torque; the ledger closes.
   subroutine test_break_inside_twisted(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(run_summary), pointer :: s
      real(dp) :: rate_a, rate_b, rate0
      integer :: kb
      call run_case(twisted_break, sim, obs, error)
      if (allocated(error)) return
      s => sim%summary()
      kb = sim%rod%break_node
      rate0 = obs%extra(kb, 4, 1)
      rate_a = obs%extra(kb, 4, obs%n_extra)
      rate_b = obs%extra(kb + 1, 4, obs%n_extra)
      write (output_unit, '(4x,a,es9.2,a,3f9.5,a)') 'twisted cable parted inside: ledger drift ', s%energy_drift, &
         '; twist rate at the cut before, then on either side at the end ', rate0, rate_a, rate_b, ' 1/m'
      call check(error, size(sim%rod3%pieces) == 2 .and. abs(rate0) > 0.05_dp .and. abs(rate_a) < 1.0e-9_dp .and. &
                 abs(rate_b - rate0) < 1.0e-9_dp*abs(rate0), 'twist rates at the cut: '//str(rate0)//' before, '// &
                 str(rate_a)//' and '//str(rate_b)//' after the ramp')
      if (allocated(error)) return
      call check(error, s%energy_drift >= 0 .and. s%energy_drift < 1.0e-11_dp, 'ledger drift '//str(s%energy_drift))
   end subroutine test_break_inside_twisted

   !> model = 'auto': 2-D for a planar scene, 3-D when end b has a y, a force end a y force or a torque,
   !> or the current a y component.
   subroutine test_auto(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: common = "&rupture enabled = .false. /"//new_line('a')// &
                                              "&numerics nodes = 11, t_end = 0.002 /"//new_line('a')// &
                                              "&output interval = 0.002, quiet = .true. /"//new_line('a')
      character(len=160) :: scenes(5)
      character(len=2) :: expected(5)
      type(simulation) :: sim
      type(keeper) :: obs
      integer :: i
      scenes(1) = "&end_b kind = 'fixed', x = 50, z = 0 /"
      ! In the vertical plane at atan(5 / 50) from x: 2-D, turned, with the 3-D fields.
      scenes(2) = "&end_b kind = 'fixed', x = 50, y = 5, z = 0 /"
      scenes(3) = "&end_b kind = 'force', force_x = 3000, force_z = 1000, torque = 5 /"
      scenes(4) = "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
                  "&fluid density = 1025, cd_normal = 1.2, current_y = 0.5 /"
      ! The same plane, with a current across it.
      scenes(5) = "&end_b kind = 'fixed', x = 50, y = 5, z = 0 /"//new_line('a')// &
                  "&fluid density = 1025, cd_normal = 1.2, current_x = 0.5 /"
      expected = ['2d', '2d', '3d', '3d', '3d']
      do i = 1, size(scenes)
         obs = keeper()
         call run_case(common//trim(scenes(i)), sim, obs, error)
         if (allocated(error)) return
         call check(error, sim%model == expected(i), 'scene '//str(i)//": model 'auto' ran "//sim%model//', expected '// &
                    expected(i))
         if (allocated(error)) return
         call check(error, (obs%n_extra > 0) .eqv. (i > 1), 'scene '//str(i)//': 3-D fields sent '// &
                    str(obs%n_extra)//' times')
         if (allocated(error)) return
      end do
   end subroutine test_auto

   !> A slack line (60 m between points 30 m apart along x and 20 m along y)
   !> let go at end b: it runs to t_end, the ledger closes, and the motion stays
   !> in the vertical plane of the chord (y / x = 2/3 at every node and
   !> snapshot, to 1e-9 of the length) while end b moves across x-z (0.68 m in y by 2 s).
   !> Its frames lie in that turned plane: no binormal shear, no curvature about n.
   !> The end history keeps y: end b starts at y = 20 m, the support's force at
   !> end a stays in the chord's plane (f_y / f_x = 2/3), and end b's peak speed
   !> in the summary is that of (vx, vy, vz) in the history.
   subroutine test_off_plane(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(run_summary), pointer :: s
      type(run_history), pointer :: h
      real(dp) :: y_moved, off_chord_plane, force_off_plane, peak, turned, turned_static
      integer :: i
      call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 30, y = 20, z = 0 /"//new_line('a')// &
                    "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
                    "&numerics model = '3d', nodes = 31, courant = 2, t_end = 2.0 /"//new_line('a')// &
                    "&output interval = 0.1, energy = .true., quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      s => sim%summary()
      y_moved = obs%extra(size(obs%extra, 1), 1, 1) - obs%extra(size(obs%extra, 1), 1, obs%n_extra)
      off_chord_plane = maxval(abs(30*obs%extra(:, 1, :) - 20*obs%fields(:, 6, :)))/sqrt(30.0_dp**2 + 20**2)/60
      write (output_unit, '(4x,a,es9.2,a,f7.3,a,es9.2,a)') 'end b off the plane, released: ledger drift ', &
         s%energy_drift, ' of the strain energy; end b moved ', y_moved, ' m in y, off the chord''s plane by ', &
         off_chord_plane, ' of the length'
      call check(error, sim%model == '3d' .and. s%time_reached >= 2.0_dp - 1.0e-12_dp, 'model '//sim%model// &
                 ', reached t = '//str(s%time_reached))
      if (allocated(error)) return
      call check(error, s%energy_drift >= 0 .and. s%energy_drift < 1.0e-6_dp, 'ledger drift '//str(s%energy_drift))
      if (allocated(error)) return
      call check(error, y_moved > 0.3_dp, 'end b moved only '//str(y_moved)//' m in y')
      if (allocated(error)) return
      call check(error, off_chord_plane < 1.0e-9_dp, 'the motion left the chord''s plane by '//str(off_chord_plane))
      if (allocated(error)) return
      ! The frames of a line in a turned vertical plane: n in the plane, b along its normal, so
      ! the binormal shear and the curvature about n vanish: in the statics to round-off, in the
      ! motion to the size its 2e-13 of the length off the plane (Newton's tolerance) gives them.
      turned_static = max(maxval(abs(obs%static_extra(:, 5)))/maxval(abs(obs%fields(:, 2, 1))), &
                          maxval(abs(obs%static_extra(:, 6)))/maxval(abs(obs%fields(:, 8, 1))))
      turned = max(maxval(abs(obs%extra(:, 5, :)))/maxval(abs(obs%fields(:, 2, :))), &
                   maxval(abs(obs%extra(:, 6, :)))/maxval(abs(obs%fields(:, 8, :))))
      write (output_unit, '(4x,a,es9.2,a,es9.2)') 'line in a turned plane: binormal shear and curvature about n / '// &
         'shear and curvature, statics ', turned_static, ', snapshots ', turned
      call check(error, turned_static < 2.0e-13_dp .and. turned < 3.0e-10_dp, 'in a turned vertical plane the '// &
                 'binormal shear or the curvature about n is '//str(turned_static)//' (statics), '//str(turned)// &
                 ' (snapshots) of the in-plane one: the frames are not in the plane')
      if (allocated(error)) return
      h => sim%history()
      call check(error, allocated(h%ends_y), 'no y components in the history of a 3-D run')
      if (allocated(error)) return
      force_off_plane = 0
      peak = 0
      do i = 0, h%n
         force_off_plane = max(force_off_plane, abs(30*h%ends_y(3, 1, i) - 20*h%ends(6, 1, i))/ &
                               (sqrt(30.0_dp**2 + 20**2)*norm2([h%ends(6:7, 1, i), h%ends_y(3, 1, i)])))
         peak = max(peak, norm2([h%ends(3:4, 2, i), h%ends_y(2, 2, i)]))
      end do
      write (output_unit, '(4x,a,f8.3,a,es9.2,a,f8.4,a,f8.4,a)') 'history: end b starts at y = ', h%ends_y(1, 2, 0), &
         ' m; end a''s force off the chord''s plane ', force_off_plane, ' of its size; end b''s peak speed ', &
         s%ends(2)%peak_speed, ' m/s (history: ', peak, ')'
      call check(error, abs(h%ends_y(1, 2, 0) - 20) < 1.0e-12_dp, 'end b starts at y = '//str(h%ends_y(1, 2, 0)))
      if (allocated(error)) return
      call check(error, force_off_plane < 1.0e-11_dp, 'end a''s force leaves the chord''s plane by '//str(force_off_plane))
      if (allocated(error)) return
      call check(error, abs(s%ends(2)%peak_speed - peak) <= 1.0e-14_dp*peak, 'end b''s peak speed in the summary, '// &
                 str(s%ends(2)%peak_speed)//' m/s, is not that of its velocity (vx, vy, vz) in the history, '//str(peak))
   end subroutine test_off_plane

   !> A line in water between a fixed end and a fairlead moving across the
   !> plane (harmonic along y, 1 m, 2 s), with a current across the plane
   !> (0.3 m/s along y, in the statics too): it runs to t_end, the ledger (with
   !> the fluid's work; Newton to 1e-10) closes, and the middle stands downstream (+y).
   !> The curvature output, frame-free: at every node and snapshot, the
   !> components about n and b (curvature_n, curvature) have the length, and
   !> curvature_z the z component, of the discrete curvature vector
   !> 2 tan(th/2) / h (a x b) / |a x b| computed here from the output's x, y, z.
   subroutine test_cross_current(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(run_summary), pointer :: s
      type(run_history), pointer :: h
      real(dp) :: y_mid, loads, kappa(3), a(3), b(3), c(3), worst_length, worst_z, largest
      real(dp), allocatable :: arc(:)
      integer :: mid, i, k
      call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                    "&end_b kind = 'motion', x = 50, z = 0, amplitude = 1, period = 2, direction_x = 0, direction_y = 1, "// &
                    "direction_z = 0, ramp_time = 0.5 /"//new_line('a')// &
                    "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = 0.3 /"// &
                    new_line('a')//"&rupture enabled = .false. /"//new_line('a')// &
                    "&numerics nodes = 31, dt = 0.01, t_end = 2.0, newton_tol = 1e-10 /"//new_line('a')// &
                    "&output interval = 0.5, energy = .true., quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      s => sim%summary()
      h => sim%history()
      mid = (size(obs%extra, 1) + 1)/2
      y_mid = obs%extra(mid, 1, obs%n_extra)
      loads = h%energy(8, h%n)
      write (output_unit, '(4x,a,es9.2,a,es10.3,a,f7.3,a)') 'cross current: ledger drift ', s%energy_drift, &
         ' of the strain energy (fluid work ', loads, ' J); middle at y = ', y_mid, ' m'
      call check(error, sim%model == '3d' .and. s%time_reached >= 2.0_dp - 1.0e-12_dp, 'model '//sim%model// &
                 ', reached t = '//str(s%time_reached))
      if (allocated(error)) return
      call check(error, s%energy_drift >= 0 .and. s%energy_drift < 1.0e-6_dp, 'ledger drift '//str(s%energy_drift))
      if (allocated(error)) return
      call check(error, y_mid > 0.01_dp .and. abs(loads) > 0, 'the middle drifted to y = '//str(y_mid)//' m')
      if (allocated(error)) return
      arc = sim%output_s()
      worst_length = 0
      worst_z = 0
      largest = 0
      do i = 1, obs%n
         do k = 2, size(arc) - 1
            a = [obs%fields(k, 6, i) - obs%fields(k - 1, 6, i), obs%extra(k, 1, i) - obs%extra(k - 1, 1, i), &
                 obs%fields(k, 7, i) - obs%fields(k - 1, 7, i)]
            b = [obs%fields(k + 1, 6, i) - obs%fields(k, 6, i), obs%extra(k + 1, 1, i) - obs%extra(k, 1, i), &
                 obs%fields(k + 1, 7, i) - obs%fields(k, 7, i)]
            c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
            kappa = 2*tan(0.5_dp*atan2(norm2(c), dot_product(a, b)))/(0.5_dp*(arc(k + 1) - arc(k - 1)))*c/norm2(c)
            largest = max(largest, norm2(kappa))
            worst_length = max(worst_length, abs(hypot(obs%fields(k, 8, i), obs%extra(k, 6, i)) - norm2(kappa)))
            worst_z = max(worst_z, abs(obs%extra(k, 3, i) - kappa(3)))
         end do
      end do
      write (output_unit, '(4x,a,es9.2,a,es9.2,a)') 'curvature against the positions: length ', worst_length/largest, &
         ', z component ', worst_z/largest, ' of the largest curvature'
      call check(error, max(worst_length, worst_z) < 1.0e-14_dp*largest, 'the curvature output differs from the '// &
                 'positions'' curvature vector by '//str(max(worst_length, worst_z)/largest))
   end subroutine test_cross_current

   !> The moment balance dM/ds + (1 + eps) t x F = 0 with M = EI (Omega2 n +
   !> Omega3 b), in the frame of rod3d%frames (parallel transport: no torque,
   !> Omega1 = 0), gives Sb = EI dOmega2/ds / (1 + eps) and Sn = -EI
   !> dOmega3/ds / (1 + eps). Checked by central differences of the output
   !> (curvature_n, curvature, strain on the nodes) against the output's
   !> binormal_shear and shear at the interior nodes 3 .. n-2 of the static
   !> state of a line in water bowed out of its plane by a cross current
   !> (0.3 m/s along y) and sagging in it, on 31, 61 and 121 nodes: the
   !> difference is a discretisation error (central differences of node
   !> values against cell differences of the moment dB/dth = EI kappa (1 +
   !> tan^2(th/2))) and falls at order 2 or faster as the cells are halved
   !> (measured: about 3). Sb is about as large as Sn there. (In a
   !> moving line the shear forces, third differences of the positions, carry
   !> a sawtooth at the grid scale that differences of node values cannot
   !> follow: not a test of the formulas.)
   subroutine test_moment_balance(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: grids(3) = [31, 61, 121]
      real(dp) :: err_b(3), err_n(3), sb_ratio(3), order_b, order_n
      integer :: g
      do g = 1, 3
         call balance(grids(g), err_b(g), err_n(g), sb_ratio(g), error)
         if (allocated(error)) return
         write (output_unit, '(4x,a,i4,a,es9.2,a,es9.2,a,f6.3)') 'moment balance by differences of the static output,', &
            grids(g), ' nodes: Sb ', err_b(g), ', Sn ', err_n(g), ' of their largest value; largest |Sb| / |Sn| ', &
            sb_ratio(g)
      end do
      order_b = log(err_b(2)/err_b(3))/log(2.0_dp)
      order_n = log(err_n(2)/err_n(3))/log(2.0_dp)
      write (output_unit, '(4x,a,f5.2,a,f5.2)') 'order from 61 to 121 nodes: Sb ', order_b, ', Sn ', order_n
      call check(error, sb_ratio(3) > 0.3_dp, 'the binormal shear is only '//str(sb_ratio(3))//' of the shear')
      if (allocated(error)) return
      call check(error, err_b(3) < 1.0e-4_dp .and. err_n(3) < 1.0e-4_dp, 'the output breaks the moment balance by '// &
                 str(err_b(3))//' (Sb) and '//str(err_n(3))//' (Sn) on 121 nodes')
      if (allocated(error)) return
      call check(error, order_b > 1.8_dp .and. order_n > 1.8_dp, 'the moment balance does not converge at order 2: '// &
                 'Sb '//str(order_b)//', Sn '//str(order_n))
   contains
      subroutine balance(nodes, err_b, err_n, ratio, error)
         integer, intent(in) :: nodes
         real(dp), intent(out) :: err_b, err_n, ratio
         type(error_type), allocatable, intent(out) :: error
         type(simulation) :: sim
         type(keeper) :: obs
         real(dp), allocatable :: s(:)
         real(dp) :: ei, fd, worst_b, worst_n
         integer :: k, n
         call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                       "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
                       "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = 0.3 /"// &
                       new_line('a')//"&rupture enabled = .false. /"//new_line('a')// &
                       "&numerics nodes = "//str(nodes)//", dt = 0.01, t_end = 0.01 /"//new_line('a')// &
                       "&output interval = 0.01, quiet = .true. /", sim, obs, error)
         if (allocated(error)) return
         call check(error, sim%model == '3d' .and. obs%n_extra == 2 .and. allocated(obs%static_extra), &
                    'model '//sim%model//', '//str(obs%n_extra)//' snapshots with 3-D fields')
         if (allocated(error)) return
         ! The static record's 3-D fields are those of the first snapshot.
         call check(error, maxval(abs(obs%static_extra - obs%extra(:, :, 1))) == 0, &
                    'the static record''s 3-D fields differ from the first snapshot''s')
         if (allocated(error)) return
         s = sim%output_s()
         n = size(s)
         ei = sim%rod%scene%ei
         worst_b = 0
         worst_n = 0
         associate (f => obs%fields(:, :, 1), x3 => obs%extra(:, :, 1))
            do k = 3, n - 2
               ! Sb = EI dOmega2/ds / (1 + eps), Omega2 = curvature_n.
               fd = ei*(x3(k + 1, 6) - x3(k - 1, 6))/(s(k + 1) - s(k - 1))/(1 + f(k, 3))
               worst_b = max(worst_b, abs(x3(k, 5) - fd))
               ! Sn = -EI dOmega3/ds / (1 + eps), Omega3 = curvature.
               fd = -ei*(f(k + 1, 8) - f(k - 1, 8))/(s(k + 1) - s(k - 1))/(1 + f(k, 3))
               worst_n = max(worst_n, abs(f(k, 2) - fd))
            end do
            err_b = worst_b/maxval(abs(x3(3:n - 2, 5)))
            err_n = worst_n/maxval(abs(f(3:n - 2, 2)))
            ratio = maxval(abs(x3(3:n - 2, 5)))/maxval(abs(f(3:n - 2, 2)))
         end associate
      end subroutine balance
   end subroutine test_moment_balance

   !> A torque turns the material frames without moving the line (the twist
   !> is not coupled to the centreline): psi = tau s with tau = M_t / GIp
   !> from the held end a, and cell c's frame is the untwisted one turned by
   !> its mean angle pbar_c = tau (s_c + s_c+1) / 2 about t. So the static
   !> state of a planar line under an end force and a torque (3-D; a cable
   !> 60 m long, one turn of twist over 60 m) has, at node k, in closed form
   !> from the untwisted run's curvature Omega3_0 (b = y there):
   !>     curvature   = Omega3_0 (cos pbar_k-1 + cos pbar_k) / 2,
   !>     curvature_n = Omega3_0 (sin pbar_k-1 + sin pbar_k) / 2,
   !> and twist = tau. With the frame turning (Omega1 = tau) the moment
   !> balance by central differences of the output reads Sb = EI (dOmega2/ds
   !> - tau Omega3) / (1 + eps) and Sn = -EI (dOmega3/ds + tau Omega2) /
   !> (1 + eps), on the middle 80 % of the line (the bending boundary layers
   !> at the pinned ends are a few cells wide). The difference is the central
   !> difference's error on the turning frame, (tau h)^2 / 6 = 4.6e-4 of the
   !> term EI tau Omega, with h = 0.5 m. The closed form holds to the
   !> statics' tolerance (the two runs take their own Newton iterations).
   subroutine test_twisted_frames(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: scene = "&end_b kind = 'force', force_x = 3000, force_z = 1000, "
      character(len=*), parameter :: rest = "&rupture enabled = .false. /"//new_line('a')// &
                                            "&numerics model = '3d', nodes = 121, dt = 0.001, t_end = 0.001 /"// &
                                            new_line('a')//"&output interval = 0.001, quiet = .true. /"
      type(simulation) :: sim0, sim
      type(keeper) :: obs0, obs
      real(dp), allocatable :: s(:), pbar(:)
      real(dp) :: tau, torque, ei, worst_closed, worst_twist, worst_b, worst_n, fd, scale
      character(len=32) :: torque_text
      integer :: k, n
      call run_case(scene//"torque = 0 /"//new_line('a')//rest, sim0, obs0, error)
      if (allocated(error)) return
      ! One turn over the 60 m: tau = 2 pi / 60 1/m, M_t = GIp tau.
      tau = 2*acos(-1.0_dp)/60
      torque = sim0%rod%scene%gip*tau
      write (torque_text, '(es24.16)') torque
      call run_case(scene//"torque = "//trim(torque_text)//" /"//new_line('a')//rest, sim, obs, error)
      if (allocated(error)) return
      s = sim%output_s()
      n = size(s)
      ei = sim%rod%scene%ei
      pbar = tau*0.5_dp*(s(1:n - 1) + s(2:n))
      worst_closed = 0
      worst_twist = maxval(abs(obs%extra(:, 4, 1) - tau))/tau
      scale = maxval(abs(obs0%fields(:, 8, 1)))
      do k = 2, n - 1
         worst_closed = max(worst_closed, abs(obs%fields(k, 8, 1) - obs0%fields(k, 8, 1)*0.5_dp* &
                                              (cos(pbar(k - 1)) + cos(pbar(k)))), &
                            abs(obs%extra(k, 6, 1) - obs0%fields(k, 8, 1)*0.5_dp*(sin(pbar(k - 1)) + sin(pbar(k)))))
      end do
      worst_closed = worst_closed/scale
      worst_b = 0
      worst_n = 0
      associate (f => obs%fields(:, :, 1), x3 => obs%extra(:, :, 1))
         ! The middle 80 %: the bending boundary layers at the pinned ends (a few cells wide) need finer cells.
         do k = n/10, n - n/10
            fd = ei*((x3(k + 1, 6) - x3(k - 1, 6))/(s(k + 1) - s(k - 1)) - tau*f(k, 8))/(1 + f(k, 3))
            worst_b = max(worst_b, abs(x3(k, 5) - fd))
            fd = -ei*((f(k + 1, 8) - f(k - 1, 8))/(s(k + 1) - s(k - 1)) + tau*x3(k, 6))/(1 + f(k, 3))
            worst_n = max(worst_n, abs(f(k, 2) - fd))
         end do
         ! The terms of the balance: EI dOmega/ds and EI tau Omega (the second the larger here).
         scale = max(maxval(abs(obs0%fields(n/10:n - n/10, 2, 1))), ei*tau*maxval(abs(obs0%fields(n/10:n - n/10, 8, 1))))
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,es9.2,a,es9.2,a)') 'twisted frames (one turn over 60 m): curvature '// &
         'components against the closed form ', worst_closed, ' of the largest curvature; twist rate ', worst_twist, &
         ' of tau; moment balance with tau: Sb ', worst_b/scale, ', Sn ', worst_n/scale, ' of its largest term'
      call check(error, sim%model == '3d' .and. worst_twist < 1.0e-13_dp, 'twist rate off tau = M_t / GIp by '// &
                 str(worst_twist))
      if (allocated(error)) return
      call check(error, worst_closed < 1.0e-11_dp, 'the curvature components of the twisted frames differ from '// &
                 'the closed form by '//str(worst_closed))
      if (allocated(error)) return
      call check(error, max(worst_b, worst_n)/scale < 1.0e-3_dp, 'the twisted output breaks the moment balance by '// &
                 str(worst_b/scale)//' (Sb) and '//str(worst_n/scale)//' (Sn)')
   end subroutine test_twisted_frames
   !> The paper's 400 kN break (5 ms) with EI / 1000 on 121 nodes at Courant 10,
   !> to 0.1 s: Newton fails in some steps (a slack zone at the fixed end) and
   !> the step control rejects them. With model = '3d' the same attempts are
   !> rejected as with '2d' (history%rejected and history%step equal), and
   !> the snapshots agree as in the reduction test (measured 5.0e-10 of each
   !> field's largest value: 8.4e-10).
   subroutine test_rejections_planar(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: scene = &
         "&cable bending_stiffness = 0.07056 /"//new_line('a')// &
         "&static tension = 400000 /"//new_line('a')// &
         "&rupture t_break = 0.005 /"//new_line('a')// &
         "&output interval = 0.02, energy = .true., quiet = .true. /"
      character(len=*), parameter :: numerics = "nodes = 121, courant = 10, t_end = 0.1 /"
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      type(run_history), pointer :: h2, h3
      type(run_summary), pointer :: s2, s3
      real(dp) :: worst, d
      integer :: j
      call run_pair(scene, numerics, sim2, obs2, sim3, obs3, error)
      if (allocated(error)) return
      h2 => sim2%history()
      h3 => sim3%history()
      s2 => sim2%summary()
      s3 => sim3%summary()
      call check(error, h2%n == h3%n .and. obs2%n == obs3%n, 'steps: '//str(h2%n)//' and '//str(h3%n))
      if (allocated(error)) return
      call check(error, all(h2%rejected(0:h2%n) == h3%rejected(0:h3%n)) .and. all(h2%step(0:h2%n) == h3%step(0:h3%n)), &
                 'the 3-D run rejected other attempts ('//str(s3%rejected_steps)//') than the 2-D run ('// &
                 str(s2%rejected_steps)//')')
      if (allocated(error)) return
      call check(error, s3%rejected_steps == s2%rejected_steps .and. s3%rejected_steps >= 4 .and. &
                 sum(h3%rejected(1:h3%n)) == s3%rejected_steps, 'rejected: '//str(s3%rejected_steps)// &
                 ' in 3-D (history: '//str(sum(h3%rejected(1:h3%n)))//'), '//str(s2%rejected_steps)//' in 2-D')
      if (allocated(error)) return
      worst = 0
      do j = 1, n_fields
         d = maxval(abs(obs2%fields(:, j, :) - obs3%fields(:, j, :)))/max(maxval(abs(obs2%fields(:, j, :))), tiny(1.0_dp))
         worst = max(worst, d)
      end do
      write (output_unit, '(4x,a,i0,a,es9.2,a)') 'planar 400 kN break at Courant 10: ', s3%rejected_steps, &
         ' rejected attempts in both models; snapshots 3d vs 2d ', worst, ' of the largest value'
      call check(error, worst < 2.0e-9_dp, 'model 3d differs from 2d by '//str(worst))
   end subroutine test_rejections_planar

   !> The off-plane slack release of end_b_off_plane_released on 121 nodes,
   !> EI / 1000, at Courant 14 to 2 s (Courant 10 on the scene's shadow on x-z before the 3-D
   !> run was prepared from its own chord: the same stress on the step control): at the
   !> requested step Newton diverges (the run stopped there before the step control).
   !> The run completes through rejected and halved steps, records them
   !> against the steps that followed, grows the step back to dt, warns of
   !> them, and its ledger closes (measured 6.2e-9 of the strain energy).
   subroutine test_rejections_off_plane(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(run_summary), pointer :: s
      type(run_history), pointer :: h
      real(dp) :: dt
      integer :: smallest, first_rejection, steps
      call run_case("&cable bending_stiffness = 0.07056 /"//new_line('a')// &
                    "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 40, y = 20, z = 0 /"//new_line('a')// &
                    "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
                    "&numerics model = '3d', nodes = 121, courant = 14, t_end = 2.0 /"//new_line('a')// &
                    "&output interval = 0.1, energy = .true., quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      s => sim%summary()
      h => sim%history()
      call sim%time_step(dt, steps)
      ! The last step is shortened to land on t_end.
      smallest = minloc(h%step(1:h%n - 1), 1)
      write (output_unit, '(4x,a,i0,a,i0,a,es9.2,a,es9.2)') 'off-plane slack release at Courant 14: ', &
         s%rejected_steps, ' rejected attempts, ', h%n, ' steps, smallest dt / ', dt/h%step(smallest), &
         '; ledger drift ', s%energy_drift
      call check(error, sim%model == '3d' .and. s%time_reached >= 2.0_dp - 1.0e-12_dp, 'model '//sim%model// &
                 ', reached t = '//str(s%time_reached))
      if (allocated(error)) return
      call check(error, s%rejected_steps > 10 .and. sum(h%rejected(1:h%n)) == s%rejected_steps .and. h%rejected(0) == 0, &
                 'rejected '//str(s%rejected_steps)//', in the history '//str(sum(h%rejected(0:h%n))))
      if (allocated(error)) return
      call check(error, all(h%step(1:h%n) <= dt*(1 + 1.0e-12_dp)) .and. h%step(smallest) <= 0.5_dp*dt*(1 + 1.0e-12_dp) &
                 .and. h%step(smallest) >= dt/1024*(1 - 1.0e-12_dp), 'steps from '//str(h%step(smallest))//' to '// &
                 str(maxval(h%step(1:h%n)))//' s, dt '//str(dt)//' s')
      if (allocated(error)) return
      ! The step grows after its smallest value, and is dt again after a rejection.
      first_rejection = findloc(h%rejected(1:h%n) > 0, .true., 1)
      call check(error, smallest < h%n .and. maxval(h%step(smallest:h%n)) >= 1.99_dp*h%step(smallest) .and. &
                 maxval(h%step(first_rejection:h%n)) >= dt*(1 - 1.0e-12_dp), 'the step did not grow back (smallest '// &
                 str(h%step(smallest))//' s at step '//str(smallest)//', first rejection at step '// &
                 str(first_rejection)//')')
      if (allocated(error)) return
      call check(error, index(s%warnings, 'step attempts were rejected') > 0, 'no warning of the rejections: '//s%warnings)
      if (allocated(error)) return
      call check(error, s%energy_drift >= 0 .and. s%energy_drift < 3.0e-8_dp, 'ledger drift '//str(s%energy_drift))
   end subroutine test_rejections_off_plane

   !> Without rejections the step control changes nothing: the cross-current
   !> scene of cross_current run by the driver, against the bare stepper
   !> (rod3d_run%step) from the driver's static state with the driver's steps
   !> and times: positions, velocities, twist and ledger equal bit for bit.
   subroutine test_bare_stepper(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(rod3d_run) :: bare
      type(run_history), pointer :: h
      type(case_config) :: config
      integer :: unit, i
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') "&material compression = 'law' /"//new_line('a')//"&end_a kind = 'fixed', x = 0, z = 0 /"// &
         new_line('a')//"&end_b kind = 'motion', x = 50, z = 0, amplitude = 1, period = 2, direction_x = 0, direction_y = 1, "// &
         "direction_z = 0, ramp_time = 0.5 /"//new_line('a')// &
         "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.01, ca_normal = 1, current_y = 0.3 /"// &
         new_line('a')//"&rupture enabled = .false. /"//new_line('a')// &
         "&numerics nodes = 31, dt = 0.01, t_end = 1.0, newton_tol = 1e-10 /"//new_line('a')// &
         "&output interval = 0.5, energy = .true., quiet = .true. /"
      close (unit)
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      bare = sim%rod3%pieces(1)%run
      call sim%run(obs, error)
      if (allocated(error)) return
      h => sim%history()
      call check(error, sim%model == '3d' .and. sum(h%rejected(0:h%n)) == 0 .and. h%n == 100, 'model '//sim%model// &
                 ', '//str(h%n)//' steps, '//str(sum(h%rejected(0:h%n)))//' rejected')
      if (allocated(error)) return
      do i = 1, h%n
         bare%t = h%time(i - 1)
         call bare%step(h%step(i), 0.5_dp, error)
         if (allocated(error)) return
      end do
      associate (driven => sim%rod3%pieces(1)%run)
         write (output_unit, '(4x,a,2es9.2,a,es9.2)') 'driver against the bare stepper, 100 steps: largest '// &
            'difference of the unknowns, velocities ', maxval(abs(bare%x - driven%x)), maxval(abs(bare%v - driven%v)), &
            '; of the ledger ', abs(bare%imbalance() - driven%imbalance())
         call check(error, all(bare%x == driven%x) .and. all(bare%v == driven%v) .and. &
                    bare%imbalance() == driven%imbalance() .and. bare%iterations == driven%iterations, &
                    'the driver''s steps differ from the bare stepper''s')
      end associate
   end subroutine test_bare_stepper
   !> The scene of rejected_steps_planar_3d_equals_2d run on to 0.3 s: the
   !> compressed zone at the fixed end collapses (a cell below 5 % of its
   !> length) in 3-D as in 2-D, and the run stops with the step control's
   !> named error once the step is at its floor; the summary holds what was
   !> done (time reached = the last record; the failing attempts counted
   !> in the summary besides those in the history).
   subroutine test_collapse(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(error_type), allocatable :: run_error
      type(run_summary), pointer :: s
      type(run_history), pointer :: h
      call run_case("&cable bending_stiffness = 0.07056 /"//new_line('a')// &
                    "&static tension = 400000 /"//new_line('a')// &
                    "&rupture t_break = 0.005 /"//new_line('a')// &
                    "&output interval = 0.1, energy = .true., quiet = .true. /"//new_line('a')// &
                    "&numerics model = '3d', nodes = 121, courant = 10, t_end = 0.3 /", sim, obs, run_error)
      call check(error, allocated(run_error), 'the collapsing 3-D run did not stop')
      if (allocated(error)) return
      s => sim%summary()
      h => sim%history()
      write (output_unit, '(4x,a,f7.4,a,i0,a)') '3-D collapse stopped at t = ', s%time_reached, ' s after ', &
         s%rejected_steps, ' rejected attempts: '//run_error%message(1:min(80, len(run_error%message)))
      call check(error, index(run_error%message, 'step control: step fell below') == 1 .and. &
                 index(run_error%message, 'squeezed') > 0 .and. index(run_error%message, 'collapsed') > 0, &
                 'message: '//run_error%message)
      if (allocated(error)) return
      call check(error, s%time_reached < 0.3_dp .and. s%time_reached == h%time(h%n) .and. &
                 s%rejected_steps > sum(h%rejected(1:h%n)), 'time reached '//str(s%time_reached)//', last record '// &
                 str(h%time(h%n))//'; rejected '//str(s%rejected_steps)//', in the history '//str(sum(h%rejected(1:h%n))))
   end subroutine test_collapse

   !> The limits of the step control in 3-D: a wall-clock limit of 1 ns stops
   !> the off-plane slack release before t_end with the named error; with no
   !> room to halve (min_step_fraction = 1) its first failing step (Newton, at
   !> Courant 10 with EI / 1000) stops it with the step control's error.
   subroutine test_limits(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: scene = "&cable bending_stiffness = 0.07056 /"//new_line('a')// &
                                            "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                                            "&end_b kind = 'fixed', x = 40, y = 20, z = 0 /"//new_line('a')// &
                                            "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
                                            "&output interval = 0.1, energy = .true., quiet = .true. /"//new_line('a')
      type(simulation) :: sim_wall, sim_floor
      type(keeper) :: obs
      type(error_type), allocatable :: run_error
      type(run_summary), pointer :: s
      call run_case(scene//"&numerics model = '3d', nodes = 121, courant = 10, t_end = 2.0, max_wall_time = 1e-9 /", &
                    sim_wall, obs, &
                    run_error)
      call check(error, allocated(run_error), 'a 1 ns wall-clock limit did not stop the 3-D run')
      if (allocated(error)) return
      s => sim_wall%summary()
      call check(error, index(run_error%message, 'wall-clock limit') == 1 .and. s%time_reached < 2.0_dp, &
                 'message: '//run_error%message//'; time reached '//str(s%time_reached))
      if (allocated(error)) return
      deallocate (run_error)
      obs = keeper()
      call run_case(scene//"&numerics model = '3d', nodes = 121, courant = 10, t_end = 2.0, min_step_fraction = 1 /", &
                    sim_floor, obs, &
                    run_error)
      call check(error, allocated(run_error), 'the 3-D run did not stop without room to halve the step')
      if (allocated(error)) return
      s => sim_floor%summary()
      write (output_unit, '(4x,a,f7.4,a)') 'min_step_fraction = 1: stopped at t = ', s%time_reached, ' s: '// &
         run_error%message(1:min(90, len(run_error%message)))
      call check(error, index(run_error%message, 'step control: step fell below') == 1 .and. &
                 index(run_error%message, 'Newton') > 0 .and. s%time_reached < 2.0_dp .and. s%rejected_steps == 1, &
                 'message: '//run_error%message//'; time reached '//str(s%time_reached)//', rejected '// &
                 str(s%rejected_steps))
   end subroutine test_limits

   !> The 3-D statics under a strong cross current (issue 15): the line of
   !> bench/peer/sway3d.py (the paper's cable in sea water, end b at (48, 0,
   !> 24) m) in 2 m/s along y, compression = 'law'. On 61 nodes Newton from
   !> the planar guess lands in a folded state (cells turning back by 2.78
   !> rad, the ends at -24 kN and +24 kN) that was reported as a complete run;
   !> now that state is refused and the continuation in the loads finds the
   !> unfolded one. Checked: every turning angle of the static state (from the
   !> output's x, y, z) below 1 rad, and the end tensions of 61 nodes against
   !> those of 121 within a bound from refinement, 8 |T(121) - T(241)|
   !> (second order gives 4; measured 61-121 / 121-241: about 4). With the
   !> fold check left out (check_static3 not called after the direct solve)
   !> this test fails.
   subroutine test_statics_strong_current(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: grids(3) = [61, 121, 241]
      real(dp) :: tension(2, 3), worst, a(3), b(3), th, d61, d121
      type(keeper) :: obs
      integer :: g, k, n
      do g = 1, 3
         block
            type(simulation) :: sim
            obs = keeper()
            call run_case(sway_scene(2.0_dp, 'law')//"&numerics model = '3d', nodes = "//str(grids(g))// &
                          ", dt = 0.001, t_end = 0.001 /", sim, obs, error)
            if (allocated(error)) return
         end block
         tension(:, g) = obs%static_tension
         if (g == 1) then
            n = size(obs%static_fields, 1)
            worst = 0
            do k = 2, n - 1
               a = [obs%static_fields(k, 6) - obs%static_fields(k - 1, 6), &
                    obs%static_extra(k, 1) - obs%static_extra(k - 1, 1), &
                    obs%static_fields(k, 7) - obs%static_fields(k - 1, 7)]
               b = [obs%static_fields(k + 1, 6) - obs%static_fields(k, 6), &
                    obs%static_extra(k + 1, 1) - obs%static_extra(k, 1), &
                    obs%static_fields(k + 1, 7) - obs%static_fields(k, 7)]
               th = acos(max(-1.0_dp, min(1.0_dp, dot_product(a, b)/(norm2(a)*norm2(b)))))
               worst = max(worst, th)
            end do
         end if
      end do
      d61 = maxval(abs(tension(:, 1) - tension(:, 2)))
      d121 = maxval(abs(tension(:, 2) - tension(:, 3)))
      write (output_unit, '(4x,a,f7.4,a,2f10.3,a,2f10.3,a,es9.2,a,es9.2,a)') '2 m/s cross current, 61 nodes: '// &
         'largest turning ', worst, ' rad; end tensions ', tension(:, 1), ' N (121 nodes: ', tension(:, 2), &
         '); |61 - 121| ', d61, ' N, |121 - 241| ', d121, ' N'
      call check(error, worst < 1.0_dp, 'the 61-node static state turns by '//str(worst)//' rad between cells')
      if (allocated(error)) return
      call check(error, d121 > 0 .and. d61 <= 8*d121, 'end tensions on 61 nodes '//str(tension(1, 1))//', '// &
                 str(tension(2, 1))//' N differ from 121 nodes by '//str(d61)//' N, more than 8 times the '// &
                 '121-241 difference '//str(d121)//' N')
   end subroutine test_statics_strong_current

   !> A 3-D static state the statics cannot find is refused. The scene: the line of
   !> statics_strong_cross_current held at end a, pulled at end b by 1 kN along x, in still
   !> water, prepared in 2-D; its planar static state is then replaced by a guess with every node
   !> at end a (cells of zero length), from which the 3-D statics is started. Newton fails, and the
   !> continuation in the fluid's loads cannot help: the preparation returns stat_numerics, the
   !> message naming the direct failure, the share of the loads reached and 'no static state found'.
   !> With continue_statics' final error left out (the run would start from the unsolved guess)
   !> this test fails. (Until version 0.6 the scene itself, pulled by 1 kN along x and 10 kN along
   !> y, was refused: its 3-D statics started from the scene's shadow on x-z. Turned onto the
   !> plane of its end force, it is solved, and equals its planar twin: test
   !> spring_and_loaded_ends_off_the_plane_equal_planar_twin.)
   subroutine test_statics_refused(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(case_config) :: config
      type(error_type), allocatable :: run_error
      integer :: unit
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') "&material compression = 'law' /"//new_line('a')// &
         "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1 /"//new_line('a')// &
         "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
         "&end_b kind = 'force', force_x = 1000 /"//new_line('a')// &
         "&rupture enabled = .false. /"//new_line('a')// &
         "&output interval = 0, quiet = .true. /"//new_line('a')// &
         "&numerics model = '2d', nodes = 61, dt = 0.001, t_end = 0.001 /"
      close (unit)
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      sim%rod%static%r(1, :) = 0
      sim%rod%static%r(2, :) = 0
      call sim%rod3%prepare(sim%rod, run_error)
      call check(error, allocated(run_error), 'a 3-D statics without a solution was accepted')
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'refused: '//run_error%message(1:min(110, len(run_error%message)))
      call check(error, run_error%stat == stat_numerics .and. index(run_error%message, '3-D statics: ') > 0 .and. &
                 index(run_error%message, 'no static state found') > 0, 'stat '// &
                 str(run_error%stat)//', message: '//run_error%message)
   end subroutine test_statics_refused

   !> The planar statics has the same weakness (issue 15): the line of
   !> statics_strong_cross_current in 2 m/s along -x (in its plane, towards
   !> end a) on 31 nodes, model = '2d', compression = 'law': Newton (and the
   !> continuation in the loads) used to end in a folded state (cells turning
   !> back by 2.56 rad, a compressed cell at -387 N) reported as a complete
   !> run. The folded state is refused at every step of the continuation,
   !> which stalls (at 11 % of the loads); until the relaxation (rod_statics,
   !> docs/theory/numerics.md) the run then stopped, naming the fold. Now the
   !> relaxation from the catenary under the mean load finds the unfolded
   !> state: the bow of the current (turning -1.89 rad in all, the largest
   !> turn between cells 0.31 rad). With the planar fold check left out
   !> (rod_statics, check_fold) the folded state is taken and this test fails.
   subroutine test_statics_planar_fold(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(error_type), allocatable :: run_error
      character(:), allocatable :: scene
      real(dp) :: a(2), b(2), th, worst, turning
      integer :: k
      scene = sway_scene(0.0_dp, 'law')
      scene = scene(1:index(scene, 'current_y') - 1)//'current_x = -2'//scene(index(scene, ' /'//new_line('a')// &
                                                                               '&end_a'):)
      call run_case(scene//"&numerics model = '2d', nodes = 31, dt = 0.001, t_end = 0.001 /", sim, obs, run_error)
      call check(error, .not. allocated(run_error), 'the planar statics failed')
      if (allocated(error)) then
         error%message = error%message//': '//run_error%message
         return
      end if
      worst = 0
      turning = 0
      associate (r => sim%rod%static%r)
         do k = 2, size(r, 2) - 1
            a = r(:, k) - r(:, k - 1)
            b = r(:, k + 1) - r(:, k)
            th = atan2(a(1)*b(2) - a(2)*b(1), dot_product(a, b))
            worst = max(worst, abs(th))
            turning = turning + th
         end do
      end associate
      write (output_unit, '(4x,a,f8.4,a,f8.4,a)') 'planar statics, 2 m/s towards end a: largest turn ', worst, &
         ' rad, turning in all ', turning, ' rad'
      call check(error, worst < 0.5_dp*acos(-1.0_dp), 'a folded planar static state was taken (turn '//str(worst)//' rad)')
      if (allocated(error)) return
      call check(error, turning > -2.1_dp .and. turning < -1.7_dp, 'not the bow of the current: turning '//str(turning))
   end subroutine test_statics_planar_fold

   !> The scene of bench/peer/sway3d.py with a current of u m/s along y and the given compression.
   function sway_scene(u, compression) result(text)
      real(dp), intent(in) :: u
      character(*), intent(in) :: compression
      character(:), allocatable :: text
      text = "&cable length = 60, diameter = 0.05, density = 1140 /"//new_line('a')// &
             "&material law = 'linear', ea = 451603.943953533, compression = '"//compression//"' /"//new_line('a')// &
             "&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1, surface_z = 100, "// &
             "current_y = "//str(u)//" /"//new_line('a')//"&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
             "&end_b kind = 'fixed', x = 48, z = 24 /"//new_line('a')//"&rupture enabled = .false. /"//new_line('a')// &
             "&output interval = 0, quiet = .true. /"//new_line('a')
   end function sway_scene

   !> End b moved across the plane (direction (0.3, 1, 0.2), amplitude 1 m,
   !> period 2 s, no smooth start; dry line, 31 nodes, dt 10 ms, to 0.8 s),
   !> once as the harmonic motion and three times as a 'table' motion whose
   !> rows (every h = 4, 2, 1 ms, from 0.37 h before 0 so that no row falls
   !> on a step's time, to 0.9 s) sample the same displacement, written here
   !> from its formula a d sin(2 pi t / T). Positions x, y, z of every node and
   !> snapshot and end b's y in the history differ by the table's
   !> interpolation error: the centred slopes, hence the end's velocity, are
   !> O(h^2) off, and the positions follow at second order (ratios 4.1, 4.0
   !> measured; 2.7e-8 m at h = 1 ms). End b's vy (5.8e-7 of its largest at
   !> h = 1 ms) is bounded at the finest table only.
   subroutine test_table_y_motion(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp), a = 1, period = 2, tr = 0.5_dp
      character(len=*), parameter :: common = "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                                              "&rupture enabled = .false. /"//new_line('a')// &
                                              "&numerics nodes = 31, dt = 0.01, t_end = 0.8, newton_tol = 1e-12 /"// &
                                              new_line('a')//"&output interval = 0.2, quiet = .true. /"
      type(simulation) :: sim0, sim
      type(keeper) :: obs0
      type(run_history), pointer :: h0, h
      real(dp) :: d(3), step, diff(3), vdiff(3)
      real(dp), allocatable :: t(:), disp(:)
      integer :: k, rows, m
      d = [0.3_dp, 1.0_dp, 0.2_dp]
      d = d/norm2(d)
      call run_case(common//new_line('a')//"&end_b kind = 'motion', x = 50, z = 0, amplitude = 1, period = 2, "// &
                    "direction_x = 0.3, direction_y = 1, direction_z = 0.2 /", sim0, obs0, error)
      if (allocated(error)) return
      h0 => sim0%history()
      do m = 1, 3
         block
            type(keeper) :: obs
            step = 0.004_dp/2**(m - 1)
            ! Rows off the steps' times (every 10 ms), from 0.37 h before the start.
            rows = nint(0.9_dp/step) + 1
            t = [(step*(k - 1.37_dp), k=1, rows)]
            disp = a*sin(2*pi*t/period)
            call run_case(common//new_line('a')//"&end_b kind = 'motion', motion = 'table', x = 50, z = 0,"// &
                          new_line('a')//column_text('table_time', t)//new_line('a')// &
                          column_text('table_x', d(1)*disp)//new_line('a')// &
                          column_text('table_y', d(2)*disp)//new_line('a')// &
                          column_text('table_z', d(3)*disp)//' /', sim, obs, error)
            if (allocated(error)) return
            call check(error, sim%model == '3d' .and. obs%n == obs0%n .and. obs%n == 5, 'model '//sim%model// &
                       ', snapshots '//str(obs%n)//' against '//str(obs0%n))
            if (allocated(error)) return
            h => sim%history()
            diff(m) = max(maxval(abs(obs%fields(:, 6:7, :) - obs0%fields(:, 6:7, :))), &
                          maxval(abs(obs%extra(:, 1, :) - obs0%extra(:, 1, :))), &
                          maxval(abs(h%ends_y(1, 2, 0:h%n) - h0%ends_y(1, 2, 0:h0%n))))/a
            vdiff(m) = maxval(abs(h%ends_y(2, 2, 0:h%n) - h0%ends_y(2, 2, 0:h0%n)))/maxval(abs(h0%ends_y(2, 2, 0:h0%n)))
         end block
      end do
      write (output_unit, '(4x,a,3es9.2,a,3es9.2,a)') 'table motion against harmonic (h = 4, 2, 1 ms): positions ', &
         diff, ' m; end b vy ', vdiff, ' of its largest'
      call check(error, maxval(abs(h0%ends_y(1, 2, 0:h0%n))) > 0.5_dp*d(2), 'end b did not move across the plane')
      if (allocated(error)) return
      call check(error, diff(3) < 1.0e-7_dp .and. vdiff(3) < 3.0e-6_dp, 'table against harmonic at h = 1 ms: '// &
                 str(diff(3))//' m, vy '//str(vdiff(3)))
      if (allocated(error)) return
      call check(error, all(diff(1:2)/diff(2:3) > 3.0_dp .and. diff(1:2)/diff(2:3) < 5.5_dp), &
                 'refinement ratios of the positions '//str(diff(1)/diff(2))//', '//str(diff(2)/diff(3)))
   end subroutine test_table_y_motion

   !> table_y in the input: a non-zero entry makes 'auto' pick 3-D and is
   !> refused by '2d' (naming the entry); all zero keeps a planar scene 2-D;
   !> a 4-column table_file is read as t, x, y, z and a 3-column one as t, x,
   !> z; a force table's y column is the 3-D end force's y component.
   subroutine test_table_y_input(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: base = "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                                            "&rupture enabled = .false. /"//new_line('a')// &
                                            "&output quiet = .true. /"//new_line('a')
      character(len=*), parameter :: motion = "&end_b kind = 'motion', motion = 'table', x = 50, z = 0, "// &
                                              "table_time = 0, 1, 2, table_x = 0, 0.1, 0.2, table_z = 0, 0, 0.3, table_y = "
      character(len=*), parameter :: file = 'build/test_table4.dat'
      character(:), allocatable :: message
      type(case_config) :: config
      integer :: unit
      call read_text(base//motion//'0, 0, 0 /', config, error)
      if (allocated(error)) return
      call check(error, config%model_to_run() == '2d', "table_y all zero: 'auto' ran "//config%model_to_run())
      if (allocated(error)) return
      call read_text(base//motion//'0, 0.5, 0 /', config, error)
      if (allocated(error)) return
      call check(error, config%model_to_run() == '3d', "table_y(2) = 0.5: 'auto' ran "//config%model_to_run())
      if (allocated(error)) return
      call read_text(base//"&numerics model = '2d' /"//new_line('a')//motion//'0, 0.5, 0 /', config, error)
      message = 'none'
      if (allocated(error)) message = error%message
      call check(error, index(message, "&end_b table_y(2) = 0.5") > 0 .and. index(message, 'x-z plane') > 0, &
                 "table_y(2) = 0.5 with model = '2d': refusal "//message)
      if (allocated(error)) return
      open (newunit=unit, file=file, status='replace', action='write')
      write (unit, '(a)') '# t x y z', '0 0 0 0', '1 0.1 0.7 0.2', '2 0.3 0.8 0.4'
      close (unit)
      call read_text(base//"&end_b kind = 'force', history = 'table', table_file = '"//file//"' /", config, error)
      if (allocated(error)) return
      associate (e => config%end_b)
         call check(error, e%table_rows == 3 .and. all(e%table_time(1:3) == [0, 1, 2]) .and. &
                    all(e%table_x(1:3) == [0.0_dp, 0.1_dp, 0.3_dp]) .and. all(e%table_y(1:3) == [0.0_dp, 0.7_dp, 0.8_dp]) &
                    .and. all(e%table_z(1:3) == [0.0_dp, 0.2_dp, 0.4_dp]) .and. config%model_to_run() == '3d', &
                    '4-column file: rows '//str(e%table_rows)//', y '//str(e%table_y(2))//', z '//str(e%table_z(2)))
      end associate
      if (allocated(error)) return
      block
         class(end_condition), allocatable :: end
         real(dp) :: f(3)
         call new_end(config%end_b, 'end_b', end, error)
         if (allocated(error)) return
         f = end%applied_force3(1.5_dp)
         call check(error, all(abs(f - [0.2_dp, 0.75_dp, 0.3_dp]) < 1.0e-15_dp), 'force table at 1.5 s: '// &
                    str(f(1))//', '//str(f(2))//', '//str(f(3)))
         if (allocated(error)) return
      end block
      open (newunit=unit, file=file, status='replace', action='write')
      write (unit, '(a)') '0 0 0', '1 0.1 0.2'
      close (unit)
      call read_text(base//"&end_b kind = 'force', history = 'table', table_file = '"//file//"' /", config, error)
      if (allocated(error)) return
      call check(error, all(config%end_b%table_z(1:2) == [0.0_dp, 0.2_dp]) .and. &
                 all(config%end_b%table_y(1:2) == 0) .and. config%model_to_run() == '2d', '3-column file: z '// &
                 str(config%end_b%table_z(2))//', y '//str(config%end_b%table_y(2)))
   end subroutine test_table_y_input

   !> The summary's dissipated energy of a 3-D run (issue 37): the paper's
   !> cable at 315 kN parted in the middle (s = 30 m, 5 ms ramp), internal
   !> damping 2000 N s, theta 0.55, the default tension-only law (the slack
   !> cells' dissipation), 41 nodes to 0.05 s, run with model = '2d' and
   !> '3d'. Both report the same dissipation, summed over the two pieces in
   !> 3-D, to 5e-14 of it (measured 9.4e-15), and each equals the
   !> last entry of its ledger's dissipation column.
   subroutine test_dissipated_summary(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: scene = &
         "&material damping = 2000 /"//new_line('a')// &
         "&static tension = 315000 /"//new_line('a')// &
         "&rupture s_break = 30.0, t_break = 0.005 /"//new_line('a')// &
         "&output interval = 0.01, energy = .true., quiet = .true. /"
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      type(run_history), pointer :: h2, h3
      type(run_summary), pointer :: s2, s3
      real(dp) :: d, booked
      call run_pair(scene, "theta = 0.55, nodes = 41, t_end = 0.05, newton_tol = 1e-12 /", sim2, obs2, sim3, obs3, error)
      if (allocated(error)) return
      h2 => sim2%history()
      h3 => sim3%history()
      s2 => sim2%summary()
      s3 => sim3%summary()
      call check(error, size(sim3%rod3%pieces) == 2, 'pieces at the end in 3-D: '//str(size(sim3%rod3%pieces)))
      if (allocated(error)) return
      d = abs(s3%dissipated - s2%dissipated)/abs(s2%dissipated)
      booked = max(abs(s2%dissipated - h2%energy(6, h2%n)), abs(s3%dissipated - h3%energy(6, h3%n)))/abs(s2%dissipated)
      write (output_unit, '(4x,a,es12.5,a,es12.5,a,es9.2,a,es9.2)') 'damped break inside: dissipated ', s2%dissipated, &
         ' J (2-D), ', s3%dissipated, ' J (3-D), relative difference ', d, '; summary vs ledger ', booked
      call check(error, s2%dissipated > 1, 'the planar run dissipated only '//str(s2%dissipated)//' J')
      if (allocated(error)) return
      call check(error, booked < 1.0e-14_dp, 'the summary''s dissipation differs from the ledger''s by '//str(booked))
      if (allocated(error)) return
      call check(error, d < 5.0e-14_dp, 'the 3-D run reports '//str(s3%dissipated)//' J dissipated, the 2-D run '// &
                 str(s2%dissipated)//' J')
   end subroutine test_dissipated_summary

   !> Write a namelist and read it.
   subroutine read_text(text, config, error)
      character(*), intent(in) :: text
      type(case_config), intent(out) :: config
      type(error_type), allocatable, intent(out) :: error
      integer :: unit
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') pushing_rope(text)
      close (unit)
      call read_config(path, config, error)
   end subroutine read_text

   !> How far a 3-D run (obs3) of a scene turned by angle (rad) about the vertical through the
   !> origin is from its planar twin (obs2): the largest difference of the tension over the largest
   !> tension, and of the positions (m) turned back into x-z (fields 1: tension; 6, 7: x, z; extra 1: y).
   subroutine twin_difference(obs2, obs3, angle, tension_err, position_err)
      type(keeper), intent(in) :: obs2, obs3
      real(dp), intent(in) :: angle
      real(dp), intent(out) :: tension_err, position_err
      real(dp) :: ca, sa
      ca = cos(angle)
      sa = sin(angle)
      tension_err = maxval(abs(obs3%fields(:, 1, 1:obs3%n) - obs2%fields(:, 1, 1:obs2%n)))/ &
                    maxval(abs(obs2%fields(:, 1, 1:obs2%n)))
      position_err = max(maxval(abs(ca*obs3%fields(:, 6, 1:obs3%n) + sa*obs3%extra(:, 1, 1:obs3%n) - &
                                    obs2%fields(:, 6, 1:obs2%n))), &
                         maxval(abs(-sa*obs3%fields(:, 6, 1:obs3%n) + ca*obs3%extra(:, 1, 1:obs3%n))), &
                         maxval(abs(obs3%fields(:, 7, 1:obs3%n) - obs2%fields(:, 7, 1:obs2%n))))
   end subroutine twin_difference

   !> The paper's fast 180 kN break between supports 70.658 m apart, with the chord along x (the
   !> planar model) and turned about the vertical by 30, 135, 210 and -30 degrees (the 3-D model):
   !> the 3-D run is prepared from its own chord, so it takes the planar twin's time step and
   !> Courant number, and its tension and positions (turned back) are the twin's. Before, it was
   !> prepared from the scene's shadow on x-z: a shorter span, a slack line, a 3.2 times longer
   !> step.
   subroutine test_turned_twin(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: span = 70.658_dp, angles(4) = [30.0_dp, 135.0_dp, 210.0_dp, -30.0_dp]
      character(*), parameter :: rest = "&rupture t_break = 0.005 /"//new_line('a')// &
                                        "&output interval = 0.005, quiet = .true. /"//new_line('a')
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      real(dp) :: a, ca, sa, dt2, dt3, tension_err, position_err, worst_t, worst_x
      integer :: k, k_steps
      character(len=40) :: xb, yb
      call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')//"&end_b kind = 'fixed', x = 70.658, z = 0 /"// &
                    new_line('a')//"&numerics model = '2d', nodes = 61, courant = 1.0, t_end = 0.02, newton_tol = 1e-10 /"// &
                    new_line('a')//rest, sim2, obs2, error)
      if (allocated(error)) return
      worst_t = 0
      worst_x = 0
      do k = 1, size(angles)
         a = angles(k)*acos(-1.0_dp)/180
         ca = cos(a)
         sa = sin(a)
         write (xb, '(es24.17)') span*ca
         write (yb, '(es24.17)') span*sa
         obs3 = keeper()
         call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')//"&end_b kind = 'fixed', x = "// &
                       trim(adjustl(xb))//", y = "//trim(adjustl(yb))//", z = 0 /"//new_line('a')// &
                       "&numerics model = '3d', nodes = 61, courant = 1.0, t_end = 0.02, newton_tol = 1e-10 /"// &
                       new_line('a')//rest, sim3, obs3, error)
         if (allocated(error)) return
         call sim2%time_step(dt2, k_steps)
         call sim3%time_step(dt3, k_steps)
         call check(error, dt3 == dt2 .and. sim3%rod%summary%courant_requested == sim2%rod%summary%courant_requested, &
                    'turned by '//str(angles(k))//' degrees: time step '//str(dt3)//' s, the planar twin '//str(dt2))
         if (allocated(error)) return
         call check(error, obs3%n == obs2%n, 'turned by '//str(angles(k))//' degrees: another number of snapshots')
         if (allocated(error)) return
         call twin_difference(obs2, obs3, a, tension_err, position_err)
         worst_t = max(worst_t, tension_err)
         worst_x = max(worst_x, position_err)
      end do
      write (output_unit, '(4x,a,es10.3,a,es10.3,a)') 'chord turned by 30, 135, 210, -30 degrees: tension ', worst_t, &
         ' of the largest, positions ', worst_x, ' m from the planar twin, the same time step'
      ! Measured 4.5e-13 and 3.9e-13 m (Newton to 1e-10); the issue asks for 1e-8 and 1e-6 m.
      call check(error, worst_t < 5.0e-12_dp .and. worst_x < 5.0e-12_dp, 'the turned runs differ from the planar twin: '// &
                 'tension '//str(worst_t)//', positions '//str(worst_x)//' m')
   end subroutine test_turned_twin
   !> Scenes whose second end is not held, turned out of the x-z plane: a spring end whose anchor
   !> lies at 45 degrees (x = y = 20 m) and a force end pulled by (300, 400, 0) N, against their
   !> planar twins (anchor at 28.28 m on x; force 500 N along x), a 30 m line on 61 nodes hanging
   !> from end a. The 3-D run is prepared from the scene turned onto the plane of the anchor or
   !> the force (driver/simulation.f90, chord_azimuth): the same step as the twin, and tensions and
   !> positions equal to it. Before, the preparation took the scene's shadow on x-z: the spring
   !> scene's 3-D statics failed (update not finite), the force scene's step came from a 300 N pull.
   subroutine test_turned_state_ends(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: head = "&cable length = 30, diameter = 0.05 /"//new_line('a')// &
                                        "&end_a kind = 'fixed', x = 0, y = 0, z = 0 /"//new_line('a'), &
                                 tail = new_line('a')//"nodes = 61, t_end = 0.1, newton_tol = 1e-10 /"//new_line('a')// &
                                        "&output interval = 0.01, quiet = .true. /"//new_line('a')
      character(len=120) :: ends3(2), ends2(2)
      real(dp) :: angles(2), a, ca, sa, dt2, dt3, tension_err, position_err, worst_t, worst_x
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      integer :: k, k_steps
      ends3(1) = "&end_b kind = 'spring', x = 20, y = 20, z = 0, stiffness = 2000 /"
      ends2(1) = "&end_b kind = 'spring', x = 28.284271247461902, z = 0, stiffness = 2000 /"
      ends3(2) = "&end_b kind = 'force', force_x = 300, force_y = 400, force_z = 0 /"
      ends2(2) = "&end_b kind = 'force', force_x = 500, force_z = 0 /"
      angles = [45.0_dp, atan2(400.0_dp, 300.0_dp)*180/acos(-1.0_dp)]
      worst_t = 0
      worst_x = 0
      do k = 1, 2
         obs2 = keeper()
         obs3 = keeper()
         call run_case(head//trim(ends2(k))//new_line('a')//"&numerics model = '2d',"//tail, sim2, obs2, error)
         if (allocated(error)) return
         call run_case(head//trim(ends3(k))//new_line('a')//"&numerics model = '3d',"//tail, sim3, obs3, error)
         if (allocated(error)) return
         call sim2%time_step(dt2, k_steps)
         call sim3%time_step(dt3, k_steps)
         call check(error, dt3 == dt2, trim(ends3(k))//': time step '//str(dt3)//' s, the planar twin '//str(dt2))
         if (allocated(error)) return
         call check(error, obs3%n == obs2%n, trim(ends3(k))//': another number of snapshots')
         if (allocated(error)) return
         call twin_difference(obs2, obs3, angles(k)*acos(-1.0_dp)/180, tension_err, position_err)
         worst_t = max(worst_t, tension_err)
         worst_x = max(worst_x, position_err)
      end do
      write (output_unit, '(4x,a,es10.3,a,es10.3,a)') 'spring anchor and end force off the plane: tension ', worst_t, &
         ' of the largest, positions ', worst_x, ' m from the planar twins, the same time step'
      ! Measured 2.8e-11 of the largest tension and 2.5e-13 m (Newton to 1e-10).
      call check(error, worst_t < 1.0e-10_dp .and. worst_x < 1.0e-12_dp, 'the turned runs differ from the planar twins: '// &
                 'tension '//str(worst_t)//', positions '//str(worst_x)//' m')
   end subroutine test_turned_state_ends
   !> model = 'auto' on a scene in a vertical plane other than x-z: a 40 m slack line between
   !> ends 38 m apart with a 5 m drop, end b let go over 10 ms, its chord turned by 60, 150 and
   !> -100 degrees about end a. It runs in 2-D (sim%model) on the scene turned into x-z, and its
   !> results, turned back, are its x-z twin's: the same step, tension, x and y the twin's x turned
   !> (cos, sin), z the same, vy the twin's vx turned, the end histories too; the other 3-D fields
   !> are zero. Measured: no difference at all (the turned end b's x is 38 exactly at these
   !> angles); 1e-12 (of the largest tension; m) leaves room for the round-off of other turns.
   !> (Mutation: the history not turned back, caught.)
   subroutine test_auto_turned(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: angles(3) = [60.0_dp, 150.0_dp, -100.0_dp]
      character(*), parameter :: rest = "&rupture s_break = 40, time = 0, t_break = 0.01 /"//new_line('a')// &
                                        "&numerics nodes = 41, t_end = 0.1, newton_tol = 1e-10 /"//new_line('a')// &
                                        "&output interval = 0.01, quiet = .true. /"//new_line('a')// &
                                        "&cable length = 40 /"//new_line('a')//"&material compression = 'none' /"
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      type(run_history), pointer :: h2, h3
      real(dp) :: a, ca, sa, dt2, dt3, tension_err, position_err, worst_t, worst_x, others
      integer :: k, k_steps, j
      character(len=40) :: xb, yb
      call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')//"&end_b kind = 'fixed', x = 38, z = -5 /"// &
                    new_line('a')//rest, sim2, obs2, error)
      if (allocated(error)) return
      worst_t = 0
      worst_x = 0
      others = 0
      do k = 1, size(angles)
         a = angles(k)*acos(-1.0_dp)/180
         ca = cos(a)
         sa = sin(a)
         write (xb, '(es24.17)') 38*ca
         write (yb, '(es24.17)') 38*sa
         obs3 = keeper()
         call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')//"&end_b kind = 'fixed', x = "// &
                       trim(adjustl(xb))//", y = "//trim(adjustl(yb))//", z = -5 /"//new_line('a')//rest, sim3, obs3, error)
         if (allocated(error)) return
         call check(error, sim3%model == '2d' .and. sim3%three_d_output(), 'turned by '//str(angles(k))// &
                    ' degrees: model '//sim3%model//' (2d expected, with the 3-D layout of the output)')
         if (allocated(error)) return
         call sim2%time_step(dt2, k_steps)
         call sim3%time_step(dt3, k_steps)
         call check(error, dt3 == dt2 .and. obs3%n == obs2%n .and. obs3%n_extra == obs3%n, 'turned by '// &
                    str(angles(k))//' degrees: time step '//str(dt3)//' s (twin '//str(dt2)//'), '//str(obs3%n)// &
                    ' snapshots with '//str(obs3%n_extra)//' sets of 3-D fields (twin '//str(obs2%n)//')')
         if (allocated(error)) return
         tension_err = maxval(abs(obs3%fields(:, 1, 1:obs3%n) - obs2%fields(:, 1, 1:obs2%n)))/ &
                       maxval(abs(obs2%fields(:, 1, 1:obs2%n)))
         ! Fields 6, 7: x, z; extra 1, 2: y, vy; the twin's snapshots in x-z turned by the angle.
         position_err = max(maxval(abs(obs3%fields(:, 6, 1:obs3%n) - ca*obs2%fields(:, 6, 1:obs2%n))), &
                            maxval(abs(obs3%extra(:, 1, 1:obs3%n) - sa*obs2%fields(:, 6, 1:obs2%n))), &
                            maxval(abs(obs3%fields(:, 7, 1:obs3%n) - obs2%fields(:, 7, 1:obs2%n))))
         others = max(others, maxval(abs(obs3%extra(:, 3:, 1:obs3%n))))
         ! The ends' histories: x, vx, force_x turned, and their y components.
         h2 => sim2%history()
         h3 => sim3%history()
         call check(error, allocated(h3%ends_y), 'turned by '//str(angles(k))//' degrees: no y components in the history')
         if (allocated(error)) return
         do j = 0, h2%n
            position_err = max(position_err, maxval(abs(h3%ends(1, :, j) - ca*h2%ends(1, :, j))), &
                               maxval(abs(h3%ends_y(1, :, j) - sa*h2%ends(1, :, j))), &
                               maxval(abs(h3%ends_y(2, :, j) - sa*h2%ends(3, :, j)))*dt2, &
                               maxval(abs(h3%ends(2, :, j) - h2%ends(2, :, j))))
            tension_err = max(tension_err, maxval(abs(h3%ends_y(3, :, j) - sa*h2%ends(6, :, j)))/ &
                              maxval(abs(obs2%fields(:, 1, 1:obs2%n))))
         end do
         worst_t = max(worst_t, tension_err)
         worst_x = max(worst_x, position_err)
      end do
      write (output_unit, '(4x,a,es10.3,a,es10.3,a,es10.3)') 'auto, plane turned by 60, 150, -100 degrees, run in 2-D: '// &
         'tension ', worst_t, ' of the largest, positions ', worst_x, ' m from the twin; other 3-D fields ', others
      call check(error, worst_t < 1.0e-12_dp .and. worst_x < 1.0e-12_dp .and. others == 0, &
                 'the turned 2-D runs differ from the x-z twin: tension '//str(worst_t)//', positions '// &
                 str(worst_x)//' m, other 3-D fields '//str(others))
   end subroutine test_auto_turned
   !> The time step of a 3-D run comes from its own static state: a 60 m line between two fixed
   !> points 55 m apart in a current of 2 m/s across its plane (tanh law, 61 nodes, Courant 1).
   !> The current strains it to 0.022 (0.001 without): its axial waves are 1.23 times faster than
   !> the planar preparation's, whose step was taken before (Courant 1.23, reported as 1). Here
   !> dt c_max / ds, with c_max from the 3-D static cells' strains computed anew, is the Courant
   !> number asked for and reported: measured 1 exactly. (Mutation: the step of the planar
   !> preparation kept, caught: 1.228.)
   subroutine test_step_from_static3(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      real(dp) :: dt, c_max, courant, l
      integer :: k, steps, n
      call run_case("&fluid density = 1025, cd_normal = 1.2, cd_tangential = 0.008, ca_normal = 1, current_y = 2 /"// &
                    new_line('a')//"&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 55, z = 0 /"//new_line('a')//"&rupture enabled = .false. /"// &
                    new_line('a')//"&material compression = 'none' /"//new_line('a')// &
                    "&numerics model = '3d', nodes = 61, t_end = 0.01 /"//new_line('a')// &
                    "&output interval = 0.01, quiet = .true. /", sim, obs, error)
      if (allocated(error)) return
      call sim%time_step(dt, steps)
      n = 61
      c_max = 0
      associate (piece => sim%rod3%pieces(1)%run%problem%piece)
         ! The static state: the snapshot at t = 0.
         do k = 1, n - 1
            l = hypot(hypot(obs%fields(k + 1, 6, 1) - obs%fields(k, 6, 1), obs%extra(k + 1, 1, 1) - obs%extra(k, 1, 1)), &
                      obs%fields(k + 1, 7, 1) - obs%fields(k, 7, 1))/piece%ds(k)
            c_max = max(c_max, sqrt(piece%law%stiffness(l - 1)/piece%mass_per_length))
         end do
         courant = dt*c_max/maxval(piece%ds)
      end associate
      write (output_unit, '(4x,a,es10.3,a,es22.15,a,es22.15)') '3-D line in a cross current: dt ', dt, ' s, Courant of the '// &
         '3-D static state ', courant, ', reported ', sim%rod%summary%courant_requested
      call check(error, abs(courant - 1) < 1.0e-12_dp .and. abs(sim%rod%summary%courant_requested - 1) < 1.0e-12_dp, &
                 'the step '//str(dt)//' s has Courant '//str(courant)//' on the 3-D static state, reported '// &
                 str(sim%rod%summary%courant_requested))
   end subroutine test_step_from_static3
end module suite_model3d
