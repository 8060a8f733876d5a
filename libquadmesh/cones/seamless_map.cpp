#include "libquadmesh/cones/seamless_map.h"

#include "libquadmesh/cones/cone_winding.h"
#include "libquadmesh/cones/internal/boundary_ligaments.h"
#include "libquadmesh/cones/internal/boundary_segments.h"
#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/cones/internal/low_rank_columns.h"
#include "libquadmesh/cones/internal/ordered_cholesky.h"
#include "libquadmesh/cones/internal/stiffness_change.h"
#include "libquadmesh/cones/internal/translation_classes.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/internal/union_find.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace qm {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// Weight of a constraint against the fitting energy (whose weights are cotangents).
constexpr double penalty_weight = 1e8;
/// Weight of the pull that fixes the map's translation before quantization does.
constexpr double gauge_weight = 1e-3;
/// Rounds of stiffening after quantization, and the factor a folded triangle's
/// weight takes each round.
constexpr int max_stiffening_rounds = 12;
constexpr double stiffening_factor = 2.0;
/// Stiffening stops when this many rounds in a row leave no fewer folds than before.
constexpr int stiffening_patience = 4;
/// The stiffness no triangle exceeds (the constraints' penalty stays far above).
constexpr double max_stiffness = 1e3;
/// A value this close to an integer after a solve is taken as integer.
constexpr double integer_tolerance = 1e-6;
/// The rounding's solves between two factorizations: each value made integer adds
/// a diagonal penalty, a rank-one change, solved by the Woodbury identity on the
/// last factorization (a column of its inverse per value: LowRankColumns) until
/// this many.
constexpr std::size_t max_low_rank = 64;
/// The rounding's fixes it may still take back: a step's (a cone's position or a
/// translation, two values) and a value tested on a fraction (DeterminedValues).
/// The low-rank solves keep them when the others enter the factorization.
constexpr std::size_t max_tentative_fixes = 3;
/// The columns of H0^-1 one solve computes at least, where as many values are
/// expected to be fixed (LowRankColumns).
constexpr std::size_t column_batch = 4;
/// The most wedges a stiffening round's change may have for the factorization to
/// be updated by it (its dense factorization, cubic in them, then costs less than
/// the system's: stiffness_change.h); past them the system is factored again.
constexpr std::size_t max_update_wedges = 400;
/// Seams and fixed values hold when no residual is above this (lattice units): a
/// rounding to other than the nearest integer that breaks them is refused, and no
/// stiffening is tried on integers that break them.
constexpr double max_consistent_residual = 1e-4;
/// The residual the seam rows and fixed values are held to at the end (lattice
/// units), by at most this many multiplier updates (PenaltySolver::hold_constraints).
constexpr double constraint_tolerance = 1e-10;
constexpr int max_multiplier_rounds = 4;

/// A real linear constraint sum coefficient * variable = rhs.
struct Row {
  std::vector<std::pair<int, double>> terms;
  double rhs = 0;
};

/// The unknowns: two per wedge (Re W, Im W), then two per cut edge (Re t, Im t).
int real_of(int wedge) { return 2 * wedge; }
int imag_of(int wedge) { return 2 * wedge + 1; }

/// i^q (x + i y), component c, is sign[q][c] times component from[q][c] of (x, y):
/// q = 0: (x, y); 1: (-y, x); 2: (-x, -y); 3: (y, -x).
constexpr int turned_from[4][2] = {{0, 1}, {1, 0}, {0, 1}, {1, 0}};
constexpr double turned_sign[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};

/// The rows of W_g(p) - i^q W_f(p) - t = 0 (two real rows).
void add_transition(int wedge_g, int wedge_f, int q, int t_var, std::vector<Row>& rows) {
  for (int c = 0; c < 2; ++c) {
    Row r;
    r.terms.push_back({2 * wedge_g + c, 1.0});
    r.terms.push_back({2 * wedge_f + turned_from[q][c], -turned_sign[q][c]});
    r.terms.push_back({t_var + c, -1.0});
    rows.push_back(std::move(r));
  }
}

/// Per triangle, the factor taking its local frame to the map's target: the metric's
/// scale e^u / size, turned into the field's frame.
std::vector<Complex> target_scales(const TriangleSoup& soup, const Eigen::VectorXd& u, const CrossField& field,
                                   double size) {
  std::vector<Complex> scale(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const double uf = (u[t[0]] + u[t[1]] + u[t[2]]) / 3.0;
    scale[f] = std::polar(std::exp(uf) / size, -field.angle[f]);
  }
  return scale;
}

/// The fitting energy's matrix (where H is given) and right side (the cotan form
/// of the Dirichlet energy of W - target on each triangle; the target's gradient
/// the scale, or the scale times `shape` where given).
void add_fitting_energy(const TriangleSoup& soup, const std::vector<Complex>& scales, const FitShape* shape,
                        const CutGraph& cut, const std::vector<double>& stiffness, Triplets* H, Eigen::VectorXd& b) {
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const CornerValues x = local_corners(soup, f);
    const auto cot = corner_cotangents(soup, f);
    const Complex scale = scales[f];
    const bool sheared = shape && shape->anticonformal[f] != Complex(0, 0);
    for (int k = 0; k < 3; ++k) {
      const auto i = static_cast<std::size_t>((k + 1) % 3), j = static_cast<std::size_t>((k + 2) % 3);
      const double w = 0.5 * stiffness[f] * cot[static_cast<std::size_t>(k)];
      const Complex e = x[j] - x[i];
      const Complex d = sheared ? scale * (shape->conformal[f] * e + shape->anticonformal[f] * std::conj(e)) : scale * e;
      const int wi = cut.wedge[f][i], wj = cut.wedge[f][j];
      for (int c = 0; c < 2; ++c) {
        const int vi = 2 * wi + c, vj = 2 * wj + c;
        const double dc = c == 0 ? d.real() : d.imag();
        if (H) {
          H->emplace_back(vi, vi, w);
          H->emplace_back(vj, vj, w);
          H->emplace_back(vi, vj, -w);
          H->emplace_back(vj, vi, -w);
        }
        b[vj] += w * dc;
        b[vi] -= w * dc;
      }
    }
  }
}

