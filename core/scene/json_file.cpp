#include "core/scene/json_file.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/scene/input_file.hpp"
#include "core/scene/json_field.hpp"
#include "core/scene/json_text.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

namespace {

using nlohmann::json;

// Builds the document like nlohmann's own parser, but keeps the path of the value being parsed, so that a
// number overflow (1e999), which nlohmann reports without a location, can be named like any other bad field.
class PathTrackingSax : public nlohmann::json_sax<json> {
 public:
  // `duplicates`: where a key given twice in one object is noted (the later value kept, as JSON.parse does);
  // null: such a key stops the parse (duplicatePath names it).
  PathTrackingSax(json& root, std::vector<std::string>* duplicates) : root_(root), duplicates_(duplicates) {}

  bool null() override { return add(nullptr); }
  bool boolean(bool v) override { return add(v); }
  bool number_integer(number_integer_t v) override { return add(v); }
  bool number_unsigned(number_unsigned_t v) override { return add(v); }
  bool number_float(number_float_t v, const string_t&) override { return add(v); }
  bool string(string_t& v) override { return add(v); }
  bool binary(binary_t& v) override { return add(json::binary(v)); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool key(string_t& k) override {
    Frame& f = frames_.back();
    f.key = k;
    if (!f.container->contains(k)) return true;
    const std::string path = JsonField::displayPath(pendingPath());
    if (!duplicates_) {
      duplicatePath_ = path;
      return false;
    }
    duplicates_->push_back(path);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) override {
    position_ = position;
    token_ = token;
    overflow_ = e.id == 406;
    message_ = e.what();
    return false;
  }

  std::size_t position() const { return position_; }
  const std::string& token() const { return token_; }
  bool overflow() const { return overflow_; }
  const std::string& message() const { return message_; }
  const std::string& duplicatePath() const { return duplicatePath_; }

  // The path of the value that the parser is reading now, e.g. lights[3].radius. Enclosing arrays already hold
  // the element being read; the innermost one does not yet.
  std::string pendingPath() const {
    std::string path;
    for (size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      const bool innermost = i + 1 == frames_.size();
      path = f.container->is_array() ? JsonField::itemPath(path, f.container->size() - (innermost ? 0 : 1))
                                     : JsonField::memberPath(path, f.key);
    }
    return path;
  }

 private:
  struct Frame {
    json* container;
    std::string key;  // objects: the member being read
  };

  json* place(json value) {
    if (frames_.empty()) {
      root_ = std::move(value);
      return &root_;
    }
    Frame& f = frames_.back();
    if (f.container->is_array()) {
      f.container->push_back(std::move(value));
      return &f.container->back();
    }
    json& slot = (*f.container)[f.key];
    slot = std::move(value);
    return &slot;
  }
  bool add(json value) {
    place(std::move(value));
    return true;
  }
  bool open(json container) {
    frames_.push_back({place(std::move(container)), {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }

  json& root_;
  std::vector<std::string>* duplicates_;
  std::string duplicatePath_;
  std::vector<Frame> frames_;
  std::size_t position_ = 0;
  std::string token_, message_;
  bool overflow_ = false;
};

// "[json.exception.parse_error.101] parse error at line 3, column 9: syntax error ..." -> "syntax error ...".
std::string withoutNlohmannPrefix(const std::string& message) {
  const std::size_t column = message.find(", column ");
  const std::size_t colon = column == std::string::npos ? std::string::npos : message.find(": ", column);
  std::string rest = colon == std::string::npos ? message : message.substr(colon + 2);
  std::replace(rest.begin(), rest.end(), '\n', ' ');
  return rest;
}

}  // namespace

json readJsonFile(const std::string& path) {
  std::string text;
  try {
    text = readInputFile(path);
  } catch (const std::runtime_error& e) {
    throw SceneError(e.what());
  }
  return parseJsonText(text, path);
}

json parseJsonText(const std::string& text, const std::string& path, std::vector<std::string>* duplicates) {
  // nlohmann's reader ends the text at a NUL byte and ignores whatever follows: a file that is not what it seems.
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    throw SceneError(path + ":" + lineColumn(text, nul) + ": a NUL byte, which JSON text cannot hold");
  }
  checkJsonNesting(text, path);

  json root;
  PathTrackingSax sax(root, duplicates);
  if (json::sax_parse(text, &sax)) return root;
  if (!sax.duplicatePath().empty()) {
    throw SceneError(path + ": " + sax.duplicatePath() + ": given twice in one object (readers differ on which "
                     "counts)");
  }
  // nlohmann reports how many characters it read; the last one read is the one in error.
  const std::string where = path + ":" + lineColumn(text, sax.position() == 0 ? 0 : sax.position() - 1) + ": ";
  if (sax.overflow()) {
    throw SceneError(where + JsonField::displayPath(sax.pendingPath()) + ": expected a finite number, got " + sax.token());
  }
  throw SceneError(where + "JSON syntax error: " + withoutNlohmannPrefix(sax.message()));
}

}  // namespace pbr
