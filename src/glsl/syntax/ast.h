// The GLSL ES 1.00 / 3.00 syntax tree: node kinds, node structs and the arena
// (SyntaxTree) that owns them. Built by Parse() (parser.h); read by sema and rules.
#pragma once

#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "glsl/syntax/node_arena.h"
#include "source/source_file.h"

namespace shaderport::glsl {

/// Every node kind. Declarations may appear wherever a statement may.
enum class NodeKind : uint8_t {
  kTranslationUnit,
  // Types and declarations.
  kTypeSpecifier,         // TypeSpecifier: `highp vec3`, `S`, `float[3]`, `struct {...}`
  kStructSpecifier,       // StructSpecifier: `struct S { float a; }`
  kVariableDeclaration,   // VariableDeclaration: `const float a = 1.0, b[2];`, `struct S {...};`
  kDeclarator,            // Declarator: one name of a declaration, `b[2] = ...`
  kQualifierDeclaration,  // QualifierDeclaration: `invariant gl_Position;`, `layout(std140)
                          // uniform;`
  kPrecisionDeclaration,  // PrecisionDeclaration: `precision mediump float;`
  kInterfaceBlock,        // InterfaceBlock: `uniform B { vec4 v; } b[2];`
  kFunctionDeclaration,   // FunctionDeclaration: prototype or definition
  kParameterDeclaration,  // ParameterDeclaration: `in highp vec2 p[2]`
  // Statements.
  kCompoundStatement,
  kExpressionStatement,
  kIfStatement,
  kForStatement,
  kWhileStatement,
  kDoWhileStatement,
  kSwitchStatement,
  kCaseLabel,  // `case 1:` or `default:` (value == nullptr)
  kBreakStatement,
  kContinueStatement,
  kReturnStatement,
  kDiscardStatement,
  kEmptyStatement,
  kErrorStatement,  // tokens skipped by error recovery at declaration/statement level
  // Expressions (all derive from Expr).
  kIdentifierExpr,
  kLiteralExpr,
  kParenExpr,
  kUnaryExpr,   // prefix and postfix, see UnaryOp
  kBinaryExpr,  // includes the comma operator
  kAssignmentExpr,
  kConditionalExpr,
  kCallExpr,    // function call, constructor (incl. `float[3](...)`) or `x.length()`
  kMemberExpr,  // `.name`: struct field or swizzle, sema decides
  kIndexExpr,
  kErrorExpr,  // a missing or unparsable expression
};

/// Tree height: recursion in the parser is bounded by limits::kBrowserParserStack, but
/// left-associative chains (`a+b+c+...`, `a.x.y[0]...`) build trees of any height
/// iteratively; valid WebGL shaders have chains of thousands of operators. Walk
/// trees with VisitPreorder/VisitPostorder (visit.h), not with unbounded recursion.

/// Stable lower-case name of a kind ("binary-expr"), used by DumpAst.
const char* NodeKindName(NodeKind kind);

/// Base of every node. Ids are dense (0..N-1 in creation order) so side tables
/// can be vectors indexed by id. Not polymorphic: the tree destroys each node as
/// the type it made it with (SyntaxTree::Make), never through a Node*.
struct Node {
  explicit Node(NodeKind k) : kind(k) {}
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  NodeKind kind;
  uint32_t id = 0;
  /// From the expansion begin of the first token to the expansion end of the last.
  /// When the tokens span files (a translation unit over Common + pass), it covers
  /// only the tokens in the first token's file. Empty for nodes with no tokens
  /// (an ErrorExpr for a missing operand), placed at the next token.
  SourceRange range;
  /// Indices into PreprocessResult::tokens, inclusive. A node with no tokens has
  /// last_token == first_token - 1 (wrapping): see HasTokens().
  uint32_t first_token = 0;
  uint32_t last_token = 0;

  bool HasTokens() const { return last_token + 1 != first_token; }

  bool IsExpr() const { return kind >= NodeKind::kIdentifierExpr; }

  /// Checked downcast: nullptr when the kind does not match (no RTTI needed).
  template <class T>
  T* As() {
    return T::Matches(kind) ? static_cast<T*>(this) : nullptr;
  }
  template <class T>
  const T* As() const {
    return T::Matches(kind) ? static_cast<const T*>(this) : nullptr;
  }

