!> The algorithmic tangent d sigma / d s (at a fixed start state) against central finite
!> differences, on every branch of the law, for every scheme: explicit, implicit, trapezoidal,
!> and substepping on top of each. Every scene checks that it really is on the branch it names
!> (and is not at a kink), and that the perturbed updates used the same sub-increments.
!> Each case prints one row of the table branch x scheme -> max relative error.
module test_tangent
  use interlock
  use interlock_assert, only: assert_true
  use test_core_support, only: table1_material, table2_material, drive_to, solve_sigma_n, &
      fd_tangent, matrix_rel_error, prepare_or_fail, rng_t, rng_uniform, nth_scheme
  use, intrinsic :: iso_fortran_env, only: output_unit
  implicit none
  private
  public :: print_header, tangent_elastic, tangent_damage, tangent_unloading, tangent_stick, &
            tangent_slide, tangent_damage_slide, tangent_open, tangent_geometry, tangent_wear, &
            tangent_wear_substeps, tangent_random_states

  integer, parameter :: n_schemes = 6
  character(len=12), parameter :: scheme_label(n_schemes) = &
    [character(len=12) :: 'explicit', 'implicit', 'trapezoidal', 'explicit+sub', 'implicit+sub', &
     'trapez.+sub']
  real(dp), parameter :: tangent_tol = 1.0e-6_dp
  real(dp), parameter :: substep_tol = 1.0e-4_dp

  integer, parameter :: b_elastic = 1, b_damage = 2, b_unloading = 3, b_stick = 4, b_slide = 5, &
                        b_damage_slide = 6, b_open = 7, b_geometry = 8, b_wear = 9
  character(len=14), parameter :: branch_label(9) = [character(len=14) :: 'elastic', &
    'damage-loading', 'unloading', 'stick', 'slide', 'damage+slide', 'open-contact', &
    'geometry-decay', 'wear']

