#pragma once
// Readback of a rendered frame (readFrame), and the lit colour as 8-bit RGBA on the CPU, for PNG and the other 8-bit
// outputs. Inputs: the G-buffer's lit colour (RGBA32F). Output: 4 bytes per
// pixel, rows top first, each channel render::toUnorm8 of the float.
//
// Read in bands of rows and converted band by band, so the float image (16
// bytes a pixel, 4 MiB at 512 x 512) never exists on the CPU: only the 4
// bytes a pixel that are written out, and one band.
#include <cstdint>
#include <vector>

#include "gl/loader.h"
#include "view/camera.h"
#include "view/frame_image.h"
#include "render/gbuffer.h"

namespace tg::render {

// What readback fetches: the float colour, every channel (EXR), or only the
// colour as 8-bit RGBA (PNG and the like), which never holds the float image
// on the CPU.
enum class Channels { Color, All, Rgba8 };

// target's channels, rows top first; depth along the view axis (+inf and a
// zero normal where nothing was drawn).
FrameImage readFrame(const gl::Api& gl, const Camera& cam, const GBuffer& target, Channels channels);

std::vector<std::uint8_t> readColorRgba8(const gl::Api& gl, const GBuffer& target);

// Rows per band for a `width`-pixel image: as many as 256 KiB of floats
// hold, at least one.
int colorBandRows(int width);

}  // namespace tg::render
