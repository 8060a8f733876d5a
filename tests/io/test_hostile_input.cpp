// Hostile and broken input files (issue 22): whatever a file holds, the readers
// end in one bad_input error that names the file and the place, in bounded time
// and memory, and the program prints it as one line and exits 3 without an
// output file.
//
// Every case runs the program first, under a memory limit of 1 GB and a time
// limit of 60 s, and only then calls the reader in this process: a reader that
// hangs or allocates gigabytes shows up as a failed check, not as a test program
// that hangs or exhausts the machine.
#include "io/read_polygon_mesh.h"
#include "io/read_surface.h"
#include "libquadmesh/core/error.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

using namespace qm;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Run {
  int status = -1;
  std::string err;
};

/// `quadmesh ARGS` as `bash -c 'ulimit -v 1000000; timeout 60 quadmesh ARGS'`
/// (without the ulimit under AddressSanitizer: test::address_space_bound).
Run quadmesh_capped(const std::string& args) {
  static int counter = 0;
  const std::string dir = test::scratch_dir("hostile_run_" + std::to_string(counter++));
  const std::string inner = test::address_space_bound(1000000) + "timeout 60 '" + QM_QUADMESH_BIN +
                            "' " + args + " >/dev/null 2>'" + dir + "/err' </dev/null";
  const std::string command = "bash -c \"" + inner + "\"";
  const int raw = std::system(command.c_str());
  Run run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.err = slurp(dir + "/err");
  return run;
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

/// The program refuses `input` with exit status 3 and exactly one stderr line
/// besides its progress lines, "quadmesh: error: ..." containing `needle`, for `info` and (if `mesh`)
/// for `mesh INPUT -o OUT.msh`, leaving no OUT.msh. False if not (the checks
/// say why), so that a caller can stop before reading the file in-process.
bool program_refuses(const std::string& input, const std::string& needle, bool mesh = true) {
  CAPTURE(input);
  bool ok = true;
  std::vector<std::string> commands = {"info " + quoted(input)};
  const std::string output = test::scratch_dir("hostile_out") + "/out.msh";
  if (mesh) commands.push_back("mesh " + quoted(input) + " -o " + quoted(output));
  for (const std::string& command : commands) {
    CAPTURE(command);
    const Run run = quadmesh_capped(command);
    CAPTURE(run.err);
    CHECK(run.status != 124);  // not killed by the time limit
    CHECK(run.status == 3);
    std::vector<std::string> lines;
    std::istringstream in(run.err);
    // every line but the progress lines ("[   0.00 s] reading ...", as test_cli)
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line[0] != '[') lines.push_back(line);
    CHECK(lines.size() == 1);
    const bool named = lines.size() == 1 && lines[0].rfind("quadmesh: error: ", 0) == 0 &&
                       lines[0].find(needle) != std::string::npos;
    CHECK(named);
    CHECK_FALSE(std::filesystem::exists(output));
    ok = ok && run.status == 3 && named && !std::filesystem::exists(output);
  }
  return ok;
}

/// The message both readers throw for `path`; each must throw bad_input.
std::string reader_error(const std::string& path) {
  std::string surface, polygons;
  try {
    io::read_surface(path);
    FAIL("read_surface read " << path);
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::bad_input);
    surface = e.what();
  }
  try {
    io::read_polygon_mesh(path);
    FAIL("read_polygon_mesh read " << path);
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::bad_input);
    polygons = e.what();
  }
  CHECK(surface == polygons);
  return surface;
}

/// The program and both readers refuse `path` with a message that contains
/// `needle` (which names the file and the place).
void refused(const std::string& path, const std::string& needle, bool mesh = true) {
  CAPTURE(path);
  REQUIRE(program_refuses(path, needle, mesh));
  const std::string message = reader_error(path);
  CAPTURE(message);
  CHECK(message.find(needle) != std::string::npos);
  CHECK(message.find('\n') == std::string::npos);
}

