!> Finite asperity depth (eq. 17-18, erratum E3, decision D1): the contact area of every
!> microplane shrinks linearly with the opening, A_g = 1 - s_N/H_N on 0 < s_N < H_N.
module interlock_geometry
  use interlock_kinds, only: dp
  implicit none
  private
  public :: contact_area

contains

  !> A_g(s_N / H_N) and dA_g/ds_N (one-sided at the kinks: 0 at s_N = 0, 0 at s_N = H_N).
  pure subroutine contact_area(s_n, inv_h_n, area, darea_dsn)
    real(dp), intent(in) :: s_n, inv_h_n
    real(dp), intent(out) :: area, darea_dsn
    real(dp) :: x
    x = s_n * inv_h_n
    if (x <= 0.0_dp) then
      area = 1.0_dp
      darea_dsn = 0.0_dp
    else if (x < 1.0_dp) then
      area = 1.0_dp - x
      darea_dsn = -inv_h_n
    else
      area = 0.0_dp
      darea_dsn = 0.0_dp
    end if
  end subroutine contact_area

end module interlock_geometry
