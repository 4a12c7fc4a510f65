#!/usr/bin/python3
"""What interlock-history promises when things go wrong (README, "Reliability").

usage: test_history_reliability.py PROGRAM DECK WORK_DIR MODE
  DECK = inputs/fig6.nml (a short good deck: one slip history, 600 steps, completes).
  MODE overwrite  The output never replaces an input or a file that is not an earlier result:
                  &output file naming the deck itself, an existing text file, an HDF5 file of
                  someone else, a FIFO (must not block) -> exit 1, a message naming the file,
                  the file untouched (byte for byte), no temporary file; an earlier result of
                  the program is replaced.
       fulldisk   A full disk, simulated by a file-size limit of 64 kB (RLIMIT_FSIZE, with
                  SIGXFSZ ignored: writes fail with EFBIG; needs no privileges): exit 1, the
                  message "cannot write", no crash (no SIGSEGV, no backtrace), no file left.
       tmpfs      The same on a real full file system, a 64 kB tmpfs (ENOSPC): needs the
                  right to mount; skipped (exit 77) where mounting is not possible.
       signals    SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1, SIGUSR2, SIGALRM and
                  SIGXCPU during a long run: the run ends by that signal, its NAME.h5.tmp-PID
                  is removed, NAME.h5 is not created (an earlier NAME.h5 is left as it was), no
                  backtrace; SIGKILL cannot be caught: the temporary file stays, the earlier
                  NAME.h5 is still untouched.
       pipe       `interlock-history DECK | head -1` on a sweep of many cases: the reader
                  closes the pipe, the next line kills the program by SIGPIPE, and its
                  temporary file is removed (no result file either).
       longname   An output name of 255 characters (the longest file name): written, and no
                  temporary file left (the temporary name is shortened to fit).
       memory     A 2,000,000-step history (separation-driven, the paper's 3-plane RIA) with
                  &output every = 1000: peak resident memory of the program (VmHWM) below
                  64 MB (rows are streamed to the file; 450-540 MB when the whole history was
                  held), and the file has the 2001 rows every = 1000 keeps.
"""
import os
import resource
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_history_h5  # noqa: E402

SKIP = 77
failures = 0


def check(ok, what):
    global failures
    print(f"[{' ok ' if ok else 'FAIL'}] {what}")
    if not ok:
        failures += 1
    return ok


def deck_with_output(deck, path, output, extra=""):
    """A copy of `deck` at `path` whose &output names `output` (replacing any &output group)."""
    with open(deck) as f:
        lines = f.read().splitlines()
    out, skipping = [], False
    for line in lines:
        if line.strip().lower().startswith("&output"):
            skipping = True
        if not skipping:
            out.append(line)
        if skipping and line.strip() == "/":
            skipping = False
    out += ["&output", f"  file = '{output}'", extra, "/", ""]
    with open(path, "w") as f:
        f.write("\n".join(out))


def leftovers(folder, stem):
    return sorted(n for n in os.listdir(folder) if n.startswith(stem) and ".tmp-" in n)


def mode_overwrite(program, deck, work):
    def refused(label, target, make, expect):
        deck_path = os.path.join(work, f"{label}.nml")
        deck_with_output(deck, deck_path, target if target != "SELF" else deck_path)
        target = deck_path if target == "SELF" else target
        make(target)
        before = open(target, "rb").read() if os.path.isfile(target) else None
        try:
            r = subprocess.run([program, deck_path], cwd=work, capture_output=True, text=True,
                               timeout=60)
        except subprocess.TimeoutExpired:
            check(False, f"{label}: the program blocked (more than 60 s)")
            return
        after = open(target, "rb").read() if os.path.isfile(target) else None
        check(r.returncode == 1 and expect in r.stderr and os.path.basename(target) in r.stderr,
              f"{label}: exit status {r.returncode} (1), message: {r.stderr.strip()[:160]}")
        check(before == after, f"{label}: {os.path.basename(target)} untouched")
        check(not leftovers(work, os.path.basename(target)), f"{label}: no temporary file left")

    def text_file(p):
        with open(p, "w") as f:
            f.write("results of last week, by hand\n")

    def foreign_hdf5(p):
        with h5py.File(p, "w") as f:
            f.attrs["program"] = "someone else"
            f["data"] = np.arange(3.0)

    def fifo(p):
        if os.path.exists(p):
            os.remove(p)
        os.mkfifo(p)

    refused("self", "SELF", lambda p: None, "is the deck itself")
    refused("text", os.path.join(work, "notes.txt"), text_file, "is not a result of")
    refused("foreign", os.path.join(work, "foreign.h5"), foreign_hdf5, "is not a result of")
    refused("fifo", os.path.join(work, "pipe.h5"), fifo, "not a regular file")

    # An earlier result of the program is replaced.
    deck_path = os.path.join(work, "again.nml")
    deck_with_output(deck, deck_path, "again.h5")
    codes = [subprocess.run([program, deck_path], cwd=work, capture_output=True).returncode
             for _ in range(2)]
    errors = check_history_h5.check_file(os.path.join(work, "again.h5"), False)
    check(codes == [0, 0] and not errors,
          f"an earlier result is replaced: exit statuses {codes}, layout {errors or 'ok'}")


