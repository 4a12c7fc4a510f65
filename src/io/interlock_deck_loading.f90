!> The loading groups of a deck: &loading (the control of each component, the points, the steps
!> of each segment and the cycles) and &sweep.
submodule (interlock_deck) interlock_deck_loading
  implicit none

contains

  module procedure read_loading
    character(len=32) :: normal_control, tangential_control
    real(dp), allocatable :: times(:), normal(:), tangential(:)
    integer, allocatable :: steps(:)
    integer :: cycles, ios, n, ns, i, c, m, k
    integer(kind=8) :: total
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    real(dp) :: period
    namelist /loading/ normal_control, tangential_control, times, normal, tangential, steps, cycles
    allocate (times(max_points), normal(max_points), tangential(max_points), steps(max_points))
    normal_control = ''
    tangential_control = ''
    times = unset
    normal = unset
    tangential = unset
    steps = unset_int
    cycles = 1
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
    call parse_control(normal_control, 'normal_control', deck%control%traction(1), message)
    if (len_trim(message) > 0) return
    call parse_control(tangential_control, 'tangential_control', deck%control%traction(2), message)
    if (len_trim(message) > 0) return
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
      if (i > 1) then
        if (.not. (times(i) > times(i - 1))) then
          message = 'times must be strictly increasing: times(' // format_integer(i) // ') = ' // &
                    value_str(times(i)) // ' <= times(' // format_integer(i - 1) // ') = ' // &
                    value_str(times(i - 1))
          return
        end if
      end if
    end do
    ns = count(steps /= unset_int)
    if (ns /= n - 1 .or. any(steps(1:max(ns, 0)) == unset_int)) then
      message = 'steps must give one value per segment: ' // format_integer(n - 1) // ' values for ' // &
                format_integer(n) // ' points (given: ' // format_integer(ns) // ')'
      return
    end if
    do i = 1, n - 1
      if (steps(i) < 1) then
        message = 'steps(' // format_integer(i) // ') = ' // format_integer(steps(i)) // &
                  ' is inadmissible: admissible steps >= 1'
        return
      end if
    end do
    if (cycles < 1 .or. cycles > max_cycles) then
      message = 'cycles = ' // format_integer(cycles) // ' is inadmissible: admissible 1 <= cycles <= ' // &
                format_integer(max_cycles)
      return
    end if
    total = int(cycles, 8) * sum(int(steps(1:n - 1), 8))
    if (total > max_total_steps) then
      message = 'the history has ' // trim(int8_text(total)) // ' steps: admissible at most ' // &
                format_integer(max_total_steps) // ' (steps summed over the segments, times cycles)'
      return
    end if
    ! Expand the cycles: cycle c > 1 goes on from the block's last point through points 2..n.
    m = n + (cycles - 1) * (n - 1)
    allocate (deck%times(m), deck%values(2, m), deck%steps(m - 1))
    period = times(n) - times(1)
    deck%times(1:n) = times(1:n)
    deck%values(1, 1:n) = normal(1:n)
    deck%values(2, 1:n) = tangential(1:n)
    deck%steps(1:n - 1) = steps(1:n - 1)
    k = n
    do c = 2, cycles
      do i = 2, n
        k = k + 1
        deck%times(k) = times(i) + real(c - 1, dp) * period
        deck%values(:, k) = [normal(i), tangential(i)]
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
  end procedure read_loading

  module procedure read_sweep
    character(len=name_len) :: parameter
    real(dp), allocatable :: values(:)
    integer :: ios, n, ip, i
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /sweep/ parameter, values
    allocate (values(max_sweep_values))
    parameter = ''
    values = unset
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
    if (ip == 0) then
      message = "parameter = '" // trim(parameter) // "' is not a property name of the material table"
      return
    end if
    if (ip == prop_max_dd .or. ip == prop_max_dtheta .or. ip == prop_tangent) then
      message = "parameter = '" // trim(parameter) // "' is a UMAT control: it has no effect " // &
                'in interlock-history'
      return
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
    n = count_given(values)
    if (n < 1) then
      message = 'values is required: one value per case (at most ' // &
                format_integer(max_sweep_values) // ')'
      return
    end if
    do i = 1, n
      call check_value(ip, values(i), message)
      if (len_trim(message) > 0) then
        message = 'values(' // format_integer(i) // '): ' // trim(message)
        return
      end if
    end do
    message = ''
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
