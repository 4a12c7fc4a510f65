# src/laws (label core): each mechanism's module by hand (test_<module>.pf), the procedures
# production calls.
foreach(stem kinematics damage friction wear geometry plane_law)
  interlock_add_core_suite(${stem})
endforeach()
