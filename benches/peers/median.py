"""Merges work-precision CSVs of the same solver from several rounds (`problem,tol,error,seconds,
steps`): one row per problem and tolerance, its seconds the median over the rounds. Errors and
steps do not depend on the round (the solvers are deterministic); a round that disagrees on them
is refused.
With --min, the fastest round instead: the time without interference from other work on the
machine, which only ever adds time (the statistic `timeit` and BenchmarkTools.jl recommend
for comparing code).
Usage: median.py [--min] round1.csv round2.csv ... > merged.csv"""
import csv
import statistics
import sys

args = sys.argv[1:]
fastest = "--min" in args
paths = [a for a in args if a != "--min"]
rows = {}
order = []
for path in paths:
    with open(path) as f:
        for r in csv.DictReader(f):
            key = (r["problem"], r["tol"])
            if key not in rows:
                rows[key] = (r["error"], r["steps"], [])
                order.append(key)
            error, steps, seconds = rows[key]
            if (r["error"], r["steps"]) != (error, steps):
                sys.exit(f"{path}: {key} gives error {r['error']} in {r['steps']} steps, "
                         f"another round {error} in {steps}")
            seconds.append(float(r["seconds"]))
print("problem,tol,error,seconds,steps")
for key in order:
    error, steps, seconds = rows[key]
    time = min(seconds) if fastest else statistics.median(seconds)
    print(f"{key[0]},{key[1]},{error},{time:.6e},{steps}")
