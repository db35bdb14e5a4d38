// The nvv binary run as a child process on generated samples (OFF, PLY, OBJ, STL) and on the
// real fandisk mesh: it succeeds, its file is readable, its printed counts are the file's, and
// every value equals the core's run in-process on the same float mesh.
#include "cli_test_support.h"

using namespace nvv_cli_test;

namespace {

// Runs nvv on `input` with `args`, reads the result and checks it against the in-process
// reference with the options `o`.
void ExpectCliEqualsCore(const std::string& input, const std::vector<std::string>& args, const nvv::FilterOptions& o,
                         bool ascii = false) {
  TempDir dir;
  std::vector<std::string> all = args;
  all.push_back(input);
  all.push_back(dir.File("out.ply"));
  const CliResult r = RunCli(all, dir);
  ASSERT_EQ(0, r.exitCode) << r.err;
  EXPECT_EQ("", r.err) << "no progress or messages on stderr when it is not a terminal";

  nvv::ResultPlyData data;
  std::string error;
  ASSERT_TRUE(nvv::ReadResultPly(dir.File("out.ply"), data, error)) << error;
  EXPECT_EQ(!ascii, data.binary);

  std::array<std::size_t, 4> printed{}, inFile{};
  ASSERT_TRUE(PrintedCounts(r.out, printed)) << r.out;
  for (const auto& v : data.vertices) {
    ASSERT_LT(v.cls, 4);
    ++inFile[v.cls];
    EXPECT_GE(v.k1, v.k2);
  }
  EXPECT_EQ(printed, inFile);

  Reference ref;
  ASSERT_TRUE(RunReference(input, o, ref)) << ref.st.message;
  EXPECT_TRUE(SameRecords(ref.records, data.vertices));
  EXPECT_EQ(std::size_t(ref.mesh.fn), data.faces.size());
  EXPECT_EQ(ref.sum.perClass[0], printed[0]);
  EXPECT_NEAR(ref.sum.radius, PrintedRadius(r.out), 1e-3 * ref.sum.radius) << "printed with 4 digits";
}

}  // namespace

TEST(CliRun, GeneratedOffEqualsTheCoreInProcess) {
  Mesh m;
  SampleMesh(m);
  TempDir dir;
  const std::string input = dir.File("sample.off");
  ASSERT_EQ(0, vcg::tri::io::ExporterOFF<Mesh>::Save(m, input.c_str()));
  ExpectCliEqualsCore(input, {}, nvv::DefaultOptions());
}

TEST(CliRun, GeneratedPlyWithAsciiOutputAndOneThreadEqualsTheCore) {
  Mesh m;
  SampleMesh(m);
  TempDir dir;
  const std::string input = dir.File("sample.ply");
  ASSERT_EQ(0, vcg::tri::io::ExporterPLY<Mesh>::Save(m, input.c_str(), vcg::tri::io::Mask::IOM_NONE, true));
  ExpectCliEqualsCore(input, {"--ascii", "--threads", "1"}, nvv::DefaultOptions(), true);
}

TEST(CliRun, GeneratedObjEqualsTheCore) {
  Mesh m;
  SampleMesh(m);
  TempDir dir;
  const std::string input = dir.File("sample.obj");
  ASSERT_EQ(0, vcg::tri::io::ExporterOBJ<Mesh>::Save(m, input.c_str(), vcg::tri::io::Mask::IOM_NONE));
  ExpectCliEqualsCore(input, {}, nvv::DefaultOptions());
}

// Normals stored in the file are kept (MeshLab keeps them too): with --update_normals false
// they come out unchanged.
TEST(CliRun, NormalsOfThePlyAreKept) {
  Mesh m;
  SampleMesh(m);
  for (auto& v : m.vert) v.N() = vcg::Point3f(0.0f, 0.6f, 0.8f);
  TempDir dir;
  const std::string input = dir.File("normals.ply");
  ASSERT_EQ(0, vcg::tri::io::ExporterPLY<Mesh>::Save(m, input.c_str(), vcg::tri::io::Mask::IOM_VERTNORMAL, true));
  nvv::FilterOptions o = nvv::DefaultOptions();
  o.updateNormals = false;
  ExpectCliEqualsCore(input, {"--update_normals", "false"}, o);
  const CliResult r = RunCli({"--update_normals", "false", input, dir.File("o.ply")}, dir);
  ASSERT_EQ(0, r.exitCode) << r.err;
  nvv::ResultPlyData data;
  std::string error;
  ASSERT_TRUE(nvv::ReadResultPly(dir.File("o.ply"), data, error)) << error;
  for (const auto& v : data.vertices) {
    EXPECT_EQ(0.0f, v.normal[0]);
    EXPECT_EQ(0.6f, v.normal[1]);
    EXPECT_EQ(0.8f, v.normal[2]);
  }
}

