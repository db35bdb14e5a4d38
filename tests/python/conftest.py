# The Python tests run the filter in the real PyMeshLab 2025.7 with the plugin of the installed
# package pymeshlab_normal_voting (scripts/pymeshlab/run-tests-pymeshlab.sh builds and installs it
# into a fresh virtual environment). What they compare against comes from the project itself:
#   NVV_PARAMS_JSON  the parameter table as JSON (`nvv_docgen --print json`), or NVV_DOCGEN the
#                    program (default: the first build*/tools/nvv_docgen of the repository)
#   NVV_CLI          the command-line tool nvv (default: the first build*/filter_normal_voting/cli/nvv)
#   NVV_PYTEST_REPORT  a file the measurements are appended to (PyMeshLab redirects the standard
#                    output while it works, and some printed lines get lost)
import functools
import glob
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import pymeshlab
import pymeshlab_normal_voting

REPO = Path(__file__).resolve().parents[2]
SAMPLES = REPO / "sample_meshes"
CAD = SAMPLES / "cad_part_noise5.ply"         # noisy CAD part, 7,915 vertices
CAD_CLEAN = SAMPLES / "cad_part.ply"          # its clean twin, same vertex order
SMALL = SAMPLES / "paper_cylinder_noise5.ply"  # 1,024 vertices: for the many short runs
FILTER = pymeshlab_normal_voting.FILTER_NAME


def _first_existing(pattern):
    hits = sorted(glob.glob(str(REPO / pattern)))
    return hits[0] if hits else None


@functools.lru_cache(maxsize=None)
def parameter_table():
    """The filter's parameter table (filter_normal_voting/filter/filter_options.cpp) as nvv_docgen prints it."""
    path = os.environ.get("NVV_PARAMS_JSON")
    if path:
        with open(path) as f:
            return json.load(f)
    docgen = os.environ.get("NVV_DOCGEN") or _first_existing("build*/tools/nvv_docgen")
    if not docgen:
        raise RuntimeError("set NVV_PARAMS_JSON or NVV_DOCGEN (nvv_docgen --print json): the tests read the "
                           "parameter table from the project, not from a copy")
    return json.loads(subprocess.check_output([docgen, "--print", "json"]))


def parameters():
    return parameter_table()["parameters"]


@pytest.fixture(scope="session")
def table():
    return parameter_table()


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("NVV_CLI") or _first_existing("build*/filter_normal_voting/cli/nvv")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("no command-line tool nvv (set NVV_CLI)")
    return path


# PyMeshLab 2025.7.post1 keeps a static pointer to the log of the MeshSet that last applied a
# filter and resets it only when a filter succeeds. After a filter raised (any filter, MeshLab's
# own too), deleting that MeshSet and loading a mesh into another one writes into the freed log:
# a use-after-free that crashes at random (PyMeshLab issue #384). A successful filter on a MeshSet
# that stays alive resets the pointer; the tests do that before each test (a test that expects a
# refusal applies a successful filter to the same MeshSet afterwards, as a user script should).
_ANCHOR = pymeshlab.MeshSet()
_ANCHOR.create_cube()


def reset_pymeshlab_logger():
    _ANCHOR.set_selection_none()


@pytest.fixture(autouse=True)
def _pymeshlab_logger_reset():
    reset_pymeshlab_logger()
    yield
    reset_pymeshlab_logger()


def load(path=CAD):
    """A new MeshSet holding the mesh. Keep the MeshSet while using its meshes: current_mesh()
    returns a reference into it (`load(p).current_mesh()` reads freed memory)."""
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(path))
    return ms


def snapshot(mesh):
    """Everything the filter may write on a mesh, as arrays (copied)."""
    s = {
        "vertices": mesh.vertex_matrix().copy(),
        "faces": mesh.face_matrix().copy(),
        "normals": mesh.vertex_normal_matrix().copy(),
        "selection": mesh.vertex_selection_array().copy(),
        "has_quality": mesh.has_vertex_scalar(),
        "has_color": mesh.has_vertex_color(),
    }
    if mesh.has_vertex_scalar():
        s["quality"] = mesh.vertex_scalar_array().copy()
    if mesh.has_vertex_color():
        s["color"] = mesh.vertex_color_matrix().copy()
    return s


def assert_same_snapshot(a, b):
    assert a.keys() == b.keys()
    for k in a:
        if isinstance(a[k], np.ndarray):
            assert np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f"), k
        else:
            assert a[k] == b[k], k


_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
              "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
              "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


def read_ply(path):
    """A PLY file's vertex element (numpy structured array) and, for a binary file whose faces
    are triangles given as `list uchar int`, its faces (n x 3); for an ASCII file faces is None."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header") + len(b"end_header")
    end = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii").splitlines()
    fmt, elements = None, []  # elements: [name, count, [(property, type) or ("list", count type, item type)]]
    for line in header:
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property":
            elements[-1][2].append(("list", words[2], words[3]) if words[1] == "list" else (words[2], words[1]))
    assert elements and elements[0][0] == "vertex", "the vertex element must come first"
    count, fields = elements[0][1], elements[0][2]
    assert all(f[0] != "list" for f in fields), "list property in the vertex element"
    if fmt == "ascii":
        rows = data[end:].decode("ascii").split("\n")[:count]
        table = np.array([[float(x) for x in r.split()[:len(fields)]] for r in rows])
        out = np.zeros(count, dtype=[(n, _PLY_TYPES[t]) for n, t in fields])
        for i, (n, _) in enumerate(fields):
            out[n] = table[:, i]
        return out, None
    order = "<" if fmt == "binary_little_endian" else ">"
    dtype = np.dtype([(n, order + _PLY_TYPES[t]) for n, t in fields])
    vertices = np.frombuffer(data, dtype=dtype, count=count, offset=end)
    faces = None
    if len(elements) > 1 and elements[1][0] == "face" and len(elements[1][2]) == 1:
        _, ctype, itype = elements[1][2][0]
        fdtype = np.dtype([("n", order + _PLY_TYPES[ctype]), ("v", order + _PLY_TYPES[itype], 3)])
        f = np.frombuffer(data, dtype=fdtype, count=elements[1][1], offset=end + count * dtype.itemsize)
        assert np.all(f["n"] == 3), "not a triangle mesh"
        faces = f["v"].astype(np.int64)
    return vertices, faces


def read_ply_vertices(path):
    """The vertex element of a PLY file (binary or ASCII) as a numpy structured array."""
    return read_ply(path)[0]


def ply_positions(path):
    v = read_ply_vertices(path)
    return np.stack([v["x"], v["y"], v["z"]], axis=1).astype(float)


def report(line):
    """A measurement: printed, and appended to $NVV_PYTEST_REPORT when set."""
    print(line, flush=True)
    path = os.environ.get("NVV_PYTEST_REPORT")
    if path:
        with open(path, "a") as f:
            f.write(line + "\n")


def rss_bytes():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) * 1024
    return 0
