// DIR/summary.json and DIR/summary.md of `quadmesh batch`: one row per part and
// the totals (docs/outputs.md "quadmesh batch").
#pragma once

#include "tools/batch/batch_row.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace qm::tools {

/// Totals over the rows: counts by status, quads and seconds summed.
struct BatchTotals {
  std::size_t rows = 0, ok = 0, failed = 0, unsupported = 0, crashed = 0, timeout = 0, missing = 0;
  std::size_t quads = 0;
  double seconds = 0;
};
BatchTotals batch_totals(const std::vector<RowResult>& results);

/// The summary (results[i] is rows[i]'s). Paths in it are the input files as
/// LIST gives them and the outputs relative to DIR, so that two runs of one LIST
/// into different folders (a local batch, a Slurm array) give the same summary
/// but for the seconds.
nlohmann::ordered_json summary_json(const std::vector<BatchRow>& rows, const std::vector<RowResult>& results);
std::string summary_markdown(const std::vector<BatchRow>& rows, const std::vector<RowResult>& results);

}  // namespace qm::tools
