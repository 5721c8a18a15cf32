// NIfTI-1/-2 through libnifti2. The header is read alone and checked against
// the file; the data is then streamed volume by volume (through znz, or zlib
// for .nii.gz), into one float per kept component.
#include <fcntl.h>
#include <nifti/nifti2_io.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string_view>

#include "io/core/format_impl.h"
#include "io/core/gzip_errors.h"
#include "io/core/nifti_layouts.h"
#include "io/core/readers.h"
#include "io/core/selection.h"
#include "io/core/volume_sink.h"
#include "util/huge_pages.h"
#include "util/number_text.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readNifti: " + path + ": " + what);
}

constexpr std::uint64_t kMaxGzipRatio = 1032;  // deflate's limit
constexpr std::size_t kChunkBytes = 1 << 22;

using Image = std::unique_ptr<nifti_image, void (*)(nifti_image*)>;

// libnifti2 prints some header errors ("** ERROR: ... bad datatype") to
// stderr whatever its debug level; our message must be the only line, so
// stderr is pointed at /dev/null for the duration of the header read.
class SilenceStderr {
 public:
  SilenceStderr() : saved_(dup(2)) {
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, 2);
      close(null);
    }
  }
  ~SilenceStderr() {
    if (saved_ >= 0) {
      dup2(saved_, 2);
      close(saved_);
    }
  }
  SilenceStderr(const SilenceStderr&) = delete;
  SilenceStderr& operator=(const SilenceStderr&) = delete;

 private:
  int saved_;
};

// What the raw header says, in the file's byte order turned into ours.
struct RawHeader {
  int version = 0;
  double voxOffset = 0;
  double pixdim[4] = {};  // as the file has them: libnifti2 turns a 0 into 1
};

// libnifti2 3.0.1's nifti_image_read copies dim[1..dim[0]] into arrays of
// eight without checking dim[0]: NIfTI-2 headers with dim[0] = 2052, or 4
// in the other byte order, smashed its stack or segfaulted (found by
// fuzz_nifti). It also turns a dimension below 1 into 1, which shifted the
// data. The raw header is read first and checked before it sees it.
RawHeader checkRawHeader(const std::string& path) {
  RawHeader r;
  void* raw = nifti_read_header(path.c_str(), &r.version, 0);
  if (!raw) fail(path, "not a readable NIfTI-1/-2 header");
  // nifti_read_header leaves the bytes in the file's order; a header whose
  // size field reads swapped is in the other byte order from ours.
  std::int64_t dim[8] = {};
  double pixdim[8] = {};
  bool sized = true;
  if (r.version == 2) {
    const auto* h = static_cast<nifti_2_header*>(raw);
    const bool native = h->sizeof_hdr == 540;
    sized = native || __builtin_bswap32(std::uint32_t(h->sizeof_hdr)) == 540;
    for (int k = 0; k < 8; ++k) dim[k] = native ? h->dim[k] : std::int64_t(__builtin_bswap64(std::uint64_t(h->dim[k])));
    for (int k = 0; k < 8; ++k)
      pixdim[k] = native ? h->pixdim[k] : std::bit_cast<double>(__builtin_bswap64(std::bit_cast<std::uint64_t>(h->pixdim[k])));
    r.voxOffset = double(native ? h->vox_offset : std::int64_t(__builtin_bswap64(std::uint64_t(h->vox_offset))));
  } else {
    const auto* h = static_cast<nifti_1_header*>(raw);
    const bool native = h->sizeof_hdr == 348;
    sized = native || __builtin_bswap32(std::uint32_t(h->sizeof_hdr)) == 348;
    for (int k = 0; k < 8; ++k) dim[k] = native ? h->dim[k] : std::int16_t(__builtin_bswap16(std::uint16_t(h->dim[k])));
    for (int k = 0; k < 8; ++k)
      pixdim[k] = native ? h->pixdim[k] : std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(h->pixdim[k])));
    r.voxOffset = native ? h->vox_offset
                         : std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(h->vox_offset)));
  }
  std::free(raw);
  std::copy(pixdim, pixdim + 4, r.pixdim);
  if (!sized) fail(path, "not a readable NIfTI-1/-2 header");
  if (dim[0] < 1 || dim[0] > 7) fail(path, "dim[0] is " + std::to_string(dim[0]) + ", not 1..7");
  for (int k = 1; k <= dim[0]; ++k)
    if (dim[k] < 1) fail(path, "dimension " + std::to_string(k) + " is " + std::to_string(dim[k]));
  // libnifti2 turns a NaN or Inf voxel size into 1, which would place the
  // voxels somewhere the file never said.
  for (int k = 1; k <= std::min<std::int64_t>(dim[0], 3); ++k)
    if (!std::isfinite(pixdim[k])) fail(path, "pixdim[" + std::to_string(k) + "] (a voxel size) is not finite");
  return r;
}

