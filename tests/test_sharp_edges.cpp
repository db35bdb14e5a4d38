// Creases of clean tessellations from their sharp edges (core/sharp_edges.h): exact where the
// mesh is clean, whatever the votes say; where it is noisy they only add the creases the votes miss.
#include <gtest/gtest.h>

#include "test_support.h"

using namespace nvv_test;

namespace {

nvv::Params SharpEdges(double angleDeg) {
  nvv::Params p = WithK(3);
  p.sharpEdgeAngleDeg = angleDeg;
  return p;
}

std::vector<char> Features(const NvvRun& r) {
  std::vector<char> f(r.res.size(), 0);
  for (std::size_t i = 0; i < r.res.size(); ++i) f[i] = nvv::IsFeature(r.res[i]);
  return f;
}

// A tent: two planes meeting along the y axis at a normal-angle alpha, on a grid of n x n cells.
void Tent(TMesh& m, double alphaDeg, int n) {
  m.Clear();
  const double slope = std::tan(alphaDeg / 2 * 3.14159265358979 / 180);
  auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = i - n / 2.0, y = j;
      v[j * (n + 1) + i].P() = vcg::Point3d(x, y, -slope * std::abs(x));
    }
  GridFaces(m, n + 1, n);
}

// How many faces of the cube [-h, h]^3 the point p lies on: 2 on an edge, 3 at a corner.
int CubeFacesAt(const vcg::Point3d& p, double h) {
  int faces = 0;
  for (int j = 0; j < 3; ++j) faces += std::abs(std::abs(p[j]) - h) < 1e-9;
  return faces;
}

}  // namespace

// A 25 deg crease is below the default crease angle of 60 deg, so the votes do not call it one;
// but its edges are sharp on a clean mesh: at the default sharp-edge angle (10 deg) every vertex
// on the ridge and no other is a crease; at 30 deg none is, the votes' few included.
TEST(SharpEdges, ACleanShallowCreaseIsFoundExactlyOnItsRidge) {
  TMesh m;
  Tent(m, 25, 20);
  const NvvRun votes = RunNvv(m, SharpEdges(0));
  const NvvRun sharp = RunNvv(m, WithK(3));
  ASSERT_TRUE(sharp.st.ok) << sharp.st.message;
  EXPECT_TRUE(sharp.sum.sharpEdges);
  EXPECT_FALSE(votes.sum.sharpEdges);
  int onRidge = 0, ridgeFound = 0, offRidgeFound = 0, votesFound = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const bool ridge = m.vert[i].P()[0] == 0;
    onRidge += ridge;
    ridgeFound += ridge && nvv::IsFeature(sharp.res[i]);
    offRidgeFound += !ridge && nvv::IsFeature(sharp.res[i]);
    votesFound += nvv::IsFeature(votes.res[i]);
  }
  EXPECT_EQ(onRidge, ridgeFound);
  EXPECT_EQ(0, offRidgeFound);
  EXPECT_GE(sharp.sum.sharpEdgeChanged, std::size_t(onRidge - votesFound));
  EXPECT_LT(votesFound, onRidge / 2);  // what the sharp edges add
  // Interior ridge vertices are creases along y with the crease's normal-angle as cusp angle.
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const auto& p = m.vert[i].P();
    if (p[0] != 0 || p[1] < 1 || p[1] > 19) continue;
    ASSERT_EQ(nvv::VertexClass::Crease, sharp.res[i].cls) << "y " << p[1];
    EXPECT_GT(std::abs(sharp.res[i].creaseTangent[1]), 0.999);
    EXPECT_NEAR(25.0, sharp.res[i].cuspAngle * 180 / 3.14159265358979, 0.01);
  }
  const NvvRun none = RunNvv(m, SharpEdges(30));
  for (std::size_t i = 0; i < m.vert.size(); ++i) EXPECT_FALSE(nvv::IsFeature(none.res[i]));
  // Every third face flipped (an STL file's orientation) change nothing: each edge's angle is
  // taken between the faces as they would be oriented alike.
  TMesh flipped;
  Tent(flipped, 25, 20);
  for (std::size_t f = 0; f < flipped.face.size(); f += 3) std::swap(flipped.face[f].V(0), flipped.face[f].V(1));
  EXPECT_EQ(Features(sharp), Features(RunNvv(flipped, WithK(3))));
}

