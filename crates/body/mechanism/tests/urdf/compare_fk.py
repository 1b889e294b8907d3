"""The lab's `kinolab fk --all-frames` against Pinocchio on a whole
collection of real robots, as an outside checker would run it.

    python tests/urdf/compare_fk.py KINOLAB ROBOTS_DIR [POSES]

KINOLAB is the command line's binary; ROBOTS_DIR a folder searched for
`*.urdf` files (PyPI's `example-robot-data` installs one). Every file is
tried, whatever its joints: at the zero pose and at POSES (default 3)
random poses, every link's pose in the root frame must match Pinocchio's
(fixed base) to 1e-9. Joints are set by name with `--set`; a mimic joint
follows its leader on both sides; random values lie inside a joint's
limits where the file gives finite ones (up to a turn either way), else in
a turn either way. Floating and planar joints stay at their origin, as
the lab reads them (Pinocchio's neutral configuration). Prints one line
per robot and a summary; exits 1 if any robot differs or is refused.
"""

import json
import math
import pathlib
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

TOLERANCE = 1e-9


def joints_of(path):
    """The file's moving joints: name -> (type, limits or None, mimic or None)."""
    root = ET.fromstring(path.read_text(errors="replace").lstrip())
    out = {}
    for j in root.iter("joint"):
        kind = j.get("type")
        if kind not in ("revolute", "continuous", "prismatic"):
            continue
        limit = j.find("limit")
        limits = None
        if kind != "continuous" and limit is not None:
            lo, hi = float(limit.get("lower", 0)), float(limit.get("upper", 0))
            if lo < hi:
                limits = (lo, hi)
        mimic = j.find("mimic")
        m = None
        if mimic is not None and mimic.get("joint") is not None:
            m = (mimic.get("joint"), float(mimic.get("multiplier", 1)), float(mimic.get("offset", 0)))
        out[j.get("name")] = (kind, limits, m)
    return out


def pose_values(joints, rng):
    """Random values for the joints that are set, by name."""
    values = {}
    for name, (kind, limits, mimic) in joints.items():
        if mimic is not None and mimic[0] in joints:
            continue
        lo, hi = (-math.pi, math.pi)
        if limits is not None:
            lo, hi = max(limits[0], -2 * math.pi), min(limits[1], 2 * math.pi)
            if lo > hi:
                lo = hi = limits[0]
        values[name] = float(rng.uniform(lo, hi))
    return values


def settled(joints, values):
    """Every joint's value: the set ones, followers from their leaders."""
    full = dict(values)
    for _ in range(len(joints)):
        for name, (_, _, mimic) in joints.items():
            if mimic is not None and mimic[0] in full and name not in values:
                leader, k, offset = mimic
                full[name] = k * full[leader] + offset
    return full


def pinocchio_frames(model, data, joints, full):
    q = pin.neutral(model)
    for jid in range(1, model.njoints):
        name = model.names[jid]
        if name not in joints:
            continue
        value = full.get(name, 0.0)
        j = model.joints[jid]
        if j.nq == 2:  # continuous: cos, sin
            q[j.idx_q], q[j.idx_q + 1] = math.cos(value), math.sin(value)
        elif j.nq == 1:
            q[j.idx_q] = value
    pin.framesForwardKinematics(model, data, q)
    return {f.name: data.oMf[i].homogeneous for i, f in enumerate(model.frames) if f.type == pin.FrameType.BODY}


def kinolab(binary, path, values):
    args = [binary, "fk", str(path), "--all-frames"]
    if values:
        args += ["--set", ",".join(f"{k}={v!r}" for k, v in values.items())]
    else:
        args += ["--q", ""]
    out = subprocess.run(args, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(out.stderr.strip().splitlines()[0] if out.stderr.strip() else f"exit {out.returncode}")
    return json.loads(out.stdout)["frames"]


def compare(binary, path, poses, rng):
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    joints = joints_of(path)
    # Only the joints Pinocchio kept as independent are set; mimic ones follow.
    worst, links = 0.0, 0
    for i in range(poses + 1):
        values = pose_values(joints, rng)
        if i == 0:
            values = {name: 0.0 for name in values}
        ours = kinolab(binary, path, values)
        theirs = pinocchio_frames(model, data, joints, settled(joints, values))
        for name, m in theirs.items():
            if name not in ours:
                continue
            links += 1
            worst = max(worst, float(np.max(np.abs(np.asarray(ours[name]) - m))))
    return worst, links


def main(binary, folder, poses=3):
    rng = np.random.default_rng(20261207)
    paths = sorted(pathlib.Path(folder).rglob("*.urdf"))
    passed = failed = skipped = 0
    for path in paths:
        try:
            pin.buildModelFromUrdf(str(path))
        except Exception as e:  # noqa: BLE001 (Pinocchio raises many kinds)
            skipped += 1
            print(f"skip {path.name}: Pinocchio does not read it ({str(e).splitlines()[0][:80]})")
            continue
        try:
            worst, links = compare(binary, path, poses, rng)
            ok = worst <= TOLERANCE and links > 0
            print(f"{'ok  ' if ok else 'DIFF'} {path.name}: {links} link poses, largest difference {worst:.1e}")
        except (RuntimeError, ValueError, KeyError) as e:
            ok = False
            print(f"FAIL {path.name}: {e}")
        passed += ok
        failed += not ok
    print(f"{passed} robots match Pinocchio, {failed} do not, {skipped} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 3))
