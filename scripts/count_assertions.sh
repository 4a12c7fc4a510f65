#!/usr/bin/env bash
# Assertion call sites of the unit suites: `@assert...` lines in tests/*.pf now, against
# `call assert_...` statements in the .f90 suites they were ported from (at git revision
# $1, default 5c995c7, the last commit before the port). One row per suite file; the totals
# must agree. Helpers outside the suites (tests/test_core_support.f90) are counted apart.
set -euo pipefail
cd "$(dirname "$0")/.."
before_rev="${1:-5c995c7}"
total_before=0
total_after=0
printf '%-22s %8s %8s\n' suite before after
for pf in tests/*.pf; do
  name=$(basename "$pf" .pf)
  before=$(git show "$before_rev:tests/$name.f90" 2>/dev/null | grep -cE '^\s*(if \(.*\) )?call assert_' || true)
  after=$(grep -cE '^\s*@assert' "$pf" || true)
  printf '%-22s %8d %8d\n' "$name" "$before" "$after"
  total_before=$((total_before + before))
  total_after=$((total_after + after))
done
printf '%-22s %8d %8d\n' total "$total_before" "$total_after"
printf '%-22s %8d %8d\n' test_core_support \
  "$(git show "$before_rev:tests/test_core_support.f90" | grep -c 'call assert_')" \
  "$(grep -c 'call assertTrue' tests/test_core_support.f90)"
