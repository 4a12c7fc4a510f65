!> The closed forms of SPEC section 8, computed here by hand from the parameters (not by the
!> library): the bilinear mode-I law, mode II under constant compression, steady sliding of a
!> fully debonded RIA, and the energy balance with finite depth and wear off.
module test_closed_forms
  use interlock
  use interlock_assert, only: assert_true, assert_equal, assert_close_rel
  use test_core_support, only: flat_material, table1_material, solve_sigma_n
  use, intrinsic :: iso_fortran_env, only: output_unit
  implicit none
  private
  public :: mode_one_bilinear, mode_two_constant_compression, steady_sliding_ria, &
            energy_balance_first_order

  real(dp), parameter :: exact_tol = 1.0e-8_dp

contains

  !> Pure mode I on a flat interface: K_n s up to (s_0n, sigma0_n), linear down to (s_cn, 0),
  !> zero beyond; the area under the curve (exact for the nodes) is Gc_bar, and so is the work.
  subroutine mode_one_bilinear()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: s0n, scn, kn, sigma(2), tangent(2, 2), expect, area, sprev, tprev
    real(dp) :: nodes(9)
    integer :: i, is
    do is = 1, 2
      call flat_material(mat, 0.5_dp, huge(1.0_dp))
      solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
      s0n = (1.0_dp - 0.9_dp) * 2.0_dp * 0.3_dp / 3.0_dp     ! (1 - eta) 2 Gc / sigma0_n
      scn = 2.0_dp * 0.3_dp / 3.0_dp
      kn = 3.0_dp / s0n
      nodes = [0.25_dp * s0n, s0n, 0.03_dp, 0.05_dp, 0.1_dp, 0.15_dp, 0.19_dp, scn, 0.25_dp]
      call interlock_state_init(mat, old)
      area = 0.0_dp
      sprev = 0.0_dp
      tprev = 0.0_dp
      do i = 1, size(nodes)
        call interlock_update(mat, solver, [nodes(i), 0.0_dp], old, new, sigma, tangent, info)
        call assert_equal(status_ok, info%status, 'mode I update')
        if (nodes(i) <= s0n) then
          expect = kn * nodes(i)
        else if (nodes(i) <= scn) then
          expect = 3.0_dp * (scn - nodes(i)) / (scn - s0n)
        else
          expect = 0.0_dp
        end if
        call assert_close_rel(expect, sigma(1), exact_tol, 3.0_dp, 'mode I sigma_N (bilinear)')
        call assert_equal(0.0_dp, sigma(2), 1.0e-14_dp, 'mode I sigma_T = 0')
        if (same_value(nodes(i), s0n)) call assert_close_rel(3.0_dp, sigma(1), exact_tol, 3.0_dp, &
                                                             'mode I peak sigma0_n at s_0n')
        if (same_value(nodes(i), scn)) call assert_equal(0.0_dp, sigma(1), exact_tol * 3.0_dp, &
                                                         'mode I zero traction at s_cn')
        area = area + 0.5_dp * (tprev + sigma(1)) * (nodes(i) - sprev)
        sprev = nodes(i)
        tprev = sigma(1)
        old = new
      end do
      call assert_close_rel(0.3_dp, area, exact_tol, 0.3_dp, 'mode I area = Gc_bar')
      call assert_close_rel(0.3_dp, old%work, exact_tol, 0.3_dp, 'mode I work = Gc_bar')
      call assert_close_rel(1.0_dp, old%damage(1), exact_tol, 1.0_dp, 'mode I D = 1 beyond s_cn')
    end do
  end subroutine mode_one_bilinear

  !> Pure mode II on a flat interface at sigma_N = -p: s_N = -p/K_n and
  !> tau = (1-D) K_t s_T + D min(K_t s_T, mu p), D from beta = s_T/s_0t; residual mu p.
  subroutine mode_two_constant_compression()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    real(dp) :: sigma(2), tangent(2, 2), s0t, kt, kn, p, mu, st, beta, d, expect, eta
    integer :: i, is
    logical :: ok
    p = 1.0_dp
    mu = 0.5_dp
    eta = 0.9_dp
    s0t = (1.0_dp - eta) * 2.0_dp * 0.3_dp / 2.0_dp        ! sigma0_t = 2 MPa
    kt = 2.0_dp / s0t
    kn = 3.0_dp / ((1.0_dp - eta) * 2.0_dp * 0.3_dp / 3.0_dp)
    do is = 1, 2
      call flat_material(mat, mu, huge(1.0_dp))
      solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
      call interlock_state_init(mat, old)
      do i = 0, 45
        st = 0.01_dp * i
        call solve_sigma_n(mat, solver, old, st, -p, new, sigma, tangent, ok)
        if (.not. ok) return
        beta = st / s0t
        d = 0.0_dp
        if (beta > 1.0_dp) d = min(1.0_dp, (beta - 1.0_dp) / (eta * beta))
        expect = (1.0_dp - d) * kt * st + d * min(kt * st, mu * p)
        call assert_close_rel(-p / kn, new%s(1), exact_tol, 1.0_dp, 'mode II s_N = -p/K_n')
        call assert_close_rel(expect, sigma(2), exact_tol, mu * p, 'mode II tau(s_T)')
        old = new
      end do
      call assert_close_rel(mu * p, sigma(2), exact_tol, 1.0_dp, 'mode II residual mu p')
      call assert_close_rel(1.0_dp, old%damage(1), exact_tol, 1.0_dp, 'mode II fully debonded')
    end do
  end subroutine mode_two_constant_compression

  !> Fully debonded RIA, infinite depth, no wear, constant p, positive slip: only the leading
  !> plane (-theta_0) stays in contact; tau/p = tan(theta_0 + atan(mu)), ds_N/ds_T = tan(theta_0).
  subroutine steady_sliding_ria()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    real(dp) :: sigma(2), tangent(2, 2), th0, p, sn_prev, rate, skn(3)
    integer :: i, is, k, n
    logical :: ok
    real(dp), parameter :: thetas(2) = [30.0_dp, 12.0_dp]
    integer :: it
    p = 0.2_dp
    n = 40
    do it = 1, size(thetas)
      do is = 1, 2
        th0 = thetas(it) * deg_to_rad
        call table1_material(mat, thetas(it), huge(1.0_dp), .true.)
        solver%scheme = merge(scheme_explicit, scheme_implicit, is == 1)
        call interlock_state_init(mat, old)
        sn_prev = 0.0_dp
        rate = 0.0_dp
        do i = 0, n
          call solve_sigma_n(mat, solver, old, 0.025_dp * i, -p, new, sigma, tangent, ok)
          if (.not. ok) return
          rate = (new%s(1) - sn_prev) / 0.025_dp
          sn_prev = new%s(1)
          old = new
        end do
        call assert_close_rel(tan(th0 + atan(0.5_dp)), sigma(2) / p, exact_tol, 1.0_dp, &
                              'steady sliding tau/p = tan(theta_0 + atan(mu))')
        call assert_close_rel(tan(th0), rate, exact_tol, 1.0_dp, &
                              'steady sliding ds_N/ds_T = tan(theta_0)')
        do k = 1, 3
          skn(k) = cos(old%theta(k)) * old%s(1) + sin(old%theta(k)) * old%s(2)
        end do
        call assert_true(skn(1) < 0.0_dp .and. skn(2) > 0.0_dp .and. skn(3) > 0.0_dp, &
                         'steady sliding: only the leading plane is in contact')
      end do
    end do
  end subroutine steady_sliding_ria

  !> work = stored + damage dissipation + friction dissipation (finite depth and wear off),
  !> both dissipations non-negative and non-decreasing. The discrete bookkeeping is first
  !> order in the step: the imbalance must fall (about halve) when the step is halved.
  subroutine energy_balance_first_order()
    integer :: is, ir
    real(dp) :: imb(3), work
    character(len=8) :: tag
    do is = 1, 2
      do ir = 1, 3
        call energy_path(merge(scheme_explicit, scheme_implicit, is == 1), 100 * 2**(ir - 1), &
                         imb(ir), work)
      end do
      tag = scheme_name(merge(scheme_explicit, scheme_implicit, is == 1))
      write (output_unit, '(a,3es11.3,a,es11.3)') '    ' // tag // ' |imbalance|/work at 100, 200, 400 steps/segment:', &
        imb, '  work', work
      ! tolerance C/n that tightens with the step (measured C ~ 0.9)
      call assert_true(imb(1) <= 1.5_dp / 100.0_dp .and. imb(2) <= 1.5_dp / 200.0_dp .and. &
                       imb(3) <= 1.5_dp / 400.0_dp, trim(tag) // &
                       ': energy imbalance <= 1.5/n (n steps per segment)')
      call assert_true(imb(2) <= 0.6_dp * imb(1) .and. imb(3) <= 0.6_dp * imb(2), &
                       trim(tag) // ': energy imbalance falls at first order with the step')
      call assert_true(imb(3) >= 0.3_dp * imb(2), trim(tag) // &
                       ': energy imbalance is first order (not suspiciously exact)')
    end do
  end subroutine energy_balance_first_order

  !> A closed mixed-mode path (compression, shear, opening, reclosing, reverse shear) on the
  !> virgin Table 1 RIA at 10 deg, infinite depth, no wear; n steps per segment.
  subroutine energy_path(scheme, n, imbalance, work)
    integer, intent(in) :: scheme, n
    real(dp), intent(out) :: imbalance, work
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), tangent(2, 2), s(2)
    integer :: iseg, i
    logical :: mono
    real(dp), parameter :: nodes(2, 7) = reshape([0.0_dp, 0.0_dp, -0.01_dp, 0.0_dp, &
      -0.01_dp, 0.1_dp, 0.05_dp, 0.15_dp, -0.005_dp, 0.05_dp, -0.01_dp, -0.1_dp, 0.1_dp, 0.0_dp], &
      [2, 7])
    call table1_material(mat, 10.0_dp, huge(1.0_dp), .false.)
    solver%scheme = scheme
    call interlock_state_init(mat, old)
    mono = .true.
    do iseg = 1, size(nodes, 2) - 1
      do i = 1, n
        s = nodes(:, iseg) + (nodes(:, iseg + 1) - nodes(:, iseg)) * real(i, dp) / real(n, dp)
        call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
        mono = mono .and. new%diss_damage >= old%diss_damage .and. &
               new%diss_friction >= old%diss_friction .and. new%stored >= 0.0_dp
        old = new
      end do
    end do
    call assert_true(mono, scheme_name(scheme) // &
                     ': dissipations non-negative and non-decreasing, stored energy >= 0')
    call assert_true(old%diss_damage > 0.0_dp .and. old%diss_friction > 0.0_dp, &
                     scheme_name(scheme) // ': the path dissipates by damage and by friction')
    work = old%work
    imbalance = abs(old%work - old%stored - old%diss_damage - old%diss_friction) / old%work
  end subroutine energy_path

end module test_closed_forms
