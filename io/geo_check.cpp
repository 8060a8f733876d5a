#include "io/geo_check.h"

#include "io/text_diagnostics.h"
#include "libquadmesh/core/error.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace qm::io {

namespace {

namespace fs = std::filesystem;

constexpr int max_include_depth = 20;

struct Token {
  enum Kind { word, string, symbol };
  Kind kind = symbol;
  std::string text;  ///< the word, the string's contents, or the symbol (">>" is one)
  int line = 1;
};

bool word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Gmsh's lexer in brief: comments (// to the end of the line, /* to */) vanish,
/// strings run from " or ' to the next same quote with no escapes, words are
/// [A-Za-z_][A-Za-z0-9_]*, numbers are one symbol, ">>" is one symbol.
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      i += 2;
      while (i < n && !(text[i] == '*' && i + 1 < n && text[i + 1] == '/')) {
        if (text[i] == '\n') ++line;
        ++i;
      }
      i = std::min(n, i + 2);
    } else if (c == '"' || c == '\'') {
      Token t{Token::string, {}, line};
      ++i;
      while (i < n && text[i] != c) {
        if (text[i] == '\n') ++line;
        t.text += text[i++];
      }
      ++i;
      tokens.push_back(std::move(t));
    } else if (word_start(c)) {
      Token t{Token::word, {}, line};
      while (i < n && word_char(text[i])) t.text += text[i++];
      tokens.push_back(std::move(t));
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      Token t{Token::symbol, {}, line};
      while (i < n && (word_char(text[i]) || text[i] == '.')) t.text += text[i++];
      tokens.push_back(std::move(t));
    } else if (c == '>' && i + 1 < n && text[i + 1] == '>') {
      tokens.push_back({Token::symbol, ">>", line});
      i += 2;
    } else {
      tokens.push_back({Token::symbol, std::string(1, c), line});
      ++i;
    }
  }
  return tokens;
}

bool inside(const fs::path& path, const fs::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // a trailing separator
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

fs::path canonical_or_normal(const fs::path& path) {
  std::error_code ec;
  fs::path result = fs::weakly_canonical(path, ec);
  return ec ? fs::absolute(path).lexically_normal() : result;
}

struct Checker {
  bool allow = false;
  fs::path root;                 ///< canonical folder of the top script
  std::vector<fs::path> stack;   ///< canonical paths of the scripts being checked

  [[noreturn]] void refuse(const std::string& shown, int line, const std::string& what,
                           bool allowable = true) const {
    throw Error(ErrorCode::bad_input,
                fmt::format("{}: line {}: {}; refused{}", shown, line, what,
                            allowable ? " (CadSandbox::allow_geo_commands allows it)" : ""),
                allowable ? "CadSandbox::allow_geo_commands" : "");
  }

  void check_file(const fs::path& file, const std::string& shown) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return;  // Gmsh will say that it cannot open it
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::vector<Token> t = tokenize(buffer.str());
    stack.push_back(canonical_or_normal(file));
    const fs::path folder = file.parent_path();
    const fs::path shown_folder = fs::path(shown).parent_path();

    auto is = [&](std::size_t k, Token::Kind kind, const char* text = nullptr) {
      return k < t.size() && t[k].kind == kind && (text == nullptr || t[k].text == text);
    };
    // A command's argument: a string, or a word starting a string expression.
    auto argument_follows = [&](std::size_t k) {
      return is(k + 1, Token::string) || is(k + 1, Token::word);
    };

    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k].kind != Token::word) continue;
      const std::string& w = t[k].text;
      const int line = t[k].line;
      if ((w == "SystemCall" || w == "System" || w == "NonBlockingSystemCall") &&
          argument_follows(k)) {
        if (!allow) refuse(shown, line, w + " runs a shell command");
      } else if (w == "OnelabRun" && is(k + 1, Token::symbol, "(")) {
        if (!allow) refuse(shown, line, w + " runs a program");
      } else if ((w == "Printf" || w == "Sprintf") && is(k + 1, Token::symbol, "(")) {
        int depth = 0;
        std::size_t m = k + 1;
        for (; m < t.size(); ++m) {
          if (is(m, Token::symbol, "(")) ++depth;
          if (is(m, Token::symbol, ")") && --depth == 0) break;
        }
        if ((is(m + 1, Token::symbol, ">") || is(m + 1, Token::symbol, ">>")) && !allow)
          refuse(shown, line, w + " writes to a file (" + t[m + 1].text + ")");
      } else if ((w == "Save" || w == "Print") && argument_follows(k)) {
        if (!allow) refuse(shown, line, w + " writes a file");
      } else if (w == "Delete" && is(k + 1, Token::word, "File")) {
        if (!allow) refuse(shown, line, "Delete File deletes a file");
      } else if (w == "CreateDir" && argument_follows(k)) {
        if (!allow) refuse(shown, line, w + " creates a folder");
      } else if (w == "Exit") {  // a keyword of Gmsh's lexer: never a variable
        if (!allow) refuse(shown, line, "Exit ends the program");
      } else if ((w == "Include" || w == "Merge" || w == "MergeWithBoundingBox") &&
                 argument_follows(k)) {
        const bool literal = is(k + 1, Token::string) && is(k + 2, Token::symbol, ";");
        if (!literal) {
          if (!allow) refuse(shown, line, w + " of a computed path (it cannot be checked)");
          continue;
        }
        const bool script = w == "Include" || fs::path(t[k + 1].text).extension() == ".geo";
        check_reference(w, t[k + 1].text, folder, shown_folder, shown, line, script);
      } else if (w == "ShapeFromFile" && is(k + 1, Token::symbol, "(")) {
        if (!(is(k + 2, Token::string) && is(k + 3, Token::symbol, ")"))) {
          if (!allow) refuse(shown, line, w + " of a computed path (it cannot be checked)");
          continue;
        }
        check_reference(w, t[k + 2].text, folder, shown_folder, shown, line, false);
      }
    }
    stack.pop_back();
  }

  /// `command "argument"` in a script in `folder`: refused outside the top
  /// script's folder; a script (Include, Merge of a .geo) is checked in turn.
  void check_reference(const std::string& command, const std::string& argument,
                       const fs::path& folder, const fs::path& shown_folder,
                       const std::string& shown, int line, bool script) {
    const fs::path target = fs::path(argument).is_absolute() ? fs::path(argument) : folder / argument;
    const fs::path canonical = canonical_or_normal(target);
    if (!allow && !inside(canonical, root))
      refuse(shown, line,
             fmt::format("{} reads \"{}\", outside the script's folder", command, printable(argument)));
    if (!script) return;
    for (const fs::path& open : stack)
      if (open == canonical)
        refuse(shown, line,
               fmt::format("{} \"{}\" includes a script that is already being read (an include "
                           "cycle)",
                           command, printable(argument)),
               false);
    if (stack.size() >= static_cast<std::size_t>(max_include_depth))
      refuse(shown, line,
             fmt::format("{} \"{}\": scripts nested deeper than {}", command, printable(argument),
                         max_include_depth),
             false);
    const std::string shown_target = fs::path(argument).is_absolute()
                                         ? argument
                                         : (shown_folder / argument).lexically_normal().string();
    check_file(target, shown_target);
  }
};

}  // namespace

void check_geo_script(const std::string& path, bool allow_commands) {
  Checker checker;
  checker.allow = allow_commands;
  checker.root = canonical_or_normal(fs::absolute(path).parent_path());
  checker.check_file(path, path);
}

}  // namespace qm::io
