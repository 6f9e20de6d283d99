!> Builds an end condition from its namelist group (&end_a or &end_b). The one
!> place where the end kinds are registered: a new kind is a new module and a
!> new `case` here.
module xcable_ends_factory
   use xcable_kinds, only: dp
   use xcable_error, only: error_type, fatal_error, stat_input
   use xcable_io_config, only: end_config
   use xcable_ends_end, only: end_condition
   use xcable_ends_table, only: time_table
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_free, only: free_end
   use xcable_ends_force, only: force_end
   use xcable_ends_motion, only: motion_end
   use xcable_ends_mass, only: mass_end
   implicit none
   private
   public :: new_end, end_kinds

   !> The registered end kinds.
   character(len=*), parameter :: end_kinds(5) = [character(len=6) :: 'fixed', 'free', 'force', 'motion', 'mass']

contains

   !> The end described by a validated &end_a / &end_b group.
   subroutine new_end(config, label, end, error)
      !> The group.
      type(end_config), intent(in) :: config
      !> 'end_a' or 'end_b'.
      character(*), intent(in) :: label
      !> The end built.
      class(end_condition), allocatable, intent(out) :: end
      !> Error for an unknown kind.
      type(error_type), allocatable, intent(out) :: error
      type(time_table) :: table
      real(dp) :: direction(3)
      if (config%table_rows >= 2) then
         table%time = config%table_time(1:config%table_rows)
         allocate (table%value(3, config%table_rows))
         table%value(1, :) = config%table_x(1:config%table_rows)
         table%value(2, :) = config%table_y(1:config%table_rows)
         table%value(3, :) = config%table_z(1:config%table_rows)
      end if
      select case (trim(config%kind))
      case ('fixed')
         allocate (end, source=fixed_end(point=[config%x, config%z], y=config%y))
      case ('free')
         allocate (end, source=free_end())
      case ('force')
         table%linear = .true.
         allocate (end, source=force_end(history=config%history, force0=[config%force_x, config%force_z], &
                                         duration=config%ramp_time, table=table, force0_y=config%force_y, &
                                         torque0=config%torque))
      case ('motion')
         ! The direction normalised over its three components (x, y, z).
         direction = [config%direction_x, config%direction_y, config%direction_z]
         if (norm2(direction) > 0) direction = direction/norm2(direction)
         allocate (end, source=motion_end(motion=config%motion, origin=[config%x, config%z], &
                                          amplitude=config%amplitude, period=config%period, phase=config%phase, &
                                          direction=direction([1, 3]), ramp_time=config%ramp_time, table=table, &
                                          origin_y=config%y, direction_y=direction(2)))
      case ('mass')
         allocate (end, source=mass_end(mass=config%mass))
      case default
         call fatal_error(error, label//": unknown kind '"//trim(config%kind)//"'", stat_input)
         return
      end select
      end%label = label
   end subroutine new_end
end module xcable_ends_factory
