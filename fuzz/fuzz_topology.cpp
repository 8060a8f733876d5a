// libFuzzer target: the topology checks (method.md section 0) on arbitrary triangle
// soups. The bytes are read as a small header (point count) and then points (three
// doubles each, any bit pattern: NaN, inf, denormals, huge values) and triangles
// (three 16-bit point indices each, taken modulo the point count, so repeated
// corners, duplicates, non-manifold edges and pinched vertices all occur).
// analyze_topology must never throw or crash, and assess_applicability must
// give a verdict for every soup.
#include "libquadmesh/topology/applicability.h"
#include "libquadmesh/topology/topology_report.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t point_count = 1 + data[0] % 64;
  std::size_t at = 1;
  qm::TriangleSoup soup;
  for (std::size_t i = 0; i < point_count && at + 24 <= size; ++i, at += 24) {
    double x[3];
    std::memcpy(x, data + at, sizeof x);
    soup.points.emplace_back(x[0], x[1], x[2]);
    soup.point_labels.push_back(static_cast<std::int64_t>(i));
  }
  if (soup.points.empty()) return 0;
  const auto n = static_cast<unsigned>(soup.points.size());
  for (std::int64_t t = 0; at + 6 <= size; at += 6, ++t) {
    std::uint16_t v[3];
    std::memcpy(v, data + at, sizeof v);
    soup.triangles.push_back({static_cast<int>(v[0] % n), static_cast<int>(v[1] % n), static_cast<int>(v[2] % n)});
    soup.triangle_labels.push_back(t);
  }
  const qm::AnalyzedSurface surface = qm::analyze_topology(soup);
  (void)qm::assess_applicability(surface);
  return 0;
}
