#include "check_result.hpp"
#include <algorithm>
#include <cstdint>
#include <iterator>
#include <numeric>

namespace sw::check_values {

namespace {

// A member of the result that is an array but not of tuples of scalars of one length: the text is
// read again with nothing held.
struct Irregular {};

// nlohmann's SAX interface: builds the Json of a text as Json::parse does (the last of duplicate
// keys kept, then refused as parse_json_text refuses them), except that with `hold` the members of
// the result object (the text's value, or its member `under`) that are lists of tuples go to
// `lists`.
class Reader {
 public:
  Reader(std::string_view what, bool hold, std::string_view under) : what_(what), hold_(hold), under_(under) {}

  Held read(std::string_view text) {
    Json::sax_parse(text.begin(), text.end(), this);
    return {std::move(root_), std::move(lists_)};
  }

  bool null() { return scalar(nullptr); }
  bool boolean(bool b) { return scalar(b); }
  bool number_integer(Json::number_integer_t v) { return scalar(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return scalar(v); }
  bool number_float(Json::number_float_t v, const std::string&) { return scalar(v); }
  bool string(std::string& s) { return scalar(std::move(s)); }
  bool binary(Json::binary_t& b) { return scalar(Json::binary(b)); }
  bool start_object(std::size_t) {
    if (in_list_) throw Irregular{};
    const bool result = hold_ && !result_ && (under_.empty() ? open_.empty() : open_.size() == 1 && open_[0].value->is_object() && key_ == under_);
    open_.push_back({place(Json::object()), {}});
    if (result) result_ = open_.back().value;
    return true;
  }
  bool key(std::string& k) {
    open_.back().keys.push_back(k);
    key_ = std::move(k);
    return true;
  }
  bool end_object() {
    refuse_duplicate_key(open_.back().keys, what_);
    open_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    if (in_tuple_) throw Irregular{};
    if (in_list_) {
      in_tuple_ = true, tuple_size_ = 0;
    } else if (result_ && open_.back().value == result_) {
      in_list_ = true, list_ = {}, list_key_ = key_;
    } else {
      open_.push_back({place(Json::array()), {}});
    }
    return true;
  }
  bool end_array() {
    if (in_tuple_) {
      if (list_.count > 0 && tuple_size_ != list_.arity) throw Irregular{};
      list_.arity = tuple_size_, ++list_.count, in_tuple_ = false;
    } else if (in_list_) {
      lists_[list_key_] = std::move(list_);
      in_list_ = false;
    } else {
      open_.pop_back();
    }
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const Json::exception& e) { throw json_text_error(e, what_); }

 private:
  bool scalar(Json v) {
    if (in_tuple_) {
      list_.push(std::move(v));
      ++tuple_size_;
    } else if (in_list_) {
      throw Irregular{};
    } else {
      place(std::move(v));
    }
    return true;
  }
  // Puts a value where the parse is: the root, the next item of an array, or the member key_.
  Json* place(Json v) {
    if (open_.empty()) return &(root_ = std::move(v));
    Json& parent = *open_.back().value;
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      return &parent.back();
    }
    return &(parent[key_] = std::move(v));
  }

  struct Open {
    Json* value;                    // an array or an object, being filled
    std::vector<std::string> keys;  // an object's keys as read, duplicates too
  };
  std::string_view what_;
  bool hold_;
  std::string_view under_;
  Json root_;
  std::vector<Open> open_;
  std::string key_;
  const Json* result_ = nullptr;  // the result object, once open
  std::map<std::string, Tuples, std::less<>> lists_;
  bool in_list_ = false, in_tuple_ = false;
  Tuples list_;
  std::string list_key_;
  std::size_t tuple_size_ = 0;
};

Held read(std::string_view text, std::string_view what, std::string_view under) {
  try {
    return Reader(what, true, under).read(text);
  } catch (const Irregular&) {
    return Reader(what, false, under).read(text);  // with nothing held
  }
}

// A held list as the Json array of arrays it was read from.
Json as_json(const Tuples& t) {
  Json a = Json::array();
  for (std::size_t k = 0; k < t.count; ++k) {
    Json tuple = Json::array();
    for (std::size_t c = 0; c < t.arity; ++c) tuple.push_back(t.at(k * t.arity + c));
    a.push_back(std::move(tuple));
  }
  return a;
}
Json whole(const Held& h) {
  Json j = h.json;
  for (const auto& [key, list] : h.lists) j[key] = as_json(list);
  return j;
}

// Sorts a list's tuples as std::sort sorts the Json array of arrays: lexicographically, by Json's <
// (integers' order, for integers).
template <class Items> void sort_tuples(Items& items, std::size_t count, std::size_t arity) {
  const auto tuple = [&](std::size_t k) { return items.begin() + static_cast<std::ptrdiff_t>(k * arity); };
  const auto a = static_cast<std::ptrdiff_t>(arity);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return std::lexicographical_compare(tuple(x), tuple(x) + a, tuple(y), tuple(y) + a); });
  Items sorted;
  for (std::size_t k : order) std::move(tuple(k), tuple(k) + a, std::back_inserter(sorted));
  items = std::move(sorted);
}
void sort_tuples(Tuples& t) {
  if (t.integers) sort_tuples(t.ints, t.count, t.arity);
  else sort_tuples(t.items, t.count, t.arity);
}

