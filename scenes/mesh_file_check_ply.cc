#include "scenes/mesh_file_check_ply.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/limits.h"
#include "scenes/mesh_loader.h"

namespace airis::scenes {

namespace {

// A PLY header is a few hundred bytes; one this long is not a mesh.
constexpr std::size_t kMaxPlyHeaderBytes = 64 * 1024;

enum class Format { kAscii, kLittleEndian, kBigEndian };

struct ScalarType {
  const char* names[2];  // PLY 1.0's name and the sized alias
  std::size_t bytes;
  bool integral;
  bool is_signed;
};

constexpr ScalarType kTypes[] = {
    {{"char", "int8"}, 1, true, true},      {{"uchar", "uint8"}, 1, true, false},
    {{"short", "int16"}, 2, true, true},    {{"ushort", "uint16"}, 2, true, false},
    {{"int", "int32"}, 4, true, true},      {{"uint", "uint32"}, 4, true, false},
    {{"float", "float32"}, 4, false, true}, {{"double", "float64"}, 8, false, true},
};

struct Property {
  std::string name;
  const ScalarType* type = nullptr;        // the value's (the items' for a list)
  const ScalarType* count_type = nullptr;  // a list's count; null for a scalar
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

[[noreturn]] void Refuse(const std::string& problem) { throw MeshLoadError(problem); }

std::string Quote(std::string_view text) { return engine::QuoteValue(text); }

std::vector<std::string_view> Words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  while (true) {
    at = line.find_first_not_of(" \t", at);
    if (at == std::string_view::npos) return out;
    const std::size_t end = std::min(line.find_first_of(" \t", at), line.size());
    out.push_back(line.substr(at, end - at));
    at = end;
  }
}

const ScalarType* FindType(std::string_view name, std::size_t line) {
  for (const ScalarType& t : kTypes) {
    if (name == t.names[0] || name == t.names[1]) return &t;
  }
  Refuse("a PLY property of unknown type " + Quote(name) + " (header line " + std::to_string(line) +
         ")");
}

/// The header's elements; `*body_at` is set to the offset of the first byte after `end_header`'s
/// line.
std::vector<Element> ParseHeader(const std::string& head, Format* format, std::size_t* body_at) {
  std::vector<Element> elements;
  bool have_format = false;
  std::size_t at = 0;
  for (std::size_t number = 1;; ++number) {
    const std::size_t end = head.find('\n', at);
    if (end == std::string::npos) Refuse("a PLY file without 'end_header' in its first 64 KiB");
    std::string_view line(head.data() + at, end - at);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at = end + 1;
    const std::string where = "PLY header line " + std::to_string(number) + ": ";
    const std::vector<std::string_view> w = Words(line);
    if (number == 1) {
      if (line != "ply") Refuse("not a PLY file (its first line must be 'ply')");
      continue;
    }
    if (w.empty()) Refuse(where + "an empty line");
    if (w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") {
      if (w.size() != 1) Refuse(where + "'end_header' followed by " + Quote(line));
      break;
    }
    if (w[0] == "format") {
      if (have_format) Refuse(where + "a second 'format' line");
      if (w.size() != 3 || w[2] != "1.0") {
        Refuse(where + "expected 'format ascii|binary_little_endian|binary_big_endian 1.0' (got " +
               Quote(line) + ")");
      }
      if (w[1] == "ascii") {
        *format = Format::kAscii;
      } else if (w[1] == "binary_little_endian") {
        *format = Format::kLittleEndian;
      } else if (w[1] == "binary_big_endian") {
        *format = Format::kBigEndian;
      } else {
        Refuse(where + "unknown format " + Quote(w[1]));
      }
      have_format = true;
    } else if (w[0] == "element") {
      if (w.size() == 2) Refuse("a PLY element " + Quote(w[1]) + " without a count");
      if (w.size() != 3) Refuse(where + "expected 'element NAME COUNT' (got " + Quote(line) + ")");
      Element e;
      e.name = std::string(w[1]);
      const auto parsed = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (parsed.ec == std::errc::result_out_of_range) e.count = UINT64_MAX;
      if (parsed.ec == std::errc::invalid_argument || parsed.ptr != w[2].data() + w[2].size()) {
        Refuse("a PLY element " + Quote(e.name) + " without a count (got " + Quote(w[2]) + ")");
      }
      // assimp 5.2.5 knows these names; for any other it reads the count from the name itself (0,
      // or the name's leading digits: "element 999...9face 1" asked for 100 GB), so its reading of
      // the body would part from this one.
      static constexpr std::string_view kKnownElements[] = {"vertex", "face", "tristrips", "edge",
                                                            "material"};
      if (std::find(std::begin(kKnownElements), std::end(kKnownElements), e.name) ==
          std::end(kKnownElements)) {
        Refuse(where + "an element " + Quote(e.name) +
               " (assimp 5.2.5 reads vertex, face, tristrips, edge and material elements only)");
      }
      for (const Element& other : elements) {
        if (other.name == e.name) Refuse(where + "a second element " + Quote(e.name));
      }
      elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (elements.empty()) Refuse(where + "a property before any element");
      Property p;
      if (w.size() == 5 && w[1] == "list") {
        p.count_type = FindType(w[2], number);
        if (!p.count_type->integral) Refuse(where + "a list counted by " + Quote(w[2]));
        p.type = FindType(w[3], number);
        p.name = std::string(w[4]);
      } else if (w.size() == 3) {
        p.type = FindType(w[1], number);
        p.name = std::string(w[2]);
      } else {
        Refuse(where +
               "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME' (got " +
               Quote(line) + ")");
      }
      for (const Property& other : elements.back().properties) {
        if (other.name == p.name) Refuse(where + "a second property " + Quote(p.name));
      }
      elements.back().properties.push_back(std::move(p));
    } else {
      Refuse(where + "unknown keyword " + Quote(w[0]));
    }
  }
  if (!have_format) Refuse("a PLY header without a 'format' line");
  *body_at = at;
  return elements;
}

/// Reads the values of element instances, ASCII or binary, and says where it is.
class BodyReader {
 public:
  BodyReader(std::string_view body, Format format) : body_(body), format_(format) {}

