!> Damage (decohesion) of a microplane (eq. 9-11 with erratum E2): the history variable beta is
!> the largest equivalent relative displacement reached, and D = (beta - 1)/(eta beta).
module interlock_damage
  use interlock_kinds, only: dp
  implicit none
  private
  public :: equivalent_displacement, damage_of_beta, damage_growth, damage_may_grow

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

  !> One increment of the law in the fused kernels' form (scalars only, divisions only while
  !> damage grows): an = <s_n>_+ / s_0n and at = s_t / s_0t (inv_s0n = 1/s_0n, inv_s0t =
  !> 1/s_0t) give beta_eq = sqrt(an^2 + at^2); beta = max(beta_old, beta_eq), D = (beta -
  !> 1)/(eta beta) (1 from beta_break = 1/(1 - eta) on, as damage_of_beta, to the bit: the
  !> stored damage may come from either path, and D must never decrease by a rounding), and
  !> (gd_n, gd_t) = dD/d(s_n, s_t) = (an / s_0n, at / s_0t) / (eta beta^3) while D grows below
  !> 1, else 0. Unchanged (beta_old, d_old, 0) when beta_eq does not exceed beta_old.
  elemental subroutine damage_growth(an, at, beta_old, d_old, eta, inv_eta, beta_break, &
                                     inv_s0n, inv_s0t, beta, d, gd_n, gd_t)
    real(dp), intent(in) :: an, at, beta_old, d_old, eta, inv_eta, beta_break, inv_s0n, inv_s0t
    real(dp), intent(out) :: beta, d, gd_n, gd_t
    real(dp) :: beq2, beq, rb, ddb
    beta = beta_old
    d = d_old
    gd_n = 0.0_dp
    gd_t = 0.0_dp
    ! The square root only where damage may grow: sqrt(x) <= b for every x <= fl(b^2) (b >= 0,
    ! round to nearest), so the test on the squares skips no growth the test on beta_eq makes,
    ! and the test on beta_eq itself decides.
    beq2 = an * an + at * at
    if (.not. beq2 > beta_old * beta_old) return
    beq = sqrt(beq2)
    if (beq > beta_old) then
      beta = beq
      if (beq >= beta_break) then
        d = 1.0_dp
      else if (beq > 1.0_dp) then
        d = (beq - 1.0_dp) / (eta * beq)
        rb = 1.0_dp / beq
        ddb = inv_eta * rb * rb * rb
        gd_n = ddb * an * inv_s0n
        gd_t = ddb * at * inv_s0t
      else
        d = 0.0_dp
      end if
    end if
  end subroutine damage_growth

  !> Damage may grow: beta_eq^2 = an^2 + at^2, with at^2 given, exceeds beta_old^2 less a
  !> relative 1e-12. A caller whose at is a norm (|s_kt| / s_0t of a tangential vector) takes its
  !> square root and damage_growth only where this holds: where it does not, beta_eq^2 computed
  !> from the rounded norm (a few ulps from at^2) does not exceed beta_old^2 either, and
  !> damage_growth would return the state unchanged.
  elemental logical function damage_may_grow(an, at_squared, beta_old)
    real(dp), intent(in) :: an, at_squared, beta_old
    real(dp), parameter :: margin = 1.0_dp - 1.0e-12_dp
    damage_may_grow = an * an + at_squared > margin * (beta_old * beta_old)
  end function damage_may_grow

  !> D(beta) = (beta - 1)/(eta beta) clipped to [0, 1], and dD/dbeta (0 outside (1, 1/(1-eta))).
  !> D = 1 exactly from beta_break = 1/(1 - eta) on, so that a state set to full damage (a
  !> separation, a pre-fractured start) never rounds back below 1.
  pure subroutine damage_of_beta(eta, beta_break, beta, d, dd_dbeta)
    real(dp), intent(in) :: eta, beta_break, beta
    real(dp), intent(out) :: d, dd_dbeta
    if (beta <= 1.0_dp) then
      d = 0.0_dp
      dd_dbeta = 0.0_dp
    else if (beta >= beta_break) then
      d = 1.0_dp
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