std::string write_bytes(const std::string& dir, const std::string& name, const std::string& bytes) {
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// --- little-endian binary building blocks -----------------------------------

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
std::string u32(std::uint32_t v) {
  std::string out;
  put_u32(out, v);
  return out;
}
void put_f32(std::string& out, float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  put_u32(out, bits);
}

/// An n x n grid of unit squares, each split in two: its points and triangles.
struct Grid {
  std::vector<std::array<float, 3>> points;
  std::vector<std::array<int, 3>> triangles;
};
Grid grid(int nx, int ny) {
  Grid g;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) g.points.push_back({float(i), float(j), 0.0f});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
      g.triangles.push_back({a, b, c});
      g.triangles.push_back({a, c, d});
    }
  return g;
}

/// Binary little-endian PLY, faces as 'list int int' (so a length can be 2^31 - 1).
std::string binary_ply(const Grid& g) {
  std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(g.points.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(g.triangles.size()) +
                    "\nproperty list int int vertex_indices\nend_header\n";
  for (const auto& p : g.points)
    for (float c : p) put_f32(out, c);
  for (const auto& t : g.triangles) {
    put_u32(out, 3);
    for (int v : t) put_u32(out, static_cast<std::uint32_t>(v));
  }
  return out;
}

/// Binary STL of the grid's triangles.
std::string binary_stl(const Grid& g) {
  std::string out(80, ' ');
  put_u32(out, static_cast<std::uint32_t>(g.triangles.size()));
  for (const auto& t : g.triangles) {
    for (int i = 0; i < 3; ++i) put_f32(out, i == 2 ? 1.0f : 0.0f);  // normal
    for (int v : t)
      for (float c : g.points[static_cast<std::size_t>(v)]) put_f32(out, c);
    out.append(2, '\0');
  }
  return out;
}

void put_u64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void put_f64(std::string& out, double d) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  put_u64(out, bits);
}

/// Binary MSH 4.1 of the grid (little endian, one node and one triangle block).
std::string msh41_binary(const Grid& g) {
  const std::size_t n = g.points.size(), m = g.triangles.size();
  std::string out = "$MeshFormat\n4.1 1 8\n";
  put_u32(out, 1);
  out += "\n$EndMeshFormat\n$Nodes\n";
  for (std::uint64_t v : {std::uint64_t{1}, std::uint64_t{n}, std::uint64_t{1}, std::uint64_t{n}}) put_u64(out, v);
  for (std::uint32_t v : {2, 1, 0}) put_u32(out, v);
  put_u64(out, n);
  for (std::size_t i = 0; i < n; ++i) put_u64(out, i + 1);
  for (const auto& p : g.points)
    for (float c : p) put_f64(out, c);
  out += "\n$EndNodes\n$Elements\n";
  for (std::uint64_t v : {std::uint64_t{1}, std::uint64_t{m}, std::uint64_t{1}, std::uint64_t{m}}) put_u64(out, v);
  for (std::uint32_t v : {2, 1, 2}) put_u32(out, v);
  put_u64(out, m);
  for (std::size_t e = 0; e < m; ++e) {
    put_u64(out, e + 1);
    for (int v : g.triangles[e]) put_u64(out, static_cast<std::uint64_t>(v) + 1);
  }
  out += "\n$EndElements\n";
  return out;
}