contains

  subroutine print_header()
    integer :: j
    write (output_unit, '(a)') 'Tangent vs central finite differences: max_ij |K - K_fd| / max_ij |K_fd|'
    write (output_unit, '(a14,6(1x,a12),a)') 'branch', (scheme_label(j), j = 1, n_schemes), &
      '  substeps(expl+sub, impl+sub, trap+sub)'
  end subroutine print_header

  subroutine tangent_elastic()
    call check_branch(b_elastic)
  end subroutine tangent_elastic

  subroutine tangent_damage()
    call check_branch(b_damage)
  end subroutine tangent_damage

  subroutine tangent_unloading()
    call check_branch(b_unloading)
  end subroutine tangent_unloading

  subroutine tangent_stick()
    call check_branch(b_stick)
  end subroutine tangent_stick

  subroutine tangent_slide()
    call check_branch(b_slide)
  end subroutine tangent_slide

  subroutine tangent_damage_slide()
    call check_branch(b_damage_slide)
  end subroutine tangent_damage_slide

  subroutine tangent_open()
    call check_branch(b_open)
  end subroutine tangent_open

  subroutine tangent_geometry()
    call check_branch(b_geometry)
  end subroutine tangent_geometry

  subroutine tangent_wear()
    call check_branch(b_wear)
  end subroutine tangent_wear

  !> Substepping really chains several sub-increments in the wear scene (otherwise the
  !> substepping columns would only repeat the plain schemes).
  subroutine tangent_wear_substeps()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: s(2), h, sigma(2), tangent(2, 2)
    integer :: is
    do is = 4, 6
      call make_solver(is, solver)
      call build_scene(b_wear, solver, mat, old, s, h)
      call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
      call assert_true(info%substeps > 2, trim(scheme_label(is)) // &
                       ': the wear scene is integrated on more than 2 sub-increments')
    end do
  end subroutine tangent_wear_substeps

  !> Tangents at the states of random histories (worn virgin Table 1 RIA with H_N = 0.3 mm,
  !> and the pre-fractured wearing Table 2 RIA), every scheme. A point is checked when two
  !> finite-difference steps (h and h/10) agree to 1e-5, i.e. no kink lies within +-h;
  !> then the tangent must match to 1e-6. At least 80 % of the points must be checkable.
  subroutine tangent_random_states()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    type(rng_t) :: g
    real(dp) :: s(2), ds(2), sigma(2), tangent(2, 2), kan(2, 2), k1(2, 2), k2(2, 2), h, &
                emax, scale(2), step(2)
    integer :: im, is, i, n_checked, n_points
    logical :: same1, same2
    do im = 1, 2
      if (im == 1) then
        call table1_material(mat, 20.0_dp, 0.3_dp, .false.)
        call interlock_paper_ria(mat, 20.0_dp * deg_to_rad, 5.0_dp * deg_to_rad, 0.05_dp)
        call prepare_or_fail(mat)
        scale = [0.06_dp, 0.3_dp]
        step = [0.01_dp, 0.03_dp]
      else
        call table2_material(mat, 30.0_dp, 7.0_dp, 1.0_dp, 2.0_dp)
        scale = [0.05_dp, 3.0_dp]
        step = [0.02_dp, 0.2_dp]
      end if
      do is = 1, n_schemes
        call make_solver(is, solver)
        g%x = 7_8 + im
        call interlock_state_init(mat, old)
        s = 0.0_dp
        emax = 0.0_dp
        n_checked = 0
        n_points = 0
        do i = 1, 1000
          ds = (2.0_dp * [rng_uniform(g), rng_uniform(g)] - 1.0_dp) * step
          s = s + ds
          s(1) = max(-scale(1), min(s(1), 2.0_dp * scale(1)))
          s(2) = max(-scale(2), min(s(2), scale(2)))
          if (mod(i, 5) == 0) then
            n_points = n_points + 1
            h = 1.0e-6_dp * max(maxval(abs(s)), 0.01_dp)
            call fd_tangent(mat, solver, old, s, h, kan, k1, new, same1)
            call fd_tangent(mat, solver, old, s, 0.1_dp * h, kan, k2, new, same2)
            if (same1 .and. same2 .and. matrix_rel_error(k1, k2) <= 1.0e-5_dp) then
              n_checked = n_checked + 1
              emax = max(emax, matrix_rel_error(kan, k1))
            end if
          end if
          call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
          call assert_true(info%status == status_ok, 'random history update succeeds')
          old = new
        end do
        write (output_unit, '(a,i0,1x,a12,a,i0,a,i0,a,es10.2)') '    material ', im, &
          scheme_label(is), ': checked ', n_checked, ' of ', n_points, &
          ' random states, max rel. error ', emax
        call assert_true(emax <= tangent_tol, trim(scheme_label(is)) // &
                         ': tangent matches finite differences at random states')
        call assert_true(n_checked >= (8 * n_points) / 10, trim(scheme_label(is)) // &
                         ': most random states are away from kinks')
      end do
    end do
  end subroutine tangent_random_states

  subroutine make_solver(is, solver)
    integer, intent(in) :: is
    type(interlock_solver_t), intent(out) :: solver
    solver%scheme = nth_scheme(is)
    ! (the coupled schemes meet 1e-4 on the wear scene's step at once: a tighter tolerance makes
    ! them chain sub-increments too)
    solver%substep_tol = merge(merge(1.0e-2_dp, 1.0_dp, is >= 5) * substep_tol, 0.0_dp, is > 3)
  end subroutine make_solver

  !> One row of the table: every scheme on branch ib.
  subroutine check_branch(ib)
    integer, intent(in) :: ib
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    real(dp) :: s(2), h, kan(2, 2), kfd(2, 2), err(n_schemes)
    integer :: is, nsub(n_schemes)
    logical :: same
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), ktmp(2, 2)

    do is = 1, n_schemes
      call make_solver(is, solver)
      call build_scene(ib, solver, mat, old, s, h)
      call fd_tangent(mat, solver, old, s, h, kan, kfd, new, same)
      call interlock_update(mat, solver, s, old, new, sigma, ktmp, info)
      nsub(is) = info%substeps
      err(is) = matrix_rel_error(kan, kfd)
      call assert_true(err(is) <= tangent_tol, trim(branch_label(ib)) // ' / ' // &
                       trim(scheme_label(is)) // ': tangent matches finite differences')
      if (.not. (err(is) <= tangent_tol)) then
        write (output_unit, '(a,4es14.6)') '    K    = ', kan
        write (output_unit, '(a,4es14.6)') '    K_fd = ', kfd
      end if
      call assert_true(same, trim(branch_label(ib)) // ' / ' // trim(scheme_label(is)) // &
                       ': the perturbation keeps the sub-increments')
      call assert_true(on_branch(ib, mat, old, new), trim(branch_label(ib)) // ' / ' // &
                       trim(scheme_label(is)) // ': the scene is on its branch')
    end do
    write (output_unit, '(a14,6(1x,es12.2),2x,3i5)') branch_label(ib), err, nsub(4:6)
  end subroutine check_branch

  !> The start state `old`, the end separation `s` and the finite-difference step `h` of
  !> branch ib, with the start state reached by the solver under test.
  subroutine build_scene(ib, solver, mat, old, s, h)
    integer, intent(in) :: ib
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_material_t), intent(out) :: mat
    type(interlock_state_t), intent(out) :: old
    real(dp), intent(out) :: s(2), h
    type(interlock_state_t) :: new
    real(dp) :: sigma(2), tangent(2, 2)
    logical :: ok
    integer :: i
    real(dp), parameter :: inf = huge(1.0_dp)

    select case (ib)
    case (b_elastic)
      call table1_material(mat, 20.0_dp, inf, .false.)
      call interlock_state_init(mat, old)
      s = [0.005_dp, 0.004_dp]
    case (b_damage)
      call table1_material(mat, 20.0_dp, inf, .false.)
      call interlock_state_init(mat, old)
      s = [0.03_dp, 0.02_dp]
    case (b_unloading)
      call table1_material(mat, 20.0_dp, inf, .false.)
      call interlock_state_init(mat, old)
      call drive_to(mat, solver, reshape([0.03_dp, 0.02_dp], [2, 1]), old)
      s = [0.02_dp, 0.012_dp]
    case (b_stick)
      ! Partially damaged planes in compression, friction traction well inside the cone.
      call table1_material(mat, 20.0_dp, inf, .false.)
      call interlock_state_init(mat, old)
      call drive_to(mat, solver, reshape([-0.08_dp, 0.0_dp, -0.08_dp, 0.03_dp], [2, 2]), old)
      s = [-0.08_dp, 0.026_dp]
    case (b_slide)
      call table1_material(mat, 20.0_dp, inf, .true.)
      call interlock_state_init(mat, old)
      call drive_to(mat, solver, reshape([-0.01_dp, 0.0_dp], [2, 1]), old)
      s = [-0.01_dp, 0.05_dp]
    case (b_damage_slide)
      call table1_material(mat, 20.0_dp, inf, .false.)
      call interlock_state_init(mat, old)
      s = [-0.005_dp, 0.03_dp]
    case (b_open)
      ! Damaged planes that slid in compression open again (the friction slip catches up).
      call table1_material(mat, 20.0_dp, inf, .false.)
      call interlock_state_init(mat, old)
      call drive_to(mat, solver, reshape([-0.08_dp, 0.0_dp, -0.08_dp, 0.03_dp], [2, 2]), old)
      s = [0.02_dp, 0.03_dp]
    case (b_geometry)
      call table1_material(mat, 20.0_dp, 0.5_dp, .false.)
      call interlock_state_init(mat, old)
      s = [0.02_dp, 0.1_dp]
    case (b_wear)
      ! Fig. 11-like: pre-fractured, theta_0 = 30, theta_f = 7 deg, zeta_0 = 1 N/mm, H_N = 2 mm,
      ! sliding at sigma_N = -2 MPa for 2 mm (dilation brings 0 < s_N < H_N), then one step.
      call table2_material(mat, 30.0_dp, 7.0_dp, 1.0_dp, 2.0_dp)
      call interlock_state_init(mat, old)
      do i = 0, 20
        call solve_sigma_n(mat, solver, old, 0.1_dp * i, -2.0_dp, new, sigma, tangent, ok)
        old = new
      end do
      s = old%s + [0.01_dp, 0.3_dp]
    case default
      s = 0.0_dp
    end select
    h = 1.0e-6_dp * maxval(abs(s))
  end subroutine build_scene

  !> Is the update old -> new clearly on branch ib (no plane at a kink)?
  logical function on_branch(ib, mat, old, new) result(ok)
    integer, intent(in) :: ib
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(in) :: old, new
    real(dp) :: skn(max_planes), skt(max_planes), dd(max_planes), dsf(max_planes), mup(max_planes)
    integer :: n, k
    n = mat%n_planes
    skn = 0.0_dp
    skt = 0.0_dp
    do k = 1, n
      skn(k) = cos(old%theta(k)) * new%s(1) + sin(old%theta(k)) * new%s(2)
      skt(k) = -sin(old%theta(k)) * new%s(1) + cos(old%theta(k)) * new%s(2)
    end do
    dd = new%damage - old%damage
    dsf = abs(new%sf - old%sf)
    mup = mat%mu * mat%kn * max(0.0_dp, -skn)
    ! no plane within 1e-3 s_0n of opening/closing
    ok = all(abs(skn(1:n)) > 1.0e-3_dp * mat%s0n)
    select case (ib)
    case (b_elastic)
      ok = ok .and. all(new%beta(1:n) < 0.9_dp) .and. all(new%damage(1:n) <= 0.0_dp)
    case (b_damage)
      ok = ok .and. all(dd(1:n) > 0.0_dp) .and. all(new%damage(1:n) < 0.99_dp) .and. &
           all(skn(1:n) > 0.0_dp)
    case (b_unloading)
      ok = ok .and. all(dd(1:n) <= 0.0_dp) .and. all(new%damage(1:n) > 0.1_dp) .and. &
           all(new%beta(1:n) <= old%beta(1:n))
    case (b_stick)
      ok = ok .and. all(skn(1:n) < 0.0_dp) .and. all(dsf(1:n) <= 0.0_dp) .and. &
           all(dd(1:n) <= 0.0_dp) .and. any(new%damage(1:n) > 0.1_dp) .and. &
           all(abs(new%tauf(1:n)) < 0.9_dp * mup(1:n))
    case (b_slide)
      ok = ok .and. count(dsf(1:n) > 0.0_dp .and. skn(1:n) < 0.0_dp) >= 2
    case (b_damage_slide)
      ok = ok .and. any(dd(1:n) > 0.0_dp .and. dsf(1:n) > 0.0_dp .and. skn(1:n) < 0.0_dp) &
           .and. all(new%damage(1:n) < 0.99_dp)
    case (b_open)
      ok = ok .and. all(skn(1:n) > 0.0_dp) .and. any(dsf(1:n) > 1.0e-3_dp) .and. &
           any(abs(old%tauf(1:n)) > 0.0_dp)
    case (b_geometry)
      ok = ok .and. new%s(1) > 0.01_dp * mat%h_n .and. new%s(1) < 0.99_dp * mat%h_n .and. &
           any(dsf(1:n) > 0.0_dp .and. skn(1:n) < 0.0_dp) .and. all(dd(1:n) > 0.0_dp)
    case (b_wear)
      ok = ok .and. new%zeta(1) > old%zeta(1) .and. abs(new%theta(1) - old%theta(1)) > 0.0_dp &
           .and. new%s(1) > 0.0_dp .and. new%s(1) < mat%h_n
    case default
      ok = .false.
    end select
  end function on_branch

end module test_tangent
