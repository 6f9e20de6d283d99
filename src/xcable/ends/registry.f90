!> The end-kind registry: the one list of the end kinds, one line each. A line
!> names the kind, the namelist variables of &end_a / &end_b it uses, whether
!> its position is prescribed (held), a phrase for the schema's `kind` entry,
!> the procedure that builds it from its group (next to its type, in
!> ends/<kind>.f90) and, where it has any, the conditions its group must meet
!> beyond the schema's ranges.
!>
!> Everything else takes the kinds from here: the factory (ends/factory.f90),
!> the schema's `kind` entry and its allowed words (io/schema.f90), the
!> validation of a group (io/input.f90: a variable given to a kind that does
!> not use it is refused, naming the kinds that do), the echo, and the generic
!> tests (test/suite_registry.f90). Adding a kind: its module, one line in
!> `end_kind_list`, and its new variables (if any) in io/config.f90,
!> io/schema.f90 and io/input.f90 (docs/dev/adding-an-end.md).
module xcable_ends_registry
   use xcable_core_error, only: error_type
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition
   use xcable_ends_fixed, only: new_fixed_end
   use xcable_ends_free, only: new_free_end
   use xcable_ends_force, only: new_force_end, check_force_end
   use xcable_ends_motion, only: new_motion_end, check_motion_end
   use xcable_ends_mass, only: new_mass_end, check_mass_end
   use xcable_ends_spring, only: new_spring_end, check_spring_end
   implicit none
   private
   public :: end_kind, end_kind_list, find_end_kind, end_kind_names, kinds_using, end_builder, end_checker

   abstract interface
      !> Builds an end from its validated group.
      subroutine end_builder(config, end)
         import :: end_config, end_condition
         !> The group.
         type(end_config), intent(in) :: config
         !> The end built.
         class(end_condition), allocatable, intent(out) :: end
      end subroutine end_builder

      !> The conditions of a kind's group beyond the schema's ranges.
      subroutine end_checker(prefix, e, other, other_held, error)
         import :: end_config, error_type
         !> Start of a message: 'file: &end_b: '.
         character(*), intent(in) :: prefix
         !> The group, the other end's group and whether that end is held.
         type(end_config), intent(in) :: e, other
         logical, intent(in) :: other_held
         !> Error naming the variable, its value and what is allowed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine end_checker
   end interface

   !> One registered end kind.
   type :: end_kind
      !> Its word (&end_a kind = '...').
      character(len=16) :: name = ''
      !> The variables of &end_a / &end_b it uses, blank-separated ('kind' aside).
      character(len=200) :: variables = ''
      !> Whether its position is prescribed (x, y, z are then its point or mean point).
      logical :: held = .false.
      !> What it is, for the schema's `kind` entry.
      character(len=64) :: doc = ''
      !> Builds it.
      procedure(end_builder), pointer, nopass :: build => null()
      !> Checks its group (none: nothing beyond the ranges).
      procedure(end_checker), pointer, nopass :: check => null()
   end type end_kind

   !> The variables of an end's table ('table' histories and motions).
   character(len=*), parameter :: table_variables = ' table_time table_x table_y table_z table_file'

contains

   !> The registered kinds, in the order the schema lists them (the first is the default).
   function end_kind_list() result(kinds)
      type(end_kind), allocatable :: kinds(:)
      kinds = [ &
               end_kind('fixed', 'x y z', .true., 'held at x, y, z', new_fixed_end, null()), &
               end_kind('free', '', .false., 'no force', new_free_end, null()), &
               end_kind('force', 'force_x force_y force_z torque history ramp_time'//table_variables, .false., &
                        'an applied force', new_force_end, check_force_end), &
               end_kind('motion', 'x y z motion amplitude period phase direction_x direction_y direction_z '// &
                        'ramp_time'//table_variables, .true., 'moved about x, y, z', new_motion_end, &
                        check_motion_end), &
               end_kind('mass', 'mass', .false., 'a point mass', new_mass_end, check_mass_end), &
               end_kind('spring', 'x y z stiffness damping rest_length mass', .false., &
                        'on a spring to the anchor x, y, z', new_spring_end, check_spring_end)]
   end function end_kind_list

   !> The registered kind of a word (found = .false. when there is none).
   subroutine find_end_kind(name, kind, found)
      !> The word.
      character(*), intent(in) :: name
      !> Its registry line.
      type(end_kind), intent(out) :: kind
      !> Whether the word is registered.
      logical, intent(out) :: found
      type(end_kind), allocatable :: kinds(:)
      integer :: i
      kinds = end_kind_list()
      found = .false.
      do i = 1, size(kinds)
         if (trim(kinds(i)%name) == trim(name)) then
            kind = kinds(i)
            found = .true.
            return
         end if
      end do
   end subroutine find_end_kind

   !> The words of the kinds, blank-separated; with held present, only those whose position
   !> is prescribed (held = .true.) or only the others (.false.).
   function end_kind_names(held) result(names)
      !> Which kinds (all when absent).
      logical, intent(in), optional :: held
      character(:), allocatable :: names
      type(end_kind), allocatable :: kinds(:)
      kinds = end_kind_list()
      if (present(held)) then
         names = words_of(kinds, kinds%held .eqv. held)
      else
         names = words_of(kinds, spread(.true., 1, size(kinds)))
      end if
   end function end_kind_names

   !> The words of the kinds that use a variable, blank-separated ('' : none).
   function kinds_using(variable) result(names)
      !> The variable's name.
      character(*), intent(in) :: variable
      character(:), allocatable :: names
      type(end_kind), allocatable :: kinds(:)
      integer :: i
      kinds = end_kind_list()
      names = words_of(kinds, [(index(' '//trim(kinds(i)%variables)//' ', ' '//trim(variable)//' ') > 0, &
                                i=1, size(kinds))])
   end function kinds_using

   !> The words of the kinds where keep is true, blank-separated.
   function words_of(kinds, keep) result(names)
      !> The kinds.
      type(end_kind), intent(in) :: kinds(:)
      !> Which to name.
      logical, intent(in) :: keep(:)
      character(:), allocatable :: names
      integer :: i
      names = ''
      do i = 1, size(kinds)
         if (.not. keep(i)) cycle
         if (len(names) > 0) names = names//' '
         names = names//trim(kinds(i)%name)
      end do
   end function words_of
end module xcable_ends_registry
