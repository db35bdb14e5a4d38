// The graph renumbered along a space-filling curve for the passes, and back for the caller.
//
// Every pass reads a neighbourhood of tens of vertices, their faces and each thread's marching
// state at those vertices' indices. Where a mesh arrives in a poor order (a midpoint subdivision
// appends every new vertex after the old ones; reconstructions and merges list vertices as they
// were made) the members of one neighbourhood lie megabytes apart and each read is a cache miss.
// Numbering the vertices along a Morton (Z-order) curve of their positions, and the faces by their
// lowest vertex, puts a neighbourhood into a few runs of adjacent entries.
//
// Only where it pays: on meshes of at least tuning::kLocalityOrderMinVertices (smaller graphs fit
// the caches) whose own order scatters a one-ring over more than tuning::kLocalityWindow indices
// (median of a sample). A grid's rows keep their order: they beat the curve (docs/design.md).
//
// The graph's arrays are gathered into the new order through a copy each (the reads are
// independent and overlap in memory; the largest copy is smaller than what the passes hold
// later). After the run the renumbered graph is released first and the results are gathered
// back into the mesh's numbering in its room; a caller that keeps the graph (the crease network)
// gets it built again from the mesh, as it was.
//
// Results depend on the numbering only where the run breaks ties by index or samples by stride,
// as they would for the same file with its vertices listed in another order; two vertex orders of
// one large mesh (same face list) get the same renumbered graph, hence the same bits.
#ifndef NVV_CORE_LOCALITY_ORDER_H
#define NVV_CORE_LOCALITY_ORDER_H

#include <vector>

#include "surface_graph.h"
#include "vertex_result.h"

namespace nvv {

class LocalityOrder {
 public:
  // Renumbers g along the curve when it is worth it (see the header comment); otherwise leaves g
  // as it is and Active() is false.
  void Apply(SurfaceGraph& g, int threads);
  // Releases the renumbered graph and puts results indexed like its vertices back in the
  // numbering g had before Apply. The caller rebuilds g where it needs it.
  void RestoreResults(SurfaceGraph& g, std::vector<VertexResult>& res, int threads);
  bool Active() const { return !vertexTo_.empty(); }

 private:
  std::vector<int> vertexTo_;  // the new index of each old vertex
};

}  // namespace nvv

#endif
