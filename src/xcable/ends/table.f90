!> A time table of a vector (force components or displacements x, y, z), for
!> the 'table' histories of force and moving ends.
!>
!> Between rows the value is a cubic Hermite interpolant whose slopes are the
!> centred differences of the rows (one-sided at the first and last row), so
!> that a prescribed displacement has a continuous velocity; `linear` gives
!> straight segments instead (a force table). Before the first time the first
!> row holds, after the last the last row.
module xcable_ends_table
   use xcable_core_kinds, only: dp
   use xcable_io_config, only: end_config
   implicit none
   private
   public :: time_table, group_table

   !> Rows of a table.
   type :: time_table
      !> Times, strictly increasing, s.
      real(dp), allocatable :: time(:)
      !> Values (components, rows): x, y, z for the ends.
      real(dp), allocatable :: value(:, :)
      !> Straight segments instead of the cubic.
      logical :: linear = .false.
   contains
      !> Value at time t.
      procedure :: at => table_at
      !> Time derivative at time t.
      procedure :: rate => table_rate
   end type time_table

contains

   !> The table of an &end_a / &end_b group (no rows when it has fewer than 2).
   function group_table(config, linear) result(table)
      !> The group.
      type(end_config), intent(in) :: config
      !> Straight segments (a force table) instead of the cubic.
      logical, intent(in) :: linear
      type(time_table) :: table
      table%linear = linear
      if (config%table_rows < 2) return
      table%time = config%table_time(1:config%table_rows)
      allocate (table%value(3, config%table_rows))
      table%value(1, :) = config%table_x(1:config%table_rows)
      table%value(2, :) = config%table_y(1:config%table_rows)
      table%value(3, :) = config%table_z(1:config%table_rows)
   end function group_table

   !> Row interval holding t and the local coordinate u in [0, 1].
   pure subroutine locate(self, t, i, u, outside)
      class(time_table), intent(in) :: self
      real(dp), intent(in) :: t
      integer, intent(out) :: i
      real(dp), intent(out) :: u
      integer, intent(out) :: outside
      integer :: lo, hi, mid, n
      n = size(self%time)
      outside = 0
      if (t <= self%time(1)) then
         i = 1; u = 0; outside = -1
         return
      end if
      if (t >= self%time(n)) then
         i = n - 1; u = 1; outside = 1
         return
      end if
      lo = 1
      hi = n
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (self%time(mid) <= t) then
            lo = mid
         else
            hi = mid
         end if
      end do
      i = lo
      u = (t - self%time(i))/(self%time(i + 1) - self%time(i))
   end subroutine locate

   !> Slope of the cubic at row j.
   pure function slope(self, j) result(d)
      class(time_table), intent(in) :: self
      integer, intent(in) :: j
      real(dp) :: d(size(self%value, 1))
      integer :: n
      n = size(self%time)
      if (j == 1) then
         d = (self%value(:, 2) - self%value(:, 1))/(self%time(2) - self%time(1))
      else if (j == n) then
         d = (self%value(:, n) - self%value(:, n - 1))/(self%time(n) - self%time(n - 1))
      else
         d = (self%value(:, j + 1) - self%value(:, j - 1))/(self%time(j + 1) - self%time(j - 1))
      end if
   end function slope

   !> Value at time t.
   pure function table_at(self, t) result(v)
      !> Table.
      class(time_table), intent(in) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      real(dp) :: v(size(self%value, 1))
      integer :: i, outside
      real(dp) :: u, h, h00, h10, h01, h11
      call locate(self, t, i, u, outside)
      if (outside < 0) then
         v = self%value(:, 1)
      else if (outside > 0) then
         v = self%value(:, size(self%time))
      else if (self%linear) then
         v = (1 - u)*self%value(:, i) + u*self%value(:, i + 1)
      else
         h = self%time(i + 1) - self%time(i)
         h00 = (1 + 2*u)*(1 - u)**2
         h10 = u*(1 - u)**2
         h01 = u*u*(3 - 2*u)
         h11 = u*u*(u - 1)
         v = h00*self%value(:, i) + h10*h*slope(self, i) + h01*self%value(:, i + 1) + h11*h*slope(self, i + 1)
      end if
   end function table_at

   !> Time derivative at time t (zero outside the table).
   pure function table_rate(self, t) result(v)
      !> Table.
      class(time_table), intent(in) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      real(dp) :: v(size(self%value, 1))
      integer :: i, outside
      real(dp) :: u, h
      call locate(self, t, i, u, outside)
      h = self%time(i + 1) - self%time(i)
      if (outside /= 0) then
         v = 0
      else if (self%linear) then
         v = (self%value(:, i + 1) - self%value(:, i))/h
      else
         v = (6*u*u - 6*u)/h*self%value(:, i) + (3*u*u - 4*u + 1)*slope(self, i) &
             + (6*u - 6*u*u)/h*self%value(:, i + 1) + (3*u*u - 2*u)*slope(self, i + 1)
      end if
   end function table_rate
end module xcable_ends_table
