!> The specialised one-step update of a three-dimensional interface in the trapezoidal scheme
!> (SPEC section 9, D11, D14), the fast path of interlock_update_3d for it: each wearing plane's
!> angle coupled to the end of the step by the trapezoidal wear equation zeta - zeta_o =
!> a_w wear_end + g_slip wear_start at theta(zeta) (a_w = 1/2, g_slip = D_o mu p_o / 2 from the
!> start yield of the start separation; without a start term a_w D |tau_f,1| |d sf_1|), solved
!> as the general path solves it (interlock_wear's safeguarded Newton iteration from the same
!> start, so the same root); on a plane that slides at the start, the friction return of D14
!> (the slip increment along the mean of the start and end directions, interlock_friction's
!> mean_direction_return and mean_direction_slide, with its wear terms), radial return where
!> D14 does not apply (a reversal); the exact 3x3 tangent with the angle's term and D14's
!> d psi, and the contact area's d A_g / d s_N term. A plane's law and its coupled step are
!> the implicit kernel's (interlock_kernel_planes_3d.inc, compiled into each kernel) with the
!> trapezoidal terms switched on. It declines (done false: the caller takes the general path)
!> what the implicit kernel declines: a separated RIA (D7), a trial friction traction near
!> overflow, a wear equation without a root within its bound (the general path then retries on
!> sub-increments), a tangent beyond the stable bound, anything not finite. It agrees with the
!> general path to round-off and shares none of its code; core_kernels3d checks it.
module interlock_kernels_3d_trapezoidal
  use interlock_kinds, only: dp, is_finite_value
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_implicit, &
      scheme_trapezoidal, max_planes
  use interlock_state, only: interlock_state_3d_t, state_3d_end_point
  use interlock_damage, only: damage_may_grow, damage_growth
  use interlock_friction, only: radial_return, vector_norm, norm_gradient, start_direction, &
      mean_direction_return, mean_direction_slide, mean_direction_tie, straight_wear_start, &
      direction_turn_of, unit_direction_turn
  use interlock_geometry, only: contact_area
  use interlock_wear, only: worn_angle, worn_angle_slope, wear_root_t, wear_root_begin, &
      wear_root_update
  use interlock_plane_law, only: plane_frame, wear_weights, start_yield, start_weight, &
      trapezoidal_end_weight, normal_traction, tangential_traction, wear_angle_error, &
      add_wear_error, wear_error_of
  use interlock_kinematics, only: to_local, to_global
  use interlock_plane_trial_3d, only: plane_trial_t, trial_bound
  implicit none
  private
  public :: trapezoidal_step_3d, trapezoidal_step_3d_estimate

  !> The plane law's trapezoidal wear terms and D14 (interlock_kernel_planes_3d.inc) and the
  !> trapezoidal weights of the coupled step (interlock_kernel_coupled_3d.inc) are compiled in
  logical, parameter :: trapezoidal_terms = .true.

contains

  !> The trapezoidal scheme's step of every plane from `old` to s = (s_N, s_T1, s_T2) [mm], with
  !> the wear equations' tolerance and bound on iterations of `solver`: the end state `new`
  !> (traction and energies included; the planes beyond n_planes untouched), the traction
  !> `sigma`, `tangent` = d sigma / d s at the fixed start state, the largest number of Newton
  !> iterations of a plane's wear equation (the general path's report). `done` false: the
  !> kernel declined (`new`, `sigma`, `tangent` partly written), the general path takes the
  !> increment. `limit`: the largest admissible sum of the tangent's magnitudes.
  pure subroutine trapezoidal_step_3d(mat, solver, s, old, limit, new, sigma, tangent, &
                                      iterations, done)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    integer, intent(out) :: iterations
    logical, intent(out) :: done
    real(dp) :: err
    call step_of_planes(mat, solver, s, old, limit, .false., new, sigma, tangent, iterations, &
                        done, err)
  end subroutine trapezoidal_step_3d

  !> trapezoidal_step_3d with the step's embedded error estimate err (the general path's of the
  !> whole increment as one step, interlock_step_3d), for error-controlled substepping: the
  !> increment is kept as one step where err is within the tolerance.
  pure subroutine trapezoidal_step_3d_estimate(mat, solver, s, old, limit, new, sigma, tangent, &
                                               iterations, done, err)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), limit
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3), err
    integer, intent(out) :: iterations
    logical, intent(out) :: done
    call step_of_planes(mat, solver, s, old, limit, .true., new, sigma, tangent, iterations, &
                        done, err)
  end subroutine trapezoidal_step_3d_estimate

  include 'interlock_kernel_planes_3d.inc'
  include 'interlock_kernel_coupled_3d.inc'

end module interlock_kernels_3d_trapezoidal
