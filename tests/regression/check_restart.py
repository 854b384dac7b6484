#!/usr/bin/python3
"""Checkpoint/restart end to end (docs/outputs.md), as after a crash. A run of S steps writes
checkpoints every K steps; then a crash at step C (K < C < S) is simulated in its output directory:
the CSV rows after step C are cut, the snapshots and checkpoints after step C deleted and run.json
reduced to its start record. The run is restarted there from the checkpoint at step K.
Checks against an uninterrupted run:
- every CSV file (time series, tracked particles, probes, collapse) row by row to --tol (0: bitwise)
  or, on another rank count, relative to the quantity's largest value, in the --compare columns;
- the XDMF files list the same snapshots, and every file they list exists;
- the final snapshots' datasets (particles sorted by id) to the same tolerance;
- run.json: the restart's rank count, the last step S, S - K steps run by the restart, the same stop
  reason, particle counts and last kinetic energy;
- bad restarts (other grid, truncated file, missing file) fail with a clear message and leave the
  output untouched.
So a restart that does nothing leaves rows and snapshots missing, and one that starts again from
step 0 runs S steps: both fail here.
usage: check_restart.py --np N --restart-np M --steps S --at K --tol T --dir D [--compare c1,c2]
       -- vpsolve options..."""
import argparse, csv, glob, json, os, re, shutil, subprocess, sys
import h5py
import numpy as np

ap = argparse.ArgumentParser()
for a in ("--np", "--restart-np", "--steps", "--at"):
    ap.add_argument(a, type=int, required=True)
ap.add_argument("--tol", type=float, required=True)
ap.add_argument("--dir", required=True)
ap.add_argument("--compare", help="comma-separated columns to compare (default: all); for restarts on another rank "
                "count, where components that are zero up to round-off (a sideways mean flow) differ in noise only")
