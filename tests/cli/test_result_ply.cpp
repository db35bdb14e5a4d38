// The full-result PLY: written binary and ascii, read back float-exactly; deleted elements
// skipped; meshes without optional components; what vcglib's importer (MeshLab's) reads; bad
// files refused.
#include "cli_test_support.h"

using namespace nvv_cli_test;

namespace {

// Core + ApplyResults on the sample, with a selection so nvv_selected is not all zero.
struct Computed {
  Mesh m;
  std::vector<nvv::VertexResult> res;
};
void Compute(Computed& c) {
  SampleMesh(c.m);
  vcg::tri::UpdateNormal<Mesh>::PerVertexAngleWeighted(c.m);
  vcg::tri::UpdateNormal<Mesh>::NormalizePerVertex(c.m);
  nvv::FilterOptions o = nvv::DefaultOptions();
  o.selection = nvv::SelectionMode::CreasesAndCorners;
  nvv::Summary sum;
  ASSERT_TRUE(vcg::tri::NormalVectorVoting<Mesh>::Compute(c.m, o.core, c.res, sum).ok);
  nvv::ApplyResults<Mesh>::Apply(c.m, c.res, o);
}

std::vector<std::array<int, 3>> FacesOf(const Mesh& m) {
  std::vector<int> index(m.vert.size(), -1);
  int n = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) index[i] = n++;
  std::vector<std::array<int, 3>> f;
  for (const auto& face : m.face) {
    if (face.IsD()) continue;
    std::array<int, 3> t;
    for (int j = 0; j < 3; ++j) t[j] = index[vcg::tri::Index(m, face.cV(j))];
    f.push_back(t);
  }
  return f;
}

// A mesh with positions and flags only: no normal, colour, quality or curvature directions.
class BareVertex;
class BareFace;
struct BareTypes : public vcg::UsedTypes<vcg::Use<BareVertex>::AsVertexType, vcg::Use<BareFace>::AsFaceType> {};
class BareVertex : public vcg::Vertex<BareTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags> {};
class BareFace : public vcg::Face<BareTypes, vcg::face::VertexRef, vcg::face::BitFlags> {};
class BareMesh : public vcg::tri::TriMesh<std::vector<BareVertex>, std::vector<BareFace>> {
 public:
  ~BareMesh() { ClearAttributes(); }  // vcglib's destructor leaves attributes allocated
};

}  // namespace

TEST(ResultPly, BinaryAndAsciiRoundTripIsFloatExact) {
  Computed c;
  Compute(c);
  TempDir dir;
  const std::vector<nvv::ResultPlyVertex> expected = RecordsOf(c.m, c.res);
  std::size_t selected = 0, curved = 0, creases = 0;
  for (const auto& v : expected) {
    selected += v.selected;
    curved += (v.flags & nvv::kCurvatureValid) != 0 && v.k1 != v.k2;
    creases += v.cls == 1;
  }
  ASSERT_GT(selected, 0u);
  ASSERT_GT(curved, 0u);
  ASSERT_GT(creases, 0u);
  for (bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    const std::string path = dir.File(binary ? "b.ply" : "a.ply");
    std::string error;
    ASSERT_TRUE(nvv::WriteResultPly(path, c.m, c.res, binary, {"first comment", "second\ncomment"}, error)) << error;
    nvv::ResultPlyData back;
    ASSERT_TRUE(nvv::ReadResultPly(path, back, error)) << error;
    EXPECT_EQ(binary, back.binary);
    EXPECT_TRUE(SameRecords(expected, back.vertices));
    EXPECT_EQ(FacesOf(c.m), back.faces);
    ASSERT_EQ(3u, back.comments.size());
    EXPECT_EQ("Normal Vector Voting results (nvv_format 1)", back.comments[0]);
    EXPECT_EQ("first comment", back.comments[1]);
    EXPECT_EQ("second comment", back.comments[2]);
    for (const auto& v : back.vertices) EXPECT_GE(v.k1, v.k2);
  }
}

