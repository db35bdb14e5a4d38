// Crease edges, lines and patches (core/crease_network.h) on shapes whose lines and patches are
// known: a cube (12 lines between 8 corners, 6 patches), a capped cylinder (2 closed lines, 3
// patches), clean and with 10 % (cube: also 20 %) of l_ave noise along the normals.
#include <gtest/gtest.h>

#include <set>

#include "core/crease_network.h"
#include "test_support.h"

using namespace nvv_test;

namespace {

struct Network {
  nvv::SurfaceGraph g;
  NvvRun run;
  nvv::CreaseNetwork net;
};

Network Find(const TMesh& m, double k = 3) {
  Network n;
  n.run = RunNvv(m, WithK(k));
  nvv::BuildSurfaceGraph(m, n.g, 1);
  n.net = nvv::FindCreaseNetwork(n.g, n.run.res, n.run.sum.radius, 60.0);
  return n;
}

// Closed cylinder of radius R and height h: side grid nu x nv, caps as fans of rings.
void CappedCylinder(TMesh& m, double R, double h, int nu, int nv) {
  m.Clear();
  const int rings = std::max(2, int(R / (2 * 3.14159265358979 * R / nu)));  // about square cells on the caps
  std::vector<vcg::Point3d> pos;
  std::vector<std::array<int, 3>> faces;
  auto ringVertex = [&](int level, int i) { return level * nu + (i % nu); };
  for (int level = 0; level <= nv; ++level)
    for (int i = 0; i < nu; ++i) {
      const double a = 2 * 3.14159265358979 * i / nu;
      pos.push_back(vcg::Point3d(R * std::cos(a), R * std::sin(a), h * level / nv));
    }
  for (int level = 0; level < nv; ++level)
    for (int i = 0; i < nu; ++i) {
      const int a = ringVertex(level, i), b = ringVertex(level, i + 1), c = ringVertex(level + 1, i + 1),
                d = ringVertex(level + 1, i);
      faces.push_back({a, b, c});
      faces.push_back({a, c, d});
    }
  for (int cap = 0; cap < 2; ++cap) {
    const double z = cap == 0 ? 0 : h;
    std::vector<int> outer(nu);
    for (int i = 0; i < nu; ++i) outer[i] = ringVertex(cap == 0 ? 0 : nv, i);
    for (int r = rings - 1; r >= 0; --r) {
      std::vector<int> inner(nu);
      if (r == 0) {
        pos.push_back(vcg::Point3d(0, 0, z));
        std::fill(inner.begin(), inner.end(), int(pos.size()) - 1);
      } else {
        for (int i = 0; i < nu; ++i) {
          const double a = 2 * 3.14159265358979 * i / nu, rr = R * r / rings;
          pos.push_back(vcg::Point3d(rr * std::cos(a), rr * std::sin(a), z));
          inner[i] = int(pos.size()) - 1;
        }
      }
      for (int i = 0; i < nu; ++i) {
        const int a = outer[i], b = outer[(i + 1) % nu], c = inner[(i + 1) % nu], d = inner[i];
        std::array<int, 3> t1{a, c, b}, t2{a, d, c};  // bottom cap faces down
        if (cap == 1) t1 = {a, b, c}, t2 = {a, c, d};
        faces.push_back(t1);
        if (c != d) faces.push_back(t2);
      }
      outer = inner;
    }
  }
  auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) v[i].P() = pos[i];
  for (const auto& f : faces) vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[f[0]], &m.vert[f[1]], &m.vert[f[2]]);
}

std::set<int> EndCorners(const nvv::CreaseNetwork& net) {
  std::set<int> corners;
  for (const auto& l : net.lines)
    for (int c : l.endCorner)
      if (c >= 0) corners.insert(c);
  return corners;
}

}  // namespace

TEST(CreaseNetwork, ACubeHasTwelveLinesEightCornersAndSixPatches) {
  for (double noise : {0.0, 0.1, 0.2}) {
    TMesh m;
    nvv_shapes::Cube(m, 5.0, 21);
    if (noise > 0) NoiseAlongNormals(m, noise * 0.5, 7);  // l_ave = 0.5
    const Network n = Find(m);
    EXPECT_EQ(6, n.net.patchCount) << "noise " << noise;
    double total = 0, cusp = 0;
    for (const auto& l : n.net.lines) {
      EXPECT_FALSE(l.closed);
      total += l.length;
      cusp += l.length * l.meanCuspAngle * 180 / 3.14159265358979;
    }
    EXPECT_NEAR(120.0, total, 12.0) << "noise " << noise;  // the cube's 12 edges of 10
    EXPECT_NEAR(90.0, cusp / total, 10.0) << "noise " << noise;
    if (noise <= 0.1) {
      EXPECT_EQ(12u, n.net.lines.size()) << "noise " << noise;
      for (const auto& l : n.net.lines) {
        EXPECT_NEAR(10.0, l.length, 1.0) << "noise " << noise;
        EXPECT_NEAR(90.0, l.meanCuspAngle * 180 / 3.14159265358979, 15.0) << "noise " << noise;
      }
    } else {  // corners classified creases split lines at junctions of three
      EXPECT_GE(n.net.lines.size(), 12u);
    }
    // Every line ends at corners where the mesh is clean; under noise a corner may be classified
    // a crease, and the line ends at its junction of three.
    if (noise == 0) EXPECT_EQ(8u, EndCorners(n.net).size());
    else EXPECT_GE(EndCorners(n.net).size(), 6u);
  }
}

// (At 20 % the rims still break for some noise seeds: a gap beyond 2 g_m or off the line's direction.)
TEST(CreaseNetwork, ACappedCylinderHasTwoClosedLinesAndThreePatches) {
  for (double noise : {0.0, 0.1}) {
    TMesh m;
    CappedCylinder(m, 5.0, 10.0, 64, 20);
    if (noise > 0) NoiseAlongNormals(m, noise * 0.5, 7);
    const Network n = Find(m);
    ASSERT_EQ(2u, n.net.lines.size()) << "noise " << noise;
    for (const auto& l : n.net.lines) {
      EXPECT_TRUE(l.closed) << "noise " << noise;
      EXPECT_NEAR(2 * 3.14159265358979 * 5.0, l.length, 1.5) << "noise " << noise;
    }
    EXPECT_EQ(3, n.net.patchCount) << "noise " << noise;
  }
}