// A cylinder of 16 facets turns by 22.5 deg at every facet line: above the sharp-edge angle, but
// not isolated, so no facet line is a crease; its rims (90 deg between side and caps) are, with
// every rim vertex found and nothing else.
TEST(SharpEdges, TessellatedCurvatureIsNotACreaseButTheRimsAre) {
  TMesh m;
  CappedCylinder(m, 5.0, 10.0, 16, 20);
  const NvvRun r = RunNvv(m, SharpEdges(nvv::Params().sharpEdgeAngleDeg));
  ASSERT_TRUE(r.st.ok) << r.st.message;
  int rim = 0, rimFound = 0, others = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const auto& p = m.vert[i].P();
    const bool onRim = (p[2] == 0 || p[2] == 10) && std::abs(std::hypot(p[0], p[1]) - 5) < 1e-9;
    rim += onRim;
    rimFound += onRim && nvv::IsFeature(r.res[i]);
    others += !onRim && nvv::IsFeature(r.res[i]);
  }
  EXPECT_EQ(32, rim);
  EXPECT_EQ(rim, rimFound);
  EXPECT_EQ(0, others);
}

// A shallow chamfer one face wide: the profile turns 20 deg, runs one edge, turns 30 deg. Neither
// line is isolated (each has the other beside it), yet both are creases, every vertex on them and
// nothing else, since the surface beyond each is flat. Two strips of a fillet (15, 30, 15 deg) are
// a curved face: no line of them is a crease, though each has a flat sheet on one side.
TEST(SharpEdges, ACleanChamferIsTwoCreasesTwoStripsOfAFilletNone) {
  std::vector<double> chamfer(13, 0.0), fillet(13, 0.0);
  chamfer[6] = 20, chamfer[7] = 30;
  fillet[5] = 15, fillet[6] = 30, fillet[7] = 15;
  TMesh m;
  Profile(m, chamfer, 12);
  const NvvRun r = RunNvv(m, WithK(3));
  ASSERT_TRUE(r.st.ok) << r.st.message;
  EXPECT_TRUE(r.sum.sharpEdges);
  int wrong = 0, onLines = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const int column = int(i % 13);
    const bool line = column == 6 || column == 7;
    onLines += line && nvv::IsFeature(r.res[i]);
    wrong += line != nvv::IsFeature(r.res[i]);
  }
  EXPECT_EQ(26, onLines);
  EXPECT_EQ(0, wrong);
  Profile(m, fillet, 12);
  const NvvRun f = RunNvv(m, WithK(3));
  ASSERT_TRUE(f.sum.sharpEdges);
  int found = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) found += nvv::IsFeature(f.res[i]);
  EXPECT_EQ(0, found);
}

