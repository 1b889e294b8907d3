"""The lab's `kinolab dynamics` against Pinocchio on a whole collection of
real robots, as an outside checker would run it.

    python tests/urdf/compare_dynamics.py KINOLAB ROBOTS_DIR

KINOLAB is the command line's binary; ROBOTS_DIR a folder searched for
`*.urdf` files (PyPI's `example-robot-data` installs one). Robots with a
continuous, floating or planar joint are skipped (Pinocchio gives those
more than one coordinate). For each robot and state of
`dynamics_goldens.py`, tau, g, M and the forward accelerations must match
to 1e-8, relative to the largest entry. Prints one line per robot and a
summary; exits 1 if any robot differs.
"""

import json
import pathlib
import subprocess
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from dynamics_goldens import golden  # noqa: E402

TOLERANCE = 1e-8


def skipped(path):
    text = path.read_text(errors="replace")
    return any(f'type="{k}"' in text for k in ("continuous", "floating", "planar"))


def kinolab(binary, path, args):
    out = subprocess.run([binary, "dynamics", str(path), *args], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(out.stderr.strip())
    return json.loads(out.stdout)


def numbers(v):
    return ",".join(repr(float(x)) for x in v)


def differs(got, want):
    got, want = np.asarray(got, float), np.asarray(want, float)
    scale = max(1.0, float(np.max(np.abs(want)))) if want.size else 1.0
    return float(np.max(np.abs(got - want))) / scale if want.size else 0.0


def compare(binary, path, g):
    """The largest relative difference between the lab and goldens `g`."""
    worst = 0.0
    for s in g["states"]:
        q, qd = numbers(s["q"]), numbers(s["qd"])
        inverse = kinolab(binary, path, ["--q", q, "--qd", qd, "--qdd", numbers(s["qdd"])])
        if inverse["order"] != g["order"]:
            raise RuntimeError(f"order {inverse['order']} vs {g['order']}")
        worst = max(worst, differs(inverse["tau"], s["tau"]), differs(inverse["gravity"], s["gravity"]),
                    differs(inverse["mass_matrix"], s["mass_matrix"]))
        forward = kinolab(binary, path, ["--q", q, "--qd", qd, "--tau", numbers(s["forward_tau"])])
        worst = max(worst, differs(forward["qdd"], s["forward_qdd"]))
    return worst


def main(binary, folder):
    paths = sorted(pathlib.Path(folder).rglob("*.urdf"))
    passed = failed = skip = 0
    for path in paths:
        if skipped(path):
            skip += 1
            continue
        try:
            g = golden(path)
        except Exception as e:  # noqa: BLE001 (Pinocchio raises many kinds)
            skip += 1
            print(f"skip {path.name}: Pinocchio gives no goldens ({str(e).splitlines()[0]})")
            continue
        try:
            worst = compare(binary, path, g)
            ok = worst <= TOLERANCE
            print(f"{'ok  ' if ok else 'DIFF'} {path.name}: {len(g['order'])} joints, largest relative difference {worst:.1e}")
        except (RuntimeError, ValueError) as e:
            ok = False
            print(f"FAIL {path.name}: {e}")
        passed += ok
        failed += not ok
    print(f"{passed} robots match Pinocchio, {failed} do not, {skip} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
