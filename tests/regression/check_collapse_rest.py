#!/usr/bin/python3
"""-collapse_rest_speed: a small pile of frictional spheres (DEM only, 2 ranks) spreads along the
floor; the run must end at the first recorded step whose last -collapse_rest_window of the
99th-percentile front (collapse.csv) moved less than speed x window, and not before: the window
ending at the row before still moved more. Without the option the same pile runs to -time_final.
usage: check_collapse_rest.py VPSOLVE WORKDIR"""
import csv, json, os, shutil, subprocess, sys

# The window is not a multiple of the row spacing (1 ms), so that its start is not a tie.
SPEED, WINDOW, FINAL = 1e-3, 0.0505, 0.5
PILE = ["-fluid_off", "-grid_lo", "0,0,0", "-grid_hi", "0.02,0.003,0.01", "-grid_n", "20,3,10",
        "-bc_ylo", "periodic", "-bc_yhi", "periodic", "-gravity", "0,0,-9.81",
        "-particles_lattice", "0.0005,0.0005,0.0005,0.006,0.0025,0.009,0.00105,0.0005,0.1,3", "-particle_density", "2500",
        "-contact_tc", "1e-3", "-contact_restitution", "0.3", "-contact_friction", "0.5", "-time_dt", "2e-5",
        "-time_final", str(FINAL), "-collapse_monitor", "-series_every", "50", "-output_dt", "0", "-output_every", "0",
        "-monitor_every", "0"]


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def run(vpsolve, out, extra):
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run(["mpirun", "-n", "2", vpsolve, *PILE, "-output_dir", out, *extra], check=True, stdout=subprocess.DEVNULL)
    record = json.load(open(os.path.join(out, "run.json")))
    rows = [(float(r["time"]), float(r["front99"])) for r in csv.DictReader(open(os.path.join(out, "collapse.csv")))]
    return record, rows


def moved(rows, end):
    """How far front99 moved over the window ending at row `end` (None: the window is not covered)."""
    t = rows[end][0]
    start = max((k for k in range(end + 1) if t - rows[k][0] >= WINDOW), default=None)
    if start is None:
        return None
    f = [r[1] for r in rows[start:end + 1]]
    return max(f) - min(f)


def main(vpsolve, work):
    record, rows = run(vpsolve, os.path.join(work, "rest"), ["-collapse_rest_speed", str(SPEED), "-collapse_rest_window", str(WINDOW)])
    if "came to rest" not in record["stop_reason"]:
        fail("stop reason %r, expected the collapse to come to rest" % record["stop_reason"])
    t_stop = rows[-1][0]
    if not t_stop < 0.9 * FINAL:
        fail("stopped at t = %g s, expected well before -time_final %g s" % (t_stop, FINAL))
    spread = rows[-1][1] - rows[0][1]
    if not spread > 10 * SPEED * WINDOW:
        fail("the front moved only %g m: nothing to come to rest" % spread)
    last, before = moved(rows, len(rows) - 1), moved(rows, len(rows) - 2)
    if last is None or not last < SPEED * WINDOW:
        fail("the last window moved %s m, not below %g" % (last, SPEED * WINDOW))
    if before is not None and before < SPEED * WINDOW:
        fail("the window ending one row earlier already moved only %g m: the run stopped late" % before)
    print("came to rest at t = %.4f s: front99 spread %.3g m, last window %.3g m, the one before %s m" % (t_stop, spread, last, before))
    record, rows = run(vpsolve, os.path.join(work, "no_rest"), [])
    if record["stop_reason"] != "reached -time_final":
        fail("without -collapse_rest_speed: stop reason %r" % record["stop_reason"])
    print("without the option: ran to t = %g s" % rows[-1][0])


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
