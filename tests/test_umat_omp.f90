!> The UMAT called from several OpenMP threads at once (each thread its own material points)
!> gives bitwise the numbers of the serial run: no SAVE'd or shared state is written.
module test_umat_omp_cases
  !$ use omp_lib, only: omp_get_num_threads
  use interlock, only: dp, umat_nstatv, same_value
  use interlock_assert
  use test_umat_interface, only: umat_point_t, call_umat
  implicit none
  private
  public :: collect_umat_omp

  integer, parameter :: n_points = 32, n_steps = 400, n_threads = 4, n_repeats = 3
  real(dp), parameter :: props(11) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 2.0_dp, &
                                      30.0_dp, 7.0_dp, 1.0_dp, 0.0_dp, 2.0_dp]

  !> What one point's history produced.
  type :: history_t
    real(dp) :: stress(2, n_steps), ddsdde(2, 2, n_steps), statev(umat_nstatv)
    real(dp) :: pnewdt(n_steps)
  end type history_t

contains

  subroutine collect_umat_omp()
    call run_case('threads_equal_serial', threads_equal_serial)
  end subroutine collect_umat_omp

  !> Separation at step j of point p: compression, then cyclic slip with dilation, different
  !> amplitude and phase per point.
  pure function path(p, j) result(s)
    integer, intent(in) :: p, j
    real(dp) :: s(2), t, amp
    t = real(j, dp) / real(n_steps, dp)
    amp = 0.1_dp + 0.02_dp * real(p, dp)
    s(1) = -0.003_dp * min(1.0_dp, 20.0_dp * t) + 0.05_dp * amp * (1.0_dp - cos(6.0_dp * t + p))
    s(2) = amp * sin(12.0_dp * t + 0.3_dp * p) * min(1.0_dp, 20.0_dp * t)
  end function path

  subroutine run_point(p, h)
    integer, intent(in) :: p
    type(history_t), intent(out) :: h
    type(umat_point_t) :: pt
    integer :: j
    allocate (pt%stress(2), pt%statev(umat_nstatv), pt%ddsdde(2, 2))
    pt%stress = 0.0_dp
    pt%statev = 0.0_dp
    pt%ddsdde = 0.0_dp
    do j = 1, n_steps
      pt%pnewdt = 1.0e36_dp
      call call_umat(pt, props, path(p, j - 1), path(p, j) - path(p, j - 1), p, 1, j)
      h%stress(:, j) = pt%stress
      h%ddsdde(:, :, j) = pt%ddsdde
      h%pnewdt(j) = pt%pnewdt
    end do
    h%statev = pt%statev
  end subroutine run_point

  subroutine threads_equal_serial()
    type(history_t), allocatable :: serial(:), parallel(:)
    integer :: p, team, mismatches, r
    allocate (serial(n_points), parallel(n_points))
    do p = 1, n_points
      call run_point(p, serial(p))
    end do
    team = 1
    mismatches = 0
    do r = 1, n_repeats   ! a race shows up only sometimes: give it several chances
      !$omp parallel num_threads(n_threads) shared(parallel, team)
      !$omp single
      !$ team = omp_get_num_threads()
      !$omp end single
      !$omp do schedule(dynamic, 1)
      do p = 1, n_points
        call run_point(p, parallel(p))
      end do
      !$omp end do
      !$omp end parallel
      do p = 1, n_points
        if (.not. (all(same_value(serial(p)%stress, parallel(p)%stress)) .and. &
                   all(same_value(serial(p)%ddsdde, parallel(p)%ddsdde)) .and. &
                   all(same_value(serial(p)%statev, parallel(p)%statev)) .and. &
                   all(same_value(serial(p)%pnewdt, parallel(p)%pnewdt)))) mismatches = mismatches + 1
      end do
    end do
    write (*, '(a,i0,a,i0,a,i0,a,i0,a)') '    ', n_repeats, ' x ', n_points, ' points x ', n_steps, &
      ' increments on ', team, ' threads'
    call assert_true(team >= 2, 'the parallel loop ran on more than one thread')
    call assert_equal(0, mismatches, 'threaded point histories that differ (bitwise) from the serial ones')
    call assert_true(maxval(serial(n_points)%statev(1:3)) > 0.99_dp, 'the histories damage the interface')
    call assert_true(serial(n_points)%statev(21) > 0.0_dp, 'the histories dissipate by friction')
  end subroutine threads_equal_serial

end module test_umat_omp_cases

program test_umat_omp
  use test_umat_omp_cases, only: collect_umat_omp
  use interlock_assert, only: suite_summary
  implicit none
  call collect_umat_omp()
  if (suite_summary('umat_omp') /= 0) error stop 1
end program test_umat_omp
