// Reads a full-result PLY (result_ply.h) back into plain structs: binary_little_endian or ascii,
// every property of ResultPlyVertex required, the crease network's face "patch" and "edge"
// element where the file has them (files without them read as before), other properties and
// elements skipped, faces must be triangles. Standard library only.
#ifndef NVV_IO_RESULT_PLY_READER_H
#define NVV_IO_RESULT_PLY_READER_H

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/result_ply_format.h"

namespace nvv {
namespace ply_read_detail {

enum class Scalar { Char, UChar, Short, UShort, Int, UInt, Float, Double, Bad };

inline Scalar ScalarFromName(const std::string& s) {
  if (s == "char" || s == "int8") return Scalar::Char;
  if (s == "uchar" || s == "uint8") return Scalar::UChar;
  if (s == "short" || s == "int16") return Scalar::Short;
  if (s == "ushort" || s == "uint16") return Scalar::UShort;
  if (s == "int" || s == "int32") return Scalar::Int;
  if (s == "uint" || s == "uint32") return Scalar::UInt;
  if (s == "float" || s == "float32") return Scalar::Float;
  if (s == "double" || s == "float64") return Scalar::Double;
  return Scalar::Bad;
}
inline std::size_t ScalarSize(Scalar t) {
  switch (t) {
    case Scalar::Char: case Scalar::UChar: return 1;
    case Scalar::Short: case Scalar::UShort: return 2;
    case Scalar::Double: return 8;
    default: return 4;
  }
}

struct Property {
  std::string name;
  Scalar type = Scalar::Bad;
  bool list = false;
  Scalar countType = Scalar::Bad;
};
struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> props;
};

// The body of the file, read value by value in either encoding. Float properties come back
// as the exact float value (widened to double), so float -> file -> float is lossless.
class BodyCursor {
 public:
  BodyCursor(const std::string& data, std::size_t pos, bool binary) : d_(data), pos_(pos), binary_(binary) {}
  bool Read(Scalar t, double& out) {
    return binary_ ? ReadBinary(t, out) : ReadAscii(t, out);
  }

 private:
  bool ReadBinary(Scalar t, double& out) {
    const std::size_t n = ScalarSize(t);
    if (pos_ + n > d_.size()) return false;
    unsigned char b[8];
    for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<unsigned char>(d_[pos_ + i]);
    pos_ += n;
    const std::uint16_t probe = 1;
    if (*reinterpret_cast<const unsigned char*>(&probe) != 1)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case Scalar::Char: { std::int8_t v; std::memcpy(&v, b, 1); out = v; break; }
      case Scalar::UChar: out = b[0]; break;
      case Scalar::Short: { std::int16_t v; std::memcpy(&v, b, 2); out = v; break; }
      case Scalar::UShort: { std::uint16_t v; std::memcpy(&v, b, 2); out = v; break; }
      case Scalar::Int: { std::int32_t v; std::memcpy(&v, b, 4); out = v; break; }
      case Scalar::UInt: { std::uint32_t v; std::memcpy(&v, b, 4); out = v; break; }
      case Scalar::Float: { float v; std::memcpy(&v, b, 4); out = v; break; }
      default: { double v; std::memcpy(&v, b, 8); out = v; break; }
    }
    return true;
  }
  bool ReadAscii(Scalar t, double& out) {
    while (pos_ < d_.size() && std::isspace(static_cast<unsigned char>(d_[pos_]))) ++pos_;
    if (pos_ >= d_.size()) return false;
    std::size_t end = pos_;
    while (end < d_.size() && !std::isspace(static_cast<unsigned char>(d_[end]))) ++end;
    const std::string tok = d_.substr(pos_, end - pos_);
    pos_ = end;
    char* stop = nullptr;
    if (t == Scalar::Float) out = std::strtof(tok.c_str(), &stop);
    else out = std::strtod(tok.c_str(), &stop);
    return stop != tok.c_str() && *stop == '\0';
  }

  const std::string& d_;
  std::size_t pos_;
  bool binary_;
};

inline bool ReadWholeFile(const std::string& path, std::string& data) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

}  // namespace ply_read_detail

