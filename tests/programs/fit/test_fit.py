#!/usr/bin/python3
"""interlock-fit recovers known parameters from curves computed by interlock-history.

usage: test_fit.py FIT HISTORY recovery SET NOISE   SET: granite | table5; NOISE: 0 or 0.02
       test_fit.py FIT HISTORY staged DECK.nml      the staged deck of inputs/fit/ (section 4.1.5)
       test_fit.py FIT HISTORY files                results replace results, never other files
       test_fit.py FIT HISTORY identifiability      a parameter the curves ignore is reported
       test_fit.py FIT HISTORY coupled              an optimum on the law's limit theta_f = theta_0
       test_fit.py FIT HISTORY inputs               inputs read as they are written
       test_fit.py FIT HISTORY deckfail             the fitted deck cannot be written: no file
       test_fit.py FIT HISTORY discretization DECK  the discretization check of the staged deck
       test_fit.py FIT HISTORY recovery3d DECK [NOISE]
                                                    the 3D deck of inputs/fit/ (azimuthal RIA,
                                                    45 deg); NOISE 0.02: its curves with noise
       test_fit.py FIT HISTORY circle               a 3D deck on a circular slip path
       test_fit.py FIT HISTORY square               a 3D square path: a per-component slip as
                                                    abscissa refused, the slip length recovers mu
       test_fit.py FIT HISTORY noisy                noise on the abscissa: refused, saying so
       test_fit.py FIT HISTORY readonly             an output folder that cannot be written:
                                                    refused before the fit
       test_fit.py FIT HISTORY enospc               a write error on the fitted deck: exit 1,
                                                    nothing written (strace)
       test_fit.py FIT HISTORY renames              SIGINT between the renames: the two files
                                                    there belong together (strace)
       test_fit.py FIT HISTORY signals              SIGQUIT, SIGXCPU, SIGXFSZ during the fit: no
                                                    backtrace

The data are the curves of a history with known parameters (scripts/fit_make_data.py; noise:
independent normal noise of 2 % of each curve's largest value, numpy default_rng(12), the same on
every machine). Without noise every parameter must come back to 1e-6 relative (staged deck:
1e-4); with noise within two of its reported standard errors. The fit starts
30-50 % off. The fit file's layout (values, std_error, correlation, curves/NAME/{x,y,model})
and the fitted deck (an ordinary history deck that interlock-history runs) are checked too. The
CPU time of the fit is printed (a measurement, not asserted here: docs/fit.md).
"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
MAKE_DATA = os.path.join(ROOT, "scripts", "fit_make_data.py")
DATA = os.path.join(ROOT, "tests", "data", "fit")
NOISY = ("Backtrace", "Program received signal", "Fortran runtime error", "ERROR STOP")

# name: (history part of the deck, cycle period/start, [(parameter, true, start, lower, upper)])
SETS = {
    "granite": ("""&interface
  sigma0_n = 0.025, sigma0_t = 0.025, gc = 0.0005, eta = 0.99, mu = 0.6898538, h_n = 4.0
/
&microplanes
  theta0_deg = 30.0, thetaf_deg = 9.0, zeta0 = 6.666
/
&loading
  normal_control = 'traction', tangential_control = 'separation'
  times = 0.0, 1.0, 6, 16, 21
  normal = 0.0, -1.0, -1.0, -1.0, -1.0
  tangential = 0.0, 0.0, 5.0, -5.0, 0.0
  steps = 1, 250, 500, 250
  cycles = 2
/
&solver
  scheme = 'implicit'
/
""", [("h_n", 4.0, 5.6, 0.5, 20.0), ("thetaf_deg", 9.0, 5.4, 0.0, 25.0),
      ("theta0_deg", 30.0, 42.0, 10.0, 60.0), ("zeta0", 6.666, 4.0, 0.5, 100.0)]),
    # Table 5, concrete-bar interface, cyclic slip +/-2 mm under -1 MPa (as
    # inputs/pullout_concrete_cyclic.nml, fewer steps)
    "table5": ("""&interface
  sigma0_n = 1.0, sigma0_t = 1.0, gc = 0.1, eta = 0.995, mu = 0.7, h_n = 1.5
/
&microplanes
  theta0_deg = 45.0, thetaf_deg = 0.0, zeta0 = 33.3
/
&loading
  normal_control = 'traction', tangential_control = 'separation'
  times = 0.0, 1.0, 3, 7, 9
  normal = 0.0, -1.0, -1.0, -1.0, -1.0
  tangential = 0.0, 0.0, 2.0, -2.0, 0.0
  steps = 1, 250, 500, 250
  cycles = 2
/
&solver
  scheme = 'implicit'
/
""", [("mu", 0.7, 0.42, 0.1, 1.5), ("h_n", 1.5, 2.1, 0.2, 10.0), ("zeta0", 33.3, 49.0, 1.0, 500.0)]),
}

FIT = """&fit
  curve_name = 'shear', 'dilation'
  curve_file = 'data.csv', 'data.csv'
  curve_x = 'slip', 'slip'
  curve_y = 'shear', 'dilation'
  curve_along = 'separation_t', 'separation_t'
  curve_against = 'traction_t', 'separation_n'
  parameters = {names}
  start = {start}
  lower = {lower}
  upper = {upper}
