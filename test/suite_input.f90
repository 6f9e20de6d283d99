!> Namelist input: the paper's cases read back, and one test per class of bad
!> input, each checking that the message names the file, the group, the
!> variable and what is allowed.
module suite_input
   use xcable_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check, check_close
   use xcable_error, only: fatal_error, stat_input
   use xcable_io_input, only: case_config, read_config
   use xcable_case, only: setup_case
   use xcable_model_equations, only: cable_model
   use xcable_solver_newton, only: newton_options
   use xcable_dynamics, only: dynamics_options
   use xcable_fixtures, only: write_text
   implicit none
   private
   public :: collect_input

   character(len=*), parameter :: path = 'build/test_input.nml'
   character(len=*), parameter :: nl = new_line('a')

contains

   subroutine collect_input(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('paper_cases', test_paper_cases), &
               new_unittest('defaults_without_groups', test_defaults), &
               new_unittest('misspelled_variable', test_misspelled), &
               new_unittest('wrong_type', test_wrong_type), &
               new_unittest('missing_slash', test_missing_slash), &
               new_unittest('missing_file', test_missing_file), &
               new_unittest('negative_length', test_negative_length), &
               new_unittest('too_few_nodes', test_nodes), &
               new_unittest('tension_not_positive', test_tension_zero), &
               new_unittest('tension_beyond_law', test_tension_range), &
               new_unittest('unknown_group', test_unknown_group), &
               new_unittest('no_group', test_no_group), &
               new_unittest('duplicated_group', test_duplicate), &
               new_unittest('nan_value', test_nan), &
               new_unittest('unknown_field', test_unknown_field), &
               new_unittest('unknown_law', test_unknown_law)]
   end subroutine collect_input

   !> Read text as a case (validation and the law-dependent checks) and expect
   !> an input error whose message contains every one of the words.
   subroutine expect_error(error, text, words)
      type(error_type), allocatable, intent(out) :: error
      character(*), intent(in) :: text
      character(len=*), intent(in) :: words(:)
      type(case_config) :: config
      type(error_type), allocatable :: err
      type(cable_model) :: model
      real(dp), allocatable :: s(:)
      type(newton_options) :: newton
      type(dynamics_options) :: dyn
      integer :: i
      if (len(text) > 0) call write_text(path, text)
      call read_config(path, config, err)
      if (.not. allocated(err)) call setup_case(config, model, s, newton, dyn, err)
      if (.not. allocated(err)) then
         call fatal_error(error, 'accepted: '//text)
         return
      end if
      call check(error, err%stat == stat_input, 'not classed as bad input: '//err%message)
      if (allocated(error)) return
      call check(error, index(err%message, new_line('a')) == 0, 'message is not one line: '//err%message)
      if (allocated(error)) return
      do i = 1, size(words)
         call check(error, index(err%message, trim(words(i))) > 0, 'message lacks "'//trim(words(i))//'": '//err%message)
         if (allocated(error)) return
      end do
   end subroutine expect_error

   subroutine test_paper_cases(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      character(len=10), parameter :: cases(4) = ['fast_180kN', 'fast_315kN', 'slow_180kN', 'slow_315kN']
      real(dp), parameter :: tension(4) = [180.0e3_dp, 315.0e3_dp, 180.0e3_dp, 315.0e3_dp]
      real(dp), parameter :: t_break(4) = [0.005_dp, 0.005_dp, 0.05_dp, 0.05_dp]
      real(dp), parameter :: t_end(4) = [0.14_dp, 0.13_dp, 0.17_dp, 0.16_dp]
      integer :: i
      do i = 1, 4
         call read_config('input/'//trim(cases(i))//'.nml', config, error)
         if (allocated(error)) return
         call check_close(error, config%tension, tension(i), cases(i)//' tension', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, config%t_break, t_break(i), cases(i)//' t_break', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, config%t_end, t_end(i), cases(i)//' t_end', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check_close(error, config%interval, 0.01_dp, cases(i)//' interval', rel_tol=1.0e-12_dp)
         if (allocated(error)) return
         call check(error, trim(config%file) == 'results/'//trim(cases(i))//'.h5', cases(i)//' output file')
         if (allocated(error)) return
      end do
   end subroutine test_paper_cases

   !> Groups left out take the paper's values; area and EI follow from d and E.
   subroutine test_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      call write_text(path, '&static tension = 180000 /'//nl)
      call read_config(path, config, error)
      if (allocated(error)) return
      call check_close(error, config%area, 1.9635e-3_dp, 'area from the diameter', rel_tol=1.0e-4_dp)
      if (allocated(error)) return
      call check_close(error, config%bending_stiffness, 70.56_dp, 'EI from E and d', rel_tol=1.0e-3_dp)
      if (allocated(error)) return
      call check_close(error, config%length, 60.0_dp, 'length', rel_tol=1.0e-12_dp)
      if (allocated(error)) return
      call check(error, trim(config%file) == 'results/test_input.h5', 'default output file: '//trim(config%file))
   end subroutine test_defaults

   subroutine test_misspelled(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&numerics nodez = 11 /'//nl, [character(16) :: path, '&numerics', 'nodez', 'allowed'])
   end subroutine test_misspelled

   subroutine test_wrong_type(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&numerics nodes = 12.5 /'//nl, [character(16) :: path, '&numerics', 'nodes', '12.5', &
                                                                 'integer'])
   end subroutine test_wrong_type

   subroutine test_missing_slash(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 1.8e5'//nl//'&rupture t_break = 0.005 /'//nl, &
                        [character(16) :: path, '&static', '/'])
   end subroutine test_missing_slash

   subroutine test_missing_file(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: config
      type(error_type), allocatable :: err
      call read_config('build/no_such_file.nml', config, err)
      call check(error, allocated(err), 'missing file accepted')
      if (allocated(error)) return
      call check(error, index(err%message, 'build/no_such_file.nml') > 0 .and. err%stat == stat_input, &
                 'message does not name the file: '//err%message)
   end subroutine test_missing_file

   subroutine test_negative_length(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&cable length = -60 /'//nl, [character(16) :: path, '&cable', 'length = -60', 'in [0.01'])
   end subroutine test_negative_length

   subroutine test_nodes(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&numerics nodes = 2 /'//nl, [character(16) :: path, '&numerics', 'nodes = 2', 'from 3'])
   end subroutine test_nodes

   subroutine test_tension_zero(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 0 /'//nl, [character(16) :: path, '&static', 'tension', '> 0'])
   end subroutine test_tension_zero

   !> 600 kN needs a strain beyond the tanh law's documented range.
   subroutine test_tension_range(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 600000 /'//nl, [character(16) :: path, '&static', 'tension', &
                                                                   'strain_max'])
   end subroutine test_tension_range

   subroutine test_unknown_group(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 1.8e5 /'//nl//'&solver tol = 1 /'//nl, &
                        [character(16) :: path, '&solver', 'allowed'])
   end subroutine test_unknown_group

   subroutine test_no_group(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '! only a comment'//nl//nl, [character(16) :: path, 'no namelist group'])
   end subroutine test_no_group

   subroutine test_duplicate(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&static tension = 1.8e5 /'//nl//'&static tension = 2e5 /'//nl, &
                        [character(16) :: path, '&static', 'twice'])
   end subroutine test_duplicate

   subroutine test_nan(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, '&rupture t_break = NaN /'//nl, [character(16) :: path, '&rupture', 't_break', 'finite'])
   end subroutine test_nan

   subroutine test_unknown_field(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&output fields = 'tension speed' /"//nl, [character(16) :: path, '&output', 'fields', &
                                                                           'speed', 'allowed'])
   end subroutine test_unknown_field

   subroutine test_unknown_law(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, "&material law = 'cubic' /"//nl, [character(16) :: path, '&material', 'cubic', 'tanh'])
   end subroutine test_unknown_law
end module suite_input
