// The crease network through the command-line tool, on shapes whose lines and patches are known:
// a cube (12 lines between 8 corners, 6 patches) and a capped cylinder (2 closed lines, 3 patches).
// Each is checked in the full-result PLY (the edge element, the faces' patches), in the polyline
// files of --crease_lines (.obj and .ply) and in the printed summary.
#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cli_test_support.h"
#include "../test_support.h"

using namespace nvv_cli_test;

namespace {

// What a run wrote, read back.
struct NetworkFiles {
  CliResult cli;
  nvv::ResultPlyData ply;
  std::vector<std::vector<int>> objLines;  // the `l` records, 1-based as written
  std::vector<nvv::ResultPlyEdge> plyLineEdges;
  std::size_t plyLineVertices = 0;
};

// The `l` records of a crease-lines OBJ.
std::vector<std::vector<int>> ReadObjLines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<int>> lines;
  std::string text;
  while (std::getline(in, text)) {
    if (text.compare(0, 2, "l ") != 0) continue;
    std::istringstream ls(text.substr(2));
    lines.emplace_back();
    for (int v; ls >> v;) lines.back().push_back(v);
  }
  return lines;
}

// The vertex count and the edges of a crease-lines PLY (ascii, as the tool writes it).
bool ReadPlyLines(const std::string& path, std::size_t& vertices, std::vector<nvv::ResultPlyEdge>& edges) {
  std::ifstream in(path);
  std::string text;
  std::size_t edgeCount = 0;
  while (std::getline(in, text) && text != "end_header") {
    std::istringstream ls(text);
    std::string key, element;
    ls >> key >> element;
    if (key == "element" && element == "vertex") ls >> vertices;
    if (key == "element" && element == "edge") ls >> edgeCount;
  }
  for (std::size_t i = 0; i < vertices && std::getline(in, text); ++i) {}
  edges.resize(edgeCount);
  for (auto& e : edges)
    if (!(in >> e.vertex[0] >> e.vertex[1] >> e.cuspAngle >> e.line)) return false;
  return true;
}

// Writes m as dir's in.ply; returns its path, or an empty string when it could not be written.
std::string SaveInput(nvv_test::TMesh& m, const TempDir& dir) {
  const std::string input = dir.File("in.ply");
  return vcg::tri::io::ExporterPLY<nvv_test::TMesh>::Save(m, input.c_str(), 0, true) == 0 ? input : std::string();
}

NetworkFiles RunOnFile(const std::string& input, const TempDir& dir) {
  NetworkFiles f;
  f.cli = RunCli({"--crease_lines", dir.File("lines.obj"), input, dir.File("out.ply")}, dir);
  EXPECT_EQ(0, f.cli.exitCode) << f.cli.err;
  std::string error;
  EXPECT_TRUE(nvv::ReadResultPly(dir.File("out.ply"), f.ply, error)) << error;
  f.objLines = ReadObjLines(dir.File("lines.obj"));
  const CliResult again = RunCli({"--quiet", "--crease_lines", dir.File("lines.ply"), input, dir.File("out2.ply")}, dir);
  EXPECT_EQ(0, again.exitCode) << again.err;
  EXPECT_TRUE(ReadPlyLines(dir.File("lines.ply"), f.plyLineVertices, f.plyLineEdges));
  return f;
}

NetworkFiles RunOn(nvv_test::TMesh& m) {
  TempDir dir;
  const std::string input = SaveInput(m, dir);
  EXPECT_FALSE(input.empty());
  return RunOnFile(input, dir);
}

// The CAD benchmark's machined block (bench/cad/make_cad_parts.py, gmsh's OpenCASCADE kernel), at
// mesh size `size`, as dir's block_<size>.obj; empty when python3-gmsh is not installed.
std::string MakeCadBlock(const std::string& size, const TempDir& dir) {
  if (std::system("/usr/bin/python3 -c 'import gmsh' > /dev/null 2>&1") != 0) return std::string();
  const std::string cmd = "/usr/bin/python3 '" NVV_SOURCE_DIR "/bench/cad/make_cad_parts.py' '" + dir.Path() +
                          "' block_" + size + " > '" + dir.File("gmsh.log") + "' 2>&1";
  EXPECT_EQ(0, std::system(cmd.c_str())) << cmd;
  return dir.File("block_" + size + ".obj");
}

