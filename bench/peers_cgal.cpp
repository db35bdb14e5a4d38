// CGAL's estimators for the accuracy benchmark (see bench_common.h).
#include "bench_common.h"

#include <algorithm>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

namespace nvv_bench {

namespace {
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Monge_via_jet_fitting<Kernel> Fitting;
typedef CGAL::Surface_mesh<Point> SurfaceMesh;

Eigen::Vector3d E(const Vector& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }
}  // namespace

void CgalJet(const PlainMesh& m, const std::vector<std::vector<int>>& nbhd,
             const std::vector<Eigen::Vector3d>& orient, std::vector<Estimate>& out) {
  out.assign(m.pos.size(), Estimate());
  std::vector<Point> pts;
  for (std::size_t v = 0; v < m.pos.size(); ++v) {
    if (nbhd[v].size() < 6) continue;  // a degree-2 jet has 6 coefficients
    pts.clear();
    for (int x : nbhd[v]) pts.push_back(Point(m.pos[x].x(), m.pos[x].y(), m.pos[x].z()));
    Fitting fit;
    Fitting::Monge_form mf = fit(pts.begin(), pts.end(), 2, 2);
    mf.comply_wrt_given_normal(Vector(orient[v].x(), orient[v].y(), orient[v].z()));
    Estimate& e = out[v];
    e.n = E(mf.normal_direction()).normalized();
    // Monge form: h = (k_max x^2 + k_min y^2) / 2 along the normal; this project's curvature
    // is positive where the surface bends away from the normal, so it is the negative.
    e.k1 = -mf.principal_curvatures(1);
    e.k2 = -mf.principal_curvatures(0);
    e.t1 = E(mf.minimal_principal_direction()).normalized();
    e.t2 = E(mf.maximal_principal_direction()).normalized();
  }
}

std::vector<char> CgalSharpVertices(const PlainMesh& m, double angleDeg) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> vi;
  for (const auto& p : m.pos) vi.push_back(sm.add_vertex(Point(p.x(), p.y(), p.z())));
  for (const auto& f : m.face) sm.add_face(vi[f[0]], vi[f[1]], vi[f[2]]);
  auto sharp = sm.add_property_map<SurfaceMesh::Edge_index, bool>("e:sharp", false).first;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(sm, angleDeg, sharp);
  std::vector<char> out(m.pos.size(), 0);
  for (auto e : sm.edges())
    if (sharp[e]) {
      out[sm.vertex(e, 0).idx()] = 1;
      out[sm.vertex(e, 1).idx()] = 1;
    }
  return out;
}

int CgalSharpEdgesSegmentation(const PlainMesh& m, double angleDeg, std::vector<std::array<int, 2>>& edges,
                               std::vector<int>& facePatch) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> vi;
  for (const auto& p : m.pos) vi.push_back(sm.add_vertex(Point(p.x(), p.y(), p.z())));
  std::vector<SurfaceMesh::Face_index> fi;
  for (const auto& f : m.face) fi.push_back(sm.add_face(vi[f[0]], vi[f[1]], vi[f[2]]));
  auto sharp = sm.add_property_map<SurfaceMesh::Edge_index, bool>("e:sharp", false).first;
  auto patch = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:patch", 0).first;
  const int count = int(CGAL::Polygon_mesh_processing::sharp_edges_segmentation(sm, angleDeg, sharp, patch));
  edges.clear();
  for (auto e : sm.edges())
    if (sharp[e] && !sm.is_border(e)) {  // CGAL counts border edges as sharp; no truth here does
      const int a = int(sm.vertex(e, 0).idx()), b = int(sm.vertex(e, 1).idx());
      edges.push_back({{std::min(a, b), std::max(a, b)}});
    }
  std::sort(edges.begin(), edges.end());
  facePatch.assign(m.face.size(), -1);
  for (std::size_t f = 0; f < fi.size(); ++f)
    if (fi[f] != SurfaceMesh::null_face()) facePatch[f] = int(patch[fi[f]]);
  return count;
}

}  // namespace nvv_bench
