!> Work-precision in three dimensions (docs/bench.md, part 3b): what an accuracy costs on the two
!> 3D scenes of granite on the `azimuthal` RIA, N_a = 3, under sigma_N = -1.5 MPa (SPEC D8: the
!> normal traction applied first at zero slip, then the slip path at constant sigma_N, s_N by
!> Newton's method on the exact tangent at every step, from the last step's increment
!> extrapolated): 8 mm at 45 deg between t1 and t2; 8 mm along t1 and back, then along t2 and
!> back. Every scheme with uniform steps (n per segment,
!> 25 x 2^j) and with global Richardson extrapolation of the runs at n and 2n (2 u(2n) - u(n)
!> for the first-order schemes, (4 u(2n) - u(n)) / 3 for the trapezoidal one; its cost is both
!> runs'), and the trapezoidal scheme with error control (substep_tol 1e-3, 1e-4,
!> 1e-5: sub-increments where the estimate of the wear and of the turn of the friction direction
!> asks for them), against a reference of its own: the trapezoidal scheme at 8 times the finest
!> run's steps (204800 and 102400 per segment). (The first-order schemes with error control are not
!> run: where the partition into sub-increments switches, sigma_N(s_N) jumps by about the
!> tolerance, which the driver's plain Newton solve for s_N does not pass.)
!> Error: the largest over the run's steps of |sigma_T - ref| / max |sigma_T,ref| (each in-plane
!> component) and |s_N - ref| / max |s_N,ref|. For the trapezoidal scheme it also prints where
!> that largest error sits (the step and its slip along the path) and the largest error beyond
!> the first millimetre of slip: on these scenes the error of the start (the flat plane's
!> cohesive peak, the planes' switches from stick to slip and the turn of their slip direction
!> within a few friction lengths mu p / K_t) is most of it.
module interlock_bench_precision_3d
  use, intrinsic :: iso_fortran_env, only: output_unit
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_3d_t, &
      interlock_info_t, interlock_state_3d_init, interlock_update_3d, interlock_azimuthal_ria, &
      interlock_material_prepare, scheme_explicit, scheme_implicit, scheme_trapezoidal, &
      scheme_name, status_ok, message_len
  use interlock_bench_scenes, only: scene_t, make_scene, median
  implicit none
  private
  public :: precision_study_3d, precision_run_3d

  real(dp), parameter :: deg = acos(-1.0_dp) / 180.0_dp, sigma_n_target = -1.5_dp
  !> the length of every segment of both paths [mm]
  real(dp), parameter :: path_length = 8.0_dp
  integer, parameter :: n_scenes = 2, base_steps = 25
  !> the finest run and the reference, 25 x 2^j steps per segment, per scene
  integer, parameter :: j_finest(n_scenes) = [10, 9], j_reference(n_scenes) = [13, 12]
  !> the error-control tolerances, and the schemes run with them
  integer, parameter :: n_tols = 3
  real(dp), parameter :: tols(n_tols) = [1.0e-3_dp, 1.0e-4_dp, 1.0e-5_dp]
  character(len=*), parameter :: tol_names(n_tols) = ['1e-3', '1e-4', '1e-5']
  integer, parameter :: controlled(1) = [scheme_trapezoidal]
  !> configurations: the schemes uniform (1-3), with Richardson (4-6), then error control
  integer, parameter :: n_configs = 6 + size(controlled) * n_tols
  !> the target's ratio: the median of this many paired timings (paired_ratio)
  integer, parameter :: paired_repetitions = 9

