!> Unit tests of interlock_kinematics (eq. 5, 29) against hand-computed values.
module test_kinematics
  use interlock_kinds, only: dp, deg_to_rad
  use interlock_kinematics, only: to_local, to_global, dlocal_dtheta
  use interlock_assert, only: assert_equal
  implicit none
  private
  public :: kinematics_rotation

contains

  subroutine kinematics_rotation()
    real(dp) :: c, sn, sl(2), sg(2)
    real(dp), parameter :: tol = 1.0e-15_dp
    c = cos(30.0_dp * deg_to_rad)
    sn = sin(30.0_dp * deg_to_rad)
    ! s = (1, 2) on a plane at +30 deg: (sqrt(3)/2 + 1, -1/2 + sqrt(3)).
    call to_local(c, sn, [1.0_dp, 2.0_dp], sl)
    call assert_equal([1.8660254037844386_dp, 1.2320508075688772_dp], sl, 4 * tol, 'to_local at 30 deg')
    ! at -30 deg: (sqrt(3)/2 - 1, 1/2 + sqrt(3))
    call to_local(c, -sn, [1.0_dp, 2.0_dp], sl)
    call assert_equal([-0.1339745962155614_dp, 2.2320508075688772_dp], sl, 4 * tol, 'to_local at -30 deg')
    ! the plane's normal traction (1, 0) points along (cos, sin) in the macro frame
    call to_global(c, sn, [1.0_dp, 0.0_dp], sg)
    call assert_equal([0.8660254037844386_dp, 0.5_dp], sg, tol, 'to_global of a unit normal traction')
    call to_global(c, sn, [0.0_dp, 1.0_dp], sg)
    call assert_equal([-0.5_dp, 0.8660254037844386_dp], sg, tol, 'to_global of a unit shear traction')
    ! R^T R = I
    call to_local(c, sn, [0.3_dp, -0.7_dp], sl)
    call to_global(c, sn, sl, sg)
    call assert_equal([0.3_dp, -0.7_dp], sg, tol, 'to_global inverts to_local')
    ! d(s_kn, s_kt)/d theta = (s_kt, -s_kn)
    call assert_equal([2.0_dp, -1.0_dp], dlocal_dtheta([1.0_dp, 2.0_dp]), 0.0_dp, 'dlocal_dtheta')
  end subroutine kinematics_rotation

end module test_kinematics
