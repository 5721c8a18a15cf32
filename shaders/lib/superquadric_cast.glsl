// One pixel's ray against a superquadric sprite (lib/superquadric_sprite.glsl),
// as superquadric.frag and the CPU glyph path cast it. In the GLSL/C++ subset
// (lib/glsl_cpp.h). Requires lib/camera.glsl, lib/ellipsoid.glsl,
// lib/superquadric.glsl and lib/superquadric_march.glsl.

// The ray restarted at its closest approach to the centre, as for
// ellipsoids, in GC: o + t d for view depth tc + t; the march runs in GC arc
// length (|d| = dl) so that eps is relative to the glyph's size.
struct SuperquadricRay {
  float tc;
  vec3 o, d;
  float dl;
  vec2 search;   // marchSearchSpan
  bool inReach;  // false: this ray cannot hit
};

SuperquadricRay superquadricRay(vec2 fragDC, vec3 centreVC, mat3 gcFromVC, vec3 shape, float eps) {
  vec3 originVC, dirVC;
  rayThroughFragment(fragDC, originVC, dirVC);
  SuperquadricRay r;
  r.tc = dot(centreVC - originVC, dirVC) / dot(dirVC, dirVC);
  r.o = gcFromVC * (originVC + r.tc * dirVC - centreVC);
  r.d = gcFromVC * dirVC;
  r.dl = length(r.d);
  // The shape lies within the sphere of radius superquadricReach in GC: a
  // ray that passes it by (with room for the march's tolerance) cannot hit,
  // and most of a thin glyph's rectangle is such rays.
  // q rounds with |o|, which reaches 1e7 for thin glyphs seen at a slant:
  // the same rounding margin as marchSearchSpan's, so a ray the march would hit
  // is never dropped here.
  vec3 q = r.o - dot(r.o, r.d) / (r.dl * r.dl) * r.d;
  float on = max(max(abs(r.o.x), abs(r.o.y)), abs(r.o.z));
  float reach = superquadricReach(shape) * (1.0f + 1e-3f) + 4.0f * eps + exp2(-19.0f) * (on + 2.0f);
  r.search = marchSearchSpan(shape, r.o, r.d / r.dl, eps, on);
  r.inReach = !(dot(q, q) > reach * reach) && r.search.x <= r.search.y;
  return r;
}

// The box's entry: the nearest view depth this glyph can be at on the ray.
float superquadricEntryVC(SuperquadricRay r) { return r.tc + unitCubeSpan(r.o, r.d / r.dl).x / r.dl; }

MarchResult marchSuperquadricRay(SuperquadricRay r, vec3 shape, int maxIter, float eps) {
  return superquadricMarch(shape, r.o, r.d / r.dl, (uNearVC - r.tc) * r.dl, r.search, maxIter, eps);
}

// The hit's view depth; false where the march missed or the hit lies
// outside the depth range.
bool superquadricHitDepth(SuperquadricRay r, MarchResult m, TG_OUT(float) depthVC) {
  if (!m.hit) return false;
  depthVC = r.tc + m.s / r.dl;
  return !(!(depthVC >= uNearVC) || (uOrtho == 1 && depthVC > uFarVC));
}

// The hit point in GC (the sign colour's) and the unit WC normal.
vec3 superquadricHitGC(SuperquadricRay r, MarchResult m) { return r.o + m.s * r.d / r.dl; }

vec3 superquadricNormalWC(mat3 gcFromVC, vec3 gradGC) {
  vec3 nVC = transpose(gcFromVC) * gradGC;  // inverse transpose of GC -> VC
  return normalize(transpose(mat3(uViewWCVC)) * nVC);
}
