!> interlock-fit DECK.nml: fit the law's parameters to measured curves (docs/fit.md). The deck is
!> an interlock-history deck with a &fit group. Exit status: 0 every stage converged; 1 a bad
!> deck, a history that cannot be run at the start values, or a file that cannot be written
!> (nothing is written); 2 the files are written but a stage stopped without converging
!> (max_iterations, or no step lowers the cost).
program interlock_fit
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use interlock_cli, only: folder_writable, warn
  use interlock_program_start, only: program_start_t, program_start, program_end, in_output_dir
  use interlock, only: dp, format_integer, format_real, scheme_name, &
      scheme_trapezoidal
  use interlock_mixed_control, only: history_t
  use interlock_history_output, only: output_check_target
  use interlock_deck, only: deck_scheme
  use interlock_fit_deck, only: fit_t, read_fit_deck, join_selected, output_names, folder_of
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use interlock_files, only: remove_file, rename_file, unguard_file, hold_signals
  use interlock_fit_model, only: fit_problem_t, fit_history, curve_model, history_output, &
      bound_state, abscissa_held, scheme_order
  use interlock_fit_output, only: stage_outcome_t, curve_outcome_t, discretization_t, &
      write_fit_file, write_fitted_deck, fitted_deck_check
  use interlock_lm, only: lm_solve, lm_jacobian, lm_statistics, lm_stats_t, lm_evaluate, &
      lm_least_squares, lm_statistics_unavailable
  implicit none

  type(program_start_t) :: start
  integer :: rc

  call program_start('interlock-fit', usage, .true., .true., start)
  call run_fit(start%decks(1)%path, rc)
  call program_end(rc)

