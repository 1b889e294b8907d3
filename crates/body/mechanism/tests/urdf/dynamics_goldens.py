"""Golden dynamics for URDF files, computed with Pinocchio (an independent
library: `pip install pin`), for `tests/dynamics.rs` and for the outside
comparison over a whole collection of robots.

    python tests/urdf/dynamics_goldens.py [URDF ...] [--out DIR]

With no files, the robots in `robots/` are used and the goldens written
beside this script as `<robot>.dynamics.json`. For each robot: a fixed
base, gravity (0, 0, -9.81), and a few random states (a fixed seed) of
the driven joints (moving joints without `mimic`, in file order): q inside
each joint's limits and [-pi, pi], q' and q'' in [-1, 1]. It writes tau = RNEA(q, q',
q''), g = RNEA(q, 0, 0), the mass matrix M(q), and q'' = FD(q, q', tau)
for a random tau. Joints that mimic another are reduced as the lab does:
they move with their leader, whose torque carries theirs.
"""

import json
import pathlib
import random
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

HERE = pathlib.Path(__file__).parent
ROBOTS = HERE.parent.parent / "robots"
STATES = 4
GRAVITY = [0.0, 0.0, -9.81]


def joints(path):
    """Moving joints in file order: (name, lower, upper, mimic or None)."""
    out = []
    for j in ET.parse(path).getroot().iter("joint"):
        kind = j.get("type")
        if kind not in ("revolute", "continuous", "prismatic"):
            continue
        limit = j.find("limit")
        lo, hi = -np.pi, np.pi
        if kind != "continuous" and limit is not None:
            lo, hi = float(limit.get("lower", 0)), float(limit.get("upper", 0))
            if lo == hi:
                lo, hi = -np.pi, np.pi
            # States a robot meets: no more than half a turn either way.
            lo, hi = max(lo, -np.pi), min(hi, np.pi)
        mimic = j.find("mimic")
        if mimic is not None:
            mimic = (mimic.get("joint"), float(mimic.get("multiplier", 1)), float(mimic.get("offset", 0)))
        out.append((j.get("name"), lo, hi, mimic))
    return out


def golden(path, seed=7):
    model = pin.buildModelFromUrdf(str(path))
    model.gravity.linear = np.array(GRAVITY)
    data = model.createData()
    listed = joints(path)
    names = {n for n, *_ in listed}
    # Mimics of joints the file does not have are read as free joints.
    listed = [(n, lo, hi, m if m and m[0] in names else None) for n, lo, hi, m in listed]
    driven = [n for n, _, _, m in listed if m is None]
    # Pinocchio's velocity index of each joint, and the reduction S that
    # maps driven rates to every joint's rate.
    index = {model.names[i]: model.joints[i].idx_v for i in range(1, model.njoints)}
    for n, *_ in listed:
        if model.joints[model.getJointId(n)].nv != 1:
            raise SystemExit(f"{path}: joint {n} is not one-dimensional")
    S = np.zeros((model.nv, len(driven)))
    offsets = np.zeros(model.nq)
    for n, _, _, m in listed:
        if m is None:
            S[index[n], driven.index(n)] = 1.0
        else:
            leader, k, offset = m
            S[index[n], driven.index(leader)] = k
            offsets[model.joints[model.getJointId(n)].idx_q] = offset
    rng = random.Random(seed)
    states = []
    for _ in range(STATES):
        qr = [rng.uniform(lo, hi) for n, lo, hi, m in listed if m is None]
        qdr = np.array([rng.uniform(-1, 1) for _ in driven])
        qddr = np.array([rng.uniform(-1, 1) for _ in driven])
        taur = np.array([rng.uniform(-5, 5) for _ in driven])
        if model.nq != model.nv:
            raise SystemExit(f"{path}: a joint has more than one coordinate")
        q = S @ np.array(qr) + offsets
        qd, qdd = S @ qdr, S @ qddr
        tau = S.T @ pin.rnea(model, data, q, qd, qdd)
        g = S.T @ pin.rnea(model, data, q, np.zeros(model.nv), np.zeros(model.nv))
        M = S.T @ pin.crba(model, data, q) @ S
        M = np.triu(M) + np.triu(M, 1).T
        bias = S.T @ pin.rnea(model, data, q, qd, np.zeros(model.nv))
        fwd = np.linalg.solve(M, taur - bias)
        states.append(
            {
                "q": qr,
                "qd": qdr.tolist(),
                "qdd": qddr.tolist(),
                "tau": tau.tolist(),
                "gravity": g.tolist(),
                "mass_matrix": M.tolist(),
                "forward_tau": taur.tolist(),
                "forward_qdd": fwd.tolist(),
            }
        )
    return {
        "robot": path.stem,
        "pinocchio": pin.__version__,
        "order": driven,
        "gravity_vector": GRAVITY,
        "states": states,
    }


def main(argv):
    out = None
    if "--out" in argv:
        i = argv.index("--out")
        out = pathlib.Path(argv[i + 1])
        argv = argv[:i] + argv[i + 2 :]
    paths = [pathlib.Path(a) for a in argv] or sorted(ROBOTS.glob("*.urdf"))
    for path in paths:
        g = golden(path)
        target = (out or HERE) / f"{path.stem}.dynamics.json"
        target.write_text(json.dumps(g) + "\n")
        print(f"{path.stem}: {len(g['order'])} driven joints -> {target}")


if __name__ == "__main__":
    main(sys.argv[1:])