TEST(ResultPly, RecordHoldsTheResultAndTheAppliedMeshValues) {
  Computed c;
  Compute(c);
  for (std::size_t i = 0; i < c.m.vert.size(); ++i) {
    const auto& v = c.m.vert[i];
    const nvv::VertexResult& r = c.res[i];
    const nvv::ResultPlyVertex o = nvv::MakeResultPlyVertex(c.m, i, r);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(v.cP()[j], o.position[j]);
      EXPECT_EQ(v.cN()[j], o.normal[j]);
      EXPECT_EQ(v.cPD1()[j], o.pd1[j]);
      EXPECT_EQ(v.cPD2()[j], o.pd2[j]);
      EXPECT_EQ(r.lambda[j], o.lambda[j]);
    }
    EXPECT_EQ(v.cK1(), o.k1);
    EXPECT_EQ(v.cK2(), o.k2);
    EXPECT_EQ(v.cQ(), o.quality);
    for (int j = 0; j < 4; ++j) EXPECT_EQ(v.cC()[j], o.color[j]);
    EXPECT_EQ(int(r.cls), int(o.cls));
    EXPECT_EQ(r.flags, o.flags);
    EXPECT_EQ(v.IsS() ? 1 : 0, int(o.selected));
    if (r.Has(nvv::kCreaseValid)) {
      EXPECT_FLOAT_EQ(float(nvv::RadToDeg(r.cuspAngle)), o.cuspAngleDeg);
      EXPECT_EQ(r.creaseCurvature, o.creaseCurvature);
      EXPECT_EQ(r.creaseTangent[0], o.creaseTangent[0]);
    } else {
      EXPECT_EQ(0.0f, o.cuspAngleDeg);
      EXPECT_EQ(0.0f, o.creaseTangent[0]);
    }
  }
}

TEST(ResultPly, DeletedVerticesAndFacesAreSkippedAndRenumbered) {
  Computed c;
  Compute(c);
  // Delete every 7th vertex with its faces, and a few more faces.
  for (std::size_t i = 0; i < c.m.vert.size(); i += 7) vcg::tri::Allocator<Mesh>::DeleteVertex(c.m, c.m.vert[i]);
  for (std::size_t f = 0; f < c.m.face.size(); ++f) {
    auto& face = c.m.face[f];
    if (face.IsD()) continue;
    if (face.V(0)->IsD() || face.V(1)->IsD() || face.V(2)->IsD() || f % 11 == 0)
      vcg::tri::Allocator<Mesh>::DeleteFace(c.m, face);
  }
  TempDir dir;
  std::string error;
  ASSERT_TRUE(nvv::WriteResultPly(dir.File("d.ply"), c.m, c.res, true, error)) << error;
  nvv::ResultPlyData back;
  ASSERT_TRUE(nvv::ReadResultPly(dir.File("d.ply"), back, error)) << error;
  EXPECT_EQ(std::size_t(c.m.vn), back.vertices.size());
  EXPECT_EQ(std::size_t(c.m.fn), back.faces.size());
  EXPECT_TRUE(SameRecords(RecordsOf(c.m, c.res), back.vertices));
  const auto faces = FacesOf(c.m);
  EXPECT_EQ(faces, back.faces);
  // The renumbered faces still join the same positions.
  std::size_t k = 0;
  for (const auto& face : c.m.face) {
    if (face.IsD()) continue;
    for (int j = 0; j < 3; ++j) EXPECT_EQ(face.cP(j)[0], back.vertices[back.faces[k][j]].position[0]);
    ++k;
  }
}

TEST(ResultPly, MeshWithoutNormalColourQualityWritesTheRecordsValues) {
  BareMesh m;
  nvv_shapes::Cube(m, 1.0, 8);
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  ASSERT_TRUE(vcg::tri::NormalVectorVoting<BareMesh>::Compute(m, nvv::Params(), res, sum).ok);
  TempDir dir;
  std::string error;
  ASSERT_TRUE(nvv::WriteResultPly(dir.File("bare.ply"), m, res, false, error)) << error;
  nvv::ResultPlyData back;
  ASSERT_TRUE(nvv::ReadResultPly(dir.File("bare.ply"), back, error)) << error;
  ASSERT_EQ(m.vert.size(), back.vertices.size());
  for (std::size_t i = 0; i < res.size(); ++i) {
    const auto& o = back.vertices[i];
    const vcg::Color4b cc = nvv::ClassColor(res[i].cls);
    for (int j = 0; j < 4; ++j) EXPECT_EQ(cc[j], o.color[j]);
    for (int j = 0; j < 3; ++j) EXPECT_EQ(res[i].Has(nvv::kNormalValid) ? res[i].normal[j] : 0.0f, o.normal[j]);
    bool valid;
    EXPECT_EQ(float(nvv::QualityValue(res[i], nvv::QualityMode::MeanCurvature, valid)), o.quality);
    EXPECT_EQ(0, o.selected);
  }
}

