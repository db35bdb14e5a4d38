// PLY reader (ascii, binary_little_endian, binary_big_endian) for mesh_reader.h. Elements and
// properties may come in any order; elements other than vertex, face and tristrips are skipped,
// as are properties the reader does not use (lists included).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "io/mesh_reader_internal.h"

namespace nvv {
namespace io {
namespace detail {

namespace {

enum class PlyType { None, Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

PlyType TypeFromName(const std::string& s) {
  if (s == "char" || s == "int8") return PlyType::Int8;
  if (s == "uchar" || s == "uint8") return PlyType::UInt8;
  if (s == "short" || s == "int16") return PlyType::Int16;
  if (s == "ushort" || s == "uint16") return PlyType::UInt16;
  if (s == "int" || s == "int32") return PlyType::Int32;
  if (s == "uint" || s == "uint32") return PlyType::UInt32;
  if (s == "float" || s == "float32") return PlyType::Float32;
  if (s == "double" || s == "float64") return PlyType::Float64;
  return PlyType::None;
}

std::size_t TypeSize(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    case PlyType::None: return 0;
  }
  return 0;
}

bool IsIntegerType(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64 && t != PlyType::None; }

enum Slot { kX, kY, kZ, kNx, kNy, kNz, kRed, kGreen, kBlue, kAlpha, kQuality, kSlots, kSkip = -1 };

struct Prop {
  std::string name;
  PlyType type = PlyType::None;   // scalar type, or the item type of a list
  PlyType count = PlyType::None;  // list count type; None for a scalar
  int slot = kSkip;
  bool IsList() const { return count != PlyType::None; }
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Prop> props;
  std::size_t headerLine = 0;
};

enum class Encoding { Ascii, LittleEndian, BigEndian };

bool HostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

class Parser : ReaderBase {
 public:
  Parser(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits)
      : ReaderBase(data, size, out, error, limits) {}

  bool Run() {
    if (!ParseHeader()) return false;
    if (!CheckCounts()) return false;
    for (const Element& e : elements_)
      if (!ReadElement(e)) return false;
    if (encoding_ == Encoding::Ascii) {
      // Anything but white space after the last record means the counts do not match the data.
      std::size_t p = pos_;
      while (p < size_ && IsSpace(data_[p])) ++p;
      if (p < size_) return Fail("more data than the header declares, at line " + std::to_string(LineOf(data_, p)));
    }
    return true;
  }

 private:
  std::vector<Element> elements_;
  Encoding encoding_ = Encoding::Ascii;
  bool swap_ = false;
  std::size_t pos_ = 0;  // reading position in data_
  std::uint64_t vertexCount_ = 0;
  bool haveVertex_ = false;

  bool Fail(const std::string& why) {
    error_ = "corrupt PLY file: " + why;
    return false;
  }

  std::string Where(std::size_t at) const {
    if (encoding_ == Encoding::Ascii) return "line " + std::to_string(LineOf(data_, at));
    return "byte offset " + std::to_string(at);
  }

  // --- header --------------------------------------------------------------------------------
  // 'element NAME COUNT': a new element, `cur` from now on.
  bool ElementLine(const std::vector<std::string>& tok, std::size_t line, Element*& cur) {
    if (tok.size() != 3) return Fail("header line " + std::to_string(line) + ": 'element' needs a name and a count");
    std::int64_t n;
    if (!ParseInt(tok[2].data(), tok[2].data() + tok[2].size(), n) || n < 0)
      return Fail("header line " + std::to_string(line) + ": element count '" + tok[2].substr(0, 40) +
                  "' is not a non-negative integer");
    for (const Element& e : elements_)
      if (e.name == tok[1]) return Fail("header line " + std::to_string(line) + ": element '" + tok[1].substr(0, 40) + "' declared twice");
    if (elements_.size() >= 1000) return Fail("the header declares more than 1000 elements");
    elements_.emplace_back();
    cur = &elements_.back();
    cur->name = tok[1];
    cur->count = std::uint64_t(n);
    cur->headerLine = line;
    return true;
  }

