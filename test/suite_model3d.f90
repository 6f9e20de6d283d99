!> The 3-D model through the program's driver (driver/simulation.f90,
!> driver/rod3d_drive.f90), from namelists: &numerics model = '3d' on a
!> planar scene gives the 2-D run's snapshots, history and summary; 'auto'
!> picks 2-D for a planar scene and 3-D otherwise; non-planar scenes (end b
!> off the plane, released; a cross current) run to t_end with a closed
!> energy ledger.
module suite_model3d
   use xcable_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_strings, only: str
   use xcable_io_input, only: read_config
   use xcable_io_config, only: case_config
   use xcable_simulation, only: simulation
   use xcable_run_records, only: run_observer, static_info, run_history, run_summary, n_fields, field_names
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_model3d

   character(len=*), parameter :: path = 'build/test_model3d.nml'

   !> Keeps every snapshot, and the extra (3-D) fields when sent.
   type, extends(run_observer) :: keeper
      integer :: n = 0, n_extra = 0
      real(dp), allocatable :: t(:), fields(:, :, :), extra(:, :, :)
   contains
      procedure :: static => keeper_static
      procedure :: snapshot => keeper_snapshot
      procedure :: snapshot_extra => keeper_extra
   end type keeper

contains

   subroutine collect_model3d(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('planar_namelist_3d_equals_2d', test_reduction), &
               new_unittest('auto_picks_model', test_auto), &
               new_unittest('end_b_off_plane_released', test_off_plane), &
               new_unittest('cross_current', test_cross_current)]
   end subroutine collect_model3d

   subroutine keeper_static(self, info, error)
      class(keeper), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
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
      write (unit, '(a)') text
      close (unit)
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      call sim%run(obs, error)
   end subroutine run_case

   !> The paper's fast 315 kN rupture on 41 nodes (to 0.08 s, past the
   !> reflection at end a), Newton to 1e-12, once with model = '2d' and once
   !> with '3d': the snapshot fields, the end history (positions, velocities,
   !> tension, force) and the energy ledger agree to 1e-10 of each quantity's
   !> largest magnitude, except the strain and the velocities (u, the ends'
   !> vx, vz), differences of positions over a cell and a step, which agree
   !> to 5e-10 (near the released end at 167 m/s); y and w stay 0.
   subroutine test_reduction(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: scene = &
         "&static tension = 315000 /"//new_line('a')// &
         "&rupture t_break = 0.005 /"//new_line('a')// &
         "&output interval = 0.01, energy = .true., quiet = .true. /"
      character(len=*), parameter :: numerics = "nodes = 41, t_end = 0.08, newton_tol = 1e-12 /"
      type(simulation) :: sim2, sim3
      type(keeper) :: obs2, obs3
      type(run_history), pointer :: h2, h3
      real(dp) :: worst, d, scale, worst_derived
      integer :: i, j, q
      character(len=16) :: where
      call run_case(scene//new_line('a')//"&numerics model = '2d', "//numerics, sim2, obs2, error)
      if (allocated(error)) return
      call run_case(scene//new_line('a')//"&numerics model = '3d', "//numerics, sim3, obs3, error)
      if (allocated(error)) return
      call check(error, sim2%model == '2d' .and. sim3%model == '3d', 'models run: '//sim2%model//', '//sim3%model)
      if (allocated(error)) return
      call check(error, obs2%n == obs3%n .and. obs2%n == 9 .and. obs3%n_extra == obs3%n .and. obs2%n_extra == 0, &
                 'snapshots: '//str(obs2%n)//' and '//str(obs3%n)//' (3-D extra: '//str(obs3%n_extra)//')')
      if (allocated(error)) return
      worst = 0
      worst_derived = 0
      where = ''
      do j = 1, n_fields
         scale = max(maxval(abs(obs2%fields(:, j, :))), tiny(1.0_dp))
         d = maxval(abs(obs2%fields(:, j, :) - obs3%fields(:, j, :)))/scale
         if (field_names(j) == 'strain' .or. field_names(j) == 'u') then
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
      do i = 1, 2
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
      write (output_unit, '(4x,a,es9.2,a,a,a,es9.2,a,es9.2,a)') 'planar namelist, model 3d vs 2d: ', worst, &
         ' of the largest value (worst: ', trim(where), '), strain and velocities ', worst_derived, '; largest |y|, |w|: ', d, &
         ' (m, m/s)'
      call check(error, worst < 1.0e-10_dp, 'model 3d differs from 2d by '//str(worst)//' ('//trim(where)//')')
      if (allocated(error)) return
      call check(error, worst_derived < 5.0e-10_dp, 'model 3d differs from 2d in strain or velocities by '//str(worst_derived))
      if (allocated(error)) return
      call check(error, d < 1.0e-12_dp, 'a planar scene in 3-D left the plane by '//str(d))
   end subroutine test_reduction

   !> model = 'auto': 2-D for a planar scene, 3-D when end b has a y, a force end a y force or a torque,
   !> or the current a y component.
   subroutine test_auto(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: common = "&rupture enabled = .false. /"//new_line('a')// &
                                              "&numerics nodes = 11, t_end = 0.002 /"//new_line('a')// &
                                              "&output interval = 0.002, quiet = .true. /"//new_line('a')
      character(len=160) :: scenes(4)
      character(len=2) :: expected(4)
      type(simulation) :: sim
      type(keeper) :: obs
      integer :: i
      scenes(1) = "&end_b kind = 'fixed', x = 50, z = 0 /"
      scenes(2) = "&end_b kind = 'fixed', x = 50, y = 5, z = 0 /"
      scenes(3) = "&end_b kind = 'force', force_x = 3000, force_z = 1000, torque = 5 /"
      scenes(4) = "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
                  "&fluid density = 1025, cd_normal = 1.2, current_y = 0.5 /"
      expected = ['2d', '3d', '3d', '3d']
      do i = 1, size(scenes)
         obs = keeper()
         call run_case(common//trim(scenes(i)), sim, obs, error)
         if (allocated(error)) return
         call check(error, sim%model == expected(i), 'scene '//str(i)//": model 'auto' ran "//sim%model//', expected '// &
                    expected(i))
         if (allocated(error)) return
         call check(error, (obs%n_extra > 0) .eqv. (expected(i) == '3d'), 'scene '//str(i)//': 3-D fields sent '// &
                    str(obs%n_extra)//' times')
         if (allocated(error)) return
      end do
   end subroutine test_auto

   !> A slack line (60 m between points 30 m apart along x and 20 m along y)
   !> let go at end b: it runs to t_end, the ledger closes, and the motion stays
   !> in the vertical plane of the chord (y / x = 2/3 at every node and
   !> snapshot, to 1e-9 of the length) while end b moves across x-z (0.68 m in y by 2 s).
   subroutine test_off_plane(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(run_summary), pointer :: s
      real(dp) :: y_moved, off_chord_plane
      call run_case("&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                    "&end_b kind = 'fixed', x = 30, y = 20, z = 0 /"//new_line('a')// &
                    "&rupture s_break = 60, t_break = 0 /"//new_line('a')// &
                    "&numerics nodes = 31, courant = 2, t_end = 2.0 /"//new_line('a')// &
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
   end subroutine test_off_plane

   !> A line in water between a fixed end and a fairlead moving across the
   !> plane (harmonic along y, 1 m, 2 s), with a current across the plane
   !> (0.3 m/s along y, in the statics too): it runs to t_end, the ledger (with
   !> the fluid's work; Newton to 1e-10) closes, and the middle stands downstream (+y).
   subroutine test_cross_current(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(keeper) :: obs
      type(run_summary), pointer :: s
      type(run_history), pointer :: h
      real(dp) :: y_mid, loads
      integer :: mid
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
   end subroutine test_cross_current
end module suite_model3d
