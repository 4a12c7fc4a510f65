!> The general path of the update (SPEC sections 5 and 9), one for 2D and 3D: the whole
!> increment as one step, or error-controlled sub-increments, over every plane of the RIA by
!> interlock_step_3d (the plane law of interlock_plane_law_3d with its derivatives written out
!> in plain reals, the wear equation's root differentiated implicitly, each plane's state
!> derivatives carried over sub-increments), with the exact 3x3 tangent of what is computed.
!> interlock_update_3d takes any history here that is not in the (n, t1) plane of a RIA with
!> every azimuth 0; interlock_update (interlock_general_update) takes a 2D increment here
!> (s_T2 = 0, every azimuth 0: the 2D law, whose tangent is the (1:2, 1:2) block) when it
!> substeps, when the RIA is separated (D7) and when the specialised kernel does not apply or
!> fails. It shares no code with the specialised kernels (interlock_kernels), which are checked
!> against it (core_kernels).
module interlock_general_path
  use interlock_kinds, only: dp, is_finite_value, within_separation_bound, separation_bound
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes, n_schemes, &
      scheme_list
  use interlock_numbers, only: format_real, format_integer
  use interlock_state, only: interlock_state_3d_t, state_3d_take
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, status_local_failure
  use interlock_step_3d, only: plane_chain_t, step_3d, chain_bounded
  use interlock_substep_control, only: next_sub_increment, count_attempt, after_failure, &
      keep_trial, next_size, check_chain, largest_increments
  implicit none
  private
  public :: general_update_3d, single_step, integrate_increment

