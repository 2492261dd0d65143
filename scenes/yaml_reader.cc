#include "scenes/yaml_reader.h"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace airis::scenes {

using engine::ConfigError;
using engine::QuoteValue;
using engine::SourceLocation;

namespace {

/// Where each document of a text starts (the parser's events, nothing built).
class DocumentStarts final : public YAML::EventHandler {
 public:
  explicit DocumentStarts(std::vector<YAML::Mark>& starts) : starts_(starts) {}
  void OnDocumentStart(const YAML::Mark& mark) override { starts_.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}

 private:
  std::vector<YAML::Mark>& starts_;
};

/// Counts the values of a document with every alias expanded (each alias adds the size of the
/// node it names), from the parser's events: linear in the text, whatever the expansion.
class ExpandedValueCounter final : public YAML::EventHandler {
 public:
  explicit ExpandedValueCounter(std::string file) : file_(std::move(file)) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { Leaf(mark, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    Add(mark, anchor < sizes_.size() ? sizes_[anchor] : 1);
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string&) override {
    Leaf(mark, anchor);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    Open(mark, anchor);
  }
  void OnSequenceEnd() override { Close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    Open(mark, anchor);
  }
  void OnMapEnd() override { Close(); }

 private:
  struct Collection {
    YAML::anchor_t anchor;
    YAML::Mark mark;
    std::uint64_t count;
  };
  void Leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
    Record(anchor, 1);
    Add(mark, 1);
  }
  void Open(const YAML::Mark& mark, YAML::anchor_t anchor) { open_.push_back({anchor, mark, 1}); }
  void Close() {
    const Collection done = open_.back();
    open_.pop_back();
    Record(done.anchor, done.count);
    Add(done.mark, done.count);
  }
  void Record(YAML::anchor_t anchor, std::uint64_t count) {
    if (anchor == YAML::NullAnchor) return;
    if (anchor >= sizes_.size()) sizes_.resize(anchor + 1, 1);
    sizes_[anchor] = count;
  }
  void Add(const YAML::Mark& mark, std::uint64_t count) {
    std::uint64_t& total = open_.empty() ? root_ : open_.back().count;
    total += count;
    if (total > engine::kMaxYamlValues) {
      YamlReader(file_).Fail(mark, "",
                             "the file expands to more than " +
                                 std::to_string(engine::kMaxYamlValues) +
                                 " values through its YAML aliases (the limit, docs/limits.md)");
    }
  }

  std::string file_;
  std::vector<Collection> open_;
  std::vector<std::uint64_t> sizes_;  // values of each anchored node, by anchor id
  std::uint64_t root_ = 0;
};

/// A key as it appears in a key path: as written when it is a plain name, else quoted (cut and
/// escaped) so that a huge or binary key makes a readable message.
std::string PrintableKey(const std::string& key) {
  for (char c : key) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '_' || c == '-';
    if (!plain) return QuoteValue(key);
  }
  return key.size() <= engine::kMaxQuotedChars ? key : QuoteValue(key);
}

}  // namespace

SourceLocation YamlReader::Where(const YAML::Mark& mark) const {
  // yaml-cpp marks are 0-based and -1 when unknown; ConfigError wants 1-based with 0 = unknown.
  return SourceLocation{file_, mark.line >= 0 ? mark.line + 1 : 0,
                        mark.column >= 0 ? mark.column + 1 : 0};
}

void YamlReader::Fail(const YAML::Mark& mark, const std::string& key_path,
                      const std::string& problem) const {
  throw ConfigError(Where(mark), key_path, problem);
}

std::string YamlReader::Describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar:
      return QuoteValue(node.Scalar());
  }
  return "?";
}

const std::string& YamlReader::RequireScalar(const YAML::Node& node, const YAML::Mark& mark,
                                             const std::string& key_path, const char* what) const {
  if (!node.IsScalar()) {
    Fail(mark, key_path, std::string("expected ") + what + " (got " + Describe(node) + ")");
  }
  return node.Scalar();
}

void YamlReader::RequireSequence(const YAML::Node& node, const YAML::Mark& mark,
                                 const std::string& key_path, const std::string& what) const {
  if (!node.IsSequence())
    Fail(mark, key_path, "expected " + what + " (got " + Describe(node) + ")");
}

