#pragma once
// 8-bit PNG through libpng's simplified API. PNG is the common output, so it
// stays off OpenImageIO: loading that library (it pulls in OpenCV, FFmpeg,
// GDAL and OpenVDB) took 0.6-0.8 s and 120 MB here, most of a small render.
#include <string>

namespace tg::io {

// `pixels`: `height` rows of `width` pixels of `channels` (3: RGB, 4: RGBA)
// bytes, top row first. Written through a temporary file renamed into place;
// throws std::runtime_error "writePng: path: problem".
void writePng(const std::string& path, int width, int height, int channels, const unsigned char* pixels);

}  // namespace tg::io
