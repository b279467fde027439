// EGL on Mesa's surfaceless platform, loaded with dlopen so that the build needs no
// EGL package and nothing links libEGL/libGL ahead of OSMesa.
#include <dlfcn.h>

#include <cstdint>

#include "render/gl_backend.h"

namespace shaderport::render {
namespace {

// The few EGL names used, from the Khronos headers (stable ABI values).
using EglDisplay = void*;
using EglContext = void*;
using EglConfig = void*;
using EglInt = int32_t;
constexpr EglInt kEglNone = 0x3038;
constexpr EglInt kEglOpenGlApi = 0x30A2;
constexpr EglInt kEglRenderableType = 0x3040;
constexpr EglInt kEglOpenGlBit = 0x0008;
constexpr EglInt kEglSurfaceType = 0x3033;
constexpr EglInt kEglContextMajorVersion = 0x3098;
constexpr EglInt kEglContextMinorVersion = 0x30FB;
constexpr EglInt kEglContextOpenGlProfileMask = 0x30FD;
constexpr EglInt kEglContextOpenGlCoreProfileBit = 0x0001;
constexpr EglInt kEglPlatformSurfacelessMesa = 0x31DD;

using GetProcAddressFn = void* (*)(const char*);
using GetPlatformDisplayFn = EglDisplay (*)(uint32_t, void*, const intptr_t*);
using InitializeFn = uint32_t (*)(EglDisplay, EglInt*, EglInt*);
using BindApiFn = uint32_t (*)(uint32_t);
using ChooseConfigFn = uint32_t (*)(EglDisplay, const EglInt*, EglConfig*, EglInt, EglInt*);
using CreateContextFn = EglContext (*)(EglDisplay, EglConfig, EglContext, const EglInt*);
using MakeCurrentFn = uint32_t (*)(EglDisplay, void*, void*, EglContext);
using DestroyContextFn = uint32_t (*)(EglDisplay, EglContext);
using TerminateFn = uint32_t (*)(EglDisplay);

class EglBackend final : public GlBackend {
 public:
  ~EglBackend() override {
    if (context_ != nullptr) {
      make_current_(display_, nullptr, nullptr, nullptr);
      destroy_context_(display_, context_);
    }
    if (display_ != nullptr) terminate_(display_);
    // The library stays loaded: Mesa's threads may still reference it until exit.
  }

  bool Start(std::string& error) override {
#if defined(SHADERPORT_EGL) && SHADERPORT_EGL == 0
    error = "this build has no EGL backend (configured with SHADERPORT_EGL=OFF)";
    return false;
#endif
    library_ = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (library_ == nullptr) {
      error = "cannot load libEGL.so.1 (install libegl1 and libegl-mesa0)";
      return false;
    }
    get_proc_ = reinterpret_cast<GetProcAddressFn>(dlsym(library_, "eglGetProcAddress"));
    if (get_proc_ == nullptr) {
      error = "libEGL.so.1 has no eglGetProcAddress";
      return false;
    }
    auto get_platform_display =
        reinterpret_cast<GetPlatformDisplayFn>(get_proc_("eglGetPlatformDisplay"));
    auto initialize = reinterpret_cast<InitializeFn>(get_proc_("eglInitialize"));
    auto bind_api = reinterpret_cast<BindApiFn>(get_proc_("eglBindAPI"));
    auto choose_config = reinterpret_cast<ChooseConfigFn>(get_proc_("eglChooseConfig"));
    auto create_context = reinterpret_cast<CreateContextFn>(get_proc_("eglCreateContext"));
    make_current_ = reinterpret_cast<MakeCurrentFn>(get_proc_("eglMakeCurrent"));
    destroy_context_ = reinterpret_cast<DestroyContextFn>(get_proc_("eglDestroyContext"));
    terminate_ = reinterpret_cast<TerminateFn>(get_proc_("eglTerminate"));
    if (!get_platform_display || !initialize || !bind_api || !choose_config || !create_context ||
        !make_current_ || !destroy_context_ || !terminate_) {
      error = "libEGL.so.1 lacks EGL 1.5 entry points";
      return false;
    }
    display_ = get_platform_display(kEglPlatformSurfacelessMesa, nullptr, nullptr);
    EglInt major = 0;
    EglInt minor = 0;
    if (display_ == nullptr || !initialize(display_, &major, &minor)) {
      display_ = nullptr;
      error = "EGL surfaceless platform (EGL_MESA_platform_surfaceless) is unavailable";
      return false;
    }
    if (!bind_api(kEglOpenGlApi)) {
      error = "eglBindAPI(EGL_OPENGL_API) failed";
      return false;
    }
    const EglInt config_attributes[] = {kEglSurfaceType, 0, kEglRenderableType, kEglOpenGlBit,
                                        kEglNone};
    EglConfig config = nullptr;
    EglInt count = 0;
    if (!choose_config(display_, config_attributes, &config, 1, &count) || count == 0) {
      error = "no EGL config for desktop OpenGL";
      return false;
    }
    const EglInt context_attributes[] = {kEglContextMajorVersion,
                                         4,
                                         kEglContextMinorVersion,
                                         5,
                                         kEglContextOpenGlProfileMask,
                                         kEglContextOpenGlCoreProfileBit,
                                         kEglNone};
    context_ = create_context(display_, config, nullptr, context_attributes);
    if (context_ == nullptr) {
      error = "eglCreateContext failed for a core 4.5 context";
      return false;
    }
    if (!make_current_(display_, nullptr, nullptr, context_)) {
      error = "eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context)";
      return false;
    }
    return true;
  }

  void* GetProc(const char* name) override { return get_proc_ ? get_proc_(name) : nullptr; }

 private:
  void* library_ = nullptr;
  GetProcAddressFn get_proc_ = nullptr;
  MakeCurrentFn make_current_ = nullptr;
  DestroyContextFn destroy_context_ = nullptr;
  TerminateFn terminate_ = nullptr;
  EglDisplay display_ = nullptr;
  EglContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<GlBackend> CreateEglBackend() { return std::make_unique<EglBackend>(); }

}  // namespace shaderport::render
