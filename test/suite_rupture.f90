!> The break at the breaking load (&rupture criterion = 'tension', mbl): where and when
!> the line parts against the crossing of the same run without the break, the same run
!> as a break at that time and place (criterion 'time'), the 3-D model against the
!> planar one, a line that never reaches its MBL, and the MBL at or below the static
!> tension.
!>
!> Two scenes, 60 m of the default line held at end a (0, 0):
!>  - 'force': end b pulled by a force along x that rises from 20 kN to 40 kN in 0.05 s
!>    (a table): the first cell to reach 30 kN is the last one, at the force end, which
!>    is not held, so the break is inside, at the node two cells from it (s = 58 m);
!>  - 'pull': end b moved harmonically along x (1 m, period 2 s) from 58 m: the first
!>    cell to reach 5 kN is the one at the fixed end a, which lets go (s = 0).
module suite_rupture
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_core_error, only: stat_input
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_io_input, only: read_config
   use xcable_driver_simulation, only: simulation
   use xcable_driver_stepping, only: start_dynamics, advance_dynamics
   use xcable_driver_rod_run, only: pause_none, rupture_tolerance
   use xcable_driver_records, only: summary_text
   use suite_golden, only: snapshot_store
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_rupture

   !> The scene file the tests write.
   character(len=*), parameter :: path = 'build/test_rupture.nml'
   character(len=*), parameter :: nl = new_line('a')
   !> The scenes (without &rupture and &numerics).
   character(len=*), parameter :: force_scene = "&cable length = 60 /"//nl// &
                                                "&end_a kind = 'fixed', x = 0, z = 0 /"//nl// &
                                                "&end_b kind = 'force', history = 'table', table_time = 0, 0.05, 1, "// &
                                                "table_x = 20000, 40000, 40000, table_z = 0, 0, 0 /"//nl// &
                                                "&output interval = 0.005, quiet = .true. /"//nl
   character(len=*), parameter :: pull_scene = "&cable length = 60 /"//nl// &
                                               "&end_a kind = 'fixed', x = 0, z = 0 /"//nl// &
                                               "&end_b kind = 'motion', x = 58, z = 0, motion = 'harmonic', "// &
                                               "amplitude = 1.0, period = 2.0, direction_x = 1, direction_z = 0 /"//nl// &
                                               "&output interval = 0.005, quiet = .true. /"//nl
   !> Their MBLs (N) and runs.
   real(dp), parameter :: force_mbl = 30.0e3_dp, pull_mbl = 5.0e3_dp
   character(len=*), parameter :: force_numerics = "&numerics nodes = 61, courant = 1.0, t_end = 0.25 /"//nl
   character(len=*), parameter :: pull_numerics = "&numerics nodes = 61, courant = 1.0, t_end = 0.45 /"//nl

