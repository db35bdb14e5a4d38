// The noise estimate (noise_estimate.h) against the noise put on the mesh, and automatic k.
// Its scale was calibrated on the noisy planes; the other shapes were not looked at.
#include <cstdio>

#include <gtest/gtest.h>

#include "test_support.h"

#include "core/noise_estimate.h"

namespace {

using nvv_test::TMesh;

double Estimate(const TMesh& m) {
  nvv::SurfaceGraph g;
  nvv::BuildSurfaceGraph(m, g, 1);
  const nvv::NoiseEstimate e = nvv::EstimateNoise(g, 0);
  std::printf("  two-rings %6.2f %%, dihedrals %6.2f %%\n", 100 * e.fromTwoRings, 100 * e.fromDihedrals);
  return e.sigmaOverEdge;
}

// Noise sigma * l_ave along the clean mesh's normals; the estimate, in units of l_ave.
double EstimateAt(TMesh& m, double sigma, unsigned seed) {
  nvv_test::NoiseAlongNormals(m, sigma * nvv_shapes::MeanEdge(m), seed);
  return Estimate(m);
}

struct Shape {
  const char* name;
  void (*build)(TMesh&);
};

void PlaneRegular(TMesh& m) { nvv_shapes::ParametricGrid(m, 80, 80, [](double s, double t) { return vcg::Point3d(79 * s, 79 * t, 0); }); }
void PlaneIrregular(TMesh& m) { nvv_shapes::ParametricGrid(m, 80, 80, [](double s, double t) { return vcg::Point3d(79 * s, 79 * t, 0); }, 0.5, 7); }
void Sphere(TMesh& m) { nvv_shapes::UVSphere(m, 20, 120, 60, 0.3, 3); }
void Torus(TMesh& m) { nvv_shapes::Torus(m, 24, 8, 150, 50, 0.3, 5); }
void Cube(TMesh& m) { nvv_shapes::Cube(m, 8, 25); }
void Cad(TMesh& m) { nvv_shapes::CadPart(m); }

const Shape kCalibration[] = {{"plane", PlaneRegular}, {"irregular plane", PlaneIrregular}};
const Shape kHeldOut[] = {{"sphere", Sphere}, {"torus", Torus}, {"cube", Cube}, {"CAD part", Cad}};
const double kNoise[] = {0.01, 0.02, 0.05, 0.1, 0.2};

// Each shape of `set` at each noise level: the estimate within `tolerance` of the noise, relatively.
template <std::size_t N>
void ExpectTheirNoise(const Shape (&set)[N], unsigned seed, double tolerance) {
  for (const Shape& s : set)
    for (double n : kNoise) {
      TMesh m;
      s.build(m);
      const double e = EstimateAt(m, n, seed);
      std::printf("%-16s noise %5.1f %%: estimate %6.2f %%\n", s.name, 100 * n, 100 * e);
      EXPECT_NEAR(e / n, 1.0, tolerance) << s.name << " at " << 100 * n << " %";
    }
}

TEST(NoiseEstimate, NoisyPlanesGiveTheirNoise) { ExpectTheirNoise(kCalibration, 11, 0.1); }

TEST(NoiseEstimate, CurvedAndCreasedShapesGiveTheirNoise) { ExpectTheirNoise(kHeldOut, 13, 0.15); }

TEST(NoiseEstimate, CleanMeshesAreNearlyNoiseFree) {
  for (const Shape* set : {kCalibration, kHeldOut})
    for (int i = 0; i < (set == kCalibration ? 2 : 4); ++i) {
      TMesh m;
      set[i].build(m);
      const double e = Estimate(m);
      std::printf("%-16s clean: estimate %6.3f %%\n", set[i].name, 100 * e);
      EXPECT_LT(e, 0.005) << set[i].name;
    }
}

// Coarse tessellations as CAD exporters write them: every two-ring spans a crease or several strips
// of a curved face, so the two-rings' residuals read high; their flat edges give 0.
TEST(NoiseEstimate, CoarseTessellationsAreNoiseFree) {
  TMesh cube, cylinder;
  nvv_shapes::Cube(cube, 8, 3);
  nvv_shapes::Cylinder(cylinder, 5, 10, 12, 3);
  for (const TMesh* m : {&cube, &cylinder}) {
    nvv::SurfaceGraph g;
    nvv::BuildSurfaceGraph(*m, g, 1);
    const nvv::NoiseEstimate e = nvv::EstimateNoise(g, 0);
    std::printf("coarse %s: two-rings %.2f %%, dihedrals %.2f %%\n", m == &cube ? "cube" : "cylinder",
                100 * e.fromTwoRings, 100 * e.fromDihedrals);
    EXPECT_GT(e.fromTwoRings, 0.02);
    EXPECT_EQ(0.0, e.sigmaOverEdge);
  }
}

// A plane cut into slivers 20 times longer than wide, as CAD exporters cut planar faces: the same
// noise tilts them far more than equilateral faces, and the noise angle the sharp edges read scales
// each edge's angle by its faces' heights, so that the slivers read as the regular plane does under
// the same noise (relative to l_ave), not as a far noisier mesh.
TEST(NoiseEstimate, SliversReadAsTheNoiseTheyCarry) {
  for (double n : {0.01, 0.05}) {
    TMesh slivers, regular;
    nvv_shapes::ParametricGrid(slivers, 161, 9, [](double s, double t) { return vcg::Point3d(80 * s, 80 * t, 0); });
    PlaneRegular(regular);
    double angle[2];
    for (TMesh* m : {&slivers, &regular}) {
      nvv_test::NoiseAlongNormals(*m, n * nvv_shapes::MeanEdge(*m), 11);
      nvv::SurfaceGraph g;
      nvv::BuildSurfaceGraph(*m, g, 1);
      angle[m == &regular] = nvv::EstimateNoise(g, 0).noiseAngle;
    }
    std::printf("noise %g %%: noise angle %.3f deg on slivers, %.3f deg on the regular plane\n", 100 * n,
                nvv::RadToDeg(angle[0]), nvv::RadToDeg(angle[1]));
    EXPECT_NEAR(angle[0] / angle[1], 1.0, 0.25) << "noise " << n;
  }
}

TEST(NoiseEstimate, AutomaticKGrowsWithTheNoise) {
  EXPECT_EQ(nvv::AutoK(0), 3.0);
  EXPECT_EQ(nvv::AutoK(0.02), 3.0);
  EXPECT_DOUBLE_EQ(nvv::AutoK(0.06), 4.0);
  EXPECT_EQ(nvv::AutoK(0.1), 5.0);
  EXPECT_EQ(nvv::AutoK(0.5), 5.0);
}

}  // namespace
