// Helpers for the command-line tool's tests: a temporary folder, running `nvv` as a child
// process, writing sample meshes with vcglib's exporters, and the in-process reference (the
// core and ApplyResults called directly on the same float mesh) that the tool must equal.
#ifndef NVV_TESTS_CLI_CLI_TEST_SUPPORT_H
#define NVV_TESTS_CLI_CLI_TEST_SUPPORT_H

#include <fcntl.h>
#include <ftw.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_mesh.h"  // vcg/complex/complex.h first, as vcglib requires

#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/export_obj.h>
#include <wrap/io_trimesh/export_off.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/export_stl.h>
#include <wrap/io_trimesh/import_obj.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>

#include "filter/apply_results.h"
#include "core/normal_vector_voting.h"
#include "io/result_ply.h"
#include "sample_meshes/synthetic_shapes.h"

namespace nvv_cli_test {

typedef nvv_cli::CliMesh Mesh;

// A fresh folder under /tmp, removed with everything in it at the end of the test.
class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/nvv_cli_test_XXXXXX";
    const char* p = ::mkdtemp(tmpl);
    path_ = p ? p : "";
  }
  ~TempDir() {
    if (path_.empty()) return;
    ::nftw(path_.c_str(), [](const char* f, const struct stat*, int, struct FTW*) { return ::remove(f); }, 16,
           FTW_DEPTH | FTW_PHYS);
  }
  std::string File(const std::string& name) const { return path_ + "/" + name; }
  const std::string& Path() const { return path_; }

 private:
  std::string path_;
};

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}
inline bool Exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

struct CliResult {
  int exitCode = -1;
  std::string out, err;
};

// Runs the nvv binary with `args`; stdout and stderr are files, so stderr is not a terminal.
inline CliResult RunCli(const std::vector<std::string>& args, const TempDir& dir) {
  CliResult r;
  const std::string outPath = dir.File("cli_stdout.txt"), errPath = dir.File("cli_stderr.txt");
  std::vector<std::string> all;
  all.push_back(NVV_CLI_PATH);
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1);
    ::dup2(e, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = ReadText(outPath);
  r.err = ReadText(errPath);
  return r;
}

// What every failure must look like: exactly one line on stderr, starting with "nvv: ".
inline ::testing::AssertionResult OneErrorLine(const CliResult& r) {
  const std::size_t nl = r.err.find('\n');
  if (r.err.compare(0, 5, "nvv: ") != 0) return ::testing::AssertionFailure() << "stderr: '" << r.err << "'";
  if (nl == std::string::npos || nl + 1 != r.err.size())
    return ::testing::AssertionFailure() << "not exactly one line: '" << r.err << "'";
  return ::testing::AssertionSuccess();
}

// Class counts of the summary line on stdout: surface, crease, corner, unclassified.
inline bool PrintedCounts(const std::string& out, std::array<std::size_t, 4>& counts) {
  std::smatch mm;
  const std::regex re("Normal vector voting: ([0-9]+) surface, ([0-9]+) crease, ([0-9]+) corner, ([0-9]+) unclassified");
  if (!std::regex_search(out, mm, re)) return false;
  for (int i = 0; i < 4; ++i) counts[i] = std::stoul(mm[i + 1].str());
  return true;
}
inline double PrintedRadius(const std::string& out) {
  std::smatch mm;
  const std::regex re("radius ([-+0-9.eE]+)");
  return std::regex_search(out, mm, re) ? std::stod(mm[1].str()) : -1.0;
}

// A sample with flat faces, 90-degree creases, corners, curved sheets and a 140-degree knife
// edge: a cube, a torus beside it and a sharp roof on the other side.
inline void SampleMesh(Mesh& m) {
  Mesh cube, torus, roof;
  nvv_shapes::Cube(cube, 1.0, 10);
  nvv_shapes::Torus(torus, 1.2, 0.45, 40, 20, 0.3, 7);
  for (auto& v : torus.vert) v.P() += vcg::Point3f(4.0f, 0.0f, 0.0f);
  nvv_shapes::Roof(roof, 140.0, 17, 1.0, 2.0);
  for (auto& v : roof.vert) v.P() += vcg::Point3f(-4.0f, 0.0f, 0.0f);
  m.Clear();
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(m, cube);
  vcg::tri::Append<Mesh, Mesh>::Mesh(m, torus);
  vcg::tri::Append<Mesh, Mesh>::Mesh(m, roof);
}

