#include "tests/io/deck_fixture.h"

#include <cmath>
#include <map>

namespace qm::test {

io::OutputMesh rectangle_deck_mesh(const RectangleDeckOptions& o) {
  io::OutputMesh mesh;
  const auto id = [&](int i, int j) { return j * (o.nx + 1) + i; };
  for (int j = 0; j <= o.ny; ++j)
    for (int i = 0; i <= o.nx; ++i) {
      double x = 2.0 * i / o.nx, y = 1.0 * j / o.ny;
      if (i > 0 && i < o.nx && j > 0 && j < o.ny) {  // a fixed pattern, not random: reproducible
        x += o.distortion * (2.0 / o.nx) * std::sin(1.7 * i + 2.3 * j);
        y += o.distortion * (1.0 / o.ny) * std::cos(2.9 * i - 1.1 * j);
      }
      mesh.points.emplace_back(x, y, 0.0);
    }
  std::map<std::pair<int, int>, int> mid;
  const auto mid_of = [&](int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    mesh.points.push_back((mesh.points[static_cast<std::size_t>(a)] + mesh.points[static_cast<std::size_t>(b)]) / 2);
    return mid[key] = static_cast<int>(mesh.points.size()) - 1;
  };
  for (int j = 0; j < o.ny; ++j)
    for (int i = 0; i < o.nx; ++i) {
      std::vector<int> f{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      if (o.clockwise) f = {f[0], f[3], f[2], f[1]};
      if (o.quadratic)
        for (std::size_t k = 0; k < 4; ++k) f.push_back(mid_of(f[k], f[(k + 1) % 4]));
      mesh.faces.push_back(f);
    }
  io::LineGroup left{"left", {}, {}}, right{"right", {}, {}}, bottom{"bottom", {}, {}}, top{"top", {}, {}};
  const auto add = [&](io::LineGroup& g, int a, int b) {
    g.edges.push_back({a, b});
    if (o.quadratic) g.mids.push_back(mid_of(a, b));
  };
  for (int i = 0; i < o.nx; ++i) {
    add(bottom, id(i, 0), id(i + 1, 0));
    add(top, id(i + 1, o.ny), id(i, o.ny));
  }
  for (int j = 0; j < o.ny; ++j) {
    add(right, id(o.nx, j), id(o.nx, j + 1));
    add(left, id(0, j + 1), id(0, j));
  }
  mesh.line_groups = {bottom, left, right, top};
  if (o.bend_radius > 0)
    for (Vec3& p : mesh.points) {
      const double t = p.x() / o.bend_radius;
      p = Vec3(o.bend_radius * std::sin(t), p.y(), o.bend_radius * (1 - std::cos(t)));
    }
  return mesh;
}

}  // namespace qm::test
