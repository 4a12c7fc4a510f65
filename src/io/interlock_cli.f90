!> What the command-line programs share (interlock-history, interlock-query, interlock-bench,
!> interlock-fuzz): ending with an exit status and nothing else. Fortran's `stop 2` and
!> `error stop 2` print "STOP 2" / "ERROR STOP 2" (and, in the Debug build, a backtrace); a
!> usage error must print only its message and the usage. And reading the command line whole,
!> whether a folder given on it can be written into (checked before any work is done), and
!> warnings: on standard error, as errors are, so that standard output holds only results.
module interlock_cli
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  implicit none
  private
  public :: exit_program, command_argument, command_text, folder_writable, warn

  interface
    !> _exit: ends the process at once, without the C exit handlers (HDF5 1.10's own handler
    !> crashes in H5F__close_cb on a file whose close failed, e.g. on a full disk; its library is
    !> closed before by interlock-history, and the Fortran units are flushed here).
    subroutine c_exit(status) bind(C, name='_exit')
      import :: c_int
      integer(c_int), value :: status
    end subroutine c_exit
    integer(c_int) function c_access(path, mode) bind(C, name='access')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
    end function c_access
  end interface

contains

  !> Flush standard output and standard error and end the program with exit status `code`.
  !> Only for the programs' main units, after every file they write is closed.
  subroutine exit_program(code)
    integer, intent(in) :: code
    flush (output_unit)
    flush (error_unit)
    call c_exit(int(code, c_int))
  end subroutine exit_program

  !> A warning of `program` ('interlock-fit: warning: ' // text) on standard error.
  subroutine warn(program, text)
    character(len=*), intent(in) :: program, text
    write (error_unit, '(a)') program // ': warning: ' // text
    flush (error_unit)
  end subroutine warn

  !> Command-line argument k, whatever its length.
  function command_argument(k) result(text)
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: length
    call get_command_argument(k, length=length)
    allocate (character(len=length) :: text)
    if (length > 0) call get_command_argument(k, text)
  end function command_argument

  !> The whole command line, whatever its length.
  function command_text() result(text)
    character(len=:), allocatable :: text
    integer :: length
    call get_command(length=length)
    allocate (character(len=length) :: text)
    if (length > 0) call get_command(text)
  end function command_text

  !> `path` is a folder in which this process may create files: access(2) on "path/." for
  !> writing and searching (only a folder has the entry ".").
  logical function folder_writable(path)
    character(len=*), intent(in) :: path
    integer(c_int), parameter :: w_ok = 2_c_int, x_ok = 1_c_int
    folder_writable = .false.
    if (len(path) == 0) return
    folder_writable = c_access(path // '/.' // c_null_char, ior(w_ok, x_ok)) == 0
  end function folder_writable

end module interlock_cli
