#!/usr/bin/python3
"""Checkpoint/restart end to end (docs/outputs.md): a run of S steps with checkpoints is
restarted from the checkpoint at step K into the same output directory, as after a crash.
Checks: the time series and the snapshot lists continue without gaps or duplicates; every
diagnostics and particle row equals the uninterrupted run's to --tol (0: bitwise, same rank count)
or, on another rank count, to the solver tolerance relative to the quantity's largest value (the
round-off-level divergence is then not compared); checkpoint_latest.h5 points at
the newest checkpoint; bad restarts (other grid, truncated file) fail with a clear message and leave
the output untouched.
usage: check_restart.py --np N --restart-np M --steps S --at K --tol T --dir D [--compare c1,c2]
       -- vpsolve options..."""
import argparse, csv, glob, os, re, shutil, subprocess, sys

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
failures = []


def run(np, out, *extra, expect_ok=True):
    full = ["mpirun", "-n", str(np), "--oversubscribe"] + cmd + ["-output_dir", out, "-time_max_steps", str(args.steps),
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
            if header[c] in skip or (args.compare and c > 0 and header[c] not in args.compare.split(",")):
                continue
            x, y = float(x), float(y)
            d = abs(x - y) / max(scale[group(header[c])], 1e-300)
            if (args.tol == 0 and x != y) or d > args.tol:
                failures.append("%s: step/time %s column %s: %r vs %r (tol %g)" % (name, r[0], header[c], y, x, args.tol))
                return
            worst = max(worst, d)
    print("%s: %d rows equal (largest difference %.2e of the quantity's scale)" % (name, len(ref) - 1, worst))


def steps_in_xmf(path):
    return [int(s) for s in re.findall(r"(?:fields|particles)_(\d{6})\.h5", open(path).read())]


shutil.rmtree(args.dir, ignore_errors=True)
ref, rst = os.path.join(args.dir, "ref"), os.path.join(args.dir, "restart")
every = ["-output_every", str(args.at), "-output_dt", "0"]
run(args.np, ref, *every)
run(args.np, rst, *every, "-checkpoint_every", str(args.at), "-checkpoint_keep", "100")
ck = os.path.join(rst, "checkpoint_%06d.h5" % args.at)
latest = os.path.join(rst, "checkpoint_latest.h5")
if os.readlink(latest) != "checkpoint_%06d.h5" % args.steps:
    failures.append("checkpoint_latest.h5 -> %s, expected checkpoint_%06d.h5" % (os.readlink(latest), args.steps))

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

# The restart, as after a crash of the run at a later step: rows after K are replaced.
run(args.restart_np, rst, *every, "-restart", ck)
compare_table("diagnostics.csv", rows(os.path.join(ref, "diagnostics.csv")), rows(os.path.join(rst, "diagnostics.csv")),
              skip=("wall_time", "pressure_iterations", "velocity_iterations") + (("max_divergence",) if args.tol else ()))
steps = [int(r[0]) for r in rows(os.path.join(rst, "diagnostics.csv"))[1:]]
if steps != list(range(1, args.steps + 1)):
    failures.append("diagnostics.csv steps are not 1..%d once each: %s" % (args.steps, steps))
for f in sorted(glob.glob(os.path.join(ref, "particle_*.csv")))[:5]:
    compare_table(os.path.basename(f), rows(f), rows(os.path.join(rst, os.path.basename(f))))
for x in ("fields.xmf", "particles.xmf"):
    if os.path.exists(os.path.join(ref, x)):
        a, b = steps_in_xmf(os.path.join(ref, x)), steps_in_xmf(os.path.join(rst, x))
        if a != b:
            failures.append("%s lists steps %s, the uninterrupted run %s" % (x, b, a))
        else:
            print("%s lists the same %d snapshots" % (x, len(set(a))))

if failures:
    print("FAILED:\n" + "\n".join(failures))
    sys.exit(1)
print("restart from step %d on %d ranks (written on %d): OK" % (args.at, args.restart_np, args.np))
