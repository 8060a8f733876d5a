// A small well-formedness check of XML documents (the SVG pictures), so that the
// tests need no XML library: elements nest and close, attributes are quoted and
// unique, text and attribute values hold no bare '<' or '&'.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace qm::test {

/// One element of a document, in document order.
struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;  ///< values as written (entities not decoded)
  std::string text;                               ///< the text directly inside it, entities decoded
};

/// Whether `xml` is one well-formed element (after an optional <?xml ...?>
/// declaration and blank space); `why` says the first problem and its offset.
/// Fills `elements` when it is. Comments, CDATA and DOCTYPE are refused.
bool parse_xml(const std::string& xml, std::vector<XmlElement>& elements, std::string& why);

}  // namespace qm::test
