// Input that once cost time or memory out of proportion to its real content, or gave values a
// user could not trust without a word: repeated faces, absurd radii, inward-facing closed meshes,
// radii too small for any triangle.
#include <gtest/gtest.h>

#include "test_support.h"

using namespace nvv_test;
using nvv::VertexClass;

namespace {

// One triangle, then `copies - 1` more faces on the same three vertices (in rotated orders).
void RepeatedTriangle(TMesh& m, int copies) {
  m.Clear();
  auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, 3);
  v[0].P() = vcg::Point3d(0, 0, 0);
  v[1].P() = vcg::Point3d(1, 0, 0);
  v[2].P() = vcg::Point3d(0, 1, 0);
  for (int i = 0; i < copies; ++i) {
    const int r = i % 3;
    vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[r], &m.vert[(r + 1) % 3], &m.vert[(r + 2) % 3]);
  }
}

bool HasWarning(const nvv::Summary& s, const std::string& words) {
  for (const auto& w : s.warnings)
    if (w.find(words) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(BoundedWork, RepeatedFacesCountOnceAndGiveTheSingleTrianglesResult) {
  TMesh one;
  RepeatedTriangle(one, 1);
  const NvvRun single = RunNvv(one, WithK(3));
  ASSERT_TRUE(single.st.ok) << single.st.message;
  for (int copies : {2, 1000, 30000}) {
    TMesh m;
    RepeatedTriangle(m, copies);
    const NvvRun r = RunNvv(m, WithK(3));
    ASSERT_TRUE(r.st.ok) << r.st.message;
    EXPECT_EQ(std::size_t(copies - 1), r.sum.repeatedFaces);
    EXPECT_TRUE(HasWarning(r.sum, "counted once"));
    EXPECT_TRUE(SameBits(single.res, r.res)) << copies << " copies";
  }
}

TEST(BoundedWork, AnAbsurdRadiusCostsWhatTheLargestKCosts) {
  EXPECT_EQ(nvv::AutoNeighbourhoodCap(50), nvv::AutoNeighbourhoodCap(1e30));
  EXPECT_EQ(nvv::AutoNeighbourhoodCap(50), nvv::AutoNeighbourhoodCap(std::nan("")));
  EXPECT_LT(nvv::AutoNeighbourhoodCap(3), nvv::AutoNeighbourhoodCap(50));
  TMesh m;
  NoisySphere(m);
  nvv::Params p = WithK(3);
  p.absoluteRadius = 1e30;
  const NvvRun r = RunNvv(m, p);
  ASSERT_TRUE(r.st.ok) << r.st.message;  // the whole mesh is every vertex's neighbourhood: still defined
  for (const auto& v : r.res) EXPECT_TRUE(std::isfinite(v.k1) && std::isfinite(v.normal[0]));
}

TEST(BoundedWork, AClosedMeshWhoseFacesPointInwardIsWarnedAbout) {
  TMesh m;
  nvv_shapes::Cube(m, 5.0, 8);
  const NvvRun outward = RunNvv(m, WithK(3));
  ASSERT_TRUE(outward.st.ok);
  EXPECT_FALSE(HasWarning(outward.sum, "point inward"));
  for (auto& f : m.face) std::swap(f.V(1), f.V(2));
  const NvvRun inward = RunNvv(m, WithK(3));
  ASSERT_TRUE(inward.st.ok);
  EXPECT_TRUE(HasWarning(inward.sum, "point inward"));
  // An open mesh has no inside: no warning whichever way it faces.
  TMesh grid;
  nvv_shapes::PaperSphere(grid);
  for (auto& f : grid.face) std::swap(f.V(1), f.V(2));
  EXPECT_FALSE(HasWarning(RunNvv(grid, WithK(3)).sum, "point inward"));
}

TEST(BoundedWork, ARadiusTooSmallForAnyTriangleIsWarnedAbout) {
  TMesh m;
  NoisySphere(m);
  nvv::Params p = WithK(3);
  p.absoluteRadius = 1e-30;
  const NvvRun r = RunNvv(m, p);
  ASSERT_TRUE(r.st.ok) << r.st.message;
  const std::size_t unclassified = r.sum.perClass[int(VertexClass::Invalid)];
  if (unclassified > 0) {
    EXPECT_TRUE(HasWarning(r.sum, "could not be classified"));
  }
  // A normal radius leaves nothing to warn about.
  EXPECT_FALSE(HasWarning(RunNvv(m, WithK(3)).sum, "could not be classified"));
}
