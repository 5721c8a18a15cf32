// Google Benchmark: loading and eigen-decomposing a raw float NRRD on one
// core (issue target: >= 10 million tensors per second per core;
// loadAndEigen is that figure).
//   build/tests/bench_load [--benchmark_filter=...]
// The file is written once to the temporary directory and read from the page
// cache, so the figures are decode + eigensystem cost, not disk speed.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "data-synthetic/generators.h"
#include "data-synthetic/random_tensors.h"
#include "io/core/input_files.h"
#include "io/core/readers.h"
#include "tensor/eigen.h"
#include "tensor/glyph.h"

using namespace tg;

namespace {

const std::string& fileFor(std::int64_t n) {
  static std::map<std::int64_t, std::string> files;
  auto& p = files[n];
  if (p.empty()) {
    const auto dir = std::filesystem::temp_directory_path() / ("tg_bench_load_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    p = (dir / ("random-" + std::to_string(n) + ".nhdr")).string();
    synth::writeRandomNrrdStreaming(p, std::size_t(n), 7);
  }
  return p;
}

void loadOnly(benchmark::State& st) {
  const std::string& path = fileFor(st.range(0));
  std::size_t n = 0;
  for (auto _ : st) {
    const io::TensorField f = io::readNrrd(path, {});
    n = f.size();
    benchmark::DoNotOptimize(f.tensors.data());
  }
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

void eigenOnly(benchmark::State& st) {
  const io::TensorField f = io::readNrrd(fileFor(st.range(0)), {});
  for (auto _ : st) {
    const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
    benchmark::DoNotOptimize(g.glyphs.data());
  }
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(f.size()));
}

void eigensolveOnly(benchmark::State& st) {
  const io::TensorField f = io::readNrrd(fileFor(st.range(0)), {});
  const std::size_t n = f.size();
  for (auto _ : st) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const float* t = &f.tensors[6 * i];
      sum += tensor::eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]}).values.x;
    }
    benchmark::DoNotOptimize(sum);
  }
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

