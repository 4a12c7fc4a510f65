!> Suite core_mechanisms: unit tests of the mechanism modules (kinematics, damage, friction,
!> wear, geometry) against hand-computed values.
program test_mechanisms_main
  use interlock_assert, only: run_case, suite_summary
  use test_kinematics
  use test_damage
  use test_friction
  use test_wear
  use test_geometry
  implicit none
  call run_case('kinematics: rotations', kinematics_rotation)
  call run_case('damage: equivalent displacement', damage_equivalent_displacement)
  call run_case('damage: D(beta)', damage_law)
  call run_case('friction: open plane and mu = 0', friction_open_and_frictionless)
  call run_case('friction: stick', friction_stick_branch)
  call run_case('friction: slide', friction_slide_branch)
  call run_case('wear: theta(zeta)', wear_law)
  call run_case('geometry: contact area', geometry_contact_area)
  if (suite_summary('core_mechanisms') /= 0) error stop 1
end program test_mechanisms_main
