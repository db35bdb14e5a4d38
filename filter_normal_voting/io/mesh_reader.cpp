// File access and format dispatch for the mesh readers (mesh_reader.h).
#include "io/mesh_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <new>
#include <stdexcept>

#include "io/mesh_reader_internal.h"

namespace nvv {
namespace io {

namespace {

std::string Lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return s;
}

const char* FileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Parses `buffer` (whose byte at `size` is '\0').
bool Dispatch(const char* buffer, std::size_t size, MeshFormat format, MeshData& out, std::string& error,
              const ReadLimits& limits) {
  out.Clear();
  error.clear();
  bool ok = false;
  try {
    switch (format) {
      case MeshFormat::Ply: ok = detail::ReadPly(buffer, size, out, error, limits); break;
      case MeshFormat::Obj: ok = detail::ReadObj(buffer, size, out, error, limits); break;
      case MeshFormat::Off: ok = detail::ReadOff(buffer, size, out, error, limits); break;
      case MeshFormat::Stl: ok = detail::ReadStl(buffer, size, out, error, limits); break;
    }
  } catch (const std::bad_alloc&) {
    ok = false;
    error = "out of memory while reading the mesh";
  } catch (const std::length_error&) {
    ok = false;
    error = "the mesh is too large to hold in memory";
  }
  if (!ok) {
    out.Clear();
    if (error.empty()) error = "the file is not a valid mesh";
    // The reason may quote the file's own bytes: no control character reaches a terminal or
    // splits the one-line message (a PLY keyword holding 0x1d once did).
    for (char& c : error)
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  }
  return ok;
}

}  // namespace

const char* FormatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Ply: return "PLY";
    case MeshFormat::Obj: return "OBJ";
    case MeshFormat::Off: return "OFF";
    case MeshFormat::Stl: return "STL";
  }
  return "?";
}

bool FormatFromPath(const std::string& path, MeshFormat& format) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return false;
  const std::string ext = Lower(path.substr(dot + 1));
  if (ext == "ply") format = MeshFormat::Ply;
  else if (ext == "obj") format = MeshFormat::Obj;
  else if (ext == "off") format = MeshFormat::Off;
  else if (ext == "stl") format = MeshFormat::Stl;
  else return false;
  return true;
}

bool ReadMeshBytes(const char* data, std::size_t size, MeshFormat format, MeshData& out, std::string& error,
                   const ReadLimits& limits) {
  out.Clear();
  if (std::uint64_t(size) > limits.maxFileBytes) {
    error = "the data is larger than the limit of " + std::to_string(limits.maxFileBytes) + " bytes";
    return false;
  }
  std::string copy;
  try {
    copy.assign(data ? data : "", data ? size : 0);  // the parsers want a '\0' after the last byte
  } catch (const std::exception&) {
    error = "out of memory while reading the mesh";
    return false;
  }
  return Dispatch(copy.c_str(), copy.size(), format, out, error, limits);
}

bool ReadMeshFile(const std::string& path, MeshData& out, std::string& error, const ReadLimits& limits) {
  out.Clear();
  MeshFormat format;
  if (!FormatFromPath(path, format)) {
    error = "unknown file format (the readers take .ply, .obj, .off and .stl)";
    return false;
  }
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    error = std::string("is ") + FileKind(st.st_mode) + ", not a mesh file";
    return false;
  }
  // O_NONBLOCK: should the path have become a FIFO since stat, opening it must not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat fst;
  if (::fstat(fd, &fst) != 0) {
    error = std::string("cannot read: ") + std::strerror(errno);
    return false;
  }
  if (!S_ISREG(fst.st_mode)) {
    error = std::string("is ") + FileKind(fst.st_mode) + ", not a mesh file";
    return false;
  }
  const std::uint64_t size = std::uint64_t(fst.st_size);
  if (fst.st_size < 0 || size > limits.maxFileBytes) {
    error = "the file is " + std::to_string(size) + " bytes, more than the limit of " +
            std::to_string(limits.maxFileBytes);
    return false;
  }
  std::string buffer;
  try {
    buffer.resize(std::size_t(size));
  } catch (const std::exception&) {
    error = "out of memory reading a file of " + std::to_string(size) + " bytes";
    return false;
  }
  std::size_t got = 0;
  while (got < buffer.size()) {
    const ssize_t r = ::read(fd, &buffer[got], buffer.size() - got);
    if (r < 0) {
      if (errno == EINTR) continue;
      error = std::string("cannot read: ") + std::strerror(errno);
      return false;
    }
    if (r == 0) {
      error = "the file became shorter while it was read (" + std::to_string(got) + " of " +
              std::to_string(size) + " bytes)";
      return false;
    }
    got += std::size_t(r);
  }
  return Dispatch(buffer.c_str(), buffer.size(), format, out, error, limits);
}

}  // namespace io
}  // namespace nvv
