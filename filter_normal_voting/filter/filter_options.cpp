#include "filter_options.h"

#include <cmath>
#include <cstdio>

namespace nvv {

namespace {

// What the algorithm does (params.h), in the dialog's order.
static_assert(tuning::kAutoVisitBudget == 2.5e8, "max_neighbourhood's help quotes the budget");

std::vector<ParamSpec> AlgorithmParameters() {
  return {
    {"neighbourhood_k", ParamType::Float, "Neighbourhood size k",
     "Radius of the neighbourhood in mean edge lengths (g_m = k * l_ave): the geodesic ball whose triangles "
     "vote, and the ball the curvature is fitted over. Small k (1-2) keeps small features; larger k (3-8) "
     "averages away scanner noise. The absolute radius is written to the log.",
     3.0, limits::kMinK, limits::kMaxK, {}, {}, false},
    {"auto_k", ParamType::Bool, "Choose k from the noise",
     "Estimate the noise along the normals (a quadratic fitted to the two-ring of sampled vertices; what it "
     "leaves over) and choose k from it instead of the value above: 3 up to 2 % of the mean edge length, "
     "rising to 5 at 10 % and more. The k chosen and the noise estimated are written to the log (the "
     "noise always is). The absolute radius, if set, still wins. The command-line tool also takes "
     "--neighbourhood_k auto.",
     0.0, 0, 1, {}, {}, false},
    {"absolute_radius", ParamType::Float, "Absolute radius (0 = use k)",
     "Neighbourhood radius in the mesh's own units. 0 means: use k times the mean edge length.",
     0.0, 0.0, limits::kMaxAbsoluteRadius, {}, {}, true},
    {"crease_angle", ParamType::Float, "Crease angle (deg)",
     "Smallest angle between the normals of two surface sheets that still counts as a crease "
     "(the paper's epsilon = 1/tan^2(angle/2) - 1; 40 deg gives epsilon = 6.5, 60 deg gives 2). Raise "
     "it to ignore shallow edges, lower it to catch them. Between 1 and 89 degrees.",
     40.0, limits::kMinAngleDeg, limits::kMaxAngleDeg, {}, {}, false},
    {"corner_angle", ParamType::Float, "Corner angle (deg)",
     "The same threshold for the third direction: how strongly a third sheet must show before a "
     "vertex is a corner (the paper's eta). Between 1 and 89 degrees.",
     60.0, limits::kMinAngleDeg, limits::kMaxAngleDeg, {}, {}, false},
    {"sharp_edge_angle", ParamType::Float, "Sharp edge angle on clean meshes (deg)",
     "On a mesh free of noise (a CAD export) the classes come from the mesh edges instead of the votes: an "
     "edge whose faces' normals are at least this far apart (and the crease angle, if lower) and that turns "
     "more than the lines beside it (a curved face cut into strips turns at every strip; a chamfer's two lines, "
     "flat beyond, both count) is a crease edge, "
     "so every vertex of a crease is found however close two creases run. On a noisy mesh such edges add the "
     "creases the votes miss and the votes keep the rest (from about 9 % of the edge length only edges that "
     "turn much more than the lines beside them, or far more than the noise tilts their faces; the noise "
     "hides more of them as it grows). 0: the votes everywhere (the paper).",
     10.0, 0.0, limits::kMaxAngleDeg, {}, {}, false},
    {"stop_at_creases", ParamType::Bool, "Stop curvature at creases",
     "When estimating curvature, do not let a neighbourhood grow across crease and corner vertices, "
     "so each side of an edge keeps its own curvature. Matters most for the Taubin and Euler estimators: "
     "the quadric fit already gives no weight to neighbours whose normal differs by the crease angle "
     "(or 50 degrees, if larger).",
     1.0, 0, 1, {}, {}, false},
    {"thin_creases", ParamType::Bool, "Thin crease bands to their ridge",
     "Pass 1 marks every vertex within about the radius of a crease as crease or corner. Keep only the "
     "ridge of that band (where a two-plane fit to the vertices' heights puts the crease line; found "
     "on noisy meshes too) and treat the rest as surface, so selections and colours show crease lines "
     "and those vertices get curvature. Off: the paper's wide band.",
     1.0, 0, 1, {}, {}, false},
    {"curvature_fit", ParamType::Enum, "Curvature estimator",
     "How the neighbourhood gives curvature. Crease-aware quadric: fits a quadratic patch to the "
     "positions and voted normals of the same-sheet neighbours (most accurate, also refines the normal). "
     "Taubin matrix: the paper's estimator. Euler least squares: the paper's curvature votes fitted "
     "to Euler's formula.",
     0.0, 0, 2, {"Crease-aware quadric fit", "Taubin matrix (paper)", "Euler least squares"},
     {"quadric", "taubin", "euler"}, false},
    {"fit_rounds", ParamType::Int, "Quadric fit rounds",
     "Crease-aware quadric fit only: how many times to fit. 1 fits the voted normals once; 2 (default) "
     "fits again with the first fit's normals, which halves the direction and curvature error on noisy "
     "smooth surfaces for about 50 % more time; 3-4 rarely add more.",
     2.0, limits::kMinFitRounds, limits::kMaxFitRounds, {}, {}, true},
    {"cubic_fit", ParamType::Bool, "Cubic where significant",
     "Crease-aware quadric fit only: where a neighbourhood reaches no crease and the mesh's border is "
     "not within half its radius, fit a cubic patch instead when its extra terms are statistically "
     "significant. Removes the normal tilt a quadratic leaves on surfaces whose curvature varies "
     "(tori, fillets, free-form scans); pass 2 takes about 10-25 % longer. Off: always the quadratic.",
     1.0, 0, 1, {}, {}, true},
    {"class_rule", ParamType::Enum, "Classification rule",
     "Sign-aware: orders the vote matrix's eigenvectors by the oriented mean vote, so sharp edges "
     "above 90 deg (knife edges, fins, blade edges) are found. Paper: the original eigenvalue order, "
     "which takes creases sharper than about 120 deg for smooth surface.",
     0.0, 0, 1, {"Sign-aware", "Paper's eigenvalue order"}, {"sign_aware", "paper"}, true},
  };
}

// What is written onto the mesh, and the neighbourhood cap.
std::vector<ParamSpec> OutputParameters() {
  return {
    {"update_normals", ParamType::Bool, "Update vertex normals",
     "Replace the normals of surface vertices by the estimated ones, and those of crease vertices by "
     "the bisector of the two sheets. Corner and unclassified vertices keep the direction of their normal "
     "(made unit length).",
     1.0, 0, 1, {}, {}, false},
    {"quality", ParamType::Enum, "Vertex quality",
     "What to store in the per-vertex quality. Curvatures of non-surface vertices are 0.",
     0.0, 0, 9,
     {"Mean curvature", "Gaussian curvature", "Max curvature k1", "Min curvature k2", "Shape index",
      "Curvedness", "Class (0 surface, 1 crease, 2 corner, 3 none)", "Cusp angle (deg)", "Surface saliency",
      "Keep"},
     {"mean", "gaussian", "k1", "k2", "shape_index", "curvedness", "class", "cusp_angle", "saliency", "keep"},
     false},
    {"color", ParamType::Enum, "Vertex colour",
     "Class colours: surface grey, crease red, corner blue, unclassified magenta. Quality ramp: the "
     "chosen quality as a red-to-blue ramp clamped at percentiles. Keep: leave colours alone. Patches: "
     "one colour per smooth patch bounded by the crease lines, on the faces, which MeshLab then shows "
     "(vertex colours are left as they were); the command-line tool, whose PLY has no face colours, "
     "colours the vertices inside each patch and those on the lines crease red or corner blue.",
     0.0, 0, 3, {"Class colours", "Quality ramp", "Keep", "Patches"}, {"classes", "ramp", "keep", "patches"}, false},
    {"color_clamp_percentile", ParamType::Float, "Ramp clamp percentile",
     "The quality ramp spans the p-th to the (100-p)-th percentile, so a few extreme values do not "
     "wash out the rest.",
     2.0, 0.0, limits::kMaxClampPercentile, {}, {}, true},
    {"selection", ParamType::Enum, "Select vertices",
     "Which vertices to select afterwards (replacing the current vertex selection), e.g. to protect "
     "creases from a following smoothing or remeshing filter. Creases and corners: by their class; "
     "vertices on crease lines: the ends of the crease edges, the lines with their gaps closed and spurs "
     "dropped (finds the crease network).",
     0.0, 0, 4, {"None (keep selection)", "Creases and corners", "Corners only", "Surface only", "Vertices on crease lines"},
     {"none", "creases", "corners", "surface", "lines"}, false},
    {"crease_edges", ParamType::Bool, "Crease edges, lines and patches",
     "Find the mesh edges that lie on creases (from the two sheets the votes found, not from the "
     "dihedral angle alone), link them into crease lines that end at corners, at the border or close on "
     "themselves, and group the faces into smooth patches bounded by the lines. The crease edges replace "
     "the faces' edge selection (MeshLab's filters on selected edges, e.g. Build a Polyline from Selected "
     "Edges, chain after this one), each face gets its patch in the attribute nvv_patch, and the counts "
     "go to the log. The command-line tool writes the edges and the patches into its PLY.",
     1.0, 0, 1, {}, {}, false},
    {"max_neighbourhood", ParamType::Int, "Neighbourhood cap (vertices)",
     "Upper bound on the vertices one neighbourhood may hold; bounds the time spent on very high "
     "valence vertices or absurd radii. 0 = automatic: four times what a uniform mesh holds within "
     "the radius, at least 1024, and on a large mesh at a large k no more than keeps the whole run "
     "within 250 million neighbourhood steps. Vertices that hit it are counted in the log.",
     0.0, 0, limits::kMaxNeighbourhoodCap, {}, {}, true},
  };
}

}  // namespace

const std::vector<ParamSpec>& FilterParameterTable() {
  static const std::vector<ParamSpec> table = [] {
    std::vector<ParamSpec> t = AlgorithmParameters();
    for (const ParamSpec& p : OutputParameters()) t.push_back(p);
    return t;
  }();
  return table;
}

const std::vector<ParamSpec>& MeshLabParameterTable() {
  static const std::vector<ParamSpec> table = [] {
    std::vector<ParamSpec> t = FilterParameterTable();
    t.push_back({"crease_lines_layer", ParamType::Bool, "Crease lines as a new layer",
                 "Also add a layer holding the crease lines as an edge mesh (one colour per line, corners in the "
                 "corner colour; per-edge attributes nvv_line and nvv_cusp_angle in degrees), named after the mesh "
                 "with \" crease lines\". The mesh stays the current layer. Implies the crease network. The "
                 "command-line tool writes the same lines to a file (--crease_lines).",
                 0.0, 0, 1, {}, {}, false});
    return t;
  }();
  return table;
}

const SaveFileSpec& ResultPlyParameter() {
  static const SaveFileSpec spec = {
      "save_results_ply", "Save all results to PLY (optional)",
      "If set, also writes every per-vertex result (class, eigenvalues, K1, K2, PD1, PD2, crease tangent, "
      "crease curvature, cusp angle, normal, quality, colour) to this PLY file, which MeshLab's own writer "
      "cannot do. Leave empty to skip. The folder must be writable."};
  return spec;
}

const ParamSpec* FindParam(const std::string& name, const std::vector<ParamSpec>& table) {
  for (const auto& p : table)
    if (name == p.name) return &p;
  return nullptr;
}

std::string SetOption(FilterOptions& o, const std::string& name, double value) {
  const ParamSpec* spec = FindParam(name, MeshLabParameterTable());
  if (!spec) return "Unknown parameter '" + name + "'.";
  if (!std::isfinite(value)) return std::string("Parameter '") + spec->name + "' is not a finite number.";
  if (spec->type == ParamType::Enum && (value != std::floor(value) || value < 0 || value >= double(spec->choices.size())))
    return std::string("Parameter '") + spec->name + "' must be one of its " + std::to_string(spec->choices.size()) + " choices.";
  if (spec->type == ParamType::Int && value != std::floor(value))
    return std::string("Parameter '") + spec->name + "' must be a whole number.";
  if ((spec->type == ParamType::Float || spec->type == ParamType::Int) && (value < spec->minValue || value > spec->maxValue)) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "Parameter '%s' (%s) = %g is outside its range [%g, %g].", spec->name, spec->label,
                  value, spec->minValue, spec->maxValue);
    return buf;
  }
  if (spec->type == ParamType::Bool && value != 0 && value != 1)
    return std::string("Parameter '") + spec->name + "' must be 0 (false) or 1 (true).";
  // Only Enum and Int values, checked against their range above, are converted: converting an
  // out-of-range double to int is undefined.
  const int iv = spec->type == ParamType::Enum || spec->type == ParamType::Int ? int(value) : 0;
  if (name == "neighbourhood_k") o.core.k = value;
  else if (name == "auto_k") o.core.autoK = value != 0;
  else if (name == "absolute_radius") o.core.absoluteRadius = value;
  else if (name == "crease_angle") o.core.creaseAngleDeg = value;
  else if (name == "corner_angle") o.core.cornerAngleDeg = value;
  else if (name == "sharp_edge_angle") o.core.sharpEdgeAngleDeg = value;
  else if (name == "stop_at_creases") o.core.stopAtCreases = value != 0;
  else if (name == "thin_creases") o.core.thinCreases = value != 0;
  else if (name == "curvature_fit") o.core.fit = CurvatureFit(iv);
  else if (name == "fit_rounds") o.core.fitRounds = iv;
  else if (name == "cubic_fit") o.core.cubicFit = value != 0;
  else if (name == "class_rule") o.core.classRule = ClassRule(iv);
  else if (name == "update_normals") o.updateNormals = value != 0;
  else if (name == "quality") o.quality = QualityMode(iv);
  else if (name == "color") o.color = ColorMode(iv);
  else if (name == "color_clamp_percentile") o.clampPercentile = value;
  else if (name == "selection") o.selection = SelectionMode(iv);
  else if (name == "max_neighbourhood") o.core.maxNeighbourhood = iv;
  else if (name == "crease_edges") o.creaseEdges = value != 0;
  else if (name == "crease_lines_layer") o.creaseLinesLayer = value != 0;
  return std::string();
}