/// A cut edge's translation variable (the first of two) and, at each of its ends,
/// the transition it takes part in. Two cut edges with one such transition in
/// common have one translation up to a quarter turn (translation_classes.h).
struct Translation {
  int variable = -1;
  std::array<TransitionEnd, 2> ends{};
};

/// Transitions across cut edges and boundary alignment; returns the translation of
/// every cut edge (in order of discovery).
std::vector<Translation> add_seams(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const CrossField& field, const CutGraph& cut, std::vector<Row>& rows,
                                   int& variables) {
  std::vector<Translation> translations;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto ks = static_cast<std::size_t>(k), ke = static_cast<std::size_t>((k + 1) % 3);
      const EdgeCorner g = adjacency.find(t[ke], t[ks]);
      if (g.face < 0) {
        // boundary side: Im (or Re) of W equal at both ends
        const int c = field.boundary_axis[f][ks] == 0 ? 1 : 0;
        Row r;
        r.terms.push_back({2 * cut.wedge[f][ke] + c, 1.0});
        r.terms.push_back({2 * cut.wedge[f][ks] + c, -1.0});
        rows.push_back(std::move(r));
        continue;
      }
      if (!cut.cut_side[f][ks] || static_cast<std::size_t>(g.face) < f) continue;
      const auto gf = static_cast<std::size_t>(g.face);
      const int t_var = variables;
      variables += 2;
      const int q = field.quarter_turns[f][ks];
      // a = t[k] sits at g's corner g.j, b = t[k + 1] at g.i
      const int ga = cut.wedge[gf][static_cast<std::size_t>(g.j)], gb = cut.wedge[gf][static_cast<std::size_t>(g.i)];
      add_transition(ga, cut.wedge[f][ks], q, t_var, rows);
      add_transition(gb, cut.wedge[f][ke], q, t_var, rows);
      Translation translation;
      translation.variable = t_var;
      translation.ends[0] = {ga, cut.wedge[f][ks], q};
      translation.ends[1] = {gb, cut.wedge[f][ke], q};
      translations.push_back(translation);
    }
  }
  return translations;
}

/// The values quantization makes integer, in the order of their phases: the
/// cones' positions first (the interior ones, and the boundary corners in an even
/// number of quads other than 2; a cut translation ending at a cone is (1 - i^q) times
/// the cone's position, integer once the position is, while an integer translation
/// may leave the cone at a half-integer point), then the boundary lines, then the
/// cut translations; or (RoundingOrder::translations_first) the translations, the
/// cones, the lines (a value left on a half is avoided as it is rounded: quantize).
struct IntegerCandidates {
  std::vector<std::vector<int>> phases;
  /// per phase, whether its values are lattice vectors (a cone's position, a
  /// translation: both coordinates rounded in one step) or lines (one value)
  std::vector<char> paired;
  /// per variable, the candidate it equals (times same_sign) by the seam rows (-1:
  /// none but itself): set from that candidate's integer at the end
  std::vector<int> same_as;
  std::vector<double> same_sign;
};

IntegerCandidates integer_candidates(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                     const CrossField& field, const CutGraph& cut, const std::vector<int>& quads,
                                     const std::vector<Translation>& translations, int variables,
                                     RoundingOrder order) {
  IntegerCandidates out;
  out.same_as.assign(static_cast<std::size_t>(variables), -1);
  out.same_sign.assign(static_cast<std::size_t>(variables), 1.0);
  std::vector<std::vector<int>>& phases = out.phases;
  phases.resize(3);
  std::vector<char> seen(soup.points.size(), 0);
  // a boundary line's values at its wedges are one value (the seam rows tie them):
  // one of them is made integer, not each (each would cost the rounding a solve)
  UnionFind line(static_cast<std::size_t>(2 * cut.wedge_count));
  std::vector<int> line_values;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto ks = static_cast<std::size_t>(k);
      const int v = soup.triangles[f][ks];
      const auto sv = static_cast<std::size_t>(v);
      const int wedge = cut.wedge[f][ks];
      // a boundary corner in an even number of quads (4 at a slit-like tip: the
      // plate round a 16-degree notch) lies on one boundary line with both its
      // sides: the line fixes one coordinate, the rounding of the position the
      // other (else the tip falls between lattice points, and the quads' boundary
      // runs past it into S). An odd count is two lines' crossing, 2 a straight side
      const bool cone = adjacency.boundary_vertex[sv] ? quads[sv] >= 4 && quads[sv] % 2 == 0 : quads[sv] != 4;
      if (cone && !seen[sv]++) {
        phases[0].push_back(real_of(wedge));
        phases[0].push_back(imag_of(wedge));
      }
      const int axis = field.boundary_axis[f][ks];
      if (axis >= 0) {
        // both ends: a cut that ends at a boundary vertex parts its two sides' wedges
        const int end = cut.wedge[f][static_cast<std::size_t>((k + 1) % 3)];
        const int a = axis == 0 ? imag_of(wedge) : real_of(wedge), b = axis == 0 ? imag_of(end) : real_of(end);
        line.unite(a, b);
        line_values.push_back(a);
        line_values.push_back(b);
      }
    }
  std::vector<int> first_of(static_cast<std::size_t>(2 * cut.wedge_count), -1);
  for (int v : line_values) {
    int& first = first_of[static_cast<std::size_t>(line.find(v))];
    if (first < 0) {
      first = v;
      phases[1].push_back(v);
    } else if (first != v) {
      out.same_as[static_cast<std::size_t>(v)] = first;
    }
  }
  // likewise the translations of a cut path's edges: one per path, the others a
  // quarter turn of it
  std::vector<std::array<TransitionEnd, 2>> ends;
  for (const Translation& t : translations) ends.push_back(t.ends);
  const TranslationClasses classes = translation_classes(ends);
  for (std::size_t i = 0; i < translations.size(); ++i) {
    const int t = translations[i].variable;
    const auto r = static_cast<std::size_t>(classes.representative[i]);
    if (r == i) {
      phases[2].push_back(t);
      phases[2].push_back(t + 1);
      continue;
    }
    const int k = classes.quarter_turns[i];
    for (int c = 0; c < 2; ++c) {
      const auto v = static_cast<std::size_t>(t + c);
      out.same_as[v] = translations[r].variable + turned_from[k][c];
      out.same_sign[v] = turned_sign[k][c];
    }
  }
  out.paired = {1, 0, 1};
  if (order == RoundingOrder::translations_first) {
    std::swap(phases[0], phases[2]);  // translations, lines, cones
    std::swap(phases[1], phases[2]);  // translations, cones, lines
    out.paired = {1, 1, 0};
  }
  return out;
}

