#include "tools/quadmesh/option_checks.h"

#include "tools/common/usage_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace qm::tools {

namespace {

/// The whole of `text` as a number (strtod: also "nan", "inf", "1e-9"); false
/// when it is empty, has anything after the number, or is not one.
bool parse_number(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

/// The value as the user wrote it, shortened for a one-line message.
std::string shown(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (out.size() >= 40) return out + "...";
    out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return out.empty() ? "''" : out;
}

/// A finite number in (0, max], a `what`.
ValueRule finite_positive(double max, const std::string& what) {
  return [max, what](const std::string& text) {
    double x = 0;
    if (!parse_number(text, x) || !std::isfinite(x) || x <= 0) return fmt::format("must be a positive {}", what);
    if (x > max) return fmt::format("must be a positive {} of at most {:g}", what, max);
    return std::string();
  };
}

/// A whole number from 1 to max, digits only.
ValueRule whole_number(std::uint64_t max) {
  return [max](const std::string& text) {
    const std::string must = fmt::format("must be a whole number from 1 to {}", max);
    if (text.empty() || text.size() > 19 ||
        !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return must;
    const std::uint64_t n = std::strtoull(text.c_str(), nullptr, 10);
    return n >= 1 && n <= max ? std::string() : must;
  };
}

}  // namespace

CLI::Option* checked(CLI::Option* option, const ValueCheck& check) {
  const std::string name = option->get_name();
  const ValueRule rule = check.rule;
  return option->check(CLI::Validator(
      [name, rule](std::string& text) {
        const std::string problem = rule(text);
        if (!problem.empty()) throw UsageError(fmt::format("{} {}: {}", name, shown(text), problem));
        return std::string();
      },
      check.help_name));
}

ValueCheck positive_length() { return {finite_positive(kMaxLength, "length"), "LENGTH"}; }

ValueCheck length_or_percent(bool or_off) {
  ValueRule rule = [or_off](const std::string& text) {
    const std::string must = or_off ? "must be off, a positive length or a percentage such as 0.5%"
                                    : "must be a positive length or a percentage such as 1.5%";
    if (or_off && text == "off") return std::string();
    const bool percent = !text.empty() && text.back() == '%';
    double x = 0;
    if (!parse_number(percent ? text.substr(0, text.size() - 1) : text, x) || !std::isfinite(x) || x <= 0)
      return must;
    if (percent && x > 100) return std::string("must be a percentage of at most 100%");
    if (!percent && x > kMaxLength) return fmt::format("must be a length of at most {:g}", kMaxLength);
    return std::string();
  };
  return {rule, or_off ? "LENGTH|P%|off" : "LENGTH|P%"};
}

ValueCheck whole_count() { return {whole_number(kMaxCount), "N"}; }

ValueCheck form_number() {
  const ValueRule number = whole_number(kMaxCount);
  ValueRule rule = [number](const std::string& text) {
    if (text == "auto" || number(text).empty()) return std::string();
    return "must be auto or " + number(text).substr(std::string("must be ").size());
  };
  return {rule, "auto|K"};
}

ValueCheck coefficient() {
  ValueRule rule = [](const std::string& text) {
    double x = 0;
    if (!parse_number(text, x) || !std::isfinite(x)) return std::string("must be a finite number");
    if (std::abs(x) > kMaxLength) return fmt::format("must be a number from {:g} to {:g}", -kMaxLength, kMaxLength);
    return std::string();
  };
  return {rule, "C"};
}

ValueCheck degrees(double low, double high, bool low_open) {
  ValueRule rule = [=](const std::string& text) {
    double x = 0;
    const bool ok = parse_number(text, x) && std::isfinite(x) && (low_open ? x > low : x >= low) && x <= high;
    return ok ? std::string()
              : fmt::format("must be an angle in degrees {} {:g} and at most {:g}", low_open ? "above" : "from", low,
                            high);
  };
  return {rule, "DEGREES"};
}

ValueCheck seconds() { return {finite_positive(kMaxSeconds, "number of seconds"), "SECONDS"}; }

ValueCheck gibibytes() { return {finite_positive(kMaxGibibytes, "number of GiB"), "GIB"}; }

ValueCheck msh_version() {
  ValueRule rule = [](const std::string& text) {
    return text == "4.1" || text == "2.2" ? std::string() : std::string("must be 4.1 or 2.2");
  };
  return {rule, "4.1|2.2"};
}

ValueCheck one_of(const std::vector<std::string>& values) {
  ValueRule rule = [values](const std::string& text) {
    if (std::find(values.begin(), values.end(), text) != values.end()) return std::string();
    return fmt::format("must be one of {}", fmt::join(values, ", "));
  };
  return {rule, fmt::format("{}", fmt::join(values, "|"))};
}

bool parse_direction(const std::string& text, double (&xyz)[3]) {
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos)) return false;
    const std::string item = text.substr(start, i < 2 ? comma - start : std::string::npos);
    if (!parse_number(item, xyz[i]) || !std::isfinite(xyz[i]) || std::abs(xyz[i]) > kMaxLength) return false;
    start = comma + 1;
  }
  return xyz[0] != 0 || xyz[1] != 0 || xyz[2] != 0;
}

ValueCheck direction() {
  ValueRule rule = [](const std::string& text) {
    double xyz[3];
    return parse_direction(text, xyz) ? std::string()
                                      : fmt::format("must be three finite numbers x,y,z of at most {:g} in size, "
                                                    "not all 0 (the direction towards the viewer)",
                                                    kMaxLength);
  };
  return {rule, "X,Y,Z"};
}

ValueCheck picture_width() {
  ValueRule rule = [](const std::string& text) {
    const std::string must = fmt::format("must be a whole number of pixels from {:g} to {:g}", kMinPictureWidth,
                                         kMaxPictureWidth);
    if (!whole_number(static_cast<std::uint64_t>(kMaxPictureWidth))(text).empty()) return must;
    return std::stod(text) >= kMinPictureWidth ? std::string() : must;
  };
  return {rule, "PX"};
}

}  // namespace qm::tools
