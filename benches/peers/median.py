"""Merges work-precision CSVs of the same solver from several rounds (`problem,tol,error,seconds,
steps`): one row per problem and tolerance, its seconds the median over the rounds. Errors and
steps do not depend on the round (the solvers are deterministic); a round that disagrees on them
is refused.
Usage: median.py round1.csv round2.csv ... > merged.csv"""
import csv
import statistics
import sys

rows = {}
order = []
for path in sys.argv[1:]:
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
    print(f"{key[0]},{key[1]},{error},{statistics.median(seconds):.6e},{steps}")