// In a single .nii file the data starts at vox_offset, at least 352 (NIfTI-1)
// or 544 (NIfTI-2) bytes in: the header and the extension flag come first.
// libnifti2 quietly reads a smaller, zero, negative or NaN offset from byte
// 348, which shifted every volume by one value.
void checkDataOffset(const std::string& path, const nifti_image& nim, const RawHeader& raw) {
  if (!nim.iname || !nim.fname || std::strcmp(nim.iname, nim.fname) != 0) return;  // .hdr/.img pair
  const double least = raw.version == 2 ? 544 : 352;
  if (!(raw.voxOffset >= least) || !(raw.voxOffset < 9.2e18))
    fail(path, "vox_offset " + std::to_string(raw.voxOffset) +
                   " is not a data offset: a .nii file's data starts at byte " + std::to_string(int(least)) +
                   " or later");
  if (double(nim.iname_offset) != std::floor(raw.voxOffset))
    fail(path, "vox_offset disagrees with the offset libnifti2 uses");
}

Image readHeader(const std::string& path) {
  nifti_set_debug_level(0);
  Image nim(nullptr, nifti_image_free);
  RawHeader raw;
  {
    const SilenceStderr quiet;
    raw = checkRawHeader(path);
    nim.reset(nifti_image_read(path.c_str(), 0));
  }
  if (!nim) fail(path, "not a readable NIfTI-1/-2 header");
  checkDataOffset(path, *nim, raw);
  // The file's qfac and voxel sizes, for placement to judge (qfacOf, voxelSizes).
  for (int k = 0; k <= 3; ++k) nim->pixdim[k] = raw.pixdim[k];
  if (!nim->iname) fail(path, "no image file named");
  return nim;
}

double (*loader(const std::string& path, int datatype))(const char*) {
  switch (datatype) {
    case NIFTI_TYPE_UINT8: return [](const char* p) { return double(*reinterpret_cast<const std::uint8_t*>(p)); };
    case NIFTI_TYPE_INT8: return [](const char* p) { return double(*reinterpret_cast<const std::int8_t*>(p)); };
    case NIFTI_TYPE_INT16: return [](const char* p) { return double(*reinterpret_cast<const std::int16_t*>(p)); };
    case NIFTI_TYPE_UINT16: return [](const char* p) { return double(*reinterpret_cast<const std::uint16_t*>(p)); };
    case NIFTI_TYPE_INT32: return [](const char* p) { return double(*reinterpret_cast<const std::int32_t*>(p)); };
    case NIFTI_TYPE_UINT32: return [](const char* p) { return double(*reinterpret_cast<const std::uint32_t*>(p)); };
    case NIFTI_TYPE_INT64: return [](const char* p) { return double(*reinterpret_cast<const std::int64_t*>(p)); };
    case NIFTI_TYPE_UINT64: return [](const char* p) { return double(*reinterpret_cast<const std::uint64_t*>(p)); };
    case NIFTI_TYPE_FLOAT32: return [](const char* p) { return double(*reinterpret_cast<const float*>(p)); };
    case NIFTI_TYPE_FLOAT64: return [](const char* p) { return *reinterpret_cast<const double*>(p); };
    default: fail(path, std::string("data type ") + nifti_datatype_string(datatype) + " is not supported");
  }
}