contains

  subroutine run_fit(path, rc)
    character(len=*), intent(in) :: path
    integer, intent(out) :: rc
    type(fit_t) :: fit
    type(fit_problem_t) :: problem
    type(stage_outcome_t), allocatable :: stages(:)
    type(curve_outcome_t), allocatable :: curves(:)
    type(lm_stats_t) :: stats
    type(discretization_t) :: disc
    type(history_t) :: hist
    character(len=1024) :: message
    character(len=:), allocatable :: base, h5_name, deck_name, why, statistics, deck_temp, &
        h5_temp, folder
    character(len=20), allocatable :: at_bound(:)
    real(dp), allocatable :: values(:), r(:), jac(:, :), typical(:), x0(:)
    real(dp) :: t0, t1
    integer :: k, stat, slash, dot, j, r1, r2, n
    logical :: ok

    rc = 1
    call read_fit_deck(path, fit, stat, message)
    if (stat /= 0) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // trim(message)
      return
    end if
    ! (the deck's path without its extension, in --output-dir if given)
    slash = index(path, '/', back=.true.)
    dot = index(path(slash + 1:), '.', back=.true.)
    base = path
    if (dot > 1) base = path(1:slash + dot - 1)
    base = in_output_dir(start%output_dir, base)
    h5_name = base // '_fit.h5'
    deck_name = base // '_fitted.nml'
    call output_check_target(h5_name, path, message, 'interlock-fit', 'curves')
    if (len_trim(message) == 0) call fitted_deck_check(deck_name, path, message)
    if (len_trim(message) > 0) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': ' // trim(message)
      return
    end if
    folder = folder_of(base)
    if (len(folder) == 0) folder = './'
    if (.not. folder_writable(folder)) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': cannot write into ' // &
        'the folder ' // folder // ' (' // h5_name // ', ' // deck_name // '): checked ' // &
        'before the fit; --output-dir DIR writes elsewhere'
      return
    end if
    call scale_check(fit, message)
    if (len_trim(message) > 0) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': ' // trim(message)
      return
    end if
    do k = 1, size(fit%warnings)
      call warn('interlock-fit', path // ': ' // trim(fit%warnings(k)))
    end do

    values = fit%start
    typical = max(abs(fit%start), 1.0e-3_dp * (fit%upper - fit%lower))
    call say(path // ': ' // format_integer(size(fit%names)) // ' free parameter(s), ' // &
             format_integer(size(fit%curves)) // ' curve(s), ' // &
             format_integer(size(fit%stages)) // ' stage(s)')
    allocate (stages(size(fit%stages)))
    problem%fit = fit
    problem%verbose = .not. start%quiet
    call cpu_time(problem%clock_start)
    do k = 1, size(fit%stages)
      call cpu_time(t0)
      problem%stage = k
      problem%values = values
      problem%free = fit%stages(k)%free
      problem%curves = fit%stages(k)%curves
      problem%m = sum([(size(fit%curves(problem%curves(j))%x), j = 1, size(problem%curves))])
      problem%runs = 0
      problem%failure = ''
      call say('stage ' // format_integer(k) // ': ' // join_selected(fit%names, problem%free) // &
               ' on ' // join_selected(fit%curve_names, problem%curves) // ' (' // format_integer(problem%m) // ' points)')
      x0 = values(problem%free)
      call lm_solve(problem, x0, fit%lower(problem%free), fit%upper(problem%free), &
                    typical(problem%free), fit%options, stages(k)%result)
      if (.not. stages(k)%result%started) then
        ! nothing was computed: a bad deck in effect (exit 1, nothing written)
        write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': stage ' // &
          format_integer(k) // ': ' // stages(k)%result%reason // ': ' // why_failed(problem)
        return
      end if
      values(problem%free) = stages(k)%result%x
      call cpu_time(t1)
      stages(k)%seconds = t1 - t0
      stages(k)%runs = problem%runs
      if (.not. stages(k)%result%converged .and. len(problem%failure) > 0) &
        stages(k)%result%reason = stages(k)%result%reason // ': ' // problem%failure
      call say('stage ' // format_integer(k) // ' stopped after ' // &
               format_integer(stages(k)%result%iterations) // ' iterations (' // &
               format_integer(problem%runs) // ' histories, ' // seconds(t1 - t0) // '): ' // &
               stages(k)%result%reason)
      if (.not. stages(k)%result%converged) then
        rc = 2
        call warn('interlock-fit', path // ': stage ' // format_integer(k) // &
          ' did NOT converge: ' // stages(k)%result%reason // ' (its last accepted values ' // &
          'are kept; the results are written, exit status 2)')
      end if
    end do

    ! statistics over all parameters and all curves, at the fitted values
    problem%values = values
    problem%free = [(j, j = 1, size(values))]
    problem%curves = [(j, j = 1, size(fit%curves))]
    problem%m = sum([(size(fit%curves(j)%x), j = 1, size(fit%curves))])
    problem%verbose = .false.
    problem%failure = ''
    allocate (r(problem%m), jac(problem%m, size(values)))
    call lm_evaluate(problem, values, r, ok)
    if (ok) call lm_jacobian(problem, values, r, fit%lower, fit%upper, typical, &
                             fit%options%fd_step, jac, ok)
    statistics = ''
    if (ok) then
      call lm_statistics(jac, r, stats)
      call discretization_check(fit, values, r, jac, stats, disc)
    else
      statistics = 'not computed: the Jacobian at the fitted values cannot be computed: ' // &
                   why_failed(problem)
      call lm_statistics_unavailable(size(values), stats)
      disc%change = [(0.0_dp, j = 1, size(values))]
      disc%ratio = disc%change
      disc%note = 'not computed (no statistics)'
      rc = 2
    end if
    disc%order = scheme_order(deck_scheme(fit%deck), fit%deck%n_components, fit%deck%extrapolate)
    at_bound = bound_state(fit, values)

    ! the curves at the fitted values (the residuals there were computed: the history runs)
    call fit_history(fit, values, hist, why)
    allocate (curves(size(fit%curves)))
    do k = 1, size(fit%curves)
      associate (c => fit%curves(k), o => curves(k))
        n = size(c%x)
        allocate (o%model(n))
        call curve_model(c, hist, o%model, r1, r2, why)
        o%history_x = history_output(hist, c%along)
        o%history_y = history_output(hist, c%against)
        o%history_x = o%history_x(r1:r2)
        o%history_y = o%history_y(r1:r2)
        o%residual_norm = sqrt(sum(c%w * (o%model - c%y)**2))
        o%rms = sqrt(sum((o%model - c%y)**2) / n)
      end associate
    end do
    call report(fit, values, stats, curves, problem%m, at_bound, statistics, disc)

    ! both files under temporary names, then both renames with the signals from outside held,
    ! so that no signal ends the program between them: a failure anywhere leaves neither file
    ! new (exit 1), and the two files there always belong together
    call write_fitted_deck(deck_name, fit, values, deck_temp, stat, message)
    if (stat == 0) then
      call write_fit_file(h5_name, fit, start%command, values, stats, stages, curves, deck_name, &
                          at_bound, statistics, disc, h5_temp, stat, message)
      if (stat /= 0) call remove_file(deck_temp)
    end if
    if (stat == 0) then
      call hold_signals(.true.)
      call rename_file(h5_temp, h5_name, stat)
      if (stat /= 0) then
        message = 'cannot rename ' // h5_temp // ' to ' // h5_name
        call remove_file(h5_temp)
        call remove_file(deck_temp)
      else
        call rename_file(deck_temp, deck_name, stat)
        if (stat /= 0) then
          message = 'cannot rename ' // deck_temp // ' to ' // deck_name // ' (' // h5_name // &
                    ' removed too)'
          call remove_file(deck_temp)
          call remove_file(h5_name)
        end if
      end if
      call unguard_file(h5_temp)
      call unguard_file(deck_temp)
      call hold_signals(.false.)
    end if
    if (allocated(deck_temp)) call unguard_file(deck_temp)
    if (stat /= 0) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': ' // trim(message)
      rc = 1
      return
    end if
    write (output_unit, '(a)') path // ' -> ' // h5_name // ', ' // deck_name
    if (rc /= 2) rc = 0
  end subroutine run_fit

  !> Curves on another scale than the model at the start values (the deck's units are mm and
  !> MPa: a slip in metres spans a thousandth of the history's): each is a warning in
  !> fit%warnings. Branch matching would compare such a curve with the first thousandth of each
  !> branch of the history, and the fit would chase parameters far off. And an abscissa that
  !> does not identify a point of the history (abscissa_held): an error, in `message`.
  subroutine scale_check(fit, message)
    type(fit_t), intent(inout) :: fit
    character(len=*), intent(out) :: message
    type(history_t) :: hist
    character(len=:), allocatable :: why
    real(dp), allocatable :: hx(:), hy(:)
    real(dp) :: data_span, model_span, ratio
    character(len=512) :: line
    integer :: k
    message = ''
    call fit_history(fit, fit%start, hist, why)
    if (len(why) > 0 .or. hist%n_rows < 2) return   ! the first stage reports it
    do k = 1, size(fit%curves)
      associate (c => fit%curves(k))
        message = abscissa_held(c, hist, fit%deck)
        if (len_trim(message) > 0) return
        hx = history_output(hist, c%along)
        hy = history_output(hist, c%against)
        data_span = maxval(c%x) - minval(c%x)
        model_span = maxval(hx) - minval(hx)
        if (model_span > 0.0_dp .and. data_span < 1.0e-2_dp * model_span) then
          line = 'curve ' // c%name // ': its abscissa ' // c%x_column // ' spans ' // &
            format_real(data_span) // ', the history''s ' // trim(output_names(c%along)) // ' ' // &
            format_real(model_span) // ' (' // format_real(model_span / data_span) // &
            ' times more): is the curve in other units than the deck (mm, MPa; a slip in ' // &
            'metres)? It is compared with the start of each branch of the history only'
          fit%warnings = [fit%warnings, line]
        end if
        data_span = maxval(abs(c%y))
        model_span = maxval(abs(hy))
        if (data_span > 0.0_dp .and. model_span > 0.0_dp) then
          ratio = data_span / model_span
          if (ratio < 1.0e-2_dp .or. ratio > 1.0e2_dp) then
            line = 'curve ' // c%name // ': its values ' // c%y_column // ' reach ' // &
              format_real(data_span) // ', the history''s ' // trim(output_names(c%against)) // &
              ' at the start values ' // format_real(model_span) // ': is the curve in other ' // &
              'units than the deck (mm, MPa)?'
            fit%warnings = [fit%warnings, line]
          end if
        end if
      end associate
    end do
  end subroutine scale_check

  !> Why the last evaluation failed, or the generic reason (residuals not finite or too large).
  function why_failed(problem) result(text)
    type(fit_problem_t), intent(in) :: problem
    character(len=:), allocatable :: text
    text = problem%failure
    if (len(text) == 0) text = 'the residuals are not finite or their norm exceeds ' // &
      '1e100 (data or weights far off the model''s scale: check the units of the curves)'
  end function why_failed

  !> The discretization check: the fitted model's history with twice the steps per segment
  !> (fit_history refine = 2), and the change of the fitted values this implies, linearised at
  !> the optimum with the Jacobian of the statistics: dp = -J^+ (r_2N - r_N) (the residuals of
  !> the finer history at the fitted values minus those of the fit's own). By Richardson, with
  !> an error C/N^q of the scheme's order q (scheme_order), the fit's bias against the exact law
  !> is about -dp 2^q / (2^q - 1) (and the finer fit's -dp / (2^q - 1)).
  subroutine discretization_check(fit, values, r, jac, stats, disc)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:), r(:), jac(:, :)
    type(lm_stats_t), intent(in) :: stats
    type(discretization_t), intent(out) :: disc
    type(history_t) :: fine
    character(len=:), allocatable :: why
    real(dp), allocatable :: dr(:), y(:)
    integer :: k, first, n, r1, r2, j

    allocate (disc%change(size(values)), disc%ratio(size(values)), dr(size(r)))
    disc%change = 0.0_dp
    disc%ratio = 0.0_dp
    disc%note = ''
    call fit_history(fit, values, fine, why, refine=2)
    first = 0
    do k = 1, size(fit%curves)
      if (len(why) > 0) exit
      associate (c => fit%curves(k))
        n = size(c%x)
        allocate (y(n))
        call curve_model(c, fine, y, r1, r2, why)
        dr(first + 1:first + n) = sqrt(c%w) * (y - c%y) - r(first + 1:first + n)
        deallocate (y)
      end associate
      first = first + n
    end do
    if (len(why) > 0) then
      disc%note = 'not computed: the history with twice the steps fails: ' // why
      return
    end if
    if (.not. all(ieee_is_finite(dr))) then
      disc%note = 'not computed: the history with twice the steps gives residuals that are ' // &
                  'not finite'
      return
    end if
    disc%change = -lm_least_squares(jac, dr)
    do j = 1, size(values)
      if (stats%identifiable(j) .and. stats%std_error(j) > 0.0_dp) &
        disc%ratio(j) = disc%change(j) / stats%std_error(j)
    end do
  end subroutine discretization_check

  !> The table of results on the terminal.
  subroutine report(fit, values, stats, curves, m, at_bound, statistics, disc)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    type(lm_stats_t), intent(in) :: stats
    type(curve_outcome_t), intent(in) :: curves(:)
    integer, intent(in) :: m
    character(len=*), intent(in) :: at_bound(:), statistics
    type(discretization_t), intent(in) :: disc
    integer :: i, j, n, order
    real(dp) :: factor
    character(len=200) :: line
    character(len=:), allocatable :: flags, bad

    n = size(values)
    write (output_unit, '(a)') 'fitted parameters (standard errors from the Jacobian of all ' // &
      'curves at the optimum, ' // format_integer(m) // ' points):'
    write (output_unit, '(a16, 3a24, 2x, a)') 'parameter', 'value', 'standard error', 'start', &
      'bounds'
    bad = ''
    do i = 1, n
      flags = ''
      select case (trim(at_bound(i)))
      case ('')
      case ('theta_f = theta_0')
        flags = ' AT THE LAW''S LIMIT theta_f = theta_0 (no wear)'
      case default
        flags = ' AT THE ' // to_upper(trim(at_bound(i)))
      end select
      if (.not. stats%identifiable(i)) then
        flags = flags // ' NOT IDENTIFIABLE'
        bad = bad // ' ' // trim(fit%names(i))
      end if
      if (stats%identifiable(i)) then
        write (line, '(a16, es24.15, es24.4, es24.6)') trim(fit%names(i)), values(i), &
          stats%std_error(i), fit%start(i)
      else
        write (line, '(a16, es24.15, a24, es24.6)') trim(fit%names(i)), values(i), 'inf', &
          fit%start(i)
      end if
      write (output_unit, '(a, 2x, a, es10.3, a, es10.3, a, a)') trim(line), '[', fit%lower(i), &
        ', ', fit%upper(i), ']', flags
    end do
    if (len(statistics) > 0) write (output_unit, '(a)') 'statistics ' // statistics
    write (output_unit, '(a)') 'correlation matrix:'
    do i = 1, n
      write (output_unit, '(a16, *(f9.4))') trim(fit%names(i)), (stats%correlation(i, j), j = 1, n)
    end do
    write (line, '(es10.3)') stats%condition
    if (stats%condition >= huge(1.0_dp)) line = 'infinite'
    if (stats%ill_conditioned) then
      write (output_unit, '(a)') 'condition number of the scaled Jacobian: ' // &
        trim(adjustl(line)) // ': ILL-CONDITIONED (above 1e4: the data determine some ' // &
        'combination of parameters poorly; see the correlations)'
    else
      write (output_unit, '(a)') 'condition number of the scaled Jacobian: ' // trim(adjustl(line))
    end if
    if (len(bad) > 0) write (output_unit, '(a)') 'not identifiable from these curves:' // bad // &
      ' (the curves do not depend on it, or only together with others: a direction of the', &
      ' scaled Jacobian with a relative singular value below 1e-6)'
    write (output_unit, '(a)') 'residuals per curve (weighted norm; rms in the curve''s unit):'
    do i = 1, size(fit%curves)
      write (output_unit, '(2x, a20, es12.4, es12.4, i8, a)') fit%curves(i)%name, &
        curves(i)%residual_norm, curves(i)%rms, size(fit%curves(i)%x), ' points'
    end do
    if (len(disc%note) > 0) then
      write (output_unit, '(a)') 'discretization check ' // disc%note
      return
    end if
    order = disc%order
    factor = 2.0_dp**order / (2.0_dp**order - 1.0_dp)
    write (output_unit, '(a)') 'discretization check (the fitted model with twice the steps ' // &
      'per segment: the change of the fitted values it implies; the bias of the fitted values ' // &
      'against the exact law is about -' // format_real(factor) // 'x the change: ' // &
      scheme_text(fit) // ', order ' // format_integer(order) // '):'
    write (output_unit, '(a16, 3a24)') 'parameter', 'change', 'change / std. error', 'bias'
    do i = 1, n
      write (output_unit, '(a16, es24.4, f24.4, es24.4)') trim(fit%names(i)), disc%change(i), &
        disc%ratio(i), -factor * disc%change(i)
    end do
    if (maxval(abs(disc%ratio)) >= 0.1_dp) then
      write (output_unit, '(a)') 'the steps move the fit by more than 0.1 standard error'
      call warn('interlock-fit', fit%deck%path // ': the steps move the fit by more than 0.1 ' // &
        'standard error (the bias against the exact law is about ' // format_real(factor) // &
        'x the change: ' // scheme_text(fit) // ' is of order ' // format_integer(order) // &
        '): ' // finer_steps(fit, order) // ' (docs/fit.md, "The steps")')
    else
      write (output_unit, '(a)') 'the steps are fine enough: every change is below 0.1 ' // &
        'standard error'
    end if
  end subroutine report

  !> "the trapezoidal scheme in 3D" (with ", extrapolated" where the deck extrapolates).
  function scheme_text(fit) result(text)
    type(fit_t), intent(in) :: fit
    character(len=:), allocatable :: text
    text = 'the ' // trim(scheme_name(deck_scheme(fit%deck))) // ' scheme'
    if (fit%deck%extrapolate) text = text // ', extrapolated,'
    text = text // ' in ' // format_integer(fit%deck%n_components) // 'D'
  end function scheme_text

  !> What lowers the bias of the deck's steps (order `order`): more steps, and each change of
  !> the &solver that raises the order in the deck's dimension (scheme_order), never the
  !> deck's own choice.
  function finer_steps(fit, order) result(text)
    type(fit_t), intent(in) :: fit
    integer, intent(in) :: order
    character(len=:), allocatable :: text
    integer :: q
    text = 'give more steps (twice the steps make the bias ' // format_real(0.5_dp**order) // &
           'x as large)'
    associate (d => fit%deck)
      q = scheme_order(scheme_trapezoidal, d%n_components, d%extrapolate)
      if (deck_scheme(d) /= scheme_trapezoidal .and. q > order) &
        text = text // ', or scheme = ''trapezoidal'' (order ' // format_integer(q) // ' here)'
      q = scheme_order(deck_scheme(d), d%n_components, .true.)
      if (.not. d%extrapolate .and. q > order) &
        text = text // ', or extrapolate = .true. (order ' // format_integer(q) // ' here)'
    end associate
  end function finer_steps

  pure function to_upper(text) result(up)
    character(len=*), intent(in) :: text
    character(len=len(text)) :: up
    integer :: i
    up = text
    do i = 1, len(text)
      if (text(i:i) >= 'a' .and. text(i:i) <= 'z') up(i:i) = achar(iachar(text(i:i)) - 32)
    end do
  end function to_upper

  function seconds(t) result(text)
    real(dp), intent(in) :: t
    character(len=:), allocatable :: text
    character(len=16) :: buf
    write (buf, '(f0.2)') t
    text = trim(buf) // ' s CPU'
  end function seconds

  subroutine say(text)
    character(len=*), intent(in) :: text
    if (start%quiet) return
    write (output_unit, '(a)') text
    flush (output_unit)
  end subroutine say

  subroutine usage(unit)
    integer, intent(in) :: unit
    write (unit, '(a)') &
      'usage: interlock-fit [--output-dir DIR] [--quiet] [--] DECK.nml', &
      '', &
      'Fits the free parameters of the &fit group (docs/fit.md) to the measured curves by', &
      'weighted least squares (projected Levenberg-Marquardt within the bounds, Jacobian by', &
      'forward differences of whole histories), stage after stage. Writes DECK_fit.h5 (the', &
      'fitted values, standard errors, correlations, each curve''s data and model) and', &
      'DECK_fitted.nml (the deck with the fitted values, without &fit) beside the deck or', &
      'in DIR; an existing file is replaced only if it is an earlier result of interlock-fit.', &
      '', &
      'Options:', &
      '  -d, --output-dir DIR  write the files into DIR (an existing folder)', &
      '  -q, --quiet           no progress lines (the results are still printed)', &
      '  -h, --help            print this help and exit (status 0)', &
      '      --version         print the library version and exit (status 0)', &
      '', &
      'Exit status: 0 every stage converged; 1 bad deck or files not written (nothing is', &
      'written); 2 written, but a stage stopped without converging.'
  end subroutine usage

end program interlock_fit
