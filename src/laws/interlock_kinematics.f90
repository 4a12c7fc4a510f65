!> Microplane kinematics (eq. 5, 29): the macro relative displacement resolved on a plane
!> inclined by theta, and the plane's traction rotated back to the macro frame.
module interlock_kinematics
  use interlock_kinds, only: dp
  implicit none
  private
  public :: to_local, to_global, dlocal_dtheta

contains

  !> (s_kn, s_kt) = R(theta) (s_N, s_T), with c = cos(theta), sn = sin(theta).
  pure subroutine to_local(c, sn, s, sl)
    real(dp), intent(in) :: c, sn, s(2)
    real(dp), intent(out) :: sl(2)
    sl(1) = c * s(1) + sn * s(2)
    sl(2) = -sn * s(1) + c * s(2)
  end subroutine to_local

  !> sigma = R(theta)^T sigma_loc.
  pure subroutine to_global(c, sn, sl, sg)
    real(dp), intent(in) :: c, sn, sl(2)
    real(dp), intent(out) :: sg(2)
    sg(1) = c * sl(1) - sn * sl(2)
    sg(2) = sn * sl(1) + c * sl(2)
  end subroutine to_global

  !> d(s_kn, s_kt)/d theta at fixed macro s: (s_kt, -s_kn).
  pure function dlocal_dtheta(sl) result(d)
    real(dp), intent(in) :: sl(2)
    real(dp) :: d(2)
    d = [sl(2), -sl(1)]
  end function dlocal_dtheta

end module interlock_kinematics