  /// Starts an instance (ASCII: its line). `what` names it in messages.
  void BeginInstance(const std::string& what) {
    what_ = what;
    if (format_ != Format::kAscii) return;
    const std::size_t end = std::min(body_.find('\n', at_), body_.size());
    if (at_ >= body_.size()) Refuse(what_ + " is missing: the file ends before it");
    line_ = Words(body_.substr(at_, end - at_));
    if (!line_.empty() && line_.back().back() == '\r') {
      line_.back().remove_suffix(1);
      if (line_.back().empty()) line_.pop_back();
    }
    word_ = 0;
    at_ = end + 1;
  }

  /// Ends an instance: an ASCII line holds no more values.
  void EndInstance() const {
    if (format_ == Format::kAscii && word_ != line_.size()) {
      Refuse(what_ + " has " + std::to_string(line_.size()) +
             " values, more than its properties take");
    }
  }

  /// The next value, as a double (integers are exact up to 2^53, more than any count allowed).
  double Next(const ScalarType& type) {
    if (format_ == Format::kAscii) {
      if (word_ >= line_.size()) Refuse(what_ + " has fewer values than its properties take");
      const std::string_view w = line_[word_++];
      double v = 0;
      if (type.integral) {
        std::int64_t i = 0;
        const auto r = std::from_chars(w.data(), w.data() + w.size(), i);
        if (r.ec != std::errc() || r.ptr != w.data() + w.size()) {
          Refuse(what_ + ": " + Quote(w) + " is not an integer");
        }
        v = static_cast<double>(i);
      } else {
        const auto r = std::from_chars(w.data(), w.data() + w.size(), v);
        if (r.ec != std::errc() || r.ptr != w.data() + w.size()) {
          Refuse(what_ + ": " + Quote(w) + " is not a number");
        }
      }
      return v;
    }
    if (body_.size() - at_ < type.bytes) Refuse(what_ + " is cut off: the file ends inside it");
    unsigned char b[8];
    std::memcpy(b, body_.data() + at_, type.bytes);
    at_ += type.bytes;
    if ((format_ == Format::kBigEndian) == (std::endian::native == std::endian::little)) {
      std::reverse(b, b + type.bytes);
    }
    auto as = [&](auto v) {
      std::memcpy(&v, b, sizeof v);
      return static_cast<double>(v);
    };
    switch (type.bytes * 4 + (type.integral ? 0 : 2) + (type.is_signed ? 1 : 0)) {
      case 4:
        return as(std::uint8_t{});
      case 5:
        return as(std::int8_t{});
      case 8:
        return as(std::uint16_t{});
      case 9:
        return as(std::int16_t{});
      case 16:
        return as(std::uint32_t{});
      case 17:
        return as(std::int32_t{});
      case 19:
        return as(float{});
      default:
        return as(double{});
    }
  }

