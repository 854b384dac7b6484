"""The collision study's functions (scripts/validation/collisions.py) for the regression checks: the
repository's root, the rank count and no command-line arguments of the check's own."""
import importlib, os, sys


def collisions(np):
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    os.environ.setdefault("VP_ROOT", root)
    os.environ["NP"] = str(np)
    sys.argv = sys.argv[:1]
    sys.path.insert(0, os.path.join(root, "scripts", "validation"))
    return importlib.import_module("collisions")
