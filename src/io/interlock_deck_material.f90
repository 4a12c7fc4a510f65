!> The material groups of a deck: &interface, &microplanes, &effects and &initial_state.
submodule (interlock_deck) interlock_deck_material
  implicit none

contains

  module procedure read_interface
    real(dp) :: sigma0_n, sigma0_t, gc, eta, mu, h_n
    logical :: prefractured
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /interface/ sigma0_n, sigma0_t, gc, eta, mu, h_n, prefractured
    sigma0_n = unset
    sigma0_t = unset
    gc = unset
    eta = unset
    mu = unset
    h_n = huge(1.0_dp)
    prefractured = .false.
    message = ''
    read (u, nml=interface, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'interface', scan%a(kp))
        read (probe, nml=interface, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(1, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    call check_required(prop_sigma0_n, sigma0_n, message); if (len_trim(message) > 0) return
    call check_required(prop_sigma0_t, sigma0_t, message); if (len_trim(message) > 0) return
    call check_required(prop_gc, gc, message); if (len_trim(message) > 0) return
    call check_required(prop_eta, eta, message); if (len_trim(message) > 0) return
    call check_required(prop_mu, mu, message); if (len_trim(message) > 0) return
    call check_required(prop_h_n, h_n, message); if (len_trim(message) > 0) return
    deck%rows(prop_sigma0_n) = sigma0_n
    deck%rows(prop_sigma0_t) = sigma0_t
    deck%rows(prop_gc) = gc
    deck%rows(prop_eta) = eta
    deck%rows(prop_mu) = mu
    deck%rows(prop_h_n) = h_n
    deck%rows(prop_prefractured) = merge(1.0_dp, 0.0_dp, prefractured)
  end procedure read_interface

  module procedure read_microplanes
    real(dp), dimension(max_planes) :: theta0_deg, thetaf_deg, zeta0, gamma_hat, phi_deg
    integer :: n_planes, ios, n, k, n_azimuths
    logical :: ok
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /microplanes/ theta0_deg, thetaf_deg, zeta0, n_planes, gamma_hat, n_azimuths, phi_deg
    theta0_deg = unset
    thetaf_deg = unset
    zeta0 = unset
    gamma_hat = unset
    phi_deg = unset
    n_planes = unset_int
    n_azimuths = unset_int
    message = ''
    read (u, nml=microplanes, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'microplanes', scan%a(kp))
        read (probe, nml=microplanes, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(2, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    if (has_gaps(theta0_deg) .or. has_gaps(thetaf_deg) .or. has_gaps(zeta0) .or. &
        has_gaps(gamma_hat)) then
      message = 'per-plane values must be given from the first plane on, without gaps'
      return
    end if
    if (has_gaps(phi_deg)) then
      message = 'per-plane values must be given from the first plane on, without gaps'
      return
    end if
    if (n_azimuths /= unset_int) then
      ! The azimuthal RIA of SPEC section 9 (a 3D case): the paper's values, N_a azimuths.
      if (n_planes /= unset_int .or. count_given(phi_deg) > 0) then
        message = 'n_azimuths (the azimuthal RIA) takes the paper''s values (one theta0_deg, ' // &
                  'thetaf_deg, zeta0): give no n_planes or phi_deg with it'
        return
      end if
      if (n_azimuths < 1 .or. n_azimuths > max_azimuths) then
        message = 'n_azimuths = ' // format_integer(n_azimuths) // ' is inadmissible: ' // &
                  'admissible 1 <= n_azimuths <= ' // format_integer(max_azimuths) // &
                  ' (1 + 2 n_azimuths planes)'
        return
      end if
      deck%rows(prop_ria) = ria_azimuthal
      deck%rows(prop_n_azimuths) = n_azimuths
      deck%n_components = 3
    end if
    if (n_planes == unset_int .and. count_given(phi_deg) > 0) then
      message = 'phi_deg (one azimuth per plane) needs a general RIA: give n_planes (or ' // &
                'n_azimuths for the azimuthal RIA)'
      return
    end if
    if (n_planes == unset_int) then
      ! The paper's symmetric RIA: one value each.
      deck%paper_ria = .true.
      deck%n_planes = 3
      if (count_given(theta0_deg) /= 1 .or. count_given(thetaf_deg) > 1 .or. &
          count_given(zeta0) > 1 .or. count_given(gamma_hat) > 0) then
        message = 'without n_planes (the paper''s RIA) give one theta0_deg, and at most one ' // &
                  'thetaf_deg and zeta0 (no gamma_hat); for a general RIA give n_planes'
        if (count_given(theta0_deg) == 0) message = 'theta0_deg is required (admissible ' // &
          format_range(prop_theta0) // ')'
        return
      end if
      deck%thetaf_given = count_given(thetaf_deg) > 0
      if (count_given(thetaf_deg) == 0) thetaf_deg(1) = theta0_deg(1)
      if (count_given(zeta0) == 0) zeta0(1) = huge(1.0_dp)
      call check_required(prop_theta0, theta0_deg(1), message); if (len_trim(message) > 0) return
      call check_required(prop_thetaf, thetaf_deg(1), message); if (len_trim(message) > 0) return
      call check_required(prop_zeta0, zeta0(1), message); if (len_trim(message) > 0) return
      if (thetaf_deg(1) > theta0_deg(1)) then
        message = "property 'thetaf_deg' = " // value_str(thetaf_deg(1)) // &
                  ' is inadmissible: admissible 0 <= thetaf_deg <= theta0_deg = ' // &
                  value_str(theta0_deg(1)) // ' [deg]'
        return
      end if
      deck%rows(prop_theta0) = theta0_deg(1)
      deck%rows(prop_thetaf) = thetaf_deg(1)
      deck%rows(prop_zeta0) = zeta0(1)
    else
      deck%paper_ria = .false.
      if (n_planes < 1 .or. n_planes > max_planes) then
        message = 'n_planes = ' // format_integer(n_planes) // ' is inadmissible: admissible 1 <= ' // &
                  'n_planes <= ' // format_integer(max_planes)
        return
      end if
      n = n_planes
      if (count_given(theta0_deg) /= n .or. count_given(gamma_hat) /= n) then
        message = 'with n_planes = ' // format_integer(n) // ' give ' // format_integer(n) // &
                  ' values of gamma_hat and of theta0_deg (given: ' // &
                  format_integer(count_given(gamma_hat)) // ' and ' // format_integer(count_given(theta0_deg)) // ')'
        return
      end if
      deck%thetaf_given = count_given(thetaf_deg) > 0
      if (count_given(thetaf_deg) == 0) thetaf_deg(1:n) = theta0_deg(1:n)
      if (count_given(zeta0) == 0) zeta0(1:n) = huge(1.0_dp)
      if (count_given(phi_deg) > 0) then
        ! Azimuths: a 3D case (SPEC section 9).
        if (count_given(phi_deg) /= n) then
          message = 'with n_planes = ' // format_integer(n) // ' give ' // format_integer(n) // &
                    ' values of phi_deg, or none (given: ' // format_integer(count_given(phi_deg)) // ')'
          return
        end if
        do k = 1, n
          if (.not. (ieee_is_finite(phi_deg(k)) .and. abs(phi_deg(k)) <= 360.0_dp)) then
            message = 'plane ' // format_integer(k) // ': phi_deg(' // format_integer(k) // ') = ' // &
                      value_str(phi_deg(k)) // ' is inadmissible: admissible -360 <= phi_deg ' // &
                      '<= 360 [deg]'
            return
          end if
        end do
        deck%azimuths_given = .true.
        deck%phi_deg = 0.0_dp
        deck%phi_deg(1:n) = phi_deg(1:n)
        deck%n_components = 3
      end if
      if (count_given(thetaf_deg) /= n .or. count_given(zeta0) /= n) then
        message = 'with n_planes = ' // format_integer(n) // ' give ' // format_integer(n) // &
                  ' values of thetaf_deg and of zeta0, or none'
        return
      end if
      do k = 1, n
        call check_required(prop_theta0, abs(theta0_deg(k)), message)
        if (len_trim(message) > 0) then
          message = 'plane ' // format_integer(k) // ': ' // trim(message) // ' (in absolute value)'
          return
        end if
        call check_required(prop_zeta0, zeta0(k), message)
        if (len_trim(message) > 0) then
          message = 'plane ' // format_integer(k) // ': ' // trim(message)
          return
        end if
        if (.not. (in_range(gamma_hat(k), 0.0_dp, 1.0_dp) .and. gamma_hat(k) > 0.0_dp)) then
          message = 'plane ' // format_integer(k) // ': gamma_hat(' // format_integer(k) // ') = ' // &
                    value_str(gamma_hat(k)) // ' is inadmissible: admissible 0 < gamma_hat <= 1 [-]'
          return
        end if
        ok = in_range(abs(thetaf_deg(k)), 0.0_dp, abs(theta0_deg(k)))
        if (ok) ok = .not. (thetaf_deg(k) * theta0_deg(k) < 0.0_dp)
        if (.not. ok) then
          message = 'plane ' // format_integer(k) // ': thetaf_deg(' // format_integer(k) // ') = ' // &
                    value_str(thetaf_deg(k)) // ' is inadmissible: admissible 0 <= |thetaf_deg| ' // &
                    '<= |theta0_deg| = ' // value_str(abs(theta0_deg(k))) // &
                    ' [deg], of the same sign as theta0_deg = ' // value_str(theta0_deg(k))
          return
        end if
      end do
      if (abs(sum(gamma_hat(1:n)) - 1.0_dp) > 1.0e-9_dp) then
        message = 'gamma_hat sums to ' // value_str(sum(gamma_hat(1:n))) // ': admissible a sum ' // &
                  'of 1 (within 1e-9): the area fractions of the microplanes'
        return
      end if
      deck%n_planes = n
      deck%gamma_hat = 0.0_dp
      deck%theta0_deg = 0.0_dp
      deck%thetaf_deg = 0.0_dp
      deck%zeta0 = huge(1.0_dp)
      deck%gamma_hat(1:n) = gamma_hat(1:n)
      deck%theta0_deg(1:n) = theta0_deg(1:n)
      deck%thetaf_deg(1:n) = thetaf_deg(1:n)
      deck%zeta0(1:n) = zeta0(1:n)
      deck%rows(prop_theta0) = abs(theta0_deg(1))
      deck%rows(prop_thetaf) = abs(thetaf_deg(1))
      deck%rows(prop_zeta0) = zeta0(1)
    end if
  end procedure read_microplanes

  module procedure read_effects
    logical :: damage, friction, interlocking, finite_depth, wear
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /effects/ damage, friction, interlocking, finite_depth, wear
    damage = .true.
    friction = .true.
    interlocking = .true.
    finite_depth = .true.
    wear = .true.
    message = ''
    read (u, nml=effects, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'effects', scan%a(kp))
        read (probe, nml=effects, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(3, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    deck%rows(prop_effect_damage:prop_effect_wear) = &
      merge(1.0_dp, 0.0_dp, [damage, friction, interlocking, finite_depth, wear])
  end procedure read_effects

  module procedure read_initial_state
    real(dp), dimension(max_planes) :: damage, beta, frictional_slip, zeta, theta, &
                                       friction_traction, sf_strike, tauf_strike
    real(dp) :: separation(3), traction(3)
    integer :: ios, nc
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /initial_state/ damage, beta, frictional_slip, zeta, theta, friction_traction, &
      separation, traction, sf_strike, tauf_strike
    damage = unset
    beta = unset
    frictional_slip = unset
    zeta = unset
    theta = unset
    friction_traction = unset
    sf_strike = unset
    tauf_strike = unset
    separation = unset
    traction = unset
    message = ''
    read (u, nml=initial_state, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'initial_state', scan%a(kp))
        read (probe, nml=initial_state, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(7, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    if (has_gaps(damage) .or. has_gaps(beta) .or. has_gaps(frictional_slip) .or. has_gaps(zeta) &
        .or. has_gaps(theta) .or. has_gaps(friction_traction) .or. has_gaps(sf_strike) .or. &
        has_gaps(tauf_strike) .or. has_gaps(separation) .or. has_gaps(traction)) then
      message = 'values must be given from the first on, without gaps'
      return
    end if
    ! (the groups before this one have said whether the deck is 3D)
    nc = deck%n_components
    if (any(count_given(separation) == [1, 5 - nc]) .or. &
        any(count_given(traction) == [1, 5 - nc])) then
      if (nc == 3) then
        message = 'separation and traction take three values each (normal, t1, t2) in a 3D deck'
      else
        message = 'separation and traction take two values each (normal, tangential) in a ' // &
                  '2D deck (three, with t2, in a 3D one: T2 loading, a path, azimuths or the ' // &
                  'azimuthal RIA)'
      end if
      return
    end if
    if (nc == 2 .and. (count_given(sf_strike) > 0 .or. count_given(tauf_strike) > 0)) then
      message = 'sf_strike and tauf_strike are the strike components of a 3D deck (T2 ' // &
                'loading, a path, azimuths or the azimuthal RIA): this deck is 2D'
      return
    end if
    message = range_message('damage', damage, 0.0_dp, 1.0_dp, '0 <= damage <= 1')
    if (len_trim(message) == 0) message = range_message('beta', beta, 0.0_dp, 1.0e12_dp, &
                                                        '0 <= beta <= 1e12')
    if (len_trim(message) == 0) message = range_message('zeta', zeta, 0.0_dp, 1.0e30_dp, &
                                                        '0 <= zeta < 1e30 [N/mm]')
    if (len_trim(message) == 0) message = range_message('theta', theta, -0.5_dp * pi, &
                                                        0.5_dp * pi, '-pi/2 < theta < pi/2 [rad]', &
                                                        open_ends=.true.)
    if (len_trim(message) > 0) return
    message = magnitude_message('frictional_slip', 'mm', frictional_slip)
    if (len_trim(message) == 0) message = magnitude_message('friction_traction', 'MPa', &
                                                              friction_traction)
    if (len_trim(message) == 0) message = magnitude_message('sf_strike', 'mm', sf_strike)
    if (len_trim(message) == 0) message = magnitude_message('tauf_strike', 'MPa', tauf_strike)
    if (len_trim(message) == 0) message = magnitude_message('separation', 'mm', separation)
    if (len_trim(message) == 0) message = magnitude_message('traction', 'MPa', traction)
    if (len_trim(message) > 0) return
    deck%has_initial_state = .true.
    deck%init_damage = damage
    deck%init_beta = beta
    deck%init_sf = frictional_slip
    deck%init_zeta = zeta
    deck%init_theta = theta
    deck%init_tauf = friction_traction
    deck%init_sf_strike = sf_strike
    deck%init_tauf_strike = tauf_strike
    deck%init_s = separation
    deck%init_sigma = traction
  end procedure read_initial_state

end submodule interlock_deck_material