namespace ply_read_detail {

// The header: lines up to and including "end_header"; `pos` ends at the body's first byte.
inline bool ReadHeader(const std::string& path, const std::string& data, ResultPlyData& out,
                       std::vector<Element>& elements, std::size_t& pos, std::string& error) {
  pos = 0;
  bool sawFormat = false, sawEnd = false;
  for (int lineNo = 0; pos < data.size() && !sawEnd; ++lineNo) {
    std::size_t eol = data.find('\n', pos);
    if (eol == std::string::npos) break;
    std::string line = data.substr(pos, eol - pos);
    pos = eol + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (lineNo == 0) {
      if (line != "ply") { error = "'" + path + "' is not a PLY file"; return false; }
      continue;
    }
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "format") {
      std::string fmt, ver;
      ls >> fmt >> ver;
      if (fmt == "ascii") out.binary = false;
      else if (fmt == "binary_little_endian") out.binary = true;
      else { error = "unsupported PLY format '" + fmt + "'"; return false; }
      sawFormat = true;
    } else if (key == "comment") {
      out.comments.push_back(line.size() > 8 ? line.substr(8) : std::string());
    } else if (key == "element") {
      Element e;
      long long n = -1;
      ls >> e.name >> n;
      if (!ls || n < 0) { error = "bad element line '" + line + "'"; return false; }
      e.count = std::size_t(n);
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) { error = "property before any element"; return false; }
      Property p;
      std::string t;
      ls >> t;
      if (t == "list") {
        std::string ct, it;
        ls >> ct >> it >> p.name;
        p.list = true;
        p.countType = ScalarFromName(ct);
        p.type = ScalarFromName(it);
        if (p.countType == Scalar::Bad || p.countType == Scalar::Float || p.countType == Scalar::Double)
          p.type = Scalar::Bad;
      } else {
        p.type = ScalarFromName(t);
        ls >> p.name;
      }
      if (p.type == Scalar::Bad || p.name.empty()) { error = "bad property line '" + line + "'"; return false; }
      elements.back().props.push_back(p);
    } else if (key == "end_header") {
      sawEnd = true;
    } else if (key != "obj_info" && !key.empty()) {
      error = "unknown header line '" + line + "'";
      return false;
    }
  }
  if (!sawFormat || !sawEnd) { error = "incomplete PLY header in '" + path + "'"; return false; }
  return true;
}

// Where each known vertex property goes in a ResultPlyVertex.
struct Slot {
  std::ptrdiff_t offset;
  bool isFloat;
};
inline std::map<std::string, Slot> VertexSlots() {
  std::map<std::string, Slot> where;  // (not "slots": Qt defines it as a macro)
  ResultPlyVertex probe;
  const char* base = reinterpret_cast<const char*>(&probe);
  ForEachResultPlyField(probe, [&](const char* name, auto& field) {
    typedef typename std::decay<decltype(field)>::type T;
    where[name] = Slot{reinterpret_cast<const char*>(&field) - base, std::is_same<T, float>::value};
  });
  return where;
}

// A value read as an index: -1 where it is not one an int can hold (a hostile file's 1e30 or NaN).
inline int ToIndex(double x) { return x >= -2147483648.0 && x <= 2147483647.0 ? int(x) : -1; }

// Where a scalar of any other element goes: record i's value x.
typedef void (*Store)(ResultPlyData& out, std::size_t i, double x);

// Element e's records: vertex properties into out.vertices through `where`, the face list
// (property `faceList`, or -1) into out.faces, the properties with a `store` through it,
// everything else read and dropped.
inline bool ReadElement(const Element& e, const std::vector<const Slot*>& where, const std::vector<Store>& store,
                        int faceList, BodyCursor& cur, ResultPlyData& out, std::string& error) {
  for (std::size_t i = 0; i < e.count; ++i) {
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      const Property& p = e.props[k];
      double x = 0;
      if (!p.list) {
        if (!cur.Read(p.type, x)) { error = "unexpected end or bad value in element '" + e.name + "'"; return false; }
        if (where[k]) {
          char* dst = reinterpret_cast<char*>(&out.vertices[i]) + where[k]->offset;
          if (where[k]->isFloat) { const float f = float(x); std::memcpy(dst, &f, sizeof f); }
          else *reinterpret_cast<std::uint8_t*>(dst) = std::uint8_t(x);
        } else if (store[k]) {
          store[k](out, i, x);
        }
        continue;
      }
      double n = 0;
      if (!cur.Read(p.countType, n) || n < 0) { error = "bad list in element '" + e.name + "'"; return false; }
      if (int(k) == faceList && n != 3) {
        error = "face " + std::to_string(i) + " has " + std::to_string(int(n)) + " vertices, not 3";
        return false;
      }
      for (int j = 0; j < int(n); ++j) {
        if (!cur.Read(p.type, x)) { error = "unexpected end or bad value in element '" + e.name + "'"; return false; }
        if (int(k) == faceList) out.faces[i][j] = int(x);
      }
    }
  }
  return true;
}

}  // namespace ply_read_detail