TEST(CliRun, StlSoupIsWelded) {
  Mesh m;
  SampleMesh(m);
  TempDir dir;
  const std::string input = dir.File("sample.stl");
  ASSERT_EQ(0, vcg::tri::io::ExporterSTL<Mesh>::Save(m, input.c_str(), true));
  const CliResult r = RunCli({input, dir.File("out.ply")}, dir);
  ASSERT_EQ(0, r.exitCode) << r.err;
  nvv::ResultPlyData data;
  std::string error;
  ASSERT_TRUE(nvv::ReadResultPly(dir.File("out.ply"), data, error)) << error;
  EXPECT_EQ(m.vert.size(), data.vertices.size()) << "welded back to the shared vertices";
  EXPECT_EQ(m.face.size(), data.faces.size());
  std::array<std::size_t, 4> counts{};
  for (const auto& v : data.vertices) ++counts[v.cls];
  EXPECT_EQ(0u, counts[3]) << "a soup would leave every vertex without neighbours";
  EXPECT_GT(counts[1], 0u);
  EXPECT_NE(std::string::npos, r.out.find("welded"));
}

TEST(CliRun, FandiskEqualsTheCoreInProcess) {
  const std::string fandisk = SharedMeshes() + "/real/fandisk.off";
  if (!Exists(fandisk)) GTEST_SKIP() << "shared meshes not found at " << SharedMeshes() << " (fandisk.off is needed)";
  ExpectCliEqualsCore(fandisk, {}, nvv::DefaultOptions());
  nvv::FilterOptions o = nvv::DefaultOptions();
  o.core.fit = nvv::CurvatureFit::EulerLeastSquares;
  o.quality = nvv::QualityMode::GaussianCurvature;
  o.color = nvv::ColorMode::QualityRamp;
  ExpectCliEqualsCore(fandisk, {"--curvature_fit", "euler", "--quality", "gaussian", "--color", "ramp"}, o);
}

TEST(CliRun, RobustnessMeshesRunToTheEnd) {
  const std::string dirPath = SharedMeshes() + "/robustness";
  if (!Exists(dirPath)) GTEST_SKIP() << "shared meshes not found at " << SharedMeshes();
  for (const char* name : {"conrod.stl", "brain.ply", "non_manif_hole.ply"}) {
    SCOPED_TRACE(name);
    TempDir dir;
    const CliResult r = RunCli({dirPath + "/" + name, dir.File("out.ply")}, dir);
    ASSERT_EQ(0, r.exitCode) << r.err;
    nvv::ResultPlyData data;
    std::string error;
    EXPECT_TRUE(nvv::ReadResultPly(dir.File("out.ply"), data, error)) << error;
  }
}

TEST(CliRun, HelpReadsLikeAManualPageAndListsEveryParameter) {
  TempDir dir;
  const CliResult r = RunCli({"--help"}, dir);
  EXPECT_EQ(0, r.exitCode);
  EXPECT_EQ("", r.err);
  std::size_t at = 0;
  for (const char* section : {"NAME\n", "SYNOPSIS\n", "DESCRIPTION\n", "OPTIONS\n", "OUTPUT\n", "EXIT STATUS\n", "EXAMPLES\n"}) {
    const std::size_t p = r.out.find(section, at);
    EXPECT_NE(std::string::npos, p) << section;
    if (p != std::string::npos) at = p;
  }
  for (const auto& spec : nvv::FilterParameterTable()) {
    EXPECT_NE(std::string::npos, r.out.find(std::string("  --") + spec.name + " ")) << spec.name;
    for (const char* token : spec.tokens) EXPECT_NE(std::string::npos, r.out.find(token)) << token;
  }
  for (const char* own : {"--ascii", "--threads", "--quiet", "--help", "--version"})
    EXPECT_NE(std::string::npos, r.out.find(own)) << own;
  for (const char* prop : {"nvv_class", "nvv_lambda1", "pd1x", "nvv_crease_tangent_x", "nvv_cusp_angle", "nvv_flags"})
    EXPECT_NE(std::string::npos, r.out.find(prop)) << prop;
  const CliResult v = RunCli({"--version"}, dir);
  EXPECT_EQ(0, v.exitCode);
  EXPECT_EQ(0u, v.out.find("nvv "));
}

TEST(CliRun, QuietPrintsNothing) {
  Mesh m;
  nvv_shapes::Cube(m, 1.0, 6);
  TempDir dir;
  ASSERT_EQ(0, vcg::tri::io::ExporterOFF<Mesh>::Save(m, dir.File("c.off").c_str()));
  const CliResult r = RunCli({"--quiet", dir.File("c.off"), dir.File("c.ply")}, dir);
  EXPECT_EQ(0, r.exitCode);
  EXPECT_EQ("", r.out);
  EXPECT_EQ("", r.err);
  EXPECT_TRUE(Exists(dir.File("c.ply")));
}
