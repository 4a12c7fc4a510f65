!> interlock-fit DECK.nml: fit the law's parameters to measured curves (docs/fit.md). The deck is
!> an interlock-history deck with a &fit group. Exit status: 0 every stage converged; 1 a bad
!> deck, a history that cannot be run at the start values, or a file that cannot be written
!> (nothing is written); 2 the files are written but a stage stopped without converging
!> (max_iterations, or no step lowers the cost).
program interlock_fit
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use interlock_cli, only: exit_program, command_argument, command_text
  use interlock, only: dp, interlock_version_string, format_integer
  use interlock_h5, only: h5_open_library, h5_close_library
  use interlock_files, only: is_folder
  use interlock_mixed_control, only: history_t
  use interlock_history_output, only: output_check_target
  use interlock_fit_deck, only: fit_t, read_fit_deck, join_selected
  use interlock_fit_model, only: fit_problem_t, fit_history, curve_model, history_output
  use interlock_fit_output, only: stage_outcome_t, curve_outcome_t, write_fit_file, &
      write_fitted_deck, fitted_deck_check
  use interlock_lm, only: lm_solve, lm_jacobian, lm_statistics, lm_stats_t
  implicit none

  character(len=:), allocatable :: arg, deck_path, output_dir, command
  integer :: nargs, i, stat, rc
  logical :: quiet, options_done

  nargs = command_argument_count()
  output_dir = ''
  deck_path = ''
  quiet = .false.
  options_done = .false.
  i = 0
  do while (i < nargs)
    i = i + 1
    arg = command_argument(i)
    if (.not. options_done .and. len(arg) > 0) then
      if (arg(1:1) == '-') then
        select case (arg)
        case ('-h', '--help')
          call usage(output_unit)
          call exit_program(0)
        case ('--version')
          write (output_unit, '(a)') 'interlock-fit ' // interlock_version_string
          call exit_program(0)
        case ('-q', '--quiet')
          quiet = .true.
        case ('-d', '--output-dir')
          if (i == nargs) then
            write (error_unit, '(a)') 'interlock-fit: error: ' // arg // ' needs a folder'
            call exit_program(1)
          end if
          i = i + 1
          output_dir = command_argument(i)
        case ('--')
          options_done = .true.
        case default
          write (error_unit, '(a)') 'interlock-fit: error: unknown option ' // arg
          call usage(error_unit)
          call exit_program(1)
        end select
        cycle
      end if
    end if
    if (len(deck_path) > 0) then
      write (error_unit, '(a)') 'interlock-fit: error: one deck at a time (' // deck_path // &
                                ', ' // arg // ')'
      call exit_program(1)
    end if
    deck_path = arg
  end do
  if (len(deck_path) == 0) then
    write (error_unit, '(a)') 'interlock-fit: error: no deck given'
    call usage(error_unit)
    call exit_program(1)
  end if
  if (len(output_dir) > 0) then
    if (.not. is_folder(output_dir)) then
      write (error_unit, '(a)') 'interlock-fit: error: --output-dir ' // output_dir // &
        ': no such folder (it must exist)'
      call exit_program(1)
    end if
  end if
  command = command_text()
  call h5_open_library(stat)
  if (stat /= 0) then
    write (error_unit, '(a)') 'interlock-fit: error: cannot initialise the HDF5 library'
    call exit_program(1)
  end if
  call run_fit(deck_path, rc)
  call h5_close_library(stat)
  call exit_program(rc)

