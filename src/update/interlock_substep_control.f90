!> The control of substepping (SPEC section 5) of the general path (interlock_general_path),
!> 2D and 3D, and the update's report of its largest increments: sizes are powers of 2 of the
!> increment (the partition does not vary with s except where a decision switches, so the
!> chained tangent is the exact derivative of what is computed); with error control a trial
!> sub-increment is kept when its embedded estimate is within the tolerance, or when it is
!> already the smallest allowed (at a kink the estimate does not shrink with the size), and
!> the next size follows from the estimate's scaling (h^2); without it (a failed one-step
!> solve) the size is quartered on failure and doubled on success.
module interlock_substep_control
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t
  use interlock_state, only: interlock_state_t
  use interlock_status, only: interlock_info_t, status_local_failure, message_len
  implicit none
  private
  public :: smallest_fraction, next_sub_increment, count_attempt, after_failure, keep_trial, &
            next_size, size_after_whole, stiffness_scale, check_chain, largest_increments

  !> A sub-increment ending this close to the end of the increment ends there.
  real(dp), parameter :: smallest_fraction = 1.0e-12_dp
  !> Error control accepts a sub-increment of this fraction of the increment whatever its
  !> estimate (2^-12: at most ~4096 sub-increments to pass a kink).
  real(dp), parameter :: smallest_controlled_fraction = 2.0_dp**(-12)

