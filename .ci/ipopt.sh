#!/usr/bin/env bash
# Installs IPOPT from Debian's packages (coinor-libipopt-dev) unless it is there: the feature
# `ipopt`, which the tests and benchmarks turn on, links it.
set -euo pipefail
if dpkg -s coinor-libipopt-dev > /dev/null 2>&1; then
    exit 0
fi
run() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
export DEBIAN_FRONTEND=noninteractive
run apt-get install -y -q coinor-libipopt-dev > /dev/null || {
    run apt-get update -q > /dev/null
    run apt-get install -y -q coinor-libipopt-dev > /dev/null
}
