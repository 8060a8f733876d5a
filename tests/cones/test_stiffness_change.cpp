// The stiffening's low-rank change (stiffness_change.h): for triangles whose
// stiffness rises by d, the change of the fitting energy's matrix is d times each
// triangle's Dirichlet form area * grad(phi_i) . grad(phi_j) per axis, computed
// here from the hat functions' gradients (not the cotangents the library uses);
// C C^T is that matrix, whatever the elimination order, with one column less than
// the wedges per axis and connected patch.
#include "libquadmesh/cones/internal/stiffness_change.h"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

using namespace qm;

namespace {

/// Three triangles in space, one of them obtuse (a negative cotangent), one a
/// sliver; each corner its own wedge but for the two vertices the first two share.
TriangleSoup three_triangles() {
  TriangleSoup soup;
  soup.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.8, 0.1), Vec3(1.4, 0.9, -0.2), Vec3(3, 0.1, 0),
                 Vec3(5, 0.15, 0), Vec3(4, 0.2, 0.02)};
  soup.triangles = {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}};
  return soup;
}

CutGraph wedges_of(const TriangleSoup& soup) {
  CutGraph cut;
  cut.wedge = {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}};
  cut.cut_side.assign(soup.triangles.size(), {0, 0, 0});
  cut.wedge_count = 7;
  return cut;
}

/// d * area * grad(phi_i) . grad(phi_j) of triangle f, added at its wedges' values on both axes.
void add_dirichlet_form(const TriangleSoup& soup, const CutGraph& cut, std::size_t f, double d, Eigen::MatrixXd& A) {
  const Triangle& t = soup.triangles[f];
  const Vec3 p0 = soup.points[static_cast<std::size_t>(t[0])], p1 = soup.points[static_cast<std::size_t>(t[1])],
             p2 = soup.points[static_cast<std::size_t>(t[2])];
  const Vec3 normal = (p1 - p0).cross(p2 - p0);
  const double twice_area = normal.norm();
  const Vec3 n = normal / twice_area;
  const std::array<Vec3, 3> p{p0, p1, p2};
  std::array<Vec3, 3> grad;
  for (std::size_t i = 0; i < 3; ++i) grad[i] = n.cross(p[(i + 2) % 3] - p[(i + 1) % 3]) / twice_area;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (int axis = 0; axis < 2; ++axis)
        A(2 * cut.wedge[f][i] + axis, 2 * cut.wedge[f][j] + axis) += d * 0.5 * twice_area * grad[i].dot(grad[j]);
}

}  // namespace

TEST_CASE("the stiffening's change: the triangles' Dirichlet forms times the stiffness added, C C^T the same") {
  const TriangleSoup soup = three_triangles();
  const CutGraph cut = wedges_of(soup);
  const int variables = 2 * cut.wedge_count;
  const std::vector<double> before{1, 2, 4};

  SUBCASE("two patches: the first two triangles and the sliver") {
    const std::vector<double> after{2, 2.5, 8};
    const StiffnessChange change = stiffness_change(soup, cut, before, after);
    CHECK(change.wedges == std::vector<int>{0, 1, 2, 3, 4, 5, 6});
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(variables, variables);
    add_dirichlet_form(soup, cut, 0, 1.0, expected);
    add_dirichlet_form(soup, cut, 1, 0.5, expected);
    add_dirichlet_form(soup, cut, 2, 4.0, expected);
    const double scale = expected.cwiseAbs().maxCoeff();
    CHECK(scale > 1);  // the sliver's form is large: the comparisons are relative to it
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(variables, variables);
    for (const auto& t : change.matrix) matrix(t.row(), t.col()) += t.value();
    CHECK((matrix - expected).cwiseAbs().maxCoeff() < 1e-12 * scale);

    // in the order of the unknowns and reversed: the same product, 2 x (4 - 1 + 3 - 1) columns
    for (const bool reversed : {false, true}) {
      CAPTURE(reversed);
      std::vector<int> position(static_cast<std::size_t>(variables));
      for (int v = 0; v < variables; ++v) position[static_cast<std::size_t>(v)] = reversed ? variables - 1 - v : v;
      const auto columns = change_columns(change, position, variables, 400);
      REQUIRE(columns);
      const Eigen::MatrixXd C = Eigen::MatrixXd(*columns);
      CHECK(C.cols() == 2 * 5);
      CHECK((C * C.transpose() - expected).cwiseAbs().maxCoeff() < 1e-10 * scale);
      // triangular in the order: on each axis, each column starts (its first row in
      // the order, where its path in L starts) after the one before
      std::vector<int> first(static_cast<std::size_t>(C.cols()), variables);
      for (Eigen::Index c = 0; c < C.cols(); ++c)
        for (int v = 0; v < variables; ++v)
          if (C(v, c) != 0) first[static_cast<std::size_t>(c)] = std::min(first[static_cast<std::size_t>(c)], position[static_cast<std::size_t>(v)]);
      for (std::size_t c = 0; c + 1 < first.size(); ++c)
        if (c + 1 != 5) CHECK(first[c] < first[c + 1]);
    }
    // too many wedges for a dense factorization: nothing
    CHECK_FALSE(change_columns(change, std::vector<int>(static_cast<std::size_t>(variables), 0), variables, 6));
  }

  SUBCASE("one triangle: its wedge 3 takes no part") {
    const std::vector<double> after{1, 3, 4};
    const StiffnessChange change = stiffness_change(soup, cut, before, after);
    CHECK(change.wedges == std::vector<int>{1, 2, 3});
    std::vector<int> position(static_cast<std::size_t>(variables));
    std::iota(position.begin(), position.end(), 0);
    const auto columns = change_columns(change, position, variables, 400);
    REQUIRE(columns);
    const Eigen::MatrixXd C = Eigen::MatrixXd(*columns);
    CHECK(C.cols() == 2 * 2);
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(variables, variables);
    add_dirichlet_form(soup, cut, 1, 1.0, expected);
    CHECK((C * C.transpose() - expected).cwiseAbs().maxCoeff() < 1e-10 * expected.cwiseAbs().maxCoeff());
    CHECK(C.row(0).cwiseAbs().maxCoeff() == 0);
  }
}

TEST_CASE("the stiffening's change: nothing where no stiffness changed; a form not semidefinite gives no columns") {
  const TriangleSoup soup = three_triangles();
  const CutGraph cut = wedges_of(soup);
  const std::vector<double> stiffness{1, 2, 4};
  const StiffnessChange none = stiffness_change(soup, cut, stiffness, stiffness);
  CHECK(none.matrix.empty());
  CHECK(none.wedges.empty());
  const std::vector<int> position(14, 0);
  const auto columns = change_columns(none, position, 14, 400);
  REQUIRE(columns);
  CHECK(columns->cols() == 0);

  StiffnessChange indefinite = stiffness_change(soup, cut, stiffness, {2, 2, 4});
  indefinite.block(0, 0) -= 10;
  CHECK_FALSE(change_columns(indefinite, std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13}, 14, 400));
}