contains

  !> The next trial sub-increment from the fraction alpha reached, of size h (clipped to the
  !> end): its end fraction a_end, 1 exactly for the last one.
  pure subroutine next_sub_increment(alpha, h, a_end)
    real(dp), intent(in) :: alpha
    real(dp), intent(inout) :: h
    real(dp), intent(out) :: a_end
    h = min(h, 1.0_dp - alpha)
    a_end = alpha + h
    if (a_end >= 1.0_dp - smallest_fraction) then
      a_end = 1.0_dp
      h = 1.0_dp - alpha
    end if
  end subroutine next_sub_increment

  !> Count one more trial; `allowed` false (and the report set) beyond the solver's bound.
  pure subroutine count_attempt(info, max_substeps, allowed)
    type(interlock_info_t), intent(inout) :: info
    integer, intent(in) :: max_substeps
    logical, intent(out) :: allowed
    info%attempts = info%attempts + 1
    allowed = info%attempts <= max_substeps
    if (.not. allowed) then
      info%status = status_local_failure
      write (info%message, '(a,i0,a)') 'substepping needed more than ', max_substeps, &
        ' sub-increments: retry with a smaller increment'
    end if
  end subroutine count_attempt

  !> A trial that was not solved or whose chained derivative is unbounded: a quarter of the
  !> size; `give_up` (and the report set) when that is below the smallest fraction.
  pure subroutine after_failure(solved, h, info, give_up)
    logical, intent(in) :: solved
    real(dp), intent(inout) :: h
    type(interlock_info_t), intent(inout) :: info
    logical, intent(out) :: give_up
    h = 0.25_dp * h
    give_up = h < smallest_fraction
    if (.not. give_up) return
    info%status = status_local_failure
    if (.not. solved) then
      info%message = 'the local wear equation has no solution on any sub-increment: ' // &
                     'retry with a smaller increment'
    else
      info%message = unstable_message()
    end if
  end subroutine after_failure

  !> The trial of size h with estimate err is kept (tol: the tolerance; `control` false:
  !> sizes driven by failures only).
  pure logical function keep_trial(control, err, tol, h)
    logical, intent(in) :: control
    real(dp), intent(in) :: err, tol, h
    keep_trial = .not. control .or. err <= tol .or. h <= smallest_controlled_fraction
  end function keep_trial

  !> The size after a trial, kept or not, rounded down to a power of 2.
  pure subroutine next_size(kept, control, err, tol, h)
    logical, intent(in) :: kept, control
    real(dp), intent(in) :: err, tol
    real(dp), intent(inout) :: h
    if (kept) then
      if (control) then
        h = h * min(4.0_dp, max(1.0_dp, 0.9_dp * sqrt(tol / max(err, tiny(1.0_dp)))))
      else
        h = 2.0_dp * h
      end if
    else
      h = h * rejection_factor(err, tol)
    end if
    h = power_of_2_below(h)
    ! Error control takes no size below the smallest it accepts whatever the estimate (below
    ! it, kept trials whose estimate stays above the tolerance would never grow back)
    if (control) h = max(h, smallest_controlled_fraction)
  end subroutine next_size

  !> The size of the next trial after the whole increment was tried as one step with the
  !> estimate err > tol (next_size of a trial of size 1 not kept).
  pure real(dp) function size_after_whole(err, tol) result(h)
    real(dp), intent(in) :: err, tol
    h = power_of_2_below(rejection_factor(err, tol))
  end function size_after_whole

  !> The factor on the size of a trial whose estimate err exceeds tol: the h^2 scaling's with a
  !> margin of 0.9, at least 0.1.
  pure real(dp) function rejection_factor(err, tol)
    real(dp), intent(in) :: err, tol
    rejection_factor = max(0.1_dp, 0.9_dp * sqrt(tol / err))
  end function rejection_factor

  !> The power of 2 at most h (h > 0 and normal; h itself where it is one): h with its
  !> significand's fraction bits cleared (scale(1.0_dp, exponent(h) - 1) without libm's frexp
  !> and ldexp).
  elemental real(dp) function power_of_2_below(h)
    real(dp), intent(in) :: h
    integer(int64), parameter :: fraction_bits = 2_int64**52 - 1_int64
    power_of_2_below = transfer(iand(transfer(h, 0_int64), not(fraction_bits)), 1.0_dp)
  end function power_of_2_below

  !> The largest stiffness the law can show (penalty, or traction over the asperity depth).
  pure real(dp) function stiffness_scale(mat)
    type(interlock_material_t), intent(in) :: mat
    stiffness_scale = max(mat%kn, mat%kt) + max(mat%sigma0_n, mat%sigma0_t) * mat%inv_h_n
  end function stiffness_scale

  !> The largest tangent entry met along the chain stays within 1e6 times the law's largest
  !> stiffness; else the chain through the sub-increments amplifies (and a product of such
  !> factors that cancels down to a normal tangent has lost its accuracy to round-off): `stable`
  !> false, and the report set.
  pure subroutine check_chain(mat, chain_peak, info, stable)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: chain_peak
    type(interlock_info_t), intent(inout) :: info
    logical, intent(out) :: stable
    stable = .not. chain_peak > 1.0e6_dp * stiffness_scale(mat)
    if (.not. stable) then
      info%status = status_local_failure
      info%message = unstable_message()
    end if
  end subroutine check_chain

  !> (a fixed length: see interlock_numbers:format_real)
  pure function unstable_message() result(message)
    character(len=message_len) :: message
    message = 'the update is unstable on small sub-increments (its derivative grows without ' // &
              'bound): use the implicit scheme or a smaller increment'
  end function unstable_message

  !> The largest damage and angle increments over the n planes of an update (its info report,
  !> which a host's increment control reads). Here, among the update's controls compiled as the
  !> UMAT's path (src/CMakeLists.txt), so that it is inlined into the update's front.
  pure subroutine largest_increments(n, old, new, info)
    integer, intent(in) :: n
    type(interlock_state_t), intent(in) :: old, new
    type(interlock_info_t), intent(inout) :: info
    integer :: k
    info%max_damage_increment = new%damage(1) - old%damage(1)
    info%max_angle_increment = abs(new%theta(1) - old%theta(1))
    do k = 2, n
      info%max_damage_increment = max(info%max_damage_increment, new%damage(k) - old%damage(k))
      info%max_angle_increment = max(info%max_angle_increment, abs(new%theta(k) - old%theta(k)))
    end do
  end subroutine largest_increments

end module interlock_substep_control