  // 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME' of element `cur`.
  bool PropertyLine(const std::vector<std::string>& tok, std::size_t line, Element* cur) {
    if (!cur) return Fail("header line " + std::to_string(line) + ": a property before any element");
    if (cur->props.size() >= 1000) return Fail("element '" + cur->name.substr(0, 40) + "' has more than 1000 properties");
    Prop pr;
    if (tok.size() == 5 && tok[1] == "list") {
      pr.count = TypeFromName(tok[2]);
      pr.type = TypeFromName(tok[3]);
      pr.name = tok[4];
      if (pr.count == PlyType::None || pr.type == PlyType::None)
        return Fail("header line " + std::to_string(line) + ": unknown list type");
      if (!IsIntegerType(pr.count))
        return Fail("header line " + std::to_string(line) + ": a list's count type must be an integer type");
    } else if (tok.size() == 3) {
      pr.type = TypeFromName(tok[1]);
      pr.name = tok[2];
      if (pr.type == PlyType::None)
        return Fail("header line " + std::to_string(line) + ": unknown property type '" + tok[1].substr(0, 40) + "'");
    } else {
      return Fail("header line " + std::to_string(line) + ": malformed 'property' line");
    }
    cur->props.push_back(pr);
    return true;
  }

  bool ParseHeader() {
    std::size_t p = 0, line = 0;
    bool sawFormat = false;
    Element* cur = nullptr;
    while (true) {
      if (p >= size_) return Fail(line == 0 ? "the file is empty" : "the header has no 'end_header' line");
      const void* hit = std::memchr(data_ + p, '\n', size_ - p);
      const std::size_t nl = hit ? std::size_t(static_cast<const char*>(hit) - data_) : size_;
      ++line;
      std::vector<std::string> tok;
      {
        std::size_t i = p;
        while (i < nl) {
          while (i < nl && IsBlank(data_[i])) ++i;
          const std::size_t b = i;
          while (i < nl && !IsBlank(data_[i])) ++i;
          if (i > b) {
            if (tok.size() >= 8 && !(tok[0] == "comment" || tok[0] == "obj_info")) {
              return Fail("header line " + std::to_string(line) + " has too many words");
            }
            if (tok.empty() || !(tok[0] == "comment" || tok[0] == "obj_info")) tok.emplace_back(data_ + b, i - b);
          }
        }
      }
      p = nl < size_ ? nl + 1 : size_;
      if (line == 1) {
        if (tok.size() != 1 || tok[0] != "ply")
          return Fail("it does not start with the line 'ply'");
        continue;
      }
      if (tok.empty()) continue;
      const std::string& k = tok[0];
      if (k == "comment" || k == "obj_info") continue;
      if (k == "end_header") {
        pos_ = p;
        break;
      }
      if (k == "format") {
        if (tok.size() < 2) return Fail("header line " + std::to_string(line) + ": 'format' without an encoding");
        if (tok[1] == "ascii") encoding_ = Encoding::Ascii;
        else if (tok[1] == "binary_little_endian") encoding_ = Encoding::LittleEndian;
        else if (tok[1] == "binary_big_endian") encoding_ = Encoding::BigEndian;
        else return Fail("header line " + std::to_string(line) + ": unknown format '" + tok[1].substr(0, 40) + "'");
        sawFormat = true;
        continue;
      }
      if (k == "element") {
        if (!ElementLine(tok, line, cur)) return false;
        continue;
      }
      if (k == "property") {
        if (!PropertyLine(tok, line, cur)) return false;
        continue;
      }
      return Fail("header line " + std::to_string(line) + ": unknown keyword '" + k.substr(0, 40) + "'");
    }
    if (!sawFormat) return Fail("the header has no 'format' line");
    swap_ = encoding_ != Encoding::Ascii && ((encoding_ == Encoding::LittleEndian) != HostIsLittleEndian());
    out_.formatDetail = encoding_ == Encoding::Ascii ? "ascii"
                        : encoding_ == Encoding::LittleEndian ? "binary_little_endian" : "binary_big_endian";
    return AssignSlots();
  }

