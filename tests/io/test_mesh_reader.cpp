// The mesh readers on valid files of every kind they take and on the files that crashed, hung
// or exhausted the memory of the importers used before them: long face lists, out-of-range and
// extreme indices, huge header counts, truncation, empty files, FIFOs, devices, directories,
// NaN and inf text.
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_reader.h"

// This file replaces the global operator new and delete with malloc and free, as a pair; GCC
// cannot see that they match.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

// The largest single allocation since the last reset: the huge-count tests assert that nothing
// near the declared size is ever requested.
static std::atomic<std::size_t> gLargestAllocation{0};
void* operator new(std::size_t n) {
  std::size_t cur = gLargestAllocation.load();
  while (n > cur && !gLargestAllocation.compare_exchange_weak(cur, n)) {
  }
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using nvv::io::MeshData;
using nvv::io::MeshFormat;
using nvv::io::ReadLimits;

namespace {

struct Result {
  bool ok;
  std::string error;
  MeshData mesh;
};

Result Read(const std::string& bytes, MeshFormat f, const ReadLimits& limits = ReadLimits()) {
  Result r;
  r.ok = nvv::io::ReadMeshBytes(bytes.data(), bytes.size(), f, r.mesh, r.error, limits);
  if (r.ok) {
    EXPECT_EQ("", r.error);
  }
  if (!r.ok) {
    EXPECT_FALSE(r.error.empty());
    EXPECT_TRUE(r.mesh.positions.empty() && r.mesh.triangles.empty()) << "a failed read leaves nothing";
  }
  return r;
}

Result ReadPath(const std::string& path) {
  Result r;
  r.ok = nvv::io::ReadMeshFile(path, r.mesh, r.error);
  return r;
}

class TempDir {
 public:
  TempDir() {
    char tmpl[] = "/tmp/nvv_io_test_XXXXXX";
    const char* d = ::mkdtemp(tmpl);
    path_ = d ? d : "/tmp";
  }
  ~TempDir() {
    for (const std::string& f : files_) ::unlink(f.c_str());
    ::rmdir(path_.c_str());
  }
  std::string File(const std::string& name) {
    files_.push_back(path_ + "/" + name);
    return files_.back();
  }
  std::string Write(const std::string& name, const std::string& bytes) {
    const std::string p = File(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  const std::string& Path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::string> files_;
};

template <class T>
void Put(std::string& s, T v, bool bigEndian = false) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (bigEndian) std::reverse(b, b + sizeof(T));
  s.append(b, sizeof(T));
}

const char* kPlyXyz = "property float x\nproperty float y\nproperty float z\n";

// A tetrahedron with one face written as a quad (0 1 2 3 is not planar: it only tests the fan).
std::string TetraPly(const std::string& format) {
  std::string s = "ply\nformat " + format + " 1.0\ncomment test\nelement vertex 4\n" + kPlyXyz +
                  "element face 3\nproperty list uchar int vertex_indices\nend_header\n";
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[3][4] = {{3, 0, 2, 1}, {3, 0, 1, 3}, {4, 1, 2, 3}};
  const bool be = format == "binary_big_endian";
  if (format == "ascii") {
    s += "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n4 1 2 3 0\n";
    return s;
  }
  for (auto& p : v)
    for (float c : p) Put(s, c, be);
  for (auto& f : faces) {
    s += char(f[0]);
    for (int k = 1; k <= f[0]; ++k) Put(s, std::int32_t(k == 4 ? 0 : f[k]), be);
  }
  return s;
}

void ExpectTetra(const Result& r) {
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(4u, r.mesh.positions.size());
  EXPECT_EQ(1.0f, r.mesh.positions[1][0]);
  EXPECT_EQ(1.0f, r.mesh.positions[3][2]);
  ASSERT_EQ(4u, r.mesh.triangles.size());
  EXPECT_EQ((std::array<int, 3>{{0, 2, 1}}), r.mesh.triangles[0]);
  EXPECT_EQ((std::array<int, 3>{{0, 1, 3}}), r.mesh.triangles[1]);
  EXPECT_EQ((std::array<int, 3>{{1, 2, 3}}), r.mesh.triangles[2]);
  EXPECT_EQ((std::array<int, 3>{{1, 3, 0}}), r.mesh.triangles[3]);
  EXPECT_EQ(1u, r.mesh.polygons);
}

std::size_t CountFaceTriangles(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string k;
    if (!(ls >> k) || k != "f") continue;
    std::size_t c = 0;
    while (ls >> k) ++c;
    if (c >= 3) n += c - 2;
  }
  return n;
}

std::vector<std::string> FilesIn(const std::string& dir, const std::string& ext) {
  std::vector<std::string> out;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return out;
  while (dirent* e = ::readdir(d)) {
    const std::string n = e->d_name;
    if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0) out.push_back(dir + "/" + n);
  }
  ::closedir(d);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

// ---- PLY ----------------------------------------------------------------------------------

TEST(PlyReader, AsciiAndBothBinaryEncodingsGiveTheSameMesh) {
  for (const char* f : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(f);
    ExpectTetra(Read(TetraPly(f), MeshFormat::Ply));
  }
}

TEST(PlyReader, EveryScalarTypeForCoordinatesAndIndices) {
  const char* types[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                         "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
  for (const char* t : types) {
    for (const char* enc : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      SCOPED_TRACE(std::string(t) + " " + enc);
      std::string s = std::string("ply\nformat ") + enc + " 1.0\nelement vertex 3\nproperty " + t + " x\nproperty " + t +
                      " y\nproperty " + t + " z\nelement face 1\nproperty list " +
                      (std::strstr(t, "float") || std::strstr(t, "double") ? "uchar" : t) + " " +
                      (std::strstr(t, "float") || std::strstr(t, "double") ? "int" : t) + " vertex_indices\nend_header\n";
      const bool be = std::string(enc) == "binary_big_endian";
      const std::string tt = t;
      auto put = [&](int v) {
        if (tt == "char" || tt == "int8") s += char(std::int8_t(v));
        else if (tt == "uchar" || tt == "uint8") s += char(std::uint8_t(v));
        else if (tt == "short" || tt == "int16") Put(s, std::int16_t(v), be);
        else if (tt == "ushort" || tt == "uint16") Put(s, std::uint16_t(v), be);
        else if (tt == "int" || tt == "int32") Put(s, std::int32_t(v), be);
        else if (tt == "uint" || tt == "uint32") Put(s, std::uint32_t(v), be);
        else if (tt == "float" || tt == "float32") Put(s, float(v), be);
        else Put(s, double(v), be);
      };
      const bool floating = std::strstr(t, "float") || std::strstr(t, "double");
      if (std::string(enc) == "ascii") {
        s += "1 2 3\n4 5 6\n7 8 9\n3 0 1 2\n";
      } else {
        for (int v = 1; v <= 9; ++v) put(v);
        if (floating) {
          s += char(3);
          for (int k = 0; k < 3; ++k) Put(s, std::int32_t(k), be);
        } else {
          put(3);
          for (int k = 0; k < 3; ++k) put(k);
        }
      }
      const Result r = Read(s, MeshFormat::Ply);
      ASSERT_TRUE(r.ok) << r.error;
      ASSERT_EQ(3u, r.mesh.positions.size());
      EXPECT_EQ(8.0f, r.mesh.positions[2][1]);
      ASSERT_EQ(1u, r.mesh.triangles.size());
      EXPECT_EQ((std::array<int, 3>{{0, 1, 2}}), r.mesh.triangles[0]);
    }
  }
}

TEST(PlyReader, UnknownElementsAndPropertiesAreSkippedInAnyOrder) {
  // Face before vertex; a list property inside each; an unknown element with a list in between.
  for (const char* enc : {"ascii", "binary_little_endian"}) {
    SCOPED_TRACE(enc);
    std::string s = std::string("ply\nformat ") + enc +
                    " 1.0\nelement face 1\nproperty uchar flags\nproperty list uchar int vertex_index\n"
                    "property list ushort double texcoord\nelement edge 2\nproperty list uint short pair\n"
                    "property int weight\nelement vertex 3\nproperty list uchar float junk\nproperty double z\n"
                    "property float y\nproperty short extra\nproperty float x\nend_header\n";
    if (std::string(enc) == "ascii") {
      s += "7 3 2 1 0 2 0.5 0.25\n2 0 1 9\n3 1 2 3 -1\n0 3 2 1 5\n1 7 6 5 2 4\n2 8 9 11 12 0 7\n";
    } else {
      s += char(7);
      s += char(3);
      for (int i : {2, 1, 0}) Put(s, std::int32_t(i));
      Put(s, std::uint16_t(2));
      Put(s, 0.5);
      Put(s, 0.25);
      for (int e = 0; e < 2; ++e) {
        Put(s, std::uint32_t(2));
        Put(s, std::int16_t(0));
        Put(s, std::int16_t(1));
        Put(s, std::int32_t(9));
      }
      const float xyz[3][3] = {{1, 2, 3}, {5, 6, 7}, {9, 8, 0}};  // x y z of each vertex
      const int junk[3] = {0, 1, 2};
      for (int v = 0; v < 3; ++v) {
        s += char(junk[v]);
        for (int j = 0; j < junk[v]; ++j) Put(s, 1.5f);
        Put(s, double(xyz[v][2]));
        Put(s, xyz[v][1]);
        Put(s, std::int16_t(-4));
        Put(s, xyz[v][0]);
      }
    }
    const Result r = Read(s, MeshFormat::Ply);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(3u, r.mesh.positions.size());
    EXPECT_EQ(2u, r.mesh.skippedElements);
    ASSERT_EQ(1u, r.mesh.triangles.size());
    EXPECT_EQ((std::array<int, 3>{{2, 1, 0}}), r.mesh.triangles[0]);
    if (std::string(enc) != "ascii") {
      EXPECT_EQ(1.0f, r.mesh.positions[0][0]);
      EXPECT_EQ(6.0f, r.mesh.positions[1][1]);
      EXPECT_EQ(0.0f, r.mesh.positions[2][2]);
    } else {
      // ascii values: vertex 0 "0 3 2 1 5 1": no junk, z=3, y=2, extra=1, x=5
      EXPECT_EQ(5.0f, r.mesh.positions[0][0]);
      EXPECT_EQ(3.0f, r.mesh.positions[0][2]);
    }
  }
}

TEST(PlyReader, NormalsColoursAndQuality) {
  const std::string s =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nproperty uchar alpha\nproperty float quality\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0 1 10 20 30 40 0.5\n1 0 0 0 0 1 50 60 70 80 1.5\n0 1 0 0 0 1 255 0 1 2 -3\n3 0 1 2\n";
  const Result r = Read(s, MeshFormat::Ply);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(3u, r.mesh.normals.size());
  EXPECT_EQ(1.0f, r.mesh.normals[2][2]);
  ASSERT_EQ(3u, r.mesh.colors.size());
  EXPECT_EQ((std::array<std::uint8_t, 4>{{50, 60, 70, 80}}), r.mesh.colors[1]);
  ASSERT_EQ(3u, r.mesh.quality.size());
  EXPECT_EQ(-3.0f, r.mesh.quality[2]);
  // Float colours 0..1, no alpha.
  const std::string f =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "property float red\nproperty float green\nproperty float blue\nend_header\n0 0 0 1 0 0.5\n";
  const Result rf = Read(f, MeshFormat::Ply);
  ASSERT_TRUE(rf.ok) << rf.error;
  EXPECT_EQ((std::array<std::uint8_t, 4>{{255, 0, 128, 255}}), rf.mesh.colors[0]);
  EXPECT_TRUE(rf.mesh.normals.empty());
  EXPECT_TRUE(rf.mesh.quality.empty());
}

namespace {
// A PLY whose single face lists `corners` vertices of a fan of `corners` vertices.
std::string LongFacePly(bool ascii, std::uint32_t corners, std::uint32_t declared) {
  std::string s = std::string("ply\nformat ") + (ascii ? "ascii" : "binary_little_endian") + " 1.0\nelement vertex " +
                  std::to_string(corners) + "\n" + kPlyXyz + "element face 1\nproperty list uint int vertex_indices\nend_header\n";
  for (std::uint32_t i = 0; i < corners; ++i) {
    const float a = float(i) / float(corners) * 6.2831853f;
    if (ascii) s += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    else {
      Put(s, std::cos(a));
      Put(s, std::sin(a));
      Put(s, 0.0f);
    }
  }
  if (ascii) {
    s += std::to_string(declared);
    for (std::uint32_t i = 0; i < corners; ++i) s += " " + std::to_string(i);
    s += "\n";
  } else {
    Put(s, declared);
    for (std::uint32_t i = 0; i < corners; ++i) Put(s, std::int32_t(i));
  }
  return s;
}
}  // namespace

TEST(PlyReader, LongFaceListsAreTriangulatedUpToTheLimit) {
  for (bool ascii : {false, true}) {
    SCOPED_TRACE(ascii ? "ascii" : "binary");
    // vcglib's importer overflowed a fixed stack buffer from about 100 corners on.
    const Result r = Read(LongFacePly(ascii, 1000, 1000), MeshFormat::Ply);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(998u, r.mesh.triangles.size());
    EXPECT_EQ(1u, r.mesh.polygons);
    EXPECT_EQ((std::array<int, 3>{{0, 998, 999}}), r.mesh.triangles.back());
    // The limit.
    ReadLimits small;
    small.maxPolygonCorners = 999;
    const Result lim = Read(LongFacePly(ascii, 1000, 1000), MeshFormat::Ply, small);
    EXPECT_FALSE(lim.ok);
    EXPECT_NE(std::string::npos, lim.error.find("limit")) << lim.error;
    // A list longer than the file.
    const Result longer = Read(LongFacePly(ascii, 1000, 4000000000u), MeshFormat::Ply);
    EXPECT_FALSE(longer.ok);
    // A list shorter than declared runs into the end of the file.
    const Result shorter = Read(LongFacePly(ascii, 100, 101), MeshFormat::Ply);
    EXPECT_FALSE(shorter.ok);
  }
}

TEST(PlyReader, DegenerateFacesAreRefused) {
  for (int n : {0, 1, 2}) {
    std::string s = "ply\nformat ascii 1.0\nelement vertex 3\n" + std::string(kPlyXyz) +
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" +
                    std::to_string(n);
    for (int k = 0; k < n; ++k) s += " " + std::to_string(k);
    const Result r = Read(s + "\n", MeshFormat::Ply);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(std::string::npos, r.error.find("corners")) << r.error;
  }
}

TEST(PlyReader, EveryIndexIsChecked) {
  // The last index of a polygon was not checked by vcglib's importer.
  for (const char* bad : {"4 0 1 2 4", "4 0 1 2 -1", "3 4 0 1", "3 0 -5 1", "5 0 1 2 3 2147483647", "3 0 1 x"}) {
    SCOPED_TRACE(bad);
    const std::string s = "ply\nformat ascii 1.0\nelement vertex 4\n" + std::string(kPlyXyz) +
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" +
                          bad + "\n";
    const Result r = Read(s, MeshFormat::Ply);
    EXPECT_FALSE(r.ok);
  }
  // Binary, uint indices beyond int.
  std::string b = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + std::string(kPlyXyz) +
                  "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) Put(b, float(i));
  b += char(3);
  Put(b, std::uint32_t(0));
  Put(b, std::uint32_t(1));
  Put(b, std::uint32_t(0xffffffffu));
  const Result r = Read(b, MeshFormat::Ply);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(std::string::npos, r.error.find("4294967295")) << r.error;
}

TEST(PlyReader, HugeHeaderCountsFailFastWithoutAllocating) {
  const std::string headers[] = {
      "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\n" + std::string(kPlyXyz) +
          "element face 100000000\nproperty list uchar int vertex_indices\nend_header\n",
      "ply\nformat ascii 1.0\nelement vertex 100000000\n" + std::string(kPlyXyz) + "end_header\n0 0 0\n",
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\n" + std::string(kPlyXyz) +
          "element face 9223372036854775807\nproperty list uchar int vertex_indices\nend_header\n",
      "ply\nformat binary_little_endian 1.0\nelement vertex 18446744073709551615\n" + std::string(kPlyXyz) + "end_header\n",
      "ply\nformat binary_little_endian 1.0\nelement junk 4611686018427387903\nproperty list uint int stuff\nend_header\n",
  };
  for (const std::string& h : headers) {
    std::string s = h + std::string(40, '\0');
    gLargestAllocation = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const Result r = Read(s, MeshFormat::Ply);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_FALSE(r.ok);
    EXPECT_LT(gLargestAllocation.load(), std::size_t(1) << 16) << "nothing near the declared size is allocated";
    EXPECT_LT(seconds, 1.0);
  }
  // Elements without properties take no room: a huge count of them is read at once.
  const Result none = Read("ply\nformat binary_little_endian 1.0\nelement nothing 4611686018427387903\nelement vertex 0\n" +
                               std::string(kPlyXyz) + "end_header\n",
                           MeshFormat::Ply);
  EXPECT_TRUE(none.ok) << none.error;
}

// Found by the mutation campaign: a header keyword holding byte 0x1d (which Python and some
// terminals take as a line break) was quoted as it was; every reason is printable ASCII, one line.
TEST(Readers, ReasonsQuoteTheFilesBytesPrintably) {
  const std::vector<std::pair<std::string, MeshFormat>> files = {
      {std::string("ply\nformat ascii 1.0\ne\xd3\x1d\xcb\xa9 vertex 3\nend_header\n"), MeshFormat::Ply},
      {std::string("ply\nformat ascii 1.0\nelement vertex 1\nproperty fl\x1boat x\nend_header\n"), MeshFormat::Ply},
      {std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \x07\x1d\n"), MeshFormat::Obj},
      {std::string("OFF\n3 1 0\n0 0 \x1b[31m\n1 0 0\n0 1 0\n3 0 1 2\n"), MeshFormat::Off},
      {std::string("solid x\nfacet \x1dnormal 0 0 1\n"), MeshFormat::Stl}};
  for (const auto& f : files) {
    const Result r = Read(f.first, f.second);
    ASSERT_FALSE(r.ok);
    for (char c : r.error)
      EXPECT_TRUE(static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) <= 126) << r.error;
  }
}

TEST(PlyReader, TruncatedBinaryFilesFail) {
  const std::string full = TetraPly("binary_little_endian");
  ASSERT_TRUE(Read(full, MeshFormat::Ply).ok);
  for (std::size_t n = 0; n < full.size(); ++n) {
    const Result r = Read(full.substr(0, n), MeshFormat::Ply);
    EXPECT_FALSE(r.ok) << n;
  }
  const std::string ascii = TetraPly("ascii");
  const Result r = Read(ascii.substr(0, ascii.size() - 4), MeshFormat::Ply);
  EXPECT_FALSE(r.ok);
}

TEST(PlyReader, HeaderErrors) {
  for (const std::string& s : {std::string("plyx\n"), std::string("ply\nformat ascii 1.0\n"),
                               std::string("ply\nelement vertex 0\nend_header\n"),
                               std::string("ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
                               std::string("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n"),
                               std::string("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"),
                               std::string("ply\nformat utf8 1.0\nend_header\n"),
                               std::string("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n"),
                               std::string("ply\nformat ascii 1.0\nelement vertex 0\n") + kPlyXyz +
                                   "element face 1\nproperty list float int vertex_indices\nend_header\n3 0 0 0\n",
                               std::string("ply\nformat ascii 1.0\nelement vertex 0\n") + kPlyXyz +
                                   "element face 1\nproperty uchar vertex_indices\nend_header\n3\n",
                               std::string("ply\nformat ascii 1.0\nelement vertex 1\n") + kPlyXyz + "end_header\n0 0 0 7\n"}) {
    const Result r = Read(s, MeshFormat::Ply);
    EXPECT_FALSE(r.ok) << s;
  }
}

TEST(PlyReader, TristripsAsMeshLabReadsThem) {
  std::string s = "ply\nformat ascii 1.0\nelement vertex 6\n" + std::string(kPlyXyz) +
                  "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 2 0\n1 2 0\n"
                  "9 0 1 2 3 -1 2 3 4 5\n";
  const Result r = Read(s, MeshFormat::Ply);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<std::array<int, 3>> expect = {{{0, 1, 2}}, {{2, 1, 3}}, {{2, 3, 4}}, {{4, 3, 5}}};
  EXPECT_EQ(expect, r.mesh.triangles);
  const Result bad = Read("ply\nformat ascii 1.0\nelement vertex 3\n" + std::string(kPlyXyz) +
                              "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                              "4 0 1 2 3\n",
                          MeshFormat::Ply);
  EXPECT_FALSE(bad.ok);
}

TEST(PlyReader, AsciiFloatsComeBackBitIdentical) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> bits;
  std::vector<float> values;
  while (values.size() < 3000) {
    const std::uint32_t u = bits(rng);
    float f;
    std::memcpy(&f, &u, 4);
    if (std::isfinite(f)) values.push_back(f);
  }
  const std::size_t nv = values.size() / 3;
  std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(nv) + "\n" + kPlyXyz + "end_header\n";
  std::string obj, off = "OFF\n" + std::to_string(nv) + " 0 0\n", stl = "solid t\n";
  char buf[64];
  for (std::size_t i = 0; i < nv; ++i) {
    std::string line;
    for (int k = 0; k < 3; ++k) {
      std::snprintf(buf, sizeof buf, "%.9g", double(values[3 * i + k]));
      line += (k ? " " : "") + std::string(buf);
    }
    ply += line + "\n";
    obj += "v " + line + "\n";
    off += line + "\n";
  }
  for (std::size_t i = 0; i + 2 < nv; i += 3) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      stl += "vertex";
      for (int j = 0; j < 3; ++j) {
        std::snprintf(buf, sizeof buf, " %.9g", double(values[3 * (i + k) + j]));
        stl += buf;
      }
      stl += "\n";
    }
    stl += "endloop\nendfacet\n";
  }
  stl += "endsolid t\n";
  const std::pair<std::string, MeshFormat> files[] = {
      {ply, MeshFormat::Ply}, {obj, MeshFormat::Obj}, {off, MeshFormat::Off}, {stl, MeshFormat::Stl}};
  for (const auto& f : files) {
    const Result r = Read(f.first, f.second);
    ASSERT_TRUE(r.ok) << r.error;
    const std::size_t n = f.second == MeshFormat::Stl ? nv / 3 * 3 : nv;
    ASSERT_EQ(n, r.mesh.positions.size());
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(0, std::memcmp(&values[3 * i + k], &r.mesh.positions[i][k], 4)) << i;
  }
}

TEST(PlyReader, NanInfAndHexTextDoNotCrash) {
  const std::string s = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty double y\nproperty float z\n"
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                        "nan inf -inf\n0x1p3 1e999 -1e-999\nNAN(123) INFINITY 1e-45\n3 0 1 2\n";
  const Result r = Read(s, MeshFormat::Ply);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(std::isnan(r.mesh.positions[0][0]));
  EXPECT_TRUE(std::isinf(r.mesh.positions[0][1]));
  EXPECT_EQ(8.0f, r.mesh.positions[1][0]);
  EXPECT_TRUE(std::isinf(r.mesh.positions[1][1]));
  // Not numbers at all.
  for (const char* bad : {"1.5.5 0 0", "0x 0 0", "- 0 0", "1e 0 0", "nanx 0 0"}) {
    const Result b = Read("ply\nformat ascii 1.0\nelement vertex 1\n" + std::string(kPlyXyz) + "end_header\n" + bad + "\n",
                          MeshFormat::Ply);
    EXPECT_FALSE(b.ok) << bad;
  }
}

// ---- OBJ ----------------------------------------------------------------------------------

TEST(ObjReader, EveryFaceIsKeptIncludingThoseOnTheFirstVertex) {
  // vcglib's importer loaded this tetrahedron as one face.
  const Result r = Read("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", MeshFormat::Obj);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(4u, r.mesh.positions.size());
  ASSERT_EQ(4u, r.mesh.triangles.size());
  EXPECT_EQ((std::array<int, 3>{{0, 2, 1}}), r.mesh.triangles[0]);
  EXPECT_EQ((std::array<int, 3>{{1, 2, 3}}), r.mesh.triangles[3]);
}

TEST(ObjReader, RelativeAndSlashedIndices) {
  const Result r = Read("# comment\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nvt 0 0\nvn 0 0 1\n"
                        "v 1 1 0 # trailing comment\nf 2/1/1 4/1/1 3/1/1\nf 1//1 2//1 -1//1\nusemtl m\ns off\nf 1/1 2/1 3/1\n"
                        "l 1 2\n",
                        MeshFormat::Obj);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<std::array<int, 3>> expect = {{{0, 1, 2}}, {{1, 3, 2}}, {{0, 1, 3}}, {{0, 1, 2}}};
  EXPECT_EQ(expect, r.mesh.triangles);
  EXPECT_EQ(1u, r.mesh.skippedElements);
}

TEST(ObjReader, BadIndicesAreRefused) {
  for (const char* f : {"f -2147483648 1 2", "f 1 2 -2147483649", "f 2147483648 1 2", "f 1 2 99999999999999999999999",
                        "f 0 1 2", "f 1 2 4", "f 1 2 -4", "f 1 2 x", "f /1 2 3", "f 1 2", "f 1", "f",
                        "f 1 2 3 100", "f 1 2 3 -9", "f 1 2 3 0 1"}) {
    SCOPED_TRACE(f);
    const Result r = Read(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + f + "\n", MeshFormat::Obj);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(std::string::npos, r.error.find("line 4")) << r.error;
  }
  // A forward reference is fine when the vertex comes later.
  EXPECT_TRUE(Read("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", MeshFormat::Obj).ok);
}

TEST(ObjReader, PolygonsAreFanTriangulated) {
  const Result r = Read("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 1 0\nf 1 2 3 4 5\n", MeshFormat::Obj);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<std::array<int, 3>> expect = {{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 4}}};
  EXPECT_EQ(expect, r.mesh.triangles);
  EXPECT_EQ(1u, r.mesh.polygons);
}

