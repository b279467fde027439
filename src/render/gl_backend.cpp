#include "render/gl_backend.h"

namespace shaderport::render {

const char* BackendName(BackendKind kind) { return kind == BackendKind::kEgl ? "egl" : "osmesa"; }

std::optional<BackendKind> BackendFromName(std::string_view name) {
  if (name == "osmesa") return BackendKind::kOsMesa;
  if (name == "egl") return BackendKind::kEgl;
  return std::nullopt;
}

BackendKind DefaultBackend() {
#ifdef SHADERPORT_DEFAULT_BACKEND_EGL
  return BackendKind::kEgl;
#else
  return BackendKind::kOsMesa;
#endif
}

std::unique_ptr<GlBackend> CreateBackend(BackendKind kind) {
  return kind == BackendKind::kEgl ? CreateEglBackend() : CreateOsMesaBackend();
}

}  // namespace shaderport::render
