#!/usr/bin/python3
"""A checkpoint's particle rows are read by their column names (its attribute particle_columns,
docs/outputs.md), so a new particle field needs no checkpoint version. On the coarse falling sphere
(2 ranks, 20 steps, a checkpoint at step 10):
- the checkpoint with its columns in reverse order restarts to the uninterrupted run's final
  particles and fields, bitwise;
- without the columns of one field (as written before the field existed) it restarts, the field
  taking its default, and runs its 10 steps;
- with a column this vpsolve does not know it is refused, naming the column, before anything is written.
usage: check_checkpoint_columns.py <vpsolve> <scratch dir>"""
import json, os, re, shutil, subprocess, sys
import h5py
import numpy as np

vpsolve, work = sys.argv[1], os.path.join(sys.argv[2], "checkpoint_columns")
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
CASE = ["-options_file", os.path.join(root, "cases", "falling_sphere.opts"), "-grid_n", "16,16,24", "-time_max_steps", "20",
        "-output_every", "10", "-output_dt", "0", "-monitor_every", "0"]
fail = []


def run(out, *extra):
    return subprocess.run(["mpirun", "-n", "2", "--oversubscribe", vpsolve] + CASE + ["-output_dir", out] + list(extra),
                          capture_output=True, text=True)


def width(name):
    """Values a checkpoint column name stands for: wall_spring[6][3] is 18."""
    return int(np.prod([int(k) for k in re.findall(r"\[(\d+)\]", name)] or [1]))


def rewrite(src, dst, change):
    """A copy of checkpoint src whose particle columns are change(list of (name, values)) of the original's."""
    shutil.copy(src, dst)
    with h5py.File(dst, "r+") as f:
        names = f.attrs["particle_columns"].decode().split(",")
        data, at, cols = np.array(f["particles"]), 0, []
        for n in names:
            cols.append((n, data[:, at:at + width(n)]))
            at += width(n)
        cols = change(cols)
        del f["particles"]
        f["particles"] = np.hstack([c for _, c in cols])
        f.attrs["particle_columns"] = np.bytes_(",".join(n for n, _ in cols))


r = run(os.path.join(work, "ref"), "-checkpoint_every", "10")
if r.returncode != 0:
    sys.exit("FAIL: the uninterrupted run: " + r.stdout[-2000:] + r.stderr[-2000:])
ck = os.path.join(work, "ref", "checkpoint_000010.h5")

rewrite(ck, os.path.join(work, "reversed.h5"), lambda cols: cols[::-1])
r = run(os.path.join(work, "reversed"), "-restart", os.path.join(work, "reversed.h5"))
if r.returncode != 0:
    fail.append("the reversed columns' restart failed: " + r.stdout[-1500:])
else:
    for name, sets in (("particles_000020.h5", ("position", "velocity", "angular_velocity")), ("fields_000020.h5", ("velocity", "pressure"))):
        with h5py.File(os.path.join(work, "ref", name)) as a, h5py.File(os.path.join(work, "reversed", name)) as b:
            for s in sets:
                if not np.array_equal(np.array(a[s]), np.array(b[s])):
                    fail.append("reversed columns: %s %s differs from the uninterrupted run's" % (name, s))
    print("reversed columns: the final particles and fields equal the uninterrupted run's" if not fail else fail[-1])

rewrite(ck, os.path.join(work, "older.h5"), lambda cols: [c for c in cols if c[0] not in ("lfx", "lfy", "lfz")])
r = run(os.path.join(work, "older"), "-restart", os.path.join(work, "older.h5"))
rec = json.load(open(os.path.join(work, "older", "run.json"))) if r.returncode == 0 else {}
if rec.get("steps_this_run") != 10 or rec.get("step") != 20:
    fail.append("without the lf columns: exit %d, run.json %s" % (r.returncode, {k: rec.get(k) for k in ("step", "steps_this_run")}))
else:
    print("without the columns lfx,lfy,lfz: restarted and ran 10 steps to step 20")

rewrite(ck, os.path.join(work, "newer.h5"), lambda cols: cols + [("zz", np.zeros((len(cols[0][1]), 1)))])
r = run(os.path.join(work, "newer"), "-restart", os.path.join(work, "newer.h5"))
message = re.search(r"option -restart: .*has the particle column zz, unknown to this vpsolve", r.stdout + r.stderr)
if r.returncode != 1 or not message or os.path.exists(os.path.join(work, "newer", "run.json")):
    fail.append("an unknown column: exit %d, %s" % (r.returncode, (r.stdout + r.stderr)[-1000:]))
else:
    print("an unknown column refused: " + message.group(0))
if fail:
    sys.exit("FAIL: " + "; ".join(fail))
print("ok")
