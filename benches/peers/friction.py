"""The cases of examples/contact_friction.rs in MuJoCo, beside dirac's results and the closed forms.

Reads dirac's lines (`case,quantity,dirac,closed form`) from the file given, runs each case in
MuJoCo (a box or a sphere on a plane, the slope made by tilting gravity by the slope's angle,
elliptic friction cones, the Newton solver, time step 1e-4 s) and prints one table with both
differences from the closed form. MuJoCo at its best for friction, as its documentation
advises against slip: `impratio` 10 and 10 iterations of its no-slip solver (with its defaults,
1 and 0, the held block creeps 7.6 mm in 10 s instead of 0.03 mm).

    python friction.py DIRAC_LINES
"""

import math
import sys

import mujoco
import numpy as np

G = 9.81
STEP = 1e-4
IMPRATIO = 10
NOSLIP = 10


def model(body: str, slope: float, mu: float) -> mujoco.MjModel:
    """A free body on the plane z = 0 under gravity tilted by `slope` about y (downhill is +x)."""
    gravity = f"{G * math.sin(slope)} 0 {-G * math.cos(slope)}"
    return mujoco.MjModel.from_xml_string(
        f"""
<mujoco>
  <option timestep="{STEP}" gravity="{gravity}" cone="elliptic" impratio="{IMPRATIO}" noslip_iterations="{NOSLIP}" solver="Newton" integrator="implicitfast"/>
  <worldbody>
    <geom name="floor" type="plane" size="50 50 0.1" friction="{mu} 0 0"/>
    <body name="thing" pos="0 0 0.1">
      <freejoint/>
      {body.format(mu=mu)}
    </body>
  </worldbody>
</mujoco>"""
    )


BOX = '<geom type="box" size="0.1 0.1 0.1" mass="2" condim="3" friction="{mu} 0 0"/>'
BALL = '<geom type="sphere" size="0.1" mass="1.5" condim="3" friction="{mu} 0 0"/>'


def final_x(body: str, slope: float, mu: float, vx0: float, t_end: float) -> float:
    """The body's x after `t_end` from rest on the plane (settled first) with velocity `vx0`."""
    m = model(body, slope, mu)
    d = mujoco.MjData(m)
    # Let the contact settle into its own penetration, held in place, before the run.
    for _ in range(2000):
        mujoco.mj_step(m, d)
        d.qvel[:] = 0.0
        d.qpos[0:2] = 0.0
    d.qvel[0] = vx0
    d.time = 0.0
    while d.time < t_end - 0.5 * STEP:
        mujoco.mj_step(m, d)
    return float(d.qpos[0])


def puck_stop(coordinate: int) -> float:
    """A 2 kg box thrown at 3 m/s along x with the side force k mu m g along y (k = 0.5,
    mu = 0.4): its x or y after 1.5 s, stopped."""
    mu, mass, k = 0.4, 2.0, 0.5
    m = model(BOX, 0.0, mu)
    d = mujoco.MjData(m)
    for _ in range(2000):
        mujoco.mj_step(m, d)
        d.qvel[:] = 0.0
        d.qpos[0:2] = 0.0
    d.qvel[0] = 3.0
    d.time = 0.0
    d.xfrc_applied[1, 1] = k * mu * mass * G
    while d.time < 1.5 - 0.5 * STEP:
        mujoco.mj_step(m, d)
    return float(d.qpos[coordinate])


