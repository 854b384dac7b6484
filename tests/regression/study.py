"""The collision study's functions (scripts/validation/collisions.py) for the regression checks: the
study runs the given vpsolve (the CTest target) and writes its runs and figures into `scratch` (a
folder named after the check under the test's working folder, in the build tree), never into the
sources; it reads no command-line arguments of the check's own."""
import importlib, os, sys


def collisions(np=2, vpsolve=None, scratch=None):
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    scratch = os.path.abspath(scratch or os.path.splitext(os.path.basename(sys.argv[0]))[0])
    os.makedirs(scratch, exist_ok=True)
    os.environ["VP_ROOT"] = root
    if vpsolve:
        os.environ["VPSOLVE"] = os.path.abspath(vpsolve)
    os.environ["VP_SCRATCH"] = os.environ["VP_FIGURES"] = scratch
    os.environ["NP"] = str(np)
    sys.argv = sys.argv[:1]
    sys.path.insert(0, os.path.join(root, "scripts", "validation"))
    return importlib.import_module("collisions")


def vpsolve_argument():
    """The check's one argument: the vpsolve binary to run."""
    if len(sys.argv) != 2:
        sys.exit("usage: %s <vpsolve binary>" % os.path.basename(sys.argv[0]))
    return sys.argv[1]
