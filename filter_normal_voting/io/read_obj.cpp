// Wavefront OBJ reader for mesh_reader.h: 'v' (with optional r g b), 'f' with v, v/vt, v/vt/vn
// and v//vn corners; indices 1-based, negative ones relative to the vertices read so far. Other
// statements (vt, vn, g, o, s, usemtl, mtllib, ...) are skipped; 'l' and 'p' are counted.
#include <algorithm>
#include <vector>

#include "io/read_text.h"

namespace nvv {
namespace io {
namespace detail {


namespace {

// The reader's state across lines: OBJ's relative indices count the vertices read so far, and a
// positive index may refer to a vertex defined further down.
class ObjReader : LineFormatReader {
 public:
  static constexpr const char* kFormat = "OBJ";
  ObjReader(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits)
      : LineFormatReader(kFormat, data, size, out, error, limits) {}

  bool Read() {
    while (lines.Next(tok)) {
      const Token& k = tok[0];
      if (TokenIs(k, "v")) {
        if (!Vertex()) return false;
      } else if (TokenIs(k, "f")) {
        if (!Face()) return false;
      } else if (TokenIs(k, "l") || TokenIs(k, "p")) {
        ++out.skippedElements;
      } else {
        ++out.skippedLines;
      }
    }
    if (maxIndex >= 0 && std::uint64_t(maxIndex) >= out.positions.size())
      return failAt(maxIndexLine, "a face refers to vertex " + std::to_string(maxIndex + 1) + ", but the file has " +
                                      std::to_string(out.positions.size()) + " vertices");
    out.formatDetail = "ascii";
    return true;
  }

 private:
  // 'v x y z [r g b [a]]'
  bool Vertex() {
    if (tok.size() < 4) return fail("a vertex needs three coordinates");
    std::array<float, 3> p;
    for (int j = 0; j < 3; ++j) {
      double v;
      if (!ParseReal(tok[1 + j].b, tok[1 + j].e, true, v))
        return fail("'" + TokenText(tok[1 + j]) + "' is not a number");
      p[j] = float(v);
    }
    if (out.positions.size() >= limits.maxVertices)
      return fail("more than " + std::to_string(limits.maxVertices) + " vertices");
    out.positions.push_back(p);
    if (tok.size() >= 7) {
      double c[4] = {0, 0, 0, 1};
      const int nc = tok.size() >= 8 ? 4 : 3;
      bool numbers = true;
      for (int j = 0; j < nc; ++j) numbers = numbers && ParseReal(tok[4 + j].b, tok[4 + j].e, true, c[j]);
      if (numbers) {
        const bool unit = c[0] <= 1 && c[1] <= 1 && c[2] <= 1 && c[3] <= 1;
        if (!anyColor) {
          out.colors.assign(out.positions.size() - 1, std::array<std::uint8_t, 4>{{255, 255, 255, 255}});
          anyColor = true;
        }
        out.colors.push_back({{ColorByte(c[0], unit), ColorByte(c[1], unit), ColorByte(c[2], unit),
                               ColorByte(c[3], unit)}});
      }
    }
    if (anyColor && out.colors.size() < out.positions.size())
      out.colors.push_back(std::array<std::uint8_t, 4>{{255, 255, 255, 255}});
    return true;
  }

  // 'f' with v, v/vt, v/vt/vn or v//vn corners, fan-triangulated.
  bool Face() {
    const std::size_t n = tok.size() - 1;
    if (n < 3) return fail("a face has " + std::to_string(n) + " corners (a face needs at least 3)");
    if (n > limits.maxPolygonCorners)
      return fail("a face has " + std::to_string(n) + " corners, more than the limit of " +
                  std::to_string(limits.maxPolygonCorners));
    corners.clear();
    for (std::size_t j = 1; j < tok.size(); ++j) {
      const char* slash = std::find(tok[j].b, tok[j].e, '/');
      std::int64_t idx;
      if (!ParseInt(tok[j].b, slash, idx))
        return fail("face corner '" + TokenText(tok[j]) + "' does not start with a vertex index");
      if (idx == 0) return fail("vertex index 0 (OBJ indices start at 1)");
      if (idx < 0) {
        idx += std::int64_t(out.positions.size());
        if (idx < 0)
          return fail("relative vertex index " + TokenText(Token{tok[j].b, slash}) + " reaches before the first vertex (" +
                      std::to_string(out.positions.size()) + " read so far)");
      } else {
        idx -= 1;
        if (std::uint64_t(idx) >= limits.maxVertices)
          return fail("vertex index " + std::to_string(idx + 1) + " is beyond any vertex the file can have");
        if (idx > maxIndex) {
          maxIndex = idx;
          maxIndexLine = lines.Line();
        }
      }
      corners.push_back(idx);
    }
    if (out.triangles.size() + (n - 2) > limits.maxTriangles)
      return fail("more than " + std::to_string(limits.maxTriangles) + " triangles");
    for (std::size_t j = 1; j + 1 < corners.size(); ++j)
      out.triangles.push_back({{int(corners[0]), int(corners[j]), int(corners[j + 1])}});
    if (n > 3) ++out.polygons;
    ++out.fileFaces;
    return true;
  }

  std::vector<std::int64_t> corners;
  std::int64_t maxIndex = -1;  // the largest positive index used, checked once all vertices are read
  std::size_t maxIndexLine = 0;
  bool anyColor = false;
};

}  // namespace

bool ReadObj(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits) {
  return ReadLineFormat<ObjReader>(data, size, out, error, limits);
}

}  // namespace detail
}  // namespace io
}  // namespace nvv
