!> The scenes of the benchmark and the single-point driver that runs them: the paper's
!> "compress first, then shear" protocol (SPEC decision D8) at constant normal traction, with a
!> safeguarded scalar Newton iteration on s_N in every step, and the effect sets and separation
!> histories of the cost-per-call measurement.
module interlock_bench_scenes
  use interlock, only: dp, deg_to_rad, interlock_material_t, interlock_solver_t, &
      interlock_state_t, interlock_info_t, interlock_update, interlock_state_init, &
      interlock_material_prepare, interlock_paper_ria, interlock_general_ria, status_ok, &
      is_nan_value, same_value, &
      scheme_implicit
  implicit none
  private
  public :: scene_t, make_scene, run_scene, slip_at, median
  public :: n_effect_sets, effect_set_names, make_effect_set, make_histories

  integer, parameter :: max_knots = 8

  !> A work-precision scene: material, constant normal traction, slip path in pseudo-time
  !> (time = accumulated |slip|), and the smallest step count of the study.
  type :: scene_t
    character(len=16) :: name = ''
    character(len=80) :: title = ''
    type(interlock_material_t) :: mat
    real(dp) :: sig_n = 0.0_dp          !< constant normal traction [MPa]
    integer :: n_knots = 0
    real(dp) :: knot_t(max_knots) = 0.0_dp  !< pseudo-time of the slip turning points [mm]
    real(dp) :: knot_s(max_knots) = 0.0_dp  !< slip at the turning points [mm]
    integer :: base_steps = 25          !< step counts are base_steps * 2**j (turning points on steps)
  end type scene_t

  integer, parameter :: n_effect_sets = 5
  character(len=24), parameter :: effect_set_names(n_effect_sets) = [character(len=24) :: &
    'damage', 'damage+friction', '+interlocking', '+finite_depth', '+wear (full model)']

