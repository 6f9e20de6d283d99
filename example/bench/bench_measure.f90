!> Errors of a benchmark run: the breaking-end speed (its peak and its
!> plateau) and the 1 % drop at the fixed end against simple-wave theory, and
!> the tension field against a reference field built from the scheme's own
!> fine runs (Richardson-extrapolated when the observed order allows).
module bench_measure
   use xcable_core_kinds, only: dp
   use bench_runs, only: run_result
   use bench_theory, only: wave_reference
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   implicit none
   private
   public :: run_errors, field_reference, measure, compression_time, build_field_reference, save_reference, &
             load_reference, compare_references

   !> Errors of one run (NaN: not measured).
   type :: run_errors
      !> Time at which the fixed end goes into compression (end of the window), s.
      real(dp) :: t_tension = 0
      !> (peak end speed - theory) / theory, while the fixed end is in tension.
      real(dp) :: speed = 0
      !> (mean end speed after the ramp - theory) / theory, while the fixed end is in tension.
      real(dp) :: plateau = 0
      !> Time of the 1 % drop of the fixed-end tension minus theory, s.
      real(dp) :: drop = 0
      !> Mean and max |T - T_ref| / T_s over nodes and snapshots in the window.
      real(dp) :: field_mean = 0, field_max = 0
   end type run_errors

   !> Reference tension field of one scheme and case.
   type :: field_reference
      logical :: ok = .false.
      !> Grid (m), snapshot times (s), tension (nodes, snapshots), N.
      real(dp), allocatable :: s(:), times(:), tension(:, :)
      !> Observed order from 241/481/961 nodes, and whether extrapolated.
      real(dp) :: order = 0
      logical :: extrapolated = .false.
      !> Mean |correction| / T_s (extrapolated), or the estimated mean error of the 961-node run: the uncertainty.
      real(dp) :: uncertainty = 0
      !> Where it comes from.
      character(len=160) :: source = ''
   end type field_reference