 protected:
  ~Node() = default;
};

/// A name as written, with the range of its token.
struct Name {
  std::string text;  // empty when absent
  SourceRange range;
  bool Empty() const { return text.empty(); }
};

// ---------------------------------------------------------------- expressions

struct Expr : Node {
  using Node::Node;
  static bool Matches(NodeKind k) { return k >= NodeKind::kIdentifierExpr; }
};

#define SHADERPORT_NODE(Type, Base, Kind) \
  Type() : Base(NodeKind::Kind) {}        \
  static bool Matches(NodeKind k) { return k == NodeKind::Kind; }

struct IdentifierExpr : Expr {
  SHADERPORT_NODE(IdentifierExpr, Expr, kIdentifierExpr)
  std::string name;
};

enum class LiteralKind : uint8_t { kInt, kUint, kFloat, kBool };

struct LiteralExpr : Expr {
  SHADERPORT_NODE(LiteralExpr, Expr, kLiteralExpr)
  LiteralKind literal_kind = LiteralKind::kInt;
  std::string text;           // as written, e.g. "0x1Fu", "1.5e3", "true"
  uint64_t int_value = 0;     // kInt / kUint (the integer as written; wraps are sema's business)
  bool int_overflow = false;  // the value does not fit in 32 bits
  double float_value = 0.0;   // kFloat
  bool bool_value = false;    // kBool
};

struct ParenExpr : Expr {
  SHADERPORT_NODE(ParenExpr, Expr, kParenExpr)
  Expr* inner = nullptr;
};

enum class UnaryOp : uint8_t {
  kPlus,
  kMinus,
  kNot,
  kBitNot,
  kPreIncrement,
  kPreDecrement,
  kPostIncrement,
  kPostDecrement,
};
const char* UnaryOpSpelling(UnaryOp op);  // "-", "++" ...

struct UnaryExpr : Expr {
  SHADERPORT_NODE(UnaryExpr, Expr, kUnaryExpr)
  UnaryOp op = UnaryOp::kPlus;
  Expr* operand = nullptr;
  SourceRange op_range;
};

enum class BinaryOp : uint8_t {
  kMul,
  kDiv,
  kMod,
  kAdd,
  kSub,
  kShl,
  kShr,
  kLess,
  kGreater,
  kLessEqual,
  kGreaterEqual,
  kEqual,
  kNotEqual,
  kBitAnd,
  kBitXor,
  kBitOr,
  kLogicalAnd,
  kLogicalXor,
  kLogicalOr,
  kComma,
};
const char* BinaryOpSpelling(BinaryOp op);  // "*", "&&", "," ...

struct BinaryExpr : Expr {
  SHADERPORT_NODE(BinaryExpr, Expr, kBinaryExpr)
  BinaryOp op = BinaryOp::kAdd;
  Expr* lhs = nullptr;
  Expr* rhs = nullptr;
  SourceRange op_range;
};

enum class AssignOp : uint8_t {
  kAssign,
  kMul,
  kDiv,
  kMod,
  kAdd,
  kSub,
  kShl,
  kShr,
  kBitAnd,
  kBitXor,
  kBitOr,
};
const char* AssignOpSpelling(AssignOp op);  // "=", "+=" ...

struct AssignmentExpr : Expr {
  SHADERPORT_NODE(AssignmentExpr, Expr, kAssignmentExpr)
  AssignOp op = AssignOp::kAssign;
  Expr* lhs = nullptr;
  Expr* rhs = nullptr;
  SourceRange op_range;
};

struct ConditionalExpr : Expr {
  SHADERPORT_NODE(ConditionalExpr, Expr, kConditionalExpr)
  Expr* condition = nullptr;
  Expr* if_true = nullptr;
  Expr* if_false = nullptr;
};

struct TypeSpecifier;

enum class CallKind : uint8_t {
  kFunction,     // `f(x)`: `callee` holds the name
  kConstructor,  // `vec3(1.0)`, `S(1.0)`, `float[2](a, b)`: `constructor_type` holds the type
  kMethod,       // `a.length()`: `object` and `callee`
};

struct CallExpr : Expr {
  SHADERPORT_NODE(CallExpr, Expr, kCallExpr)
  CallKind call_kind = CallKind::kFunction;
  Name callee;                                // function or method name (also set for constructors)
  TypeSpecifier* constructor_type = nullptr;  // kConstructor only
  Expr* object = nullptr;                     // kMethod only
  std::vector<Expr*> arguments;
  bool void_argument = false;  // written `f(void)`
};

struct MemberExpr : Expr {
  SHADERPORT_NODE(MemberExpr, Expr, kMemberExpr)
  Expr* object = nullptr;
  Name member;  // field name or swizzle ("xyz")
};

struct IndexExpr : Expr {
  SHADERPORT_NODE(IndexExpr, Expr, kIndexExpr)
  Expr* base = nullptr;
  Expr* index = nullptr;  // never null after parsing (an ErrorExpr when missing)
};

struct ErrorExpr : Expr {
  SHADERPORT_NODE(ErrorExpr, Expr, kErrorExpr)
};

// ------------------------------------------------------- types and qualifiers

enum class Precision : uint8_t { kNone, kLow, kMedium, kHigh };
const char* PrecisionSpelling(Precision p);  // "", "lowp", "mediump", "highp"

enum class QualifierKind : uint8_t {
  kConst,
  kIn,
  kOut,
  kInOut,
  kUniform,
  kAttribute,
  kVarying,
  kCentroid,
  kFlat,
  kSmooth,
  kInvariant,
  kLayout,
  kPrecision,  // lowp/mediump/highp: also copied to TypeSpecifier::precision
};
const char* QualifierSpelling(
    QualifierKind kind);  // "const", "layout", ... ("precision" for kPrecision)

/// `name` or `name = value` inside `layout(...)`.
struct LayoutId {
  Name name;
  Expr* value = nullptr;
};

/// One qualifier as written, in source order.
struct Qualifier {
  QualifierKind kind = QualifierKind::kConst;
  Precision precision = Precision::kNone;  // kPrecision only
  SourceRange range;                       // the keyword; for layout, `layout(...)` whole
  std::vector<LayoutId> layout_ids;        // kLayout only
};

struct QualifierList {
  std::vector<Qualifier> items;
  bool Has(QualifierKind kind) const {
    for (const auto& q : items) {
      if (q.kind == kind) return true;
    }
    return false;
  }
  bool Empty() const { return items.empty(); }
};

/// One `[size]` of an array: size == nullptr for `[]`.
struct ArrayDimension {
  Expr* size = nullptr;
  SourceRange range;  // from '[' to ']'
};

enum class TypeNameKind : uint8_t {
  kBuiltin,  // a type keyword of the language version (`float`, `sampler2D`, `void`)
  kStruct,   // a struct declared earlier, or declared right here (`struct_def`)
  kUnknown,  // an identifier used in type position that names no known type
};

struct StructSpecifier;

/// The type part of a declaration, parameter, return type or constructor.
/// Precision written among the qualifiers lands here; so do `float[3]` sizes.
struct TypeSpecifier : Node {
  SHADERPORT_NODE(TypeSpecifier, Node, kTypeSpecifier)
  Name name;  // "vec3", "S"; the struct's name (maybe empty) for a struct_def
  TypeNameKind name_kind = TypeNameKind::kBuiltin;
  Precision precision = Precision::kNone;
  StructSpecifier* struct_def = nullptr;  // `struct S { ... }` written in place
  std::vector<ArrayDimension> array;      // `float[3]`: dimensions written on the type
};

struct VariableDeclaration;

struct StructSpecifier : Node {
  SHADERPORT_NODE(StructSpecifier, Node, kStructSpecifier)
  Name name;  // empty for an anonymous struct
  std::vector<VariableDeclaration*> fields;
};

// ---------------------------------------------------------------- declarations

struct Declarator : Node {
  SHADERPORT_NODE(Declarator, Node, kDeclarator)
  Name name;
  std::vector<ArrayDimension> array;  // `a[2]`
  Expr* initializer = nullptr;
};

/// `qualifiers type declarators;` Also struct fields (no qualifiers except
/// precision) and a bare struct definition (`struct S {...};`, no declarators).
struct VariableDeclaration : Node {
  SHADERPORT_NODE(VariableDeclaration, Node, kVariableDeclaration)
  QualifierList qualifiers;
  TypeSpecifier* type = nullptr;  // never null after parsing
  std::vector<Declarator*> declarators;
};

/// Qualifiers alone: `invariant gl_Position, v;` or `layout(std140) uniform;`.
struct QualifierDeclaration : Node {
  SHADERPORT_NODE(QualifierDeclaration, Node, kQualifierDeclaration)
  QualifierList qualifiers;
  std::vector<Name> names;
};

struct PrecisionDeclaration : Node {
  SHADERPORT_NODE(PrecisionDeclaration, Node, kPrecisionDeclaration)
  Precision precision = Precision::kNone;
  TypeSpecifier* type = nullptr;
};

/// `uniform Block { members } instance[N];` (ESSL 3.00).
struct InterfaceBlock : Node {
  SHADERPORT_NODE(InterfaceBlock, Node, kInterfaceBlock)
  QualifierList qualifiers;
  Name block_name;
  std::vector<VariableDeclaration*> members;
  Name instance_name;  // empty when none
  std::vector<ArrayDimension> instance_array;
};

struct ParameterDeclaration : Node {
  SHADERPORT_NODE(ParameterDeclaration, Node, kParameterDeclaration)
  QualifierList qualifiers;
  TypeSpecifier* type = nullptr;
  Name name;  // empty for an unnamed parameter
  std::vector<ArrayDimension> array;
};

struct CompoundStatement;

struct FunctionDeclaration : Node {
  SHADERPORT_NODE(FunctionDeclaration, Node, kFunctionDeclaration)
  QualifierList qualifiers;  // on the return type (usually only precision)
  TypeSpecifier* return_type = nullptr;
  Name name;
  std::vector<ParameterDeclaration*> parameters;  // a lone `(void)` gives none
  bool void_parameter = false;                    // written `f(void)`
  CompoundStatement* body = nullptr;              // nullptr for a prototype
};

// ------------------------------------------------------------------ statements

struct CompoundStatement : Node {
  SHADERPORT_NODE(CompoundStatement, Node, kCompoundStatement)
  std::vector<Node*> statements;  // statements and declarations, in order
};

struct ExpressionStatement : Node {
  SHADERPORT_NODE(ExpressionStatement, Node, kExpressionStatement)
  Expr* expression = nullptr;
};

struct IfStatement : Node {
  SHADERPORT_NODE(IfStatement, Node, kIfStatement)
  Expr* condition = nullptr;
  Node* then_branch = nullptr;
  Node* else_branch = nullptr;  // nullptr without else
};

/// `for (init; condition; increment) body`. `init` is a VariableDeclaration,
/// an ExpressionStatement or an EmptyStatement; `condition` is an Expr or a
/// VariableDeclaration (`bool b = f()`), or nullptr; `increment` may be nullptr.
struct ForStatement : Node {
  SHADERPORT_NODE(ForStatement, Node, kForStatement)
  Node* init = nullptr;
  Node* condition = nullptr;
  Expr* increment = nullptr;
  Node* body = nullptr;
};

/// `condition` is an Expr or a VariableDeclaration.
struct WhileStatement : Node {
  SHADERPORT_NODE(WhileStatement, Node, kWhileStatement)
  Node* condition = nullptr;
  Node* body = nullptr;
};

struct DoWhileStatement : Node {
  SHADERPORT_NODE(DoWhileStatement, Node, kDoWhileStatement)
  Node* body = nullptr;
  Expr* condition = nullptr;
};

/// The body's statements include the CaseLabels as ordinary statements.
struct SwitchStatement : Node {
  SHADERPORT_NODE(SwitchStatement, Node, kSwitchStatement)
  Expr* selector = nullptr;
  CompoundStatement* body = nullptr;
};

struct CaseLabel : Node {
  SHADERPORT_NODE(CaseLabel, Node, kCaseLabel)
  Expr* value = nullptr;  // nullptr for `default:`
};

struct BreakStatement : Node {
  SHADERPORT_NODE(BreakStatement, Node, kBreakStatement)
};
struct ContinueStatement : Node {
  SHADERPORT_NODE(ContinueStatement, Node, kContinueStatement)
};
struct DiscardStatement : Node {
  SHADERPORT_NODE(DiscardStatement, Node, kDiscardStatement)
};
struct EmptyStatement : Node {
  SHADERPORT_NODE(EmptyStatement, Node, kEmptyStatement)
};
struct ReturnStatement : Node {
  SHADERPORT_NODE(ReturnStatement, Node, kReturnStatement)
  Expr* value = nullptr;
};
struct ErrorStatement : Node {
  SHADERPORT_NODE(ErrorStatement, Node, kErrorStatement)
};

struct TranslationUnit : Node {
  SHADERPORT_NODE(TranslationUnit, Node, kTranslationUnit)
  std::vector<Node*> declarations;  // external declarations (and ErrorStatements)
};

#undef SHADERPORT_NODE

// ------------------------------------------------------------------- the tree

/// One node of a tree's preorder (SyntaxTree::Preorder).
struct PreorderEntry {
  const Node* node = nullptr;
  uint32_t depth = 0;  // the root's is 0
  uint32_t end = 0;    // index in the preorder just past the node's subtree
};

/// Owns every node. Nodes never move; pointers stay valid for the tree's life.
/// Nodes live in an arena of the tree's own (a tree has thousands of small nodes:
/// one heap block each made malloc and free a tenth of `check`); destroying the
/// tree runs the destructors of the nodes that have any (names, child vectors),
/// then releases the arena's few blocks at once.
class SyntaxTree {
 public:
  SyntaxTree() = default;
  SyntaxTree(SyntaxTree&& other) noexcept { *this = std::move(other); }
  SyntaxTree& operator=(SyntaxTree&& other) noexcept;
  SyntaxTree(const SyntaxTree&) = delete;
  SyntaxTree& operator=(const SyntaxTree&) = delete;
  ~SyntaxTree() { DestroyNodes(); }

