#include "shotlab/io/json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

namespace shotlab {

std::string describe(const nlohmann::json& v) {
  using nlohmann::json;
  constexpr size_t kLongest = 40;  // characters quoted from a string
  switch (v.type()) {
    case json::value_t::array: return "an array of " + std::to_string(v.size());
    case json::value_t::object: return "an object";
    case json::value_t::string: {
      const std::string text = json(v.get<std::string>().substr(0, kLongest)).dump(-1, ' ', false,
                                                                                  json::error_handler_t::replace);
      return v.get<std::string>().size() > kLongest ? text.substr(0, text.size() - 1) + "...\"" : text;
    }
    default: return v.dump(-1, ' ', false, json::error_handler_t::replace);
  }
}

namespace {

constexpr size_t kEdits = 2;  // a name at most this many single-letter edits off is worth pointing out

// How many single-letter edits (insert, delete, replace, swap neighbours; ignoring case) make a into b, or more than
// kEdits when that is more than kEdits.
size_t edits(const std::string& a, const std::string& b) {
  if ((a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > kEdits) return kEdits + 1;
  auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  };
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + !same(a[i - 1], b[j - 1])});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The hint for a misspelt name: the nearest of `names` (the first of equals) within kEdits, said by `say`.
template <class Names, class Say>
std::string nearest(const std::string& name, const Names& names, Say&& say) {
  size_t best = kEdits + 1;
  std::string hint;
  for (const std::string& known : names)
    if (const size_t e = known == name ? best : edits(name, known); e < best) best = e, hint = say(known);
  return hint;
}

}  // namespace

JsonNode::JsonNode(const nlohmann::json& j, std::string source, std::string path)
    : j_(&j), source_(std::move(source)), path_(std::move(path)), used_(std::make_shared<std::set<std::string>>()) {}

void JsonNode::finish() const {
  if (!j_->is_object()) return;
  for (const auto& item : j_->items())
    if (!used_->count(item.key())) {
      const std::string hint =
          nearest(item.key(), *used_, [](const std::string& k) { return " (did you mean '" + k + "'?)"; });
      throw UnknownFieldError(source_ + ": " + child_path(item.key()) + ": unknown field" + hint, item.key());
    }
}

std::string JsonNode::child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void JsonNode::fail(const std::string& problem) const {
  throw InputError(source_ + ": " + (path_.empty() ? "(top level)" : path_) + ": " + problem);
}

bool JsonNode::has(const std::string& key) const { return j_->is_object() && j_->contains(key); }

JsonNode JsonNode::operator[](const std::string& key) const {
  if (!j_->is_object()) fail("must be an object");
  used_->insert(key);
  const auto it = j_->find(key);
  if (it == j_->end()) {
    std::vector<std::string> unused;
    for (const auto& item : j_->items())
      if (!used_->count(item.key())) unused.push_back(item.key());
    const std::string hint =
        nearest(key, unused, [](const std::string& k) { return " (is '" + k + "' a misspelling of it?)"; });
    JsonNode(*j_, source_, child_path(key)).fail("missing required field" + hint);
  }
  return JsonNode(*it, source_, child_path(key));
}

void JsonNode::optional(const std::string& key, const std::function<void(const JsonNode&)>& read) const {
  if (!j_->is_object()) fail("must be an object");
  used_->insert(key);
  if (has(key)) read((*this)[key]);
}

std::vector<JsonNode> JsonNode::items() const {
  if (!j_->is_array()) fail("must be an array");
  std::vector<JsonNode> out;
  for (size_t i = 0; i < j_->size(); ++i) out.emplace_back((*j_)[i], source_, path_ + "[" + std::to_string(i) + "]");
  return out;
}

double JsonNode::number() const {
  if (!j_->is_number()) fail("must be a number, got " + std::string(j_->type_name()));
  const double v = j_->get<double>();
  if (!std::isfinite(v)) fail("must be a finite number");
  return v;
}

double JsonNode::positive() const {
  const double v = number();
  if (!(v > 0)) fail("must be positive, got " + describe(*j_));
  return v;
}

double JsonNode::non_negative() const {
  const double v = number();
  if (v < 0) fail("must not be negative, got " + describe(*j_));
  return v;
}

int JsonNode::integer(int min, int max) const {
  if (!j_->is_number_integer()) fail("must be an integer, got " + describe(*j_));
  const long long v = j_->get<long long>();
  if (v < min || v > max) fail("must be between " + std::to_string(min) + " and " + std::to_string(max));
  return static_cast<int>(v);
}

bool JsonNode::boolean() const {
  if (!j_->is_boolean()) fail("must be true or false, got " + std::string(j_->type_name()));
  return j_->get<bool>();
}

std::string JsonNode::string() const {
  if (!j_->is_string()) fail("must be a string, got " + std::string(j_->type_name()));
  return j_->get<std::string>();
}

Vec3 JsonNode::vec3() const {
  if (!j_->is_array() || j_->size() != 3) fail("must be an array of 3 numbers [x, y, z]");
  const auto e = items();
  return {e[0].number(), e[1].number(), e[2].number()};
}

// Whole turns taken off first: 1e308 degrees times pi would overflow to infinity (a NaN direction).
double JsonNode::angle_degrees() const { return std::fmod(number(), 360.0) * M_PI / 180.0; }

}  // namespace shotlab
