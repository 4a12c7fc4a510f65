!> interlock-fuzz: random admissible materials and random separation histories (random walks
!> with reversals and jumps), checking after every update the invariants (D in [0,1] and
!> non-decreasing, zeta non-decreasing, theta between theta_f and theta_0, dissipations,
!> finite and bounded traction and tangent) and, every --fd-every updates, the tangent against
!> finite differences away from kinks (fuzz_fd_check, shared with --3d: central and one-sided
!> differences, Richardson-extrapolated, retried with smaller steps; columns whose differences
!> disagree among themselves straddle a kink and are skipped).
!> Every failing input is written and printed as a replay deck (docs/deck-format.md).
!>
!>   interlock-fuzz [--updates N] [--seed S] [--fd-every K] [--deck-dir DIR] [--max-decks M]
!>   interlock-fuzz --garbage N [--seed S]
!>   interlock-fuzz --3d N [--seed S] [--fd-every K] [--beyond-bound]
!>
!> With --garbage, N calls of the UMAT entries (the external UMAT with NTENS = 2 and 3, the
!> latter with the paper's and the azimuthal RIA; the thin layer with NTENS = 6 and 4, in Abaqus' and CalculiX's PNEWDT conventions) with garbage mixed into valid
!> input instead: NaN (quiet and signalling), +-Inf, denormals, huge and out-of-range values in
!> every argument the host passes (garbage_calls). Every call must either leave its outputs
!> untouched or return them finite, and PNEWDT as it came or as a request of its convention;
!> in the Debug build (FP traps on invalid, zero, overflow) any trap ends the run.
!>
!> With --3d, N calls of the three-dimensional update with random materials (azimuths
!> included), histories and garbage (fuzz_3d); --beyond-bound: garbage separations of any
!> finite magnitude, beyond separation_bound included.
!>
!> Exit status 0 when no invariant, tangent or status failure was found; 2 on a usage error (the
!> usage on stderr).
program interlock_fuzz
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan, &
      ieee_positive_inf, ieee_negative_inf
  use interlock_cli, only: exit_program, command_argument, folder_writable
  use interlock
  use interlock_material, only: n_schemes
  use interlock_replay, only: interlock_write_replay_deck
  use test_stability_tools
  use test_umat_interface, only: UMAT
  use fuzz_3d, only: fuzz_3d_counts_t, fuzz_3d_run
  use fuzz_fd_check, only: check_tangent_2d
  use interlock_umat_layer, only: interlock_umat_layer_point, host_abaqus, host_calculix, &
      layer_nstatv_extra, layer_nstatv_extra_3d
  implicit none

  integer(int64) :: n_updates = 100000_int64, done = 0_int64, n_fd = 0_int64, n_fd_skip = 0_int64
  integer :: seed = 1, fd_every = 10, max_decks = 5, n_decks = 0, n_fail = 0, n_materials = 0
  integer :: n_status = 0, n_stated = 0, worst_newton = 0, worst_attempts = 0
  character(len=:), allocatable :: deck_dir
  type(rng_t) :: rng
  real(dp) :: t0, t1
  integer(int64) :: n_garbage = 0_int64, n_3d = 0_int64
  type(fuzz_3d_counts_t) :: counts_3d
  logical :: beyond_bound = .false.

  !> The arguments of a UMAT call besides the material point's STRESS, STATEV, STRAN, DSTRAN
  !> and PROPS (the sizes NTENS, NSTATV, NPROPS are drawn with them).
  type :: host_arguments_t
    !> (DDSDDE as the UMAT sees it: its first NTENS**2 values are the NTENS x NTENS matrix)
    real(dp) :: ddsdde(36), sse, spd, scd, rpl, ddsddt(6), drplde(6), drpldt, pnewdt
    real(dp) :: time(2), dtime, temp, dtemp, predef(4), dpred(4), coords(3), drot(3, 3), &
                celent, dfgrd0(3, 3), dfgrd1(3, 3)
    integer :: ndi, nshr, noel, npt, layer, kspt, jstep(4), kinc
    character(len=12) :: cmname
  end type host_arguments_t


  call parse_arguments()
  call rng_seed(rng, seed)
  if (n_garbage > 0) then
    call garbage_calls()
    stop
  end if
  if (n_3d > 0) then
    call cpu_time(t0)
    call fuzz_3d_run(rng, n_3d, fd_every, beyond_bound, counts_3d)
    call cpu_time(t1)
    write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a,i0,a)') 'interlock-fuzz --3d: seed ', &
      seed, ', ', counts_3d%materials, ' materials (', counts_3d%materials_refused, &
      ' garbled ones refused), ', counts_3d%updates, ' updates (', counts_3d%garbage_s, &
      ' with a garbage separation, ', counts_3d%refused, ' refused)'
    write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,f8.2,a)') '  tangent checks ', &
      counts_3d%fd_checks, ' (', counts_3d%fd_skipped, ' skipped at kinks), stated ' // &
      'failures ', counts_3d%stated, ', failures ', counts_3d%failures, '; ', t1 - t0, ' s'
    if (counts_3d%failures > 0) error stop 1
    stop
  end if
  call cpu_time(t0)
  do while (done < n_updates)
    call one_history()
  end do
  call cpu_time(t1)
  write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a)') 'interlock-fuzz: seed ', seed, ', ', &
    n_materials, ' materials, ', done, ' updates, ', n_fd, ' tangent checks (', n_fd_skip, &
    ' skipped at kinks)'
  write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,f8.2,a)') '  failures ', n_fail, &
    ' (status failures ', n_status, '), worst Newton iterations ', worst_newton, &
    ', worst sub-increments tried ', worst_attempts, '; ', t1 - t0, ' s'
  write (output_unit, '(a,i0,a)') '  stated failures (explicit wear on tiny sub-increments, ' // &
    'the core names the remedy): ', n_stated, ' histories ended'
  if (n_fail > 0) error stop 1

