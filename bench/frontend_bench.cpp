// Time per corpus file of each stage: our front end (lex, preprocess, parse,
// analyse) and glslang validation as `check` runs it. Run:
//   build/bench/bench/frontend_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "driver/dialect.h"
#include "driver/front_end.h"
#include "driver/input_files.h"
#include "validate/glslang_validator.h"
#include "validate/shadertoy_contract.h"

namespace {

using namespace shaderport;

struct CorpusFile {
  std::string name;
  std::string text;
  driver::DetectedKind kind;
};

const std::vector<CorpusFile>& Corpus() {
  static const std::vector<CorpusFile> files = [] {
    std::vector<CorpusFile> out;
    const auto inputs =
        driver::CollectInputFiles({std::filesystem::path(SHADERPORT_SOURCE_DIR) / "corpus"});
    for (const auto& path : inputs.files) {
      std::ifstream in(path, std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      out.push_back({path.string(), text.str(), driver::DetectKind(text.str(), path)});
    }
    return out;
  }();
  return files;
}

void BM_FrontEnd(benchmark::State& state) {
  for (auto _ : state) {
    for (const CorpusFile& corpus : Corpus()) {
      SourceManager sources;
      const SourceFile& file = sources.Add(corpus.name, corpus.text);
      driver::FrontEndOptions options;
      options.analyze = true;
      benchmark::DoNotOptimize(driver::RunFrontEnd(file, nullptr, corpus.kind, sources, options));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(Corpus().size()));
}
BENCHMARK(BM_FrontEnd)->Unit(benchmark::kMillisecond);

void BM_GlslangValidation(benchmark::State& state) {
  for (auto _ : state) {
    for (const CorpusFile& corpus : Corpus()) {
      SourceManager sources;
      const SourceFile& file = sources.Add(corpus.name, corpus.text);
      validate::ValidationRequest request;
      if (corpus.kind.dialect == driver::Dialect::kShaderToy) {
        request = validate::ComposeShaderToyRequest(sources, corpus.kind.pass, {}, nullptr, file);
      } else {
        request.parts.push_back({file.Name(), file.Text(), file.Id(), validate::PartKind::kUser});
        request.stage = corpus.kind.stage;
      }
      benchmark::DoNotOptimize(validate::ValidateWithGlslang(request));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(Corpus().size()));
}
BENCHMARK(BM_GlslangValidation)->Unit(benchmark::kMillisecond);

}  // namespace
