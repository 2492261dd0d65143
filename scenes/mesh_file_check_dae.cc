#include "scenes/mesh_file_check_dae.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <iterator>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "engine/core/config.h"
#include "engine/core/limits.h"
#include "scenes/mesh_loader.h"

namespace airis::scenes {

using engine::kMaxMeshVertices;

namespace {

std::string Count(std::uint64_t n) { return std::to_string(n); }

[[noreturn]] void Refuse(const std::string& problem) { throw MeshLoadError(problem); }

bool IsSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

/// The value of attribute `name` among `attributes` (a start tag's text after its name), quoted
/// with either quote and with spaces allowed around '='; nothing if the tag has no such attribute.
std::optional<std::string_view> Attribute(std::string_view attributes, std::string_view name) {
  for (std::size_t at = attributes.find(name); at != std::string_view::npos;
       at = attributes.find(name, at + 1)) {
    if (at == 0 || !IsSpace(attributes[at - 1])) continue;
    std::size_t k = at + name.size();
    while (k < attributes.size() && IsSpace(attributes[k])) ++k;
    if (k >= attributes.size() || attributes[k] != '=') continue;
    ++k;
    while (k < attributes.size() && IsSpace(attributes[k])) ++k;
    if (k >= attributes.size() || (attributes[k] != '"' && attributes[k] != '\'')) continue;
    const std::size_t end = attributes.find(attributes[k], k + 1);
    if (end == std::string_view::npos) return std::nullopt;
    return attributes.substr(k + 1, end - k - 1);
  }
  return std::nullopt;
}

/// A COLLADA index list (`<p>`, `<vcount>`, `<h>`, `<v>`; its element's name ends at `name_end`)
/// holds whole numbers and white space only (the schema's ListOfUInts; skin
/// weights' `<v>` may hold -1), each below the vertex limit. assimp 5.2.5 reads "0OOO 1 2" as a
/// list that never ends and allocates gigabytes (docs/fuzzing.md, "Findings").
void CheckDaeIndexList(const std::string& text, const std::string& tag, std::size_t name_end,
                       std::size_t index) {
  const std::size_t close = text.find('>', name_end);
  if (close == std::string::npos) Refuse("COLLADA <" + tag + "> " + Count(index) + " does not end");
  if (text[close - 1] == '/') return;
  const std::size_t end = std::min(text.find('<', close), text.size());
  for (std::size_t k = close + 1; k < end;) {
    const unsigned char c = static_cast<unsigned char>(text[k]);
    if (std::isspace(c)) {
      ++k;
      continue;
    }
    const std::size_t digits = k + (tag == "v" && c == '-' ? 1 : 0);
    std::uint64_t value = 0;
    const auto r = std::from_chars(text.data() + digits, text.data() + end, value);
    const bool ends =
        r.ptr == text.data() + end || std::isspace(static_cast<unsigned char>(*r.ptr));
    if (r.ec != std::errc() || !ends || value >= 3 * kMaxMeshVertices) {
      std::size_t word_end = k;
      while (word_end < end && !std::isspace(static_cast<unsigned char>(text[word_end]))) {
        ++word_end;
      }
      Refuse("COLLADA <" + tag + "> " + Count(index) + " holds " +
             engine::QuoteValue(text.substr(k, word_end - k)) +
             " where an index (a whole number below " + Count(3 * kMaxMeshVertices) + ") belongs");
    }
    k = static_cast<std::size_t>(r.ptr - text.data());
  }
}

/// A value array (`<float_array>`, ...; `what` names it) has a whole-number `count` attribute equal
/// to the number of values it holds.
void CheckDaeArray(const std::string& text, const std::string& what, std::string_view attributes,
                   std::size_t close) {
  std::optional<std::uint64_t> declared;
  if (const auto count = Attribute(attributes, "count")) {
    std::uint64_t n = 0;
    const auto r = std::from_chars(count->data(), count->data() + count->size(), n);
    if (r.ec == std::errc() && r.ptr == count->data() + count->size() && !count->empty()) {
      declared = n;
    }
  }
  if (!declared) Refuse(what + " without a whole-number 'count' attribute");
  if (*declared > 3 * kMaxMeshVertices) {
    Refuse("the file declares " + Count(*declared) +
           " values in one COLLADA array, more than the limit of " + Count(3 * kMaxMeshVertices) +
           " (docs/limits.md)");
  }
  std::uint64_t values = 0;
  if (text[close - 1] != '/') {
    const std::size_t end = std::min(text.find('<', close), text.size());
    bool in_value = false;
    for (std::size_t k = close + 1; k < end; ++k) {
      const bool space = IsSpace(text[k]);
      if (!space && !in_value) ++values;
      in_value = !space;
    }
  }
  if (values != *declared) {
    Refuse(what + " declares count=" + Count(*declared) + " but holds " + Count(values) +
           " values");
  }
}

/// An instance element and the reference it makes (`#id`, or whatever the file holds).
struct Instance {
  std::string what;
  const char* attribute;
  std::optional<std::string_view> reference;
};

}  // namespace

void CheckDaeText(const std::string& text) {
  static const std::string kArrays[] = {"float_array",  "int_array",  "Name_array", "IDREF_array",
                                        "SIDREF_array", "bool_array", "token_array"};
  // The index lists of primitives (<p>, <vcount>, <h>) and of skin weights (<v>).
  static const std::string kIndexLists[] = {"p", "vcount", "h", "v"};
  // The instances assimp resolves, each by its url; a material instance names its material by
  // `target`. assimp gives up on a scene instance naming no scene, and leaks the meshes read.
  static const std::string kInstances[] = {
      "instance_visual_scene", "instance_node",   "instance_geometry",
      "instance_controller",   "instance_camera", "instance_light",
      "instance_effect",       "instance_image",  "instance_material"};
  std::size_t arrays = 0;
  std::size_t lists = 0;
  std::unordered_set<std::string_view> ids;
  std::vector<Instance> instances;
  std::unordered_map<std::string, std::size_t> instances_of;  // per element name
  for (std::size_t open = text.find('<'); open != std::string::npos;
       open = text.find('<', open + 1)) {
    if (text.compare(open, 4, "<!--") == 0) {
      open = text.find("-->", open + 4);
      if (open == std::string::npos) Refuse("a COLLADA comment that does not end");
      continue;
    }
    std::size_t name_end = open + 1;
    while (name_end < text.size() && (std::isalnum(static_cast<unsigned char>(text[name_end])) ||
                                      text[name_end] == '_' || text[name_end] == ':')) {
      ++name_end;
    }
    const std::string tag = text.substr(open + 1, name_end - open - 1);
    if (tag.empty()) continue;  // an end tag, a declaration or a processing instruction
    if (std::find(std::begin(kIndexLists), std::end(kIndexLists), tag) != std::end(kIndexLists)) {
      CheckDaeIndexList(text, tag, name_end, lists++);
      continue;
    }
    const std::size_t close = text.find('>', name_end);
    if (close == std::string::npos) Refuse("COLLADA <" + tag + "> does not end");
    const std::string_view attributes(text.data() + name_end, close - name_end);
    if (const auto id = Attribute(attributes, "id")) ids.insert(*id);
    if (std::find(std::begin(kArrays), std::end(kArrays), tag) != std::end(kArrays)) {
      CheckDaeArray(text, "COLLADA <" + tag + "> " + Count(arrays++), attributes, close);
    } else if (std::find(std::begin(kInstances), std::end(kInstances), tag) !=
               std::end(kInstances)) {
      const char* attribute = tag == "instance_material" ? "target" : "url";
      instances.push_back({"COLLADA <" + tag + "> " + Count(instances_of[tag]++), attribute,
                           Attribute(attributes, attribute)});
    }
  }
  for (const Instance& instance : instances) {
    if (!instance.reference) {
      Refuse(instance.what + " without its '" + instance.attribute + "' attribute");
    }
    const std::string_view ref = *instance.reference;
    if (ref.empty() || ref[0] != '#' || ids.count(ref.substr(1)) == 0) {
      Refuse(instance.what + ": " + instance.attribute + "=" + engine::QuoteValue(ref) +
             " names no element of the file (expected '#' and the id of one: airis reads a COLLADA "
             "file alone)");
    }
  }
}

}  // namespace airis::scenes
