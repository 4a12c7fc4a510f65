"""Runs the calling script under a python3 that has the modules it needs.

The project's scripts need Debian's python3-numpy, python3-h5py or python3-matplotlib, which
/usr/bin/python3 has; the first `python3` on PATH may be another one (pyenv, a virtual
environment) without them. A script calls

    python_with.modules("numpy", "h5py")

before it imports them (and before it does anything else): when the interpreter running it
lacks one, the script is started again, with the same arguments, by the first of
/usr/bin/python3 and the other python3 executables on PATH that has them all (os.execv: the
same process, standard streams and working directory); when none has them, it exits with a
message naming the modules and Debian's packages.
"""
import importlib.util
import os
import subprocess
import sys

# Set in the environment of the restarted script: it never restarts twice.
RESTARTED = "INTERLOCK_PYTHON_RESTARTED"
DEBIAN_PACKAGES = {"numpy": "python3-numpy", "h5py": "python3-h5py",
                   "matplotlib": "python3-matplotlib"}


def _candidates():
    """/usr/bin/python3, then every python3 on PATH, each once, not the running one."""
    seen = {os.path.realpath(sys.executable)}
    paths = ["/usr/bin/python3"] + [os.path.join(d, "python3")
                                    for d in os.environ.get("PATH", "").split(os.pathsep) if d]
    for path in paths:
        real = os.path.realpath(path)
        if real in seen or not os.access(path, os.X_OK):
            continue
        seen.add(real)
        yield path


def modules(*names):
    """Returns when the running interpreter has every module in `names`; else restarts the
    calling script under one that has, or exits naming what is missing."""
    lacking = [name for name in names if importlib.util.find_spec(name) is None]
    if not lacking:
        return
    script = os.path.abspath(sys.argv[0])
    if not os.environ.get(RESTARTED):
        probe = "import " + ", ".join(names)
        for exe in _candidates():
            ok = subprocess.run([exe, "-c", probe], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL).returncode == 0
            if ok:
                sys.stdout.flush()
                sys.stderr.flush()
                os.environ[RESTARTED] = exe
                os.execv(exe, [exe, script] + sys.argv[1:])
    packages = " ".join(DEBIAN_PACKAGES.get(name, name) for name in lacking)
    where = ("the interpreter it restarted under" if os.environ.get(RESTARTED) else
             "and so do /usr/bin/python3 and every python3 on PATH")
    sys.exit(f"{os.path.basename(script)}: needs the Python modules {', '.join(lacking)}, which "
             f"{sys.executable} lacks ({where}; Debian: apt-get install {packages})")
