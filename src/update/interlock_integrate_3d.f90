!> The update of one material point of a three-dimensional interface over one increment (SPEC
!> section 9): every scheme, error-controlled substepping, D7 separation, the effect switches,
!> and the exact 3x3 tangent of what is computed, in plain reals: one step or each
!> sub-increment by interlock_step_3d (the plane law of interlock_plane_law_3d with its
!> derivatives written out, the wear equation's root differentiated implicitly, each plane's
!> state derivatives carried over sub-increments). A history that
!> stays in the (n, t1) plane on a RIA whose azimuths are all 0 is the 2D law's: it goes to
!> interlock_update, and only the strike stiffness is added (SPEC section 9: the T2-T2 entry of
!> the tangent), so that such a point pays for the third component almost nothing.
module interlock_integrate_3d
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp, is_finite_value, within_separation_bound, separation_bound
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes, n_schemes, &
      scheme_list, scheme_explicit, scheme_trapezoidal
  use interlock_numbers, only: format_real, format_integer
  use interlock_state, only: interlock_state_3d_t
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, status_local_failure
  use interlock_geometry, only: contact_area
  use interlock_plane_law, only: plane_frame
  use interlock_plane_law_3d, only: slides_at_start
  use interlock_step_3d, only: plane_chain_t, step_3d, chain_bounded
  use interlock_integrate, only: interlock_update
  use interlock_general_update, only: largest_increments
  use interlock_substep_control, only: next_sub_increment, count_attempt, after_failure, &
      keep_trial, next_size, check_chain
  implicit none
  private
  public :: interlock_update_3d, general_update_3d


