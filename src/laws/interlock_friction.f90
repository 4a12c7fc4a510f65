!> Coulomb friction on the damaged part of a microplane (eq. 7 with erratum E1): an elastic
!> predictor on the friction traction and a return to |tau_f| = mu p, p the contact pressure.
!> The return in scalar form (friction_step: a plane of a two-dimensional interface) and in
!> vector form (radial_return: the tangential 2-vector of a plane of a three-dimensional one);
!> SPEC D14's vector return of the trapezoidal scheme (start_direction, mean_direction_return,
!> mean_direction_slide, mean_direction_tie: the slip increment along the mean of the start and
!> end directions) with the trapezoidal wear terms of the slip (wear_start, wear_end;
!> straight_wear_start along a straight slip path), stated once for the general path
!> (interlock_plane_law_3d) and the trapezoidal kernel.
module interlock_friction
  use interlock_kinds, only: dp
  implicit none
  private
  public :: friction_step, radial_return, direction_turn, direction_turn_of, &
            unit_direction_turn, vector_norm, norm_gradient, sign_of, slides_at_start, &
            start_direction, mean_direction_return, mean_direction_slide, mean_direction_tie, &
            straight_wear_start

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

  !> D14's slip direction of a plane that slides over the whole step (SPEC decision D14): with
  !> the start direction n_o = tauf_o / |tauf_o| and the trial traction tau_tr, the slip
  !> increment along the mean direction (n_o + n_new) / |n_o + n_new| and tau_f = mu p n_new
  !> make tau_tr - mu p n_new parallel to that mean, which is then the direction of
  !> v = tau_tr + mu p n_o; n_new is n_o turned by twice v's angle psi from n_o. In n_o's
  !> frame, v = (a, b) with a = tau_tr . n_o + mu p, b = n_o x tau_tr: n_new = ((a^2 - b^2)
  !> n_o + 2 a b n_o') / (a^2 + b^2), n_o' = n_o turned by +90 deg; closed form, no iteration
  !> (with b = 0, as in every 2D step, n_new = n_o to the bit). Its derivative: d n_new = 2
  !> d psi n_new', d psi = (a db - b da) / (a^2 + b^2), through tau_tr (K_t d s_kt) and mu p.
  !> Applies (`ok`) where the plane slides at the start (the caller's, start_direction) and
  !> the turn 2 psi is at most 90 deg (a >= |b|); else radial return (a reversal turns by 180
  !> deg). The caller has |tau_tr| > mu p (sliding at the end).
  pure subroutine mean_direction_return(kt, n_o, tr, mu_p, g_mu1, chain, drivers, ok, n_new, &
                                        g_psi, phi_turn, u, cos_psi, sin_psi)
    real(dp), intent(in) :: kt   !< K_t [MPa/mm]
    real(dp), intent(in) :: n_o(2)   !< the start direction (start_direction)
    real(dp), intent(in) :: tr(2), mu_p
    real(dp), intent(in) :: g_mu1   !< d(mu p) / d s_kn (its only entry)
    logical, intent(in) :: chain   !< phi_turn is wanted
    logical, intent(in) :: drivers   !< u, cos_psi and sin_psi are wanted
    logical, intent(out) :: ok
    !> n_new; d psi / d sl in g_psi (d n_new = 2 d psi n_new'); with `chain` the turn of
    !> n_new's angle per turn of n_o's, d (phi_o + 2 psi) / d phi_o
    real(dp), intent(out) :: n_new(2), g_psi(3), phi_turn
    !> the mean direction u = v / |v| (the slip's) and (cos, sin)(psi) of its angle from n_o
    real(dp), intent(out) :: u(2), cos_psi, sin_psi
    real(dp) :: a, b, a2, b2, v2, m, scale_ab, inv_norm, inv_v2, va(2)
    ok = .false.
    a = tr(1) * n_o(1) + tr(2) * n_o(2) + mu_p
    b = n_o(1) * tr(2) - n_o(2) * tr(1)
    if (.not. (a > 0.0_dp .and. a >= abs(b))) return
    ok = .true.
    ! n_new depends on the direction of (a, b) only: scaled where the squares would overflow
    ! (a trial traction from a huge admissible slip, as vector_norm)
    m = max(abs(a), abs(b))
    scale_ab = 1.0_dp
    if (m >= 1.0e150_dp) then
      a = a / m
      b = b / m
      scale_ab = m
    end if
    a2 = a * a
    b2 = b * b
    v2 = a2 + b2
    n_new(1) = ((a2 - b2) * n_o(1) - (2.0_dp * a * b) * n_o(2)) / v2
    n_new(2) = ((a2 - b2) * n_o(2) + (2.0_dp * a * b) * n_o(1)) / v2
    ! da = d(mu p) + K_t n_o . d s_kt, db = K_t n_o x d s_kt (no s_kn entry), so that d psi =
    ! (a db - b da) / |v|^2 = (K_t (-v_2, v_1) . d s_kt - b d(mu p)) / |v|^2 with v = a n_o +
    ! b n_o' in the frame (e, q) (va; the slip's direction u = v / |v|)
    va(1) = a * n_o(1) - b * n_o(2)
    va(2) = a * n_o(2) + b * n_o(1)
    inv_v2 = 1.0_dp / (v2 * scale_ab)
    g_psi(1) = (0.0_dp - b * g_mu1) * inv_v2
    g_psi(2) = (0.0_dp - va(2)) * (kt * inv_v2)
    g_psi(3) = va(1) * (kt * inv_v2)
    if (drivers) then
      inv_norm = 1.0_dp / sqrt(v2)
      cos_psi = a * inv_norm
      sin_psi = b * inv_norm
      u(1) = va(1) * inv_norm
      u(2) = va(2) * inv_norm
    end if
    ! turning n_o by d phi_o: da = b d phi_o, db = -(a - mu p) d phi_o, so n_new's angle
    ! phi_o + 2 psi turns by (2 a mu p / (a^2 + b^2) - 1) d phi_o
    phi_turn = 0.0_dp
    if (chain) phi_turn = 2.0_dp * a * (mu_p / scale_ab) / v2 - 1.0_dp
  end subroutine mean_direction_return

  !> D14's start: where a plane slides at the start of a step (slides_at_start with its start
  !> friction traction tauf_o and the start state's mu p_o, interlock_plane_law's start_yield
  !> with the start separation's dip component), `mean_o` and the start direction of slip n_o =
  !> tauf_o / |tauf_o|; else not mean_o (radial return) and n_o = 0. A property of the start
  !> state: taken once per step, not at each evaluation of a wear equation's iteration.
  pure subroutine start_direction(tauf_o, mu_p_o, mean_o, n_o)
    real(dp), intent(in) :: tauf_o(2), mu_p_o
    logical, intent(out) :: mean_o
    real(dp), intent(out) :: n_o(2)
    real(dp) :: t_norm, d
    ! (without branches: planes that slide at the start and others alternate; the divisor 1
    ! where the direction is not taken)
    t_norm = vector_norm(tauf_o)
    mean_o = slides_at_start(t_norm, mu_p_o)
    d = merge(t_norm, 1.0_dp, mean_o)
    n_o(1) = merge(tauf_o(1) / d, 0.0_dp, mean_o)
    n_o(2) = merge(tauf_o(2) / d, 0.0_dp, mean_o)
  end subroutine start_direction

  !> A plane slides at the start of a step: its friction traction's magnitude |tauf_o| is
  !> mu p_o > 0, to a relative 1e-10 (the round-off between the stored friction traction and the
  !> start pressure recomputed from the start separation at the start angle).
  elemental logical function slides_at_start(tauf_o_norm, mu_p_o)
    real(dp), intent(in) :: tauf_o_norm, mu_p_o
    real(dp), parameter :: sliding_tol = 1.0e-10_dp
    slides_at_start = mu_p_o > 0.0_dp .and. tauf_o_norm >= (1.0_dp - sliding_tol) * mu_p_o
  end function slides_at_start

  !> |a| of a tangential 2-vector. Its squares are taken as they are while they stay far from
  !> overflow, else scaled by the larger component: an admissible state (a frictional slip of
  !> 1e150 mm) times a stiff interface's K_t gives a trial traction whose square is beyond the
  !> largest number.
  pure real(dp) function vector_norm(a) result(r)
    real(dp), intent(in) :: a(2)
    real(dp) :: b(2), m
    m = max(abs(a(1)), abs(a(2)))
    if (m < 1.0e150_dp) then
      r = sqrt(a(1) * a(1) + a(2) * a(2))
    else
      b(1) = a(1) / m
      b(2) = a(2) / m
      r = m * sqrt(b(1) * b(1) + b(2) * b(2))
    end if
  end function vector_norm

  !> d|a| = (a / |a|) . da for the gradients g_a(:, i) = d a(i); 0 at a = 0 (a kink).
  pure function norm_gradient(a, a_norm, g_a) result(g)
    real(dp), intent(in) :: a(2), a_norm, g_a(3, 2)
    real(dp) :: g(3)
    g = 0.0_dp
    if (a_norm > 0.0_dp) g = (a(1) / a_norm) * g_a(:, 1) + (a(2) / a_norm) * g_a(:, 2)
  end function norm_gradient

  !> D14's slide (mean_direction_return applied, ok): tau_f = mu p n_new with its derivative
  !> (d n_new(i) = nt(i) d psi, nt = 2 n_new turned by +90 deg; mu p has an s_kn entry alone),
  !> the slip of the step dsf = (tau_tr - tau_f) / K_t (what the trial traction exceeds the
  !> bound by) and sf = s_kt - tau_f / K_t, |d sf| (slip_norm); and the trapezoidal wear terms:
  !> the flow is along the friction traction, so that the wear rate is D mu p n_1^2 |d sf| / dt,
  !> at the start of the step (per D mu p) wear_start = |d sf| n_o,1^2 and at its end wear_end
  !> = D |tau_f,1| |d sf| |n_new,1|, with `drivers` their derivatives d / d sl (D of slope g_dmg
  !> where damage grows, `grows`).
  pure subroutine mean_direction_slide(mu_p, g_mu1, inv_kt, st, tr, n_o, n_new, g_psi, u, &
                                       cos_psi, sin_psi, dmg, g_dmg, grows, drivers, tauf, &
                                       g_tauf, sf, dsf, slip_norm, wear_start, wear_end, &
                                       g_wear_start, g_wear_end)
    real(dp), intent(in) :: mu_p, g_mu1, inv_kt, st(2), tr(2), n_o(2)
    !> mean_direction_return's n_new, g_psi, u, cos_psi, sin_psi
    real(dp), intent(in) :: n_new(2), g_psi(3), u(2), cos_psi, sin_psi
    real(dp), intent(in) :: dmg, g_dmg(3)
    logical, intent(in) :: grows, drivers
    real(dp), intent(out) :: tauf(2), g_tauf(3, 2), sf(2), dsf(2), slip_norm, wear_start, &
                             wear_end, g_wear_start(3), g_wear_end(3)
    real(dp) :: nt(2), x, atau, un, ut, g_slip_norm(3), sg, g_x(3), g_atau(3)
    integer :: i
    nt(1) = -2.0_dp * n_new(2)
    nt(2) = 2.0_dp * n_new(1)
    do i = 1, 2
      tauf(i) = mu_p * n_new(i)
      g_tauf(1, i) = n_new(i) * g_mu1 + mu_p * (nt(i) * g_psi(1))
      g_tauf(2, i) = mu_p * (nt(i) * g_psi(2))
      g_tauf(3, i) = mu_p * (nt(i) * g_psi(3))
      dsf(i) = (tr(i) - tauf(i)) * inv_kt
      sf(i) = st(i) - tauf(i) * inv_kt
    end do
    if (drivers) then
      ! (tau_tr - tau_f is along the slip's direction u: its magnitude is the projection on u,
      ! without a square root)
      slip_norm = abs(dsf(1) * u(1) + dsf(2) * u(2))
    else
      slip_norm = vector_norm(dsf)
    end if
    wear_start = slip_norm * (n_o(1) * n_o(1))
    x = slip_norm * abs(n_new(1))
    atau = dmg * abs(tauf(1))
    wear_end = atau * x
    if (drivers) then
      ! d|d sf| = u . d dsf along the slip's direction, the mean direction u, d dsf = d s_kt -
      ! d tau_f / K_t: u . d tau_f = (u . n_new) d(mu p) + mu p (u . nt) d psi, u . n_new =
      ! cos psi, u . nt = -2 sin psi
      un = cos_psi * inv_kt
      ut = (2.0_dp * mu_p * sin_psi) * inv_kt
      g_slip_norm(1) = -(un * g_mu1 - ut * g_psi(1))
      g_slip_norm(2) = u(1) + ut * g_psi(2)
      g_slip_norm(3) = u(2) + ut * g_psi(3)
      g_wear_start = g_slip_norm * (n_o(1) * n_o(1))
      ! (tau_f,1 = mu p n_new,1: the sign of n_new,1)
      sg = sign_of(n_new(1))
      g_x = g_slip_norm * abs(n_new(1)) + (slip_norm * sg * nt(1)) * g_psi
      g_atau = (dmg * sg) * g_tauf(:, 1)
      if (grows) g_atau = g_dmg * abs(tauf(1)) + g_atau
      g_wear_end = g_atau * x + atau * g_x
    end if
  end subroutine mean_direction_slide

  !> D14 on a plane closed at the tie s_kn = 0 (mu p = 0, SPEC D13) that slid at the start,
  !> where mean_direction_return gave n_new: the free plane's values (tau_f = 0, sf = s_kt, the
  !> slip slip_norm = |s_kt - sf_o|), the slide's derivatives with mu p = 0 along n_new, d
  !> tau_f = d(mu p) n_new (g_mu: d(mu p) / d sl), the slip (tau_tr - mu p n_new) / K_t; the
  !> wear terms (mean_direction_slide's) wear_start = |d sf| n_o,1^2 and wear_end = 0, with
  !> `drivers` their derivatives and that of the dip slip |d sf_1|.
  pure subroutine mean_direction_tie(kt, inv_kt, tr, n_o, n_new, g_mu, dmg, slip_norm, drivers, &
                                     g_tauf, wear_start, wear_end, g_slip_dip, g_wear_start, &
                                     g_wear_end)
    real(dp), intent(in) :: kt, inv_kt, tr(2), n_o(2), n_new(2), g_mu(3), dmg, slip_norm
    logical, intent(in) :: drivers
    real(dp), intent(out) :: g_tauf(3, 2), wear_start, wear_end, g_slip_dip(3), &
                             g_wear_start(3), g_wear_end(3)
    real(dp) :: dsf(2), g_dsf(3, 2), g_slip_norm(3), g_atau(3)
    integer :: i
    do i = 1, 2
      g_tauf(:, i) = n_new(i) * g_mu
    end do
    wear_start = slip_norm * (n_o(1) * n_o(1))
    wear_end = 0.0_dp
    if (drivers) then
      do i = 1, 2
        dsf(i) = tr(i) * inv_kt
        g_dsf(:, i) = (0.0_dp - g_tauf(:, i)) * inv_kt
        g_dsf(1 + i, i) = (kt - g_tauf(1 + i, i)) * inv_kt
      end do
      g_slip_norm = norm_gradient(dsf, vector_norm(dsf), g_dsf)
      g_slip_dip = sign_of(dsf(1)) * g_dsf(:, 1)
      g_atau = abs(n_new(1)) * g_mu
      g_wear_start = g_slip_norm * (n_o(1) * n_o(1))
      g_wear_end = dmg * g_atau * (slip_norm * abs(n_new(1)))
    end if
  end subroutine mean_direction_tie

  !> The trapezoidal start wear term of a slip along a straight path in the step (radial
  !> return, sticking, free: D14's direction not taken): the slip of the step |d sf| (slip_norm)
  !> times the squared dip share of its direction, |d sf_1|^2 / |d sf| (slip_dip = |d sf_1|;
  !> share 1 without slip), with `drivers` its derivative from those of slip_dip and slip_norm.
  pure subroutine straight_wear_start(slip_dip, slip_norm, g_slip_dip, g_slip_norm, drivers, &
                                      wear_start, g_wear_start)
    real(dp), intent(in) :: slip_dip, slip_norm, g_slip_dip(3), g_slip_norm(3)
    logical, intent(in) :: drivers
    real(dp), intent(out) :: wear_start, g_wear_start(3)
    real(dp) :: share, g_share(3)
    share = 1.0_dp
    if (slip_norm > 0.0_dp) share = slip_dip / slip_norm
    wear_start = slip_dip * share
    if (drivers) then
      g_share = 0.0_dp
      if (slip_norm > 0.0_dp) g_share = (g_slip_dip - share * g_slip_norm) / slip_norm
      g_wear_start = g_slip_dip * share + slip_dip * g_share
    end if
  end subroutine straight_wear_start

  !> The slope of |x|: -1 below 0, else +1 (the right side at 0).
  elemental real(dp) function sign_of(x)
    real(dp), intent(in) :: x
    sign_of = merge(-1.0_dp, 1.0_dp, x < 0.0_dp)
  end function sign_of

end module interlock_friction
