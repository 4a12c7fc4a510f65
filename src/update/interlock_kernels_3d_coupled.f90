!> The specialised one-step update of a three-dimensional interface in the implicit scheme
!> (SPEC section 9), the fast path of interlock_update_3d for it: each wearing plane's angle
!> coupled to the end of the step by its wear equation zeta - zeta_o = D |tau_f,1| |d sf_1| at
!> theta(zeta), solved as the general path solves it (interlock_wear's safeguarded Newton
!> iteration from the same start, so the same root), the plane's law and traction at the
!> root's angle, and the exact 3x3 tangent: R^T (K_loc + d sig_loc / d theta (x) d theta / d sl)
!> R of each plane times its weight, d theta / d s by implicit differentiation at the root
!> (or along the plane's contact, where the root is pinned at the kink where the plane loses
!> it), and the contact area's d A_g / d s_N term. A plane's law is the explicit kernel's
!> (interlock_kernel_planes_3d.inc, compiled into both kernels), with the derivative of the
!> work that wears. It declines (done false: the caller takes the general path) what the
!> explicit kernel declines and a wear equation without a root (the general path then
!> retries on sub-increments). It agrees with the general path to round-off and shares none of
!> its code; core_kernels3d checks it.
module interlock_kernels_3d_coupled
  use interlock_kinds, only: dp, is_finite_value
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_implicit, &
      max_planes
  use interlock_state, only: interlock_state_3d_t, state_3d_end_point
  use interlock_damage, only: damage_may_grow, damage_growth
  use interlock_friction, only: radial_return, direction_turn_of
  use interlock_geometry, only: contact_area
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  use interlock_plane_law, only: plane_frame, wear_weights, normal_traction, tangential_traction, &
      wear_angle_error, add_wear_error, wear_error_of, start_yield, start_weight
  use interlock_kinematics, only: to_local, to_global
  implicit none
  private
  public :: coupled_step_3d, coupled_step_3d_estimate

  !> A trial friction traction whose components reach this is left to the general path (its
  !> norm is scaled there against overflow of the squares)
  real(dp), parameter :: trial_bound = 1.0e150_dp

