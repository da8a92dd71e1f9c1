"""Compares work-precision curves: for every point of the first (dirac) curve, the wall time each
peer needs for the same achieved error (log-log interpolation between the peer's points), and the
ratio; with --svg, draws all curves in one log-log work-precision diagram.
Usage: compare.py [LABEL=]dirac.csv LABEL=peer.csv [LABEL=peer.csv ...] [--svg out.svg]
(the first curve's label defaults to "dirac Radau").

A path holding `*` names the rounds of an alternated run (`rounds/radau.*.csv`, one file per
round, numbered): then each round's ratio is formed from that round's two curves (the peer's
time interpolated on its own curve of the same round), and the table shows the median time over
the rounds, the median ratio and the range of the rounds' ratios. Both sides must have as many
rounds. Errors and steps must agree between rounds (the solvers are deterministic)."""
import csv
import glob
import math
import re
import statistics
import sys


def load_one(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    out = {}
    for r in rows:
        out.setdefault(r["problem"], []).append(
            (float(r["error"]), float(r["seconds"]), int(r["steps"]), float(r["tol"])))
    return out


def load(path):
    """A list of rounds (one curve set each), in the order of their round numbers."""
    if "*" not in path:
        return [load_one(path)]
    paths = sorted(glob.glob(path), key=lambda p: int(re.findall(r"\d+", p)[-1]))
    if not paths:
        sys.exit(f"no file matches {path}")
    rounds = [load_one(p) for p in paths]
    for other, p in zip(rounds[1:], paths[1:]):
        for problem, points in rounds[0].items():
            if [(e, n) for e, _, n, _ in points] != [(e, n) for e, _, n, _ in other.get(problem, [])]:
                sys.exit(f"{p}: {problem} reaches other errors or steps than {paths[0]}")
    return rounds


def merged(rounds):
    """One curve set, each point's seconds the median over the rounds."""
    out = {}
    for problem, points in rounds[0].items():
        out[problem] = [(e, statistics.median(r[problem][i][1] for r in rounds), n, tol)
                        for i, (e, _, n, tol) in enumerate(points)]
    return out


def time_at(curve, error):
    """The peer's time at `error`, interpolated in log-log space; None outside its range."""
    pts = sorted((e, s) for e, s, _, _ in curve if e > 0)
    for (e1, s1), (e2, s2) in zip(pts, pts[1:]):
        if e1 <= error <= e2:
            w = (math.log(error) - math.log(e1)) / (math.log(e2) - math.log(e1))
            return math.exp(math.log(s1) + w * (math.log(s2) - math.log(s1)))
    return None


args = sys.argv[1:]
svg = None
if "--svg" in args:
    k = args.index("--svg")
    svg = args[k + 1]
    del args[k:k + 2]
base_label, base_path = args[0].split("=", 1) if "=" in args[0] else ("dirac Radau", args[0])
base_rounds = load(base_path)
radau = merged(base_rounds)
peer_rounds = [(label, load(path)) for label, path in (a.split("=", 1) for a in args[1:])]
peers = [(label, merged(rounds)) for label, rounds in peer_rounds]
for (label, rounds), (_, peer) in zip(peer_rounds, peers):
    if len(rounds) != len(base_rounds):
        sys.exit(f"{label}: {len(rounds)} rounds against {len(base_rounds)} of {base_label}")
    paired = len(rounds) > 1
    print(f"{base_label} against {label}" + (f" ({len(rounds)} rounds; ratio the median of the rounds' ratios, "
                                              "their range beside it):" if paired else ":"))
    print(f"{'problem':10} {'tol':>8} {'error':>10} {'dirac s':>11} {'peer s':>11} {'ratio':>7}"
          + (f" {'range':>13}" if paired else ""))
    for problem, points in radau.items():
        for i, (error, seconds, steps, tol) in enumerate(points):
            other = time_at(peer.get(problem, []), error)
            ratios = []
            for mine, theirs in zip(base_rounds, rounds):
                t = time_at(theirs.get(problem, []), error)
                if t:
                    ratios.append(mine[problem][i][1] / t)
            ratio = f"{statistics.median(ratios):7.3f}" if ratios else "    n/a"
            other_s = f"{other:11.3e}" if other else "        n/a"
            span = f" {min(ratios):6.3f}–{max(ratios):6.3f}" if paired and ratios else ""
            print(f"{problem:10} {tol:8.0e} {error:10.2e} {seconds:11.3e} {other_s} {ratio}{span}")
    print()


def work_precision_svg(path):
    """Log-log work-precision plot: achieved error against wall time, every solver and problem."""
    series = []
    palette = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"]
    dashes = {"pendulum": "", "chain": "6,3", "pendulum8": "2,3"}
    for k, (solver, data) in enumerate([(base_label, radau)] + peers):
        for problem, pts in data.items():
            pts = sorted((math.log10(e), math.log10(s)) for e, s, _, _ in pts if e > 0)
            series.append((f"{solver}, {problem}", palette[k % len(palette)], dashes.get(problem, ""), pts))
    xs = [x for *_, p in series for x, _ in p]
    ys = [y for *_, p in series for _, y in p]
    x0, x1, y0, y1 = math.floor(min(xs)), math.ceil(max(xs)), math.floor(min(ys)), math.ceil(max(ys))
    w, h, left, right, top, bottom = 1000, 560, 90, 330, 40, 60
    pw, ph = w - left - right, h - top - bottom
    sx = lambda x: left + (x - x0) / (x1 - x0) * pw
    sy = lambda y: top + (y1 - y) / (y1 - y0) * ph
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="13">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{left + pw / 2}" y="24" text-anchor="middle" font-size="16">Work-precision: dirac against its peers</text>',
           f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#444"/>']
    for x in range(x0, x1 + 1):
        out.append(f'<line x1="{sx(x)}" y1="{top}" x2="{sx(x)}" y2="{top + ph}" stroke="#ddd"/>')
        out.append(f'<text x="{sx(x)}" y="{top + ph + 18}" text-anchor="middle">1e{x}</text>')
    for y in range(y0, y1 + 1):
        out.append(f'<line x1="{left}" y1="{sy(y)}" x2="{left + pw}" y2="{sy(y)}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 6}" y="{sy(y) + 4}" text-anchor="end">1e{y}</text>')
    out.append(f'<text x="{left + pw / 2}" y="{h - 15}" text-anchor="middle">achieved error (log10)</text>')
    out.append(f'<text x="20" y="{top + ph / 2}" text-anchor="middle" transform="rotate(-90 20 {top + ph / 2})">wall time per solve [s] (log10)</text>')
    for k, (name, color, dash, pts) in enumerate(series):
        points = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in pts)
        style = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<polyline points="{points}" fill="none" stroke="{color}" stroke-width="2"{style}/>')
        for x, y in pts:
            out.append(f'<circle cx="{sx(x):.1f}" cy="{sy(y):.1f}" r="3" fill="{color}"/>')
        ly = top + 16 + 20 * k
        out.append(f'<line x1="{left + pw + 12}" y1="{ly}" x2="{left + pw + 34}" y2="{ly}" stroke="{color}" stroke-width="2"{style}/>')
        out.append(f'<text x="{left + pw + 40}" y="{ly + 4}">{name}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if svg:
    work_precision_svg(svg)
    print(f"wrote {svg}")
