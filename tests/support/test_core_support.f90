!> Shared helpers of the core suites: the paper's parameter sets as materials, driving a point
!> along a path, holding sigma_N constant by Newton's method on tangent(1,1), a central
!> finite-difference tangent, and a portable random-number generator for the random histories.
module test_core_support
  use interlock
  use interlock_general_path, only: general_update_3d
  use funit, only: assertTrue
  implicit none
  private
  public :: table1_material, table2_material, flat_material, prepare_or_fail
  public :: drive_to, solve_sigma_n, fd_tangent, matrix_rel_error, slide_history
  public :: rng_t, rng_uniform, read_reference_row, nth_scheme
  public :: granite_3d_material, table1_3d_material, state_3d_of, fd_tangent_3d, &
            solve_sigma_n_3d, rotate_in_plane, rotate_tangent, general_3d

  !> xorshift64 (Marsaglia): identical sequences on every compiler and platform.
  type :: rng_t
    integer(kind=8) :: x = 88172645463325252_8
  end type rng_t

contains

  !> The schemes in turn: 1, 4, ... explicit; 2, 5, ... implicit; 3, 6, ... trapezoidal.
  pure integer function nth_scheme(i) result(scheme)
    integer, intent(in) :: i
    select case (mod(i - 1, 3))
    case (0)
      scheme = scheme_explicit
    case (1)
      scheme = scheme_implicit
    case default
      scheme = scheme_trapezoidal
    end select
  end function nth_scheme

  !> Validate a material in a test: a failure is an assertion failure, not a stop.
  subroutine prepare_or_fail(mat)
    type(interlock_material_t), intent(inout) :: mat
    integer :: stat
    character(len=message_len) :: msg
    call interlock_material_prepare(mat, stat, msg)
    call assertTrue(stat == status_ok, 'material prepare: ' // trim(msg))
  end subroutine prepare_or_fail

  !> Table 1 of the paper (sigma0 = 3 MPa, Gc_bar = 0.3 N/mm, eta = 0.9, mu = 0.5), the
  !> three-plane RIA at theta_0 [deg], no wear, asperity depth h_n [mm].
  subroutine table1_material(mat, theta0_deg, h_n, prefractured)
    type(interlock_material_t), intent(out) :: mat
    real(dp), intent(in) :: theta0_deg, h_n
    logical, intent(in) :: prefractured
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 3.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.5_dp
    mat%h_n = h_n
    mat%prefractured = prefractured
    call interlock_paper_ria(mat, theta0_deg * deg_to_rad, theta0_deg * deg_to_rad, huge(1.0_dp))
    call prepare_or_fail(mat)
  end subroutine table1_material

  !> Table 2 of the paper (pre-fractured, sigma0 = 0.025 MPa, Gc_bar = 5e-4 N/mm, eta = 0.99,
  !> mu = 0.5) with the RIA (theta_0, theta_f [deg], zeta_0 [N/mm]) and depth h_n [mm].
  subroutine table2_material(mat, theta0_deg, thetaf_deg, zeta0, h_n)
    type(interlock_material_t), intent(out) :: mat
    real(dp), intent(in) :: theta0_deg, thetaf_deg, zeta0, h_n
    mat%sigma0_n = 0.025_dp
    mat%sigma0_t = 0.025_dp
    mat%gc = 0.0005_dp
    mat%eta = 0.99_dp
    mat%mu = 0.5_dp
    mat%h_n = h_n
    mat%prefractured = .true.
    call interlock_paper_ria(mat, theta0_deg * deg_to_rad, thetaf_deg * deg_to_rad, zeta0)
    call prepare_or_fail(mat)
  end subroutine table2_material

  !> One flat plane (the Alfano-Sacco model) with Table 1 values and friction mu.
  subroutine flat_material(mat, mu, h_n)
    type(interlock_material_t), intent(out) :: mat
    real(dp), intent(in) :: mu, h_n
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 2.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = mu
    mat%h_n = h_n
    call interlock_general_ria(mat, 1, [1.0_dp], [0.0_dp], [0.0_dp])
    call prepare_or_fail(mat)
  end subroutine flat_material

  !> Drive `state` through the separations path(:, i) in turn (one update each).
  subroutine drive_to(mat, solver, path, state)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: path(:, :)
    type(interlock_state_t), intent(inout) :: state
    type(interlock_state_t) :: new
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), tangent(2, 2)
    integer :: i
    do i = 1, size(path, 2)
      call interlock_update(mat, solver, path(:, i), state, new, sigma, tangent, info)
      if (info%status /= status_ok) then
        call assertTrue(.false., 'drive_to: ' // trim(info%message))
        return
      end if
      state = new
    end do
  end subroutine drive_to

  !> Find s_N such that sigma_N(s_N, s_t) = sig_n from `old` (Newton on tangent(1,1), starting
  !> from old%s(1)); `new`, `sigma` and `tangent` are those of the converged update.
  subroutine solve_sigma_n(mat, solver, old, s_t, sig_n, new, sigma, tangent, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s_t, sig_n
    type(interlock_state_t), intent(out) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    logical, intent(out) :: ok
    type(interlock_info_t) :: info
    real(dp) :: s(2)
    integer :: it
    s = [old%s(1), s_t]
    ok = .false.
    do it = 1, 60
      call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
      if (info%status /= status_ok) exit
      if (abs(sigma(1) - sig_n) <= 1.0e-13_dp * max(abs(sig_n), 1.0e-3_dp)) then
        ok = .true.
        exit
      end if
      if (.not. (tangent(1, 1) > 0.0_dp)) exit
      s(1) = s(1) - (sigma(1) - sig_n) / tangent(1, 1)
    end do
    call assertTrue(ok, 'solve_sigma_n converged')
  end subroutine solve_sigma_n

  !> The paper's protocol (D8): sigma_N applied in one step at s_T = 0, then n uniform slip
  !> steps to t_end at constant sigma_N. Row i (0 = after the preload) of `hist` holds
  !> (s_N, s_T, sigma_N, sigma_T, theta_1, D_1, zeta_1); `last` is the final state.
  subroutine slide_history(mat, solver, sig_n, t_end, n, hist, last)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: sig_n, t_end
    integer, intent(in) :: n
    real(dp), intent(out) :: hist(0:n, 7)
    type(interlock_state_t), intent(out) :: last
    type(interlock_state_t) :: old, new
    real(dp) :: sigma(2), tangent(2, 2)
    integer :: i
    logical :: ok
    hist = 0.0_dp
    call interlock_state_init(mat, old)
    do i = 0, n
      call solve_sigma_n(mat, solver, old, t_end * real(i, dp) / real(n, dp), sig_n, new, sigma, &
                         tangent, ok)
      if (.not. ok) exit
      hist(i, :) = [new%s(1), new%s(2), sigma(1), sigma(2), new%theta(1), new%damage(1), &
                    new%zeta(1)]
      old = new
    end do
    last = old
  end subroutine slide_history

  !> Central finite differences of sigma(s) at fixed `old`, step h in each component.
  !> `kan` is the tangent returned at s; `same_steps` is true when the perturbed updates used
  !> the same sub-increments (accepted and tried) as the update at s.
  subroutine fd_tangent(mat, solver, old, s, h, kan, kfd, new, same_steps)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(2), h
    real(dp), intent(out) :: kan(2, 2), kfd(2, 2)
    type(interlock_state_t), intent(out) :: new
    logical, intent(out) :: same_steps
    type(interlock_state_t) :: tmp
    type(interlock_info_t) :: info0, infop, infom
    real(dp) :: sp(2), sm(2), sigp(2), sigm(2), sig0(2), ktmp(2, 2)
    integer :: j
    call interlock_update(mat, solver, s, old, new, sig0, kan, info0)
    if (info0%status /= status_ok) call assertTrue(.false., 'fd_tangent base: ' // &
                                                   trim(info0%message))
    same_steps = .true.
    do j = 1, 2
      sp = s
      sm = s
      sp(j) = s(j) + h
      sm(j) = s(j) - h
      call interlock_update(mat, solver, sp, old, tmp, sigp, ktmp, infop)
      call interlock_update(mat, solver, sm, old, tmp, sigm, ktmp, infom)
      call assertTrue(infop%status == status_ok .and. infom%status == status_ok, &
                       'fd_tangent perturbed updates succeed')
      kfd(:, j) = (sigp - sigm) / (sp(j) - sm(j))
      same_steps = same_steps .and. infop%substeps == info0%substeps .and. &
                   infom%substeps == info0%substeps .and. infop%attempts == info0%attempts &
                   .and. infom%attempts == info0%attempts
    end do
  end subroutine fd_tangent

  !> max |a - b| / max |b| (b = the reference), 0 when both vanish.
  pure real(dp) function matrix_rel_error(a, b) result(e)
    real(dp), intent(in) :: a(2, 2), b(2, 2)
    real(dp) :: d, r
    d = maxval(abs(a - b))
    r = maxval(abs(b))
    if (r > 0.0_dp) then
      e = d / r
    else
      e = d
    end if
  end function matrix_rel_error

  !> The first data row (17 columns, see tests/data/core/README.md) of a reference CSV copied
  !> from the independent reference curves (tests/data/reference); `path` is relative to the test's working directory (tests/).
  subroutine read_reference_row(path, row)
    character(len=*), intent(in) :: path
    real(dp), intent(out) :: row(17)
    integer :: u, ios
    row = 0.0_dp
    open (newunit=u, file=path, status='old', action='read', iostat=ios)
    call assertTrue(ios == 0, 'open reference ' // path)
    if (ios /= 0) return
    read (u, *, iostat=ios)
    if (ios == 0) read (u, *, iostat=ios) row
    call assertTrue(ios == 0, 'read reference ' // path)
    close (u)
  end subroutine read_reference_row

  !> Granite (SPEC, Lee et al.: sigma0 = 0.025 MPa, Gc_bar = 5e-4 N/mm, eta = 0.99,
  !> mu = tan(34.6 deg), H_N = 4 mm) on the `azimuthal` RIA with n_azimuths directions
  !> (theta_0 = 30, theta_f = 9 deg, zeta_0 = 6.666 N/mm; n_azimuths = 1 is `paper`).
  subroutine granite_3d_material(mat, n_azimuths)
    type(interlock_material_t), intent(out) :: mat
    integer, intent(in) :: n_azimuths
    mat%sigma0_n = 0.025_dp
    mat%sigma0_t = 0.025_dp
    mat%gc = 0.0005_dp
    mat%eta = 0.99_dp
    mat%mu = tan(34.6_dp * deg_to_rad)
    mat%h_n = 4.0_dp
    call interlock_azimuthal_ria(mat, n_azimuths, 30.0_dp * deg_to_rad, 9.0_dp * deg_to_rad, &
                                 6.666_dp)
    call prepare_or_fail(mat)
  end subroutine granite_3d_material

  !> Table 1 (sigma0 = 3 MPa, Gc_bar = 0.3 N/mm, eta = 0.9, mu = 0.5, theta_0 = 25 deg,
  !> H_N = 0.5 mm, no wear) on the `azimuthal` RIA with n_azimuths directions.
  subroutine table1_3d_material(mat, n_azimuths)
    type(interlock_material_t), intent(out) :: mat
    integer, intent(in) :: n_azimuths
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 3.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.5_dp
    mat%h_n = 0.5_dp
    call interlock_azimuthal_ria(mat, n_azimuths, 25.0_dp * deg_to_rad, 25.0_dp * deg_to_rad, &
                                 huge(1.0_dp))
    call prepare_or_fail(mat)
  end subroutine table1_3d_material

  !> The general three-dimensional path (never the 2D route) with its `info` reset as it
  !> requires.
  subroutine general_3d(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3)
    type(interlock_state_3d_t), intent(in) :: old
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    type(interlock_info_t), intent(out) :: info
    info%status = status_ok
    info%newton_iterations = 0
    info%substeps = 1
    info%attempts = 1
    info%max_angle_increment = 0.0_dp
    info%max_damage_increment = 0.0_dp
    call general_update_3d(mat, solver, s, old, new, sigma, tangent, info)
  end subroutine general_3d

  !> The 3D state of a 2D one: the strike components and s_T2, sigma_T2 zero.
  pure function state_3d_of(state) result(st)
    type(interlock_state_t), intent(in) :: state
    type(interlock_state_3d_t) :: st
    st%interlock_state_t = state
    st%sf_strike = 0.0_dp
    st%tauf_strike = 0.0_dp
    st%s_t2 = 0.0_dp
    st%sigma_t2 = 0.0_dp
  end function state_3d_of

  !> Central finite differences of the 3D traction at fixed `old`, step h in each component
  !> (interlock_update_3d); `ok` false when a perturbed update fails.
  subroutine fd_tangent_3d(mat, solver, old, s, h, kfd, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3), h
    real(dp), intent(out) :: kfd(3, 3)
    logical, intent(out) :: ok
    type(interlock_state_3d_t) :: tmp
    type(interlock_info_t) :: infop, infom
    real(dp) :: sp(3), sm(3), sigp(3), sigm(3), ktmp(3, 3)
    integer :: j
    ok = .true.
    do j = 1, 3
      sp = s
      sm = s
      sp(j) = s(j) + h
      sm(j) = s(j) - h
      call interlock_update_3d(mat, solver, sp, old, tmp, sigp, ktmp, infop)
      call interlock_update_3d(mat, solver, sm, old, tmp, sigm, ktmp, infom)
      ok = ok .and. infop%status == status_ok .and. infom%status == status_ok
      kfd(:, j) = (sigp - sigm) / (sp(j) - sm(j))
    end do
  end subroutine fd_tangent_3d

  !> Find s_N such that sigma_N(s_N, s_T1, s_T2) = sig_n from `old` (Newton on tangent(1,1),
  !> starting from old%s(1)); `new`, `sigma` and `tangent` are those of the converged update.
  subroutine solve_sigma_n_3d(mat, solver, old, s_t, sig_n, new, sigma, tangent, ok)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s_t(2), sig_n
    type(interlock_state_3d_t), intent(out) :: new
    real(dp), intent(out) :: sigma(3), tangent(3, 3)
    logical, intent(out) :: ok
    type(interlock_info_t) :: info
    real(dp) :: s(3)
    integer :: it
    s = [old%s(1), s_t(1), s_t(2)]
    ok = .false.
    do it = 1, 60
      call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
      if (info%status /= status_ok) exit
      if (abs(sigma(1) - sig_n) <= 1.0e-13_dp * max(abs(sig_n), 1.0e-3_dp)) then
        ok = .true.
        exit
      end if
      if (.not. (tangent(1, 1) > 0.0_dp)) exit
      s(1) = s(1) - (sigma(1) - sig_n) / tangent(1, 1)
    end do
    call assertTrue(ok, 'solve_sigma_n_3d converged')
  end subroutine solve_sigma_n_3d

  !> (x_N, x_T1, x_T2) with its in-plane part rotated by the angle a about n.
  pure function rotate_in_plane(x, a) result(y)
    real(dp), intent(in) :: x(3), a
    real(dp) :: y(3)
    y = [x(1), cos(a) * x(2) - sin(a) * x(3), sin(a) * x(2) + cos(a) * x(3)]
  end function rotate_in_plane

  !> R K R^T with R the rotation by a about n.
  pure function rotate_tangent(k, a) result(kr)
    real(dp), intent(in) :: k(3, 3), a
    real(dp) :: kr(3, 3), r(3, 3)
    r = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, cos(a), sin(a), 0.0_dp, -sin(a), cos(a)], &
                [3, 3])
    kr = matmul(r, matmul(k, transpose(r)))
  end function rotate_tangent

  !> A uniform number in [0, 1).
  real(dp) function rng_uniform(g) result(u)
    type(rng_t), intent(inout) :: g
    integer(kind=8) :: x
    x = g%x
    x = ieor(x, shiftr(x, 12))
    x = ieor(x, shiftl(x, 25))
    x = ieor(x, shiftr(x, 27))
    g%x = x
    ! the top 53 bits of the state as a fraction (plain xorshift64: no wrapping products)
    u = real(shiftr(x, 11), dp) * 2.0_dp**(-53)
  end function rng_uniform

end module test_core_support
