#!/usr/bin/env bash
# Regenerates the Pinocchio references of tests/integration/robots.rs into tests/references/.
# Installs Pinocchio (`pin`) and SciPy into a virtual environment under target/. Not part of
# CI: the CSV files are committed.
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=target/references/venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet scipy pin
"$venv/bin/python" tests/references/robots.py tests/robots/panda/panda.urdf tests/references
"$venv/bin/python" tests/references/robots.py --floating tests/robots/panda/panda.urdf tests/references/panda_floating.csv 43
"$venv/bin/python" tests/references/robots.py --aba tests/robots/panda/panda.urdf tests/references/panda_aba.csv 44
