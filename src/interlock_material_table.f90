!> The single source of truth for the material description (in the spirit of an MFront
!> `.mfront` file): every property (name, symbol, unit, default, admissible range, deck group,
!> one-line description) and every state variable. The UMAT's PROPS and STATEV layouts, the
!> validation messages, the names used by decks and HDF5 files, `interlock-query` and
!> `docs/material.md` are all generated from these two tables.
module interlock_material_table
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp, same_value, infinite_threshold, exponent_bits, is_finite_bits, &
      is_nan_value
  implicit none
  private
  public :: property_t, statevar_t, properties, statevars
  public :: n_properties, n_required_properties, n_statevars_per_plane, n_statevars_global
  public :: umat_planes, umat_nstatv, property_index, statevar_index
  public :: check_property, property_ok, properties_ok, format_range, format_real, format_integer
  public :: kind_real, kind_flag, kind_choice
  public :: keys_in_range, key_in_range, all_properties_ok, property_defaults
  public :: prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
            prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, &
            prop_max_dd, prop_max_dtheta, prop_effect_damage, prop_effect_friction, &
            prop_effect_interlocking, prop_effect_finite_depth, prop_effect_wear, prop_tangent, &
            tangent_exact, tangent_symmetric
  public :: sv_damage, sv_beta, sv_frictional_slip, sv_zeta, sv_theta, sv_friction_traction, &
            sv_work, sv_damage_dissipation, sv_friction_dissipation, sv_initialized

  integer, parameter :: kind_real = 1   !< a real number in a range
  integer, parameter :: kind_flag = 2   !< 0 (off / false) or 1 (on / true)
  integer, parameter :: kind_choice = 3 !< an integer code in a range

  real(dp), parameter :: big = huge(1.0_dp)

  !> One material property. Bounds are inclusive unless the matching `*_open` is set;
  !> `infinite_ok` admits +infinity (a value >= infinite_threshold or +Inf): the effect is off.
  type :: property_t
    character(len=24) :: name
    character(len=12) :: symbol
    character(len=6)  :: unit
    character(len=12) :: group
    integer  :: kind
    logical  :: required
    real(dp) :: default
    real(dp) :: lower
    logical  :: lower_open
    real(dp) :: upper
    logical  :: upper_open
    logical  :: infinite_ok
    character(len=96) :: description
  end type property_t

  !> One state variable; per-plane variables occupy one STATEV slot per microplane.
  type :: statevar_t
    character(len=24) :: name
    character(len=6)  :: unit
    logical :: per_plane
    character(len=96) :: description
  end type statevar_t

  integer, parameter :: n_properties = 20
  !> PROPS(1:n_required_properties) must be given; the rest take their defaults.
  integer, parameter :: n_required_properties = 9

  integer, parameter :: prop_sigma0_n = 1, prop_sigma0_t = 2, prop_gc = 3, prop_eta = 4, &
                        prop_mu = 5, prop_h_n = 6, prop_theta0 = 7, prop_thetaf = 8, &
                        prop_zeta0 = 9, prop_prefractured = 10, prop_scheme = 11, &
                        prop_substep_tol = 12, prop_max_dd = 13, prop_max_dtheta = 14, &
                        prop_effect_damage = 15, prop_effect_friction = 16, &
                        prop_effect_interlocking = 17, prop_effect_finite_depth = 18, &
                        prop_effect_wear = 19, prop_tangent = 20
  !> The codes of property `tangent`: the exact algorithmic tangent, or a symmetric one for
  !> hosts that keep only the symmetric part of DDSDDE (CalculiX).
  integer, parameter :: tangent_exact = 1, tangent_symmetric = 2

  type(property_t), parameter :: properties(n_properties) = [ &
    property_t('sigma0_n', 'sigma0_n', 'MPa', 'interface', kind_real, .true., 0.0_dp, &
               0.0_dp, .true., big, .false., .false., 'peak normal (mode I) traction'), &
    property_t('sigma0_t', 'sigma0_t', 'MPa', 'interface', kind_real, .true., 0.0_dp, &
               0.0_dp, .true., big, .false., .false., 'peak tangential (mode II) traction'), &
    property_t('gc', 'Gc_bar', 'N/mm', 'interface', kind_real, .true., 0.0_dp, &
               0.0_dp, .true., big, .false., .false., 'macroscopic fracture energy of the RIA'), &
    property_t('eta', 'eta', '-', 'interface', kind_real, .true., 0.0_dp, &
               0.0_dp, .true., 1.0_dp, .true., .false., &
               'ductility parameter: s_0 = (1 - eta) s_c; stiffness K = sigma0 / s_0'), &
    property_t('mu', 'mu', '-', 'interface', kind_real, .true., 0.0_dp, &
               0.0_dp, .false., 100.0_dp, .false., .false., &
               'Coulomb friction coefficient on the damaged part of each microplane'), &
    property_t('h_n', 'H_N', 'mm', 'interface', kind_real, .true., 0.0_dp, &
               0.0_dp, .true., big, .false., .true., &
               'asperity depth; >= 1e30 or Inf: infinite depth (finite-depth effect off)'), &
    property_t('theta0_deg', 'theta_0', 'deg', 'microplanes', kind_real, .true., 0.0_dp, &
               0.0_dp, .false., 90.0_dp, .true., .false., &
               'initial inclination of the inclined microplanes (RIA: -theta_0, 0, +theta_0)'), &
    property_t('thetaf_deg', 'theta_f', 'deg', 'microplanes', kind_real, .true., 0.0_dp, &
               0.0_dp, .false., 90.0_dp, .true., .false., &
               'final (fully worn) inclination, 0 <= theta_f <= theta_0'), &
    property_t('zeta0', 'zeta_0', 'N/mm', 'microplanes', kind_real, .true., 0.0_dp, &
               0.0_dp, .true., big, .false., .true., &
               'wear energy scale; >= 1e30 or Inf: no wear'), &
    property_t('prefractured', 'D_0', '-', 'interface', kind_flag, .false., 0.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               '1: interface fully debonded from the start (D = 1), 0: intact'), &
    property_t('scheme', 'scheme', '-', 'solver', kind_choice, .false., 3.0_dp, &
               1.0_dp, .false., 3.0_dp, .false., .false., &
               'integration scheme: 1 explicit (the paper''s), 2 implicit (backward Euler), ' // &
               '3 trapezoidal'), &
    property_t('substep_tol', 'tol', '-', 'solver', kind_real, .false., 0.0_dp, &
               0.0_dp, .false., 1.0_dp, .true., .false., &
               'local error tolerance of substepping; 0: no substepping'), &
    property_t('max_damage_increment', 'dD_max', '-', 'umat', kind_real, .false., 0.25_dp, &
               0.0_dp, .true., 1.0_dp, .false., .false., &
               'UMAT: largest damage increment per increment before PNEWDT < 1 is proposed'), &
    property_t('max_angle_increment_deg', 'dtheta_max', 'deg', 'umat', kind_real, .false., 1.0_dp, &
               0.0_dp, .true., 90.0_dp, .false., .false., &
               'UMAT: largest microplane rotation per increment before PNEWDT < 1 is proposed'), &
    property_t('damage', 'damage', '-', 'effects', kind_flag, .false., 1.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               'effect switch: damage (decohesion); 0: D stays at its initial value'), &
    property_t('friction', 'friction', '-', 'effects', kind_flag, .false., 1.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               'effect switch: Coulomb friction; 0: as mu = 0'), &
    property_t('interlocking', 'interlock', '-', 'effects', kind_flag, .false., 1.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               'effect switch: inclined microplanes; 0: one flat plane (Alfano-Sacco)'), &
    property_t('finite_depth', 'finite_H', '-', 'effects', kind_flag, .false., 1.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               'effect switch: finite asperity depth; 0: as H_N = infinity'), &
    property_t('wear', 'wear', '-', 'effects', kind_flag, .false., 1.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               'effect switch: asperity wear; 0: as zeta_0 = infinity (theta constant)'), &
    property_t('tangent', 'tangent', '-', 'umat', kind_choice, .false., 1.0_dp, &
               1.0_dp, .false., 2.0_dp, .false., .false., &
               'UMAT: DDSDDE 1 exact, 2 symmetric, for hosts that symmetrize (CalculiX)') ]

  !> The columns of the table that property_ok compares with, as plain arrays.
  real(dp), parameter :: lower(n_properties) = properties%lower
  real(dp), parameter :: upper(n_properties) = properties%upper
  logical, parameter :: lower_open(n_properties) = properties%lower_open
  logical, parameter :: upper_open(n_properties) = properties%upper_open
  logical, parameter :: infinite_ok(n_properties) = properties%infinite_ok
  logical, parameter :: integer_valued(n_properties) = properties%kind /= kind_real
  !> The bounds as closed ones: an open bound moved to the next representable number, and
  !> values >= infinite_threshold admitted only where infinity is admissible.
  real(dp), parameter :: lowest(n_properties) = merge(nearest(lower, 1.0_dp), lower, lower_open)
  real(dp), parameter :: highest(n_properties) = merge(huge(1.0_dp), &
    min(merge(nearest(upper, -1.0_dp), upper, upper_open), nearest(infinite_threshold, -1.0_dp)), &
    infinite_ok)

  !> The closed bounds as ordered keys (keys_in_range): lowest <= x <= highest for a finite x
  !> exactly when lowest_key <= key(x) <= highest_key, and NaN and the infinities
  !> outside unless +Inf is admissible (highest_key is then the key of +Inf), so that a whole
  !> PROPS is checked by integer comparisons (no comparison of a NaN, no branch per value).
  !> A lower bound 0 admits -0 (key -1), as the comparison -0 >= 0 does.
  integer(int64), parameter :: lowest_bits(n_properties) = transfer(lowest, 0_int64, n_properties)
  integer(int64), parameter :: highest_bits(n_properties) = transfer(highest, 0_int64, n_properties)
  integer(int64), parameter :: lowest_key(n_properties) = merge(-1_int64, &
    merge(lowest_bits, ieor(lowest_bits, huge(0_int64)), lowest_bits >= 0), lowest_bits == 0)
  integer(int64), parameter :: highest_key(n_properties) = merge(exponent_bits, &
    merge(highest_bits, ieor(highest_bits, huge(0_int64)), highest_bits >= 0), infinite_ok)
  !> The flags (0 or 1), checked by their bits in one test.
  logical, parameter :: flag_row(n_properties) = properties%kind == kind_flag
  !> The defaults as a plain array (the optional properties a short PROPS leaves out).
  real(dp), parameter :: property_defaults(n_properties) = properties%default

  integer, parameter :: n_statevars_per_plane = 6
  integer, parameter :: n_statevars_global = 4
  integer, parameter :: sv_damage = 1, sv_beta = 2, sv_frictional_slip = 3, sv_zeta = 4, &
                        sv_theta = 5, sv_friction_traction = 6, &
                        sv_work = 7, sv_damage_dissipation = 8, sv_friction_dissipation = 9, &
                        sv_initialized = 10

  type(statevar_t), parameter :: statevars(n_statevars_per_plane + n_statevars_global) = [ &
    statevar_t('damage', '-', .true., 'damage D_k in [0, 1], non-decreasing'), &
    statevar_t('beta', '-', .true., 'history maximum of the equivalent relative displacement'), &
    statevar_t('frictional_slip', 'mm', .true., 'frictional slip sf_k along the microplane'), &
    statevar_t('zeta', 'N/mm', .true., 'accumulated frictional work zeta_k (drives wear)'), &
    statevar_t('theta', 'rad', .true., 'current inclination theta_k of the microplane'), &
    statevar_t('friction_traction', 'MPa', .true., &
               'friction traction K_t (s_kt - sf_k) at the end of the increment'), &
    statevar_t('work', 'N/mm', .false., 'work done on the interface, sum of sigma . ds'), &
    statevar_t('damage_dissipation', 'N/mm', .false., 'energy dissipated by damage'), &
    statevar_t('friction_dissipation', 'N/mm', .false., 'energy dissipated by friction'), &
    statevar_t('initialized', '-', .false., '0 before the first increment, 1 after') ]

  !> The UMAT uses the paper's symmetric three-plane RIA.
  integer, parameter :: umat_planes = 3
  integer, parameter :: umat_nstatv = n_statevars_per_plane * umat_planes + n_statevars_global