/
"""


def run(command, cwd):
    t0 = time.perf_counter()
    r = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        print(r.stdout[-4000:])
        print(r.stderr[-4000:])
        sys.exit(f"FAIL: {' '.join(command)} exited with {r.returncode}")
    return r.stdout, wall


def check_outputs(fit_h5, fitted_deck, history, work):
    with h5py.File(fit_h5, "r") as f:
        assert f.attrs["program"] == "interlock-fit"
        names = [str(s) for s in f.attrs["parameters"]]
        values = np.asarray(f.attrs["values"])
        se = np.asarray(f.attrs["std_error"])
        corr = f["correlation"][()]
        n = len(names)
        assert corr.shape == (n, n), corr.shape
        assert np.allclose(np.diag(corr), 1.0)
        assert np.all(np.abs(corr) <= 1.0 + 1e-12)
        for name in f["curves"]:
            g = f["curves"][name]
            assert g["x"].shape == g["y"].shape == g["model"].shape
        cpu = sum(float(f["stages"][k].attrs["cpu_seconds"]) for k in f["stages"])
    out, _ = run([history, "--output-dir", work, fitted_deck], work)
    assert "completed" in out
    return dict(zip(names, zip(values, se))), cpu


def recovery(fit, history, which, noise):
    history_part, params = SETS[which]
    with tempfile.TemporaryDirectory() as work:
        data_deck = os.path.join(work, "truth.nml")
        with open(data_deck, "w") as f:
            f.write(history_part)
        cmd = [MAKE_DATA, history, data_deck, os.path.join(work, "data.csv")]
        if noise > 0:
            cmd += ["--noise", str(noise), "--seed", "12"]
        run([sys.executable] + cmd, work)
        deck = os.path.join(work, f"{which}.nml")
        fmt = lambda i: ", ".join(repr(p[i]) for p in params)
        with open(deck, "w") as f:
            f.write(history_part + FIT.format(names=", ".join(f"'{p[0]}'" for p in params),
                                              start=fmt(2), lower=fmt(3), upper=fmt(4)))
        out, wall = run([fit, deck], work)
        print(out)
        got, cpu = check_outputs(os.path.join(work, f"{which}_fit.h5"),
                                 os.path.join(work, f"{which}_fitted.nml"), history, work)
    bad = []
    for name, true, start, lo, hi in params:
        value, se = got[name]
        assert 0.3 <= abs(start - true) / true <= 0.5 + 1e-9, (name, start, true)
        if noise == 0:
            ok = abs(value - true) <= 1e-6 * abs(true)
            print(f"{name}: {value!r} true {true} relative error {abs(value - true) / true:.2e}")
        else:
            ok = abs(value - true) <= 2 * se
            print(f"{name}: {value!r} true {true} standard error {se:.3e} "
                  f"off by {abs(value - true) / se:.2f} standard errors")
        if not ok:
            bad.append(name)
    print(f"fit: {cpu:.2f} s CPU, {wall:.2f} s wall")
    if bad:
        sys.exit(f"FAIL: not recovered: {bad}")


def staged(fit, history, deck_src):
    truth = {"h_n": 4.0, "thetaf_deg": 9.0, "theta0_deg": 30.0, "zeta0": 6.666}
    with tempfile.TemporaryDirectory() as work:
        deck = os.path.join(work, os.path.basename(deck_src))
        shutil.copy(deck_src, deck)
        run([sys.executable, MAKE_DATA, history, deck, os.path.join(work, "granite_cycles.csv"),
             "--cycle-start", "1", "--cycle-period", "20"], work)
        out, wall = run([fit, deck], work)
        print(out)
        stem = os.path.splitext(os.path.basename(deck))[0]
        got, cpu = check_outputs(os.path.join(work, stem + "_fit.h5"),
                                 os.path.join(work, stem + "_fitted.nml"), history, work)
        with open(deck) as f:
            text = f.read()
        # the plot script: one PNG per curve in the deck's order, and the combined one
        plot, _ = run([sys.executable, os.path.join(ROOT, "scripts", "plot_fit.py"),
                       os.path.join(work, stem + "_fit.h5"), "--combined",
                       os.path.join(work, "all.png")], work)
        written = [os.path.basename(x) for x in plot.split()]
        assert written == [f"{stem}_fit_{c}.png" for c in
                           ("shear2", "dilation2", "shear1", "dilation1")] + ["all.png"], written
        assert all(os.path.getsize(os.path.join(work, x)) > 0 for x in written)
    bad = not_recovered(got, truth, 1e-4, "paper")
    print(f"staged fit: {cpu:.2f} s CPU, {wall:.2f} s wall (target: under 30 s on one core)")
    assert "stage_parameters" in text
    if bad:
        sys.exit(f"FAIL: not recovered: {bad}")


def not_recovered(got, truth, tolerance, source):
    """The parameters of `truth` that the fit (`got`: name -> (value, std_error)) missed by more
    than `tolerance` relative; each printed."""
    bad = []
    for name, true in truth.items():
        value = got[name][0]
        print(f"{name}: {value!r} {source} {true} relative error {abs(value - true) / true:.2e}")
        if abs(value - true) > tolerance * true:
            bad.append(name)
    return bad


def files(fit, history):
    """An earlier result is replaced; a file that is not one is never touched (nothing is written
    then, and no temporary file is left)."""
    history_part, params = SETS["table5"]
    with tempfile.TemporaryDirectory() as work:
        data_deck = os.path.join(work, "truth.nml")
        with open(data_deck, "w") as f:
            f.write(history_part)
        run([sys.executable, MAKE_DATA, history, data_deck, os.path.join(work, "data.csv")], work)
        deck = os.path.join(work, "t.nml")
        with open(deck, "w") as f:
            f.write(history_part + FIT.format(names="'mu'", start="0.42", lower="0.1", upper="1.5"))
        run([fit, "-q", deck], work)
        run([fit, "-q", deck], work)      # replaces its own results
        for victim in ("t_fit.h5", "t_fitted.nml"):
            for name in ("t_fit.h5", "t_fitted.nml"):
                os.remove(os.path.join(work, name)) if os.path.exists(os.path.join(work, name)) else None
            with open(os.path.join(work, victim), "w") as f:
                f.write("precious\n")
            r = subprocess.run([fit, "-q", deck], cwd=work, capture_output=True, text=True)
            assert r.returncode == 1, (victim, r.returncode, r.stdout, r.stderr)
            assert "refusing to overwrite" in r.stderr, r.stderr
            with open(os.path.join(work, victim)) as f:
                assert f.read() == "precious\n"
            left = sorted(n for n in os.listdir(work) if n.startswith("t_") and n != victim)
            assert not left, left
        print("foreign files refused, earlier results replaced")


def identifiability(fit, history):
    """A parameter the curves do not depend on (zeta_0 with wear switched off) is reported not
    identifiable (terminal and HDF5), the others keep finite standard errors."""
    history_part, _ = SETS["table5"]
    history_part += "&effects\n  wear = .false.\n/\n"
    with tempfile.TemporaryDirectory() as work:
        data_deck = os.path.join(work, "truth.nml")
        with open(data_deck, "w") as f:
            f.write(history_part)
        run([sys.executable, MAKE_DATA, history, data_deck, os.path.join(work, "data.csv"),
             "--noise", "0.02"], work)
        deck = os.path.join(work, "t.nml")
        with open(deck, "w") as f:
            f.write(history_part + FIT.format(names="'mu', 'zeta0'", start="0.42, 49.0",
                                              lower="0.1, 1.0", upper="1.5, 500.0"))
        out, _ = run([fit, "-q", deck], work)
        print(out)
        assert "not identifiable from these curves: zeta0" in out, out
        with h5py.File(os.path.join(work, "t_fit.h5"), "r") as f:
            ident = list(f.attrs["identifiable"])
            se = f.attrs["std_error"]
        assert ident == [1.0, 0.0], ident
        assert se[0] < 1e-2 and se[1] > 1e300, se
    print("zeta0 reported not identifiable without wear")


def fit_run(fit, deck, work, *args):
    """Run the fit; (status, stdout, stderr). No runtime error or backtrace either way."""
    r = subprocess.run([fit, *args, deck], cwd=work, capture_output=True, text=True, timeout=600)
    noisy = [w for w in NOISY if w in r.stdout + r.stderr]
    assert not noisy, (noisy, r.stderr[-2000:])
    return r.returncode, r.stdout, r.stderr


def coupled(fit, history):
    """Data of an unworn joint (theta_f = theta_0 = 20 deg), four parameters free from the deck's
    worn values: the optimum lies on the law's limit theta_f = theta_0. Every difference step
    stays inside the admissible set, the fit converges there (status 0), writes its results, and
    reports theta_f and theta_0 at that limit (terminal and HDF5 `at_bound`); zeta_0 is then not
    identifiable (without wear the curves do not depend on it)."""
    with tempfile.TemporaryDirectory() as work:
        for name in ("gen.nml", "coupled.nml"):
            shutil.copy(os.path.join(DATA, name), work)
        run([sys.executable, MAKE_DATA, history, "gen.nml", "nowear.csv"], work)
        rc, out, err = fit_run(fit, "coupled.nml", work)
        print(out, err)
        assert rc == 0, (rc, err)
        assert "AT THE LAW'S LIMIT theta_f = theta_0" in out, out
        assert "not identifiable from these curves: zeta0" in out, out
        with h5py.File(os.path.join(work, "coupled_fit.h5"), "r") as f:
            names = [str(x) for x in f.attrs["parameters"]]
            values = dict(zip(names, f.attrs["values"]))
            at = dict(zip(names, [str(x) for x in f.attrs["at_bound"]]))
            assert f["stages"]["1"].attrs["converged"] == 1
            assert "discretization_change" in f.attrs
        assert names == ["h_n", "theta0_deg", "thetaf_deg", "zeta0"], names
        assert at["thetaf_deg"] == at["theta0_deg"] == "theta_f = theta_0", at
        for name, true in (("h_n", 2.5), ("theta0_deg", 20.0), ("thetaf_deg", 20.0)):
            assert abs(values[name] - true) <= 1e-6 * true, (name, values[name])
        assert values["thetaf_deg"] <= values["theta0_deg"], values
        run([history, "--output-dir", work, os.path.join(work, "coupled_fitted.nml")], work)
        # the same curves with slip and dilation in metres: warned before the fit, and the
        # results (far off, at bounds) written with the warning stored
        with open(os.path.join(work, "nowear.csv")) as f:
            lines = f.read().splitlines()
        head = lines[0].split(",")
        cols = [head.index("slip"), head.index("dilation")]
        with open(os.path.join(work, "metres.csv"), "w") as f:
            f.write(lines[0] + "\n")
            for line in lines[1:]:
                v = line.split(",")
                for c in cols:
                    v[c] = repr(float(v[c]) / 1000.0)
                f.write(",".join(v) + "\n")
        with open(os.path.join(work, "coupled.nml")) as f:
            text = f.read().replace("nowear.csv", "metres.csv")
        with open(os.path.join(work, "metres.nml"), "w") as f:
            f.write(text)
        rc, out, err = fit_run(fit, "metres.nml", work, "-q")
        assert rc in (0, 2), (rc, err)
        assert "(1000 times more): is the curve in other units than the deck (mm, MPa; a slip " \
               "in metres)?" in err and "warning" not in out, (out, err)
        with h5py.File(os.path.join(work, "metres_fit.h5"), "r") as f:
            assert any("slip in metres" in str(x) for x in f.attrs["warnings"])
    print("the optimum on theta_f = theta_0: converged, written, reported at the limit; "
          "a slip in metres warned about")


def inputs(fit, history):
    """Inputs read as written: a CSV with a byte-order mark and no header keeps its first row;
    a number of 72 characters is read whole (0.1, not cut to 0.0); one curve_weight for two
    curves applies to both (and says so)."""
    with tempfile.TemporaryDirectory() as work:
        for name in os.listdir(DATA):
            shutil.copy(os.path.join(DATA, name), work)
        rc, out, err = fit_run(fit, "bom_noheader.nml", work, "-q")
        assert rc == 0, err
        with h5py.File(os.path.join(work, "bom_noheader_fit.h5"), "r") as f:
            x = f["curves"]["shear"]["x"][()]
        assert x.size == 201 and x[0] == 0.0, (x.size, x[:2])
        print("BOM without header: all 201 rows, the first slip 0.0")
        rc, out, err = fit_run(fit, "field_70chars.nml", work, "-q")
        assert rc == 0, err
        with h5py.File(os.path.join(work, "field_70chars_fit.h5"), "r") as f:
            y = f["curves"]["shear"]["y"][()]
        assert y[99] == 0.1, y[99]
        print("a 72-character field read whole: 0.1")
        run([sys.executable, MAKE_DATA, history, "gen_worn.nml", "worn.csv"], work)
        rc, out, err = fit_run(fit, "b16_short_weight.nml", work, "-q")
        assert rc == 0, err
        assert "curve_weight gives one value for 2 curves: it applies to every curve" in err, err
        assert "warning" not in out, out      # warnings go to standard error
        with h5py.File(os.path.join(work, "b16_short_weight_fit.h5"), "r") as f:
            w = [f["curves"][c]["weight"][()] for c in ("shear", "dilation")]
            assert any("curve_weight" in str(x) for x in f.attrs["warnings"])
        assert all(np.all(v == 1.0) for v in w), [v[:3] for v in w]
        print("one curve_weight for two curves: 1.0 on both, said")


def deckfail(fit, history):
    """When the fitted deck cannot be written (its temporary name is taken by a folder), the
    fit exits 1 and writes nothing: an earlier DECK_fit.h5 stays as it was, no new file appears,
    the folder that took the name is left alone."""
    with tempfile.TemporaryDirectory() as work:
        for name in ("bom_noheader.nml", "curve_bom_noheader.csv"):
            shutil.copy(os.path.join(DATA, name), work)
        rc, _, err = fit_run(fit, "bom_noheader.nml", work, "-q")
        assert rc == 0, err
        os.remove(os.path.join(work, "bom_noheader_fitted.nml"))
        earlier = open(os.path.join(work, "bom_noheader_fit.h5"), "rb").read()
        r = subprocess.run(["bash", "-c", 'mkdir bom_noheader_fitted.nml.tmp-$$ && exec "$0" -q '
                            'bom_noheader.nml', fit], cwd=work, capture_output=True, text=True,
                           timeout=600)
        print(r.stdout, r.stderr)
        assert r.returncode == 1, r.returncode
        assert "cannot write the fitted deck" in r.stderr, r.stderr
        assert open(os.path.join(work, "bom_noheader_fit.h5"), "rb").read() == earlier
        left = sorted(os.listdir(work))
        assert not os.path.exists(os.path.join(work, "bom_noheader_fitted.nml")), left
        assert [n for n in left if ".tmp-" in n and not os.path.isdir(os.path.join(work, n))] == []
        assert any(os.path.isdir(os.path.join(work, n)) for n in left), left
    print("exit 1: the fit file not replaced, no fitted deck, the folder left alone")


def discretization(fit, history, deck_src):
    """The discretization check on the shipped staged granite deck with 2 % noise (the docs'
    example): printed and stored, every change below 0.1 standard error. The same data fitted
    with the implicit scheme at 100 steps per mm (first order) moves theta_0 by more than 0.1
    standard error, and the check says so: it can fail. The bias factor and the advice follow
    the order of each scheme in 2D."""
    with tempfile.TemporaryDirectory() as work:
        deck = os.path.join(work, "granite.nml")
        shutil.copy(deck_src, deck)
        run([sys.executable, MAKE_DATA, history, deck, os.path.join(work, "granite_cycles.csv"),
             "--cycle-start", "1", "--cycle-period", "20", "--noise", "0.02", "--seed", "12"], work)
        with open(deck) as f:
            text = f.read()
        coarse = text.replace("scheme = 'trapezoidal'", "scheme = 'implicit'")
        coarse = coarse.replace("steps = 1, 1000, 2000, 1000", "steps = 1, 500, 1000, 500")
        assert coarse != text
        with open(os.path.join(work, "implicit100.nml"), "w") as f:
            f.write(coarse)
        ratios, outs, errs = {}, {}, {}
        for stem in ("granite", "implicit100"):
            rc, out, err = fit_run(fit, stem + ".nml", work, "-q")
            print(out, err)
            outs[stem], errs[stem] = out, err
            assert rc == 0, err
            assert "discretization check" in out
            with h5py.File(os.path.join(work, stem + "_fit.h5"), "r") as f:
                names = [str(x) for x in f.attrs["parameters"]]
                ratio = np.asarray(f.attrs["discretization_change_se"])
                change = np.asarray(f.attrs["discretization_change"])
                se = np.asarray(f.attrs["std_error"])
                assert f.attrs["discretization_check"] == ""
            assert np.allclose(ratio, change / se), (ratio, change / se)
            ratios[stem] = dict(zip(names, ratio))
            assert ("the steps are fine enough" in out) == all(abs(ratio) < 0.1), out
            print(stem, {n: f"{r:.4f}" for n, r in ratios[stem].items()})
        assert all(abs(r) < 0.1 for r in ratios["granite"].values()), ratios["granite"]
        assert abs(ratios["implicit100"]["theta0_deg"]) >= 0.1, ratios["implicit100"]
        # what holds for each scheme in 2D: the trapezoidal scheme second order, implicit first,
        # and the advice names what raises the order
        assert "-1.333333x the change: the trapezoidal scheme in 2D, order 2" in outs["granite"]
        assert "-2x the change: the implicit scheme in 2D, order 1" in outs["implicit100"]
        for advice in ("give more steps (twice the steps make the bias 0.5x as large)",
                       "scheme = 'trapezoidal' (order 2 here)", "extrapolate = .true. (order 2 here)"):
            assert advice in errs["implicit100"], (advice, errs["implicit100"])
    print("discretization check: shipped deck below 0.1 standard error, implicit 100/mm above")


def history_columns(h5, names):
    """The history outputs `names` (interlock-fit's, docs/fit.md) of case 1 of an
    interlock-history file, computed from its separation and traction (3D)."""
    with h5py.File(h5, "r") as f:
        s = f["cases/0001/separation"][()]
        t = f["cases/0001/traction"][()]
    steps = np.hypot(np.diff(s[:, 1]), np.diff(s[:, 2]))
    table = {"slip_length": np.concatenate([[0.0], np.cumsum(steps)]), "separation_n": s[:, 0],
             "separation_t1": s[:, 1], "separation_t2": s[:, 2], "traction_t1": t[:, 1],
             "traction_t2": t[:, 2], "traction_t_magnitude": np.hypot(t[:, 1], t[:, 2])}
    return [table[n] for n in names]


def same_as_history(fit_h5, history_h5):
    """Each curve's fitted history in the fit file (history_x, history_y over the rows the curve
    uses) is the history interlock-history writes for the fitted deck (the same parameters), to
    round-off: the fit runs the case as interlock-history does. Returns the largest relative
    difference."""
    worst = 0.0
    with h5py.File(fit_h5, "r") as f:
        for name in f["curves"]:
            g = f["curves"][name]
            along, against = str(g.attrs["along"]), str(g.attrs["against"])
            hx, hy = g["history_x"][()], g["history_y"][()]
            x, y = history_columns(history_h5, [along, against])
            # the rows the curve uses: a contiguous run of the history's rows
            starts = [k for k in range(x.size - hx.size + 1)
                      if x[k] == hx[0] and y[k] == hy[0]] or \
                     [int(np.argmin(np.abs(x - hx[0]) + np.abs(y - hy[0])))]
            k = starts[0]
            assert k + hx.size <= x.size, (name, k, hx.size, x.size)
            for a, b in ((hx, x[k:k + hx.size]), (hy, y[k:k + hy.size])):
                d = np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300)
                worst = max(worst, d)
                assert d <= 1e-12, (name, along, against, d)
            print(f"curve {name}: {against} against {along}, {hx.size} rows: the fit's history "
                  f"and interlock-history's differ by {d:.1e} relative")
    return worst


def recovery3d(fit, history, deck_src, noise=0.0):
    """The shipped 3D deck: its CSV is what interlock-history computes with the deck's values (a
    regression guard: regenerated here and compared), the fit recovers mu and theta_0 from 35 %
    off to 1e-6 relative, and its model history is interlock-history's for the fitted deck.
    With noise > 0 the curves get noise (seed 12) and each parameter must come back within two
    of its standard errors."""
    truth = {"mu": 0.6898538, "theta0_deg": 30.0}
    with tempfile.TemporaryDirectory() as work:
        stem = os.path.splitext(os.path.basename(deck_src))[0]
        deck = os.path.join(work, stem + ".nml")
        shutil.copy(deck_src, deck)
        shutil.copy(os.path.join(os.path.dirname(deck_src), stem + ".csv"), work)
        fresh = os.path.join(work, "fresh.csv")
        run([sys.executable, MAKE_DATA, history, deck, fresh], work)
        shipped = np.loadtxt(os.path.join(work, stem + ".csv"), delimiter=",", skiprows=1)
        made = np.loadtxt(fresh, delimiter=",", skiprows=1)
        assert shipped.shape == made.shape, (shipped.shape, made.shape)
        scale = np.maximum(np.max(np.abs(made), axis=0), 1e-300)
        drift = float(np.max(np.abs(shipped - made) / scale))
        print(f"shipped CSV against interlock-history now: {drift:.1e} relative (regression guard)")
        assert drift <= 1e-9, drift
        if noise > 0:
            run([sys.executable, MAKE_DATA, history, deck, os.path.join(work, stem + ".csv"),
                 "--noise", str(noise), "--seed", "12"], work)
        out, wall = run([fit, deck], work)
        print(out)
        got, cpu = check_outputs(os.path.join(work, stem + "_fit.h5"),
                                 os.path.join(work, stem + "_fitted.nml"), history, work)
        same_as_history(os.path.join(work, stem + "_fit.h5"),
                        os.path.join(work, stem + "_fitted.h5"))
    if noise > 0:
        bad = []
        for name, true in truth.items():
            value, se = got[name]
            print(f"{name}: {value!r} true {true} standard error {se:.3e} "
                  f"off by {abs(value - true) / se:.2f} standard errors")
            if not abs(value - true) <= 2 * se:
                bad.append(name)
    else:
        bad = not_recovered(got, truth, 1e-6, "true")
    print(f"3D fit: {cpu:.2f} s CPU, {wall:.2f} s wall")
    if bad:
        sys.exit(f"FAIL: not recovered: {bad}")


def circle(fit, history):
    """A 3D deck on a circular slip path (out to r = 0.5 mm along t1, one turn): the fit runs
    the circle, not its chord (which would be a point: the turn ends where it starts): its
    history is interlock-history's for the fitted deck to round-off, the path reaches
    |s_T2| = r and the slip length of the leg out and the turn's chords, and mu comes back to
    1e-6 relative."""
    with tempfile.TemporaryDirectory() as work:
        shutil.copy(os.path.join(DATA, "circle3d.nml"), work)
        run([sys.executable, MAKE_DATA, history, "circle3d.nml", "circle3d.csv"], work)
        rc, out, err = fit_run(fit, "circle3d.nml", work, "-q")
        print(out, err)
        assert rc == 0, (rc, err)
        got, _ = check_outputs(os.path.join(work, "circle3d_fit.h5"),
                               os.path.join(work, "circle3d_fitted.nml"), history, work)
        same_as_history(os.path.join(work, "circle3d_fit.h5"),
                        os.path.join(work, "circle3d_fitted.h5"))
        with h5py.File(os.path.join(work, "circle3d_fit.h5"), "r") as f:
            length = f["curves"]["shear_t2"]["history_x"][()]
        s_t2, = history_columns(os.path.join(work, "circle3d_fitted.h5"), ["separation_t2"])
    # the leg out (r) and the turn in 400 steps: 400 chords of 2 r sin(pi / 400), the sum of
    # the rows' |delta s_T| (r + 2 pi r less 6.5e-5 r)
    r = 0.5
    chords = r + 400 * 2 * r * np.sin(np.pi / 400)
    print(f"slip length {length[-1]!r} (the leg out and 400 chords of the turn: {chords!r}), "
          f"max |s_T2| {np.max(np.abs(s_t2))!r}")
    assert abs(length[-1] - chords) <= 1e-12 * chords, (length[-1], chords)
    assert abs(np.max(np.abs(s_t2)) - r) <= 1e-4 * r, np.max(np.abs(s_t2))
    value = got["mu"][0]
    print(f"mu: {value!r} true 0.6898538 relative error {abs(value / 0.6898538 - 1):.2e}")
    assert abs(value / 0.6898538 - 1) <= 1e-6, value


def square(fit, history):
    """A blind 3D fit on a square path (an outside review's curves: granite-like joint,
    azimuthal RIA of 3 azimuths, sigma_N = -1.5 MPa, a square of side 2 mm, 2 % noise; the
    review's mu = 0.732). With the lab's per-component slips as abscissae (slip_t1 for sigma_T1)
    every point of the second leg, where s_T1 holds still at 2 mm, would be compared with one
    value of the history: the deck is refused before the fit, naming the curve, the leg and
    what to take instead. With the slip length as abscissa mu comes back within two standard
    errors, and the discretization check says what holds for the trapezoidal scheme in 3D
    (first order: the bias about twice the change, no advice to take the scheme it takes)."""
    with tempfile.TemporaryDirectory() as work:
        for name in ("square3d.nml", "square3d.csv"):
            shutil.copy(os.path.join(DATA, name), work)
        rc, out, err = fit_run(fit, "square3d.nml", work, "-q")
        print(out, err)
        assert rc == 1, rc
        for said in ("curve shear_t1: its abscissa slip_t1 (the history's separation_t1) holds "
                     "still at 2 from time 3 to 5 of the history (leg 2 of the square path)",
                     "the curve has 101 points there", "take the slip length"):
            assert said in err, (said, err)
        assert "stage 1" not in out, out
        assert sorted(os.listdir(work)) == ["square3d.csv", "square3d.nml"], os.listdir(work)
        with open(os.path.join(work, "square3d.nml")) as f:
            text = f.read()
        length = text.replace("curve_x = 'slip_t1', 'slip_t2', 'slip_t1'",
                              "curve_x = 'slip_length', 'slip_length', 'slip_length'")
        length = length.replace("curve_along = 'separation_t1', 'separation_t2', 'separation_t1'",
                                "curve_along = 'slip_length', 'slip_length', 'slip_length'")
        assert length.count("slip_length") == 6, length
        with open(os.path.join(work, "length.nml"), "w") as f:
            f.write(length)
        rc, out, err = fit_run(fit, "length.nml", work, "-q")
        print(out, err)
        assert rc == 0, (rc, err)
        # The trapezoidal scheme is second order in 3D (SPEC D14): 400 steps per leg are fine.
        assert "against the exact law is about -1.333333x the change: the trapezoidal scheme " \
               "in 3D, order 2" in out, out
        assert "the steps are fine enough" in out, out
        assert "scheme = 'trapezoidal'" not in out + err, (out, err)
        got, _ = check_outputs(os.path.join(work, "length_fit.h5"),
                               os.path.join(work, "length_fitted.nml"), history, work)
        with h5py.File(os.path.join(work, "length_fit.h5"), "r") as f:
            assert f.attrs["discretization_order"] == 2, f.attrs["discretization_order"]
    value, se = got["mu"]
    print(f"mu: {value!r} against the review's 0.732, standard error {se:.2e}: "
          f"{abs(value - 0.732) / se:.2f} standard errors")
    assert abs(value - 0.732) <= 2 * se, (value, se)


def noisy(fit, history):
    """2 um of noise on the slip of a cyclic test sampled every 3.2 um (an outside review's
    curve: 40001 rows) turns the abscissa back thousands of times: refused, and the message
    says the curve's branches are tiny and why (noise on the abscissa), not only that the
    history has fewer branches."""
    with tempfile.TemporaryDirectory() as work:
        shutil.copy(os.path.join(DATA, "granite_fast.nml"), work)
        clean = np.loadtxt(os.path.join(DATA, "granite_fast.csv"), delimiter=",", skiprows=1)
        t = np.linspace(0.0, clean[-1, 0], 40001)
        rows = np.column_stack([t] + [np.interp(t, clean[:, 0], clean[:, k]) for k in (1, 2, 3)])
        rows[:, 1] += np.random.default_rng(41).normal(0.0, 0.002, t.size)
        np.savetxt(os.path.join(work, "granite_fast.csv"), rows, delimiter=",", fmt="%.9g",
                   header="time,slip_mm,shear_MPa,dilation_mm", comments="")
        rc, out, err = fit_run(fit, "granite_fast.nml", work, "-q")
        print(err)
        assert rc == 1, rc
        for said in ("monotone branches, the history's separation_t through 5 only",
                     "branches span less than 1 % of its range: noise on the abscissa?"):
            assert said in err, (said, err)


def as_nobody():
    """The command prefix that drops root's privileges (root writes into any folder), or []."""
    if os.geteuid() != 0:
        return []
    setpriv = shutil.which("setpriv")
    if setpriv is None:
        sys.exit(77)      # skipped: root cannot be kept out of a folder without setpriv
    return [setpriv, "--reuid", "65534", "--regid", "65534", "--clear-groups"]


def readonly(fit, history):
    """An output folder that cannot be written into is refused before the fit (exit 1, no
    stage run), the folder named."""
    with tempfile.TemporaryDirectory() as work:
        os.chmod(work, 0o755)
        for name in ("granite_fast.nml", "granite_fast.csv"):
            shutil.copy(os.path.join(DATA, name), work)
        out_dir = os.path.join(work, "ro")
        os.mkdir(out_dir)
        os.chmod(out_dir, 0o555)
        r = subprocess.run(as_nobody() + [fit, "--output-dir", "ro", "granite_fast.nml"],
                           cwd=work, capture_output=True, text=True, timeout=600)
        print(r.stdout, r.stderr)
        assert r.returncode == 1, r.returncode
        assert "cannot write into the folder ro/" in r.stderr, r.stderr
        assert "stage 1" not in r.stdout, r.stdout
        assert os.listdir(out_dir) == [], os.listdir(out_dir)


def traced(command, work, inject):
    """Run `command` under strace (the trace in trace.txt) with the fault `inject` (-e
    inject=..., or None); (status, stdout, stderr). Exit 77 (skipped) without strace."""
    strace = shutil.which("strace")
    if strace is None:
        sys.exit(77)
    faults = ["-e", inject] if inject else []
    r = subprocess.run([strace, "-f", "-o", "trace.txt", "-e", "trace=write,rename"] + faults
                       + command, cwd=work, capture_output=True, text=True, timeout=600)
    return r.returncode, r.stdout, r.stderr


def enospc(fit, history):
    """A write error (ENOSPC) on the fitted deck: exit 1, the error said, neither file left, and
    no success line (it exited 0 with an empty fitted deck)."""
    with tempfile.TemporaryDirectory() as work:
        for name in ("granite_fast.nml", "granite_fast.csv"):
            shutil.copy(os.path.join(DATA, name), work)
        # which write(2) is the fitted deck's: the first that starts with its mark
        traced([fit, "-q", "granite_fast.nml"], work, None)
        with open(os.path.join(work, "trace.txt")) as f:
            writes = [line for line in f if " write(" in line]
        n = 1 + next(k for k, line in enumerate(writes) if "interlock-fit: fitted deck" in line)
        for name in ("granite_fast_fit.h5", "granite_fast_fitted.nml"):
            os.remove(os.path.join(work, name))
        rc, out, err = traced([fit, "-q", "granite_fast.nml"], work,
                              f"inject=write:error=ENOSPC:when={n}")
        print(rc, out, err)
        assert rc == 1, rc
        assert "cannot write the fitted deck" in err, err
        assert " -> " not in out, out
        left = sorted(set(os.listdir(work)) - {"granite_fast.nml", "granite_fast.csv", "trace.txt"})
        assert left == [], left


def renames(fit, history):
    """SIGINT right after the first rename of the two result files, with an earlier result
    there: the program ends by the signal, and the two files there belong together (both new:
    the renames are done with the signals held), never a new fit file beside the old deck."""
    with tempfile.TemporaryDirectory() as work:
        for name in ("granite_fast.nml", "granite_fast.csv"):
            shutil.copy(os.path.join(DATA, name), work)
        run([fit, "-q", "granite_fast.nml"], work)
        old = {n: open(os.path.join(work, n), "rb").read()
               for n in ("granite_fast_fit.h5", "granite_fast_fitted.nml")}
        with open(os.path.join(work, "granite_fast.nml")) as f:
            text = f.read()
        with open(os.path.join(work, "granite_fast.nml"), "w") as f:
            f.write(text.replace("start = 4.0, 30.0", "start = 3.0, 30.0"))
        rc, out, err = traced([fit, "-q", "granite_fast.nml"], work, "inject=rename:signal=INT:when=1")
        print(rc, err)
        new = {n: open(os.path.join(work, n), "rb").read() != old[n] for n in old}
        print("new:", new)
        assert rc in (1, 130, -signal.SIGINT), rc
        assert new["granite_fast_fit.h5"] == new["granite_fast_fitted.nml"], new
        with h5py.File(os.path.join(work, "granite_fast_fit.h5"), "r") as f:
            values = [float(v) for v in f.attrs["values"]]
        with open(os.path.join(work, "granite_fast_fitted.nml")) as f:
            header = f.readline()
        assert float(header.split("h_n = ")[1].split()[0]) == values[0], (header, values)


def signals(fit, history):
    """SIGQUIT and SIGXCPU during the fit end it as they end interlock-history, without the
    Fortran runtime's backtrace; SIGXFSZ (sent, or a file-size limit) does not end it."""
    with tempfile.TemporaryDirectory() as work:
        for name in ("square3d.nml", "square3d.csv"):
            shutil.copy(os.path.join(DATA, name), work)
        with open(os.path.join(work, "square3d.nml")) as f:
            text = f.read().replace("'slip_t1', 'slip_t2', 'slip_t1'",
                                    "'slip_length', 'slip_length', 'slip_length'")
            text = text.replace("'separation_t1', 'separation_t2', 'separation_t1'",
                                "'slip_length', 'slip_length', 'slip_length'")
        with open(os.path.join(work, "length.nml"), "w") as f:
            f.write(text)
        for sig in (signal.SIGQUIT, signal.SIGXCPU, signal.SIGXFSZ):
            p = subprocess.Popen([fit, "length.nml"], cwd=work, stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, text=True)
            while not p.stdout.readline().startswith("stage 1"):
                pass                             # until the fit has begun
            p.send_signal(sig)
            out, err = p.communicate(timeout=600)
            print(sig.name, p.returncode, err[-300:])
            for marker in ("Backtrace", "Program received signal"):
                assert marker not in err, (sig.name, err)
            if sig == signal.SIGXFSZ:
                assert p.returncode == 0, (sig.name, p.returncode)
            else:
                assert p.returncode == -sig, (sig.name, p.returncode)
            assert not [n for n in os.listdir(work) if ".tmp-" in n], os.listdir(work)


def main():
    fit, history, mode = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
    modes = {"identifiability": identifiability, "files": files, "coupled": coupled,
             "inputs": inputs, "deckfail": deckfail, "circle": circle, "square": square,
             "noisy": noisy, "readonly": readonly, "enospc": enospc, "renames": renames,
             "signals": signals}
    if mode == "recovery":
        recovery(fit, history, sys.argv[4], float(sys.argv[5]))
    elif mode == "recovery3d" and len(sys.argv) > 5:
        recovery3d(fit, history, sys.argv[4], float(sys.argv[5]))
    elif mode in ("staged", "discretization", "recovery3d"):
        {"staged": staged, "discretization": discretization,
         "recovery3d": recovery3d}[mode](fit, history, sys.argv[4])
    elif mode in modes:
        modes[mode](fit, history)
    else:
        sys.exit(__doc__)
    print("ok")


if __name__ == "__main__":
    main()
