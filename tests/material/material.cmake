# src/material: the frame of the per-plane state (label core), and the material table (label
# umat: the table drives the UMAT's PROPS and STATEV) tells the truth (defaults, PROPS slots,
# STATEV layout).
interlock_add_core_suite(state_frame)
interlock_add_pfunit_suite(umat_table LABEL umat TEST_SOURCES test_umat_table.pf)
