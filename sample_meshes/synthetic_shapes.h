// Synthetic surfaces with known geometry, as vcglib meshes: the paper's 32x32 grids
// (plane, sphere cap, cylinder; 1 mm spacing), closed spheres, cylinders, tori and saddles,
// roofs (two planes meeting at a chosen normal-angle) and a cube. Used by the sample-mesh
// generator, the tests and the benchmarks, so every one of them measures the same shapes.
//
// Noise: Gaussian, standard deviation = fraction * l_ave (the paper's "variance" read as a
// standard deviation), along z for the paper's grids and along the true normal elsewhere.
#ifndef NVV_SAMPLE_MESHES_SYNTHETIC_SHAPES_H
#define NVV_SAMPLE_MESHES_SYNTHETIC_SHAPES_H

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/append.h>

namespace nvv_shapes {

constexpr double kPi = 3.14159265358979323846;

// A (nu x nv) vertex grid over parameters (s, t) in [0,1]^2 mapped by `f`, two triangles per
// cell. irregular > 0 jitters the parameters by that fraction of a cell and flips diagonals
// at random; wrapU closes the grid in s (cylinders, tori); wrapV in t (tori).
template <class MeshType>
void ParametricGrid(MeshType& m, int nu, int nv, const std::function<vcg::Point3d(double, double)>& f,
                    double irregular = 0.0, unsigned seed = 1, bool wrapU = false, bool wrapV = false) {
  m.Clear();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jit(-0.5, 0.5);
  const int cu = wrapU ? nu : nu - 1, cv = wrapV ? nv : nv - 1;
  auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, nu * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      double s = double(i) / cu, t = double(j) / cv;
      const bool interiorU = wrapU || (i > 0 && i < nu - 1), interiorV = wrapV || (j > 0 && j < nv - 1);
      if (irregular > 0 && interiorU) s += irregular * jit(rng) / cu;
      if (irregular > 0 && interiorV) t += irregular * jit(rng) / cv;
      const vcg::Point3d p = f(s, t);
      (vi + (j * nu + i))->P() = typename MeshType::CoordType(p[0], p[1], p[2]);
    }
  std::bernoulli_distribution flip(0.5);
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) {
      const int i1 = (i + 1) % nu, j1 = (j + 1) % nv;
      auto* a = &m.vert[j * nu + i];
      auto* b = &m.vert[j * nu + i1];
      auto* c = &m.vert[j1 * nu + i1];
      auto* d = &m.vert[j1 * nu + i];
      if (irregular > 0 && flip(rng)) {
        vcg::tri::Allocator<MeshType>::AddFace(m, a, b, d);
        vcg::tri::Allocator<MeshType>::AddFace(m, b, c, d);
      } else {
        vcg::tri::Allocator<MeshType>::AddFace(m, a, b, c);
        vcg::tri::Allocator<MeshType>::AddFace(m, a, c, d);
      }
    }
}

