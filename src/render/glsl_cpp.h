#pragma once
// shaders/lib's shared maths compiled as C++ over GLM: the same files the
// glyph shaders include (lib/glsl_cpp.h says which subset they keep), inside
// a struct whose members are their uniforms. The CPU glyph path
// (render/cpu_glyphs.h) sets the members as the raster path sets the
// uniforms (setCameraUniforms, setGlyphUniforms) and calls the functions, so
// that both paths run one copy of the intersection, bounds and normal code.
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/vector_relational.hpp>

#include "view/camera.h"
#include "render/frame_params.h"
#include "shaders/lib/glsl_cpp.h"

namespace tg::render::glsl {

using glm::abs;
using glm::any;
using glm::atan;
using glm::bvec4;
using glm::ceil;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::equal;
using glm::exp2;
using glm::floor;
using glm::greaterThan;
using glm::isinf;
using glm::isnan;
using glm::ivec2;
using glm::ivec3;
using glm::length;
using glm::exp;
using glm::lessThanEqual;
using glm::log;
using glm::log2;
using glm::mat3;
using glm::mat4;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::sign;
using glm::sqrt;
using glm::transpose;
using glm::uint;
using glm::vec2;
using glm::vec3;
using glm::vec4;

#define uniform
struct Shaders {
#include "shaders/lib/camera.glsl"
#include "shaders/lib/glyph_record_type.glsl"
#include "shaders/lib/ellipsoid.glsl"
#include "shaders/lib/glyph_size.glsl"
#include "shaders/lib/selection.glsl"
#include "shaders/lib/pixel_centres.glsl"
#include "shaders/lib/ellipsoid_sprite.glsl"
#include "shaders/lib/superquadric.glsl"
#include "shaders/lib/blob.glsl"
#include "shaders/lib/prism.glsl"

  // The uniforms of camera.glsl, as render/camera_uniforms.cpp sets them.
  void setCamera(const Camera& cam);
  // Those of glyph_size.glsl and selection.glsl, as setGlyphUniforms.
  void setGlyph(const FrameParams& p);
};

// The Newton march's variants (lib/superquadric_march.glsl's options), each
// with the set-up and the cast that depend on them, as the raster path
// builds one program per variant. A variant leaves some parameters unread.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
struct MarchGeneral : Shaders {
#include "render/glsl_cpp_march.inc"
};
#define TG_MARCH_CONVEX 1
struct MarchConvex : Shaders {
#include "render/glsl_cpp_march.inc"
};
#undef TG_MARCH_CONVEX
#define TG_MARCH_MIXED 1
struct MarchMixed : Shaders {
#include "render/glsl_cpp_march.inc"
};
#undef TG_MARCH_MIXED
#pragma GCC diagnostic pop
#undef uniform

using GlyphRecord = Shaders::GlyphRecord;
using EllipsoidSprite = Shaders::EllipsoidSprite;
using PrismSprite = Shaders::PrismSprite;
using BlobBump = Shaders::BlobBump;
using SuperquadricSprite = MarchGeneral::SuperquadricSprite;
using SuperquadricRay = MarchGeneral::SuperquadricRay;
using MarchResult = MarchGeneral::MarchResult;

}  // namespace tg::render::glsl