contains

  subroutine run_fit(path, rc)
    character(len=*), intent(in) :: path
    integer, intent(out) :: rc
    type(fit_t) :: fit
    type(fit_problem_t) :: problem
    type(stage_outcome_t), allocatable :: stages(:)
    type(curve_outcome_t), allocatable :: curves(:)
    type(lm_stats_t) :: stats
    type(history_t) :: hist
    character(len=1024) :: message
    character(len=:), allocatable :: base, h5_name, deck_name, why
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
    slash = index(path, '/', back=.true.)
    base = path(slash + 1:)
    dot = index(base, '.', back=.true.)
    if (dot > 1) base = base(1:dot - 1)
    if (len(output_dir) > 0) then
      base = output_dir // '/' // base
    else
      base = path(1:slash) // base
    end if
    h5_name = base // '_fit.h5'
    deck_name = base // '_fitted.nml'
    call output_check_target(h5_name, path, message, 'interlock-fit', 'curves')
    if (len_trim(message) == 0) call fitted_deck_check(deck_name, path, message)
    if (len_trim(message) > 0) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': ' // trim(message)
      return
    end if

    values = fit%start
    typical = max(abs(fit%start), 1.0e-3_dp * (fit%upper - fit%lower))
    call say(path // ': ' // format_integer(size(fit%names)) // ' free parameter(s), ' // &
             format_integer(size(fit%curves)) // ' curve(s), ' // &
             format_integer(size(fit%stages)) // ' stage(s)')
    allocate (stages(size(fit%stages)))
    problem%fit = fit
    problem%verbose = .not. quiet
    call cpu_time(problem%clock_start)
    do k = 1, size(fit%stages)
      call cpu_time(t0)
      problem%stage = k
      problem%values = values
      problem%free = fit%stages(k)%free
      problem%curves = fit%stages(k)%curves
      problem%m = sum([(size(fit%curves(problem%curves(j))%x), j = 1, size(problem%curves))])
      problem%runs = 0
      call say('stage ' // format_integer(k) // ': ' // join_selected(fit%names, problem%free) // &
               ' on ' // join_selected(fit%curve_names, problem%curves) // ' (' // format_integer(problem%m) // ' points)')
      x0 = values(problem%free)
      call lm_solve(problem, x0, fit%lower(problem%free), fit%upper(problem%free), &
                    typical(problem%free), fit%options, stages(k)%result)
      if (stages(k)%result%iterations == 0 .or. (.not. stages(k)%result%converged .and. &
          index(stages(k)%result%reason, 'start values') > 0)) then
        write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': stage ' // &
          format_integer(k) // ': ' // stages(k)%result%reason // ': ' // problem%failure
        return
      end if
      values(problem%free) = stages(k)%result%x
      call cpu_time(t1)
      stages(k)%seconds = t1 - t0
      stages(k)%runs = problem%runs
      call say('stage ' // format_integer(k) // ' stopped after ' // &
               format_integer(stages(k)%result%iterations) // ' iterations (' // &
               format_integer(problem%runs) // ' histories, ' // seconds(t1 - t0) // '): ' // &
               stages(k)%result%reason)
      if (.not. stages(k)%result%converged) rc = 2
    end do

    ! statistics over all parameters and all curves, at the fitted values
    problem%values = values
    problem%free = [(j, j = 1, size(values))]
    problem%curves = [(j, j = 1, size(fit%curves))]
    problem%m = sum([(size(fit%curves(j)%x), j = 1, size(fit%curves))])
    problem%verbose = .false.
    allocate (r(problem%m), jac(problem%m, size(values)))
    call problem%residuals(values, r, ok)
    if (ok) call lm_jacobian(problem, values, r, fit%lower, fit%upper, typical, &
                             fit%options%fd_step, jac, ok)
    if (.not. ok) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': at the fitted values: ' // &
                                problem%failure
      return
    end if
    call lm_statistics(jac, r, stats)

    ! the curves at the fitted values
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
    call report(fit, values, stats, curves, problem%m)

    call write_fit_file(h5_name, fit, command, values, stats, stages, curves, deck_name, stat, &
                        message)
    if (stat == 0) call write_fitted_deck(deck_name, fit, values, stat, message)
    if (stat /= 0) then
      write (error_unit, '(a)') 'interlock-fit: error: ' // path // ': ' // trim(message)
      rc = 1
      return
    end if
    write (output_unit, '(a)') path // ' -> ' // h5_name // ', ' // deck_name
    if (rc /= 2) rc = 0
  end subroutine run_fit

  !> The table of results on the terminal.
  subroutine report(fit, values, stats, curves, m)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    type(lm_stats_t), intent(in) :: stats
    type(curve_outcome_t), intent(in) :: curves(:)
    integer, intent(in) :: m
    integer :: i, j, n
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
      if (values(i) <= fit%lower(i) .or. values(i) >= fit%upper(i)) flags = ' AT A BOUND'
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
  end subroutine report

  function seconds(t) result(text)
    real(dp), intent(in) :: t
    character(len=:), allocatable :: text
    character(len=16) :: buf
    write (buf, '(f0.2)') t
    text = trim(buf) // ' s CPU'
  end function seconds

  subroutine say(text)
    character(len=*), intent(in) :: text
    if (quiet) return
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
