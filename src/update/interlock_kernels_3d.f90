!> The specialised one-step update of a three-dimensional interface in the explicit scheme (SPEC
!> section 9), the fast path of interlock_update_3d: every plane's angle frozen at its stored
!> value within the step, the wear of eq. 25 after it, and the exact 3x3 tangent at the fixed
!> angles (R^T K_loc R of each plane times its weight, R = B A the turns by the plane's angle and
!> its azimuth: a run of planes that share an azimuth summed in its frame and turned by A once;
!> and the contact area's d A_g / d s_N term). Each plane's law is taken with its values and its
!> 3x3 local tangent only, in scalars, from the mechanisms' procedures (interlock_damage,
!> interlock_friction's radial return, eq. 6 of interlock_plane_law, interlock_wear,
!> interlock_geometry): none of the general path's derivatives of the start state, wear drivers or
!> D14 terms. A plane whose s_kn is within the round-off of its rotation is at the tie s_kn = 0
!> and closed for every derivative (SPEC D13), as in the general path: a path in a plane's surface
!> (the paper's RIA slid along a ridge) stays there. It declines (done false: the caller takes the
!> general path, interlock_general_path, unchanged) what it does not handle at that cost: a
!> separated RIA (D7), a trial friction traction near overflow, a tangent beyond the stable bound,
!> anything not finite. It agrees with the general path to round-off and shares none of its code;
!> core_kernels3d checks it.
module interlock_kernels_3d
  use interlock_kinds, only: dp, is_finite_value
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      max_planes
  use interlock_state, only: interlock_state_3d_t, state_3d_end_point
  use interlock_damage, only: damage_may_grow, damage_growth
  use interlock_friction, only: radial_return, vector_norm, norm_gradient, &
      mean_direction_return, mean_direction_slide, mean_direction_tie, straight_wear_start, &
      direction_turn_of
  use interlock_geometry, only: contact_area
  use interlock_wear, only: worn_angle
  use interlock_plane_law, only: plane_frame, wear_weights, normal_traction, tangential_traction, &
      wear_angle_error, add_wear_error, wear_error_of
  use interlock_kinematics, only: to_local, to_global
  use interlock_plane_trial_3d, only: plane_trial_t, trial_bound
  implicit none
  private
  public :: explicit_step_3d, explicit_step_3d_estimate

  !> The plane law's trapezoidal wear terms and D14 (interlock_kernel_planes_3d.inc) are not
  !> compiled into this kernel
  logical, parameter :: trapezoidal_terms = .false.
  !> The scheme of this kernel's planes (scheme_plane's wear weights)
  type(interlock_solver_t), parameter :: explicit_solver = interlock_solver_t(scheme=scheme_explicit)

