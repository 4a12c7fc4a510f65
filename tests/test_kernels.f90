!> The specialised kernels (interlock_kernels) against the general path (interlock_ria): every
!> effect set without wear, both schemes, random separation histories with reversals, jumps,
!> opening past H_N and re-closing. From the same start state, traction, tangent and end state
!> must agree to round-off. The general path is an independent implementation of the same law
!> (gradient vectors through the mechanism modules, not the kernels' scalar code).
module test_kernels
  use interlock
  use interlock_assert, only: assert_true, assert_equal
  use test_core_support, only: rng_t, rng_uniform, prepare_or_fail
  implicit none
  private
  public :: test_flat_damage_only, test_flat_ria_no_friction, test_flat_friction, test_flat_depth, test_ria_fixed_angles, &
            test_ria_prefractured, test_general_ria_two_planes, test_kernel_selection, &
            test_ria_explicit_wear, test_theta_zero_is_single_plane

  real(dp), parameter :: tol = 1.0e-12_dp   !< relative to the natural scale of each quantity

contains

  subroutine base_material(mat, mu, h_n)
    type(interlock_material_t), intent(out) :: mat
    real(dp), intent(in) :: mu, h_n
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 2.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = mu
    mat%h_n = h_n
  end subroutine base_material

  subroutine one_flat_plane(mat)
    type(interlock_material_t), intent(inout) :: mat
    mat%n_planes = 1
    mat%gamma_hat(1) = 1.0_dp
  end subroutine one_flat_plane

  !> Both paths from the same start state along a random history; `expected_kernel` is the
  !> kernel the material must have selected.
  subroutine compare_paths(mat, expected_kernel, label)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: expected_kernel
    character(len=*), intent(in) :: label
    type(interlock_material_t) :: gen
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new_k, new_g
    type(interlock_info_t) :: info_k, info_g
    type(rng_t) :: rng
    real(dp) :: s(2), sig_k(2), sig_g(2), k_k(2, 2), k_g(2, 2), scale_s(2), ksc, ssc, u, target
    integer :: scheme, i, n, worst
    real(dp) :: err, err_max

    call assert_equal(expected_kernel, mat%kernel, label // ': kernel selected')
    gen = mat
    gen%kernel = kernel_general
    scale_s = [mat%s0n, mat%s0t]
    ksc = max(mat%kn, mat%kt)
    ssc = max(mat%sigma0_n, mat%sigma0_t)
    n = mat%n_planes
    do scheme = scheme_explicit, scheme_trapezoidal
      solver%scheme = scheme
      call interlock_state_init(mat, old)
      s = 0.0_dp
      err_max = 0.0_dp
      worst = 0
      do i = 1, 3000
        ! s_T: a random walk with reversals and jumps; s_N: pulled towards a target that
        ! alternates between compression and opening (past H_N for the shallow asperities).
        u = rng_uniform(rng)
        if (u < 0.03_dp) then
          s(2) = s(2) + (rng_uniform(rng) - 0.5_dp) * 20.0_dp * scale_s(2)
        else
          s(2) = s(2) + (rng_uniform(rng) - 0.5_dp) * 0.8_dp * scale_s(2)
        end if
        target = merge(-1.5_dp, 3.0_dp, mod(i / 250, 2) == 0) * scale_s(1)
        s(1) = 0.8_dp * s(1) + 0.2_dp * target + (rng_uniform(rng) - 0.5_dp) * scale_s(1)
        call interlock_update(mat, solver, s, old, new_k, sig_k, k_k, info_k)
        call interlock_update(gen, solver, s, old, new_g, sig_g, k_g, info_g)
        if (info_k%status /= status_ok .or. info_g%status /= status_ok) then
          ! (a message is defined only for the update that failed)
          if (info_k%status /= status_ok) then
            call assert_true(.false., label // ': the kernel''s update failed: ' // &
                             trim(info_k%message))
          else
            call assert_true(.false., label // ': the general update failed: ' // &
                             trim(info_g%message))
          end if
          return
        end if
        err = max(maxval(abs(sig_k - sig_g)) / ssc, maxval(abs(k_k - k_g)) / ksc, &
                  maxval(abs(new_k%damage(1:n) - new_g%damage(1:n))), &
                  maxval(abs(new_k%beta(1:n) - new_g%beta(1:n))) / mat%beta_break, &
                  maxval(abs(new_k%sf(1:n) - new_g%sf(1:n))) / mat%s0t, &
                  maxval(abs(new_k%tauf(1:n) - new_g%tauf(1:n))) / ssc, &
                  maxval(abs(new_k%zeta(1:n) - new_g%zeta(1:n))) / (mat%gc + maxval(new_g%zeta)), &
                  maxval(abs(new_k%theta(1:n) - new_g%theta(1:n))), &
                  abs(new_k%work - new_g%work) / (mat%gc + abs(new_g%work)), &
                  abs(new_k%diss_damage - new_g%diss_damage) / (mat%gc + new_g%diss_damage), &
                  abs(new_k%diss_friction - new_g%diss_friction) / (mat%gc + new_g%diss_friction), &
                  abs(new_k%stored - new_g%stored) / (mat%gc + new_g%stored))
        if (err > err_max) then
          err_max = err
          worst = i
        end if
        old = new_g
      end do
      write (*, '(2x,a,1x,a,a,es10.3,a,i0)') label, trim(scheme_name(scheme)), &
        ': largest relative difference kernel vs general ', err_max, ' at step ', worst
      call assert_true(err_max <= tol, label // ' ' // scheme_name(scheme) // &
                       ': kernel and general path agree to round-off')
    end do
  end subroutine compare_paths

  subroutine test_flat_damage_only()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.5_dp, huge(1.0_dp))
    call one_flat_plane(mat)
    mat%effect(effect_friction) = .false.
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_cohesive, 'flat, damage only')
  end subroutine test_flat_damage_only

  !> The law without friction (interlock_integrate:decohesion_step) on a flat RIA of three
  !> planes sharing one history, intact and pre-fractured (no damage evolution).
  subroutine test_flat_ria_no_friction()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.0_dp, huge(1.0_dp))
    call interlock_paper_ria(mat, 0.0_dp, 0.0_dp, 20.0_dp)
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_cohesive, 'flat RIA, damage, mu = 0')
    mat%prefractured = .true.
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_cohesive, 'flat RIA, pre-fractured, mu = 0')
  end subroutine test_flat_ria_no_friction

  subroutine test_flat_friction()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.5_dp, huge(1.0_dp))
    ! The paper's RIA with theta_0 = 0 is three identical flat planes: one computed.
    call interlock_paper_ria(mat, 0.0_dp, 0.0_dp, 20.0_dp)
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_cohesive, 'flat RIA, damage + friction')
  end subroutine test_flat_friction

  subroutine test_flat_depth()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.7_dp, 0.05_dp)
    call one_flat_plane(mat)
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_flat, 'flat, damage + friction + depth')
  end subroutine test_flat_depth

  subroutine test_ria_fixed_angles()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.5_dp, 0.5_dp)
    call interlock_paper_ria(mat, 25.0_dp * deg_to_rad, 25.0_dp * deg_to_rad, 20.0_dp)
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_inclined, 'RIA 25 deg, no wear, depth 0.5')
  end subroutine test_ria_fixed_angles

  subroutine test_ria_prefractured()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.5_dp, 1.0_dp)
    mat%prefractured = .true.
    call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 20.0_dp)
    mat%effect(effect_wear) = .false.
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_inclined, 'pre-fractured RIA, wear off')
  end subroutine test_ria_prefractured

  subroutine test_general_ria_two_planes()
    type(interlock_material_t) :: mat
    call base_material(mat, 2.0_dp, huge(1.0_dp))
    mat%n_planes = 2
    mat%gamma_hat(1:2) = [0.3_dp, 0.7_dp]
    mat%theta0(1:2) = [-10.0_dp, 20.0_dp] * deg_to_rad
    mat%thetaf(1:2) = mat%theta0(1:2)
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_inclined, 'two planes -10/+20 deg, mu = 2')
  end subroutine test_general_ria_two_planes

  !> Explicit wear: the angle frozen in the step, one exponential per plane that wore. (The
  !> implicit scheme with wear always takes the general path, so its comparison is trivial.)
  subroutine test_ria_explicit_wear()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.5_dp, 0.5_dp)
    call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 0.05_dp)
    call prepare_or_fail(mat)
    call compare_paths(mat, kernel_inclined, 'RIA 30/7 deg, wear, depth 0.5')
  end subroutine test_ria_explicit_wear

  !> SPEC section 7: theta = 0 gives the single-plane model whatever H_N. The three-plane RIA at
  !> theta_0 = 0 is computed plane by plane on the general path (no flat shortcut, no kernel)
  !> and compared with one flat plane on the flat kernel, along the same random history.
  subroutine test_theta_zero_is_single_plane()
    type(interlock_material_t) :: ria, one
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: o_r, n_r, o_1, n_1
    type(interlock_info_t) :: i_r, i_1
    type(rng_t) :: rng
    real(dp) :: s(2), sig_r(2), sig_1(2), k_r(2, 2), k_1(2, 2), h_n(3), err
    integer :: ih, i
    h_n = [0.05_dp, 0.5_dp, huge(1.0_dp)]
    do ih = 1, 3
      call base_material(ria, 0.5_dp, h_n(ih))
      call interlock_paper_ria(ria, 0.0_dp, 0.0_dp, 20.0_dp)
      call prepare_or_fail(ria)
      ria%flat = .false.
      ria%kernel = kernel_general
      call base_material(one, 0.5_dp, h_n(ih))
      call one_flat_plane(one)
      call prepare_or_fail(one)
      call interlock_state_init(ria, o_r)
      call interlock_state_init(one, o_1)
      s = 0.0_dp
      err = 0.0_dp
      do i = 1, 2000
        s(2) = s(2) + (rng_uniform(rng) - 0.5_dp) * 0.8_dp * one%s0t
        s(1) = 0.8_dp * s(1) + 0.2_dp * merge(-1.5_dp, 3.0_dp, mod(i / 250, 2) == 0) * one%s0n &
               + (rng_uniform(rng) - 0.5_dp) * one%s0n
        call interlock_update(ria, solver, s, o_r, n_r, sig_r, k_r, i_r)
        call interlock_update(one, solver, s, o_1, n_1, sig_1, k_1, i_1)
        err = max(err, maxval(abs(sig_r - sig_1)) / one%sigma0_n, &
                  maxval(abs(k_r - k_1)) / one%kn, maxval(abs(n_r%damage(1:3) - n_1%damage(1))))
        o_r = n_r
        o_1 = n_1
      end do
      write (*, '(2x,a,es10.3,a,es10.3)') 'theta = 0 RIA vs one plane, H_N = ', h_n(ih), &
        ': largest relative difference ', err
      call assert_true(err <= tol, 'theta = 0: three planes equal one flat plane')
    end do
  end subroutine test_theta_zero_is_single_plane

  !> Interlocking off makes any RIA flat.
  subroutine test_kernel_selection()
    type(interlock_material_t) :: mat
    call base_material(mat, 0.5_dp, 1.0_dp)
    call interlock_paper_ria(mat, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 20.0_dp)
    call prepare_or_fail(mat)
    call assert_equal(kernel_inclined, mat%kernel, 'wear: the inclined kernel (explicit scheme)')
    mat%effect(effect_interlocking) = .false.
    call prepare_or_fail(mat)
    call assert_equal(kernel_flat, mat%kernel, 'interlocking off selects the flat kernel')
    call assert_true(all(mat%theta_init(1:3) >= 0.0_dp .and. mat%theta_init(1:3) <= 0.0_dp), &
                     'interlocking off: every plane flat')
  end subroutine test_kernel_selection

end module test_kernels

program test_kernels_main
  use interlock_assert, only: run_case, suite_summary
  use test_kernels
  implicit none
  call run_case('flat, damage only', test_flat_damage_only)
  call run_case('flat RIA without friction, intact and pre-fractured', test_flat_ria_no_friction)
  call run_case('flat RIA, damage + friction', test_flat_friction)
  call run_case('flat, damage + friction + depth', test_flat_depth)
  call run_case('RIA without wear', test_ria_fixed_angles)
  call run_case('pre-fractured RIA without wear', test_ria_prefractured)
  call run_case('two-plane RIA, locking friction', test_general_ria_two_planes)
  call run_case('RIA with explicit wear', test_ria_explicit_wear)
  call run_case('theta = 0 is the single-plane model', test_theta_zero_is_single_plane)
  call run_case('kernel selection', test_kernel_selection)
  if (suite_summary('core_kernels') /= 0) error stop 1
end program test_kernels_main
