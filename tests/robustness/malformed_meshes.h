// A corpus of malformed and adversarial meshes and parameters, generated deterministically:
// the defects real scans and isosurfaces arrive with (holes, duplicate and unreferenced vertices,
// non-manifold edges and vertices, zero-area and needle triangles, flipped faces, tiny components,
// extreme and non-finite coordinates, huge valences) and parameters no one should type.
#ifndef NVV_TESTS_ROBUSTNESS_MALFORMED_MESHES_H
#define NVV_TESTS_ROBUSTNESS_MALFORMED_MESHES_H

#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "../test_mesh.h"
#include "filter/filter_options.h"
#include "sample_meshes/synthetic_shapes.h"

namespace nvv_robust {

using nvv_test::TMesh;
typedef vcg::tri::Allocator<TMesh> Alloc;

struct Case {
  std::string name;
  std::function<void(TMesh&)> make;
  nvv::FilterOptions options = nvv::DefaultOptions();
  bool mayRefuse = true;  // false: a defined result is required (the defect is one the core absorbs)
};

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

inline void Grid(TMesh& m, int n, unsigned seed = 1, double irregular = 0.0) {
  nvv_shapes::ParametricGrid(m, n, n, [n](double s, double t) {
    return vcg::Point3d(n * s, n * t, 0.3 * std::sin(3 * s) * std::cos(2 * t) * n);
  }, irregular, seed);
}
inline void Sphere(TMesh& m, int n, unsigned seed = 1) { nvv_shapes::UVSphere(m, 5.0, 2 * n, n, 0.3, seed); }

// Triangle soup: every face gets its own three vertices (unwelded STL).
inline void Unweld(TMesh& m) {
  TMesh soup;
  for (const auto& f : m.face) {
    auto vi = Alloc::AddVertices(soup, 3);
    for (int j = 0; j < 3; ++j) (vi + j)->P() = f.cP(j);
    Alloc::AddFace(soup, &*vi, &*(vi + 1), &*(vi + 2));
  }
  m.Clear();
  vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, soup);
}

