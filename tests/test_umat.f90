!> The UMAT against the library: the same numbers over a history that exercises damage,
!> friction, interlocking, finite depth and wear; bad input is rejected without touching
!> STRESS and STATEV; PNEWDT proposes a step that meets the accuracy bounds.
module test_umat_cases
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock
  use interlock_assert
  use test_umat_interface, only: umat_point_t, call_umat
  implicit none
  private
  public :: collect_umat

  integer, parameter :: ntens = 2
  !> Interface with interlocking, finite depth and wear (theta_0 = 30, theta_f = 7 deg).
  real(dp), parameter :: props_wear(9) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 2.0_dp, &
                                          30.0_dp, 7.0_dp, 1.0_dp]
  !> Flat interface, mode I closed forms: s_0n = 0.02 mm, s_cn = 0.2 mm.
  real(dp), parameter :: props_flat(9) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 1.0e30_dp, &
                                          0.0_dp, 0.0_dp, 1.0e30_dp]
  integer, parameter :: n_legs = 4
  integer, parameter :: leg_steps(n_legs) = [2, 40, 30, 20]
  real(dp), parameter :: leg_end(2, n_legs) = reshape([-0.004_dp, 0.0_dp, 0.076_dp, 0.4_dp, &
                                                       -0.004_dp, -0.1_dp, 0.05_dp, 0.2_dp], [2, n_legs])

