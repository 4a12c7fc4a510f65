!> The &fit group of an interlock-fit deck (docs/fit.md): the measured curves (CSV files, their
!> columns, the history output each is compared with, weights, a window), the free parameters
!> (material-table names, start values, bounds) and the stages (which parameters on which
!> curves, in order). The rest of the deck is an ordinary interlock-history deck (read_deck).
!> Every error names the deck, the group, the variable and what is admissible.
module interlock_fit_deck
  use interlock, only: dp, properties, property_index, check_property, format_range, &
      format_integer, format_real, same_value, prop_sigma0_n, prop_zeta0, prop_h_n, prop_theta0, &
      prop_thetaf, status_ok
  use interlock_deck, only: deck_t, read_deck, deck_groups, deck_property
  use interlock_deck_text, only: group_scan_t, scan_deck, to_lower => lower
  use interlock_csv, only: csv_t, read_csv, csv_column, printable_text
  use interlock_lm, only: lm_options_t
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
  implicit none
  private
  public :: fit_t, curve_t, stage_t, read_fit_deck, output_names, n_outputs, fit_groups, &
            split_branches, join_selected, law_angles, folder_of

  integer, parameter :: max_curves = 32, max_free = 16, max_stages = 16
  integer, parameter :: name_len = 64, file_len = 1024, list_len = 1024
  real(dp), parameter :: unset = -huge(1.0_dp)
  !> The range of a weight (curve_weight, and each value of a weight column up to 0): weights
  !> far outside it would make the residuals vanish or their squares overflow.
  real(dp), parameter :: min_weight = 1.0e-100_dp, max_weight = 1.0e100_dp

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

  character(len=13), parameter :: fit_groups(9) = [character(len=13) :: deck_groups, 'fit']

  character(len=*), parameter :: fit_vars = 'curve_name, curve_file, curve_x, curve_y, ' // &
    'curve_along, curve_against, curve_weight, curve_weight_column, curve_window_column, ' // &
    'curve_window_min, curve_window_max, parameters, start, lower, upper, stage_parameters, ' // &
    'stage_curves, max_iterations, xtol, ftol, gtol, fd_step'

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

  type :: stage_t
    integer, allocatable :: free(:)        !< parameter indices
    integer, allocatable :: curves(:)      !< curve indices
  end type stage_t

  type :: fit_t
    type(deck_t) :: deck
    type(curve_t), allocatable :: curves(:)
    character(len=name_len), allocatable :: curve_names(:)   !< curves(:)%name
    character(len=name_len), allocatable :: names(:)
    integer, allocatable :: property(:)
    real(dp), allocatable :: start(:), lower(:), upper(:)
    type(stage_t), allocatable :: stages(:)
    type(lm_options_t) :: options
    character(len=512), allocatable :: warnings(:)   !< printed before the fit
  end type fit_t

