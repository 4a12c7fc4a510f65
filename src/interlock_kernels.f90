!> Specialised one-step updates, chosen once when the material is prepared, so that a scene
!> pays only for the effects it uses (SPEC section 7): without wear the inclinations are
!> constant (sines and cosines computed once, at set-up), one flat plane needs no rotation at
!> all, and the local law is written with scalar derivatives instead of the general path's
!> gradient vectors (which substepping and the implicit wear equation need). The explicit
!> scheme freezes each angle within the step, so with wear it runs the same kernel with the
!> stored angle's sine and cosine, and one exponential per plane that wore. Each kernel agrees
!> with the general path (interlock_ria) to round-off; a test checks it.
module interlock_kernels
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, scheme_implicit, kernel_flat
  use interlock_wear, only: worn_angle
  use interlock_state, only: interlock_state_t
  use interlock_geometry, only: contact_area
  use interlock_damage, only: damage_dissipation_increment
  implicit none
  private
  public :: kernel_step

  !> The law of one microplane in its own frame over one step, with d(traction)/d(s_kn, s_kt).
  type :: plane_law_t
    real(dp) :: beta, dmg, sf, tauf, zeta
    real(dp) :: sig(2), k(2, 2)
    real(dp) :: psi, wdmg, wfric
  end type plane_law_t

