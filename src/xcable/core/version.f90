!> The version of xcable: the one string that `xcable --version`, the result
!> files and the checkpoints report. fpm.toml's `version` holds the same
!> number (the package version fpm builds and installs); the test
!> output/version_matches_fpm_toml fails when the two differ, so a release
!> changes this line and fpm.toml together (and CHANGELOG.md).
module xcable_core_version
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
   implicit none
   private
   public :: code_version, version_lines, unoptimised_note

   !> Version of the code, as in fpm.toml.
   character(len=*), parameter :: code_version = '0.5.0'

contains

   !> What `xcable --version` prints: the version, the compiler and its options,
   !> one per line (no trailing new line).
   function version_lines() result(text)
      character(:), allocatable :: text
      text = 'xcable '//code_version//new_line('a')//'compiler: '//compiler_version()//new_line('a')// &
             'compiler options: '//compiler_options()
   end function version_lines

   !> For a build without optimisation (fpm's default debug profile, as `fpm run` makes it),
   !> how to get the optimised one; '' for an optimised build.
   function unoptimised_note() result(text)
      character(:), allocatable :: text
      character(:), allocatable :: options
      options = ' '//compiler_options()//' '
      text = ''
      if (index(options, ' -O') > 0 .and. index(options, ' -O0 ') == 0) return
      text = 'this build is not optimised (fpm''s debug profile, with run-time checks): it runs about 5 '// &
             'times slower than the release build; `fpm run --profile release -- <case.nml>` or `make build` '// &
             '(then bin/xcable <case.nml>) give the fast one'
   end function unoptimised_note
end module xcable_core_version
