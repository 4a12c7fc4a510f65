!> The model side of a fit: the history of the deck with given parameter values (run in
!> memory), the history outputs along which the curves are compared, and the residuals of a
!> stage: sqrt(w_i) (y_model(x_i) - y_i) for every point of every curve of the stage.
!> Matching by branches: the abscissa of a cyclic test (the slip) runs back and forth, so a
!> measured point on the b-th monotone run of its abscissa is compared with the history
!> interpolated linearly on the history's b-th monotone run of the same output (with the run's
!> turning point before it). The branches of the file are counted before the window is applied,
!> so that a window (one cycle) keeps its place in the history.
module interlock_fit_model
  use, intrinsic :: iso_fortran_env, only: output_unit
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_3d_t, &
      prop_theta0, prop_thetaf, status_ok, format_integer, format_real, scheme_trapezoidal
  use interlock_deck, only: deck_t, deck_case, deck_set_property, deck_loading
  use interlock_mixed_control, only: history_t, run_history, run_history_extrapolated, arc_t
  use interlock_fit_deck, only: fit_t, curve_t, split_branches, law_angles, output_names, out_separation_t1, &
      out_separation_t2, out_traction_t1, out_traction_t2, out_traction_t_magnitude, out_slip_length
  use interlock_lm, only: lm_problem_t
  implicit none
  private
  public :: fit_problem_t, fit_history, curve_model, history_output, bound_state, law_project, &
            abscissa_held, scheme_order

  !> One stage's least-squares problem: all parameters' current values, the free ones of the
  !> stage (x of the problem) and its curves.
  type, extends(lm_problem_t) :: fit_problem_t
    type(fit_t) :: fit
    real(dp), allocatable :: values(:)
    integer, allocatable :: free(:), curves(:)
    integer :: stage = 1
    integer :: runs = 0
    real(dp) :: clock_start = 0.0_dp
    logical :: verbose = .true.
    character(len=:), allocatable :: failure   !< why the last evaluation failed
  contains
    procedure :: residuals => fit_residuals
    procedure :: progress => fit_progress
    procedure :: project => fit_project
  end type fit_problem_t

