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
  use interlock, only: dp, deg_to_rad, pi, max_planes, max_azimuths, n_effects, &
      interlock_material_t, interlock_solver_t, interlock_state_3d_t, interlock_state_3d_init, &
      interlock_material_prepare, interlock_paper_ria, interlock_azimuthal_ria, &
      interlock_general_ria, scheme_explicit, scheme_implicit, &
      scheme_trapezoidal, properties, property_index, check_property, format_range, &
      format_integer, format_real, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, prop_max_dd, &
      prop_max_dtheta, prop_tangent, prop_effect_damage, prop_effect_wear, is_nan_value, same_value, &
      is_infinite_value, prop_ria, prop_n_azimuths, ria_paper, &
      status_ok, status_bad_input
  use interlock_step_solver, only: control_t
  use interlock_path, only: arc_t, path_points
  use interlock_files, only: path_kind, path_absent, path_folder, path_other
  use interlock_deck_text, only: group_scan_t, scan_deck, probe_text, value_text, lower
  use interlock_deck_checks
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_get_halting_mode, &
      ieee_set_halting_mode, ieee_overflow, ieee_invalid, ieee_divide_by_zero
  implicit none
  private
  public :: deck_t, read_deck, deck_case, deck_n_cases, deck_groups, deck_set_property, &
            deck_loading, sweep_slip_angle, deck_ria_name, case_n_azimuths
  public :: max_points, max_sweep_values, max_total_steps, max_deck_bytes
  public :: n_datasets, history_datasets, curves_datasets, datasets_text, dataset_index

  integer, parameter :: max_points = 10001        !< points of one loading block
  integer, parameter :: max_sweep_values = 1000   !< cases of one deck
  integer, parameter :: max_total_steps = 2 * 10**6 !< steps of one case (cycles included)
  integer, parameter :: max_deck_bytes = 4 * 1024 * 1024
  integer, parameter :: max_cycles = 100000
  integer, parameter :: name_len = 64, path_len = 4096

  !> The datasets of a case (docs/history-output.md), in the order they are written; `&output`
  !> `store` picks among them ('all', 'curves' or a comma-separated list of these names). The
  !> first three (time, separation, traction) are always written.
  !> The last two (the strike components of the frictional slip and of the friction traction)
  !> belong to 3D cases only.
  integer, parameter :: n_datasets = 17
  character(len=20), parameter :: history_datasets(n_datasets) = [character(len=20) :: 'time', &
    'separation', 'traction', 'damage', 'beta', 'theta', 'zeta', 'frictional_slip', &
    'friction_traction', 'work', 'stored_energy', 'damage_dissipation', &
    'friction_dissipation', 'iterations', 'substeps', 'sf_strike', 'tauf_strike']
  integer, parameter :: first_3d_dataset = 16
  !> store = 'curves': no per-plane dataset.
  logical, parameter :: curves_datasets(n_datasets) = [.true., .true., .true., .false., &
    .false., .false., .false., .false., .false., .true., .true., .true., .true., .true., .true., &
    .false., .false.]
  !> &sweep parameter = 'angle_deg': the direction of the &loading path (not a property)
  integer, parameter :: sweep_slip_angle = -1
  integer, parameter :: n_always = 3
  integer, parameter :: store_len = 1024


  integer, parameter :: title_len = 1024

  !> A validated deck. The loading block is stored expanded over its cycles.
  type :: deck_t
    character(len=:), allocatable :: path, text, output_file, title
    logical :: output_given = .false.   !< &output file given (else the deck's name with .h5)
    !> &output every: rows 0, every, 2 every, ... and the last row of each case are written
    integer :: every = 1
    !> &output store: stored(k) = history_datasets(k) is written
    logical :: stored(n_datasets) = .true.
    logical :: store_listed = .false.   !< store is a list of names (not 'all' or 'curves')
    !> 3 (N, T1, T2): the deck uses T2 loading, azimuths, a path or the azimuthal RIA (a 3D
    !> case, SPEC section 9); 2 otherwise (the 2D law)
    integer :: n_components = 2
    ! &interface
    real(dp) :: sigma0_n = 0.0_dp, sigma0_t = 0.0_dp, gc = 0.0_dp, eta = 0.0_dp, mu = 0.0_dp
    real(dp) :: h_n = huge(1.0_dp)
    logical :: prefractured = .false.
    ! &microplanes
    logical :: paper_ria = .true.
    logical :: thetaf_given = .false.   !< without thetaf_deg the planes do not wear (theta_f = theta_0)
    integer :: n_planes = 3
    real(dp), dimension(max_planes) :: gamma_hat = 0.0_dp, theta0_deg = 0.0_dp, &
                                       thetaf_deg = 0.0_dp, zeta0 = huge(1.0_dp), phi_deg = 0.0_dp
    integer :: n_azimuths = 0           !< the azimuthal RIA with this many azimuths; 0: none
    logical :: azimuths_given = .false. !< phi_deg given (a general RIA in 3D)
    ! &effects
    logical :: effect(n_effects) = .true.
    ! &loading, expanded over the cycles: points (times(i), values(:, i)), steps per segment
    type(control_t) :: control
    real(dp), allocatable :: times(:), values(:, :)
    integer, allocatable :: steps(:)
    integer :: cycles = 1
    integer :: n_steps = 0
    !> a path (3D): 'straight', 'square' or 'circle' in the (T1, T2) plane after a preload of the
    !> normal component, turned by path_angle_deg from t1; '' when the points are given
    character(len=8) :: path_kind = ''
    real(dp) :: path_angle_deg = 0.0_dp, path_size = 0.0_dp, path_turns = 1.0_dp, &
                path_normal = 0.0_dp
    !> the arc segments of the path (3D; sweep = 0: a straight segment), one per segment
    type(arc_t), allocatable :: arcs(:)
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
                                       init_zeta = unset, init_theta = unset, init_tauf = unset, &
                                       init_sf_strike = unset, init_tauf_strike = unset
    !> (normal, tangential) or, in a 3D deck, (normal, t1, t2)
    real(dp) :: init_s(3) = unset, init_sigma(3) = unset
  end type deck_t

  !> The readers of the groups, one per group (submodules interlock_deck_material,
  !> interlock_deck_loading, interlock_deck_run): the namelist of group `scan` read from unit u
  !> (the deck as `text`, for messages) into `deck`; message /= '' on failure.
  interface
    module subroutine read_interface(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_interface
    module subroutine read_microplanes(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_microplanes
    module subroutine read_effects(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_effects
    module subroutine read_initial_state(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_initial_state
    module subroutine read_loading(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_loading
    module subroutine read_sweep(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_sweep
    module subroutine read_solver(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_solver
    module subroutine read_output(u, text, scan, deck, message)
      integer, intent(in) :: u
      character(len=*), intent(in) :: text
      type(group_scan_t), intent(in) :: scan
      type(deck_t), intent(inout) :: deck
      character(len=*), intent(out) :: message
    end subroutine read_output
  end interface

  public :: deck_property

contains

  !> Number of cases: one per sweep value, or one.
  pure integer function deck_n_cases(deck)
    type(deck_t), intent(in) :: deck
    deck_n_cases = 1
    if (deck%sweep_property /= 0) deck_n_cases = size(deck%sweep_values)
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
    type(interlock_state_3d_t) :: state
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
      call check_plane_indices(g, scan(g), planes_in_deck(deck%text, scan(2), 'n_planes'), &
                               planes_in_deck(deck%text, scan(2), 'n_azimuths'), message)
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
    deck%control%n = deck%n_components
    ! The strike datasets belong to 3D cases (SPEC section 9).
    if (deck%n_components == 2) then
      if (deck%store_listed .and. any(deck%stored(first_3d_dataset:))) then
        message = path // ': &output: store names sf_strike or tauf_strike, datasets of 3D ' // &
                  'cases (T2 loading, azimuths, a path or the azimuthal RIA): this deck is 2D'
        return
      end if
      deck%stored(first_3d_dataset:) = .false.
    end if
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
    type(interlock_state_3d_t), intent(out) :: state
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
    else if (ip == sweep_slip_angle) then
      label = 'angle_deg = ' // short_real(deck%sweep_values(icase)) // ' deg'
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
    if (d%paper_ria .and. case_n_azimuths(deck, icase) > 0) then
      call interlock_azimuthal_ria(mat, case_n_azimuths(deck, icase), &
                                   d%theta0_deg(1) * deg_to_rad, d%thetaf_deg(1) * deg_to_rad, &
                                   d%zeta0(1))
    else if (d%paper_ria) then
      call interlock_paper_ria(mat, d%theta0_deg(1) * deg_to_rad, d%thetaf_deg(1) * deg_to_rad, &
                               d%zeta0(1))
    else
      n = d%n_planes
      ! (deck%phi_deg is 0 where the deck gives no azimuths)
      call interlock_general_ria(mat, n, d%gamma_hat(1:n), d%theta0_deg(1:n) * deg_to_rad, &
                                 d%thetaf_deg(1:n) * deg_to_rad, d%zeta0(1:n), &
                                 deck%phi_deg(1:n) * deg_to_rad)
    end if
    why = inverse_check(mat, .not. d%paper_ria)
    if (len_trim(why) == 0) why = scale_check(mat)
    if (len_trim(why) == 0) call interlock_material_prepare(mat, stat, why)
    if (len_trim(why) > 0) then
      if (deck%sweep_property /= 0) then
        message = deck%path // ': ' // trim(case_text(deck, icase)) // ' ' // trim(why)
      else if (index(why, 'gamma') == 1 .or. index(why, 'theta') == 1 .or. &
               index(why, 'plane') == 1 .or. index(why, 'n_planes') == 1 .or. &
               index(why, 'zeta0') == 1) then
        message = deck%path // ': &microplanes: ' // trim(why)
      else
        message = deck%path // ': &interface: ' // trim(why)
      end if
      stat = status_bad_input
      return
    end if
    solver = d%solver

    call interlock_state_3d_init(mat, state)
    n = mat%n_planes
    if (deck%has_initial_state) then
      call apply_initial(deck%init_damage, state%damage, 'damage', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_beta, state%beta, 'beta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_sf, state%sf, 'frictional_slip', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_zeta, state%zeta, 'zeta', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_theta, state%theta, 'theta', why)
      if (len_trim(why) == 0) call check_angles(why)
      if (len_trim(why) == 0) call apply_initial(deck%init_tauf, state%tauf, 'friction_traction', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_sf_strike, state%sf_strike, &
                                                 'sf_strike', why)
      if (len_trim(why) == 0) call apply_initial(deck%init_tauf_strike, state%tauf_strike, &
                                                 'tauf_strike', why)
      if (len_trim(why) == 0 .and. .not. mat%use_friction) call no_friction_traction(why)
      if (len_trim(why) > 0) then
        message = deck%path // ': &initial_state: ' // trim(case_text(deck, icase)) // trim(why)
        stat = status_bad_input
        return
      end if
      if (.not. same_value(deck%init_s(1), unset)) state%s = deck%init_s(1:2)
      if (.not. same_value(deck%init_s(3), unset)) state%s_t2 = deck%init_s(3)
      if (.not. same_value(deck%init_sigma(1), unset)) state%sigma = deck%init_sigma(1:2)
      if (.not. same_value(deck%init_sigma(3), unset)) state%sigma_t2 = deck%init_sigma(3)
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

    !> Each plane's angle lies between its theta_f and theta_0 (the range the UMAT admits for
    !> the same state, with its slack of 4 ulps of theta_0): the wear law only turns the angle
    !> from theta_0 towards theta_f.
    subroutine check_angles(why)
      character(len=*), intent(out) :: why
      real(dp) :: slack, lo, hi
      integer :: k
      why = ''
      do k = 1, n
        slack = 4.0_dp * epsilon(1.0_dp) * abs(mat%theta_init(k))
        lo = min(mat%theta_init(k), mat%thetaf_eff(k)) - slack
        hi = max(mat%theta_init(k), mat%thetaf_eff(k)) + slack
        if (state%theta(k) >= lo .and. state%theta(k) <= hi) cycle
        why = 'theta(' // format_integer(k) // ') = ' // value_str(state%theta(k)) // &
              ' rad is inadmissible: admissible between thetaf and theta0 of plane ' // &
              format_integer(k) // ', ' // degrees(mat%thetaf_eff(k)) // ' and ' // &
              degrees(mat%theta_init(k)) // ' deg (in rad: ' // value_str(mat%thetaf_eff(k)) // &
              ' and ' // value_str(mat%theta_init(k)) // ')'
        return
      end do
    end subroutine check_angles

    !> An angle of the deck, given in degrees and kept in radians, back in degrees for a
    !> message (to 1e-9 deg: the round trip's last bits are not the deck's).
    function degrees(angle) result(text)
      real(dp), intent(in) :: angle
      character(len=:), allocatable :: text
      text = short_real(anint(angle / deg_to_rad * 1.0e9_dp) / 1.0e9_dp)
    end function degrees

    !> Without friction (mu = 0, or the effect off) an admissible state carries no friction
    !> traction, along the dip or the strike (|tau_f| <= mu p = 0); the laws rely on it.
    subroutine no_friction_traction(why)
      character(len=*), intent(out) :: why
      call first_nonzero('friction_traction', state%tauf(1:n), why)
      if (len_trim(why) == 0) call first_nonzero('tauf_strike', state%tauf_strike(1:n), why)
    end subroutine no_friction_traction

    subroutine first_nonzero(name, tauf, why)
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: tauf(:)
      character(len=*), intent(out) :: why
      integer :: k
      why = ''
      do k = 1, size(tauf)
        if (abs(tauf(k)) > 0.0_dp) then
          why = name // '(' // format_integer(k) // ') = ' // format_real(tauf(k)) // &
                ' is inadmissible: without friction (mu = 0 or friction switched off) ' // &
                'admissible ' // name // ' = 0'
          return
        end if
      end do
    end subroutine first_nonzero

  end subroutine deck_case

  !> The loading path of case `icase`: the points' values (deck%n_components per point) and the
  !> arcs of its segments (a 3D path; not allocated otherwise). A sweep over the path's direction
  !> (angle_deg) turns the path; otherwise the deck's path.
  subroutine deck_loading(deck, icase, values, arcs)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    real(dp), allocatable, intent(out) :: values(:, :)
    type(arc_t), allocatable, intent(out) :: arcs(:)
    real(dp), allocatable :: times(:)
    if (deck%sweep_property == sweep_slip_angle) then
      call path_points(deck%path_kind, deck%sweep_values(icase), deck%path_size, deck%path_turns, &
                       deck%path_normal, times, values, arcs)
    else
      values = deck%values
      if (allocated(deck%arcs)) arcs = deck%arcs
    end if
  end subroutine deck_loading

  !> The kind of the RIA of case `icase` (SPEC section 9): 'paper', 'azimuthal' or 'general'.
  pure function deck_ria_name(deck, icase) result(name)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    character(len=:), allocatable :: name
    if (.not. deck%paper_ria) then
      name = 'general'
    else if (case_n_azimuths(deck, icase) > 0) then
      name = 'azimuthal'
    else
      name = 'paper'
    end if
  end function deck_ria_name

  !> The azimuths of the azimuthal RIA of case `icase` (0: not the azimuthal RIA): the deck's
  !> n_azimuths, or the swept one; a sweep over `ria` takes the paper's RIA (0) or the azimuthal
  !> one (1) with the deck's n_azimuths (the table's default where the deck gives none).
  pure integer function case_n_azimuths(deck, icase) result(n_azimuths)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    n_azimuths = deck%n_azimuths
    select case (deck%sweep_property)
    case (prop_ria)
      if (nint(deck%sweep_values(icase)) == ria_paper) then
        n_azimuths = 0
      else if (n_azimuths == 0) then
        n_azimuths = nint(properties(prop_n_azimuths)%default)
      end if
    case (prop_n_azimuths)
      n_azimuths = nint(deck%sweep_values(icase))
    end select
  end function case_n_azimuths

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

  !> The deck's value of property `ip` as deck_set_property sets it (a per-plane angle: the
  !> magnitude of plane 1; thetaf_deg not given: theta0_deg, no wear; zeta0 of plane 1); a row
  !> the deck does not hold: the table's default.
  pure real(dp) function deck_property(d, ip) result(v)
    type(deck_t), intent(in) :: d
    integer, intent(in) :: ip
    select case (ip)
    case (prop_sigma0_n)
      v = d%sigma0_n
    case (prop_sigma0_t)
      v = d%sigma0_t
    case (prop_gc)
      v = d%gc
    case (prop_eta)
      v = d%eta
    case (prop_mu)
      v = d%mu
    case (prop_h_n)
      v = d%h_n
    case (prop_theta0)
      v = abs(d%theta0_deg(1))
    case (prop_thetaf)
      v = abs(d%thetaf_deg(1))
      if (.not. d%thetaf_given) v = abs(d%theta0_deg(1))
    case (prop_zeta0)
      v = d%zeta0(1)
    case (prop_prefractured)
      v = merge(1.0_dp, 0.0_dp, d%prefractured)
    case (prop_scheme)
      v = real(d%solver%scheme, dp)
    case (prop_substep_tol)
      v = d%solver%substep_tol
    case (prop_effect_damage:prop_effect_wear)
      v = merge(1.0_dp, 0.0_dp, d%effect(ip - prop_effect_damage + 1))
    case default
      v = properties(ip)%default
    end select
  end function deck_property

  !> "case 3 (h_n = 0.5 mm): " for sweeps, '' otherwise.
  function case_text(deck, icase) result(text)
    type(deck_t), intent(in) :: deck
    integer, intent(in) :: icase
    character(len=:), allocatable :: text
    text = ''
    if (deck%sweep_property /= 0) text = '&sweep case ' // format_integer(icase) // ' (' // &
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

  !> The number of microplanes (name = 'n_planes') or azimuths ('n_azimuths') the deck
  !> declares in &microplanes when it is given (and reads as an integer), else 0 (not given, or
  !> not readable: left to the namelist read).
  function planes_in_deck(text, micro, name) result(n)
    character(len=*), intent(in) :: text
    type(group_scan_t), intent(in) :: micro
    character(len=*), intent(in) :: name   !< 'n_planes' or 'n_azimuths'
    integer :: n, k, ios
    character(len=:), allocatable :: value
    n = 0
    do k = 1, micro%n
      if (trim(micro%a(k)%name) /= name .or. len_trim(micro%a(k)%subscript) > 0) cycle
      value = value_text(text, micro%a(k))
      read (value, *, iostat=ios) n
      if (ios /= 0) n = 0
    end do
  end function planes_in_deck

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

  !> '' if eta, h_n and each plane's zeta0 are at least 1e-100, the bound below which the
  !> library's interlock_material_prepare refuses them (the law takes their inverses), else why
  !> not, naming the one that is not (so that the message is given under its own group;
  !> `per_plane`: the deck gives zeta0 per plane).
  function inverse_check(mat, per_plane) result(why)
    type(interlock_material_t), intent(in) :: mat
    logical, intent(in) :: per_plane
    character(len=256) :: why
    real(dp), parameter :: smallest_inverted = 1.0e-100_dp
    integer :: k
    why = ''
    if (mat%eta < smallest_inverted) why = 'eta = ' // value_str(mat%eta) // &
      ' is inadmissible: admissible eta >= 1e-100 (the law takes its inverse)'
    if (mat%h_n < smallest_inverted) why = 'h_n = ' // value_str(mat%h_n) // &
      ' is inadmissible: admissible h_n >= 1e-100 mm (the law takes its inverse)'
    if (len_trim(why) > 0) return
    do k = 1, mat%n_planes
      if (mat%zeta0(k) >= smallest_inverted) cycle
      why = 'zeta0 = ' // value_str(mat%zeta0(k)) // ' is inadmissible'
      if (per_plane) why = 'zeta0(' // format_integer(k) // ') = ' // value_str(mat%zeta0(k)) // &
                           ' is inadmissible'
      why = trim(why) // ': admissible zeta0 >= 1e-100 N/mm (the law takes its inverse)'
      return
    end do
  end function inverse_check

  !> '' if the derived scales of the material are representable, else why not: the opening
  !> lengths s_c = 2 Gc / sigma0, s_0 = (1 - eta) s_c [mm] and the stiffnesses K = sigma0 / s_0
  !> [MPa/mm] must lie in [2^-300, 2^300] (about 4.9e-91 .. 2.0e90), the range the library's
  !> interlock_material_prepare admits (computed in logarithms, so nothing overflows here; the
  !> message says it in the deck's terms, per component).
  function scale_check(mat) result(why)
    type(interlock_material_t), intent(in) :: mat
    character(len=256) :: why
    real(dp), parameter :: lim = 300.0_dp * log(2.0_dp)
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
              short_real(anint(ln_k / log(10.0_dp))) // ' MPa/mm: admissible 2^-300 <= s_c' // &
              c // ', s_0' // c // ' <= 2^300 mm and 2^-300 <= K_' // c // ' <= 2^300 MPa/mm ' // &
              '(2^300 = 2.04e90)'
        return
      end if
    end do
  end function scale_check

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

end module interlock_deck