contains

  !> The three scenes: 'fig11' (Table 2, H_N = 2, zeta_0 = 1, monotonic slip to 50 mm),
  !> 'fig12' (H_N = 5, zeta_0 = 20, slip 0 -> 10 -> -10 -> 10 mm), 'granite' (Lee et al.:
  !> mu = tan 34.6 deg, theta_f = 9 deg, H_N = 4, zeta_0 = 6.666, sigma_N = -1 MPa assumed,
  !> two cycles 0 -> 5 -> -5 -> 5 -> -5 -> 0 mm).
  pure subroutine make_scene(name, sc, stat, message)
    character(len=*), intent(in) :: name
    type(scene_t), intent(out) :: sc
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    real(dp) :: slips(max_knots), theta0, thetaf, zeta0
    integer :: nk, k

    sc%name = name
    sc%mat%sigma0_n = 0.025_dp
    sc%mat%sigma0_t = 0.025_dp
    sc%mat%gc = 0.0005_dp
    sc%mat%eta = 0.99_dp
    sc%mat%mu = 0.5_dp
    theta0 = 30.0_dp
    select case (name)
    case ('fig11')
      sc%title = 'Fig. 11: H_N = 2 mm, zeta_0 = 1 N/mm, sigma_N = -2 MPa, slip 0 -> 50 mm'
      sc%mat%h_n = 2.0_dp
      thetaf = 7.0_dp
      zeta0 = 1.0_dp
      sc%sig_n = -2.0_dp
      nk = 2
      slips(1:nk) = [0.0_dp, 50.0_dp]
      sc%base_steps = 25
    case ('fig12')
      sc%title = 'Fig. 12: H_N = 5 mm, zeta_0 = 20 N/mm, sigma_N = -2 MPa, slip 0/+10/-10/+10 mm'
      sc%mat%h_n = 5.0_dp
      thetaf = 7.0_dp
      zeta0 = 20.0_dp
      sc%sig_n = -2.0_dp
      nk = 4
      slips(1:nk) = [0.0_dp, 10.0_dp, -10.0_dp, 10.0_dp]
      sc%base_steps = 25
    case ('granite')
      sc%title = 'granite (Lee et al.): H_N = 4 mm, zeta_0 = 6.666, sigma_N = -1 MPa, 2 x +/-5 mm'
      sc%mat%mu = tan(34.6_dp * deg_to_rad)
      sc%mat%h_n = 4.0_dp
      thetaf = 9.0_dp
      zeta0 = 6.666_dp
      sc%sig_n = -1.0_dp
      nk = 6
      slips(1:nk) = [0.0_dp, 5.0_dp, -5.0_dp, 5.0_dp, -5.0_dp, 0.0_dp]
      sc%base_steps = 24     ! turning points every 5 mm of a 40 mm path: a multiple of 8
    case default
      stat = 1
      message = 'unknown scene ' // trim(name)
      return
    end select
    call interlock_paper_ria(sc%mat, theta0 * deg_to_rad, thetaf * deg_to_rad, zeta0)
    sc%n_knots = nk
    sc%knot_s(1:nk) = slips(1:nk)
    sc%knot_t(1) = 0.0_dp
    do k = 2, nk
      sc%knot_t(k) = sc%knot_t(k - 1) + abs(slips(k) - slips(k - 1))
    end do
    call interlock_material_prepare(sc%mat, stat, message)
  end subroutine make_scene

  !> The slip at pseudo-time t (piecewise linear between the turning points).
  pure real(dp) function slip_at(sc, t) result(s)
    type(scene_t), intent(in) :: sc
    real(dp), intent(in) :: t
    integer :: k
    real(dp) :: w
    s = sc%knot_s(sc%n_knots)
    do k = 2, sc%n_knots
      if (t <= sc%knot_t(k)) then
        w = (t - sc%knot_t(k - 1)) / (sc%knot_t(k) - sc%knot_t(k - 1))
        s = sc%knot_s(k - 1) + w * (sc%knot_s(k) - sc%knot_s(k - 1))
        return
      end if
    end do
  end function slip_at

  !> Run a scene with n uniform slip steps after the preload step. Rows i = 0, every, 2 every,
  !> ..., n (row 0: after the preload) of s_N and sigma_T are returned in sn(0:), sigt(0:).
  !> The preload step is one step of the implicit scheme whatever `solver` says, so that every
  !> configuration integrates the slip history from the same state (the reference's): on the
  !> Table 2 scenes the inclined planes already slide under the preload (tan 30 deg > mu), and
  !> one step of each scheme wears them differently (explicit: not at all; implicit: by the
  !> end-of-step work; trapezoidal: half of it), a difference that no slip step count removes
  !> (fig11: 7e-4 in sigma_T between the implicit and the trapezoidal preload).
  !> `updates` counts the calls of interlock_update (Newton iterations on s_N included).
  !> `max_residual`: see solve_normal (0 to round-off unless substepping makes sigma_N jump).
  !> ok = .false. when an update or the Newton iteration on s_N failed.
  pure subroutine run_scene(sc, solver, n, every, sn, sigt, ok, updates, max_newton, max_residual, why)
    type(scene_t), intent(in) :: sc
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: n, every
    real(dp), intent(out) :: sn(0:), sigt(0:)
    logical, intent(out) :: ok
    integer, intent(out) :: updates, max_newton
    real(dp), intent(out) :: max_residual   !< largest |sigma_N - sig_n| / |sig_n| accepted
    character(len=*), intent(out), optional :: why
    character(len=256) :: reason
    type(interlock_state_t) :: st(2)
    type(interlock_solver_t) :: preload
    real(dp) :: s(2), sig(2), t_end, res
    integer :: i, cur, its

    t_end = sc%knot_t(sc%n_knots)
    call interlock_state_init(sc%mat, st(1))
    cur = 1
    s = 0.0_dp
    updates = 0
    max_newton = 0
    max_residual = 0.0_dp
    sn = 0.0_dp
    sigt = 0.0_dp
    preload = solver
    preload%scheme = scheme_implicit
    preload%substep_tol = 0.0_dp
    do i = 0, n
      if (i > 0) then
        s(2) = slip_at(sc, t_end * real(i, dp) / real(n, dp))
        call solve_normal(sc%mat, solver, sc%sig_n, s, st(cur), st(3 - cur), sig, its, ok, res, &
                          reason)
      else
        call solve_normal(sc%mat, preload, sc%sig_n, s, st(cur), st(3 - cur), sig, its, ok, res, &
                          reason)
      end if
      updates = updates + its
      max_newton = max(max_newton, its)
      if (ok) max_residual = max(max_residual, res)
      if (.not. ok) then
        if (present(why)) write (why, '(a,i0,a,es12.5,a)') 'step ', i, ' (s_T = ', s(2), '): ' // &
          trim(reason)
        return
      end if
      cur = 3 - cur
      if (mod(i, every) == 0) then
        sn(i / every) = s(1)
        sigt(i / every) = sig(2)
      end if
    end do
  end subroutine run_scene

  !> Find s_N with sigma_N(s_N, s_T) = sig_n from `old` (s(1) in: the start guess; out: the
  !> root). Newton's method on the exact tangent, safeguarded: every evaluation narrows a
  !> bracket (sigma_N grows with s_N), steps that leave it or a non-positive slope fall back to
  !> bisection, or to doubling steps until the root is bracketed.
  !> With adaptive substepping sigma_N(s_N) can jump (the accepted sub-increments change with
  !> s_N); when the bracket shrinks to a jump, the side with the smaller residual is taken if
  !> that residual is below `jump_accept` |sig_n|, and `residual` (|sigma_N - sig_n|/|sig_n|)
  !> says how far from the target it is.
  pure subroutine solve_normal(mat, solver, sig_n, s, old, new, sig, its, ok, residual, reason)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: sig_n
    real(dp), intent(inout) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(out) :: new
    real(dp), intent(out) :: sig(2), residual
    integer, intent(out) :: its
    logical, intent(out) :: ok
    character(len=*), intent(out) :: reason
    integer, parameter :: max_its = 200
    real(dp), parameter :: rel_tol = 1.0e-12_dp, jump_accept = 0.05_dp
    type(interlock_info_t) :: info
    real(dp) :: tangent(2, 2), f, x, xn, lo, hi, width, x_best, f_best
    logical :: have_lo, have_hi

    have_lo = .false.
    have_hi = .false.
    lo = 0.0_dp
    hi = 0.0_dp
    width = max(abs(sig_n) / mat%kn, 1.0e-3_dp)
    x = s(1)
    x_best = x
    f_best = huge(1.0_dp)
    ok = .false.
    residual = huge(1.0_dp)
    reason = 'the Newton iteration on s_N did not converge'
    its = 0
    do while (its < max_its)
      its = its + 1
      call interlock_update(mat, solver, [x, s(2)], old, new, sig, tangent, info)
      if (info%status /= status_ok) then
        write (reason, '(a,es12.5,a)') 'interlock_update at s_N = ', x, ': ' // trim(info%message)
        return
      end if
      f = sig(1) - sig_n
      if (abs(f) < abs(f_best)) then
        f_best = f
        x_best = x
      end if
      if (abs(f) <= rel_tol * abs(sig_n)) then
        ok = .true.
        exit
      end if
      if (f < 0.0_dp) then
        lo = x
        have_lo = .true.
      else
        hi = x
        have_hi = .true.
      end if
      if (have_lo .and. have_hi .and. hi - lo <= 8.0_dp * epsilon(1.0_dp) * max(abs(lo), abs(hi))) then
        ! No root between two neighbouring numbers: sigma_N jumps here.
        if (abs(f_best) <= jump_accept * abs(sig_n)) then
          ok = .true.
          if (.not. same_value(x, x_best)) then
            x = x_best
            its = its + 1
            call interlock_update(mat, solver, [x, s(2)], old, new, sig, tangent, info)
            f = sig(1) - sig_n
          end if
        else
          write (reason, '(a,es12.5,a,es12.5)') 'sigma_N jumps at s_N = ', x, &
            ': no root, residual ', f_best
        end if
        exit
      end if
      if (tangent(1, 1) > 0.0_dp) then
        xn = x - f / tangent(1, 1)
      else
        xn = x
      end if
      if ((have_lo .and. .not. xn > lo) .or. (have_hi .and. .not. xn < hi) .or. &
          .not. abs(xn - x) > 0.0_dp .or. is_nan_value(xn)) then
        if (have_lo .and. have_hi) then
          xn = 0.5_dp * (lo + hi)
        else if (have_lo) then
          xn = x + width
          width = 2.0_dp * width
        else
          xn = x - width
          width = 2.0_dp * width
        end if
      end if
      x = xn
    end do
    s(1) = x
    if (ok) residual = abs(f) / abs(sig_n)
  end subroutine solve_normal

  !> The material of effect set `iset` (1: damage only, flat plane, mu = 0, H_N infinite; 2: +
  !> friction mu = 0.5; 3: + interlocking, the 3-plane RIA at 30 deg; 4: + finite depth
  !> H_N = 1 mm; 5: + wear theta_f = 7 deg, zeta_0 = 1 N/mm: the full model). Table 1 cohesion:
  !> sigma0 = 3 MPa, Gc = 0.3 N/mm, eta = 0.9.
  pure subroutine make_effect_set(iset, mat, stat, message)
    integer, intent(in) :: iset
    type(interlock_material_t), intent(out) :: mat
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 3.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.0_dp
    mat%h_n = huge(1.0_dp)
    if (iset >= 2) mat%mu = 0.5_dp
    if (iset >= 3) then
      call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 30.0_dp * deg_to_rad, huge(1.0_dp))
    else
      call interlock_general_ria(mat, 1, [1.0_dp], [0.0_dp], [0.0_dp])
    end if
    if (iset >= 4) mat%h_n = 1.0_dp
    if (iset >= 5) call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 1.0_dp)
    call interlock_material_prepare(mat, stat, message)
  end subroutine make_effect_set

  !> Three separation histories of npts points each [mm] (s_0 = 0.02 mm, s_c = 0.2 mm):
  !> 1 monotonic mixed-mode opening to (0.3, 0.6); 2 cyclic shear under a fixed closure
  !> s_N = -0.005 with amplitude growing to 0.6 (10 reversals); 3 mixed: opening and closing
  !> (s_N between -0.012 and +0.08) with growing cyclic shear, loading and unloading interleaved.
  pure subroutine make_histories(npts, h)
    integer, intent(in) :: npts
    real(dp), intent(out) :: h(:, :, :)
    real(dp), parameter :: two_pi = 6.283185307179586_dp
    real(dp) :: t
    integer :: i
    do i = 1, npts
      t = real(i, dp) / real(npts, dp)
      h(:, i, 1) = t * [0.3_dp, 0.6_dp]
      h(:, i, 2) = [-0.005_dp, 0.6_dp * t * sin(two_pi * 5.0_dp * t)]
      h(:, i, 3) = [0.034_dp + 0.046_dp * sin(two_pi * 3.0_dp * t + 0.3_dp), &
                    0.1_dp * t + 0.4_dp * t * sin(two_pi * 4.0_dp * t)]
    end do
  end subroutine make_histories

  !> The median of x (the mean of the two middle values for an even size).
  pure real(dp) function median(x)
    real(dp), intent(in) :: x(:)
    real(dp) :: y(size(x)), t
    integer :: i, j, n
    n = size(x)
    y = x
    do i = 2, n            ! insertion sort: n is small
      t = y(i)
      j = i - 1
      do while (j >= 1)
        if (.not. y(j) > t) exit
        y(j + 1) = y(j)
        j = j - 1
      end do
      y(j + 1) = t
    end do
    if (mod(n, 2) == 1) then
      median = y((n + 1) / 2)
    else
      median = 0.5_dp * (y(n / 2) + y(n / 2 + 1))
    end if
  end function median

end module interlock_bench_scenes
