// The checks of option values, in the user's terms: every numeric option refuses
// NaN, infinities, values out of its range and absurdly large ones while the
// command line is parsed (exit 2), with one line
// "--size inf: must be a positive length or a percentage such as 1.5%".
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace qm::tools {

/// What a check says of an option's text: "" when acceptable, else what it must be.
using ValueRule = std::function<std::string(const std::string& text)>;

struct ValueCheck {
  ValueRule rule;
  std::string help_name;  ///< shown in --help after the option ("LENGTH", "N")
};

/// The largest length, count or coefficient any option takes: far beyond any
/// mesh, small enough that its square and its products stay finite.
constexpr double kMaxLength = 1e12;
constexpr std::uint64_t kMaxCount = 1000000000;  // 1e9
constexpr double kMaxSeconds = 1e6;
constexpr double kMaxGibibytes = 1e6;
/// The range of a picture's width in pixels (--width).
constexpr double kMinPictureWidth = 100;
constexpr double kMaxPictureWidth = 4000;

/// Attaches `check` to `option`: a value it refuses ends the parse with a
/// UsageError "OPTION VALUE: PROBLEM" (exit 2). Returns `option`.
CLI::Option* checked(CLI::Option* option, const ValueCheck& check);

/// A length in (0, kMaxLength].
ValueCheck positive_length();
/// A length in (0, kMaxLength] or a percentage P% with 0 < P <= 100; `or_off`
/// also accepts "off".
ValueCheck length_or_percent(bool or_off = false);
/// A whole number from 1 to kMaxCount, digits only (no overflow).
ValueCheck whole_count();
/// --form: "auto" or a whole number from 1 to kMaxCount.
ValueCheck form_number();
/// A finite coefficient of absolute value at most kMaxLength (zero and negative allowed).
ValueCheck coefficient();
/// An angle in degrees in [low, high], or (low, high] when `low_open`.
ValueCheck degrees(double low, double high, bool low_open);
/// A time in seconds in (0, kMaxSeconds].
ValueCheck seconds();
/// A memory size in GiB in (0, kMaxGibibytes].
ValueCheck gibibytes();
/// --msh-version: 4.1 or 2.2, as written.
ValueCheck msh_version();
/// One of `values`, as written (--color).
ValueCheck one_of(const std::vector<std::string>& values);
/// A direction x,y,z (--view): three finite numbers of size at most kMaxLength,
/// not all 0.
ValueCheck direction();
/// --width: a whole number of pixels from kMinPictureWidth to kMaxPictureWidth.
ValueCheck picture_width();
/// Reads a text direction() accepts into `xyz`; false for any other text.
bool parse_direction(const std::string& text, double (&xyz)[3]);

}  // namespace qm::tools