double GetOption(const FilterOptions& o, const std::string& name) {
  if (name == "neighbourhood_k") return o.core.k;
  if (name == "auto_k") return o.core.autoK ? 1 : 0;
  if (name == "absolute_radius") return o.core.absoluteRadius;
  if (name == "crease_angle") return o.core.creaseAngleDeg;
  if (name == "corner_angle") return o.core.cornerAngleDeg;
  if (name == "sharp_edge_angle") return o.core.sharpEdgeAngleDeg;
  if (name == "stop_at_creases") return o.core.stopAtCreases ? 1 : 0;
  if (name == "thin_creases") return o.core.thinCreases ? 1 : 0;
  if (name == "curvature_fit") return int(o.core.fit);
  if (name == "fit_rounds") return o.core.fitRounds;
  if (name == "cubic_fit") return o.core.cubicFit ? 1 : 0;
  if (name == "class_rule") return int(o.core.classRule);
  if (name == "update_normals") return o.updateNormals ? 1 : 0;
  if (name == "quality") return int(o.quality);
  if (name == "color") return int(o.color);
  if (name == "color_clamp_percentile") return o.clampPercentile;
  if (name == "selection") return int(o.selection);
  if (name == "max_neighbourhood") return o.core.maxNeighbourhood;
  if (name == "crease_edges") return o.creaseEdges ? 1 : 0;
  if (name == "crease_lines_layer") return o.creaseLinesLayer ? 1 : 0;
  return std::nan("");
}

FilterOptions DefaultOptions() {
  FilterOptions o;
  for (const auto& p : FilterParameterTable()) SetOption(o, p.name, p.defaultValue);
  return o;
}

std::string ValidateOptions(const FilterOptions& o) {
  std::string e = ValidateParams(o.core);
  if (!e.empty()) return e;
  if (!std::isfinite(o.clampPercentile) || o.clampPercentile < 0 || o.clampPercentile > 49)
    return "The ramp clamp percentile must be between 0 and 49.";
  return std::string();
}

}  // namespace nvv
