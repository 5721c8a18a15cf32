// Every texture unit, image unit and storage-buffer binding the renderer's
// passes use: one table that the GLSL (#include "lib/bindings.h", embedded
// like the other shaders) and the C++ (#include "shaders/lib/bindings.h")
// both read, so that a binding cannot be matched by comment only. Only
// #define lines and comments: valid in both languages.
#ifndef TG_BINDINGS_H
#define TG_BINDINGS_H

// Texture units. The lighting pass reads the G-buffer at 0..2; the deferred
// effects (AO, outlines) read depth where lighting reads albedo.
#define TG_UNIT_ALBEDO 0
#define TG_UNIT_NORMAL 1
#define TG_UNIT_ID 2
#define TG_UNIT_EFFECT_DEPTH 0
#define TG_UNIT_MESH_SCENE_DEPTH 2   // mesh.frag's forward (see-through) pass
#define TG_UNIT_OCCLUDER_DEPTH 3     // lib/occlusion.glsl, occluder_pyramid.comp
#define TG_UNIT_OCCLUDER_PYRAMID 4
#define TG_UNIT_AO 6                 // the blurred occlusion, for lighting (TG_AO)
#define TG_UNIT_AO_RAW 6             // the raw occlusion, for the blur
#define TG_UNIT_SHADOW_SCENE_DEPTH 7 // lib/shadow.glsl
#define TG_UNIT_SHADOW_MAP 8
#define TG_UNIT_LEGEND_ATLAS 0
#define TG_UNIT_SLICE 0              // a slice plane's underlay
#define TG_UNIT_RESOLVE_DEPTH 0      // depth_resolve.frag: a path's float window depth
#define TG_UNIT_CPU_DEPTH 0          // cpu_gbuffer.frag: the CPU path's window depth,
#define TG_UNIT_CPU_RECORD 1         // record index + 1 (0: empty),
#define TG_UNIT_CPU_NORMAL 2         // WC normal,
#define TG_UNIT_CPU_HIT_GC 3         // GC hit point (sign colours only);
#define TG_UNIT_CPU_RUNS 4           // cast_runs.vert: the pixel runs those passes write
#define TG_UNIT_AA_SAMPLE 9          // anti-aliasing (render/antialias_pass.h): a sample's lit colour,
#define TG_UNIT_AA_FRAME_ID 10       // the frame's own ids (where edges are),
#define TG_UNIT_AA_SUM 11            // the samples' sum,
#define TG_UNIT_AA_DEPTH 12          // the frame's depth (aa_coverage.frag)

// Image units: the occluder pyramid's reduction.
#define TG_IMAGE_PYRAMID_FINER 0
#define TG_IMAGE_PYRAMID_COARSER 1
// The compute glyph path's resolve (render/compute_glyphs.h): cpu_gbuffer.frag's inputs.
#define TG_IMAGE_CAST_DEPTH 2
#define TG_IMAGE_CAST_RECORD 3
#define TG_IMAGE_CAST_NORMAL 4
#define TG_IMAGE_CAST_HIT_GC 5

// Shader storage buffers.
#define TG_SSBO_GLYPHS 0             // lib/glyph_record.glsl
#define TG_SSBO_ITERATION_STATS 1
#define TG_SSBO_KEPT_INDEX 2         // culling (render/glyph_culling.h)
#define TG_SSBO_RANGES 3
#define TG_SSBO_KEPT_COUNT 4
#define TG_SSBO_COMMANDS 5
#define TG_SSBO_VISIBLE 6
#define TG_SSBO_LEGEND_VERTICES 7    // not 0: the records stay bound for the next frame
#define TG_SSBO_COLOR_SCALARS 8      // lib/glyph_color.glsl: per-glyph scalars, indexed like the records
#define TG_SSBO_MESH_VERTICES 9
#define TG_SSBO_COLOR_TABLE 10       // lib/glyph_color.glsl: a host's colour table (GlyphRenderer::setColorTable)
#define TG_SSBO_TRACT_POINTS 11      // tract.vert: streamlines, separated by w = 0
#define TG_SSBO_AA_ID_RECORDS 12     // aa_coverage.frag: where each input id's record is
// The compute glyph path (lib/compute_vis.glsl): the visibility buffer, the
// tiled glyphs' set-ups, the tiles' counts, starts and lists, and its counters.
#define TG_SSBO_VIS 13
#define TG_SSBO_CANDIDATES 14
#define TG_SSBO_TILE_COUNT 15
#define TG_SSBO_TILE_START 16
#define TG_SSBO_TILE_LIST 17
#define TG_SSBO_COMPUTE_STATE 18
#define TG_SSBO_BATCH_BOUNDS 19  // the chunk's batches of records: centre box, largest |eigenvalue|, FA
#define TG_SSBO_BATCH_LIST 20    // the batches left after the cull (compute_batches.comp)
#define TG_SSBO_ACTIVE_TILES 21  // the tiles with glyphs to cast (compute_scan.comp)

#endif
