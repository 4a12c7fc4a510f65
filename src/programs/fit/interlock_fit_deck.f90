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
  use interlock_fit_curves, only: n_outputs, output_names, output_index, output_in_deck, &
      deck_outputs, join, join_selected, split_branches, branch_turns, out_separation_t, &
      out_traction_t, out_separation_t1, out_separation_t2, out_traction_t1, out_traction_t2, &
      out_traction_t_magnitude, out_slip_length, curve_t, curve_spec_t, read_curve, folder_of, &
      unset, name_len, file_len
  use interlock_lm, only: lm_options_t
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
  implicit none
  private
  public :: fit_t, curve_t, stage_t, read_fit_deck, output_names, n_outputs, fit_groups, &
            split_branches, join_selected, law_angles, folder_of
  public :: out_separation_t, out_traction_t, out_separation_t1, out_separation_t2, &
            out_traction_t1, out_traction_t2, out_traction_t_magnitude, out_slip_length

  integer, parameter :: max_curves = 32, max_free = 16, max_stages = 16
  integer, parameter :: list_len = 1024


  character(len=13), parameter :: fit_groups(9) = [character(len=13) :: deck_groups, 'fit']

  character(len=*), parameter :: fit_vars = 'curve_name, curve_file, curve_x, curve_y, ' // &
    'curve_along, curve_against, curve_weight, curve_weight_column, curve_window_column, ' // &
    'curve_window_min, curve_window_max, parameters, start, lower, upper, stage_parameters, ' // &
    'stage_curves, max_iterations, xtol, ftol, gtol, fd_step'


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
    type(curve_spec_t) :: spec

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
      spec = curve_spec_t(curve_name(i), curve_x(i), curve_y(i), curve_along(i), &
                          curve_against(i), curve_weight_column(i), curve_window_column(i), &
                          curve_file(i), curve_weight(i), curve_window_min(i), curve_window_max(i))
      call read_curve(i, spec, curve_name(1:i - 1), path, prefix, fd%deck, fd%curves(i), message)
      if (len_trim(message) > 0) return
      curve_name(i) = spec%name
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
    np = fit%deck%n_planes
    if (it0 > 0) then
      theta0 = values(it0)
    else if (fit%deck%paper_ria) then
      theta0 = deck_property(fit%deck, prop_theta0)
    else
      theta0 = minval(abs(fit%deck%theta0_deg(1:np)))
    end if
    relevant = itf > 0 .or. fit%deck%thetaf_given
    thetaf = 0.0_dp
    if (itf > 0) then
      thetaf = values(itf)
    else if (relevant .and. fit%deck%paper_ria) then
      thetaf = deck_property(fit%deck, prop_thetaf)
    else if (relevant) then
      thetaf = maxval(abs(fit%deck%thetaf_deg(1:np)))
    end if
  end subroutine law_angles






  function fittable_names() result(text)
    character(len=:), allocatable :: text
    character(len=len(properties(1)%name)) :: names(prop_zeta0 - prop_sigma0_n + 1)
    names = properties(prop_sigma0_n:prop_zeta0)%name   ! a component of an array: not contiguous
    text = join(names)
  end function fittable_names

end module interlock_fit_deck