// The per-field bit patterns of a record, in file order, so records compare float-exactly.
inline std::vector<std::pair<std::string, std::uint32_t>> FieldBits(const nvv::ResultPlyVertex& v) {
  std::vector<std::pair<std::string, std::uint32_t>> bits;
  nvv::ForEachResultPlyField(v, [&](const char* name, const auto& field) {
    std::uint32_t b = 0;
    std::memcpy(&b, &field, sizeof field);
    bits.emplace_back(name, b);
  });
  return bits;
}
inline ::testing::AssertionResult SameRecords(const std::vector<nvv::ResultPlyVertex>& a,
                                              const std::vector<nvv::ResultPlyVertex>& b) {
  if (a.size() != b.size()) return ::testing::AssertionFailure() << a.size() << " vs " << b.size() << " vertices";
  std::size_t bad = 0;
  std::ostringstream first;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto fa = FieldBits(a[i]), fb = FieldBits(b[i]);
    for (std::size_t k = 0; k < fa.size(); ++k)
      if (fa[k].second != fb[k].second && bad++ == 0) first << "vertex " << i << " field " << fa[k].first;
  }
  if (bad) return ::testing::AssertionFailure() << bad << " fields differ, first: " << first.str();
  return ::testing::AssertionSuccess();
}

// The records the tool must write for mesh m with results res (non-deleted vertices).
inline std::vector<nvv::ResultPlyVertex> RecordsOf(const Mesh& m, const std::vector<nvv::VertexResult>& res) {
  std::vector<nvv::ResultPlyVertex> v;
  for (std::size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) v.push_back(nvv::MakeResultPlyVertex(m, i, res[i]));
  return v;
}

// In-process reference: vcglib's importer, MeshLab's normals on load (angle-weighted, normalized,
// only when the file has none), the core, ApplyResults. PLY, OFF and OBJ.
struct Reference {
  Mesh mesh;
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  nvv::Status st;
  std::vector<nvv::ResultPlyVertex> records;
  nvv::CreaseOutputs crease;  // when nvv::WantsCreaseNetwork(options)
};
// A reference OBJ reader for the generated samples (v lines, triangular f lines with positive
// indices): vcglib's importer drops every face that uses the file's first vertex.
inline bool ReadTriangleObj(const std::string& path, Mesh& m) {
  std::ifstream in(path);
  std::string line;
  std::vector<vcg::Point3f> v;
  std::vector<std::array<int, 3>> f;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string k;
    if (!(ls >> k)) continue;
    if (k == "v") {
      std::string x, y, z;
      ls >> x >> y >> z;
      v.push_back(vcg::Point3f(float(std::atof(x.c_str())), float(std::atof(y.c_str())), float(std::atof(z.c_str()))));
    } else if (k == "f") {
      std::array<int, 3> t;
      for (int j = 0; j < 3; ++j) {
        std::string c;
        if (!(ls >> c)) return false;
        t[j] = std::atoi(c.c_str()) - 1;
        if (t[j] < 0 || t[j] >= int(v.size())) return false;
      }
      f.push_back(t);
    }
  }
  vcg::tri::Allocator<Mesh>::AddVertices(m, v.size());
  for (std::size_t i = 0; i < v.size(); ++i) m.vert[i].P().Import(v[i]);
  for (const auto& t : f) vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[t[0]], &m.vert[t[1]], &m.vert[t[2]]);
  return true;
}

inline bool RunReference(const std::string& path, const nvv::FilterOptions& o, Reference& r) {
  namespace io = vcg::tri::io;
  int mask = 0, err = 0;
  const std::string ext = path.substr(path.size() - 4);
  if (ext == ".ply") err = io::ImporterPLY<Mesh>::ErrorCritical(io::ImporterPLY<Mesh>::Open(r.mesh, path.c_str(), mask));
  else if (ext == ".off") err = io::ImporterOFF<Mesh>::Open(r.mesh, path.c_str(), mask);
  else if (ext == ".obj") err = ReadTriangleObj(path, r.mesh) ? 0 : 1;  // vcglib's drops faces on vertex 1
  else return false;
  if (err) return false;
  if (!(mask & io::Mask::IOM_VERTNORMAL)) {
    vcg::tri::UpdateNormal<Mesh>::PerVertexAngleWeighted(r.mesh);
    vcg::tri::UpdateNormal<Mesh>::NormalizePerVertex(r.mesh);
  }
  nvv::SurfaceGraph g;
  r.st = vcg::tri::NormalVectorVoting<Mesh>::Compute(r.mesh, o.core, r.res, r.sum, g);
  if (!r.st.ok) return false;
  const bool network = nvv::WantsCreaseNetwork(o);
  if (network) r.crease = nvv::FindCreaseOutputs(r.mesh, g, r.res, r.sum, o.core.creaseAngleDeg);
  nvv::ApplyResults<Mesh>::Apply(r.mesh, r.res, o, network ? &r.crease : nullptr);
  r.records = RecordsOf(r.mesh, r.res);
  return true;
}

inline std::string SharedMeshes() { return NVV_SHARED_MESHES; }

}  // namespace nvv_cli_test

#endif
