"""One round of the optimal control benchmark's CasADi side (benches/peers/optimal.sh): the
same problems as benches/optimal.rs (`cartpole`, `chain8`, `acrobot`, `panda`), the same DMOC transcription (the variational
integrator's trapezoidal discrete Lagrangian, forces at the midpoint, p_0 and p_N from the
Legendre map), the same variables, bounds, starting point and IPOPT options, built with
CasADi's SX expressions and nlpsol (exact Hessian by its own algorithmic differentiation).
Prints `casadi,problem,N,cost,iterations,solve seconds,evaluation seconds,construction
seconds`: the
solve's wall time around the solver's call, the evaluation's from CasADi's own statistics
(objective, constraints and their derivatives).

With TRANSCRIPTION=collocation, the problem is transcribed as dirac's optimal::Collocation
does instead: Radau IIA with three stages on the implicit Lagrangian system, positions and
velocities at each node and stage, the stage equations on q and on the momenta dL/dv, the
running cost by Radau's weights, the inputs held over each interval."""
import os
import sys
import time

import casadi as ca

MC, MP, L, G = 1.0, 0.3, 0.5, 9.81
HORIZON, X_MAX, F_MAX = 2.0, 1.5, 20.0


CHAIN_M, CHAIN_L, LINKS = 0.2, 0.25, 8
ACRO_M, ACRO_L, ACRO_HORIZON = 1.0, 1.0, 3.0


def cart_pole(q, v):
    return (0.5 * (MC + MP) * v[0] ** 2 + MP * L * v[0] * v[1] * ca.cos(q[1])
            + 0.5 * MP * L * L * v[1] ** 2 + MP * G * L * ca.cos(q[1]))


def chain(q, v):
    """tests/zoo Pendulum8: L = 1/2 sum_ij (8 - max(i, j)) m l^2 w_i w_j cos(th_i - th_j)
    + g sum_i (8 - i) m l cos th_i, 0-based."""
    kinetic = 0
    for i in range(LINKS):
        for j in range(LINKS):
            kinetic += (LINKS - max(i, j)) * CHAIN_M * CHAIN_L ** 2 * v[i] * v[j] * ca.cos(q[i] - q[j])
    potential = sum((LINKS - i) * CHAIN_M * G * CHAIN_L * ca.cos(q[i]) for i in range(LINKS))
    return 0.5 * kinetic + potential


def acrobot(q, v):
    """tests/zoo Acrobot: two equal point-mass links, absolute angles from hanging."""
    m, l = ACRO_M, ACRO_L
    return (0.5 * 2 * m * l * l * v[0] ** 2 + 0.5 * m * l * l * v[1] ** 2
            + m * l * l * v[0] * v[1] * ca.cos(q[0] - q[1])
            + 2 * m * G * l * ca.cos(q[0]) + m * G * l * ca.cos(q[1]))


PANDA_START = [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8]
PANDA_END = [1.0, 0.2, -0.5, -1.5, 0.4, 1.6, 0.0]
# The weight of every joint's velocity in the Panda's running cost, h/2 * w * |v|^2 per
# interval as dirac's Problem::velocity_weight: without it the program has many local optima
# (from the same start, IPOPT lands in different ones for N = 10 ... 50 as the guess changes),
# with it IPOPT reaches the same optimum from a straight line or a gravity-compensating guess.
PANDA_VELOCITY_WEIGHT = 10.0
# The joints' limits and efforts of panda_arm.urdf, as benches/optimal.rs writes them; checked
# against Pinocchio's reading of the file in panda_limits().
PANDA_LOWER = [-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973]
PANDA_UPPER = [2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973]
PANDA_EFFORT = [87.0, 87.0, 87.0, 87.0, 12.0, 12.0, 12.0]


def panda_limits():
    """The position bounds and the torque bounds of each joint, from the URDF file."""
    import pinocchio as pin
    model = pin.buildModelFromUrdf("tests/robots/panda/panda_arm.urdf")
    read = [list(model.lowerPositionLimit), list(model.upperPositionLimit), list(model.effortLimit)]
    if any(abs(a - b) > 1e-12 for got, ours in zip(read, [PANDA_LOWER, PANDA_UPPER, PANDA_EFFORT])
           for a, b in zip(got, ours)):
        sys.exit(f"panda_arm.urdf's limits are {read}, the benchmark's differ")
    return list(zip(PANDA_LOWER, PANDA_UPPER)), [(-e, e) for e in PANDA_EFFORT]


