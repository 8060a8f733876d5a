#include "tools/batch/batch_row.h"

#include "tools/common/exit_codes.h"

#include <fmt/format.h>

namespace qm::tools {

namespace {
using Json = nlohmann::ordered_json;

double number_or_zero(const Json& j) { return j.is_number() ? j.get<double>() : 0.0; }
}  // namespace

RowFiles row_files(const BatchRow& row) {
  const std::string base = "parts/" + row.name;
  return {base + ".msh", base + ".report.json", base + ".log", base + ".row.json"};
}

std::vector<std::string> row_arguments(const BatchRow& row) {
  const RowFiles files = row_files(row);
  std::vector<std::string> args = {"mesh", row.file, "-o", files.mesh, "--report", files.report, "-q"};
  if (!row.size.empty()) args.insert(args.end(), {"--size", row.size});
  args.insert(args.end(), row.options.begin(), row.options.end());
  return args;
}

RowResult row_result(const io::ChildResult& child, const std::string& first_error, const Json& report) {
  RowResult r;
  r.seconds = child.seconds;
  r.status = io::status_name(child.status);
  r.detail = child.detail;
  if (!first_error.empty()) r.detail += ": " + first_error;
  if (child.status == io::ChildStatus::failed && child.exit_code == exit_unsupported) r.status = "unsupported";
  if (child.status != io::ChildStatus::ok) return r;
  if (!report.is_object() || !report.contains("quality")) {
    r.status = "failed";
    r.detail = "the mesher ended well but left no report";
    return r;
  }
  const Json& q = report["quality"];
  r.quads = q.value("quads", std::size_t{0});
  r.singular_vertices = q.value("irregular_interior", std::size_t{0});
  r.min_scaled_jacobian = number_or_zero(q.value("min_scaled_jacobian", Json()));
  r.angle_deviation = number_or_zero(q.value("angle_dev_mean", Json()));
  return r;
}

Json row_result_json(const BatchRow& row, const RowResult& r) {
  return {{"index", row.index},
          {"name", row.name},
          {"file", row.file},
          {"size", row.size},
          {"options", row.options},
          {"arguments", row_arguments(row)},
          {"status", r.status},
          {"detail", r.detail},
          {"quads", r.quads},
          {"singular_vertices", r.singular_vertices},
          {"min_scaled_jacobian", r.min_scaled_jacobian},
          {"angle_deviation", r.angle_deviation},
          {"seconds", r.seconds}};
}

std::optional<RowResult> row_result_from_json(const Json& j, const BatchRow& row) {
  try {
    if (j.at("arguments").get<std::vector<std::string>>() != row_arguments(row)) return std::nullopt;
    RowResult r;
    r.status = j.at("status").get<std::string>();
    r.detail = j.at("detail").get<std::string>();
    r.quads = j.at("quads").get<std::size_t>();
    r.singular_vertices = j.at("singular_vertices").get<std::size_t>();
    r.min_scaled_jacobian = j.at("min_scaled_jacobian").get<double>();
    r.angle_deviation = j.at("angle_deviation").get<double>();
    r.seconds = j.at("seconds").get<double>();
    if (r.status == "missing") return std::nullopt;
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace qm::tools
