#include "tests/support/test_meshes.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>

namespace qm::test {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::string shared_mesh(const std::string& name) { return std::string(QM_DATA_DIR) + "/" + name; }
std::string example(const std::string& name) { return std::string(QM_EXAMPLES_DIR) + "/" + name; }

namespace {

/// The scratch folders this test process made, removed when it exits (kept when
/// QUADMESH_KEEP_TEST_FILES is set, to look at a failure's files). Only by the
/// process that made them: a forked child that exits leaves them.
class ScratchFolders {
 public:
  void add(const std::filesystem::path& dir) {
    const std::lock_guard<std::mutex> lock(mutex_);
    dirs_.push_back(dir);
  }
  ~ScratchFolders() {
    if (::getpid() != owner_ || std::getenv("QUADMESH_KEEP_TEST_FILES") != nullptr) return;
    for (const std::filesystem::path& dir : dirs_) {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  }

 private:
  const pid_t owner_ = ::getpid();
  std::mutex mutex_;
  std::vector<std::filesystem::path> dirs_;
};

ScratchFolders& scratch_folders() {
  static ScratchFolders folders;
  return folders;
}

}  // namespace

std::string scratch_dir(const std::string& test_name) {
  namespace fs = std::filesystem;
  // the process id keeps two test runs at once (two checkouts, ctest -j) apart
  const fs::path dir =
      fs::temp_directory_path() / ("quadmesh-test-" + std::to_string(::getpid()) + "-" + test_name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  scratch_folders().add(dir);
  return dir.string();
}

std::string write_text(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

std::string plate_geo(double width, double height, double fillet, const std::vector<std::array<double, 3>>& holes) {
  std::string text = "SetFactory(\"OpenCASCADE\");\n";
  text += fillet > 0 ? fmt::format("Rectangle(1) = {{0, 0, 0, {}, {}, {}}};\n", width, height, fillet)
                     : fmt::format("Rectangle(1) = {{0, 0, 0, {}, {}}};\n", width, height);
  for (std::size_t i = 0; i < holes.size(); ++i)
    text += fmt::format("Disk({}) = {{{}, {}, 0, {}}};\n", i + 2, holes[i][0], holes[i][1], holes[i][2]);
  return text + fmt::format("BooleanDifference{{ Surface{{1}}; Delete; }}{{ Surface{{2:{}}}; Delete; }}\n",
                            holes.size() + 1);
}

std::string five_hole_plate_geo() {
  return plate_geo(150, 50, 0,
                   {{32.90, 18.35, 4.56}, {62.03, 25.02, 3.24}, {11.41, 22.08, 4.47}, {140.19, 14.53, 4.62},
                    {43.14, 28.38, 3.18}});
}

std::string long_arm_bracket_geo() {
  return "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 200, 40};\n"
         "Rectangle(100) = {100, 20, 0, 200, 40};\n"
         "BooleanDifference{ Surface{1}; Delete; }{ Surface{100}; Delete; }\n"
         "Disk(2) = {123.93, 10.68, 0, 3.53};\nDisk(3) = {24.34, 17.21, 0, 6.02};\n"
         "Disk(4) = {78.69, 28.56, 0, 7.76};\n"
         "BooleanDifference{ Surface{1}; Delete; }{ Surface{2:4}; Delete; }\n";
}

std::string edge_hole_plate_geo() {
  return plate_geo(150, 50, 10,
                   {{122.11, 20.79, 4.67}, {26.16, 42.26, 3.11}, {118.24, 39.33, 5.60}, {8.58, 26.46, 4.43},
                    {40.01, 13.69, 4.42}, {91.62, 24.62, 4.57}});
}

std::string crowded_holes_plate_geo() {
  return plate_geo(120, 50, 0,
                   {{52.78, 8.49, 3.91}, {106.45, 22.66, 4.62}, {53.22, 41.52, 3.04}, {90.68, 30.67, 4.48},
                    {56.39, 30.13, 3.15}, {21.40, 30.85, 3.52}, {79.84, 17.41, 3.98}});
}

TriangleSoup annulus(double r0, double r1, int rings, int sectors) {
  TriangleSoup s;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double r = r0 + (r1 - r0) * i / rings, t = 2 * kPi * j / sectors;
      s.points.emplace_back(r * std::cos(t), r * std::sin(t), 0.0);
    }
  auto id = [&](int i, int j) { return i * sectors + (j % sectors); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TriangleSoup disk(int rings, int sectors) {
  TriangleSoup s = annulus(0.2, 1.0, rings, sectors);
  const int center = static_cast<int>(s.points.size());
  s.points.emplace_back(0.0, 0.0, 0.0);
  for (int j = 0; j < sectors; ++j) s.triangles.push_back({center, j, (j + 1) % sectors});
  return s;
}

TriangleSoup sector(double theta, int rings, int sectors, double radius) {
  TriangleSoup s;
  s.points.emplace_back(0.0, 0.0, 0.0);
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j <= sectors; ++j) {
      const double r = radius * static_cast<double>(i) / rings, t = theta * j / sectors;
      s.points.emplace_back(r * std::cos(t), r * std::sin(t), 0.0);
    }
  auto id = [&](int i, int j) { return i == 0 ? 0 : 1 + (i - 1) * (sectors + 1) + j; };
  for (int j = 0; j < sectors; ++j) s.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TriangleSoup sphere() {
  TriangleSoup s;
  s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return s;
}

TriangleSoup torus(double R, double r, int u, int v) {
  TriangleSoup s;
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < v; ++j) {
      const double a = 2 * kPi * i / u, b = 2 * kPi * j / v;
      s.points.emplace_back((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
                            r * std::sin(b));
    }
  auto id = [&](int i, int j) { return (i % u) * v + (j % v); };
  for (int i = 0; i < u; ++i)
    for (int j = 0; j < v; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TriangleSoup moebius(int segments) {
  TriangleSoup s;
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * kPi * i / segments;
    for (double w : {-0.3, 0.3}) {
      const double rr = 1.0 + w * std::cos(a / 2);
      s.points.emplace_back(rr * std::cos(a), rr * std::sin(a), w * std::sin(a / 2));
    }
  }
  for (int i = 0; i < segments; ++i) {
    const int a0 = 2 * i, a1 = 2 * i + 1;
    // the last strip closes with a half twist: bottom meets top
    const bool last = i + 1 == segments;
    const int b0 = last ? 1 : 2 * (i + 1), b1 = last ? 0 : 2 * (i + 1) + 1;
    s.triangles.push_back({a0, b0, b1});
    s.triangles.push_back({a0, b1, a1});
  }
  return s;
}

TriangleSoup two_components() {
  TriangleSoup a = disk(2, 8), b = disk(3, 8);
  const int offset = static_cast<int>(a.points.size());
  for (Vec3 p : b.points) a.points.push_back(p + Vec3(5, 0, 0));
  for (Triangle t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

TriangleSoup bow_tie() {
  TriangleSoup s;
  s.points = {{0, 0, 0}, {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0}};
  s.triangles = {{0, 2, 1}, {0, 3, 4}};
  return s;
}

TriangleSoup book() {
  TriangleSoup s;
  s.points = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, -1, 0}};
  s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  return s;
}

TriangleSoup grid(int n) {
  TriangleSoup s;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) s.points.emplace_back(double(i) / n, double(j) / n, 0.0);
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TriangleSoup l_shape(int n) {
  TriangleSoup s;
  std::map<std::pair<int, int>, int> id;
  auto point = [&](int i, int j) {
    const auto [it, fresh] = id.emplace(std::make_pair(i, j), static_cast<int>(s.points.size()));
    if (fresh) s.points.emplace_back(double(i) / n, double(j) / n, 0.0);
    return it->second;
  };
  for (int i = 0; i < 2 * n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      if (i >= n && j >= n) continue;
      s.triangles.push_back({point(i, j), point(i + 1, j), point(i + 1, j + 1)});
      s.triangles.push_back({point(i, j), point(i + 1, j + 1), point(i, j + 1)});
    }
  return s;
}

/// `soup` without the triangles within `rings` rings of each vertex of `centres`
/// (each ring: the triangles at the vertices the last one reached), its unused
/// points dropped: a blocky hole cut out of a scan, as the shared ones were.
TriangleSoup cut_holes(const TriangleSoup& soup, const std::vector<int>& centres, int rings) {
  std::vector<std::vector<std::size_t>> at(soup.points.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int v : soup.triangles[f]) at[static_cast<std::size_t>(v)].push_back(f);
  std::vector<char> removed(soup.triangles.size(), 0);
  for (int centre : centres) {
    std::set<int> front{centre};
    for (int r = 0; r < rings; ++r) {
      std::set<int> next;
      for (int v : front)
        for (std::size_t f : at[static_cast<std::size_t>(v)])
          if (!removed[f]) {
            removed[f] = 1;
            next.insert(soup.triangles[f].begin(), soup.triangles[f].end());
          }
      front = std::move(next);
    }
  }
  TriangleSoup out;
  std::vector<int> index(soup.points.size(), -1);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    if (removed[f]) continue;
    Triangle t = soup.triangles[f];
    for (int& v : t) {
      if (index[static_cast<std::size_t>(v)] < 0) {
        index[static_cast<std::size_t>(v)] = static_cast<int>(out.points.size());
        out.points.push_back(soup.points[static_cast<std::size_t>(v)]);
      }
      v = index[static_cast<std::size_t>(v)];
    }
    out.triangles.push_back(t);
  }
  return out;
}

void write_obj(const TriangleSoup& soup, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  for (const Vec3& p : soup.points) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : soup.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

const std::vector<ManifestEntry>& manifest() {
  static const std::vector<ManifestEntry> entries = {
      {"kitten-2holes.obj", 2458, 4880, 2, 1, -2, true},
      {"kitten.off", 2500, 5000, 0, 1, 0, true},
      {"fertility-3holes.obj", 4433, 8823, 3, 4, -9, true},
      {"fertility.off", 4494, 9000, 0, 4, -6, true},
      {"chipped-torus.obj", 560, 1102, 1, 1, -1, true},
      {"flatmesh.off", 1936, 3646, 5, 0, -3, true},
      {"pig.off", 468, 891, 7, 0, -5, true},
      {"aqua-center.off", 5000, 9669, 3, 0, -1, true},
      {"bunny-open.obj", 34834, 69451, 5, 0, -3, true},
      {"bunny-open-large.obj", 139122, 277804, 5, 0, -3, true},
      {"hinge.stl", 598, 1212, 0, 5, -8, true},
      {"ogre-body-pinched.obj", 26034, 51992, 8, 1, -8, false},
  };
  return entries;
}

}  // namespace qm::test
