#!/usr/bin/env python3
"""Write the hand-made regression cases of the reliability issue into
tests/fuzz/regressions/ (generated cases that once failed are saved there
by `cargo xtask fuzz --save`). Run from the repository root."""
import json, os

OUT = "tests/fuzz/regressions"
os.makedirs(OUT, exist_ok=True)

LESSON = "---\ntitle: Deep\nminutes: 1\nobjectives:\n  - Survive\n---\n\n# Deep\n\n"
UNIT = "---\ntitle: A unit\n---\n\nA unit.\n"
RUN = {"controller": {"kind": "polar", "k_rho": 3, "k_alpha": 8, "k_beta": -1.5},
       "start": {"x": -1, "y": 0.5, "theta_deg": 0}, "goal": {"x": 0, "y": 0, "theta_deg": 0},
       "dt": 0.001, "duration": 10, "output_every": 100}

def dh(n, a=0.1):
    return {"name": "chain", "convention": "standard_dh",
            "joints": [{"name": f"q{i}", "type": "revolute", "a": a, "alpha_deg": 0, "d": 0}
                       for i in range(n)]}

def case(name, command, args, files=(), expect=None, sink=None, note=""):
    c = {"command": command, "args": args}
    if files:
        c["files"] = [[n, spec] for n, spec in files]
    if sink:
        c["sink"] = sink
    c["note"] = note
    if expect:
        c["expect"] = expect
    with open(os.path.join(OUT, f"{command}-{name}.json"), "w") as f:
        json.dump(c, f, indent=1, ensure_ascii=False)
        f.write("\n")

def text(t):
    return {"text": t}

def refused(*pieces):
    return {"exit": 2, "stderr_contains": list(pieces)}

# 1. Crashes
case("deep-quotes", "lessons", ["lessons", "course"],
     [("course/01-u/unit.md", text(UNIT)),
      ("course/01-u/01-l.md", text(LESSON + ">" * 10000 + " x\n"))],
     refused("nested more than"), note="a line of 10 000 `>` overflowed the parser's stack")
case("deep-lists", "lessons", ["lessons", "course"],
     [("course/01-u/unit.md", text(UNIT)),
      ("course/01-u/01-l.md", text(LESSON + "- " * 10000 + "x\n"))],
     refused("nested more than"), note="10 000 list markers overflowed the stack")
case("long-chain", "fk", ["fk", "chain.model.json"],
     [("chain.model.json", text(json.dumps(dh(30000))))],
     refused("at most 512 joints"), note="30 000 joints needed quadratic memory and aborted")
case("full-disk", "batch", ["batch", "run.json", "--count", "100", "--paths"],
     [("run.json", text(json.dumps(RUN)))], {"exit": 3, "stderr_contains": ["cannot write the answer"]},
     sink="full", note="a full disk panicked with a backtrace")
case("closed-pipe", "batch", ["batch", "run.json", "--count", "200", "--paths"],
     [("run.json", text(json.dumps(RUN)))], sink="closed",
     note="a closed pipe panicked with a backtrace")
# 2. Unbounded work
long_run = dict(RUN, dt=0.0001, duration=100)
case("batch-product", "batch", ["batch", "run.json", "--count", "1000", "--paths"],
     [("run.json", text(json.dumps(long_run)))], refused("--count", "steps"),
     note="starts and steps were capped apart, not their product")
mounts = []
for level in range(12):
    sub = f"m{level + 1}.model.json"
    mounts.append((f"m{level}.model.json", text(json.dumps({
        "name": f"m{level}", "convention": "transforms",
        "joints": [{"name": "j", "type": "revolute"}],
        "frames": [{"name": "port", "body": "j"}],
        "mounts": [{"name": f"c{k}", "model": sub, "at": "port"} for k in range(3)]}))))
mounts.append(("m12.model.json", text(json.dumps({"name": "leaf", "convention": "transforms",
                                                     "joints": [{"name": "j", "type": "revolute"}]}))))
case("exponential-mounts", "fk", ["fk", "m0.model.json"], mounts,
     refused("m0.model.json", "more than 64 model files"),
     note="files that each mount the next three times grew exponentially under the depth cap")