def mode_fulldisk(program, deck, work, tmpfs=False):
    deck_path = os.path.join(work, "full.nml")
    deck_with_output(deck, deck_path, "full.h5")

    def expect_clean_failure(label, folder, preexec=None):
        r = subprocess.run([program, "--output-dir", folder, deck_path], capture_output=True,
                           text=True, timeout=120, preexec_fn=preexec)
        check(r.returncode == 1, f"{label}: exit status {r.returncode} (1)")
        check("cannot write" in r.stderr, f"{label}: message: {r.stderr.strip()[:200]}")
        crashed = any(w in r.stderr for w in ("SIGSEGV", "Backtrace", "Segmentation"))
        check(not crashed, f"{label}: no crash, no backtrace")
        left = [n for n in os.listdir(folder) if n.startswith("full.h5")]
        check(not left, f"{label}: no file left ({left})")

    def limit_file_size():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (65536, 65536))

    if tmpfs:
        small = os.path.join(work, "tmpfs")
    else:
        limited = os.path.join(work, "limited")
        os.makedirs(limited, exist_ok=True)
        expect_clean_failure("file-size limit 64 kB (EFBIG)", limited, limit_file_size)
        return None

    os.makedirs(small, exist_ok=True)
    subprocess.run(["umount", small], capture_output=True)
    m = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", small],
                       capture_output=True, text=True)
    if m.returncode != 0:
        print(f"(a 64 kB tmpfs cannot be mounted here: {m.stderr.strip()}; that part is skipped)")
        return SKIP
    try:
        expect_clean_failure("64 kB tmpfs (ENOSPC)", small)
    finally:
        subprocess.run(["umount", small], capture_output=True)
    return None


def long_deck(path, steps, every=1, cases=1):
    """A separation-driven slip history of `steps` steps on the paper's 3-plane RIA (`cases` > 1:
    a sweep over mu with that many cases)."""
    sweep = ""
    if cases > 1:
        sweep = ("&sweep\n  parameter = 'mu', values = "
                 + ", ".join(f"{0.5 + 0.01 * i:.2f}" for i in range(cases)) + "\n/\n")
    with open(path, "w") as f:
        f.write(f"""! written by test_history_reliability.py
&interface
  sigma0_n = 3.0, sigma0_t = 3.0, gc = 0.3, eta = 0.9, mu = 0.5, h_n = 1.0
/
&microplanes
  theta0_deg = 45.0, thetaf_deg = 20.0, zeta0 = 50.0
/
&loading
  normal_control = 'separation', tangential_control = 'separation'
  times = 0.0, 1.0
  normal = 0.0, -0.001
  tangential = 0.0, 2.0
  steps = {steps}
/
&output
  every = {every}
/
""" + sweep)


