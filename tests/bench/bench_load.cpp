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
#include <map>

#include "data-synthetic/generators.h"
#include "io/readers.h"
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
// limits (io/read_guard.h) and the field comes back through a memfd. The
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

// The guard's fixed cost per file: fork, limits, memfd and wait, on one tensor.
void guardPerFile(benchmark::State& st) {
  const std::string& path = fileFor(1);
  for (auto _ : st) benchmark::DoNotOptimize(io::readTensorField(path, {}).size());
}
void unguardedPerFile(benchmark::State& st) {
  const std::string& path = fileFor(1);
  for (auto _ : st) benchmark::DoNotOptimize(io::readTensorFieldInProcess(path, {}).size());
}

}  // namespace

BENCHMARK(loadOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(eigenOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(eigensolveOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(eigensolveBlockOnly)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(loadAndEigen)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(loadAndEigenGuarded)->Arg(1 << 21)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(guardPerFile)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(unguardedPerFile)->Unit(benchmark::kMicrosecond)->UseRealTime();

BENCHMARK_MAIN();
