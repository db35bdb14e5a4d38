// Line and token walking for the text readers (OBJ, OFF, ascii STL). Not part of the public
// interface.
#ifndef NVV_IO_READ_TEXT_H
#define NVV_IO_READ_TEXT_H

#include <string>
#include <vector>

#include "io/mesh_reader_internal.h"

namespace nvv {
namespace io {
namespace detail {

// Walks a buffer line by line; each line split into tokens, '#' starting a comment.
class LineReader {
 public:
  LineReader(const char* data, std::size_t size) : data_(data), size_(size) {}
  // Next line with at least one token; false at the end of the data.
  bool Next(std::vector<Token>& tokens) {
    while (pos_ < size_) {
      const std::size_t b = pos_;
      std::size_t e = b;
      while (e < size_ && data_[e] != '\n') ++e;
      pos_ = e < size_ ? e + 1 : size_;
      ++line_;
      tokens.clear();
      std::size_t i = b;
      while (i < e) {
        while (i < e && IsBlank(data_[i])) ++i;
        if (i >= e || data_[i] == '#') break;
        const std::size_t t = i;
        while (i < e && !IsBlank(data_[i]) && data_[i] != '#') ++i;
        tokens.push_back(Token{data_ + t, data_ + i});
      }
      if (!tokens.empty()) return true;
    }
    return false;
  }
  std::size_t Line() const { return line_; }
  std::size_t Remaining() const { return size_ - pos_; }

 private:
  const char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

inline bool TokenIs(const Token& t, const char* s) {
  const std::size_t n = std::strlen(s);
  return std::size_t(t.e - t.b) == n && std::memcmp(t.b, s, n) == 0;
}

// A colour component as a byte: 0-255 as written, or 0-1 when `unit` (scaled and rounded).
inline std::uint8_t ColorByte(double v, bool unit) {
  if (unit) v = v * 255.0 + 0.5;
  if (!(v > 0)) return 0;
  if (v >= 255) return 255;
  return std::uint8_t(v);
}

inline bool OnlySpace(const char* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i)
    if (!IsSpace(data[i])) return false;
  return true;
}

// What the line-based readers (OBJ, OFF) share: the lines and the current line's tokens, the
// mesh they fill, where a refusal's reason goes ("corrupt <format> file: line N: why"), and the
// limits they read within. Reader::kFormat names the format in the messages.
class LineFormatReader {
 protected:
  LineFormatReader(const char* format, const char* data, std::size_t size, MeshData& out, std::string& error,
                   const ReadLimits& limits)
      : lines(data, size), out(out), error(error), limits(limits), format_(format) {}
  bool fail(const std::string& why) { return failAt(lines.Line(), why); }
  bool failAt(std::size_t line, const std::string& why) {
    error = std::string("corrupt ") + format_ + " file: line " + std::to_string(line) + ": " + why;
    return false;
  }

  LineReader lines;
  std::vector<Token> tok;
  MeshData& out;
  std::string& error;
  const ReadLimits& limits;

 private:
  const char* format_;
};

// Reads the bytes with Reader (a LineFormatReader), unless they hold nothing but white space.
template <class Reader>
bool ReadLineFormat(const char* data, std::size_t size, MeshData& out, std::string& error, const ReadLimits& limits) {
  if (OnlySpace(data, size)) {
    error = std::string("the ") + Reader::kFormat + " file is empty";
    return false;
  }
  return Reader(data, size, out, error, limits).Read();
}

}  // namespace detail
}  // namespace io
}  // namespace nvv

#endif