contains

  !> The implicit scheme's step of every plane from `old` to s = (s_N, s_T1, s_T2) [mm], with
  !> the wear equations' tolerance and bound on iterations of `solver`: the end state `new`
  !> (traction and energies included; the planes beyond n_planes untouched), the traction
  !> `sigma`, `tangent` = d sigma / d s at the fixed start state, the largest number of Newton
  !> iterations of a plane's wear equation (the general path's report). `done` false: the
  !> kernel declined (`new`, `sigma`, `tangent` partly written), the general path takes the
  !> increment. `limit`: the largest admissible sum of the tangent's magnitudes.
  pure subroutine coupled_step_3d(mat, solver, s, old, limit, new, sigma, tangent, iterations, &
                                  done)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    integer, intent(out) :: iterations
    logical, intent(out) :: done
    real(dp) :: err
    call step_of_planes(mat, solver, s, old, limit, .false., new, sigma, tangent, iterations, &
                        done, err)
  end subroutine coupled_step_3d

  !> coupled_step_3d with the step's embedded error estimate err (the general path's of the
  !> whole increment as one step, interlock_step_3d), for error-controlled substepping: the
  !> increment is kept as one step where err is within the tolerance.
  pure subroutine coupled_step_3d_estimate(mat, solver, s, old, limit, new, sigma, tangent, &
                                           iterations, done, err)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3), err
    integer, intent(out) :: iterations
    logical, intent(out) :: done
    call step_of_planes(mat, solver, s, old, limit, .true., new, sigma, tangent, iterations, &
                        done, err)
  end subroutine coupled_step_3d_estimate

  !> Plane k over the step to s (azimuth frame cp, sp; start angle's frame c_o, sn_o), area
  !> fraction gam, contact area `area` (slope darea): a wearing plane's wear equation F(zeta)
  !> = zeta - zeta_o - G(theta(zeta)), G = D |tau_f,1| |d sf_1|, from Newton's point at zeta_o
  !> (F' there from the start angle's evaluation) by the iteration's points; where the root is
  !> at the kink where the plane just loses contact and the last point is on the open side,
  !> once more at the closed side's last point (the traction's derivative and the angle's from
  !> the same side). One evaluation site of the law (plane_at_angle, with its traction, so
  !> that the last point's is the root's), so that it is inlined once. Adds its weighted
  !> traction, tangent (K_loc with the angle's term d sig_loc / d theta (x) d theta / d sl,
  !> d theta / d sl = theta' dG / d sl / F' at the root; pinned at the contact kink, d theta /
  !> d s = -m / s_kt1) and energies, stores its end state (a plane that does not wear: zeta_o
  !> + G at its angle) in `new`; `iterations`: the wear equation's. `ok` false: declined
  !> (plane_at_angle, or no root). With `estimate` its share of the step's error estimate is
  !> added to err_angle and err_traction (the coupled schemes' angle error,
  !> interlock_plane_law:wear_angle_error, at the root).
  pure subroutine scheme_plane(mat, solver, k, cp, sp, c_o, sn_o, s, old, gam, area, darea, &
                               estimate, sigma, tangent, energy, err_angle, err_traction, new, &
                               iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    real(dp), intent(in) :: cp, sp, c_o, sn_o, s(3), gam, area, darea
    type(interlock_state_3d_t), intent(in) :: old
    logical, intent(in) :: estimate
    real(dp), intent(inout) :: sigma(3), tangent(3, 3), energy(3), err_angle, err_traction
    type(interlock_state_3d_t), intent(inout) :: new
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    type(wear_root_t) :: rt
    real(dp) :: c, sn, sl(3), tie, beta, dmg, sf(2), tauf(2), slip_dip, g_wfric(3), sig_loc(3), &
                k_loc(3, 3), tauf_norm, slip_norm, a_w, g_slip, zeta, theta, thp, fp, drv, &
                g_drv(3), dtheta_sl(3), ksl(3), e
    integer :: phase, j
    logical :: grows, wears, pinned, angle

    iterations = 0
    wears = mat%plane_wears(k)
    ! (the implicit weights: a_w = 1, no start weight)
    call wear_weights(mat, scheme_implicit, old%damage(k), old%tauf(k), c_o, sn_o, old%s(1), &
                      0.0_dp, a_w, g_slip)
    theta = old%theta(k)
    zeta = old%zeta(k)
    c = c_o
    sn = sn_o
    thp = 0.0_dp
    fp = 1.0_dp
    g_wfric = 0.0_dp
    phase = 0
    do
      if (phase > 0) then
        call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), rt%x, theta, &
                        thp)
        call plane_frame(mat, k, theta, c, sn)
      end if
      call plane_at_angle(mat, k, cp, sp, c, sn, s, old, wears, .false., gam, area, darea, &
                          sigma, tangent, energy, sl, tie, beta, dmg, sf, tauf, slip_dip, &
                          g_wfric, sig_loc, k_loc, tauf_norm, slip_norm, grows, ok)
      if (.not. ok) return
      drv = a_w * (dmg * abs(tauf(1)) * slip_dip) + g_slip * slip_dip
      if (.not. wears) exit
      if (phase == 0) thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), old%theta(k))
      g_drv = a_w * g_wfric
      ! F' = 1 - theta' dG / d theta, dG / d theta = g_drv . d sl / d theta
      fp = 1.0_dp - thp * (g_drv(1) * sl(2) - g_drv(2) * sl(1))
      if (phase == 0) then
        ! (no work: the root is zeta_o, the start angle)
        if (.not. drv > 0.0_dp) exit
        call wear_root_begin(rt, old%zeta(k), drv, fp)
        phase = 1
      else if (phase == 1) then
        call wear_root_update(rt, rt%x - old%zeta(k) - drv, fp, solver%newton_tol, &
                              solver%newton_max_iterations)
        if (.not. rt%done) cycle
        iterations = rt%iterations
        ok = rt%ok
        if (.not. ok) return
        if (drv > 0.0_dp .or. abs(tauf(1)) + abs(tauf(2)) > 0.0_dp) exit
        ! the root where the plane just loses contact, the last point on the open side: the
        ! closed side's last point
        rt%x = rt%lo
        phase = 2
      else
        ! (phase 2: the closed side's last point taken)
        exit
      end if
    end do
    ! the angle's term, where the angle moves with s
    angle = .false.
    if (wears) then
      ! A root on a jump of F where the plane loses contact stays there as s moves: the angle
      ! follows the plane's contact, d theta / d s = -m / s_kt1; else d theta = theta' dG / F'
      ! (none where dG = 0: a plane that sticks or is free; a NaN is kept).
      pinned = .false.
      if (phase > 0) then
        zeta = rt%x
        if (rt%at_jump) pinned = abs(sl(2)) > 0.0_dp .and. abs(thp) > 0.0_dp .and. &
                                 .not. abs(sl(1)) > tie
      end if
      if (pinned) then
        dtheta_sl = 0.0_dp
        dtheta_sl(1) = -1.0_dp / sl(2)
        angle = .true.
      else
        angle = .not. abs(g_drv(1)) + abs(g_drv(2)) + abs(g_drv(3)) <= 0.0_dp
        if (angle) dtheta_sl = g_drv * (thp / fp)
      end if
    else
      zeta = old%zeta(k) + drv
    end if
    ! (d sig_loc / d theta at fixed s: the angle's term and the estimate's, at K_loc without
    ! the angle's term)
    if (angle .or. estimate) ksl = traction_angle_slope(sl, sig_loc, k_loc)
    if (angle) then
      do j = 1, 3
        k_loc(:, j) = k_loc(:, j) + ksl * dtheta_sl(j)
      end do
    end if
    call plane_share(cp, sp, c, sn, sig_loc, k_loc, .not. (grows .or. angle), gam, area, darea, &
                     sigma, tangent)
    call plane_energies(mat, k, old, sl, beta, dmg, sf, tauf, tauf_norm, slip_norm, sig_loc, &
                        gam * area, energy)
    if (estimate) then
      e = 0.0_dp
      if (wears) e = coupled_angle_error(mat, k, cp, sp, c_o, sn_o, old, theta, zeta, dmg, &
                                         tauf, slip_dip, slip_norm, sf)
      call add_plane_error(e, gam * area, cp, sp, c, sn, ksl, dmg, tauf_norm, &
                           plane_turn(k, old, tauf, tauf_norm, slip_norm), err_angle, &
                           err_traction)
    end if
    call store_plane(k, beta, dmg, sf, zeta, theta, tauf, new)
  end subroutine scheme_plane

  !> The implicit scheme's angle error of plane k's wear over the step (interlock_plane_law:
  !> wear_angle_error; azimuth frame cp, sp, start angle's frame c_o, sn_o): the work that
  !> wears D |tau_f,1| |d sf_1| and the slip |d sf_1| weighted by the dip share of the slip's
  !> direction (|d sf_1| / |d sf|) at the end angle theta, zeta, against the trapezoidal start
  !> weight D_o mu p_o / 2 of the start state (its yield at the start separation).
  pure real(dp) function coupled_angle_error(mat, k, cp, sp, c_o, sn_o, old, theta, zeta, dmg, &
                                             tauf, slip_dip, slip_norm, sf) result(e)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(in) :: cp, sp, c_o, sn_o, theta, zeta, dmg, tauf(2), slip_dip, &
                            slip_norm, sf(2)
    type(interlock_state_3d_t), intent(in) :: old
    real(dp) :: slip, g_trap, share
    ! (|d sf|: the radial return's slip, or the free plane's |sf - sf_o|)
    slip = slip_norm
    if (.not. slip > 0.0_dp) slip = norm2([sf(1) - old%sf(k), sf(2) - old%sf_strike(k)])
    share = 1.0_dp
    if (slip > 0.0_dp) share = slip_dip / slip
    g_trap = start_weight(old%damage(k), start_yield(mat, c_o, sn_o, old%s(1), &
                                                     cp * old%s(2) + sp * old%s_t2))
    e = wear_angle_error(mat, k, scheme_implicit, theta, old%theta(k), zeta, old%zeta(k), &
                         dmg * abs(tauf(1)) * slip_dip, slip_dip * share, 0.0_dp, g_trap)
  end function coupled_angle_error

  include 'interlock_kernel_planes_3d.inc'

end module interlock_kernels_3d_coupled
