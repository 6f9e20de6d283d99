!> The independent reference for the slack releases: the released end's
!> position in the peer lumped-mass runs (bench/peer, lumped.py, one TSV per
!> case and grid, a row every 0.01 s with columns t, end_x, end_z, ...).
!> Their grid N counts segments (N + 1 nodes).
module stress_reference
   use xcable_core_kinds, only: dp
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   private
   public :: peer_grids, peer_position

   !> Grids (segments) of the peer runs, coarse to fine.
   integer, parameter :: peer_grids(6) = [200, 400, 800, 1600, 3200, 6400]

contains

   !> Released end's position of one peer run at the given times; found is
   !> false when its file is absent or unreadable (x, z NaN where a time is missing).
   subroutine peer_position(dir, tension, t_break, segments, times, x, z, found)
      !> Directory of the peer runs (bench/peer/runs).
      character(*), intent(in) :: dir
      !> Static end tension, N; breaking time, s (5 ms: 'fast', 50 ms: 'slow').
      real(dp), intent(in) :: tension, t_break
      !> Segments of the peer grid.
      integer, intent(in) :: segments
      !> Times, s.
      real(dp), intent(in) :: times(:)
      !> Position of the released end at each time, m.
      real(dp), intent(out) :: x(:), z(:)
      !> Whether the file was read.
      logical, intent(out) :: found
      character(len=512) :: path, line
      character(len=4) :: speed
      real(dp) :: t, xi, zi
      integer :: u, ios, k
      x = ieee_value(1.0_dp, ieee_quiet_nan)
      z = x
      speed = merge('fast', 'slow', t_break < 0.02_dp)
      write (path, '(a,"/lumped_slack_",i0,"kN_",a,"_N",i0,".tsv")') trim(dir), nint(tension/1.0e3_dp), trim(speed), &
         segments
      open (newunit=u, file=trim(path), status='old', action='read', iostat=ios)
      found = ios == 0
      if (.not. found) return
      read (u, '(a)', iostat=ios) line
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         read (line, *, iostat=ios) t, xi, zi
         if (ios /= 0) cycle
         do k = 1, size(times)
            if (abs(t - times(k)) <= 1.0e-6_dp) then
               x(k) = xi
               z(k) = zi
            end if
         end do
      end do
      close (u)
   end subroutine peer_position
end module stress_reference
