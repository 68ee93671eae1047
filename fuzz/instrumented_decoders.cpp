// stb_image and tinygltf come as Debian shared libraries, built without coverage or sanitizer instrumentation:
// libFuzzer could not see their branches and ASan could not check their memory accesses. The fuzz targets link
// these instrumented definitions instead, which take precedence over the shared libraries' at link time.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

// stb_image is declared and defined above; tinygltf's own include of it would define it twice.
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
