// OSMesa needs a client buffer to make a context current; the renderer draws into
// its own framebuffer object, so a 1x1 buffer is enough.
#include <array>

#include "base/osmesa_library.h"
#include "render/gl_backend.h"

namespace shaderport::render {
namespace {

class OsMesaBackend final : public GlBackend {
 public:
  ~OsMesaBackend() override {
    if (context_ != nullptr) {
      lib_->make_current(nullptr, nullptr, 0, 0, 0);
      lib_->destroy_context(context_);
    }
  }

  bool Start(std::string& error) override {
    lib_ = LoadOsMesa(error);
    if (lib_ == nullptr) return false;
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = lib_->create_context_attribs(attributes, nullptr);
    if (context_ == nullptr) {
      error = "OSMesaCreateContextAttribs failed for a core 4.5 context";
      return false;
    }
    if (!lib_->make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      error = "OSMesaMakeCurrent failed";
      return false;
    }
    return true;
  }

  void* GetProc(const char* name) override {
    return reinterpret_cast<void*>(lib_->get_proc_address(name));
  }

 private:
  const OsMesaLibrary* lib_ = nullptr;  // set by Start; context_ needs it
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> buffer_{};
};

}  // namespace

std::unique_ptr<GlBackend> CreateOsMesaBackend() { return std::make_unique<OsMesaBackend>(); }

}  // namespace shaderport::render