/// The fitting energy with the seam rows and the fixed values as penalties,
/// solved again after each fix. A fix only adds to a diagonal entry, and the
/// stiffening only changes values, so the sparsity pattern never changes: it is
/// ordered and analysed once per ordering. Both are positive semidefinite terms
/// of low rank, so the factorization is updated by them (OrderedCholesky::update)
/// rather than computed again: a map factors its system once, where no fix in the
/// factorization is taken back (the rounding's fixes enter it by the Woodbury
/// identity first, solve_low_rank, and 64 at a time by an update). Ordered as
/// `ordering` says (MapOrdering, analyse()), its minimum degree ordering first
/// unless `nested_dissection_first`.
class PenaltySolver {
 public:
  /// `stop`, when set, is asked before every solve (stop_request.h: Stopped).
  PenaltySolver(int variables, Triplets energy, Eigen::VectorXd rhs, std::vector<Row> rows,
                bool nested_dissection_first, MapOrdering& ordering, StopRequest stop = {})
      : n_(variables),
        rows_(std::move(rows)),
        minimum_degree_first_(!nested_dissection_first),
        ordering_(ordering),
        columns_(variables, max_low_rank, column_batch),
        stop_(std::move(stop)) {
    set_energy(std::move(energy), std::move(rhs));
  }

  void fix(int variable, double value) { fixed_.push_back({variable, value}); }

  /// Takes the last `count` fixes back (a rounding tried and refused).
  void unfix(std::size_t count) {
    fixed_.resize(fixed_.size() - count);
    if (fixed_.size() < factored_) refactor_ = true;  // a full solve had them: factor again
  }

  void set_energy(Triplets energy, Eigen::VectorXd rhs) {
    base_rhs_ = with_seam_rhs(std::move(rhs));
    for (const Row& r : rows_)
      for (const auto& [i, ci] : r.terms)
        for (const auto& [j, cj] : r.terms) energy.emplace_back(i, j, penalty_weight * ci * cj);
    for (int v = 0; v < n_; ++v) energy.emplace_back(v, v, 0.0);  // every diagonal entry in the pattern
    base_ = SparseMatrix(n_, n_);
    base_.setFromTriplets(energy.begin(), energy.end());
  }

  /// The energy changed by `change` (its matrix) and `rhs` (its right side, whole):
  /// where the factorization can be updated (no fix in it taken back, the change
  /// of few enough wedges and semidefinite), it is updated by the values fixed
  /// since it was computed and by the change's columns (stiffness_change.h), and
  /// true is returned; else nothing is changed and false returned (set_energy
  /// then, and solve()).
  bool update_energy(const StiffnessChange& change, Eigen::VectorXd rhs) {
    if (refactor_ || updates_refused_) return false;
    const std::optional<SparseMatrix> C = change_columns(change, solver_.positions(), n_, max_update_wedges);
    if (!C || !update_factor(*C)) return false;
    for (const auto& t : change.matrix) base_.coeffRef(t.row(), t.col()) += t.value();
    base_rhs_ = with_seam_rhs(std::move(rhs));
    factored_solution_ = solve_factored();
    return true;
  }

  /// The fixes since the last factorization, but for the last `keep`, added to it
  /// by a rank-k update (their penalties w e_v e_v^T: C's columns sqrt(w) e_v), and
  /// its solution; false where it cannot be updated.
  bool commit_fixes(std::size_t keep) {
    if (!update_factor(SparseMatrix(n_, 0), keep)) return false;
    factored_solution_ = solve_factored();
    return true;
  }

  /// The minimizer on the factorization as it stands (after update_energy).
  const Eigen::VectorXd& updated_solution() const { return factored_solution_; }

  /// The minimizer with every value fixed so far: a factorization of the whole system.
  Eigen::VectorXd solve() {
    stop_if_requested(stop_);
    SparseMatrix H = base_;
    for (const auto& [v, value] : fixed_) H.coeffRef(v, v) += penalty_weight;
    const Analysis analysed_before = analysed_;
    analyse(H);
    // an updated factor is an LDL' one: analysed again (the same permutation), it
    // is factored as the others
    if (updated_ && analysed_ == analysed_before) solver_.analyse_by(H, solver_.permutation());
    updated_ = false;
    solver_.factorize(H);
    if (solver_.info() != Eigen::Success)
      throw Error(ErrorCode::solver, "the seamless map's system could not be factored");
    ++factorizations_;
    if (analysed_ == Analysis::nested_dissection) ++nested_dissection_factorizations_;
    factored_ = fixed_.size();
    Eigen::VectorXd z = solve_factored();
    factored_solution_ = z;
    columns_.clear();
    refactor_ = false;
    return z;
  }