def panda_lagrangian():
    """The Panda arm of tests/robots/panda/panda_arm.urdf (tests/zoo PandaTorques): its
    kinematic tree, masses, centres and inertias as Pinocchio reads them from the file (numbers
    only), its Lagrangian T - V written here in SX: each joint frame is its parent's times the
    joint's placement times a rotation about z by its angle; a body's centre velocity is the
    Jacobian of its position times v, its angular velocity the sum of the world axes times the
    joint rates. Checked against Pinocchio's energies at a random state before use."""
    import numpy as np
    import pinocchio as pin

    model = pin.buildModelFromUrdf("tests/robots/panda/panda_arm.urdf")

    def lagrangian(q, v):
        rotations, positions, omegas = [ca.SX.eye(3)], [ca.SX.zeros(3)], [ca.SX.zeros(3)]
        kinetic, potential = 0, 0
        for i in range(1, model.njoints):
            parent = model.parents[i]
            placement = model.jointPlacements[i]
            r_parent, p_parent = rotations[parent], positions[parent]
            c, s = ca.cos(q[i - 1]), ca.sin(q[i - 1])
            rz = ca.vertcat(ca.horzcat(c, -s, 0), ca.horzcat(s, c, 0), ca.horzcat(0, 0, 1))
            rotation = r_parent @ ca.DM(placement.rotation) @ rz
            position = p_parent + r_parent @ ca.DM(placement.translation)
            omega = omegas[parent] + rotation[:, 2] * v[i - 1]
            rotations.append(rotation)
            positions.append(position)
            omegas.append(omega)
            inertia = model.inertias[i]
            centre = position + rotation @ ca.DM(inertia.lever)
            velocity = ca.jacobian(centre, q) @ v
            body = rotation.T @ omega
            kinetic += 0.5 * inertia.mass * ca.dot(velocity, velocity)
            kinetic += 0.5 * ca.dot(body, ca.DM(inertia.inertia) @ body)
            potential += inertia.mass * G * centre[2]
        return kinetic - potential

    # The check: T and V against Pinocchio's at a random state (an independent implementation).
    qs, vs = ca.SX.sym("q", 7), ca.SX.sym("v", 7)
    energy = ca.Function("energy", [qs, vs], [lagrangian(qs, vs)])
    rng = np.random.default_rng(3)
    q, v = rng.uniform(-1, 1, 7), rng.uniform(-1, 1, 7)
    data = model.createData()
    expected = pin.computeKineticEnergy(model, data, q, v) - pin.computePotentialEnergy(model, data, q)
    got = float(energy(q, v))
    if abs(got - expected) > 1e-10 * max(1.0, abs(expected)):
        sys.exit(f"the Panda's Lagrangian is {got}, Pinocchio's {expected}")
    return lagrangian


def problem(name):
    """The Lagrangian, the forces of the inputs, the sizes, the bounds and the targets."""
    if name == "cartpole":
        force = lambda u: ca.vertcat(u, 0)
        return cart_pole, force, 2, 1, [(-X_MAX, X_MAX), (-ca.inf, ca.inf)], (-F_MAX, F_MAX), [0.0, ca.pi]
    if name == "panda":
        force = lambda u: u
        positions, torques = panda_limits()
        return panda_lagrangian(), force, 7, 7, positions, torques, PANDA_END
    if name == "acrobot":
        force = lambda u: ca.vertcat(-u, u)
        return acrobot, force, 2, 1, [(-ca.inf, ca.inf)] * 2, (-ca.inf, ca.inf), [ca.pi, ca.pi]
    force = lambda u: ca.vertcat(*[u[i] - u[i + 1] for i in range(LINKS - 1)], u[LINKS - 1])
    return chain, force, LINKS, LINKS, [(-ca.inf, ca.inf)] * LINKS, (-ca.inf, ca.inf), [0.5] * LINKS


