#!/usr/bin/env python3
"""A user's program that goes wrong in one chosen way, for the exec: failure tests (docs/exchange.md).

usage: bad_integrator.py MODE INPUT OUTPUT. Every mode first says something on stderr, as a
failing program would, then: exit (status 7), sleep (starts a child in its process group, which
the timeout must end too: its pid goes to $BAD_CHILD_PID_FILE when set; then says it is ready by
creating $BAD_READY_FILE when set, and blocks forever, so only a timeout or a signal ends it and a
test knows its stderr line was written before that), none (no output file),
garbage (bytes that are not HDF5), missing (no /fields/vz), short (every field one member short),
nan (a NaN at member 3 of vx), float32 (the fields as float32), copy (the input unchanged).
"""
import os
import subprocess
import sys
import time

mode, source, target = sys.argv[1:4]
print("bad_integrator: starting in mode", mode, file=sys.stderr)
print("bad_integrator: " + mode + " is what I do", file=sys.stderr)
sys.stderr.flush()

if mode == "exit":
    sys.exit(7)
if mode == "sleep":
    child = subprocess.Popen(["sleep", "infinity"])
    if os.environ.get("BAD_CHILD_PID_FILE"):
        with open(os.environ["BAD_CHILD_PID_FILE"], "w") as f:
            f.write(str(child.pid))
    if os.environ.get("BAD_READY_FILE"):
        open(os.environ["BAD_READY_FILE"], "w").close()
    while True:
        time.sleep(3600)
if mode == "none":
    sys.exit(0)
if mode == "garbage":
    with open(target, "wb") as f:
        f.write(b"this is not HDF5 at all\n" * 10)
    sys.exit(0)

import h5py  # noqa: E402 (the modes above need no h5py)
import numpy as np  # noqa: E402

with h5py.File(source, "r") as f:
    names = list(f.attrs["fields"])
    y = {n: f["fields"][n][...] for n in names}
with h5py.File(target, "w") as f:
    g = f.create_group("fields")
    for n in names:
        if mode == "missing" and n == "vz":
            continue
        data = y[n][:-1] if mode == "short" else y[n].copy()
        if mode == "nan" and n == "vx":
            data[3] = np.nan
        g.create_dataset(n, data=data, dtype="f4" if mode == "float32" else "f8")
