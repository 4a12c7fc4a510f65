!> A point history under mixed control: one material point taken step by step along a loading
!> path (interlock_path), each step solved by interlock_step_solver, each row handed to a sink
!> (interlock_history_sink) as soon as it is computed. One run loop serves the plain history
!> (run_history: the path's steps) and global Richardson extrapolation
!> (run_history_extrapolated: the history run twice in lockstep from the same initial state,
!> with the path's steps (n) and with every segment's step count doubled (2n); separation and
!> traction are 2 u(2n) - u(n) at the n run's steps). The module is the driver's front: it
!> passes on the types and the step solve its users need.
module interlock_mixed_control
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_3d_t, &
      status_ok, format_real, format_integer
  use interlock_path, only: arc_t, path_point
  use interlock_history_sink, only: history_row_t, history_sink_t, history_t, begin_history, &
      note_sliding_jump
  use interlock_step_solver, only: control_t, solve_step, point_vector
  implicit none
  private
  public :: control_t, arc_t, history_row_t, history_sink_t, history_t, solve_step, run_history, &
            run_history_extrapolated

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
    call run_path(mat, solver, ctl, times, values, steps, initial, hist, 1, arcs)
  end subroutine run_history

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
    call run_path(mat, solver, ctl, times, values, steps, initial, hist, 2, arcs)
  end subroutine run_history_extrapolated

  !> The run loop of run_history (refinement 1: the run with the path's steps alone) and
  !> run_history_extrapolated (refinement 2: that run and, in lockstep, the run whose segments
  !> of more than one step have twice the steps, fine_steps_per_step).
  subroutine run_path(mat, solver, ctl, times, values, steps, initial, hist, refinement, arcs)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(control_t), intent(in) :: ctl
    real(dp), intent(in) :: times(:), values(:, :)
    integer, intent(in) :: steps(:), refinement
    type(interlock_state_3d_t), intent(in) :: initial
    class(history_sink_t), intent(inout) :: hist
    type(arc_t), intent(in), optional :: arcs(:)
    type(interlock_state_3d_t) :: old_c, new_c, old_f, new_f
    type(history_row_t) :: row
    real(dp), dimension(ctl%n) :: tc_start, tc_end, tf_start, tf_end, sigma_c, sigma_f
    real(dp) :: time, time_f
    integer :: iseg, j, k, refine, step_f, iterations, substeps, it, sub, stat, n
    logical :: extrapolated
    character(len=512) :: message

    n = ctl%n
    extrapolated = refinement == 2
    call begin_history(hist, mat%n_planes, n, extrapolated)
    old_c = initial
    old_f = old_c
    step_f = 0
    tc_end = values(1:n, 1)
    tf_end = values(1:n, 1)
    do iseg = 1, size(steps)
      refine = 0
      if (extrapolated) refine = fine_steps_per_step(steps(iseg))
      do j = 1, steps(iseg)
        tc_start = tc_end
        call path_point(times, values(1:n, :), iseg, j, steps(iseg), tc_end, time, arcs)
        call solve_step(mat, solver, ctl, old_c, tc_start, tc_end, new_c, sigma_c, iterations, &
                        substeps, stat, message)
        if (stat /= status_ok) then
          hist%status = 'stopped at ' // step_place(steps, iseg, j, time) // ': '
          if (extrapolated) hist%status = hist%status // 'the run with the deck''s steps: '
          hist%status = hist%status // trim(message)
          return
        end if
        ! The fine run's steps that end where the coarse run's step j does (none without it).
        do k = 1, refine
          tf_start = tf_end
          step_f = step_f + 1
          call path_point(times, values(1:n, :), iseg, refine * (j - 1) + k, refine * steps(iseg), &
                          tf_end, time_f, arcs)
          call solve_step(mat, solver, ctl, old_f, tf_start, tf_end, new_f, sigma_f, it, sub, &
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
        if (extrapolated) then
          row = state_row(time, new_f, sigma_f, iterations, substeps)
          row%separation(1:n) = 2.0_dp * point_vector(new_f%s, new_f%s_t2, n) - &
                                point_vector(new_c%s, new_c%s_t2, n)
          row%traction(1:n) = 2.0_dp * sigma_f - sigma_c
        else
          row = state_row(time, new_c, sigma_c, iterations, substeps)
        end if
        call keep_row(hist, row, steps, iseg, j, stat)
        if (stat /= 0) return
        if (steps(iseg) == 1) call note_sliding_jump(hist, mat%n_planes, old_c, new_c, times, iseg)
        old_c = new_c
      end do
    end do
  end subroutine run_path

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
    row%separation(1:size(sigma)) = point_vector(new%s, new%s_t2, size(sigma))
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

end module interlock_mixed_control
