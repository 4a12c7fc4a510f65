!> Suite core_tangent: the algorithmic tangent of every branch and scheme (test_tangent).
program test_tangent_main
  use interlock_assert, only: run_case, suite_summary
  use test_tangent
  implicit none
  call print_header()
  call run_case('tangent: elastic', tangent_elastic)
  call run_case('tangent: damage loading', tangent_damage)
  call run_case('tangent: unloading', tangent_unloading)
  call run_case('tangent: stick', tangent_stick)
  call run_case('tangent: slide', tangent_slide)
  call run_case('tangent: damage loading and slide', tangent_damage_slide)
  call run_case('tangent: open contact', tangent_open)
  call run_case('tangent: geometry decay', tangent_geometry)
  call run_case('tangent: wear', tangent_wear)
  call run_case('tangent: wear scene is substepped', tangent_wear_substeps)
  call run_case('tangent: random states', tangent_random_states)
  if (suite_summary('core_tangent') /= 0) error stop 1
end program test_tangent_main