// Under noise a chamfer's lines must also continue along another sharp edge (a noise edge beside
// a crease stands alone). A 60 + 60 deg chamfer one face wide, 10 % noise (the votes see one crease
// between the lines; the sharp edges count isolated edges only), 4 seeds: the sharp edges add
// vertices of both lines (154 of 216 without the chamfer rule, 182 with it) and nothing else: off
// the lines the same 4 vertices as without the rule (lone noise edges that pass the isolation test
// by themselves: one beside a line, two in a flat sheet, one next to the border).
TEST(SharpEdges, ANoisyChamferGetsBothLinesFromItsSharpEdges) {
  std::vector<double> chamfer(13, 0.0);
  chamfer[6] = 60, chamfer[7] = 60;
  int lineVertices = 0, withSharp = 0, byVotes = 0, besideLines = 0, offLines = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    TMesh m;
    Profile(m, chamfer, 30);
    NoiseAlongNormals(m, 0.1 * nvv_shapes::MeanEdge(m), seed);
    const NvvRun on = RunNvv(m, WithK(3)), votes = RunNvv(m, SharpEdges(0));
    ASSERT_TRUE(on.sum.sharpEdgesAdded);
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      const int column = int(i % 13), row = int(i / 13);
      if (row < 2 || row > 28) continue;  // the border's vertices have one side only
      if (column == 6 || column == 7)
        ++lineVertices, withSharp += nvv::IsFeature(on.res[i]), byVotes += nvv::IsFeature(votes.res[i]);
      else
        (column == 5 || column == 8 ? besideLines : offLines) += nvv::IsFeature(on.res[i]) && !nvv::IsFeature(votes.res[i]);
    }
  }
  std::printf("[60 + 60 deg chamfer, 10 %% noise, 4 seeds] line vertices found %d of %d (votes alone %d); added one edge "
              "beside the lines %d, farther %d\n", withSharp, lineVertices, byVotes, besideLines, offLines);
  EXPECT_GE(withSharp, byVotes + lineVertices / 5);
  EXPECT_LE(besideLines + offLines, 4);
}

// A cube's twelve edges on a clean grid: every edge vertex is a feature, the eight corners are
// corners, nothing else is marked.
TEST(SharpEdges, ACleanCubeIsExactlyItsEdgesAndCorners) {
  TMesh m;
  nvv_shapes::Cube(m, 5.0, 21);
  const NvvRun r = RunNvv(m, SharpEdges(nvv::Params().sharpEdgeAngleDeg));
  int wrong = 0, corners = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const int extreme = CubeFacesAt(m.vert[i].cP(), 5);
    wrong += (extreme >= 2) != nvv::IsFeature(r.res[i]);
    if (extreme == 3) corners += r.res[i].cls == nvv::VertexClass::Corner;
  }
  EXPECT_EQ(0, wrong);
  EXPECT_EQ(8, corners);
  // The sharp edges overwrite every class the thinning of the votes' band would set, so on a clean
  // mesh it is skipped: the same bits with it on and off, nothing reported thinned, also at a low
  // crease angle whose band is several rows wide.
  for (double crease : {40.0, 20.0}) {
    nvv::Params thin = SharpEdges(nvv::Params().sharpEdgeAngleDeg), wide = thin;
    thin.creaseAngleDeg = wide.creaseAngleDeg = crease;
    wide.thinCreases = false;
    const NvvRun t = RunNvv(m, thin);
    EXPECT_EQ(0u, t.sum.thinned) << "crease angle " << crease;
    EXPECT_TRUE(SameBits(t.res, RunNvv(m, wide).res)) << "crease angle " << crease;
  }
}

