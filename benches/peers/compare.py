"""Compares work-precision curves: for every dirac Radau point, the wall time SUNDIALS IDA
needs for the same achieved error (log-log interpolation between IDA's points), and the ratio.
Usage: compare.py radau.csv ida.csv"""
import csv
import math
import sys


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    out = {}
    for r in rows:
        out.setdefault(r["problem"], []).append(
            (float(r["error"]), float(r["seconds"]), int(r["steps"]), float(r["tol"])))
    return out


def time_at(curve, error):
    """IDA's time at `error`, interpolated in log-log space; None outside IDA's range."""
    pts = sorted((e, s) for e, s, _, _ in curve if e > 0)
    for (e1, s1), (e2, s2) in zip(pts, pts[1:]):
        if e1 <= error <= e2:
            w = (math.log(error) - math.log(e1)) / (math.log(e2) - math.log(e1))
            return math.exp(math.log(s1) + w * (math.log(s2) - math.log(s1)))
    return None


radau, ida = load(sys.argv[1]), load(sys.argv[2])
print(f"{'problem':10} {'tol':>8} {'error':>10} {'radau s':>11} {'ida s':>11} {'ratio':>7}")
for problem, points in radau.items():
    for error, seconds, steps, tol in points:
        other = time_at(ida.get(problem, []), error)
        ratio = f"{seconds / other:7.3f}" if other else "    n/a"
        ida_s = f"{other:11.3e}" if other else "        n/a"
        print(f"{problem:10} {tol:8.0e} {error:10.2e} {seconds:11.3e} {ida_s} {ratio}")
