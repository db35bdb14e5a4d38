// Every way the tool can fail: the exit status of its class (2 arguments, 3 input, 4 refused
// by the filter, 5 output) and exactly one line on stderr starting with "nvv: ".
#include "cli_test_support.h"

using namespace nvv_cli_test;

namespace {

class CliErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    Mesh m;
    nvv_shapes::Cube(m, 1.0, 5);
    good_ = dir_.File("good.off");
    ASSERT_EQ(0, vcg::tri::io::ExporterOFF<Mesh>::Save(m, good_.c_str()));
  }
  // Runs nvv and checks the status, the one stderr line, and that no output was left behind.
  void ExpectFailure(int code, const std::vector<std::string>& args, const char* mentions = nullptr) {
    const CliResult r = RunCli(args, dir_);
    EXPECT_EQ(code, r.exitCode) << r.err;
    EXPECT_TRUE(OneErrorLine(r));
    if (mentions) {
      EXPECT_NE(std::string::npos, r.err.find(mentions)) << r.err;
    }
    EXPECT_FALSE(Exists(Out()));
  }
  std::string Out() const { return dir_.File("out.ply"); }
  std::string Write(const std::string& name, const std::string& text) {
    WriteText(dir_.File(name), text);
    return dir_.File(name);
  }

  TempDir dir_;
  std::string good_;
};

}  // namespace

TEST_F(CliErrors, MissingInputIs3) {
  ExpectFailure(3, {dir_.File("no_such_mesh.off"), Out()}, "no_such_mesh.off");
}

