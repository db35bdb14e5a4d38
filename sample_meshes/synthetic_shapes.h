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
#include <vcg/complex/algorithms/create/marching_cubes.h>
#include <vcg/complex/algorithms/create/mc_trivial_walker.h>

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

// The paper's Fig. 10: a torus extracted by marching cubes from the implicit
// (sqrt(x^2+y^2) - a)^2 + z^2 - b^2 on an n^3 grid (irregular, isosurface-like triangles).
template <class MeshType>
void MarchingCubesTorus(MeshType& m, double a, double b, int n) {
  typedef vcg::SimpleVolume<vcg::SimpleVoxel<float>> Volume;
  typedef vcg::tri::TrivialWalker<MeshType, Volume> Walker;
  typedef vcg::tri::MarchingCubes<MeshType, Walker> MC;
  m.Clear();
  const double e = a + b + 2.0;
  Volume vol;
  vol.Init(vcg::Point3i(n, n, n), vcg::Box3f(vcg::Point3f(-e, -e, -e), vcg::Point3f(e, e, e)));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double x = -e + 2 * e * i / (n - 1), y = -e + 2 * e * j / (n - 1), z = -e + 2 * e * k / (n - 1);
        const double r = std::sqrt(x * x + y * y) - a;
        vol.Val(i, j, k) = float(r * r + z * z - b * b);
      }
  Walker walker;
  MC mc(m, walker);
  walker.template BuildMesh<MC>(m, vol, mc, 0.0f);
  // Grid coordinates back to world coordinates.
  for (auto& v : m.vert) {
    if (v.IsD()) continue;
    for (int c = 0; c < 3; ++c) v.P()[c] = typename MeshType::ScalarType(-e + 2 * e * v.P()[c] / (n - 1));
  }
}

