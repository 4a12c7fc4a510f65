!> interlock-bench: what accuracy costs in time.
!>
!> 1. Cost per call of interlock_update (traction + tangent) for each effect set and scheme,
!>    over precomputed separation histories, as the median of interleaved repetitions, and the
!>    same as a ratio to a minimal bilinear cohesive law timed in the same run; the same
!>    histories through the external UMAT against the update it wraps.
!> 2. Work-precision of every scheme/tolerance on the paper's Fig. 11, Fig. 12 and granite
!>    scenes at constant normal traction: error against a converged reference versus CPU time,
!>    the observed order, and the CPU time each scheme needs for a given error.
!>
!> Usage: interlock-bench --out DIR [--quick] [--only cost|precision] [--target ERR]
!> Writes DIR/cost.csv, DIR/umat_cost.csv, DIR/cost3d.csv, DIR/work_precision.csv, DIR/reference.csv and
!> DIR/wp_summary.csv (DIR is required: nothing is written into the working folder unasked). A usage error prints the
!> usage on stderr and exits with status 2; --help prints it on stdout (status 0).
program interlock_bench
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
  use interlock_cli, only: exit_program, folder_writable
  use interlock, only: dp, max_planes, interlock_material_t, interlock_solver_t, interlock_state_t, &
      interlock_info_t, interlock_update, interlock_state_init, scheme_explicit, scheme_implicit, &
      scheme_trapezoidal, scheme_name, status_ok, interlock_version_string, n_properties_2d, &
      props_to_material, umat_controls_t, interlock_state_3d_t, interlock_state_3d_init, &
      interlock_update_3d, interlock_azimuthal_ria, interlock_material_prepare, deg_to_rad
  use interlock_bench_bilinear, only: bilinear_t, bilinear_state_t, bilinear_setup, bilinear_update
  use interlock_bench_scenes, only: scene_t, make_scene, run_scene, slip_at, n_effect_sets, &
      effect_set_names, make_effect_set, make_histories, median
  use interlock_bench_umat, only: umat_props, time_umat, time_umat_floor, time_umat_3d
  use interlock_bench_precision_3d, only: precision_study_3d, precision_run_3d
  implicit none

  integer, parameter :: n_scenes = 3
  character(len=8), parameter :: scene_names(n_scenes) = [character(len=8) :: &
    'fig11', 'fig12', 'granite']
  logical :: quick, do_cost, do_precision, do_precision_3d
  character(len=16) :: dump_scene, dump_scheme
  real(dp) :: dump_tol
  integer :: dump_steps, profile_set, profile_scheme, profile_passes
  logical :: profile_umat
  !> 0: the 2D update; 1: the 3D one on the histories turned by 30 deg; 2: azimuthal N_a = 3 on
  !> them; 3: the 3D one on the histories in the (n, t1) plane
  integer :: profile_3d
  real(dp) :: profile_tol
  !> --profile-path: the scheme (0: none), tolerance and steps of one run of the 45-deg 3D scene
  integer :: path_scheme, path_steps
  real(dp) :: path_tol
  logical :: path_ok
  character(len=512) :: out_dir
  real(dp) :: target_error
  integer :: problems

  !> The UMAT rows of the cost study: 1..n_umat_rows UMAT calls (effect set, scheme: explicit,
  !> implicit, trapezoidal), then the updates they wrap, then the floor of the UMAT's overhead
  !> per effect set.
  integer, parameter :: n_umat_schemes = 3
  integer, parameter :: n_umat_rows = n_umat_schemes * n_effect_sets
  integer, parameter :: n_umat_cols = 2 * n_umat_rows + n_effect_sets
  type :: umat_rows_t
    real(dp) :: props(n_properties_2d, n_umat_rows)
    type(interlock_material_t) :: mats(n_umat_rows)
    type(interlock_solver_t) :: solvers(n_umat_rows)
    type(umat_controls_t) :: controls
    real(dp), allocatable :: times(:, :)
    real(dp) :: chk(0:n_umat_cols)
    integer :: inner(0:n_umat_cols), cuts(n_umat_rows), fails
  end type umat_rows_t

  call parse_arguments()
  problems = 0
  if (len_trim(dump_scene) > 0) then
    call dump_history()
    stop
  end if
  if (profile_set >= 0) then
    call profile_run()
    stop
  end if
  if (path_scheme > 0) then
    call precision_run_3d(path_scheme, path_tol, path_steps, path_ok)
    if (.not. path_ok) error stop 1
    stop
  end if
  write (output_unit, '(a)') 'interlock-bench (interlock ' // interlock_version_string // ')' // &
    merge(' --quick', '        ', quick)
  if (do_cost) call cost_study()
  if (do_cost) call cost_study_3d()
  if (do_precision) call precision_study()
  if (do_precision_3d) call precision_study_3d_csv()
  if (problems > 0) then
    write (error_unit, '(a,i0,a)') 'interlock-bench: ', problems, ' problem(s), see above'
    error stop 1
  end if

