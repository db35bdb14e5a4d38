#!/usr/bin/env bash
# Builds everything and runs the whole test suite (unit tests of the core, the command-line tool,
# and integration tests that drive Debian's real MeshLab 2020.09). Installs what it needs first.
# Usage: sudo bash scripts/run-tests.sh            (BUILD_DIR=build-tests by default)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
build=${BUILD_DIR:-build-tests}
bash scripts/install-deps.sh
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
ninja -C "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
