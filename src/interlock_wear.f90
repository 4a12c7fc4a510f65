!> Asperity wear (eq. 22): the inclination decays exponentially with the frictional work,
!> theta(zeta) = (theta_0 - theta_f) exp(-zeta/zeta_0) + theta_f.
module interlock_wear
  use interlock_kinds, only: dp
  implicit none
  private
  public :: worn_angle, worn_angle_slope

contains

  !> theta(zeta) and d theta / d zeta for one plane (inv_zeta0 = 1/zeta_0).
  pure subroutine worn_angle(theta0, thetaf, inv_zeta0, zeta, theta, dtheta_dzeta)
    real(dp), intent(in) :: theta0, thetaf, inv_zeta0, zeta
    real(dp), intent(out) :: theta, dtheta_dzeta
    real(dp) :: e
    e = exp(-zeta * inv_zeta0)
    theta = (theta0 - thetaf) * e + thetaf
    dtheta_dzeta = -(theta0 - thetaf) * inv_zeta0 * e
  end subroutine worn_angle

  !> d theta / d zeta from the current angle, without an exponential: -(theta - theta_f)/zeta_0.
  pure real(dp) function worn_angle_slope(thetaf, inv_zeta0, theta)
    real(dp), intent(in) :: thetaf, inv_zeta0, theta
    worn_angle_slope = -(theta - thetaf) * inv_zeta0
  end function worn_angle_slope

end module interlock_wear
