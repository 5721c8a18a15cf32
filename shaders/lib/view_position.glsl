// Visible surface points from the G-buffer's reversed window depth, and view
// points back to pixels. Needs lib/camera.glsl.

// The point (VC) that window depth z shows at window position fragDC.
vec3 positionVC(vec2 fragDC, float z) {
  vec3 originVC, dirVC;
  rayThroughFragment(fragDC, originVC, dirVC);
  return originVC + dirVC * viewDepthFromWindowDepth(z);
}

// The window position (pixels) of a view-space point in front of the eye.
vec2 windowFromVC(vec3 pVC) {
  vec4 clip = uProjVCCC * vec4(pVC, 1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * uViewportDC;
}
