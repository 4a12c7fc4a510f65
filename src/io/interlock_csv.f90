!> Measured curves as CSV files: an optional header line of column names, then rows of numbers
!> separated by commas (blanks and tabs around them ignored); blank lines and lines starting
!> with '#' are skipped, and a UTF-8 byte-order mark before the first line is ignored. Every value
!> must be a decimal number of magnitude below max_magnitude (1e150: the fit squares and sums
!> them), written as [sign] digits [. digits] [e|d [sign] digits]: NaN, Inf, an empty field,
!> text, a larger value, a row of another length, a line of more than max_line characters and a
!> header name of more than 64 characters or given twice are errors naming the file, the line
!> and the column. A number may have any number of digits (it is read whole, never cut). A
!> control character (a binary file) or a NUL byte (UTF-16 text: the hint says so) is an error
!> naming the line; no message echoes a byte that is not printable text (printable_text).
module interlock_csv
  use interlock, only: dp, format_integer
  use interlock_files, only: path_kind, path_regular
  use, intrinsic :: iso_fortran_env, only: iostat_eor
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: csv_t, read_csv, csv_column, parse_number, max_magnitude, max_line, printable_text

  !> The longest line read (characters, without the line end).
  integer, parameter :: max_line = 65536
  !> The longest header name.
  integer, parameter :: name_len = 64
  !> Values must be below this in magnitude: the fit squares and sums them (double precision
  !> overflows above 1.8e308).
  real(dp), parameter :: max_magnitude = 1.0e150_dp

  type :: csv_t
    character(len=name_len), allocatable :: names(:)   !< header names ('' without a header)
    real(dp), allocatable :: values(:, :)              !< (rows, columns)
    integer, allocatable :: lines(:)                   !< the file's line of each row
  end type csv_t

