!> Bounded nonlinear least squares: minimise f(x) = 1/2 |r(x)|^2 over the box lower <= x <= upper
!> by a projected Levenberg-Marquardt method, and the statistics of the optimum (standard errors,
!> correlations, conditioning) from the Jacobian there.
!>
!> Why projected, not a transform: the parameters keep their own units all the way (the Jacobian
!> at the optimum is the one of the model, so the standard errors need no chain rule that blows up
!> near a bound, as x = l + (u - l) sin^2(y) would), and a parameter that ends on a bound is seen
!> there (it is reported). The admissible set is the box and what the problem's `project` adds
!> (a constraint that couples parameters, such as theta_f <= theta_0 of the law): every point at
!> which the residuals are evaluated, difference steps included, lies in it. Each iteration: the
!> Jacobian by one-sided differences of whole residual vectors (forward, or backward where the
!> forward step would leave the admissible set); the parameters on a bound whose gradient points out of
!> the box are held (active set); the others take the step p of the damped linear problem
!>   min | [J_F; sqrt(lambda) D_F] p + [r; 0] |
!> solved by LAPACK dgelsd (SVD, never the normal equations; D: Moré's scaling, the largest
!> column norms of J so far), and the trial point is the projection of x + p onto the box (then
!> the problem's projection). The
!> trial is accepted when it lowers f by at least 1e-4 of the reduction predicted by the linear
!> model along the projected step; lambda then shrinks (Nielsen's rule), else it grows.
!> Stopping (lm_result_t%reason): the scaled projected gradient |g_j| / (|J_j| |r|) <= gtol for
!> every free parameter; the accepted step |D s| <= xtol (|D x| + xtol); the actual and predicted
!> relative reductions of f both <= ftol; f = 0; or max_iterations, or no step can lower f, or
!> the residuals cannot be computed at a point of the admissible set. Whatever the stop, the
!> result is the last accepted point (lm_result_t%started: the start itself could be evaluated).
!> Residuals that are not finite, or whose norm exceeds max_residual_norm (their squares would
!> overflow), count as residuals that cannot be computed: never as a fit.
module interlock_lm
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use interlock, only: dp
  implicit none
  private
  public :: lm_problem_t, lm_options_t, lm_result_t, lm_stats_t, lm_solve, lm_jacobian, &
            lm_statistics, lm_statistics_unavailable, lm_least_squares, lm_evaluate, max_residual_norm

  !> The largest residual norm taken as computed: far above any weighted misfit of data in
  !> their own units, far below the square root of the largest double (the cost is |r|^2 / 2).
  real(dp), parameter :: max_residual_norm = 1.0e100_dp

  !> A least-squares problem: m residuals of n parameters. residuals(x, r, ok): ok = .false.
  !> where r cannot be computed (the trial point is then rejected); progress: a report per
  !> accepted iteration; project: moves a point of the box into the admissible set where a
  !> constraint couples parameters (the default: the box is the admissible set).
  type, abstract :: lm_problem_t
    integer :: m = 0
  contains
    procedure(residual_function), deferred :: residuals
    procedure(progress_report), deferred :: progress
    procedure :: project => no_projection
  end type lm_problem_t

  abstract interface
    subroutine residual_function(problem, x, r, ok)
      import :: lm_problem_t, dp
      class(lm_problem_t), intent(inout) :: problem
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: r(:)
      logical, intent(out) :: ok
    end subroutine residual_function
    !> Called after each accepted iteration (iteration 0: the start).
    subroutine progress_report(problem, iteration, x, cost, lambda)
      import :: lm_problem_t, dp
      class(lm_problem_t), intent(inout) :: problem
      integer, intent(in) :: iteration
      real(dp), intent(in) :: x(:), cost, lambda
    end subroutine progress_report
  end interface

  type :: lm_options_t
    real(dp) :: xtol = 1.0e-10_dp   !< relative step
    real(dp) :: ftol = 1.0e-14_dp   !< relative reduction of the cost
    real(dp) :: gtol = 1.0e-10_dp   !< scaled projected gradient
    real(dp) :: fd_step = 1.0e-6_dp !< forward-difference step relative to max(|x|, typical)
    integer :: max_iterations = 100
  end type lm_options_t

  type :: lm_result_t
    real(dp), allocatable :: x(:), r(:)
    real(dp) :: cost = 0.0_dp
    integer :: iterations = 0, evaluations = 0
    logical :: converged = .false.
    logical :: started = .false.   !< the residuals at the start values could be computed
    character(len=:), allocatable :: reason
  end type lm_result_t

  !> Statistics at the optimum (lm_statistics).
  type :: lm_stats_t
    real(dp), allocatable :: std_error(:), correlation(:, :), singular(:)
    real(dp) :: sigma2 = 0.0_dp       !< residual variance 2 f / (m - n)
    real(dp) :: condition = 1.0_dp    !< of the column-scaled Jacobian
    logical, allocatable :: identifiable(:)
    logical :: ill_conditioned = .false.
  end type lm_stats_t

  !> Condition number of the column-scaled Jacobian above which the problem is reported
  !> ill-conditioned, and relative singular value below which a direction is not identifiable
  !> (forward differences with a relative step of 1e-6 resolve derivatives to about 1e-6).
  real(dp), parameter :: ill_condition = 1.0e4_dp, unidentifiable = 1.0e-6_dp

  interface
    subroutine dgelsd(m, n, nrhs, a, lda, b, ldb, s, rcond, rank, work, lwork, iwork, info)
      import :: dp
      integer, intent(in) :: m, n, nrhs, lda, ldb, lwork
      real(dp), intent(inout) :: a(lda, *), b(ldb, *)
      real(dp), intent(out) :: s(*), work(*)
      real(dp), intent(in) :: rcond
      integer, intent(out) :: rank, iwork(*), info
    end subroutine dgelsd
    subroutine dgesvd(jobu, jobvt, m, n, a, lda, s, u, ldu, vt, ldvt, work, lwork, info)
      import :: dp
      character, intent(in) :: jobu, jobvt
      integer, intent(in) :: m, n, lda, ldu, ldvt, lwork
      real(dp), intent(inout) :: a(lda, *)
      real(dp), intent(out) :: s(*), u(ldu, *), vt(ldvt, *), work(*)
      integer, intent(out) :: info
    end subroutine dgesvd
  end interface

contains

  !> Minimise 1/2 |r(x)|^2 over [lower, upper] from x0 (inside the box). `typical`: the size of
  !> each parameter for the difference steps (> 0).
  subroutine lm_solve(problem, x0, lower, upper, typical, opts, res)
    class(lm_problem_t), intent(inout) :: problem
    real(dp), intent(in) :: x0(:), lower(:), upper(:), typical(:)
    type(lm_options_t), intent(in) :: opts
    type(lm_result_t), intent(out) :: res
    integer :: n, m, it, j, nf, k
    real(dp), allocatable :: x(:), r(:), jac(:, :), g(:), d(:), xt(:), rt(:), s(:), p(:), col(:)
    logical, allocatable :: free(:)
    real(dp) :: f, ft, lambda, nu, pred, rho, rnorm, gmax, xnorm, snorm, f_old
    logical :: ok

    n = size(x0)
    m = problem%m
    allocate (x(n), r(m), jac(m, n), g(n), d(n), xt(n), rt(m), s(n), col(n), free(n))
    x = min(max(x0, lower), upper)
    call problem%project(x)
    d = 0.0_dp
    r = 0.0_dp
    res%evaluations = 1
    call lm_evaluate(problem, x, r, ok)
    if (.not. ok) then
      res%reason = 'the residuals cannot be computed at the start values'
      call finish()
      return
    end if
    res%started = .true.
    f = 0.5_dp * norm2(r)**2
    lambda = 1.0e-3_dp
    nu = 2.0_dp
    call problem%progress(0, x, f, 0.0_dp)
    res%reason = ''
    do it = 1, opts%max_iterations
      res%iterations = it
      if (f <= tiny(1.0_dp)) then
        res%reason = 'zero residual (the data are matched exactly)'
        res%converged = .true.
        exit
      end if
      call lm_jacobian(problem, x, r, lower, upper, typical, opts%fd_step, jac, ok)
      res%evaluations = res%evaluations + n
      if (.not. ok) then
        res%reason = 'the residuals cannot be computed at a difference step of the Jacobian ' // &
                     '(within the admissible set)'
        exit
      end if
      g = matmul(r, jac)
      rnorm = norm2(r)
      do j = 1, n
        col(j) = norm2(jac(:, j))
        d(j) = max(d(j), col(j))
        if (d(j) <= 0.0_dp) d(j) = 1.0_dp / typical(j)
        free(j) = .not. ((x(j) <= lower(j) .and. g(j) > 0.0_dp) .or. &
                         (x(j) >= upper(j) .and. g(j) < 0.0_dp))
      end do
      gmax = 0.0_dp
      do j = 1, n
        if (free(j) .and. col(j) > 0.0_dp) gmax = max(gmax, abs(g(j)) / (col(j) * rnorm))
      end do
      if (gmax <= opts%gtol) then
        res%reason = 'gradient: the scaled projected gradient is <= gtol'
        res%converged = .true.
        exit
      end if
      nf = count(free)
      do
        p = damped_step(jac, r, d, lambda, free, nf)
        xt = x
        k = 0
        do j = 1, n
          if (.not. free(j)) cycle
          k = k + 1
          xt(j) = min(max(x(j) + p(k), lower(j)), upper(j))
        end do
        call problem%project(xt)
        s = xt - x
        pred = f - 0.5_dp * sum((r + matmul(jac, s))**2)
        rho = -1.0_dp
        if (pred > 0.0_dp) then
          call lm_evaluate(problem, xt, rt, ok)
          res%evaluations = res%evaluations + 1
          if (ok) then
            ft = 0.5_dp * norm2(rt)**2
            rho = (f - ft) / pred
          end if
        end if
        if (rho > 1.0e-4_dp) then
          snorm = norm2(d * s)
          xnorm = norm2(d * x)
          f_old = f
          x = xt
          r = rt
          f = ft
          lambda = lambda * max(1.0_dp / 3.0_dp, 1.0_dp - (2.0_dp * rho - 1.0_dp)**3)
          nu = 2.0_dp
          call problem%progress(it, x, f, lambda)
          if (f_old - f <= opts%ftol * f_old .and. pred <= opts%ftol * f_old) then
            res%reason = 'cost: the actual and predicted relative reductions are <= ftol'
            res%converged = .true.
          else if (snorm <= opts%xtol * (xnorm + opts%xtol)) then
            res%reason = 'step: the relative step is <= xtol'
            res%converged = .true.
          end if
          exit
        end if
        if (maxval(abs(s) / typical) <= epsilon(1.0_dp)) then
          res%reason = 'step: no step inside the bounds lowers the cost (the damped step ' // &
                       'vanishes)'
          res%converged = .true.
          exit
        end if
        lambda = lambda * nu
        nu = 2.0_dp * nu
        if (lambda > 1.0e20_dp) then
          res%reason = 'no step lowers the cost (lambda > 1e20): the Jacobian by differences ' // &
                       'may be too inaccurate (raise fd_step) or the model not smooth here'
          exit
        end if
      end do
      if (len(res%reason) > 0) exit
    end do
    if (len(res%reason) == 0) res%reason = 'max_iterations reached before convergence'
    call finish()

  contains

    subroutine finish()
      res%x = x
      res%r = r
      res%cost = 0.0_dp
      if (res%started) res%cost = 0.5_dp * norm2(r)**2
    end subroutine finish

  end subroutine lm_solve

  !> The step of the free parameters: least-squares solution of [J_F; sqrt(lambda) D_F] p = [-r; 0].
  function damped_step(jac, r, d, lambda, free, nf) result(p)
    real(dp), intent(in) :: jac(:, :), r(:), d(:), lambda
    logical, intent(in) :: free(:)
    integer, intent(in) :: nf
    real(dp) :: p(nf)
    real(dp), allocatable :: a(:, :), b(:)
    integer :: m, j, k

    m = size(r)
    p = 0.0_dp
    if (nf == 0) return
    allocate (a(m + nf, nf), b(m + nf))
    a = 0.0_dp
    k = 0
    do j = 1, size(free)
      if (.not. free(j)) cycle
      k = k + 1
      a(1:m, k) = jac(:, j)
      a(m + k, k) = sqrt(lambda) * d(j)
    end do
    b(1:m) = -r
    b(m + 1:) = 0.0_dp
    p = lm_least_squares(a, b)
  end function damped_step

  !> The minimum-norm least-squares solution of a x = b (LAPACK dgelsd: SVD, never the normal
  !> equations; singular values below machine precision times the largest are dropped). Zero
  !> if LAPACK fails.
  function lm_least_squares(a, b) result(x)
    real(dp), intent(in) :: a(:, :), b(:)
    real(dp) :: x(size(a, 2))
    real(dp), allocatable :: aa(:, :), bb(:, :), sv(:), work(:)
    integer, allocatable :: iwork(:)
    integer :: m, n, ld, rank, info, lwork
    real(dp) :: query(1)
    integer :: iquery(1)

    m = size(a, 1)
    n = size(a, 2)
    x = 0.0_dp
    if (n == 0 .or. m == 0) return
    ld = max(m, n)
    allocate (aa(m, n), bb(ld, 1), sv(min(m, n)))
    aa = a
    bb = 0.0_dp
    bb(1:m, 1) = b
    call dgelsd(m, n, 1, aa, m, bb, ld, sv, -1.0_dp, rank, query, -1, iquery, info)
    lwork = max(1, int(query(1)))
    allocate (work(lwork), iwork(max(1, iquery(1))))
    call dgelsd(m, n, 1, aa, m, bb, ld, sv, -1.0_dp, rank, work, lwork, iwork, info)
    if (info == 0) x = bb(1:n, 1)
  end function lm_least_squares

  !> The residuals at x, checked: ok = .false. where the problem cannot compute them, or where
  !> they are not finite or their norm exceeds max_residual_norm.
  subroutine lm_evaluate(problem, x, r, ok)
    class(lm_problem_t), intent(inout) :: problem
    real(dp), intent(in) :: x(:)
    real(dp), intent(out) :: r(:)
    logical, intent(out) :: ok
    call problem%residuals(x, r, ok)
    if (.not. ok) return
    ok = all(ieee_is_finite(r))
    if (ok) ok = norm2(r) <= max_residual_norm
  end subroutine lm_evaluate

  !> The default projection: none (the box is the admissible set).
  subroutine no_projection(problem, x)
    class(lm_problem_t), intent(inout) :: problem
    real(dp), intent(inout) :: x(:)
    if (.false.) x(1) = x(1) + real(problem%m, dp)   ! (both arguments are part of the interface)
  end subroutine no_projection

  !> One-sided difference Jacobian of r at x (a point of the admissible set): column j from one
  !> more evaluation at x + h_j e_j, h_j = fd_step max(|x_j|, typical_j), taken backwards where
  !> the forward point would leave the admissible set (the box, then the problem's projection:
  !> a step that either moves is not taken). ok = .false.: neither step stays inside, or the
  !> residuals cannot be computed there.
  subroutine lm_jacobian(problem, x, r, lower, upper, typical, fd_step, jac, ok)
    class(lm_problem_t), intent(inout) :: problem
    real(dp), intent(in) :: x(:), r(:), lower(:), upper(:), typical(:), fd_step
    real(dp), intent(out) :: jac(:, :)
    logical, intent(out) :: ok
    real(dp), allocatable :: xh(:), rh(:)
    real(dp) :: h, step, intended
    integer :: j, side
    logical :: inside
    allocate (xh(size(x)), rh(size(r)))
    ok = .false.
    do j = 1, size(x)
      step = fd_step * max(abs(x(j)), typical(j))
      inside = .false.
      ! forward, backward, and (a box narrower than the step) half the larger room
      do side = 1, 3
        select case (side)
        case (1)
          h = step
        case (2)
          h = -step
        case default
          h = 0.5_dp * merge(upper(j) - x(j), lower(j) - x(j), upper(j) - x(j) >= x(j) - lower(j))
        end select
        xh = x
        xh(j) = x(j) + h
        if (xh(j) > upper(j) .or. xh(j) < lower(j) .or. .not. abs(xh(j) - x(j)) > 0.0_dp) cycle
        intended = xh(j)
        call problem%project(xh)
        ! inside: the projection moved nothing
        inside = .not. (abs(xh(j) - intended) > 0.0_dp .or. any(abs(xh(1:j - 1) - x(1:j - 1)) > 0.0_dp) &
                        .or. any(abs(xh(j + 1:) - x(j + 1:)) > 0.0_dp))
        if (inside) exit
      end do
      if (.not. inside) return
      h = xh(j) - x(j)
      call lm_evaluate(problem, xh, rh, ok)
      if (.not. ok) return
      jac(:, j) = (rh - r) / h
    end do
    ok = .true.
  end subroutine lm_jacobian

  !> Standard errors and correlations from the Jacobian `jac` and residuals `r` at the optimum:
  !> cov = sigma^2 (J^T J)^-1, sigma^2 = |r|^2 / (m - n), computed from the SVD of J with its
  !> columns scaled to unit norm (dgesvd), so that units do not enter the condition number.
  !> A parameter is not identifiable when its column is zero or when it takes part (|v_jk| > 0.1)
  !> in a direction whose relative singular value is below 1e-6; its standard error is then
  !> +huge and the covariance is the pseudo-inverse's over the other directions.
  subroutine lm_statistics(jac, r, st)
    real(dp), intent(in) :: jac(:, :), r(:)
    type(lm_stats_t), intent(out) :: st
    integer :: m, n, j, k, info, lwork
    real(dp), allocatable :: a(:, :), u(:, :), vt(:, :), work(:), cov(:, :), c(:)
    real(dp) :: query(1)

    m = size(jac, 1)
    n = size(jac, 2)
    allocate (a(m, n), u(1, 1), vt(n, n), c(n), cov(n, n), st%singular(min(m, n)))
    allocate (st%std_error(n), st%correlation(n, n), st%identifiable(n))
    st%identifiable = .true.
    do j = 1, n
      c(j) = norm2(jac(:, j))
      if (c(j) > 0.0_dp) then
        a(:, j) = jac(:, j) / c(j)
      else
        a(:, j) = 0.0_dp
        st%identifiable(j) = .false.
      end if
    end do
    st%sigma2 = 0.0_dp
    if (m > n) st%sigma2 = dot_product(r, r) / real(m - n, dp)
    call dgesvd('N', 'A', m, n, a, m, st%singular, u, 1, vt, n, query, -1, info)
    lwork = max(1, int(query(1)))
    allocate (work(lwork))
    call dgesvd('N', 'A', m, n, a, m, st%singular, u, 1, vt, n, work, lwork, info)
    st%singular = merge(st%singular, 0.0_dp, info == 0)
    st%condition = huge(1.0_dp)
    if (st%singular(min(m, n)) > 0.0_dp) st%condition = st%singular(1) / st%singular(min(m, n))
    st%ill_conditioned = st%condition > ill_condition .or. m < n
    cov = 0.0_dp
    do k = 1, min(m, n)
      if (st%singular(k) > unidentifiable * st%singular(1)) then
        do j = 1, n
          cov(:, j) = cov(:, j) + vt(k, :) * vt(k, j) / st%singular(k)**2
        end do
      else
        where (abs(vt(k, :)) > 0.1_dp) st%identifiable = .false.
      end if
    end do
    if (m < n) st%identifiable = .false.
    do j = 1, n
      if (st%identifiable(j)) then
        st%std_error(j) = sqrt(st%sigma2 * cov(j, j)) / c(j)
      else
        st%std_error(j) = huge(1.0_dp)
      end if
    end do
    do k = 1, n
      do j = 1, n
        if (cov(j, j) > 0.0_dp .and. cov(k, k) > 0.0_dp) then
          st%correlation(j, k) = cov(j, k) / sqrt(cov(j, j) * cov(k, k))
        else
          st%correlation(j, k) = merge(1.0_dp, 0.0_dp, j == k)
        end if
      end do
    end do
  end subroutine lm_statistics

  !> The statistics of n parameters where none can be computed: infinite standard errors, no
  !> parameter identifiable, the unit matrix as correlation, an infinite condition number.
  pure subroutine lm_statistics_unavailable(n, st)
    integer, intent(in) :: n
    type(lm_stats_t), intent(out) :: st
    integer :: j
    allocate (st%std_error(n), st%correlation(n, n), st%identifiable(n), st%singular(n))
    st%std_error = huge(1.0_dp)
    st%identifiable = .false.
    st%singular = 0.0_dp
    st%correlation = 0.0_dp
    do j = 1, n
      st%correlation(j, j) = 1.0_dp
    end do
    st%condition = huge(1.0_dp)
    st%ill_conditioned = .true.
  end subroutine lm_statistics_unavailable

end module interlock_lm
