#include "io/surface_transfer.h"

#include <cstring>
#include <type_traits>

namespace qm::io {

namespace {

constexpr char magic[] = "QMSF1";
constexpr char end_mark[] = "END";

class Writer {
 public:
  template <typename T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put_text(const std::string& text) {
    put<std::uint64_t>(text.size());
    bytes_ += text;
  }
  void raw(const char* text) { bytes_ += text; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    T value{};
    if (!need(sizeof value)) return value;
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  /// A count of items of `item_size` bytes each, checked against what is left.
  std::size_t count(std::size_t item_size) {
    const auto n = get<std::uint64_t>();
    if (ok_ && item_size > 0 && n > (bytes_.size() - at_) / item_size) ok_ = false;
    return ok_ ? static_cast<std::size_t>(n) : 0;
  }
  std::string text() {
    const std::size_t n = count(1);
    if (!need(n)) return {};
    std::string t = bytes_.substr(at_, n);
    at_ += n;
    return t;
  }
  bool expect(const char* word) {
    const std::size_t n = std::strlen(word);
    if (!need(n) || bytes_.compare(at_, n, word) != 0) return ok_ = false;
    at_ += n;
    return true;
  }
  bool ok() const { return ok_; }
  bool at_end() const { return at_ == bytes_.size(); }

 private:
  bool need(std::size_t n) {
    if (!ok_ || bytes_.size() - at_ < n) ok_ = false;
    return ok_;
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
  bool ok_ = true;
};

}  // namespace

std::string encode_surface(const SurfaceFile& file) {
  const TriangleSoup& soup = file.soup;
  Writer w;
  w.raw(magic);
  w.put<char>('S');
  w.put<double>(file.cad_mesh_size);
  w.put<std::uint64_t>(file.polygons_split);
  w.put<std::uint64_t>(soup.points.size());
  for (const Vec3& p : soup.points) {
    w.put<double>(p.x());
    w.put<double>(p.y());
    w.put<double>(p.z());
  }
  w.put<std::uint64_t>(soup.point_labels.size());
  for (std::int64_t label : soup.point_labels) w.put<std::int64_t>(label);
  w.put<std::uint64_t>(soup.triangles.size());
  for (const Triangle& t : soup.triangles)
    for (int v : t) w.put<std::int32_t>(v);
  w.put<std::uint64_t>(soup.triangle_labels.size());
  for (std::int64_t label : soup.triangle_labels) w.put<std::int64_t>(label);
  w.put<std::uint64_t>(soup.cad.edges.size());
  for (const CurveEdge& e : soup.cad.edges) {
    w.put<std::int32_t>(e.a);
    w.put<std::int32_t>(e.b);
    w.put<std::int32_t>(e.curve);
  }
  w.put<std::uint64_t>(soup.cad.groups.size());
  for (const PhysicalCurveGroup& g : soup.cad.groups) {
    w.put<std::int32_t>(g.tag);
    w.put_text(g.name);
    w.put<std::uint64_t>(g.curves.size());
    for (int c : g.curves) w.put<std::int32_t>(c);
  }
  w.put<std::uint64_t>(soup.cad.surface_groups.size());
  for (const PhysicalSurfaceGroup& g : soup.cad.surface_groups) {
    w.put<std::int32_t>(g.tag);
    w.put_text(g.name);
    w.put<std::uint64_t>(g.elements.size());
    for (std::int64_t e : g.elements) w.put<std::int64_t>(e);
  }
  w.raw(end_mark);
  return w.take();
}

std::string encode_error(const Error& error) {
  Writer w;
  w.raw(magic);
  w.put<char>('E');
  w.put<std::int32_t>(static_cast<std::int32_t>(error.code()));
  w.put_text(error.what());
  w.raw(end_mark);
  return w.take();
}

std::optional<std::variant<SurfaceFile, Error>> decode_result(const std::string& bytes,
                                                                Format format) {
  Reader r(bytes);
  if (!r.expect(magic)) return std::nullopt;
  const char kind = r.get<char>();
  if (kind == 'E') {
    const auto code = static_cast<ErrorCode>(r.get<std::int32_t>());
    std::string message = r.text();
    if (!r.expect(end_mark) || !r.at_end()) return std::nullopt;
    return std::variant<SurfaceFile, Error>(Error(code, message));
  }
  if (kind != 'S') return std::nullopt;
  SurfaceFile file;
  file.format = format;
  TriangleSoup& soup = file.soup;
  file.cad_mesh_size = r.get<double>();
  file.polygons_split = static_cast<std::size_t>(r.get<std::uint64_t>());
  soup.points.resize(r.count(3 * sizeof(double)));
  for (Vec3& p : soup.points) {
    const double x = r.get<double>(), y = r.get<double>(), z = r.get<double>();
    p = Vec3(x, y, z);
  }
  soup.point_labels.resize(r.count(sizeof(std::int64_t)));
  for (std::int64_t& label : soup.point_labels) label = r.get<std::int64_t>();
  soup.triangles.resize(r.count(3 * sizeof(std::int32_t)));
  for (Triangle& t : soup.triangles)
    for (int& v : t) v = r.get<std::int32_t>();
  soup.triangle_labels.resize(r.count(sizeof(std::int64_t)));
  for (std::int64_t& label : soup.triangle_labels) label = r.get<std::int64_t>();
  soup.cad.edges.resize(r.count(3 * sizeof(std::int32_t)));
  for (CurveEdge& e : soup.cad.edges) {
    e.a = r.get<std::int32_t>();
    e.b = r.get<std::int32_t>();
    e.curve = r.get<std::int32_t>();
  }
  soup.cad.groups.resize(r.count(sizeof(std::int32_t) + 2 * sizeof(std::uint64_t)));
  for (PhysicalCurveGroup& g : soup.cad.groups) {
    g.tag = r.get<std::int32_t>();
    g.name = r.text();
    g.curves.resize(r.count(sizeof(std::int32_t)));
    for (int& c : g.curves) c = r.get<std::int32_t>();
  }
  soup.cad.surface_groups.resize(r.count(sizeof(std::int32_t) + 2 * sizeof(std::uint64_t)));
  for (PhysicalSurfaceGroup& g : soup.cad.surface_groups) {
    g.tag = r.get<std::int32_t>();
    g.name = r.text();
    g.elements.resize(r.count(sizeof(std::int64_t)));
    for (std::int64_t& e : g.elements) e = r.get<std::int64_t>();
  }
  if (!r.expect(end_mark) || !r.at_end() || !r.ok()) return std::nullopt;
  return std::variant<SurfaceFile, Error>(std::move(file));
}

}  // namespace qm::io
