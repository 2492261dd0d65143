#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/world/sensor_samples.h"

namespace airis::engine {

/// One field of a PCD file: its name, its type letter (F float, U unsigned, I signed) and size in
/// bytes.
struct PcdField {
  std::string name;
  char type = 'F';
  int size = 4;
  std::string doc;  ///< what it holds (docs/dataset-format.md); not in the file
  bool operator==(const PcdField& o) const {
    return name == o.name && type == o.type && size == o.size;
  }
};

/// The fields of a scan's PCD file, in the order each point's record holds them (packed, no
/// padding): x y z (F4, metres, sensor frame), range_m (F4), intensity (F4), time_offset_s (F4),
/// ring (U2), column (U4), instance_id (U4), class_id (U1): 35 bytes a point.
std::span<const PcdField> ScanPcdFields();

/// A lidar scan as a binary PCD file (the Point Cloud Library's format, version 0.7; read by PCL,
/// Open3D's tensor reader and CloudCompare): the scan's returns as an unorganised cloud (WIDTH =
/// returns, HEIGHT = 1) of ScanPcdFields, little-endian, viewpoint the sensor origin. Depends only
/// on the points: the same scan gives the same bytes.
std::vector<std::uint8_t> EncodeScanPcd(const PointCloudSample& scan);

/// A binary PCD file read back: its fields, point count and the packed records.
struct PcdCloud {
  std::vector<PcdField> fields;
  std::size_t points = 0;
  std::size_t record_bytes = 0;    ///< sum of the fields' sizes
  std::vector<std::uint8_t> data;  ///< points * record_bytes

  /// Byte offset of field `name` in a record; throws DatasetIoError when absent.
  std::size_t Offset(const std::string& name) const;
  /// Field `name` of point `i`, as the type T of its size (float, std::uint16_t, ...).
  template <class T>
  T Get(std::size_t i, const std::string& name) const {
    T value;
    const std::uint8_t* p = data.data() + i * record_bytes + Offset(name);
    std::copy(p, p + sizeof(T), reinterpret_cast<std::uint8_t*>(&value));
    return value;
  }
};

/// Reads a binary PCD file with one value per field (what EncodeScanPcd writes). Throws
/// DatasetIoError naming `name` for another PCD flavour (ascii, compressed, COUNT > 1) or a file
/// shorter than its header says.
PcdCloud DecodePcd(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace airis::engine