contains

  !> Runs the study; writes its rows to the open CSV unit `u` (header written by the caller's
  !> open) and prints the CPU time each configuration needs for 1e-3, 1e-4 and 1e-6, and whether
  !> the trapezoidal scheme (its cheapest configuration without extrapolation) reaches 1e-4 on
  !> the 45-deg scene at >= 20x less CPU than the explicit one (met or MISSED; the uniform
  !> steps' ratio printed too). ok: every run succeeded.
  subroutine precision_study_3d(u, quick, ok)
    integer, intent(in) :: u
    logical, intent(in) :: quick
    logical, intent(out) :: ok
    character(len=*), parameter :: scene_names(n_scenes) = [character(len=22) :: &
      'granite_3d_45deg', 'granite_3d_t1_t2_back']
    real(dp), parameter :: targets(3) = [1.0e-3_dp, 1.0e-4_dp, 1.0e-6_dp]
    integer :: is, scheme, j, jmax, n, n_ref, n_seg, c, it, ic
    real(dp), allocatable :: ref(:, :), run_n(:, :), run_2n(:, :), rich(:, :)
    real(dp) :: err(0:10, n_configs), cpu(0:10, n_configs), t_run(0:11), cost(3), ratio, &
                err_late(0:10), best_trapezoidal, cost_c, paired(3)
    integer :: at(0:10), c_best
    logical :: run_ok, extra(3)
    character(len=28) :: labels(n_configs)

    ok = .true.
    write (output_unit, '(/,a)') '== Work-precision in 3D: granite, azimuthal N_a = 3, ' // &
      'sigma_N = -1.5 MPa; error = max over the run of |sigma_T - ref| / max|sigma_T,ref| ' // &
      'and |s_N - ref| / max|s_N,ref|; reference: the trapezoidal scheme at 8 times the ' // &
      'finest run''s steps'
    do is = 1, n_scenes
      jmax = merge(2, j_finest(is), quick)
      n_ref = base_steps * 2**merge(5, j_reference(is), quick)
      n_seg = merge(1, 4, is == 1)
      allocate (ref(3, 0:n_seg * n_ref))
      call run_path(is, scheme_trapezoidal, 0.0_dp, n_ref, ref, run_ok)
      if (.not. run_ok) then
        ok = .false.
        write (output_unit, '(a)') '  the reference run failed'
        deallocate (ref)
        cycle
      end if
      do scheme = 1, 3
        labels(scheme) = scheme_name(scheme)
        labels(3 + scheme) = trim(scheme_name(scheme)) // ' Richardson'
        allocate (run_n(3, 0:n_seg * base_steps))
        call timed(is, scheme, 0.0_dp, base_steps, run_n, run_ok, t_run(0))
        ok = ok .and. run_ok
        call error_profile(run_n, ref, base_steps, n_ref, n_seg, err(0, scheme), at(0), &
                           err_late(0))
        cpu(0, scheme) = t_run(0)
        do j = 1, jmax + 1
          n = base_steps * 2**j
          allocate (run_2n(3, 0:n_seg * n), rich(3, 0:n_seg * n / 2))
          call timed(is, scheme, 0.0_dp, n, run_2n, run_ok, t_run(j))
          ok = ok .and. run_ok
          if (j <= jmax) then
            call error_profile(run_2n, ref, n, n_ref, n_seg, err(j, scheme), at(j), &
                               err_late(j))
            cpu(j, scheme) = t_run(j)
          end if
          ! Richardson of the runs at n/2 and n, on the n/2 grid
          if (scheme == scheme_trapezoidal) then
            rich = (4.0_dp * run_2n(:, 0:n_seg * n:2) - run_n) / 3.0_dp
          else
            rich = 2.0_dp * run_2n(:, 0:n_seg * n:2) - run_n
          end if
          err(j - 1, 3 + scheme) = run_error(rich, ref, n / 2, n_ref, n_seg)
          cpu(j - 1, 3 + scheme) = t_run(j - 1) + t_run(j)
          deallocate (rich)
          call move_alloc(run_2n, run_n)
        end do
        deallocate (run_n)
        if (scheme == scheme_trapezoidal) then
          write (output_unit, '(/,2x,a,a)') trim(scene_names(is)), ', trapezoidal: where ' // &
            'the largest error sits (step, slip along the path), the largest beyond 1 mm of slip'
          do j = 0, jmax
            n = base_steps * 2**j
            write (output_unit, '(4x,a,i6,a,es9.2,a,i6,a,f8.4,a,es9.2)') 'n =', n, ': ', &
              err(j, scheme), ' at step', at(j), ' (', &
              path_length * real(at(j), dp) / real(n, dp), ' mm); beyond 1 mm', err_late(j)
          end do
        end if
      end do
      c = 6
      do ic = 1, size(controlled)
        do it = 1, n_tols
          c = c + 1
          labels(c) = trim(scheme_name(controlled(ic))) // ' substep ' // tol_names(it)
          do j = 0, jmax
            n = base_steps * 2**j
            allocate (run_n(3, 0:n_seg * n))
            call timed(is, controlled(ic), tols(it), n, run_n, run_ok, cpu(j, c))
            ok = ok .and. run_ok
            err(j, c) = run_error(run_n, ref, n, n_ref, n_seg)
            deallocate (run_n)
          end do
        end do
      end do
      write (output_unit, '(/,2x,a,a)') trim(scene_names(is)), &
        ': CPU seconds to reach a relative error of 1e-3, 1e-4, 1e-6 (* extrapolated)'
      do c = 1, n_configs
        do j = 0, jmax
          write (u, '(a,",",a,",",i0,",",es12.5,",",es12.5)') trim(scene_names(is)), &
            trim(labels(c)), base_steps * 2**j, cpu(j, c), err(j, c)
        end do
        do j = 1, 3
          cost(j) = cost_to_reach(err(0:jmax, c), cpu(0:jmax, c), targets(j), extra(j))
        end do
        write (output_unit, '(4x,a28,3a12,a,es9.2,a,i0,a)') labels(c), &
          (fmt_cost(cost(j), extra(j)), j = 1, 3), '   (error ', err(jmax, c), ' at ', &
          base_steps * 2**jmax, ' steps per segment)'
      end do
      if (is == 1 .and. .not. quick) then
        ! the explicit scheme's only configuration without extrapolation: uniform steps
        best_trapezoidal = cost_to_reach(err(0:jmax, 3), cpu(0:jmax, 3), 1.0e-4_dp, extra(2))
        ratio = cost_to_reach(err(0:jmax, 1), cpu(0:jmax, 1), 1.0e-4_dp, extra(1))
        write (output_unit, '(2x,a,f8.1,a)') 'uniform steps: the trapezoidal scheme reaches ' // &
          '1e-4 at', ratio / best_trapezoidal, 'x less CPU than the explicit one'
        c_best = 3
        do c = 7, n_configs
          if (index(labels(c), trim(scheme_name(scheme_trapezoidal))) /= 1) cycle
          cost_c = cost_to_reach(err(0:jmax, c), cpu(0:jmax, c), 1.0e-4_dp, extra(2))
          if (cost_c < best_trapezoidal) then
            best_trapezoidal = cost_c
            c_best = c
          end if
        end do
        ratio = ratio / best_trapezoidal
        ! The sweep times each configuration minutes apart from the other; the target's ratio
        ! from the runs it rests on timed again in turn (paired_ratio)
        call paired_ratio(is, err(0:jmax, 1), cpu(0:jmax, 1), scheme_explicit, 0.0_dp, &
                          err(0:jmax, c_best), cpu(0:jmax, c_best), scheme_trapezoidal, &
                          config_tol(c_best), 1.0e-4_dp, paired, run_ok)
        ok = ok .and. run_ok
        write (output_unit, '(2x,a,a,a,f8.1,a)') 'the cheapest trapezoidal configuration: ', &
          trim(labels(c_best)), '; from the sweep''s timings', ratio, 'x'
        write (output_unit, '(2x,a,i0,a,f8.1,a,f6.1,a,f6.1,a,a)') 'target: the trapezoidal ' // &
          'scheme (uniform or with error control) reaches 1e-4 at >= 20x less CPU than the ' // &
          'explicit one (median of ', paired_repetitions, ' paired timings): ', paired(2), &
          'x (', paired(1), '-', paired(3), '): ', &
          trim(merge('met   ', 'MISSED', paired(2) >= 20.0_dp))
      end if
      write (output_unit, '(2x,a)') '(* extrapolated beyond the finest run with the order ' // &
        'observed between its two finest step counts)'
      deallocate (ref)
    end do
  end subroutine precision_study_3d

  !> One run of the 45-deg scene at n steps (tol: the substepping tolerance, 0 for none), for a
  !> profiler (callgrind's --toggle-collect on run_path): prints the end point (s_N, sigma_T1,
  !> sigma_T2). ok: the run succeeded.
  subroutine precision_run_3d(scheme, tol, n, ok)
    integer, intent(in) :: scheme, n
    real(dp), intent(in) :: tol
    logical, intent(out) :: ok
    real(dp), allocatable :: q(:, :)
    allocate (q(3, 0:n))
    call run_path(1, scheme, tol, n, q, ok)
    write (output_unit, '(a,3es25.16)') 'granite_3d_45deg, end point (s_N, sigma_T1, sigma_T2):', &
      q(:, n)
  end subroutine precision_run_3d

  !> The run at n steps per segment, repeated until it has taken 0.05 s; cpu: seconds per run.
  subroutine timed(is, scheme, tol, n, q, ok, cpu)
    integer, intent(in) :: is, scheme, n
    real(dp), intent(in) :: tol
    real(dp), intent(out) :: q(:, 0:)
    logical, intent(out) :: ok
    real(dp), intent(out) :: cpu
    real(dp) :: t0, t1
    integer :: reps
    reps = 0
    call cpu_time(t0)
    do
      call run_path(is, scheme, tol, n, q, ok)
      reps = reps + 1
      call cpu_time(t1)
      if (.not. ok .or. t1 - t0 >= 0.05_dp) exit
    end do
    cpu = (t1 - t0) / reps
  end subroutine timed

  !> Scene is in n steps per segment (tol: the substepping tolerance, 0 for none): q(:, i) =
  !> (s_N, sigma_T1, sigma_T2) after step i (0: the preload).
  subroutine run_path(is, scheme, tol, n, q, ok)
    integer, intent(in) :: is, scheme, n
    real(dp), intent(in) :: tol
    real(dp), intent(out) :: q(:, 0:)
    logical, intent(out) :: ok
    type(interlock_material_t) :: mat
    type(scene_t) :: sc
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old, new
    real(dp) :: corners(2, 5), t(2), sigma(3), tangent(3, 3), s_n, s_n_prev
    integer :: j, i, n_seg, stat
    character(len=message_len) :: msg
    ! the 2D work-precision's granite (interlock_bench_scenes) on the azimuthal RIA
    call make_scene('granite', sc, stat, msg)
    ok = stat == status_ok
    if (.not. ok) return
    mat = sc%mat
    call interlock_azimuthal_ria(mat, 3, 30.0_dp * deg, 9.0_dp * deg, 6.666_dp)
    call interlock_material_prepare(mat, stat, msg)
    ok = stat == status_ok
    if (.not. ok) return
    solver%scheme = scheme
    solver%substep_tol = tol
    call interlock_state_3d_init(mat, old)
    if (is == 1) then
      n_seg = 1
      corners(:, 1:2) = reshape([0.0_dp, 0.0_dp, 4.0_dp * sqrt(2.0_dp), 4.0_dp * sqrt(2.0_dp)], &
                                [2, 2])
    else
      n_seg = 4
      corners = reshape([0.0_dp, 0.0_dp, 8.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 8.0_dp, &
                         0.0_dp, 0.0_dp], [2, 5])
    end if
    call solve_normal(mat, solver, old, [0.0_dp, 0.0_dp], old%s(1), new, sigma, tangent, ok)
    if (.not. ok) return
    old = new
    q(:, 0) = [old%s(1), sigma(2), sigma(3)]
    s_n_prev = old%s(1)
    do j = 1, n_seg
      do i = 1, n
        t = corners(:, j) + (corners(:, j + 1) - corners(:, j)) * (real(i, dp) / real(n, dp))
        ! The first iterate of s_N: the last step's increment repeated (as FE codes extrapolate
        ! the last increment); on a segment's first step, whose direction is new, the start's
        ! s_N moved along the last step's tangent at constant sigma_N.
        if (i > 1) then
          s_n = 2.0_dp * old%s(1) - s_n_prev
        else if (tangent(1, 1) > 0.0_dp) then
          s_n = old%s(1) - (tangent(1, 2) * (t(1) - old%s(2)) + &
                            tangent(1, 3) * (t(2) - old%s_t2)) / tangent(1, 1)
        else
          s_n = old%s(1)
        end if
        s_n_prev = old%s(1)
        call solve_normal(mat, solver, old, t, s_n, new, sigma, tangent, ok)
        if (.not. ok) return
        old = new
        q(:, (j - 1) * n + i) = [old%s(1), sigma(2), sigma(3)]
      end do
    end do
  end subroutine run_path

  !> s_N with sigma_N(s_N, s_T) = -1.5 MPa from the first iterate s_n by Newton's method on the
  !> tangent, to 1e-12 (`tangent`: the last iterate's); with error control, where sigma_N(s_N) jumps by about the tolerance (the partition
  !> into sub-increments switches) and the iteration cycles, the last iterate within the
  !> tolerance is taken.
  subroutine solve_normal(mat, solver, old, s_t, s_n, new, sigma, tangent, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s_t(2)
    real(dp), intent(in) :: s_n   !< the first iterate
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    logical, intent(out) :: ok
    type(interlock_info_t) :: info
    real(dp) :: s(3)
    integer :: it
    s = [s_n, s_t(1), s_t(2)]
    ok = .false.
    do it = 1, 60
      call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
      if (info%status /= status_ok) return
      if (abs(sigma(1) - sigma_n_target) <= 1.0e-12_dp * abs(sigma_n_target)) then
        ok = .true.
        return
      end if
      if (.not. (tangent(1, 1) > 0.0_dp)) return
      s(1) = s(1) - (sigma(1) - sigma_n_target) / tangent(1, 1)
    end do
    ok = abs(sigma(1) - sigma_n_target) <= solver%substep_tol * abs(sigma_n_target)
  end subroutine solve_normal

  !> The error of a run at n steps per segment against the reference at n_ref.
  pure real(dp) function run_error(q, ref, n, n_ref, n_seg) result(e)
    real(dp), intent(in) :: q(:, 0:), ref(:, 0:)
    integer, intent(in) :: n, n_ref, n_seg
    integer :: at
    real(dp) :: e_late
    call error_profile(q, ref, n, n_ref, n_seg, e, at, e_late)
  end function run_error

  !> run_error, the step `at` where it sits and the largest error beyond the first millimetre
  !> of slip along the path (e_late).
  pure subroutine error_profile(q, ref, n, n_ref, n_seg, e, at, e_late)
    real(dp), intent(in) :: q(:, 0:), ref(:, 0:)
    integer, intent(in) :: n, n_ref, n_seg
    real(dp), intent(out) :: e, e_late
    integer, intent(out) :: at
    real(dp) :: scale_t, scale_n, e_i
    integer :: i, stride
    stride = n_ref / n
    scale_n = maxval(abs(ref(1, :)))
    scale_t = maxval(abs(ref(2:3, :)))
    e = 0.0_dp
    e_late = 0.0_dp
    at = 0
    do i = 0, n_seg * n
      e_i = max(abs(q(1, i) - ref(1, i * stride)) / scale_n, &
                maxval(abs(q(2:3, i) - ref(2:3, i * stride))) / scale_t)
      if (e_i > e) then
        e = e_i
        at = i
      end if
      if (path_length * real(i, dp) > real(n, dp)) e_late = max(e_late, e_i)
    end do
  end subroutine error_profile

  !> CPU time to reach `target`: log-log interpolation between the two levels that bracket it
  !> where the runs stay below it from the finer one on; beyond the finest run, extrapolated
  !> with the order observed between the two finest levels and a cost proportional to the
  !> steps (`extrapolated`); huge where the errors do not fall there.
  real(dp) function cost_to_reach(err, cpu, target, extrapolated) result(t)
    real(dp), intent(in) :: err(0:), cpu(0:), target
    logical, intent(out) :: extrapolated
    integer :: lo, hi
    real(dp) :: a, factor
    call reach_weights(err, target, lo, hi, a, factor, extrapolated)
    t = huge(1.0_dp)
    if (lo >= 0) t = cost_from_levels(cpu, lo, hi, a, factor)
  end function cost_to_reach

  !> The CPU time to reach a target from the levels' times cpu and reach_weights' lo, hi, a and
  !> factor: factor cpu(lo)^(1 - a) cpu(hi)^a.
  pure real(dp) function cost_from_levels(cpu, lo, hi, a, factor) result(t)
    real(dp), intent(in) :: cpu(0:), a, factor
    integer, intent(in) :: lo, hi
    t = factor * exp(log(cpu(lo)) + a * log(cpu(hi) / cpu(lo)))
  end function cost_from_levels

  !> How cost_to_reach forms the CPU time to reach `target` from the levels' times: t = factor
  !> cpu(lo)^(1 - a) cpu(hi)^a (lo < 0: not reached).
  pure subroutine reach_weights(err, target, lo, hi, a, factor, extrapolated)
    real(dp), intent(in) :: err(0:), target
    integer, intent(out) :: lo, hi
    real(dp), intent(out) :: a, factor
    logical, intent(out) :: extrapolated
    integer :: j, jm, first
    real(dp) :: order
    lo = -1
    hi = -1
    a = 0.0_dp
    factor = 1.0_dp
    extrapolated = .false.
    jm = ubound(err, 1)
    first = -1
    do j = jm, 0, -1
      if (.not. err(j) <= target) exit
      first = j
    end do
    if (first < 0) then
      if (jm < 1 .or. .not. (err(jm) < err(jm - 1) .and. err(jm) > 0.0_dp)) return
      order = log(err(jm - 1) / err(jm)) / log(2.0_dp)
      lo = jm
      hi = jm
      factor = (err(jm) / target)**(1.0_dp / order)
      extrapolated = .true.
    else if (first == 0) then
      lo = 0
      hi = 0
    else
      lo = first - 1
      hi = first
      a = log(err(first - 1) / target) / log(err(first - 1) / err(first))
    end if
  end subroutine reach_weights

  !> The ratio of the CPU times two configurations (scheme, substepping tolerance; their errors
  !> and times per level from the sweep) take to reach `target`, from the levels that
  !> cost_to_reach reads, timed again in turn (the first's, then the second's, the order
  !> alternating) paired_repetitions times: ratio = (smallest, median, largest) of the
  !> repetitions' ratios, each from runs timed within a fraction of a second of each other, so
  !> that a change in the machine's speed between the sweep's configurations cancels. ok: every
  !> run succeeded (ratio 0 where a configuration does not reach the target).
  subroutine paired_ratio(is, err_1, cpu_1, scheme_1, tol_1, err_2, cpu_2, scheme_2, tol_2, &
                          target, ratio, ok)
    integer, intent(in) :: is, scheme_1, scheme_2
    real(dp), intent(in) :: err_1(0:), cpu_1(0:), tol_1, err_2(0:), cpu_2(0:), tol_2, target
    real(dp), intent(out) :: ratio(3)
    logical, intent(out) :: ok
    integer :: lo(2), hi(2), scheme(2), r, n_seg, i, j, w
    real(dp) :: a(2), factor(2), tol(2), cpu(0:ubound(err_1, 1), 2), ratios(paired_repetitions)
    real(dp), allocatable :: q(:, :)
    logical :: extrapolated, run_ok
    ok = .true.
    scheme = [scheme_1, scheme_2]
    tol = [tol_1, tol_2]
    ratio = 0.0_dp
    call reach_weights(err_1, target, lo(1), hi(1), a(1), factor(1), extrapolated)
    call reach_weights(err_2, target, lo(2), hi(2), a(2), factor(2), extrapolated)
    if (lo(1) < 0 .or. lo(2) < 0) return
    cpu(:, 1) = cpu_1
    cpu(:, 2) = cpu_2
    n_seg = merge(1, 4, is == 1)
    do r = 1, paired_repetitions
      do i = 1, 2
        w = merge(i, 3 - i, mod(r, 2) == 1)
        do j = lo(w), hi(w)
          allocate (q(3, 0:n_seg * base_steps * 2**j))
          call timed(is, scheme(w), tol(w), base_steps * 2**j, q, run_ok, cpu(j, w))
          ok = ok .and. run_ok
          deallocate (q)
        end do
      end do
      ratios(r) = cost_from_levels(cpu(:, 1), lo(1), hi(1), a(1), factor(1)) / &
                  cost_from_levels(cpu(:, 2), lo(2), hi(2), a(2), factor(2))
    end do
    ratio = [minval(ratios), median(ratios), maxval(ratios)]
  end subroutine paired_ratio

  !> The substepping tolerance of configuration c (0: none).
  pure real(dp) function config_tol(c) result(tol)
    integer, intent(in) :: c
    tol = 0.0_dp
    if (c > 6) tol = tols(mod(c - 7, n_tols) + 1)
  end function config_tol

  !> A CPU time, '*' when extrapolated beyond the finest run, '-' when not reached.
  pure function fmt_cost(t, extrapolated) result(s)
    real(dp), intent(in) :: t
    logical, intent(in) :: extrapolated
    character(len=12) :: s
    if (t >= huge(1.0_dp)) then
      s = '           -'
    else
      write (s, '(es11.2,a1)') t, merge('*', ' ', extrapolated)
    end if
  end function fmt_cost

end module interlock_bench_precision_3d
