"""LC ladder netlists and their exact solution, for benches/peers/spice.sh; the other circuits
of the comparison and their references.

`netlist N FILE`: an N-node ladder (L = C = 1; L1 from ground to node 1, Lk from node k-1 to k,
Ck from node k to ground), node voltages starting from a Gaussian pulse five nodes wide centred
at N/3, inductor currents from zero, simulated to t = 10. `.save` keeps the 401 nodes around the
pulse (the waves travel one node per unit time, so nothing else moves).

`reference N FILE`: those nodes' voltages at t = 10 from the ladder's modes, computed here in
closed form: the node-voltage matrix T (2 on the diagonal but 1 in the last row, -1 beside it)
has eigenvectors sin(j theta_k), theta_k = (2k-1) pi / (2N+1), eigenvalues 4 sin^2(theta_k/2),
so v_j(t) = sum_k c_k cos(omega_k t) sin(j theta_k) with omega_k = 2 sin(theta_k/2).
"""
import os
import subprocess
import sys
import time

import numpy as np


def pulse(n):
    j = np.arange(1, n + 1, dtype=float)
    return np.exp(-(((j - n / 3.0) / 5.0) ** 2))


def window(n):
    centre = int(round(n / 3.0))
    return list(range(max(1, centre - 200), min(n, centre + 200) + 1))


def netlist(n, path, tran=".tran 1 10 uic"):
    v0 = pulse(n)
    with open(path, "w") as f:
        f.write(f"LC ladder of {n} nodes from a pulse\n")
        for k in range(1, n + 1):
            a = "0" if k == 1 else f"n{k - 1}"
            f.write(f"L{k} {a} n{k} 1\nC{k} n{k} 0 1\n")
        # Voltages below 1e-300 are written as zero: the pulse's tails underflow anyway.
        f.write(".ic " + " ".join(f"v(n{k})={v0[k - 1]:.17e}" for k in range(1, n + 1) if v0[k - 1] > 1e-300) + "\n")
        f.write(".save " + " ".join(f"v(n{k})" for k in window(n)) + "\n")
        f.write(f"{tran}\n.end\n")


def reference(n, path, t=10.0):
    v0 = pulse(n)
    support = np.nonzero(v0 > 1e-300)[0] + 1  # node numbers where the pulse is not zero
    nodes = np.array(window(n), dtype=float)
    k = np.arange(1, n + 1, dtype=float)
    theta = (2 * k - 1) * np.pi / (2 * n + 1)
    # sum_{j=1}^{n} sin^2(j theta) = n/2 - sin(n theta) cos((n+1) theta) / (2 sin theta)
    norm = n / 2 - np.sin(n * theta) * np.cos((n + 1) * theta) / (2 * np.sin(theta))
    out = np.zeros(len(nodes))
    for lo in range(0, n, 2000):
        th = theta[lo:lo + 2000]
        c = np.sin(np.outer(th, support)) @ v0[support - 1] / norm[lo:lo + 2000]
        out += np.sin(np.outer(nodes, th)) @ (c * np.cos(2 * np.sin(th / 2) * t))
    with open(path, "w") as f:
        for j, v in zip(window(n), out):
            f.write(f"n{j} {v:.17e}\n")


def last_row(path, stop=10.0):
    """The last sample (at `stop`) of a dirac CSV or an ngspice ASCII raw file, as
    {node: voltage}."""
    text = open(path).read()
    if "Values:" in text:
        head, values = text.split("Values:\n")
        names = [line.split("\t")[2] for line in head.split("Variables:\n")[1].strip("\n").split("\n")]
        numbers = values.split()
        last = numbers[len(numbers) - len(names):]
        assert abs(float(last[0]) - stop) <= 1e-12 * stop, last[0]
    else:
        lines = text.strip().split("\n")
        names, last = lines[0].split(","), lines[-1].split(",")
        assert abs(float(last[0]) - stop) <= 1e-12 * stop, last[0]
    return {name[2:-1]: float(v) for name, v in zip(names[1:], last[1:])}


