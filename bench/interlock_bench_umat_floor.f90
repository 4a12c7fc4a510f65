!> The floor of the UMAT's overhead, in a file of its own so that the compiler cannot inline it
!> into the timing loop (a host's call of a UMAT is never inlined).
module interlock_bench_umat_floor
  use interlock, only: dp, umat_nstatv
  implicit none
  private
  public :: umat_floor_call

contains

  !> One call of the floor: read every given property and check it against its range (plain
  !> comparisons, the ranges written in), derive the constants the law needs (K_n, K_t, the
  !> inverses of s_0n, s_0t and eta) and, with interlocking on, the cosine and sine of the one
  !> fixed angle theta_0 (the RIA's planes are -theta_0, 0, +theta_0); read and check the 22
  !> state variables (ranges; theta between theta_f and theta_0); write the 22 back, and the
  !> traction and tangent (here the undamaged law, so that the outputs depend on the inputs).
  subroutine umat_floor_call(props, nprops, statev, stress, stran, dstran, ddsdde, bad)
    integer, intent(in) :: nprops
    real(dp), intent(in) :: props(nprops), stran(2), dstran(2)
    real(dp), intent(inout) :: statev(umat_nstatv), stress(2)
    real(dp), intent(out) :: ddsdde(2, 2)
    integer, intent(inout) :: bad
    real(dp), parameter :: big = huge(1.0_dp)
    real(dp) :: kn, kt, inv_s0n, inv_s0t, inv_eta, c, sn, s0n, s0t, th0, thf, lo(3), hi(3)
    logical :: ok, interlocking
    integer :: k
    ok = nprops >= 9 .and. nprops <= 19
    ok = ok .and. props(1) > 0.0_dp .and. props(1) <= big .and. props(2) > 0.0_dp .and. &
         props(2) <= big .and. props(3) > 0.0_dp .and. props(3) <= big .and. &
         props(4) > 0.0_dp .and. props(4) < 1.0_dp .and. props(5) >= 0.0_dp .and. &
         props(5) <= 100.0_dp .and. props(6) > 0.0_dp .and. props(7) >= 0.0_dp .and. &
         props(7) < 90.0_dp .and. props(8) >= 0.0_dp .and. props(8) <= props(7) .and. &
         props(9) > 0.0_dp
    do k = 10, nprops
      ok = ok .and. props(k) >= 0.0_dp .and. props(k) <= 90.0_dp
    end do
    s0n = (1.0_dp - props(4)) * 2.0_dp * props(3) / props(1)
    s0t = (1.0_dp - props(4)) * 2.0_dp * props(3) / props(2)
    inv_s0n = 1.0_dp / s0n
    inv_s0t = 1.0_dp / s0t
    kn = props(1) * inv_s0n
    kt = props(2) * inv_s0t
    inv_eta = 1.0_dp / props(4)
    th0 = props(7) * 0.017453292519943295_dp
    thf = props(8) * 0.017453292519943295_dp
    c = 1.0_dp
    sn = 0.0_dp
    interlocking = th0 > 0.0_dp
    if (nprops >= 17) interlocking = interlocking .and. props(17) > 0.5_dp
    if (interlocking) then
      c = cos(th0)
      sn = sin(th0)
    end if
    lo = 0.0_dp
    hi = 0.0_dp
    if (interlocking) then
      lo = [thf, 0.0_dp, thf]
      hi = [th0, 0.0_dp, th0]
    end if
    if (statev(22) > 0.5_dp) then
      do k = 1, 3
        ok = ok .and. statev(k) >= 0.0_dp .and. statev(k) <= 1.0_dp .and. &
             statev(3 + k) >= 0.0_dp .and. statev(3 + k) <= big .and. &
             abs(statev(6 + k)) <= 1.0e150_dp .and. statev(9 + k) >= 0.0_dp .and. &
             statev(9 + k) <= 1.0e150_dp .and. abs(statev(12 + k)) >= lo(k) .and. &
             abs(statev(12 + k)) <= hi(k) .and. abs(statev(15 + k)) <= 1.0e150_dp
      end do
      ok = ok .and. abs(statev(19)) <= 1.0e150_dp .and. abs(statev(20)) <= 1.0e150_dp .and. &
           abs(statev(21)) <= 1.0e150_dp .and. statev(22) <= 1.0_dp
    end if
    ok = ok .and. abs(stress(1)) <= 1.0e150_dp .and. abs(stress(2)) <= 1.0e150_dp
    if (.not. ok) bad = bad + 1
    stress(1) = kn * (stran(1) + dstran(1)) * c
    stress(2) = kt * (stran(2) + dstran(2)) + sn * inv_s0n * inv_s0t * inv_eta
    ddsdde(1, 1) = kn
    ddsdde(2, 1) = 0.0_dp
    ddsdde(1, 2) = 0.0_dp
    ddsdde(2, 2) = kt
    do k = 1, umat_nstatv - 1
      statev(k) = statev(k) + 0.0_dp * stress(1)
    end do
    statev(22) = 1.0_dp
  end subroutine umat_floor_call

end module interlock_bench_umat_floor
