!> The one pack/unpack between the material table's PROPS and STATEV layouts (used by the
!> UMAT) and the library's material, solver and state types.
module interlock_props
  use interlock_kinds, only: dp
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: same_value, is_finite_bits
  use interlock_numbers, only: key_in_range, format_integer, format_real
  use interlock_material_table, only: n_properties, n_required_properties, &
      check_property, all_properties_ok, property_defaults, umat_planes, umat_nstatv, statevar_t, &
      n_statevars_per_plane, prop_theta0, prop_thetaf, prop_prefractured, prop_ria, &
      prop_n_azimuths, ria_paper, statevar_index_3d, statevar_3d, strike_statevars, &
      n_statevars_3d, &
      n_statevars_global, sv_frictional_slip_strike, sv_friction_traction_strike, &
      sv_damage, sv_beta, sv_frictional_slip, sv_zeta, sv_theta, sv_friction_traction, &
      sv_work, sv_damage_dissipation, sv_friction_dissipation, sv_initialized, statevars, &
      n_statevars_strike, state_bound, bound_broken, bound_broken_history, bound_plane_angle, &
      bound_flag
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes
  use interlock_material_rows, only: umat_controls_t, material_from_rows, rows_n_azimuths
  use interlock_state, only: interlock_state_t, interlock_state_init, interlock_state_3d_t, &
      interlock_state_3d_init
  use interlock_status, only: status_bad_input
  implicit none
  private
  public :: props_to_material, props_n_to_material, statev_to_state, state_to_statev, umat_controls_t
  public :: statev_bounds, statev_bad_index, statev_message, state_bound
  public :: props_n_to_material_3d, props_n_planes_3d, statev_bad_index_3d, statev_message_3d, statev_to_state_3d, &
            state_to_statev_3d, statev_range, statev_variable, nprops_message

  ! The STATEV layout of interlock_material_table:statevar_index as constants, for the path
  ! every UMAT call takes: per-plane variable `v` of plane k in slot slot_v + k.
  integer, parameter :: slot_damage = (sv_damage - 1) * umat_planes, &
                        slot_beta = (sv_beta - 1) * umat_planes, &
                        slot_sf = (sv_frictional_slip - 1) * umat_planes, &
                        slot_zeta = (sv_zeta - 1) * umat_planes, &
                        slot_theta = (sv_theta - 1) * umat_planes, &
                        slot_tauf = (sv_friction_traction - 1) * umat_planes, &
                        slot_global = n_statevars_per_plane * umat_planes - n_statevars_per_plane, &
                        slot_work = slot_global + sv_work, &
                        slot_diss_damage = slot_global + sv_damage_dissipation, &
                        slot_diss_friction = slot_global + sv_friction_dissipation, &
                        slot_flag = slot_global + sv_initialized
  !> The 2D STATEV layout's rows of the table, slot by slot (per-plane variables by variable,
  !> then plane; then the point's): their bounds and how the material narrows them.
  real(dp), parameter :: slot_lower(umat_nstatv) = [reshape(spread( &
    statevars(1:n_statevars_per_plane)%lower, 1, umat_planes), [n_statevars_per_plane * umat_planes]), &
    statevars(n_statevars_per_plane + 1:)%lower]
  real(dp), parameter :: slot_upper(umat_nstatv) = [reshape(spread( &
    statevars(1:n_statevars_per_plane)%upper, 1, umat_planes), [n_statevars_per_plane * umat_planes]), &
    statevars(n_statevars_per_plane + 1:)%upper]
  integer, parameter :: slot_bound(umat_nstatv) = [reshape(spread( &
    statevars(1:n_statevars_per_plane)%bound, 1, umat_planes), [n_statevars_per_plane * umat_planes]), &
    statevars(n_statevars_per_plane + 1:)%bound]

  !> A three-dimensional point's variables (statevar_3d: the 2D ones, then the strike
  !> components), their fixed bounds as ordered keys and how the material narrows them, for
  !> statev_bad_index_3d's check of every call (the flag's lower bound 1, as in 2D).
  integer, parameter :: n_vars_3d = n_statevars_3d
  real(dp), parameter :: var_lower_3d(n_vars_3d) = [statevars%lower, strike_statevars%lower]
  real(dp), parameter :: var_upper_3d(n_vars_3d) = [statevars%upper, strike_statevars%upper]
  integer, parameter :: var_bound_3d(n_vars_3d) = [statevars%bound, strike_statevars%bound]
  integer(int64), parameter :: var_lo_bits(n_vars_3d) = &
    transfer(merge(1.0_dp, var_lower_3d, var_bound_3d == bound_flag), 0_int64, n_vars_3d)
  integer(int64), parameter :: var_hi_bits(n_vars_3d) = transfer(var_upper_3d, 0_int64, n_vars_3d)
  integer(int64), parameter :: var_lo_key_3d(n_vars_3d) = merge(-1_int64, &
    merge(var_lo_bits, ieor(var_lo_bits, huge(0_int64)), var_lo_bits >= 0), var_lo_bits == 0)
  integer(int64), parameter :: var_hi_key_3d(n_vars_3d) = &
    merge(var_hi_bits, ieor(var_hi_bits, huge(0_int64)), var_hi_bits >= 0)

  !> The checks a PROPS can fail (props_refusal), each with its message (props_message).
  integer, parameter :: refused_none = 0, refused_count = 1, refused_value = 2, &
                        refused_angles = 3, refused_ria_2d = 4

  !> The rows' bounds as ordered keys (interlock_material_table:key_in_range), for the check of
  !> every UMAT call: the flag 1 (statev_bad_index has taken the uninitialised STATEV before);
  !> the bounds the material narrows (pre-fractured, the angles) are compared after these, on
  !> values then known finite. A lower bound 0 admits -0 (key -1), as the comparison -0 >= 0
  !> does.
  real(dp), parameter :: statev_lo_fixed(umat_nstatv) = &
    merge(1.0_dp, slot_lower, slot_bound == bound_flag)
  integer(int64), parameter :: lo_bits(umat_nstatv) = transfer(statev_lo_fixed, 0_int64, umat_nstatv)
  integer(int64), parameter :: hi_bits(umat_nstatv) = transfer(slot_upper, 0_int64, umat_nstatv)
  integer(int64), parameter :: statev_lo_key(umat_nstatv) = merge(-1_int64, &
    merge(lo_bits, ieor(lo_bits, huge(0_int64)), lo_bits >= 0), lo_bits == 0)
  integer(int64), parameter :: statev_hi_key(umat_nstatv) = &
    merge(hi_bits, ieor(hi_bits, huge(0_int64)), hi_bits >= 0)

