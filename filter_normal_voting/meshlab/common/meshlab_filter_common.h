// What both MeshLab plugin APIs (2020.09's MeshFilterInterface and 2022.02+'s FilterPlugin)
// share: the filter's names and help, its parameters built from nvv::FilterParameterTable(),
// their validation, the run that writes results onto the MeshModel and its summary values. The
// API layers only translate calls and errors.
//
// The same source compiles against both MeshLab trees; the 2022.02+/2025.07 build defines
// NVV_MESHLAB_API_2025 (and MESHLAB_VERSION, which its headers require).
#ifndef NVV_MESHLAB_FILTER_COMMON_H
#define NVV_MESHLAB_FILTER_COMMON_H

#include <map>
#include <string>

#include <QString>
#include <QStringList>
#include <QVariant>

#ifdef NVV_MESHLAB_API_2025
// MeshLab 2022.02 and later: the document and the parameters have headers of their own.
#include <common/ml_document/mesh_document.h>
#include <common/ml_document/mesh_model.h>
#include <common/parameters/rich_parameter_list.h>
#else
#include <common/interfaces.h>
#endif

#include "filter/filter_options.h"
#include "core/vertex_result.h"

namespace nvv_meshlab {

// Menu entry; also the name .mlx scripts use. Stable.
QString FilterName();
// PyMeshLab's name for the filter. Stable.
QString PythonName();
// The dialog's help: method, outputs and every parameter, in a user's words.
QString FilterInfo();

// Adds every parameter of nvv::MeshLabParameterTable(), with its default, to the dialog.
void AddParameters(RichParameterList& par);

// Reads the dialog's values into options (and the optional full-result PLY path); returns the
// reason when one is refused.
QString ReadOptions(const RichParameterList& par, nvv::FilterOptions& options, QString& resultPly);

// The MeshModel components the run writes (for postCondition and updateDataMask); with the
// options, also those only they ask for (the faces' colours of the patch colouring).
int OutputMask(const nvv::FilterOptions* options = nullptr);

struct Outcome {
  bool ok = false;
  QString error;          // when !ok: the reason, for errorMessage / MLException and the log
  QStringList log;        // when ok: summary and warnings
  nvv::Summary summary;
  // The crease network's counts (0 when it was not asked for): edges, lines, closed lines,
  // distinct corners at line ends, patches and their smallest and largest size in faces.
  int creaseEdges = 0, creaseLines = 0, closedLines = 0, lineCorners = 0;
  int patches = 0, smallestPatch = 0, largestPatch = 0;
};

// Runs the filter on md's current mesh and, when resultPly is not empty, writes the full-result
// PLY there; with options.creaseLinesLayer, adds the crease lines as a new layer after it.
// On failure (refused mesh, unwritable file, cancellation) the mesh is untouched.
// Progress goes to cb from the calling thread only (the GUI pumps its event loop in it).
Outcome Run(MeshDocument& md, const nvv::FilterOptions& options, const QString& resultPly, vcg::CallBackPos* cb);

// The run's summary as named values (PyMeshLab hands them to the script as a dict):
// surface_vertices, crease_vertices, corner_vertices, unclassified_vertices, capped_vertices,
// thinned_vertices,
// k1_min, k1_max, k2_min, k2_max, absolute_radius, k_used (k, or automatic k's choice),
// noise_estimate (noise along the normals / mean edge length), mean_edge_length, epsilon, eta,
// sign_aware_rule, seconds, seconds_pass1, seconds_pass2,
// crease_edge_count, crease_lines, closed_crease_lines, line_end_corners, patches,
// smallest_patch_faces, largest_patch_faces (0 when crease_edges is off and no patch colours).
std::map<std::string, QVariant> SummaryValues(const Outcome& outcome);

}  // namespace nvv_meshlab

#endif