def error(result, ref, stop=10.0):
    """The largest nodal error at `stop`, relative to the largest reference voltage."""
    exact = {line.split()[0]: float(line.split()[1]) for line in open(ref)}
    got = last_row(result, stop)
    assert set(got) == set(exact), "the columns differ from the reference's nodes"
    return max(abs(got[k] - exact[k]) for k in exact) / max(abs(v) for v in exact.values())


def check_norm():
    for n in (7, 100, 1001):
        k = np.arange(1, n + 1)
        theta = (2 * k - 1) * np.pi / (2 * n + 1)
        direct = (np.sin(np.outer(theta, np.arange(1, n + 1))) ** 2).sum(axis=1)
        closed = n / 2 - np.sin(n * theta) * np.cos((n + 1) * theta) / (2 * np.sin(theta))
        assert np.allclose(direct, closed, rtol=1e-12, atol=1e-9), n


def rlc_netlist(n, path):
    """The LC ladder with a 10 Ω resistor from every node to the reference: a lossy line."""
    netlist(n, path)
    text = open(path).read().replace(".ic", "".join(f"R{k} n{k} 0 10\n" for k in range(1, n + 1)) + ".ic", 1)
    open(path, "w").write(text.replace("LC ladder", "RLC ladder", 1))


def rlc_reference(n, path, t=10.0):
    """The lossy ladder's node voltages at t from the matrix exponential of its linear system
    (scipy's expm_multiply): C v' = i_k - i_(k+1) - v/R, L i_k' = v_(k-1) - v_k."""
    import scipy.sparse as sp
    from scipy.sparse.linalg import expm_multiply
    k = np.arange(n)
    # x = (v_1..v_n, i_1..i_n)
    rows, cols, vals = [], [], []
    def put(r, c, v):
        rows.append(r); cols.append(c); vals.append(v)
    for j in range(n):
        put(j, n + j, 1.0)              # + i_j
        if j + 1 < n:
            put(j, n + j + 1, -1.0)     # - i_(j+1)
        put(j, j, -1.0 / 10.0)          # - v_j / R
        put(n + j, j, -1.0)             # - v_j
        if j > 0:
            put(n + j, j - 1, 1.0)      # + v_(j-1)
    a = sp.csr_matrix((vals, (rows, cols)), shape=(2 * n, 2 * n))
    x0 = np.concatenate([pulse(n), np.zeros(n)])
    x = expm_multiply(a * t, x0)
    with open(path, "w") as f:
        for j in window(n):
            f.write(f"n{j} {x[j - 1]:.17e}\n")


CLIPPER = """diode clipper
V1 in 0 SIN(0 2 1k)
R1 in out 1k
C1 out 0 10n
D1 out 0 dmod
D2 0 out dmod
.model dmod D(IS=1e-14 N=1)
.save v(out)
.tran 10u 4m
.end
"""


def clipper_reference(path):
    """The clipper's output at 4 ms: C v' = (u - v)/R - is (e^(v/vt) - 1) + is (e^(-v/vt) - 1)
    - 2 gmin v (SPICE's gmin, 1e-12 S, across each junction), by scipy's DOP853 and Radau at
    tight tolerances, which must agree."""
    from scipy.integrate import solve_ivp
    # k T / q at 27 °C with the constants ngspice 39 uses (CODATA 2014, its const.h), as dirac.
    vt = 1.38064852e-23 * 300.15 / 1.6021766208e-19
    def f(t, v):
        u = 2.0 * np.sin(2 * np.pi * 1e3 * t)
        i = (u - v[0]) / 1e3 - 1e-14 * np.expm1(v[0] / vt) + 1e-14 * np.expm1(-v[0] / vt) - 2e-12 * v[0]
        return [i / 1e-8]
    a = solve_ivp(f, (0, 4e-3), [0.0], method="DOP853", rtol=1e-13, atol=1e-16).y[0, -1]
    b = solve_ivp(f, (0, 4e-3), [0.0], method="Radau", rtol=1e-12, atol=1e-15).y[0, -1]
    assert abs(a - b) < 1e-9, (a, b)
    with open(path, "w") as out:
        out.write(f"out {a:.17e}\n")


