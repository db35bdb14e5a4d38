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
