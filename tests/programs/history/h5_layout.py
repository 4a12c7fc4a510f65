#!/usr/bin/python3
"""The layout of an interlock-history HDF5 file as text: every group and dataset (path, shape,
dtype, chunking) and every attribute (name, dtype kind, shape and value), one line each, sorted.
The attributes that name the run rather than the result (version, command_line, deck_file) are
listed with their type only.

usage: h5_layout.py FILE.h5                      print the layout
       h5_layout.py FILE.h5 --compare LAYOUT.txt  exit 1 (printing the differences) unless the
                                                  file's layout is the stored one
"""
import sys

import h5py
import numpy as np

RUN_ATTRIBUTES = {"version", "command_line", "deck_file"}


def attribute_line(where, name, value):
    if isinstance(value, (bytes, np.bytes_)):
        value = value.decode()
    if isinstance(value, str):
        kind, shape = "str", "()"
    else:
        arr = np.asarray(value)
        kind, shape = arr.dtype.str, str(arr.shape)
        value = arr.tolist()
    return f"@ {where}:{name} {kind} {shape}" + ("" if name in RUN_ATTRIBUTES else " = " + repr(value))


def layout(path):
    lines = []

    def visit(name, obj):
        where = "/" + name if name else "/"
        if isinstance(obj, h5py.Dataset):
            lines.append(f"D {where} {obj.shape} {obj.dtype.str} chunks={obj.chunks} "
                         f"maxshape={obj.maxshape}")
        else:
            lines.append(f"G {where}")
        for a in obj.attrs:
            lines.append(attribute_line(where, a, obj.attrs[a]))

    with h5py.File(path, "r") as f:
        visit("", f)
        f.visititems(visit)
    return sorted(lines)


def main(argv):
    if len(argv) == 1:
        print("\n".join(layout(argv[0])))
        return 0
    if len(argv) == 3 and argv[1] == "--compare":
        got = layout(argv[0])
        with open(argv[2], encoding="utf-8") as f:
            want = f.read().splitlines()
        if got == want:
            print(f"{argv[0]}: the layout of {argv[2]} ({len(want)} lines)")
            return 0
        gs, ws = set(got), set(want)
        for line in sorted(ws - gs):
            print("missing:    " + line)
        for line in sorted(gs - ws):
            print("unexpected: " + line)
        if gs == ws:
            print("the same lines in another order or with repeats")
        return 1
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