def mode_signals(program, deck, work):
    stem = "long"
    deck_path = os.path.join(work, stem + ".nml")
    # Long (10 x 2e6 steps: seconds even in Release) but small (every = 1000: a few MB).
    long_deck(deck_path, 2000000, every=1000, cases=10)
    final = os.path.join(work, stem + ".h5")
    # An earlier result, which an interrupted run must leave as it was.
    deck_with_output(deck, os.path.join(work, "earlier.nml"), final)
    subprocess.run([program, os.path.join(work, "earlier.nml")], cwd=work, check=True,
                   capture_output=True)
    earlier = open(final, "rb").read()
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT, signal.SIGPIPE,
                signal.SIGUSR1, signal.SIGUSR2, signal.SIGALRM, signal.SIGXCPU, signal.SIGKILL):
        name = signal.Signals(sig).name
        for n in leftovers(work, stem + ".h5"):
            os.remove(os.path.join(work, n))
        p = subprocess.Popen([program, deck_path], cwd=work, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        temp = os.path.join(work, f"{stem}.h5.tmp-{p.pid}")
        t0 = time.time()
        while not os.path.exists(temp) and p.poll() is None and time.time() - t0 < 60:
            time.sleep(0.01)
        time.sleep(0.2)
        running = p.poll() is None and os.path.exists(temp)
        check(running, f"{name}: the run is writing {os.path.basename(temp)}")
        if not running:
            p.kill()
            p.wait()
            continue
        p.send_signal(sig)
        _, err = p.communicate(timeout=60)
        check(p.returncode == -sig, f"{name}: the run ended by the signal (returncode "
              f"{p.returncode}, expected {-sig}; a shell shows {128 + sig})")
        untouched = open(final, "rb").read() == earlier
        if sig == signal.SIGKILL:
            check(os.path.exists(temp) and untouched,
                  f"{name}: cannot be caught: {os.path.basename(temp)} stays (documented), "
                  "the earlier result is untouched")
            os.remove(temp)
        else:
            check(not os.path.exists(temp) and untouched,
                  f"{name}: {os.path.basename(temp)} removed, the earlier result untouched")
        check("Backtrace" not in err, f"{name}: no backtrace")


def mode_pipe(program, deck, work):
    sweep = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "history",
                         "pipe_sweep.nml")
    shutil.copy(sweep, os.path.join(work, "p.nml"))
    p = subprocess.Popen([program, "p.nml"], cwd=work, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    first = p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read().decode(errors="replace")
    p.wait(timeout=300)
    check(b"case 0001" in first, f"the first line: {first!r}")
    check(p.returncode == -signal.SIGPIPE, f"ended by SIGPIPE (returncode {p.returncode}, "
          f"expected {-signal.SIGPIPE}; a shell shows 141)")
    left = sorted(os.listdir(work))
    check(left == ["p.nml"], f"no temporary and no result file left ({left})")
    check("Backtrace" not in err, "no backtrace")


def mode_longname(program, deck, work):
    name = "x" * 252 + ".h5"
    deck_with_output(deck, os.path.join(work, "long.nml"), name)
    r = subprocess.run([program, "long.nml"], cwd=work, capture_output=True, text=True,
                       timeout=300)
    check(r.returncode == 0, f"an output name of {len(name)} characters: exit status "
          f"{r.returncode} {r.stderr.strip()[:300]}")
    left = sorted(os.listdir(work))
    check(left == sorted(["long.nml", name]), f"the file written, nothing else ({len(left)} "
          "names)")


def mode_memory(program, deck, work):
    deck_path = os.path.join(work, "memory.nml")
    steps, every = 2000000, 1000
    long_deck(deck_path, steps, every)
    t0 = time.time()
    # The program's own peak resident memory: VmHWM of /proc/PID/status (the high-water mark of
    # the program's address space since exec; ru_maxrss of a child would count the Python
    # process it was forked from), read until the program ends.
    p = subprocess.Popen([program, "--output-dir", work, deck_path], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    peak_kb = 0
    while p.poll() is None:
        try:
            with open(f"/proc/{p.pid}/status") as f:
                for line in f:
                    if line.startswith("VmHWM:"):
                        peak_kb = max(peak_kb, int(line.split()[1]))
        except OSError:
            pass
        time.sleep(0.01)
    _, err = p.communicate()
    wall = time.time() - t0
    peak_mb = peak_kb / 1024.0
    check(p.returncode == 0, f"{steps} steps, every = {every}: exit status {p.returncode}"
          + (f": {err.strip()}" if p.returncode else f" ({wall:.1f} s)"))
    check(0 < peak_mb < 64.0, f"peak resident memory (VmHWM) {peak_mb:.1f} MB < 64 MB (rows "
          "streamed; the whole history held took 450-540 MB)")
    path = os.path.join(work, "memory.h5")
    if p.returncode == 0:
        errors = check_history_h5.check_file(path, False)
        with h5py.File(path, "r") as f:
            n = len(f["cases/0001/time"])
            last = f["cases/0001/time"][-1]
        check(not errors and n == steps // every + 1 and last == 1.0,
              f"{n} rows (rows 0, 1000, ..., 1999000 and the last), layout {errors or 'ok'}")
    if os.path.exists(path):
        os.remove(path)


def main(argv):
    modes = {"overwrite": mode_overwrite, "fulldisk": mode_fulldisk, "signals": mode_signals,
             "memory": mode_memory, "pipe": mode_pipe, "longname": mode_longname,
             "tmpfs": lambda program, deck, work: mode_fulldisk(program, deck, work, True)}
    if len(argv) != 4 or argv[3] not in modes:
        print(__doc__)
        return 2
    program, deck, work, mode = argv
    program, deck = os.path.abspath(program), os.path.abspath(deck)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    code = modes[mode](program, deck, work)
    print(f"history_reliability {mode}: {failures} failed")
    if failures:
        return 1
    return code or 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