contains

  !> Index of a property by name (case-sensitive, trimmed); 0 when unknown.
  pure integer function property_index(name)
    character(len=*), intent(in) :: name
    integer :: i
    property_index = 0
    do i = 1, n_properties
      if (trim(properties(i)%name) == trim(name)) then
        property_index = i
        return
      end if
    end do
  end function property_index

  !> STATEV slot of state variable `ivar` (plane `k` for per-plane variables) in the UMAT layout:
  !> per-plane variables by variable, then plane; then the global ones.
  pure integer function statevar_index(ivar, k)
    integer, intent(in) :: ivar, k
    if (ivar <= n_statevars_per_plane) then
      statevar_index = (ivar - 1) * umat_planes + k
    else
      statevar_index = n_statevars_per_plane * umat_planes + (ivar - n_statevars_per_plane)
    end if
  end function statevar_index

  !> Whether `value` is admissible for property i (rows_ok).
  pure logical function property_ok(i, value) result(ok)
    integer, intent(in) :: i
    real(dp), intent(in) :: value
    ok = rows_ok([value], i)
  end function property_ok

  !> Whether values(i) is admissible for property i, for every i (one call for a whole PROPS).
  pure logical function properties_ok(values) result(ok)
    real(dp), intent(in) :: values(:)
    ok = rows_ok(values(1:min(size(values), n_properties)), 1)
  end function properties_ok

  !> Whether values(j) is admissible for property first + j - 1, for every j: integer
  !> comparisons of the values' order keys with the table's closed bounds (lowest_key,
  !> highest_key: NaN, -Inf, and +Inf where no infinity is admissible fail; no comparison of
  !> a NaN), so that a caller that checks every call (the UMAT) builds a message only on
  !> failure; flags and choices are whole numbers (their ranges lie within [0, 2^52), where
  !> x + 2^52 - 2^52 rounds x to a whole number).
  pure logical function rows_ok(values, first) result(ok)
    real(dp), intent(in) :: values(:)
    integer, intent(in) :: first
    integer :: j, i, n
    n = size(values)
    ok = keys_in_range(n, values, lowest_key(first:first + n - 1), &
                       highest_key(first:first + n - 1))
    if (.not. ok) return
    do j = 1, size(values)
      i = first + j - 1
      if (integer_valued(i)) ok = ok .and. is_whole(values(j))
    end do
  end function rows_ok

  !> Whether every value of a PROPS (n_required_properties <= size(values) <= n_properties,
  !> checked by the caller; the optional properties the host leaves out take their defaults,
  !> admissible: test_umat_table checks them) is admissible (the UMAT's check on every call): the loop over
  !> the table unrolled, so that every bound is a constant and key_in_range keeps one test and
  !> a branch never taken on the success path (a flag by is_flag; a choice whole too).
  pure logical function all_properties_ok(values) result(ok)
    real(dp), intent(in), contiguous :: values(:)
    integer :: i
    ok = .false.
    !GCC$ unroll 20
    do i = 1, n_properties
      if (i > n_required_properties) then
        if (i > size(values)) exit
      end if
      if (flag_row(i)) then
        if (.not. is_flag(values(i))) return
      else
        if (.not. key_in_range(values(i), lowest_key(i), highest_key(i))) return
        if (integer_valued(i)) then
          if (.not. is_whole(values(i))) return
        end if
      end if
    end do
    ok = .true.
  end function all_properties_ok

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

  !> Check one value against its table row. On failure `ok` is false and `message` names the
  !> property, the value and the admissible range.
  pure subroutine check_property(i, value, ok, message)
    integer, intent(in) :: i
    real(dp), intent(in) :: value
    logical, intent(out) :: ok
    character(len=*), intent(out) :: message
    ok = property_ok(i, value)
    message = ''
    if (.not. ok) then
      message = "property '" // trim(properties(i)%name) // "' = " // trim(format_real(value)) &
                // ' is inadmissible: admissible ' // trim(format_range(i))
    end if
  end subroutine check_property

  !> The admissible range of property i as text, e.g. "0 < eta < 1".
  pure function format_range(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    type(property_t) :: p
    p = properties(i)
    select case (p%kind)
    case (kind_flag)
      text = trim(p%name) // ' = 0 or 1'
    case (kind_choice)
      text = trim(p%name) // ' an integer from ' // trim(format_real(p%lower)) // ' to ' // &
             trim(format_real(p%upper))
    case default
      text = trim(format_real(p%lower)) // trim(merge(' < ', ' <=', p%lower_open)) // ' ' // &
             trim(p%name)
      if (p%upper < huge(1.0_dp)) then
        text = text // trim(merge(' < ', ' <=', p%upper_open)) // ' ' // &
               trim(format_real(p%upper))
      else if (.not. p%infinite_ok) then
        text = text // ' < 1e30'
      end if
      if (p%infinite_ok) text = text // ' (or >= 1e30 / Inf for infinity)'
      text = text // ' [' // trim(p%unit) // ']'
    end select
  end function format_range

  !> A compact, exact-enough rendering of a real for messages and tables.
  pure function format_real(x) result(text)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    ! (from the bits first: a signalling NaN, which a host may pass, traps in any float test)
    if (.not. is_finite_bits(x)) then
      if (is_nan_value(x)) then
        text = 'NaN'
      else
        text = merge('-Inf', '+Inf', transfer(x, 0_int64) < 0_int64)
      end if
    else if (same_value(x, anint(x)) .and. abs(x) < 1.0e9_dp) then
      write (buf, '(i0)') nint(x, kind=8)
      text = trim(buf)
    else
      ! Six significant digits, trailing zeros dropped: 0.3, -0.0015, 2.5e-07, 1e+200.
      if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e6_dp) then
        write (buf, '(f0.6)') x
        buf = adjustl(buf)
        if (index(buf, '.') > 0) buf = strip_zeros(buf)
        if (buf(1:1) == '.') buf = '0' // buf(1:len(buf) - 1)
        if (buf(1:2) == '-.') buf = '-0' // buf(2:len(buf) - 1)
        if (len_trim(strip_zeros(buf)) == 0) buf = '0'
        text = trim(buf)
      else
        write (buf, '(es14.5e3)') x
        buf = adjustl(buf)
        text = trim(strip_zeros(buf(1:index(buf, 'E') - 1))) // 'e' // &
               trim(exponent_text(buf(index(buf, 'E') + 1:)))
      end if
    end if
  end function format_real

  !> An integer as text, without blanks: 42 -> "42".
  pure function format_integer(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    character(len=16) :: buf
    write (buf, '(i0)') i
    text = trim(buf)
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

  !> "+005" -> "+05" (at least two digits), "-010" -> "-10".
  pure function exponent_text(s) result(r)
    character(len=*), intent(in) :: s
    character(len=:), allocatable :: r
    integer :: i
    r = trim(adjustl(s))
    i = 2
    do while (len(r) > 3 .and. r(i:i) == '0')
      r = r(1:i - 1) // r(i + 1:)
    end do
  end function exponent_text

end module interlock_material_table
