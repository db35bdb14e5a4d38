#!/usr/bin/env bash
# Builds the filter for the real PyMeshLab 2025.7.post1 (the wheel from the Python Package Index),
# packs it as the wheel pymeshlab_normal_voting, installs that into a fresh virtual environment and
# runs the Python test suite (tests/python/) and the README's Python example there. On Debian
# bookworm after `bash scripts/install-deps.sh`; needs the network for pip (PyPI) and, when no copy
# is at hand, for MeshLab 2025.07's source from Debian's archive. Runs on the host, no chroot:
#   1. venv-build: pymeshlab, setuptools (pinned in constraints.txt)
#   2. MeshLab 2025.07's source (headers + vcglib): $NVV_MESHLAB_SRC, else the one the sid-chroot
#      part unpacked (build-2025/chroot/nvv-work/meshlab-src), else Debian's orig tarball
#      (checked against its SHA-256) unpacked into build-pymeshlab/meshlab-src
#   3. the command-line tool nvv and nvv_docgen (the CLI reference, the parameter table as JSON)
#   4. the plugin: double scalars, bookworm's compiler and Qt 5.15.8 headers, linked against
#      PyMeshLab's own libmeshlab-common.so; RUNPATH $ORIGIN/../../pymeshlab/lib:$ORIGIN/..
#   5. the wheel dist/pymeshlab_normal_voting-0.1.0-py3-none-manylinux_2_35_x86_64.whl
#   6. venv-test: a fresh venv with only the wheel and the pinned test tools; pytest; README example
# Everything goes under build-pymeshlab/ (NVV_PYMESHLAB_BUILD). Ends with the line
# "pytest: N passed, M failed, K skipped" and the elapsed time; exits non-zero on any failure.
# Settings: NVV_JOBS (compile jobs, default nproc), NVV_CPU_LOCK (a file: compiles and the suite
# run under `flock` on it), NVV_PYTHON (default /usr/bin/python3), NVV_MESHLAB_SRC, NVV_CLI and
# NVV_DOCGEN (use these builds instead of building them), NVV_MIRROR (Debian archive URI).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
build=${NVV_PYMESHLAB_BUILD:-$repo/build-pymeshlab}
python=${NVV_PYTHON:-/usr/bin/python3}
jobs=${NVV_JOBS:-$(nproc)}
constraints=$here/constraints.txt
start=$(date +%s)
log() { echo "[pymeshlab $(date +%H:%M:%S) +$(( $(date +%s) - start ))s] $*"; }
died=0
die() { died=1; echo "[pymeshlab] FAILED: $*" >&2; echo "[pymeshlab] FAILED after $(( $(date +%s) - start )) s" >&2; exit 1; }
# Any other failing command (set -e) is reported too.
trap 'rc=$?; [ $rc -eq 0 ] || [ $died = 1 ] || echo "[pymeshlab] FAILED (exit $rc) after $(( $(date +%s) - start )) s" >&2' EXIT
heavy() { if [ -n "${NVV_CPU_LOCK:-}" ]; then flock "$NVV_CPU_LOCK" "$@"; else "$@"; fi; }
mkdir -p "$build"

# The pins of every package pip installs; pip itself is the one of Debian's python3-venv.
pin() { sed -n "s/^$1==//p" "$constraints"; }
pymeshlab_version=$(pin pymeshlab)
[ -n "$pymeshlab_version" ] || die "no pymeshlab pin in $constraints"
"$python" -c 'import sys; assert sys.version_info[:2] >= (3, 9)' || die "$python is older than Python 3.9"
"$python" -m venv --help >/dev/null 2>&1 || die "$python has no venv module (apt-get install python3-venv)"

# ---- 1. build environment: PyMeshLab's wheel holds the libmeshlab-common.so to link against
log "== venv-build: pymeshlab==$pymeshlab_version, setuptools==$(pin setuptools)"
if [ ! -x "$build/venv-build/bin/python" ]; then "$python" -m venv "$build/venv-build"; fi
"$build/venv-build/bin/pip" install -q --disable-pip-version-check -c "$constraints" \
  "pymeshlab==$pymeshlab_version" "setuptools==$(pin setuptools)" > "$build/pip-build.log" 2>&1 ||
  { cat "$build/pip-build.log"; die "pip install into venv-build"; }