contains

  !> One increment with a specialised kernel. `done` is false when the kernel does not apply
  !> to this increment (a separated RIA): the caller then takes the general path.
  pure subroutine kernel_step(mat, scheme, s, old, new, tangent, done)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(2, 2)
    logical, intent(out) :: done
    type(plane_law_t) :: p
    real(dp) :: area, darea, sigma(2), sl(2), c, sn, gam, kg(2, 2), sg(2), theta, slope
    integer :: k

    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)
    done = area > 0.0_dp
    if (.not. done) return
    new%diss_damage = old%diss_damage
    new%diss_friction = old%diss_friction
    new%stored = 0.0_dp
    if (mat%kernel == kernel_flat) then
      call plane_law(mat, scheme, s, old%beta(1), old%sf(1), old%zeta(1), old%tauf(1), &
                     old%damage(1), p)
      sigma = area * p%sig
      tangent = area * p%k
      call store_plane(p, 1, area, old%theta(1), new)
      do k = 2, mat%n_planes
        new%beta(k) = p%beta
        new%damage(k) = p%dmg
        new%sf(k) = p%sf
        new%zeta(k) = p%zeta
        new%theta(k) = old%theta(k)
        new%tauf(k) = p%tauf
      end do
    else
      sigma = 0.0_dp
      tangent = 0.0_dp
      do k = 1, mat%n_planes
        theta = old%theta(k)
        if (mat%plane_wears(k)) then
          c = cos(theta)
          sn = sin(theta)
        else
          c = mat%cos0(k)
          sn = mat%sin0(k)
        end if
        sl = [c * s(1) + sn * s(2), -sn * s(1) + c * s(2)]
        call plane_law(mat, scheme, sl, old%beta(k), old%sf(k), old%zeta(k), old%tauf(k), &
                       old%damage(k), p)
        gam = mat%gamma_hat(k) * area
        ! R^T sigma_loc and R^T K_loc R.
        sg = [c * p%sig(1) - sn * p%sig(2), sn * p%sig(1) + c * p%sig(2)]
        kg(1, 1) = c * (c * p%k(1, 1) - sn * p%k(1, 2)) - sn * (c * p%k(2, 1) - sn * p%k(2, 2))
        kg(1, 2) = c * (sn * p%k(1, 1) + c * p%k(1, 2)) - sn * (sn * p%k(2, 1) + c * p%k(2, 2))
        kg(2, 1) = sn * (c * p%k(1, 1) - sn * p%k(1, 2)) + c * (c * p%k(2, 1) - sn * p%k(2, 2))
        kg(2, 2) = sn * (sn * p%k(1, 1) + c * p%k(1, 2)) + c * (sn * p%k(2, 1) + c * p%k(2, 2))
        sigma = sigma + gam * sg
        tangent = tangent + gam * kg
        p%sig = sg
        ! Explicit wear (eq. 22, 25): the angle for the next step.
        if (mat%plane_wears(k) .and. p%zeta > old%zeta(k)) call worn_angle(mat%theta_init(k), &
            mat%thetaf_eff(k), mat%inv_zeta0(k), p%zeta, theta, slope)
        call store_plane(p, k, gam, theta, new)
      end do
      if (mat%use_depth) then
        ! d A_g / d s_N times the traction at unit area.
        tangent(:, 1) = tangent(:, 1) + darea * sigma / area
      end if
    end if
    if (mat%kernel == kernel_flat .and. mat%use_depth) then
      tangent(:, 1) = tangent(:, 1) + darea * p%sig
    end if
    new%s = s
    new%sigma = sigma
    new%work = old%work + 0.5_dp * dot_product(old%sigma + sigma, s - old%s)
  end subroutine kernel_step

  !> The plane's end-of-step state into `new`, and its share (weight g) of the energies.
  pure subroutine store_plane(p, k, g, theta_old, new)
    type(plane_law_t), intent(in) :: p
    integer, intent(in) :: k
    real(dp), intent(in) :: g, theta_old
    type(interlock_state_t), intent(inout) :: new
    new%beta(k) = p%beta
    new%damage(k) = p%dmg
    new%sf(k) = p%sf
    new%zeta(k) = p%zeta
    new%theta(k) = theta_old
    new%tauf(k) = p%tauf
    new%diss_damage = new%diss_damage + g * p%wdmg
    new%diss_friction = new%diss_friction + g * p%wfric
    new%stored = new%stored + g * p%psi
  end subroutine store_plane

  !> Damage, friction and traction of one plane with constant inclination, in its own frame.
  pure subroutine plane_law(mat, scheme, sl, beta_o, sf_o, zeta_o, tauf_o, dmg_o, p)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: scheme
    real(dp), intent(in) :: sl(2), beta_o, sf_o, zeta_o, tauf_o, dmg_o
    type(plane_law_t), intent(out) :: p
    real(dp) :: an, at, beq, ddb, gd(2), dtau(2), mu_p, tau_trial, sgn, pos_n, neg_n, slip, x

    ! Damage (interlock_damage): beta = max(beta_o, beta_eq), D = (beta - 1)/(eta beta).
    p%beta = beta_o
    p%dmg = dmg_o
    gd = 0.0_dp
    if (mat%use_damage) then
      an = max(0.0_dp, sl(1)) / mat%s0n
      at = sl(2) / mat%s0t
      beq = sqrt(an * an + at * at)
      if (beq > beta_o) then
        p%beta = beq
        if (beq > 1.0_dp) then
          x = (beq - 1.0_dp) / (mat%eta * beq)
          if (beq >= mat%beta_break) then
            p%dmg = 1.0_dp
          else
            p%dmg = x
            ddb = 1.0_dp / (mat%eta * beq * beq * beq)
            gd = [ddb * an / mat%s0n, ddb * at / mat%s0t]
          end if
        else
          p%dmg = 0.0_dp
        end if
      end if
    end if

    ! Friction (interlock_friction).
    mu_p = 0.0_dp
    if (mat%use_friction) mu_p = -mat%mu_eff * mat%kn * min(0.0_dp, sl(1))
    if (mu_p > 0.0_dp) then
      tau_trial = mat%kt * (sl(2) - sf_o)
      if (abs(tau_trial) <= mu_p) then
        p%sf = sf_o
        p%tauf = tau_trial
        dtau = [0.0_dp, mat%kt]
        slip = 0.0_dp
      else
        sgn = sign(1.0_dp, tau_trial)
        p%tauf = sgn * mu_p
        p%sf = sl(2) - p%tauf / mat%kt
        dtau = [-sgn * mat%mu_eff * mat%kn, 0.0_dp]
        slip = (abs(tau_trial) - mu_p) / mat%kt
      end if
    else
      p%sf = sl(2)
      p%tauf = 0.0_dp
      dtau = 0.0_dp
      slip = abs(p%sf - sf_o)
    end if

    ! Traction and its derivative (interlock_microplane).
    pos_n = max(0.0_dp, sl(1))
    neg_n = min(0.0_dp, sl(1))
    p%sig(1) = mat%kn * neg_n + (1.0_dp - p%dmg) * mat%kn * pos_n
    p%sig(2) = (1.0_dp - p%dmg) * mat%kt * sl(2) + p%dmg * p%tauf
    if (sl(1) > 0.0_dp) then
      p%k(1, 1) = (1.0_dp - p%dmg) * mat%kn - mat%kn * pos_n * gd(1)
    else
      p%k(1, 1) = mat%kn
    end if
    p%k(1, 2) = -mat%kn * pos_n * gd(2)
    p%k(2, 1) = p%dmg * dtau(1) + (p%tauf - mat%kt * sl(2)) * gd(1)
    p%k(2, 2) = (1.0_dp - p%dmg) * mat%kt + p%dmg * dtau(2) + (p%tauf - mat%kt * sl(2)) * gd(2)

    ! Frictional work and energies (interlock_schemes).
    p%wfric = p%dmg * abs(p%tauf) * slip
    if (scheme == scheme_implicit) then
      p%zeta = zeta_o + p%wfric
    else
      p%zeta = zeta_o + dmg_o * abs(tauf_o) * slip
    end if
    p%psi = 0.5_dp * ((1.0_dp - p%dmg) * (mat%kn * sl(1)**2 + mat%kt * sl(2)**2) + &
                      p%dmg * (mat%kn * neg_n**2 + p%tauf**2 / mat%kt))
    p%wdmg = 0.0_dp
    if (p%dmg > dmg_o) p%wdmg = damage_dissipation_increment(mat%eta, mat%beta_break, &
        mat%kn * mat%s0n**2, beta_o, p%beta) - 0.5_dp * p%tauf**2 / mat%kt * (p%dmg - dmg_o)
  end subroutine plane_law

end module interlock_kernels
