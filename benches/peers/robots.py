"""The peers' side of benches/peers/robots.sh.

    robots.py setup URDF DIR    the reference swing (DIR/arm_swing.csv) and Pinocchio's model
                                for the C++ driver (DIR/panda_arm.bin)
    robots.py mujoco URDF DIR [ROUND]
                                MuJoCo's swing over a range of time steps (DIR/mujoco_ROUND.csv)
    robots.py compare URDF DIR [ROUNDS]
                                the ratios, from the files the other steps wrote: each round's
                                ratio from that round's pair of runs, then the median and the
                                range over the rounds

The swing starts from rest at the configuration SWING_START of tests/zoo/robots.rs and lasts
1 s under gravity (0, 0, -9.81) with the URDF's joint damping. The reference is Pinocchio's
forward dynamics (ABA, tau = -damping * v) integrated by SciPy's DOP853 at rtol = atol = 1e-12,
sampled every 0.1 s; an error is the largest joint-angle error over those samples. The free
swing leaves the joint limits (setup prints by how much): MuJoCo runs with its limits disabled,
as dirac's model of the arm has none.
"""

import csv
import math
import re
import statistics
import sys
import time

import numpy as np

SWING_START = [0.3, 0.5, -0.4, -1.2, 0.2, 1.4, 0.6]
SAMPLES = np.linspace(0.0, 1.0, 11)


def setup(urdf, out):
    import pinocchio as pin
    from scipy.integrate import solve_ivp

    model = pin.buildModelFromUrdf(urdf)
    data = model.createData()
    model.saveToBinary(f"{out}/panda_arm.bin")
    damping = np.array(model.damping)

    def rhs(_t, y):
        q, v = y[: model.nq], y[model.nq:]
        return np.concatenate([v, pin.aba(model, data, q, v, -damping * v)])

    start = np.concatenate([SWING_START, np.zeros(model.nv)])
    sol = solve_ivp(rhs, (0.0, 1.0), start, method="DOP853", rtol=1e-12, atol=1e-12, t_eval=SAMPLES)
    assert sol.success, sol.message
    lower, upper = model.lowerPositionLimit, model.upperPositionLimit
    inside = np.all((sol.y[:7].T >= lower) & (sol.y[:7].T <= upper))
    print(f"reference swing: {sol.nfev} evaluations; within the joint limits throughout: {inside}")
    for j in range(7):
        lo, hi = float(np.min(sol.y[j])), float(np.max(sol.y[j]))
        if lo < lower[j] or hi > upper[j]:
            print(f"  joint {j + 1} spans [{lo:.2f}, {hi:.2f}] rad against its limits [{lower[j]:.2f}, {upper[j]:.2f}]")
    with open(f"{out}/arm_swing.csv", "w") as f:
        f.write(",".join(["t"] + [f"q{i}" for i in range(7)] + [f"v{i}" for i in range(7)]) + "\n")
        for t, y in zip(sol.t, sol.y.T):
            f.write(",".join(repr(float(x)) for x in [t, *y]) + "\n")


def reference(out):
    rows = np.loadtxt(f"{out}/arm_swing.csv", delimiter=",", skiprows=1)
    return rows[:, 1:8]


def mujoco_model(urdf, out):
    """The URDF without its visual and collision elements (MuJoCo would load their meshes),
    static links fused as MuJoCo's URDF import does by default, joint limits disabled (the
    free swing leaves them, and dirac's model has none)."""
    import mujoco

    text = open(urdf).read()
    text = re.sub(r"<(visual|collision)>.*?</\1>", "", text, flags=re.S)
    path = f"{out}/panda_arm_mujoco.urdf"
    open(path, "w").write(text)
    model = mujoco.MjModel.from_xml_path(path)
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_LIMIT
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    assert model.nq == 7, model.nq
    return model


def run_mujoco(out_dir, urdf, round_="1"):
    import mujoco

    model = mujoco_model(urdf, out_dir)
    print(f"MuJoCo {mujoco.__version__}: nq = {model.nq}, damping {list(model.dof_damping)}, "
          f"gravity {list(model.opt.gravity)}")
    ref = reference(out_dir)
    integrators = {
        "mujoco_euler": mujoco.mjtIntegrator.mjINT_EULER,
        "mujoco_rk4": mujoco.mjtIntegrator.mjINT_RK4,
        "mujoco_implicitfast": mujoco.mjtIntegrator.mjINT_IMPLICITFAST,
    }
    rows = []
    for name, integrator in integrators.items():
        model.opt.integrator = integrator
        for dt in [2e-3, 1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5, 1e-5]:
            model.opt.timestep = dt
            per_sample = round(0.1 / dt)
            data = mujoco.MjData(model)
            times, error = [], 0.0
            for _ in range(5):
                mujoco.mj_resetData(model, data)
                data.qpos[:] = SWING_START
                data.qvel[:] = 0.0
                mujoco.mj_forward(model, data)
                error, clock = 0.0, 0.0
                for k in range(1, 11):
                    start = time.perf_counter()
                    mujoco.mj_step(model, data, nstep=per_sample)
                    clock += time.perf_counter() - start
                    q = np.array(data.qpos)
                    error = max(error, float(np.max(np.abs(q - ref[k]))) if np.all(np.isfinite(q)) else math.inf)
                times.append(clock)
            rows.append((name, dt, error, statistics.median(times), 10 * per_sample))
            print(f"{name:20} dt {dt:8.0e}: error {error:9.2e}, {statistics.median(times):9.3e} s")
    with open(f"{out_dir}/mujoco_{round_}.csv", "w") as f:
        f.write("problem,tol,error,seconds,steps\n")
        for name, dt, error, seconds, steps in rows:
            f.write(f"{name},{dt},{error},{seconds},{steps}\n")


