#!/usr/bin/python3
"""Runs a vpsolve case and checks its outputs against the output contract (docs/outputs.md) and
stored reference values.
usage: check_run.py --np N --dir OUT [--expect [file.csv:]column=value:reltol ...] [--steps S,S,...] -- vpsolve args...
--expect: a value of the last row of diagnostics.csv (or of the named CSV file of the run).
--steps: the steps of the diagnostics.csv rows, exactly.
A run with collapse.csv (-collapse_monitor) must also have written deposit.csv, whose two bins
next to the back wall hold the last row's height_back (the same spheres)."""
import argparse, csv, glob, os, shutil, subprocess, sys
import xml.etree.ElementTree as ET
import h5py

CONTRACT = ["step", "time", "dt", "cfl", "pressure_iterations", "max_divergence", "kinetic_energy", "wall_time"]


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def check_fields(out):
    files = sorted(glob.glob(os.path.join(out, "fields_*.h5")))
    if not files:
        return 0
    xmf = ET.parse(os.path.join(out, "fields.xmf")).getroot()
    for item in xmf.iter("DataItem"):
        if item.get("ItemType") == "HyperSlab":
            fail("fields.xmf uses a HyperSlab item")
        if item.get("Format") != "HDF":
            continue
        fname, dset = item.text.strip().split(":")
        if os.path.isabs(fname):
            fail("fields.xmf uses an absolute path: " + fname)
        with h5py.File(os.path.join(out, fname), "r") as f:
            dims = tuple(int(x) for x in item.get("Dimensions").split())
            if f[dset].shape != dims:
                fail("%s:%s has shape %s, XDMF says %s" % (fname, dset, f[dset].shape, dims))
    for fn in files:
        with h5py.File(fn, "r") as f:
            v, p = f["velocity"], f["pressure"]
            if v.shape[:3] != p.shape or v.shape[3] != 3:
                fail("%s: velocity %s / pressure %s shapes" % (fn, v.shape, p.shape))
            for a in ("time", "origin", "spacing"):
                if a not in f.attrs:
                    fail("%s: attribute %s missing" % (fn, a))
    return len(files)


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def check_collapse(out):
    path = os.path.join(out, "collapse.csv")
    if not os.path.exists(path):
        return
    last = read_rows(path)[-1]
    deposit = read_rows(os.path.join(out, "deposit.csv"))
    back = max(float(r["h"]) for r in deposit[:2])
    if back != float(last["height_back"]):
        fail("deposit.csv next to the back wall %.10g, collapse.csv height_back %s" % (back, last["height_back"]))
    if not float(last["front"]) >= float(last["front99"]) > 0:
        fail("collapse.csv: front %s below its 99th percentile %s" % (last["front"], last["front99"]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--expect", action="append", default=[])
    ap.add_argument("--steps")
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.cmd[1:] if a.cmd and a.cmd[0] == "--" else a.cmd
    shutil.rmtree(a.dir, ignore_errors=True)
    run = ["mpirun", "-n", str(a.np), "--oversubscribe"] + cmd + ["-output_dir", a.dir]
    r = subprocess.run(run, capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        fail("vpsolve exited with %d" % r.returncode)
    rows = read_rows(os.path.join(a.dir, "diagnostics.csv"))
    if list(rows[0].keys())[:len(CONTRACT)] != CONTRACT:
        fail("diagnostics.csv header %s" % list(rows[0].keys()))
    last = rows[-1]
    if a.steps is not None:
        steps = [int(r["step"]) for r in rows]
        if steps != [int(x) for x in a.steps.split(",")]:
            fail("diagnostics.csv rows at steps %s, expected %s" % (steps, a.steps))
    n = check_fields(a.dir)
    check_collapse(a.dir)
    for e in a.expect:
        col, rest = e.split("=")
        value, tol = (float(x) for x in rest.split(":"))
        row = last
        if ":" in col:
            name, col = col.split(":")
            row = read_rows(os.path.join(a.dir, name))[-1]
        got = float(row[col])
        rel = abs(got - value) / max(abs(value), 1e-300)
        print("%s = %.10g (reference %.10g, relative difference %.2e, tolerance %.0e)" % (col, got, value, rel, tol))
        if rel > tol:
            fail("%s differs from its reference" % col)
    print("ok: %d steps, %d field snapshots" % (len(rows), n))


main()
