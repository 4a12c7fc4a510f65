!> The example of README.md ("Build and use"), built and run as a test: one update of the
!> paper's RIA (Table 1, theta = 45 deg, H_N = 1 mm) from the virgin state. Still elastic and
!> with K_n = K_t = 150 MPa/mm, so sigma = K s whatever the plane angles: the test checks that.
program readme_example
  use interlock
  implicit none
  type(interlock_material_t) :: mat
  type(interlock_solver_t) :: solver            ! scheme_trapezoidal (default), _implicit, _explicit
  type(interlock_state_t) :: old, new
  type(interlock_info_t) :: info
  real(dp) :: sigma(2), tangent(2, 2)
  integer :: stat
  character(len=message_len) :: message

  mat%sigma0_n = 3.0_dp; mat%sigma0_t = 3.0_dp; mat%gc = 0.3_dp; mat%eta = 0.9_dp; mat%mu = 0.5_dp
  mat%h_n = 1.0_dp                               ! huge(1.0_dp): infinite depth
  call interlock_paper_ria(mat, 45.0_dp * deg_to_rad, 45.0_dp * deg_to_rad, huge(1.0_dp))
  call interlock_material_prepare(mat, stat, message)   ! validates; resolves the effect set once
  call interlock_state_init(mat, old)
  call interlock_update(mat, solver, [-0.001_dp, 0.01_dp], old, new, sigma, tangent, info)
  if (info%status /= status_ok) print *, trim(info%message)

  print '(a,2es24.16)', 'sigma = ', sigma
  if (stat /= status_ok .or. info%status /= status_ok) error stop 'the update failed'
  if (any(abs(sigma - 150.0_dp * [-0.001_dp, 0.01_dp]) > 1.0e-12_dp)) &
    error stop 'expected sigma = K s = (-0.15, 1.5) MPa'
  if (abs(tangent(1, 1) - 150.0_dp) > 1.0e-10_dp .or. abs(tangent(2, 2) - 150.0_dp) > 1.0e-10_dp &
      .or. abs(tangent(1, 2)) > 1.0e-10_dp .or. abs(tangent(2, 1)) > 1.0e-10_dp) &
    error stop 'expected the elastic tangent K I, K = 150 MPa/mm'
  print '(a)', 'readme example: 1 passed, 0 failed'
end program readme_example
