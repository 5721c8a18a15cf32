#include "io/core/png_writer.h"

#include <png.h>

#include <memory>
#include <stdexcept>

#include "io/field/atomic_file.h"

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
  // Uninitialised: only the pages the encoder writes are ever touched, not
  // the worst case's (more than the pixels themselves).
  png_alloc_size_t bytes = PNG_IMAGE_PNG_SIZE_MAX(image);
  const std::unique_ptr<unsigned char[]> encoded(new unsigned char[bytes]);
  if (!png_image_write_to_memory(&image, encoded.get(), &bytes, 0, pixels, stride, nullptr)) fail(image.message);
  AtomicFile out(path);
  out.write(encoded.get(), bytes);
  out.commit(std::int64_t(bytes));
}

}  // namespace tg::io
