"""References for tests/integration/robots.rs, computed with Pinocchio from the same URDF file
that dirac reads (tests/robots/panda/panda.urdf), independently of dirac.

    bash tests/references/robots.sh

writes
- panda_dynamics.csv: at 20 random states (joint positions uniform within the URDF's limits,
  velocities uniform in [-2, 2], seed 38), the joint-space mass matrix (crba), the gravity
  torques (computeGeneralizedGravity) and the bias torques C(q, v) v + g(q)
  (nonLinearEffects), one state per row: q0..q8, v0..v8, M00..M88 (row-major), g0..g8, b0..b8;
- panda_swing.csv: a 1 s free swing under gravity from rest, with the URDF's joint damping
  (tau = -d v) and its mimic joint (panda_finger_joint2 = panda_finger_joint1) reduced by
  hand: with G the 9 x 8 map from the eight independent velocities, G^T M G a = -G^T (nle + D G v).
  Integrated by SciPy's DOP853 at rtol = atol = 1e-12; rows t, q0..q8, v0..v8 every 0.1 s;
- panda_frames.csv: at 10 random joint positions (uniform within the limits, seed 41), the
  pose of six links in the world (framesForwardKinematics, oMf), the root link included: per
  link its origin x, y, z and its rotation r11..r33 (row-major); rows q0..q8 and then the links'.

    python robots.py --aba ROBOT.urdf OUT.csv SEED

writes, at 20 random states (joint positions uniform within the URDF's limits, velocities
uniform in [-2, 2], torques uniform in [-5, 5]), the accelerations of Pinocchio's
articulated-body algorithm (aba) under those torques, with no damping: rows q0..q8, v0..v8,
tau0..tau8, a0..a8.

    python robots.py --floating ROBOT.urdf OUT.csv SEED

writes, for the robot with Pinocchio's free flyer as its root joint (its other joints revolute or
prismatic, each column named by its joint, in Pinocchio's depth-first order), at 10 random states (joint
positions uniform within the URDF's limits, [-pi, pi] where it has none, the base anywhere in
[-1, 1]^3 turned by a uniformly random rotation, every velocity uniform in [-2, 2]), the base's
origin x, y, z and rotation r11..r33 (row-major, oMi of the root joint), the joint positions,
the base's linear and angular velocity in its own axes (Pinocchio's free-flyer velocity), the
joint velocities, and crba, computeGeneralizedGravity and nonLinearEffects in those velocities.
"""

import sys

import numpy as np
import pinocchio as pin
from scipy.integrate import solve_ivp

# The start of the swing: the arm out to the side, fingers half open.
SWING_START = [0.3, 0.5, -0.4, -1.2, 0.2, 1.4, 0.6, 0.02, 0.02]


def main(urdf, out):
    model = pin.buildModelFromUrdf(urdf)
    data = model.createData()
    assert model.nq == model.nv == 9, (model.nq, model.nv)
    rng = np.random.default_rng(38)
    rows = []
    for _ in range(20):
        q = rng.uniform(model.lowerPositionLimit, model.upperPositionLimit)
        v = rng.uniform(-2.0, 2.0, model.nv)
        mass = pin.crba(model, data, q)
        mass = np.triu(mass) + np.triu(mass, 1).T
        gravity = pin.computeGeneralizedGravity(model, data, q).copy()
        bias = pin.nonLinearEffects(model, data, q, v).copy()
        rows.append(np.concatenate([q, v, mass.ravel(), gravity, bias]))
    header = (
        [f"q{i}" for i in range(9)]
        + [f"v{i}" for i in range(9)]
        + [f"M{i}{j}" for i in range(9) for j in range(9)]
        + [f"g{i}" for i in range(9)]
        + [f"b{i}" for i in range(9)]
    )
    np.savetxt(f"{out}/panda_dynamics.csv", np.array(rows), delimiter=",", header=",".join(header),
               comments="", fmt="%.17g")

    damping = np.diag(model.damping)
    reduce = np.zeros((9, 8))
    reduce[:8, :8] = np.eye(8)
    reduce[8, 7] = 1.0

    def rhs(_t, y):
        qr, vr = y[:8], y[8:]
        q, v = reduce @ qr, reduce @ vr
        mass = pin.crba(model, data, q)
        mass = np.triu(mass) + np.triu(mass, 1).T
        nle = pin.nonLinearEffects(model, data, q, v)
        a = np.linalg.solve(reduce.T @ mass @ reduce, -reduce.T @ (nle + damping @ v))
        return np.concatenate([vr, a])

    times = np.linspace(0.0, 1.0, 11)
    start = np.concatenate([SWING_START[:8], np.zeros(8)])
    sol = solve_ivp(rhs, (0.0, 1.0), start, method="DOP853", rtol=1e-12, atol=1e-12, t_eval=times)
    assert sol.success, sol.message
    rows = [np.concatenate([[t], reduce @ y[:8], reduce @ y[8:]]) for t, y in zip(sol.t, sol.y.T)]
    header = ["t"] + [f"q{i}" for i in range(9)] + [f"v{i}" for i in range(9)]
    np.savetxt(f"{out}/panda_swing.csv", np.array(rows), delimiter=",", header=",".join(header),
               comments="", fmt="%.17g")

    frames(model, data, out)


