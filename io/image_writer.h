#pragma once
// Frame output through OpenImageIO, chosen by extension:
//   .png            8-bit RGBA
//   .exr            float R G B A Z N.X N.Y N.Z and uint32 id
//   any other OIIO  RGBA in the format's default depth
#include <string>

#include "render/frame_image.h"

namespace tg::io {

// Throws std::runtime_error "writeImage: path: problem"; never leaves a
// partial file at `path`.
void writeImage(const render::FrameImage& img, const std::string& path);

// Whether writeImage(…, path) writes depth, normal and id (EXR) and so needs
// them read back.
bool writesGeometryChannels(const std::string& path);

}  // namespace tg::io