TEST(ObjReader, NumbersAndColours) {
  const Result r = Read("v nan inf -inf\nv 0x10 1e999 3\nv 1 2 3 1 0.5 0\n", MeshFormat::Obj);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(std::isnan(r.mesh.positions[0][0]));
  EXPECT_EQ(16.0f, r.mesh.positions[1][0]);
  ASSERT_EQ(3u, r.mesh.colors.size());
  EXPECT_EQ((std::array<std::uint8_t, 4>{{255, 128, 0, 255}}), r.mesh.colors[2]);
  EXPECT_FALSE(Read("v 1 2\n", MeshFormat::Obj).ok);
  EXPECT_FALSE(Read("v 1 2 three\n", MeshFormat::Obj).ok);
}

TEST(ObjReader, ShippedObjMeshesLoadWithEveryFace) {
  std::vector<std::string> files = FilesIn(NVV_SAMPLE_MESHES, ".obj");
  const std::vector<std::string> shared = FilesIn(std::string(NVV_SHARED_MESHES) + "/real", ".obj");
  files.insert(files.end(), shared.begin(), shared.end());
  if (files.empty())
    GTEST_SKIP() << "no OBJ meshes: neither the sample meshes nor the shared meshes at " << NVV_SHARED_MESHES << " have any";
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    const Result r = ReadPath(f);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(CountFaceTriangles(f), r.mesh.triangles.size());
  }
}

