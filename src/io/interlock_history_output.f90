!> The HDF5 result file of interlock-history (the contract of docs/history-output.md): file
!> attributes (program, version, command line, the deck's full text), one group per case
!> /cases/NNNN with the material, effects, scheme, sweep and status as attributes and the
!> history as datasets (each with `unit` and `description`). The rows of a case are written as
!> they are computed (a case_writer_t is the history's sink): the rows that `&output every`
!> keeps go to a block of at most one chunk and each full block is appended to extendible,
!> chunked datasets, so memory is bounded by one chunk, whatever the history's length. The file
!> is written under a temporary name in the destination folder (removed on any failure and on
!> every signal that ends the program) and renamed when complete. It never replaces a file that is not an
!> earlier result of interlock-history (output_check_target).
module interlock_history_output
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use interlock, only: dp, rad_to_deg, interlock_material_t, interlock_solver_t, properties, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_substep_tol, n_effects, effect_names, scheme_name, &
      is_infinite_value, interlock_version_string
  use interlock_h5, only: h5_file_t, h5_series_t, h5_create_file, h5_close_file, h5_has_marks, &
      h5_create_group, h5_close_group, h5_create_series, h5_append, h5_close_series, h5_attribute
  use interlock_deck, only: deck_t, deck_n_cases, n_datasets, history_datasets, deck_ria_name, &
      case_n_azimuths, &
      sweep_slip_angle
  use interlock_mixed_control, only: history_row_t, history_sink_t, history_t
  use interlock_files, only: path_kind, path_absent, path_regular, path_folder, same_file, &
      guard_file, unguard_file, remove_file, rename_file, temporary_name
  implicit none
  private
  public :: output_t, case_writer_t, output_check_target, output_open, output_begin_case, &
            output_end_case, output_close, output_abort, output_create

  !> The program name in the root attribute `program`: with the group /cases, the mark of a
  !> file that a later run may replace.
  character(len=*), parameter :: program_name = 'interlock-history'
  !> Rows per chunk (and per block held in memory) at most.
  integer, parameter :: max_chunk_rows = 4096
  !> dataset_shape: what a row of a dataset holds
  integer, parameter :: shape_single = 1, shape_pair = 2, shape_planes = 3, shape_count = 4

  !> An output file being written.
  type :: output_t
    character(len=:), allocatable :: final_name, temp_name
    type(h5_file_t) :: file, cases
    logical :: open = .false.
  end type output_t

  !> The rows of one case on their way to /cases/NNNN: the sink of run_history.
  type, extends(history_sink_t) :: case_writer_t
    type(h5_file_t) :: group
    type(h5_series_t) :: series(n_datasets)
    logical :: wanted(n_datasets) = .false.
    integer :: every = 1
    !> kept rows not yet written (at most one chunk)
    type(history_t) :: block
    integer :: block_rows = 1
    !> the last row computed when `every` did not keep it (written at the end: the end of the
    !> history, or the last row before a stop, is always in the file)
    type(history_row_t) :: last
    logical :: last_pending = .false.
    integer :: stat = 0
    character(len=:), allocatable :: name
  contains
    procedure :: put => writer_put
  end type case_writer_t


contains

  !> May a result be written to `final_name`? Only if nothing is there, or an earlier result of
  !> this program (an HDF5 file whose root has the attribute `program` and the group /cases):
  !> never the deck, a file of any other kind, a folder, a FIFO or a device. message = '' if so.
  !> `program` and `link` (optional, interlock-fit): another program's marks (the value of the
  !> attribute `program` is not compared: a file of either program is never taken for the other's
  !> unless it has the other's group).
  subroutine output_check_target(final_name, deck_path, message, program, link)
    character(len=*), intent(in) :: final_name, deck_path
    character(len=*), intent(out) :: message
    character(len=*), intent(in), optional :: program, link
    character(len=:), allocatable :: who, mark
    message = ''
    who = program_name
    mark = 'cases'
    if (present(program)) who = program
    if (present(link)) mark = link
    select case (path_kind(final_name))
    case (path_absent)
    case (path_regular)
      if (same_file(final_name, deck_path)) then
        message = 'the output file ' // final_name // ' is the deck itself: refusing to ' // &
                  'overwrite it (give another &output file)'
      else if (.not. h5_has_marks(final_name, 'program', mark)) then
        message = 'the output file ' // final_name // ' exists and is not a result of ' // &
                  who // ': refusing to overwrite it (remove it, or give another ' // &
                  '&output file)'
      end if
    case (path_folder)
      message = 'the output file ' // final_name // ' is a folder'
    case default
      message = 'the output file ' // final_name // ' exists and is not a regular file ' // &
                '(a FIFO, a device or a socket): refusing to write to it'
    end select
  end subroutine output_check_target

  !> Create the temporary file beside `final_name` and write the file attributes. The
  !> temporary file is removed if the program ends before it is complete.
  subroutine output_open(final_name, deck, command, out, stat, message)
    character(len=*), intent(in) :: final_name, command
    type(deck_t), intent(in) :: deck
    type(output_t), intent(out) :: out
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message

    call output_create(final_name, out, stat, message)
    if (stat /= 0) return
    call h5_attribute(out%file, 'program', program_name, stat)
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

  !> Create the temporary file NAME.tmp-PID beside `final_name` (out%file, guarded: removed if
  !> the program ends before it is complete: interlock_files' guard); output_close renames it.
  subroutine output_create(final_name, out, stat, message)
    character(len=*), intent(in) :: final_name
    type(output_t), intent(out) :: out
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message

    message = ''
    out%final_name = final_name
    out%temp_name = temporary_name(final_name)
    call guard_file(out%temp_name, stat)
    if (stat /= 0) then
      message = 'cannot guard ' // out%temp_name // ' against interruption (path too long?)'
      return
    end if
    call h5_create_file(out%temp_name, out%file, stat)
    if (stat /= 0) then
      message = 'cannot create ' // out%temp_name // ' (does the folder exist and is it writable?)'
      call remove_file(out%temp_name)
      call unguard_file(out%temp_name)
      return
    end if
    out%open = .true.
  end subroutine output_create

  !> Start case `icase` as /cases/NNNN: its attributes and empty datasets; `writer` is then the
  !> sink of the case's history (run_history), and output_end_case completes it.
  subroutine output_begin_case(out, icase, deck, mat, solver, label, writer, stat, message)
    type(output_t), intent(inout) :: out
    integer, intent(in) :: icase
    type(deck_t), intent(in) :: deck
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    character(len=*), intent(in) :: label
    type(case_writer_t), intent(out) :: writer
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    type(h5_file_t) :: g
    character(len=4) :: name
    character(len=:), allocatable :: effects, stored
    integer :: np, k, width

    message = ''
    write (name, '(i4.4)') icase
    writer%name = name
    call h5_create_group(out%cases, name, writer%group, stat)
    if (stat /= 0) then
      message = 'cannot create the group /cases/' // name // ' in ' // out%temp_name
      return
    end if
    g = writer%group
    np = mat%n_planes
    writer%every = deck%every
    writer%wanted = deck%stored
    ! Rows kept of a completed case: 0, every, 2 every, ... and the last; a chunk holds them all
    ! (a small file stays small), or max_chunk_rows.
    k = max(deck%n_steps, 1) - 1
    writer%block_rows = min(max_chunk_rows, k / deck%every + 1 + merge(1, 0, mod(k, deck%every) /= 0))
    writer%block%n_planes = np
    writer%block%n_components = deck%n_components
    call writer%block%reserve(writer%block_rows)
    ! &output store: the datasets written.
    stored = ''
    do k = 1, n_datasets
      if (.not. deck%stored(k)) cycle
      if (len(stored) > 0) stored = stored // ','
      stored = stored // trim(history_datasets(k))
    end do
    ! What the case is.
    call ok(h5_text(g, 'label', label))
    call ok(h5_text(g, 'sweep_parameter', trim(deck%sweep_parameter)))
    if (deck%sweep_property /= 0) call ok(h5_real(g, 'sweep_value', deck%sweep_values(icase)))
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
    call ok(h5_int(g, 'every', deck%every))
    call ok(h5_text(g, 'stored', stored))
    ! A 3D case (SPEC section 9): the frame, the third component and the RIA's azimuths.
    if (deck%n_components == 3) then
      call ok(h5_text(g, 'frame', 'local interface frame (n, t1, t2), right-handed, t2 = n x t1; ' // &
                      't1 is the slip axis of the input; the per-plane state (theta, ' // &
                      'frictional_slip, friction_traction, sf_strike, tauf_strike) is in ' // &
                      'each plane''s frame (m_k, e_k, q_k) at its phi_deg as given, which ' // &
                      'may lie outside [0, 180): the same plane at phi_deg - 180 with theta ' // &
                      'negated has these five of opposite sign'))
      call ok(h5_text(g, 'components', 'N, T1, T2'))
      call ok(h5_text(g, 't2_control', control_name(deck%control%traction(3))))
      call ok(h5_text(g, 'ria', deck_ria_name(deck, icase)))
      call ok(h5_int(g, 'n_azimuths', case_n_azimuths(deck, icase)))
      call ok(h5_real_1d(g, 'phi_deg', mat%phi(1:np) * rad_to_deg))
      call ok(h5_text(g, 'phi_deg_unit', 'deg'))
      call ok(h5_text(g, 'path', trim(deck%path_kind)))
      if (len_trim(deck%path_kind) > 0) then
        if (deck%sweep_property == sweep_slip_angle) then
          call ok(h5_real(g, 'angle_deg', deck%sweep_values(icase)))
        else
          call ok(h5_real(g, 'angle_deg', deck%path_angle_deg))
        end if
        call ok(h5_real(g, 'path_size', deck%path_size))
        call ok(h5_real(g, 'path_turns', deck%path_turns))
        call ok(h5_real(g, 'path_normal', deck%path_normal))
      end if
    end if
    ! The datasets, empty: rows are appended as they come.
    do k = 1, n_datasets
      if (.not. writer%wanted(k) .or. stat /= 0) cycle
      select case (dataset_shape(k))
      case (shape_pair)
        width = deck%n_components
      case (shape_planes)
        width = np
      case default
        width = 0
      end select
      call h5_create_series(g, trim(history_datasets(k)), dataset_shape(k) == shape_count, &
                            width, writer%block_rows, dataset_unit(k), &
                            dataset_description(k, deck%extrapolate, deck%n_components == 3), &
                            writer%series(k), stat)
    end do
    if (stat /= 0) message = 'cannot write the case /cases/' // name // ' to ' // out%temp_name

  contains

    subroutine ok(s)
      integer, intent(in) :: s
      if (stat == 0) stat = s
    end subroutine ok

    subroutine property(ip, value)
      integer, intent(in) :: ip
      real(dp), intent(in) :: value
      call ok(h5_real(g, trim(properties(ip)%name), value))
      call ok(h5_text(g, trim(properties(ip)%name) // '_unit', trim(properties(ip)%unit)))
    end subroutine property

    subroutine property_planes(ip, values)
      integer, intent(in) :: ip
      real(dp), intent(in), contiguous :: values(:)
      call ok(h5_real_1d(g, trim(properties(ip)%name), values))
      call ok(h5_text(g, trim(properties(ip)%name) // '_unit', trim(properties(ip)%unit)))
    end subroutine property_planes

  end subroutine output_begin_case

  !> The sink's put: keep rows 1, 1 + every, 1 + 2 every, ... (the file's rows 0, every, ...)
  !> in the block, write the block when it is full; remember the other rows' last one.
  subroutine writer_put(sink, row, stat)
    class(case_writer_t), intent(inout) :: sink
    type(history_row_t), intent(in) :: row
    integer, intent(out) :: stat
    stat = sink%stat
    if (stat /= 0) return
    if (mod(sink%n_rows - 1, sink%every) /= 0) then
      sink%last = row
      sink%last_pending = .true.
      return
    end if
    sink%last_pending = .false.
    call add_to_block(sink, row, stat)
  end subroutine writer_put

  subroutine add_to_block(writer, row, stat)
    type(case_writer_t), intent(inout) :: writer
    type(history_row_t), intent(in) :: row
    integer, intent(out) :: stat
    stat = 0
    if (writer%block%n_rows == writer%block_rows) call write_block(writer, stat)
    if (stat /= 0) return
    writer%block%n_rows = writer%block%n_rows + 1
    call writer%block%put(row, stat)
  end subroutine add_to_block

  !> Append the block's rows to the datasets and empty the block.
  subroutine write_block(writer, stat)
    type(case_writer_t), intent(inout) :: writer
    integer, intent(out) :: stat
    integer :: k, n
    stat = 0
    n = writer%block%n_rows
    if (n == 0) return
    associate (b => writer%block, s => writer%series)
      do k = 1, n_datasets
        if (.not. writer%wanted(k) .or. stat /= 0) cycle
        select case (trim(history_datasets(k)))
        case ('time')
          call h5_append(s(k), b%time(1:n), stat)
        case ('separation')
          call h5_append(s(k), b%separation(:, 1:n), stat)
        case ('traction')
          call h5_append(s(k), b%traction(:, 1:n), stat)
        case ('damage')
          call h5_append(s(k), b%damage(:, 1:n), stat)
        case ('beta')
          call h5_append(s(k), b%beta(:, 1:n), stat)
        case ('theta')
          call h5_append(s(k), b%theta(:, 1:n), stat)
        case ('zeta')
          call h5_append(s(k), b%zeta(:, 1:n), stat)
        case ('frictional_slip')
          call h5_append(s(k), b%frictional_slip(:, 1:n), stat)
        case ('friction_traction')
          call h5_append(s(k), b%friction_traction(:, 1:n), stat)
        case ('work')
          call h5_append(s(k), b%work(1:n), stat)
        case ('stored_energy')
          call h5_append(s(k), b%stored(1:n), stat)
        case ('damage_dissipation')
          call h5_append(s(k), b%diss_damage(1:n), stat)
        case ('friction_dissipation')
          call h5_append(s(k), b%diss_friction(1:n), stat)
        case ('iterations')
          call h5_append(s(k), b%iterations(1:n), stat)
        case ('substeps')
          call h5_append(s(k), b%substeps(1:n), stat)
        case ('sf_strike')
          call h5_append(s(k), b%sf_strike(:, 1:n), stat)
        case ('tauf_strike')
          call h5_append(s(k), b%tauf_strike(:, 1:n), stat)
        end select
      end do
    end associate
    call writer%block%clear()
    writer%stat = stat
  end subroutine write_block

  !> Complete the case: the last row (if `every` left it out), the rows still in the block, the
  !> attributes known at the end (status, n_rows, extrapolation); close its datasets and group.
  subroutine output_end_case(out, writer, stat, message)
    type(output_t), intent(in) :: out
    type(case_writer_t), intent(inout) :: writer
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    character(len=:), allocatable :: how
    integer :: k, s2

    message = ''
    stat = writer%stat
    if (stat == 0 .and. writer%last_pending) call add_to_block(writer, writer%last, stat)
    if (stat == 0) call write_block(writer, stat)
    how = ''
    if (writer%extrapolated) then
      how = 'global Richardson extrapolation of two runs from the same initial state, one ' // &
        'with the deck''s steps (n) and one with the step count of every segment of more ' // &
        'than one step doubled (2n; a one-step segment, e.g. the preload, is taken alike in ' // &
        'both runs): separation and traction are 2 u(2n) - u(n) at the steps of the n run; ' // &
        'damage, beta, theta, zeta, frictional_slip, friction_traction and the energies are ' // &
        'those of the 2n run at the same steps (not extrapolated: extrapolated values could ' // &
        'leave their admissible ranges); iterations and substeps are the sums of both runs ' // &
        '(one step of the n run and the steps of the 2n run that end at the same point per row)'
    end if
    if (stat == 0) call h5_attribute(writer%group, 'status', writer%status, stat)
    if (stat == 0) stat = h5_int(writer%group, 'n_rows', writer%series(1)%rows)
    if (stat == 0) stat = h5_int(writer%group, 'extrapolated', merge(1, 0, writer%extrapolated))
    if (stat == 0) stat = h5_text(writer%group, 'extrapolation', how)
    do k = 1, n_datasets
      call h5_close_series(writer%series(k), s2)
      if (stat == 0) stat = s2
    end do
    call h5_close_group(writer%group, s2)
    if (stat == 0) stat = s2
    if (stat /= 0) message = 'cannot write the case /cases/' // writer%name // ' to ' // &
                             out%temp_name // ' (is the disk full?)'
  end subroutine output_end_case

  !> Close the file and give it its final name.
  subroutine output_close(out, stat, message, rename)
    type(output_t), intent(inout) :: out
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    !> .false.: close only; the complete file stays out%temp_name, guarded, for the caller to
    !> rename together with another file (interlock-fit's pair)
    logical, intent(in), optional :: rename
    integer :: s2
    message = ''
    call h5_close_group(out%cases, stat)
    call h5_close_file(out%file, s2)
    out%open = .false.
    if (stat == 0) stat = s2
    if (stat /= 0) then
      message = 'cannot close ' // out%temp_name // ' (is the disk full?)'
      call remove_file(out%temp_name)
      call unguard_file(out%temp_name)
      return
    end if
    if (present(rename)) then
      if (.not. rename) return
    end if
    call rename_file(out%temp_name, out%final_name, stat)
    if (stat /= 0) then
      message = 'cannot rename ' // out%temp_name // ' to ' // out%final_name
      call remove_file(out%temp_name)
    end if
    call unguard_file(out%temp_name)
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
    call unguard_file(out%temp_name)
  end subroutine output_abort


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
    real(dp), intent(in), contiguous :: x(:)
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

  !> What a row of dataset k is: one real, a (normal, tangential) pair, one value per plane,
  !> or one count.
  pure integer function dataset_shape(k)
    integer, intent(in) :: k
    select case (trim(history_datasets(k)))
    case ('separation', 'traction')
      dataset_shape = shape_pair
    case ('damage', 'beta', 'theta', 'zeta', 'frictional_slip', 'friction_traction', 'sf_strike', &
          'tauf_strike')
      dataset_shape = shape_planes
    case ('iterations', 'substeps')
      dataset_shape = shape_count
    case default
      dataset_shape = shape_single
    end select
  end function dataset_shape

  pure function dataset_unit(k) result(unit)
    integer, intent(in) :: k
    character(len=:), allocatable :: unit
    select case (trim(history_datasets(k)))
    case ('separation', 'frictional_slip', 'sf_strike')
      unit = 'mm'
    case ('traction', 'friction_traction', 'tauf_strike')
      unit = 'MPa'
    case ('theta')
      unit = 'rad'
    case ('zeta', 'work', 'stored_energy', 'damage_dissipation', 'friction_dissipation')
      unit = 'N/mm'
    case default
      unit = '-'
    end select
  end function dataset_unit

  !> The `description` of dataset k, with what extrapolation (&solver extrapolate) made of it.
  pure function dataset_description(k, extrapolated, three_d) result(text)
    integer, intent(in) :: k
    logical, intent(in) :: extrapolated, three_d
    character(len=:), allocatable :: text, state_note, count_note, extrapolated_note
    state_note = ''
    count_note = ''
    extrapolated_note = ''
    if (extrapolated) then
      state_note = ' (of the run with doubled steps)'
      count_note = ' (summed over the step of the run with the deck''s steps and the steps ' // &
        'of the run with doubled steps that end at the same point)'
      extrapolated_note = ' (Richardson-extrapolated: 2 u(2n) - u(n), u(n) with the deck''s ' // &
        'steps, u(2n) with the step count of every segment of more than one step doubled)'
    end if
    select case (trim(history_datasets(k)))
    case ('time')
      text = 'pseudo-time at the end of each step written (row 0: after the first step; with ' // &
        'every = k > 1 the steps 1, 1 + k, 1 + 2k, ... and the last)'
    case ('separation')
      if (three_d) then
        text = 'relative displacement (s_N, s_T1, s_T2) in the frame (n, t1, t2): column 0 ' // &
          'normal (> 0 opening), 1 along t1, 2 along t2' // extrapolated_note
      else
        text = 'relative displacement (s_N, s_T): column 0 normal (> 0 opening), 1 tangential' // &
          extrapolated_note
      end if
    case ('traction')
      if (three_d) then
        text = 'traction (sigma_N, sigma_T1, sigma_T2) in the frame (n, t1, t2): column 0 ' // &
          'normal (< 0 compression), 1 along t1, 2 along t2' // extrapolated_note
      else
        text = 'traction (sigma_N, sigma_T): column 0 normal (< 0 compression), 1 tangential' // &
          extrapolated_note
      end if
    case ('damage')
      text = 'damage D_k of each microplane (column k-1 = plane k)' // state_note
    case ('beta')
      text = 'history maximum of the equivalent relative displacement of each microplane' // &
        state_note
    case ('theta')
      text = 'current inclination theta_k of each microplane' // state_note
    case ('zeta')
      text = 'accumulated frictional work zeta_k of each microplane (drives wear)' // state_note
    case ('frictional_slip')
      if (three_d) then
        text = 'frictional slip sf_k of each microplane along its dip direction e_k (the ' // &
          'strike component: sf_strike)' // state_note
      else
        text = 'frictional slip sf_k along each microplane' // state_note
      end if
    case ('friction_traction')
      if (three_d) then
        text = 'friction traction tau_f of each microplane along its dip direction e_k at the ' // &
          'end of the step (the strike component: tauf_strike)' // state_note
      else
        text = 'friction traction K_t (s_kt - sf_k) of each microplane at the end of the step' // &
          state_note
      end if
    case ('sf_strike')
      text = 'frictional slip of each microplane along its strike q_k = -sin(phi_k) t1 + ' // &
        'cos(phi_k) t2' // state_note
    case ('tauf_strike')
      text = 'friction traction of each microplane along its strike q_k at the end of the step' // &
        state_note
    case ('work')
      text = 'work done on the interface since the initial state, sum of sigma . ds' // state_note
    case ('stored_energy')
      text = 'stored (free) energy of the interface' // state_note
    case ('damage_dissipation')
      text = 'energy dissipated by damage since the initial state' // state_note
    case ('friction_dissipation')
      text = 'energy dissipated by friction since the initial state' // state_note
    case ('iterations')
      text = 'Newton iterations of the mixed-control solve of each step (all attempts; 0 when ' // &
        'every component is separation-driven)' // count_note
    case default
      text = 'sub-increments of each step: the library''s sub-increments summed over the ' // &
        'accepted step cuts (1: the step was neither cut nor substepped)' // count_note
    end select
  end function dataset_description

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
