!> Shared set-ups of the tests: the paper's cable, grids and cases.
module xcable_fixtures
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type
   use xcable_io_input, only: case_config
   use xcable_box_case, only: setup_case
   use xcable_box_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_box_dynamics, only: dynamics_options
   use xcable_io_input, only: read_config
   use xcable_driver_simulation, only: simulation
   use xcable_driver_records, only: run_observer
   implicit none
   private
   public :: paper_case, write_text, pushing_rope, run_text, column_text

contains

   !> The paper's cable with the given tension, grid and rupture, built like the app does.
   subroutine paper_case(tension, nodes, model, s, newton, dynamics, error, t_break, t_end, courant, theta, law, &
                         bending_stiffness)
      real(dp), intent(in) :: tension
      integer, intent(in) :: nodes
      type(cable_model), intent(out) :: model
      real(dp), allocatable, intent(out) :: s(:)
      type(newton_options), intent(out) :: newton
      type(dynamics_options), intent(out) :: dynamics
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in), optional :: t_break, t_end, courant, theta, bending_stiffness
      character(*), intent(in), optional :: law
      type(case_config) :: config
      config%source = 'test'
      config%tension = tension
      config%nodes = nodes
      if (present(bending_stiffness)) config%bending_stiffness = bending_stiffness
      if (present(law)) config%law = law
      if (present(t_break)) config%t_break = t_break
      if (present(t_end)) config%t_end = t_end
      if (present(courant)) config%courant = courant
      if (present(theta)) config%theta = theta
      config%newton_tol = 1.0e-10_dp
      config%quiet = .true.
      call setup_case(config, model, s, newton, dynamics, error)
   end subroutine paper_case

   !> Write a text file (a namelist for the input tests).
   subroutine write_text(path, text)
      character(*), intent(in) :: path, text
      integer :: unit
      open (newunit=unit, file=path, status='replace', action='write', access='stream', form='unformatted')
      write (unit) text
      close (unit)
   end subroutine write_text

   !> Scenes written for the paper's rope, which pushes back along its law in compression (the
   !> default before compression = 'none' became it): a case text that says nothing of the material
   !> gets compression = 'law'.
   function pushing_rope(text) result(case_text)
      character(*), intent(in) :: text
      character(:), allocatable :: case_text
      case_text = text
      if (index(text, '&material') == 0) case_text = "&material compression = 'law' /"//new_line('a')//text
   end function pushing_rope
   !> Write a case given as namelist text to path, read it, prepare and run it.
   subroutine run_text(path, text, sim, obs, error)
      !> Where the namelist is written; its text.
      character(*), intent(in) :: path, text
      !> The simulation and what receives its results.
      type(simulation), intent(inout) :: sim
      class(run_observer), intent(inout) :: obs
      !> Error of reading, preparing or running.
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, text//new_line('a'))
      call read_config(path, config, error)
      if (allocated(error)) return
      call sim%prepare(config, error)
      if (allocated(error)) return
      call sim%run(obs, error)
   end subroutine run_text
   !> A namelist column: name = v1, v2, ... (five values a line).
   function column_text(name, v) result(text)
      !> Variable name and its values.
      character(*), intent(in) :: name
      real(dp), intent(in) :: v(:)
      character(:), allocatable :: text
      character(len=32) :: item
      integer :: k
      text = name//' ='
      do k = 1, size(v)
         write (item, '(es24.16e3)') v(k)
         text = text//' '//trim(adjustl(item))//','
         if (mod(k, 5) == 0) text = text//new_line('a')
      end do
   end function column_text

end module xcable_fixtures