// ---- OFF ----------------------------------------------------------------------------------

TEST(OffReader, Variants) {
  const Result plain = Read("# a comment\nOFF\n# another\n4 2 5\n0 0 0\n1 0 0 # here\n1 1 0\n\n0 1 0\n3 0 1 2\n4 0 1 2 3 255 0 0\n",
                            MeshFormat::Off);
  ASSERT_TRUE(plain.ok) << plain.error;
  EXPECT_EQ(4u, plain.mesh.positions.size());
  EXPECT_EQ(3u, plain.mesh.triangles.size());
  EXPECT_EQ(1u, plain.mesh.polygons);
  const Result same = Read("OFF 3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n", MeshFormat::Off);
  ASSERT_TRUE(same.ok) << same.error;
  EXPECT_EQ(1u, same.mesh.triangles.size());
  const Result coff = Read("COFF\n2 0 0\n0 0 0 255 0 0 255\n1 0 0 0.0 1.0 0.0 1.0\n", MeshFormat::Off);
  ASSERT_TRUE(coff.ok) << coff.error;
  ASSERT_EQ(2u, coff.mesh.colors.size());
  EXPECT_EQ((std::array<std::uint8_t, 4>{{255, 0, 0, 255}}), coff.mesh.colors[0]);
  EXPECT_EQ((std::array<std::uint8_t, 4>{{0, 255, 0, 255}}), coff.mesh.colors[1]);
  const Result noff = Read("NOFF\n1 0 0\n0 0 0 0 0 1\n", MeshFormat::Off);
  ASSERT_TRUE(noff.ok) << noff.error;
  ASSERT_EQ(1u, noff.mesh.normals.size());
  EXPECT_EQ(1.0f, noff.mesh.normals[0][2]);
  const Result cnoff = Read("CNOFF\n1 0 0\n0 0 0 0 1 0 10 20 30\n", MeshFormat::Off);
  ASSERT_TRUE(cnoff.ok) << cnoff.error;
  EXPECT_EQ(1.0f, cnoff.mesh.normals[0][1]);
  EXPECT_EQ((std::array<std::uint8_t, 4>{{10, 20, 30, 255}}), cnoff.mesh.colors[0]);
  for (const char* bad : {"4OFF\n0 0 0\n", "nOFF\n4\n0 0 0\n", "XOFF\n0 0 0\n", "OFX\n0 0 0\n", "OFF\n1\n0 0 0\n",
                          "OFF\n-1 0 0\n", "OFF\n1 0 0\n0 0\n", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
                          "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
                          "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2147483648\n"}) {
    const Result r = Read(bad, MeshFormat::Off);
    EXPECT_FALSE(r.ok) << bad;
  }
}

