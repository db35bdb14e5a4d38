"""The Python libraries' normal and curvature estimators on the smooth-surface meshes of the
accuracy benchmark, scored together with this filter's default by one implementation of the
benchmark's metrics.

usage: python_peers.py MESH_DIR OUT_CSV

MESH_DIR holds what `nvv_bench_accuracy export MESH_DIR` writes: the meshes of the "grids" and
"variants" sections (same shapes, seeds and noise) as binary PLY with the truth and this filter's
default estimates at k = 3 and 5 as vertex properties, listed in meshes.csv. OUT_CSV gets one
row per section, shape, noise level and estimator (the columns of smooth_grids.csv, with
"section" first); OUT_CSV without .csv + "_versions.txt" the packages' versions, the estimators
whose curvature sign was flipped and PyMeshLab's default scale on each shape in l_ave.

The metrics are bench/smooth.cpp's MeasureOne, over the scored vertices of the three seeds:
  normal     angle between the estimated and the true normal, in degrees, either orientation
             (|cos|: an unoriented normal scores as its better orientation);
  direction  angle between the direction of the smaller curvature and the truth (where defined);
  curvature  100 |k - k_true| R for k1 and for k2 (R: 31 mm on the grids, the tube radius on the
             torus);
median = v[n / 2], p90 = v[min(n - 1, floor(0.9 n))], mean = the sum in ascending order / n,
as nvv_test::StatsOf. Every estimator's curvature sign is calibrated as CalibrateSigns does: on
the clean sphere grid (seed 1) the sum of k1 + k2 over the scored vertices must be positive,
else k1, k2 = -k2, -k1 and the directions swap. Curvatures are ordered k1 >= k2 with their
directions. A non-finite curvature counts as 0 (as the benchmark does for MeshLab's), a zero or
non-finite normal or direction as 90 degrees.

kind, as in the benchmark: 0 this filter's default, 2 a peer at the same radius k l_ave,
3 a peer with its own fixed neighbourhood (compared at every k).
"""
import csv
import importlib.metadata
import math
import os
import sys
import time
from contextlib import contextmanager

import numpy as np

os.environ.setdefault("OMP_NUM_THREADS", "1")

PACKAGES = ["pymeshlab", "libigl", "trimesh", "rtree", "open3d-cpu", "numpy", "scipy"]


