#include "tests/support/xml_check.h"

#include <cctype>

namespace qm::test {

namespace {

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' || c == '.';
}

/// Decodes the five predefined entities and numeric ones; false on any other '&'.
bool decode(const std::string& raw, std::string& out) {
  out.clear();
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '<') return false;
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    const std::size_t end = raw.find(';', i);
    if (end == std::string::npos) return false;
    const std::string entity = raw.substr(i + 1, end - i - 1);
    if (entity == "amp") out += '&';
    else if (entity == "lt") out += '<';
    else if (entity == "gt") out += '>';
    else if (entity == "quot") out += '"';
    else if (entity == "apos") out += '\'';
    else if (entity.size() > 1 && entity[0] == '#') out += '?';
    else return false;
    i = end;
  }
  return true;
}

}  // namespace

bool parse_xml(const std::string& xml, std::vector<XmlElement>& elements, std::string& why) {
  elements.clear();
  std::vector<std::size_t> open;  // indices into elements
  std::size_t i = 0;
  const auto fail = [&](const std::string& what) {
    why = what + " at offset " + std::to_string(i);
    return false;
  };
  const auto skip_space = [&] {
    while (i < xml.size() && std::isspace(static_cast<unsigned char>(xml[i]))) ++i;
  };
  skip_space();
  if (xml.compare(i, 5, "<?xml") == 0) {
    const std::size_t end = xml.find("?>", i);
    if (end == std::string::npos) return fail("unterminated declaration");
    i = end + 2;
    skip_space();
  }
  bool root_closed = false;
  while (i < xml.size()) {
    if (xml[i] != '<') {
      const std::size_t next = xml.find('<', i);
      const std::string raw = xml.substr(i, next == std::string::npos ? std::string::npos : next - i);
      std::string text;
      if (!decode(raw, text)) return fail("a bare & in text");
      if (open.empty()) {
        for (char c : raw)
          if (!std::isspace(static_cast<unsigned char>(c))) return fail("text outside the root element");
      } else {
        elements[open.back()].text += text;
      }
      if (next == std::string::npos) break;
      i = next;
      continue;
    }
    if (root_closed) return fail("a second root element");
    if (xml.compare(i, 2, "</") == 0) {
      std::size_t j = i + 2;
      while (j < xml.size() && name_char(xml[j])) ++j;
      const std::string name = xml.substr(i + 2, j - i - 2);
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      if (j >= xml.size() || xml[j] != '>') return fail("a malformed end tag");
      if (open.empty() || elements[open.back()].name != name) return fail("</" + name + "> closes nothing open");
      open.pop_back();
      root_closed = open.empty();
      i = j + 1;
      continue;
    }
    if (xml.compare(i, 2, "<!") == 0 || xml.compare(i, 2, "<?") == 0) return fail("a comment, CDATA or DOCTYPE");
    XmlElement element;
    std::size_t j = i + 1;
    while (j < xml.size() && name_char(xml[j])) ++j;
    element.name = xml.substr(i + 1, j - i - 1);
    if (element.name.empty()) return fail("a '<' without an element name");
    bool self_closing = false;
    while (true) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
      if (j >= xml.size()) return fail("an unterminated start tag");
      if (xml[j] == '>') break;
      if (xml.compare(j, 2, "/>") == 0) {
        self_closing = true;
        ++j;
        break;
      }
      const std::size_t name_start = j;
      while (j < xml.size() && name_char(xml[j])) ++j;
      const std::string attribute = xml.substr(name_start, j - name_start);
      if (attribute.empty() || j >= xml.size() || xml[j] != '=') return fail("an attribute without =\"value\"");
      ++j;
      if (j >= xml.size() || (xml[j] != '"' && xml[j] != '\'')) return fail("an unquoted attribute value");
      const char quote = xml[j];
      const std::size_t end = xml.find(quote, j + 1);
      if (end == std::string::npos) return fail("an unterminated attribute value");
      const std::string raw = xml.substr(j + 1, end - j - 1);
      std::string decoded;
      if (!decode(raw, decoded)) return fail("a bare < or & in attribute " + attribute);
      if (!element.attributes.emplace(attribute, raw).second) return fail("attribute " + attribute + " repeated");
      j = end + 1;
      if (j < xml.size() && !std::isspace(static_cast<unsigned char>(xml[j])) && xml[j] != '>' && xml[j] != '/')
        return fail("no space between attributes");
    }
    elements.push_back(std::move(element));
    if (self_closing)
      root_closed = open.empty();
    else
      open.push_back(elements.size() - 1);
    i = j + 1;
  }
  if (!open.empty()) return fail("<" + elements[open.back()].name + "> is not closed");
  if (elements.empty()) return fail("no element");
  return true;
}

}  // namespace qm::test
