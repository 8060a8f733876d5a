#include "io/text_check.h"

#include <fmt/format.h>

#include <array>
#include <fstream>

namespace qm::io {

bool is_binary_byte(unsigned char byte) {
  if (byte >= 0x20) return false;
  return !(byte == '\t' || byte == '\n' || byte == '\v' || byte == '\f' || byte == '\r' ||
           byte == 0x1a);
}

std::optional<std::string> check_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 1 << 16> block{};
  long line_no = 1;
  std::size_t line_length = 0;
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto count = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < count; ++i) {
      const auto byte = static_cast<unsigned char>(block[i]);
      if (byte == '\n') {
        ++line_no;
        line_length = 0;
        continue;
      }
      if (is_binary_byte(byte))
        return fmt::format("{}: line {}: not text (byte 0x{:02x})", path, line_no, byte);
      if (++line_length > max_text_line)
        return fmt::format("{}: line {}: not text (a line over 1 MiB)", path, line_no);
    }
  }
  return std::nullopt;
}

}  // namespace qm::io