contains

  !> The explicit scheme's step of every plane from `old` to s = (s_N, s_T1, s_T2) [mm]: the end
  !> state `new` (traction and energies included; the planes beyond n_planes untouched), the
  !> traction `sigma` and `tangent` = d sigma / d s at the fixed start state. `done` false: the
  !> kernel declined (`new`, `sigma`, `tangent` partly written), the general path takes the
  !> increment. `limit`: the largest admissible sum of the tangent's magnitudes (the general
  !> path's stable bound on its entries; a larger sum is declined).
  pure subroutine explicit_step_3d(mat, s, old, limit, new, sigma, tangent, done)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    logical, intent(out) :: done
    integer :: iterations
    real(dp) :: err
    call step_of_planes(mat, explicit_solver, s, old, limit, .false., new, sigma, tangent, &
                        iterations, done, err)
  end subroutine explicit_step_3d

  !> explicit_step_3d with the step's embedded error estimate err (the general path's of the
  !> whole increment as one step, interlock_step_3d), for error-controlled substepping: the
  !> increment is kept as one step where err is within the tolerance.
  pure subroutine explicit_step_3d_estimate(mat, s, old, limit, new, sigma, tangent, done, err)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3), err
    logical, intent(out) :: done
    integer :: iterations
    call step_of_planes(mat, explicit_solver, s, old, limit, .true., new, sigma, tangent, &
                        iterations, done, err)
  end subroutine explicit_step_3d_estimate

  !> Plane k at its frozen start angle (frame c, sn; azimuth frame cp, sp) over the step to its
  !> trial t (plane_trial), area fraction gam, contact area `area` (slope darea): its traction
  !> and tangent added to sigma and tangent in its azimuth's frame (plane_share), its energies
  !> added (plane_at_angle), its end state stored in `new`, with the wear of eq. 25 after the
  !> step; with `estimate` its share of the step's error estimate added to err_angle and
  !> err_traction (the explicit scheme's angle error, interlock_plane_law:wear_angle_error, at
  !> the start angle's traction). `ok` false: declined. No iterations.
  pure subroutine scheme_plane(mat, solver, k, cp, sp, c, sn, t, old, gam, area, darea, &
                               estimate, sigma, tangent, energy, err_angle, err_traction, new, &
                               iterations, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: k
    real(dp), intent(in) :: cp, sp, c, sn, gam, area, darea
    type(plane_trial_t), intent(in) :: t
    type(interlock_state_3d_t), intent(in) :: old
    logical, intent(in) :: estimate
    real(dp), intent(inout) :: sigma(3), tangent(3, 3), energy(3), err_angle, err_traction
    type(interlock_state_3d_t), intent(inout) :: new
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    real(dp) :: beta, dmg, sf(2), tauf(2), slip_dip, g_wfric(3), sig_loc(3), &
                k_loc(3, 3), tauf_norm, slip_norm, a_w, g_slip, zeta, theta, slope, e, wear(2), &
                g_wear(3, 2)
    logical :: grows

    iterations = 0
    ! (with the estimate the plane's traction and K_loc come back, for d sig / d theta, and its
    ! share is added here)
    call plane_at_angle(mat, k, c, sn, t, old, .false., .not. estimate, .false., &
                        .false., [0.0_dp, 0.0_dp], gam, area, darea, sigma, tangent, energy, &
                        beta, dmg, sf, tauf, slip_dip, g_wfric, wear, g_wear, sig_loc, k_loc, &
                        tauf_norm, slip_norm, grows, ok)
    if (.not. ok) return
    if (estimate) then
      call plane_share(c, sn, sig_loc, k_loc, .not. grows, gam, area, darea, sigma, tangent)
      call plane_energies(mat, k, old, t%sl, beta, dmg, sf, tauf, tauf_norm, slip_norm, sig_loc, &
                          gam * area, energy)
    end if

    ! Explicit wear (eq. 25): the frictional work driven by the start state's friction traction,
    ! the angle for the next step (eq. 22) on a plane that wears.
    call wear_weights(mat, solver%scheme, old%damage(k), old%tauf(k), c, sn, old%s(1), 0.0_dp, &
                      a_w, g_slip)
    zeta = old%zeta(k) + (a_w * (dmg * abs(tauf(1)) * slip_dip) + g_slip * slip_dip)
    theta = old%theta(k)
    if (mat%plane_wears(k) .and. zeta > old%zeta(k)) &
      call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), zeta, theta, slope)
    if (estimate) then
      e = 0.0_dp
      if (mat%plane_wears(k)) e = wear_angle_error(mat, k, scheme_explicit, theta, &
                                                   old%theta(k), zeta, old%zeta(k), &
                                                   dmg * abs(tauf(1)) * slip_dip, slip_dip, &
                                                   g_slip, 0.0_dp)
      call add_plane_error(e, gam * area, cp, sp, c, sn, traction_angle_slope(t%sl, sig_loc, &
                           k_loc), dmg, tauf_norm, plane_turn(k, old, tauf, tauf_norm, &
                           slip_norm), err_angle, err_traction)
    end if
    call store_plane(k, beta, dmg, sf, zeta, theta, tauf, new)
  end subroutine scheme_plane

  include 'interlock_kernel_planes_3d.inc'

end module interlock_kernels_3d
