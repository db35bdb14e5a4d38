# Every parameter of the table changes what it should when set through PyMeshLab. A parameter
# added to the table without a case here fails test_every_parameter_has_a_case.
import numpy as np
import pytest

import pymeshlab
from conftest import CAD, CAD_CLEAN, load, parameters

CREASE, CORNER = 1, 2


def run(path=CAD, **kwargs):
    """Runs the filter on a fresh mesh; returns the dict and the mesh's per-vertex outputs."""
    ms = path if isinstance(path, pymeshlab.MeshSet) else load(path)
    out = ms.compute_normal_vector_voting(**kwargs)
    m = ms.current_mesh()
    return {
        "dict": out,
        "quality": m.vertex_scalar_array().copy(),
        "color": m.vertex_color_array().copy(),
        "normal": m.vertex_normal_matrix().copy(),
        "selected": m.vertex_selection_array().copy(),
        "cls": m.vertex_custom_scalar_attribute_array("nvv_class").copy(),
    }


def count(r, *classes):
    return int(sum(np.sum(r["cls"] == c) for c in classes))


def quality_diff(a, b):
    return float(np.max(np.abs(a["quality"] - b["quality"])))


def colour_diffs(a, b):
    return int(np.sum(a["color"] != b["color"]))


def roof(alpha_deg=150.0, n=33, half=16.0, length=32.0):
    """Two planes meeting along the y axis, their normals alpha apart (the sharp roof of the
    project's synthetic shapes): only the sign-aware rule finds its ridge."""
    slope = np.tan(np.radians(alpha_deg) / 2)
    s, t = np.meshgrid(np.arange(n) / (n - 1), np.arange(n) / (n - 1))
    x = half * (2 * s - 1)
    v = np.stack([x, length * (t - 0.5), -slope * np.abs(x)], axis=-1).reshape(-1, 3)
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            faces += [(a, b, c), (a, c, d)]
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=np.array(faces, dtype=np.int32)))
    return ms


@pytest.fixture(scope="module")
def base():
    return run()


def check_neighbourhood_k(base):
    assert quality_diff(base, run(neighbourhood_k=6)) > 1e-3


def check_auto_k(base):
    # The sample has 5 % of l_ave noise along its normals: automatic k estimates it and runs at
    # 3 + 2 (noise - 2 %) / 8 % (about 3.75); the clean twin keeps 3.
    r = run(auto_k=True)
    d = r["dict"]
    assert base["dict"]["k_used"] == 3.0 and d["noise_estimate"] == pytest.approx(base["dict"]["noise_estimate"])
    assert d["noise_estimate"] == pytest.approx(0.05, rel=0.15)
    assert d["k_used"] == pytest.approx(3 + 2 * (d["noise_estimate"] - 0.02) / 0.08)
    assert d["absolute_radius"] == pytest.approx(d["k_used"] * d["mean_edge_length"])
    assert quality_diff(base, r) > 1e-3
    clean = run(CAD_CLEAN, auto_k=True)["dict"]
    assert clean["k_used"] == 3.0 and clean["noise_estimate"] < 0.005


def check_absolute_radius(base):
    r = run(absolute_radius=3.5)
    assert quality_diff(base, r) > 1e-3
    assert r["dict"]["absolute_radius"] == pytest.approx(3.5)


# Both angles drive the votes; on the lightly noisy sample the sharp edges add the shallow creases
# whatever the angles, so the votes are compared alone (sharp_edge_angle 0).
def check_crease_angle(base):
    votes = run(sharp_edge_angle=0)
    assert count(run(crease_angle=30, sharp_edge_angle=0), CREASE, CORNER) > count(votes, CREASE, CORNER) + 50


def check_corner_angle(base):
    votes = run(sharp_edge_angle=0)
    assert count(run(corner_angle=10, sharp_edge_angle=0), CORNER) > count(votes, CORNER) + 10


def check_sharp_edge_angle(base):
    # A clean 25 deg roof: below the 60 deg crease angle for the votes, sharp for its edges
    # (default 10 deg); at 30 deg its edges are not sharp either.
    sharp = run(roof(alpha_deg=25.0))
    votes = run(roof(alpha_deg=25.0), sharp_edge_angle=0)
    assert count(sharp, CREASE, CORNER) == 33  # the ridge, and only the ridge
    assert count(votes, CREASE, CORNER) < 16
    assert count(run(roof(alpha_deg=25.0), sharp_edge_angle=30), CREASE, CORNER) == 0


def check_stop_at_creases(base):
    assert quality_diff(run(curvature_fit=1), run(curvature_fit=1, stop_at_creases=False)) > 1e-3


def check_thin_creases(base):
    # At 30 deg the part's crease band is wide. Thinning acts on the votes' band: the sharp edges,
    # which add creases on this lightly noisy part after it, are off.
    thin = run(crease_angle=30, sharp_edge_angle=0)
    wide = run(crease_angle=30, sharp_edge_angle=0, thin_creases=False)
    thinned = thin["dict"]["thinned_vertices"]
    assert thinned > 100
    assert count(wide, CREASE, CORNER) == count(thin, CREASE, CORNER) + thinned
    assert wide["dict"]["thinned_vertices"] == 0


