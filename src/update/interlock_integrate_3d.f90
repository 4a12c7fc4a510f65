!> The update of one material point of a three-dimensional interface over one increment (SPEC
!> section 9): every scheme, error-controlled substepping, D7 separation, the effect switches,
!> and the exact 3x3 tangent of what is computed, in plain reals, by the general path
!> (interlock_general_path, which the 2D update shares). A history that
!> stays in the (n, t1) plane on a RIA whose azimuths are all 0 is the 2D law's: it goes to
!> interlock_update, and only the strike stiffness is added (SPEC section 9: the T2-T2 entry of
!> the tangent), so that such a point pays for the third component almost nothing.
module interlock_integrate_3d
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp, within_separation_bound
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      scheme_implicit, scheme_trapezoidal
  use interlock_state, only: interlock_state_3d_t
  use interlock_status, only: interlock_info_t, status_ok
  use interlock_geometry, only: contact_area
  use interlock_plane_law, only: plane_frame
  use interlock_plane_law_3d, only: slides_at_start
  use interlock_integrate, only: interlock_update
  use interlock_general_path, only: general_update_3d
  use interlock_kernels_3d, only: explicit_step_3d, explicit_step_3d_estimate
  use interlock_kernels_3d_coupled, only: coupled_step_3d, coupled_step_3d_estimate
  use interlock_kernels_3d_trapezoidal, only: trapezoidal_step_3d, trapezoidal_step_3d_estimate
  use interlock_substep_control, only: largest_increments, stiffness_scale, size_after_whole
  implicit none
  private
  public :: interlock_update_3d


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
    integer :: iterations
    logical :: done

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
    ! The explicit scheme's kernel (interlock_kernels_3d), the implicit one's
    ! (interlock_kernels_3d_coupled) and the trapezoidal one's (interlock_kernels_3d_trapezoidal)
    ! where they apply; the general path takes what they decline, and reports bad input. Their
    ! tangent stays within the general path's stable bound on one step
    ! (interlock_substep_control:check_chain).
    if ((solver%scheme == scheme_explicit .or. solver%scheme == scheme_implicit .or. &
         solver%scheme == scheme_trapezoidal) .and. &
        mat%prepared .and. solver%substep_tol <= 0.0_dp .and. all(within_separation_bound(s))) then
      if (solver%scheme == scheme_explicit) then
        call explicit_step_3d(mat, s, old, 1.0e6_dp * stiffness_scale(mat), new, sigma, &
                              tangent, done)
        iterations = 0
      else if (solver%scheme == scheme_implicit) then
        call coupled_step_3d(mat, solver, s, old, 1.0e6_dp * stiffness_scale(mat), new, sigma, &
                             tangent, iterations, done)
      else
        call trapezoidal_step_3d(mat, solver, s, old, 1.0e6_dp * stiffness_scale(mat), new, &
                                 sigma, tangent, iterations, done)
      end if
      if (done) then
        call one_step_report(info)
        info%newton_iterations = iterations
        call largest_increments(mat%n_planes, old%interlock_state_t, new%interlock_state_t, &
                                info)
        return
      end if
    end if
    if (solver%substep_tol > 0.0_dp .and. mat%prepared .and. all(within_separation_bound(s))) then
      call controlled_update(mat, solver, s, old, new, sigma, tangent, info)
      return
    end if
    call one_step_report(info)
    info%max_angle_increment = 0.0_dp
    call general_update_3d(mat, solver, s, old, new, sigma, tangent, info)
  end subroutine interlock_update_3d

  !> An error-controlled update (substep_tol > 0) of a prepared material within the separation
  !> bound: the whole increment by the scheme's one-step kernel first, with its embedded error
  !> estimate (the general path's first trial, computed on the way); kept as one step where the
  !> kernel takes it and the estimate is within the tolerance, else the general path's
  !> sub-increments (interlock_general_path:general_update_3d), the first one sized from the
  !> estimate (that trial counted among the attempts, its wear iterations reported), or from
  !> the whole increment where the kernel declined or the scheme has none.
  pure subroutine controlled_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    real(dp) :: limit, err
    integer :: iterations, n
    logical :: done

    limit = 1.0e6_dp * stiffness_scale(mat)
    iterations = 0
    done = .false.
    ! (the schemes whose one-step kernel has an estimating entry)
    select case (solver%scheme)
    case (scheme_explicit)
      call explicit_step_3d_estimate(mat, s, old, limit, new, sigma, tangent, done, err)
    case (scheme_implicit)
      call coupled_step_3d_estimate(mat, solver, s, old, limit, new, sigma, tangent, &
                                    iterations, done, err)
    case (scheme_trapezoidal)
      call trapezoidal_step_3d_estimate(mat, solver, s, old, limit, new, sigma, tangent, &
                                        iterations, done, err)
    end select
    call one_step_report(info)
    info%max_angle_increment = 0.0_dp
    if (.not. done) then
      call general_update_3d(mat, solver, s, old, new, sigma, tangent, info)
      return
    end if
    info%newton_iterations = iterations
    if (err <= solver%substep_tol) then
      ! (interlock_substep_control:largest_increments' report, written out: a further call of
      ! it costs the 2D update's front its inlined copy, interlock-bench part 1)
      n = mat%n_planes
      info%max_damage_increment = maxval(new%damage(1:n) - old%damage(1:n))
      info%max_angle_increment = maxval(abs(new%theta(1:n) - old%theta(1:n)))
      return
    end if
    call general_update_3d(mat, solver, s, old, new, sigma, tangent, info, &
                           size_after_whole(err, solver%substep_tol))
  end subroutine controlled_update

  !> The report of an update taken as one step, before what it finds out: status ok, one
  !> sub-increment in one attempt, no wear iteration.
  pure subroutine one_step_report(info)
    type(interlock_info_t), intent(inout) :: info
    info%status = status_ok
    info%newton_iterations = 0
    info%substeps = 1
    info%attempts = 1
  end subroutine one_step_report

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

end module interlock_integrate_3d
