!> The general update of one material point over one increment (SPEC section 5): the argument
!> checks, the specialised kernel of the material's effect set or the general path, optionally
!> with error-controlled substepping, and the exact algorithmic tangent of what was computed. A
!> failed local solve is retried on sub-increments before it is reported. interlock_update
!> (interlock_integrate) calls it, through kernel_update (a specialised kernel without
!> substepping, with only the checks it needs), for everything but the flat-plane laws it runs
!> itself. A module of its own, compiled as the UMAT's path rather than as the laws
!> (src/CMakeLists.txt): general_update is too large to be inlined into the front, where it
!> would make every call of the small laws pay for saving registers; the small kernel_update
!> is inlined there.
module legacy_general_update
  use interlock_kinds, only: dp, is_finite_value, within_separation_bound, separation_bound
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes, &
      n_schemes, scheme_list, kernel_general
  use interlock_numbers, only: format_real, format_integer
  use interlock_state, only: interlock_state_t
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, status_local_failure
  use interlock_ria, only: ria_step
  use interlock_kernels, only: kernel_step
  use interlock_substep_control, only: next_sub_increment, count_attempt, after_failure, &
      keep_trial, next_size, check_chain
  implicit none
  private
  public :: general_update


contains

  !> interlock_update (its contract) for every material and solver but the flat-plane laws of
  !> interlock_update itself: a specialised kernel without substepping first, with only the
  !> checks it needs (mat%kernel /= kernel_general only in a prepared material; s tested on its
  !> bits, interlock_kinds:within_separation_bound), else general_update. When the kernel does not apply
  !> or its result is not finite, general_update takes the increment again (and reports). A
  !> small procedure of its own: through general_update's checks and frame the full model's
  !> update costs more (interlock-bench's cost rows, docs/bench.md).
  pure subroutine kernel_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    logical :: done
    if (mat%kernel /= kernel_general .and. solver%substep_tol <= 0.0_dp .and. &
        solver%scheme >= 1 .and. solver%scheme <= n_schemes .and. &
        within_separation_bound(s(1)) .and. within_separation_bound(s(2))) then
      call kernel_step(mat, solver, s, old, new, tangent, done, info%newton_iterations)
      if (done) then
        if (finite_response(new%sigma, tangent)) then
          sigma = new%sigma
          call largest_increments(mat%n_planes, old, new, info)
          return
        end if
      end if
    end if
    call general_update(mat, solver, s, old, new, sigma, tangent, info)
  end subroutine kernel_update

  !> interlock_update (its contract) for any material and solver. `info` comes reset by
  !> interlock_update (status ok, no message, counts 1 or 0); the fields set here are the
  !> ones the update finds out.
  pure subroutine general_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    logical :: ok, done
    real(dp) :: err, h_first

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
    if (.not. (within_separation_bound(s(1)) .and. within_separation_bound(s(2)))) then
      call fail(old, new, sigma, tangent, info, status_bad_input, &
                'the relative displacement s = (' // format_real(s(1)) // ', ' // &
                format_real(s(2)) // ') mm is inadmissible: admissible |s_N|, |s_T| <= ' // &
                format_real(separation_bound) // ' mm')
      return
    end if

    ! Every path below sets the whole tangent when it succeeds (fail() zeroes it otherwise).
    done = .false.
    if (solver%substep_tol > 0.0_dp) then
      ! The whole increment by the specialised kernel first (it computes the error estimate on
      ! the way, as the first trial of substep would); sub-increments only when the estimate
      ! exceeds the tolerance, the first one sized from it.
      h_first = 1.0_dp
      if (mat%kernel /= kernel_general) then
        call kernel_step(mat, solver, s, old, new, tangent, done, info%newton_iterations, err)
        if (.not. done) err = 0.0_dp
        if (err > solver%substep_tol) then
          done = .false.
          h_first = max(0.1_dp, 0.9_dp * sqrt(solver%substep_tol / err))
          h_first = scale(1.0_dp, exponent(h_first) - 1)
        end if
      end if
      if (.not. done) call substep(mat, solver, s, old, new, tangent, info, solver%substep_tol, &
                                   h_first)
    else
      ! The specialised kernel of the material's effect set, when it applies.
      if (mat%kernel /= kernel_general) call kernel_step(mat, solver, s, old, new, tangent, &
                                                         done, info%newton_iterations)
      if (.not. done) then
        call ria_step(mat, solver, s, old, new, tangent, info%newton_iterations, ok)
        if (.not. ok) then
          ! The one-step solve failed: retry on sub-increments, split only as failures require.
          call substep(mat, solver, s, old, new, tangent, info, huge(1.0_dp), 0.5_dp)
        end if
      end if
    end if
    if (info%status /= status_ok) then
      call fail(old, new, sigma, tangent, info, info%status, info%message)
      return
    end if
    sigma = new%sigma
    if (.not. finite_response(sigma, tangent)) then
      call fail(old, new, sigma, tangent, info, status_local_failure, &
                'the traction or tangent is not finite: retry with a smaller increment')
      return
    end if
    call largest_increments(mat%n_planes, old, new, info)
  end subroutine general_update

  !> Traction and tangent finite: a NaN or an infinity in any entry makes the sum NaN or
  !> infinite (so does a sum beyond huge, which no traction or stiffness of the law comes near).
  pure logical function finite_response(sigma, tangent)
    real(dp), intent(in) :: sigma(2), tangent(2, 2)
    finite_response = is_finite_value(abs(sigma(1)) + abs(sigma(2)) + abs(tangent(1, 1)) + &
                                      abs(tangent(2, 1)) + abs(tangent(1, 2)) + abs(tangent(2, 2)))
  end function finite_response

  !> The largest damage and angle increments over the n planes of an update (its info report).
  pure subroutine largest_increments(n, old, new, info)
    integer, intent(in) :: n
    type(interlock_state_t), intent(in) :: old, new
    type(interlock_info_t), intent(inout) :: info
    integer :: k
    info%max_damage_increment = new%damage(1) - old%damage(1)
    info%max_angle_increment = abs(new%theta(1) - old%theta(1))
    do k = 2, n
      info%max_damage_increment = max(info%max_damage_increment, new%damage(k) - old%damage(k))
      info%max_angle_increment = max(info%max_angle_increment, abs(new%theta(k) - old%theta(k)))
    end do
  end subroutine largest_increments

  !> Report a failure: `new` = `old`, the traction at the start, no tangent.
  pure subroutine fail(old, new, sigma, tangent, info, code, message)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    integer, intent(in) :: code
    character(len=*), intent(in) :: message
    info%status = code
    info%message = message
    info%max_damage_increment = 0.0_dp
    info%max_angle_increment = 0.0_dp
    new = old
    sigma = old%sigma
    tangent = 0.0_dp
  end subroutine fail

  !> Sub-increments linear in s. With error control (tol finite) each trial sub-increment is
  !> taken once, with the embedded estimate of its local error that the planes compute on the
  !> way (interlock_schemes: the angle difference of the first- and second-order wear
  !> increments, which costs no further evaluation); it is kept when the estimate is within
  !> `tol` [rad] (or when the sub-increment is already the smallest allowed: at a kink the
  !> estimate does not shrink with the size), and the next size follows from the estimate's
  !> scaling (h^2). Damage and friction need no estimate: on a sub-increment linear in s they
  !> are exact in every scheme; without wear one sub-increment is the whole increment. Without
  !> error control (a failed one-step solve) the size is quartered on failure and doubled on
  !> success. Sizes are powers of 2, so that the partition of the increment does not vary with
  !> s except where a decision switches: the chained tangent is then the exact derivative of
  !> what is computed. Nothing is allocated.
  pure subroutine substep(mat, solver, s, old, new, tangent, info, tol, h_first)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2), tol
    real(dp), intent(in) :: h_first   !< the first sub-increment's fraction, a power of 2
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(inout) :: tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    type(interlock_state_t) :: cur, trial
    real(dp) :: ds(2), alpha, h, a_end, err, s_end(2), t_trial(2, 2)
    real(dp) :: jac(4, 2, max_planes), jac_trial(4, 2, max_planes)
    real(dp) :: chain_peak
    integer :: it, n_accepted
    logical :: solved, stable, control, kept, give_up, allowed

    control = tol < huge(1.0_dp)
    ds = s - old%s
    cur = old
    alpha = 0.0_dp
    h = h_first
    jac = 0.0_dp
    n_accepted = 0
    info%attempts = 0
    chain_peak = 0.0_dp
    do while (alpha < 1.0_dp)
      call next_sub_increment(alpha, h, a_end)
      if (a_end >= 1.0_dp) then
        s_end = s
      else
        s_end = old%s + a_end * ds
      end if
      call count_attempt(info, solver%max_substeps, allowed)
      if (.not. allowed) return
      call ria_step(mat, solver, s_end, cur, trial, t_trial, it, solved, jac, a_end, jac_trial, &
                    alpha, err)
      info%newton_iterations = max(info%newton_iterations, it)
      stable = .true.
      if (solved) stable = bounded(jac_trial, mat%n_planes)
      if (.not. (solved .and. stable)) then
        call after_failure(solved, h, info, give_up)
        if (give_up) return
        cycle
      end if
      kept = keep_trial(control, err, tol, h)
      if (kept) then
        cur = trial
        jac(:, :, 1:mat%n_planes) = jac_trial(:, :, 1:mat%n_planes)
        tangent = t_trial
        chain_peak = max(chain_peak, maxval(abs(t_trial)))
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

  !> The chained derivatives of the n planes in use stay far from overflow: an update whose
  !> derivative exceeds this is reported (an explicit wear update on tiny sub-increments can
  !> amplify it exponentially). A NaN is not caught here (finite_response reports it). Plane
  !> by plane with fixed shapes and no maxval (its NaN handling and an assumed-shape section
  !> would add work to every sub-increment).
  pure logical function bounded(jac, n)
    real(dp), intent(in) :: jac(4, 2, max_planes)
    integer, intent(in) :: n
    integer :: k
    bounded = .true.
    do k = 1, n
      if (any(abs(jac(:, :, k)) > 1.0e100_dp)) bounded = .false.
    end do
  end function bounded

end module legacy_general_update
