!> The start of a program that reads decks and writes its results into files (interlock-history,
!> interlock-fit): the command line (-h/--help, --version, -d/--output-dir DIR, -q/--quiet where
!> the program has it, `--`, the decks), the output folder (an existing folder, checked before
!> any work), the signal guard's handlers (a signal ends the program without the Fortran
!> runtime's backtrace and removes the temporary files: interlock_posix.c) and the HDF5 library;
!> and its end (`program_end`).
!> A usage error prints its message and the usage on standard error and ends the program with
!> status 1; --help and --version print on standard output and end it with status 0.
module interlock_program_start
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use interlock_cli, only: exit_program, command_argument, command_text
  use interlock_files, only: is_folder, guard_signals
  use interlock_h5, only: h5_open_library, h5_close_library
  use interlock_version, only: interlock_version_string
  implicit none
  private
  public :: program_start_t, deck_path_t, program_start, program_end, in_output_dir

  !> One deck named on the command line.
  type :: deck_path_t
    character(len=:), allocatable :: path
  end type deck_path_t

  !> What the command line asks for.
  type :: program_start_t
    character(len=:), allocatable :: output_dir   !< --output-dir, '' when not given
    character(len=:), allocatable :: command      !< the whole command line (for the files)
    type(deck_path_t), allocatable :: decks(:)    !< the decks, in their order (at least one)
    logical :: quiet = .false.                    !< --quiet (where the program has it)
  end type program_start_t

  abstract interface
    !> The program's usage text on `unit`.
    subroutine usage_writer(unit)
      integer, intent(in) :: unit
    end subroutine usage_writer
  end interface

contains

  !> Read the command line of `program` ('interlock-fit'), check the output folder, install the
  !> signal guard and open the HDF5 library; on a usage error or a failure to start, the message
  !> on standard error and exit status 1. `one_deck`: the program takes one deck only;
  !> `has_quiet`: it takes -q/--quiet.
  subroutine program_start(program, usage, one_deck, has_quiet, start)
    character(len=*), intent(in) :: program
    procedure(usage_writer) :: usage
    logical, intent(in) :: one_deck
    logical, intent(in) :: has_quiet
    type(program_start_t), intent(out) :: start
    character(len=:), allocatable :: arg
    integer :: nargs, i, n_decks, stat
    logical :: options_done

    nargs = command_argument_count()
    allocate (start%decks(max(nargs, 1)))
    n_decks = 0
    start%output_dir = ''
    options_done = .false.
    i = 0
    do while (i < nargs)
      i = i + 1
      arg = command_argument(i)
      if (.not. options_done .and. len(arg) > 0) then
        if (arg(1:1) == '-') then
          select case (arg)
          case ('-h', '--help')
            call usage(output_unit)
            call exit_program(0)
          case ('--version')
            write (output_unit, '(a)') program // ' ' // interlock_version_string
            call exit_program(0)
          case ('-d', '--output-dir')
            if (i == nargs) call usage_error(arg // ' needs a folder')
            i = i + 1
            start%output_dir = command_argument(i)
          case ('--')
            options_done = .true.
          case default
            if (has_quiet .and. (arg == '-q' .or. arg == '--quiet')) then
              start%quiet = .true.
            else
              call usage_error('unknown option ' // arg)
            end if
          end select
          cycle
        end if
      end if
      if (one_deck .and. n_decks == 1) call usage_error('one deck at a time (' // &
                                                        start%decks(1)%path // ', ' // arg // ')')
      n_decks = n_decks + 1
      start%decks(n_decks)%path = arg
    end do
    if (n_decks == 0) call usage_error('no deck given')
    start%decks = start%decks(1:n_decks)
    if (len(start%output_dir) > 0) then
      if (.not. is_folder(start%output_dir)) call start_error('--output-dir ' // &
        start%output_dir // ': no such folder (it must exist)')
    end if
    start%command = command_text()
    call guard_signals(stat)
    if (stat /= 0) call start_error('cannot install the signal handlers')
    call h5_open_library(stat)
    if (stat /= 0) call start_error('cannot initialise the HDF5 library')

  contains

    !> A usage error: the message and the usage on standard error, exit status 1.
    subroutine usage_error(why)
      character(len=*), intent(in) :: why
      write (error_unit, '(a)') program // ': error: ' // why
      call usage(error_unit)
      call exit_program(1)
    end subroutine usage_error

    !> The program cannot start: the message on standard error, exit status 1.
    subroutine start_error(why)
      character(len=*), intent(in) :: why
      write (error_unit, '(a)') program // ': error: ' // why
      call exit_program(1)
    end subroutine start_error

  end subroutine program_start

  !> The end of a program that program_start started: the HDF5 library closed (every file is
  !> closed by then), exit status `rc`.
  subroutine program_end(rc)
    integer, intent(in) :: rc
    integer :: stat
    call h5_close_library(stat)
    call exit_program(rc)
  end subroutine program_end

  !> The file `name` in the output folder `output_dir` (its base name there), or `name` itself
  !> when no output folder is given.
  function in_output_dir(output_dir, name) result(path)
    character(len=*), intent(in) :: output_dir, name
    character(len=:), allocatable :: path
    if (len(output_dir) == 0) then
      path = name
    else
      path = output_dir // '/' // name(index(name, '/', back=.true.) + 1:)
    end if
  end function in_output_dir

end module interlock_program_start
