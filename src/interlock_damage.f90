!> Damage (decohesion) of a microplane (eq. 9-11 with erratum E2): the history variable beta is
!> the largest equivalent relative displacement reached, and D = (beta - 1)/(eta beta).
module interlock_damage
  use interlock_kinds, only: dp
  implicit none
  private
  public :: equivalent_displacement, damage_of_beta

contains

  !> beta_eq = sqrt((<s_kn>_+ / s_0n)^2 + (s_kt / s_0t)^2) and its gradient wrt (s_kn, s_kt)
  !> (the gradient is only meaningful where beta_eq > 0).
  pure subroutine equivalent_displacement(sl, s0n, s0t, beq, dbeq)
    real(dp), intent(in) :: sl(2), s0n, s0t
    real(dp), intent(out) :: beq, dbeq(2)
    real(dp) :: an, at
    an = max(0.0_dp, sl(1)) / s0n
    at = sl(2) / s0t
    beq = sqrt(an * an + at * at)
    if (beq > 0.0_dp) then
      dbeq = [an / (s0n * beq), at / (s0t * beq)]
    else
      dbeq = 0.0_dp
    end if
  end subroutine equivalent_displacement

  !> D(beta) = (beta - 1)/(eta beta) clipped to [0, 1], and dD/dbeta (0 outside (1, 1/(1-eta))).
  pure subroutine damage_of_beta(eta, beta, d, dd_dbeta)
    real(dp), intent(in) :: eta, beta
    real(dp), intent(out) :: d, dd_dbeta
    if (beta <= 1.0_dp) then
      d = 0.0_dp
      dd_dbeta = 0.0_dp
    else
      d = (beta - 1.0_dp) / (eta * beta)
      if (d >= 1.0_dp) then
        d = 1.0_dp
        dd_dbeta = 0.0_dp
      else
        dd_dbeta = 1.0_dp / (eta * beta * beta)
      end if
    end if
  end subroutine damage_of_beta

end module interlock_damage
