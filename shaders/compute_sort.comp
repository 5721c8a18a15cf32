#version 450 core
// The compute glyph path's tile sort (render/compute_glyphs.h): a workgroup
// per run of kSortRun entries of a tile's list (x and z the active tile, y
// the run) puts the run in order of nearest depth, ties in list order, so that
// compute_cast.comp casts it front to back and stops at the first glyph
// behind a pixel's hit: a bitonic sort in shared memory. One run a
// workgroup: runs sorted in a loop within one workgroup came out unsorted on
// llvmpipe 22.3 (dt-helix at --scale 100, 59,280 entries a tile;
// ComputeGlyphs.CrowdedTilesOfManySortedRunsMatchTheRasterPath).
#include "lib/compute_vis.glsl"

layout(local_size_x = 256) in;

shared uint sKey[kSortRun];
shared uint sCandidate[kSortRun];

void main() {
  uint tile = activeTiles[gl_WorkGroupID.z * gl_NumWorkGroups.x + gl_WorkGroupID.x];
  uint b = tileStart[tile], e = min(tileStart[tile + 1u], entryCapacity);
  uint base = b + gl_WorkGroupID.y * kSortRun;
  if (base >= e) return;  // the whole workgroup: this tile has fewer runs
  uint n = min(kSortRun, e - base);
  uint lane = gl_LocalInvocationIndex;
  uint size = 2u;
  while (size < n) size <<= 1u;
  for (uint j = lane; j < size; j += 256u) {
    uint k = j < n ? tileList[base + j] : 0u;
    sCandidate[j] = k;
    sKey[j] = j < n ? orderKey(candidates[k].centreVC_near.w) : 0xFFFFFFFFu;
  }
  barrier();
  // Batcher's bitonic network: log2(size) (log2(size) + 1) / 2 steps, each
  // a compare-exchange of disjoint pairs.
  for (uint run = 2u; run <= size; run <<= 1u)
    for (uint step = run >> 1u; step > 0u; step >>= 1u) {
      for (uint i = lane; i < size; i += 256u) {
        uint o = i ^ step;
        // Equal keys keep their list order (the candidate index breaks ties).
        bool greater = sKey[i] > sKey[o] || (sKey[i] == sKey[o] && sCandidate[i] > sCandidate[o]);
        if (o > i && greater == ((i & run) == 0u)) {
          uint t = sKey[i];
          sKey[i] = sKey[o];
          sKey[o] = t;
          t = sCandidate[i];
          sCandidate[i] = sCandidate[o];
          sCandidate[o] = t;
        }
      }
      barrier();
    }
  for (uint j = lane; j < n; j += 256u) tileList[base + j] = sCandidate[j];
}
