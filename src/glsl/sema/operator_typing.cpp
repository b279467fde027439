#include "glsl/sema/operator_typing.h"

namespace shaderport::glsl {
namespace {

bool IsNumericValue(const Type& t) { return t.IsNumeric() && !t.IsSampler() && !t.IsStruct(); }

// + - / % and the bitwise operators: same types, or a scalar with a vector/matrix of its base.
Type ComponentWise(const Type& lhs, const Type& rhs) {
  if (lhs == rhs) return lhs;
  if (lhs.base != rhs.base) return Type::Unknown();
  if (lhs.IsScalar()) return rhs;
  if (rhs.IsScalar()) return lhs;
  return Type::Unknown();
}

Type Multiply(const Type& lhs, const Type& rhs) {
  if (lhs.IsMatrix() && rhs.IsMatrix()) {
    if (lhs.columns != rhs.rows) return Type::Unknown();
    return Type::Matrix(rhs.columns, lhs.rows);
  }
  if (lhs.IsMatrix() && rhs.IsVector() && rhs.base == BaseType::kFloat) {
    return lhs.columns == rhs.rows ? Type::Vector(BaseType::kFloat, lhs.rows) : Type::Unknown();
  }
  if (lhs.IsVector() && lhs.base == BaseType::kFloat && rhs.IsMatrix()) {
    return lhs.rows == rhs.rows ? Type::Vector(BaseType::kFloat, rhs.columns) : Type::Unknown();
  }
  return ComponentWise(lhs, rhs);
}

}  // namespace

Type UnaryResultType(UnaryOp op, const Type& operand) {
  if (operand.IsUnknown()) return Type::Unknown();
  switch (op) {
    case UnaryOp::kPlus:
    case UnaryOp::kMinus:
    case UnaryOp::kPreIncrement:
    case UnaryOp::kPreDecrement:
    case UnaryOp::kPostIncrement:
    case UnaryOp::kPostDecrement:
      return IsNumericValue(operand) ? operand : Type::Unknown();
    case UnaryOp::kNot:
      return operand == Type::Bool() ? operand : Type::Unknown();
    case UnaryOp::kBitNot:
      return operand.IsIntegral() ? operand : Type::Unknown();
  }
  return Type::Unknown();
}

Type BinaryResultType(BinaryOp op, const Type& lhs, const Type& rhs) {
  if (op == BinaryOp::kComma) return rhs;
  if (lhs.IsUnknown() || rhs.IsUnknown()) return Type::Unknown();
  switch (op) {
    case BinaryOp::kAdd:
    case BinaryOp::kSub:
    case BinaryOp::kDiv:
      if (!IsNumericValue(lhs) || !IsNumericValue(rhs)) return Type::Unknown();
      return ComponentWise(lhs, rhs);
    case BinaryOp::kMul:
      if (!IsNumericValue(lhs) || !IsNumericValue(rhs)) return Type::Unknown();
      return Multiply(lhs, rhs);
    case BinaryOp::kMod:
    case BinaryOp::kBitAnd:
    case BinaryOp::kBitXor:
    case BinaryOp::kBitOr:
      if (!lhs.IsIntegral() || !rhs.IsIntegral()) return Type::Unknown();
      return ComponentWise(lhs, rhs);
    case BinaryOp::kShl:
    case BinaryOp::kShr:
      // The operands' bases may differ (int << uint); a vector shifts by a scalar or a vector of
      // its size, a scalar only by a scalar.
      if (!lhs.IsIntegral() || !rhs.IsIntegral()) return Type::Unknown();
      if (rhs.IsScalar() || rhs.rows == lhs.rows) return lhs;
      return Type::Unknown();
    case BinaryOp::kLess:
    case BinaryOp::kGreater:
    case BinaryOp::kLessEqual:
    case BinaryOp::kGreaterEqual:
      return lhs == rhs && lhs.IsScalar() && IsNumericValue(lhs) ? Type::Bool() : Type::Unknown();
    case BinaryOp::kEqual:
    case BinaryOp::kNotEqual:
      return lhs == rhs && !lhs.IsSampler() && !lhs.IsVoid() ? Type::Bool() : Type::Unknown();
    case BinaryOp::kLogicalAnd:
    case BinaryOp::kLogicalXor:
    case BinaryOp::kLogicalOr:
      return lhs == Type::Bool() && rhs == Type::Bool() ? Type::Bool() : Type::Unknown();
    case BinaryOp::kComma:
      return rhs;
  }
  return Type::Unknown();
}

bool CompoundAssignOperator(AssignOp op, BinaryOp& binary) {
  switch (op) {
    case AssignOp::kAssign:
      return false;
    case AssignOp::kMul:
      binary = BinaryOp::kMul;
      return true;
    case AssignOp::kDiv:
      binary = BinaryOp::kDiv;
      return true;
    case AssignOp::kMod:
      binary = BinaryOp::kMod;
      return true;
    case AssignOp::kAdd:
      binary = BinaryOp::kAdd;
      return true;
    case AssignOp::kSub:
      binary = BinaryOp::kSub;
      return true;
    case AssignOp::kShl:
      binary = BinaryOp::kShl;
      return true;
    case AssignOp::kShr:
      binary = BinaryOp::kShr;
      return true;
    case AssignOp::kBitAnd:
      binary = BinaryOp::kBitAnd;
      return true;
    case AssignOp::kBitXor:
      binary = BinaryOp::kBitXor;
      return true;
    case AssignOp::kBitOr:
      binary = BinaryOp::kBitOr;
      return true;
  }
  return false;
}

Type SwizzleType(const Type& object, std::string_view swizzle) {
  if (!object.IsVector() || swizzle.empty() || swizzle.size() > 4) return Type::Unknown();
  static constexpr std::string_view kSets[] = {"xyzw", "rgba", "stpq"};
  for (std::string_view set : kSets) {
    bool ok = true;
    for (char c : swizzle) {
      size_t index = set.find(c);
      if (index == std::string_view::npos || index >= object.rows) {
        ok = false;
        break;
      }
    }
    if (ok) return Type::Vector(object.base, static_cast<int>(swizzle.size()));
  }
  return Type::Unknown();
}

Type IndexResultType(const Type& base) {
  if (base.IsArray()) return base.Element();
  if (base.IsMatrix()) return base.Column();
  if (base.IsVector()) return base.Component();
  return Type::Unknown();
}

Type IntToFloat(const Type& type) {
  if (type.IsArray() || type.base != BaseType::kInt || type.columns != 1) return Type::Unknown();
  return Type::Vector(BaseType::kFloat, type.rows);
}

}  // namespace shaderport::glsl
