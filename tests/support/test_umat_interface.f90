!> The explicit interface of the external UMAT (as an FE code written in modern Fortran would
!> declare it) and a point driver that fills the arguments a cohesive element does not use.
module test_umat_interface
  use interlock, only: dp
  implicit none
  private
  public :: UMAT, umat_point_t, call_umat

  interface
    recursive subroutine UMAT(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, &
                              DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, &
                              CMNAME, NDI, NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, &
                              PNEWDT, CELENT, DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC)
      import :: dp
      integer, intent(in) :: NDI, NSHR, NTENS, NSTATV, NPROPS, NOEL, NPT, LAYER, KSPT, JSTEP(4), KINC
      character(len=*), intent(in) :: CMNAME
      real(dp), intent(inout) :: STRESS(NTENS), STATEV(NSTATV), DDSDDE(NTENS, NTENS), SSE, SPD, &
                                 SCD, RPL, DRPLDT, DDSDDT(NTENS), DRPLDE(NTENS), PNEWDT
      real(dp), intent(in) :: STRAN(NTENS), DSTRAN(NTENS), TIME(2), DTIME, TEMP, DTEMP, &
                              PREDEF(*), DPRED(*), PROPS(NPROPS), COORDS(3), DROT(3, 3), CELENT, &
                              DFGRD0(3, 3), DFGRD1(3, 3)
    end subroutine UMAT
  end interface

  !> What a cohesive integration point keeps between increments (host side).
  type :: umat_point_t
    real(dp), allocatable :: stress(:), statev(:), ddsdde(:, :)
    real(dp) :: sse = 0.0_dp, spd = 0.0_dp, scd = 0.0_dp, pnewdt = 1.0e36_dp
  end type umat_point_t

contains

  !> One UMAT call for point `pt` (its arrays sized NTENS, NSTATV), from STRAN by DSTRAN.
  subroutine call_umat(pt, props, stran, dstran, noel, npt, kinc)
    type(umat_point_t), intent(inout) :: pt
    real(dp), intent(in) :: props(:), stran(:), dstran(:)
    integer, intent(in) :: noel, npt, kinc
    real(dp) :: rpl, drpldt, ddsddt(size(stran)), drplde(size(stran)), time(2), predef(1), &
                dpred(1), coords(3), drot(3, 3), dfgrd(3, 3)
    integer :: jstep(4), k
    time = [0.0_dp, 0.0_dp]
    predef = 0.0_dp
    dpred = 0.0_dp
    coords = 0.0_dp
    drot = 0.0_dp
    do k = 1, 3
      drot(k, k) = 1.0_dp
    end do
    dfgrd = drot
    jstep = [1, 1, 0, 0]
    rpl = 0.0_dp
    drpldt = 0.0_dp
    ddsddt = 0.0_dp
    drplde = 0.0_dp
    call UMAT(pt%stress, pt%statev, pt%ddsdde, pt%sse, pt%spd, pt%scd, rpl, ddsddt, drplde, &
              drpldt, stran, dstran, time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, 'TEST', 1, 1, &
              size(stran), size(pt%statev), props, size(props), coords, drot, pt%pnewdt, 1.0_dp, &
              dfgrd, dfgrd, noel, npt, 1, 1, jstep, kinc)
  end subroutine call_umat

end module test_umat_interface
