#include "io/core/image_writer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/field/atomic_file.h"
#include "io/core/oiio_module.h"
#include "io/core/png_writer.h"

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

void writeThroughOiio(const std::string& path, const OiioImage& img) {
  const OiioModule& m = oiioModule("writeImage", path);
  AtomicFile out(path);
  out.commit(m.write(path, out.tempPath(), out.fd(), img));
}

}  // namespace

bool writesGeometryChannels(const std::string& path) { return lowerExtension(path) == "exr"; }

bool canWriteImage(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == "png") return true;
  return !ext.empty() && oiioModule("canWriteImage", path).canWrite(path);
}

std::vector<unsigned char> toRgba8(const render::FrameImage& img) {
  if (img.rgba.empty()) return img.rgba8;
  std::vector<unsigned char> px(img.rgba.size());
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = render::toUnorm8(img.rgba[i]);
  return px;
}

void writeImage(const render::FrameImage& img, const std::string& path) {
  const std::size_t n = std::size_t(img.width) * img.height;
  const std::string ext = lowerExtension(path);
  if (ext.empty()) fail(path, "no file extension");
  if (img.rgba.size() != 4 * n && img.rgba8.size() != 4 * n) fail(path, "the frame has no colour channels");
  if (ext == "exr") {
    if (img.rgba.size() != 4 * n) fail(path, "EXR output needs the float colour read back");
    if (img.depth.size() != n || img.normalWC.size() != 3 * n || img.id.size() != n)
      fail(path, "EXR output needs the depth, normal and id channels read back");
    // Native per-channel layout: 8 floats then one uint32 per pixel.
    std::vector<unsigned char> buf(n * 36);
    for (std::size_t i = 0; i < n; ++i) {
      float f[8] = {img.rgba[4 * i], img.rgba[4 * i + 1], img.rgba[4 * i + 2], img.rgba[4 * i + 3],
                    img.depth[i], img.normalWC[3 * i], img.normalWC[3 * i + 1], img.normalWC[3 * i + 2]};
      std::memcpy(&buf[36 * i], f, 32);
      std::memcpy(&buf[36 * i + 32], &img.id[i], 4);
    }
    OiioImage out;
    out.width = img.width;
    out.height = img.height;
    out.channelNames = {"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "id"};
    out.channelIsUint.assign(9, false);
    out.channelIsUint[8] = true;
    out.zChannel = 4;
    out.alphaChannel = 3;
    out.compression = "zip";
    out.pixels = buf.data();
    writeThroughOiio(path, out);
    return;
  }
  // A frame read back as 8 bits is written as it is, not copied.
  std::vector<unsigned char> converted;
  const std::vector<unsigned char>& px = img.rgba.empty() ? img.rgba8 : (converted = toRgba8(img));
  if (ext == "png") {
    writePng(path, img.width, img.height, 4, px.data());
    return;
  }
  // Other formats take the same 8-bit values, as floats for OIIO to store.
  std::vector<float> f(4 * n);
  for (std::size_t i = 0; i < 4 * n; ++i) f[i] = float(px[i]) / 255.0f;
  OiioImage out;
  out.width = img.width;
  out.height = img.height;
  out.channelNames = {"R", "G", "B", "A"};
  out.channelIsUint.assign(4, false);
  out.alphaChannel = 3;
  out.storeUint8 = true;
  out.pixels = f.data();
  writeThroughOiio(path, out);
}

}  // namespace tg::io