// MeshLab opens PLY files with vcglib's ImporterPLY: it must read positions, normals, colours,
// quality and faces as written.
TEST(ResultPly, VcglibImporterReadsTheStandardProperties) {
  Computed c;
  Compute(c);
  TempDir dir;
  for (bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    std::string error;
    ASSERT_TRUE(nvv::WriteResultPly(dir.File("v.ply"), c.m, c.res, binary, error)) << error;
    Mesh back;
    int mask = 0;
    ASSERT_EQ(0, vcg::tri::io::ImporterPLY<Mesh>::Open(back, dir.File("v.ply").c_str(), mask));
    namespace M = vcg::tri::io;
    EXPECT_TRUE(mask & M::Mask::IOM_VERTNORMAL);
    EXPECT_TRUE(mask & M::Mask::IOM_VERTCOLOR);
    EXPECT_TRUE(mask & M::Mask::IOM_VERTQUALITY);
    ASSERT_EQ(c.m.vert.size(), back.vert.size());
    ASSERT_EQ(c.m.face.size(), back.face.size());
    for (std::size_t i = 0; i < back.vert.size(); ++i) {
      EXPECT_EQ(c.m.vert[i].cP(), back.vert[i].cP());
      EXPECT_EQ(c.m.vert[i].cN(), back.vert[i].cN());
      EXPECT_EQ(c.m.vert[i].cC(), back.vert[i].cC());
      EXPECT_EQ(c.m.vert[i].cQ(), back.vert[i].cQ());
    }
    for (std::size_t f = 0; f < back.face.size(); ++f)
      for (int j = 0; j < 3; ++j)
        EXPECT_EQ(vcg::tri::Index(c.m, c.m.face[f].cV(j)), vcg::tri::Index(back, back.face[f].cV(j)));
  }
}

TEST(ResultPly, ReaderRefusesBrokenFiles) {
  Computed c;
  Compute(c);
  TempDir dir;
  std::string error;
  ASSERT_TRUE(nvv::WriteResultPly(dir.File("ok.ply"), c.m, c.res, true, error)) << error;
  const std::string good = ReadText(dir.File("ok.ply"));
  nvv::ResultPlyData back;
  auto refuses = [&](const std::string& name, const std::string& text) {
    WriteText(dir.File(name), text);
    error.clear();
    const bool ok = nvv::ReadResultPly(dir.File(name), back, error);
    EXPECT_FALSE(ok) << name;
    EXPECT_FALSE(error.empty()) << name;
  };
  refuses("truncated.ply", good.substr(0, good.size() - 5));
  refuses("not_ply.ply", "hello\n");
  refuses("no_header_end.ply", "ply\nformat ascii 1.0\nelement vertex 0\n");
  refuses("big_endian.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 0\nend_header\n");
  refuses("missing_property.ply",
          "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n");
  EXPECT_FALSE(nvv::ReadResultPly(dir.File("missing.ply"), back, error));
  // A quad face in an otherwise valid ascii file.
  ASSERT_TRUE(nvv::WriteResultPly(dir.File("a.ply"), c.m, c.res, false, error)) << error;
  std::string ascii = ReadText(dir.File("a.ply"));
  const std::size_t lastFace = ascii.rfind("\n3 ", ascii.size() - 2);
  ASSERT_NE(std::string::npos, lastFace);
  refuses("quad.ply", ascii.substr(0, lastFace) + "\n4 0 1 2 3\n");
  refuses("bad_index.ply", ascii.substr(0, lastFace) + "\n3 0 1 99999999\n");
}