TEST(OffReader, PolygonCoordinatesAreNotReadBeforeTheIndicesAreChecked) {
  // vcglib's importer read the coordinates of a polygon's corners before checking the indices.
  const Result r = Read("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n5 0 1 2 100000000 -7\n", MeshFormat::Off);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(std::string::npos, r.error.find("100000000")) << r.error;
}

TEST(OffReader, HugeCountsFailFast) {
  gLargestAllocation = 0;
  const Result r = Read("OFF\n100000000 100000000 0\n0 0 0\n", MeshFormat::Off);
  EXPECT_FALSE(r.ok);
  EXPECT_LT(gLargestAllocation.load(), std::size_t(1) << 16);
  EXPECT_FALSE(Read("OFF\n3 1000000000000000000000 0\n0 0 0\n", MeshFormat::Off).ok);
}

// ---- STL ----------------------------------------------------------------------------------

namespace {
std::string BinaryStl(std::uint32_t declared, std::uint32_t facets, const std::string& header = std::string(80, ' ')) {
  std::string s = header;
  Put(s, declared);
  for (std::uint32_t f = 0; f < facets; ++f) {
    for (int k = 0; k < 12; ++k) Put(s, float(k == 0 ? 0 : (k / 3 == 1 + int(f % 3)) ? f + k : k));
    s += std::string(2, '\0');
  }
  return s;
}
}  // namespace

