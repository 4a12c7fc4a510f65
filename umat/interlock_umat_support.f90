!> The check sequence of a UMAT call, which both bodies run (the 2D body
!> umat/interlock_umat_body.f90, NTENS = 2; the 3D one umat/interlock_umat_body_3d.f90,
!> NTENS = 3; the thin layer umat/interlock_umat_layer.f90 through them): the host's arguments,
!> the properties, the state and the separations, in the order, with the messages and PNEWDT
!> answers of umat/interlock_umat_body.f90's header; and what a successful call writes besides
!> the traction, the tangent and the state. The messages are umat/interlock_umat_reports.f90's.
!>
!> **Cost.** The sequence runs on every call: every value that may be garbage is tested on
!> its bits (interlock_numbers:key_in_range: no comparison of a NaN); a failure is one call of
!> a report (the messages are built there, in a file of their own, so that the sequence stays
!> small enough to inline). This file is compiled for link-time optimisation with the bodies
!> and the library's UMAT path (umat/CMakeLists.txt), so that the checks inline into each body.
!>
!> **Threads.** No SAVE'd, module or COMMON state; `recursive`: every local on the stack.
module interlock_umat_support
  use interlock_numbers, only: key_in_range
  use interlock_umat_reports, only: bad_precision, bad_ntens, reject_argument, reject_nstatv, &
      reject_layer_nstatv, reject_properties, reject_start_separation, reject_statev, &
      reject_diverged, bad_stress
  use interlock, only: dp, separation_bound, interlock_material_t, interlock_solver_t, &
      interlock_state_t, umat_controls_t, status_ok, message_len, is_nan_value
  use interlock_step_control, only: pnewdt_none, separation_bits, increment_bits, state_bits
  implicit none
  private
  public :: umat_check_call, umat_symmetric_tangent_wanted, umat_energies