# ---- input
def read_ply(path):
    """Vertex properties (a dict of arrays), faces (m x 3 int64) and the header comments."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    comments, props, nv, nf = {}, [], 0, 0
    types = {"double": "<f8", "uchar": "u1", "int": "<i4", "float": "<f4"}
    element = None
    for line in header:
        w = line.split()
        if w[0] == "comment":
            comments[w[1]] = " ".join(w[2:])
        elif w[0] == "element":
            element = w[1]
            if element == "vertex":
                nv = int(w[2])
            elif element == "face":
                nf = int(w[2])
        elif w[0] == "property" and element == "vertex":
            props.append((w[2], types[w[1]]))
    vdt = np.dtype(props)
    verts = np.frombuffer(data, dtype=vdt, count=nv, offset=end)
    fdt = np.dtype([("n", "u1"), ("i", "<i4", (3,))])
    faces = np.frombuffer(data, dtype=fdt, count=nf, offset=end + nv * vdt.itemsize)
    if not (faces["n"] == 3).all():
        sys.exit("python_peers.py: %s: not a triangle mesh" % path)
    return {k: verts[k].astype(np.float64) for k in verts.dtype.names}, faces["i"].astype(np.int64), comments


def vec(v, prefix):
    return np.stack([v[prefix + "x"], v[prefix + "y"], v[prefix + "z"]], axis=1)


# ---- the estimators. Each returns a dict with n (normals) and, if it has them, k1, k2
# (curvatures, any order and sign) and t1, t2 (their directions).
class Estimator:
    def __init__(self, name, kind, k, fn):
        self.name, self.kind, self.k, self.fn = name, kind, k, fn
        self.sign = 1.0
        self.seconds = 0.0


@contextmanager
def quiet_stdout():
    """Silences what compiled code prints to file descriptor 1 (pymeshlab's Scale Dependent
    Quadric Fitting prints a line per call)."""
    sys.stdout.flush()
    saved = os.dup(1)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
    try:
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


def unit(a):
    a = np.asarray(a, dtype=np.float64)
    n = np.linalg.norm(a, axis=1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(n > 0, a / np.where(n > 0, n, 1), 0.0)


def pymeshlab_curvature(method, scale_k=None):
    import pymeshlab

    def fn(mesh):
        ms = pymeshlab.MeshSet()
        # As a loaded mesh: MeshLab computes angle-weighted vertex normals (the curvature filter
        # keeps them).
        ms.add_mesh(pymeshlab.Mesh(mesh["V"], mesh["F"]))
        args = {"method": method}
        if scale_k is not None:
            args["scale"] = pymeshlab.PureValue(scale_k * mesh["lave"])
        out = {}
        # The filter writes K1 (the curvature along direction 1) or K2 as the vertex quality:
        # vcglib's VertexFromMinCurvatureDir writes K1, VertexFromMaxCurvatureDir K2.
        for which, cc in (("k1", "Min Curvature"), ("k2", "Max Curvature")):
            with quiet_stdout():
                ms.compute_curvature_principal_directions_per_vertex(curvcolormethod=cc, **args)
            m = ms.current_mesh()
            if m.vertex_number() != len(mesh["V"]):
                sys.exit("python_peers.py: pymeshlab changed the vertex count")
            out[which] = m.vertex_scalar_array().copy()
        out["t1"] = m.vertex_curvature_principal_dir1_matrix().copy()
        out["t2"] = m.vertex_curvature_principal_dir2_matrix().copy()
        out["n"] = m.vertex_normal_matrix().copy()
        return out

    return fn


def ball_counts(V, r):
    from scipy.spatial import cKDTree
    return np.array([len(x) for x in cKDTree(V).query_ball_point(V, r)])


def pymeshlab_cloud_normals(neighbours_k=None):
    import pymeshlab

    def fn(mesh):
        ms = pymeshlab.MeshSet()
        ms.add_mesh(pymeshlab.Mesh(mesh["V"]))  # the vertices as a point cloud
        if neighbours_k is None:
            ms.compute_normal_for_point_clouds()
        else:  # as many neighbours as the ball of radius k l_ave holds on average
            n = int(round(ball_counts(mesh["V"], neighbours_k * mesh["lave"]).mean()))
            ms.compute_normal_for_point_clouds(k=n)
        return {"n": ms.current_mesh().vertex_normal_matrix().copy()}

    return fn


def igl_curvature(radius=None):
    import igl

    def fn(mesh):
        if radius is None:  # libigl's default: radius 5, k-ring
            pd1, pd2, pv1, pv2, _ = igl.principal_curvature(mesh["V"], mesh["F"])
        else:  # the ball of radius `radius` times libigl's mean edge length (igl::avg_edge_length
            # counts each interior edge twice: within 0.3 % of l_ave on these meshes)
            pd1, pd2, pv1, pv2, _ = igl.principal_curvature(mesh["V"], mesh["F"], radius=int(radius), useKring=False)
        return {"n": igl.per_vertex_normals(mesh["V"], mesh["F"]), "k1": pv1, "k2": pv2, "t1": pd1, "t2": pd2}

    return fn


def trimesh_curvature(k):
    import trimesh
    import trimesh.curvature as tc

    def fn(mesh):
        t = trimesh.Trimesh(mesh["V"], mesh["F"], process=False)
        r = k * mesh["lave"]
        # Curvature measures of the ball of radius r divided by its area on a smooth surface,
        # pi r^2 (exact on a sphere through the centre): Gaussian and mean curvature.
        K = tc.discrete_gaussian_curvature_measure(t, mesh["V"], r) / (math.pi * r * r)
        H = tc.discrete_mean_curvature_measure(t, mesh["V"], r) / (math.pi * r * r)
        d = np.sqrt(np.maximum(H * H - K, 0))
        return {"n": np.asarray(t.vertex_normals), "k1": H + d, "k2": H - d}

    return fn


def open3d_normals(k=None, max_nn=None):
    import open3d as o3d

    def fn(mesh):
        pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(mesh["V"]))
        if k is None:
            pc.estimate_normals()  # its default: the 30 nearest points
        elif max_nn is None:
            pc.estimate_normals(search_param=o3d.geometry.KDTreeSearchParamRadius(k * mesh["lave"]))
        else:
            pc.estimate_normals(search_param=o3d.geometry.KDTreeSearchParamHybrid(k * mesh["lave"], max_nn))
        return {"n": np.asarray(pc.normals)}

    return fn


def from_file(k):
    def fn(mesh):
        v = mesh["props"]
        p = "nvv%d_" % k
        return {"n": vec(v, p + "n"), "k1": v[p + "k1"], "k2": v[p + "k2"], "t2": vec(v, p + "t2"),
                "t1": np.zeros((len(v["x"]), 3))}

    return fn


def estimators():
    e = [Estimator("NVV quadric (default) k=%d" % k, 0, k, from_file(k)) for k in (3, 5)]
    for name, method in (("Taubin approximation", "Taubin approximation"), ("Normal Cycles", "Normal Cycles"),
                         ("Quadric Fitting", "Quadric Fitting")):
        e.append(Estimator("pymeshlab %s" % name, 3, 0, pymeshlab_curvature(method)))
    e.append(Estimator("pymeshlab PCA (default scale)", 3, 0, pymeshlab_curvature("Principal Component Analysis")))
    e.append(Estimator("pymeshlab Scale Dependent QF (default scale)", 3, 0,
                       pymeshlab_curvature("Scale Dependent Quadric Fitting")))
    e.append(Estimator("pymeshlab point-cloud normals (k=10)", 3, 0, pymeshlab_cloud_normals()))
    e.append(Estimator("libigl principal_curvature (default, 5-ring)", 3, 0, igl_curvature()))
    e.append(Estimator("trimesh vertex normals", 3, 0, lambda m: {"n": np.asarray(
        __import__("trimesh").Trimesh(m["V"], m["F"], process=False).vertex_normals)}))
    e.append(Estimator("open3d normals (default, 30 nearest)", 3, 0, open3d_normals()))
    for k in (3, 5):
        e.append(Estimator("pymeshlab PCA r=%d l_ave" % k, 2, k, pymeshlab_curvature("Principal Component Analysis", k)))
        e.append(Estimator("pymeshlab Scale Dependent QF r=%d l_ave" % k, 2, k,
                           pymeshlab_curvature("Scale Dependent Quadric Fitting", k)))
        e.append(Estimator("pymeshlab point-cloud normals, ball of r=%d l_ave" % k, 2, k, pymeshlab_cloud_normals(k)))
        e.append(Estimator("libigl principal_curvature r=%d l_ave" % k, 2, k, igl_curvature(k)))
        e.append(Estimator("trimesh curvature measures r=%d l_ave" % k, 2, k, trimesh_curvature(k)))
        e.append(Estimator("open3d normals r=%d l_ave" % k, 2, k, open3d_normals(k)))
        e.append(Estimator("open3d normals r=%d l_ave, 30 nearest" % k, 2, k, open3d_normals(k, 30)))
    return e


# ---- scoring (bench/smooth.cpp's MeasureOne and nvv_test::StatsOf)
def normalized(est):
    """k1 >= k2 with their directions, non-finite curvatures as 0."""
    out = {"n": unit(est["n"])}
    if "k1" not in est:
        return out
    a, b = np.asarray(est["k1"], dtype=np.float64), np.asarray(est["k2"], dtype=np.float64)
    bad = ~(np.isfinite(a) & np.isfinite(b))
    a, b = np.where(bad, 0.0, a), np.where(bad, 0.0, b)
    da = np.asarray(est.get("t1", np.zeros((len(a), 3))), dtype=np.float64)
    db = np.asarray(est.get("t2", np.zeros((len(a), 3))), dtype=np.float64)
    swap = a < b
    out["k1"], out["k2"] = np.where(swap, b, a), np.where(swap, a, b)
    out["t1"], out["t2"] = np.where(swap[:, None], db, da), np.where(swap[:, None], da, db)
    out["has_dir"] = "t2" in est
    return out


def apply_sign(sign, e):
    if sign > 0 or "k1" not in e:
        return e
    e = dict(e)
    e["k1"], e["k2"] = -e["k2"], -e["k1"]
    e["t1"], e["t2"] = e["t2"], e["t1"]
    return e


def angle_deg(a, b):
    """nvv_test::AngleDeg: acos(min(1, |a.b|)) of the normalized vectors; zero vectors: 90."""
    a, b = unit(a), unit(b)
    c = np.abs(a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1] + a[:, 2] * b[:, 2])
    c = np.where(np.isfinite(c), c, 0.0)
    return np.arccos(np.minimum(1.0, c)) * 180.0 / 3.14159265358979323846


def stats(v):
    v = np.sort(np.asarray(v, dtype=np.float64))
    n = len(v)
    if n == 0:
        return [float("nan")] * 3
    return [v[n // 2], v[min(n - 1, int(0.9 * n))], np.cumsum(v)[-1] / n]


def main():
    mesh_dir, out_csv = sys.argv[1:3]
    with open(os.path.join(mesh_dir, "meshes.csv")) as f:
        listing = list(csv.DictReader(f))
    ests = estimators()

    def load(row):
        props, F, comments = read_ply(os.path.join(mesh_dir, row["file"]))
        return {"V": np.ascontiguousarray(vec(props, "")), "F": np.ascontiguousarray(F), "props": props,
                "lave": float(comments["l_ave"]), "scale": float(comments["curvature_scale"])}

    # Curvature signs on the clean sphere grid, seed 1 (CalibrateSigns).
    cal = next(r for r in listing if r["section"] == "grids" and r["shape"] == "sphere" and r["noise"] == "0"
               and r["seed"] == "1")
    m = load(cal)
    scored = m["props"]["scored"] > 0
    for e in ests:
        est = normalized(e.fn(m))
        if "k1" in est:
            s = est["k1"] + est["k2"]
            e.sign = -1.0 if s[scored & np.isfinite(s)].sum() < 0 else 1.0

    # PyMeshLab's default scale (PCA, Scale Dependent Quadric Fitting) is 10 % of the bounding
    # box diagonal: in l_ave on each clean shape, for the page.
    scales = []
    for r in listing:
        if r["noise"] == "0" and r["seed"] == "1":
            m = load(r)
            scales.append((r["section"], r["shape"], 0.1 * np.linalg.norm(m["V"].max(0) - m["V"].min(0)) / m["lave"]))
    groups = {}
    for r in listing:
        groups.setdefault((r["section"], r["shape"], r["noise"]), []).append(r)
    rows = []
    for (section, shape, noise), rs in groups.items():
        acc = {e.name: {"normal": [], "dir": [], "curv": []} for e in ests}
        for r in sorted(rs, key=lambda r: int(r["seed"])):
            m = load(r)
            v = m["props"]
            use = v["scored"] > 0
            has_dir = use & (v["has_dir"] > 0)
            tn, tt2 = vec(v, "true_n"), vec(v, "true_t2")
            for e in ests:
                t0 = time.perf_counter()
                est = apply_sign(e.sign, normalized(e.fn(m)))
                e.seconds += time.perf_counter() - t0
                a = acc[e.name]
                a["normal"].append(angle_deg(est["n"][use], tn[use]))
                if "k1" in est:
                    if est["has_dir"]:
                        a["dir"].append(angle_deg(est["t2"][has_dir], tt2[has_dir]))
                    c1 = 100 * np.abs(est["k1"][use] - v["true_k1"][use]) * m["scale"]
                    c2 = 100 * np.abs(est["k2"][use] - v["true_k2"][use]) * m["scale"]
                    a["curv"].append(np.stack([c1, c2], axis=1).ravel())
        for e in ests:
            a = acc[e.name]
            cells = []
            for key in ("normal", "dir", "curv"):
                cells += stats(np.concatenate(a[key]) if a[key] else [])
            rows.append([section, shape, noise, e.name, e.kind, e.k] + cells)
        print("python peers: %s %s %s %% done" % (section, shape, noise), flush=True)

    with open(out_csv, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")  # quotes the names that hold a comma
        w.writerow(["section", "shape", "noise", "estimator", "kind", "k", "normal_med", "normal_p90", "normal_mean",
                    "dir_med", "dir_p90", "dir_mean", "curv_med", "curv_p90", "curv_mean"])
        for r in rows:  # numbers as the benchmark prints them (%g)
            w.writerow(r[:4] + ["%d" % r[4], "%g" % r[5]] + ["%g" % float(x) for x in r[6:]])
    with open(os.path.splitext(out_csv)[0] + "_versions.txt", "w") as f:
        for p in PACKAGES:
            f.write("%s %s\n" % (p, importlib.metadata.version(p)))
        f.write("python %s\n" % sys.version.split()[0])
        for e in ests:
            if e.sign < 0:
                f.write("flipped %s\n" % e.name)
        for section, shape, x in scales:
            f.write("default_scale %s|%s|%.6g\n" % (section, shape, x))
    for e in sorted(ests, key=lambda e: -e.seconds):
        print("  %6.1f s  %s" % (e.seconds, e.name))


if __name__ == "__main__":
    main()