  /// The root; nullptr only for a default-constructed tree.
  const TranslationUnit* Root() const { return root_; }
  TranslationUnit* Root() { return root_; }
  void SetRoot(TranslationUnit* root) { root_ = root; }

  uint32_t NodeCount() const { return static_cast<uint32_t>(nodes_.size()); }
  const Node& NodeAt(uint32_t id) const { return *nodes_[id]; }
  Node& NodeAt(uint32_t id) { return *nodes_[id]; }
  /// Room for `count` nodes without growing the node table.
  void Reserve(size_t count) {
    nodes_.reserve(count);
    destructors_.reserve(count);
  }

  /// Every node reachable from the root, in preorder with children in source order:
  /// built once by IndexPreorder() when the tree is complete (the parser does it) so
  /// that the many walks over one tree (every WebGL rule makes one) are a loop over
  /// an array instead of a traversal each. Empty before IndexPreorder().
  std::span<const PreorderEntry> Preorder() const { return preorder_; }
  /// The kind of each node of Preorder(), at the same index: walks that look at a few
  /// kinds scan this small table and read only the nodes they want.
  std::span<const NodeKind> PreorderKinds() const { return preorder_kinds_; }
  /// The index of node `id` in Preorder(), or kNotInPreorder (not reachable from
  /// the root, or no index yet).
  static constexpr uint32_t kNotInPreorder = UINT32_MAX;
  uint32_t PreorderIndexOf(uint32_t id) const {
    return id < preorder_index_.size() ? preorder_index_[id] : kNotInPreorder;
  }
  /// Builds Preorder() (iteratively: trees may be deeper than the call stack allows).
  /// Call again after changing the tree's shape.
  void IndexPreorder();

