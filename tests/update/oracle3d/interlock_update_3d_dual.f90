!> The three-dimensional update in dual numbers (interlock_dual: every value carries its
!> derivatives with respect to the end separation of the increment and, in column 4, to the
!> frictional work of the wear equation being solved), an independent oracle of the library's
!> derivatives: interlock_step_3d writes the tangent and the chain over sub-increments out by
!> hand, this module lets the numbers carry them through the same law
!> (interlock_plane_law_3d_dual). Every scheme, error-controlled substepping with the library's
!> control (interlock_substep_control), D7, the RIA sum; no checks of the input and no route of
!> (n, t1) histories to the 2D update: the tests give it admissible input and compare.
module interlock_update_3d_dual
  use interlock_kinds, only: dp
  use interlock_dual, only: dual_t, n_dual, constant, operator(+), operator(-), operator(*), &
      operator(/), abs, max
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes, &
      scheme_explicit, scheme_trapezoidal
  use interlock_state, only: interlock_state_3d_t
  use interlock_status, only: interlock_info_t, status_ok, status_local_failure
  use interlock_wear, only: wear_root_t, wear_root_begin, wear_root_update, worn_angle_slope
  use interlock_plane_law, only: wear_angle_error, add_wear_error, wear_error_of
  use interlock_friction, only: direction_turn
  use interlock_plane_law_3d_dual, only: plane_dual_t, plane_response_3d_t, plane_law_3d, &
      plane_angle_frame, worn_angle_3d, start_pressure_3d
  use interlock_substep_control, only: next_sub_increment, count_attempt, after_failure, &
      keep_trial, next_size, check_chain
  implicit none
  private
  public :: dual_update_3d, dual_step_3d