// libnifti2 3.0.1 reports nifti_type 1 for NIfTI-2 files too; the header
// reader tells the versions apart.
int niftiVersion(const std::string& path) {
  int version = 0;
  std::free(nifti_read_header(path.c_str(), &version, 0));
  return version;
}


// Streams values [0, count) of the image file, in order, to consume(value).
// The data the header describes must fit in the image file (or, gzipped,
// within deflate's ratio of it). Called before anything is sized by the header.
void checkDataSize(const std::string& path, const nifti_image& nim, std::uint64_t count) {
  loader(path, nim.datatype);
  if (nim.nbyper < 1 || nim.nbyper > 8) fail(path, "bytes per value " + std::to_string(nim.nbyper) + " is not 1..8");
  const std::uint64_t bytes = count * std::uint64_t(nim.nbyper);
  const bool gz = nifti_is_gzfile(nim.iname);
  const std::int64_t fileSize = nifti_get_filesize(nim.iname);
  if (fileSize < 0) fail(path, std::string("cannot open image file ") + nim.iname);
  if (nim.iname_offset < 0) fail(path, "negative data offset");
  const std::uint64_t avail = std::uint64_t(std::max<std::int64_t>(fileSize - (gz ? 0 : nim.iname_offset), 0));
  if (gz ? bytes > avail * kMaxGzipRatio : bytes > avail)
    fail(path, "data is truncated: the header describes " + std::to_string(bytes) + " bytes, the file has " +
                   std::to_string(avail) + (gz ? " compressed" : ""));
}

// The image file's bytes from the data offset on. A .gz image is read with
// zlib itself rather than through znz: znzread turns a zlib error into a
// count near 2^64 and cannot say what it was, and a stream cut at its
// trailer would go unnoticed; gzerror tells both (io/core/gzip_errors.h, shared with the NRRD reader).
class ImageBytes {
 public:
  ImageBytes(const std::string& path, const nifti_image& nim) : path_(path) {
    const std::string cannot = std::string("cannot open image file ") + nim.iname;
    if (nifti_is_gzfile(nim.iname)) {
      gz_.reset(gzopen(nim.iname, "rb"));
      if (!gz_) fail(path, cannot);
      gzbuffer(gz_.get(), 1 << 18);
      if (gzseek(gz_.get(), z_off_t(nim.iname_offset), SEEK_SET) < 0) fail(path, "cannot seek to the image data");
    } else {
      plain_.reset(znzopen(nim.iname, "rb", 0));
      if (!plain_) fail(path, cannot);
      if (znzseek(plain_.get(), nim.iname_offset, SEEK_SET) < 0) fail(path, "cannot seek to the image data");
    }
  }
  // Up to n bytes; fewer only where the data ends.
  std::size_t read(char* dst, std::size_t n) {
    if (!gz_) return znzread(dst, 1, n, plain_.get());
    const int got = gzread(gz_.get(), dst, unsigned(n));
    if (got < 0) corrupt();
    return std::size_t(got);
  }
  // One read past the data reaches the end of a gzip stream, where zlib
  // checks its CRC: corrupt data that still inflated is refused.
  void finish() {
    if (!gz_ || gzdirect(gz_.get())) return;
    char extra;
    if (gzread(gz_.get(), &extra, 1) < 0) corrupt();
    if (const std::string problem = gzipTrailerError(gz_.get()); !problem.empty()) fail(path_, problem);
  }

