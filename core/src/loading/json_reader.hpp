// Reading a JSON object field by field, with a clear InputError for anything wrong. Internal to
// the core's loaders (scenes, scripts).
//
// Every accessor records the key it was asked for; finish() then rejects any other key as
// unknown, suggesting the closest known one ("stifness": did you mean "stiffness"?). Messages
// read: "<file>: /generators/0/nodes: must be an integer in [2, 4194304], got 1e+09".
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "springlab/error.hpp"
#include "springlab/model.hpp"

namespace springlab::json_reader {

using json = nlohmann::json;

struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;
  std::string text() const;
  bool contains(double x) const;
};
inline Range positive(double hi = 1e12) {
  return {0.0, hi, true, false};
}
inline Range non_negative(double hi = 1e12) {
  return {0.0, hi};
}
inline Range between(double lo, double hi) {
  return {lo, hi};
}
// Masses, kg: a microgram to a million tonnes. The floor keeps 1 / m finite, and a generator's
// node mass too (a total of 1e-9 kg over the most nodes a scene may have): a particle of 5e-324
// kg, "positive", had an infinite inverse mass.
inline Range mass_range() {
  return {1e-9, 1e9};
}

class ObjectReader {
 public:
  // `where` is the label of the document for messages ("scene 'rope.json'").
  ObjectReader(const json& object, std::string pointer, std::string where);

  bool has(const char* key);
  double number(const char* key, Range range);  // required
  double number(const char* key, double fallback, Range range);
  std::int64_t integer(const char* key, std::int64_t lo, std::int64_t hi);  // required
  std::int64_t integer(const char* key, std::int64_t fallback, std::int64_t lo, std::int64_t hi);
  bool boolean(const char* key, bool fallback);
  Vec3 vec3(const char* key);  // required
  Vec3 vec3(const char* key, const Vec3& fallback);
  std::string text(const char* key, const std::string& fallback);
  std::string choice(const char* key, const std::string& fallback,
                     const std::vector<std::string>& options);
  std::optional<ObjectReader> object(const char* key);
  std::vector<ObjectReader> objects(const char* key);  // an array of objects; missing = empty
  // The raw value, for fields with a shape of their own; marks the key known.
  const json* raw(const char* key);

  // Declares keys read later, so that finish() can be called first: an unknown field is then
  // reported before anything else is checked.
  void expect(std::initializer_list<const char*> keys);

  [[noreturn]] void fail(const char* key, const std::string& what) const;
  [[noreturn]] void fail(const std::string& what) const;  // about the object itself
  void finish() const;

  std::string path(const char* key) const { return pointer_ + "/" + key; }
  const std::string& pointer() const { return pointer_; }
  const std::string& where() const { return where_; }

 private:
  const json& object_;
  std::string pointer_, where_;
  std::vector<std::string> known_;
};

// A document's text parsed, or an InputError: "<where>: not valid JSON: <what and where in it>".
json parse_document(const std::string& text, const std::string& where);

// A file's whole text, or an InputError: "<what> '<path>': cannot be read (...)" (a folder, a
// missing file, no permission, a failed read). `what` names the kind: "scene", "script", "lesson".
std::string read_document(const std::string& path, const std::string& what);

// A value as JSON text for messages. A string set with --set may hold bytes that are not UTF-8
// (a file's cannot: the parser refuses them); they are shown as U+FFFD instead of throwing.
std::string dump(const json& value);

// "got -1", "got \"abc\"", "got an array" for messages.
std::string describe(const json& value);

// Checks and returns an element's value as a number, with the same message style.
double as_number(const json& value, const std::string& pointer, const std::string& where,
                 Range range);
std::int64_t as_integer(const json& value, const std::string& pointer, const std::string& where,
                        std::int64_t lo, std::int64_t hi);
[[noreturn]] void fail_at(const std::string& where, const std::string& pointer,
                          const std::string& what);

}  // namespace springlab::json_reader
