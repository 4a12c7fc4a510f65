!> Unit tests of interlock_geometry (eq. 17-18, erratum E3) against hand-computed values.
module test_geometry
  use interlock_kinds, only: dp
  use interlock_geometry, only: contact_area
  use interlock_assert, only: assert_equal
  implicit none
  private
  public :: geometry_contact_area

contains

  subroutine geometry_contact_area()
    real(dp) :: a, da
    ! H_N = 0.5 mm (1/H_N = 2)
    call contact_area(-0.1_dp, 2.0_dp, a, da)
    call assert_equal([1.0_dp, 0.0_dp], [a, da], 0.0_dp, 'closed: A_g = 1')
    call contact_area(0.1_dp, 2.0_dp, a, da)
    call assert_equal([0.8_dp, -2.0_dp], [a, da], 1.0e-15_dp, 'opening: A_g = 1 - s_N/H_N, slope -1/H_N')
    call contact_area(0.5_dp, 2.0_dp, a, da)
    call assert_equal([0.0_dp, 0.0_dp], [a, da], 0.0_dp, 's_N = H_N: separated (one-sided 0)')
    call contact_area(0.7_dp, 2.0_dp, a, da)
    call assert_equal([0.0_dp, 0.0_dp], [a, da], 0.0_dp, 's_N > H_N: separated')
    call contact_area(0.0_dp, 2.0_dp, a, da)
    call assert_equal([1.0_dp, 0.0_dp], [a, da], 0.0_dp, 's_N = 0: closed side (one-sided 0)')
    ! infinite depth (1/H_N = 0)
    call contact_area(100.0_dp, 0.0_dp, a, da)
    call assert_equal([1.0_dp, 0.0_dp], [a, da], 0.0_dp, 'infinite depth: A_g = 1')
  end subroutine geometry_contact_area

end module test_geometry
