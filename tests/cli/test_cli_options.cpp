// Every parameter of the table reaches the filter: for each option the tool's file equals the
// core run in-process with that option, differs from the defaults' file where the option has
// an effect, and the visible outputs (selection, quality, colour, curvature) mean what they say.
#include <functional>
#include <set>

#include "cli_test_support.h"
#include "core/noise_estimate.h"

using namespace nvv_cli_test;

namespace {

// The sample as an OFF file, written once for all tests of this file.
class CliOptions : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    Mesh m;
    SampleMesh(m);
    input_ = dir_->File("sample.off");
    ASSERT_EQ(0, vcg::tri::io::ExporterOFF<Mesh>::Save(m, input_.c_str()));
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  // Runs nvv with `args` on the sample and reads its file.
  static nvv::ResultPlyData Run(const std::vector<std::string>& args, CliResult* result = nullptr) {
    TempDir out;
    std::vector<std::string> all = args;
    all.push_back(input_);
    all.push_back(out.File("out.ply"));
    const CliResult r = RunCli(all, out);
    EXPECT_EQ(0, r.exitCode) << r.err;
    nvv::ResultPlyData data;
    std::string error;
    EXPECT_TRUE(nvv::ReadResultPly(out.File("out.ply"), data, error)) << error;
    if (result) *result = r;
    return data;
  }
  static std::vector<nvv::ResultPlyVertex> ReferenceRecords(const nvv::FilterOptions& o) {
    Reference ref;
    EXPECT_TRUE(RunReference(input_, o, ref)) << ref.st.message;
    return ref.records;
  }

  static TempDir* dir_;
  static std::string input_;
};
TempDir* CliOptions::dir_ = nullptr;
std::string CliOptions::input_;

struct OptionCase {
  const char* label;
  std::vector<std::string> args;       // the option under test (plus its baseline)
  std::vector<std::string> baseline;   // what it is compared against (empty: the defaults)
  std::function<void(nvv::FilterOptions&)> set;
  bool changesOutput;
};

std::vector<OptionCase> Cases() {
  using O = nvv::FilterOptions;
  return {
    {"neighbourhood_k", {"--neighbourhood_k", "5"}, {}, [](O& o) { o.core.k = 5; }, true},
    // The sample is clean: automatic k keeps 3 (AutomaticKFollowsTheNoise shows a noisy mesh).
    {"auto_k", {"--auto_k", "true"}, {}, [](O& o) { o.core.autoK = true; }, false},
    {"absolute_radius", {"--absolute_radius", "0.45"}, {}, [](O& o) { o.core.absoluteRadius = 0.45; }, true},
    // The sample is clean: its sharp edges give the classes, and the crease angle acts on the
    // quadric fit's samples only above 60 deg (tuning.h); the votes show both angles.
    {"crease_angle", {"--crease_angle", "75"}, {}, [](O& o) { o.core.creaseAngleDeg = 75; }, true},
    {"corner_angle", {"--sharp_edge_angle", "0", "--corner_angle", "85"}, {"--sharp_edge_angle", "0"},
     [](O& o) { o.core.sharpEdgeAngleDeg = 0; o.core.cornerAngleDeg = 85; }, true},
    {"sharp_edge_angle", {"--sharp_edge_angle", "0"}, {}, [](O& o) { o.core.sharpEdgeAngleDeg = 0; }, true},
    // The quadric fit already leaves out neighbours across a crease; the paper's Taubin votes
    // show whether the march stops there.
    {"stop_at_creases", {"--curvature_fit", "taubin", "--stop_at_creases", "false"}, {"--curvature_fit", "taubin"},
     [](O& o) { o.core.fit = nvv::CurvatureFit::PaperTaubin; o.core.stopAtCreases = false; }, true},
    {"curvature_fit_taubin", {"--curvature_fit", "taubin"}, {},
     [](O& o) { o.core.fit = nvv::CurvatureFit::PaperTaubin; }, true},
    {"curvature_fit_euler", {"--curvature_fit", "euler"}, {},
     [](O& o) { o.core.fit = nvv::CurvatureFit::EulerLeastSquares; }, true},
    // At 60 deg the CAD part's band is one vertex wide already; at 30 deg it is wide.
    // Thinning acts on the votes' band: the clean part's sharp edges, which need none, are off.
    {"thin_creases", {"--sharp_edge_angle", "0", "--crease_angle", "30", "--thin_creases", "false"},
     {"--sharp_edge_angle", "0", "--crease_angle", "30"},
     [](O& o) { o.core.sharpEdgeAngleDeg = 0; o.core.creaseAngleDeg = 30; o.core.thinCreases = false; }, true},
    {"fit_rounds", {"--fit_rounds", "1"}, {}, [](O& o) { o.core.fitRounds = 1; }, true},
    {"cubic_fit", {"--cubic_fit", "false"}, {}, [](O& o) { o.core.cubicFit = false; }, true},
    {"class_rule", {"--class_rule", "paper"}, {}, [](O& o) { o.core.classRule = nvv::ClassRule::PaperOrder; }, true},
    {"update_normals", {"--update_normals", "false"}, {}, [](O& o) { o.updateNormals = false; }, true},
    {"quality_gaussian", {"--quality", "gaussian"}, {}, [](O& o) { o.quality = nvv::QualityMode::GaussianCurvature; }, true},
    {"quality_shape_index", {"--quality", "shape_index"}, {}, [](O& o) { o.quality = nvv::QualityMode::ShapeIndex; }, true},
    {"quality_cusp_angle", {"--quality", "cusp_angle"}, {}, [](O& o) { o.quality = nvv::QualityMode::CuspAngle; }, true},
    {"quality_keep", {"--quality", "keep"}, {}, [](O& o) { o.quality = nvv::QualityMode::Keep; }, true},
    {"color_ramp", {"--color", "ramp"}, {}, [](O& o) { o.color = nvv::ColorMode::QualityRamp; }, true},
    {"color_keep", {"--color", "keep"}, {}, [](O& o) { o.color = nvv::ColorMode::Keep; }, true},
    {"color_clamp_percentile", {"--color", "ramp", "--color_clamp_percentile", "20"}, {"--color", "ramp"},
     [](O& o) { o.color = nvv::ColorMode::QualityRamp; o.clampPercentile = 20; }, true},
    {"selection", {"--selection", "corners"}, {}, [](O& o) { o.selection = nvv::SelectionMode::CornersOnly; }, true},
    {"max_neighbourhood", {"--max_neighbourhood", "16"}, {}, [](O& o) { o.core.maxNeighbourhood = 16; }, true},
    {"color_patches", {"--color", "patches"}, {}, [](O& o) { o.color = nvv::ColorMode::Patches; }, true},
    // Per face and per edge only: the vertices are those of the defaults (CreaseEdges... below).
    {"crease_edges", {"--crease_edges", "false"}, {}, [](O& o) { o.creaseEdges = false; }, false},
  };
}

