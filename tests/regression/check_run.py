#!/usr/bin/python3
"""Runs a vpsolve case and checks its outputs against the output contract (docs/outputs.md) and
stored reference values.
usage: check_run.py --np N --dir OUT [--expect [file.csv:]column=value:reltol ...] [--steps S,S,...] -- vpsolve args...
--expect: a value of the last row of diagnostics.csv (or of the named CSV file of the run).
--steps: the steps of the diagnostics.csv rows, exactly.
--anchor "script args": a check of the run's physics against an independent number, run as
`/usr/bin/python3 script args <run folder>` after the run (tests/regression/anchor_*.py).
A run with collapse.csv (-collapse_monitor) must also have written deposit.csv, whose two bins
next to the back wall hold the last row's height_back (the same spheres).
run.json must record the rank count, the options given on the command line, the last step and a
normal stop reason, the particle counts (none lost; the last snapshot's count) and the last kinetic
energies of diagnostics.csv."""
import argparse, csv, glob, json, os, shutil, subprocess, sys
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


def check_run_record(out, np, cmd, last):
    rec = json.load(open(os.path.join(out, "run.json")))
    if rec.get("ranks") != np:
        fail("run.json: ranks %s, the run had %d" % (rec.get("ranks"), np))
    if rec.get("step") != int(last["step"]):
        fail("run.json: last step %s, diagnostics.csv ends at %s" % (rec.get("step"), last["step"]))
    reason = rec.get("stop_reason", "")
    given = {cmd[k]: cmd[k + 1] if k + 1 < len(cmd) else "" for k in range(1, len(cmd)) if cmd[k].startswith("-")}
    if reason == "reached -time_max_steps":
        ok = int(given.get("-time_max_steps", rec["step"])) == rec["step"]
    elif reason == "reached -time_final":
        ok = "-time_final" not in given or rec["time"] >= float(given["-time_final"]) * (1 - 1e-12)
    else:
        ok = reason == "the collapse came to rest (-collapse_rest_speed)"
    if not ok:
        fail("run.json: stop reason '%s' at step %s, t = %s" % (reason, rec.get("step"), rec.get("time")))
    options = rec.get("options", {})
    for name in given:
        if name[1:] in options and not options[name[1:]]["given"]:
            fail("run.json: option %s given on the command line is not recorded as given" % name)
    if "particles" in rec:
        snaps = sorted(glob.glob(os.path.join(out, "particles_*.h5")))
        count = len(h5py.File(snaps[-1], "r")["id"]) if snaps else rec["particles"]
        if not rec["particles"] == rec["particles_at_start"] == count:
            fail("run.json: %s particles at the end, %s at the start, %d in the last snapshot" %
                 (rec["particles"], rec["particles_at_start"], count))
    for key in ("kinetic_energy", "particle_kinetic_energy"):
        if key in last and abs(rec.get(key, float("nan")) - float(last[key])) > 1e-9 * abs(float(last[key])):
            fail("run.json: %s %s, diagnostics.csv's last row %s" % (key, rec.get(key), last[key]))
    print("run.json: %d ranks, step %d, %s" % (np, rec["step"], reason))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--expect", action="append", default=[])
    ap.add_argument("--steps")
    ap.add_argument("--anchor", action="append", default=[])
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.cmd[1:] if a.cmd and a.cmd[0] == "--" else a.cmd
    shutil.rmtree(a.dir, ignore_errors=True)
    launcher = ["mpirun", "-n", str(a.np), "--oversubscribe"] if a.np > 1 else []  # one rank: a singleton, no launcher to tear down
    run = launcher + cmd + ["-output_dir", a.dir]
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
    check_run_record(a.dir, a.np, cmd, last)
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
    for anchor in a.anchor:
        script, *rest = anchor.split()
        r = subprocess.run(["/usr/bin/python3", os.path.join(os.path.dirname(os.path.abspath(__file__)), script)] + rest + [a.dir])
        if r.returncode != 0:
            fail("the physics anchor %s failed" % anchor)
    print("ok: %d steps, %d field snapshots" % (len(rows), n))


main()