TEST(StlReader, BinaryAndAscii) {
  const Result b = Read(BinaryStl(3, 3), MeshFormat::Stl);
  ASSERT_TRUE(b.ok) << b.error;
  EXPECT_EQ(9u, b.mesh.positions.size());
  EXPECT_EQ(3u, b.mesh.triangles.size());
  EXPECT_EQ((std::array<int, 3>{{6, 7, 8}}), b.mesh.triangles[2]);
  // A binary STL whose header starts with "solid", as many exporters write it.
  const Result bs = Read(BinaryStl(2, 2, "solid" + std::string(75, ' ')), MeshFormat::Stl);
  ASSERT_TRUE(bs.ok) << bs.error;
  EXPECT_EQ(2u, bs.mesh.triangles.size());
  const Result a = Read("solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
                        "  endloop\n endfacet\nendsolid x\nsolid y\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n"
                        "vertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n",
                        MeshFormat::Stl);
  ASSERT_TRUE(a.ok) << a.error;
  EXPECT_EQ(7u, a.mesh.positions.size());
  EXPECT_EQ(3u, a.mesh.triangles.size());
  EXPECT_EQ(1u, a.mesh.polygons);
}

TEST(StlReader, TruncatedAndMalformed) {
  const std::string full = BinaryStl(4, 4);
  for (std::size_t n = 0; n < full.size(); ++n) {
    const Result r = Read(full.substr(0, n), MeshFormat::Stl);
    EXPECT_FALSE(r.ok) << n;
  }
  gLargestAllocation = 0;
  const Result huge = Read(BinaryStl(100000000, 1), MeshFormat::Stl);
  EXPECT_FALSE(huge.ok);
  EXPECT_NE(std::string::npos, huge.error.find("truncated")) << huge.error;
  EXPECT_LT(gLargestAllocation.load(), std::size_t(1) << 16);
  for (const char* bad : {"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n",
                          "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1",
                          "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 nan\nvertex 0 1 q\n",
                          "solid x\nfacet\n", "solid x\nbanana\n", "not an stl at all"}) {
    const Result r = Read(bad, MeshFormat::Stl);
    EXPECT_FALSE(r.ok) << bad;
  }
}

