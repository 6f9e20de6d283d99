!> Loads distributed along the cable: the abstract type every such load
!> extends (fluid drag and added mass today).
!>
!> The rod (model/rod.f90) asks a load for the force per unstretched length on
!> one cell, given the cell's state at the time the step is centred on: its mid
!> position x and unstretched length ds, its stretch vector e (the cell vector
!> over its unstretched length, so |e| = 1 + eps; the cell's ends are
!> x -+ e ds / 2), its velocity w and its acceleration a (the means of its two
!> nodes'). It also asks for the derivatives of that force with respect to x, e,
!> w and a, from which it builds the Jacobian; the generic finite-difference
!> tests check them. A load's work is booked by the driver from the forces the
!> rod applied, so the energy ledger closes with any load. A load that is
!> conservative and constant (buoyancy) is given as a lift per unstretched
!> length instead, which the rod adds to the weight (and so to the gravity
!> energy). A new load is one module extending `cable_load` and one line in
!> loads/factory.f90 where the loads of a case are built.
!>
!> Frame: x horizontal, z vertical (up); forces in N.
module xcable_loads_load
   use xcable_core_kinds, only: dp
   implicit none
   private
   public :: cable_load, load_slot, cell_kinematics, measure_names, load_measures, note_measures, any_skew, &
             loads_in_statics, any_static_form

   !> A distributed load.
   type, abstract :: cable_load
   contains
      !> Name, for the output's list of terms.
      procedure(name_interface), deferred :: name
      !> Force per unstretched length on a cell and its derivatives.
      procedure(cell_force_interface), deferred :: cell_force
      !> Upward force per unstretched length that does not depend on the motion, N/m.
      procedure :: lift => load_lift
      !> Whether the load has a 3-D form (cell_force3) for the 3-D rod (model/rod3d.f90).
      procedure :: has_3d => load_has_3d
      !> The same in 3-D: vectors (x, y, z), z up; derivatives 3x3.
      procedure :: cell_force3 => load_cell_force3
      !> Whether the load shares its force unequally between a cell's two nodes (cell_skew).
      procedure :: has_skew => load_has_skew
      !> The unequal share: node a of the cell takes ds (f / 2 + g), node b ds (f / 2 - g), per
      !> unstretched length g and its derivatives, in either dimension (2 or 3 components, the
      !> last vertical). A load with a potential that varies along the cell (a stiff contact)
      !> needs it: with equal shares, nodes moving alternately up and down leave every cell's
      !> mean unchanged, a mode the load would not resist.
      procedure :: cell_skew => load_cell_skew
      !> Name of a length the load measures along the cable for the history (a dataset
      !> /history/<name> and the summary's static_<name>; '' : none, the default).
      procedure :: measure_name => load_measure_name
      !> That length on one cell with its ends at r1 and r2 (any dimension, the last component
      !> vertical) and unstretched length ds, m.
      procedure :: cell_measure => load_cell_measure
      !> A line for the run's log about the measure at the start, of a cable of unstretched
      !> length (m) ('' : nothing to say, the default).
      procedure :: measure_note => load_measure_note
      !> Height of a floor the load holds the line above (a seabed's bottom) under the
      !> horizontal point p (x, or x and y), m; -huge: none (the default). The statics say when
      !> a line is too long to be taut over it (model/rod_statics.f90).
      procedure :: floor => load_floor
      !> Whether the statics (on) or the dynamics (off) evaluates the load next, with the line's
      !> axial stiffness near zero strain (N) and weight in the fluid (N/m) and the share of its
      !> static form to apply (a continuation): a load may act in the statics as the dynamics
      !> cannot (the seabed's static friction). Default: the same.
      procedure :: set_statics => load_set_statics
      !> Whether the load acts otherwise in the statics than in the dynamics (default: no).
      procedure :: static_form => load_static_form
   end type cable_load

   !> A slot of an array of loads: the load, and the part of the line it acts on (the cells
   !> whose middle lies in s_from <= s < s_to, arc length from end a of the whole line, m; the
   !> whole line by default). A line of segments has one slot per load and segment.
   type :: load_slot
      class(cable_load), allocatable :: load
      real(dp) :: s_from = -huge(1.0_dp), s_to = huge(1.0_dp)
   contains
      !> Whether the load acts on the cell between arc lengths sa and sb.
      procedure :: acts_on => slot_acts_on
   end type load_slot

   abstract interface
      pure function name_interface(self) result(name)
         import :: cable_load
         class(cable_load), intent(in) :: self
         character(:), allocatable :: name
      end function name_interface

      !> Force per unstretched length f on a cell with mid position x, unstretched length ds,
      !> stretch vector e (so that its ends are x -+ e ds / 2), velocity w and acceleration a,
      !> and df/dx, df/de, df/dw, df/da (2x2, row i = component i of f).
      pure subroutine cell_force_interface(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
         import :: cable_load, dp
         class(cable_load), intent(in) :: self
         real(dp), intent(in) :: x(2), ds, e(2), w(2), a(2)
         real(dp), intent(out) :: f(2), df_dx(2, 2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      end subroutine cell_force_interface
   end interface

contains

   !> A cell's kinematics for its load, in any dimension (the planar and the 3-D rod). In a
   !> step (dt > 0) they are centred on the step: stretch vector (e0 + e1) / 2, velocity
   !> (R1 - R0) / dt and acceleration (V1 - V0) / dt, with V1 from the theta rule, each the
   !> mean of the cell's two nodes; in statics (dt = 0) the stretch vector e1 at rest.
   !> de_coef is de/de1 (1/2 in a step, 1 in statics). The cell's mid position xm is centred
   !> as e is: the mean of the old and new mid positions in a step, the new one in statics;
   !> dx_coef is dxm/dR1 of each of its two nodes (1/4 in a step, 1/2 in statics).
   pure subroutine cell_kinematics(e0, e1, r0, v0, r1, dt, theta, e, w, a, de_coef, xm, dx_coef)
      !> Stretch vectors of the cell at the old and new level.
      real(dp), intent(in) :: e0(:), e1(:)
      !> Old positions and velocities of the cell's two nodes (dimension, 2).
      real(dp), intent(in) :: r0(:, :), v0(:, :)
      !> New positions of the two nodes (dimension, 2).
      real(dp), intent(in) :: r1(:, :)
      !> Step (0: statics) and time weight.
      real(dp), intent(in) :: dt, theta
      !> Stretch vector, velocity and acceleration of the cell.
      real(dp), intent(out) :: e(:), w(:), a(:)
      !> de/de1.
      real(dp), intent(out) :: de_coef
      !> Mid position of the cell and dxm/dR1 of each node.
      real(dp), intent(out) :: xm(:), dx_coef
      real(dp) :: v1(size(e), 2)
      if (dt > 0) then
         xm = 0.25_dp*(r0(:, 1) + r0(:, 2) + r1(:, 1) + r1(:, 2))
         dx_coef = 0.25_dp
      else
         xm = 0.5_dp*(r1(:, 1) + r1(:, 2))
         dx_coef = 0.5_dp
      end if
      if (dt > 0) then
         e = 0.5_dp*(e0 + e1)
         w = 0.5_dp*((r1(:, 1) - r0(:, 1)) + (r1(:, 2) - r0(:, 2)))/dt
         v1 = ((r1 - r0)/dt - (1 - theta)*v0)/theta
         a = 0.5_dp*((v1(:, 1) - v0(:, 1)) + (v1(:, 2) - v0(:, 2)))/dt
         de_coef = 0.5_dp
      else
         e = e1
         w = 0
         a = 0
         de_coef = 1
      end if
   end subroutine cell_kinematics

   pure logical function load_has_3d(self)
      class(cable_load), intent(in) :: self
      load_has_3d = .false.
   end function load_has_3d

   !> No 3-D form: zero force (the 3-D rod refuses such a load, see has_3d).
   pure subroutine load_cell_force3(self, x, ds, e, w, a, f, df_dx, df_de, df_dw, df_da)
      class(cable_load), intent(in) :: self
      real(dp), intent(in) :: x(3), ds, e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_dx(3, 3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      f = 0
      df_dx = 0
      df_de = 0
      df_dw = 0
      df_da = 0
   end subroutine load_cell_force3

   pure function load_measure_name(self) result(name)
      class(cable_load), intent(in) :: self
      character(:), allocatable :: name
      name = ''
   end function load_measure_name

   pure real(dp) function load_cell_measure(self, r1, r2, ds)
      class(cable_load), intent(in) :: self
      real(dp), intent(in) :: r1(:), r2(:), ds
      load_cell_measure = 0
   end function load_cell_measure

   !> The default: a load acts in the statics as in the dynamics.
   subroutine load_set_statics(self, on, stiffness, weight, share)
      class(cable_load), intent(inout) :: self
      logical, intent(in) :: on
      real(dp), intent(in) :: stiffness, weight, share
   end subroutine load_set_statics

   !> The default: no static form of its own.
   pure logical function load_static_form(self)
      class(cable_load), intent(in) :: self
      load_static_form = .false.
   end function load_static_form

   !> Whether any load of an array acts otherwise in the statics (cable_load%static_form).
   logical function any_static_form(loads)
      !> The loads (unallocated: none).
      type(load_slot), allocatable, intent(in) :: loads(:)
      integer :: k
      any_static_form = .false.
      if (.not. allocated(loads)) return
      do k = 1, size(loads)
         any_static_form = any_static_form .or. loads(k)%load%static_form()
      end do
   end function any_static_form

   !> Every load of an array told whether the statics (on) or the dynamics (off) evaluates it
   !> (cable_load%set_statics); nothing without loads.
   subroutine loads_in_statics(loads, on, stiffness, weight, share)
      !> The loads (unallocated: none).
      type(load_slot), allocatable, intent(inout) :: loads(:)
      !> Statics (.true.) or dynamics.
      logical, intent(in) :: on
      !> The line's axial stiffness near zero strain (N) and its weight in the fluid per
      !> unstretched length (N/m), for a static form that depends on them.
      real(dp), intent(in) :: stiffness, weight
      !> The share of the static form to apply, in (0, 1] (the statics' continuation; default 1).
      real(dp), intent(in), optional :: share
      real(dp) :: part
      integer :: k
      if (.not. allocated(loads)) return
      part = 1
      if (present(share)) part = share
      do k = 1, size(loads)
         call loads(k)%load%set_statics(on, stiffness, weight, part)
      end do
   end subroutine loads_in_statics

   pure real(dp) function load_floor(self, p)
      class(cable_load), intent(in) :: self
      real(dp), intent(in) :: p(:)
      load_floor = -huge(1.0_dp)
   end function load_floor

   function load_measure_note(self, value, length) result(text)
      class(cable_load), intent(in) :: self
      real(dp), intent(in) :: value, length
      character(:), allocatable :: text
      text = ''
   end function load_measure_note

   !> Whether the slot's load acts on the cell between arc lengths sa and sb (m): its middle in
   !> s_from <= s < s_to.
   elemental logical function slot_acts_on(self, sa, sb)
      !> The slot.
      class(load_slot), intent(in) :: self
      !> The cell's arc lengths from end a, m.
      real(dp), intent(in) :: sa, sb
      real(dp) :: mid
      mid = 0.5_dp*(sa + sb)
      slot_acts_on = mid >= self%s_from .and. mid < self%s_to
   end function slot_acts_on

   !> The names of the lengths the loads measure (one per name: the slots of one load on
   !> several segments measure into one value).
   function measure_names(loads) result(names)
      !> The loads.
      type(load_slot), intent(in) :: loads(:)
      character(len=32), allocatable :: names(:)
      integer :: i
      allocate (names(0))
      do i = 1, size(loads)
         if (len(loads(i)%load%measure_name()) == 0) cycle
         if (any(names == loads(i)%load%measure_name())) cycle
         names = [character(len=32) :: names, loads(i)%load%measure_name()]
      end do
   end function measure_names

   !> The loads' measures (in the order of measure_names) on a cable with nodes r (dimension,
   !> n) and cells of unstretched lengths ds, added to values. s: the nodes' arc lengths from
   !> end a (m), for loads that act on part of the line (not present: every load on every cell).
   subroutine load_measures(loads, r, ds, values, s)
      !> The loads.
      type(load_slot), intent(in) :: loads(:)
      !> Node positions (dimension, n), m, and unstretched cell lengths (n - 1), m.
      real(dp), intent(in) :: r(:, :), ds(:)
      !> The measures, m (added to).
      real(dp), intent(inout) :: values(:)
      !> Arc lengths of the nodes, m.
      real(dp), intent(in), optional :: s(:)
      integer :: slot(size(loads)), i, j, k, c, count
      ! Each measuring slot's place in measure_names: that of the first slot with its name (no
      ! list of names built: this runs at every record).
      count = 0
      do i = 1, size(loads)
         slot(i) = 0
         if (len(loads(i)%load%measure_name()) == 0) cycle
         do k = 1, i - 1
            if (slot(k) == 0) cycle
            if (loads(k)%load%measure_name() == loads(i)%load%measure_name()) then
               slot(i) = slot(k)
               exit
            end if
         end do
         if (slot(i) == 0) then
            count = count + 1
            slot(i) = count
         end if
      end do
      do i = 1, size(loads)
         if (slot(i) == 0) cycle
         j = slot(i)
         do c = 1, size(ds)
            if (present(s)) then
               if (.not. loads(i)%acts_on(s(c), s(c + 1))) cycle
            end if
            values(j) = values(j) + loads(i)%load%cell_measure(r(:, c), r(:, c + 1), ds(c))
         end do
      end do
   end subroutine load_measures

   !> Index of name in names (0: not there).
   pure integer function name_index(names, name)
      character(len=*), intent(in) :: names(:), name
      integer :: k
      name_index = 0
      do k = 1, size(names)
         if (trim(names(k)) == trim(name)) then
            name_index = k
            return
         end if
      end do
   end function name_index

   !> What the loads say about their measures at the start (values in the order of
   !> measure_names) of a cable of unstretched length (m): one line each, appended to notes.
   subroutine note_measures(loads, values, length, notes)
      !> The loads.
      type(load_slot), intent(in) :: loads(:)
      !> The measures at the start, m; the cable's unstretched length, m.
      real(dp), intent(in) :: values(:), length
      !> Lines so far ('' : none).
      character(:), allocatable, intent(inout) :: notes
      character(:), allocatable :: line
      character(len=32), allocatable :: names(:)
      logical, allocatable :: noted(:)
      integer :: i, j
      names = measure_names(loads)
      allocate (noted(size(names)))
      noted = .false.
      do i = 1, size(loads)
         if (len(loads(i)%load%measure_name()) == 0) cycle
         j = name_index(names, loads(i)%load%measure_name())
         if (noted(j)) cycle
         noted(j) = .true.
         line = loads(i)%load%measure_note(values(j), length)
         if (len(line) == 0) cycle
         if (len(notes) > 0) notes = notes//new_line('a')
         notes = notes//line
      end do
   end subroutine note_measures

   !> Whether any of the loads shares its force unequally (has_skew).
   pure logical function any_skew(loads)
      !> The loads.
      type(load_slot), intent(in) :: loads(:)
      integer :: i
      any_skew = .false.
      do i = 1, size(loads)
         if (loads(i)%load%has_skew()) any_skew = .true.
      end do
   end function any_skew

   pure logical function load_has_skew(self)
      class(cable_load), intent(in) :: self
      load_has_skew = .false.
   end function load_has_skew

   !> Equal shares: g = 0.
   pure subroutine load_cell_skew(self, x, ds, e, w, a, g, dg_dx, dg_de, dg_dw, dg_da)
      class(cable_load), intent(in) :: self
      real(dp), intent(in) :: x(:), ds, e(:), w(:), a(:)
      real(dp), intent(out) :: g(:), dg_dx(:, :), dg_de(:, :), dg_dw(:, :), dg_da(:, :)
      g = 0
      dg_dx = 0
      dg_de = 0
      dg_dw = 0
      dg_da = 0
   end subroutine load_cell_skew

   pure real(dp) function load_lift(self)
      class(cable_load), intent(in) :: self
      load_lift = 0
   end function load_lift
end module xcable_loads_load