std::set<int> Ids(const std::vector<int>& ids) {
  std::set<int> s(ids.begin(), ids.end());
  s.erase(-1);
  return s;
}

std::set<int> LinesOf(const std::vector<nvv::ResultPlyEdge>& edges) {
  std::set<int> s;
  for (const auto& e : edges) s.insert(e.line);
  return s;
}

// The corners (class 2) that end a crease edge of the result file.
std::set<int> CornersOnEdges(const nvv::ResultPlyData& d) {
  std::set<int> corners;
  for (const auto& e : d.edges)
    for (int v : e.vertex)
      if (d.vertices[v].cls == 2) corners.insert(v);
  return corners;
}

// Checks what every shape shares: each face in a patch, the lines' edges the same in both files.
void CheckConsistent(const NetworkFiles& f) {
  ASSERT_EQ(f.ply.faces.size(), f.ply.facePatch.size());
  for (int p : f.ply.facePatch) EXPECT_GE(p, 0);
  // Each crease edge belongs to one line, in the result file and in the polyline PLY alike.
  EXPECT_EQ(f.ply.edges.size(), f.plyLineEdges.size());
  EXPECT_EQ(LinesOf(f.ply.edges), LinesOf(f.plyLineEdges));
  std::size_t objEdges = 0;
  for (const auto& l : f.objLines) objEdges += l.size() - 1;
  EXPECT_EQ(f.ply.edges.size(), objEdges);
  for (const auto& e : f.ply.edges) {
    EXPECT_LT(e.vertex[0], e.vertex[1]);
    EXPECT_GT(e.cuspAngle, 1.2f) << "about 90 degrees, in radians";
    EXPECT_LT(e.cuspAngle, 1.9f);
  }
}

}  // namespace

TEST(CliCreaseNetwork, ACubeHasTwelveLinesEightCornersAndSixPatches) {
  nvv_test::TMesh m;
  nvv_shapes::Cube(m, 5.0, 21);
  const NetworkFiles f = RunOn(m);
  CheckConsistent(f);
  EXPECT_EQ(6u, Ids(f.ply.facePatch).size());
  EXPECT_EQ(12u, LinesOf(f.ply.edges).size());
  EXPECT_EQ(8u, CornersOnEdges(f.ply).size());
  ASSERT_EQ(12u, f.objLines.size());
  for (const auto& l : f.objLines) EXPECT_NE(l.front(), l.back()) << "open lines, from corner to corner";
  EXPECT_NE(std::string::npos, f.cli.out.find("in 12 lines (0 closed, 8 corners at their ends); 6 patches of"))
      << f.cli.out;
}

TEST(CliCreaseNetwork, ACappedCylinderHasTwoClosedLinesAndThreePatches) {
  nvv_test::TMesh m;
  nvv_test::CappedCylinder(m, 5.0, 10.0, 64, 20);
  const NetworkFiles f = RunOn(m);
  CheckConsistent(f);
  EXPECT_EQ(3u, Ids(f.ply.facePatch).size());
  EXPECT_EQ(2u, LinesOf(f.ply.edges).size());
  EXPECT_EQ(0u, CornersOnEdges(f.ply).size());
  ASSERT_EQ(2u, f.objLines.size());
  for (const auto& l : f.objLines) {
    EXPECT_EQ(l.front(), l.back()) << "a closed line repeats its first vertex";
    EXPECT_EQ(65u, l.size()) << "the rim's 64 vertices";
  }
  EXPECT_EQ(128u, f.plyLineVertices);
  EXPECT_NE(std::string::npos, f.cli.out.find("in 2 lines (2 closed, 0 corners at their ends); 3 patches of"))
      << f.cli.out;
}

