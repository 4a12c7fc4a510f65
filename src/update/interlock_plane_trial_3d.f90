!> A plane's trial at a relative displacement, for the 3D one-step kernels
!> (interlock_kernel_planes_3d.inc: plane_trial): its local separation, the round-off of its
!> normal component and its trial friction traction with the norm.
module interlock_plane_trial_3d
  use interlock_kinds, only: dp
  implicit none
  private
  public :: plane_trial_t, trial_bound

  !> A trial friction traction whose components reach this is left to the general path (its
  !> norm is scaled there against overflow of the squares)
  real(dp), parameter :: trial_bound = 1.0e150_dp

  !> A plane's trial at s (no default values: a local array of them is not set on each call).
  type :: plane_trial_t
    !> s_N and the dip component d . s of the in-plane separation: the pair that the plane's
    !> angle turns (plane_trial_at_angle) [mm]
    real(dp) :: normal_dip(2)
    !> the local separation (m . s, e . s, q . s) [mm]
    real(dp) :: sl(3)
    !> the round-off of s_kn: up to it the plane is closed for every derivative (SPEC D13)
    real(dp) :: tie
    !> the trial friction traction K_t (s_kt - sf_o) [MPa] and its norm (huge where a
    !> component reaches trial_bound: its square would overflow)
    real(dp) :: tr(2), trn
  end type plane_trial_t

end module interlock_plane_trial_3d
