!> The HDF5 result file of interlock-history (the contract of docs/history-output.md): file
!> attributes (program, version, command line, the deck's full text), one group per case
!> /cases/NNNN with the material, effects, scheme, sweep and status as attributes and the
!> history as datasets (each with `unit` and `description`). The file is written under a
!> temporary name in the destination folder and renamed when complete; on any failure the
!> temporary file is removed.
module interlock_history_output
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use interlock, only: dp, rad_to_deg, interlock_material_t, interlock_solver_t, properties, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_substep_tol, n_effects, effect_names, scheme_name, &
      is_infinite_value, interlock_version_string
  use interlock_h5, only: h5_file_t, h5_create_file, h5_close_file, h5_create_group, &
      h5_close_group, h5_write, h5_attribute
  use interlock_deck, only: deck_t, deck_n_cases, n_datasets, history_datasets, &
      dataset_index
  use interlock_mixed_control, only: history_t
  implicit none
  private
  public :: output_t, output_open, output_write_case, output_close, output_abort

  !> An output file being written.
  type :: output_t
    character(len=:), allocatable :: final_name, temp_name
    type(h5_file_t) :: file, cases
    logical :: open = .false.
  end type output_t

  interface
    integer(c_int) function c_rename(old, new) bind(C, name='rename')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: old(*), new(*)
    end function c_rename
    integer(c_int) function c_remove(path) bind(C, name='remove')
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
    end function c_remove
    integer(c_int) function c_getpid() bind(C, name='getpid')
      import :: c_int
    end function c_getpid
  end interface

contains

  !> Create the temporary file beside `final_name` and write the file attributes.
  subroutine output_open(final_name, deck, command, out, stat, message)
    character(len=*), intent(in) :: final_name, command
    type(deck_t), intent(in) :: deck
    type(output_t), intent(out) :: out
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    character(len=16) :: pid

    message = ''
    write (pid, '(i0)') c_getpid()
    out%final_name = final_name
    out%temp_name = final_name // '.tmp-' // trim(pid)
    call h5_create_file(out%temp_name, out%file, stat)
    if (stat /= 0) then
      message = 'cannot create ' // out%temp_name // ' (does the folder exist and is it writable?)'
      call remove_file(out%temp_name)
      return
    end if
    out%open = .true.
    call h5_attribute(out%file, 'program', 'interlock-history', stat)
    if (stat == 0) call h5_attribute(out%file, 'version', interlock_version_string, stat)
    if (stat == 0) call h5_attribute(out%file, 'command_line', command, stat)
    if (stat == 0) call h5_attribute(out%file, 'deck', deck%text, stat)
    if (stat == 0) call h5_attribute(out%file, 'deck_file', deck%path, stat)
    if (stat == 0) call h5_attribute(out%file, 'title', deck%title, stat)
    if (stat == 0) call h5_attribute(out%file, 'n_cases', deck_n_cases(deck), stat)
    if (stat == 0) call h5_attribute(out%file, 'sweep_parameter', trim(deck%sweep_parameter), stat)
    if (stat == 0) call h5_create_group(out%file, 'cases', out%cases, stat)
    if (stat /= 0) then
      message = 'cannot write the file attributes of ' // out%temp_name
      call output_abort(out)
    end if
  end subroutine output_open

  !> Write case `icase` as /cases/NNNN.
  subroutine output_write_case(out, icase, deck, mat, solver, label, hist, stat, message)
    type(output_t), intent(inout) :: out
    integer, intent(in) :: icase
    type(deck_t), intent(in) :: deck
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    character(len=*), intent(in) :: label
    type(history_t), intent(in) :: hist
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    type(h5_file_t) :: g
    character(len=4) :: name
    character(len=:), allocatable :: effects, how, state_note, count_note
    integer :: n, np, k, ignore
    integer, allocatable :: idx(:)
    character(len=:), allocatable :: stored

    message = ''
    write (name, '(i4.4)') icase
    call h5_create_group(out%cases, name, g, stat)
    if (stat /= 0) then
      message = 'cannot create the group /cases/' // name
      return
    end if
    ! &output every: the rows kept (0, every, 2 every, ... and the last computed row).
    idx = kept_rows(hist%n_rows, deck%every)
    n = size(idx)
    np = mat%n_planes
    ! &output store: the datasets written.
    stored = ''
    do k = 1, n_datasets
      if (.not. deck%stored(k)) cycle
      if (len(stored) > 0) stored = stored // ','
      stored = stored // trim(history_datasets(k))
    end do
    ! Status and what the case is.
    call h5_attribute(g, 'status', hist%status, stat)
    call ok(h5_text(g, 'label', label))
    call ok(h5_text(g, 'sweep_parameter', trim(deck%sweep_parameter)))
    if (deck%sweep_property > 0) call ok(h5_real(g, 'sweep_value', deck%sweep_values(icase)))
    ! The material: every property of the table with its unit.
    call property(prop_sigma0_n, mat%sigma0_n)
    call property(prop_sigma0_t, mat%sigma0_t)
    call property(prop_gc, mat%gc)
    call property(prop_eta, mat%eta)
    call property(prop_mu, mat%mu)
    call property(prop_h_n, infinite(mat%h_n))
    call property_planes(prop_theta0, mat%theta0(1:np) * rad_to_deg)
    call property_planes(prop_thetaf, mat%thetaf(1:np) * rad_to_deg)
    call property_planes(prop_zeta0, infinite(mat%zeta0(1:np)))
    call ok(h5_int(g, 'prefractured', merge(1, 0, mat%prefractured)))
    call ok(h5_text(g, 'prefractured_unit', '-'))
    call ok(h5_int(g, 'n_planes', np))
    call ok(h5_real_1d(g, 'gamma_hat', mat%gamma_hat(1:np)))
    call ok(h5_text(g, 'gamma_hat_unit', '-'))
    ! Effects, scheme, control.
    effects = ''
    do k = 1, n_effects
      call ok(h5_int(g, 'effect_' // trim(effect_names(k)), merge(1, 0, mat%effect(k))))
      if (mat%effect(k)) then
        if (len(effects) > 0) effects = effects // ','
        effects = effects // trim(effect_names(k))
      end if
    end do
    call ok(h5_text(g, 'effects', effects))
    call ok(h5_text(g, 'scheme', scheme_name(solver%scheme)))
    call property(prop_substep_tol, solver%substep_tol)
    call ok(h5_text(g, 'normal_control', control_name(deck%control%traction(1))))
    call ok(h5_text(g, 'tangential_control', control_name(deck%control%traction(2))))
    call ok(h5_real(g, 'newton_tol', deck%control%tol))
    call ok(h5_int(g, 'n_steps', deck%n_steps))
    call ok(h5_int(g, 'n_rows', n))
    call ok(h5_int(g, 'every', deck%every))
    call ok(h5_text(g, 'stored', stored))
    ! Richardson extrapolation (&solver extrapolate): what was extrapolated.
    how = ''
    state_note = ''
    count_note = ''
    if (hist%extrapolated) then
      how = 'global Richardson extrapolation of two runs from the same initial state, one ' // &
        'with the deck''s steps (n) and one with every segment''s step count doubled (2n): ' // &
        'separation and traction are 2 u(2n) - u(n) at the steps of the n run; damage, ' // &
        'beta, theta, zeta, frictional_slip, friction_traction and the energies are those ' // &
        'of the 2n run at the same steps (not extrapolated: extrapolated values could leave ' // &
        'their admissible ranges); iterations and substeps are the sums of both runs (one ' // &
        'step of the n run and two of the 2n run per row)'
      state_note = ' (of the run with doubled steps)'
      count_note = ' (summed over the step of the run with the deck''s steps and the two ' // &
        'steps of the run with doubled steps)'
    end if
    call ok(h5_int(g, 'extrapolated', merge(1, 0, hist%extrapolated)))
    call ok(h5_text(g, 'extrapolation', how))
    ! The history.
    if (stat == 0) call h5_write(g, 'time', hist%time(idx), '-', &
      'pseudo-time at the end of each step written (row 0: after the first step; with ' // &
      'every = k > 1 the steps 1, 1 + k, 1 + 2k, ... and the last)', stat)
    if (stat == 0) call h5_write(g, 'separation', hist%separation(:, idx), 'mm', &
      'relative displacement (s_N, s_T): column 0 normal (> 0 opening), 1 tangential' // &
      extrapolated_note(hist%extrapolated), stat)
    if (stat == 0) call h5_write(g, 'traction', hist%traction(:, idx), 'MPa', &
      'traction (sigma_N, sigma_T): column 0 normal (< 0 compression), 1 tangential' // &
      extrapolated_note(hist%extrapolated), stat)
    if (stat == 0 .and. want('damage')) call h5_write(g, 'damage', &
      hist%damage(:, idx), '-', &
      'damage D_k of each microplane (column k-1 = plane k)' // state_note, stat)
    if (stat == 0 .and. want('beta')) call h5_write(g, 'beta', &
      hist%beta(:, idx), '-', &
      'history maximum of the equivalent relative displacement of each microplane' // &
      state_note, stat)
    if (stat == 0 .and. want('theta')) call h5_write(g, 'theta', &
      hist%theta(:, idx), 'rad', &
      'current inclination theta_k of each microplane' // state_note, stat)
    if (stat == 0 .and. want('zeta')) call h5_write(g, 'zeta', &
      hist%zeta(:, idx), 'N/mm', &
      'accumulated frictional work zeta_k of each microplane (drives wear)' // state_note, stat)
    if (stat == 0 .and. want('frictional_slip')) call h5_write(g, 'frictional_slip', &
      hist%frictional_slip(:, idx), 'mm', &
      'frictional slip sf_k along each microplane' // state_note, stat)
    if (stat == 0 .and. want('friction_traction')) call h5_write(g, 'friction_traction', &
      hist%friction_traction(:, idx), 'MPa', &
      'friction traction K_t (s_kt - sf_k) of each microplane at the end of the step' // &
      state_note, stat)
    if (stat == 0 .and. want('work')) call h5_write(g, 'work', &
      hist%work(idx), 'N/mm', &
      'work done on the interface since the initial state, sum of sigma . ds' // state_note, &
      stat)
    if (stat == 0 .and. want('stored_energy')) call h5_write(g, 'stored_energy', &
      hist%stored(idx), 'N/mm', &
      'stored (free) energy of the interface' // state_note, stat)
    if (stat == 0 .and. want('damage_dissipation')) call h5_write(g, 'damage_dissipation', &
      hist%diss_damage(idx), 'N/mm', &
      'energy dissipated by damage since the initial state' // state_note, stat)
    if (stat == 0 .and. want('friction_dissipation')) call h5_write(g, 'friction_dissipation', &
      hist%diss_friction(idx), 'N/mm', &
      'energy dissipated by friction since the initial state' // state_note, stat)
    if (stat == 0 .and. want('iterations')) call h5_write(g, 'iterations', &
      hist%iterations(idx), '-', &
      'Newton iterations of the mixed-control solve of each step (all attempts; 0 when ' // &
      'every component is separation-driven)' // count_note, stat)
    if (stat == 0 .and. want('substeps')) call h5_write(g, 'substeps', &
      hist%substeps(idx), '-', &
      'sub-increments of each step: the library''s sub-increments summed over the accepted ' // &
      'step cuts (1: the step was neither cut nor substepped)' // count_note, stat)
    if (stat /= 0) message = 'cannot write the case /cases/' // name // ' to ' // out%temp_name
    call h5_close_group(g, ignore)

  contains

    subroutine ok(s)
      integer, intent(in) :: s
      if (stat == 0) stat = s
    end subroutine ok

    logical function want(dataset)
      character(len=*), intent(in) :: dataset
      want = deck%stored(dataset_index(dataset))
    end function want

    subroutine property(ip, value)
      integer, intent(in) :: ip
      real(dp), intent(in) :: value
      call ok(h5_real(g, trim(properties(ip)%name), value))
      call ok(h5_text(g, trim(properties(ip)%name) // '_unit', trim(properties(ip)%unit)))
    end subroutine property

    subroutine property_planes(ip, values)
      integer, intent(in) :: ip
      real(dp), intent(in) :: values(:)
      call ok(h5_real_1d(g, trim(properties(ip)%name), values))
      call ok(h5_text(g, trim(properties(ip)%name) // '_unit', trim(properties(ip)%unit)))
    end subroutine property_planes

  end subroutine output_write_case

  !> Close the file and give it its final name.
  subroutine output_close(out, stat, message)
    type(output_t), intent(inout) :: out
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    integer :: s2
    message = ''
    call h5_close_group(out%cases, stat)
    call h5_close_file(out%file, s2)
    out%open = .false.
    if (stat == 0) stat = s2
    if (stat /= 0) then
      message = 'cannot close ' // out%temp_name
      call remove_file(out%temp_name)
      return
    end if
    stat = c_rename(out%temp_name // c_null_char, out%final_name // c_null_char)
    if (stat /= 0) then
      message = 'cannot rename ' // out%temp_name // ' to ' // out%final_name
      call remove_file(out%temp_name)
    end if
  end subroutine output_close

  !> Give up: close what is open and remove the temporary file.
  subroutine output_abort(out)
    type(output_t), intent(inout) :: out
    integer :: ignore
    if (out%open) then
      call h5_close_group(out%cases, ignore)
      call h5_close_file(out%file, ignore)
      out%open = .false.
    end if
    if (allocated(out%temp_name)) call remove_file(out%temp_name)
  end subroutine output_abort

  subroutine remove_file(path)
    character(len=*), intent(in) :: path
    integer(c_int) :: ignore
    ignore = c_remove(path // c_null_char)
  end subroutine remove_file

  ! Function wrappers so that a chain of attribute writes stops at the first failure.
  integer function h5_text(g, name, text) result(stat)
    type(h5_file_t), intent(in) :: g
    character(len=*), intent(in) :: name, text
    call h5_attribute(g, name, text, stat)
  end function h5_text

  integer function h5_real(g, name, x) result(stat)
    type(h5_file_t), intent(in) :: g
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: x
    call h5_attribute(g, name, x, stat)
  end function h5_real

  integer function h5_real_1d(g, name, x) result(stat)
    type(h5_file_t), intent(in) :: g
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: x(:)
    call h5_attribute(g, name, x, stat)
  end function h5_real_1d

  integer function h5_int(g, name, i) result(stat)
    type(h5_file_t), intent(in) :: g
    character(len=*), intent(in) :: name
    integer, intent(in) :: i
    call h5_attribute(g, name, i, stat)
  end function h5_int

  pure function control_name(traction) result(text)
    logical, intent(in) :: traction
    character(len=:), allocatable :: text
    if (traction) then
      text = 'traction'
    else
      text = 'separation'
    end if
  end function control_name

  !> The note on an extrapolated dataset's description ('' when not extrapolated).
  pure function extrapolated_note(extrapolated) result(text)
    logical, intent(in) :: extrapolated
    character(len=:), allocatable :: text
    text = ''
    if (extrapolated) text = ' (Richardson-extrapolated: 2 u(2n) - u(n), u(n) with the ' // &
      'deck''s steps, u(2n) with every segment''s step count doubled)'
  end function extrapolated_note

  !> The rows written with `&output every = k` out of n computed rows: 1, 1 + k, 1 + 2k, ...
  !> (Fortran indices; rows 0, k, 2k, ... in the file's 0-based numbering) and always the last
  !> row n (the end of the history, or the last step before a stop).
  pure function kept_rows(n, every) result(idx)
    integer, intent(in) :: n, every
    integer, allocatable :: idx(:)
    integer :: i, m
    if (n < 1) then
      allocate (idx(0))
      return
    end if
    m = (n - 1) / every + 1
    if (mod(n - 1, every) /= 0) m = m + 1
    allocate (idx(m))
    idx(1:(n - 1) / every + 1) = [(1 + i * every, i = 0, (n - 1) / every)]
    idx(m) = n
  end function kept_rows

  !> +Inf for the "infinite" convention (>= 1e30), the value otherwise.
  elemental real(dp) function infinite(x)
    real(dp), intent(in) :: x
    if (is_infinite_value(x)) then
      infinite = ieee_value(1.0_dp, ieee_positive_inf)
    else
      infinite = x
    end if
  end function infinite

end module interlock_history_output
