// What both MeshLab plugin APIs (2020.09's MeshFilterInterface and 2022.02+'s FilterPlugin)
// share: the filter's names and help, its parameters built from nvv::FilterParameterTable(),
// their validation, and the run that writes results onto the MeshModel. The API layers only
// translate calls and errors.
#ifndef NVV_MESHLAB_FILTER_COMMON_H
#define NVV_MESHLAB_FILTER_COMMON_H

#include <QString>
#include <QStringList>

#include <common/interfaces.h>

#include "core/filter_options.h"
#include "core/vertex_result.h"

namespace nvv_meshlab {

// Menu entry; also the name .mlx scripts use. Stable.
QString FilterName();
// PyMeshLab's name for the filter. Stable.
QString PythonName();
// The dialog's help: method, outputs and every parameter, in a user's words.
QString FilterInfo();

// Adds every parameter of the table, with its default, to the dialog.
void AddParameters(RichParameterList& par);

// Reads the dialog's values into options; returns the reason when one is refused.
QString ReadOptions(const RichParameterList& par, nvv::FilterOptions& options);

// The MeshModel components the run writes (for postCondition and updateDataMask).
int OutputMask();

struct Outcome {
  bool ok = false;
  QString error;          // when !ok: the reason, for errorMessage / MLException and the log
  QStringList log;        // when ok: summary and warnings
  nvv::Summary summary;
};

// Runs the filter on mm. On failure (refused mesh, cancellation) the mesh is untouched.
Outcome Run(MeshModel& mm, const nvv::FilterOptions& options, vcg::CallBackPos* cb);

}  // namespace nvv_meshlab

#endif
