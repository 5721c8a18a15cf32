#include "io/image_writer.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
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

// OIIO's writers see a file that never fails: the first error is kept here
// and reported once the writer is done, so a library that ignores a short
// write (libpng) or exits on one (libjpeg) never meets it.
class FdProxy final : public OIIO::Filesystem::IOProxy {
 public:
  explicit FdProxy(const AtomicFile& f) : IOProxy(f.tempPath(), Write), fd_(f.fd()) {}
  const char* proxytype() const override { return "tensorglyph-fd"; }
  size_t write(const void* buf, size_t n) override {
    pwrite(buf, n, m_pos);
    m_pos += std::int64_t(n);
    return n;
  }
  size_t pwrite(const void* buf, size_t n, int64_t offset) override {
    const auto* p = static_cast<const char*>(buf);
    for (std::size_t done = 0; done < n && !error_;) {
      const ssize_t w = ::pwrite(fd_, p + done, n - done, offset + std::int64_t(done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) error_ = w < 0 ? errno : EIO;
      else done += std::size_t(w);
    }
    size_ = std::max(size_, std::size_t(offset) + n);
    return n;
  }
  size_t read(void* buf, size_t n) override {
    const size_t r = pread(buf, n, m_pos);
    m_pos += std::int64_t(r);
    return r;
  }
  size_t pread(void* buf, size_t n, int64_t offset) override {
    const ssize_t r = ::pread(fd_, buf, n, offset);
    return r > 0 ? std::size_t(r) : 0;
  }
  size_t size() const override { return size_; }
  int error() const { return error_; }

 private:
  int fd_;
  int error_ = 0;
  std::size_t size_ = 0;
};

}  // namespace

bool writesGeometryChannels(const std::string& path) { return lowerExtension(path) == "exr"; }

void writeImage(const render::FrameImage& img, const std::string& path) {
  const std::size_t n = std::size_t(img.width) * img.height;
  const std::string ext = lowerExtension(path);
  if (ext.empty()) fail(path, "no file extension");
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
    writeOiioImage(path, spec, OIIO::TypeUnknown, buf.data());
    return;
  }
  OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> px(4 * n);
  for (std::size_t i = 0; i < 4 * n; ++i)
    px[i] = static_cast<unsigned char>(std::clamp(img.rgba[i], 0.0f, 1.0f) * 255.0f + 0.5f);
  writeOiioImage(path, spec, OIIO::TypeDesc::UINT8, px.data());
}

void writeOiioImage(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc format, const void* pixels) {
  auto writer = OIIO::ImageOutput::create(path);
  if (!writer) fail(path, "no image format for extension \"." + lowerExtension(path) + "\"");
  AtomicFile out(path);
  if (writer->supports("ioproxy")) {
    FdProxy proxy(out);
    if (!writer->set_ioproxy(&proxy) || !writer->open(path, spec) || !writer->write_image(format, pixels) ||
        !writer->close())
      fail(path, writer->geterror());
    if (proxy.error()) fail(path, std::string("write failed: ") + std::strerror(proxy.error()));
    writer.reset();
    out.commit(std::int64_t(proxy.size()));
    return;
  }
  // A writer that takes only a path (sgi, ico, heif) cannot be told its
  // writes failed: what it wrote must decode again before it is committed.
  if (!writer->open(out.tempPath(), spec) || !writer->write_image(format, pixels) || !writer->close())
    fail(path, writer->geterror());
  writer.reset();
  auto check = OIIO::ImageInput::open(out.tempPath());
  std::vector<float> back;
  if (check) back.resize(std::size_t(spec.width) * spec.height * std::size_t(spec.nchannels));
  if (!check || check->spec().width != spec.width || check->spec().height != spec.height ||
      !check->read_image(0, 0, 0, std::min(spec.nchannels, check->spec().nchannels), OIIO::TypeDesc::FLOAT,
                         back.data()))
    fail(path, "what was written does not read back (disk full?)");
  check.reset();
  out.commit();
}

}  // namespace tg::io
