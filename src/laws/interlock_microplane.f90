!> The cohesive-frictional law of one microplane (Alfano-Sacco, eq. 6): damage and friction
!> combined into the local traction, with exact derivatives with respect to the local
!> variables v = (s_kn, s_kt, beta_old, sf_old).
module interlock_microplane
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t
  use interlock_damage, only: equivalent_displacement, damage_of_beta
  use interlock_friction, only: friction_return
  implicit none
  private
  public :: local_t, microplane_update

  !> Values at the end of the step and their gradients wrt v = (s_kn, s_kt, beta_old, sf_old).
  type :: local_t
    real(dp) :: beta, gbeta(4)
    real(dp) :: dmg, gdmg(4)
    real(dp) :: sf, gsf(4)
    real(dp) :: tauf, gtauf(4)
    real(dp) :: sig(2), gsig(2, 4)   !< local traction (sigma_kn, sigma_kt)
    real(dp) :: slip, gslip(4)       !< |sf - sf_old|
    real(dp) :: wdrv, gwdrv(4)       !< D |tau_f| |sf - sf_old|: frictional work on the damaged part
    integer  :: branch               !< friction branch (interlock_friction)
  end type local_t

contains

  pure subroutine microplane_update(mat, sl, beta_old, sf_old, dmg_frozen, r)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sl(2), beta_old, sf_old, dmg_frozen
    type(local_t), intent(out) :: r
    real(dp) :: beq, dbeq(2), dd_dbeta, dsf(3), dtauf(3), dslip(3), pos_n, neg_n, atau, sgt

    ! Damage (SPEC 4.3).
    r%beta = beta_old
    r%gbeta = [0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp]
    if (mat%use_damage) then
      call equivalent_displacement(sl, mat%s0n, mat%s0t, beq, dbeq)
      if (beq > beta_old) then
        r%beta = beq
        r%gbeta = [dbeq(1), dbeq(2), 0.0_dp, 0.0_dp]
      end if
      call damage_of_beta(mat%eta, mat%beta_break, r%beta, r%dmg, dd_dbeta)
      r%gdmg = dd_dbeta * r%gbeta
    else
      r%dmg = dmg_frozen
      r%gdmg = 0.0_dp
    end if

    ! Friction on the damaged part (SPEC 4.4).
    call friction_return(mat%kn, mat%kt, mat%mu_eff, sl, sf_old, r%sf, r%tauf, dsf, dtauf, &
                         r%slip, dslip, r%branch)
    r%gsf = [dsf(1), dsf(2), 0.0_dp, dsf(3)]
    r%gtauf = [dtauf(1), dtauf(2), 0.0_dp, dtauf(3)]
    r%gslip = [dslip(1), dslip(2), 0.0_dp, dslip(3)]

    ! Local traction (SPEC 4.5): sigma_kn = K_n s_kn - D K_n <s_kn>_+.
    pos_n = max(0.0_dp, sl(1))
    neg_n = min(0.0_dp, sl(1))
    r%sig(1) = mat%kn * neg_n + (1.0_dp - r%dmg) * mat%kn * pos_n
    r%sig(2) = (1.0_dp - r%dmg) * mat%kt * sl(2) + r%dmg * r%tauf
    r%gsig(1, :) = -mat%kn * pos_n * r%gdmg
    if (sl(1) > 0.0_dp) then
      r%gsig(1, 1) = r%gsig(1, 1) + (1.0_dp - r%dmg) * mat%kn
    else
      r%gsig(1, 1) = r%gsig(1, 1) + mat%kn
    end if
    r%gsig(2, :) = r%dmg * r%gtauf + (r%tauf - mat%kt * sl(2)) * r%gdmg
    r%gsig(2, 2) = r%gsig(2, 2) + (1.0_dp - r%dmg) * mat%kt

    ! Frictional work on the damaged part (decision D4): the implicit wear driver.
    atau = abs(r%tauf)
    sgt = sign(1.0_dp, r%tauf)
    r%wdrv = r%dmg * atau * r%slip
    r%gwdrv = atau * r%slip * r%gdmg + r%dmg * r%slip * sgt * r%gtauf + r%dmg * atau * r%gslip
  end subroutine microplane_update

end module interlock_microplane
