#!/usr/bin/python3
"""Instructions per update (callgrind), counting only the updates.

usage: /usr/bin/python3 bench/profile_updates.py BENCH [--passes 10] [--top 8]
           [CONFIG ...]
BENCH is the interlock-bench executable (Release build). CONFIG is SET:SCHEME[:TOL] as for
`interlock-bench --profile SET SCHEME PASSES [TOL]` (SET 0 = bilinear baseline, 1..5 = damage,
+friction, +interlocking, +finite depth, +wear; SCHEME 1 = explicit, 2 = implicit, 3 =
trapezoidal); a leading `u` (u5:1) profiles the same set through the external UMAT
(`--profile ... --umat`), a leading `f` (f5:1) the floor of the UMAT's overhead
(`--umat-floor`); default: the configurations of docs/bench.md.

valgrind runs with --toggle-collect on interlock_update (bilinear_update for SET 0, the external
UMAT or the floor's call for u and f), so the set-up (histories, material, start-up, output) is
not counted: the total is the inclusive cost of the call, divided by the number of calls the
program reports. The table gives that, the calls of malloc per call, and the self cost per
call of the most expensive functions inside.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

UPDATE = "__interlock_integrate_MOD_interlock_update"
BILINEAR = "__interlock_bench_bilinear_MOD_bilinear_update"
UMAT = "umat_"
UMAT_FLOOR = "__interlock_bench_umat_floor_MOD_umat_floor_call"
DEFAULT = ["0:1", "1:1", "1:2", "3:1", "5:1", "5:2", "5:1:1e-3", "5:2:1e-3",
           "u1:1", "u2:1", "u3:1", "u5:1", "u5:2", "f1:1", "f5:1"]
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


def malloc_calls(out):
    """Calls of malloc recorded in a callgrind output file (cfn= lines name the callee, the
    next calls= line counts the calls; fn= and cfn= names are compressed to "(id) name" on
    first use)."""
    names, total, callee = {}, 0, None
    with open(out) as f:
        for line in f:
            if line.startswith("fn="):
                m = re.match(r"fn=\((\d+)\) (.*)", line.strip())
                if m:
                    names[m.group(1)] = m.group(2)
            elif line.startswith("cfn="):
                m = re.match(r"cfn=\((\d+)\)(?: (.*))?", line.strip())
                if m.group(2):
                    names[m.group(1)] = m.group(2)
                callee = names.get(m.group(1), "")
            elif line.startswith("calls=") and callee is not None:
                if re.fullmatch(r"(__libc_)?malloc('\d+)?", (callee.split() or [''])[0]):
                    total += int(line.split("=")[1].split()[0])
                callee = None
    return total


def profile(bench, cfg, passes, top):
    mode = cfg[0] if cfg[0] in "uf" else ""
    parts = cfg.lstrip("uf").split(":")
    st, scheme = int(parts[0]), int(parts[1])
    tol = parts[2] if len(parts) > 2 else "0"
    fn = {"u": UMAT, "f": UMAT_FLOOR}.get(mode, BILINEAR if st == 0 else UPDATE)
    extra = {"u": ["--umat"], "f": ["--umat-floor"]}.get(mode, [])
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cg.out")
        run = subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
             f"--toggle-collect={fn}", bench, "--profile", str(st), str(scheme), str(passes),
             tol] + extra, capture_output=True, text=True, check=True)
        m = re.search(r"calls: (\d+)", run.stdout)
        fails = re.search(r"failed updates: (\d+)", run.stdout)
        calls = int(m.group(1))
        ann = subprocess.run(["callgrind_annotate", "--threshold=100", out],
                             capture_output=True, text=True, check=True).stdout
        mallocs = malloc_calls(out)
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
    if mode == "u":
        label = "UMAT: " + label
    elif mode == "f":
        label = "floor of the UMAT overhead: " + label.split(",")[0]
    return label, total / calls, [(k, v / calls) for k, v in rows], calls, \
        int(fails.group(1)) if fails else 0, mallocs / calls


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bench")
    ap.add_argument("configs", nargs="*", default=DEFAULT)
    ap.add_argument("--passes", type=int, default=10)
    ap.add_argument("--top", type=int, default=8)
    args = ap.parse_intermixed_args()
    print("| configuration | instr./call (inclusive) | malloc/call | where (self instructions per call) |")
    print("|---|---:|---:|---|")
    for cfg in args.configs:
        label, per_call, rows, calls, fails, mallocs = profile(args.bench, cfg, args.passes,
                                                               args.top)
        where = ", ".join(f"`{k}` {v:.0f}" for k, v in rows if v >= 5)
        note = f" ({fails} of {calls} updates failed)" if fails else ""
        print(f"| {label}{note} | {per_call:.0f} | {mallocs:.2f} | {where} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
