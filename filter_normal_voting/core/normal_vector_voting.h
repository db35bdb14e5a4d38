// Normal Vector Voting (Page, Sun, Koschan, Paik, Abidi: "Normal Vector Voting: Crease
// Detection and Curvature Estimation on Large, Noisy Meshes", Graphical Models 64, 2002).
//
// Entry point, in the manner of vcglib's tri::UpdateCurvature:
//
//   std::vector<nvv::VertexResult> res;
//   nvv::Summary sum;
//   nvv::Status st = vcg::tri::NormalVectorVoting<MyMesh>::Compute(m, params, res, sum, cb);
//
// Inputs:  m       any vcglib triangle mesh (read only: the mesh is never modified)
//          params  see params.h (k in mean edge lengths, crease / corner angles, fit, ...)
//          cb      progress, called from the calling thread only; returning false cancels
// Outputs: res     one VertexResult per slot of m.vert (deleted slots are Invalid)
//          sum     counts per class, ranges, radius, timings, warnings about the input
// On refusal or cancellation res is empty and the Status says why.
//
// The run, stage by stage (normal_vector_voting.cpp; each stage lives in the file of its
// section of the paper or of its refinement):
//   validate   the parameters and the mesh                                  (this file)
//   vote       pass 1: classes and normals, par. 6.2-6.3                    (normal_votes.h)
//   thin       crease bands thinned to their ridge                          (crease_thinning.h)
//   fit        pass 2: curvature of surface vertices, par. 6.4              (surface_curvature.h)
//   creases    pass 2: curvature along crease lines, par. 6.5               (crease_curvature.h)
//   summarise  counts, ranges and warnings                                  (this file)
// Each pass is parallel over vertices (OpenMP); every vertex's result depends only on the
// previous stage's results and its own neighbourhood, so any thread count gives the same bits.
#ifndef NVV_CORE_NORMAL_VECTOR_VOTING_H
#define NVV_CORE_NORMAL_VECTOR_VOTING_H

#include <string>
#include <vector>

#include "locality_order.h"
#include "parallel_pass.h"
#include "params.h"
#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

struct Status {
  bool ok = false;
  bool cancelled = false;
  std::string message;  // why it was refused, empty when ok
};

// Both passes on a prepared graph. Results are indexed like the graph's vertices.
Status RunNormalVectorVoting(const SurfaceGraph& g, const Params& p, std::vector<VertexResult>& res, Summary& sum,
                             const Progress& cb = Progress());

}  // namespace nvv

namespace vcg {
namespace tri {

template <class MeshType>
class NormalVectorVoting {
 public:
  static nvv::Status Compute(const MeshType& m, const nvv::Params& p, std::vector<nvv::VertexResult>& res,
                             nvv::Summary& sum, const nvv::Progress& cb = nvv::Progress()) {
    nvv::SurfaceGraph g;
    return Run(m, p, res, sum, g, false, cb);
  }
  // The same, keeping the working copy in g for what reads the mesh's edges and faces after the
  // run (the crease network, crease_network.h).
  static nvv::Status Compute(const MeshType& m, const nvv::Params& p, std::vector<nvv::VertexResult>& res,
                             nvv::Summary& sum, nvv::SurfaceGraph& g, const nvv::Progress& cb = nvv::Progress()) {
    return Run(m, p, res, sum, g, true, cb);
  }

 private:
  static nvv::Status Run(const MeshType& m, const nvv::Params& p, std::vector<nvv::VertexResult>& res,
                         nvv::Summary& sum, nvv::SurfaceGraph& g, bool keepGraph, const nvv::Progress& cb) {
    // An absurd thread count is refused by the run below; until then the graph must not try it.
    const int graphThreads = nvv::ValidateParams(p).empty() ? p.threads : 1;
    nvv::BuildSurfaceGraph(m, g, graphThreads);
    // A large mesh in a poor order is renumbered for the passes (locality_order.h); the results
    // come back in m's numbering, and the graph is built again in it where the caller keeps it.
    nvv::LocalityOrder order;
    order.Apply(g, graphThreads);
    const nvv::Status st = nvv::RunNormalVectorVoting(g, p, res, sum, cb);
    if (order.Active()) {
      order.RestoreResults(g, res, graphThreads);
      if (keepGraph) nvv::BuildSurfaceGraph(m, g, graphThreads);
    }
    return st;
  }
};

}  // namespace tri
}  // namespace vcg

#endif
