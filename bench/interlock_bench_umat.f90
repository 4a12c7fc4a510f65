!> The UMAT rows of the cost benchmark: the histories of the cost study through the Abaqus
!> calling sequence of the external `UMAT` (umat/), as a host calls it at one integration point
!> (PROPS parsed every call, STATEV and STRESS kept by the host and passed in and out, STRAN
!> and DSTRAN), and the floor of what any UMAT must do per call besides its law.
module interlock_bench_umat
  use interlock, only: dp, n_properties_2d, properties, umat_nstatv, n_statevars_strike, umat_planes, prop_mu, prop_h_n, &
      prop_theta0, prop_thetaf, prop_zeta0, prop_scheme, prop_effect_interlocking
  use interlock_bench_umat_floor, only: umat_floor_call
  ! (the explicit interface of the external UMAT, as a host written in modern Fortran declares it)
  use test_umat_interface, only: UMAT
  implicit none
  private
  public :: umat_props, time_umat, time_umat_floor, time_umat_3d


contains

  !> PROPS of effect set `iset` (the materials of interlock_bench_scenes:make_effect_set) with
  !> the given scheme: a 2D element's deck, PROPS 1-20. The UMAT always has the paper's
  !> three-plane RIA: the flat sets 1 and 2 switch interlocking off (three flat planes sharing
  !> one history).
  pure subroutine umat_props(iset, scheme, props)
    integer, intent(in) :: iset, scheme
    real(dp), intent(out) :: props(n_properties_2d)
    props = properties(1:n_properties_2d)%default
    props(1:4) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp]
    props(prop_mu) = merge(0.5_dp, 0.0_dp, iset >= 2)
    props(prop_h_n) = merge(1.0_dp, 1.0e30_dp, iset >= 4)
    props(prop_theta0) = 30.0_dp
    props(prop_thetaf) = merge(7.0_dp, 30.0_dp, iset >= 5)
    props(prop_zeta0) = merge(1.0_dp, 1.0e30_dp, iset >= 5)
    props(prop_scheme) = real(scheme, dp)
    if (iset <= 2) props(prop_effect_interlocking) = 0.0_dp
  end subroutine umat_props

  !> Every history through the UMAT from a virgin STATEV, one call per point. `cuts` counts
  !> the calls that proposed PNEWDT < 1 (their results are kept, as in a run without cut-backs).
  subroutine time_umat(props, h, chk, fails, cuts)
    real(dp), intent(in) :: props(:), h(:, :, :)
    real(dp), intent(inout) :: chk
    integer, intent(inout) :: fails, cuts
    call run_umat_histories(props, h, chk, fails, cuts, .false.)
  end subroutine time_umat

  !> The host's loop of time_umat (floor false) and time_umat_floor (floor true).
  subroutine run_umat_histories(props, h, chk, fails, cuts, floor)
    real(dp), intent(in) :: props(:), h(:, :, :)
    real(dp), intent(inout) :: chk
    integer, intent(inout) :: fails, cuts
    logical, intent(in) :: floor
    real(dp) :: stress(2), statev(umat_nstatv), ddsdde(2, 2), sse, spd, scd, rpl, ddsddt(2), &
                drplde(2), drpldt, stran(2), dstran(2), time(2), dtime, temp, dtemp, predef(1), &
                dpred(1), coords(3), drot(3, 3), pnewdt, celent, dfgrd0(3, 3), dfgrd1(3, 3), acc
    integer :: ih, i
    time = 0.0_dp
    dtime = 1.0_dp
    temp = 0.0_dp
    dtemp = 0.0_dp
    predef = 0.0_dp
    dpred = 0.0_dp
    coords = 0.0_dp
    drot = 0.0_dp
    celent = 1.0_dp
    dfgrd0 = 0.0_dp
    dfgrd1 = 0.0_dp
    sse = 0.0_dp
    spd = 0.0_dp
    scd = 0.0_dp
    rpl = 0.0_dp
    ddsddt = 0.0_dp
    drplde = 0.0_dp
    drpldt = 0.0_dp
    acc = 0.0_dp
    do ih = 1, size(h, 3)
      statev = 0.0_dp
      stress = 0.0_dp
      stran = 0.0_dp
      do i = 1, size(h, 2)
        dstran = h(:, i, ih) - stran
        pnewdt = 1.0_dp
        if (floor) then
          call umat_floor_call(props, size(props), statev, stress, stran, dstran, ddsdde, fails)
        else
          call UMAT(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, &
                    dstran, time, dtime, temp, dtemp, predef, dpred, 'BENCH', 1, 1, 2, &
                    umat_nstatv, props, size(props), coords, drot, pnewdt, celent, dfgrd0, &
                    dfgrd1, 1, 1, 1, 1, [1, 1, 0, 0], i)
        end if
        if (pnewdt < 0.0_dp) fails = fails + 1   ! bad input (accuracy cuts propose 0.1 .. 1)
        if (pnewdt < 1.0_dp) cuts = cuts + 1
        stran = h(:, i, ih)
        acc = acc + (stress(1) + stress(2)) + (ddsdde(1, 1) + ddsdde(2, 2)) + &
              (ddsdde(1, 2) + ddsdde(2, 1))
      end do
    end do
    chk = chk + acc
  end subroutine run_umat_histories

  !> The floor of the UMAT's overhead over its law, on the same histories and with the same
  !> host side as time_umat: what any UMAT of this law must do per call besides the update
  !> (interlock_bench_umat_floor).
  subroutine time_umat_floor(props, h, chk)
    real(dp), intent(in) :: props(:), h(:, :, :)
    real(dp), intent(inout) :: chk
    integer :: fails, cuts
    fails = 0
    cuts = 0
    call run_umat_histories(props, h, chk, fails, cuts, .true.)
    chk = chk + fails   ! (states the floor's checks refused: none on these histories)
  end subroutine time_umat_floor

  !> Every history h(3, :, :) through the UMAT as a 3D cohesive element (NTENS = 3) with the
  !> PROPS of a 2D element (the paper's RIA), from a virgin STATEV, one call per point.
  subroutine time_umat_3d(props, h, chk, fails)
    real(dp), intent(in) :: props(:), h(:, :, :)
    real(dp), intent(inout) :: chk
    integer, intent(inout) :: fails
    !> (umat_nstatv_3d for the paper's RIA, as a constant)
    integer, parameter :: nstatv = umat_nstatv + n_statevars_strike * umat_planes
    real(dp) :: stress(3), statev(nstatv), ddsdde(3, 3), sse, spd, scd, rpl, ddsddt(3), &
                drplde(3), drpldt, stran(3), time(2), zero1(1), coords(3), eye(3, 3), pnewdt, acc
    integer :: ih, i
    time = 0.0_dp
    zero1 = 0.0_dp
    coords = 0.0_dp
    eye = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
    sse = 0.0_dp
    spd = 0.0_dp
    scd = 0.0_dp
    rpl = 0.0_dp
    ddsddt = 0.0_dp
    drplde = 0.0_dp
    drpldt = 0.0_dp
    acc = 0.0_dp
    do ih = 1, size(h, 3)
      statev = 0.0_dp
      stress = 0.0_dp
      stran = 0.0_dp
      do i = 1, size(h, 2)
        pnewdt = 1.0_dp
        call UMAT(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, &
                  h(:, i, ih) - stran, time, 1.0_dp, 0.0_dp, 0.0_dp, zero1, zero1, 'BENCH3D', 1, &
                  2, 3, nstatv, props, size(props), coords, eye, pnewdt, 1.0_dp, eye, eye, 1, 1, &
                  1, 1, [1, 1, 0, 0], i)
        if (pnewdt < 0.0_dp) fails = fails + 1
        stran = h(:, i, ih)
        acc = acc + sum(stress) + sum(ddsdde)
      end do
    end do
    chk = chk + acc
  end subroutine time_umat_3d

end module interlock_bench_umat
