// A headless OpenGL context: OSMesa (Debian 12's Mesa) or EGL surfaceless (newer
// Mesa releases removed OSMesa). Both render into the renderer's own framebuffer
// object, so a backend only has to make a core 3.3+ context current.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace shaderport::render {

enum class BackendKind : uint8_t { kOsMesa, kEgl };

const char* BackendName(BackendKind kind);
std::optional<BackendKind> BackendFromName(std::string_view name);
// The backend `shaderport render` uses without --backend.
BackendKind DefaultBackend();

class GlBackend {
 public:
  virtual ~GlBackend() = default;
  // Creates the context and makes it current on this thread; false with `error` set.
  virtual bool Start(std::string& error) = 0;
  virtual void* GetProc(const char* name) = 0;
};

// Only call in the render child: creating a context starts llvmpipe threads.
std::unique_ptr<GlBackend> CreateOsMesaBackend();
// nullptr-free: when libEGL cannot be loaded, Start() fails with a message.
std::unique_ptr<GlBackend> CreateEglBackend();
std::unique_ptr<GlBackend> CreateBackend(BackendKind kind);

}  // namespace shaderport::render
