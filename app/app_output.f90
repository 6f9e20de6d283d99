!> The program's result file: the library's result_file, with progress lines
!> on stderr (the library itself never prints).
module xcable_app_output
   use xcable_core_kinds, only: dp
   use xcable_io_output, only: result_file
   use, intrinsic :: iso_fortran_env, only: error_unit
   implicit none
   private
   public :: app_output

   !> Result file that reports progress.
   type, extends(result_file) :: app_output
      !> No progress lines.
      logical :: quiet = .false.
   contains
      procedure :: progress => print_progress
   end type app_output

contains

   !> Progress on stderr (the driver calls it at most once a second).
   subroutine print_progress(self, t, t_end, wall)
      !> Output.
      class(app_output), intent(inout) :: self
      !> Time reached and end of the run (s); wall time so far (s).
      real(dp), intent(in) :: t, t_end, wall
      if (self%quiet) return
      write (error_unit, '(a,f5.1,a,es10.3,a,es10.3,a,f8.1,a,f8.1,a)') 'xcable: ', 100*t/t_end, '%  t = ', t, ' s of ', &
         t_end, ' s, wall ', wall, ' s, remaining ', wall*(t_end - t)/max(t, tiny(t)), ' s'
   end subroutine print_progress
end module xcable_app_output