contains

  subroutine read_csv(path, csv, message)
    character(len=*), intent(in) :: path
    type(csv_t), intent(out) :: csv
    character(len=*), intent(out) :: message
    integer :: u, ios, line, ncol, nrow, k, n, j
    character(len=max_line) :: text
    character(len=1) :: extra
    character(len=512) :: iomsg
    real(dp), allocatable :: row(:), rows(:, :), grown(:, :)
    integer, allocatable :: first(:), last(:), row_lines(:), grown_lines(:)

    message = ''
    if (path_kind(path) /= path_regular) then
      message = 'the curve file ' // path // ' does not exist or is not a regular file'
      return
    end if
    open (newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      message = 'cannot open the curve file ' // path // ': ' // trim(iomsg)
      return
    end if
    ncol = 0
    nrow = 0
    line = 0
    allocate (rows(0, 0), row_lines(64))
    do
      text = ''
      n = 0
      read (u, '(a)', advance='no', size=n, iostat=ios) text
      if (ios /= 0 .and. ios /= iostat_eor) exit
      line = line + 1
      if (ios == 0) then
        ! the buffer is full: the line goes on unless its end comes next
        k = 0
        read (u, '(a)', advance='no', size=k, iostat=ios) extra
        if (ios /= iostat_eor .or. k > 0) then
          message = path // ': line ' // format_integer(line) // ' is longer than ' // &
                    format_integer(max_line) // ' characters (the longest line read)'
          close (u)
          return
        end if
      end if
      if (line == 1 .and. n >= 3) then
        ! a UTF-8 byte-order mark (EF BB BF) is not part of the first field
        if (ichar(text(1:1)) == 239 .and. ichar(text(2:2)) == 187 .and. ichar(text(3:3)) == 191) &
          text = text(4:)
      end if
      k = len_trim(text)
      if (k > 0) then
        if (text(k:k) == achar(13)) text(k:k) = ' '
      end if
      message = control_character(text(1:n), line, path)
      if (len_trim(message) > 0) then
        close (u)
        return
      end if
      k = verify(text, ' ' // achar(9))
      if (k == 0) cycle
      if (text(k:k) == '#') cycle
      call split(text(1:len_trim(text)), first, last)
      if (ncol == 0) then
        ncol = size(first)
        allocate (csv%names(ncol))
        csv%names = ''
        deallocate (rows)
        allocate (rows(ncol, 64))
        if (.not. all_numbers(text, first, last)) then
          do j = 1, ncol
            if (last(j) - first(j) + 1 > name_len) then
              message = path // ': line ' // format_integer(line) // ', column ' // &
                        format_integer(j) // ': the header name ''' // &
                        printable_text(text(first(j):last(j))) // ''' is longer than ' // format_integer(name_len) // ' characters'
              close (u)
              return
            end if
            csv%names(j) = text(first(j):last(j))
            if (j > 1 .and. len_trim(csv%names(j)) > 0) then
              if (any(csv%names(1:j - 1) == csv%names(j))) then
                message = path // ': line ' // format_integer(line) // ', column ' // &
                          format_integer(j) // ': the header name ''' // &
                          printable_text(trim(csv%names(j))) // ''' is given twice (a column must be named once)'
                close (u)
                return
              end if
            end if
          end do
          cycle
        end if
      end if
      if (size(first) /= ncol) then
        message = path // ': line ' // format_integer(line) // ' has ' // &
                  format_integer(size(first)) // ' fields: every row needs ' // format_integer(ncol)
        close (u)
        return
      end if
      call read_row(text, first, last, row, message)
      if (len_trim(message) > 0) then
        message = path // ': line ' // format_integer(line) // ', ' // trim(message)
        close (u)
        return
      end if
      nrow = nrow + 1
      if (nrow > size(rows, 2)) then
        allocate (grown(ncol, 2 * size(rows, 2)), grown_lines(2 * size(rows, 2)))
        grown(:, 1:nrow - 1) = rows(:, 1:nrow - 1)
        grown_lines(1:nrow - 1) = row_lines(1:nrow - 1)
        call move_alloc(grown, rows)
        call move_alloc(grown_lines, row_lines)
      end if
      rows(:, nrow) = row
      row_lines(nrow) = line
    end do
    close (u)
    if (ncol == 0) then
      message = 'the curve file ' // path // ' holds no data'
      return
    end if
    csv%values = transpose(rows(:, 1:nrow))
    csv%lines = row_lines(1:nrow)
  end subroutine read_csv

  !> '' or the error for the first control character of a line (`text`, its end of line
  !> removed; tabs and the CR of a CR LF line end are text): a NUL byte says UTF-16 (every
  !> second byte of ASCII text in UTF-16 is 0), as does a UTF-16 byte-order mark.
  function control_character(text, line, path) result(message)
    character(len=*), intent(in) :: text, path
    integer, intent(in) :: line
    character(len=512) :: message
    integer :: i, code
    message = ''
    if (line == 1 .and. len(text) >= 2) then
      if ((iachar(text(1:1)) == 255 .and. iachar(text(2:2)) == 254) .or. &
          (iachar(text(1:1)) == 254 .and. iachar(text(2:2)) == 255)) then
        message = path // ': line 1 starts with a UTF-16 byte-order mark: the file is UTF-16 ' // &
                  'text (Windows "Unicode"); save it as ASCII or UTF-8 (CSV UTF-8)'
        return
      end if
    end if
    do i = 1, len(text)
      code = iachar(text(i:i))
      if (code >= 32 .and. code /= 127) cycle
      if (code == 9 .or. (code == 13 .and. i == len(text))) cycle
      message = path // ': line ' // format_integer(line) // ', character ' // &
                format_integer(i) // ': a control character (code ' // format_integer(code) // &
                '): the curve file must be text (ASCII or UTF-8, numbers separated by commas)'
      if (code == 0) message = trim(message) // '; a NUL byte: is it UTF-16 text (Windows ' // &
                               '"Unicode")? Save it as ASCII or UTF-8 (CSV UTF-8)'
      return
    end do
  end function control_character

  !> `text` as it may be echoed in a message: printable ASCII and well-formed UTF-8 sequences
  !> kept, every other byte (a control character, a byte of a binary file or of another
  !> encoding) replaced by '?'.
  pure function printable_text(text) result(shown)
    character(len=*), intent(in) :: text
    character(len=len(text)) :: shown
    integer :: i, k, n, code
    shown = text
    i = 1
    do while (i <= len(text))
      code = iachar(text(i:i))
      if (code >= 32 .and. code < 127) then
        i = i + 1
        cycle
      end if
      ! the length of a UTF-8 sequence from its lead byte (0: not a lead byte)
      n = 0
      if (code >= 194 .and. code <= 223) n = 2
      if (code >= 224 .and. code <= 239) n = 3
      if (code >= 240 .and. code <= 244) n = 4
      if (n > 0 .and. i + n - 1 <= len(text)) then
        if (all([(iachar(text(k:k)) >= 128 .and. iachar(text(k:k)) <= 191, k = i + 1, i + n - 1)])) then
          i = i + n
          cycle
        end if
      end if
      shown(i:i) = '?'
      i = i + 1
    end do
  end function printable_text

  !> The column named `name` (a header name, case as written, or a 1-based column number).
  !> 0 if there is none.
  integer function csv_column(csv, name)
    type(csv_t), intent(in) :: csv
    character(len=*), intent(in) :: name
    integer :: k, ios
    do csv_column = 1, size(csv%names)
      if (trim(csv%names(csv_column)) == trim(name)) return
    end do
    csv_column = 0
    if (len_trim(name) == 0 .or. len_trim(name) > 9) return
    if (verify(trim(name), '0123456789') /= 0) return
    read (name, *, iostat=ios) k
    if (ios == 0 .and. k >= 1 .and. k <= size(csv%names)) csv_column = k
  end function csv_column

  !> The fields of a line: text(first(k):last(k)) without the blanks and tabs around them.
  pure subroutine split(text, first, last)
    character(len=*), intent(in) :: text
    integer, allocatable, intent(out) :: first(:), last(:)
    integer :: n, i, a, b
    n = count([(text(i:i) == ',', i = 1, len(text))]) + 1
    allocate (first(n), last(n))
    a = 1
    n = 0
    do i = 1, len(text) + 1
      if (i <= len(text)) then
        if (text(i:i) /= ',') cycle
      end if
      n = n + 1
      b = i - 1
      do while (a <= b)
        if (text(a:a) /= ' ' .and. text(a:a) /= achar(9)) exit
        a = a + 1
      end do
      do while (b >= a)
        if (text(b:b) /= ' ' .and. text(b:b) /= achar(9)) exit
        b = b - 1
      end do
      first(n) = a
      last(n) = b
      a = i + 1
    end do
  end subroutine split

  logical function all_numbers(text, first, last)
    character(len=*), intent(in) :: text
    integer, intent(in) :: first(:), last(:)
    integer :: i
    real(dp) :: x
    character(len=200) :: why
    all_numbers = .true.
    do i = 1, size(first)
      call parse_number(text(first(i):last(i)), x, why)
      if (len_trim(why) > 0) all_numbers = .false.
    end do
  end function all_numbers

  subroutine read_row(text, first, last, row, message)
    character(len=*), intent(in) :: text
    integer, intent(in) :: first(:), last(:)
    real(dp), allocatable, intent(out) :: row(:)
    character(len=*), intent(out) :: message
    integer :: i
    character(len=200) :: why
    message = ''
    allocate (row(size(first)))
    do i = 1, size(first)
      call parse_number(text(first(i):last(i)), row(i), why)
      if (len_trim(why) > 0) then
        message = 'column ' // format_integer(i) // ': ''' // &
                  printable_text(text(first(i):last(i))) // ''' ' // trim(why)
        return
      end if
    end do
  end subroutine read_row

  !> A decimal number [sign] digits [. digits] [e|E|d|D [sign] digits] (at least one digit
  !> before the exponent) of magnitude below max_magnitude; why /= '' says what it is not.
  !> The magnitude is found from the digits before anything is converted, so no conversion
  !> overflows; a value below 1e-400 in magnitude is 0.
  subroutine parse_number(field, x, why)
    character(len=*), intent(in) :: field
    real(dp), intent(out) :: x
    character(len=*), intent(out) :: why
    integer :: i, n, digits, int_digits, first_nonzero, expo, esign, ios
    logical :: point

    x = 0.0_dp
    why = ''
    n = len(field)
    if (n == 0) then
      why = 'is empty: every field needs a number'
      return
    end if
    i = 1
    if (index('+-', field(1:1)) > 0) i = 2
    digits = 0
    int_digits = 0
    first_nonzero = 0
    point = .false.
    do while (i <= n)
      if (field(i:i) == '.' .and. .not. point) then
        point = .true.
      else if (index('0123456789', field(i:i)) > 0) then
        digits = digits + 1
        if (.not. point) int_digits = int_digits + 1
        if (first_nonzero == 0 .and. field(i:i) /= '0') first_nonzero = digits
      else
        exit
      end if
      i = i + 1
    end do
    expo = 0
    if (digits > 0 .and. i <= n) then
      if (index('eEdD', field(i:i)) > 0 .and. i < n) then
        i = i + 1
        esign = 1
        if (index('+-', field(i:i)) > 0) then
          if (field(i:i) == '-') esign = -1
          i = i + 1
        end if
        if (i > n) digits = 0
        do while (i <= n)
          if (index('0123456789', field(i:i)) == 0) exit
          if (expo < 100000) expo = 10 * expo + (iachar(field(i:i)) - iachar('0'))
          i = i + 1
        end do
        expo = esign * expo
      end if
    end if
    if (digits == 0 .or. i <= n) then
      why = 'is not a finite number (NaN, Inf, empty fields and text are rejected)'
      return
    end if
    if (first_nonzero == 0) return
    ! the value is 0.d... x 10^(int_digits - first_nonzero + 1 + expo)
    if (int_digits - first_nonzero + 1 + expo > 150) then
      why = 'is beyond the largest magnitude read, 1e150 (the fit squares and sums the values)'
      return
    end if
    if (int_digits - first_nonzero + 1 + expo < -400) return
    read (field, *, iostat=ios) x
    if (ios /= 0) then
      why = 'is not a finite number (NaN, Inf, empty fields and text are rejected)'
      return
    end if
    if (.not. ieee_is_finite(x) .or. abs(x) >= max_magnitude) then
      x = 0.0_dp
      why = 'is beyond the largest magnitude read, 1e150 (the fit squares and sums the values)'
    end if
  end subroutine parse_number

end module interlock_csv
