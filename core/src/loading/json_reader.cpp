#include "loading/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace springlab {

std::string closest_match(const std::string& word, const std::string* candidates,
                          std::size_t count) {
  // Levenshtein distance; a suggestion must be within a third of the word's length.
  const auto distance = [](const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diagonal = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
        diagonal = up;
      }
    }
    return row[b.size()];
  };
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t d = distance(word, candidates[k]);
    if (d < best_distance) {
      best_distance = d;
      best = candidates[k];
    }
  }
  return best;
}

namespace json_reader {

namespace {
std::string number_text(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}
}  // namespace

std::string Range::text() const {
  std::string lo_text = std::isinf(lo) ? "-inf" : number_text(lo);
  std::string hi_text = std::isinf(hi) ? "inf" : number_text(hi);
  return (lo_open ? "(" : "[") + lo_text + ", " + hi_text + (hi_open ? ")" : "]");
}

bool Range::contains(double x) const {
  return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
}

json parse_document(const std::string& text, const std::string& where) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    // nlohmann's message names the line and column; drop its "[json.exception...] " prefix.
    std::string what = e.what();
    const auto start = what.find("] ");
    throw InputError(where + ": not valid JSON: " +
                     (start == std::string::npos ? what : what.substr(start + 2)));
  }
}

std::string read_document(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(what + " '" + path + "': is a folder, not a " + what + " file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(what + " '" + path + "': cannot be read (no such file, or no permission)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(what + " '" + path + "': reading failed");
  return text.str();
}

std::string dump(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "got null";
    case json::value_t::boolean:
      return std::string("got ") + (value.get<bool>() ? "true" : "false");
    case json::value_t::string:
      return "got the string " + dump(value);
    case json::value_t::array:
      return "got an array";
    case json::value_t::object:
      return "got an object";
    default:
      return "got " + value.dump();
  }
}

void fail_at(const std::string& where, const std::string& pointer, const std::string& what) {
  throw InputError(where + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
}

double as_number(const json& value, const std::string& pointer, const std::string& where,
                 Range range) {
  if (!value.is_number())
    fail_at(where, pointer, "must be a number in " + range.text() + ", " + describe(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail_at(where, pointer, "must be finite, got " + value.dump());
  if (!range.contains(x))
    fail_at(where, pointer, "must be in " + range.text() + ", got " + number_text(x));
  return x;
}

std::int64_t as_integer(const json& value, const std::string& pointer, const std::string& where,
                        std::int64_t lo, std::int64_t hi) {
  const std::string allowed =
      "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!value.is_number()) fail_at(where, pointer, allowed + ", " + describe(value));
  const double x = value.get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || x < static_cast<double>(lo) ||
      x > static_cast<double>(hi))
    fail_at(where, pointer, allowed + ", got " + number_text(x));
  return static_cast<std::int64_t>(x);
}

ObjectReader::ObjectReader(const json& object, std::string pointer, std::string where)
    : object_(object), pointer_(std::move(pointer)), where_(std::move(where)) {
  if (!object_.is_object()) fail("must be an object, " + describe(object_));
}

void ObjectReader::expect(std::initializer_list<const char*> keys) {
  for (const char* k : keys) known_.emplace_back(k);
}

bool ObjectReader::has(const char* key) {
  known_.emplace_back(key);
  return object_.contains(key);
}

void ObjectReader::fail(const char* key, const std::string& what) const {
  fail_at(where_, path(key), what);
}

void ObjectReader::fail(const std::string& what) const {
  fail_at(where_, pointer_, what);
}

double ObjectReader::number(const char* key, Range range) {
  if (!has(key)) fail(key, "is required: a number in " + range.text());
  return as_number(object_[key], path(key), where_, range);
}

double ObjectReader::number(const char* key, double fallback, Range range) {
  return has(key) ? as_number(object_[key], path(key), where_, range) : fallback;
}

std::int64_t ObjectReader::integer(const char* key, std::int64_t lo, std::int64_t hi) {
  if (!has(key))
    fail(key,
         "is required: an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return as_integer(object_[key], path(key), where_, lo, hi);
}

std::int64_t ObjectReader::integer(const char* key, std::int64_t fallback, std::int64_t lo,
                                   std::int64_t hi) {
  return has(key) ? as_integer(object_[key], path(key), where_, lo, hi) : fallback;
}

bool ObjectReader::boolean(const char* key, bool fallback) {
  if (!has(key)) return fallback;
  const json& v = object_[key];
  if (!v.is_boolean()) fail(key, "must be true or false, " + describe(v));
  return v.get<bool>();
}

Vec3 ObjectReader::vec3(const char* key) {
  if (!has(key)) fail(key, "is required: an array of 3 numbers [x, y, z]");
  return vec3(key, Vec3::Zero());
}

Vec3 ObjectReader::vec3(const char* key, const Vec3& fallback) {
  if (!has(key)) return fallback;
  const json& v = object_[key];
  if (!v.is_array() || v.size() != 3)
    fail(key, "must be an array of 3 numbers [x, y, z], " + describe(v));
  const Range any{-1e9, 1e9};
  Vec3 out;
  for (int c = 0; c < 3; ++c)
    out[c] = as_number(v[c], path(key) + "/" + std::to_string(c), where_, any);
  return out;
}

std::string ObjectReader::text(const char* key, const std::string& fallback) {
  if (!has(key)) return fallback;
  const json& v = object_[key];
  if (!v.is_string()) fail(key, "must be a string, " + describe(v));
  return v.get<std::string>();
}

std::string ObjectReader::choice(const char* key, const std::string& fallback,
                                 const std::vector<std::string>& options) {
  std::string list;
  for (const auto& o : options) list += (list.empty() ? "" : ", ") + o;
  if (!has(key)) {
    if (!fallback.empty()) return fallback;
    fail(key, "is required: one of " + list);
  }
  const json& v = object_[key];
  if (!v.is_string()) fail(key, "must be one of " + list + ", " + describe(v));
  std::string s = v.get<std::string>();  // (not const: returned by move)
  if (std::find(options.begin(), options.end(), s) != options.end()) return s;
  const std::string near = closest_match(s, options.data(), options.size());
  fail(key, "unknown value \"" + s + "\"" +
                (near.empty() ? "" : "; did you mean \"" + near + "\"?") + " (one of " + list +
                ")");
}

std::optional<ObjectReader> ObjectReader::object(const char* key) {
  if (!has(key)) return std::nullopt;
  return ObjectReader(object_[key], path(key), where_);
}

std::vector<ObjectReader> ObjectReader::objects(const char* key) {
  std::vector<ObjectReader> out;
  if (!has(key)) return out;
  const json& v = object_[key];
  if (!v.is_array()) fail(key, "must be an array of objects, " + describe(v));
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    out.emplace_back(v[i], path(key) + "/" + std::to_string(i), where_);
  return out;
}

const json* ObjectReader::raw(const char* key) {
  return has(key) ? &object_[key] : nullptr;
}

void ObjectReader::finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    std::vector<std::string> known = known_;
    std::sort(known.begin(), known.end());
    known.erase(std::unique(known.begin(), known.end()), known.end());
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    const std::string near = closest_match(key, known.data(), known.size());
    fail_at(where_, pointer_ + "/" + key,
            "unknown field" + (near.empty() ? "" : "; did you mean \"" + near + "\"?") +
                " (known fields here: " + list + ")");
  }
}

}  // namespace json_reader
}  // namespace springlab
