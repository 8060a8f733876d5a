// Text inside an XML (SVG) document.
#pragma once

#include <string>

namespace qm::tools {

/// `text` with &, <, > and " replaced by their entities, so that it can stand in
/// an element's text or an attribute value.
std::string xml_escaped(const std::string& text);

}  // namespace qm::tools
