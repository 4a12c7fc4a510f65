!> Working precision, constants and the convention for "infinite" parameters.
module interlock_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int64
  implicit none
  private
  public :: dp, pi, deg_to_rad, rad_to_deg, infinite_threshold, separation_bound, &
            within_separation_bound
  public :: is_finite_bits, is_finite_value, is_infinite_value, is_nan_value, same_value, &
            exponent_bits

  integer, parameter :: dp = real64
  real(dp), parameter :: pi = 3.14159265358979323846264338327950288_dp
  real(dp), parameter :: deg_to_rad = pi / 180.0_dp
  real(dp), parameter :: rad_to_deg = 180.0_dp / pi
  !> A parameter at or above this value (or +Inf) means "+infinity", i.e. the effect it
  !> controls is off (H_N, zeta_0). FE input files cannot always hold an IEEE infinity.
  real(dp), parameter :: infinite_threshold = 1.0e30_dp
  !> The largest admissible |s_N|, |s_T| [mm] (a kilometre: no interface of an FE model opens
  !> or slides that far; beyond it the input is bad, e.g. a host in other units or a diverged
  !> iteration). With stiffnesses <= 1e90 MPa/mm and lengths >= 1e-90 mm (what
  !> interlock_material_prepare admits) every traction, ratio s/s_0 and energy of the update
  !> stays below 1e200: no overflow, no FP trap.
  real(dp), parameter :: separation_bound = 1.0e6_dp
  !> The exponent field of a real(dp): all ones in a NaN or an infinity.
  integer(int64), parameter :: exponent_bits = shiftl(2047_int64, 52)

contains

  !> x is finite (not NaN, not +-Inf), from its bits: iand(bits, exponent_bits) /=
  !> exponent_bits. For values from outside the library (separations, PROPS, STATEV, deck
  !> values): it compares no NaN (an ordered comparison of a NaN raises the invalid exception,
  !> a trap in hosts that run with traps on; a signalling NaN traps in any floating-point
  !> test) and needs no IEEE module (whose save and restore of the floating-point state around
  !> each procedure costs more than the test).
  elemental logical function is_finite_bits(x)
    real(dp), intent(in) :: x
    is_finite_bits = iand(transfer(x, 0_int64), exponent_bits) /= exponent_bits
  end function is_finite_bits

  !> |x| <= separation_bound, from its bits (false for a NaN or an infinity): the magnitude's
  !> bits of non-negative doubles order as their values. For separations from outside the
  !> library, as is_finite_bits.
  elemental logical function within_separation_bound(x)
    real(dp), intent(in) :: x
    within_separation_bound = ibclr(transfer(x, 0_int64), 63) <= &
                              transfer(separation_bound, 0_int64)
  end function within_separation_bound

  !> x is finite (not NaN, not +-Inf), by one comparison: for values the library computed
  !> from finite input (a traction, a sum of them), where under traps a NaN or an overflow
  !> would already have trapped where it was made. The comparison raises the invalid
  !> exception on a NaN: for input use is_finite_bits.
  elemental logical function is_finite_value(x)
    real(dp), intent(in) :: x
    is_finite_value = abs(x) <= huge(x)
  end function is_finite_value

  !> x means "+infinity" in a parameter (H_N, zeta_0): +Inf or a finite x >= infinite_threshold
  !> (FE input files cannot always hold an IEEE infinity). False for NaN and -Inf; no
  !> floating-point exception on any input.
  elemental logical function is_infinite_value(x)
    real(dp), intent(in) :: x
    if (is_finite_bits(x)) then
      is_infinite_value = x >= infinite_threshold
    else
      is_infinite_value = transfer(x, 0_int64) == exponent_bits   ! +Inf: sign 0, mantissa 0
    end if
  end function is_infinite_value

  !> x is a NaN (from its bits: the exponent all ones, a mantissa other than 0); no
  !> floating-point exception on any input.
  elemental logical function is_nan_value(x)
    real(dp), intent(in) :: x
    is_nan_value = iand(transfer(x, 0_int64), huge(0_int64)) > exponent_bits
  end function is_nan_value

  !> a == b without the compiler's warning on real equality: used where exact equality is meant
  !> (flags stored as reals, a parameter that switches an effect off exactly).
  elemental logical function same_value(a, b)
    real(dp), intent(in) :: a, b
    same_value = .not. (a < b .or. a > b)
  end function same_value

end module interlock_kinds
