!> A local failure inside the UMAT, with INTERLOCK_REPLAY_DIR set (by CTest), writes a replay
!> deck; the test `test_umat_replay_history` then runs that deck through interlock-history and
!> expects the same failure. The failing increment: the paper's RIA at 70 deg with fast wear
!> (zeta_0 = 1 N/mm), eta = 0.99999 (K ~ 1.5e6 MPa/mm), H_N = 0.01 mm, the explicit scheme with
!> substepping at 1e-4, one increment from the virgin state to s = (-0.011, 0.01) mm: the chained
!> derivative of the explicit wear update grows without bound on the sub-increments, and the
!> library says so.
program test_umat_replay
  use interlock, only: dp, umat_nstatv
  use interlock_assert, only: assert_true, assert_equal, run_case, suite_summary
  use test_umat_interface, only: umat_point_t, call_umat
  implicit none
  call run_case('a local failure writes a replay deck', failure_writes_deck)
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
end program test_umat_replay
