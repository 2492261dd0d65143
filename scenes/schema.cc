#include "scenes/schema.h"

namespace airis::scenes {

namespace {

/// Escapes the characters that would break a Markdown table cell.
std::string Cell(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '|') {
      out += "\\|";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string FieldTableMarkdown(std::span<const FieldDoc> fields, const std::string& prefix) {
  std::string out = "| key | type | default | meaning |\n|---|---|---|---|\n";
  for (const FieldDoc& f : fields) {
    out += "| `" + Cell(prefix + f.key) + "` | " + Cell(f.type) + " | " +
           (f.default_value.empty() ? "" : "`" + Cell(f.default_value) + "`") + " | " +
           Cell(f.doc) + " |\n";
  }
  return out;
}

}  // namespace airis::scenes
