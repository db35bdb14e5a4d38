// Input that once cost time or memory out of proportion to its real content, or gave values a
// user could not trust without a word: repeated faces, absurd radii, inward-facing closed meshes,
// radii too small for any triangle.
#include <gtest/gtest.h>

#include "core/ball_flood.h"
#include "core/geodesic_march.h"
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
  EXPECT_EQ(nvv::AutoNeighbourhoodCap(50, 1000), nvv::AutoNeighbourhoodCap(1e30, 1000));
  EXPECT_EQ(nvv::AutoNeighbourhoodCap(50, 1000), nvv::AutoNeighbourhoodCap(std::nan(""), 1000));
  EXPECT_LT(nvv::AutoNeighbourhoodCap(3, 1000), nvv::AutoNeighbourhoodCap(50, 1000));
  TMesh m;
  NoisySphere(m);
  nvv::Params p = WithK(3);
  p.absoluteRadius = 1e30;
  const NvvRun r = RunNvv(m, p);
  ASSERT_TRUE(r.st.ok) << r.st.message;  // the whole mesh is every vertex's neighbourhood: still defined
  for (const auto& v : r.res) EXPECT_TRUE(std::isfinite(v.k1) && std::isfinite(v.normal[0]));
}

TEST(BoundedWork, TheAutomaticCapKeepsTheWholeMeshWithinTheVisitBudget) {
  using nvv::AutoNeighbourhoodCap;
  using nvv::tuning::kAutoCapMin;
  // Small meshes: the cap is 16 k^2 (at least 1,024) as before, at any k.
  EXPECT_EQ(40000, AutoNeighbourhoodCap(50, 6000));
  EXPECT_EQ(kAutoCapMin, AutoNeighbourhoodCap(3, 1600000));
  EXPECT_EQ(kAutoCapMin, AutoNeighbourhoodCap(8, 1000000));
  // Large meshes at a large k: the cap times the vertices stays within the budget...
  for (std::size_t n : {100000u, 250000u, 1000000u, 10000000u}) {
    const int cap = AutoNeighbourhoodCap(50, n);
    EXPECT_LE(double(cap) * double(n), std::max(nvv::tuning::kAutoVisitBudget, double(kAutoCapMin) * double(n))) << n;
    EXPECT_GE(cap, kAutoCapMin) << n;
  }
  // ... down to the floor: k = 50 on a million vertices marches what k = 8 does.
  EXPECT_EQ(kAutoCapMin, AutoNeighbourhoodCap(50, 1000000));
}

namespace {

// `spokes` triangles sharing only vertex 0, each far from the others: every spoke's ball
// holds the centre, whose faces are all of the mesh.
void Star(TMesh& m, int spokes) {
  m.Clear();
  auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, 1 + 2 * spokes);
  v[0].P() = vcg::Point3d(0, 0, 0);
  for (int i = 0; i < spokes; ++i) {
    const double a = 6.283185307179586 * i / spokes, z = double(i % 7) - 3.0;
    v[1 + 2 * i].P() = vcg::Point3d(std::cos(a), std::sin(a), z * 0.1);
    v[2 + 2 * i].P() = vcg::Point3d(std::cos(a) + 0.3, std::sin(a) + 0.2, z * 0.1 + 0.5);
    vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[0], &m.vert[1 + 2 * i], &m.vert[2 + 2 * i]);
  }
}

// One triangle's spine 0-1 shared by `pages` faces whose third vertices all sit on vertex 0
// (a file listing one point 100,000 times).
void BookOfDuplicates(TMesh& m, int pages) {
  m.Clear();
  auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, 2 + pages);
  v[0].P() = vcg::Point3d(1, 0, 0);
  v[1].P() = vcg::Point3d(0, 1, 0);
  for (int i = 0; i < pages; ++i) {
    v[2 + i].P() = vcg::Point3d(0, 0, 0);
    vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[2 + i], &m.vert[0], &m.vert[1]);
  }
}

}  // namespace

TEST(BoundedWork, AMarchScansABoundedNumberOfFacesWhateverTheValences) {
  TMesh m;
  Star(m, 3000);
  nvv::SurfaceGraph g;
  nvv::BuildSurfaceGraph(m, g, 1);
  nvv::GeodesicMarch march(g);
  nvv::BallFlood flood(g);
  const int cap = 64;
  const long long bound = (long long)cap * nvv::tuning::kMarchFacesPerVertex;
  auto facesOf = [&](const std::vector<int>& reached, int source) {
    long long faces = 0;
    for (int x : reached)
      if (x != source) faces += g.FaceEnd(x) - g.FaceBegin(x);
    return faces;
  };
  for (int spoke : {1, 2, 1001, 5999}) {
    EXPECT_FALSE(march.Run(spoke, 10.0, cap)) << spoke;  // the centre is within reach, but not within the bound
    EXPECT_LE(facesOf(march.Reached(), spoke), bound) << spoke;
    EXPECT_FALSE(flood.Run(spoke, 10.0, cap)) << spoke;
    EXPECT_LE(facesOf(flood.Reached(), spoke), bound) << spoke;
  }
  // The centre's own march expands its 3,000 faces once and stops at the vertex cap.
  EXPECT_FALSE(march.Run(0, 10.0, cap));
  EXPECT_EQ(std::size_t(cap), march.Reached().size());
}

TEST(BoundedWork, HighValenceFansAndBookEdgesRunToTheEnd) {
  for (int shape = 0; shape < 2; ++shape) {
    TMesh m;
    if (shape == 0) Star(m, 20000);
    else BookOfDuplicates(m, 20000);
    const NvvRun r = RunNvv(m, WithK(3));
    ASSERT_TRUE(r.st.ok) << r.st.message;
    EXPECT_GT(r.sum.capped, 0u) << shape;
    for (const auto& v : r.res) {
      EXPECT_TRUE(std::isfinite(v.normal[0]) && std::isfinite(v.k1) && std::isfinite(v.k2)) << shape;
    }
  }
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
