// The compact graph: the same bits on any thread count, the orientation check, and the
// huge-page advice of its large arrays.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "test_support.h"

using namespace nvv_test;

namespace {

template <class T>
bool SameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void ExpectSameGraph(const nvv::SurfaceGraph& a, const nvv::SurfaceGraph& b) {
  EXPECT_TRUE(SameBytes(a.pos, b.pos));
  EXPECT_TRUE(SameBytes(a.usable, b.usable));
  EXPECT_TRUE(SameBytes(a.face, b.face));
  EXPECT_TRUE(SameBytes(a.faceNormal, b.faceNormal));
  EXPECT_TRUE(SameBytes(a.faceArea, b.faceArea));
  EXPECT_TRUE(SameBytes(a.faceEdge, b.faceEdge));
  EXPECT_TRUE(SameBytes(a.vfStart, b.vfStart));
  EXPECT_TRUE(SameBytes(a.vfList, b.vfList));
  EXPECT_TRUE(SameBytes(a.nonManifoldEdges, b.nonManifoldEdges));
  EXPECT_TRUE(SameBytes(a.edgeGroupKey, b.edgeGroupKey));
  EXPECT_TRUE(SameBytes(a.edgeGroupStart, b.edgeGroupStart));
  EXPECT_TRUE(SameBytes(a.edgeGroupFaces, b.edgeGroupFaces));
  EXPECT_EQ(0, std::memcmp(&a.meanEdge, &b.meanEdge, sizeof(double)));
  EXPECT_EQ(0, std::memcmp(&a.maxArea, &b.maxArea, sizeof(double)));
  EXPECT_EQ(a.consistentlyOriented, b.consistentlyOriented);
  EXPECT_EQ(a.degenerate, b.degenerate);
  EXPECT_EQ(a.dropped, b.dropped);
  EXPECT_EQ(a.unreferenced, b.unreferenced);
}

}  // namespace

TEST(SurfaceGraph, SameBitsOnOneAndTwoThreads) {
  TMesh m;
  NoisySphere(m);
  // A zero-area face (a vertex on its opposite edge's midpoint) and a face repeating a vertex.
  auto& f = m.face[m.face.size() / 2];
  f.V(2)->P() = (f.V(0)->P() + f.V(1)->P()) * 0.5;
  m.face[7].V(1) = m.face[7].V(0);
  nvv::SurfaceGraph one, two;
  nvv::BuildSurfaceGraph(m, one, 1);
  nvv::BuildSurfaceGraph(m, two, 2);
  EXPECT_GE(one.degenerate, 1u);
  EXPECT_EQ(one.dropped, 1u);
  EXPECT_TRUE(one.consistentlyOriented);
  ExpectSameGraph(one, two);
}

TEST(SurfaceGraph, OneFlippedFaceBreaksOrientationOnAnyThreadCount) {
  for (std::size_t which : {std::size_t(0), std::size_t(500), std::size_t(1700)}) {
    TMesh m;
    NoisySphere(m);
    ASSERT_LT(which, m.face.size());
    std::swap(m.face[which].V(0), m.face[which].V(1));
    nvv::SurfaceGraph one, two;
    nvv::BuildSurfaceGraph(m, one, 1);
    nvv::BuildSurfaceGraph(m, two, 2);
    EXPECT_FALSE(one.consistentlyOriented) << "face " << which;
    ExpectSameGraph(one, two);
  }
}

namespace {

// A graph from raw positions and faces.
nvv::SurfaceGraph Graph(std::vector<Eigen::Vector3d> pos, const std::vector<std::array<int, 3>>& faces) {
  nvv::SurfaceGraph g;
  std::vector<std::uint8_t> usable(pos.size(), 1);
  g.Build(std::move(pos), std::move(usable), faces, 1);
  return g;
}

// `pages` triangles on the spine 0-1, page i's third vertex at angle i around the spine.
nvv::SurfaceGraph Book(int pages) {
  std::vector<Eigen::Vector3d> pos = {{0, 0, 0}, {0, 0, 1}};
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < pages; ++i) {
    const double a = 6.283185307179586 * i / pages;
    pos.emplace_back(std::cos(a), std::sin(a), 0.5);
    faces.push_back({0, 1, 2 + i});
  }
  return Graph(std::move(pos), faces);
}

std::vector<int> FacesAcross(const nvv::SurfaceGraph& g, int f, int a, int b) {
  std::vector<int> out;
  g.ForEachFaceAcross(f, a, b, [&](int o) { out.push_back(o); });
  return out;
}

}  // namespace

