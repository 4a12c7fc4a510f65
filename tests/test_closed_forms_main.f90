!> Suite core_closed_forms: SPEC section 8 (test_closed_forms).
program test_closed_forms_main
  use interlock_assert, only: run_case, suite_summary
  use test_closed_forms
  implicit none
  call run_case('closed form: mode I bilinear', mode_one_bilinear)
  call run_case('closed form: mode II at constant compression', mode_two_constant_compression)
  call run_case('closed form: steady sliding of a debonded RIA', steady_sliding_ria)
  call run_case('closed form: energy balance, first order', energy_balance_first_order)
  if (suite_summary('core_closed_forms') /= 0) error stop 1
end program test_closed_forms_main
