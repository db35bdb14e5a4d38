// Mesh file readers for PLY (ascii, binary little and big endian), OBJ, OFF and STL (binary and
// ascii), in plain C++14 with the standard library only. They read untrusted files: the whole
// file is read into memory with its real size (only regular files are read), every count in a
// header is checked against the bytes actually present before anything is allocated, every
// index is checked before it is used, and every failure is a false return with a one-sentence
// reason. Polygons are fan-triangulated (v0, vi, vi+1) up to ReadLimits::maxPolygonCorners.
#ifndef NVV_IO_MESH_READER_H
#define NVV_IO_MESH_READER_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace nvv {
namespace io {

enum class MeshFormat { Ply, Obj, Off, Stl };

struct MeshData {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals;        // empty, or one per vertex (the file had normals)
  std::vector<std::array<std::uint8_t, 4>> colors;  // empty, or one per vertex (the file had colours)
  std::vector<float> quality;                       // empty, or one per vertex (PLY 'quality')
  std::vector<std::array<int, 3>> triangles;        // polygons fan-triangulated (v0, vi, vi+1)
  std::size_t polygons = 0;         // faces with more than 3 corners that were triangulated
  std::size_t fileFaces = 0;        // faces (polygons and triangles) read; PLY tristrips: strips
  std::size_t skippedElements = 0;  // PLY: records of elements not read (edges, materials, ...);
                                    // OBJ: lines ('l') and points ('p'); OFF: edges declared
  std::size_t skippedLines = 0;     // OBJ: lines with a keyword the reader does not use (vt, g, ...)
  std::string formatDetail;         // e.g. "binary_little_endian", "ascii", "COFF"
  void Clear() { *this = MeshData(); }
};

struct ReadLimits {
  // A polygon with more corners is refused (a face list that long is nearly always corruption).
  std::uint32_t maxPolygonCorners = 1u << 16;
  // Files larger than this are refused before reading (4 GiB).
  std::uint64_t maxFileBytes = std::uint64_t(4) << 30;
  // At most this many vertices and triangles (the mesh library indexes them with int).
  std::uint64_t maxVertices = 0x7fffffff;
  std::uint64_t maxTriangles = 0x7fffffff;
};

// Reads a mesh file, its format chosen by the extension. True on success; otherwise false with a
// one-sentence reason in `error` (naming the line or byte offset where that helps) and `out`
// cleared.
bool ReadMeshFile(const std::string& path, MeshData& out, std::string& error, const ReadLimits& limits = ReadLimits());
// Reads a mesh from memory (the same parsers as ReadMeshFile).
bool ReadMeshBytes(const char* data, std::size_t size, MeshFormat format, MeshData& out, std::string& error,
                   const ReadLimits& limits = ReadLimits());
// The format from the file name's extension (.ply, .obj, .off, .stl, any case); false when none.
bool FormatFromPath(const std::string& path, MeshFormat& format);
// "PLY", "OBJ", "OFF" or "STL".
const char* FormatName(MeshFormat format);

}  // namespace io
}  // namespace nvv

#endif
