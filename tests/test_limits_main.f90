!> Suite core_limits: SPEC section 7 (test_limits).
program test_limits_main
  use interlock_assert, only: run_case, suite_summary
  use test_limits
  implicit none
  call run_case('limit: theta = 0 is the single-plane model', flat_ria_is_single_plane)
  call run_case('limit: H_N = 1e3 mm is infinite depth', deep_asperities_are_infinite)
  call run_case('limit: theta_f = theta_0 gives a plateau', no_wear_plateau)
  call run_case('limit: theta_f = 0 removes the dilation', wear_to_flat_removes_dilation)
  if (suite_summary('core_limits') /= 0) error stop 1
end program test_limits_main
