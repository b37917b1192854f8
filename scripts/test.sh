#!/usr/bin/env bash
# The project's test command (README.md, "The two commands"): dependencies, Release build, then every test.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
