// One row of `quadmesh batch`: the `quadmesh mesh` command it runs, where its
// outputs go, and its result as DIR/parts/NAME.row.json holds it.
#pragma once

#include "io/child_process.h"
#include "tools/batch/batch_list.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace qm::tools {

/// The files of a row, relative to the batch's folder DIR.
struct RowFiles {
  std::string mesh;    ///< parts/NAME.msh
  std::string report;  ///< parts/NAME.report.json
  std::string log;     ///< parts/NAME.log: the child's stdout and stderr
  std::string result;  ///< parts/NAME.row.json: written last; the row is done when it is there
};
RowFiles row_files(const BatchRow& row);

/// The arguments after the program: `mesh FILE -o MESH --report REPORT -q
/// [--size SIZE] OPTIONS...` (paths relative to DIR, where the child runs).
std::vector<std::string> row_arguments(const BatchRow& row);

/// What became of a row. Status: ok, failed, unsupported (exit 4: the method
/// cannot take the input), crashed, timeout, or missing (no result yet: --collect).
struct RowResult {
  std::string status = "missing";
  std::string detail;  ///< why, for any status but ok
  double seconds = 0;
  // from the report (status ok)
  std::size_t quads = 0;
  std::size_t singular_vertices = 0;  ///< interior vertices of valence other than 4
  double min_scaled_jacobian = 0;     ///< Verdict's
  double angle_deviation = 0;         ///< mean |corner angle - 90| in degrees
};

/// The result from how the child ended, its log's first error line and its
/// report (null when unreadable: an ok child without a report is `failed`).
RowResult row_result(const io::ChildResult& child, const std::string& first_error,
                     const nlohmann::ordered_json& report);

/// NAME.row.json: the row (index, name, file, size, options), its arguments and
/// its result; and back. row_result_from_json returns nullopt unless the JSON is a
/// finished row for exactly these arguments (a changed LIST line runs again).
nlohmann::ordered_json row_result_json(const BatchRow& row, const RowResult& result);
std::optional<RowResult> row_result_from_json(const nlohmann::ordered_json& j, const BatchRow& row);

}  // namespace qm::tools
