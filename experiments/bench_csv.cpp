// Throughput of load_dataset_csv on files as `generate` writes them (seed model, Hertz, 1 %
// noise, the four channels, every number with %.17g): 2,500 rows (about 250 KB, one run of a
// `batch` campaign), 1e5 and 1e6 rows. Each file is written once and then read from the page
// cache, so the figure is the parser's, not the disk's; bytes/s are per wall-clock second.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <frictionid/io/dataset_csv.hpp>
#include <frictionid/io/dataset_writer.hpp>
#include <frictionid/model_variant.hpp>
#include <frictionid/synthetic_data.hpp>

namespace {

using namespace frictionid;
namespace fs = std::filesystem;

// The file of `rows` rows, written on first use and removed at exit.
const fs::path& csv_file(std::size_t rows) {
  struct Files {
    std::map<std::size_t, fs::path> paths;
    ~Files() {
      std::error_code ec;
      for (const auto& [rows, path] : paths) fs::remove(path, ec);
    }
  };
  static Files files;
  auto [it, added] = files.paths.try_emplace(rows);
  if (added) {
    const auto law = model::PressureLaw<double>::hertz();
    SyntheticDesign design;
    design.rows = rows;
    const Dataset data = generate_dataset(ModelKind::Seed, law, default_parameters(law), design,
                                          NoiseSpec{0.01, 0.0, false}, 5);
    it->second =
        fs::temp_directory_path() / ("frictionid_bench_csv_" + std::to_string(rows) + ".csv");
    std::ofstream(it->second, std::ios::binary) << dataset_csv_text(data);
  }
  return it->second;
}

void csv_read(benchmark::State& state) {
  const fs::path& path = csv_file(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(load_dataset_csv(path.string()));
  state.SetBytesProcessed(state.iterations() * static_cast<long>(fs::file_size(path)));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(csv_read)
    ->Arg(2500)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
