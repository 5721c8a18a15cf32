#version 450 core
// Coverage from the font atlas (its white texel for lines and fills).
#include "lib/bindings.h"
layout(binding = TG_UNIT_LEGEND_ATLAS) uniform sampler2D uAtlas;

in vec2 vUV;
in vec4 vColor;
out vec4 oColor;

void main() {
  oColor = vec4(vColor.rgb, vColor.a * texture(uAtlas, vUV).r);
}
