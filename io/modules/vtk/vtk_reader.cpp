#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <vtkCallbackCommand.h>
#include <vtkCharArray.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLReader.h>

#include "io/core/format_impl.h"
#include "io/core/nifti_layouts.h"
#include "io/core/read_guard.h"
#include "io/core/readers.h"
#include "io/core/selection.h"
#include "io/core/volume_sink.h"
#include "io/core/tsv_trailer.h"
#include "io/modules/vtk/vtk_capture.h"
#include "io/modules/vtk/vtk_dataset.h"
#include "io/modules/vtk/vtk_legacy_scan.h"
#include "io/modules/vtk/vtk_nonfinite.h"
#include "io/modules/vtk/vtk_xml_checks.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readVtk: " + path + ": " + what);
}

// Collects the first error an algorithm raises instead of letting VTK print
// it; attached for as long as the sink lives.
class ErrorSink {
 public:
  explicit ErrorSink(vtkAlgorithm* algorithm) {
    cb_->SetCallback(&ErrorSink::onEvent);
    cb_->SetClientData(this);
    algorithm->AddObserver(vtkCommand::ErrorEvent, cb_);
  }
  ErrorSink(const ErrorSink&) = delete;
  ErrorSink& operator=(const ErrorSink&) = delete;
  const std::string& first() const { return first_; }

 private:
  static void onEvent(vtkObject*, unsigned long, void* self, void* callData) {
    auto* sink = static_cast<ErrorSink*>(self);
    if (sink->first_.empty() && callData) {
      std::string msg(static_cast<const char*>(callData));
      msg.erase(std::remove(msg.begin(), msg.end(), '\n'), msg.end());
      sink->first_ = msg;
    }
  }
  std::string first_;
  vtkNew<vtkCallbackCommand> cb_;
};

// VTK makes a rectilinear grid's points from its coordinate arrays by index,
// unchecked: X_COORDINATES shorter than DIMENSIONS gave points read past the
// array's end, and they were drawn. A structured grid's cells index its
// points by DIMENSIONS in the same way.
void checkGridPoints(vtkDataSet* ds, const std::string& path) {
  int d[3] = {0, 0, 0};
  if (auto* rg = vtkRectilinearGrid::SafeDownCast(ds)) {
    rg->GetDimensions(d);
    vtkDataArray* coords[3] = {rg->GetXCoordinates(), rg->GetYCoordinates(), rg->GetZCoordinates()};
    for (int k = 0; k < 3; ++k) {
      const vtkIdType n = coords[k] ? coords[k]->GetNumberOfValues() : 0;
      if (n != d[k])
        fail(path, std::string(1, "XYZ"[k]) + "_COORDINATES hold " + std::to_string(n) + " values, DIMENSIONS say " +
                       std::to_string(d[k]));
    }
  } else if (auto* sg = vtkStructuredGrid::SafeDownCast(ds)) {
    sg->GetDimensions(d);
    const long long want = (long long)d[0] * d[1] * d[2];
    if (sg->GetNumberOfPoints() != want)
      fail(path, "DIMENSIONS give " + std::to_string(want) + " points, the file has " +
                     std::to_string(sg->GetNumberOfPoints()));
  }
}

