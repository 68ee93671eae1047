#include "core/scene/json_field.hpp"

#include <cmath>
#include <sstream>

#include "core/scene/json_text.hpp"
#include "core/scene/messages.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

namespace {

constexpr const char* kVec3 = "an array of 3 numbers";

std::string format(double v) {
  std::ostringstream ss;
  ss << v;
  return ss.str();
}

}  // namespace

bool NumberRule::accepts(double v) const {
  // A value beyond float range would become inf once stored.
  if (!std::isfinite(v) || !std::isfinite(static_cast<float>(v))) return false;
  if (lo && (loOpen ? v <= *lo : v < *lo)) return false;
  return !(hi && (hiOpen ? v >= *hi : v > *hi));
}

std::string NumberRule::describe() const {
  if (lo && hi) {
    return "a number in " + std::string(loOpen ? "(" : "[") + format(*lo) + ", " + format(*hi) + (hiOpen ? ")" : "]");
  }
  if (lo) {
    const std::string bound = loName.empty() ? format(*lo) : loName + " (" + format(*lo) + ")";
    return std::string("a finite number ") + (loOpen ? "> " : ">= ") + bound;
  }
  return "a finite number";
}

JsonField JsonField::operator[](const std::string& key) const {
  const std::string path = memberPath(path_, key);
  if (!value_) return {nullptr, file_, path, reads_};
  if (!value_->is_object()) expected("an object");
  reads_->opened.insert(value_);
  const auto it = value_->find(key);
  if (it == value_->end()) return {nullptr, file_, path, reads_};
  reads_->lookedUp.insert(&*it);
  return {&*it, file_, path, reads_};
}

std::vector<JsonField> JsonField::items() const {
  std::vector<JsonField> out;
  if (!value_) return out;
  if (!value_->is_array()) expected("an array");
  reads_->opened.insert(value_);
  for (std::size_t i = 0; i < value_->size(); ++i) out.push_back({&(*value_)[i], file_, itemPath(path_, i), reads_});
  return out;
}

std::vector<std::pair<std::string, JsonField>> JsonField::members() const {
  std::vector<std::pair<std::string, JsonField>> out;
  if (!value_) return out;
  if (!value_->is_object()) expected("an object");
  reads_->opened.insert(value_);
  for (const auto& [key, member] : value_->items()) {
    reads_->lookedUp.insert(&member);
    out.push_back({key, JsonField(&member, file_, memberPath(path_, key), reads_)});
  }
  return out;
}

bool JsonField::required(bool hasFallback, const std::string& what) const {
  if (value_) return true;
  if (!hasFallback) expected(what);
  return false;
}

float JsonField::number(const NumberRule& rule, std::optional<float> fallback) const {
  if (!required(fallback.has_value(), rule.describe())) return *fallback;
  if (!value_->is_number() || !rule.accepts(value_->get<double>())) expected(rule.describe());
  return static_cast<float>(value_->get<double>());
}

double JsonField::real(const NumberRule& rule, std::optional<double> fallback) const {
  if (!required(fallback.has_value(), rule.describe())) return *fallback;
  if (!value_->is_number() || !rule.accepts(value_->get<double>())) expected(rule.describe());
  return value_->get<double>();
}

glm::vec3 JsonField::vec3(const NumberRule& rule, std::optional<glm::vec3> fallback) const {
  if (!required(fallback.has_value(), kVec3)) return *fallback;
  if (!value_->is_array() || value_->size() != 3) expected(kVec3);
  const std::vector<JsonField> e = items();
  return {e[0].number(rule), e[1].number(rule), e[2].number(rule)};
}

glm::vec3 JsonField::vec3OrNumber(const NumberRule& rule, std::optional<glm::vec3> fallback) const {
  const std::string what = "a number or " + std::string(kVec3);
  if (!required(fallback.has_value(), what)) return *fallback;
  if (value_->is_number()) return glm::vec3(number(rule));
  if (!value_->is_array()) expected(what);
  return vec3(rule);
}

std::pair<float, float> JsonField::interval(const NumberRule& rule) const {
  const std::string what = "[lo, hi], lo <= hi, each " + rule.describe();
  required(false, what);
  if (!value_->is_array() || value_->size() != 2) expected(what);
  const std::vector<JsonField> e = items();
  const float lo = e[0].number(rule), hi = e[1].number(rule);
  if (lo > hi) expected(what);
  return {lo, hi};
}

uint64_t JsonField::integer(uint64_t max, std::optional<uint64_t> fallback) const {
  const std::string what = "an integer in [0, " + std::to_string(max) + "]";
  if (!required(fallback.has_value(), what)) return *fallback;
  // nlohmann stores non-negative integer literals as unsigned; 3.0 or -1 are not counts.
  if (!value_->is_number_unsigned() || value_->get<uint64_t>() > max) expected(what);
  return value_->get<uint64_t>();
}

std::string JsonField::string() const {
  required(false, "a string");
  if (!value_->is_string()) expected("a string");
  return value_->get<std::string>();
}

bool JsonField::boolean(bool fallback) const {
  if (!value_) return fallback;
  if (!value_->is_boolean()) expected("true or false");
  return value_->get<bool>();
}

void JsonField::expected(const std::string& what) const {
  fail("expected " + what + (value_ ? ", got " + quoteJson(*value_) : ", but the field is missing"));
}

void JsonField::fail(const std::string& message) const {
  throw SceneError(file_ + ": " + displayPath(path_) + ": " + message);
}

void JsonField::reportUnknownKeys(bool strict) const { reportUnknownKeys(*reads_->root, "", strict); }

void JsonField::reportUnknownKeys(const nlohmann::json& value, const std::string& path, bool strict) const {
  if (!reads_->opened.count(&value)) return;
  if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) reportUnknownKeys(value[i], itemPath(path, i), strict);
    return;
  }
  for (const auto& [key, member] : value.items()) {
    const std::string memberAt = memberPath(path, key);
    if (reads_->lookedUp.count(&member)) {
      reportUnknownKeys(member, memberAt, strict);
      continue;
    }
    const std::string line = file_ + ": " + memberAt + ": unknown key";
    if (strict) throw SceneError(line);
    warnOnce(line);
  }
}

std::string JsonField::memberPath(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string JsonField::itemPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

std::string JsonField::displayPath(const std::string& path) { return path.empty() ? "top level" : path; }

}  // namespace pbr
