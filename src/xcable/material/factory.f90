!> Builds the material law of a case: the one place where laws are registered.
!>
!> A law is a module extending `material_law` (material/law.f90). To add one,
!> write its module, add its word to `law_names` and one `case` to `new_law`;
!> the schema's list of allowed words (io/schema.f90) and the generic tests
!> (test/suite_registry.f90) take the words from `law_names`. The compression
!> option (`compression = 'none'`) wraps whichever law was built
!> (material/tension_only.f90), so a new law gets it without further code.
module xcable_material_factory
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, stat_input
   use xcable_io_config, only: case_config
   use xcable_material_law, only: material_law, tanh_law_of, linear_law
   use xcable_material_table, only: table_law, new_table_law
   use xcable_material_tension_only, only: new_tension_only
   implicit none
   private
   public :: law_names, new_law, new_case_law

   !> The registered laws, as the namelist names them (&material law).
   character(len=*), parameter :: law_names(3) = [character(len=6) :: 'tanh', 'linear', 'table']

contains

   !> Build a law from its name and parameters (no table: a 'table' law needs its rows,
   !> new_case_law reads them from the case).
   subroutine new_law(law, name, p, ea, strain_max, error)
      !> The law built.
      class(material_law), allocatable, intent(out) :: law
      !> A word of law_names other than 'table'.
      character(*), intent(in) :: name
      !> Coefficients of the tanh law.
      real(dp), intent(in) :: p(5)
      !> EA of the linear law, N.
      real(dp), intent(in) :: ea
      !> Largest documented strain.
      real(dp), intent(in) :: strain_max
      !> Error (stat_input) if the name is unknown.
      type(error_type), allocatable, intent(out) :: error
      select case (name)
      case ('tanh')
         allocate (law, source=tanh_law_of(p, strain_max))
      case ('linear')
         allocate (law, source=linear_law(ea=ea, strain_max=strain_max))
      case default
         call fatal_error(error, "unknown material law '"//name//"'; allowed: "//allowed_words(), stat_input)
      end select
   end subroutine new_law

   !> The law of a validated case, with its compression option applied.
   subroutine new_case_law(config, ea, law, error)
      !> Validated case.
      type(case_config), intent(in) :: config
      !> EA of the linear law, N (derived from the case as the reader does).
      real(dp), intent(in) :: ea
      !> The law built.
      class(material_law), allocatable, intent(out) :: law
      !> Error (stat_input) naming the bad row or word.
      type(error_type), allocatable, intent(out) :: error
      class(material_law), allocatable :: base
      type(table_law) :: table
      select case (trim(config%law))
      case ('table')
         call new_table_law(config%material_table_strain(1:config%material_table_rows), &
                            config%material_table_tension(1:config%material_table_rows), table, error)
         if (.not. allocated(error)) allocate (base, source=table)
      case default
         call new_law(base, trim(config%law), config%p, ea, config%strain_max, error)
      end select
      if (allocated(error)) return
      select case (trim(config%compression))
      case ('none')
         allocate (law, source=new_tension_only(base))
      case default
         call move_alloc(base, law)
      end select
   end subroutine new_case_law

   !> 'tanh', 'linear', 'table' (the registered words, quoted).
   function allowed_words() result(text)
      character(:), allocatable :: text
      integer :: k
      text = ''
      do k = 1, size(law_names)
         if (k > 1) text = text//', '
         text = text//"'"//trim(law_names(k))//"'"
      end do
   end function allowed_words
end module xcable_material_factory