inline std::vector<Case> MalformedCorpus() {
  std::vector<Case> c;
  auto add = [&](std::string name, std::function<void(TMesh&)> make, bool mayRefuse = true) {
    Case k;
    k.name = std::move(name);
    k.make = std::move(make);
    k.mayRefuse = mayRefuse;
    c.push_back(k);
  };
  add("empty", [](TMesh&) {});
  for (int n : {1, 2, 3, 10, 1000})
    add("point_cloud_" + std::to_string(n), [n](TMesh& m) {
      auto vi = Alloc::AddVertices(m, n);
      for (int i = 0; i < n; ++i) (vi + i)->P() = vcg::Point3d(i, i % 7, i % 3);
    });
  // Single triangles of every shape, including degenerate ones.
  const double tri[][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0},    {0, 0, 0, 1, 0, 0, 2, 0, 0},
                           {0, 0, 0, 0, 0, 0, 0, 0, 0},    {0, 0, 0, 1e-20, 0, 0, 0, 1e-20, 0},
                           {0, 0, 0, 1e20, 0, 0, 0, 1e20, 0}, {0, 0, 0, 1, 0, 0, 0.5, 1e-9, 0}};
  for (int t = 0; t < 6; ++t)
    add("one_triangle_" + std::to_string(t), [t, tri](TMesh& m) {  // tri by copy: the case runs after this scope ends
      auto vi = Alloc::AddVertices(m, 3);
      for (int j = 0; j < 3; ++j) (vi + j)->P() = vcg::Point3d(tri[t][3 * j], tri[t][3 * j + 1], tri[t][3 * j + 2]);
      Alloc::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
    });
  for (int n : {3, 10, 100})
    add("collinear_strip_" + std::to_string(n), [n](TMesh& m) {
      auto vi = Alloc::AddVertices(m, n);
      for (int i = 0; i < n; ++i) (vi + i)->P() = vcg::Point3d(i, 2 * i, 3 * i);
      for (int i = 0; i + 2 < n; ++i) Alloc::AddFace(m, &m.vert[i], &m.vert[i + 1], &m.vert[i + 2]);
    });
  for (unsigned seed = 1; seed <= 60; ++seed) {
    const int n = 4 + int(seed % 13);
    add("repeated_faces_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed);
      const std::size_t f = m.face.size();
      for (std::size_t i = 0; i < f; i += 1 + seed % 5)
        for (unsigned r = 0; r < 1 + seed % 4; ++r) Alloc::AddFace(m, m.face[i].V(0), m.face[i].V(1), m.face[i].V(2));
    }, false);
    add("zero_area_and_needles_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed, 0.5);
      std::mt19937 rng(seed);
      for (auto& v : m.vert)  // collapse some vertices onto a neighbour, squash others onto a line
        if (rng() % 4 == 0) v.P() = m.vert[rng() % m.vert.size()].P();
        else if (rng() % 5 == 0) v.P()[1] = std::floor(v.P()[1]);
    });
    add("duplicate_vertices_soup_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed);
      Unweld(m);
    }, false);
    add("unreferenced_vertices_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed);
      auto vi = Alloc::AddVertices(m, seed * 3);
      for (unsigned i = 0; i < seed * 3; ++i) (vi + i)->P() = vcg::Point3d(i, -1.0 * i, 7);
    }, false);
    add("non_manifold_edge_fan_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed);
      const int fins = 1 + int(seed % 20);
      auto* a = &m.vert[n + 1];
      auto* b = &m.vert[n + 2];
      for (int i = 0; i < fins; ++i) {
        auto vi = Alloc::AddVertices(m, 1);
        vi->P() = vcg::Point3d(n + 1.5, 1.0 + 0.1 * i, 1.0 + i);
        a = &m.vert[n + 1];  // AddVertices may reallocate
        b = &m.vert[n + 2];
        Alloc::AddFace(m, a, b, &*vi);
      }
    }, false);
    add("bow_tie_vertex_" + std::to_string(seed), [n, seed](TMesh& m) {
      TMesh other;
      Grid(m, n, seed);
      Grid(other, n, seed + 1);
      for (auto& v : other.vert) v.P() = vcg::Point3d(-v.P()[0], -v.P()[1], v.P()[2]);  // touches m at (0,0)
      vcg::tri::Append<TMesh, TMesh>::Mesh(m, other);
      vcg::tri::Clean<TMesh>::RemoveDuplicateVertex(m);
      vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
    }, false);
    add("flipped_faces_" + std::to_string(seed), [n, seed](TMesh& m) {
      Sphere(m, n, seed);
      std::mt19937 rng(seed);
      for (auto& f : m.face)
        if (rng() % (2 + seed % 6) == 0) std::swap(f.V(1), f.V(2));
    }, false);
    add("tiny_components_" + std::to_string(seed), [seed](TMesh& m) {
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> u(-100, 100);
      for (unsigned i = 0; i < 20 * seed; ++i) {
        auto vi = Alloc::AddVertices(m, 3);
        const vcg::Point3d o(u(rng), u(rng), u(rng));
        (vi)->P() = o;
        (vi + 1)->P() = o + vcg::Point3d(u(rng), u(rng), u(rng)) * 0.01;
        (vi + 2)->P() = o + vcg::Point3d(u(rng), u(rng), u(rng)) * 0.01;
        Alloc::AddFace(m, &*vi, &*(vi + 1), &*(vi + 2));
      }
    }, false);
    for (double scale : {1e-30, 1e-12, 1e12, 1e30})
      add("scaled_" + std::to_string(seed) + "_" + std::to_string(int(std::log10(scale))), [n, seed, scale](TMesh& m) {
        Sphere(m, n, seed);
        for (auto& v : m.vert) v.P() = v.P() * scale + vcg::Point3d(scale, 0, 0);
      });
    add("far_from_origin_" + std::to_string(seed), [n, seed](TMesh& m) {
      Sphere(m, n, seed);
      for (auto& v : m.vert) v.P() += vcg::Point3d(1e15, -1e15, 3e14);
    });
    for (double bad : {kNaN, kInf, -kInf})
      add("non_finite_" + std::to_string(seed) + "_" + std::to_string(bad), [n, seed, bad](TMesh& m) {
        Sphere(m, n, seed);
        std::mt19937 rng(seed);
        for (auto& v : m.vert)
          if (rng() % 7 == 0) v.P()[rng() % 3] = bad;
      });
    add("all_non_finite_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed);
      for (auto& v : m.vert) v.P() = vcg::Point3d(kNaN, kNaN, kNaN);
    });
    add("boundary_only_strip_" + std::to_string(seed), [seed](TMesh& m) {
      nvv_shapes::ParametricGrid(m, 3 + int(seed), 2, [](double s, double t) { return vcg::Point3d(20 * s, t, 0.1 * s * s); });
    }, false);
    add("deleted_elements_" + std::to_string(seed), [n, seed](TMesh& m) {
      Sphere(m, n, seed);
      std::mt19937 rng(seed);
      for (auto& f : m.face)
        if (rng() % 5 == 0) Alloc::DeleteFace(m, f);
      for (auto& v : m.vert)
        if (rng() % 9 == 0) Alloc::DeleteVertex(m, v);  // faces may still point at it
    });
    add("repeated_vertex_in_face_" + std::to_string(seed), [n, seed](TMesh& m) {
      Grid(m, n, seed);
      std::mt19937 rng(seed);
      for (auto& f : m.face)
        if (rng() % 3 == 0) f.V(rng() % 3) = f.V((rng() % 2) + 1 == 1 ? 0 : 1);
    });
  }
  // A 100,000-valence fan: one vertex shared by a closed ring of 100,000 thin triangles.
  add("fan_100000", [](TMesh& m) {
    const int n = 100000;
    auto vi = Alloc::AddVertices(m, n + 1);
    vi->P() = vcg::Point3d(0, 0, 1);
    for (int i = 0; i < n; ++i) {
      const double a = 2 * nvv_shapes::kPi * i / n;
      (vi + 1 + i)->P() = vcg::Point3d(std::cos(a), std::sin(a), 0);
    }
    for (int i = 0; i < n; ++i) Alloc::AddFace(m, &m.vert[0], &m.vert[1 + i], &m.vert[1 + (i + 1) % n]);
  }, false);
  return c;
}

