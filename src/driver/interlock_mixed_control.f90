!> Mixed control of one material point: each component of the relative displacement (two in 2D:
!> N, T; three in 3D: N, T1, T2, SPEC section 9) is either prescribed (separation-driven) or
!> solved for so that the matching traction takes a prescribed value (traction-driven). A 2D
!> point is updated by interlock_update, a 3D one by interlock_update_3d. One driven component:
!> a scalar Newton iteration on the consistent tangent, safeguarded by a bracket (bisection
!> fallback) and a bounded bracket search. Two or three: Newton on the driven block of the
!> tangent (LAPACK dgesv) with a backtracking line search. Every step is solved
!> from the state at the start of the step (the state is never updated during the iterations);
!> a step that cannot be solved is cut in halves (and regrown after successes), a bounded number
!> of times. A history is a sequence of such steps along a loading path of straight segments
!> and, in 3D, circular arcs in the (T1, T2) plane (arc_t).
!> Where the relative tolerance is below the floating-point resolution of the separation (a very
!> stiff interface, or newton_tol near eps), a solve is accepted once the residual is at most
!> what that resolution allows, |K| 8 eps |s| (a Newton correction of at most 8 ulps of s, or s
!> resolved to adjacent floating-point numbers; docs/history-output.md).
!> Global Richardson extrapolation (run_history_extrapolated): the history is run twice in
!> lockstep from the same initial state, with the path's steps (n) and with every segment's
!> step count doubled (2n); separation and traction are 2 u(2n) - u(n) at the n run's steps.
module interlock_mixed_control
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_t, &
      interlock_state_3d_t, interlock_info_t, interlock_update, interlock_update_3d, status_ok, &
      format_real, format_integer, is_nan_value, max_planes, separation_bound
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: control_t, arc_t, history_row_t, history_sink_t, history_t, solve_step, run_history, &
            run_history_extrapolated, component_names

  character(len=10), parameter :: component_names(2) = [character(len=10) :: 'normal', 'tangential']
  !> The names of the components in messages: 2D (N, T) and 3D (N, T1, T2).
  character(len=8), parameter :: traction_names(2) = [character(len=8) :: 'sigma_N', 'sigma_T']
  character(len=8), parameter :: traction_names_3d(3) = [character(len=8) :: 'sigma_N', &
    'sigma_T1', 'sigma_T2']
  character(len=4), parameter :: separation_names(2) = [character(len=4) :: 's_N', 's_T']
  character(len=4), parameter :: separation_names_3d(3) = [character(len=4) :: 's_N', 's_T1', 's_T2']
  !> The one-step segments that slid or wore named in history_sink_t%sliding_jumps (the others
  !> are counted).
  integer, parameter :: listed_jumps = 3

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

  !> A segment of the loading path that is a circular arc in the (T1, T2) plane (3D only): at
  !> the fraction f of the segment the in-plane components are center + radius (cos a, sin a),
  !> a = angle0 + sweep f; the normal component goes linearly. sweep = 0: a straight segment.
  type :: arc_t
    real(dp) :: sweep = 0.0_dp          !< angle swept [rad], > 0 counter-clockwise
    real(dp) :: angle0 = 0.0_dp         !< angle of the start point about the center [rad]
    real(dp) :: radius = 0.0_dp         !< [mm]
    real(dp) :: center(2) = 0.0_dp      !< (s_T1, s_T2) [mm]
  end type arc_t

  !> One row of a history: the state at the end of a load step. separation and traction hold
  !> (N, T) in 2D, (N, T1, T2) in 3D (the sink's n_components).
  type :: history_row_t
    real(dp) :: time = 0.0_dp
    real(dp) :: separation(3) = 0.0_dp, traction(3) = 0.0_dp
    real(dp), dimension(max_planes) :: damage = 0.0_dp, beta = 0.0_dp, frictional_slip = 0.0_dp, &
                                       zeta = 0.0_dp, theta = 0.0_dp, friction_traction = 0.0_dp
    !> the strike components of the frictional slip and the friction traction (3D)
    real(dp), dimension(max_planes) :: sf_strike = 0.0_dp, tauf_strike = 0.0_dp
    real(dp) :: work = 0.0_dp, stored = 0.0_dp, diss_damage = 0.0_dp, diss_friction = 0.0_dp
    integer :: iterations = 0, substeps = 0
  end type history_row_t

  !> Where the rows of a history go as they are computed (run_history, put): kept in memory
  !> (history_t) or written to a file as they come (interlock_history_output), so that a long
  !> history never has to be held whole.
  type, abstract :: history_sink_t
    integer :: n_rows = 0                         !< rows computed so far
    integer :: n_planes = 0
    integer :: n_components = 2                   !< 2 (N, T) or 3 (N, T1, T2)
    character(len=:), allocatable :: status       !< 'completed' or why the case stopped
    !> .true.: separation and traction are Richardson-extrapolated, 2 u(2n) - u(n); the state
    !> variables and energies are those of the run with doubled steps, iterations and substeps
    !> the sums of both runs (run_history_extrapolated)
    logical :: extrapolated = .false.
    !> The one-step segments (load jumps) in which a plane slid or wore, as "t = a to b, ...",
    !> '' if none: their end state is the scheme's, not the law's (one step of a scheme of
    !> order one or two over the whole jump), and more steps elsewhere do not change it. The
    !> first listed_jumps of them, then their count ("... and 997 more: 1000 segments"): a deck
    !> with one point per step has thousands.
    character(len=:), allocatable :: sliding_jumps
    !> how many one-step segments slid or wore; the text of the first listed_jumps of them
    integer :: n_sliding_jumps = 0
    character(len=:), allocatable :: listed_jumps_text
  contains
    procedure(put_row), deferred :: put
  end type history_sink_t

  abstract interface
    !> Take row sink%n_rows (already counted). stat /= 0: the row could not be kept (the history
    !> stops; the sink knows why).
    subroutine put_row(sink, row, stat)
      import :: history_sink_t, history_row_t
      class(history_sink_t), intent(inout) :: sink
      type(history_row_t), intent(in) :: row
      integer, intent(out) :: stat
    end subroutine put_row
  end interface

  !> A whole history in memory: one row per load step (row 1 = after the first step).
  type, extends(history_sink_t) :: history_t
    real(dp), allocatable :: time(:)
    real(dp), allocatable :: separation(:, :), traction(:, :)         ! (n_components, n)
    real(dp), allocatable :: damage(:, :), beta(:, :), frictional_slip(:, :), zeta(:, :), &
                             theta(:, :), friction_traction(:, :), &
                             sf_strike(:, :), tauf_strike(:, :)       ! (n_planes, n)
    real(dp), allocatable :: work(:), stored(:), diss_damage(:), diss_friction(:)
    integer, allocatable :: iterations(:), substeps(:)
  contains
    procedure :: put => history_put
    procedure :: reserve => history_reserve
    procedure :: clear => history_clear
  end type history_t

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

  !> Run a whole history: the path goes through the points (times(i), values(:, i)) in
  !> `steps(i)` uniform steps per segment, each component's value (ctl%n of them: values(1:n,
  !> i)) being a separation [mm] or a traction [MPa] as `ctl%traction` says; `arcs` (optional,
  !> 3D, one per segment): the segments that are arcs in the (T1, T2) plane. The history starts
  !> from `initial` (a 2D history from its in-plane part: its strike components and s_T2,
  !> sigma_T2 are 0; point 1 should match it). Each row goes to `hist` as soon as it is
  !> computed. The history stops early when a step cannot be solved or a row cannot be kept.
  subroutine run_history(mat, solver, ctl, times, values, steps, initial, hist, arcs)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    real(dp), intent(in) :: times(:), values(:, :)
    integer, intent(in) :: steps(:)
    type(interlock_state_3d_t), intent(in) :: initial
    class(history_sink_t), intent(inout) :: hist
    type(arc_t), intent(in), optional :: arcs(:)
    type(interlock_state_3d_t) :: old, new
    real(dp) :: t_start(ctl%n), t_end(ctl%n), sigma(ctl%n), time
    integer :: iseg, j, iterations, substeps, stat
    character(len=512) :: message

    call begin_history(hist, mat%n_planes, ctl%n, .false.)
    old = initial
    t_end = values(1:ctl%n, 1)
    do iseg = 1, size(steps)
      do j = 1, steps(iseg)
        t_start = t_end
        call path_point(times, values(1:ctl%n, :), iseg, j, steps(iseg), t_end, time, arcs)
        call solve_step_3d(mat, solver, ctl, old, t_start, t_end, new, sigma, iterations, &
                           substeps, stat, message)
        if (stat /= status_ok) then
          hist%status = 'stopped at ' // step_place(steps, iseg, j, time) // ': ' // trim(message)
          return
        end if
        call keep_row(hist, state_row(time, new, sigma, iterations, substeps), steps, iseg, j, &
                      stat)
        if (stat /= 0) return
        if (steps(iseg) == 1) call note_sliding_jump(hist, mat%n_planes, old, new, times, iseg)
        old = new
      end do
    end do
  end subroutine run_history

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

  !> A one-step segment iseg from `old` to `new`: noted in hist%sliding_jumps where a plane slid
  !> (its frictional slip changed, along the dip or the strike) or wore (its inclination changed).
  subroutine note_sliding_jump(hist, np, old, new, times, iseg)
    class(history_sink_t), intent(inout) :: hist
    integer, intent(in) :: np, iseg
    type(interlock_state_3d_t), intent(in) :: old, new
    real(dp), intent(in) :: times(:)
    if (.not. (any(abs(new%sf(1:np) - old%sf(1:np)) > 0.0_dp) .or. &
               any(abs(new%sf_strike(1:np) - old%sf_strike(1:np)) > 0.0_dp) .or. &
               any(abs(new%theta(1:np) - old%theta(1:np)) > 0.0_dp))) return
    hist%n_sliding_jumps = hist%n_sliding_jumps + 1
    if (hist%n_sliding_jumps <= listed_jumps) then
      if (hist%n_sliding_jumps > 1) hist%listed_jumps_text = hist%listed_jumps_text // ', '
      hist%listed_jumps_text = hist%listed_jumps_text // 't = ' // format_real(times(iseg)) // &
                               ' to ' // format_real(times(iseg + 1))
      hist%sliding_jumps = hist%listed_jumps_text
    else
      hist%sliding_jumps = hist%listed_jumps_text // ' and ' // &
        format_integer(hist%n_sliding_jumps - listed_jumps) // ' more: ' // &
        format_integer(hist%n_sliding_jumps) // ' segments'
    end if
  end subroutine note_sliding_jump

  !> Global Richardson extrapolation of a history: the run with the path's steps (n, the
  !> "coarse" run) and the run with the step count of every segment of more than one step
  !> doubled (2n, the "fine" run) go in lockstep from the same initial state (each is step for
  !> step what run_history computes). A segment of one step is a load jump (the paper's
  !> preload): both runs take it alike, in one step, so that both start the next segment from
  !> the same kind of state and the extrapolation converges to the deck's history with that
  !> jump. Row i is at the coarse run's step i (= the fine run's step that ends at the same time
  !> and path point): separation and traction are 2 u_fine - u_coarse (second order where both
  !> runs are first order); the state variables and energies are the fine run's (extrapolating
  !> them could leave their admissible ranges: D in [0, 1], zeta >= 0, theta between theta_f and
  !> theta_0); iterations and substeps are the sums of the coarse step and the fine step(s). A
  !> traction-driven component is solved to its target in both runs, so its extrapolated value
  !> is the target within 3 ctl%tol times the traction scale. The history stops at the first
  !> coarse step where either run cannot solve its step(s); the status says which run and why.
  subroutine run_history_extrapolated(mat, solver, ctl, times, values, steps, initial, hist, arcs)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    real(dp), intent(in) :: times(:), values(:, :)
    integer, intent(in) :: steps(:)
    type(interlock_state_3d_t), intent(in) :: initial
    class(history_sink_t), intent(inout) :: hist
    type(arc_t), intent(in), optional :: arcs(:)
    type(interlock_state_3d_t) :: old_c, new_c, old_f, new_f
    type(history_row_t) :: row
    real(dp), dimension(ctl%n) :: tc_start, tc_end, tf_start, tf_end, sigma_c, sigma_f
    real(dp) :: time, time_f
    integer :: iseg, j, k, refine, step_f, iterations, substeps, it, sub, stat, n
    character(len=512) :: message

    n = ctl%n
    call begin_history(hist, mat%n_planes, n, .true.)
    old_c = initial
    old_f = old_c
    step_f = 0
    tc_end = values(1:n, 1)
    tf_end = values(1:n, 1)
    do iseg = 1, size(steps)
      refine = fine_steps_per_step(steps(iseg))
      do j = 1, steps(iseg)
        tc_start = tc_end
        call path_point(times, values(1:n, :), iseg, j, steps(iseg), tc_end, time, arcs)
        call solve_step_3d(mat, solver, ctl, old_c, tc_start, tc_end, new_c, sigma_c, iterations, &
                           substeps, stat, message)
        if (stat /= status_ok) then
          hist%status = 'stopped at ' // step_place(steps, iseg, j, time) // &
                        ': the run with the deck''s steps: ' // trim(message)
          return
        end if
        do k = 1, refine
          tf_start = tf_end
          step_f = step_f + 1
          call path_point(times, values(1:n, :), iseg, refine * (j - 1) + k, refine * steps(iseg), &
                          tf_end, time_f, arcs)
          call solve_step_3d(mat, solver, ctl, old_f, tf_start, tf_end, new_f, sigma_f, it, sub, &
                             stat, message)
          if (stat /= status_ok) then
            hist%status = 'stopped at ' // step_place(steps, iseg, j, time) // &
                          ': the run with doubled steps, at its step ' // &
                          format_integer(step_f) // ' (time ' // format_real(time_f) // '): ' // &
                          trim(message)
            return
          end if
          iterations = iterations + it
          substeps = substeps + sub
          old_f = new_f
        end do
        row = state_row(time, new_f, sigma_f, iterations, substeps)
        row%separation(1:n) = 2.0_dp * point_s(new_f, n) - point_s(new_c, n)
        row%traction(1:n) = 2.0_dp * sigma_f - sigma_c
        call keep_row(hist, row, steps, iseg, j, stat)
        if (stat /= 0) return
        if (steps(iseg) == 1) call note_sliding_jump(hist, mat%n_planes, old_c, new_c, times, iseg)
        old_c = new_c
      end do
    end do
  end subroutine run_history_extrapolated

  !> Steps of the run with doubled steps per step of a segment of n steps: 2, or 1 for a
  !> one-step segment (a load jump, taken alike in both runs).
  pure integer function fine_steps_per_step(n)
    integer, intent(in) :: n
    fine_steps_per_step = merge(1, 2, n == 1)
  end function fine_steps_per_step

  !> "step 3 of 21 (segment 2 of 2, its step 2 of 20; time 1.1)": where a step is on the path,
  !> counted from the path's first step (a preload segment included).
  function step_place(steps, iseg, j, time) result(text)
    integer, intent(in) :: steps(:), iseg, j
    real(dp), intent(in) :: time
    character(len=:), allocatable :: text
    text = 'step ' // format_integer(sum(steps(1:iseg - 1)) + j) // ' of ' // &
           format_integer(sum(steps)) // ' (segment ' // format_integer(iseg) // ' of ' // &
           format_integer(size(steps)) // ', its step ' // format_integer(j) // ' of ' // &
           format_integer(steps(iseg)) // '; time ' // format_real(time) // ')'
  end function step_place

  !> A history about to be computed: no rows, status 'completed' until a step fails.
  subroutine begin_history(hist, np, n_components, extrapolated)
    class(history_sink_t), intent(inout) :: hist
    integer, intent(in) :: np, n_components
    logical, intent(in) :: extrapolated
    hist%n_planes = np
    hist%n_components = n_components
    hist%n_rows = 0
    hist%extrapolated = extrapolated
    hist%status = 'completed'
    hist%sliding_jumps = ''
    hist%listed_jumps_text = ''
    hist%n_sliding_jumps = 0
  end subroutine begin_history

  !> Hand the next row (step j of segment iseg) to the sink; stat /= 0 (the sink could not keep
  !> it): the history stops.
  subroutine keep_row(hist, row, steps, iseg, j, stat)
    class(history_sink_t), intent(inout) :: hist
    type(history_row_t), intent(in) :: row
    integer, intent(in) :: steps(:), iseg, j
    integer, intent(out) :: stat
    hist%n_rows = hist%n_rows + 1
    call hist%put(row, stat)
    if (stat /= 0) then
      hist%n_rows = hist%n_rows - 1
      hist%status = 'stopped at ' // step_place(steps, iseg, j, row%time) // &
                    ': the row could not be stored'
    end if
  end subroutine keep_row

  !> The row of the state `new` at the end of a step.
  pure function state_row(time, new, sigma, iterations, substeps) result(row)
    real(dp), intent(in) :: time, sigma(:)
    type(interlock_state_3d_t), intent(in) :: new
    integer, intent(in) :: iterations, substeps
    type(history_row_t) :: row
    row%time = time
    row%separation(1:size(sigma)) = point_s(new, size(sigma))
    row%traction(1:size(sigma)) = sigma
    row%sf_strike = new%sf_strike
    row%tauf_strike = new%tauf_strike
    row%damage = new%damage
    row%beta = new%beta
    row%frictional_slip = new%sf
    row%zeta = new%zeta
    row%theta = new%theta
    row%friction_traction = new%tauf
    row%work = new%work
    row%stored = new%stored
    row%diss_damage = new%diss_damage
    row%diss_friction = new%diss_friction
    row%iterations = iterations
    row%substeps = substeps
  end function state_row

  !> history_t: keep the row (room grows by doubling).
  subroutine history_put(sink, row, stat)
    class(history_t), intent(inout) :: sink
    type(history_row_t), intent(in) :: row
    integer, intent(out) :: stat
    integer :: n, np
    stat = 0
    n = sink%n_rows
    np = sink%n_planes
    if (.not. allocated(sink%time)) call sink%reserve(max(n, 16))
    if (n > size(sink%time)) call sink%reserve(2 * size(sink%time))
    sink%time(n) = row%time
    sink%separation(:, n) = row%separation(1:sink%n_components)
    sink%traction(:, n) = row%traction(1:sink%n_components)
    sink%damage(:, n) = row%damage(1:np)
    sink%beta(:, n) = row%beta(1:np)
    sink%frictional_slip(:, n) = row%frictional_slip(1:np)
    sink%zeta(:, n) = row%zeta(1:np)
    sink%theta(:, n) = row%theta(1:np)
    sink%friction_traction(:, n) = row%friction_traction(1:np)
    sink%sf_strike(:, n) = row%sf_strike(1:np)
    sink%tauf_strike(:, n) = row%tauf_strike(1:np)
    sink%work(n) = row%work
    sink%stored(n) = row%stored
    sink%diss_damage(n) = row%diss_damage
    sink%diss_friction(n) = row%diss_friction
    sink%iterations(n) = row%iterations
    sink%substeps(n) = row%substeps
  end subroutine history_put

  !> Room for `capacity` rows, keeping the rows held.
  subroutine history_reserve(sink, capacity)
    class(history_t), intent(inout) :: sink
    integer, intent(in) :: capacity
    integer :: np
    np = sink%n_planes
    call grow_real(sink%time)
    call grow_real(sink%work)
    call grow_real(sink%stored)
    call grow_real(sink%diss_damage)
    call grow_real(sink%diss_friction)
    call grow_int(sink%iterations)
    call grow_int(sink%substeps)
    call grow_real_2d(sink%separation, sink%n_components)
    call grow_real_2d(sink%traction, sink%n_components)
    call grow_real_2d(sink%damage, np)
    call grow_real_2d(sink%beta, np)
    call grow_real_2d(sink%frictional_slip, np)
    call grow_real_2d(sink%zeta, np)
    call grow_real_2d(sink%theta, np)
    call grow_real_2d(sink%friction_traction, np)
    call grow_real_2d(sink%sf_strike, np)
    call grow_real_2d(sink%tauf_strike, np)

  contains

    subroutine grow_real(x)
      real(dp), allocatable, intent(inout) :: x(:)
      real(dp), allocatable :: y(:)
      integer :: m
      allocate (y(capacity))
      m = 0
      if (allocated(x)) m = min(size(x), capacity)
      if (m > 0) y(1:m) = x(1:m)
      call move_alloc(y, x)
    end subroutine grow_real

    subroutine grow_int(x)
      integer, allocatable, intent(inout) :: x(:)
      integer, allocatable :: y(:)
      integer :: m
      allocate (y(capacity))
      m = 0
      if (allocated(x)) m = min(size(x), capacity)
      if (m > 0) y(1:m) = x(1:m)
      call move_alloc(y, x)
    end subroutine grow_int

    subroutine grow_real_2d(x, width)
      real(dp), allocatable, intent(inout) :: x(:, :)
      integer, intent(in) :: width
      real(dp), allocatable :: y(:, :)
      integer :: m
      allocate (y(width, capacity))
      m = 0
      if (allocated(x)) m = min(size(x, 2), capacity)
      if (m > 0) y(:, 1:m) = x(:, 1:m)
      call move_alloc(y, x)
    end subroutine grow_real_2d

  end subroutine history_reserve

  !> Forget the rows held (the room stays): the next row is row 1 again.
  subroutine history_clear(sink)
    class(history_t), intent(inout) :: sink
    sink%n_rows = 0
  end subroutine history_clear

  !> The path's values and time at the end of step j of segment iseg, in n uniform steps (the
  !> segment's end point exactly at j = n). The same expression for every run, so that the
  !> step 2j of 2n steps lands on the same numbers as the step j of n. An arc segment (arcs,
  !> 3D) takes its in-plane components on the arc at every step, its end included (the deck
  !> puts the segment's end point there by the same expression).
  pure subroutine path_point(times, values, iseg, j, n, target, time, arcs)
    real(dp), intent(in) :: times(:), values(:, :)
    integer, intent(in) :: iseg, j, n
    real(dp), intent(out) :: target(:), time
    type(arc_t), intent(in), optional :: arcs(:)
    real(dp) :: f
    if (j == n) then
      target = values(:, iseg + 1)
      time = times(iseg + 1)
    else
      f = real(j, dp) / real(n, dp)
      target = values(:, iseg) + (values(:, iseg + 1) - values(:, iseg)) * f
      time = times(iseg) + (times(iseg + 1) - times(iseg)) * f
    end if
    if (present(arcs) .and. size(target) == 3) then
      if (abs(arcs(iseg)%sweep) > 0.0_dp) target(2:3) = arc_point(arcs(iseg), j, n)
    end if
  end subroutine path_point

  !> The point (s_T1, s_T2) of an arc after j of its n steps: angle0 + sweep j / n.
  pure function arc_point(arc, j, n) result(p)
    type(arc_t), intent(in) :: arc
    integer, intent(in) :: j, n
    real(dp) :: p(2), a
    a = arc%angle0 + arc%sweep * real(j, dp) / real(n, dp)
    p = arc%center + arc%radius * [cos(a), sin(a)]
  end function arc_point

  !> The separation of a point with n components: (s_N, s_T) or (s_N, s_T1, s_T2).
  pure function point_s(state, n) result(s)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: n
    real(dp) :: s(n)
    s(1:2) = state%s
    if (n == 3) s(3) = state%s_t2
  end function point_s

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
    sigma = point_sigma(old, ctl%n)
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
      sigma = point_sigma(cur, ctl%n)
    else
      new = old
      sigma = point_sigma(old, ctl%n)
    end if
  end subroutine solve_step_3d

  !> The traction of a point with n components.
  pure function point_sigma(state, n) result(sigma)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: n
    real(dp) :: sigma(n)
    sigma(1:2) = state%sigma
    if (n == 3) sigma(3) = state%sigma_t2
  end function point_sigma

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
    if (n == 2) then
      name = trim(traction_names(i))
    else
      name = trim(traction_names_3d(i))
    end if
  end function traction_name

  pure function separation_name(i, n) result(name)
    integer, intent(in) :: i, n
    character(len=:), allocatable :: name
    if (n == 2) then
      name = trim(separation_names(i))
    else
      name = trim(separation_names_3d(i))
    end if
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
    s = point_s(old, n)
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


end module interlock_mixed_control