pmlib=$("$build/venv-build/bin/python" -c 'import os, pymeshlab; print(os.path.join(os.path.dirname(pymeshlab.__file__), "lib"))' 2>/dev/null | tail -1)
[ -f "$pmlib/libmeshlab-common.so" ] || die "no libmeshlab-common.so in PyMeshLab's wheel ($pmlib)"
qt_wheel=$(grep -ao 'Qt 5\.[0-9]*\.[0-9]*' "$pmlib/libQt5Core.so.5" | head -1 || true)
log "PyMeshLab's MeshLab core: $pmlib (bundles ${qt_wheel:-an unknown Qt})"

# ---- 2. MeshLab 2025.07's source
meshlab_src=${NVV_MESHLAB_SRC:-}
chroot_src=${NVV_BUILD_2025:-$repo/build-2025}/chroot/nvv-work/meshlab-src
if [ -z "$meshlab_src" ] && [ -f "$chroot_src/src/common/plugins/interfaces/filter_plugin.h" ]; then meshlab_src=$chroot_src; fi
if [ -z "$meshlab_src" ]; then
  meshlab_src=$build/meshlab-src
  if [ ! -f "$meshlab_src/src/common/plugins/interfaces/filter_plugin.h" ]; then
    # The orig tarball of Debian's meshlab 2025.07~dfsg (sid), the same the sid chroot's
    # `apt-get source` fetches; its src/common equals upstream's tag MeshLab-2025.07.
    tarball=meshlab_2025.07~dfsg.orig.tar.xz
    sha256=d22c98d362f2a284e481af8dbfc272b2222f5b9c67b3cf8bec57d1c3161886f4
    source "$repo/scripts/meshlab2025/chroot-env.sh"
    url="$(nvv_mirror)/pool/main/m/meshlab/$tarball"
    log "== MeshLab 2025.07 source: $url"
    "$python" - "$url" "$build/$tarball" <<'PY' || die "download of $url"
import sys, urllib.request
with urllib.request.urlopen(sys.argv[1], timeout=120) as r, open(sys.argv[2], "wb") as f:
    f.write(r.read())
PY
    echo "$sha256  $build/$tarball" | sha256sum -c --quiet - || die "$tarball: SHA-256 differs"
    rm -rf "$meshlab_src.tmp" && mkdir -p "$meshlab_src.tmp"
    tar -xf "$build/$tarball" -C "$meshlab_src.tmp" --strip-components=1
    rm -rf "$meshlab_src" && mv "$meshlab_src.tmp" "$meshlab_src" && rm -f "$build/$tarball"
  fi
fi
[ -f "$meshlab_src/src/common/plugins/interfaces/filter_plugin.h" ] || die "no MeshLab 2025.07 source tree at $meshlab_src"
grep -q '2025.07' "$meshlab_src/ML_VERSION" 2>/dev/null || die "$meshlab_src is not MeshLab 2025.07 ($(cat "$meshlab_src/ML_VERSION" 2>/dev/null))"
log "MeshLab source: $meshlab_src"

# ---- 3. the command-line tool and the docs generator (the main build's own CMake project)
cli=${NVV_CLI:-}
docgen=${NVV_DOCGEN:-}
if [ -z "$cli" ] || [ -z "$docgen" ]; then
  log "== nvv and nvv_docgen (-j$jobs)"
  cmake -S "$repo" -B "$build/main" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNVV_BUILD_TESTS=OFF \
    -DNVV_BUILD_PLUGIN=OFF > "$build/main-configure.log" 2>&1 || { cat "$build/main-configure.log"; die "configure of the main build"; }
  heavy ninja -C "$build/main" -j "$jobs" nvv_cli nvv_docgen > "$build/main-build.log" 2>&1 ||
    { tail -40 "$build/main-build.log"; die "build of nvv and nvv_docgen"; }
  cli=${cli:-$build/main/filter_normal_voting/cli/nvv}
  docgen=${docgen:-$build/main/tools/nvv_docgen}
fi
[ -x "$cli" ] || die "no command-line tool at $cli"
"$docgen" --print json > "$build/parameters.json" || die "$docgen --print json"

