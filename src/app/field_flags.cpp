#include "app/field_flags.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "app/cli_common.h"
#include "app/frame_check.h"
#include "app/scale/option_ranges.h"
#include "io/core/format_table.h"
#include "io/core/nifti_layouts.h"
#include "tensor/axis_map.h"

namespace tg::app {
namespace {

constexpr const char* kSizesFromNames = "field or selection";
constexpr const char* kScaleModeNames = "absolute, max or spacing";

// From the one table of layouts: each name, its order and where it applies.
std::string layoutHelp() {
  std::string h = "order of six components (NIfTI; 6-component VTK arrays): ";
  const auto& all = io::niftiLayouts();
  for (std::size_t k = 0; k < all.size(); ++k) {
    const io::NiftiLayout& l = all[k];
    const bool alias = k > 0 && all[k - 1].sym == l.sym && all[k - 1].inputs == l.inputs;
    h += std::string(k ? ", " : "") + l.name + " (" + (alias ? std::string("as ") + all[k - 1].name : l.order) +
         (l.inputs & io::kNiftiInput ? "" : "; not NIfTI") + (l.inputs & io::kVtkInput ? "" : "; not VTK") + ")";
  }
  return h + "; default: the NIfTI header's, VTK's own";
}

}  // namespace

void FieldFlags::addTo(OptionTable& ap, bool scaling) {
  using Args = OptionArgs;
  io::Selection& sel = read.selection;
  const std::string group = ap.groupDefault();
  ap.setGroup("input and selection");
  ap.arg("--array NAME").help("VTK: the point array holding the tensors (9, 6, 4 or 3 components)")
      .action([&](Args a) { read.arrayName = a[1]; });
  ap.arg("--layout L").help(layoutHelp()).oneOf(io::layoutChoices(io::kNiftiInput | io::kVtkInput | io::kArrayInput))
      .action([&](Args a) { read.layout = a[1]; });
  ap.arg("--frame F").help("NIfTI tensor axes: voxel, fsl (voxel, i reversed when det > 0) or world; default: the "
                           "layout's (fsl: fsl, mrtrix: world, else voxel)")
      .oneOf(io::kTensorFrameChoices).action([&](Args a) { read.frame = a[1]; });
  ap.arg("--tensor-axes A,B,C").help("read the stored tensors' axes as these: a signed permutation of x, y, z (the "
                                     "components' axes), e.g. -x,y,z mirrors x (a b-table fitted with x flipped), "
                                     "y,x,z swaps x and y; the frame check suggests one when fibres cohere better")
      .action([&](Args a) { read.tensorAxes = a[1]; });
  ap.arg("--mask FILE").help("scalar volume on the same grid (" + io::extensionList(io::kScalarUse) + ")").action([&](Args a) {
    sel.maskPath = a[1];
  });
  ap.arg("--mask-min V").help("keep voxels whose mask value is >= V (needs --mask)").range(ranges::kAnyFloat)
      .byDefault(formatNumber(sel.maskMin))
      .action([&](Args a) {
        sel.maskMin = parseDouble("--mask-min", a[1]);
        maskMinGiven = true;
      });
  ap.arg("--confidence-min C").help("masked NRRD tensors: keep confidence >= C").range(ranges::kAnyFloat)
      .byDefault(formatNumber(sel.confidenceMin))
      .action([&](Args a) {
        sel.confidenceMin = parseDouble("--confidence-min", a[1]);
        read.confidenceGiven = true;
      });
  ap.arg("--slice SPEC").help("a slice, or with :THICKNESS a slab centred on it: i|j|k:INDEX along a voxel axis (x, y, z "
                               "are i, j, k, as ever), axial|coronal|sagittal:INDEX along the voxel axis nearest S, A "
                               "or R, or x|y|z=POS[mm] at a world position (axial=POS is z=POS); e.g. k:40, "
                               "axial:40:5, z=12.5mm")
      .action([&](Args a) {
        try {
          sel.slice = io::parseSlice(a[1]);
        } catch (const std::invalid_argument& e) {
          throw UsageError(std::string("--slice: ") + e.what());
        }
      });
  ap.arg("--stride N").help("every N-th voxel along each axis but a --slice's own (every N-th point of a point set); "
                            "glyphs are sized to the thinned spacing")
      .range(ranges::kStride).action([&](Args a) { sel.stride = parseInt("--stride", a[1]); });
  ap.arg("--roi X0 Y0 Z0 X1 Y1 Z1").help("keep samples inside this box (WC)").range(ranges::kAnyFloat).action([&](Args a) {
    std::array<double, 6> b;
    for (int k = 0; k < 6; ++k) b[k] = parseDouble("--roi", a[1 + k]);
    sel.roiWC = b;
  });
  ap.arg("--cl-min V").help("hide glyphs with Westin's linear measure cl below V").range(ranges::kUnit).action([&](Args a) {
    glyph.clMin = parseDouble("--cl-min", a[1]);
  });
  ap.arg("--cp-min V").help("hide glyphs with Westin's planar measure cp below V").range(ranges::kUnit).action([&](Args a) {
    glyph.cpMin = parseDouble("--cp-min", a[1]);
  });
  // Single precision: the glyph records hold float eigenvalues, and their
  // sum (the trace) must stay below 3.4e38 too.
  ap.setGroup("glyphs");
  ap.arg("--min-eigenvalue E").help("raise eigenvalues below E to E (shape only; FA is from the data)")
      .range({-1e37, 1e37}).action([&](Args a) { glyph.minEigenvalue = parseDouble("--min-eigenvalue", a[1]); });
  if (!scaling) {
    ap.setGroup(group);
    return;
  }
  // Reloads: the whole field is read again for it.
  ap.arg("--sizes-from W").help("field (default): sizes, the magnitude mapping, the clamp and the colour windows "
                                "from the whole field, so a tensor is drawn at one size and in one colour on every "
                                "slice, ROI or stride; selection: all from the selected tensors only")
      .oneOf(kSizesFromNames).action([&](Args a) {
        const std::string w = a[1];
        if (w != "field" && w != "selection")
          throw UsageError("--sizes-from: unknown source \"" + w + "\"; choose " + kSizesFromNames);
        sizesFromSelection = w == "selection";
      });
  // Sizing is a frame parameter: the glyph records hold eigenvalues, not sizes.
  const bool reloads = ap.reloadsDefault();
  ap.setReloadsDefault(false);
  ap.arg("--scale S").help("a factor on the automatic size (--scale 2: glyphs twice as big); with --scale-mode "
                           "absolute, the glyph diameter in world units per eigenvalue unit, as ParaView's "
                           "TensorGlyph ScaleFactor (Teem's tend glyph -gsc is S/2)")
      .range(ranges::kPositiveFloat).action([&](Args a) { scale = parseDouble("--scale", a[1]); });
  ap.arg("--scale-mode M").help("spacing (the default), max or absolute: spacing: the glyph at the " +
                                std::to_string(std::lround(100 * tensor::ScaleParams{}.percentile)) +
                                "th percentile of the whole field's non-zero tensors is S sample spacings across; "
                                "max: the largest is; absolute: S is the diameter per eigenvalue unit")
      .oneOf(kScaleModeNames).action([&](Args a) {
        const std::string m = a[1];
        if (m == "absolute") scaleMode = tensor::ScaleMode::Absolute;
        else if (m == "max") scaleMode = tensor::ScaleMode::Max;
        else if (m == "spacing") scaleMode = tensor::ScaleMode::Spacing;
        else throw UsageError("--scale-mode: unknown mode \"" + m + "\"; choose " + kScaleModeNames);
      });
  ap.arg("--magnitude M").help("how a glyph's largest |eigenvalue| m sets its size, shape ratios and signs kept: "
                               "linear (default), log (lambda0 ln(1 + m/lambda0)) or shape (every glyph the same size)")
      .oneOf(tensor::kMagnitudeNames).action([&](Args a) {
        const auto m = tensor::magnitudeNamed(a[1]);
        if (!m) throw UsageError(std::string("--magnitude: unknown mapping \"") + a[1] + "\"; choose " +
                                 tensor::kMagnitudeNames);
        sizing.magnitude = *m;
        magnitudeGiven = true;
      });
  ap.arg("--lambda0 L").help("--magnitude log: the knee; shape: the size every glyph gets (default: the median "
                             "|eigenvalue|)")
      .range(ranges::kPositiveFloat).action([&](Args a) { sizing.lambda0 = parseDouble("--lambda0", a[1]); });
  ap.arg("--clamp N").help("no glyph wider than N sample spacings, its shape kept (vtkTensorGlyph's ClampScaling); "
                           "0: off (default 2 with --scale-mode spacing or max, off with absolute)")
      .range(ranges::kClampSpacings).action([&](Args a) { sizing.clampSpacings = parseDouble("--clamp", a[1]); });
  ap.setReloadsDefault(reloads);
  ap.setGroup(group);
}

void FieldFlags::validate() const {
  const io::Selection& sel = read.selection;
  if (maskMinGiven && sel.maskPath.empty()) throw UsageError("--mask-min needs --mask");
  if (!read.layout.empty() && !io::isLayoutName(read.layout))
    throw UsageError("--layout: unknown layout \"" + read.layout + "\"; choose " +
                     io::layoutChoices(io::kNiftiInput | io::kVtkInput | io::kArrayInput));
  if (!read.frame.empty() && !io::tensorFrameNamed(read.frame))
    throw UsageError("--frame: unknown frame \"" + read.frame + "\"; choose " + io::kTensorFrameChoices);
  if (!read.tensorAxes.empty() && !tensor::axisMapNamed(read.tensorAxes))
    throw UsageError("--tensor-axes: \"" + read.tensorAxes + "\" is not a signed permutation of x, y, z; e.g. -x,y,z "
                     "or y,x,z");
  if (sizing.lambda0 && sizing.magnitude == tensor::Magnitude::Linear)
    throw UsageError("--lambda0 applies to --magnitude log or shape only");
}

double FieldFlags::scaleFor(const tensor::GlyphSet& set, double spacing) const {
  return tensor::resolveScale(scaleParams(), tensor::sampleMagnitudes(set, spacing)).scale;
}

tensor::ScaleParams FieldFlags::scaleParams() const {
  tensor::ScaleParams p = sizing;
  p.mode = scaleMode.value_or(tensor::ScaleMode::Spacing);
  p.factor = scale.value_or(1.0);
  return p;
}

void checkOptionsApply(const std::string& input, const io::ReadOptions& opt) {
  const io::InputFormat format = input.empty() ? io::InputFormat::Unknown : io::inputFormatOf(input);
  if (format == io::InputFormat::Unknown && !input.empty()) return;  // the reader names the extension
  const std::string flag = io::inapplicableOption(format, opt);
  if (flag.empty()) return;
  throw UsageError(flag + " does not apply to " +
                   (input.empty() ? std::string("the built-in scene") : input + ", a " + io::inputFormatName(format) +
                                                                            " file"));
}

void checkLoaded(const io::TensorField& f, const io::ReadOptions& opt) {
  if (opt.confidenceGiven && !f.hasConfidence)
    throw UsageError("--confidence-min does not apply to " + f.path + ": its tensors have no confidence value (" +
                     f.layout + ")");
  // The options that left nothing, named: the data alone is not to blame.
  const io::Selection& sel = opt.selection;
  const std::string maskBy = " (--mask, --mask-min " + formatNumber(sel.maskMin) + ")";
  std::string selectedBy = std::string(sel.slice ? " --slice" : "") + (sel.stride > 1 ? " --stride" : "") +
                           (sel.roiWC ? " --roi" : "");
  if (!selectedBy.empty()) selectedBy = " (" + selectedBy.substr(1) + ")";
  if (f.size() == 0)
    throw io::InputError("checkLoaded: " + f.path + ": no tensor to draw: of " + std::to_string(f.totalPoints) + ", " +
                         std::to_string(f.skippedNonFinite) + " skipped (NaN/Inf), " + std::to_string(f.skippedOverflow) +
                         " skipped (overflow), " + std::to_string(f.masked) + " masked" + (f.masked ? maskBy : "") + ", " +
                         std::to_string(f.unselected) + " outside the selection" + (f.unselected ? selectedBy : ""));
}

void checkDrawable(const tensor::GlyphSet& g, const std::string& path) {
  // --cl-min and --cp-min apply after the eigensystems, so checkLoaded cannot
  // see that they leave nothing; an empty set then failed as "the glyphs
  // extend beyond the floating-point range".
  if (g.glyphs.empty() && g.droppedByShape > 0)
    throw io::InputError("checkDrawable: " + path + ": no tensor to draw: all " + std::to_string(g.droppedByShape) +
                         " are below --cl-min or --cp-min");
  // Zero eigenvalues everywhere (or values below single precision's range)
  // give glyphs of size zero: an empty image, and a scale with no meaning.
  if (!g.glyphs.empty() && !(g.maxAbsEigenvalue > 0.0))
    throw io::InputError("checkDrawable: " + path + ": every tensor is zero (" + std::to_string(g.glyphs.size()) +
                         " of them, after single-precision rounding): no glyph has a size to draw");
}

FrameCheck reportLoad(const io::TensorField& f, const char* command, const io::ReadOptions& read) {
  const std::string path = printable(f.path);
  for (const std::string& w : f.warnings)
    std::fprintf(stderr, "tensorglyph %s: %s: %s\n", command, path.c_str(), printable(w).c_str());
  if (f.skippedNonFinite)
    std::fprintf(stderr, "tensorglyph %s: %s: skipped %zu tensors with NaN/Inf components\n", command, path.c_str(),
                 f.skippedNonFinite);
  if (f.skippedOverflow)
    std::fprintf(stderr,
                 "tensorglyph %s: %s: skipped %zu tensors whose values overflow single precision (beyond 3.4e38)\n",
                 command, path.c_str(), f.skippedOverflow);
  FrameCheck check = checkFrame(f, read);
  if (const std::string w = frameWarning(check); !w.empty())
    std::fprintf(stderr, "tensorglyph %s: %s: %s\n", command, path.c_str(), w.c_str());
  return check;
}

}  // namespace tg::app
