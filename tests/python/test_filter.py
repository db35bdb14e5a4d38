# The filter in the real PyMeshLab 2025.7: found by its python name with the table's parameters,
# every parameter's range enforced by a PyMeshLab exception that leaves the mesh as it was, the
# returned dict, the per-vertex outputs, the same numbers as the command-line tool, and a clear
# refusal of a mesh without faces. Parameter names, types, ranges and defaults come from the
# project's parameter table (conftest.parameter_table), never from a copy.
import math
import re
import subprocess

import numpy as np
import pytest

import pymeshlab
import pymeshlab_normal_voting
from conftest import CAD, FILTER, SMALL, assert_same_snapshot, load, parameters, read_ply_vertices, report, snapshot

PYTHON_TYPES = {"float": float, "int": int, "bool": bool, "enum": int}
PRINTED_TYPES = {"float": "float", "int": "int", "bool": "bool", "enum": "str"}
CLASS_SURFACE, CLASS_CREASE, CLASS_CORNER, CLASS_NONE = 0, 1, 2, 3


def ids(params):
    return [p["name"] for p in params]


def test_filter_is_found_by_its_python_name(table):
    assert table["python_name"] == FILTER == "compute_normal_vector_voting"
    assert FILTER in pymeshlab.filter_list()
    assert callable(getattr(pymeshlab.MeshSet, FILTER))
    ms = load(SMALL)
    values = ms.filter_parameter_values(FILTER)
    assert list(values) == [p["name"] for p in table["parameters"]] + [table["save_file"]["name"]]


def test_importing_again_and_loading_again_is_harmless():
    import importlib
    importlib.reload(pymeshlab_normal_voting)
    assert pymeshlab.filter_list().count(FILTER) == 1
    assert pymeshlab_normal_voting.load() == FILTER
    with pytest.raises(pymeshlab.PyMeshLabException, match="already loaded"):
        pymeshlab.load_plugin(pymeshlab_normal_voting.PLUGIN_PATH)


@pytest.mark.parametrize("spec", parameters(), ids=ids(parameters()))
def test_parameter_has_the_tables_type_and_default(spec, capfd):
    ms = load(SMALL)
    value = ms.filter_parameter_values(FILTER)[spec["name"]]
    assert type(value) is PYTHON_TYPES[spec["type"]]
    assert value == pytest.approx(spec["default"])
    # PyMeshLab's own listing: "name : type = default"; an enum shows its label.
    pymeshlab.print_filter_parameter_list(FILTER)
    out = capfd.readouterr().out
    line = re.search(r"^\s*%s : (\w+) = (.*)$" % spec["name"], out, re.M)
    assert line, out
    assert line.group(1) == PRINTED_TYPES[spec["type"]]
    if spec["type"] == "enum":
        assert line.group(2) == "'%s'" % spec["choices"][int(spec["default"])]
    elif spec["type"] == "bool":
        assert line.group(2) == str(bool(spec["default"]))
    else:
        assert float(line.group(2)) == pytest.approx(spec["default"])


def test_save_results_ply_is_a_string_parameter(table, capfd):
    pymeshlab.print_filter_parameter_list(FILTER)
    assert re.search(r"^\s*%s : str = ''$" % table["save_file"]["name"], capfd.readouterr().out, re.M)


def in_range_values(spec):
    t = spec["type"]
    if t == "bool":
        return [True, False]
    if t == "enum":
        return list(range(len(spec["choices"]))) + list(spec["choices"])
    if t == "int":
        return [int(spec["min"]), int(spec["max"]), int(spec["default"])]
    mid = spec["min"] + 0.5 * (min(spec["max"], 10 * max(spec["default"], 1)) - spec["min"])
    return [spec["min"], spec["max"], mid]


def out_of_range_values(spec):
    t = spec["type"]
    if t == "enum":
        return [len(spec["choices"]), -1, "no such choice"]
    if t == "int":
        return [int(spec["min"]) - 1, int(spec["max"]) + 1]
    if t == "float":
        step = max(0.5 * abs(spec["min"]), 0.5) if spec["min"] != 0 else 0.5
        return [spec["min"] - step, spec["max"] + max(0.5 * abs(spec["max"]), 0.5), math.inf, math.nan]
    return []  # a bool has no value outside its range