# ---- 4. the plugin, against PyMeshLab's own core
log "== plugin (double, against PyMeshLab's libmeshlab-common.so, -j$jobs)"
cmake -S "$repo/filter_normal_voting/meshlab/v2025" -B "$build/plugin" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DNVV_MESHLAB_SCALAR=double -DNVV_MESHLAB_SRC="$meshlab_src" -DNVV_MESHLAB_LIB_DIR="$pmlib" -DNVV_BUILD_TESTS=OFF \
  -DCMAKE_BUILD_WITH_INSTALL_RPATH=ON '-DCMAKE_INSTALL_RPATH=$ORIGIN/../../pymeshlab/lib;$ORIGIN/..' \
  > "$build/plugin-configure.log" 2>&1 || { cat "$build/plugin-configure.log"; die "configure of the plugin"; }
heavy ninja -C "$build/plugin" -j "$jobs" filter_normal_voting > "$build/plugin-build.log" 2>&1 ||
  { tail -40 "$build/plugin-build.log"; die "build of the plugin"; }
plugin=$build/plugin/libfilter_normal_voting.so

# What the plugin needs from the system must exist where PyMeshLab's wheel runs (its tag is
# manylinux_2_35: glibc 2.35, and Ubuntu 22.04's libstdc++ of GCC 12, GLIBCXX_3.4.30); everything
# else must be a library PyMeshLab bundles (loaded by then; found through the RUNPATH too).
maxver() { objdump -T "$plugin" | grep -o "$1_[0-9.]*" | sed "s/^$1_//" | sort -V | tail -1; }
vle() { [ "$(printf '%s\n%s\n' "$1" "$2" | sort -V | tail -1)" = "$2" ]; }
glibc=$(maxver GLIBC) glibcxx=$(maxver GLIBCXX) cxxabi=$(maxver CXXABI)
vle "$glibc" 2.35 || die "the plugin needs GLIBC_$glibc, newer than manylinux_2_35"
vle "$glibcxx" 3.4.30 || die "the plugin needs GLIBCXX_$glibcxx, newer than GCC 12's libstdc++"
vle "$cxxabi" 1.3.13 || die "the plugin needs CXXABI_$cxxabi, newer than GCC 12's libstdc++"
for lib in $(readelf -d "$plugin" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
  case $lib in
    libc.so.6|libm.so.6|libstdc++.so.6|libgcc_s.so.1) ;;
    *) [ -e "$pmlib/$lib" ] || die "the plugin needs $lib, which PyMeshLab's wheel does not bundle" ;;
  esac
done
runpath=$(readelf -d "$plugin" | sed -n 's/.*(RUNPATH).*\[\(.*\)\]/\1/p')
log "plugin: $(du -k "$plugin" | cut -f1) KB; needs GLIBC_$glibc GLIBCXX_$glibcxx CXXABI_$cxxabi; RUNPATH $runpath"

