!> Suite core_invariants: random histories (test_invariants).
program test_invariants_main
  use interlock_assert, only: run_case, suite_summary
  use test_invariants
  implicit none
  call run_case('invariants: random history, virgin RIA', random_history_virgin_ria)
  call run_case('invariants: random history, pre-fractured RIA', random_history_prefractured_ria)
  if (suite_summary('core_invariants') /= 0) error stop 1
end program test_invariants_main