TEST_F(CliErrors, CorruptInputIs3) {
  ExpectFailure(3, {Write("garbage.ply", "this is not a mesh\n\x01\x02\x03"), Out()}, "garbage.ply");
  ExpectFailure(3, {Write("garbage.off", "hello world\n1 2 3\n"), Out()});
  ExpectFailure(3, {Write("garbage.stl", "not an stl at all"), Out()});
  ExpectFailure(3, {Write("bad_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), Out()});
  // A binary PLY cut short in its vertex data.
  const std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 10\n"
                          "property list uchar int vertex_indices\nend_header\n" + std::string(40, '\0');
  ExpectFailure(3, {Write("truncated.ply", ply), Out()});
  ExpectFailure(3, {dir_.Path(), Out()}, "directory");
}

TEST_F(CliErrors, FilesThatAreNotRegularOrAreEmptyAre3) {
  // A FIFO must be refused at once, not waited on; /dev/zero under a mesh name must not be read.
  const std::string fifo = dir_.File("pipe.ply");
  ASSERT_EQ(0, ::mkfifo(fifo.c_str(), 0600));
  ExpectFailure(3, {fifo, Out()}, "FIFO");
  const std::string zero = dir_.File("zero.stl");
  ASSERT_EQ(0, ::symlink("/dev/zero", zero.c_str()));
  ExpectFailure(3, {zero, Out()}, "device");
  for (const char* name : {"empty.ply", "empty.obj", "empty.off", "empty.stl"})
    ExpectFailure(3, {Write(name, ""), Out()}, name);
  // A huge count in a tiny file is refused before anything is allocated.
  ExpectFailure(3, {Write("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\n"
                                      "property float y\nproperty float z\nend_header\n"), Out()}, "huge.ply");
}

TEST_F(CliErrors, UnsupportedExtensionIs3) {
  ExpectFailure(3, {Write("mesh.xyz", "0 0 0\n"), Out()}, ".xyz");
  ExpectFailure(3, {Write("mesh", "OFF\n0 0 0\n"), Out()}, "no extension");
}

TEST_F(CliErrors, BadArgumentsAre2) {
  ExpectFailure(2, {"--no_such_option", "1", good_, Out()}, "--no_such_option");
  ExpectFailure(2, {"-x", good_, Out()}, "-x");
  // MeshLab's lines layer has no meaning here: the message names the tool's lines file instead.
  ExpectFailure(2, {"--crease_lines_layer", "true", good_, Out()}, "--crease_lines FILE");
  ExpectFailure(2, {"--neighbourhood_k", "-1", good_, Out()}, "neighbourhood_k");
  ExpectFailure(2, {"--neighbourhood_k", "0", good_, Out()});
  ExpectFailure(2, {"--crease_angle", "120", good_, Out()}, "crease_angle");
  ExpectFailure(2, {"--corner_angle", "abc", good_, Out()}, "corner_angle");
  ExpectFailure(2, {"--absolute_radius", "nan", good_, Out()});
  // Only decimal numbers: hexadecimal, infinities and stray characters are refused.
  ExpectFailure(2, {"--neighbourhood_k", "0x3", good_, Out()}, "neighbourhood_k");
  ExpectFailure(2, {"--crease_angle", "0x1p5", good_, Out()}, "crease_angle");
  ExpectFailure(2, {"--absolute_radius", "inf", good_, Out()});
  ExpectFailure(2, {"--neighbourhood_k", "3 ", good_, Out()});
  ExpectFailure(2, {"--max_neighbourhood", "3.5", good_, Out()});
  ExpectFailure(2, {"--max_neighbourhood", "10000001", good_, Out()}, "10000000");  // the range --help gives
  ExpectFailure(2, {"--quality", "colourful", good_, Out()}, "shape_index");
  ExpectFailure(2, {"--quality", "10", good_, Out()});
  ExpectFailure(2, {"--stop_at_creases", "maybe", good_, Out()});
  ExpectFailure(2, {"--threads", "-2", good_, Out()});
  ExpectFailure(2, {"--ascii=yes", good_, Out()});
  ExpectFailure(2, {good_, Out(), "--crease_angle"}, "needs a value");
  ExpectFailure(2, {}, "missing");
  ExpectFailure(2, {good_}, "missing");
  ExpectFailure(2, {good_, Out(), dir_.File("third.ply")}, "too many");
  ExpectFailure(2, {good_, dir_.File("out.off")}, ".ply");
  // Arguments are checked before the input is read.
  ExpectFailure(2, {"--crease_angle", "120", dir_.File("missing.off"), Out()});
}

TEST_F(CliErrors, MeshTheFilterRefusesIs4) {
  const std::string pointCloud = Write("cloud.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  ExpectFailure(4, {pointCloud, Out()}, "point cloud");
  const std::string empty = Write("empty.ply",
      "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 0\nproperty list uchar int vertex_indices\nend_header\n");
  ExpectFailure(4, {empty, Out()}, "empty");
  const std::string flat = Write("degenerate.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 1 2\n3 1 2 3\n");
  ExpectFailure(4, {flat, Out()}, "zero area");
}

TEST_F(CliErrors, UnwritableOutputIs5) {
  const CliResult r = RunCli({good_, "/nonexistent_nvv_dir/sub/out.ply"}, dir_);
  EXPECT_EQ(5, r.exitCode);
  EXPECT_TRUE(OneErrorLine(r));
  EXPECT_EQ("", r.out) << "refused before the computation";
  // The output name is an existing directory.
  ASSERT_EQ(0, ::mkdir(dir_.File("dir.ply").c_str(), 0755));
  const CliResult d = RunCli({good_, dir_.File("dir.ply")}, dir_);
  EXPECT_EQ(5, d.exitCode);
  EXPECT_TRUE(OneErrorLine(d));
  // A folder without write permission (meaningless for root, who may write anywhere).
  if (::geteuid() != 0) {
    ASSERT_EQ(0, ::mkdir(dir_.File("ro").c_str(), 0555));
    ExpectFailure(5, {good_, dir_.File("ro/out.ply")});
  }
}

// Finite vertices get finite values at any scale the corpus holds, and a NaN vertex does not
// spread to its neighbours: the normals computed on loading leave such faces out, and are taken
// on the mesh scaled to unit size where float cross products would overflow or underflow.
TEST_F(CliErrors, FiniteVerticesGetFiniteValuesAtAnyScaleAndBesideNaN) {
  for (double scale : {1e-30, 1.0, 1e30}) {
    Mesh m;
    nvv_shapes::Cube(m, 1.0, 5);
    for (auto& v : m.vert) v.P() *= scale;
    if (scale == 1.0) m.vert[7].P()[0] = std::nan("");
    const std::string in = dir_.File("scaled.off");
    ASSERT_EQ(0, vcg::tri::io::ExporterOFF<Mesh>::Save(m, in.c_str()));
    for (const char* keep : {"true", "false"}) {  // update_normals false: the loaded normals are kept
      const CliResult r = RunCli({"--update_normals", keep, in, Out()}, dir_);
      ASSERT_EQ(0, r.exitCode) << r.err;
      nvv::ResultPlyData d;
      std::string error;
      ASSERT_TRUE(nvv::ReadResultPly(Out(), d, error)) << error;
      for (std::size_t i = 0; i < d.vertices.size(); ++i) {
        const nvv::ResultPlyVertex& v = d.vertices[i];
        if (!(std::isfinite(v.position[0]) && std::isfinite(v.position[1]) && std::isfinite(v.position[2]))) continue;
        EXPECT_TRUE(std::isfinite(v.normal[0]) && std::isfinite(v.normal[1]) && std::isfinite(v.normal[2]))
            << "scale " << scale << ", update_normals " << keep << ", vertex " << i;
        EXPECT_TRUE(std::isfinite(v.k1) && std::isfinite(v.k2) && std::isfinite(v.quality)) << i;
      }
      std::remove(Out().c_str());
    }
  }
}

// A file listing one point 100,000 times, each copy making a triangle with the same edge (a
// "book" whose spine every face shares): quadratic in the copies once (16 GB, then "out of
// memory"); now every vertex is classified, in time and memory linear in the file.
TEST_F(CliErrors, OnePointListedAHundredThousandTimesRunsToTheEnd) {
  const int copies = 100000;
  std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(copies + 2) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(copies) +
                    "\nproperty list uchar int vertex_indices\nend_header\n1 0 0\n0 1 0\n";
  for (int i = 0; i < copies; ++i) ply += "0 0 0\n";
  for (int i = 0; i < copies; ++i) ply += "3 " + std::to_string(i + 2) + " 0 1\n";
  const CliResult r = RunCli({Write("book.ply", ply), Out()}, dir_);
  ASSERT_EQ(0, r.exitCode) << r.err;
  std::array<std::size_t, 4> counts{};
  ASSERT_TRUE(PrintedCounts(r.out, counts)) << r.out;
  EXPECT_EQ(std::size_t(copies + 2), counts[0] + counts[1] + counts[2]) << r.out;  // none unclassified
  EXPECT_EQ(0u, counts[3]) << r.out;
  EXPECT_NE(std::string::npos, r.out.find("neighbourhood cap")) << r.out;
}
