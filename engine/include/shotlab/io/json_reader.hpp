// Strict, path-aware reading of JSON documents: every error names the file, the field (as a path such as
// balls[2].mass) and the problem, and a field nobody asked for is an error, not silently ignored.
#pragma once
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "shotlab/vec.hpp"

namespace shotlab {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A field the format does not have (a misspelt name), `name` its key: what a sweep refuses before its first run.
struct UnknownFieldError : InputError {
  UnknownFieldError(const std::string& message, std::string key) : InputError(message), name(std::move(key)) {}
  std::string name;
};

// A value as an error message quotes it: a number or a short string as written, anything longer or nested by its
// kind ("an array of 3", "an object"); invalid UTF-8 replaced. Never long, never recursive.
std::string describe(const nlohmann::json& value);

class JsonNode {
 public:
  JsonNode(const nlohmann::json& j, std::string source, std::string path);

  bool has(const std::string& key) const;
  JsonNode operator[](const std::string& key) const;  // required field
  // Calls read(child) when the field is present.
  void optional(const std::string& key, const std::function<void(const JsonNode&)>& read) const;
  // Reads key, when present, into `out` through one of the checks below (e.g. &JsonNode::positive).
  template <class T>
  void optional(const std::string& key, T& out, T (JsonNode::*check)() const) const {
    optional(key, [&](const JsonNode& v) { out = (v.*check)(); });
  }
  std::vector<JsonNode> items() const;  // array elements

  double number() const;                  // finite
  double positive() const;                // > 0
  double non_negative() const;            // >= 0
  int integer(int min, int max) const;
  bool boolean() const;
  std::string string() const;
  Vec3 vec3() const;
  double angle_degrees() const;  // a number in degrees, returned in radians

  // Call after reading an object: any field that was not asked for is an error (a typo must not pass silently).
  void finish() const;

  [[noreturn]] void fail(const std::string& problem) const;
  const std::string& path() const { return path_; }
  const nlohmann::json& raw() const { return *j_; }

 private:
  std::string child_path(const std::string& key) const;
  const nlohmann::json* j_;
  std::string source_, path_;
  std::shared_ptr<std::set<std::string>> used_;
};

// A field of S read, when present, into S::*member through one of JsonNode's checks; lists of them read a struct.
template <class S, class T>
struct Field {
  const char* key;
  T S::*member;
  T (JsonNode::*check)() const;
};
template <class S, class T, size_t N>
void read_fields(const JsonNode& n, S& s, const Field<S, T> (&fields)[N]) {
  for (const Field<S, T>& f : fields) n.optional(f.key, s.*f.member, f.check);
}

}  // namespace shotlab
