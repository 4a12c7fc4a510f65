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
  use interlock_damage, only: damage_of_beta, damage_dissipation_increment
  use interlock_microplane, only: local_t, microplane_update
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  use interlock_kernels, only: plane_frame, plane_law_t, plane_law
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
    type(local_t) :: r
    real(dp) :: c, sn, c_start, sn_start, sl(2), dthw(6), gz(6), dsl_dth(2), dz, ddo_db, dtmp, &
                sig_th(2), thp, fp, a_end, a_start, g_start, gdrv(4), dgs(6), gl(2), &
                gsig_n(6), gsig_t(6)
    logical :: coupled

    p%ok = .true.
    p%iterations = 0
    p%wear_error = 0.0_dp
    p%dsig_dtheta = 0.0_dp
    dz = 0.0_dp
    dthw = 0.0_dp
    gz = 0.0_dp
    ! The wear driver of the schemes that couple the angle to the end of the step:
    ! zeta = zeta_o + a_end D |tau_f| |d sf| + g_start |d sf|, g_start = a_start D_o mu p_o
    ! fixed within the step (implicit: a_end = 1, a_start = 0; trapezoidal: 1/2, 1/2).
    coupled = solver%scheme /= scheme_explicit
    ! The frame of the start angle, once (the material's while the plane is unworn): the
    ! trapezoidal start value and the wear equation's first evaluation share it.
    if (mat%plane_wears(k)) then
      call plane_frame(mat, k, theta_o, c_start, sn_start)
    else
      c_start = mat%cos0(k)
      sn_start = mat%sin0(k)
    end if
    a_end = 1.0_dp
    a_start = 0.0_dp
    g_start = 0.0_dp
    dgs = 0.0_dp
    if (solver%scheme == scheme_trapezoidal) then
      a_end = 0.5_dp
      a_start = 0.5_dp
      call trapezoidal_start(mat, k, s_o, so_ratio, beta_o, dmg_o, theta_o, c_start, sn_start, &
                             ncol, g_start, dgs)
    end if
    thp = 0.0_dp
    fp = 1.0_dp
    if (coupled .and. mat%plane_wears(k)) then
      c = c_start
      sn = sn_start
      call solve_wear(mat, solver, k, s, beta_o, sf_o, zeta_o, dmg_o, theta_o, a_end, g_start, &
                      r, p%zeta, p%theta, c, sn, sl, thp, fp, p%iterations, p%ok)
      if (.not. p%ok) return
    else
      p%theta = theta_o
      if (.not. mat%plane_wears(k)) p%theta = mat%theta_init(k)
      c = c_start
      sn = sn_start
      call to_local(c, sn, s, sl)
      call microplane_update(mat, sl, beta_o, sf_o, mat%d_frozen, r)
      if (coupled) then
        p%zeta = zeta_o + (a_end * r%wdrv + g_start * r%slip)
      else
        ! Explicit (eq. 25): theta frozen at its start value, zeta driven by the start traction.
        dz = dmg_o * abs(tauf_o) * r%slip
        p%zeta = zeta_o + dz
        if (mat%plane_wears(k) .and. dz > 0.0_dp) then
          call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), p%zeta, &
                          p%theta, dtmp)
        end if
        if (ncol > 2 .and. mat%plane_wears(k)) then
          dthw(5) = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o)
        end if
      end if
    end if
    if (coupled) then
      ! zeta = zeta_o + G(w, theta(zeta)): implicit differentiation, d zeta/d w = (dG/dw)/F'
      ! (F' = 1 and thp = 0 where the angle is constant).
      gdrv = a_end * r%gwdrv + g_start * r%gslip
      gz(1) = (gdrv(1) * c - gdrv(2) * sn + r%slip * dgs(1)) / fp
      gz(2) = (gdrv(1) * sn + gdrv(2) * c + r%slip * dgs(2)) / fp
      if (ncol > 2) then
        gz(3:4) = gdrv(3:4) + r%slip * dgs(3:4)
        gz(5) = 1.0_dp + r%slip * dgs(5)
        gz(6) = r%slip * dgs(6)
        gz(3:6) = gz(3:6) / fp
      end if
      dthw(1:ncol) = thp * gz(1:ncol)
    end if

    ! dv/dw = P + dv/dtheta (x) dtheta/dw, v = (s_kn, s_kt, beta_o, sf_o), P the rotation in
    ! columns 1:2 and the identity in 3:4: each row of d(.)/dv is chained by chain_row.
    dsl_dth = dlocal_dtheta(sl)

    if (.not. coupled) then
      ! d zeta / d w for the explicit update zeta = zeta_o + D_o |tauf_o| |sf - sf_o|.
      gz = dmg_o * abs(tauf_o) * chain_row(r%gslip, c, sn, dsl_dth, dthw, ncol)
      if (ncol > 2) then
        ddo_db = 0.0_dp
        if (mat%use_damage) call damage_of_beta(mat%eta, mat%beta_break, beta_o, dtmp, ddo_db)
        gz(3) = gz(3) + abs(tauf_o) * r%slip * ddo_db
        gz(5) = gz(5) + 1.0_dp
        gz(6) = gz(6) + dmg_o * r%slip * sign(1.0_dp, tauf_o)
      end if
    end if

    if (estimate .and. mat%plane_wears(k)) then
      if (coupled) then
        ! Backward Euler minus trapezoidal, (D |tau_f| - D_o mu p_o) |d sf| / 2, as an angle
        ! through the secant d theta / d zeta of the step (the tangent vanishes where the plane
        ! wears out within the step).
        if (solver%scheme /= scheme_trapezoidal) call trapezoidal_start(mat, k, s_o, 0.0_dp, &
            beta_o, dmg_o, theta_o, c_start, sn_start, 2, g_start, dgs)
        if (p%zeta > zeta_o) p%wear_error = abs(p%theta - theta_o) * &
            abs(0.5_dp * r%wdrv - g_start * r%slip) / (p%zeta - zeta_o)
      else
        ! Explicit: the traction is taken at the angle of the start, the error is first order
        ! in the angle increment itself (decision D10), and in the difference from the
        ! backward-Euler increment (which sees wear that the start traction does not drive).
        p%wear_error = max(abs(p%theta - theta_o), min(abs(theta_o - mat%thetaf_eff(k)), &
            abs(worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o) * (r%wdrv - dz))))
      end if
    end if

    p%beta = r%beta
    p%dmg = r%dmg
    p%sf = r%sf
    p%tauf = r%tauf
    ! Columns beyond ncol are zero (dthw is).
    p%gq(1, :) = chain_row(r%gbeta, c, sn, dsl_dth, dthw, ncol)
    p%gq(2, :) = chain_row(r%gsf, c, sn, dsl_dth, dthw, ncol)
    p%gq(3, :) = gz
    p%gq(4, :) = chain_row(r%gtauf, c, sn, dsl_dth, dthw, ncol)

    call to_global(c, sn, r%sig, p%sig)
    ! d(R^T)/dtheta sigma_loc
    sig_th = [-sn * r%sig(1) - c * r%sig(2), c * r%sig(1) - sn * r%sig(2)]
    ! R^T (d sigma_loc/d v) (dv/dw) + d(R^T)/dtheta sigma_loc dtheta/dw, row by row (no
    ! temporary on the heap)
    gsig_n = chain_row(r%gsig(1, :), c, sn, dsl_dth, dthw, ncol)
    gsig_t = chain_row(r%gsig(2, :), c, sn, dsl_dth, dthw, ncol)
    p%gsig(1, :) = (c * gsig_n - sn * gsig_t) + sig_th(1) * dthw
    p%gsig(2, :) = (sn * gsig_n + c * gsig_t) + sig_th(2) * dthw
    if (estimate .and. mat%plane_wears(k)) then
      gl = matmul(r%gsig(:, 1:2), dsl_dth)
      p%dsig_dtheta = [c * gl(1) - sn * gl(2), sn * gl(1) + c * gl(2)] + sig_th
    end if

    ! Energies (stored energy of eq. 21 per unit plane area).
    p%psi = 0.5_dp * ((1.0_dp - r%dmg) * (mat%kn * sl(1)**2 + mat%kt * sl(2)**2) + &
                      r%dmg * (mat%kn * min(0.0_dp, sl(1))**2 + r%tauf**2 / mat%kt))
    ! Y dD with Y = c beta^2/2 - tau_f^2/(2 K_t) while damage grows (beta = beta_eq): the
    ! first part integrated exactly, the friction part at first order.
    p%wdmg = 0.0_dp
    if (r%dmg > dmg_o) p%wdmg = damage_dissipation_increment(mat%eta, mat%beta_break, &
        mat%kn * mat%s0n**2, beta_o, r%beta) - 0.5_dp * r%tauf**2 / mat%kt * (r%dmg - dmg_o)
    p%wfric = r%wdrv
  end subroutine plane_step

  !> The trapezoidal scheme's start value of the wear driver, g_start = D_o mu p_o / 2 with p_o
  !> the contact pressure of the start state (interlock_kernels:start_yield: where the slip of
  !> the step begins, |tau_f| = mu p), and its gradient with respect to w (columns 1:2: with
  !> respect to s_o, times so_ratio; theta_o = theta(zeta_o) for a wearing plane, (c, sn) its
  !> frame).
  pure subroutine trapezoidal_start(mat, k, s_o, so_ratio, beta_o, dmg_o, theta_o, c, sn, ncol, &
                                    g, dg)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k, ncol
    real(dp), intent(in) :: s_o(2), so_ratio, beta_o, dmg_o, theta_o, c, sn
    real(dp), intent(out) :: g, dg(6)
    real(dp) :: skn, kmu, d_tmp, dd_db
    dg = 0.0_dp
    skn = c * s_o(1) + sn * s_o(2)
    kmu = mat%mu_eff * mat%kn
    g = 0.0_dp
    if (.not. (s_o(1) * mat%inv_h_n < 1.0_dp .and. skn < 0.0_dp)) return
    g = 0.5_dp * dmg_o * (kmu * max(0.0_dp, -skn))
    dg(1:2) = -0.5_dp * dmg_o * kmu * so_ratio * [c, sn]
    if (ncol > 2) then
      dd_db = 0.0_dp
      if (mat%use_damage) call damage_of_beta(mat%eta, mat%beta_break, beta_o, d_tmp, dd_db)
      dg(3) = 0.5_dp * kmu * max(0.0_dp, -skn) * dd_db
      ! d skn / d theta = s_kt of the start state
      if (mat%plane_wears(k)) dg(5) = -0.5_dp * dmg_o * kmu * (-sn * s_o(1) + c * s_o(2)) * &
          worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o)
    end if
  end subroutine trapezoidal_start

  !> g . dv/dw for a row g = d(.)/dv, v = (s_kn, s_kt, beta_o, sf_o), w = (s_N, s_T, beta_o,
  !> sf_o, zeta_o, tauf_o): dv/dw = P + dv/dtheta (x) dtheta/dw with P the rotation
  !> R = d(s_kn, s_kt)/d(s_N, s_T) = [[c, sn], [-sn, c]] in columns 1:2 and the identity in 3:4
  !> (columns beyond ncol: 0, as dthw's). The products written out: most of the chain of a
  !> sub-increment.
  pure function chain_row(g, c, sn, dsl_dth, dthw, ncol) result(row)
    real(dp), intent(in) :: g(4), c, sn, dsl_dth(2), dthw(6)
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

  !> Coupled wear of one plane: F(zeta) = zeta - zeta_o - G(theta(zeta)) = 0, with the driver
  !> G = a_end D |tau_f| |sf - sf_o| + g_start |sf - sf_o| evaluated at the end of the step
  !> (backward Euler: a_end = 1, g_start = 0; trapezoidal: 1/2 and D_o |tauf_o| / 2).
  !> F(zeta_o) = -G <= 0; the root is bracketed from zeta_o upwards and found by Newton's
  !> method safeguarded by bisection. (c, sn): in, the frame of theta_o; out, of the root. The
  !> iterates need F and F' only: the kernels' scalar plane law (interlock_kernels:plane_law,
  !> the same values to round-off); the law with its gradients (microplane_update), which the
  !> chain needs, is evaluated once, at the root.
  pure subroutine solve_wear(mat, solver, k, s, beta_o, sf_o, zeta_o, dmg_o, theta_o, a_end, &
                             g_start, r, zeta, theta, c, sn, sl, thp, fp, iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    real(dp), intent(in) :: s(2), beta_o, sf_o, zeta_o, dmg_o, theta_o, a_end, g_start
    type(local_t), intent(out) :: r
    real(dp), intent(inout) :: c, sn
    real(dp), intent(out) :: zeta, theta, sl(2), thp, fp
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    type(wear_root_t) :: rt
    real(dp) :: f, dmg

    ok = .true.
    iterations = 0
    ! The damage the general law uses where it does not evolve.
    dmg = merge(dmg_o, mat%d_frozen, mat%use_damage)
    ! At zeta_o: theta = theta_o (stored), no exponential, its frame given.
    theta = theta_o
    thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), theta_o)
    call wear_residual(mat, k, s, beta_o, sf_o, zeta_o, dmg, a_end, g_start, zeta_o, .false., &
                       theta, thp, c, sn, sl, f)
    zeta = zeta_o
    if (-f > 0.0_dp) then
      ! (else no frictional work: zeta stays, F = 0 exactly)
      call wear_root_begin(rt, zeta_o, -f)
      do
        call wear_residual(mat, k, s, beta_o, sf_o, zeta_o, dmg, a_end, g_start, rt%x, .true., &
                           theta, thp, c, sn, sl, f, fp)
        call wear_root_update(rt, f, fp, solver%newton_tol, solver%newton_max_iterations)
        if (rt%done) exit
      end do
      zeta = rt%x
      iterations = rt%iterations
      ok = rt%ok
    end if
    call microplane_update(mat, sl, beta_o, sf_o, mat%d_frozen, r)
    fp = 1.0_dp - thp * dot_product(a_end * r%gwdrv(1:2) + g_start * r%gslip(1:2), &
                                    dlocal_dtheta(sl))
  end subroutine solve_wear

  !> F(z) = z - zeta_o - G(theta(z)) and F'(z) for plane k (theta, its slope and its frame
  !> (c, sn) kept as given when `update_angle` is false: they are the start-of-step values).
  pure subroutine wear_residual(mat, k, s, beta_o, sf_o, zeta_o, dmg_o, a_end, g_start, z, &
                                update_angle, theta, thp, c, sn, sl, f, fp)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(in) :: s(2), beta_o, sf_o, zeta_o, dmg_o, a_end, g_start, z
    logical, intent(in) :: update_angle
    real(dp), intent(inout) :: theta, thp, c, sn
    real(dp), intent(out) :: sl(2), f
    real(dp), intent(out), optional :: fp
    type(plane_law_t) :: q
    if (update_angle) then
      call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), z, theta, thp)
      c = cos(theta)
      sn = sin(theta)
    end if
    call to_local(c, sn, s, sl)
    call plane_law(mat, sl, beta_o, sf_o, zeta_o, dmg_o, a_end, g_start, q)
    f = z - zeta_o - q%drv
    if (present(fp)) fp = 1.0_dp - thp * dot_product(q%gdrv, dlocal_dtheta(sl))
  end subroutine wear_residual

end module interlock_schemes
