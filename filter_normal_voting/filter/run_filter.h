// The filter's run sequence, shared by the command-line tool and both MeshLab adapters:
//
//   check the results file's folder -> compute (refused or cancelled: the mesh is untouched)
//   -> enable the mesh's components -> apply the results -> write the results PLY -> log lines
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
#include "filter/filter_options.h"
#include "io/result_ply.h"

namespace nvv {

struct RunRequest {
  FilterOptions options;
  std::string resultPly;                 // empty: no results file
  bool binaryPly = true;
  std::vector<std::string> plyComments;  // extra header comments of the results file
};

struct RunOutcome {
  enum Failure { kNone, kRefused, kCancelled, kCannotWrite };
  Failure failure = kNone;
  std::string error;                 // why it failed, one sentence
  bool meshChanged = false;          // false whenever failure is kRefused or kCancelled
  Summary summary;
  std::vector<std::string> log;      // the summary line and the settings line
  std::vector<std::string> warnings; // about the input, one sentence each
  bool Ok() const { return failure == kNone; }
};

// Empty when a file can be written at `path`: its folder exists and is writable and the path
// is not a directory. Otherwise the reason.
std::string CheckOutputPath(const std::string& path);

// The settings line of the log: k, the absolute radius, the angles and their constants.
std::string SettingsLine(const FilterOptions& options, const Summary& s);

// Runs the filter on m. `enable(needs)` is called just before the results are applied, so a
// front end can enable the mesh components they need (MeshLab's updateDataMask).
template <class MeshType>
RunOutcome RunFilter(MeshType& m, const RunRequest& request, const Progress& progress = Progress(),
                     const std::function<void(const typename ApplyResults<MeshType>::Needs&)>& enable = nullptr) {
  RunOutcome out;
  if (!request.resultPly.empty()) {  // refuse an unwritable destination before any work
    out.error = CheckOutputPath(request.resultPly);
    if (!out.error.empty()) {
      out.failure = RunOutcome::kCannotWrite;
      return out;
    }
  }
  std::vector<VertexResult> res;
  Status st;
  try {  // the working copy and the results of a huge mesh may not fit: refuse, never throw
    st = vcg::tri::NormalVectorVoting<MeshType>::Compute(m, request.options.core, res, out.summary, progress);
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
  ApplyResults<MeshType>::Apply(m, res, request.options);
  out.meshChanged = true;
  out.log.push_back(SummaryLine(out.summary));
  out.log.push_back(SettingsLine(request.options, out.summary));
  out.warnings = out.summary.warnings;
  std::string error;
  if (!request.resultPly.empty() &&
      !WriteResultPly(request.resultPly, m, res, request.binaryPly, request.plyComments, error)) {
    out.failure = RunOutcome::kCannotWrite;
    out.error = error;
  }
  return out;
}

}  // namespace nvv

#endif