contains

  subroutine parse_arguments()
    integer :: i, n, ios
    character(len=:), allocatable :: arg, val
    deck_dir = '.'
    val = ''
    n = command_argument_count()
    i = 1
    do while (i <= n)
      arg = command_argument(i)
      select case (arg)
      case ('-h', '--help')
        call usage(output_unit)
        call exit_program(0)
      case ('--beyond-bound')
        beyond_bound = .true.
      case ('--version')
        write (output_unit, '(a)') 'interlock-fuzz ' // interlock_version_string
        call exit_program(0)
      case ('--updates', '--seed', '--fd-every', '--deck-dir', '--max-decks', '--garbage', &
            '--3d')
        if (i == n) call usage_error(arg // ' needs a value')
        val = command_argument(i + 1)
        ios = 0
        select case (arg)
        case ('--updates')
          read (val, *, iostat=ios) n_updates
          if (ios == 0 .and. n_updates < 1) ios = 1
        case ('--seed')
          read (val, *, iostat=ios) seed
        case ('--fd-every')
          read (val, *, iostat=ios) fd_every
          if (ios == 0 .and. fd_every < 1) ios = 1
        case ('--deck-dir')
          deck_dir = val
          ! the replay decks' paths are held in 512 characters (report)
          if (len(deck_dir) > 450) call usage_error('--deck-dir: a path of ' // &
            'at most 450 characters (the replay decks'' names follow it)')
          if (.not. folder_writable(deck_dir)) call usage_error('--deck-dir ' // deck_dir // &
            ': no such folder, or not writable (it must exist and be writable)')
        case ('--max-decks')
          read (val, *, iostat=ios) max_decks
          if (ios == 0 .and. max_decks < 0) ios = 1
        case ('--garbage')
          read (val, *, iostat=ios) n_garbage
          if (ios == 0 .and. n_garbage < 1) ios = 1
        case ('--3d')
          read (val, *, iostat=ios) n_3d
          if (ios == 0 .and. n_3d < 1) ios = 1
        end select
        if (ios /= 0) call usage_error(arg // ' ' // val // ': not an admissible ' // &
          'value (--updates, --fd-every, --garbage, --3d: integers >= 1; --seed: an integer; ' // &
          '--max-decks >= 0)')
        i = i + 1
      case default
        call usage_error('unknown argument ' // arg)
      end select
      i = i + 1
    end do
  end subroutine parse_arguments

  subroutine usage(unit)
    integer, intent(in) :: unit
    write (unit, '(a)') 'usage: interlock-fuzz [--updates N] [--seed S] ' // &
      '[--fd-every K] [--deck-dir DIR] [--max-decks M] | --garbage N [--seed S] | ' // &
      '--3d N [--seed S] [--fd-every K] [--beyond-bound] | --help | --version'
  end subroutine usage

  subroutine usage_error(message)
    character(len=*), intent(in) :: message
    write (error_unit, '(a)') 'interlock-fuzz: error: ' // message
    call usage(error_unit)
    call exit_program(2)
  end subroutine usage_error


  !> A value for a slot that held `x`: usually x, sometimes garbage.
  function garble(x, p) result(y)
    real(dp), intent(in) :: x, p
    real(dp) :: y
    real(dp) :: u
    y = x
    if (rng_uniform(rng) >= p) return
    u = rng_uniform(rng)
    select case (rng_int(rng, 1, 13))
    case (1)
      y = ieee_value(1.0_dp, ieee_quiet_nan)
    case (13)                                     ! signalling NaN (traps in any float test)
      y = transfer(ior(shiftl(2047_int64, 52), 1_int64), 1.0_dp)
    case (2)
      y = ieee_value(1.0_dp, ieee_positive_inf)
    case (3)
      y = ieee_value(1.0_dp, ieee_negative_inf)
    case (4)
      y = 1.0e-310_dp * (1.0_dp + u)            ! denormal
    case (5)
      y = -1.0e-310_dp * (1.0_dp + u)
    case (6)
      y = huge(1.0_dp) * (0.5_dp + 0.5_dp * u)
    case (7)
      y = -huge(1.0_dp) * (0.5_dp + 0.5_dp * u)
    case (8)
      y = 10.0_dp**(600.0_dp * u - 300.0_dp)    ! any magnitude
    case (9)
      y = -10.0_dp**(600.0_dp * u - 300.0_dp)
    case (10)
      y = 0.0_dp
    case (11)                                     ! out of range nearby
      if (is_finite_bits(x)) then
        if (abs(x) < 1.0e300_dp) y = x * (1.0_dp + 10.0_dp * (u - 0.5_dp))
      end if
    case default
      y = -x
    end select
  end function garble

  !> --garbage: calls of the three entries a host uses (the external 2D UMAT, Abaqus'
  !> convention; the thin layer with NTENS = 6 and 4 in Abaqus' and CalculiX's conventions)
  !> with garbage now and then in every argument the host passes: PROPS, STATEV, STRESS,
  !> STRAN, DSTRAN, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT, PNEWDT on entry, the sizes
  !> (NTENS, NSTATV, NPROPS, NDI, NSHR), TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, COORDS,
  !> DROT, CELENT, DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC and CMNAME. Each call
  !> must leave its outputs (STRESS, the STATEV it owns, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT,
  !> DRPLDE, DRPLDT) untouched or return them all finite, and return PNEWDT as it came or as a
  !> request of its convention (Abaqus: finite, < 1; CalculiX: in (0, 1)); any trap of the
  !> Debug build ends the run.
  subroutine garbage_calls()
    integer, parameter :: entry_umat = 1, entry_layer = 2, entry_ntens(5) = [2, 6, 6, 4, 3]
    !> STATEV slots of a point: the 3D law's with N_a = 6 and the layer's six
    integer, parameter :: max_statev = 8 * (1 + 2 * max_azimuths) + 4 + 6
    real(dp), parameter :: props_base(14) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 2.0_dp, &
      30.0_dp, 7.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.25_dp, 1.0_dp]
    !> One point of each entry kind (host side): what the host keeps between calls.
    type :: garbage_point_t
      real(dp) :: stress(6) = 0.0_dp, statev(max_statev) = 0.0_dp, stran(6) = 0.0_dp
    end type garbage_point_t
    type(garbage_point_t) :: points(5), pt, before
    type(host_arguments_t) :: args, args_in
    real(dp) :: props(n_properties + 4), dstran(6), p, h
    integer :: n_props, k, which, entry, host, ntens, nstatv, owned, law_nstatv, extra
    integer(int64) :: call_no, n_rejected(2), n_bad, n_calls(2)
    logical :: touched
    n_rejected = 0
    n_calls = 0
    n_bad = 0
    do call_no = 1, n_garbage
      p = merge(0.005_dp, 0.1_dp, rng_uniform(rng) < 0.5_dp)
      which = rng_int(rng, 1, 5)   ! UMAT 2D; layer NTENS 6 Abaqus, 6 ccx, 4 either; UMAT 3D
      entry = merge(entry_umat, entry_layer, which == 1 .or. which == 5)
      host = host_abaqus
      if (which == 3) host = host_calculix
      if (rng_uniform(rng) < 0.5_dp .and. which == 4) host = host_calculix
      ntens = entry_ntens(which)
      ! PROPS: the interlock ones after the layer's head (h, e_other, normal, slip); a 3D
      ! point has the azimuthal RIA now and then (the same for the point's whole life).
      n_props = rng_int(rng, n_required_properties, n_properties)
      props = 0.0_dp
      props(5:4 + n_properties) = properties%default
      law_nstatv = umat_nstatv
      extra = merge(0, layer_nstatv_extra, entry == entry_umat)
      if (ntens == 3 .or. ntens == 6) then
        if (which == 5) then
          n_props = n_properties
          props(4 + prop_ria) = real(ria_azimuthal, dp)
          props(4 + prop_n_azimuths) = 3.0_dp
        end if
        law_nstatv = umat_nstatv_3d(props_n_planes_3d(n_props, props(5:4 + n_props)))
        if (entry == entry_layer) extra = layer_nstatv_extra_3d
      end if
      if (rng_uniform(rng) < p / 8.0_dp) ntens = rng_int(rng, 1, 6)
      nstatv = merge(law_nstatv, law_nstatv + extra, rng_uniform(rng) < 0.5_dp)
      if (rng_uniform(rng) < p / 8.0_dp) nstatv = rng_int(rng, 1, max_statev)
      props(5:18) = props_base
      props(14) = merge(1.0_dp, 0.0_dp, rng_uniform(rng) < 0.2_dp)
      props(15) = real(rng_int(rng, 1, n_schemes), dp)
      props(16) = merge(1.0e-3_dp, 0.0_dp, rng_uniform(rng) < 0.2_dp)
      h = 10.0_dp**(rng_uniform(rng) * 4.0_dp - 3.0_dp)
      if (ntens == 4) then
        k = rng_int(rng, 1, 2)
        props(1:4) = [h, 0.01_dp, real(k, dp), real(3 - k, dp)]
      else
        k = rng_int(rng, 1, 3)
        props(1:4) = [h, 0.01_dp, real(k, dp), real(1 + mod(k + rng_int(rng, 0, 1), 3), dp)]
      end if
      do k = 1, 4 + n_props
        props(k) = garble(props(k), p / 4.0_dp)
      end do
      ! The slots the entry writes, for the NTENS it is given (a garbled NTENS selects the other
      ! law: the layer with NTENS = 4 runs the 2D law and writes its slots only; an NTENS that
      ! selects no law is refused) and the RIA that PROPS 21-22 select (garbled ones may select
      ! another admissible RIA).
      law_nstatv = umat_nstatv
      extra = merge(0, layer_nstatv_extra, entry == entry_umat)
      if (ntens == merge(3, 6, entry == entry_umat)) then
        law_nstatv = umat_nstatv_3d(planes_3d(props(5:4 + n_props)))
        if (entry == entry_layer) extra = layer_nstatv_extra_3d
      end if
      ! The point: carried on from its last accepted call, with garbage now and then.
      pt = points(which)
      if (rng_uniform(rng) < 0.05_dp) pt = garbage_point_t()       ! a fresh point
      do k = 1, max_statev
        pt%statev(k) = garble(pt%statev(k), p / 8.0_dp)
      end do
      do k = 1, 6
        pt%stress(k) = garble(pt%stress(k), p / 8.0_dp)
        pt%stran(k) = garble(pt%stran(k), p / 8.0_dp)
        dstran(k) = garble(0.1_dp * (rng_uniform(rng) - 0.5_dp) * &
                           merge(0.2_dp, 1.0_dp / h * 0.05_dp, entry == entry_umat), p / 4.0_dp)
      end do
      call garbage_host_arguments(args, ntens, host, p)
      args_in = args
      before = pt
      select case (entry)
      case (entry_umat)
        call UMAT(pt%stress, pt%statev, args%ddsdde, args%sse, args%spd, args%scd, args%rpl, &
                  args%ddsddt, args%drplde, args%drpldt, pt%stran, dstran, args%time, &
                  args%dtime, args%temp, args%dtemp, args%predef, args%dpred, &
                  trim(args%cmname), args%ndi, args%nshr, ntens, nstatv, props(5:4 + n_props), &
                  n_props, args%coords, args%drot, args%pnewdt, args%celent, args%dfgrd0, &
                  args%dfgrd1, args%noel, args%npt, args%layer, args%kspt, args%jstep, args%kinc)
        owned = min(nstatv, law_nstatv)
      case default
        call interlock_umat_layer_point(pt%stress, pt%statev, args%ddsdde, args%sse, args%spd, &
          args%scd, args%rpl, args%ddsddt, args%drplde, args%drpldt, pt%stran, dstran, &
          args%time, args%dtime, args%temp, args%dtemp, args%predef, args%dpred, &
          trim(args%cmname), args%ndi, args%nshr, ntens, nstatv, props, 4 + n_props, &
          args%coords, args%drot, args%pnewdt, args%celent, args%dfgrd0, args%dfgrd1, &
          args%noel, args%npt, args%layer, args%kspt, args%jstep, args%kinc, host)
        owned = min(nstatv, law_nstatv)
        if (nstatv >= law_nstatv + extra) owned = law_nstatv + extra
      end select
      n_calls(entry) = n_calls(entry) + 1
      touched = .not. (all(same_bits(pt%stress(1:ntens), before%stress(1:ntens))) .and. &
                       all(same_bits(pt%statev(1:owned), before%statev(1:owned))) .and. &
                       outputs_same(args, args_in, ntens))
      if (.not. pnewdt_admissible(args_in%pnewdt, args%pnewdt, host)) then
        n_bad = n_bad + 1
        write (output_unit, '(a,i0,a,es12.4,a,es12.4)') 'FAIL garbage call ', call_no, &
          ': PNEWDT in ', args_in%pnewdt, ', out ', args%pnewdt
      end if
      if (.not. touched) then
        if (.not. same_bits(args%pnewdt, args_in%pnewdt)) n_rejected(entry) = n_rejected(entry) + 1
      else if (.not. (all(is_finite_bits(pt%stress(1:ntens))) .and. &
                      all(is_finite_bits(pt%statev(1:owned))) .and. &
                      outputs_finite(args, ntens))) then
        n_bad = n_bad + 1
        write (output_unit, '(a,i0,a,i0,a,i0,a,i0)') 'FAIL garbage call ', call_no, &
          ': accepted, not finite; entry ', entry, ', host ', host, ', NTENS ', ntens
        write (output_unit, '(a,4l2)') '  not finite: STRESS, STATEV, the others ', &
          .not. all(is_finite_bits(pt%stress(1:ntens))), &
          .not. all(is_finite_bits(pt%statev(1:owned))), .not. outputs_finite(args, ntens)
        write (output_unit, '(a,24es10.2)') '  PROPS ', props(1:4 + n_props)
        write (output_unit, '(a,6es10.2)') '  STRAN ', pt%stran(1:ntens)
        write (output_unit, '(a,6es10.2)') '  DSTRAN ', dstran(1:ntens)
      else if (.not. same_bits(args%pnewdt, args_in%pnewdt) .and. host == host_calculix) then
        continue            ! an accuracy request: the host discards the attempt
      else
        ! accepted: the host goes on from the end of the increment
        pt%stran(1:ntens) = pt%stran(1:ntens) + dstran(1:ntens)
        points(which) = pt
      end if
      if (.not. all(is_finite_bits(points(which)%stran))) then
        points(which)%stran = 0.0_dp
      else if (.not. all(abs(points(which)%stran) <= 1.0e3_dp)) then
        points(which)%stran = 0.0_dp
      end if
    end do
    write (output_unit, '(a,i0,a,i0,a,i0,a,i0)') 'interlock-fuzz --garbage: seed ', seed, ', ', &
      n_calls(entry_umat), ' UMAT calls (NTENS 2 and 3), ', n_rejected(entry_umat), &
      ' rejected, failures ', n_bad
    write (output_unit, '(a,i0,a,i0,a)') '  thin layer (NTENS 6 and 4, Abaqus and CalculiX): ', &
      n_calls(entry_layer), ' calls, ', n_rejected(entry_layer), ' rejected'
    if (n_bad > 0) error stop 1

  end subroutine garbage_calls

  !> The planes of the RIA that PROPS select in 3D (props_n_planes_3d), read by the bits of
  !> PROPS 21-22 (no comparison of garbage): 3 unless ria is exactly 1 and n_azimuths a whole
  !> number of range.
  pure integer function planes_3d(props) result(n_planes)
    real(dp), intent(in) :: props(:)
    integer :: a, n_azimuths
    n_planes = 3
    if (size(props) < prop_ria) return
    if (.not. same_bits(props(prop_ria), real(ria_azimuthal, dp))) return
    n_azimuths = nint(properties(prop_n_azimuths)%default)
    if (size(props) >= prop_n_azimuths) then
      do a = 1, max_azimuths
        if (same_bits(props(prop_n_azimuths), real(a, dp))) n_azimuths = a
      end do
    end if
    n_planes = 1 + 2 * n_azimuths
  end function planes_3d

  !> a and b have the same bits (NaN equals NaN; no comparison of a NaN).
  elemental logical function same_bits(x, y)
    real(dp), intent(in) :: x, y
    same_bits = transfer(x, 1_int64) == transfer(y, 1_int64)
  end function same_bits

  !> Every argument of a UMAT call that is not the material point's own (host side).
  subroutine garbage_host_arguments(a, ntens, host, p)
    type(host_arguments_t), intent(out) :: a
    integer, intent(in) :: ntens, host
    real(dp), intent(in) :: p
    character(len=*), parameter :: names(5) = [character(len=12) :: 'FUZZ', 'FUZZ_B', '', &
      'fuzz c', 'FUZZ' // achar(9) // 'D']
    integer :: i, j
    a%ddsdde = 7.5_dp
    a%sse = rng_uniform(rng)
    a%spd = 0.0_dp
    a%scd = rng_uniform(rng)
    a%rpl = 0.0_dp
    a%ddsddt = 0.0_dp
    a%drplde = 0.0_dp
    a%drpldt = 0.0_dp
    a%pnewdt = merge(-1.0_dp, 1.0_dp, host == host_calculix)
    a%time = [rng_uniform(rng), 1.0_dp + rng_uniform(rng)]
    a%dtime = 0.1_dp
    a%temp = 20.0_dp
    a%dtemp = 0.0_dp
    a%predef = 0.0_dp
    a%dpred = 0.0_dp
    a%coords = [rng_uniform(rng), rng_uniform(rng), rng_uniform(rng)]
    a%drot = 0.0_dp
    do i = 1, 3
      a%drot(i, i) = 1.0_dp
    end do
    a%celent = 1.0_dp
    a%dfgrd0 = a%drot
    a%dfgrd1 = a%drot
    ! (the reals now and then garbage; what the host may leave uninitialised, as ccx does
    ! with LAYER, KSPT, CELENT, PREDEF and DPRED, most often)
    do j = 1, ntens
      do i = 1, ntens
        a%ddsdde(i + ntens * (j - 1)) = garble(a%ddsdde(i + ntens * (j - 1)), p)
      end do
      a%ddsddt(j) = garble(a%ddsddt(j), p)
      a%drplde(j) = garble(a%drplde(j), p)
    end do
    a%sse = garble(a%sse, p)
    a%spd = garble(a%spd, p)
    a%scd = garble(a%scd, p)
    a%rpl = garble(a%rpl, p)
    a%drpldt = garble(a%drpldt, p)
    a%pnewdt = garble(a%pnewdt, p / 2.0_dp)
    a%time = [garble(a%time(1), p), garble(a%time(2), p)]
    a%dtime = garble(a%dtime, p)
    a%temp = garble(a%temp, p)
    a%dtemp = garble(a%dtemp, p)
    do i = 1, size(a%predef)
      a%predef(i) = garble(a%predef(i), 5.0_dp * p)
      a%dpred(i) = garble(a%dpred(i), 5.0_dp * p)
    end do
    do i = 1, 3
      a%coords(i) = garble(a%coords(i), p)
      do j = 1, 3
        a%drot(i, j) = garble(a%drot(i, j), p)
        a%dfgrd0(i, j) = garble(a%dfgrd0(i, j), p)
        a%dfgrd1(i, j) = garble(a%dfgrd1(i, j), p)
      end do
    end do
    a%celent = garble(a%celent, 5.0_dp * p)
    a%ndi = garble_integer(3, p)
    a%nshr = garble_integer(ntens - 3, p)
    a%noel = garble_integer(rng_int(rng, 1, 100000), p)
    a%npt = garble_integer(rng_int(rng, 1, 8), p)
    a%layer = garble_integer(1, 5.0_dp * p)
    a%kspt = garble_integer(1, 5.0_dp * p)
    a%jstep = [garble_integer(1, p), garble_integer(1, p), garble_integer(0, p), &
               garble_integer(0, p)]
    a%kinc = garble_integer(rng_int(rng, 1, 1000), p)
    a%cmname = names(1)
    if (rng_uniform(rng) < p) a%cmname = names(rng_int(rng, 1, size(names)))
  end subroutine garbage_host_arguments

  !> An integer argument that held `n`: usually n, sometimes garbage.
  integer function garble_integer(n, p) result(m)
    integer, intent(in) :: n
    real(dp), intent(in) :: p
    m = n
    if (rng_uniform(rng) >= p) return
    select case (rng_int(rng, 1, 5))
    case (1)
      m = huge(0)
    case (2)
      m = -huge(0) - 1
    case (3)
      m = 0
    case (4)
      m = -1
    case default
      m = rng_int(rng, -1000000, 1000000)
    end select
  end function garble_integer

  !> The outputs in `a` (DDSDDE, the energies, the thermal ones) bitwise those of `b`.
  logical function outputs_same(a, b, ntens)
    type(host_arguments_t), intent(in) :: a, b
    integer, intent(in) :: ntens
    outputs_same = all(same_bits(a%ddsdde(1:ntens**2), b%ddsdde(1:ntens**2))) .and. &
      all(same_bits([a%sse, a%spd, a%scd, a%rpl, a%drpldt], &
                    [b%sse, b%spd, b%scd, b%rpl, b%drpldt])) .and. &
      all(same_bits(a%ddsddt(1:ntens), b%ddsddt(1:ntens))) .and. &
      all(same_bits(a%drplde(1:ntens), b%drplde(1:ntens)))
  end function outputs_same

  logical function outputs_finite(a, ntens)
    type(host_arguments_t), intent(in) :: a
    integer, intent(in) :: ntens
    outputs_finite = all(is_finite_bits(a%ddsdde(1:ntens**2))) .and. &
      all(is_finite_bits([a%sse, a%spd, a%scd, a%rpl, a%drpldt])) .and. &
      all(is_finite_bits(a%ddsddt(1:ntens))) .and. all(is_finite_bits(a%drplde(1:ntens)))
  end function outputs_finite

  !> PNEWDT on return is the value that came in, or a request of the host's convention; a NaN
  !> that came in may also come back as the host's "no request" (-1 ccx, 1 Abaqus).
  logical function pnewdt_admissible(p_in, p_out, host)
    real(dp), intent(in) :: p_in, p_out
    integer, intent(in) :: host
    pnewdt_admissible = same_bits(p_in, p_out)
    if (pnewdt_admissible .or. .not. is_finite_bits(p_out)) return
    pnewdt_admissible = is_nan_value(p_in) .and. &
                        same_bits(p_out, merge(-1.0_dp, 1.0_dp, host == host_calculix))
    if (pnewdt_admissible) return
    if (host == host_calculix) then
      pnewdt_admissible = p_out > 0.0_dp .and. p_out < 1.0_dp
    else
      pnewdt_admissible = p_out < 1.0_dp
    end if
  end function pnewdt_admissible

  !> A random admissible material and solver.
  subroutine random_material(mat, solver)
    type(interlock_material_t), intent(out) :: mat
    type(interlock_solver_t), intent(out) :: solver
    real(dp) :: scale, sc, th0, thf, z0, g(max_planes)
    integer :: k, n, stat
    character(len=message_len) :: message
    do
      scale = rng_log_uniform(rng, 1.0e-6_dp, 1.0e3_dp)
      mat%sigma0_n = 3.0_dp * scale * rng_log_uniform(rng, 0.1_dp, 10.0_dp)
      mat%sigma0_t = 3.0_dp * scale * rng_log_uniform(rng, 0.1_dp, 10.0_dp)
      sc = rng_log_uniform(rng, 1.0e-3_dp, 10.0_dp)          ! s_c of mode I [mm]
      mat%gc = 0.5_dp * sc * mat%sigma0_n
      mat%eta = 1.0_dp - rng_log_uniform(rng, 1.0e-5_dp, 0.95_dp)
      mat%mu = merge(0.0_dp, 2.0_dp * rng_uniform(rng), rng_uniform(rng) < 0.15_dp)
      if (rng_uniform(rng) < 0.2_dp) then
        mat%h_n = huge(1.0_dp)
      else
        mat%h_n = rng_log_uniform(rng, 1.0e-4_dp, 1.0e3_dp)
      end if
      mat%prefractured = rng_uniform(rng) < 0.2_dp
      z0 = merge(huge(1.0_dp), rng_log_uniform(rng, 1.0e-6_dp, 1.0e6_dp), &
                 rng_uniform(rng) < 0.25_dp)
      if (rng_uniform(rng) < 0.5_dp) then
        th0 = rng_uniform(rng) * 80.0_dp * deg_to_rad
        thf = th0 * merge(1.0_dp, rng_uniform(rng), rng_uniform(rng) < 0.2_dp)
        call interlock_paper_ria(mat, th0, thf, z0)
      else
        n = rng_int(rng, 1, max_planes)
        mat%n_planes = n
        do k = 1, n
          g(k) = 0.05_dp + rng_uniform(rng)
        end do
        mat%gamma_hat = 0.0_dp
        mat%phi = 0.0_dp
        mat%gamma_hat(1:n) = g(1:n) / sum(g(1:n))
        mat%gamma_hat(n) = 1.0_dp - sum(mat%gamma_hat(1:n - 1))
        do k = 1, n
          mat%theta0(k) = (2.0_dp * rng_uniform(rng) - 1.0_dp) * 85.0_dp * deg_to_rad
          mat%thetaf(k) = mat%theta0(k) * rng_uniform(rng)
          mat%zeta0(k) = z0
          if (.not. is_infinite_value(z0)) mat%zeta0(k) = z0 * rng_log_uniform(rng, 0.1_dp, 10.0_dp)
        end do
      end if
      do k = 1, n_effects
        mat%effect(k) = rng_uniform(rng) > 0.1_dp
      end do
      call interlock_material_prepare(mat, stat, message)
      if (stat == status_ok) exit
    end do
    ! (every scheme of the library: interlock_material:n_schemes)
    solver%scheme = rng_int(rng, 1, n_schemes)
    solver%substep_tol = 0.0_dp
    if (rng_uniform(rng) < 0.3_dp) solver%substep_tol = rng_log_uniform(rng, 1.0e-5_dp, 1.0e-2_dp)
  end subroutine random_material

  !> One material, one random separation history.
  subroutine one_history()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: s(2), ds(2), dir(2), len_t, len_n, lo_n, hi_n, sigma(2), tangent(2, 2), step
    integer :: i, n_steps
    character(len=200) :: what

    call random_material(mat, solver)
    n_materials = n_materials + 1
    call interlock_state_init(mat, old)
    len_t = mat%sct
    len_n = mat%scn
    lo_n = -3.0_dp * mat%s0n
    hi_n = 3.0_dp * len_n
    if (mat%use_depth) hi_n = min(max(hi_n, 1.5_dp * mat%h_n), 10.0_dp * max(len_n, mat%h_n))
    n_steps = rng_int(rng, 20, 300)
    dir = [rng_uniform(rng) - 0.5_dp, rng_uniform(rng) - 0.5_dp]
    do i = 1, n_steps
      if (done >= n_updates) return
      if (rng_uniform(rng) < 0.1_dp) dir = -dir                          ! reversal
      if (rng_uniform(rng) < 0.2_dp) dir = [rng_uniform(rng) - 0.5_dp, rng_uniform(rng) - 0.5_dp]
      step = rng_log_uniform(rng, 1.0e-6_dp, 0.2_dp)
      if (rng_uniform(rng) < 0.03_dp) step = rng_log_uniform(rng, 0.5_dp, 5.0_dp)   ! jump
      if (rng_uniform(rng) < 0.02_dp) step = 1.0e-9_dp / len_t                     ! 1e-9 mm
      ds = step * [dir(1) * len_n, dir(2) * len_t] / max(norm2(dir), 1.0e-3_dp)
      s = old%s + ds
      ! keep the walk in a physical window: interpenetration of a few s_0n at most
      if (s(1) < lo_n) s(1) = lo_n + rng_uniform(rng) * mat%s0n
      if (s(1) > hi_n) s(1) = hi_n * rng_uniform(rng)
      if (abs(s(2)) > 5.0_dp * len_t) s(2) = sign(5.0_dp * len_t * rng_uniform(rng), s(2))
      call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
      done = done + 1
      worst_newton = max(worst_newton, info%newton_iterations)
      worst_attempts = max(worst_attempts, info%attempts)
      if (info%status /= status_ok) then
        if (index(info%message, 'unstable on small sub-increments') > 0) then
          ! A stated failure with its remedy (explicit wear update, error-controlled
          ! substepping): counted, the history ends here.
          n_stated = n_stated + 1
          return
        end if
        n_status = n_status + 1
        call report(mat, solver, old, s, 'status failure: ' // trim(info%message))
        return
      end if
      call check_update(mat, old, new, sigma, tangent, what)
      if (len_trim(what) > 0) then
        call report(mat, solver, old, s, 'invariant: ' // trim(what))
        return
      end if
      if (fd_every > 0) then
        if (mod(done, int(fd_every, int64)) == 0) then
          call check_tangent_2d(mat, solver, old, s, sigma, tangent, what, n_fd, n_fd_skip)
          if (len_trim(what) > 0) then
            call report(mat, solver, old, s, 'tangent: ' // trim(what))
            return
          end if
        end if
      end if
      old = new
    end do
  end subroutine one_history

  !> Write the failing input as a replay deck and print it.
  subroutine report(mat, solver, old, s, why)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(2)
    character(len=*), intent(in) :: why
    character(len=512) :: path, line
    integer :: ios, u
    n_fail = n_fail + 1
    write (output_unit, '(a,i0,a)') 'FAILURE at update ', done, ': ' // trim(why)
    if (n_decks >= max_decks) return
    n_decks = n_decks + 1
    write (path, '(a,a,i0,a,i0,a)') trim(deck_dir), '/fuzz_seed', seed, '_fail', n_decks, '.nml'
    call interlock_write_replay_deck(trim(path), mat, solver, old, s, why, ios)
    if (ios /= 0) then
      write (output_unit, '(a)') '  (could not write ' // trim(path) // ')'
      return
    end if
    write (output_unit, '(a)') '  replay deck ' // trim(path) // ':'
    open (newunit=u, file=trim(path), status='old', action='read', iostat=ios)
    do while (ios == 0)
      read (u, '(a)', iostat=ios) line
      if (ios == 0) write (output_unit, '(4x,a)') trim(line)
    end do
    close (u)
  end subroutine report

end program interlock_fuzz
