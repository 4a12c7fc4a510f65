!> The update of one material point over one increment (SPEC section 5): the chosen scheme,
!> optionally with error-controlled substepping, and the exact algorithmic tangent of what was
!> computed. A failed local solve is retried on sub-increments before it is reported.
module interlock_integrate
  use interlock_kinds, only: dp, is_nan_value
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes, &
      scheme_explicit, scheme_implicit, kernel_general
  use interlock_state, only: interlock_state_t
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, status_local_failure
  use interlock_ria, only: ria_step
  use interlock_kernels, only: kernel_step
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  implicit none
  private
  public :: interlock_update

  real(dp), parameter :: smallest_fraction = 1.0e-12_dp

contains

  !> Integrate from `old` (state at the start of the increment) to the relative displacement
  !> `s` (end of the increment). `new` is the state at the end, `sigma` the traction and
  !> `tangent` = d sigma / d s, the exact derivative of the computed traction.
  !> On failure `info%status` /= status_ok, `info%message` says why, and `new` = `old`.
  pure subroutine interlock_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(out) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(out) :: info
    logical :: ok, done
    integer :: n

    new = old
    sigma = old%sigma
    tangent = 0.0_dp
    if (.not. mat%prepared) then
      info%status = status_bad_input
      info%message = 'the material has not been prepared (call interlock_material_prepare)'
      return
    end if
    if (solver%scheme /= scheme_explicit .and. solver%scheme /= scheme_implicit) then
      info%status = status_bad_input
      info%message = 'unknown integration scheme: admissible 1 (explicit) or 2 (implicit)'
      return
    end if
    if (any(is_nan_value(s)) .or. .not. all(ieee_is_finite(s))) then
      info%status = status_bad_input
      info%message = 'the relative displacement is not a finite number'
      return
    end if

    if (solver%substep_tol > 0.0_dp) then
      call substep(mat, solver, s, old, new, tangent, info, solver%substep_tol)
    else
      done = .false.
      info%attempts = 1
      ! The specialised kernel of the material's effect set, when it applies.
      if (mat%kernel /= kernel_general) call kernel_step(mat, solver%scheme, s, old, new, &
                                                         tangent, done)
      ok = .true.
      if (.not. done) call ria_step(mat, solver, s, old, new, tangent, info%newton_iterations, ok)
      if (.not. ok) then
        ! The one-step solve failed: retry on sub-increments, split only as failures require.
        call substep(mat, solver, s, old, new, tangent, info, huge(1.0_dp))
      end if
    end if
    if (info%status /= status_ok) then
      new = old
      sigma = old%sigma
      tangent = 0.0_dp
      return
    end if
    sigma = new%sigma
    if (.not. (all(ieee_is_finite(sigma)) .and. all(ieee_is_finite(tangent)))) then
      info%status = status_local_failure
      info%message = 'the traction or tangent is not finite: retry with a smaller increment'
      new = old
      sigma = old%sigma
      tangent = 0.0_dp
      return
    end if
    n = mat%n_planes
    info%max_damage_increment = maxval(new%damage(1:n) - old%damage(1:n))
    info%max_angle_increment = maxval(abs(new%theta(1:n) - old%theta(1:n)))
  end subroutine interlock_update

  !> Sub-increments linear in s. Each trial sub-increment is taken once whole and once as two
  !> halves; their difference estimates the local error, the halves are kept when it is within
  !> `tol`, and the next size follows from first-order error scaling.
  pure subroutine substep(mat, solver, s, old, new, tangent, info, tol)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2), tol
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    type(interlock_state_t) :: cur, full, half1, half2
    real(dp) :: ds(2), alpha, h, a_end, err, s_end(2), s_mid(2), t_full(2, 2), t_half(2, 2)
    real(dp) :: jac(4, 2, max_planes), jac1(4, 2, max_planes), jac2(4, 2, max_planes)
    integer :: it1, it2, it3, n_accepted
    logical :: ok1, ok2, ok3, control

    control = tol < huge(1.0_dp)
    ds = s - old%s
    cur = old
    alpha = 0.0_dp
    h = 1.0_dp
    jac = 0.0_dp
    n_accepted = 0
    tangent = 0.0_dp
    if (.not. control) h = 0.5_dp
    do while (alpha < 1.0_dp)
      h = min(h, 1.0_dp - alpha)
      a_end = alpha + h
      if (a_end >= 1.0_dp - smallest_fraction) then
        a_end = 1.0_dp
        h = 1.0_dp - alpha
        s_end = s
      else
        s_end = old%s + a_end * ds
      end if
      s_mid = old%s + (alpha + 0.5_dp * h) * ds
      info%attempts = info%attempts + 1
      if (info%attempts > solver%max_substeps) then
        info%status = status_local_failure
        write (info%message, '(a,i0,a)') 'substepping did not meet its tolerance within ', &
          solver%max_substeps, ' sub-increments: retry with a smaller increment'
        return
      end if
      ok1 = .true.
      it1 = 0
      if (control) call ria_step(mat, solver, s_end, cur, full, t_full, it1, ok1)
      call ria_step(mat, solver, s_mid, cur, half1, t_half, it2, ok2, jac, alpha + 0.5_dp * h, jac1)
      ok3 = .false.
      it3 = 0
      if (ok2) call ria_step(mat, solver, s_end, half1, half2, t_half, it3, ok3, jac1, a_end, jac2)
      info%newton_iterations = max(info%newton_iterations, it1, it2, it3)
      if (.not. (ok1 .and. ok2 .and. ok3)) then
        h = 0.25_dp * h
        if (h < smallest_fraction) then
          info%status = status_local_failure
          info%message = 'the local wear equation has no solution on any sub-increment: ' // &
                         'retry with a smaller increment'
          return
        end if
        cycle
      end if
      err = 0.0_dp
      if (control) err = local_error(mat, full, half2)
      if (err <= tol .or. h <= 1.0e-6_dp) then
        cur = half2
        jac = jac2
        tangent = t_half
        alpha = a_end
        n_accepted = n_accepted + 2
        if (control) h = h * min(4.0_dp, max(1.0_dp, 0.9_dp * sqrt(tol / max(err, tiny(1.0_dp)))))
      else
        h = h * max(0.1_dp, 0.9_dp * sqrt(tol / err))
      end if
      ! Sizes are powers of 2 so that the partition of the increment does not vary with s
      ! (except where a decision switches): the chained tangent is then the exact derivative.
      if (control) h = scale(1.0_dp, exponent(h) - 1)
    end do
    new = cur
    info%substeps = n_accepted
  end subroutine substep

  !> Local error estimate between one whole and two half sub-increments: the largest of the
  !> traction difference (relative to the peak tractions), the damage difference and the
  !> angle difference [rad].
  pure real(dp) function local_error(mat, a, b)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(in) :: a, b
    integer :: n
    real(dp) :: sref
    n = mat%n_planes
    sref = max(mat%sigma0_n, mat%sigma0_t) + maxval(abs(b%sigma))
    local_error = max(maxval(abs(a%sigma - b%sigma)) / sref, &
                      maxval(abs(a%damage(1:n) - b%damage(1:n))), &
                      maxval(abs(a%theta(1:n) - b%theta(1:n))))
  end function local_error

end module interlock_integrate
