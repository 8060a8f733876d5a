#include "tools/batch/batch_list.h"

#include "tools/common/usage_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>

namespace qm::tools {

namespace {

namespace fs = std::filesystem;

/// The comma-separated fields of one CSV line, double quotes honoured; throws
/// UsageError for an unterminated quote.
std::vector<std::string> csv_fields(const std::string& line, const std::string& where) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) throw UsageError(fmt::format("{}: a quote is not closed", where));
  return fields;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// "5%", "2.5", "1e-3": what `quadmesh mesh --size` takes (it checks the range).
bool is_size(const std::string& s) {
  if (s.empty()) return false;
  const std::string number = s.back() == '%' ? s.substr(0, s.size() - 1) : s;
  try {
    std::size_t used = 0;
    const double x = std::stod(number, &used);
    return used == number.size() && x > 0;
  } catch (...) {
    return false;
  }
}

/// A name usable as a file stem: letters, digits, '.', '-', '_' kept, the rest '_'.
std::string file_stem_name(const std::string& file) {
  std::string name = fs::path(file).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return name.empty() ? std::string("part") : name;
}

/// Names made unique: a stem that several rows share gets "-K" (the row's index).
void name_rows(std::vector<BatchRow>& rows) {
  std::map<std::string, int> uses;
  for (const BatchRow& row : rows) ++uses[file_stem_name(row.file)];
  for (BatchRow& row : rows) {
    const std::string stem = file_stem_name(row.file);
    row.name = uses[stem] > 1 ? fmt::format("{}-{}", stem, row.index) : stem;
  }
}

}  // namespace

std::vector<BatchRow> parse_batch_list(const std::string& text, const std::string& list_path,
                                       const std::string& default_size) {
  const fs::path folder = fs::absolute(list_path).parent_path();
  std::vector<BatchRow> rows;
  std::istringstream in(text);
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::string where = fmt::format("{}:{}", list_path, line_number);
    const std::string content = trimmed(line);
    if (content.empty() || content[0] == '#') continue;
    std::vector<std::string> fields = csv_fields(content, where);
    for (std::string& f : fields) f = trimmed(f);
    if (rows.empty() && fields[0] == "file") continue;  // the header
    if (fields.size() > 3)
      throw UsageError(fmt::format("{}: {} fields; a row is file,size,options (quote a field with a comma)", where,
                                   fields.size()));
    if (fields[0].empty()) throw UsageError(fmt::format("{}: no file", where));
    BatchRow row;
    row.index = static_cast<int>(rows.size()) + 1;
    row.file = fs::absolute(folder / fields[0]).lexically_normal().string();
    row.size = fields.size() > 1 && !fields[1].empty() ? fields[1] : default_size;
    if (!row.size.empty() && !is_size(row.size))
      throw UsageError(fmt::format("{}: size '{}' is not a positive length or a percentage such as 5%", where,
                                   row.size));
    if (fields.size() > 2) row.options = words(fields[2]);
    for (const std::string& option : row.options)
      if (option == "-o" || option.rfind("--output", 0) == 0 || option.rfind("--report", 0) == 0 ||
          option.rfind("-o", 0) == 0)
        throw UsageError(fmt::format("{}: option {}: batch names each row's outputs itself", where, option));
    rows.push_back(std::move(row));
  }
  name_rows(rows);
  return rows;
}

std::vector<BatchRow> rows_for_files(const std::vector<std::string>& files, const std::string& default_size) {
  std::vector<BatchRow> rows;
  for (const std::string& file : files) {
    BatchRow row;
    row.index = static_cast<int>(rows.size()) + 1;
    row.file = fs::absolute(file).lexically_normal().string();
    row.size = default_size;
    rows.push_back(std::move(row));
  }
  name_rows(rows);
  return rows;
}

nlohmann::ordered_json rows_json(const std::vector<BatchRow>& rows) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const BatchRow& row : rows)
    j.push_back({{"index", row.index}, {"name", row.name}, {"file", row.file}, {"size", row.size},
                 {"options", row.options}});
  return j;
}

std::vector<BatchRow> rows_from_json(const nlohmann::ordered_json& j, const std::string& where) {
  std::vector<BatchRow> rows;
  try {
    for (const auto& r : j) {
      BatchRow row;
      row.index = r.at("index").get<int>();
      row.name = r.at("name").get<std::string>();
      row.file = r.at("file").get<std::string>();
      row.size = r.at("size").get<std::string>();
      row.options = r.at("options").get<std::vector<std::string>>();
      rows.push_back(std::move(row));
    }
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(fmt::format("{}: not a batch's list of rows: {}", where, e.what()));
  }
  if (!j.is_array()) throw UsageError(fmt::format("{}: not a batch's list of rows", where));
  return rows;
}

}  // namespace qm::tools
