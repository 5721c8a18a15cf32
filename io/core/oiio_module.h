#pragma once
// What the program asks of OpenImageIO, behind a module loaded on first use
// (tensorglyph-oiio.so beside the binary). Every command that does not write
// an EXR, another non-PNG format or a benchmark plot then runs without
// loading OpenImageIO at all (io/core/png_writer.h says what that saves).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/core/plot_panels.h"

namespace tg::io {

// An image laid out per pixel, channel after channel, as OIIO's ImageSpec.
struct OiioImage {
  int width = 0, height = 0;
  std::vector<std::string> channelNames;  // one per channel
  std::vector<bool> channelIsUint;        // uint32 channel (else float32)
  int zChannel = -1, alphaChannel = -1;
  std::string compression;  // e.g. "zip"; empty: the format's default
  bool storeUint8 = false;  // every channel float in memory, 8-bit in the file
  const void* pixels = nullptr;
};

// The module's entry points; a version mismatch is refused at load.
struct OiioModule {
  static constexpr int kVersion = 2;  // 2: PlotSeries' point labels, spreads and mark
  int version;
  // Whether OIIO has a writer for `path`'s extension.
  bool (*canWrite)(const std::string& path);
  // Encodes `img` for `path` (its extension chooses the format) into the
  // open file `fd`, or, for writers that take only a path, into `tempPath`,
  // and checks what was written. Returns the file's size (-1 where the
  // writer took a path: its size is not known), or throws
  // std::runtime_error "writeImage: path: problem".
  std::int64_t (*write)(const std::string& path, const std::string& tempPath, int fd, const OiioImage& img);
  // Draws benchmark plot panels into `rgb` (w * panels x h, 3 floats per
  // pixel, top row first); false when no font was found.
  bool (*drawPlot)(const std::vector<PlotPanel>& panels, int w, int h, std::vector<float>& rgb);
};

// Loads the module once and returns it, or throws std::runtime_error
// "<who>: <what> needs tensorglyph-oiio.so ...: <why>".
const OiioModule& oiioModule(const std::string& who, const std::string& what);

}  // namespace tg::io

extern "C" const tg::io::OiioModule* tg_oiio_module();
