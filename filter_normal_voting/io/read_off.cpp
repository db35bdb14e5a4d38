// OFF reader for mesh_reader.h: OFF, COFF, NOFF, CNOFF (and STOFF / the ST prefix) with the
// counts on the keyword's line or the next; one vertex and one face per line, '#' comments
// anywhere. 4OFF and nOFF (not 3-D) are refused.
#include <vector>

#include "io/read_text.h"

namespace nvv {
namespace io {
namespace detail {

namespace {

bool HasDot(const Token& t) {
  for (const char* p = t.b; p != t.e; ++p)
    if (*p == '.' || *p == 'e' || *p == 'E') return true;
  return false;
}

// An OFF file is read in three parts: the keyword and the counts, then the vertices, then the
// faces, each refusing what does not fit with the line it is on.
class OffReader : LineFormatReader {
 public:
  static constexpr const char* kFormat = "OFF";
  OffReader(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits)
      : LineFormatReader(kFormat, data, size, out, error, limits) {}

  bool Read() { return Header() && Vertices() && Faces(); }

 private:
  // The keyword (its prefixes say which columns the vertices have) and the counts, checked
  // against the bytes that follow before anything is allocated.
  bool Header() {
    if (!lines.Next(tok)) return fail("no header");
    const std::string key(tok[0].b, tok[0].e);
    if (key.size() < 3 || key.compare(key.size() - 3, 3, "OFF") != 0)
      return fail("the file does not start with an OFF keyword (OFF, COFF, NOFF, CNOFF, ...)");
    for (std::size_t i = 0; i + 3 < key.size(); ++i) {
      const char c = key[i];
      if (c == 'C') hasColor = true;
      else if (c == 'N') hasNormal = true;
      else if (c == 'S' && i + 1 + 3 < key.size() && key[i + 1] == 'T') { hasTex = true; ++i; }
      else if (c == '4' || c == 'n') return fail("'" + TokenText(tok[0]) + "': only 3-D OFF files are read (no 4OFF or nOFF)");
      else return fail("unknown OFF keyword '" + TokenText(tok[0]) + "'");
    }
    out.formatDetail = key.substr(0, 16);
    std::vector<Token> counts(tok.begin() + 1, tok.end());
    if (counts.empty()) {
      if (!lines.Next(tok)) return fail("the file ends before the vertex and face counts");
      counts = tok;
    }
    if (counts.size() < 2 || counts.size() > 3) return fail("expected the counts 'vertices faces [edges]'");
    std::int64_t ne = 0;
    if (!ParseInt(counts[0].b, counts[0].e, nv) || !ParseInt(counts[1].b, counts[1].e, nf) ||
        (counts.size() == 3 && !ParseInt(counts[2].b, counts[2].e, ne)) || nv < 0 || nf < 0 || ne < 0)
      return fail("the counts are not non-negative integers");
    // Each vertex line takes at least 6 bytes ("0 0 0\n"), each face line 8 ("3 0 1 2\n"); the last
    // line may lack its newline.
    const std::uint64_t rem = lines.Remaining();
    if (std::uint64_t(nv) > rem || std::uint64_t(nf) > rem || std::uint64_t(nv) * 6 + std::uint64_t(nf) * 8 > rem + 1)
      return fail("the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                  " faces, but only " + std::to_string(rem) + " bytes follow");
    if (std::uint64_t(nv) > limits.maxVertices) return fail("more vertices than the limit");
    out.skippedElements = std::size_t(ne);
    return true;
  }

  bool Vertices() {
    const std::size_t need = 3 + (hasNormal ? 3 : 0);
    out.positions.resize(std::size_t(nv));
    if (hasNormal) out.normals.resize(std::size_t(nv));
    for (std::size_t i = 0; i < std::size_t(nv); ++i) {
      if (!lines.Next(tok)) return fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
      if (tok.size() < need)
        return fail("vertex " + std::to_string(i) + " has " + std::to_string(tok.size()) + " numbers, " +
                    std::to_string(need) + " expected");
      double v[6];
      for (std::size_t j = 0; j < need; ++j)
        if (!ParseReal(tok[j].b, tok[j].e, true, v[j])) return fail("'" + TokenText(tok[j]) + "' is not a number");
      out.positions[i] = {{float(v[0]), float(v[1]), float(v[2])}};
      if (hasNormal) out.normals[i] = {{float(v[3]), float(v[4]), float(v[5])}};
      if (hasColor) {
        const std::size_t rest = tok.size() - need - (hasTex ? 2 : 0);
        if (tok.size() >= need + (hasTex ? 2 : 0) && (rest == 3 || rest == 4)) {
          if (out.colors.empty()) out.colors.assign(std::size_t(nv), std::array<std::uint8_t, 4>{{255, 255, 255, 255}});
          const bool unit = HasDot(tok[need]);
          double c[4] = {0, 0, 0, unit ? 1.0 : 255.0};
          for (std::size_t j = 0; j < rest; ++j)
            if (!ParseReal(tok[need + j].b, tok[need + j].e, true, c[j]))
              return fail("'" + TokenText(tok[need + j]) + "' is not a colour component");
          out.colors[i] = {{ColorByte(c[0], unit), ColorByte(c[1], unit), ColorByte(c[2], unit), ColorByte(c[3], unit)}};
        }
      }
    }
    return true;
  }

  bool Faces() {
    out.triangles.reserve(std::size_t(nf));
    for (std::size_t f = 0; f < std::size_t(nf); ++f) {
      if (!lines.Next(tok)) return fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
      std::int64_t n;
      if (!ParseInt(tok[0].b, tok[0].e, n)) return fail("face " + std::to_string(f) + " does not start with its corner count");
      if (n < 3) return fail("face " + std::to_string(f) + " has " + std::to_string(n) + " corners (a face needs at least 3)");
      if (std::uint64_t(n) > limits.maxPolygonCorners)
        return fail("face " + std::to_string(f) + " has " + std::to_string(n) + " corners, more than the limit of " +
                    std::to_string(limits.maxPolygonCorners));
      if (tok.size() < std::size_t(n) + 1)
        return fail("face " + std::to_string(f) + " lists " + std::to_string(tok.size() - 1) + " of its " +
                    std::to_string(n) + " corners");
      int idx[3] = {0, 0, 0};
      for (std::int64_t j = 0; j < n; ++j) {
        const Token& t = tok[std::size_t(j) + 1];
        std::int64_t v;
        if (!ParseInt(t.b, t.e, v)) return fail("face corner '" + TokenText(t) + "' is not an integer");
        if (v < 0 || v >= nv)
          return fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + ", but the file has " +
                      std::to_string(nv) + " vertices");
        if (j == 0) idx[0] = int(v);
        else if (j == 1) idx[1] = int(v);
        else {
          idx[2] = int(v);
          if (out.triangles.size() + 1 > limits.maxTriangles) return fail("more triangles than the limit");
          out.triangles.push_back({{idx[0], idx[1], idx[2]}});
          idx[1] = idx[2];
        }
      }
      if (n > 3) ++out.polygons;
      ++out.fileFaces;
    }
    return true;
  }

  bool hasNormal = false, hasColor = false, hasTex = false;
  std::int64_t nv = 0, nf = 0;
};

}  // namespace

bool ReadOff(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits) {
  return ReadLineFormat<OffReader>(data, size, out, error, limits);
}

}  // namespace detail
}  // namespace io
}  // namespace nvv
