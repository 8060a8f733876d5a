// The rows of `quadmesh batch LIST`: one part (an input file) each, with its size
// and extra `quadmesh mesh` options, read from a CSV text or a folder's files.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace qm::tools {

struct BatchRow {
  int index = 0;                     ///< from 1, in LIST order (Slurm's array index)
  std::string name;                  ///< the outputs' stem: the file's stem, made unique
  std::string file;                  ///< the input, absolute
  std::string size;                  ///< --size of this row ("5%", "2.5"), or "" for the default
  std::vector<std::string> options;  ///< further `quadmesh mesh` options, as words
};

/// Rows from the CSV text of a list file `list_path` (README "quadmesh batch"):
/// `file,size,options` per line, an optional header line starting with `file`,
/// blank lines and lines starting with '#' ignored; a field may be double-quoted
/// ("" inside is a quote). `file` is taken relative to the list's folder; options
/// are words separated by spaces. An empty size gets `default_size`. Throws
/// UsageError "LIST:N: ..." for a line without a file, more than three fields, a
/// size that is not a length or percentage, or an option batch sets itself (-o,
/// --output, --report).
std::vector<BatchRow> parse_batch_list(const std::string& text, const std::string& list_path,
                                       const std::string& default_size);

/// Rows for the given input files (a folder's, sorted by the caller), every one at
/// `default_size` with no options.
std::vector<BatchRow> rows_for_files(const std::vector<std::string>& files, const std::string& default_size);

/// The rows as DIR/list.json holds them, and back (for --collect). from_json
/// throws UsageError naming `where` when the JSON is not such a list.
nlohmann::ordered_json rows_json(const std::vector<BatchRow>& rows);
std::vector<BatchRow> rows_from_json(const nlohmann::ordered_json& j, const std::string& where);

}  // namespace qm::tools