/// Binary MSH 2.2 of the grid (little endian, one group of triangles).
std::string msh22_binary(const Grid& g) {
  std::string out = "$MeshFormat\n2.2 1 8\n";
  put_u32(out, 1);
  out += "\n$EndMeshFormat\n$Nodes\n" + std::to_string(g.points.size()) + "\n";
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    put_u32(out, static_cast<std::uint32_t>(i + 1));
    for (float c : g.points[i]) put_f64(out, c);
  }
  out += "\n$EndNodes\n$Elements\n" + std::to_string(g.triangles.size()) + "\n";
  for (std::uint32_t v : {std::uint32_t{2}, static_cast<std::uint32_t>(g.triangles.size()), std::uint32_t{2}})
    put_u32(out, v);
  for (std::size_t e = 0; e < g.triangles.size(); ++e) {
    for (std::uint32_t v : {static_cast<std::uint32_t>(e + 1), std::uint32_t{1}, std::uint32_t{1}}) put_u32(out, v);
    for (int v : g.triangles[e]) put_u32(out, static_cast<std::uint32_t>(v + 1));
  }
  out += "\n$EndElements\n";
  return out;
}

/// MSH 2.2 of the grid, its node and element counts changed by the deltas.
std::string msh22(const Grid& g, int node_delta, int element_delta) {
  std::ostringstream out;
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
      << static_cast<int>(g.points.size()) + node_delta << "\n";
  for (std::size_t i = 0; i < g.points.size(); ++i)
    out << i + 1 << " " << g.points[i][0] << " " << g.points[i][1] << " " << g.points[i][2] << "\n";
  out << "$EndNodes\n$Elements\n" << static_cast<int>(g.triangles.size()) + element_delta << "\n";
  for (std::size_t e = 0; e < g.triangles.size(); ++e) {
    out << e + 1 << " 2 2 0 1";
    for (int v : g.triangles[e]) out << " " << v + 1;
    out << "\n";
  }
  out << "$EndElements\n";
  return out.str();
}

/// MSH 4.1 of the grid (one node block, one triangle block), the blocks' sizes
/// changed by the deltas (the section totals are left true).
std::string msh41(const Grid& g, int node_block_delta, int element_block_delta) {
  const std::size_t n = g.points.size(), m = g.triangles.size();
  std::ostringstream out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 " << n << " 1 " << n << "\n2 1 0 "
      << static_cast<int>(n) + node_block_delta << "\n";
  for (std::size_t i = 0; i < n; ++i) out << i + 1 << "\n";
  for (const auto& p : g.points) out << p[0] << " " << p[1] << " " << p[2] << "\n";
  out << "$EndNodes\n$Elements\n1 " << m << " 1 " << m << "\n2 1 2 "
      << static_cast<int>(m) + element_block_delta << "\n";
  for (std::size_t e = 0; e < m; ++e) {
    out << e + 1;
    for (int v : g.triangles[e]) out << " " << v + 1;
    out << "\n";
  }
  out << "$EndElements\n";
  return out.str();
}

}  // namespace

TEST_CASE("defect 1: only regular files are read, and text formats must be text") {
  const std::string dir = test::scratch_dir("hostile_not_regular");
  namespace fs = std::filesystem;

  const std::string fifo = dir + "/x.off";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  REQUIRE(program_refuses(fifo, "x.off: is a FIFO (named pipe), not a mesh file"));
  CHECK(reader_error(fifo) == fifo + ": is a FIFO (named pipe), not a mesh file");

  // devices that never end, under a mesh file's name
  fs::create_symlink("/dev/zero", dir + "/zero.obj");
  refused(dir + "/zero.obj", "zero.obj: is a character device, not a mesh file");
  fs::create_symlink("/dev/urandom", dir + "/urandom.stl");
  refused(dir + "/urandom.stl", "urandom.stl: is a character device, not a mesh file");

  fs::create_directory(dir + "/folder.ply");
  refused(dir + "/folder.ply", "folder.ply: is a directory, not a mesh file");

  // regular files of NUL bytes or binary garbage under text formats' names
  const std::string zeros(4 << 20, '\0');
  for (const char* name : {"zeros.obj", "zeros.off", "zeros.msh"})
    refused(write_bytes(dir, name, zeros), std::string(name) + ": line 1: not text (byte 0x00)");
  refused(write_bytes(dir, "zeros.ply", "ply\nformat ascii 1.0\n" + zeros),
          "zeros.ply: line 3: not text (byte 0x00)");
  refused(write_bytes(dir, "zeros.stl", "solid zeros\n" + zeros),
          "zeros.stl: line 2: not text (byte 0x00)");

  std::mt19937 random(7);
  std::string garbage(1 << 20, '\0');
  for (char& c : garbage) c = static_cast<char>(0x80 | (random() & 0x7f));  // no line end at all
  garbage[1000] = '\x01';
  refused(write_bytes(dir, "garbage.obj", "v 0 0 0\n" + garbage),
          "garbage.obj: line 2: not text (byte 0x01)");
  // a line longer than any mesh file has (no control byte in it)
  refused(write_bytes(dir, "long.off", "OFF\n" + std::string(2 << 20, '7')),
          "long.off: line 2: not text (a line over 1 MiB)");
}

