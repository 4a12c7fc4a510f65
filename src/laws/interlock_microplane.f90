!> The general path's derivatives of one microplane's law (interlock_plane_law, eq. 6) with
!> respect to the local variables v = (s_kn, s_kt, beta_old, sf_old): the columns of the
!> separation are the law's 2x2 tangent and partials, the columns of the start state are added
!> here. Substepping chains them over sub-increments (interlock_schemes, interlock_ria).
module interlock_microplane
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t
  use interlock_damage, only: equivalent_displacement, damage_of_beta
  use interlock_plane_law, only: plane_response_t, wear_driver
  implicit none
  private
  public :: local_t, microplane_gradients

  !> Gradients wrt v = (s_kn, s_kt, beta_old, sf_old) of the plane's end state, its local
  !> traction and its frictional work D |tau_f| |sf - sf_old|.
  type :: local_t
    real(dp) :: gbeta(4), gdmg(4), gsf(4), gtauf(4), gslip(4), gwfric(4)
    real(dp) :: gsig(2, 4)
  end type local_t

contains

  !> The gradients of the law's response p at the local separation sl from the start
  !> history variable beta_o.
  pure subroutine microplane_gradients(mat, sl, beta_o, p, r)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sl(2), beta_o
    type(plane_response_t), intent(in) :: p
    type(local_t), intent(out) :: r
    real(dp) :: beq, dbeq(2), d_tmp, dd_dbeta, gw_n, gw_t, drv

    ! Damage (SPEC 4.3): where beta grew it is beta_eq(s_k), else beta_old, and D = D(beta).
    r%gbeta = [0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp]
    r%gdmg = 0.0_dp
    if (mat%use_damage) then
      if (p%beta > beta_o) then
        call equivalent_displacement(sl, mat%s0n, mat%s0t, beq, dbeq)
        r%gbeta = [dbeq(1), dbeq(2), 0.0_dp, 0.0_dp]
        r%gdmg(1:2) = [p%gd_n, p%gd_t]
      else
        call damage_of_beta(mat%eta, mat%beta_break, beta_o, d_tmp, dd_dbeta)
        r%gdmg(3) = dd_dbeta
      end if
    end if

    ! Friction (SPEC 4.4): sticking, sf = sf_old and tau_f = K_t (s_kt - sf_old); sliding,
    ! sf = s_kt - tau_f / K_t; free (no contact or no friction), sf = s_kt.
    if (p%dtauf_t > 0.0_dp) then
      r%gsf = [0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp]
    else
      r%gsf = [-p%dtauf_n * mat%inv_kt, 1.0_dp, 0.0_dp, 0.0_dp]
    end if
    r%gtauf = [p%dtauf_n, p%dtauf_t, 0.0_dp, -p%dtauf_t]
    r%gslip = [abs(p%dtauf_n) * mat%inv_kt, p%dslip_t, 0.0_dp, -p%dslip_t]

    ! The traction (eq. 6): D and tau_f carry the start state's columns.
    r%gsig(1, :) = [p%k_nn, p%k_nt, -mat%kn * max(0.0_dp, sl(1)) * r%gdmg(3), 0.0_dp]
    r%gsig(2, :) = [p%k_tn, p%k_tt, (p%tauf - mat%kt * sl(2)) * r%gdmg(3), p%dmg * r%gtauf(4)]

    ! The frictional work on the damaged part (decision D4), the wear driver.
    call wear_driver(mat, p, 1.0_dp, 0.0_dp, drv, gw_n, gw_t)
    r%gwfric = [gw_n, gw_t, abs(p%tauf) * p%slip * r%gdmg(3), &
                p%dmg * p%slip * sign(1.0_dp, p%tauf) * r%gtauf(4) + &
                p%dmg * abs(p%tauf) * r%gslip(4)]
  end subroutine microplane_gradients

end module interlock_microplane