  /// Orders and analyses H's pattern where solve() needs it: at the first solve by
  /// the minimum degree ordering, and by the shared nested dissection where it
  /// pays (MapOrdering), from the first solve of a map from a lattice shift and
  /// from the second of another map.
  void analyse(const SparseMatrix& H) {
    if (analysed_ == Analysis::none && !minimum_degree_first_ && ordering_.has_nested_dissection()) {
      // the cone set's nested dissection is known (it paid on this very pattern):
      // no minimum degree analysis to decide it again
      nested_dissection_pays_ = true;
    } else if (analysed_ == Analysis::none) {
      solver_.analyzePattern(H);
      analysed_ = Analysis::minimum_degree;
      nested_dissection_pays_ = ordering_.nested_dissection_pays(solver_.cholmod().fl, n_);
      if (minimum_degree_first_) {
        // the maps from lattice offsets, made where this one folds, will ask for it
        if (nested_dissection_pays_)
          ordering_.offer_nested_dissection([H] { return OrderedCholesky().analyse_by_nested_dissection(H); });
        return;
      }
    }
    if (analysed_ == Analysis::nested_dissection || !nested_dissection_pays_) return;
    const std::vector<int>& permutation =
        ordering_.nested_dissection([&] { return solver_.analyse_by_nested_dissection(H); });
    solver_.analyse_by(H, permutation);
    analysed_ = Analysis::nested_dissection;
  }

  /// The same minimizer after more values were fixed, from the last factorization
  /// (H0, its solution x0): with U the fixed values' unit vectors since then, Y =
  /// H0^-1 U and M = I / w + U^T Y, the penalized system's solution is x0 + Y
  /// M^-1 (values - U^T x0) (Woodbury; the same as solve() up to round-off). Past
  /// max_low_rank of them, they are added to the factorization (commit_fixes).
  Eigen::VectorXd solve_low_rank() {
    stop_if_requested(stop_);
    if (refactor_) return solve();
    std::size_t k = fixed_.size() - factored_;
    if (k == 0) return factored_solution_;
    // the rounding's last fixes may still be taken back: left to the low-rank
    // solve, so that taking them back needs no new factorization
    if (k > max_low_rank && !commit_fixes(max_tentative_fixes)) return solve();
    k = fixed_.size() - factored_;
    std::vector<int> values(k);
    for (std::size_t i = 0; i < k; ++i) values[i] = fixed_[factored_ + i].first;
    const Eigen::MatrixXd& Y = columns_.align(values, [&](const Eigen::MatrixXd& units) {
      Eigen::MatrixXd solved = solver_.solve(units);
      if (solver_.info() != Eigen::Success) throw Error(ErrorCode::solver, "the seamless map's solve failed");
      return solved;
    });
    const auto K = static_cast<Eigen::Index>(k);
    Eigen::MatrixXd M = Eigen::MatrixXd::Identity(K, K) / penalty_weight;
    Eigen::VectorXd gap(K);
    for (Eigen::Index i = 0; i < K; ++i) {
      const auto& [v, value] = fixed_[factored_ + static_cast<std::size_t>(i)];
      for (Eigen::Index j = 0; j < K; ++j) M(i, j) += Y(v, j);
      gap[i] = value - factored_solution_[v];
    }
    const Eigen::VectorXd c = M.partialPivLu().solve(gap);
    Eigen::VectorXd z = factored_solution_ + Y.leftCols(K) * c;
    if (!z.allFinite()) return solve();
    return z;
  }

  /// The values the rounding is likely to fix next, nearest first: a solve for a
  /// missing column fills its batch with theirs.
  void expect(std::vector<int> variables) { columns_.expect(std::move(variables)); }

  /// z (the minimizer with every value fixed so far) with the seam rows and fixed
  /// values held to round-off: the penalty leaves them off by the energy's pull
  /// over penalty_weight (up to 1e-4 where the stiffening weighs a triangle 1e3).
  /// Multiplier updates of the augmented Lagrangian method, z <- z - H^-1 w C^T
  /// (C z - d), each one back-substitution on the system's factorization; each
  /// shrinks the residual by about the energy's weight over the penalty's.
  Eigen::VectorXd hold_constraints(Eigen::VectorXd z) {
    // the factorization with every value fixed: the low-rank solves' values added
    // to it by an update, or a new one
    if (refactor_ || factored_ != fixed_.size()) z = commit_fixes(0) ? factored_solution_ : solve();
    for (int round = 0; round < max_multiplier_rounds && max_residual(z) > constraint_tolerance; ++round) {
      Eigen::VectorXd pull = Eigen::VectorXd::Zero(n_);
      for (const Row& r : rows_) {
        double s = -r.rhs;
        for (const auto& [i, c] : r.terms) s += c * z[i];
        for (const auto& [i, c] : r.terms) pull[i] += penalty_weight * c * s;
      }
      for (const auto& [v, value] : fixed_) pull[v] += penalty_weight * (z[v] - value);
      const Eigen::VectorXd step = solver_.solve(pull);
      if (solver_.info() != Eigen::Success || !step.allFinite()) break;
      z -= step;
    }
    return z;
  }

  const std::vector<Row>& rows() const { return rows_; }
  std::size_t factorizations() const { return factorizations_; }
  std::size_t updates() const { return updates_; }
  std::size_t nested_dissection_factorizations() const { return nested_dissection_factorizations_; }
  const LowRankColumns& low_rank_columns() const { return columns_; }

  double max_residual(const Eigen::VectorXd& z) const {
    double worst = 0;
    for (const Row& r : rows_) {
      double s = -r.rhs;
      for (const auto& [i, c] : r.terms) s += c * z[i];
      worst = std::max(worst, std::abs(s));
    }
    for (const auto& [v, value] : fixed_) worst = std::max(worst, std::abs(z[v] - value));
    return worst;
  }

