!> interlock-fuzz --3d: random admissible three-dimensional materials (the `paper` and
!> `azimuthal` RIAs, general RIAs with random azimuths in [-2 pi, 2 pi], random effect sets)
!> and random 3D separation histories through interlock_update_3d, every scheme, a share with
!> substepping, with garbage now and then: a component of the separation NaN (quiet or
!> signalling), +-Inf, huge, denormal or of any magnitude; a given material value garbled
!> before interlock_material_prepare (which must reject it or give a material the update
!> takes); a scheme code out of range. After every call: the status is one of the library's
!> codes; an accepted update has finite, bounded traction, tangent and state and keeps the
!> invariants (D in [0, 1] and non-decreasing, zeta non-decreasing, theta between theta_f and
!> theta_0, friction dissipation non-decreasing); a refused one leaves new = old and returns a
!> zero tangent and a finite traction; a non-finite separation is refused as bad input. Every
!> --fd-every accepted updates the tangent is checked against finite differences away from
!> kinks. In the Debug build any floating-point trap ends the run.
module fuzz_3d
  use, intrinsic :: iso_fortran_env, only: output_unit, int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan, &
      ieee_positive_inf, ieee_negative_inf
  use interlock
  use interlock_material, only: n_schemes
  use test_stability_tools, only: rng_t, rng_uniform, rng_int, rng_log_uniform, check_update
  use fuzz_fd_check, only: check_tangent_3d
  implicit none
  private
  public :: fuzz_3d_counts_t, fuzz_3d_run

  !> What a run did and found.
  type :: fuzz_3d_counts_t
    integer(int64) :: updates = 0, refused = 0, garbage_s = 0, materials = 0, &
                      materials_refused = 0, fd_checks = 0, fd_skipped = 0, failures = 0, &
                      stated = 0
  end type fuzz_3d_counts_t