double YamlReader::ParseDouble(const YAML::Node& node, const YAML::Mark& mark,
                               const std::string& key_path) const {
  const std::string& text = RequireScalar(node, mark, key_path, "a number");
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || result.ec == std::errc::invalid_argument ||
      result.ptr != digits.data() + digits.size()) {
    if (text == ".nan" || text == ".NaN" || text == ".inf" || text == "-.inf" || text == ".Inf" ||
        text == "-.Inf" || text == "nan" || text == "inf" || text == "-inf") {
      Fail(mark, key_path, "must be a finite number (got " + text + ")");
    }
    Fail(mark, key_path, "expected a number (got " + QuoteValue(text) + ")");
  }
  if (result.ec == std::errc::result_out_of_range || !std::isfinite(value)) {
    Fail(mark, key_path, "must be a finite number (got " + QuoteValue(text) + ")");
  }
  return value;
}

std::int64_t YamlReader::ParseInteger(const YAML::Node& node, const YAML::Mark& mark,
                                      const std::string& key_path, std::int64_t lo,
                                      std::int64_t hi) const {
  const std::string& text = RequireScalar(node, mark, key_path, "an integer");
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  std::int64_t value = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const std::string range = " (got " + QuoteValue(text) + "; expected " + std::to_string(lo) +
                            " to " + std::to_string(hi) + ")";
  if (result.ec == std::errc::result_out_of_range) Fail(mark, key_path, "out of range" + range);
  if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    Fail(mark, key_path, "expected an integer (got " + QuoteValue(text) + ")");
  }
  if (value < lo || value > hi) Fail(mark, key_path, "out of range" + range);
  return value;
}

std::uint64_t YamlReader::ParseUnsigned64(const YAML::Node& node, const YAML::Mark& mark,
                                          const std::string& key_path) const {
  const std::string& text = RequireScalar(node, mark, key_path, "an integer");
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  std::uint64_t value = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (result.ec == std::errc::result_out_of_range || (!digits.empty() && digits.front() == '-')) {
    Fail(mark, key_path,
         "out of range (got " + QuoteValue(text) + "; expected 0 to 18446744073709551615)");
  }
  if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
    Fail(mark, key_path, "expected an integer (got " + QuoteValue(text) + ")");
  }
  return value;
}

bool YamlReader::ParseBool(const YAML::Node& node, const YAML::Mark& mark,
                           const std::string& key_path) const {
  const std::string& text = RequireScalar(node, mark, key_path, "true or false");
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  Fail(mark, key_path, "expected true or false (got " + QuoteValue(text) + ")");
}

void YamlReader::FailEnum(const YAML::Mark& mark, const std::string& key_path,
                          const std::string& text, const std::vector<std::string>& choices) const {
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) list += (i + 1 == choices.size()) ? " or " : ", ";
    list += choices[i];
  }
  std::string problem = "unknown value " + QuoteValue(text) + " (expected " + list;
  if (const auto close = engine::ClosestMatch(text, choices))
    problem += "; did you mean '" + *close + "'?";
  Fail(mark, key_path, problem + ")");
}

bool YamlReader::FindKey(const YAML::Node& node, std::string_view key, YAML::Node* value,
                         YAML::Mark* mark) {
  for (const auto& entry : node) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) {
      value->reset(entry.second);  // reset rebinds; operator= would write into the tree
      *mark = entry.first.Mark();
      return true;
    }
  }
  return false;
}

std::size_t YamlReader::ParseListIndex(const YAML::Node& key, const std::string& key_path,
                                       std::size_t size) const {
  const std::string last = size == 0 ? "" : " (0 to " + std::to_string(size - 1) + ")";
  std::size_t index = 0;
  const std::string text = key.IsScalar() ? key.Scalar() : "";
  const auto result = std::from_chars(text.data(), text.data() + text.size(), index);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    Fail(key.Mark(), key_path,
         "a map in place of a list changes entries by their 0-based index: expected an index" +
             last + " as key (got " + Describe(key) + ")");
  }
  if (index >= size) {
    Fail(key.Mark(), key_path + "[" + text + "]",
         "no entry " + text + " to change: the list has " + std::to_string(size) +
             (size == 1 ? " entry" : " entries") + last);
  }
  return index;
}

