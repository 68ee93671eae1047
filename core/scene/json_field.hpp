#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace pbr {

// The numbers a field accepts: finite as float and within optional bounds.
struct NumberRule {
  std::optional<double> lo, hi;
  bool loOpen = false, hiOpen = false;
  std::string loName;  // a bound read from another field, named in messages: "> camera.near (0.5)"

  static NumberRule any() { return {}; }
  static NumberRule atLeast(double lo) { return {lo, std::nullopt, false, false, {}}; }
  static NumberRule above(double lo, std::string name = {}) { return {lo, std::nullopt, true, false, std::move(name)}; }
  static NumberRule closed(double lo, double hi) { return {lo, hi, false, false, {}}; }
  static NumberRule open(double lo, double hi) { return {lo, hi, true, true, {}}; }

  bool accepts(double v) const;
  std::string describe() const;  // "a number in [0, 1]"
};

// A value of a parsed JSON document with its path, so that every error is one line naming the file, the path and
// what was expected: "scene.json: lights[3].radius: expected a finite number >= 0, got -1". A field may be absent;
// accessors then return their fallback, or fail when there is none (the field is required).
// The fields of one document share a record of what was read, so that keys nobody read can be named afterwards.
class JsonField {
 public:
  JsonField(const nlohmann::json& root, std::string file)
      : value_(&root), file_(std::move(file)), reads_(std::make_shared<Reads>(Reads{&root, {}, {}})) {}

  bool present() const { return value_ != nullptr; }
  // For a field that takes a keyword or an object.
  bool isString() const { return value_ && value_->is_string(); }
  // For a field that may be null (a report's "not applicable").
  bool isNull() const { return value_ && value_->is_null(); }

  // A member: absent when missing. Fails when this field is present but not an object.
  JsonField operator[](const std::string& key) const;
  // The elements of an array; none when absent. Fails when this field is present but not an array.
  std::vector<JsonField> items() const;
  // The members of an object, in nlohmann's key order; none when absent. Fails when present but not an object.
  std::vector<std::pair<std::string, JsonField>> members() const;

  float number(const NumberRule& rule, std::optional<float> fallback = std::nullopt) const;
  // As number, without rounding to float: for measurements read back at the precision they were written with.
  double real(const NumberRule& rule, std::optional<double> fallback = std::nullopt) const;
  glm::vec3 vec3(const NumberRule& rule, std::optional<glm::vec3> fallback = std::nullopt) const;
  // A number n stands for (n, n, n): a grey colour, a uniform scale.
  glm::vec3 vec3OrNumber(const NumberRule& rule, std::optional<glm::vec3> fallback = std::nullopt) const;
  // [lo, hi] with lo <= hi, both following `rule`.
  std::pair<float, float> interval(const NumberRule& rule) const;
  uint64_t integer(uint64_t max, std::optional<uint64_t> fallback = std::nullopt) const;  // in [0, max]
  std::string string() const;
  bool boolean(bool fallback) const;

  // "F: P: expected WHAT, got V", or "..., but the field is missing" when absent.
  [[noreturn]] void expected(const std::string& what) const;
  // "F: P: MESSAGE".
  [[noreturn]] void fail(const std::string& message) const;

  // Once the document is read: an object key never looked up by operator[] (a key only checked with present()
  // was looked up) is a misspelt or unsupported field, reported as "F: P: unknown key" on stderr, one line each,
  // or with `strict` thrown as a SceneError for the first (members in key order, as nlohmann keeps them). Only
  // objects and arrays that were read are searched, so nothing under an unknown key is named but the key itself.
  void reportUnknownKeys(bool strict) const;

  static std::string memberPath(const std::string& path, const std::string& key);
  static std::string itemPath(const std::string& path, std::size_t index);
  static std::string displayPath(const std::string& path);  // the root has an empty path

 private:
  struct Reads {
    const nlohmann::json* root;
    std::unordered_set<const nlohmann::json*> opened;    // objects and arrays whose content was read
    std::unordered_set<const nlohmann::json*> lookedUp;  // members found by operator[]
  };

  JsonField(const nlohmann::json* value, std::string file, std::string path, std::shared_ptr<Reads> reads)
      : value_(value), file_(std::move(file)), path_(std::move(path)), reads_(std::move(reads)) {}
  // The search of reportUnknownKeys below `value`, found at `path`.
  void reportUnknownKeys(const nlohmann::json& value, const std::string& path, bool strict) const;
  // Fails with `what` unless present or a fallback exists; true when the value must be read.
  bool required(bool hasFallback, const std::string& what) const;

  const nlohmann::json* value_;
  std::string file_, path_;
  std::shared_ptr<Reads> reads_;
};

}  // namespace pbr
