!> The general update of one material point over one increment (SPEC section 5): the argument
!> checks, the specialised kernel of the material's effect set or the general path
!> (interlock_general_path, the 3D law with s_T2 = 0 and every azimuth 0, whose tangent's
!> (1:2, 1:2) block is the 2D tangent), optionally with error-controlled substepping, and the
!> exact algorithmic tangent of what was computed. A failed local solve is retried on
!> sub-increments before it is reported. interlock_update (interlock_integrate) calls it,
!> through kernel_update (a specialised kernel without substepping, with only the checks it
!> needs), for everything but the flat-plane laws it runs itself. A module of its own, compiled as the UMAT's path rather than as the laws
!> (src/CMakeLists.txt): general_update is too large to be inlined into the front, where it
!> would make every call of the small laws pay for saving registers; the small kernel_update
!> is inlined there.
module interlock_general_update
  use interlock_kinds, only: dp, is_finite_value, within_separation_bound, separation_bound
  use interlock_material, only: interlock_material_t, interlock_solver_t, n_schemes, &
      scheme_list, kernel_general
  use interlock_numbers, only: format_real, format_integer
  use interlock_state, only: interlock_state_t, interlock_state_3d_t, state_take
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, status_local_failure
  use interlock_kernels, only: kernel_step
  use interlock_general_path, only: integrate_increment
  use interlock_substep_control, only: largest_increments, size_after_whole
  implicit none
  private
  public :: general_update, kernel_update