contains

  !> The history of the deck with the parameters set to `values` (fit%names order), run as
  !> interlock-history runs the deck's case: its loading points and the arcs of a 3D path
  !> (deck_loading), two or three components.
  !> message /= '': the values are inadmissible together or the history stopped.
  !> refine = 2: every segment of more than one step in twice as many steps (the discretization
  !> check; a one-step segment is a load jump and stays one step, as with `extrapolate`).
  subroutine fit_history(fit, values, hist, message, refine)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    type(history_t), intent(inout) :: hist
    character(len=:), allocatable, intent(out) :: message
    integer, intent(in), optional :: refine
    type(deck_t) :: d
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: state
    real(dp), allocatable :: points(:, :)
    type(arc_t), allocatable :: arcs(:)
    character(len=:), allocatable :: label
    character(len=1024) :: why
    integer :: i, stat

    message = ''
    d = fit%deck
    do i = 1, size(values)
      call deck_set_property(d, fit%property(i), values(i))
      if (fit%property(i) == prop_thetaf) d%thetaf_given = .true.
    end do
    if (present(refine)) then
      where (d%steps > 1) d%steps = refine * d%steps
    end if
    call deck_case(d, 1, mat, solver, state, label, stat, why)
    if (stat /= status_ok) then
      message = 'at ' // parameter_text(fit, values) // ': ' // trim(why)
      return
    end if
    hist%n_rows = 0
    call deck_loading(d, 1, points, arcs)
    if (d%extrapolate .and. allocated(arcs)) then
      call run_history_extrapolated(mat, solver, d%control, d%times, points, d%steps, state, &
                                    hist, arcs)
    else if (d%extrapolate) then
      call run_history_extrapolated(mat, solver, d%control, d%times, points, d%steps, state, hist)
    else if (allocated(arcs)) then
      call run_history(mat, solver, d%control, d%times, points, d%steps, state, hist, arcs)
    else
      call run_history(mat, solver, d%control, d%times, points, d%steps, state, hist)
    end if
    if (hist%status /= 'completed') message = 'at ' // parameter_text(fit, values) // &
                                              ': the history ' // hist%status
  end subroutine fit_history

  !> The order in the step of a history integrated by `scheme` (scheme_explicit, _implicit,
  !> _trapezoidal) in `n_components` dimensions (2 or 3), with (`extrapolate`) or without the
  !> history's global Richardson extrapolation. This states the schemes' measured orders
  !> (docs/model.md sections 5 and 9); the discretization check's bias estimate and advice
  !> follow from it. Explicit and implicit: first order. Trapezoidal: second order in 2D and in
  !> 3D (its slip direction by SPEC D14's mean-direction rule). Extrapolation, 2 u(2n) - u(n):
  !> second order in 2D from any scheme; in 3D counted as the scheme's own order (the bench
  !> measures 0.9 to 2.3 per doubling for the explicit and implicit schemes, docs/bench.md part 3b).
  pure integer function scheme_order(scheme, n_components, extrapolate) result(order)
    integer, intent(in) :: scheme, n_components
    logical, intent(in) :: extrapolate
    order = 1
    if (scheme == scheme_trapezoidal .or. (n_components == 2 .and. extrapolate)) order = 2
  end function scheme_order

  !> "name = value, ..." of every parameter, as the deck gives them (angles as magnitudes).
  function parameter_text(fit, values) result(text)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, size(values)
      if (i > 1) text = text // ', '
      text = text // trim(fit%names(i)) // ' = ' // format_real(values(i))
    end do
  end function parameter_text

  !> The law's constraint between two parameters, |theta_f| <= |theta_0| (SPEC: the asperities
  !> wear from theta_0 down to theta_f), on `values` (all parameters, fit%names order) where
  !> the parameters `movable` (indices) may move: where both may, the projection onto the
  !> half-plane (both to their mean, within both boxes: the projected step then slides along the
  !> constraint), else theta_f down to theta_0 or theta_0 up to theta_f. Each bound of the box
  !> lies in its parameter's own admissible range and the boxes meet the constraint
  !> (read_fit_deck), so the box and this constraint make the admissible set.
  pure subroutine law_project(fit, values, movable)
    type(fit_t), intent(in) :: fit
    real(dp), intent(inout) :: values(:)
    integer, intent(in) :: movable(:)
    integer :: it0, itf
    real(dp) :: theta0, thetaf, mean
    logical :: relevant, move0, movef
    call law_angles(fit, values, it0, itf, theta0, thetaf, relevant)
    if (.not. relevant .or. thetaf <= theta0) return
    movef = .false.
    move0 = .false.
    if (itf > 0) movef = any(movable == itf)
    if (it0 > 0) move0 = any(movable == it0)
    if (movef .and. move0) then
      mean = 0.5_dp * (thetaf + theta0)
      mean = min(max(mean, fit%lower(itf), fit%lower(it0)), fit%upper(itf), fit%upper(it0))
      values(itf) = mean
      values(it0) = mean
    else if (movef) then
      values(itf) = max(theta0, fit%lower(itf))
    else if (move0) then
      values(it0) = min(thetaf, fit%upper(it0))
    end if
  end subroutine law_project

  !> Where each parameter ended: '' (inside), 'lower bound', 'upper bound', or the law's limit
  !> 'theta_f = theta_0' (theta_f and theta_0 both on it, to 1e-8 relative, about the
  !> resolution of the fit's difference steps: an unworn joint).
  function bound_state(fit, values) result(state)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    character(len=20) :: state(size(values))
    integer :: i, it0, itf
    real(dp) :: theta0, thetaf
    logical :: relevant
    state = ''
    do i = 1, size(values)
      if (values(i) <= fit%lower(i)) state(i) = 'lower bound'
      if (values(i) >= fit%upper(i)) state(i) = 'upper bound'
    end do
    call law_angles(fit, values, it0, itf, theta0, thetaf, relevant)
    if (relevant .and. thetaf >= theta0 * (1.0_dp - 1.0e-8_dp)) then
      if (itf > 0) state(itf) = 'theta_f = theta_0'
      if (it0 > 0) state(it0) = 'theta_f = theta_0'
    end if
  end function bound_state

  !> The problem's admissible set: the law's constraint on the stage's free parameters.
  subroutine fit_project(problem, x)
    class(fit_problem_t), intent(inout) :: problem
    real(dp), intent(inout) :: x(:)
    real(dp), allocatable :: values(:)
    allocate (values(size(problem%values)))
    values = problem%values
    values(problem%free) = x
    call law_project(problem%fit, values, problem%free)
    x = values(problem%free)
  end subroutine fit_project

  !> History output k (interlock_fit_deck's output_names) as a series over the rows. The
  !> T2 outputs of a 2D history (which read_fit_deck refuses) would be zero.
  function history_output(hist, k) result(v)
    type(history_t), intent(in) :: hist
    integer, intent(in) :: k
    real(dp), allocatable :: v(:), t2(:)
    integer :: n, i
    n = hist%n_rows
    select case (k)
    case (1)
      v = hist%time(1:n)
    case (2)
      v = hist%separation(1, 1:n)
    case (3, out_separation_t1)
      v = hist%separation(2, 1:n)
    case (4)
      v = hist%traction(1, 1:n)
    case (5, out_traction_t1)
      v = hist%traction(2, 1:n)
    case (out_separation_t2)
      v = component_t2(hist%separation)
    case (out_traction_t2)
      v = component_t2(hist%traction)
    case (out_traction_t_magnitude)
      v = hypot(hist%traction(2, 1:n), component_t2(hist%traction))
    case (out_slip_length)
      t2 = component_t2(hist%separation)
      allocate (v(n))
      if (n > 0) v(1) = 0.0_dp
      do i = 2, n
        v(i) = v(i - 1) + hypot(hist%separation(2, i) - hist%separation(2, i - 1), t2(i) - t2(i - 1))
      end do
    case (6)
      v = hist%work(1:n)
    case (7)
      v = hist%stored(1:n)
    case (8)
      v = hist%diss_damage(1:n)
    case default
      v = hist%diss_friction(1:n)
    end select

  contains

    !> The T2 row of a (components, rows) array over the history's rows; zero in 2D.
    function component_t2(a) result(c)
      real(dp), intent(in) :: a(:, :)
      real(dp) :: c(n)
      c = 0.0_dp
      if (size(a, 1) >= 3) c = a(3, 1:n)
    end function component_t2

  end function history_output

  !> '' or why the curve's abscissa does not identify a point of the history `hist` (of the
  !> deck `d`): on a branch of the history its output c%along holds still (within the branch
  !> split's tolerance) for more than one step while c%against changes by more than 1e-3 of its
  !> largest magnitude, and the curve has more than one point at that value on that branch.
  !> Branch matching would compare each of them with one value of the history (where the
  !> branch first reaches it). A per-component slip on a path that holds that component for a
  !> whole leg is such an abscissa (s_T1 on the second leg of a square path); the slip length
  !> and time, which grow with every step, are not.
  function abscissa_held(c, hist, d) result(message)
    type(curve_t), intent(in) :: c
    type(history_t), intent(in) :: hist
    type(deck_t), intent(in) :: d
    character(len=:), allocatable :: message
    real(dp), allocatable :: hx(:), hy(:)
    integer, allocatable :: hb(:)
    real(dp) :: tol, yscale, t_mid
    integer :: a, z, n, points, seg

    message = ''
    n = hist%n_rows
    if (n < 3) return
    allocate (hx(n), hy(n))
    hx = history_output(hist, c%along)
    hy = history_output(hist, c%against)
    tol = 1.0e-6_dp * (maxval(hx) - minval(hx))
    yscale = maxval(abs(hy))
    call split_branches(hx, tol, hb)
    a = 1
    do while (a < n)
      z = a
      do while (z < n)
        if (abs(hx(z + 1) - hx(a)) > tol .or. hb(z + 1) /= hb(a)) exit
        z = z + 1
      end do
      if (z - a >= 2 .and. maxval(hy(a:z)) - minval(hy(a:z)) > 1.0e-3_dp * yscale) then
        points = count(c%branch == hb(a) .and. abs(c%x - hx(a)) <= max(tol, c%tolerance))
        if (points >= 2) then
          t_mid = 0.5_dp * (hist%time(a) + hist%time(z))
          seg = max(1, min(size(d%times) - 1, count(d%times < t_mid)))
          message = 'curve ' // c%name // ': its abscissa ' // c%x_column // ' (the ' // &
            'history''s ' // trim(output_names(c%along)) // ') holds still at ' // &
            format_real(hx(a)) // ' from time ' // format_real(hist%time(a)) // ' to ' // &
            format_real(hist%time(z)) // ' of the history (' // segment_name(d, seg) // &
            '), while ' // &
            trim(output_names(c%against)) // ' goes from ' // format_real(hy(a)) // ' to ' // &
            format_real(hy(z)) // '; the curve has ' // format_integer(points) // ' points ' // &
            'there, each of which would be compared with one value of the history. The ' // &
            'abscissa must identify a point of the history: take the slip length ' // &
            '(curve_along = ''slip_length'', curve_x the file''s column of the slip path''s ' // &
            'length) or time (docs/fit.md, "The abscissa")'
          return
        end if
      end if
      a = z + 1
    end do
  end function abscissa_held

  !> "segment k of the loading", or "leg k of the square path" on a path deck
  !> (segment 1 is its preload).
  function segment_name(d, seg) result(text)
    type(deck_t), intent(in) :: d
    integer, intent(in) :: seg
    character(len=:), allocatable :: text
    if (len_trim(d%path_kind) > 0 .and. seg > 1) then
      text = 'leg ' // format_integer(seg - 1) // ' of the ' // trim(d%path_kind) // ' path'
    else
      text = 'segment ' // format_integer(seg) // ' of the loading'
    end if
  end function segment_name

  !> The model's values at the curve's points (branch matching, linear interpolation), and the
  !> range of history rows between the first and the last row used (first_row:last_row), for plots.
  subroutine curve_model(c, hist, y, first_row, last_row, message)
    type(curve_t), intent(in) :: c
    type(history_t), intent(in) :: hist
    real(dp), intent(out) :: y(:)
    integer, intent(out) :: first_row, last_row
    character(len=:), allocatable, intent(out) :: message
    real(dp), allocatable :: hx(:), hy(:)
    integer, allocatable :: hb(:)
    integer :: i, b, lo, hi, k, a, z, nb
    real(dp) :: tol, t

    message = ''
    allocate (hx(hist%n_rows), hy(hist%n_rows))
    hx = history_output(hist, c%along)
    hy = history_output(hist, c%against)
    first_row = 1
    last_row = size(hx)
    y = 0.0_dp
    if (size(hx) < 2) then
      message = 'the history has fewer than 2 rows'
      return
    end if
    tol = 1.0e-6_dp * (maxval(hx) - minval(hx))
    call split_branches(hx, tol, hb)
    nb = hb(size(hb))
    if (maxval(c%branch) > nb) then
      message = 'curve ' // c%name // ': its abscissa ' // c%x_column // ' runs through ' // &
                format_integer(maxval(c%branch)) // ' monotone branches, the history''s ' // &
                trim(output_names(c%along)) // ' through ' // format_integer(nb) // &
                ' only: the loading of the deck must follow the test''s path (' // c%turns // ')'
      return
    end if
    first_row = size(hx)
    last_row = 1
    b = 0
    lo = 1
    hi = 0
    do i = 1, size(c%x)
      if (c%branch(i) /= b) then
        b = c%branch(i)
        lo = findloc(hb, b, dim=1)
        hi = findloc(hb, b, dim=1, back=.true.)
        if (lo > 1) lo = lo - 1
      end if
      ! the segment of [lo, hi] that holds x (the branch is monotone)
      a = 0
      do k = lo, hi - 1
        if ((hx(k) - c%x(i)) * (hx(k + 1) - c%x(i)) <= 0.0_dp .and. abs(hx(k + 1) - hx(k)) > 0.0_dp) then
          a = k
          exit
        end if
      end do
      if (a == 0) then
        ! outside the branch's range by at most the split tolerance: the nearer end
        z = merge(lo, hi, abs(hx(lo) - c%x(i)) <= abs(hx(hi) - c%x(i)))
        if (abs(hx(z) - c%x(i)) > max(tol, c%tolerance)) then
          message = 'curve ' // c%name // ': the point ' // c%x_column // ' = ' // &
                    format_real(c%x(i)) // ' (branch ' // format_integer(b) // ') is outside ' // &
                    'the history''s range [' // format_real(min(hx(lo), hx(hi))) // ', ' // &
                    format_real(max(hx(lo), hx(hi))) // '] on that branch'
          return
        end if
        y(i) = hy(z)
        first_row = min(first_row, z)
        last_row = max(last_row, z)
      else
        t = (c%x(i) - hx(a)) / (hx(a + 1) - hx(a))
        y(i) = hy(a) + t * (hy(a + 1) - hy(a))
        first_row = min(first_row, a)
        last_row = max(last_row, a + 1)
      end if
    end do
  end subroutine curve_model

  subroutine fit_residuals(problem, x, r, ok)
    class(fit_problem_t), intent(inout) :: problem
    real(dp), intent(in) :: x(:)
    real(dp), intent(out) :: r(:)
    logical, intent(out) :: ok
    type(history_t) :: hist
    real(dp), allocatable :: values(:), y(:)
    character(len=:), allocatable :: message
    integer :: k, ic, first, n, r1, r2

    allocate (values(size(problem%values)))
    values = problem%values
    values(problem%free) = x
    problem%runs = problem%runs + 1
    call fit_history(problem%fit, values, hist, message)
    ok = len(message) == 0
    if (.not. ok) then
      problem%failure = message
      return
    end if
    first = 0
    do k = 1, size(problem%curves)
      ic = problem%curves(k)
      associate (c => problem%fit%curves(ic))
        n = size(c%x)
        allocate (y(n))
        call curve_model(c, hist, y, r1, r2, message)
        if (len(message) > 0) then
          problem%failure = message
          ok = .false.
          return
        end if
        r(first + 1:first + n) = sqrt(c%w) * (y - c%y)
        deallocate (y)
      end associate
      first = first + n
    end do
  end subroutine fit_residuals

  !> One line per accepted iteration: the cost, the free parameters, histories run, CPU time.
  subroutine fit_progress(problem, iteration, x, cost, lambda)
    class(fit_problem_t), intent(inout) :: problem
    integer, intent(in) :: iteration
    real(dp), intent(in) :: x(:), cost, lambda
    character(len=:), allocatable :: line
    character(len=32) :: buf
    real(dp) :: now
    integer :: j
    if (.not. problem%verbose) return
    call cpu_time(now)
    write (buf, '(es11.4)') cost
    line = '  stage ' // format_integer(problem%stage) // ' iteration ' // &
           format_integer(iteration) // ': cost ' // trim(adjustl(buf))
    do j = 1, size(x)
      write (buf, '(g0.8)') x(j)
      line = line // ', ' // trim(problem%fit%names(problem%free(j))) // ' = ' // trim(buf)
    end do
    write (buf, '(es8.1)') lambda
    line = line // ' (lambda ' // trim(adjustl(buf)) // ', ' // format_integer(problem%runs) // &
           ' histories, '
    write (buf, '(f0.1)') now - problem%clock_start
    line = line // trim(buf) // ' s)'
    write (output_unit, '(a)') line
    flush (output_unit)
  end subroutine fit_progress

end module interlock_fit_model