TEST(SurfaceGraph, FacesAcrossAnEdgeOneBorderOrSeveral) {
  // Two triangles on a square: one face across the diagonal, none across the rim.
  const auto square = Graph({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_EQ(std::vector<int>{1}, FacesAcross(square, 0, 2, 0));
  EXPECT_EQ(std::vector<int>{0}, FacesAcross(square, 1, 0, 2));
  EXPECT_TRUE(FacesAcross(square, 0, 0, 1).empty());
  EXPECT_TRUE(square.OnBorder(0));
  // A book of 5 pages: every other page is across the spine, in face order.
  const auto book5 = Book(5);
  EXPECT_EQ((std::vector<int>{0, 1, 3, 4}), FacesAcross(book5, 2, 1, 0));
  EXPECT_TRUE(book5.OnBorder(2));  // (its other two edges are the book's rim)
  // A book of more pages than are worth pairing lists one other page only.
  const auto book = Book(nvv::tuning::kMaxFacesListedPerEdge + 1);
  EXPECT_EQ(std::vector<int>{0}, FacesAcross(book, 3, 0, 1));
  EXPECT_EQ(std::vector<int>{1}, FacesAcross(book, 0, 0, 1));
}

TEST(SurfaceGraph, OrientationAndClosureFromTheEdgesDirections) {
  const std::vector<Eigen::Vector3d> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const auto out = Graph(tet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  EXPECT_TRUE(out.consistentlyOriented);
  EXPECT_TRUE(out.closed);
  EXPECT_NEAR(1.0 / 6.0, out.volume, 1e-15);
  const auto in = Graph(tet, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
  EXPECT_TRUE(in.closed);
  EXPECT_NEAR(-1.0 / 6.0, in.volume, 1e-15);
  // One face turned: its edges are used twice in one direction.
  const auto flipped = Graph(tet, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 3, 2}});
  EXPECT_FALSE(flipped.consistentlyOriented);
  EXPECT_FALSE(flipped.closed);
  // An open, consistently oriented strip is not closed.
  const auto open = Graph(tet, {{0, 2, 1}, {0, 1, 3}});
  EXPECT_TRUE(open.consistentlyOriented);
  EXPECT_FALSE(open.closed);
  // A book whose pages all run 0 -> 1 is inconsistent; alternating pages are not.
  EXPECT_FALSE(Book(4).consistentlyOriented);
}

TEST(HugePages, AssignAndReserveKeepTheirValues) {
  std::vector<double> v;
  nvv::AssignOnHugePages(v, 3u << 20, 2.5);  // 24 MB
  ASSERT_EQ(v.size(), std::size_t(3) << 20);
  EXPECT_EQ(v.front(), 2.5);
  EXPECT_EQ(v.back(), 2.5);
  const double* block = v.data();
  nvv::AssignOnHugePages(v, 1u << 20, -1.0);  // smaller: the same block, new values
  EXPECT_EQ(v.data(), block);
  ASSERT_EQ(v.size(), std::size_t(1) << 20);
  EXPECT_EQ(v.back(), -1.0);

  std::vector<int> w{4, 5, 6};
  nvv::ReserveOnHugePages(w, 2u << 20);
  EXPECT_GE(w.capacity(), std::size_t(2) << 20);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0], 4);
  EXPECT_EQ(w[2], 6);
}

// The advice reaches the kernel: the mapping holding the block's 2 MB-aligned part carries the
// "hg" (MADV_HUGEPAGE) flag in /proc/self/smaps, whether or not huge pages were free to grant.
TEST(HugePages, LargeBlocksAreAdvised) {
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) GTEST_SKIP() << "no transparent huge pages";
  const std::vector<float> v = nvv::FilledOnHugePages(std::size_t(8) << 20, 1.0f);  // 32 MB
  const std::uintptr_t huge = std::uintptr_t(2) << 20;
  const std::uintptr_t inside = (reinterpret_cast<std::uintptr_t>(v.data()) + huge - 1) & ~(huge - 1);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inMapping = false, found = false, advised = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inMapping = lo <= inside && inside < hi;
      found = found || inMapping;
    } else if (inMapping && line.rfind("VmFlags:", 0) == 0) {
      advised = line.find(" hg") != std::string::npos;
    }
  }
  ASSERT_TRUE(found);
  EXPECT_TRUE(advised);
}