 private:
  [[noreturn]] void corrupt() { fail(path_, gzipReadError(gz_.get())); }
  struct GzClose {
    void operator()(gzFile g) const { gzclose(g); }
  };
  struct ZnzClose {
    void operator()(znzFile z) const { Xznzclose(&z); }
  };
  std::string path_;
  std::unique_ptr<gzFile_s, GzClose> gz_;
  std::unique_ptr<std::remove_pointer_t<znzFile>, ZnzClose> plain_;
};

template <class Consume>
void streamValues(const std::string& path, const nifti_image& nim, std::uint64_t count, Consume&& consume) {
  checkDataSize(path, nim, count);
  const auto load = loader(path, nim.datatype);
  const std::uint64_t tsize = std::uint64_t(nim.nbyper);
  ImageBytes in(path, nim);
  const bool swap = nim.byteorder != nifti_short_order() && tsize > 1;
  const double slope = nim.scl_slope, inter = nim.scl_inter;
  const bool scaled = slope != 0.0 && std::isfinite(slope) && !(slope == 1.0 && inter == 0.0);
  // No larger than the data: a fresh reader process faults in every page.
  std::vector<char> buf(std::size_t(std::min<std::uint64_t>(kChunkBytes, count * tsize)));
  for (std::uint64_t done = 0; done < count;) {
    const std::size_t want = std::size_t(std::min<std::uint64_t>(kChunkBytes / tsize, count - done));
    // Whole bytes: a partly read last value is not a value.
    if (const std::size_t got = in.read(buf.data(), want * tsize); got != want * tsize)
      fail(path, "data is truncated: the header describes " + std::to_string(count) + " values, the image ends after " +
                     std::to_string(done + got / tsize));
    if (swap) nifti_swap_Nbytes(std::int64_t(want), int(tsize), buf.data());
    for (std::size_t i = 0; i < want; ++i) {
      const double x = load(buf.data() + i * tsize);
      consume(scaled ? slope * x + inter : x);
    }
    done += want;
  }
  in.finish();
}

// A voxel size of 0 or below is invalid. libnifti2 builds the qform and we
// built "method 1" with 1 in its place; nibabel (and so DIPY) uses |pixdim|
// and 1 for 0. Where pixdim places the voxels, nibabel's reading is taken and
// said, so that the two readers put the glyphs in the same place.
std::array<double, 3> voxelSizes(const nifti_image& nim, std::vector<std::string>* warnings) {
  std::array<double, 3> d{};
  for (int k = 0; k < 3; ++k) {
    const double p = nim.pixdim[k + 1];
    d[std::size_t(k)] = p > 0 ? p : p < 0 ? -p : 1.0;
    if (!(p > 0) && warnings)
      warnings->push_back("pixdim[" + std::to_string(k + 1) + "] (a voxel size) is " + util::numberText(p) + "; " +
                           util::numberText(d[std::size_t(k)]) + " is used, as nibabel uses it");
  }
  return d;
}

// A placement code as nibabel (and so DIPY) reads it: one outside NIfTI's
// 0..5 is 0, unknown. libnifti2 used any code above 0: a file with
// sform_code 7 was placed by its sform here and by its qform in nibabel.
int usableCode(int code, const char* name, std::vector<std::string>& warnings) {
  if (code >= 0 && code <= NIFTI_XFORM_TEMPLATE_OTHER) return code;
  if (code > 0)
    warnings.push_back(std::string(name) + " is " + std::to_string(code) +
                       ", not a NIfTI code (0..5); it is not used, as nibabel does not use it");
  return 0;
}

// The qform's handedness (pixdim[0]) as nibabel reads it: 1 unless it is -1.
// libnifti2 takes the sign of any value, so a qfac of -2 flipped z here and
// not in nibabel.
double qfacOf(const nifti_image& nim, std::vector<std::string>* warnings) {
  const double p = nim.pixdim[0];
  if (p < 0 && p != -1.0 && warnings)
    warnings->push_back("pixdim[0] (qfac) is " + util::numberText(p) + ", not 1 or -1; 1 is used, as nibabel uses it");
  return p == -1.0 ? -1.0 : 1.0;
}

