!> One step of every plane of a three-dimensional interface (SPEC section 9) in the solver's
!> scheme, in plain reals with the exact 3x3 tangent written out: the plane law
!> (interlock_plane_law_3d) at the angle of the step, the wear equation of the coupled schemes
!> solved by the safeguarded Newton iteration of interlock_wear and differentiated implicitly at
!> its root, the frame's rotation and the angle's derivative chained by hand, the contact area
!> and D7. The whole increment as one step (the update without substepping).
module interlock_step_3d
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      scheme_trapezoidal
  use interlock_state, only: interlock_state_3d_t
  use interlock_geometry, only: contact_area
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  use interlock_plane_law, only: plane_frame
  use interlock_plane_law_3d, only: plane_start_3d_t, plane_law_3d_t, plane_law_3d, &
      start_pressure_3d, local_separation, to_macro
  implicit none
  private
  public :: one_step_3d

contains

  !> The increment from `old` to s as one step: the end state `new` (its traction and energies
  !> included; the planes beyond n_planes untouched), the traction's derivative d sigma / d s
  !> in `tangent`, the largest number of Newton iterations of a wear equation; `ok` false when
  !> a wear equation has no solution (then `new` is partly written).
  pure subroutine one_step_3d(mat, solver, s, old, new, tangent, iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    type(plane_law_3d_t) :: p
    type(plane_start_3d_t) :: o
    real(dp) :: area, darea, gam, w, sig(3), sig_k(3), k_k(3, 3), s_o(3), old_sig(3), zeta, &
                theta
    integer :: k, n_eval, it
    logical :: shared

    ok = .true.
    iterations = 0
    sig = 0.0_dp
    tangent = 0.0_dp
    new%diss_damage = old%diss_damage
    new%diss_friction = old%diss_friction
    new%stored = 0.0_dp
    s_o = [old%s(1), old%s(2), old%s_t2]

    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)

    if (area <= 0.0_dp) then
      ! Separated (decision D7): nothing transmitted, no bond survives, nothing slides.
      do k = 1, mat%n_planes
        new%beta(k) = old%beta(k)
        new%damage(k) = old%damage(k)
        if (mat%use_damage) then
          new%beta(k) = max(old%beta(k), mat%beta_break)
          new%damage(k) = 1.0_dp
        end if
        new%sf(k) = old%sf(k)
        new%sf_strike(k) = old%sf_strike(k)
        new%zeta(k) = old%zeta(k)
        new%theta(k) = old%theta(k)
        new%tauf(k) = 0.0_dp
        new%tauf_strike(k) = 0.0_dp
      end do
    else
      ! Identical flat planes share one history: computed once, copied (SPEC section 7).
      shared = mat%flat .and. mat%azimuths_zero
      n_eval = merge(1, mat%n_planes, shared)
      do k = 1, n_eval
        o = plane_of(old, k)
        call plane_step(mat, mat%cos_phi(k), mat%sin_phi(k), solver, k, s, s_o, o, p, sig_k, &
                        k_k, zeta, theta, it, ok)
        if (.not. ok) return
        iterations = max(iterations, it)
        gam = merge(1.0_dp, mat%gamma_hat(k), shared)
        w = gam * area
        sig = sig + w * sig_k
        tangent = tangent + w * k_k
        tangent(:, 1) = tangent(:, 1) + (gam * darea) * sig_k
        new%diss_damage = new%diss_damage + gam * area * p%wdmg
        new%diss_friction = new%diss_friction + gam * area * p%wfric
        new%stored = new%stored + gam * area * p%psi
        call store_plane(p, zeta, theta, k, new)
      end do
      do k = n_eval + 1, mat%n_planes
        call store_plane(p, zeta, theta, k, new)
      end do
    end if
    old_sig = [old%sigma(1), old%sigma(2), old%sigma_t2]
    new%s = s(1:2)
    new%s_t2 = s(3)
    new%sigma = sig(1:2)
    new%sigma_t2 = sig(3)
    new%work = old%work + 0.5_dp * dot_product(old_sig + sig, s - s_o)
  end subroutine one_step_3d

  !> Plane k of a state.
  pure type(plane_start_3d_t) function plane_of(state, k) result(o)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: k
    o%beta = state%beta(k)
    o%dmg = state%damage(k)
    o%sf = [state%sf(k), state%sf_strike(k)]
    o%zeta = state%zeta(k)
    o%theta = state%theta(k)
    o%tauf = [state%tauf(k), state%tauf_strike(k)]
  end function plane_of

  !> Store plane k's end state (the response p, its frictional work zeta and angle theta).
  pure subroutine store_plane(p, zeta, theta, k, state)
    type(plane_law_3d_t), intent(in) :: p
    real(dp), intent(in) :: zeta, theta
    integer, intent(in) :: k
    type(interlock_state_3d_t), intent(inout) :: state
    state%beta(k) = p%beta
    state%damage(k) = p%dmg
    state%sf(k) = p%sf(1)
    state%sf_strike(k) = p%sf(2)
    state%zeta(k) = zeta
    state%theta(k) = theta
    state%tauf(k) = p%tauf(1)
    state%tauf_strike(k) = p%tauf(2)
  end subroutine store_plane

  !> Plane k over the step in the solver's scheme (SPEC section 9, "Schemes"): the angle frozen
  !> at its start value (explicit) or coupled to the end of the step by the wear equation,
  !> zeta - zeta_o = G(theta(zeta)) with G = a_end D |tau_f,1| |d sf_1| + g_slip |d sf_1|
  !> (explicit, implicit: wear_weights of the 2D law with the dip components) or D11's
  !> trapezoidal rule with D14's terms, solved by the safeguarded Newton iteration of
  !> interlock_wear. Returns the response p at the angle of the traction, the plane's traction
  !> sig_k in the macro frame with its derivative k_k = d sig_k / d s (through the angle:
  !> d sig_k / d theta (x) d theta / d s, by implicit differentiation at the root,
  !> d zeta / d s = (dG / d s) / F', F' = 1 - theta' dG / d theta), and the end values of
  !> zeta and theta.
  pure subroutine plane_step(mat, cp, sp, solver, k, s, s_o, o, p, sig_k, k_k, zeta, theta, &
                             iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp   !< cos and sin of the plane's azimuth
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    real(dp), intent(in) :: s(3), s_o(3)
    type(plane_start_3d_t), intent(in) :: o
    type(plane_law_3d_t), intent(out) :: p
    real(dp), intent(out) :: sig_k(3), k_k(3, 3), zeta, theta
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    type(wear_root_t) :: rt
    real(dp) :: c, sn, c_o, sn_o, mu_p_o, a_end, g_slip, drv, g_drv(3), thp, fp, rot(3, 3), &
                dsig_dtheta(3), dzeta(3)
    logical :: coupled, wears, trapezoidal
    integer :: j

    ok = .true.
    iterations = 0
    coupled = solver%scheme /= scheme_explicit
    trapezoidal = solver%scheme == scheme_trapezoidal
    wears = mat%plane_wears(k)
    ! The trapezoidal start value D_o mu p_o / 2; mu p_o also decides whether the plane slides
    ! at the start (D14's mean-direction rule).
    mu_p_o = 0.0_dp
    if (.not. coupled) then
      a_end = 0.0_dp
      g_slip = o%dmg * abs(o%tauf(1))
    else if (trapezoidal) then
      call plane_frame(mat, k, o%theta, c_o, sn_o)
      mu_p_o = start_pressure_3d(mat, cp, sp, c_o, sn_o, s_o)
      a_end = 0.5_dp
      g_slip = (0.5_dp * o%dmg) * mu_p_o
    else
      a_end = 1.0_dp
      g_slip = 0.0_dp
    end if

    theta = o%theta
    zeta = o%zeta
    call evaluate(mat, k, cp, sp, s, o, mu_p_o, a_end, g_slip, trapezoidal, coupled .and. wears, &
                  theta, c, sn, p, drv, g_drv)
    if (coupled .and. wears) then
      ! F(zeta) = zeta - zeta_o - G(theta(zeta)); at zeta_o the stored angle and its slope, no
      ! exponential.
      thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), o%theta)
      fp = 1.0_dp - thp * angle_slope(g_drv, p%sl)
      if (drv > 0.0_dp) then
        call wear_root_begin(rt, o%zeta, drv)
        do
          call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), rt%x, theta, &
                          thp)
          call evaluate(mat, k, cp, sp, s, o, mu_p_o, a_end, g_slip, trapezoidal, .true., theta, &
                        c, sn, p, drv, g_drv)
          fp = 1.0_dp - thp * angle_slope(g_drv, p%sl)
          call wear_root_update(rt, rt%x - o%zeta - drv, fp, solver%newton_tol, &
                                solver%newton_max_iterations)
          if (rt%done) exit
        end do
        iterations = rt%iterations
        ok = rt%ok
        if (.not. ok) return
        if (.not. drv > 0.0_dp) then
          ! The root is where the plane just loses contact (very fast wear turns it until
          ! then), within round-off of that kink, and the last point is on the open side: take
          ! the closed side's last point, rt%lo (F < 0 there, so some work: the plane is in
          ! contact), a few ulps from the root, so that the angle's derivative and the
          ! traction's come from the same side (mixed, they are neither one-sided derivative).
          rt%x = rt%lo
          call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), rt%x, theta, &
                          thp)
          call evaluate(mat, k, cp, sp, s, o, mu_p_o, a_end, g_slip, trapezoidal, .true., theta, &
                        c, sn, p, drv, g_drv)
          fp = 1.0_dp - thp * angle_slope(g_drv, p%sl)
        end if
        zeta = rt%x
      end if
      call rotated(cp, sp, c, sn, p, sig_k, k_k)
      rot(1, :) = [c, sn * cp, sn * sp]
      rot(2, :) = [-sn, c * cp, c * sp]
      rot(3, :) = [0.0_dp, -sp, cp]
      ! d zeta / d s = (dG / d s) / F' at the root, d theta / d s = theta' d zeta / d s;
      ! d sig_k / d theta at fixed s = sigma_kn e - sigma_kt1 m + R^T K_loc d sl / d theta
      dzeta = matmul(g_drv, rot) * (thp / fp)
      dsig_dtheta = to_macro(cp, sp, c, sn, matmul(p%k_loc, [p%sl(2), -p%sl(1), 0.0_dp])) + &
                    (p%sig_loc(1) * rot(2, :) - p%sig_loc(2) * rot(1, :))
      do j = 1, 3
        k_k(:, j) = k_k(:, j) + dsig_dtheta * dzeta(j)
      end do
    else
      call rotated(cp, sp, c, sn, p, sig_k, k_k)
      zeta = o%zeta + drv
      if (.not. coupled .and. wears) then
        ! explicit (eq. 25): the angle of the worn zeta for the next step
        if (zeta > o%zeta) call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), &
                                           mat%inv_zeta0(k), zeta, theta, thp)
      end if
    end if
  end subroutine plane_step

  !> The plane law at angle theta (its frame c, sn) and the scheme's wear driver G with
  !> d G / d sl: a_end D |tau_f,1| |d sf_1| + g_slip |d sf_1| (explicit, implicit), a_end
  !> wear_end + g_slip wear_start (trapezoidal: the dip component of D_o mu p_o n at the start);
  !> d G / d sl only with `drivers` (else 0).
  pure subroutine evaluate(mat, k, cp, sp, s, o, mu_p_o, a_end, g_slip, trapezoidal, drivers, &
                           theta, c, sn, p, drv, g_drv)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(in) :: cp, sp, s(3), mu_p_o, a_end, g_slip, theta
    type(plane_start_3d_t), intent(in) :: o
    logical, intent(in) :: trapezoidal, drivers
    real(dp), intent(out) :: c, sn, drv, g_drv(3)
    type(plane_law_3d_t), intent(out) :: p
    call plane_frame(mat, k, theta, c, sn)
    call plane_law_3d(mat, local_separation(cp, sp, c, sn, s), o, mu_p_o, drivers, p)
    g_drv = 0.0_dp
    if (trapezoidal) then
      drv = a_end * p%wear_end + g_slip * p%wear_start
      if (drivers) g_drv = a_end * p%g_wear_end + g_slip * p%g_wear_start
    else
      drv = a_end * p%wfric_dip + g_slip * p%slip_dip
      if (drivers) g_drv = a_end * p%g_wfric_dip + g_slip * p%g_slip_dip
    end if
  end subroutine evaluate

  !> dG / d theta at fixed s of a driver with d G / d sl = g_drv: g_drv . d sl / d theta, d sl /
  !> d theta = (s_kt1, -s_kn, 0).
  pure real(dp) function angle_slope(g_drv, sl)
    real(dp), intent(in) :: g_drv(3), sl(3)
    angle_slope = g_drv(1) * sl(2) - g_drv(2) * sl(1)
  end function angle_slope

  !> The plane's traction in the macro frame and its derivative at fixed angle, R^T K_loc R,
  !> with R = d sl / d s (rows m, e, q): each row of K_loc R is R^T times K_loc's row, and each
  !> column of R^T (K_loc R) R^T times that column, both by to_macro.
  pure subroutine rotated(cp, sp, c, sn, p, sig_k, k_k)
    real(dp), intent(in) :: cp, sp, c, sn
    type(plane_law_3d_t), intent(in) :: p
    real(dp), intent(out) :: sig_k(3), k_k(3, 3)
    real(dp) :: a(3, 3)
    integer :: i
    sig_k = to_macro(cp, sp, c, sn, p%sig_loc)
    do i = 1, 3
      a(i, :) = to_macro(cp, sp, c, sn, p%k_loc(i, :))
    end do
    do i = 1, 3
      k_k(:, i) = to_macro(cp, sp, c, sn, a(:, i))
    end do
  end subroutine rotated

end module interlock_step_3d
