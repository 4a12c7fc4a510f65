!> What every reader of a deck group shares: the groups and their variables (what each takes,
!> for messages), the "not given" marks, and the checks and messages of values: a namelist read
!> that failed, a required value, a value out of its range or not finite, plane indices.
module interlock_deck_checks
  use interlock, only: dp, max_planes, max_azimuths, properties, check_property, format_range, format_integer, &
      format_real, is_nan_value, same_value, is_infinite_value, is_finite_bits
  use interlock_deck_text, only: group_scan_t, probe_text, value_text, lower, int8_text
  implicit none
  private
  public :: deck_groups, group_required, var_t, deck_vars, real_list, unset, unset_int
  public :: nml_error, var_index, group_vars, check_plane_indices, is_plane_variable, &
            check_assignments, check_required, check_value, range_message, magnitude_message
  public :: value_str, finite_text, short_real, int8_text, in_range, is_given, count_given, has_gaps

  !> "Not given" marks for namelist variables (a deck cannot mean these values).
  real(dp), parameter :: unset = -huge(1.0_dp)
  integer, parameter :: unset_int = -huge(1)

  character(len=13), parameter :: deck_groups(8) = [character(len=13) :: 'interface', &
    'microplanes', 'effects', 'loading', 'solver', 'sweep', 'initial_state', 'output']
  logical, parameter :: group_required(8) = [.true., .true., .false., .true., .false., .false., &
                                             .false., .false.]
  !> The variables of each group and what each takes (messages name them).
  type :: var_t
    integer :: group
    character(len=24) :: name
    character(len=72) :: what
  end type var_t
  !> The limits the material owns (max_planes, max_azimuths) as text, for the constant texts
  !> of deck_vars: a whole number below 100 as its digits (tens by an exact division; two_digits
  !> fails to compile, by a division by zero, should a limit reach 100).
  integer, parameter :: two_digits = 1 / merge(1, 0, max(max_planes, max_azimuths) < 100)
  integer, parameter :: planes_tens = (max_planes - mod(max_planes, 10)) / 10, &
                        azimuths_tens = (max_azimuths - mod(max_azimuths, 10)) / 10
  character(len=*), parameter :: max_planes_text = &
    repeat(achar(48 + planes_tens), min(two_digits, planes_tens)) // &
    achar(48 + mod(max_planes, 10))
  character(len=*), parameter :: max_azimuths_text = &
    repeat(achar(48 + azimuths_tens), min(two_digits, azimuths_tens)) // &
    achar(48 + mod(max_azimuths, 10))
  character(len=*), parameter :: real_list = &
    'real numbers, one per microplane (at most ' // max_planes_text // ')'
  type(var_t), parameter :: deck_vars(*) = [ &
    var_t(1, 'sigma0_n', 'a real number [MPa]'), var_t(1, 'sigma0_t', 'a real number [MPa]'), &
    var_t(1, 'gc', 'a real number [N/mm]'), var_t(1, 'eta', 'a real number [-]'), &
    var_t(1, 'mu', 'a real number [-]'), var_t(1, 'h_n', 'a real number [mm] (or Inf)'), &
    var_t(1, 'prefractured', 'a logical (.true. or .false.)'), &
    var_t(2, 'theta0_deg', real_list // ' [deg]'), var_t(2, 'thetaf_deg', real_list // ' [deg]'), &
    var_t(2, 'zeta0', real_list // ' [N/mm] (or Inf)'), &
    var_t(2, 'n_planes', 'an integer (1 to ' // max_planes_text // ')'), &
    var_t(2, 'gamma_hat', real_list // ' [-]'), &
    var_t(3, 'damage', 'a logical (.true. or .false.)'), &
    var_t(3, 'friction', 'a logical (.true. or .false.)'), &
    var_t(3, 'interlocking', 'a logical (.true. or .false.)'), &
    var_t(3, 'finite_depth', 'a logical (.true. or .false.)'), &
    var_t(3, 'wear', 'a logical (.true. or .false.)'), &
    var_t(4, 'normal_control', "a quoted string: 'traction' or 'separation'"), &
    var_t(4, 'tangential_control', "a quoted string: 'traction' or 'separation'"), &
    var_t(4, 'times', 'real numbers, one per point (at most 10001)'), &
    var_t(4, 'normal', 'real numbers, one per point (at most 10001) [MPa or mm]'), &
    var_t(4, 'tangential', 'real numbers, one per point (at most 10001) [MPa or mm]'), &
    var_t(4, 'steps', 'integers, one per segment (at most 10000)'), &
    var_t(4, 'cycles', 'an integer (1 to 100000)'), &
    var_t(5, 'scheme', "a quoted string: 'explicit', 'implicit' or 'trapezoidal'"), &
    var_t(5, 'substep_tol', 'a real number [-]'), var_t(5, 'newton_tol', 'a real number [-]'), &
    var_t(5, 'newton_max_iterations', 'an integer (1 to 1000)'), &
    var_t(5, 'max_cuts', 'an integer (0 to 50)'), &
    var_t(5, 'extrapolate', 'a logical (.true. or .false.)'), &
    var_t(6, 'parameter', 'a quoted string: a property name of the material table'), &
    var_t(6, 'values', 'real numbers, one per case (at most 1000)'), &
    var_t(7, 'damage', real_list), var_t(7, 'beta', real_list), &
    var_t(7, 'frictional_slip', real_list // ' [mm]'), var_t(7, 'zeta', real_list // ' [N/mm]'), &
    var_t(7, 'theta', real_list // ' [rad]'), &
    var_t(7, 'friction_traction', real_list // ' [MPa]'), &
    var_t(7, 'separation', 'two real numbers (normal, tangential) [mm]; 3D: three (t2 last)'), &
    var_t(7, 'traction', 'two real numbers (normal, tangential) [MPa]; 3D: three (t2 last)'), &
    var_t(8, 'file', 'a quoted string: a file path (at most 4096 characters)'), &
    var_t(8, 'title', 'a quoted string (at most 1024 characters)'), &
    var_t(8, 'every', 'an integer (1 to 2000000)'), &
    var_t(8, 'store', "a quoted string: 'all', 'curves' or a list of dataset names"), &
    var_t(2, 'n_azimuths', 'an integer (1 to ' // max_azimuths_text // '): the azimuthal RIA'), &
    var_t(2, 'phi_deg', real_list // ' [deg]'), &
    var_t(4, 't2_control', "a quoted string: 'traction' or 'separation'"), &
    var_t(4, 't2', 'real numbers, one per point (at most 10001) [MPa or mm]'), &
    var_t(4, 'path', "a quoted string: 'straight', 'square' or 'circle'"), &
    var_t(4, 'angle_deg', 'a real number [deg]: the path''s direction from t1'), &
    var_t(4, 'length', 'a real number [mm]: the straight path''s length'), &
    var_t(4, 'side', 'a real number [mm]: the square''s side'), &
    var_t(4, 'radius', 'a real number [mm]: the circle''s radius'), &
    var_t(4, 'turns', 'a real number [-]: the circle''s turns'), &
    var_t(6, 'range', 'three real numbers: first value, last value, number of values'), &
    var_t(7, 'sf_strike', real_list // ' [mm]: 3D, strike slip'), &
    var_t(7, 'tauf_strike', real_list // ' [MPa]: 3D, strike friction')]

contains

  !> The message of a failed namelist read: the assignment `k` that fails when read alone
  !> (its variable, value and what the variable takes), or the runtime's message.
  subroutine nml_error(g, text, scan, k, iomsg, probe_msg, message)
    integer, intent(in) :: g, k
    character(len=*), intent(in) :: text, iomsg, probe_msg
    type(group_scan_t), intent(in) :: scan
    character(len=*), intent(out) :: message
    integer :: v
    if (k >= 1 .and. k <= scan%n) then
      v = var_index(g, scan%a(k)%name)
      message = trim(scan%a(k)%name) // trim(scan%a(k)%subscript) // ' = ' // &
                value_text(text, scan%a(k)) // ' cannot be read (line ' // format_integer(scan%a(k)%line) // &
                '): ' // trim(scan%a(k)%name)
      if (v > 0) then
        message = trim(message) // ' takes ' // trim(deck_vars(v)%what)
      end if
      message = trim(message) // ' (Fortran: ' // trim(probe_msg) // ')'
    else
      message = trim(iomsg) // ' (the variables of this group are: ' // group_vars(g) // ')'
    end if
  end subroutine nml_error

  !> Index in deck_vars of variable `name` of group g, 0 if there is none.
  pure integer function var_index(g, name)
    integer, intent(in) :: g
    character(len=*), intent(in) :: name
    integer :: v
    var_index = 0
    do v = 1, size(deck_vars)
      if (deck_vars(v)%group == g .and. trim(deck_vars(v)%name) == trim(name)) then
        var_index = v
        return
      end if
    end do
  end function var_index

  !> "sigma0_n, sigma0_t, ...": the variables of group g.
  pure function group_vars(g) result(text)
    integer, intent(in) :: g
    character(len=:), allocatable :: text
    integer :: v
    text = ''
    do v = 1, size(deck_vars)
      if (deck_vars(v)%group /= g) cycle
      if (len(text) > 0) text = text // ', '
      text = text // trim(deck_vars(v)%name)
    end do
  end function group_vars

  !> An element of a per-plane array, `name(k) = value`, must name a plane: 1 <= k <= n_planes
  !> (the paper's RIA without n_planes: one value in &microplanes, its 3 planes in
  !> &initial_state; the azimuthal RIA's 1 + 2 n_azimuths there), and k <= max_planes in any
  !> case. Checked before the duplicates, so that
  !> `theta0_deg = -10, 10` followed by `theta0_deg(3) = 5` says that plane 3 does not exist.
  subroutine check_plane_indices(g, scan, n_planes, n_azimuths, message)
    integer, intent(in) :: g, n_planes, n_azimuths
    type(group_scan_t), intent(in) :: scan
    character(len=*), intent(out) :: message
    integer :: k, index_value, limit, ios
    character(len=:), allocatable :: sub, why
    message = ''
    why = ''
    do k = 1, scan%n
      sub = trim(scan%a(k)%subscript)
      if (len(sub) < 3) cycle
      if (.not. is_plane_variable(trim(deck_groups(g)), trim(scan%a(k)%name))) cycle
      read (sub(2:len(sub) - 1), *, iostat=ios) index_value
      if (ios /= 0) cycle
      if (n_planes > 0) then
        limit = min(n_planes, max_planes)
        why = 'n_planes = ' // format_integer(n_planes)
      else if (trim(deck_groups(g)) == 'microplanes') then
        limit = 1
        why = 'without n_planes, the paper''s RIA takes one value (give n_planes for a ' // &
              'general RIA)'
      else if (n_azimuths >= 1 .and. n_azimuths <= max_azimuths) then
        limit = 1 + 2 * n_azimuths
        why = 'the azimuthal RIA with n_azimuths = ' // format_integer(n_azimuths) // ' has ' // &
              format_integer(limit) // ' planes'
      else
        limit = 3
        why = 'the paper''s RIA has 3 planes (no n_planes in &microplanes)'
      end if
      if (index_value < 1 .or. index_value > limit) then
        message = trim(scan%a(k)%name) // sub // ' (line ' // format_integer(scan%a(k)%line) // &
                  '): there is no plane ' // format_integer(index_value) // ': admissible ' // &
                  'indices 1..' // format_integer(limit) // ' (' // why // ')'
        return
      end if
    end do
  end subroutine check_plane_indices

  !> The variables that take one value per microplane.
  pure logical function is_plane_variable(group, name)
    character(len=*), intent(in) :: group, name
    select case (group)
    case ('microplanes')
      is_plane_variable = any(name == [character(len=10) :: 'gamma_hat', 'theta0_deg', &
                                       'thetaf_deg', 'zeta0', 'phi_deg'])
    case ('initial_state')
      is_plane_variable = any(name == [character(len=17) :: 'damage', 'beta', 'frictional_slip', &
                                       'zeta', 'theta', 'friction_traction', 'sf_strike', &
                                       'tauf_strike'])
    case default
      is_plane_variable = .false.
    end select
  end function is_plane_variable

  !> Every assignment of group g names a variable of the group, and none is given twice.
  subroutine check_assignments(g, scan, message)
    integer, intent(in) :: g
    type(group_scan_t), intent(in) :: scan
    character(len=*), intent(out) :: message
    integer :: k, j
    message = ''
    do k = 1, scan%n
      if (var_index(g, scan%a(k)%name) == 0) then
        message = 'unknown variable ' // trim(scan%a(k)%name) // ' (line ' // &
                  format_integer(scan%a(k)%line) // '; the variables of this group are: ' // &
                  group_vars(g) // ')'
        return
      end if
      do j = 1, k - 1
        if (scan%a(j)%name /= scan%a(k)%name) cycle
        if (len_trim(scan%a(j)%subscript) > 0 .and. len_trim(scan%a(k)%subscript) > 0 .and. &
            scan%a(j)%subscript /= scan%a(k)%subscript) cycle
        message = trim(scan%a(k)%name) // trim(scan%a(k)%subscript) // &
                  ' is given more than once (lines ' // format_integer(scan%a(j)%line) // ' and ' // &
                  format_integer(scan%a(k)%line) // '): give each variable once'
        return
      end do
    end do
  end subroutine check_assignments

  !> A required real: given, and inside its table range.
  subroutine check_required(iprop, value, message)
    integer, intent(in) :: iprop
    real(dp), intent(in) :: value
    character(len=*), intent(out) :: message
    message = ''
    if (.not. is_nan_value(value)) then
      if (same_value(value, unset)) then
        message = trim(properties(iprop)%name) // ' is required (admissible ' // &
                  format_range(iprop) // ')'
        return
      end if
    end if
    call check_value(iprop, value, message)
  end subroutine check_required

  !> A real for messages: 'NaN', '+Inf', '-Inf', or the shortest text that reads back as x.
  function value_str(x) result(text)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: text
    if (is_nan_value(x)) then
      text = 'NaN'
    else if (abs(x) > huge(1.0_dp)) then
      text = merge('+Inf', '-Inf', x > 0.0_dp)
    else if (abs(x) >= 1.0e30_dp) then
      text = finite_text(x)
    else
      text = short_real(x)
    end if
  end function value_str

  !> x (finite, nonzero) in the shortest scientific notation that reads back as x: '1e+200',
  !> '2.5e-07'.
  function finite_text(x) result(text)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=40) :: buf
    real(dp) :: back
    integer :: digits, ios, e
    character(len=:), allocatable :: mantissa, exponent
    do digits = 1, 17
      write (buf, '(es30.' // format_integer(max(digits - 1, 1)) // 'e3)') x
      read (buf, *, iostat=ios) back
      if (ios == 0) then
        if (same_value(back, x)) exit
      end if
    end do
    buf = adjustl(buf)
    e = index(buf, 'E')
    mantissa = buf(1:e - 1)
    exponent = trim(buf(e + 1:))
    if (index(mantissa, '.') > 0) then
      do while (mantissa(len(mantissa):len(mantissa)) == '0')
        mantissa = mantissa(1:len(mantissa) - 1)
      end do
      if (mantissa(len(mantissa):len(mantissa)) == '.') mantissa = mantissa(1:len(mantissa) - 1)
    end if
    do while (len(exponent) > 3 .and. exponent(2:2) == '0')
      exponent = exponent(1:1) // exponent(3:)
    end do
    text = mantissa // 'e' // exponent
  end function finite_text

  !> '' if `value` is admissible for property ip, else the message (the value as written).
  subroutine check_value(ip, value, message)
    integer, intent(in) :: ip
    real(dp), intent(in) :: value
    character(len=*), intent(out) :: message
    logical :: ok
    call check_property(ip, value, ok, message)
    message = ''
    if (ok) return
    message = "property '" // trim(properties(ip)%name) // "' = " // value_str(value) // &
              ' is inadmissible: admissible ' // format_range(ip)
    if (.not. properties(ip)%infinite_ok .and. is_infinite_value(value) .and. &
        abs(value) <= huge(1.0_dp)) then
      message = trim(message) // ' (values >= 1e30 mean infinity, which ' // &
                trim(properties(ip)%name) // ' does not admit)'
    end if
  end subroutine check_value

  !> The shortest decimal text that reads back as x (labels: '0.5', '1e+04', 'inf').
  function short_real(x) result(text)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=40) :: buf
    real(dp) :: back
    integer :: digits, ios
    if (is_infinite_value(x)) then
      text = 'inf'
      return
    end if
    if (is_nan_value(x)) then
      text = 'NaN'
      return
    end if
    if (same_value(x, 0.0_dp)) then
      text = '0'
      return
    end if
    do digits = 1, 17
      write (buf, '(g0.' // format_integer(digits) // ')') x
      read (buf, *, iostat=ios) back
      if (ios == 0) then
        if (same_value(back, x)) exit
      end if
    end do
    text = finite_text(x)
    if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e5_dp) then
      write (buf, '(f0.' // format_integer(max(digits - 1 - floor(log10(abs(x))), 0)) // ')') x
      text = trim(adjustl(buf))
      if (index(text, '.') > 0) then
        do while (text(len(text):len(text)) == '0')
          text = text(1:len(text) - 1)
        end do
        if (text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
      end if
      if (text(1:1) == '.') text = '0' // text
      if (text(1:2) == '-.') text = '-0' // text(2:)
    end if
  end function short_real

  !> lo <= x <= hi, false for NaN (tested first).
  !> '' or the message for the first given value of `x` outside [lo, hi] (with open_ends, outside
  !> (lo, hi)); `admissible` states the range in the message.
  function range_message(name, x, lo, hi, admissible, open_ends) result(message)
    character(len=*), intent(in) :: name, admissible
    real(dp), intent(in) :: x(:), lo, hi
    logical, intent(in), optional :: open_ends
    character(len=:), allocatable :: message
    logical :: open
    integer :: k
    open = .false.
    if (present(open_ends)) open = open_ends
    message = ''
    do k = 1, count_given(x)
      if (.not. in_range(x(k), lo, hi) .or. &
          (open .and. (same_value(x(k), lo) .or. same_value(x(k), hi)))) then
        message = name // '(' // format_integer(k) // ') = ' // value_str(x(k)) // &
                  ' is inadmissible: admissible ' // admissible
        return
      end if
    end do
  end function range_message

  !> '' when every given value of an &initial_state array is finite and |x| <= 1e12, else the
  !> message naming the first one that is not (a finite value beyond as out of range).
  function magnitude_message(name, unit, x) result(message)
    character(len=*), intent(in) :: name, unit
    real(dp), intent(in) :: x(:)
    character(len=:), allocatable :: message
    integer :: k
    message = ''
    do k = 1, count_given(x)
      if (.not. in_range(x(k), -1.0e12_dp, 1.0e12_dp)) then
        message = name // '(' // format_integer(k) // ') = ' // value_str(x(k))
        if (.not. is_finite_bits(x(k))) then
          message = message // ' is not a finite number [' // unit // ']'
        else
          message = message // ' is inadmissible: admissible |' // name // '| <= 1e12 [' // &
                    unit // ']'
        end if
        return
      end if
    end do
  end function magnitude_message

  elemental logical function in_range(x, lo, hi)
    real(dp), intent(in) :: x, lo, hi
    in_range = .false.
    if (is_nan_value(x)) return
    in_range = x >= lo .and. x <= hi
  end function in_range

  elemental logical function is_given(x)
    real(dp), intent(in) :: x
    is_given = .true.
    if (is_nan_value(x)) return
    is_given = .not. same_value(x, unset)
  end function is_given

  !> Index of the last given entry.
  pure integer function count_given(a)
    real(dp), intent(in) :: a(:)
    integer :: i
    count_given = 0
    do i = size(a), 1, -1
      if (is_given(a(i))) then
        count_given = i
        return
      end if
    end do
  end function count_given

  pure logical function has_gaps(a)
    real(dp), intent(in) :: a(:)
    has_gaps = .not. all(is_given(a(1:count_given(a))))
  end function has_gaps

end module interlock_deck_checks