  /// Bytes (binary) or lines (ASCII) left, the least that `count` more instances of `per` bytes
  /// need, so that a count the body cannot hold is refused before it is walked.
  bool CanHold(std::uint64_t count, std::uint64_t per) const {
    const std::uint64_t left = body_.size() - std::min(at_, body_.size());
    if (format_ == Format::kAscii) return count <= left / 2;  // "0\n" at least
    return per == 0 || count <= left / per;
  }

 private:
  std::string_view body_;
  Format format_;
  std::size_t at_ = 0;
  std::string what_;
  std::vector<std::string_view> line_;
  std::size_t word_ = 0;
};

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

void CheckPlyFile(const std::string& path, std::uintmax_t file_bytes) {
  const std::string text = ReadFile(path);  // at most kMaxMeshFileBytes (checked by the caller)
  Format format = Format::kAscii;
  std::size_t body_at = 0;
  const std::vector<Element> elements =
      ParseHeader(text.substr(0, kMaxPlyHeaderBytes), &format, &body_at);
  const std::uint64_t body_bytes = file_bytes - std::min<std::uint64_t>(body_at, file_bytes);
  std::uint64_t vertices = 0;
  bool have_vertex = false;
  for (const Element& e : elements) {
    if (e.properties.empty()) Refuse("the PLY element " + Quote(e.name) + " has no properties");
    if (e.name == "vertex") {
      if (e.count > engine::kMaxMeshVertices) {
        Refuse("the file declares " + std::to_string(e.count) +
               " vertices, more than the limit of " + std::to_string(engine::kMaxMeshVertices) +
               " (docs/limits.md)");
      }
      for (const char* axis : {"x", "y", "z"}) {
        const bool found = std::any_of(
            e.properties.begin(), e.properties.end(),
            [&](const Property& p) { return p.name == axis && p.count_type == nullptr; });
        if (!found) {
          Refuse("the PLY element 'vertex' has no scalar property '" + std::string(axis) + "'");
        }
      }
      vertices = e.count;
      have_vertex = true;
    }
    if (e.name == "face" && e.count > engine::kMaxMeshTriangles) {
      Refuse("the file declares " + std::to_string(e.count) + " faces, more than the limit of " +
             std::to_string(engine::kMaxMeshTriangles) + " (docs/limits.md)");
    }
  }
  if (!have_vertex) Refuse("a PLY file without a 'vertex' element");
  BodyReader body(std::string_view(text).substr(std::min(body_at, text.size())), format);
  for (const Element& e : elements) {
    std::uint64_t per = 0;
    for (const Property& p : e.properties) per += (p.count_type ? p.count_type : p.type)->bytes;
    if (!body.CanHold(e.count, std::max<std::uint64_t>(per, 1))) {
      Refuse("the header declares " + std::to_string(e.count) + " " + Quote(e.name) +
             " elements, more than the " + std::to_string(body_bytes) + " bytes after it can hold");
    }
    const bool is_face = e.name == "face";
    for (std::uint64_t i = 0; i < e.count; ++i) {
      body.BeginInstance("PLY " + e.name + " " + std::to_string(i));
      for (const Property& p : e.properties) {
        if (p.count_type == nullptr) {
          body.Next(*p.type);
          continue;
        }
        const double n = body.Next(*p.count_type);
        const bool corners = is_face && (p.name == "vertex_indices" || p.name == "vertex_index");
        if (n < 0 || (corners && n < 3)) {
          Refuse("PLY " + e.name + " " + std::to_string(i) + " has a list '" + p.name + "' of " +
                 std::to_string(static_cast<std::int64_t>(n)) + " values" +
                 (corners ? " (a face needs at least 3 corners)" : ""));
        }
        for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(n); ++k) {
          const double v = body.Next(*p.type);
          if (corners &&
              !(v >= 0 && v < static_cast<double>(vertices) && v == static_cast<std::int64_t>(v))) {
            Refuse("PLY face " + std::to_string(i) + " names vertex " + engine::FormatNumber(v) +
                   ", but the file has " + std::to_string(vertices) + " vertices");
          }
        }
      }
      body.EndInstance();
    }
  }
}

}  // namespace airis::scenes
