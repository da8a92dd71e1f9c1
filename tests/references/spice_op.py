"""ngspice's DC operating points of the netlists in tests/spice/op/, for
tests/integration/spice.rs, independently of dirac:

    bash tests/references/spice.sh

Each netlist's `.tran` and `.end` are removed and ngspice's `op` is run with tolerances far
below its defaults (reltol 1e-12, abstol 1e-18 A, vntol 1e-15 V), printing 15 digits. Writes
spice_op.csv: one row per node voltage and branch current, `netlist,name,value`, the names as
ngspice prints them (`v(node)` for a node, `i(vname)` for the current through a voltage source or
an inductor, from its first node through it to its second).
"""

import pathlib
import re
import subprocess
import sys
import tempfile

TIGHT = ".options reltol=1e-12 abstol=1e-18 vntol=1e-15\n.control\nset numdgt=15\nop\nprint all\n.endc\n.end\n"


def operating_point(ngspice, netlist):
    lines = netlist.read_text().splitlines()
    kept = [l for l in lines if not re.match(r"\s*\.(tran|end)\b", l, re.IGNORECASE)]
    with tempfile.TemporaryDirectory() as tmp:
        deck = pathlib.Path(tmp) / netlist.name
        deck.write_text("\n".join(kept) + "\n" + TIGHT)
        # ngspice exits with status 1 when the deck asks for no analysis of its own (the `op`
        # runs from the control block): the printed rows are checked instead.
        out = subprocess.run([ngspice, "-b", str(deck)], capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        m = re.match(r"^([\w:#.]+) = ([-+0-9.eE]+)$", line.strip())
        if not m:
            continue
        name, value = m.group(1), float(m.group(2))
        if name.endswith("#branch"):
            name = f"i({name[: -len('#branch')]})"
        else:
            name = f"v({name})"
        rows.append((name, value))
    assert rows, f"ngspice printed no operating point for {netlist}:\n{out}"
    return rows


def main(ngspice, root, out):
    netlists = sorted((root / "tests/spice/op").glob("*.cir"))
    with open(out, "w") as f:
        f.write("netlist,name,value\n")
        for netlist in netlists:
            for name, value in operating_point(ngspice, netlist):
                f.write(f"{netlist.relative_to(root)},{name},{value!r}\n")


if __name__ == "__main__":
    main(sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3])