 private:
  /// The factorization updated by C C^T, C the columns sqrt(w) e_v of the values
  /// fixed since it was computed but the last `keep`, then `more`. False, and
  /// nothing changed, where it cannot be: fixes in it were taken back, or CHOLMOD
  /// refused an update before (then the next solve() factors anew).
  bool update_factor(const SparseMatrix& more, std::size_t keep = 0) {
    if (refactor_ || updates_refused_) return false;
    QM_ASSERT(keep <= fixed_.size() - factored_);
    const std::size_t pending = fixed_.size() - factored_ - keep;
    std::vector<Eigen::Triplet<double>> entries;
    for (std::size_t k = 0; k < pending; ++k)
      entries.emplace_back(fixed_[factored_ + k].first, static_cast<int>(k), std::sqrt(penalty_weight));
    for (Eigen::Index c = 0; c < more.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(more, c); it; ++it)
        entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(pending + static_cast<std::size_t>(c)),
                             it.value());
    SparseMatrix C(n_, static_cast<Eigen::Index>(pending) + more.cols());
    C.setFromTriplets(entries.begin(), entries.end());
    C.makeCompressed();
    updated_ = true;  // (refused, the factor is symbolic: solve() analyses it again)
    if (!solver_.update(C)) {
      updates_refused_ = true;
      refactor_ = true;
      return false;
    }
    ++updates_;
    factored_ += pending;
    columns_.clear();
    return true;
  }

  /// `rhs` with the seam rows' penalty terms.
  Eigen::VectorXd with_seam_rhs(Eigen::VectorXd rhs) const {
    for (const Row& r : rows_)
      for (const auto& [i, ci] : r.terms) rhs[i] += penalty_weight * ci * r.rhs;
    return rhs;
  }

  /// The solution on the factorization as it stands, which holds fixed_[0, factored_).
  Eigen::VectorXd solve_factored() {
    Eigen::VectorXd b = base_rhs_;
    for (std::size_t k = 0; k < factored_; ++k) b[fixed_[k].first] += penalty_weight * fixed_[k].second;
    Eigen::VectorXd z = solver_.solve(b);
    if (solver_.info() != Eigen::Success || !z.allFinite())
      throw Error(ErrorCode::solver, "the seamless map's solve failed");
    return z;
  }

  int n_;
  std::vector<Row> rows_;                       ///< the seams' rows
  std::vector<std::pair<int, double>> fixed_;   ///< values made integer
  SparseMatrix base_;                           ///< energy + seam penalties
  Eigen::VectorXd base_rhs_;
  OrderedCholesky solver_;
  bool minimum_degree_first_ = true;
  MapOrdering& ordering_;
  enum class Analysis { none, minimum_degree, nested_dissection } analysed_ = Analysis::none;
  bool nested_dissection_pays_ = false;
  std::size_t factorizations_ = 0, nested_dissection_factorizations_ = 0;
  std::size_t factored_ = 0;          ///< fixed_[0, factored_) are in the factorization
  Eigen::VectorXd factored_solution_;  ///< its solution
  LowRankColumns columns_;            ///< H0^-1 e_v of the values fixed since, and of some expected
  bool refactor_ = false;  ///< fixes in the factorization were taken back
  bool updated_ = false;   ///< the factorization was updated (update_factor) since it was computed
  bool updates_refused_ = false;  ///< CHOLMOD refused an update: none tried again
  std::size_t updates_ = 0;
  StopRequest stop_;
};

/// Sets exactly what the seam rows make of exact values: a row z_g = i^q z_f + t
/// whose other terms are exact gives its last one exactly, repeated until none
/// does. `exact` starts as the values made integer. Without it a wedge tied to an
/// integer only by the rows keeps the penalty's error (up to 1e-5 after the
/// stiffening): at a corner or cone whose wedges differ, the extraction's reference
/// chart may be such a wedge, and the lattice point then lies beside the vertex
/// (off S's boundary at a corner: a stray point).
void propagate_exact_values(const std::vector<Row>& rows, std::vector<char>& exact, Eigen::VectorXd& z) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const Row& r : rows) {
      int unknown = -1, count = 0;
      double known = 0, coefficient = 0;
      for (const auto& [i, c] : r.terms) {
        if (exact[static_cast<std::size_t>(i)]) {
          known += c * z[i];
        } else {
          ++count;
          unknown = i;
          coefficient = c;
        }
      }
      if (count != 1 || std::abs(coefficient) != 1.0) continue;
      z[unknown] = (r.rhs - known) / coefficient;
      exact[static_cast<std::size_t>(unknown)] = 1;
      changed = true;
    }
  }
}

/// The integers to try for values `v` at z, nearest first: each value's nearest
/// integer, then the next one on its other side (for one value also the next on
/// the same side): what a rounding that would put two corners on one lattice point
/// falls back to.
std::vector<std::vector<double>> rounding_options(const std::vector<int>& v, const Eigen::VectorXd& z) {
  auto nearest = [&](int i) { return std::round(z[i]); };
  auto other = [&](int i) { return nearest(i) + (z[i] >= nearest(i) ? 1.0 : -1.0); };
  if (v.size() == 1)
    return {{nearest(v[0])}, {other(v[0])}, {2 * nearest(v[0]) - other(v[0])}};
  auto beyond = [&](int i) { return 2 * nearest(i) - other(i); };
  return {{nearest(v[0]), nearest(v[1])}, {other(v[0]), nearest(v[1])}, {nearest(v[0]), other(v[1])},
          {other(v[0]), other(v[1])}, {beyond(v[0]), nearest(v[1])}, {nearest(v[0]), beyond(v[1])}};
}

/// A value this far from an integer after a solve is at a fraction.
constexpr double fraction_tolerance = 1e-3;

/// The fixed values and the seam rows may determine a value not fixed yet: the
/// rows around a vertex whose cut paths turn by a half turn relative to each other
/// give 2 t_a = (1 - i) t_b, say (a handle's two loops), and once t_b is an integer
/// of odd coordinate sum, t_a is a half-integer no rounding makes integer (the
/// seams open). Denominators are powers of 1 - i, so such a value lies on a half
/// or a quarter. `determined` holds the values seen determined so far (which
/// values are determined depends on which are fixed, not on their integers, so a
/// rounding's options share it).
class DeterminedValues {
 public:
  DeterminedValues(std::vector<int> candidates, std::size_t variables)
      : candidates_(std::move(candidates)), determined_(variables, 0) {}

