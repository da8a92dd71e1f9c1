"""References for tests/integration/control.rs, computed with python-control (and SciPy, with
SLICOT through slycot for the Riccati equations), independently of dirac.

    bash tests/references/control.sh

writes control.txt: one matrix per line, `name rows columns` and its entries row by row
(complex values as two matrices, `name.re` and `name.im`).

Two models:

- the cart-pole of examples/cart_pole.rs linearised about upright by hand: cart mass mc, a point
  mass mp on a rod of length l, its angle th from upright; state (x, th, vx, w), input the
  force on the cart, outputs the cart's position and the angle. With
  M = [[mc + mp, mp l], [mp l, mp l²]], M [ẍ; θ̈] = [u; mp g l θ] to first order.
- a five-state, two-input, two-output model with arbitrary numbers (some modes unstable,
  a cross-coupled R, a feedthrough).
"""

import sys

import control
import numpy as np


def cart_pole():
    mc, mp, l, g = 1.0, 0.3, 0.5, 9.81
    mass = np.array([[mc + mp, mp * l], [mp * l, mp * l * l]])
    stiffness = np.array([[0.0, 0.0], [0.0, mp * g * l]])
    inverse = np.linalg.inv(mass)
    a = np.block([[np.zeros((2, 2)), np.eye(2)], [inverse @ stiffness, np.zeros((2, 2))]])
    b = np.vstack([np.zeros((2, 1)), inverse @ np.array([[1.0], [0.0]])])
    c = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]])
    d = np.zeros((2, 1))
    return a, b, c, d


def five_state():
    a = np.array(
        [
            [-0.5, 1.0, 0.0, 0.2, 0.0],
            [0.3, -1.2, 0.7, 0.0, 0.1],
            [0.0, 0.4, 0.1, 1.0, 0.0],
            [0.5, 0.0, -0.8, -0.3, 0.6],
            [0.0, 0.2, 0.0, -0.4, 0.25],
        ]
    )
    b = np.array([[1.0, 0.0], [0.0, 0.5], [0.2, 0.0], [0.0, 1.0], [0.3, 0.4]])
    c = np.array([[1.0, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.5, 0.0]])
    d = np.array([[0.0, 0.0], [0.1, 0.0]])
    return a, b, c, d


def write(out, name, m):
    m = np.atleast_2d(np.asarray(m))
    if np.iscomplexobj(m):
        write(out, name + ".re", m.real)
        write(out, name + ".im", m.imag)
        return
    rows, columns = m.shape
    values = " ".join(repr(float(x)) for x in m.ravel())
    out.write(f"{name} {rows} {columns} {values}\n")


def sort_complex(values):
    values = np.asarray(values, dtype=complex)
    return values[np.lexsort((values.imag, values.real))]


def closed_loop_poles(a, b, k):
    # python-control's own poles (the third value of lqr and dlqr) come from slycot in single
    # precision (complex64); the eigenvalues of A − B K with its gain K are double precision.
    return sort_complex(np.linalg.eigvals(a - b @ k))


def main(path):
    with open(path, "w") as out:
        out.write(f"# python-control {control.__version__}, NumPy {np.__version__}\n")

        a, b, c, d = cart_pole()
        write(out, "cart.a", a)
        write(out, "cart.b", b)
        q = np.diag([1.0, 10.0, 0.1, 0.1])
        r = np.array([[0.1]])
        k, s, e = control.lqr(a, b, q, r)
        write(out, "cart.lqr.gain", k)
        write(out, "cart.lqr.riccati", s)
        write(out, "cart.lqr.poles", closed_loop_poles(a, b, k))
        write(out, "cart.lqr.poles_single", sort_complex(e))
        dt = 0.01
        sampled = control.c2d(control.ss(a, b, c, d), dt, method="zoh")
        write(out, "cart.zoh.a", sampled.A)
        write(out, "cart.zoh.b", sampled.B)
        k, s, e = control.dlqr(sampled.A, sampled.B, q, r)
        write(out, "cart.dlqr.gain", k)
        write(out, "cart.dlqr.riccati", s)
        write(out, "cart.dlqr.poles", closed_loop_poles(sampled.A, sampled.B, k))
        write(out, "cart.dlqr.poles_single", sort_complex(e))
        poles = [-1.0, -2.0, -3.0 + 1.0j, -3.0 - 1.0j]
        write(out, "cart.place.gain", control.place(a, b, poles))
        omega = np.logspace(-1, 2, 7)
        write(out, "cart.bode.omega", omega)
        response = control.frequency_response(control.ss(a, b, c, d), omega)
        # fresp: outputs × inputs × frequencies; the angle's response to the force.
        write(out, "cart.bode.angle", response.frdata[1, 0, :])
        times = np.linspace(0.0, 2.0, 9)
        write(out, "cart.step.times", times)
        step = control.step_response(control.ss(a, b, c, d), times, input=0, squeeze=False)
        write(out, "cart.step.outputs", step.outputs[:, 0, :])

        a, b, c, d = five_state()
        write(out, "five.a", a)
        write(out, "five.b", b)
        write(out, "five.c", c)
        write(out, "five.d", d)
        q = np.diag([1.0, 2.0, 0.5, 1.0, 3.0])
        r = np.array([[1.0, 0.2], [0.2, 0.5]])
        write(out, "five.q", q)
        write(out, "five.r", r)
        k, s, e = control.lqr(a, b, q, r)
        write(out, "five.lqr.gain", k)
        write(out, "five.lqr.riccati", s)
        write(out, "five.lqr.poles", closed_loop_poles(a, b, k))
        write(out, "five.lqr.poles_single", sort_complex(e))
        dt = 0.1
        sampled = control.c2d(control.ss(a, b, c, d), dt, method="zoh")
        write(out, "five.zoh.a", sampled.A)
        write(out, "five.zoh.b", sampled.B)
        k, s, e = control.dlqr(sampled.A, sampled.B, q, r)
        write(out, "five.dlqr.gain", k)
        write(out, "five.dlqr.riccati", s)
        write(out, "five.dlqr.poles", closed_loop_poles(sampled.A, sampled.B, k))
        write(out, "five.dlqr.poles_single", sort_complex(e))
        write(out, "five.poles", sort_complex(control.ss(a, b, c, d).poles()))
        write(out, "five.ctrb", control.ctrb(a, b))
        write(out, "five.obsv", control.obsv(a, c))
        # The zeros of the channel from input 1 to output 0 (no feedthrough) and of the channel
        # from input 0 to output 1 (feedthrough 0.1).
        channel = control.ss(a, b[:, [1]], c[[0], :], d[[0], [1]])
        write(out, "five.zeros.0.1", sort_complex(channel.zeros()))
        channel = control.ss(a, b[:, [0]], c[[1], :], d[[1], [0]])
        write(out, "five.zeros.1.0", sort_complex(channel.zeros()))
        omega = np.array([0.01, 0.3, 1.0, 2.5, 10.0, 100.0])
        write(out, "five.bode.omega", omega)
        response = control.frequency_response(control.ss(a, b, c, d), omega)
        for i in range(2):
            for j in range(2):
                write(out, f"five.bode.{i}.{j}", response.frdata[i, j, :])
        times = np.linspace(0.0, 3.0, 7)
        write(out, "five.step.times", times)
        step = control.step_response(control.ss(a, b, c, d), times, input=1, squeeze=False)
        write(out, "five.step.outputs", step.outputs[:, 0, :])


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "control.txt")