// value_diff of the arrays of arrays two lists were read from: their lengths, then tuple by tuple.
std::optional<std::string> list_diff(const Tuples& want, const Tuples& got, const Tolerance& tol, bool exact, const std::string& path) {
  if (want.count != got.count) return path + ": expected " + std::to_string(want.count) + " entries, got " + std::to_string(got.count);
  if (want.count > 0 && want.arity != got.arity) return path + "[0]: expected " + std::to_string(want.arity) + " entries, got " + std::to_string(got.arity);
  // Equal values of one type never differ: value_diff (and the path it names) only for the others.
  // (Json's == is no test across types: it holds 2^64 - 1 equal to -1, and 2^53 + 1 to 2^53.)
  const auto same = [](const Json& w, const Json& g) { return w.type() == g.type() && w == g; };
  const auto equal = [&](std::size_t i) {
    if (want.integers && got.integers) return want.ints[i] == got.ints[i];
    if (!want.integers && !got.integers) return same(want.items[i], got.items[i]);
    return same(want.at(i), got.at(i));
  };
  for (std::size_t i = 0; i < want.count * want.arity; ++i) {
    if (equal(i)) continue;
    const std::size_t k = i / want.arity, c = i % want.arity;
    if (auto d = value_diff(want.at(i), got.at(i), tol, exact, path + "[" + std::to_string(k) + "][" + std::to_string(c) + "]", 3)) return d;
  }
  return std::nullopt;
}

// The names of a result's members, in the order of a Json object's keys.
std::vector<std::string> member_names(const Held& h) {
  std::vector<std::string> names;
  for (auto it = h.json.begin(); it != h.json.end(); ++it) names.push_back(it.key());
  for (const auto& [key, list] : h.lists) names.push_back(key);
  std::sort(names.begin(), names.end());
  return names;
}
bool has_member(const Held& h, const std::string& key) { return h.json.contains(key) || h.lists.contains(key); }

}  // namespace

void Tuples::push(Json v) {
  if (integers && v.is_number_integer() && (!v.is_number_unsigned() || v.get<std::uint64_t>() <= std::uint64_t(INT64_MAX))) {
    ints.push_back(v.get<std::int64_t>());
    return;
  }
  if (integers) {  // the list's first scalar that is no 64-bit integer: all of them as Json from here
    for (std::size_t i = 0; i < ints.size(); ++i) items.push_back(at(i));
    ints = {};
    integers = false;
  }
  items.push_back(std::move(v));
}

Json Tuples::at(std::size_t i) const {
  if (!integers) return items[i];
  return ints[i] >= 0 ? Json(static_cast<std::uint64_t>(ints[i])) : Json(ints[i]);
}

Held read_trace_line(std::string_view text, std::string_view what) {
  check_json_text(text, what);
  return read(text, what, "result");
}

Held read_result(std::string_view text) { return read(text, "result", ""); }

Held canonical(const Algorithm& alg, Held result) {
  if (result.lists.empty() || alg.reshapes_result) return {alg.canonical(result.lists.empty() ? std::move(result.json) : whole(result)), {}};
  for (std::string_view key : alg.result_sets) {
    const auto list = result.lists.find(key);
    if (list != result.lists.end()) sort_tuples(list->second);
    else sort_result_set(result.json, key);
  }
  return result;
}

std::optional<std::string> result_diff(const Held& want, const Held& got, const Tolerance& tol, bool exact) {
  if (want.lists.empty() && got.lists.empty()) return value_diff(want.json, got.json, tol, exact, "result");
  if (!want.json.is_object() || !got.json.is_object()) return value_diff(whole(want), whole(got), tol, exact, "result");
  // value_diff's rule for two objects, over members held either way: each of want's (but the
  // informational "fallback") in key order, missing or differing, then any got has besides.
  for (const std::string& key : member_names(want)) {
    if (key == "fallback") continue;
    if (!has_member(got, key)) return "result: missing \"" + key + "\"";
    const auto w = want.lists.find(key), g = got.lists.find(key);
    const std::string path = "result." + key;
    std::optional<std::string> d;
    if (w != want.lists.end() && g != got.lists.end()) d = list_diff(w->second, g->second, tol, exact, path);
    else if (w != want.lists.end()) d = value_diff(as_json(w->second), got.json[key], tol, exact, path, 1);
    else if (g != got.lists.end()) d = value_diff(want.json[key], as_json(g->second), tol, exact, path, 1);
    else d = value_diff(want.json[key], got.json[key], tol, exact, path, 1);
    if (d) return d;
  }
  for (const std::string& key : member_names(got))
    if (key != "fallback" && !has_member(want, key)) return "result: unexpected \"" + key + "\"";
  return std::nullopt;
}

}  // namespace sw::check_values