  /// The candidates not in `fixed` that the fixed values determine at other than an
  /// integer, in solution z. A candidate on a half or a quarter is tested by fixing
  /// it to its nearest integer: the seams open if it is determined (one low-rank
  /// solve; a free value lands that close to a fraction only by chance).
  std::size_t at_fractions(PenaltySolver& solver, const std::vector<char>& fixed, const Eigen::VectorXd& z,
                           SeamlessMapReport& report) {
    std::size_t count = 0;
    for (int v : candidates_) {
      const auto sv = static_cast<std::size_t>(v);
      if (fixed[sv]) continue;
      const double off = std::abs(z[v] - std::round(z[v]));
      if (off < fraction_tolerance) continue;
      if (!determined_[sv]) {
        const double quarters = 4 * z[v];
        if (std::abs(quarters - std::round(quarters)) > 4 * max_consistent_residual) continue;
        solver.fix(v, std::round(z[v]));
        const double residual = solver.max_residual(solver.solve_low_rank());
        ++report.solves;
        solver.unfix(1);
        if (residual < max_consistent_residual) continue;
        determined_[sv] = 1;
      }
      ++count;
    }
    return count;
  }

 private:
  std::vector<int> candidates_;
  std::vector<char> determined_;
};

/// Strips between two boundary lines this wide in the map before quantization
/// (quads) are kept from being rounded to nothing (boundary_ligaments.h); wider
/// ones cannot be (their lines' nearest integers differ), a narrower one is taken
/// as the two lines meeting.
constexpr double min_ligament_width = 0.1;
constexpr double max_ligament_width = 1.2;

/// What one rounding option leaves: whether the seams still close, the values it
/// makes determined at fractions, the boundary segments of length 0 and the
/// ligaments without a quad.
struct RoundingOutcome {
  bool consistent = true;
  std::size_t fractions = 0;
  std::size_t collapsed = 0;
};

/// The map before quantization is fixed only up to a translation (the energy and
/// the seam rows do not see it; the gauge's pull is faint), so the first solve
/// leaves it where the factorization's round-off does: a tenth of a quad apart
/// between two orderings of one system, which decides what the greedy rounding
/// makes of every value. A map quantized from a lattice shift is first moved by
/// the translation that brings the values the rounding makes integer nearest to
/// integers: per axis, the one maximizing sum cos 2 pi (x + c) over the values x
/// of that axis (their circular mean), which the round-off changes only by its
/// own size; then by the shift.
Complex lattice_offset(const IntegerCandidates& order, int wedge_values, const Eigen::VectorXd& z) {
  std::array<Complex, 2> sum{};
  for (const std::vector<int>& candidates : order.phases)
    for (int v : candidates)
      if (v < wedge_values) sum[static_cast<std::size_t>(v % 2)] += std::polar(1.0, 2 * M_PI * z[v]);
  const auto offset = [](Complex s) { return std::abs(s) > 0 ? -std::arg(s) / (2 * M_PI) : 0.0; };
  return {offset(sum[0]), offset(sum[1])};
}

/// z moved by the translation c: every wedge by c, and a cut translation t of
/// W_g = i^q W_f + t by (1 - i^q) c.
void translate(Eigen::VectorXd& z, Complex c, int wedge_values, const std::vector<Translation>& translations) {
  for (int v = 0; v < wedge_values; v += 2) {
    z[v] += c.real();
    z[v + 1] += c.imag();
  }
  const std::array<double, 2> xy{c.real(), c.imag()};
  for (const Translation& t : translations) {
    // i^q c by the tables the transition rows use
    const int q = t.ends[0].quarter_turns;
    for (int k = 0; k < 2; ++k) z[t.variable + k] += xy[k] - turned_sign[q][k] * xy[turned_from[q][k]];
  }
}

/// The candidates not fixed and not in `step` that the rounding would fix next if
/// z stayed as it is: the nearest to integers first (with their pairs), as many
/// as two batches of columns.
std::vector<int> expected_values(const std::vector<int>& candidates, const std::vector<char>& fixed,
                                 const Eigen::VectorXd& z, const std::vector<int>& step, bool paired) {
  std::vector<std::pair<double, int>> open;
  for (int v : candidates)
    if (!fixed[static_cast<std::size_t>(v)] && std::find(step.begin(), step.end(), v) == step.end())
      open.push_back({std::abs(z[v] - std::round(z[v])), v});
  const std::size_t wanted = 2 * column_batch;
  const auto take = std::min(open.size(), wanted);
  std::partial_sort(open.begin(), open.begin() + static_cast<std::ptrdiff_t>(take), open.end());
  std::vector<int> expected;
  for (std::size_t i = 0; i < take && expected.size() < wanted; ++i) {
    const int v = open[i].second;
    if (std::find(expected.begin(), expected.end(), v) != expected.end()) continue;
    expected.push_back(v);
    const int pair = v ^ 1;
    if (paired && !fixed[static_cast<std::size_t>(pair)] && std::find(step.begin(), step.end(), pair) == step.end() &&
        std::find(expected.begin(), expected.end(), pair) == expected.end())
      expected.push_back(pair);
  }
  return expected;
}

