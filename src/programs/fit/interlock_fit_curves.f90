!> The measured curves of interlock-fit (docs/fit.md): a curve read from its CSV file and
!> windowed and weighted (read_curve), the history outputs it is compared with (curve_along,
!> curve_against: those of a 2D or a 3D deck), and the monotone runs (branches) of its
!> abscissa, along which a measured point meets the history.
module interlock_fit_curves
  use interlock, only: dp, format_integer, format_real, same_value
  use interlock_deck, only: deck_t
  use interlock_deck_text, only: to_lower => lower
  use interlock_csv, only: csv_t, read_csv, csv_column, printable_text
  implicit none
  private
  public :: n_outputs, output_names, output_index, output_in_deck, deck_outputs, join, &
            join_selected, split_branches, branch_turns, curve_t, curve_spec_t, read_curve, &
            folder_of, unset, name_len, file_len

  integer, parameter :: name_len = 64, file_len = 1024
  !> A real of the &fit group not given.
  real(dp), parameter :: unset = -huge(1.0_dp)
  !> The range of a weight (curve_weight, and each value of a weight column up to 0): weights
  !> far outside it would make the residuals vanish or their squares overflow.
  real(dp), parameter :: min_weight = 1.0e-100_dp, max_weight = 1.0e100_dp

  !> One measured curve, windowed: points (x, y) with weights w; branch: the monotone run of the
  !> abscissa (over the whole file, before the window) that each point is on.
  type :: curve_t
    character(len=:), allocatable :: name, file, x_column, y_column
    integer :: along = 0, against = 0      !< indices into output_names
    real(dp), allocatable :: x(:), y(:), w(:)
    integer, allocatable :: branch(:)
    real(dp) :: tolerance = 0.0_dp         !< abscissa tolerance of the branch split
    !> where the abscissa turns in the file (branch_turns), for the message when the history
    !> has fewer branches
    character(len=:), allocatable :: turns
  end type curve_t

  !> One curve of the &fit group as given: the i-th value of each curve_* list.
  type :: curve_spec_t
    character(len=name_len) :: name = '', x = '', y = '', along = '', against = '', &
                               weight_column = '', window_column = ''
    character(len=file_len) :: file = ''
    real(dp) :: weight = unset, window_min = unset, window_max = unset
  end type curve_spec_t

  !> History outputs a curve can be compared with (one value per row). separation_t and
  !> traction_t are the tangential components of a 2D deck; a 3D deck names its components t1
  !> and t2 (separation_t1, traction_t1 are the same columns in 2D, where t is t1). Derived
  !> outputs, in 2D and 3D: traction_t_magnitude = |sigma_T| = sqrt(sigma_T1^2 + sigma_T2^2), and
  !> slip_length, the length of the slip path in the (T1, T2) plane from row 0 (the sum of the
  !> rows' |delta s_T|: monotone, so a cyclic or curved path is one branch along it).
  integer, parameter :: n_outputs = 15
  character(len=20), parameter :: output_names(n_outputs) = [character(len=20) :: 'time', &
    'separation_n', 'separation_t', 'traction_n', 'traction_t', 'work', 'stored_energy', &
    'damage_dissipation', 'friction_dissipation', 'separation_t1', 'separation_t2', &
    'traction_t1', 'traction_t2', 'traction_t_magnitude', 'slip_length']
  integer, parameter, public :: out_separation_t = 3, out_traction_t = 5, out_separation_t1 = 10, &
    out_separation_t2 = 11, out_traction_t1 = 12, out_traction_t2 = 13, &
    out_traction_t_magnitude = 14, out_slip_length = 15

contains

  !> Number each value by the monotone run of x it is on (1, 2, ...): a run ends where x turns
  !> back by more than `tolerance` from its extreme; the points after the extreme start the next.
  pure subroutine split_branches(x, tolerance, branch)
    real(dp), intent(in) :: x(:), tolerance
    integer, allocatable, intent(out) :: branch(:)
    integer :: i, dir, iext, b
    allocate (branch(size(x)))
    if (size(x) == 0) return
    b = 1
    dir = 0
    iext = 1
    branch(1) = 1
    do i = 2, size(x)
      branch(i) = b
      if (dir == 0) then
        if (x(i) > x(iext) + tolerance) dir = 1
        if (x(i) < x(iext) - tolerance) dir = -1
        iext = i
      else if (dir * (x(i) - x(iext)) >= 0.0_dp) then
        iext = i
      else if (abs(x(i) - x(iext)) > tolerance) then
        b = b + 1
        branch(iext + 1:i) = b
        dir = -dir
        iext = i
      end if
    end do
  end subroutine split_branches

  !> Where the abscissa x of a curve file turns (its branches, split_branches), for a message:
  !> the lines of the extremes where it turns back (at most 6 listed), and how many of the
  !> branches span less than 1 % of the abscissa's range, with a word on noise where most do
  !> (each turn back by more than 1e-6 of the range starts a branch).
  function branch_turns(x, branch, lines, column, file) result(text)
    real(dp), intent(in) :: x(:)
    integer, intent(in) :: branch(:), lines(:)
    character(len=*), intent(in) :: column, file
    character(len=:), allocatable :: text
    integer :: nb, b, i, small, listed
    real(dp) :: span
    nb = branch(size(branch))
    text = ''
    if (nb < 2) return
    span = maxval(x) - minval(x)
    small = 0
    listed = 0
    text = column // ' turns at line'
    if (nb > 2) text = text // 's'
    do b = 2, nb
      i = findloc(branch, b, dim=1) - 1   ! the extreme before the branch
      if (listed < 6) then
        if (listed > 0) text = text // ','
        text = text // ' ' // format_integer(lines(i))
        listed = listed + 1
      else if (listed == 6) then
        text = text // ', ...'
        listed = listed + 1
      end if
    end do
    text = text // ' of ' // file
    do b = 1, nb
      if (maxval(x, mask=branch == b) - minval(x, mask=branch == b) < 1.0e-2_dp * span) &
        small = small + 1
    end do
    if (2 * small > nb) then
      text = text // '; ' // format_integer(small) // ' of its ' // format_integer(nb) // &
             ' branches span less than 1 % of its range: noise on the abscissa? Every turn ' // &
             'back by more than 1e-6 of the range starts a branch: smooth the column, or take ' // &
             'one that runs with the test, such as time'
    end if
  end function branch_turns

  integer function output_index(name)
    character(len=*), intent(in) :: name
    do output_index = 1, n_outputs
      if (trim(output_names(output_index)) == trim(to_lower(adjustl(name)))) return
    end do
    output_index = 0
  end function output_index

  !> Whether history output k exists for the deck: the T2 outputs in 3D only; separation_t and
  !> traction_t in 2D only (in 3D the tangential components are t1 and t2).
  pure logical function output_in_deck(k, deck)
    integer, intent(in) :: k
    type(deck_t), intent(in) :: deck
    if (deck%n_components == 3) then
      output_in_deck = k /= out_separation_t .and. k /= out_traction_t
    else
      output_in_deck = k /= out_separation_t2 .and. k /= out_traction_t2
    end if
  end function output_in_deck

  !> The history outputs of the deck's dimension, joined by ', '.
  function deck_outputs(deck) result(text)
    type(deck_t), intent(in) :: deck
    character(len=:), allocatable :: text
    integer :: k
    text = join_selected(output_names, pack([(k, k = 1, n_outputs)], &
                                            [(output_in_deck(k, deck), k = 1, n_outputs)]))
  end function deck_outputs

  function join(names) result(text)
    character(len=*), intent(in) :: names(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, size(names)
      if (i > 1) text = text // ', '
      text = text // trim(names(i))
    end do
  end function join

  !> names(idx(1)), names(idx(2)), ... joined by ', '.
  function join_selected(names, idx) result(text)
    character(len=*), intent(in) :: names(:)
    integer, intent(in) :: idx(:)
    character(len=:), allocatable :: text
    text = join(names(idx))
  end function join_selected

  !> Curve i of the &fit group as `spec` gives it (earlier: the names of the curves before it)
  !> read from its file (relative to the folder of the deck `path`) and windowed, its outputs
  !> among those of `deck`; message /= '' (after `prefix`) when it cannot be.
  subroutine read_curve(i, spec, earlier, path, prefix, deck, c, message)
    integer, intent(in) :: i
    type(curve_spec_t), intent(inout) :: spec
    character(len=*), intent(in) :: earlier(:), path, prefix
    type(deck_t), intent(in) :: deck
    type(curve_t), intent(out) :: c
    character(len=*), intent(out) :: message
    type(csv_t) :: csv
    integer :: cx, cy, cw, cwin, n
    logical, allocatable :: keep(:)
    real(dp) :: scale
    character(len=:), allocatable :: file, cname

    message = ''
    cname = trim(spec%name)
    if (len(cname) == 0) cname = 'curve' // format_integer(i)
    if (index(cname, ',') > 0 .or. index(cname, '/') > 0) then
      message = prefix // 'curve_name(' // format_integer(i) // ') = ''' // cname // &
                ''': a name without commas or slashes'
      return
    end if
    if (any(earlier == cname)) then
      message = prefix // 'curve_name: ''' // cname // ''' is given twice'
      return
    end if
    c%name = cname
    spec%name = cname
    file = trim(spec%file)
    if (file(1:1) /= '/') file = folder_of(path) // file
    c%file = file
    c%along = output_for_deck(spec%along, 'curve_along', cname)
    if (len_trim(message) > 0) return
    c%against = output_for_deck(spec%against, 'curve_against', cname)
    if (len_trim(message) > 0) return
    call read_csv(file, csv, message)
    if (len_trim(message) > 0) then
      message = prefix // 'curve ' // cname // ': ' // trim(message)
      return
    end if
    cx = find_column(csv, spec%x, 'curve_x', cname)
    if (len_trim(message) > 0) return
    cy = find_column(csv, spec%y, 'curve_y', cname)
    if (len_trim(message) > 0) return
    c%x_column = trim(spec%x)
    c%y_column = trim(spec%y)
    n = size(csv%values, 1)
    allocate (keep(n))
    keep = .true.
    if (spec%window_column /= '') then
      cwin = find_column(csv, spec%window_column, 'curve_window_column', cname)
      if (len_trim(message) > 0) return
      if (same_value(spec%window_min, unset)) spec%window_min = -huge(1.0_dp)
      if (same_value(spec%window_max, unset)) spec%window_max = huge(1.0_dp)
      keep = csv%values(:, cwin) >= spec%window_min .and. &
             csv%values(:, cwin) <= spec%window_max
      if (.not. any(keep)) then
        message = prefix // 'curve ' // cname // ': the window ' // &
                  trim(spec%window_column) // ' in [' // format_real(spec%window_min) // &
                  ', ' // format_real(spec%window_max) // '] holds no row of ' // file // &
                  ' (its ' // trim(spec%window_column) // ' runs from ' // &
                  format_real(minval(csv%values(:, cwin))) // ' to ' // &
                  format_real(maxval(csv%values(:, cwin))) // ')'
        return
      end if
    else if (.not. same_value(spec%window_min, unset) .or. &
             .not. same_value(spec%window_max, unset)) then
      message = prefix // 'curve ' // cname // ': curve_window_min/max without ' // &
                'curve_window_column (the column the window applies to)'
      return
    end if
    if (count(keep) < 2) then
      message = prefix // 'curve ' // cname // ': ' // file // ' has ' // &
                format_integer(count(keep)) // ' point(s) in the window: too few (at least 2)'
      return
    end if
    c%tolerance = 1.0e-6_dp * (maxval(csv%values(:, cx)) - minval(csv%values(:, cx)))
    call split_branches(csv%values(:, cx), c%tolerance, c%branch)
    c%turns = branch_turns(csv%values(:, cx), c%branch, csv%lines, trim(spec%x), &
                           trim(spec%file))
    c%branch = pack(c%branch, keep)
    c%x = pack(csv%values(:, cx), keep)
    c%y = pack(csv%values(:, cy), keep)
    if (spec%weight_column /= '') then
      cw = find_column(csv, spec%weight_column, 'curve_weight_column', cname)
      if (len_trim(message) > 0) return
      c%w = pack(csv%values(:, cw), keep)
      if (any(c%w < 0.0_dp) .or. any(c%w > max_weight)) then
        message = prefix // 'curve ' // cname // ': the weight column ' // &
                  trim(spec%weight_column) // ' has values outside [0, ' // &
                  format_real(max_weight) // '] (admissible 0 <= weight <= ' // &
                  format_real(max_weight) // ')'
        return
      end if
      if (all(c%w <= 0.0_dp)) then
        message = prefix // 'curve ' // cname // ': every weight in the column ' // &
                  trim(spec%weight_column) // ' is 0 (the curve would not count)'
        return
      end if
    else
      allocate (c%w(size(c%x)))
      c%w = 1.0_dp
    end if
    if (.not. same_value(spec%weight, unset)) then
      if (.not. (spec%weight >= min_weight .and. spec%weight <= max_weight)) then
        message = prefix // 'curve ' // cname // ': curve_weight = ' // &
                  format_real(spec%weight) // ' is inadmissible: admissible ' // &
                  format_real(min_weight) // ' <= curve_weight <= ' // format_real(max_weight)
        return
      end if
      c%w = c%w * spec%weight
    else
      scale = maxval(abs(c%y))
      if (scale <= 0.0_dp) then
        message = prefix // 'curve ' // cname // ': every value of ' // trim(spec%y) // &
                  ' in ' // file // ' is 0: the default weight 1/max|y|^2 needs one that is ' // &
                  'not (the wrong column? If a curve of zeros is meant, give curve_weight)'
        return
      end if
      if (scale < sqrt(min_weight)) then
        message = prefix // 'curve ' // cname // ': every value of ' // trim(spec%y) // &
                  ' is below ' // format_real(sqrt(min_weight)) // ' in magnitude: the ' // &
                  'default weight 1/max|y|^2 would exceed ' // format_real(max_weight) // &
                  ' (give curve_weight, or the values in another unit)'
        return
      end if
      c%w = c%w * (1.0_dp / scale)**2
    end if

  contains

    !> The history output `name` (curve_along or curve_against of the curve being read) among
    !> those of the deck's dimension; 0 and a message naming the admissible ones otherwise.
    integer function output_for_deck(name, variable, cname)
      character(len=*), intent(in) :: name, variable, cname
      character(len=:), allocatable :: dimension, lead, derived
      output_for_deck = output_index(name)
      dimension = merge('3D', '2D', deck%n_components == 3)
      lead = prefix // 'curve ' // cname // ': ' // variable // ' = ''' // &
             trim(name) // ''''
      if (output_for_deck == 0) then
        message = lead // ' is no history output; the outputs of this ' // dimension // &
                  ' deck: ' // deck_outputs(deck)
      else if (.not. output_in_deck(output_for_deck, deck)) then
        if (deck%n_components == 3) then
          derived = 'slip_length (the slip path''s length)'
          if (output_for_deck == out_traction_t) derived = 'traction_t_magnitude (|sigma_T|)'
          message = lead // ' is ambiguous in a 3D deck: name the component (' // &
                    trim(output_names(output_for_deck)) // '1 or ' // &
                    trim(output_names(output_for_deck)) // '2), or ' // derived // &
                    '; the outputs of this 3D deck: ' // deck_outputs(deck)
        else
          message = lead // ' is an output of 3D decks only (this deck is 2D: no T2 loading, ' // &
                    'path, azimuths or azimuthal RIA, docs/deck-format.md); the outputs of ' // &
                    'this 2D deck: ' // deck_outputs(deck)
        end if
      end if
      if (len_trim(message) > 0) output_for_deck = 0
    end function output_for_deck

    !> The column `name` of `csv` (header name or number); 0 and a message if there is none.
    integer function find_column(csv, name, variable, cname)
      type(csv_t), intent(in) :: csv
      character(len=*), intent(in) :: name, variable, cname
      find_column = csv_column(csv, trim(name))
      if (find_column == 0) message = prefix // 'curve ' // cname // ': ' // variable // &
        ' = ''' // trim(name) // ''' is no column of the file (its columns: ' // &
        trim(printable_text(join(csv%names))) // '; or a column number 1 to ' // format_integer(size(csv%names)) // ')'
    end function find_column

  end subroutine read_curve

  !> The folder part of `path` with its final '/' ('' for a bare file name).
  function folder_of(path) result(folder)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: folder
    integer :: slash
    slash = index(path, '/', back=.true.)
    folder = path(1:slash)
  end function folder_of

end module interlock_fit_curves
