!> Integration of one microplane over one step, for each scheme (SPEC section 5): how the
!> inclination is treated within the step and how the frictional work zeta is updated.
!> Results come with exact derivatives with respect to w = (s_N, s_T, beta_old, sf_old,
!> zeta_old, tauf_old); only the first `ncol` columns are computed (2: the tangent alone,
!> 6: also what substepping needs to chain sub-increments).
module interlock_schemes
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      scheme_trapezoidal
  use interlock_kinematics, only: to_local, to_global, dlocal_dtheta
  use interlock_damage, only: damage_of_beta
  use interlock_microplane, only: local_t, microplane_gradients
  use interlock_wear, only: worn_angle, worn_angle_slope
  use interlock_plane_law, only: plane_response_t, plane_law, traction_angle_slope, plane_frame, &
      trapezoidal_weight, wear_weights, coupled_wear, wear_angle_error
  implicit none
  private
  public :: plane_t, plane_step

  !> One plane at the end of the step; q = (beta, sf, zeta, tauf).
  type :: plane_t
    real(dp) :: beta, dmg, sf, zeta, theta, tauf
    real(dp) :: sig(2)             !< the plane's traction in the macro frame [MPa]
    real(dp) :: gsig(2, 6)         !< d sig / d w
    real(dp) :: gq(4, 6)           !< d q / d w
    real(dp) :: psi                !< stored energy density of the plane [N/mm]
    real(dp) :: wdmg               !< energy dissipated by damage in the step [N/mm]
    real(dp) :: wfric              !< frictional work in the step, D |tau_f| |d sf| [N/mm]
    !> |theta_1 - theta_2| [rad] of the first-order (backward-Euler) and the second-order
    !> (trapezoidal) wear increments of the step: the embedded local error estimate of
    !> substepping (computed on request only; 0 for a plane that does not wear)
    real(dp) :: wear_error
    real(dp) :: dsig_dtheta(2)     !< d sig / d theta at fixed s (with wear_error)
    integer  :: iterations         !< Newton iterations of the wear equation
    logical  :: ok
  end type plane_t

