// Piecewise-smooth shapes with known creases for the accuracy benchmark: roofs (two planes,
// normals alpha apart, sheets sampled at 1 mm), a cube and a capped cylinder (90 deg rims).
// Per vertex: whether it lies on a crease, the true normal, curvatures and direction of the
// smaller curvature where defined, and the distance to the nearest crease along the surface.
#ifndef NVV_BENCH_CREASE_SHAPES_H
#define NVV_BENCH_CREASE_SHAPES_H

#include <cmath>
#include <string>
#include <vector>

#include "peers_vcg.h"
#include "sample_meshes/synthetic_shapes.h"

namespace nvv_bench {

struct VertexTruth {
  bool feature = false;  // on a crease line (or a corner)
  bool use = true;       // far enough from the mesh boundary to be scored
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), t2 = Eigen::Vector3d::Zero();
  double k1 = 0, k2 = 0;
  bool hasDir = false;
  double dist = 0;       // to the nearest crease, along the surface
};

struct CreaseShape {
  std::string name;
  double alphaDeg;  // normal-angle of its creases
  int kind;         // 0 roof, 1 cube, 2 capped cylinder
};

const double kCapR = 8, kCapH = 16, kCubeH = 8;

inline void BuildCreaseShape(const CreaseShape& s, TMesh& m) {
  if (s.kind == 0) {
    // Sheets 16 mm wide at 1 mm spacing whatever the angle: half-width in x is 16 cos(alpha/2).
    nvv_shapes::Roof(m, s.alphaDeg, 33, 16 * std::cos(s.alphaDeg * M_PI / 360), 32);
  } else if (s.kind == 1) {
    nvv_shapes::Cube(m, kCubeH, 17);
  } else {
    // Rows 0..8 bottom cap (centre to rim), 8..24 side, 24..32 top cap (rim to centre).
    nvv_shapes::ParametricGrid(m, 50, 33, [](double u, double t) {
      const int j = int(std::lround(t * 32));
      const double th = 2 * M_PI * u;
      double rho, z;
      if (j <= 8) { rho = kCapR * j / 8; z = -kCapH / 2; }
      else if (j <= 24) { rho = kCapR; z = -kCapH / 2 + kCapH * (j - 8) / 16; }
      else { rho = kCapR * (32 - j) / 8; z = kCapH / 2; }
      return vcg::Point3d(rho * std::cos(th), rho * std::sin(th), z);
    }, 0, 1, true, false);
    vcg::tri::Clean<TMesh>::RemoveDuplicateVertex(m);
    vcg::tri::Clean<TMesh>::RemoveDegenerateFace(m);
    vcg::tri::Clean<TMesh>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
  }
}

inline VertexTruth CreaseTruthAt(const CreaseShape& s, const vcg::Point3d& q) {
  const Eigen::Vector3d p(q[0], q[1], q[2]);
  VertexTruth t;
  const double eps = 1e-6;
  if (s.kind == 0) {
    const double a = s.alphaDeg * M_PI / 360;
    t.feature = std::abs(p.x()) < eps;
    t.n = Eigen::Vector3d((p.x() > 0 ? 1 : -1) * std::sin(a), 0, std::cos(a));
    t.dist = std::abs(p.x()) / std::cos(a);
    t.use = std::abs(p.y()) <= 12 + eps && t.dist <= 12 + eps;
  } else if (s.kind == 1) {
    int onFace = 0, axis = 0;
    for (int i = 0; i < 3; ++i)
      if (std::abs(std::abs(p[i]) - kCubeH) < eps) { ++onFace; axis = i; }
    t.feature = onFace >= 2;
    t.n = Eigen::Vector3d::Zero();
    t.n[axis] = p[axis] > 0 ? 1 : -1;
    t.dist = std::min(kCubeH - std::abs(p[(axis + 1) % 3]), kCubeH - std::abs(p[(axis + 2) % 3]));
  } else {
    const double rho = std::hypot(p.x(), p.y());
    if (std::abs(p.z()) < kCapH / 2 - eps) {
      t.n = Eigen::Vector3d(p.x(), p.y(), 0) / rho;
      t.k1 = 1 / kCapR;
      t.t2 = Eigen::Vector3d::UnitZ();
      t.hasDir = true;
      t.dist = kCapH / 2 - std::abs(p.z());
    } else if (rho < kCapR - eps) {
      t.n = Eigen::Vector3d(0, 0, p.z() > 0 ? 1 : -1);
      t.dist = kCapR - rho;
    } else {
      t.feature = true;
    }
  }
  return t;
}

// The crease curves through q, one bit each: the roof's ridge; the cube's twelve edges; the
// capped cylinder's bottom and top rims. A mesh edge lies on a crease when its two ends share
// a bit (two vertices on different cube edges next to a corner share none).
inline unsigned CreaseCurvesAt(const CreaseShape& s, const vcg::Point3d& q) {
  const double eps = 1e-6;
  if (s.kind == 0) return std::abs(q[0]) < eps ? 1u : 0u;
  if (s.kind == 1) {
    unsigned bits = 0;
    const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int k = 0; k < 3; ++k) {
      const int i = pairs[k][0], j = pairs[k][1];
      if (std::abs(std::abs(q[i]) - kCubeH) < eps && std::abs(std::abs(q[j]) - kCubeH) < eps)
        bits |= 1u << (4 * k + 2 * (q[i] > 0) + (q[j] > 0));
    }
    return bits;
  }
  const double rho = std::hypot(q[0], q[1]);
  if (std::abs(std::abs(q[2]) - kCapH / 2) < eps && std::abs(rho - kCapR) < 1e-4) return q[2] > 0 ? 2u : 1u;
  return 0;
}

struct F1 {
  double precision = 0, recall = 0, f1 = 0;
};
inline F1 ScoreFeatures(const std::vector<char>& found, const std::vector<char>& truth, const std::vector<char>& use) {
  double tp = 0, fp = 0, fn = 0;
  for (std::size_t i = 0; i < found.size(); ++i) {
    if (!use[i]) continue;
    if (found[i] && truth[i]) ++tp;
    else if (found[i]) ++fp;
    else if (truth[i]) ++fn;
  }
  F1 r;
  r.precision = tp + fp > 0 ? tp / (tp + fp) : 1;
  r.recall = tp + fn > 0 ? tp / (tp + fn) : 1;
  r.f1 = r.precision + r.recall > 0 ? 2 * r.precision * r.recall / (r.precision + r.recall) : 0;
  return r;
}

}  // namespace nvv_bench

#endif