// Runs a reader whose counts are checked. Errors fail the read; the first
// warning comes back in vtkSaid, for the caller to refuse unless it can
// account for it. `legacyPoints`: what checkLegacyCounts found (0 for XML,
// whose header VTK reads first). `dims`: the grid a mask must have.
ReadResult runReader(vtkAlgorithm* reader, const std::string& path, std::uint64_t fileSize,
                     std::uint64_t legacyPoints, const ReadOptions& opt, const int* dims, std::uint64_t textCopies = 0) {
  const ErrorSink sink(reader);
  const VtkMessageCapture said;
  auto check = [&](const char* stage) {
    if (!sink.first().empty()) fail(path, cleanVtkMessage(sink.first()));
    if (reader->GetErrorCode()) fail(path, said.first().empty() ? stage : said.first());
  };
  const bool xml = legacyPoints == 0;
  std::uint64_t points = legacyPoints;
  std::vector<PieceGap> gaps;
  // What VTK holds while it parses: the file's values decoded (an ASCII value
  // is at least 2 bytes and becomes at most 8), or for compressed XML all
  // points with a generous 256 bytes of arrays and cells each.
  // `textCopies`: copies of the file's text VTK holds when it reads from memory.
  std::uint64_t libraryBytes = (4 + textCopies) * fileSize;
  if (xml) {
    reader->UpdateInformation();
    check("unreadable XML header");
    points = xmlPoints(reader, path);
    // zlib cannot compress beyond ~1032:1, so more points than that per byte is corrupt.
    if (points > fileSize * 1032) fail(path, "header claims " + std::to_string(points) + " points, more than the file can hold");
    if (xmlCompressed(reader)) libraryBytes = std::max(libraryBytes, 256 * points);
    checkXmlStructure(reader, path);
    gaps = matchPieceArrays(reader, path);
    check("unreadable XML header");
    if (dims) {
      int e[6];
      vtkInformation* info = reader->GetOutputInformation(0);
      if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT())) fail(path, "a mask or underlay must be image data");
      info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
      const int got[3] = {e[1] - e[0] + 1, e[3] - e[2] + 1, e[5] - e[4] + 1};
      if (const std::string m = maskGridMismatch(got, dims); !m.empty()) fail(path, m);
    }
  }
  promiseData("readVtk", path, opt, libraryBytes, dims ? 0 : points, libraryBytes);
  reader->Update();
  check("VTK reader failed");
  auto* out = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!out) fail(path, said.first().empty() ? "no dataset in file" : said.first());
  checkGridPoints(out, path);
  return {out, said.first(), {}, std::move(gaps)};
}

// Index to world of image data: origin + Direction diag(spacing) ijk.
GridPlacement imagePlacement(vtkImageData* img) {
  GridPlacement p;
  double spacing[3];
  img->GetSpacing(spacing);
  img->GetOrigin(p.originWC);
  const double* dir = img->GetDirectionMatrix()->GetData();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) p.axesWC[3 * r + c] = dir[3 * r + c] * spacing[c];
  return p;
}

bool isLegacy(const std::string& path) {
  return path.size() > 4 && (path.ends_with(".vtk") || path.ends_with(".VTK"));
}

std::string nameOf(vtkDataArray* a) { return a->GetName() ? a->GetName() : "?"; }

// Without --array (io::tensorLikeArray): 9 and 6 components, and
// OpenGeoSys's 4-component stress and strain on 2-D meshes.
bool tensorLike(int nc, const std::string& name) { return tensorLikeArray(nc, name); }
bool tensorLike(vtkDataArray* a) { return tensorLike(a->GetNumberOfComponents(), nameOf(a)); }

// An XML point array a piece lacks could be the one read as the tensors
// (the one --array names, the active tensors, or without --array any
// tensor-like one): such a file is refused rather than read without it.
void checkPieceGaps(const ReadResult& read, const std::string& path, const ReadOptions& opt) {
  for (const PieceGap& g : read.pieceGaps)
    if (opt.arrayName.empty() ? g.activeTensors || tensorLike(g.components, g.name) : g.name == opt.arrayName)
      fail(path, g.problem);
}

bool hasTensorArray(vtkDataSet* ds) {
  vtkPointData* pd = ds->GetPointData();
  if (pd->GetTensors()) return true;
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k)
    if (vtkDataArray* a = pd->GetArray(k); a && tensorLike(a)) return true;
  return false;
}

std::string describeArrays(vtkPointData* pd, bool onlyTensorLike) {
  std::string list;
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k)
    if (vtkDataArray* a = pd->GetArray(k); a && (!onlyTensorLike || tensorLike(a)))
      list += std::string(list.empty() ? "" : ", ") + nameOf(a) + " (" + std::to_string(a->GetNumberOfComponents()) +
              " components)";
  return list;
}

