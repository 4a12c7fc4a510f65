!> The input deck of interlock-history (docs/deck-format.md): namelist groups read with
!> iostat/iomsg, validated through the library's material table (check_property,
!> format_range) and interlock_material_prepare. Every error names the deck file, the group,
!> the variable and the admissible range; nothing is ever stopped here (status + message).
!> Before any namelist read the file is checked as text: size, control bytes, the group names
!> (unknown or repeated groups are errors, required groups must be present).
module interlock_deck
  use interlock, only: dp, deg_to_rad, pi, max_planes, n_effects, &
      interlock_material_t, interlock_solver_t, interlock_state_t, interlock_state_init, &
      interlock_material_prepare, interlock_paper_ria, scheme_explicit, scheme_implicit, &
      properties, property_index, check_property, format_range, format_real, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, prop_max_dd, &
      prop_max_dtheta, prop_effect_damage, prop_effect_wear, is_nan_value, same_value, &
      is_infinite_value, &
      status_ok, status_bad_input
  use interlock_mixed_control, only: control_t
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: deck_t, read_deck, deck_case, deck_n_cases, deck_groups
  public :: max_points, max_sweep_values, max_total_steps, max_deck_bytes

  integer, parameter :: max_points = 10001        !< points of one loading block
  integer, parameter :: max_sweep_values = 1000   !< cases of one deck
  integer, parameter :: max_total_steps = 2000000 !< steps of one case (cycles included)
  integer, parameter :: max_deck_bytes = 4 * 1024 * 1024
  integer, parameter :: max_cycles = 100000
  integer, parameter :: name_len = 64, path_len = 4096

  !> "Not given" marks for namelist variables (a deck cannot mean these values).
  real(dp), parameter :: unset = -huge(1.0_dp)
  integer, parameter :: unset_int = -huge(1)

  character(len=13), parameter :: deck_groups(8) = [character(len=13) :: 'interface', &
    'microplanes', 'effects', 'loading', 'solver', 'sweep', 'initial_state', 'output']
  logical, parameter :: group_required(8) = [.true., .true., .false., .true., .false., .false., &
                                             .false., .false.]
  character(len=*), parameter :: vars_interface = 'sigma0_n, sigma0_t, gc, eta, mu, h_n, prefractured'
  character(len=*), parameter :: vars_microplanes = 'theta0_deg, thetaf_deg, zeta0, n_planes, gamma_hat'
  character(len=*), parameter :: vars_effects = 'damage, friction, interlocking, finite_depth, wear'
  character(len=*), parameter :: vars_loading = &
    'normal_control, tangential_control, times, normal, tangential, steps, cycles'
  character(len=*), parameter :: vars_solver = &
    'scheme, substep_tol, newton_tol, newton_max_iterations, max_cuts'
  character(len=*), parameter :: vars_sweep = 'parameter, values'
  character(len=*), parameter :: vars_initial = &
    'damage, beta, frictional_slip, zeta, theta, friction_traction, separation, traction'
  character(len=*), parameter :: vars_output = 'file, title'

  !> A validated deck. The loading block is stored expanded over its cycles.
  type :: deck_t
    character(len=:), allocatable :: path, text, output_file, title
    ! &interface
    real(dp) :: sigma0_n = 0.0_dp, sigma0_t = 0.0_dp, gc = 0.0_dp, eta = 0.0_dp, mu = 0.0_dp
    real(dp) :: h_n = huge(1.0_dp)
    logical :: prefractured = .false.
    ! &microplanes
    logical :: paper_ria = .true.
    logical :: thetaf_given = .false.   !< without thetaf_deg the planes do not wear (theta_f = theta_0)
    integer :: n_planes = 3
    real(dp), dimension(max_planes) :: gamma_hat = 0.0_dp, theta0_deg = 0.0_dp, &
                                       thetaf_deg = 0.0_dp, zeta0 = huge(1.0_dp)
    ! &effects
    logical :: effect(n_effects) = .true.
    ! &loading, expanded over the cycles: points (times(i), values(:, i)), steps per segment
    type(control_t) :: control
    real(dp), allocatable :: times(:), values(:, :)
    integer, allocatable :: steps(:)
    integer :: cycles = 1
    integer :: n_steps = 0
    ! &solver
    type(interlock_solver_t) :: solver
    ! &sweep
    character(len=name_len) :: sweep_parameter = ''
    integer :: sweep_property = 0
    real(dp), allocatable :: sweep_values(:)
    ! &initial_state (unset entries keep the initial state of the material)
    logical :: has_initial_state = .false.
    real(dp), dimension(max_planes) :: init_damage = unset, init_beta = unset, init_sf = unset, &
                                       init_zeta = unset, init_theta = unset, init_tauf = unset
    real(dp) :: init_s(2) = unset, init_sigma(2) = unset
  end type deck_t

