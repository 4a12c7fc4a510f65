!> Coulomb friction on the damaged part of a microplane (eq. 7 with erratum E1): an elastic
!> predictor on the friction traction and a return to |tau_f| = mu p, p the contact pressure.
module interlock_friction
  use interlock_kinds, only: dp
  implicit none
  private
  public :: friction_step

contains

  !> The return mapping (scalars only, the material's inverse 1/K_t): mu_p = mu K_n <-s_n>_- is the bound (0 on an open plane or with friction
  !> off: the damaged part follows freely), mu_kn = mu K_n its derivative wrt -s_n, st the
  !> tangential separation, sf_old the slip at the start. `closed`: the plane is in contact
  !> for the derivatives (s_n <= 0 with friction on): at s_n = 0 exactly, where mu_p = 0, the
  !> derivatives are the closed side's (SPEC D13). Returns the slip sf, the friction traction
  !> tauf and its derivatives wrt (s_n, s_t), the slip increment |d sf| and its sign (0 while
  !> sticking or without slip; d|d sf|/d s_t).
  elemental subroutine friction_step(mu_p, mu_kn, closed, kt, inv_kt, st, sf_old, sf, tauf, &
                                     dtauf_dsn, dtauf_dst, slip, slip_sign)
    real(dp), intent(in) :: mu_p, mu_kn, kt, inv_kt, st, sf_old
    logical, intent(in) :: closed
    real(dp), intent(out) :: sf, tauf, dtauf_dsn, dtauf_dst, slip, slip_sign
    real(dp) :: tau_trial
    if (mu_p > 0.0_dp) then
      tau_trial = kt * (st - sf_old)
      if (abs(tau_trial) <= mu_p) then
        sf = sf_old
        tauf = tau_trial
        dtauf_dsn = 0.0_dp
        dtauf_dst = kt
        slip = 0.0_dp
        slip_sign = 0.0_dp
      else
        tauf = sign(mu_p, tau_trial)
        sf = st - tauf * inv_kt
        dtauf_dsn = -sign(mu_kn, tau_trial)
        dtauf_dst = 0.0_dp
        slip = (abs(tau_trial) - mu_p) * inv_kt
        slip_sign = sign(1.0_dp, tau_trial)
      end if
    else
      sf = st
      tauf = 0.0_dp
      dtauf_dsn = 0.0_dp
      dtauf_dst = 0.0_dp
      slip = abs(sf - sf_old)
      slip_sign = 0.0_dp
      if (slip > 0.0_dp) then
        slip_sign = sign(1.0_dp, sf - sf_old)
        ! s_n = 0 exactly: the slide with mu p = 0 for the derivatives (the values are the
        ! same on both sides); at the cone's apex (no slip) a kink where they stay 0.
        if (closed) dtauf_dsn = -slip_sign * mu_kn
      end if
    end if
  end subroutine friction_step

end module interlock_friction
