!> The input deck of interlock-history (docs/deck-format.md): the deck type and its reader.
!> Namelist groups read with iostat/iomsg, validated through the library's material table
!> (check_property, format_range); every case is built once (interlock_deck_case, through the
!> material table's one mapping to the material) to validate it. Every error names the deck file, the group,
!> the variable and the admissible range; nothing is ever stopped here (status + message).
!> Before any namelist read the file is checked as text (interlock_deck_text): size, control
!> bytes, line ends, the groups (unknown, repeated, unclosed groups and text outside every group
!> are errors, required groups must be present) and the variables of each group (unknown or
!> repeated variables are errors). A value that cannot be read is found by re-reading each
!> assignment of the group alone, so that the message names the variable.
module interlock_deck
  use interlock, only: dp, deg_to_rad, pi, max_planes, max_azimuths, &
      interlock_material_t, interlock_solver_t, interlock_state_3d_t, interlock_state_3d_init, &
      material_from_rows, umat_controls_t, scheme_explicit, scheme_implicit, &
      scheme_trapezoidal, properties, property_index, check_property, format_range, &
      format_integer, format_real, n_properties, property_defaults, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, prop_max_dd, &
      prop_max_dtheta, prop_tangent, prop_effect_damage, prop_effect_wear, is_nan_value, same_value, &
      is_infinite_value, prop_ria, prop_n_azimuths, ria_paper, ria_azimuthal, &
      status_ok, status_bad_input
  use interlock_step_solver, only: control_t
  use interlock_path, only: arc_t, path_points
  use interlock_deck_text, only: group_scan_t, scan_deck, probe_text, value_text, lower, &
      load_text, max_deck_bytes
  use interlock_deck_schema, only: n_datasets, history_datasets, curves_datasets, &
      first_3d_dataset, n_always, datasets_text, dataset_index
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
  integer, parameter :: max_cycles = 100000
  integer, parameter :: name_len = 64, path_len = 4096

  !> &sweep parameter = 'angle_deg': the direction of the &loading path (not a property)
  integer, parameter :: sweep_slip_angle = -1
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
    !> The value of each row of the material table as the deck gives it (&interface,
    !> &microplanes, &effects, &solver; the paper's or the azimuthal RIA), in the table's
    !> units; the table's default where the deck gives none. interlock_material_rows maps them
    !> to the material. Over a general RIA the rows theta0_deg, thetaf_deg and zeta0 hold the
    !> magnitudes of plane 1 (what a sweep or a fit starts from).
    real(dp) :: rows(n_properties) = property_defaults
    !> The rows a fit sets over the deck's values (deck_set_property): over a general RIA they
    !> set every plane.
    logical :: varied(n_properties) = .false.
    ! &microplanes
    logical :: paper_ria = .true.
    logical :: thetaf_given = .false.   !< without thetaf_deg the planes do not wear (theta_f = theta_0)
    !> a general RIA (paper_ria false): its planes as given (the paper's RIA: 3 planes, and no
    !> per-plane value here)
    integer :: n_planes = 3
    real(dp), dimension(max_planes) :: gamma_hat = 0.0_dp, theta0_deg = 0.0_dp, &
                                       thetaf_deg = 0.0_dp, zeta0 = huge(1.0_dp), phi_deg = 0.0_dp
    logical :: azimuths_given = .false. !< phi_deg given (a general RIA in 3D)
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
    ! &solver (besides the rows scheme and substep_tol)
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

  public :: deck_property, deck_scheme

  !> The cases of a deck (submodule interlock_deck_case).
  interface
    !> The material, solver and initial state of case `icase` (the sweep value applied).
    module subroutine deck_case(deck, icase, mat, solver, state, label, stat, message)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: icase
      type(interlock_material_t), intent(out) :: mat
      type(interlock_solver_t), intent(out) :: solver
      type(interlock_state_3d_t), intent(out) :: state
      character(len=:), allocatable, intent(out) :: label
      integer, intent(out) :: stat
      character(len=*), intent(out) :: message
    end subroutine deck_case
    !> The loading path of case `icase`: the points' values and the arcs of its segments.
    module subroutine deck_loading(deck, icase, values, arcs)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: icase
      real(dp), allocatable, intent(out) :: values(:, :)
      type(arc_t), allocatable, intent(out) :: arcs(:)
    end subroutine deck_loading
    !> The kind of the RIA of case `icase`: 'paper', 'azimuthal' or 'general'.
    module pure function deck_ria_name(deck, icase) result(name)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: icase
      character(len=:), allocatable :: name
    end function deck_ria_name
    !> The azimuths of the azimuthal RIA of case `icase` (0: not the azimuthal RIA).
    module pure integer function case_n_azimuths(deck, icase) result(n_azimuths)
      type(deck_t), intent(in) :: deck
      integer, intent(in) :: icase
    end function case_n_azimuths
    !> Set row `ip` of the material table of the deck `d` to `v` (a sweep, a fit).
    module pure subroutine deck_set_property(d, ip, v)
      type(deck_t), intent(inout) :: d
      integer, intent(in) :: ip
      real(dp), intent(in) :: v
    end subroutine deck_set_property
    !> The integration scheme of the deck (row `scheme`).
    module pure integer function deck_scheme(d)
      type(deck_t), intent(in) :: d
    end function deck_scheme
    !> The deck's value of row `ip`.
    module pure real(dp) function deck_property(d, ip) result(v)
      type(deck_t), intent(in) :: d
      integer, intent(in) :: ip
    end function deck_property
  end interface

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



  ! ------------------------------------------------------------------- helpers


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
