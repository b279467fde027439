// Typed reads of the members of one JSON object of a ShaderToy document. A member
// of the wrong type, out of range or missing where it is required is a problem
// with its JSON pointer, never an exception: nlohmann's value() and get<>() throw
// on a wrong type (a string "0" for a channel number stopped whole runs).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace shaderport::driver::project {

struct MemberProblem {
  std::string pointer;  // RFC 6901, of the member (or of the object when it is missing)
  std::string message;
};

// The problems of one document: the first kMaxDiagnosticsPerFile are kept, the
// rest only counted, so that a document of a million wrong members stays small.
class MemberProblems {
 public:
  void Add(std::string pointer, std::string message);
  size_t Count() const { return count_; }
  std::vector<MemberProblem>& Kept() { return kept_; }

 private:
  std::vector<MemberProblem> kept_;
  size_t count_ = 0;
};

enum class Presence { kOptional, kRequired };

class MemberReader {
 public:
  // `object` must be a JSON object; `pointer` is its own pointer ("" for the root).
  MemberReader(const nlohmann::json& object, std::string pointer, MemberProblems& problems)
      : object_(object), pointer_(std::move(pointer)), problems_(problems) {}

  const std::string& Pointer() const { return pointer_; }
  MemberProblems& Problems() const { return problems_; }
  std::string PointerOf(std::string_view name) const;

  // nullopt when absent or a problem (which is then reported).
  std::optional<std::string> String(const char* name, Presence presence = Presence::kOptional);
  // The first of `name` and `other` that is present (the site renamed some members).
  std::optional<std::string> EitherString(const char* name, const char* other);
  std::optional<int64_t> Integer(const char* name, int64_t min, int64_t max,
                                 Presence presence = Presence::kOptional);
  // A boolean, or the strings "true" / "false" the site writes for samplers.
  std::optional<bool> Flag(const char* name);
  // A string or an integer (the site's ids of generated outputs, old and new).
  const nlohmann::json* Id(const char* name);
  const nlohmann::json* Array(const char* name, Presence presence = Presence::kOptional);
  const nlohmann::json* Object(const char* name, Presence presence = Presence::kOptional);

 private:
  const nlohmann::json* Find(const char* name, Presence presence);
  void WrongType(const char* name, const nlohmann::json& value, std::string_view expected);

  const nlohmann::json& object_;
  std::string pointer_;
  MemberProblems& problems_;
};

// "a string", "an array", "the number 1.5" ...: what a wrong value is, for messages.
std::string DescribeJsonValue(const nlohmann::json& value);

}  // namespace shaderport::driver::project