contains

  !> Number of cases: one per sweep value, or one.
  pure integer function deck_n_cases(deck)
    type(deck_t), intent(in) :: deck
    deck_n_cases = 1
    if (deck%sweep_property > 0) deck_n_cases = size(deck%sweep_values)
  end function deck_n_cases

  !> Read and validate the deck `path`. stat /= status_ok: `message` says what is wrong, where
  !> (file, group, variable) and what is admissible. Every case is built once to validate it.
  subroutine read_deck(path, deck, stat, message)
    character(len=*), intent(in) :: path
    type(deck_t), intent(out) :: deck
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    logical :: present_groups(size(deck_groups))
    integer :: u, ios, g, icase
    character(len=512) :: iomsg
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: state
    character(len=:), allocatable :: label

    stat = status_bad_input
    message = ''
    deck%path = path
    call load_text(path, deck%text, stat, message)
    if (stat /= status_ok) return
    stat = status_bad_input
    call scan_groups(path, deck%text, present_groups, message)
    if (len_trim(message) > 0) return
    do g = 1, size(deck_groups)
      if (group_required(g) .and. .not. present_groups(g)) then
        message = path // ': the required group &' // trim(deck_groups(g)) // &
                  ' is missing (required groups: &interface, &microplanes, &loading)'
        return
      end if
    end do

    open (newunit=u, file=path, status='old', action='read', form='formatted', &
          access='sequential', iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      message = path // ': cannot open the deck: ' // trim(iomsg)
      return
    end if
    do g = 1, size(deck_groups)
      if (.not. present_groups(g)) cycle
      rewind (u)
      select case (g)
      case (1)
        call read_interface(u, deck, message)
      case (2)
        call read_microplanes(u, deck, message)
      case (3)
        call read_effects(u, deck, message)
      case (4)
        call read_loading(u, deck, message)
      case (5)
        call read_solver(u, deck, message)
      case (6)
        call read_sweep(u, deck, message)
      case (7)
        call read_initial_state(u, deck, message)
      case (8)
        call read_output(u, deck, message)
      end select
      if (len_trim(message) > 0) then
        message = path // ': &' // trim(deck_groups(g)) // ': ' // trim(message)
        close (u)
        return
      end if
    end do
    close (u)
    if (.not. allocated(deck%output_file)) deck%output_file = default_output(path)
    if (.not. allocated(deck%title)) deck%title = ''
    do icase = 1, deck_n_cases(deck)
      call deck_case(deck, icase, mat, solver, state, label, stat, message)
      if (stat /= status_ok) return
    end do
    stat = status_ok
  end subroutine read_deck

  !> The material, solver and initial state of case `icase` (the sweep value applied).
  subroutine deck_case(deck, icase, mat, solver, state, label, stat, message)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    type(interlock_material_t), intent(out) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(interlock_state_t), intent(out) :: state
    character(len=:), allocatable, intent(out) :: label
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    type(deck_t) :: d
    real(dp) :: v
    integer :: ip, n
    character(len=256) :: why

    stat = status_bad_input
    label = ''
    d%sigma0_n = deck%sigma0_n
    d%sigma0_t = deck%sigma0_t
    d%gc = deck%gc
    d%eta = deck%eta
    d%mu = deck%mu
    d%h_n = deck%h_n
    d%prefractured = deck%prefractured
    d%paper_ria = deck%paper_ria
    d%n_planes = deck%n_planes
    d%gamma_hat = deck%gamma_hat
    d%theta0_deg = deck%theta0_deg
    d%thetaf_deg = deck%thetaf_deg
    d%zeta0 = deck%zeta0
    d%effect = deck%effect
    d%solver = deck%solver
    d%thetaf_given = deck%thetaf_given
    ip = deck%sweep_property
    if (ip > 0) then
      v = deck%sweep_values(icase)
      label = trim(deck%sweep_parameter) // ' = ' // short_real(v)
      if (trim(properties(ip)%unit) /= '-') label = label // ' ' // trim(properties(ip)%unit)
      select case (ip)
      case (prop_sigma0_n)
        d%sigma0_n = v
      case (prop_sigma0_t)
        d%sigma0_t = v
      case (prop_gc)
        d%gc = v
      case (prop_eta)
        d%eta = v
      case (prop_mu)
        d%mu = v
      case (prop_h_n)
        d%h_n = v
      case (prop_theta0)
        d%theta0_deg(1) = v
        if (.not. d%paper_ria) d%theta0_deg(1:d%n_planes) = sign(v, deck%theta0_deg(1:d%n_planes))
      case (prop_thetaf)
        d%thetaf_deg(1) = v
        if (.not. d%paper_ria) d%thetaf_deg(1:d%n_planes) = sign(v, deck%theta0_deg(1:d%n_planes))
      case (prop_zeta0)
        d%zeta0 = v
      case (prop_prefractured)
        d%prefractured = v > 0.5_dp
      case (prop_scheme)
        d%solver%scheme = nint(v)
      case (prop_substep_tol)
        d%solver%substep_tol = v
      case (prop_effect_damage:prop_effect_wear)
        d%effect(ip - prop_effect_damage + 1) = v > 0.5_dp
      end select
    end if
    if (.not. d%thetaf_given) d%thetaf_deg = d%theta0_deg

    mat%sigma0_n = d%sigma0_n
    mat%sigma0_t = d%sigma0_t
    mat%gc = d%gc
    mat%eta = d%eta
    mat%mu = d%mu
    mat%h_n = d%h_n
    mat%prefractured = d%prefractured
    mat%effect = d%effect
    if (d%paper_ria) then
      call interlock_paper_ria(mat, d%theta0_deg(1) * deg_to_rad, d%thetaf_deg(1) * deg_to_rad, &
                               d%zeta0(1))
    else
      n = d%n_planes
      mat%n_planes = n
      mat%gamma_hat(1:n) = d%gamma_hat(1:n)
      mat%theta0(1:n) = d%theta0_deg(1:n) * deg_to_rad
      mat%thetaf(1:n) = d%thetaf_deg(1:n) * deg_to_rad
      mat%zeta0(1:n) = d%zeta0(1:n)
    end if
    call interlock_material_prepare(mat, stat, why)
    if (stat /= status_ok) then
      message = deck%path // ': ' // trim(case_text(deck, icase)) // trim(why)
      stat = status_bad_input
      return
    end if
    solver = d%solver

    call interlock_state_init(mat, state)
    n = mat%n_planes
    if (deck%has_initial_state) then
      call apply_initial(deck%init_damage, state%damage, 'damage', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_beta, state%beta, 'beta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_sf, state%sf, 'frictional_slip', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_zeta, state%zeta, 'zeta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_theta, state%theta, 'theta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_tauf, state%tauf, 'friction_traction', why)
      if (len_trim(why) > 0) then
        message = deck%path // ': &initial_state: ' // trim(case_text(deck, icase)) // trim(why)
        stat = status_bad_input
        return
      end if
      if (.not. same_value(deck%init_s(1), unset)) state%s = deck%init_s
      if (.not. same_value(deck%init_sigma(1), unset)) state%sigma = deck%init_sigma
    end if
    stat = status_ok
    message = ''

  contains

    subroutine apply_initial(given, field, name, why)
      real(dp), intent(in) :: given(:)
      real(dp), intent(inout) :: field(:)
      character(len=*), intent(in) :: name
      character(len=*), intent(out) :: why
      integer :: m
      why = ''
      m = count_given(given)
      if (m == 0) return
      if (m /= n) then
        why = name // ' has ' // int_text(m) // ' values: give one per microplane (' // &
              int_text(n) // ')'
        return
      end if
      field(1:n) = given(1:n)
    end subroutine apply_initial

  end subroutine deck_case

  !> "case 3 (h_n = 0.5 mm): " for sweeps, '' otherwise.
  function case_text(deck, icase) result(text)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    character(len=:), allocatable :: text
    text = ''
    if (deck%sweep_property > 0) text = '&sweep case ' // int_text(icase) // ' (' // &
      trim(deck%sweep_parameter) // ' = ' // format_real(deck%sweep_values(icase)) // '): '
  end function case_text

  ! ------------------------------------------------------------------ text checks

  !> The whole file as text (stream read): it must exist, be non-empty, at most
  !> max_deck_bytes long, and hold no control bytes but tab, line feed, carriage return, form feed.
  subroutine load_text(path, text, stat, message)
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: text
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    logical :: exists
    integer :: u, ios, i, c, line
    integer(kind=8) :: nbytes
    character(len=512) :: iomsg

    stat = status_bad_input
    message = ''
    text = ''
    inquire (file=path, exist=exists, size=nbytes)
    if (.not. exists) then
      message = path // ': no such deck file'
      return
    end if
    if (nbytes == 0) then
      message = path // ': the deck is empty'
      return
    end if
    if (nbytes < 0 .or. nbytes > max_deck_bytes) then
      message = path // ': the deck is not a regular file of at most ' // &
                int_text(max_deck_bytes) // ' bytes'
      return
    end if
    deallocate (text)
    allocate (character(len=int(nbytes)) :: text)
    open (newunit=u, file=path, status='old', action='read', access='stream', &
          form='unformatted', iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      message = path // ': cannot open the deck: ' // trim(iomsg)
      return
    end if
    read (u, iostat=ios, iomsg=iomsg) text
    close (u)
    if (ios /= 0) then
      message = path // ': cannot read the deck: ' // trim(iomsg)
      return
    end if
    line = 1
    do i = 1, len(text)
      c = iachar(text(i:i))
      if (c == 10) line = line + 1
      if (c < 32 .and. c /= 9 .and. c /= 10 .and. c /= 13 .and. c /= 12 .or. c == 127) then
        message = path // ': line ' // int_text(line) // ': byte ' // int_text(i) // &
                  ' is a control character (code ' // int_text(c) // &
                  '): the deck must be a text file (a Fortran namelist)'
        return
      end if
    end do
    stat = status_ok
  end subroutine load_text

  !> Find the namelist groups (&name outside comments and strings). Unknown or repeated groups
  !> are errors (message /= '').
  subroutine scan_groups(path, text, found, message)
    character(len=*), intent(in) :: path, text
    logical, intent(out) :: found(:)
    character(len=*), intent(out) :: message
    integer :: i, j, g, line
    logical :: in_comment
    character :: quote, ch
    character(len=64) :: name

    found = .false.
    message = ''
    in_comment = .false.
    quote = ' '
    line = 1
    i = 1
    do while (i <= len(text))
      ch = text(i:i)
      if (ch == achar(10)) then
        line = line + 1
        in_comment = .false.
        quote = ' '
      else if (in_comment) then
        continue
      else if (quote /= ' ') then
        if (ch == quote) quote = ' '
      else if (ch == '!') then
        in_comment = .true.
      else if (ch == '''' .or. ch == '"') then
        quote = ch
      else if (ch == '&' .or. ch == '$') then
        j = i + 1
        do while (j <= len(text))
          if (.not. is_name_char(text(j:j))) exit
          j = j + 1
        end do
        name = lower(text(i + 1:min(j - 1, i + 64)))
        if (name == 'end') then
          continue
        else if (j == i + 1) then
          message = path // ': line ' // int_text(line) // ': a ''' // ch // &
                    ''' that does not start a group name'
          return
        else
          g = group_index(name)
          if (g == 0) then
            message = path // ': line ' // int_text(line) // ': unknown group &' // &
                      trim(name) // ' (the groups are &interface, ' // &
                      '&microplanes, &effects, &loading, &solver, &sweep, &initial_state, &output)'
            return
          end if
          if (found(g)) then
            message = path // ': line ' // int_text(line) // ': the group &' // &
                      trim(deck_groups(g)) // ' appears more than once'
            return
          end if
          found(g) = .true.
        end if
        i = j - 1
      end if
      i = i + 1
    end do
  end subroutine scan_groups

  pure integer function group_index(name)
    character(len=*), intent(in) :: name
    integer :: g
    group_index = 0
    do g = 1, size(deck_groups)
      if (trim(deck_groups(g)) == trim(name)) group_index = g
    end do
  end function group_index

  pure logical function is_name_char(ch)
    character, intent(in) :: ch
    is_name_char = (ch >= 'a' .and. ch <= 'z') .or. (ch >= 'A' .and. ch <= 'Z') .or. &
                   (ch >= '0' .and. ch <= '9') .or. ch == '_'
  end function is_name_char

  pure function lower(s) result(t)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: t
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
    end do
  end function lower

  ! ----------------------------------------------------------------- the groups

  subroutine nml_error(ios, iomsg, variables, message)
    integer, intent(in) :: ios
    character(len=*), intent(in) :: iomsg, variables
    character(len=*), intent(out) :: message
    if (ios < 0) then
      message = 'the group could not be read (end of file before its closing /): ' // trim(iomsg)
    else
      message = trim(iomsg) // ' (the variables of this group are: ' // variables // ')'
    end if
  end subroutine nml_error

  !> A required real: given, and inside its table range.
  subroutine check_required(iprop, value, message)
    integer, intent(in) :: iprop
    real(dp), intent(in) :: value
    character(len=*), intent(out) :: message
    logical :: ok
    message = ''
    if (.not. is_nan_value(value)) then
      if (same_value(value, unset)) then
        message = trim(properties(iprop)%name) // ' is required (admissible ' // &
                  format_range(iprop) // ')'
        return
      end if
    end if
    call check_property(iprop, value, ok, message)
    if (ok) message = ''
  end subroutine check_required

  subroutine read_interface(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    real(dp) :: sigma0_n, sigma0_t, gc, eta, mu, h_n
    logical :: prefractured
    integer :: ios
    character(len=512) :: iomsg
    namelist /interface/ sigma0_n, sigma0_t, gc, eta, mu, h_n, prefractured
    sigma0_n = unset
    sigma0_t = unset
    gc = unset
    eta = unset
    mu = unset
    h_n = huge(1.0_dp)
    prefractured = .false.
    message = ''
    read (u, nml=interface, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_interface, message)
      return
    end if
    call check_required(prop_sigma0_n, sigma0_n, message); if (len_trim(message) > 0) return
    call check_required(prop_sigma0_t, sigma0_t, message); if (len_trim(message) > 0) return
    call check_required(prop_gc, gc, message); if (len_trim(message) > 0) return
    call check_required(prop_eta, eta, message); if (len_trim(message) > 0) return
    call check_required(prop_mu, mu, message); if (len_trim(message) > 0) return
    call check_required(prop_h_n, h_n, message); if (len_trim(message) > 0) return
    deck%sigma0_n = sigma0_n
    deck%sigma0_t = sigma0_t
    deck%gc = gc
    deck%eta = eta
    deck%mu = mu
    deck%h_n = h_n
    deck%prefractured = prefractured
  end subroutine read_interface

  subroutine read_microplanes(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    real(dp), dimension(max_planes) :: theta0_deg, thetaf_deg, zeta0, gamma_hat
    integer :: n_planes, ios, n, k
    character(len=512) :: iomsg
    namelist /microplanes/ theta0_deg, thetaf_deg, zeta0, n_planes, gamma_hat
    theta0_deg = unset
    thetaf_deg = unset
    zeta0 = unset
    gamma_hat = unset
    n_planes = unset_int
    message = ''
    read (u, nml=microplanes, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_microplanes, message)
      return
    end if
    if (has_gaps(theta0_deg) .or. has_gaps(thetaf_deg) .or. has_gaps(zeta0) .or. &
        has_gaps(gamma_hat)) then
      message = 'per-plane values must be given from the first plane on, without gaps'
      return
    end if
    if (n_planes == unset_int) then
      ! The paper's symmetric RIA: one value each.
      deck%paper_ria = .true.
      deck%n_planes = 3
      if (count_given(theta0_deg) /= 1 .or. count_given(thetaf_deg) > 1 .or. &
          count_given(zeta0) > 1 .or. count_given(gamma_hat) > 0) then
        message = 'without n_planes (the paper''s RIA) give one theta0_deg, and at most one ' // &
                  'thetaf_deg and zeta0 (no gamma_hat); for a general RIA give n_planes'
        if (count_given(theta0_deg) == 0) message = 'theta0_deg is required (admissible ' // &
          format_range(prop_theta0) // ')'
        return
      end if
      deck%thetaf_given = count_given(thetaf_deg) > 0
      if (count_given(thetaf_deg) == 0) thetaf_deg(1) = theta0_deg(1)
      if (count_given(zeta0) == 0) zeta0(1) = huge(1.0_dp)
      call check_required(prop_theta0, theta0_deg(1), message); if (len_trim(message) > 0) return
      call check_required(prop_thetaf, thetaf_deg(1), message); if (len_trim(message) > 0) return
      call check_required(prop_zeta0, zeta0(1), message); if (len_trim(message) > 0) return
      if (thetaf_deg(1) > theta0_deg(1)) then
        message = "property 'thetaf_deg' = " // format_real(thetaf_deg(1)) // &
                  ' is inadmissible: admissible 0 <= thetaf_deg <= theta0_deg = ' // &
                  format_real(theta0_deg(1)) // ' [deg]'
        return
      end if
      deck%theta0_deg = 0.0_dp
      deck%thetaf_deg = 0.0_dp
      deck%zeta0 = huge(1.0_dp)
      deck%theta0_deg(1) = theta0_deg(1)
      deck%thetaf_deg(1) = thetaf_deg(1)
      deck%zeta0(1) = zeta0(1)
    else
      deck%paper_ria = .false.
      if (n_planes < 1 .or. n_planes > max_planes) then
        message = 'n_planes = ' // int_text(n_planes) // ' is inadmissible: admissible 1 <= ' // &
                  'n_planes <= ' // int_text(max_planes)
        return
      end if
      n = n_planes
      if (count_given(theta0_deg) /= n .or. count_given(gamma_hat) /= n) then
        message = 'with n_planes = ' // int_text(n) // ' give ' // int_text(n) // &
                  ' values of gamma_hat and of theta0_deg (given: ' // &
                  int_text(count_given(gamma_hat)) // ' and ' // int_text(count_given(theta0_deg)) // ')'
        return
      end if
      deck%thetaf_given = count_given(thetaf_deg) > 0
      if (count_given(thetaf_deg) == 0) thetaf_deg(1:n) = theta0_deg(1:n)
      if (count_given(zeta0) == 0) zeta0(1:n) = huge(1.0_dp)
      if (count_given(thetaf_deg) /= n .or. count_given(zeta0) /= n) then
        message = 'with n_planes = ' // int_text(n) // ' give ' // int_text(n) // &
                  ' values of thetaf_deg and of zeta0, or none'
        return
      end if
      do k = 1, n
        call check_required(prop_theta0, abs(theta0_deg(k)), message)
        if (len_trim(message) > 0) then
          message = 'plane ' // int_text(k) // ': ' // trim(message) // ' (in absolute value)'
          return
        end if
        call check_required(prop_zeta0, zeta0(k), message)
        if (len_trim(message) > 0) then
          message = 'plane ' // int_text(k) // ': ' // trim(message)
          return
        end if
        if (is_nan_value(gamma_hat(k)) .or. is_nan_value(thetaf_deg(k))) then
          message = 'plane ' // int_text(k) // ': gamma_hat and thetaf_deg must be numbers (NaN given)'
          return
        end if
      end do
      deck%n_planes = n
      deck%gamma_hat = 0.0_dp
      deck%theta0_deg = 0.0_dp
      deck%thetaf_deg = 0.0_dp
      deck%zeta0 = huge(1.0_dp)
      deck%gamma_hat(1:n) = gamma_hat(1:n)
      deck%theta0_deg(1:n) = theta0_deg(1:n)
      deck%thetaf_deg(1:n) = thetaf_deg(1:n)
      deck%zeta0(1:n) = zeta0(1:n)
    end if
  end subroutine read_microplanes

  subroutine read_effects(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    logical :: damage, friction, interlocking, finite_depth, wear
    integer :: ios
    character(len=512) :: iomsg
    namelist /effects/ damage, friction, interlocking, finite_depth, wear
    damage = .true.
    friction = .true.
    interlocking = .true.
    finite_depth = .true.
    wear = .true.
    message = ''
    read (u, nml=effects, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_effects, message)
      return
    end if
    deck%effect = [damage, friction, interlocking, finite_depth, wear]
  end subroutine read_effects

  subroutine read_loading(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    character(len=32) :: normal_control, tangential_control
    real(dp), allocatable :: times(:), normal(:), tangential(:)
    integer, allocatable :: steps(:)
    integer :: cycles, ios, n, ns, i, c, m, k
    integer(kind=8) :: total
    character(len=512) :: iomsg
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
      call nml_error(ios, iomsg, vars_loading, message)
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
      message = 'times has ' // int_text(n) // ' values: a history needs at least 2 points ' // &
                '(an empty history has nothing to compute)'
      return
    end if
    if (count_given(normal) /= n .or. count_given(tangential) /= n) then
      message = 'times, normal and tangential must have the same number of values (given: ' // &
                int_text(n) // ', ' // int_text(count_given(normal)) // ', ' // &
                int_text(count_given(tangential)) // ')'
      return
    end if
    do i = 1, n
      if (.not. (ieee_is_finite(times(i)) .and. ieee_is_finite(normal(i)) .and. &
                 ieee_is_finite(tangential(i)))) then
        message = 'point ' // int_text(i) // ': times, normal and tangential must be finite ' // &
                  'numbers (NaN or Inf given)'
        return
      end if
      if (abs(normal(i)) > 1.0e12_dp .or. abs(tangential(i)) > 1.0e12_dp .or. &
          abs(times(i)) > 1.0e12_dp) then
        message = 'point ' // int_text(i) // ': admissible |times|, |normal|, |tangential| ' // &
                  '<= 1e12 [mm or MPa]'
        return
      end if
      if (i > 1) then
        if (.not. (times(i) > times(i - 1))) then
          message = 'times must be strictly increasing: times(' // int_text(i) // ') = ' // &
                    format_real(times(i)) // ' <= times(' // int_text(i - 1) // ') = ' // &
                    format_real(times(i - 1))
          return
        end if
      end if
    end do
    ns = count(steps /= unset_int)
    if (ns /= n - 1 .or. any(steps(1:max(ns, 0)) == unset_int)) then
      message = 'steps must give one value per segment: ' // int_text(n - 1) // ' values for ' // &
                int_text(n) // ' points (given: ' // int_text(ns) // ')'
      return
    end if
    do i = 1, n - 1
      if (steps(i) < 1) then
        message = 'steps(' // int_text(i) // ') = ' // int_text(steps(i)) // &
                  ' is inadmissible: admissible steps >= 1'
        return
      end if
    end do
    if (cycles < 1 .or. cycles > max_cycles) then
      message = 'cycles = ' // int_text(cycles) // ' is inadmissible: admissible 1 <= cycles <= ' // &
                int_text(max_cycles)
      return
    end if
    total = int(cycles, 8) * sum(int(steps(1:n - 1), 8))
    if (total > max_total_steps) then
      message = 'the history has ' // trim(int8_text(total)) // ' steps: admissible at most ' // &
                int_text(max_total_steps) // ' (steps summed over the segments, times cycles)'
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
  end subroutine read_loading

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

  subroutine read_solver(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    character(len=32) :: scheme
    real(dp) :: substep_tol, newton_tol
    integer :: newton_max_iterations, max_cuts, ios
    logical :: ok
    character(len=512) :: iomsg
    namelist /solver/ scheme, substep_tol, newton_tol, newton_max_iterations, max_cuts
    scheme = 'explicit'
    substep_tol = 0.0_dp
    newton_tol = deck%control%tol
    newton_max_iterations = deck%control%max_iterations
    max_cuts = deck%control%max_cuts
    message = ''
    read (u, nml=solver, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_solver, message)
      return
    end if
    select case (lower(trim(adjustl(scheme))))
    case ('explicit')
      deck%solver%scheme = scheme_explicit
    case ('implicit')
      deck%solver%scheme = scheme_implicit
    case default
      message = "scheme = '" // trim(scheme) // "' is inadmissible: admissible 'explicit' or 'implicit'"
      return
    end select
    call check_property(prop_substep_tol, substep_tol, ok, message)
    if (.not. ok) return
    message = ''
    deck%solver%substep_tol = substep_tol
    ok = .false.
    if (.not. is_nan_value(newton_tol)) ok = newton_tol >= 1.0e-16_dp .and. newton_tol <= 1.0e-2_dp
    if (.not. ok) then
      message = 'newton_tol = ' // format_real(newton_tol) // &
                ' is inadmissible: admissible 1e-16 <= newton_tol <= 1e-2 [-]'
      return
    end if
    if (newton_max_iterations < 1 .or. newton_max_iterations > 1000) then
      message = 'newton_max_iterations = ' // int_text(newton_max_iterations) // &
                ' is inadmissible: admissible 1 <= newton_max_iterations <= 1000'
      return
    end if
    if (max_cuts < 0 .or. max_cuts > 50) then
      message = 'max_cuts = ' // int_text(max_cuts) // ' is inadmissible: admissible 0 <= max_cuts <= 50'
      return
    end if
    deck%control%tol = newton_tol
    deck%control%max_iterations = newton_max_iterations
    deck%control%max_cuts = max_cuts
  end subroutine read_solver

  subroutine read_sweep(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    character(len=name_len) :: parameter
    real(dp), allocatable :: values(:)
    integer :: ios, n, ip, i
    logical :: ok
    character(len=512) :: iomsg
    namelist /sweep/ parameter, values
    allocate (values(max_sweep_values))
    parameter = ''
    values = unset
    message = ''
    read (u, nml=sweep, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_sweep, message)
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
    if (ip == prop_max_dd .or. ip == prop_max_dtheta) then
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
                int_text(max_sweep_values) // ')'
      return
    end if
    do i = 1, n
      call check_property(ip, values(i), ok, message)
      if (.not. ok) then
        message = 'values(' // int_text(i) // '): ' // trim(message)
        return
      end if
    end do
    message = ''
    deck%sweep_parameter = lower(trim(adjustl(parameter)))
    deck%sweep_property = ip
    deck%sweep_values = values(1:n)
  end subroutine read_sweep

  subroutine read_initial_state(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    real(dp), dimension(max_planes) :: damage, beta, frictional_slip, zeta, theta, friction_traction
    real(dp) :: separation(2), traction(2)
    integer :: ios, k
    character(len=512) :: iomsg
    namelist /initial_state/ damage, beta, frictional_slip, zeta, theta, friction_traction, &
      separation, traction
    damage = unset
    beta = unset
    frictional_slip = unset
    zeta = unset
    theta = unset
    friction_traction = unset
    separation = unset
    traction = unset
    message = ''
    read (u, nml=initial_state, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_initial, message)
      return
    end if
    if (has_gaps(damage) .or. has_gaps(beta) .or. has_gaps(frictional_slip) .or. has_gaps(zeta) &
        .or. has_gaps(theta) .or. has_gaps(friction_traction)) then
      message = 'per-plane values must be given from the first plane on, without gaps'
      return
    end if
    if (count_given(separation) == 1 .or. count_given(traction) == 1) then
      message = 'separation and traction take two values each (normal, tangential)'
      return
    end if
    do k = 1, count_given(damage)
      if (.not. in_range(damage(k), 0.0_dp, 1.0_dp)) then
        message = 'damage(' // int_text(k) // ') = ' // format_real(damage(k)) // &
                  ' is inadmissible: admissible 0 <= damage <= 1'
        return
      end if
    end do
    do k = 1, count_given(beta)
      if (.not. in_range(beta(k), 0.0_dp, 1.0e12_dp)) then
        message = 'beta(' // int_text(k) // ') = ' // format_real(beta(k)) // &
                  ' is inadmissible: admissible 0 <= beta <= 1e12'
        return
      end if
    end do
    do k = 1, count_given(zeta)
      if (.not. in_range(zeta(k), 0.0_dp, 1.0e30_dp)) then
        message = 'zeta(' // int_text(k) // ') = ' // format_real(zeta(k)) // &
                  ' is inadmissible: admissible 0 <= zeta < 1e30 [N/mm]'
        return
      end if
    end do
    do k = 1, count_given(theta)
      if (.not. in_range(theta(k), -0.5_dp * pi, 0.5_dp * pi) .or. &
          same_value(abs(theta(k)), 0.5_dp * pi)) then
        message = 'theta(' // int_text(k) // ') = ' // format_real(theta(k)) // &
                  ' is inadmissible: admissible -pi/2 < theta < pi/2 [rad]'
        return
      end if
    end do
    do k = 1, count_given(frictional_slip)
      if (.not. in_range(frictional_slip(k), -1.0e12_dp, 1.0e12_dp)) then
        message = 'frictional_slip(' // int_text(k) // ') is not a finite number [mm]'
        return
      end if
    end do
    do k = 1, count_given(friction_traction)
      if (.not. in_range(friction_traction(k), -1.0e12_dp, 1.0e12_dp)) then
        message = 'friction_traction(' // int_text(k) // ') is not a finite number [MPa]'
        return
      end if
    end do
    do k = 1, count_given(separation)
      if (.not. in_range(separation(k), -1.0e12_dp, 1.0e12_dp)) then
        message = 'separation(' // int_text(k) // ') is not a finite number [mm]'
        return
      end if
    end do
    do k = 1, count_given(traction)
      if (.not. in_range(traction(k), -1.0e12_dp, 1.0e12_dp)) then
        message = 'traction(' // int_text(k) // ') is not a finite number [MPa]'
        return
      end if
    end do
    deck%has_initial_state = .true.
    deck%init_damage = damage
    deck%init_beta = beta
    deck%init_sf = frictional_slip
    deck%init_zeta = zeta
    deck%init_theta = theta
    deck%init_tauf = friction_traction
    deck%init_s = separation
    deck%init_sigma = traction
  end subroutine read_initial_state

  subroutine read_output(u, deck, message)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    character(len=path_len) :: file
    character(len=1024) :: title
    integer :: ios
    character(len=512) :: iomsg
    namelist /output/ file, title
    file = ''
    title = ''
    message = ''
    read (u, nml=output, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call nml_error(ios, iomsg, vars_output, message)
      return
    end if
    if (len_trim(file) > 0) deck%output_file = trim(adjustl(file))
    deck%title = trim(title)
  end subroutine read_output

  ! ------------------------------------------------------------------- helpers

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
      write (buf, '(g0.' // int_text(digits) // ')') x
      read (buf, *, iostat=ios) back
      if (ios == 0) then
        if (same_value(back, x)) exit
      end if
    end do
    write (buf, '(es30.' // int_text(max(digits - 1, 1)) // ')') x
    text = trim(adjustl(buf))
    if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e5_dp) then
      write (buf, '(f0.' // int_text(max(digits - 1 - floor(log10(abs(x))), 0)) // ')') x
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

  !> The deck's name with .h5 instead of its extension, in the working folder.
  pure function default_output(path) result(file)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: file
    integer :: slash, dot
    slash = index(path, '/', back=.true.)
    file = path(slash + 1:)
    dot = index(file, '.', back=.true.)
    if (dot > 1) file = file(1:dot - 1)
    if (len(file) == 0) file = 'history'
    file = file // '.h5'
  end function default_output

  !> lo <= x <= hi, false for NaN (tested first).
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

  pure function int_text(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    character(len=16) :: buf
    write (buf, '(i0)') i
    text = trim(buf)
  end function int_text

  pure function int8_text(i) result(text)
    integer(kind=8), intent(in) :: i
    character(len=24) :: text
    write (text, '(i0)') i
  end function int8_text

end module interlock_deck