# ---- 5. the wheel
log "== wheel"
rm -rf "$build/wheel-src" "$build/dist"
cp -r "$repo/python" "$build/wheel-src"
rm -rf "$build/wheel-src/build" "$build/wheel-src"/*.egg-info
mkdir -p "$build/wheel-src/pymeshlab_normal_voting/lib"
cp "$plugin" "$build/wheel-src/pymeshlab_normal_voting/lib/"
"$build/venv-build/bin/pip" wheel -q --disable-pip-version-check --no-deps --no-build-isolation \
  -w "$build/dist" "$build/wheel-src" > "$build/wheel.log" 2>&1 || { cat "$build/wheel.log"; die "pip wheel"; }
wheel=$(ls "$build"/dist/pymeshlab_normal_voting-*.whl)
case $(basename "$wheel") in
  pymeshlab_normal_voting-0.1.0-py3-none-manylinux_2_35_x86_64.whl) ;;
  *) die "unexpected wheel name $(basename "$wheel")" ;;
esac
# (the listing first: grep -q would stop reading early and fail the pipe)
listing=$("$python" -m zipfile -l "$wheel")
grep -q '^pymeshlab_normal_voting/lib/libfilter_normal_voting.so ' <<< "$listing" || die "the wheel lacks the plugin at its root"
log "wheel: $wheel ($(du -k "$wheel" | cut -f1) KB)"

# ---- 6. a fresh environment with the wheel only, the suite, the README's example
log "== venv-test: fresh venv, pip install the wheel"
rm -rf "$build/venv-test"
"$python" -m venv "$build/venv-test"
vpy=$build/venv-test/bin/python
"$vpy" -m pip install -q --disable-pip-version-check -c "$constraints" "$wheel" \
  "pytest==$(pin pytest)" "numpy==$(pin numpy)" > "$build/pip-test.log" 2>&1 || { cat "$build/pip-test.log"; die "pip install of the wheel"; }
"$vpy" -m pip check > /dev/null || die "pip check in venv-test"
"$vpy" -m pip freeze --all > "$build/venv-test-freeze.txt"
"$vpy" -c 'import pymeshlab, pymeshlab_normal_voting as p; assert p.FILTER_NAME in pymeshlab.filter_list(); print("loaded", p.PLUGIN_PATH)' ||
  die "import pymeshlab_normal_voting"

log "== pytest tests/python"
suite_start=$(date +%s)
rm -f "$build/pytest.xml" "$build/measurements.txt"
set +e
( cd "$repo" && NVV_CLI="$cli" NVV_PARAMS_JSON="$build/parameters.json" NVV_PYTEST_REPORT="$build/measurements.txt" \
  heavy "$vpy" -m pytest tests/python -p no:cacheprovider -rs -v --junitxml="$build/pytest.xml" \
  --basetemp="$build/pytest-tmp" ) 2>&1 | tee "$build/pytest.log"
pytest_rc=${PIPESTATUS[0]}
set -e
suite_seconds=$(( $(date +%s) - suite_start ))
[ ! -f "$build/measurements.txt" ] || cat "$build/measurements.txt"
# The tally from pytest's JUnit XML; a run that died before writing it (a crash) counts as 1 failed.
read -r passed failed skipped < <("$python" - "$build/pytest.xml" <<'PY'
import sys, xml.etree.ElementTree as ET
try:
    root = ET.parse(sys.argv[1]).getroot()
except Exception:
    print(0, 1, 0)
    sys.exit()
suites = [root] if root.tag == "testsuite" else root.findall("testsuite")
n = {k: sum(int(s.get(k, 0)) for s in suites) for k in ["tests", "failures", "errors", "skipped"]}
print(n["tests"] - n["failures"] - n["errors"] - n["skipped"], n["failures"] + n["errors"], n["skipped"])
PY
)

log "== README example (as printed, in venv-test)"
example_rc=0
rm -rf "$build/readme-example" && mkdir -p "$build/readme-example"
sed -n '/<!-- pymeshlab-example -->/,/<!-- end pymeshlab-example -->/p' "$repo/README.md" |
  sed -n '/^```python$/,/^```$/p' | sed '1d;$d' > "$build/readme-example/example.py"
[ -s "$build/readme-example/example.py" ] || die "no Python example between the pymeshlab-example markers in README.md"
cp "$repo/sample_meshes/cad_part_noise5.ply" "$build/readme-example/"
(cd "$build/readme-example" && "$vpy" example.py) > "$build/readme-example/output.txt" 2>&1 || example_rc=$?
cat "$build/readme-example/output.txt"
if [ $example_rc -eq 0 ] && grep -q crease_vertices "$build/readme-example/output.txt"; then
  log "README example: ok"
else
  echo "[pymeshlab] README example FAILED (exit $example_rc)" >&2; example_rc=1
fi

echo "pymeshlab: pymeshlab==$pymeshlab_version (${qt_wheel:-Qt ?}), wheel $(basename "$wheel"), suite ${suite_seconds} s, total $(( $(date +%s) - start )) s"
echo "pytest: $passed passed, $failed failed, $skipped skipped"
[ "$pytest_rc" -eq 0 ] || die "pytest exited $pytest_rc"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ] || die "pytest: $failed failed, $passed passed"
[ "$example_rc" -eq 0 ] || die "the README's Python example"
log "PyMeshLab part passed in $(( $(date +%s) - start )) s"