contains

   subroutine collect_rupture(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('break_where_and_when_mbl_is_reached', test_where_and_when), &
               new_unittest('tension_break_equals_time_break', test_equals_time_break), &
               new_unittest('model3d_same_break', test_model3d), &
               new_unittest('mbl_never_reached', test_never_reached), &
               new_unittest('mbl_below_static_tension', test_static_mbl)]
   end subroutine collect_rupture

   !> Read a case from text and prepare it.
   subroutine prepare_text(text, sim, error)
      character(*), intent(in) :: text
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      integer :: unit
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') text
      close (unit)
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
   end subroutine prepare_text

   !> Prepare and run a case from text.
   subroutine run_text(text, sim, error, store)
      character(*), intent(in) :: text
      type(simulation), intent(inout) :: sim
      type(error_type), allocatable, intent(out) :: error
      type(snapshot_store), intent(inout), optional :: store
      call prepare_text(text, sim, error)
      if (allocated(error)) return
      call sim%run(store, error)
   end subroutine run_text

   !> The crossing of mbl in the run of a scene without the break, found independently of
   !> the driver's search: the planar run paused after every step (checkpoint_steps = 1),
   !> the cell tensions of the law from the positions, and the first step whose largest one
   !> reaches mbl. Two estimates of its time: t_lin, where that cell's tension, linear between
   !> the step's two levels, reaches mbl (the earliest of the cells past mbl); t_bis, by
   !> bisection inside the step on the end of the run (t_end: the run's last step shortened to
   !> land there, as a step aimed at the crossing is) to 1e-12 s, the time at which the
   !> largest cell tension of the run's last level reaches mbl. t_lin = t_bis = -1 when it
   !> never does. text is the scene without &numerics; numerics_of(t_end) gives that group.
   subroutine reference_crossing(text, model_nodes, mbl, t_lin, t_bis, cell, s_mid, error)
      character(*), intent(in) :: text
      integer, intent(in) :: model_nodes
      real(dp), intent(in) :: mbl
      real(dp), intent(out) :: t_lin, t_bis, s_mid
      integer, intent(out) :: cell
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      real(dp), allocatable :: before(:), after(:)
      real(dp) :: t_before, t_after, tc, lo, hi, mid
      integer :: pause, c, k
      t_lin = -1
      t_bis = -1
      cell = 0
      s_mid = 0
      call prepare_text(text//"&rupture enabled = .false. /"//nl//numerics_of(model_nodes, 1.0_dp), sim, error)
      if (allocated(error)) return
      sim%rod%options%checkpoint_steps = 1
      call start_dynamics(sim%rod, sim%planar, error=error)
      if (allocated(error)) return
      before = tensions(sim)
      t_before = sim%rod%t
      do
         call advance_dynamics(sim%rod, sim%planar, error=error, pause=pause)
         if (allocated(error)) return
         after = tensions(sim)
         if (maxval(after) >= mbl) exit
         if (pause == pause_none) return
         before = after
         t_before = sim%rod%t
      end do
      t_after = sim%rod%t
      t_lin = huge(1.0_dp)
      do c = 1, size(after)
         if (after(c) < mbl) cycle
         tc = t_before + (mbl - before(c))/(after(c) - before(c))*(t_after - t_before)
         if (tc < t_lin) then
            t_lin = tc
            cell = c
         end if
      end do
      s_mid = 0.5_dp*(sim%rod%s(cell) + sim%rod%s(cell + 1))
      ! Bisection on t_end inside the step.
      lo = t_before
      hi = t_after
      do k = 1, 60
         if (hi - lo <= 1.0e-12_dp) exit
         mid = 0.5_dp*(lo + hi)
         call run_text(text//"&rupture enabled = .false. /"//nl//numerics_of(model_nodes, mid), sim, error)
         if (allocated(error)) return
         if (maxval(tensions(sim)) >= mbl) then
            hi = mid
         else
            lo = mid
         end if
      end do
      t_bis = 0.5_dp*(lo + hi)
   end subroutine reference_crossing

   !> The &numerics group of the tests' runs: nodes, courant 1, t_end (s).
   function numerics_of(nodes, t_end) result(text)
      integer, intent(in) :: nodes
      real(dp), intent(in) :: t_end
      character(:), allocatable :: text
      character(len=32) :: t
      write (t, '(es24.17)') t_end
      text = "&numerics nodes = "//str(nodes)//", courant = 1.0, t_end = "//trim(adjustl(t))//" /"//nl
   end function numerics_of

   !> Cell tensions of the law of the planar run's single piece, N.
   function tensions(sim) result(ten)
      type(simulation), intent(in) :: sim
      real(dp), allocatable :: ten(:)
      integer :: n
      associate (piece => sim%rod%pieces(1)%problem%piece, r => sim%rod%pieces(1)%r)
         n = piece%n
         ten = piece%law%tension(norm2(r(:, 2:n) - r(:, 1:n - 1), 1)/piece%ds - 1)
      end associate
   end function tensions

   !> Both scenes, planar: the break starts when the run without it first reaches the MBL
   !> (reference_crossing: its bisection on the run's end), within 1e-6 s (the search stops
   !> within rupture_tolerance of the MBL); in that first cell (break_cell_s its middle), with
   !> its tension within rupture_tolerance of the MBL; at the expected node (the force scene:
   !> s = 58 m, two cells from the force end, which is not held; the pull scene: the fixed end
   !> a). The recoil follows: an end moves off at more than 10 m/s after the break, and the
   !> front of the break reaches the held end (the 1 % drop of its tension) after it. The
   !> linear interpolation of the tension within the step (t_lin) is printed for comparison.
   subroutine test_where_and_when(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=5), parameter :: names(2) = ['force', 'pull ']
      real(dp), parameter :: expected_s(2) = [58.0_dp, 0.0_dp]
      type(simulation) :: sim
      real(dp) :: t_lin, t_bis, s_ref, mbl
      integer :: i, cell
      character(:), allocatable :: scene, numerics
      do i = 1, 2
         if (i == 1) then
            scene = force_scene
            numerics = force_numerics
            mbl = force_mbl
         else
            scene = pull_scene
            numerics = pull_numerics
            mbl = pull_mbl
         end if
         call reference_crossing(scene, 61, mbl, t_lin, t_bis, cell, s_ref, error)
         if (allocated(error)) return
         call check(error, t_bis > 0, trim(names(i))//': the run without the break never reaches the MBL')
         if (allocated(error)) return
         call run_text(scene//numerics//"&rupture criterion = 'tension', mbl = "//str(mbl)//", t_break = 0.005 /", &
                       sim, error)
         if (allocated(error)) return
         associate (s => sim%rod%summary)
            write (output_unit, '(4x,a,f11.8,a,f11.8,a,es9.2,a,es9.2,a)') trim(names(i))//': break at t =', &
               s%break_time, ' s; the run without it reaches the MBL at', t_bis, ' s (', s%break_time - t_bis, &
               ' s; linear in the step:', t_lin - t_bis, ' s)'
            write (output_unit, '(4x,a,f6.2,a,f6.2,a,f6.2,a,es9.2,a,f8.2,a)') '  cell at s =', s%break_cell_s, &
               ' m (reference', s_ref, ' m), break node s =', s%break_s, ' m, tension/MBL - 1 =', &
               s%break_tension/mbl - 1, ', peak end speed', s%peak_end_speed, ' m/s'
            write (output_unit, '(4x,a,i0,a)') '  steps tried in the search: ', sim%rod%rupture%aims, &
               ' (the step past the MBL and its replacements but the last)'
            call check(error, s%broke .and. s%by_tension, trim(names(i))//': no break')
            if (allocated(error)) return
            call check(error, abs(s%break_time - t_bis) <= 3.0e-7_dp, trim(names(i))//': break at '// &
                       str(s%break_time)//' s, the crossing at '//str(t_bis)//' s')
            if (allocated(error)) return
            call check(error, abs(s%break_cell_s - s_ref) <= 1.0e-9_dp, trim(names(i))//': first cell at '// &
                       str(s%break_cell_s)//' m, the reference''s at '//str(s_ref)//' m')
            if (allocated(error)) return
            call check(error, abs(s%break_tension/mbl - 1) <= rupture_tolerance, trim(names(i))// &
                       ': tension at the break '//str(s%break_tension)//' N')
            if (allocated(error)) return
            call check(error, abs(s%break_s - expected_s(i)) <= 1.0e-9_dp, trim(names(i))//': break node at '// &
                       str(s%break_s)//' m')
            if (allocated(error)) return
            call check(error, s%peak_end_speed > 10 .and. s%peak_end_speed_time > s%break_time, &
                       trim(names(i))//': no recoil after the break')
            if (allocated(error)) return
            call check(error, s%front_arrival_time > s%break_time, trim(names(i))//': no front after the break')
            if (allocated(error)) return
         end associate
      end do
   end subroutine test_where_and_when

   !> The force scene's break by tension and a break by time at the time and place it
   !> reports (criterion 'time', s_break = break_s, time = break_time, the same t_break):
   !> the same history of the four ends and the same snapshots, to 1e-12 of their scales.
   subroutine test_equals_time_break(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: by_tension, by_time
      type(snapshot_store) :: store_tension, store_time
      real(dp) :: d_history, d_snap
      integer :: m
      character(len=32) :: where, when
      call run_text(force_scene//force_numerics//"&rupture criterion = 'tension', mbl = "//str(force_mbl)// &
                    ", t_break = 0.005 /", by_tension, error, store_tension)
      if (allocated(error)) return
      write (where, '(es24.17)') by_tension%rod%summary%break_s
      write (when, '(es24.17)') by_tension%rod%summary%break_time
      call run_text(force_scene//force_numerics//"&rupture criterion = 'time', s_break = "//trim(adjustl(where))// &
                    ", time = "//trim(adjustl(when))//", t_break = 0.005 /", by_time, error, store_time)
      if (allocated(error)) return
      call check(error, by_time%rod%history%n == by_tension%rod%history%n .and. store_time%n == store_tension%n, &
                 'steps '//str(by_time%rod%history%n)//' and '//str(by_tension%rod%history%n)//', snapshots '// &
                 str(store_time%n)//' and '//str(store_tension%n))
      if (allocated(error)) return
      m = by_time%rod%history%n
      associate (a => by_tension%rod%history%ends(:, :, 0:m), b => by_time%rod%history%ends(:, :, 0:m))
         d_history = maxval(abs(a - b))/maxval(abs(b))
      end associate
      associate (a => store_tension%fields(:, :, 1:store_time%n), b => store_time%fields(:, :, 1:store_time%n))
         d_snap = maxval(abs(a - b))/maxval(abs(b))
      end associate
      write (output_unit, '(4x,a,es9.2,a,es9.2,a,i0,a)') 'tension against time break: history', d_history, &
         ', snapshots', d_snap, ' of their scales (', m, ' steps)'
      call check(error, d_history <= 1.0e-12_dp .and. d_snap <= 1.0e-12_dp, 'the runs differ: '//str(d_history)// &
                 ', '//str(d_snap))
   end subroutine test_equals_time_break

   !> Both scenes with model = '3d' against the planar runs, and the pull scene turned 30
   !> degrees about the vertical through end a (its chord off the x-z plane, its motion along
   !> the chord) in 3-D against the planar pull: the same break node and first cell, the break
   !> time within 1e-12 s in the plane (measured 8e-14 s) and 3e-9 s turned (measured 6.2e-10 s:
   !> the turned scene's coordinates are rounded, its state differs at round-off and the search
   !> lands at another time within its tolerance), the tension within rupture_tolerance of
   !> the MBL.
   subroutine test_model3d(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=6), parameter :: names(3) = ['force ', 'pull  ', 'turned']
      type(simulation) :: planar, three
      character(:), allocatable :: text
      real(dp) :: mbl
      integer :: i
      do i = 1, 3
         if (i == 3) then
            ! The planar pull of i = 2 stays.
            call run_text("&cable length = 60 /"//nl//"&end_a kind = 'fixed', x = 0, z = 0 /"//nl// &
                          "&end_b kind = 'motion', x = 50.22947341949744, y = 29.0, z = 0, motion = 'harmonic', "// &
                          "amplitude = 1.0, period = 2.0, direction_x = 0.8660254037844387, direction_y = 0.5, "// &
                          "direction_z = 0 /"//nl//"&output interval = 0.005, quiet = .true. /"//nl// &
                          "&rupture criterion = 'tension', mbl = "//str(mbl)//", t_break = 0.005 /"//nl// &
                          "&numerics model = '3d', nodes = 61, courant = 1.0, t_end = 0.45 /", three, error)
            if (allocated(error)) return
            call compare()
            if (allocated(error)) return
            cycle
         end if
         if (i == 1) then
            mbl = force_mbl
            text = force_scene//"&rupture criterion = 'tension', mbl = "//str(mbl)//", t_break = 0.005 /"//nl
            call run_text(text//force_numerics, planar, error)
            if (allocated(error)) return
            call run_text(text//"&numerics model = '3d', nodes = 61, courant = 1.0, t_end = 0.25 /", three, error)
         else
            mbl = pull_mbl
            text = pull_scene//"&rupture criterion = 'tension', mbl = "//str(mbl)//", t_break = 0.005 /"//nl
            call run_text(text//pull_numerics, planar, error)
            if (allocated(error)) return
            call run_text(text//"&numerics model = '3d', nodes = 61, courant = 1.0, t_end = 0.45 /", three, error)
         end if
         if (allocated(error)) return
         call compare()
         if (allocated(error)) return
      end do
   contains

      !> The 3-D run's break against the planar one's.
      subroutine compare()
         associate (p => planar%rod%summary, q => three%rod%summary)
            write (output_unit, '(4x,a,2f11.7,a,es9.2,a,2f7.2,a,2f7.2,a,es9.2)') trim(names(i))// &
               ': break time planar, 3-D', p%break_time, q%break_time, ' s (', q%break_time - p%break_time, &
               ' s); node', p%break_s, q%break_s, ' m; cell', p%break_cell_s, q%break_cell_s, &
               ' m; 3-D tension/MBL - 1', q%break_tension/mbl - 1
            call check(error, q%broke .and. q%by_tension, trim(names(i))//': the 3-D run does not break')
            if (allocated(error)) return
            call check(error, abs(q%break_time - p%break_time) <= merge(3.0e-9_dp, 1.0e-12_dp, i == 3), &
                       trim(names(i))//': 3-D break at '// &
                       str(q%break_time)//' s, planar at '//str(p%break_time)//' s')
            if (allocated(error)) return
            call check(error, q%break_s == p%break_s .and. q%break_cell_s == p%break_cell_s, trim(names(i))// &
                       ': 3-D break at s = '//str(q%break_s)//' m (cell '//str(q%break_cell_s)//' m), planar at '// &
                       str(p%break_s)//' m (cell '//str(p%break_cell_s)//' m)')
            if (allocated(error)) return
            call check(error, abs(q%break_tension/mbl - 1) <= rupture_tolerance, trim(names(i))// &
                       ': 3-D tension at the break '//str(q%break_tension)//' N')
            if (allocated(error)) return
         end associate
      end subroutine compare
   end subroutine test_model3d

   !> The pull scene with an MBL above anything it reaches by t_end (7 kN; its largest cell
   !> tension is 6.53 kN): no break, the largest cell tension below the MBL and above the
   !> static one, where and when, and the summary says so; the run is the run without
   !> &rupture (history to the bit).
   subroutine test_never_reached(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim, plain
      character(:), allocatable :: text
      integer :: m
      call run_text(pull_scene//pull_numerics//"&rupture criterion = 'tension', mbl = 9000 /", sim, error)
      if (allocated(error)) return
      call run_text(pull_scene//pull_numerics, plain, error)
      if (allocated(error)) return
      text = summary_text(sim%rod%summary, sim%rod%info, sim%rod%history%end_labels)
      associate (s => sim%rod%summary)
         write (output_unit, '(4x,a,f9.2,a,f7.3,a,f7.4,a)') 'largest tension', s%largest_tension, ' N at s =', &
            s%largest_tension_s, ' m, t =', s%largest_tension_time, ' s'
         call check(error, .not. s%broke .and. s%by_tension, 'a break, or not by tension')
         if (allocated(error)) return
         call check(error, s%largest_tension > sim%rod%static_max_tension .and. s%largest_tension < 9000, &
                    'largest tension '// &
                    str(s%largest_tension)//' N')
         if (allocated(error)) return
         call check(error, index(text, 'the tension never reached the MBL') > 0, 'the summary does not say so: '//text)
         if (allocated(error)) return
      end associate
      m = plain%rod%history%n
      call check(error, sim%rod%history%n == m, 'steps differ')
      if (allocated(error)) return
      call check(error, all(sim%rod%history%ends(:, :, 0:m) == plain%rod%history%ends(:, :, 0:m)), &
                 'the history differs from the run without &rupture')
   end subroutine test_never_reached

   !> An MBL at or below the largest static tension (the pull scene's 1.415 kN) is bad input
   !> found after the statics: stat_input, one line naming the file, the group, mbl and its
   !> value, and the static tension.
   subroutine test_static_mbl(error)
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      type(error_type), allocatable :: err
      call prepare_text(pull_scene//pull_numerics//"&rupture criterion = 'tension', mbl = 1400 /", sim, err)
      call check(error, allocated(err), 'accepted an MBL below the static tension')
      if (allocated(error)) return
      write (output_unit, '(4x,a)') err%message
      call check(error, err%stat == stat_input .and. index(err%message, new_line('a')) == 0, 'not one line of bad input')
      if (allocated(error)) return
      call check(error, index(err%message, path) > 0 .and. index(err%message, '&rupture: mbl = 1400') > 0 .and. &
                 index(err%message, 'the line would part in statics') > 0 .and. index(err%message, '1.415 kN') > 0, &
                 'the message lacks the file, group, value or static tension: '//err%message)
   end subroutine test_static_mbl
end module suite_rupture
