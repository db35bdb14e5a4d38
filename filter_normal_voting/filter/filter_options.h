// Everything a user sets when running the filter: the algorithm's parameters (params.h)
// plus what to write onto the mesh. The table below is the single definition of every
// parameter's stable name, label, help text, default and range; the MeshLab dialogs (both
// plugin APIs), the command-line tool and the tests all read it.
//
// Names are stable: .mlx scripts, PyMeshLab keyword arguments and CLI options use them.
#ifndef NVV_FILTER_FILTER_OPTIONS_H
#define NVV_FILTER_FILTER_OPTIONS_H

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/params.h"

namespace nvv {

// The filter's name in MeshLab's menus and .mlx scripts, and PyMeshLab's name for it. Stable.
constexpr const char* kFilterName = "Normal Vector Voting: Creases, Normals and Curvature";
constexpr const char* kPythonFilterName = "compute_normal_vector_voting";

enum class QualityMode : int {
  MeanCurvature = 0, GaussianCurvature, MaxCurvature, MinCurvature, ShapeIndex, Curvedness,
  Class, CuspAngle, SurfaceSaliency, Keep
};
enum class ColorMode : int { Classes = 0, QualityRamp, Keep, Patches };
enum class SelectionMode : int { None = 0, CreasesAndCorners, CornersOnly, SurfaceOnly, CreaseLines };

struct FilterOptions {
  Params core;
  bool updateNormals = true;
  QualityMode quality = QualityMode::MeanCurvature;
  ColorMode color = ColorMode::Classes;
  double clampPercentile = 2.0;  // the quality ramp spans the p-th to (100-p)-th percentile
  SelectionMode selection = SelectionMode::None;
  bool creaseEdges = true;       // crease edges, lines and patches (crease_network.h) after the run
  bool creaseLinesLayer = false; // MeshLab only: the crease lines as a new layer (crease_lines_layer.h)
};

// True when the run must find the crease network: its edges, its lines, or the patches to colour.
inline bool WantsCreaseNetwork(const FilterOptions& o) {
  return o.creaseEdges || o.creaseLinesLayer || o.color == ColorMode::Patches || o.selection == SelectionMode::CreaseLines;
}

enum class ParamType { Float, Int, Bool, Enum };

struct ParamSpec {
  const char* name;   // stable identifier
  ParamType type;
  const char* label;  // short label (MeshLab dialog)
  const char* help;   // tooltip and --help text, in a user's words
  double defaultValue;
  double minValue, maxValue;         // Float / Int
  std::vector<const char*> choices;  // Enum: labels, value = index
  std::vector<const char*> tokens;   // Enum: short names for the command line
  bool advanced;                     // shown in the dialog's advanced section
};

// Every parameter of the filter, in the order of the dialog.
const std::vector<ParamSpec>& FilterParameterTable();

// The parameters of the MeshLab filter (both APIs, .mlx scripts, PyMeshLab): the table above plus
// what only MeshLab can do with a result, the crease lines as a new layer (crease_lines_layer),
// which the command-line tool writes to a file instead (--crease_lines).
const std::vector<ParamSpec>& MeshLabParameterTable();

// The other parameter only the MeshLab filter has: a file to write the full-result PLY to (see
// filter_normal_voting/io/result_ply.h), because MeshLab's own PLY writer cannot save curvature
// directions or the per-vertex results from a script. The command-line tool always writes it.
struct SaveFileSpec {
  const char* name;
  const char* label;
  const char* help;
};
const SaveFileSpec& ResultPlyParameter();

// The entry of parameter `name` in `table`, or null.
const ParamSpec* FindParam(const std::string& name, const std::vector<ParamSpec>& table = FilterParameterTable());

// Sets option `name` (any of MeshLabParameterTable()) from a number (Bool: 0/1, Enum: index). Returns an error sentence, or
// empty when set. Values outside the table's range are refused here, not clamped.
std::string SetOption(FilterOptions& o, const std::string& name, double value);

// The value of option `name` as SetOption takes it (Bool: 0/1, Enum: index); NaN if unknown.
double GetOption(const FilterOptions& o, const std::string& name);

// Options with every parameter at its table default.
FilterOptions DefaultOptions();

// Empty when the options can run; otherwise the reason, in a user's words.
std::string ValidateOptions(const FilterOptions& o);

}  // namespace nvv

#endif
