// Invariance (rigid motion, scale, renumbering), determinism across thread counts,
// cancellation, and defined results on degenerate input.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <numeric>
#include <random>

#include "core/tuning.h"
#include "test_support.h"

using namespace nvv_test;
using nvv::VertexClass;

namespace {


// Fraction of vertices whose class agrees, and the worst curvature / normal differences.
struct Diff {
  double classAgree = 0, maxK = 0, maxNormalDeg = 0;
};
Diff Compare(const std::vector<nvv::VertexResult>& a, const std::vector<nvv::VertexResult>& b,
             const std::vector<int>& map, double kScale, const Eigen::Matrix3d& rot) {
  Diff d;
  int agree = 0, n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto& ra = a[i];
    const auto& rb = b[map[i]];
    ++n;
    if (ra.cls != rb.cls) continue;
    ++agree;
    if (ra.Has(nvv::kCurvatureValid) && rb.Has(nvv::kCurvatureValid)) {
      const double scale = std::max<double>(std::abs(ra.k1), 1e-3);
      d.maxK = std::max(d.maxK, std::abs(ra.k1 * kScale - rb.k1) / (scale * kScale));
      d.maxK = std::max(d.maxK, std::abs(ra.k2 * kScale - rb.k2) / (scale * kScale));
    }
    if (ra.Has(nvv::kNormalValid))
      d.maxNormalDeg = std::max(d.maxNormalDeg, AngleDeg(rot * E(ra.normal), E(rb.normal)));
  }
  d.classAgree = double(agree) / n;
  return d;
}
std::vector<int> Identity(std::size_t n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

}  // namespace

TEST(Invariance, RigidMotion) {
  TMesh m;
  NoisySphere(m);
  const NvvRun a = RunNvv(m, WithK(3.0));
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (auto& v : m.vert) {
    const Eigen::Vector3d q = rot * E(v.cP()) + Eigen::Vector3d(100, -50, 7);
    v.P() = vcg::Point3d(q.x(), q.y(), q.z());
  }
  const NvvRun b = RunNvv(m, WithK(3.0));
  const Diff d = Compare(a.res, b.res, Identity(m.vert.size()), 1.0, rot);
  EXPECT_GE(d.classAgree, 0.999);
  EXPECT_LT(d.maxK, 1e-3);
  EXPECT_LT(d.maxNormalDeg, 0.01);
}

TEST(Invariance, UniformScaleDividesCurvature) {
  TMesh m;
  NoisySphere(m);
  const NvvRun a = RunNvv(m, WithK(3.0));
  const double s = 7.3;
  for (auto& v : m.vert) v.P() *= s;
  const NvvRun b = RunNvv(m, WithK(3.0));
  const Diff d = Compare(a.res, b.res, Identity(m.vert.size()), 1.0 / s, Eigen::Matrix3d::Identity());
  EXPECT_GE(d.classAgree, 0.999);
  EXPECT_LT(d.maxK, 1e-3);
  EXPECT_NEAR(a.sum.radius * s, b.sum.radius, 1e-9 * b.sum.radius);
}

TEST(Invariance, VertexAndFaceRenumbering) {
  TMesh m;
  NoisySphere(m);
  const NvvRun a = RunNvv(m, WithK(3.0));
  // Rebuild the mesh with vertices and faces in a random order.
  std::vector<int> perm = Identity(m.vert.size());
  std::mt19937 rng(5);
  std::shuffle(perm.begin(), perm.end(), rng);
  TMesh p;
  auto vi = vcg::tri::Allocator<TMesh>::AddVertices(p, m.vert.size());
  (void)vi;
  for (std::size_t i = 0; i < m.vert.size(); ++i) p.vert[perm[i]].P() = m.vert[i].cP();
  std::vector<int> faceOrder = Identity(m.face.size());
  std::shuffle(faceOrder.begin(), faceOrder.end(), rng);
  for (int fi : faceOrder) {
    const auto& f = m.face[fi];
    const int rot = fi % 3;  // also rotate each face's vertex order
    vcg::tri::Allocator<TMesh>::AddFace(p, &p.vert[perm[vcg::tri::Index(m, f.cV(rot))]],
                                        &p.vert[perm[vcg::tri::Index(m, f.cV((rot + 1) % 3))]],
                                        &p.vert[perm[vcg::tri::Index(m, f.cV((rot + 2) % 3))]]);
  }
  const NvvRun b = RunNvv(p, WithK(3.0));
  const Diff d = Compare(a.res, b.res, perm, 1.0, Eigen::Matrix3d::Identity());
  EXPECT_GE(d.classAgree, 0.999);
  EXPECT_LT(d.maxK, 1e-3);
  EXPECT_LT(d.maxNormalDeg, 0.01);
}

