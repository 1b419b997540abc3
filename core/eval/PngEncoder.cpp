#include "eval/PngEncoder.hpp"

#include "unimap/Errors.hpp"

// The one translation unit with stb_image_write's implementation; static so
// it cannot clash with another copy (for example libstb.so) in the process.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace unimap::eval {
namespace {

// stbi_write_func: appends each chunk to the std::string passed as context.
void Append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::string EncodePng(const PlotCanvas& canvas) {
  std::string bytes;
  const int ok = stbi_write_png_to_func(&Append, &bytes, canvas.width(), canvas.height(), 3,
                                        canvas.rgb().data(), canvas.width() * 3);
  if (ok == 0) throw Error("PNG encoding failed");
  return bytes;
}

}  // namespace unimap::eval
