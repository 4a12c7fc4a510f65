!> Unit tests of interlock_wear (eq. 22) against hand-computed values.
module test_wear
  use interlock_kinds, only: dp
  use interlock_wear, only: worn_angle, worn_angle_slope
  use interlock_assert, only: assert_equal
  implicit none
  private
  public :: wear_law

contains

  subroutine wear_law()
    real(dp) :: th, dth
    real(dp), parameter :: e1 = 0.36787944117144233_dp   ! exp(-1)
    ! theta_0 = 0.5, theta_f = 0.1, zeta_0 = 2, zeta = 2: 0.4 e^-1 + 0.1, slope -0.4/2 e^-1
    call worn_angle(0.5_dp, 0.1_dp, 0.5_dp, 2.0_dp, th, dth)
    call assert_equal([0.4_dp * e1 + 0.1_dp, -0.2_dp * e1], [th, dth], 1.0e-16_dp, 'theta(zeta_0)')
    call assert_equal(dth, worn_angle_slope(0.1_dp, 0.5_dp, th), 1.0e-16_dp, 'slope from the angle')
    ! negative planes wear towards their (negative) theta_f
    call worn_angle(-0.5_dp, -0.1_dp, 0.5_dp, 2.0_dp, th, dth)
    call assert_equal([-0.4_dp * e1 - 0.1_dp, 0.2_dp * e1], [th, dth], 1.0e-16_dp, 'negative plane')
    ! fresh and fully worn
    call worn_angle(0.5_dp, 0.1_dp, 0.5_dp, 0.0_dp, th, dth)
    call assert_equal([0.5_dp, -0.2_dp], [th, dth], 0.0_dp, 'theta(0) = theta_0')
    call worn_angle(0.5_dp, 0.1_dp, 0.5_dp, 2000.0_dp, th, dth)
    call assert_equal([0.1_dp, 0.0_dp], [th, dth], 1.0e-300_dp, 'theta(huge zeta) = theta_f')
    ! no wear (1/zeta_0 = 0)
    call worn_angle(0.5_dp, 0.1_dp, 0.0_dp, 7.0_dp, th, dth)
    call assert_equal([0.5_dp, 0.0_dp], [th, dth], 0.0_dp, 'no wear with 1/zeta_0 = 0')
  end subroutine wear_law

end module test_wear
