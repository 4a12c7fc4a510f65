!> Unit tests of interlock_friction (eq. 7, erratum E1) against hand-computed values:
!> K_n = 150, K_t = 100, mu = 0.5.
module test_friction
  use interlock_kinds, only: dp
  use interlock_friction, only: friction_return, friction_free, friction_stick, friction_slide
  use interlock_assert, only: assert_equal
  implicit none
  private
  public :: friction_open_and_frictionless, friction_stick_branch, friction_slide_branch

  real(dp), parameter :: kn = 150.0_dp, kt = 100.0_dp, mu = 0.5_dp, tol = 1.0e-13_dp

contains

  subroutine friction_open_and_frictionless()
    real(dp) :: sf, tauf, dsf(3), dtauf(3), slip, dslip(3)
    integer :: branch
    ! open plane: the damaged part follows freely
    call friction_return(kn, kt, mu, [0.01_dp, 0.02_dp], 0.005_dp, sf, tauf, dsf, dtauf, slip, &
                         dslip, branch)
    call assert_equal(friction_free, branch, 'open plane: free branch')
    call assert_equal([0.02_dp, 0.0_dp, 0.015_dp], [sf, tauf, slip], tol, 'open plane: sf, tauf, slip')
    call assert_equal([0.0_dp, 1.0_dp, 0.0_dp], dsf, 0.0_dp, 'open plane: dsf')
    call assert_equal([0.0_dp, 0.0_dp, 0.0_dp], dtauf, 0.0_dp, 'open plane: dtauf')
    call assert_equal([0.0_dp, 1.0_dp, -1.0_dp], dslip, 0.0_dp, 'open plane: dslip')
    ! mu = 0 in compression: no shear either
    call friction_return(kn, kt, 0.0_dp, [-0.01_dp, -0.02_dp], 0.005_dp, sf, tauf, dsf, dtauf, &
                         slip, dslip, branch)
    call assert_equal(friction_free, branch, 'mu = 0: free branch')
    call assert_equal([-0.02_dp, 0.0_dp, 0.025_dp], [sf, tauf, slip], tol, 'mu = 0: sf, tauf, slip')
    call assert_equal([0.0_dp, -1.0_dp, 1.0_dp], dslip, 0.0_dp, 'mu = 0: dslip (negative slip)')
    ! open plane without slip: zero gradient of |sf - sf_old| (not a kink, SPEC section 6)
    call friction_return(kn, kt, mu, [0.01_dp, 0.005_dp], 0.005_dp, sf, tauf, dsf, dtauf, slip, &
                         dslip, branch)
    call assert_equal([0.0_dp, 0.0_dp, 0.0_dp], dslip, 0.0_dp, 'open plane, no slip: dslip = 0')
  end subroutine friction_open_and_frictionless

  subroutine friction_stick_branch()
    real(dp) :: sf, tauf, dsf(3), dtauf(3), slip, dslip(3)
    integer :: branch
    ! mu p = 0.5 * 150 * 0.02 = 1.5; trial 100 * (0.01 - 0.005) = 0.5: stick
    call friction_return(kn, kt, mu, [-0.02_dp, 0.01_dp], 0.005_dp, sf, tauf, dsf, dtauf, slip, &
                         dslip, branch)
    call assert_equal(friction_stick, branch, 'stick branch')
    call assert_equal([0.005_dp, 0.5_dp, 0.0_dp], [sf, tauf, slip], tol, 'stick: sf, tauf, slip')
    call assert_equal([0.0_dp, 0.0_dp, 1.0_dp], dsf, 0.0_dp, 'stick: dsf')
    call assert_equal([0.0_dp, 100.0_dp, -100.0_dp], dtauf, 0.0_dp, 'stick: dtauf')
    call assert_equal([0.0_dp, 0.0_dp, 0.0_dp], dslip, 0.0_dp, 'stick: dslip')
  end subroutine friction_stick_branch

  subroutine friction_slide_branch()
    real(dp) :: sf, tauf, dsf(3), dtauf(3), slip, dslip(3)
    integer :: branch
    ! trial 100 * (0.04 - 0.005) = 3.5 > 1.5: slide, sf = 0.04 - 1.5/100, slip = 2/100
    call friction_return(kn, kt, mu, [-0.02_dp, 0.04_dp], 0.005_dp, sf, tauf, dsf, dtauf, slip, &
                         dslip, branch)
    call assert_equal(friction_slide, branch, 'slide branch (+)')
    call assert_equal([0.025_dp, 1.5_dp, 0.02_dp], [sf, tauf, slip], tol, 'slide (+): sf, tauf, slip')
    call assert_equal([0.75_dp, 1.0_dp, 0.0_dp], dsf, tol, 'slide (+): dsf')
    call assert_equal([-75.0_dp, 0.0_dp, 0.0_dp], dtauf, tol, 'slide (+): dtauf')
    call assert_equal([0.75_dp, 1.0_dp, -1.0_dp], dslip, tol, 'slide (+): dslip')
    ! trial -4 < -1.5: slide backwards
    call friction_return(kn, kt, mu, [-0.02_dp, -0.04_dp], 0.0_dp, sf, tauf, dsf, dtauf, slip, &
                         dslip, branch)
    call assert_equal(friction_slide, branch, 'slide branch (-)')
    call assert_equal([-0.025_dp, -1.5_dp, 0.025_dp], [sf, tauf, slip], tol, 'slide (-): sf, tauf, slip')
    call assert_equal([-0.75_dp, 1.0_dp, 0.0_dp], dsf, tol, 'slide (-): dsf')
    call assert_equal([75.0_dp, 0.0_dp, 0.0_dp], dtauf, tol, 'slide (-): dtauf')
    call assert_equal([0.75_dp, -1.0_dp, 1.0_dp], dslip, tol, 'slide (-): dslip')
  end subroutine friction_slide_branch

end module test_friction
