!> The deck of interlock-history as text, before any namelist read (docs/deck-format.md): the
!> groups (&name ... /) and, inside each, the assignments `name = values` (outside strings and
!> `!` comments). This lets the reader reject what a namelist read would silently accept or
!> report without naming the variable: text outside every group, unknown or repeated groups,
!> unclosed groups, unknown or repeated variables; and it lets it name the variable whose value
!> cannot be read, by re-reading each assignment alone (`probe_text`). Before all of it the file
!> is loaded as text and checked as bytes (`load_text`: its size, control bytes, line ends).
module interlock_deck_text
  use interlock, only: format_integer, status_ok, status_bad_input
  use interlock_files, only: path_kind, path_absent, path_folder, path_other
  implicit none
  private
  public :: group_scan_t, assignment_t, scan_deck, probe_text, value_text, &
            is_name_char, lower, load_text, int8_text, max_deck_bytes

  integer, parameter :: max_deck_bytes = 4 * 1024 * 1024   !< the size of a deck

  integer, parameter :: name_len = 64

  !> One `name[(subscripts)] = values` of a group: the text span [first, last] from the name to
  !> just before the next assignment or the end of the group.
  type :: assignment_t
    character(len=name_len) :: name = ''
    character(len=name_len) :: subscript = ''   !< '(2)' etc., blanks removed; '' for the whole
    integer :: first = 0, equals = 0, last = 0, line = 0
  end type assignment_t

  !> One group: where it is and its assignments.
  type :: group_scan_t
    logical :: present = .false.
    integer :: line = 0, first = 0, last = 0   !< text after the group name up to the terminator
    integer :: n = 0
    type(assignment_t), allocatable :: a(:)
  end type group_scan_t

