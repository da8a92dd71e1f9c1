"""Builds the kernel benchmark's models in CasADi (SX), generates C for their flat residual and
sparse Jacobian, and writes one C file per model into the folder given as argument.

The formulas are those of benches/kernels.rs: y = (q, v, p, lambda),
f = (v, p - dL/dv, dL/dq + A^T lambda, A v)."""
import sys

import casadi as ca

out = sys.argv[1]


def flat(q, v, p, lam, dl_dq, dl_dv, rows):
    n = q.shape[0]
    at_lam = ca.SX.zeros(n, 1)
    av = []
    for k, row in enumerate(rows):
        at_lam += row.T * lam[k]
        av.append(ca.mtimes(row, v))
    parts = [v, p - dl_dv, dl_dq + at_lam] + av
    return ca.vertcat(*parts)


def model_chain():
    m, k = [1.0, 2.0, 3.0], [4.0, 5.0, 6.0]
    y = ca.SX.sym("y", 9)
    q, v, p = y[0:3], y[3:6], y[6:9]
    lag = 0.5 * sum(m[i] * v[i] ** 2 for i in range(3)) - 0.5 * (
        k[0] * q[0] ** 2 + k[1] * (q[1] - q[0]) ** 2 + k[2] * (q[2] - q[1]) ** 2)
    return y, flat(q, v, p, [], ca.gradient(lag, q), ca.gradient(lag, v), [])


def model_pendulum8():
    mass, length, g = 0.5, 0.25, 9.81
    y = ca.SX.sym("y", 24)
    th, w, p = y[0:8], y[8:16], y[16:24]
    lag = 0
    for i in range(8):
        for j in range(8):
            lag += 0.5 * (8 - max(i, j)) * mass * length * length * w[i] * w[j] * ca.cos(th[i] - th[j])
        lag += (8 - i) * mass * g * length * ca.cos(th[i])
    return y, flat(th, w, p, [], ca.gradient(lag, th), ca.gradient(lag, w), [])


def model_cartesian(links):
    mass, g, length = 1.0, 9.81, 1.0
    n = 2 * links
    y = ca.SX.sym("y", 3 * n + links)
    q, v, p, lam = y[0:n], y[n:2 * n], y[2 * n:3 * n], y[3 * n:]
    lag = 0.5 * mass * ca.sumsqr(v) - mass * g * sum(q[2 * i + 1] for i in range(links))
    rows = []
    for k in range(links):
        dx = q[2 * k] - (q[2 * k - 2] if k else 0)
        dy = q[2 * k + 1] - (q[2 * k - 1] if k else 0)
        phi = dx ** 2 + dy ** 2 - length ** 2
        rows.append(ca.jacobian(phi, q))
    return y, flat(q, v, p, lam, ca.gradient(lag, q), ca.gradient(lag, v), rows)


models = {"chain": model_chain(), "pendulum8": model_pendulum8()}
for links in [2, 4, 8, 16]:
    models[f"cartesian{links}"] = model_cartesian(links)

for name, (y, f) in models.items():
    fj = ca.Function(f"fj_{name}", [y], [f, ca.jacobian(f, y)])
    gen = ca.CodeGenerator(f"{name}.c", {"with_header": True})
    gen.add(fj)
    gen.generate(out + "/")
    print(name, y.shape[0], fj.nnz_out(1))
