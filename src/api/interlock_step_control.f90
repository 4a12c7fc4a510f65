!> The increment control a host gets from the law: the fraction of an increment it is asked to
!> retry with (the UMAT's PNEWDT, the C API's step_fraction), and the bounds a host's
!> separations and tractions must meet. One source for the UMAT (umat/) and the C API
!> (src/api/interlock_c_api.f90); the reasoning behind the accuracy bounds is in the UMAT's
!> header (umat/interlock_umat_body.f90, "PNEWDT").
module interlock_step_control
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp, separation_bound
  use interlock_status, only: interlock_info_t, status_ok
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit
  use interlock_material_table, only: umat_planes
  use interlock_state, only: interlock_state_t, interlock_state_3d_t
  use interlock_integrate, only: interlock_update
  use interlock_integrate_3d, only: interlock_update_3d
  use interlock_props, only: umat_controls_t, state_bound
  implicit none
  private
  public :: step_fraction, step_fraction_3d, step_factor
  public :: pnewdt_bad_input, pnewdt_none, pnewdt_local_failure, pnewdt_diverged, keep_fraction, &
            pnewdt_min_factor, separation_bits, increment_bits, state_bits

  !> Bad input: no retry helps (stop).
  real(dp), parameter :: pnewdt_bad_input = -1.0_dp
  !> "No request" in Abaqus' convention (what a NaN PNEWDT on entry is replaced by).
  real(dp), parameter :: pnewdt_none = 1.0_dp
  !> A local integration failure: a shorter increment may pass.
  real(dp), parameter :: pnewdt_local_failure = 0.5_dp
  !> A diverged global iteration: the cut hosts make for their own diverged iterations.
  real(dp), parameter :: pnewdt_diverged = 0.25_dp
  !> The accuracy bounds: no request for a fraction f >= keep_fraction (the cut would shave
  !> too little to pay for the discarded attempt); requests no smaller than pnewdt_min_factor.
  real(dp), parameter :: keep_fraction = 0.8_dp
  real(dp), parameter :: pnewdt_min_factor = 0.01_dp
  !> A damage or angle bound exceeded by less (relative) is met (step_factor).
  real(dp), parameter :: slack = 1.0e-6_dp
  !> The bounds of a start separation, of an increment and of a traction on entry as ordered
  !> keys (key_in_range: the symmetric range [-1 - B, B] of keys is |x| <= B, one test on the
  !> magnitude's bits).
  integer(int64), parameter :: separation_bits = transfer(separation_bound, 0_int64), &
    increment_bits = transfer(2.0_dp * separation_bound, 0_int64), &
    state_bits = transfer(state_bound, 0_int64)

contains

  !> The fraction of the increment old -> new of a point of a 2D interface that the accuracy
  !> bounds ask a host to retry with: 1 when they hold (or the cut would shave less than
  !> 1 - keep_fraction), else max(pnewdt_min_factor, f) (step_factor; with wear in the explicit
  !> scheme from the state a zero increment gives: one more update, only then).
  pure real(dp) function step_fraction(mat, solver, controls, old, new) result(fraction)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(umat_controls_t), intent(in) :: controls
    type(interlock_state_t), intent(in) :: old, new
    type(interlock_state_t) :: anchor
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), tangent(2, 2), f
    fraction = 1.0_dp
    ! (every bound met, the common case: one test per plane, no call)
    if (bounds_met(mat, controls, old, new)) return
    f = step_factor(mat, controls, old, old, new)
    ! (in the implicit and trapezoidal schemes a zero increment is a no-op, SPEC D10: `old`
    ! is the anchor already)
    if (f < keep_fraction .and. mat%use_wear .and. solver%scheme == scheme_explicit) then
      call interlock_update(mat, solver, old%s, old, anchor, sigma, tangent, info)
      if (info%status == status_ok) f = step_factor(mat, controls, old, anchor, new)
    end if
    if (f < keep_fraction) fraction = max(pnewdt_min_factor, f)
  end function step_fraction

  !> step_fraction for a point of a three-dimensional interface (the damage and the dip angles
  !> of every plane of its RIA).
  pure real(dp) function step_fraction_3d(mat, solver, controls, old, new) result(fraction)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(umat_controls_t), intent(in) :: controls
    type(interlock_state_3d_t), intent(in) :: old, new
    type(interlock_state_3d_t) :: anchor
    type(interlock_info_t) :: info
    real(dp) :: sigma(3), tangent(3, 3), f
    fraction = 1.0_dp
    f = step_factor(mat, controls, old%interlock_state_t, old%interlock_state_t, &
                    new%interlock_state_t)
    if (f < keep_fraction .and. mat%use_wear .and. solver%scheme == scheme_explicit) then
      call interlock_update_3d(mat, solver, [old%s, old%s_t2], old, anchor, sigma, tangent, info)
      if (info%status == status_ok) f = step_factor(mat, controls, old%interlock_state_t, &
                                                    anchor%interlock_state_t, new%interlock_state_t)
    end if
    if (f < keep_fraction) fraction = max(pnewdt_min_factor, f)
  end function step_fraction_3d

  !> Every plane's damage and angle increments within their bounds (the slack of step_factor
  !> included): step_factor would return 1. Any other case (NaN too) goes to step_factor.
  pure logical function bounds_met(mat, controls, old, new)
    type(interlock_material_t), intent(in) :: mat
    type(umat_controls_t), intent(in) :: controls
    type(interlock_state_t), intent(in) :: old, new
    real(dp) :: damage_bound, angle_bound
    integer :: k
    damage_bound = controls%max_damage_increment * (1.0_dp + slack)
    angle_bound = controls%max_angle_increment * (1.0_dp + slack)
    bounds_met = .true.
    ! (the 2D material has umat_planes planes: the loops unrolled, no branch per plane)
    !GCC$ unroll 3
    do k = 1, umat_planes
      bounds_met = bounds_met .and. new%damage(k) - old%damage(k) <= damage_bound
    end do
    if (bounds_met .and. mat%use_wear) then
      !GCC$ unroll 3
      do k = 1, umat_planes
        bounds_met = bounds_met .and. abs(new%theta(k) - old%theta(k)) <= angle_bound
      end do
    end if
  end function bounds_met

  !> Fraction f of the increment old -> new that meets the damage and angle bounds (1 when
  !> both hold), interpolating the drivers beta and zeta linearly between `zero` (the state a
  !> zero increment gives) and `new` (the UMAT's header says why these drivers).
  pure real(dp) function step_factor(mat, controls, old, zero, new) result(f)
    type(interlock_material_t), intent(in) :: mat
    type(umat_controls_t), intent(in) :: controls
    type(interlock_state_t), intent(in) :: old, zero, new
    integer :: k
    real(dp) :: d_target, beta_target, span, dzeta_target, dzeta_zero
    f = 1.0_dp
    do k = 1, mat%n_planes
      if (new%damage(k) - old%damage(k) > controls%max_damage_increment * (1.0_dp + slack)) then
        ! D = (beta - 1) / (eta beta)  <=>  beta = 1 / (1 - eta D)
        d_target = old%damage(k) + controls%max_damage_increment
        beta_target = 1.0_dp / (1.0_dp - mat%eta * d_target)
        ! (no cut helps when the zero increment is already beyond the target: no request)
        if (new%beta(k) > zero%beta(k) .and. beta_target > zero%beta(k)) then
          ! (the quotient only when below f <= 1: no overflow on a tiny denominator)
          if (beta_target - zero%beta(k) < f * (new%beta(k) - zero%beta(k))) &
            f = (beta_target - zero%beta(k)) / (new%beta(k) - zero%beta(k))
        end if
      end if
      if (mat%plane_wears(k) .and. abs(new%theta(k) - old%theta(k)) > &
          controls%max_angle_increment * (1.0_dp + slack)) then
        ! theta(zeta) - theta_f = (theta_0 - theta_f) exp(-zeta/zeta_0): the angle turns by
        ! |theta_old - theta_f| (1 - exp(-dzeta/zeta_0)) when zeta grows by dzeta.
        span = abs(old%theta(k) - mat%thetaf_eff(k))
        dzeta_zero = zero%zeta(k) - old%zeta(k)
        if (span > controls%max_angle_increment) then
          dzeta_target = -mat%zeta0(k) * log(1.0_dp - controls%max_angle_increment / span)
        else
          dzeta_target = 0.0_dp
        end if
        if (new%zeta(k) > zero%zeta(k) .and. dzeta_target > dzeta_zero) then
          if (dzeta_target - dzeta_zero < f * (new%zeta(k) - zero%zeta(k))) &
            f = (dzeta_target - dzeta_zero) / (new%zeta(k) - zero%zeta(k))
        end if
      end if
    end do
  end function step_factor

end module interlock_step_control
