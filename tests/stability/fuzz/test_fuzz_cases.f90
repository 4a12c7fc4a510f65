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
  call run_case('fuzz3d_seed20261126_explicit_planes_at_tie', &
                fuzz3d_seed20261126_explicit_planes_at_tie)
  call run_case('fuzz3d_seed12345_root_at_contact_loss', fuzz3d_seed12345_root_at_contact_loss)
  call run_case('fuzz3d_seed20261126_newton_start_open_side', &
                fuzz3d_seed20261126_newton_start_open_side)
  call run_case('beyond_bound_seed6_explicit_surface_overshoot', &
                beyond_bound_seed6_explicit_surface_overshoot)
  if (suite_summary('stability_fuzz_cases') /= 0) error stop 1

contains

  !> Every effect on, the material prepared; the scheme with error control to substep_tol; the
  !> initial state.
  subroutine prepare(mat, scheme, substep_tol, solver, old)
    type(interlock_material_t), intent(inout) :: mat
    integer, intent(in) :: scheme
    real(dp), intent(in) :: substep_tol
    type(interlock_solver_t), intent(out) :: solver
    type(interlock_state_3d_t), intent(out) :: old
    integer :: stat
    character(len=message_len) :: msg
    mat%effect = .true.
    call interlock_material_prepare(mat, stat, msg)
    call assert_true(stat == status_ok, 'material: ' // trim(msg))
    solver%scheme = scheme
    solver%substep_tol = substep_tol
    call interlock_state_3d_init(mat, old)
  end subroutine prepare

  !> Plane k ends at s_kn = 0 (to round-off) and each column of the tangent is the one-sided
  !> derivative on the side where s_j moves the plane into contact (SPEC D13).
  subroutine closed_side(mat, solver, old, s, k)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3)
    integer, intent(in) :: k
    type(interlock_state_3d_t) :: new
    type(interlock_info_t) :: info
    real(dp) :: sigma(3), tangent(3, 3), normal(3), d(3)
    integer :: j
    character(len=20) :: what
    call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    normal = plane_normal(mat, new, k)
    call assert_true(abs(dot_product(normal, s)) <= 1.0e-15_dp, 'plane at s_kn = 0')
    do j = 1, 3
      d = 0.0_dp
      d(j) = -sign(1.0_dp, normal(j))
      write (what, '(a,i0)') 'column ', j
      call one_sided(mat, solver, old, s, sigma, tangent, d, trim(what))
    end do
  end subroutine closed_side

  !> The planes `ties` end at s_kn = 0 (to round-off) and the tangent's derivative along d =
  !> -(sum of their normals), which moves every one of them into contact, is the one-sided
  !> derivative on that side (SPEC D13 for each plane); so is each column j whose s_j moves
  !> them all into contact on one side.
  subroutine closed_together(mat, solver, old, s, ties)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3)
    integer, intent(in) :: ties(:)
    type(interlock_state_3d_t) :: new
    type(interlock_info_t) :: info
    real(dp) :: sigma(3), tangent(3, 3), d(3), normals(3, size(ties))
    integer :: i, j
    character(len=20) :: what
    call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    do i = 1, size(ties)
      normals(:, i) = plane_normal(mat, new, ties(i))
    end do
    do j = 1, 3
      if (all(normals(j, :) > 0.0_dp) .or. all(normals(j, :) < 0.0_dp)) then
        d = 0.0_dp
        d(j) = -sign(1.0_dp, normals(j, 1))
        write (what, '(a,i0)') 'column ', j
        call one_sided(mat, solver, old, s, sigma, tangent, d, trim(what))
      end if
    end do
    d = 0.0_dp
    do i = 1, size(ties)
      call assert_true(abs(dot_product(plane_normal(mat, new, ties(i)), s)) <= 1.0e-15_dp, &
                       'plane at s_kn = 0')
      d = d - plane_normal(mat, new, ties(i))
    end do
    d = d / norm2(d)
    do i = 1, size(ties)
      call assert_true(dot_product(plane_normal(mat, new, ties(i)), d) < 0.0_dp, &
                       'd moves every plane into contact')
    end do
    call one_sided(mat, solver, old, s, sigma, tangent, d, 'closing all')
  end subroutine closed_together

  !> The normal of plane k at its angle in `state`.
  pure function plane_normal(mat, state, k) result(normal)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: k
    real(dp) :: normal(3)
    normal = [cos(state%theta(k)), sin(state%theta(k)) * cos(mat%phi(k)), &
              sin(state%theta(k)) * sin(mat%phi(k))]
  end function plane_normal

  !> tangent . d is the one-sided derivative of the traction along d (|d| = 1) at s, the
  !> difference Richardson-extrapolated from steps h and h/2 (fast wear curves the traction
  !> within h); h = 1e-6 |s|, where the round-off of the wear roots (the iteration stops within
  !> its tolerance: 1e-12 MPa on the surface path below) stays far below the differences.
  subroutine one_sided(mat, solver, old, s, sigma, tangent, d, label)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3), sigma(3), tangent(3, 3), d(3)
    character(len=*), intent(in) :: label
    type(interlock_state_3d_t) :: tmp
    type(interlock_info_t) :: info
    real(dp) :: f1(3), f2(3), k3(3, 3), h, richardson(3), kd(3)
    character(len=160) :: what
    h = 1.0e-6_dp * maxval(abs(s))
    call interlock_update_3d(mat, solver, s + h * d, old, tmp, f1, k3, info)
    call interlock_update_3d(mat, solver, s + 0.5_dp * h * d, old, tmp, f2, k3, info)
    richardson = 2.0_dp * (f2 - sigma) / (0.5_dp * h) - (f1 - sigma) / h
    kd = matmul(tangent, d)
    write (what, '(a,a,3es12.4,a,3es12.4)') label, ': tangent', kd, ' closing side', richardson
    call assert_true(maxval(abs(kd - richardson)) <= 1.0e-3_dp * &
                     max(maxval(abs(richardson)), maxval(abs(kd))), trim(what))
  end subroutine one_sided

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
    call prepare(mat, scheme_trapezoidal, 6.0100113849687975e-05_dp, solver, old)
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
    call prepare(mat, scheme_trapezoidal, 1.0637710449713071e-03_dp, solver, old)
    s = [-3.5097549731983784e-05_dp, -1.0471795598336267e-06_dp, -7.2492041785926331e-06_dp]

    call replay_3d(mat, solver, old, s)
  end subroutine beyond_bound_seed2_tiny_zeta0

  !> `interlock-fuzz --3d 3000000 --seed 20261126`, update 2173960: seven planes with azimuths,
  !> pre-fractured, very fast wear (zeta_0 = 1.95e-6 N/mm), the explicit scheme with error
  !> control (64 sub-increments), a separation path through the origin (the end separation is
  !> 1.208 times the start one). Planes 5, 6 and 7 wore until they just lost contact and stay at
  !> s_kn = 0 (within 3e-20 mm) over every sub-increment: the tie, closed for the derivatives
  !> (SPEC D13). There the friction traction is 0 and its closed-side derivative d(mu p) n
  !> is not: the next sub-increment's start weight D_o |tau_f,1| has the derivative D_o
  !> |n_1| d(mu p) (n_1 < 0 here), and the closed side's wear turns the plane, d theta = theta'
  !> d zeta, though the stored zeta did not grow. Column 3 closes plane 6 on one side and
  !> planes 5 and 7 on the other: the one-sided differences of sigma_N are -1.0270e3 and
  !> -1.0291e3 MPa/mm, the tangent (each plane on its closed side) -1.0284e3; taking
  !> d |tau_f,1| = d tau_f,1 at tau_f,1 = 0 and d theta = 0 there gave -2.4e3. Columns 1 and 2
  !> close all three planes.
  subroutine fuzz3d_seed20261126_explicit_planes_at_tie()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old
    real(dp) :: s(3)

    mat%sigma0_n = 4.0615255473861717e-01_dp
    mat%sigma0_t = 5.3898357143188957e-01_dp
    mat%gc = 1.0352227455559602e-03_dp
    mat%eta = 9.9607349458362715e-01_dp
    mat%mu = 1.6251065713046391e+00_dp
    mat%h_n = 6.5273828885864725e+02_dp
    mat%prefractured = .true.
    mat%n_planes = 7
    mat%gamma_hat(1:7) = [5.0052713788254675e-02_dp, 2.8714266690513968e-01_dp, &
      1.7830245234328537e-01_dp, 2.9516597333814513e-02_dp, 6.2021408929845194e-02_dp, &
      2.8691166059369499e-01_dp, 1.0605250010596556e-01_dp]
    mat%theta0(1:7) = [-5.1693509241682989e-01_dp, -1.0303997836627039e+00_dp, &
      -4.8791669457364240e-01_dp, -1.2981602344863410e+00_dp, 1.2859260216729662e+00_dp, &
      1.1850318195720728e+00_dp, 7.8886018712705508e-01_dp]
    mat%thetaf(1:7) = [-1.8477860703289481e-01_dp, -8.5978115245446907e-01_dp, &
      -1.6490906702363922e-01_dp, -2.4593519965546479e-01_dp, 1.8914815178015004e-01_dp, &
      2.5902484822162530e-01_dp, 2.3479242410293280e-01_dp]
    mat%zeta0(1:7) = 1.9522425237232919e-06_dp
    mat%phi(1:7) = [6.1354171808468276e+00_dp, -1.1570866537062596e+00_dp, &
      9.6473294894337736e-01_dp, 2.3794913177950900e+00_dp, -3.5529649046057616e+00_dp, &
      3.2220330082143795e+00_dp, -3.4128899604694145e+00_dp]
    call prepare(mat, scheme_explicit, 1.7554254809966024e-04_dp, solver, old)
    old%damage(1:7) = 1.0_dp
    old%beta(1:7) = 2.54679388911619128e+02_dp
    old%sf(1:7) = [1.35956633856067417e-04_dp, 9.92702593237930876e-05_dp, &
      7.52924092800245817e-05_dp, 4.74899483618645220e-05_dp, -1.34358516217138700e-04_dp, &
      -1.32841093272367149e-04_dp, -1.36218798302670729e-04_dp]
    old%zeta(1:7) = [0.0_dp, 4.61049339989048874e-06_dp, 0.0_dp, 0.0_dp, &
      1.90712564951946953e-06_dp, 1.89436628968878435e-06_dp, 8.53105353943687002e-07_dp]
    old%theta(1:7) = [-5.16935092416829889e-01_dp, -8.75864608416352608e-01_dp, &
      -4.87916694573642395e-01_dp, -1.29816023448634099e+00_dp, 6.02063346630184348e-01_dp, &
      6.09934149725303354e-01_dp, 5.92708885423513965e-01_dp]
    old%tauf(1:7) = [0.0_dp, 3.17526060171428939e-02_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
    old%sf_strike(1:7) = [-5.79485786259386414e-06_dp, 9.18555211460786507e-05_dp, &
      -1.04021519408475702e-04_dp, -6.04755770212984922e-05_dp, -2.38832195432153858e-05_dp, &
      3.12388058994387776e-05_dp, -8.18889765456016388e-06_dp]
    old%tauf_strike(1:7) = [0.0_dp, 2.93698041835568080e-02_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
      0.0_dp, 0.0_dp]
    old%s = [7.60931695634928495e-05_dp, 1.11046003287094115e-04_dp]
    old%s_t2 = -2.23882503908805079e-05_dp
    old%sigma = [2.10969181480203912e-03_dp, 1.24287063668395755e-02_dp]
    old%sigma_t2 = -7.33030142011723788e-03_dp
    s = [9.1915879543450336e-05_dp, 1.3413675787813528e-04_dp, -2.7043632666657424e-05_dp]

    call replay_3d(mat, solver, old, s)
    call closed_together(mat, solver, old, s, [5, 6, 7])
  end subroutine fuzz3d_seed20261126_explicit_planes_at_tie

  !> `interlock-fuzz --3d 3000000 --beyond-bound --seed 6`, update 2164130: eleven planes with
  !> azimuths, pre-fractured, very fast wear (zeta_0 = 5.7e-5 N/mm), the explicit scheme with
  !> error control (794 sub-increments), a separation path through the origin (the end
  !> separation is 1116 times the start one). Plane 5 wears until it just loses contact and then
  !> follows its surface: over the last 90 sub-increments its s_kn is within the round-off of 0
  !> (+-5e-20 mm), the tie. The last sub-increments grow (to 0.27 of the increment), and there
  !> the wear that a closing perturbation causes in the next sub-increment (its start weight
  !> D_o |tau_f,1|) turns the plane by more than the perturbation: it opens and stops wearing.
  !> Taking the closed side at every one of those ties chained that overshoot as if the plane
  !> stayed closed: |d theta / dS| grew from 4.3e3 to 7.8e6 over the last 8 sub-increments
  !> and column 1 of the tangent was (-1.3e5, -2.2e6, -2.4e6) MPa/mm against the differences'
  !> (8.9e3, 8.2e5, 2.6e5). Each column is the one-sided derivative along the direction that
  !> closes plane 5 (SPEC D13 at its first tie), which closed_side checks.
  subroutine beyond_bound_seed6_explicit_surface_overshoot()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old
    real(dp) :: s(3)

    mat%sigma0_n = 1.1069728391559897e+02_dp
    mat%sigma0_t = 1.3328001537037987e+03_dp
    mat%gc = 3.0111482372290226e+01_dp
    mat%eta = 9.9998246283494074e-01_dp
    mat%mu = 5.2907200109731412e-01_dp
    mat%h_n = 6.4687045004931552e+00_dp
    mat%prefractured = .true.
    mat%n_planes = 11
    mat%gamma_hat(1:11) = [1.6929359960764725e-01_dp, 8.9313233637436526e-02_dp, &
      9.0422037731947968e-03_dp, 1.1041501372125043e-01_dp, 4.3072415815396170e-02_dp, &
      1.4581107410240685e-01_dp, 1.3718256584730487e-01_dp, 2.3699080875271394e-02_dp, &
      1.5439738924210702e-01_dp, 9.7260877304857080e-02_dp, 2.0512546073127691e-02_dp]
    mat%theta0(1:11) = [-1.8101340970269015e-02_dp, 5.7666017942620040e-01_dp, &
      -2.3803790663412153e-01_dp, -1.4362840841342299e+00_dp, -1.4459697285679960e+00_dp, &
      6.3992968715996967e-01_dp, 1.1317956762275418e+00_dp, 5.7731680616840819e-01_dp, &
      1.0077625998676418e+00_dp, 2.2193888484043248e-01_dp, 6.9168704214373800e-01_dp]
    mat%thetaf(1:11) = [-1.4328137414135715e-02_dp, 5.1125354613959528e-01_dp, &
      -9.2775774944104050e-02_dp, -5.2082503253870205e-01_dp, -2.5622080249959012e-01_dp, &
      3.7387303599545163e-01_dp, 1.0741985618628695e+00_dp, 4.1285310490229887e-01_dp, &
      3.5909645407139196e-01_dp, 5.7145427230231978e-02_dp, 5.7265377207442869e-01_dp]
    mat%zeta0(1:11) = 5.7179868644025554e-05_dp
    mat%phi(1:11) = [-4.6315377220451932e+00_dp, -3.7270335897204689e+00_dp, &
      2.2574566763609321e+00_dp, 4.8260929957193941e+00_dp, -2.2154267281413578e+00_dp, &
      -7.2629113179004456e-01_dp, -6.0031927060133281e+00_dp, -2.6204602207002798e+00_dp, &
      -2.2466871996856073e+00_dp, 2.4439677084475093e+00_dp, -4.9152147615378660e-03_dp]
    call prepare(mat, scheme_explicit, 3.31436821005449717e-04_dp, solver, old)
    old%damage(1:11) = 1.0_dp
    old%beta(1:11) = 5.70217590255392643e+04_dp
    old%sf(1:11) = [-1.24417859091590759e-08_dp, -2.16759730367876299e-08_dp, &
      3.45399644272695231e-08_dp, 8.42608386541313155e-08_dp, 8.77831943443538215e-08_dp, &
      -6.77856080849071945e-08_dp, -9.61908926354916530e-08_dp, -4.85140451906984149e-09_dp, &
      -4.78343111576250824e-08_dp, 4.76630585229737853e-09_dp, -8.83432461013905102e-08_dp]
    old%zeta(1:11) = [0.0_dp, 0.0_dp, 0.0_dp, 1.25017645389492444e-10_dp, &
      3.99888024948525525e-09_dp, 0.0_dp, 1.29914859873758836e-09_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
      0.0_dp]
    old%theta(1:11) = [-1.81013409702690149e-02_dp, 5.76660179426200403e-01_dp, &
      -2.38037906634121527e-01_dp, -1.43628208258346257e+00_dp, -1.44588652625859648e+00_dp, &
      6.39929687159969673e-01_dp, 1.13179436761382601e+00_dp, 5.77316806168408192e-01_dp, &
      1.00776259986764183e+00_dp, 2.21938884840432477e-01_dp, 6.91687042143737996e-01_dp]
    old%tauf(1:11) = [0.0_dp, 0.0_dp, 0.0_dp, 5.93479236078611316e-03_dp, &
      1.82216210259952188e-01_dp, 0.0_dp, -5.40237672462658830e-02_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
      0.0_dp]
    old%sf_strike(1:11) = [4.70420166113858969e-08_dp, 4.00440863933290718e-08_dp, &
      4.66156118052180313e-08_dp, -4.74729505798837932e-08_dp, -2.59062848851757690e-08_dp, &
      -4.36283861570551907e-08_dp, -4.36938940030538698e-09_dp, -7.42685639991929842e-09_dp, &
      -2.46237540585870723e-08_dp, 4.29668701075643386e-08_dp, -1.79312124256847870e-08_dp]
    old%tauf_strike(1:11) = [0.0_dp, 0.0_dp, 0.0_dp, -3.34368977268252208e-03_dp, &
      -5.37750430358431494e-02_dp, 0.0_dp, -2.45398363091292853e-03_dp, 0.0_dp, 0.0_dp, &
      0.0_dp, 0.0_dp]
    old%s = [8.33543784167826026e-08_dp, -4.57614712334993258e-08_dp]
    old%s_t2 = -1.77064997606593996e-08_dp
    old%sigma = [7.06891009466473468e-03_dp, -2.69900017830744382e-02_dp]
    old%sigma_t2 = -1.78866071410587330e-02_dp
    s = [9.3036045303021203e-05_dp, -5.1076696769602983e-05_dp, -1.9763121568176262e-05_dp]

    call replay_3d(mat, solver, old, s)
    call closed_side(mat, solver, old, s, 5)
  end subroutine beyond_bound_seed6_explicit_surface_overshoot

  !> `interlock-fuzz --3d 3000000 --seed 12345`, update 851150: 13 planes with azimuths,
  !> pre-fractured, very fast wear (zeta_0 = 4.1e-6 N/mm), trapezoidal, one step. Plane 1's wear
  !> root lies where it loses contact, on a jump of the wear equation (its driver's start term
  !> follows the start direction of slip on the closed side and the step's slip on the open
  !> one), and stays there as s moves: its traction stays 0 and its angle follows its contact.
  !> The wear equation's slope there gave d sigma / d s_N = 5.0e4 against 4.3e4 by central
  !> differences (stable from h = 1e-10 to 1e-15 mm).
  subroutine fuzz3d_seed12345_root_at_contact_loss()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old
    real(dp) :: s(3)

    mat%sigma0_n = 1.01704851866639121e+001_dp
    mat%sigma0_t = 1.36605533392876275e+001_dp
    mat%gc = 8.81940843112670111e-003_dp
    mat%eta = 9.01830725390447174e-001_dp
    mat%mu = 1.75867994757732160e+000_dp
    mat%h_n = 2.62758449054317167e-001_dp
    mat%prefractured = .true.
    mat%n_planes = 13
    mat%gamma_hat(1:13) = [5.55555555555555525e-002_dp, 3.33333333333333315e-001_dp, &
      5.55555555555555525e-002_dp, 5.55555555555555525e-002_dp, &
      5.55555555555555525e-002_dp, 5.55555555555555525e-002_dp, &
      5.55555555555555525e-002_dp, 5.55555555555555525e-002_dp, &
      5.55555555555555525e-002_dp, 5.55555555555555525e-002_dp, &
      5.55555555555555525e-002_dp, 5.55555555555555525e-002_dp, &
      5.55555555555555525e-002_dp]
    mat%theta0(1:13) = [-1.0966029596875193e+00_dp, 0.0000000000000000e+00_dp, &
      1.0966029596875193e+00_dp, &
      -1.0966029596875193e+00_dp, 1.0966029596875193e+00_dp, -1.0966029596875193e+00_dp, &
      1.0966029596875193e+00_dp, -1.0966029596875193e+00_dp, 1.0966029596875193e+00_dp, &
      -1.0966029596875193e+00_dp, 1.0966029596875193e+00_dp, -1.0966029596875193e+00_dp, &
      1.0966029596875193e+00_dp]
    mat%thetaf(1:13) = [-3.2703604121174468e-01_dp, 0.0000000000000000e+00_dp, &
      3.2703604121174468e-01_dp, &
      -3.2703604121174468e-01_dp, 3.2703604121174468e-01_dp, -3.2703604121174468e-01_dp, &
      3.2703604121174468e-01_dp, -3.2703604121174468e-01_dp, 3.2703604121174468e-01_dp, &
      -3.2703604121174468e-01_dp, 3.2703604121174468e-01_dp, -3.2703604121174468e-01_dp, &
      3.2703604121174468e-01_dp]
    mat%zeta0(1:13) = [4.13235246476355866e-006_dp, huge(1.0_dp), 4.13235246476355866e-006_dp, &
      4.13235246476355866e-006_dp, 4.13235246476355866e-006_dp, &
      4.13235246476355866e-006_dp, 4.13235246476355866e-006_dp, &
      4.13235246476355866e-006_dp, 4.13235246476355866e-006_dp, &
      4.13235246476355866e-006_dp, 4.13235246476355866e-006_dp, &
      4.13235246476355866e-006_dp, 4.13235246476355866e-006_dp]
    mat%phi(1:13) = [0.0000000000000000e+00_dp, 0.0000000000000000e+00_dp, &
      0.0000000000000000e+00_dp, &
      5.2359877559829882e-01_dp, 5.2359877559829882e-01_dp, 1.0471975511965976e+00_dp, &
      1.0471975511965976e+00_dp, 1.5707963267948966e+00_dp, 1.5707963267948966e+00_dp, &
      2.0943951023931953e+00_dp, 2.0943951023931953e+00_dp, 2.6179938779914944e+00_dp, &
      2.6179938779914944e+00_dp]
    call prepare(mat, scheme_trapezoidal, 0.0_dp, solver, old)
    old%damage(1:13) = [1.00000000000000000e+000_dp, 1.00000000000000000e+000_dp, &
      1.00000000000000000e+000_dp, 1.00000000000000000e+000_dp, &
      1.00000000000000000e+000_dp, 1.00000000000000000e+000_dp, &
      1.00000000000000000e+000_dp, 1.00000000000000000e+000_dp, &
      1.00000000000000000e+000_dp, 1.00000000000000000e+000_dp, &
      1.00000000000000000e+000_dp, 1.00000000000000000e+000_dp, &
      1.00000000000000000e+000_dp]
    old%beta(1:13) = [1.01864865965169340e+001_dp, 1.01864865965169340e+001_dp, &
      1.01864865965169340e+001_dp, 1.01864865965169340e+001_dp, &
      1.01864865965169340e+001_dp, 1.01864865965169340e+001_dp, &
      1.01864865965169340e+001_dp, 1.01864865965169340e+001_dp, &
      1.01864865965169340e+001_dp, 1.01864865965169340e+001_dp, &
      1.01864865965169340e+001_dp, 1.01864865965169340e+001_dp, &
      1.01864865965169340e+001_dp]
    old%sf(1:13) = [-1.36167071972708635e-005_dp, -2.28922136103377112e-006_dp, &
      5.20282064153505398e-006_dp, -5.21847684374215677e-006_dp, &
      1.06122337086603711e-005_dp, -2.91383039418105063e-006_dp, &
      1.52624561414477950e-005_dp, 4.63352305060873987e-006_dp, &
      2.32801515383024353e-005_dp, 3.41625381934560987e-006_dp, &
      2.40458406317014872e-005_dp, -8.33061274677481130e-007_dp, &
      2.13953398432465897e-005_dp]
    old%zeta(1:13) = [4.19648415872186424e-006_dp, 4.17821691024977389e-005_dp, &
      1.10767154428244198e-005_dp, 2.08536769145115577e-006_dp, &
      8.00028262886743221e-007_dp, 1.86802125985698631e-007_dp, &
      6.90542468467105154e-008_dp, 1.17272948592802938e-005_dp, &
      6.00704818735838031e-006_dp, 2.05774450405468847e-005_dp, &
      1.52688386130044787e-005_dp, 2.13759997724804824e-005_dp, &
      8.34431781340253803e-006_dp]
    old%theta(1:13) = [-6.05784138758117763e-001_dp, 0.00000000000000000e+000_dp, &
      3.79774307349109441e-001_dp, -7.91639244968062483e-001_dp, &
      9.61148770634393745e-001_dp, -1.06258942786475630e+000_dp, &
      1.08384985836205638e+000_dp, -3.72092020382747635e-001_dp, &
      5.06893535501094616e-001_dp, -3.32328230941851432e-001_dp, &
      3.46158762375073370e-001_dp, -3.31398289182516070e-001_dp, &
      4.29198283431317884e-001_dp]
    old%tauf(1:13) = [-2.00250929355329205e-001_dp, -9.74783772453004849e-001_dp, &
      -1.26314102934783690e+000_dp, -2.29216919104787170e-001_dp, &
      -1.57627000418897184e-001_dp, -6.46225358817192064e-002_dp, &
      0.00000000000000000e+000_dp, 1.14746697927104346e+000_dp, &
      0.00000000000000000e+000_dp, 1.64847748023497442e+000_dp, &
      1.89179983119483086e-001_dp, 1.76171961864900273e+000_dp, &
      1.51614884695620233e-001_dp]
    old%sf_strike(1:13) = [1.91458632945726493e-005_dp, 1.52099721647040067e-005_dp, &
      1.31768808045098378e-005_dp, 1.60740578689576919e-005_dp, &
      1.80814947738309605e-005_dp, 4.62521438320632406e-006_dp, &
      2.01277832323809759e-005_dp, -2.08408463028645767e-006_dp, &
      1.13343915141433745e-005_dp, -8.88858274793443500e-006_dp, &
      -1.71017534104863702e-006_dp, -1.17955314055370226e-005_dp, &
      -1.23875992758295102e-005_dp]
    old%tauf_strike(1:13) = [1.59277555273635185e-001_dp, 5.83442356885320978e-001_dp, &
      8.02545417666367666e-001_dp, 8.03294422710647105e-001_dp, &
      5.86956102262244928e-001_dp, 1.67068748179554505e+000_dp, &
      0.00000000000000000e+000_dp, 1.44608808626349683e+000_dp, &
      0.00000000000000000e+000_dp, 9.04451007168949772e-001_dp, &
      1.30845322163331002e-001_dp, -4.28949348471433720e-002_dp, &
      2.09112890693316233e-002_dp]
    old%s = [-1.08136452861155025e-005_dp, -1.13343915141433728e-005_dp]
    old%s_t2 = 2.06238244893880944e-005_dp
    old%sigma = [-4.02960605237749458e-001_dp, -8.05384336144614021e-001_dp]
    old%sigma_t2 = 6.03416492342104149e-001_dp
    s = [-1.12207749395254671e-05_dp, -1.79333263081740433e-05_dp, 2.46362651584662281e-05_dp]

    call replay_3d(mat, solver, old, s)
  end subroutine fuzz3d_seed12345_root_at_contact_loss

  !> `interlock-fuzz --3d 3000000 --seed 20261126` with the wear root's first point Newton's
  !> from zeta_o on every step: 10 planes with azimuths, very fast wear (zeta_0 = 5.8e-6 N/mm),
  !> implicit, one step. Plane 6 starts deep in contact (its work g0 = 1.1e7 N/mm) and wears
  !> until it loses contact at zeta = 1.09e-6, where its work falls steeply to 0: the root.
  !> Newton's first point (5.8e-7) is below it; the next is on the open side, where F = zeta -
  !> zeta_o = 1e-6 is within 1e-13 g0: taken as the root, the state was taken at the earlier
  !> point (F = -5.5e6 there), with a traction twice the root's and a tangent that matched no
  !> difference (column 3: -2.7e5 against -7.2e5 MPa/mm).
  subroutine fuzz3d_seed20261126_newton_start_open_side()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old
    real(dp) :: s(3)

    mat%sigma0_n = 5.78235152074211328e+002_dp
    mat%sigma0_t = 1.39652069276175121e+003_dp
    mat%gc = 3.52433045972696505e+002_dp
    mat%eta = 9.99916208843687260e-001_dp
    mat%mu = 1.68753269474966405e+000_dp
    mat%h_n = 1.0e30_dp
    mat%prefractured = .false.
    mat%n_planes = 10
    mat%gamma_hat(1:10) = [1.85797553104200680e-001_dp, 2.26479180295765907e-002_dp, &
      8.83450939807944452e-002_dp, 8.04090967402954354e-002_dp, &
      7.52535277194696650e-002_dp, 1.60405661302962355e-001_dp, &
      1.52416485735867219e-001_dp, 8.64593295721347022e-002_dp, &
      8.80576412427952065e-002_dp, 6.02076925719036149e-002_dp]
    mat%theta0(1:10) = deg_to_rad * &
      [7.04461775221513022e+001_dp, 8.38544122514431507e+001_dp, &
      3.50997112172075703e+001_dp, -5.83205992459556626e+001_dp, &
      -3.92345773847490022e+001_dp, -7.46751036086975688e+001_dp, &
      7.77429014924665154e+001_dp, -7.24851519922902412e+001_dp, &
      5.82749213410393878e+001_dp, -1.76347118075706533e+001_dp]
    mat%thetaf(1:10) = deg_to_rad * &
      [5.79317570834979421e+001_dp, 7.48298423025371733e+001_dp, &
      4.27724317622082628e-001_dp, -2.41032174872936444e+001_dp, &
      -1.93796466739462510e+001_dp, -1.59088272521493801e+000_dp, &
      1.50941197438216950e+001_dp, -6.31576813516012834e+001_dp, &
      1.06536986805753351e+001_dp, -1.54773555319197564e+000_dp]
    mat%zeta0(1:10) = [5.79564934701932718e-006_dp, 5.79564934701932718e-006_dp, &
      5.79564934701932718e-006_dp, 5.79564934701932718e-006_dp, &
      5.79564934701932718e-006_dp, 5.79564934701932718e-006_dp, &
      5.79564934701932718e-006_dp, 5.79564934701932718e-006_dp, &
      5.79564934701932718e-006_dp, 5.79564934701932718e-006_dp]
    mat%phi(1:10) = deg_to_rad * &
      [4.53269320599684633e+001_dp, 2.97314702007802829e+001_dp, &
      2.01047525559104798e+002_dp, 2.11910080226304416e+002_dp, &
      -6.25331868954565877e+001_dp, -1.04416449943277144e+002_dp, &
      -2.52649459203334573e+002_dp, 2.34494888545975755e+002_dp, &
      1.89632789194019040e+002_dp, 1.43123060746798387e+002_dp]
    call prepare(mat, scheme_implicit, 0.0_dp, solver, old)
    old%damage(1:10) = [9.99664985391722771e-001_dp, 9.99666428478498181e-001_dp, &
      9.99311800171800546e-001_dp, 9.99649647763052318e-001_dp, &
      9.99538444751724375e-001_dp, 9.99665928941495086e-001_dp, &
      9.99664725568830570e-001_dp, 9.99665808343368156e-001_dp, &
      9.99550324114995448e-001_dp, 9.99337273564930961e-001_dp]
    old%beta(1:10) = [2.38790178161509084e+003_dp, 2.39615812961426855e+003_dp, &
      1.29544868034558203e+003_dp, 2.30354219199223871e+003_dp, &
      1.83382692810130402e+003_dp, 2.39329366976101301e+003_dp, &
      2.38642129462152116e+003_dp, 2.39260315839099076e+003_dp, &
      1.87466245839540557e+003_dp, 1.33965281366319300e+003_dp]
    old%sf(1:10) = [-1.00913517411104992e-001_dp, -1.01161153817097657e-001_dp, &
      -3.74929502563459069e-002_dp, 9.64585094649808017e-002_dp, &
      6.74800765753264670e-002_dp, 1.00312686216279659e-001_dp, &
      -9.82962526242994322e-002_dp, 1.01044212734145600e-001_dp, &
      -7.25653325178099301e-002_dp, 3.37254575708082344e-002_dp]
    old%zeta(1:10) = [0.00000000000000000e+000_dp, 1.15241093747137742e-005_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp]
    old%theta(1:10) = [1.22951774320596074e+000_dp, 1.32759213980897428e+000_dp, &
      6.12605527239458714e-001_dp, -1.01788647857804859e+000_dp, &
      -6.84772555992376186e-001_dp, -1.30332642723967185e+000_dp, &
      1.35686960109715415e+000_dp, -1.26510456107399216e+000_dp, &
      1.01708924874184659e+000_dp, -3.07783783682428591e-001_dp]
    old%tauf(1:10) = [0.00000000000000000e+000_dp, -2.33874588872920930e-004_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp]
    old%sf_strike(1:10) = [7.83183837950524736e-004_dp, -5.98651284796718718e-003_dp, &
      9.59600121055786091e-003_dp, 5.05610831468461357e-003_dp, &
      -2.41054102219356858e-002_dp, -1.33104022778260129e-002_dp, &
      2.25108804362303683e-002_dp, -4.76812571180013946e-003_dp, &
      1.39933132205956410e-002_dp, 2.47355617761918431e-002_dp]
    old%tauf_strike(1:10) = [0.00000000000000000e+000_dp, -3.72833129386404165e-005_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp, &
      0.00000000000000000e+000_dp, 0.00000000000000000e+000_dp]
    old%s = [9.81841172467559087e-002_dp, -1.81851714228951807e-002_dp]
    old%s_t2 = -1.72799317107175006e-002_dp
    old%sigma = [9.78262254924192234e+002_dp, -1.30075894710183860e+002_dp]
    old%sigma_t2 = -2.54443127697560442e+002_dp
    s = [2.26029657633510794e+000_dp, -9.65092276471667621e-001_dp, &
      -9.86438542497712789e-001_dp]


    call replay_3d(mat, solver, old, s)
  end subroutine fuzz3d_seed20261126_newton_start_open_side

end program test_fuzz_cases
