!> The stability matrix (hard cases stay numerically stable): a covering design over
!> the material factors (every pair of levels, plus every one-factor extreme around a Table 1
!> baseline), crossed with every loading and every scheme. Each cell must end 'completed' with
!> finite, bounded outputs or with a stated, legitimate failure reason; never NaN/Inf, never an
!> unbounded iteration count. `--doc FILE` also writes the summary table (docs/stability.md);
!> `--verbose` prints the cells that ended with a stated reason too.
module test_stability_matrix_suite
  use, intrinsic :: iso_fortran_env, only: output_unit
  use interlock
  use interlock_material, only: n_schemes, scheme_names, scheme_list
  use interlock_assert
  use test_stability_tools
  implicit none
  private
  public :: collect_stability_matrix, doc_path, verbose

  integer, parameter :: n_factors = 9, max_levels = 6
  integer, parameter :: f_hn = 1, f_eta = 2, f_scale = 3, f_theta0 = 4, f_thetaf = 5, &
                        f_zeta0 = 6, f_mu = 7, f_pre = 8, f_ria = 9
  integer, parameter :: n_levels(n_factors) = [6, 5, 4, 5, 3, 4, 3, 2, 3]
  character(len=22), parameter :: factor_names(n_factors) = [character(len=22) :: &
    'H_N [mm]', 'eta', 'sigma0, Gc_bar scale', 'theta_0 [deg]', 'theta_f / theta_0', &
    'zeta_0 [N/mm]', 'mu', 'pre-fractured', 'RIA']
  real(dp), parameter :: inf = huge(1.0_dp)
  !> level values (unused slots 0); H_N and zeta_0 use huge() for +infinity
  real(dp), parameter :: level_values(max_levels, n_factors) = reshape([ &
    1.0e-6_dp, 1.0e-3_dp, 1.0e-2_dp, 1.0_dp, 1.0e3_dp, inf, &
    0.5_dp, 0.9_dp, 0.99_dp, 0.999_dp, 0.99999_dp, 0.0_dp, &
    1.0e-6_dp, 1.0e-3_dp, 1.0_dp, 1.0e3_dp, 0.0_dp, 0.0_dp, &
    0.0_dp, 1.0e-8_dp, 5.0_dp, 45.0_dp, 70.0_dp, 0.0_dp, &
    1.0_dp, 0.5_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
    1.0e-6_dp, 1.0_dp, 1.0e6_dp, inf, 0.0_dp, 0.0_dp, &
    0.0_dp, 0.5_dp, 2.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
    0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
    1.0_dp, 2.0_dp, 3.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], [max_levels, n_factors])
  character(len=12), parameter :: ria_names(3) = [character(len=12) :: &
    'paper 3', 'single', 'general 4']
  !> Table 1 baseline: H_N = 1 mm, eta = 0.9, scale 1, theta_0 = 45 deg, no wear, mu = 0.5.
  integer, parameter :: baseline(n_factors) = [4, 2, 3, 4, 1, 4, 2, 1, 1]

  !> The columns: every scheme of the library (interlock_material:scheme_names, so that a new
  !> scheme is run by itself), each without and with substepping.
  integer, parameter :: n_columns = 2 * n_schemes, n_loadings = 6
  character(len=24), parameter :: loading_names(n_loadings) = [character(len=24) :: &
    'monotonic slip, sigma_N', 'cyclic slip, sigma_N', 'open past H_N, re-close', &
    'pure opening', 'whole history, 1 step', 'steps of 1e-9 mm']
  real(dp), parameter :: substep_tol = 1.0e-4_dp

  !> One step of a loading: mixed (a = sigma_N target [MPa], b = s_T) or separation (a, b = s).
  type :: step_t
    logical :: mixed
    real(dp) :: a, b
  end type step_t

  !> Outcome of one cell: 0 completed, 1 failed with a legitimate stated reason, 2 defect.
  type :: cell_t
    integer :: row, loading, scheme, outcome = 0, reason = 0
    integer :: newton = 0, mixed_it = 0, attempts = 0, updates = 0
  end type cell_t

  integer, parameter :: max_reasons = 40
  character(len=200) :: reasons(max_reasons) = ''
  logical :: reason_legit(max_reasons) = .false.
  integer :: n_reasons = 0

  integer, allocatable :: design(:, :)
  integer :: n_pairwise = 0
  type(cell_t), allocatable :: cells(:)
  character(len=256) :: doc_path = ''
  logical :: verbose = .false.   !< --verbose: print the cells with stated failures too