case("dev-zero", "simulate", ["simulate", "/dev/zero"], [], refused("/dev/zero", "not a regular file"),
     note="/dev/zero was read until memory ran out")
case("fifo", "analyze", ["analyze", "robot.json"], [("robot.json", "fifo")],
     refused("not a regular file"), note="a FIFO with no writer blocked forever")
case("huge-file", "field", ["field", "f.field.json", "--at", "0,0"],
     [("f.field.json", {"repeat": {"text": " ", "count": 5000000}})], refused("input bound"),
     note="files were read without a size cap")
# 3. Exit 0 with nonsense
case("unstable-gains", "simulate", ["simulate", "run.json"],
     [("run.json", text(json.dumps(dict(RUN, controller={"kind": "polar", "k_rho": 3, "k_alpha": -8, "k_beta": 1.5}))))],
     {"exit": 0, "stdout_contains": ['"diverged":true', "unstable"]},
     note="a diverging run printed null for the final pose")
case("coarse-dt", "simulate", ["simulate", "run.json"],
     [("run.json", text(json.dumps(dict(RUN, dt=1, duration=100))))],
     {"exit": 0, "stdout_contains": ['"diverged":true', "dt is too large"]},
     note="dt = 1 s printed null for the final pose and path length")
case("huge-q", "fk", ["fk", "catalogue:puma560", "--q", "1e308,0,0,0,0,0"], [], refused("--q", "q[0]"),
     note="joint values near 1e308 printed a matrix of nulls")
case("huge-link", "fk", ["fk", "m.model.json", "--q", "0,0"],
     [("m.model.json", text(json.dumps(dh(2, a=1e308))))], refused("joints[0].a"),
     note="link lengths near 1e308 printed a matrix of nulls")
case("ik-nan", "ik", ["ik", "m.model.json", "--position", "1,1,0"],
     [("m.model.json", text(json.dumps(dh(2, a=1e200))))], refused("joints[0].a"),
     note="IK said converged with error 0 when FK of its answer was NaN")
case("axis-overflow", "fk", ["fk", "m.model.json", "--q", "0"],
     [("m.model.json", text(json.dumps({"name": "m", "convention": "transforms",
        "joints": [{"name": "j", "type": "revolute", "axis": [1e308, 1e308, 0]}]})))],
     refused("joints[0].axis"), note="an axis whose norm overflows was accepted")
case("tiny-radius", "analyze", ["analyze", "r.robot.json"],
     [("r.robot.json", text(json.dumps({"name": "r", "wheels": [
        {"kind": "fixed", "alpha_deg": 90, "beta_deg": 0, "l": 0.2, "radius": 5e-324}]})))],
     refused("wheels[0].radius"), note="a radius of 5e-324 passed the 'above 0' check")
case("huge-twist", "drive", ["drive", "catalogue:tricycle", "--twist", "1e160,0,0"], [],
     refused("--twist", "1e160"), note="a twist of 1e160 reported ICR none and a spin of 0")
case("huge-gains", "gains", ["gains", "1e160,8,-1.5"], [], refused("k_rho"),
     note="gains near 1e160 gave a null eigenvalue")
case("huge-start", "simulate", ["simulate", "run.json"],
     [("run.json", text(json.dumps(dict(RUN, start={"x": 0, "y": 0, "theta_deg": 1e300}))))],
     refused("start.theta_deg"), note="a start heading of 1e300 degrees")
# 4. Errors that are not one line or name the wrong thing
case("newline-in-kind", "analyze", ["analyze", "r.robot.json"],
     [("r.robot.json", text(json.dumps({"name": "r", "wheels": [
        {"kind": "fixed\nkinolab: fake", "alpha_deg": 0, "beta_deg": 0, "l": 0.2, "radius": 0.1}]})))],
     refused("wheels[0].kind", "\\n"), note="a newline in a wheel kind split the message")
case("newline-in-file-name", "analyze", ["analyze", "odd\nname.json"], [], refused("odd\\nname.json"),
     note="a newline in a file name split the message")
