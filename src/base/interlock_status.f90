!> Status codes and the per-update report. The library never stops the host program:
!> every failure comes back here, as a code and a message.
module interlock_status
  use interlock_kinds, only: dp
  implicit none
  private
  public :: interlock_info_t
  public :: status_ok, status_bad_input, status_local_failure, message_len

  integer, parameter :: status_ok = 0            !< the update succeeded
  integer, parameter :: status_bad_input = 1     !< inadmissible parameters or arguments (fatal)
  integer, parameter :: status_local_failure = 2 !< the local integration failed: retry with a smaller step
  integer, parameter :: message_len = 512

  !> What one update reports besides its results. `message` is defined only when `status` /=
  !> status_ok (it says why): it has no default value, so that a caller's fresh report (the
  !> UMAT declares one on every call) does not pay for clearing a long string it never reads.
  type :: interlock_info_t
    integer :: status = status_ok
    character(len=message_len) :: message
    integer :: newton_iterations = 0   !< largest iteration count of one plane's wear solve
    integer :: substeps = 1            !< sub-increments accepted
    integer :: attempts = 0            !< sub-increments tried (accepted and rejected)
    real(dp) :: max_damage_increment = 0.0_dp  !< max over planes of D_new - D_old
    real(dp) :: max_angle_increment = 0.0_dp   !< max over planes of |theta_new - theta_old| [rad]
  end type interlock_info_t

end module interlock_status