contains

  !> Read a fit deck: the history deck (read_deck, &fit allowed) and the &fit group.
  subroutine read_fit_deck(path, fd, stat, message)
    character(len=*), intent(in) :: path
    type(fit_t), intent(out) :: fd
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    type(group_scan_t) :: scan(size(fit_groups))
    character(len=name_len) :: curve_name(max_curves), curve_x(max_curves), curve_y(max_curves), &
        curve_along(max_curves), curve_against(max_curves), curve_weight_column(max_curves), &
        curve_window_column(max_curves), parameters(max_free)
    character(len=file_len) :: curve_file(max_curves)
    real(dp) :: curve_weight(max_curves), curve_window_min(max_curves), &
                curve_window_max(max_curves), start(max_free), lower(max_free), upper(max_free)
    character(len=list_len) :: stage_parameters(max_stages), stage_curves(max_stages)
    integer :: max_iterations
    real(dp) :: xtol, ftol, gtol, fd_step
    namelist /fit/ curve_name, curve_file, curve_x, curve_y, curve_along, curve_against, &
      curve_weight, curve_weight_column, curve_window_column, curve_window_min, &
      curve_window_max, parameters, start, lower, upper, stage_parameters, stage_curves, &
      max_iterations, xtol, ftol, gtol, fd_step
    integer :: u, ios, k, nc, np, ns, i
    character(len=512) :: iomsg
    character(len=:), allocatable :: prefix

    stat = 1
    call read_deck(path, fd%deck, stat, message, ['fit'])
    if (stat /= status_ok) return
    stat = 1
    call scan_deck(fd%deck%text, fit_groups, scan, message)
    if (len_trim(message) > 0) then
      message = path // ': ' // trim(message)
      return
    end if
    prefix = path // ': &fit: '
    if (.not. scan(9)%present) then
      message = path // ': the group &fit is missing (interlock-fit needs the curves and ' // &
                'the free parameters: docs/fit.md)'
      return
    end if
    if (fd%deck%sweep_property /= 0) then
      message = path // ': &sweep: a fit deck has one case (remove &sweep)'
      return
    end if
    do k = 1, scan(9)%n
      if (index(', ' // fit_vars // ',', ', ' // trim(to_lower(scan(9)%a(k)%name)) // ',') == 0) then
        message = prefix // 'line ' // format_integer(scan(9)%a(k)%line) // ': unknown ' // &
                  'variable ' // trim(scan(9)%a(k)%name) // ' (the variables are ' // fit_vars // ')'
        return
      end if
    end do

    curve_name = ''
    curve_file = ''
    curve_x = ''
    curve_y = ''
    curve_along = ''
    curve_against = ''
    curve_weight = unset
    curve_weight_column = ''
    curve_window_column = ''
    curve_window_min = unset
    curve_window_max = unset
    parameters = ''
    start = unset
    lower = unset
    upper = unset
    stage_parameters = ''
    stage_curves = ''
    max_iterations = fd%options%max_iterations
    xtol = fd%options%xtol
    ftol = fd%options%ftol
    gtol = fd%options%gtol
    fd_step = fd%options%fd_step
    open (newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
    if (ios == 0) read (u, nml=fit, iostat=ios, iomsg=iomsg)
    close (u)
    if (ios /= 0) then
      message = prefix // 'cannot read the group: ' // trim(iomsg) // ' (docs/fit.md says what ' // &
                'each variable takes)'
      return
    end if

    allocate (fd%warnings(0))
    ! every real value given is a number: NaN or Inf is an error, never "not given"
    if (.not. finite_list('curve_weight', curve_weight)) return
    if (.not. finite_list('curve_window_min', curve_window_min)) return
    if (.not. finite_list('curve_window_max', curve_window_max)) return
    if (.not. finite_list('start', start)) return
    if (.not. finite_list('lower', lower)) return
    if (.not. finite_list('upper', upper)) return

    ! options
    if (max_iterations < 1 .or. max_iterations > 100000) then
      message = prefix // 'max_iterations = ' // format_integer(max_iterations) // &
                ' is inadmissible: admissible 1 to 100000'
      return
    end if
    if (.not. in_range(xtol, 0.0_dp, 1.0_dp, 'xtol')) return
    if (.not. in_range(ftol, 0.0_dp, 1.0_dp, 'ftol')) return
    if (.not. in_range(gtol, 0.0_dp, 1.0_dp, 'gtol')) return
    if (.not. in_range(fd_step, 1.0e-12_dp, 0.1_dp, 'fd_step')) return
    fd%options%max_iterations = max_iterations
    fd%options%xtol = xtol
    fd%options%ftol = ftol
    fd%options%gtol = gtol
    fd%options%fd_step = fd_step

    ! parameters
    np = count(parameters /= '')
    if (np == 0 .or. any(parameters(np + 1:) /= '')) then
      message = prefix // 'parameters: give the names of the free parameters, one after the ' // &
                'other (at most ' // format_integer(max_free) // ')'
      return
    end if
    if (.not. per_item_real('start', start, np, 'free parameter')) return
    if (.not. per_item_real('lower', lower, np, 'free parameter')) return
    if (.not. per_item_real('upper', upper, np, 'free parameter')) return
    allocate (fd%names(np), fd%property(np))
    fd%names = parameters(1:np)
    fd%start = start(1:np)
    fd%lower = lower(1:np)
    fd%upper = upper(1:np)
    do i = 1, np
      call check_parameter(i)
      if (len_trim(message) > 0) return
    end do
    call check_angles()
    if (len_trim(message) > 0) return

    ! curves
    nc = count(curve_file /= '')
    if (nc == 0 .or. any(curve_file(nc + 1:) /= '')) then
      message = prefix // 'curve_file: give one CSV file per curve (at most ' // &
                format_integer(max_curves) // ')'
      return
    end if
    if (.not. per_item_text('curve_name', curve_name, nc, .false.)) return
    if (.not. per_item_text('curve_x', curve_x, nc, .true.)) return
    if (.not. per_item_text('curve_y', curve_y, nc, .true.)) return
    if (.not. per_item_text('curve_along', curve_along, nc, .true.)) return
    if (.not. per_item_text('curve_against', curve_against, nc, .true.)) return
    if (.not. per_item_text('curve_weight_column', curve_weight_column, nc, .true.)) return
    if (.not. per_item_text('curve_window_column', curve_window_column, nc, .true.)) return
    if (.not. per_item_real('curve_weight', curve_weight, nc, 'curve')) return
    if (.not. per_item_real('curve_window_min', curve_window_min, nc, 'curve')) return
    if (.not. per_item_real('curve_window_max', curve_window_max, nc, 'curve')) return
    allocate (fd%curves(nc))
    do i = 1, nc
      call read_curve(i)
      if (len_trim(message) > 0) return
    end do

    fd%curve_names = curve_name(1:nc)

    ! stages
    ns = count(stage_parameters /= '')
    if (ns == 0) then
      if (any(stage_curves /= '')) then
        message = prefix // 'stage_curves is given without stage_parameters'
        return
      end if
      allocate (fd%stages(1))
      fd%stages(1)%free = [(i, i = 1, np)]
      fd%stages(1)%curves = [(i, i = 1, nc)]
    else
      if (count(stage_curves /= '') /= ns) then
        message = prefix // 'stage_curves: give one list of curves per stage (' // &
                  format_integer(ns) // ' stages in stage_parameters)'
        return
      end if
      allocate (fd%stages(ns))
      do k = 1, ns
        call parse_list(stage_parameters(k), fd%names, 'stage_parameters', fd%stages(k)%free)
        if (len_trim(message) > 0) return
        if (trim(to_lower(adjustl(stage_curves(k)))) == 'all') then
          fd%stages(k)%curves = [(i, i = 1, nc)]
        else
          call parse_list(stage_curves(k), curve_name(1:nc), 'stage_curves', fd%stages(k)%curves)
          if (len_trim(message) > 0) return
        end if
      end do
      do i = 1, np
        if (.not. any([(any(fd%stages(k)%free == i), k = 1, ns)])) then
          message = prefix // 'parameter ' // trim(fd%names(i)) // ' is in no stage ' // &
                    '(stage_parameters)'
          return
        end if
      end do
    end if
    do k = 1, size(fd%stages)
      i = sum([(size(fd%curves(fd%stages(k)%curves(nc))%x), nc = 1, size(fd%stages(k)%curves))])
      if (i <= size(fd%stages(k)%free)) then
        message = prefix // 'stage ' // format_integer(k) // ': its curves have ' // &
                  format_integer(i) // ' points: a fit of ' // &
                  format_integer(size(fd%stages(k)%free)) // ' parameters needs more points ' // &
                  'than parameters'
        return
      end if
    end do
    stat = status_ok
    message = ''

  contains

    !> Every value of a real list is finite (its unset elements are: -huge).
    logical function finite_list(name, x)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: x(:)
      integer :: k
      finite_list = .true.
      do k = 1, size(x)
        if (ieee_is_finite(x(k))) cycle
        finite_list = .false.
        message = prefix // name // '(' // format_integer(k) // ') = ' // &
                  trim(merge('NaN     ', 'Infinity', ieee_is_nan(x(k)))) // ' is not a finite ' // &
                  'number (give a finite value, or leave the whole list out for its default)'
        return
      end do
    end function finite_list

    !> A real list with one value per item (n items, `what` they are): none given (every
    !> element unset: the default, or an error later where the list is required), exactly n,
    !> or one, which then applies to all. Anything else is an error naming the list.
    logical function per_item_real(name, x, n, what)
      character(len=*), intent(in) :: name, what
      real(dp), intent(inout) :: x(:)
      integer, intent(in) :: n
      integer :: k
      do k = size(x), 1, -1
        if (.not. same_value(x(k), unset)) exit
      end do
      per_item_real = list_count(name, k, n, what)
      if (.not. per_item_real) return
      if (k == 1) x(2:n) = x(1)
      if (k == 1 .and. n > 1) call note_one_for_all(name, n, what)
      do k = 1, merge(n, 0, k > 0)
        if (.not. same_value(x(k), unset)) cycle
        message = prefix // name // '(' // format_integer(k) // ') is not given: give one ' // &
                  'value per ' // what // ' or one for all'
        per_item_real = .false.
        return
      end do
    end function per_item_real

    !> As per_item_real for a list of names ('' unset); allow_one: one value may apply to all
    !> (not for curve_name: names differ).
    logical function per_item_text(name, x, n, allow_one)
      character(len=*), intent(in) :: name
      character(len=*), intent(inout) :: x(:)
      integer, intent(in) :: n
      logical, intent(in) :: allow_one
      integer :: k
      do k = size(x), 1, -1
        if (x(k) /= '') exit
      end do
      if (.not. allow_one .and. k == 1 .and. n > 1) then
        message = prefix // name // ' gives 1 value for ' // format_integer(n) // ' curves: ' // &
                  'give one per curve (in the order of curve_file), or leave it out'
        per_item_text = .false.
        return
      end if
      per_item_text = list_count(name, k, n, 'curve')
      if (per_item_text .and. k == 1) x(2:n) = x(1)
      if (per_item_text .and. k == 1 .and. n > 1) call note_one_for_all(name, n, 'curve')
    end function per_item_text

    !> One value of a list for n > 1 items applies to all: said before the fit.
    subroutine note_one_for_all(name, n, what)
      character(len=*), intent(in) :: name, what
      integer, intent(in) :: n
      character(len=512) :: line
      line = '&fit: ' // name // ' gives one value for ' // format_integer(n) // ' ' // what // &
             's: it applies to every ' // what
      fd%warnings = [fd%warnings, line]
    end subroutine note_one_for_all

    !> k values given for n items: 0, 1 or n.
    logical function list_count(name, k, n, what)
      character(len=*), intent(in) :: name, what
      integer, intent(in) :: k, n
      list_count = k == 0 .or. k == 1 .or. k == n
      if (list_count) return
      message = prefix // name // ' gives ' // format_integer(k) // ' values for ' // &
                format_integer(n) // ' ' // what // 's: give one per ' // what // ' (in the ' // &
                'order of ' // merge('curve_file', 'parameters', what == 'curve') // &
                '), or one value for all'
    end function list_count

    logical function in_range(x, lo, hi, name)
      real(dp), intent(in) :: x, lo, hi
      character(len=*), intent(in) :: name
      in_range = .false.
      if (ieee_is_nan(x)) then
        message = prefix // name // ' = NaN is not a number: admissible ' // format_real(lo) // &
                  ' <= ' // name // ' <= ' // format_real(hi)
        return
      end if
      in_range = x >= lo .and. x <= hi
      if (.not. in_range) message = prefix // name // ' = ' // format_real(x) // &
        ' is inadmissible: admissible ' // format_real(lo) // ' <= ' // name // ' <= ' // format_real(hi)
    end function in_range

    subroutine check_parameter(i)
      integer, intent(in) :: i
      integer :: ip
      logical :: ok
      character(len=256) :: why
      character(len=:), allocatable :: name
      name = trim(to_lower(fd%names(i)))
      fd%names(i) = name
      ip = property_index(name)
      if (ip == 0) then
        message = prefix // 'parameters: ''' // name // ''' is not a property of the material ' // &
                  'table (the parameters a fit can free: ' // fittable_names() // ')'
        return
      end if
      if (ip < prop_sigma0_n .or. ip > prop_zeta0) then
        message = prefix // 'parameters: ''' // name // ''' is not a parameter a fit can free ' // &
                  '(a flag, a choice or a solver control); the parameters: ' // fittable_names()
        return
      end if
      if (count(fd%names(1:i) == name) > 1) then
        message = prefix // 'parameters: ''' // name // ''' is given twice'
        return
      end if
      fd%property(i) = ip
      if (same_value(fd%start(i), unset)) fd%start(i) = deck_property(fd%deck, ip)
      if (same_value(fd%lower(i), unset) .or. same_value(fd%upper(i), unset)) then
        message = prefix // 'parameter ' // name // ' needs both bounds (lower and upper, ' // &
                  'finite, in ' // format_range(ip) // ')'
        return
      end if
      if (.not. (fd%lower(i) < fd%upper(i))) then
        message = prefix // 'parameter ' // name // ': lower = ' // format_real(fd%lower(i)) // &
                  ' must be below upper = ' // format_real(fd%upper(i))
        return
      end if
      if (fd%start(i) < fd%lower(i) .or. fd%start(i) > fd%upper(i)) then
        message = prefix // 'parameter ' // name // ': the bounds [' // format_real(fd%lower(i)) // &
                  ', ' // format_real(fd%upper(i)) // '] exclude the start value ' // &
                  format_real(fd%start(i)) // ' (admissible lower <= start <= upper)'
        return
      end if
      call check_property(ip, fd%lower(i), ok, why)
      if (ok) call check_property(ip, fd%upper(i), ok, why)
      if (ok .and. fd%upper(i) >= 1.0e30_dp) then
        ok = .false.
        why = 'the bounds must be finite (< 1e30)'
      end if
      if (.not. ok) then
        message = prefix // 'parameter ' // name // ' bounds [' // format_real(fd%lower(i)) // &
                  ', ' // format_real(fd%upper(i)) // ']: ' // trim(why)
        return
      end if
      if (fd%lower(i) <= 0.0_dp .and. (ip == prop_h_n .or. ip == prop_zeta0)) then
        message = prefix // 'parameter ' // name // ': lower = ' // format_real(fd%lower(i)) // &
                  ' is inadmissible: admissible lower > 0 ' // '[' // trim(properties(ip)%unit) // ']'
        return
      end if
    end subroutine check_parameter

    !> The law's constraint |theta_f| <= |theta_0| between two parameters: the boxes (or the
    !> deck's values of a parameter not freed) must leave a point that meets it, and the start
    !> values must meet it.
    subroutine check_angles()
      integer :: i0, if0
      real(dp) :: hi0, lof, s0, sf
      real(dp), allocatable :: corner(:)
      logical :: relevant
      call law_angles(fd, fd%start, i0, if0, s0, sf, relevant)
      if (.not. relevant .or. (i0 == 0 .and. if0 == 0)) return   ! read_deck checked the deck
      ! the box's corner most favourable to theta_f <= theta_0
      corner = fd%start
      if (i0 > 0) corner(i0) = fd%upper(i0)
      if (if0 > 0) corner(if0) = fd%lower(if0)
      call law_angles(fd, corner, i0, if0, hi0, lof, relevant)
      if (lof > hi0) then
        message = prefix // 'theta_f >= ' // format_real(lof) // ' deg and theta_0 <= ' // &
                  format_real(hi0) // ' deg (bounds or the deck''s values) leave no admissible ' // &
                  'point: the law needs |theta_f| <= |theta_0|'
      else if (sf > s0) then
        message = prefix // 'the start values theta_f = ' // format_real(sf) // ' deg and ' // &
                  'theta_0 = ' // format_real(s0) // ' deg are inadmissible: the law needs ' // &
                  '|theta_f| <= |theta_0|'
      end if
    end subroutine check_angles

    subroutine read_curve(i)
      integer, intent(in) :: i
      type(csv_t) :: csv
      integer :: cx, cy, cw, cwin, n
      logical, allocatable :: keep(:)
      real(dp) :: scale
      character(len=:), allocatable :: file, cname
      type(curve_t) :: c

      cname = trim(curve_name(i))
      if (len(cname) == 0) cname = 'curve' // format_integer(i)
      if (index(cname, ',') > 0 .or. index(cname, '/') > 0) then
        message = prefix // 'curve_name(' // format_integer(i) // ') = ''' // cname // &
                  ''': a name without commas or slashes'
        return
      end if
      if (any(curve_name(1:i - 1) == cname)) then
        message = prefix // 'curve_name: ''' // cname // ''' is given twice'
        return
      end if
      c%name = cname
      curve_name(i) = cname
      file = trim(curve_file(i))
      if (file(1:1) /= '/') file = folder_of(path) // file
      c%file = file
      c%along = output_for_deck(curve_along(i), 'curve_along', cname)
      if (len_trim(message) > 0) return
      c%against = output_for_deck(curve_against(i), 'curve_against', cname)
      if (len_trim(message) > 0) return
      call read_csv(file, csv, message)
      if (len_trim(message) > 0) then
        message = prefix // 'curve ' // cname // ': ' // trim(message)
        return
      end if
      cx = find_column(csv, curve_x(i), 'curve_x', cname)
      if (len_trim(message) > 0) return
      cy = find_column(csv, curve_y(i), 'curve_y', cname)
      if (len_trim(message) > 0) return
      c%x_column = trim(curve_x(i))
      c%y_column = trim(curve_y(i))
      n = size(csv%values, 1)
      allocate (keep(n))
      keep = .true.
      if (curve_window_column(i) /= '') then
        cwin = find_column(csv, curve_window_column(i), 'curve_window_column', cname)
        if (len_trim(message) > 0) return
        if (same_value(curve_window_min(i), unset)) curve_window_min(i) = -huge(1.0_dp)
        if (same_value(curve_window_max(i), unset)) curve_window_max(i) = huge(1.0_dp)
        keep = csv%values(:, cwin) >= curve_window_min(i) .and. &
               csv%values(:, cwin) <= curve_window_max(i)
        if (.not. any(keep)) then
          message = prefix // 'curve ' // cname // ': the window ' // &
                    trim(curve_window_column(i)) // ' in [' // format_real(curve_window_min(i)) // &
                    ', ' // format_real(curve_window_max(i)) // '] holds no row of ' // file // &
                    ' (its ' // trim(curve_window_column(i)) // ' runs from ' // &
                    format_real(minval(csv%values(:, cwin))) // ' to ' // &
                    format_real(maxval(csv%values(:, cwin))) // ')'
          return
        end if
      else if (.not. same_value(curve_window_min(i), unset) .or. &
               .not. same_value(curve_window_max(i), unset)) then
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
      c%turns = branch_turns(csv%values(:, cx), c%branch, csv%lines, trim(curve_x(i)), &
                             trim(curve_file(i)))
      c%branch = pack(c%branch, keep)
      c%x = pack(csv%values(:, cx), keep)
      c%y = pack(csv%values(:, cy), keep)
      if (curve_weight_column(i) /= '') then
        cw = find_column(csv, curve_weight_column(i), 'curve_weight_column', cname)
        if (len_trim(message) > 0) return
        c%w = pack(csv%values(:, cw), keep)
        if (any(c%w < 0.0_dp) .or. any(c%w > max_weight)) then
          message = prefix // 'curve ' // cname // ': the weight column ' // &
                    trim(curve_weight_column(i)) // ' has values outside [0, ' // &
                    format_real(max_weight) // '] (admissible 0 <= weight <= ' // &
                    format_real(max_weight) // ')'
          return
        end if
        if (all(c%w <= 0.0_dp)) then
          message = prefix // 'curve ' // cname // ': every weight in the column ' // &
                    trim(curve_weight_column(i)) // ' is 0 (the curve would not count)'
          return
        end if
      else
        allocate (c%w(size(c%x)))
        c%w = 1.0_dp
      end if
      if (.not. same_value(curve_weight(i), unset)) then
        if (.not. (curve_weight(i) >= min_weight .and. curve_weight(i) <= max_weight)) then
          message = prefix // 'curve ' // cname // ': curve_weight = ' // &
                    format_real(curve_weight(i)) // ' is inadmissible: admissible ' // &
                    format_real(min_weight) // ' <= curve_weight <= ' // format_real(max_weight)
          return
        end if
        c%w = c%w * curve_weight(i)
      else
        scale = maxval(abs(c%y))
        if (scale <= 0.0_dp) then
          message = prefix // 'curve ' // cname // ': every value of ' // trim(curve_y(i)) // &
                    ' in ' // file // ' is 0: the default weight 1/max|y|^2 needs one that is ' // &
                    'not (the wrong column? If a curve of zeros is meant, give curve_weight)'
          return
        end if
        if (scale < sqrt(min_weight)) then
          message = prefix // 'curve ' // cname // ': every value of ' // trim(curve_y(i)) // &
                    ' is below ' // format_real(sqrt(min_weight)) // ' in magnitude: the ' // &
                    'default weight 1/max|y|^2 would exceed ' // format_real(max_weight) // &
                    ' (give curve_weight, or the values in another unit)'
          return
        end if
        c%w = c%w * (1.0_dp / scale)**2
      end if
      fd%curves(i) = c
    end subroutine read_curve

    !> The history output `name` (curve_along or curve_against of the curve being read) among
    !> those of the deck's dimension; 0 and a message naming the admissible ones otherwise.
    integer function output_for_deck(name, variable, cname)
      character(len=*), intent(in) :: name, variable, cname
      character(len=:), allocatable :: dimension, lead, derived
      output_for_deck = output_index(name)
      dimension = merge('3D', '2D', fd%deck%n_components == 3)
      lead = prefix // 'curve ' // cname // ': ' // variable // ' = ''' // &
             trim(name) // ''''
      if (output_for_deck == 0) then
        message = lead // ' is no history output; the outputs of this ' // dimension // &
                  ' deck: ' // deck_outputs(fd%deck)
      else if (.not. output_in_deck(output_for_deck, fd%deck)) then
        if (fd%deck%n_components == 3) then
          derived = 'slip_length (the slip path''s length)'
          if (output_for_deck == out_traction_t) derived = 'traction_t_magnitude (|sigma_T|)'
          message = lead // ' is ambiguous in a 3D deck: name the component (' // &
                    trim(output_names(output_for_deck)) // '1 or ' // &
                    trim(output_names(output_for_deck)) // '2), or ' // derived // &
                    '; the outputs of this 3D deck: ' // deck_outputs(fd%deck)
        else
          message = lead // ' is an output of 3D decks only (this deck is 2D: no T2 loading, ' // &
                    'path, azimuths or azimuthal RIA, docs/deck-format.md); the outputs of ' // &
                    'this 2D deck: ' // deck_outputs(fd%deck)
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

    subroutine parse_list(text, names, variable, indices)
      character(len=*), intent(in) :: text, names(:), variable
      integer, allocatable, intent(out) :: indices(:)
      integer :: a, b, j
      character(len=name_len) :: item
      allocate (indices(0))
      a = 1
      do while (a <= len_trim(text))
        b = index(text(a:), ',')
        if (b == 0) then
          b = len_trim(text) + 1
        else
          b = a + b - 1
        end if
        item = to_lower(adjustl(text(a:b - 1)))
        if (item == '') then
          message = prefix // variable // ' = ''' // trim(text) // ''': an empty item'
          return
        end if
        do j = 1, size(names)
          if (trim(to_lower(names(j))) == trim(item)) exit
        end do
        if (j > size(names)) then
          message = prefix // variable // ': ''' // trim(item) // ''' is none of ' // join(names)
          return
        end if
        indices = [indices, j]
        a = b + 1
      end do
    end subroutine parse_list

  end subroutine read_fit_deck

  !> The magnitudes of theta_0 and theta_f at `values` (a free parameter's value, else the
  !> deck's: the smallest |theta_0| of its planes), their indices among the parameters (0: not
  !> free), and whether theta_f applies (freed or given by the deck; otherwise it follows
  !> theta_0: no wear).
  pure subroutine law_angles(fit, values, it0, itf, theta0, thetaf, relevant)
    type(fit_t), intent(in) :: fit
    real(dp), intent(in) :: values(:)
    integer, intent(out) :: it0, itf
    real(dp), intent(out) :: theta0, thetaf
    logical, intent(out) :: relevant
    integer :: np
    it0 = findloc(fit%property, prop_theta0, dim=1)
    itf = findloc(fit%property, prop_thetaf, dim=1)
    np = 1
    if (.not. fit%deck%paper_ria) np = fit%deck%n_planes
    if (it0 > 0) then
      theta0 = values(it0)
    else
      theta0 = minval(abs(fit%deck%theta0_deg(1:np)))
    end if
    relevant = itf > 0 .or. fit%deck%thetaf_given
    thetaf = 0.0_dp
    if (itf > 0) then
      thetaf = values(itf)
    else if (relevant) then
      thetaf = maxval(abs(fit%deck%thetaf_deg(1:np)))
    end if
  end subroutine law_angles

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

  !> The folder part of `path` with its final '/' ('' for a bare file name).
  function folder_of(path) result(folder)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: folder
    integer :: slash
    slash = index(path, '/', back=.true.)
    folder = path(1:slash)
  end function folder_of

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

  function fittable_names() result(text)
    character(len=:), allocatable :: text
    character(len=len(properties(1)%name)) :: names(prop_zeta0 - prop_sigma0_n + 1)
    names = properties(prop_sigma0_n:prop_zeta0)%name   ! a component of an array: not contiguous
    text = join(names)
  end function fittable_names

end module interlock_fit_deck