// The SIMD block solver the glyph builder uses, without the records.
void eigensolveBlockOnly(benchmark::State& st) {
  const io::TensorField f = io::readNrrd(fileFor(st.range(0)), {});
  const std::size_t n = f.size();
  tensor::EigenBlock block;
  for (auto _ : st) {
    double sum = 0;
    for (std::size_t b = 0; b < n; b += tensor::kEigenBlock) {
      tensor::eigensolveBlock(&f.tensors[6 * b], std::min(tensor::kEigenBlock, n - b), block);
      sum += block.values[0][0];
    }
    benchmark::DoNotOptimize(sum);
  }
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

void loadAndEigen(benchmark::State& st) {
  const std::string& path = fileFor(st.range(0));
  std::size_t n = 0;
  for (auto _ : st) {
    const io::TensorField f = io::readNrrd(path, {});
    const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
    n = g.glyphs.size();
    benchmark::DoNotOptimize(g.glyphs.data());
  }
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

// The same through readTensorField: the read runs in a child process under
// limits (io/core/read_guard.h) and its arrays are copied out of it. The
// difference to loadAndEigen is the guard's cost.
void loadAndEigenGuarded(benchmark::State& st) {
  const std::string& path = fileFor(st.range(0));
  std::size_t n = 0;
  for (auto _ : st) {
    const io::TensorField f = io::readTensorField(path, {});
    const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
    n = g.glyphs.size();
    benchmark::DoNotOptimize(g.glyphs.data());
  }
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

// The same with progress on, as on a terminal: the parent reads the child's
// file offset 10 times a second, and the eigen-decomposition reports every
// 64k tensors. The difference to loadAndEigenGuarded is what progress costs.
void loadAndEigenGuardedProgress(benchmark::State& st) {
  const std::string& path = fileFor(st.range(0));
  std::size_t n = 0, reports = 0;
  io::ReadOptions opt;
  opt.progress = [&reports](std::string_view, double, double, std::string_view) { ++reports; };
  for (auto _ : st) {
    const io::TensorField f = io::readTensorField(path, opt);
    const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1, {}, opt.progress);
    n = g.glyphs.size();
    benchmark::DoNotOptimize(g.glyphs.data());
  }
  st.counters["reports"] = benchmark::Counter(double(reports) / double(st.iterations()));
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

// The guard's fixed cost per file: fork, limits, the socket and wait, on one tensor.
void guardPerFile(benchmark::State& st) {
  const std::string& path = fileFor(1);
  for (auto _ : st) benchmark::DoNotOptimize(io::readTensorField(path, {}).size());
}
void unguardedPerFile(benchmark::State& st) {
  const std::string& path = fileFor(1);
  for (auto _ : st) benchmark::DoNotOptimize(io::readTensorFieldInProcess(path, {}).size());
}

// The same tensors as an MRtrix image in one of kMifLayouts: the first is the
// NRRD's own raw file named by a .mih (voxel by voxel, read as it comes); the
// others are transcoded and gathered by the reader before the sink.
constexpr const char* kMifLayouts[] = {"+1,+2,+3,+0", "-1,+2,+3,+0", "+0,+1,+2,+3", "-0,+2,+1,+3"};

std::string mifFor(std::int64_t n, std::size_t layout) {
  const std::filesystem::path nhdr = fileFor(n);
  const synth::GridDims d = synth::gridDims(std::size_t(n));
  const std::string name = nhdr.stem().string() + "-layout" + std::to_string(layout);
  const std::filesystem::path mih = nhdr.parent_path() / (name + ".mih");
  if (std::filesystem::exists(mih)) return mih.string();
  // synth names its data file uniquely (io/field/atomic_file.h); the header says which.
  std::string raw = std::filesystem::path(io::nrrdDataFiles(nhdr.string()).at(0)).filename().string();
  if (layout > 0) {
    // Value (voxel v, component c) moves to its offset under the layout.
    std::ifstream in(nhdr.parent_path() / raw, std::ios::binary);
    std::vector<float> src(6 * std::size_t(n)), dst(src.size());
    in.read(reinterpret_cast<char*>(src.data()), std::streamsize(src.size() * sizeof(float)));
    const std::size_t dim[4] = {d.x, d.y, d.z, 6};
    int rank[4];
    bool down[4];
    for (int a = 0; a < 4; ++a) {
      const std::string item = std::string(kMifLayouts[layout]).substr(std::size_t(3 * a), 2);
      down[a] = item[0] == '-';
      rank[a] = item[1] - '0';
    }
    std::size_t stride[4];
    for (int a = 0; a < 4; ++a) {
      stride[a] = 1;
      for (int b = 0; b < 4; ++b) stride[a] *= rank[b] < rank[a] ? dim[b] : 1;
    }
    for (std::size_t v = 0; v < std::size_t(n); ++v)
      for (std::size_t c = 0; c < 6; ++c) {
        const std::size_t idx[4] = {v % d.x, v / d.x % d.y, v / (d.x * d.y), c};
        std::size_t off = 0;
        for (int a = 0; a < 4; ++a) off += (down[a] ? dim[a] - 1 - idx[a] : idx[a]) * stride[a];
        dst[off] = src[6 * v + c];
      }
    raw = name + ".raw";
    std::ofstream(nhdr.parent_path() / raw, std::ios::binary)
        .write(reinterpret_cast<const char*>(dst.data()), std::streamsize(dst.size() * sizeof(float)));
  }
  std::ofstream(mih) << "mrtrix image\ndim: " << d.x << "," << d.y << "," << d.z << ",6\nvox: 1,1,1,1\nlayout: "
                     << kMifLayouts[layout] << "\ndatatype: Float32LE\ntransform: 1,0,0,0\ntransform: 0,1,0,0\n"
                     << "transform: 0,0,1,0\nfile: " << raw << "\nEND\n";
  return mih.string();
}

// Arguments: tensor count, index into kMifLayouts. Compare with loadOnly.
void loadMif(benchmark::State& st) {
  const std::string path = mifFor(st.range(0), std::size_t(st.range(1)));
  std::size_t n = 0;
  for (auto _ : st) {
    const io::TensorField f = io::readMif(path, {});
    n = f.size();
    benchmark::DoNotOptimize(f.tensors.data());
  }
  st.SetLabel(kMifLayouts[st.range(1)]);
  st.SetItemsProcessed(std::int64_t(st.iterations()) * std::int64_t(n));
}

}  // namespace

BENCHMARK(loadMif)->ArgsProduct({{1 << 21}, {0, 1, 2, 3}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(loadOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(eigenOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(eigensolveOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(eigensolveBlockOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(loadAndEigen)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(loadAndEigenGuarded)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(loadAndEigenGuardedProgress)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(guardPerFile)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(unguardedPerFile)->Unit(benchmark::kMicrosecond)->UseRealTime();

BENCHMARK_MAIN();
