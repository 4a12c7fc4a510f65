!> Updates the fuzzers found whose tangent matched no finite difference, each replayed from its
!> exact input (material, solver, start state, separation) and checked as the fuzzer checks
!> it (fuzz_fd_check): the update is accepted and its tangent matches a central or a
!> Richardson-extrapolated one-sided difference.
program test_fuzz_cases
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock
  use interlock_assert, only: assert_true, run_case, suite_summary
  use fuzz_fd_check, only: check_tangent_3d
  implicit none

  call run_case('beyond_bound_seed2_surface_path', beyond_bound_seed2_surface_path)
  call run_case('beyond_bound_seed2_tiny_zeta0', beyond_bound_seed2_tiny_zeta0)
  if (suite_summary('stability_fuzz_cases') /= 0) error stop 1

contains

  !> Every effect on, the material prepared; the trapezoidal scheme with error control to
  !> substep_tol; the initial state.
  subroutine prepare_trapezoidal(mat, substep_tol, solver, old)
    type(interlock_material_t), intent(inout) :: mat
    real(dp), intent(in) :: substep_tol
    type(interlock_solver_t), intent(out) :: solver
    type(interlock_state_3d_t), intent(out) :: old
    integer :: stat
    character(len=message_len) :: msg
    mat%effect = .true.
    call interlock_material_prepare(mat, stat, msg)
    call assert_true(stat == status_ok, 'material: ' // trim(msg))
    solver%scheme = scheme_trapezoidal
    solver%substep_tol = substep_tol
    call interlock_state_3d_init(mat, old)
  end subroutine prepare_trapezoidal

  !> Plane k ends at s_kn = 0 (to round-off) and each column of the tangent is the one-sided
  !> derivative on the side where s_j moves the plane into contact (SPEC D13), against the
  !> one-sided difference Richardson-extrapolated from steps h and h/2 (fast wear curves the
  !> traction within h).
  subroutine closed_side(mat, solver, old, s, k)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3)
    integer, intent(in) :: k
    type(interlock_state_3d_t) :: new, tmp
    type(interlock_info_t) :: info
    real(dp) :: sigma(3), tangent(3, 3), normal(3), f1(3), f2(3), k3(3, 3), sp(3), h, dir, &
                richardson(3)
    integer :: j
    character(len=160) :: what
    call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    normal = [cos(new%theta(k)), sin(new%theta(k)) * cos(mat%phi(k)), &
              sin(new%theta(k)) * sin(mat%phi(k))]
    call assert_true(abs(dot_product(normal, s)) <= 1.0e-15_dp, 'plane at s_kn = 0')
    h = 1.0e-7_dp * maxval(abs(s))
    do j = 1, 3
      dir = -sign(1.0_dp, normal(j))
      sp = s
      sp(j) = s(j) + dir * h
      call interlock_update_3d(mat, solver, sp, old, tmp, f1, k3, info)
      sp(j) = s(j) + dir * 0.5_dp * h
      call interlock_update_3d(mat, solver, sp, old, tmp, f2, k3, info)
      richardson = (2.0_dp * (f2 - sigma) / (0.5_dp * h) - (f1 - sigma) / h) * dir
      write (what, '(a,i0,a,3es12.4,a,3es12.4)') 'column ', j, ': tangent', tangent(:, j), &
        ' closing side', richardson
      call assert_true(maxval(abs(tangent(:, j) - richardson)) <= 1.0e-3_dp * &
                       max(maxval(abs(richardson)), maxval(abs(tangent(:, j)))), trim(what))
    end do
  end subroutine closed_side

  !> The update from `old` to s is accepted and its tangent passes the fuzzers' check.
  subroutine replay_3d(mat, solver, old, s)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t) :: new
    type(interlock_info_t) :: info
    real(dp) :: sigma(3), tangent(3, 3)
    integer(int64) :: n_checks, n_skipped
    character(len=200) :: what
    call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    call assert_true(info%status == status_ok, 'update: ' // trim(info%message))
    n_checks = 0
    n_skipped = 0
    call check_tangent_3d(mat, solver, old, s, sigma, tangent, what, n_checks, n_skipped)
    call assert_true(len_trim(what) == 0, 'tangent: ' // trim(what))
  end subroutine replay_3d

  !> `interlock-fuzz --3d 300000 --beyond-bound --seed 2`, update 214540: six planes with
  !> azimuths, pre-fractured, fast wear (zeta_0 = 7.8 N/mm), trapezoidal with error control
  !> (582 sub-increments), a separation path through the origin (the end separation is 47.6
  !> times the start one). Plane 3 slides, wears until it just loses contact, and from then on
  !> the path runs in its surface: its s_kn is 0 or +-1.4e-17 (round-off) at the end of each
  !> of the last 260 sub-increments, every one of them the tie s_kn = 0 for the derivatives. The
  !> traction is 0 at the end and on the opening side; the closing side's derivative is small
  !> (0.24 MPa/mm). The fuzzers' check skips a column whose one-sided differences disagree;
  !> SPEC D13 asks for the closing side's, which closed_side checks.
  subroutine beyond_bound_seed2_surface_path()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old
    real(dp) :: s(3)

    mat%sigma0_n = 4.0223326531577435e+01_dp
    mat%sigma0_t = 3.9662514326172889e+01_dp
    mat%gc = 3.6791032856979022e+01_dp
    mat%eta = 9.9967233789611354e-01_dp
    mat%mu = 1.3242561754592577e+00_dp
    mat%h_n = huge(1.0_dp)
    mat%prefractured = .true.
    mat%n_planes = 6
    mat%gamma_hat(1:6) = [2.7592098682477612e-01_dp, 2.2710639212112160e-01_dp, &
      7.8669905961126038e-02_dp, 3.3667872859559966e-01_dp, 3.1066836167598602e-02_dp, &
      5.0557150329778033e-02_dp]
    mat%theta0(1:6) = [-8.4252114759453212e-01_dp, 9.1086027662918956e-01_dp, &
      -1.3715830610202024e+00_dp, -1.3211321936057385e+00_dp, -4.2929518123590643e-01_dp, &
      1.5893612576234151e-01_dp]
    mat%thetaf(1:6) = [-2.7677233980951673e-02_dp, 2.0833855399832601e-01_dp, &
      -1.0143472469415941e-02_dp, -8.7092824159602111e-01_dp, -1.2730435914187033e-01_dp, &
      1.4909353773592812e-01_dp]
    mat%zeta0(1:6) = 7.7930797379742032e+00_dp
    mat%phi(1:6) = [-1.5041904254583807e+00_dp, 3.9355884750202144e+00_dp, &
      -3.2984527093520466e+00_dp, 4.4449701218400879e+00_dp, -3.1631336213787170e-01_dp, &
      -1.5172545536002575e+00_dp]
    call prepare_trapezoidal(mat, 6.0100113849687975e-05_dp, solver, old)
    old%damage(1:6) = 1.0_dp
    old%beta(1:6) = 3.05192449214850740e+03_dp
    old%sf(1:6) = [3.50300908360978713e-03_dp, -4.88046027065697566e-04_dp, &
      5.02211702912514456e-04_dp, 2.81958639818754133e-03_dp, -1.85014330975611990e-03_dp, &
      5.04912785874458005e-04_dp]
    old%zeta(1:6) = [0.0_dp, 0.0_dp, 7.46670827431898387e-02_dp, 1.34480598718358130e-01_dp, &
      0.0_dp, 0.0_dp]
    old%theta(1:6) = [-8.42521147594532116e-01_dp, 9.10860276629189558e-01_dp, &
      -1.35860112190122906e+00_dp, -1.31342993629185467e+00_dp, -4.29295181235906431e-01_dp, &
      1.58936125762341507e-01_dp]
    old%tauf(1:6) = [0.0_dp, 0.0_dp, 2.63316948908824770e+02_dp, 9.37358257749511097e+01_dp, &
      0.0_dp, 0.0_dp]
    old%sf_strike(1:6) = [-4.47067081215914847e-03_dp, -2.18493329433109423e-03_dp, &
      2.24770791000102011e-04_dp, -2.57158772691374899e-03_dp, -2.64862724889534159e-03_dp, &
      -4.45651188703882848e-03_dp]
    old%tauf_strike(1:6) = [0.0_dp, 0.0_dp, 1.17078652281771539e+02_dp, &
      -8.52281366196048253e+01_dp, 0.0_dp, 0.0_dp]
    old%s = [3.75315151788633596e-03_dp, -4.39056513655067780e-03_dp]
    old%s_t2 = -1.34984392089101284e-03_dp
    old%sigma = [3.89660287111173247e+01_dp, -6.03060143294925481e+01_dp]
    old%sigma_t2 = -3.60080912187136519e+01_dp
    s = [1.78545962955315135e-01_dp, -2.08869180071087207e-01_dp, -6.42151486680701405e-02_dp]

    call replay_3d(mat, solver, old, s)
    call closed_side(mat, solver, old, s, 3)
  end subroutine beyond_bound_seed2_surface_path

  !> `interlock-fuzz --3d 3000000 --beyond-bound --seed 2`, update 443070: the azimuthal RIA
  !> (N_a = 3, theta_0 = 42.6 deg, theta_f = 3.3 deg) from the virgin state, the trapezoidal
  !> scheme, plane 6 with zeta_0 = 1e-64 N/mm (an admissible garbled value). Plane 6 slides at
  !> its initial angle and sticks at its final one, so the wear equation's root lies where it
  !> switches, within zeta ~ 1e-64 of zeta_o = 0, and the iteration ends on the stuck side (no
  !> wear driver, a friction traction): the plane is taken stuck there, not at the bracket's
  !> lower end (unworn and sliding). Column 1 of the differences, (3.67e6, -1.41e5, -1.02e6)
  !> MPa/mm, agrees to 6 digits from steps 3.5e-10 down to 3.5e-15.
  subroutine beyond_bound_seed2_tiny_zeta0()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old
    real(dp) :: s(3), th0, thf

    mat%sigma0_n = 1.1708404583598458e+02_dp
    mat%sigma0_t = 3.5753043048694514e+02_dp
    mat%gc = 5.0295909149133833e-01_dp
    mat%eta = 9.9635940735553274e-01_dp
    mat%mu = 7.0014950610357707e-01_dp
    mat%h_n = huge(1.0_dp)
    mat%prefractured = .false.
    mat%n_planes = 7
    th0 = 7.4369934885196320e-01_dp
    thf = 5.7776904599958184e-02_dp
    mat%gamma_hat(1:7) = [1.1111111111111110e-01_dp, 3.3333333333333331e-01_dp, &
      1.1111111111111110e-01_dp, 1.1111111111111110e-01_dp, 1.1111111111111110e-01_dp, &
      1.1111111111111110e-01_dp, 1.1111111111111110e-01_dp]
    mat%theta0(1:7) = [-th0, 0.0_dp, th0, -th0, th0, -th0, th0]
    mat%thetaf(1:7) = [-thf, 0.0_dp, thf, -thf, thf, -thf, thf]
    mat%zeta0(1:7) = huge(1.0_dp)
    mat%zeta0(6) = 1.0038848328181973e-64_dp
    mat%phi(1:7) = [0.0_dp, 0.0_dp, 0.0_dp, 1.0471975511965976e+00_dp, &
      1.0471975511965976e+00_dp, 2.0943951023931953e+00_dp, 2.0943951023931953e+00_dp]
    call prepare_trapezoidal(mat, 1.0637710449713071e-03_dp, solver, old)
    s = [-3.5097549731983784e-05_dp, -1.0471795598336267e-06_dp, -7.2492041785926331e-06_dp]

    call replay_3d(mat, solver, old, s)
  end subroutine beyond_bound_seed2_tiny_zeta0

end program test_fuzz_cases
