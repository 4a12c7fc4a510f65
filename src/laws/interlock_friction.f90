!> Coulomb friction on the damaged part of a microplane (eq. 7 with erratum E1): an elastic
!> predictor on the friction traction and a return to |tau_f| = mu p, p the contact pressure.
!> The return in scalar form (friction_step: a plane of a two-dimensional interface) and in
!> vector form (radial_return: the tangential 2-vector of a plane of a three-dimensional one).
module interlock_friction
  use interlock_kinds, only: dp
  implicit none
  private
  public :: friction_step, radial_return, direction_turn, direction_turn_of, &
            unit_direction_turn

contains

  !> The return mapping (scalars only, the material's inverse 1/K_t): mu_p = mu K_n <-s_n>_- is the bound (0 on an open plane or with friction
  !> off: the damaged part follows freely), mu_kn = mu K_n its derivative wrt -s_n, st the
  !> tangential separation, sf_old the slip at the start. `closed`: the plane is in contact
  !> for the derivatives (s_n <= 0 with friction on): at s_n = 0 exactly, where mu_p = 0, the
  !> derivatives are the closed side's (SPEC D13). Returns the slip sf, the friction traction
  !> tauf and its derivatives wrt (s_n, s_t), the slip increment |d sf| and its sign (0 while
  !> sticking or without slip; d|d sf|/d s_t).
  elemental subroutine friction_step(mu_p, mu_kn, closed, kt, inv_kt, st, sf_old, sf, tauf, &
                                     dtauf_dsn, dtauf_dst, slip, slip_sign)
    real(dp), intent(in) :: mu_p, mu_kn, kt, inv_kt, st, sf_old
    logical, intent(in) :: closed
    real(dp), intent(out) :: sf, tauf, dtauf_dsn, dtauf_dst, slip, slip_sign
    real(dp) :: tau_trial
    if (mu_p > 0.0_dp) then
      tau_trial = kt * (st - sf_old)
      if (abs(tau_trial) <= mu_p) then
        sf = sf_old
        tauf = tau_trial
        dtauf_dsn = 0.0_dp
        dtauf_dst = kt
        slip = 0.0_dp
        slip_sign = 0.0_dp
      else
        tauf = sign(mu_p, tau_trial)
        sf = st - tauf * inv_kt
        dtauf_dsn = -sign(mu_kn, tau_trial)
        dtauf_dst = 0.0_dp
        slip = (abs(tau_trial) - mu_p) * inv_kt
        slip_sign = sign(1.0_dp, tau_trial)
      end if
    else
      sf = st
      tauf = 0.0_dp
      dtauf_dsn = 0.0_dp
      dtauf_dst = 0.0_dp
      slip = abs(sf - sf_old)
      slip_sign = 0.0_dp
      if (slip > 0.0_dp) then
        slip_sign = sign(1.0_dp, sf - sf_old)
        ! s_n = 0 exactly: the slide with mu p = 0 for the derivatives (the values are the
        ! same on both sides); at the cone's apex (no slip) a kink where they stay 0.
        if (closed) dtauf_dsn = -slip_sign * mu_kn
      end if
    end if
  end subroutine friction_step

  !> The return of a tangential 2-vector whose trial traction tr = K_t (s_kt - sf_o), of norm
  !> trn, exceeds the bound mu_p > 0: back to |tau_f| = mu p along n = tr / |tr| (radial return,
  !> backward Euler on the slip direction): tau_f = mu p n, sf = s_kt - tau_f / K_t, the slip of
  !> the step |d sf| = (|tr| - mu p) / K_t. Derivatives with respect to the local separation
  !> (s_kn, s_kt1, s_kt2), g_x(j) = d x / d sl(j): g_mu the bound's, g_nv(:, i) = d n_i =
  !> (K_t / |tr|) (e_i - n_i n) . d s_kt, g_tauf(:, i) = n_i g_mu + mu p g_nv(:, i). In one
  !> dimension this is friction_step's slide. `in_plane` (absent: false): tr(2) = 0, and only the
  !> derivatives of the first components with respect to (s_kn, s_kt1) are wanted: n = (+-1, 0),
  !> whose derivative there (the projector's 1-1 entry) is 0, tau_f,2 = 0; the derivatives of the
  !> second components are left 0.
  pure subroutine radial_return(mu_p, g_mu, kt, inv_kt, st, tr, trn, nv, g_nv, sf, tauf, &
                                g_tauf, slip, in_plane)
    real(dp), intent(in) :: mu_p, g_mu(3), kt, inv_kt, st(2), tr(2), trn
    real(dp), intent(out) :: nv(2), g_nv(3, 2), sf(2), tauf(2), g_tauf(3, 2), slip
    logical, intent(in), optional :: in_plane
    real(dp) :: q
    integer :: i
    logical :: plane_nt
    plane_nt = .false.
    if (present(in_plane)) plane_nt = in_plane
    if (plane_nt) then
      nv(1) = sign(1.0_dp, tr(1))
      nv(2) = 0.0_dp
      g_nv = 0.0_dp
      g_tauf(:, 2) = 0.0_dp
      tauf(2) = 0.0_dp
      sf(2) = st(2)
      tauf(1) = mu_p * nv(1)
      g_tauf(:, 1) = nv(1) * g_mu
      sf(1) = st(1) - tauf(1) * inv_kt
    else
      do i = 1, 2
        nv(i) = tr(i) / trn
      end do
      ! (the projector's entries one by one: its s_kn row is 0)
      q = kt / trn
      g_nv(1, :) = 0.0_dp
      g_nv(2, 1) = q * (1.0_dp - nv(1) * nv(1))
      g_nv(3, 1) = q * (0.0_dp - nv(1) * nv(2))
      g_nv(2, 2) = q * (0.0_dp - nv(2) * nv(1))
      g_nv(3, 2) = q * (1.0_dp - nv(2) * nv(2))
      do i = 1, 2
        tauf(i) = mu_p * nv(i)
        g_tauf(1, i) = nv(i) * g_mu(1)
        g_tauf(2:3, i) = nv(i) * g_mu(2:3) + mu_p * g_nv(2:3, i)
        sf(i) = st(i) - tauf(i) * inv_kt
      end do
    end if
    slip = (trn - mu_p) * inv_kt
  end subroutine radial_return

  !> The turn of the friction traction's direction over a step from tauf_o to tauf, 1 - cos of
  !> the angle a between them (about a^2 / 2): the local error of a first-order rule on the
  !> slip direction, which substepping's error estimate weighs (in 3D an inclined plane's local
  !> slip path turns, and its direction is the slowest part of the friction to resolve). 0
  !> where either traction is 0 and where the direction turns by 90 deg or more: a reversal,
  !> which passes through sticking and which radial return integrates exactly. Taken as
  !> sin(a)^2 / (1 + cos a), without cancellation, and exactly 0 for parallel tractions (every
  !> 2D step).
  pure real(dp) function direction_turn(tauf_o, tauf) result(turn)
    real(dp), intent(in) :: tauf_o(2), tauf(2)
    turn = direction_turn_of(tauf_o, tauf, norm2(tauf))
  end function direction_turn

  !> direction_turn where the caller has the end traction's magnitude, norm = |tauf| (a plane
  !> law's |tau_f|).
  pure real(dp) function direction_turn_of(tauf_o, tauf, norm) result(turn)
    real(dp), intent(in) :: tauf_o(2), tauf(2), norm
    real(dp) :: norm_o, u_o(2), u(2)
    turn = 0.0_dp
    ! (unit vectors first: any admissible traction, squared, may overflow)
    norm_o = norm2(tauf_o)
    if (.not. (norm_o > 0.0_dp .and. norm > 0.0_dp)) return
    u_o = tauf_o / norm_o
    u = tauf / norm
    turn = unit_direction_turn(u_o, u)
  end function direction_turn_of

  !> direction_turn of the unit vectors u_o and u of the two tractions' directions.
  pure real(dp) function unit_direction_turn(u_o, u) result(turn)
    real(dp), intent(in) :: u_o(2), u(2)
    real(dp) :: c
    turn = 0.0_dp
    c = u_o(1) * u(1) + u_o(2) * u(2)
    if (c > 0.0_dp) turn = (u_o(1) * u(2) - u_o(2) * u(1))**2 / (1.0_dp + c)
  end function unit_direction_turn

end module interlock_friction