def check_curvature_fit(base):
    assert quality_diff(base, run(curvature_fit="Taubin matrix (paper)")) > 1e-3


def check_fit_rounds(base):
    assert quality_diff(base, run(fit_rounds=1)) > 1e-3


def check_cubic_fit(base):
    assert quality_diff(base, run(cubic_fit=False)) > 1e-3


def check_class_rule(base):
    assert count(run(roof()), CREASE) > 20
    # the votes' rule alone (the clean roof's sharp edges find its ridge whatever the rule)
    assert count(run(roof(), class_rule="Paper's eigenvalue order", sharp_edge_angle=0), CREASE) == 0
    assert count(run(roof(), class_rule="Paper's eigenvalue order"), CREASE) > 20


def check_update_normals(base):
    loaded_ms = load(CAD)  # kept alive: current_mesh() is a reference into its MeshSet
    loaded = loaded_ms.current_mesh().vertex_normal_matrix()
    r = run(update_normals=False)
    assert np.max(np.linalg.norm(loaded - r["normal"], axis=1)) < 1e-6
    assert np.max(np.linalg.norm(base["normal"] - r["normal"], axis=1)) > 1e-2


def check_quality(base):
    assert set(np.unique(run(quality=6)["quality"])) == {0.0, 1.0, 2.0}


def check_color(base):
    r = run(color="Quality ramp")
    assert colour_diffs(base, r) > len(r["color"]) // 2
    # Patches: one colour per patch on the faces; the vertex colours as they were.
    ms = load(CAD)
    before = ms.current_mesh().vertex_color_array().copy()
    d = ms.compute_normal_vector_voting(color="Patches")
    m = ms.current_mesh()
    assert m.has_face_color()
    assert len(np.unique(m.face_color_array())) == d["patches"] > 1  # packed ARGB, one per face
    assert np.array_equal(before, m.vertex_color_array())


def check_color_clamp_percentile(base):
    r = run(color=1, color_clamp_percentile=30)
    assert colour_diffs(run(color=1), r) > len(r["color"]) // 4


def check_selection(base):
    assert int(np.sum(base["selected"])) == 0
    r = run(selection="Creases and corners")
    assert int(np.sum(r["selected"])) == count(r, CREASE, CORNER)
    assert int(np.sum(run(selection="Corners only")["selected"])) == count(r, CORNER)
    # Vertices on crease lines: as many as the lines' layer has vertices.
    ms = load(CAD)
    ms.compute_normal_vector_voting(selection="Vertices on crease lines", crease_lines_layer=True)
    assert int(np.sum(ms.mesh(0).vertex_selection_array())) == ms.mesh(1).vertex_number() > 10


def check_crease_edges(base):
    # On by default: the network's counts in the dict and each face's patch in nvv_patch.
    d = base["dict"]
    assert d["crease_edge_count"] > 100 and d["crease_lines"] > 0 and d["patches"] > 1
    ms = load(CAD)
    ms.compute_normal_vector_voting()
    patch = ms.current_mesh().face_custom_scalar_attribute_array("nvv_patch")
    assert len(np.unique(patch[patch >= 0])) == d["patches"]
    assert int(np.min(patch)) >= -1 and int(np.max(patch)) == d["patches"] - 1
    off = run(crease_edges=False)["dict"]
    assert off["crease_edge_count"] == 0 and off["patches"] == 0


def check_crease_lines_layer(base):
    # Off by default: no layer. On: a second layer after the mesh, which stays the current one,
    # holding every crease edge once, between vertices of the mesh on the lines.
    ms = load(CAD)
    d = ms.compute_normal_vector_voting(crease_lines_layer=True)
    assert ms.mesh_number() == 2 and ms.current_mesh_id() == 0
    mesh, layer = ms.mesh(0), ms.mesh(1)
    assert layer.face_number() == 0
    assert layer.edge_number() == d["crease_edge_count"] == base["dict"]["crease_edge_count"]
    on_mesh = {tuple(p) for p in mesh.vertex_matrix()}
    assert all(tuple(p) in on_mesh for p in layer.vertex_matrix())
    edges = layer.edge_matrix()
    assert edges.min() >= 0 and edges.max() == layer.vertex_number() - 1
    assert len({tuple(sorted(e)) for e in edges}) == layer.edge_number()  # each crease edge once
    assert len(np.unique(layer.vertex_color_array())) > 2  # a colour per line
    # Asked with crease_edges off, the layer still comes: it implies the network.
    ms = load(CAD)
    ms.compute_normal_vector_voting(crease_edges=False, crease_lines_layer=True)
    assert ms.mesh_number() == 2 and ms.mesh(1).edge_number() == d["crease_edge_count"]
    one = load(CAD)
    one.compute_normal_vector_voting()
    assert one.mesh_number() == 1


def check_max_neighbourhood(base):
    r = run(max_neighbourhood=16)
    assert quality_diff(base, r) > 1e-3
    assert r["dict"]["capped_vertices"] > 0


CASES = {name[len("check_"):]: f for name, f in globals().items() if name.startswith("check_")}


def test_every_parameter_has_a_case():
    assert sorted(p["name"] for p in parameters()) == sorted(CASES)


@pytest.mark.parametrize("name", sorted(CASES))
def test_parameter_is_honoured(name, base):
    CASES[name](base)