// Parameters no one should type, each on an ordinary mesh: every one must be refused.
inline std::vector<std::pair<std::string, double>> AbsurdParameters() {
  std::vector<std::pair<std::string, double>> p;
  for (double k : {0.0, -1.0, kNaN, kInf, -kInf, 1e9, 1e-9, 51.0}) p.push_back({"neighbourhood_k", k});
  for (double a : {0.0, 89.5, 90.0, 180.0, 360.0, -5.0, kNaN, kInf}) {
    p.push_back({"crease_angle", a});
    p.push_back({"corner_angle", a});
  }
  for (double r : {-1.0, kNaN, kInf, -kInf, 1e31}) p.push_back({"absolute_radius", r});
  for (const auto& spec : nvv::FilterParameterTable())  // enums: below, past the end, between, NaN
    if (spec.type == nvv::ParamType::Enum)
      for (double e : {-1.0, double(spec.choices.size()), 0.5, 1e9, kNaN}) p.push_back({spec.name, e});
  for (double c : {-4.0, 3.5, 1e12, kNaN}) p.push_back({"max_neighbourhood", c});
  for (double q : {-1.0, 50.0, 100.0, kNaN}) p.push_back({"color_clamp_percentile", q});
  return p;
}

}  // namespace nvv_robust

#endif