# The links whose poses panda_frames.csv holds: the root, an arm link, the last arm link, the
# hand (fixed to it), the tool centre point (fixed, rotated) and a finger (prismatic).
FRAME_LINKS = ["panda_link0", "panda_link3", "panda_link7", "panda_hand", "panda_hand_tcp", "panda_leftfinger"]


def frames(model, data, out):
    rng = np.random.default_rng(41)
    rows = []
    for _ in range(10):
        q = rng.uniform(model.lowerPositionLimit, model.upperPositionLimit)
        pin.framesForwardKinematics(model, data, q)
        row = list(q)
        for link in FRAME_LINKS:
            pose = data.oMf[model.getFrameId(link, pin.BODY)]
            row += list(pose.translation) + list(pose.rotation.ravel())
        rows.append(row)
    header = [f"q{i}" for i in range(9)]
    for link in FRAME_LINKS:
        header += [f"{link}_{a}" for a in "xyz"] + [f"{link}_r{i}{j}" for i in range(1, 4) for j in range(1, 4)]
    np.savetxt(f"{out}/panda_frames.csv", np.array(rows), delimiter=",", header=",".join(header),
               comments="", fmt="%.17g")


def aba(urdf, out, seed):
    model = pin.buildModelFromUrdf(urdf)
    data = model.createData()
    rng = np.random.default_rng(seed)
    n = model.nv
    rows = []
    for _ in range(20):
        q = rng.uniform(model.lowerPositionLimit, model.upperPositionLimit)
        v = rng.uniform(-2.0, 2.0, n)
        tau = rng.uniform(-5.0, 5.0, n)
        a = pin.aba(model, data, q, v, tau).copy()
        rows.append(np.concatenate([q, v, tau, a]))
    header = [f"{x}{i}" for x in ("q", "v", "tau", "a") for i in range(n)]
    np.savetxt(out, np.array(rows), delimiter=",", header=",".join(header), comments="", fmt="%.17g")


def floating(urdf, out, seed):
    model = pin.buildModelFromUrdf(urdf, pin.JointModelFreeFlyer())
    data = model.createData()
    nv = model.nv
    assert model.nq == nv + 1 and all(model.joints[k].nq == 1 for k in range(2, model.njoints))
    lower = np.where(np.isfinite(model.lowerPositionLimit[7:]), model.lowerPositionLimit[7:], -np.pi)
    upper = np.where(np.isfinite(model.upperPositionLimit[7:]), model.upperPositionLimit[7:], np.pi)
    # Pinocchio reads an unlimited joint's limits as +-1.8e308.
    lower = np.maximum(lower, -np.pi)
    upper = np.minimum(upper, np.pi)
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(10):
        rotation = pin.Quaternion(rng.normal(size=4)).normalized()
        q = np.concatenate([rng.uniform(-1.0, 1.0, 3), rotation.coeffs(), rng.uniform(lower, upper)])
        v = rng.uniform(-2.0, 2.0, nv)
        pin.forwardKinematics(model, data, q)
        base = data.oMi[1]
        mass = pin.crba(model, data, q)
        mass = np.triu(mass) + np.triu(mass, 1).T
        gravity = pin.computeGeneralizedGravity(model, data, q).copy()
        bias = pin.nonLinearEffects(model, data, q, v).copy()
        rows.append(np.concatenate([base.translation, base.rotation.ravel(), q[7:], v, mass.ravel(), gravity, bias]))
    # Pinocchio orders the joints depth first: each column is named by its joint.
    names = [model.names[k] for k in range(2, model.njoints)]
    header = (
        [f"base_{a}" for a in "xyz"]
        + [f"base_r{i}{j}" for i in range(1, 4) for j in range(1, 4)]
        + names
        + [f"base_v{a}" for a in "xyz"]
        + [f"base_w{a}" for a in "xyz"]
        + [f"v_{name}" for name in names]
        + [f"M{i}_{j}" for i in range(nv) for j in range(nv)]
        + [f"g{i}" for i in range(nv)]
        + [f"b{i}" for i in range(nv)]
    )
    np.savetxt(out, np.array(rows), delimiter=",", header=",".join(header), comments="", fmt="%.17g")


if __name__ == "__main__":
    if sys.argv[1] == "--floating":
        floating(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    elif sys.argv[1] == "--aba":
        aba(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    else:
        main(sys.argv[1], sys.argv[2])