case("long-key", "simulate", ["simulate", "run.json"],
     [("run.json", text("{\"" + "k" * 3000000 + "\": 1}"))], refused("unknown field"),
     note="a 10 MB string was echoed whole")
case("syntax-run", "simulate", ["simulate", "run.json"],
     [("run.json", text('{\n  "controller": { "kind": "polar", "k_rho": 3, "k_alpha": 8, "k_beta": -1.5 },\n  "start": { "x": 1 "y": 0 }\n}'))],
     refused("line 3 column"), note="syntax errors in run files lost their line and column")
case("syntax-model", "fk", ["fk", "m.model.json"],
     [("m.model.json", text('{\n "name": "m",\n "convention": "transforms",\n "joints": [ {"name": "j" "type": "revolute"} ]\n}'))],
     refused("line 4 column"), note="syntax errors in model files lost their line and column")
case("question-path", "analyze", ["analyze", "r.robot.json"],
     [("r.robot.json", text('{"name": "r", "wheels": [{"kind": "fixed", "alpha_deg": 0, "beta_deg": 0, "l": 0.2, "radius": 0.1}, {"kind": "fix'))],
     {"exit": 2, "stderr_contains": ["wheels[1]"], "stderr_lacks": ["?"]},
     note="`?` appeared as a path segment")
case("gamma-name", "analyze", ["analyze", "r.robot.json"],
     [("r.robot.json", text(json.dumps({"name": "r", "wheels": [
        {"kind": "swedish", "alpha_deg": 0, "beta_deg": 0, "l": 0.2, "radius": 0.1, "gamma_deg": 90}]})))],
     refused("wheels[0].gamma_deg"), note="messages named wheels[0].gamma for gamma_deg")
case("limits-in-degrees", "fk", ["fk", "m.model.json", "--q", "0"],
     [("m.model.json", text(json.dumps({"name": "m", "convention": "standard_dh", "joints": [
        {"name": "q1", "type": "revolute", "a": 0.1, "limits_deg": [90, -90]}]})))],
     refused("joints[0].limits_deg", "90"), note="limits were printed in radians for a _deg key")
case("dh-angle-name", "fk", ["fk", "m.model.json", "--q", "0"],
     [("m.model.json", text(json.dumps({"name": "m", "convention": "standard_dh", "joints": [
        {"name": "q1", "type": "revolute", "a": 0.1, "alpha_deg": 1e300}]})))],
     refused("joints[0].alpha_deg"), note="DH errors named alpha for alpha_deg")
case("coupling-overflow", "fk", ["fk", "m.model.json", "--q", "1"],
     [("m.model.json", text(json.dumps({"name": "m", "convention": "standard_dh", "joints": [
        {"name": "q1", "type": "revolute", "a": 0.1}, {"name": "q2", "type": "revolute", "a": 0.1}],
        "couplings": [{"follower": "q2", "leader": "q1", "ratio": 1e300}]})))],
     refused("couplings[0].ratio"), note="a coupling overflow blamed --q")
case("segment-angle-name", "simulate", ["simulate", "run.json"],
     [("run.json", text(json.dumps({"controller": {"kind": "open_loop", "segments": [
        {"kind": "arc", "radius": 1, "angle_deg": 1e300}]}, "start": {"x": 0, "y": 0, "theta_deg": 0}})))],
     refused("angle_deg"), note="plan errors named angle for angle_deg")
case("bare", "usage", [], [], refused("no command given"),
     note="bare `kinolab` printed its description as an error")
case("missing-option", "usage", ["ik", "catalogue:puma560"], [], refused("--position"),
     note="a missing option was not named")
case("leg-hint", "leg-events", ["leg-events", "18"], [], {"exit": 2, "stderr_contains": ["17"], "stderr_lacks": ["leg_events", "()"]},
     note="a hint named a Rust function the user cannot call")
case("no-joints", "fk", ["fk", "m.model.json"],
     [("m.model.json", text(json.dumps({"name": "m", "convention": "transforms",
        "joints": [{"name": "plate", "type": "fixed", "origin": {"xyz": [0, 0, 1]}}]})))],
     {"exit": 0, "stdout_contains": ['"matrix"']}, note="a model with no movable joints could not be used with fk")