TEST_CASE("an OFF face whose vertex count overflows a long is refused, named by its line (a fuzz finding)") {
  const std::string dir = test::scratch_dir("hostile_off_face_count");
  // the count saturates at LONG_MAX; checking for its indices by count + 1 overflowed
  refused(write_bytes(dir, "huge-face.off",
                      "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n" + std::string("3") +
                          std::string(36, '0') + " 0 2 3\n"),
          "huge-face.off: line 8: expected a face 'n i1 ... in' with n >= 3");
}

TEST_CASE("defect 2: a PLY header is checked line by line before CGAL reads it") {
  const std::string dir = test::scratch_dir("hostile_ply_header");
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  auto ply = [&](const std::string& name, const std::string& header) {
    return write_bytes(dir, name, header + body);
  };
  const std::string good =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  CHECK(io::read_surface(ply("good.ply", good)).soup.triangles.size() == 1);

  // the crash: 'property' lines with no element before them
  auto misspelt = good;
  misspelt.replace(misspelt.find("element vertex"), 14, "elment vertex");
  refused(ply("misspelt.ply", misspelt), "misspelt.ply: line 3: unknown PLY header line 'elment vertex 3'");
  misspelt = good;
  misspelt.replace(misspelt.find("element vertex"), 14, "element vertx");
  refused(ply("vertx.ply", misspelt), "vertx.ply: line 3: expected 'element vertex N', found 'element vertx'");

  struct Case {
    const char* name;
    std::string from, to, needle;
  };
  const std::vector<Case> cases = {
      {"magic.ply", "ply\n", "plx\n", "line 1: a PLY file starts with 'ply', found 'plx'"},
      {"format.ply", "format ascii 1.0", "format ascii 2.0", "line 2: expected 'format ascii 1.0'"},
      {"encoding.ply", "format ascii 1.0", "format text 1.0", "line 2: unknown PLY format 'text'"},
      {"negative.ply", "element vertex 3", "element vertex -3", "line 3: expected 'element NAME COUNT'"},
      {"huge.ply", "element vertex 3", "element vertex 3000000000",
       "line 3: 3000000000 vertices: more than 2^31 - 1"},
      {"overflow.ply", "element face 1", "element face 99999999999999999999999",
       "line 7: expected 'element NAME COUNT'"},
      {"type.ply", "property float y", "property real y", "line 5: unknown property type 'real'"},
      {"int_x.ply", "property float x", "property int x", "line 4: vertex property 'x' must be float or double"},
      {"no_z.ply", "property float z", "property float w", "line 3: element vertex has no property 'z'"},
      {"no_face.ply", "element face 1", "element facet 1", "line 9: the header declares no 'element face'"},
      {"no_list.ply", "property list uchar int vertex_indices", "property int vertex_indices",
       "line 8: face property 'vertex_indices' must be a list of int or uint"},
      {"float_length.ply", "list uchar int", "list float int",
       "line 8: a list's length type must be an integer type, found 'float'"},
      {"empty_line.ply", "property float z\n", "property float z\n\n", "line 7: empty line in the PLY header"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.name);
    std::string header = good;
    REQUIRE(header.find(c.from) != std::string::npos);
    header.replace(header.find(c.from), c.from.size(), c.to);
    refused(ply(c.name, header), std::string(c.name) + ": " + c.needle, false);
  }
  // a header that never ends
  refused(write_bytes(dir, "endless.ply", good.substr(0, good.find("end_header"))),
          "endless.ply: the PLY header has no 'end_header' (truncated?)", false);
}