void PrintTo(const OptionCase& c, std::ostream* os) { *os << c.label; }

class EveryOption : public CliOptions, public ::testing::WithParamInterface<OptionCase> {};

}  // namespace

TEST_P(EveryOption, ReachesTheFilter) {
  const OptionCase& c = GetParam();
  nvv::FilterOptions o = nvv::DefaultOptions();
  c.set(o);
  const nvv::ResultPlyData data = Run(c.args);
  EXPECT_TRUE(SameRecords(ReferenceRecords(o), data.vertices));
  const nvv::ResultPlyData base = Run(c.baseline);
  if (c.changesOutput) {
    EXPECT_FALSE(SameRecords(base.vertices, data.vertices)) << "the option had no effect";
  }
  // The header records the value the run used.
  bool recorded = false;
  const std::string expect = "nvv " + c.args[c.args.size() - 2] + " " + c.args.back();
  for (const auto& comment : data.comments) recorded = recorded || comment == expect;
  EXPECT_TRUE(recorded) << expect;
}

INSTANTIATE_TEST_SUITE_P(Cli, EveryOption, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<OptionCase>& i) { return std::string(i.param.label); });

TEST_F(CliOptions, EveryTableParameterIsCovered) {
  for (const auto& spec : nvv::FilterParameterTable()) {
    bool covered = false;
    for (const auto& c : Cases())
      for (const auto& a : c.args) covered = covered || a == std::string("--") + spec.name;
    EXPECT_TRUE(covered) << spec.name;
  }
}

TEST_F(CliOptions, SelectionSelectsTheClasses) {
  const std::vector<std::pair<const char*, std::function<bool(int)>>> modes = {
    {"none", [](int) { return false; }},
    {"creases", [](int c) { return c == 1 || c == 2; }},
    {"corners", [](int c) { return c == 2; }},
    {"surface", [](int c) { return c == 0; }},
  };
  for (const auto& mode : modes) {
    SCOPED_TRACE(mode.first);
    const nvv::ResultPlyData d = Run({"--selection", mode.first});
    std::size_t selected = 0;
    for (const auto& v : d.vertices) {
      EXPECT_EQ(mode.second(v.cls), v.selected == 1);
      selected += v.selected;
    }
    if (std::string(mode.first) != "none") {
      EXPECT_GT(selected, 0u);
    }
  }
}

