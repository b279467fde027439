#include "validate/snprintf_fast_path.h"

#include <climits>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace shaderport::validate {
namespace {

// Per thread: a shared counter would bounce between cores on every token.
thread_local uint64_t fast_path_copies = 0;

}  // namespace

uint64_t SnprintfFastPathCopiesOnThisThread() { return fast_path_copies; }

#if SHADERPORT_WRAP_SNPRINTF

bool SnprintfFastPathLinked() { return true; }

// snprintf by the linker's name for the wrapper: every call of snprintf in the link
// comes here.
int WrappedSnprintf(char* out, size_t size, const char* format, ...) asm("__wrap_snprintf");

// "%s" with a string is a bounded copy (C11 7.21.6.5: at most size - 1 bytes and a NUL,
// the full length returned); a null pointer, which glibc prints as "(null)", and every
// other format go to vsnprintf.
int WrappedSnprintf(char* out, size_t size, const char* format, ...) {
  va_list arguments;
  va_start(arguments, format);
  if (format[0] == '%' && format[1] == 's' && format[2] == '\0') {
    va_list peek;
    va_copy(peek, arguments);
    const char* text = va_arg(peek, const char*);
    va_end(peek);
    const size_t length = text != nullptr ? std::strlen(text) : 0;
    if (text != nullptr && length <= INT_MAX) {
      va_end(arguments);
      if (size != 0) {
        const size_t copied = length < size ? length : size - 1;
        std::memcpy(out, text, copied);
        out[copied] = '\0';
      }
      ++fast_path_copies;
      return static_cast<int>(length);
    }
  }
  const int result = std::vsnprintf(out, size, format, arguments);
  va_end(arguments);
  return result;
}

#else

bool SnprintfFastPathLinked() { return false; }

#endif

}  // namespace shaderport::validate
