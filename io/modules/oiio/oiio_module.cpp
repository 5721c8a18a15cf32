// The OpenImageIO module (io/core/oiio_module.h): built as tensorglyph-oiio.so and
// loaded only by the commands that write through OpenImageIO.
#include "io/core/oiio_module.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error("writeImage: " + path + ": " + what);
}

// OIIO's writers see a file that never fails: the first error is kept here
// and reported once the writer is done, so a library that ignores a short
// write (libpng) or exits on one (libjpeg) never meets it.
class FdProxy final : public OIIO::Filesystem::IOProxy {
 public:
  FdProxy(const std::string& tempPath, int fd) : IOProxy(tempPath, Write), fd_(fd) {}
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


bool canWrite(const std::string& path) { return OIIO::ImageOutput::create(path) != nullptr; }

OIIO::ImageSpec specOf(const OiioImage& img) {
  const int n = int(img.channelNames.size());
  const bool anyUint = std::find(img.channelIsUint.begin(), img.channelIsUint.end(), true) != img.channelIsUint.end();
  OIIO::ImageSpec spec(img.width, img.height, n, img.storeUint8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.channelnames = img.channelNames;
  if (anyUint) {
    spec.channelformats.assign(std::size_t(n), OIIO::TypeDesc::FLOAT);
    for (int c = 0; c < n; ++c)
      if (img.channelIsUint[std::size_t(c)]) spec.channelformats[std::size_t(c)] = OIIO::TypeDesc::UINT;
  }
  spec.z_channel = img.zChannel;
  spec.alpha_channel = img.alphaChannel;
  if (!img.compression.empty()) spec.attribute("compression", img.compression);
  return spec;
}

std::int64_t write(const std::string& path, const std::string& tempPath, int fd, const OiioImage& img) {
  const OIIO::ImageSpec spec = specOf(img);
  // Mixed channel formats are passed in their native layout; otherwise floats.
  const OIIO::TypeDesc format = spec.channelformats.empty() ? OIIO::TypeDesc::FLOAT : OIIO::TypeUnknown;
  const void* pixels = img.pixels;
  auto writer = OIIO::ImageOutput::create(path);
  if (!writer) fail(path, "no image format for this extension");
  if (writer->supports("ioproxy")) {
    FdProxy proxy(tempPath, fd);
    if (!writer->set_ioproxy(&proxy) || !writer->open(path, spec) || !writer->write_image(format, pixels) ||
        !writer->close())
      fail(path, writer->geterror());
    if (proxy.error()) fail(path, std::string("write failed: ") + std::strerror(proxy.error()));
    return std::int64_t(proxy.size());
  }
  // A writer that takes only a path (sgi, ico, heif) cannot be told its
  // writes failed: what it wrote must decode again before it is committed.
  if (!writer->open(tempPath, spec) || !writer->write_image(format, pixels) || !writer->close())
    fail(path, writer->geterror());
  writer.reset();
  auto check = OIIO::ImageInput::open(tempPath);
  std::vector<float> back;
  if (check) back.resize(std::size_t(spec.width) * spec.height * std::size_t(spec.nchannels));
  if (!check || check->spec().width != spec.width || check->spec().height != spec.height ||
      !check->read_image(0, 0, 0, std::min(spec.nchannels, check->spec().nchannels), OIIO::TypeDesc::FLOAT,
                         back.data()))
    fail(path, "what was written does not read back (disk full?)");
  return -1;
}

}  // namespace

}  // namespace tg::io

extern "C" const tg::io::OiioModule* tg_oiio_module() {
  static const tg::io::OiioModule m{tg::io::OiioModule::kVersion, tg::io::canWrite, tg::io::write, tg::io::drawPlot};
  return &m;
}