/// Greedy rounding, phase by phase: fix every candidate already integer (a cone's
/// position or a translation pinned at the end) and the one nearest to an
/// integer, solve, repeat. Returns the final solution; `fixed`
/// gets the values made integer. With `lattice_shift`, the first solve is moved
/// to lattice_offset plus the shift: the first values fixed then fix the
/// translation.
Eigen::VectorXd quantize(PenaltySolver& solver, const IntegerCandidates& order, const BoundarySegments& segments,
                         const std::vector<Ligament>& facing, int wedge_values,
                         const std::vector<Translation>& translations, std::optional<Complex> lattice_shift,
                         std::vector<std::pair<int, double>>& integers, SeamlessMapReport& report) {
  const std::vector<std::vector<int>>& phases = order.phases;
  Eigen::VectorXd z = solver.solve();
  ++report.solves;
  if (lattice_shift) translate(z, lattice_offset(order, wedge_values, z) + *lattice_shift, wedge_values, translations);
  // the strips between two loops that rounding could leave without a quad
  const std::vector<Ligament> ligaments = narrow_ligaments(facing, z, min_ligament_width, max_ligament_width);
  const auto collapsed = [&](const Eigen::VectorXd& x) {
    return collapsed_segments(segments, x) + collapsed_ligaments(ligaments, x);
  };
  std::vector<char> fixed(static_cast<std::size_t>(z.size()), 0);
  std::vector<int> all;
  for (const std::vector<int>& candidates : phases) all.insert(all.end(), candidates.begin(), candidates.end());
  DeterminedValues determined(all, fixed.size());
  // a cone's position or a translation already integer when its turn comes is,
  // but for chance, made so by those fixed before (a translation by its cones'
  // positions): pinned only once the rounding ends, it takes no column and no
  // place among the low-rank solves' (bunny-open's kept map: 7 factorizations
  // instead of 8, the same quads). A line stays pinned at once: one integer by
  // chance would move with the next rounding, past the guards that keep two
  // corners off one lattice point and a ligament from being rounded to nothing
  std::vector<std::pair<int, double>> unpinned;
  for (std::size_t phase = 0; phase < phases.size(); ++phase)
    for (const std::vector<int>& candidates = phases[phase];;) {
      int nearest = -1;
      double nearest_distance = 1;
      for (int v : candidates) {
        if (fixed[static_cast<std::size_t>(v)]) continue;
        const double d = std::abs(z[v] - std::round(z[v]));
        if (d < integer_tolerance) {
          fixed[static_cast<std::size_t>(v)] = 1;
          if (order.paired[phase] != 0) unpinned.push_back({v, std::round(z[v])});
          else solver.fix(v, std::round(z[v]));
          integers.push_back({v, std::round(z[v])});
          ++report.integer_values;
        } else if (d < nearest_distance) {
          nearest_distance = d;
          nearest = v;
        }
      }
      if (nearest < 0) break;
      // a cone's position and a translation are lattice vectors: both of their
      // coordinates are rounded in one step (one solve, not two)
      const bool paired = order.paired[phase] != 0;
      std::vector<int> step;
      for (int v : paired ? std::vector<int>{nearest, nearest ^ 1} : std::vector<int>{nearest})
        if (!fixed[static_cast<std::size_t>(v)]) step.push_back(v);
      solver.expect(expected_values(candidates, fixed, z, step, paired));
      // the nearest integers, unless they determine another value at a fraction or
      // put two corners on one lattice point (a boundary segment of length 0) where
      // the next ones do not; when every option does, the one with fewest
      // fractions, then fewest collapsed segments
      for (int v : step) fixed[static_cast<std::size_t>(v)] = 1;
      const RoundingOutcome before{true, determined.at_fractions(solver, fixed, z, report),
                                   collapsed(z)};
      const std::vector<std::vector<double>> options = rounding_options(step, z);
      Eigen::VectorXd next;
      std::size_t chosen = 0;
      RoundingOutcome best;
      for (std::size_t o = 0; o < options.size(); ++o) {
        for (std::size_t i = 0; i < step.size(); ++i) solver.fix(step[i], options[o][i]);
        next = solver.solve_low_rank();
        ++report.solves;
        RoundingOutcome outcome;
        // an integer other than the nearest may contradict values fixed before (the
        // seams then open): never taken
        outcome.consistent = o == 0 || solver.max_residual(next) < max_consistent_residual;
        if (outcome.consistent) {
          outcome.collapsed = collapsed(next);
          outcome.fractions = determined.at_fractions(solver, fixed, next, report);
        }
        if (outcome.consistent && outcome.fractions <= before.fractions && outcome.collapsed <= before.collapsed) {
          chosen = o;
          break;
        }
        if (o == 0 || (outcome.consistent && std::pair(outcome.fractions, outcome.collapsed) <
                                                 std::pair(best.fractions, best.collapsed))) {
          best = outcome;
          chosen = o;
        }
        solver.unfix(step.size());
        if (o + 1 == options.size()) {
          for (std::size_t i = 0; i < step.size(); ++i) solver.fix(step[i], options[chosen][i]);
          next = solver.solve_low_rank();
          ++report.solves;
        }
      }
      if (chosen > 0) ++report.other_integers;
      for (std::size_t i = 0; i < step.size(); ++i) {
        const int v = step[i];
        const double value = options[chosen][i];
        integers.push_back({v, value});
        ++report.integer_values;
        report.max_rounding = std::max(report.max_rounding, std::abs(z[v] - value));
      }
      z = std::move(next);
    }
  double moved = 0;
  for (const auto& [v, value] : unpinned) {
    solver.fix(v, value);
    moved = std::max(moved, std::abs(z[v] - value));
  }
  if (moved >= integer_tolerance) {  // one was integer by chance, and the rounding moved it
    z = solver.solve_low_rank();
    ++report.solves;
  }
  return z;
}

/// The map's corners: each triangle corner's wedge value in z.
FaceMap corner_values(const CutGraph& cut, const Eigen::VectorXd& z) {
  FaceMap map;
  map.corners.resize(cut.wedge.size());
  for (std::size_t f = 0; f < cut.wedge.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const int w = cut.wedge[f][k];
      map.corners[f][k] = Complex(z[real_of(w)], z[imag_of(w)]);
    }
  return map;
}

/// Per triangle: its image is not positive.
std::vector<char> folded_triangles(const FaceMap& map) {
  std::vector<char> folded(map.corners.size(), 0);
  for (std::size_t f = 0; f < map.corners.size(); ++f) folded[f] = image_area2(map.corners[f]) <= 0;
  return folded;
}

/// Multiplies the stiffness of folded triangles and of the triangles at their
/// corners.
void stiffen(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<char>& folded,
             std::vector<double>& stiffness) {
  std::vector<char> near(folded.size(), 0);
  for (std::size_t f = 0; f < folded.size(); ++f)
    if (folded[f])
      for (int v : soup.triangles[f])
        for (int g : adjacency.vertex_faces[static_cast<std::size_t>(v)]) near[static_cast<std::size_t>(g)] = 1;
  for (std::size_t f = 0; f < folded.size(); ++f)
    if (folded[f] || near[f]) stiffness[f] = std::min(max_stiffness, stiffness[f] * stiffening_factor);
}

}  // namespace

