!> The specialised one-step update of a three-dimensional interface in the explicit scheme
!> (SPEC section 9), the fast path of interlock_update_3d: every plane's angle frozen at its
!> stored value within the step, the wear of eq. 25 after it, and the exact 3x3 tangent at
!> the fixed angles (R^T K_loc R of each plane times its weight, and the contact area's
!> d A_g / d s_N term). Each plane's law is taken with its values and its 3x3 local tangent
!> only, in scalars, from the mechanisms' procedures (interlock_damage, interlock_friction's
!> radial return, eq. 6 of interlock_plane_law, interlock_wear, interlock_geometry): none of
!> the general path's derivatives of the start state, wear drivers or D14 terms. A plane whose
!> s_kn is within the round-off of its rotation is at the tie s_kn = 0 and closed for every
!> derivative (SPEC D13), as in the general path: a path in a plane's surface (the paper's RIA
!> slid along a ridge) stays there. It declines (done false: the caller takes the general
!> path, interlock_general_path, unchanged) what it does not handle at that cost: a separated
!> RIA (D7), a trial friction traction near overflow, a tangent beyond the stable bound,
!> anything not finite. It agrees with the general path to round-off and shares none of its
!> code; core_kernels3d checks it.
module interlock_kernels_3d
  use interlock_kinds, only: dp, is_finite_value
  use interlock_material, only: interlock_material_t, scheme_explicit, max_planes
  use interlock_state, only: interlock_state_3d_t, state_3d_end_point
  use interlock_damage, only: damage_may_grow, damage_growth
  use interlock_friction, only: radial_return
  use interlock_geometry, only: contact_area
  use interlock_wear, only: worn_angle
  use interlock_plane_law, only: plane_frame, wear_weights, normal_traction, tangential_traction
  use interlock_kinematics, only: to_local, to_global
  implicit none
  private
  public :: explicit_step_3d

  !> A trial friction traction whose components reach this is left to the general path (its
  !> norm is scaled there against overflow of the squares)
  real(dp), parameter :: trial_bound = 1.0e150_dp

