#include "io/image_writer.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "io/atomic_file.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("writeImage: " + path + ": " + what);
}

std::string lowerExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

bool writesGeometryChannels(const std::string& path) { return lowerExtension(path) == "exr"; }

void writeImage(const render::FrameImage& img, const std::string& path) {
  const std::size_t n = std::size_t(img.width) * img.height;
  const std::string ext = lowerExtension(path);
  if (ext.empty()) fail(path, "no file extension");
  AtomicOutput out(path);
  auto writer = OIIO::ImageOutput::create(out.tempPath());
  if (!writer) fail(path, "no image format for extension \"." + ext + "\"");
  bool ok = false;
  if (ext == "exr") {
    if (img.depth.size() != n || img.normalWC.size() != 3 * n || img.id.size() != n)
      fail(path, "EXR output needs the depth, normal and id channels read back");
    OIIO::ImageSpec spec(img.width, img.height, 9, OIIO::TypeDesc::FLOAT);
    spec.nchannels = 9;
    spec.channelnames = {"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "id"};
    spec.channelformats.assign(9, OIIO::TypeDesc::FLOAT);
    spec.channelformats[8] = OIIO::TypeDesc::UINT;
    spec.z_channel = 4;
    spec.alpha_channel = 3;
    spec.attribute("compression", "zip");
    // Native per-channel layout: 8 floats then one uint32 per pixel.
    std::vector<unsigned char> buf(n * 36);
    for (std::size_t i = 0; i < n; ++i) {
      float f[8] = {img.rgba[4 * i], img.rgba[4 * i + 1], img.rgba[4 * i + 2], img.rgba[4 * i + 3],
                    img.depth[i], img.normalWC[3 * i], img.normalWC[3 * i + 1], img.normalWC[3 * i + 2]};
      std::memcpy(&buf[36 * i], f, 32);
      std::memcpy(&buf[36 * i + 32], &img.id[i], 4);
    }
    ok = writer->open(out.tempPath(), spec) && writer->write_image(OIIO::TypeUnknown, buf.data());
  } else {
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
    std::vector<unsigned char> px(4 * n);
    for (std::size_t i = 0; i < 4 * n; ++i)
      px[i] = static_cast<unsigned char>(std::clamp(img.rgba[i], 0.0f, 1.0f) * 255.0f + 0.5f);
    ok = writer->open(out.tempPath(), spec) && writer->write_image(OIIO::TypeDesc::UINT8, px.data());
  }
  if (!ok) fail(path, writer->geterror());
  if (!writer->close()) fail(path, writer->geterror());
  writer.reset();
  out.commit();
}

}  // namespace tg::io
