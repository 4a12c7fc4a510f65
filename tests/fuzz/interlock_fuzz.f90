!> interlock-fuzz: random admissible materials and random separation histories (random walks
!> with reversals and jumps), checking after every update the invariants (D in [0,1] and
!> non-decreasing, zeta non-decreasing, theta between theta_f and theta_0, dissipations,
!> finite and bounded traction and tangent) and, every --fd-every updates, the tangent against
!> central finite differences away from kinks (points where finite differences with two step
!> sizes, or the one-sided ones, disagree are skipped as a branch switch within the stencil).
!> Every failing input is written and printed as a replay deck (docs/deck-format.md).
!>
!>   interlock-fuzz [--updates N] [--seed S] [--fd-every K] [--deck-dir DIR] [--max-decks M]
!>   interlock-fuzz --garbage N [--seed S]
!>
!> With --garbage, N calls of the external UMAT with garbage mixed into valid input instead:
!> NaN (quiet and signalling), +-Inf, denormals, huge and out-of-range values in PROPS, STATEV,
!> STRESS, STRAN and DSTRAN. Every call must either be rejected (PNEWDT < 1, STRESS, STATEV,
!> DDSDDE, SSE and SCD untouched, one message line) or return finite outputs; in the Debug
!> build (FP traps on invalid, zero, overflow) any trap ends the run.
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
  use test_umat_interface, only: umat_point_t, call_umat
  implicit none

  integer(int64) :: n_updates = 100000_int64, done = 0_int64, n_fd = 0_int64, n_fd_skip = 0_int64
  integer :: seed = 1, fd_every = 10, max_decks = 5, n_decks = 0, n_fail = 0, n_materials = 0
  integer :: n_status = 0, n_stated = 0, worst_newton = 0, worst_attempts = 0
  character(len=:), allocatable :: deck_dir
  type(rng_t) :: rng
  real(dp) :: t0, t1
  integer(int64) :: n_garbage = 0_int64


  call parse_arguments()
  call rng_seed(rng, seed)
  if (n_garbage > 0) then
    call garbage_calls()
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
    n = command_argument_count()
    i = 1
    do while (i <= n)
      arg = command_argument(i)
      select case (arg)
      case ('-h', '--help')
        call usage(output_unit)
        call exit_program(0)
      case ('--version')
        write (output_unit, '(a)') 'interlock-fuzz ' // interlock_version_string
        call exit_program(0)
      case ('--updates', '--seed', '--fd-every', '--deck-dir', '--max-decks', '--garbage')
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
        end select
        if (ios /= 0) call usage_error(arg // ' ' // val // ': not an admissible ' // &
          'value (--updates, --fd-every, --garbage: integers >= 1; --seed: an integer; ' // &
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
      '[--fd-every K] [--deck-dir DIR] [--max-decks M] | --garbage N [--seed S] | --help | ' // &
      '--version'
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

  !> --garbage: UMAT calls with garbage in every input; each call rejected with its outputs
  !> untouched, or finite.
  subroutine garbage_calls()
    real(dp), parameter :: props_base(14) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 2.0_dp, &
      30.0_dp, 7.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.25_dp, 1.0_dp]
    type(umat_point_t) :: pt, before
    real(dp) :: props(n_properties), stran(2), dstran(2), p
    integer :: n_props, k, n_rejected, n_bad
    integer(int64) :: call_no
    allocate (pt%stress(2), pt%statev(umat_nstatv), pt%ddsdde(2, 2))
    n_rejected = 0
    n_bad = 0
    pt%stress = 0.0_dp
    pt%statev = 0.0_dp
    pt%ddsdde = 0.0_dp
    stran = 0.0_dp
    do call_no = 1, n_garbage
      p = merge(0.005_dp, 0.1_dp, rng_uniform(rng) < 0.5_dp)
      n_props = rng_int(rng, 9, n_properties)
      props = properties%default
      props(1:14) = props_base
      props(10) = merge(1.0_dp, 0.0_dp, rng_uniform(rng) < 0.2_dp)
      props(11) = real(rng_int(rng, 1, n_schemes), dp)
      props(12) = merge(1.0e-3_dp, 0.0_dp, rng_uniform(rng) < 0.2_dp)
      do k = 1, n_props
        props(k) = garble(props(k), p / 4.0_dp)
      end do
      if (rng_uniform(rng) < 0.05_dp) then          ! a fresh point
        pt%statev = 0.0_dp
        pt%stress = 0.0_dp
        stran = 0.0_dp
      end if
      do k = 1, umat_nstatv
        pt%statev(k) = garble(pt%statev(k), p / 8.0_dp)
      end do
      pt%stress = [garble(pt%stress(1), p / 8.0_dp), garble(pt%stress(2), p / 8.0_dp)]
      stran = [garble(stran(1), p / 8.0_dp), garble(stran(2), p / 8.0_dp)]
      dstran = [0.02_dp * (rng_uniform(rng) - 0.5_dp), 0.05_dp * (rng_uniform(rng) - 0.5_dp)]
      dstran = [garble(dstran(1), p / 4.0_dp), garble(dstran(2), p / 4.0_dp)]
      before = pt
      pt%pnewdt = 1.0_dp
      call call_umat(pt, props(1:n_props), stran, dstran, 1, 1, int(min(call_no, 2000000000_int64)))
      if (pt%pnewdt < 0.0_dp) then
        n_rejected = n_rejected + 1
        if (changed(before, pt)) then
          n_bad = n_bad + 1
          write (output_unit, '(a,i0,a)') 'FAIL garbage call ', call_no, &
            ': rejected but outputs changed'
        end if
      else if (.not. changed(before, pt)) then
        ! untouched: a local failure (PNEWDT 0.5) or a zero increment
        if (pt%pnewdt < 1.0_dp) n_rejected = n_rejected + 1
      else if (.not. (all(is_finite_bits(pt%stress)) .and. all(is_finite_bits(pt%ddsdde)) .and. &
                      all(is_finite_bits(pt%statev)) .and. is_finite_bits(pt%sse) .and. &
                      is_finite_bits(pt%scd))) then
        n_bad = n_bad + 1
        write (output_unit, '(a,i0,a)') 'FAIL garbage call ', call_no, ': accepted, not finite'
        write (output_unit, '(a,19es10.2)') '  PROPS ', props(1:n_props)
        write (output_unit, '(a,22es10.2)') '  STATEV in ', before%statev
        write (output_unit, '(a,6es10.2)') '  STRESS, STRAN, DSTRAN ', before%stress, stran, dstran
      else
        ! accepted: the host goes on from the end of the increment
        stran = stran + dstran
      end if
      if (.not. all(is_finite_bits(stran))) then
        stran = 0.0_dp
      else if (.not. all(abs(stran) <= 1.0e3_dp)) then
        stran = 0.0_dp
      end if
    end do
    write (output_unit, '(a,i0,a,i0,a,i0,a,i0)') 'interlock-fuzz --garbage: seed ', seed, ', ', &
      n_garbage, ' UMAT calls, ', n_rejected, ' rejected, failures ', n_bad
    if (n_bad > 0) error stop 1
  end subroutine garbage_calls

  !> Whether any output of the UMAT differs (bitwise; NaN equals NaN) between a and b.
  logical function changed(a, b)
    type(umat_point_t), intent(in) :: a, b
    changed = .not. (all(same_bits(a%stress, b%stress)) .and. all(same_bits(a%statev, b%statev)) &
                     .and. all(same_bits(a%ddsdde, b%ddsdde)) .and. same_bits(a%sse, b%sse) &
                     .and. same_bits(a%scd, b%scd))
  end function changed

  elemental logical function same_bits(x, y)
    real(dp), intent(in) :: x, y
    same_bits = transfer(x, 1_int64) == transfer(y, 1_int64)
  end function same_bits

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
          call check_tangent(mat, solver, old, s, sigma, tangent, what)
          if (len_trim(what) > 0) then
            call report(mat, solver, old, s, 'tangent: ' // trim(what))
            return
          end if
        end if
      end if
      old = new
    end do
  end subroutine one_history

  !> The tangent against finite differences of the traction (same start state), column by
  !> column. Central differences with steps h and h/2, and the one-sided ones, must agree with
  !> each other (else a kink lies within the stencil: skipped); the tangent must then match the
  !> central or a one-sided difference (SPEC 6: any one-sided derivative at a kink).
  subroutine check_tangent(mat, solver, old, s, sigma, tangent, what)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(2), sigma(2), tangent(2, 2)
    character(len=*), intent(out) :: what
    real(dp) :: h, fp1(2), fm1(2), fp2(2), fm2(2), c1(2), c2(2), f1(2), f2(2), b1(2), b2(2)
    real(dp) :: kref, tol, noise, hs
    integer :: j, m
    logical :: narrow
    logical :: ok
    what = ''
    do j = 1, 2
      h = 1.0e-6_dp * max(abs(s(j)), min(mat%s0n, mat%s0t))
      call eval(mat, solver, old, s, j, h, fp1, ok); if (.not. ok) return
      call eval(mat, solver, old, s, j, -h, fm1, ok); if (.not. ok) return
      call eval(mat, solver, old, s, j, 0.5_dp * h, fp2, ok); if (.not. ok) return
      call eval(mat, solver, old, s, j, -0.5_dp * h, fm2, ok); if (.not. ok) return
      n_fd = n_fd + 1
      c1 = (fp1 - fm1) / (2.0_dp * h)
      c2 = (fp2 - fm2) / h
      f1 = (fp1 - sigma) / h
      f2 = (fp2 - sigma) / (0.5_dp * h)
      b1 = (sigma - fm1) / h
      b2 = (sigma - fm2) / (0.5_dp * h)
      kref = max(maxval(abs(tangent(:, j))), maxval(abs(c2)), maxval(abs(f2)), &
                 maxval(abs(b2))) + tiny(1.0_dp)
      noise = 1.0e3_dp * epsilon(1.0_dp) * (maxval(abs([sigma, fp1, fm1])) + &
              mat%kn * norm2(s)) / h
      tol = 1.0e-4_dp * kref + noise
      if (.not. (close(c1, c2, tol) .and. close(f1, f2, 20.0_dp * tol) .and. &
                 close(b1, b2, 20.0_dp * tol))) then
        n_fd_skip = n_fd_skip + 1
        cycle
      end if
      if (close(tangent(:, j), c2, 10.0_dp * tol) .or. close(tangent(:, j), f2, 20.0_dp * tol) &
          .or. close(tangent(:, j), b2, 20.0_dp * tol)) cycle
      ! A kink closer than h (several planes switch branch within 1e-6 relative): the smooth
      ! piece around s is narrower than the stencil. Retry with stencils 1e3 and 1e5 times
      ! smaller (their round-off is larger in proportion).
      narrow = .false.
      do m = 3, 5, 2
        hs = h * 10.0_dp**(-m)
        call eval(mat, solver, old, s, j, hs, fp1, ok); if (.not. ok) return
        call eval(mat, solver, old, s, j, -hs, fm1, ok); if (.not. ok) return
        c1 = (fp1 - fm1) / (2.0_dp * hs)
        if (close(tangent(:, j), c1, 10.0_dp * tol + 10.0_dp**m * noise)) narrow = .true.
      end do
      if (narrow) then
        n_fd_skip = n_fd_skip + 1
        cycle
      end if
      write (what, '(a,i0,a,2es12.4,a,2es12.4,a,2es12.4,a,2es12.4)') 'column ', j, ': tangent', &
        tangent(:, j), ' central FD', c2, ' forward', f2, ' backward', b2
      return
    end do
  end subroutine check_tangent

  subroutine eval(mat, solver, old, s, jj, dh, f, okay)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(2), dh
    integer, intent(in) :: jj
    real(dp), intent(out) :: f(2)
    logical, intent(out) :: okay
    type(interlock_state_t) :: tmp
    type(interlock_info_t) :: inf
    real(dp) :: sp(2), tg(2, 2)
    sp = s
    sp(jj) = sp(jj) + dh
    call interlock_update(mat, solver, sp, old, tmp, f, tg, inf)
    okay = inf%status == status_ok
  end subroutine eval

  pure logical function close(a, b, tol)
    real(dp), intent(in) :: a(2), b(2), tol
    close = maxval(abs(a - b)) <= tol
  end function close

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