contains

   !> A quiet NaN.
   real(dp) function nan()
      nan = ieee_value(1.0_dp, ieee_quiet_nan)
   end function nan

   !> First time the fixed-end tension is <= 0 (end of the history if never), s.
   real(dp) function compression_time(r)
      !> A run whose history was read.
      type(run_result), intent(in) :: r
      integer :: i
      compression_time = r%time(size(r%time))
      do i = 2, size(r%time)
         if (r%fixed_end_tension(i) <= 0) then
            compression_time = r%time(i - 1) + (r%time(i) - r%time(i - 1))*r%fixed_end_tension(i - 1)/ &
                               (r%fixed_end_tension(i - 1) - r%fixed_end_tension(i))
            return
         end if
      end do
   end function compression_time

   !> Errors of one run against the references.
   subroutine measure(r, w, f, length, tension, t_break, e)
      !> The run.
      type(run_result), intent(in) :: r
      !> Simple-wave references of its case.
      type(wave_reference), intent(in) :: w
      !> Reference tension field of its scheme.
      type(field_reference), intent(in) :: f
      !> Cable length (m), static end tension T_s (N), breaking time (s).
      real(dp), intent(in) :: length, tension, t_break
      !> The errors.
      type(run_errors), intent(out) :: e
      integer :: i, j, k, m, nn, cnt
      real(dp) :: peak, t0, x, tref, err, area, span, a, b
      e%speed = nan()
      e%plateau = nan()
      e%drop = nan()
      e%field_mean = nan()
      e%field_max = nan()
      if (.not. r%ok) return
      e%t_tension = compression_time(r)
      ! Peak, and the time mean after the ramp (trapezoids, the part of each step inside the window).
      peak = 0
      area = 0
      span = 0
      do i = 1, size(r%time)
         if (r%time(i) <= e%t_tension) peak = max(peak, r%end_speed(i))
         if (i == 1) cycle
         a = max(r%time(i - 1), t_break)
         b = min(r%time(i), e%t_tension)
         if (b <= a) cycle
         area = area + (b - a)*0.5_dp*(speed_at(a, i) + speed_at(b, i))
         span = span + (b - a)
      end do
      e%speed = (peak - w%end_speed)/w%end_speed
      if (span > 0) e%plateau = (area/span - w%end_speed)/w%end_speed
      t0 = r%fixed_end_tension(1)
      do i = 2, size(r%time)
         if (r%fixed_end_tension(i) <= 0.99_dp*t0) then
            e%drop = r%time(i - 1) + (r%time(i) - r%time(i - 1))*(0.99_dp*t0 - r%fixed_end_tension(i - 1))/ &
                     (r%fixed_end_tension(i) - r%fixed_end_tension(i - 1)) - w%drop_time
            exit
         end if
      end do
      if (.not. f%ok .or. .not. allocated(r%tension)) return
      nn = size(r%tension, 1)
      if (nn < 2) return
      e%field_mean = 0
      e%field_max = 0
      cnt = 0
      do j = 1, size(f%times)
         m = snapshot_index(r, f%times(j))
         if (m == 0) then
            e%field_mean = nan()
            e%field_max = nan()
            return
         end if
         do k = 1, nn
            x = length*(k - 1)/(nn - 1)
            tref = interpolate(f%s, f%tension(:, j), x)
            err = abs(r%tension(k, m) - tref)/tension
            e%field_mean = e%field_mean + err
            e%field_max = max(e%field_max, err)
            cnt = cnt + 1
         end do
      end do
      e%field_mean = e%field_mean/cnt

   contains

      !> End speed at time t in [time(i-1), time(i)], linear in the step.
      real(dp) function speed_at(t, i)
         real(dp), intent(in) :: t
         integer, intent(in) :: i
         speed_at = r%end_speed(i - 1) + (r%end_speed(i) - r%end_speed(i - 1))*(t - r%time(i - 1))/ &
                    (r%time(i) - r%time(i - 1))
      end function speed_at
   end subroutine measure

   !> Index of the snapshot at time t (0: none).
   integer function snapshot_index(r, t) result(m)
      !> The run.
      type(run_result), intent(in) :: r
      !> Time, s.
      real(dp), intent(in) :: t
      integer :: i
      m = 0
      if (.not. allocated(r%snapshot_time)) return
      do i = 1, size(r%snapshot_time)
         if (abs(r%snapshot_time(i) - t) < 1.0e-7_dp) then
            m = i
            return
         end if
      end do
   end function snapshot_index

   !> Tension at node k of a run at snapshot time t (NaN if absent).
   real(dp) function value_at(r, k, t)
      !> The run.
      type(run_result), intent(in) :: r
      !> Node.
      integer, intent(in) :: k
      !> Snapshot time, s.
      real(dp), intent(in) :: t
      integer :: m
      value_at = nan()
      if (.not. allocated(r%tension)) return
      m = snapshot_index(r, t)
      if (m > 0 .and. k <= size(r%tension, 1)) value_at = r%tension(k, m)
   end function value_at

   !> The reference field from the Courant-1 runs on 241, 481 and 961 nodes: the
   !> snapshots while the fixed end of the finest run is in tension; Richardson
   !> with p = 2 on 481/961 nodes when the observed order is within 0.3 of 2,
   !> else the 961-node run itself.
   subroutine build_field_reference(r241, r481, r961, length, tension, f)
      !> The three runs.
      type(run_result), intent(in) :: r241, r481, r961
      !> Cable length (m), static end tension T_s (N).
      real(dp), intent(in) :: length, tension
      !> The reference (ok when all three runs were read).
      type(field_reference), intent(out) :: f
      integer :: j, k, nw, nn
      real(dp) :: t_window, d1, d2, cnt
      if (.not. (r241%ok .and. r481%ok .and. r961%ok)) return
      if (.not. (allocated(r241%tension) .and. allocated(r481%tension) .and. allocated(r961%tension))) return
      if (size(r241%tension, 1) /= 241 .or. size(r481%tension, 1) /= 481 .or. size(r961%tension, 1) /= 961) return
      t_window = compression_time(r961)
      nw = count(r961%snapshot_time > 0 .and. r961%snapshot_time <= t_window)
      if (nw == 0) return
      f%times = pack(r961%snapshot_time, r961%snapshot_time > 0 .and. r961%snapshot_time <= t_window)
      ! Observed order on the 241-node points.
      d1 = 0
      d2 = 0
      cnt = 0
      do j = 1, nw
         do k = 1, 241
            d1 = d1 + abs(value_at(r481, 2*k - 1, f%times(j)) - value_at(r241, k, f%times(j)))
            d2 = d2 + abs(value_at(r961, 4*k - 3, f%times(j)) - value_at(r481, 2*k - 1, f%times(j)))
            cnt = cnt + 1
         end do
      end do
      f%order = log(d1/d2)/log(2.0_dp)
      f%extrapolated = abs(f%order - 2) <= 0.3_dp
      if (f%extrapolated) then
         nn = 481
         allocate (f%s(nn), f%tension(nn, nw))
         f%uncertainty = 0
         do j = 1, nw
            do k = 1, nn
               f%s(k) = length*(k - 1)/(nn - 1)
               f%tension(k, j) = value_at(r961, 2*k - 1, f%times(j)) + &
                                 (value_at(r961, 2*k - 1, f%times(j)) - value_at(r481, k, f%times(j)))/3
               f%uncertainty = f%uncertainty + abs(value_at(r961, 2*k - 1, f%times(j)) - value_at(r481, k, f%times(j)))/3
            end do
         end do
         f%uncertainty = f%uncertainty/(nn*nw)/tension
         f%source = '961 and 481 nodes at Courant 1, Richardson-extrapolated (p = 2)'
      else
         nn = 961
         allocate (f%s(nn), f%tension(nn, nw))
         do j = 1, nw
            do k = 1, nn
               f%s(k) = length*(k - 1)/(nn - 1)
               f%tension(k, j) = value_at(r961, k, f%times(j))
            end do
         end do
         f%uncertainty = d2/cnt/tension/max(2**f%order - 1, 1.0_dp)
         f%source = '961 nodes at Courant 1 (observed order too far from 2 to extrapolate)'
      end if
      f%ok = .not. any(ieee_is_nan(f%tension))
   end subroutine build_field_reference

   !> Save a reference for `quick` runs.
   subroutine save_reference(f, path)
      !> The reference.
      type(field_reference), intent(in) :: f
      !> File (stream, unformatted).
      character(*), intent(in) :: path
      integer :: unit, ios, m
      if (.not. f%ok) return
      open (newunit=unit, file=path, status='replace', action='write', access='stream', form='unformatted', iostat=ios)
      if (ios /= 0) return
      m = len_trim(f%source)
      write (unit) size(f%s), size(f%times), f%order, f%extrapolated, f%uncertainty, m, f%source(1:m), f%s, f%times, &
         f%tension
      close (unit)
   end subroutine save_reference

   !> A reference saved by the last full run (ok false if there is none).
   subroutine load_reference(path, f)
      !> File written by save_reference.
      character(*), intent(in) :: path
      !> The reference.
      type(field_reference), intent(out) :: f
      integer :: unit, ios, nn, nw, m
      open (newunit=unit, file=path, status='old', action='read', access='stream', form='unformatted', iostat=ios)
      if (ios /= 0) return
      read (unit, iostat=ios) nn, nw, f%order, f%extrapolated, f%uncertainty, m
      if (ios /= 0 .or. nn < 2 .or. nw < 1 .or. m < 1 .or. m > len(f%source)) then
         close (unit)
         return
      end if
      f%source = ''
      read (unit, iostat=ios) f%source(1:m)
      allocate (f%s(nn), f%times(nw), f%tension(nn, nw))
      if (ios == 0) read (unit, iostat=ios) f%s, f%times, f%tension
      close (unit)
      f%ok = ios == 0
      f%source = trim(f%source)//' (saved by the last full run)'
   end subroutine load_reference

   !> Mean and max |T_a - T_b| / T_s of two references at the snapshots they share,
   !> on a 481-node grid (linear interpolation of both).
   subroutine compare_references(a, b, length, tension, mean, largest, shared)
      !> The two references.
      type(field_reference), intent(in) :: a, b
      !> Cable length (m), static end tension T_s (N).
      real(dp), intent(in) :: length, tension
      !> Mean and max of the difference / T_s (NaN: nothing shared).
      real(dp), intent(out) :: mean, largest
      !> Snapshots compared.
      integer, intent(out) :: shared
      integer :: i, j, k, cnt
      real(dp) :: x, d
      mean = nan()
      largest = nan()
      shared = 0
      if (.not. (a%ok .and. b%ok)) return
      mean = 0
      largest = 0
      cnt = 0
      do i = 1, size(a%times)
         do j = 1, size(b%times)
            if (abs(a%times(i) - b%times(j)) > 1.0e-7_dp) cycle
            shared = shared + 1
            do k = 1, 481
               x = length*(k - 1)/480
               d = abs(interpolate(a%s, a%tension(:, i), x) - interpolate(b%s, b%tension(:, j), x))/tension
               mean = mean + d
               largest = max(largest, d)
               cnt = cnt + 1
            end do
         end do
      end do
      if (cnt > 0) then
         mean = mean/cnt
      else
         mean = nan()
         largest = nan()
      end if
   end subroutine compare_references

   !> Linear interpolation on an increasing uniform grid (exact at its points).
   pure real(dp) function interpolate(xg, yg, x)
      !> Grid and values.
      real(dp), intent(in) :: xg(:), yg(:)
      !> Where.
      real(dp), intent(in) :: x
      integer :: i
      real(dp) :: w
      i = max(1, min(size(xg) - 1, int((x - xg(1))/(xg(size(xg)) - xg(1))*(size(xg) - 1)) + 1))
      do while (i > 1 .and. xg(i) > x)
         i = i - 1
      end do
      do while (i < size(xg) - 1 .and. xg(i + 1) < x)
         i = i + 1
      end do
      w = (x - xg(i))/(xg(i + 1) - xg(i))
      if (abs(x - xg(i)) < 1.0e-9_dp) w = 0
      if (abs(x - xg(i + 1)) < 1.0e-9_dp) w = 1
      interpolate = (1 - w)*yg(i) + w*yg(i + 1)
   end function interpolate
end module bench_measure
