!> Unit tests of the mixed-control solver of interlock-history (src/driver/
!> interlock_mixed_control.f90) against closed forms of SPEC section 8 on a flat interface.
module test_history_mixed_control_cases
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_t, &
      interlock_state_init, interlock_material_prepare, interlock_paper_ria, status_ok, &
      scheme_implicit, same_value, interlock_state_3d_t, interlock_state_3d_init
  use interlock_mixed_control, only: control_t, history_t, solve_step, run_history, &
      run_history_extrapolated
  use interlock_assert, only: assert_equal, assert_true
  implicit none
  private
  public :: collect_history_mixed_control

contains

  subroutine collect_history_mixed_control()
    use interlock_assert, only: run_case
    call run_case('preload_normal_traction_closed_form', preload_normal_traction_closed_form)
    call run_case('both_tractions_elastic_dgesv', both_tractions_elastic_dgesv)
    call run_case('three_tractions_elastic_3d', three_tractions_elastic_3d)
    call run_case('debonded_flat_slip_any_direction_3d', debonded_flat_slip_any_direction_3d)
    call run_case('tangential_traction_below_friction_limit', tangential_traction_below_friction_limit)
    call run_case('tangential_traction_above_friction_limit_fails', &
                  tangential_traction_above_friction_limit_fails)
    call run_case('separated_interface_stops_history', separated_interface_stops_history)
    call run_case('failed_step_names_its_target_and_place', failed_step_names_its_target_and_place)
    call run_case('extrapolated_history_is_composed_of_both_runs', &
                  extrapolated_history_is_composed_of_both_runs)
    call run_case('extrapolated_history_stops_naming_the_run', &
                  extrapolated_history_stops_naming_the_run)
  end subroutine collect_history_mixed_control

  !> Table 1 parameters, a flat RIA (theta = 0): K_n = K_t = 150 MPa/mm.
  subroutine flat_material(mat, h_n, prefractured)
    type(interlock_material_t), intent(out) :: mat
    real(dp), intent(in) :: h_n
    logical, intent(in) :: prefractured
    integer :: stat
    character(len=256) :: message
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 3.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.5_dp
    mat%h_n = h_n
    mat%prefractured = prefractured
    call interlock_paper_ria(mat, 0.0_dp, 0.0_dp, huge(1.0_dp))
    call interlock_material_prepare(mat, stat, message)
    call assert_true(stat == status_ok, 'material prepared: ' // trim(message))
  end subroutine flat_material

  subroutine preload_normal_traction_closed_form()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(2)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .false.)
    call interlock_state_init(mat, old)
    ctl%traction(1:2) = [.true., .false.]
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp], [-0.2_dp, 0.0_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat == status_ok, 'preload solved: ' // trim(message))
    ! s_N = sigma_N / K_n with K_n = sigma0_n / ((1 - eta) 2 Gc / sigma0_n) = 150 MPa/mm.
    call assert_equal(-0.2_dp / 150.0_dp, new%s(1), 1.0e-15_dp, 's_N = sigma_N / K_n')
    call assert_equal(-0.2_dp, sigma(1), 3.0e-12_dp, 'sigma_N = target')
    call assert_equal(0.0_dp, new%s(2), 0.0_dp, 's_T prescribed')
    call assert_true(sub == 1, 'one sub-increment')
    call assert_true(it >= 1 .and. it <= 3, 'Newton converges in at most 3 iterations (linear)')
  end subroutine preload_normal_traction_closed_form

  subroutine both_tractions_elastic_dgesv()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(2)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .false.)
    call interlock_state_init(mat, old)
    ctl%traction(1:2) = [.true., .true.]
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp], [-0.1_dp, 0.05_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat == status_ok, 'both components solved: ' // trim(message))
    call assert_equal(-0.1_dp / 150.0_dp, new%s(1), 1.0e-15_dp, 's_N = sigma_N / K_n')
    call assert_equal(0.05_dp / 150.0_dp, new%s(2), 1.0e-15_dp, 's_T = sigma_T / K_t')
    call assert_equal(0.0_dp, new%damage(1), 0.0_dp, 'still elastic')
  end subroutine both_tractions_elastic_dgesv

  !> Three components traction-driven (Newton on the 3x3 tangent) on a flat elastic interface:
  !> s = sigma / K componentwise (K_n = K_t = 150 MPa/mm), in any in-plane direction.
  subroutine three_tractions_elastic_3d()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(3)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .false.)
    call interlock_state_3d_init(mat, old)
    ctl%n = 3
    ctl%traction = [.true., .true., .true.]
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp, 0.0_dp], [-0.1_dp, 0.03_dp, 0.04_dp], &
                    new, sigma, it, sub, stat, message)
    call assert_true(stat == status_ok, 'three components solved: ' // trim(message))
    call assert_equal(-0.1_dp / 150.0_dp, new%s(1), 1.0e-15_dp, 's_N = sigma_N / K_n')
    call assert_equal(0.03_dp / 150.0_dp, new%s(2), 1.0e-15_dp, 's_T1 = sigma_T1 / K_t')
    call assert_equal(0.04_dp / 150.0_dp, new%s_t2, 1.0e-15_dp, 's_T2 = sigma_T2 / K_t')
    call assert_equal(0.04_dp, sigma(3), 1.0e-13_dp, 'sigma_T2 = target')
    call assert_equal(0.0_dp, new%damage(1), 0.0_dp, 'still elastic')
  end subroutine three_tractions_elastic_3d

  !> SPEC section 9's closed form through the driver: a debonded (pre-fractured) flat interface
  !> under sigma_N = -0.2 MPa (traction-driven) slid 0.1 mm at 30 deg from t1 in 10 steps: the
  !> shear is mu p = 0.1 MPa along the slip, none across.
  subroutine debonded_flat_slip_any_direction_3d()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(3), c, s, start(3), end(3)
    integer :: it, sub, stat, j
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .true.)
    call interlock_state_3d_init(mat, old)
    ctl%n = 3
    ctl%traction = [.true., .false., .false.]
    c = cos(acos(-1.0_dp) / 6.0_dp)
    s = sin(acos(-1.0_dp) / 6.0_dp)
    end = [-0.2_dp, 0.0_dp, 0.0_dp]
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp, 0.0_dp], end, new, sigma, it, sub, &
                    stat, message)
    call assert_true(stat == status_ok, 'preload solved: ' // trim(message))
    do j = 1, 10
      old = new
      start = end
      end = [-0.2_dp, 0.01_dp * j * c, 0.01_dp * j * s]
      call solve_step(mat, solver, ctl, old, start, end, new, sigma, it, sub, stat, message)
      call assert_true(stat == status_ok, 'slip step solved: ' // trim(message))
    end do
    call assert_equal(-0.2_dp, sigma(1), 1.0e-12_dp, 'sigma_N held')
    call assert_equal(0.1_dp * c, sigma(2), 1.0e-13_dp, 'sigma_T1 = mu p cos(30 deg)')
    call assert_equal(0.1_dp * s, sigma(3), 1.0e-13_dp, 'sigma_T2 = mu p sin(30 deg)')
  end subroutine debonded_flat_slip_any_direction_3d

  !> Pre-fractured flat interface under p = 0.2 MPa: tau = min(K_t s_T, mu p) (SPEC 8).
  subroutine tangential_traction_below_friction_limit()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(2)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .true.)
    call interlock_state_init(mat, old)
    ctl%traction(1:2) = [.true., .true.]
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp], [-0.2_dp, 0.05_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat == status_ok, 'sticking solved: ' // trim(message))
    call assert_equal(0.05_dp / 150.0_dp, new%s(2), 1.0e-14_dp, 'sticking: s_T = tau / K_t')
    call assert_equal(-0.2_dp / 150.0_dp, new%s(1), 1.0e-14_dp, 's_N = -p / K_n')
  end subroutine tangential_traction_below_friction_limit

  subroutine tangential_traction_above_friction_limit_fails()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(2)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .true.)
    call interlock_state_init(mat, old)
    ctl%traction(1:2) = [.false., .true.]
    old%s = [-0.2_dp / 150.0_dp, 0.0_dp]
    ! mu p = 0.1 MPa is the largest shear a sliding, fully damaged plane carries.
    call solve_step(mat, solver, ctl, old, [old%s(1), 0.0_dp], [old%s(1), 0.15_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat /= status_ok, 'no s_T carries sigma_T > mu p')
    call assert_true(index(message, 'no s_T carries sigma_T') > 0, 'reason: ' // trim(message))
    call assert_equal(old%s(2), new%s(2), 0.0_dp, 'the state is left as it was')
  end subroutine tangential_traction_above_friction_limit_fails

  !> A history that opens the interface while a shear traction is prescribed: an open, fully
  !> damaged interface carries no shear, so the history stops; the rows computed before are kept
  !> and the status says why.
  subroutine separated_interface_stops_history()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(interlock_state_3d_t) :: initial
    type(control_t) :: ctl
    type(history_t) :: hist
    real(dp) :: sigma(2)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, 1.0_dp, .false.)
    call interlock_state_3d_init(mat, initial)
    ctl%traction(1:2) = [.false., .true.]
    call run_history(mat, solver, ctl, [0.0_dp, 1.0_dp, 2.0_dp], &
                     reshape([0.0_dp, 0.0_dp, -0.001_dp, 0.01_dp, 2.0_dp, 0.01_dp], [2, 3]), &
                     [2, 2], initial, hist)
    call assert_true(hist%n_rows == 2, 'two rows kept')
    call assert_true(index(hist%status, 'stopped at step 3 of 4 (segment 2 of 2, its step 1 of 2;') &
                     == 1, 'status: ' // hist%status)
    call assert_true(index(hist%status, 'no s_T carries sigma_T') > 0, 'reason: ' // hist%status)
    call assert_equal(0.01_dp, hist%traction(2, 2), 1.0e-13_dp, 'row 2 carries sigma_T')
    ! Beyond H_N the traction is identically 0: the reason names the separation (SPEC D7).
    old = initial%interlock_state_t
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp], [1.5_dp, 0.0_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat == status_ok, 'zero shear beyond H_N: ' // trim(message))
    call assert_equal(0.0_dp, sigma(1), 0.0_dp, 'nothing transmitted beyond H_N')
    old = new
    call solve_step(mat, solver, ctl, old, [1.5_dp, 0.0_dp], [1.5_dp, 0.01_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat /= status_ok, 'no shear beyond H_N')
    call assert_true(index(message, 'separated') > 0, 'reason: ' // trim(message))
  end subroutine separated_interface_stops_history

  !> A step that fails names the step's own target (not the target of its
  !> last halved sub-step, 0.01 MPa / 2**30 here) and why no solution exists: a fully damaged
  !> interface (infinite H_N) or one separated beyond H_N carries no tension.
  subroutine failed_step_names_its_target_and_place()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_t) :: old, new
    type(control_t) :: ctl
    real(dp) :: sigma(2)
    integer :: it, sub, stat
    character(len=512) :: message
    call flat_material(mat, huge(1.0_dp), .false.)
    call interlock_state_init(mat, old)
    old%damage = 1.0_dp
    old%beta = 1.0e3_dp
    old%s = [0.5_dp, 0.0_dp]
    old%sigma = 0.0_dp
    ctl%traction(1:2) = [.true., .false.]
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp], [0.01_dp, 0.0_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat /= status_ok, 'no tension on a fully damaged interface')
    call assert_true(index(message, 'cannot reach sigma_N = 0.01 MPa') == 1, &
                     'the step''s target first: ' // trim(message))
    call assert_true(index(message, 'fully damaged') > 0, 'says why: ' // trim(message))
    call flat_material(mat, 0.1_dp, .false.)
    call solve_step(mat, solver, ctl, old, [0.0_dp, 0.0_dp], [0.01_dp, 0.0_dp], new, sigma, it, &
                    sub, stat, message)
    call assert_true(stat /= status_ok .and. index(message, 'has separated (s_N = 0.5 >= H_N') > 0, &
                     'beyond H_N: says the interface has separated: ' // trim(message))
  end subroutine failed_step_names_its_target_and_place

  !> Richardson extrapolation on a wearing RIA (Table 2, theta_0 = 30, theta_f = 7 deg,
  !> zeta_0 = 1 N/mm, H_N = 1 mm; implicit; a one-step preload, then 20 slip steps): row i is
  !> built from row i of the run with the path's steps (n) and the row of the run with the slip
  !> segment's steps doubled (2n; the one-step preload is not refined) that ends
  !> at the same point, each computed here by run_history: separation and traction
  !> 2 u(2n) - u(n), the 2n run's state variables and energies bit for bit, iterations and
  !> substeps summed over the steps; the preload row the same in both runs, so extrapolated it is
  !> the plain row bit for bit; sigma_N (traction-driven) within 3 newton_tol of its target; and
  !> the extrapolation changes the result (wear makes it depend on the step).
  subroutine extrapolated_history_is_composed_of_both_runs()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: initial
    type(control_t) :: ctl
    type(history_t) :: coarse, fine, extra
    real(dp), parameter :: times(3) = [0.0_dp, 1.0_dp, 3.0_dp]
    real(dp), parameter :: values(2, 3) = reshape([0.0_dp, 0.0_dp, -2.0_dp, 0.0_dp, -2.0_dp, &
                                                   2.0_dp], [2, 3])
    integer :: i, f, stat
    integer :: it_fine, sub_fine
    character(len=256) :: message
    logical :: same
    mat%sigma0_n = 0.025_dp
    mat%sigma0_t = 0.025_dp
    mat%gc = 0.0005_dp
    mat%eta = 0.99_dp
    mat%mu = 0.5_dp
    mat%h_n = 1.0_dp
    call interlock_paper_ria(mat, 30.0_dp * acos(-1.0_dp) / 180.0_dp, &
                             7.0_dp * acos(-1.0_dp) / 180.0_dp, 1.0_dp)
    call interlock_material_prepare(mat, stat, message)
    call assert_true(stat == status_ok, 'material prepared: ' // trim(message))
    solver%scheme = scheme_implicit
    call interlock_state_3d_init(mat, initial)
    ctl%traction(1:2) = [.true., .false.]
    call run_history(mat, solver, ctl, times, values, [1, 20], initial, coarse)
    call run_history(mat, solver, ctl, times, values, [1, 40], initial, fine)
    call run_history_extrapolated(mat, solver, ctl, times, values, [1, 20], initial, extra)
    call assert_true(extra%status == 'completed' .and. extra%n_rows == 21 .and. extra%extrapolated, &
                     'extrapolated history completed, 21 rows: ' // extra%status)
    call assert_true(.not. (coarse%extrapolated .or. fine%extrapolated), 'plain runs not marked')
    if (extra%n_rows /= 21 .or. coarse%n_rows /= 21 .or. fine%n_rows /= 41) return
    same = .true.
    do i = 1, 21
      ! The fine run's row at the same point, and the fine steps that lead there from the last.
      if (i == 1) then
        f = 1
        it_fine = fine%iterations(1)
        sub_fine = fine%substeps(1)
      else
        f = 2 * i - 1
        it_fine = fine%iterations(f - 1) + fine%iterations(f)
        sub_fine = fine%substeps(f - 1) + fine%substeps(f)
      end if
      same = same .and. same_value(extra%time(i), coarse%time(i)) .and. &
             same_value(extra%time(i), fine%time(f)) .and. &
             all(same_value(extra%separation(:, i), &
                            2.0_dp * fine%separation(:, f) - coarse%separation(:, i))) .and. &
             all(same_value(extra%traction(:, i), &
                            2.0_dp * fine%traction(:, f) - coarse%traction(:, i))) .and. &
             all(same_value(extra%damage(:, i), fine%damage(:, f))) .and. &
             all(same_value(extra%beta(:, i), fine%beta(:, f))) .and. &
             all(same_value(extra%theta(:, i), fine%theta(:, f))) .and. &
             all(same_value(extra%zeta(:, i), fine%zeta(:, f))) .and. &
             all(same_value(extra%frictional_slip(:, i), fine%frictional_slip(:, f))) .and. &
             all(same_value(extra%friction_traction(:, i), fine%friction_traction(:, f))) .and. &
             same_value(extra%work(i), fine%work(f)) .and. &
             same_value(extra%diss_friction(i), fine%diss_friction(f)) .and. &
             extra%iterations(i) == coarse%iterations(i) + it_fine .and. &
             extra%substeps(i) == coarse%substeps(i) + sub_fine
      call assert_equal(-2.0_dp, extra%traction(1, i), 3.0_dp * ctl%tol * 2.0_dp, &
                        'sigma_N extrapolates to its target')
    end do
    call assert_true(all(same_value(extra%separation(:, 1), coarse%separation(:, 1))) .and. &
                     all(same_value(extra%traction(:, 1), coarse%traction(:, 1))), &
                     'the one-step preload: the same in both runs, so its extrapolated row is ' // &
                     'the plain row bit for bit')
    call assert_true(same, 'rows composed of the coarse row i and the fine row at the same point')
    call assert_true(abs(extra%traction(2, 21) - coarse%traction(2, 21)) > 1.0e-6_dp, &
                     'with wear the extrapolation changes sigma_T')
  end subroutine extrapolated_history_is_composed_of_both_runs

  !> The history of separated_interface_stops_history, extrapolated: it stops at the same step,
  !> keeps the rows before it, and the status names the run that failed.
  subroutine extrapolated_history_stops_naming_the_run()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: initial
    type(control_t) :: ctl
    type(history_t) :: hist
    call flat_material(mat, 1.0_dp, .false.)
    call interlock_state_3d_init(mat, initial)
    ctl%traction(1:2) = [.false., .true.]
    call run_history_extrapolated(mat, solver, ctl, [0.0_dp, 1.0_dp, 2.0_dp], &
                     reshape([0.0_dp, 0.0_dp, -0.001_dp, 0.01_dp, 2.0_dp, 0.01_dp], [2, 3]), &
                     [2, 2], initial, hist)
    call assert_true(hist%n_rows == 2, 'two rows kept')
    call assert_true(index(hist%status, 'stopped at step 3 ') == 1, 'status: ' // hist%status)
    call assert_true(index(hist%status, 'the run with the deck''s steps: cannot reach') > 0 .and. &
                     index(hist%status, 'no s_T carries sigma_T') > 0, &
                     'reason: ' // hist%status)
    call assert_equal(0.01_dp, hist%traction(2, 2), 3.0e-13_dp, 'row 2 carries sigma_T')
  end subroutine extrapolated_history_stops_naming_the_run

end module test_history_mixed_control_cases

program test_history_mixed_control
  use test_history_mixed_control_cases, only: collect_history_mixed_control
  use interlock_assert, only: suite_summary
  implicit none
  call collect_history_mixed_control()
  if (suite_summary('history_mixed_control') /= 0) error stop 1
end program test_history_mixed_control