// Under noise the sharp edges only add: every vertex the votes call a feature stays one, and every
// vertex they add lies on the cube's edges (5, 10 and 20 % noise); on a clean mesh the result does not
// depend on the thread count.
TEST(SharpEdges, OnNoisyMeshesTheyOnlyAddAndOnlyOnTheEdges) {
  for (double noise : {0.05, 0.1, 0.2}) {
    TMesh m;
    const double h = 5.0;
    nvv_shapes::Cube(m, h, 21);
    std::vector<int> onEdge(m.vert.size());  // before the noise
    for (std::size_t i = 0; i < m.vert.size(); ++i) onEdge[i] = CubeFacesAt(m.vert[i].cP(), h);
    NoiseAlongNormals(m, noise * nvv_shapes::MeanEdge(m), 3);
    const NvvRun on = RunNvv(m, SharpEdges(nvv::Params().sharpEdgeAngleDeg)), votes = RunNvv(m, SharpEdges(0));
    EXPECT_FALSE(on.sum.sharpEdges) << "noise " << noise;
    EXPECT_TRUE(on.sum.sharpEdgesAdded) << "noise " << noise;
    int lost = 0, added = 0, addedOffEdges = 0;
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      const bool v = nvv::IsFeature(votes.res[i]), s = nvv::IsFeature(on.res[i]);
      lost += v && !s;
      added += s && !v;
      addedOffEdges += s && !v && onEdge[i] < 2;
    }
    std::printf("[cube, %g %% noise] %d vertices added by the sharp edges, %d off the edges\n", 100 * noise, added,
                addedOffEdges);
    EXPECT_EQ(0, lost) << "noise " << noise;
    EXPECT_EQ(0, addedOffEdges) << "noise " << noise;
  }
  TMesh m;
  CappedCylinder(m, 5.0, 10.0, 16, 20);
  nvv::Params one = SharpEdges(nvv::Params().sharpEdgeAngleDeg), two = SharpEdges(nvv::Params().sharpEdgeAngleDeg);
  one.threads = 1;
  two.threads = 2;
  EXPECT_TRUE(SameBits(RunNvv(m, one).res, RunNvv(m, two).res));
}

// Noisy and coarse: a box of 3 x 3 vertices a face (each face two by two cells) under 10 % noise, 4
// seeds. The ball spans whole faces, so the votes leave most of its edge vertices out (29 of 80); the
// sharp edges add more of them (48) and nothing else, on one and two threads alike.
TEST(SharpEdges, OnANoisyCoarseBoxTheyAddTheEdgesTheVotesMiss) {
  int edgeVertices = 0, byVotes = 0, withSharp = 0, offEdges = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    TMesh m;
    const double h = 5.0;
    nvv_shapes::Cube(m, h, 3);
    std::vector<int> onEdge(m.vert.size());  // before the noise
    for (std::size_t i = 0; i < m.vert.size(); ++i) onEdge[i] = CubeFacesAt(m.vert[i].cP(), h);
    NoiseAlongNormals(m, 0.1 * nvv_shapes::MeanEdge(m), seed);
    nvv::Params one = SharpEdges(nvv::Params().sharpEdgeAngleDeg), two = one;
    one.threads = 1;
    two.threads = 2;
    const NvvRun on = RunNvv(m, one), votes = RunNvv(m, SharpEdges(0));
    ASSERT_TRUE(on.sum.sharpEdgesAdded);
    EXPECT_TRUE(SameBits(on.res, RunNvv(m, two).res)) << "seed " << seed;
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
      if (onEdge[i] >= 2) ++edgeVertices, byVotes += nvv::IsFeature(votes.res[i]), withSharp += nvv::IsFeature(on.res[i]);
      else offEdges += nvv::IsFeature(on.res[i]) && !nvv::IsFeature(votes.res[i]);
    }
  }
  std::printf("[coarse box, 10 %% noise, 4 seeds] edge vertices found %d of %d (votes alone %d), %d added off the edges\n",
              withSharp, edgeVertices, byVotes, offEdges);
  EXPECT_GE(withSharp, byVotes + edgeVertices / 5);  // 29 -> 48 of 80
  EXPECT_EQ(0, offEdges);
}