def value_cases(kind):
    cases = []
    for spec in parameters():
        for v in (in_range_values if kind == "in" else out_of_range_values)(spec):
            cases.append(pytest.param(spec, v, id="%s=%r" % (spec["name"], v)))
    return cases


@pytest.mark.parametrize("spec,value", value_cases("in"))
def test_values_within_the_documented_range_are_accepted(spec, value):
    ms = load(SMALL)
    kwargs = {spec["name"]: value}
    if spec["name"] == "absolute_radius" and value > 1e6:
        kwargs["max_neighbourhood"] = 64  # a radius around the whole mesh, each neighbourhood capped
    out = ms.compute_normal_vector_voting(**kwargs)
    assert out["surface_vertices"] + out["crease_vertices"] + out["corner_vertices"] + \
        out["unclassified_vertices"] == ms.current_mesh().vertex_number()


@pytest.mark.parametrize("spec", [p for p in parameters() if p["type"] == "enum"],
                         ids=ids([p for p in parameters() if p["type"] == "enum"]))
def test_an_enum_takes_its_label_or_its_index_alike(spec):
    for index, label in enumerate(spec["choices"]):
        a, b = load(SMALL), load(SMALL)
        a.compute_normal_vector_voting(**{spec["name"]: index})
        b.compute_normal_vector_voting(**{spec["name"]: label})
        assert_same_snapshot(snapshot(a.current_mesh()), snapshot(b.current_mesh()))


@pytest.mark.parametrize("spec,value", value_cases("out"))
def test_values_outside_the_documented_range_raise_and_leave_the_mesh_unchanged(spec, value):
    ms = load(SMALL)
    before = snapshot(ms.current_mesh())
    if spec["type"] == "enum":
        # PyMeshLab checks an enum itself, before the filter runs.
        with pytest.raises(pymeshlab.InvalidEnumException):
            ms.compute_normal_vector_voting(**{spec["name"]: value})
    else:
        with pytest.raises(pymeshlab.PyMeshLabException) as e:
            ms.compute_normal_vector_voting(**{spec["name"]: value})
        assert spec["name"] in str(e.value)
        assert "not changed" in str(e.value)
    assert_same_snapshot(before, snapshot(ms.current_mesh()))
    ms.compute_normal_vector_voting()  # the mesh set is still usable


def test_mesh_without_faces_is_refused_with_the_reason_and_left_unchanged():
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]], dtype=float)))
    before = snapshot(ms.current_mesh())
    with pytest.raises(pymeshlab.PyMeshLabException, match="no faces"):
        ms.compute_normal_vector_voting()
    assert_same_snapshot(before, snapshot(ms.current_mesh()))
    ms.set_selection_none()  # a successful filter after a refusal (see conftest: PyMeshLab issue #384)


INT_KEYS = ["surface_vertices", "crease_vertices", "corner_vertices", "unclassified_vertices", "capped_vertices",
            "thinned_vertices", "crease_edge_count", "crease_lines", "closed_crease_lines", "line_end_corners",
            "patches", "smallest_patch_faces", "largest_patch_faces"]
FLOAT_KEYS = ["k1_min", "k1_max", "k2_min", "k2_max", "absolute_radius", "k_used", "noise_estimate",
              "mean_edge_length", "epsilon", "eta",
              "seconds", "seconds_pass1", "seconds_pass2"]