contains

  !> s_o: the separation at the start of the step (the trapezoidal scheme's start value of the
  !> wear driver depends on it), so_ratio: d s_o / d s over the ratio by which ria_step scales
  !> the columns d/ds (0 for one step; substepping: start over end fraction of the increment).
  !> estimate: compute p%wear_error and p%dsig_dtheta (substepping's error control).
  pure subroutine plane_step(mat, solver, k, s, s_o, so_ratio, beta_o, sf_o, zeta_o, tauf_o, &
                             dmg_o, theta_o, ncol, estimate, p)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k, ncol
    logical, intent(in) :: estimate
    real(dp), intent(in) :: s(2), s_o(2), so_ratio, beta_o, sf_o, zeta_o, tauf_o, dmg_o, theta_o
    type(plane_t), intent(out) :: p
    type(plane_response_t) :: q
    type(local_t) :: r
    real(dp) :: c, sn, c_start, sn_start, sl(2), dthw(6), gz(6), dsl_dth(2), ddo_db, dtmp, &
                sig_th(2), thp, fp, a_end, g_slip, gdrv(4), dgs(6), gsig_n(6), gsig_t(6), &
                d_law, gdrv_n, gdrv_t
    logical :: coupled

    p%ok = .true.
    p%iterations = 0
    p%wear_error = 0.0_dp
    p%dsig_dtheta = 0.0_dp
    dthw = 0.0_dp
    gz = 0.0_dp
    ! The wear driver zeta - zeta_o = a_end D |tau_f| |d sf| + g_slip |d sf| of the scheme
    ! (interlock_plane_law:wear_weights); the implicit and trapezoidal schemes couple the angle
    ! to the end of the step.
    coupled = solver%scheme /= scheme_explicit
    ! The frame of the start angle, once (the material's while the plane is unworn): the
    ! trapezoidal start value and the wear equation's first evaluation share it.
    if (mat%plane_wears(k)) then
      call plane_frame(mat, k, theta_o, c_start, sn_start)
    else
      c_start = mat%cos0(k)
      sn_start = mat%sin0(k)
    end if
    call wear_weights(mat, solver%scheme, dmg_o, tauf_o, c_start, sn_start, s_o(1), s_o(2), &
                      a_end, g_slip)
    dgs = 0.0_dp
    if (solver%scheme == scheme_trapezoidal) call trapezoidal_start_gradient(mat, k, s_o, &
        so_ratio, beta_o, dmg_o, theta_o, c_start, sn_start, ncol, dgs)
    ! The damage the law takes where it does not evolve: the material's constant one.
    d_law = merge(dmg_o, mat%d_frozen, mat%use_damage)
    thp = 0.0_dp
    fp = 1.0_dp
    c = c_start
    sn = sn_start
    p%theta = theta_o
    if (coupled .and. mat%plane_wears(k)) then
      call coupled_wear(mat, k, s, beta_o, d_law, sf_o, zeta_o, a_end, g_slip, solver%newton_tol, &
                        solver%newton_max_iterations, p%theta, c, sn, q, p%zeta, sl, thp, fp, &
                        gdrv_n, gdrv_t, p%iterations, p%ok)
      if (.not. p%ok) return
    else
      if (.not. mat%plane_wears(k)) p%theta = mat%theta_init(k)
      call to_local(c, sn, s, sl)
      call plane_law(mat, sl(1), sl(2), beta_o, d_law, sf_o, mat%use_friction, q)
      p%zeta = zeta_o + (a_end * q%wfric + g_slip * q%slip)
      if (.not. coupled .and. mat%plane_wears(k)) then
        ! Explicit (eq. 25): theta frozen at its start value within the step; the angle of
        ! the worn zeta for the next.
        if (p%zeta > zeta_o) call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), &
                                             mat%inv_zeta0(k), p%zeta, p%theta, dtmp)
        if (ncol > 2) dthw(5) = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o)
      end if
    end if
    call microplane_gradients(mat, sl, beta_o, q, r)
    if (coupled) then
      ! zeta = zeta_o + G(w, theta(zeta)): implicit differentiation, d zeta/d w = (dG/dw)/F'
      ! (F' = 1 and thp = 0 where the angle is constant).
      gdrv = a_end * r%gwfric + g_slip * r%gslip
      gz(1) = (gdrv(1) * c - gdrv(2) * sn + q%slip * dgs(1)) / fp
      gz(2) = (gdrv(1) * sn + gdrv(2) * c + q%slip * dgs(2)) / fp
      if (ncol > 2) then
        gz(3:4) = gdrv(3:4) + q%slip * dgs(3:4)
        gz(5) = 1.0_dp + q%slip * dgs(5)
        gz(6) = q%slip * dgs(6)
        gz(3:6) = gz(3:6) / fp
      end if
      dthw(1:ncol) = thp * gz(1:ncol)
    end if

    ! dv/dw = P + dv/dtheta (x) dtheta/dw, v = (s_kn, s_kt, beta_o, sf_o), P the rotation in
    ! columns 1:2 and the identity in 3:4: each row of d(.)/dv is chained by chain_row.
    dsl_dth = dlocal_dtheta(sl)

    if (.not. coupled) then
      ! d zeta / d w for the explicit update zeta = zeta_o + D_o |tauf_o| |sf - sf_o|.
      gz = g_slip * chain_row(r%gslip, c, sn, dsl_dth, dthw, ncol)
      if (ncol > 2) then
        ddo_db = 0.0_dp
        if (mat%use_damage) call damage_of_beta(mat%eta, mat%beta_break, beta_o, dtmp, ddo_db)
        gz(3) = gz(3) + abs(tauf_o) * q%slip * ddo_db
        gz(5) = gz(5) + 1.0_dp
        gz(6) = gz(6) + dmg_o * q%slip * sign(1.0_dp, tauf_o)
      end if
    end if

    if (estimate .and. mat%plane_wears(k)) then
      p%wear_error = wear_angle_error(mat, k, solver%scheme, p%theta, theta_o, p%zeta, zeta_o, &
                                      q%wfric, q%slip, g_slip, trapezoidal_weight(mat, dmg_o, &
                                      c_start, sn_start, s_o(1), s_o(2)))
      p%dsig_dtheta = traction_angle_slope(q, c, sn, sl)
    end if

    p%beta = q%beta
    p%dmg = q%dmg
    p%sf = q%sf
    p%tauf = q%tauf
    ! Columns beyond ncol are zero (dthw is).
    p%gq(1, :) = chain_row(r%gbeta, c, sn, dsl_dth, dthw, ncol)
    p%gq(2, :) = chain_row(r%gsf, c, sn, dsl_dth, dthw, ncol)
    p%gq(3, :) = gz
    p%gq(4, :) = chain_row(r%gtauf, c, sn, dsl_dth, dthw, ncol)

    call to_global(c, sn, [q%sig_n, q%sig_t], p%sig)
    ! d(R^T)/dtheta sigma_loc
    sig_th = [-sn * q%sig_n - c * q%sig_t, c * q%sig_n - sn * q%sig_t]
    ! R^T (d sigma_loc/d v) (dv/dw) + d(R^T)/dtheta sigma_loc dtheta/dw, row by row (no
    ! temporary on the heap)
    gsig_n = chain_row(r%gsig(1, :), c, sn, dsl_dth, dthw, ncol)
    gsig_t = chain_row(r%gsig(2, :), c, sn, dsl_dth, dthw, ncol)
    p%gsig(1, :) = (c * gsig_n - sn * gsig_t) + sig_th(1) * dthw
    p%gsig(2, :) = (sn * gsig_n + c * gsig_t) + sig_th(2) * dthw

    p%psi = q%psi
    p%wdmg = q%wdmg
    p%wfric = q%wfric
  end subroutine plane_step

  !> The gradient with respect to w of the trapezoidal scheme's start weight g = D_o mu p_o / 2
  !> (interlock_plane_law:trapezoidal_weight; p_o the contact pressure of the start state):
  !> columns 1:2 with respect to s_o, times so_ratio; theta_o = theta(zeta_o) for a wearing
  !> plane, (c, sn) its frame.
  pure subroutine trapezoidal_start_gradient(mat, k, s_o, so_ratio, beta_o, dmg_o, theta_o, c, &
                                             sn, ncol, dg)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k, ncol
    real(dp), intent(in) :: s_o(2), so_ratio, beta_o, dmg_o, theta_o, c, sn
    real(dp), intent(out) :: dg(6)
    real(dp) :: skn, kmu, d_tmp, dd_db
    dg = 0.0_dp
    skn = c * s_o(1) + sn * s_o(2)
    ! (at s_kn = 0 exactly the closed side's derivative, SPEC D13)
    if (.not. (s_o(1) * mat%inv_h_n < 1.0_dp .and. .not. skn > 0.0_dp)) return
    kmu = mat%mu_eff * mat%kn
    dg(1:2) = -0.5_dp * dmg_o * kmu * so_ratio * [c, sn]
    if (ncol > 2) then
      dd_db = 0.0_dp
      if (mat%use_damage) call damage_of_beta(mat%eta, mat%beta_break, beta_o, d_tmp, dd_db)
      dg(3) = 0.5_dp * kmu * max(0.0_dp, -skn) * dd_db
      ! d skn / d theta = s_kt of the start state
      if (mat%plane_wears(k)) dg(5) = -0.5_dp * dmg_o * kmu * (-sn * s_o(1) + c * s_o(2)) * &
          worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o)
    end if
  end subroutine trapezoidal_start_gradient

  !> g . dv/dw for a row g = d(.)/dv, v = (s_kn, s_kt, beta_o, sf_o), w = (s_N, s_T, beta_o,
  !> sf_o, zeta_o, tauf_o): dv/dw = P + dv/dtheta (x) dtheta/dw with P the rotation
  !> R = d(s_kn, s_kt)/d(s_N, s_T) = [[c, sn], [-sn, c]] in columns 1:2 and the identity in 3:4
  !> (columns beyond ncol: 0, as dthw's). The products written out: most of the chain of a
  !> sub-increment.
  pure function chain_row(g, c, sn, dsl_dth, dthw, ncol) result(row)
    real(dp), intent(in) :: g(:), c, sn, dsl_dth(2), dthw(6)   !< g(1:4); any stride (no copy of a row)
    integer, intent(in) :: ncol
    real(dp) :: row(6)
    row = (g(1) * dsl_dth(1) + g(2) * dsl_dth(2)) * dthw
    row(1) = row(1) + (g(1) * c - g(2) * sn)
    row(2) = row(2) + (g(1) * sn + g(2) * c)
    if (ncol > 2) then
      row(3) = row(3) + g(3)
      row(4) = row(4) + g(4)
    end if
  end function chain_row

end module interlock_schemes