// The affine in use: sform if coded, else qform, else pixdim (NIfTI's
// "method 1"); true when an affine places the voxels.
bool placement(const nifti_image& nim, VolumeGeometry& g, TensorField& f) {
  // xyzt_units' spatial code: what the legend's scale bar and `info` name.
  f.lengthUnits = nim.xyz_units == NIFTI_UNITS_MM ? "mm" : nim.xyz_units == NIFTI_UNITS_METER ? "m"
                  : nim.xyz_units == NIFTI_UNITS_MICRON ? "um" : "";
  const int sformCode = usableCode(nim.sform_code, "sform_code", f.warnings);
  const int qformCode = usableCode(nim.qform_code, "qform_code", f.warnings);
  nifti_dmat44 qform = nim.qto_xyz;
  if (qformCode > 0) {
    std::vector<std::string>* said = sformCode > 0 ? nullptr : &f.warnings;
    const std::array<double, 3> d = voxelSizes(nim, said);
    const double b = nim.quatern_b, c = nim.quatern_c, q = nim.quatern_d;
    // libnifti2 scales a longer (b, c, d) to length 1; nibabel refuses it.
    if (said && b * b + c * c + q * q > 1 + 1e-6)
      said->push_back("the qform's quaternion (b, c, d) is longer than 1; scaled to 1 as libnifti2 does (nibabel "
                      "refuses the file)");
    qform = nifti_quatern_to_dmat44(nim.quatern_b, nim.quatern_c, nim.quatern_d, nim.qoffset_x, nim.qoffset_y,
                                    nim.qoffset_z, d[0], d[1], d[2], qfacOf(nim, said));
  }
  const nifti_dmat44* m = sformCode > 0 ? &nim.sto_xyz : qformCode > 0 ? &qform : nullptr;
  if (m) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) g.axesWC[3 * r + c] = m->m[r][c];
      g.originWC[r] = m->m[r][3];
    }
    f.space = sformCode > 0 ? "RAS (sform)" : "RAS (qform)";
    // Two placements in one file: whichever is right, a reader that takes
    // the other draws elsewhere, so the disagreement is said (as MRtrix does).
    if (sformCode > 0 && qformCode > 0) {
      double diff = 0, step = 0;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) {
          diff = std::max(diff, std::abs(nim.sto_xyz.m[r][c] - qform.m[r][c]));
          if (c < 3) step = std::max(step, std::abs(nim.sto_xyz.m[r][c]));
        }
      if (!(diff <= 1e-3 * step))
        f.warnings.push_back("the sform and qform disagree (by up to " + std::to_string(diff) +
                             "); the sform is used, as FSL, nibabel and MRtrix use it");
    }
    return true;
  }
  const std::array<double, 3> d = voxelSizes(nim, &f.warnings);
  for (int k = 0; k < 3; ++k) g.axesWC[4 * k] = d[std::size_t(k)];
  f.space = "voxel grid (no sform or qform)";
  f.warnings.push_back("no sform or qform; placed by pixdim alone");
  return false;
}

// dim[k], or 1 beyond dim[0] (writers leave those 0 or stale).
std::int64_t dimOr1(const nifti_image& nim, int k) { return k <= nim.dim[0] ? nim.dim[k] : 1; }

std::uint64_t spatialVoxels(const std::string& path, const nifti_image& nim, VolumeGeometry& g) {
  std::uint64_t n = 1;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t d = dimOr1(nim, k + 1);
    if (d > INT32_MAX) fail(path, "dimension " + std::to_string(k + 1) + " is too large");
    g.dims[k] = int(d);
    n *= std::uint64_t(d);
  }
  if (n > kMaxInputs) fail(path, "more than 2^32-256 voxels");
  return n;
}

// The component order and frame to read with, and what chose each.
struct Convention {
  const NiftiLayout* layout;
  TensorFrame frame;
  std::string layoutSource, frameSource;
};

