!> The law of one microplane of a 2D interface over one step, for the 2D fast paths: the
!> flat-plane laws of the front (interlock_integrate) and the specialised kernels
!> (interlock_kernels); the general path, 2D and 3D, has the 3D plane law
!> (interlock_plane_law_3d), which calls this module's mechanism pieces. In the plane's
!> frame: damage (eq. 9-11, interlock_damage), Coulomb friction on the damaged part (eq. 7,
!> interlock_friction), the traction of eq. 6 (normal_traction, tangential_traction: also the
!> 3D law's) and its exact 2x2 tangent, the frictional work, the damage dissipation and the
!> stored energy (eq. 21); the wear driver of each scheme (eq. 22-25, decisions D4, D11), the
!> coupled wear equation of the implicit and trapezoidal schemes and the embedded error
!> estimate of substepping. Small scalar procedures: with link-time optimisation they are
!> inlined into each caller (src/CMakeLists.txt), where what a caller does not use is dropped.
module interlock_plane_law
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, scheme_explicit, scheme_implicit
  use interlock_damage, only: damage_growth
  use interlock_friction, only: friction_step
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  implicit none
  private
  public :: plane_response_t, plane_law, add_rotated, traction_angle_slope, plane_frame
  public :: start_yield, trapezoidal_weight, start_weight, trapezoidal_end_weight, wear_weights
  public :: wear_driver, coupled_wear
  public :: wear_angle_error, add_wear_error, wear_error_of
  public :: normal_traction, tangential_traction

  !> The trapezoidal scheme's weight a_end of the end work D |tau_f| |d sf| (D11, wear_weights)
  real(dp), parameter :: trapezoidal_end_weight = 0.5_dp

  !> One plane over one step, in its own frame, from its start state (beta_o, D_o, sf_o) to the
  !> local separation (s_kn, s_kt). Derivatives are with respect to (s_kn, s_kt) at fixed start
  !> state. Scalars only, so that an inlined call keeps them in registers.
  type :: plane_response_t
    real(dp) :: beta, dmg, sf, tauf   !< the end state: beta, D, the slip sf, tau_f [-, -, mm, MPa]
    real(dp) :: sig_n, sig_t          !< the local traction (eq. 6) [MPa]
    real(dp) :: k_nn, k_nt, k_tn, k_tt   !< d(sig_n, sig_t) / d(s_kn, s_kt) [MPa/mm]
    real(dp) :: gd_n, gd_t            !< dD / d(s_kn, s_kt)
    real(dp) :: dtauf_n, dtauf_t      !< d tau_f / d(s_kn, s_kt)
    real(dp) :: slip                  !< |sf - sf_o| [mm]
    real(dp) :: dslip_t               !< d|sf - sf_o| / d s_kt: the slip's sign (0 sticking)
    real(dp) :: wfric   !< frictional work on the damaged part, D |tau_f| |sf - sf_o| [N/mm]
    real(dp) :: wdmg    !< energy dissipated by damage in the step [N/mm]
    real(dp) :: psi     !< stored energy at the end of the step [N/mm]
  end type plane_response_t

contains

  !> The plane's law (SPEC 4.3-4.6). `friction`: the friction return runs (the material's
  !> use_friction; a caller that knows it is off passes .false.: without friction tau_f = 0
  !> and the damaged part follows the separation freely). d_o is the damage where the damage
  !> law does not run.
  elemental subroutine plane_law(mat, sl_n, sl_t, beta_o, d_o, sf_o, friction, p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sl_n, sl_t, beta_o, d_o, sf_o
    logical, intent(in) :: friction
    type(plane_response_t), intent(out) :: p
    real(dp) :: pos, mu_p, kpos, kts, tk, work

    ! Damage (interlock_damage): beta = max(beta_o, beta_eq), D = (beta - 1)/(eta beta),
    ! divisions only while it grows.
    pos = max(0.0_dp, sl_n)
    p%beta = beta_o
    p%dmg = d_o
    p%gd_n = 0.0_dp
    p%gd_t = 0.0_dp
    if (mat%use_damage) call damage_growth(pos * mat%inv_s0n, sl_t * mat%inv_s0t, beta_o, d_o, &
      mat%eta, mat%inv_eta, mat%beta_break, mat%inv_s0n, mat%inv_s0t, p%beta, p%dmg, p%gd_n, &
      p%gd_t)

    ! Friction on the damaged part (interlock_friction): elastic predictor, return to
    ! |tau_f| = mu p with the contact pressure p = K_n <-s_kn>_+.
    mu_p = 0.0_dp
    if (friction) mu_p = -mat%mu_eff * mat%kn * min(0.0_dp, sl_n)
    call friction_step(mu_p, mat%mu_eff * mat%kn, friction .and. .not. sl_n > 0.0_dp, mat%kt, &
                       mat%inv_kt, sl_t, sf_o, p%sf, p%tauf, p%dtauf_n, p%dtauf_t, p%slip, &
                       p%dslip_t)

    ! The traction (eq. 6): sigma_kn = K_n s_kn - D K_n <s_kn>_+,
    ! sigma_kt = (1 - D) K_t s_kt + D tau_f, and its derivative; tk = tau_f - K_t s_kt is
    ! d sigma_kt / d D. (Without friction tau_f = 0: its terms are left out, not added as zeros,
    ! which the compiler could not drop.)
    kpos = mat%kn * pos
    kts = mat%kt * sl_t
    p%sig_n = normal_traction(mat%kn, sl_n, p%dmg, kpos)
    if (sl_n > 0.0_dp) then
      p%k_nn = (1.0_dp - p%dmg) * mat%kn - kpos * p%gd_n
    else
      p%k_nn = mat%kn
    end if
    p%k_nt = -kpos * p%gd_t
    if (friction) then
      tk = p%tauf - kts
    else
      tk = -kts
    end if
    p%sig_t = tangential_traction(p%dmg, kts, p%tauf, friction)
    p%k_tn = tk * p%gd_n
    p%k_tt = (1.0_dp - p%dmg) * mat%kt
    if (friction) then
      p%k_tn = p%dmg * p%dtauf_n + p%k_tn
      p%k_tt = p%k_tt + p%dmg * p%dtauf_t
    end if
    p%k_tt = p%k_tt + tk * p%gd_t

    ! Energies. The frictional work on the damaged part drives wear (decision D4). The damage
    ! dissipation is Y dD with Y = c beta^2 / 2 - tau_f^2 / (2 K_t) while D grows (beta =
    ! beta_eq, c = K_n s_0n^2 = K_t s_0t^2): the first part integrated exactly, c (beta -
    ! beta_o) / (2 eta) over the range where D grows, whatever the step size; the friction part
    ! at first order. Stored: psi = (1 - D) psi_e + D psi_f = (sigma_k . s_k - D tau_f sf) / 2
    ! (s_kt - sf = tau_f / K_t).
    p%wfric = 0.0_dp
    if (friction) p%wfric = p%dmg * abs(p%tauf) * p%slip
    p%wdmg = 0.0_dp
    if (p%dmg > d_o) then
      p%wdmg = mat%decohesion_energy_factor * (min(max(p%beta, 1.0_dp), mat%beta_break) - &
                                               min(max(beta_o, 1.0_dp), mat%beta_break))
      if (friction) p%wdmg = p%wdmg - 0.5_dp * p%tauf**2 * mat%inv_kt * (p%dmg - d_o)
    end if
    work = p%sig_n * sl_n + p%sig_t * sl_t
    if (friction) work = work - p%dmg * p%tauf * p%sf
    p%psi = 0.5_dp * work
  end subroutine plane_law

  !> The traction of eq. 6 normal to a plane, sigma_kn = K_n s_kn - D K_n <s_kn>_+: the bond
  !> carries tension in the undamaged part only, contact carries compression in full. kn_pos =
  !> K_n <s_kn>_+, which the caller's tangent uses too.
  elemental real(dp) function normal_traction(kn, sl_n, dmg, kn_pos) result(sig)
    real(dp), intent(in) :: kn, sl_n, dmg, kn_pos
    sig = kn * sl_n - dmg * kn_pos
  end function normal_traction

  !> The traction of eq. 6 along a plane (one component of its tangential vector in 3D),
  !> sigma_kt = (1 - D) K_t s_kt + D tau_f: the undamaged part elastic, the damaged one
  !> carrying the friction traction; kt_sl = K_t s_kt. `friction` false: tau_f = 0, its term
  !> left out (not added as a zero, which the compiler could not drop).
  elemental real(dp) function tangential_traction(dmg, kt_sl, tauf, friction) result(sig)
    real(dp), intent(in) :: dmg, kt_sl, tauf
    logical, intent(in) :: friction
    sig = (1.0_dp - dmg) * kt_sl
    if (friction) sig = sig + dmg * tauf
  end function tangential_traction

  !> mu p at the start of the step on the plane of frame (c, sn) = (cos theta_o, sin theta_o),
  !> s_o the start separation: the friction traction of the damaged part where the slip of the
  !> step begins (|tauf_o| if it slid at the start; if it stuck, the value at which it starts
  !> to slide, to first order); 0 when the start state is separated (decision D7).
  elemental real(dp) function start_yield(mat, c, sn, s_o_n, s_o_t) result(mu_p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: c, sn, s_o_n, s_o_t
    mu_p = 0.0_dp
    if (s_o_n * mat%inv_h_n < 1.0_dp) &
      mu_p = mat%mu_eff * mat%kn * max(0.0_dp, -(c * s_o_n + sn * s_o_t))
  end function start_yield

  !> The weights of the plane's wear driver in each scheme (SPEC section 5):
  !> zeta - zeta_o = a_end D |tau_f| |d sf| + g_slip |d sf|, with D |tau_f| at the end of the
  !> step and g_slip fixed by the start state: explicit (eq. 25) 0 and D_o |tauf_o|; implicit
  !> (backward Euler) 1 and 0; trapezoidal (D11) 1/2 and D_o mu p_o / 2 (start_yield for the
  !> plane of frame (c, sn) and the start separation s_o).
  elemental subroutine wear_weights(mat, scheme, d_o, tauf_o, c, sn, s_o_n, s_o_t, a_end, g_slip)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme
    real(dp), intent(in) :: d_o, tauf_o, c, sn, s_o_n, s_o_t
    real(dp), intent(out) :: a_end, g_slip
    if (scheme == scheme_explicit) then
      a_end = 0.0_dp
      g_slip = d_o * abs(tauf_o)
    else if (scheme == scheme_implicit) then
      a_end = 1.0_dp
      g_slip = 0.0_dp
    else
      a_end = trapezoidal_end_weight
      g_slip = trapezoidal_weight(mat, d_o, c, sn, s_o_n, s_o_t)
    end if
  end subroutine wear_weights

  !> The trapezoidal scheme's start weight D_o mu p_o / 2 (start_yield).
  elemental real(dp) function trapezoidal_weight(mat, d_o, c, sn, s_o_n, s_o_t) result(g)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: d_o, c, sn, s_o_n, s_o_t
    g = start_weight(d_o, start_yield(mat, c, sn, s_o_n, s_o_t))
  end function trapezoidal_weight

  !> The trapezoidal start weight D_o mu p_o / 2 of a start yield mu_p = mu p_o (start_yield)
  !> that the caller has already.
  elemental real(dp) function start_weight(d_o, mu_p) result(g)
    real(dp), intent(in) :: d_o, mu_p
    g = 0.5_dp * d_o * mu_p
  end function start_weight

  !> The wear driver G = a_end D |tau_f| |d sf| + g_slip |d sf| of the plane's response p and
  !> its derivative with respect to (s_kn, s_kt) at fixed start state (d|tau_f| = sign(tau_f)
  !> d tau_f; tau_f = 0 where the damaged part is free; d|d sf| / d s_kn = |d tau_f / d s_kn|
  !> / K_t, the bound's slope while sliding, 0 otherwise).
  elemental subroutine wear_driver(mat, p, a_end, g_slip, drv, gdrv_n, gdrv_t)
    type(interlock_material_t), intent(in) :: mat
    type(plane_response_t), intent(in) :: p
    real(dp), intent(in) :: a_end, g_slip
    real(dp), intent(out) :: drv, gdrv_n, gdrv_t
    real(dp) :: atau, sgt, dslip_n
    atau = abs(p%tauf)
    sgt = sign(1.0_dp, p%tauf)
    dslip_n = abs(p%dtauf_n) * mat%inv_kt
    drv = a_end * p%wfric + g_slip * p%slip
    gdrv_n = a_end * (atau * p%slip * p%gd_n + p%dmg * p%slip * sgt * p%dtauf_n + &
                      p%dmg * atau * dslip_n) + g_slip * dslip_n
    gdrv_t = a_end * (atau * p%slip * p%gd_t + p%dmg * p%slip * sgt * p%dtauf_t + &
                      p%dmg * atau * p%dslip_t) + g_slip * p%dslip_t
  end subroutine wear_driver

  !> Add the plane's traction and tangent, rotated to the macro frame and weighted by w (area
  !> fraction x contact area): sigma += w R^T sigma_k, tangent += w R^T K_k R, with R =
  !> d(s_kn, s_kt)/d(s_N, s_T) = [[c, sn], [-sn, c]]. `flat`: c = 1 and sn = 0 exactly (the
  !> plane's frame is the macro one; no rotation, the same values).
  pure subroutine add_rotated(p, flat, c, sn, w, sigma, tangent)
    type(plane_response_t), intent(in) :: p
    logical, intent(in) :: flat
    real(dp), intent(in) :: c, sn, w
    real(dp), intent(inout) :: sigma(2), tangent(2, 2)
    real(dp) :: wc, ws, t11, t12, t21, t22
    if (flat) then
      sigma(1) = sigma(1) + w * p%sig_n
      sigma(2) = sigma(2) + w * p%sig_t
      tangent(1, 1) = tangent(1, 1) + w * p%k_nn
      tangent(1, 2) = tangent(1, 2) + w * p%k_nt
      tangent(2, 1) = tangent(2, 1) + w * p%k_tn
      tangent(2, 2) = tangent(2, 2) + w * p%k_tt
    else
      wc = w * c
      ws = w * sn
      sigma(1) = sigma(1) + (wc * p%sig_n - ws * p%sig_t)
      sigma(2) = sigma(2) + (ws * p%sig_n + wc * p%sig_t)
      t11 = p%k_nn * c - p%k_nt * sn
      t12 = p%k_nn * sn + p%k_nt * c
      t21 = p%k_tn * c - p%k_tt * sn
      t22 = p%k_tn * sn + p%k_tt * c
      tangent(1, 1) = tangent(1, 1) + (wc * t11 - ws * t21)
      tangent(1, 2) = tangent(1, 2) + (wc * t12 - ws * t22)
      tangent(2, 1) = tangent(2, 1) + (ws * t11 + wc * t21)
      tangent(2, 2) = tangent(2, 2) + (ws * t12 + wc * t22)
    end if
  end subroutine add_rotated

  !> d sigma / d theta at fixed macro s of the plane's traction in the macro frame, sigma =
  !> R^T sigma_k(R s): d(R^T)/d theta sigma_k + R^T K_k d s_k/d theta, with d s_k / d theta =
  !> (s_kt, -s_kn) (unweighted; (c, sn) the frame, sl the local separation).
  pure function traction_angle_slope(p, c, sn, sl) result(dsig)
    type(plane_response_t), intent(in) :: p
    real(dp), intent(in) :: c, sn, sl(2)
    real(dp) :: dsig(2)
    real(dp) :: t1, t2
    t1 = p%k_nn * sl(2) - p%k_nt * sl(1)
    t2 = p%k_tn * sl(2) - p%k_tt * sl(1)
    dsig(1) = -sn * p%sig_n - c * p%sig_t + (c * t1 - sn * t2)
    dsig(2) = c * p%sig_n - sn * p%sig_t + (sn * t1 + c * t2)
  end function traction_angle_slope

  !> cos and sin of plane k at angle theta: while the plane is unworn (theta = theta_0 to the
  !> bit) the material's, computed once with the same functions (the same values), else libm's.
  !> Most planes of an FE model, and every plane while it opens, have not worn.
  pure subroutine plane_frame(mat, k, theta, c, sn)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(in) :: theta
    real(dp), intent(out) :: c, sn
    if (theta >= mat%theta_init(k) .and. theta <= mat%theta_init(k)) then
      c = mat%cos0(k)
      sn = mat%sin0(k)
    else
      c = cos(theta)
      sn = sin(theta)
    end if
  end subroutine plane_frame

  !> The wear equation of a wearing plane k in a scheme that couples its angle to the end of
  !> the step (implicit, trapezoidal): F(zeta) = zeta - zeta_o - G(theta(zeta)) = 0 with the
  !> driver G of wear_weights (a_end, g_slip) and theta(zeta) of eq. 22, solved by the
  !> safeguarded Newton iteration of interlock_wear (bracketed from zeta_o upwards, so it cannot
  !> diverge). The start state (beta_o, d_o, sf_o, zeta_o) and s: the macro separation at the
  !> end of the step; (c, sn): in, the frame of the start angle theta (inout: the stored
  !> angle), out, the frame of the root's angle. Returns the law at the root (p: zeta in
  !> `zeta`), the local separation sl there, thp = d theta / d zeta and F' = 1 - thp dG/d theta
  !> at the root (dG/d theta = grad G . (s_kt, -s_kn)), and the driver's derivative (gdrv_n,
  !> gdrv_t) with respect to the local separation. `ok` false: the iteration reached a bound.
  pure subroutine coupled_wear(mat, k, s, beta_o, d_o, sf_o, zeta_o, a_end, g_slip, tol, &
                               max_iterations, theta, c, sn, p, zeta, sl, thp, fp, gdrv_n, &
                               gdrv_t, iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k, max_iterations
    real(dp), intent(in) :: s(2), beta_o, d_o, sf_o, zeta_o, a_end, g_slip, tol
    real(dp), intent(inout) :: theta, c, sn
    type(plane_response_t), intent(out) :: p
    real(dp), intent(out) :: zeta, sl(2), thp, fp, gdrv_n, gdrv_t
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    type(wear_root_t) :: rt
    real(dp) :: drv
    ! At zeta_o the angle is the stored one: no exponential (and the frame given).
    thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta)
    call wear_evaluate(mat, s, beta_o, d_o, sf_o, a_end, g_slip, c, sn, thp, p, sl, drv, gdrv_n, &
                       gdrv_t, fp)
    zeta = zeta_o
    iterations = 0
    ok = .true.
    if (drv > 0.0_dp) then
      ! (else no frictional work: zeta stays, F = 0 exactly)
      call wear_root_begin(rt, zeta_o, drv, fp)
      do
        call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), rt%x, theta, thp)
        c = cos(theta)
        sn = sin(theta)
        call wear_evaluate(mat, s, beta_o, d_o, sf_o, a_end, g_slip, c, sn, thp, p, sl, drv, &
                           gdrv_n, gdrv_t, fp)
        call wear_root_update(rt, rt%x - zeta_o - drv, fp, tol, max_iterations)
        if (rt%done) exit
      end do
      zeta = rt%x
      iterations = rt%iterations
      ok = rt%ok
    end if
  end subroutine coupled_wear

  !> One evaluation of coupled_wear's equation: the law at the frame (c, sn) of a trial angle
  !> (slope thp = d theta / d zeta), the driver G and F' = 1 - thp dG/d theta there.
  pure subroutine wear_evaluate(mat, s, beta_o, d_o, sf_o, a_end, g_slip, c, sn, thp, p, sl, &
                                drv, gdrv_n, gdrv_t, fp)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(2), beta_o, d_o, sf_o, a_end, g_slip, c, sn, thp
    type(plane_response_t), intent(out) :: p
    real(dp), intent(out) :: sl(2), drv, gdrv_n, gdrv_t, fp
    sl(1) = c * s(1) + sn * s(2)
    sl(2) = -sn * s(1) + c * s(2)
    call plane_law(mat, sl(1), sl(2), beta_o, d_o, sf_o, mat%use_friction, p)
    call wear_driver(mat, p, a_end, g_slip, drv, gdrv_n, gdrv_t)
    fp = 1.0_dp - thp * (gdrv_n * sl(2) - gdrv_t * sl(1))
  end subroutine wear_evaluate

  !> The embedded local error estimate of a wearing plane's step [rad], for substepping: the
  !> difference between the first-order (backward Euler) and the second-order (trapezoidal)
  !> wear increments as an angle. Coupled schemes: (D |tau_f| - D_o mu p_o) |d sf| / 2 (g_trap
  !> = D_o mu p_o / 2, the trapezoidal start weight) through the step's secant d theta / d zeta
  !> (the tangent vanishes where the plane wears out within the step). Explicit (the angle
  !> frozen at theta_o, g_slip = D_o |tauf_o|): the traction is taken at the start angle, so the
  !> error is first order in the angle increment itself (decision D10), and in the difference
  !> from the backward-Euler increment, which sees wear the start traction does not drive.
  elemental real(dp) function wear_angle_error(mat, k, scheme, theta, theta_o, zeta, zeta_o, &
                                               wfric, slip, g_slip, g_trap) result(e)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k, scheme
    real(dp), intent(in) :: theta, theta_o, zeta, zeta_o, wfric, slip, g_slip, g_trap
    if (scheme == scheme_explicit) then
      e = max(abs(theta - theta_o), min(abs(theta_o - mat%thetaf_eff(k)), &
              abs(worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o) * &
                  (wfric - g_slip * slip))))
    else
      e = 0.0_dp
      if (zeta > zeta_o) e = abs(theta - theta_o) * abs(0.5_dp * wfric - g_trap * slip) / &
                             (zeta - zeta_o)
    end if
  end function wear_angle_error

  !> Accumulate a plane's angle error e and the traction error it causes, w |d sigma_k /
  !> d theta| e (w: the plane's weight, area fraction x contact area).
  pure subroutine add_wear_error(e, w, dsig_dtheta, err_angle, err_traction)
    real(dp), intent(in) :: e, w, dsig_dtheta(2)
    real(dp), intent(inout) :: err_angle, err_traction
    err_angle = max(err_angle, e)
    err_traction = max(err_traction, w * max(abs(dsig_dtheta(1)), abs(dsig_dtheta(2))) * e)
  end subroutine add_wear_error

  !> The step's error estimate: the larger of the angle error [rad] and the traction error
  !> relative to the peak traction plus the current one.
  pure real(dp) function wear_error_of(mat, err_angle, err_traction, sigma) result(err)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: err_angle, err_traction, sigma(2)
    err = max(err_angle, err_traction / (max(mat%sigma0_n, mat%sigma0_t) + &
                                         max(abs(sigma(1)), abs(sigma(2)))))
  end function wear_error_of

end module interlock_plane_law
