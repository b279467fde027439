// Tree walks over one long expression `a+a+...+a` of N terms (a left-nested chain N
// deep): each must take time linear in N. `dump --types` read every sub-expression's
// whole text and took minutes at 400,000 terms (issue 31). Run:
//   build/bench/bench/tree_walk_bench
// and read the BigO line of each benchmark: "N" (linear) is the promise; a quadratic
// walk shows as "N^2" and as ~16x the time per step of 4x in N.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "driver/dialect.h"
#include "driver/front_end.h"
#include "glsl/sema/semantic_model.h"
#include "glsl/syntax/parser.h"

namespace {

using namespace shaderport;

std::string ChainShader(int64_t terms) {
  std::string text = "void mainImage(out vec4 c, in vec2 p) {\n  float a = p.x;\n  float x = a";
  text.reserve(text.size() + static_cast<size_t>(terms) * 2 + 64);
  for (int64_t i = 1; i < terms; ++i) text += "+a";
  return text + ";\n  c = vec4(x);\n}\n";
}

// One analysed chain shader per N, made outside the timed loop.
struct Analysed {
  SourceManager sources;
  const SourceFile* file = nullptr;
  driver::FrontEndResult front;
};

std::unique_ptr<Analysed> Analyse(int64_t terms) {
  auto analysed = std::make_unique<Analysed>();
  analysed->file = &analysed->sources.Add("chain.glsl", ChainShader(terms));
  driver::DetectedKind kind;
  kind.dialect = driver::Dialect::kShaderToy;
  driver::FrontEndOptions options;
  options.analyze = true;
  analysed->front = driver::RunFrontEnd(*analysed->file, nullptr, kind, analysed->sources, options);
  return analysed;
}

void BM_FrontEnd(benchmark::State& state) {
  SourceManager sources;
  const SourceFile& file = sources.Add("chain.glsl", ChainShader(state.range(0)));
  driver::DetectedKind kind;
  kind.dialect = driver::Dialect::kShaderToy;
  driver::FrontEndOptions options;
  options.analyze = true;
  for (auto _ : state) {
    benchmark::DoNotOptimize(driver::RunFrontEnd(file, nullptr, kind, sources, options));
  }
  state.SetComplexityN(state.range(0));
}

void BM_DumpTypes(benchmark::State& state) {
  const auto analysed = Analyse(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        glsl::DumpTypes(analysed->front.parsed.tree, *analysed->front.model, analysed->sources));
  }
  state.SetComplexityN(state.range(0));
}

void BM_DumpAst(benchmark::State& state) {
  const auto analysed = Analyse(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(glsl::DumpAst(analysed->front.parsed.tree, analysed->sources));
  }
  state.SetComplexityN(state.range(0));
}

// 25,000 to 400,000 terms in steps of 4x (400,000 is the case of issue 31).
void Sizes(benchmark::internal::Benchmark* bench) {
  bench->RangeMultiplier(4)->Range(25'000, 400'000)->Unit(benchmark::kMillisecond);
  bench->Complexity(benchmark::oN);
}

BENCHMARK(BM_FrontEnd)->Apply(Sizes);
BENCHMARK(BM_DumpTypes)->Apply(Sizes);
BENCHMARK(BM_DumpAst)->Apply(Sizes);

}  // namespace