contains

  !> The general three-dimensional update (interlock_update_3d's contract) for any material,
  !> solver and history. `info` comes reset. `h_first` (with substep_tol > 0; absent: the whole
  !> increment first): the caller has tried the whole increment as one step (a one-step kernel
  !> with the general path's error estimate) and found the estimate above substep_tol; the
  !> sub-increments start at this fraction (interlock_substep_control:size_after_whole), and
  !> that trial counts as the first attempt.
  pure subroutine general_update_3d(mat, solver, s, old, new, sigma, tangent, info, h_first)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    real(dp), intent(in), optional :: h_first

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

    if (present(h_first)) then
      call substep(mat, solver, s, old, new, tangent, info, solver%substep_tol, h_first, &
                   .false., 1)
    else
      call integrate_increment(mat, solver, s, old, new, tangent, info, solver%substep_tol, &
                               1.0_dp, .false.)
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

  !> The increment from `old` to s on the general path: tol > 0, error-controlled
  !> sub-increments from the fraction h_first; else the whole increment as one step, retried on
  !> sub-increments (split only as failures require) when its solve fails. `in_plane`: the
  !> increment lies in the (n, t1) plane of a RIA with every azimuth 0 (substep's 2-column
  !> chain). info%status says whether `new` and `tangent` hold the result (on failure `new` may
  !> be partly written).
  pure subroutine integrate_increment(mat, solver, s, old, new, tangent, info, tol, h_first, &
                                      in_plane)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), tol, h_first
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    logical, intent(in) :: in_plane
    if (tol > 0.0_dp) then
      call substep(mat, solver, s, old, new, tangent, info, tol, h_first, in_plane, 0)
    else
      call single_step(mat, solver, s, old, new, tangent, info)
      if (info%status == status_local_failure) then
        info%status = status_ok
        call substep(mat, solver, s, old, new, tangent, info, huge(1.0_dp), 0.5_dp, in_plane, &
                     0)
      end if
    end if
  end subroutine integrate_increment

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
  !> again or set to `old`). `wear_error`: the embedded error estimate of the step, the first
  !> trial of substepping (which the specialised kernels compute too).
  pure subroutine single_step(mat, solver, s, old, new, tangent, info, wear_error)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    real(dp), intent(out), optional :: wear_error
    type(plane_chain_t) :: unused(1)
    real(dp) :: err
    integer :: it
    logical :: solved, allowed
    info%attempts = 0
    call count_attempt(info, solver%max_substeps, allowed)
    if (.not. allowed) return
    call step_3d(mat, solver, s, old, new, tangent, it, solved, .false., 0.0_dp, 1.0_dp, unused, &
                 unused, present(wear_error), err)
    if (present(wear_error)) wear_error = err
    info%newton_iterations = max(info%newton_iterations, it)
    if (.not. solved) then
      info%status = status_local_failure
      info%message = 'the local wear equation has no solution'
      tangent = 0.0_dp
      return
    end if
    call check_chain(mat, largest_magnitude(tangent), info, allowed)
    if (.not. allowed) return
    info%substeps = 1
  end subroutine single_step

  !> maxval(abs(a)) of a 3x3 matrix as one comparison per entry (0 if every entry is a NaN, which
  !> maxval gives as NaN: neither exceeds a bound).
  pure real(dp) function largest_magnitude(a) result(peak)
    real(dp), intent(in) :: a(3, 3)
    integer :: i, j
    peak = 0.0_dp
    do j = 1, 3
      do i = 1, 3
        if (abs(a(i, j)) > peak) peak = abs(a(i, j))
      end do
    end do
  end function largest_magnitude

  !> Sub-increments linear in s. With error control (tol finite) each trial sub-increment is
  !> taken once, with the embedded estimate of its local error that the planes compute on the
  !> way (the angle difference of the first- and second-order wear increments, and the
  !> traction error it causes, which cost no further evaluation); it is kept when the estimate
  !> is within `tol` (or when the sub-increment is already the smallest allowed: at a kink the
  !> estimate does not shrink with the size), and the next size follows from the estimate's
  !> scaling (h^2). Damage needs no estimate: on a sub-increment linear in s it is exact in
  !> every scheme, and so is friction in 2D; in 3D the direction of slip of an inclined plane
  !> turns within a step, and each sliding plane adds the turn of its friction direction
  !> (interlock_friction:direction_turn) to the estimate. Without error control (tol = huge:
  !> a failed one-step solve) the size is quartered on failure and doubled on success. Sizes are powers of 2 (h_first is one), so that the partition of the
  !> increment does not vary with s except where a decision switches. Each plane's state
  !> carries its derivatives with respect to the end of the increment from one sub-increment to
  !> the next (interlock_step_3d's chain), so that the tangent is the exact one of the chain; a
  !> trial over the whole increment (the first where h_first = 1) is the one-step law's, without
  !> the chain: its tangent at the fixed start state is the chain's.
  !> `in_plane`: an increment of the 2D law (s_T2 = 0, no strike state, every azimuth 0) whose
  !> caller takes the (1:2, 1:2) block of the tangent alone (step_3d's in_plane). The state
  !> and the chain of the current and the trial sub-increment take turns in two slots, `new`
  !> and a local one (the first trial reads `old` and writes `new`: a whole increment kept as
  !> one trial is not copied, the others once at most); on failure `new` is partly written
  !> (the callers report the failure and keep `old`); the planes beyond n_planes are not
  !> written; nothing is allocated. `tried`: the trials of the increment its caller has taken
  !> (counted in info%attempts, against max_substeps).
  pure subroutine substep(mat, solver, s, old, new, tangent, info, tol, h_first, in_plane, tried)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), tol, h_first
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(3, 3)
    type(interlock_info_t), intent(inout) :: info
    logical, intent(in) :: in_plane
    integer, intent(in) :: tried
    type(interlock_state_3d_t) :: st
    type(plane_chain_t) :: jc(max_planes, 2)
    real(dp) :: ds(3), s_old(3), s_end(3), alpha, h, a_end, err, chain_peak, tangent_trial(3, 3)
    !> the planes' frames of the start angles of the current sub-increment (slot fs) and of
    !> the end angles of the trial (3 - fs): each state's computed once
    real(dp) :: frames(2, max_planes, 2)
    integer :: it, n_accepted, k, n, cur, trial, fs
    logical :: solved, stable, control, kept, give_up, allowed, whole, chained, known

    control = tol >= 0.0_dp .and. tol < huge(1.0_dp)
    n = mat%n_planes
    s_old = [old%s(1), old%s(2), old%s_t2]
    ds = s - s_old
    ! (a trial sub-increment writes every value but those of the planes beyond n, which no
    ! step reads and `new` does not take)
    chained = .false.
    cur = 0
    trial = 1
    alpha = 0.0_dp
    h = h_first
    n_accepted = 0
    info%attempts = tried
    tangent = 0.0_dp
    chain_peak = 0.0_dp
    known = .false.
    fs = 1
    do while (alpha < 1.0_dp)
      call next_sub_increment(alpha, h, a_end)
      s_end = s_old + a_end * ds
      if (a_end >= 1.0_dp) s_end = s
      call count_attempt(info, solver%max_substeps, allowed)
      if (.not. allowed) return
      ! (the whole increment as one trial: its tangent at the fixed start state is the chain's,
      ! and no later sub-increment needs its derivatives: the one-step law, without the chain)
      whole = .not. alpha > 0.0_dp .and. a_end >= 1.0_dp
      if (whole) then
        call step_3d(mat, solver, s_end, old, new, tangent_trial, it, solved, .false., alpha, &
                     a_end, jc(1:n, 2), jc(1:n, 1), .true., err, in_plane)
      else
        if (.not. chained) then
          ! (the chain's slots, set where the first sub-increment is tried: a whole increment
          ! taken as one trial needs none)
          do k = 1, n
            jc(k, 1) = plane_chain_t(0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                                     0.0_dp)
            jc(k, 2) = jc(k, 1)
          end do
          chained = .true.
        end if
        select case (cur)
        case (0)
          call step_3d(mat, solver, s_end, old, new, tangent_trial, it, solved, .true., alpha, &
                       a_end, jc(1:n, 2), jc(1:n, 1), .true., err, in_plane, frames, known, fs)
        case (1)
          call step_3d(mat, solver, s_end, new, st, tangent_trial, it, solved, .true., alpha, &
                       a_end, jc(1:n, 1), jc(1:n, 2), .true., err, in_plane, frames, known, fs)
        case default
          call step_3d(mat, solver, s_end, st, new, tangent_trial, it, solved, .true., alpha, &
                       a_end, jc(1:n, 2), jc(1:n, 1), .true., err, in_plane, frames, known, fs)
        end select
        known = .true.
      end if
      info%newton_iterations = max(info%newton_iterations, it)
      stable = .true.
      if (solved .and. .not. whole) stable = chain_bounded(jc(:, trial), n, merge(2, 3, in_plane))
      if (.not. (solved .and. stable)) then
        call after_failure(solved, h, info, give_up)
        if (give_up) return
        cycle
      end if
      kept = keep_trial(control, err, tol, h)
      if (kept) then
        cur = trial
        trial = 3 - cur
        tangent = tangent_trial
        if (in_plane) then
          ! (the rest of the tangent is 0 there)
          chain_peak = max(chain_peak, maxval(abs(tangent(1:2, 1:2))))
        else
          chain_peak = max(chain_peak, maxval(abs(tangent)))
        end if
        alpha = a_end
        n_accepted = n_accepted + 1
        fs = 3 - fs
      end if
      call next_size(kept, control, err, tol, h)
    end do
    call check_chain(mat, chain_peak, info, allowed)
    if (.not. allowed) return
    if (cur == 2) call state_3d_take(n, st, new)
    info%substeps = n_accepted
  end subroutine substep

end module interlock_general_path
