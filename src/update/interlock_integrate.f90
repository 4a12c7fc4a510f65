!> The update of one material point over one increment (SPEC section 5), the library's entry
!> point. The flat-plane laws without finite depth (a bilinear cohesive law, and the
!> Alfano-Sacco interface with friction) run here with only the checks they need, so that the
!> scenes most FE runs of an intact interface are made of pay close to a hand-coded cohesive
!> law; everything else goes to interlock_general_update (kernel_update).
module interlock_integrate
  use interlock_kinds, only: dp, within_separation_bound
  use interlock_material, only: interlock_material_t, interlock_solver_t, n_schemes, &
      kernel_cohesive
  use interlock_state, only: interlock_state_t
  use interlock_status, only: interlock_info_t, status_ok
  use interlock_general_update, only: kernel_update
  use interlock_kernels, only: share_first_plane
  use interlock_plane_law, only: plane_response_t, plane_law, wear_weights
  implicit none
  private
  public :: interlock_update

contains

  !> Integrate from `old` (state at the start of the increment) to the relative displacement
  !> `s` (end of the increment). `new` receives the state at the end (its contents on entry do
  !> not matter; it must not be `old` itself), `sigma` the traction and `tangent` =
  !> d sigma / d s, the exact derivative of the computed traction. Every field of `info` but
  !> the message is set by the call (it is intent(inout) so that a successful update does not
  !> pay for clearing the message). On failure `info%status` /= status_ok, `info%message` says
  !> why, `new` = `old` and `sigma` = `old%sigma`; on success the message is not defined. A NaN,
  !> an infinity or a component beyond separation_bound in `s` is bad input (no floating-point
  !> exception is raised on it).
  pure subroutine interlock_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info

    info%status = status_ok
    info%newton_iterations = 0
    info%substeps = 1
    info%attempts = 1
    info%max_angle_increment = 0.0_dp
    ! The kernel is kernel_cohesive only in a prepared material. s is tested on its bits (a
    ! NaN in an ordered comparison raises the invalid exception, a trap in hosts that run with
    ! traps on; within_separation_bound is false for both): anything else is checked and
    ! reported by kernel_update (a specialised kernel)
    ! or general_update.
    if (mat%kernel == kernel_cohesive .and. solver%substep_tol <= 0.0_dp .and. &
        solver%scheme >= 1 .and. solver%scheme <= n_schemes .and. &
        within_separation_bound(s(1)) .and. within_separation_bound(s(2))) then
      if (mat%use_friction) then
        call flat_plane_step(mat, solver%scheme, .true., s, old, new, sigma, tangent)
      else
        call flat_plane_step(mat, solver%scheme, .false., s, old, new, sigma, tangent)
      end if
      info%max_damage_increment = new%damage(1) - old%damage(1)
    else
      call kernel_update(mat, solver, s, old, new, sigma, tangent, info)
    end if
  end subroutine interlock_update

  !> One flat plane without finite depth (SPEC section 7): with `friction` false a bilinear
  !> cohesive law, the mixed-mode damage alone; with it the Alfano-Sacco interface, Coulomb
  !> friction on the damaged part. The plane's law (interlock_plane_law) in the global frame,
  !> the energies and the work; every plane of a flat RIA shares the history. The law most FE
  !> runs of an intact interface call: no rotation, no contact area, and without friction no
  !> friction return (`friction` is a constant at each call, so that the inlined law drops
  !> what it does not use). Agrees with the general path to round-off (core_kernels).
  pure subroutine flat_plane_step(mat, scheme, friction, s, old, new, sigma, tangent)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme
    logical, intent(in) :: friction
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(plane_response_t) :: p
    real(dp) :: a_end, g_slip

    call plane_law(mat, s(1), s(2), old%beta(1), old%damage(1), old%sf(1), friction, p)
    sigma(1) = p%sig_n
    sigma(2) = p%sig_t
    tangent(1, 1) = p%k_nn
    tangent(2, 1) = p%k_tn
    tangent(1, 2) = p%k_nt
    tangent(2, 2) = p%k_tt
    new%beta(1) = p%beta
    new%damage(1) = p%dmg
    new%sf(1) = p%sf
    new%theta(1) = old%theta(1)
    new%tauf(1) = p%tauf
    if (friction) then
      ! The wear driver of each scheme (no wear on a flat plane, but zeta is kept as the
      ! paper's output).
      call wear_weights(mat, scheme, old%damage(1), old%tauf(1), 1.0_dp, 0.0_dp, old%s(1), &
                        old%s(2), a_end, g_slip)
      new%zeta(1) = old%zeta(1) + (a_end * p%wfric + g_slip * p%slip)
      new%diss_friction = old%diss_friction + p%wfric
    else
      ! No friction traction, no frictional work: in an admissible start state tau_f = 0 too
      ! (|tau_f| <= mu p), so no scheme's driver adds any.
      new%zeta(1) = old%zeta(1)
      new%diss_friction = old%diss_friction
    end if
    if (mat%n_planes > 1) call share_first_plane(mat%n_planes, old, new)
    new%stored = p%psi
    new%diss_damage = old%diss_damage + p%wdmg
    new%work = old%work + 0.5_dp * ((old%sigma(1) + sigma(1)) * (s(1) - old%s(1)) + &
                                    (old%sigma(2) + sigma(2)) * (s(2) - old%s(2)))
    new%s = s
    new%sigma = sigma
  end subroutine flat_plane_step

end module interlock_integrate
