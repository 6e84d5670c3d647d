// JSON text to a document (with the checks the library does not make) and --set overrides applied to a document.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "shotlab/io/scene_json.hpp"

namespace shotlab {
namespace {

using nlohmann::json;

// The field path (as in error messages: balls[2].position[1]) at byte offset `pos` of a JSON text: a walk over the
// text before it that tracks object keys and array indices. Used to name the field of a number that overflows,
// which the JSON library reports by offset only.
std::string json_path_at(const std::string& text, size_t pos) {
  struct Level {
    bool array;
    int index = 0;
    std::string key;
  };
  std::vector<Level> levels;
  for (size_t i = 0; i < std::min(pos, text.size()); ++i) {
    const char c = text[i];
    if (c == '"') {
      std::string str;
      for (++i; i < text.size() && text[i] != '"'; ++i) str += text[i] == '\\' ? text[++i] : text[i];
      size_t j = i + 1;
      while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j < text.size() && text[j] == ':' && !levels.empty()) levels.back().key = str;
    } else if (c == '{' || c == '[') {
      levels.push_back({c == '[', 0, ""});
    } else if ((c == '}' || c == ']') && !levels.empty()) {
      levels.pop_back();
    } else if (c == ',' && !levels.empty() && levels.back().array) {
      ++levels.back().index;
    }
  }
  std::string path;
  for (const Level& l : levels)
    path += l.array ? "[" + std::to_string(l.index) + "]" : (path.empty() ? "" : ".") + l.key;
  return path.empty() ? "(top level)" : path;
}

// Rejects, while parsing, a document nested deeper than kMaxJsonDepth and a key given twice in one object (the
// library would keep the last one silently).
json::parser_callback_t strict_checks(std::string& problem) {
  auto keys = std::make_shared<std::vector<std::set<std::string>>>();  // of each open object, innermost last
  return [keys, &problem](int depth, json::parse_event_t event, json& parsed) {
    if (!problem.empty()) return false;
    if (depth > kMaxJsonDepth) {
      problem = "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels";
    } else if (event == json::parse_event_t::object_start) {
      keys->emplace_back();
    } else if (event == json::parse_event_t::object_end && !keys->empty()) {
      keys->pop_back();
    } else if (event == json::parse_event_t::key && !keys->empty()) {
      if (!keys->back().insert(parsed.get<std::string>()).second)
        problem = "the key " + describe(parsed) + " is given twice in one object";
    }
    return problem.empty();
  };
}

// Parses with strict_checks: a problem they find is an InputError at `where`, any other failure the library's.
json parse_strict(const std::string& text, const std::string& where) {
  std::string problem;
  try {
    json doc = json::parse(text, strict_checks(problem));
    if (!problem.empty()) throw InputError(where + ": " + problem);
    return doc;
  } catch (const json::exception&) {
    if (!problem.empty()) throw InputError(where + ": " + problem);
    throw;
  }
}

}  // namespace

json parse_json_text(const std::string& text, const std::string& source) {
  try {
    return parse_strict(text, source);
  } catch (const json::parse_error& e) {
    throw InputError(source + ": malformed JSON: " + e.what());
  } catch (const json::out_of_range& e) {
    // Number overflow (1e999): the library gives no position; find the first such token ourselves.
    size_t pos = std::string::npos;
    bool in_string = false;  // "1e400" inside a string (a name) is no number
    for (size_t i = 0; i < text.size() && pos == std::string::npos; ++i) {
      if (text[i] == '"' && (i == 0 || text[i - 1] != '\\')) in_string = !in_string;
      if (in_string || !std::isdigit(static_cast<unsigned char>(text[i]))) continue;
      if (i > 0 && std::isalnum(static_cast<unsigned char>(text[i - 1]))) continue;
      size_t end = i;
      while (end < text.size() && std::strchr("0123456789.eE+-", text[end])) ++end;
      if (!std::isfinite(std::strtod(text.substr(i, end - i).c_str(), nullptr))) pos = i;
      i = end - 1;
    }
    throw InputError(source + ": " + json_path_at(text, pos) + ": must be a finite number (" + e.what() + ")");
  }
}

namespace {

// The VALUE of --set PATH=VALUE: JSON, or a bare word taken as a string (an integrator name).
json override_value(const std::string& text, const std::string& where) {
  try {
    return parse_strict(text, where);
  } catch (const json::parse_error&) {
    const bool looks_like_json = !text.empty() && std::strchr("{[\"-0123456789", text[0]);
    if (looks_like_json) throw InputError(where + ": the value is not valid JSON (a bare word is taken as a string)");
    return text;
  } catch (const json::exception&) {  // a number that overflows (1e400)
    throw InputError(where + ": the value is not a finite number");
  }
}

// Splits "a.b[2].c" into a, b, 2, c.
std::vector<std::string> override_path(const std::string& path) {
  std::vector<std::string> parts;
  std::string cur;
  for (char ch : path) {
    if (ch == '.' || ch == '[' || ch == ']') {
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (!cur.empty()) parts.push_back(cur);
  return parts;
}

// The element of an array named by an index or by its "id"; nullptr when there is none.
json* array_element(json& array, const std::string& key) {
  if (std::all_of(key.begin(), key.end(), ::isdigit)) {
    size_t i = 0;
    const auto [end, err] = std::from_chars(key.data(), key.data() + key.size(), i);
    return err == std::errc() && end == key.data() + key.size() && i < array.size() ? &array[i] : nullptr;
  }
  for (json& e : array)
    if (e.is_object() && e.contains("id") && e["id"].is_string() && e["id"].get<std::string>() == key) return &e;
  return nullptr;
}

}  // namespace

void apply_override(json& doc, const std::string& assignment) {
  const std::string where = "--set " + describe(json(assignment));
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError(where + ": expected PATH=VALUE");
  const std::string path = assignment.substr(0, eq);
  const json value = override_value(assignment.substr(eq + 1), where);
  const std::vector<std::string> parts = override_path(path);
  if (parts.empty()) throw InputError(where + ": the path names no field");
  json* node = &doc;
  for (const std::string& key : parts) {
    if (node->is_array()) {
      node = array_element(*node, key);
      if (!node) throw InputError(where + ": no element " + describe(json(key)) + " in that array");
    } else {
      if (node->is_null()) *node = json::object();
      if (!node->is_object())
        throw InputError(where + ": " + describe(json(key)) + " is inside a value that is not an object");
      node = &(*node)[key];
    }
  }
  *node = value;
}

}  // namespace shotlab