CONTROLLED = """controlled sources
.subckt amp in out params: gain=2
E1 out 0 in 0 {gain}
.ends
V5 u 0 SIN(0 1 0.5)
R9 u k 1
C7 k 0 1
X4 k m amp params: gain=3
R10 m n 1
C8 n 0 1
F1 0 y V5 2
R11 y 0 1
H1 z 0 v5 0.5
R12 z 0 1
.save v(k) v(m) v(n) v(y) v(z)
.tran 0.1 5
.end
"""


def controlled_reference(path):
    """The controlled sources' nodes at 5 s: C7 v(k)' = sin(pi t) - v(k), v(m) = 3 v(k) (E),
    C8 v(n)' = v(m) - v(n); the current into V5's + pin i5 = v(k) - sin(pi t), v(y) = 2 i5 (F into
    R11), v(z) = 0.5 i5 (H); by scipy's DOP853 and Radau at tight tolerances, which must agree."""
    from scipy.integrate import solve_ivp
    def f(t, x):
        return [np.sin(np.pi * t) - x[0], 3.0 * x[0] - x[1]]
    a = solve_ivp(f, (0, 5), [0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-16).y[:, -1]
    b = solve_ivp(f, (0, 5), [0.0, 0.0], method="Radau", rtol=1e-12, atol=1e-15).y[:, -1]
    assert np.abs(a - b).max() < 1e-9, (a, b)
    i5 = a[0] - np.sin(5 * np.pi)
    with open(path, "w") as out:
        for node, v in (("k", a[0]), ("m", 3 * a[0]), ("n", a[1]), ("y", 2 * i5), ("z", 0.5 * i5)):
            out.write(f"{node} {v:.17e}\n")


def run(command, env=None):
    """The wall time of one run of `command` (a whole process: reading, building, simulating,
    writing), which must succeed."""
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    return time.perf_counter() - start


ROUNDS = 3


def compare(sizes, ngspice, dirac, out):
    """Runs both simulators on each circuit over a range of tolerances, dirac's and ngspice's
    runs alternated, ROUNDS rounds, each run's time the median of its rounds; prints a table of
    (time, error) and, for every ngspice run, dirac's error at ngspice's time and dirac's time
    at ngspice's error, interpolated log-log between dirac's runs.

    Cases with a largest step (`.tran`'s fourth value) are run by dirac as it reads them (the
    step not applied: Radau's error control bounds its error and its dense output gives every
    printed point) and, shown beside them and not compared, with `--max-step` (applied)."""
    env = dict(os.environ, SPICE_ASCIIRAWFILE="1")
    cases = [("LC ladder", n, False) for n in sizes] + [("LC ladder", n, True) for n in sizes]
    cases += [("RLC ladder", 1000, False), ("diode clipper", 1, False), ("diode clipper", 1, True),
              ("controlled sources", 1, False)]
    rows = []
    for name, n, bounded in cases:
        stem = {"LC ladder": f"lc{n}", "RLC ladder": f"rlc{n}", "diode clipper": "clipper",
                "controlled sources": "controlled"}[name] + ("_max" if bounded else "")
        cir, ref = f"{out}/{stem}.cir", f"{out}/{stem}.ref"
        stop = {"diode clipper": 4e-3, "controlled sources": 5.0}.get(name, 10.0)
        if name == "LC ladder":
            netlist(n, cir, ".tran 0.01 10 0 0.01 uic" if bounded else ".tran 1 10 uic")
            reference(n, ref)
        elif name == "RLC ladder":
            rlc_netlist(n, cir)
            rlc_reference(n, ref)
        elif name == "diode clipper":
            open(cir, "w").write(CLIPPER.replace(".tran 10u 4m", ".tran 10u 4m 0 1u" if bounded else ".tran 10u 4m"))
            clipper_reference(ref)
        else:
            open(cir, "w").write(CONTROLLED)
            controlled_reference(ref)
        label = f"{name}, max step" if bounded else name
        body = open(cir).read().replace(".end\n", "")
        # Every run of the case: (simulator, setting, command, env, result file).
        runs = []
        for tol in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10):
            csv = f"{out}/{stem}_dirac_{tol:g}.csv"
            runs.append(("dirac Radau", f"tol {tol:g}", [dirac, cir, "--tol", f"{tol:g}", "--out", csv, "--svg", f"{out}/{stem}_dirac.svg"], None, csv))
        if bounded:
            for tol in (1e-3, 1e-6, 1e-9):
                csv = f"{out}/{stem}_dirac_max_{tol:g}.csv"
                runs.append(("dirac Radau, --max-step", f"tol {tol:g}", [dirac, cir, "--tol", f"{tol:g}", "--max-step", "--out", csv, "--svg", f"{out}/{stem}_dirac.svg"], None, csv))
        for method in ("trap", "gear"):
            for reltol in (1e-3, 1e-4, 1e-5, 1e-6):
                deck, raw = f"{out}/{stem}_{method}_{reltol:g}.cir", f"{out}/{stem}_{method}_{reltol:g}.raw"
                with open(deck, "w") as f:
                    f.write(body + f".options reltol={reltol:g} method={method}\n.end\n")
                runs.append((f"ngspice {method}", f"reltol {reltol:g}", [ngspice, "-b", "-r", raw, deck], env, raw))
        # Alternated: dirac's runs and ngspice's interleaved, round after round.
        ours_first = [k for k in range(len(runs)) if runs[k][0].startswith("dirac")]
        theirs = [k for k in range(len(runs)) if runs[k][0].startswith("ngspice")]
        order = [k for pair in zip(ours_first, theirs) for k in pair]
        order += [k for k in range(len(runs)) if k not in order]
        times = [[] for _ in runs]
        for _ in range(ROUNDS):
            for k in order:
                times[k].append(run(runs[k][2], runs[k][3]))
        seconds = [sorted(t)[len(t) // 2] for t in times]
        errors = [error(r[4], ref, stop) for r in runs]
        ours = [(seconds[k], errors[k]) for k in range(len(runs)) if runs[k][0] == "dirac Radau"]
        for k, r in enumerate(runs):
            row = (r[0], label, n, r[1], seconds[k], errors[k])
            if r[0].startswith("ngspice"):
                row += tuple(against(ours, seconds[k], errors[k]))
            rows.append(row)
    print("| simulator | circuit | nodes | setting | wall time (s) | error | dirac's error at this time | ratio | dirac's time at this error | ratio |")
    print("|---|---|---:|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        line = f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]:.3f} | {r[5]:.2e} |"
        if len(r) > 6:
            e_at, t_at = r[6], r[7]
            line += f" {e_at:.2e} | {r[5] / e_at:.0f}× smaller | {t_at:.3f} | {t_at / r[4]:.2f}× |"
        else:
            line += " | | | |"
        print(line)
    compared = [r for r in rows if len(r) > 6]
    met = [r for r in compared if r[5] / r[6] >= 100]
    print(f"\n{len(met)} of {len(compared)} ngspice runs: dirac's error at ngspice's time at least 100× smaller; "
          f"smallest margin {min(r[5] / r[6] for r in compared):.0f}×; "
          f"dirac's time at ngspice's error {min(r[7] / r[4] for r in compared):.2f}–{max(r[7] / r[4] for r in compared):.2f}×")


def against(ours, seconds, e):
    """dirac's error at `seconds` and its time at error `e`, interpolated log-log between its
    runs (sorted by time), or taken from the nearest end when outside them."""
    def interpolate(xs, ys, x):
        xs, ys = np.log(xs), np.log(ys)
        order = np.argsort(xs)
        return float(np.exp(np.interp(np.log(x), xs[order], ys[order])))
    # Keep the runs that are not beaten on both counts by another (the work-precision front).
    front = [p for p in ours if not any(q[0] <= p[0] and q[1] < p[1] for q in ours if q is not p)]
    times, errors = [p[0] for p in front], [p[1] for p in front]
    return interpolate(times, errors, seconds), interpolate(errors, times, e)


if __name__ == "__main__":
    if sys.argv[1] == "compare":
        compare([int(n) for n in sys.argv[2].split(",") if n], sys.argv[3], sys.argv[4], sys.argv[5])
        sys.exit()
    what = sys.argv[1]
    if what == "error":
        print(f"{error(sys.argv[2], sys.argv[3]):.3e}")
        sys.exit()
    n, path = int(sys.argv[2]), sys.argv[3]
    if what == "netlist":
        netlist(n, path)
    else:
        check_norm()
        reference(n, path)