contains

  subroutine parse_arguments()
    integer :: i, n, ios
    character(len=512) :: arg, val
    quick = .false.
    do_cost = .true.
    do_precision = .true.
    do_precision_3d = .true.
    out_dir = ''
    target_error = 1.0e-4_dp
    dump_scene = ''
    profile_set = -1
    profile_tol = 0.0_dp
    profile_umat = .false.
    profile_3d = 0
    path_scheme = 0
    n = command_argument_count()
    if (n == 0) call usage('no arguments: --out DIR is required')
    i = 1
    do while (i <= n)
      call get_command_argument(i, arg)
      select case (trim(arg))
      case ('--version')
        write (output_unit, '(a)') 'interlock-bench ' // interlock_version_string
        call exit_program(0)
      case ('--quick')
        quick = .true.
      case ('--out', '--only', '--target')
        if (i == n) call usage('missing value after ' // trim(arg))
        call get_command_argument(i + 1, val)
        i = i + 1
        select case (trim(arg))
        case ('--out')
          out_dir = val
          if (len_trim(out_dir) == 0) call usage('--out takes a folder')
        case ('--only')
          do_cost = trim(val) == 'cost'
          do_precision = trim(val) == 'precision'
          do_precision_3d = trim(val) == 'precision3d'
          if (.not. (do_cost .or. do_precision .or. do_precision_3d)) &
            call usage('--only takes cost, precision or precision3d')
        case ('--target')
          read (val, *, iostat=ios) target_error
          if (ios /= 0 .or. .not. target_error > 0.0_dp) call usage('--target takes a positive error')
        end select
      case ('--history')
        if (i + 4 > n) call usage('--history takes SCENE SCHEME TOL N')
        call get_command_argument(i + 1, dump_scene)
        call get_command_argument(i + 2, dump_scheme)
        call get_command_argument(i + 3, val)
        read (val, *, iostat=ios) dump_tol
        if (ios /= 0) call usage('--history: TOL must be a number (0: no substepping)')
        call get_command_argument(i + 4, val)
        read (val, *, iostat=ios) dump_steps
        if (ios /= 0 .or. dump_steps < 1) call usage('--history: N must be a positive integer')
        i = i + 4
      case ('--profile')
        if (i + 3 > n) call usage('--profile takes SET SCHEME PASSES [TOL]')
        call get_command_argument(i + 1, val)
        read (val, *, iostat=ios) profile_set
        if (ios /= 0 .or. profile_set < 0 .or. profile_set > n_effect_sets) &
          call usage('--profile: SET is 0 (bilinear) .. 5 (full model)')
        profile_scheme = scheme_argument(i + 2, '--profile')
        call get_command_argument(i + 3, val)
        read (val, *, iostat=ios) profile_passes
        if (ios /= 0 .or. profile_passes < 1) call usage('--profile: PASSES must be positive')
        i = i + 3
        if (i < n) then             ! optional substepping tolerance
          call get_command_argument(i + 1, val)
          if (val(1:2) /= '--') then
            read (val, *, iostat=ios) profile_tol
            if (ios /= 0 .or. profile_tol < 0.0_dp) &
              call usage('--profile: TOL must be a non-negative number (0: no substepping)')
            i = i + 1
          end if
        end if
      case ('--profile-path')
        if (i + 3 > n) call usage('--profile-path takes SCHEME TOL N')
        path_scheme = scheme_argument(i + 1, '--profile-path')
        call get_command_argument(i + 2, val)
        read (val, *, iostat=ios) path_tol
        if (ios /= 0 .or. path_tol < 0.0_dp) &
          call usage('--profile-path: TOL must be a non-negative number (0: no substepping)')
        call get_command_argument(i + 3, val)
        read (val, *, iostat=ios) path_steps
        if (ios /= 0 .or. path_steps < 1) call usage('--profile-path: N must be a positive integer')
        i = i + 3
      case ('--umat')
        profile_umat = .true.
      case ('--turned')
        profile_3d = 1
      case ('--azimuthal')
        profile_3d = 2
      case ('--in-plane')
        profile_3d = 3
      case ('--umat-floor')
        profile_umat = .true.
        profile_tol = -1.0_dp
      case ('-h', '--help')
        call usage('')
      case default
        call usage('unknown argument ' // trim(arg))
      end select
      i = i + 1
    end do
    if (profile_umat .and. profile_3d == 2) &
      call usage('--azimuthal takes no --umat or --umat-floor: the UMAT''s PROPS hold the paper''s RIA')
    if (profile_umat .and. profile_3d > 0 .and. profile_tol < 0.0_dp) &
      call usage('--umat-floor has no 3D variant: --turned and --in-plane take --umat')
    if (len_trim(dump_scene) == 0 .and. profile_set < 0 .and. path_scheme == 0 .and. &
        len_trim(out_dir) == 0) &
      call usage('--out DIR is required: the existing folder for the CSV files')
    ! checked before any work: the CSV files are written only at the end of each study
    if (len_trim(out_dir) > 0) then
      if (.not. folder_writable(trim(out_dir))) &
        call usage('--out ' // trim(out_dir) // ': no such folder, or not writable (it must ' // &
                   'exist and be writable)')
    end if
  end subroutine parse_arguments

  !> The scheme number (1 explicit, 2 implicit, 3 trapezoidal) in command argument `pos` of
  !> `option`; a usage error if it is none.
  integer function scheme_argument(pos, option) result(scheme)
    integer, intent(in) :: pos
    character(len=*), intent(in) :: option
    character(len=64) :: val
    integer :: ios
    call get_command_argument(pos, val)
    read (val, *, iostat=ios) scheme
    if (ios /= 0 .or. scheme < scheme_explicit .or. scheme > scheme_trapezoidal) &
      call usage(option // ': SCHEME is 1 (explicit), 2 (implicit) or 3 (trapezoidal)')
  end function scheme_argument

  !> Print the usage and end: on stdout with status 0 when `message` is empty (--help), else
  !> the message and the usage on stderr, status 2.
  subroutine usage(message)
    character(len=*), intent(in) :: message
    integer :: unit
    unit = output_unit
    if (len_trim(message) > 0) then
      unit = error_unit
      write (unit, '(a)') 'interlock-bench: error: ' // trim(message)
    end if
    write (unit, '(a)') 'usage: interlock-bench --out DIR [--quick] ' // &
      '[--only cost|precision|precision3d] [--target ERR]'
    write (unit, '(a)') '       interlock-bench --profile SET SCHEME PASSES [TOL]  ' // &
      '(one cost configuration only, for valgrind/gprof: SET 0 bilinear, 1..5 effect sets; ' // &
      'SCHEME 1 explicit, 2 implicit, 3 trapezoidal; TOL substepping tolerance, default 0; 3 x 4000-point ' // &
      'histories; see bench/profile_updates.py); with --umat: through the UMAT, ' // &
      'with --umat-floor: the floor of the UMAT''s overhead; with --turned or --azimuthal: ' // &
      'the 3D update on the histories turned by 30 deg (the full model''s RIA, or azimuthal N_a = 3), ' // &
      'with --in-plane: on the histories in the (n, t1) plane; --turned or --in-plane with --umat: ' // &
      'the UMAT as a 3D element (NTENS = 3, the full model''s PROPS)'
    write (unit, '(a)') '       interlock-bench --profile-path SCHEME TOL N  ' // &
      '(one run of part 3b''s 45-deg 3D scene at N steps, for valgrind: SCHEME 1 explicit, ' // &
      '2 implicit, 3 trapezoidal; TOL substepping tolerance, 0 for none; prints the end point)'
    write (unit, '(a)') '       interlock-bench --history SCENE SCHEME TOL N  ' // &
      '(one run of a scene as CSV on stdout; SCENE fig11|fig12|granite, ' // &
      'SCHEME explicit|implicit|trapezoidal)'
    write (unit, '(a)') '       interlock-bench --help | --version'
    write (unit, '(a)') '  writes DIR/cost.csv, DIR/umat_cost.csv, DIR/cost3d.csv, DIR/work_precision.csv, ' // &
      'DIR/reference.csv, DIR/wp_summary.csv, DIR/work_precision_3d.csv (DIR must exist)'
    write (unit, '(a)') '  exit status: 0 done, 1 a problem found (see the output), 2 a usage error'
    if (len_trim(message) > 0) call exit_program(2)
    call exit_program(0)
  end subroutine usage


  pure function path(name) result(p)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: p
    p = trim(out_dir) // '/' // name
  end function path

  subroutine open_csv(name, unit, header)
    character(len=*), intent(in) :: name, header
    integer, intent(out) :: unit
    integer :: ios
    character(len=256) :: msg
    open (newunit=unit, file=path(name), status='replace', action='write', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      write (error_unit, '(a)') 'interlock-bench: cannot write ' // path(name) // ': ' // trim(msg)
      error stop 2
    end if
    write (unit, '(a)') header
  end subroutine open_csv

  pure function fmt_tol(tol) result(s)
    real(dp), intent(in) :: tol
    character(len=8) :: s
    if (tol > 0.0_dp) then
      write (s, '(es8.0)') tol
      s = adjustl(s)
    else
      s = 'none'
    end if
  end function fmt_tol

  !> One run of a scene, as CSV on standard output: time, s_N, s_T, sigma_T.
  subroutine dump_history()
    type(scene_t) :: sc
    type(interlock_solver_t) :: solver
    real(dp), allocatable :: sn(:), st(:)
    integer :: stat, i, updates, max_newton
    logical :: ok
    character(len=256) :: message
    real(dp) :: t, resid, t0, t1
    call make_scene(trim(dump_scene), sc, stat, message)
    if (stat /= status_ok) call usage(trim(message))
    select case (trim(dump_scheme))
    case ('explicit')
      solver%scheme = scheme_explicit
    case ('implicit')
      solver%scheme = scheme_implicit
    case ('trapezoidal')
      solver%scheme = scheme_trapezoidal
    case default
      call usage('--history: SCHEME must be explicit, implicit or trapezoidal')
    end select
    solver%substep_tol = dump_tol
    allocate (sn(0:dump_steps), st(0:dump_steps))
    call cpu_time(t0)
    call run_scene(sc, solver, dump_steps, 1, sn, st, ok, updates, max_newton, resid, message)
    call cpu_time(t1)
    write (output_unit, '(a)') 'time,s_N,s_T,sigma_T'
    do i = 0, dump_steps
      t = sc%knot_t(sc%n_knots) * real(i, dp) / real(dump_steps, dp)
      write (output_unit, '(es22.14,3(",",es22.14))') t, sn(i), slip_at(sc, t), st(i)
    end do
    write (error_unit, '(a,i0,a,es9.2,a,es10.3)') 'updates: ', updates, '; largest normal-traction ' // &
      'residual accepted (relative): ', resid, '; cpu_s: ', t1 - t0
    if (.not. ok) then
      write (error_unit, '(a)') 'the run failed: ' // trim(message)
      error stop 3
    end if
  end subroutine dump_history

  !> Run one configuration of the cost study PASSES times over the histories (nothing timed):
  !> for a profiler, e.g. valgrind --tool=callgrind interlock-bench --profile 5 1 20. The set-up
  !> (histories, material) costs about as much as 10^5 bilinear updates: count only the updates
  !> (bench/profile_updates.py collects inside interlock_update / bilinear_update only).
  subroutine profile_run()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    real(dp), allocatable :: h(:, :, :), h3(:, :, :)
    real(dp) :: chk, props(n_properties_2d)
    integer :: k, stat, fails, nsub, cuts
    character(len=256) :: message
    allocate (h(2, 4000, 3))
    call make_histories(4000, h)
    call make_effect_set(max(1, profile_set), mat, stat, message)
    if (stat /= status_ok) call usage(trim(message))
    solver%scheme = profile_scheme
    solver%substep_tol = max(0.0_dp, profile_tol)
    chk = 0.0_dp
    fails = 0
    cuts = 0
    if (profile_umat) call umat_props(max(1, profile_set), profile_scheme, props)
    if (profile_3d > 0) then
      allocate (h3(3, 4000, 3))
      h3(1, :, :) = h(1, :, :)
      h3(2, :, :) = cos(30.0_dp * deg_to_rad) * h(2, :, :)
      h3(3, :, :) = sin(30.0_dp * deg_to_rad) * h(2, :, :)
      if (profile_3d == 3) then
        h3(2, :, :) = h(2, :, :)
        h3(3, :, :) = 0.0_dp
      end if
      if (profile_3d == 2) then
        call interlock_azimuthal_ria(mat, 3, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 1.0_dp)
        call interlock_material_prepare(mat, stat, message)
        if (stat /= status_ok) call usage(trim(message))
      end if
    end if
    do k = 1, profile_passes
      if (profile_3d > 0 .and. profile_umat) then
        call time_umat_3d(props, h3, chk, fails)
      else if (profile_3d > 0) then
        call time_interlock_3d(mat, solver, h3, chk, fails)
      else if (profile_umat .and. profile_tol < 0.0_dp) then
        call time_umat_floor(props, h, chk)
      else if (profile_umat) then
        call time_umat(props, h, chk, fails, cuts)
      else if (profile_set == 0) then
        call time_bilinear(mat, h, chk)
      else
        call time_interlock(mat, solver, h, chk, fails, nsub)
      end if
    end do
    write (output_unit, '(a,i0,a,es22.15,a,i0)') 'calls: ', 12000 * profile_passes, '; checksum ', &
      chk, '; failed updates: ', fails
  end subroutine profile_run

  ! ------------------------------------------------------------------------------------------
  ! 1. Cost per call
  ! ------------------------------------------------------------------------------------------

  subroutine cost_study()
    integer, parameter :: n_cfg = 2 * n_effect_sets + 5
    type(interlock_material_t) :: mats(n_effect_sets)
    type(interlock_solver_t) :: solvers(n_cfg)
    integer, parameter :: floor_cfg = n_cfg + 1   !< the lower bound of the full model (time_floor)
    integer :: cfg_set(n_cfg), npts, reps, rep, c, stat, u, fails, nsub, k, inner(0:floor_cfg)
    real(dp) :: min_rep
    real(dp), allocatable :: h(:, :, :), times(:, :)
    real(dp) :: t0, t1, chk(0:floor_cfg), ns(0:floor_cfg), ns_lo(0:floor_cfg), ns_hi(0:floor_cfg), &
                calls, dev
    real(dp) :: subs(n_cfg), chk_pass
    character(len=256) :: message
    character(len=24) :: label
    type(umat_rows_t) :: um

    npts = merge(100, 4000, quick)
    reps = merge(3, 21, quick)
    min_rep = merge(0.0_dp, 0.004_dp, quick)
    allocate (h(2, npts, 3), times(reps, 0:floor_cfg))
    call make_histories(npts, h)
    calls = real(3 * npts, dp)
    do c = 1, n_effect_sets
      call make_effect_set(c, mats(c), stat, message)
      if (stat /= status_ok) then
        write (error_unit, '(a)') 'effect set ' // trim(effect_set_names(c)) // ': ' // trim(message)
        error stop 2
      end if
    end do
    ! Configurations: (set, explicit), (set, implicit) for every set, then the full model with
    ! substepping at tol = 1e-3 for both schemes, then the full model with the trapezoidal
    ! scheme (on the other sets it runs the implicit scheme's code), plain and substepped at
    ! 1e-3 (where one sub-increment is enough) and at 1e-6 (where the increments are split).
    do c = 1, n_effect_sets
      cfg_set(2 * c - 1) = c
      cfg_set(2 * c) = c
      solvers(2 * c - 1)%scheme = scheme_explicit
      solvers(2 * c)%scheme = scheme_implicit
    end do
    cfg_set(n_cfg - 4:n_cfg) = n_effect_sets
    solvers(n_cfg - 4)%scheme = scheme_explicit
    solvers(n_cfg - 3)%scheme = scheme_implicit
    solvers(n_cfg - 4)%substep_tol = 1.0e-3_dp
    solvers(n_cfg - 3)%substep_tol = 1.0e-3_dp
    solvers(n_cfg - 2:n_cfg)%scheme = scheme_trapezoidal
    solvers(n_cfg - 1)%substep_tol = 1.0e-3_dp
    solvers(n_cfg)%substep_tol = 1.0e-6_dp

    ! The baseline must compute what the damage-only set computes (else the ratio means nothing).
    dev = baseline_deviation(mats(1), h)
    write (output_unit, '(/,a,i0,a,i0,a)') '== Cost per call: 3 histories x ', npts, &
      ' points, median of ', reps, ' interleaved repetitions (CPU time)'
    write (output_unit, '(a,es9.2)') 'bilinear baseline vs damage-only set, max relative ' // &
      'difference of traction and tangent: ', dev
    if (.not. dev < 1.0e-12_dp) then
      write (error_unit, '(a)') 'the bilinear baseline does not reproduce the damage-only set'
      problems = problems + 1
    end if

    chk = 0.0_dp
    fails = 0
    subs = 0.0_dp
    ! Rep 0 warms up, is not timed, and sets how many passes over the histories one timed
    ! repetition makes (inner), so that each timing spans at least min_rep CPU seconds.
    inner = 1
    nsub = 0
    do rep = 0, reps
      call cpu_time(t0)
      do k = 1, inner(0)
        call time_bilinear(mats(1), h, chk(0))
      end do
      call cpu_time(t1)
      call record_time(rep, 0, t1 - t0, min_rep, inner, times)
      do c = 1, n_cfg
        call cpu_time(t0)
        do k = 1, inner(c)
          call time_interlock(mats(cfg_set(c)), solvers(c), h, chk(c), fails, nsub)
        end do
        call cpu_time(t1)
        call record_time(rep, c, t1 - t0, min_rep, inner, times)
        subs(c) = real(nsub, dp) / calls
      end do
      call cpu_time(t0)
      do k = 1, inner(floor_cfg)
        call time_floor(mats(n_effect_sets), h, chk(floor_cfg))
      end do
      call cpu_time(t1)
      call record_time(rep, floor_cfg, t1 - t0, min_rep, inner, times)
      call time_umat_rows(rep, reps, min_rep, h, um)
      if (rep == 0) chk_pass = sum(chk)   ! one pass of everything: reproducible
    end do
    if (fails > 0) then
      write (error_unit, '(a,i0,a)') 'cost study: ', fails, ' updates failed'
      problems = problems + 1
    end if
    do c = 0, floor_cfg
      ns(c) = 1.0e9_dp * median(times(:, c)) / calls
      ns_lo(c) = 1.0e9_dp * minval(times(:, c)) / calls
      ns_hi(c) = 1.0e9_dp * maxval(times(:, c)) / calls
    end do

    call open_csv('cost.csv', u, 'effect_set,scheme,substep_tol,ns_per_call,ratio_to_bilinear,' // &
      'ns_min,ns_max,mean_substeps,calls_per_rep,reps,checksum')
    write (output_unit, '(a24,1x,a8,1x,a6,3(1x,a10),1x,a10,1x,a8)') 'effect set', 'scheme', 'subtol', &
      'ns/call', 'min', 'max', 'x bilinear', 'substeps'
    write (output_unit, '(a24,1x,a8,1x,a6,3(1x,f10.1),1x,f10.2,1x,a8)') 'bilinear (baseline)', '-', &
      '-', ns(0), ns_lo(0), ns_hi(0), 1.0_dp, '-'
    write (u, '(a,",",es12.5,",",es12.5,3(",",es12.5),",",i0,",",i0,",",es22.15)') &
      'bilinear,-,none', ns(0), 1.0_dp, ns_lo(0), ns_hi(0), 1.0_dp, nint(calls), reps, chk(0)
    do c = 1, n_cfg
      label = effect_set_names(cfg_set(c))
      write (output_unit, '(a24,1x,a8,1x,a6,3(1x,f10.1),1x,f10.2,1x,f8.2)') label, &
        scheme_name(solvers(c)%scheme), fmt_tol(solvers(c)%substep_tol), ns(c), ns_lo(c), ns_hi(c), &
        ns(c) / ns(0), subs(c)
      write (u, '(a,",",a,",",a,",",es12.5,",",es12.5,3(",",es12.5),",",i0,",",i0,",",es22.15)') &
        trim(label), scheme_name(solvers(c)%scheme), trim(fmt_tol(solvers(c)%substep_tol)), ns(c), &
        ns(c) / ns(0), ns_lo(c), ns_hi(c), subs(c), nint(calls), reps, chk(c)
    end do
    write (output_unit, '(a24,1x,a8,1x,a6,3(1x,f10.1),1x,f10.2,1x,a8)') 'floor of the full model', &
      '-', '-', ns(floor_cfg), ns_lo(floor_cfg), ns_hi(floor_cfg), ns(floor_cfg) / ns(0), '-'
    write (u, '(a,",",es12.5,",",es12.5,3(",",es12.5),",",i0,",",i0,",",es22.15)') &
      'floor of the full model,-,none', ns(floor_cfg), ns(floor_cfg) / ns(0), ns_lo(floor_cfg), &
      ns_hi(floor_cfg), 1.0_dp, nint(calls), reps, chk(floor_cfg)
    close (u)
    write (output_unit, '(a)') '(floor of the full model: the bilinear law on each of the 3 ' // &
      'planes, and exp, cos and sin of each of the 2 wearing angles, per call; no update of ' // &
      'the full model can cost less)'
    write (output_unit, '(a,es22.15,a,es12.5,a)') 'checksum (sum of tractions and tangents, one ' // &
      'pass of every configuration): ', chk_pass, ' (all passes: ', sum(chk), ')'
    write (output_unit, '(a)') 'targets: damage-only <= 1.3 x bilinear: ' // &
      verdict(ns(1) / ns(0) <= 1.3_dp) // ' (explicit ' // fmt_ratio(ns(1) / ns(0)) // &
      ', implicit ' // fmt_ratio(ns(2) / ns(0)) // '); full model explicit <= 4 x: ' // &
      verdict(ns(2 * n_effect_sets - 1) / ns(0) <= 4.0_dp) // ' (' // &
      fmt_ratio(ns(2 * n_effect_sets - 1) / ns(0)) // '; its floor alone ' // &
      fmt_ratio(ns(floor_cfg) / ns(0)) // ')'
    ! The full model's explicit update against its floor, in the same run.
    write (output_unit, '(a)') 'targets: full model explicit <= 1.5 x its floor: ' // &
      verdict(ns(2 * n_effect_sets - 1) / ns(floor_cfg) <= 1.5_dp) // ' (' // &
      fmt_ratio(ns(2 * n_effect_sets - 1) / ns(floor_cfg)) // ')'
    call report_umat_rows(um, ns(0), calls)
    ! Substepping: the cost of one sub-increment (time per update over the mean number of
    ! sub-increments) against the plain update of the same scheme on the same histories.
    write (output_unit, '(a)') 'substepping, cost per sub-increment / plain update of the ' // &
      'scheme (target <= 2): explicit ' // &
      fmt_ratio(ns(n_cfg - 4) / subs(n_cfg - 4) / ns(2 * n_effect_sets - 1)) // ', implicit ' // &
      fmt_ratio(ns(n_cfg - 3) / subs(n_cfg - 3) / ns(2 * n_effect_sets)) // ', trapezoidal ' // &
      fmt_ratio(ns(n_cfg - 1) / subs(n_cfg - 1) / ns(n_cfg - 2)) // ' (at 1e-6, ' // &
      fmt_ratio(subs(n_cfg)) // ' sub-increments per update: ' // &
      fmt_ratio(ns(n_cfg) / subs(n_cfg) / ns(n_cfg - 2)) // ')'
  end subroutine cost_study

  !> One repetition of the UMAT rows (interleaved with the others in cost_study): for every
  !> effect set and scheme the UMAT call, the update it wraps (the material the UMAT builds from
  !> the same PROPS, same history) and, per effect set, the floor of the UMAT's overhead.
  subroutine time_umat_rows(rep, reps, min_rep, h, um)
    integer, intent(in) :: rep, reps
    real(dp), intent(in) :: min_rep, h(:, :, :)
    type(umat_rows_t), intent(inout) :: um
    real(dp) :: t0, t1
    integer :: c, k, j, stat, nsub, cuts
    character(len=256) :: message
    if (rep == 0) then
      allocate (um%times(reps, 0:n_umat_cols))
      um%chk = 0.0_dp
      um%fails = 0
      um%cuts = 0
      um%inner = 1
      do c = 1, n_effect_sets
        do j = 1, n_umat_schemes
          k = n_umat_schemes * (c - 1) + j
          call umat_props(c, j, um%props(:, k))
          call props_to_material(um%props(:, k), um%mats(k), um%solvers(k), um%controls, stat, &
                                 message)
          if (stat /= status_ok) then
            write (error_unit, '(a)') 'UMAT rows, effect set ' // trim(effect_set_names(c)) // &
              ': ' // trim(message)
            error stop 2
          end if
        end do
      end do
    end if
    do j = 1, n_umat_rows
      call cpu_time(t0)
      cuts = 0
      do k = 1, um%inner(j)
        call time_umat(um%props(:, j), h, um%chk(j), um%fails, cuts)
      end do
      call cpu_time(t1)
      if (rep == 0) um%cuts(j) = cuts   ! one pass
      call record_time(rep, j, t1 - t0, min_rep, um%inner, um%times)
      call cpu_time(t0)
      do k = 1, um%inner(n_umat_rows + j)
        call time_interlock(um%mats(j), um%solvers(j), h, um%chk(n_umat_rows + j), &
                            um%fails, nsub)
      end do
      call cpu_time(t1)
      call record_time(rep, n_umat_rows + j, t1 - t0, min_rep, um%inner, um%times)
    end do
    do c = 1, n_effect_sets
      j = 2 * n_umat_rows + c
      call cpu_time(t0)
      do k = 1, um%inner(j)
        call time_umat_floor(um%props(:, n_umat_schemes * (c - 1) + 1), h, um%chk(j))
      end do
      call cpu_time(t1)
      call record_time(rep, j, t1 - t0, min_rep, um%inner, um%times)
    end do
  end subroutine time_umat_rows

  !> The UMAT table (stdout and DIR/umat_cost.csv) and the verdicts on the cost targets:
  !> overhead (UMAT call - update) <= 5 bilinear calls for every row, full model's UMAT call
  !> <= 1.5 x its update.
  subroutine report_umat_rows(um, ns_bilinear, calls)
    type(umat_rows_t), intent(in) :: um
    real(dp), intent(in) :: ns_bilinear, calls
    real(dp) :: ns(0:n_umat_cols), umat_ns, update_ns, over, floor_ns, worst, full_ratio
    integer :: c, j, sch, u
    logical :: ok_over, ok_full
    do j = 1, n_umat_cols
      ns(j) = 1.0e9_dp * median(um%times(:, j)) / calls
    end do
    if (um%fails > 0) then
      write (error_unit, '(a,i0,a)') 'UMAT rows: ', um%fails, ' calls failed'
      problems = problems + 1
    end if
    write (output_unit, '(/,a)') '== UMAT call (Abaqus calling sequence, PROPS parsed every ' // &
      'call) against the update it wraps, same histories, same run; ns per call'
    write (output_unit, '(a24,1x,a8,5(1x,a10),1x,a8)') 'effect set', 'scheme', 'UMAT', 'update', &
      'overhead', 'x bilinear', 'UMAT/upd.', 'cuts'
    call open_csv('umat_cost.csv', u, 'effect_set,scheme,umat_ns,update_ns,overhead_ns,' // &
      'overhead_bilinear_calls,umat_over_update,floor_ns,floor_bilinear_calls,pnewdt_cuts,' // &
      'calls_per_rep,checksum')
    ok_over = .true.
    worst = 0.0_dp
    full_ratio = 0.0_dp
    do c = 1, n_effect_sets
      floor_ns = ns(2 * n_umat_rows + c)
      do sch = 1, n_umat_schemes
        j = n_umat_schemes * (c - 1) + sch
        umat_ns = ns(j)
        update_ns = ns(n_umat_rows + j)
        over = umat_ns - update_ns
        worst = max(worst, over / ns_bilinear)
        ok_over = ok_over .and. over <= 5.0_dp * ns_bilinear
        if (c == n_effect_sets) full_ratio = max(full_ratio, umat_ns / update_ns)
        write (output_unit, '(a24,1x,a8,3(1x,f10.1),2(1x,f10.2),1x,i8)') effect_set_names(c), &
          scheme_name(sch), umat_ns, update_ns, over, over / ns_bilinear, umat_ns / update_ns, &
          um%cuts(j)
        write (u, '(a,",",a,7(",",es12.5),2(",",i0),",",es22.15)') trim(effect_set_names(c)), &
          scheme_name(sch), umat_ns, update_ns, over, over / ns_bilinear, umat_ns / update_ns, &
          floor_ns, floor_ns / ns_bilinear, um%cuts(j), nint(calls), um%chk(j)
      end do
      write (output_unit, '(a24,1x,a8,1x,a10,1x,a10,1x,f10.1,1x,f10.2)') effect_set_names(c), &
        'floor', '-', '-', floor_ns, floor_ns / ns_bilinear
    end do
    close (u)
    ok_full = full_ratio <= 1.5_dp
    write (output_unit, '(a)') '(overhead = UMAT - update, x bilinear = overhead in calls of ' // &
      'the bilinear law; floor = what any UMAT must do per call besides its law: read and ' // &
      'check PROPS and STATEV, derive the constants and the sine and cosine of theta_0, write ' // &
      'STATEV back; cuts = calls per pass proposing PNEWDT < 1)'
    write (output_unit, '(a)') 'targets: UMAT overhead <= 5 x bilinear for every row: ' // &
      verdict(ok_over) // ' (largest ' // fmt_ratio(worst) // '); full model UMAT <= 1.5 x ' // &
      'its update: ' // verdict(ok_full) // ' (' // fmt_ratio(full_ratio) // ')'
  end subroutine report_umat_rows


  !> Store the time of one repetition (per pass); rep 0 (warm-up) sets the passes per repetition.
  pure subroutine record_time(rep, c, dt, min_rep, inner, times)
    integer, intent(in) :: rep, c
    real(dp), intent(in) :: dt, min_rep
    integer, intent(inout) :: inner(0:)
    real(dp), intent(inout) :: times(:, 0:)
    if (rep > 0) then
      times(rep, c) = dt / inner(c)
    else
      inner(c) = max(1, min(1000, ceiling(min_rep / max(dt, 1.0e-7_dp))))
    end if
  end subroutine record_time

  pure function verdict(ok) result(s)
    logical, intent(in) :: ok
    character(len=:), allocatable :: s
    s = merge('met   ', 'MISSED', ok)
    s = trim(s)
  end function verdict

  pure function fmt_ratio(x) result(s)
    real(dp), intent(in) :: x
    character(len=:), allocatable :: s
    character(len=16) :: b
    write (b, '(f8.2,"x")') x
    s = trim(adjustl(b))
  end function fmt_ratio

  ! ------------------------------------------------------------------------------------------
  ! 1b. Cost per call in three dimensions
  ! ------------------------------------------------------------------------------------------

  !> The three-dimensional update against the 2D one on the cost study's histories, interleaved
  !> in one run, for the full model (effect set 5) and each scheme: the 2D update; the 3D update
  !> of the same material with every azimuth 0 and no T2 loading (the histories in the (n, t1)
  !> plane: target <= 1.2 x the 2D update); the same histories turned by 30 deg in the
  !> interface plane (T2 loading, the general 3D path: target <= 1.5 x); the `azimuthal` RIA
  !> with N_a = 3 on the turned histories (target <= 3.5 x); and the external UMAT with the full model's PROPS: as a 2D element
  !> on the histories, as a 3D element (NTENS = 3) on the turned ones. Writes DIR/cost3d.csv.
  subroutine cost_study_3d()
    integer, parameter :: n_kinds = 6
    integer, parameter :: n_schemes = 3   !< explicit, implicit, trapezoidal
    character(len=32), parameter :: kind_names(n_kinds) = [character(len=32) :: '2D', &
      '3D, in the (n, t1) plane', '3D, turned 30 deg', '3D azimuthal N_a = 3, turned', &
      'UMAT NTENS = 2', 'UMAT NTENS = 3, turned 30 deg']
    type(interlock_material_t) :: mat, mat_az
    type(interlock_solver_t) :: solver
    integer :: npts, reps, rep, stat, u, fails, kind, scheme, k, inner(0:n_kinds), cuts
    real(dp) :: min_rep, t0, t1, calls, chk(0:n_kinds), ns(n_kinds, n_schemes), ang, &
                ratio(n_kinds, n_schemes), props(n_properties_2d)
    real(dp), allocatable :: h(:, :, :), h3(:, :, :), h3t(:, :, :), times(:, :)
    character(len=256) :: message

    npts = merge(100, 2000, quick)
    reps = merge(3, 11, quick)
    min_rep = merge(0.0_dp, 0.004_dp, quick)
    allocate (h(2, npts, 3), h3(3, npts, 3), h3t(3, npts, 3), times(reps, 0:n_kinds))
    call make_histories(npts, h)
    ang = 30.0_dp * deg_to_rad
    h3(1:2, :, :) = h
    h3(3, :, :) = 0.0_dp
    h3t(1, :, :) = h(1, :, :)
    h3t(2, :, :) = cos(ang) * h(2, :, :)
    h3t(3, :, :) = sin(ang) * h(2, :, :)
    calls = real(3 * npts, dp)
    call make_effect_set(n_effect_sets, mat, stat, message)
    mat_az = mat
    call interlock_azimuthal_ria(mat_az, 3, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 1.0_dp)
    call interlock_material_prepare(mat_az, stat, message)
    if (stat /= status_ok) then
      write (error_unit, '(a)') 'azimuthal RIA: ' // trim(message)
      error stop 2
    end if
    write (output_unit, '(/,a,i0,a,i0,a)') '== Cost per call in 3D: full model, 3 histories x ', &
      npts, ' points, median of ', reps, ' interleaved repetitions (CPU time)'
    call open_csv('cost3d.csv', u, 'scheme,update,ns_per_call,ratio_to_2d,calls_per_rep,reps')
    fails = 0
    cuts = 0
    do scheme = 1, n_schemes
      solver%scheme = scheme
      call umat_props(n_effect_sets, scheme, props)
      chk = 0.0_dp
      inner = 1
      do rep = 0, reps
        call cpu_time(t0)
        do k = 1, inner(1)
          call time_interlock_2d_only(mat, solver, h, chk(1), fails)
        end do
        call cpu_time(t1)
        call record_time(rep, 1, t1 - t0, min_rep, inner, times)
        do kind = 2, n_kinds
          call cpu_time(t0)
          do k = 1, inner(kind)
            if (kind == 2) then
              call time_interlock_3d(mat, solver, h3, chk(kind), fails)
            else if (kind == 3) then
              call time_interlock_3d(mat, solver, h3t, chk(kind), fails)
            else if (kind == 4) then
              call time_interlock_3d(mat_az, solver, h3t, chk(kind), fails)
            else if (kind == 5) then
              call time_umat(props, h, chk(kind), fails, cuts)
            else
              call time_umat_3d(props, h3t, chk(kind), fails)
            end if
          end do
          call cpu_time(t1)
          call record_time(rep, kind, t1 - t0, min_rep, inner, times)
        end do
      end do
      do kind = 1, n_kinds
        ns(kind, scheme) = 1.0e9_dp * median(times(:, kind)) / calls
        ! (the ratio of each repetition, whose 2D and 3D timings follow each other within
        ! milliseconds, then their median: a change of the machine's speed between repetitions
        ! cancels)
        ratio(kind, scheme) = median(times(:, kind) / times(:, 1))
        ! (the update's name holds commas: quoted, as RFC 4180 says)
        write (u, '(a,3a,",",es12.5,",",es12.5,",",i0,",",i0)') trim(scheme_name(scheme)), &
          ',"', trim(kind_names(kind)), '"', ns(kind, scheme), ratio(kind, scheme), &
          nint(calls), reps
      end do
    end do
    close (u)
    write (output_unit, '(a32,3(1x,a22))') 'update', (trim(scheme_name(scheme)) // &
      ' ns (x 2D)', scheme = 1, n_schemes)
    do kind = 1, n_kinds
      write (output_unit, '(a32,3(1x,f12.1,1x,"(",f6.2,")",1x))') kind_names(kind), &
        (ns(kind, scheme), ratio(kind, scheme), scheme = 1, n_schemes)
    end do
    write (output_unit, '(a)') 'targets: 3D update in the (n, t1) plane <= 1.2 x 2D: ' // &
      verdict(all(ratio(2, :) <= 1.2_dp)) // ' (largest ' // &
      fmt_ratio(maxval(ratio(2, :))) // '); turned 30 deg <= 1.5 x: ' // &
      verdict(all(ratio(3, :) <= 1.5_dp)) // ' (largest ' // &
      fmt_ratio(maxval(ratio(3, :))) // '); azimuthal N_a = 3 turned <= 3.5 x: ' // &
      verdict(all(ratio(4, :) <= 3.5_dp)) // ' (largest ' // &
      fmt_ratio(maxval(ratio(4, :))) // ')'
    if (fails > 0) then
      write (error_unit, '(a,i0,a)') 'cost study in 3D: ', fails, ' updates failed'
      problems = problems + 1
    end if
  end subroutine cost_study_3d

  !> time_interlock without the substep count (the 3D cost study's 2D row).
  subroutine time_interlock_2d_only(mat, solver, h, chk, fails)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: h(:, :, :)
    real(dp), intent(inout) :: chk
    integer, intent(inout) :: fails
    integer :: nsub
    call time_interlock(mat, solver, h, chk, fails, nsub)
  end subroutine time_interlock_2d_only

  !> The 3D update along the histories h(3, :, :).
  subroutine time_interlock_3d(mat, solver, h, chk, fails)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: h(:, :, :)
    real(dp), intent(inout) :: chk
    integer, intent(inout) :: fails
    type(interlock_state_3d_t) :: st(2)
    type(interlock_info_t) :: info
    real(dp) :: sig(3), tangent(3, 3), acc
    integer :: ih, i, cur
    acc = 0.0_dp
    do ih = 1, size(h, 3)
      call interlock_state_3d_init(mat, st(1))
      cur = 1
      do i = 1, size(h, 2)
        call interlock_update_3d(mat, solver, h(:, i, ih), st(cur), st(3 - cur), sig, tangent, &
                                 info)
        if (info%status /= status_ok) fails = fails + 1
        acc = acc + sum(sig) + sum(tangent)
        cur = 3 - cur
      end do
    end do
    chk = chk + acc
  end subroutine time_interlock_3d

  subroutine time_interlock(mat, solver, h, chk, fails, nsub)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: h(:, :, :)
    real(dp), intent(inout) :: chk
    integer, intent(inout) :: fails
    integer, intent(out) :: nsub
    type(interlock_state_t) :: st(2)
    type(interlock_info_t) :: info
    real(dp) :: sig(2), tangent(2, 2), acc
    integer :: ih, i, cur
    acc = 0.0_dp
    nsub = 0
    do ih = 1, size(h, 3)
      call interlock_state_init(mat, st(1))
      cur = 1
      do i = 1, size(h, 2)
        call interlock_update(mat, solver, h(:, i, ih), st(cur), st(3 - cur), sig, tangent, info)
        if (info%status /= status_ok) fails = fails + 1
        nsub = nsub + info%substeps
        acc = acc + (sig(1) + sig(2)) + (tangent(1, 1) + tangent(2, 2)) + &
              (tangent(1, 2) + tangent(2, 1))
        cur = 3 - cur
      end do
    end do
    chk = chk + acc
  end subroutine time_interlock

  subroutine time_bilinear(mat, h, chk)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: h(:, :, :)
    real(dp), intent(inout) :: chk
    type(bilinear_t) :: law
    type(bilinear_state_t) :: st(2)
    real(dp) :: sig(2), tangent(2, 2), acc
    integer :: ih, i, cur
    call bilinear_setup(mat, law)
    acc = 0.0_dp
    do ih = 1, size(h, 3)
      st(1) = bilinear_state_t()
      cur = 1
      do i = 1, size(h, 2)
        call bilinear_update(law, h(:, i, ih), st(cur), st(3 - cur), sig, tangent)
        acc = acc + (sig(1) + sig(2)) + (tangent(1, 1) + tangent(2, 2)) + &
              (tangent(1, 2) + tangent(2, 1))
        cur = 3 - cur
      end do
    end do
    chk = chk + acc
  end subroutine time_bilinear

  !> A lower bound of the cost of any update of the full model with the paper's RIA (effect set
  !> 5: three planes, two of them wearing), measured on the same histories: the bilinear law on
  !> each plane in its frame (no friction, no contact area, no tangent rotation), and for each
  !> wearing plane the worn angle of eq. 22 (one exponential) and the cosine and sine of its
  !> frame. The frictional work driving the wear is taken as the slip increment, so the angles
  !> change every call as they do while a joint slides. What the full model adds (friction on
  !> every plane, the rotation of tractions and tangents, the energies) makes any real update
  !> dearer than this.
  subroutine time_floor(mat, h, chk)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: h(:, :, :)
    real(dp), intent(inout) :: chk
    type(bilinear_t) :: law
    type(bilinear_state_t) :: st(max_planes, 2)
    real(dp) :: sig(2), tangent(2, 2), acc, sl(2), c(max_planes), sn(max_planes), &
                zeta(max_planes), theta, s_prev
    integer :: ih, i, cur, k
    call bilinear_setup(mat, law)
    acc = 0.0_dp
    do ih = 1, size(h, 3)
      st = bilinear_state_t()
      c = cos(mat%theta_init)
      sn = sin(mat%theta_init)
      zeta = 0.0_dp
      s_prev = 0.0_dp
      cur = 1
      do i = 1, size(h, 2)
        do k = 1, mat%n_planes
          sl = [c(k) * h(1, i, ih) + sn(k) * h(2, i, ih), -sn(k) * h(1, i, ih) + c(k) * h(2, i, ih)]
          call bilinear_update(law, sl, st(k, cur), st(k, 3 - cur), sig, tangent)
          acc = acc + (sig(1) + sig(2)) + (tangent(1, 1) + tangent(2, 2)) + &
                (tangent(1, 2) + tangent(2, 1))
          if (mat%plane_wears(k)) then
            zeta(k) = zeta(k) + abs(h(2, i, ih) - s_prev)
            theta = (mat%theta_init(k) - mat%thetaf_eff(k)) * exp(-zeta(k) * mat%inv_zeta0(k)) + &
                    mat%thetaf_eff(k)
            c(k) = cos(theta)
            sn(k) = sin(theta)
          end if
        end do
        s_prev = h(2, i, ih)
        cur = 3 - cur
      end do
    end do
    chk = chk + acc
  end subroutine time_floor

  !> Largest difference between the bilinear baseline and interlock's damage-only set over
  !> the histories (traction and tangent, each relative to its largest magnitude).
  real(dp) function baseline_deviation(mat, h) result(dev)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: h(:, :, :)
    type(interlock_solver_t) :: solver
    type(bilinear_t) :: law
    type(bilinear_state_t) :: b(2)
    type(interlock_state_t) :: st(2)
    type(interlock_info_t) :: info
    real(dp) :: sig_a(2), sig_b(2), tan_a(2, 2), tan_b(2, 2), dsig, dtan, msig, mtan
    integer :: ih, i, cur
    call bilinear_setup(mat, law)
    dsig = 0.0_dp
    dtan = 0.0_dp
    msig = tiny(1.0_dp)
    mtan = tiny(1.0_dp)
    do ih = 1, size(h, 3)
      call interlock_state_init(mat, st(1))
      b(1) = bilinear_state_t()
      cur = 1
      do i = 1, size(h, 2)
        call interlock_update(mat, solver, h(:, i, ih), st(cur), st(3 - cur), sig_a, tan_a, info)
        call bilinear_update(law, h(:, i, ih), b(cur), b(3 - cur), sig_b, tan_b)
        dsig = max(dsig, maxval(abs(sig_a - sig_b)))
        dtan = max(dtan, maxval(abs(tan_a - tan_b)))
        msig = max(msig, maxval(abs(sig_b)))
        mtan = max(mtan, maxval(abs(tan_b)))
        cur = 3 - cur
      end do
    end do
    dev = max(dsig / msig, dtan / mtan)
  end function baseline_deviation

  ! ------------------------------------------------------------------------------------------
  ! 2. Work-precision
  ! ------------------------------------------------------------------------------------------

  !> Part 3b (interlock_bench_precision_3d): the 3D scenes, into work_precision_3d.csv.
  subroutine precision_study_3d_csv()
    integer :: u
    logical :: ok
    call open_csv('work_precision_3d.csv', u, 'scene,config,n_steps_per_segment,cpu_s,error')
    call precision_study_3d(u, quick, ok)
    close (u)
    if (.not. ok) problems = problems + 1
  end subroutine precision_study_3d_csv

  subroutine precision_study()
    real(dp), allocatable :: tols_explicit(:), tols_implicit(:), tols_trapezoidal(:)
    integer :: jmax, ref_shift, n_cfg, is, c, j, n_grid, n, u, ur, us
    integer :: updates, max_newton, runs
    type(scene_t) :: sc
    type(interlock_solver_t), allocatable :: solvers(:)
    real(dp), allocatable :: ref_sn(:), ref_st(:), sn(:), st(:)
    real(dp), allocatable :: err(:, :), cpu(:, :), prev_sn(:), prev_st(:), r_sn(:), r_st(:)
    logical, allocatable :: okr(:, :)
    character(len=24), allocatable :: labels(:)
    character(len=10), allocatable :: tol_names(:)
    integer, allocatable :: scheme_of(:)
    integer :: n_all, cr, prev_updates
    real(dp) :: e_st, e_sn, e_curve, min_time, order, cost_t, cost_explicit, best_cost, uncert, plain, resid
    real(dp) :: cost_implicit
    integer :: j_hi, best_j
    logical :: this_extrapolated, implicit_extrapolated
    character(len=256) :: why
    integer :: best_c, stat
    logical :: ok, reached, extrapolated, rich
    character(len=256) :: message
    character(len=24) :: label

    if (quick) then
      jmax = 2
      ref_shift = 4
      tols_explicit = [0.0_dp, 1.0e-2_dp]
      tols_implicit = [0.0_dp, 1.0e-2_dp]
      tols_trapezoidal = [0.0_dp, 1.0e-3_dp]
      min_time = 0.0_dp
    else
      jmax = 10
      ref_shift = 4
      ! (explicit substepping at 1e-5 costs ~10 s per run for no gain: left out)
      tols_explicit = [0.0_dp, 1.0e-2_dp, 1.0e-3_dp, 1.0e-4_dp]
      tols_implicit = [0.0_dp, 1.0e-2_dp, 1.0e-3_dp, 1.0e-4_dp, 1.0e-5_dp]
      tols_trapezoidal = [0.0_dp, 1.0e-3_dp, 1.0e-4_dp, 1.0e-5_dp]
      min_time = 0.05_dp
    end if
    ! Configurations run: each scheme with uniform steps and with substepping; then two
    ! derived ones: global Richardson extrapolation 2 u(2n) - u(n) of the uniform-step runs of
    ! each scheme (the runs at n and 2n are both timed: its cost is their sum).
    n_cfg = size(tols_explicit) + size(tols_implicit) + size(tols_trapezoidal)
    n_all = n_cfg + 2
    allocate (solvers(n_cfg), err(0:jmax, n_all), cpu(0:jmax, n_all), okr(0:jmax, n_all), &
              labels(n_all), tol_names(n_all), scheme_of(n_all))
    do c = 1, n_cfg
      if (c <= size(tols_explicit)) then     ! configuration 1 is the paper's: explicit, uniform
        solvers(c)%scheme = scheme_explicit
        solvers(c)%substep_tol = tols_explicit(c)
      else if (c <= size(tols_explicit) + size(tols_implicit)) then
        solvers(c)%scheme = scheme_implicit
        solvers(c)%substep_tol = tols_implicit(c - size(tols_explicit))
      else
        solvers(c)%scheme = scheme_trapezoidal
        solvers(c)%substep_tol = tols_trapezoidal(c - size(tols_explicit) - size(tols_implicit))
      end if
      scheme_of(c) = solvers(c)%scheme
      tol_names(c) = fmt_tol(solvers(c)%substep_tol)
      labels(c) = trim(scheme_name(scheme_of(c))) // ' ' // trim(tol_names(c))
    end do
    scheme_of(n_cfg + 1:) = [scheme_explicit, scheme_implicit]
    tol_names(n_cfg + 1:) = 'richardson'
    do c = n_cfg + 1, n_all
      labels(c) = trim(scheme_name(scheme_of(c))) // ' Richardson'
    end do

    write (output_unit, '(/,a)') '== Work-precision: error = max over the history of ' // &
      '|sigma_T - ref| / max|sigma_T,ref| and |s_N - ref| / max|s_N,ref|, at every step of the run'
    call open_csv('work_precision.csv', u, 'scene,scheme,substep_tol,config,n_steps,cpu_s,error,' // &
      'error_sigma_t,error_s_n,updates,runs_timed,max_normal_residual,ok,error_curve')
    call open_csv('reference.csv', ur, 'scene,n_reference,uncertainty,plain_error_at_n_reference,' // &
      'order_check')
    call open_csv('wp_summary.csv', us, 'scene,scheme,substep_tol,config,observed_order,' // &
      'cpu_s_at_target,target_error,explicit_uniform_over_this,extrapolated,' // &
      'explicit_extrapolated,n_steps_first_below')

    do is = 1, n_scenes
      call make_scene(trim(scene_names(is)), sc, stat, message)
      if (stat /= status_ok) then
        write (error_unit, '(a)') trim(message)
        error stop 2
      end if
      n_grid = sc%base_steps * 2**jmax
      allocate (ref_sn(0:n_grid), ref_st(0:n_grid))
      call make_reference(sc, n_grid, ref_shift, ref_sn, ref_st, uncert, plain, order)
      write (output_unit, '(/,a)') trim(sc%title)
      write (output_unit, '(a,i0,a,i0,a,es9.2,a,es9.2,a,f5.2,a)') '  reference: Richardson of ' // &
        'implicit at ', n_grid * 2**ref_shift, ' and ', n_grid * 2**(ref_shift + 1), &
        ' steps; uncertainty ', uncert, ' (vs the pair one level coarser); plain implicit at ', &
        plain, ' (observed order ', order, ')'
      flush (output_unit)
      write (ur, '(a,",",i0,",",es12.5,",",es12.5,",",f8.4)') trim(sc%name), &
        n_grid * 2**(ref_shift + 1), uncert, plain, order
      if (.not. uncert < merge(5.0e-3_dp, 1.0e-5_dp, quick)) then
        write (error_unit, '(a)') '  the reference of ' // trim(sc%name) // ' is not converged'
        problems = problems + 1
      end if
      write (output_unit, '(a20,1x,a7,2x,a)') 'scheme / substep tol', 'order', &
        'error (cpu ms) at n_steps = base * 2**j'

      okr = .false.
      err = huge(1.0_dp)
      cpu = 0.0_dp
      allocate (prev_sn(0:n_grid), prev_st(0:n_grid), r_sn(0:n_grid), r_st(0:n_grid))
      prev_sn = 0.0_dp
      prev_st = 0.0_dp
      prev_updates = 0
      do c = 1, n_cfg
        label = labels(c)
        cr = 0
        ! (Richardson's 2 u(2n) - u(n) is for the first-order schemes)
        if (.not. solvers(c)%substep_tol > 0.0_dp .and. solvers(c)%scheme /= scheme_trapezoidal) &
          cr = n_cfg + merge(1, 2, solvers(c)%scheme == scheme_explicit)
        do j = 0, jmax
          n = sc%base_steps * 2**j
          allocate (sn(0:n), st(0:n))
          call timed_run(sc, solvers(c), n, min_time, sn, st, ok, updates, max_newton, resid, why, &
                         cpu(j, c), runs)
          okr(j, c) = ok
          if (ok) then
            e_st = maxval(abs(st - ref_st(0:n_grid:n_grid / n))) / maxval(abs(ref_st))
            e_sn = maxval(abs(sn - ref_sn(0:n_grid:n_grid / n))) / maxval(abs(ref_sn))
            e_curve = max(interp_error(st, ref_st), interp_error(sn, ref_sn))
          else
            e_curve = huge(1.0_dp)
            e_st = huge(1.0_dp)
            e_sn = huge(1.0_dp)
            if (j >= 2) problems = problems + 1
            write (error_unit, '(a,i0,a)') '  ' // trim(sc%name) // ' ' // trim(label) // ' at ', n, &
              ' steps failed: ' // trim(why)
          end if
          err(j, c) = max(e_st, e_sn)
          if (.not. ok) resid = -1.0_dp
          write (u, '(a,",",a,",",a,",",a,",",i0,4(",",es12.5),",",i0,",",i0,",",es12.5,",",l1,' // &
            '",",es12.5)') &
            trim(sc%name), scheme_name(solvers(c)%scheme), trim(fmt_tol(solvers(c)%substep_tol)), &
            trim(label), n, cpu(j, c), err(j, c), e_st, e_sn, updates, runs, resid, ok, e_curve
          if (cr > 0) then
            ! Global Richardson extrapolation on the coarser grid, from this run and the last.
            rich = .false.
            if (j > 0) rich = ok .and. okr(j - 1, c)    ! (no short-circuit in Fortran)
            if (rich) then
              r_sn(0:n / 2) = 2.0_dp * sn(0:n:2) - prev_sn(0:n / 2)
              r_st(0:n / 2) = 2.0_dp * st(0:n:2) - prev_st(0:n / 2)
              e_st = maxval(abs(r_st(0:n / 2) - ref_st(0:n_grid:2 * n_grid / n))) / maxval(abs(ref_st))
              e_sn = maxval(abs(r_sn(0:n / 2) - ref_sn(0:n_grid:2 * n_grid / n))) / maxval(abs(ref_sn))
              e_curve = max(interp_error(r_st(0:n / 2), ref_st), interp_error(r_sn(0:n / 2), ref_sn))
              err(j - 1, cr) = max(e_st, e_sn)
              cpu(j - 1, cr) = cpu(j - 1, c) + cpu(j, c)
              okr(j - 1, cr) = .true.
              write (u, '(a,",",a,",",a,",",a,",",i0,4(",",es12.5),",",i0,",",i0,",",es12.5,",",' // &
                'l1,",",es12.5)') trim(sc%name), scheme_name(scheme_of(cr)), trim(tol_names(cr)), &
                trim(labels(cr)), n / 2, cpu(j - 1, cr), err(j - 1, cr), e_st, e_sn, &
                updates + prev_updates, runs, 0.0_dp, .true., e_curve
            end if
            prev_sn(0:n) = sn
            prev_st(0:n) = st
            prev_updates = updates
          end if
          deallocate (sn, st)
        end do
      end do

      ! Table: order, error and CPU time per step count (every other level on the terminal).
      ! CPU time to reach the target: between measured step counts by log-log interpolation
      ! (cost_at); beyond the finest run, for the uniform-step configurations only, at the
      ! observed order (cost ~ n ~ error^(-1/order), extrapolate_cost).
      cost_explicit = cost_at(err(:, 1), cpu(:, 1), okr(:, 1), target_error, reached, j_hi)
      extrapolated = .false.
      if (.not. reached) then
        cost_explicit = extrapolate_cost(err(:, 1), cpu(:, 1), okr(:, 1), sc%base_steps, jmax, &
                                         target_error)
        extrapolated = cost_explicit > 0.0_dp
      end if
      best_cost = huge(1.0_dp)
      best_c = 0
      best_j = -1
      cost_implicit = -1.0_dp
      implicit_extrapolated = .false.
      do c = 1, n_all
        label = labels(c)
        order = observed_order(err(:, c), okr(:, c), sc%base_steps, merge(jmax, jmax - 1, c <= n_cfg))
        write (output_unit, '(a20,1x,f7.2,2x)', advance='no') label, order
        do j = 0, jmax, merge(1, 2, quick)
          if (okr(j, c)) then
            write (output_unit, '(es8.1,"(",f0.1,")",1x)', advance='no') err(j, c), 1.0e3_dp * cpu(j, c)
          else if (c > n_cfg) then
            write (output_unit, '(a,1x)', advance='no') '-'
          else
            write (output_unit, '(a,1x)', advance='no') 'failed'
          end if
        end do
        write (output_unit, '(a)') ''
        flush (output_unit)
        cost_t = cost_at(err(:, c), cpu(:, c), okr(:, c), target_error, reached, j_hi)
        this_extrapolated = .false.
        if (.not. reached .and. c <= n_cfg) then
          if (.not. solvers(c)%substep_tol > 0.0_dp) then
            cost_t = extrapolate_cost(err(:, c), cpu(:, c), okr(:, c), sc%base_steps, jmax, &
                                      target_error)
            this_extrapolated = cost_t > 0.0_dp
          end if
        end if
        if (c == 1 + size(tols_explicit)) then      ! implicit, uniform steps
          cost_implicit = merge(cost_t, -1.0_dp, reached .or. this_extrapolated)
          implicit_extrapolated = this_extrapolated
        end if
        if (reached) then
          if (cost_t < best_cost) then
            best_cost = cost_t
            best_c = c
            best_j = j_hi
          end if
        end if
        if (reached .or. this_extrapolated) then
          write (us, '(a,",",a,",",a,",",a,",",f8.4,",",es12.5,",",es9.2,",",es12.5,",",l1,",",' // &
            'l1,",",i0)') trim(sc%name), scheme_name(scheme_of(c)), trim(tol_names(c)), &
            trim(label), order, cost_t, target_error, merge(cost_explicit / cost_t, -1.0_dp, &
            cost_explicit > 0.0_dp), this_extrapolated, extrapolated, &
            merge(sc%base_steps * 2**max(j_hi, 0), -1, reached)
        else
          write (us, '(a,",",a,",",a,",",a,",",f8.4,",",a,",",es9.2,",",a,",",l1,",",a)') &
            trim(sc%name), scheme_name(scheme_of(c)), trim(tol_names(c)), &
            trim(label), order, 'not reached', target_error, '', .false., merge('T', 'F', extrapolated) &
            // ',-1'
        end if
      end do
      write (output_unit, '(a)') '  (columns: n_steps = ' // trim(steps_list(sc%base_steps, jmax, &
        merge(1, 2, quick))) // ')'
      write (output_unit, '(a,es8.1,a)', advance='no') '  CPU time for error ', target_error, ': '
      if (cost_explicit > 0.0_dp) then
        write (output_unit, '(a,es9.2,a)', advance='no') 'explicit uniform ', cost_explicit, ' s' // &
          trim(merge(' (extrapolated)', '               ', extrapolated)) // '; '
      else
        write (output_unit, '(a)', advance='no') 'explicit uniform not reached; '
      end if
      if (cost_implicit > 0.0_dp) then
        write (output_unit, '(a,es9.2,a)', advance='no') 'implicit uniform ', cost_implicit, ' s' // &
          trim(merge(' (extrapolated)', '               ', implicit_extrapolated)) // '; '
      else
        write (output_unit, '(a)', advance='no') 'implicit uniform not reached; '
      end if
      if (best_c > 0) then
        label = labels(best_c)
        write (output_unit, '(a,es9.2,a,i0,a)', advance='no') 'best measured: ' // trim(label) // ' ', &
          best_cost, ' s (interpolated; its runs stay below the target from n = ', &
          sc%base_steps * 2**max(best_j, 0), ' on)'
        if (cost_explicit > 0.0_dp) write (output_unit, '(a,f0.1,a)', advance='no') ', ', &
          cost_explicit / best_cost, 'x cheaper than explicit uniform'
        write (output_unit, '(a)') ''
      else
        write (output_unit, '(a)') 'no configuration reaches it within the measured step counts'
      end if
      deallocate (ref_sn, ref_st, prev_sn, prev_st, r_sn, r_st)
    end do
    close (u)
    close (ur)
    close (us)
  end subroutine precision_study

  !> The run's curve x(0:n), linearly interpolated between its steps, against the reference
  !> at every point of the finest grid (size(ref) - 1 steps), relative to max |ref|: the error
  !> of the curve a user would plot, which also sees what happens between coarse steps.
  pure real(dp) function interp_error(x, ref) result(e)
    real(dp), intent(in) :: x(0:), ref(0:)
    integer :: n, n_grid, stride, k, i
    real(dp) :: w, v
    n = size(x) - 1
    n_grid = size(ref) - 1
    stride = n_grid / n
    e = 0.0_dp
    do k = 0, n_grid
      i = k / stride
      if (i >= n) then
        v = x(n)
      else
        w = real(mod(k, stride), dp) / real(stride, dp)
        v = (1.0_dp - w) * x(i) + w * x(i + 1)
      end if
      e = max(e, abs(v - ref(k)))
    end do
    e = e / maxval(abs(ref))
  end function interp_error

  pure function steps_list(base, jmax, stride) result(s)
    integer, intent(in) :: base, jmax, stride
    character(len=:), allocatable :: s
    character(len=16) :: b
    integer :: j
    s = ''
    do j = 0, jmax, stride
      write (b, '(i0)') base * 2**j
      s = s // trim(b) // merge(', ', '  ', j + stride <= jmax)
    end do
    s = trim(s)
  end function steps_list

  !> Run a scene repeatedly until min_time CPU seconds have passed; cpu = mean per run.
  subroutine timed_run(sc, solver, n, min_time, sn, st, ok, updates, max_newton, resid, why, cpu, &
                       runs)
    type(scene_t), intent(in) :: sc
    type(interlock_solver_t), intent(in) :: solver
    integer, intent(in) :: n
    real(dp), intent(in) :: min_time
    real(dp), intent(out) :: sn(0:), st(0:), cpu, resid
    character(len=*), intent(out) :: why
    logical, intent(out) :: ok
    integer, intent(out) :: updates, max_newton, runs
    real(dp) :: t0, t1, total
    total = 0.0_dp
    runs = 0
    do
      call cpu_time(t0)
      call run_scene(sc, solver, n, 1, sn, st, ok, updates, max_newton, resid, why)
      call cpu_time(t1)
      total = total + (t1 - t0)
      runs = runs + 1
      if (total >= min_time .or. .not. ok .or. runs >= 1000) exit
    end do
    cpu = total / runs
  end subroutine timed_run

  !> The reference on the finest run grid (n_grid steps): local Richardson extrapolation
  !> 2 u(2m) - u(m) of the implicit scheme (first order) at m = n_grid 2**shift steps.
  !> `uncert` compares it with the extrapolation one level coarser (m/2, m), `plain` is the
  !> error of u(2m) itself, `order` = log2(|u(m) - R| / |u(2m) - R|).
  subroutine make_reference(sc, n_grid, shift, ref_sn, ref_st, uncert, plain, order)
    type(scene_t), intent(in) :: sc
    integer, intent(in) :: n_grid, shift
    real(dp), intent(out) :: ref_sn(0:), ref_st(0:), uncert, plain, order
    type(interlock_solver_t) :: solver
    real(dp), dimension(0:n_grid) :: a_sn, a_st, b_sn, b_st, c_sn, c_st
    integer :: m, updates, max_newton
    logical :: ok1, ok2, ok3
    real(dp) :: ea, r1, r2, r3

    solver%scheme = scheme_implicit
    m = n_grid * 2**shift
    call run_scene(sc, solver, m / 2, 2**(shift - 1), c_sn, c_st, ok1, updates, max_newton, r1)
    call run_scene(sc, solver, m, 2**shift, a_sn, a_st, ok2, updates, max_newton, r2)
    call run_scene(sc, solver, 2 * m, 2**(shift + 1), b_sn, b_st, ok3, updates, max_newton, r3)
    if (.not. (ok1 .and. ok2 .and. ok3 .and. max(r1, r2, r3) < 1.0e-10_dp)) then
      write (error_unit, '(a)') 'the reference run of ' // trim(sc%name) // ' failed'
      error stop 3
    end if
    ref_sn = 2.0_dp * b_sn - a_sn
    ref_st = 2.0_dp * b_st - a_st
    uncert = rel_diff(ref_sn, ref_st, 2.0_dp * a_sn - c_sn, 2.0_dp * a_st - c_st)
    plain = rel_diff(ref_sn, ref_st, b_sn, b_st)
    ea = rel_diff(ref_sn, ref_st, a_sn, a_st)
    order = log(ea / max(plain, tiny(1.0_dp))) / log(2.0_dp)
  end subroutine make_reference

  pure real(dp) function rel_diff(r_sn, r_st, x_sn, x_st) result(d)
    real(dp), intent(in) :: r_sn(:), r_st(:), x_sn(:), x_st(:)
    d = max(maxval(abs(x_sn - r_sn)) / maxval(abs(r_sn)), maxval(abs(x_st - r_st)) / maxval(abs(r_st)))
  end function rel_diff

  !> Slope of log(error) against log(n_steps) (least squares over the finer half of the levels),
  !> as a positive order; 0 when fewer than two usable points.
  pure real(dp) function observed_order(err, ok, base, jmax) result(order)
    real(dp), intent(in) :: err(0:)
    logical, intent(in) :: ok(0:)
    integer, intent(in) :: base, jmax
    real(dp) :: x, y, sx, sy, sxx, sxy
    integer :: j, m
    sx = 0.0_dp
    sy = 0.0_dp
    sxx = 0.0_dp
    sxy = 0.0_dp
    m = 0
    do j = jmax / 2, jmax
      if (.not. ok(j) .or. .not. err(j) > 0.0_dp) cycle
      x = log(real(base, dp) * 2.0_dp**j)
      y = log(err(j))
      sx = sx + x
      sy = sy + y
      sxx = sxx + x * x
      sxy = sxy + x * y
      m = m + 1
    end do
    order = 0.0_dp
    if (m >= 2) order = -(m * sxy - sx * sy) / (m * sxx - sx * sx)
  end function observed_order

  !> CPU time to reach `target` beyond the finest run (level jmax), at the observed order over
  !> the finer half of the levels (cost proportional to the step count): -1 when the finest run
  !> failed or the order is below 0.5 (no meaningful extrapolation).
  pure real(dp) function extrapolate_cost(err, cpu, ok, base, jmax, target) result(t)
    real(dp), intent(in) :: err(0:), cpu(0:), target
    logical, intent(in) :: ok(0:)
    integer, intent(in) :: base, jmax
    real(dp) :: order
    t = -1.0_dp
    if (.not. ok(jmax)) return
    order = observed_order(err, ok, base, jmax)
    if (order > 0.5_dp) t = cpu(jmax) * (err(jmax) / target)**(1.0_dp / order)
  end function extrapolate_cost

  !> CPU time from which a configuration stays at or below `target`: from the last step count
  !> whose error is above it (or whose run failed), log-log interpolation to the next one; the
  !> coarsest run's time when every run reaches it. (The last crossing, not the first: a coarse
  !> run can look accurate only because its few steps miss the sharp part of the curve.)
  !> j_hi: the level of the first run at or below the target from which on all stay below.
  real(dp) function cost_at(err, cpu, ok, target, reached, j_hi) result(t)
    real(dp), intent(in) :: err(0:), cpu(0:), target
    logical, intent(in) :: ok(0:)
    logical, intent(out) :: reached
    integer, intent(out) :: j_hi
    integer :: j, jlast, jabove
    real(dp) :: w
    reached = .false.
    t = 0.0_dp
    j_hi = -1
    jlast = -1
    do j = 0, size(err) - 1
      if (ok(j)) jlast = j
    end do
    if (jlast < 0) return
    if (err(jlast) > target) return
    jabove = -1
    do j = 0, jlast
      if (.not. ok(j)) then
        jabove = j
      else if (err(j) > target) then
        jabove = j
      end if
    end do
    reached = .true.
    j_hi = jabove + 1
    if (jabove < 0) then
      t = cpu(0)
      return
    end if
    t = cpu(jabove + 1)
    if (ok(jabove) .and. err(jabove + 1) > 0.0_dp .and. cpu(jabove) > 0.0_dp .and. &
        cpu(jabove + 1) > 0.0_dp) then
      w = log(target / err(jabove)) / log(err(jabove + 1) / err(jabove))
      t = exp(log(cpu(jabove)) + w * log(cpu(jabove + 1) / cpu(jabove)))
    end if
  end function cost_at

end program interlock_bench
