!> The input deck of interlock-history (docs/deck-format.md): namelist groups read with
!> iostat/iomsg, validated through the library's material table (check_property,
!> format_range) and interlock_material_prepare. Every error names the deck file, the group,
!> the variable and the admissible range; nothing is ever stopped here (status + message).
!> Before any namelist read the file is checked as text (interlock_deck_text): size, control
!> bytes, line ends, the groups (unknown, repeated, unclosed groups and text outside every group
!> are errors, required groups must be present) and the variables of each group (unknown or
!> repeated variables are errors). A value that cannot be read is found by re-reading each
!> assignment of the group alone, so that the message names the variable.
module interlock_deck
  use interlock, only: dp, deg_to_rad, pi, max_planes, n_effects, &
      interlock_material_t, interlock_solver_t, interlock_state_t, interlock_state_init, &
      interlock_material_prepare, interlock_paper_ria, scheme_explicit, scheme_implicit, &
      scheme_trapezoidal, properties, property_index, check_property, format_range, &
      format_integer, format_real, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, prop_max_dd, &
      prop_max_dtheta, prop_tangent, prop_effect_damage, prop_effect_wear, is_nan_value, same_value, &
      is_infinite_value, &
      status_ok, status_bad_input
  use interlock_mixed_control, only: control_t
  use interlock_files, only: path_kind, path_absent, path_folder, path_other
  use interlock_deck_text, only: group_scan_t, scan_deck, probe_text, value_text, lower
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_get_halting_mode, &
      ieee_set_halting_mode, ieee_overflow, ieee_invalid, ieee_divide_by_zero
  implicit none
  private
  public :: deck_t, read_deck, deck_case, deck_n_cases, deck_groups, deck_set_property
  public :: max_points, max_sweep_values, max_total_steps, max_deck_bytes
  public :: n_datasets, history_datasets, curves_datasets, datasets_text, dataset_index

  integer, parameter :: max_points = 10001        !< points of one loading block
  integer, parameter :: max_sweep_values = 1000   !< cases of one deck
  integer, parameter :: max_total_steps = 2000000 !< steps of one case (cycles included)
  integer, parameter :: max_deck_bytes = 4 * 1024 * 1024
  integer, parameter :: max_cycles = 100000
  integer, parameter :: name_len = 64, path_len = 4096

  !> The datasets of a case (docs/history-output.md), in the order they are written; `&output`
  !> `store` picks among them ('all', 'curves' or a comma-separated list of these names). The
  !> first three (time, separation, traction) are always written.
  integer, parameter :: n_datasets = 15
  character(len=20), parameter :: history_datasets(n_datasets) = [character(len=20) :: 'time', &
    'separation', 'traction', 'damage', 'beta', 'theta', 'zeta', 'frictional_slip', &
    'friction_traction', 'work', 'stored_energy', 'damage_dissipation', &
    'friction_dissipation', 'iterations', 'substeps']
  !> store = 'curves': no per-plane dataset.
  logical, parameter :: curves_datasets(n_datasets) = [.true., .true., .true., .false., &
    .false., .false., .false., .false., .false., .true., .true., .true., .true., .true., .true.]
  integer, parameter :: n_always = 3
  integer, parameter :: store_len = 1024

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
  character(len=*), parameter :: real_list = 'real numbers, one per microplane (at most 8)'
  type(var_t), parameter :: deck_vars(*) = [ &
    var_t(1, 'sigma0_n', 'a real number [MPa]'), var_t(1, 'sigma0_t', 'a real number [MPa]'), &
    var_t(1, 'gc', 'a real number [N/mm]'), var_t(1, 'eta', 'a real number [-]'), &
    var_t(1, 'mu', 'a real number [-]'), var_t(1, 'h_n', 'a real number [mm] (or Inf)'), &
    var_t(1, 'prefractured', 'a logical (.true. or .false.)'), &
    var_t(2, 'theta0_deg', real_list // ' [deg]'), var_t(2, 'thetaf_deg', real_list // ' [deg]'), &
    var_t(2, 'zeta0', real_list // ' [N/mm] (or Inf)'), &
    var_t(2, 'n_planes', 'an integer (1 to 8)'), var_t(2, 'gamma_hat', real_list // ' [-]'), &
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
    var_t(7, 'separation', 'two real numbers (normal, tangential) [mm]'), &
    var_t(7, 'traction', 'two real numbers (normal, tangential) [MPa]'), &
    var_t(8, 'file', 'a quoted string: a file path (at most 4096 characters)'), &
    var_t(8, 'title', 'a quoted string (at most 1024 characters)'), &
    var_t(8, 'every', 'an integer (1 to 2000000)'), &
    var_t(8, 'store', "a quoted string: 'all', 'curves' or a list of dataset names")]
  integer, parameter :: title_len = 1024

  !> A validated deck. The loading block is stored expanded over its cycles.
  type :: deck_t
    character(len=:), allocatable :: path, text, output_file, title
    logical :: output_given = .false.   !< &output file given (else the deck's name with .h5)
    !> &output every: rows 0, every, 2 every, ... and the last row of each case are written
    integer :: every = 1
    !> &output store: stored(k) = history_datasets(k) is written
    logical :: stored(n_datasets) = .true.
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
    !> Global Richardson extrapolation: run each case with the deck's steps and with the step
    !> count of every segment of more than one step doubled; separation and traction =
    !> 2 u(2n) - u(n)
    logical :: extrapolate = .false.
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
  !> Floating-point halting is off while the deck is read, so that a value such as 1e400 reads
  !> as +Inf (and is then rejected or taken as infinity) even in a trapping (Debug) build.
  !> `extra_groups` (optional): groups of another program's deck (interlock-fit's &fit) that
  !> the text check accepts and the reader leaves to that program.
  subroutine read_deck(path, deck, stat, message, extra_groups)
    character(len=*), intent(in) :: path
    type(deck_t), intent(out) :: deck
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    character(len=*), intent(in), optional :: extra_groups(:)
    logical :: halt(3)
    call ieee_get_halting_mode(ieee_overflow, halt(1))
    call ieee_get_halting_mode(ieee_invalid, halt(2))
    call ieee_get_halting_mode(ieee_divide_by_zero, halt(3))
    call ieee_set_halting_mode(ieee_overflow, .false.)
    call ieee_set_halting_mode(ieee_invalid, .false.)
    call ieee_set_halting_mode(ieee_divide_by_zero, .false.)
    if (present(extra_groups)) then
      call read_deck_text(path, deck, stat, message, extra_groups)
    else
      call read_deck_text(path, deck, stat, message, [character(len=1) ::])
    end if
    call ieee_set_halting_mode(ieee_overflow, halt(1))
    call ieee_set_halting_mode(ieee_invalid, halt(2))
    call ieee_set_halting_mode(ieee_divide_by_zero, halt(3))
  end subroutine read_deck

  subroutine read_deck_text(path, deck, stat, message, extra_groups)
    character(len=*), intent(in) :: path
    type(deck_t), intent(inout) :: deck
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    character(len=*), intent(in) :: extra_groups(:)
    type(group_scan_t) :: scan(size(deck_groups) + size(extra_groups))
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
    call scan_deck(deck%text, [character(len=max(len(deck_groups), len(extra_groups))) :: &
                   deck_groups, extra_groups], scan, message)
    if (len_trim(message) > 0) then
      message = path // ': ' // trim(message)
      return
    end if
    do g = 1, size(deck_groups)
      if (group_required(g) .and. .not. scan(g)%present) then
        message = path // ': the required group &' // trim(deck_groups(g)) // &
                  ' is missing (required groups: &interface, &microplanes, &loading)'
        return
      end if
    end do
    do g = 1, size(deck_groups)
      if (.not. scan(g)%present) cycle
      call check_plane_indices(g, scan(g), planes_in_deck(deck%text, scan(2)), message)
      if (len_trim(message) == 0) call check_assignments(g, scan(g), message)
      if (len_trim(message) > 0) then
        message = path // ': &' // trim(deck_groups(g)) // ': ' // trim(message)
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
      if (.not. scan(g)%present) cycle
      rewind (u)
      select case (g)
      case (1)
        call read_interface(u, deck%text, scan(g), deck, message)
      case (2)
        call read_microplanes(u, deck%text, scan(g), deck, message)
      case (3)
        call read_effects(u, deck%text, scan(g), deck, message)
      case (4)
        call read_loading(u, deck%text, scan(g), deck, message)
      case (5)
        call read_solver(u, deck%text, scan(g), deck, message)
      case (6)
        call read_sweep(u, deck%text, scan(g), deck, message)
      case (7)
        call read_initial_state(u, deck%text, scan(g), deck, message)
      case (8)
        call read_output(u, deck%text, scan(g), deck, message)
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
  end subroutine read_deck_text

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
      call deck_set_property(d, ip, v)
    end if
    ! thetaf_deg absent: = theta0_deg (no wear), unless it is the swept parameter.
    if (.not. d%thetaf_given .and. ip /= prop_thetaf) d%thetaf_deg = d%theta0_deg
    ! A swept angle takes each plane's sign (the paper's RIA: -theta, 0, +theta): say what is
    ! wrong in the deck's terms (the swept magnitude against each plane's), not with the signed
    ! angle of a plane.
    if (ip == prop_theta0 .and. d%thetaf_given .or. ip == prop_thetaf) then
      do n = 1, merge(1, d%n_planes, d%paper_ria)
        if (abs(d%thetaf_deg(n)) <= abs(d%theta0_deg(n))) cycle
        if (ip == prop_thetaf) then
          why = 'thetaf_deg = ' // short_real(v) // ' deg is inadmissible for plane ' // &
                format_integer(n) // ' (theta0_deg = ' // short_real(deck%theta0_deg(n)) // &
                '): admissible 0 <= thetaf_deg <= ' // short_real(abs(deck%theta0_deg(n))) // &
                ' deg (the swept angle takes the sign of each plane''s theta0_deg)'
        else
          why = 'theta0_deg = ' // short_real(v) // ' deg is inadmissible for plane ' // &
                format_integer(n) // ' (thetaf_deg = ' // short_real(deck%thetaf_deg(n)) // &
                '): admissible theta0_deg >= ' // short_real(abs(deck%thetaf_deg(n))) // &
                ' deg (the swept angle takes the sign of each plane''s theta0_deg)'
        end if
        message = deck%path // ': ' // trim(case_text(deck, icase)) // ' ' // trim(why)
        stat = status_bad_input
        return
      end do
    end if

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
    why = scale_check(mat)
    if (len_trim(why) == 0) call interlock_material_prepare(mat, stat, why)
    if (len_trim(why) > 0) then
      if (deck%sweep_property > 0) then
        message = deck%path // ': ' // trim(case_text(deck, icase)) // ' ' // trim(why)
      else if (index(why, 'gamma') == 1 .or. index(why, 'theta') == 1 .or. &
               index(why, 'plane') == 1 .or. index(why, 'n_planes') == 1) then
        message = deck%path // ': &microplanes: ' // trim(why)
      else
        message = deck%path // ': &interface: ' // trim(why)
      end if
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
      if (len_trim(why) == 0 .and. .not. mat%use_friction) call no_friction_traction(why)
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
        why = name // ' has ' // format_integer(m) // ' values: give one per microplane (' // &
              format_integer(n) // ')'
        return
      end if
      field(1:n) = given(1:n)
    end subroutine apply_initial

    !> Without friction (mu = 0, or the effect off) an admissible state carries no friction
    !> traction (|tau_f| <= mu p = 0); the laws rely on it.
    subroutine no_friction_traction(why)
      character(len=*), intent(out) :: why
      integer :: k
      why = ''
      do k = 1, n
        if (abs(state%tauf(k)) > 0.0_dp) then
          why = 'friction_traction(' // format_integer(k) // ') = ' // &
                format_real(state%tauf(k)) // ' is inadmissible: without friction (mu = 0 ' // &
                'or friction switched off) admissible friction_traction = 0'
          return
        end if
      end do
    end subroutine no_friction_traction

  end subroutine deck_case

  !> Set property `ip` (a row of the material table that a sweep or a fit may vary) of the
  !> deck `d` to `v`: a per-plane angle is a magnitude that takes each plane's sign.
  pure subroutine deck_set_property(d, ip, v)
    type(deck_t), intent(inout) :: d
    integer, intent(in) :: ip
    real(dp), intent(in) :: v
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
      if (d%paper_ria) then
        d%theta0_deg(1) = v
      else
        d%theta0_deg(1:d%n_planes) = sign(v, d%theta0_deg(1:d%n_planes))
      end if
    case (prop_thetaf)
      if (d%paper_ria) then
        d%thetaf_deg(1) = v
      else
        d%thetaf_deg(1:d%n_planes) = sign(v, d%theta0_deg(1:d%n_planes))
      end if
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
  end subroutine deck_set_property

  !> "case 3 (h_n = 0.5 mm): " for sweeps, '' otherwise.
  function case_text(deck, icase) result(text)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    character(len=:), allocatable :: text
    text = ''
    if (deck%sweep_property > 0) text = '&sweep case ' // format_integer(icase) // ' (' // &
      trim(deck%sweep_parameter) // ' = ' // value_str(deck%sweep_values(icase)) // '): '
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
    logical :: ok_cr
    integer(kind=8) :: nbytes
    character(len=512) :: iomsg

    stat = status_bad_input
    message = ''
    text = ''
    select case (path_kind(path))
    case (path_absent)
      message = path // ': no such deck file'
      return
    case (path_folder)
      message = path // ': the deck is a folder, not a file'
      return
    case (path_other)
      message = path // ': the deck is not a regular file (a FIFO, a device such as ' // &
                '/dev/zero, or a socket): give a deck file'
      return
    end select
    inquire (file=path, exist=exists, size=nbytes)
    if (.not. exists) then
      message = path // ': no such deck file'
      return
    end if
    if (nbytes == 0) then
      message = path // ': the deck is empty'
      return
    end if
    if (nbytes < 0) then
      message = path // ': the deck is not a regular file'
      return
    end if
    if (nbytes > max_deck_bytes) then
      message = path // ': the deck has ' // trim(int8_text(nbytes)) // ' bytes: admissible ' // &
                'at most ' // format_integer(max_deck_bytes) // ' bytes (4 MiB)'
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
    ! A UTF-8 byte order mark (EF BB BF, written by some Windows editors) marks the encoding;
    ! it is not text: dropped.
    if (len(text) >= 3) then
      if (text(1:3) == char(239) // char(187) // char(191)) text = text(4:)
    end if
    if (len(text) == 0) then
      message = path // ': the deck is empty (only a UTF-8 byte order mark)'
      return
    end if
    if (len(text) >= 2) then
      c = ichar(text(1:1)) + 256 * ichar(text(2:2))
      if (c == 255 + 256 * 254 .or. c == 254 + 256 * 255) then
        message = path // ': the deck is UTF-16 encoded (a byte order mark ' // &
                  'and NUL bytes): write it as ASCII or UTF-8 text'
        return
      end if
    end if
    line = 1
    do i = 1, len(text)
      c = iachar(text(i:i))
      if (c == 10) line = line + 1
      if (c == 13) then
        ok_cr = i < len(text)
        if (ok_cr) ok_cr = text(i + 1:i + 1) == achar(10)
        if (.not. ok_cr) then
          message = path // ': line ' // format_integer(line) // ': a carriage return (code 13) ' // &
                    'without a line feed: line ends must be LF (Unix) or CR LF (Windows)'
          return
        end if
      end if
      if (c < 32 .and. c /= 9 .and. c /= 10 .and. c /= 13 .and. c /= 12 .or. c == 127) then
        message = path // ': line ' // format_integer(line) // ': byte ' // format_integer(i) // &
                  ' is a control character (code ' // format_integer(c) // &
                  '): the deck must be a text file (a Fortran namelist)'
        return
      end if
    end do
    stat = status_ok
  end subroutine load_text

  ! ----------------------------------------------------------------- the groups

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

  !> The number of microplanes the deck declares: &microplanes n_planes when it is given (and
  !> reads as an integer), else 0 (the paper's RIA, or not readable: left to the namelist read).
  function planes_in_deck(text, micro) result(n)
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: micro
    integer :: n, k, ios
    character(len=:), allocatable :: value
    n = 0
    do k = 1, micro%n
      if (trim(micro%a(k)%name) /= 'n_planes' .or. len_trim(micro%a(k)%subscript) > 0) cycle
      value = value_text(text, micro%a(k))
      read (value, *, iostat=ios) n
      if (ios /= 0) n = 0
    end do
  end function planes_in_deck

  !> An element of a per-plane array, `name(k) = value`, must name a plane: 1 <= k <= n_planes
  !> (the paper's RIA without n_planes: one value in &microplanes, its 3 planes in
  !> &initial_state), and k <= max_planes in any case. Checked before the duplicates, so that
  !> `theta0_deg = -10, 10` followed by `theta0_deg(3) = 5` says that plane 3 does not exist.
  subroutine check_plane_indices(g, scan, n_planes, message)
    integer, intent(in) :: g, n_planes
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
                                       'thetaf_deg', 'zeta0'])
    case ('initial_state')
      is_plane_variable = any(name == [character(len=17) :: 'damage', 'beta', 'frictional_slip', &
                                       'zeta', 'theta', 'friction_traction'])
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

  subroutine read_interface(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    real(dp) :: sigma0_n, sigma0_t, gc, eta, mu, h_n
    logical :: prefractured
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
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
      do kp = 1, scan%n
        probe = probe_text(text, 'interface', scan%a(kp))
        read (probe, nml=interface, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(1, text, scan, kp, iomsg, iomsg2, message)
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

  subroutine read_microplanes(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    real(dp), dimension(max_planes) :: theta0_deg, thetaf_deg, zeta0, gamma_hat
    integer :: n_planes, ios, n, k
    logical :: ok
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /microplanes/ theta0_deg, thetaf_deg, zeta0, n_planes, gamma_hat
    theta0_deg = unset
    thetaf_deg = unset
    zeta0 = unset
    gamma_hat = unset
    n_planes = unset_int
    message = ''
    read (u, nml=microplanes, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'microplanes', scan%a(kp))
        read (probe, nml=microplanes, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(2, text, scan, kp, iomsg, iomsg2, message)
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
        message = "property 'thetaf_deg' = " // value_str(thetaf_deg(1)) // &
                  ' is inadmissible: admissible 0 <= thetaf_deg <= theta0_deg = ' // &
                  value_str(theta0_deg(1)) // ' [deg]'
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
        message = 'n_planes = ' // format_integer(n_planes) // ' is inadmissible: admissible 1 <= ' // &
                  'n_planes <= ' // format_integer(max_planes)
        return
      end if
      n = n_planes
      if (count_given(theta0_deg) /= n .or. count_given(gamma_hat) /= n) then
        message = 'with n_planes = ' // format_integer(n) // ' give ' // format_integer(n) // &
                  ' values of gamma_hat and of theta0_deg (given: ' // &
                  format_integer(count_given(gamma_hat)) // ' and ' // format_integer(count_given(theta0_deg)) // ')'
        return
      end if
      deck%thetaf_given = count_given(thetaf_deg) > 0
      if (count_given(thetaf_deg) == 0) thetaf_deg(1:n) = theta0_deg(1:n)
      if (count_given(zeta0) == 0) zeta0(1:n) = huge(1.0_dp)
      if (count_given(thetaf_deg) /= n .or. count_given(zeta0) /= n) then
        message = 'with n_planes = ' // format_integer(n) // ' give ' // format_integer(n) // &
                  ' values of thetaf_deg and of zeta0, or none'
        return
      end if
      do k = 1, n
        call check_required(prop_theta0, abs(theta0_deg(k)), message)
        if (len_trim(message) > 0) then
          message = 'plane ' // format_integer(k) // ': ' // trim(message) // ' (in absolute value)'
          return
        end if
        call check_required(prop_zeta0, zeta0(k), message)
        if (len_trim(message) > 0) then
          message = 'plane ' // format_integer(k) // ': ' // trim(message)
          return
        end if
        if (.not. (in_range(gamma_hat(k), 0.0_dp, 1.0_dp) .and. gamma_hat(k) > 0.0_dp)) then
          message = 'plane ' // format_integer(k) // ': gamma_hat(' // format_integer(k) // ') = ' // &
                    value_str(gamma_hat(k)) // ' is inadmissible: admissible 0 < gamma_hat <= 1 [-]'
          return
        end if
        ok = in_range(abs(thetaf_deg(k)), 0.0_dp, abs(theta0_deg(k)))
        if (ok) ok = .not. (thetaf_deg(k) * theta0_deg(k) < 0.0_dp)
        if (.not. ok) then
          message = 'plane ' // format_integer(k) // ': thetaf_deg(' // format_integer(k) // ') = ' // &
                    value_str(thetaf_deg(k)) // ' is inadmissible: admissible 0 <= |thetaf_deg| ' // &
                    '<= |theta0_deg| = ' // value_str(abs(theta0_deg(k))) // &
                    ' [deg], of the same sign as theta0_deg = ' // value_str(theta0_deg(k))
          return
        end if
      end do
      if (abs(sum(gamma_hat(1:n)) - 1.0_dp) > 1.0e-9_dp) then
        message = 'gamma_hat sums to ' // value_str(sum(gamma_hat(1:n))) // ': admissible a sum ' // &
                  'of 1 (within 1e-9): the area fractions of the microplanes'
        return
      end if
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

  subroutine read_effects(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    logical :: damage, friction, interlocking, finite_depth, wear
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /effects/ damage, friction, interlocking, finite_depth, wear
    damage = .true.
    friction = .true.
    interlocking = .true.
    finite_depth = .true.
    wear = .true.
    message = ''
    read (u, nml=effects, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'effects', scan%a(kp))
        read (probe, nml=effects, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(3, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    deck%effect = [damage, friction, interlocking, finite_depth, wear]
  end subroutine read_effects

  subroutine read_loading(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
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

  subroutine read_solver(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    character(len=32) :: scheme
    real(dp) :: substep_tol, newton_tol
    integer :: newton_max_iterations, max_cuts, ios
    logical :: ok, extrapolate
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /solver/ scheme, substep_tol, newton_tol, newton_max_iterations, max_cuts, extrapolate
    scheme = 'trapezoidal'
    substep_tol = 0.0_dp
    newton_tol = deck%control%tol
    newton_max_iterations = deck%control%max_iterations
    max_cuts = deck%control%max_cuts
    extrapolate = .false.
    message = ''
    read (u, nml=solver, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'solver', scan%a(kp))
        read (probe, nml=solver, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(5, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    select case (lower(trim(adjustl(scheme))))
    case ('explicit')
      deck%solver%scheme = scheme_explicit
    case ('implicit')
      deck%solver%scheme = scheme_implicit
    case ('trapezoidal')
      deck%solver%scheme = scheme_trapezoidal
    case default
      message = "scheme = '" // trim(scheme) // "' is inadmissible: admissible 'explicit', " // &
                "'implicit' or 'trapezoidal'"
      return
    end select
    call check_value(prop_substep_tol, substep_tol, message)
    if (len_trim(message) > 0) return
    deck%solver%substep_tol = substep_tol
    ok = .false.
    if (.not. is_nan_value(newton_tol)) ok = newton_tol >= 1.0e-16_dp .and. newton_tol <= 1.0e-2_dp
    if (.not. ok) then
      message = 'newton_tol = ' // value_str(newton_tol) // &
                ' is inadmissible: admissible 1e-16 <= newton_tol <= 1e-2 [-]'
      return
    end if
    if (newton_max_iterations < 1 .or. newton_max_iterations > 1000) then
      message = 'newton_max_iterations = ' // format_integer(newton_max_iterations) // &
                ' is inadmissible: admissible 1 <= newton_max_iterations <= 1000'
      return
    end if
    if (max_cuts < 0 .or. max_cuts > 50) then
      message = 'max_cuts = ' // format_integer(max_cuts) // ' is inadmissible: admissible 0 <= max_cuts <= 50'
      return
    end if
    deck%control%tol = newton_tol
    deck%control%max_iterations = newton_max_iterations
    deck%control%max_cuts = max_cuts
    deck%extrapolate = extrapolate
  end subroutine read_solver

  subroutine read_sweep(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
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
  end subroutine read_sweep

  subroutine read_initial_state(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    real(dp), dimension(max_planes) :: damage, beta, frictional_slip, zeta, theta, friction_traction
    real(dp) :: separation(2), traction(2)
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
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
      do kp = 1, scan%n
        probe = probe_text(text, 'initial_state', scan%a(kp))
        read (probe, nml=initial_state, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(7, text, scan, kp, iomsg, iomsg2, message)
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
    message = range_message('damage', damage, 0.0_dp, 1.0_dp, '0 <= damage <= 1')
    if (len_trim(message) == 0) message = range_message('beta', beta, 0.0_dp, 1.0e12_dp, &
                                                        '0 <= beta <= 1e12')
    if (len_trim(message) == 0) message = range_message('zeta', zeta, 0.0_dp, 1.0e30_dp, &
                                                        '0 <= zeta < 1e30 [N/mm]')
    if (len_trim(message) == 0) message = range_message('theta', theta, -0.5_dp * pi, &
                                                        0.5_dp * pi, '-pi/2 < theta < pi/2 [rad]', &
                                                        open_ends=.true.)
    if (len_trim(message) > 0) return
    message = not_finite_message('frictional_slip', 'mm', frictional_slip)
    if (len_trim(message) == 0) message = not_finite_message('friction_traction', 'MPa', &
                                                              friction_traction)
    if (len_trim(message) == 0) message = not_finite_message('separation', 'mm', separation)
    if (len_trim(message) == 0) message = not_finite_message('traction', 'MPa', traction)
    if (len_trim(message) > 0) return
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

  subroutine read_output(u, text, scan, deck, message)
    integer, intent(in) :: u
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: scan
    type(deck_t), intent(inout) :: deck
    character(len=*), intent(out) :: message
    character(len=path_len + 1) :: file
    character(len=title_len + 1) :: title
    character(len=store_len + 1) :: store
    integer :: every
    integer :: ios
    character(len=512) :: iomsg, iomsg2
    character(len=:), allocatable :: probe
    integer :: kp
    namelist /output/ file, title, every, store
    file = ''
    title = ''
    every = 1
    store = 'all'
    message = ''
    read (u, nml=output, iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      do kp = 1, scan%n
        probe = probe_text(text, 'output', scan%a(kp))
        read (probe, nml=output, iostat=ios, iomsg=iomsg2)
        if (ios /= 0) exit
      end do
      call nml_error(8, text, scan, kp, iomsg, iomsg2, message)
      return
    end if
    if (len_trim(file) > path_len) then
      message = 'file is longer than ' // format_integer(path_len) // ' characters: admissible at most ' // &
                format_integer(path_len) // ' characters'
      return
    end if
    if (len_trim(title) > title_len) then
      message = 'title is longer than ' // format_integer(title_len) // ' characters: admissible at most ' // &
                format_integer(title_len) // ' characters'
      return
    end if
    file = adjustl(file)
    if (len_trim(file) == 0 .and. any(scan%a(1:scan%n)%name == 'file')) then
      message = "file = '" // trim(file) // "' is empty: give a file name, or leave file out " // &
                "for the default (the deck's name with .h5, in the working folder)"
      return
    end if
    if (len_trim(file) > 0) then
      if (file(len_trim(file):len_trim(file)) == '/' .or. trim(file) == '.' .or. &
          trim(file) == '..') then
        message = "file = '" // trim(file) // "' is a folder: give a file name (e.g. 'out/" // &
                  "result.h5'; the folder must exist)"
        return
      end if
      deck%output_file = trim(file)
      deck%output_given = .true.
    end if
    deck%title = trim(title)
    if (every < 1 .or. every > max_total_steps) then
      message = 'every = ' // format_integer(every) // ' is inadmissible: admissible 1 <= every <= ' // &
                format_integer(max_total_steps) // ' (every = k keeps rows 0, k, 2k, ... and the last)'
      return
    end if
    deck%every = every
    if (len_trim(store) > store_len) then
      message = 'store is longer than ' // format_integer(store_len) // ' characters: admissible ' // &
                "'all', 'curves' or a comma-separated list of dataset names: " // datasets_text()
      return
    end if
    call parse_store(store, deck%stored, message)
  end subroutine read_output

  !> &output store: 'all', 'curves', or a comma-separated list of dataset names (case and
  !> blanks do not matter; a name may be repeated). time, separation and traction are always
  !> written. message /= '' for anything else, listing the admissible names.
  subroutine parse_store(store, stored, message)
    character(len=*), intent(in) :: store
    logical, intent(out) :: stored(n_datasets)
    character(len=*), intent(out) :: message
    character(len=:), allocatable :: rest, item
    character(len=*), parameter :: admissible = "admissible 'all', 'curves' or a " // &
      'comma-separated list of dataset names: '
    integer :: comma, k, j
    message = ''
    stored = .true.
    select case (lower(trim(adjustl(store))))
    case ('all')
      return
    case ('curves')
      stored = curves_datasets
      return
    end select
    stored = .false.
    stored(1:n_always) = .true.
    rest = trim(store)
    k = 0
    do
      k = k + 1
      comma = index(rest, ',')
      if (comma > 0) then
        item = lower(trim(adjustl(rest(1:comma - 1))))
        rest = rest(comma + 1:)
      else
        item = lower(trim(adjustl(rest)))
      end if
      if (len(item) == 0) then
        message = "store = " // quoted(store) // " is inadmissible: item " // format_integer(k) // &
                  ' is empty; ' // admissible // datasets_text()
        return
      end if
      j = dataset_index(item)
      if (j == 0) then
        message = "store = " // quoted(store) // " is inadmissible: " // quoted(item) // " is not a " // &
                  'dataset name; ' // admissible // datasets_text()
        if (item == 'all' .or. item == 'curves') message = "store = " // quoted(store) // &
          " is inadmissible: " // quoted(item) // " stands alone, not in a list; " // admissible // &
          datasets_text()
        return
      end if
      stored(j) = .true.
      if (comma == 0) exit
    end do

  contains

    !> 'text' in quotes, cut to 60 characters ('...') so that the message keeps its end.
    pure function quoted(text) result(q)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: q
      if (len_trim(text) > 60) then
        q = "'" // text(1:60) // "...'"
      else
        q = "'" // trim(text) // "'"
      end if
    end function quoted

  end subroutine parse_store

  !> Index of dataset `name` in history_datasets, 0 if there is none.
  pure integer function dataset_index(name)
    character(len=*), intent(in) :: name
    integer :: k
    dataset_index = 0
    do k = 1, n_datasets
      if (trim(history_datasets(k)) == trim(name)) then
        dataset_index = k
        return
      end if
    end do
  end function dataset_index

  !> "time, separation, ...": the dataset names of a case.
  pure function datasets_text() result(text)
    character(len=:), allocatable :: text
    integer :: k
    text = trim(history_datasets(1))
    do k = 2, n_datasets
      text = text // ', ' // trim(history_datasets(k))
    end do
  end function datasets_text

  ! ------------------------------------------------------------------- helpers

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

  !> '' if the derived scales of the material are representable, else why not: the opening
  !> lengths s_c = 2 Gc / sigma0, s_0 = (1 - eta) s_c [mm] and the stiffnesses K = sigma0 / s_0
  !> [MPa/mm] must lie in [1e-100, 1e100] (computed in logarithms, so nothing overflows here;
  !> the library itself would divide by an underflowed s_0).
  function scale_check(mat) result(why)
    type(interlock_material_t), intent(in) :: mat
    character(len=256) :: why
    real(dp), parameter :: lim = 100.0_dp * log(10.0_dp)
    real(dp) :: ln_sc, ln_s0, ln_k
    integer :: i
    real(dp) :: sigma0
    character(len=1) :: c
    why = ''
    do i = 1, 2
      sigma0 = merge(mat%sigma0_n, mat%sigma0_t, i == 1)
      c = merge('n', 't', i == 1)
      ln_sc = log(2.0_dp) + log(mat%gc) - log(sigma0)
      ln_s0 = log(1.0_dp - mat%eta) + ln_sc
      ln_k = log(sigma0) - ln_s0
      if (abs(ln_sc) > lim .or. abs(ln_s0) > lim .or. abs(ln_k) > lim) then
        why = 'sigma0_' // c // ' = ' // value_str(sigma0) // ', gc = ' // value_str(mat%gc) // &
              ' and eta = ' // value_str(mat%eta) // ' give s_0' // c // ' = 10^' // &
              short_real(anint(ln_s0 / log(10.0_dp))) // ' mm and K_' // c // ' = 10^' // &
              short_real(anint(ln_k / log(10.0_dp))) // ' MPa/mm: admissible 1e-100 <= s_c' // &
              c // ', s_0' // c // ' <= 1e100 mm and 1e-100 <= K_' // c // ' <= 1e100 MPa/mm'
        return
      end if
    end do
  end function scale_check

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
  !> '' when every given value of an &initial_state array is a finite number (|x| <= 1e12),
  !> else the message naming the first one that is not.
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

  pure function not_finite_message(name, unit, x) result(message)
    character(len=*), intent(in) :: name, unit
    real(dp), intent(in) :: x(:)
    character(len=:), allocatable :: message
    integer :: k
    message = ''
    do k = 1, count_given(x)
      if (.not. in_range(x(k), -1.0e12_dp, 1.0e12_dp)) then
        message = name // '(' // format_integer(k) // ') is not a finite number [' // unit // ']'
        return
      end if
    end do
  end function not_finite_message

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

  pure function int8_text(i) result(text)
    integer(kind=8), intent(in) :: i
    character(len=24) :: text
    write (text, '(i0)') i
  end function int8_text

end module interlock_deck