contains

  subroutine collect_umat()
    call run_case('umat_equals_library_explicit', umat_equals_library_explicit)
    call run_case('umat_equals_library_implicit', umat_equals_library_implicit)
    call run_case('umat_equals_library_substepping', umat_equals_library_substepping)
    call run_case('bad_properties_rejected', bad_properties_rejected)
    call run_case('bad_sizes_rejected', bad_sizes_rejected)
    call run_case('nonfinite_separation_cuts_back', nonfinite_separation_cuts_back)
    call run_case('pnewdt_only_lowered', pnewdt_only_lowered)
    call run_case('pnewdt_damage_bound_mode_I', pnewdt_damage_bound_mode_i)
    call run_case('pnewdt_damage_bound_mixed_mode', pnewdt_damage_bound_mixed_mode)
    call run_case('pnewdt_clamped', pnewdt_clamped)
    call run_case('pnewdt_angle_bound', pnewdt_angle_bound)
    call run_case('bad_statev_rejected', bad_statev_rejected)
    call run_case('bad_stress_rejected', bad_stress_rejected)
    call run_case('separation_beyond_bound_rejected', separation_beyond_bound_rejected)
    call run_case('tiny_inverted_properties_rejected', tiny_inverted_properties_rejected)
    call run_case('prefractured_beta_running_maximum', prefractured_beta_running_maximum)
  end subroutine collect_umat

  !> The separation at step j of the test history (piecewise linear legs from 0).
  pure function history_point(j) result(s)
    integer, intent(in) :: j
    real(dp) :: s(2), a(2)
    integer :: leg, j0
    j0 = 0
    a = 0.0_dp
    s = 0.0_dp
    do leg = 1, n_legs
      if (j <= j0 + leg_steps(leg)) then
        s = a + real(j - j0, dp) / real(leg_steps(leg), dp) * (leg_end(:, leg) - a)
        return
      end if
      j0 = j0 + leg_steps(leg)
      a = leg_end(:, leg)
    end do
    s = a
  end function history_point

  function new_point(nstatv, nt) result(pt)
    integer, intent(in) :: nstatv, nt
    type(umat_point_t) :: pt
    allocate (pt%stress(nt), pt%statev(nstatv), pt%ddsdde(nt, nt))
    pt%stress = 0.0_dp
    pt%statev = 0.0_dp
    pt%ddsdde = 0.0_dp
  end function new_point

  !> The largest relative difference, floor 1 (bitwise: 0).
  pure real(dp) function reldiff(a, b)
    real(dp), intent(in) :: a(:), b(:)
    reldiff = maxval(abs(a - b) / max(1.0_dp, abs(a)))
  end function reldiff

  subroutine umat_equals_library_explicit()
    call compare_with_library(scheme_explicit, 0.0_dp)
  end subroutine umat_equals_library_explicit

  subroutine umat_equals_library_implicit()
    call compare_with_library(scheme_implicit, 0.0_dp)
  end subroutine umat_equals_library_implicit

  subroutine umat_equals_library_substepping()
    call compare_with_library(scheme_implicit, 1.0e-4_dp)
    call compare_with_library(scheme_explicit, 1.0e-4_dp)
  end subroutine umat_equals_library_substepping

  !> The library driven directly (material set through the API, not through PROPS) and the
  !> UMAT driven like an FE code, step by step over the same history.
  subroutine compare_with_library(scheme, tol)
    integer, intent(in) :: scheme
    real(dp), intent(in) :: tol
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    type(umat_point_t) :: pt
    real(dp) :: props(12), stran(2), dstran(2), s(2), sigma(2), tangent(2, 2), worst, sv(22)
    integer :: stat, j, k, n_steps
    character(len=message_len) :: message
    character(len=64) :: label

    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 3.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.5_dp
    mat%h_n = 2.0_dp
    call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 1.0_dp)
    call interlock_material_prepare(mat, stat, message)
    call assert_equal(status_ok, stat, 'library material prepared: ' // trim(message))
    solver%scheme = scheme
    solver%substep_tol = tol
    call interlock_state_init(mat, old)
    props = [props_wear, 0.0_dp, real(scheme, dp), tol]
    write (label, '(a,a,a,es8.1)') 'scheme ', scheme_name(scheme), ', substep_tol ', tol

    pt = new_point(umat_nstatv, ntens)
    n_steps = sum(leg_steps)
    worst = 0.0_dp
    do j = 1, n_steps
      stran = history_point(j - 1)
      dstran = history_point(j) - stran
      s = stran + dstran
      pt%pnewdt = 1.0e36_dp
      call call_umat(pt, props, stran, dstran, 1, 1, j)
      call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
      if (info%status /= status_ok) then
        call assert_true(.false., trim(label) // ': library update failed: ' // trim(info%message))
        return
      end if
      do k = 1, 3
        sv(statevar_index(sv_damage, k)) = new%damage(k)
        sv(statevar_index(sv_beta, k)) = new%beta(k)
        sv(statevar_index(sv_frictional_slip, k)) = new%sf(k)
        sv(statevar_index(sv_zeta, k)) = new%zeta(k)
        sv(statevar_index(sv_theta, k)) = new%theta(k)
        sv(statevar_index(sv_friction_traction, k)) = new%tauf(k)
      end do
      sv(statevar_index(sv_work, 0)) = new%work
      sv(statevar_index(sv_damage_dissipation, 0)) = new%diss_damage
      sv(statevar_index(sv_friction_dissipation, 0)) = new%diss_friction
      sv(statevar_index(sv_initialized, 0)) = 1.0_dp
      worst = max(worst, reldiff(sigma, pt%stress), reldiff(reshape(tangent, [4]), &
                  reshape(pt%ddsdde, [4])), reldiff(sv, pt%statev), &
                  reldiff([new%stored, new%diss_damage + new%diss_friction, 0.0_dp], &
                          [pt%sse, pt%scd, pt%spd]))
      old = new
    end do
    write (*, '(a,es10.3,a,i0,a,i0,a)') '    ' // trim(label) // ': largest relative difference ', &
      worst, ' over ', n_steps, ' increments (', count([worst > 0.0_dp]), ' = not bitwise)'
    call assert_equal(0.0_dp, worst, 1.0e-14_dp, trim(label) // ': UMAT = library')
    ! The history really exercised the mechanisms (else the comparison proves little).
    call assert_true(maxval(new%damage(1:3)) > 0.99_dp, trim(label) // ': damage reached 1')
    call assert_true(new%diss_friction > 0.1_dp, trim(label) // ': friction dissipated')
    call assert_true(abs(new%theta(1) + 30.0_dp * deg_to_rad) > 1.0_dp * deg_to_rad, &
                     trim(label) // ': the leading plane wore by more than 1 deg')
  end subroutine compare_with_library

  !> A point after three ordinary increments of the wear history (non-trivial STATEV).
  function loaded_point() result(pt)
    type(umat_point_t) :: pt
    integer :: j
    pt = new_point(umat_nstatv, ntens)
    do j = 1, 5
      call call_umat(pt, props_wear, history_point(j - 1), history_point(j) - history_point(j - 1), &
                     1, 1, j)
    end do
  end function loaded_point

  !> One call with `props` from `pt`'s state; the call must be rejected with PNEWDT = expect
  !> and leave STRESS, STATEV and DDSDDE as they were.
  subroutine expect_rejected(pt, props, stran, dstran, expect, what)
    type(umat_point_t), intent(in) :: pt
    real(dp), intent(in) :: props(:), stran(:), dstran(:), expect
    character(len=*), intent(in) :: what
    type(umat_point_t) :: trial
    trial = pt
    trial%pnewdt = 1.0e36_dp
    call call_umat(trial, props, stran, dstran, 7, 3, 1)
    call assert_equal(expect, trial%pnewdt, 0.0_dp, what // ': PNEWDT')
    call assert_true(all(same_bits(trial%stress, pt%stress)), what // ': STRESS untouched')
    call assert_true(all(same_bits(trial%statev, pt%statev)), what // ': STATEV untouched')
    call assert_true(all(same_value(trial%ddsdde, pt%ddsdde)), what // ': DDSDDE untouched')
    call assert_true(same_value(trial%sse, pt%sse) .and. same_value(trial%scd, pt%scd), &
                     what // ': SSE, SCD untouched')
  end subroutine expect_rejected

  !> Every property out of its range (derived from the table's bounds), NaN and infinity, and
  !> theta_f > theta_0.
  subroutine bad_properties_rejected()
    type(umat_point_t) :: pt
    real(dp) :: base(n_properties), props(n_properties), bad(6), nan, inf
    type(property_t) :: p
    integer :: i, j, nbad
    character(len=80) :: what
    nan = ieee_value(1.0_dp, ieee_quiet_nan)
    inf = ieee_value(1.0_dp, ieee_positive_inf)
    pt = loaded_point()
    base = properties%default
    base(1:9) = props_wear
    do i = 1, n_properties
      p = properties(i)
      nbad = 1
      bad(1) = nan
      if (p%kind == kind_real) then
        nbad = nbad + 1
        bad(nbad) = merge(p%lower, p%lower - 1.0_dp, p%lower_open)
        if (p%upper < huge(1.0_dp)) then
          nbad = nbad + 1
          bad(nbad) = merge(p%upper, p%upper + 1.0_dp, p%upper_open)
        end if
        if (.not. p%infinite_ok) then
          nbad = nbad + 1
          bad(nbad) = inf
        end if
        nbad = nbad + 1
        bad(nbad) = -inf
      else
        bad(2:4) = [p%lower - 1.0_dp, p%upper + 1.0_dp, p%lower + 0.5_dp]
        nbad = 4
      end if
      do j = 1, nbad
        props = base
        props(i) = bad(j)
        write (what, '(a,i0,a,a,a,a)') 'PROPS(', i, ') ', trim(p%name), ' = ', format_real(bad(j))
        call expect_rejected(pt, props, [0.0_dp, 0.0_dp], [1.0e-3_dp, 0.0_dp], -1.0_dp, trim(what))
      end do
    end do
    props = base
    props(prop_thetaf) = 31.0_dp
    call expect_rejected(pt, props, [0.0_dp, 0.0_dp], [1.0e-3_dp, 0.0_dp], -1.0_dp, &
                         'theta_f = 31 > theta_0 = 30')
  end subroutine bad_properties_rejected

  subroutine bad_sizes_rejected()
    type(umat_point_t) :: pt, pt3, pt1, pt_short
    real(dp) :: props(n_properties + 1)
    pt = loaded_point()
    props = 0.0_dp
    props(1:9) = props_wear
    call expect_rejected(pt, props(1:8), [0.0_dp, 0.0_dp], [1.0e-3_dp, 0.0_dp], -1.0_dp, 'NPROPS = 8')
    props(1:n_properties) = properties%default
    props(1:9) = props_wear
    props(n_properties + 1) = 1.0_dp
    call expect_rejected(pt, props, [0.0_dp, 0.0_dp], [1.0e-3_dp, 0.0_dp], -1.0_dp, 'NPROPS = 20')
    pt_short = new_point(umat_nstatv - 1, ntens)
    pt_short%statev = 0.125_dp
    pt_short%stress = [0.5_dp, 0.25_dp]
    call expect_rejected(pt_short, props_wear, [0.0_dp, 0.0_dp], [1.0e-3_dp, 0.0_dp], -1.0_dp, &
                         'NSTATV = 21')
    pt3 = new_point(umat_nstatv, 3)
    pt3%stress = [1.0_dp, 2.0_dp, 3.0_dp]
    pt3%statev = 0.5_dp
    call expect_rejected(pt3, props_wear, [0.0_dp, 0.0_dp, 0.0_dp], [1.0e-3_dp, 0.0_dp, 0.0_dp], &
                         -1.0_dp, 'NTENS = 3')
    pt1 = new_point(umat_nstatv, 1)
    pt1%stress = [1.0_dp]
    call expect_rejected(pt1, props_wear, [0.0_dp], [1.0e-3_dp], -1.0_dp, 'NTENS = 1')
  end subroutine bad_sizes_rejected

  !> A diverged global iteration (NaN or Inf separation) is a local failure: cut back.
  subroutine nonfinite_separation_cuts_back()
    type(umat_point_t) :: pt
    real(dp) :: nan, inf
    nan = ieee_value(1.0_dp, ieee_quiet_nan)
    inf = ieee_value(1.0_dp, ieee_positive_inf)
    pt = loaded_point()
    call expect_rejected(pt, props_wear, [0.0_dp, 0.0_dp], [nan, 0.0_dp], 0.5_dp, 'DSTRAN = NaN')
    call expect_rejected(pt, props_wear, [0.0_dp, 0.0_dp], [0.0_dp, inf], 0.5_dp, 'DSTRAN = Inf')
  end subroutine nonfinite_separation_cuts_back

  !> An increment within the bounds leaves PNEWDT alone; a bound never raises it.
  subroutine pnewdt_only_lowered()
    type(umat_point_t) :: pt, trial
    pt = new_point(umat_nstatv, ntens)
    pt%pnewdt = 1.0e36_dp
    call call_umat(pt, props_flat, [0.0_dp, 0.0_dp], [0.01_dp, 0.0_dp], 1, 1, 1)
    call assert_equal(1.0e36_dp, pt%pnewdt, 0.0_dp, 'elastic increment: PNEWDT unchanged')
    trial = pt
    trial%pnewdt = 0.05_dp
    call call_umat(trial, props_flat, [0.01_dp, 0.0_dp], [0.09_dp, 0.0_dp], 1, 1, 2)
    call assert_equal(0.05_dp, trial%pnewdt, 0.0_dp, 'a smaller PNEWDT from the host is kept')
    trial = pt
    trial%pnewdt = 1.0_dp
    call call_umat(trial, props_flat, [0.01_dp, 0.0_dp], [0.09_dp, 0.0_dp], 1, 1, 2)
    call assert_true(trial%pnewdt < 1.0_dp, 'damage increment 0.66 > 0.25: PNEWDT < 1')
  end subroutine pnewdt_only_lowered

  !> From `pt`, the increment dstran exceeds the damage bound: PNEWDT = f < 1; the retried
  !> increment f * dstran meets the bound, and is not more than `slack` below it.
  subroutine check_damage_retry(pt, props, stran, dstran, slack, what)
    type(umat_point_t), intent(in) :: pt
    real(dp), intent(in) :: props(:), stran(2), dstran(2), slack
    character(len=*), intent(in) :: what
    type(umat_point_t) :: first, retry
    real(dp) :: f, dd_first, dd_retry, bound
    bound = 0.25_dp   ! the table default of max_damage_increment
    first = pt
    first%pnewdt = 1.0e36_dp
    call call_umat(first, props, stran, dstran, 1, 1, 1)
    dd_first = maxval(first%statev(1:3) - pt%statev(1:3))
    f = first%pnewdt
    call assert_true(dd_first > bound, what // ': the first increment exceeds the bound')
    call assert_true(f < 1.0_dp .and. f >= 0.1_dp, what // ': 0.1 <= PNEWDT < 1')
    retry = pt
    retry%pnewdt = 1.0e36_dp
    call call_umat(retry, props, stran, f * dstran, 1, 1, 1)
    dd_retry = maxval(retry%statev(1:3) - pt%statev(1:3))
    write (*, '(a,f8.5,a,f8.5,a,f8.5)') '    ' // what // ': dD ', dd_first, ' -> PNEWDT ', f, &
      ' -> dD ', dd_retry
    call assert_true(dd_retry <= bound * (1.0_dp + 1.0e-12_dp), what // ': the retry meets the bound')
    call assert_true(dd_retry >= bound - slack, what // ': the retry is not far below the bound')
    call assert_equal(1.0e36_dp, retry%pnewdt, 0.0_dp, what // ': the retry is accepted')
  end subroutine check_damage_retry

  subroutine pnewdt_damage_bound_mode_i()
    type(umat_point_t) :: pt
    pt = new_point(umat_nstatv, ntens)
    ! Virgin to beyond the peak: D jumps from 0 to 0.889; beta is linear along mode I, so the
    ! proposed fraction meets the bound exactly.
    call check_damage_retry(pt, props_flat, [0.0_dp, 0.0_dp], [0.1_dp, 0.0_dp], 1.0e-9_dp, &
                            'mode I from 0')
    call call_umat(pt, props_flat, [0.0_dp, 0.0_dp], [0.025_dp, 0.0_dp], 1, 1, 1)
    call check_damage_retry(pt, props_flat, [0.025_dp, 0.0_dp], [0.075_dp, 0.0_dp], 1.0e-9_dp, &
                            'mode I from D = 0.22')
  end subroutine pnewdt_damage_bound_mode_i

  subroutine pnewdt_damage_bound_mixed_mode()
    type(umat_point_t) :: pt
    real(dp) :: props(9)
    props = props_wear
    props(6) = 1.0e30_dp
    pt = new_point(umat_nstatv, ntens)
    call check_damage_retry(pt, props, [0.0_dp, 0.0_dp], [0.01_dp, 0.04_dp], 0.05_dp, &
                            'mixed mode, RIA')
  end subroutine pnewdt_damage_bound_mixed_mode

  subroutine pnewdt_clamped()
    type(umat_point_t) :: pt
    pt = new_point(umat_nstatv, ntens)
    call call_umat(pt, props_flat, [0.0_dp, 0.0_dp], [0.021_dp, 0.0_dp], 1, 1, 1)
    pt%pnewdt = 1.0e36_dp
    call call_umat(pt, props_flat, [0.021_dp, 0.0_dp], [10.0_dp, 0.0_dp], 1, 1, 2)
    call assert_equal(0.1_dp, pt%pnewdt, 0.0_dp, 'PNEWDT clamped to 0.1')
  end subroutine pnewdt_clamped

  !> Sliding on worn asperities: a large slip increment turns the leading plane by more than
  !> max_angle_increment_deg = 1; the retried increment turns it by at most 1 deg.
  subroutine pnewdt_angle_bound()
    type(umat_point_t) :: pt, first, retry
    real(dp) :: props(9), dstran(2), f, dth_first, dth_retry, bound
    integer :: j
    props = props_wear
    props(6) = 1.0e30_dp
    bound = 1.0_dp * deg_to_rad
    pt = new_point(umat_nstatv, ntens)
    call call_umat(pt, props, [0.0_dp, 0.0_dp], [-0.004_dp, 0.0_dp], 1, 1, 1)
    do j = 1, 40
      call call_umat(pt, props, [-0.004_dp, 0.005_dp * (j - 1)], [0.0_dp, 0.005_dp], 1, 1, j + 1)
    end do
    dstran = [0.0_dp, 0.1_dp]
    first = pt
    first%pnewdt = 1.0e36_dp
    call call_umat(first, props, [-0.004_dp, 0.2_dp], dstran, 1, 1, 42)
    dth_first = maxval(abs(first%statev(13:15) - pt%statev(13:15)))
    f = first%pnewdt
    call assert_true(dth_first > bound, 'the large increment turns a plane by more than 1 deg')
    call assert_true(maxval(first%statev(1:3) - pt%statev(1:3)) <= 0.25_dp, &
                     'the damage bound is not what triggers')
    call assert_true(f < 1.0_dp .and. f >= 0.1_dp, '0.1 <= PNEWDT < 1')
    retry = pt
    retry%pnewdt = 1.0e36_dp
    call call_umat(retry, props, [-0.004_dp, 0.2_dp], f * dstran, 1, 1, 42)
    dth_retry = maxval(abs(retry%statev(13:15) - pt%statev(13:15)))
    write (*, '(a,f8.4,a,f8.5,a,f8.4,a)') '    angle: dtheta ', dth_first * rad_to_deg, &
      ' deg -> PNEWDT ', f, ' -> dtheta ', dth_retry * rad_to_deg, ' deg'
    call assert_true(dth_retry <= bound * (1.0_dp + 1.0e-12_dp), 'the retry meets the angle bound')
    call assert_true(dth_retry >= 0.5_dp * bound, 'the retry is not far below the bound')
    call assert_equal(1.0e36_dp, retry%pnewdt, 0.0_dp, 'the retry is accepted')
  end subroutine pnewdt_angle_bound

  !> a and b have the same bits (NaN garbage included; no comparison of a NaN, which traps in
  !> the Debug build).
  elemental logical function same_bits(a, b)
    real(dp), intent(in) :: a, b
    same_bits = transfer(a, 1_int64) == transfer(b, 1_int64)
  end function same_bits

  !> Garbage STATEV on entry (issue 10 item 5): each slot out of its range is rejected as bad
  !> input, STRESS and STATEV untouched (was: NaN or carried-on garbage with PNEWDT = 1).
  subroutine bad_statev_rejected()
    type(umat_point_t) :: pt, bad
    real(dp) :: nan, inf
    integer, parameter :: n_cases = 14
    integer, parameter :: slot(n_cases) = [1, 2, 3, 4, 7, 10, 13, 13, 15, 16, 19, 22, 22, 22]
    real(dp) :: value(n_cases), props(10)
    character(len=64) :: what
    integer :: c
    nan = ieee_value(1.0_dp, ieee_quiet_nan)
    inf = ieee_value(1.0_dp, ieee_positive_inf)
    ! damage < 0, > 1, NaN; beta < 0; slip Inf; zeta < 0; theta of plane 1 (-30 .. -7 deg)
    ! positive, and beyond -theta_0; theta of plane 3 NaN; friction traction NaN; work -Inf;
    ! the flag 0.5, 2, NaN
    value = [-0.1_dp, 1.5_dp, nan, -1.0_dp, inf, -1.0_dp, 0.1_dp, -0.6_dp, nan, nan, -inf, &
             0.5_dp, 2.0_dp, nan]
    pt = loaded_point()
    do c = 1, n_cases
      bad = pt
      bad%statev(slot(c)) = value(c)
      write (what, '(a,i0,a,a)') 'STATEV(', slot(c), ') = ', format_real(value(c))
      call expect_rejected(bad, props_wear, history_point(5), &
                           history_point(6) - history_point(5), -1.0_dp, trim(what))
    end do
    ! A pre-fractured interface has D = 1 and beta >= 1/(1 - eta).
    props(1:9) = props_wear
    props(10) = 1.0_dp
    call expect_rejected(pt, props, history_point(5), history_point(6) - history_point(5), &
                         -1.0_dp, 'pre-fractured with STATEV damage < 1')
  end subroutine bad_statev_rejected

  !> A non-finite or absurd traction on entry is rejected (it enters the work increment).
  subroutine bad_stress_rejected()
    type(umat_point_t) :: pt, bad
    real(dp) :: nan, inf
    nan = ieee_value(1.0_dp, ieee_quiet_nan)
    inf = ieee_value(1.0_dp, ieee_positive_inf)
    pt = loaded_point()
    bad = pt
    bad%stress(1) = nan
    call expect_rejected(bad, props_wear, history_point(5), history_point(6) - history_point(5), &
                         -1.0_dp, 'STRESS(1) = NaN')
    bad = pt
    bad%stress(2) = -inf
    call expect_rejected(bad, props_wear, history_point(5), history_point(6) - history_point(5), &
                         -1.0_dp, 'STRESS(2) = -Inf')
    bad = pt
    bad%stress(2) = 1.0e200_dp
    call expect_rejected(bad, props_wear, history_point(5), history_point(6) - history_point(5), &
                         -1.0_dp, 'STRESS(2) = 1e200')
  end subroutine bad_stress_rejected

  !> Separations beyond the admissible 1e6 mm are bad input (issue 10 item 6: 1e100 mm gave
  !> beta = Inf and NaN energies with PNEWDT = 0.1); 1e6 mm itself runs to a finite answer.
  subroutine separation_beyond_bound_rejected()
    type(umat_point_t) :: pt, ok_pt
    pt = loaded_point()
    call expect_rejected(pt, props_wear, [0.0_dp, 0.0_dp], [1.0e100_dp, 0.0_dp], -1.0_dp, &
                         'DSTRAN = (1e100, 0)')
    call expect_rejected(pt, props_wear, [0.0_dp, 0.0_dp], [0.0_dp, -1.0e100_dp], -1.0_dp, &
                         'DSTRAN = (0, -1e100)')
    call expect_rejected(pt, props_wear, [2.0e6_dp, 0.0_dp], [-2.0e6_dp, 0.0_dp], -1.0_dp, &
                         'STRAN = (2e6, 0)')
    ok_pt = pt
    call call_umat(ok_pt, props_wear, [0.0_dp, 0.0_dp], [1.0e6_dp, -1.0e6_dp], 1, 1, 6)
    call assert_true(ok_pt%pnewdt > 0.0_dp .and. all(abs(ok_pt%stress) <= huge(1.0_dp)) .and. &
                     all(abs(ok_pt%statev) <= huge(1.0_dp)) .and. abs(ok_pt%sse) <= huge(1.0_dp) &
                     .and. abs(ok_pt%scd) <= huge(1.0_dp), 'separation 1e6 mm: finite answer')
  end subroutine separation_beyond_bound_rejected

  !> eta, H_N, zeta_0 whose inverse would overflow (a denormal) are rejected (issue 10 item 7:
  !> zeta_0 = 1e-310 trapped in the Debug build).
  subroutine tiny_inverted_properties_rejected()
    type(umat_point_t) :: pt
    real(dp) :: props(9)
    integer :: i
    integer, parameter :: which(3) = [prop_eta, prop_h_n, prop_zeta0]
    pt = loaded_point()
    do i = 1, 3
      props = props_wear
      props(which(i)) = 1.0e-310_dp
      call expect_rejected(pt, props, history_point(5), history_point(6) - history_point(5), &
                           -1.0_dp, 'PROPS(' // format_integer(which(i)) // ') = 1e-310')
    end do
  end subroutine tiny_inverted_properties_rejected

  !> Issue 10 item 8: a pre-fractured interface keeps beta as the running maximum (SPEC 4.3).
  !> Table 1 values, theta_0 = 25 deg, H_N infinite, virgin STATEV, STRAN = 0, DSTRAN =
  !> (0.5, 0): on each plane s_k = 0.5 (cos theta_k, -sin theta_k) mm, and with s_0n = s_0t =
  !> 0.02 mm beta_k = 0.5 / 0.02 = 25 (was 1/(1 - eta) = 10); D = 1. For both schemes, with
  !> substepping (the general path) and flat (interlocking off: the inlined flat law).
  subroutine prefractured_beta_running_maximum()
    type(umat_point_t) :: pt
    real(dp) :: props(n_properties)
    integer :: variant
    character(len=40) :: what
    do variant = 1, 4
      props = properties%default
      props(1:10) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 1.0e30_dp, 25.0_dp, 25.0_dp, &
                     1.0e30_dp, 1.0_dp]
      select case (variant)
      case (2)
        props(prop_scheme) = 2.0_dp
      case (3)
        props(prop_substep_tol) = 1.0e-3_dp
      case (4)
        props(prop_effect_interlocking) = 0.0_dp
      end select
      write (what, '(a,i0)') 'pre-fractured, variant ', variant
      pt = new_point(umat_nstatv, ntens)
      call call_umat(pt, props, [0.0_dp, 0.0_dp], [0.5_dp, 0.0_dp], 1, 1, 1)
      call assert_true(pt%pnewdt > 0.0_dp, trim(what) // ': accepted')
      call assert_equal(25.0_dp, pt%statev(4), 1.0e-12_dp, trim(what) // ': beta plane 1')
      call assert_equal(25.0_dp, pt%statev(5), 1.0e-12_dp, trim(what) // ': beta plane 2')
      call assert_equal(25.0_dp, pt%statev(6), 1.0e-12_dp, trim(what) // ': beta plane 3')
      call assert_true(all(same_value(pt%statev(1:3), 1.0_dp)), trim(what) // ': D = 1')
      call assert_true(all(abs(pt%stress) <= 1.0e-12_dp), trim(what) // ': open, no traction')
    end do
  end subroutine prefractured_beta_running_maximum

end module test_umat_cases

program test_umat
  use test_umat_cases, only: collect_umat
  use interlock_assert, only: suite_summary
  implicit none
  call collect_umat()
  if (suite_summary('umat') /= 0) error stop 1
end program test_umat