contains

  !> The update of interlock_update_3d's contract in dual numbers (admissible input): one step,
  !> retried on sub-increments split as failures require where its solve fails, or substepping
  !> with the solver's tolerance. `new`, sigma and tangent are set where info%status =
  !> status_ok.
  pure subroutine dual_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    info%status = status_ok
    info%newton_iterations = 0
    info%substeps = 1
    if (solver%substep_tol > 0.0_dp) then
      call substep(mat, solver, s, old, new, tangent, info, solver%substep_tol, 1.0_dp)
    else
      call substep(mat, solver, s, old, new, tangent, info, -1.0_dp, 1.0_dp)
      if (info%status == status_local_failure) then
        info%status = status_ok
        call substep(mat, solver, s, old, new, tangent, info, huge(1.0_dp), 0.5_dp)
      end if
    end if
    sigma = [new%sigma(1), new%sigma(2), new%sigma_t2]
  end subroutine dual_update_3d

  !> The increment as one step in dual numbers. `new`, the traction and tangent are set only
  !> where info%status = status_ok.
  pure subroutine dual_step_3d(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    info%status = status_ok
    info%newton_iterations = 0
    call substep(mat, solver, s, old, new, tangent, info, -1.0_dp, 1.0_dp)
    sigma = [new%sigma(1), new%sigma(2), new%sigma_t2]
  end subroutine dual_step_3d

  !> Sub-increments linear in s, as the general path takes them (interlock_general_path:substep,
  !> the same control and the same sizes): tol < 0, the whole increment in one step (a failed
  !> solve is reported as status_local_failure, for the caller to retry); tol finite, error
  !> control on the embedded wear estimate; tol = huge, sizes split only as failures require.
  !> The planes' state carries its derivative with respect to the end of the increment from
  !> one sub-increment to the next, so that the tangent is the exact one of the chain.
  pure subroutine substep(mat, solver, s, old, new, tangent, info, tol, h_first)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), tol, h_first
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    type(interlock_state_3d_t) :: cur, trial
    type(plane_dual_t) :: planes(max_planes), planes_trial(max_planes)
    type(dual_t) :: s_end(3), s_start(3), sig(3)
    real(dp) :: ds(3), s_old(3), alpha, h, a_end, err, chain_peak
    integer :: it, n_accepted, i, k
    logical :: solved, stable, control, single, kept, give_up, allowed

    single = tol < 0.0_dp
    control = tol >= 0.0_dp .and. tol < huge(1.0_dp)
    s_old = [old%s(1), old%s(2), old%s_t2]
    ds = s - s_old
    cur = old
    do k = 1, mat%n_planes
      planes(k) = plane_of(old, k)
    end do
    alpha = 0.0_dp
    h = h_first
    n_accepted = 0
    info%attempts = 0
    tangent = 0.0_dp
    chain_peak = 0.0_dp
    do while (alpha < 1.0_dp)
      call next_sub_increment(alpha, h, a_end)
      do i = 1, 3
        s_end(i) = constant(s_old(i) + a_end * ds(i))
        if (a_end >= 1.0_dp) s_end(i)%v = s(i)
        s_end(i)%d(i) = a_end
        s_start(i) = constant(cur_separation(cur, i))
        s_start(i)%d(i) = alpha
      end do
      call count_attempt(info, solver%max_substeps, allowed)
      if (.not. allowed) return
      call ria_step(mat, solver, s_end, s_start, cur, planes, trial, planes_trial, sig, it, &
                    solved, .not. single, err)
      info%newton_iterations = max(info%newton_iterations, it)
      if (single .and. .not. solved) then
        info%status = status_local_failure
        info%message = 'the local wear equation has no solution'
        return
      end if
      stable = .true.
      if (solved .and. .not. single) stable = bounded(planes_trial, mat%n_planes)
      if (.not. (solved .and. stable)) then
        call after_failure(solved, h, info, give_up)
        if (give_up) return
        cycle
      end if
      kept = keep_trial(control, err, tol, h)
      if (kept) then
        cur = trial
        planes(1:mat%n_planes) = planes_trial(1:mat%n_planes)
        do i = 1, 3
          tangent(i, :) = sig(i)%d(1:3)
        end do
        chain_peak = max(chain_peak, maxval(abs(tangent)))
        alpha = a_end
        n_accepted = n_accepted + 1
      end if
      call next_size(kept, control, err, tol, h)
    end do
    call check_chain(mat, chain_peak, info, allowed)
    if (.not. allowed) return
    new = cur
    info%substeps = n_accepted
  end subroutine substep

  !> Component i of the separation of a state.
  pure real(dp) function cur_separation(state, i) result(x)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: i
    if (i <= 2) then
      x = state%s(i)
    else
      x = state%s_t2
    end if
  end function cur_separation

  !> Plane k of a state, as numbers without derivatives.
  pure type(plane_dual_t) function plane_of(state, k) result(q)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: k
    q%beta = constant(state%beta(k))
    q%dmg = constant(state%damage(k))
    q%sf = constant([state%sf(k), state%sf_strike(k)])
    q%zeta = constant(state%zeta(k))
    q%theta = constant(state%theta(k))
    q%tauf = constant([state%tauf(k), state%tauf_strike(k)])
  end function plane_of

  !> Store plane k's values in a state.
  pure subroutine store_plane(q, k, state)
    type(plane_dual_t), intent(in) :: q
    integer, intent(in) :: k
    type(interlock_state_3d_t), intent(inout) :: state
    state%beta(k) = q%beta%v
    state%damage(k) = q%dmg%v
    state%sf(k) = q%sf(1)%v
    state%sf_strike(k) = q%sf(2)%v
    state%zeta(k) = q%zeta%v
    state%theta(k) = q%theta%v
    state%tauf(k) = q%tauf(1)%v
    state%tauf_strike(k) = q%tauf(2)%v
  end subroutine store_plane

  !> The chained derivatives of the planes in use stay far from overflow (as the 2D update's).
  pure logical function bounded(planes, n)
    type(plane_dual_t), intent(in) :: planes(:)
    integer, intent(in) :: n
    integer :: k
    bounded = .true.
    do k = 1, n
      if (any(abs(planes(k)%beta%d) > 1.0e100_dp) .or. any(abs(planes(k)%dmg%d) > 1.0e100_dp) &
          .or. any(abs(planes(k)%sf(1)%d) > 1.0e100_dp) .or. &
          any(abs(planes(k)%sf(2)%d) > 1.0e100_dp) .or. any(abs(planes(k)%zeta%d) > 1.0e100_dp) &
          .or. any(abs(planes(k)%tauf(1)%d) > 1.0e100_dp) .or. &
          any(abs(planes(k)%tauf(2)%d) > 1.0e100_dp)) bounded = .false.
    end do
  end function bounded

  !> Every plane of the RIA over one (sub-)increment from the state `old` (its planes `o`, with
  !> their derivatives) at separation s_start to s_end: the traction with its derivatives, the
  !> end state and its planes; `estimate`: the embedded error estimate of the wear (`err`).
  pure subroutine ria_step(mat, solver, s_end, s_start, old, o, new, q, sig, iterations, ok, &
                           estimate, err)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(dual_t), intent(in) :: s_end(3), s_start(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(plane_dual_t), intent(in) :: o(:)
    type(interlock_state_3d_t), intent(out) :: new
    type(plane_dual_t), intent(inout) :: q(:)
    type(dual_t), intent(out) :: sig(3)
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    logical, intent(in) :: estimate
    real(dp), intent(out) :: err
    type(plane_response_3d_t) :: p
    type(dual_t) :: area, x, w
    real(dp) :: gam, e, dsig_dtheta(3), err_angle, err_traction, sig_v(3), s_v(3), old_sig(3), &
                old_s(3)
    integer :: k, n_eval, it

    new = old
    ok = .true.
    iterations = 0
    err = 0.0_dp
    err_angle = 0.0_dp
    err_traction = 0.0_dp
    sig = constant(0.0_dp)
    new%stored = 0.0_dp

    area = constant(1.0_dp)
    if (mat%use_depth) then
      x = s_end(1) * mat%inv_h_n
      if (x%v <= 0.0_dp) then
        area = constant(1.0_dp)
      else if (x%v < 1.0_dp) then
        area = 1.0_dp - x
      else
        area = constant(0.0_dp)
      end if
    end if

    if (area%v <= 0.0_dp) then
      ! Separated (decision D7): nothing transmitted, no bond survives, nothing slides.
      do k = 1, mat%n_planes
        q(k) = o(k)
        if (mat%use_damage) then
          q(k)%beta = max(o(k)%beta, mat%beta_break)
          q(k)%dmg = constant(1.0_dp)
        end if
        q(k)%tauf = constant([0.0_dp, 0.0_dp])
        call store_plane(q(k), k, new)
      end do
    else
      n_eval = merge(1, mat%n_planes, mat%flat .and. mat%azimuths_zero)
      do k = 1, n_eval
        call plane_step(mat, mat%cos_phi(k), mat%sin_phi(k), solver, k, s_end, s_start, o(k), estimate, q(k), &
                        p, it, ok, e, dsig_dtheta)
        if (.not. ok) return
        iterations = max(iterations, it)
        gam = merge(1.0_dp, mat%gamma_hat(k), mat%flat .and. mat%azimuths_zero)
        w = gam * area
        if (estimate) then
          call add_wear_error(e, w%v, [dsig_dtheta(1), max(abs(dsig_dtheta(2)), &
                              abs(dsig_dtheta(3)))], err_angle, err_traction)
          ! the friction direction's turn, on a plane that slides at the end
          if (abs(q(k)%sf(1)%v - o(k)%sf(1)%v) + abs(q(k)%sf(2)%v - o(k)%sf(2)%v) > 0.0_dp) &
            err_traction = max(err_traction, w%v * q(k)%dmg%v * &
              norm2([q(k)%tauf(1)%v, q(k)%tauf(2)%v]) * &
              direction_turn([o(k)%tauf(1)%v, o(k)%tauf(2)%v], [q(k)%tauf(1)%v, q(k)%tauf(2)%v]))
        end if
        sig = sig + w * p%sig
        new%diss_damage = new%diss_damage + gam * area%v * p%wdmg
        new%diss_friction = new%diss_friction + gam * area%v * p%wfric
        new%stored = new%stored + gam * area%v * p%psi
        call store_plane(q(k), k, new)
      end do
      do k = n_eval + 1, mat%n_planes
        ! Identical flat planes share one history: computed once, copied (SPEC section 7).
        q(k) = q(1)
        call store_plane(q(k), k, new)
      end do
    end if
    sig_v = sig%v
    s_v = s_end%v
    old_sig = [old%sigma(1), old%sigma(2), old%sigma_t2]
    old_s = [old%s(1), old%s(2), old%s_t2]
    new%s = s_v(1:2)
    new%s_t2 = s_v(3)
    new%sigma = sig_v(1:2)
    new%sigma_t2 = sig_v(3)
    new%work = old%work + 0.5_dp * dot_product(old_sig + sig_v, s_v - old_s)
    if (estimate) err = wear_error_of(mat, err_angle, err_traction, &
                                      [sig_v(1), max(abs(sig_v(2)), abs(sig_v(3)))])
  end subroutine ria_step

  !> Plane k over one step in the solver's scheme (SPEC section 9, "Schemes"): the angle frozen
  !> at its start value (explicit) or coupled to the end of the step by the wear equation,
  !> zeta - zeta_o = a_end D |tau_f,1| |d sf_1| + g_slip |d sf_1| (wear_weights of the 2D law
  !> with the dip components), solved by the safeguarded Newton iteration of interlock_wear and
  !> differentiated implicitly at its root. Returns the end state q, the response p at the
  !> angle of the traction (its derivative column 4: d / d theta at fixed s), and with
  !> `estimate` the wear's embedded error estimate e [rad] and d sig / d theta.
  pure subroutine plane_step(mat, cp, sp, solver, k, s, s_o, o, estimate, q, p, iterations, &
                             ok, e, dsig_dtheta)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp   !< cos and sin of the plane's azimuth
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    type(dual_t), intent(in) :: s(3), s_o(3)
    type(plane_dual_t), intent(in) :: o
    logical, intent(in) :: estimate
    type(plane_dual_t), intent(out) :: q
    type(plane_response_3d_t), intent(out) :: p
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    real(dp), intent(out) :: e, dsig_dtheta(3)
    type(wear_root_t) :: rt
    type(dual_t) :: c_o, sn_o, g_slip, g_trap, drv, theta, zeta, z, mu_p_o
    real(dp) :: a_end, fp, thp
    logical :: coupled, wears, trapezoidal
    integer :: i

    ok = .true.
    iterations = 0
    e = 0.0_dp
    dsig_dtheta = 0.0_dp
    coupled = solver%scheme /= scheme_explicit
    trapezoidal = solver%scheme == scheme_trapezoidal
    wears = mat%plane_wears(k)
    ! The trapezoidal start value D_o mu p_o / 2 (also the error estimate's reference); mu p_o
    ! also decides whether the plane slides at the start (D14's mean-direction rule).
    g_trap = constant(0.0_dp)
    mu_p_o = constant(0.0_dp)
    if (trapezoidal .or. estimate) then
      call plane_angle_frame(mat, k, o%theta, c_o, sn_o)
      mu_p_o = start_pressure_3d(mat, cp, sp, c_o, sn_o, s_o)
      g_trap = (0.5_dp * o%dmg) * mu_p_o
    end if
    if (.not. trapezoidal) mu_p_o = constant(0.0_dp)
    if (.not. coupled) then
      a_end = 0.0_dp
      g_slip = o%dmg * abs(o%tauf(1))
    else if (trapezoidal) then
      a_end = 0.5_dp
      g_slip = g_trap
    else
      a_end = 1.0_dp
      g_slip = constant(0.0_dp)
    end if

    theta = o%theta
    if (coupled .and. wears) then
      ! F(zeta) = zeta - zeta_o - G(theta(zeta)): column 4 carries d / d zeta (F' = 1 - dG /
      ! d zeta); at zeta_o the stored angle and its slope, no exponential.
      thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), o%theta%v)
      ! (the angle is theta(zeta) of the unknown zeta: its start-state columns would count
      ! the start angle's derivative twice, through F')
      theta%d(1:3) = 0.0_dp
      theta%d(4) = thp
      call evaluate(mat, cp, sp, k, theta, s, o, mu_p_o, a_end, g_slip, trapezoidal, p, drv)
      fp = 1.0_dp - drv%d(4)
      zeta = o%zeta
      if (drv%v > 0.0_dp) then
        ! (a sub-increment smaller than the increment, d s_o / dS > 0 or d s / dS < 1: the first
        ! point Newton's from zeta_o, as the plain path's)
        call wear_root_begin(rt, o%zeta%v, drv%v, fp)
        do
          z = constant(rt%x)
          z%d(4) = 1.0_dp
          theta = worn_angle_3d(mat, k, z)
          call evaluate(mat, cp, sp, k, theta, s, o, mu_p_o, a_end, g_slip, trapezoidal, p, drv)
          fp = 1.0_dp - drv%d(4)
          call wear_root_update(rt, rt%x - o%zeta%v - drv%v, fp, solver%newton_tol, &
                                solver%newton_max_iterations)
          if (rt%done) exit
        end do
        iterations = rt%iterations
        ok = rt%ok
        if (.not. ok) return
        if (.not. (drv%v > 0.0_dp .or. abs(p%tauf(1)%v) + abs(p%tauf(2)%v) > 0.0_dp)) then
          ! The root is where the plane just loses contact (very fast wear turns it until
          ! then; not where it sticks, no friction traction), within round-off of that kink,
          ! and the last point is on the open side: take
          ! the closed side's last point, rt%lo (F < 0 there, so some work: the plane is in
          ! contact), a few ulps from the root, so that the angle's derivative and the
          ! traction's come from the same side (mixed, they are neither one-sided derivative).
          rt%x = rt%lo
          z = constant(rt%x)
          z%d(4) = 1.0_dp
          theta = worn_angle_3d(mat, k, z)
          call evaluate(mat, cp, sp, k, theta, s, o, mu_p_o, a_end, g_slip, trapezoidal, p, drv)
          fp = 1.0_dp - drv%d(4)
        end if
        zeta%v = rt%x
      end if
      ! d zeta = (d zeta_o + dG) / F' at the root, then the angle with it
      do i = 1, 3
        zeta%d(i) = (o%zeta%d(i) + drv%d(i)) / fp
      end do
      zeta%d(4) = 0.0_dp
      thp = theta%d(4)
      theta%d(1:3) = thp * zeta%d(1:3)
    end if
    ! The traction's angle with column 4 = d / d theta at fixed s (the error estimate's).
    theta%d(4) = 1.0_dp
    call evaluate(mat, cp, sp, k, theta, s, o, mu_p_o, a_end, g_slip, trapezoidal, p, drv)
    if (.not. (coupled .and. wears)) then
      zeta = o%zeta + drv
      if (.not. coupled .and. wears) then
        ! explicit (eq. 25): the angle of the worn zeta for the next step
        if (zeta%v > o%zeta%v) theta = worn_angle_3d(mat, k, zeta)
      end if
    end if

    q%beta = p%beta
    q%dmg = p%dmg
    q%sf = p%sf
    q%tauf = p%tauf
    q%zeta = zeta
    q%theta = theta
    call clear_column_4(q)

    if (estimate .and. wears) then
      if (coupled) then
        e = wear_angle_error(mat, k, solver%scheme, q%theta%v, o%theta%v, q%zeta%v, o%zeta%v, &
                             p%wear_end%v, p%wear_start%v, g_slip%v, g_trap%v)
      else
        e = wear_angle_error(mat, k, solver%scheme, q%theta%v, o%theta%v, q%zeta%v, o%zeta%v, &
                             p%wfric_dip%v, p%slip_dip%v, g_slip%v, g_trap%v)
      end if
      do i = 1, 3
        dsig_dtheta(i) = p%sig(i)%d(4)
      end do
    end if
  end subroutine plane_step

  !> The plane law at angle theta and the scheme's wear driver G = a_end D |tau_f,1| |d sf_1| +
  !> g_slip |d sf_1| (explicit, implicit), with the trapezoidal start value the dip component of
  !> D_o mu p_o n: g_slip |d sf_1| times the dip share of the step's slip direction n.
  pure subroutine evaluate(mat, cp, sp, k, theta, s, o, mu_p_o, a_end, g_slip, trapezoidal, p, &
                          drv)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp
    integer, intent(in) :: k
    type(dual_t), intent(in) :: theta, s(3), mu_p_o, g_slip
    type(plane_dual_t), intent(in) :: o
    real(dp), intent(in) :: a_end
    logical, intent(in) :: trapezoidal
    type(plane_response_3d_t), intent(out) :: p
    type(dual_t), intent(out) :: drv
    type(dual_t) :: c, sn
    call plane_angle_frame(mat, k, theta, c, sn)
    call plane_law_3d(mat, cp, sp, c, sn, s, o, mu_p_o, p)
    if (trapezoidal) then
      drv = a_end * p%wear_end + g_slip * p%wear_start
    else
      drv = a_end * p%wfric_dip + g_slip * p%slip_dip
    end if
  end subroutine evaluate

  !> A stored plane's derivatives are with respect to the end separation only.
  pure subroutine clear_column_4(q)
    type(plane_dual_t), intent(inout) :: q
    q%beta%d(n_dual) = 0.0_dp
    q%dmg%d(n_dual) = 0.0_dp
    q%sf(1)%d(n_dual) = 0.0_dp
    q%sf(2)%d(n_dual) = 0.0_dp
    q%zeta%d(n_dual) = 0.0_dp
    q%theta%d(n_dual) = 0.0_dp
    q%tauf(1)%d(n_dual) = 0.0_dp
    q%tauf(2)%d(n_dual) = 0.0_dp
  end subroutine clear_column_4

end module interlock_update_3d_dual
