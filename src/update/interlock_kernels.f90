!> Specialised one-step updates, chosen once when the material is prepared, so that a scene
!> pays only for the effects it uses (SPEC section 7; one flat plane without finite depth,
!> the bilinear law and the Alfano-Sacco interface, runs in interlock_integrate itself):
!> without wear the inclinations are constant (sines and cosines computed once, at set-up),
!> one flat plane needs no rotation at all, and the local law is written with scalar
!> derivatives instead of the general path's gradient vectors (which substepping needs). The
!> explicit scheme freezes each angle within the step, so with wear it runs the same kernel
!> with the stored angle's sine and cosine, and one exponential per plane that wore; the
!> implicit scheme adds the scalar wear equation per wearing plane. Each kernel agrees with
!> the general path (interlock_ria) to round-off; a test checks it.
module interlock_kernels
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      scheme_implicit, scheme_trapezoidal, kernel_flat, max_planes
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  use interlock_state, only: interlock_state_t
  use interlock_geometry, only: contact_area
  use interlock_damage, only: damage_growth
  use interlock_friction, only: friction_step
  implicit none
  private
  public :: kernel_step, share_first_plane, start_yield, plane_frame, plane_law_t, plane_law

  !> The law of one microplane in its own frame over one step, with d(traction)/d(s_kn, s_kt).
  type :: plane_law_t
    real(dp) :: beta, dmg, sf, tauf, zeta
    real(dp) :: sig(2), k(2, 2)
    real(dp) :: psi, wdmg, wfric
    !> the wear driver of the coupled schemes, a_end wfric + g_start |sf - sf_o|, and its
    !> derivative d/d(s_kn, s_kt) at fixed start state
    real(dp) :: drv, gdrv(2)
    real(dp) :: slip    !< |sf - sf_o|
  end type plane_law_t

