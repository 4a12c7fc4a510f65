!> The single source of truth for the material description (in the spirit of an MFront
!> `.mfront` file): every property (name, symbol, unit, default, admissible range, deck group,
!> one-line description) and every state variable (name, unit, admissible range and how the
!> material narrows it, description). The UMAT's PROPS and STATEV layouts and checks, the
!> validation messages, the names used by decks and HDF5 files, `interlock-query`, the C API's
!> descriptions and `docs/material.md` are all generated from these two tables.
module interlock_material_table
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp, infinite_threshold, exponent_bits
  use interlock_numbers, only: keys_in_range, key_in_range, is_flag, is_whole, format_real
  implicit none
  private
  public :: property_t, statevar_t, properties, statevars
  public :: n_properties, n_required_properties, n_statevars_per_plane, n_statevars_global
  public :: umat_planes, umat_nstatv, property_index, statevar_index
  public :: n_properties_2d, prop_ria, prop_n_azimuths, ria_paper, ria_azimuthal, &
            strike_statevars, n_statevars_strike, sv_frictional_slip_strike, &
            sv_friction_traction_strike, umat_nstatv_3d, statevar_index_3d, statevar_3d, &
            n_statevars_3d
  public :: check_property, property_ok, properties_ok, format_range
  public :: kind_real, kind_flag, kind_choice
  public :: all_properties_ok, property_defaults
  public :: prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
            prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, &
            prop_max_dd, prop_max_dtheta, prop_effect_damage, prop_effect_friction, &
            prop_effect_interlocking, prop_effect_finite_depth, prop_effect_wear, prop_tangent, &
            tangent_exact, tangent_symmetric
  public :: sv_damage, sv_beta, sv_frictional_slip, sv_zeta, sv_theta, sv_friction_traction, &
            sv_work, sv_damage_dissipation, sv_friction_dissipation, sv_initialized
  public :: state_bound, bound_fixed, bound_broken, bound_broken_history, bound_plane_angle, &
            bound_flag, format_statevar_range

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

  !> Largest magnitude admitted for a state variable that is not otherwise bounded (slips,
  !> works, energies, friction tractions) and for the traction STRESS on entry: far beyond any
  !> value the law reaches from separations within separation_bound (tractions <= 1e100 MPa,
  !> works <= 1e110 N/mm for stiffnesses <= 1e90 MPa/mm), and far enough below overflow that
  !> no product of the update with such a value overflows.
  real(dp), parameter :: state_bound = 1.0e150_dp

  !> How a state variable's admissible range follows from the material, besides its row's
  !> [lower, upper]: not at all; raised to 1 on a pre-fractured interface (damage); raised to
  !> beta_break = 1/(1 - eta) on a pre-fractured interface (beta); between theta_f and theta_0
  !> of its plane, with 4 ulps of slack for the rounding of the wear law (theta; the row's
  !> bounds then only keep it finite); 0 before the first increment, 1 after (the flag).
  integer, parameter :: bound_fixed = 0, bound_broken = 1, bound_broken_history = 2, &
                        bound_plane_angle = 3, bound_flag = 4

  !> One state variable; per-plane variables occupy one STATEV slot per microplane. A value
  !> lies in [lower, upper] (a NaN in none), narrowed for the material as `bound` says.
  type :: statevar_t
    character(len=24) :: name
    character(len=6)  :: unit
    logical :: per_plane
    real(dp) :: lower
    real(dp) :: upper
    integer :: bound
    character(len=96) :: description
  end type statevar_t

  !> PROPS 1 .. n_properties_2d describe the law (any element); the ones after them select
  !> the RIA of a three-dimensional interface (SPEC section 9), which a 2D element admits
  !> only as the paper's RIA.
  integer, parameter :: n_properties_2d = 20
  integer, parameter :: n_properties = 22
  !> PROPS(1:n_required_properties) must be given; the rest take their defaults.
  integer, parameter :: n_required_properties = 9

  integer, parameter :: prop_sigma0_n = 1, prop_sigma0_t = 2, prop_gc = 3, prop_eta = 4, &
                        prop_mu = 5, prop_h_n = 6, prop_theta0 = 7, prop_thetaf = 8, &
                        prop_zeta0 = 9, prop_prefractured = 10, prop_scheme = 11, &
                        prop_substep_tol = 12, prop_max_dd = 13, prop_max_dtheta = 14, &
                        prop_effect_damage = 15, prop_effect_friction = 16, &
                        prop_effect_interlocking = 17, prop_effect_finite_depth = 18, &
                        prop_effect_wear = 19, prop_tangent = 20, prop_ria = 21, &
                        prop_n_azimuths = 22
  !> The codes of property `ria`: the paper's three planes (every azimuth 0: a 2D roughness
  !> extruded along t2), or the `azimuthal` RIA of SPEC section 9 with n_azimuths directions.
  integer, parameter :: ria_paper = 0, ria_azimuthal = 1
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
               'UMAT: DDSDDE 1 exact, 2 symmetric, for hosts that symmetrize (CalculiX)'), &
    property_t('ria', 'RIA', '-', '3d', kind_choice, .false., 0.0_dp, &
               0.0_dp, .false., 1.0_dp, .false., .false., &
               '3D element: RIA 0 paper (azimuths 0), 1 azimuthal; a 2D element admits 0 only'), &
    ! (upper bound: interlock_material's max_azimuths, which this module cannot use; umat_3d
    ! checks that they agree)
    property_t('n_azimuths', 'N_a', '-', '3d', kind_choice, .false., 3.0_dp, &
               1.0_dp, .false., 6.0_dp, .false., .false., &
               'ria = 1: dip directions pi j / N_a, j < N_a: planes 1 + 2 N_a (N_a = 1: paper)') ]

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
    statevar_t('damage', '-', .true., 0.0_dp, 1.0_dp, bound_broken, &
               'damage D_k in [0, 1], non-decreasing'), &
    statevar_t('beta', '-', .true., 0.0_dp, state_bound, bound_broken_history, &
               'history maximum of the equivalent relative displacement'), &
    statevar_t('frictional_slip', 'mm', .true., -state_bound, state_bound, bound_fixed, &
               'frictional slip sf_k along the microplane (3D: along its dip e_k at its phi_k ' // &
               'as given)'), &
    statevar_t('zeta', 'N/mm', .true., 0.0_dp, state_bound, bound_fixed, &
               'accumulated frictional work zeta_k (drives wear)'), &
    statevar_t('theta', 'rad', .true., -state_bound, state_bound, bound_plane_angle, &
               'current inclination theta_k of the microplane (signed in the frame of its ' // &
               'phi_k as given)'), &
    statevar_t('friction_traction', 'MPa', .true., -state_bound, state_bound, bound_fixed, &
               'friction traction K_t (s_kt - sf_k) at the end of the increment'), &
    statevar_t('work', 'N/mm', .false., -state_bound, state_bound, bound_fixed, &
               'work done on the interface, sum of sigma . ds'), &
    statevar_t('damage_dissipation', 'N/mm', .false., -state_bound, state_bound, bound_fixed, &
               'energy dissipated by damage'), &
    statevar_t('friction_dissipation', 'N/mm', .false., -state_bound, state_bound, bound_fixed, &
               'energy dissipated by friction'), &
    statevar_t('initialized', '-', .false., 0.0_dp, 1.0_dp, bound_flag, &
               '0 before the first increment, 1 after') ]

  !> The UMAT uses the paper's symmetric three-plane RIA.
  integer, parameter :: umat_planes = 3
  integer, parameter :: umat_nstatv = n_statevars_per_plane * umat_planes + n_statevars_global

  !> A three-dimensional point (SPEC section 9) keeps, besides the 2D state (whose
  !> frictional_slip and friction_traction are then the dip components, along e_k), the strike
  !> components of each plane (along q_k). Its STATEV: the 2D layout for its planes, then
  !> these, by variable then plane, so that the paper's RIA in 3D has the 2D STATEV 1-22
  !> unchanged and the strike components in 23-28.
  integer, parameter :: n_statevars_strike = 2
  integer, parameter :: sv_frictional_slip_strike = 11, sv_friction_traction_strike = 12
  !> The variables of a three-dimensional point.
  integer, parameter :: n_statevars_3d = n_statevars_per_plane + n_statevars_global + &
                                        n_statevars_strike
  type(statevar_t), parameter :: strike_statevars(n_statevars_strike) = [ &
    statevar_t('frictional_slip_strike', 'mm', .true., -state_bound, state_bound, bound_fixed, &
               '3D: frictional slip of plane k along its strike q_k (the frame of its phi_k ' // &
               'as given)'), &
    statevar_t('friction_traction_strike', 'MPa', .true., -state_bound, state_bound, &
               bound_fixed, '3D: friction traction of plane k along its strike q_k (the frame of its ' // &
               'phi_k as given)') ]

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

  !> The STATEV slots of a three-dimensional point with n_planes planes (SPEC section 9).
  pure integer function umat_nstatv_3d(n_planes)
    integer, intent(in) :: n_planes
    umat_nstatv_3d = (n_statevars_per_plane + n_statevars_strike) * n_planes + n_statevars_global
  end function umat_nstatv_3d

  !> STATEV slot of state variable `ivar` (1 .. sv_friction_traction_strike; plane `k` for
  !> per-plane variables) of a three-dimensional point with n_planes planes: the 2D layout for
  !> n_planes planes, then the strike components by variable, then plane.
  pure integer function statevar_index_3d(ivar, k, n_planes) result(slot)
    integer, intent(in) :: ivar, k, n_planes
    if (ivar <= n_statevars_per_plane) then
      slot = (ivar - 1) * n_planes + k
    else if (ivar <= n_statevars_per_plane + n_statevars_global) then
      slot = n_statevars_per_plane * n_planes + (ivar - n_statevars_per_plane)
    else
      slot = n_statevars_per_plane * n_planes + n_statevars_global + &
             (ivar - sv_frictional_slip_strike) * n_planes + k
    end if
  end function statevar_index_3d

  !> The row of state variable `ivar` of a three-dimensional point (statevar_index_3d).
  pure function statevar_3d(ivar) result(row)
    integer, intent(in) :: ivar
    type(statevar_t) :: row
    if (ivar <= size(statevars)) then
      row = statevars(ivar)
    else
      row = strike_statevars(ivar - size(statevars))
    end if
  end function statevar_3d

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
    !GCC$ unroll 22
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

  !> format_range's text, blank-padded (see interlock_numbers:format_real).
  pure function format_range_padded(i) result(padded)
    integer, intent(in) :: i
    character(len=160) :: padded
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
    padded = text
  end function format_range_padded

  !> The admissible range of property i as text, e.g. "0 < eta < 1".
  pure function format_range(i) result(text)
    integer, intent(in) :: i
    character(len=len_trim(format_range_padded(i))) :: text
    text = format_range_padded(i)
  end function format_range

  !> format_statevar_range's text, blank-padded (see interlock_numbers:format_real).
  pure function format_statevar_range_padded(ivar) result(padded)
    integer, intent(in) :: ivar
    character(len=160) :: padded
    character(len=:), allocatable :: text
    type(statevar_t) :: v
    v = statevar_3d(ivar)
    select case (v%bound)
    case (bound_flag)
      text = trim(v%name) // ' = 0 (before the first increment) or 1'
    case (bound_plane_angle)
      text = trim(v%name) // ' between theta_f and theta_0 of its plane'
    case default
      if (v%lower <= -state_bound .and. v%upper >= state_bound) then
        text = '|' // trim(v%name) // '| <= ' // trim(format_real(state_bound))
      else
        text = trim(format_real(v%lower)) // ' <= ' // trim(v%name) // ' <= ' // &
               trim(format_real(v%upper))
      end if
      if (v%bound == bound_broken) text = text // ' (1 when pre-fractured)'
      if (v%bound == bound_broken_history) text = text // ' (>= 1/(1 - eta) when pre-fractured)'
    end select
    padded = text // ' [' // trim(v%unit) // ']'
  end function format_statevar_range_padded

  !> The admissible range of state variable ivar (statevar_3d) as text, e.g.
  !> "0 <= damage <= 1 (1 when pre-fractured) [-]".
  pure function format_statevar_range(ivar) result(text)
    integer, intent(in) :: ivar
    character(len=len_trim(format_statevar_range_padded(ivar))) :: text
    text = format_statevar_range_padded(ivar)
  end function format_statevar_range

end module interlock_material_table