def test_returned_dict_holds_the_summary():
    ms = load(CAD)
    out = ms.compute_normal_vector_voting(selection="Creases and corners")
    report("[dict] %s" % out)
    assert set(out) == set(INT_KEYS) | set(FLOAT_KEYS) | {"sign_aware_rule"}
    for k in INT_KEYS:
        assert type(out[k]) is int, k
    for k in FLOAT_KEYS:
        assert type(out[k]) is float, k
    assert out["sign_aware_rule"] is True
    m = ms.current_mesh()
    cls = m.vertex_custom_scalar_attribute_array("nvv_class")
    for key, c in [("surface_vertices", CLASS_SURFACE), ("crease_vertices", CLASS_CREASE),
                   ("corner_vertices", CLASS_CORNER), ("unclassified_vertices", CLASS_NONE)]:
        assert out[key] == int(np.sum(cls == c)), key
    assert out["crease_vertices"] > 100 and out["corner_vertices"] > 0
    assert m.selected_vertex_number() == out["crease_vertices"] + out["corner_vertices"]
    assert out["k1_min"] < out["k1_max"] and out["k2_min"] <= out["k1_max"]
    assert out["absolute_radius"] == pytest.approx(3.0 * out["mean_edge_length"], rel=1e-9)
    assert out["k_used"] == 3.0 and out["noise_estimate"] == pytest.approx(0.05, rel=0.15)  # the sample's 5 %
    # Eq. 11 at the default crease angle 40 deg (1 / tan^2 20 deg - 1) and corner angle 60 deg
    assert out["epsilon"] == pytest.approx(1 / math.tan(math.radians(20)) ** 2 - 1) and out["eta"] == pytest.approx(2.0)
    assert out["seconds"] > 0 and out["seconds"] >= out["seconds_pass1"]
    assert load(CAD).compute_normal_vector_voting(absolute_radius=3.5)["absolute_radius"] == pytest.approx(3.5)
    # The method PyMeshLab adds and apply_filter are one call.
    assert set(load(SMALL).apply_filter(FILTER)) == set(out)


SCALAR_ATTRIBUTES = ["nvv_class", "nvv_surface_saliency", "nvv_crease_saliency", "nvv_corner_saliency",
                     "nvv_cusp_angle", "nvv_crease_curvature"]


def test_per_vertex_outputs_are_reachable_from_python(tmp_path):
    ms = load(CAD)
    out = ms.compute_normal_vector_voting(save_results_ply=str(tmp_path / "results.ply"))
    m = ms.current_mesh()
    n = m.vertex_number()
    res = read_ply_vertices(tmp_path / "results.ply")
    assert len(res) == n
    cls = m.vertex_custom_scalar_attribute_array("nvv_class")
    assert set(np.unique(cls)) <= {0.0, 1.0, 2.0, 3.0}
    assert np.array_equal(cls, res["nvv_class"])
    for name in SCALAR_ATTRIBUTES:
        a = m.vertex_custom_scalar_attribute_array(name)
        assert a.shape == (n,) and np.all(np.isfinite(a)), name
    np.testing.assert_allclose(m.vertex_custom_scalar_attribute_array("nvv_cusp_angle"), res["nvv_cusp_angle"],
                               rtol=1e-5, atol=1e-4)
    tangent = m.vertex_custom_point_attribute_matrix("nvv_crease_tangent")
    assert tangent.shape == (n, 3)
    crease = cls == CLASS_CREASE
    np.testing.assert_allclose(np.linalg.norm(tangent[crease], axis=1), 1.0, atol=1e-5)
    # Quality: mean curvature (the default); k1 >= k2 with their directions, unit and tangent.
    surface = cls == CLASS_SURFACE
    q = m.vertex_scalar_array()
    np.testing.assert_allclose(q[surface], 0.5 * (res["k1"] + res["k2"])[surface], rtol=1e-4, atol=1e-6)
    assert np.all(q[~surface] == 0)
    assert out["k2_min"] <= q.min() and q.max() <= out["k1_max"]
    pd1, pd2 = m.vertex_curvature_principal_dir1_matrix(), m.vertex_curvature_principal_dir2_matrix()
    normals = m.vertex_normal_matrix()
    np.testing.assert_allclose(np.linalg.norm(pd1[surface], axis=1), 1.0, atol=1e-5)
    np.testing.assert_allclose(np.linalg.norm(pd2[surface], axis=1), 1.0, atol=1e-5)
    assert np.max(np.abs(np.sum(pd1[surface] * pd2[surface], axis=1))) < 1e-4
    assert np.max(np.abs(np.sum(pd1[surface] * normals[surface], axis=1))) < 1e-3
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-6)
    # Colour: one colour per class.
    colors = m.vertex_color_array()
    for c in (CLASS_SURFACE, CLASS_CREASE, CLASS_CORNER):
        assert len(np.unique(colors[cls == c])) == 1, c
    assert len(np.unique(colors[cls != CLASS_NONE])) == 3
    # Other quality modes write what they name.
    ms.compute_normal_vector_voting(quality="Class (0 surface, 1 crease, 2 corner, 3 none)", update_normals=False)
    m = ms.current_mesh()
    assert np.array_equal(m.vertex_scalar_array(), m.vertex_custom_scalar_attribute_array("nvv_class"))