// A mesh large enough to be renumbered for locality (core/locality_order.h), listed in two
// different scattered orders: the passes see the same renumbered graph, so every vertex gets the
// same bits whatever the file's order, and each result lands on its own vertex (its normal is the
// torus's there). Without the renumbering the two orders sample the noise estimate at different
// vertices and break ties differently.
TEST(Invariance, ALargeMeshInAPoorOrderGivesTheSameBitsInAnyOrder) {
  TMesh m;
  nvv_shapes::Torus(m, 3.0, 1.0, 700, 300, 0.2, 3);
  ASSERT_GE(int(m.vert.size()), nvv::tuning::kLocalityOrderMinVertices);
  std::vector<std::vector<nvv::VertexResult>> mapped;
  for (unsigned seed : {11u, 12u}) {
    std::vector<int> perm = Identity(m.vert.size());
    std::mt19937 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    TMesh p;
    vcg::tri::Allocator<TMesh>::AddVertices(p, m.vert.size());
    for (std::size_t i = 0; i < m.vert.size(); ++i) p.vert[perm[i]].P() = m.vert[i].cP();
    for (const auto& f : m.face)
      vcg::tri::Allocator<TMesh>::AddFace(p, &p.vert[perm[vcg::tri::Index(m, f.cV(0))]],
                                          &p.vert[perm[vcg::tri::Index(m, f.cV(1))]],
                                          &p.vert[perm[vcg::tri::Index(m, f.cV(2))]]);
    nvv::SurfaceGraph g;
    std::vector<nvv::VertexResult> res;
    nvv::Summary sum;
    // k = 1.5: the order is what is tested, and the sanitizer builds run this mesh too.
    ASSERT_TRUE(vcg::tri::NormalVectorVoting<TMesh>::Compute(p, WithK(1.5), res, sum, g).ok);
    // The graph handed back is the mesh's own, as a fresh build makes it.
    nvv::SurfaceGraph fresh;
    nvv::BuildSurfaceGraph(p, fresh);
    EXPECT_TRUE(g.pos == fresh.pos && g.face == fresh.face && g.vfStart == fresh.vfStart && g.vfList == fresh.vfList);
    std::vector<nvv::VertexResult> back(res.size());
    int wrong = 0;
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      back[i] = res[perm[i]];
      const Eigen::Vector3d x = E(m.vert[i].cP());
      const Eigen::Vector3d c = 3.0 * Eigen::Vector3d(x.x(), x.y(), 0).normalized();
      // (either orientation: the grid's faces decide it, not the test)
      if (!back[i].Has(nvv::kNormalValid) ||
          std::abs(E(back[i].normal).normalized().dot((x - c).normalized())) < std::cos(5.0 * M_PI / 180)) ++wrong;
    }
    EXPECT_EQ(wrong, 0);
    mapped.push_back(back);
  }
  EXPECT_TRUE(SameBits(mapped[0], mapped[1]));
}

TEST(Determinism, SameBitsForOneAndTwoThreads) {
  TMesh m;
  NoisySphere(m);
  for (auto fit : {nvv::CurvatureFit::SheetQuadric, nvv::CurvatureFit::PaperTaubin}) {
    nvv::Params p = WithK(3.0, fit);
    p.threads = 1;
    const NvvRun a = RunNvv(m, p);
    p.threads = 2;
    const NvvRun b = RunNvv(m, p);
    ASSERT_EQ(a.res.size(), b.res.size());
    EXPECT_TRUE(SameBits(a.res, b.res));
  }
}

TEST(Cancellation, CallbackReturningFalseCancels) {
  TMesh m;
  nvv_shapes::Torus(m, 6, 2, 200, 80);
  int calls = 0;
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  const nvv::Status st = vcg::tri::NormalVectorVoting<TMesh>::Compute(m, WithK(5.0), res, sum,
      [&calls](int, const char*) { return ++calls < 2; });
  EXPECT_FALSE(st.ok);
  EXPECT_TRUE(st.cancelled);
  EXPECT_TRUE(res.empty());
  EXPECT_GE(calls, 2);
}

