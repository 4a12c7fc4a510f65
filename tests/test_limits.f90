!> The limits of SPEC section 7: theta = 0 is the single-plane model whatever H_N; a very deep
!> asperity (H_N = 1e3 mm) is the infinite-depth model to ~1e-3; theta_f = theta_0 gives a
!> horizontal sliding plateau; theta_f = 0 drives the dilation back towards zero.
module test_limits
  use interlock
  use interlock_assert, only: assert_true, assert_equal, assert_close_rel
  use test_core_support, only: table1_material, table2_material, prepare_or_fail, slide_history, &
      read_reference_row
  use, intrinsic :: iso_fortran_env, only: output_unit
  implicit none
  private
  public :: flat_ria_is_single_plane, deep_asperities_are_infinite, no_wear_plateau, &
            wear_to_flat_removes_dilation

contains

  !> Three flat planes, and a worn 30-deg RIA with interlocking off, against one flat plane,
  !> along a mixed path that also separates (s_N > H_N) and recloses; both schemes.
  subroutine flat_ria_is_single_plane()
    type(interlock_material_t) :: single, ria0, ria_off
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: st1, st2, st3, nw1, nw2, nw3
    type(interlock_info_t) :: i1, i2, i3
    real(dp) :: s(2), sg1(2), sg2(2), sg3(2), t1(2, 2), t2(2, 2), t3(2, 2), dmax, hn
    integer :: ih, is, iseg, i
    real(dp), parameter :: depths(3) = [0.05_dp, 0.5_dp, huge(1.0_dp)]
    real(dp), parameter :: nodes(2, 8) = reshape([0.0_dp, 0.0_dp, -0.01_dp, 0.0_dp, &
      -0.01_dp, 0.1_dp, 0.03_dp, 0.15_dp, 0.08_dp, 0.1_dp, -0.005_dp, 0.05_dp, &
      -0.02_dp, -0.1_dp, 0.1_dp, 0.0_dp], [2, 8])
    do ih = 1, size(depths)
      hn = depths(ih)
      single%sigma0_n = 3.0_dp
      single%sigma0_t = 3.0_dp
      single%gc = 0.3_dp
      single%eta = 0.9_dp
      single%mu = 0.5_dp
      single%h_n = hn
      single%n_planes = 1
      single%gamma_hat(1) = 1.0_dp
      call prepare_or_fail(single)
      call table1_material(ria0, 0.0_dp, hn, .false.)
      ria_off = single
      ria_off%effect(effect_interlocking) = .false.
      call interlock_paper_ria(ria_off, 30.0_dp * deg_to_rad, 7.0_dp * deg_to_rad, 1.0_dp)
      call prepare_or_fail(ria_off)
      do is = 1, 2
        solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
        call interlock_state_init(single, st1)
        call interlock_state_init(ria0, st2)
        call interlock_state_init(ria_off, st3)
        dmax = 0.0_dp
        do iseg = 1, size(nodes, 2) - 1
          do i = 1, 20
            s = nodes(:, iseg) + (nodes(:, iseg + 1) - nodes(:, iseg)) * real(i, dp) / 20.0_dp
            call interlock_update(single, solver, s, st1, nw1, sg1, t1, i1)
            call interlock_update(ria0, solver, s, st2, nw2, sg2, t2, i2)
            call interlock_update(ria_off, solver, s, st3, nw3, sg3, t3, i3)
            dmax = max(dmax, maxval(abs(sg2 - sg1)), maxval(abs(sg3 - sg1)), &
                       maxval(abs(t2 - t1)) * single%s0n, maxval(abs(t3 - t1)) * single%s0n, &
                       abs(nw2%damage(1) - nw1%damage(1)) * 3.0_dp, &
                       abs(nw3%damage(3) - nw1%damage(1)) * 3.0_dp)
            st1 = nw1
            st2 = nw2
            st3 = nw3
          end do
        end do
        write (output_unit, '(a,es10.3,a,es10.3)') '    H_N = ', min(hn, 1.0e99_dp), &
          '  max |difference| [MPa] = ', dmax
        call assert_true(dmax <= 1.0e-13_dp * 3.0_dp, 'theta = 0 RIA equals the single plane to round-off')
        call assert_true(st1%diss_damage > 0.0_dp .and. st1%diss_friction > 0.0_dp, &
                         'the comparison path damages and slides')
      end do
    end do
  end subroutine flat_ria_is_single_plane

  !> Fig. 5 scene (Table 1, theta = 45 deg, sigma_N = -0.2 MPa, slip to 0.6 mm): H_N = 1e3 mm
  !> against H_N = +infinity.
  subroutine deep_asperities_are_infinite()
    type(interlock_material_t) :: deep, inf
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: last
    integer, parameter :: n = 60
    real(dp) :: hd(0:n, 7), hi(0:n, 7), et, en, ref(17)
    integer :: is
    call read_reference_row('data/core/fig5_HN_inf_last_row.csv', ref)
    call table1_material(deep, 45.0_dp, 1.0e3_dp, .false.)
    call table1_material(inf, 45.0_dp, huge(1.0_dp), .false.)
    call assert_true(deep%use_depth .and. .not. inf%use_depth, 'depth 1e3 mm is finite, huge is infinite')
    do is = 1, 2
      solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
      call slide_history(deep, solver, -0.2_dp, 0.6_dp, n, hd, last)
      call slide_history(inf, solver, -0.2_dp, 0.6_dp, n, hi, last)
      et = maxval(abs(hd(:, 4) - hi(:, 4))) / maxval(abs(hi(:, 4)))
      en = maxval(abs(hd(:, 1) - hi(:, 1))) / maxval(abs(hi(:, 1)))
      write (output_unit, '(a,2es10.3)') '    H_N = 1e3 vs infinite, rel. diff sigma_T, s_N: ', et, en
      call assert_true(et <= 1.0e-3_dp .and. en <= 1.0e-3_dp, 'H_N = 1e3 mm is infinite depth to 1e-3')
      call assert_true(et > 1.0e-8_dp, 'H_N = 1e3 mm still acts (the comparison is not vacuous)')
      ! no wear: step-size independent, so the reference holds to its printed digits
      call assert_close_rel(ref(2), hi(n, 1), 1.0e-9_dp, 1.0e-3_dp, &
                            'infinite depth: s_N at 0.6 mm (reference fig5/HN_inf.csv)')
      call assert_close_rel(ref(5), hi(n, 4), 1.0e-9_dp, 1.0e-3_dp, &
                            'infinite depth: sigma_T at 0.6 mm (reference fig5/HN_inf.csv)')
    end do
  end subroutine deep_asperities_are_infinite

  !> Fig. 10 with theta_f = theta_0 = 30 deg (zeta_0 = 20 N/mm, H_N = 1 mm, sigma_N = -2 MPa):
  !> once only the leading plane slides, tau = p tan(theta_0 + atan(mu)) exactly, however far
  !> the slip goes and although the finite depth shrinks the contact area.
  subroutine no_wear_plateau()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: last
    integer, parameter :: n = 200
    real(dp) :: h(0:n, 7), plateau
    integer :: is, i
    call table2_material(mat, 30.0_dp, 30.0_dp, 20.0_dp, 1.0_dp)
    call assert_true(.not. mat%use_wear, 'theta_f = theta_0 switches wear off')
    plateau = 2.0_dp * tan(30.0_dp * deg_to_rad + atan(0.5_dp))
    do is = 1, 2
      solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
      call slide_history(mat, solver, -2.0_dp, 20.0_dp, n, h, last)
      do i = n / 4, n
        call assert_close_rel(plateau, h(i, 4), 1.0e-9_dp, 1.0_dp, 'horizontal sliding plateau')
      end do
      call assert_close_rel(30.0_dp * deg_to_rad, -last%theta(1), 1.0e-15_dp, 1.0_dp, 'no wear of theta_1')
      call assert_true(h(n, 1) > h(n / 2, 1) .and. h(n, 1) < 1.0_dp, &
                       'dilation grows towards H_N on the plateau')
    end do
  end subroutine no_wear_plateau

  !> Fig. 10 with theta_f = 0: the inclination wears to 0 and the dilation falls back towards 0
  !> (reference fig10/thetaf_0.csv: peak 0.467 mm at 3.2 mm of slip, 0.032 mm at 20 mm).
  subroutine wear_to_flat_removes_dilation()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: last
    integer, parameter :: n = 400
    real(dp) :: h(0:n, 7), peak, ref(17)
    integer :: is
    call read_reference_row('data/core/fig10_thetaf_0_last_row.csv', ref)
    call table2_material(mat, 30.0_dp, 0.0_dp, 20.0_dp, 1.0_dp)
    do is = 1, 2
      solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
      call slide_history(mat, solver, -2.0_dp, 20.0_dp, n, h, last)
      peak = maxval(h(:, 1))
      write (output_unit, '(a,3es11.3)') '    theta_f = 0: peak s_N, final s_N, final theta_1 [deg]: ', &
        peak, h(n, 1), h(n, 5) * rad_to_deg
      call assert_true(peak > 0.4_dp, 'the asperities first dilate the interface')
      call assert_true(h(n, 1) < 0.15_dp * peak, 'dilation falls back towards zero')
      call assert_true(all(h(3 * n / 4 + 1:n, 1) < h(3 * n / 4:n - 1, 1)), &
                       'dilation keeps decreasing at the end')
      call assert_true(abs(h(n, 5)) < 1.0_dp * deg_to_rad, 'theta_1 worn to within 1 deg of 0')
      call assert_true(all(abs(h(1:n, 5)) <= abs(h(0:n - 1, 5))), 'theta_1 decays monotonically')
      ! 400 steps of a first-order scheme against the converged reference: a few per cent
      call assert_close_rel(ref(2), h(n, 1), 0.1_dp, 1.0e-3_dp, &
                            'final dilation near the converged reference (fig10/thetaf_0.csv)')
      call assert_close_rel(ref(7), h(n, 5) * rad_to_deg, 0.1_dp, 1.0e-3_dp, &
                            'final theta_1 near the converged reference (fig10/thetaf_0.csv)')
    end do
  end subroutine wear_to_flat_removes_dilation

end module test_limits
