#include "engine/dataset/pcd_file.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <sstream>

#include "engine/dataset/file_io.h"

namespace airis::engine {
namespace {

// Appends the little-endian bytes of `value` (x86-64 and ARM64 are little-endian).
template <class T>
void Put(std::vector<std::uint8_t>& out, T value) {
  std::uint8_t bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

// A whole number of a header line; throws DatasetIoError naming the file otherwise.
std::size_t ToCount(const std::string& text, const std::string& name) {
  std::size_t value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    throw DatasetIoError(name + ": '" + text + "' in the header is not a count");
  }
  return value;
}

}  // namespace

std::span<const PcdField> ScanPcdFields() {
  static const PcdField kFields[] = {
      {"x", 'F', 4, "position of the return, sensor frame at its firing time (m)"},
      {"y", 'F', 4, ""},
      {"z", 'F', 4, ""},
      {"range_m", 'F', 4, "measured range along the beam, noise included (m)"},
      {"intensity", 'F', 4,
       "stand-in: reflectivity of the material hit (mean linear base colour) x cosine of the "
       "incidence angle, 0 to 1"},
      {"time_offset_s", 'F', 4, "firing time minus the scan's time_ns (s, <= 0)"},
      {"ring", 'U', 2, "laser: index into the manifest's ring_elevations_deg"},
      {"column", 'U', 4, "azimuth step of the scan, in firing order"},
      {"instance_id", 'U', 4, "instance of the surface hit (labels.json)"},
      {"class_id", 'U', 1, "class of the surface hit (labels.json)"}};
  return kFields;
}

std::vector<std::uint8_t> EncodeScanPcd(const PointCloudSample& scan) {
  // The header of PCD v0.7 (pointclouds.org, "The PCD (Point Cloud Data) file format").
  std::string fields, sizes, types, counts;
  for (const PcdField& f : ScanPcdFields()) {
    fields += " " + f.name;
    sizes += " " + std::to_string(f.size);
    types += std::string(" ") + f.type;
    counts += " 1";
  }
  const std::string n = std::to_string(scan.points.size());
  const std::string header = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS" +
                             fields + "\nSIZE" + sizes + "\nTYPE" + types + "\nCOUNT" + counts +
                             "\nWIDTH " + n + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + n +
                             "\nDATA binary\n";
  std::vector<std::uint8_t> out(header.begin(), header.end());
  out.reserve(out.size() + 35 * scan.points.size());  // bytes of a record
  for (const PointReturn& p : scan.points) {
    Put(out, p.p_S_m.x());
    Put(out, p.p_S_m.y());
    Put(out, p.p_S_m.z());
    Put(out, p.range_m);
    Put(out, p.intensity);
    Put(out, p.time_offset_s);
    Put(out, p.ring);
    Put(out, p.column);
    Put(out, p.instance_id);
    Put(out, p.class_id);
  }
  return out;
}

std::size_t PcdCloud::Offset(const std::string& name) const {
  std::size_t offset = 0;
  for (const PcdField& f : fields) {
    if (f.name == name) return offset;
    offset += static_cast<std::size_t>(f.size);
  }
  throw DatasetIoError("PCD cloud has no field '" + name + "'");
}

PcdCloud DecodePcd(std::span<const std::uint8_t> bytes, const std::string& name) {
  const auto fail = [&](const std::string& why) -> PcdCloud {
    throw DatasetIoError(name + ": " + why);
  };
  PcdCloud cloud;
  std::vector<std::string> names, types;
  std::vector<int> sizes;
  std::size_t pos = 0;
  for (;;) {
    const auto end = std::find(bytes.begin() + static_cast<std::ptrdiff_t>(pos), bytes.end(),
                               static_cast<std::uint8_t>('\n'));
    if (end == bytes.end()) return fail("header has no DATA line");
    const std::string line(bytes.begin() + static_cast<std::ptrdiff_t>(pos), end);
    pos = static_cast<std::size_t>(end - bytes.begin()) + 1;
    std::istringstream words(line);
    std::string key, word;
    words >> key;
    if (key.empty() || key[0] == '#') continue;
    std::vector<std::string> values;
    while (words >> word) values.push_back(word);
    if (key == "FIELDS") names = values;
    if (key == "TYPE") types = values;
    if (key == "SIZE") {
      for (const auto& v : values) sizes.push_back(static_cast<int>(ToCount(v, name)));
    }
    if (key == "COUNT" &&
        std::any_of(values.begin(), values.end(), [](const std::string& v) { return v != "1"; })) {
      return fail("fields with COUNT other than 1 are not read");
    }
    if (key == "POINTS" && !values.empty()) cloud.points = ToCount(values[0], name);
    if (key == "DATA") {
      if (values.empty() || values[0] != "binary") return fail("not DATA binary");
      break;
    }
  }
  if (names.empty() || names.size() != types.size() || names.size() != sizes.size()) {
    return fail("FIELDS, SIZE and TYPE differ in length");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    cloud.fields.push_back({names[i], types[i].empty() ? '?' : types[i][0], sizes[i], ""});
    cloud.record_bytes += static_cast<std::size_t>(sizes[i]);
  }
  const std::size_t want = cloud.points * cloud.record_bytes;
  if (bytes.size() - pos < want) {
    return fail("holds " + std::to_string(bytes.size() - pos) + " bytes of points, expected " +
                std::to_string(want));
  }
  cloud.data.assign(bytes.begin() + static_cast<std::ptrdiff_t>(pos),
                    bytes.begin() + static_cast<std::ptrdiff_t>(pos + want));
  return cloud;
}

}  // namespace airis::engine
