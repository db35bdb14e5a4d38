# The filter chained with PyMeshLab's own filters, the three recipes of docs/meshlab2025.md, each
# asserting a measured benefit over the same chain without our filter:
#  1. crease-preserving smoothing: select creases and corners, invert, Laplacian on the rest;
#  2. feature-aware simplification: our classes as vertex quality weight Quadric Edge Collapse,
#     so at the same face budget the input's crease vertices lie closer to the decimated mesh;
#  3. crease-preserving remeshing (the README's): the faces touching the crease lines kept,
#     isotropic remeshing of the rest, against the remesher alone at its default feature angle.
# The noisy sample cad_part_noise5.ply and its clean twin cad_part.ply share their vertex order;
# the twin is read straight from its file.
import numpy as np
import pytest

import pymeshlab
from conftest import CAD, CAD_CLEAN, load, ply_positions, read_ply, report

SMOOTHING = dict(stepsmoothnum=3, boundary=True, cotangentweight=False)


def test_crease_preserving_smoothing_keeps_creases_and_removes_noise():
    ms = load(CAD)
    noisy = ms.current_mesh().vertex_matrix().copy()
    ms.compute_normal_vector_voting(selection="Creases and corners")
    crease = ms.current_mesh().vertex_selection_array().copy()
    ms.apply_selection_inverse(invfaces=False, invverts=True)
    ms.apply_coord_laplacian_smoothing(selected=True, **SMOOTHING)
    chain = ms.current_mesh().vertex_matrix()

    plain_ms = load(CAD)  # the same smoothing on everything
    plain_ms.apply_coord_laplacian_smoothing(selected=False, **SMOOTHING)
    plain = plain_ms.current_mesh().vertex_matrix()
    clean = ply_positions(CAD_CLEAN)

    kept = int(np.sum(np.all(chain[crease] == noisy[crease], axis=1)))
    assert crease.sum() > 100
    assert kept == crease.sum(), "crease or corner vertices moved"
    # The bottom face (z = 0) away from its edges: distance to the true plane.
    flat = (np.abs(clean[:, 2]) < 1e-6) & (np.abs(clean[:, 0]) < 8) & (np.abs(clean[:, 1]) < 10)
    assert flat.sum() > 200
    rms = lambda p: float(np.sqrt(np.mean(p[flat, 2] ** 2)))
    err = lambda p: float(np.mean(np.linalg.norm(p[crease] - clean[crease], axis=1)))
    report("[chain smoothing] %d crease/corner vertices kept in place; bottom-face noise RMS %.4f -> %.4f (plain "
          "Laplacian %.4f); mean distance of crease vertices from the clean shape: noisy %.4f, chain %.4f, plain "
          "Laplacian %.4f" % (kept, rms(noisy), rms(chain), rms(plain), err(noisy), err(chain), err(plain)))
    assert rms(chain) < 0.5 * rms(noisy)
    assert err(chain) < err(plain)


def true_crease_vertices(angle=30.0):
    """Vertices of the clean twin where two of its incident faces meet at more than `angle` degrees."""
    verts, f = read_ply(CAD_CLEAN)
    v = np.stack([verts["x"], verts["y"], verts["z"]], axis=1).astype(float)
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    n /= np.linalg.norm(n, axis=1)[:, None]
    incident = [[] for _ in range(len(v))]
    for fi, tri in enumerate(f):
        for vi in tri:
            incident[vi].append(fi)
    cos_angle = np.cos(np.radians(angle))
    sharp = [i for i, fs in enumerate(incident) if len(fs) > 1 and np.min(n[fs] @ n[fs].T) < cos_angle]
    return np.array(sharp)


def distance_from_points(ms, points):
    """MeshLab's Hausdorff filter from the points (a new point-cloud layer) to the current mesh."""
    target = ms.current_mesh_id()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=points), "crease points")
    d = ms.get_hausdorff_distance(sampledmesh=ms.current_mesh_id(), targetmesh=target, samplevert=True,
                                  sampleface=False, sampleedge=False, samplenum=len(points),
                                  maxdist=pymeshlab.PureValue(1e6))
    ms.delete_current_mesh()
    ms.set_current_mesh(target)
    return d