def top(quantity: str) -> float:
    """The top of examples/contact_friction.rs: 0.5 kg, moments 1.5e-4 across its axis and 2e-4
    about it at its centre, a ball tip of 2 mm whose centre is 4 cm below the centre, tilted
    0.3 rad about x, spinning at 200 rad/s about its axis, its centre thrown at 0.3 m/s along x.
    `holds`: the first time in 0.5 s that the point that touches slips slower than 1 mm/s
    (NaN if never); `x` and `tilt`: the centre's x and the tilt after 0.05 s."""
    l, r, theta = 0.04, 0.002, 0.3
    m = mujoco.MjModel.from_xml_string(
        f"""
<mujoco>
  <option timestep="{STEP}" gravity="0 0 {-G}" cone="elliptic" impratio="{IMPRATIO}" noslip_iterations="{NOSLIP}" solver="Newton" integrator="implicitfast"/>
  <worldbody>
    <geom type="plane" size="50 50 0.1" friction="0.3 0 0"/>
    <body name="top">
      <freejoint/>
      <inertial pos="0 0 0" mass="0.5" diaginertia="1.5e-4 1.5e-4 2e-4"/>
      <geom name="tip" type="sphere" pos="0 0 {-l}" size="{r}" condim="3" friction="0.3 0 0"/>
    </body>
  </worldbody>
</mujoco>"""
    )
    d = mujoco.MjData(m)
    d.qpos[:] = [0.0, 0.0, l * math.cos(theta) + r, math.cos(theta / 2), math.sin(theta / 2), 0.0, 0.0]
    d.qvel[:] = [0.3, 0.0, 0.0, 0.0, 0.0, 200.0]
    tip = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "tip")
    velocity = np.zeros(6)
    holds, early = math.nan, None
    while d.time < 0.5 - 0.5 * STEP:
        mujoco.mj_step(m, d)
        if early is None and d.time >= 0.05 - 0.5 * STEP:
            early = (float(d.qpos[0]), math.acos(d.xmat[1].reshape(3, 3)[2, 2]))
        if math.isnan(holds):
            # The tip's centre (angular, linear) in the world, then the point r below it.
            mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_GEOM, tip, velocity, 0)
            w, v = velocity[:3], velocity[3:]
            slip = (v[0] - r * w[1], v[1] + r * w[0])
            if math.hypot(*slip) < 1e-3:
                holds = d.time
    return {"holds": holds, "x": early[0], "tilt": early[1]}[quantity]


CASES = {
    "block stops on the flat": lambda: final_x(BOX, 0.0, 0.4, 3.0, 2.0),
    "block held on a slope (mu 0.5; tan 0.3 = 0.31)": lambda: final_x(BOX, 0.3, 0.5, 0.0, 10.0),
    "block slides down a slope (mu 0.3; tan 0.5 = 0.55)": lambda: final_x(BOX, 0.5, 0.3, 0.0, 2.0),
    "ball rolls down a slope (mu 0.5)": lambda: final_x(BALL, 0.4, 0.5, 0.0, 2.0),
    ("puck thrown with a side force (cone; mu 0.4; k 0.5)", "stop x [m]"): lambda: puck_stop(0),
    ("puck thrown with a side force (cone; mu 0.4; k 0.5)", "stop y [m]"): lambda: puck_stop(1),
    ("top on a round tip (r 2 mm; mu 0.3; 200 rad/s)", "time its tip holds [s]"): lambda: top("holds"),
    ("top on a round tip (r 2 mm; mu 0.3; 200 rad/s)", "centre x after 0.05 s [m]"): lambda: top("x"),
    ("top on a round tip (r 2 mm; mu 0.3; 200 rad/s)", "tilt after 0.05 s [rad]"): lambda: top("tilt"),
}


def main() -> None:
    print(f"MuJoCo {mujoco.__version__}, time step {STEP} s, elliptic cones, Newton solver, impratio {IMPRATIO}, no-slip iterations {NOSLIP}")
    print()
    print("| case | quantity | closed form | dirac | dirac − closed | MuJoCo | MuJoCo − closed (− dirac) |")
    print("|---|---|---:|---:|---:|---:|---:|")
    with open(sys.argv[1]) as lines:
        for line in lines:
            case, quantity, ours, closed = line.strip().rsplit(",", 3)
            ours, closed = float(ours), float(closed)
            theirs = (CASES.get((case, quantity)) or CASES[case])()
            if math.isnan(closed):
                # No closed form: MuJoCo beside dirac.
                print(f"| {case} | {quantity} | — | {ours:.12g} | — | {theirs:.9g} | ({theirs - ours:.1e}) |")
                continue
            print(
                f"| {case} | {quantity} | {closed:.9g} | {ours:.12g} | {ours - closed:.1e} "
                f"| {theirs:.9g} | {theirs - closed:.1e} |"
            )


if __name__ == "__main__":
    main()