def damping(name, dof):
    """The joints' viscous damping (the URDF's `<dynamics damping>`, as Pinocchio reads it; dirac
    makes it a Rayleigh dissipation), zero for the hand-written models."""
    if name != "panda":
        return [0.0] * dof
    import pinocchio as pin
    return list(pin.buildModelFromUrdf("tests/robots/panda/panda_arm.urdf").damping)


def build(name, n):
    h = (ACRO_HORIZON if name == "acrobot" else HORIZON) / n
    lagrangian, input_force, dof, nu, position_bounds, input_bounds, target = problem(name)
    origin = PANDA_START if name == "panda" else [0.0] * dof
    friction = damping(name, dof)
    smoothing = PANDA_VELOCITY_WEIGHT if name == "panda" else 0.0
    q, v = ca.SX.sym("q", dof), ca.SX.sym("v", dof)
    lag = lagrangian(q, v)
    lq = ca.Function("lq", [q, v], [ca.gradient(lag, q)])
    lv = ca.Function("lv", [q, v], [ca.gradient(lag, v)])
    nodes = [ca.SX.sym(f"q{k}", dof) for k in range(n + 1)]
    pushes = [ca.SX.sym(f"u{k}", nu) for k in range(n)]
    zero = ca.DM.zeros(dof)
    equations, cost = [], 0
    d2_before = None
    for k in range(n):
        a, b, u = nodes[k], nodes[k + 1], pushes[k]
        vel = (b - a) / h
        p = 0.5 * (lv(a, vel) + lv(b, vel))
        force = input_force(u) - ca.DM(friction) * vel
        d1 = 0.5 * h * lq(a, vel) - p + 0.5 * h * force
        d2 = 0.5 * h * lq(b, vel) + p + 0.5 * h * force
        start = lv(ca.DM(origin), zero) if k == 0 else d2_before
        equations.append(start + d1)
        d2_before = d2
        cost += 0.5 * h * ca.sumsqr(u) + 0.5 * h * smoothing * ca.sumsqr(vel)
    equations.append(d2_before - lv(nodes[n], zero))
    x = ca.vertcat(*nodes, *pushes)
    # One bound for every input, or one per input.
    per_input = input_bounds if isinstance(input_bounds, list) else [input_bounds] * nu
    lower = [b[0] for b in position_bounds] * (n + 1) + [b[0] for b in per_input] * n
    upper = [b[1] for b in position_bounds] * (n + 1) + [b[1] for b in per_input] * n
    lower[0:dof] = upper[0:dof] = origin
    lower[dof * n:dof * (n + 1)] = upper[dof * n:dof * (n + 1)] = target
    guess = []
    for k in range(n + 1):
        guess += [o + (t - o) * k / n for o, t in zip(origin, target)]
    guess += [0.0] * (nu * n)
    options = {"ipopt": {"print_level": 0, "sb": "yes", "tol": 1e-8}, "print_time": False}
    solver = ca.nlpsol("dmoc", "ipopt", {"x": x, "f": cost, "g": ca.vertcat(*equations)}, options)
    return solver, guess, lower, upper


# Radau IIA's three-stage tableau (Hairer and Wanner, Table IV.5.6).
SQ6 = 6 ** 0.5
RADAU_C = [0.0, (4 - SQ6) / 10, (4 + SQ6) / 10, 1.0]
RADAU_A = [[(88 - 7 * SQ6) / 360, (296 - 169 * SQ6) / 1800, (-2 + 3 * SQ6) / 225],
           [(296 + 169 * SQ6) / 1800, (88 + 7 * SQ6) / 360, (-2 - 3 * SQ6) / 225],
           [(16 - SQ6) / 36, (16 + SQ6) / 36, 1 / 9]]