  bool AssignSlots() {
    static const char* const names[kSlots] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha", "quality"};
    for (Element& e : elements_) {
      if (e.name == "vertex") {
        haveVertex_ = true;
        vertexCount_ = e.count;
        bool used[kSlots] = {false};
        for (Prop& p : e.props) {
          if (p.IsList()) continue;
          for (int s = 0; s < kSlots; ++s)
            if (!used[s] && p.name == names[s]) {
              p.slot = s;
              used[s] = true;
            }
        }
        for (int s = kX; s <= kZ; ++s)
          if (!used[s]) return Fail(std::string("the vertex element has no '") + names[s] + "' property");
        hasNormals_ = used[kNx] && used[kNy] && used[kNz];
        hasColors_ = used[kRed] && used[kGreen] && used[kBlue];
        hasQuality_ = used[kQuality];
      } else if (e.name == "face" || e.name == "tristrips") {
        bool found = false;
        for (Prop& p : e.props)
          if (!found && p.IsList() && (p.name == "vertex_indices" || (e.name == "face" && p.name == "vertex_index"))) {
            if (!IsIntegerType(p.type))
              return Fail("the " + e.name + " element's '" + p.name + "' list is not of an integer type");
            p.slot = 0;
            found = true;
          }
        if (!found && e.count > 0)
          return Fail("the " + e.name + " element has no 'vertex_indices' list property");
      }
    }
    if (haveVertex_ && vertexCount_ > limits_.maxVertices)
      return Fail("the header declares " + std::to_string(vertexCount_) + " vertices, more than the limit of " +
                  std::to_string(limits_.maxVertices));
    return true;
  }

  bool hasNormals_ = false, hasColors_ = false, hasQuality_ = false;

  // Every element's records need at least some bytes: refuse counts the file cannot hold before
  // anything is allocated.
  bool CheckCounts() {
    const std::uint64_t remaining = size_ - pos_;
    std::uint64_t needed = 0;
    for (const Element& e : elements_) {
      if (e.count == 0) continue;
      std::uint64_t per = 0;  // minimal bytes (binary) or values (ascii) per record
      for (const Prop& p : e.props)
        per += encoding_ == Encoding::Ascii ? 1 : TypeSize(p.IsList() ? p.count : p.type);
      if (per == 0) {
        // Records without properties take no room: nothing to read and nothing to check.
        continue;
      }
      // ascii: each value is at least one character and one separator (the last one may lack it).
      const std::uint64_t room = encoding_ == Encoding::Ascii ? (remaining + 1) / 2 : remaining;
      if (e.count > room / per || needed + e.count * per > room) {
        return Fail("the header (line " + std::to_string(e.headerLine) + ") declares " + std::to_string(e.count) +
                    " '" + e.name.substr(0, 40) + "' records, but only " + std::to_string(remaining) +
                    " bytes of data follow");
      }
      needed += e.count * per;
    }
    return true;
  }

  // --- values --------------------------------------------------------------------------------
  // Reads one scalar of type t into v. Binary: bounds-checked; ascii: one token.
  bool ReadValue(PlyType t, double& v, const char* what, std::uint64_t record) {
    if (encoding_ == Encoding::Ascii) {
      std::size_t p = pos_;
      while (p < size_ && IsSpace(data_[p])) ++p;
      if (p >= size_)
        return Fail("the file ends inside " + std::string(what) + " record " + std::to_string(record));
      const std::size_t b = p;
      while (p < size_ && !IsSpace(data_[p])) ++p;
      pos_ = p;
      if (IsIntegerType(t)) {
        std::int64_t n;
        if (!ParseInt(data_ + b, data_ + p, n))
          return Fail("'" + TokenText(Token{data_ + b, data_ + p}) + "' at " + Where(b) + " is not an integer");
        if (!InRange(t, n))
          return Fail("value " + std::to_string(n) + " at " + Where(b) + " does not fit its property type");
        v = double(n);
      } else if (!ParseReal(data_ + b, data_ + p, t == PlyType::Float64, v)) {
        return Fail("'" + TokenText(Token{data_ + b, data_ + p}) + "' at " + Where(b) + " is not a number");
      }
      return true;
    }
    const std::size_t n = TypeSize(t);
    if (size_ - pos_ < n)
      return Fail("the file ends inside " + std::string(what) + " record " + std::to_string(record) +
                  " (byte offset " + std::to_string(pos_) + ")");
    unsigned char b[8];
    std::memcpy(b, data_ + pos_, n);
    pos_ += n;
    if (swap_) std::reverse(b, b + n);
    switch (t) {
      case PlyType::Int8: { std::int8_t x; std::memcpy(&x, b, 1); v = x; break; }
      case PlyType::UInt8: { v = b[0]; break; }
      case PlyType::Int16: { std::int16_t x; std::memcpy(&x, b, 2); v = x; break; }
      case PlyType::UInt16: { std::uint16_t x; std::memcpy(&x, b, 2); v = x; break; }
      case PlyType::Int32: { std::int32_t x; std::memcpy(&x, b, 4); v = x; break; }
      case PlyType::UInt32: { std::uint32_t x; std::memcpy(&x, b, 4); v = x; break; }
      case PlyType::Float32: { float x; std::memcpy(&x, b, 4); v = double(x); break; }
      case PlyType::Float64: { double x; std::memcpy(&x, b, 8); v = double(float(x)); break; }
      case PlyType::None: return Fail("internal: no type");
    }
    return true;
  }

