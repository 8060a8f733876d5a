// Writing a file so that it appears complete or not at all.
#pragma once

#include <functional>
#include <string>

namespace qm::io {

/// Calls write(temporary) with a temporary path in the destination's folder that
/// keeps the destination's extension (writers choose formats by extension), then
/// renames it onto `path`. If write throws, the temporary file is removed and the
/// exception propagates; nothing is left at `path`.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace qm::io