def test_feature_aware_simplification_keeps_creases_closer_at_the_same_face_budget():
    idx = true_crease_vertices()
    assert len(idx) > 100
    original = ply_positions(CAD)[idx]
    truth = ply_positions(CAD_CLEAN)[idx]
    input_ms = load(CAD)  # kept alive: current_mesh() is a reference into its MeshSet
    budget = input_ms.current_mesh().face_number() // 10
    outcomes = {}
    for name in ["plain decimation", "quality-weighted (class)"]:
        ms = load(CAD)
        kwargs = {}
        if name.startswith("quality"):
            # Class as quality (0 surface, 1 crease, 2 corner), colours kept: MeshLab scales each
            # vertex's quadric by 1 + 99 q01^2, creases ~26 times, corners 100 times a surface vertex.
            ms.compute_normal_vector_voting(quality=6, color=2)
            kwargs["qualityweight"] = True
        ms.meshing_decimation_quadric_edge_collapse(targetfacenum=budget, **kwargs)
        faces = ms.current_mesh().face_number()
        d, t = distance_from_points(ms, original), distance_from_points(ms, truth)
        outcomes[name] = (faces, d["mean"], d["RMS"], d["max"], t["mean"])
        report("[chain simplification] %-26s %5d faces: distance of %d crease vertices: mean %.4f RMS %.4f max %.4f "
              "(clean crease positions: mean %.4f)" % ((name,) + (faces,) + (len(idx),) + outcomes[name][1:]))
    plain, weighted = outcomes["plain decimation"], outcomes["quality-weighted (class)"]
    for faces, *_ in (plain, weighted):
        assert abs(faces - budget) <= budget // 50
    report("[chain simplification] quality-weighted: mean crease distance %.1f%% of plain decimation's, RMS %.1f%%"
          % (100 * weighted[1] / plain[1], 100 * weighted[2] / plain[2]))
    assert weighted[1] < 0.8 * plain[1]
    assert weighted[2] < plain[2]


def test_crease_preserving_remeshing_keeps_the_lines_and_remeshes_the_rest():
    idx = true_crease_vertices(10.0)  # also the part's 18 and 29 deg creases
    assert len(idx) > 200
    original = ply_positions(CAD)[idx]
    input_ms = load(CAD)  # the input's face count and mean edge (the filter's summary gives it)
    input_faces = input_ms.current_mesh().face_number()
    lave = input_ms.compute_normal_vector_voting(update_normals=False, quality=9, color=2)["mean_edge_length"]
    remesh = dict(iterations=10, targetlen=pymeshlab.PureValue(2 * lave), featuredeg=30, checksurfdist=False)
    outcomes = {}
    for name in ["remesher alone, 30 deg", "recipe"]:
        ms = load(CAD)
        if name == "recipe":
            ms.compute_normal_vector_voting(crease_angle=15, selection="Vertices on crease lines")
            on_lines = ms.current_mesh().vertex_matrix()[ms.current_mesh().vertex_selection_array()].copy()
            ms.compute_selection_transfer_vertex_to_face(inclusive=False)
            ms.apply_selection_inverse(invfaces=True, invverts=True)
            ms.meshing_isotropic_explicit_remeshing(selectedonly=True, **remesh)
            kept = {tuple(p) for p in ms.current_mesh().vertex_matrix()}
            assert len(on_lines) > 200
            assert all(tuple(p) in kept for p in on_lines), "a vertex of a crease line moved"
        else:
            ms.meshing_isotropic_explicit_remeshing(selectedonly=False, **remesh)
        faces = ms.current_mesh().face_number()
        d = distance_from_points(ms, original)
        outcomes[name] = (faces, d["mean"], d["max"])
        report("[chain remeshing] %-24s %5d faces: distance of %d crease vertices (10 deg and up): mean %.4f max %.4f"
               % ((name, faces, len(idx)) + outcomes[name][1:]))
    alone, recipe = outcomes["remesher alone, 30 deg"], outcomes["recipe"]
    assert recipe[0] < input_faces // 2, "most of the mesh remeshed"
    assert recipe[1] < 0.8 * alone[1], "the remesher alone rounds the shallow creases"