TEST_CASE("defect 3: binary PLY counts are checked against the file size before any reading") {
  const std::string dir = test::scratch_dir("hostile_ply_counts");
  const Grid g = grid(10, 10);  // 121 vertices, 200 triangles: 4.8 KB
  const std::string ply = binary_ply(g);
  CHECK(io::read_surface(write_bytes(dir, "good.ply", ply)).soup.triangles.size() == 200);
  const std::size_t faces_at = ply.find("end_header\n") + 11 + 12 * g.points.size();

  // the 3.9 KB file that took 8.2 GB: face 7's list length is 2^31 - 1
  std::string bad = ply;
  bad.replace(faces_at + 7 * 16, 4, u32(0x7fffffff));
  refused(write_bytes(dir, "length.ply", bad),
          "length.ply: face 7: a list of 2147483647 values runs past the end of the file");

  bad = ply;
  bad.replace(faces_at + 9 * 16, 4, u32(0xfffffffe));  // -2
  refused(write_bytes(dir, "negative.ply", bad), "negative.ply: face 9: negative list length -2");

  bad = ply;
  bad.replace(faces_at + 3 * 16 + 8, 4, u32(1u << 30));
  refused(write_bytes(dir, "index.ply", bad),
          "index.ply: face 3: vertex index 1073741824 is not in 0..120");

  bad = ply;  // counts that the file cannot hold
  bad.replace(bad.find("element vertex 121"), 18, "element vertex 1210000");
  refused(write_bytes(dir, "vertices.ply", bad),
          "vertices.ply: line 3: 'element vertex 1210000' cannot be true: the file has 4652 bytes "
          "after its header");
  bad = ply;
  bad.replace(bad.find("element face 200"), 16, "element face 2147483647");
  refused(write_bytes(dir, "faces.ply", bad), "faces.ply: line 7: 'element face 2147483647' cannot be true");

  // truncated, and counts too small: data left over
  refused(write_bytes(dir, "cut.ply", ply.substr(0, ply.size() - 10)),
          "cut.ply: line 7: 'element face 200' cannot be true");
  // a quad and a flag per face, the last flag cut off: the counts fit, the data ends
  std::string quad =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list int int vertex_indices\nproperty int flag\nend_header\n";
  for (float c : {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}) put_f32(quad, c);
  for (std::uint32_t v : {4, 0, 1, 2, 3}) put_u32(quad, v);
  refused(write_bytes(dir, "cut2.ply", quad), "cut2.ply: the file ends in face 0 of 1 (truncated?)");
  bad = ply;
  bad.replace(bad.find("element face 200"), 16, "element face 190");
  refused(write_bytes(dir, "small.ply", bad),
          "small.ply: 160 bytes follow the last face (is a count in the header too small?)");

  // NaN coordinate
  bad = ply;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::string bits;
  put_f32(bits, nan);
  bad.replace(ply.find("end_header\n") + 11 + 12 * 5 + 4, 4, bits);
  refused(write_bytes(dir, "nan.ply", bad), "nan.ply: vertex 5: coordinate y is not a finite number");

  // ASCII: a list length of 2^31 - 1, and a vertex count the file cannot hold
  const std::string ascii_header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  refused(write_bytes(dir, "ascii_length.ply", ascii_header + "0 0 0\n1 0 0\n0 1 0\n2147483647 0 1 2\n"),
          "ascii_length.ply: the file ends in face 0 of 1 (truncated?)");
  std::string big = ascii_header;
  big.replace(big.find("vertex 3"), 8, "vertex 2000000000");
  refused(write_bytes(dir, "ascii_count.ply", big + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
          "ascii_count.ply: line 3: 'element vertex 2000000000' cannot be true");
}

TEST_CASE("defect 3: binary STL and MSH counts that the file cannot hold") {
  const std::string dir = test::scratch_dir("hostile_stl_msh_counts");
  const Grid g = grid(4, 3);
  std::string stl = binary_stl(g);
  CHECK(io::read_surface(write_bytes(dir, "good.stl", stl)).soup.triangles.size() == 24);
  stl.replace(80, 4, u32(0xffffffff));
  refused(write_bytes(dir, "count.stl", stl),
          "count.stl: binary STL header announces 4294967295 triangles (214748364834 bytes) but "
          "the file has 1284 bytes");

  // MSH counts far beyond the file: no allocation, the lines are counted
  std::string msh = msh22(g, 0, 0);
  msh.replace(msh.find("$Nodes\n20\n"), 10, "$Nodes\n4000000000\n");
  refused(write_bytes(dir, "nodes.msh", msh), "nodes.msh: line 5: $Nodes declares 4000000000 nodes but 20 follow");
  msh = msh41(g, 0, 0);
  msh.replace(msh.find("2 1 2 24\n"), 9, "2 1 2 2147483647\n");
  refused(write_bytes(dir, "block.msh", msh),
          "block.msh: line 50: the element block declares 2147483647 elements but 24 follow");
  msh = msh22(g, 0, 0);
  msh.replace(msh.find("$Nodes\n20\n"), 10, "$Nodes\n-20\n");
  refused(write_bytes(dir, "negative.msh", msh), "negative.msh: line 5: expected the number of nodes after $Nodes");

  // binary MSH: the counts are checked against the bytes left
  const std::string b41 = msh41_binary(g), b22 = msh22_binary(g);
  CHECK(io::read_surface(write_bytes(dir, "good41.msh", b41)).soup.triangles.size() == 24);
  CHECK(io::read_surface(write_bytes(dir, "good22.msh", b22)).soup.triangles.size() == 24);
  const std::size_t nodes41 = b41.find("$Nodes\n") + 7, elements41 = b41.find("$Elements\n") + 10;
  msh = b41;
  msh.replace(nodes41 + 8, 8, std::string("\0\0\0\0\0\1\0\0", 8));  // 2^40 nodes in all
  refused(write_bytes(dir, "total41b.msh", msh),
          "total41b.msh: $Nodes declares 1099511627776 nodes but its blocks hold 20");
  msh = b41;
  msh.replace(nodes41 + 32 + 12, 8, std::string("\0\0\0\0\2\0\0\0", 8));  // block: 2^33 nodes
  refused(write_bytes(dir, "nodes41b.msh", msh), "nodes41b.msh: $Nodes block 1 declares 8589934592 nodes; the");
  msh = b41;
  msh.replace(elements41 + 32 + 12, 4, u32(0x7fffffff));
  refused(write_bytes(dir, "elements41b.msh", msh),
          "elements41b.msh: $Elements block 1 declares 2147483647 elements; the");
  msh = b22;
  msh.replace(msh.find("$Nodes\n20\n"), 10, "$Nodes\n4000000000\n");
  refused(write_bytes(dir, "nodes22b.msh", msh), "nodes22b.msh: $Nodes declares 4000000000 nodes; the");
  msh = b22;
  msh.replace(msh.find("$Elements\n24\n") + 13 + 4, 4, u32(1u << 30));
  refused(write_bytes(dir, "elements22b.msh", msh),
          "elements22b.msh: $Elements: a group declares 1073741824 elements");
}

TEST_CASE("defect 4: no silent loss: a NaN in binary STL, MSH counts that disagree with the data") {
  const std::string dir = test::scratch_dir("hostile_silent_loss");
  const Grid g = grid(23, 4);  // 120 nodes, 184 triangles
  std::string stl = binary_stl(g);
  std::string nan;
  put_f32(nan, std::numeric_limits<float>::quiet_NaN());
  stl.replace(84 + 16 * 50 + 12 + 12 + 4, 4, nan);  // triangle 17 (from 1), corner 2, y
  refused(write_bytes(dir, "nan.stl", stl),
          "nan.stl: triangle 17 of 184: corner 2 has a coordinate that is not a finite number (nan)");
  stl = binary_stl(g);
  std::string inf;
  put_f32(inf, -std::numeric_limits<float>::infinity());
  stl.replace(84 + 183 * 50 + 12 + 24 + 8, 4, inf);
  refused(write_bytes(dir, "inf.stl", stl), "inf.stl: triangle 184 of 184: corner 3 has a coordinate");

  CHECK(io::read_surface(write_bytes(dir, "good22.msh", msh22(g, 0, 0))).soup.triangles.size() == 184);
  CHECK(io::read_surface(write_bytes(dir, "good41.msh", msh41(g, 0, 0))).soup.triangles.size() == 184);
  // format 2.2: the section counts
  refused(write_bytes(dir, "elements22.msh", msh22(g, 0, -10)),
          "elements22.msh: line 128: $Elements declares 174 elements but 184 follow");
  refused(write_bytes(dir, "elements22_more.msh", msh22(g, 0, 10)),
          "elements22_more.msh: line 128: $Elements declares 194 elements but 184 follow");
  refused(write_bytes(dir, "nodes22.msh", msh22(g, -10, 0)),
          "nodes22.msh: line 5: $Nodes declares 110 nodes but 120 follow");
  // format 4.1: the block sizes
  refused(write_bytes(dir, "elements41.msh", msh41(g, 0, -10)),
          "elements41.msh: line 250: the element block declares 174 elements but 184 follow");
  refused(write_bytes(dir, "elements41_more.msh", msh41(g, 0, 10)),
          "elements41_more.msh: line 250: the element block declares 194 elements but 184 follow");
  refused(write_bytes(dir, "nodes41.msh", msh41(g, -10, 0)),
          "nodes41.msh: line 6: the node block declares 110 nodes but 120 follow");
  refused(write_bytes(dir, "nodes41_more.msh", msh41(g, 10, 0)),
          "nodes41_more.msh: line 6: the node block declares 130 nodes but 120 follow");
  // format 4.1: a section total that its blocks contradict
  std::string msh = msh41(g, 0, 0);
  msh.replace(msh.find("$Elements\n1 184 1 184\n"), 22, "$Elements\n1 174 1 184\n");
  refused(write_bytes(dir, "total41.msh", msh),
          "total41.msh: line 249: $Elements declares 174 elements but its blocks hold 184");
  // OFF: faces after the declared ones
  refused(write_bytes(dir, "faces.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n"),
          "faces.off: line 7: data after the 1 faces the header declares");
}

TEST_CASE("defect 5: truncated files, huge indices, Inf and NaN in text formats") {
  const std::string dir = test::scratch_dir("hostile_other");
  const Grid g = grid(23, 4);
  const std::string msh = msh22(g, 0, 0);
  refused(write_bytes(dir, "cut.msh", msh.substr(0, msh.size() / 2)),
          "cut.msh: section '$Elements' opened at line 127 is not closed (truncated?)");
  std::string nan_msh = msh;
  nan_msh.replace(nan_msh.find("\n3 2 0 0\n"), 9, "\n3 2 nan 0\n");
  refused(write_bytes(dir, "nan.msh", nan_msh), "nan.msh: line 8: coordinate 'nan' is not a finite number");
  std::string short_element = msh;
  short_element.replace(short_element.find("\n5 2 2 0 1 "), 11, "\n5 2 2 0 ");
  refused(write_bytes(dir, "element.msh", short_element),
          "element.msh: line 133: an element of type 2 with 2 tags has 7 values, not 8");

  // MSH 4.1: Gmsh crashed (SIGSEGV) on an element node tag far beyond the others
  std::string node41 = msh41(g, 0, 0);
  const std::size_t element5 = node41.find("\n5 ", node41.find("$Elements")) + 3;
  node41.replace(element5, node41.find(' ', element5) - element5, "3000000000");
  refused(write_bytes(dir, "node41.msh", node41),
          "node41.msh: line 255: element 5 refers to node '3000000000', but the node tags go from 1 to 120");
  std::string node41b = msh41_binary(g);
  const std::size_t element4 = node41b.find("$Elements\n") + 10 + 32 + 20 + 3 * 32 + 8;
  std::string tag;
  put_u64(tag, 3000000000u);
  node41b.replace(element4, 8, tag);
  refused(write_bytes(dir, "node41b.msh", node41b),
          "node41b.msh: $Elements block 1: element 4 refers to node 3000000000, but the node tags go "
          "from 1 to 120");

  const std::string ascii_ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  refused(write_bytes(dir, "inf.ply", ascii_ply + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"),
          "inf.ply: line 11: coordinate 'inf' is not a finite number");
  refused(write_bytes(dir, "index.ply", ascii_ply + "0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967296\n"),
          "index.ply: line 13: vertex index '4294967296' is not in 0..2");
  refused(write_bytes(dir, "extra.ply", ascii_ply + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n"),
          "extra.ply: line 14: data after the last face (is a count in the header too small?)");
  refused(write_bytes(dir, "two.ply", ascii_ply + "0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n2 0 1\n"),
          "two.ply: line 13: face 0: 2 vertices (a face needs at least 3)");
  refused(write_bytes(dir, "cut.ply", ascii_ply + "0 0 0\n1 0 0\n0 1"),
          "cut.ply: line 3: 'element vertex 3' cannot be true");

  refused(write_bytes(dir, "index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999\n"),
          "index.off: line 6: vertex index '99999999999' is not in 0..2");
  refused(write_bytes(dir, "count.off", "OFF\n3000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
          "count.off: the file ends after 4 of 3000000000 vertices (truncated?)");
  refused(write_bytes(dir, "negative.off", "OFF\n-3 1 0\n0 0 0\n"),
          "negative.off: line 2: expected the counts 'vertices faces edges'");
  refused(write_bytes(dir, "nan.obj", "v 0 0 0\nv 1 0 0\nv 0 NaN 0\nf 1 2 3\n"),
          "nan.obj: line 3: coordinate 'NaN' is not a finite number");
  refused(write_bytes(dir, "index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775807\n"),
          "index.obj: line 4: face refers to vertex 9223372036854775807, but the file defines only 3");
  refused(write_bytes(dir, "cut.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
          "cut.stl: ASCII STL without 'endsolid' (truncated?)");
  refused(write_bytes(dir, "short.stl", std::string(60, 'x')),
          "short.stl: 60 bytes is too short for a binary STL and it is not ASCII STL");
}

TEST_CASE("found by fuzz_read_off: a line of form feeds is blank, not a line without tokens") {
  // the blank-line test skipped spaces, tabs and CRs, the tokenizer also form feeds
  // and vertical tabs: "\f" passed as a content line with no first token, and the
  // OFF and OBJ diagnoses read tokens[0] of an empty list (SIGSEGV in the program)
  const std::string dir = test::scratch_dir("hostile_formfeed");
  refused(write_bytes(dir, "ff.off", "\f\n\n#0\n\n\n\n3\f\f\f\f\f\f\f\f\f\f\f\f\f\f\f\f\ff"), "ff.off: line ");
  refused(write_bytes(dir, "ff.obj", "\v\f\nv 0 0 0\n\f\nv 1 0 0\nv 0 1 0\n\v\nf 1 2\n"), "ff.obj: line ");
}