contains

  !> The checks of a UMAT call of the law of dimension n (2: the 2D body, 3: the 3D one), in
  !> this order: a NaN PNEWDT on entry replaced by 1 (no request); the precision of
  !> the reals; NTENS = n; NSTATV (in 2D before the PROPS, in 3D once the PROPS have given the
  !> RIA's plane count), and for the thin layer no NSTATV between the law's count and the
  !> law's and the layer's; the PROPS; STRAN (bad input); STRESS on entry; STATEV; last DSTRAN
  !> and the end of the increment (a diverged global iteration: every bad input wins over it,
  !> so that a host is stopped, not sent into cutbacks, by input no cutback repairs). On
  !> success `ok`, the material, the solver, the controls, `nsv` (the law's STATEV count) and
  !> s = STRAN + DSTRAN; otherwise one line names the point and the value
  !> (once per material and kind) and PNEWDT is lowered, nothing else written.
  recursive subroutine umat_check_call(n, NTENS, NSTATV, NPROPS, STRESS, STATEV, STRAN, DSTRAN, &
      PROPS, PNEWDT, NOEL, NPT, KINC, CMNAME, mat, solver, controls, nsv, s, ok, &
      layer_props_offset, layer_nstatv_extra)
    use interlock, only: props_n_to_material, props_n_to_material_3d, umat_nstatv, &
        umat_nstatv_3d, statev_bad_index, statev_bad_index_3d
    integer, intent(in) :: n   !< the law's dimension: 2 or 3
    integer, intent(in) :: NTENS, NSTATV, NPROPS, NOEL, NPT, KINC
    real(dp), intent(in) :: STRESS(NTENS), STATEV(NSTATV), STRAN(NTENS), DSTRAN(NTENS), &
                            PROPS(NPROPS)
    real(dp), intent(inout) :: PNEWDT
    character(len=*), intent(in) :: CMNAME
    type(interlock_material_t), intent(inout) :: mat
    type(interlock_solver_t), intent(inout) :: solver      !< (set by the PROPS)
    type(umat_controls_t), intent(inout) :: controls       !< (set by the PROPS)
    integer, intent(out) :: nsv
    real(dp), intent(out) :: s(n)   !< STRAN + DSTRAN (when ok)
    logical, intent(out) :: ok
    !> For the thin layer: PROPS are its PROPS from this index + 1 on (messages name both).
    integer, intent(in), optional :: layer_props_offset
    !> For the thin layer: the slots of its output after the law's STATEV.
    integer, intent(in), optional :: layer_nstatv_extra
    character(len=message_len) :: message
    integer :: stat, bad

    ok = .false.
    nsv = 0
    if (is_nan_value(PNEWDT)) PNEWDT = pnewdt_none
    if (precision(STRESS) < 15 .or. precision(PROPS) < 15 .or. precision(PNEWDT) < 15) then
      call reject_argument(bad_precision, min(precision(STRESS), precision(PROPS), &
                           precision(PNEWDT)), [0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (NTENS /= n) then
      call reject_argument(bad_ntens, NTENS, [0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (n == 2) then
      nsv = umat_nstatv
      if (.not. nstatv_admitted()) return
      call props_n_to_material(NPROPS, PROPS, mat, solver, controls, stat, message)
    else
      call props_n_to_material_3d(NPROPS, PROPS, mat, solver, controls, stat, message)
    end if
    if (stat /= status_ok) then
      call reject_properties(message, NPROPS, NOEL, NPT, KINC, CMNAME, PNEWDT, layer_props_offset)
      return
    end if
    if (n == 3) then
      ! (the STATEV the RIA needs: known once the PROPS are)
      nsv = umat_nstatv_3d(mat%n_planes)
      if (.not. nstatv_admitted()) return
    end if
    if (.not. magnitudes_within(n, STRAN, separation_bits)) then
      call reject_start_separation(STRAN(1:n), NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (.not. magnitudes_within(n, STRESS, state_bits)) then
      call reject_argument(bad_stress, 0, STRESS(1:n), NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (n == 2) then
      bad = statev_bad_index(STATEV(1:nsv), mat)
    else
      bad = statev_bad_index_3d(STATEV(1:nsv), mat)
    end if
    if (bad /= 0) then
      call reject_statev(STATEV(1:nsv), n, bad, mat, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    ! |x| <= bound on the magnitude's bits, then the sum of values now known finite.
    if (magnitudes_within(n, DSTRAN, increment_bits)) then
      s = STRAN(1:n) + DSTRAN(1:n)
      ok = abs(s(1)) <= separation_bound .and. abs(s(2)) <= separation_bound
      if (n == 3) ok = ok .and. abs(s(3)) <= separation_bound
    end if
    if (.not. ok) call reject_diverged(DSTRAN(1:n), NOEL, NPT, KINC, CMNAME, PNEWDT)

  contains

    !> NSTATV >= nsv, and for the thin layer not between nsv and nsv + its output's slots.
    logical function nstatv_admitted()
      nstatv_admitted = .false.
      if (NSTATV < nsv) then
        call reject_nstatv(NSTATV, nsv, n, mat%n_planes, NOEL, NPT, KINC, CMNAME, PNEWDT)
        return
      end if
      if (present(layer_nstatv_extra)) then
        if (NSTATV > nsv .and. NSTATV < nsv + layer_nstatv_extra) then
          call reject_layer_nstatv(NSTATV, nsv, layer_nstatv_extra, NOEL, NPT, KINC, CMNAME, &
                                   PNEWDT)
          return
        end if
      end if
      nstatv_admitted = .true.
    end function nstatv_admitted

  end subroutine umat_check_call

  !> |x(i)| <= the value of the bits `bound` for i = 1..n, on the magnitudes' bits
  !> (key_in_range: false for NaN and the infinities, no comparison of a NaN), counted, not
  !> branched.
  pure logical function magnitudes_within(n, x, bound) result(ok)
    use, intrinsic :: iso_fortran_env, only: int64
    integer, intent(in) :: n
    real(dp), intent(in) :: x(n)
    integer(int64), intent(in) :: bound
    integer :: i, n_out
    n_out = 0
    do i = 1, n
      n_out = n_out + merge(0, 1, key_in_range(x(i), -1_int64 - bound, bound))
    end do
    ok = n_out == 0
  end function magnitudes_within

  !> Property `tangent` = 2: a symmetric DDSDDE for hosts that symmetrize (the update is not
  !> touched; src/api/interlock_host_tangent.f90 says why this one). PROPS are checked: a whole
  !> number, no rounding call.
  pure logical function umat_symmetric_tangent_wanted(nprops, props) result(wanted)
    use interlock, only: prop_tangent, tangent_symmetric
    integer, intent(in) :: nprops
    real(dp), intent(in) :: props(nprops)
    wanted = .false.
    if (nprops >= prop_tangent) wanted = props(prop_tangent) > tangent_symmetric - 0.5_dp
  end function umat_symmetric_tangent_wanted

  !> The energies of a successful call: SSE the stored energy, SCD the dissipation (damage +
  !> friction), SPD = 0; no heat generation, no thermal coupling (RPL and its derivatives 0).
  pure subroutine umat_energies(new, sse, spd, scd, rpl, ddsddt, drplde, drpldt)
    class(interlock_state_t), intent(in) :: new
    real(dp), intent(out) :: sse, spd, scd, rpl, ddsddt(:), drplde(:), drpldt
    sse = new%stored
    spd = 0.0_dp
    scd = new%diss_damage + new%diss_friction
    rpl = 0.0_dp
    ddsddt = 0.0_dp
    drplde = 0.0_dp
    drpldt = 0.0_dp
  end subroutine umat_energies

end module interlock_umat_support