contains

  !> interlock_update (its contract) for every material and solver but the flat-plane laws of
  !> interlock_update itself: a specialised kernel without substepping first, with only the
  !> checks it needs (mat%kernel /= kernel_general only in a prepared material; s tested on its
  !> bits, interlock_kinds:within_separation_bound), else general_update. When the kernel does not apply
  !> or its result is not finite, general_update takes the increment again (and reports). A
  !> small procedure of its own: through general_update's checks and frame the full model's
  !> update costs more (interlock-bench's cost rows, docs/bench.md).
  pure subroutine kernel_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    logical :: done
    if (mat%kernel /= kernel_general .and. solver%substep_tol <= 0.0_dp .and. &
        solver%scheme >= 1 .and. solver%scheme <= n_schemes .and. &
        within_separation_bound(s(1)) .and. within_separation_bound(s(2))) then
      call kernel_step(mat, solver, s, old, new, tangent, done, info%newton_iterations)
      if (done) then
        if (finite_response(new%sigma, tangent)) then
          sigma = new%sigma
          call largest_increments(mat%n_planes, old, new, info)
          return
        end if
      end if
    end if
    call general_update(mat, solver, s, old, new, sigma, tangent, info)
  end subroutine kernel_update

  !> interlock_update (its contract) for any material and solver. `info` comes reset by
  !> interlock_update (status ok, no message, counts 1 or 0); the fields set here are the
  !> ones the update finds out.
  pure subroutine general_update(mat, solver, s, old, new, sigma, tangent, info)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    logical :: done
    real(dp) :: err, h_first

    if (.not. mat%prepared) then
      call fail(old, new, sigma, tangent, info, status_bad_input, &
                'the material has not been prepared (call interlock_material_prepare)')
      return
    end if
    if (solver%scheme < 1 .or. solver%scheme > n_schemes) then
      call fail(old, new, sigma, tangent, info, status_bad_input, 'scheme = ' // &
                format_integer(solver%scheme) // ' is inadmissible: admissible ' // &
                scheme_list())
      return
    end if
    if (.not. (within_separation_bound(s(1)) .and. within_separation_bound(s(2)))) then
      call fail(old, new, sigma, tangent, info, status_bad_input, &
                'the relative displacement s = (' // format_real(s(1)) // ', ' // &
                format_real(s(2)) // ') mm is inadmissible: admissible |s_N|, |s_T| <= ' // &
                format_real(separation_bound) // ' mm')
      return
    end if

    ! Every path below sets the whole tangent when it succeeds (fail() zeroes it otherwise).
    done = .false.
    if (solver%substep_tol > 0.0_dp) then
      ! The whole increment by the specialised kernel first (it computes the error estimate on
      ! the way, as the first trial of substep would); sub-increments only when the estimate
      ! exceeds the tolerance, the first one sized from it.
      h_first = 1.0_dp
      if (mat%kernel /= kernel_general) then
        call kernel_step(mat, solver, s, old, new, tangent, done, info%newton_iterations, err)
        if (.not. done) err = 0.0_dp
        if (err > solver%substep_tol) then
          done = .false.
          h_first = size_after_whole(err, solver%substep_tol)
        end if
      end if
      if (.not. done) call general_path(mat, solver, s, old, new, tangent, info, &
                                        solver%substep_tol, h_first)
    else
      ! The specialised kernel of the material's effect set, when it applies.
      if (mat%kernel /= kernel_general) call kernel_step(mat, solver, s, old, new, tangent, &
                                                         done, info%newton_iterations)
      if (.not. done) then
        info%newton_iterations = 0
        call general_path(mat, solver, s, old, new, tangent, info, 0.0_dp, 1.0_dp)
      end if
    end if
    if (info%status /= status_ok) then
      call fail(old, new, sigma, tangent, info, info%status, info%message)
      return
    end if
    sigma = new%sigma
    if (.not. finite_response(sigma, tangent)) then
      call fail(old, new, sigma, tangent, info, status_local_failure, &
                'the traction or tangent is not finite: retry with a smaller increment')
      return
    end if
    call largest_increments(mat%n_planes, old, new, info)
  end subroutine general_update

  !> Traction and tangent finite: a NaN or an infinity in any entry makes the sum NaN or
  !> infinite (so does a sum beyond huge, which no traction or stiffness of the law comes near).
  pure logical function finite_response(sigma, tangent)
    real(dp), intent(in) :: sigma(2), tangent(2, 2)
    finite_response = is_finite_value(abs(sigma(1)) + abs(sigma(2)) + abs(tangent(1, 1)) + &
                                      abs(tangent(2, 1)) + abs(tangent(1, 2)) + abs(tangent(2, 2)))
  end function finite_response

  !> Report a failure: `new` = `old`, the traction at the start, no tangent.
  pure subroutine fail(old, new, sigma, tangent, info, code, message)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    integer, intent(in) :: code
    character(len=*), intent(in) :: message
    info%status = code
    info%message = message
    info%max_damage_increment = 0.0_dp
    info%max_angle_increment = 0.0_dp
    new = old
    sigma = old%sigma
    tangent = 0.0_dp
  end subroutine fail

  !> The general path (interlock_general_path) of a 2D increment, in the (n, t1) plane of the
  !> 3D law: tol > 0, error-controlled sub-increments from the fraction h_first; tol = 0, the
  !> whole increment as one step, retried on sub-increments (split only as failures require)
  !> when its solve fails. Only the material's planes are converted and written (an update
  !> defines the values of those alone: interlock_state); `new` is written only on success.
  pure subroutine general_path(mat, solver, s, old, new, tangent, info, tol, h_first)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2), tol, h_first
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(inout) :: tangent(2, 2)
    type(interlock_info_t), intent(inout) :: info
    type(interlock_state_3d_t) :: old_3d, new_3d
    real(dp) :: tangent_3d(3, 3)
    integer :: n, k
    n = mat%n_planes
    old_3d%interlock_state_t = old
    do k = 1, n
      old_3d%sf_strike(k) = 0.0_dp
      old_3d%tauf_strike(k) = 0.0_dp
    end do
    old_3d%s_t2 = 0.0_dp
    old_3d%sigma_t2 = 0.0_dp
    call integrate_increment(mat, solver, [s(1), s(2), 0.0_dp], old_3d, new_3d, tangent_3d, &
                             info, tol, h_first, .true.)
    if (info%status /= status_ok) return
    call state_take(n, new_3d%interlock_state_t, new)
    tangent = tangent_3d(1:2, 1:2)
  end subroutine general_path

end module interlock_general_update
