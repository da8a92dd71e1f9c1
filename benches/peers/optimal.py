"""One round of the optimal control benchmark's CasADi side (benches/peers/optimal.sh): the
same cart-pole swing-up as benches/optimal.rs, the same DMOC transcription (the variational
integrator's trapezoidal discrete Lagrangian, forces at the midpoint, p_0 and p_N from the
Legendre map), the same variables, bounds, starting point and IPOPT options, built with
CasADi's SX expressions and nlpsol (exact Hessian by its own algorithmic differentiation).
Prints `casadi,N,cost,iterations,solve seconds,evaluation seconds,construction seconds`: the
solve's wall time around the solver's call, the evaluation's from CasADi's own statistics
(objective, constraints and their derivatives)."""
import sys
import time

import casadi as ca

MC, MP, L, G = 1.0, 0.3, 0.5, 9.81
HORIZON, X_MAX, F_MAX = 2.0, 1.5, 20.0


def lagrangian(q, v):
    return (0.5 * (MC + MP) * v[0] ** 2 + MP * L * v[0] * v[1] * ca.cos(q[1])
            + 0.5 * MP * L * L * v[1] ** 2 + MP * G * L * ca.cos(q[1]))


def build(n):
    h = HORIZON / n
    q, v = ca.SX.sym("q", 2), ca.SX.sym("v", 2)
    lag = lagrangian(q, v)
    lq = ca.Function("lq", [q, v], [ca.gradient(lag, q)])
    lv = ca.Function("lv", [q, v], [ca.gradient(lag, v)])
    nodes = [ca.SX.sym(f"q{k}", 2) for k in range(n + 1)]
    pushes = [ca.SX.sym(f"u{k}", 1) for k in range(n)]
    equations, cost = [], 0
    d2_before = None
    for k in range(n):
        a, b, u = nodes[k], nodes[k + 1], pushes[k]
        vel = (b - a) / h
        p = 0.5 * (lv(a, vel) + lv(b, vel))
        force = ca.vertcat(u, 0)
        d1 = 0.5 * h * lq(a, vel) - p + 0.5 * h * force
        d2 = 0.5 * h * lq(b, vel) + p + 0.5 * h * force
        start = lv(ca.DM([0, 0]), ca.DM([0, 0])) if k == 0 else d2_before
        equations.append(start + d1)
        d2_before = d2
        cost += 0.5 * h * u ** 2
    equations.append(d2_before - lv(nodes[n], ca.DM([0, 0])))
    x = ca.vertcat(*nodes, *pushes)
    lower = [-X_MAX, -ca.inf] * (n + 1) + [-F_MAX] * n
    upper = [X_MAX, ca.inf] * (n + 1) + [F_MAX] * n
    lower[0:2] = upper[0:2] = [0.0, 0.0]
    lower[2 * n:2 * n + 2] = upper[2 * n:2 * n + 2] = [0.0, ca.pi]
    guess = []
    for k in range(n + 1):
        guess += [0.0, ca.pi * k / n]
    guess += [0.0] * n
    options = {"ipopt": {"print_level": 0, "sb": "yes", "tol": 1e-8}, "print_time": False}
    solver = ca.nlpsol("dmoc", "ipopt", {"x": x, "f": cost, "g": ca.vertcat(*equations)}, options)
    return solver, guess, lower, upper


def main():
    for n in [int(a) for a in sys.argv[1:]] or [50, 100]:
        started = time.perf_counter()
        solver, guess, lower, upper = build(n)
        construction = time.perf_counter() - started
        started = time.perf_counter()
        result = solver(x0=guess, lbx=lower, ubx=upper, lbg=0, ubg=0)
        solve = time.perf_counter() - started
        stats = solver.stats()
        if not stats["success"]:
            sys.exit(f"N = {n}: {stats['return_status']}")
        evaluation = sum(stats[f"t_wall_nlp_{part}"] for part in ["f", "g", "grad_f", "jac_g", "hess_l"])
        print(f"casadi,{n},{float(result['f']):.12e},{stats['iter_count']},{solve:.6e},"
              f"{evaluation:.6e},{construction:.6e}")


if __name__ == "__main__":
    main()
