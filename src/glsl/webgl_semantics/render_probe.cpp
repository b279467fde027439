// Instrumentation for the smoke render, not a browser behaviour: a second fragment
// output (location 1) whose
//  .x counts loop body executions, so a render can tell that llvmpipe's silent cap
//     of 65535 iterations per invocation was reached (the picture then is not what
//     a browser draws), and
//  .y becomes 1 where the colour output is assigned (mainImage's out parameter, or
//     the shader's single output), so a pixel that never assigns it can be told
//     from one that is really black or white;
//  .z is assigned branch conditions when arithmetic is kept in source order
//     (source_order_arithmetic.cpp); the render does not read it.
// GLSL ES 3.00 needs explicit locations with several outputs, so the probe is only
// added when the shader has exactly one output without a layout, which gets location 0.
// With probe_in_alpha (a main() that sets alpha itself and has no `return`) the probe
// is a global variable instead, and the end of main() writes it to the output's alpha
// (.x where .y is 1, -1 - .x where it is 0): one colour target, whose store llvmpipe
// compiles into every shader (gl_renderer.cpp). Mesa still keeps the conditions exact:
// a variable read into an invariant output becomes invariant, and so do the values
// assigned to it.
// Where a write cannot be marked (inside a macro), writes are not tracked (.y = 1).
// Components are written by index ([0], [1]): the user's code may `#define x`.
#include "glsl/sema/language.h"
#include "glsl/syntax/visit.h"
#include "glsl/webgl_semantics/semantics_context.h"

