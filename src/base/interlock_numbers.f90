!> Numbers on their bits and as text: the range test of any bits by integer operations (no
!> comparison of a NaN, so a signalling NaN from a host never traps), flags and whole numbers,
!> and the compact rendering of reals and integers that every message uses.
module interlock_numbers
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp, same_value, is_finite_bits, is_nan_value
  implicit none
  private
  public :: keys_in_range, key_in_range, is_flag, is_whole, format_real, format_reals, &
            format_integer

contains

  !> lo(i) <= key(x(i)) <= hi(i) for every i (key_in_range): a range check of any bits by
  !> integer operations only (no comparison of a NaN), counted, not branched.
  pure logical function keys_in_range(n, x, lo, hi) result(ok)
    integer, intent(in) :: n
    real(dp), intent(in) :: x(n)
    integer(int64), intent(in) :: lo(n), hi(n)
    integer :: i, n_out
    n_out = 0
    do i = 1, n
      n_out = n_out + merge(0, 1, key_in_range(x(i), lo(i), hi(i)))
    end do
    ok = n_out == 0
  end function keys_in_range

  !> lo <= key(x) <= hi, with key(x) the bits of x as an integer that orders as x does (IEEE
  !> 754 doubles: a non-negative x as its bits, a negative one with every bit but the sign
  !> flipped): -0 just below +0 (key -1), NaN beyond the infinities (+NaN above +Inf, -NaN
  !> below -Inf). Integer operations only: no comparison of a NaN. The test is the cheapest
  !> for the range's shape; with constant bounds (an unrolled loop over a table) the compiler
  !> keeps only that one: a symmetric range |x| <= B on the magnitude's bits; a range of
  !> non-negative keys on the bits themselves (a negative number's bits are negative as an
  !> integer); a range from -0 likewise, -0 admitted by its pattern; any other by the key.
  elemental logical function key_in_range(x, lo, hi) result(ok)
    real(dp), intent(in) :: x
    integer(int64), intent(in) :: lo, hi
    integer(int64), parameter :: minus_zero = -huge(0_int64) - 1_int64
    integer(int64) :: bits
    bits = transfer(x, 0_int64)
    if (lo == -hi - 1_int64) then
      ok = iand(bits, huge(bits)) <= hi
    else if (lo >= 0_int64) then
      ok = bits >= lo .and. bits <= hi
    else if (lo == -1_int64) then
      ok = ble(bits, hi) .or. bits == minus_zero   ! (unsigned: a negative number's bits beyond)
    else
      bits = ieor(bits, iand(shifta(bits, 63), huge(bits)))
      ok = bits >= lo .and. bits <= hi
    end if
  end function key_in_range

  !> x is 0 or 1 (a flag), from its bits: +-0 or the bits of 1 (no comparison of a NaN).
  elemental logical function is_flag(x)
    real(dp), intent(in) :: x
    integer(int64), parameter :: one_bits = transfer(1.0_dp, 0_int64)
    integer(int64) :: bits
    bits = transfer(x, 0_int64)
    is_flag = iand(bits, huge(bits)) == 0_int64 .or. bits == one_bits
  end function is_flag

  !> x is a whole number, for x within [0, 2^52) (a flag's or a choice's range, checked).
  elemental logical function is_whole(x)
    real(dp), intent(in) :: x
    real(dp), parameter :: whole = 2.0_dp**52
    is_whole = .not. ((x + whole) - whole < x .or. (x + whole) - whole > x)
  end function is_whole

  !> format_real's text, blank-padded: six significant digits, trailing zeros dropped (0.3,
  !> -0.0015, 2.5e-07, 1e+200); but a rounded text that would look exact (fewer than six digits
  !> left, as 6 + 1e-10 would print "6") is replaced by the shortest text that reads back as x
  !> (up to 17 digits: "6.0000000001"), so that a value refused at a bound never reads as the
  !> bound itself.
  pure function real_text(x) result(text)
    real(dp), intent(in) :: x
    character(len=32) :: text
    integer :: digits
    ! (from the bits first: a signalling NaN, which a host may pass, traps in any float test)
    if (.not. is_finite_bits(x)) then
      if (is_nan_value(x)) then
        text = 'NaN'
      else
        text = merge('-Inf', '+Inf', transfer(x, 0_int64) < 0_int64)
      end if
    else if (same_value(x, anint(x)) .and. abs(x) < 1.0e9_dp) then
      text = format_integer_8(nint(x, kind=int64))
    else
      text = rounded_text(x, 0)
      if (significant_digits(text) < 6 .and. .not. reads_as(text, x)) then
        do digits = 7, 17
          text = rounded_text(x, digits)
          if (reads_as(text, x)) exit
        end do
      end if
    end if
  end function real_text

  !> x (finite, not a small whole number) as text, trailing zeros dropped: digits = 0, six
  !> decimals from 1e-3 to 1e6 and six significant digits elsewhere; else `digits` significant
  !> digits, in the same two styles.
  pure function rounded_text(x, digits) result(text)
    real(dp), intent(in) :: x
    integer, intent(in) :: digits
    character(len=32) :: text
    character(len=32) :: buf
    character(len=16) :: form
    integer :: decimals
    if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e6_dp) then
      decimals = 6
      if (digits > 0) decimals = max(0, digits - 1 - floor(log10(abs(x))))
      write (form, '(a,i0,a)') '(f0.', decimals, ')'
      write (buf, form) x
      buf = adjustl(buf)
      if (index(buf, '.') > 0) buf = strip_zeros(buf)
      if (buf(1:1) == '.') buf = '0' // buf(1:len(buf) - 1)
      if (buf(1:2) == '-.') buf = '-0' // buf(2:len(buf) - 1)
      if (len_trim(strip_zeros(buf)) == 0) buf = '0'
      text = buf
    else
      write (form, '(a,i0,a,i0,a)') '(es', 9 + max(digits, 6), '.', max(digits, 6) - 1, 'e3)'
      write (buf, form) x
      buf = adjustl(buf)
      text = trim(strip_zeros(buf(1:index(buf, 'E') - 1))) // 'e' // &
             trim(exponent_text(buf(index(buf, 'E') + 1:)))
    end if
  end function rounded_text

  !> The significant digits of a number's text (its mantissa's digits from the first nonzero).
  pure integer function significant_digits(text) result(n)
    character(len=*), intent(in) :: text
    integer :: i
    logical :: leading
    n = 0
    leading = .true.
    do i = 1, len_trim(text)
      if (text(i:i) == 'e' .or. text(i:i) == 'E') exit
      if (text(i:i) < '0' .or. text(i:i) > '9') cycle
      if (leading .and. text(i:i) == '0') cycle
      leading = .false.
      n = n + 1
    end do
  end function significant_digits

  !> The text reads back as x (finite).
  pure logical function reads_as(text, x)
    character(len=*), intent(in) :: text
    real(dp), intent(in) :: x
    real(dp) :: y
    integer :: ios
    read (text, *, iostat=ios) y
    reads_as = ios == 0
    if (reads_as) reads_as = same_value(y, x)
  end function reads_as

  !> A compact, exact-enough rendering of a real for messages and tables.
  !> The text functions here (and every function whose text a UMAT call may build) declare
  !> their result's length by a specification expression, never as deferred (`len=:`): at a
  !> call of a function with a deferred-length result, gfortran 12 keeps the result's length
  !> in a static variable of the caller, which concurrent threads overwrite (garbled messages
  !> from a UMAT called on several threads; test umat_omp). The text is built twice (once
  !> for its length): on the messages' path only.
  pure function format_real(x) result(text)
    real(dp), intent(in) :: x
    character(len=len_trim(real_text(x))) :: text
    text = real_text(x)
  end function format_real

  !> format_reals' text, blank-padded.
  pure function reals_text(x) result(padded)
    real(dp), intent(in) :: x(:)
    character(len=240) :: padded
    character(len=:), allocatable :: text
    integer :: i
    text = format_real(x(1))
    do i = 2, size(x)
      text = text // ', ' // format_real(x(i))
    end do
    padded = text
  end function reals_text

  !> Reals as a list (format_real each): "x, y, z".
  pure function format_reals(x) result(text)
    real(dp), intent(in) :: x(:)
    character(len=len_trim(reals_text(x))) :: text
    text = reals_text(x)
  end function format_reals

  !> format_integer's text for a 64-bit integer, blank-padded.
  pure function format_integer_8(i) result(text)
    integer(int64), intent(in) :: i
    character(len=24) :: text
    character(len=24) :: buf
    integer(int64) :: n
    integer :: p
    n = abs(i)   ! (|i| < 2^63: the integers of a message)
    p = len(buf) + 1
    do
      p = p - 1
      buf(p:p) = achar(iachar('0') + int(mod(n, 10_int64)))
      n = n / 10_int64
      if (n == 0_int64) exit
    end do
    if (i < 0) then
      p = p - 1
      buf(p:p) = '-'
    end if
    text = buf(p:)
  end function format_integer_8

  !> An integer as text, without blanks: 42 -> "42".
  !> Digit by digit, without an internal write (no run-time library call on a UMAT's message
  !> path).
  pure function format_integer(i) result(text)
    integer, intent(in) :: i
    character(len=len_trim(format_integer_8(int(i, int64)))) :: text
    text = format_integer_8(int(i, int64))
  end function format_integer

  !> "1.500000" -> "1.5", "2.000" -> "2".
  pure function strip_zeros(s) result(r)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: r
    integer :: n
    r = s
    n = len_trim(r)
    do while (n > 1 .and. r(n:n) == '0')
      r(n:n) = ' '
      n = n - 1
    end do
    if (r(n:n) == '.') r(n:n) = ' '
  end function strip_zeros

  !> "+005" -> "+05" (at least two digits), "-010" -> "-10"; blank-padded.
  pure function exponent_text(s) result(r)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: r
    integer :: n
    r = adjustl(s)
    n = len_trim(r)
    do while (n > 3 .and. r(2:2) == '0')
      r = r(1:1) // r(3:)
      n = n - 1
    end do
  end function exponent_text

end module interlock_numbers
