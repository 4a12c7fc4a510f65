!> Asperity wear (eq. 22): the inclination decays exponentially with the frictional work,
!> theta(zeta) = (theta_0 - theta_f) exp(-zeta/zeta_0) + theta_f.
module interlock_wear
  use interlock_kinds, only: dp
  implicit none
  private
  public :: worn_angle, worn_angle_slope
  public :: wear_root_t, wear_root_begin, wear_root_update

  !> The backward-Euler wear equation of one plane, F(zeta) = zeta - zeta_o - g(theta(zeta)) = 0
  !> (g the frictional work in the step, >= 0), solved by reverse communication: the caller
  !> evaluates F and F' at `x` and calls wear_root_update until `done`. F(zeta_o) = -g0 <= 0;
  !> the root is bracketed from zeta_o upwards (Newton's steps from below where F' > 0, else
  !> doubling steps) and found by Newton's method safeguarded
  !> by bisection, so it cannot diverge. `ok` is false when a bound was reached.
  type :: wear_root_t
    real(dp) :: zeta_o = 0.0_dp, x = 0.0_dp, lo = 0.0_dp, hi = 0.0_dp, width = 0.0_dp
    real(dp) :: scale = 0.0_dp
    logical :: bracketed = .false., done = .false., ok = .true.
    !> done where the bracket closed on a jump of F (the residual not at round-off): F changes
    !> sign there without a zero, and the root stays at that point as the data move
    logical :: at_jump = .false.
    !> the first point was Newton's from zeta_o (F'(zeta_o) > 0)
    logical :: newton_start = .false.
    integer :: iterations = 0, expansions = 0
  end type wear_root_t

  integer, parameter :: max_expansions = 200

contains

  !> theta(zeta) and d theta / d zeta for one plane (inv_zeta0 = 1/zeta_0).
  pure subroutine worn_angle(theta0, thetaf, inv_zeta0, zeta, theta, dtheta_dzeta)
    real(dp), intent(in) :: theta0, thetaf, inv_zeta0, zeta
    real(dp), intent(out) :: theta, dtheta_dzeta
    real(dp) :: e
    e = exp(-zeta * inv_zeta0)
    theta = (theta0 - thetaf) * e + thetaf
    dtheta_dzeta = -(theta0 - thetaf) * inv_zeta0 * e
  end subroutine worn_angle

  !> d theta / d zeta from the current angle, without an exponential: -(theta - theta_f)/zeta_0.
  pure real(dp) function worn_angle_slope(thetaf, inv_zeta0, theta)
    real(dp), intent(in) :: thetaf, inv_zeta0, theta
    worn_angle_slope = -(theta - thetaf) * inv_zeta0
  end function worn_angle_slope

  !> Start from F(zeta_o) = -g0 (g0 > 0) with the slope F'(zeta_o) = fp_o there: the first
  !> point to evaluate is Newton's, zeta_o + g0 / fp_o (F' > 0), where the root is within the
  !> square of the step's curvature term, so that the first point often meets the tolerance;
  !> zeta_o + g0 where F' <= 0 (the bracket's doubling steps from there).
  pure subroutine wear_root_begin(rt, zeta_o, g0, fp_o)
    type(wear_root_t), intent(out) :: rt
    real(dp), intent(in) :: zeta_o, g0, fp_o
    rt%zeta_o = zeta_o
    rt%lo = zeta_o
    rt%width = g0
    rt%scale = g0
    rt%x = zeta_o + g0
    if (fp_o > 0.0_dp) then
      rt%x = zeta_o + g0 / fp_o
      rt%newton_start = .true.
    end if
  end subroutine wear_root_begin

  !> F = f and F' = fp at rt%x: the next point in rt%x, or rt%done (root at rt%x when rt%ok).
  pure subroutine wear_root_update(rt, f, fp, tol, max_iterations)
    type(wear_root_t), intent(inout) :: rt
    real(dp), intent(in) :: f, fp, tol
    integer, intent(in) :: max_iterations
    real(dp) :: xn
    ! Converged wherever the residual is at round-off of zeta: also at the first point when
    ! the plane is fully worn (theta = theta_f: F is linear and zeta_o + g0 is its root). The
    ! round-off is that of the work g0 or of zeta, except at a point without work (g = 0, F =
    ! zeta - zeta_o: the plane has lost contact there, or sticks), which is a root only where
    ! zeta - zeta_o is at round-off of zeta itself: the work falls from g0 to 0 between zeta_o
    ! and that point (steeply, or with a jump, where the plane loses contact), and the root is
    ! on the way.
    rt%scale = max(rt%scale, abs(rt%x))
    if (abs(f) <= tol * merge(rt%scale, abs(rt%x), f < rt%x - rt%zeta_o)) then
      call finish(rt, fp > 0.0_dp)
      return
    end if
    if (.not. rt%bracketed) then
      if (f < 0.0_dp .and. rt%newton_start .and. fp > 0.0_dp) then
        ! below the root from Newton's first point: Newton's step upwards (F' > 0) where it
        ! moves, else the doubling steps
        xn = rt%x - f / fp
        if (xn > rt%x) then
          rt%lo = rt%x
          rt%iterations = rt%iterations + 1
          if (rt%iterations > max_iterations) then
            call finish(rt, .false.)
            return
          end if
          rt%x = xn
          rt%width = xn - rt%zeta_o
          return
        end if
      end if
      if (f < 0.0_dp) then
        rt%lo = rt%x
        rt%width = 2.0_dp * rt%width
        rt%x = rt%zeta_o + rt%width
        rt%expansions = rt%expansions + 1
        if (rt%expansions > max_expansions) call finish(rt, .false.)
        return
      end if
      rt%hi = rt%x
      rt%bracketed = .true.
    else
      if (f < 0.0_dp) then
        rt%lo = rt%x
      else
        rt%hi = rt%x
      end if
      if (rt%hi - rt%lo <= 4.0_dp * epsilon(1.0_dp) * abs(rt%x)) then
        rt%at_jump = .true.
        call finish(rt, fp > 0.0_dp)
        return
      end if
    end if
    rt%iterations = rt%iterations + 1
    if (rt%iterations > max_iterations) then
      call finish(rt, .false.)
      return
    end if
    if (fp > 0.0_dp) then
      xn = rt%x - f / fp
    else
      xn = rt%lo - 1.0_dp
    end if
    if (.not. (xn > rt%lo .and. xn < rt%hi)) xn = 0.5_dp * (rt%lo + rt%hi)
    if (.not. (abs(xn - rt%x) > 0.0_dp)) then
      call finish(rt, fp > 0.0_dp)     ! cannot move: at round-off
      return
    end if
    rt%x = xn
  end subroutine wear_root_update

  pure subroutine finish(rt, ok)
    type(wear_root_t), intent(inout) :: rt
    logical, intent(in) :: ok
    rt%done = .true.
    rt%ok = ok
  end subroutine finish

end module interlock_wear
