// The shaderport command line: a thin layer over the library.
#include <cstdio>

int main() {
  std::puts("shaderport " SHADERPORT_VERSION);
  return 0;
}