Convention convention(const std::string& path, const nifti_image& nim, const ReadOptions& opt) {
  if (const std::string o = inapplicableOption(InputFormat::Nifti, opt); !o.empty())
    fail(path, o + " does not apply to NIfTI");
  Convention c{nullptr, TensorFrame::Fsl, "--layout", "--frame"};
  if (!opt.layout.empty()) {
    c.layout = niftiLayoutNamed(opt.layout, kNiftiInput);
    if (!c.layout)
      fail(path, unusableLayout(opt.layout, kNiftiInput, "NIfTI"));
  } else if (nim.intent_code == NIFTI_INTENT_SYMMATRIX) {
    c.layout = niftiLayoutNamed("nifti");
    c.layoutSource = "the SYMMATRIX intent; override with --layout";
  } else if (std::string_view(nim.descrip, strnlen(nim.descrip, sizeof nim.descrip)).starts_with("MRtrix version")) {
    c.layout = niftiLayoutNamed("mrtrix");  // MRtrix's NIfTI writer signs its files so
    c.layoutSource = "the descrip names MRtrix; override with --layout";
  } else {
    c.layout = niftiLayoutNamed("fsl");
    c.layoutSource = "the default, FSL's; override with --layout";
  }
  if (!opt.frame.empty()) {
    const auto named = tensorFrameNamed(opt.frame);
    if (!named) fail(path, "unknown frame \"" + opt.frame + "\"; choose " + kTensorFrameChoices);
    c.frame = *named;
  } else {
    c.frame = c.layout->frame;
    c.frameSource = std::string("the ") + c.layout->name + " layout's; override with --frame";
  }
  return c;
}

}  // namespace

