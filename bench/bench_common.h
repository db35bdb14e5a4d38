// Plain data shared by the accuracy benchmark's translation units: a triangle mesh as arrays,
// one estimator's per-vertex answer, and the CGAL peers (compiled apart from vcglib).
#ifndef NVV_BENCH_BENCH_COMMON_H
#define NVV_BENCH_BENCH_COMMON_H

#include <Eigen/Core>
#include <array>
#include <vector>

namespace nvv_bench {

struct PlainMesh {
  std::vector<Eigen::Vector3d> pos;
  std::vector<std::array<int, 3>> face;
};

// One estimator's answer at a vertex. Curvatures follow this project's convention after the
// harness calibrated the estimator's sign: k1 >= k2, outward sphere of radius R has +1/R.
struct Estimate {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  Eigen::Vector3d t1 = Eigen::Vector3d::Zero();  // direction of k1
  Eigen::Vector3d t2 = Eigen::Vector3d::Zero();  // direction of k2
  double k1 = 0, k2 = 0;
};

// CGAL 5.5 Monge_via_jet_fitting, degree 2 (d = d' = 2), at every vertex on the points
// nbhd[v] (v first). The normal is complied with orient[v]; curvatures are converted to this
// project's sign (CGAL's Monge coefficients are signed against the normal).
void CgalJet(const PlainMesh& m, const std::vector<std::vector<int>>& nbhd,
             const std::vector<Eigen::Vector3d>& orient, std::vector<Estimate>& out);

// CGAL::Polygon_mesh_processing::detect_sharp_edges(angle): 1 for vertices of sharp edges.
std::vector<char> CgalSharpVertices(const PlainMesh& m, double angleDeg);

// CGAL::Polygon_mesh_processing::sharp_edges_segmentation(angle): the sharp edges as vertex
// pairs (lower index first; border edges, which CGAL counts as sharp, left out) and the patch of each face of m (-1 for a face CGAL's halfedge
// structure refused: a non-manifold one). Returns the number of patches.
int CgalSharpEdgesSegmentation(const PlainMesh& m, double angleDeg, std::vector<std::array<int, 2>>& edges,
                               std::vector<int>& facePatch);

}  // namespace nvv_bench

#endif