contains

  !> Integrate from `old` to the relative displacement s = (s_N, s_T1, s_T2) [mm]; the contract
  !> of interlock_update (interlock_integrate) with three components: `new` the end state,
  !> `sigma` the traction (sigma_N, sigma_T1, sigma_T2) [MPa], `tangent` = d sigma / d s.
  pure subroutine interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    real(dp) :: tangent_2d(2, 2)

    if (mat%prepared .and. solver%substep_tol <= 0.0_dp .and. in_dip_planes(mat, s, old)) then
      call interlock_update(mat, solver, s(1:2), old%interlock_state_t, new%interlock_state_t, &
                            sigma(1:2), tangent_2d, info)
      if (info%status /= status_ok) then
        new%sf_strike = old%sf_strike
        new%tauf_strike = old%tauf_strike
        new%s_t2 = old%s_t2
        new%sigma_t2 = old%sigma_t2
        sigma(3) = old%sigma_t2
        tangent = 0.0_dp
        return
      end if
      if (info%substeps == 1) then
        tangent(1:2, 1:2) = tangent_2d
        tangent(3, 1:2) = 0.0_dp
        tangent(1:2, 3) = 0.0_dp
        tangent(3, 3) = strike_stiffness(mat, solver%scheme, s, old, new)
        sigma(3) = 0.0_dp
        new%sf_strike(1:mat%n_planes) = 0.0_dp
        new%tauf_strike(1:mat%n_planes) = 0.0_dp
        new%s_t2 = s(3)
        new%sigma_t2 = 0.0_dp
        return
      end if
      ! (a one-step solve that failed and was taken on sub-increments: the strike stiffness is
      ! then a chain; the general path computes it)
    end if
    info%status = status_ok
    info%newton_iterations = 0
    info%substeps = 1
    info%attempts = 1
    info%max_angle_increment = 0.0_dp
    call general_update_3d(mat, solver, s, old, new, sigma, tangent, info)
  end subroutine interlock_update_3d

  !> The point stays in the (n, t1) plane of a RIA whose azimuths are all 0: s_T2 = 0 at the
  !> start and the end and no plane has a strike component of slip or friction traction
  !> (then none arises, by the symmetry s_T2 -> -s_T2 of the law).
  pure logical function in_dip_planes(mat, s, old)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    integer :: k
    in_dip_planes = .false.
    if (.not. mat%azimuths_zero) return
    if (.not. (zero_bits(s(3)) .and. zero_bits(old%s_t2))) return
    do k = 1, mat%n_planes
      if (.not. (zero_bits(old%sf_strike(k)) .and. zero_bits(old%tauf_strike(k)))) return
    end do
    in_dip_planes = .true.
  end function in_dip_planes

  !> x is +0 or -0, tested on its bits (no comparison: a NaN raises no exception).
  elemental logical function zero_bits(x)
    real(dp), intent(in) :: x
    zero_bits = ibclr(transfer(x, 0_int64), 63) == 0_int64
  end function zero_bits

  !> d sigma_T2 / d s_T2 of a one-step update in the (n, t1) plane (azimuths 0): each plane's
  !> d sigma_kt,2 / d s_kt,2 = (1 - D) K_t + D k_f, k_f = d tau_f,2 / d s_kt,2: K_t sticking,
  !> K_t mu p / |tau_tr| sliding (the radial return's transverse stiffness), 0 where the
  !> damaged part is free; the damage and the angle do not change to first order in s_T2.
  !> Sliding, the trial traction is the friction traction plus K_t times the slip of the step
  !> (both along the slip), so k_f = K_t |tau_f| / (|tau_f| + K_t |sf - sf_o|), which also
  !> gives K_t while sticking: no frame is needed but where tau_f = 0 (a free plane, or a
  !> closed one exactly at its trial traction 0).
  pure real(dp) function strike_stiffness(mat, scheme, s, old, new) result(k33)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old, new
    real(dp) :: area, darea, c, sn, sl_n, atau, k_f, gam, slip
    integer :: k, n_eval
    k33 = 0.0_dp
    area = 1.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)
    if (area <= 0.0_dp) return
    n_eval = merge(1, mat%n_planes, mat%flat)
    do k = 1, n_eval
      atau = abs(new%tauf(k))
      if (atau > 0.0_dp) then
        slip = mat%kt * abs(new%sf(k) - old%sf(k))
        if (scheme == scheme_trapezoidal .and. slip > 0.0_dp .and. &
            ((new%tauf(k) > 0.0_dp) .eqv. (old%tauf(k) > 0.0_dp)) .and. &
            plane_slides_at_start(mat, k, old)) then
          ! D14's mean-direction rule, n_new = n_o turned by 2 atan(b / a), b = K_t s_kt,2
          ! n_o,1, a = |tau_tr| + mu p: d tau_f,2 / d s_kt,2 = 2 K_t mu p / (|tau_tr| + mu p)
          k_f = mat%kt * (2.0_dp * atau / (2.0_dp * atau + slip))
        else
          k_f = mat%kt * (atau / (atau + slip))
        end if
      else
        ! closed (mu p > 0: sticking at a zero trial traction, so sf = sf_o) or free; the angle
        ! the traction was computed at: the start one in the explicit scheme. A free plane
        ! whose slip changed is open: no frame needed.
        k_f = 0.0_dp
        if (mat%use_friction .and. .not. (new%sf(k) < old%sf(k) .or. new%sf(k) > old%sf(k))) then
          if (scheme == scheme_explicit) then
            call plane_frame(mat, k, old%theta(k), c, sn)
          else
            call plane_frame(mat, k, new%theta(k), c, sn)
          end if
          sl_n = c * s(1) + sn * s(2)
          if (sl_n < 0.0_dp) k_f = mat%kt
        end if
      end if
      gam = merge(1.0_dp, mat%gamma_hat(k), mat%flat)
      k33 = k33 + gam * area * ((1.0_dp - new%damage(k)) * mat%kt + new%damage(k) * k_f)
    end do
  end function strike_stiffness

  !> Plane k of a state in the (n, t1) plane slides: its friction traction is mu p of its
  !> separation at its angle (D14's test, as mean_direction_return takes it; a separated state
  !> does not slide).
  pure logical function plane_slides_at_start(mat, k, old)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    type(interlock_state_3d_t), intent(in) :: old
    real(dp) :: c, sn, mu_p_o
    plane_slides_at_start = .false.
    if (old%s(1) * mat%inv_h_n >= 1.0_dp) return
    call plane_frame(mat, k, old%theta(k), c, sn)
    mu_p_o = mat%mu_eff * mat%kn * max(0.0_dp, -(c * old%s(1) + sn * old%s(2)))
    plane_slides_at_start = slides_at_start(abs(old%tauf(k)), mu_p_o)
  end function plane_slides_at_start

  !> The general three-dimensional update (interlock_update_3d's contract) for any material,
  !> solver and history. `info` comes reset.
  pure subroutine general_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info

    if (.not. mat%prepared) then
      call fail(old, new, sigma, tangent, info, status_bad_input, &
                'the material has not been prepared (call interlock_material_prepare)')
      return
    end if
    if (solver%scheme < 1 .or. solver%scheme > n_schemes) then
      call fail(old, new, sigma, tangent, info, status_bad_input, 'scheme = ' // &
                format_integer(solver%scheme) // ' is inadmissible: admissible ' // &
                scheme_list())
      return
    end if
    if (.not. all(within_separation_bound(s))) then
      call fail(old, new, sigma, tangent, info, status_bad_input, &
                'the relative displacement s = (' // format_real(s(1)) // ', ' // &
                format_real(s(2)) // ', ' // format_real(s(3)) // &
                ') mm is inadmissible: admissible |s_N|, |s_T1|, |s_T2| <= ' // &
                format_real(separation_bound) // ' mm')
      return
    end if

    if (solver%substep_tol > 0.0_dp) then
      call substep(mat, solver, s, old, new, tangent, info, solver%substep_tol, 1.0_dp)
    else
      call single_step(mat, solver, s, old, new, tangent, info)
      if (info%status == status_local_failure) then
        ! The one-step solve failed: retry on sub-increments, split only as failures require.
        info%status = status_ok
        call substep(mat, solver, s, old, new, tangent, info, huge(1.0_dp), 0.5_dp)
      end if
    end if
    if (info%status /= status_ok) then
      call fail(old, new, sigma, tangent, info, info%status, info%message)
      return
    end if
    sigma = [new%sigma(1), new%sigma(2), new%sigma_t2]
    if (.not. is_finite_value(sum(abs(sigma)) + sum(abs(tangent)))) then
      call fail(old, new, sigma, tangent, info, status_local_failure, &
                'the traction or tangent is not finite: retry with a smaller increment')
      return
    end if
    call largest_increments(mat%n_planes, old%interlock_state_t, new%interlock_state_t, info)
  end subroutine general_update_3d

  !> Report a failure: `new` = `old`, the traction at the start, no tangent.
  pure subroutine fail(old, new, sigma, tangent, info, code, message)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    integer, intent(in) :: code
    character(len=*), intent(in) :: message
    info%status = code
    info%message = message
    info%max_damage_increment = 0.0_dp
    info%max_angle_increment = 0.0_dp
    new = old
    sigma = [old%sigma(1), old%sigma(2), old%sigma_t2]
    tangent = 0.0_dp
  end subroutine fail

  !> The whole increment as one step, in plain reals (interlock_step_3d); a wear equation
  !> without solution, or a derivative beyond the stable bound, is reported as
  !> status_local_failure (for the caller to retry on sub-increments; `new` is then written
  !> again or set to `old`).
  pure subroutine single_step(mat, solver, s, old, new, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    type(plane_chain_t) :: unused(1)
    real(dp) :: err
    integer :: it
    logical :: solved, allowed
    info%attempts = 0
    call count_attempt(info, solver%max_substeps, allowed)
    if (.not. allowed) return
    call step_3d(mat, solver, s, old, new, tangent, it, solved, .false., 0.0_dp, 1.0_dp, unused, &
                 unused, .false., err)
    info%newton_iterations = max(info%newton_iterations, it)
    if (.not. solved) then
      info%status = status_local_failure
      info%message = 'the local wear equation has no solution'
      tangent = 0.0_dp
      return
    end if
    call check_chain(mat, maxval(abs(tangent)), info, allowed)
    if (.not. allowed) return
    info%substeps = 1
  end subroutine single_step

  !> Sub-increments linear in s, as the 2D update takes them (interlock_general_update:substep,
  !> the same control and the same sizes): tol finite, error control on the embedded wear
  !> estimate; tol = huge, sizes split only as failures require. Each plane's state carries its
  !> derivatives with respect to the end of the increment from one sub-increment to the next
  !> (interlock_step_3d's chain), so that the tangent is the exact one of the chain.
  pure subroutine substep(mat, solver, s, old, new, tangent, info, tol, h_first)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), tol, h_first
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    type(interlock_state_3d_t) :: cur, trial
    type(plane_chain_t) :: jo(max_planes), jn(max_planes)
    real(dp) :: ds(3), s_old(3), s_end(3), alpha, h, a_end, err, chain_peak, tangent_trial(3, 3)
    integer :: it, n_accepted, k
    logical :: solved, stable, control, kept, give_up, allowed

    control = tol >= 0.0_dp .and. tol < huge(1.0_dp)
    s_old = [old%s(1), old%s(2), old%s_t2]
    ds = s - s_old
    cur = old
    do k = 1, mat%n_planes
      jo(k) = plane_chain_t(0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp)
    end do
    alpha = 0.0_dp
    h = h_first
    n_accepted = 0
    info%attempts = 0
    tangent = 0.0_dp
    chain_peak = 0.0_dp
    do while (alpha < 1.0_dp)
      call next_sub_increment(alpha, h, a_end)
      s_end = s_old + a_end * ds
      if (a_end >= 1.0_dp) s_end = s
      call count_attempt(info, solver%max_substeps, allowed)
      if (.not. allowed) return
      trial = cur
      call step_3d(mat, solver, s_end, cur, trial, tangent_trial, it, solved, .true., alpha, &
                   a_end, jo, jn, .true., err)
      info%newton_iterations = max(info%newton_iterations, it)
      stable = .true.
      if (solved) stable = chain_bounded(jn, mat%n_planes)
      if (.not. (solved .and. stable)) then
        call after_failure(solved, h, info, give_up)
        if (give_up) return
        cycle
      end if
      kept = keep_trial(control, err, tol, h)
      if (kept) then
        cur = trial
        jo(1:mat%n_planes) = jn(1:mat%n_planes)
        tangent = tangent_trial
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
end module interlock_integrate_3d
