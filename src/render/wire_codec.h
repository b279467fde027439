// The byte encoding both render wire formats use (request_wire: parent to worker,
// outcome_wire: worker to parent): fixed-size values in host order and strings
// with a 64-bit length, read back with a bounds check on every field. Both ends
// are the same binary, so host order is enough.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace shaderport::render::wire {

template <typename T>
void Put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

inline void PutString(std::string& out, const std::string& text) {
  Put(out, static_cast<uint64_t>(text.size()));
  out += text;
}

struct Reader {
  const std::string& bytes;
  size_t at = 0;

  template <typename T>
  bool Get(T& value) {
    if (bytes.size() - at < sizeof(T)) return false;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return true;
  }
  bool GetString(std::string& text) {
    uint64_t size = 0;
    if (!Get(size) || bytes.size() - at < size) return false;
    text.assign(bytes, at, size);
    at += size;
    return true;
  }
  bool GetBool(bool& value) {
    uint8_t byte = 0;
    if (!Get(byte) || byte > 1) return false;
    value = byte == 1;
    return true;
  }
};

}  // namespace shaderport::render::wire
