#!/usr/bin/env bash
# Regenerates the python-control references of tests/integration/control.rs into
# tests/references/control.txt. Installs python-control, SciPy and slycot (SLICOT's Riccati
# solvers) into a virtual environment under target/. Not part of CI: the file is committed.
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=target/references/venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet scipy control slycot
"$venv/bin/python" tests/references/control_reference.py tests/references/control.txt
