// Shared pieces of the mesh readers (mesh_reader.h): token and number parsing over an in-memory
// buffer. Not part of the public interface.
#ifndef NVV_IO_MESH_READER_INTERNAL_H
#define NVV_IO_MESH_READER_INTERNAL_H

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "io/mesh_reader.h"

namespace nvv {
namespace io {
namespace detail {

// The parsers. `data[size]` is readable and is '\0' (the callers guarantee it).
bool ReadPly(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits);
bool ReadObj(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits);
bool ReadOff(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits);
bool ReadStl(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits);

inline bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
inline bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// 1-based line number of byte `pos`.
inline std::size_t LineOf(const char* data, std::size_t pos) {
  std::size_t line = 1;
  for (std::size_t i = 0; i < pos; ++i)
    if (data[i] == '\n') ++line;
  return line;
}

// Parses the whole token [b, e) as a number: float (correctly rounded, as strtof) or double then
// rounded to float (as atof does in most importers). False when the token is not entirely a
// number. Hex floats, inf and nan are accepted as the C library reads them.
inline bool ParseReal(const char* b, const char* e, bool viaDouble, double& value) {
  const std::size_t n = std::size_t(e - b);
  if (n == 0) return false;
  char small[80];
  std::string big;
  const char* s;
  if (n < sizeof small) {
    std::memcpy(small, b, n);
    small[n] = '\0';
    s = small;
  } else {
    if (n > (std::size_t(1) << 20)) return false;  // no number is a megabyte long
    big.assign(b, n);
    s = big.c_str();
  }
  char* end = nullptr;
  if (viaDouble) {
    value = double(float(std::strtod(s, &end)));
  } else {
    value = double(std::strtof(s, &end));
  }
  return end == s + n;
}

// Parses the whole token [b, e) as a decimal integer (optional sign). False when it is not one or
// is beyond +-2^62.
inline bool ParseInt(const char* b, const char* e, std::int64_t& value) {
  if (b == e) return false;
  bool neg = false;
  if (*b == '+' || *b == '-') {
    neg = *b == '-';
    ++b;
  }
  if (b == e) return false;
  std::int64_t v = 0;
  for (; b != e; ++b) {
    if (*b < '0' || *b > '9') return false;
    if (v > (std::int64_t(1) << 62) / 10) return false;
    v = v * 10 + (*b - '0');
  }
  value = neg ? -v : v;
  return true;
}

// Splits the line [b, e) into whitespace-separated tokens (at most `max`, the rest counted).
// What every reader holds: the file's bytes, the mesh it fills, where the reason for a refusal
// goes, and the limits it reads within.
class ReaderBase {
 protected:
  ReaderBase(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits)
      : data_(data), size_(size), out_(out), error_(error), limits_(limits) {}
  const char* data_;
  std::size_t size_;
  MeshData& out_;
  std::string& error_;
  const ReadLimits& limits_;
};

struct Token {
  const char* b;
  const char* e;
};

inline std::string TokenText(const Token& t, std::size_t max = 40) {
  const std::size_t n = std::size_t(t.e - t.b);
  std::string s(t.b, n < max ? n : max);
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  if (n > max) s += "...";
  return s;
}

}  // namespace detail
}  // namespace io
}  // namespace nvv

#endif