FaceMap seamless_map(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                     const CrossField& field, const CutGraph& cut, const std::vector<int>& quads, double size,
                     SeamlessMapReport& report, RoundingOrder order, const FitShape* shape,
                     std::optional<Complex> lattice_shift, const StopRequest& stop, MapOrdering* ordering,
                     bool hold_short_segments) {
  QM_ASSERT(size > 0);
  report = {};
  std::vector<Row> rows;
  int variables = 2 * cut.wedge_count;
  const std::vector<Translation> translations = add_seams(soup, adjacency, field, cut, rows, variables);
  std::vector<double> stiffness(soup.triangles.size(), 1.0);
  const std::vector<Complex> scales = target_scales(soup, u, field, size);
  auto energy = [&](Triplets& H, Eigen::VectorXd& b) {
    H.clear();
    b = Eigen::VectorXd::Zero(variables);
    add_fitting_energy(soup, scales, shape, cut, stiffness, &H, b);
    // gauge: the map is fixed up to a translation; a faint pull of wedge 0 to 0
    // makes the system definite without competing with the integer values
    H.emplace_back(0, 0, gauge_weight);
    H.emplace_back(1, 1, gauge_weight);
  };
  Triplets H;
  Eigen::VectorXd b;
  energy(H, b);
  const BoundarySegments segments = boundary_segments(soup, adjacency, field, cut, quads, scales);
  const std::vector<std::size_t> short_ones = short_segments(segments);
  report.short_segments = short_ones.size();
  if (hold_short_segments) {
    for (std::size_t s : short_ones) rows.push_back(Row{segment_terms(segments, s), 1.0});
    report.segments_held = short_ones.size();
  }
  // a map from a lattice shift is a new draw, its translation set apart from the
  // round-off (moved to the values' circular mean), so it may be ordered by nested
  // dissection from its first solve; another map's first solve leaves the
  // translation the quantization starts from where the minimum degree ordering's
  // round-off does, as the seed's maps always did (the same quads)
  MapOrdering own_ordering;
  PenaltySolver solver(variables, std::move(H), std::move(b), std::move(rows), lattice_shift.has_value(),
                       ordering ? *ordering : own_ordering, stop);
  std::vector<std::pair<int, double>> integers;
  const IntegerCandidates candidates =
      integer_candidates(soup, adjacency, field, cut, quads, translations, variables, order);
  Eigen::VectorXd z =
      quantize(solver, candidates, segments,
               facing_boundary_lines(soup, adjacency, field, cut, quads), 2 * cut.wedge_count, translations,
               lattice_shift, integers, report);
  // stiffening [Bommes et al. 2009]: triangles left folded, and those around
  // them, weigh more in the fit, until none is folded. Not when the integer values
  // contradict the seams (no stiffness closes them), nor once the folds have not
  // become fewer in stiffening_patience rounds (a fold pinned between integer
  // values does not move), nor once they are more than their fewest while an
  // interior cone is wound a turn short: the map then winds round it by the wrong
  // angle, which no weight mends (of the 58 such maps of the meshes, examples and
  // parts measured, none came out unfolded; bunny-open's nearer capped cones: 5
  // folds, then 7, 8, 8, 7 in four more factorizations)
  const bool seams_close = solver.max_residual(z) < max_consistent_residual;
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  int stalled = 0;
  for (int round = 0; seams_close && round < max_stiffening_rounds && stalled < stiffening_patience; ++round) {
    const FaceMap image = corner_values(cut, z);
    const std::vector<char> folded = folded_triangles(image);
    const auto count = static_cast<std::size_t>(std::count(folded.begin(), folded.end(), 1));
    if (count == 0) break;
    const bool more_than_fewest = count > fewest;
    stalled = count < fewest ? 0 : stalled + 1;
    fewest = std::min(fewest, count);
    if (more_than_fewest && !misturned_cones(soup, adjacency, image, quads).empty()) {
      report.stiffening_lost = true;
      break;
    }
    const std::vector<double> before = stiffness;
    stiffen(soup, adjacency, folded, stiffness);
    // a few triangles weigh more: the factorization updated by their forms where
    // it holds every integer value (stiffness_change.h), else factored again
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(variables);
    add_fitting_energy(soup, scales, shape, cut, stiffness, nullptr, rhs);
    if (solver.update_energy(stiffness_change(soup, cut, before, stiffness), rhs)) {
      z = solver.updated_solution();
    } else {
      energy(H, b);
      solver.set_energy(std::move(H), std::move(b));
      z = solver.solve();
    }
    ++report.solves;
    ++report.stiffening_rounds;
  }
  if (seams_close) z = solver.hold_constraints(std::move(z));
  // the penalty leaves the integer values ~1e-9 off, the size of the extraction's
  // fixed-point unit (2^-30): they are set exactly, so that cones and boundary
  // lines are lattice points and lines in every chart
  std::vector<char> exact(static_cast<std::size_t>(variables), 0);
  for (const auto& [v, value] : integers) {
    z[v] = value;
    exact[static_cast<std::size_t>(v)] = 1;
  }
  for (std::size_t v = 0; v < candidates.same_as.size(); ++v)
    if (candidates.same_as[v] >= 0) {
      z[static_cast<Eigen::Index>(v)] = candidates.same_sign[v] * z[candidates.same_as[v]];
      exact[v] = 1;
    }
  propagate_exact_values(solver.rows(), exact, z);
  report.max_seam_residual = solver.max_residual(z);
  report.factorizations = solver.factorizations();
  report.nested_dissection_factorizations = solver.nested_dissection_factorizations();
  report.low_rank_columns = solver.low_rank_columns().computed();
  report.low_rank_column_solves = solver.low_rank_columns().solves();
  report.factorization_updates = solver.updates();

  FaceMap map = corner_values(cut, z);
  const std::vector<char> folded = folded_triangles(map);
  report.inverted_triangles = static_cast<std::size_t>(std::count(folded.begin(), folded.end(), 1));
  return map;
}

}  // namespace qm