contains

  !> n_updates calls of interlock_update_3d; failures are printed.
  !> beyond_bound: the finite garbage separations include magnitudes beyond separation_bound
  !> (up to huge), else those are drawn again (NaN and infinities stay); and garbage angles.
  subroutine fuzz_3d_run(rng, n_updates, fd_every, beyond_bound, c)
    type(rng_t), intent(inout) :: rng
    integer(int64), intent(in) :: n_updates
    integer, intent(in) :: fd_every
    logical, intent(in) :: beyond_bound
    type(fuzz_3d_counts_t), intent(inout) :: c
    do while (c%updates < n_updates)
      call one_history(rng, n_updates, fd_every, beyond_bound, c)
    end do
  end subroutine fuzz_3d_run

  !> A value for a slot that held x: garbage of every kind.
  function garbage(rng, x) result(y)
    type(rng_t), intent(inout) :: rng
    real(dp), intent(in) :: x
    real(dp) :: y, u
    u = rng_uniform(rng)
    select case (rng_int(rng, 1, 11))
    case (1)
      y = ieee_value(1.0_dp, ieee_quiet_nan)
    case (2)
      y = transfer(ior(shiftl(2047_int64, 52), 1_int64), 1.0_dp)   ! signalling NaN
    case (3)
      y = ieee_value(1.0_dp, ieee_positive_inf)
    case (4)
      y = ieee_value(1.0_dp, ieee_negative_inf)
    case (5)
      y = 1.0e-310_dp * (1.0_dp + u)
    case (6)
      y = huge(1.0_dp) * (0.5_dp + 0.5_dp * u)
    case (7)
      y = -huge(1.0_dp) * (0.5_dp + 0.5_dp * u)
    case (8)
      y = 10.0_dp**(600.0_dp * u - 300.0_dp)
    case (9)
      y = -10.0_dp**(600.0_dp * u - 300.0_dp)
    case (10)
      y = 0.0_dp
    case default
      y = -x
    end select
  end function garbage

  !> A random material (admissible, or refused by prepare after garbage) and solver.
  subroutine random_material(rng, beyond_bound, mat, solver, c)
    type(rng_t), intent(inout) :: rng
    logical, intent(in) :: beyond_bound
    type(interlock_material_t), intent(out) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(fuzz_3d_counts_t), intent(inout) :: c
    real(dp) :: scale, sc, th0, thf, z0, g(max_planes)
    integer :: k, n, stat, slot
    character(len=message_len) :: message
    do
      scale = rng_log_uniform(rng, 1.0e-6_dp, 1.0e3_dp)
      mat%sigma0_n = 3.0_dp * scale * rng_log_uniform(rng, 0.1_dp, 10.0_dp)
      mat%sigma0_t = 3.0_dp * scale * rng_log_uniform(rng, 0.1_dp, 10.0_dp)
      sc = rng_log_uniform(rng, 1.0e-3_dp, 10.0_dp)
      mat%gc = 0.5_dp * sc * mat%sigma0_n
      mat%eta = 1.0_dp - rng_log_uniform(rng, 1.0e-5_dp, 0.95_dp)
      mat%mu = merge(0.0_dp, 2.0_dp * rng_uniform(rng), rng_uniform(rng) < 0.15_dp)
      mat%h_n = huge(1.0_dp)
      if (rng_uniform(rng) < 0.8_dp) mat%h_n = rng_log_uniform(rng, 1.0e-4_dp, 1.0e3_dp)
      mat%prefractured = rng_uniform(rng) < 0.2_dp
      z0 = merge(huge(1.0_dp), rng_log_uniform(rng, 1.0e-6_dp, 1.0e6_dp), &
                 rng_uniform(rng) < 0.25_dp)
      th0 = rng_uniform(rng) * 80.0_dp * deg_to_rad
      thf = th0 * merge(1.0_dp, rng_uniform(rng), rng_uniform(rng) < 0.2_dp)
      mat%phi = 0.0_dp
      if (rng_uniform(rng) < 0.5_dp) then
        call interlock_azimuthal_ria(mat, rng_int(rng, 1, max_azimuths), th0, thf, z0)
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
          mat%phi(k) = (2.0_dp * rng_uniform(rng) - 1.0_dp) * 2.0_dp * pi
        end do
      end if
      do k = 1, n_effects
        mat%effect(k) = rng_uniform(rng) > 0.1_dp
      end do
      if (rng_uniform(rng) < 0.1_dp) then
        ! garbage in one given value
        slot = rng_int(rng, 1, 9)
        k = rng_int(rng, 1, max_planes)
        select case (slot)
        case (1)
          mat%sigma0_n = garbage(rng, mat%sigma0_n)
        case (2)
          mat%sigma0_t = garbage(rng, mat%sigma0_t)
        case (3)
          mat%gc = garbage(rng, mat%gc)
        case (4)
          mat%eta = garbage(rng, mat%eta)
        case (5)
          mat%mu = garbage(rng, mat%mu)
        case (6)
          mat%h_n = garbage(rng, mat%h_n)
        case (7)
          ! (garbage angles with --beyond-bound only: a huge or signalling-NaN phi or theta0
          ! traps in interlock_material_prepare's message, which converts it to degrees)
          if (beyond_bound) mat%phi(k) = garbage(rng, mat%phi(k))
        case (8)
          if (beyond_bound) mat%theta0(k) = garbage(rng, mat%theta0(k))
        case default
          mat%zeta0(k) = garbage(rng, mat%zeta0(k))
        end select
      end if
      call interlock_material_prepare(mat, stat, message)
      if (stat == status_ok) exit
      c%materials_refused = c%materials_refused + 1
      if (stat /= status_bad_input) then
        c%failures = c%failures + 1
        write (output_unit, '(a,i0)') 'FAIL 3D: material_prepare returned status ', stat
      end if
    end do
    solver%scheme = rng_int(rng, 1, n_schemes)
    if (rng_uniform(rng) < 0.02_dp) solver%scheme = rng_int(rng, -5, 10)
    solver%substep_tol = 0.0_dp
    if (rng_uniform(rng) < 0.3_dp) solver%substep_tol = rng_log_uniform(rng, 1.0e-5_dp, 1.0e-2_dp)
  end subroutine random_material

  subroutine one_history(rng, n_updates, fd_every, beyond_bound, c)
    type(rng_t), intent(inout) :: rng
    integer(int64), intent(in) :: n_updates
    integer, intent(in) :: fd_every
    logical, intent(in) :: beyond_bound
    type(fuzz_3d_counts_t), intent(inout) :: c
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: s(3), ds(3), dir(3), sigma(3), tangent(3, 3), step, lo_n, hi_n, len_t, len_n
    integer :: i, n_steps, j
    logical :: bad_s, garbled
    character(len=200) :: what

    call random_material(rng, beyond_bound, mat, solver, c)
    c%materials = c%materials + 1
    call interlock_state_3d_init(mat, old)
    len_t = mat%sct
    len_n = mat%scn
    lo_n = -3.0_dp * mat%s0n
    hi_n = 3.0_dp * len_n
    if (mat%use_depth) hi_n = min(max(hi_n, 1.5_dp * mat%h_n), 10.0_dp * max(len_n, mat%h_n))
    n_steps = rng_int(rng, 20, 300)
    dir = [rng_uniform(rng), rng_uniform(rng), rng_uniform(rng)] - 0.5_dp
    do i = 1, n_steps
      if (c%updates >= n_updates) return
      if (rng_uniform(rng) < 0.1_dp) dir = -dir
      if (rng_uniform(rng) < 0.2_dp) dir = [rng_uniform(rng), rng_uniform(rng), &
                                            rng_uniform(rng)] - 0.5_dp
      step = rng_log_uniform(rng, 1.0e-6_dp, 0.2_dp)
      if (rng_uniform(rng) < 0.03_dp) step = rng_log_uniform(rng, 0.5_dp, 5.0_dp)
      ds = step * [dir(1) * len_n, dir(2) * len_t, dir(3) * len_t] / max(norm2(dir), 1.0e-3_dp)
      s = [old%s(1), old%s(2), old%s_t2] + ds
      if (s(1) < lo_n) s(1) = lo_n + rng_uniform(rng) * mat%s0n
      if (s(1) > hi_n) s(1) = hi_n * rng_uniform(rng)
      if (norm2(s(2:3)) > 5.0_dp * len_t) s(2:3) = s(2:3) * (5.0_dp * len_t / norm2(s(2:3))) * &
                                                   rng_uniform(rng)
      bad_s = .false.
      garbled = .false.
      if (rng_uniform(rng) < 0.05_dp) then
        garbled = .true.
        j = rng_int(rng, 1, 3)
        do
          s(j) = garbage(rng, s(j))
          if (beyond_bound .or. .not. is_finite_bits(s(j))) exit
          if (abs(s(j)) <= separation_bound) exit
        end do
        c%garbage_s = c%garbage_s + 1
      end if
      ! (a material of extreme lengths can also take a plain step beyond the bound)
      bad_s = .not. all(within_separation_bound(s))
      call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
      c%updates = c%updates + 1
      what = ''
      if (info%status /= status_ok) then
        c%refused = c%refused + 1
        if (info%status /= status_bad_input .and. info%status /= status_local_failure) then
          what = 'status is not a library code'
        else if (.not. same_state(old, new)) then
          what = 'a refused update changed the state'
        else if (.not. (all(is_finite_bits(sigma)) .and. all(same_value(tangent, 0.0_dp)))) then
          what = 'a refused update returned a traction not finite or a tangent not zero'
        else if (info%status == status_local_failure .and. &
                 index(info%message, 'unstable on small sub-increments') > 0) then
          c%stated = c%stated + 1
          return
        else if (info%status == status_bad_input .and. .not. bad_s .and. &
                 solver%scheme >= 1 .and. solver%scheme <= n_schemes) then
          what = 'bad input on an admissible call: ' // trim(info%message)
        else if (info%status == status_local_failure .and. .not. garbled) then
          what = 'local failure: ' // trim(info%message)
        end if
        if (len_trim(what) > 0) call report(mat, solver, old, s, what, c)
        if (info%status == status_local_failure .or. garbled) return
        cycle
      end if
      if (bad_s) then
        call report(mat, solver, old, s, 'a separation beyond separation_bound was accepted', c)
        return
      end if
      if (garbled) then
        ! (a finite garbage separation the update took: checked, then the history ends)
        call check_3d(mat, old, new, sigma, tangent, what)
        if (len_trim(what) > 0) call report(mat, solver, old, s, 'invariant after garbage: ' &
                                            // trim(what), c)
        return
      end if
      call check_3d(mat, old, new, sigma, tangent, what)
      if (len_trim(what) > 0) then
        call report(mat, solver, old, s, 'invariant: ' // trim(what), c)
        return
      end if
      if (mod(c%updates, int(fd_every, int64)) == 0) then
        call check_tangent_3d(mat, solver, old, s, sigma, tangent, what, c%fd_checks, &
                              c%fd_skipped)
        if (len_trim(what) > 0) then
          call report(mat, solver, old, s, 'tangent: ' // trim(what), c)
          return
        end if
      end if
      old = new
    end do
  end subroutine one_history

  !> The invariants of an accepted update (test_stability_tools:check_update on the normal and
  !> the in-plane magnitude), and the strike components finite.
  subroutine check_3d(mat, old, new, sigma, tangent, what)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_3d_t), intent(in) :: old, new
    real(dp), intent(in) :: sigma(3), tangent(3, 3)
    character(len=*), intent(out) :: what
    type(interlock_state_t) :: o2, n2
    integer :: n
    n = mat%n_planes
    what = ''
    if (.not. (all(ieee_is_finite(sigma)) .and. all(ieee_is_finite(tangent)) .and. &
               all(ieee_is_finite([new%sf_strike(1:n), new%tauf_strike(1:n), new%s_t2, &
                                   new%sigma_t2])))) then
      what = 'a 3D value (traction, tangent, strike components) is NaN/Inf'
      return
    end if
    o2 = old%interlock_state_t
    n2 = new%interlock_state_t
    n2%s = [new%s(1), norm2([new%s(2), new%s_t2])]
    call check_update(mat, o2, n2, [sigma(1), norm2(sigma(2:3))], tangent(1:2, 1:2), what)
  end subroutine check_3d

  !> Every value of two states has the same bits.
  logical function same_state(a, b)
    type(interlock_state_3d_t), intent(in) :: a, b
    same_state = all(bits(a) == bits(b))
  end function same_state

  function bits(st) result(b)
    type(interlock_state_3d_t), intent(in) :: st
    integer(int64), allocatable :: b(:)
    b = transfer([st%damage, st%beta, st%sf, st%zeta, st%theta, st%tauf, st%sf_strike, &
                  st%tauf_strike, st%s, st%sigma, st%s_t2, st%sigma_t2, st%work, st%stored, &
                  st%diss_damage, st%diss_friction], 0_int64, 6 * max_planes + 2 * max_planes &
                  + 10)
  end function bits

  !> Print a failing input (the 3D update has no replay deck: the material, solver, start
  !> state and separation as text).
  subroutine report(mat, solver, old, s, why, c)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3)
    character(len=*), intent(in) :: why
    type(fuzz_3d_counts_t), intent(inout) :: c
    integer :: n, ios
    character(len=64) :: deck
    n = mat%n_planes
    c%failures = c%failures + 1
    write (output_unit, '(a,i0,a)') 'FAIL 3D at update ', c%updates, ': ' // trim(why)
    if (c%failures > 5) return
    ! (a replay deck of the update, in the working folder, for interlock-history)
    write (deck, '(a,i0,a)') 'fuzz_3d_fail', c%failures, '.nml'
    call interlock_write_replay_deck(trim(deck), mat, solver, old, s, why, ios)
    if (ios == 0) write (output_unit, '(a)') '  replay deck ' // trim(deck)
    write (output_unit, '(a,6es24.16,l2)') '  sigma0_n, sigma0_t, gc, eta, mu, h_n, pre: ', &
      mat%sigma0_n, mat%sigma0_t, mat%gc, mat%eta, mat%mu, mat%h_n, mat%prefractured
    write (output_unit, '(a,5l2)') '  effects ', mat%effect
    write (output_unit, '(a,13es24.16)') '  gamma_hat ', mat%gamma_hat(1:n)
    write (output_unit, '(a,13es24.16)') '  theta0 ', mat%theta0(1:n)
    write (output_unit, '(a,13es24.16)') '  thetaf ', mat%thetaf(1:n)
    write (output_unit, '(a,13es24.16)') '  zeta0 ', mat%zeta0(1:n)
    write (output_unit, '(a,13es24.16)') '  phi ', mat%phi(1:n)
    write (output_unit, '(a,i0,a,es24.16)') '  scheme ', solver%scheme, ' substep_tol ', &
      solver%substep_tol
    write (output_unit, '(a,3es24.16)') '  s old ', old%s, old%s_t2
    write (output_unit, '(a,3es24.16)') '  s new ', s
  end subroutine report

end module fuzz_3d
