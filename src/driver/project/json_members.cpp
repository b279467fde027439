#include "driver/project/json_members.h"

#include "base/limits.h"

namespace shaderport::driver::project {

using nlohmann::json;

std::string DescribeJsonValue(const json& value) {
  switch (value.type()) {
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::null:
      return "null";
    case json::value_t::number_float:
      return "the number " + value.dump();
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      return "the integer " + value.dump();
    default:
      return "a " + std::string(value.type_name());
  }
}

void MemberProblems::Add(std::string pointer, std::string message) {
  if (++count_ <= limits::kMaxDiagnosticsPerFile)
    kept_.push_back({std::move(pointer), std::move(message)});
}

std::string MemberReader::PointerOf(std::string_view name) const {
  std::string pointer = pointer_ + "/";
  for (const char c : name) {
    if (c == '~') {
      pointer += "~0";
    } else if (c == '/') {
      pointer += "~1";
    } else {
      pointer += c;
    }
  }
  return pointer;
}

const json* MemberReader::Find(const char* name, Presence presence) {
  const auto it = object_.find(name);
  if (it != object_.end()) return &*it;
  if (presence == Presence::kRequired) {
    problems_.Add(pointer_, "missing member \"" + std::string(name) + "\" at " +
                                (pointer_.empty() ? "/" : pointer_));
  }
  return nullptr;
}

void MemberReader::WrongType(const char* name, const json& value, std::string_view expected) {
  problems_.Add(PointerOf(name), "\"" + std::string(name) + "\" at " + PointerOf(name) +
                                     " must be " + std::string(expected) + ", not " +
                                     DescribeJsonValue(value));
}

std::optional<std::string> MemberReader::String(const char* name, Presence presence) {
  const json* value = Find(name, presence);
  if (value == nullptr) return std::nullopt;
  if (!value->is_string()) {
    WrongType(name, *value, "a string");
    return std::nullopt;
  }
  return value->get<std::string>();
}

std::optional<std::string> MemberReader::EitherString(const char* name, const char* other) {
  return object_.contains(name) ? String(name) : String(other);
}

std::optional<int64_t> MemberReader::Integer(const char* name, int64_t min, int64_t max,
                                             Presence presence) {
  const json* value = Find(name, presence);
  if (value == nullptr) return std::nullopt;
  const std::string range = "an integer from " + std::to_string(min) + " to " + std::to_string(max);
  // An unsigned value above INT64_MAX is out of range, not wrapped.
  if (value->is_number_unsigned() && value->get<uint64_t>() > static_cast<uint64_t>(max)) {
    WrongType(name, *value, range);
    return std::nullopt;
  }
  if (!value->is_number_integer() || value->get<int64_t>() < min || value->get<int64_t>() > max) {
    WrongType(name, *value, range);
    return std::nullopt;
  }
  return value->get<int64_t>();
}

std::optional<bool> MemberReader::Flag(const char* name) {
  const json* value = Find(name, Presence::kOptional);
  if (value == nullptr) return std::nullopt;
  if (value->is_boolean()) return value->get<bool>();
  if (value->is_string() && (*value == "true" || *value == "false")) return *value == "true";
  WrongType(name, *value, "true or false (a boolean or a string)");
  return std::nullopt;
}

const json* MemberReader::Id(const char* name) {
  const json* value = Find(name, Presence::kOptional);
  if (value == nullptr || value->is_string() || value->is_number_integer()) return value;
  WrongType(name, *value, "a string or an integer");
  return nullptr;
}

const json* MemberReader::Array(const char* name, Presence presence) {
  const json* value = Find(name, presence);
  if (value == nullptr || value->is_array()) return value;
  WrongType(name, *value, "an array");
  return nullptr;
}

const json* MemberReader::Object(const char* name, Presence presence) {
  const json* value = Find(name, presence);
  if (value == nullptr || value->is_object()) return value;
  WrongType(name, *value, "an object");
  return nullptr;
}

}  // namespace shaderport::driver::project