// A box with fillets on its vertical edges, a 45 deg chamfer round its top and a through hole, made
// and meshed by a CAD kernel: its sharp model curves close into 5 loops (top face | chamfer,
// chamfer | sides, the bottom rim, the hole's two rims), with no corner, and they bound 5 smooth
// patches (the top, the chamfer, the sides with their fillets, the bottom, the hole). The fillets'
// boundaries are tangent: no line. At the CAD kernel's coarse, default and fine mesh sizes the
// network is exact; at the export size (the hole's 12 facets folded across a sliver) the patches are.
TEST(CliCreaseNetwork, ACadBlockWithFilletsAChamferAndAHoleHasFiveClosedLinesAndFivePatches) {
  for (const std::string size : {"default", "fine", "coarse", "export"}) {
    SCOPED_TRACE(size);
    TempDir dir;
    const std::string input = MakeCadBlock(size, dir);
    if (input.empty()) GTEST_SKIP() << "python3-gmsh is not installed (apt-get install python3-gmsh)";
    const NetworkFiles f = RunOnFile(input, dir);
    ASSERT_EQ(f.ply.faces.size(), f.ply.facePatch.size());
    EXPECT_EQ(5u, Ids(f.ply.facePatch).size());
    if (size == "export") continue;
    EXPECT_EQ(5u, LinesOf(f.ply.edges).size());
    EXPECT_EQ(0u, CornersOnEdges(f.ply).size());
    ASSERT_EQ(5u, f.objLines.size());
    for (const auto& l : f.objLines) EXPECT_EQ(l.front(), l.back()) << "closed";
    EXPECT_NE(std::string::npos, f.cli.out.find("in 5 lines (5 closed, 0 corners at their ends); 5 patches of"))
        << f.cli.out;
    // 45 deg (chamfer; down to 34 deg between the coarse facets of its cone round a fillet) or
    // 90 deg (bottom rim, hole).
    for (const auto& e : f.ply.edges) {
      EXPECT_GT(e.cuspAngle, 0.5f);
      EXPECT_LT(e.cuspAngle, 1.7f);
    }
  }
}

// Without the network the file is the one earlier versions wrote: no patch, no edge element.
TEST(CliCreaseNetwork, OffLeavesTheFileAsBefore) {
  nvv_test::TMesh m;
  nvv_shapes::Cube(m, 5.0, 9);
  TempDir dir;
  const std::string input = SaveInput(m, dir);
  ASSERT_FALSE(input.empty());
  const CliResult r = RunCli({"--crease_edges", "false", input, dir.File("out.ply")}, dir);
  ASSERT_EQ(0, r.exitCode) << r.err;
  EXPECT_EQ(std::string::npos, r.out.find("Crease network")) << r.out;
  std::ifstream in(dir.File("out.ply"), std::ios::binary);
  std::string header, text;
  while (std::getline(in, text) && text != "end_header") header += text + "\n";
  EXPECT_EQ(std::string::npos, header.find("patch")) << header;
  EXPECT_EQ(std::string::npos, header.find("element edge")) << header;
  nvv::ResultPlyData d;
  std::string error;
  ASSERT_TRUE(nvv::ReadResultPly(dir.File("out.ply"), d, error)) << error;
  EXPECT_TRUE(d.facePatch.empty());
  EXPECT_TRUE(d.edges.empty());
}

TEST(CliCreaseNetwork, ALinesFileOfAnotherKindIsRefused) {
  TempDir dir;
  const CliResult r = RunCli({"--crease_lines", dir.File("lines.txt"), dir.File("in.ply"), dir.File("out.ply")}, dir);
  EXPECT_EQ(2, r.exitCode);
  EXPECT_NE(std::string::npos, r.err.find(".obj or .ply")) << r.err;
}

TEST(CliCreaseNetwork, AnUnwritableLinesFileIsRefusedBeforeAnyWork) {
  nvv_test::TMesh m;
  nvv_shapes::Cube(m, 5.0, 5);
  TempDir dir;
  const std::string input = SaveInput(m, dir);
  ASSERT_FALSE(input.empty());
  const CliResult r = RunCli({"--crease_lines", "/nonexistent/dir/lines.obj", input, dir.File("out.ply")}, dir);
  EXPECT_EQ(5, r.exitCode);
  EXPECT_NE(std::string::npos, r.err.find("cannot write the crease lines")) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(std::ifstream(dir.File("out.ply")).good());
}
