#!/usr/bin/python3
"""One torque-free sphere in the shear cell (-rheology_monitor; docs/rheology.md): it spins at gamma/2,
its stresslet (the first moment of its penalization force) is (10/3) pi mu a^3 gamma within the
box's effect, the wall traction equals the core's bulk stress (the momentum balance), and the core's
solid fraction is the sphere's volume over the core's (the sphere lies inside it).
usage: check_rheology_sphere.py VPSOLVE OUTDIR [NPROC]
(scripts/validation/rheology.py runs measure() at other resolutions and cell sizes.)"""
import csv, math, os, shutil, subprocess, sys

A, MU, GAMMA = 5e-4, 0.1, 10.0  # radius (m), viscosity (Pa s), shear rate (1/s)


def measure(vpsolve, out, nproc, box=6, res=8, reuse=False):
    """The sphere in a cubic cell of `box` diameters at `res` cells per diameter, to strain 0.4:
    spin / (gamma/2), stresslet / ((10/3) pi mu a^3 gamma), bulk / wall - 1."""
    L, n = box * 2 * A, box * res
    U = 0.5 * GAMMA * L
    if not (reuse and os.path.exists(os.path.join(out, "rheology.csv"))):
        shutil.rmtree(out, ignore_errors=True)
        args = ["mpirun", "-n", str(nproc), vpsolve, "-grid_lo", "0,0,0", "-grid_hi", f"{L},{L},{L}", "-grid_n", f"{n},{n},{n}",
                "-bc_xlo", "periodic", "-bc_xhi", "periodic", "-bc_ylo", "periodic", "-bc_yhi", "periodic",
                "-bc_zlo", "velocity", "-bc_zhi", "velocity", "-bc_zlo_velocity", f"{-U},0,0", "-bc_zhi_velocity", f"{U},0,0",
                "-init_flow", "couette", "-fluid_rho", "1000", "-fluid_mu", str(MU),
                "-particle_position", f"{L/2},{L/2},{L/2}", "-particle_radius", str(A), "-particle_density", "1000",
                "-contact_tc", "2e-5", "-contact_hydro", "keep", "-pressure_pc_type", "fft", "-time_dt_max", "4e-4",
                "-dem_substeps", "10", "-time_final", "0.04", "-rheology_monitor", "-rheology_margin", "0",
                "-track_particles", "all", "-output_dt", "0", "-monitor_every", "0", "-output_dir", out]
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    row = list(csv.DictReader(open(os.path.join(out, "rheology.csv"))))[-1]
    spin = float(list(csv.DictReader(open(os.path.join(out, "particle_0.csv"))))[-1]["wy"]) / (GAMMA / 2)
    # The core (margin 0) runs from the first to the last cell centre; its hydrodynamic stress less the
    # mean viscous stress is the stresslet over the core's volume.
    volume = L * L * (L - L / n)
    stresslet = (float(row["eta_hydro"]) - float(row["core_rate"])) * MU * GAMMA * volume
    ratio = stresslet / (10 / 3 * math.pi * MU * A**3 * GAMMA)
    return spin, ratio, float(row["eta_r_bulk"]) / float(row["eta_r"]) - 1


if __name__ == "__main__":
    spin, ratio, balance = measure(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else 2)
    L, n = 6 * 2 * A, 6 * 8  # measure()'s default cell
    phi_core = float(list(csv.DictReader(open(os.path.join(sys.argv[2], "rheology.csv"))))[-1]["phi_core"])
    phi_sphere = 4 / 3 * math.pi * A**3 / (L * L * (L - L / n))
    print(f"spin / (gamma/2) {spin:.4f}; stresslet / ((10/3) pi mu a^3 gamma) {ratio:.4f}; bulk / wall - 1 {balance:.1e}; "
          f"phi_core {phi_core:.6e} (the sphere's {phi_sphere:.6e})")
    # The walls, 2.5 d from the sphere's surface, raise the stresslet by a few per cent (docs/rheology.md).
    sys.exit(0 if abs(spin - 1) < 0.03 and 1.0 <= ratio <= 1.08 and abs(balance) < 1e-3
             and abs(phi_core / phi_sphere - 1) < 1e-9 else 1)
