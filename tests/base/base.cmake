# src/base (label core): format_real's digits.
interlock_add_core_suite(numbers)