contains

  !> Read and validate PROPS(1:nprops) of a 2D element. Missing optional properties take their
  !> defaults. Every call of the UMAT comes here, so the success path is plain comparisons and
  !> arithmetic (no message, no formatted write, no copy of a long string): the messages are
  !> built by props_message only when a check fails. The RIA is the paper's, valid by
  !> construction. `mat` is intent(inout) only so that the caller's fresh material is not
  !> initialised a second time on every call: every field the update reads is set here.
  pure subroutine props_to_material(props, mat, solver, controls, stat, message)
    real(dp), intent(in), contiguous :: props(:)
    type(interlock_material_t), intent(inout) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(umat_controls_t), intent(out) :: controls
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    call props_n_to_material(size(props), props, mat, solver, controls, stat, message)
  end subroutine props_to_material

  !> props_to_material for the host's PROPS(NPROPS) as it comes (the UMAT's every call: no
  !> array descriptor to build).
  pure subroutine props_n_to_material(n, props, mat, solver, controls, stat, message)
    integer, intent(in) :: n
    real(dp), intent(in) :: props(n)
    type(interlock_material_t), intent(inout) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(umat_controls_t), intent(out) :: controls
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    integer :: refusal
    stat = status_bad_input
    refusal = props_refusal(n, props, .true.)
    if (refusal /= refused_none) then
      call props_message(props, refusal, message)
      return
    end if
    call material_from_rows(n, props, mat, solver, controls, stat, message)
  end subroutine props_n_to_material

  !> props_n_to_material for a three-dimensional interface (SPEC section 9): PROPS 1-20 as
  !> there, PROPS(21) `ria` and PROPS(22) `n_azimuths` the RIA. The paper's RIA is the 2D
  !> material to the bit (every azimuth 0: interlock_update_3d takes the 2D route while the
  !> point stays in the (n, t1) plane).
  pure subroutine props_n_to_material_3d(n, props, mat, solver, controls, stat, message)
    integer, intent(in) :: n
    real(dp), intent(in) :: props(n)
    type(interlock_material_t), intent(inout) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(umat_controls_t), intent(out) :: controls
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    integer :: refusal
    stat = status_bad_input
    refusal = props_refusal(n, props, .false.)
    if (refusal /= refused_none) then
      call props_message(props, refusal, message)
      return
    end if
    call material_from_rows(n, props, mat, solver, controls, stat, message)
  end subroutine props_n_to_material_3d

  !> Which check PROPS(1:n) fails (refused_*), refused_none when none: each tested on its own
  !> (the value checks by integer comparisons, no comparison of a NaN): the count, every value
  !> against its row, theta_f <= theta_0, and on a 2D element (`planar`) the paper's RIA. PROPS
  !> are checked here, where they enter; material_from_rows then maps the rows.
  pure integer function props_refusal(n, props, planar) result(refusal)
    integer, intent(in) :: n
    real(dp), intent(in) :: props(n)
    logical, intent(in) :: planar
    refusal = refused_count
    if (n < n_required_properties .or. n > n_properties) return
    refusal = refused_value
    if (.not. all_properties_ok(props)) return
    refusal = refused_angles
    if (.not. props(prop_thetaf) <= props(prop_theta0)) return
    refusal = refused_ria_2d
    ! (the RIA of a 2D element is the paper's: PROPS(21), when given, must say so)
    if (planar .and. n >= prop_ria) then
      if (props(prop_ria) > ria_paper + 0.5_dp) return
    end if
    refusal = refused_none
  end function props_refusal

  !> The number of planes of the RIA that an admissible PROPS(1:n) selects for a
  !> three-dimensional interface (props_n_to_material_3d): 3 for the paper's, 1 + 2 N_a for the
  !> azimuthal one.
  pure integer function props_n_planes_3d(n, props) result(n_planes)
    integer, intent(in) :: n
    real(dp), intent(in) :: props(n)
    real(dp) :: rows(prop_ria:prop_n_azimuths)
    rows = property_defaults(prop_ria:prop_n_azimuths)
    if (n >= prop_ria) rows(prop_ria:min(n, prop_n_azimuths)) = props(prop_ria:min(n, prop_n_azimuths))
    n_planes = 1 + 2 * rows_n_azimuths(rows(prop_ria), rows(prop_n_azimuths))
  end function props_n_planes_3d

  !> The message of a PROPS that props_refusal refused: the check it failed, in its own terms.
  pure subroutine props_message(props, refusal, message)
    real(dp), intent(in) :: props(:)
    integer, intent(in) :: refusal
    character(len=*), intent(out) :: message
    integer :: i
    logical :: ok
    select case (refusal)
    case (refused_count)
      call nprops_message(size(props), message)
    case (refused_value)
      do i = 1, size(props)
        call check_property(i, props(i), ok, message)
        if (.not. ok) then
          message = 'PROPS(' // format_integer(i) // '): ' // trim(message)
          return
        end if
      end do
    case (refused_angles)
      message = "property 'thetaf_deg' must not exceed 'theta0_deg': admissible 0 <= " // &
                'thetaf_deg <= theta0_deg'
    case default
      message = 'PROPS(' // format_integer(prop_ria) // "): property 'ria' = " // &
                format_real(props(prop_ria)) // ' is inadmissible with a 2D element ' // &
                '(NTENS = 2): admissible ria = 0 (the paper''s RIA; the azimuthal RIA needs a ' // &
                '3D element, NTENS = 3)'
    end select
  end subroutine props_message

  !> The message of a PROPS of n values (n outside the admissible count).
  pure subroutine nprops_message(n, message)
    integer, intent(in) :: n
    character(len=*), intent(out) :: message
    message = 'NPROPS = ' // format_integer(n) // ' is inadmissible: admissible ' // &
              format_integer(n_required_properties) // ' <= NPROPS <= ' // &
              format_integer(n_properties) // ' (see interlock-query --props)'
  end subroutine nprops_message

  !> The admissible range of STATEV(1:size(lo)) for material `mat` in the layout of its
  !> planes (statevar_index_3d; the 2D layout for the paper's three planes), the strike
  !> components included where size(lo) covers them: each slot's row (statevar_range).
  pure subroutine statev_bounds(mat, lo, hi)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(out) :: lo(:), hi(:)
    integer :: ivar, k, n, n_vars, slot
    n = mat%n_planes
    n_vars = n_statevars_per_plane + n_statevars_global
    if (size(lo) > n_statevars_per_plane * n + n_statevars_global) n_vars = n_vars + n_statevars_strike
    do ivar = 1, n_vars
      if (ivar <= n_statevars_per_plane .or. ivar > n_statevars_per_plane + n_statevars_global) then
        do k = 1, n
          slot = statevar_index_3d(ivar, k, n)
          call statev_range(mat, ivar, k, lo(slot), hi(slot))
        end do
      else
        slot = statevar_index_3d(ivar, 0, n)
        call statev_range(mat, ivar, 0, lo(slot), hi(slot))
      end if
    end do
  end subroutine statev_bounds

  !> The admissible range of state variable ivar (statevar_3d) of plane k (0: of the point)
  !> for material `mat`: its row's [lower, upper] narrowed as its `bound` says.
  pure subroutine statev_range(mat, ivar, k, lo, hi)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: ivar, k
    real(dp), intent(out) :: lo, hi
    type(statevar_t) :: row
    row = statevar_3d(ivar)
    lo = row%lower
    hi = row%upper
    select case (row%bound)
    case (bound_broken)
      if (mat%prefractured) lo = 1.0_dp
    case (bound_broken_history)
      if (mat%prefractured) lo = mat%beta_break
    case (bound_plane_angle)
      call angle_range(mat, k, lo, hi)
    end select
  end subroutine statev_range

  !> The range of the angle of plane k: between theta_f and theta_0, with 4 ulps of slack.
  pure subroutine angle_range(mat, k, lo, hi)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(out) :: lo, hi
    real(dp) :: slack
    slack = 4.0_dp * epsilon(1.0_dp) * abs(mat%theta_init(k))
    lo = min(mat%theta_init(k), mat%thetaf_eff(k)) - slack
    hi = max(mat%theta_init(k), mat%thetaf_eff(k)) + slack
  end subroutine angle_range

  !> The first STATEV slot outside its range (statev_bounds), 0 when every one is admissible.
  !> An uninitialised STATEV (flag 0, as FE codes start) is admissible whatever its other slots.
  pure integer function statev_bad_index(statev, mat) result(bad)
    real(dp), intent(in) :: statev(umat_nstatv)
    type(interlock_material_t), intent(in) :: mat
    real(dp) :: lo(umat_nstatv), hi(umat_nstatv), theta_lo, theta_hi
    integer :: i
    logical :: ok
    bad = 0
    if (.not. is_finite_bits(statev(slot_flag))) then
      bad = slot_flag
      return
    end if
    if (statev(slot_flag) < 0.5_dp) then
      if (.not. same_value(statev(slot_flag), 0.0_dp)) bad = slot_flag
      return
    end if
    ! The common case in straight comparisons: every slot within its fixed range by integer
    ! comparisons of the bits (no comparison of a NaN), then the bounds that depend on the
    ! material on the values now known finite.
    ! (the loop unrolled: every bound a constant, one test and one branch per slot, see
    ! key_in_range)
    ok = .true.
    !GCC$ unroll 22
    do i = 1, umat_nstatv
      if (.not. key_in_range(statev(i), statev_lo_key(i), statev_hi_key(i))) then
        ok = .false.
        exit
      end if
    end do
    ! The bounds the material narrows, as the rows say (unrolled: slot_bound a constant per
    ! slot, so that only the slots with such a bound are compared; plane k of a per-plane slot
    ! i <= n_statevars_per_plane * umat_planes is mod(i - 1, umat_planes) + 1).
    if (ok) then
      !GCC$ unroll 22
      do i = 1, umat_nstatv
        select case (slot_bound(i))
        case (bound_broken)
          if (mat%prefractured) ok = ok .and. statev(i) >= 1.0_dp
        case (bound_broken_history)
          if (mat%prefractured) ok = ok .and. statev(i) >= mat%beta_break
        case (bound_plane_angle)
          call angle_range(mat, mod(i - 1, umat_planes) + 1, theta_lo, theta_hi)
          ok = ok .and. statev(i) >= theta_lo .and. statev(i) <= theta_hi
        end select
      end do
      if (ok) return
    end if
    ! Which one: the first slot outside its range.
    call statev_bounds(mat, lo, hi)
    lo(slot_flag) = 1.0_dp
    bad = first_out_of_range(statev, lo, hi)
  end function statev_bad_index

  !> The first i with values(i) not finite or outside [lo(i), hi(i)], 0 when none (each value
  !> tested on its bits before it is compared: no comparison of a NaN).
  pure integer function first_out_of_range(values, lo, hi) result(bad)
    real(dp), intent(in) :: values(:), lo(:), hi(:)
    integer :: i
    bad = 0
    do i = 1, size(values)
      if (.not. is_finite_bits(values(i))) then
        bad = i
        return
      else if (.not. (values(i) >= lo(i) .and. values(i) <= hi(i))) then
        bad = i
        return
      end if
    end do
  end function first_out_of_range

  !> The message for STATEV(i) outside its range: index, name, plane, value, range.
  pure subroutine statev_message(statev, i, mat, message)
    real(dp), intent(in) :: statev(umat_nstatv)
    integer, intent(in) :: i
    type(interlock_material_t), intent(in) :: mat
    character(len=*), intent(out) :: message
    call slot_message(i, statev(i), umat_planes, mat, message)
  end subroutine statev_message

  !> The message for STATEV(i) = x of a point with n_planes planes (statev_variable) outside
  !> its range (statev_range).
  pure subroutine slot_message(i, x, n_planes, mat, message)
    integer, intent(in) :: i, n_planes
    real(dp), intent(in) :: x
    type(interlock_material_t), intent(in) :: mat
    character(len=*), intent(out) :: message
    character(len=:), allocatable :: name
    type(statevar_t) :: row
    real(dp) :: lo, hi
    integer :: ivar, k
    call statev_variable(i, n_planes, ivar, k)
    call statev_range(mat, ivar, k, lo, hi)
    row = statevar_3d(ivar)
    name = trim(row%name)
    if (k > 0) name = name // ' of plane ' // format_integer(k)
    if (row%bound == bound_flag) then
      message = 'STATEV(' // format_integer(i) // ') = ' // format_real(x) // ' (' // &
                name // ') is inadmissible: admissible 0 (first increment) or 1'
    else
      message = 'STATEV(' // format_integer(i) // ') = ' // format_real(x) // ' (' // &
                name // ') is inadmissible: admissible ' // format_real(lo) // ' <= ' // &
                trim(row%name) // ' <= ' // format_real(hi) // ' [' // &
                trim(row%unit) // ']'
      if (mat%prefractured .and. (row%bound == bound_broken .or. &
                                  row%bound == bound_broken_history)) message = trim(message) &
        // ' (pre-fractured: PROPS(' // format_integer(prop_prefractured) // ') = 1)'
    end if
  end subroutine slot_message

  !> STATEV -> state; an uninitialised STATEV (all zero, as FE codes start) gives the virgin
  !> state of the material. `state` is intent(inout) only so that the caller's fresh state is
  !> not initialised a second time on every call: every per-plane field and the energies are
  !> set here (the caller sets s and sigma).
  pure subroutine statev_to_state(statev, mat, state)
    real(dp), intent(in) :: statev(umat_nstatv)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(inout) :: state
    if (statev(slot_flag) < 0.5_dp) then
      call interlock_state_init(mat, state)
      return
    end if
    state%damage(1:umat_planes) = statev(slot_damage + 1:slot_damage + umat_planes)
    state%beta(1:umat_planes) = statev(slot_beta + 1:slot_beta + umat_planes)
    state%sf(1:umat_planes) = statev(slot_sf + 1:slot_sf + umat_planes)
    state%zeta(1:umat_planes) = statev(slot_zeta + 1:slot_zeta + umat_planes)
    state%theta(1:umat_planes) = statev(slot_theta + 1:slot_theta + umat_planes)
    state%tauf(1:umat_planes) = statev(slot_tauf + 1:slot_tauf + umat_planes)
    state%work = statev(slot_work)
    state%diss_damage = statev(slot_diss_damage)
    state%diss_friction = statev(slot_diss_friction)
    state%stored = 0.0_dp
  end subroutine statev_to_state

  pure subroutine state_to_statev(state, statev)
    type(interlock_state_t), intent(in) :: state
    real(dp), intent(inout) :: statev(umat_nstatv)
    statev(slot_damage + 1:slot_damage + umat_planes) = state%damage(1:umat_planes)
    statev(slot_beta + 1:slot_beta + umat_planes) = state%beta(1:umat_planes)
    statev(slot_sf + 1:slot_sf + umat_planes) = state%sf(1:umat_planes)
    statev(slot_zeta + 1:slot_zeta + umat_planes) = state%zeta(1:umat_planes)
    statev(slot_theta + 1:slot_theta + umat_planes) = state%theta(1:umat_planes)
    statev(slot_tauf + 1:slot_tauf + umat_planes) = state%tauf(1:umat_planes)
    statev(slot_work) = state%work
    statev(slot_diss_damage) = state%diss_damage
    statev(slot_diss_friction) = state%diss_friction
    statev(slot_flag) = 1.0_dp
  end subroutine state_to_statev

  ! --- A three-dimensional point (SPEC section 9): STATEV as statevar_index_3d lays it out
  ! for the material's planes, umat_nstatv_3d(mat%n_planes) slots: loops over the planes from
  ! each variable's base slot (slot_base), on the 3D UMAT's every call.

  !> The first STATEV slot of a three-dimensional point outside its range, 0 when every one
  !> is admissible (an uninitialised STATEV, flag 0, whatever its other slots); every value
  !> tested on its bits before it is compared (no comparison of a NaN). The common case, on
  !> every call, as statev_bad_index's: each variable's slots (contiguous in the layout of
  !> statevar_index_3d) against its fixed range by integer comparisons of the bits, in a loop
  !> unrolled over the variables, then the bounds the material narrows on values then known
  !> finite; which slot fails is found only when one does.
  pure integer function statev_bad_index_3d(statev, mat) result(bad)
    real(dp), intent(in) :: statev(:)
    type(interlock_material_t), intent(in) :: mat
    real(dp) :: theta_lo, theta_hi
    integer :: flag, n, n_vars, ivar, first, last, slot, k
    logical :: ok
    bad = 0
    n = mat%n_planes
    flag = statevar_index_3d(sv_initialized, 0, n)
    if (.not. is_finite_bits(statev(flag))) then
      bad = flag
      return
    end if
    if (statev(flag) < 0.5_dp) then
      if (.not. same_value(statev(flag), 0.0_dp)) bad = flag
      return
    end if
    n_vars = n_statevars_per_plane + n_statevars_global
    if (size(statev) > n_statevars_per_plane * n + n_statevars_global) n_vars = n_vars_3d
    ok = .true.
    !GCC$ unroll 12
    do ivar = 1, n_vars_3d
      if (ivar > n_vars) exit
      first = slot_base(ivar, n)
      last = first
      ! (a variable of every plane: its planes' slots follow its base)
      if (ivar <= n_statevars_per_plane .or. ivar > n_statevars_per_plane + n_statevars_global) then
        first = first + 1
        last = last + n
      end if
      do slot = first, last
        ok = ok .and. key_in_range(statev(slot), var_lo_key_3d(ivar), var_hi_key_3d(ivar))
      end do
    end do
    if (ok) then
      do k = 1, n
        if (mat%prefractured) then
          ok = ok .and. statev(slot_base(sv_damage, n) + k) >= 1.0_dp .and. &
               statev(slot_base(sv_beta, n) + k) >= mat%beta_break
        end if
        call angle_range(mat, k, theta_lo, theta_hi)
        slot = slot_base(sv_theta, n) + k
        ok = ok .and. statev(slot) >= theta_lo .and. statev(slot) <= theta_hi
      end do
      if (ok) return
    end if
    bad = first_bad_slot_3d(statev, mat)
  end function statev_bad_index_3d

  !> statev_bad_index_3d's slot when one fails: the first outside its range (statev_bounds;
  !> the bounds on the stack, in arrays of a fixed length beyond the largest RIA's STATEV:
  !> nothing allocated).
  pure integer function first_bad_slot_3d(statev, mat) result(bad)
    real(dp), intent(in) :: statev(:)
    type(interlock_material_t), intent(in) :: mat
    real(dp) :: lo(n_vars_3d * max_planes), hi(n_vars_3d * max_planes)
    integer :: n
    n = min(size(statev), size(lo))
    call statev_bounds(mat, lo(1:n), hi(1:n))
    lo(statevar_index_3d(sv_initialized, 0, mat%n_planes)) = 1.0_dp
    bad = first_out_of_range(statev, lo(1:n), hi(1:n))
  end function first_bad_slot_3d

  !> The message for STATEV(i) of a three-dimensional point outside its range.
  pure subroutine statev_message_3d(statev, i, mat, message)
    real(dp), intent(in) :: statev(:)
    integer, intent(in) :: i
    type(interlock_material_t), intent(in) :: mat
    character(len=*), intent(out) :: message
    call slot_message(i, statev(i), mat%n_planes, mat, message)
  end subroutine statev_message_3d

  !> The state variable (ivar, statevar_3d) and plane (k; 0 for a variable of the point) of
  !> STATEV(i) of a point with n_planes planes (statevar_index_3d's layout; for the 2D
  !> element's three planes the 2D layout, statevar_index).
  pure subroutine statev_variable(i, n_planes, ivar, k)
    integer, intent(in) :: i, n_planes
    integer, intent(out) :: ivar, k
    integer :: n
    n = n_planes
    if (i <= n_statevars_per_plane * n) then
      ivar = (i - 1) / n + 1
      k = i - (ivar - 1) * n
    else if (i <= n_statevars_per_plane * n + n_statevars_global) then
      ivar = n_statevars_per_plane + i - n_statevars_per_plane * n
      k = 0
    else
      ivar = sv_frictional_slip_strike + (i - n_statevars_per_plane * n - n_statevars_global - 1) / n
      k = i - statevar_index_3d(ivar, 0, n)
    end if
  end subroutine statev_variable

  !> STATEV -> the state of a three-dimensional point (statev_to_state's conventions).
  pure subroutine statev_to_state_3d(statev, mat, state)
    real(dp), intent(in) :: statev(:)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_3d_t), intent(inout) :: state
    integer :: n, k
    n = mat%n_planes
    if (statev(slot_base(sv_initialized, n)) < 0.5_dp) then
      call interlock_state_3d_init(mat, state)
      return
    end if
    ! (slot by slot, plane k's slot of a variable its base + k: an array section of a run-time
    ! length, or a loop gfortran turns into one, is a call of memcpy for three values;
    ! src/CMakeLists.txt)
    do k = 1, n
      state%damage(k) = statev(slot_base(sv_damage, n) + k)
      state%beta(k) = statev(slot_base(sv_beta, n) + k)
      state%sf(k) = statev(slot_base(sv_frictional_slip, n) + k)
      state%zeta(k) = statev(slot_base(sv_zeta, n) + k)
      state%theta(k) = statev(slot_base(sv_theta, n) + k)
      state%tauf(k) = statev(slot_base(sv_friction_traction, n) + k)
      state%sf_strike(k) = statev(slot_base(sv_frictional_slip_strike, n) + k)
      state%tauf_strike(k) = statev(slot_base(sv_friction_traction_strike, n) + k)
    end do
    state%work = statev(slot_base(sv_work, n))
    state%diss_damage = statev(slot_base(sv_damage_dissipation, n))
    state%diss_friction = statev(slot_base(sv_friction_dissipation, n))
    state%stored = 0.0_dp
  end subroutine statev_to_state_3d

  !> Variable ivar's (statevar_3d) slot of a point with n planes, or the slot its planes'
  !> slots follow (plane k's is this + k: statevar_index_3d's layout, by variable then plane).
  pure integer function slot_base(ivar, n)
    integer, intent(in) :: ivar, n
    slot_base = statevar_index_3d(ivar, 0, n)
  end function slot_base

  !> The state of a three-dimensional point with n_planes planes -> STATEV.
  pure subroutine state_to_statev_3d(state, n_planes, statev)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: n_planes
    real(dp), intent(inout) :: statev(:)
    integer :: n, k
    n = n_planes
    do k = 1, n
      statev(slot_base(sv_damage, n) + k) = state%damage(k)
      statev(slot_base(sv_beta, n) + k) = state%beta(k)
      statev(slot_base(sv_frictional_slip, n) + k) = state%sf(k)
      statev(slot_base(sv_zeta, n) + k) = state%zeta(k)
      statev(slot_base(sv_theta, n) + k) = state%theta(k)
      statev(slot_base(sv_friction_traction, n) + k) = state%tauf(k)
      statev(slot_base(sv_frictional_slip_strike, n) + k) = state%sf_strike(k)
      statev(slot_base(sv_friction_traction_strike, n) + k) = state%tauf_strike(k)
    end do
    statev(slot_base(sv_work, n)) = state%work
    statev(slot_base(sv_damage_dissipation, n)) = state%diss_damage
    statev(slot_base(sv_friction_dissipation, n)) = state%diss_friction
    statev(slot_base(sv_initialized, n)) = 1.0_dp
  end subroutine state_to_statev_3d

end module interlock_props
