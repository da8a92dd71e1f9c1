"""The reference of `friction_cone::a_side_force_curves_the_slip_to_a_stop`.

A puck slides on the floor at v0 along x under Coulomb's isotropic friction (deceleration
mu g against the slip) and a constant side force (acceleration a along y, a < mu g). With s
the speed and theta the angle of the velocity from +y,

    ds/dt = -mu g + a cos(theta),    s dtheta/dt = -a sin(theta),

so s(theta) = C tan(theta / 2)^k / sin(theta), k = mu g / a, and the time and the position
at the stop (theta -> 0) are quadratures over theta. Run with `python3 cone_curve.py`
(mpmath, 30 digits). With k = a / (mu g) the quadratures equal, to all their digits at
k = 1/2, 1/3, 1/4, the closed forms

    t = v0 / (mu g (1 - k^2)),   x = 2 v0^2 / (mu g (4 - k^2)),   y = k v0^2 / (4 mu g (1 - k^2)),

which the tests differentiate for the sensitivities.
"""
from mpmath import mp, mpf, quad, tan, sin, cos, pi

mp.dps = 30
mu, g, s0, th0 = mpf("0.4"), mpf("9.81"), mpf(3), pi / 2


def stop(k):
    """Time, x and y of the stop with the side force k mu g, by quadrature."""
    a = k * mu * g
    C = s0 * sin(th0) / tan(th0 / 2) ** (1 / k)

    def s(th):
        return C * tan(th / 2) ** (1 / k) / sin(th)

    # dt = s dtheta / (a sin theta) along the motion (theta falls to 0).
    t = quad(lambda th: s(th) / (a * sin(th)), [0, th0])
    x = quad(lambda th: s(th) * sin(th) * s(th) / (a * sin(th)), [0, th0])
    y = quad(lambda th: s(th) * cos(th) * s(th) / (a * sin(th)), [0, th0])
    return t, x, y


for k in [mpf(1) / 2, mpf(1) / 3, mpf(1) / 4]:
    t, x, y = stop(k)
    closed = (s0 / (mu * g * (1 - k**2)), 2 * s0**2 / (mu * g * (4 - k**2)), k * s0**2 / (4 * mu * g * (1 - k**2)))
    print("k", k, "stop", t, "x", x, "y", y)
    print("  less the closed forms", t - closed[0], x - closed[1], y - closed[2])
