// The whole dataset's magnitude sample and sample spacing, the same on every
// rank of a distributed run, and the same for any number of ranks: what
// sizes the glyphs in the spacing and max modes.
#pragma once
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

class vtkMultiProcessController;

namespace tg::paraview {

// `local`'s glyphs on this rank, and `gridSpacing`: the smallest spacing of
// its image pieces, 0 when a piece with points is not an image, infinity when
// it has none. Every rank's glyphs are gathered (a collective call over
// `controller`; null or one rank: this process alone), put in one order (by
// position, then eigenvalues) and counted once per position, since ranks
// share the points on their boundaries; the spacing is the grid's, else
// io::estimateSampleSpacing over those positions, and the sample
// tensor::sampleMagnitudes' over them. Memory: every rank holds every glyph
// record once, for the time of the call.
tensor::MagnitudeSample globalMagnitudeSample(const tensor::GlyphSet& local, double gridSpacing,
                                              vtkMultiProcessController* controller);

}  // namespace tg::paraview