// Vertices on crease lines: exactly the ends of the crease edges, also with crease_edges off.
TEST_F(CliOptions, SelectionOfLineVerticesIsTheEndsOfTheCreaseEdges) {
  const nvv::ResultPlyData d = Run({"--selection", "lines"});
  std::set<int> ends;
  for (const auto& e : d.edges) ends.insert(e.vertex[0]), ends.insert(e.vertex[1]);
  ASSERT_GT(ends.size(), 10u);
  for (std::size_t i = 0; i < d.vertices.size(); ++i) EXPECT_EQ(ends.count(int(i)) == 1, d.vertices[i].selected == 1) << i;
  const nvv::ResultPlyData off = Run({"--selection", "lines", "--crease_edges", "false"});
  ASSERT_EQ(d.vertices.size(), off.vertices.size());
  for (std::size_t i = 0; i < d.vertices.size(); ++i) EXPECT_EQ(d.vertices[i].selected, off.vertices[i].selected) << i;
}

TEST_F(CliOptions, QualityHoldsTheChosenValue) {
  const nvv::ResultPlyData cls = Run({"--quality", "class"});
  for (const auto& v : cls.vertices) EXPECT_EQ(float(v.cls), v.quality);
  const nvv::ResultPlyData k1 = Run({"--quality", "k1"});
  for (const auto& v : k1.vertices) EXPECT_EQ(v.k1, v.quality);
  const nvv::ResultPlyData k2 = Run({"--quality", "k2"});
  for (const auto& v : k2.vertices) EXPECT_EQ(v.k2, v.quality);
  const nvv::ResultPlyData mean = Run({});
  for (const auto& v : mean.vertices) EXPECT_NEAR(0.5 * (double(v.k1) + v.k2), v.quality, 1e-6 + 1e-6 * std::abs(v.k1));
  const nvv::ResultPlyData cusp = Run({"--quality", "cusp_angle"});
  std::size_t creases = 0;
  for (const auto& v : cusp.vertices) {
    EXPECT_NEAR(v.cuspAngleDeg, v.quality, 1e-3);
    creases += v.cls == 1 && v.quality > 45.0f;
  }
  EXPECT_GT(creases, 0u) << "the cube's and the roof's creases have cusp angles of 90 and 140 degrees";
}

TEST_F(CliOptions, ColourFollowsTheChosenMode) {
  const nvv::ResultPlyData classes = Run({});
  for (const auto& v : classes.vertices) {
    const vcg::Color4b c = nvv::ClassColor(nvv::VertexClass(v.cls));
    for (int j = 0; j < 4; ++j) EXPECT_EQ(c[j], v.color[j]);
  }
  const nvv::ResultPlyData keep = Run({"--color", "keep"});
  for (const auto& v : keep.vertices)
    for (int j = 0; j < 4; ++j) EXPECT_EQ(255, v.color[j]) << "an OFF without colours loads white";
  const nvv::ResultPlyData ramp = Run({"--color", "ramp", "--quality", "gaussian"});
  std::size_t notClassColour = 0;
  for (const auto& v : ramp.vertices) {
    const vcg::Color4b c = nvv::ClassColor(nvv::VertexClass(v.cls));
    notClassColour += c[0] != v.color[0] || c[1] != v.color[1] || c[2] != v.color[2];
  }
  EXPECT_GT(notClassColour, ramp.vertices.size() / 2);
}

// The crease network in the file is the one the run sequence finds in-process; off, the file
// has neither the faces' patches nor the edges.
TEST_F(CliOptions, CreaseEdgesWriteTheNetwork) {
  Reference ref;
  ASSERT_TRUE(RunReference(input_, nvv::DefaultOptions(), ref)) << ref.st.message;
  const nvv::ResultPlyData d = Run({});
  ASSERT_EQ(ref.crease.net.edges.size(), d.edges.size());
  for (std::size_t e = 0; e < d.edges.size(); ++e) {
    EXPECT_EQ(ref.crease.net.edges[e][0], d.edges[e].vertex[0]);
    EXPECT_EQ(ref.crease.net.edges[e][1], d.edges[e].vertex[1]);
    EXPECT_EQ(ref.crease.net.edgeCuspAngle[e], d.edges[e].cuspAngle);
    EXPECT_EQ(ref.crease.net.edgeLine[e], d.edges[e].line);
  }
  EXPECT_EQ(ref.crease.meshFacePatch, d.facePatch);
  EXPECT_GT(ref.crease.net.patchCount, 3) << "the cube's six faces, the torus, the roof's two sheets";
  const nvv::ResultPlyData off = Run({"--crease_edges", "false"});
  EXPECT_TRUE(off.edges.empty());
  EXPECT_TRUE(off.facePatch.empty());
  EXPECT_EQ(d.faces, off.faces);
}

