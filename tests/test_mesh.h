// A plain vcglib mesh for the tests (double precision), with what vcglib's own curvature
// estimators need so they can run on the same meshes for comparison.
#ifndef NVV_TESTS_TEST_MESH_H
#define NVV_TESTS_TEST_MESH_H

#include <vcg/complex/complex.h>

namespace nvv_test {
class TVertex;
class TFace;
struct TUsedTypes : public vcg::UsedTypes<vcg::Use<TVertex>::AsVertexType, vcg::Use<TFace>::AsFaceType> {};
class TVertex : public vcg::Vertex<TUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::VFAdj,
                                   vcg::vertex::Curvatured, vcg::vertex::CurvatureDird, vcg::vertex::Qualityd,
                                   vcg::vertex::Color4b, vcg::vertex::Mark, vcg::vertex::BitFlags> {};
class TFace : public vcg::Face<TUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::VFAdj,
                               vcg::face::FFAdj, vcg::face::Mark, vcg::face::BitFlags> {};
class TMesh : public vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TFace>> {
 public:
  // vcglib's TriMesh destructor leaves the per-vertex attributes allocated (LeakSanitizer).
  ~TMesh() { ClearAttributes(); }
};
}  // namespace nvv_test

#endif
