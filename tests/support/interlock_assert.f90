!> A small assertion layer shaped like pFUnit's (@assertEqual(expected, actual, tolerance)):
!> tolerance-based checks that print the expected and actual values and the tolerance, and
!> count failures.
module interlock_assert
  use, intrinsic :: iso_fortran_env, only: real64, output_unit
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: assert_equal, assert_true, assert_close_rel, assert_finite
  public :: test_case_t, run_case, suite_summary, failures, checks

  integer, parameter :: dp = real64
  integer :: failures = 0   !< failed checks so far in this suite (a test program is serial)
  integer :: checks = 0
  character(len=128) :: current = ''

  abstract interface
    subroutine test_procedure()
    end subroutine test_procedure
  end interface

  !> A named test procedure (as pFUnit's @test).
  type :: test_case_t
    character(len=64) :: name
    procedure(test_procedure), pointer, nopass :: run => null()
  end type test_case_t

  interface assert_equal
    module procedure assert_equal_real, assert_equal_int, assert_equal_real_array
  end interface assert_equal

contains

  subroutine run_case(name, proc)
    character(len=*), intent(in) :: name
    procedure(test_procedure) :: proc
    integer :: before
    before = failures
    current = name
    call proc()
    if (failures == before) then
      write (output_unit, '(a)') '[ ok ] ' // trim(name)
    else
      write (output_unit, '(a,i0,a)') '[FAIL] ' // trim(name) // ' (', failures - before, &
        ' failed checks)'
    end if
  end subroutine run_case

  !> Prints the summary line and returns the process exit status to use (0 when all passed).
  integer function suite_summary(suite) result(code)
    character(len=*), intent(in) :: suite
    write (output_unit, '(a,": ",i0," checks, ",i0," failed")') trim(suite), checks, failures
    code = merge(0, 1, failures == 0)
  end function suite_summary

  !> |actual - expected| <= tolerance (absolute).
  subroutine assert_equal_real(expected, actual, tolerance, what)
    real(dp), intent(in) :: expected, actual, tolerance
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. (abs(actual - expected) <= tolerance)) then
      failures = failures + 1
      write (output_unit, '(a)') '  FAILED ' // trim(current) // ': ' // what
      write (output_unit, '(a,es24.16,a,es24.16,a,es10.3,a,es10.3)') '    expected ', expected, &
        '  actual ', actual, '  |diff| ', abs(actual - expected), '  tolerance ', tolerance
    end if
  end subroutine assert_equal_real

  subroutine assert_equal_real_array(expected, actual, tolerance, what)
    real(dp), intent(in) :: expected(:), actual(:), tolerance
    character(len=*), intent(in) :: what
    integer :: i
    character(len=16) :: idx
    if (size(expected) /= size(actual)) then
      call assert_true(.false., what // ': arrays of different size')
      return
    end if
    do i = 1, size(expected)
      write (idx, '(a,i0,a)') '(', i, ')'
      call assert_equal_real(expected(i), actual(i), tolerance, what // trim(idx))
    end do
  end subroutine assert_equal_real_array

  subroutine assert_equal_int(expected, actual, what)
    integer, intent(in) :: expected, actual
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (expected /= actual) then
      failures = failures + 1
      write (output_unit, '(a)') '  FAILED ' // trim(current) // ': ' // what
      write (output_unit, '(a,i0,a,i0)') '    expected ', expected, '  actual ', actual
    end if
  end subroutine assert_equal_int

  !> |actual - expected| <= rel_tol * max(|expected|, floor).
  subroutine assert_close_rel(expected, actual, rel_tol, floor, what)
    real(dp), intent(in) :: expected, actual, rel_tol, floor
    character(len=*), intent(in) :: what
    call assert_equal_real(expected, actual, rel_tol * max(abs(expected), floor), what)
  end subroutine assert_close_rel

  subroutine assert_true(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. condition) then
      failures = failures + 1
      write (output_unit, '(a)') '  FAILED ' // trim(current) // ': ' // what
    end if
  end subroutine assert_true

  subroutine assert_finite(x, what)
    real(dp), intent(in) :: x(:)
    character(len=*), intent(in) :: what
    call assert_true(all(ieee_is_finite(x)), what // ' is finite')
  end subroutine assert_finite

end module interlock_assert
