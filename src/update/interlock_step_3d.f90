!> One step of every plane of a three-dimensional interface (SPEC section 9) in the solver's
!> scheme, in plain reals with the exact 3x3 tangent written out: the plane law
!> (interlock_plane_law_3d) at the angle of the step, the wear equation of the coupled schemes
!> solved by the safeguarded Newton iteration of interlock_wear and differentiated implicitly at
!> its root, the frame's rotation and the angle's derivative chained by hand, the contact area
!> and D7. The whole increment as one step (step_3d without `chain`), or one sub-increment of
!> it whose start state carries its derivatives with respect to the increment's end separation
!> S (`chain`: substepping), so that the tangent is the exact one of the chain: each plane's
!> state derivatives d(state)/dS are carried from one sub-increment to the next
!> (plane_chain_t), through the plane law's derivatives with respect to the local separation,
!> the start slip, damage and history and the start direction of slip.
module interlock_step_3d
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      scheme_trapezoidal, max_planes
  use interlock_state, only: interlock_state_3d_t, state_3d_end_point
  use interlock_geometry, only: contact_area
  use interlock_friction, only: direction_turn_of, unit_direction_turn, start_direction
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  use interlock_plane_law, only: plane_frame, wear_weights, start_yield, start_weight, &
      trapezoidal_end_weight, wear_angle_error, add_wear_error, wear_error_of
  use interlock_plane_law_3d, only: plane_start_3d_t, plane_law_3d_t, plane_law_3d_parts, &
      plane_traction_3d, local_frame, contact_round_off, to_macro
  implicit none
  private
  public :: plane_chain_t, step_3d, chain_bounded

  !> The derivatives of one plane's state with respect to the end separation S of the
  !> increment (columns S_N, S_T1, S_T2); atauf1 = d |tau_f,1| / dS, the explicit scheme's start
  !> weight's (its sign is not the stored tau_f,1's where that is 0 at the tie s_kn = 0);
  !> side(j) (the explicit scheme): the direction (+1: +S_j, -1: -S_j) whose one-sided
  !> derivative column j is since the plane first ended a sub-increment at the tie, the one
  !> that closed it there; 0 before (chain_at_tie).
  type :: plane_chain_t
    real(dp) :: beta(3), dmg(3), sf(3, 2), zeta(3), theta(3), tauf(3, 2)
    real(dp) :: atauf1(3), side(3)
  end type plane_chain_t