vtkDataArray* pickTensorArray(vtkDataSet* ds, const std::string& path, const ReadOptions& opt) {
  vtkPointData* pd = ds->GetPointData();
  vtkDataArray* arr = nullptr;
  if (!opt.arrayName.empty()) {
    arr = pd->GetArray(opt.arrayName.c_str());
    if (!arr) {
      const std::string seen = describeArrays(pd, false);
      fail(path, "no point array named \"" + opt.arrayName + "\"" + (seen.empty() ? "" : "; found " + seen));
    }
  } else if (!(arr = pd->GetTensors())) {
    // No active tensors: the one tensor-like array, never the first of several.
    int count = 0;
    for (int k = 0; k < pd->GetNumberOfArrays(); ++k)
      if (vtkDataArray* a = pd->GetArray(k); a && tensorLike(a) && ++count == 1) arr = a;
    if (count > 1)
      fail(path, std::to_string(count) + " point arrays could hold the tensors: " + describeArrays(pd, true) +
                     "; choose one with --array");
    if (!arr) {
      const std::string seen = describeArrays(pd, false);
      fail(path, seen.empty() ? "no point tensors"
                              : "no point array with 9 or 6 components (or a 4-component OpenGeoSys sigma or "
                                "epsilon); found " + seen + "; --array NAME reads 4 or 3 components as 2-D tensors");
    }
  }
  const int nc = arr->GetNumberOfComponents();
  if (nc != 9 && nc != 6 && nc != 4 && nc != 3)
    fail(path, "point array \"" + nameOf(arr) + "\" has " + std::to_string(nc) +
                   " components; expected 9, 6 (XX YY ZZ XY YZ XZ), 4 (XX YY ZZ XY) or 3 (XX YY XY)");
  if (arr->GetNumberOfTuples() != ds->GetNumberOfPoints())
    fail(path, "tensor array has " + std::to_string(arr->GetNumberOfTuples()) + " tuples for " +
                   std::to_string(ds->GetNumberOfPoints()) + " points");
  return arr;
}

// The component order as read, for `info`.
std::string layoutOf(vtkDataArray* arr, const NiftiLayout& six, bool named) {
  if (!arr) return "Sxx Syy Szz Syz Szx Sxy";
  switch (arr->GetNumberOfComponents()) {
    case 9: return "9 values (row-major 3x3)";
    case 6:
      return std::string("6 values, ") + six.name + ": " + six.order +
             (named ? " (--layout)" : " (VTK's own order; override with --layout)");
    case 4: return "4 values, 2-D (XX YY ZZ XY, as OpenGeoSys writes them); XZ = YZ = 0";
    default: return "3 values, 2-D (XX YY XY); ZZ = XZ = YZ = 0";
  }
}

// One tuple of `nc` components as a full row-major 3x3; six in `six`'s order.
void fullTensor(int nc, const double* t, const NiftiLayout& six, double full[9]) {
  const double zero[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  std::copy(zero, zero + 9, full);
  if (nc == 9) {
    std::copy(t, t + 9, full);
  } else if (nc == 6) {
    double s[6];  // xx xy xz yy yz zz
    for (int k = 0; k < 6; ++k) s[k] = t[six.sym[std::size_t(k)]];
    const double f[9] = {s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5]};
    std::copy(f, f + 9, full);
  } else {  // XX YY ZZ XY, or XX YY XY
    planarTensor(nc, t, full);
  }
}

// The order of a 6-component array: --layout's, else VTK's own. Checked on
// the whole array before anything is kept: no criterion tells a stress
// field's order in general (it may be indefinite), but on points in a
// coordinate plane the out-of-plane shears vanish (io/core/nifti_layouts.h).
const NiftiLayout& sixComponentOrder(vtkDataSet* ds, vtkDataArray* arr, const NonFiniteText& nonFinite,
                                     const std::string& path, const ReadOptions& opt, TensorField& f) {
  const NiftiLayout* chosen = niftiLayoutNamed(opt.layout.empty() ? "vtk" : opt.layout, kVtkInput);
  if (!chosen)
    fail(path, unusableLayout(opt.layout, kVtkInput, "VTK"));
  const vtkIdType n = arr->GetNumberOfTuples();
  LayoutSample sample{std::uint64_t(n)};
  const vtkIdType step = std::max<vtkIdType>(1, n / 16384);
  double t[6];
  for (vtkIdType i = 0; i < n; i += step) {
    arr->GetTuple(i, t);
    for (double& x : t) x = nonFinite.restore(x);
    sample.offer(std::uint64_t(i), t);
  }
  double b[6];
  ds->GetBounds(b);
  const double lo[3] = {b[0], b[2], b[4]}, hi[3] = {b[1], b[3], b[5]};
  const LayoutAdvice advice = adviseLayout(sample, *chosen, opt.layout.empty(), kVtkInput,
                                           Plausibility{false, coordinatePlaneNormal(lo, hi)}, cliLayoutName);
  if (!advice.refusal.empty()) fail(path, "array \"" + nameOf(arr) + "\": " + advice.refusal);
  if (!advice.warning.empty()) f.warnings.push_back("array \"" + nameOf(arr) + "\": " + advice.warning);
  return *chosen;
}

}  // namespace