  /// Creates a node with the next id.
  template <class T>
  T* Make() {
    static_assert(std::is_base_of_v<Node, T>);
    if (!arena_) arena_ = std::make_unique<NodeArena>();
    T* node = new (arena_->Allocate(sizeof(T), alignof(T))) T();
    node->id = NodeCount();
    nodes_.push_back(node);
    if constexpr (!std::is_trivially_destructible_v<T>) {
      destructors_.push_back({node, [](Node* n) { static_cast<T*>(n)->~T(); }});
    }
    return node;
  }

 private:
  struct Destructor {
    Node* node;
    void (*destroy)(Node*);
  };
  void DestroyNodes();
  // A node waiting to be placed by IndexPreorder, with its depth.
  struct PreorderItem {
    const Node* node;
    uint32_t depth;
  };
  void IndexSharedPreorder();  // IndexPreorder for a tree with a node under two parents

  std::unique_ptr<NodeArena> arena_;
  std::vector<Node*> nodes_;
  std::vector<Destructor> destructors_;  // the nodes whose type has a destructor to run
  TranslationUnit* root_ = nullptr;
  std::vector<PreorderEntry> preorder_;
  std::vector<NodeKind> preorder_kinds_;
  std::vector<uint32_t> preorder_index_;  // by node id
};

}  // namespace shaderport::glsl
