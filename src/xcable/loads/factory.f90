!> Builds the distributed loads of a case: the one place where loads are registered.
!>
!> A load is a module extending `cable_load` (loads/load.f90) with a builder
!> `<name>_from_case(config, area, load)` that leaves `load` unallocated when the
!> case does not ask for it. To add one, write its module and add one line to
!> `case_loads` below; both rods, the ledger, the history's measures and the
!> generic Jacobian and ledger tests (test/suite_registry.f90) take it from
!> there.
module xcable_loads_factory
   use xcable_core_kinds, only: dp
   use xcable_io_config, only: case_config
   use xcable_loads_load, only: cable_load, load_slot
   use xcable_loads_fluid, only: fluid_from_case
   use xcable_loads_seabed, only: seabed_from_case
   implicit none
   private
   public :: case_loads

   abstract interface
      !> A load's builder: the load a case asks for (unallocated: none).
      subroutine builder(config, area, load)
         import :: case_config, dp, cable_load
         !> Validated case.
         type(case_config), intent(in) :: config
         !> Unstretched cross-section of the cable, m^2.
         real(dp), intent(in) :: area
         !> The load, or unallocated.
         class(cable_load), allocatable, intent(out) :: load
      end subroutine builder
   end interface

contains

   !> The loads of a case, in the order of the lines below.
   subroutine case_loads(config, area, loads)
      !> Validated case.
      type(case_config), intent(in) :: config
      !> Unstretched cross-section of the cable, m^2.
      real(dp), intent(in) :: area
      !> The loads (empty: none).
      type(load_slot), allocatable, intent(out) :: loads(:)
      allocate (loads(0))
      call add(fluid_from_case)
      call add(seabed_from_case)
   contains
      subroutine add(build)
         procedure(builder) :: build
         class(cable_load), allocatable :: load
         type(load_slot), allocatable :: longer(:)
         integer :: k
         call build(config, area, load)
         if (.not. allocated(load)) return
         allocate (longer(size(loads) + 1))
         do k = 1, size(loads)
            call move_alloc(loads(k)%load, longer(k)%load)
         end do
         call move_alloc(load, longer(size(longer))%load)
         call move_alloc(longer, loads)
      end subroutine add
   end subroutine case_loads
end module xcable_loads_factory