def build_collocation(name, n):
    """dirac's optimal::Collocation of the same problem: variables the points (q, v), P = 0 ..
    3N (point 3k is node k), then the inputs; rows, per stage i of interval k,
    q_i - q_0 - h sum_j a_ij v_j and p(X_i) - p(X_0) - h sum_j a_ij [L_q + F](X_j, u_k)."""
    h = (ACRO_HORIZON if name == "acrobot" else HORIZON) / n
    lagrangian, input_force, dof, nu, position_bounds, input_bounds, target = problem(name)
    origin = PANDA_START if name == "panda" else [0.0] * dof
    friction = damping(name, dof)
    smoothing = PANDA_VELOCITY_WEIGHT if name == "panda" else 0.0
    q, v = ca.SX.sym("q", dof), ca.SX.sym("v", dof)
    lag = lagrangian(q, v)
    lq = ca.Function("lq", [q, v], [ca.gradient(lag, q)])
    lv = ca.Function("lv", [q, v], [ca.gradient(lag, v)])
    points = [(ca.SX.sym(f"q{p}", dof), ca.SX.sym(f"v{p}", dof)) for p in range(3 * n + 1)]
    pushes = [ca.SX.sym(f"u{k}", nu) for k in range(n)]
    equations, cost = [], 0
    for k in range(n):
        u = pushes[k]
        x = points[3 * k:3 * k + 4]
        momenta = [lv(qj, vj) for qj, vj in x]
        rates = [lq(qj, vj) + input_force(u) - ca.DM(friction) * vj for qj, vj in x]
        for i in range(3):
            velocity = x[i + 1][0] - x[0][0] - h * sum(RADAU_A[i][j - 1] * x[j][1] for j in range(1, 4))
            momentum = momenta[i + 1] - momenta[0] - h * sum(RADAU_A[i][j - 1] * rates[j] for j in range(1, 4))
            equations += [velocity, momentum]
        for j in range(1, 4):
            cost += 0.5 * h * RADAU_A[2][j - 1] * smoothing * ca.sumsqr(x[j][1])
        cost += 0.5 * h * ca.sumsqr(u)
    variables = ca.vertcat(*[ca.vertcat(qp, vp) for qp, vp in points], *pushes)
    per_input = input_bounds if isinstance(input_bounds, list) else [input_bounds] * nu
    free = [(-ca.inf, ca.inf)] * dof
    lower, upper = [], []
    for p in range(3 * n + 1):
        bounds = [(o, o) for o in origin] if p == 0 else [(t, t) for t in target] if p == 3 * n else position_bounds
        velocities = [(0.0, 0.0)] * dof if p in (0, 3 * n) else free
        lower += [b[0] for b in bounds + velocities]
        upper += [b[1] for b in bounds + velocities]
    lower += [b[0] for b in per_input] * n
    upper += [b[1] for b in per_input] * n
    # The guess as Collocation::guess: straight lines through the stages, each interval's mean
    # velocity at its points, the start's and the end's velocities given.
    guess = []
    nodes = [[o + (t - o) * k / n for o, t in zip(origin, target)] for k in range(n + 1)]
    for p in range(3 * n + 1):
        k, j = min(p // 3, n - 1), p - 3 * min(p // 3, n - 1)
        a, b = nodes[k], nodes[k + 1]
        position = [ai + RADAU_C[j] * (bi - ai) for ai, bi in zip(a, b)]
        velocity = [0.0] * dof if p in (0, 3 * n) else [(bi - ai) / h for ai, bi in zip(a, b)]
        guess += position + velocity
    guess += [0.0] * (nu * n)
    options = {"ipopt": {"print_level": 0, "sb": "yes", "tol": 1e-8}, "print_time": False}
    solver = ca.nlpsol("radau", "ipopt", {"x": variables, "f": cost, "g": ca.vertcat(*equations)}, options)
    return solver, guess, lower, upper


def main():
    names = [a for a in sys.argv[1:] if not a.isdigit()]
    name = names[0] if names else "cartpole"
    collocated = os.environ.get("TRANSCRIPTION") == "collocation"
    for n in [int(a) for a in sys.argv[1:] if a.isdigit()] or [50, 100]:
        started = time.perf_counter()
        solver, guess, lower, upper = (build_collocation if collocated else build)(name, n)
        construction = time.perf_counter() - started
        started = time.perf_counter()
        result = solver(x0=guess, lbx=lower, ubx=upper, lbg=0, ubg=0)
        solve = time.perf_counter() - started
        stats = solver.stats()
        if not stats["success"]:
            sys.exit(f"N = {n}: {stats['return_status']}")
        evaluation = sum(stats[f"t_wall_nlp_{part}"] for part in ["f", "g", "grad_f", "jac_g", "hess_l"])
        print(f"casadi,{name},{n},{float(result['f']):.12e},{stats['iter_count']},{solve:.6e},"
              f"{evaluation:.6e},{construction:.6e}")


if __name__ == "__main__":
    main()
