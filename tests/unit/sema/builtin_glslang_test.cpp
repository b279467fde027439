// Cross-checks the built-in tables against glslang: for every overload, in ESSL 1.00 and 3.00
// and in both stages, a shader calling it with the right argument types must compile exactly
// when the table says the overload is available, and a copy with one argument of another type
// must compile exactly when the table's overload resolution finds a match.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "glsl/sema/builtins.h"
#include "glsl/sema/overload_resolution.h"
#include "glsl/sema/struct_table.h"
#include "glslang_oracle.h"

namespace shaderport::glsl {
namespace {

using testing::CompileWithGlslang;

struct Combo {
  int version;
  model::Stage stage;
};
constexpr Combo kCombos[] = {{100, model::Stage::kVertex},
                             {100, model::Stage::kFragment},
                             {300, model::Stage::kVertex},
                             {300, model::Stage::kFragment}};

std::string Header(int version, std::string_view extension) {
  std::string s;
  if (version == 300) s += "#version 300 es\n";
  if (version == 100 && !extension.empty()) {
    s += "#extension " + std::string(extension) + " : enable\n";
  }
  s += "precision highp float;\nprecision highp int;\n";
  return s;
}

// A value of `type` to initialise a local with.
std::string ValueOf(const Type& type) { return Spell(type) + "(1)"; }

// A type of another kind than `type`, with the same shape where possible.
Type Mutate(const Type& type) {
  if (type.IsMatrix()) return Type::Vector(BaseType::kFloat, type.rows);
  switch (type.base) {
    case BaseType::kFloat:
      return Type::Vector(BaseType::kInt, type.rows);
    case BaseType::kInt:
      return Type::Vector(BaseType::kFloat, type.rows);
    case BaseType::kUint:
      return Type::Vector(BaseType::kInt, type.rows);
    default:
      return Type::Vector(BaseType::kFloat, type.rows);
  }
}

// A shader calling `f` with locals of `arg_types`, assigning the result to `result`.
std::string CallShader(const BuiltinFunction& f, const std::vector<Type>& arg_types,
                       const Type& result, int version, std::string_view extension) {
  std::string globals, locals, call = f.name + "(";
  for (size_t i = 0; i < arg_types.size(); ++i) {
    const Type& t = arg_types[i];
    std::string name = "a" + std::to_string(i);
    if (t.IsSampler()) {
      globals += "uniform highp " + Spell(t) + " " + name + ";\n";
    } else if (f.params[i].qualifier != ParamQualifier::kIn) {
      locals += "  " + Spell(t) + " " + name + ";\n";
    } else {
      locals += std::string("  ") + (f.params[i].must_be_constant ? "const " : "") + Spell(t) +
                " " + name + " = " + ValueOf(t) + ";\n";
    }
    call += (i ? ", " : "") + name;
  }
  return Header(version, extension) + globals + "void main() {\n" + locals + "  " + Spell(result) +
         " r = " + call + ");\n}\n";
}

struct Tally {
  int agree = 0;
  std::vector<std::string> disagreements;
  void Check(bool expected, const std::string& shader, model::Stage stage,
             const std::string& what) {
    testing::GlslangResult r = CompileWithGlslang(shader, stage);
    if (r.ok == expected) {
      ++agree;
    } else {
      disagreements.push_back(what + (expected ? " (table: valid)" : " (table: invalid)") + "\n" +
                              shader + r.log);
    }
  }
};

std::string Describe(const BuiltinFunction& f, const std::vector<Type>& args, const Combo& c) {
  std::string s = Spell(f.return_type) + " " + f.name + "(";
  for (size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + Spell(args[i]);
  return s + ") in ESSL " + std::to_string(c.version) +
         (c.stage == model::Stage::kVertex ? " vertex" : " fragment");
}

// The overload our resolution picks among the available ones, else nullptr.
const BuiltinFunction* StrictlyResolve(const BuiltinFunction& f, const std::vector<Type>& args,
                                       const Combo& c) {
  BuiltinCallMatch m = ResolveBuiltinCall(f.name, args, c.version, c.stage);
  if (m.function == nullptr || !m.available || m.uncertain) return nullptr;
  return m.function;
}

// Where glslang 12 and the table knowingly differ. The EXT_shader_texture_lod spec adds its
// functions to fragment shaders only (as ANGLE, the WebGL reference, does); glslang also
// accepts the Grad forms in vertex shaders.
bool IsKnownGlslangQuirk(const BuiltinFunction& f, const Combo& c) {
  return c.version == 100 && c.stage == model::Stage::kVertex && f.name.ends_with("GradEXT");
}

TEST(BuiltinGlslangTest, FunctionsAgreeWithGlslang) {
  Tally tally;
  int quirks = 0;
  for (const BuiltinFunction& f : AllBuiltinFunctions()) {
    std::vector<Type> args;
    for (const BuiltinParam& p : f.params) args.push_back(p.type);
    for (const Combo& c : kCombos) {
      // Right types: valid exactly when some overload with these types is available.
      const BuiltinFunction* picked = StrictlyResolve(f, args, c);
      std::string_view extension = picked != nullptr ? picked->extension : f.extension;
      std::string shader = CallShader(f, args, f.return_type, c.version, extension);
      if (IsKnownGlslangQuirk(f, c)) {
        quirks += CompileWithGlslang(shader, c.stage).ok != (picked != nullptr);
        continue;
      }
      tally.Check(picked != nullptr, shader, c.stage, "call " + Describe(f, args, c));
      // ESSL 1.00 extension functions need their #extension.
      if (c.version == 100 && !f.extension.empty() && f.AvailableIn(c.version, c.stage)) {
        tally.Check(false, CallShader(f, args, f.return_type, c.version, ""), c.stage,
                    "call without extension " + Describe(f, args, c));
      }
      if (!f.AvailableIn(c.version, c.stage)) continue;
      // One argument of another type: valid exactly when our resolution finds a match.
      for (size_t i = 0; i < args.size(); ++i) {
        if (args[i].IsSampler() || f.params[i].qualifier != ParamQualifier::kIn) continue;
        std::vector<Type> mutated = args;
        mutated[i] = Mutate(args[i]);
        if (!BuiltinTypeAvailable(mutated[i], c.version)) continue;
        const BuiltinFunction* other = StrictlyResolve(f, mutated, c);
        Type result = other != nullptr ? other->return_type : f.return_type;
        tally.Check(other != nullptr, CallShader(f, mutated, result, c.version, f.extension),
                    c.stage, "mutated call " + Describe(f, mutated, c));
        break;
      }
    }
  }
  std::cout << "[ glslang  ] built-in function checks: " << tally.agree << " agree, "
            << tally.disagreements.size() << " disagree, " << quirks << " known glslang quirks\n";
  for (size_t i = 0; i < tally.disagreements.size() && i < 20; ++i) {
    ADD_FAILURE() << tally.disagreements[i];
  }
  EXPECT_EQ(quirks, 4);  // the four *GradEXT overloads in ESSL 1.00 vertex shaders
  EXPECT_GT(tally.agree, 4000);
  EXPECT_EQ(tally.disagreements.size(), 0u);
}

TEST(BuiltinGlslangTest, VariablesAgreeWithGlslang) {
  Tally tally;
  StructTable structs;
  for (const BuiltinVariable& v : AllBuiltinVariables()) {
    Type element = v.type.Element();
    std::string read = v.name + (v.type.IsArray() ? "[0]" : "");
    for (const Combo& c : kCombos) {
      const BuiltinVariable* found = FindBuiltinVariable(v.name, c.version, c.stage);
      bool valid = found != nullptr && found->type == v.type;
      std::string body = "void main() {\n  " + Spell(element, &structs) + " r = " + read + ";\n}\n";
      tally.Check(valid, Header(c.version, v.extension) + body, c.stage,
                  v.name + " in ESSL " + std::to_string(c.version));
      if (!valid) continue;
      if (!v.extension.empty()) {
        tally.Check(false, Header(c.version, "") + body, c.stage,
                    v.name + " without extension in ESSL " + std::to_string(c.version));
      }
      Type other = element.IsStruct() ? Type::Float() : Mutate(element);
      tally.Check(false,
                  Header(c.version, v.extension) + "void main() {\n  " + Spell(other) +
                      " r = " + read + ";\n}\n",
                  c.stage, v.name + " as " + Spell(other));
    }
  }
  std::cout << "[ glslang  ] built-in variable checks: " << tally.agree << " agree, "
            << tally.disagreements.size() << " disagree\n";
  for (size_t i = 0; i < tally.disagreements.size() && i < 20; ++i) {
    ADD_FAILURE() << tally.disagreements[i];
  }
  EXPECT_GT(tally.agree, 100);
  EXPECT_EQ(tally.disagreements.size(), 0u);
}

}  // namespace
}  // namespace shaderport::glsl
