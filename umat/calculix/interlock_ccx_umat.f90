!> CalculiX's `umat`: the interlock law in a thin layer of continuum elements.
!>
!> ccx 2.20 calls `umat` for every material named `ABAQUS<anything>` (umat_main.f ->
!> umat_abaqus.f) with the Abaqus argument list, NTENS = 6 in the user's local axes, and
!> PNEWDT = -1 meaning "no request". This replaces ccx's stub umat.f (leave umat.o out of the
!> link: scripts/build_calculix.sh does) and hands every point to the thin-layer entry with
!> CalculiX's PNEWDT convention (umat/interlock_umat_layer.f90 has PROPS, STATEV and the
!> conventions; docs/calculix.md how ccx calls it).
!>
!> ccx's "linear iteration" (the first iteration of a step whose prescribed displacements
!> change) passes the old field's quadratic Green-Lagrange term as DSTRAN and wants the
!> tangent at the start of the increment: that call is recognised
!> (interlock_umat_layer:calculix_linear_iteration) and answered with a zero increment.
!>
!> **Threads.** ccx calls it from several threads at once: no state is kept but the messages'
!> table (umat/interlock_umat_messages.f90, under its lock); `recursive`.
recursive subroutine umat(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT, &
                          STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, &
                          NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, &
                          DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC)
  use, intrinsic :: iso_fortran_env, only: real64
  use interlock_umat_layer, only: interlock_umat_layer_point, host_calculix, &
      calculix_linear_iteration
  implicit none
  integer, intent(in) :: NDI, NSHR, NTENS, NSTATV, NPROPS, NOEL, NPT, LAYER, KSPT, JSTEP(4), KINC
  character(len=*), intent(in) :: CMNAME
  real(real64), intent(inout) :: STRESS(NTENS), STATEV(NSTATV), DDSDDE(NTENS, NTENS)
  real(real64), intent(inout) :: SSE, SPD, SCD, RPL, DRPLDT, DDSDDT(NTENS), DRPLDE(NTENS)
  real(real64), intent(in) :: STRAN(NTENS), DSTRAN(NTENS), TIME(2), DTIME, TEMP, DTEMP
  real(real64), intent(in) :: PREDEF(*), DPRED(*), PROPS(NPROPS), COORDS(3), DROT(3, 3), CELENT
  real(real64), intent(in) :: DFGRD0(3, 3), DFGRD1(3, 3)
  real(real64), intent(inout) :: PNEWDT
  real(real64) :: increment(NTENS)

  increment = DSTRAN
  if (calculix_linear_iteration(NTENS, DSTRAN, DFGRD0, DFGRD1, JSTEP)) increment = 0.0_real64
  call interlock_umat_layer_point(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, &
    DRPLDT, STRAN, increment, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, NSHR, &
    NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, NOEL, NPT, &
    LAYER, KSPT, JSTEP, KINC, host_calculix)
end subroutine umat
