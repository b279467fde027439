#include "base/osmesa_library.h"

#include <dlfcn.h>

namespace shaderport {
namespace {

struct Loaded {
  OsMesaLibrary library;
  std::string error;  // empty when every entry point was found
};

template <class Fn>
bool Resolve(void* handle, const char* name, Fn& out, std::string& error) {
  out = reinterpret_cast<Fn>(dlsym(handle, name));
  if (out == nullptr && error.empty()) error = std::string("libOSMesa.so.8 has no ") + name;
  return out != nullptr;
}

Loaded Load() {
  Loaded loaded;
  // RTLD_GLOBAL as a linked library was: Mesa's drivers may look its symbols up.
  void* handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_GLOBAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    loaded.error = std::string("cannot load libOSMesa.so.8 (install libosmesa6)") +
                   (why != nullptr ? std::string(": ") + why : std::string());
    return loaded;
  }
  OsMesaLibrary& lib = loaded.library;
  Resolve(handle, "OSMesaCreateContextAttribs", lib.create_context_attribs, loaded.error);
  Resolve(handle, "OSMesaMakeCurrent", lib.make_current, loaded.error);
  Resolve(handle, "OSMesaDestroyContext", lib.destroy_context, loaded.error);
  Resolve(handle, "OSMesaGetProcAddress", lib.get_proc_address, loaded.error);
  return loaded;
}

}  // namespace

const OsMesaLibrary* LoadOsMesa(std::string& error) {
  static const Loaded loaded = Load();
  if (!loaded.error.empty()) {
    error = loaded.error;
    return nullptr;
  }
  return &loaded.library;
}

}  // namespace shaderport