contains

  !> The explicit scheme's step of every plane from `old` to s = (s_N, s_T1, s_T2) [mm]: the end
  !> state `new` (traction and energies included; the planes beyond n_planes untouched), the
  !> traction `sigma` and `tangent` = d sigma / d s at the fixed start state. `done` false: the
  !> kernel declined (`new`, `sigma`, `tangent` partly written), the general path takes the
  !> increment. `limit`: the largest admissible sum of the tangent's magnitudes (the general
  !> path's stable bound on its entries; a larger sum is declined).
  pure subroutine explicit_step_3d(mat, s, old, limit, new, sigma, tangent, done)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    logical, intent(out) :: done
    real(dp) :: area, darea, c(max_planes), sn(max_planes), gam, energy(3)
    integer :: k, n_eval
    logical :: shared

    sigma = 0.0_dp
    tangent = 0.0_dp
    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)
    done = area > 0.0_dp
    if (.not. done) return
    ! Identical flat planes share one history (SPEC section 7): computed once, copied.
    shared = mat%flat .and. mat%azimuths_zero
    n_eval = merge(1, mat%n_planes, shared)
    ! (the frames first: libm's sincos waits for the floating-point work before it)
    do k = 1, n_eval
      call plane_frame(mat, k, old%theta(k), c(k), sn(k))
    end do
    energy = [old%diss_damage, old%diss_friction, 0.0_dp]
    do k = 1, n_eval
      gam = merge(1.0_dp, mat%gamma_hat(k), shared)
      call explicit_plane(mat, k, mat%cos_phi(k), mat%sin_phi(k), c(k), sn(k), s, old, gam, &
                          area, darea, sigma, tangent, energy, new, done)
      if (.not. done) return
    end do
    do k = n_eval + 1, mat%n_planes
      new%beta(k) = new%beta(1)
      new%damage(k) = new%damage(1)
      new%sf(k) = new%sf(1)
      new%sf_strike(k) = new%sf_strike(1)
      new%zeta(k) = new%zeta(1)
      new%theta(k) = new%theta(1)
      new%tauf(k) = new%tauf(1)
      new%tauf_strike(k) = new%tauf_strike(1)
    end do
    done = within_limit(sigma, tangent, limit)
    if (.not. done) return
    new%diss_damage = energy(1)
    new%diss_friction = energy(2)
    new%stored = energy(3)
    call state_3d_end_point(old, s, sigma, new)
  end subroutine explicit_step_3d

  !> The traction is finite and the tangent's magnitudes sum to at most `limit` (false for a
  !> NaN anywhere: no comparison with it holds).
  pure logical function within_limit(sigma, tangent, limit)
    real(dp), intent(in) :: sigma(3), tangent(3, 3), limit
    ! (the sums written out: no loop)
    within_limit = is_finite_value(abs(sigma(1)) + abs(sigma(2)) + abs(sigma(3))) .and. &
                   abs(tangent(1, 1)) + abs(tangent(2, 1)) + abs(tangent(3, 1)) + &
                   abs(tangent(1, 2)) + abs(tangent(2, 2)) + abs(tangent(3, 2)) + &
                   abs(tangent(1, 3)) + abs(tangent(2, 3)) + abs(tangent(3, 3)) <= limit
  end function within_limit

  !> Plane k at its frozen start angle (frame c, sn; azimuth frame cp, sp) over the step to s,
  !> area fraction gam, contact area `area` (slope darea): adds its weighted traction to sigma,
  !> its weighted R^T K_loc R and the area's term to `tangent`, its energies to energy
  !> (damage and friction dissipation, stored), and stores its end state in `new`. `ok` false:
  !> declined (a trial friction traction near overflow).
  pure subroutine explicit_plane(mat, k, cp, sp, c, sn, s, old, gam, area, darea, sigma, &
                                 tangent, energy, new, ok)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(in) :: cp, sp, c, sn, s(3), gam, area, darea
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(inout) :: sigma(3), tangent(3, 3), energy(3)
    type(interlock_state_3d_t), intent(inout) :: new
    logical, intent(out) :: ok
    real(dp) :: dip, sl(3), tie, pos, dpos, beta, dmg, gd_n, gd_t, tn, tn2, g_dmg(3), mu_p, &
                g_mu(3), tr(2), trn, nv(2), g_nv(3, 2), sf(2), tauf(2), g_tauf(3, 2), &
                slip_norm, slip_dip, tauf_norm, kpos, kts, k_loc(3, 3), sig_loc(3), sig_k(3), &
                w, a_w, g_slip, zeta, theta, slope, wdmg, work, sf_tie(2), tauf_tie(2), &
                slip_tie, d_q(2)
    integer :: i
    logical :: grows, open, closed, flat

    ! The local separation (m . s, e . s, q . s) and the round-off of s_kn: up to it, the plane
    ! is closed for every derivative (SPEC D13: the tie s_kn = 0; a path in the plane's surface
    ! gives s_kn = 0 or a few ulps either side).
    ! (interlock_kinematics' turns: by the azimuth in (t1, t2), then by theta in (n, d))
    call to_local(cp, sp, s(2:3), d_q)
    dip = d_q(1)
    sl(3) = d_q(2)
    call to_local(c, sn, [s(1), dip], sl(1:2))
    tie = 8.0_dp * epsilon(1.0_dp) * (abs(c * s(1)) + abs(sn * dip))
    open = sl(1) > tie

    ! Damage, isotropic in the microplane, from <s_kn>_+ and |s_kt| (interlock_damage).
    pos = max(0.0_dp, sl(1))
    dpos = merge(1.0_dp, 0.0_dp, open)
    beta = old%beta(k)
    gd_n = 0.0_dp
    gd_t = 0.0_dp
    tn = 0.0_dp
    g_dmg = 0.0_dp
    if (mat%use_damage) then
      dmg = old%damage(k)
      tn2 = sl(2) * sl(2) + sl(3) * sl(3)
      if (damage_may_grow(pos * mat%inv_s0n, tn2 * (mat%inv_s0t * mat%inv_s0t), beta)) then
        tn = sqrt(tn2)
        call damage_growth(pos * mat%inv_s0n, tn * mat%inv_s0t, old%beta(k), old%damage(k), &
                           mat%eta, mat%inv_eta, mat%beta_break, mat%inv_s0n, mat%inv_s0t, &
                           beta, dmg, gd_n, gd_t)
      end if
    else
      dmg = mat%d_frozen
    end if
    grows = gd_n > 0.0_dp .or. gd_t > 0.0_dp
    if (grows) then
      g_dmg(1) = gd_n * dpos
      if (tn > 0.0_dp) then
        g_dmg(2) = gd_t * (sl(2) / tn)
        g_dmg(3) = gd_t * (sl(3) / tn)
      end if
    end if

    ! Friction on the damaged part, to |tau_f| = mu p (interlock_friction's radial return);
    ! free on an open plane or without friction.
    mu_p = 0.0_dp
    g_mu = 0.0_dp
    closed = .false.
    if (mat%use_friction) then
      mu_p = -mat%mu_eff * mat%kn * min(sl(1), 0.0_dp)
      closed = .not. open
      if (closed) g_mu(1) = -mat%mu_eff * mat%kn
    end if
    slip_dip = 0.0_dp
    slip_norm = 0.0_dp
    g_tauf = 0.0_dp
    ok = .true.
    trn = 0.0_dp
    if (closed) then
      tr(1) = mat%kt * (sl(2) - old%sf(k))
      tr(2) = mat%kt * (sl(3) - old%sf_strike(k))
      ok = max(abs(tr(1)), abs(tr(2))) < trial_bound
      if (.not. ok) return
      trn = sqrt(tr(1) * tr(1) + tr(2) * tr(2))
    end if
    if (mu_p > 0.0_dp) then
      if (trn <= mu_p) then
        ! stick
        sf(1) = old%sf(k)
        sf(2) = old%sf_strike(k)
        tauf = tr
        tauf_norm = trn
        g_tauf(2, 1) = mat%kt
        g_tauf(3, 2) = mat%kt
      else
        call radial_return(mu_p, g_mu, mat%kt, mat%inv_kt, sl(2:3), tr, trn, nv, g_nv, sf, &
                           tauf, g_tauf, slip_norm)
        tauf_norm = mu_p
        slip_dip = abs(nv(1)) * slip_norm
      end if
    else
      sf = sl(2:3)
      tauf = 0.0_dp
      tauf_norm = 0.0_dp
      slip_dip = abs(sf(1) - old%sf(k))
      ! Closed with mu p = 0 (the tie): the free plane's values, the slide's derivatives d tau_f
      ! = d(mu p) n (SPEC D13); at the cone's apex (tau_tr = 0) a kink where they stay 0.
      if (closed .and. trn > 0.0_dp) &
        call radial_return(mu_p, g_mu, mat%kt, mat%inv_kt, sl(2:3), tr, trn, nv, g_nv, sf_tie, &
                           tauf_tie, g_tauf, slip_tie)
    end if

    ! The traction (eq. 6) and its derivative K_loc: d sigma_kn = K_n (1 - D <s_kn>_+') ds_kn -
    ! K_n <s_kn>_+ dD, d sigma_kt = (1 - D) K_t ds_kt + D d tau_f + (tau_f - K_t s_kt) dD.
    kpos = mat%kn * pos
    sig_loc(1) = normal_traction(mat%kn, sl(1), dmg, kpos)
    k_loc(1, 1) = mat%kn - (dmg * mat%kn) * dpos
    k_loc(1, 2:3) = 0.0_dp
    do i = 1, 2
      kts = mat%kt * sl(1 + i)
      sig_loc(1 + i) = tangential_traction(dmg, kts, tauf(i), .true.)
      k_loc(1 + i, :) = dmg * g_tauf(:, i)
      k_loc(1 + i, 1 + i) = k_loc(1 + i, 1 + i) + (1.0_dp - dmg) * mat%kt
      if (grows) k_loc(1 + i, :) = k_loc(1 + i, :) + (tauf(i) - kts) * g_dmg
    end do
    if (grows) k_loc(1, :) = k_loc(1, :) - kpos * g_dmg

    ! The plane's share: R^T sigma_loc and R^T K_loc R weighted, the area's slope times the
    ! traction at unit area.
    w = gam * area
    ! (a flat plane of a RIA whose azimuths are 0: the local frame is the macro one)
    flat = .not. abs(sn) > 0.0_dp .and. c >= 1.0_dp .and. cp >= 1.0_dp .and. .not. abs(sp) > 0.0_dp
    if (flat) then
      sig_k = sig_loc
    else
      sig_k = macro_vector(cp, sp, c, sn, sig_loc)
    end if
    call add_turned(cp, sp, c, sn, flat, k_loc, .not. grows, w, tangent)
    sigma = sigma + w * sig_k
    if (darea < 0.0_dp) tangent(:, 1) = tangent(:, 1) + (gam * darea) * sig_k

    ! Energies: the frictional work on the damaged part, the damage dissipation Y dD (the
    ! elastic part exact, the friction part at first order), the stored energy (sigma_k . s_k -
    ! D tau_f . sf) / 2.
    wdmg = 0.0_dp
    if (dmg > old%damage(k)) then
      wdmg = mat%decohesion_energy_factor * (min(max(beta, 1.0_dp), mat%beta_break) - &
                                             min(max(old%beta(k), 1.0_dp), mat%beta_break))
      wdmg = wdmg - 0.5_dp * tauf_norm**2 * mat%inv_kt * (dmg - old%damage(k))
    end if
    work = sig_loc(1) * sl(1) + sig_loc(2) * sl(2) + sig_loc(3) * sl(3) - &
           dmg * (tauf(1) * sf(1) + tauf(2) * sf(2))
    energy(1) = energy(1) + w * wdmg
    energy(2) = energy(2) + w * (dmg * tauf_norm * slip_norm)
    energy(3) = energy(3) + w * (0.5_dp * work)

    ! Explicit wear (eq. 25): the frictional work driven by the start state's friction traction,
    ! the angle for the next step (eq. 22) on a plane that wears.
    call wear_weights(mat, scheme_explicit, old%damage(k), old%tauf(k), c, sn, old%s(1), &
                      0.0_dp, a_w, g_slip)
    zeta = old%zeta(k) + (a_w * (dmg * abs(tauf(1)) * slip_dip) + g_slip * slip_dip)
    theta = old%theta(k)
    if (mat%plane_wears(k) .and. zeta > old%zeta(k)) &
      call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), zeta, theta, slope)

    new%beta(k) = beta
    new%damage(k) = dmg
    new%sf(k) = sf(1)
    new%sf_strike(k) = sf(2)
    new%zeta(k) = zeta
    new%theta(k) = theta
    new%tauf(k) = tauf(1)
    new%tauf_strike(k) = tauf(2)
  end subroutine explicit_plane

  !> A local vector v (along m, e, q) in the macro frame (n, t1, t2): R^T v, turned back by
  !> theta in (m, e), then by the azimuth in (d, q).
  pure function macro_vector(cp, sp, c, sn, v) result(u)
    real(dp), intent(in) :: cp, sp, c, sn, v(3)
    real(dp) :: u(3)
    real(dp) :: along_dip
    u(1) = v(1)
    along_dip = v(2)
    call turn(c, sn, u(1), along_dip)
    u(2) = along_dip
    u(3) = v(3)
    call turn(cp, sp, u(2), u(3))
  end function macro_vector

  !> tangent += w R^T K_loc R, R = B A: B turns by theta in the indices (1, 2), A by the azimuth
  !> in (2, 3) (interlock_kinematics' turn of a pair); each turn applied to the columns, then to
  !> the rows, entry by entry in scalars (none for a `flat` plane, whose R is the identity).
  !> `normal_row`: K_loc's normal row is 0 off its diagonal (damage does not grow): the
  !> columns' turn of its zeros left out.
  pure subroutine add_turned(cp, sp, c, sn, flat, k_loc, normal_row, w, tangent)
    real(dp), intent(in) :: cp, sp, c, sn, k_loc(3, 3), w
    logical, intent(in) :: flat, normal_row
    real(dp), intent(inout) :: tangent(3, 3)
    real(dp) :: x(3), y(3), z(3)   ! the columns of K_loc as they turn
    integer :: i
    x = k_loc(:, 1)
    y = k_loc(:, 2)
    z = k_loc(:, 3)
    if (.not. flat) then
      ! columns, then rows, by theta
      call turn(c, sn, x(1), x(2))
      if (normal_row) then
        y(1) = 0.0_dp - sn * y(2)
        z(1) = 0.0_dp - sn * z(2)
        y(2) = c * y(2)
        z(2) = c * z(2)
      else
        call turn(c, sn, y(1), y(2))
        call turn(c, sn, z(1), z(2))
      end if
      do i = 1, 3
        call turn(c, sn, x(i), y(i))
      end do
      if (sp < 0.0_dp .or. sp > 0.0_dp .or. cp < 1.0_dp) then
        ! columns, then rows, by the azimuth
        call turn(cp, sp, x(2), x(3))
        call turn(cp, sp, y(2), y(3))
        call turn(cp, sp, z(2), z(3))
        do i = 1, 3
          call turn(cp, sp, y(i), z(i))
        end do
      end if
    end if
    tangent(:, 1) = tangent(:, 1) + w * x
    tangent(:, 2) = tangent(:, 2) + w * y
    tangent(:, 3) = tangent(:, 3) + w * z
  end subroutine add_turned

  !> (x, y) turned by the angle of (cs, sn) = (cos, sin) in its plane (to_global).
  pure subroutine turn(cs, sn, x, y)
    real(dp), intent(in) :: cs, sn
    real(dp), intent(inout) :: x, y
    real(dp) :: v(2)
    call to_global(cs, sn, [x, y], v)
    x = v(1)
    y = v(2)
  end subroutine turn

end module interlock_kernels_3d
