!> Scenes beyond the paper's against closed forms: a line parting in the
!> middle (mirror symmetry, and simple-wave theory for each half), a hanging
!> chain (Bessel-zero frequencies), a pendulum (a mass on a light stiff
!> line), and a taut line whose end is moved harmonically (linear string
!> theory, d'Alembert with the reflections).
module suite_scenes
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_driver_simulation, only: simulation
   use xcable_theory_closed_forms, only: wall_drop_time
   use xcable_io_input, only: read_config
   use xcable_fixtures, only: write_text
   use suite_rod_statics, only: statics_config
   use suite_rod_dynamics, only: rupture_config, run_config
   use suite_golden, only: snapshot_store
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_scenes, free_end_period

   real(dp), parameter :: pi = acos(-1.0_dp)

contains

   subroutine collect_scenes(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('break_in_the_middle', test_middle_break), &
               new_unittest('hanging_chain_bessel', test_hanging_chain), &
               new_unittest('pendulum', test_pendulum), &
               new_unittest('harmonic_end_motion_string_theory', test_harmonic), &
               new_unittest('no_rupture_group_no_break', test_no_rupture), &
               new_unittest('heave_summary_from_its_history', test_heave_summary), &
               new_unittest('coarse_grid_warned_with_nodes', test_coarse_grid), &
               new_unittest('dynamic_compression_warned', test_compression_warned)]
   end subroutine collect_scenes

   !> The paper's cable at 180 kN parting at mid-span: the two halves mirror
   !> each other, and each fixed end sees the 1 % drop when simple-wave theory
   !> says for a cable of half the length released at its end.
   subroutine test_middle_break(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(snapshot_store) :: store
      type(case_config) :: c
      real(dp) :: mirror, theory, span, err_a, err_b, speed_a, speed_b
      integer :: n, k, last
      c = rupture_config(180.0e3_dp, 0.005_dp, 0.04_dp, 241)
      c%s_break = 30
      c%interval = 0.01_dp
      call run_config(c, sim, error, store)
      if (allocated(error)) return
      n = size(store%fields, 1)
      last = store%n
      span = store%fields(n, 6, 1)
      mirror = 0
      do k = 1, n
         mirror = max(mirror, abs(store%fields(k, 6, last) + store%fields(n + 1 - k, 6, last) - span), &
                      abs(store%fields(k, 7, last) - store%fields(n + 1 - k, 7, last)))
      end do
      associate (s => sim%rod%scene, e => sim%rod%summary%ends)
         theory = wall_drop_time(s%law, s%mass, 0.5_dp*s%length, s%law%strain_at(180.0e3_dp), 0.005_dp, 0.01_dp)
         err_a = e(1)%front_arrival_time - theory
         err_b = e(2)%front_arrival_time - theory
         speed_a = e(3)%peak_speed
         speed_b = e(4)%peak_speed
      end associate
      write (output_unit, '(4x,a,es10.3,a,f9.6,a,2es11.3,a,2f10.4)') 'break at L/2: mirror mismatch of the positions ', &
         mirror, ' m; 1 % drop theory ', theory, ' s, error at end a, b', err_a, err_b, ' s; new ends peak speeds', &
         speed_a, speed_b
      call check(error, mirror < 1.0e-9_dp, 'the halves do not mirror each other (mismatch '//str(mirror)//' m)')
      if (allocated(error)) return
      call check(error, abs(err_a) < 5.0e-6_dp .and. abs(err_b) < 5.0e-6_dp, 'front arrival off simple-wave theory')
      if (allocated(error)) return
      call check_close(error, speed_a, speed_b, 'peak speeds of the two new ends', rel_tol=1.0e-9_dp)
   end subroutine test_middle_break

   !> A chain (a 10 m line, nearly inextensible, EI 1e-3 N m^2) hanging from
   !> end a, started in its first mode, J0(2 omega sqrt((L - s) / g)), swings
   !> with omega = j0,1 / 2 sqrt(g / L): the period of the free end.
   subroutine test_hanging_chain(error)
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: j01 = 2.404825557695773_dp
      real(dp) :: omega, period(2), exact
      integer, parameter :: nodes(2) = [31, 61]
      integer :: i
      type(case_config) :: c
      omega = 0
      do i = 1, 2
         c = statics_config(nodes(i))
         c%length = 10
         c%law = 'linear'
         c%ea = 1.0e8_dp
         c%bending_stiffness = 1.0e-3_dp
         c%end_b%kind = 'free'
         c%given = ''
         c%dt = 0.005_dp
         c%t_end = 11
         omega = 0.5_dp*j01*sqrt(c%gravity/c%length)
         call free_end_period(c, 'chain', omega, period(i), error)
         if (allocated(error)) return
      end do
      exact = 2*pi/omega
      write (output_unit, '(4x,a,f10.6,a,2es11.3)') 'hanging chain: period j0,1 theory ', exact, &
         ' s; relative error on 31/61 nodes', (period - exact)/exact
      call check(error, abs(period(2) - exact) < 1.5e-4_dp*exact, 'hanging-chain period off the Bessel-zero result')
      if (allocated(error)) return
      call check(error, abs(period(2) - exact) < abs(period(1) - exact), 'hanging-chain period error does not shrink')
   end subroutine test_hanging_chain

   !> Start the chain or pendulum with a small horizontal velocity of the
   !> given shape and measure the period of the free end's swing from its
   !> zero crossings (linear interpolation between steps).
   subroutine free_end_period(c, shape, omega, period, error)
      type(case_config), intent(in) :: c
      character(*), intent(in) :: shape
      real(dp), intent(in) :: omega
      real(dp), intent(out) :: period
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      real(dp) :: crossings(20), y
      integer :: k, nc
      call sim%prepare(c, error)
      if (allocated(error)) return
      associate (piece => sim%rod%pieces(1), s => sim%rod%s)
         do k = 1, size(s)
            y = s(size(s)) - s(k)
            if (shape == 'chain') then
               piece%v(:, k) = [0.01_dp*bessel_j0(2*omega*sqrt(y/c%gravity)), 0.0_dp]
            else
               piece%v(:, k) = [0.01_dp*s(k)/s(size(s)), 0.0_dp]
            end if
         end do
         piece%v(:, 1) = 0
      end associate
      call sim%run(error=error)
      if (allocated(error)) return
      nc = 0
      associate (h => sim%rod%history)
         do k = 2, h%n
            if (h%ends(1, 2, k - 1) > 0 .and. h%ends(1, 2, k) <= 0 .or. h%ends(1, 2, k - 1) < 0 .and. h%ends(1, 2, k) >= 0) then
               if (nc == size(crossings)) exit
               nc = nc + 1
               crossings(nc) = h%time(k - 1) + (h%time(k) - h%time(k - 1))*h%ends(1, 2, k - 1) &
                               /(h%ends(1, 2, k - 1) - h%ends(1, 2, k))
            end if
         end do
      end associate
      call check(error, nc >= 3, 'fewer than three zero crossings of the free end')
      if (allocated(error)) return
      ! Crossings every half period.
      period = 2*(crossings(nc) - crossings(1))/(nc - 1)
   end subroutine free_end_period

   !> A 100 kg mass on a light, stiff 10 m line swings with the period of a
   !> compound pendulum, 2 pi sqrt(l / g (M + m_c / 3) / (M + m_c / 2)), l the
   !> stretched length and m_c the line's mass (2e-4 of M: it shortens the
   !> period by 1.6e-5).
   subroutine test_pendulum(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      real(dp) :: period, exact, stretched, mass, line
      c = statics_config(21)
      c%length = 10
      c%density = 1
      c%law = 'linear'
      c%ea = 1.0e8_dp
      c%bending_stiffness = 1.0e-6_dp
      c%end_b%kind = 'mass'
      mass = 100
      c%end_b%mass = mass
      c%given = ''
      c%dt = 0.005_dp
      c%t_end = 13
      stretched = c%length*(1 + mass*c%gravity/c%ea)
      line = c%density*0.25_dp*pi*c%diameter**2*c%length
      exact = 2*pi*sqrt(stretched/c%gravity*(mass + line/3)/(mass + line/2))
      call free_end_period(c, 'rigid', 2*pi/exact, period, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a,f10.6,a,es11.3)') 'pendulum: compound-pendulum period ', exact, ' s; relative error', &
         (period - exact)/exact
      call check(error, abs(period - exact) < 6.0e-6_dp*exact, 'pendulum period off the compound pendulum')
   end subroutine test_pendulum

   !> A taut line (linear law, 1 % strain, no weight) whose end a is moved
   !> up and down by 1 mm with a smooth start: the transverse displacement at
   !> mid-span against linear string theory (waves at c = sqrt(T / (m (1 + eps)))
   !> per unstretched length, reflected at both ends), over three crossings.
   subroutine test_harmonic(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      type(simulation) :: sim
      type(snapshot_store) :: store
      integer, parameter :: nodes(2) = [101, 201]
      real(dp) :: worst(2), amplitude, period, ramp, ea, tension, speed, mid, exact
      integer :: i, k
      ! 1 mm: the stretch of the moving line (its second-order coupling to the tension) stays negligible.
      amplitude = 0.001_dp
      ! Not a multiple of the fundamental period 2 L / c = 0.30 s: no resonance.
      period = 0.13_dp
      ramp = 0.13_dp
      ea = 1.0e6_dp
      do i = 1, 2
         c = statics_config(nodes(i))
         c%length = 10
         c%law = 'linear'
         c%ea = ea
         c%gravity = 0
         c%bending_stiffness = 1.0e-6_dp
         c%end_a%kind = 'motion'
         c%end_a%amplitude = amplitude
         c%end_a%period = period
         c%end_a%ramp_time = ramp
         c%end_a%direction_x = 0
         c%end_a%direction_z = 1
         c%end_b%x = 10.1_dp
         c%end_b%z = 0
         c%given = 'end_b%x end_b%z'
         c%t_end = 0.45_dp
         c%interval = 0.005_dp
         store = snapshot_store()
         call run_config(c, sim, error, store)
         if (allocated(error)) return
         tension = ea*0.01_dp
         speed = sqrt(tension/(sim%rod%scene%mass*1.01_dp))
         mid = 0.5_dp*c%length
         worst(i) = 0
         do k = 1, store%n
            exact = string(store%times(k), mid)
            worst(i) = max(worst(i), abs(store%fields((nodes(i) + 1)/2, 7, k) - exact))
         end do
      end do
      write (output_unit, '(4x,a,f8.3,a,2es11.3,a)') 'harmonic end motion: string speed ', speed, &
         ' m/s; largest error of the mid-span displacement on 101/201 nodes', worst/amplitude, ' of the amplitude'
      call check(error, worst(2) < 0.007_dp*amplitude, 'mid-span motion off linear string theory by more than 0.7 %')
      if (allocated(error)) return
      call check(error, worst(2) < 0.35_dp*worst(1), 'the error does not fall at second order')

   contains

      !> d'Alembert: the driven end's motion travelling right, reflected with a sign change at both ends.
      real(dp) function string(t, s)
         real(dp), intent(in) :: t, s
         integer :: j
         string = 0
         do j = 0, 20
            string = string + drive(t - (s + 2*j*c%length)/speed) - drive(t - (2*c%length - s + 2*j*c%length)/speed)
         end do
      end function string

      !> The prescribed motion of end a (motion_end 'harmonic' with a smooth start).
      real(dp) function drive(t)
         real(dp), intent(in) :: t
         real(dp) :: w
         if (t <= 0) then
            drive = 0
            return
         end if
         w = 1
         if (t < ramp) w = sin(0.5_dp*pi*t/ramp)**2
         drive = amplitude*w*sin(2*pi*t/period)
      end function drive
   end subroutine test_harmonic

   !> A case without &rupture does not break: the paper's 180 kN line held between its two
   !> supports keeps its end tensions (a static state stays static), while the same case with a
   !> &rupture group (t_break only) parts at end b as it always did.
   subroutine test_no_rupture(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: body = "&static tension = 180000 /"//new_line('a')// &
                                        "&numerics nodes = 41, courant = 1.0, t_end = 0.03 /"//new_line('a')// &
                                        "&output quiet = .true., interval = 0.01 /"//new_line('a')
      type(case_config) :: c
      type(simulation) :: sim
      real(dp) :: drift, drop
      call write_text('build/test_no_rupture.nml', body)
      call read_config('build/test_no_rupture.nml', c, error)
      if (allocated(error)) return
      call check(error, .not. c%break_enabled, 'a case without &rupture asks for a break')
      if (allocated(error)) return
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(error=error)
      if (allocated(error)) return
      ! History row 5: end tension (driver/records.f90); ends 1, 2 are end a, end b.
      associate (h => sim%rod%history)
         drift = maxval(abs(h%ends(5, 1:2, h%n) - h%ends(5, 1:2, 0)))/h%ends(5, 2, 0)
      end associate
      call write_text('build/test_no_rupture.nml', body//"&rupture t_break = 0.005 /"//new_line('a'))
      call read_config('build/test_no_rupture.nml', c, error)
      if (allocated(error)) return
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(error=error)
      if (allocated(error)) return
      associate (h => sim%rod%history)
         drop = h%ends(5, 2, h%n)/h%ends(5, 2, 0)
      end associate
      write (output_unit, '(4x,a,es10.3,a,f8.4)') 'no &rupture: end tensions drift by ', drift, &
         ' of the static; with &rupture t_break = 0.005 / end b keeps ', drop
      call check(error, drift < 1.0e-6_dp, 'the end tensions of a case without &rupture changed by '//str(drift))
      if (allocated(error)) return
      call check(error, drop < 0.1_dp, 'the same case with &rupture did not release end b ('//str(drop)//')')
   end subroutine test_no_rupture

   !> A mooring line in heave (anchor fixed, fairlead moved harmonically, no break): the summary
   !> is the history's own extremes. The peak end speed is the fairlead's (A omega once the ramp
   !> is over, to the time step's error), the smallest fixed-end tension is the anchor's (not the moving end's), and there
   !> is no front arrival (nothing broke).
   subroutine test_heave_summary(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: case_text = &
         "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
         "&end_b kind = 'motion', x = 50, z = 30, motion = 'harmonic', amplitude = 0.5, period = 2,"// &
         " direction_x = 0, direction_z = 1, ramp_time = 1 /"//new_line('a')// &
         "&material compression = 'none' /"//new_line('a')// &
         "&numerics nodes = 41, courant = 1.0, t_end = 4 /"//new_line('a')// &
         "&output quiet = .true., interval = 0.1 /"//new_line('a')
      real(dp), parameter :: a_omega = 0.5_dp*2*pi/2
      type(case_config) :: c
      type(simulation) :: sim
      real(dp) :: speed, fastest, lowest
      integer :: i, j
      call write_text('build/test_heave_summary.nml', case_text)
      call read_config('build/test_heave_summary.nml', c, error)
      if (allocated(error)) return
      call sim%prepare(c, error)
      if (allocated(error)) return
      call sim%run(error=error)
      if (allocated(error)) return
      associate (h => sim%rod%history, m => sim%rod%summary)
         fastest = 0
         do j = 1, 2
            call check(error, m%ends(j)%max_tension == maxval(h%ends(5, j, 0:h%n)) .and. &
                       m%ends(j)%min_tension == minval(h%ends(5, j, 0:h%n)), &
                       trim(h%end_labels(j))//': the summary tensions are not the history extremes')
            if (allocated(error)) return
            do i = 0, h%n
               speed = norm2(h%ends(3:4, j, i))
               fastest = max(fastest, speed)
            end do
         end do
         lowest = minval(h%ends(5, 1, 0:h%n))
         write (output_unit, '(4x,a,f8.5,a,f8.5,a,f10.3,a,l1)') 'heave: peak end speed ', m%peak_end_speed, &
            ' m/s (A omega ', a_omega, '), smallest anchor tension ', m%min_fixed_end_tension, ' N; a front: ', &
            m%has_front
         call check(error, m%peak_end_speed == fastest .and. m%peak_end_speed_end == 'end_b', &
                    'the peak end speed is not the fastest end of the history (the fairlead)')
         if (allocated(error)) return
         ! The recorded speed is the step's (theta rule), not the closed form's: 1.3e-5 off here.
         call check(error, abs(m%peak_end_speed - a_omega) < 5.0e-5_dp*a_omega, &
                    'the fairlead''s peak speed is not A omega: '//str(m%peak_end_speed))
         if (allocated(error)) return
         call check(error, m%has_fixed_end .and. m%min_fixed_end_tension == lowest, &
                    'the smallest fixed-end tension is not the anchor''s')
         if (allocated(error)) return
         call check(error, .not. m%has_front .and. .not. m%broke, 'a front or a break reported for a heave')
      end associate
   end subroutine test_heave_summary

   !> A grid too coarse for the scene is warned with the node count that resolves it: a slack
   !> line on 5 nodes (its shape turns by 0.64 rad per cell) and the paper's break ramped over
   !> 5 ms on 11 nodes (its front spans one cell); the same scenes on enough nodes are not warned.
   subroutine test_coarse_grid(error)
      type(error_type), allocatable, intent(out) :: error
      character(*), parameter :: slack = "&end_a kind = 'fixed', x = 0, z = 0 /"//new_line('a')// &
                                         "&end_b kind = 'fixed', x = 50, z = 0 /"//new_line('a')// &
                                         "&output quiet = .true. /"//new_line('a')
      character(*), parameter :: paper = "&static tension = 180000 /"//new_line('a')//"&rupture t_break = 0.005 /"// &
                                         new_line('a')//"&output quiet = .true., interval = 0.0005 /"//new_line('a')
      character(:), allocatable :: warned
      call warnings_of(slack//"&numerics nodes = 5, t_end = 0.01 /", warned, error)
      if (allocated(error)) return
      call check(error, index(warned, 'too coarse for the shape; about 27 nodes') > 0, &
                 'a slack line on 5 nodes is not warned with 27 nodes: '//warned)
      if (allocated(error)) return
      call warnings_of(slack//"&numerics nodes = 41, t_end = 0.01 /", warned, error)
      if (allocated(error)) return
      call check(error, index(warned, 'too coarse') == 0, 'a slack line on 41 nodes is warned: '//warned)
      if (allocated(error)) return
      call warnings_of(paper//"&numerics nodes = 11, t_end = 0.001 /", warned, error)
      if (allocated(error)) return
      call check(error, index(warned, 'front') > 0 .and. index(warned, 'nodes resolve it') > 0, &
                 'the paper''s 5 ms break on 11 nodes is not warned: '//warned)
      if (allocated(error)) return
      call warnings_of(paper//"&numerics nodes = 241, t_end = 0.001 /", warned, error)
      if (allocated(error)) return
      call check(error, index(warned, 'front') == 0, 'the paper''s break on 241 nodes is warned: '//warned)
   contains
      subroutine warnings_of(text, warnings, error)
         character(*), intent(in) :: text
         character(:), allocatable, intent(out) :: warnings
         type(error_type), allocatable, intent(out) :: error
         type(case_config) :: c
         type(simulation) :: sim
         call write_text('build/test_coarse_grid.nml', text//new_line('a'))
         call read_config('build/test_coarse_grid.nml', c, error)
         if (allocated(error)) return
         call sim%prepare(c, error)
         if (allocated(error)) return
         call sim%run(error=error)
         if (allocated(error)) return
         warnings = sim%rod%summary%warnings
         write (output_unit, '(4x,a)') 'warned: '//warnings
      end subroutine warnings_of
   end subroutine test_coarse_grid

   !> The paper's fast 180 kN break compresses the line near the fixed end after the reflection:
   !> with compression = 'law' the run warns with the compression, where and when (the smallest
   !> strain of the history); a rope that cannot push (compression = 'none') is not warned.
   subroutine test_compression_warned(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: c
      type(simulation) :: sim
      c = rupture_config(180.0e3_dp, 0.005_dp, 0.12_dp, 61)
      c%compression = 'law'
      call run_config(c, sim, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'law: '//sim%rod%summary%warnings
      call check(error, index(sim%rod%summary%warnings, 'compressed to -') > 0 .and. &
                 index(sim%rod%summary%warnings, ' at s = ') > 0 .and. &
                 sim%rod%summary%min_strain_time > 0.05_dp .and. sim%rod%summary%min_strain_s < 30, &
                 'the compression of the paper''s break near its fixed end after the reflection is not warned')
      if (allocated(error)) return
      c%compression = 'none'
      call run_config(c, sim, error)
      if (allocated(error)) return
      write (output_unit, '(4x,a)') 'none: '//sim%rod%summary%warnings
      call check(error, index(sim%rod%summary%warnings, 'compressed') == 0, 'a rope that cannot push is warned')
   end subroutine test_compression_warned
end module suite_scenes