def load(path):
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            out.setdefault(r["problem"], []).append((float(r["error"]), float(r["seconds"]), float(r["tol"])))
    return out


def time_at(curve, error):
    """The time at `error` on a work-precision curve, interpolated in log-log space; below the
    curve's largest error only. Above it, the time of the point with the largest error, marked
    as an upper bound (that point reaches a smaller error)."""
    pts = sorted((e, s) for e, s, _ in curve if 0 < e < math.inf)
    if not pts or error < pts[0][0]:
        return None, ""
    if error >= pts[-1][0]:
        return min(s for e, s in pts), "<="
    for (e1, s1), (e2, s2) in zip(pts, pts[1:]):
        if e1 <= error <= e2:
            w = (math.log(error) - math.log(e1)) / (math.log(e2) - math.log(e1))
            # Work-precision curves are not always monotone: take the cheapest point at this
            # error or better.
            interpolated = math.exp(math.log(s1) + w * (math.log(s2) - math.log(s1)))
            better = [s for e, s in pts if e <= error]
            return min([interpolated] + better), ""
    return None, ""


def spread(values):
    """`median [low–high]` of per-round values."""
    return f"{statistics.median(values):.2f} [{min(values):.2f}–{max(values):.2f}]"


def compare(out, rounds):
    def per_round(prefix):
        values = {}
        for round_ in range(1, rounds + 1):
            with open(f"{out}/{prefix}_{round_}.csv") as f:
                for line in f:
                    name, value = line.strip().split(",")
                    values.setdefault(name, []).append(float(value))
        return values

    pin_r, dirac_r = per_round("pinocchio"), per_round("dirac")
    pin_t = {k: statistics.median(v) for k, v in pin_r.items()}
    dirac_t = {k: statistics.median(v) for k, v in dirac_r.items()}
    print(f"\nOne evaluation, seconds per call (medians of {rounds} alternated rounds, each a median of "
          "15 batches); ratios per round, median [range]:")
    for k, v in pin_t.items():
        if k != "nv":
            print(f"  Pinocchio {k:28} {v:9.3e}  rounds {' '.join(f'{x:.3e}' for x in pin_r[k])}")
    for k, v in dirac_t.items():
        print(f"  dirac     {k:28} {v:9.3e}  rounds {' '.join(f'{x:.3e}' for x in dirac_r[k])}")

    def ratio(mine, theirs):
        return spread([a / b for a, b in zip(dirac_r[mine], pin_r[theirs])])

    # computeABADerivatives returns the accelerations (data.ddq) with their derivatives: it is
    # everything an implicit step asks of Pinocchio, so it alone is the baseline.
    for k in ("residual_and_jacobian", "residual_and_jacobian_blocks"):
        print(f"  ratio dirac {k} / Pinocchio computeABADerivatives: {ratio(k, 'aba_derivatives')}")
    print(f"  ratio dirac mass_matrix / Pinocchio CRBA: {ratio('mass_matrix', 'crba')}")
    print(f"  ratio dirac bias_torques / Pinocchio nonLinearEffects: {ratio('bias_torques', 'nonlinear_effects')}")
    print(f"  ratio dirac forward_dynamics / Pinocchio ABA: {ratio('forward_dynamics', 'aba')}")

    dirac = [load(f"{out}/dirac_swing_{r}.csv") for r in range(1, rounds + 1)]
    mujoco = [load(f"{out}/mujoco_{r}.csv") for r in range(1, rounds + 1)]
    print(f"\nThe 1 s swing at equal achieved error (dirac's time at MuJoCo's error, interpolated on the "
          f"same round's curve; times the median of {rounds} alternated rounds, ratios per round, "
          "median [range]):")
    print(f"  {'MuJoCo':20} {'dt':>7} {'error':>9} {'MuJoCo s':>10} | "
          f"{'Explicit s':>11} {'ratio':>18} | {'Radau s':>11} {'ratio':>18}")
    for name, points in mujoco[0].items():
        for i, (error, _, dt) in enumerate(points):
            theirs = [m[name][i][1] for m in mujoco]
            cells = []
            for method in ("explicit", "radau"):
                mine = [time_at(d[method], error) for d in dirac]
                if any(t is None for t, _ in mine):
                    best = min(e for e, _, _ in dirac[0][method])
                    cells.append(f"{'n/a':>11} {f'(best {best:.1e})':>18}")
                    continue
                mark = mine[0][1]
                ratios = [t / s for (t, _), s in zip(mine, theirs)]
                cells.append(f"{mark:>2}{statistics.median(t for t, _ in mine):9.3e} {spread(ratios):>18}")
            print(f"  {name:20} {dt:7.0e} {error:9.2e} {statistics.median(theirs):10.3e} | {cells[0]} | {cells[1]}")
    print("\ndirac's own curve (the first round's errors and steps, the median time):")
    for method, points in dirac[0].items():
        for i, (error, _, tol) in enumerate(points):
            seconds = statistics.median(d[method][i][1] for d in dirac)
            print(f"  {method:9} tol {tol:7.0e}: error {error:9.2e} in {seconds:9.3e} s")


if __name__ == "__main__":
    command, urdf, out = sys.argv[1:4]
    extra = sys.argv[4] if len(sys.argv) > 4 else None
    if command == "setup":
        setup(urdf, out)
    elif command == "mujoco":
        run_mujoco(out, urdf, extra or "1")
    elif command == "compare":
        compare(out, int(extra or 3))