// A 45 deg roof under 5 % noise: below a 60 deg crease angle the votes leave its ridge to the
// surface; the mesh is lightly noisy, so its sharp edges add the ridge and every vertex the votes
// call a feature stays one. The same bits on one and two threads.
TEST(SharpEdges, LightlyNoisyMeshesGetTheCreasesTheVotesMiss) {
  TMesh m;
  nvv_shapes::Roof(m, 45.0, 33, 16 * std::cos(nvv::DegToRad(22.5)), 32);
  std::vector<char> ridge(m.vert.size());
  for (std::size_t i = 0; i < m.vert.size(); ++i) ridge[i] = std::abs(m.vert[i].cP()[0]) < 1e-9;
  NoiseAlongNormals(m, 0.05 * nvv_shapes::MeanEdge(m), 5);
  nvv::Params one = SharpEdges(nvv::Params().sharpEdgeAngleDeg), votesOnly = SharpEdges(0);
  one.creaseAngleDeg = votesOnly.creaseAngleDeg = 85;
  nvv::Params two = one;
  one.threads = 1;
  two.threads = 2;
  const NvvRun on = RunNvv(m, one), votes = RunNvv(m, votesOnly);
  EXPECT_TRUE(on.sum.sharpEdgesAdded);
  EXPECT_TRUE(SameBits(on.res, RunNvv(m, two).res));
  auto feature = [](const nvv::VertexResult& r) { return r.cls == nvv::VertexClass::Crease || r.cls == nvv::VertexClass::Corner; };
  int ridgeFound = 0, ridgeByVotes = 0, ridgeCount = 0, votesKept = 0, votesFeatures = 0, offRidge = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    ridgeCount += ridge[i];
    if (ridge[i]) ridgeFound += feature(on.res[i]), ridgeByVotes += feature(votes.res[i]);
    else offRidge += feature(on.res[i]) && !feature(votes.res[i]);
    if (feature(votes.res[i])) ++votesFeatures, votesKept += feature(on.res[i]);
  }
  std::printf("[45 deg roof, 5 %% noise] ridge %d of %d (votes alone %d), %d added off the ridge\n", ridgeFound,
              ridgeCount, ridgeByVotes, offRidge);
  EXPECT_LT(ridgeByVotes, ridgeCount / 3);
  EXPECT_GE(ridgeFound, ridgeCount - 2);
  EXPECT_LE(offRidge, 2);
  EXPECT_EQ(votesFeatures, votesKept);
}

// Steps one edge wide under 10 % and 20 % noise, 4 seeds each: every 90 deg line has another one
// edge away, so none is isolated, and the ball spans several steps, so the votes miss most of them.
// Their faces tilt far less than the lines turn: the sharp edges keep the lines by their angle alone
// (line vertices found at 10 % 113 of 168, 76 with isolated edges only; at 20 % 15 and 5).
TEST(SharpEdges, UnderHeavyNoiseALineFarAboveTheNoiseNeedsNoIsolation) {
  for (const std::pair<double, int>& noiseAndFound : {std::make_pair(0.1, 100), std::make_pair(0.2, 12)}) {
    const double noise = noiseAndFound.first;
    const int atLeast = noiseAndFound.second;
    int lineVertices = 0, found = 0, byVotes = 0, offLines = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
      TMesh m;
      const std::vector<double> turns = {0, 90, -90, 90, -90, 90, -90, 0};
      const int cols = int(turns.size()), rows = 8;
      Profile(m, turns, rows);
      NoiseAlongNormals(m, noise * nvv_shapes::MeanEdge(m), seed);
      const NvvRun on = RunNvv(m, SharpEdges(nvv::Params().sharpEdgeAngleDeg)), votes = RunNvv(m, SharpEdges(0));
      ASSERT_FALSE(on.sum.sharpEdges);
      for (std::size_t i = 0; i < m.vert.size(); ++i) {
        const int col = int(i) % cols, row = int(i) / cols;
        if (row == 0 || row == rows) continue;  // the lines' ends, on the border
        if (turns[std::size_t(col)] != 0) {
          ++lineVertices;
          found += nvv::IsFeature(on.res[i]);
          byVotes += nvv::IsFeature(votes.res[i]);
        } else {
          offLines += nvv::IsFeature(on.res[i]) && !nvv::IsFeature(votes.res[i]);
        }
      }
    }
    std::printf("[steps, %g %% noise, 4 seeds] line vertices found %d of %d (votes alone %d), %d added off the lines\n",
                100 * noise, found, lineVertices, byVotes, offLines);
    EXPECT_GE(found, atLeast) << "noise " << noise;
    EXPECT_EQ(0, offLines) << "noise " << noise;
  }
}
