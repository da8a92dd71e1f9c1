"""The A1 quadruped standing under a joint PD controller and falling without it, in MuJoCo,
beside dirac's run of the same robot (benches/peers/standing.rs).

Reads dirac's lines (`case,t,quantity,value`) from the file given, loads the same URDF into
MuJoCo (its visuals dropped, a free joint on the base, the plane z = 0), starts from dirac's
start (the four feet on the ground), runs the same PD law sampled at 1 kHz (held between
samples) and prints both runs' base and joints side by side. Standing, only the feet's
collision spheres touch and the joint limits are off, as in dirac's standing robot; falling,
the trunk's box touches too and the joints stop at their limits (MuJoCo's limits stiffened to
a 2 ms time constant, dirac's are hard), with the feet's friction and without. MuJoCo at its
best for contact with friction: elliptic cones, `impratio` 10, 10 iterations of its no-slip
solver, the Newton solver, time step 1e-4 s.

    python standing.py A1_URDF DIRAC_LINES [PAGE CHROMIUM]

With the standing run's 3D page and headless Chromium, also checks the page: at the run's end
its screenshot is not background where dirac's state puts each foot (projected by the camera
the page reports on its canvas), and is background in the corner.
"""

import re
import sys
import time
from collections import defaultdict

import mujoco
import numpy as np

KP, KD, PERIOD, MU, STEP, LIMIT_TIME = 50.0, 3.0, 1e-3, 0.8, 1e-4, 2e-3
LEGS = ["FR", "FL", "RR", "RL"]
JOINTS = [("hip", 0.0), ("thigh", 0.8), ("calf", -1.81)]


def model(urdf: str, falling: bool = False, mu: float = MU) -> mujoco.MjModel:
    text = open(urdf).read()
    text = re.sub(r"<visual>.*?</visual>", "", text, flags=re.S)
    # The feet's spheres; falling, the trunk's box too.
    touches = lambda shape: "sphere" in shape or (falling and "0.267 0.194 0.114" in shape)
    text = re.sub(r"<collision>.*?</collision>", lambda m: m.group(0) if touches(m.group(0)) else "", text, flags=re.S)
    text = re.sub(r"(<robot[^>]*>)", r'\1<mujoco><compiler discardvisual="true" fusestatic="false"/></mujoco>', text, count=1)
    path = "/tmp/dirac_a1_mujoco.urdf"
    open(path, "w").write(text)
    spec = mujoco.MjSpec.from_file(path)
    spec.option.timestep = STEP
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.option.impratio = 10
    spec.option.noslip_iterations = 10
    spec.option.solver = mujoco.mjtSolver.mjSOL_NEWTON
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    if not falling:
        spec.option.disableflags |= mujoco.mjtDisableBit.mjDSBL_LIMIT
    for joint in spec.joints:
        joint.solref_limit = [LIMIT_TIME, 1.0]
    spec.worldbody.first_body().add_freejoint()
    floor = spec.worldbody.add_geom()
    floor.type = mujoco.mjtGeom.mjGEOM_PLANE
    floor.size = [10, 10, 0.1]
    for geom in spec.geoms:
        geom.friction = [mu, 0, 0]
        geom.condim = 3 if mu > 0 else 1
    return spec.compile()


def run(m: mujoco.MjModel, start: dict, end: float, times: list, control: bool) -> dict:
    d = mujoco.MjData(m)
    d.qpos[0:3] = [start["base_x"], start["base_y"], start["base_z"]]
    d.qpos[3:7] = [1, 0, 0, 0]
    joints = [f"{leg}_{j}_joint" for leg in LEGS for j, _ in JOINTS]
    angles = {f"{leg}_{j}_joint": a for leg in LEGS for j, a in JOINTS}
    adr = {name: (m.joint(name).qposadr[0], m.joint(name).dofadr[0]) for name in joints}
    actuated = {name: m.joint(name).dofadr[0] for name in joints}
    for name in joints:
        d.qpos[adr[name][0]] = start[name]
    mujoco.mj_forward(m, d)
    out = defaultdict(dict)
    per_sample = round(PERIOD / STEP)
    samples = iter(sorted(times))
    next_sample = next(samples, None)
    step = 0
    while True:
        t = step * STEP
        while next_sample is not None and abs(t - next_sample) < 0.5 * STEP:
            out[next_sample].update({"base_x": d.qpos[0], "base_y": d.qpos[1], "base_z": d.qpos[2]})
            out[next_sample].update({name: d.qpos[adr[name][0]] for name in joints})
            next_sample = next(samples, None)
        if t >= end - 0.5 * STEP:
            break
        if step % per_sample == 0:
            d.qfrc_applied[:] = 0.0
            if control:
                for name in joints:
                    q, v = d.qpos[adr[name][0]], d.qvel[adr[name][1]]
                    d.qfrc_applied[actuated[name]] = KP * (angles[name] - q) - KD * v
        mujoco.mj_step(m, d)
        step += 1
    return out


