!> The loading groups of a deck: &loading (the control of each component, the points, the steps
!> of each segment and the cycles) and &sweep.
submodule (interlock_deck) interlock_deck_loading
  implicit none

contains

  module procedure read_loading
    character(len=32) :: normal_control, tangential_control, t2_control, path
    real(dp), allocatable :: times(:), normal(:), tangential(:), t2(:)
    integer, allocatable :: steps(:)
    integer :: cycles, ios, n, ns, i, c, m, k, nc
    integer(kind=8) :: total
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    real(dp) :: period, angle_deg, length, side, radius, turns
    logical :: three_d
    namelist /loading/ normal_control, tangential_control, times, normal, tangential, steps, cycles, &
      t2_control, t2, path, angle_deg, length, side, radius, turns
    allocate (times(max_points), normal(max_points), tangential(max_points), steps(max_points), &
              t2(max_points))
    normal_control = ''
    tangential_control = ''
    t2_control = ''
    path = ''
    times = unset
    normal = unset
    tangential = unset
    t2 = unset
    steps = unset_int
    cycles = 1
    angle_deg = unset
    length = unset
    side = unset
    radius = unset
    turns = unset
    message = ''
    read (u, nml=loading, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'loading', scan%a(kp))
        read (probe, nml=loading, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(4, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    if (len_trim(path) > 0) then
      call read_path()
      return
    end if
    if (any([is_given(angle_deg), is_given(length), is_given(side), is_given(radius), &
             is_given(turns)])) then
      message = 'angle_deg, length, side, radius and turns describe a path: give path = ' // &
                "'straight', 'square' or 'circle' (or the points: times, normal, tangential, t2)"
      return
    end if
    ! T2 loading: a 3D case (SPEC section 9); a 3D RIA (azimuths) without it: s_T2 = 0.
    three_d = len_trim(t2_control) > 0 .or. count_given(t2) > 0
    call parse_control(normal_control, 'normal_control', deck%control%traction(1), message)
    if (len_trim(message) > 0) return
    call parse_control(tangential_control, 'tangential_control', deck%control%traction(2), message)
    if (len_trim(message) > 0) return
    if (.not. three_d .and. deck%n_components == 3) then
      three_d = .true.
      t2_control = 'separation'
      t2(1:max(count_given(times), 1)) = 0.0_dp
    end if
    if (three_d) then
      if (len_trim(t2_control) == 0) then
        message = "t2_control is required with t2: admissible 'traction' or 'separation'"
        return
      end if
      call parse_control(t2_control, 't2_control', deck%control%traction(3), message)
      if (len_trim(message) > 0) return
      if (has_gaps(t2)) then
        message = 'times, normal, tangential and t2 must be given from the first point on, ' // &
                  'without gaps'
        return
      end if
    end if
    if (has_gaps(times) .or. has_gaps(normal) .or. has_gaps(tangential)) then
      message = 'times, normal and tangential must be given from the first point on, without gaps'
      return
    end if
    n = count_given(times)
    if (n < 2) then
      message = 'times has ' // format_integer(n) // ' values: a history needs at least 2 points ' // &
                '(an empty history has nothing to compute)'
      return
    end if
    if (count_given(normal) /= n .or. count_given(tangential) /= n) then
      message = 'times, normal and tangential must have the same number of values (given: ' // &
                format_integer(n) // ', ' // format_integer(count_given(normal)) // ', ' // &
                format_integer(count_given(tangential)) // ')'
      return
    end if
    if (three_d .and. count_given(t2) /= n) then
      message = 't2 must have one value per point, as times (given: ' // format_integer(n) // &
                ' times and ' // format_integer(count_given(t2)) // ' values of t2)'
      return
    end if
    if (.not. three_d) t2(1:n) = 0.0_dp
    do i = 1, n
      if (.not. (ieee_is_finite(times(i)) .and. ieee_is_finite(normal(i)) .and. &
                 ieee_is_finite(tangential(i)))) then
        message = 'point ' // format_integer(i) // ': times, normal and tangential must be finite ' // &
                  'numbers (NaN or Inf given)'
        return
      end if
      if (abs(normal(i)) > 1.0e12_dp .or. abs(tangential(i)) > 1.0e12_dp .or. &
          abs(times(i)) > 1.0e12_dp) then
        message = 'point ' // format_integer(i) // ': admissible |times|, |normal|, |tangential| ' // &
                  '<= 1e12 [mm or MPa]'
        return
      end if
      if (.not. ieee_is_finite(t2(i)) .or. abs(t2(i)) > 1.0e12_dp) then
        message = 'point ' // format_integer(i) // ': t2 = ' // value_str(t2(i)) // &
                  ' is inadmissible: admissible a finite |t2| <= 1e12 [mm or MPa]'
        return
      end if
      if (i > 1) then
        if (.not. (times(i) > times(i - 1))) then
          message = 'times must be strictly increasing: times(' // format_integer(i) // ') = ' // &
                    value_str(times(i)) // ' <= times(' // format_integer(i - 1) // ') = ' // &
                    value_str(times(i - 1))
          return
        end if
      end if
    end do
    call check_steps(n - 1)
    if (len_trim(message) > 0) return
    ! Expand the cycles: cycle c > 1 goes on from the block's last point through points 2..n.
    nc = merge(3, 2, three_d)
    m = n + (cycles - 1) * (n - 1)
    allocate (deck%times(m), deck%values(nc, m), deck%steps(m - 1))
    period = times(n) - times(1)
    deck%times(1:n) = times(1:n)
    deck%values(1, 1:n) = normal(1:n)
    deck%values(2, 1:n) = tangential(1:n)
    if (three_d) deck%values(3, 1:n) = t2(1:n)
    deck%steps(1:n - 1) = steps(1:n - 1)
    k = n
    do c = 2, cycles
      do i = 2, n
        k = k + 1
        deck%times(k) = times(i) + real(c - 1, dp) * period
        if (three_d) then
          deck%values(:, k) = [normal(i), tangential(i), t2(i)]
        else
          deck%values(:, k) = [normal(i), tangential(i)]
        end if
        deck%steps(k - 1) = steps(i - 1)
      end do
    end do
    do k = 2, m
      if (.not. deck%times(k) > deck%times(k - 1)) then
        message = 'cycles: the times of the repeated block are not increasing (round-off): ' // &
                  'use fewer cycles or a longer block'
        return
      end if
    end do
    deck%cycles = cycles
    deck%n_steps = int(total)
    if (three_d) deck%n_components = 3

  contains

    !> steps: one value >= 1 per segment (n_segments), cycles in range, the total bounded.
    subroutine check_steps(n_segments)
      integer, intent(in) :: n_segments
      ns = count(steps /= unset_int)
      if (ns /= n_segments .or. any(steps(1:max(ns, 0)) == unset_int)) then
        message = 'steps must give one value per segment: ' // format_integer(n_segments) // &
                  ' values for ' // format_integer(n_segments + 1) // ' points (given: ' // &
                  format_integer(ns) // ')'
        return
      end if
      do i = 1, n_segments
        if (steps(i) < 1) then
          message = 'steps(' // format_integer(i) // ') = ' // format_integer(steps(i)) // &
                    ' is inadmissible: admissible steps >= 1'
          return
        end if
      end do
      if (cycles < 1 .or. cycles > max_cycles) then
        message = 'cycles = ' // format_integer(cycles) // ' is inadmissible: admissible 1 <= ' // &
                  'cycles <= ' // format_integer(max_cycles)
        return
      end if
      total = int(cycles, 8) * sum(int(steps(1:n_segments), 8))
      if (total > max_total_steps) then
        message = 'the history has ' // trim(int8_text(total)) // ' steps: admissible at most ' // &
                  format_integer(max_total_steps) // ' (steps summed over the segments, times cycles)'
        return
      end if
    end subroutine check_steps

    !> A path in the (T1, T2) plane (a 3D case): the normal component preloaded to its one value
    !> at zero slip, then held along the path; the slip components separation-driven.
    subroutine read_path()
      character(len=:), allocatable :: kind, size_name
      real(dp) :: size_mm
      integer :: n_legs
      kind = lower(trim(adjustl(path)))
      select case (kind)
      case ('straight')
        n_legs = 1
        size_name = 'length'
        size_mm = length
      case ('square')
        n_legs = 4
        size_name = 'side'
        size_mm = side
      case ('circle')
        n_legs = 2
        size_name = 'radius'
        size_mm = radius
      case default
        message = "path = '" // trim(path) // "' is inadmissible: admissible 'straight', " // &
                  "'square' or 'circle'"
        return
      end select
      if (count_given(times) > 0 .or. count_given(tangential) > 0 .or. count_given(t2) > 0) then
        message = "with path = '" // kind // "' the points follow from the path: give normal " // &
                  '(one value) and the path''s size, not times, tangential or t2'
        return
      end if
      call parse_control(normal_control, 'normal_control', deck%control%traction(1), message)
      if (len_trim(message) > 0) return
      deck%control%traction(2:3) = .false.
      if (len_trim(tangential_control) > 0 .or. len_trim(t2_control) > 0) then
        if (lower(trim(adjustl(tangential_control))) /= 'separation' .and. &
            len_trim(tangential_control) > 0 .or. &
            lower(trim(adjustl(t2_control))) /= 'separation' .and. len_trim(t2_control) > 0) then
          message = "with path = '" // kind // "' the slip follows the path: tangential_control " // &
                    "and t2_control are 'separation' (or absent)"
          return
        end if
      end if
      if (count_given(normal) /= 1) then
        message = "with path = '" // kind // "' give normal = one value (sigma_N [MPa] or s_N " // &
                  '[mm], applied at zero slip in the first segment and then held; given: ' // &
                  format_integer(count_given(normal)) // ' values)'
        return
      end if
      if (.not. ieee_is_finite(normal(1)) .or. abs(normal(1)) > 1.0e12_dp) then
        message = 'normal = ' // value_str(normal(1)) // ' is inadmissible: admissible a finite ' // &
                  '|normal| <= 1e12 [MPa or mm]'
        return
      end if
      if (is_given(length) .and. kind /= 'straight' .or. is_given(side) .and. kind /= 'square' .or. &
          (is_given(radius) .or. is_given(turns)) .and. kind /= 'circle') then
        message = "with path = '" // kind // "' give " // size_name // &
                  merge(' and turns', '          ', kind == 'circle') // &
                  ' (length: straight, side: square, radius and turns: circle)'
        message = trim(message)
        return
      end if
      if (.not. is_given(size_mm)) then
        message = size_name // " is required with path = '" // kind // "' [mm]"
        return
      end if
      if (.not. (ieee_is_finite(size_mm) .and. size_mm > 0.0_dp .and. size_mm <= 1.0e6_dp)) then
        message = size_name // ' = ' // value_str(size_mm) // ' is inadmissible: admissible ' // &
                  '0 < ' // size_name // ' <= 1e6 [mm]'
        return
      end if
      if (kind == 'circle') then
        if (.not. is_given(turns)) turns = 1.0_dp
        if (.not. (ieee_is_finite(turns) .and. turns > 0.0_dp .and. turns <= 1.0e4_dp)) then
          message = 'turns = ' // value_str(turns) // ' is inadmissible: admissible 0 < turns ' // &
                    '<= 1e4 (counter-clockwise turns about the origin)'
          return
        end if
      else
        turns = 1.0_dp
      end if
      if (.not. is_given(angle_deg)) angle_deg = 0.0_dp
      if (.not. (ieee_is_finite(angle_deg) .and. abs(angle_deg) <= 360.0_dp)) then
        message = 'angle_deg = ' // value_str(angle_deg) // ' is inadmissible: admissible ' // &
                  '-360 <= angle_deg <= 360 [deg]'
        return
      end if
      if (cycles /= 1) then
        message = "cycles = " // format_integer(cycles) // " is inadmissible with path = '" // &
                  kind // "': admissible cycles = 1 (a circle takes turns)"
        return
      end if
      ns = count(steps /= unset_int)
      if (ns /= n_legs + 1) then
        message = "with path = '" // kind // "' steps gives " // format_integer(n_legs + 1) // &
                  ' values: the preload, then ' // trim(merge('the slip      ', &
                  'each leg      ', n_legs == 1)) // ' (given: ' // format_integer(ns) // ')'
        if (kind == 'circle') message = "with path = 'circle' steps gives 3 values: the " // &
          'preload, the leg out to the circle, the turns (given: ' // format_integer(ns) // ')'
        return
      end if
      call check_steps(n_legs + 1)
      if (len_trim(message) > 0) return
      deck%path_kind = kind
      deck%path_angle_deg = angle_deg
      deck%path_size = size_mm
      deck%path_turns = turns
      deck%path_normal = normal(1)
      call path_points(kind, angle_deg, size_mm, turns, normal(1), deck%times, deck%values, &
                       deck%arcs)
      deck%steps = steps(1:n_legs + 1)
      deck%cycles = 1
      deck%n_steps = int(total)
      deck%n_components = 3
    end subroutine read_path

  end procedure read_loading

  module procedure read_sweep
    character(len=name_len) :: parameter
    real(dp), allocatable :: values(:)
    real(dp) :: range(3)
    integer :: ios, n, ip, i
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /sweep/ parameter, values, range
    allocate (values(max_sweep_values))
    parameter = ''
    values = unset
    range = unset
    message = ''
    read (u, nml=sweep, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'sweep', scan%a(kp))
        read (probe, nml=sweep, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(6, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    if (len_trim(parameter) == 0) then
      message = 'parameter is required: the name of a property (see interlock-query)'
      return
    end if
    ip = property_index(lower(trim(adjustl(parameter))))
    if (lower(trim(adjustl(parameter))) == 'angle_deg') then
      ! The direction of the path (a 3D case), not a property.
      if (len_trim(deck%path_kind) == 0) then
        message = "parameter = 'angle_deg' sweeps the direction of a &loading path: give " // &
                  "path = 'straight', 'square' or 'circle' in &loading"
        return
      end if
      ip = sweep_slip_angle
    end if
    if (ip == 0) then
      message = "parameter = '" // trim(parameter) // "' is not a property name of the material table"
      return
    end if
    if (ip == prop_max_dd .or. ip == prop_max_dtheta .or. ip == prop_tangent) then
      message = "parameter = '" // trim(parameter) // "' is a UMAT control: it has no effect " // &
                'in interlock-history'
      return
    end if
    if (ip == prop_ria .or. ip == prop_n_azimuths) then
      ! The RIA of each case: the paper's values on the paper's or the azimuthal RIA (SPEC
      ! section 9), a 3D case.
      if (.not. deck%paper_ria) then
        message = "parameter = '" // trim(parameter) // "' sweeps the RIA of the paper's " // &
                  'values (one theta0_deg, thetaf_deg, zeta0): give no n_planes in &microplanes'
        return
      end if
      if (deck%n_components /= 3) then
        message = "parameter = '" // trim(parameter) // "' sweeps the RIA of a 3D case: give " // &
                  "t2 loading, a path or n_azimuths (this deck is 2D)"
        return
      end if
    end if
    if ((ip == prop_theta0 .or. ip == prop_thetaf) .and. .not. deck%paper_ria) then
      if (.not. all(same_value(abs(deck%theta0_deg(1:deck%n_planes)), &
                               abs(deck%theta0_deg(1))))) then
        message = "parameter = '" // trim(parameter) // "' needs the paper's RIA or planes " // &
                  'of one inclination (+/-)'
        return
      end if
    end if
    if (has_gaps(values)) then
      message = 'values must be given from the first on, without gaps'
      return
    end if
    if (count_given(range) > 0) then
      ! range = first, last, count: count values evenly spaced from first to last.
      if (count_given(values) > 0 .or. count_given(range) /= 3 .or. has_gaps(range)) then
        message = 'range takes three numbers (first, last, number of values) and replaces ' // &
                  'values: give one of them'
        return
      end if
      if (.not. (ieee_is_finite(range(1)) .and. ieee_is_finite(range(2)))) then
        message = 'range: first and last must be finite numbers'
        return
      end if
      if (.not. (range(3) >= 1.0_dp .and. range(3) <= real(max_sweep_values, dp))) then
        message = 'range: the number of values ' // value_str(range(3)) // ' is inadmissible: ' // &
                  'admissible an integer from 1 to ' // format_integer(max_sweep_values)
        return
      end if
      if (.not. same_value(range(3), anint(range(3)))) then
        message = 'range: the number of values ' // value_str(range(3)) // ' is inadmissible: ' // &
                  'admissible an integer from 1 to ' // format_integer(max_sweep_values)
        return
      end if
      n = nint(range(3))
      values(1) = range(1)
      do i = 2, n
        values(i) = range(1) + (range(2) - range(1)) * real(i - 1, dp) / real(n - 1, dp)
      end do
    end if
    n = count_given(values)
    if (n < 1) then
      message = 'values is required: one value per case (at most ' // &
                format_integer(max_sweep_values) // ')'
      return
    end if
    do i = 1, n
      if (ip == sweep_slip_angle) then
        message = ''
        if (.not. (ieee_is_finite(values(i)) .and. abs(values(i)) <= 360.0_dp)) message = &
          'angle_deg = ' // value_str(values(i)) // ' is inadmissible: admissible -360 <= ' // &
          'angle_deg <= 360 [deg]'
      else
        call check_value(ip, values(i), message)
      end if
      if (len_trim(message) > 0) then
        message = 'values(' // format_integer(i) // '): ' // trim(message)
        return
      end if
    end do
    message = ''
    ! (a sweep over n_azimuths is one over the azimuthal RIA)
    if (ip == prop_n_azimuths) deck%rows(prop_ria) = ria_azimuthal
    deck%sweep_parameter = lower(trim(adjustl(parameter)))
    deck%sweep_property = ip
    deck%sweep_values = values(1:n)
  end procedure read_sweep

  subroutine parse_control(text, name, traction, message)
    character(len=*), intent(in) :: text, name
    logical, intent(out) :: traction
    character(len=*), intent(out) :: message
    message = ''
    traction = .false.
    select case (lower(trim(adjustl(text))))
    case ('traction')
      traction = .true.
    case ('separation')
      traction = .false.
    case ('')
      message = name // " is required: admissible 'traction' or 'separation'"
    case default
      message = name // " = '" // trim(text) // "' is inadmissible: admissible 'traction' or " // &
                "'separation'"
    end select
  end subroutine parse_control

end submodule interlock_deck_loading
