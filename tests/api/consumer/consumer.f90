!> Uses the installed library: mode I on a flat interface reaches sigma0_n at s_0n.
program consumer
  use interlock
  implicit none
  type(interlock_material_t) :: mat
  type(interlock_solver_t) :: solver
  type(interlock_state_t) :: old, new
  type(interlock_info_t) :: info
  real(dp) :: sigma(2), tangent(2, 2)
  integer :: stat
  character(len=message_len) :: message
  mat%sigma0_n = 3.0_dp
  mat%sigma0_t = 3.0_dp
  mat%gc = 0.3_dp
  mat%eta = 0.9_dp
  mat%mu = 0.5_dp
  call interlock_paper_ria(mat, 0.0_dp, 0.0_dp, huge(1.0_dp))
  call interlock_material_prepare(mat, stat, message)
  if (stat /= status_ok) error stop 'prepare failed'
  call interlock_state_init(mat, old)
  call interlock_update(mat, solver, [0.02_dp, 0.0_dp], old, new, sigma, tangent, info)
  write (*, '(a,a,a,f12.9)') 'interlock ', interlock_version_string, ': mode-I peak ', sigma(1)
  if (info%status /= status_ok .or. abs(sigma(1) - 3.0_dp) > 1.0e-12_dp) error stop 'wrong peak'
end program consumer
