!> Builds an end condition from its namelist group (&end_a or &end_b), by the
!> builder its kind's line in the registry (ends/registry.f90) names.
module xcable_ends_factory
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_io_config, only: end_config
   use xcable_ends_end_condition, only: end_condition
   use xcable_ends_registry, only: end_kind, find_end_kind, end_kind_names
   implicit none
   private
   public :: new_end, end_kinds

contains

   !> The registered end kinds' words.
   function end_kinds() result(names)
      character(len=16), allocatable :: names(:)
      character(:), allocatable :: words
      integer :: i, k, n
      words = end_kind_names()//' '
      n = count([(words(i:i) == ' ', i=1, len(words))])
      allocate (names(n))
      do k = 1, n
         i = index(words, ' ')
         names(k) = words(1:i - 1)
         words = words(i + 1:)
      end do
   end function end_kinds

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
      type(end_kind) :: kind
      logical :: found
      call find_end_kind(config%kind, kind, found)
      if (.not. found) then
         call fatal_error(error, label//": unknown kind '"//trim(config%kind)//"'; registered: "// &
                          end_kind_names(), stat_input)
         return
      end if
      call kind%build(config, end)
      end%label = label
   end subroutine new_end
end module xcable_ends_factory
