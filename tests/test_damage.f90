!> Unit tests of interlock_damage (eq. 9-11, erratum E2) against hand-computed values.
module test_damage
  use interlock_kinds, only: dp
  use interlock_damage, only: equivalent_displacement, damage_of_beta
  use interlock_assert, only: assert_equal
  implicit none
  private
  public :: damage_equivalent_displacement, damage_law

contains

  subroutine damage_equivalent_displacement()
    real(dp) :: beq, dbeq(2)
    ! opening: (0.03/0.01, 0.04/0.02) = (3, 2): beta = sqrt(13), grad = (3, 2)/(s0 sqrt(13))
    call equivalent_displacement([0.03_dp, 0.04_dp], 0.01_dp, 0.02_dp, beq, dbeq)
    call assert_equal(3.605551275463989_dp, beq, 1.0e-15_dp, 'beta_eq in opening')
    call assert_equal([83.20502943378437_dp, 27.735009811261456_dp], dbeq, 1.0e-12_dp, &
                      'd beta_eq / d s_loc in opening')
    ! compression: only the shear counts
    call equivalent_displacement([-0.03_dp, 0.04_dp], 0.01_dp, 0.02_dp, beq, dbeq)
    call assert_equal(2.0_dp, beq, 1.0e-15_dp, 'beta_eq in compression')
    call assert_equal([0.0_dp, 50.0_dp], dbeq, 1.0e-13_dp, 'd beta_eq / d s_loc in compression')
    call equivalent_displacement([-0.03_dp, -0.04_dp], 0.01_dp, 0.02_dp, beq, dbeq)
    call assert_equal([0.0_dp, -50.0_dp], dbeq, 1.0e-13_dp, 'gradient for negative shear')
    ! zero: no NaN, zero gradient
    call equivalent_displacement([0.0_dp, 0.0_dp], 0.01_dp, 0.02_dp, beq, dbeq)
    call assert_equal(0.0_dp, beq, 0.0_dp, 'beta_eq at zero')
    call assert_equal([0.0_dp, 0.0_dp], dbeq, 0.0_dp, 'gradient at zero')
  end subroutine damage_equivalent_displacement

  subroutine damage_law()
    real(dp) :: d, dd
    call damage_of_beta(0.9_dp, 10.0_dp, 0.5_dp, d, dd)
    call assert_equal([0.0_dp, 0.0_dp], [d, dd], 0.0_dp, 'D(0.5) = 0 (elastic)')
    call damage_of_beta(0.9_dp, 10.0_dp, 1.0_dp, d, dd)
    call assert_equal([0.0_dp, 0.0_dp], [d, dd], 0.0_dp, 'D(1) = 0 (onset)')
    ! D = (beta - 1)/(eta beta) = 1/1.8, dD/dbeta = 1/(eta beta^2) = 1/3.6
    call damage_of_beta(0.9_dp, 10.0_dp, 2.0_dp, d, dd)
    call assert_equal([0.5555555555555556_dp, 0.2777777777777778_dp], [d, dd], 1.0e-15_dp, &
                      'D(2) and dD/dbeta with eta = 0.9')
    call damage_of_beta(0.5_dp, 2.0_dp, 1.5_dp, d, dd)
    call assert_equal([2.0_dp / 3.0_dp, 8.0_dp / 9.0_dp], [d, dd], 1.0e-15_dp, &
                      'D(1.5) and dD/dbeta with eta = 0.5')
    ! beyond 1/(1 - eta) = 10: fully damaged, flat
    call damage_of_beta(0.9_dp, 10.0_dp, 20.0_dp, d, dd)
    call assert_equal([1.0_dp, 0.0_dp], [d, dd], 0.0_dp, 'D(20) = 1 with eta = 0.9')
    ! exactly at beta_break D is exactly 1 (no round-off below it after a separation)
    call damage_of_beta(0.08356_dp, 1.0_dp / (1.0_dp - 0.08356_dp), 1.0_dp / (1.0_dp - 0.08356_dp), &
                        d, dd)
    call assert_equal([1.0_dp, 0.0_dp], [d, dd], 0.0_dp, 'D(1/(1 - eta)) = 1 exactly')
  end subroutine damage_law

end module test_damage