TensorField impl::readNifti(const std::string& path, const ReadOptions& opt) {
  const Image nim = readHeader(path);
  TensorField f;
  f.path = path;
  VolumeGeometry g;
  const std::uint64_t voxels = spatialVoxels(path, *nim, g);
  // Six components along dim 4 (FSL, MRtrix) or dim 5 (the SYMMATRIX intent).
  const std::int64_t nt = dimOr1(*nim, 4), nu = dimOr1(*nim, 5);
  if (!(nt == 6 && nu == 1) && !(nt == 1 && nu == 6))
    fail(path, "dimensions " + std::to_string(g.dims[0]) + "x" + std::to_string(g.dims[1]) + "x" +
                   std::to_string(g.dims[2]) + "x" + std::to_string(nt) + "x" + std::to_string(nu) +
                   " hold no tensor; expected 6 volumes along dimension 4 or 5");
  if (dimOr1(*nim, 6) != 1 || dimOr1(*nim, 7) != 1) fail(path, "dimensions 6 and 7 must be 1");
  const Convention conv = convention(path, *nim, opt);
  ComponentLayout cl;
  cl.sym = conv.layout->sym;
  f.layout = std::string(conv.layout->name) + ": " + conv.layout->order + " (" + conv.layoutSource + ")";

  const bool affine = placement(*nim, g, f);
  double a[9];
  std::copy(g.axesWC, g.axesWC + 9, a);
  const double det = determinant3(a);
  if (!(std::abs(det) > 0) || !std::isfinite(det)) fail(path, "the affine is singular");
  const FrameMap map = tensorFrameMap(conv.frame, a, affine);
  g.tensorToWC = map.tensorToWC;
  f.tensorToWC = map.tensorToWC;
  f.otherFrames = otherFrames(conv.frame, a, affine);
  f.frame = std::string(tensorFrameName(conv.frame)) + " (" + conv.frameSource + "): " + map.description;
  f.description = "NIfTI-" + std::to_string(niftiVersion(path)) + " volume, " + std::to_string(g.dims[0]) +
                  "x" + std::to_string(g.dims[1]) + "x" + std::to_string(g.dims[2]) + ", " +
                  nifti_datatype_string(nim->datatype);

  // Which voxels to keep is known before any data: decide it first, then
  // read the six volumes in file order into the kept voxels' slots only.
  checkDataSize(path, *nim, 6 * voxels);
  const GridPlacement placed = placementOf(g);
  const Selector sel(opt.selection, path, g.dims, &placed);
  VolumeSink sink(f, g, cl, sel, 0.0);
  std::vector<std::uint32_t> kept;  // empty: every voxel is kept
  if (!sel.selectsAll())
    for (std::uint64_t v = 0; v < voxels; ++v)
      if (sink.accept(v)) kept.push_back(std::uint32_t(v));
  const std::uint64_t keptCount = sel.selectsAll() ? voxels : kept.size();
  promiseData("readNifti", path, opt, 6 * voxels * std::uint64_t(nim->nbyper), keptCount);
  // Values arrive volume by volume: component c of voxels 0..voxels-1, then
  // c + 1. They are kept component-major and appended as they are decoded,
  // so that memory grows with the data actually in the file, never with what
  // a (gzipped, perhaps truncated) header claims.
  FloatGather comps;
  comps.reserve(6 * std::size_t(keptCount));
  std::uint64_t v = 0;
  std::size_t slot = 0;
  streamValues(path, *nim, 6 * voxels, [&](double x) {
    if (kept.empty()) {
      comps.push_back(x);
    } else if (slot < kept.size() && kept[slot] == v) {
      comps.push_back(x);
      ++slot;
    }
    if (++v == voxels) {
      v = 0;
      slot = 0;
    }
  });
  f.reserve(std::size_t(keptCount));
  double v6[6];
  const std::size_t stride = std::size_t(keptCount);
  for (std::size_t r = 0; r < stride; ++r) {
    for (std::size_t c = 0; c < 6; ++c) v6[c] = comps.get(c * stride + r);
    sink.pushAccepted(kept.empty() ? r : kept[r], v6);
  }
  sink.finish();
  // A file that says its six values are something else (a vector, a general
  // 2x3 matrix, labels, a time series) is read as asked, but said to be.
  if (nim->intent_code != NIFTI_INTENT_NONE && nim->intent_code != NIFTI_INTENT_SYMMATRIX &&
      nim->intent_code != NIFTI_INTENT_ESTIMATE)
    f.warnings.push_back(std::string("the header's intent is ") + nifti_intent_string(nim->intent_code) + " (" +
                         std::to_string(nim->intent_code) + "), not a symmetric matrix: its six values may be no tensor");
  // Diffusion tensors are what NIfTI holds: a default order that reads them
  // as indefinite, when one other order reads them right, is refused.
  const LayoutAdvice advice =
      adviseLayout(LayoutSample::ofComponents(comps.floats(), std::size_t(keptCount)), *conv.layout,
                   opt.layout.empty(), kNiftiInput, Plausibility{true, -1}, cliNiftiLayoutName);
  if (!advice.refusal.empty()) fail(path, advice.refusal);
  if (!advice.warning.empty()) f.warnings.push_back(advice.warning);
  return f;
}

ScalarVolume impl::readNiftiScalar(const std::string& path, const int* dims) {
  const Image nim = readHeader(path);
  VolumeGeometry g;
  const std::uint64_t voxels = spatialVoxels(path, *nim, g);
  if (std::uint64_t(nim->nvox) != voxels) fail(path, "a mask or underlay must be a single 3D volume");
  if (const std::string m = maskGridMismatch(g.dims, dims); !m.empty()) fail(path, m);
  ScalarVolume s;
  std::copy(g.dims, g.dims + 3, s.dims);
  TensorField unused;
  if (placement(*nim, g, unused)) s.placement = placementOf(g);  // else its placement is unstated
  streamValues(path, *nim, voxels, [&](double x) { s.values.push_back(float(x)); });
  return s;
}

}  // namespace tg::io
