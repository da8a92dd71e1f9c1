#!/usr/bin/env bash
# Regenerates the SciPy references of tests/integration/components.rs into tests/references/.
# Installs SciPy into a virtual environment under target/. Not part of CI: the CSV files are
# committed.
set -euo pipefail
cd "$(dirname "$0")/../.."
venv=target/references/venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
"$venv/bin/pip" install --quiet scipy
"$venv/bin/python" tests/references/components.py tests/references
