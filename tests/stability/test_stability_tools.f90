!> Tools shared by the stability matrix and the fuzzer: a portable random generator, the
!> mixed-control step (constant normal traction, imposed slip) by a safeguarded scalar Newton
!> iteration on s_N, the physical traction bound and the per-update invariant checks.
module test_stability_tools
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use interlock
  implicit none
  private
  public :: rng_t, rng_seed, rng_uniform, rng_int, rng_log_uniform
  public :: mixed_step, mixed_max_iterations, traction_bound, check_update, theta_range
  public :: fmt_real

  !> L'Ecuyer's combined multiplicative generator (1988): portable, no integer overflow in int64,
  !> period about 2.3e18. The same seed gives the same stream with every compiler.
  type :: rng_t
    integer(int64) :: s1 = 12345_int64, s2 = 67890_int64
  end type rng_t

  !> Bound on the iterations of one mixed-control step (Newton + bracketing + bisection).
  integer, parameter :: mixed_max_iterations = 300

contains

  pure subroutine rng_seed(rng, seed)
    type(rng_t), intent(out) :: rng
    integer, intent(in) :: seed
    integer(int64) :: x
    x = abs(int(seed, int64))
    rng%s1 = 1_int64 + mod(x * 7919_int64 + 12345_int64, 2147483562_int64)
    rng%s2 = 1_int64 + mod(x * 104729_int64 + 67890_int64, 2147483398_int64)
  end subroutine rng_seed

  !> Uniform in (0, 1).
  function rng_uniform(rng) result(u)
    type(rng_t), intent(inout) :: rng
    real(dp) :: u
    integer(int64) :: z
    rng%s1 = mod(40014_int64 * rng%s1, 2147483563_int64)
    rng%s2 = mod(40692_int64 * rng%s2, 2147483399_int64)
    z = rng%s1 - rng%s2
    if (z < 1_int64) z = z + 2147483562_int64
    u = real(z, dp) * 4.656613057391769e-10_dp
  end function rng_uniform

  !> Uniform integer in lo..hi.
  function rng_int(rng, lo, hi) result(i)
    type(rng_t), intent(inout) :: rng
    integer, intent(in) :: lo, hi
    integer :: i
    i = lo + min(hi - lo, int(rng_uniform(rng) * real(hi - lo + 1, dp)))
  end function rng_int

  !> Log-uniform in [lo, hi] (lo, hi > 0).
  function rng_log_uniform(rng, lo, hi) result(x)
    type(rng_t), intent(inout) :: rng
    real(dp), intent(in) :: lo, hi
    real(dp) :: x
    x = lo * (hi / lo)**rng_uniform(rng)
  end function rng_log_uniform

  !> A physically motivated bound on |sigma| (Euclidean) at the separation s: on every plane the
  !> cohesive part never exceeds the peak tractions (it is (1-D) K s with beta >= s/s_0), the
  !> contact part is the penalty K_n on the interpenetration, and the friction is at most mu
  !> times the contact pressure; area fractions and A_g are <= 1 and the rotations are
  !> orthogonal. Without damage evolution the cohesive part is linear elastic instead.
  pure real(dp) function traction_bound(mat, s) result(b)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: s(2)
    real(dp) :: ns, cohesive
    ns = norm2(s)
    if (mat%use_damage) then
      cohesive = mat%sigma0_n + mat%sigma0_t
    else if (mat%prefractured) then
      cohesive = 0.0_dp
    else
      cohesive = (mat%kn + mat%kt) * ns
    end if
    b = (1.0_dp + 1.0e-9_dp) * (cohesive + (1.0_dp + mat%mu_eff) * mat%kn * ns) + tiny(1.0_dp)
  end function traction_bound

  !> The admissible range of plane k's inclination: between theta_f and theta_0 (effective).
  pure subroutine theta_range(mat, k, lo, hi)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    real(dp), intent(out) :: lo, hi
    lo = min(mat%theta_init(k), mat%thetaf_eff(k))
    hi = max(mat%theta_init(k), mat%thetaf_eff(k))
  end subroutine theta_range

  !> The invariants of one accepted update from `old` to `new` (empty `what` when all hold):
  !> D in [0,1] and non-decreasing, zeta non-decreasing, theta between theta_f and theta_0,
  !> friction dissipation non-decreasing, finite and bounded traction, finite tangent.
  pure subroutine check_update(mat, old, new, sigma, tangent, what)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(in) :: old, new
    real(dp), intent(in) :: sigma(2), tangent(2, 2)
    character(len=*), intent(out) :: what
    integer :: k, n
    real(dp) :: lo, hi, b, tol_e
    character(len=8) :: kb

    what = ''
    n = mat%n_planes
    if (.not. (all(ieee_is_finite(sigma)) .and. all(ieee_is_finite(tangent)))) then
      what = 'traction or tangent is NaN/Inf'
      return
    end if
    if (.not. all(ieee_is_finite([new%damage(1:n), new%beta(1:n), new%sf(1:n), new%zeta(1:n), &
                                  new%theta(1:n), new%tauf(1:n), new%work, new%stored, &
                                  new%diss_damage, new%diss_friction]))) then
      what = 'a state variable is NaN/Inf'
      return
    end if
    b = traction_bound(mat, new%s)
    if (norm2(sigma) > b) then
      what = '|sigma| = ' // fmt_real(norm2(sigma)) // ' exceeds the bound ' // fmt_real(b)
      return
    end if
    do k = 1, n
      write (kb, '(i0)') k
      if (new%damage(k) < 0.0_dp .or. new%damage(k) > 1.0_dp) then
        what = 'D(' // trim(kb) // ') = ' // fmt_real(new%damage(k)) // ' outside [0,1]'
        return
      end if
      if (new%damage(k) < old%damage(k)) then
        what = 'D(' // trim(kb) // ') decreased from ' // fmt_real(old%damage(k)) // ' to ' // &
               fmt_real(new%damage(k))
        return
      end if
      if (new%zeta(k) < old%zeta(k)) then
        what = 'zeta(' // trim(kb) // ') decreased'
        return
      end if
      call theta_range(mat, k, lo, hi)
      if (new%theta(k) < lo - 1.0e-15_dp * abs(lo) .or. new%theta(k) > hi + 1.0e-15_dp * abs(hi)) then
        what = 'theta(' // trim(kb) // ') = ' // fmt_real(new%theta(k)) // &
               ' rad outside [theta_f, theta_0]'
        return
      end if
      if (abs(new%theta(k)) > abs(mat%theta0(k)) * (1.0_dp + 1.0e-15_dp)) then
        what = '|theta(' // trim(kb) // ')| > |theta_0|'
        return
      end if
    end do
    tol_e = 1.0e-12_dp * (abs(new%work) + abs(old%diss_damage) + abs(old%diss_friction)) + &
            tiny(1.0_dp)
    if (new%diss_friction < old%diss_friction - tol_e) then
      what = 'friction dissipation decreased by ' // fmt_real(old%diss_friction - new%diss_friction)
      return
    end if
    ! No check on the damage dissipation: its increment Y dD, with Y = c beta^2/2 -
    ! tau_f^2/(2 K_t), is negative when |tau_f| > K_t |s_kt| while damage grows (after a shear
    ! reversal), even accumulated over a history. That is a property of the law as SPEC section
    ! 4 states it (decision D9; reproducer: tests/data/stability_negative_
    ! damage_dissipation.nml); SPEC section 8's non-negative claim is checked where it is made,
    ! on monotonic histories (core_closed_forms, core_invariants).
  end subroutine check_update

  !> One step with the normal traction prescribed (sigma_N = sig_n) and the slip imposed
  !> (s_T = s_t): find s_N by a safeguarded Newton iteration (bracketing, bisection), each trial
  !> an update from the same `old`. stat: 0 converged; 1 the core failed at a trial s_N (its
  !> message in `reason`); 2 no root (the normal traction jumps across the target); 3 the
  !> iteration bound was reached. `iterations` counts the trial updates.
  subroutine mixed_step(mat, solver, old, sig_n, s_t, new, sigma, tangent, info, &
                             iterations, stat, reason)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: sig_n, s_t
    type(interlock_state_t), intent(out) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(out) :: info
    integer, intent(out) :: iterations, stat
    character(len=*), intent(out) :: reason
    real(dp) :: x, f, k, lo, hi, flo, fhi, xn, dstep, tol, th_lo(max_planes), th_hi(max_planes)
    real(dp) :: noise
    logical :: lo_set, hi_set

    reason = ''
    stat = 0
    iterations = 0
    tol = 1.0e-11_dp * abs(sig_n) + 1.0e-14_dp * min(mat%sigma0_n, mat%sigma0_t)
    dstep = max(mat%s0n, 1.0e-3_dp * abs(old%s(1)))
    lo_set = .false.
    hi_set = .false.
    lo = 0.0_dp
    hi = 0.0_dp
    flo = 0.0_dp
    fhi = 0.0_dp
    x = old%s(1)
    if (mat%use_depth) x = min(x, mat%h_n)
    call evaluate(x)
    if (stat /= 0) return
    do
      ! sigma_N is a sum of plane tractions that can be far larger than itself (locking):
      ! its round-off noise scales with |sigma| and the contact stress K_n |s|.
      noise = 64.0_dp * epsilon(1.0_dp) * (norm2(sigma) + mat%kn * norm2([x, s_t]))
      if (abs(f) <= tol + noise) return
      if (f < 0.0_dp) then
        lo = x
        flo = f
        th_lo = new%theta
        lo_set = .true.
      else
        hi = x
        fhi = f
        th_hi = new%theta
        hi_set = .true.
      end if
      if (iterations >= mixed_max_iterations) then
        stat = 3
        reason = 'mixed control: no convergence within the iteration bound'
        return
      end if
      xn = x
      if (k > 0.0_dp) xn = x - f / k
      if (lo_set .and. hi_set) then
        if (.not. (xn > lo .and. xn < hi)) xn = 0.5_dp * (lo + hi)
        if (.not. (xn > lo .and. xn < hi)) then
          ! Adjacent floating-point numbers: converged to round-off unless the traction jumps.
          if (min(abs(flo), abs(fhi)) <= 8.0_dp * abs(k) * spacing(max(abs(lo), abs(hi))) + &
              tol + noise) then
            if (abs(flo) < abs(fhi)) then
              x = lo
            else
              x = hi
            end if
            call evaluate(x)
            return
          end if
          stat = 2
          if (maxval(abs(th_lo(1:mat%n_planes) - th_hi(1:mat%n_planes))) > 1.0e-9_dp) then
            reason = 'mixed control: no s_N carries sigma_N: the wear update switches branch ' // &
                     '(theta jumps by ' // &
                     fmt_real(maxval(abs(th_lo(1:mat%n_planes) - th_hi(1:mat%n_planes)))) // &
                     ' rad between adjacent s_N), sigma_N jumps from ' // fmt_real(flo + sig_n) // &
                     ' to ' // fmt_real(fhi + sig_n) // ' MPa'
          else
            reason = 'mixed control: sigma_N(s_N) jumps across the target between s_N = ' // &
                     fmt_real(lo, 17) // ' and ' // fmt_real(hi, 17) // ' (from ' // &
                     fmt_real(flo + sig_n) // ' to ' // fmt_real(fhi + sig_n) // &
                     ' MPa) with no change of theta'
          end if
          return
        end if
      else if (lo_set) then
        ! Need a larger s_N.
        if (.not. (xn > x .and. xn < x + dstep)) xn = x + dstep
        dstep = 4.0_dp * dstep
        if (mat%use_depth) xn = min(xn, mat%h_n)
        if (.not. (xn > x)) then
          stat = 2
          reason = 'mixed control: cannot carry sigma_N = ' // fmt_real(sig_n) // &
                   ' MPa: the interface has separated, s_N >= H_N'
          return
        end if
      else
        if (.not. (xn < x .and. xn > x - dstep)) xn = x - dstep
        dstep = 4.0_dp * dstep
      end if
      x = xn
      call evaluate(x)
      if (stat /= 0) return
    end do

  contains

    subroutine evaluate(xe)
      real(dp), intent(in) :: xe
      iterations = iterations + 1
      call interlock_update(mat, solver, [xe, s_t], old, new, sigma, tangent, info)
      if (info%status /= status_ok) then
        stat = 1
        reason = trim(info%message)
        return
      end if
      f = sigma(1) - sig_n
      k = tangent(1, 1)
    end subroutine evaluate

  end subroutine mixed_step

  pure function fmt_real(x, digits) result(str)
    real(dp), intent(in) :: x
    integer, intent(in), optional :: digits
    character(len=:), allocatable :: str
    character(len=40) :: buf
    if (present(digits)) then
      write (buf, '(es26.17e3)') x
    else
      write (buf, '(es12.5)') x
    end if
    str = trim(adjustl(buf))
  end function fmt_real

end module test_stability_tools
