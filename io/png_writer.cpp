#include "io/png_writer.h"

#include <png.h>

#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"

namespace tg::io {

void writePng(const std::string& path, int width, int height, int channels, const unsigned char* pixels) {
  auto fail = [&](const std::string& what) { throw std::runtime_error("writePng: " + path + ": " + what); };
  if (width <= 0 || height <= 0 || (channels != 3 && channels != 4)) fail("no pixels, or not RGB/RGBA");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  const png_int_32 stride = png_int_32(width) * channels;
  // Room for the largest file these pixels can make, so that they are
  // compressed once (asking for the size first compresses them twice).
  std::vector<unsigned char> encoded(PNG_IMAGE_PNG_SIZE_MAX(image));
  png_alloc_size_t bytes = encoded.size();
  if (!png_image_write_to_memory(&image, encoded.data(), &bytes, 0, pixels, stride, nullptr)) fail(image.message);
  AtomicFile out(path);
  out.write(encoded.data(), bytes);
  out.commit(std::int64_t(bytes));
}

}  // namespace tg::io