def test_saved_ply_carries_normals_quality_and_colour(tmp_path):
    ms = load(CAD)
    ms.compute_normal_vector_voting(quality="Mean curvature", color="Class colours")
    path = str(tmp_path / "saved.ply")
    ms.save_current_mesh(path, save_vertex_normal=True)  # PyMeshLab leaves normals out of a PLY by default
    back_ms = load(path)  # kept alive: current_mesh() is a reference into its MeshSet
    back = back_ms.current_mesh()
    m = ms.current_mesh()
    assert back.vertex_number() == m.vertex_number()
    np.testing.assert_allclose(back.vertex_scalar_array(), m.vertex_scalar_array(), rtol=1e-6, atol=1e-12)
    assert np.array_equal(back.vertex_color_array(), m.vertex_color_array())
    np.testing.assert_allclose(back.vertex_normal_matrix(), m.vertex_normal_matrix(), atol=1e-5)


def run_cli(cli, tmp_path, *options):
    out = tmp_path / "cli.ply"
    proc = subprocess.run([cli, *options, str(CAD), str(out)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return read_ply_vertices(out)


def test_results_equal_the_command_line_tools(cli, tmp_path):
    ref = run_cli(cli, tmp_path)
    ms = load(CAD)
    ms.compute_normal_vector_voting(save_results_ply=str(tmp_path / "results.ply"))
    got = read_ply_vertices(tmp_path / "results.ply")
    m = ms.current_mesh()
    assert len(ref) == len(got) == m.vertex_number()
    # The same mesh: MeshLab's importer and the tool's reader give the same coordinates.
    xyz = np.stack([ref["x"], ref["y"], ref["z"]], axis=1)
    assert np.array_equal(xyz, m.vertex_matrix().astype(np.float32))
    # The full results, file against file: no class differs, every value within float precision.
    assert int(np.sum(ref["nvv_class"] != got["nvv_class"])) == 0
    worst = 0.0
    for f in ["k1", "k2", "pd1x", "pd1y", "pd1z", "pd2x", "pd2y", "pd2z", "nvv_cusp_angle", "nvv_crease_curvature",
              "nvv_lambda1", "nvv_lambda2", "nvv_lambda3", "quality", "nx", "ny", "nz"]:
        a, b = ref[f].astype(float), got[f].astype(float)
        worst = max(worst, float(np.max(np.abs(a - b) / (1e-3 + np.abs(a)))))
    report("[PyMeshLab vs nvv CLI] max relative difference of the results: %.3g" % worst)
    assert worst < 1e-4
    for f in ["red", "green", "blue", "alpha", "nvv_flags", "nvv_selected"]:
        assert np.array_equal(ref[f], got[f]), f
    # What stays on the MeshSet's mesh: quality, normals, colour.
    q = m.vertex_scalar_array()
    assert np.max(np.abs(ref["quality"] - q) / (1e-3 + np.abs(ref["quality"]))) < 1e-3
    assert np.max(np.linalg.norm(np.stack([ref["nx"], ref["ny"], ref["nz"]], axis=1) - m.vertex_normal_matrix(),
                                 axis=1)) < 1e-4
    rgba = m.vertex_color_matrix()
    np.testing.assert_allclose(rgba * 255.0, np.stack([ref["red"], ref["green"], ref["blue"], ref["alpha"]], axis=1),
                               atol=0.51)


def test_results_equal_the_command_line_tools_with_other_options(cli, tmp_path):
    ref = run_cli(cli, tmp_path, "--neighbourhood_k", "5", "--crease_angle", "30", "--curvature_fit", "taubin")
    ms = load(CAD)
    ms.compute_normal_vector_voting(neighbourhood_k=5, crease_angle=30, curvature_fit="Taubin matrix (paper)",
                                    save_results_ply=str(tmp_path / "results.ply"))
    got = read_ply_vertices(tmp_path / "results.ply")
    assert int(np.sum(ref["nvv_class"] != got["nvv_class"])) == 0
    for f in ["k1", "k2", "quality"]:
        a, b = ref[f].astype(float), got[f].astype(float)
        assert np.max(np.abs(a - b) / (1e-3 + np.abs(a))) < 1e-4, f
