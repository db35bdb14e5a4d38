// Fast marching distances against analytic geodesics, and against edge Dijkstra.
#include <gtest/gtest.h>

#include <queue>

#include "test_support.h"
#include "core/geodesic_march.h"

using namespace nvv_test;

namespace {

// Edge Dijkstra over the same graph: the baseline fast marching must beat.
std::vector<double> EdgeDijkstra(const nvv::SurfaceGraph& g, int src) {
  std::vector<double> d(g.VertexCount(), 1e300);
  typedef std::pair<double, int> QE;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
  d[src] = 0;
  q.push({0, src});
  while (!q.empty()) {
    const auto e = q.top();
    q.pop();
    if (e.first > d[e.second]) continue;
    for (int i = g.FaceBegin(e.second); i < g.FaceEnd(e.second); ++i)
      for (int o : g.face[g.vfList[i]]) {
        const double nd = e.first + (g.pos[o] - g.pos[e.second]).norm();
        if (nd < d[o]) { d[o] = nd; q.push({nd, o}); }
      }
  }
  return d;
}

struct Errors {
  Stats march, dijkstra;
};

// Relative errors of reached vertices beyond 2 l_ave from the source.
template <class Truth>
Errors Compare(const TMesh& m, int src, double radius, Truth truth) {
  nvv::SurfaceGraph g;
  nvv::BuildSurfaceGraph(m, g);
  nvv::GeodesicMarch march(g);
  march.Run(src, radius, 1 << 30);
  const auto dj = EdgeDijkstra(g, src);
  std::vector<double> em, ed;
  for (int v : march.Reached()) {
    const double t = truth(g.pos[src], g.pos[v]);
    if (t < 2 * g.meanEdge) continue;
    em.push_back(std::abs(march.Distance(v) - t) / t);
    ed.push_back(std::abs(dj[v] - t) / t);
  }
  return {StatsOf(em), StatsOf(ed)};
}

int Nearest(const TMesh& m, const vcg::Point3d& p) {
  int best = 0;
  for (int i = 0; i < int(m.vert.size()); ++i)
    if (vcg::Distance(m.vert[i].cP(), p) < vcg::Distance(m.vert[best].cP(), p)) best = i;
  return best;
}

double Euclid(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm(); }

}  // namespace

TEST(GeodesicMarch, PlaneRegularGridIsExactEuclidean) {
  TMesh m;
  nvv_shapes::PaperPlane(m);
  const Errors e = Compare(m, Nearest(m, vcg::Point3d(0, 0, 0)), 12.0, Euclid);
  EXPECT_GT(e.march.n, 300u);
  EXPECT_LT(e.march.max, 1e-9);           // unfolding is exact on a plane
  EXPECT_GT(e.dijkstra.max, 0.05);        // edge paths are not (zig-zag off the edge directions)
}

TEST(GeodesicMarch, PlaneIrregularGridWithinOneAndHalfPercent) {
  TMesh m;
  nvv_shapes::PaperPlane(m, 0.6, 7);
  const Errors e = Compare(m, Nearest(m, vcg::Point3d(0, 0, 0)), 12.0, Euclid);
  EXPECT_LT(e.march.median, 0.002);
  EXPECT_LT(e.march.p90, 0.015);
  EXPECT_LT(e.march.median * 5, e.dijkstra.median);
}

TEST(GeodesicMarch, SphereGreatCircle) {
  const double R = 10;
  for (double irr : {0.0, 0.6}) {
    TMesh m;
    nvv_shapes::UVSphere(m, R, 96, 48, irr, 3);
    auto greatCircle = [R](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return R * std::acos(std::max(-1.0, std::min(1.0, a.normalized().dot(b.normalized()))));
    };
    const Errors e = Compare(m, Nearest(m, vcg::Point3d(R, 0, 0)), 6.0, greatCircle);
    EXPECT_GT(e.march.n, 200u) << "irregular " << irr;
    EXPECT_LT(e.march.median, 0.01) << "irregular " << irr;
    EXPECT_LT(e.march.p90, 0.02) << "irregular " << irr;
    EXPECT_LT(e.march.median, e.dijkstra.median) << "irregular " << irr;
  }
}

TEST(GeodesicMarch, CylinderUnrolled) {
  const double R = 8;
  for (double irr : {0.0, 0.6}) {
    TMesh m;
    nvv_shapes::Cylinder(m, R, 30, 80, 50, irr, 5);
    auto unrolled = [R](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      const double dth = std::acos(std::max(-1.0, std::min(1.0, a.head<2>().normalized().dot(b.head<2>().normalized()))));
      return std::hypot(R * dth, a.z() - b.z());
    };
    const Errors e = Compare(m, Nearest(m, vcg::Point3d(R, 0, 0)), 6.0, unrolled);
    EXPECT_GT(e.march.n, 200u);
    EXPECT_LT(e.march.median, 0.01) << "irregular " << irr;
    EXPECT_LT(e.march.p90, 0.02) << "irregular " << irr;
    EXPECT_LT(e.march.median, e.dijkstra.median) << "irregular " << irr;
  }
}

TEST(GeodesicMarch, StopsAtRadiusAndResetsScratch) {
  TMesh m;
  nvv_shapes::PaperPlane(m);
  nvv::SurfaceGraph g;
  nvv::BuildSurfaceGraph(m, g);
  nvv::GeodesicMarch march(g);
  const int c = Nearest(m, vcg::Point3d(0, 0, 0));
  march.Run(c, 3.0, 1 << 30);
  const std::size_t first = march.Reached().size();
  for (int v : march.Reached()) EXPECT_LE(march.Distance(v), 3.0);
  // A second march from a far corner must not see the first march's distances.
  march.Run(0, 3.0, 1 << 30);
  EXPECT_FALSE(march.IsReached(c));
  march.Run(c, 3.0, 1 << 30);
  EXPECT_EQ(first, march.Reached().size());
  // The cap stops the march.
  EXPECT_FALSE(march.Run(c, 100.0, 50));
  EXPECT_EQ(50u, march.Reached().size());
}

TEST(GeodesicMarch, BlockedVerticesAreReachedButNotCrossed) {
  TMesh m;
  nvv_shapes::PaperPlane(m);
  nvv::SurfaceGraph g;
  nvv::BuildSurfaceGraph(m, g);
  nvv::GeodesicMarch march(g);
  // Block the column x = 0.5 (a wall); start left of it.
  auto wall = [&](int v) { return std::abs(g.pos[v].x() - 0.5) < 1e-9; };
  const int src = Nearest(m, vcg::Point3d(-2.5, 0, 0));
  march.Run(src, 8.0, 1 << 30, wall);
  bool wallReached = false;
  for (int v : march.Reached()) {
    EXPECT_LT(g.pos[v].x(), 0.6);  // nothing beyond the wall
    wallReached = wallReached || wall(v);
  }
  EXPECT_TRUE(wallReached);
}