namespace {

// Every array of a legacy file, not only the first of each attribute kind,
// so that --array can name any of them.
vtkSmartPointer<vtkDataSetReader> legacyReader() {
  auto r = vtkSmartPointer<vtkDataSetReader>::New();
  r->ReadAllTensorsOn();
  r->ReadAllFieldsOn();
  r->ReadAllScalarsOn();
  r->ReadAllVectorsOn();
  return r;
}

}  // namespace

// VTK 9.1's legacy reader dereferences null on some corrupt bodies that pass
// every header check (tests/fuzz/vtk-body-crashes), and its XML parser
// recurses once per nesting level: readTensorField runs all of this in a
// child process (io/core/read_guard.h), which turns such crashes into one line.
ReadResult readDataSet(const std::string& path, const ReadOptions& opt, const int* dims) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) fail(path, "cannot open file");
  const std::uint64_t fileSize = std::uint64_t(st.st_size);
  std::string ext = path.substr(path.find_last_of('.') + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  vtkSmartPointer<vtkAlgorithm> reader;
  std::uint64_t legacyPoints = 0;
  if (ext == "vtk") {
    legacyPoints = std::max<std::uint64_t>(checkLegacyCounts(path, fileSize), 1);
    auto r = legacyReader();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (ext == "vti") {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (ext == "vtu") {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (ext == "vtp") {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (ext == "vts") {
    auto r = vtkSmartPointer<vtkXMLStructuredGridReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else {
    fail(path, "unknown VTK extension \"." + ext + "\"");
  }
  ReadResult read = runReader(reader, path, fileSize, legacyPoints, opt, dims);
  // C++ streams stop at "nan" and "inf": read such a file again from a copy
  // whose non-finite words are sentinels (io/modules/vtk/vtk_nonfinite.h).
  if (legacyPoints && read.vtkSaid.find("Error reading ascii data") != std::string::npos) {
    NonFiniteText nonFinite = NonFiniteText::replace(path);
    if (!nonFinite.empty()) {
      read = ReadResult{};  // the failed pass's arrays go before the second pass
      auto r = legacyReader();
      auto text = vtkSmartPointer<vtkCharArray>::New();
      text->SetArray(const_cast<char*>(nonFinite.text().data()), vtkIdType(nonFinite.text().size()), 1);
      r->SetInputArray(text);
      r->ReadFromInputStringOn();
      // VTK copies the text twice more (a std::string, then a stream).
      read = runReader(r, path, fileSize, legacyPoints, opt, dims, 3);
      read.nonFinite = std::move(nonFinite);
    }
  }
  return read;
}

void impl::checkVtkLegacyHeader(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) fail(path, "cannot open file");
  checkLegacyCounts(path, std::uint64_t(st.st_size));
  vtkNew<vtkDataSetReader> r;
  const ErrorSink sink(r);
  const VtkMessageCapture said;
  r->SetFileName(path.c_str());
  if (r->ReadOutputType() < 0 || !sink.first().empty() || !said.first().empty())
    fail(path, !sink.first().empty() ? sink.first() : !said.first().empty() ? said.first() : "not a legacy VTK dataset");
}

void impl::checkVtkXmlHeader(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) fail(path, "cannot open file");
  vtkNew<vtkXMLUnstructuredGridReader> r;
  const ErrorSink sink(r);
  const VtkMessageCapture said;
  r->SetFileName(path.c_str());
  r->UpdateInformation();
  if (!sink.first().empty() || r->GetErrorCode())
    fail(path, !sink.first().empty() ? cleanVtkMessage(sink.first()) : said.first().empty() ? "unreadable XML header" : said.first());
  xmlPoints(r, path);
  checkXmlStructure(r, path);
  if (!said.first().empty()) fail(path, said.first());
}

ScalarVolume impl::readVtiScalar(const std::string& path, const int* dims) {
  // An underlay (no dims) is held to the load's memory before VTK decodes it.
  ReadOptions opt;
  if (!dims) opt.memoryBudget = defaultMemoryBudget();
  const ReadResult read = readDataSet(path, opt, dims);
  if (!read.vtkSaid.empty()) fail(path, read.vtkSaid);
  // The scalar array is chosen by its place, which a missing array moves.
  if (!read.pieceGaps.empty()) fail(path, read.pieceGaps[0].problem);
  vtkDataSet* ds = read.data;
  auto* img = vtkImageData::SafeDownCast(ds);
  if (!img) fail(path, "a mask or underlay must be image data");
  vtkDataArray* a = img->GetPointData()->GetScalars();
  if (!a && img->GetPointData()->GetNumberOfArrays() > 0) a = img->GetPointData()->GetArray(0);
  if (!a || a->GetNumberOfComponents() != 1) fail(path, "no one-component point array to use as a mask or underlay");
  ScalarVolume v;
  img->GetDimensions(v.dims);
  v.placement = imagePlacement(img);
  const vtkIdType n = a->GetNumberOfTuples();
  v.values.resize(std::size_t(n));
  for (vtkIdType i = 0; i < n; ++i) v.values[std::size_t(i)] = float(a->GetComponent(i, 0));
  return v;
}

TensorField impl::readVtk(const std::string& path, const ReadOptions& opt) {
  if (const std::string o = inapplicableOption(InputFormat::Vtk, opt); !o.empty())
    fail(path, o + " does not apply to VTK, whose tensors are in the points' world axes");
  const ReadResult read = readDataSet(path, opt);
  checkPieceGaps(read, path, opt);
  vtkDataSet* ds = read.data;
  const vtkIdType n = ds->GetNumberOfPoints();
  if (n <= 0) fail(path, "no points");
  if (n > vtkIdType(kMaxInputs)) fail(path, "more than 2^32-256 points");
  // A legacy file without point tensors may carry 3D-TSV's stress trailer.
  std::vector<double> trailer;
  vtkDataArray* arr = nullptr;
  const bool fromTrailer = isLegacy(path) && opt.arrayName.empty() && !hasTensorArray(ds) &&
                           readTsvStressTrailer(path, std::uint64_t(n), trailer);
  if (!fromTrailer) arr = pickTensorArray(ds, path, opt);
  // VTK stops, with a warning, at a 3D-TSV trailer's first line; that one is
  // accounted for. Any other word from VTK means its arrays cannot be trusted.
  if (!read.vtkSaid.empty() && !(fromTrailer && read.vtkSaid.find("Unsupported point attribute type") != std::string::npos))
    fail(path, read.vtkSaid);

  const int nc = arr ? arr->GetNumberOfComponents() : 9;
  if (!opt.layout.empty() && nc != 6)
    fail(path, "--layout applies to 6-component arrays; " +
                   (arr ? "\"" + nameOf(arr) + "\" has " + std::to_string(nc) + " components"
                        : std::string("the 3D-TSV stress trailer has 9")));
  TensorField f;
  const NiftiLayout& six =
      nc == 6 ? sixComponentOrder(ds, arr, read.nonFinite, path, opt, f) : *niftiLayoutNamed("vtk");
  f.path = path;
  f.arrayName = arr ? (arr->GetName() ? arr->GetName() : "") : "Cartesian Stress (3D-TSV trailer)";
  f.description = std::string(ds->GetClassName()) + ", " + std::to_string(n) + " points";
  f.layout = layoutOf(arr, six, !opt.layout.empty());
  auto* image = vtkImageData::SafeDownCast(ds);
  f.frame = std::string("world: the points' axes, not rotated, as VTK's filters take them") +
            (image && !image->GetDirectionMatrix()->IsIdentity() ? " (the Direction matrix places points only)" : "");
  if (nc <= 4) {
    double b[6];
    ds->GetBounds(b);
    if (b[5] > b[4])
      f.warnings.push_back("2-D tensors lie in the x-y plane, but the points span z from " + std::to_string(b[4]) +
                           " to " + std::to_string(b[5]));
  }
  std::optional<GridPlacement> placed;
  if (image) {
    placed = imagePlacement(image);
    // As the volume readers refuse a singular grid: drawn, every glyph along
    // an axis of spacing 0 would lie on one plane.
    if (gridIsSingular(image->GetDimensions(), placed->axesWC)) {
      const double* s = image->GetSpacing();
      fail(path, s[0] == 0 || s[1] == 0 || s[2] == 0 ? "the image spacing is singular (a spacing of 0)"
                                                     : "the image grid is singular (its Direction and spacing)");
    }
  }
  vtkDataArray* colorArr = nullptr;
  if (!opt.colorArray.empty()) {
    colorArr = ds->GetPointData()->GetArray(opt.colorArray.c_str());
    if (!colorArr) {
      const std::string seen = describeArrays(ds->GetPointData(), false);
      f.pointArrays = seen.empty() ? "none" : seen;
    } else if (colorArr->GetNumberOfComponents() != 1 || colorArr->GetNumberOfTuples() != n) {
      fail(path, "--color-array: point array \"" + nameOf(colorArr) + "\" has " +
                     std::to_string(colorArr->GetNumberOfComponents()) + " components and " +
                     std::to_string(colorArr->GetNumberOfTuples()) + " tuples; colour takes 1 component per point");
    } else {
      f.colorArrayName = nameOf(colorArr);
    }
  }
  const Selector sel(opt.selection, path, image ? image->GetDimensions() : nullptr, placed ? &*placed : nullptr);
  if (sel.selectsAll()) f.reserve(std::size_t(n));
  double p[3], t[9], full[9];
  double maxAsym = 0;
  for (vtkIdType i = 0; i < n; ++i) {
    ds->GetPoint(i, p);
    for (double& x : p) x = read.nonFinite.restore(x);
    if (!sel.admit(std::uint64_t(i), p, f)) continue;
    // The colour value of each tensor kept (addFull may skip a non-finite one).
    const std::size_t kept = f.ids.size();
    if (!arr) {
      f.addFull(std::uint32_t(i), p, &trailer[9 * std::size_t(i)]);
    } else {
      arr->GetTuple(i, t);
      for (int k = 0; k < nc; ++k) t[k] = read.nonFinite.restore(t[k]);
      fullTensor(nc, t, six, full);
      if (nc == 9) maxAsym = std::max(maxAsym, asymmetry(full));
      f.addFull(std::uint32_t(i), p, full);
    }
    if (colorArr && f.ids.size() > kept) f.colorValues.push_back(float(read.nonFinite.restore(colorArr->GetComponent(i, 0))));
  }
  if (std::string w = asymmetryWarning("9-component tensors", maxAsym); !w.empty()) f.warnings.push_back(std::move(w));
  if (auto* img = image) {
    GridInfo g;
    img->GetDimensions(g.dims);
    img->GetSpacing(g.spacing);
    img->GetOrigin(g.origin);
    const double* dir = img->GetDirectionMatrix()->GetData();
    std::copy(dir, dir + 9, g.directions);
    f.grid = g;
    // The kept samples' spacing: a stride thins them, a slice drops its own axis.
    const double spacing[3] = {std::abs(g.spacing[0]), std::abs(g.spacing[1]), std::abs(g.spacing[2])};
    const double s = sel.keptSpacing(spacing);
    f.sampleSpacing = std::isfinite(s) ? s : 0.0;
  }
  if (f.sampleSpacing <= 0) f.sampleSpacing = estimateSampleSpacing(f.positions);
  return f;
}

}  // namespace tg::io