  static bool InRange(PlyType t, std::int64_t n) {
    switch (t) {
      case PlyType::Int8: return n >= -128 && n <= 127;
      case PlyType::UInt8: return n >= 0 && n <= 255;
      case PlyType::Int16: return n >= -32768 && n <= 32767;
      case PlyType::UInt16: return n >= 0 && n <= 65535;
      case PlyType::Int32: return n >= -2147483648LL && n <= 2147483647LL;
      case PlyType::UInt32: return n >= 0 && n <= 4294967295LL;
      default: return true;
    }
  }

  // Reads a list's count and checks that its items can be present.
  bool ReadListCount(const Prop& p, std::uint64_t& n, const char* what, std::uint64_t record) {
    const std::size_t at = pos_;
    double c;
    if (!ReadValue(p.count, c, what, record)) return false;
    if (c < 0) return Fail("negative list length at " + Where(at) + " (" + std::string(what) + " record " + std::to_string(record) + ")");
    n = std::uint64_t(c);
    const std::uint64_t remaining = size_ - pos_;
    const std::uint64_t room = encoding_ == Encoding::Ascii ? (remaining + 1) / 2 : remaining / TypeSize(p.type);
    if (n > room)
      return Fail("a list of " + std::to_string(n) + " items at " + Where(at) + " (" + what + " record " +
                  std::to_string(record) + ") is longer than the rest of the file");
    return true;
  }

  bool SkipProp(const Prop& p, const char* what, std::uint64_t record) {
    double v;
    if (!p.IsList()) return ReadValue(p.type, v, what, record);
    std::uint64_t n;
    if (!ReadListCount(p, n, what, record)) return false;
    if (encoding_ != Encoding::Ascii) {
      pos_ += std::size_t(n * TypeSize(p.type));  // checked by ReadListCount
      return true;
    }
    for (std::uint64_t i = 0; i < n; ++i)
      if (!ReadValue(p.type, v, what, record)) return false;
    return true;
  }

  static std::uint8_t ColorByte(PlyType t, double v) {
    if (!IsIntegerType(t)) v = v * 255.0 + 0.5;  // float colours are 0..1
    if (!(v > 0)) return 0;                       // NaN too
    if (v >= 255) return 255;
    return std::uint8_t(v);
  }

  // --- elements ------------------------------------------------------------------------------
  bool ReadElement(const Element& e) {
    if (e.name == "vertex") return ReadVertices(e);
    if (e.name == "face") return ReadFaces(e, false);
    if (e.name == "tristrips") return ReadFaces(e, true);
    if (e.props.empty()) return true;
    for (std::uint64_t r = 0; r < e.count; ++r)
      for (const Prop& p : e.props)
        if (!SkipProp(p, e.name.c_str(), r)) return false;
    out_.skippedElements += std::size_t(e.count);
    return true;
  }

  bool ReadVertices(const Element& e) {
    const std::size_t n = std::size_t(e.count);
    out_.positions.resize(n);
    if (hasNormals_) out_.normals.resize(n);
    if (hasColors_) out_.colors.assign(n, std::array<std::uint8_t, 4>{{255, 255, 255, 255}});
    if (hasQuality_) out_.quality.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (const Prop& p : e.props) {
        if (p.slot == kSkip) {
          if (!SkipProp(p, "vertex", i)) return false;
          continue;
        }
        double v;
        if (!ReadValue(p.type, v, "vertex", i)) return false;
        switch (p.slot) {
          case kX: case kY: case kZ: out_.positions[i][p.slot - kX] = float(v); break;
          case kNx: case kNy: case kNz: if (hasNormals_) out_.normals[i][p.slot - kNx] = float(v); break;
          case kRed: case kGreen: case kBlue: case kAlpha:
            if (hasColors_) out_.colors[i][p.slot - kRed] = ColorByte(p.type, v);
            break;
          case kQuality: out_.quality[i] = float(v); break;
          default: break;
        }
      }
    }
    return true;
  }

