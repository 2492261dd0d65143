#include "scenes/gdal_session.h"

#include <cpl_error.h>
#include <gdal.h>

#include <mutex>

namespace airis::scenes {
namespace {

void CPL_STDCALL Keep(CPLErr level, CPLErrorNum, const char* message) {
  if (level < CE_Failure || message == nullptr) return;  // warnings and notes are not errors
  *static_cast<std::string*>(CPLGetErrorHandlerUserData()) = message;
}

}  // namespace

GdalErrorCapture::GdalErrorCapture() {
  static std::once_flag registered;
  std::call_once(registered, [] { GDALAllRegister(); });
  CPLPushErrorHandlerEx(Keep, &last_);
}

GdalErrorCapture::~GdalErrorCapture() { CPLPopErrorHandler(); }

std::string GdalErrorCapture::Message(const std::string& fallback) const {
  return last_.empty() ? fallback : last_;
}

}  // namespace airis::scenes
