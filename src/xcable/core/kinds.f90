!> Working precision of the whole code.
module xcable_core_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int64
   implicit none
   private
   public :: dp, i8

   !> Double precision, used for every real quantity.
   integer, parameter :: dp = real64
   !> 64-bit integer (clock counts).
   integer, parameter :: i8 = int64
end module xcable_core_kinds