inline bool ReadResultPly(const std::string& path, ResultPlyData& out, std::string& error) {
  using namespace ply_read_detail;
  out = ResultPlyData();
  std::string data;
  if (!ReadWholeFile(path, data)) {
    error = "cannot read '" + path + "'";
    return false;
  }
  std::vector<Element> elements;
  std::size_t pos = 0;
  if (!ReadHeader(path, data, out, elements, pos, error)) return false;
  const std::map<std::string, Slot> fieldSlots = VertexSlots();
  BodyCursor cur(data, pos, out.binary);
  bool sawVertex = false, sawFace = false;
  for (const Element& e : elements) {
    std::vector<const Slot*> where(e.props.size(), nullptr);
    std::vector<Store> store(e.props.size(), nullptr);
    int faceList = -1;
    if (e.name == "vertex") {
      sawVertex = true;
      std::map<std::string, bool> found;
      for (std::size_t k = 0; k < e.props.size(); ++k) {
        auto it = fieldSlots.find(e.props[k].name);
        if (it != fieldSlots.end() && !e.props[k].list) { where[k] = &it->second; found[it->first] = true; }
      }
      for (const auto& s : fieldSlots)
        if (!found.count(s.first)) { error = "vertex property '" + s.first + "' is missing"; return false; }
      out.vertices.resize(e.count);
    }
    if (e.name == "face") {
      sawFace = true;
      for (std::size_t k = 0; k < e.props.size(); ++k)
        if (e.props[k].list && (e.props[k].name == "vertex_indices" || e.props[k].name == "vertex_index"))
          faceList = int(k);
      if (faceList < 0) { error = "the face element has no vertex_indices list"; return false; }
      out.faces.resize(e.count);
      for (std::size_t k = 0; k < e.props.size(); ++k)
        if (!e.props[k].list && e.props[k].name == "patch") {
          store[k] = [](ResultPlyData& o, std::size_t i, double x) { o.facePatch[i] = ToIndex(x); };
          out.facePatch.assign(e.count, -1);
        }
    }
    if (e.name == "edge") {
      const std::map<std::string, Store> edgeStores = {
          {"vertex1", [](ResultPlyData& o, std::size_t i, double x) { o.edges[i].vertex[0] = ToIndex(x); }},
          {"vertex2", [](ResultPlyData& o, std::size_t i, double x) { o.edges[i].vertex[1] = ToIndex(x); }},
          {"cusp_angle", [](ResultPlyData& o, std::size_t i, double x) { o.edges[i].cuspAngle = float(x); }},
          {"line", [](ResultPlyData& o, std::size_t i, double x) { o.edges[i].line = ToIndex(x); }}};
      for (std::size_t k = 0; k < e.props.size(); ++k) {
        const auto it = edgeStores.find(e.props[k].name);
        if (it != edgeStores.end() && !e.props[k].list) store[k] = it->second;
      }
      out.edges.resize(e.count);
    }
    if (!ReadElement(e, where, store, faceList, cur, out, error)) return false;
  }
  if (!sawVertex) { error = "no vertex element"; return false; }
  if (!sawFace) { error = "no face element"; return false; }
  for (std::size_t i = 0; i < out.faces.size(); ++i)
    for (int j = 0; j < 3; ++j)
      if (out.faces[i][j] < 0 || std::size_t(out.faces[i][j]) >= out.vertices.size()) {
        error = "face " + std::to_string(i) + " refers to a vertex that does not exist";
        return false;
      }
  for (std::size_t i = 0; i < out.edges.size(); ++i)
    for (int j = 0; j < 2; ++j)
      if (out.edges[i].vertex[j] < 0 || std::size_t(out.edges[i].vertex[j]) >= out.vertices.size()) {
        error = "edge " + std::to_string(i) + " refers to a vertex that does not exist";
        return false;
      }
  return true;
}

}  // namespace nvv

#endif