case("duplicate-key", "simulate", ["simulate", "run.json"],
     [("run.json", text('{"dt": 0.001, "dt": 0.002, "controller": {"kind": "polar", "k_rho": 3, "k_alpha": 8, "k_beta": -1.5}, "start": {"x": 1, "y": 0, "theta_deg": 0}, "goal": {"x": 0, "y": 0, "theta_deg": 0}}'))],
     refused("duplicate field `dt`"), note="duplicate keys")
# Round-two commands inherit the same rules
GAIT = {"name": "crawl", "duty_factor": 0.75, "stride": 0.2, "com": [0, 0],
        "legs": [{"name": "LF", "x": 0.3, "y": 0.2, "phase": 0.25}, {"name": "RF", "x": 0.3, "y": -0.2, "phase": 0.75},
                 {"name": "LH", "x": -0.3, "y": 0.2, "phase": 0.0}, {"name": "RH", "x": -0.3, "y": -0.2, "phase": 0.5}]}
case("duty-one", "gait", ["gait", "g.gait.json"], [("g.gait.json", text(json.dumps(dict(GAIT, duty_factor=1))))],
     refused("duty_factor"), note="a duty factor of 1 (never lifting) is outside (0, 1)")
case("phase-one", "gait", ["gait", "g.gait.json"],
     [("g.gait.json", text(json.dumps(dict(GAIT, legs=[dict(GAIT["legs"][0], phase=1.0)]))))],
     refused("legs[0].phase"), note="a phase of 1 is the same instant as 0")
case("no-legs", "gait", ["gait", "g.gait.json"], [("g.gait.json", text(json.dumps(dict(GAIT, legs=[]))))],
     refused("legs"), note="fewer than one leg")
case("flight", "gait", ["gait", "g.gait.json", "--samples", "50"],
     [("g.gait.json", text(json.dumps(dict(GAIT, duty_factor=0.2))))],
     {"exit": 0, "stdout_contains": ['"margin":null', '"statically_stable":false']},
     note="a running gait has instants with no foot down: the margin is null there, by the contract")
case("samples-bound", "gait", ["gait", "catalogue:hexapod-wave", "--samples", "100001"], [],
     refused("--samples"), note="samples are bounded")
CPG = {"frequency": 1.0, "legs": ["LF", "RF", "LH", "RH"], "target_phases": [0.25, 0.75, 0.0, 0.5],
       "weight": 2.0, "initial_deg": [0, 10, 20, 30], "dt": 0.001, "duration": 10.0}
case("tiny-dt", "cpg", ["cpg", "c.cpg.json"], [("c.cpg.json", text(json.dumps(dict(CPG, dt=1e-9))))],
     refused("dt", "steps"), note="duration / dt is bounded")
case("lengths", "cpg", ["cpg", "c.cpg.json"], [("c.cpg.json", text(json.dumps(dict(CPG, initial_deg=[0]))))],
     refused("initial_deg"), note="one initial phase per leg")
case("start-in-obstacle", "plan", ["plan", "catalogue:two-rooms", "--from", "5.1,1", "--to", "9,5", "--cell", "0.25"], [],
     refused("--from"), note="a start in an occupied cell is bad input")
case("cell-bound", "plan", ["plan", "catalogue:two-rooms", "--from", "1,1", "--to", "9,5", "--cell", "0.0001"], [],
     refused("--cell"), note="the grid's cell count is bounded")
case("walled-in", "plan", ["plan", "w.world.json", "--from", "1,1", "--to", "3,3", "--cell", "0.25"],
     [("w.world.json", text(json.dumps({"bounds": [0, 0, 4, 4], "robot_radius": 0.1,
        "obstacles": [{"kind": "wall", "from": [2, 0], "to": [2, 4], "thickness": 0.2}]})))],
     {"exit": 0, "stdout_contains": ['"cost":null']}, note="no path is an answer, not an error")
