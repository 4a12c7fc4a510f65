!> Replay decks (src/api/interlock_replay.f90): a failing update is written as a deck, the deck is
!> read back with the group definitions of docs/deck-format.md, and the update rebuilt from
!> the deck's values fails the same way (and succeeds with the default solver).
module test_stability_replay_suite
  use interlock
  use interlock_replay, only: interlock_write_replay_deck
  use interlock_assert
  implicit none
  private
  public :: collect_stability_replay, read_deck, deck_t

  character(len=*), parameter :: deck = 'stability_replay_deck.nml'

  !> What the deck holds, as read back.
  type :: deck_t
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old
    real(dp) :: s_new(2) = 0.0_dp
    integer :: n_steps = 0
    integer :: max_cuts = -1
    character(len=16) :: normal_control = '', tangential_control = ''
  end type deck_t

contains

  subroutine collect_stability_replay()
    call run_case('replay_deck_reproduces_failure', test_replay_deck)
  end subroutine collect_stability_replay

  !> Fig. 11 interface (Table 2, pre-fractured, theta_0 = 30, theta_f = 7 deg) with fast wear,
  !> a large slip increment under compression, implicit wear with no Newton iteration allowed
  !> (every sub-increment's wear equation must be solved at its first point).
  subroutine hard_case(mat, solver, old, s_new)
    type(interlock_material_t), intent(out) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(interlock_state_t), intent(out) :: old
    real(dp), intent(out) :: s_new(2)
    type(interlock_state_t) :: virgin
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), tangent(2, 2)
    integer :: stat
    character(len=message_len) :: message
    mat%sigma0_n = 0.025_dp
    mat%sigma0_t = 0.025_dp
    mat%gc = 0.0005_dp
    mat%eta = 0.99_dp
    mat%mu = 0.5_dp
    mat%h_n = 2.0_dp
    mat%prefractured = .true.
    call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 1.0_dp)
    call interlock_material_prepare(mat, stat, message)
    call assert_equal(status_ok, stat, 'prepare: ' // trim(message))
    solver%scheme = scheme_implicit
    call interlock_state_init(mat, virgin)
    call interlock_update(mat, solver, [-0.004_dp, 0.0_dp], virgin, old, sigma, tangent, info)
    call assert_equal(status_ok, info%status, 'preload')
    s_new = [-0.004_dp, 0.8_dp]
    solver%newton_max_iterations = 0
  end subroutine hard_case

  subroutine test_replay_deck()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info, info2
    type(deck_t) :: d
    real(dp) :: s_new(2), sigma(2), tangent(2, 2)
    integer :: ios, stat, k
    character(len=message_len) :: message
    logical :: exists

    call hard_case(mat, solver, old, s_new)
    call interlock_update(mat, solver, s_new, old, new, sigma, tangent, info)
    call assert_equal(status_local_failure, info%status, 'the hard case fails locally')

    call interlock_write_replay_deck(deck, mat, solver, old, s_new, &
      'test: ' // trim(info%message), ios)
    call assert_equal(0, ios, 'deck written')
    inquire (file=deck // '.tmp', exist=exists)
    call assert_true(.not. exists, 'the temporary file was renamed')

    call read_deck(deck, d, ios)
    call assert_equal(0, ios, 'deck parses as namelists')
    if (ios /= 0) return
    call assert_true(d%normal_control == 'separation' .and. &
                     d%tangential_control == 'separation', 'separation-driven loading')
    call assert_equal(1, d%n_steps, 'a single step')
    call interlock_material_prepare(d%mat, stat, message)
    call assert_equal(status_ok, stat, 'the deck material is admissible: ' // trim(message))
    ! the values read back are the ones written (bit for bit; angles via degrees to 1 ulp)
    call assert_equal(mat%sigma0_n, d%mat%sigma0_n, 0.0_dp, 'sigma0_n')
    call assert_equal(mat%eta, d%mat%eta, 0.0_dp, 'eta')
    call assert_equal(mat%h_n, d%mat%h_n, 0.0_dp, 'h_n')
    do k = 1, mat%n_planes
      call assert_equal(mat%theta0(k), d%mat%theta0(k), 4.0_dp * spacing(mat%theta0(k)), 'theta0')
      call assert_equal(old%beta(k), d%old%beta(k), 0.0_dp, 'beta')
      call assert_equal(old%theta(k), d%old%theta(k), 0.0_dp, 'theta')
      call assert_equal(old%tauf(k), d%old%tauf(k), 0.0_dp, 'friction traction')
    end do
    call assert_equal(old%s, d%old%s, 0.0_dp, 'separation')
    call assert_equal(old%sigma, d%old%sigma, 0.0_dp, 'traction')
    call assert_equal(s_new, d%s_new, 0.0_dp, 'end separation')
    call assert_equal(solver%scheme, d%solver%scheme, 'scheme')
    call assert_equal(0, d%max_cuts, 'the deck asks for no step cutting')
    ! the core's Newton bound is not a deck variable (the deck's newton_* are interlock-history's
    ! mixed control): the deck records it in a comment, the replay applies it
    d%solver%newton_max_iterations = solver%newton_max_iterations

    ! re-run from the deck's values: the same failure
    call interlock_update(d%mat, d%solver, d%s_new, d%old, new, sigma, tangent, info2)
    call assert_equal(info%status, info2%status, 'the replay fails with the same status')
    call assert_true(info%message == info2%message, 'and the same message: ' // trim(info2%message))
    ! and with the default Newton bound the update goes through
    d%solver%newton_max_iterations = 60
    call interlock_update(d%mat, d%solver, d%s_new, d%old, new, sigma, tangent, info2)
    call assert_equal(status_ok, info2%status, 'the replayed update succeeds with 60 iterations')
    call assert_true(info2%newton_iterations > 1, 'it needs more than one Newton iteration')
  end subroutine test_replay_deck

  !> Read a deck with the group definitions of docs/deck-format.md (each group in its own
  !> scope: some names, e.g. `damage`, appear in two groups with different types).
  subroutine read_deck(path, d, ios)
    character(len=*), intent(in) :: path
    type(deck_t), intent(out) :: d
    integer, intent(out) :: ios
    integer :: u
    open (newunit=u, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) return
    call read_interface(u, d, ios); if (ios /= 0) goto 9
    call read_microplanes(u, d, ios); if (ios /= 0) goto 9
    call read_effects(u, d, ios); if (ios /= 0) goto 9
    call read_solver(u, d, ios); if (ios /= 0) goto 9
    call read_initial_state(u, d, ios); if (ios /= 0) goto 9
    call read_loading(u, d, ios)
9   close (u)
  end subroutine read_deck

  subroutine read_interface(u, d, ios)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: d
    integer, intent(out) :: ios
    real(dp) :: sigma0_n, sigma0_t, gc, eta, mu, h_n
    logical :: prefractured
    namelist /interface/ sigma0_n, sigma0_t, gc, eta, mu, h_n, prefractured
    h_n = huge(1.0_dp)
    prefractured = .false.
    rewind (u)
    read (u, nml=interface, iostat=ios)
    d%mat%sigma0_n = sigma0_n
    d%mat%sigma0_t = sigma0_t
    d%mat%gc = gc
    d%mat%eta = eta
    d%mat%mu = mu
    d%mat%h_n = h_n
    d%mat%prefractured = prefractured
  end subroutine read_interface

  subroutine read_microplanes(u, d, ios)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: d
    integer, intent(out) :: ios
    integer :: n_planes
    real(dp), dimension(max_planes) :: gamma_hat, theta0_deg, thetaf_deg, zeta0
    namelist /microplanes/ n_planes, gamma_hat, theta0_deg, thetaf_deg, zeta0
    n_planes = 0
    gamma_hat = 0.0_dp
    theta0_deg = 0.0_dp
    thetaf_deg = 0.0_dp
    zeta0 = huge(1.0_dp)
    rewind (u)
    read (u, nml=microplanes, iostat=ios)
    d%mat%n_planes = n_planes
    d%mat%gamma_hat = gamma_hat
    d%mat%theta0 = theta0_deg * deg_to_rad
    d%mat%thetaf = thetaf_deg * deg_to_rad
    d%mat%zeta0 = zeta0
    d%mat%phi = 0.0_dp
  end subroutine read_microplanes

  subroutine read_effects(u, d, ios)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: d
    integer, intent(out) :: ios
    logical :: damage, friction, interlocking, finite_depth, wear
    namelist /effects/ damage, friction, interlocking, finite_depth, wear
    damage = .true.
    friction = .true.
    interlocking = .true.
    finite_depth = .true.
    wear = .true.
    rewind (u)
    read (u, nml=effects, iostat=ios)
    d%mat%effect = [damage, friction, interlocking, finite_depth, wear]
  end subroutine read_effects

  subroutine read_solver(u, d, ios)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: d
    integer, intent(out) :: ios
    character(len=16) :: scheme
    real(dp) :: substep_tol, newton_tol
    integer :: newton_max_iterations, max_cuts
    namelist /solver/ scheme, substep_tol, newton_tol, newton_max_iterations, max_cuts
    scheme = 'explicit'
    substep_tol = 0.0_dp
    newton_tol = 1.0e-12_dp
    newton_max_iterations = 50
    max_cuts = -1
    rewind (u)
    read (u, nml=solver, iostat=ios)
    d%solver%scheme = merge(scheme_implicit, scheme_explicit, scheme == 'implicit')
    d%solver%substep_tol = substep_tol
    d%max_cuts = max_cuts
  end subroutine read_solver

  subroutine read_initial_state(u, d, ios)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: d
    integer, intent(out) :: ios
    real(dp), dimension(max_planes) :: damage, beta, frictional_slip, zeta, theta, &
                                       friction_traction
    real(dp) :: separation(2), traction(2)
    namelist /initial_state/ damage, beta, frictional_slip, zeta, theta, friction_traction, &
                             separation, traction
    damage = 0.0_dp
    beta = 0.0_dp
    frictional_slip = 0.0_dp
    zeta = 0.0_dp
    theta = 0.0_dp
    friction_traction = 0.0_dp
    separation = 0.0_dp
    traction = 0.0_dp
    rewind (u)
    read (u, nml=initial_state, iostat=ios)
    d%old%damage = damage
    d%old%beta = beta
    d%old%sf = frictional_slip
    d%old%zeta = zeta
    d%old%theta = theta
    d%old%tauf = friction_traction
    d%old%s = separation
    d%old%sigma = traction
  end subroutine read_initial_state

  subroutine read_loading(u, d, ios)
    integer, intent(in) :: u
    type(deck_t), intent(inout) :: d
    integer, intent(out) :: ios
    character(len=16) :: normal_control, tangential_control
    real(dp) :: times(100), normal(100), tangential(100)
    integer :: steps(100), cycles
    namelist /loading/ normal_control, tangential_control, times, normal, tangential, steps, cycles
    steps = 0
    normal = 0.0_dp
    tangential = 0.0_dp
    cycles = 1
    rewind (u)
    read (u, nml=loading, iostat=ios)
    d%normal_control = normal_control
    d%tangential_control = tangential_control
    d%s_new = [normal(2), tangential(2)]
    d%n_steps = count(steps > 0)
    if (d%n_steps == 1) d%n_steps = steps(1)
    if (.not. all(abs(d%old%s - [normal(1), tangential(1)]) <= 0.0_dp)) ios = -2
  end subroutine read_loading

end module test_stability_replay_suite

program test_stability_replay
  use test_stability_replay_suite, only: collect_stability_replay
  use interlock_assert, only: suite_summary
  implicit none
  call collect_stability_replay()
  if (suite_summary('test_stability_replay') /= 0) error stop 1
end program test_stability_replay
