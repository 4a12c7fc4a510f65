!> Invariants along long random histories (fixed seed, portable generator), for every scheme
!> with and without substepping: D in [0, 1] and non-decreasing, beta and zeta non-decreasing,
!> theta between theta_f and theta_0, both dissipations non-negative and non-decreasing, and
!> nothing NaN or infinite. Each update must also succeed, and a zero increment after it must
!> return the same traction (SPEC D10) in every scheme but the explicit one, where it must not
!> somewhere (the test sees the difference).
module test_invariants
  use interlock
  use interlock_assert, only: assert_true, assert_equal
  use test_core_support, only: table1_material, table2_material, prepare_or_fail, rng_t, &
      rng_uniform, nth_scheme
  use, intrinsic :: iso_fortran_env, only: output_unit
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: random_history_virgin_ria, random_history_prefractured_ria

  integer, parameter :: n_steps = 20000

contains

  !> Table 1 RIA (20 deg, worn towards 5 deg with zeta_0 = 0.05 N/mm, H_N = 0.3 mm), virgin:
  !> random mixed-mode steps that damage, slide, open beyond H_N and reclose.
  subroutine random_history_virgin_ria()
    type(interlock_material_t) :: mat
    call table1_material(mat, 20.0_dp, 0.3_dp, .false.)
    call interlock_paper_ria(mat, 20.0_dp * deg_to_rad, 5.0_dp * deg_to_rad, 0.05_dp)
    call prepare_or_fail(mat)
    call run_all_solvers(mat, [-0.06_dp, 0.4_dp], 0.3_dp, [0.01_dp, 0.03_dp], 11_8)
  end subroutine random_history_virgin_ria

  !> Table 2, pre-fractured, 30 -> 7 deg, zeta_0 = 1 N/mm, H_N = 2 mm: long random slip with
  !> strong wear, under compression and in opening.
  subroutine random_history_prefractured_ria()
    type(interlock_material_t) :: mat
    call table2_material(mat, 30.0_dp, 7.0_dp, 1.0_dp, 2.0_dp)
    call run_all_solvers(mat, [-0.05_dp, 1.0_dp], 3.0_dp, [0.03_dp, 0.2_dp], 23_8)
  end subroutine random_history_prefractured_ria

  subroutine run_all_solvers(mat, sn_range, st_max, step, seed)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sn_range(2), st_max, step(2)
    integer(kind=8), intent(in) :: seed
    type(interlock_solver_t) :: solver
    integer :: is
    do is = 1, 6
      solver%scheme = nth_scheme(is)
      solver%substep_tol = merge(1.0e-3_dp, 0.0_dp, is > 3)
      call random_history(mat, solver, sn_range, st_max, step, seed)
    end do
  end subroutine run_all_solvers

  !> n_steps random steps: increments uniform in +-step (a jump of 5 steps one time in 20),
  !> s_N kept within sn_range and |s_T| <= st_max by reflection.
  subroutine random_history(mat, solver, sn_range, st_max, step, seed)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: sn_range(2), st_max, step(2)
    integer(kind=8), intent(in) :: seed
    type(rng_t) :: g
    type(interlock_state_t) :: old, new, again
    type(interlock_info_t) :: info
    real(dp) :: s(2), ds(2), sigma(2), tangent(2, 2), lo(max_planes), hi(max_planes), sigma0(2), &
                jump
    integer :: i, n, bad(8), nsub, nslide, n_jumps
    character(len=32) :: tag
    n = mat%n_planes
    g%x = seed
    lo = min(mat%theta_init, mat%thetaf_eff)
    hi = max(mat%theta_init, mat%thetaf_eff)
    call interlock_state_init(mat, old)
    s = 0.0_dp
    bad = 0
    n_jumps = 0
    nsub = 0
    nslide = 0
    do i = 1, n_steps
      ds = (2.0_dp * [rng_uniform(g), rng_uniform(g)] - 1.0_dp) * step
      if (rng_uniform(g) < 0.05_dp) ds = 5.0_dp * ds
      s = s + ds
      if (s(1) > sn_range(2)) s(1) = 2.0_dp * sn_range(2) - s(1)
      if (s(1) < sn_range(1)) s(1) = 2.0_dp * sn_range(1) - s(1)
      if (abs(s(2)) > st_max) s(2) = sign(2.0_dp * st_max - abs(s(2)), s(2))
      call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
      if (info%status /= status_ok) then
        bad(1) = bad(1) + 1
        cycle
      end if
      nsub = nsub + info%substeps
      if (any(abs(new%sf(1:n) - old%sf(1:n)) > 0.0_dp .and. abs(new%tauf(1:n)) > 0.0_dp)) &
        nslide = nslide + 1
      if (.not. (all(ieee_is_finite(sigma)) .and. all(ieee_is_finite(tangent)) .and. &
                 state_is_finite(new))) bad(2) = bad(2) + 1
      if (any(new%damage(1:n) < 0.0_dp) .or. any(new%damage(1:n) > 1.0_dp)) bad(3) = bad(3) + 1
      if (any(new%damage(1:n) < old%damage(1:n)) .or. any(new%beta(1:n) < old%beta(1:n))) &
        bad(4) = bad(4) + 1
      if (any(new%zeta(1:n) < old%zeta(1:n))) bad(5) = bad(5) + 1
      if (any(new%theta(1:n) < lo(1:n)) .or. any(new%theta(1:n) > hi(1:n))) bad(6) = bad(6) + 1
      if (new%diss_damage < old%diss_damage .or. new%diss_damage < 0.0_dp) bad(7) = bad(7) + 1
      if (new%diss_friction < old%diss_friction .or. new%diss_friction < 0.0_dp) &
        bad(8) = bad(8) + 1
      ! SPEC D10: a zero increment returns the traction of the end of the step, except in the
      ! explicit scheme (the paper's; it turns the frame to the angle stored for the next step).
      call interlock_update(mat, solver, s, new, again, sigma0, tangent, info)
      jump = maxval(abs(sigma0 - sigma)) / (max(mat%sigma0_n, mat%sigma0_t) + maxval(abs(sigma)))
      ! (to round-off: the stick traction K_t (s_kt - sf) is recomputed)
      if (jump > 1.0e-11_dp) n_jumps = n_jumps + 1
      if (info%status /= status_ok) bad(1) = bad(1) + 1
      old = new
    end do
    tag = scheme_name(solver%scheme)
    if (solver%substep_tol > 0.0_dp) tag = trim(tag) // '+substepping'
    write (output_unit, '(4x,a,a,i0,a,i0,a,2es11.3,a,f7.3,a,es10.3)') tag, ' substeps ', nsub, &
      '  sliding steps ', nslide, &
      '  D_k range ', minval(old%damage(1:n)), maxval(old%damage(1:n)), '  theta_1 [deg] ', &
      old%theta(1) * rad_to_deg, '  zeta_1 ', old%zeta(1)
    tag = trim(tag) // ': '
    call assert_equal(0, bad(1), trim(tag) // 'every update succeeds')
    call assert_equal(0, bad(2), trim(tag) // 'traction, tangent and state are finite')
    call assert_equal(0, bad(3), trim(tag) // 'D in [0, 1]')
    call assert_equal(0, bad(4), trim(tag) // 'D and beta non-decreasing')
    call assert_equal(0, bad(5), trim(tag) // 'zeta non-decreasing')
    call assert_equal(0, bad(6), trim(tag) // 'theta between theta_f and theta_0')
    call assert_equal(0, bad(7), trim(tag) // 'damage dissipation non-negative, non-decreasing')
    call assert_equal(0, bad(8), trim(tag) // 'friction dissipation non-negative, non-decreasing')
    if (solver%scheme == scheme_explicit) then
      call assert_true(n_jumps > 0, trim(tag) // 'a zero increment after wear jumps (D10)')
    else
      call assert_equal(0, n_jumps, trim(tag) // 'a zero increment returns the same traction (D10)')
    end if
    ! The history must exercise what it guards.
    call assert_true(maxval(old%damage(1:n)) >= 1.0_dp, trim(tag) // 'the history breaks a plane')
    call assert_true(nslide > n_steps / 20, trim(tag) // 'the history slides in contact often')
    call assert_true(any(abs(old%theta(1:n) - mat%theta_init(1:n)) > 1.0e-3_dp), &
                     trim(tag) // 'the history wears a plane')
  end subroutine random_history

  logical function state_is_finite(st) result(ok)
    type(interlock_state_t), intent(in) :: st
    ok = all(ieee_is_finite(st%damage)) .and. all(ieee_is_finite(st%beta)) .and. &
         all(ieee_is_finite(st%sf)) .and. all(ieee_is_finite(st%zeta)) .and. &
         all(ieee_is_finite(st%theta)) .and. all(ieee_is_finite(st%tauf)) .and. &
         all(ieee_is_finite(st%s)) .and. all(ieee_is_finite(st%sigma)) .and. &
         ieee_is_finite(st%work) .and. ieee_is_finite(st%stored) .and. &
         ieee_is_finite(st%diss_damage) .and. ieee_is_finite(st%diss_friction)
  end function state_is_finite

end module test_invariants
