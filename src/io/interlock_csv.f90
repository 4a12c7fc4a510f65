!> Measured curves as CSV files: an optional header line of column names, then rows of numbers
!> separated by commas (blanks around them ignored); blank lines and lines starting with '#' are
!> skipped. Every value must be a finite number: NaN, Inf, an empty field or text is an error
!> naming the file, the line and the column; so are rows of different lengths.
module interlock_csv
  use interlock, only: dp, format_integer
  use interlock_files, only: path_kind, path_regular
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: csv_t, read_csv, csv_column

  integer, parameter :: max_line = 65536

  type :: csv_t
    character(len=64), allocatable :: names(:)   !< header names ('' without a header)
    real(dp), allocatable :: values(:, :)        !< (rows, columns)
  end type csv_t

contains

  subroutine read_csv(path, csv, message)
    character(len=*), intent(in) :: path
    type(csv_t), intent(out) :: csv
    character(len=*), intent(out) :: message
    integer :: u, ios, line, ncol, nrow, k
    character(len=max_line) :: text
    character(len=512) :: iomsg
    real(dp), allocatable :: row(:), rows(:, :), grown(:, :)
    character(len=64), allocatable :: fields(:)
    logical :: header_done

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
    header_done = .false.
    allocate (rows(0, 0))
    do
      read (u, '(a)', iostat=ios) text
      if (ios /= 0) exit
      line = line + 1
      k = len_trim(text)
      if (k > 0) then
        if (text(k:k) == achar(13)) text(k:k) = ' '
      end if
      if (len_trim(text) == 0) cycle
      k = verify(text, ' ' // achar(9))
      if (text(k:k) == '#') cycle
      call split(trim(text), fields)
      if (ncol == 0) then
        ncol = size(fields)
        allocate (csv%names(ncol))
        csv%names = ''
        deallocate (rows)
        allocate (rows(ncol, 64))
        if (.not. all_numbers(fields)) then
          csv%names = fields
          header_done = .true.
          cycle
        end if
      end if
      if (size(fields) /= ncol) then
        message = path // ': line ' // format_integer(line) // ' has ' // &
                  format_integer(size(fields)) // ' fields: every row needs ' // format_integer(ncol)
        close (u)
        return
      end if
      call read_row(fields, row, message)
      if (len_trim(message) > 0) then
        message = path // ': line ' // format_integer(line) // ', ' // trim(message)
        close (u)
        return
      end if
      nrow = nrow + 1
      if (nrow > size(rows, 2)) then
        allocate (grown(ncol, 2 * size(rows, 2)))
        grown(:, 1:nrow - 1) = rows(:, 1:nrow - 1)
        call move_alloc(grown, rows)
      end if
      rows(:, nrow) = row
    end do
    close (u)
    if (ncol == 0) then
      message = 'the curve file ' // path // ' holds no data'
      return
    end if
    csv%values = transpose(rows(:, 1:nrow))
  end subroutine read_csv

  !> The column named `name` (a header name, case as written, or a 1-based column number).
  !> 0 if there is none.
  integer function csv_column(csv, name)
    type(csv_t), intent(in) :: csv
    character(len=*), intent(in) :: name
    integer :: k, ios
    do csv_column = 1, size(csv%names)
      if (trim(csv%names(csv_column)) == trim(name)) return
    end do
    read (name, *, iostat=ios) k
    csv_column = 0
    if (ios == 0 .and. verify(trim(name), '0123456789') == 0) then
      if (k >= 1 .and. k <= size(csv%names)) csv_column = k
    end if
  end function csv_column

  subroutine split(text, fields)
    character(len=*), intent(in) :: text
    character(len=64), allocatable, intent(out) :: fields(:)
    integer :: n, i, start
    n = count([(text(i:i) == ',', i = 1, len(text))]) + 1
    allocate (fields(n))
    start = 1
    n = 0
    do i = 1, len(text) + 1
      if (i > len(text)) then
        n = n + 1
        fields(n) = adjustl(text(start:))
      else if (text(i:i) == ',') then
        n = n + 1
        fields(n) = adjustl(text(start:i - 1))
        start = i + 1
      end if
    end do
  end subroutine split

  logical function all_numbers(fields)
    character(len=*), intent(in) :: fields(:)
    integer :: i, ios
    real(dp) :: x
    all_numbers = .true.
    do i = 1, size(fields)
      read (fields(i), *, iostat=ios) x
      if (ios /= 0 .or. len_trim(fields(i)) == 0 .or. &
          verify(trim(fields(i)), '0123456789+-.eEdDnNaAiIfF') /= 0) all_numbers = .false.
    end do
  end function all_numbers

  subroutine read_row(fields, row, message)
    character(len=*), intent(in) :: fields(:)
    real(dp), allocatable, intent(out) :: row(:)
    character(len=*), intent(out) :: message
    integer :: i, ios
    message = ''
    allocate (row(size(fields)))
    do i = 1, size(fields)
      ios = 1
      if (len_trim(fields(i)) > 0 .and. verify(trim(fields(i)), '0123456789+-.eEdD') == 0) &
        read (fields(i), *, iostat=ios) row(i)
      if (ios == 0) then
        if (.not. ieee_is_finite(row(i))) ios = 1
      end if
      if (ios /= 0) then
        message = 'column ' // format_integer(i) // ': ''' // trim(fields(i)) // &
                  ''' is not a finite number (NaN, Inf, empty fields and text are rejected)'
        return
      end if
    end do
  end subroutine read_row

end module interlock_csv
