#pragma once

#include <span>
#include <string>

namespace airis::scenes {

/// One row of docs/limits.md.
struct LimitDoc {
  const char* what;   ///< what is bounded
  std::string value;  ///< the bound, with its unit
  const char* keys;   ///< the keys or options it applies to
};

/// Every limit of engine/core/limits.h (and the few kept beside what they bound), in the order
/// docs/limits.md lists them.
std::span<const LimitDoc> Limits();

/// The Markdown table of Limits() (| what | limit | applies to |), as docs/limits.md holds it
/// (checked by a test).
std::string LimitsMarkdown();

}  // namespace airis::scenes
