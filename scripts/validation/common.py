"""Shared by the validation scripts: where the repository, the solver and the figures are, and a
non-interactive matplotlib."""
import os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

root = os.environ.get("VP_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
ranks = os.environ.get("NP", "2")
vpsolve = os.path.join(root, "build", "vpsolve")
outdir = os.path.join(root, "docs", "validation")
os.makedirs(outdir, exist_ok=True)