// A CAD-like part: a profile in (x, z) extruded along y over [-len/2, len/2], with capped ends.
// Profile, counter-clockwise: bottom (-10,0)-(10,0), right side up to (10,6), a chamfer to
// (7,10), a circular roof arc (centre (0.3,0.35), radius ~11.75) down to (-10,6), left side.
// Normal-angles of the creases along y: 90 (both bottom edges), 36.9 (side/chamfer),
// 18.4 (chamfer/roof, shallow), 28.7 (roof/left side); the roof is a cylinder (kappa = 1/11.75).
// The caps meet every side at 90 deg; the profile's corners on the caps are 3-sheet corners.
// h is the target edge length.
template <class MeshType>
void CadPart(MeshType& m, double len = 24, double h = 0.5) {
  typedef vcg::Point2d P2;
  std::vector<P2> ring;  // closed profile polyline, a vertex on every crease
  auto segment = [&](P2 a, P2 b) {
    const int n = std::max(1, int(std::lround((b - a).Norm() / h)));
    for (int i = 0; i < n; ++i) ring.push_back(a + (b - a) * (double(i) / n));
  };
  segment(P2(-10, 0), P2(10, 0));
  segment(P2(10, 0), P2(10, 6));
  segment(P2(10, 6), P2(7, 10));
  {
    const P2 c(0.3, 0.35), A(7, 10), B(-10, 6);
    const double R = (A - c).Norm(), a0 = std::atan2(A[1] - c[1], A[0] - c[0]), a1 = std::atan2(B[1] - c[1], B[0] - c[0]);
    const int n = std::max(1, int(std::lround(R * (a1 - a0) / h)));
    for (int i = 0; i < n; ++i) {
      const double t = a0 + (a1 - a0) * i / n;
      ring.push_back(i == 0 ? A : c + P2(std::cos(t), std::sin(t)) * R);
    }
  }
  segment(P2(-10, 6), P2(-10, 0));
  const int nr = int(ring.size()), ny = std::max(2, int(std::lround(len / h)) + 1);
  m.Clear();
  MeshType part;
  ParametricGrid(part, nr, ny, [&](double s, double t) {
    const P2 q = ring[std::min(nr - 1, int(std::lround(s * nr)) % nr)];
    return vcg::Point3d(q[0], len * (0.5 - t), q[1]);  // y decreasing: outward sides
  }, 0.0, 1, true, false);
  vcg::tri::Append<MeshType, MeshType>::Mesh(m, part);
  // Caps: rings shrinking towards the centroid with proportionally fewer points (so no needle
  // triangles), consecutive rings zipped by their angular parameter.
  P2 c(0, 0);
  for (const auto& q : ring) c += q;
  c /= double(nr);
  std::vector<double> param(nr + 1, 0.0);  // arc-length parameter of the outer ring in [0, 1]
  for (int i = 0; i < nr; ++i) param[i + 1] = param[i] + (ring[(i + 1) % nr] - ring[i]).Norm();
  for (double& p : param) p /= param[nr];
  auto outerAt = [&](double u) {
    int i = int(std::upper_bound(param.begin(), param.end(), u) - param.begin()) - 1;
    i = std::max(0, std::min(nr - 1, i));
    const double f = (u - param[i]) / std::max(1e-12, param[i + 1] - param[i]);
    return ring[i] + (ring[(i + 1) % nr] - ring[i]) * f;
  };
  const double maxRadius = 11.0;
  const int rings = std::max(2, int(std::lround(maxRadius / h)));
  for (int side = -1; side <= 1; side += 2) {
    part.Clear();
    const typename MeshType::ScalarType y = typename MeshType::ScalarType(side * len * 0.5);
    std::vector<std::vector<typename MeshType::VertexPointer>> rv(rings);
    std::vector<std::vector<double>> ru(rings);
    for (int r = 0; r < rings; ++r) {
      const double f = 1.0 - double(r) / rings;
      const int n = r == 0 ? nr : std::max(6, int(std::lround(nr * f)));
      auto vi = vcg::tri::Allocator<MeshType>::AddVertices(part, n);
      for (int i = 0; i < n; ++i) {
        const double u = r == 0 ? param[i] : double(i) / n;
        const P2 q = r == 0 ? ring[i] : c + (outerAt(u) - c) * f;
        (vi + i)->P() = typename MeshType::CoordType(q[0], y, q[1]);
        ru[r].push_back(u);
      }
      // AddVertices may reallocate: take the pointers after the last allocation below.
    }
    auto centre = vcg::tri::Allocator<MeshType>::AddVertices(part, 1);
    centre->P() = typename MeshType::CoordType(c[0], y, c[1]);
    int base = 0;
    for (int r = 0; r < rings; ++r) {
      for (std::size_t i = 0; i < ru[r].size(); ++i) rv[r].push_back(&part.vert[base + i]);
      base += int(ru[r].size());
    }
    auto* mid = &part.vert[base];
    auto addTri = [&](typename MeshType::VertexPointer a, typename MeshType::VertexPointer b, typename MeshType::VertexPointer d) {
      if (side > 0) vcg::tri::Allocator<MeshType>::AddFace(part, a, d, b);  // +y cap faces +y
      else vcg::tri::Allocator<MeshType>::AddFace(part, a, b, d);
    };
    for (int r = 0; r + 1 < rings; ++r) {  // zip ring r (outer) with ring r+1 (inner)
      const int no = int(ru[r].size()), ni = int(ru[r + 1].size());
      int i = 0, j = 0;
      while (i < no || j < ni) {
        const double uo = i + 1 <= no ? (i + 1 < no ? ru[r][i + 1] : 1.0) : 2.0;
        const double ui = j + 1 <= ni ? (j + 1 < ni ? ru[r + 1][j + 1] : 1.0) : 2.0;
        if (uo <= ui) { addTri(rv[r][i % no], rv[r][(i + 1) % no], rv[r + 1][j % ni]); ++i; }
        else { addTri(rv[r][i % no], rv[r + 1][(j + 1) % ni], rv[r + 1][j % ni]); ++j; }
      }
    }
    const int nl = int(ru[rings - 1].size());
    for (int i = 0; i < nl; ++i) addTri(rv[rings - 1][i], rv[rings - 1][(i + 1) % nl], mid);
    vcg::tri::Append<MeshType, MeshType>::Mesh(m, part);
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
