!> What interlock-fit writes (docs/fit.md): the HDF5 file of the fit (the fitted parameters, their
!> standard errors and correlations, each stage's outcome, each curve's data, weights and model,
!> and the fitted history along it) and the fitted deck (the deck with the fitted values and
!> without &fit: an ordinary interlock-history deck). Both are written under temporary names
!> (interlock_history_output's file safety) and renamed together when both are complete
!> (interlock_fit_main), and neither replaces a file that is not an earlier result of
!> interlock-fit.
module interlock_fit_output
  use interlock, only: dp, interlock_version_string, format_integer, properties, prop_theta0, &
      prop_thetaf, prop_zeta0
  use interlock_h5, only: h5_file_t, h5_series_t, h5_create_group, h5_close_group, &
      h5_create_series, h5_append, h5_close_series, h5_attribute
  use interlock_history_output, only: output_t, output_create, output_close, output_abort
  use interlock_files, only: path_kind, path_absent, path_regular, same_file, guard_file, &
      unguard_file, remove_file, temporary_name, write_file
  use interlock_deck_text, only: group_scan_t, scan_deck
  use interlock_fit_deck, only: fit_t, fit_groups, output_names, join_selected
  use interlock_lm, only: lm_result_t, lm_stats_t
  implicit none
  private
  public :: stage_outcome_t, curve_outcome_t, discretization_t, write_fit_file, &
            write_fitted_deck, fitted_deck_check, fitted_deck_mark

  character(len=*), parameter :: fitted_deck_mark = '! interlock-fit: fitted deck'

  type :: stage_outcome_t
    type(lm_result_t) :: result
    real(dp) :: seconds = 0.0_dp
    integer :: runs = 0
  end type stage_outcome_t

  !> A curve at the fitted values: the model at the data points and the history along it.
  type :: curve_outcome_t
    real(dp), allocatable :: model(:), history_x(:), history_y(:)
    real(dp) :: residual_norm = 0.0_dp   !< sqrt(sum w (model - y)^2)
    real(dp) :: rms = 0.0_dp             !< sqrt(mean (model - y)^2), in the curve's unit
  end type curve_outcome_t

  !> The discretization check: the change of each fitted value that twice the steps per segment
  !> implies (linearised at the optimum), and that change in standard errors. note: '' when
  !> computed, else why not.
  type :: discretization_t
    real(dp), allocatable :: change(:), ratio(:)
    character(len=:), allocatable :: note
    integer :: order = 1   !< the order of the deck's scheme in its dimension (scheme_order)
  end type discretization_t

contains

  !> Write the fit file for `final_name` (checked by the caller with output_check_target) as
  !> `temp`, complete and guarded, for the caller to rename (stat /= 0: nothing is left).
  !> at_bound: where each parameter ended (interlock_fit_model's bound_state); statistics: ''
  !> or why the statistics could not be computed.
  subroutine write_fit_file(final_name, fit, command, values, stats, stages, curves, &
                            fitted_deck_name, at_bound, statistics, disc, temp, stat, message)
    character(len=*), intent(in) :: final_name, command, fitted_deck_name, at_bound(:), statistics
    character(len=:), allocatable, intent(out) :: temp
    type(fit_t), intent(in) :: fit
    real(dp), intent(in), contiguous :: values(:)
    type(lm_stats_t), intent(in) :: stats
    type(stage_outcome_t), intent(in) :: stages(:)
    type(curve_outcome_t), intent(in) :: curves(:)
    type(discretization_t), intent(in) :: disc
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    type(output_t) :: out
    type(h5_file_t) :: g, sg, top
    integer :: k

    call output_create(final_name, out, stat, message)
    if (stat /= 0) return
    temp = out%temp_name
    call h5_attribute(out%file, 'program', 'interlock-fit', stat)
    if (stat == 0) call h5_attribute(out%file, 'version', interlock_version_string, stat)
    if (stat == 0) call h5_attribute(out%file, 'command_line', command, stat)
    if (stat == 0) call h5_attribute(out%file, 'deck', fit%deck%text, stat)
    if (stat == 0) call h5_attribute(out%file, 'deck_file', fit%deck%path, stat)
    if (stat == 0) call h5_attribute(out%file, 'fitted_deck', fitted_deck_name, stat)
    if (stat == 0) call h5_attribute(out%file, 'parameters', fit%names, stat)
    if (stat == 0) call h5_attribute(out%file, 'curve_names', fit%curve_names, stat)
    if (stat == 0) call h5_attribute(out%file, 'at_bound', at_bound, stat)
    if (stat == 0) call h5_attribute(out%file, 'statistics', statistics, stat)
    if (stat == 0) call h5_attribute(out%file, 'discretization_change', disc%change, stat)
    if (stat == 0) call h5_attribute(out%file, 'discretization_change_se', disc%ratio, stat)
    if (stat == 0) call h5_attribute(out%file, 'discretization_check', disc%note, stat)
    if (stat == 0) call h5_attribute(out%file, 'discretization_order', disc%order, stat)
    if (stat == 0 .and. size(fit%warnings) > 0) &
      call h5_attribute(out%file, 'warnings', fit%warnings, stat)
    if (stat == 0) call h5_attribute(out%file, 'values', values, stat)
    if (stat == 0) call h5_attribute(out%file, 'std_error', stats%std_error, stat)
    if (stat == 0) call h5_attribute(out%file, 'start', fit%start, stat)
    if (stat == 0) call h5_attribute(out%file, 'lower', fit%lower, stat)
    if (stat == 0) call h5_attribute(out%file, 'upper', fit%upper, stat)
    if (stat == 0) call h5_attribute(out%file, 'identifiable', merge(1.0_dp, 0.0_dp, stats%identifiable), stat)
    if (stat == 0) call h5_attribute(out%file, 'condition_number', stats%condition, stat)
    if (stat == 0) call h5_attribute(out%file, 'ill_conditioned', &
                                     merge(1, 0, stats%ill_conditioned), stat)
    if (stat == 0) call h5_attribute(out%file, 'residual_variance', stats%sigma2, stat)
    if (stat == 0) call put_matrix(out%file, 'correlation', stats%correlation, '-', &
      'correlation matrix of the fitted parameters (order of the attribute parameters), from ' // &
      'the Jacobian of all curves at the fitted values', stat)
    if (stat == 0) call h5_create_group(out%file, 'stages', top, stat)
    do k = 1, size(stages)
      if (stat /= 0) exit
      call h5_create_group(top, format_integer(k), sg, stat)
      if (stat == 0) call h5_attribute(sg, 'reason', stages(k)%result%reason, stat)
      if (stat == 0) call h5_attribute(sg, 'converged', merge(1, 0, stages(k)%result%converged), stat)
      if (stat == 0) call h5_attribute(sg, 'iterations', stages(k)%result%iterations, stat)
      if (stat == 0) call h5_attribute(sg, 'histories', stages(k)%runs, stat)
      if (stat == 0) call h5_attribute(sg, 'cost', stages(k)%result%cost, stat)
      if (stat == 0) call h5_attribute(sg, 'cpu_seconds', stages(k)%seconds, stat)
      if (stat == 0) call h5_attribute(sg, 'free', join_selected(fit%names, fit%stages(k)%free), stat)
      if (stat == 0) call h5_attribute(sg, 'values', stages(k)%result%x, stat)
      if (stat == 0) call h5_attribute(sg, 'curves', join_selected(fit%curve_names, fit%stages(k)%curves), stat)
      if (stat == 0) call h5_close_group(sg, stat)
    end do
    if (stat == 0) call h5_close_group(top, stat)
    ! the group 'curves' is the mark of a fit file (output_check_target)
    if (stat == 0) call h5_create_group(out%file, 'curves', out%cases, stat)
    do k = 1, size(fit%curves)
      if (stat /= 0) exit
      associate (c => fit%curves(k), o => curves(k))
        call h5_create_group(out%cases, c%name, g, stat)
        if (stat == 0) call h5_attribute(g, 'file', c%file, stat)
        if (stat == 0) call h5_attribute(g, 'x_column', c%x_column, stat)
        if (stat == 0) call h5_attribute(g, 'y_column', c%y_column, stat)
        if (stat == 0) call h5_attribute(g, 'along', trim(output_names(c%along)), stat)
        if (stat == 0) call h5_attribute(g, 'against', trim(output_names(c%against)), stat)
        if (stat == 0) call h5_attribute(g, 'residual_norm', o%residual_norm, stat)
        if (stat == 0) call h5_attribute(g, 'rms', o%rms, stat)
        if (stat == 0) call put_vector(g, 'x', c%x, 'the measured abscissa (' // c%x_column // &
                                       ') in the window', stat)
        if (stat == 0) call put_vector(g, 'y', c%y, 'the measured values (' // c%y_column // ')', stat)
        if (stat == 0) call put_vector(g, 'weight', c%w, 'the weight of each point', stat)
        if (stat == 0) call put_vector(g, 'model', o%model, 'the fitted history''s ' // &
          trim(output_names(c%against)) // ' at x (same branch, linear interpolation)', stat)
        if (stat == 0) call put_vector(g, 'history_x', o%history_x, 'the fitted history''s ' // &
          trim(output_names(c%along)) // ' over the branches of the window', stat)
        if (stat == 0) call put_vector(g, 'history_y', o%history_y, 'the fitted history''s ' // &
          trim(output_names(c%against)) // ' over the branches of the window', stat)
        if (stat == 0) call h5_close_group(g, stat)
      end associate
    end do
    if (stat /= 0) then
      message = 'cannot write ' // out%temp_name // ' (is the disk full?)'
      call output_abort(out)
      return
    end if
    call output_close(out, stat, message, rename=.false.)
  end subroutine write_fit_file

  subroutine put_vector(loc, name, x, description, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, description
    real(dp), intent(in), contiguous :: x(:)
    integer, intent(out) :: stat
    type(h5_series_t) :: s
    integer :: s2
    call h5_create_series(loc, name, .false., 0, max(1, size(x)), '', description, s, stat)
    if (stat == 0) call h5_append(s, x, stat)
    call h5_close_series(s, s2)
    if (stat == 0) stat = s2
  end subroutine put_vector

  subroutine put_matrix(loc, name, a, unit, description, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, unit, description
    real(dp), intent(in), contiguous :: a(:, :)
    integer, intent(out) :: stat
    type(h5_series_t) :: s
    integer :: s2
    call h5_create_series(loc, name, .false., size(a, 1), max(1, size(a, 2)), unit, description, &
                          s, stat)
    if (stat == 0) call h5_append(s, a, stat)
    call h5_close_series(s, s2)
    if (stat == 0) stat = s2
  end subroutine put_matrix

  !> May the fitted deck be written to `name`? Only if nothing is there or an earlier fitted deck
  !> (its first line is fitted_deck_mark), never the deck itself. message = '' if so.
  subroutine fitted_deck_check(name, deck_path, message)
    character(len=*), intent(in) :: name, deck_path
    character(len=*), intent(out) :: message
    integer :: u, ios
    character(len=len(fitted_deck_mark)) :: first
    message = ''
    select case (path_kind(name))
    case (path_absent)
    case (path_regular)
      if (same_file(name, deck_path)) then
        message = 'the fitted deck ' // name // ' is the deck itself: refusing to overwrite it'
        return
      end if
      first = ''
      open (newunit=u, file=name, status='old', action='read', iostat=ios)
      if (ios == 0) read (u, '(a)', iostat=ios) first
      if (ios == 0) close (u)
      if (first /= fitted_deck_mark) message = 'the fitted deck ' // name // ' exists and ' // &
        'is not a result of interlock-fit: refusing to overwrite it (remove it, or use ' // &
        '--output-dir)'
    case default
      message = 'the fitted deck ' // name // ' exists and is not a regular file: refusing ' // &
                'to write to it'
    end select
  end subroutine fitted_deck_check

  !> The deck with the fitted values (each free parameter's value replaced, or added to its
  !> group where the deck left it at its default) and without the group &fit; written as
  !> `temp` (NAME.tmp-PID, guarded), which the caller renames to `name` once the fit file is
  !> written too (or removes).
  subroutine write_fitted_deck(name, fit, values, temp, stat, message)
    character(len=*), intent(in) :: name
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    character(len=:), allocatable, intent(out) :: temp
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    type(group_scan_t) :: scan(size(fit_groups))
    character(len=:), allocatable :: text, header
    integer :: n_edit, i, k, g, ios, ip, first, last, amp, np
    integer, allocatable :: at(:), cut(:)
    character(len=512), allocatable :: put(:)
    character(len=:), allocatable :: value
    logical :: found

    text = fit%deck%text
    call scan_deck(text, fit_groups, scan, message)
    stat = 1
    if (len_trim(message) > 0) return
    allocate (at(size(values) + 1), cut(size(values) + 1), put(size(values) + 1))
    n_edit = 0
    do i = 1, size(values)
      ip = fit%property(i)
      g = merge(2, 1, ip >= prop_theta0 .and. ip <= prop_zeta0)
      np = 1
      if (.not. fit%deck%paper_ria) np = fit%deck%n_planes
      value = ''
      do k = 1, np
        if (k > 1) value = value // ', '
        if (ip == prop_theta0 .or. ip == prop_thetaf) then
          value = value // real_text(sign(values(i), fit%deck%theta0_deg(k)))
        else
          value = value // real_text(values(i))
        end if
      end do
      found = .false.
      do k = 1, scan(g)%n
        if (trim(scan(g)%a(k)%name) /= trim(properties(ip)%name)) cycle
        found = .true.
        first = scan(g)%a(k)%equals + 1
        last = value_end(text, first, scan(g)%a(k)%last)
        call add_edit(first, last - first + 1, ' ' // value)
      end do
      if (.not. found) call add_edit(scan(g)%first, 0, achar(10) // '  ' // &
                                     trim(properties(ip)%name) // ' = ' // value // &
                                     '   ! added by interlock-fit' // achar(10))
    end do
    ! remove &fit: from its '&' to the end of its terminator
    amp = index(text(1:scan(9)%first), '&', back=.true.)
    if (amp == 0) amp = index(text(1:scan(9)%first), '$', back=.true.)
    last = scan(9)%last + 1
    if (text(last:last) /= '/') last = min(len(text), last + 3)
    call add_edit(amp, last - amp + 1, '')
    ! apply from the end, so that earlier positions stay valid
    do while (n_edit > 0)
      k = maxloc(at(1:n_edit), dim=1)
      text = text(1:at(k) - 1) // trim(put(k)) // text(at(k) + cut(k):)
      at(k) = -1
      if (all(at(1:n_edit) < 0)) exit
    end do
    header = fitted_deck_mark // ' from ' // fit%deck%path // ' (interlock-fit ' // &
             interlock_version_string // '): fitted'
    do i = 1, size(values)
      header = header // ' ' // trim(fit%names(i)) // ' = ' // real_text(values(i))
    end do
    temp = temporary_name(name)
    call guard_file(temp, stat)
    if (stat /= 0) then
      message = 'cannot guard ' // temp // ' against interruption'
      return
    end if
    call write_file(temp, header // achar(10) // text, ios)
    if (ios /= 0) then
      message = 'cannot write the fitted deck ' // name // ' (as ' // temp // '; is the disk ' // &
                'full?)'
      call remove_file(temp)
      call unguard_file(temp)
      stat = 1
    else
      stat = 0
      message = ''
    end if

  contains

    subroutine add_edit(where, length, replacement)
      integer, intent(in) :: where, length
      character(len=*), intent(in) :: replacement
      n_edit = n_edit + 1
      at(n_edit) = where
      cut(n_edit) = length
      put(n_edit) = replacement
    end subroutine add_edit

  end subroutine write_fitted_deck

  !> The last character of a value list that starts at `first` (before a comment, and without
  !> the blanks, line breaks and separating comma that follow it).
  pure integer function value_end(text, first, last) result(e)
    character(len=*), intent(in) :: text
    integer, intent(in) :: first, last
    integer :: bang
    e = last
    bang = index(text(first:last), '!')
    if (bang > 0) e = first + bang - 2
    do while (e >= first)
      if (index(' ,' // achar(9) // achar(10) // achar(13), text(e:e)) == 0) exit
      e = e - 1
    end do
  end function value_end

  !> A real that reads back to the same double.
  function real_text(x) result(text)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=40) :: buf
    write (buf, '(es24.16e3)') x
    text = trim(adjustl(buf))
  end function real_text

end module interlock_fit_output
