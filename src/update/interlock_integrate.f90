!> The update of one material point over one increment (SPEC section 5), the library's entry
!> point. The flat-plane laws without finite depth (a bilinear cohesive law, and the
!> Alfano-Sacco interface with friction) run here with only the checks they need, so that the
!> scenes most FE runs of an intact interface are made of pay close to a hand-coded cohesive
!> law; everything else goes to interlock_general_update (kernel_update).
module interlock_integrate
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      scheme_implicit, scheme_trapezoidal, kernel_cohesive
  use interlock_state, only: interlock_state_t
  use interlock_status, only: interlock_info_t, status_ok
  use interlock_general_update, only: kernel_update
  use interlock_kernels, only: share_first_plane
  use interlock_damage, only: damage_growth
  use interlock_friction, only: friction_step
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
  !> why, `new` = `old` and `sigma` = `old%sigma`; on success the message is not defined.
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
    ! The kernel is kernel_cohesive only in a prepared material. abs(x) <= huge is false for NaN
    ! and both infinities: anything else is checked and reported by kernel_update (a
    ! specialised kernel) or general_update.
    if (mat%kernel == kernel_cohesive .and. solver%substep_tol <= 0.0_dp .and. &
        (solver%scheme == scheme_explicit .or. solver%scheme == scheme_implicit .or. &
         solver%scheme == scheme_trapezoidal) .and. &
        abs(s(1)) <= huge(1.0_dp) .and. abs(s(2)) <= huge(1.0_dp)) then
      if (mat%use_friction) then
        call cohesive_friction_step(mat, solver%scheme, s, old, new, sigma, tangent)
      else
        call decohesion_step(mat, s, old, new, sigma, tangent)
      end if
      info%max_damage_increment = new%damage(1) - old%damage(1)
    else
      call kernel_update(mat, solver, s, old, new, sigma, tangent, info)
    end if
  end subroutine interlock_update

  !> One flat plane without finite depth and without friction (a bilinear cohesive law, SPEC
  !> section 7): the mixed-mode damage of interlock_damage, the stored energy, the exact
  !> decohesion energy and the work. Every plane of a flat RIA shares the history. Written for
  !> the fewest operations (it is the law most FE runs of an intact interface call): divisions
  !> only while damage grows, no friction return, stored energy = sigma . s / 2 (no friction
  !> traction). Agrees with the general path to round-off (core_kernels). Why its blocks are
  !> written out rather than shared with the kernels: interlock_kernels:fixed_angle_plane.
  pure subroutine decohesion_step(mat, s, old, new, sigma, tangent)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    real(dp) :: pos, d, gd1, gd2, kpos, kts

    pos = max(0.0_dp, s(1))
    d = old%damage(1)
    gd1 = 0.0_dp
    gd2 = 0.0_dp
    new%beta(1) = old%beta(1)
    new%diss_damage = old%diss_damage
    if (mat%use_damage) then
      call damage_growth(pos * mat%inv_s0n, s(2) * mat%inv_s0t, old%beta(1), old%damage(1), &
                         mat%eta, mat%inv_eta, mat%beta_break, mat%inv_s0n, mat%inv_s0t, &
                         new%beta(1), d, gd1, gd2)
      if (d > old%damage(1)) new%diss_damage = old%diss_damage + &
        mat%decohesion_energy_factor * (min(new%beta(1), mat%beta_break) - &
                                        min(max(old%beta(1), 1.0_dp), mat%beta_break))
    end if
    kpos = mat%kn * pos
    kts = mat%kt * s(2)
    sigma(1) = mat%kn * s(1) - d * kpos
    sigma(2) = (1.0_dp - d) * kts
    if (s(1) > 0.0_dp) then
      tangent(1, 1) = (1.0_dp - d) * mat%kn - kpos * gd1
    else
      tangent(1, 1) = mat%kn
    end if
    tangent(1, 2) = -kpos * gd2
    tangent(2, 1) = -kts * gd1
    tangent(2, 2) = (1.0_dp - d) * mat%kt - kts * gd2
    new%damage(1) = d
    new%sf(1) = s(2)
    ! No friction traction, no frictional work: in an admissible start state tau_f = 0 too
    ! (|tau_f| <= mu p), so neither scheme's driver (eq. 25 uses the start state's) adds any.
    new%zeta(1) = old%zeta(1)
    new%theta(1) = old%theta(1)
    new%tauf(1) = 0.0_dp
    if (mat%n_planes > 1) call share_first_plane(mat%n_planes, old, new)
    new%stored = 0.5_dp * (s(1) * sigma(1) + s(2) * sigma(2))
    new%diss_friction = old%diss_friction
    new%work = old%work + 0.5_dp * ((old%sigma(1) + sigma(1)) * (s(1) - old%s(1)) + &
                                    (old%sigma(2) + sigma(2)) * (s(2) - old%s(2)))
    new%s = s
    new%sigma = sigma
  end subroutine decohesion_step

  !> One flat plane without finite depth, with Coulomb friction on the damaged part (the
  !> Alfano-Sacco interface): the mixed-mode damage (interlock_damage), the friction return
  !> (interlock_friction, written out with scalar derivatives), the stored energy, the exact
  !> decohesion energy and the frictional work. Every plane of a flat RIA shares the history.
  !> Agrees with the general path to round-off (core_kernels).
  pure subroutine cohesive_friction_step(mat, scheme, s, old, new, sigma, tangent)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    real(dp) :: pos, d, gd1, gd2, kpos, kts, mu_p, slip_sign, sf, tauf, &
                dtauf1, dtauf2, slip, work_fric

    pos = max(0.0_dp, s(1))
    d = old%damage(1)
    gd1 = 0.0_dp
    gd2 = 0.0_dp
    new%beta(1) = old%beta(1)
    if (mat%use_damage) call damage_growth(pos * mat%inv_s0n, s(2) * mat%inv_s0t, old%beta(1), &
      old%damage(1), mat%eta, mat%inv_eta, mat%beta_break, mat%inv_s0n, mat%inv_s0t, &
      new%beta(1), d, gd1, gd2)
    ! Friction return (interlock_friction): elastic predictor, return to |tau_f| = mu p.
    mu_p = -mat%mu_eff * mat%kn * min(0.0_dp, s(1))
    call friction_step(mu_p, mat%mu_eff * mat%kn, mat%kt, mat%inv_kt, s(2), old%sf(1), sf, tauf, &
                       dtauf1, dtauf2, slip, slip_sign)
    kpos = mat%kn * pos
    kts = mat%kt * s(2)
    sigma(1) = mat%kn * s(1) - d * kpos
    sigma(2) = (1.0_dp - d) * kts + d * tauf
    if (s(1) > 0.0_dp) then
      tangent(1, 1) = (1.0_dp - d) * mat%kn - kpos * gd1
    else
      tangent(1, 1) = mat%kn
    end if
    tangent(1, 2) = -kpos * gd2
    tangent(2, 1) = d * dtauf1 + (tauf - kts) * gd1
    tangent(2, 2) = (1.0_dp - d) * mat%kt + d * dtauf2 + (tauf - kts) * gd2
    ! Frictional work (decision D4) and the wear driver of each scheme (no wear on a flat plane,
    ! but zeta is kept as the paper's output).
    work_fric = d * abs(tauf) * slip
    if (scheme == scheme_explicit) then
      new%zeta(1) = old%zeta(1) + old%damage(1) * abs(old%tauf(1)) * slip
    else if (scheme == scheme_implicit) then
      new%zeta(1) = old%zeta(1) + work_fric
    else
      ! (start value of the trapezoidal driver: interlock_kernels:start_yield, no depth here)
      new%zeta(1) = old%zeta(1) + 0.5_dp * (work_fric + old%damage(1) * &
                                            (mat%mu_eff * mat%kn * max(0.0_dp, -old%s(1))) * slip)
    end if
    new%damage(1) = d
    new%sf(1) = sf
    new%theta(1) = old%theta(1)
    new%tauf(1) = tauf
    if (mat%n_planes > 1) call share_first_plane(mat%n_planes, old, new)
    ! psi = (1 - D) psi_e + D psi_f = (sigma . s - D tau_f sf) / 2.
    new%stored = 0.5_dp * (s(1) * sigma(1) + s(2) * sigma(2) - d * tauf * sf)
    new%diss_damage = old%diss_damage
    if (d > old%damage(1)) new%diss_damage = old%diss_damage + mat%decohesion_energy_factor * &
        (min(new%beta(1), mat%beta_break) - min(max(old%beta(1), 1.0_dp), mat%beta_break)) - &
        0.5_dp * tauf**2 * mat%inv_kt * (d - old%damage(1))
    new%diss_friction = old%diss_friction + work_fric
    new%work = old%work + 0.5_dp * ((old%sigma(1) + sigma(1)) * (s(1) - old%s(1)) + &
                                    (old%sigma(2) + sigma(2)) * (s(2) - old%s(2)))
    new%s = s
    new%sigma = sigma
  end subroutine cohesive_friction_step

end module interlock_integrate
