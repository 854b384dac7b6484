"""Shared by the validation scripts: where the repository, the solver and the figures are, and a
non-interactive matplotlib."""
import os
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

root = os.environ.get("VP_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
ranks = os.environ.get("NP", "2")
# The binaries, the runs' scratch folder and the figures' folder; the tests point them into their build folder.
vpsolve = os.environ.get("VPSOLVE", os.path.join(root, "build", "vpsolve"))
harada = os.environ.get("HARADA", os.path.join(root, "build", "harada"))
scratch = os.environ.get("VP_SCRATCH", "/tmp")
outdir = os.environ.get("VP_FIGURES", os.path.join(root, "docs", "validation"))
os.makedirs(outdir, exist_ok=True)


def help_requested(doc):
    """With -h or --help: prints the script's usage (its docstring) and exits, running nothing."""
    if "-h" in sys.argv or "--help" in sys.argv:
        print(doc.strip())
        sys.exit(0)


def chosen_study(doc, studies, valued=()):
    """The first study named on the command line (all when none is), refused unless it is one of
    `studies`; the options in `valued` take the next argument as their value. -h / --help prints the
    usage instead."""
    help_requested(doc)
    args = sys.argv[1:]
    names = [a for k, a in enumerate(args) if not a.startswith("-") and (k == 0 or args[k - 1] not in valued)]
    what = names[0] if names else "all"
    if what not in tuple(studies) + ("all",):
        sys.exit("unknown study '%s' (valid: %s, all)" % (what, ", ".join(studies)))
    return what
