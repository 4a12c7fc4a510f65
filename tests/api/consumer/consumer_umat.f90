!> Calls the installed UMAT as an FE code does (implicit interface, PROPS/STATEV arrays).
program consumer_umat
  implicit none
  integer, parameter :: dp = kind(1.0d0)
  real(dp) :: stress(2), statev(22), ddsdde(2, 2), sse, spd, scd, rpl, ddsddt(2), drplde(2), &
              drpldt, stran(2), dstran(2), time(2), predef(1), dpred(1), props(9), coords(3), &
              drot(3, 3), pnewdt, dfgrd(3, 3)
  integer :: jstep(4)
  external :: UMAT
  props = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 1.0e30_dp, 0.0_dp, 0.0_dp, 1.0e30_dp]
  stress = 0.0_dp
  statev = 0.0_dp
  ddsdde = 0.0_dp
  sse = 0.0_dp
  spd = 0.0_dp
  scd = 0.0_dp
  stran = 0.0_dp
  dstran = [0.01_dp, 0.0_dp]
  time = 0.0_dp
  predef = 0.0_dp
  dpred = 0.0_dp
  coords = 0.0_dp
  drot = 0.0_dp
  dfgrd = 0.0_dp
  jstep = [1, 1, 0, 0]
  pnewdt = 1.0e36_dp
  call UMAT(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, &
            time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, 'CONSUMER', 1, 1, 2, 22, props, 9, &
            coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, 1, 1, 1, 1, jstep, 1)
  write (*, '(a,f12.9,a,f8.3)') 'UMAT: elastic traction ', stress(1), ', K_n ', ddsdde(1, 1)
  if (abs(stress(1) - 1.5_dp) > 1.0e-12_dp .or. abs(ddsdde(1, 1) - 150.0_dp) > 1.0e-9_dp) &
    error stop 'wrong UMAT result'
end program consumer_umat