TEST_F(CliOptions, TaubinFitGivesOtherCurvaturesThanTheQuadric) {
  const nvv::ResultPlyData quadric = Run({});
  const nvv::ResultPlyData taubin = Run({"--curvature_fit", "taubin"});
  ASSERT_EQ(quadric.vertices.size(), taubin.vertices.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < quadric.vertices.size(); ++i) {
    EXPECT_GE(taubin.vertices[i].k1, taubin.vertices[i].k2);
    differ += quadric.vertices[i].k1 != taubin.vertices[i].k1;
  }
  EXPECT_GT(differ, quadric.vertices.size() / 4);
}

TEST_F(CliOptions, NeighbourhoodCapIsReportedInFlagsAndSummary) {
  CliResult r;
  const nvv::ResultPlyData d = Run({"--max_neighbourhood", "16"}, &r);
  std::size_t capped = 0;
  for (const auto& v : d.vertices) capped += (v.flags & nvv::kNeighbourhoodCapped) != 0;
  EXPECT_GT(capped, 0u);
  EXPECT_NE(std::string::npos, r.out.find("warning: " + std::to_string(capped) + " vertices reached the neighbourhood cap"))
      << r.out;
}

TEST_F(CliOptions, AbsoluteRadiusIsTheRadiusUsed) {
  CliResult r;
  Run({"--absolute_radius", "0.45"}, &r);
  EXPECT_DOUBLE_EQ(0.45, PrintedRadius(r.out));
}

// On the noisy sphere cap (5 % of l_ave along z) automatic k estimates about that noise, says so,
// and runs at the k it chose (3.75 at 5 %), which is the in-process run's; the clean sample keeps 3.
TEST_F(CliOptions, AutomaticKFollowsTheNoise) {
  const std::string sphere = std::string(NVV_SOURCE_DIR) + "/sample_meshes/paper_sphere_noise5.ply";
  TempDir out;
  const CliResult r = RunCli({"--neighbourhood_k", "auto", sphere, out.File("auto.ply")}, out);
  ASSERT_EQ(0, r.exitCode) << r.err;
  const std::size_t at = r.out.find("; k = "), noise = r.out.find("noise along the normals ");
  ASSERT_NE(std::string::npos, at) << r.out;
  ASSERT_NE(std::string::npos, noise) << r.out;
  const double k = std::stod(r.out.substr(at + 6)), sigma = std::stod(r.out.substr(noise + 24)) / 100;
  std::printf("[auto k] noise %.4f of l_ave -> k = %g\n", sigma, k);
  EXPECT_NEAR(0.05, sigma, 0.0075);
  EXPECT_NE(std::string::npos, r.out.find("chosen from the noise")) << r.out;
  EXPECT_NEAR(nvv::AutoK(sigma), k, 0.02);  // both printed to 2-3 digits
  EXPECT_GT(k, 3.5);
  nvv::FilterOptions o = nvv::DefaultOptions();
  o.core.autoK = true;
  Reference ref;
  ASSERT_TRUE(RunReference(sphere, o, ref)) << ref.st.message;
  EXPECT_NEAR(ref.sum.k, k, 0.006);
  nvv::ResultPlyData data;
  std::string error;
  ASSERT_TRUE(nvv::ReadResultPly(out.File("auto.ply"), data, error)) << error;
  EXPECT_TRUE(SameRecords(ref.records, data.vertices));
  o.core.autoK = false;
  Reference fixed;
  ASSERT_TRUE(RunReference(sphere, o, fixed)) << fixed.st.message;
  EXPECT_FALSE(SameRecords(fixed.records, data.vertices)) << "automatic k ran at k = 3";
  // The clean sample: k = 3, and a noise estimate near 0.
  CliResult clean;
  Run({"--neighbourhood_k", "auto"}, &clean);
  EXPECT_NE(std::string::npos, clean.out.find("; k = 3 chosen from the noise")) << clean.out;
}

TEST_F(CliOptions, SpellingsOfOneValueGiveTheSameFile) {
  auto same = [&](const std::vector<std::string>& a, const std::vector<std::string>& b) {
    EXPECT_TRUE(SameRecords(Run(a).vertices, Run(b).vertices));
  };
  same({"--quality", "class"}, {"--quality", "6"});
  same({"--quality", "class"}, {"--quality=class"});
  same({"--curvature_fit", "euler"}, {"--curvature_fit", "2"});
  same({"--stop_at_creases", "no"}, {"--stop_at_creases", "0"});
  same({"--stop_at_creases", "FALSE"}, {"--stop_at_creases=false"});
  same({"--update_normals", "yes"}, {});
  same({"--threads", "1"}, {"--threads", "2"});
}