TEST(ResultPly, WriteFailureIsReportedAndLeavesNoFile) {
  Computed c;
  Compute(c);
  std::string error;
  EXPECT_FALSE(nvv::WriteResultPly("/nonexistent_nvv_dir/out.ply", c.m, c.res, true, error));
  EXPECT_NE(std::string::npos, error.find("/nonexistent_nvv_dir/out.ply")) << error;
  std::vector<nvv::VertexResult> wrongSize(c.res.begin(), c.res.end() - 1);
  TempDir dir;
  error.clear();
  EXPECT_FALSE(nvv::WriteResultPly(dir.File("w.ply"), c.m, wrongSize, true, error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(Exists(dir.File("w.ply")));
}

// The crease network's faces are mapped from the graph back to the mesh's slots past deleted
// vertices and faces, a face on a repeated vertex and a repeated face (both skipped by the
// filter, so in no patch), and its edges renumbered with the vertices, in both encodings; vcglib's
// importer still reads the file's standard part.
TEST(ResultPly, CreaseNetworkFollowsTheMeshsSlots) {
  Mesh m;
  SampleMesh(m);
  for (std::size_t i = 5; i < m.vert.size(); i += 13) vcg::tri::Allocator<Mesh>::DeleteVertex(m, m.vert[i]);
  for (auto& face : m.face)
    if (face.V(0)->IsD() || face.V(1)->IsD() || face.V(2)->IsD()) vcg::tri::Allocator<Mesh>::DeleteFace(m, face);
  std::size_t live = 0;
  while (m.face[live].IsD()) ++live;
  Mesh::VertexPointer a = m.face[live].V(0), b = m.face[live].V(1), c = m.face[live].V(2);
  const std::size_t repeatedVertex = m.face.size(), repeatedFace = m.face.size() + 1;
  vcg::tri::Allocator<Mesh>::AddFace(m, a, a, b);
  vcg::tri::Allocator<Mesh>::AddFace(m, b, c, a);  // the first live face again, rotated
  vcg::tri::UpdateNormal<Mesh>::PerVertexAngleWeighted(m);
  vcg::tri::UpdateNormal<Mesh>::NormalizePerVertex(m);
  const nvv::FilterOptions o = nvv::DefaultOptions();
  std::vector<nvv::VertexResult> res;
  nvv::Summary sum;
  nvv::SurfaceGraph g;
  ASSERT_TRUE(vcg::tri::NormalVectorVoting<Mesh>::Compute(m, o.core, res, sum, g).ok);
  const std::vector<int> slot = nvv::GraphFaceSlots(m, g);
  for (int f = 0; f < g.FaceCount(); ++f) {
    ASSERT_GE(slot[f], 0);
    for (int j = 0; j < 3; ++j) EXPECT_EQ(g.face[f][j], int(vcg::tri::Index(m, m.face[slot[f]].cV(j))));
  }
  const nvv::CreaseOutputs crease = nvv::FindCreaseOutputs(m, g, res, sum, o.core.creaseAngleDeg);
  EXPECT_EQ(-1, crease.meshFacePatch[repeatedVertex]);
  EXPECT_EQ(-1, crease.meshFacePatch[repeatedFace]);
  EXPECT_GE(crease.meshFacePatch[live], 0);
  ASSERT_GT(crease.net.edges.size(), 0u);
  nvv::ApplyResults<Mesh>::Apply(m, res, o, &crease);
  std::vector<int> newIndex(m.vert.size(), -1);
  int n = 0;
  for (std::size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) newIndex[i] = n++;
  std::vector<int> livePatch;
  for (std::size_t s = 0; s < m.face.size(); ++s)
    if (!m.face[s].IsD()) livePatch.push_back(crease.meshFacePatch[s]);
  TempDir dir;
  for (bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    std::string error;
    ASSERT_TRUE(nvv::WriteResultPly(dir.File("n.ply"), m, res, binary, {}, error, &crease)) << error;
    nvv::ResultPlyData back;
    ASSERT_TRUE(nvv::ReadResultPly(dir.File("n.ply"), back, error)) << error;
    EXPECT_EQ(livePatch, back.facePatch);
    ASSERT_EQ(crease.net.edges.size(), back.edges.size());
    for (std::size_t e = 0; e < back.edges.size(); ++e) {
      EXPECT_EQ(newIndex[crease.net.edges[e][0]], back.edges[e].vertex[0]);
      EXPECT_EQ(newIndex[crease.net.edges[e][1]], back.edges[e].vertex[1]);
      EXPECT_EQ(crease.net.edgeCuspAngle[e], back.edges[e].cuspAngle);
      EXPECT_EQ(crease.net.edgeLine[e], back.edges[e].line);
    }
    Mesh standard;
    int mask = 0;
    ASSERT_EQ(0, vcg::tri::io::ImporterPLY<Mesh>::Open(standard, dir.File("n.ply").c_str(), mask));
    EXPECT_EQ(std::size_t(m.fn), standard.face.size());
  }
  // The crease edges are the faces' edge selection, on both faces of each (one where a gap is
  // closed along the border).
  std::size_t selected = 0;
  for (const auto& face : m.face)
    for (int j = 0; j < 3 && !face.IsD(); ++j) selected += face.IsFaceEdgeS(j);
  EXPECT_LE(selected, 2 * crease.net.edges.size());
  EXPECT_GE(selected, 2 * crease.net.edges.size() - crease.net.gapEdges);
}
