!> An admissible STATEV with a frictional slip of 1e150 mm (the bound) on a stiff interface:
!> the 3D radial return squared a trial traction of 1e154 MPa and returned NaN (accepted with
!> PNEWDT 1 in Release, a floating-point trap in Debug). The 2D UMAT on the same state stays
!> finite; the 3D UMAT (NTENS = 3), the thin layer (NTENS = 6) and a state found by the
!> adversarial fuzzer (bit for bit) must too: every output finite, the call accepted or cut
!> back.
program test_umat_huge_slip
  use interlock_assert, only: assert_true, run_case, suite_summary
  use test_umat_interface, only: UMAT
  implicit none
  integer, parameter :: dp = kind(1.0d0)

  call run_case('huge_slip_2d_3d_layer', huge_slip_2d_3d_layer)
  call run_case('fuzzed_state_3d', fuzzed_state_3d)
  if (suite_summary('umat_huge_slip') /= 0) error stop 1

contains

  !> Table 1 strengths with K = 1e3 and 1.5e4 MPa/mm, debonded, plane 1's slip 1e150 mm, a
  !> compressive separation and a slip increment: NTENS 2, 3 and the layer.
  subroutine huge_slip_2d_3d_layer()
    use interlock_umat_layer, only: interlock_umat_layer_point, host_abaqus
    real(dp) :: stress(3), statev(28), ddsdde(3, 3), sse, spd, scd, rpl, ddsddt(3), &
                drplde(3), drpldt, stran(3), dstran(3), time(2), predef(1), dpred(1), &
                coords(3), drot(3, 3), pnewdt, props(20), th, sig_2d
    real(dp) :: lstress(6), lstatev(34), lddsdde(6, 6), lstran(6), ldstran(6), lprops(24), &
                ddt(6), dre(6)
    integer :: jstep(4), ntens
    character(len=40) :: what
    jstep = 0; time = 0; coords = 0; drot = 0; rpl = 0; spd = 0; drpldt = 0
    ddsddt = 0; drplde = 0; predef = 0; dpred = 0
    th = 45.0_dp * acos(-1.0_dp) / 180.0_dp
    props = [3.0_dp, 3.0_dp, 0.003_dp, 0.9_dp, 0.5_dp, 1.0e30_dp, 45.0_dp, 45.0_dp, 1.0e30_dp, &
             0.0_dp, 3.0_dp, 0.0_dp, 0.25_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, &
             1.0_dp]
    sig_2d = 0.0_dp
    do ntens = 2, 3
      statev = 0
      statev(1:3) = 1.0_dp                 ! damage
      statev(4:6) = 100.0_dp               ! beta
      statev(7) = 1.0e150_dp               ! frictional slip of plane 1: admissible (<= 1e150)
      statev(13:15) = [-th, 0.0_dp, th]    ! theta
      statev(22) = 1.0_dp                  ! initialised
      stress = 0; ddsdde = 0; sse = 0; scd = 0
      stran = [-1.0e-4_dp, 0.0_dp, 0.0_dp]
      dstran = [0.0_dp, 1.0e-5_dp, 1.0e-5_dp]
      pnewdt = 1.0_dp
      call UMAT(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, &
                dstran, time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, 'HUGESLIP', 1, ntens - 1, &
                ntens, 28, props, 20, coords, drot, pnewdt, 1.0_dp, drot, drot, 1, 1, 0, 0, &
                jstep, 1)
      write (what, '(a,i0)') 'NTENS ', ntens
      call assert_true(pnewdt >= 1.0_dp, trim(what) // ': accepted')
      call assert_true(all_finite([stress(1:ntens), statev(1:22), sse, scd, &
                                   reshape(ddsdde(1:ntens, 1:ntens), [ntens * ntens])]), &
                       trim(what) // ': every output finite')
      if (ntens == 2) sig_2d = stress(1)
      ! (s_T2 = 1e-5 mm barely changes the normal traction of the 2D update)
      if (ntens == 3) call assert_true(abs(stress(1) - sig_2d) <= 1.0e-2_dp * abs(sig_2d), &
                                       'NTENS 3: sigma_N near the 2D one')
    end do
    lprops(1:4) = [1.0_dp, 1.0e3_dp, 3.0_dp, 1.0_dp]
    lprops(5:24) = props
    lstatev = 0
    lstatev(1:3) = 1.0_dp; lstatev(4:6) = 100.0_dp; lstatev(7) = 1.0e150_dp
    lstatev(13:15) = [-th, 0.0_dp, th]; lstatev(22) = 1.0_dp
    lstress = 0; lddsdde = 0; lstran = 0; ldstran = 0; sse = 0; scd = 0; ddt = 0; dre = 0
    lstran(3) = -1.0e-4_dp                    ! s_N (normal axis 3)
    ldstran(5) = 1.0e-5_dp                    ! gamma_31: s_T1 (slip axis 1)
    ldstran(6) = 1.0e-5_dp                    ! gamma_23: s_T2 (t2 = n x t1 = axis 2)
    pnewdt = 1.0_dp
    call interlock_umat_layer_point(lstress, lstatev, lddsdde, sse, spd, scd, rpl, ddt, dre, &
      drpldt, lstran, ldstran, time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, 'HUGESLIPL', 3, 3, &
      6, 34, lprops, 24, coords, drot, pnewdt, 1.0_dp, drot, drot, 1, 1, 0, 0, jstep, 1, &
      host_abaqus)
    call assert_true(pnewdt >= 1.0_dp, 'layer: accepted')
    call assert_true(all_finite([lstress, lstatev, sse, scd, reshape(lddsdde, [36])]), &
                     'layer: every output finite')
  end subroutine huge_slip_2d_3d_layer

  !> The fuzzer's state (a 3D UMAT call, NTENS = 3, 7 planes, slip 1e150 mm in STATEV(20)).
  subroutine fuzzed_state_3d()
    use, intrinsic :: iso_fortran_env, only: int64
    real(dp) :: stress(3), statev(60), ddsdde(3, 3), sse, spd, scd, rpl, ddsddt(3), &
                drplde(3), drpldt, stran(3), dstran(3), time(2), predef(4), dpred(4), &
                coords(3), drot(3, 3), pnewdt, props(21)
    integer :: jstep(4)
    time = [1.0_dp, 1.0_dp]; predef = 0; dpred = 0; coords = [1.0_dp, 2.0_dp, 3.0_dp]
    drot = 0; drot(1, 1) = 1; drot(2, 2) = 1; drot(3, 3) = 1; jstep = [1, 1, 0, 0]
    ddsdde = -1.2345e-300_dp; ddsddt = 0; drplde = 0; rpl = 0; drpldt = 0
    props(1) = transfer(int(z'3D316D34D5A7D659', int64), 1.0_dp)
    props(2) = transfer(int(z'3D77DF48ED2DB52A', int64), 1.0_dp)
    props(3) = transfer(int(z'30A3681E209A887C', int64), 1.0_dp)
    props(4) = transfer(int(z'3FE0000000000000', int64), 1.0_dp)
    props(5) = transfer(int(z'4059000000000000', int64), 1.0_dp)
    props(6) = transfer(int(z'374A0C61C768CECB', int64), 1.0_dp)
    props(7) = transfer(int(z'404A3E52BBC4248C', int64), 1.0_dp)
    props(8) = transfer(int(z'404A3E52BBC4248C', int64), 1.0_dp)
    props(9) = transfer(int(z'2B2BFF2EE48E0530', int64), 1.0_dp)
    props(10) = transfer(int(z'0000000000000000', int64), 1.0_dp)
    props(11) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(12) = transfer(int(z'3D880D6DA9877BED', int64), 1.0_dp)
    props(13) = transfer(int(z'3FD0000000000000', int64), 1.0_dp)
    props(14) = transfer(int(z'4056800000000000', int64), 1.0_dp)
    props(15) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(16) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(17) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(18) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(19) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(20) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    props(21) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(1) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(2) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(3) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(4) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(5) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(6) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(7) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(8) = transfer(int(z'4030BC483649DC2D', int64), 1.0_dp)
    statev(9) = transfer(int(z'404A64D268C37166', int64), 1.0_dp)
    statev(10) = transfer(int(z'4050FC3E66EF595D', int64), 1.0_dp)
    statev(11) = transfer(int(z'404C50286C44E787', int64), 1.0_dp)
    statev(12) = transfer(int(z'40508785D8B37E4F', int64), 1.0_dp)
    statev(13) = transfer(int(z'40511133C8947364', int64), 1.0_dp)
    statev(14) = transfer(int(z'4043ACA7FFB16693', int64), 1.0_dp)
    statev(15) = transfer(int(z'B32098F7B328D0F8', int64), 1.0_dp)
    statev(16) = transfer(int(z'33715DBF38F8FFDC', int64), 1.0_dp)
    statev(17) = transfer(int(z'337B1614EFF120F5', int64), 1.0_dp)
    statev(18) = transfer(int(z'B3631E2ED5FD6D7D', int64), 1.0_dp)
    statev(19) = transfer(int(z'3370F6B04812F3FF', int64), 1.0_dp)
    statev(20) = transfer(int(z'5F138D352E5096AF', int64), 1.0_dp)
    statev(21) = transfer(int(z'33490273779F0682', int64), 1.0_dp)
    statev(22) = transfer(int(z'30D8C9891245EBDA', int64), 1.0_dp)
    statev(23) = transfer(int(z'0000000000000000', int64), 1.0_dp)
    statev(24) = transfer(int(z'0000000000000000', int64), 1.0_dp)
    statev(25) = transfer(int(z'30E511E1EBEC1AC1', int64), 1.0_dp)
    statev(26) = transfer(int(z'30B990A4D6786E6A', int64), 1.0_dp)
    statev(27) = transfer(int(z'3098B97A8D4E51C3', int64), 1.0_dp)
    statev(28) = transfer(int(z'309002793B8E7397', int64), 1.0_dp)
    statev(29) = transfer(int(z'BFED50706381E102', int64), 1.0_dp)
    statev(30) = transfer(int(z'0000000000000000', int64), 1.0_dp)
    statev(31) = transfer(int(z'3FED50706381E102', int64), 1.0_dp)
    statev(32) = transfer(int(z'BFED50706381E102', int64), 1.0_dp)
    statev(33) = transfer(int(z'3FED50706381E102', int64), 1.0_dp)
    statev(34) = transfer(int(z'BFED50706381E102', int64), 1.0_dp)
    statev(35) = transfer(int(z'3FED50706381E102', int64), 1.0_dp)
    statev(36) = transfer(int(z'BDAB43B9FC6BADF9', int64), 1.0_dp)
    statev(37) = transfer(int(z'3D948A0F0D5DAA3D', int64), 1.0_dp)
    statev(38) = transfer(int(z'0000000000000000', int64), 1.0_dp)
    statev(39) = transfer(int(z'BDA775563AD58B7C', int64), 1.0_dp)
    statev(40) = transfer(int(z'3D978110AB1514F5', int64), 1.0_dp)
    statev(41) = transfer(int(z'BD59C81AE7D1DF36', int64), 1.0_dp)
    statev(42) = transfer(int(z'3DAD72E3B4484439', int64), 1.0_dp)
    statev(43) = transfer(int(z'31169FC17FC2F934', int64), 1.0_dp)
    statev(44) = transfer(int(z'309F62E5740E58C7', int64), 1.0_dp)
    statev(45) = transfer(int(z'3121961F818F1F83', int64), 1.0_dp)
    statev(46) = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    statev(47) = transfer(int(z'B332205B8A60D29C', int64), 1.0_dp)
    statev(48) = transfer(int(z'B350FAE99BFE07A0', int64), 1.0_dp)
    statev(49) = transfer(int(z'B3554D2B2AF692BA', int64), 1.0_dp)
    statev(50) = transfer(int(z'B372213DFF6C5F7F', int64), 1.0_dp)
    statev(51) = transfer(int(z'B373827D8D9593C7', int64), 1.0_dp)
    statev(52) = transfer(int(z'B36B7DB8FD324204', int64), 1.0_dp)
    statev(53) = transfer(int(z'B365E1FF87A8DE6F', int64), 1.0_dp)
    statev(54) = transfer(int(z'BDAEC7334244668E', int64), 1.0_dp)
    statev(55) = transfer(int(z'BD8FB95CD036F7C8', int64), 1.0_dp)
    statev(56) = transfer(int(z'0000000000000000', int64), 1.0_dp)
    statev(57) = transfer(int(z'BD8704B93B37C59D', int64), 1.0_dp)
    statev(58) = transfer(int(z'3D81807D06664C66', int64), 1.0_dp)
    statev(59) = transfer(int(z'3D6276C12195AD65', int64), 1.0_dp)
    statev(60) = transfer(int(z'BDA36E9F749359D4', int64), 1.0_dp)
    stran(1) = transfer(int(z'B373BDDFE5878A23', int64), 1.0_dp)
    dstran(1) = transfer(int(z'B3317B1808F1D2B2', int64), 1.0_dp)
    stress(1) = transfer(int(z'BD90B39C7D5A4C6C', int64), 1.0_dp)
    stran(2) = transfer(int(z'3372C3DC99B155EB', int64), 1.0_dp)
    dstran(2) = transfer(int(z'B32F16B782A2CFDD', int64), 1.0_dp)
    stress(2) = transfer(int(z'3D714A4748ACCC4A', int64), 1.0_dp)
    stran(3) = transfer(int(z'B3554D2B2AF692BA', int64), 1.0_dp)
    dstran(3) = transfer(int(z'B331EDF0F674F9E0', int64), 1.0_dp)
    stress(3) = transfer(int(z'BD8098DBC89B84DF', int64), 1.0_dp)
    pnewdt = transfer(int(z'3FF0000000000000', int64), 1.0_dp)
    sse = transfer(int(z'3FC0000000000000', int64), 1.0_dp)
    spd = transfer(int(z'3FB0000000000000', int64), 1.0_dp)
    scd = transfer(int(z'3FA0000000000000', int64), 1.0_dp)
    call UMAT(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
              time, 0.1_dp, 20.0_dp, 0.0_dp, predef, dpred, 'REPRO', 1, 2, 3, 60, props, &
              21, coords, drot, pnewdt, 1.0_dp, drot, drot, 7, 2, 1, 1, jstep, 3)
    call assert_true(pnewdt >= 1.0_dp .or. pnewdt < 1.0_dp, 'PNEWDT not NaN')
    call assert_true(all_finite([stress, statev, sse, scd, reshape(ddsdde, [9])]), &
                     'every output finite')
  end subroutine fuzzed_state_3d

  !> Every value finite (no comparison that traps on a NaN is needed: abs(NaN) <= huge is
  !> false, and quiet).
  logical function all_finite(x)
    real(dp), intent(in) :: x(:)
    integer :: i
    all_finite = .true.
    do i = 1, size(x)
      all_finite = all_finite .and. abs(x(i)) <= huge(1.0_dp)
    end do
  end function all_finite

end program test_umat_huge_slip