bool YamlReader::FindListEntry(const YAML::Node& node, std::size_t index, YAML::Node* value,
                               YAML::Mark* mark) {
  if (node.IsSequence()) {
    if (index >= node.size()) return false;
    value->reset(node[index]);
    *mark = value->Mark();
    return true;
  }
  if (!node.IsMap()) return false;
  for (const auto& entry : node) {
    std::size_t key = 0;
    const std::string& text = entry.first.Scalar();
    const auto result = std::from_chars(text.data(), text.data() + text.size(), key);
    if (result.ec == std::errc() && result.ptr == text.data() + text.size() && key == index) {
      value->reset(entry.second);
      *mark = entry.first.Mark();
      return true;
    }
  }
  return false;
}

void YamlReader::RejectUnknownKeys(
    const YAML::Node& node, const std::string& key_path, const std::vector<std::string>& known,
    const std::vector<std::pair<std::string, std::string>>& renamed) const {
  std::vector<std::string> seen;
  for (const auto& entry : node) {
    const YAML::Node& key = entry.first;
    Collect([&] {
      if (!key.IsScalar())
        Fail(key.Mark(), key_path, "a key must be a plain name (got " + Describe(key) + ")");
      const std::string& name = key.Scalar();
      const std::string path = yaml_detail::JoinKey(key_path, PrintableKey(name));
      bool is_known = false;
      for (const auto& k : known) is_known = is_known || k == name;
      if (is_known) {
        // Only known keys are remembered: an unknown one is refused below, so this stays short.
        for (const auto& s : seen) {
          if (s == name) Fail(key.Mark(), path, "duplicate key");
        }
        seen.push_back(name);
        return;
      }
      for (const auto& [old_key, new_key] : renamed) {
        if (old_key == name) {
          Fail(key.Mark(), path,
               "renamed to '" + new_key +
                   "' in format 2 (names say their frame and unit: docs/architecture.md, "
                   "\"Names\")");
        }
      }
      std::string problem = "unknown key " + QuoteValue(name);
      // A typo of an old spelling suggests the key's new name.
      std::vector<std::string> candidates = known;
      for (const auto& r : renamed) candidates.push_back(r.first);
      if (auto close =
              engine::ClosestMatch(name.substr(0, 4 * engine::kMaxQuotedChars), candidates)) {
        for (const auto& [old_key, new_key] : renamed) {
          if (*close == old_key) *close = new_key;
        }
        problem += " (did you mean '" + *close + "'?)";
      } else {
        problem += " (valid keys: ";
        for (std::size_t i = 0; i < known.size(); ++i) problem += (i > 0 ? ", " : "") + known[i];
        problem += ")";
      }
      Fail(key.Mark(), path, problem);
    });
  }
}

YAML::Mark YamlReader::FindFieldMark(const YAML::Node& node, const YAML::Mark& mark,
                                     std::string_view field) {
  // Walk the field's relative path ("mount.roll_deg", "species[2].height_m") through the node to
  // the deepest key that exists.
  YAML::Node current;
  current.reset(node);
  YAML::Mark where = mark;
  std::size_t pos = 0;
  while (pos < field.size() && current.IsDefined()) {
    if (field[pos] == '.') {
      ++pos;
      continue;
    }
    if (field[pos] == '[') {
      const std::size_t close = field.find(']', pos);
      if (close == std::string::npos) break;
      std::size_t index = 0;
      const auto parsed = std::from_chars(field.data() + pos + 1, field.data() + close, index);
      YAML::Node value;
      if (parsed.ec != std::errc() || !FindListEntry(current, index, &value, &where)) break;
      current.reset(value);
      pos = close + 1;
      continue;
    }
    const std::size_t end = std::min(field.find_first_of(".[", pos), field.size());
    YAML::Node value;
    YAML::Mark key_mark;
    if (!current.IsMap() || !FindKey(current, field.substr(pos, end - pos), &value, &key_mark)) {
      break;
    }
    current.reset(value);
    where = key_mark;
    pos = end;
  }
  return where;
}

