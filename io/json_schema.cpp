// JSON Schema validation for the keywords the project's schemas use. The schema is checked as a whole before
// any document: a keyword this validator does not know would otherwise be ignored without a word.
// Debian's maintained C++ validator (valijson) reports generic messages without the expected values, hence this.
//
// Decisions:
// - A value of the wrong type gets that one error; nothing inside it is checked. So does a value outside its
//   `enum` or unequal to its `const`.
// - A failed oneOf/anyOf is one error at the value, unless it is a discriminated union (every branch fixes the
//   same key with `const`): then the key picks the branch, whose own errors are reported.
#include "io/json_schema.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>
#include <string_view>

namespace uvtk::io {
namespace {

using Json = nlohmann::json;

// Found strings are cut to this many characters in messages.
constexpr std::size_t kMaxQuoted = 60;

const std::set<std::string, std::less<>> kAnnotations = {"$schema", "$id",      "title",   "description",
                                                         "default", "examples", "$comment"};
const std::map<std::string, std::string, std::less<>> kTypeNouns = {
    {"string", "a string"},  {"number", "a number"}, {"integer", "an integer"}, {"boolean", "a boolean"},
    {"object", "an object"}, {"array", "an array"},  {"null", "null"}};

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

std::size_t characterCount(const std::string& s) {
  std::size_t count = 0;
  for (char c : s) count += isContinuationByte(c) ? 0 : 1;
  return count;
}

std::string compact(const Json& value) { return value.dump(-1, ' ', false, Json::error_handler_t::replace); }

// A found value as messages print it: compact JSON for a scalar (a long string cut), "an object" or "an array".
std::string describe(const Json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  if (!value.is_string() || characterCount(value.get_ref<const std::string&>()) <= kMaxQuoted) return compact(value);
  const auto& s = value.get_ref<const std::string&>();
  std::size_t end = 0;
  for (std::size_t characters = 0; characters < kMaxQuoted; ++characters) {
    ++end;
    while (end < s.size() && isContinuationByte(s[end])) ++end;
  }
  const std::string quoted = compact(Json(s.substr(0, end)));
  return quoted.substr(0, quoted.size() - 1) + "...\"";
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

// "x, y, 3": strings bare, other values as JSON.
std::string listOf(const Json& values) {
  std::vector<std::string> items;
  for (const Json& v : values) items.push_back(v.is_string() ? v.get<std::string>() : compact(v));
  return join(items, ", ");
}

std::string pointerToken(const std::string& key) {
  std::string token;
  for (char c : key) token += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return token;
}

std::string child(const std::string& path, const std::string& key) { return path + "/" + pointerToken(key); }

bool hasType(const Json& value, const std::string& type) {
  if (type == "string") return value.is_string();
  if (type == "number") return value.is_number();
  if (type == "integer") {
    if (value.is_number_integer()) return true;
    if (!value.is_number_float()) return false;
    const double x = value.get<double>();
    return std::isfinite(x) && std::floor(x) == x;
  }
  if (type == "boolean") return value.is_boolean();
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  return value.is_null();
}

// The `type` keyword (a name or an array of names) as the types it allows.
std::vector<std::string> typeNames(const Json& type) {
  if (type.is_string()) return {type.get<std::string>()};
  return type.get<std::vector<std::string>>();
}

std::string typeList(const Json& type) {
  std::vector<std::string> nouns;
  for (const std::string& name : typeNames(type)) nouns.push_back(kTypeNouns.at(name));
  return join(nouns, " or ");
}

// "an integer" where the schema allows integers and not other numbers, else "a number".
std::string numberNoun(const Json& schema) {
  const auto type = schema.find("type");
  if (type == schema.end()) return "a number";
  const std::vector<std::string> names = typeNames(*type);
  const bool integer = std::find(names.begin(), names.end(), "integer") != names.end();
  const bool number = std::find(names.begin(), names.end(), "number") != names.end();
  return integer && !number ? "an integer" : "a number";
}

std::string items(std::size_t n) { return std::to_string(n) + (n == 1 ? " item" : " items"); }

[[noreturn]] void schemaFault(const std::string& at, const std::string& what) {
  throw std::logic_error("JSON schema " + (at.empty() ? std::string("/") : at) + ": " + what);
}

class Validator {
 public:
  explicit Validator(const Json& root) : root_(root) { check(root, ""); }

  void validate(const Json& value, const Json& schema, const std::string& path,
                std::vector<SchemaError>& errors) const {
    if (const auto ref = schema.find("$ref"); ref != schema.end()) validate(value, target(*ref), path, errors);
    if (const auto type = schema.find("type"); type != schema.end()) {
      const std::vector<std::string> names = typeNames(*type);
      if (std::none_of(names.begin(), names.end(), [&](const std::string& name) { return hasType(value, name); })) {
        errors.push_back({path, "expected " + typeList(*type) + ", found " + describe(value)});
        return;
      }
    }
    if (const auto values = schema.find("enum"); values != schema.end()) {
      if (std::find(values->begin(), values->end(), value) == values->end()) {
        errors.push_back({path, "expected one of " + listOf(*values) + ", found " + describe(value)});
        return;
      }
    }
    if (const auto constant = schema.find("const"); constant != schema.end() && value != *constant) {
      errors.push_back({path, "expected " + compact(*constant) + ", found " + describe(value)});
      return;
    }

    if (value.is_number()) checkBounds(value, schema, path, errors);
    if (value.is_string()) checkString(value.get_ref<const std::string&>(), schema, path, errors);
    if (value.is_array()) checkArray(value, schema, path, errors);
    if (value.is_object()) checkObject(value, schema, path, errors);

    if (const auto branches = schema.find("oneOf"); branches != schema.end())
      checkAlternatives(value, *branches, true, path, errors);
    if (const auto branches = schema.find("anyOf"); branches != schema.end())
      checkAlternatives(value, *branches, false, path, errors);
  }

 private:
  // ---- the schema itself ----

  void check(const Json& schema, const std::string& at) {
    if (!schema.is_object()) schemaFault(at, "expected a schema (an object), found " + describe(schema));
    for (const auto& [keyword, value] : schema.items()) {
      const std::string here = child(at, keyword);
      if (keyword == "description") {
        if (!value.is_string()) schemaFault(here, "expected a string");
      } else if (kAnnotations.count(keyword) || keyword == "const") {
        // any value will do
      } else if (keyword == "type") {
        const bool names = value.is_string() ||
                           (value.is_array() && !value.empty() &&
                            std::all_of(value.begin(), value.end(), [](const Json& name) { return name.is_string(); }));
        if (!names) schemaFault(here, "expected a type name or an array of them");
        for (const std::string& name : typeNames(value))
          if (!kTypeNouns.count(name)) schemaFault(here, "unknown type \"" + name + "\"");
      } else if (keyword == "enum") {
        if (!value.is_array() || value.empty()) schemaFault(here, "expected a non-empty array");
      } else if (keyword == "properties" || keyword == "$defs") {
        if (!value.is_object()) schemaFault(here, "expected an object");
        for (const auto& [name, subschema] : value.items()) check(subschema, child(here, name));
      } else if (keyword == "required") {
        if (!value.is_array() || !std::all_of(value.begin(), value.end(), [](const Json& k) { return k.is_string(); }))
          schemaFault(here, "expected an array of strings");
      } else if (keyword == "additionalProperties") {
        if (!value.is_boolean()) check(value, here);
      } else if (keyword == "items") {
        check(value, here);
      } else if (keyword == "minItems" || keyword == "maxItems" || keyword == "minLength") {
        if (!value.is_number_integer() || value < 0) schemaFault(here, "expected a non-negative integer");
      } else if (keyword == "minimum" || keyword == "maximum" || keyword == "exclusiveMinimum" ||
                 keyword == "exclusiveMaximum") {
        if (!value.is_number()) schemaFault(here, "expected a number");
      } else if (keyword == "pattern") {
        if (!value.is_string()) schemaFault(here, "expected a string");
        try {
          patterns_.emplace(value.get<std::string>(), std::regex(value.get<std::string>(), std::regex::ECMAScript));
        } catch (const std::regex_error& e) {
          schemaFault(here, std::string("invalid regular expression: ") + e.what());
        }
      } else if (keyword == "oneOf" || keyword == "anyOf") {
        if (!value.is_array() || value.empty()) schemaFault(here, "expected a non-empty array of schemas");
        for (std::size_t i = 0; i < value.size(); ++i) check(value[i], child(here, std::to_string(i)));
      } else if (keyword == "$ref") {
        // Follow the chain once here, so that validation never loops on "a" -> "b" -> "a".
        std::set<const Json*> seen = {&schema};
        for (const Json* s = &schema; s->contains("$ref");) {
          s = &target(s->at("$ref"), here);
          if (!seen.insert(s).second) schemaFault(here, "$ref cycle");
        }
      } else {
        schemaFault(here, "unsupported keyword \"" + keyword + "\" (this validator would ignore it)");
      }
    }
  }

  // The schema a "$ref" names; only "#/$defs/NAME" in the root schema.
  const Json& target(const Json& ref, const std::string& at = "") const {
    constexpr std::string_view kPrefix = "#/$defs/";
    if (!ref.is_string() || ref.get_ref<const std::string&>().rfind(kPrefix, 0) != 0)
      schemaFault(at, "expected a $ref of the form \"#/$defs/NAME\", found " + compact(ref));
    const std::string token = ref.get<std::string>().substr(kPrefix.size());
    std::string name;  // the pointer token unescaped (RFC 6901: "~1" is '/', "~0" is '~')
    for (std::size_t i = 0; i < token.size(); ++i) {
      const bool escape = token[i] == '~' && i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1');
      name += escape ? (token[++i] == '1' ? '/' : '~') : token[i];
    }
    const auto defs = root_.find("$defs");
    if (token.find('/') != std::string::npos || defs == root_.end() || !defs->contains(name))
      schemaFault(at, "$ref " + compact(ref) + " names no schema under /$defs");
    return defs->at(name);
  }

  const Json& resolved(const Json& schema) const {
    const Json* s = &schema;
    while (s->contains("$ref")) s = &target(s->at("$ref"));
    return *s;
  }

  // ---- keywords by the type of the value ----

  void checkBounds(const Json& value, const Json& schema, const std::string& path,
                   std::vector<SchemaError>& errors) const {
    struct Bound {
      const char* keyword;
      const char* relation;
      bool (*holds)(const Json&, const Json&);
    };
    static const Bound kBounds[] = {
        {"minimum", ">=", [](const Json& v, const Json& b) { return !(v < b); }},
        {"exclusiveMinimum", ">", [](const Json& v, const Json& b) { return b < v; }},
        {"maximum", "<=", [](const Json& v, const Json& b) { return !(b < v); }},
        {"exclusiveMaximum", "<", [](const Json& v, const Json& b) { return v < b; }},
    };
    for (const Bound& bound : kBounds) {
      const auto limit = schema.find(bound.keyword);
      if (limit != schema.end() && !bound.holds(value, *limit))
        errors.push_back({path, "expected " + numberNoun(schema) + " " + bound.relation + " " + compact(*limit) +
                                    ", found " + compact(value)});
    }
  }

  void checkString(const std::string& value, const Json& schema, const std::string& path,
                   std::vector<SchemaError>& errors) const {
    if (const auto minLength = schema.find("minLength"); minLength != schema.end()) {
      const auto least = minLength->get<std::size_t>();
      if (characterCount(value) < least)
        errors.push_back({path, least == 1 ? "expected a non-empty string"
                                           : "expected at least " + std::to_string(least) + " characters"});
    }
    if (const auto pattern = schema.find("pattern"); pattern != schema.end()) {
      const auto& text = pattern->get_ref<const std::string&>();
      if (!std::regex_search(value, patterns_.at(text)))
        errors.push_back({path, "expected a string matching " + text + ", found " + describe(Json(value))});
    }
  }

  void checkArray(const Json& value, const Json& schema, const std::string& path,
                  std::vector<SchemaError>& errors) const {
    const std::size_t n = value.size();
    const std::size_t least = schema.value("minItems", std::size_t{0});
    const std::size_t most = schema.value("maxItems", SIZE_MAX);
    if (least == most && n != least) {
      errors.push_back({path, "expected " + items(least) + ", found " + std::to_string(n)});
    } else if (n < least) {
      errors.push_back({path, "expected at least " + items(least) + ", found " + std::to_string(n)});
    } else if (n > most) {
      errors.push_back({path, "expected at most " + items(most) + ", found " + std::to_string(n)});
    }
    if (const auto itemSchema = schema.find("items"); itemSchema != schema.end())
      for (std::size_t i = 0; i < n; ++i) validate(value[i], *itemSchema, child(path, std::to_string(i)), errors);
  }

  void checkObject(const Json& value, const Json& schema, const std::string& path,
                   std::vector<SchemaError>& errors) const {
    if (const auto required = schema.find("required"); required != schema.end())
      for (const Json& key : *required)
        if (!value.contains(key.get_ref<const std::string&>()))
          errors.push_back({path, "missing required key " + compact(key)});

    static const Json kNone = Json::object();
    const auto propertiesAt = schema.find("properties");
    const Json& properties = propertiesAt != schema.end() ? *propertiesAt : kNone;
    const auto additional = schema.find("additionalProperties");
    for (const auto& [key, member] : value.items()) {
      const std::string memberPath = child(path, key);
      if (const auto property = properties.find(key); property != properties.end()) {
        validate(member, *property, memberPath, errors);
      } else if (additional != schema.end() && additional->is_object()) {
        validate(member, *additional, memberPath, errors);
      } else if (additional != schema.end() && *additional == false) {
        std::vector<std::string> known;
        for (const auto& entry : properties.items()) known.push_back(entry.key());
        errors.push_back(
            {memberPath, "unknown key " + compact(key) + "; " +
                             (known.empty() ? "expected no keys" : "expected one of: " + join(known, ", "))});
      }
    }
  }

  // ---- oneOf and anyOf ----

  // The key that every branch fixes with properties.KEY.const (or .enum), to distinct values; "" if there is none.
  std::string discriminator(const Json& branches) const {
    const Json& first = resolved(branches[0]);
    const auto properties = first.find("properties");
    if (properties == first.end()) return "";
    for (const auto& property : properties->items()) {
      const std::string& key = property.key();
      std::vector<Json> values;
      std::size_t fixed = 0;  // branches that fix the key to values no other branch has
      for (const Json& branch : branches) {
        const Json constants = branchConstants(branch, key);
        const bool distinct = std::all_of(constants.begin(), constants.end(), [&](const Json& c) {
          return std::find(values.begin(), values.end(), c) == values.end();
        });
        if (constants.empty() || !distinct) break;
        values.insert(values.end(), constants.begin(), constants.end());
        ++fixed;
      }
      if (fixed == branches.size()) return key;
    }
    return "";
  }

  // The values the branch's properties.KEY.const or .enum allow; empty if it fixes none.
  Json branchConstants(const Json& branch, const std::string& key) const {
    const Json& schema = resolved(branch);
    const auto properties = schema.find("properties");
    if (properties == schema.end()) return Json::array();
    const auto property = properties->find(key);
    if (property == properties->end()) return Json::array();
    if (const auto constant = property->find("const"); constant != property->end()) return Json::array({*constant});
    if (const auto values = property->find("enum"); values != property->end() && values->is_array()) return *values;
    return Json::array();
  }

  // How a branch reads in "expected A or B": its description, else what its const, enum or type allow.
  std::string describeBranch(const Json& branch, std::size_t index) const {
    if (const auto d = branch.find("description"); d != branch.end()) return d->get<std::string>();
    if (const auto c = branch.find("const"); c != branch.end()) return compact(*c);
    if (const auto e = branch.find("enum"); e != branch.end()) return "one of " + listOf(*e);
    if (const auto t = branch.find("type"); t != branch.end()) return typeList(*t);
    if (const auto r = branch.find("$ref"); r != branch.end()) return describeBranch(target(*r), index);
    return "alternative " + std::to_string(index + 1);
  }

  void checkAlternatives(const Json& value, const Json& branches, bool exactlyOne, const std::string& path,
                         std::vector<SchemaError>& errors) const {
    if (const std::string key = discriminator(branches); !key.empty()) {
      if (!value.is_object()) {
        errors.push_back({path, "expected an object, found " + describe(value)});
        return;
      }
      const auto selector = value.find(key);
      if (selector == value.end()) {
        errors.push_back({path, "missing required key " + compact(Json(key))});
        return;
      }
      Json allowed = Json::array();
      for (const Json& branch : branches) {
        const Json constants = branchConstants(branch, key);
        if (std::find(constants.begin(), constants.end(), *selector) != constants.end()) {
          validate(value, branch, path, errors);
          return;
        }
        allowed.insert(allowed.end(), constants.begin(), constants.end());
      }
      errors.push_back({path, "expected " + key + " one of " + listOf(allowed) + ", found " + describe(*selector)});
      return;
    }

    std::size_t matches = 0;
    for (const Json& branch : branches) {
      std::vector<SchemaError> branchErrors;
      validate(value, branch, path, branchErrors);
      matches += branchErrors.empty() ? 1 : 0;
    }
    if (matches == 1 || (matches > 1 && !exactlyOne)) return;
    if (matches > 1) {
      errors.push_back({path, "matches more than one alternative"});
      return;
    }
    std::vector<std::string> descriptions;
    for (std::size_t i = 0; i < branches.size(); ++i) descriptions.push_back(describeBranch(branches[i], i));
    errors.push_back({path, "expected " + join(descriptions, " or ") + ", found " + describe(value)});
  }

  const Json& root_;
  std::map<std::string, std::regex> patterns_;  // every `pattern` of the schema, compiled once
};

}  // namespace

std::vector<SchemaError> validateJson(const nlohmann::json& document, const nlohmann::json& schema) {
  Validator validator(schema);
  std::vector<SchemaError> errors;
  validator.validate(document, schema, "", errors);
  return errors;
}

std::string toString(const SchemaError& e) { return (e.path.empty() ? "/" : e.path) + ": " + e.message; }

}  // namespace uvtk::io
