// MeshLab's estimators for the accuracy benchmark: the vcglib functions that MeshLab 2020.09's
// "Compute curvature principal directions" filter calls (meshfilter.cpp, FP_COMPUTE_PRINC_CURV_DIR:
// Taubin, PCA with radius bbox diagonal / 20, Normal Cycles, Quadric Fitting), its angle-weighted
// vertex normals, and "Select Crease Edges" (FaceEdgeSelSignedCrease on dihedral angles).
#ifndef NVV_BENCH_PEERS_VCG_H
#define NVV_BENCH_PEERS_VCG_H

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "test_mesh.h"  // vcg/complex/complex.h first, as vcglib requires

#include <vcg/complex/algorithms/update/curvature.h>
#include <vcg/complex/algorithms/update/curvature_fitting.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include "bench_common.h"
#include "test_support.h"

namespace nvv_bench {

typedef nvv_test::TMesh TMesh;

enum class VcgMethod { Taubin, PCA, NormalCycle, QuadricFitting };

// One of MeshLab's principal-direction methods on a copy of m. pcaRadius <= 0 takes MeshLab's
// own (bbox diagonal / 20). sign = +1 or -1 maps vcglib's curvature sign onto this project's.
inline void VcgCurvature(const TMesh& src, VcgMethod method, double pcaRadius, double sign,
                         std::vector<Estimate>& out) {
  TMesh m;
  vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh&>(src));  // vcglib takes a non-const source
  vcg::tri::UpdateBounding<TMesh>::Box(m);
  vcg::tri::UpdateTopology<TMesh>::VertexFace(m);
  vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
  vcg::tri::UpdateNormal<TMesh>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<TMesh>::NormalizePerVertex(m);
  switch (method) {
    case VcgMethod::Taubin: vcg::tri::UpdateCurvature<TMesh>::PrincipalDirections(m); break;
    case VcgMethod::PCA:
      vcg::tri::UpdateCurvature<TMesh>::PrincipalDirectionsPCA(
          m, pcaRadius > 0 ? pcaRadius : m.bbox.Diag() / 20.0, true);
      break;
    case VcgMethod::NormalCycle: vcg::tri::UpdateCurvature<TMesh>::PrincipalDirectionsNormalCycle(m); break;
    case VcgMethod::QuadricFitting: vcg::tri::UpdateCurvatureFitting<TMesh>::computeCurvature(m); break;
  }
  out.assign(m.vert.size(), Estimate());
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const auto& v = m.vert[i];
    Estimate& e = out[i];
    e.n = Eigen::Vector3d(v.cN()[0], v.cN()[1], v.cN()[2]).normalized();
    double a = sign * v.cK1(), b = sign * v.cK2();
    Eigen::Vector3d da(v.cPD1()[0], v.cPD1()[1], v.cPD1()[2]), db(v.cPD2()[0], v.cPD2()[1], v.cPD2()[2]);
    if (!std::isfinite(a) || !std::isfinite(b)) a = b = 0;
    if (a < b) { std::swap(a, b); std::swap(da, db); }
    e.k1 = a;
    e.k2 = b;
    e.t1 = da.normalized();
    e.t2 = db.normalized();
  }
}

// The noise model and the normals it follows are the tests' (tests/test_support.h).
using nvv_test::AngleWeightedNormals;
using nvv_test::NoiseAlongNormals;

// MeshLab's "Select Crease Edges" with both thresholds at +-angleDeg: the selected edges as vertex
// pairs, each once per face that selects it.
inline std::vector<std::array<int, 2>> DihedralCreaseEdges(const TMesh& src, double angleDeg) {
  TMesh m;
  vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh&>(src));  // vcglib takes a non-const source
  vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
  vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
  const double a = angleDeg * M_PI / 180.0;
  vcg::tri::UpdateFlags<TMesh>::FaceEdgeSelSignedCrease(m, -a, a);
  std::vector<std::array<int, 2>> edges;
  for (auto& f : m.face)
    for (int z = 0; z < 3; ++z)
      if (f.IsFaceEdgeS(z)) edges.push_back({{int(vcg::tri::Index(m, f.V0(z))), int(vcg::tri::Index(m, f.V1(z)))}});
  return edges;
}

// The same test's vertices: 1 for vertices of selected edges.
inline std::vector<char> DihedralCreaseVertices(const TMesh& src, double angleDeg) {
  std::vector<char> out(src.vert.size(), 0);
  for (const auto& e : DihedralCreaseEdges(src, angleDeg)) out[e[0]] = out[e[1]] = 1;
  return out;
}

}  // namespace nvv_bench

#endif