contains

  !> The step from `old` (at its separation s_o) to s: the end state `new` (its traction and
  !> energies included; the planes beyond n_planes untouched), the traction's derivative in
  !> `tangent`, the largest number of Newton iterations of a wear equation; `ok` false when a
  !> wear equation has no solution (then `new` is partly written). Without `chain`, tangent =
  !> d sigma / d s at the fixed start state. With `chain`, the step is a sub-increment of an
  !> increment with end separation S, from its fraction h_start to h_end (ds_o / dS = h_start,
  !> ds / dS = h_end); jo(k) are the start planes' derivatives d / dS, and `tangent` = d sigma /
  !> dS, jn(k) the end planes' (h_start = 0: the start state is the increment's, jo = 0 is not
  !> read). `estimate`: the embedded error estimate of the wear in err. `in_plane` (absent:
  !> false): the increment lies in the (n, t1) plane (s_T2 = 0
  !> at its start and end, no strike component in the state, every azimuth 0), where every
  !> strike derivative is 0, and only the (1:2, 1:2) block of `tangent` is wanted (the rest of
  !> `tangent` 0); with `chain` the chain carries the columns S_N and S_T1 alone (the others of
  !> jn stay as they come). A wear equation's iteration starts at Newton's point from zeta_o
  !> (F' there comes with the start angle's evaluation; on small steps it usually meets the
  !> tolerance at once), as the specialised kernels' does.
  pure subroutine step_3d(mat, solver, s, old, new, tangent, iterations, ok, chain, h_start, &
                          h_end, jo, jn, estimate, err, in_plane, frames, known, slot)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), h_start, h_end
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3), err
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    logical, intent(in) :: chain, estimate
    type(plane_chain_t), intent(in) :: jo(:)
    type(plane_chain_t), intent(inout) :: jn(:)
    logical, intent(in), optional :: in_plane
    !> (all three or none; with `chain`) the planes' frames (cos, sin) of the start angles in
    !> frames(:, :, slot), read where `known`, else written, and, where ok, of the end angles
    !> in frames(:, :, 3 - slot): the next sub-increment's start frames, not computed again
    !> (the planes evaluated alone: the first where identical flat planes share one history)
    real(dp), intent(inout), optional :: frames(2, max_planes, 2)
    logical, intent(in), optional :: known
    integer, intent(in), optional :: slot
    type(plane_law_3d_t) :: p
    type(plane_start_3d_t) :: o
    type(wear_root_t) :: rt
    real(dp) :: area, darea, gam, w, sig(3), sig_k(3), s_o(3), zeta, &
                theta, e, dsig_dtheta(3), turn, err_angle, err_traction, fo(2, max_planes), &
                c_n, sn_n, diss_damage, diss_friction, stored
    integer :: k, n_eval, it, ncol
    logical :: shared, carried

    ok = .true.
    iterations = 0
    ncol = 3
    if (present(in_plane)) then
      if (in_plane) ncol = 2
    end if
    err = 0.0_dp
    err_angle = 0.0_dp
    err_traction = 0.0_dp
    sig = 0.0_dp
    tangent = 0.0_dp
    ! (the energies summed over the planes in scalars, stored in `new` once)
    diss_damage = old%diss_damage
    diss_friction = old%diss_friction
    stored = 0.0_dp
    s_o = [old%s(1), old%s(2), old%s_t2]

    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)
    ! Identical flat planes share one history: computed once, copied (SPEC section 7).
    shared = mat%flat .and. mat%azimuths_zero
    n_eval = merge(1, mat%n_planes, shared)
    carried = present(frames)
    if (carried) then
      ! (the start frames as below, or the caller's)
      if (known) then
        fo(:, 1:n_eval) = frames(:, 1:n_eval, slot)
      else
        do k = 1, n_eval
          call plane_frame(mat, k, old%theta(k), fo(1, k), fo(2, k))
        end do
        frames(:, 1:n_eval, slot) = fo(:, 1:n_eval)
      end if
    end if

    if (area <= 0.0_dp) then
      ! Separated (decision D7): nothing transmitted, no bond survives, nothing slides.
      if (carried) frames(:, 1:n_eval, 3 - slot) = fo(:, 1:n_eval)
      do k = 1, mat%n_planes
        new%beta(k) = old%beta(k)
        new%damage(k) = old%damage(k)
        if (chain) jn(k) = jo(k)
        if (mat%use_damage) then
          new%beta(k) = max(old%beta(k), mat%beta_break)
          new%damage(k) = 1.0_dp
          if (chain) then
            if (mat%beta_break > old%beta(k)) jn(k)%beta = 0.0_dp
            jn(k)%dmg = 0.0_dp
          end if
        end if
        new%sf(k) = old%sf(k)
        new%sf_strike(k) = old%sf_strike(k)
        new%zeta(k) = old%zeta(k)
        new%theta(k) = old%theta(k)
        new%tauf(k) = 0.0_dp
        new%tauf_strike(k) = 0.0_dp
        if (chain) then
          jn(k)%tauf = 0.0_dp
          jn(k)%atauf1 = 0.0_dp
        end if
      end do
    else
      ! The start angles' frames first (the stored ones unless worn): libm's sincos sets and
      ! restores the rounding mode, which waits for the floating-point work before it, so that
      ! the planes' laws after it overlap (the same values).
      if (.not. carried) then
        do k = 1, n_eval
          call plane_frame(mat, k, old%theta(k), fo(1, k), fo(2, k))
        end do
      end if
      do k = 1, n_eval
        o = plane_of(old, k)
        gam = merge(1.0_dp, mat%gamma_hat(k), shared)
        w = gam * area
        call plane_step(mat, mat%cos_phi(k), mat%sin_phi(k), fo(1, k), fo(2, k), solver, k, s, &
                        s_o, o, estimate, chain, h_start, h_end, jo(min(k, size(jo))), ncol, &
                        w, p, sig_k, tangent, zeta, theta, jn(min(k, size(jn))), e, &
                        dsig_dtheta, turn, it, ok, rt, c_n, sn_n)
        if (.not. ok) return
        if (carried) then
          frames(1, k, 3 - slot) = c_n
          frames(2, k, 3 - slot) = sn_n
        end if
        iterations = max(iterations, it)
        if (estimate) then
          call add_wear_error(e, w, [dsig_dtheta(1), max(abs(dsig_dtheta(2)), &
                              abs(dsig_dtheta(3)))], err_angle, err_traction)
          ! the friction direction's turn, on a plane that slides at the end (none in the
          ! plane (n, t1) of a 2D increment: the direction cannot turn)
          ! (|tau_f| = p%tauf_norm)
          if (ncol > 2 .and. p%slip_norm > 0.0_dp) err_traction = max(err_traction, w * &
            p%dmg * p%tauf_norm * turn)
        end if
        sig = sig + w * sig_k
        if (darea < 0.0_dp) tangent(:, 1) = tangent(:, 1) + (gam * darea * h_end) * sig_k
        diss_damage = diss_damage + gam * area * p%wdmg
        diss_friction = diss_friction + gam * area * p%wfric
        stored = stored + gam * area * p%psi
        call store_plane(p, zeta, theta, k, new)
      end do
      do k = n_eval + 1, mat%n_planes
        call store_plane(p, zeta, theta, k, new)
        if (chain) jn(k) = jn(1)
      end do
    end if
    new%diss_damage = diss_damage
    new%diss_friction = diss_friction
    new%stored = stored
    call state_3d_end_point(old, s, sig, new)
    if (estimate) err = wear_error_of(mat, err_angle, err_traction, &
                                      [sig(1), max(abs(sig(2)), abs(sig(3)))])
  end subroutine step_3d

  !> The chained derivatives of the planes in use stay far from overflow: the sum of their
  !> magnitudes (one comparison per plane; a NaN is not caught here but by the update's
  !> finiteness check). ncol = 2: a chain in the plane (n, t1) (step_3d's in_plane), whose
  !> other entries are 0.
  pure logical function chain_bounded(jn, n, ncol)
    type(plane_chain_t), intent(in) :: jn(:)
    integer, intent(in) :: n, ncol
    integer :: k
    real(dp), parameter :: bound = 1.0e100_dp
    real(dp) :: total
    chain_bounded = .true.
    do k = 1, n
      if (ncol > 2) then
        total = sum(abs(jn(k)%beta)) + sum(abs(jn(k)%dmg)) + sum(abs(jn(k)%sf)) + &
                sum(abs(jn(k)%zeta)) + sum(abs(jn(k)%tauf))
      else
        total = abs(jn(k)%beta(1)) + abs(jn(k)%beta(2)) + abs(jn(k)%dmg(1)) + &
                abs(jn(k)%dmg(2)) + abs(jn(k)%sf(1, 1)) + abs(jn(k)%sf(2, 1)) + &
                abs(jn(k)%zeta(1)) + abs(jn(k)%zeta(2)) + abs(jn(k)%tauf(1, 1)) + &
                abs(jn(k)%tauf(2, 1))
      end if
      if (total > bound) chain_bounded = .false.
    end do
  end function chain_bounded

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
  !> zeta - zeta_o = G(theta(zeta)) with G = a_w D |tau_f,1| |d sf_1| + g_slip |d sf_1|
  !> (explicit, implicit: wear_weights of the 2D law with the dip components) or D11's
  !> trapezoidal rule with D14's terms, solved by the safeguarded Newton iteration of
  !> interlock_wear. Returns the response p at the angle of the traction, the plane's traction
  !> sig_k in the macro frame, adds its derivative k_k times the weight w to `tangent`
  !> (through the angle: d sig_k / d theta (x) d theta, by implicit differentiation at the
  !> root, d zeta = (dG) / F', F' = 1 - theta' dG / d theta; with ncol = 2 the (1:2, 1:2)
  !> block alone), the end values of zeta and theta, with `chain` the end state's
  !> derivatives jn, with `estimate` the wear's embedded error estimate e [rad] and
  !> dsig_dtheta = d sig_k / d theta at fixed s.
  pure subroutine plane_step(mat, cp, sp, c_o, sn_o, solver, k, s, s_o, o, estimate, chain, &
                             h_start, h_end, jo, ncol, w, p, sig_k, tangent, zeta, theta, jn, &
                             e, dsig_dtheta, turn, iterations, ok, rt, c_n, sn_n)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp   !< cos and sin of the plane's azimuth
    real(dp), intent(in) :: c_o, sn_o   !< cos and sin of its start angle (plane_frame)
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    real(dp), intent(in) :: s(3), s_o(3), h_start, h_end
    type(plane_start_3d_t), intent(in) :: o
    logical, intent(in) :: estimate, chain
    type(plane_chain_t), intent(in) :: jo
    integer, intent(in) :: ncol   !< the columns of the chain (chain_plane)
    real(dp), intent(in) :: w   !< its weight (area fraction x contact area)
    type(plane_law_3d_t), intent(out) :: p
    real(dp), intent(out) :: sig_k(3), zeta, theta, e, dsig_dtheta(3)
    !> (estimate, ncol = 3, a plane that slides at the end) the turn of its friction direction
    !> over the step (interlock_friction:direction_turn; from D14's start direction where it
    !> was taken); else 0
    real(dp), intent(out) :: turn
    real(dp), intent(inout) :: tangent(3, 3)
    type(plane_chain_t), intent(inout) :: jn
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    !> the wear equation's iteration: the caller's, so that its default initialisation is not
    !> repeated on every plane of every scheme (wear_root_begin sets it where an iteration
    !> starts; nothing else reads it)
    type(wear_root_t), intent(inout) :: rt
    !> the frame (cos, sin) of the end angle `theta` (the explicit scheme's worn angle's: with
    !> `chain` before the increment's end alone, where a next sub-increment starts there)
    real(dp), intent(out) :: c_n, sn_n
    real(dp) :: c, sn, dip_o, mu_p_o, a_w, g_slip, g_trap, drv, g_drv(3), thp, fp, &
                ksl(3), dtheta_sl(3), k_k(3, 3), tie, n_o(2)
    logical :: coupled, wears, trapezoidal, drivers, flat, terms, pinned, mean_o, angle
    integer :: phase

    ok = .true.
    iterations = 0
    e = 0.0_dp
    thp = 0.0_dp
    coupled = solver%scheme /= scheme_explicit
    trapezoidal = solver%scheme == scheme_trapezoidal
    wears = mat%plane_wears(k)
    drivers = wears .and. (coupled .or. chain)
    ! The scheme's wear weights (wear_weights of the 2D law, with the dip component of the
    ! start separation); mu p_o, the start state's friction bound, also decides whether the
    ! plane slides at the start (D14's mean-direction rule), and the trapezoidal start weight
    ! D_o mu p_o / 2 is the error estimate's reference.
    ! (the start angle's frame: also the frame of the law's first evaluation; the start
    ! separation's dip component only where a start yield is taken: the explicit and implicit
    ! weights have none)
    dip_o = 0.0_dp
    if (trapezoidal .or. estimate) dip_o = cp * s_o(2) + sp * s_o(3)
    mu_p_o = 0.0_dp
    g_trap = 0.0_dp
    if (trapezoidal .or. estimate) then
      mu_p_o = start_yield(mat, c_o, sn_o, s_o(1), dip_o)
      g_trap = start_weight(o%dmg, mu_p_o)
    end if
    if (trapezoidal) then
      ! (wear_weights' trapezoidal weights, from the start yield above)
      a_w = trapezoidal_end_weight
      g_slip = g_trap
    else
      call wear_weights(mat, solver%scheme, o%dmg, o%tauf(1), c_o, sn_o, s_o(1), dip_o, a_w, &
                        g_slip)
    end if
    ! D14's start direction of slip (the trapezoidal scheme; none in the plane (n, t1), where the
    ! direction cannot turn)
    mean_o = .false.
    if (trapezoidal .and. ncol > 2) call start_direction(o%tauf, mu_p_o, mean_o, n_o)
    ! The trapezoidal wear terms: its driver where it has a start term (a start weight, or D14's
    ! direction), the chain's, and the coupled schemes' error estimate; without them the
    ! trapezoidal driver is a_w D |tau_f,1| |d sf_1| (evaluate).
    terms = (trapezoidal .and. (g_slip > 0.0_dp .or. mean_o .or. chain)) .or. &
            (estimate .and. coupled)

    theta = o%theta
    zeta = o%zeta
    c = c_o
    sn = sn_o
    flat = flat_frame(cp, sp, c, sn)
    ! The law at the start angle (the traction with it where the angle is not solved for);
    ! where the angle is coupled to the end of the step, the wear equation F(zeta) = zeta -
    ! zeta_o - G(theta(zeta)) from there (at zeta_o the stored angle and its slope, no
    ! exponential) by the iteration's points, and where the root is at the kink where the plane
    ! just loses contact, once more at the closed side's last point: one evaluation site, so
    ! that the law is inlined once.
    phase = 0
    do
      if (phase > 0) then
        call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), rt%x, theta, &
                        thp)
        call plane_frame(mat, k, theta, c, sn)
        flat = flat_frame(cp, sp, c, sn)
      end if
      call evaluate(mat, cp, sp, s, o, mean_o, n_o, a_w, g_slip, trapezoidal, terms, drivers, &
                    chain, .not. (coupled .and. wears), ncol < 3, c, sn, flat, p, drv, g_drv, &
                    tie)
      if (.not. (coupled .and. wears)) exit
      if (phase == 0) thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), o%theta)
      fp = 1.0_dp - thp * angle_slope(g_drv, p%sl)
      if (phase == 0) then
        if (.not. drv > 0.0_dp) exit
        call wear_root_begin(rt, o%zeta, drv, fp)
        phase = 1
      else if (phase == 1) then
        call wear_root_update(rt, rt%x - o%zeta - drv, fp, solver%newton_tol, &
                              solver%newton_max_iterations)
        if (.not. rt%done) cycle
        iterations = rt%iterations
        ok = rt%ok
        if (.not. ok) return
        if (drv > 0.0_dp .or. abs(p%tauf(1)) + abs(p%tauf(2)) > 0.0_dp) exit
        ! The root is where the plane just loses contact (very fast wear turns it until
        ! then), within round-off of that kink, and the last point is on the open side (no
        ! friction traction; a plane that sticks there has its root where it switches to
        ! sliding, and the last point is that root): take the closed side's last point, rt%lo
        ! (F < 0 there, so some work: the plane is in contact), a few ulps from the root, so
        ! that the angle's derivative and the traction's come from the same side (mixed,
        ! they are neither one-sided derivative).
        rt%x = rt%lo
        phase = 2
      else
        exit
      end if
    end do
    ! A root where the plane loses contact, on a jump of F (the trapezoidal driver's start term
    ! follows the start direction of slip on the closed side, the step's slip on the open one:
    ! where the open side wears less, F jumps from < 0 to > 0 there), stays there as s moves:
    ! the angle follows the plane's contact, s_kn(theta, s) = 0, so that d theta / d s = -m /
    ! s_kt1 (d s_kn / d theta = s_kt1), not the wear equation's slope.
    ! (the frame of the last point evaluated, the root's)
    c_n = c
    sn_n = sn
    pinned = .false.
    if (phase > 0) then
      if (rt%at_jump) pinned = abs(p%sl(2)) > 0.0_dp .and. abs(thp) > 0.0_dp .and. &
                               .not. abs(p%sl(1)) > contact_round_off(cp, sp, c, sn, s)
    end if
    if (coupled .and. wears) then
      if (phase > 0) zeta = rt%x
    else
      zeta = o%zeta + drv
      thp = 0.0_dp
      if (.not. coupled .and. wears) then
        ! explicit (eq. 25): the angle of the worn zeta for the next step
        if (zeta > o%zeta) then
          call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), zeta, theta, &
                          thp)
          if (chain .and. h_end < 1.0_dp) call plane_frame(mat, k, theta, c_n, sn_n)
        else if (chain) then
          ! (the slope for the chain alone)
          thp = worn_angle_slope(mat%thetaf_eff(k), mat%inv_zeta0(k), o%theta)
        end if
      end if
    end if
    ! the traction, its derivative and the energies at the wear equation's root (not at its
    ! iterates)
    if (coupled .and. wears) call plane_traction_3d(mat, o, chain, p)
    if (flat) then
      sig_k = p%sig_loc
    else
      sig_k = to_macro(cp, sp, c, sn, p%sig_loc)
    end if
    angle = coupled .and. wears .and. .not. chain
    if (wears .and. (angle .or. estimate)) then
      ! d sig_k / d theta at fixed s = sigma_kn e - sigma_kt1 m + R^T K_loc d sl / d theta
      ! (ksl: in the plane's frame)
      ksl = p%k_loc(:, 1) * p%sl(2) - p%k_loc(:, 2) * p%sl(1)
      ksl(1) = ksl(1) - p%sig_loc(2)
      ksl(2) = ksl(2) + p%sig_loc(1)
      dsig_dtheta = 0.0_dp
      if (estimate) dsig_dtheta = to_macro(cp, sp, c, sn, ksl)
    else
      ! (0 where the angle does not move; read by the error estimate alone)
      ksl = 0.0_dp
      dsig_dtheta = 0.0_dp
    end if
    if (chain) then
      call chain_plane(mat, cp, sp, c, sn, c_o, sn_o, s_o, o, jo, p, coupled .and. wears, &
                       wears .and. .not. coupled, trapezoidal, a_w, g_slip, mu_p_o, g_drv, &
                       thp, fp, h_start, h_end, ncol, pinned, k_k, jn)
      if (.not. coupled) then
        ! (the explicit scheme's law is evaluated once, at the start angle: its tie)
        if (.not. abs(p%sl(1)) > tie) &
          call chain_at_tie(mat, cp, sp, c, sn, o, jo, p, wears, a_w, g_slip, mu_p_o, &
                            mean_o, n_o, thp, fp, s_o, h_start, h_end, ncol, k_k, jn)
      end if
      if (ncol > 2) then
        tangent = tangent + w * k_k
      else
        ! (the (1:2, 1:2) block alone: chain_plane's k_k has no more)
        tangent(1:2, 1:2) = tangent(1:2, 1:2) + w * k_k(1:2, 1:2)
      end if
    else
      if (angle) then
        ! d zeta / d s = (dG / d s) / F' at the root, d theta / d s = theta' d zeta / d s, dG /
        ! d s = R^T dG / d sl: d theta / d s = R^T dtheta_sl in the plane's frame (pinned: -m /
        ! s_kt1, R^T (-1, 0, 0) / s_kt1)
        if (pinned) then
          dtheta_sl = 0.0_dp
          dtheta_sl(1) = -1.0_dp / p%sl(2)
        else
          dtheta_sl = g_drv * (thp / fp)
        end if
      else
        dtheta_sl = 0.0_dp
      end if
      ! (K_loc's normal row: plane_traction_3d; the angle's term fills it)
      call add_turned(cp, sp, c, sn, flat, p%k_loc, .not. (p%dmg_grows .or. angle), angle, &
                      ksl, dtheta_sl, w, tangent)
    end if

    turn = 0.0_dp
    if (estimate .and. ncol > 2 .and. p%tauf_norm > 0.0_dp .and. p%slip_norm > 0.0_dp) then
      if (mean_o) then
        ! (n_o = tauf_o / |tauf_o|)
        turn = unit_direction_turn(n_o, p%tauf / p%tauf_norm)
      else
        turn = direction_turn_of(o%tauf, p%tauf, p%tauf_norm)
      end if
    end if
    if (estimate .and. wears) then
      if (coupled) then
        e = wear_angle_error(mat, k, solver%scheme, theta, o%theta, zeta, o%zeta, p%wear_end, &
                             p%wear_start, g_slip, g_trap)
      else
        e = wear_angle_error(mat, k, solver%scheme, theta, o%theta, zeta, o%zeta, p%wfric_dip, &
                             p%slip_dip, g_slip, g_trap)
      end if
    end if
  end subroutine plane_step

  !> The derivatives with respect to the increment's end S of one plane's step (`chain`):
  !> d sl = R ds + d sl / d theta d theta, ds = h_end dS; the start state's derivatives jo
  !> through the plane law's derivatives with respect to the start slip, damage, history and
  !> start direction of slip (plane_law_3d_t); the angle of the traction: theta_o (explicit,
  !> jo%theta) or the root's, d zeta = (d zeta_o + dG at fixed theta) / F' (`coupled_wear`);
  !> the start weight g_slip's own derivative (explicit D_o |tauf_o,1|, trapezoidal
  !> D_o mu p_o / 2 with mu p_o from the start separation, ds_o = h_start dS, at theta_o).
  !> Returns d sig_k / dS in k_k and the end state's derivatives jn, their columns 1 to ncol
  !> (the others untouched). On the first sub-increment (h_start = 0) jo = 0 and the start
  !> state's terms vanish: they are left out. ncol = 2 (in_plane_chain): the (1:2, 1:2) block
  !> of k_k and no strike rows of jn (which stay 0).
  pure subroutine chain_plane(mat, cp, sp, c, sn, c_o, sn_o, s_o, o, jo, p, coupled_wear, &
                              explicit_wear, trapezoidal, a_w, g_slip, mu_p_o, g_drv, thp, fp, &
                              h_start, h_end, ncol, pinned, k_k, jn)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp, c, sn, c_o, sn_o, s_o(3), a_w, g_slip, mu_p_o, &
                            g_drv(3), thp, fp, h_start, h_end
    type(plane_start_3d_t), intent(in) :: o
    type(plane_chain_t), intent(in) :: jo
    type(plane_law_3d_t), intent(in) :: p
    logical, intent(in) :: coupled_wear, explicit_wear, trapezoidal
    integer, intent(in) :: ncol
    logical, intent(in) :: pinned   !< the root stays at the contact kink (plane_step)
    real(dp), intent(out) :: k_k(3, 3)
    type(plane_chain_t), intent(inout) :: jn
    real(dp) :: rot(3, 3), dsl(3, 3), jphi(3), dg(3), d_drv(3), dtheta(3), dsig_loc(3), tn2, &
                dsn_o(3), x_o, q2, h1(2), h2(2), hdmg1, phi1, phi2, gdsl, dsig_dth(3), gtau(2)
    integer :: i, j, nrow
    logical :: fresh, negative_tauf1, strike

    fresh = .not. h_start > 0.0_dp
    if (fresh) then
      jn%side = 0.0_dp
    else
      jn%side = jo%side
    end if
    ! (the strike rows of jn: 0 with the columns S_N, S_T1 alone, where d s_kt2 = 0 too)
    nrow = ncol - 1
    strike = ncol > 2
    ! the start direction of slip's angle: d phi_o = n_o' . dtauf_o / |tauf_o|
    jphi = 0.0_dp
    if (p%mean .and. .not. fresh) then
      tn2 = o%tauf(1) * o%tauf(1) + o%tauf(2) * o%tauf(2)
      jphi = (o%tauf(1) * jo%tauf(:, 2) - o%tauf(2) * jo%tauf(:, 1)) / tn2
    end if
    ! the wear driver's derivatives through the start state: G = a_w Q1 + g_slip Q2 (a plane
    ! that wears; the law gives the drivers' derivatives only there), with the start weight's
    ! derivative dg
    d_drv = 0.0_dp
    if ((coupled_wear .or. explicit_wear) .and. .not. fresh) then
      dg = 0.0_dp
      if (explicit_wear) then
        dg = jo%dmg * abs(o%tauf(1)) + o%dmg * jo%atauf1
      else if (trapezoidal) then
        dsn_o = 0.0_dp
        ! (closed at the tie s_kn = 0, SPEC D13, as the plane law)
        x_o = -(c_o * s_o(1) + sn_o * (cp * s_o(2) + sp * s_o(3)))
        if (s_o(1) * mat%inv_h_n < 1.0_dp .and. &
            .not. -contact_round_off(cp, sp, c_o, sn_o, s_o) > x_o) &
          dsn_o = -(mat%mu_eff * mat%kn) * (h_start * [c_o, sn_o * cp, sn_o * sp] + &
                   (-sn_o * s_o(1) + c_o * (cp * s_o(2) + sp * s_o(3))) * jo%theta)
        dg = 0.5_dp * (jo%dmg * mu_p_o + o%dmg * dsn_o)
      end if
      if (trapezoidal) then
        h1 = -(p%g_wear_end(2:3) - p%dmg_wear_end * p%g_dmg(2:3))
        hdmg1 = merge(p%dmg_wear_end, 0.0_dp, p%dmg_kept)
        phi1 = p%phi_wear_end
        h2 = -p%g_wear_start(2:3)
        phi2 = p%phi_wear_start
        q2 = p%wear_start
      else
        h1 = -(p%g_wfric_dip(2:3) - p%dmg_wfric_dip * p%g_dmg(2:3))
        hdmg1 = merge(p%dmg_wfric_dip, 0.0_dp, p%dmg_kept)
        phi1 = 0.0_dp
        h2 = -p%g_slip_dip(2:3)
        phi2 = 0.0_dp
        q2 = p%slip_dip
      end if
      if (strike) then
        d_drv = a_w * (h1(1) * jo%sf(:, 1) + h1(2) * jo%sf(:, 2) + phi1 * jphi + hdmg1 * jo%dmg) + &
                g_slip * (h2(1) * jo%sf(:, 1) + h2(2) * jo%sf(:, 2) + phi2 * jphi) + dg * q2
      else
        ! (no strike slip, no start direction's turn)
        d_drv(1:2) = a_w * (h1(1) * jo%sf(1:2, 1) + hdmg1 * jo%dmg(1:2)) + &
                     g_slip * (h2(1) * jo%sf(1:2, 1)) + dg(1:2) * q2
      end if
    end if
    ! d sl at fixed angle, then the angle the traction is taken at
    rot = frame_rows(cp, sp, c, sn)
    do j = 1, ncol
      dsl(:, j) = h_end * rot(:, j)
    end do
    if (coupled_wear) then
      do j = 1, ncol
        if (pinned) then
          dtheta(j) = -dsl(1, j) / p%sl(2)
          jn%zeta(j) = dtheta(j) / thp
        else
          gdsl = dot_local(g_drv, dsl(:, j), strike)
          if (fresh) then
            jn%zeta(j) = gdsl / fp
          else
            jn%zeta(j) = (jo%zeta(j) + gdsl + d_drv(j)) / fp
          end if
          dtheta(j) = thp * jn%zeta(j)
        end if
        jn%theta(j) = dtheta(j)
      end do
    else
      dtheta = jo%theta
    end if
    do j = 1, ncol
      dsl(1, j) = dsl(1, j) + p%sl(2) * dtheta(j)
      dsl(2, j) = dsl(2, j) - p%sl(1) * dtheta(j)
    end do
    if (.not. coupled_wear) then
      do j = 1, ncol
        gdsl = dot_local(g_drv, dsl(:, j), strike)
        if (fresh) then
          jn%zeta(j) = gdsl
        else
          jn%zeta(j) = jo%zeta(j) + gdsl + d_drv(j)
        end if
        jn%theta(j) = jo%theta(j)
        if (explicit_wear) jn%theta(j) = thp * jn%zeta(j)
      end do
    end if
    ! the end state, and the traction: d sig_loc, then R^T d sig_loc + (d sig_k / d theta at
    ! fixed sl) d theta. d |tau_f,1| = sign(tau_f,1) d tau_f,1; where tau_f,1 = 0 on a plane
    ! closed at the tie (SPEC D13: tau_f = mu p n with mu p = 0, mu p >= 0 on the closed side)
    ! the sign is n_1's, which d tau_f,1 / d s_kn = -mu K_n n_1 carries (a free or sticking
    ! plane: 0 there)
    negative_tauf1 = p%tauf(1) < 0.0_dp .or. &
                     (.not. p%tauf(1) > 0.0_dp .and. p%g_tauf(1, 1) > 0.0_dp)
    dsig_dth = p%sig_loc(1) * rot(2, :) - p%sig_loc(2) * rot(1, :)
    if (strike) k_k = 0.0_dp
    do j = 1, ncol
      jn%dmg(j) = dot_local(p%g_dmg, dsl(:, j), strike)
      jn%beta(j) = dot_local(p%g_beta, dsl(:, j), strike)
      do i = 1, nrow
        gtau(i) = dot_local(p%g_tauf(:, i), dsl(:, j), strike)
        jn%tauf(j, i) = gtau(i)
        jn%sf(j, i) = dot_local(p%g_sf(:, i), dsl(:, j), strike)
      end do
      do i = 1, ncol
        dsig_loc(i) = dot_local(p%k_loc(i, :), dsl(:, j), strike)
      end do
      if (.not. fresh) then
        if (p%dmg_kept) then
          jn%dmg(j) = jn%dmg(j) + jo%dmg(j)
          dsig_loc(1:2) = dsig_loc(1:2) + p%dmg_sig(1:2) * jo%dmg(j)
          if (strike) dsig_loc(3) = dsig_loc(3) + p%dmg_sig(3) * jo%dmg(j)
        end if
        if (p%beta_kept) jn%beta(j) = jn%beta(j) + jo%beta(j)
        do i = 1, nrow
          jn%tauf(j, i) = jn%tauf(j, i) - p%g_tauf(2, i) * jo%sf(j, 1)
          jn%sf(j, i) = jn%sf(j, i) - p%g_sf(2, i) * jo%sf(j, 1)
          if (strike) then
            jn%tauf(j, i) = jn%tauf(j, i) - p%g_tauf(3, i) * jo%sf(j, 2) + p%phi_tauf(i) * jphi(j)
            jn%sf(j, i) = jn%sf(j, i) - p%g_sf(3, i) * jo%sf(j, 2) + jo%sf(j, i) + &
                          p%phi_sf(i) * jphi(j)
          else
            jn%sf(j, i) = jn%sf(j, i) + jo%sf(j, i)
          end if
          dsig_loc(1 + i) = dsig_loc(1 + i) + p%dmg * (jn%tauf(j, i) - gtau(i))
        end do
      end if
      if (negative_tauf1) then
        jn%atauf1(j) = -jn%tauf(j, 1)
      else
        jn%atauf1(j) = jn%tauf(j, 1)
      end if
      if (strike) then
        k_k(:, j) = to_macro(cp, sp, c, sn, dsig_loc) + dsig_dth * dtheta(j)
      else
        ! (every azimuth 0: to_macro's turn by theta in (n, t1) alone)
        k_k(1, j) = (c * dsig_loc(1) - sn * dsig_loc(2)) + dsig_dth(1) * dtheta(j)
        k_k(2, j) = (sn * dsig_loc(1) + c * dsig_loc(2)) + dsig_dth(2) * dtheta(j)
      end if
    end do
  end subroutine chain_plane

  !> The explicit scheme's chain where the plane ends the sub-increment at the tie s_kn = 0
  !> (within its round-off, contact_round_off; chain_plane gave the closed side, SPEC D13).
  !> Column j is the one-sided derivative along the direction side(j) e_j that closed the plane
  !> where it first ended a sub-increment at the tie (D13 there); at each later tie the side is
  !> the one that direction's perturbation of s_kn enters, d s_kn = h_end m_j + s_kt1 d
  !> theta_o, the open one where it opens the plane. Where the plane follows its surface (it
  !> wears whenever it closes, the start weight D_o |tau_f,1| of the next sub-increment, and
  !> turns until it just loses contact), the closed side's chain over sub-increments larger
  !> than the wear's turn can follow overshoots into the open side: the closed side's
  !> derivatives alone grow without bound (a factor -(1 - gain) per sub-increment), while
  !> the perturbed plane opens and stops wearing. The open side's derivatives are those of
  !> the plane law at s_kn = 0 on the open side (free, no friction traction), through
  !> chain_plane; the values are unchanged.
  pure subroutine chain_at_tie(mat, cp, sp, c, sn, o, jo, p, wears, a_w, g_slip, mu_p_o, &
                               mean_o, n_o, thp, fp, s_o, h_start, h_end, ncol, k_k, jn)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp, c, sn   !< the azimuth's frame, the (start) angle's
    type(plane_start_3d_t), intent(in) :: o
    type(plane_chain_t), intent(in) :: jo
    type(plane_law_3d_t), intent(in) :: p
    logical, intent(in) :: wears
    real(dp), intent(in) :: a_w, g_slip, mu_p_o, thp, fp, s_o(3), h_start, h_end
    logical, intent(in) :: mean_o   !< D14 (plane_law_3d_parts), from the start direction n_o
    real(dp), intent(in) :: n_o(2)
    integer, intent(in) :: ncol
    real(dp), intent(inout) :: k_k(3, 3)
    type(plane_chain_t), intent(inout) :: jn
    type(plane_law_3d_t) :: q
    type(plane_chain_t) :: jq
    real(dp) :: sl(3), g_drv(3), k_q(3, 3), m(3), d_kn, side
    integer :: j
    logical :: fresh

    fresh = .not. h_start > 0.0_dp
    ! (the open side's derivatives: the law at s_kn = 0 with a tie below it)
    sl = p%sl
    sl(1) = 0.0_dp
    call plane_law_3d_parts(mat, sl, -1.0_dp, o, mean_o, n_o, wears, .true., .true., .false., &
                            ncol < 3, q)
    g_drv = 0.0_dp
    if (wears) g_drv = a_w * q%g_wfric_dip + g_slip * q%g_slip_dip
    jq = jn
    call chain_plane(mat, cp, sp, c, sn, c, sn, s_o, o, jo, q, .false., wears, .false., a_w, &
                     g_slip, mu_p_o, g_drv, thp, fp, h_start, h_end, ncol, .false., k_q, jq)
    m = [c, sn * cp, sn * sp]
    do j = 1, ncol
      d_kn = h_end * m(j)
      side = 0.0_dp
      if (.not. fresh) then
        d_kn = d_kn + p%sl(2) * jo%theta(j)
        side = jo%side(j)
      end if
      if (side > 0.0_dp .or. side < 0.0_dp) then
        if (side * d_kn > 0.0_dp) then
          jn%beta(j) = jq%beta(j)
          jn%dmg(j) = jq%dmg(j)
          jn%sf(j, :) = jq%sf(j, :)
          jn%zeta(j) = jq%zeta(j)
          jn%theta(j) = jq%theta(j)
          jn%tauf(j, :) = jq%tauf(j, :)
          jn%atauf1(j) = jq%atauf1(j)
          k_k(:, j) = k_q(:, j)
        end if
      else if (d_kn > 0.0_dp .or. d_kn < 0.0_dp) then
        side = -sign(1.0_dp, d_kn)
      end if
      jn%side(j) = side
    end do
  end subroutine chain_at_tie

  !> g . v of two local vectors (the order of dot_product; any stride: a row of k_loc without a
  !> copy); without `strike` (a chain in the plane (n, t1), where v(3) = 0) the first two terms
  !> alone.
  pure real(dp) function dot_local(g, v, strike) result(d)
    real(dp), intent(in) :: g(:), v(:)
    logical, intent(in) :: strike
    d = g(1) * v(1) + g(2) * v(2)
    if (strike) d = d + g(3) * v(3)
  end function dot_local

  !> The plane law at the angle of frame (c, sn) (`flat`: the macro one), with its traction,
  !> tangent and energies if `traction` (else plane_traction_3d gives them), and the scheme's
  !> wear driver G with
  !> d G / d sl: a_end D |tau_f,1| |d sf_1| + g_slip |d sf_1| (explicit, implicit), a_end
  !> wear_end + g_slip wear_start (trapezoidal: the dip component of D_o mu p_o n at the start);
  !> d G / d sl only with `drivers` (else 0). `terms`: the trapezoidal wear terms are wanted
  !> (plane_law_3d_parts; with `trapezoidal`, where D14's direction was taken or g_slip > 0:
  !> without them a trapezoidal driver is the implicit one's form, g_slip = 0 and no D14).
  pure subroutine evaluate(mat, cp, sp, s, o, mean_o, n_o, a_end, g_slip, trapezoidal, terms, &
                           drivers, chain, traction, in_plane, c, sn, flat, p, drv, g_drv, &
                           tie)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp, s(3), a_end, g_slip, c, sn
    logical, intent(in) :: mean_o   !< D14 (plane_law_3d_parts), from the start direction n_o
    real(dp), intent(in) :: n_o(2)
    type(plane_start_3d_t), intent(in) :: o
    logical, intent(in) :: trapezoidal, terms, drivers, chain, traction
    logical, intent(in) :: in_plane   !< plane_law_3d_parts'
    logical, intent(in) :: flat   !< flat_frame(cp, sp, c, sn)
    real(dp), intent(out) :: drv, g_drv(3)
    type(plane_law_3d_t), intent(out) :: p
    real(dp), intent(out) :: tie   !< the round-off of s_kn (local_frame)
    real(dp) :: sl(3)
    ! (one call of the law: inlined once)
    if (flat) then
      sl = s
      tie = contact_round_off(cp, sp, c, sn, s)
    else
      call local_frame(cp, sp, c, sn, s, sl, tie)
    end if
    call plane_law_3d_parts(mat, sl, tie, o, mean_o, n_o, drivers, chain, traction, terms, &
                            in_plane, p)
    if (trapezoidal .and. terms) then
      drv = a_end * p%wear_end + g_slip * p%wear_start
      if (drivers) then
        ! (in the plane (n, t1) the s_kt2 entry is not wanted)
        g_drv(1:2) = a_end * p%g_wear_end(1:2) + g_slip * p%g_wear_start(1:2)
        g_drv(3) = 0.0_dp
        if (.not. in_plane) g_drv(3) = a_end * p%g_wear_end(3) + g_slip * p%g_wear_start(3)
      end if
    else
      drv = a_end * p%wfric_dip + g_slip * p%slip_dip
      if (drivers) then
        ! (the implicit scheme has no start weight: g_slip = 0)
        if (g_slip > 0.0_dp) then
          g_drv = a_end * p%g_wfric_dip + g_slip * p%g_slip_dip
        else
          g_drv = a_end * p%g_wfric_dip
        end if
      end if
    end if
    if (.not. drivers) g_drv = 0.0_dp
  end subroutine evaluate

  !> dG / d theta at fixed s of a driver with d G / d sl = g_drv: g_drv . d sl / d theta, d sl /
  !> d theta = (s_kt1, -s_kn, 0).
  pure real(dp) function angle_slope(g_drv, sl)
    real(dp), intent(in) :: g_drv(3), sl(3)
    angle_slope = g_drv(1) * sl(2) - g_drv(2) * sl(1)
  end function angle_slope

  !> R = d sl / d s: the rows m, e, q of a plane of azimuth frame (cp, sp) at angle theta (frame
  !> c, sn).
  pure function frame_rows(cp, sp, c, sn) result(rot)
    real(dp), intent(in) :: cp, sp, c, sn
    real(dp) :: rot(3, 3)
    rot(1, :) = [c, sn * cp, sn * sp]
    rot(2, :) = [-sn, c * cp, c * sp]
    rot(3, :) = [0.0_dp, -sp, cp]
  end function frame_rows

  !> tangent += w R^T (K_loc + u (x) v) R, the plane's derivative at fixed angle and, where
  !> `angle`, the angle's term d sig_k / d theta (x) d theta / d s = R^T (u (x) v) R with u = d
  !> sig_loc / d theta, v = d theta / d sl in the plane's frame, with R = d sl / d s
  !> (rows m, e, q) = B A: B turns by theta in (n, d) (to_macro's first rotation), A by the
  !> azimuth in (t1, t2); each turns both sides in one plane of the frame, the columns
  !> (B^T K_loc), then the rows ((B^T K_loc) B); the azimuth's only where phi /= 0, none for a
  !> flat plane. The entries are turned and added as scalars (in registers, not through a
  !> 3x3 array in memory); where the normal row of K_loc is 0 off its diagonal (`normal_row`:
  !> damage does not grow), its products are left out (the same values).
  pure subroutine add_turned(cp, sp, c, sn, flat, k_loc, normal_row, angle, u, v, w, tangent)
    real(dp), intent(in) :: cp, sp, c, sn
    logical, intent(in) :: flat   !< flat_frame(cp, sp, c, sn)
    real(dp), intent(in) :: k_loc(3, 3)
    logical, intent(in) :: normal_row   !< k_loc(1, 2:3) = 0
    logical, intent(in) :: angle
    real(dp), intent(in) :: u(3), v(3), w
    real(dp), intent(inout) :: tangent(3, 3)
    real(dp) :: a11, a21, a31, a12, a22, a32, a13, a23, a33
    a11 = k_loc(1, 1)
    a21 = k_loc(2, 1)
    a31 = k_loc(3, 1)
    a12 = k_loc(1, 2)
    a22 = k_loc(2, 2)
    a32 = k_loc(3, 2)
    a13 = k_loc(1, 3)
    a23 = k_loc(2, 3)
    a33 = k_loc(3, 3)
    if (angle) then
      a11 = a11 + u(1) * v(1)
      a21 = a21 + u(2) * v(1)
      a31 = a31 + u(3) * v(1)
      a12 = a12 + u(1) * v(2)
      a22 = a22 + u(2) * v(2)
      a32 = a32 + u(3) * v(2)
      a13 = a13 + u(1) * v(3)
      a23 = a23 + u(2) * v(3)
      a33 = a33 + u(3) * v(3)
    end if
    if (.not. flat) then
      ! by theta in the plane of the indices 1 and 2: each column's pair, then each row's
      call turn_pair(c, sn, a11, a21)
      if (normal_row) then
        ! (turn_pair's values with a12 = a13 = 0)
        a12 = 0.0_dp - sn * a22
        a22 = c * a22
        a13 = 0.0_dp - sn * a23
        a23 = c * a23
      else
        call turn_pair(c, sn, a12, a22)
        call turn_pair(c, sn, a13, a23)
      end if
      call turn_pair(c, sn, a11, a12)
      call turn_pair(c, sn, a21, a22)
      call turn_pair(c, sn, a31, a32)
      if (sp < 0.0_dp .or. sp > 0.0_dp .or. cp < 1.0_dp) then
        ! by the azimuth in the plane of the indices 2 and 3
        call turn_pair(cp, sp, a21, a31)
        call turn_pair(cp, sp, a22, a32)
        call turn_pair(cp, sp, a23, a33)
        call turn_pair(cp, sp, a12, a13)
        call turn_pair(cp, sp, a22, a23)
        call turn_pair(cp, sp, a32, a33)
      end if
    end if
    tangent(1, 1) = tangent(1, 1) + w * a11
    tangent(2, 1) = tangent(2, 1) + w * a21
    tangent(3, 1) = tangent(3, 1) + w * a31
    tangent(1, 2) = tangent(1, 2) + w * a12
    tangent(2, 2) = tangent(2, 2) + w * a22
    tangent(3, 2) = tangent(3, 2) + w * a32
    tangent(1, 3) = tangent(1, 3) + w * a13
    tangent(2, 3) = tangent(2, 3) + w * a23
    tangent(3, 3) = tangent(3, 3) + w * a33
  end subroutine add_turned

  !> The plane's frame is the macro one: azimuth and angle 0 exactly (cos 1, sin 0), where the
  !> rotations are the identity (the same values; a flat plane of a RIA whose azimuths are 0).
  pure logical function flat_frame(cp, sp, c, sn)
    real(dp), intent(in) :: cp, sp, c, sn
    ! (sn first: most planes are inclined)
    flat_frame = .false.
    if (abs(sn) <= 0.0_dp) flat_frame = cp >= 1.0_dp .and. c >= 1.0_dp .and. abs(sp) <= 0.0_dp
  end function flat_frame

  !> The pair (x, y) of a vector turned by (cs, sn) = (cos, sin) of an angle in its plane: (cs x
  !> - sn y, sn x + cs y).
  pure subroutine turn_pair(cs, sn, x, y)
    real(dp), intent(in) :: cs, sn
    real(dp), intent(inout) :: x, y
    real(dp) :: x_o
    x_o = x
    x = cs * x_o - sn * y
    y = sn * x_o + cs * y
  end subroutine turn_pair

end module interlock_step_3d