contains

  !> One increment with a specialised kernel. `done` is false when the kernel does not apply
  !> to this increment (a separated RIA, or an implicit wear equation the bounded iteration did
  !> not solve): the caller then takes the general path, which can also sub-increment.
  !> wear_error: the embedded local error estimate of substepping, as interlock_ria:ria_step
  !> computes it (every scheme).
  pure subroutine kernel_step(mat, solver, s, old, new, tangent, done, iterations, wear_error)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(2, 2)
    logical, intent(out) :: done
    integer, intent(out) :: iterations
    real(dp), intent(out), optional :: wear_error
    type(plane_law_t) :: p
    real(dp) :: area, darea, sigma(2), sl(2), c, sn, gam, kg(2, 2), sg(2), theta, slope, &
                dthds(2), dsig_dth(2), err_angle, err_traction, e, a_end, g_slip, wfric, slip, &
                c_o, s_o, c_k(max_planes), sn_k(max_planes)
    integer :: k, scheme, it

    scheme = solver%scheme
    iterations = 0
    err_angle = 0.0_dp
    err_traction = 0.0_dp
    if (present(wear_error)) wear_error = 0.0_dp
    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)
    done = area > 0.0_dp
    if (.not. done) return
    new%diss_damage = old%diss_damage
    new%diss_friction = old%diss_friction
    new%stored = 0.0_dp
    sigma = 0.0_dp
    tangent = 0.0_dp
    if (mat%kernel == kernel_flat) then
      ! Every plane flat: one computed, in the global frame, the others share its history.
      call wear_weights(mat, scheme, 1, 1.0_dp, 0.0_dp, old, a_end, g_slip)
      call fixed_angle_plane(mat, a_end, g_slip, 1, .true., 1.0_dp, 0.0_dp, area, s, old, new, &
                             sigma, tangent)
      if (mat%n_planes > 1) call share_first_plane(mat%n_planes, old, new)
    else
      if (scheme == scheme_explicit) then
        ! The frozen frames first: libm's sincos sets and restores the rounding mode, which
        ! waits for the floating-point work before it, so that the planes' laws after it
        ! overlap (the same values).
        do k = 1, mat%n_planes
          if (mat%plane_wears(k)) call plane_frame(mat, k, old%theta(k), c_k(k), sn_k(k))
        end do
      end if
      do k = 1, mat%n_planes
        if (.not. mat%plane_wears(k)) then
          call wear_weights(mat, scheme, k, mat%cos0(k), mat%sin0(k), old, a_end, g_slip)
          if (flat_plane(mat, k)) then
            call fixed_angle_plane(mat, a_end, g_slip, k, .true., 1.0_dp, 0.0_dp, &
                                   mat%gamma_hat(k) * area, s, old, new, sigma, tangent)
          else
            call fixed_angle_plane(mat, a_end, g_slip, k, .false., mat%cos0(k), mat%sin0(k), &
                                   mat%gamma_hat(k) * area, s, old, new, sigma, tangent)
          end if
        else if (scheme == scheme_explicit) then
          ! Explicit (eq. 25): the angle frozen at its stored value within the step, the wear
          ! driven by the start state's friction traction.
          c = c_k(k)
          sn = sn_k(k)
          g_slip = old%damage(k) * abs(old%tauf(k))
          gam = mat%gamma_hat(k) * area
          if (present(wear_error)) then
            call fixed_angle_plane(mat, 0.0_dp, g_slip, k, .false., c, sn, gam, s, old, new, &
                                   sigma, tangent, wfric, slip, dsig_dth)
          else
            call fixed_angle_plane(mat, 0.0_dp, g_slip, k, .false., c, sn, gam, s, old, new, &
                                   sigma, tangent)
          end if
          ! Explicit wear (eq. 22, 25): the angle for the next step.
          if (new%zeta(k) > old%zeta(k)) then
            call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), new%zeta(k), &
                            theta, slope)
            new%theta(k) = theta
          end if
          if (present(wear_error)) then
            ! (interlock_schemes:plane_step) The traction is taken at the start angle: the error
            ! is first order in the angle increment itself (decision D10), and in the difference
            ! from the backward-Euler increment, which sees wear the start traction does not drive.
            e = max(abs(new%theta(k) - old%theta(k)), min(abs(old%theta(k) - mat%thetaf_eff(k)), &
                    abs(worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), old%theta(k)) * &
                        (wfric - g_slip * slip))))
            err_angle = max(err_angle, e)
            err_traction = max(err_traction, gam * maxval(abs(dsig_dth)) * e)
          end if
        else
          theta = old%theta(k)
          call coupled_wear_plane(mat, solver, k, s, old, p, theta, c, sn, sl, dthds, it, done)
          iterations = max(iterations, it)
          if (.not. done) return
          gam = mat%gamma_hat(k) * area
          ! R^T sigma_loc and R^T K_loc R.
          sg = [c * p%sig(1) - sn * p%sig(2), sn * p%sig(1) + c * p%sig(2)]
          kg(1, 1) = c * (c * p%k(1, 1) - sn * p%k(1, 2)) - sn * (c * p%k(2, 1) - sn * p%k(2, 2))
          kg(1, 2) = c * (sn * p%k(1, 1) + c * p%k(1, 2)) - sn * (sn * p%k(2, 1) + c * p%k(2, 2))
          kg(2, 1) = sn * (c * p%k(1, 1) - sn * p%k(1, 2)) + c * (c * p%k(2, 1) - sn * p%k(2, 2))
          kg(2, 2) = sn * (sn * p%k(1, 1) + c * p%k(1, 2)) + c * (sn * p%k(2, 1) + c * p%k(2, 2))
          ! Implicit wear: theta depends on s through zeta. d sigma_k / d theta =
          ! d(R^T)/d theta sigma_loc + R^T K_loc d s_loc/d theta, d s_loc/d theta = (s_kt, -s_kn).
          dsig_dth = [-sn * p%sig(1) - c * p%sig(2), c * p%sig(1) - sn * p%sig(2)] + &
                     [c * (p%k(1, 1) * sl(2) - p%k(1, 2) * sl(1)) - &
                      sn * (p%k(2, 1) * sl(2) - p%k(2, 2) * sl(1)), &
                      sn * (p%k(1, 1) * sl(2) - p%k(1, 2) * sl(1)) + &
                      c * (p%k(2, 1) * sl(2) - p%k(2, 2) * sl(1))]
          kg(:, 1) = kg(:, 1) + dsig_dth * dthds(1)
          kg(:, 2) = kg(:, 2) + dsig_dth * dthds(2)
          sigma = sigma + gam * sg
          tangent = tangent + gam * kg
          if (present(wear_error) .and. p%zeta > old%zeta(k)) then
            ! (interlock_schemes:plane_step: backward Euler minus trapezoidal, as an angle)
            call plane_frame(mat, k, old%theta(k), c_o, s_o)
            e = abs(theta - old%theta(k)) * abs(0.5_dp * p%wfric - 0.5_dp * old%damage(k) * &
                start_yield(mat, c_o, s_o, old%s) * p%slip) / (p%zeta - old%zeta(k))
            err_angle = max(err_angle, e)
            err_traction = max(err_traction, gam * maxval(abs(dsig_dth)) * e)
          end if
          call store_plane(p, k, gam, theta, new)
        end if
      end do
    end if
    ! d A_g / d s_N times the traction at unit area.
    if (mat%use_depth) tangent(:, 1) = tangent(:, 1) + darea * sigma / area
    new%s = s
    new%sigma = sigma
    new%work = old%work + 0.5_dp * dot_product(old%sigma + sigma, s - old%s)
    if (present(wear_error)) wear_error = max(err_angle, err_traction / &
        (max(mat%sigma0_n, mat%sigma0_t) + maxval(abs(sigma))))
  end subroutine kernel_step

  !> One plane whose angle is fixed within the step (constant, or frozen by the explicit
  !> scheme) with frame (c, sn) and weight w (area fraction x contact area): the law of
  !> plane_law written out with scalar derivatives and no intermediate record, its traction and
  !> tangent rotated to the global frame and added (R^T sigma_k w, R^T K_k R w), its end state
  !> into `new` (angle unchanged) and its share of the energies. The plane that most scenes
  !> are made of, so it is written for the fewest operations. The damage and friction blocks
  !> stand here, in plane_law and in the flat-plane laws of interlock_integrate on purpose:
  !> gfortran -O2 does not inline a procedure of their size that is called from several
  !> places, and calls in these paths cost much of an update (interlock-bench, with the damage
  !> growth and this plane as calls from the flat-plane laws: damage only 7.9 -> 9.2 ns,
  !> damage + friction 10.5 -> 19 ns). core_kernels holds all of them to the general path.
  pure subroutine fixed_angle_plane(mat, a_end, g_slip, k, flat, c, sn, w, s, old, new, sigma, &
                                    tangent, wfric_out, slip_out, dsig_dtheta)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: a_end, g_slip   !< the wear driver a_end D |tau_f| |d sf| + g_slip |d sf|
    integer, intent(in) :: k
    !> c = 1 and sn = 0 exactly (a flat plane: the paper's middle plane, every plane of a flat
    !> RIA): its frame is the global one, no rotation (the same values)
    logical, intent(in) :: flat
    real(dp), intent(in) :: c, sn, w, s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(inout) :: sigma(2), tangent(2, 2)
    !> (substepping's error estimate) the plane's frictional work D |tau_f| |d sf|, its slip
    !> |d sf| and d sigma_k / d theta at fixed s in the global frame, unweighted
    real(dp), intent(out), optional :: wfric_out, slip_out, dsig_dtheta(2)
    real(dp) :: sl1, sl2, pos, beta, d, gd1, gd2, mu_p, slip_sign, sf, &
                tauf, dtauf1, dtauf2, slip, kpos, kts, ls1, ls2, k11, k12, k21, k22, t11, t12, &
                t21, t22, wc, ws, wfric, wdmg

    if (flat) then
      sl1 = s(1)
      sl2 = s(2)
    else
      sl1 = c * s(1) + sn * s(2)
      sl2 = -sn * s(1) + c * s(2)
    end if
    ! Damage (interlock_damage), divisions only while it grows.
    pos = max(0.0_dp, sl1)
    beta = old%beta(k)
    d = old%damage(k)
    gd1 = 0.0_dp
    gd2 = 0.0_dp
    if (mat%use_damage) call damage_growth(pos * mat%inv_s0n, sl2 * mat%inv_s0t, old%beta(k), &
      old%damage(k), mat%eta, mat%inv_eta, mat%beta_break, mat%inv_s0n, mat%inv_s0t, beta, d, &
      gd1, gd2)
    ! Friction return (interlock_friction).
    mu_p = 0.0_dp
    if (mat%use_friction) mu_p = -mat%mu_eff * mat%kn * min(0.0_dp, sl1)
    call friction_step(mu_p, mat%mu_eff * mat%kn, mat%kt, mat%inv_kt, sl2, old%sf(k), sf, tauf, &
                       dtauf1, dtauf2, slip, slip_sign)
    ! Traction and tangent in the plane's frame (interlock_microplane).
    kpos = mat%kn * pos
    kts = mat%kt * sl2
    ls1 = mat%kn * sl1 - d * kpos
    ls2 = (1.0_dp - d) * kts + d * tauf
    if (sl1 > 0.0_dp) then
      k11 = (1.0_dp - d) * mat%kn - kpos * gd1
    else
      k11 = mat%kn
    end if
    k12 = -kpos * gd2
    k21 = d * dtauf1 + (tauf - kts) * gd1
    k22 = (1.0_dp - d) * mat%kt + d * dtauf2 + (tauf - kts) * gd2
    ! To the global frame, weighted: w R^T sigma_k and w R^T (K_k R).
    if (flat) then
      sigma(1) = sigma(1) + w * ls1
      sigma(2) = sigma(2) + w * ls2
      tangent(1, 1) = tangent(1, 1) + w * k11
      tangent(1, 2) = tangent(1, 2) + w * k12
      tangent(2, 1) = tangent(2, 1) + w * k21
      tangent(2, 2) = tangent(2, 2) + w * k22
    else
      wc = w * c
      ws = w * sn
      sigma(1) = sigma(1) + (wc * ls1 - ws * ls2)
      sigma(2) = sigma(2) + (ws * ls1 + wc * ls2)
      t11 = k11 * c - k12 * sn
      t12 = k11 * sn + k12 * c
      t21 = k21 * c - k22 * sn
      t22 = k21 * sn + k22 * c
      tangent(1, 1) = tangent(1, 1) + (wc * t11 - ws * t21)
      tangent(1, 2) = tangent(1, 2) + (wc * t12 - ws * t22)
      tangent(2, 1) = tangent(2, 1) + (ws * t11 + wc * t21)
      tangent(2, 2) = tangent(2, 2) + (ws * t12 + wc * t22)
    end if
    ! Frictional work (decision D4), the wear driver of each scheme, the energies (the
    ! decohesion part of Y dD exactly, interlock_damage:damage_dissipation_increment).
    wfric = d * abs(tauf) * slip
    new%zeta(k) = old%zeta(k) + (a_end * wfric + g_slip * slip)
    wdmg = 0.0_dp
    if (d > old%damage(k)) wdmg = mat%decohesion_energy_factor * &
        (min(max(beta, 1.0_dp), mat%beta_break) - min(max(old%beta(k), 1.0_dp), mat%beta_break)) &
        - 0.5_dp * tauf**2 * mat%inv_kt * (d - old%damage(k))
    new%diss_damage = new%diss_damage + w * wdmg
    new%diss_friction = new%diss_friction + w * wfric
    ! psi = (1 - D) psi_e + D psi_f = (sigma_k . s_k - D tau_f sf) / 2.
    new%stored = new%stored + w * 0.5_dp * (ls1 * sl1 + ls2 * sl2 - d * tauf * sf)
    new%beta(k) = beta
    new%damage(k) = d
    new%sf(k) = sf
    new%theta(k) = old%theta(k)
    new%tauf(k) = tauf
    if (present(wfric_out)) wfric_out = wfric
    if (present(slip_out)) slip_out = slip
    if (present(dsig_dtheta)) then
      ! d(R^T)/d theta sigma_k + R^T K_k d s_k/d theta, d s_k/d theta = (s_kt, -s_kn)
      t11 = k11 * sl2 - k12 * sl1
      t21 = k21 * sl2 - k22 * sl1
      dsig_dtheta = [-sn * ls1 - c * ls2 + (c * t11 - sn * t21), &
                     c * ls1 - sn * ls2 + (sn * t11 + c * t21)]
    end if
  end subroutine fixed_angle_plane

  !> A wearing plane with a scheme that couples the angle to the end of the step (interlock_wear:
  !> the wear equation zeta = zeta_o + G(theta(zeta)) of the implicit or the trapezoidal scheme,
  !> solved by the safeguarded Newton iteration), in its own frame at the root's angle, and
  !> d theta / d s by implicit differentiation: d zeta/d s = (grad G . R) / F'.
  pure subroutine coupled_wear_plane(mat, solver, k, s, old, p, theta, c, sn, sl, dthds, &
                                     iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(plane_law_t), intent(out) :: p
    real(dp), intent(inout) :: theta
    real(dp), intent(out) :: c, sn, sl(2), dthds(2)
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    type(wear_root_t) :: rt
    real(dp) :: thp, fp, a_end, g_start
    ! The driver G = a_end D |tau_f| |d sf| + g_start |d sf| (interlock_schemes:plane_step).
    ! At zeta_o the angle is the stored one: no exponential (and no cosine and sine while
    ! the plane is unworn).
    call plane_frame(mat, k, theta, c, sn)
    a_end = 1.0_dp
    g_start = 0.0_dp
    if (solver%scheme == scheme_trapezoidal) then
      a_end = 0.5_dp
      g_start = 0.5_dp * old%damage(k) * start_yield(mat, c, sn, old%s)
    end if
    thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta)
    call wear_evaluate(mat, k, s, old, a_end, g_start, c, sn, thp, p, sl, fp)
    iterations = 0
    ok = .true.
    if (p%drv > 0.0_dp) then
      call wear_root_begin(rt, old%zeta(k), p%drv)
      do
        call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), rt%x, theta, thp)
        c = cos(theta)
        sn = sin(theta)
        call wear_evaluate(mat, k, s, old, a_end, g_start, c, sn, thp, p, sl, fp)
        call wear_root_update(rt, rt%x - old%zeta(k) - p%drv, fp, solver%newton_tol, &
                              solver%newton_max_iterations)
        if (rt%done) exit
      end do
      iterations = rt%iterations
      ok = rt%ok
      p%zeta = rt%x
    end if
    dthds = thp * [p%gdrv(1) * c - p%gdrv(2) * sn, p%gdrv(1) * sn + p%gdrv(2) * c] / fp
  end subroutine coupled_wear_plane

  !> The plane at the angle of frame (c, sn) = (cos theta, sin theta), slope thp = d theta /
  !> d zeta, and F' = 1 - thp dG/d theta of its wear equation, dG/d theta = grad G . (s_kt,
  !> -s_kn).
  pure subroutine wear_evaluate(mat, k, s, old, a_end, g_start, c, sn, thp, p, sl, fp)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(in) :: s(2), a_end, g_start, c, sn, thp
    type(interlock_state_t), intent(in) :: old
    type(plane_law_t), intent(out) :: p
    real(dp), intent(out) :: sl(2), fp
    sl = [c * s(1) + sn * s(2), -sn * s(1) + c * s(2)]
    call plane_law(mat, sl, old%beta(k), old%sf(k), old%zeta(k), old%damage(k), a_end, g_start, p)
    fp = 1.0_dp - thp * (p%gdrv(1) * sl(2) - p%gdrv(2) * sl(1))
  end subroutine wear_evaluate

  !> The plane's end-of-step state into `new`, and its share (weight g) of the energies.
  pure subroutine store_plane(p, k, g, theta_old, new)
    type(plane_law_t), intent(in) :: p
    integer, intent(in) :: k
    real(dp), intent(in) :: g, theta_old
    type(interlock_state_t), intent(inout) :: new
    new%beta(k) = p%beta
    new%damage(k) = p%dmg
    new%sf(k) = p%sf
    new%zeta(k) = p%zeta
    new%theta(k) = theta_old
    new%tauf(k) = p%tauf
    new%diss_damage = new%diss_damage + g * p%wdmg
    new%diss_friction = new%diss_friction + g * p%wfric
    new%stored = new%stored + g * p%psi
  end subroutine store_plane

  !> Damage, friction and traction of one plane in its own frame at a trial angle of the
  !> coupled wear equation, with the wear driver a_end D |tau_f| |d sf| + g_start |d sf| and
  !> its gradient.
  pure subroutine plane_law(mat, sl, beta_o, sf_o, zeta_o, dmg_o, a_end, g_start, p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sl(2), beta_o, sf_o, zeta_o, dmg_o, a_end, g_start
    type(plane_law_t), intent(out) :: p
    real(dp) :: gd(2), dtau(2), mu_p, sgn, pos_n, neg_n, slip, &
                dslip(2)

    ! Damage (interlock_damage): beta = max(beta_o, beta_eq), D = (beta - 1)/(eta beta);
    ! divisions only while damage grows (the inverses are the material's).
    p%beta = beta_o
    p%dmg = dmg_o
    gd = 0.0_dp
    if (mat%use_damage) call damage_growth(max(0.0_dp, sl(1)) * mat%inv_s0n, &
      sl(2) * mat%inv_s0t, beta_o, dmg_o, mat%eta, mat%inv_eta, mat%beta_break, mat%inv_s0n, &
      mat%inv_s0t, p%beta, p%dmg, gd(1), gd(2))

    ! Friction (interlock_friction).
    mu_p = 0.0_dp
    if (mat%use_friction) mu_p = -mat%mu_eff * mat%kn * min(0.0_dp, sl(1))
    call friction_step(mu_p, mat%mu_eff * mat%kn, mat%kt, mat%inv_kt, sl(2), sf_o, p%sf, p%tauf, &
                       dtau(1), dtau(2), slip, sgn)
    ! (d slip / d(s_n, s_t): the bound's slope while sliding, the slip's sign; 0 sticking)
    dslip = [0.0_dp, sgn]
    if (mu_p > 0.0_dp .and. abs(sgn) > 0.5_dp) dslip(1) = mat%mu_eff * mat%kn * mat%inv_kt

    ! Traction and its derivative (interlock_microplane).
    pos_n = max(0.0_dp, sl(1))
    neg_n = min(0.0_dp, sl(1))
    p%sig(1) = mat%kn * neg_n + (1.0_dp - p%dmg) * mat%kn * pos_n
    p%sig(2) = (1.0_dp - p%dmg) * mat%kt * sl(2) + p%dmg * p%tauf
    if (sl(1) > 0.0_dp) then
      p%k(1, 1) = (1.0_dp - p%dmg) * mat%kn - mat%kn * pos_n * gd(1)
    else
      p%k(1, 1) = mat%kn
    end if
    p%k(1, 2) = -mat%kn * pos_n * gd(2)
    p%k(2, 1) = p%dmg * dtau(1) + (p%tauf - mat%kt * sl(2)) * gd(1)
    p%k(2, 2) = (1.0_dp - p%dmg) * mat%kt + p%dmg * dtau(2) + (p%tauf - mat%kt * sl(2)) * gd(2)

    ! Frictional work and energies (interlock_schemes): the decohesion part of Y dD exactly
    ! (interlock_damage:damage_dissipation_increment), the friction part at first order.
    p%wfric = p%dmg * abs(p%tauf) * slip
    p%slip = slip
    p%drv = a_end * p%wfric + g_start * slip
    ! grad of D |tau_f| slip; d|tau_f| = sign(tau_f) dtau (tau_f = 0 where it is free)
    p%gdrv = a_end * (abs(p%tauf) * slip * gd + p%dmg * slip * sign(1.0_dp, p%tauf) * dtau + &
                      p%dmg * abs(p%tauf) * dslip) + g_start * dslip
    p%zeta = zeta_o + p%drv
    ! psi = (1 - D) psi_e + D psi_f = (sig . s_k - D tau_f sf) / 2 (sl(2) - sf = tau_f / K_t).
    p%psi = 0.5_dp * (p%sig(1) * sl(1) + p%sig(2) * sl(2) - p%dmg * p%tauf * p%sf)
    p%wdmg = 0.0_dp
    if (p%dmg > dmg_o) p%wdmg = mat%decohesion_energy_factor * &
        (min(max(p%beta, 1.0_dp), mat%beta_break) - min(max(beta_o, 1.0_dp), mat%beta_break)) &
        - 0.5_dp * p%tauf**2 * mat%inv_kt * (p%dmg - dmg_o)
  end subroutine plane_law

  !> The weights of a plane's wear driver zeta - zeta_o = a_end D |tau_f| |d sf| + g_slip |d sf|
  !> in each scheme (interlock_schemes:plane_step): explicit 0 and D_o |tauf_o| (eq. 25),
  !> implicit 1 and 0, trapezoidal 1/2 and D_o mu p_o / 2.
  pure subroutine wear_weights(mat, scheme, k, c, sn, old, a_end, g_slip)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme, k
    real(dp), intent(in) :: c, sn
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(out) :: a_end, g_slip
    if (scheme == scheme_explicit) then
      a_end = 0.0_dp
      g_slip = old%damage(k) * abs(old%tauf(k))
    else if (scheme == scheme_implicit) then
      a_end = 1.0_dp
      g_slip = 0.0_dp
    else
      a_end = 0.5_dp
      g_slip = 0.5_dp * old%damage(k) * start_yield(mat, c, sn, old%s)
    end if
  end subroutine wear_weights

  !> mu p at the start of the step on the plane of frame (c, sn): the friction traction of the
  !> damaged part where the slip of the step begins (|tauf_o| if it slid at the start; if it
  !> stuck, the value at which it starts to slide, to first order), the trapezoidal scheme's
  !> start value of the wear driver; 0 when the start state is separated (decision D7).
  pure real(dp) function start_yield(mat, c, sn, s_o) result(mu_p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: c, sn, s_o(2)
    mu_p = 0.0_dp
    if (s_o(1) * mat%inv_h_n < 1.0_dp) &
      mu_p = mat%mu_eff * mat%kn * max(0.0_dp, -(c * s_o(1) + sn * s_o(2)))
  end function start_yield

  !> cos and sin of plane k at angle theta: while the plane is unworn (theta = theta_0 to the
  !> bit) the material's, computed once with the same functions (the same values), else libm's.
  !> Most planes of an FE model, and every plane while it opens, have not worn. (Also the start
  !> frame of the general path's planes, interlock_schemes:plane_step.)
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

  !> Plane k's constant frame is the global one: sin theta_0 = 0 and cos theta_0 = 1 exactly.
  pure logical function flat_plane(mat, k)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    flat_plane = abs(mat%sin0(k)) <= 0.0_dp .and. mat%cos0(k) >= 1.0_dp
  end function flat_plane

  !> A flat RIA of several planes: planes 2..n take plane 1's history (their angles stay).
  pure subroutine share_first_plane(n, old, new)
    integer, intent(in) :: n
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    integer :: k
    do k = 2, n
      new%beta(k) = new%beta(1)
      new%damage(k) = new%damage(1)
      new%sf(k) = new%sf(1)
      new%zeta(k) = new%zeta(1)
      new%theta(k) = old%theta(k)
      new%tauf(k) = new%tauf(1)
    end do
  end subroutine share_first_plane

end module interlock_kernels
