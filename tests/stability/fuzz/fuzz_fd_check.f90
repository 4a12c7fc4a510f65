!> The fuzzers' check of an update's tangent against finite differences of its traction (same
!> start state), column by column, for the 2D update (interlock-fuzz) and the 3D one (--3d,
!> fuzz_3d) alike: one check, check_tangent_fd, of an update_t (the update from the checked one's
!> start state to a perturbed separation: interlock_update or interlock_update_3d).
!> Central differences with steps h and h/2 and the one-sided ones must agree among themselves
!> (else a kink lies within the stencil: the column is skipped); the tangent must then match
!> the central difference, or the central or a one-sided one Richardson-extrapolated from h
!> and h/2 (fast wear curves the traction so much within h that a plain difference is off by
!> more than the tolerance, and at a kink the tangent is one side's, SPEC 6). A column that
!> matches none is checked again with steps 1e-2 and 1e-4 times as small before it fails:
!> error-controlled substepping chooses its partition of the increment from s, so the traction
!> it computes jumps (by the tolerance's order) wherever that choice switches, and with fast
!> wear such switches, or kinks of several planes, can lie closer together than the first step
!> (differences over them are smooth-looking but off by a percent; the tangent is the
!> derivative between them).
module fuzz_fd_check
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_t, &
      interlock_state_3d_t, interlock_info_t, interlock_update, interlock_update_3d, status_ok
  implicit none
  private
  public :: check_tangent_2d, check_tangent_3d

  !> The outcomes of one column's check.
  integer, parameter :: fd_match = 0, fd_kink = 1, fd_mismatch = 2, fd_failed_eval = 3

  !> The checked update: its material, solver and start state; `traction` gives the traction
  !> at s + dh e_j.
  type, abstract :: update_t
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
  contains
    procedure(traction_at), deferred :: traction
  end type update_t

  abstract interface
    !> The traction f of the update to s + dh e_j; ok false when the update refused it.
    subroutine traction_at(u, s, j, dh, f, ok)
      import :: update_t, dp
      class(update_t), intent(in) :: u
      real(dp), intent(in) :: s(:), dh
      integer, intent(in) :: j
      real(dp), intent(out) :: f(:)
      logical, intent(out) :: ok
    end subroutine traction_at
  end interface

  type, extends(update_t) :: update_2d_t
    type(interlock_state_t) :: old
  contains
    procedure :: traction => traction_2d
  end type update_2d_t

  type, extends(update_t) :: update_3d_t
    type(interlock_state_3d_t) :: old
  contains
    procedure :: traction => traction_3d
  end type update_3d_t

contains

  !> The tangent of interlock_update from `old` to s against finite differences.
  subroutine check_tangent_2d(mat, solver, old, s, sigma, tangent, what, n_checks, n_skipped)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(2), sigma(2), tangent(2, 2)
    character(len=*), intent(out) :: what
    integer(int64), intent(inout) :: n_checks, n_skipped
    call check_tangent_fd(update_2d_t(mat, solver, old), s, sigma, tangent, what, n_checks, &
                          n_skipped)
  end subroutine check_tangent_2d

  !> The tangent of interlock_update_3d from `old` to s against finite differences.
  subroutine check_tangent_3d(mat, solver, old, s, sigma, tangent, what, n_checks, n_skipped)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3), sigma(3), tangent(3, 3)
    character(len=*), intent(out) :: what
    integer(int64), intent(inout) :: n_checks, n_skipped
    call check_tangent_fd(update_3d_t(mat, solver, old), s, sigma, tangent, what, n_checks, &
                          n_skipped)
  end subroutine check_tangent_3d

  subroutine traction_2d(u, s, j, dh, f, ok)
    class(update_2d_t), intent(in) :: u
    real(dp), intent(in) :: s(:), dh
    integer, intent(in) :: j
    real(dp), intent(out) :: f(:)
    logical, intent(out) :: ok
    type(interlock_state_t) :: tmp
    type(interlock_info_t) :: info
    real(dp) :: sp(2), g(2), k(2, 2)
    sp = s
    sp(j) = sp(j) + dh
    call interlock_update(u%mat, u%solver, sp, u%old, tmp, g, k, info)
    f = g
    ok = info%status == status_ok
  end subroutine traction_2d

  subroutine traction_3d(u, s, j, dh, f, ok)
    class(update_3d_t), intent(in) :: u
    real(dp), intent(in) :: s(:), dh
    integer, intent(in) :: j
    real(dp), intent(out) :: f(:)
    logical, intent(out) :: ok
    type(interlock_state_3d_t) :: tmp
    type(interlock_info_t) :: info
    real(dp) :: sp(3), g(3), k(3, 3)
    sp = s
    sp(j) = sp(j) + dh
    call interlock_update_3d(u%mat, u%solver, sp, u%old, tmp, g, k, info)
    f = g
    ok = info%status == status_ok
  end subroutine traction_3d

  !> Check tangent = d sigma / d s of update u at s (n components). The step is 1e-6 of |s_j|,
  !> at least 1e-6 of the material's smallest characteristic separation; the round-off scale
  !> of the differences is set by its normal stiffness. `what` is blank when the
  !> tangent passes (or an update of a difference was refused: nothing to check), else it
  !> names the column and the values. n_checks counts the columns checked, n_skipped those
  !> skipped at kinks.
  subroutine check_tangent_fd(u, s, sigma, tangent, what, n_checks, n_skipped)
    class(update_t), intent(in) :: u
    real(dp), intent(in) :: s(:), sigma(:), tangent(:, :)
    character(len=*), intent(out) :: what
    integer(int64), intent(inout) :: n_checks, n_skipped
    real(dp) :: h
    integer :: j, level, outcome
    what = ''
    do j = 1, size(s)
      h = 1.0e-6_dp * max(abs(s(j)), min(u%mat%s0n, u%mat%s0t))
      n_checks = n_checks + 1
      do level = 0, 2
        call check_column(u, s, sigma, tangent, j, h * 1.0e-2_dp**level, outcome, what)
        if (outcome == fd_failed_eval) return
        if (outcome == fd_kink) n_skipped = n_skipped + 1
        if (outcome /= fd_mismatch) exit
      end do
      if (outcome == fd_mismatch) return
      what = ''
    end do
  end subroutine check_tangent_fd

  !> One column j of check_tangent_fd with step h: outcome fd_match, fd_kink (the differences
  !> disagree among themselves), fd_mismatch (`what` says how) or fd_failed_eval (an update
  !> of the differences was refused).
  subroutine check_column(u, s, sigma, tangent, j, h, outcome, what)
    class(update_t), intent(in) :: u
    real(dp), intent(in) :: s(:), sigma(:), tangent(:, :), h
    integer, intent(in) :: j
    integer, intent(out) :: outcome
    character(len=*), intent(out) :: what
    real(dp), dimension(size(sigma)) :: fp1, fm1, fp2, fm2, c1, c2, f2, b2
    real(dp) :: kref, tol, noise, err
    logical :: ok
    character(len=40) :: fmt
    what = ''
    outcome = fd_failed_eval
    call u%traction(s, j, h, fp1, ok); if (.not. ok) return
    call u%traction(s, j, -h, fm1, ok); if (.not. ok) return
    call u%traction(s, j, 0.5_dp * h, fp2, ok); if (.not. ok) return
    call u%traction(s, j, -0.5_dp * h, fm2, ok); if (.not. ok) return
    c1 = (fp1 - fm1) / (2.0_dp * h)
    c2 = (fp2 - fm2) / h
    f2 = (fp2 - sigma) / (0.5_dp * h)
    b2 = (sigma - fm2) / (0.5_dp * h)
    kref = max(maxval(abs(tangent(:, j))), maxval(abs(c2)), maxval(abs(f2)), &
               maxval(abs(b2))) + tiny(1.0_dp)
    noise = 1.0e3_dp * epsilon(1.0_dp) * (maxval(abs([sigma, fp1, fm1])) + &
            u%mat%kn * norm2(s)) / h
    tol = 1.0e-4_dp * kref + noise
    outcome = fd_kink
    if (.not. (maxval(abs(c1 - c2)) <= tol .and. maxval(abs(f2 - b2)) <= 20.0_dp * tol)) return
    outcome = fd_match
    if (maxval(abs(tangent(:, j) - c2)) <= 10.0_dp * tol) return
    ! (central, forward, backward: (4 D(h/2) - D(h)) / 3 and 2 D(h/2) - D(h))
    err = min(maxval(abs(tangent(:, j) - (4.0_dp * c2 - c1) / 3.0_dp)), &
              maxval(abs(tangent(:, j) - (2.0_dp * f2 - (fp1 - sigma) / h))), &
              maxval(abs(tangent(:, j) - (2.0_dp * b2 - (sigma - fm1) / h))))
    if (err <= 10.0_dp * tol) return
    outcome = fd_mismatch
    write (fmt, '(a,i0,a,i0,a)') '(a,i0,a,', size(sigma), 'es12.4,a,', size(sigma), &
      'es12.4,a,es8.1)'
    write (what, fmt) 'column ', j, ': tangent', tangent(:, j), ' central FD', c2, ' h', h
  end subroutine check_column

end module fuzz_fd_check
