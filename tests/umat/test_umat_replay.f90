!> A local failure inside the UMAT, with INTERLOCK_REPLAY_DIR set (by CTest), writes a replay
!> deck; the test `test_umat_replay_history` then runs that deck through interlock-history and
!> expects the same failure. The failing increment: the paper's RIA at 70 deg with fast wear
!> (zeta_0 = 1 N/mm), eta = 0.99999 (K ~ 1.5e6 MPa/mm), H_N = 0.01 mm, the explicit scheme with
!> substepping at 1e-4, one increment from the virgin state to s = (-0.011, 0.01) mm: the chained
!> derivative of the explicit wear update grows without bound on the sub-increments, and the
!> library says so. The 3D UMAT (NTENS = 3) writes a 3D deck: the same material on the
!> azimuthal RIA with N_a = 3, two increments of oblique slip under closure with the implicit
!> scheme (stable: strike slip and friction enter the state), then an increment with the
!> explicit one that fails the same way; `umat_history_replay_3d` replays it.
program test_umat_replay
  use interlock, only: dp, umat_nstatv, umat_nstatv_3d, property_defaults
  use interlock_assert, only: assert_true, assert_equal, run_case, suite_summary
  use test_umat_interface, only: umat_point_t, call_umat
  implicit none
  call run_case('a local failure writes a replay deck', failure_writes_deck)
  call run_case('a local failure of the 3D UMAT writes a 3D replay deck', failure_writes_deck_3d)
  if (suite_summary('test_umat_replay') /= 0) error stop 1
contains
  subroutine failure_writes_deck()
    type(umat_point_t) :: pt
    real(dp), parameter :: props(12) = [3.0_dp, 3.0_dp, 0.3_dp, 0.99999_dp, 0.5_dp, 0.01_dp, &
                                        70.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 1.0e-4_dp]
    character(len=4096) :: dir
    integer :: length, stat
    logical :: exists
    allocate (pt%stress(2), pt%statev(umat_nstatv), pt%ddsdde(2, 2))
    pt%stress = 0.0_dp
    pt%statev = 0.0_dp
    pt%ddsdde = 0.0_dp
    pt%pnewdt = 1.0_dp
    call get_environment_variable('INTERLOCK_REPLAY_DIR', dir, length, stat)
    call assert_true(stat == 0 .and. length > 0, 'INTERLOCK_REPLAY_DIR is set by the test')
    call call_umat(pt, props, [0.0_dp, 0.0_dp], [-0.011_dp, 0.01_dp], 5, 2, 3)
    call assert_equal(0.5_dp, pt%pnewdt, 0.0_dp, 'a local failure proposes PNEWDT = 0.5')
    call assert_equal([0.0_dp, 0.0_dp], pt%stress, 0.0_dp, 'STRESS untouched')
    call assert_true(maxval(abs(pt%statev)) <= 0.0_dp, 'STATEV untouched')
    inquire (file=trim(dir) // '/interlock_replay_e5_p2_k3.nml', exist=exists)
    call assert_true(exists, 'the replay deck interlock_replay_e5_p2_k3.nml is written')
  end subroutine failure_writes_deck

  subroutine failure_writes_deck_3d()
    type(umat_point_t) :: pt
    real(dp) :: props(22), props_implicit(22), stress(3), statev(umat_nstatv_3d(7))
    character(len=4096) :: dir
    integer :: length, stat, i
    logical :: exists
    props = property_defaults(1:22)
    props(1:12) = [3.0_dp, 3.0_dp, 0.3_dp, 0.99999_dp, 0.5_dp, 0.01_dp, 70.0_dp, 0.0_dp, &
                   1.0_dp, 0.0_dp, 1.0_dp, 1.0e-4_dp]
    props(21:22) = [1.0_dp, 3.0_dp]
    props(13:14) = [1.0_dp, 90.0_dp]   ! no accuracy bound: PNEWDT stays 1 on success
    allocate (pt%stress(3), pt%statev(umat_nstatv_3d(7)), pt%ddsdde(3, 3))
    pt%stress = 0.0_dp
    pt%statev = 0.0_dp
    pt%ddsdde = 0.0_dp
    call get_environment_variable('INTERLOCK_REPLAY_DIR', dir, length, stat)
    props_implicit = props
    props_implicit(11) = 2.0_dp
    do i = 1, 2
      pt%pnewdt = 1.0_dp
      call call_umat(pt, props_implicit, [-0.002_dp, 0.001_dp, 0.0005_dp] * (i - 1), &
                     [-0.002_dp, 0.001_dp, 0.0005_dp], 6, 1, i)
      call assert_true(pt%pnewdt >= 1.0_dp, 'oblique increment accepted')
    end do
    call assert_true(maxval(abs(pt%statev(7 * 6 + 1:7 * 8))) > 0.0_dp, &
                     'the state has strike components')
    stress = pt%stress
    statev = pt%statev
    pt%pnewdt = 1.0_dp
    call call_umat(pt, props, [-0.004_dp, 0.002_dp, 0.001_dp], [-0.007_dp, 0.008_dp, 0.006_dp], &
                   6, 1, 3)
    print '(a, es10.3)', 'PNEWDT after the third increment ', pt%pnewdt
    call assert_equal(0.5_dp, pt%pnewdt, 0.0_dp, 'a local failure proposes PNEWDT = 0.5')
    call assert_true(maxval(abs(pt%stress - stress)) <= 0.0_dp .and. &
                     maxval(abs(pt%statev - statev)) <= 0.0_dp, 'STRESS and STATEV untouched')
    inquire (file=trim(dir) // '/interlock_replay_e6_p1_k3.nml', exist=exists)
    call assert_true(exists, 'the replay deck interlock_replay_e6_p1_k3.nml is written')
  end subroutine failure_writes_deck_3d
end program test_umat_replay
