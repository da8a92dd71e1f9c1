"""References for tests/integration/components.rs, computed with SciPy from the circuits'
equations written by hand (nodal analysis), independently of dirac.

    bash tests/references/components.sh

writes cauer_step.csv (the CauerLowPassAnalog filter's step response) and chua.csv (Chua's
circuit), both by DOP853 at rtol = atol = 1e-13. Chua's piecewise-linear resistor is
integrated piece by piece: each crossing of v = ±Ve is located (solve_ivp's terminal events)
and the integration restarted there, so no step straddles a kink.
"""

import sys

import numpy as np
from scipy.integrate import solve_ivp

TOL = dict(method="DOP853", rtol=1e-13, atol=1e-13)


def cauer(out):
    # Modelica.Electrical.Analog.Examples.CauerLowPassAnalog's values.
    l1, l2 = 1.304, 0.8586
    c1, c3, c5 = 1.072, 1.682, 0.7262
    c2 = 1 / (1.704992**2 * l1)
    c4 = 1 / (1.179945**2 * l2)
    r1 = r2 = 1.0
    # Node voltages v1, v2, v3 (C1, C3, C5 to ground; C2 ∥ L1 from 1 to 2, C4 ∥ L2 from 2 to 3)
    # and the inductor currents i1 (1 → 2), i2 (2 → 3): M v' = f, L i' = Δv.
    mass = np.array([[c1 + c2, -c2, 0.0], [-c2, c2 + c3 + c4, -c4], [0.0, -c4, c4 + c5]])
    inverse = np.linalg.inv(mass)

    def rhs(t, x):
        v1, v2, v3, i1, i2 = x
        source = 1.0 if t >= 1.0 else 0.0
        f = np.array([(source - v1) / r1 - i1, i1 - i2, i2 - v3 / r2])
        return np.concatenate([inverse @ f, [(v1 - v2) / l1, (v2 - v3) / l2]])

    times = [2.0, 3.0, 5.0, 10.0, 20.0, 40.0, 60.0]
    # At rest until the step at t = 1.
    sol = solve_ivp(rhs, (1.0, 60.0), np.zeros(5), t_eval=times, **TOL)
    assert sol.success
    with open(out, "w") as f:
        f.write("t,v1,v2,v3,i_l1,i_l2\n")
        for k, t in enumerate(sol.t):
            f.write(f"{float(t)!r}," + ",".join(repr(float(x)) for x in sol.y[:, k]) + "\n")


def chua(out, horizon):
    # Modelica.Electrical.Analog.Examples.ChuaCircuit's values.
    l, ro, g, c1, c2 = 18.0, 12.5e-3, 0.565, 10.0, 100.0
    ga, gb, ve = -0.757576, -0.409091, 1.0

    def nr(v):
        if v < -ve:
            return gb * (v + ve) - ga * ve
        if v > ve:
            return gb * (v - ve) + ga * ve
        return ga * v

    def rhs(t, x):
        # C1's voltage (node b, with the nonlinear resistor), C2's (node a), L's current a → ground
        # through Ro.
        vb, va, il = x
        return [(g * (va - vb) - nr(vb)) / c1, (g * (vb - va) - il) / c2, (va - ro * il) / l]

    def kink(level, direction):
        def event(t, x):
            return x[0] - level

        event.terminal = True
        event.direction = direction
        return event

    times = np.arange(0.0, horizon + 1e-9, 50.0)
    t, x = 0.0, np.array([4.0, 0.0, 0.0])
    samples = {}
    while t < horizon:
        # Each level watched for the crossing away from the side the state is on, so a restart
        # on the level just crossed does not find it again.
        # On a level (just crossed), the side is where the motion goes.
        side = [x[0] - level if abs(x[0] - level) > 1e-9 else rhs(t, x)[0] for level in (ve, -ve)]
        events = [kink(level, -np.sign(s)) for level, s in zip((ve, -ve), side)]
        sol = solve_ivp(rhs, (t, horizon), x, events=events, dense_output=True, **TOL)
        assert sol.status >= 0
        end = sol.t[-1]
        for s in times:
            if t <= s <= end and s not in samples:
                samples[s] = sol.sol(s)
        t, x = end, sol.y[:, -1]
    with open(out, "w") as f:
        f.write("t,v_c1,v_c2,i_l\n")
        for s in times:
            f.write(f"{float(s)!r}," + ",".join(repr(float(v)) for v in samples[s]) + "\n")


if __name__ == "__main__":
    directory = sys.argv[1]
    cauer(f"{directory}/cauer_step.csv")
    chua(f"{directory}/chua.csv", 5000.0)
