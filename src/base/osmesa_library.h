// libOSMesa, loaded on first use (dlopen) instead of linked: a linked OSMesa made every
// run load Mesa and LLVM and resolve their symbols at start-up (1.5 % of a `check` that
// never renders). Only the four entry points used are looked up; GL functions come
// through get_proc_address as before.
#pragma once

#include <GL/osmesa.h>

#include <string>

namespace shaderport {

struct OsMesaLibrary {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

// The library, loaded once per process (thread-safe); nullptr with `error` set when
// libOSMesa.so.8 or one of its entry points is missing. It stays loaded until exit.
const OsMesaLibrary* LoadOsMesa(std::string& error);

}  // namespace shaderport
