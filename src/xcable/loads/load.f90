!> Loads distributed along the cable: the abstract type every such load
!> extends (fluid drag and added mass today).
!>
!> The rod (model/rod.f90) asks a load for the force per unstretched length on
!> one cell, given the cell's kinematics at the time the step is centred on:
!> its stretch vector e (the cell vector over its unstretched length, so
!> |e| = 1 + eps), its velocity w and its acceleration a (the means of its two
!> nodes'). It also asks for the derivatives of that force with respect to e,
!> w and a, from which it builds the Jacobian; the generic finite-difference
!> tests check them. A load's work is booked by the driver from the forces the
!> rod applied, so the energy ledger closes with any load. A load that is
!> conservative and constant (buoyancy) is given as a lift per unstretched
!> length instead, which the rod adds to the weight (and so to the gravity
!> energy). A new load is one module extending `cable_load` and one line in
!> scene/scene.f90 where the loads of a case are built.
!>
!> Frame: x horizontal, z vertical (up); forces in N.
module xcable_loads_load
   use xcable_kinds, only: dp
   implicit none
   private
   public :: cable_load, load_slot

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
   end type cable_load

   !> A slot of an array of loads.
   type :: load_slot
      class(cable_load), allocatable :: load
   end type load_slot

   abstract interface
      pure function name_interface(self) result(name)
         import :: cable_load
         class(cable_load), intent(in) :: self
         character(:), allocatable :: name
      end function name_interface

      !> Force per unstretched length f on a cell with stretch vector e, velocity w and
      !> acceleration a, and df/de, df/dw, df/da (2x2, row i = component i of f).
      pure subroutine cell_force_interface(self, e, w, a, f, df_de, df_dw, df_da)
         import :: cable_load, dp
         class(cable_load), intent(in) :: self
         real(dp), intent(in) :: e(2), w(2), a(2)
         real(dp), intent(out) :: f(2), df_de(2, 2), df_dw(2, 2), df_da(2, 2)
      end subroutine cell_force_interface
   end interface

contains

   pure logical function load_has_3d(self)
      class(cable_load), intent(in) :: self
      load_has_3d = .false.
   end function load_has_3d

   !> No 3-D form: zero force (the 3-D rod refuses such a load, see has_3d).
   pure subroutine load_cell_force3(self, e, w, a, f, df_de, df_dw, df_da)
      class(cable_load), intent(in) :: self
      real(dp), intent(in) :: e(3), w(3), a(3)
      real(dp), intent(out) :: f(3), df_de(3, 3), df_dw(3, 3), df_da(3, 3)
      f = 0
      df_de = 0
      df_dw = 0
      df_da = 0
   end subroutine load_cell_force3

   pure real(dp) function load_lift(self)
      class(cable_load), intent(in) :: self
      load_lift = 0
   end function load_lift
end module xcable_loads_load
