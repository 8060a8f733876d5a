#include "libquadmesh/quality/curved_jacobian.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>

namespace qm {

namespace {

/// Reference coordinates of the nodes, in the element order.
constexpr std::array<std::array<double, 2>, 9> node_xi{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0},
                                                        {0, 1}, {-1, 0}, {0, 0}}};

/// d/dxi and d/deta of the shape functions of an n-node quad at (x, y).
void shape_derivatives(std::size_t n, double x, double y, std::array<double, 9>& dx, std::array<double, 9>& dy) {
  if (n == 4) {
    for (std::size_t i = 0; i < 4; ++i) {
      const double xi = node_xi[i][0], yi = node_xi[i][1];
      dx[i] = xi * (1 + y * yi) / 4;
      dy[i] = yi * (1 + x * xi) / 4;
    }
  } else if (n == 8) {  // serendipity
    for (std::size_t i = 0; i < 4; ++i) {
      const double xi = node_xi[i][0], yi = node_xi[i][1];
      dx[i] = xi * (1 + y * yi) * (2 * x * xi + y * yi) / 4;
      dy[i] = yi * (1 + x * xi) * (x * xi + 2 * y * yi) / 4;
    }
    for (std::size_t i = 4; i < 8; ++i) {
      const double xi = node_xi[i][0], yi = node_xi[i][1];
      if (xi == 0) {
        dx[i] = -x * (1 + y * yi);
        dy[i] = yi * (1 - x * x) / 2;
      } else {
        dx[i] = xi * (1 - y * y) / 2;
        dy[i] = -y * (1 + x * xi);
      }
    }
  } else {  // 9-node Lagrange: products of the 1D quadratics at -1, 0, 1
    const auto l = [](double t, double ti) { return ti < 0 ? t * (t - 1) / 2 : ti > 0 ? t * (t + 1) / 2 : 1 - t * t; };
    const auto dl = [](double t, double ti) { return ti < 0 ? t - 0.5 : ti > 0 ? t + 0.5 : -2 * t; };
    for (std::size_t i = 0; i < 9; ++i) {
      dx[i] = dl(x, node_xi[i][0]) * l(y, node_xi[i][1]);
      dy[i] = l(x, node_xi[i][0]) * dl(y, node_xi[i][1]);
    }
  }
}

/// x_xi x x_eta at (x, y).
Vec3 area_vector(const std::vector<Vec3>& points, const std::vector<int>& element, double x, double y) {
  std::array<double, 9> dx{}, dy{};
  shape_derivatives(element.size(), x, y, dx, dy);
  Vec3 tx = Vec3::Zero(), ty = Vec3::Zero();
  for (std::size_t i = 0; i < element.size(); ++i) {
    tx += dx[i] * points[static_cast<std::size_t>(element[i])];
    ty += dy[i] * points[static_cast<std::size_t>(element[i])];
  }
  return tx.cross(ty);
}

}  // namespace

double jacobian_ratio(const std::vector<Vec3>& points, const std::vector<int>& element) {
  if (element.size() != 4 && element.size() != 8 && element.size() != 9)
    throw AssertionError(fmt::format("a quad has 4, 8 or 9 nodes, not {}", element.size()));
  const Vec3 centre = area_vector(points, element, 0, 0);
  if (!(centre.norm() > 0)) return -1;
  const Vec3 n = centre.normalized();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  constexpr int k = jacobian_samples_per_side;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double x = -1 + 2.0 * i / (k - 1), y = -1 + 2.0 * j / (k - 1);
      const double jac = area_vector(points, element, x, y).dot(n);
      lo = std::min(lo, jac);
      hi = std::max(hi, jac);
    }
  return hi > 0 ? lo / hi : -1;
}

CurvedJacobians curved_jacobians(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& elements) {
  CurvedJacobians out;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const double r = jacobian_ratio(points, elements[k]);
    if (r <= 0) ++out.non_positive;
    if (out.worst < 0 || r < out.min_ratio) {
      out.min_ratio = r;
      out.worst = static_cast<int>(k);
    }
  }
  return out;
}

}  // namespace qm