// ---- files --------------------------------------------------------------------------------

TEST(MeshFiles, ZeroByteFilesOfEveryFormatFail) {
  TempDir dir;
  for (const char* name : {"empty.ply", "empty.obj", "empty.off", "empty.stl"}) {
    const Result r = ReadPath(dir.Write(name, ""));
    EXPECT_FALSE(r.ok) << name;
    EXPECT_NE(std::string::npos, r.error.find("empty")) << r.error;
  }
}

TEST(MeshFiles, FifoIsRefusedAtOnce) {
  TempDir dir;
  const std::string fifo = dir.File("pipe.ply");
  ASSERT_EQ(0, ::mkfifo(fifo.c_str(), 0600));
  const auto t0 = std::chrono::steady_clock::now();
  const Result r = ReadPath(fifo);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(std::string::npos, r.error.find("FIFO")) << r.error;
}

TEST(MeshFiles, DirectoriesAndDevicesAreRefused) {
  TempDir dir;
  const std::string sub = dir.File("folder.obj");
  ASSERT_EQ(0, ::mkdir(sub.c_str(), 0700));
  const Result d = ReadPath(sub);
  EXPECT_FALSE(d.ok);
  EXPECT_NE(std::string::npos, d.error.find("directory")) << d.error;
  ::rmdir(sub.c_str());
  // /dev/zero under a mesh name: it would never end.
  const std::string zero = dir.File("zero.stl");
  ASSERT_EQ(0, ::symlink("/dev/zero", zero.c_str()));
  const Result z = ReadPath(zero);
  EXPECT_FALSE(z.ok);
  EXPECT_NE(std::string::npos, z.error.find("device")) << z.error;
  const Result missing = ReadPath(dir.Path() + "/missing.off");
  EXPECT_FALSE(missing.ok);
  EXPECT_NE(std::string::npos, missing.error.find("cannot open")) << missing.error;
}

