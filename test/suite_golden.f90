!> Golden regression tests: cases run through the simulation driver and
!> compared with figures stored when they were first made, so that a
!> restructuring cannot drift unnoticed.
!>
!> test/golden/reference_v0.1.txt holds the figures of xcable 0.1 (the
!> paper's box scheme) for the g_*.nml cases of test/golden: status, static
!> span and sag, the summary figures and checksums (sum and sum of squares)
!> of the snapshot fields at two snapshots. The box scheme of this version
!> must reproduce them to 1e-12 relative (the arithmetic is the same).
!> test/golden/reference_rod.txt pins the rod discretisation in the same way.
module suite_golden
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_error, only: fatal_error
   use xcable_core_strings, only: str
   use xcable_io_input, only: case_config, read_config
   use xcable_driver_simulation, only: simulation
   use xcable_driver_records, only: run_observer, static_info, run_summary, field_names, n_fields
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_golden, snapshot_store, golden_values

   !> Keeps every snapshot.
   type, extends(run_observer) :: snapshot_store
      integer :: n = 0
      real(dp), allocatable :: times(:)
      real(dp), allocatable :: fields(:, :, :)
   contains
      procedure :: static => store_static
      procedure :: snapshot => store_snapshot
   end type snapshot_store

contains

   subroutine collect_golden(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('box_scheme_v0.1', test_box), &
               new_unittest('rod', test_rod)]
   end subroutine collect_golden

   subroutine store_static(self, info, error)
      class(snapshot_store), intent(inout) :: self
      type(static_info), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
   end subroutine store_static

   subroutine store_snapshot(self, t, fields, error)
      class(snapshot_store), intent(inout) :: self
      real(dp), intent(in) :: t
      real(dp), intent(in) :: fields(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: tt(:), ff(:, :, :)
      if (.not. allocated(self%times)) then
         allocate (self%times(64), self%fields(size(fields, 1), n_fields, 64))
      else if (self%n == size(self%times)) then
         allocate (tt(2*self%n), ff(size(fields, 1), n_fields, 2*self%n))
         tt(1:self%n) = self%times
         ff(:, :, 1:self%n) = self%fields
         call move_alloc(tt, self%times)
         call move_alloc(ff, self%fields)
      end if
      self%n = self%n + 1
      self%times(self%n) = t
      self%fields(:, :, self%n) = fields
   end subroutine store_snapshot

   !> Run a case and list its figures as (name, value) pairs in the reference's naming.
   subroutine golden_values(path, names, values, status, error)
      !> Namelist file.
      character(*), intent(in) :: path
      !> Names and values of the figures.
      character(len=48), allocatable, intent(out) :: names(:)
      real(dp), allocatable, intent(out) :: values(:)
      !> 'complete' or 'failed'.
      character(:), allocatable, intent(out) :: status
      !> Error when the case cannot be read or prepared.
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      type(simulation) :: sim
      type(snapshot_store) :: store
      type(error_type), allocatable :: run_error
      type(static_info), pointer :: info
      type(run_summary), pointer :: s
      integer :: it, k
      integer :: picks(2)
      character(len=*), parameter :: checked(6) = [character(len=9) :: 'tension', 'u', 'v', 'x', 'z', 'curvature']
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      call sim%run(store, run_error)
      status = merge('failed  ', 'complete', allocated(run_error))
      status = trim(status)
      info => sim%static()
      s => sim%summary()
      allocate (names(0), values(0))
      call add('static_span', info%span)
      call add('static_sag', info%sag)
      call add('peak_end_speed', s%peak_end_speed)
      call add('peak_end_speed_time', s%peak_end_speed_time)
      call add('min_fixed_end_tension', s%min_fixed_end_tension)
      call add('min_fixed_end_tension_time', s%min_fixed_end_tension_time)
      call add('front_arrival_time', s%front_arrival_time)
      call add('energy_drift', s%energy_drift)
      call add('max_unit_norm_error', s%max_unit_norm_error)
      call add('time_reached', s%time_reached)
      call add('steps', real(s%steps, dp))
      call add('newton_iterations', real(s%newton_iterations, dp))
      call add('rejected_steps', real(s%rejected_steps, dp))
      ! Snapshots (0-based, as in the reference): one third of the way and the last.
      picks = [store%n/3, store%n - 1]
      do it = 1, 2
         call add('snapshot_time_'//str(picks(it)), store%times(picks(it) + 1))
         do k = 1, size(checked)
            associate (f => store%fields(:, findloc(field_names, checked(k), 1), picks(it) + 1))
               call add(trim(checked(k))//'_sum_'//str(picks(it)), sum(f))
               call add(trim(checked(k))//'_sumsq_'//str(picks(it)), sum(f**2))
            end associate
         end do
      end do

   contains

      subroutine add(name, value)
         character(*), intent(in) :: name
         real(dp), intent(in) :: value
         names = [names, [character(len=48) :: name]]
         values = [values, value]
      end subroutine add
   end subroutine golden_values

   !> Compare every case of a reference file; tol is relative (absolute for zero references).
   subroutine compare_reference(reference, tol, error)
      character(*), intent(in) :: reference
      real(dp), intent(in) :: tol
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: line, case_name, key, text
      character(len=48), allocatable :: names(:)
      real(dp), allocatable :: values(:)
      character(:), allocatable :: status, current
      real(dp) :: expected, worst, dev
      integer :: unit, ios, i, compared
      character(len=96) :: worst_name
      open (newunit=unit, file=reference, status='old', action='read', iostat=ios)
      call check(error, ios == 0, 'cannot open '//reference)
      if (allocated(error)) return
      current = ''
      worst = 0
      compared = 0
      worst_name = ''
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (len_trim(line) == 0 .or. line(1:1) == '#') cycle
         read (line, *) case_name, key, text
         if (trim(case_name) /= current) then
            current = trim(case_name)
            call golden_values('test/golden/'//current//'.nml', names, values, status, error)
            if (allocated(error)) then
               error%message = current//': '//error%message
               close (unit)
               return
            end if
         end if
         if (trim(key) == 'status') then
            call check(error, trim(text) == status, current//': status '//status//', expected '//trim(text))
            if (allocated(error)) exit
            cycle
         end if
         read (text, *) expected
         i = findloc(names, trim(key), 1)
         call check(error, i > 0, current//': no figure '//trim(key))
         if (allocated(error)) exit
         dev = abs(values(i) - expected)/max(abs(expected), 1.0e-300_dp)
         if (expected == 0) dev = abs(values(i))
         compared = compared + 1
         if (dev > worst) then
            worst = dev
            worst_name = current//' '//trim(key)
         end if
         call check(error, dev <= tol, current//': '//trim(key)//' = '//str(values(i))//', reference '// &
                    str(expected)//' (relative difference '//str(dev)//', tolerance '//str(tol)//')')
         if (allocated(error)) exit
      end do
      close (unit)
      write (output_unit, '(4x,a,i0,a,es10.2,a)') reference//': ', compared, ' figures, largest relative difference ', &
         worst, ' ('//trim(worst_name)//')'
   end subroutine compare_reference

   !> The box scheme reproduces version 0.1.
   subroutine test_box(error)
      type(error_type), allocatable, intent(out) :: error
      call compare_reference('test/golden/reference_v0.1.txt', 1.0e-12_dp, error)
   end subroutine test_box

   !> The rod discretisation reproduces the figures pinned when it was made
   !> (five scenes: the paper's fast 315 kN break through the buckling, the
   !> slow 180 kN one with the lumped mass, an inclined line parting in the
   !> middle, a slack swing without compression and with theta 0.6, a mass
   !> under a heaving fairlead). With XCABLE_WRITE_GOLDEN=<file> in the
   !> environment the figures are written to <file> instead, and the test
   !> fails (so that a new reference is never taken silently).
   subroutine test_rod(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: cases(5) = [character(len=14) :: 'r_fast315', 'r_slow180', 'r_break_middle', &
                                                 'r_swing', 'r_heave_mass']
      character(len=512) :: target
      integer :: length, status
      call get_environment_variable('XCABLE_WRITE_GOLDEN', target, length, status)
      if (status == 0 .and. length > 0) then
         call write_reference(trim(target), cases, error)
         if (.not. allocated(error)) call fatal_error(error, 'reference written to '//trim(target)//' (not a pass)')
         return
      end if
      call compare_reference('test/golden/reference_rod.txt', 1.0e-9_dp, error)
   end subroutine test_rod

   !> Write the figures of the cases in the reference's format.
   subroutine write_reference(path, cases, error)
      character(*), intent(in) :: path
      character(len=*), intent(in) :: cases(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=48), allocatable :: names(:)
      real(dp), allocatable :: values(:)
      character(:), allocatable :: status
      integer :: unit, i, k
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') '# Figures of the rod scheme (test/suite_golden.f90, test_rod), written with XCABLE_WRITE_GOLDEN.'
      do i = 1, size(cases)
         call golden_values('test/golden/'//trim(cases(i))//'.nml', names, values, status, error)
         if (allocated(error)) then
            close (unit)
            return
         end if
         write (unit, '(a)') trim(cases(i))//' status '//status
         do k = 1, size(names)
            write (unit, '(a,1x,a,1x,es24.16e3)') trim(cases(i)), trim(names(k)), values(k)
         end do
      end do
      close (unit)
   end subroutine write_reference
end module suite_golden
