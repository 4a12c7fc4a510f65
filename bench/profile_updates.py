#!/usr/bin/python3
"""Instructions per update (callgrind), counting only the updates.

usage: /usr/bin/python3 bench/profile_updates.py BENCH [--passes 10] [--top 8]
           [CONFIG ...]
BENCH is the interlock-bench executable (Release build). CONFIG is SET:SCHEME[:TOL] as for
`interlock-bench --profile SET SCHEME PASSES [TOL]` (SET 0 = bilinear baseline, 1..5 = damage,
+friction, +interlocking, +finite depth, +wear; SCHEME 1 = explicit, 2 = implicit, 3 = trapezoidal); default:
the configurations of docs/bench.md.

valgrind runs with --toggle-collect on interlock_update (bilinear_update for SET 0), so the
set-up (histories, material, start-up, output) is not counted: the total is the inclusive cost
of the update, divided by the number of calls the program reports. The table gives that and
the self cost per call of the most expensive functions inside the update.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

UPDATE = "__interlock_integrate_MOD_interlock_update"
BILINEAR = "__interlock_bench_bilinear_MOD_bilinear_update"
DEFAULT = ["0:1", "1:1", "1:2", "3:1", "5:1", "5:2", "5:1:1e-3", "5:2:1e-3"]
NAMES = {0: "bilinear baseline", 1: "damage only", 2: "damage+friction", 3: "+interlocking",
         4: "+finite depth", 5: "full model (+wear)"}


def short(fn):
    """Readable function name from a callgrind_annotate 'file:function [object]' entry."""
    fn = re.sub(r"\s*\[.*\]$", "", fn)
    fn = fn.split(":")[-1] if ":" in fn and not fn.startswith("__") else fn
    m = re.match(r"__(\w+?)_MOD_(\w+)", fn)
    if m:
        fn = m.group(2)
    fn = fn.replace(".isra.0", "").replace(".constprop.0", "")
    for libm in ("sincos", "exp", "sin", "cos", "atan2", "log", "pow"):
        if re.fullmatch(rf"_*(ieee754_)?{libm}(_fma|_avx2|_sse2)?(@@GLIBC_[\d.]+)?", fn):
            return libm + " (libm)"
    return fn


def profile(bench, cfg, passes, top):
    parts = cfg.split(":")
    st, scheme = int(parts[0]), int(parts[1])
    tol = parts[2] if len(parts) > 2 else "0"
    fn = BILINEAR if st == 0 else UPDATE
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        run = subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
             f"--toggle-collect={fn}", bench, "--profile", str(st), str(scheme), str(passes),
             tol], capture_output=True, text=True, check=True)
        m = re.search(r"calls: (\d+)", run.stdout)
        fails = re.search(r"failed updates: (\d+)", run.stdout)
        calls = int(m.group(1))
        ann = subprocess.run(["callgrind_annotate", "--threshold=100", out],
                             capture_output=True, text=True, check=True).stdout
    total = None
    self_costs = {}
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+)\s+(?:\([\d. %]+\)\s+)?(.*)$", line)
        if not m:
            continue
        n = int(m.group(1).replace(",", ""))
        what = m.group(2).strip()
        if what.startswith("PROGRAM TOTALS"):
            total = n
        elif what:
            name = short(what)
            # libm splits sincos/exp over several source files: merge them
            self_costs[name] = self_costs.get(name, 0) + n
    label = NAMES[st] + ("" if st == 0 else ", " + {1: "explicit", 2: "implicit"}.get(scheme,
                                                                                      "trapezoidal"))
    if float(tol) > 0:
        label += f", substep_tol {tol}"
    rows = sorted(self_costs.items(), key=lambda kv: -kv[1])[:top]
    return label, total / calls, [(k, v / calls) for k, v in rows], calls, \
        int(fails.group(1)) if fails else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bench")
    ap.add_argument("configs", nargs="*", default=DEFAULT)
    ap.add_argument("--passes", type=int, default=10)
    ap.add_argument("--top", type=int, default=8)
    args = ap.parse_intermixed_args()
    print("| configuration | instr./call (inclusive) | where (self instructions per call) |")
    print("|---|---:|---|")
    for cfg in args.configs:
        label, per_call, rows, calls, fails = profile(args.bench, cfg, args.passes, args.top)
        where = ", ".join(f"`{k}` {v:.0f}" for k, v in rows if v >= 5)
        note = f" ({fails} of {calls} updates failed)" if fails else ""
        print(f"| {label}{note} | {per_call:.0f} | {where} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
