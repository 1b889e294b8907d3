"""Golden forward kinematics for the URDF files in `robots/`, computed with
Pinocchio (an independent library: `pip install pin`), for
`tests/urdf.rs`.

Run from the crate's folder: `python tests/urdf/goldens.py`. For each
robot it draws joint values (a fixed seed, inside each joint's limits),
sets every mimic joint from its leader, and writes every link's pose in
the root link's frame to `tests/urdf/<robot>.golden.json`.
"""

import json
import pathlib
import random
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

HERE = pathlib.Path(__file__).parent
ROBOTS = HERE.parent.parent / "robots"
CONFIGS = 6


def joints(path):
    """Movable joints in file order: (name, lower, upper, mimic or None)."""
    out = []
    for j in ET.parse(path).getroot().iter("joint"):
        if j.get("type") not in ("revolute", "continuous", "prismatic"):
            continue
        limit = j.find("limit")
        lo, hi = -np.pi, np.pi
        if j.get("type") != "continuous" and limit is not None:
            lo, hi = float(limit.get("lower", 0)), float(limit.get("upper", 0))
        mimic = j.find("mimic")
        if mimic is not None:
            mimic = (
                mimic.get("joint"),
                float(mimic.get("multiplier", 1)),
                float(mimic.get("offset", 0)),
            )
        out.append((j.get("name"), lo, hi, mimic))
    return out


def golden(name):
    path = ROBOTS / f"{name}.urdf"
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    rng = random.Random(7)
    configs = []
    for _ in range(CONFIGS):
        values = {}
        for joint, lo, hi, mimic in joints(path):
            if mimic is None:
                values[joint] = rng.uniform(lo, hi)
        for joint, _, _, mimic in joints(path):
            if mimic is not None:
                leader, k, offset = mimic
                values[joint] = k * values[leader] + offset
        q = pin.neutral(model)
        for joint, v in values.items():
            jid = model.getJointId(joint)
            idx = model.joints[jid].idx_q
            if model.joints[jid].nq == 2:  # continuous: cos, sin
                q[idx], q[idx + 1] = np.cos(v), np.sin(v)
            else:
                q[idx] = v
        pin.framesForwardKinematics(model, data, q)
        frames = {
            f.name: data.oMf[i].homogeneous.tolist()
            for i, f in enumerate(model.frames)
            if f.type == pin.FrameType.BODY
        }
        driven = {j[0] for j in joints(path) if j[3] is None}
        configs.append(
            {"set": {k: v for k, v in values.items() if k in driven}, "frames": frames}
        )
    out = {"robot": name, "pinocchio": pin.__version__, "configs": configs}
    (HERE / f"{name}.golden.json").write_text(json.dumps(out) + "\n")


for robot in ("panda", "ur5", "solo12"):
    golden(robot)