// The paper's 32x32 grids (1,024 vertices, 1,922 triangles, 1 mm spacing) centred at the origin.
template <class MeshType>
void PaperPlane(MeshType& m, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, 32, 32, [](double s, double t) { return vcg::Point3d(31 * s - 15.5, 31 * t - 15.5, 0); },
                 irregular, seed);
}
// Sphere of radius R: z = sqrt(R^2 - x^2 - y^2) over the 32x32 grid; centre (0, 0, 0), outward = up.
template <class MeshType>
void PaperSphere(MeshType& m, double R = 31, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, 32, 32, [R](double s, double t) {
    const double x = 31 * s - 15.5, y = 31 * t - 15.5;
    return vcg::Point3d(x, y, std::sqrt(R * R - x * x - y * y));
  }, irregular, seed);
}
// Cylinder of radius R with its axis along y: z = sqrt(R^2 - x^2); outward = up.
template <class MeshType>
void PaperCylinder(MeshType& m, double R = 31, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, 32, 32, [R](double s, double t) {
    const double x = 31 * s - 15.5, y = 31 * t - 15.5;
    return vcg::Point3d(x, y, std::sqrt(R * R - x * x));
  }, irregular, seed);
}
// Saddle z = (x^2 - y^2) / (2 a) over the paper's grid: at the origin kappa = +-1/a.
template <class MeshType>
void Saddle(MeshType& m, double a = 31, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, 32, 32, [a](double s, double t) {
    const double x = 31 * s - 15.5, y = 31 * t - 15.5;
    return vcg::Point3d(x, y, (x * x - y * y) / (2 * a));
  }, irregular, seed);
}
// Sphere as a UV grid with two small holes at the poles, outward normals.
template <class MeshType>
void UVSphere(MeshType& m, double R, int nu, int nv, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, nu, nv, [R](double s, double t) {
    const double th = 2 * kPi * s, ph = kPi * (0.02 + 0.96 * t);
    return vcg::Point3d(R * std::sin(ph) * std::cos(th), R * std::sin(ph) * std::sin(th), -R * std::cos(ph));
  }, irregular, seed, true, false);
}
// Open cylinder around the z axis, height h, outward normals.
template <class MeshType>
void Cylinder(MeshType& m, double R, double h, int nu, int nv, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, nu, nv, [R, h](double s, double t) {
    const double th = 2 * kPi * s;
    return vcg::Point3d(R * std::cos(th), R * std::sin(th), h * (t - 0.5));
  }, irregular, seed, true, false);
}
// Torus around z: major radius a, minor radius b, outward normals.
// Principal curvatures at minor angle phi: 1/b (around the tube) and cos(phi)/(a + b cos(phi)).
template <class MeshType>
void Torus(MeshType& m, double a, double b, int nu, int nv, double irregular = 0, unsigned seed = 1) {
  ParametricGrid(m, nu, nv, [a, b](double s, double t) {
    const double th = 2 * kPi * s, ph = 2 * kPi * t;
    const double r = a + b * std::cos(ph);
    return vcg::Point3d(r * std::cos(th), r * std::sin(th), b * std::sin(ph));
  }, irregular, seed, true, true);
}
// Roof: two planes meeting along the y axis, their normals alpha degrees apart (alpha = 0: flat).
// Width 2 * half in x, length `len` in y; n x n grid with a vertex row on the ridge (n odd).
template <class MeshType>
void Roof(MeshType& m, double alphaDeg, int n = 33, double half = 16, double len = 32,
          double irregular = 0, unsigned seed = 1) {
  const double slope = std::tan(alphaDeg * kPi / 360.0);
  ParametricGrid(m, n, n, [=](double s, double t) {
    const double x = half * (2 * s - 1);
    return vcg::Point3d(x, len * (t - 0.5), -slope * std::abs(x));
  }, irregular, seed);
}

// Axis-aligned cube [-h, h]^3 with n x n vertices per face, outward normals, shared edges welded.
template <class MeshType>
void Cube(MeshType& m, double h, int n) {
  m.Clear();
  MeshType side;
  for (int axis = 0; axis < 3; ++axis)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      ParametricGrid(side, n, n, [=](double s, double t) {
        double a = h * (2 * s - 1), b = h * (2 * t - 1);
        if (sgn < 0) std::swap(a, b);  // keep the faces outward
        vcg::Point3d p;
        p[axis] = sgn * h;
        p[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = b;
        return p;
      });
      vcg::tri::Append<MeshType, MeshType>::Mesh(m, side);
    }
  vcg::tri::Clean<MeshType>::RemoveDuplicateVertex(m);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
}

// Gaussian noise of standard deviation sigma along `dir(p)` at every vertex.
template <class MeshType>
void AddNoise(MeshType& m, double sigma, unsigned seed,
              const std::function<vcg::Point3d(const vcg::Point3d&)>& dir) {
  if (!(sigma > 0)) return;
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  for (auto& v : m.vert) {
    if (v.IsD()) continue;
    const vcg::Point3d p(v.P()[0], v.P()[1], v.P()[2]);
    const vcg::Point3d q = p + dir(p) * gauss(rng);
    v.P() = typename MeshType::CoordType(q[0], q[1], q[2]);
  }
}
inline vcg::Point3d AlongZ(const vcg::Point3d&) { return vcg::Point3d(0, 0, 1); }

// Mean edge length over the faces' edges (each interior edge counted twice, as the core does).
template <class MeshType>
double MeanEdge(const MeshType& m) {
  double sum = 0;
  int cnt = 0;
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    for (int j = 0; j < 3; ++j) {
      sum += vcg::Distance(f.cP(j), f.cP((j + 1) % 3));
      ++cnt;
    }
  }
  return cnt ? sum / cnt : 0.0;
}

}  // namespace nvv_shapes

#endif
