#pragma once
// Frame output, chosen by extension:
//   .png            8-bit RGBA through libpng (io/core/png_writer.h)
//   .exr            float R G B A Z N.X N.Y N.Z and uint32 id, through OpenImageIO
//   any other OIIO  RGBA in the format's default depth, through OpenImageIO
// OpenImageIO is loaded only for the formats that need it (io/core/oiio_module.h).
#include <string>
#include <vector>

#include "view/frame_image.h"

namespace tg::io {

// The 8-bit RGBA every 8-bit format stores (rows top first): each channel
// clamped to 0..1 and rounded (render::toUnorm8), or the frame's own rgba8
// when it was read back as 8 bits. The Python module returns the same bytes.
std::vector<unsigned char> toRgba8(const render::FrameImage& img);

// Throws std::runtime_error "writeImage: path: problem" (disk full included);
// never leaves a partial or temporary file.
void writeImage(const render::FrameImage& img, const std::string& path);

// Whether writeImage can write `path`: PNG always; other extensions when
// OpenImageIO has a writer for them (loading its module). Throws when the
// module is needed and cannot be loaded.
bool canWriteImage(const std::string& path);

// Whether writeImage(…, path) writes depth, normal and id (EXR) and so needs
// them read back.
bool writesGeometryChannels(const std::string& path);

}  // namespace tg::io