void YamlReader::FailInvalidField(const YAML::Node& node, const YAML::Mark& mark,
                                  const std::string& key_path,
                                  const engine::InvalidField& e) const {
  // An absent key means the default was invalid: reported at the struct.
  const std::string& field = e.field();
  std::string path = key_path;
  if (!field.empty())
    path = (path.empty() || field.front() == '[') ? path + field : path + "." + field;
  Fail(FindFieldMark(node, mark, field), path, e.problem());
}

void YamlReader::RequireListSize(std::size_t size, const YAML::Mark& mark,
                                 const std::string& key_path) const {
  if (size <= engine::kMaxListEntries) return;
  Fail(mark, key_path,
       "a list of " + std::to_string(size) + " entries is longer than the limit of " +
           std::to_string(engine::kMaxListEntries) + " (docs/limits.md)");
}

void YamlReader::RequireUtf8(const std::string& text, const YAML::Mark& mark,
                             const std::string& key_path) const {
  if (!engine::IsValidUtf8(text))
    Fail(mark, key_path, "is not valid UTF-8 text (got " + QuoteValue(text) + ")");
}

YAML::Node LoadYamlString(const std::string& text, const std::string& file) {
  // The documents are counted with at most two parser passes rather than read with
  // YAML::LoadAll: yaml-cpp 0.7 never gets past a ',' outside a flow collection ("a: 1\n,") and
  // yields an empty document there for ever, which LoadAll collects until memory runs out (found by
  // the mission fuzzer: 52 bytes, 3 GB).
  YAML::Node first;
  std::vector<YAML::Mark> starts;
  try {
    first = YAML::Load(text);
    std::istringstream in(text);
    YAML::Parser parser(in);
    DocumentStarts counter(starts);
    while (starts.size() < 2 && parser.HandleNextDocument(counter)) {
    }
  } catch (const YAML::Exception& e) {
    throw ConfigError(SourceLocation{file, e.mark.line >= 0 ? e.mark.line + 1 : 0,
                                     e.mark.column >= 0 ? e.mark.column + 1 : 0},
                      "", "invalid YAML: " + e.msg);
  }
  for (const YAML::Mark& at : starts) {
    if (at.pos >= 0 && static_cast<std::size_t>(at.pos) < text.size() && text[at.pos] == ',') {
      YamlReader(file).Fail(at, "",
                            "invalid YAML: a ',' outside a flow sequence or map ([...] or {...})");
    }
  }
  if (starts.size() > 1) {
    // A second document would be ignored: its settings silently lost.
    YAML::Mark at = starts[1];
    if (at.line < 0) {
      // An empty second document has no position: point at its '---' (the last one).
      at.line = 0;
      at.column = 0;
      std::size_t line_start = 0;
      for (int line = 0; line_start < text.size(); ++line) {
        if (text.compare(line_start, 3, "---") == 0) at.line = line;
        const std::size_t next = text.find('\n', line_start);
        if (next == std::string::npos) break;
        line_start = next + 1;
      }
    }
    YamlReader(file).Fail(at, "",
                          "a second YAML document (after '---'): a file holds one document, "
                          "merge them or use `include`");
  }
  if (text.find('&') != std::string::npos) {
    // Anchors, so perhaps aliases: count what they expand to before anything reads the tree.
    std::istringstream in(text);
    YAML::Parser parser(in);
    ExpandedValueCounter counter(file);
    parser.HandleNextDocument(counter);
  }
  return first;
}

YAML::Node LoadYamlFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    throw ConfigError(SourceLocation{path, 0, 0}, "", "file not found");
  }
  if (fs::is_directory(status)) {
    throw ConfigError(SourceLocation{path, 0, 0}, "", "is a folder, not a YAML file");
  }
  if (!fs::is_regular_file(status)) {
    throw ConfigError(SourceLocation{path, 0, 0}, "", "is not a regular file");
  }
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (!ec && bytes > engine::kMaxYamlFileBytes) {
    throw ConfigError(SourceLocation{path, 0, 0}, "",
                      "the file has " + std::to_string(bytes) + " bytes, more than the limit of " +
                          std::to_string(engine::kMaxYamlFileBytes) + " (docs/limits.md)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(SourceLocation{path, 0, 0}, "", "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return LoadYamlString(text.str(), path);
}

}  // namespace airis::scenes
