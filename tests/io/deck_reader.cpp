#include "tests/io/deck_reader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace qm::test {

namespace {

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) {
    field.erase(std::remove_if(field.begin(), field.end(), [](unsigned char c) { return std::isspace(c); }),
                field.end());
    out.push_back(field);
  }
  return out;
}

/// The value of KEY=value in a keyword line ("" if absent).
std::string keyword_value(const std::string& line, const std::string& key) {
  for (const std::string& f : split_commas(line)) {
    std::string upper = f;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper.rfind(key + "=", 0) == 0) return f.substr(key.size() + 1);
  }
  return "";
}

std::string field(const std::string& line, std::size_t start, std::size_t width) {
  if (start >= line.size()) return "";
  std::string f = line.substr(start, width);
  f.erase(std::remove_if(f.begin(), f.end(), [](unsigned char c) { return std::isspace(c); }), f.end());
  return f;
}

}  // namespace

DeckRead read_inp(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  DeckRead deck;
  std::string line, block, name, type;
  while (std::getline(in, line)) {
    if (line.empty() || line.rfind("**", 0) == 0) continue;
    if (line[0] == '*') {
      const std::string keyword = split_commas(line)[0];
      block = keyword;
      if (keyword == "*ELEMENT") {
        type = keyword_value(line, "TYPE");
        name = keyword_value(line, "ELSET");
      }
      if (keyword == "*NSET") name = keyword_value(line, "NSET");
      if (keyword == "*SURFACE") name = keyword_value(line, "NAME");
      if (keyword == "*ELEMENT" && (type.rfind("T3D", 0) == 0 || type.rfind("B3", 0) == 0)) block = "line";
      continue;
    }
    const std::vector<std::string> f = split_commas(line);
    if (block == "*NODE")
      deck.nodes[std::stoi(f[0])] = Vec3(std::stod(f[1]), std::stod(f[2]), f.size() > 3 ? std::stod(f[3]) : 0.0);
    else if (block == "line")
      ++deck.line_elements;
    else if (block == "*ELEMENT") {
      DeckElementRead e{std::stoi(f[0]), type, {}};
      for (std::size_t i = 1; i < f.size(); ++i)
        if (!f[i].empty()) e.nodes.push_back(std::stoi(f[i]));
      deck.elements.push_back(e);
      deck.element_sets[name].push_back(e.id);
    } else if (block == "*NSET") {
      for (const std::string& id : f)
        if (!id.empty()) deck.node_sets[name].push_back(std::stoi(id));
    } else if (block == "*SURFACE") {
      deck.surfaces[name].push_back({std::stoi(f[0]), f[1]});
    }
  }
  return deck;
}

DeckRead read_bdf(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  DeckRead deck;
  std::string set_name;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.rfind("$ node set ", 0) == 0) set_name = l.substr(11, l.find(':') - 11);
    if (l.rfind("GRID*", 0) == 0) {  // large field, continuation "*" line holds z
      const std::string& c = lines.at(i + 1);
      deck.nodes[std::stoi(field(l, 8, 16))] =
          Vec3(std::stod(field(l, 40, 16)), std::stod(field(l, 56, 16)), std::stod(field(c, 8, 16)));
      continue;
    }
    const std::string card = field(l, 0, 8);
    if (card.empty() || card[0] == '$' || card == "*") continue;
    // small field entry with blank-field continuation lines
    std::vector<int> values;
    for (std::size_t j = i;; ++j) {
      for (std::size_t k = 8; k < 72; k += 8)
        if (const std::string v = field(lines[j], k, 8); !v.empty()) values.push_back(std::stoi(v));
      if (j + 1 >= lines.size() || lines[j + 1].rfind("        ", 0) != 0) {
        i = j;
        break;
      }
    }
    if (card == "SET1")
      deck.node_sets[set_name] = std::vector<int>(values.begin() + 1, values.end());
    else if (card == "CBAR" || card == "CROD")
      ++deck.line_elements;
    else
      deck.elements.push_back({values.at(0), card, std::vector<int>(values.begin() + 2, values.end())});
  }
  return deck;
}

DeckRead read_unv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  DeckRead deck;
  std::string line;
  int dataset = 0;
  bool open = false;
  while (std::getline(in, line)) {
    if (field(line, 0, 80) == "-1") {
      open = !open;
      dataset = 0;
      continue;
    }
    if (open && dataset == 0) {
      dataset = std::stoi(field(line, 0, 80));
      continue;
    }
    std::istringstream words(line);
    if (dataset == 2411) {
      int id = 0;
      words >> id;
      std::string coords;
      std::getline(in, coords);
      std::istringstream c(coords);
      double x = 0, y = 0, z = 0;
      c >> x >> y >> z;
      deck.nodes[id] = Vec3(x, y, z);
    } else if (dataset == 2412) {
      int id = 0, property = 0, material = 0, color = 0, count = 0;
      std::string type;
      words >> id >> type >> property >> material >> color >> count;
      std::vector<int> nodes;
      while (static_cast<int>(nodes.size()) < count && std::getline(in, line)) {
        std::istringstream n(line);
        for (int v = 0; n >> v;) nodes.push_back(v);
      }
      if (count == 8) nodes = {nodes[0], nodes[2], nodes[4], nodes[6], nodes[1], nodes[3], nodes[5], nodes[7]};
      deck.elements.push_back({id, type, nodes});
    } else if (dataset == 2467) {
      std::vector<int> head;
      for (int v = 0; words >> v;) head.push_back(v);
      std::string name;
      std::getline(in, name);
      name = field(name, 0, 80);
      const int count = head.at(7);
      std::vector<int> entity;
      while (static_cast<int>(entity.size()) < 4 * count && std::getline(in, line)) {
        std::istringstream n(line);
        for (int v = 0; n >> v;) entity.push_back(v);
      }
      for (int k = 0; k < count; ++k) {
        const int code = entity[static_cast<std::size_t>(4 * k)], tag = entity[static_cast<std::size_t>(4 * k + 1)];
        (code == 7 ? deck.node_sets : deck.element_sets)[name].push_back(tag);
      }
    }
  }
  return deck;
}

std::vector<Vec3> element_points(const DeckRead& deck, const DeckElementRead& e) {
  std::vector<Vec3> out;
  for (int v : e.nodes) out.push_back(deck.nodes.at(v));
  return out;
}

}  // namespace qm::test
