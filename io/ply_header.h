// The header of a PLY file, read and checked before CGAL's reader sees the file.
//
// CGAL's PLY reader trusts its header: a 'property' line before any 'element'
// line (a misspelt "element vertex") makes it crash, and a count it believes
// makes it allocate. So the header is parsed here first, every line is checked,
// and what the mesh readers need (vertex x y z, a face list of indices) must be
// there.
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace qm::io {

enum class PlyEncoding { ascii, binary_little_endian, binary_big_endian };

/// One value type of the PLY format: char uchar short ushort int uint float double
/// (or int8 ... float64).
struct PlyType {
  int size = 0;  ///< bytes in a binary file
  bool is_float = false;
  bool is_signed = false;
};

struct PlyProperty {
  std::string name;
  PlyType value;       ///< a scalar's type, or a list's item type
  bool is_list = false;
  PlyType length;      ///< a list's length type (an integer type)
  long line = 0;       ///< where the header declares it
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  long line = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  std::size_t vertex_element = 0;  ///< index in `elements` of "vertex"
  std::size_t face_element = 0;    ///< index in `elements` of "face"
  std::size_t face_indices = 0;    ///< index in the face's properties of its index list
  long lines = 0;                  ///< header lines, end_header included
};

/// Reads the header from the start of `in` (left just after end_header) into
/// `header`. Returns "FILE: line N: what is wrong" for the first line that is not
/// a valid header line, or for a header without 'element vertex' (x y z float or
/// double), 'element face' (a list of int or uint named vertex_indices or
/// vertex_index) or end_header.
std::optional<std::string> read_ply_header(std::istream& in, const std::string& path,
                                           PlyHeader& header);

}  // namespace qm::io
