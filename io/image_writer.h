#pragma once
// Frame output through OpenImageIO, chosen by extension:
//   .png            8-bit RGBA
//   .exr            float R G B A Z N.X N.Y N.Z and uint32 id
//   any other OIIO  RGBA in the format's default depth
#include <OpenImageIO/imageio.h>

#include <string>

#include "render/frame_image.h"

namespace tg::io {

// Throws std::runtime_error "writeImage: path: problem" (disk full included);
// never leaves a partial or temporary file.
void writeImage(const render::FrameImage& img, const std::string& path);

// Any image through OpenImageIO with the same guarantees: `pixels` in
// `format` laid out as `spec`, written as `spec` says, by path's extension.
// Every write is checked (through an I/O proxy where the format has one, else
// by decoding the file again) before it is renamed into place.
void writeOiioImage(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc format, const void* pixels);

// Whether writeImage(…, path) writes depth, normal and id (EXR) and so needs
// them read back.
bool writesGeometryChannels(const std::string& path);

}  // namespace tg::io