namespace shaderport::glsl {
namespace {

const VariableDeclaration* SingleOutput(const SyntaxTree& tree) {
  const VariableDeclaration* found = nullptr;
  for (const Node* node : tree.Root()->declarations) {
    const auto* decl = node->As<VariableDeclaration>();
    if (decl == nullptr || !decl->qualifiers.Has(QualifierKind::kOut)) continue;
    if (found != nullptr || decl->declarators.size() != 1) return nullptr;
    found = decl;
  }
  return found;
}

// The variable an lvalue-ish expression names at its root (`o.xy[1]` -> o).
uint32_t RootSymbol(const Expr* expr, const SemanticModel& model) {
  for (int depth = 0; expr != nullptr && depth < 64; ++depth) {
    if (const auto* member = expr->As<MemberExpr>()) {
      expr = member->object;
    } else if (const auto* index = expr->As<IndexExpr>()) {
      expr = index->base;
    } else if (const auto* paren = expr->As<ParenExpr>()) {
      expr = paren->inner;
    } else if (expr->kind == NodeKind::kIdentifierExpr) {
      return model.SymbolAt(expr->id);
    } else {
      return kNoSymbol;
    }
  }
  return kNoSymbol;
}

// Whether the statement or expression assigns `target` (=, op=, ++/--, or passes
// it to a call).
bool WritesTarget(const Node* code, uint32_t target, const SemanticModel& model) {
  if (code == nullptr) return false;
  bool writes = false;
  VisitPreorder(*code, [&](const Node& node, uint32_t) {
    if (const auto* assignment = node.As<AssignmentExpr>()) {
      writes = writes || RootSymbol(assignment->lhs, model) == target;
    } else if (const auto* unary = node.As<UnaryExpr>()) {
      writes = writes ||
               (unary->op >= UnaryOp::kPreIncrement && RootSymbol(unary->operand, model) == target);
    } else if (const auto* call = node.As<CallExpr>()) {
      for (const Expr* argument : call->arguments) {
        writes = writes || RootSymbol(argument, model) == target;
      }
    }
    return !writes;
  });
  return writes;
}

// The colour output the site or the page reads, and where its writes can be.
struct Target {
  uint32_t symbol = kNoSymbol;
  const Node* scope = nullptr;  // mainImage's body, or the whole tree
};

Target FindTarget(const SemanticsContext& c, const VariableDeclaration& output) {
  for (const Node* node : c.tree.Root()->declarations) {
    const auto* function = node->As<FunctionDeclaration>();
    if (function == nullptr || function->body == nullptr || function->name.text != "mainImage" ||
        function->parameters.empty() ||
        !function->parameters[0]->qualifiers.Has(QualifierKind::kOut)) {
      continue;
    }
    return {c.model.SymbolAt(function->parameters[0]->id), function->body};
  }
  return {c.model.SymbolAt(output.declarators[0]->id), c.tree.Root()};
}

// `out vec4 name;`: the only output the probe can share.
bool IsPlainVec4(const VariableDeclaration& output) {
  return output.type->name.text == "vec4" && output.type->array.empty() &&
         output.declarators[0]->array.empty();
}

// A `return` in main() would skip the alpha write at its end.
bool HasReturn(const Node& body) {
  bool found = false;
  VisitPreorder(body, [&](const Node& node, uint32_t) {
    found = found || node.kind == NodeKind::kReturnStatement;
    return !found;
  });
  return found;
}

struct PendingEdit {
  SourceRange at;
  std::string text;
};

}  // namespace

void AddRenderProbe(SemanticsContext& c, MainPrologue& prologue) {
  if (c.model.version < kEssl300) return;
  const VariableDeclaration* output = SingleOutput(c.tree);
  if (output == nullptr || output->qualifiers.Has(QualifierKind::kLayout)) return;
  const FunctionDeclaration* main = FindMainDefinition(c.tree);
  const Node* first_function = FirstFunctionDefinition(c.tree);
  const auto output_span = c.edits.Span(*output);
  const auto declare_at = first_function ? c.edits.Span(*first_function) : std::nullopt;
  if (main == nullptr || !output_span || !declare_at) return;
  const SourceRange declare = *declare_at;
  const std::string probe(kRenderProbeOutput);

  // Loops: count every body execution. Nothing is added when a loop cannot be counted.
  std::vector<PendingEdit> loop_begins, loop_ends;
  bool loops_complete = true;
  uint32_t loops = 0;
  // A float count, not an int converted at every iteration: Mesa and llvmpipe compiled
  // the AO template's render in 3 % fewer instructions. Exact to 2^24, far past the cap.
  const std::string count = " " + probe + "[0] += 1.0;";
  VisitPreorder(c.tree, [&](const Node& node, uint32_t) {
    const Node* body = nullptr;
    if (const auto* loop = node.As<ForStatement>()) body = loop->body;
    if (const auto* loop = node.As<WhileStatement>()) body = loop->body;
    if (const auto* loop = node.As<DoWhileStatement>()) body = loop->body;
    if (body == nullptr) return true;
    ++loops;
    if (const auto* compound = body->As<CompoundStatement>()) {
      const auto at = c.edits.AfterOpeningBrace(*compound);
      loops_complete = loops_complete && at.has_value();
      if (at) loop_begins.push_back({*at, count});
      return true;
    }
    const auto span = c.edits.Span(*body);
    loops_complete = loops_complete && span.has_value();
    if (span) {
      loop_begins.push_back({{span->file, span->begin, span->begin}, "{" + count + " "});
      loop_ends.push_back({{span->file, span->end, span->end}, " }"});
    }
    return true;
  });
  if (!loops_complete) return;

  // Writes of the colour output: each such statement also sets .y.
  const Target target = FindTarget(c, *output);
  std::vector<PendingEdit> write_begins, write_ends;
  bool writes_complete = target.symbol != kNoSymbol;
  if (writes_complete) {
    VisitPreorder(*target.scope, [&](const Node& node, uint32_t) {
      // A for loop whose header writes the output is marked as a whole (its init is
      // a statement that cannot be wrapped in braces).
      const Node* marked = nullptr;
      if (const auto* loop = node.As<ForStatement>()) {
        const bool header_writes = WritesTarget(loop->init, target.symbol, c.model) ||
                                   WritesTarget(loop->condition, target.symbol, c.model) ||
                                   WritesTarget(loop->increment, target.symbol, c.model);
        if (!header_writes) return true;
        marked = loop;
      } else if (const auto* statement = node.As<ExpressionStatement>()) {
        const Node* parent = c.Parent(*statement);
        if (parent != nullptr && parent->kind == NodeKind::kForStatement) {
          const auto* header = parent->As<ForStatement>();
          if (header->init == statement) return false;  // part of the header, seen above
        }
        if (!WritesTarget(statement, target.symbol, c.model)) return false;
        marked = statement;
      } else {
        return true;
      }
      const auto span = c.edits.Span(*marked);
      writes_complete = writes_complete && span.has_value();
      if (span && marked->kind == NodeKind::kForStatement) {
        write_begins.push_back(
            {{span->file, span->begin, span->begin}, "{ " + probe + "[1] = 1.0; "});
        write_ends.push_back({{span->file, span->end, span->end}, " }"});
        return true;  // writes in the body are marked too
      }
      if (span) {
        write_begins.push_back({{span->file, span->begin, span->begin}, "{ "});
        write_ends.push_back({{span->file, span->end, span->end}, " " + probe + "[1] = 1.0; }"});
      }
      return false;
    });
  }
  if (!writes_complete) write_begins.clear(), write_ends.clear();

  // At one offset a loop's brace opens before a write's and closes after it.
  for (auto* list : {&loop_begins, &write_begins, &write_ends, &loop_ends}) {
    for (PendingEdit& edit : *list) c.edits.Insert(edit.at.file, edit.at.begin, edit.text);
  }
  const bool exact = c.options.source_order_arithmetic;
  if (exact) ExposeBranchConditions(c, probe);
  const std::string initial =
      "vec4(0.0, " + std::string(writes_complete ? "0.0" : "1.0") + ", 0.0, 0.0)";
  const auto main_end = c.options.probe_in_alpha && IsPlainVec4(*output) && !HasReturn(*main->body)
                            ? c.edits.BeforeClosingBrace(*main->body)
                            : std::nullopt;
  if (main_end) {
    const std::string alpha = output->declarators[0]->name.text + "[3]";
    c.edits.Insert(declare.file, declare.begin, "highp vec4 " + probe + " = " + initial + "; ");
    c.edits.Insert(
        main_end->file, main_end->begin,
        alpha + " = " + probe + "[1] != 0.0 ? " + probe + "[0] : -1.0 - " + probe + "[0]; ");
    c.result.probe_in_alpha = true;
  } else {
    c.edits.Insert(output_span->file, output_span->begin, "layout(location = 0) ");
    c.edits.Insert(declare.file, declare.begin,
                   std::string(exact ? "invariant " : "") + "layout(location = 1) out highp vec4 " +
                       probe + "; ");
    prologue.statements.push_back(probe + " = " + initial + ";");
  }
  c.result.counted_loops = loops;
  c.result.tracks_output_writes = writes_complete;
  c.result.render_probe = true;
}

}  // namespace shaderport::glsl
