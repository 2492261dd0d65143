#pragma once

// GDAL for the scenes library: drivers registered once, and GDAL's error messages caught for the
// scene's own errors instead of printed to stderr.

#include <string>

namespace airis::scenes {

/// While alive, GDAL errors raised on this thread are kept (the last one) instead of printed.
/// Registers GDAL's drivers on first use.
class GdalErrorCapture {
 public:
  GdalErrorCapture();
  ~GdalErrorCapture();
  GdalErrorCapture(const GdalErrorCapture&) = delete;
  GdalErrorCapture& operator=(const GdalErrorCapture&) = delete;

  /// The last error GDAL raised since construction, or `fallback` when it raised none.
  std::string Message(const std::string& fallback) const;
  /// True when GDAL raised an error since construction.
  bool HasError() const { return !last_.empty(); }

 private:
  std::string last_;
};

}  // namespace airis::scenes
