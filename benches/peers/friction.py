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


CASES = {
    "block stops on the flat": lambda: final_x(BOX, 0.0, 0.4, 3.0, 2.0),
    "block held on a slope (mu 0.5; tan 0.3 = 0.31)": lambda: final_x(BOX, 0.3, 0.5, 0.0, 10.0),
    "block slides down a slope (mu 0.3; tan 0.5 = 0.55)": lambda: final_x(BOX, 0.5, 0.3, 0.0, 2.0),
    "ball rolls down a slope (mu 0.5)": lambda: final_x(BALL, 0.4, 0.5, 0.0, 2.0),
}


def main() -> None:
    print(f"MuJoCo {mujoco.__version__}, time step {STEP} s, elliptic cones, Newton solver, impratio {IMPRATIO}, no-slip iterations {NOSLIP}")
    print()
    print("| case | quantity | closed form | dirac | dirac − closed | MuJoCo | MuJoCo − closed |")
    print("|---|---|---:|---:|---:|---:|---:|")
    with open(sys.argv[1]) as lines:
        for line in lines:
            case, quantity, ours, closed = line.strip().rsplit(",", 3)
            ours, closed = float(ours), float(closed)
            theirs = CASES[case]()
            print(
                f"| {case} | {quantity} | {closed:.9g} | {ours:.12g} | {ours - closed:.1e} "
                f"| {theirs:.9g} | {theirs - closed:.1e} |"
            )


if __name__ == "__main__":
    main()
