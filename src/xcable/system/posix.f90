!> What xcable needs from the operating system, bound to the small C file
!> posix.c beside this one: the SIGTERM flag, atomic and durable file
!> replacement, the process id and a 64-bit checksum of memory.
!>
!> The SIGTERM handler (installed by the program, app/main.f90) only sets a
!> flag; a rod run checks it once per step attempt (driver/rod_run.f90), so a
!> signal never interrupts a computation half-way. The flag is process state
!> held by the C file, not a Fortran module variable.
module xcable_system_posix
   use xcable_core_kinds, only: dp
   use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_size_t, c_char, c_null_char
   implicit none
   private
   public :: install_termination_handler, termination_requested, clear_termination, raise_termination
   public :: replace_file, process_id, checksum_start, checksum_update, checksum_text, new_run_id

   interface
      function c_install() result(status) bind(c, name='xcable_install_termination_handler')
         import :: c_int
         integer(c_int) :: status
      end function c_install
      function c_requested() result(flag) bind(c, name='xcable_termination_requested')
         import :: c_int
         integer(c_int) :: flag
      end function c_requested
      subroutine c_clear() bind(c, name='xcable_clear_termination')
      end subroutine c_clear
      function c_raise() result(status) bind(c, name='xcable_raise_termination')
         import :: c_int
         integer(c_int) :: status
      end function c_raise
      function c_replace(source, target) result(status) bind(c, name='xcable_replace_file')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: source(*), target(*)
         integer(c_int) :: status
      end function c_replace
      subroutine c_error_text(number, message, capacity) bind(c, name='xcable_error_text')
         import :: c_int, c_char, c_size_t
         integer(c_int), value :: number
         character(kind=c_char), intent(out) :: message(*)
         integer(c_size_t), value :: capacity
      end subroutine c_error_text
      function c_pid() result(pid) bind(c, name='xcable_process_id')
         import :: c_int
         integer(c_int) :: pid
      end function c_pid
      function c_checksum_start() result(hash) bind(c, name='xcable_checksum_start')
         import :: c_int64_t
         integer(c_int64_t) :: hash
      end function c_checksum_start
      function c_checksum_update(hash, data, bytes) result(next) bind(c, name='xcable_checksum_update')
         import :: c_int64_t, c_size_t
         integer(c_int64_t), value :: hash
         type(*), intent(in) :: data(*)
         integer(c_size_t), value :: bytes
         integer(c_int64_t) :: next
      end function c_checksum_update
   end interface

   !> Continue a checksum over an array or a text.
   interface checksum_update
      module procedure checksum_reals, checksum_ints, checksum_text_update
   end interface checksum_update

contains

   !> Install the SIGTERM handler that sets the termination flag; '' or why it failed.
   function install_termination_handler() result(message)
      character(:), allocatable :: message
      integer(c_int) :: status
      status = c_install()
      message = ''
      if (status /= 0) message = 'cannot install the SIGTERM handler: '//error_text(status)
   end function install_termination_handler

   !> Whether SIGTERM has arrived since the handler was installed.
   logical function termination_requested()
      termination_requested = c_requested() /= 0
   end function termination_requested

   !> Forget an earlier SIGTERM (tests).
   subroutine clear_termination()
      call c_clear()
   end subroutine clear_termination

   !> Send SIGTERM to this process (tests; with the handler installed only the flag is set).
   subroutine raise_termination()
      integer(c_int) :: status
      status = c_raise()
   end subroutine raise_termination

   !> Replace target by source atomically and durably (fsync, rename, fsync of
   !> the directory); '' or why it failed.
   function replace_file(source, target) result(message)
      !> The new file, and the name it gets.
      character(*), intent(in) :: source, target
      character(:), allocatable :: message
      integer(c_int) :: status
      status = c_replace(source//c_null_char, target//c_null_char)
      message = ''
      if (status /= 0) message = error_text(status)
   end function replace_file

   !> The text of an errno value.
   function error_text(number) result(text)
      integer(c_int), intent(in) :: number
      character(:), allocatable :: text
      character(kind=c_char, len=200) :: buffer
      call c_error_text(number, buffer, int(len(buffer), c_size_t))
      text = trim(buffer)
   end function error_text

   !> The id of this process.
   integer function process_id()
      process_id = int(c_pid())
   end function process_id

   !> An identifier of a new run: the date and time to the millisecond, the
   !> process id and the clock count ('20261201T135212.345-p4242-c12345678').
   function new_run_id() result(id)
      character(:), allocatable :: id
      integer :: values(8)
      integer(c_int64_t) :: count
      character(len=64) :: buffer
      call date_and_time(values=values)
      call system_clock(count)
      write (buffer, '(i4.4,2i2.2,a,3i2.2,a,i3.3,a,i0,a,i0)') values(1:3), 'T', values(5:7), '.', values(8), '-p', &
         process_id(), '-c', count
      id = trim(buffer)
   end function new_run_id

   !> The starting value of a checksum.
   function checksum_start() result(hash)
      integer(c_int64_t) :: hash
      hash = c_checksum_start()
   end function checksum_start

   !> Continue a checksum over reals.
   subroutine checksum_reals(hash, values)
      !> Checksum so far.
      integer(c_int64_t), intent(inout) :: hash
      !> Values.
      real(dp), contiguous, intent(in) :: values(:)
      hash = c_checksum_update(hash, values, int(size(values), c_size_t)*storage_size(values)/8)
   end subroutine checksum_reals

   !> Continue a checksum over integers.
   subroutine checksum_ints(hash, values)
      !> Checksum so far.
      integer(c_int64_t), intent(inout) :: hash
      !> Values.
      integer, contiguous, intent(in) :: values(:)
      hash = c_checksum_update(hash, values, int(size(values), c_size_t)*storage_size(values)/8)
   end subroutine checksum_ints

   !> Continue a checksum over the characters of a text.
   subroutine checksum_text_update(hash, text)
      !> Checksum so far.
      integer(c_int64_t), intent(inout) :: hash
      !> Text.
      character(*), intent(in) :: text
      character(kind=c_char), allocatable :: chars(:)
      integer :: i
      allocate (chars(len(text)))
      do i = 1, len(text)
         chars(i) = text(i:i)
      end do
      hash = c_checksum_update(hash, chars, int(len(text), c_size_t))
   end subroutine checksum_text_update

   !> A checksum as 16 hexadecimal digits.
   function checksum_text(hash) result(text)
      integer(c_int64_t), intent(in) :: hash
      character(len=16) :: text
      write (text, '(z16.16)') hash
   end function checksum_text
end module xcable_system_posix
