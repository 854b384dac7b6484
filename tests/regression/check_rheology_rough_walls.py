#!/usr/bin/python3
"""Liquid sheared between rough walls (-particles_rough_walls: a layer of fixed spheres on each wall,
moving with it; docs/rheology.md): the wall traction, which counts the forces of the liquid on the
walls' spheres, balances the core's viscous stress in the steady state, and the core shears faster
than the nominal rate (the spheres carry the liquid between them with the walls).
usage: check_rheology_rough_walls.py VPSOLVE OUTDIR [NPROC]"""
import csv, os, shutil, subprocess, sys

vpsolve, out = sys.argv[1], sys.argv[2]
nproc = sys.argv[3] if len(sys.argv) > 3 else "2"
shutil.rmtree(out, ignore_errors=True)
# 4 d x 4 d x 6 d (d = 1 mm) at d/dx 6; the viscous time of the gap (L^2 / (pi^2 nu)) is 0.036 s.
subprocess.run(["mpirun", "-n", nproc, vpsolve, "-grid_lo", "0,0,0", "-grid_hi", "0.004,0.004,0.006", "-grid_n", "24,24,36",
                "-bc_xlo", "periodic", "-bc_xhi", "periodic", "-bc_ylo", "periodic", "-bc_yhi", "periodic",
                "-bc_zlo", "velocity", "-bc_zhi", "velocity", "-bc_zlo_velocity", "-0.03,0,0", "-bc_zhi_velocity", "0.03,0,0",
                "-init_flow", "couette", "-fluid_rho", "1000", "-fluid_mu", "0.1", "-particles_rough_walls", "5e-4",
                "-particle_density", "1000", "-contact_tc", "2e-5", "-contact_hydro", "keep", "-pressure_pc_type", "fft",
                "-time_dt_max", "4e-4", "-dem_substeps", "10", "-time_final", "0.25", "-rheology_monitor", "-output_dt", "0",
                "-monitor_every", "0", "-output_dir", out], check=True, stdout=subprocess.DEVNULL)
rows = [r for r in csv.DictReader(open(os.path.join(out, "rheology.csv"))) if float(r["time"]) >= 0.1]
# The walls' spheres cross the grid: their penalization force swings by a few per cent from step to
# step; the mean over the last 0.15 s (four viscous times) is steady.
mean = {k: sum(float(r[k]) for r in rows) / len(rows) for k in ("eta_r", "eta_r_bottom", "eta_r_top", "eta_r_bulk", "core_rate")}
balance = mean["eta_r"] / mean["eta_r_bulk"] - 1
print(f"{len(rows)} rows from t = 0.1 s: eta_r {mean['eta_r']:.4f} (bottom {mean['eta_r_bottom']:.4f}, top {mean['eta_r_top']:.4f}), "
      f"eta_r_bulk {mean['eta_r_bulk']:.4f}, wall / bulk - 1 {balance:.1e}, core_rate {mean['core_rate']:.4f}")
sys.exit(0 if abs(balance) < 3e-3 and abs(mean["eta_r_bottom"] / mean["eta_r_top"] - 1) < 3e-3 and mean["core_rate"] > 1.2 else 1)
