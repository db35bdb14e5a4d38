// STL reader for mesh_reader.h. Binary when the size is exactly 84 + 50 x (the facet count in
// the header); otherwise ASCII when the text starts with 'solid'; otherwise a binary STL with
// bytes after its last facet (ignored) when it contains non-text bytes. Every facet gets its own
// three vertices (a triangle soup, as the file stores it); facets of an ASCII STL with more than
// three vertices are fan-triangulated.
#include <cstring>
#include <vector>

#include "io/mesh_reader_internal.h"

namespace nvv {
namespace io {
namespace detail {

namespace {

float LeFloat(const unsigned char* p) {
  const std::uint32_t u = std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) |
                          (std::uint32_t(p[3]) << 24);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

bool ReadBinary(const char* data, std::size_t size, std::uint64_t facets, MeshData& out, std::string& error,
                const ReadLimits& limits) {
  if (facets * 3 > limits.maxVertices || facets > limits.maxTriangles) {
    error = "binary STL declares " + std::to_string(facets) + " facets, more than the limit";
    return false;
  }
  out.positions.resize(std::size_t(facets * 3));
  out.triangles.resize(std::size_t(facets));
  const unsigned char* p = reinterpret_cast<const unsigned char*>(data) + 84;
  for (std::size_t f = 0; f < std::size_t(facets); ++f, p += 50) {
    for (int k = 0; k < 3; ++k)
      out.positions[3 * f + k] = {{LeFloat(p + 12 + 12 * k), LeFloat(p + 16 + 12 * k), LeFloat(p + 20 + 12 * k)}};
    out.triangles[f] = {{int(3 * f), int(3 * f + 1), int(3 * f + 2)}};
  }
  out.fileFaces = std::size_t(facets);
  (void)size;
  return true;
}

class AsciiStl : ReaderBase {
 public:
  AsciiStl(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits)
      : ReaderBase(data, size, out, error, limits) {}

  bool Run() {
    if (!Next() || !Is("solid")) return Fail("an ASCII STL starts with 'solid'");
    SkipLine();  // the solid's name
    std::vector<std::array<float, 3>> loop;
    while (Next()) {
      if (Is("endsolid")) {
        SkipLine();
        continue;
      }
      if (Is("solid")) {
        SkipLine();
        continue;
      }
      if (!Is("facet")) return Fail("expected 'facet', found '" + Text() + "'");
      if (!Next() || !Is("normal")) return Fail("expected 'normal' after 'facet'");
      float n[3];
      for (int j = 0; j < 3; ++j)
        if (!Number(n[j])) return false;
      if (!Next() || !Is("outer")) return Fail("expected 'outer loop'");
      if (!Next() || !Is("loop")) return Fail("expected 'outer loop'");
      loop.clear();
      while (true) {
        if (!Next()) return Fail("the file ends inside a facet");
        if (Is("endloop")) break;
        if (!Is("vertex")) return Fail("expected 'vertex' or 'endloop', found '" + Text() + "'");
        if (loop.size() >= limits_.maxPolygonCorners) return Fail("a facet with more corners than the limit");
        std::array<float, 3> v;
        for (int j = 0; j < 3; ++j)
          if (!Number(v[j])) return false;
        loop.push_back(v);
      }
      if (!Next() || !Is("endfacet")) return Fail("expected 'endfacet'");
      if (loop.size() < 3)
        return Fail("a facet has " + std::to_string(loop.size()) + " vertices (a facet needs at least 3)");
      if (out_.positions.size() + loop.size() > limits_.maxVertices ||
          out_.triangles.size() + loop.size() - 2 > limits_.maxTriangles)
        return Fail("more facets than the limit");
      const int base = int(out_.positions.size());
      out_.positions.insert(out_.positions.end(), loop.begin(), loop.end());
      for (std::size_t k = 1; k + 1 < loop.size(); ++k)
        out_.triangles.push_back({{base, base + int(k), base + int(k) + 1}});
      if (loop.size() > 3) ++out_.polygons;
      ++out_.fileFaces;
    }
    return true;
  }

 private:
  std::size_t pos_ = 0, tb_ = 0, te_ = 0;

  bool Next() {
    while (pos_ < size_ && IsSpace(data_[pos_])) ++pos_;
    if (pos_ >= size_) return false;
    tb_ = pos_;
    while (pos_ < size_ && !IsSpace(data_[pos_])) ++pos_;
    te_ = pos_;
    return true;
  }
  void SkipLine() {
    while (pos_ < size_ && data_[pos_] != '\n') ++pos_;
  }
  bool Is(const char* word) const {
    const std::size_t n = std::strlen(word);
    if (te_ - tb_ != n) return false;
    for (std::size_t i = 0; i < n; ++i) {
      char c = data_[tb_ + i];
      if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
      if (c != word[i]) return false;
    }
    return true;
  }
  std::string Text() const { return TokenText(Token{data_ + tb_, data_ + te_}); }
  bool Number(float& f) {
    if (!Next()) return Fail("the file ends inside a facet");
    double v;
    if (!ParseReal(data_ + tb_, data_ + te_, false, v)) return Fail("'" + Text() + "' is not a number");
    f = float(v);
    return true;
  }
  bool Fail(const std::string& why) {
    error_ = "corrupt ASCII STL file: line " + std::to_string(LineOf(data_, tb_)) + ": " + why;
    return false;
  }
};

bool StartsWithSolid(const char* data, std::size_t size) {
  std::size_t i = 0;
  while (i < size && IsSpace(data[i])) ++i;
  if (size - i < 5) return false;
  for (int k = 0; k < 5; ++k) {
    char c = data[i + k];
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    if (c != "solid"[k]) return false;
  }
  return size - i == 5 || IsSpace(data[i + 5]);
}

bool HasBinaryBytes(const char* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) {
    const unsigned char c = static_cast<unsigned char>(data[i]);
    if (c == 0 || c > 127) return true;
  }
  return false;
}

}  // namespace

bool ReadStl(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits) {
  if (size == 0) {
    error = "the STL file is empty";
    return false;
  }
  std::uint64_t facets = 0;
  if (size >= 84) {
    const unsigned char* c = reinterpret_cast<const unsigned char*>(data) + 80;
    facets = std::uint64_t(c[0]) | (std::uint64_t(c[1]) << 8) | (std::uint64_t(c[2]) << 16) | (std::uint64_t(c[3]) << 24);
    if (84 + 50 * facets == size) {
      out.formatDetail = "binary";
      return ReadBinary(data, size, facets, out, error, limits);
    }
  }
  if (StartsWithSolid(data, size) && !HasBinaryBytes(data, size)) {
    out.formatDetail = "ascii";
    AsciiStl a(data, size, out, error, limits);
    return a.Run();
  }
  if (size >= 84 && 84 + 50 * facets < size && HasBinaryBytes(data, size)) {
    out.formatDetail = "binary, " + std::to_string(size - (84 + 50 * facets)) + " bytes after the last facet ignored";
    return ReadBinary(data, size, facets, out, error, limits);
  }
  if (size >= 84 && 84 + 50 * facets > size && (!StartsWithSolid(data, size) || HasBinaryBytes(data, size))) {
    error = "truncated binary STL: the header declares " + std::to_string(facets) + " facets (" +
            std::to_string(84 + 50 * facets) + " bytes), the file has " + std::to_string(size) + " bytes";
    return false;
  }
  error = "not a valid STL file (neither a binary STL of the right size, 84 + 50 x facets bytes, nor an ASCII STL "
          "starting with 'solid')";
  return false;
}

}  // namespace detail
}  // namespace io
}  // namespace nvv
