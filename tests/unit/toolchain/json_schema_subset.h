// A validator for the subset of JSON Schema (draft-07) that docs/reflect.schema.json uses:
// type, const, enum, required, properties, additionalProperties: false, items, minimum,
// and $ref to "#/definitions/...". Enough to keep the schema and the output in step.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shaderport::toolchain::testing {

inline bool HasType(const nlohmann::json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "integer") return value.is_number_integer();
  if (type == "number") return value.is_number();
  if (type == "null") return value.is_null();
  return false;
}

inline void CheckSchema(const nlohmann::json& root, const nlohmann::json& schema,
                        const nlohmann::json& value, const std::string& path,
                        std::vector<std::string>& errors) {
  if (schema.contains("$ref")) {
    const std::string ref = schema["$ref"];
    const std::string prefix = "#/definitions/";
    if (ref.rfind(prefix, 0) != 0 || !root["definitions"].contains(ref.substr(prefix.size()))) {
      errors.push_back(path + ": unresolved $ref " + ref);
      return;
    }
    CheckSchema(root, root["definitions"][ref.substr(prefix.size())], value, path, errors);
    return;
  }
  if (schema.contains("type")) {
    bool any = false;
    const nlohmann::json& types = schema["type"];
    for (const auto& type : types.is_array() ? types : nlohmann::json::array({types})) {
      any = any || HasType(value, type.get<std::string>());
    }
    if (!any) {
      errors.push_back(path + ": not of type " + types.dump());
      return;
    }
  }
  if (schema.contains("const") && value != schema["const"]) {
    errors.push_back(path + ": is not " + schema["const"].dump());
  }
  if (schema.contains("enum") &&
      std::find(schema["enum"].begin(), schema["enum"].end(), value) == schema["enum"].end()) {
    errors.push_back(path + ": " + value.dump() + " not in " + schema["enum"].dump());
  }
  if (schema.contains("minimum") && value.is_number() && value < schema["minimum"]) {
    errors.push_back(path + ": below minimum");
  }
  if (value.is_object()) {
    for (const auto& key : schema.value("required", nlohmann::json::array())) {
      if (!value.contains(key.get<std::string>())) errors.push_back(path + ": lacks " + key.dump());
    }
    const nlohmann::json properties = schema.value("properties", nlohmann::json::object());
    for (const auto& [key, member] : value.items()) {
      if (properties.contains(key)) {
        CheckSchema(root, properties[key], member, path + "." + key, errors);
      } else if (schema.value("additionalProperties", true) == false) {
        errors.push_back(path + ": unexpected property " + key);
      }
    }
  }
  if (value.is_array() && schema.contains("items")) {
    for (size_t i = 0; i < value.size(); ++i) {
      CheckSchema(root, schema["items"], value[i], path + "[" + std::to_string(i) + "]", errors);
    }
  }
}

inline std::vector<std::string> SchemaErrors(const nlohmann::json& schema,
                                             const nlohmann::json& value) {
  std::vector<std::string> errors;
  CheckSchema(schema, schema, value, "$", errors);
  return errors;
}

}  // namespace shaderport::toolchain::testing