TEST(Degenerate, RefusesMeshesWithoutSurface) {
  TMesh m;
  nvv::Status st = RunNvv(m, WithK(3)).st;  // empty
  EXPECT_FALSE(st.ok);
  EXPECT_FALSE(st.message.empty());
  vcg::tri::Allocator<TMesh>::AddVertices(m, 10);  // a point cloud
  for (int i = 0; i < 10; ++i) m.vert[i].P() = vcg::Point3d(i, i * i, 0);
  st = RunNvv(m, WithK(3)).st;
  EXPECT_FALSE(st.ok);
  EXPECT_NE(std::string::npos, st.message.find("triangles"));
  // All faces collinear: zero area everywhere.
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
  for (int i = 0; i < 3; ++i) m.vert[i].P() = vcg::Point3d(i, 0, 0);
  st = RunNvv(m, WithK(3)).st;
  EXPECT_FALSE(st.ok);
  EXPECT_NE(std::string::npos, st.message.find("zero area"));
}

TEST(Degenerate, RefusesAbsurdParameters) {
  TMesh m;
  nvv_shapes::PaperPlane(m);
  for (double k : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), 1e9}) {
    const NvvRun r = RunNvv(m, WithK(k));
    EXPECT_FALSE(r.st.ok) << k;
    EXPECT_TRUE(r.res.empty());
  }
  for (double phi : {0.0, 90.0, 180.0, -5.0}) {
    nvv::Params p;
    p.creaseAngleDeg = phi;
    EXPECT_FALSE(RunNvv(m, p).st.ok) << phi;
  }
}

TEST(Degenerate, DefectsGiveDefinedResults) {
  TMesh m;
  nvv_shapes::PaperSphere(m, 31);
  const std::size_t n = m.vert.size();
  // An unreferenced vertex, a NaN vertex (its faces are dropped), a zero-area face,
  // a non-manifold fin (third face on an edge), and a deleted vertex.
  auto extra = vcg::tri::Allocator<TMesh>::AddVertices(m, 3);
  extra->P() = vcg::Point3d(0, 0, 100);
  (extra + 1)->P() = vcg::Point3d(0, 0, std::numeric_limits<double>::quiet_NaN());
  (extra + 2)->P() = vcg::Point3d(3, 3, 50);
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[n + 1], &m.vert[0], &m.vert[1]);
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[40], &m.vert[40 + 1], &m.vert[40 + 1]);  // repeats a vertex
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[100], &m.vert[101], &m.vert[n + 2]);   // fin
  // Zero area: three collinear vertices of one row.
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[200], &m.vert[201], &m.vert[202]);
  m.vert[500].SetD();
  const NvvRun r = RunNvv(m, WithK(3.0));
  ASSERT_TRUE(r.st.ok) << r.st.message;
  ASSERT_EQ(m.vert.size(), r.res.size());
  EXPECT_EQ(VertexClass::Invalid, r.res[n].cls);      // unreferenced
  EXPECT_EQ(VertexClass::Invalid, r.res[n + 1].cls);  // NaN
  EXPECT_EQ(VertexClass::Invalid, r.res[500].cls);    // deleted
  EXPECT_EQ(1u, r.sum.nonFiniteVertices);
  EXPECT_GE(r.sum.droppedFaces, 2u);
  EXPECT_FALSE(r.sum.warnings.empty());
  for (const auto& v : r.res) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_TRUE(std::isfinite(v.normal[j]));
      EXPECT_TRUE(std::isfinite(v.t1[j]));
      EXPECT_TRUE(std::isfinite(v.lambda[j]));
    }
    EXPECT_TRUE(std::isfinite(v.k1) && std::isfinite(v.k2) && std::isfinite(v.cuspAngle));
    if (v.cls == VertexClass::Invalid) {
      EXPECT_EQ(0, v.flags);
    }
  }
}

TEST(Degenerate, SingleTriangleAndTinyComponents) {
  TMesh m;
  vcg::tri::Allocator<TMesh>::AddVertices(m, 3);
  m.vert[0].P() = vcg::Point3d(0, 0, 0);
  m.vert[1].P() = vcg::Point3d(1, 0, 0);
  m.vert[2].P() = vcg::Point3d(0, 1, 0);
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
  const NvvRun r = RunNvv(m, WithK(3.0));
  ASSERT_TRUE(r.st.ok);
  for (const auto& v : r.res) {
    EXPECT_EQ(VertexClass::Surface, v.cls);
    EXPECT_NEAR(1.0, std::abs(v.normal[2]), 1e-6);
  }
}
