!> Near-integer values of integer-valued properties are refused (right) with a message that
!> shows why: the value with the digits that read back as it ("6.0000000001", "6 + 1 ulp" as
!> "6.000000000000001"), never rounded to the bound it exceeds ("'n_azimuths' = 6 is
!> inadmissible: admissible ... from 1 to 6"). The 3D UMAT (n_azimuths, scheme) and the thin
!> layer (normal_axis). The messages go to the UMAT's output; the CTest matches them.
program umat_near_integer_message
  use interlock_umat_layer, only: interlock_umat_layer_point, host_abaqus
  use test_umat_interface, only: UMAT
  implicit none
  integer, parameter :: dp = kind(1.0d0)
  real(dp) :: stress(6), statev(120), ddsdde(36), sse, spd, scd, rpl, ddsddt(6), drplde(6), &
              drpldt, stran(6), dstran(6), time(2), predef(1), dpred(1), coords(3), drot(9), &
              pnewdt, props(26), lp(26)
  integer :: jstep(4), refused
  stress = 0; statev = 0; ddsdde = 0; stran = 0; dstran = 0; time = 0; coords = 0; drot = 0
  jstep = 0
  refused = 0
  props(1:22) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 1.0_dp, 45.0_dp, 45.0_dp, 1.0e30_dp, &
                 0.0_dp, 3.0_dp, 0.0_dp, 0.25_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, &
                 1.0_dp, 1.0_dp, 1.0_dp, 6.0000000001_dp]
  call umat_call('NEARINT')
  props(22) = nearest(6.0_dp, 2.0_dp)
  call umat_call('NEARULP')
  props(11) = 2.9999999999_dp
  props(22) = 3.0_dp
  call umat_call('NEARINT2')
  lp(1:4) = [0.1_dp, 1.0e3_dp, 1.0000000001_dp, 3.0_dp]
  lp(5:26) = props(1:22)
  lp(15) = 3.0_dp
  pnewdt = 1
  call interlock_umat_layer_point(stress, statev(1:40), ddsdde, sse, spd, scd, rpl, ddsddt, &
    drplde, drpldt, stran, dstran, time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, 'NEARINT3', 3, 3, &
    6, 40, lp, 26, coords, drot, pnewdt, 1.0_dp, drot, drot, 1, 1, 0, 0, jstep, 1, host_abaqus)
  if (pnewdt < 0.0_dp) refused = refused + 1
  write (*, '(a,i0,a)') 'umat_near_integer_message: ', refused, ' of 4 calls refused'

contains

  subroutine umat_call(name)
    character(len=*), intent(in) :: name
    pnewdt = 1
    call UMAT(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
              time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, name, 1, 2, 3, 120, props, 22, &
              coords, drot, pnewdt, 1.0_dp, drot, drot, 1, 1, 0, 0, jstep, 1)
    if (pnewdt < 0.0_dp) refused = refused + 1
  end subroutine umat_call

end program umat_near_integer_message
