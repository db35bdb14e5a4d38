// Helpers shared by the tests: running the core on a test mesh, vcglib's one-ring estimators
// on the same mesh, and error statistics.
#ifndef NVV_TESTS_TEST_SUPPORT_H
#define NVV_TESTS_TEST_SUPPORT_H

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <cstring>

#include "test_mesh.h"  // vcg/complex/complex.h first, as vcglib requires

#include <vcg/complex/algorithms/update/curvature.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include "core/normal_vector_voting.h"
#include "sample_meshes/synthetic_shapes.h"

namespace nvv_test {

// The paper's sphere cap (R = 31 mm), jittered triangulation, 5 % noise along z.
inline void NoisySphere(TMesh& m) {
  nvv_shapes::PaperSphere(m, 31, 0.5, 4);
  nvv_shapes::AddNoise(m, 0.05 * nvv_shapes::MeanEdge(m), 3, nvv_shapes::AlongZ);
}

// vcglib's angle-weighted vertex normals (what MeshLab computes by default).
inline std::vector<Eigen::Vector3d> AngleWeightedNormals(const TMesh& src) {
  TMesh m;
  vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh&>(src));  // vcglib takes a non-const source
  vcg::tri::UpdateNormal<TMesh>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<TMesh>::NormalizePerVertex(m);
  std::vector<Eigen::Vector3d> n(m.vert.size());
  for (std::size_t i = 0; i < m.vert.size(); ++i) n[i] = Eigen::Vector3d(m.vert[i].cN()[0], m.vert[i].cN()[1], m.vert[i].cN()[2]);
  return n;
}

// Gaussian noise of standard deviation sigma along the clean mesh's angle-weighted normals
// (the true normal on smooth parts and faces, the bisector on creases).
inline void NoiseAlongNormals(TMesh& m, double sigma, unsigned seed) {
  if (!(sigma > 0)) return;
  const std::vector<Eigen::Vector3d> n = AngleWeightedNormals(m);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const Eigen::Vector3d d = n[i] * g(rng);
    m.vert[i].P() += vcg::Point3d(d.x(), d.y(), d.z());
  }
}

inline Eigen::Vector3d E(const vcg::Point3d& p) { return Eigen::Vector3d(p[0], p[1], p[2]); }
inline Eigen::Vector3d E(const float* p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

struct NvvRun {
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  nvv::Status st;
};
inline NvvRun RunNvv(const TMesh& m, const nvv::Params& p) {
  NvvRun r;
  r.st = vcg::tri::NormalVectorVoting<TMesh>::Compute(m, p, r.res, r.sum);
  return r;
}
// True when two result arrays hold the same bits in every field (field by field: the record's
// padding bytes are not part of its value).
inline bool SameBits(const std::vector<nvv::VertexResult>& a, const std::vector<nvv::VertexResult>& b) {
  auto same = [](const void* x, const void* y, std::size_t n) { return std::memcmp(x, y, n) == 0; };
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const nvv::VertexResult &r = a[i], &s = b[i];
    if (r.cls != s.cls || r.flags != s.flags || !same(r.lambda, s.lambda, sizeof r.lambda) ||
        !same(r.normal, s.normal, sizeof r.normal) || !same(&r.k1, &s.k1, sizeof r.k1) ||
        !same(&r.k2, &s.k2, sizeof r.k2) || !same(r.t1, s.t1, sizeof r.t1) || !same(r.t2, s.t2, sizeof r.t2) ||
        !same(r.creaseTangent, s.creaseTangent, sizeof r.creaseTangent) ||
        !same(&r.creaseCurvature, &s.creaseCurvature, sizeof r.creaseCurvature) ||
        !same(&r.cuspAngle, &s.cuspAngle, sizeof r.cuspAngle))
      return false;
  }
  return true;
}

inline nvv::Params WithK(double k, nvv::CurvatureFit fit = nvv::CurvatureFit::SheetQuadric) {
  nvv::Params p;
  p.k = k;
  p.fit = fit;
  return p;
}

// vcglib's angle-weighted one-ring normals (what MeshLab computes by default).
inline void OneRingNormals(TMesh& m) {
  vcg::tri::UpdateNormal<TMesh>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<TMesh>::NormalizePerVertex(m);
}
// vcglib's Taubin one-ring principal directions (MeshLab's "Taubin approximation").
inline void OneRingTaubin(TMesh& m) {
  vcg::tri::UpdateTopology<TMesh>::VertexFace(m);
  vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
  vcg::tri::UpdateCurvature<TMesh>::PrincipalDirections(m);
}

struct Stats {
  double median = 0, p90 = 0, mean = 0, max = 0;
  std::size_t n = 0;
};
inline Stats StatsOf(std::vector<double> v) {
  Stats s;
  s.n = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.median = v[v.size() / 2];
  s.p90 = v[std::min(v.size() - 1, std::size_t(0.9 * v.size()))];
  for (double x : v) s.mean += x;
  s.mean /= v.size();
  s.max = v.back();
  return s;
}
inline double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double c = std::abs(a.normalized().dot(b.normalized()));
  return nvv::RadToDeg(std::acos(std::min(1.0, c)));
}
// Interior of the paper's 32x32 grids: |x|, |y| <= limit (away from the boundary).
inline bool Interior(const vcg::Point3d& p, double limit) {
  return std::abs(p[0]) <= limit && std::abs(p[1]) <= limit;
}

// Closed cylinder of radius R and height h: side grid nu x nv, caps as fans of rings.
inline void CappedCylinder(TMesh& m, double R, double h, int nu, int nv) {
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

// The faces of a grid of vertices stored row by row, `cols` to a row, over `rows` rows of cells:
// each cell cut into two triangles along the same diagonal.
inline void GridFaces(TMesh& m, int cols, int rows) {
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i + 1 < cols; ++i) {
      const int a = j * cols + i, b = a + 1, c = a + cols + 1, d = a + cols;
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]);
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[c], &m.vert[d]);
    }
}

// A profile in the xz plane extruded along y over n cells: columns one unit of arc apart, the
// profile turning by turnDeg[i] at column i (0 elsewhere), each cell cut into two triangles.
inline void Profile(TMesh& m, const std::vector<double>& turnDeg, int n) {
  m.Clear();
  const int cols = int(turnDeg.size());
  std::vector<vcg::Point3d> at(std::size_t(cols), vcg::Point3d(0, 0, 0));
  double heading = 0;
  for (int i = 1; i < cols; ++i) {
    heading += turnDeg[std::size_t(i - 1)] * 3.14159265358979 / 180;
    at[std::size_t(i)] = at[std::size_t(i - 1)] + vcg::Point3d(std::cos(heading), 0, std::sin(heading));
  }
  auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, std::size_t(cols * (n + 1)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i < cols; ++i) v[j * cols + i].P() = at[std::size_t(i)] + vcg::Point3d(0, j, 0);
  GridFaces(m, cols, n);
}

}  // namespace nvv_test

#endif
