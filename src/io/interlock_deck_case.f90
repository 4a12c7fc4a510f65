!> The cases of a deck: the rows of each case (the swept value applied), its material, solver
!> and initial state (the material through interlock_material_rows, the one mapping of the
!> table's rows), its loading path (interlock_path's points for a swept path direction), and
!> the RIA it names in the history file.
submodule (interlock_deck) interlock_deck_case
  implicit none

contains

  !> The material, solver and initial state of case `icase` (the sweep value applied).
  module procedure deck_case
    real(dp) :: values(n_properties), v
    logical :: varied(n_properties)
    type(umat_controls_t) :: controls
    integer :: ip, n
    character(len=256) :: why, derived

    stat = status_bad_input
    label = ''
    ip = deck%sweep_property
    call case_values(deck, icase, values, varied)
    if (ip > 0) then
      v = deck%sweep_values(icase)
      label = trim(deck%sweep_parameter) // ' = ' // short_real(v)
      if (trim(properties(ip)%unit) /= '-') label = label // ' ' // trim(properties(ip)%unit)
    else if (ip == sweep_slip_angle) then
      label = 'angle_deg = ' // short_real(deck%sweep_values(icase)) // ' deg'
    end if
    ! A swept angle takes each plane's sign (the paper's RIA: -theta, 0, +theta): say what is
    ! wrong in the deck's terms (the swept magnitude against each plane's), not with the signed
    ! angle of a plane.
    if (ip == prop_theta0 .and. deck%thetaf_given .or. ip == prop_thetaf) then
      do n = 1, merge(1, deck%n_planes, deck%paper_ria)
        if (case_angle(prop_thetaf, n) <= case_angle(prop_theta0, n)) cycle
        if (ip == prop_thetaf) then
          why = 'thetaf_deg = ' // short_real(v) // ' deg is inadmissible for plane ' // &
                format_integer(n) // ' (theta0_deg = ' // short_real(deck_angle(prop_theta0, n)) // &
                '): admissible 0 <= thetaf_deg <= ' // short_real(abs(deck_angle(prop_theta0, n))) // &
                ' deg (the swept angle takes the sign of each plane''s theta0_deg)'
        else
          why = 'theta0_deg = ' // short_real(v) // ' deg is inadmissible for plane ' // &
                format_integer(n) // ' (thetaf_deg = ' // short_real(deck_angle(prop_thetaf, n)) // &
                '): admissible theta0_deg >= ' // short_real(abs(deck_angle(prop_thetaf, n))) // &
                ' deg (the swept angle takes the sign of each plane''s theta0_deg)'
        end if
        message = deck%path // ': ' // trim(case_text(deck, icase)) // ' ' // trim(why)
        stat = status_bad_input
        return
      end do
    end if

    derived = ''
    if (deck%paper_ria) then
      call material_from_rows(n_properties, values, mat, solver, controls, stat, derived, varied)
    else
      n = deck%n_planes
      ! (deck%phi_deg is 0 where the deck gives no azimuths)
      call material_from_rows(n_properties, values, mat, solver, controls, stat, derived, &
                              varied, deck%gamma_hat(1:n), deck%theta0_deg(1:n), &
                              deck%thetaf_deg(1:n), deck%zeta0(1:n), deck%phi_deg(1:n))
    end if
    if (stat /= status_ok) then
      ! (the deck's own words for the derived scales, where they are the reason)
      why = inverse_check(mat, .not. deck%paper_ria)
      if (len_trim(why) == 0) why = scale_check(mat)
      if (len_trim(why) == 0) why = derived
      if (deck%sweep_property /= 0) then
        message = deck%path // ': ' // trim(case_text(deck, icase)) // ' ' // trim(why)
      else if (index(why, 'gamma') == 1 .or. index(why, 'theta') == 1 .or. &
               index(why, 'plane') == 1 .or. index(why, 'n_planes') == 1 .or. &
               index(why, 'zeta0') == 1) then
        message = deck%path // ': &microplanes: ' // trim(why)
      else
        message = deck%path // ': &interface: ' // trim(why)
      end if
      stat = status_bad_input
      return
    end if

    call interlock_state_3d_init(mat, state)
    n = mat%n_planes
    if (deck%has_initial_state) then
      call apply_initial(deck%init_damage, state%damage, 'damage', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_beta, state%beta, 'beta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_sf, state%sf, 'frictional_slip', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_zeta, state%zeta, 'zeta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_theta, state%theta, 'theta', why)
      if (len_trim(why) == 0) call check_angles(why)
      if (len_trim(why) == 0) call apply_initial(deck%init_tauf, state%tauf, 'friction_traction', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_sf_strike, state%sf_strike, &
                                                 'sf_strike', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_tauf_strike, state%tauf_strike, &
                                                 'tauf_strike', why)
      if (len_trim(why) == 0 .and. .not. mat%use_friction) call no_friction_traction(why)
      if (len_trim(why) > 0) then
        message = deck%path // ': &initial_state: ' // trim(case_text(deck, icase)) // trim(why)
        stat = status_bad_input
        return
      end if
      if (.not. same_value(deck%init_s(1), unset)) state%s = deck%init_s(1:2)
      if (.not. same_value(deck%init_s(3), unset)) state%s_t2 = deck%init_s(3)
      if (.not. same_value(deck%init_sigma(1), unset)) state%sigma = deck%init_sigma(1:2)
      if (.not. same_value(deck%init_sigma(3), unset)) state%sigma_t2 = deck%init_sigma(3)
    end if
    stat = status_ok
    message = ''

  contains

    !> The magnitude of angle row `row` (theta0_deg or thetaf_deg) of plane k in this case: the
    !> case's row where it is the paper's RIA or the row is varied, else the plane's.
    real(dp) function case_angle(row, k)
      integer, intent(in) :: row, k
      if (deck%paper_ria .or. varied(row)) then
        case_angle = abs(values(row))
      else
        case_angle = abs(deck_angle(row, k))
      end if
    end function case_angle

    !> The deck's angle row `row` of plane k, signed as given.
    real(dp) function deck_angle(row, k)
      integer, intent(in) :: row, k
      if (deck%paper_ria) then
        deck_angle = deck%rows(row)
      else if (row == prop_theta0) then
        deck_angle = deck%theta0_deg(k)
      else
        deck_angle = deck%thetaf_deg(k)
      end if
    end function deck_angle

    subroutine apply_initial(given, field, name, why)
      real(dp), intent(in) :: given(:)
      real(dp), intent(inout) :: field(:)
      character(len=*), intent(in) :: name
      character(len=*), intent(out) :: why
      integer :: m
      why = ''
      m = count_given(given)
      if (m == 0) return
      if (m /= n) then
        why = name // ' has ' // format_integer(m) // ' values: give one per microplane (' // &
              format_integer(n) // ')'
        return
      end if
      field(1:n) = given(1:n)
    end subroutine apply_initial

    !> Each plane's angle lies between its theta_f and theta_0 (the range the UMAT admits for
    !> the same state, with its slack of 4 ulps of theta_0): the wear law only turns the angle
    !> from theta_0 towards theta_f.
    subroutine check_angles(why)
      character(len=*), intent(out) :: why
      real(dp) :: slack, lo, hi
      integer :: k
      why = ''
      do k = 1, n
        slack = 4.0_dp * epsilon(1.0_dp) * abs(mat%theta_init(k))
        lo = min(mat%theta_init(k), mat%thetaf_eff(k)) - slack
        hi = max(mat%theta_init(k), mat%thetaf_eff(k)) + slack
        if (state%theta(k) >= lo .and. state%theta(k) <= hi) cycle
        why = 'theta(' // format_integer(k) // ') = ' // value_str(state%theta(k)) // &
              ' rad is inadmissible: admissible between thetaf and theta0 of plane ' // &
              format_integer(k) // ', ' // degrees(mat%thetaf_eff(k)) // ' and ' // &
              degrees(mat%theta_init(k)) // ' deg (in rad: ' // value_str(mat%thetaf_eff(k)) // &
              ' and ' // value_str(mat%theta_init(k)) // ')'
        return
      end do
    end subroutine check_angles

    !> An angle of the deck, given in degrees and kept in radians, back in degrees for a
    !> message (to 1e-9 deg: the round trip's last bits are not the deck's).
    function degrees(angle) result(text)
      real(dp), intent(in) :: angle
      character(len=:), allocatable :: text
      text = short_real(anint(angle / deg_to_rad * 1.0e9_dp) / 1.0e9_dp)
    end function degrees

    !> Without friction (mu = 0, or the effect off) an admissible state carries no friction
    !> traction, along the dip or the strike (|tau_f| <= mu p = 0); the laws rely on it.
    subroutine no_friction_traction(why)
      character(len=*), intent(out) :: why
      call first_nonzero('friction_traction', state%tauf(1:n), why)
      if (len_trim(why) == 0) call first_nonzero('tauf_strike', state%tauf_strike(1:n), why)
    end subroutine no_friction_traction

    subroutine first_nonzero(name, tauf, why)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: tauf(:)
      character(len=*), intent(out) :: why
      integer :: k
      why = ''
      do k = 1, size(tauf)
        if (abs(tauf(k)) > 0.0_dp) then
          why = name // '(' // format_integer(k) // ') = ' // format_real(tauf(k)) // &
                ' is inadmissible: without friction (mu = 0 or friction switched off) ' // &
                'admissible ' // name // ' = 0'
          return
        end if
      end do
    end subroutine first_nonzero

  end procedure deck_case

  !> The loading path of case `icase`: the points' values (deck%n_components per point) and the
  !> arcs of its segments (a 3D path; not allocated otherwise). A sweep over the path's direction
  !> (angle_deg) turns the path; otherwise the deck's path.
  module procedure deck_loading
    real(dp), allocatable :: times(:)
    if (deck%sweep_property == sweep_slip_angle) then
      call path_points(deck%path_kind, deck%sweep_values(icase), deck%path_size, deck%path_turns, &
                       deck%path_normal, times, values, arcs)
    else
      values = deck%values
      if (allocated(deck%arcs)) arcs = deck%arcs
    end if
  end procedure deck_loading

  !> The kind of the RIA of case `icase` (SPEC section 9): 'paper', 'azimuthal' or 'general'.
  module procedure deck_ria_name
    if (.not. deck%paper_ria) then
      name = 'general'
    else if (case_n_azimuths(deck, icase) > 0) then
      name = 'azimuthal'
    else
      name = 'paper'
    end if
  end procedure deck_ria_name

  !> The azimuths of the azimuthal RIA of case `icase` (0: not the azimuthal RIA): its rows
  !> `ria` and `n_azimuths`, swept or the deck's (a sweep over n_azimuths is one over the
  !> azimuthal RIA: read_sweep sets `ria`).
  module procedure case_n_azimuths
    real(dp) :: values(n_properties)
    logical :: varied(n_properties)
    call case_values(deck, icase, values, varied)
    n_azimuths = 0
    if (nint(values(prop_ria)) /= ria_paper) n_azimuths = nint(values(prop_n_azimuths))
  end procedure case_n_azimuths

  !> The rows of case `icase`: the deck's, the swept one set (and varied); thetaf_deg not
  !> given and not varied follows theta0_deg (no wear).
  pure subroutine case_values(deck, icase, values, varied)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    real(dp), intent(out) :: values(n_properties)
    logical, intent(out) :: varied(n_properties)
    values = deck%rows
    varied = deck%varied
    if (deck%sweep_property > 0) then
      values(deck%sweep_property) = deck%sweep_values(icase)
      varied(deck%sweep_property) = .true.
    end if
    if (.not. deck%thetaf_given .and. .not. varied(prop_thetaf)) then
      values(prop_thetaf) = values(prop_theta0)
      varied(prop_thetaf) = varied(prop_theta0)
    end if
  end subroutine case_values

  !> Set row `ip` of the material table (a property a sweep or a fit may vary) of the deck `d`
  !> to `v` (interlock_material_rows maps it to the material; over a general RIA an angle is a
  !> magnitude that takes each plane's sign).
  module procedure deck_set_property
    d%rows(ip) = v
    d%varied(ip) = .true.
  end procedure deck_set_property

  !> The integration scheme of the deck (row `scheme`).
  module procedure deck_scheme
    deck_scheme = nint(d%rows(prop_scheme))
  end procedure deck_scheme

  !> The deck's value of row `ip` as deck_set_property sets it (over a general RIA an angle
  !> and zeta0: plane 1's magnitude; thetaf_deg not given: theta0_deg, no wear); a row the
  !> deck does not give: the table's default.
  module procedure deck_property
    v = d%rows(ip)
  end procedure deck_property

  !> "case 3 (h_n = 0.5 mm): " for sweeps, '' otherwise.
  function case_text(deck, icase) result(text)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    character(len=:), allocatable :: text
    text = ''
    if (deck%sweep_property /= 0) text = '&sweep case ' // format_integer(icase) // ' (' // &
      trim(deck%sweep_parameter) // ' = ' // value_str(deck%sweep_values(icase)) // '): '
  end function case_text

  !> '' if eta, h_n and each plane's zeta0 are at least 1e-100, the bound below which the
  !> library's interlock_material_prepare refuses them (the law takes their inverses), else why
  !> not, naming the one that is not (so that the message is given under its own group;
  !> `per_plane`: the deck gives zeta0 per plane).
  function inverse_check(mat, per_plane) result(why)
    type(interlock_material_t), intent(in) :: mat
    logical, intent(in) :: per_plane
    character(len=256) :: why
    real(dp), parameter :: smallest_inverted = 1.0e-100_dp
    integer :: k
    why = ''
    if (mat%eta < smallest_inverted) why = 'eta = ' // value_str(mat%eta) // &
      ' is inadmissible: admissible eta >= 1e-100 (the law takes its inverse)'
    if (mat%h_n < smallest_inverted) why = 'h_n = ' // value_str(mat%h_n) // &
      ' is inadmissible: admissible h_n >= 1e-100 mm (the law takes its inverse)'
    if (len_trim(why) > 0) return
    do k = 1, mat%n_planes
      if (mat%zeta0(k) >= smallest_inverted) cycle
      why = 'zeta0 = ' // value_str(mat%zeta0(k)) // ' is inadmissible'
      if (per_plane) why = 'zeta0(' // format_integer(k) // ') = ' // value_str(mat%zeta0(k)) // &
                           ' is inadmissible'
      why = trim(why) // ': admissible zeta0 >= 1e-100 N/mm (the law takes its inverse)'
      return
    end do
  end function inverse_check

  !> '' if the derived scales of the material are representable, else why not: the opening
  !> lengths s_c = 2 Gc / sigma0, s_0 = (1 - eta) s_c [mm] and the stiffnesses K = sigma0 / s_0
  !> [MPa/mm] must lie in [2^-300, 2^300] (about 4.9e-91 .. 2.0e90), the range the library's
  !> interlock_material_prepare admits (computed in logarithms, so nothing overflows here; the
  !> message says it in the deck's terms, per component).
  function scale_check(mat) result(why)
    type(interlock_material_t), intent(in) :: mat
    character(len=256) :: why
    real(dp), parameter :: lim = 300.0_dp * log(2.0_dp)
    real(dp) :: ln_sc, ln_s0, ln_k
    integer :: i
    real(dp) :: sigma0
    character(len=1) :: c
    why = ''
    do i = 1, 2
      sigma0 = merge(mat%sigma0_n, mat%sigma0_t, i == 1)
      c = merge('n', 't', i == 1)
      ln_sc = log(2.0_dp) + log(mat%gc) - log(sigma0)
      ln_s0 = log(1.0_dp - mat%eta) + ln_sc
      ln_k = log(sigma0) - ln_s0
      if (abs(ln_sc) > lim .or. abs(ln_s0) > lim .or. abs(ln_k) > lim) then
        why = 'sigma0_' // c // ' = ' // value_str(sigma0) // ', gc = ' // value_str(mat%gc) // &
              ' and eta = ' // value_str(mat%eta) // ' give s_0' // c // ' = 10^' // &
              short_real(anint(ln_s0 / log(10.0_dp))) // ' mm and K_' // c // ' = 10^' // &
              short_real(anint(ln_k / log(10.0_dp))) // ' MPa/mm: admissible 2^-300 <= s_c' // &
              c // ', s_0' // c // ' <= 2^300 mm and 2^-300 <= K_' // c // ' <= 2^300 MPa/mm ' // &
              '(2^300 = 2.04e90)'
        return
      end if
    end do
  end function scale_check

end submodule interlock_deck_case
