// The crease lines as an edge mesh: what MeshLab's "crease lines" layer holds (both plugin APIs
// build it here; the command-line tool writes the same lines to a file, crease_lines_file.h).
//
//   vertices  the mesh vertices the lines pass through, each once (crease_outputs.h's
//             LinesAsEdges), at the mesh's positions; coloured by line where the edge mesh has
//             vertex colours (one colour per line, corners in the corner class colour);
//   edges     each line's edges in order along it; per-edge attributes of the mesh's scalar (as
//             nvv_patch is): nvv_line, the line's id (as in the PLY's edge element and the lines
//             file), and nvv_cusp_angle in degrees (as the vertices' nvv_cusp_angle);
//   Tr        the mesh's transformation, so the layer lies on the mesh it came from.
#ifndef NVV_FILTER_CREASE_LINES_LAYER_H
#define NVV_FILTER_CREASE_LINES_LAYER_H

#include <vcg/complex/complex.h>

#include "core/params.h"
#include "filter/apply_results.h"
#include "filter/crease_outputs.h"

namespace nvv {

// Fills `em` (cleared first) with the lines of `c`, a network found on `m`.
template <class MeshType, class EdgeMeshType>
void BuildCreaseLinesLayer(const MeshType& m, const CreaseOutputs& c, EdgeMeshType& em) {
  using Alloc = vcg::tri::Allocator<EdgeMeshType>;
  using Scalar = typename EdgeMeshType::ScalarType;
  em.Clear();
  const CreaseLineEdges le = LinesAsEdges(c, m.vert.size());
  if (le.meshVertex.empty()) return;
  auto v0 = Alloc::AddVertices(em, le.meshVertex.size());
  for (std::size_t i = 0; i < le.meshVertex.size(); ++i) {
    const auto& p = m.vert[le.meshVertex[i]].cP();
    v0[i].P() = typename EdgeMeshType::CoordType(Scalar(p[0]), Scalar(p[1]), Scalar(p[2]));
  }
  auto e0 = Alloc::AddEdges(em, le.edges.size());
  auto line = Alloc::template GetPerEdgeAttribute<Scalar>(em, AttributeNames::Line());
  auto cusp = Alloc::template GetPerEdgeAttribute<Scalar>(em, AttributeNames::CuspAngle());
  for (std::size_t i = 0; i < le.edges.size(); ++i) {
    const CreaseLineEdges::Edge& e = le.edges[i];
    e0[i].V(0) = &em.vert[e.a];
    e0[i].V(1) = &em.vert[e.b];
    line[e0[i]] = Scalar(e.line);
    cusp[e0[i]] = Scalar(RadToDeg(e.cuspAngle));
  }
  if (vcg::tri::HasPerVertexColor(em)) {
    const int count = int(c.net.lines.size());
    for (std::size_t l = 0; l < c.net.lines.size(); ++l)
      for (int v : le.polylines[l]) em.vert[v].C() = vcg::Color4b::Scatter(count, int(l), 0.8f, 0.9f);
    for (std::size_t l = 0; l < c.net.lines.size(); ++l)  // a corner ends several lines: its own colour
      for (int end = 0; end < 2; ++end)
        if (c.net.lines[l].endCorner[end] >= 0)
          em.vert[end == 0 ? le.polylines[l].front() : le.polylines[l].back()].C() = ClassColor(VertexClass::Corner);
  }
  em.Tr.Import(m.Tr);
  vcg::tri::UpdateBounding<EdgeMeshType>::Box(em);
}

}  // namespace nvv

#endif
