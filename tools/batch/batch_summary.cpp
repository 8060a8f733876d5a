#include "tools/batch/batch_summary.h"

#include <fmt/format.h>

namespace qm::tools {

BatchTotals batch_totals(const std::vector<RowResult>& results) {
  BatchTotals t;
  for (const RowResult& r : results) {
    ++t.rows;
    if (r.status == "ok") ++t.ok;
    else if (r.status == "unsupported") ++t.unsupported;
    else if (r.status == "crashed") ++t.crashed;
    else if (r.status == "timeout") ++t.timeout;
    else if (r.status == "missing") ++t.missing;
    else ++t.failed;
    t.quads += r.quads;
    t.seconds += r.seconds;
  }
  return t;
}

nlohmann::ordered_json summary_json(const std::vector<BatchRow>& rows, const std::vector<RowResult>& results) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BatchRow& row = rows[i];
    const RowResult& r = results[i];
    const RowFiles files = row_files(row);
    const bool ok = r.status == "ok";
    list.push_back({{"index", row.index},
                    {"name", row.name},
                    {"file", row.file},
                    {"size", row.size},
                    {"options", row.options},
                    {"status", r.status},
                    {"detail", r.detail},
                    {"quads", r.quads},
                    {"singular_vertices", r.singular_vertices},
                    {"min_scaled_jacobian", ok ? nlohmann::ordered_json(r.min_scaled_jacobian) : nullptr},
                    {"angle_deviation", ok ? nlohmann::ordered_json(r.angle_deviation) : nullptr},
                    {"seconds", r.seconds},
                    {"mesh", ok ? nlohmann::ordered_json(files.mesh) : nullptr},
                    {"report", ok ? nlohmann::ordered_json(files.report) : nullptr},
                    {"log", files.log}});
  }
  const BatchTotals t = batch_totals(results);
  nlohmann::ordered_json j;
  j["rows"] = list;
  j["totals"] = {{"rows", t.rows},         {"ok", t.ok},           {"failed", t.failed},
                 {"unsupported", t.unsupported}, {"crashed", t.crashed}, {"timeout", t.timeout},
                 {"missing", t.missing},   {"quads", t.quads},     {"seconds", t.seconds}};
  return j;
}

std::string summary_markdown(const std::vector<BatchRow>& rows, const std::vector<RowResult>& results) {
  std::string md = "# quadmesh batch\n\n";
  md += "| # | part | status | quads | singular vertices | min SJ | angle dev. mean | seconds | detail |\n";
  md += "|---:|---|---|---:|---:|---:|---:|---:|---|\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RowResult& r = results[i];
    const bool ok = r.status == "ok";
    std::string detail = r.detail;
    for (char& c : detail)
      if (c == '|' || c == '\n') c = ' ';
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.2f} | {} |\n", rows[i].index, rows[i].name, r.status,
                      ok ? std::to_string(r.quads) : "-", ok ? std::to_string(r.singular_vertices) : "-",
                      ok ? fmt::format("{:.3f}", r.min_scaled_jacobian) : "-",
                      ok ? fmt::format("{:.2f}", r.angle_deviation) : "-", r.seconds, detail);
  }
  const BatchTotals t = batch_totals(results);
  md += fmt::format(
      "\n**Totals.** {} rows: {} ok, {} failed, {} unsupported, {} crashed, {} timeout, {} missing; {} quads; "
      "{:.2f} s of meshing.\n",
      t.rows, t.ok, t.failed, t.unsupported, t.crashed, t.timeout, t.missing, t.quads, t.seconds);
  return md;
}

}  // namespace qm::tools
