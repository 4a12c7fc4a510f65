!> Files as the operating system sees them (interlock_posix.c and the C library): what a path
!> names, whether it is a folder that can be opened, whether two paths are the same file,
!> removing and renaming, and the guard that removes unfinished output files when the program
!> ends before they are complete (any signal that ends it and can be caught, or an exit).
module interlock_files
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_associated, c_long
  implicit none
  private
  public :: path_absent, path_regular, path_folder, path_other, path_kind, same_file, &
            guard_file, unguard_file, remove_file, rename_file, process_id, temporary_name, &
            is_folder, guard_signals, hold_signals, write_file

  !> What a path names (path_kind): nothing, a regular file, a folder, anything else (a FIFO,
  !> a device, a socket).
  integer, parameter :: path_absent = 0, path_regular = 1, path_folder = 2, path_other = 3

  interface
    type(c_ptr) function c_opendir(path) bind(C, name='opendir')
      import :: c_ptr, c_char
      character(kind=c_char), intent(in) :: path(*)
    end function c_opendir
    integer(c_int) function c_closedir(dir) bind(C, name='closedir')
      import :: c_ptr, c_int
      type(c_ptr), value :: dir
    end function c_closedir
    integer(c_int) function c_path_kind(path) bind(C, name='interlock_path_kind')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
    end function c_path_kind
    integer(c_int) function c_same_file(a, b) bind(C, name='interlock_same_file')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: a(*), b(*)
    end function c_same_file
    integer(c_int) function c_guard_file(path) bind(C, name='interlock_guard_file')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
    end function c_guard_file
    integer(c_int) function c_guard_signals() bind(C, name='interlock_guard_signals')
      import :: c_int
    end function c_guard_signals
    integer(c_int) function c_hold_signals(hold) bind(C, name='interlock_hold_signals')
      import :: c_int
      integer(c_int), value :: hold
    end function c_hold_signals
    integer(c_int) function c_write_file(path, data, n) bind(C, name='interlock_write_file')
      import :: c_int, c_char, c_long
      character(kind=c_char), intent(in) :: path(*), data(*)
      integer(c_long), value :: n
    end function c_write_file
    subroutine c_unguard_file(path) bind(C, name='interlock_unguard_file')
      import :: c_char
      character(kind=c_char), intent(in) :: path(*)
    end subroutine c_unguard_file

    integer(c_int) function c_rename(old, new) bind(C, name='rename')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: old(*), new(*)
    end function c_rename
    integer(c_int) function c_unlink(path) bind(C, name='unlink')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
    end function c_unlink
    integer(c_int) function c_getpid() bind(C, name='getpid')
      import :: c_int
    end function c_getpid
  end interface

contains

  !> An existing folder (opendir succeeds).
  logical function is_folder(path)
    character(len=*), intent(in) :: path
    type(c_ptr) :: dir
    integer(c_int) :: ignore
    dir = c_opendir(path // c_null_char)
    is_folder = c_associated(dir)
    if (is_folder) ignore = c_closedir(dir)
  end function is_folder

  !> path_absent, path_regular, path_folder or path_other (symbolic links followed).
  integer function path_kind(path)
    character(len=*), intent(in) :: path
    path_kind = int(c_path_kind(path // c_null_char))
  end function path_kind

  !> Both paths exist and name the same file (the same device and inode).
  logical function same_file(a, b)
    character(len=*), intent(in) :: a, b
    same_file = c_same_file(a // c_null_char, b // c_null_char) /= 0
  end function same_file

  !> From now on `path` is removed if the program ends before unguard_file(path): by a signal
  !> (SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, ...: every one that ends it and can be caught)
  !> or an exit. stat /= 0: the guard could not be set (a path of 8192 bytes or more, or four
  !> files guarded already).
  subroutine guard_file(path, stat)
    character(len=*), intent(in) :: path
    integer, intent(out) :: stat
    stat = int(c_guard_file(path // c_null_char))
  end subroutine guard_file

  !> The guard's signal handlers from now on, before any file is guarded (as guard_file installs
  !> them): a signal that ends the program then ends it without the Fortran runtime's backtrace,
  !> and SIGXFSZ makes a write fail instead. stat /= 0: they could not be installed.
  subroutine guard_signals(stat)
    integer, intent(out) :: stat
    stat = int(c_guard_signals())
  end subroutine guard_signals

  !> hold = .true.: the signals sent from outside wait until hold_signals(.false.), so that
  !> what is done meanwhile (renaming two files that belong together) is done whole; a signal
  !> that came meanwhile takes effect at hold_signals(.false.).
  subroutine hold_signals(hold)
    logical, intent(in) :: hold
    integer(c_int) :: ignore
    ignore = c_hold_signals(merge(1_c_int, 0_c_int, hold))
  end subroutine hold_signals

  !> The guarded file `path` is complete or gone: the end of the program no longer removes it.
  subroutine unguard_file(path)
    character(len=*), intent(in) :: path
    call c_unguard_file(path // c_null_char)
  end subroutine unguard_file


  !> Write `text` as the file `path` (created or truncated), every byte or an error: stat /= 0
  !> (the C library's errno) when a write or the close failed, a full disk or a file-size limit
  !> included; the file may then hold part of it (the caller removes it).
  subroutine write_file(path, text, stat)
    character(len=*), intent(in) :: path, text
    integer, intent(out) :: stat
    stat = int(c_write_file(path // c_null_char, text, int(len(text), c_long)))
  end subroutine write_file

  !> Remove a file if it is there (nothing happens otherwise; never a folder: unlink(2)).
  subroutine remove_file(path)
    character(len=*), intent(in) :: path
    integer(c_int) :: ignore
    ignore = c_unlink(path // c_null_char)
  end subroutine remove_file

  !> Give file `old` the name `new` (replacing a file of that name in one step). stat /= 0:
  !> it could not.
  subroutine rename_file(old, new, stat)
    character(len=*), intent(in) :: old, new
    integer, intent(out) :: stat
    stat = int(c_rename(old // c_null_char, new // c_null_char))
  end subroutine rename_file

  !> The temporary name of the output file `final_name` while it is written: NAME.tmp-PID in the
  !> same folder (the rename that completes it stays on one file system). Where that would
  !> exceed the 255 bytes a file name may have (NAME_MAX of Linux file systems), NAME is cut
  !> and followed by a hash of the whole name, so that every legal output name has a legal,
  !> distinct temporary name.
  function temporary_name(final_name) result(temp)
    character(len=*), intent(in) :: final_name
    character(len=:), allocatable :: temp
    integer, parameter :: name_max = 255
    character(len=16) :: pid
    character(len=8) :: hash
    character(len=:), allocatable :: base, folder, suffix
    integer :: slash, i
    integer(8) :: h
    write (pid, '(i0)') process_id()
    suffix = '.tmp-' // trim(pid)
    slash = index(final_name, '/', back=.true.)
    folder = final_name(1:slash)
    base = final_name(slash + 1:)
    if (len(base) + len(suffix) > name_max) then
      ! FNV-1a, 32 bits
      h = 2166136261_8
      do i = 1, len(base)
        h = iand(ieor(h, int(iachar(base(i:i)), 8)) * 16777619_8, 4294967295_8)
      end do
      write (hash, '(z8.8)') h
      base = base(1:name_max - len(suffix) - 9) // '-' // hash
    end if
    temp = folder // base // suffix
  end function temporary_name

  !> This process's id.
  integer function process_id()
    process_id = int(c_getpid())
  end function process_id

end module interlock_files
