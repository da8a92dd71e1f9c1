"""ngspice's small-signal sweeps (`.ac`) of the netlists in tests/spice/ac/, for
tests/integration/spice.rs, independently of dirac:

    bash tests/references/spice.sh

Each netlist is run by ngspice in batch mode with its operating point solved far below the
default tolerances (reltol 1e-12, abstol 1e-18 A, vntol 1e-15 V), the sweep written as an ASCII
raw file with 17 digits. Writes spice_ac.csv: one row per frequency and quantity,
`netlist,frequency,name,re,im`, the names as ngspice writes them (`v(node)`; `i(name)` for the
current through a voltage source, an `E`, an `H` or an inductor, from its first node through it
to its second).
"""

import os
import pathlib
import re
import subprocess
import sys
import tempfile

TIGHT = ".options reltol=1e-12 abstol=1e-18 vntol=1e-15 numdgt=17\n.end\n"


def sweep(ngspice, netlist):
    lines = netlist.read_text().splitlines()
    kept = [l for l in lines if not re.match(r"\s*\.end\b", l, re.IGNORECASE)]
    with tempfile.TemporaryDirectory() as tmp:
        deck, raw = pathlib.Path(tmp) / netlist.name, pathlib.Path(tmp) / "out.raw"
        deck.write_text("\n".join(kept) + "\n" + TIGHT)
        env = dict(os.environ, SPICE_ASCIIRAWFILE="1")
        subprocess.run([ngspice, "-b", "-r", str(raw), str(deck)], check=True, capture_output=True, env=env)
        text = raw.read_text()
    head, values = text.split("Values:\n")
    names = [l.split("\t")[2] for l in head.split("Variables:\n")[1].strip("\n").split("\n")]
    numbers = values.split()
    rows, k = [], 0
    while k < len(numbers):
        k += 1  # the point's index
        point = []
        for _ in names:
            re_, im = numbers[k].split(",")
            point.append((float(re_), float(im)))
            k += 1
        rows.append(point)
    out = []
    for point in rows:
        f = point[0][0]
        for name, (re_, im) in zip(names[1:], point[1:]):
            out.append((f, name, re_, im))
    assert out, f"ngspice wrote no sweep for {netlist}"
    return out


def main(ngspice, root, out):
    netlists = sorted((root / "tests/spice/ac").glob("*.cir"))
    with open(out, "w") as f:
        f.write("netlist,frequency,name,re,im\n")
        for netlist in netlists:
            for freq, name, re_, im in sweep(ngspice, netlist):
                f.write(f"{netlist.relative_to(root)},{freq!r},{name},{re_!r},{im!r}\n")


if __name__ == "__main__":
    main(sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3])