def main():
    urdf, lines = sys.argv[1], sys.argv[2]
    dirac = defaultdict(lambda: defaultdict(dict))
    ends = {}
    for line in open(lines):
        case, t, quantity, value = line.strip().split(",", 3)
        if case == "end":
            ends[quantity] = (float(t), value)
            continue
        dirac[case][float(t)][quantity] = float(value)
    start = dirac["start"][0.0]
    m = model(urdf)
    print(f"MuJoCo {mujoco.__version__}: nq = {m.nq}, mass {sum(m.body_mass):.4f} kg, step {STEP} s")
    for case, control, mu in [("standing", True, MU), ("falling", False, MU), ("frictionless", False, 0.0)]:
        times = sorted(dirac[case])
        end = max(times)
        if case in ends:
            print(f"\ndirac's {case} run reached {ends[case][0]} s: {ends[case][1]}")
        m = model(urdf, falling=not control, mu=mu)
        clock = time.perf_counter()
        theirs = run(m, start, end, times, control)
        print(f"MuJoCo: {end} s in {time.perf_counter() - clock:.2f} s of wall time")
        print(f"\n{case} ({'PD at 1 kHz' if control else f'no torques, mu = {mu}'}):")
        print(f"{'t':>6} | {'dirac z':>10} {'MuJoCo z':>10} {'Δz':>9} | {'dirac x':>10} {'MuJoCo x':>10} | {'joints Δ (rad)':>14}")
        for t in times:
            mine, other = dirac[case][t], theirs.get(t)
            if other is None:
                continue
            joints = max(abs(mine[k] - other[k]) for k in mine if k.endswith("_joint"))
            print(
                f"{t:6.3f} | {mine['base_z']:10.6f} {other['base_z']:10.6f} {mine['base_z'] - other['base_z']:+9.2e} | "
                f"{mine['base_x']:+10.6f} {other['base_x']:+10.6f} | {joints:14.2e}"
            )
        if control:
            # Settled (the PD's oscillation has died out by 2.5 s in both): what moves after.
            late = [t for t in times if t >= 2.5]
            for name, run_ in [("dirac", dirac[case]), ("MuJoCo", theirs)]:
                z = [run_[t]["base_z"] for t in late]
                x = [run_[t]["base_x"] for t in late]
                print(f"{name}: from 2.5 s to 5 s the base moves {max(z) - min(z):.2e} m in z, {max(x) - min(x):.2e} m in x")


def view(page: str, chromium: str, feet: dict, t: float) -> bool:
    import subprocess

    from PIL import Image

    url = f"file://{page}#t={t:e}"
    dom = subprocess.run([chromium, "--virtual-time-budget=1000", "--dump-dom", url], capture_output=True, text=True, check=True).stdout
    canvas = re.search(r"<canvas[^>]*>", dom).group(0)
    read = lambda name: [float(x) for x in re.search(rf'{name}="([^"]*)"', canvas).group(1).split(",")]
    centre, right, up, scale, pixel = read("data-center"), read("data-right"), read("data-up"), read("data-scale")[0], read("data-pixel")
    shot = page.replace(".html", ".png")
    subprocess.run(
        [chromium, "--virtual-time-budget=1000", "--window-size=800,700", "--force-device-scale-factor=1", f"--screenshot={shot}", url],
        capture_output=True, check=True,
    )
    image = Image.open(shot).convert("RGB")
    ok = image.getpixel((20, 20)) == (255, 255, 255)
    print(f"\n3D page at t = {t} s ({shot}): the corner is {'background' if ok else 'not background'}")
    for leg in LEGS:
        p = [feet[f"{leg}_foot_{axis}"] for axis in "xyz"]
        d = [p[i] - centre[i] for i in range(3)]
        along = lambda axis: sum(axis[i] * d[i] for i in range(3))
        at = (round(pixel[0] + scale * along(right)), round(pixel[1] - scale * along(up)))
        shown = image.getpixel(at)
        drawn = shown != (255, 255, 255)
        ok &= drawn
        print(f"{leg} foot at ({p[0]:+.4f}, {p[1]:+.4f}, {p[2]:+.4f}) m, pixel {at}: {shown} {'(drawn)' if drawn else '(background!)'}")
    return ok


if __name__ == "__main__":
    main()
    if len(sys.argv) > 4:
        lines = [line.strip().split(",") for line in open(sys.argv[2])]
        feet = {quantity: float(value) for case, t, quantity, value in lines if case == "view"}
        end = max(float(t) for case, t, _, _ in lines if case == "view")
        if not view(sys.argv[3], sys.argv[4], feet, end):
            sys.exit("the 3D page does not show the robot's feet where dirac's state puts them")
