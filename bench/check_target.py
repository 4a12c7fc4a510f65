#!/usr/bin/python3
"""Check the "CPU time to reach" figures between the benchmark's power-of-two step counts.

usage: /usr/bin/python3 bench/check_target.py BENCH [--scene granite] [--scheme implicit]
           [--plain] [--refine 64] [--repeat 5] N [N ...]
For each step count N (turning points must fall on steps: a multiple of 8 for granite, of 1 for
fig11, of 4 for fig12), runs `BENCH --history SCENE SCHEME 0 N` and 2N, combines them as
2 u(2N) - u(N) at the common steps (global Richardson extrapolation, as in interlock-bench; with
--plain: u(N) alone), and prints its error against a reference of its own, Richardson of the
implicit scheme at N*refine and 2N*refine steps (same error measure as the benchmark: max over
the steps of |sigma_T - ref| / max|sigma_T,ref| and |s_N - ref| / max|s_N,ref|), with the CPU
time of the runs (median of --repeat timings of each, as printed by --history). Also prints
the plain error at N and the reference's uncertainty against the pair one level coarser.
Example (the granite 1e-4 target): check_target.py BENCH 1792 2048 2304; and for the paper's
scheme: check_target.py BENCH --scheme explicit --plain --refine 1 294912.
With --explicit-steps NE, each N is also compared in the same run with the paper's scheme
(explicit, uniform) at NE steps: its error against the implicit Richardson reference at NE and
2 NE steps, its CPU time (the timings of the two interleaved), and the ratio of the CPU times;
e.g. check_target.py BENCH --scheme trapezoidal --plain --explicit-steps 294912 1536 2048.
"""
import argparse
import statistics
import subprocess


def history(bench, scene, scheme, n):
    run = subprocess.run([bench, "--history", scene, scheme, "0", str(n)], capture_output=True,
                         text=True, check=True)
    sn, st = [], []
    for line in run.stdout.splitlines()[1:]:
        _, a, _, c = line.split(",")
        sn.append(float(a))
        st.append(float(c))
    cpu = float(run.stderr.split("cpu_s:")[1].split()[0])
    return sn, st, cpu


def richardson(fine, coarse):
    return [2.0 * f - c for f, c in zip(fine[::2], coarse)]


def error(sn, st, ref_sn, ref_st):
    stride = (len(ref_sn) - 1) // (len(sn) - 1)
    e_sn = max(abs(x - ref_sn[i * stride]) for i, x in enumerate(sn)) / max(map(abs, ref_sn))
    e_st = max(abs(x - ref_st[i * stride]) for i, x in enumerate(st)) / max(map(abs, ref_st))
    return max(e_sn, e_st)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("bench")
    ap.add_argument("steps", type=int, nargs="+")
    ap.add_argument("--scene", default="granite")
    ap.add_argument("--scheme", default="implicit", choices=["implicit", "explicit", "trapezoidal"])
    ap.add_argument("--plain", action="store_true", help="no extrapolation: the run at N")
    ap.add_argument("--refine", type=int, default=64)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--explicit-steps", type=int, default=0,
                    help="also time the explicit scheme at this step count, interleaved")
    args = ap.parse_args()
    what = f"{args.scheme} " + ("uniform" if args.plain else "Richardson (N, 2N)")
    explicit = None
    if args.explicit_steps:
        ne = args.explicit_steps
        a_sn, a_st, _ = history(args.bench, args.scene, "implicit", ne)
        b_sn, b_st, _ = history(args.bench, args.scene, "implicit", 2 * ne)
        e_sn, e_st, _ = history(args.bench, args.scene, "explicit", ne)
        explicit = error(e_sn, e_st, richardson(b_sn, a_sn), richardson(b_st, a_st))
        print(f"explicit uniform at {ne} steps: error {explicit:.2e} (reference: implicit "
              f"Richardson at {ne} and {2 * ne} steps)")
    print(f"| N | {what}: error | CPU ms | plain {args.scheme} error at N "
          "| reference uncertainty |" + (" explicit CPU ms | explicit / this |" if explicit else ""))
    print("|---:|---:|---:|---:|---:|" + ("---:|---:|" if explicit else ""))
    for n in args.steps:
        m = n * args.refine
        h_sn, h_st, _ = history(args.bench, args.scene, "implicit", m // 2)
        a_sn, a_st, _ = history(args.bench, args.scene, "implicit", m)
        b_sn, b_st, _ = history(args.bench, args.scene, "implicit", 2 * m)
        ref_sn, ref_st = richardson(b_sn, a_sn), richardson(b_st, a_st)
        unc = error(richardson(a_sn, h_sn), richardson(a_st, h_st), ref_sn, ref_st)
        runs = {}
        cpus_explicit = []
        for k in (n,) if args.plain else (n, 2 * n):
            cpus = []
            for _ in range(args.repeat):
                sn, st, cpu = history(args.bench, args.scene, args.scheme, k)
                cpus.append(cpu)
                if explicit and k == n:
                    cpus_explicit.append(history(args.bench, args.scene, "explicit",
                                                 args.explicit_steps)[2])
            runs[k] = (sn, st, statistics.median(cpus))
        e_plain = error(runs[n][0], runs[n][1], ref_sn, ref_st)
        if args.plain:
            e_r = e_plain
            cpu = 1e3 * runs[n][2]
        else:
            r_sn = richardson(runs[2 * n][0], runs[n][0])
            r_st = richardson(runs[2 * n][1], runs[n][1])
            e_r = error(r_sn, r_st, ref_sn, ref_st)
            cpu = 1e3 * (runs[n][2] + runs[2 * n][2])
        extra = ""
        if explicit:
            cpu_e = 1e3 * statistics.median(cpus_explicit)
            extra = f" {cpu_e:.1f} | {cpu_e / cpu:.1f}x |"
        print(f"| {n} | {e_r:.2e} | {cpu:.1f} | {e_plain:.2e} | {unc:.1e} |" + extra, flush=True)


if __name__ == "__main__":
    main()
