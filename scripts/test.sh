#!/usr/bin/env bash
# The project's test command (README.md, "The two commands"): dependencies, the Release build of
# everything (the command line, the tests, the benchmark drivers), then every test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --build build -j "$(nproc)"   # the tests and the benchmark drivers CTest runs
ctest --test-dir build --output-on-failure -j "$(nproc)"
