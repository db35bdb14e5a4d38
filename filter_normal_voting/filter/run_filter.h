// The filter's run sequence, shared by the command-line tool and both MeshLab adapters:
//
//   check the output files' folders -> compute (refused or cancelled: the mesh is untouched)
//   -> the crease network, when asked -> enable the mesh's components -> apply the results
//   -> write the results PLY and the crease lines -> log lines
//
// Front ends only translate: their parameters into a RunRequest, the progress callback, and the
// RunOutcome into their exit codes, dialogs, logs or dictionaries.
#ifndef NVV_FILTER_RUN_FILTER_H
#define NVV_FILTER_RUN_FILTER_H

#include <functional>
#include <new>
#include <string>
#include <vector>

#include "core/normal_vector_voting.h"
#include "filter/apply_results.h"
#include "filter/crease_outputs.h"
#include "filter/filter_options.h"
#include "io/crease_lines_file.h"
#include "io/result_ply.h"

namespace nvv {

struct RunRequest {
  FilterOptions options;
  std::string resultPly;                 // empty: no results file
  bool binaryPly = true;
  std::vector<std::string> plyComments;  // extra header comments of the results file
  std::string creaseLines;               // empty: no crease-lines file (.ply or .obj, crease_lines_file.h)
  // The crease network is found when the options want it or a crease-lines file is asked for.
  bool WantsCreaseNetwork() const { return nvv::WantsCreaseNetwork(options) || !creaseLines.empty(); }
};

struct RunOutcome {
  enum Failure { kNone, kRefused, kCancelled, kCannotWrite };
  Failure failure = kNone;
  std::string error;                 // why it failed, one sentence
  bool meshChanged = false;          // false whenever failure is kRefused or kCancelled
  Summary summary;
  std::vector<std::string> log;      // the summary line, the settings line, the crease network's line
  std::vector<std::string> warnings; // about the input, one sentence each
  bool creaseNetwork = false;        // crease holds the run's crease network
  CreaseOutputs crease;
  bool Ok() const { return failure == kNone; }
};

// Empty when a file can be written at `path`: its folder exists and is writable and the path
// is not a directory. Otherwise the reason; `what` names the file in it.
std::string CheckOutputPath(const std::string& path, const std::string& what = "the results PLY");

// The settings line of the log: k, the absolute radius, the angles and their constants.
std::string SettingsLine(const FilterOptions& options, const Summary& s);

// Runs the filter on m. `enable(needs)` is called just before the results are applied, so a
// front end can enable the mesh components they need (MeshLab's updateDataMask).
template <class MeshType>
RunOutcome RunFilter(MeshType& m, const RunRequest& request, const Progress& progress = Progress(),
                     const std::function<void(const typename ApplyResults<MeshType>::Needs&)>& enable = nullptr) {
  RunOutcome out;
  for (const std::string* path : {&request.resultPly, &request.creaseLines}) {
    if (path->empty()) continue;  // refuse an unwritable destination before any work
    out.error = CheckOutputPath(*path, path == &request.resultPly ? "the results PLY" : "the crease lines");
    if (!out.error.empty()) {
      out.failure = RunOutcome::kCannotWrite;
      return out;
    }
  }
  std::vector<VertexResult> res;
  Status st;
  try {  // the working copy and the results of a huge mesh may not fit: refuse, never throw
    SurfaceGraph g;  // kept for the crease network, which reads the mesh's edges and faces
    st = vcg::tri::NormalVectorVoting<MeshType>::Compute(m, request.options.core, res, out.summary, g, progress);
    if (st.ok && request.WantsCreaseNetwork()) {
      out.crease = FindCreaseOutputs(m, g, res, out.summary, request.options.core.creaseAngleDeg);
      out.creaseNetwork = true;
    }
  } catch (const std::bad_alloc&) {
    st = Status();
    st.message = "Out of memory: the mesh's working copy and results did not fit.";
  }
  if (!st.ok) {
    out.failure = st.cancelled ? RunOutcome::kCancelled : RunOutcome::kRefused;
    out.error = st.message;
    return out;
  }
  if (enable) enable(ApplyResults<MeshType>::NeedsFor(request.options));
  const CreaseOutputs* crease = out.creaseNetwork ? &out.crease : nullptr;
  ApplyResults<MeshType>::Apply(m, res, request.options, crease);
  out.meshChanged = true;
  out.log.push_back(SummaryLine(out.summary));
  out.log.push_back(SettingsLine(request.options, out.summary));
  if (crease) out.log.push_back(CreaseNetworkLine(*crease));
  out.warnings = out.summary.warnings;
  std::string error;
  if ((!request.resultPly.empty() &&
       !WriteResultPly(request.resultPly, m, res, request.binaryPly, request.plyComments, error, crease)) ||
      (!request.creaseLines.empty() && !WriteCreaseLines(request.creaseLines, m, out.crease, error))) {
    out.failure = RunOutcome::kCannotWrite;
    out.error = error;
  }
  return out;
}

}  // namespace nvv

#endif