ap.add_argument("cmd", nargs=argparse.REMAINDER)
args = ap.parse_args()
cmd = args.cmd[1:] if args.cmd and args.cmd[0] == "--" else args.cmd
S, K = args.steps, args.at
C = K + max(1, (S - K) // 2)  # the simulated crash: after the checkpoint, before the end
failures = []
SNAPSHOT = re.compile(r"(fields|particles|checkpoint)_(\d{6})\.h5$")


def run(np_, out, *extra, expect_ok=True):
    full = ["mpirun", "-n", str(np_), "--oversubscribe"] + cmd + ["-output_dir", out, "-time_max_steps", str(S),
                                                                  "-monitor_every", "0"] + list(extra)
    p = subprocess.run(full, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if expect_ok and p.returncode != 0:
        sys.exit("FAILED: %s\n%s" % (" ".join(full), p.stdout[-3000:]))
    return p


def rows(path):
    with open(path) as f:
        return list(csv.reader(f))


def group(column):
    """Components share a scale: vx, vy, vz -> v; mean_u, mean_v, mean_w -> mean_."""
    if column.startswith("mean_"):
        return "mean_"
    return column[:-1] if column[-1:] in "xyz" else column


def compared(column):
    return not args.compare or column in args.compare.split(",")


def differ(x, y, scale):
    """Relative difference of x and y over the quantity's scale, and whether it fails the tolerance."""
    d = abs(x - y) / max(scale, 1e-300)
    return d, (args.tol == 0 and x != y) or d > args.tol


def compare_table(name, ref, got, skip=()):
    if len(ref) != len(got):
        failures.append("%s: %d rows, the uninterrupted run has %d" % (name, len(got), len(ref)))
        return
    header = ref[0]
    # Across rank counts, differences are relative to the largest value of the quantity (round-off
    # noise in a component that is zero, e.g. a sideways velocity, is not compared to itself).
    scale = {}
    for r in ref[1:]:
        for c, x in enumerate(r):
            scale[group(header[c])] = max(scale.get(group(header[c]), 0.0), abs(float(x)))
    worst = 0.0
    for r, g in zip(ref[1:], got[1:]):
        for c, (x, y) in enumerate(zip(r, g)):
            if header[c] in skip or (c > 0 and not compared(header[c])):
                continue
            d, bad = differ(float(x), float(y), scale[group(header[c])])
            if bad:
                failures.append("%s: step/time %s column %s: %r vs %r (tol %g)" % (name, r[0], header[c], y, x, args.tol))
                return
            worst = max(worst, d)
    print("%s: %d rows equal (largest difference %.2e of the quantity's scale)" % (name, len(ref) - 1, worst))


def simulate_crash(out):
    """The output directory as a run that died during step C + 1 leaves it."""
    diag = rows(os.path.join(out, "diagnostics.csv"))
    t_crash = next(float(r[1]) for r in diag[1:] if int(r[0]) == C)
    for path in glob.glob(os.path.join(out, "*.csv")):
        table = rows(path)
        if table[0][0] not in ("step", "time"):  # written once at the end (deposit.csv)
            os.remove(path)
            continue
        limit = C if table[0][0] == "step" else t_crash * (1 + 1e-9)
        with open(path, "w", newline="") as f:
            csv.writer(f).writerows([table[0]] + [r for r in table[1:] if float(r[0]) <= limit])
    for path in glob.glob(os.path.join(out, "*.h5")):
        m = SNAPSHOT.search(path)
        if m and int(m.group(2)) > C:
            os.remove(path)
    latest = os.path.join(out, "checkpoint_latest.h5")
    os.remove(latest)
    os.symlink("checkpoint_%06d.h5" % K, latest)
    record = json.load(open(os.path.join(out, "run.json")))
    start = {k: v for k, v in record.items() if k in ("program", "version", "date", "host", "ranks", "command", "options", "petsc_options")}
    json.dump(start, open(os.path.join(out, "run.json"), "w"), indent=2)


def xmf_steps(path):
    return [int(s) for s in re.findall(r"(?:fields|particles)_(\d{6})\.h5", open(path).read())]


def compare_snapshot(ref_file, got_file):
    with h5py.File(ref_file, "r") as a, h5py.File(got_file, "r") as b:
        order = lambda h: np.argsort(np.array(h["id"]).ravel()) if "id" in h else None
        oa, ob = order(a), order(b)
        worst = 0.0
        for name in a:
            # Across rank counts (--compare) the positions and velocities, and the columns named.
            if not isinstance(a[name], h5py.Dataset) or not (compared(name) or name in ("position", "velocity")):
                continue
            x = np.array(a[name])
            y = np.array(b[name]) if name in b else None
            if y is None or x.shape != y.shape:
                failures.append("%s: dataset %s missing or of another shape" % (got_file, name))
                continue
            if oa is not None and x.shape[:1] == oa.shape:
                x, y = x[oa], y[ob]
            scale = float(np.abs(x).max()) if x.size else 0.0
            d = float(np.abs(x - y).max()) / max(scale, 1e-300) if x.size else 0.0
            if (args.tol == 0 and not np.array_equal(x, y)) or d > args.tol:
                failures.append("%s: dataset %s differs from the uninterrupted run's by %.3e of its scale" % (got_file, name, d))
            worst = max(worst, d)
    print("%s: datasets equal (largest difference %.2e of the quantity's scale)" % (os.path.basename(got_file), worst))


shutil.rmtree(args.dir, ignore_errors=True)
ref, rst = os.path.join(args.dir, "ref"), os.path.join(args.dir, "restart")
every = ["-output_every", str(K), "-output_dt", "0"]
run(args.np, ref, *every)
run(args.np, rst, *every, "-checkpoint_every", str(K), "-checkpoint_keep", "100")
ck = os.path.join(rst, "checkpoint_%06d.h5" % K)
latest = os.path.join(rst, "checkpoint_latest.h5")
if os.readlink(latest) != "checkpoint_%06d.h5" % S:
    failures.append("checkpoint_latest.h5 -> %s, expected checkpoint_%06d.h5" % (os.readlink(latest), S))
simulate_crash(rst)

# Bad restarts first: they must fail clearly and leave the output as it is.
before = {f: open(f, "rb").read() for f in glob.glob(os.path.join(rst, "*.csv")) + glob.glob(os.path.join(rst, "*.xmf"))}
truncated = os.path.join(args.dir, "truncated.h5")
with open(ck, "rb") as f:
    data = f.read()
with open(truncated, "wb") as f:
    f.write(data[: len(data) // 2])
n = [int(v) for v in re.search(r"-grid_n\s+(\S+)", " ".join(cmd)).group(1).split(",")] if "-grid_n" in cmd else None
bad = [(["-restart", truncated], r"option -restart: .*(truncated|damaged|not an HDF5)"),
       (["-restart", os.path.join(rst, "none.h5")], r"option -restart: cannot read")]
if n:
    bad.append((["-restart", ck, "-grid_n", "%d,%d,%d" % (n[0] * 2, n[1], n[2])], r"option -restart: .* was written for -grid_n"))
for extra, pattern in bad:
    p = run(args.restart_np, rst, *every, *extra, expect_ok=False)
    if p.returncode == 0 or not re.search(pattern, p.stdout):
        failures.append("restart %s: exit %d, no message matching '%s':\n%s" % (" ".join(extra), p.returncode, pattern, p.stdout[-1500:]))
    else:
        print("bad restart refused: " + re.search(pattern, p.stdout).group(0))
for f, content in before.items():
    if open(f, "rb").read() != content:
        failures.append("a refused restart changed " + f)

# The restart from step K: rows K+1..C are replaced, C+1..S written anew.
run(args.restart_np, rst, *every, "-restart", latest)
for f in sorted(glob.glob(os.path.join(ref, "*.csv"))):
    name = os.path.basename(f)
    if not os.path.exists(os.path.join(rst, name)):
        failures.append("the restart did not write " + name)
        continue
    skip = ("wall_time", "pressure_iterations", "velocity_iterations") + (("max_divergence",) if args.tol else ())
    compare_table(name, rows(f), rows(os.path.join(rst, name)), skip=skip if name == "diagnostics.csv" else ())
steps = [int(r[0]) for r in rows(os.path.join(rst, "diagnostics.csv"))[1:]]
if steps != sorted(set(steps)) or steps[-1:] != [S]:
    failures.append("diagnostics.csv steps are not increasing once each to %d: %s" % (S, steps))
for x in ("fields.xmf", "particles.xmf"):
    if os.path.exists(os.path.join(ref, x)):
        a, b = xmf_steps(os.path.join(ref, x)), xmf_steps(os.path.join(rst, x))
        missing = [f for f in re.findall(r"((?:fields|particles)_\d{6}\.h5)", open(os.path.join(rst, x)).read())
                   if not os.path.exists(os.path.join(rst, f))]
        if a != b or missing:
            failures.append("%s lists steps %s (missing files %s), the uninterrupted run %s" % (x, b, missing, a))
        else:
            print("%s lists the same %d snapshots, all present" % (x, len(set(a))))
for kind in ("fields", "particles"):
    last = "%s_%06d.h5" % (kind, S)
    if os.path.exists(os.path.join(ref, last)):
        if not os.path.exists(os.path.join(rst, last)):
            failures.append("the restart wrote no " + last)
        else:
            compare_snapshot(os.path.join(ref, last), os.path.join(rst, last))
a, b = json.load(open(os.path.join(ref, "run.json"))), json.load(open(os.path.join(rst, "run.json")))
want = {"ranks": args.restart_np, "step": S, "steps_this_run": S - K, "stop_reason": a.get("stop_reason"),
        "particles_at_start": a.get("particles_at_start"), "particles": a.get("particles")}
wrong = ["%s %r (expected %r)" % (k, b.get(k), v) for k, v in want.items() if b.get(k) != v]
for k in ("kinetic_energy", "particle_kinetic_energy"):
    if k in a and (k not in b or differ(a[k], b[k], abs(a[k]))[1]):
        wrong.append("%s %r (uninterrupted %r)" % (k, b.get(k), a[k]))
if wrong:
    failures.append("run.json of the restart: " + ", ".join(wrong))
else:
    print("run.json: %d ranks, %d steps run to step %d, stop reason %s" % (args.restart_np, S - K, S, b["stop_reason"]))

if failures:
    print("FAILED:\n" + "\n".join(failures))
    sys.exit(1)
print("restart from step %d after a crash at step %d, on %d ranks (written on %d): OK" % (K, C, args.restart_np, args.np))