  bool ReadFaces(const Element& e, bool strips) {
    const char* what = strips ? "tristrips" : "face";
    if (e.count > 0 && !haveVertex_) return Fail(std::string("the file has ") + what + " but no vertex element");
    // A face record takes at least 4 bytes (binary: count and 3 one-byte indices; ascii "3 0 1 2").
    if (!strips) out_.triangles.reserve(std::size_t(std::min<std::uint64_t>(e.count, (size_ - pos_) / 4)));
    std::vector<std::int64_t> idx;
    for (std::uint64_t r = 0; r < e.count; ++r) {
      for (const Prop& p : e.props) {
        if (p.slot == kSkip) {
          if (!SkipProp(p, what, r)) return false;
          continue;
        }
        const std::size_t at = pos_;
        std::uint64_t n;
        if (!ReadListCount(p, n, what, r)) return false;
        if (!strips) {
          if (n < 3)
            return Fail("face " + std::to_string(r) + " at " + Where(at) + " has " + std::to_string(n) +
                        " corners (a face needs at least 3)");
          if (n > limits_.maxPolygonCorners)
            return Fail("face " + std::to_string(r) + " at " + Where(at) + " has " + std::to_string(n) +
                        " corners, more than the limit of " + std::to_string(limits_.maxPolygonCorners));
        }
        idx.resize(std::size_t(n));
        for (std::size_t k = 0; k < idx.size(); ++k) {
          double v;
          const std::size_t vat = pos_;
          if (!ReadValue(p.type, v, what, r)) return false;
          idx[k] = std::int64_t(v);
          const bool separator = strips && idx[k] == -1;
          if (!separator && (idx[k] < 0 || std::uint64_t(idx[k]) >= vertexCount_))
            return Fail(std::string(what) + " " + std::to_string(r) + " refers to vertex " + std::to_string(idx[k]) +
                        " at " + Where(vat) + ", but the file has " + std::to_string(vertexCount_) + " vertices");
        }
        if (strips) {
          if (!AddStrip(idx, r)) return false;
        } else {
          if (out_.triangles.size() + (n - 2) > limits_.maxTriangles)
            return Fail("more than " + std::to_string(limits_.maxTriangles) + " triangles");
          for (std::size_t k = 1; k + 1 < idx.size(); ++k)
            out_.triangles.push_back({{int(idx[0]), int(idx[k]), int(idx[k + 1])}});
          if (n > 3) ++out_.polygons;
        }
        ++out_.fileFaces;
      }
    }
    return true;
  }

  // Stanford triangle strips, -1 separating strips, as MeshLab reads them: the orientation
  // alternates along a strip.
  bool AddStrip(const std::vector<std::int64_t>& v, std::uint64_t record) {
    int remainder = 0;
    for (std::size_t k = 0; k + 2 < v.size(); ++k) {
      if (v[k + 2] == -1) {
        k += 2;
        remainder = (k % 2) ? 0 : 1;
        continue;
      }
      if (v[k] == -1 || v[k + 1] == -1)
        return Fail("tristrip " + std::to_string(record) + " has a separator (-1) inside a triangle");
      if (out_.triangles.size() + 1 > limits_.maxTriangles)
        return Fail("more than " + std::to_string(limits_.maxTriangles) + " triangles");
      std::array<int, 3> t{{int(v[k]), int(v[k + 1]), int(v[k + 2])}};
      if ((k + remainder) % 2) std::swap(t[0], t[1]);
      out_.triangles.push_back(t);
    }
    return true;
  }
};

}  // namespace

bool ReadPly(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits) {
  Parser p(data, size, out, error, limits);
  return p.Run();
}

}  // namespace detail
}  // namespace io
}  // namespace nvv
