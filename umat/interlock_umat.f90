!> Abaqus-style UMAT of the interlock cohesive-zone law, for 2D and 3D cohesive elements.
!>
!> A thin wrapper: NTENS = 3 (3D cohesive elements, COH3D8) goes to
!> `interlock_umat_cohesive_3d` (umat/interlock_umat_body_3d.f90), any other NTENS to the 2D
!> body `interlock_umat_cohesive` (umat/interlock_umat_body.f90, with the whole description of
!> PROPS, STATEV, PNEWDT and the arguments; it rejects an NTENS other than 2). The bodies
!> exist under their own names so that a host which brings a `umat` of its own (CalculiX's stub) or another entry
!> (the thin layer for hosts without cohesive elements) can call the same law.
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the table of the messages
!> already written (umat/interlock_umat_messages.f90: only when a message is due, under a
!> lock); the procedure is `recursive` so that every local lives on the stack: safe to call
!> from many threads at once.
recursive subroutine UMAT(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT, &
                          STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, &
                          NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, &
                          DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC)
  use, intrinsic :: iso_fortran_env, only: real64
  use interlock_umat_body, only: interlock_umat_cohesive
  use interlock_umat_body_3d, only: interlock_umat_cohesive_3d
  implicit none
  integer, intent(in) :: NDI, NSHR, NTENS, NSTATV, NPROPS, NOEL, NPT, LAYER, KSPT, JSTEP(4), KINC
  character(len=*), intent(in) :: CMNAME
  real(real64), intent(inout) :: STRESS(NTENS), STATEV(NSTATV), DDSDDE(NTENS, NTENS)
  real(real64), intent(inout) :: SSE, SPD, SCD, RPL, DRPLDT, DDSDDT(NTENS), DRPLDE(NTENS)
  real(real64), intent(in) :: STRAN(NTENS), DSTRAN(NTENS), TIME(2), DTIME, TEMP, DTEMP
  real(real64), intent(in) :: PREDEF(*), DPRED(*), PROPS(NPROPS), COORDS(3), DROT(3, 3), CELENT
  real(real64), intent(in) :: DFGRD0(3, 3), DFGRD1(3, 3)
  real(real64), intent(inout) :: PNEWDT

  if (NTENS == 3) then
    call interlock_umat_cohesive_3d(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, &
      DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, NSHR, NTENS, &
      NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, NOEL, NPT, LAYER, &
      KSPT, JSTEP, KINC)
    return
  end if
  call interlock_umat_cohesive(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, &
    DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, NSHR, NTENS, &
    NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, NOEL, NPT, LAYER, &
    KSPT, JSTEP, KINC)
end subroutine UMAT
