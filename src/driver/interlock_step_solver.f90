!> One load step of a material point under mixed control: each component of the relative
!> displacement (two in 2D: N, T; three in 3D: N, T1, T2, SPEC section 9) is either prescribed
!> (separation-driven) or solved for so that the matching traction takes a prescribed value
!> (traction-driven). A 2D point is updated by interlock_update, a 3D one by
!> interlock_update_3d. One driven component: a scalar Newton iteration on the consistent
!> tangent, safeguarded by a bracket (bisection fallback) and a bounded bracket search. Two or
!> three: Newton on the driven block of the tangent (LAPACK dgesv) with a backtracking line
!> search. Every step is solved from the state at the start of the step (the state is never
!> updated during the iterations); a step that cannot be solved is cut in halves (and regrown
!> after successes), a bounded number of times.
!> Where the relative tolerance is below the floating-point resolution of the separation (a very
!> stiff interface, or newton_tol near eps), a solve is accepted once the residual is at most
!> what that resolution allows, |K| 8 eps |s| (a Newton correction of at most 8 ulps of s, or s
!> resolved to adjacent floating-point numbers; docs/history-output.md).
module interlock_step_solver
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_t, &
      interlock_state_3d_t, interlock_info_t, interlock_update, interlock_update_3d, status_ok, &
      format_real, format_integer, is_nan_value, separation_bound
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: control_t, solve_step, point_vector

  !> The names of the components in messages: 2D (N, T) and 3D (N, T1, T2).
  character(len=8), parameter :: traction_names(2) = [character(len=8) :: 'sigma_N', 'sigma_T']
  character(len=8), parameter :: traction_names_3d(3) = [character(len=8) :: 'sigma_N', &
    'sigma_T1', 'sigma_T2']
  character(len=4), parameter :: separation_names(2) = [character(len=4) :: 's_N', 's_T']
  character(len=4), parameter :: separation_names_3d(3) = [character(len=4) :: 's_N', 's_T1', 's_T2']

  !> How the components are driven and how hard the solver may try.
  type :: control_t
    !> components: 2 (N, T: the 2D law) or 3 (N, T1, T2: the 3D law of SPEC section 9)
    integer  :: n = 2
    !> .true.: traction-driven component (only the first n count)
    logical  :: traction(3) = [.true., .false., .false.]
    real(dp) :: tol = 1.0e-12_dp                 !< relative residual on the driven tractions
    integer  :: max_iterations = 50              !< Newton iterations per solve (bracket search included)
    integer  :: max_cuts = 30                    !< a step may be cut down to 2**(-max_cuts) of itself
  end type control_t

  !> One load step (solve_step_3d); the 2D form takes and returns the 2D state.
  interface solve_step
    module procedure solve_step_2d, solve_step_3d
  end interface solve_step

  interface
    !> LAPACK: solve A X = B by LU with partial pivoting.
    subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: dp
      integer, intent(in) :: n, nrhs, lda, ldb
      real(dp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgesv
  end interface

contains

  !> The 3D state of a history that starts from the (2D) state `initial`: no strike slip or
  !> friction traction, s_T2 = sigma_T2 = 0.
  pure function initial_3d(initial) result(state)
    type(interlock_state_t), intent(in) :: initial
    type(interlock_state_3d_t) :: state
    state%interlock_state_t = initial
    state%sf_strike = 0.0_dp
    state%tauf_strike = 0.0_dp
    state%s_t2 = 0.0_dp
    state%sigma_t2 = 0.0_dp
  end function initial_3d

  !> The separation or the traction of a point with n components from its in-plane pair and
  !> its T2 component: (N, T) or (N, T1, T2).
  pure function point_vector(pair, t2, n) result(v)
    real(dp), intent(in) :: pair(2), t2
    integer, intent(in) :: n
    real(dp) :: v(n)
    v(1:2) = pair
    if (n == 3) v(3) = t2
  end function point_vector

  !> The update of a point with n = size(s) components: interlock_update (2D, the 2D part of
  !> the states) or interlock_update_3d.
  pure subroutine update_point(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(:)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(:), tangent(:, :)
    type(interlock_info_t), intent(inout) :: info
    if (size(s) == 2) then
      call interlock_update(mat, solver, s, old%interlock_state_t, new%interlock_state_t, sigma, &
                            tangent, info)
      new%sf_strike = old%sf_strike
      new%tauf_strike = old%tauf_strike
      new%s_t2 = old%s_t2
      new%sigma_t2 = old%sigma_t2
    else
      call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    end if
  end subroutine update_point

  !> solve_step for a 2D point (ctl%n = 2): the 2D state in and out.
  subroutine solve_step_2d(mat, solver, ctl, old, target_start, target_end, new, sigma, &
                           iterations, substeps, stat, message)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: target_start(2), target_end(2)
    type(interlock_state_t), intent(out) :: new
    real(dp), intent(out) :: sigma(2)
    integer, intent(out) :: iterations, substeps, stat
    character(len=*), intent(out) :: message
    type(interlock_state_3d_t) :: new_3d
    type(control_t) :: ctl_2d
    ctl_2d = ctl
    ctl_2d%n = 2
    call solve_step_3d(mat, solver, ctl_2d, initial_3d(old), target_start, target_end, new_3d, &
                       sigma, iterations, substeps, stat, message)
    new = new_3d%interlock_state_t
  end subroutine solve_step_2d

  !> One load step from `old`: the driven values (ctl%n components) go linearly from
  !> `target_start` to `target_end`. On failure the step is cut in halves (at most ctl%max_cuts
  !> times in a row), and the sub-step grows again (doubles) after each success. `iterations`
  !> counts the Newton iterations of all attempts; `substeps` the library's sub-increments of
  !> the accepted updates (1 per accepted sub-step without substepping). stat /= status_ok:
  !> `message` says why.
  subroutine solve_step_3d(mat, solver, ctl, old, target_start, target_end, new, sigma, &
                           iterations, substeps, stat, message)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: target_start(:), target_end(:)
    type(interlock_state_3d_t), intent(out) :: new
    real(dp), intent(out) :: sigma(:)
    integer, intent(out) :: iterations, substeps, stat
    character(len=*), intent(out) :: message
    type(interlock_state_3d_t) :: cur, trial
    real(dp) :: f, h, f_next, target(size(target_end)), h_min
    integer :: it, lsub, attempts, max_attempts
    logical :: ok

    cur = old
    f = 0.0_dp
    h = 1.0_dp
    h_min = 0.5_dp**ctl%max_cuts
    iterations = 0
    substeps = 0
    attempts = 0
    ! Each cut halves h; each success can double it: bounded by the cut depth times the halvings.
    max_attempts = 4 * (ctl%max_cuts + 1) * (ctl%max_cuts + 2)
    stat = status_ok
    message = ''
    sigma = point_vector(old%sigma, old%sigma_t2, ctl%n)
    do while (f < 1.0_dp)
      attempts = attempts + 1
      if (attempts > max_attempts) then
        stat = 2
        message = 'cannot reach ' // targets_text(ctl, target_end) // ' at the end of the ' // &
                  'step: more than ' // format_integer(max_attempts) // ' attempts'
        exit
      end if
      f_next = min(1.0_dp, f + h)
      if (f_next >= 1.0_dp) then
        target = target_end
      else
        target = target_start + f_next * (target_end - target_start)
      end if
      call solve_point(mat, solver, ctl, cur, target, trial, sigma, it, lsub, ok, message)
      iterations = iterations + it
      if (ok) then
        cur = trial
        f = f_next
        substeps = substeps + lsub
        h = min(2.0_dp * h, 1.0_dp)
      else
        h = 0.5_dp * h
        if (h < h_min) then
          stat = 2
          message = 'cannot reach ' // targets_text(ctl, target_end) // ' at the end of the ' // &
                    'step: the step cut ' // format_integer(ctl%max_cuts) // ' times, its ' // &
                    'sub-step to ' // targets_text(ctl, target) // ' fails: ' // trim(message)
          exit
        end if
      end if
    end do
    if (stat == status_ok) then
      new = cur
      sigma = point_vector(cur%sigma, cur%sigma_t2, ctl%n)
    else
      new = old
      sigma = point_vector(old%sigma, old%sigma_t2, ctl%n)
    end if
  end subroutine solve_step_3d

  !> "sigma_N = 0.01 MPa", "sigma_N = -2 MPa, sigma_T = 0.3 MPa", or the prescribed separations
  !> when no component is traction-driven: the values a (sub-)step is to reach.
  function targets_text(ctl, target) result(text)
    type(control_t), intent(in) :: ctl
    real(dp), intent(in) :: target(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, ctl%n
      if (len(text) > 0) text = text // ', '
      if (ctl%traction(i)) then
        text = text // traction_name(i, ctl%n) // ' = ' // format_real(target(i)) // ' MPa'
      else
        text = text // separation_name(i, ctl%n) // ' = ' // format_real(target(i)) // ' mm'
      end if
    end do
  end function targets_text

  !> The name of traction component i of a point with n components (sigma_T in 2D, sigma_T1 and
  !> sigma_T2 in 3D).
  pure function traction_name(i, n) result(name)
    integer, intent(in) :: i, n
    character(len=:), allocatable :: name
    name = trim(merge(traction_names(min(i, 2)), traction_names_3d(i), n == 2))
  end function traction_name

  pure function separation_name(i, n) result(name)
    integer, intent(in) :: i, n
    character(len=:), allocatable :: name
    name = trim(merge(separation_names(min(i, 2)), separation_names_3d(i), n == 2))
  end function separation_name

  !> Find s such that the driven components of the traction take `target` (the others are
  !> prescribed separations), from the state `old`, starting from s = old's separation.
  subroutine solve_point(mat, solver, ctl, old, target, new, sigma, iterations, substeps, ok, reason)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: target(:)
    type(interlock_state_3d_t), intent(out) :: new
    real(dp), intent(out) :: sigma(:)
    integer, intent(out) :: iterations, substeps
    logical, intent(out) :: ok
    character(len=*), intent(out) :: reason
    real(dp) :: s(ctl%n), tangent(ctl%n, ctl%n)
    type(interlock_info_t) :: info
    integer :: i, n, driven(ctl%n), m

    n = ctl%n
    s = point_vector(old%s, old%s_t2, n)
    m = 0
    do i = 1, n
      if (ctl%traction(i)) then
        m = m + 1
        driven(m) = i
      else
        s(i) = target(i)
      end if
    end do
    iterations = 0
    substeps = 0
    reason = ''
    if (m >= 2) then
      call newton_nd(mat, solver, ctl, driven(1:m), old, target, s, new, sigma, iterations, info, &
                     ok, reason)
    else if (m == 1) then
      call newton_1d(mat, solver, ctl, driven(1), old, target(driven(1)), s, new, sigma, &
                     iterations, info, ok, reason)
    else
      call update_point(mat, solver, s, old, new, sigma, tangent, info)
      ok = info%status == status_ok
      if (.not. ok) reason = info%message
    end if
    if (ok) substeps = info%substeps
  end subroutine solve_point

  !> The traction scale of the residual test: the driven value, or the interface strength.
  pure real(dp) function residual_scale(mat, i, target)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: i
    real(dp), intent(in) :: target
    residual_scale = max(abs(target), merge(mat%sigma0_n, mat%sigma0_t, i == 1))
  end function residual_scale

  !> Scalar safeguarded Newton on s(i): residual r(x) = sigma_i(x) - target. Until a sign change
  !> is found the search follows Newton when it points the way an increasing traction needs, and
  !> otherwise steps (doubling) in that direction; once bracketed, Newton steps that leave the
  !> bracket or do not halve the residual are replaced by bisection.
  subroutine newton_1d(mat, solver, ctl, i, old, target, s, new, sigma, iterations, info, ok, reason)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    integer, intent(in) :: i
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: target
    real(dp), intent(inout) :: s(:)
    type(interlock_state_3d_t), intent(out) :: new
    real(dp), intent(out) :: sigma(:)
    integer, intent(out) :: iterations
    type(interlock_info_t), intent(out) :: info
    logical, intent(out) :: ok
    character(len=*), intent(out) :: reason
    real(dp) :: tangent(size(s), size(s)), r, d, x, x_new, x_lo, x_hi, r_prev, step, ftol, xscale, r_min, r_max, &
                r_lo, r_hi
    logical :: have_lo, have_hi, bisect

    ok = .false.
    reason = ''
    iterations = 0
    ftol = ctl%tol * residual_scale(mat, i, target)
    xscale = merge(mat%s0n, mat%s0t, i == 1)
    step = xscale
    have_lo = .false.
    have_hi = .false.
    x_lo = 0.0_dp
    x_hi = 0.0_dp
    r_lo = 0.0_dp
    r_hi = 0.0_dp
    r_prev = huge(1.0_dp)
    r_min = huge(1.0_dp)
    r_max = -huge(1.0_dp)
    x = s(i)
    do
      s(i) = x
      call update_point(mat, solver, s, old, new, sigma, tangent, info)
      if (info%status /= status_ok) then
        reason = info%message
        return
      end if
      r = sigma(i) - target
      r_min = min(r_min, r)
      r_max = max(r_max, r)
      if (abs(r) <= ftol) then
        ok = .true.
        return
      end if
      if (iterations >= ctl%max_iterations) exit
      iterations = iterations + 1
      ! Keep the bracket: x_lo has r < 0, x_hi has r > 0.
      if (r < 0.0_dp) then
        x_lo = x
        r_lo = r
        have_lo = .true.
      else
        x_hi = x
        r_hi = r
        have_hi = .true.
      end if
      d = tangent(i, i)
      ! A Newton correction within the resolution of s (|r / d| <= 8 eps |s|): no floating-point
      ! s does better, whatever the tolerance asks (a tolerance near eps: Newton would stall
      ! there, s unchanged, until its iterations run out).
      if (abs(r) <= resolution_floor(x, d)) then
        ok = .true.
        return
      end if
      bisect = .false.
      if (have_lo .and. have_hi) then
        if (abs(x_hi - x_lo) <= 4.0_dp * epsilon(1.0_dp) * max(abs(x_lo), abs(x_hi)) + &
            tiny(1.0_dp)) then
          ! The bracket is down to adjacent floating-point numbers: accept its better end if
          ! its residual is what that resolution allows with this stiffness (a very stiff
          ! interface: |K| 8 ulp(s) > ftol); otherwise the traction really jumps.
          x = merge(x_lo, x_hi, abs(r_lo) <= abs(r_hi))
          if (min(abs(r_lo), abs(r_hi)) <= resolution_floor(x, d)) then
            s(i) = x
            call update_point(mat, solver, s, old, new, sigma, tangent, info)
            ok = info%status == status_ok
            if (.not. ok) reason = info%message
            return
          end if
          reason = 'the ' // names(i) // ' jumps across the prescribed value ' // &
                   format_real(target) // ' MPa at ' // separation_name(i, size(s)) // ' = ' // &
                   format_real(x) // ' mm: no solution'
          return
        end if
        if (abs(d) > 0.0_dp .and. ieee_is_finite(d)) then
          x_new = x - r / d
          bisect = .not. (x_new > min(x_lo, x_hi) .and. x_new < max(x_lo, x_hi)) .or. &
                   abs(r) > 0.5_dp * r_prev
        else
          bisect = .true.
        end if
        if (bisect) x_new = 0.5_dp * (x_lo + x_hi)
      else
        ! No sign change yet: an increasing traction needs x to go down when r > 0.
        if (d > 0.0_dp .and. ieee_is_finite(d)) then
          x_new = x - r / d
        else
          x_new = x - sign(step, r)
          step = 2.0_dp * step
        end if
        if (.not. ieee_is_finite(x_new)) exit
        ! The update admits |s| <= separation_bound: no root is sought beyond it.
        if (abs(x_new) > separation_bound) then
          if (abs(x) >= separation_bound) exit
          x_new = sign(separation_bound, x_new)
        end if
      end if
      r_prev = abs(r)
      x = x_new
    end do
    ! No root within the iteration budget.
    if (.not. (have_lo .and. have_hi)) then
      reason = 'no ' // separation_name(i, size(s)) // ' carries ' // names(i) // &
               ' = ' // format_real(target) // ' MPa (the ' // names(i) // &
               ' found ranges from ' // format_real(r_min + target) // ' to ' // &
               format_real(r_max + target) // ' MPa)'
      if (mat%use_depth .and. s(1) >= mat%h_n .and. i >= 2) then
        reason = trim(reason) // ': the interface has separated (s_N = ' // format_real(s(1)) // &
                 ' >= H_N = ' // format_real(mat%h_n) // ' mm) and transmits no traction'
      else if (mat%use_depth .and. old%s(1) >= mat%h_n .and. i == 1 .and. target > 0.0_dp) then
        reason = trim(reason) // ': the interface has separated (s_N = ' // format_real(old%s(1)) // &
                 ' >= H_N = ' // format_real(mat%h_n) // ' mm) and carries no tension'
      else if (i == 1 .and. target > 0.0_dp .and. r_max + target <= 0.0_dp .and. &
               all(old%damage(1:mat%n_planes) >= 1.0_dp)) then
        reason = trim(reason) // ': the interface is fully damaged (D = 1 on every ' // &
                 'microplane) and carries no tension'
      end if
    else
      reason = 'the ' // names(i) // ' Newton iteration did not converge in ' // &
               format_integer(ctl%max_iterations) // ' iterations'
    end if

  contains

    function names(i) result(name)
      integer, intent(in) :: i
      character(len=:), allocatable :: name
      name = traction_name(i, size(s))
    end function names

  end subroutine newton_1d

  !> Two or three components traction-driven (`driven`, the others prescribed): Newton on the
  !> driven block of the tangent (LAPACK dgesv) with a backtracking line search on the scaled
  !> residual.
  subroutine newton_nd(mat, solver, ctl, driven, old, target, s, new, sigma, iterations, info, ok, &
                       reason)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    integer, intent(in) :: driven(:)
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: target(:)
    real(dp), intent(inout) :: s(:)
    type(interlock_state_3d_t), intent(out) :: new
    real(dp), intent(out) :: sigma(:)
    integer, intent(out) :: iterations
    type(interlock_info_t), intent(out) :: info
    logical, intent(out) :: ok
    character(len=*), intent(out) :: reason
    real(dp) :: tangent(size(s), size(s)), a(size(driven), size(driven)), b(size(driven), 1), &
                r(size(driven)), scale(size(driven)), norm, norm_trial, lambda, s_trial(size(s)), &
                sigma_trial(size(s)), tangent_trial(size(s), size(s)), stiffness(3), floor_sum
    type(interlock_state_3d_t) :: trial
    type(interlock_info_t) :: info_trial
    integer :: ipiv(size(driven)), lapack_info, k, attempt, m, j, n

    ok = .false.
    reason = ''
    iterations = 0
    m = size(driven)
    n = size(s)
    do j = 1, m
      scale(j) = residual_scale(mat, driven(j), target(driven(j)))
    end do
    stiffness = [mat%kn, mat%kt, mat%kt]
    call update_point(mat, solver, s, old, new, sigma, tangent, info)
    if (info%status /= status_ok) then
      reason = info%message
      return
    end if
    r = sigma(driven) - target(driven)
    norm = maxval(abs(r) / scale)
    do
      if (norm <= ctl%tol) then
        ok = .true.
        return
      end if
      if (iterations >= ctl%max_iterations) then
        reason = 'the (' // driven_names(traction_name) // ') Newton iteration did not converge in ' // &
                 format_integer(ctl%max_iterations) // ' iterations'
        return
      end if
      iterations = iterations + 1
      ! The consistent tangent first; where it is singular (a kink, an open damaged plane) or
      ! gives no descent, the elastic (penalty) stiffness diag(K_n, K_t, K_t), never singular.
      descent_search: block
        logical :: descent
        descent = .false.
        do attempt = 1, 2
          if (attempt == 1) then
            a = tangent(driven, driven)
          else
            a = 0.0_dp
            do j = 1, m
              a(j, j) = stiffness(driven(j))
            end do
          end if
          b(:, 1) = -r
          call dgesv(m, 1, a, m, ipiv, b, m, lapack_info)
          if (lapack_info /= 0 .or. .not. all(ieee_is_finite(b(:, 1)))) cycle
          lambda = 1.0_dp
          do k = 1, 30
            s_trial = s
            s_trial(driven) = s(driven) + lambda * b(:, 1)
            call update_point(mat, solver, s_trial, old, trial, sigma_trial, tangent_trial, &
                              info_trial)
            if (info_trial%status == status_ok) then
              norm_trial = maxval(abs(sigma_trial(driven) - target(driven)) / scale)
              if (.not. is_nan_value(norm_trial)) then
                if (norm_trial <= (1.0_dp - 1.0e-4_dp * lambda) * norm) then
                  descent = .true.
                  exit
                end if
              end if
            end if
            lambda = 0.5_dp * lambda
          end do
          if (descent) exit
        end do
        if (.not. descent) then
          ! No step reduces the residual: accept if it is what the floating-point resolution of
          ! s allows with this tangent (a very stiff interface).
          ok = .true.
          do k = 1, m
            floor_sum = resolution_floor(s(driven(1)), tangent(driven(k), driven(1)))
            do j = 2, m
              floor_sum = floor_sum + resolution_floor(s(driven(j)), tangent(driven(k), driven(j)))
            end do
            ok = ok .and. abs(r(k)) <= floor_sum
          end do
          if (ok) return
          reason = 'no (' // driven_names(separation_name) // ') near (' // &
                   driven_values(s) // ') mm reduces the residual of (' // &
                   driven_names(traction_name) // ') = (' // driven_values(target) // &
                   ') MPa: no solution'
          return
        end if
      end block descent_search
      s = s_trial
      new = trial
      sigma = sigma_trial
      tangent = tangent_trial
      info = info_trial
      r = sigma(driven) - target(driven)
      norm = norm_trial
    end do

  contains

    !> "sigma_N, sigma_T": the names of the driven components.
    function driven_names(name_of) result(text)
      interface
        pure function name_of(i, n) result(name)
          integer, intent(in) :: i, n
          character(len=:), allocatable :: name
        end function name_of
      end interface
      character(len=:), allocatable :: text
      integer :: jj
      text = name_of(driven(1), n)
      do jj = 2, m
        text = text // ', ' // name_of(driven(jj), n)
      end do
    end function driven_names

    function driven_values(x) result(text)
      real(dp), intent(in) :: x(:)
      character(len=:), allocatable :: text
      integer :: jj
      text = format_real(x(driven(1)))
      do jj = 2, m
        text = text // ', ' // format_real(x(driven(jj)))
      end do
    end function driven_values

  end subroutine newton_nd

  !> The traction residual that the floating-point resolution of a separation x allows with
  !> stiffness d: |d| 8 eps |x| (0 where d is not finite).
  elemental real(dp) function resolution_floor(x, d)
    real(dp), intent(in) :: x, d
    resolution_floor = 0.0_dp
    if (ieee_is_finite(d) .and. ieee_is_finite(x)) resolution_floor = abs(d) * 8.0_dp * &
      epsilon(1.0_dp) * abs(x)
  end function resolution_floor

end module interlock_step_solver