contains

  subroutine collect_stability_matrix()
    call run_case('covering_design', test_covering_design)
    call run_case('mixed_control_closed_form', test_mixed_control_closed_form)
    call run_case('stability_matrix', test_stability_matrix)
  end subroutine collect_stability_matrix

  ! ---------------------------------------------------------------- the design

  !> Greedy pairwise covering design (AETG-like, deterministic seed), then the baseline and
  !> every one-factor extreme (each factor at its first and last level, others at baseline).
  subroutine build_design()
    logical :: covered(max_levels, n_factors, max_levels, n_factors)
    integer :: rows(n_factors, 400), cand(n_factors), best(n_factors), order(n_factors)
    integer :: n, f, g, i, j, l, gain, best_gain, pick, count_unc, tries, score, best_score, tmp
    type(rng_t) :: rng
    logical :: dup

    call rng_seed(rng, 2024)
    covered = .false.
    do f = 1, n_factors
      do l = 1, max_levels
        do g = 1, n_factors
          do j = 1, max_levels
            if (f == g .or. l > n_levels(f) .or. j > n_levels(g)) covered(l, f, j, g) = .true.
          end do
        end do
      end do
    end do
    n = 0
    do
      count_unc = count(.not. covered)
      if (count_unc == 0) exit
      best_gain = -1
      do tries = 1, 40
        ! seed the row with a random uncovered pair
        pick = rng_int(rng, 1, count_unc)
        cand = 0
        i = 0
        outer: do f = 1, n_factors
          do l = 1, n_levels(f)
            do g = 1, n_factors
              do j = 1, n_levels(g)
                if (.not. covered(l, f, j, g)) then
                  i = i + 1
                  if (i == pick) then
                    cand(f) = l
                    cand(g) = j
                    exit outer
                  end if
                end if
              end do
            end do
          end do
        end do outer
        order = [(f, f = 1, n_factors)]
        do f = n_factors, 2, -1
          g = rng_int(rng, 1, f)
          tmp = order(f); order(f) = order(g); order(g) = tmp
        end do
        do i = 1, n_factors
          f = order(i)
          if (cand(f) /= 0) cycle
          best_score = -1
          do l = 1, n_levels(f)
            score = 0
            do g = 1, n_factors
              if (cand(g) /= 0) then
                if (.not. covered(l, f, cand(g), g)) score = score + 1
              end if
            end do
            score = 2 * score
            if (rng_uniform(rng) < 0.5_dp) score = score + 1
            if (score > best_score) then
              best_score = score
              cand(f) = l
            end if
          end do
        end do
        gain = 0
        do f = 1, n_factors
          do g = f + 1, n_factors
            if (.not. covered(cand(f), f, cand(g), g)) gain = gain + 1
          end do
        end do
        if (gain > best_gain) then
          best_gain = gain
          best = cand
        end if
      end do
      n = n + 1
      rows(:, n) = best
      do f = 1, n_factors
        do g = 1, n_factors
          covered(best(f), f, best(g), g) = .true.
        end do
      end do
    end do
    n_pairwise = n
    ! baseline and one-factor extremes
    do i = 0, 2 * n_factors
      cand = baseline
      if (i > 0) then
        f = (i + 1) / 2
        cand(f) = merge(1, n_levels(f), mod(i, 2) == 1)
      end if
      dup = .false.
      do j = n_pairwise + 1, n
        if (all(rows(:, j) == cand)) dup = .true.
      end do
      if (.not. dup) then
        n = n + 1
        rows(:, n) = cand
      end if
    end do
    design = rows(:, 1:n)
  end subroutine build_design

  subroutine test_covering_design()
    integer :: f, g, l, j, i
    logical :: found
    integer :: missing
    call build_design()
    write (output_unit, '(a,i0,a,i0,a)') '  design: ', n_pairwise, ' pairwise rows + ', &
      size(design, 2) - n_pairwise, ' one-factor extremes (incl. baseline)'
    missing = 0
    do f = 1, n_factors
      do g = f + 1, n_factors
        do l = 1, n_levels(f)
          do j = 1, n_levels(g)
            found = .false.
            do i = 1, n_pairwise
              if (design(f, i) == l .and. design(g, i) == j) found = .true.
            end do
            if (.not. found) missing = missing + 1
          end do
        end do
      end do
    end do
    call assert_equal(0, missing, 'pairs of levels not covered by the pairwise rows')
    do f = 1, n_factors
      do l = 1, 2
        found = .false.
        do i = 1, size(design, 2)
          if (design(f, i) == merge(1, n_levels(f), l == 1) .and. &
              count(design(:, i) /= baseline) == 1) found = .true.
        end do
        call assert_true(found, 'one-factor extreme of ' // trim(factor_names(f)))
      end do
    end do
    call assert_true(size(design, 2) < 80, 'the design stays small (< 80 rows)')
  end subroutine test_covering_design

  ! ---------------------------------------------------------------- material, loading

  subroutine make_material(row, mat, ok, message)
    integer, intent(in) :: row(n_factors)
    type(interlock_material_t), intent(out) :: mat
    logical, intent(out) :: ok
    character(len=*), intent(out) :: message
    real(dp) :: scale, th0, thf, z0
    integer :: stat
    scale = level_values(row(f_scale), f_scale)
    mat%sigma0_n = 3.0_dp * scale
    mat%sigma0_t = 3.0_dp * scale
    mat%gc = 0.3_dp * scale
    mat%eta = level_values(row(f_eta), f_eta)
    mat%mu = level_values(row(f_mu), f_mu)
    mat%h_n = level_values(row(f_hn), f_hn)
    mat%prefractured = row(f_pre) == 2
    th0 = level_values(row(f_theta0), f_theta0) * deg_to_rad
    thf = level_values(row(f_thetaf), f_thetaf) * th0
    z0 = level_values(row(f_zeta0), f_zeta0)
    select case (row(f_ria))
    case (1)
      call interlock_paper_ria(mat, th0, thf, z0)
    case (2)
      call interlock_general_ria(mat, 1, [1.0_dp], [th0], [thf], [z0])
    case default
      mat%n_planes = 4
      mat%phi(1:4) = 0.0_dp
      mat%gamma_hat(1:4) = [0.1_dp, 0.2_dp, 0.3_dp, 0.4_dp]
      mat%theta0(1:4) = th0 * [-1.0_dp, -0.3_dp, 0.6_dp, 1.0_dp]
      mat%thetaf(1:4) = thf * [-1.0_dp, -0.3_dp, 0.6_dp, 1.0_dp]
      if (is_infinite_value(z0)) then
        mat%zeta0(1:4) = inf
      else
        mat%zeta0(1:4) = z0 * [1.0_dp, 2.0_dp, 0.5_dp, 1.0_dp]
      end if
    end select
    call interlock_material_prepare(mat, stat, message)
    ok = stat == status_ok
  end subroutine make_material

  !> The steps of loading `il` for the material (lengths from s_c, pressure sigma0_n / 15 as
  !> Table 1's 0.2 MPa for 3 MPa).
  subroutine make_loading(il, mat, steps)
    integer, intent(in) :: il
    type(interlock_material_t), intent(in) :: mat
    type(step_t), allocatable, intent(out) :: steps(:)
    real(dp) :: p, l, s_open, pts(6), s_peak
    integer :: i, j, n
    p = -mat%sigma0_n / 15.0_dp
    l = mat%sct
    allocate (steps(0))
    select case (il)
    case (1)   ! preload in one step, then monotonic slip to 3 s_c
      steps = [step_t(.true., p, 0.0_dp)]
      n = 60
      steps = [steps, (step_t(.true., p, 3.0_dp * l * i / n), i = 1, n)]
    case (2)   ! cyclic slip with reversals
      steps = [step_t(.true., p, 0.0_dp)]
      pts = [0.0_dp, 1.5_dp, -1.5_dp, 1.0_dp, -0.5_dp, 0.5_dp] * l
      n = 25
      do j = 2, size(pts)
        steps = [steps, (step_t(.true., p, pts(j - 1) + (pts(j) - pts(j - 1)) * i / n), i = 1, n)]
      end do
    case (3)   ! open past H_N with slip, re-close, compress, slip
      if (mat%use_depth) then
        s_open = 1.5_dp * mat%h_n
      else
        s_open = 3.0_dp * mat%scn
      end if
      n = 20
      steps = [(step_t(.false., s_open * i / n, 0.5_dp * l * i / n), i = 1, n)]
      steps = [steps, (step_t(.false., s_open * (n - i) / n, 0.5_dp * l), i = 1, n)]
      steps = [steps, step_t(.true., p, 0.5_dp * l)]
      steps = [steps, (step_t(.true., p, 0.5_dp * l + l * i / n), i = 1, n)]
    case (4)   ! pure opening with an unloading
      n = 30
      steps = [(step_t(.false., 1.5_dp * mat%scn * i / n, 0.0_dp), i = 1, n)]
      steps = [steps, (step_t(.false., 1.5_dp * mat%scn * (n - i) / n, 0.0_dp), i = 1, n)]
      steps = [steps, (step_t(.false., 3.0_dp * mat%scn * i / n, 0.0_dp), i = 1, n)]
    case (5)   ! the whole monotonic history in one step
      steps = [step_t(.true., p, 3.0_dp * l)]
    case default   ! steps of 1e-9 mm around the peak, forward then back
      s_peak = mat%s0t
      steps = [step_t(.true., p, 0.0_dp)]
      n = 10
      steps = [steps, (step_t(.true., p, s_peak * i / n), i = 1, n)]
      steps = [steps, (step_t(.true., p, s_peak + 1.0e-9_dp * i), i = 1, 150)]
      steps = [steps, (step_t(.true., p, s_peak + 1.0e-9_dp * (150 - i)), i = 1, 75)]
    end select
  end subroutine make_loading

  !> Column `column`: scheme (column + 1) / 2, with substepping in the even columns.
  subroutine make_solver(column, solver)
    integer, intent(in) :: column
    type(interlock_solver_t), intent(out) :: solver
    solver%scheme = (column + 1) / 2
    solver%substep_tol = merge(substep_tol, 0.0_dp, mod(column, 2) == 0)
  end subroutine make_solver

  !> The label of column `column`: the scheme's name, '+sub' with substepping.
  function column_label(column) result(label)
    integer, intent(in) :: column
    character(len=:), allocatable :: label
    label = trim(scheme_names((column + 1) / 2))
    if (mod(column, 2) == 0) label = label // '+sub'
  end function column_label

  !> Index of a failure reason (numbers stripped so that reasons group), added when new.
  integer function reason_index(text, legit) result(idx)
    character(len=*), intent(in) :: text
    logical, intent(in) :: legit
    character(len=200) :: key
    integer :: i
    key = ''
    do i = 1, min(len_trim(text), 200)
      if (index('0123456789', text(i:i)) > 0) then
        key(i:i) = '#'
      else
        key(i:i) = text(i:i)
      end if
    end do
    ! the numbers of a message do not make a different reason
    i = index(key, ' (theta jumps')
    if (i > 0) key(i:) = ': theta and sigma_N jump between adjacent s_N'
    i = index(key, ' between s_N')
    if (i > 0) key(i:) = ' with no change of theta (substep partition switch)'
    do i = 2, len_trim(key) - 1
      if ((key(i:i) == '-' .or. key(i:i) == '+') .and. &
          (key(i + 1:i + 1) == '#' .and. index('E (', key(i - 1:i - 1)) > 0)) key(i:i) = '~'
    end do
    do idx = 1, n_reasons
      if (reasons(idx) == key) return
    end do
    if (n_reasons < max_reasons) n_reasons = n_reasons + 1
    idx = n_reasons
    reasons(idx) = key
    reason_legit(idx) = legit
  end function reason_index

  !> A failure is legitimate when it states a physical impossibility of the prescribed loading
  !> (compression asked of a separated interface), a response that is discontinuous in s_N
  !> (a branch switch of the implicit wear equation, or a change of the sub-increment
  !> partition of error-controlled substepping: no s_N carries the target), or an explicit
  !> wear update whose derivative grows without bound on tiny sub-increments (the core says
  !> so and names the remedy). NaN/Inf, a violated invariant or an unexplained
  !> non-convergence are defects.
  logical function is_legitimate(stat, text)
    integer, intent(in) :: stat
    character(len=*), intent(in) :: text
    is_legitimate = (stat == 2 .and. (index(text, 'has separated') > 0 .or. &
                                      index(text, 'switches branch') > 0 .or. &
                                      index(text, 'jumps across the target') > 0)) .or. &
                    (stat == 1 .and. index(text, 'unstable on small sub-increments') > 0)
  end function is_legitimate

  !> Run one cell; print the first defect in detail (parameters, state, increment).
  subroutine run_cell(c)
    type(cell_t), intent(inout) :: c
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    type(step_t), allocatable :: steps(:)
    real(dp) :: sigma(2), tangent(2, 2)
    character(len=message_len) :: message
    character(len=200) :: what
    logical :: ok
    integer :: i, it, stat

    call make_material(design(:, c%row), mat, ok, message)
    if (.not. ok) then
      c%outcome = 2
      c%reason = reason_index('bad material: ' // trim(message), .false.)
      return
    end if
    call make_solver(c%scheme, solver)
    call make_loading(c%loading, mat, steps)
    call interlock_state_init(mat, old)
    do i = 1, size(steps)
      if (steps(i)%mixed) then
        call mixed_step(mat, solver, old, steps(i)%a, steps(i)%b, new, sigma, tangent, info, &
                        it, stat, message)
        c%mixed_it = max(c%mixed_it, it)
        c%updates = c%updates + it
      else
        call interlock_update(mat, solver, [steps(i)%a, steps(i)%b], old, new, sigma, tangent, info)
        c%updates = c%updates + 1
        stat = merge(0, 1, info%status == status_ok)
        if (stat /= 0) message = info%message
      end if
      c%newton = max(c%newton, info%newton_iterations)
      c%attempts = max(c%attempts, info%attempts)
      if (stat /= 0) then
        if (is_legitimate(stat, message)) then
          c%outcome = 1
          if (verbose) call print_defect(c, mat, old, i, steps(i), 'stated: ' // message)
        else
          c%outcome = 2
          call print_defect(c, mat, old, i, steps(i), message)
        end if
        c%reason = reason_index(message, c%outcome == 1)
        return
      end if
      call check_update(mat, old, new, sigma, tangent, what)
      if (len_trim(what) > 0) then
        c%outcome = 2
        c%reason = reason_index('invariant: ' // trim(what), .false.)
        call print_defect(c, mat, old, i, steps(i), 'invariant: ' // what)
        return
      end if
      if (info%newton_iterations > solver%newton_max_iterations) then
        c%outcome = 2
        c%reason = reason_index('Newton iterations above the solver bound', .false.)
        return
      end if
      old = new
    end do
  end subroutine run_cell

  subroutine print_defect(c, mat, old, istep, st, message)
    type(cell_t), intent(in) :: c
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(in) :: old
    integer, intent(in) :: istep
    type(step_t), intent(in) :: st
    character(len=*), intent(in) :: message
    integer :: n
    n = mat%n_planes
    write (output_unit, '(a,i0,a,a,a,a,a,i0)') '  DEFECT row ', c%row, ' loading "', &
      trim(loading_names(c%loading)), '" scheme ', column_label(c%scheme), ' step ', istep
    write (output_unit, '(4x,a)') trim(message)
    write (output_unit, '(4x,a,9(1x,i0))') 'levels', design(:, c%row)
    write (output_unit, '(4x,a,6es12.4)') 'sigma0_n sigma0_t gc eta mu h_n', mat%sigma0_n, &
      mat%sigma0_t, mat%gc, mat%eta, mat%mu, mat%h_n
    write (output_unit, '(4x,a,8es12.4)') 'theta0', mat%theta0(1:n)
    write (output_unit, '(4x,a,8es12.4)') 'thetaf', mat%thetaf(1:n)
    write (output_unit, '(4x,a,8es12.4)') 'zeta0 ', mat%zeta0(1:n)
    write (output_unit, '(4x,a,l2,a,2es24.16)') 'mixed', st%mixed, '  target', st%a, st%b
    write (output_unit, '(4x,a,2es24.16,a,2es24.16)') 'old s', old%s, ' old sigma', old%sigma
    write (output_unit, '(4x,a,8es24.16)') 'old D', old%damage(1:n)
    write (output_unit, '(4x,a,8es24.16)') 'old beta', old%beta(1:n)
    write (output_unit, '(4x,a,8es24.16)') 'old sf', old%sf(1:n)
    write (output_unit, '(4x,a,8es24.16)') 'old zeta', old%zeta(1:n)
    write (output_unit, '(4x,a,8es24.16)') 'old theta', old%theta(1:n)
    write (output_unit, '(4x,a,8es24.16)') 'old tauf', old%tauf(1:n)
  end subroutine print_defect

  ! ---------------------------------------------------------------- tests

  !> The mixed-control driver against SPEC 8 (pure mode II on a flat interface under constant
  !> compression p): s_N = -p/K_n and the residual shear mu p.
  subroutine test_mixed_control_closed_form()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), tangent(2, 2), p, st, d, beta, tau
    integer :: it, stat, i
    character(len=message_len) :: message
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 3.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.5_dp
    call interlock_general_ria(mat, 1, [1.0_dp], [0.0_dp], [0.0_dp])
    call interlock_material_prepare(mat, stat, message)
    call assert_equal(status_ok, stat, 'prepare')
    p = 0.2_dp
    call interlock_state_init(mat, old)
    do i = 0, 30
      st = 0.02_dp * i
      call mixed_step(mat, solver, old, -p, st, new, sigma, tangent, info, it, stat, message)
      call assert_equal(0, stat, 'mixed step converged')
      call assert_close_rel(-p / mat%kn, new%s(1), 1.0e-9_dp, 1.0e-30_dp, 's_N = -p/K_n')
      call assert_close_rel(-p, sigma(1), 1.0e-10_dp, 1.0e-30_dp, 'sigma_N = -p')
      beta = max(old%beta(1), st / mat%s0t)
      d = 0.0_dp
      if (beta > 1.0_dp) d = min(1.0_dp, (beta - 1.0_dp) / (mat%eta * beta))
      tau = (1.0_dp - d) * mat%kt * st + d * min(mat%kt * st, mat%mu * p)
      call assert_close_rel(tau, sigma(2), 1.0e-9_dp, 1.0e-12_dp, 'tau (SPEC 8)')
      call assert_true(it <= 5, 'few mixed iterations on a linear normal response')
      old = new
    end do
  end subroutine test_mixed_control_closed_form

  subroutine test_stability_matrix()
    integer :: n_cells, r, il, is, ic, worst_newton, worst_mixed, worst_attempts, total
    integer :: n_defects
    real(dp) :: t0, t1
    if (.not. allocated(design)) call build_design()
    n_cells = size(design, 2) * n_loadings * n_columns
    allocate (cells(n_cells))
    ic = 0
    call cpu_time(t0)
    do r = 1, size(design, 2)
      do il = 1, n_loadings
        do is = 1, n_columns
          ic = ic + 1
          cells(ic)%row = r
          cells(ic)%loading = il
          cells(ic)%scheme = is
          call run_cell(cells(ic))
        end do
      end do
    end do
    call cpu_time(t1)
    worst_newton = maxval(cells%newton)
    worst_mixed = maxval(cells%mixed_it)
    worst_attempts = maxval(cells%attempts)
    total = sum(cells%updates)
    n_defects = count(cells%outcome == 2)
    write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,f7.2,a)') '  cells ', n_cells, &
      ': completed ', count(cells%outcome == 0), ', stated failures ', &
      count(cells%outcome == 1), ', defects ', n_defects, '; updates ', total, ' in ', t1 - t0, ' s'
    write (output_unit, '(a,i0,a,i0,a,i0)') '  worst: core Newton iterations ', worst_newton, &
      ', mixed-control iterations ', worst_mixed, ', sub-increments tried ', worst_attempts
    do r = 1, n_reasons
      write (output_unit, '(a,i0,a,l1,a,i0,a)') '  reason ', r, ' (legit ', reason_legit(r), &
        ', ', count(cells%reason == r), ' cells): ' // trim(reasons(r))
    end do
    call assert_equal(0, n_defects, 'cells with a defect (NaN/Inf, violated invariant, ' // &
                      'unstated failure or non-convergence)')
    call assert_true(worst_mixed <= mixed_max_iterations, 'mixed-control iterations bounded')
    call assert_true(worst_newton <= 60, 'core Newton iterations within the solver bound')
    if (len_trim(doc_path) > 0) call write_doc(trim(doc_path), n_cells, total, worst_newton, &
                                               worst_mixed, worst_attempts)
  end subroutine test_stability_matrix

  ! ---------------------------------------------------------------- the table

  function level_label(f, l) result(str)
    integer, intent(in) :: f, l
    character(len=:), allocatable :: str
    real(dp) :: v
    character(len=32) :: buf
    v = level_values(l, f)
    select case (f)
    case (f_pre)
      str = merge('yes', 'no ', l == 2)
      str = trim(str)
    case (f_ria)
      str = trim(ria_names(l))
    case default
      if (is_infinite_value(v)) then
        str = 'infinite'
      else
        write (buf, '(g0)') v
        if (v >= 1.0e-3_dp .and. v < 1.0e4_dp) write (buf, '(f0.5)') v
        str = trim(adjustl(buf))
        do while (len(str) > 1 .and. index(str, '.') > 0 .and. str(len(str):len(str)) == '0')
          str = str(1:len(str) - 1)
        end do
        if (str(len(str):len(str)) == '.') str = str(1:len(str) - 1)
        if (str(1:1) == '.') str = '0' // str
        ! (1.0E-06, 1.0E+06: no long run of digits in the table)
        if ((v > 0.0_dp .and. v < 1.0e-3_dp) .or. v >= 1.0e4_dp) then
          write (buf, '(es8.1)') v
          str = trim(adjustl(buf))
        end if
      end if
    end select
  end function level_label

  function cell_text(mask) result(str)
    logical, intent(in) :: mask(:)
    character(len=:), allocatable :: str
    character(len=32) :: buf
    integer :: r, n
    write (buf, '(i0,a,i0)') count(mask .and. cells%outcome == 0), '/', count(mask)
    str = trim(buf)
    do r = 1, n_reasons
      n = count(mask .and. cells%reason == r .and. cells%outcome /= 0)
      if (n > 0) then
        write (buf, '(a,i0,a,i0,a)') ' +', n, ' [', r, ']'
        str = str // trim(buf)
      end if
    end do
  end function cell_text

  subroutine write_doc(path, n_cells, total, worst_newton, worst_mixed, worst_attempts)
    character(len=*), intent(in) :: path
    integer, intent(in) :: n_cells, total, worst_newton, worst_mixed, worst_attempts
    integer :: u, f, l, is, il, r
    character(len=:), allocatable :: line
    open (newunit=u, file=path, status='replace', action='write')
    write (u, '(a)') '# Stability matrix'
    write (u, '(a)') ''
    write (u, '(a)') 'Generated by `stability_matrix --doc docs/stability.md` (the executable ' // &
      'of the CTest `stability_matrix`, label stability, run from the repository root). ' // &
      'Each cell is one material (a row of the design) under one ' // &
      'loading with one scheme, integrated from the virgin state; it must end *completed* ' // &
      'with finite, bounded outputs, or with a stated, legitimate failure reason.'
    write (u, '(a)') ''
    write (u, '(a,i0,a,i0,a,i0,a,i0,a,i0,a)') '- Design: ', n_pairwise, &
      ' rows covering every pair of levels of the ', n_factors, ' factors (greedy AETG-like), ' // &
      'plus ', size(design, 2) - n_pairwise, ' one-factor extremes around the Table 1 ' // &
      'baseline (H_N = 1 mm, eta = 0.9, sigma0 = 3 MPa, Gc_bar = 0.3 N/mm, theta_0 = 45 deg, ' // &
      'no wear, mu = 0.5, intact, paper RIA); x ', n_loadings, ' loadings x ', n_schemes, &
      ' schemes (every scheme of the library, below) x without and with substepping.'
    write (u, '(a,i0,a,i0,a)') '- Cells: ', n_cells, '; updates (including mixed-control ' // &
      'trials): ', total, '.'
    write (u, '(a,i0,a,i0,a,i0,a)') '- Worst iteration counts: core wear Newton ', worst_newton, &
      ' (bound 60), mixed-control trial updates per step ', worst_mixed, ' (bound ', &
      mixed_max_iterations, '),'
    write (u, '(a,i0,a)') '  sub-increments tried in one update ', worst_attempts, '.'
    write (u, '(a)') '- Checks after every update: D in [0,1] and non-decreasing, zeta ' // &
      'non-decreasing, theta between theta_f and theta_0 (so |theta| <= |theta_0|), ' // &
      'friction dissipation non-decreasing (the damage dissipation increment of the law ' // &
      'as SPEC states it can be negative when a plane''s local shear reverses, ' // &
      'docs/model.md, decision D9), ' // &
      'traction and tangent finite, and'
    write (u, '(a)') '  |sigma| <= c + (1 + mu) K_n |s| with c = sigma0_n + sigma0_t ' // &
      '(the cohesive part never exceeds the peak tractions, contact is the penalty K_n on ' // &
      'the interpenetration, friction at most mu times the contact pressure).'
    write (u, '(a)') '- Schemes: every scheme of the library (PROPS 11 = ' // scheme_list() // &
      '), each without and with substepping (tol 1e-4): one column each. Loadings: ' // &
      'sigma_N = -sigma0_n/15 (Table 1: -0.2 MPa) held by a ' // &
      'safeguarded scalar Newton iteration on s_N; lengths in units of s_c = 2 Gc_bar/sigma0.'
    write (u, '(a)') ''
    write (u, '(a)') 'Cell text: completed/total, then `+n [r]` for n cells that ended with ' // &
      'reason r (legend below).'
    write (u, '(a)') ''
    line = '| factor | level |'
    do is = 1, n_columns
      line = line // ' ' // column_label(is) // ' |'
    end do
    write (u, '(a)') line
    line = '|---|---|'
    do is = 1, n_columns
      line = line // '---|'
    end do
    write (u, '(a)') line
    do f = 1, n_factors
      do l = 1, n_levels(f)
        line = '| ' // trim(factor_names(f)) // ' | ' // level_label(f, l) // ' |'
        do is = 1, n_columns
          line = line // ' ' // cell_text(design(f, cells%row) == l .and. cells%scheme == is) // ' |'
        end do
        write (u, '(a)') line
      end do
    end do
    do il = 1, n_loadings
      line = '| loading | ' // trim(loading_names(il)) // ' |'
      do is = 1, n_columns
        line = line // ' ' // cell_text(cells%loading == il .and. cells%scheme == is) // ' |'
      end do
      write (u, '(a)') line
    end do
    line = '| all | |'
    do is = 1, n_columns
      line = line // ' ' // cell_text(cells%scheme == is) // ' |'
    end do
    write (u, '(a)') line
    write (u, '(a)') ''
    write (u, '(a)') 'The fuzzer (`interlock-fuzz`, tests/stability/fuzz) complements the ' // &
      'matrix with random admissible materials and random separation histories (CTest: ' // &
      '1e5 updates, seed 1; a long run: `interlock-fuzz --seed 7 --updates 10000000`); every failing ' // &
      'input is written as a replay deck (docs/deck-format.md).'
    write (u, '(a)') ''
    if (n_reasons == 0) then
      write (u, '(a)') 'No cell failed.'
    else
      write (u, '(a)') 'Reasons (`#` stands for a digit, `~` for a sign):'
      write (u, '(a)') ''
      do r = 1, n_reasons
        write (u, '(a,i0,a)') '- [', r, '] ' // merge('legitimate: ', 'DEFECT:     ', &
          reason_legit(r)) // trim(reasons(r))
      end do
    end if
    close (u)
  end subroutine write_doc

end module test_stability_matrix_suite

program test_stability_matrix
  use test_stability_matrix_suite, only: collect_stability_matrix, doc_path, verbose
  use interlock_assert, only: suite_summary
  implicit none
  integer :: i, n
  character(len=256) :: arg
  n = command_argument_count()
  i = 1
  do while (i <= n)
    call get_command_argument(i, arg)
    if (arg == '--doc' .and. i < n) then
      call get_command_argument(i + 1, doc_path)
      i = i + 1
    end if
    if (arg == '--verbose') verbose = .true.
    i = i + 1
  end do
  call collect_stability_matrix()
  if (suite_summary('stability_matrix') /= 0) error stop 1
end program test_stability_matrix