contains

  !> Split `text` into the groups `names` (lower case). message /= '' on text outside every
  !> group, an unknown, repeated or unclosed group, or text before a group's first variable.
  subroutine scan_deck(text, names, groups, message)
    character(len=*), intent(in) :: text
    character(len=*), intent(in) :: names(:)
    type(group_scan_t), intent(out) :: groups(size(names))
    character(len=*), intent(out) :: message
    integer :: i, j, g, line
    character :: ch
    character(len=name_len) :: name

    message = ''
    line = 1
    i = 1
    do while (i <= len(text))
      ch = text(i:i)
      if (ch == achar(10)) then
        line = line + 1
      else if (is_blank(ch)) then
        continue
      else if (ch == '!') then
        i = comment_end(text, i)
      else if (ch == '&' .or. ch == '$') then
        j = group_name_end(text, i)
        name = lower(text(i + 1:min(j - 1, i + name_len)))
        if (j == i + 1) then
          message = 'line ' // format_integer(line) // ': a ''' // ch // ''' that does not start a ' // &
                    'group name'
          return
        end if
        if (name == 'end') then
          message = 'line ' // format_integer(line) // ': ' // ch // 'end outside a group'
          return
        end if
        do g = 1, size(names)
          if (trim(names(g)) == trim(name)) exit
        end do
        if (g > size(names)) then
          message = 'line ' // format_integer(line) // ': unknown group &' // trim(name) // &
                    ' (the groups are &' // join(names, ', &') // ')'
          return
        end if
        if (groups(g)%present) then
          message = 'line ' // format_integer(line) // ': the group &' // trim(names(g)) // &
                    ' appears more than once'
          return
        end if
        groups(g)%present = .true.
        groups(g)%line = line
        call scan_group(text, j, line, trim(names(g)), groups(g), i, message)
        if (len_trim(message) > 0) return
      else
        message = 'line ' // format_integer(line) // ': text outside a group: ''' // &
                  snippet(text(i:min(len(text), i + 200))) // ''' (everything but comments ' // &
                  'must be inside a group &name ... /; comments start with !)'
        return
      end if
      i = i + 1
    end do
  end subroutine scan_deck

  !> The body of one group from `first` (just after its name): its assignments up to the
  !> closing '/' (or &end). On return `i` is the terminator's last character.
  subroutine scan_group(text, first, line, gname, group, i, message)
    character(len=*), intent(in) :: text, gname
    integer, intent(in) :: first
    integer, intent(inout) :: line
    type(group_scan_t), intent(inout) :: group
    integer, intent(out) :: i
    character(len=*), intent(out) :: message
    integer :: j, k, n_cap, name_end, eq, lo
    character :: ch, quote
    type(assignment_t), allocatable :: grown(:)
    character(len=name_len) :: sub

    message = ''
    group%first = first
    n_cap = 16
    allocate (group%a(n_cap))
    group%n = 0
    quote = ' '
    i = first
    do while (i <= len(text))
      ch = text(i:i)
      if (ch == achar(10)) then
        line = line + 1
      else if (quote /= ' ') then
        if (ch == quote) quote = ' '
      else if (ch == '''' .or. ch == '"') then
        quote = ch
      else if (ch == '!') then
        i = comment_end(text, i)
      else if (ch == '/') then
        call close_group(i - 1)
        return
      else if (ch == '&' .or. ch == '$') then
        j = group_name_end(text, i)
        if (lower(text(i + 1:j - 1)) == 'end') then
          call close_group(i - 1)
          i = j - 1
          return
        end if
        message = '&' // gname // ' (line ' // format_integer(group%line) // ') is not closed by ''/'' ' // &
                  'before line ' // format_integer(line) // ': ''' // snippet(text(i:min(len(text), i + 40))) // ''''
        return
      else if (is_letter(ch) .and. starts_name(i)) then
        ! A name; an assignment if '=' follows (after blanks and one subscript).
        j = i
        do while (j < len(text))
          if (.not. is_name_char(text(j + 1:j + 1))) exit
          j = j + 1
        end do
        name_end = j
        k = skip_blanks(j + 1)
        sub = ''
        if (k <= len(text)) then
          if (text(k:k) == '(') then
            lo = k
            do while (k <= len(text))
              if (text(k:k) == ')' .or. text(k:k) == achar(10)) exit
              k = k + 1
            end do
            sub = squeeze(text(lo:min(k, len(text))))
            k = skip_blanks(k + 1)
          end if
        end if
        eq = 0
        if (k <= len(text)) then
          if (text(k:k) == '=') eq = k
        end if
        if (eq > 0) then
          if (group%n > 0) then
            group%a(group%n)%last = i - 1
          else if (len_trim(strip(text(first:i - 1))) > 0) then
            message = '&' // gname // ': unexpected text before the first variable: ''' // &
                      snippet(strip(text(first:i - 1))) // ''' (line ' // format_integer(line) // ')'
            return
          end if
          if (group%n == n_cap) then
            n_cap = 2 * n_cap
            allocate (grown(n_cap))
            grown(1:group%n) = group%a(1:group%n)
            call move_alloc(grown, group%a)
          end if
          group%n = group%n + 1
          group%a(group%n)%name = lower(text(i:min(name_end, i + name_len - 1)))
          group%a(group%n)%subscript = sub
          group%a(group%n)%first = i
          group%a(group%n)%equals = eq
          group%a(group%n)%line = line
          do j = i, eq
            if (text(j:j) == achar(10)) line = line + 1
          end do
          i = eq
        else
          i = name_end
        end if
      end if
      i = i + 1
    end do
    message = '&' // gname // ' (line ' // format_integer(group%line) // ') is not closed: the ' // &
              'deck ends before its closing ''/'''
    if (quote /= ' ') message = trim(message) // ' (a string opened with ' // quote // &
                                ' is not closed)'

  contains

    subroutine close_group(last)
      integer, intent(in) :: last
      group%last = last
      if (group%n > 0) then
        group%a(group%n)%last = last
      else if (len_trim(strip(text(first:last))) > 0) then
        message = '&' // gname // ': unexpected text: ''' // snippet(strip(text(first:last))) // &
                  ''' (a variable is set as name = value)'
      end if
    end subroutine close_group

    logical function starts_name(pos)
      integer, intent(in) :: pos
      starts_name = .true.
      if (pos > 1) starts_name = .not. (is_name_char(text(pos - 1:pos - 1)) .or. &
                                        text(pos - 1:pos - 1) == '.')
    end function starts_name

    integer function skip_blanks(pos)
      integer, intent(in) :: pos
      skip_blanks = pos
      do while (skip_blanks <= len(text))
        if (.not. (is_blank(text(skip_blanks:skip_blanks)) .or. &
                   text(skip_blanks:skip_blanks) == achar(10))) exit
        skip_blanks = skip_blanks + 1
      end do
    end function skip_blanks

  end subroutine scan_group

  !> "&group <assignment> /" on one line, comments removed: a namelist record that reads the
  !> one assignment alone.
  function probe_text(text, gname, a) result(probe)
    character(len=*), intent(in) :: text, gname
    type(assignment_t), intent(in) :: a
    character(len=:), allocatable :: probe
    probe = '&' // gname // ' ' // strip(text(a%first:a%last)) // ' /'
  end function probe_text

  !> The value text of an assignment (one line, comments removed, at most ~60 characters).
  function value_text(text, a) result(value)
    character(len=*), intent(in) :: text
    type(assignment_t), intent(in) :: a
    character(len=:), allocatable :: value
    value = snippet(trim(adjustl(strip(text(a%equals + 1:a%last)))))
    do while (len(value) > 0)
      if (value(len(value):len(value)) /= ',') exit
      value = trim(value(1:len(value) - 1))
    end do
  end function value_text

  !> The text with comments removed and line breaks, tabs, form feeds as blanks.
  pure function strip(text) result(out)
    character(len=*), intent(in) :: text
    character(len=len(text)) :: out
    integer :: i
    character :: quote
    logical :: comment
    out = text
    quote = ' '
    comment = .false.
    do i = 1, len(text)
      if (text(i:i) == achar(10)) then
        comment = .false.
        out(i:i) = ' '
      else if (comment) then
        out(i:i) = ' '
      else if (quote /= ' ') then
        if (text(i:i) == quote) quote = ' '
      else if (text(i:i) == '!') then
        comment = .true.
        out(i:i) = ' '
      else if (text(i:i) == '''' .or. text(i:i) == '"') then
        quote = text(i:i)
      else if (is_blank(text(i:i))) then
        out(i:i) = ' '
      end if
    end do
  end function strip

  !> At most 60 characters of text, blank runs squeezed, '...' when cut.
  pure function snippet(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: i, n
    character(len=64) :: buf
    buf = ''
    n = 0
    do i = 1, len(text)
      if (n >= 60) exit
      if (text(i:i) == achar(10) .or. is_blank(text(i:i))) then
        if (n == 0) cycle
        if (buf(n:n) == ' ') cycle
        n = n + 1
        buf(n:n) = ' '
      else
        n = n + 1
        buf(n:n) = text(i:i)
      end if
    end do
    out = trim(buf(1:max(n, 1)))
    if (i <= len(text)) then
      if (len_trim(text(i:)) > 0) out = out // '...'
    end if
  end function snippet

  pure function squeeze(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: i
    out = ''
    do i = 1, len(text)
      if (.not. (is_blank(text(i:i)) .or. text(i:i) == achar(10))) out = out // text(i:i)
    end do
  end function squeeze

  pure function join(names, sep) result(out)
    character(len=*), intent(in) :: names(:), sep
    character(len=:), allocatable :: out
    integer :: g
    out = trim(names(1))
    do g = 2, size(names)
      out = out // sep // trim(names(g))
    end do
  end function join

  pure logical function is_blank(ch)
    character, intent(in) :: ch
    is_blank = ch == ' ' .or. ch == achar(9) .or. ch == achar(13) .or. ch == achar(12)
  end function is_blank

  pure logical function is_letter(ch)
    character, intent(in) :: ch
    is_letter = (ch >= 'a' .and. ch <= 'z') .or. (ch >= 'A' .and. ch <= 'Z')
  end function is_letter

  pure logical function is_name_char(ch)
    character, intent(in) :: ch
    is_name_char = is_letter(ch) .or. (ch >= '0' .and. ch <= '9') .or. ch == '_'
  end function is_name_char

  pure function lower(s) result(t)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: t
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
    end do
  end function lower


  !> The last character of the comment that starts at text(i:i) (the one before the line feed).
  pure integer function comment_end(text, i) result(k)
    character(len=*), intent(in) :: text
    integer, intent(in) :: i
    k = i
    do while (k < len(text))
      if (text(k + 1:k + 1) == achar(10)) exit
      k = k + 1
    end do
  end function comment_end

  !> One past the last character of the name that follows the '&' or '$' at text(i:i).
  pure integer function group_name_end(text, i) result(j)
    character(len=*), intent(in) :: text
    integer, intent(in) :: i
    j = i + 1
    do while (j <= len(text))
      if (.not. is_name_char(text(j:j))) exit
      j = j + 1
    end do
  end function group_name_end

  !> The whole file as text (stream read): it must exist, be non-empty, at most
  !> max_deck_bytes long, and hold no control bytes but tab, line feed, carriage return, form feed.
  subroutine load_text(path, text, stat, message)
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: text
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    logical :: exists
    integer :: u, ios, i, c, line
    logical :: ok_cr
    integer(kind=8) :: nbytes
    character(len=512) :: iomsg

    stat = status_bad_input
    message = ''
    text = ''
    select case (path_kind(path))
    case (path_absent)
      message = path // ': no such deck file'
      return
    case (path_folder)
      message = path // ': the deck is a folder, not a file'
      return
    case (path_other)
      message = path // ': the deck is not a regular file (a FIFO, a device such as ' // &
                '/dev/zero, or a socket): give a deck file'
      return
    end select
    inquire (file=path, exist=exists, size=nbytes)
    if (.not. exists) then
      message = path // ': no such deck file'
      return
    end if
    if (nbytes == 0) then
      message = path // ': the deck is empty'
      return
    end if
    if (nbytes < 0) then
      message = path // ': the deck is not a regular file'
      return
    end if
    if (nbytes > max_deck_bytes) then
      message = path // ': the deck has ' // trim(int8_text(nbytes)) // ' bytes: admissible ' // &
                'at most ' // format_integer(max_deck_bytes) // ' bytes (4 MiB)'
      return
    end if
    deallocate (text)
    allocate (character(len=int(nbytes)) :: text)
    open (newunit=u, file=path, status='old', action='read', access='stream', &
          form='unformatted', iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      message = path // ': cannot open the deck: ' // trim(iomsg)
      return
    end if
    read (u, iostat=ios, iomsg=iomsg) text
    close (u)
    if (ios /= 0) then
      message = path // ': cannot read the deck: ' // trim(iomsg)
      return
    end if
    ! A UTF-8 byte order mark (EF BB BF, written by some Windows editors) marks the encoding;
    ! it is not text: dropped.
    if (len(text) >= 3) then
      if (text(1:3) == char(239) // char(187) // char(191)) text = text(4:)
    end if
    if (len(text) == 0) then
      message = path // ': the deck is empty (only a UTF-8 byte order mark)'
      return
    end if
    if (len(text) >= 2) then
      c = ichar(text(1:1)) + 256 * ichar(text(2:2))
      if (c == 255 + 256 * 254 .or. c == 254 + 256 * 255) then
        message = path // ': the deck is UTF-16 encoded (a byte order mark ' // &
                  'and NUL bytes): write it as ASCII or UTF-8 text'
        return
      end if
    end if
    line = 1
    do i = 1, len(text)
      c = iachar(text(i:i))
      if (c == 10) line = line + 1
      if (c == 13) then
        ok_cr = i < len(text)
        if (ok_cr) ok_cr = text(i + 1:i + 1) == achar(10)
        if (.not. ok_cr) then
          message = path // ': line ' // format_integer(line) // ': a carriage return (code 13) ' // &
                    'without a line feed: line ends must be LF (Unix) or CR LF (Windows)'
          return
        end if
      end if
      if (c < 32 .and. c /= 9 .and. c /= 10 .and. c /= 13 .and. c /= 12 .or. c == 127) then
        message = path // ': line ' // format_integer(line) // ': byte ' // format_integer(i) // &
                  ' is a control character (code ' // format_integer(c) // &
                  '): the deck must be a text file (a Fortran namelist)'
        return
      end if
    end do
    stat = status_ok
  end subroutine load_text

  pure function int8_text(i) result(text)
    integer(kind=8), intent(in) :: i
    character(len=24) :: text
    write (text, '(i0)') i
  end function int8_text

end module interlock_deck_text