TEST(MeshFiles, FormatFromTheExtensionInAnyCase) {
  MeshFormat f;
  ASSERT_TRUE(nvv::io::FormatFromPath("a/b.PLY", f));
  EXPECT_EQ(MeshFormat::Ply, f);
  ASSERT_TRUE(nvv::io::FormatFromPath("x.Obj", f));
  EXPECT_EQ(MeshFormat::Obj, f);
  ASSERT_TRUE(nvv::io::FormatFromPath("x.off", f));
  EXPECT_EQ(MeshFormat::Off, f);
  ASSERT_TRUE(nvv::io::FormatFromPath("x.sTl", f));
  EXPECT_EQ(MeshFormat::Stl, f);
  EXPECT_FALSE(nvv::io::FormatFromPath("x.xyz", f));
  EXPECT_FALSE(nvv::io::FormatFromPath("dir.ply/file", f));
  EXPECT_FALSE(nvv::io::FormatFromPath("noext", f));
}

TEST(MeshFiles, SampleMeshesLoad) {
  const std::vector<std::string> files = FilesIn(NVV_SAMPLE_MESHES, ".ply");
  ASSERT_FALSE(files.empty());
  for (const std::string& f : files) {
    const Result r = ReadPath(f);
    ASSERT_TRUE(r.ok) << f << ": " << r.error;
    EXPECT_GT(r.mesh.triangles.size(), 0u) << f;
  }
}
